/* figure_layers.c - a panel's layers in pixels: grid, particles, curves,
 * arrows, each possibly a mirror copy.
 *
 * The grid and particle drawing is frame.c's, moved here unchanged in its
 * arithmetic, so single-panel frames keep their exact pixels: lines are
 * snapped to the pixel grid so that 1-px grid lines are crisp instead of
 * 2-px grey smears, and particles are converted in fixed chunks. */
#include "figure_internal.h"

#include <math.h>
#include <stdlib.h>

#define MIN_CELL_PX 3.0     /* denser grid lines would just paint grey */
#define PARTICLE_CHUNK 4096 /* particles converted per lr_canvas_discs call */
#define HEAD_HALF_ANGLE 0.4363323129985824   /* 25 degrees */

/* ---- grid ------------------------------------------------------------- */

typedef struct pen {
    double width;       /* pixels */
    double extend;      /* pixels added at both ends (to close corners) */
    lr_rgba colour;
    double dash;        /* pixels; 0: solid */
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

/* The part of a grid line inside the window: x = at, y in [a, b] when
 * vertical, else y = at, x in [a, b]. Its ends are snapped and lengthened
 * by the pen's extend outwards (pixel y runs down, so a vertical line's
 * low end is its larger pixel y). */
static void draw_axis_line(lr_canvas *c, const fig_view *v, int vertical, double at,
                           double a, double b, const pen *p)
{
    const double at0 = vertical ? v->wx0 : v->wy0, at1 = vertical ? v->wx1 : v->wy1;
    const double lo = vertical ? v->wy0 : v->wx0, hi = vertical ? v->wy1 : v->wx1;
    double t = tolerance(at0, at1);
    if (at < at0 - t || at > at1 + t || !clip(&a, &b, lo, hi))
        return;
    double pa[2], pb[2];   /* pixel x, y of the two ends */
    if (vertical) {
        fig_to_pixel(v, at, a, &pa[0], &pa[1]);
        fig_to_pixel(v, at, b, &pb[0], &pb[1]);
    } else {
        fig_to_pixel(v, a, at, &pa[0], &pa[1]);
        fig_to_pixel(v, b, at, &pb[0], &pb[1]);
    }
    const int along = vertical ? 1 : 0;
    const double fixed = snap(pb[1 - along], p->width);
    const double ext = vertical ? p->extend : -p->extend;
    const double ea = snap(pa[along], p->width) + ext, eb = snap(pb[along], p->width) - ext;
    if (vertical)
        lr_canvas_line(c, fixed, ea, fixed, eb, p->width, p->colour, p->dash);
    else
        lr_canvas_line(c, ea, fixed, eb, fixed, p->width, p->colour, p->dash);
}

/* Interior line indices 1..n-1 whose position origin + i*h lies in
 * [lo, hi]; computed, not scanned, so a huge grid seen through a small
 * window costs nothing. Empty when *i0 > *i1. */
static void line_range(double origin, double h, int n, double lo, double hi,
                       int *i0, int *i1)
{
    /* the slack lets draw_axis_line judge lines on the window edge */
    double a = ceil((lo - origin) / h - 1e-6), b = floor((hi - origin) / h + 1e-6);
    *i0 = a > 1.0 ? (a < n ? (int)a : n) : 1;
    *i1 = b < n - 1.0 ? (b > 0.0 ? (int)b : 0) : n - 1;
}

void fig_draw_grid(lr_canvas *c, const fig_view *v, const lr_grid *g, int skip)
{
    const pen cell = { 1.0, 0.0, LR_FIG_GRID, 0.0 };
    const pen outline = { 2.0, 1.0, LR_FIG_OUTLINE, 0.0 };
    double gx1 = g->x0 + g->nx * g->hx, gy1 = g->y0 + g->ny * g->hy;
    int i0, i1;
    if (v->s * g->hx >= MIN_CELL_PX) {
        line_range(g->x0, g->hx, g->nx, v->wx0, v->wx1, &i0, &i1);
        for (int i = i0; i <= i1; i++)
            draw_axis_line(c, v, 1, g->x0 + i * g->hx, g->y0, gy1, &cell);
    }
    if (v->s * g->hy >= MIN_CELL_PX) {
        line_range(g->y0, g->hy, g->ny, v->wy0, v->wy1, &i0, &i1);
        for (int j = i0; j <= i1; j++)
            draw_axis_line(c, v, 0, g->y0 + j * g->hy, g->x0, gx1, &cell);
    }
    /* The walls, left, right, bottom, top. A side skipped is no wall: on
     * the left and the bottom it is a mirror axis, marked by a dashed line;
     * on the right and the top it is left out. */
    const pen axis = { 1.0, 0.0, LR_FIG_OUTLINE, 6.0 };
    const struct { int skip, mirror, vertical; double at, a, b; } side[4] = {
        { FIG_SKIP_LEFT, 1, 1, g->x0, g->y0, gy1 }, { FIG_SKIP_RIGHT, 0, 1, gx1, g->y0, gy1 },
        { FIG_SKIP_BOTTOM, 1, 0, g->y0, g->x0, gx1 }, { FIG_SKIP_TOP, 0, 0, gy1, g->x0, gx1 },
    };
    for (int k = 0; k < 4; k++) {
        const pen *pn = !(skip & side[k].skip) ? &outline : side[k].mirror ? &axis : NULL;
        if (pn)
            draw_axis_line(c, v, side[k].vertical, side[k].at, side[k].a, side[k].b, pn);
    }
}

/* ---- particles -------------------------------------------------------- */

int fig_value_range(const lr_panel *p, double *lo, double *hi)
{
    int found = 0;
    double a = INFINITY, b = -INFINITY;
    for (int s = 0; s < (p->split ? 2 : 1); s++)
        for (size_t k = 0; k < p->side[s].npoints; k++) {
            const lr_points *pts = &p->side[s].points[k];
            if (!pts->value)
                continue;
            for (size_t i = 0; i < pts->n; i++)
                if (isfinite(pts->value[i])) {
                    a = fmin(a, pts->value[i]);
                    b = fmax(b, pts->value[i]);
                    found = 1;
                }
        }
    *lo = a;
    *hi = b;
    return found;
}

static lr_rgba point_colour(const lr_points *pts, size_t i, const lr_panel *p,
                            double vmin, double vmax)
{
    if (!pts->value)
        return lr_palette(pts->group ? pts->group[i] : 0);
    return lr_cmap_colour(p->cmap, (pts->value[i] - vmin) / (vmax - vmin));
}

static double point_radius(const lr_points *pts, size_t i)
{
    int g = pts->group ? pts->group[i] : 0;
    if (pts->group_radius && g >= 0 && g < pts->ngroups)
        return pts->group_radius[g];
    return pts->radius;
}

/* lr_points.band: from each point to its next one a band, the half at
 * each end in that end's colour, so that a membrane whose points are a
 * pixel or two apart still shows its colour along it (docs/api.md,
 * sim:frame `band`; issue 16 item 3). Over the discs; a half is drawn
 * only when its point is in the window. The pieces run a little past
 * their point (a quarter of the width) so that bends have no notches. */
static void draw_band(lr_canvas *c, const fig_view *v, const fig_mirror *m,
                      const lr_points *pts, const lr_panel *p, double vmin, double vmax)
{
    double w = pts->band, ext = 0.25 * w;
    for (size_t i = 0; i < pts->n; i++) {
        long j = pts->next[i];
        if (j < 0 || (size_t)j >= pts->n || (size_t)j == i)
            continue;
        double ends[2][2];
        size_t id[2] = { i, (size_t)j };
        int inside[2];
        for (int e = 0; e < 2; e++) {
            double x = fig_mx(m, pts->x[id[e]]), y = fig_my(m, pts->y[id[e]]);
            inside[e] = x >= v->wx0 && x <= v->wx1 && y >= v->wy0 && y <= v->wy1;
            fig_to_pixel(v, x, y, &ends[e][0], &ends[e][1]);
        }
        double dx = ends[1][0] - ends[0][0], dy = ends[1][1] - ends[0][1];
        double len = hypot(dx, dy);
        if (!(len > 0) || !isfinite(len))
            continue;
        double ux = dx / len, uy = dy / len;
        double mx = 0.5 * (ends[0][0] + ends[1][0]), my = 0.5 * (ends[0][1] + ends[1][1]);
        for (int e = 0; e < 2; e++) {
            if (!inside[e])
                continue;
            double s = e == 0 ? -1.0 : 1.0;   /* outward from the middle */
            lr_canvas_line(c, mx, my, ends[e][0] + s * ext * ux, ends[e][1] + s * ext * uy,
                           w, point_colour(pts, id[e], p, vmin, vmax), 0.0);
        }
    }
}

/* Converted in fixed chunks so a million particles need no big buffers; a
 * chunk is drawn when it is full or the next point's radius differs (bodies
 * with radii of their own, lr_points.group_radius). */
int fig_draw_points(lr_canvas *c, const fig_view *v, const fig_mirror *m,
                    const lr_points *pts, const lr_panel *p, double vmin, double vmax)
{
    if (pts->n == 0)
        return 0;
    double *px = malloc(PARTICLE_CHUNK * sizeof *px);
    double *py = malloc(PARTICLE_CHUNK * sizeof *py);
    lr_rgba *colour = malloc(PARTICLE_CHUNK * sizeof *colour);
    int rc = px && py && colour ? 0 : -1;
    double r = fmax(1.0, pts->radius * v->s);
    size_t k = 0;
    for (size_t i = 0; i < pts->n && rc == 0; i++) {
        double ri = fmax(1.0, point_radius(pts, i) * v->s);
        if (ri != r && k > 0) {
            lr_canvas_discs(c, k, px, py, r, colour);
            k = 0;
        }
        r = ri;
        double reach = r / v->s;    /* a disc partly inside the window is shown */
        double x = fig_mx(m, pts->x[i]), y = fig_my(m, pts->y[i]);
        if (!(x >= v->wx0 - reach && x <= v->wx1 + reach &&
              y >= v->wy0 - reach && y <= v->wy1 + reach))
            continue;   /* outside, or NaN */
        fig_to_pixel(v, x, y, &px[k], &py[k]);
        colour[k] = point_colour(pts, i, p, vmin, vmax);
        if (++k == PARTICLE_CHUNK) {
            lr_canvas_discs(c, k, px, py, r, colour);
            k = 0;
        }
    }
    if (rc == 0 && k > 0)
        lr_canvas_discs(c, k, px, py, r, colour);
    if (rc == 0 && pts->band > 0 && pts->next)
        draw_band(c, v, m, pts, p, vmin, vmax);
    free(px);
    free(py);
    free(colour);
    return rc;
}

/* ---- curves and arrows ------------------------------------------------ */

static void map(const fig_view *v, const fig_mirror *m, double x, double y,
                double *px, double *py)
{
    fig_to_pixel(v, fig_mx(m, x), fig_my(m, y), px, py);
}

void fig_draw_curve(lr_canvas *c, const fig_view *v, const fig_mirror *m,
                    const lr_curve *cv)
{
    size_t segments = cv->pairs ? cv->n / 2
                    : cv->closed && cv->n > 2 ? cv->n : cv->n - (cv->n > 0);
    /* solid pieces overlap a little so that the joints have no notches */
    double ext = cv->dash > 0 ? 0.0 : 0.25 * cv->width;
    for (size_t s = 0; s < segments; s++) {
        size_t i = cv->pairs ? 2 * s : s;
        size_t j = cv->pairs ? i + 1 : (i + 1) % cv->n;
        double ax, ay, bx, by;
        map(v, m, cv->x[i], cv->y[i], &ax, &ay);
        map(v, m, cv->x[j], cv->y[j], &bx, &by);
        double len = hypot(bx - ax, by - ay);
        if (!(len > 0))
            continue;
        double ex = ext * (bx - ax) / len, ey = ext * (by - ay) / len;
        lr_canvas_line(c, ax - ex, ay - ey, bx + ex, by + ey, cv->width,
                       cv->colour, cv->dash);
    }
}

/* Shafts as lines; the heads, filled triangles, in one fill. */
int fig_draw_arrows(lr_canvas *c, const fig_view *v, const fig_mirror *m,
                    const lr_arrows *a)
{
    if (a->n == 0)
        return 0;
    double *heads = malloc(6 * a->n * sizeof *heads);
    size_t *counts = malloc(a->n * sizeof *counts);
    if (!heads || !counts) {
        free(heads);
        free(counts);
        return -1;
    }
    /* thinned (lr_arrows.thin): every k-th arrow, as long as the gap
     * between drawn arrows; else every arrow at its length */
    size_t stride = 1;
    double length = a->length;
    double gap_px = a->spacing * v->s;
    if (a->thin > 0 && gap_px > 0 && isfinite(gap_px)) {
        double k = ceil(a->thin / gap_px - 1e-9);
        stride = k > 1 ? (k < (double)a->n ? (size_t)k : a->n) : 1;
        length = (double)stride * a->spacing;
    }
    size_t nh = 0;
    for (size_t i = 0; i < a->n; i += stride) {
        double ux = m->fx ? -a->ux[i] : a->ux[i], uy = m->fy ? -a->uy[i] : a->uy[i];
        double x = fig_mx(m, a->x[i]), y = fig_my(m, a->y[i]);
        double ax, ay, bx, by;
        fig_to_pixel(v, x, y, &ax, &ay);
        fig_to_pixel(v, x + length * ux, y + length * uy, &bx, &by);
        double len = hypot(bx - ax, by - ay);
        if (!(len > 0) || !isfinite(len))
            continue;   /* zero or bad direction */
        double dx = (bx - ax) / len, dy = (by - ay) / len;
        double h = fmin(a->head, 0.6 * len), w = h * tan(HEAD_HALF_ANGLE);
        double cx = bx - h * dx, cy = by - h * dy;  /* the head's base */
        lr_canvas_line(c, ax, ay, cx + 0.5 * dx, cy + 0.5 * dy, a->width,
                       a->colour, a->dash);
        double *t = heads + 6 * nh;
        t[0] = bx;
        t[1] = by;
        t[2] = cx - w * dy;
        t[3] = cy + w * dx;
        t[4] = cx + w * dy;
        t[5] = cy - w * dx;
        counts[nh++] = 3;
    }
    lr_canvas_fill(c, nh, counts, heads, a->colour);
    free(heads);
    free(counts);
    return 0;
}
