/* plot.c - drawing a time-series plot: layout, axes, grid, series, legend.
 *
 * Everything is drawn through the lr_canvas interface, so plots look like
 * frames (same font, same antialiasing) and will follow the canvas to other
 * backends. Two things the canvas does not offer are done here:
 *
 * - text widths, needed to lay out tick labels and the legend: measured
 *   with a private cairo context set up like the canvas's (same face, no
 *   hinting, unhinted metrics), so the numbers match what the canvas draws;
 * - polylines: a series is drawn as straight pieces with lr_canvas_line.
 *   To keep that fast and true for long series, points are first reduced
 *   per pixel column to the first, lowest, highest and last (so every spike
 *   stays visible), then nearly collinear runs are merged, then each piece
 *   is clipped to the plot area and, for dashed series, cut into dashes
 *   here (a dash pattern restarted on every short piece would look solid).
 *   Pieces are lengthened by half the line width where they meet, which
 *   closes the notches and faint seams that butt-capped, separately
 *   antialiased pieces would otherwise leave at every joint. */
#include "plot.h"

#include <cairo.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "util.h"

static const lr_rgba WHITE = { 1.0, 1.0, 1.0, 1.0 };
static const lr_rgba TEXT = { 0.13, 0.13, 0.13, 1.0 };
static const lr_rgba FRAME = { 0.25, 0.25, 0.25, 1.0 };
static const lr_rgba GRID = { 0.88, 0.88, 0.88, 1.0 };
static const lr_rgba LEGEND_FILL = { 1.0, 1.0, 1.0, 0.92 };
static const lr_rgba LEGEND_EDGE = { 0.78, 0.78, 0.78, 1.0 };

#define DEFAULT_LINE_WIDTH 1.5
#define MAX_TICKS 64
#define X_PAD 0.0            /* auto x range: time axes end where the data do */
#define X_PAD_MARKERS 0.02   /* ...unless markers would be cut in half */
#define Y_PAD 0.05           /* auto y range: fraction of the span added each side */
#define SIMPLIFY_TOL 0.15    /* px: merged points stay this close to the line */
#define SIMPLIFY_RUN 128     /* points merged at most into one piece */
#define MARKER_BATCH 256
#define FAR_PX 1e300         /* beyond this a mapped point is unusable */
#define MIN_AREA_PX 20.0     /* smallest plot area worth drawing */

static int has_text(const char *s) { return s && *s; }

/* "series 2 ('analytic')" or "series 2", for messages. */
static void series_name(const lr_plot *p, size_t k, char *buf, size_t len)
{
    const char *label = p->series[k].label;
    if (has_text(label))
        snprintf(buf, len, "series %zu ('%s')", k + 1, label);
    else
        snprintf(buf, len, "series %zu", k + 1);
}

/* ---- validation and ranges -------------------------------------------- */

/* 0 if p can be drawn, else -1 with the reason in why. */
static int plot_problem(const lr_plot *p, const char *path, char *why, size_t len)
{
    if (p->width <= 0 || p->height <= 0 || p->width > 32767 || p->height > 32767) {
        snprintf(why, len, "invalid image size %dx%d (1..32767 each)", p->width,
                 p->height);
        return -1;
    }
    if (p->nseries == 0 || !p->series) {
        snprintf(why, len, "a plot needs at least one series");
        return -1;
    }
    for (size_t k = 0; k < p->nseries; k++) {
        const lr_plot_series *s = &p->series[k];
        char name[160];
        series_name(p, k, name, sizeof name);
        if (s->n == 0) {
            snprintf(why, len, "%s is empty", name);
            return -1;
        }
        if (!s->x || !s->y) {
            snprintf(why, len, "%s has no x or y array", name);
            return -1;
        }
        if (!isfinite(s->width) || s->width > 100.0) {
            snprintf(why, len, "%s: line width must be finite and at most 100 px",
                     name);
            return -1;
        }
    }
    if (p->fixed_x && !(isfinite(p->x0) && isfinite(p->x1) && p->x0 < p->x1 &&
                        isfinite(p->x1 - p->x0))) {
        snprintf(why, len, "x range [%g, %g] must be finite with x0 < x1", p->x0, p->x1);
        return -1;
    }
    if (p->fixed_y && !(isfinite(p->y0) && isfinite(p->y1) && p->y0 < p->y1 &&
                        isfinite(p->y1 - p->y0))) {
        snprintf(why, len, "y range [%g, %g] must be finite with y0 < y1", p->y0, p->y1);
        return -1;
    }
    if ((int)p->legend < 0 || p->legend > LR_LEGEND_NONE) {
        snprintf(why, len, "unknown legend position %d", (int)p->legend);
        return -1;
    }
    if (p->csv && (!*p->csv || strcmp(p->csv, path) == 0)) {
        snprintf(why, len, "the CSV path must be a file other than the image");
        return -1;
    }
    return 0;
}

/* The range of the finite values on one axis (0: x, 1: y). When the other
 * axis is fixed only the points it shows count, so zooming into a time
 * window also fits the values to what is seen. 0 if there are none. */
static int data_range(const lr_plot *p, int axis, int filter, double *lo, double *hi)
{
    int other_fixed = filter && (axis == 0 ? p->fixed_y : p->fixed_x);
    double olo = axis == 0 ? p->y0 : p->x0, ohi = axis == 0 ? p->y1 : p->x1;
    int found = 0;
    *lo = INFINITY;
    *hi = -INFINITY;
    for (size_t k = 0; k < p->nseries; k++) {
        const lr_plot_series *s = &p->series[k];
        const double *v = axis == 0 ? s->x : s->y, *o = axis == 0 ? s->y : s->x;
        for (size_t i = 0; i < s->n; i++) {
            if (!isfinite(v[i]) || !isfinite(o[i]))
                continue;
            if (other_fixed && !(o[i] >= olo && o[i] <= ohi))
                continue;
            *lo = fmin(*lo, v[i]);
            *hi = fmax(*hi, v[i]);
            found = 1;
        }
    }
    return found;
}

/* The automatic range: the data's, padded by `pad` of its span each side.
 * No data: [0, 1]. A single value (constant series, one point): 10 % of its
 * size each side (or [-1, 1] around zero), so the value sits mid-height
 * with readable ticks. -1 if the span overflows. */
static int auto_range(const lr_plot *p, int axis, double pad, double *lo, double *hi)
{
    if (!data_range(p, axis, 1, lo, hi) && !data_range(p, axis, 0, lo, hi)) {
        *lo = 0.0;
        *hi = 1.0;
        return 0;
    }
    double span = *hi - *lo;
    if (!isfinite(span))
        return -1;
    if (span <= 1e-12 * fmax(fabs(*lo), fabs(*hi))) {
        double c = 0.5 * *lo + 0.5 * *hi;
        double half = c != 0.0 ? 0.1 * fabs(c) : 1.0;
        *lo = c - half;
        *hi = c + half;
    } else {
        *lo -= pad * span;
        *hi += pad * span;
    }
    return isfinite(*lo) && isfinite(*hi) && isfinite(*hi - *lo) ? 0 : -1;
}

/* ---- text widths ---------------------------------------------------------- */

typedef struct meter {
    cairo_surface_t *surface;
    cairo_t *cr;
} meter;

/* Mirrors the canvas's font setup (canvas_cairo.c): what is measured here
 * is what the canvas draws. A failure only makes widths estimates. */
static void meter_open(meter *m)
{
    m->surface = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
    m->cr = cairo_create(m->surface);
    cairo_font_options_t *fo = cairo_font_options_create();
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_antialias(fo, CAIRO_ANTIALIAS_GRAY);
    cairo_set_font_options(m->cr, fo);
    cairo_font_options_destroy(fo);
    cairo_select_font_face(m->cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                           CAIRO_FONT_WEIGHT_NORMAL);
}

static void meter_close(meter *m)
{
    cairo_destroy(m->cr);
    cairo_surface_destroy(m->surface);
}

/* Length of the UTF-8 sequence at s if cairo accepts it (well-formed, no
 * surrogate, at most U+10FFFF, no noncharacter), else 0. cairo's errors
 * stick to the context, so nothing it would reject is passed to it. */
static size_t utf8_seq(const unsigned char *s)
{
    if (s[0] < 0x80)
        return 1;
    size_t n;
    uint32_t cp, lowest;
    if (s[0] >= 0xC2 && s[0] <= 0xDF) { n = 2; cp = s[0] & 0x1Fu; lowest = 0x80; }
    else if ((s[0] & 0xF0) == 0xE0) { n = 3; cp = s[0] & 0x0Fu; lowest = 0x800; }
    else if (s[0] >= 0xF0 && s[0] <= 0xF4) { n = 4; cp = s[0] & 0x07u; lowest = 0x10000; }
    else return 0;
    for (size_t i = 1; i < n; i++) {
        if ((s[i] & 0xC0) != 0x80)
            return 0;
        cp = cp << 6 | (s[i] & 0x3Fu);
    }
    if (cp < lowest || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF) ||
        (cp >= 0xFDD0 && cp <= 0xFDEF) || (cp & 0xFFFE) == 0xFFFE)
        return 0;
    return n;
}

/* Characters in s (a rejected byte counts as one, as the canvas shows it
 * as '?'); sets *valid to whether all of s is acceptable. */
static size_t utf8_count(const char *s, int *valid)
{
    const unsigned char *u = (const unsigned char *)s;
    size_t count = 0;
    *valid = 1;
    while (*u) {
        size_t k = utf8_seq(u);
        if (k == 0) {
            *valid = 0;
            k = 1;
        }
        u += k;
        count++;
    }
    return count;
}

/* The advance width of s at size px, as lr_canvas_text will draw it. */
static double text_width(meter *m, double size, const char *s)
{
    if (!has_text(s))
        return 0.0;
    int valid;
    size_t chars = utf8_count(s, &valid);
    if (valid && cairo_status(m->cr) == CAIRO_STATUS_SUCCESS) {
        cairo_text_extents_t e;
        cairo_set_font_size(m->cr, size);
        cairo_text_extents(m->cr, s, &e);
        if (cairo_status(m->cr) == CAIRO_STATUS_SUCCESS)
            return e.x_advance;
    }
    return 0.62 * size * (double)chars;   /* DejaVu Sans's digits are 0.64 em */
}

/* ---- layout ------------------------------------------------------------- */

typedef struct axis {
    double lo, hi;
    int n;
    double step;
    double t[MAX_TICKS];
    char label[MAX_TICKS][LR_TICK_LABEL_MAX];
    double width[MAX_TICKS];    /* of each label, pixels */
} axis;

typedef struct layout {
    double font, title_font, legend_font;
    double pad, tick_len;
    double l, t, r, b;          /* plot area: left, top, right, bottom edges */
    axis x, y;
} layout;

static double map_x(const layout *L, double v)
{
    return L->l + (v - L->x.lo) / (L->x.hi - L->x.lo) * (L->r - L->l);
}

static double map_y(const layout *L, double v)
{
    return L->b - (v - L->y.lo) / (L->y.hi - L->y.lo) * (L->b - L->t);
}

static void compute_ticks(axis *a, int intervals, meter *m, double font)
{
    a->n = lr_plot_ticks(a->lo, a->hi, intervals, a->t, MAX_TICKS, &a->step);
    if (a->n < 0)
        a->n = 0;
    lr_plot_tick_labels(a->t, a->n, a->step, a->label);
    for (int i = 0; i < a->n; i++)
        a->width[i] = text_width(m, font, a->label[i]);
}

/* Horizontal labels must not touch: a gap of one font size between them. */
static int x_labels_fit(const axis *a, double len, double font)
{
    double px_per_step = len * a->step / (a->hi - a->lo);
    for (int i = 0; i + 1 < a->n; i++)
        if (0.5 * (a->width[i] + a->width[i + 1]) + font > px_per_step)
            return 0;
    return 1;
}

/* Ticks for an axis `len` pixels long, about one per `spacing` pixels;
 * fewer while x labels would collide, more while fewer than two ticks
 * would show (a scale needs two readings). */
static void axis_ticks(axis *a, double len, double spacing, int horizontal, meter *m,
                       double font)
{
    int k = (int)(len / spacing);
    k = k < 1 ? 1 : k > MAX_TICKS - 2 ? MAX_TICKS - 2 : k;
    compute_ticks(a, k, m, font);
    while (horizontal && k > 1 && !x_labels_fit(a, len, font))
        compute_ticks(a, --k, m, font);
    while (a->n < 2 && k < MAX_TICKS - 2)
        compute_ticks(a, ++k, m, font);
}

static double max_width(const axis *a)
{
    double w = 0.0;
    for (int i = 0; i < a->n; i++)
        w = fmax(w, a->width[i]);
    return w;
}

/* Places the plot area and the ticks; -1 if the image is too small. */
static int lay_out(const lr_plot *p, layout *L, meter *m)
{
    double W = p->width, H = p->height;
    L->font = fmin(48.0, fmax(10.0, fmin(W * 0.625, H) / 40.0));
    L->title_font = 1.25 * L->font;
    L->legend_font = 0.95 * L->font;
    L->pad = 0.8 * L->font;
    L->tick_len = 0.4 * L->font;
    L->t = L->pad + (has_text(p->title) ? 1.5 * L->title_font : 0.0) +
           (has_text(p->ylabel) ? 2.0 * L->font : 0.6 * L->font);
    L->b = H - L->pad - L->tick_len - 1.4 * L->font -
           (has_text(p->xlabel) ? 1.5 * L->font : 0.0);
    if (L->b - L->t < MIN_AREA_PX)
        return -1;
    axis_ticks(&L->y, L->b - L->t, fmax(50.0, 4.0 * L->font), 0, m, L->font);
    L->l = L->pad + max_width(&L->y) + L->tick_len + 0.4 * L->font;
    L->r = W - L->pad;
    for (int pass = 0; pass < 2; pass++) {
        if (L->r - L->l < MIN_AREA_PX)
            return -1;
        axis_ticks(&L->x, L->r - L->l, fmax(80.0, 6.0 * L->font), 1, m, L->font);
        if (L->x.n == 0)
            break;
        /* the last label is centred on its tick: keep it inside the image */
        double over = map_x(L, L->x.t[L->x.n - 1]) + 0.5 * L->x.width[L->x.n - 1] -
                      (W - 0.5 * L->pad);
        if (over <= 0.0)
            break;
        L->r -= over;
    }
    return L->r - L->l < MIN_AREA_PX ? -1 : 0;
}

/* ---- pieces, dashes, clipping ------------------------------------------ */

typedef struct pen {
    lr_canvas *c;
    double cl, ct, cr, cb;      /* clip rectangle */
    double width;
    lr_rgba colour;
    int dashed;
    double on, off, phase;      /* dash and gap length; where in the period */
} pen;

/* One straight piece; an end that is a joint (the line goes on from there)
 * is lengthened by half the width to close the joint. */
static void draw_piece(pen *pn, double ax, double ay, double bx, double by,
                       int joint_a, int joint_b)
{
    double dx = bx - ax, dy = by - ay, len = hypot(dx, dy);
    if (!(len > 0.0))
        return;
    double ext = 0.5 * pn->width, ux = dx / len, uy = dy / len;
    if (joint_a) {
        ax -= ext * ux;
        ay -= ext * uy;
    }
    if (joint_b) {
        bx += ext * ux;
        by += ext * uy;
    }
    lr_canvas_line(pn->c, ax, ay, bx, by, pn->width, pn->colour, 0.0);
}

/* A clipped segment, solid or cut into dashes that continue the pattern
 * of the previous segment. */
static void dash_segment(pen *pn, double ax, double ay, double bx, double by,
                         int joint_a, int joint_b)
{
    if (!pn->dashed) {
        draw_piece(pn, ax, ay, bx, by, joint_a, joint_b);
        return;
    }
    double len = hypot(bx - ax, by - ay), period = pn->on + pn->off, pos = 0.0;
    if (!(len > 0.0))
        return;
    while (pos < len) {
        double step;
        if (pn->phase < pn->on) {
            step = fmin(pn->on - pn->phase, len - pos);
            double t0 = pos / len, t1 = (pos + step) / len;
            int ja = pos == 0.0 && joint_a && pn->phase > 0.0;
            int jb = pos + step >= len && joint_b && pn->phase + step < pn->on;
            draw_piece(pn, ax + t0 * (bx - ax), ay + t0 * (by - ay),
                       ax + t1 * (bx - ax), ay + t1 * (by - ay), ja, jb);
        } else {
            step = fmin(period - pn->phase, len - pos);
        }
        pos += step;
        pn->phase += step;
        if (pn->phase >= period)
            pn->phase -= period;
    }
}

/* Liang-Barsky: the parameters [*t0, *t1] of the part of a->b inside the
 * rectangle [l, r] x [t, b]; 0 if no part is. */
static int clip_params(double ax, double ay, double bx, double by, double l, double t,
                       double r, double b, double *t0, double *t1)
{
    double dx = bx - ax, dy = by - ay;
    if (!isfinite(dx) || !isfinite(dy))
        return 0;
    const double pq[4][2] = { { -dx, ax - l }, { dx, r - ax },
                              { -dy, ay - t }, { dy, b - ay } };
    *t0 = 0.0;
    *t1 = 1.0;
    for (int i = 0; i < 4; i++) {
        double pp = pq[i][0], q = pq[i][1];
        if (pp == 0.0) {
            if (q < 0.0)
                return 0;   /* parallel to this edge and outside it */
            continue;
        }
        double u = q / pp;
        if (pp < 0.0) {
            if (u > *t1)
                return 0;
            if (u > *t0)
                *t0 = u;
        } else {
            if (u < *t0)
                return 0;
            if (u < *t1)
                *t1 = u;
        }
    }
    return 1;
}

/* The part of a->b inside the clip rectangle; an end cut by the rectangle
 * is no joint. */
static void clip_segment(pen *pn, double ax, double ay, double bx, double by,
                         int joint_a, int joint_b)
{
    double t0, t1;
    if (!clip_params(ax, ay, bx, by, pn->cl, pn->ct, pn->cr, pn->cb, &t0, &t1))
        return;
    if (t0 > 0.0)
        joint_a = 0;
    if (t1 < 1.0)
        joint_b = 0;
    double dx = bx - ax, dy = by - ay;
    dash_segment(pn, ax + t0 * dx, ay + t0 * dy, ax + t1 * dx, ay + t1 * dy,
                 joint_a, joint_b);
}

static int inside(const pen *pn, double x, double y)
{
    return x >= pn->cl && x <= pn->cr && y >= pn->ct && y <= pn->cb;
}

static void dot(pen *pn, double x, double y, double r)
{
    if (inside(pn, x, y))
        lr_canvas_discs(pn->c, 1, &x, &y, r, &pn->colour);
}

/* ---- polyline simplification ------------------------------------------- */

/* Merges runs of points that stay within SIMPLIFY_TOL of one straight
 * piece; what it emits goes to clip_segment. One polyline at a time. */
typedef struct simp {
    pen *pn;
    int started, pieces;
    double ax, ay;                      /* anchor: the last emitted vertex */
    int nb;
    double bx[SIMPLIFY_RUN], by[SIMPLIFY_RUN];  /* points since the anchor */
    double xmin, xmax, ymin, ymax;      /* extent, to spot a "line" that is a dot */
} simp;

/* Whether q lies within tol of the segment a-b (not just of its line, so
 * a path that doubles back is kept). Written so that overflow or NaN
 * answers "no". */
static int near_segment(double ax, double ay, double bx, double by, double qx,
                        double qy, double tol)
{
    double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
    double t = len2 > 0.0 ? ((qx - ax) * dx + (qy - ay) * dy) / len2 : 0.0;
    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    double ex = ax + t * dx - qx, ey = ay + t * dy - qy;
    return ex * ex + ey * ey <= tol * tol;
}

static void simp_emit(simp *s, double x, double y, int more)
{
    clip_segment(s->pn, s->ax, s->ay, x, y, s->pieces > 0, more);
    s->pieces++;
    s->ax = x;
    s->ay = y;
}

static void simp_add(simp *s, double x, double y)
{
    if (!s->started) {
        s->started = 1;
        s->pieces = 0;
        s->nb = 0;
        s->ax = s->xmin = s->xmax = x;
        s->ay = s->ymin = s->ymax = y;
        s->pn->phase = 0.0;
        return;
    }
    s->xmin = fmin(s->xmin, x);
    s->xmax = fmax(s->xmax, x);
    s->ymin = fmin(s->ymin, y);
    s->ymax = fmax(s->ymax, y);
    if (s->nb < SIMPLIFY_RUN) {
        int ok = 1;
        for (int i = 0; i < s->nb && ok; i++)
            ok = near_segment(s->ax, s->ay, x, y, s->bx[i], s->by[i], SIMPLIFY_TOL);
        if (ok) {
            s->bx[s->nb] = x;
            s->by[s->nb++] = y;
            return;
        }
    }
    simp_emit(s, s->bx[s->nb - 1], s->by[s->nb - 1], 1);
    s->bx[0] = x;
    s->by[0] = y;
    s->nb = 1;
}

/* Ends the polyline. One that covers less than a pixel (a single point, a
 * constant stretch between gaps) is drawn as a dot, so it is not lost. */
static void simp_end(simp *s)
{
    if (!s->started)
        return;
    if (s->nb > 0)
        simp_emit(s, s->bx[s->nb - 1], s->by[s->nb - 1], 0);
    if (s->xmax - s->xmin < 0.5 && s->ymax - s->ymin < 0.5)
        dot(s->pn, s->ax, s->ay, fmax(2.0, 1.2 * s->pn->width));
    s->started = 0;
}

/* ---- per-column reduction ---------------------------------------------- */

/* Consecutive points in one pixel column become at most four: the first,
 * the lowest, the highest (in their order) and the last. The drawn line
 * covers the same pixels, whatever the number of points. */
typedef struct column {
    int on;
    double col;
    double fx, fy, lx, ly, nx, ny, mx, my;      /* first, last, min, max */
    size_t fi, li, ni, mi;
} column;

static void column_flush(column *c, simp *s)
{
    if (!c->on)
        return;
    simp_add(s, c->fx, c->fy);
    int min_first = c->ni <= c->mi;
    size_t i1 = min_first ? c->ni : c->mi, i2 = min_first ? c->mi : c->ni;
    double x1 = min_first ? c->nx : c->mx, y1 = min_first ? c->ny : c->my;
    double x2 = min_first ? c->mx : c->nx, y2 = min_first ? c->my : c->ny;
    if (i1 != c->fi && i1 != c->li)
        simp_add(s, x1, y1);
    if (i2 != i1 && i2 != c->fi && i2 != c->li)
        simp_add(s, x2, y2);
    if (c->li != c->fi)
        simp_add(s, c->lx, c->ly);
    c->on = 0;
}

static void column_add(column *c, simp *s, double x, double y, size_t i)
{
    double col = floor(x);
    if (c->on && col == c->col) {
        c->lx = x;
        c->ly = y;
        c->li = i;
        if (y < c->ny) {
            c->nx = x;
            c->ny = y;
            c->ni = i;
        }
        if (y > c->my) {
            c->mx = x;
            c->my = y;
            c->mi = i;
        }
        return;
    }
    column_flush(c, s);
    c->on = 1;
    c->col = col;
    c->fx = c->lx = c->nx = c->mx = x;
    c->fy = c->ly = c->ny = c->my = y;
    c->fi = c->li = c->ni = c->mi = i;
}

/* ---- series ------------------------------------------------------------- */

static double line_width(const lr_plot_series *s)
{
    return s->width > 0.0 ? s->width : DEFAULT_LINE_WIDTH;
}

static double marker_radius(const lr_plot_series *s)
{
    return fmax(2.0, 1.5 * line_width(s));
}

static pen series_pen(lr_canvas *c, const lr_plot_series *s, double l, double t,
                      double r, double b)
{
    pen pn;
    memset(&pn, 0, sizeof pn);
    pn.c = c;
    pn.cl = l;
    pn.ct = t;
    pn.cr = r;
    pn.cb = b;
    pn.width = line_width(s);
    pn.colour = lr_palette(s->colour);
    pn.dashed = s->dashed;
    /* dashes long enough to read as a line, gaps wide enough to see */
    pn.on = fmax(6.0, 4.0 * pn.width);
    pn.off = fmax(4.0, 2.5 * pn.width);
    return pn;
}

/* The pixel position of point i; 0 if it is not finite (a gap). */
static int point_px(const layout *L, const lr_plot_series *s, size_t i, double *px,
                    double *py)
{
    if (!isfinite(s->x[i]) || !isfinite(s->y[i]))
        return 0;
    *px = map_x(L, s->x[i]);
    *py = map_y(L, s->y[i]);
    return fabs(*px) < FAR_PX && fabs(*py) < FAR_PX;
}

static void draw_line_series(lr_canvas *c, const layout *L, const lr_plot_series *s)
{
    pen pn = series_pen(c, s, L->l, L->t, L->r, L->b);
    simp *sp = calloc(1, sizeof *sp);   /* ~2 kB of run buffer: off the stack */
    if (!sp)
        return;
    sp->pn = &pn;
    column col = { 0 };
    for (size_t i = 0; i < s->n; i++) {
        double px, py;
        if (point_px(L, s, i, &px, &py)) {
            column_add(&col, sp, px, py, i);
        } else {
            column_flush(&col, sp);
            simp_end(sp);
        }
    }
    column_flush(&col, sp);
    simp_end(sp);
    free(sp);
}

static void draw_marker_series(lr_canvas *c, const layout *L, const lr_plot_series *s)
{
    double px[MARKER_BATCH], py[MARKER_BATCH];
    lr_rgba colour[MARKER_BATCH];
    lr_rgba k = lr_palette(s->colour);
    double r = marker_radius(s);
    double lastx = NAN, lasty = NAN;
    int n = 0;
    for (size_t i = 0; i < s->n; i++) {
        double x, y;
        if (!point_px(L, s, i, &x, &y) || x < L->l || x > L->r || y < L->t || y > L->b)
            continue;
        /* many points on one spot (a long series) draw one disc */
        double qx = floor(4.0 * x), qy = floor(4.0 * y);
        if (qx == lastx && qy == lasty)
            continue;
        lastx = qx;
        lasty = qy;
        px[n] = x;
        py[n] = y;
        colour[n] = k;
        if (++n == MARKER_BATCH) {
            lr_canvas_discs(c, (size_t)n, px, py, r, colour);
            n = 0;
        }
    }
    if (n > 0)
        lr_canvas_discs(c, (size_t)n, px, py, r, colour);
}

/* ---- axes ------------------------------------------------------------- */

/* A 1-px line on a pixel centre is one crisp pixel wide. */
static double crisp(double p) { return floor(p) + 0.5; }

/* A filled rectangle: a butt-capped line as wide as the rectangle is tall
 * (the canvas strokes rectangles but does not fill them). */
static void fill_rect(lr_canvas *c, double x, double y, double w, double h, lr_rgba k)
{
    lr_canvas_line(c, x, y + 0.5 * h, x + w, y + 0.5 * h, h, k, 0.0);
}

static void draw_grid(lr_canvas *c, const layout *L)
{
    for (int i = 0; i < L->x.n; i++) {
        double px = crisp(map_x(L, L->x.t[i]));
        if (px > L->l + 1.0 && px < L->r - 1.0)     /* not on the frame */
            lr_canvas_line(c, px, L->t, px, L->b, 1.0, GRID, 0.0);
    }
    for (int i = 0; i < L->y.n; i++) {
        double py = crisp(map_y(L, L->y.t[i]));
        if (py > L->t + 1.0 && py < L->b - 1.0)
            lr_canvas_line(c, L->l, py, L->r, py, 1.0, GRID, 0.0);
    }
}

static void draw_axes(lr_canvas *c, const lr_plot *p, const layout *L)
{
    double f = L->font;
    /* the frame on pixel centres: its 1-px lines are crisp */
    double l = crisp(L->l), t = crisp(L->t), r = crisp(L->r), b = crisp(L->b);
    lr_canvas_rect(c, l, t, r - l, b - t, 1.0, FRAME);
    for (int i = 0; i < L->x.n; i++) {
        double px = crisp(map_x(L, L->x.t[i]));
        lr_canvas_line(c, px, b, px, b + L->tick_len, 1.0, FRAME, 0.0);
        lr_canvas_text(c, map_x(L, L->x.t[i]), b + L->tick_len + 0.3 * f + 0.95 * f, f,
                       TEXT, LR_ALIGN_CENTER, L->x.label[i]);
    }
    for (int i = 0; i < L->y.n; i++) {
        double py = crisp(map_y(L, L->y.t[i]));
        lr_canvas_line(c, l - L->tick_len, py, l, py, 1.0, FRAME, 0.0);
        /* digits are ~0.73 em tall: this baseline centres them on the tick */
        lr_canvas_text(c, l - L->tick_len - 0.35 * f, map_y(L, L->y.t[i]) + 0.36 * f,
                       f, TEXT, LR_ALIGN_RIGHT, L->y.label[i]);
    }
    if (has_text(p->xlabel))
        lr_canvas_text(c, 0.5 * (L->l + L->r), p->height - L->pad - 0.25 * f, f, TEXT,
                       LR_ALIGN_CENTER, p->xlabel);
    /* The canvas has no rotated text: the y label heads the y axis, above
     * its tick labels, as in many physics papers. */
    if (has_text(p->ylabel))
        lr_canvas_text(c, L->pad, L->t - 0.95 * f, f, TEXT, LR_ALIGN_LEFT, p->ylabel);
    if (has_text(p->title))
        lr_canvas_text(c, 0.5 * p->width, L->pad + 0.95 * L->title_font,
                       L->title_font, TEXT, LR_ALIGN_CENTER, p->title);
}

/* ---- legend ----------------------------------------------------------- */

static void draw_sample(lr_canvas *c, const lr_plot_series *s, double x0, double x1,
                        double y)
{
    pen pn = series_pen(c, s, 0.0, 0.0, lr_canvas_width(c), lr_canvas_height(c));
    if (s->markers) {
        double px = 0.5 * (x0 + x1);
        lr_canvas_discs(c, 1, &px, &y, marker_radius(s), &pn.colour);
        return;
    }
    /* whole dashes, centred, so the sample looks like the pattern */
    if (pn.dashed) {
        double len = x1 - x0, period = pn.on + pn.off;
        int k = (int)((len + pn.off) / period);
        if (k >= 1) {
            double used = k * period - pn.off;
            x0 += 0.5 * (len - used);
            x1 = x0 + used;
        }
    }
    dash_segment(&pn, x0, y, x1, y, 0, 0);
}

typedef struct box { double x, y, w, h; } box;

/* How much data a legend at b would hide: the line pieces crossing it and
 * the markers inside it. Long series are sampled (every k-th point), which
 * is plenty to tell a crowded corner from an empty one. */
static double legend_cost(const lr_plot *p, const layout *L, const box *b)
{
    double cost = 0.0, x1 = b->x + b->w, y1 = b->y + b->h;
    for (size_t k = 0; k < p->nseries; k++) {
        const lr_plot_series *s = &p->series[k];
        size_t stride = s->n > 4000 ? s->n / 2000 : 1;
        int have = 0;
        double qx = 0.0, qy = 0.0;
        for (size_t i = 0; i < s->n; i += stride) {
            double px, py, t0, t1;
            if (!point_px(L, s, i, &px, &py)) {
                have = 0;
                continue;
            }
            if (s->markers)
                cost += px >= b->x && px <= x1 && py >= b->y && py <= y1;
            else if (have && clip_params(qx, qy, px, py, b->x, b->y, x1, y1, &t0, &t1))
                cost += 1.0;
            qx = px;
            qy = py;
            have = 1;
        }
    }
    return cost;
}

/* The legend box at position pos (not BEST or NONE). */
static box legend_at(const layout *L, lr_legend pos, double w, double h)
{
    double inset = 0.6 * L->font;
    box b = { 0.0, 0.0, w, h };
    switch (pos) {
    case LR_LEGEND_TOP_LEFT: case LR_LEGEND_LEFT: case LR_LEGEND_BOTTOM_LEFT:
        b.x = L->l + inset;
        break;
    case LR_LEGEND_TOP: case LR_LEGEND_CENTER: case LR_LEGEND_BOTTOM:
        b.x = 0.5 * (L->l + L->r - w);
        break;
    default:
        b.x = L->r - inset - w;
    }
    switch (pos) {
    case LR_LEGEND_BOTTOM_LEFT: case LR_LEGEND_BOTTOM: case LR_LEGEND_BOTTOM_RIGHT:
        b.y = L->b - inset - h;
        break;
    case LR_LEGEND_LEFT: case LR_LEGEND_CENTER: case LR_LEGEND_RIGHT:
        b.y = 0.5 * (L->t + L->b - h);
        break;
    default:
        b.y = L->t + inset;
    }
    /* whole pixels: the 1-px border is crisp */
    b.x = floor(b.x);
    b.y = floor(b.y);
    b.w = ceil(b.w);
    b.h = ceil(b.h);
    return b;
}

static box best_legend(const lr_plot *p, const layout *L, double w, double h)
{
    static const lr_legend order[] = {
        LR_LEGEND_TOP_RIGHT, LR_LEGEND_TOP_LEFT, LR_LEGEND_BOTTOM_RIGHT,
        LR_LEGEND_BOTTOM_LEFT, LR_LEGEND_RIGHT, LR_LEGEND_LEFT, LR_LEGEND_TOP,
        LR_LEGEND_BOTTOM, LR_LEGEND_CENTER
    };
    box best = legend_at(L, order[0], w, h);
    double least = legend_cost(p, L, &best);
    for (size_t i = 1; i < sizeof order / sizeof order[0] && least > 0.0; i++) {
        box b = legend_at(L, order[i], w, h);
        double cost = legend_cost(p, L, &b);
        if (cost < least) {
            least = cost;
            best = b;
        }
    }
    return best;
}

static void draw_legend(lr_canvas *c, const lr_plot *p, const layout *L, meter *m)
{
    if (p->legend == LR_LEGEND_NONE)
        return;
    double f = L->legend_font, labw = 0.0;
    int rows = 0;
    for (size_t k = 0; k < p->nseries; k++)
        if (has_text(p->series[k].label)) {
            labw = fmax(labw, text_width(m, f, p->series[k].label));
            rows++;
        }
    if (rows == 0)
        return;
    double row = 1.5 * f, inner = 0.6 * f, sample = fmax(30.0, 2.6 * f);
    double w = inner + sample + 0.6 * f + labw + inner, h = rows * row + inner;
    box b = p->legend == LR_LEGEND_BEST ? best_legend(p, L, w, h)
                                        : legend_at(L, p->legend, w, h);
    fill_rect(c, b.x, b.y, b.w, b.h, LEGEND_FILL);
    lr_canvas_rect(c, b.x + 0.5, b.y + 0.5, b.w - 1.0, b.h - 1.0, 1.0, LEGEND_EDGE);
    int i = 0;
    for (size_t k = 0; k < p->nseries; k++) {
        const lr_plot_series *s = &p->series[k];
        if (!has_text(s->label))
            continue;
        double cy = b.y + 0.5 * inner + row * (i++ + 0.5);
        draw_sample(c, s, b.x + inner, b.x + inner + sample, cy);
        lr_canvas_text(c, b.x + inner + sample + 0.6 * f, cy + 0.36 * f, f, TEXT,
                       LR_ALIGN_LEFT, s->label);
    }
}

/* ---- the plot --------------------------------------------------------- */

/* Draws everything; the pixels (straight RGBA) or NULL with why set. */
static unsigned char *render(const lr_plot *p, layout *L, meter *m, char *why,
                             size_t len)
{
    lr_canvas *c = lr_canvas_cairo_new(p->width, p->height, why, len);
    if (!c)
        return NULL;
    lr_canvas_clear(c, WHITE);
    draw_grid(c, L);
    for (size_t k = 0; k < p->nseries; k++) {
        if (p->series[k].markers)
            draw_marker_series(c, L, &p->series[k]);
        else
            draw_line_series(c, L, &p->series[k]);
    }
    draw_axes(c, p, L);     /* after the data: the frame stays on top */
    draw_legend(c, p, L, m);
    unsigned char *rgba = lr_canvas_read_rgba(c);
    lr_canvas_free(c);
    if (!rgba)
        snprintf(why, len, "drawing failed (out of memory)");
    return rgba;
}

int lr_plot_write(const lr_plot *p, const char *path, const lr_text_chunk *text,
                  size_t ntext, char *err, size_t errlen)
{
    if (!p || !path || !*path) {
        lu_err(err, errlen, "cannot write plot: %s", p ? "empty path" : "no plot");
        return -1;
    }
    char why[512] = "";
    if (plot_problem(p, path, why, sizeof why) != 0) {
        lu_err(err, errlen, "cannot write '%s': %s", path, why);
        return -1;
    }
    layout *L = calloc(1, sizeof *L);   /* tick tables: a few kB */
    if (!L) {
        lu_err(err, errlen, "cannot write '%s': out of memory", path);
        return -1;
    }
    if (p->fixed_x) {
        L->x.lo = p->x0;
        L->x.hi = p->x1;
    } else {
        int markers = 0;
        for (size_t k = 0; k < p->nseries; k++)
            markers |= p->series[k].markers;
        if (auto_range(p, 0, markers ? X_PAD_MARKERS : X_PAD, &L->x.lo, &L->x.hi))
            snprintf(why, sizeof why, "the x values span more than a double can hold");
    }
    if (p->fixed_y) {
        L->y.lo = p->y0;
        L->y.hi = p->y1;
    } else if (auto_range(p, 1, Y_PAD, &L->y.lo, &L->y.hi)) {
        snprintf(why, sizeof why, "the y values span more than a double can hold");
    }
    unsigned char *rgba = NULL;
    if (!why[0]) {
        meter m;
        meter_open(&m);
        if (lay_out(p, L, &m) != 0)
            snprintf(why, sizeof why, "image %dx%d is too small for the plot",
                     p->width, p->height);
        else
            rgba = render(p, L, &m, why, sizeof why);
        meter_close(&m);
    }
    free(L);
    if (!rgba) {
        lu_err(err, errlen, "cannot write '%s': %s", path, why);
        return -1;
    }
    int rc = lr_image_write(path, p->width, p->height, rgba, text, ntext, err, errlen);
    free(rgba);
    /* the plot is its picture and its data: a CSV that cannot be written
     * (a full disk) takes the picture with it (issue 31 item 6) */
    if (rc == 0 && p->csv && (rc = lr_plot_write_csv(p, p->csv, err, errlen)) != 0)
        unlink(path);
    return rc;
}
