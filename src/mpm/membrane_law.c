/* membrane_law.c - the registry of membrane laws and what the engine asks
 * of them (the contract: membrane_law.h).
 *
 * Adding a law: its file membrane_law_NAME.c, its lm_law value (mpm.h) and
 * its line in `laws` below; docs/contributing.md walks through it. */
#include <math.h>

#include "membrane_law.h"
#include "step.h"
#include "util.h"

/* Indexed by lm_law: the order is the enum's, and a law's number is what
 * a checkpoint stores, so a new law goes at the end. */
static const lm_membrane_law *const laws[LM_LAW_COUNT] = {
    [LM_LAW_UNIAXIAL] = &lm_law_uniaxial,
    [LM_LAW_PLANE_STRESS] = &lm_law_plane_stress,
    [LM_LAW_NEO_HOOKEAN] = &lm_law_neo_hookean,
};

const lm_membrane_law *lm_membrane_law_of(lm_law law)
{
    return (unsigned)law < LM_LAW_COUNT ? laws[law] : NULL;
}

const char *lm_law_name(int law)
{
    return law >= 0 && law < LM_LAW_COUNT ? laws[law]->name : NULL;
}

/* [M] §3.2 / Fig 13, the one-way law: E_t = 0 while eps_t < 0, the
 * compressive strain kept (slack), whatever the law. */
double lm_membrane_stress(const lm_material *mat, double et)
{
    if (mat->one_way && et < 0) return 0;
    return laws[mat->law]->stress(mat, et);
}

void lm_membrane_stress_biaxial(const lm_material *mat, double et, double eh, double *st,
                                double *sh)
{
    const lm_membrane_law *law = laws[mat->law];
    if (!law->stress_biaxial) {   /* cords: along the meridian only */
        *st = lm_membrane_stress(mat, et);
        *sh = 0;
        return;
    }
    law->stress_biaxial(mat, et, eh, st, sh);
    if (!mat->one_way || (*st >= 0 && *sh >= 0)) return;
    lm_membrane_wrinkle(law, mat, et, eh, st, sh);
}

double lm_membrane_szz(const lm_material *mat, double st)
{
    const lm_membrane_law *law = laws[mat->law];
    return law->szz ? law->szz(mat, st) : 0;
}

double lm_membrane_energy(const lm_material *mat, double V, double et)
{
    if (mat->one_way && et < 0) return 0;   /* slack: no stress, no energy */
    return laws[mat->law]->energy(mat, V, et);
}

double lm_membrane_ring_energy(const lm_material *mat, double V, double et, double eh)
{
    return laws[mat->law]->energy_biaxial(mat, V, et, eh);
}

double lm_membrane_segment_energy_of(const lm_material *mat, double L0, double eps)
{
    if (mat->one_way && eps < 0) return 0;
    return laws[mat->law]->energy_segment(mat, L0, eps);
}

double lm_membrane_wave_speed(const lm_material *mat)
{
    return laws[mat->law]->wave_speed(mat);
}

int lm_membrane_law_validate(const lm_material *mat, char *err, size_t errlen)
{
    const lm_membrane_law *law = lm_membrane_law_of(mat->law);
    if (!law) {
        lu_err(err, errlen, "law %d is not a membrane law (0 to %d)", (int)mat->law,
               LM_LAW_COUNT - 1);
        return -1;
    }
    return law->validate ? law->validate(mat, err, errlen) : 0;
}

/* ---- shared by the laws linear in the (logarithmic) strain ------------- */

/* The papers' small-strain energy of a point: 1/2 V sigma_t eps_t. */
double lm_membrane_energy_linear(const lm_material *mat, double V, double et)
{
    return 0.5 * V * lm_membrane_stress(mat, et) * et;
}

/* A ring's: 1/2 V (sigma_t eps_t + sigma_h eps_h), wrinkled or not. */
double lm_membrane_ring_energy_linear(const lm_material *mat, double V, double et, double eh)
{
    double st, sh;
    lm_membrane_stress_biaxial(mat, et, eh, &st, &sh);
    return 0.5 * V * (st * et + sh * eh);
}

/* A segment's exact energy under sigma = Ep eps: thickness * int sigma dl
 * with l = L0 exp(eps), = Ep L0 thickness [(eps - 1) e^eps + 1]
 * (~ 1/2 Ep A L0 eps^2). */
double lm_membrane_segment_energy_linear(const lm_material *mat, double Ep, double L0,
                                         double eps)
{
    return Ep * L0 * mat->thickness * ((eps - 1) * exp(eps) + 1);
}
