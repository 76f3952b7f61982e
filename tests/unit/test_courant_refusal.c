/* test_courant_refusal.c - issue 33 item 1: the Courant refusal and the
 * energy watch live in the engine, so a C caller of the step gets what
 * sim:run gives. Sees only the public header.
 *
 * The refusal: tests/bad/courant_usl.lua's scene (cell 0.05, dt 0.035,
 * USL, an elastic disk rho 1000, E 1000, nu 0.3; c = 1.16024) built in C:
 * lm_sim_step refuses it before moving anything, with the numbers that
 * test expects of sim:run's message (Courant 0.81216 against 1 x 0.7,
 * dt <= 0.0301662). lm_sim_try_dt refuses a dt the same way and keeps the
 * old one; a raised limit lets the step go.
 *
 * The watch: a disk at rest whose velocities the caller sets after the
 * watch began (energy put in from outside, which the watch cannot tell
 * from the numerics' and is documented to report) is reported after 100
 * steps; the same run watched from after the kick is not. */
#include <string.h>

#include "check.h"
#include "mpm.h"

static lm_sim *disk_scene(double dt, lm_scheme scheme)
{
    lm_sim_def d;
    lm_sim_def_default(&d);
    d.hx = d.hy = 0.05;
    d.dt = dt;
    d.scheme = scheme;
    d.basis = LM_BASIS_BSPLINE2;   /* lamina.sim's default */
    char err[256];
    lm_sim *sim = lm_sim_new(&d, err, sizeof err);
    if (!sim) return NULL;
    lm_material rubber = {.kind = LM_ELASTIC, .rho = 1000, .E = 1000, .nu = 0.3};
    lm_region disk = {.kind = LM_REGION_DISK, .cx = 0.5, .cy = 0.5, .r = 0.2,
                      .x0 = 0.3, .y0 = 0.3, .x1 = 0.7, .y1 = 0.7};
    lm_body_def b;
    lm_body_def_default(&b);
    b.mat = lm_sim_add_material(sim, &rubber);
    b.region = &disk;
    if (lm_sim_create_body(sim, &b) < 0) {
        lm_sim_free(sim);
        return NULL;
    }
    return sim;
}

int main(void)
{
    /* the refusal, from the step */
    lm_sim *sim = disk_scene(0.035, LM_USL);
    CHECK(sim != NULL);
    uint64_t h0 = lm_sim_hash(sim);
    CHECK(lm_sim_step(sim) == LM_ERR_COURANT);
    CHECK(strncmp(sim->err, "dt = 0.035 is too large: Courant number dt*c/h = 0.81216", 56) == 0);
    CHECK(strstr(sim->err, "exceeds courant = 1 x 0.7 for scheme = \"usl\"") != NULL);
    CHECK(strstr(sim->err, "c_max = 1.16024 from body 1") != NULL);
    CHECK(strstr(sim->err, "use dt <= 0.0301662 or raise courant") != NULL);
    CHECK(sim->step == 0 && sim->t == 0 && lm_sim_hash(sim) == h0);   /* nothing moved */
    CHECK(lm_sim_step(sim) == LM_ERR_COURANT);   /* and again: it stays refused */
    /* the limit raised: the same dt steps */
    CHECK(lm_sim_set_courant(sim, 2) == LM_OK);
    CHECK(lm_sim_step(sim) == LM_OK && sim->step == 1);
    /* a dt past the new limit (2 x 0.7 = 1.4, dt <= 0.0603) is refused, the
     * old one kept */
    CHECK(lm_sim_try_dt(sim, 0.07) == LM_ERR_COURANT);
    CHECK(strstr(sim->err, "dt = 0.07 is too large") != NULL);
    CHECK(sim->def.dt == 0.035);
    CHECK(lm_sim_step(sim) == LM_OK && sim->step == 2);
    CHECK(lm_sim_try_dt(sim, 0.02) == LM_OK && sim->def.dt == 0.02);
    lm_sim_free(sim);

    /* MUSL passes the same dt (0.81 < 1): no refusal */
    sim = disk_scene(0.035, LM_MUSL);
    CHECK(sim != NULL && lm_sim_check_courant(sim) == LM_OK && lm_sim_step(sim) == LM_OK);
    lm_sim_free(sim);

    /* the energy watch */
    lm_sim *a = disk_scene(0.005, LM_MUSL), *b = disk_scene(0.005, LM_MUSL);
    CHECK(a != NULL && b != NULL);
    lm_energy_watch wa, wb;
    lm_energy_watch_begin(a, &wa);
    for (size_t q = 0; q < a->p.n; q++) a->p.vx[q] = b->p.vx[q] = 0.05;   /* the kick */
    lm_energy_watch_begin(b, &wb);
    for (int k = 0; k < 120; k++) {
        lm_energy_watch_step(a, &wa);
        lm_energy_watch_step(b, &wb);
        CHECK(lm_sim_step(a) == LM_OK && lm_sim_step(b) == LM_OK);
    }
    char msg[1200] = "";
    CHECK(lm_energy_watch_end(a, &wa, msg, sizeof msg) == 1);
    CHECK(strncmp(msg, "the total energy rose by ", 25) == 0);
    CHECK(strstr(msg, "(steps 0 to 120)") != NULL);
    char none[1200] = "";
    CHECK(lm_energy_watch_end(b, &wb, none, sizeof none) == 0 && none[0] == 0);
    lm_sim_free(a);
    lm_sim_free(b);
    return CHECK_DONE();
}
