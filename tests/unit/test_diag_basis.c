/* test_diag_basis.c - the diagnostics that map particles to the grid use
 * the run's basis and its walls (diag.c): for every basis, the kinetic
 * energy the grid sees of a uniformly moving block equals the particles'
 * by free walls (is at most that where a symmetry wall's mirror image stops
 * its normal part, and for a non-uniform motion), and a gas of uniform
 * pressure reads that pressure at every node it touches, beside symmetry
 * and fixed walls too. */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "sim_fixture.h"
#include "step.h"

static void one_basis(lm_basis b, lm_bc bc)
{
    lm_sim_def d;
    lm_sim_def_default(&d);
    d.x1 = 1; d.y1 = 1; d.hx = d.hy = 0.125; d.dt = 1e-4;
    d.basis = b;
    for (int s = 0; s < 4; s++) d.bc[s] = bc;
    char err[256];
    lm_sim *sim = lm_sim_new(&d, err, sizeof err);
    CHECK(sim != NULL);
    /* a gas filling the lower-left part, walls included */
    lm_material gas = {.kind = LM_GAS, .rho = 2, .gamma = 1.4, .e0 = 250};
    CHECK(fixture_block(sim, &gas, 0, 0, 0.6, 0.5, 2, 0.3, -0.1, 0, 1) >= 0);
    lm_energy e = lm_sim_energy(sim);
    double gk = lm_sim_grid_kinetic(sim);
    if (bc == LM_BC_FREE)       /* nothing constrains the uniform motion */
        CHECK_NEAR(gk, e.kinetic, 1e-13 * e.kinetic);
    else                        /* a mirror image stops its normal part */
        CHECK(gk <= e.kinetic * (1 + 1e-14));
    size_t nn = (size_t)(sim->grid.nx + 1) * (sim->grid.ny + 1);
    double *pr = malloc(nn * sizeof *pr);
    size_t have = lm_grid_gas_pressure(sim, pr);
    CHECK(have > 20);
    size_t seen = 0;
    for (size_t i = 0; i < nn; i++) {
        if (isnan(pr[i])) continue;
        seen++;
        CHECK_NEAR(pr[i], 0.4 * 2 * 250, 1e-12);
    }
    CHECK(seen == have);
    /* a non-uniform velocity: the grid sees at most the particles' energy */
    for (size_t q = 0; q < sim->p.n; q++) sim->p.vx[q] = sin(17.0 * q);
    CHECK(lm_sim_grid_kinetic(sim) <= lm_sim_energy(sim).kinetic * (1 + 1e-14));
    free(pr);
    lm_sim_free(sim);
}

int main(void)
{
    for (int b = LM_BASIS_LINEAR; b <= LM_BASIS_BSPLINE2; b++) {
        one_basis((lm_basis)b, LM_BC_FREE);
        one_basis((lm_basis)b, LM_BC_SYMMETRY);
    }
    return CHECK_DONE();
}
