/* membrane_law_uniaxial.c - a string or wire ([T] eq 5.9, [M] §3):
 * sigma_t = E eps_t, nothing across it; in the axisymmetric form
 * meridional cords (no hoop stress). The contract: membrane_law.h. */
#include <math.h>

#include "membrane_law.h"

static double stress(const lm_material *mat, double et)
{
    return mat->E * et;
}

static double energy_segment(const lm_material *mat, double L0, double eps)
{
    return lm_membrane_segment_energy_linear(mat, mat->E, L0, eps);
}

/* docs/physics.md §5: the bar wave sqrt(E / rho). */
static double wave_speed(const lm_material *mat)
{
    return sqrt(mat->E / mat->rho);
}

const lm_membrane_law lm_law_uniaxial = {
    .name = "uniaxial",
    .stress = stress,
    .szz = NULL,              /* free across: sigma_z = 0 */
    .stress_biaxial = NULL,   /* cords: sigma_h = 0 */
    .stress_taut = NULL,
    .energy = lm_membrane_energy_linear,
    .energy_biaxial = lm_membrane_ring_energy_linear,
    .energy_segment = energy_segment,
    .wave_speed = wave_speed,
    .validate = NULL,
};
