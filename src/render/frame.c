/* frame.c - one simulation frame as a picture: grid, particles, label.
 *
 * The world window is fitted into the image at one scale for x and y (so a
 * circle stays a circle), centred in what is left after a small margin and
 * the text bands. World y points up, pixel y down. Lines are snapped to the
 * pixel grid so that 1-px grid lines are crisp instead of 2-px grey smears. */
#include "render.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

/* Okabe & Ito (2008), readable with every common colour-vision deficiency.
 * Blue and vermilion first: the two most distinct, for the common case of
 * two bodies. Yellow and black last: weakest on white, and black would
 * hide among the text and outline. */
static const lr_rgba palette[] = {
    { 0x00 / 255.0, 0x72 / 255.0, 0xB2 / 255.0, 1.0 },   /* blue */
    { 0xD5 / 255.0, 0x5E / 255.0, 0x00 / 255.0, 1.0 },   /* vermilion */
    { 0x00 / 255.0, 0x9E / 255.0, 0x73 / 255.0, 1.0 },   /* bluish green */
    { 0xE6 / 255.0, 0x9F / 255.0, 0x00 / 255.0, 1.0 },   /* orange */
    { 0x56 / 255.0, 0xB4 / 255.0, 0xE9 / 255.0, 1.0 },   /* sky blue */
    { 0xCC / 255.0, 0x79 / 255.0, 0xA7 / 255.0, 1.0 },   /* reddish purple */
    { 0xF0 / 255.0, 0xE4 / 255.0, 0x42 / 255.0, 1.0 },   /* yellow */
    { 0x00 / 255.0, 0x00 / 255.0, 0x00 / 255.0, 1.0 },   /* black */
};
#define NPALETTE ((int)(sizeof palette / sizeof palette[0]))

static const lr_rgba BACKGROUND = { 1.0, 1.0, 1.0, 1.0 };
static const lr_rgba GRID_GREY = { 0.85, 0.85, 0.85, 1.0 };
static const lr_rgba OUTLINE_GREY = { 0.35, 0.35, 0.35, 1.0 };
static const lr_rgba TEXT_GREY = { 0.2, 0.2, 0.2, 1.0 };

#define MARGIN 0.04         /* of the image's smaller side */
#define TEXT_BAND 1.5       /* height of a text line, in font sizes */
#define MIN_CELL_PX 3.0     /* denser grid lines would just paint grey */
#define PARTICLE_CHUNK 4096 /* particles converted per lr_canvas_discs call */

lr_rgba lr_palette(int g)
{
    int k = g % NPALETTE;
    return palette[k < 0 ? k + NPALETTE : k];
}

static void set_err(char *err, size_t errlen, const char *fmt, ...)
{
    if (!err || errlen == 0)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

/* ---- layout ----------------------------------------------------------- */

typedef struct view {
    double s;           /* pixels per world unit */
    double ox, oy;      /* pixel position of the world origin */
    double margin;      /* pixels */
    double font;        /* label and title size, pixels */
} view;

static void to_pixel(const view *v, double x, double y, double *px, double *py)
{
    *px = v->ox + v->s * x;
    *py = v->oy - v->s * y;
}

static int has_text(const char *s) { return s && *s; }

/* NULL if the frame can be drawn, else what is wrong with it. */
static const char *frame_problem(const lr_frame *f)
{
    if (f->width <= 0 || f->height <= 0)
        return "image size must be positive";
    double ww = f->wx1 - f->wx0, wh = f->wy1 - f->wy0;
    if (!isfinite(ww) || !isfinite(wh) || !(ww > 0) || !(wh > 0))
        return "world window must be finite with wx1 > wx0 and wy1 > wy0";
    if (f->n > 0 && (!f->x || !f->y))
        return "particle positions missing";
    if (!isfinite(f->radius) || f->radius < 0)
        return "particle radius must be finite and not negative";
    const lr_grid *g = f->grid;
    if (g && (g->nx < 0 || g->ny < 0 || !(g->hx > 0) || !(g->hy > 0) ||
              !isfinite(g->x0 + g->nx * g->hx) || !isfinite(g->y0 + g->ny * g->hy)))
        return "grid needs finite cell sizes > 0 and cell counts >= 0";
    return NULL;
}

/* Fits the world window into the image; -1 if no room is left for it. */
static int fit_view(const lr_frame *f, view *v)
{
    double w = f->width, h = f->height;
    v->margin = MARGIN * fmin(w, h);
    v->font = fmax(12.0, h / 40.0);
    double band = TEXT_BAND * v->font;
    double top_band = has_text(f->title) ? band : 0.0;
    double bottom_band = has_text(f->label) ? band : 0.0;
    /* In a tiny image the text would crowd out the picture: then the text
     * is drawn over the picture instead of beside it. */
    if (h - 2.0 * v->margin - top_band - bottom_band < 0.5 * h)
        top_band = bottom_band = 0.0;
    double left = v->margin, right = w - v->margin;
    double top = v->margin + top_band, bottom = h - v->margin - bottom_band;
    double aw = right - left, ah = bottom - top;
    if (aw < 1.0 || ah < 1.0)
        return -1;
    double ww = f->wx1 - f->wx0, wh = f->wy1 - f->wy0;
    v->s = fmin(aw / ww, ah / wh);
    if (!(v->s > 0) || !isfinite(v->s))
        return -1;
    v->ox = left + 0.5 * (aw - v->s * ww) - v->s * f->wx0;
    v->oy = top + 0.5 * (ah - v->s * wh) + v->s * f->wy1;
    return 0;
}

/* ---- lines ------------------------------------------------------------ */

typedef struct pen {
    double width;       /* pixels */
    double extend;      /* pixels added at both ends (to close corners) */
    lr_rgba colour;
} pen;

/* Odd widths sit on pixel centres, even widths on pixel edges: crisp. */
static double snap(double p, double width)
{
    return ((long)lround(width) % 2) ? floor(p) + 0.5 : floor(p + 0.5);
}

/* Clips world interval [a, b] to [lo, hi]; 0 if nothing is left. */
static int clip(double *a, double *b, double lo, double hi)
{
    if (*a > *b) {
        double t = *a;
        *a = *b;
        *b = t;
    }
    *a = fmax(*a, lo);
    *b = fmin(*b, hi);
    return *a <= *b;
}

/* Lines exactly on the window's edge must survive rounding (x0 + n*h). */
static double tolerance(double lo, double hi) { return 1e-9 * (hi - lo); }

/* The part of world segment x = const, y in [ya, yb] inside the window. */
static void draw_vline(lr_canvas *c, const lr_frame *f, const view *v,
                       double x, double ya, double yb, const pen *p)
{
    double t = tolerance(f->wx0, f->wx1);
    if (x < f->wx0 - t || x > f->wx1 + t || !clip(&ya, &yb, f->wy0, f->wy1))
        return;
    double px, pa, pb;
    to_pixel(v, x, ya, &px, &pa);
    to_pixel(v, x, yb, &px, &pb);
    px = snap(px, p->width);
    lr_canvas_line(c, px, snap(pa, p->width) + p->extend, px,
                   snap(pb, p->width) - p->extend, p->width, p->colour, 0.0);
}

/* The part of world segment y = const, x in [xa, xb] inside the window. */
static void draw_hline(lr_canvas *c, const lr_frame *f, const view *v,
                       double y, double xa, double xb, const pen *p)
{
    double t = tolerance(f->wy0, f->wy1);
    if (y < f->wy0 - t || y > f->wy1 + t || !clip(&xa, &xb, f->wx0, f->wx1))
        return;
    double py, pa, pb;
    to_pixel(v, xa, y, &pa, &py);
    to_pixel(v, xb, y, &pb, &py);
    py = snap(py, p->width);
    lr_canvas_line(c, snap(pa, p->width) - p->extend, py,
                   snap(pb, p->width) + p->extend, py, p->width, p->colour, 0.0);
}

/* Interior line indices 1..n-1 whose position origin + i*h lies in
 * [lo, hi]; computed, not scanned, so a huge grid seen through a small
 * window costs nothing. Empty when *i0 > *i1. */
static void line_range(double origin, double h, int n, double lo, double hi,
                       int *i0, int *i1)
{
    /* the slack lets draw_vline/draw_hline judge lines on the window edge */
    double a = ceil((lo - origin) / h - 1e-6), b = floor((hi - origin) / h + 1e-6);
    *i0 = a > 1.0 ? (a < n ? (int)a : n) : 1;
    *i1 = b < n - 1.0 ? (b > 0.0 ? (int)b : 0) : n - 1;
}

static void draw_grid(lr_canvas *c, const lr_frame *f, const view *v)
{
    const lr_grid *g = f->grid;
    const pen cell = { 1.0, 0.0, GRID_GREY };
    const pen outline = { 2.0, 1.0, OUTLINE_GREY };
    double gx1 = g->x0 + g->nx * g->hx, gy1 = g->y0 + g->ny * g->hy;
    int i0, i1;
    if (v->s * g->hx >= MIN_CELL_PX) {
        line_range(g->x0, g->hx, g->nx, f->wx0, f->wx1, &i0, &i1);
        for (int i = i0; i <= i1; i++)
            draw_vline(c, f, v, g->x0 + i * g->hx, g->y0, gy1, &cell);
    }
    if (v->s * g->hy >= MIN_CELL_PX) {
        line_range(g->y0, g->hy, g->ny, f->wy0, f->wy1, &i0, &i1);
        for (int j = i0; j <= i1; j++)
            draw_hline(c, f, v, g->y0 + j * g->hy, g->x0, gx1, &cell);
    }
    draw_vline(c, f, v, g->x0, g->y0, gy1, &outline);
    draw_vline(c, f, v, gx1, g->y0, gy1, &outline);
    draw_hline(c, f, v, g->y0, g->x0, gx1, &outline);
    draw_hline(c, f, v, gy1, g->x0, gx1, &outline);
}

/* ---- particles and text ----------------------------------------------- */

/* Converted in fixed chunks so a million particles need no big buffers. */
static int draw_particles(lr_canvas *c, const lr_frame *f, const view *v)
{
    if (f->n == 0)
        return 0;
    double *px = malloc(PARTICLE_CHUNK * sizeof *px);
    double *py = malloc(PARTICLE_CHUNK * sizeof *py);
    lr_rgba *colour = malloc(PARTICLE_CHUNK * sizeof *colour);
    int rc = px && py && colour ? 0 : -1;
    double r = fmax(1.0, f->radius * v->s);
    double reach = r / v->s;    /* a disc partly inside the window is shown */
    size_t k = 0;
    for (size_t i = 0; i < f->n && rc == 0; i++) {
        double x = f->x[i], y = f->y[i];
        if (!(x >= f->wx0 - reach && x <= f->wx1 + reach &&
              y >= f->wy0 - reach && y <= f->wy1 + reach))
            continue;   /* outside, or NaN */
        to_pixel(v, x, y, &px[k], &py[k]);
        colour[k] = lr_palette(f->group ? f->group[i] : 0);
        if (++k == PARTICLE_CHUNK) {
            lr_canvas_discs(c, k, px, py, r, colour);
            k = 0;
        }
    }
    if (rc == 0 && k > 0)
        lr_canvas_discs(c, k, px, py, r, colour);
    free(px);
    free(py);
    free(colour);
    return rc;
}

/* Label bottom-left, title centred on top, each in its reserved band. */
static void draw_label(lr_canvas *c, const lr_frame *f, const view *v)
{
    if (has_text(f->label))
        lr_canvas_text(c, v->margin, f->height - v->margin - 0.3 * v->font,
                       v->font, TEXT_GREY, LR_ALIGN_LEFT, f->label);
    if (has_text(f->title))
        lr_canvas_text(c, 0.5 * f->width, v->margin + v->font, v->font,
                       TEXT_GREY, LR_ALIGN_CENTER, f->title);
}

/* Draws the frame; the pixels (straight RGBA) or NULL with err set. */
static unsigned char *render(const lr_frame *f, const view *v, const char *path,
                             char *err, size_t errlen)
{
    char why[256] = "";
    lr_canvas *c = lr_canvas_cairo_new(f->width, f->height, why, sizeof why);
    if (!c) {
        set_err(err, errlen, "cannot write '%s': %s", path, why);
        return NULL;
    }
    lr_canvas_clear(c, BACKGROUND);
    if (f->grid)
        draw_grid(c, f, v);
    int rc = draw_particles(c, f, v);
    draw_label(c, f, v);
    unsigned char *rgba = rc == 0 ? lr_canvas_read_rgba(c) : NULL;
    lr_canvas_free(c);
    if (!rgba)
        set_err(err, errlen, "cannot write '%s': drawing failed (out of "
                "memory)", path);
    return rgba;
}

int lr_frame_write(const lr_frame *f, const char *path, char *err, size_t errlen)
{
    if (!f || !path || !*path) {
        set_err(err, errlen, "cannot write frame: %s",
                f ? "empty path" : "no frame");
        return -1;
    }
    const char *problem = frame_problem(f);
    if (problem) {
        set_err(err, errlen, "cannot write '%s': %s", path, problem);
        return -1;
    }
    view v;
    if (fit_view(f, &v) != 0) {
        set_err(err, errlen, "cannot write '%s': image %dx%d is too small for "
                "the frame", path, f->width, f->height);
        return -1;
    }
    unsigned char *rgba = render(f, &v, path, err, errlen);
    if (!rgba)
        return -1;
    int rc = lr_png_write(path, f->width, f->height, rgba, f->text, f->ntext,
                          err, errlen);
    free(rgba);
    return rc;
}
