/* test_axisym.c - the axisymmetric form's terms (src/mpm/axisym.c), for
 * every basis:
 *   - adjoint: the internal force with its hoop term and the strain rate
 *     with its hoop rate are transposes, so the internal power balances,
 *     -sum_i f_i . v_i = sum_p V_p (sigma : L + sigma_thth D_thth), for a
 *     random stress on a block reaching the axis and a random grid velocity
 *     (ghost nodes filled as the step fills them);
 *   - exact rates: a uniform radial expansion v_r = a r gives the hoop rate
 *     D_thth = a at every particle;
 *   - equilibrium: a uniform pressure on the regular seeding lattice puts no
 *     force on the interior nodes (the r-weighted quadrature of d(rN)/dr
 *     is exact at symmetric placement), with the bilinear hats. */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "sim_fixture.h"
#include "step.h"

static lm_sim *new_sim(lm_basis b)
{
    lm_sim_def d;
    lm_sim_def_default(&d);
    d.x0 = 0; d.x1 = 1; d.y0 = 0; d.y1 = 1;
    d.hx = d.hy = 0.1;
    d.dt = 1e-4;
    d.basis = b;
    d.axisym = 1;
    d.bc[LM_LEFT] = LM_BC_SYMMETRY;
    char err[256];
    lm_sim *sim = lm_sim_new(&d, err, sizeof err);
    CHECK(sim != NULL);
    return sim;
}

static void adjoint(lm_basis b)
{
    lm_sim *sim = new_sim(b);
    lm_material mat = {.kind = LM_ELASTIC, .rho = 10, .E = 1e4, .nu = 0.3};
    CHECK(fixture_block(sim, &mat, 0, 0.2, 0.63, 0.77, 3, 0, 0, 0, 3) >= 0);
    lm_particles *p = &sim->p;
    srand(7);
    for (size_t q = 0; q < p->n; q++) {
        p->sxx[q] = rand() / (double)RAND_MAX - 0.5;
        p->syy[q] = rand() / (double)RAND_MAX - 0.5;
        p->sxy[q] = rand() / (double)RAND_MAX - 0.5;
        p->szz[q] = rand() / (double)RAND_MAX - 0.5;
    }
    lm_step_clear(sim);
    lm_step_shape(sim);
    lm_step_p2g(sim);
    lm_step_forces(sim);
    lm_grid *g = &sim->grid;
    size_t nn = lm_grid_nodes(g);
    for (size_t i = 0; i < nn; i++) {
        g->vx[i] = rand() / (double)RAND_MAX - 0.5;
        g->vy[i] = rand() / (double)RAND_MAX - 0.5;
    }
    lm_grid_apply_bc(g, g->vx, g->vy);
    double *const fill[2] = {g->vx, g->vy};
    static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
    lm_grid_fill(g, 2, fill, comp);
    /* the grid's power over the real nodes (the fold left the ghosts empty) */
    double pg = 0, scale = 0;
    for (int j = 0; j <= g->ny; j++)
        for (int i = 0; i <= g->nx; i++) {
            long k = lm_grid_node(g, i, j);
            pg -= g->fx[k] * g->vx[k] + g->fy[k] * g->vy[k];
            scale += fabs(g->fx[k]) + fabs(g->fy[k]);
        }
    double pp = 0;
    const int W = g->sw, NS = W * W;
    for (size_t q = 0; q < p->n; q++) {
        double L[4] = {0, 0, 0, 0};
        lm_weights wt;
        lm_weights_of(sim, q, &wt);
        for (int k = 0; k < NS; k++) {
            long i = lm_stencil_node(g, W, p->node[q], k);
            L[0] += g->vx[i] * wt.Gx[k];
            L[1] += g->vx[i] * wt.Gy[k];
            L[2] += g->vy[i] * wt.Gx[k];
            L[3] += g->vy[i] * wt.Gy[k];
        }
        double V = p->m[q] / p->rho[q];
        pp += V * (p->sxx[q] * L[0] + p->syy[q] * L[3] + p->sxy[q] * (L[1] + L[2]) +
                   p->szz[q] * lm_axisym_hoop_rate(sim, q));
    }
    CHECK(scale > 0.1);
    CHECK_NEAR(pg, pp, 1e-13 * scale);
    lm_sim_free(sim);
}

static void radial_rate(lm_basis b)
{
    lm_sim *sim = new_sim(b);
    lm_material mat = {.kind = LM_ELASTIC, .rho = 10, .E = 1e4, .nu = 0.3};
    CHECK(fixture_block(sim, &mat, 0, 0.2, 0.63, 0.77, 3, 0, 0, 0, 3) >= 0);
    lm_step_clear(sim);
    lm_step_shape(sim);
    lm_grid *g = &sim->grid;
    const double a = 2.5;
    for (int j = -g->pad; j <= g->ny + g->pad; j++)
        for (int i = -g->pad; i <= g->nx + g->pad; i++) {
            long k = lm_grid_node(g, i, j);
            g->vx[k] = a * (g->x0 + i * g->hx);   /* the ghost beyond the axis: its image */
            g->vy[k] = 0;
        }
    double worst = 0;
    for (size_t q = 0; q < sim->p.n; q++)
        worst = fmax(worst, fabs(lm_axisym_hoop_rate(sim, q) - a));
    CHECK_NEAR(worst, 0, 1e-12 * a);
    lm_sim_free(sim);
}

static void pressure_equilibrium(void)
{
    lm_sim *sim = new_sim(LM_BASIS_LINEAR);
    lm_material gas = {.kind = LM_GAS, .rho = 1, .gamma = 1.4, .e0 = 2.5};
    CHECK(fixture_block(sim, &gas, 0, 0, 0.6, 1, 4, 0, 0, 0, 3) >= 0);
    lm_particles *p = &sim->p;
    for (size_t q = 0; q < p->n; q++) {
        p->m[q] *= p->x[q];   /* per radian, as seeding does */
        p->sxx[q] = p->syy[q] = p->szz[q] = -1;
    }
    lm_step_clear(sim);
    lm_step_shape(sim);
    lm_step_p2g(sim);
    lm_step_forces(sim);
    const lm_grid *g = &sim->grid;
    double worst = 0, edge = 0;
    for (int j = 1; j < g->ny; j++)
        for (int i = 1; i < 6; i++)   /* interior: off the axis and the body's edge */
            worst = fmax(worst, fabs(g->fx[lm_grid_node(g, i, j)]));
    edge = fabs(g->fx[lm_grid_node(g, 6, 5)]);   /* the free edge is pushed */
    CHECK(edge > 1e-3);
    CHECK_NEAR(worst, 0, 1e-14);
    lm_sim_free(sim);
}

int main(void)
{
    static const lm_basis bases[3] = {LM_BASIS_LINEAR, LM_BASIS_GIMP, LM_BASIS_BSPLINE2};
    for (int b = 0; b < 3; b++) {
        adjoint(bases[b]);
        radial_rate(bases[b]);
    }
    pressure_equilibrium();
    return CHECK_DONE();
}
