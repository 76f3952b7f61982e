/* membrane_wrinkle.c - the one-way (wrinkle) rule of a ring, for every
 * biaxial law ([M] §3.2 in two directions, the tension-field rule).
 *
 * A membrane cannot carry compression: where the law's biaxial stresses
 * are not both >= 0, it wrinkles across and is pulled only along its
 * larger strain, uniaxially (the law's stress_taut, the other direction
 * free of stress); slack when neither strain is positive. Continuous
 * where the smaller stress reaches 0: there the law's biaxial state is
 * its uniaxial one (for the neo-Hookean law too: P2 = 0 at l2 = l1^-1/2,
 * where P1 / l2 is stress_taut's P(l1) / l2). In one direction
 * (the plane form, cords) the rule is sigma_t = 0 while eps_t < 0, applied
 * by the registry (membrane_law.c). */
#include "membrane_law.h"

void lm_membrane_wrinkle(const lm_membrane_law *law, const lm_material *mat, double et,
                         double eh, double *st, double *sh)
{
    if (et >= eh) {
        *st = et > 0 ? law->stress_taut(mat, et, eh) : 0;
        *sh = 0;
    } else {
        *sh = eh > 0 ? law->stress_taut(mat, eh, et) : 0;
        *st = 0;
    }
}
