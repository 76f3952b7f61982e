/* material.c - what every material kind answers: validation, wave speed. */
#include <math.h>
#include <stdio.h>

#include "mpm.h"

/* physics.md §5: the plane-strain P-wave or the plane-stress wave. */
double lm_material_wave_speed(const lm_material *mat)
{
    double E = mat->E, nu = mat->nu, rho = mat->rho;
    switch (mat->kind) {
    case LM_ELASTIC:
        if (mat->plane == LM_PLANE_STRAIN)
            return sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * rho));
        return sqrt(E / ((1 - nu * nu) * rho));
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
    }
    return 0;
}
