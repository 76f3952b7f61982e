/* figure_fill.c - filled contours: the region f >= level of a sampled
 * field, as one multi-ring fill per level.
 *
 * Each cell contributes the polygon of its corners at or above the level
 * and the points where its edges cross it (marching squares, Lorensen &
 * Cline's idea in two dimensions). Every ring is wound the same way, so
 * under the nonzero rule neighbouring cells unite into one region with no
 * seams, through either backend. Levels are painted in the order given, so
 * increasing levels give nested bands. A saddle cell is resolved by its
 * centre value, as layer_contour.c's lines are; cells with a non-finite
 * corner are left out. */
#include "figure_internal.h"

#include <math.h>
#include <stdlib.h>
#include "util.h"

/* Corners counter-clockwise (x right, y up) from (i, j); edge k joins
 * corner k to corner k+1. */
static const int cdx[4] = { 0, 1, 1, 0 };
static const int cdy[4] = { 0, 0, 1, 1 };

typedef struct rings {
    double *xy;
    size_t *counts;
    size_t nxy, capxy, nrings, caprings;
    int failed;
} rings;

static void add_point(rings *r, double x, double y)
{
    if (lu_reserve(&r->xy, &r->capxy, r->nxy + 2, sizeof *r->xy, 1024) != 0) {
        r->failed = 1;
        return;
    }
    r->xy[r->nxy++] = x;
    r->xy[r->nxy++] = y;
}

static void end_ring(rings *r, size_t npoints)
{
    if (r->failed)
        return;
    if (lu_reserve(&r->counts, &r->caprings, r->nrings + 1, sizeof *r->counts, 256) != 0) {
        r->failed = 1;
        return;
    }
    r->counts[r->nrings++] = npoints;
}

typedef struct cell_ctx {
    const fig_view *v;
    const fig_mirror *m;
    double x0, y0, dx, dy;      /* world position of sample (0, 0), spacing */
} cell_ctx;

/* Sample-index coordinates to pixels. */
static void put(rings *r, const cell_ctx *k, double i, double j)
{
    double px, py;
    fig_to_pixel(k->v, fig_mx(k->m, k->x0 + i * k->dx), fig_my(k->m, k->y0 + j * k->dy),
                 &px, &py);
    add_point(r, px, py);
}

/* Where edge e of cell (i, j) crosses the level, in index coordinates. */
static void crossing(const double val[4], int i, int j, int e, double level,
                     double *x, double *y)
{
    int a = e, b = (e + 1) & 3;
    double t = (level - val[a]) / (val[b] - val[a]);
    t = t >= 0.0 ? (t > 1.0 ? 1.0 : t) : 0.0;   /* NaN too */
    *x = i + cdx[a] + t * (cdx[b] - cdx[a]);
    *y = j + cdy[a] + t * (cdy[b] - cdy[a]);
}

static void cell(rings *r, const cell_ctx *k, const double val[4], int i, int j,
                 double level)
{
    int in[4], nin = 0;
    for (int q = 0; q < 4; q++) {
        in[q] = val[q] >= level;
        nin += in[q];
    }
    if (nin == 0)
        return;
    double cx[4], cy[4];
    for (int e = 0; e < 4; e++)
        if (in[e] != in[(e + 1) & 3])
            crossing(val, i, j, e, level, &cx[e], &cy[e]);
    int saddle = nin == 2 && in[0] == in[2];
    if (saddle && 0.25 * (val[0] + val[1] + val[2] + val[3]) < level) {
        /* two separate corners: each with the crossings of its two edges */
        for (int q = 0; q < 4; q++)
            if (in[q]) {
                int e0 = (q + 3) & 3;
                put(r, k, cx[e0], cy[e0]);
                put(r, k, i + cdx[q], j + cdy[q]);
                put(r, k, cx[q], cy[q]);
                end_ring(r, 3);
            }
        return;
    }
    /* around the cell: each inside corner, then its edge's crossing */
    size_t n = 0;
    for (int q = 0; q < 4; q++) {
        if (in[q]) {
            put(r, k, i + cdx[q], j + cdy[q]);
            n++;
        }
        if (in[q] != in[(q + 1) & 3]) {
            put(r, k, cx[q], cy[q]);
            n++;
        }
    }
    end_ring(r, n);
}

int fig_draw_field(lr_canvas *c, const fig_view *v, const fig_mirror *m,
                   const lr_field *fd, const lr_panel *p, double vmin, double vmax)
{
    if (!fd->f || fd->nx < 1 || fd->ny < 1)
        return 0;
    cell_ctx k = { v, m, fd->x0, fd->y0, (fd->x1 - fd->x0) / fd->nx,
                   (fd->y1 - fd->y0) / fd->ny };
    int sx = fd->nx + 1;
    for (int l = 0; l < fd->nlevels; l++) {
        double level = fd->levels[l];
        rings r = { 0 };
        for (int j = 0; j < fd->ny && !r.failed; j++)
            for (int i = 0; i < fd->nx; i++) {
                double val[4];
                int finite = 1;
                for (int q = 0; q < 4; q++) {
                    val[q] = fd->f[(i + cdx[q]) + (size_t)sx * (j + cdy[q])];
                    finite &= isfinite(val[q]) != 0;
                }
                if (finite)
                    cell(&r, &k, val, i, j, level);
            }
        if (!r.failed && r.nrings > 0) {
            lr_rgba colour = fd->colours ? fd->colours[l]
                                         : lr_cmap_colour(p->cmap, (level - vmin) / (vmax - vmin));
            lr_canvas_fill(c, r.nrings, r.counts, r.xy, colour);
        }
        int failed = r.failed;
        free(r.xy);
        free(r.counts);
        if (failed)
            return -1;
    }
    return 0;
}
