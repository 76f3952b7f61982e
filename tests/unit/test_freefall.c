/* test_freefall.c - a block in free fall follows the explicit update's
 * discrete trajectory to round-off: with p_i^L = p_i + dt m_i g and a
 * uniform velocity field, x^n = x^0 + g dt^2 n(n+1)/2 = 1/2 g t^2 + 1/2 g dt t
 * (docs/physics.md §1 steps 3-4), and v^n = g t exactly. No stress arises. */
#include <math.h>

#include "check.h"
#include "sim_fixture.h"

static void fall(lm_scheme scheme)
{
    lm_sim_def d;
    lm_sim_def_default(&d);
    d.x0 = 0; d.y0 = -10; d.x1 = 1; d.y1 = 1;
    d.hx = d.hy = 0.1;
    d.dt = 1e-3;
    d.gy = -9.81;
    d.scheme = scheme;
    for (int s = 0; s < 4; s++) d.bc[s] = LM_BC_FREE;
    char err[256];
    lm_sim *sim = lm_sim_new(&d, err, sizeof err);
    lm_material mat = {.kind = LM_ELASTIC, .rho = 1000, .E = 1e6, .nu = 0.3, .plane = LM_PLANE_STRAIN};
    CHECK(fixture_block(sim, &mat, 0.3, 0.6, 0.7, 0.9, 2, 0, 0, 0, 1) >= 0);
    size_t n = sim->p.n;
    double *y0 = malloc(n * sizeof *y0), *x0 = malloc(n * sizeof *x0);
    for (size_t q = 0; q < n; q++) {
        y0[q] = sim->p.y[q];
        x0[q] = sim->p.x[q];
    }
    int steps = 1000;
    for (int s = 0; s < steps; s++) CHECK(lm_sim_step(sim) == LM_OK);
    double t = sim->t, g = d.gy, dt = d.dt;
    double drop = 0.5 * g * t * t + 0.5 * g * dt * t;
    double worst = 0, worst_v = 0, worst_s = 0;
    for (size_t q = 0; q < n; q++) {
        worst = fmax(worst, fabs(sim->p.y[q] - (y0[q] + drop)));
        worst = fmax(worst, fabs(sim->p.x[q] - x0[q]));
        worst_v = fmax(worst_v, fabs(sim->p.vy[q] - g * t));
        worst_s = fmax(worst_s, fabs(sim->p.syy[q]) + fabs(sim->p.sxx[q]));
    }
    /* round-off: a few ulps of the distance fallen, per step */
    CHECK_NEAR(worst, 0, 1e-12 * fabs(drop) * steps);
    CHECK_NEAR(worst_v, 0, 1e-12 * fabs(g * t));
    CHECK_NEAR(worst_s, 0, 1e-6);
    fprintf(stderr, "free fall (%s): drop %.15g, worst position error %.3g, "
            "velocity error %.3g\n", scheme == LM_MUSL ? "MUSL" : "USL", drop, worst, worst_v);
    free(x0);
    free(y0);
    lm_sim_free(sim);
}

int main(void)
{
    fall(LM_MUSL);
    fall(LM_USL);
    return CHECK_DONE();
}
