/* test_stress_cell.c - the cell-centred stress of [T] §5.4.3
 * (sim{stress = "cell"}, stress_cell.c): the internal forces sum to zero
 * (momentum), a uniform stress leaves every interior node without force,
 * a whole run conserves momentum, and the default "points" gives the
 * papers' quadrature f_i = -sum_p V_p sigma_p . G_ip bit for bit. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "sim_fixture.h"
#include "step.h"

static lm_sim *block(lm_stress stress, double x0, double y0, double x1, double y1, int np,
                     double jitter, lm_material *mat)
{
    lm_sim_def d;
    lm_sim_def_default(&d);
    d.x1 = 2; d.y1 = 1; d.hx = 0.1; d.hy = 0.1; d.dt = 1e-4;
    d.stress = stress;
    char err[256];
    lm_sim *sim = lm_sim_new(&d, err, sizeof err);
    CHECK(sim != NULL);
    CHECK(fixture_block(sim, mat, x0, y0, x1, y1, np, 0.5, -0.2, jitter, 11) >= 0);
    return sim;
}

static void wavy_stress(lm_sim *sim)
{
    for (size_t q = 0; q < sim->p.n; q++) {
        sim->p.sxx[q] = 100 * sin(7 * sim->p.x[q]);
        sim->p.syy[q] = 50 * cos(5 * sim->p.y[q]);
        sim->p.sxy[q] = 30 * sin(3 * sim->p.x[q] * sim->p.y[q]);
    }
}

static void forces(lm_sim *sim)
{
    lm_step_clear(sim);
    lm_step_shape(sim);
    lm_step_p2g(sim);
    lm_step_forces(sim);
}

/* Sum f = 0 and momentum kept over 50 steps (no gravity, walls untouched). */
static void momentum(void)
{
    lm_material mat = {.kind = LM_ELASTIC, .rho = 10, .E = 1e4, .nu = 0.3,
                       .plane = LM_PLANE_STRAIN};
    lm_sim *sim = block(LM_STRESS_CELL, 0.53, 0.31, 1.27, 0.77, 3, 0.4, &mat);
    wavy_stress(sim);
    double M = lm_body_mass(sim, -1), px0, py0;
    lm_sim_momentum(sim, &px0, &py0);
    forces(sim);
    size_t nn = lm_grid_nodes(&sim->grid);
    double fx = 0, fy = 0, fabsx = 0;
    for (size_t i = 0; i < nn; i++) {
        fx += sim->grid.fx[i];
        fy += sim->grid.fy[i];
        fabsx += fabs(sim->grid.fx[i]);
    }
    CHECK(fabsx > 1);
    CHECK_NEAR(fx, 0, 1e-12 * fabsx);
    CHECK_NEAR(fy, 0, 1e-12 * fabsx);
    for (int s = 0; s < 50; s++) CHECK(lm_sim_step(sim) == LM_OK);
    double px, py;
    lm_sim_momentum(sim, &px, &py);
    CHECK_NEAR(px, px0, 1e-12 * M);
    CHECK_NEAR(py, py0, 1e-12 * M);
    lm_sim_free(sim);
}

/* A uniform stress on whole cells (2 x 2 per cell, equal volumes): only
 * the nodes on the block's outline carry force, the interior ones none
 * (with point quadrature this holds too; with the points jittered within
 * their cells it holds only for the cell stress). */
static void uniform(void)
{
    lm_material mat = {.kind = LM_ELASTIC, .rho = 10, .E = 1e4, .nu = 0.3,
                       .plane = LM_PLANE_STRAIN};
    lm_sim *sim = block(LM_STRESS_CELL, 0.5, 0.3, 1.3, 0.8, 2, 0, &mat);
    /* move every point within its own cell: the cell stress must not care */
    const lm_grid *g = &sim->grid;
    for (size_t q = 0; q < sim->p.n; q++) {
        double fx = (sim->p.x[q] - g->x0) / g->hx, fy = (sim->p.y[q] - g->y0) / g->hy;
        double cx = floor(fx), cy = floor(fy);
        sim->p.x[q] = g->x0 + g->hx * (cx + 0.05 + 0.9 * fabs(sin(3.7 * q)));
        sim->p.y[q] = g->y0 + g->hy * (cy + 0.05 + 0.9 * fabs(cos(2.3 * q)));
        sim->p.sxx[q] = 120;
        sim->p.syy[q] = -70;
        sim->p.sxy[q] = 45;
    }
    forces(sim);
    double fmax = 0, interior = 0;
    for (int j = 0; j <= g->ny; j++) {
        for (int i = 0; i <= g->nx; i++) {
            size_t n = (size_t)j * (size_t)(g->nx + 1) + (size_t)i;
            double x = g->x0 + i * g->hx, y = g->y0 + j * g->hy;
            double f = hypot(sim->grid.fx[n], sim->grid.fy[n]);
            if (f > fmax) fmax = f;
            if (x > 0.5 + 1e-9 && x < 1.3 - 1e-9 && y > 0.3 + 1e-9 && y < 0.8 - 1e-9)
                if (f > interior) interior = f;
        }
    }
    CHECK(fmax > 1);
    CHECK_NEAR(interior, 0, 1e-12 * fmax);
    lm_sim_free(sim);
}

/* "points" (the default) is today's quadrature, bit for bit. */
static void points_unchanged(void)
{
    lm_material mat = {.kind = LM_ELASTIC, .rho = 10, .E = 1e4, .nu = 0.3,
                       .plane = LM_PLANE_STRAIN};
    lm_sim *sim = block(LM_STRESS_POINTS, 0.53, 0.31, 1.27, 0.77, 3, 0.4, &mat);
    wavy_stress(sim);
    forces(sim);
    size_t nn = lm_grid_nodes(&sim->grid);
    double fx[nn], fy[nn];
    memset(fx, 0, sizeof fx);
    memset(fy, 0, sizeof fy);
    const lm_particles *p = &sim->p;
    for (size_t q = 0; q < p->n; q++) {
        double V = p->m[q] / p->rho[q];
        lm_weights wt;
        lm_weights_of(sim, q, &wt);
        for (int k = 0; k < 4; k++) {
            int i = p->node[q] + (k >> 1) * (sim->grid.nx + 1) + (k & 1);
            double gx = wt.Gx[k], gy = wt.Gy[k];
            fx[i] -= V * (p->sxx[q] * gx + p->sxy[q] * gy);
            fy[i] -= V * (p->sxy[q] * gx + p->syy[q] * gy);
        }
    }
    int same = 1;
    for (size_t i = 0; i < nn; i++)
        same &= memcmp(&fx[i], &sim->grid.fx[i], sizeof fx[i]) == 0 &&
                memcmp(&fy[i], &sim->grid.fy[i], sizeof fy[i]) == 0;
    CHECK(same);
    lm_sim_free(sim);
}

int main(void)
{
    momentum();
    uniform();
    points_unchanged();
    return CHECK_DONE();
}
