/* test_jaumann.c - the objective stress rate ([F] eq 19, docs/physics.md §1
 * step 8): a counter-clockwise rigid spin omega turns diag(s, 0) into
 * sigma_xy = +s omega dt; spinning a stress a quarter turn in many small
 * steps rotates it (diag(s, 0) -> diag(0, s)) and keeps its invariants. */
#include <math.h>

#include "check.h"
#include "step.h"

int main(void)
{
    lm_material mat = {.kind = LM_ELASTIC, .rho = 1, .E = 1e4, .nu = 0.3, .plane = LM_PLANE_STRESS};
    double s = 5, omega = 2, dt = 1e-3;
    /* v = omega (-y, x): L_xy = -omega, L_yx = omega, w = (L_xy - L_yx)/2 */
    double w = -omega;
    double sxx = s, syy = 0, sxy = 0, szz = 0;
    lm_elastic_update(&mat, 0, 0, 0, w, dt, &sxx, &syy, &sxy, &szz);
    CHECK_NEAR(sxy, s * omega * dt, 1e-15);
    CHECK_NEAR(sxx, s, 1e-15);

    sxx = s; syy = 0; sxy = 0;
    int n = 100000;
    double h = (acos(-1.0) / 2) / omega / n;
    for (int k = 0; k < n; k++) lm_elastic_update(&mat, 0, 0, 0, w, h, &sxx, &syy, &sxy, &szz);
    /* forward Euler on the rotation: error O(h), amplitude grows by
     * (1 + (2 omega h)^2)^(n/2) ~ 1 + 2 omega^2 h t */
    CHECK_NEAR(sxx, 0, 1e-3 * s);
    CHECK_NEAR(syy, s, 1e-3 * s);
    CHECK_NEAR(sxy, 0, 1e-3 * s);
    CHECK_NEAR(sxx + syy, s, 1e-9);   /* the trace is kept exactly */

    /* plane strain: sigma_zz = nu (sxx + syy) for a pure strain increment */
    lm_material ps = {.kind = LM_ELASTIC, .rho = 1, .E = 1e4, .nu = 0.3, .plane = LM_PLANE_STRAIN};
    sxx = syy = sxy = szz = 0;
    lm_elastic_update(&ps, 1e-4, -3e-5, 2e-5, 0, dt, &sxx, &syy, &sxy, &szz);
    CHECK_NEAR(szz, 0.3 * (sxx + syy), 1e-12);
    double G = 1e4 / 2.6;
    CHECK_NEAR(sxy, 2 * G * 2e-5, 1e-12);
    /* strain energy density 1/2 sigma:eps for that increment */
    double W = 0.5 * (sxx * 1e-4 + syy * -3e-5 + 2 * sxy * 2e-5);
    CHECK_NEAR(lm_elastic_energy_density(&ps, sxx, syy, sxy, szz), W, 1e-15);
    return CHECK_DONE();
}
