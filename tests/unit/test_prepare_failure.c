/* test_prepare_failure.c - issue 33 item 1: lm_sim_prepare leaves nothing
 * marked prepared when it fails. A membrane whose normals come without
 * connectivity (isosurface) cannot be prepared while one of its points is
 * NaN; the sim stays unprepared, and once the point is put back the next
 * prepare succeeds and gives the same tangents and stresses, to the bit,
 * as the same scene prepared without the failure (the reference). */
#include <math.h>
#include <string.h>

#include "check.h"
#include "step.h"

#define NPTS 12

static lm_sim *scene(int *mb)
{
    lm_sim_def d;
    lm_sim_def_default(&d);
    d.hx = d.hy = 0.1;
    d.dt = 1e-4;
    d.courant = 2;   /* dt c / h = 1.41 for this membrane: what the test
                        steps is the prepare, not the Courant refusal */
    char err[256];
    lm_sim *sim = lm_sim_new(&d, err, sizeof err);
    if (!sim) return NULL;
    /* static: the sim borrows the material (a local would dangle once
     * scene returns: read as garbage by the step's material-update table) */
    static lm_material skin = {.kind = LM_MEMBRANE, .rho = 0.5, .E = 1e6, .nu = 0.3,
                        .thickness = 0.01, .law = LM_LAW_UNIAXIAL};
    int si = lm_sim_add_material(sim, &skin);
    *mb = lm_sim_add_membrane(sim, si, 1);
    for (int k = 0; k < NPTS; k++) {   /* a circle of radius 0.2, stretched 1 % */
        double a = 2 * 3.14159265358979323846 * k / NPTS;
        size_t q = sim->p.n;
        if (lm_sim_add_particle(sim, *mb, 0.5 + 0.2 * cos(a), 0.5 + 0.2 * sin(a), 0, 0, 1e-3,
                                0.5) != LM_OK ||
            lm_sim_set_membrane_point(sim, q, 0.01, 0.01) != LM_OK)
            return NULL;
    }
    if (lm_sim_set_membrane_normals(sim, *mb, LM_NORMALS_ISOSURFACE) != LM_OK) return NULL;
    return sim;
}

int main(void)
{
    int mb, rb;
    lm_sim *sim = scene(&mb), *ref = scene(&rb);
    CHECK(sim != NULL && ref != NULL);
    CHECK(lm_sim_prepare(ref) == LM_OK && ref->prepared == 1);

    double x3 = sim->p.x[3];
    sim->p.x[3] = NAN;
    CHECK(lm_sim_prepare(sim) != LM_OK);
    CHECK(sim->prepared == 0);      /* was 1: the next step skipped the prepare */
    CHECK(strstr(sim->err, "normals of membrane") != NULL);

    sim->p.x[3] = x3;               /* the scene fixed */
    CHECK(lm_sim_prepare(sim) == LM_OK && sim->prepared == 1);
    size_t n = sim->p.n;
    CHECK(n == ref->p.n && n == NPTS);
    CHECK(memcmp(sim->p.tx, ref->p.tx, n * sizeof *sim->p.tx) == 0);
    CHECK(memcmp(sim->p.ty, ref->p.ty, n * sizeof *sim->p.ty) == 0);
    CHECK(memcmp(sim->p.sxx, ref->p.sxx, n * sizeof *sim->p.sxx) == 0);
    CHECK(memcmp(sim->p.syy, ref->p.syy, n * sizeof *sim->p.syy) == 0);
    CHECK(memcmp(sim->p.sxy, ref->p.sxy, n * sizeof *sim->p.sxy) == 0);
    /* and it steps as the reference does */
    CHECK(lm_sim_step_then(sim, 0) == LM_OK && lm_sim_step_then(ref, 0) == LM_OK);
    CHECK(lm_sim_hash(sim) == lm_sim_hash(ref));
    lm_sim_free(sim);
    lm_sim_free(ref);
    return CHECK_DONE();
}
