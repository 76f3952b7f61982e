/* sim3_region.c - 3D regions (ball, box, cylinder) and seeding a region
 * by a predicate (docs/3d.md "Lua API"): the Lua layer's lamina.ball,
 * lamina.box, lamina.cylinder and a function f(x, y, z) all come here as
 * inside(). Points sit at the centres of the sub-cells of an
 * nx x ny x nz pattern per cell, the papers' counting that lm3_seed_box
 * and the 2D seeding (seed.c) use, so a region's volume is shared
 * equally: each point carries h^3 / (nx ny nz). */
#include <math.h>

#include "mpm3.h"

int lm3_region_contains(const lm3_region *r, const double x[3])
{
    switch (r->kind) {
    case LM3_BALL: {
        double d2 = 0;
        for (int a = 0; a < 3; a++) d2 += (x[a] - r->c[a]) * (x[a] - r->c[a]);
        return d2 <= r->r * r->r;
    }
    case LM3_BOX:
        for (int a = 0; a < 3; a++)
            if (!(x[a] >= r->lo[a] && x[a] <= r->hi[a])) return 0;
        return 1;
    case LM3_CYLINDER: {
        /* the axis' parameter s in [0, 1] and the distance from it */
        double u[3], w[3], uu = 0, uw = 0;
        for (int a = 0; a < 3; a++) {
            u[a] = r->b[a] - r->a[a];
            w[a] = x[a] - r->a[a];
            uu += u[a] * u[a];
            uw += u[a] * w[a];
        }
        double s = uw / uu;
        if (!(s >= 0 && s <= 1)) return 0;
        double d2 = 0;
        for (int a = 0; a < 3; a++) {
            double e = w[a] - s * u[a];
            d2 += e * e;
        }
        return d2 <= r->r * r->r;
    }
    }
    return 0;
}

/* The candidate sub-cells: index ranges per direction (i0 > i1: none). */
static int candidates(const lm3_sim *sim, const lm3_seed_def *d, long i0[3], long i1[3])
{
    const lm3_grid *g = &sim->grid;
    for (int a = 0; a < 3; a++) {
        if (d->k[a] < 1 || d->k[a] > LM3_MAX_PPC_DIR) return -1;
        double s = g->h / d->k[a];
        double lo = fmax(d->lo[a], g->lo[a]), hi = fmin(d->hi[a], g->lo[a] + g->n[a] * g->h);
        i0[a] = (long)ceil((lo - g->lo[a]) / s - 0.5);
        i1[a] = (long)floor((hi - g->lo[a]) / s - 0.5);
        if (i0[a] < 0) i0[a] = 0;
        if (i1[a] > (long)g->n[a] * d->k[a] - 1) i1[a] = (long)g->n[a] * d->k[a] - 1;
        if (i1[a] < i0[a]) return 0;
    }
    return 1;
}

static void point_at(const lm3_sim *sim, const lm3_seed_def *d, long a, long b, long c,
                     double x[3])
{
    const lm3_grid *g = &sim->grid;
    const long i[3] = {a, b, c};
    for (int e = 0; e < 3; e++) x[e] = g->lo[e] + (i[e] + 0.5) * (g->h / d->k[e]);
}

long lm3_seed_count(const lm3_sim *sim, const lm3_seed_def *d)
{
    long i0[3], i1[3];
    int any = candidates(sim, d, i0, i1);
    if (any <= 0) return any;
    long n = 0;
    for (long c = i0[2]; c <= i1[2]; c++)
        for (long b = i0[1]; b <= i1[1]; b++)
            for (long a = i0[0]; a <= i1[0]; a++) {
                double x[3];
                point_at(sim, d, a, b, c, x);
                int in = d->inside(d->ctx, x);
                if (in < 0) return -1;
                n += in > 0;
            }
    return n;
}

long lm3_seed(lm3_sim *sim, const lm3_seed_def *d)
{
    long i0[3], i1[3];
    int any = candidates(sim, d, i0, i1);
    if (any <= 0) return any;
    size_t n0 = sim->p.n;
    const double h = sim->grid.h, V = h * h * h / ((double)d->k[0] * d->k[1] * d->k[2]);
    long added = 0;
    for (long c = i0[2]; c <= i1[2]; c++)
        for (long b = i0[1]; b <= i1[1]; b++)
            for (long a = i0[0]; a <= i1[0]; a++) {
                double x[3], v[3] = {d->v0[0], d->v0[1], d->v0[2]};
                point_at(sim, d, a, b, c, x);
                int in = d->inside(d->ctx, x);
                if (in < 0) goto undo;
                if (!in) continue;
                if (d->velocity && d->velocity(d->ctx, x, v) < 0) goto undo;
                if (lm3_particle_add(sim, d->mat, x, v, V) != LM_OK) goto undo;
                added++;
            }
    return added;
undo:
    sim->p.n = n0;
    return -1;
}
