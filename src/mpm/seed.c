/* seed.c - filling a region with particles: ppc = npx * npy trial points per
 * cell on a regular pattern, kept when inside the region (normals paper §2;
 * the papers count 4 = 2x2, 16 = 4x4, 64 = 8x8). */
#include <math.h>

#include "mpm.h"

static int clampi(int v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : v; }

lm_seed_range lm_seed_range_for(const lm_grid *g, int npx, int npy,
                                double x0, double y0, double x1, double y1)
{
    lm_seed_range r;
    r.npx = npx;
    r.npy = npy;
    r.i0 = clampi((int)floor((x0 - g->x0) / g->hx), 0, g->nx);
    r.i1 = clampi((int)ceil((x1 - g->x0) / g->hx), 0, g->nx);
    r.j0 = clampi((int)floor((y0 - g->y0) / g->hy), 0, g->ny);
    r.j1 = clampi((int)ceil((y1 - g->y0) / g->hy), 0, g->ny);
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
