/* test_split.c - gas splitting (split.c): a thinned gas point becomes four
 * with mass, momentum, centre of mass, kinetic and internal energy kept;
 * a point that is not thin enough, one within a cell of a membrane, and any
 * point of a material without `split` stay whole; bodies after the gas
 * keep their points in order; the children's uGIMP squares are quarters. */
#include <math.h>

#include "check.h"
#include "step.h"

static lm_sim *make(void)
{
    lm_sim_def d;
    lm_sim_def_default(&d);
    d.x1 = 2; d.y1 = 1; d.hx = 0.1; d.hy = 0.1; d.dt = 1e-4;
    char err[256];
    return lm_sim_new(&d, err, sizeof err);
}

int main(void)
{
    lm_sim *sim = make();
    CHECK(sim != NULL);
    lm_material gas = {.kind = LM_GAS, .rho = 1, .gamma = 1.4, .e0 = 250, .split = 16};
    lm_material skin = {.kind = LM_MEMBRANE, .rho = 0.5, .E = 1e6, .nu = 0.3,
                        .thickness = 0.1, .law = LM_LAW_UNIAXIAL};
    int gi = lm_sim_add_material(sim, &gas), si = lm_sim_add_material(sim, &skin);
    int gb = lm_sim_add_body(sim, gi);
    /* 0: thin (V = 0.01 / 16 * 2 > h^2 / 16), far from the membrane;
     * 1: not thin; 2: thin but 0.05 from the membrane at x = 1.5 */
    double m = 0.01 / 16;
    CHECK(lm_sim_add_particle(sim, gb, 0.5, 0.5, 0.3, -0.2, m, 0.5) == LM_OK);
    CHECK(lm_sim_add_particle(sim, gb, 0.7, 0.5, 0.1, 0.0, m, 2.0) == LM_OK);
    CHECK(lm_sim_add_particle(sim, gb, 1.45, 0.5, 0.0, 0.1, m, 0.5) == LM_OK);
    sim->p.e[0] = 400;
    int mb = lm_sim_add_membrane(sim, si, 0);
    for (int k = 0; k < 5; k++) {
        size_t q = sim->p.n;
        CHECK(lm_sim_add_particle(sim, mb, 1.5, 0.3 + 0.1 * k, 0, 0, 0.005, 0.5) == LM_OK);
        CHECK(lm_sim_set_membrane_point(sim, q, 0.1, 0) == LM_OK);
    }
    CHECK(lm_sim_prepare(sim) == LM_OK);
    lm_energy e0 = lm_sim_energy(sim);
    double px0, py0, cx0, cy0, M0 = lm_body_mass(sim, gb);
    lm_sim_momentum(sim, &px0, &py0);
    lm_body_com(sim, gb, &cx0, &cy0);

    CHECK(lm_step_split(sim) == LM_OK);
    CHECK(sim->p.n == 11);
    CHECK(sim->bodies[gb].count == 6 && sim->bodies[gb].first == 0);
    CHECK(sim->bodies[mb].first == 6 && sim->bodies[mb].count == 5);
    for (int k = 0; k < 5; k++)               /* the membrane moved up, in order */
        CHECK_NEAR(sim->p.y[6 + k], 0.3 + 0.1 * k, 1e-15);
    CHECK_NEAR(sim->p.m[0], m / 4, 1e-20);    /* the parent is a child now */
    CHECK_NEAR(sim->p.m[1], m, 1e-20);        /* the others untouched */
    CHECK_NEAR(sim->p.m[2], m, 1e-20);
    double a = 0.25 * sqrt(m / 0.5);
    CHECK_NEAR(sim->p.x[0], 0.5 - a, 1e-15);
    CHECK_NEAR(sim->p.y[0], 0.5 - a, 1e-15);
    /* uGIMP: each child's square is a quarter of the parent's (h/4 at the
     * default seeding), the others keep theirs */
    CHECK(sim->p.lx[0] == 0.125 * 0.1 && sim->p.ly[0] == 0.125 * 0.1);
    CHECK(sim->p.lx[1] == 0.25 * 0.1);
    for (int k = 3; k < 6; k++) {             /* three siblings after the body */
        CHECK(sim->p.lx[k] == 0.125 * 0.1 && sim->p.ly[k] == 0.125 * 0.1);
        CHECK_NEAR(sim->p.m[k], m / 4, 1e-20);
        CHECK_NEAR(sim->p.vx[k], 0.3, 0);
        CHECK_NEAR(sim->p.e[k], 400, 0);
        CHECK_NEAR(sim->p.rho[k], 0.5, 0);
        CHECK(sim->p.body[k] == gb);
    }
    lm_energy e1 = lm_sim_energy(sim);
    double px1, py1, cx1, cy1;
    lm_sim_momentum(sim, &px1, &py1);
    lm_body_com(sim, gb, &cx1, &cy1);
    CHECK_NEAR(lm_body_mass(sim, gb), M0, 1e-18);
    CHECK_NEAR(px1, px0, 1e-17);
    CHECK_NEAR(py1, py0, 1e-17);
    CHECK_NEAR(cx1, cx0, 1e-15);
    CHECK_NEAR(cy1, cy0, 1e-15);
    CHECK_NEAR(e1.kinetic, e0.kinetic, 1e-16);
    CHECK_NEAR(e1.internal, e0.internal, 1e-13);

    /* the children are not thin enough to split again */
    CHECK(lm_step_split(sim) == LM_OK);
    CHECK(sim->p.n == 11);
    lm_sim_free(sim);
    return CHECK_DONE();
}
