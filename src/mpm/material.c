/* material.c - what every material kind answers: validation, wave speed. */
#include <math.h>
#include <stdio.h>

#include "membrane_law.h"
#include "mpm.h"
#include "step.h"
#include "util.h"

/* docs/physics.md §5: the plane-strain P-wave or the plane-stress wave;
 * a membrane's from its law. */
double lm_material_wave_speed(const lm_material *mat)
{
    double E = mat->E, nu = mat->nu, rho = mat->rho;
    switch (mat->kind) {
    case LM_ELASTIC:
        if (mat->plane == LM_PLANE_STRAIN)
            return sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * rho));
        return sqrt(E / ((1 - nu * nu) * rho));
    case LM_MEMBRANE:
        return lm_membrane_wave_speed(mat);   /* its law's (membrane_law.h) */
    case LM_GAS:
        return lm_gas_sound_speed(mat, mat->e0);
    case LM_LINEAR_FLUID:
        return sqrt(mat->beta / rho);
    }
    return 0;
}

/* 0 when ok, else -1 with "what (got v)" in err. */
static int check(int ok, double v, const char *what, char *err, size_t errlen)
{
    if (ok) return 0;
    lu_err(err, errlen, "%s (got %g)", what, v);
    return -1;
}

int lm_material_validate(const lm_material *mat, char *err, size_t errlen)
{
    if (check(mat->rho > 0 && isfinite(mat->rho), mat->rho, "rho must be positive and finite",
              err, errlen))
        return -1;
    switch (mat->kind) {
    case LM_ELASTIC:
        if (check(mat->E > 0 && isfinite(mat->E), mat->E, "E must be positive and finite", err,
                  errlen) ||
            check(mat->nu > -1 && mat->nu < 0.5, mat->nu, "nu must lie in (-1, 0.5)", err,
                  errlen))
            return -1;
        break;
    case LM_MEMBRANE:
        if (check(mat->E >= 0 && isfinite(mat->E), mat->E, "E must be non-negative and finite",
                  err, errlen) ||
            check(mat->nu > -1 && mat->nu < 1, mat->nu, "nu must lie in (-1, 1)", err, errlen) ||
            check(mat->thickness > 0 && isfinite(mat->thickness), mat->thickness,
                  "thickness must be positive", err, errlen) ||
            lm_membrane_law_validate(mat, err, errlen))
            return -1;
        break;
    case LM_GAS:
        if (check(mat->gamma > 1 && isfinite(mat->gamma), mat->gamma,
                  "gamma must be greater than 1", err, errlen) ||
            check(mat->e0 >= 0 && isfinite(mat->e0), mat->e0,
                  "the internal energy e must be >= 0", err, errlen) ||
            check(mat->mu >= 0 && isfinite(mat->mu), mat->mu, "mu must be >= 0", err, errlen))
            return -1;
        if (mat->av && !(mat->av_lambda > 0 && mat->av_c1 >= 0 && mat->av_c2 >= 0)) {
            lu_err(err, errlen, "artificial viscosity needs lambda > 0, c1 >= 0, c2 >= 0");
            return -1;
        }
        break;
    case LM_LINEAR_FLUID:
        if (check(mat->beta > 0 && isfinite(mat->beta), mat->beta, "beta must be positive", err,
                  errlen))
            return -1;
        break;
    }
    return 0;
}
