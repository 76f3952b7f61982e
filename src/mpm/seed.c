/* seed.c - filling a region with particles: ppc = npx * npy trial points per
 * cell on a regular pattern, kept when inside the region (normals paper §2;
 * the papers count 4 = 2x2, 16 = 4x4, 64 = 8x8). */
#include <math.h>

#include "mpm.h"

/* A cell index in [0, hi] from a double: clamped before the conversion, as
 * a region far larger than the domain (a disk of radius 1e12) or a NaN
 * would not fit an int (found by fuzzing, tests/fuzz). */
static int cell_index(double v, int hi) { return !(v > 0) ? 0 : v > hi ? hi : (int)v; }

lm_seed_range lm_seed_range_for(const lm_grid *g, int npx, int npy,
                                double x0, double y0, double x1, double y1)
{
    lm_seed_range r;
    r.npx = npx;
    r.npy = npy;
    r.i0 = cell_index(floor((x0 - g->x0) / g->hx), g->nx);
    r.i1 = cell_index(ceil((x1 - g->x0) / g->hx), g->nx);
    r.j0 = cell_index(floor((y0 - g->y0) / g->hy), g->ny);
    r.j1 = cell_index(ceil((y1 - g->y0) / g->hy), g->ny);
    return r;
}

size_t lm_seed_count(const lm_seed_range *r)
{
    return (size_t)(r->i1 - r->i0) * r->npx * (size_t)(r->j1 - r->j0) * r->npy;
}

/* Point k in row-major order over the whole sub-cell lattice of the range,
 * so a body's particles come out in rows, bottom to top. */
void lm_seed_point(const lm_grid *g, const lm_seed_range *r, size_t k,
                   double *x, double *y)
{
    size_t cols = (size_t)(r->i1 - r->i0) * r->npx;
    size_t a = k % cols, b = k / cols;
    *x = g->x0 + (r->i0 + (a + 0.5) / r->npx) * g->hx;
    *y = g->y0 + (r->j0 + (b + 0.5) / r->npy) * g->hy;
}

double lm_seed_mass(const lm_grid *g, int npx, int npy, double rho)
{
    return rho * g->hx * g->hy / (npx * npy);
}

/* A sub-cell the region's boundary cuts stands for the area inside it, at
 * that area's centroid: the seeded mass is then rho times the region's area
 * and the gas meets a curved wall evenly, where the centres rule leaves a
 * gap between the last points and the wall that changes with the angle (on
 * the circle of [N] §8 that jagged edge loads the membrane unevenly and
 * wrinkles it early; docs/normals.md "Centred elements"). A 3 x 3 probe (corners,
 * edge midpoints, centre) finds the sub-cells the boundary misses; a cut one
 * is sampled on a 16 x 16 lattice (area to 1/256 of the sub-cell). */
#define CLIP_PROBE 3
#define CLIP_SAMPLES 16

double lm_seed_clip(const lm_grid *g, int npx, int npy, double x, double y,
                    lm_inside_fn inside, void *ctx, double *cx, double *cy)
{
    double dx = g->hx / npx, dy = g->hy / npy;
    int hits = 0;
    for (int a = 0; a < CLIP_PROBE; a++)
        for (int b = 0; b < CLIP_PROBE; b++)
            hits += inside(ctx, x + dx * (a / (CLIP_PROBE - 1.0) - 0.5),
                           y + dy * (b / (CLIP_PROBE - 1.0) - 0.5)) != 0;
    *cx = x;
    *cy = y;
    if (hits == CLIP_PROBE * CLIP_PROBE) return 1;
    if (hits == 0) return 0;    /* a boundary no probe sees cuts off a sliver */
    int n = 0;
    double sx = 0, sy = 0;
    for (int a = 0; a < CLIP_SAMPLES; a++)
        for (int b = 0; b < CLIP_SAMPLES; b++) {
            double px = x + dx * ((a + 0.5) / CLIP_SAMPLES - 0.5);
            double py = y + dy * ((b + 0.5) / CLIP_SAMPLES - 0.5);
            if (!inside(ctx, px, py)) continue;
            n++;
            sx += px;
            sy += py;
        }
    if (n == 0) return 0;
    if (n == CLIP_SAMPLES * CLIP_SAMPLES) return 1;   /* whole: keep the centre */
    *cx = sx / n;
    *cy = sy / n;
    return (double)n / (CLIP_SAMPLES * CLIP_SAMPLES);
}
