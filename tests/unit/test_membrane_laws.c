/* test_membrane_laws.c - every registered membrane law keeps the contract
 * (src/mpm/membrane_law.h; issue 33 item 3). The checks run over the
 * registry, so a new law is checked the day it is registered:
 * - its name is unique and the registry's list ends after the last law;
 * - no strain, no stress; at small strain the slope d sigma / d eps is
 *   rho c^2 with c its wave speed at rest (the Courant check's);
 * - the segment energy's derivative is the stress, at large strain too
 *   (d E / d eps = thickness L0 e^eps sigma: the segment force is the
 *   energy's, so the segment form keeps energy);
 * - the point and ring energies are the work of the stress at small strain
 *   (the linear laws' 1/2 V sigma eps is exact only there);
 * - the one-way rule gives slack points no stress and no energy, and the
 *   tension field of a ring is continuous where it starts. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "membrane_law.h"
#include "step.h"

/* A membrane material of law k that its law accepts. */
static lm_material material(int k, int one_way)
{
    lm_material m = {.kind = LM_MEMBRANE, .rho = 2, .E = 3e4, .nu = 0.3, .thickness = 0.01,
                     .law = (lm_law)k, .one_way = one_way};
    char err[256];
    if (lm_material_validate(&m, err, sizeof err)) m.nu = 0.5;
    CHECK(lm_material_validate(&m, err, sizeof err) == 0);
    return m;
}

static double rel(double a, double b)
{
    return fabs(a - b) / fmax(fabs(b), 1e-300);
}

static void check_law(int k)
{
    const lm_membrane_law *law = lm_membrane_law_of((lm_law)k);
    CHECK(law != NULL && law->name && strcmp(lm_law_name(k), law->name) == 0);
    for (int j = 0; j < k; j++) CHECK(strcmp(lm_law_name(j), law->name) != 0);
    lm_material m = material(k, 0);
    const double d = 1e-6, L0 = 0.7, V0 = 0.3;

    CHECK(lm_membrane_stress(&m, 0) == 0);
    double slope = (lm_membrane_stress(&m, d) - lm_membrane_stress(&m, -d)) / (2 * d);
    double c = lm_material_wave_speed(&m);
    CHECK_NEAR(slope / (m.rho * c * c), 1, 1e-6);

    static const double eps[] = {-0.3, -0.05, 0.02, 0.4, 0.69};
    for (size_t i = 0; i < sizeof eps / sizeof eps[0]; i++) {
        double e = eps[i];
        double dE = (lm_membrane_segment_energy_of(&m, L0, e + d) -
                     lm_membrane_segment_energy_of(&m, L0, e - d)) / (2 * d);
        double want = m.thickness * L0 * exp(e) * lm_membrane_stress(&m, e);
        if (!(rel(dE, want) < 1e-6))
            fprintf(stderr, "law %s, eps %g: dE/deps %.12g, work %.12g\n", law->name, e, dE,
                    want);
        CHECK(rel(dE, want) < 1e-6);
    }

    /* small strain: the point's energy at volume V0 e^eps, the ring's at
     * V0 e^(et + eh), are the work of the stresses to O(eps) */
    const double e = 1e-3, eh = 4e-4, h = 1e-7;
    double dP = (lm_membrane_energy(&m, V0 * exp(e + h), e + h) -
                 lm_membrane_energy(&m, V0 * exp(e - h), e - h)) / (2 * h);
    CHECK(rel(dP, V0 * exp(e) * lm_membrane_stress(&m, e)) < 2e-3);
    double st, sh;
    lm_membrane_stress_biaxial(&m, e, eh, &st, &sh);
    double dR = (lm_membrane_ring_energy(&m, V0 * exp(e + h + eh), e + h, eh) -
                 lm_membrane_ring_energy(&m, V0 * exp(e - h + eh), e - h, eh)) / (2 * h);
    CHECK(rel(dR, V0 * exp(e + eh) * st) < 2e-3);
    if (law->stress_biaxial) {
        double dH = (lm_membrane_ring_energy(&m, V0 * exp(e + eh + h), e, eh + h) -
                     lm_membrane_ring_energy(&m, V0 * exp(e + eh - h), e, eh - h)) / (2 * h);
        CHECK(rel(dH, V0 * exp(e + eh) * sh) < 2e-3);
    } else {
        CHECK(sh == 0);   /* cords */
    }

    /* the one-way rule */
    lm_material w = material(k, 1);
    CHECK(lm_membrane_stress(&w, -0.1) == 0 && lm_membrane_energy(&w, V0, -0.1) == 0 &&
          lm_membrane_segment_energy_of(&w, L0, -0.1) == 0);
    CHECK(lm_membrane_stress(&w, 0.1) == lm_membrane_stress(&m, 0.1));
    lm_membrane_stress_biaxial(&w, -0.1, -0.2, &st, &sh);
    CHECK(st == 0 && sh == 0 && lm_membrane_ring_energy(&w, V0, -0.1, -0.2) == 0);
    if (law->stress_biaxial) {
        /* the hoop strain where the full law's hoop stress crosses 0 at
         * et = 0.2 (bisection), then the stresses just either side */
        double lo = -1, hi = 0.2, et = 0.2;
        for (int it = 0; it < 200; it++) {
            double mid = 0.5 * (lo + hi);
            law->stress_biaxial(&w, et, mid, &st, &sh);
            if (sh < 0) lo = mid; else hi = mid;
        }
        double st_in, sh_in, st_out, sh_out;
        lm_membrane_stress_biaxial(&w, et, hi + 1e-9, &st_in, &sh_in);
        lm_membrane_stress_biaxial(&w, et, lo - 1e-9, &st_out, &sh_out);
        CHECK(sh_in >= 0 && sh_out == 0);
        CHECK(rel(st_out, st_in) < 1e-6);
        CHECK(rel(lm_membrane_ring_energy(&w, V0, et, lo - 1e-9),
                  lm_membrane_ring_energy(&w, V0, et, hi + 1e-9)) < 1e-6);
    }
    printf("law %-12s: checked (wave speed at rest %.6g)\n",
           law->name, c);
}

int main(void)
{
    CHECK(lm_law_name(LM_LAW_COUNT) == NULL && lm_law_name(-1) == NULL);
    CHECK(lm_membrane_law_of(LM_LAW_COUNT) == NULL);
    for (int k = 0; k < LM_LAW_COUNT; k++) check_law(k);
    /* an unregistered law is refused by the validation, naming it */
    lm_material bad = {.kind = LM_MEMBRANE, .rho = 1, .E = 1, .thickness = 1,
                       .law = LM_LAW_COUNT};
    char err[256];
    CHECK(lm_material_validate(&bad, err, sizeof err) != 0 && strstr(err, "law 3") != NULL);
    return CHECK_DONE();
}
