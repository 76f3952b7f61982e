/* sim_fixture.h - small simulations for the unit tests. */
#ifndef LAMINA_SIM_FIXTURE_H
#define LAMINA_SIM_FIXTURE_H

#include <stdlib.h>

#include "mpm.h"

/* A rectangle [x0,x1]x[y0,y1] of one elastic material seeded npx*npy per
 * cell, every particle with velocity (vx, vy) plus a seeded random part of
 * size jitter (so the transfer tests see a non-uniform field). */
static int fixture_block(lm_sim *sim, lm_material *mat, double x0, double y0,
                         double x1, double y1, int np, double vx, double vy,
                         double jitter, unsigned seed)
{
    int mi = lm_sim_add_material(sim, mat);
    int b = lm_sim_add_body(sim, mi);
    lm_region r = {0};
    r.kind = LM_REGION_RECT;
    r.x0 = x0; r.y0 = y0; r.x1 = x1; r.y1 = y1;
    lm_seed_range sr = lm_seed_range_for(&sim->grid, np, np, x0, y0, x1, y1);
    double m = lm_seed_mass(&sim->grid, np, np, mat->rho);
    srand(seed);
    for (size_t k = 0; k < lm_seed_count(&sr); k++) {
        double x, y;
        lm_seed_point(&sim->grid, &sr, k, &x, &y);
        if (!lm_region_contains(&r, x, y)) continue;
        double jx = jitter * (rand() / (double)RAND_MAX - 0.5);
        double jy = jitter * (rand() / (double)RAND_MAX - 0.5);
        if (lm_sim_add_particle(sim, b, x, y, vx + jx, vy + jy, m, mat->rho) != LM_OK)
            return -1;
    }
    return b;
}

#endif
