/* canvas.c - the public lr_canvas calls, forwarded to a backend.
 *
 * Input that no backend could draw (a NULL canvas, NaN or infinite
 * coordinates, a width that is not positive) is dropped here, once, so the
 * backends agree on it: a frame with one bad particle still draws the rest
 * on cairo and OSMesa alike. */
#include "canvas_backend.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "util.h"

/* ---- backends ---------------------------------------------------------- */

static const char *const backend_names[LR_BACKEND_COUNT] = { "cairo", "osmesa", "egl" };

/* "gl" asks for OpenGL without caring how: EGL where it works, since
 * OSMesa is gone from Mesa 25.1 on. */
static lr_backend gl_choice(void)
{
    if (lr_backend_check(LR_BACKEND_EGL, NULL, 0) == 0)
        return LR_BACKEND_EGL;
#ifdef LAMINA_HAVE_OSMESA
    return LR_BACKEND_OSMESA;
#else
    return LR_BACKEND_EGL;
#endif
}

int lr_backend_parse(const char *name, lr_backend *b, char *err, size_t errlen)
{
    int i = lu_name_index(name, backend_names, LR_BACKEND_COUNT);
    if (i >= 0 || (name && strcmp(name, "gl") == 0)) {
        *b = i >= 0 ? (lr_backend)i : gl_choice();
        return 0;
    }
    lu_err(err, errlen, "unknown backend '%s' (known: cairo, osmesa, egl, gl)",
           name ? name : "");
    return -1;
}

const char *lr_backend_name(lr_backend b)
{
    return b >= 0 && b < LR_BACKEND_COUNT ? backend_names[b] : "cairo";
}

int lr_backend_check(lr_backend b, char *err, size_t errlen)
{
    switch (b) {
    case LR_BACKEND_CAIRO:
        return 0;
    case LR_BACKEND_OSMESA:
#ifdef LAMINA_HAVE_OSMESA
        return 0;
#else
        lu_err(err, errlen, "this lamina was built without OSMesa (install "
                "libosmesa6-dev and rebuild, or use the egl or cairo backend)");
        return -1;
#endif
    case LR_BACKEND_EGL:
#ifdef LAMINA_HAVE_EGL
        return lr_canvas_egl_probe(err, errlen);
#else
        lu_err(err, errlen, "this lamina was built without EGL (install "
                "libegl-dev, libegl-mesa0 and libgl-dev and rebuild, or use the "
                "osmesa or cairo backend)");
        return -1;
#endif
    }
    lu_err(err, errlen, "unknown backend");
    return -1;
}

#ifndef LAMINA_HAVE_GL
void lr_canvas_gl_release(void) {}
#endif

/* A backend this lamina was built without: NULL, and why in err. */
#if !defined(LAMINA_HAVE_OSMESA) || !defined(LAMINA_HAVE_EGL)
static lr_canvas *not_built(lr_backend b, char *err, size_t errlen)
{
    lr_backend_check(b, err, errlen);
    return NULL;
}
#endif

#ifndef LAMINA_HAVE_OSMESA
lr_canvas *lr_canvas_osmesa_new(int width, int height, char *err, size_t errlen)
{
    (void)width, (void)height;
    return not_built(LR_BACKEND_OSMESA, err, errlen);
}
#endif

#ifndef LAMINA_HAVE_EGL
lr_canvas *lr_canvas_egl_new(int width, int height, char *err, size_t errlen)
{
    (void)width, (void)height;
    return not_built(LR_BACKEND_EGL, err, errlen);
}
#endif

lr_canvas *lr_canvas_new(lr_backend b, int width, int height, char *err, size_t errlen)
{
    if (lr_backend_check(b, err, errlen) != 0)
        return NULL;
    if (width < 1 || height < 1 || width > LR_CANVAS_MAX_SIZE ||
        height > LR_CANVAS_MAX_SIZE) {
        lu_err(err, errlen, "cannot create canvas: invalid size %dx%d "
               "(1..%d each)", width, height, LR_CANVAS_MAX_SIZE);
        return NULL;
    }
    switch (b) {
    case LR_BACKEND_OSMESA:
        return lr_canvas_osmesa_new(width, height, err, errlen);
    case LR_BACKEND_EGL:
        return lr_canvas_egl_new(width, height, err, errlen);
    default:
        return lr_canvas_cairo_new(width, height, err, errlen);
    }
}

lr_backend lr_canvas_backend(const lr_canvas *c)
{
    return c ? c->ops->backend : LR_BACKEND_CAIRO;
}

lr_format lr_format_of(const char *path)
{
    size_t n = path ? strlen(path) : 0;
    if (n > 4 && strcasecmp(path + n - 4, ".svg") == 0)
        return LR_FORMAT_SVG;
    if (n > 4 && strcasecmp(path + n - 4, ".pdf") == 0)
        return LR_FORMAT_PDF;
    return LR_FORMAT_PNG;
}

/* ---- forwarding -------------------------------------------------------- */

static int finite2(double a, double b) { return isfinite(a) && isfinite(b); }

void lr_canvas_free(lr_canvas *c)
{
    if (c) {
        size_t charged = c->charged;
        c->ops->destroy(c);
        lu_budget_release(LU_MEM_RENDER, charged);
    }
}

int lr_canvas_charge(int width, int height, size_t *charged, char *err, size_t errlen)
{
    size_t bytes = 4 * (size_t)width * (size_t)height;
    if (lu_budget_charge(LU_MEM_RENDER, bytes) != 0) {
        lu_err(err, errlen, "cannot create a %d x %d canvas: %s", width, height,
               lu_budget_oom());
        return -1;
    }
    *charged = bytes;
    return 0;
}

int lr_canvas_width(const lr_canvas *c) { return c ? c->width : 0; }
int lr_canvas_height(const lr_canvas *c) { return c ? c->height : 0; }

void lr_canvas_clear(lr_canvas *c, lr_rgba colour)
{
    if (c)
        c->ops->clear(c, colour);
}

void lr_canvas_line(lr_canvas *c, double x0, double y0, double x1, double y1,
                    double width, lr_rgba colour, double dash)
{
    if (!c || !finite2(x0, y0) || !finite2(x1, y1) || !(width > 0) ||
        !isfinite(width))
        return;
    c->ops->line(c, x0, y0, x1, y1, width, colour, dash > 0 && isfinite(dash) ? dash : 0.0);
}

void lr_canvas_rect(lr_canvas *c, double x, double y, double w, double h,
                    double line_width, lr_rgba stroke)
{
    if (!c || !finite2(x, y) || !finite2(w, h) || !(line_width > 0) ||
        !isfinite(line_width))
        return;
    c->ops->rect(c, x, y, w, h, line_width, stroke);
}

void lr_canvas_discs(lr_canvas *c, size_t n, const double *px, const double *py,
                     double r, const lr_rgba *colours)
{
    if (!c || n == 0 || !px || !py || !colours || !(r > 0) || !isfinite(r))
        return;
    c->ops->discs(c, n, px, py, r, colours);
}

void lr_canvas_fill(lr_canvas *c, size_t npoly, const size_t *counts,
                    const double *xy, lr_rgba colour)
{
    if (!c || npoly == 0 || !counts || !xy)
        return;
    size_t total = 0;
    for (size_t k = 0; k < npoly; k++)
        total += counts[k];
    for (size_t i = 0; i < 2 * total; i++)
        if (!isfinite(xy[i]))
            return;     /* a hole in one ring would change the whole fill */
    c->ops->fill(c, npoly, counts, xy, colour);
}

void lr_canvas_clip(lr_canvas *c, int x, int y, int w, int h)
{
    if (!c)
        return;
    int x1 = x + (w > 0 ? w : 0), y1 = y + (h > 0 ? h : 0);
    x = x < 0 ? 0 : x > c->width ? c->width : x;
    y = y < 0 ? 0 : y > c->height ? c->height : y;
    x1 = x1 < x ? x : x1 > c->width ? c->width : x1;
    y1 = y1 < y ? y : y1 > c->height ? c->height : y1;
    if (x1 == x || y1 == y) {
        /* nothing left: a one-pixel clip outside the image would still
         * draw, so clip to an empty rectangle the backends accept */
        c->ops->clip(c, 0, 0, -1, -1);
        return;
    }
    c->ops->clip(c, x, y, x1 - x, y1 - y);
}

void lr_canvas_unclip(lr_canvas *c)
{
    if (c)
        c->ops->clip(c, 0, 0, 0, 0);
}

unsigned char *lr_canvas_read_rgba(lr_canvas *c)
{
    return c ? c->ops->read_rgba(c) : NULL;
}

int lr_canvas_finish(lr_canvas *c, char *err, size_t errlen)
{
    if (!c || !c->ops->finish) {
        lu_err(err, errlen, "cannot finish: not a vector canvas");
        return -1;
    }
    return c->ops->finish(c, err, errlen);
}

/* ---- text -------------------------------------------------------------- */

/* Decodes one UTF-8 sequence at s the way cairo accepts it; returns its
 * length, or 0 if cairo would reject it (malformed, overlong, surrogate,
 * beyond U+10FFFF, or a Unicode noncharacter). */
static size_t utf8_len(const unsigned char *s)
{
    size_t len;
    uint32_t cp, min;
    if (s[0] < 0x80)
        return 1;
    if ((s[0] & 0xE0) == 0xC0) { len = 2; cp = s[0] & 0x1F; min = 0x80; }
    else if ((s[0] & 0xF0) == 0xE0) { len = 3; cp = s[0] & 0x0F; min = 0x800; }
    else if ((s[0] & 0xF8) == 0xF0) { len = 4; cp = s[0] & 0x07; min = 0x10000; }
    else return 0;
    for (size_t k = 1; k < len; k++) {
        if ((s[k] & 0xC0) != 0x80)
            return 0;   /* also stops at the terminating NUL */
        cp = (cp << 6) | (s[k] & 0x3F);
    }
    if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF) ||
        (cp >= 0xFDD0 && cp <= 0xFDEF) || (cp & 0xFFFE) == 0xFFFE)
        return 0;
    return len;
}

char *lr_utf8_clean(const char *text)
{
    size_t n = strlen(text);
    char *out = malloc(n + 1);
    if (!out)
        return NULL;
    const unsigned char *s = (const unsigned char *)text;
    size_t i = 0;
    while (i < n) {
        size_t k = utf8_len(s + i);
        if (k == 0) {
            out[i++] = '?';
            continue;
        }
        memcpy(out + i, s + i, k);
        i += k;
    }
    out[n] = '\0';
    return out;
}

void lr_canvas_text(lr_canvas *c, double x, double y, double size,
                    lr_rgba colour, lr_align align, const char *text)
{
    if (!c || !text || !*text || !finite2(x, y) || !(size > 0) ||
        !isfinite(size))
        return;
    char *clean = lr_utf8_clean(text);
    if (!clean)
        return;
    c->ops->text(c, x, y, size, colour, align, clean);
    free(clean);
}
