/* test_p2g.c - particle-to-grid transfers conserve mass and momentum, the
 * internal forces sum to zero (sum_i G_ip = 0), and a whole step conserves
 * linear momentum to round-off when no boundary is touched (docs/physics.md §1);
 * for every scheme and every basis. */
#include <math.h>

#include "check.h"
#include "sim_fixture.h"
#include "step.h"

static void one_scheme(lm_scheme scheme, lm_basis basis)
{
    lm_sim_def d;
    lm_sim_def_default(&d);
    d.x1 = 2; d.y1 = 1; d.hx = 0.1; d.hy = 0.1; d.dt = 1e-4;
    d.scheme = scheme;
    d.basis = basis;
    char err[256];
    lm_sim *sim = lm_sim_new(&d, err, sizeof err);
    CHECK(sim != NULL);
    lm_material mat = {.kind = LM_ELASTIC, .rho = 10, .E = 1e4, .nu = 0.3, .plane = LM_PLANE_STRAIN};
    CHECK(fixture_block(sim, &mat, 0.53, 0.31, 1.27, 0.77, 3, 0.5, -0.2, 0.4, 11) >= 0);
    /* give the block stress so that forces are not trivially zero */
    for (size_t q = 0; q < sim->p.n; q++) {
        sim->p.sxx[q] = 100 * sin(7 * sim->p.x[q]);
        sim->p.syy[q] = 50 * cos(5 * sim->p.y[q]);
        sim->p.sxy[q] = 30 * sin(3 * sim->p.x[q] * sim->p.y[q]);
    }
    double M = lm_body_mass(sim, -1), px0, py0;
    lm_sim_momentum(sim, &px0, &py0);

    lm_step_clear(sim);
    lm_step_shape(sim);
    lm_step_p2g(sim);
    double mg = 0, pgx = 0, pgy = 0;
    size_t nn = lm_grid_nodes(&sim->grid);
    for (size_t i = 0; i < nn; i++) {
        mg += sim->grid.m[i];
        pgx += sim->grid.px[i];
        pgy += sim->grid.py[i];
    }
    CHECK_NEAR(mg, M, 1e-13 * M);
    CHECK_NEAR(pgx, px0, 1e-13 * M);
    CHECK_NEAR(pgy, py0, 1e-13 * M);

    lm_step_forces(sim);
    double fx = 0, fy = 0, fabsx = 0;
    for (size_t i = 0; i < nn; i++) {
        fx += sim->grid.fx[i];
        fy += sim->grid.fy[i];
        fabsx += fabs(sim->grid.fx[i]);
    }
    CHECK(fabsx > 1);              /* the forces are there ... */
    CHECK_NEAR(fx, 0, 1e-12 * fabsx);  /* ... and sum to zero */
    CHECK_NEAR(fy, 0, 1e-12 * fabsx);

    /* whole steps: momentum unchanged (no gravity, walls untouched) */
    for (int s = 0; s < 50; s++) CHECK(lm_sim_step(sim) == LM_OK);
    double px, py;
    lm_sim_momentum(sim, &px, &py);
    CHECK_NEAR(px, px0, 1e-12 * M);
    CHECK_NEAR(py, py0, 1e-12 * M);
    lm_sim_free(sim);
}

int main(void)
{
    for (int b = LM_BASIS_LINEAR; b <= LM_BASIS_BSPLINE2; b++) {
        one_scheme(LM_MUSL, (lm_basis)b);
        one_scheme(LM_USL, (lm_basis)b);
    }
    return CHECK_DONE();
}
