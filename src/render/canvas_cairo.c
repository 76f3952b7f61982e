/* canvas_cairo.c - the lr_canvas interface over a cairo ARGB32 image surface.
 *
 * Every drawing call is void (the interface is shared with future backends
 * that cannot fail per call); cairo keeps a sticky error status instead, and
 * lr_canvas_read_rgba reports it by returning NULL, so a frame is never
 * written from a half-drawn surface. Because that status is sticky, inputs
 * that would put cairo into an error state (invalid UTF-8, non-finite
 * coordinates) are filtered here rather than passed on. */
#include "render.h"

#include <cairo.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct lr_canvas {
    cairo_surface_t *surface;
    cairo_t *cr;
    int width, height;
    cairo_surface_t *stamps;    /* disc coverage masks, NULL until needed */
    double stamp_r;             /* the radius they were drawn for */
    int stamp_reach, stamp_size;
};

/* Discs per path fill: one fill per colour run, but bounded so that a long
 * run does not build a path of megabytes first. */
#define DISC_BATCH 1024

/* Discs up to this radius (pixels) are stamped, see "discs" below. */
#define STAMP_MAX_RADIUS 24.0

/* Sub-pixel positions per axis a stamped disc can take: at most 1/8 px
 * off, which no one sees. */
#define STAMP_PHASES 4

/* Below this radius an arc is slower than a pixel and looks no better. */
#define DISC_MIN_ARC_RADIUS 0.8

/* M_PI is not in strict C11 */
#define TWO_PI 6.283185307179586476925286766559

static void set_err(char *err, size_t errlen, const char *msg, const char *why)
{
    if (err && errlen > 0)
        snprintf(err, errlen, "%s: %s", msg, why);
}

/* Images must match across machines, so nothing may depend on the local
 * fontconfig setup: no hinting, unhinted metrics, greyscale antialiasing
 * (never subpixel). The face is still looked up by name through cairo's
 * "toy" API; bundling the font file and loading it directly comes later. */
static int setup_font(cairo_t *cr)
{
    cairo_font_options_t *fo = cairo_font_options_create();
    if (cairo_font_options_status(fo) != CAIRO_STATUS_SUCCESS) {
        cairo_font_options_destroy(fo);
        return -1;
    }
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_antialias(fo, CAIRO_ANTIALIAS_GRAY);
    cairo_set_font_options(cr, fo);
    cairo_font_options_destroy(fo);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                           CAIRO_FONT_WEIGHT_NORMAL);
    return cairo_status(cr) == CAIRO_STATUS_SUCCESS ? 0 : -1;
}

lr_canvas *lr_canvas_cairo_new(int width, int height, char *err, size_t errlen)
{
    if (width <= 0 || height <= 0 || width > 32767 || height > 32767) {
        char why[64];
        snprintf(why, sizeof why, "invalid size %dx%d (1..32767 each)", width,
                 height);
        set_err(err, errlen, "cannot create canvas", why);
        return NULL;
    }
    lr_canvas *c = calloc(1, sizeof *c);
    if (!c) {
        set_err(err, errlen, "cannot create canvas", "out of memory");
        return NULL;
    }
    c->width = width;
    c->height = height;
    c->surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
    cairo_status_t st = cairo_surface_status(c->surface);
    if (st == CAIRO_STATUS_SUCCESS) {
        c->cr = cairo_create(c->surface);
        st = cairo_status(c->cr);
    }
    if (st == CAIRO_STATUS_SUCCESS && setup_font(c->cr) != 0)
        st = cairo_status(c->cr) != CAIRO_STATUS_SUCCESS ? cairo_status(c->cr)
                                                         : CAIRO_STATUS_NO_MEMORY;
    if (st != CAIRO_STATUS_SUCCESS) {
        set_err(err, errlen, "cannot create canvas", cairo_status_to_string(st));
        lr_canvas_free(c);
        return NULL;
    }
    cairo_set_antialias(c->cr, CAIRO_ANTIALIAS_DEFAULT);
    return c;
}

void lr_canvas_free(lr_canvas *c)
{
    if (!c)
        return;
    /* cairo_destroy / cairo_surface_destroy accept NULL */
    cairo_destroy(c->cr);
    cairo_surface_destroy(c->surface);
    cairo_surface_destroy(c->stamps);
    free(c);
}

int lr_canvas_width(const lr_canvas *c) { return c ? c->width : 0; }
int lr_canvas_height(const lr_canvas *c) { return c ? c->height : 0; }

static void set_colour(cairo_t *cr, lr_rgba k)
{
    cairo_set_source_rgba(cr, k.r, k.g, k.b, k.a);
}

void lr_canvas_clear(lr_canvas *c, lr_rgba colour)
{
    if (!c)
        return;
    /* SOURCE, not OVER: a translucent clear colour must replace, not blend */
    cairo_save(c->cr);
    cairo_set_operator(c->cr, CAIRO_OPERATOR_SOURCE);
    set_colour(c->cr, colour);
    cairo_paint(c->cr);
    cairo_restore(c->cr);
}

static int finite2(double a, double b) { return isfinite(a) && isfinite(b); }

void lr_canvas_line(lr_canvas *c, double x0, double y0, double x1, double y1,
                    double width, lr_rgba colour, double dash)
{
    if (!c || !finite2(x0, y0) || !finite2(x1, y1) || !(width > 0) ||
        !isfinite(width))
        return;
    cairo_t *cr = c->cr;
    cairo_save(cr);
    cairo_set_line_width(cr, width);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    if (dash > 0 && isfinite(dash))
        cairo_set_dash(cr, &dash, 1, 0.0);
    set_colour(cr, colour);
    cairo_new_path(cr);
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
    cairo_stroke(cr);
    cairo_restore(cr);
}

void lr_canvas_rect(lr_canvas *c, double x, double y, double w, double h,
                    double line_width, lr_rgba stroke)
{
    if (!c || !finite2(x, y) || !finite2(w, h) || !(line_width > 0) ||
        !isfinite(line_width))
        return;
    cairo_t *cr = c->cr;
    cairo_save(cr);
    cairo_set_line_width(cr, line_width);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
    set_colour(cr, stroke);
    cairo_new_path(cr);
    cairo_rectangle(cr, x, y, w, h);
    cairo_stroke(cr);
    cairo_restore(cr);
}

/* ---- discs ------------------------------------------------------------
 *
 * A million small discs through cairo's path filler cost seconds (every
 * arc is tessellated). Small discs are therefore stamped: cairo draws the
 * antialiased disc once into an A8 coverage mask for each of
 * STAMP_PHASES x STAMP_PHASES sub-pixel offsets, and each disc composites
 * its colour through the nearest mask straight into the surface (OVER,
 * premultiplied, integer arithmetic: deterministic). That bypasses the
 * cairo context, which is equivalent only because this canvas never sets
 * a clip or a transform. Large discs, which are few and cover many pixels,
 * still go through cairo's paths. */

static int same_colour(const lr_rgba *a, const lr_rgba *b)
{
    return a->r == b->r && a->g == b->g && a->b == b->b && a->a == b->a;
}

static void fill_run(cairo_t *cr, const lr_rgba *colour, size_t *in_path)
{
    if (*in_path == 0)
        return;
    set_colour(cr, *colour);
    cairo_fill(cr);
    *in_path = 0;
}

/* Culling also keeps far-away points out of cairo's fixed-point range. */
static int near_canvas(const lr_canvas *c, double x, double y, double reach)
{
    return finite2(x, y) && x + reach >= 0 && y + reach >= 0 &&
           x - reach <= c->width && y - reach <= c->height;
}

/* Path fill, one fill per colour run. Arcs are traced clockwise on screen,
 * so under the default winding rule overlapping discs unite. */
static void discs_filled(lr_canvas *c, size_t n, const double *px,
                         const double *py, double r, const lr_rgba *colours)
{
    cairo_t *cr = c->cr;
    const lr_rgba *run = NULL;
    size_t in_path = 0;
    cairo_save(cr);
    cairo_new_path(cr);
    for (size_t i = 0; i < n; i++) {
        if (!near_canvas(c, px[i], py[i], r))
            continue;
        if (!run || !same_colour(run, &colours[i]) || in_path == DISC_BATCH) {
            if (run)
                fill_run(cr, run, &in_path);
            run = &colours[i];
        }
        cairo_new_sub_path(cr);
        cairo_arc(cr, px[i], py[i], r, 0.0, TWO_PI);
        in_path++;
    }
    if (run)
        fill_run(cr, run, &in_path);
    cairo_restore(cr);
}

/* Builds (or keeps) the coverage masks for radius r; -1 on failure. The
 * mask for phase (qx, qy) is tile qy*STAMP_PHASES+qx, tiles stacked
 * vertically; its pixel (reach, reach) holds the disc centre's pixel. */
static int prepare_stamps(lr_canvas *c, double r)
{
    if (c->stamps && c->stamp_r == r)
        return 0;
    cairo_surface_destroy(c->stamps);
    c->stamps = NULL;
    int reach = (int)ceil(r) + 1, size = 2 * reach + 1;
    int tiles = STAMP_PHASES * STAMP_PHASES;
    cairo_surface_t *m = cairo_image_surface_create(CAIRO_FORMAT_A8, size,
                                                    size * tiles);
    cairo_t *cr = cairo_create(m);   /* an error object if m is one */
    for (int q = 0; q < tiles; q++) {
        double fx = (q % STAMP_PHASES + 0.5) / STAMP_PHASES;
        double fy = (q / STAMP_PHASES + 0.5) / STAMP_PHASES;
        cairo_new_sub_path(cr);
        cairo_arc(cr, reach + fx, q * size + reach + fy, r, 0.0, TWO_PI);
    }
    cairo_fill(cr);
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_flush(m);
    if (st != CAIRO_STATUS_SUCCESS ||
        cairo_surface_status(m) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(m);
        return -1;
    }
    c->stamps = m;
    c->stamp_r = r;
    c->stamp_reach = reach;
    c->stamp_size = size;
    return 0;
}

/* x*y/255 rounded, exactly, for x, y in 0..255 */
static uint32_t mul255(uint32_t x, uint32_t y)
{
    uint32_t t = x * y + 128;
    return (t + (t >> 8)) >> 8;
}

/* A colour as premultiplied 8-bit channels: a, r, g, b. */
typedef struct argb8 { uint32_t ch[4]; } argb8;

static uint32_t to8(double v)
{
    return v <= 0 ? 0 : v >= 1 ? 255 : (uint32_t)lround(v * 255.0);
}

static argb8 premultiply(lr_rgba k)
{
    argb8 p;
    p.ch[0] = to8(k.a);
    p.ch[1] = mul255(to8(k.r), p.ch[0]);
    p.ch[2] = mul255(to8(k.g), p.ch[0]);
    p.ch[3] = mul255(to8(k.b), p.ch[0]);
    return p;
}

/* Composites colour k at coverage cov (1..255) OVER the pixel at dst. */
static void blend(unsigned char *dst, const argb8 *k, uint32_t cov)
{
    uint32_t d;
    memcpy(&d, dst, sizeof d);
    uint32_t keep = 255 - mul255(k->ch[0], cov), out = 0;
    for (int i = 0; i < 4; i++) {
        int shift = 24 - 8 * i;
        uint32_t v = mul255(k->ch[i], cov) + mul255((d >> shift) & 0xFF, keep);
        out |= v << shift;
    }
    memcpy(dst, &out, sizeof out);
}

/* The phase bin of a coordinate's fractional part. */
static int phase(double frac)
{
    int q = (int)(frac * STAMP_PHASES);
    return q < 0 ? 0 : q >= STAMP_PHASES ? STAMP_PHASES - 1 : q;
}

static void stamp_disc(lr_canvas *c, unsigned char *img, int istride,
                       double x, double y, const argb8 *k)
{
    double fx = floor(x), fy = floor(y);
    int reach = c->stamp_reach, size = c->stamp_size;
    int x0 = (int)fx - reach, y0 = (int)fy - reach;
    int q = phase(y - fy) * STAMP_PHASES + phase(x - fx);
    int mstride = cairo_image_surface_get_stride(c->stamps);
    const unsigned char *tile = cairo_image_surface_get_data(c->stamps) +
                                (size_t)q * size * mstride;
    int j0 = y0 < 0 ? -y0 : 0, j1 = c->height - y0 < size ? c->height - y0 : size;
    int i0 = x0 < 0 ? -x0 : 0, i1 = c->width - x0 < size ? c->width - x0 : size;
    for (int j = j0; j < j1; j++) {
        const unsigned char *cov = tile + (size_t)j * mstride;
        unsigned char *row = img + (size_t)(y0 + j) * istride + 4 * (size_t)x0;
        for (int i = i0; i < i1; i++)
            if (cov[i])
                blend(row + 4 * (size_t)i, k, cov[i]);
    }
}

/* Below DISC_MIN_ARC_RADIUS a disc is the pixel holding its centre, so
 * a dot stays crisp; otherwise a stamp from prepare_stamps. */
static void discs_stamped(lr_canvas *c, size_t n, const double *px,
                          const double *py, double r, const lr_rgba *colours)
{
    cairo_surface_flush(c->surface);
    unsigned char *img = cairo_image_surface_get_data(c->surface);
    int istride = cairo_image_surface_get_stride(c->surface);
    int dot = r < DISC_MIN_ARC_RADIUS;
    const lr_rgba *last = NULL;
    argb8 k = { { 0, 0, 0, 0 } };
    for (size_t i = 0; i < n; i++) {
        double x = px[i], y = py[i];
        if (!near_canvas(c, x, y, dot ? 1.0 : r))
            continue;
        if (!last || !same_colour(last, &colours[i])) {
            last = &colours[i];
            k = premultiply(*last);
        }
        if (!dot) {
            stamp_disc(c, img, istride, x, y, &k);
        } else if (x >= 0 && y >= 0 && x < c->width && y < c->height) {
            size_t at = (size_t)floor(y) * istride + 4 * (size_t)floor(x);
            blend(img + at, &k, 255);
        }
    }
    cairo_surface_mark_dirty(c->surface);
}

void lr_canvas_discs(lr_canvas *c, size_t n, const double *px, const double *py,
                     double r, const lr_rgba *colours)
{
    if (!c || n == 0 || !px || !py || !colours || !(r > 0) || !isfinite(r) ||
        cairo_status(c->cr) != CAIRO_STATUS_SUCCESS)
        return;
    if (r < DISC_MIN_ARC_RADIUS ||
        (r <= STAMP_MAX_RADIUS && prepare_stamps(c, r) == 0))
        discs_stamped(c, n, px, py, r, colours);
    else
        discs_filled(c, n, px, py, r, colours);
}

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

/* A copy of text that cairo will accept: each rejected byte becomes '?'.
 * Labels come from user scripts, and one bad byte must not poison the
 * canvas (cairo errors are sticky). NULL on OOM. */
static char *utf8_clean(const char *text)
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
    char *clean = utf8_clean(text);
    if (!clean)
        return;
    cairo_t *cr = c->cr;
    cairo_save(cr);
    cairo_set_font_size(cr, size);
    if (align != LR_ALIGN_LEFT) {
        cairo_text_extents_t ext;
        cairo_text_extents(cr, clean, &ext);
        x -= align == LR_ALIGN_CENTER ? ext.x_advance / 2.0 : ext.x_advance;
    }
    set_colour(cr, colour);
    cairo_new_path(cr);
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, clean);
    cairo_restore(cr);
    free(clean);
}

/* ARGB32 is a native-endian uint32 per pixel with premultiplied colour;
 * PNG wants straight RGBA bytes. Rounded division keeps a round trip of
 * opaque colours exact. */
static void unpremultiply_row(const unsigned char *src, unsigned char *dst,
                              int width)
{
    for (int x = 0; x < width; x++) {
        uint32_t p;
        memcpy(&p, src + 4 * (size_t)x, sizeof p);
        uint32_t a = p >> 24;
        uint32_t rgb[3] = { (p >> 16) & 0xFF, (p >> 8) & 0xFF, p & 0xFF };
        unsigned char *d = dst + 4 * (size_t)x;
        for (int k = 0; k < 3; k++) {
            uint32_t v = a ? (rgb[k] * 255 + a / 2) / a : 0;
            d[k] = (unsigned char)(v > 255 ? 255 : v);
        }
        d[3] = (unsigned char)a;
    }
}

unsigned char *lr_canvas_read_rgba(lr_canvas *c)
{
    if (!c || cairo_status(c->cr) != CAIRO_STATUS_SUCCESS)
        return NULL;
    cairo_surface_flush(c->surface);
    if (cairo_surface_status(c->surface) != CAIRO_STATUS_SUCCESS)
        return NULL;
    const unsigned char *data = cairo_image_surface_get_data(c->surface);
    int stride = cairo_image_surface_get_stride(c->surface);
    if (!data)
        return NULL;
    size_t row = 4 * (size_t)c->width;
    unsigned char *out = malloc(row * (size_t)c->height);
    if (!out)
        return NULL;
    for (int y = 0; y < c->height; y++)
        unpremultiply_row(data + (size_t)y * (size_t)stride, out + (size_t)y * row,
                          c->width);
    return out;
}
