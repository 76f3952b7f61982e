/* test_contact.c - contact pairs (contact.h, issue 14 items 2 and 6).
 *
 * - the two-bar impact of [M] §4.2 with release, and a skewed variant with
 *   friction: total momentum of the particles stays at its initial value to
 *   round-off through contact and release, and at every step the grid's
 *   kinetic energy after the correction is at most the energy before it
 *   (lm_contact.ke_after <= ke_before), for every basis contact runs on
 *   (the quadratic B-spline is refused);
 * - a pair whose bodies never meet leaves the state bit for bit as without
 *   it (the default single field is untouched);
 * - bad pairs are refused by name. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "contact.h"
#include "sim_fixture.h"

static lm_material bar = {.kind = LM_ELASTIC, .rho = 1, .E = 1e5, .nu = 0.3,
                          .plane = LM_PLANE_STRESS};

/* The bars of [M] Fig 17 (x in [1, 2.25] and [2.75, 4]), the right one
 * offset by dy and moving with (0, vy0) so that friction has something to
 * do; walls half a domain away so that wider stencils do not reach them. */
static lm_sim *bars(lm_basis basis, double dy, double vy0, int *a, int *b)
{
    lm_sim_def d;
    lm_sim_def_default(&d);
    d.x0 = -1; d.y0 = -1; d.x1 = 7; d.y1 = 6;
    d.hx = d.hy = 0.25;
    d.dt = 7e-4;
    d.basis = basis;
    char err[256];
    lm_sim *sim = lm_sim_new(&d, err, sizeof err);
    *a = fixture_block(sim, &bar, 1, 0.25, 2.25, 4.75, 2, 2, 0, 0, 1);
    *b = fixture_block(sim, &bar, 2.75, 0.25 + dy, 4, 4.75 + dy, 2, 0, vy0, 0, 1);
    return sim;
}

static void conservation(lm_basis basis, lm_contact_law law)
{
    int a, b;
    lm_sim *sim = bars(basis, law == LM_CONTACT_FRICTION ? 0.5 : 0,
                       law == LM_CONTACT_FRICTION ? 0.5 : 0, &a, &b);
    CHECK(lm_sim_add_contact(sim, a, b, law, law == LM_CONTACT_FRICTION ? 0.3 : 0) == 0);
    double px0, py0, px, py;
    lm_sim_momentum(sim, &px0, &py0);
    double scale = lm_body_mass(sim, -1) * 2;
    double worst_p = 0, worst_e = 0;
    long released = 0, slid = 0, stuck = 0;
    for (int s = 0; s < 715; s++) {   /* to t = 0.5 */
        CHECK(lm_sim_step(sim) == LM_OK);
        lm_sim_momentum(sim, &px, &py);
        worst_p = fmax(worst_p, fmax(fabs(px - px0), fabs(py - py0)));
        const lm_contact *c = sim->contact;
        worst_e = fmax(worst_e, c->ke_after - c->ke_before * (1 + 1e-12));
        released += c->nodes_release;
        slid += c->nodes_slide;
        stuck += c->nodes_stick;
    }
    printf("%s %s: max |momentum change| %.3g (scale %.3g), max KE rise %.3g, "
           "node-steps stick %ld release %ld slide %ld\n",
           lm_basis_name(basis), law == LM_CONTACT_RELEASE ? "release" : "friction",
           worst_p, scale, worst_e, stuck, released, slid);
    CHECK(worst_p <= 1e-12 * scale);
    CHECK(worst_e <= 0);
    CHECK(stuck > 0 && released > 0);
    if (law == LM_CONTACT_FRICTION) CHECK(slid > 0);
    lm_sim_free(sim);
}

/* A pair that never meets: the same bits as no pair. */
static void untouched(void)
{
    int a, b;
    lm_sim *one = bars(LM_BASIS_LINEAR, 0, 0, &a, &b);
    lm_sim *two = bars(LM_BASIS_LINEAR, 0, 0, &a, &b);
    /* the bars meet near t = 0.16 */
    CHECK(lm_sim_add_contact(two, a, b, LM_CONTACT_RELEASE, 0) == 0);
    for (int s = 0; s < 150; s++) {
        CHECK(lm_sim_step(one) == LM_OK);
        CHECK(lm_sim_step(two) == LM_OK);
    }
    CHECK(lm_sim_hash(one) == lm_sim_hash(two));
    lm_sim_free(one);
    lm_sim_free(two);
}

static void refused(void)
{
    int a, b;
    lm_sim *sim = bars(LM_BASIS_LINEAR, 0, 0, &a, &b);
    CHECK(lm_sim_add_contact(sim, a, a, LM_CONTACT_RELEASE, 0) < 0);
    CHECK(strstr(sim->err, "same body") != NULL);
    CHECK(lm_sim_add_contact(sim, a, b, LM_CONTACT_FRICTION, -0.1) < 0);
    CHECK(strstr(sim->err, "mu") != NULL);
    CHECK(lm_sim_add_contact(sim, a, b, (lm_contact_law)7, 0) < 0);
    CHECK(strstr(sim->err, "law") != NULL);
    CHECK(lm_sim_add_contact(sim, a, b, LM_CONTACT_RELEASE, 0) == 0);
    CHECK(lm_sim_add_contact(sim, b, a, LM_CONTACT_RELEASE, 0) < 0);
    CHECK(strstr(sim->err, "already") != NULL);
    /* the papers' forms as printed: pair 0 takes them, no other pair */
    CHECK(lm_sim_contact_form(sim, 0, LM_CTEST_EQ26, LM_CUPDATE_EQ21) == 0);
    CHECK(lm_sim_contact_form(sim, 1, LM_CTEST_EQ26, LM_CUPDATE_EQ21) < 0);
    CHECK(strstr(sim->err, "no contact pair 1") != NULL);
    CHECK(lm_sim_contact_form(sim, 0, (lm_contact_test)5, LM_CUPDATE_LAMINA) < 0);
    CHECK(strstr(sim->err, "eq26") != NULL);
    lm_sim_free(sim);
    /* the quadratic B-spline is refused by name (contact.c says why) */
    sim = bars(LM_BASIS_BSPLINE2, 0, 0, &a, &b);
    CHECK(lm_sim_add_contact(sim, a, b, LM_CONTACT_RELEASE, 0) < 0);
    CHECK(strstr(sim->err, "bspline2") != NULL);
    lm_sim_free(sim);
}

int main(void)
{
    conservation(LM_BASIS_LINEAR, LM_CONTACT_RELEASE);
    conservation(LM_BASIS_GIMP, LM_CONTACT_RELEASE);
    conservation(LM_BASIS_LINEAR, LM_CONTACT_FRICTION);
    conservation(LM_BASIS_GIMP, LM_CONTACT_FRICTION);
    untouched();
    refused();
    return CHECK_DONE();
}
