/* block3_fixture.h - the 3D scene the threads and SIMD unit tests share
 * (test_sim3_threads.c, test_sim3_threads_span.c, test_sim3_simd.c): a
 * unit box of 20^3 cells with fixed faces and gravity, and in its middle
 * half a block of 2 x 2 x 2 particles a cell (8 000), elastic (rho 1000,
 * E 1e6, nu 0.3) or a gas with the artificial viscosity of about the same
 * wave speed (c = 36.7 m/s); dt = 0.2 h / c. */
#ifndef LAMINA_BLOCK3_FIXTURE_H
#define LAMINA_BLOCK3_FIXTURE_H

#include <string.h>

#include "check.h"
#include "mpm3.h"

/* The box and the block, not yet moving; its material's index in *mi
 * (mi may be NULL). */
static inline lm3_sim *block3_new(lm_basis basis, lm_scheme scheme, int gas, int threads,
                                  int *mi)
{
    lm3_def d;
    memset(&d, 0, sizeof d);
    d.hi[0] = d.hi[1] = d.hi[2] = 1;
    d.cell = 1.0 / 20;
    d.basis = basis;
    d.scheme = scheme;
    d.gravity[2] = -9.81;
    d.threads = threads;
    for (int f = 0; f < LM3_FACES; f++) d.bc[f] = LM_BC_FIXED;
    lm3_material m = {.rho = 1000, .E = 1e6, .nu = 0.3};
    if (gas) {
        lm3_material g = {.rho = 1000, .kind = LM3_GAS, .gamma = 1.4, .mu = 0.1, .av = 1,
                          .av_c1 = 1, .av_c2 = 1, .av_lambda = 0.75, .e0 = 1.35e3 / 0.56};   /* c = 36.7 m/s */
        m = g;
    }
    d.dt = 0.2 * d.cell / 36.7;
    char err[256];
    lm3_sim *sim = lm3_sim_create(&d, err, sizeof err);
    int k = lm3_material_add(sim, &m, err, sizeof err);
    double lo[3] = {0.25, 0.25, 0.25}, hi[3] = {0.75, 0.75, 0.75}, v[3] = {0, 0, 0};
    CHECK(lm3_seed_box(sim, k, lo, hi, 2, v) > 4096);
    if (mi) *mi = k;
    return sim;
}

/* Every particle spinning about z and sheared (every stress component
 * moves) and falling at 1 m/s. */
static inline void block3_spin(lm3_sim *sim)
{
    for (size_t q = 0; q < sim->p.n; q++) {
        double x = sim->p.x[0][q] - 0.5, y = sim->p.x[1][q] - 0.5, z = sim->p.x[2][q] - 0.5;
        sim->p.v[0][q] = -2 * y + 0.5 * z;
        sim->p.v[1][q] = 2 * x;
        sim->p.v[2][q] = 0.3 * x - 1;
    }
}

#endif
