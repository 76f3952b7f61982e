/* membrane_law_plane_stress.c - a linear plane-stress sheet ([T] eq 5.15):
 * sigma_n = 0 through the thickness; in the plane form the sheet is held
 * in depth (eps_z = 0), so sigma_t = E' eps_t and sigma_z = nu sigma_t with
 * E' = E / (1 - nu^2); a ring (axisymmetric form) is biaxial, sigma_t =
 * E'(eps_t + nu eps_h), sigma_h = E'(eps_h + nu eps_t). The contract:
 * membrane_law.h. */
#include <math.h>

#include "membrane_law.h"

static double stress(const lm_material *mat, double et)
{
    return mat->E * et / (1 - mat->nu * mat->nu);
}

static double szz(const lm_material *mat, double st)
{
    return mat->nu * st;
}

static void stress_biaxial(const lm_material *mat, double et, double eh, double *st,
                           double *sh)
{
    double Ep = mat->E / (1 - mat->nu * mat->nu);
    *st = Ep * (et + mat->nu * eh);
    *sh = Ep * (eh + mat->nu * et);
}

/* Wrinkled across, the sheet is in uniaxial stress: sigma = E eps. */
static double stress_taut(const lm_material *mat, double e, double e_other)
{
    (void)e_other;
    return mat->E * e;
}

static double energy_segment(const lm_material *mat, double L0, double eps)
{
    return lm_membrane_segment_energy_linear(mat, mat->E / (1 - mat->nu * mat->nu), L0, eps);
}

/* docs/physics.md §5: the plane-stress wave sqrt(E / ((1 - nu^2) rho)). */
static double wave_speed(const lm_material *mat)
{
    double E = mat->E, nu = mat->nu, rho = mat->rho;
    return sqrt(E / ((1 - nu * nu) * rho));
}

const lm_membrane_law lm_law_plane_stress = {
    .name = "plane_stress",
    .stress = stress,
    .szz = szz,
    .stress_biaxial = stress_biaxial,
    .stress_taut = stress_taut,
    .energy = lm_membrane_energy_linear,
    .energy_biaxial = lm_membrane_ring_energy_linear,
    .energy_segment = energy_segment,
    .wave_speed = wave_speed,
    .validate = NULL,
};
