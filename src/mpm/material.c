/* material.c - what every material kind answers: validation, wave speed. */
#include <math.h>
#include <stdio.h>

#include "mpm.h"
#include "step.h"

/* docs/physics.md §5: the plane-strain P-wave or the plane-stress wave. */
double lm_material_wave_speed(const lm_material *mat)
{
    double E = mat->E, nu = mat->nu, rho = mat->rho;
    switch (mat->kind) {
    case LM_ELASTIC:
        if (mat->plane == LM_PLANE_STRAIN)
            return sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * rho));
        return sqrt(E / ((1 - nu * nu) * rho));
    case LM_MEMBRANE:
        if (mat->law == LM_LAW_PLANE_STRESS) return sqrt(E / ((1 - nu * nu) * rho));
        return sqrt(E / rho);
    case LM_GAS:
        return lm_gas_sound_speed(mat, mat->e0);
    case LM_LINEAR_FLUID:
        return sqrt(mat->beta / rho);
    }
    return 0;
}

int lm_material_validate(const lm_material *mat, char *err, size_t errlen)
{
    if (!(mat->rho > 0) || !isfinite(mat->rho)) {
        snprintf(err, errlen, "rho must be positive and finite (got %g)", mat->rho);
        return -1;
    }
    switch (mat->kind) {
    case LM_ELASTIC:
        if (!(mat->E > 0) || !isfinite(mat->E)) {
            snprintf(err, errlen, "E must be positive and finite (got %g)", mat->E);
            return -1;
        }
        if (!(mat->nu > -1) || !(mat->nu < 0.5)) {
            snprintf(err, errlen, "nu must lie in (-1, 0.5) (got %g)", mat->nu);
            return -1;
        }
        break;
    case LM_MEMBRANE:
        if (!(mat->E >= 0) || !isfinite(mat->E)) {
            snprintf(err, errlen, "E must be non-negative and finite (got %g)", mat->E);
            return -1;
        }
        if (!(mat->nu > -1) || !(mat->nu < 1)) {
            snprintf(err, errlen, "nu must lie in (-1, 1) (got %g)", mat->nu);
            return -1;
        }
        if (!(mat->thickness > 0) || !isfinite(mat->thickness)) {
            snprintf(err, errlen, "thickness must be positive (got %g)", mat->thickness);
            return -1;
        }
        break;
    case LM_GAS:
        if (!(mat->gamma > 1) || !isfinite(mat->gamma)) {
            snprintf(err, errlen, "gamma must be greater than 1 (got %g)", mat->gamma);
            return -1;
        }
        if (!(mat->e0 >= 0) || !isfinite(mat->e0)) {
            snprintf(err, errlen, "the internal energy e must be >= 0 (got %g)", mat->e0);
            return -1;
        }
        if (!(mat->mu >= 0) || !isfinite(mat->mu)) {
            snprintf(err, errlen, "mu must be >= 0 (got %g)", mat->mu);
            return -1;
        }
        if (mat->av && !(mat->av_lambda > 0 && mat->av_c1 >= 0 && mat->av_c2 >= 0)) {
            snprintf(err, errlen, "artificial viscosity needs lambda > 0, c1 >= 0, c2 >= 0");
            return -1;
        }
        break;
    case LM_LINEAR_FLUID:
        if (!(mat->beta > 0) || !isfinite(mat->beta)) {
            snprintf(err, errlen, "beta must be positive (got %g)", mat->beta);
            return -1;
        }
        break;
    }
    return 0;
}
