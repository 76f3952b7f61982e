/* membrane_law_neo_hookean.c - the incompressible neo-Hookean membrane,
 * for large stretch (rubber; lamina's, after Rivlin's neo-Hookean solid).
 * The contract: membrane_law.h.
 *
 * The solid: W = mu/2 (l1^2 + l2^2 + l3^2 - 3) per unstrained volume,
 * incompressible (l1 l2 l3 = 1), so sigma_i = mu l_i^2 - p. A membrane is
 * in plane stress through its thickness: sigma_3 = 0 gives p = mu l3^2,
 * and with l3 = 1/(l1 l2)
 *   W(l1, l2) = mu/2 (l1^2 + l2^2 + 1/(l1^2 l2^2) - 3),
 *   P1 = dW/dl1 = mu (l1 - 1/(l1^3 l2^2))          (nominal stress)
 *   sigma1 = l1 P1 = mu (l1^2 - 1/(l1 l2)^2)        (Cauchy, J = 1).
 * Uniaxial tension, the strip free across (P2 = 0, so l2 = l1^(-1/2)):
 *   W = mu/2 (l^2 + 2/l - 3),  P = mu (l - 1/l^2),  sigma = mu (l^2 - 1/l),
 * and the tension per unstrained width T = thickness * P. At small strain
 * l = 1 + eps: P = 3 mu eps, so Young's modulus is E = 3 mu: the law takes
 * E (as every membrane does) and mu = E / 3; nu is 1/2 by incompressibility.
 *
 * What the engine stores (membrane_law.h): the tension per unit current
 * length over the unstrained thickness, since its volume of a point is the
 * unstrained thickness times the current length (and ring radius).
 * - The plane form is the strip: the unit depth is its unstrained width,
 *   free to narrow, so sigma_t = P (sigma_z = 0) and the force per unit
 *   depth is T.
 * - A ring (axisymmetric form): the tension per current length is
 *   sigma1 * thickness * l3, so s1 = sigma1 / (l1 l2) = P1 / l2, and
 *   likewise s2 = P2 / l1; the force per radian s1 thickness r = P1
 *   thickness r0, the work of W.
 * - Wrinkled across (membrane_wrinkle.c) the ring is the strip along its
 *   taut direction: s = P(l) / l_other, the strip's force over the
 *   ring's present width across.
 * The energies are W times the unstrained volume (V / l in the plane form,
 * V / (l1 l2) for a ring, thickness L0 for a segment), so the segment
 * force thickness dW/dl is the work's.
 *
 * The waves: dP/dl = mu (1 + 2/l^3) is 3 mu = E at rest, so the speed at
 * rest is sqrt(E / rho), the Courant check's (as for the linear laws, the
 * speed at rest: stretched, the wave is slower along the unstrained strip,
 * sqrt(mu (1 + 2/l^3) / rho), but l times that across the grid, 1.29
 * times the speed at rest at l = 2; the linear law's is sqrt(l) times). */
#include <math.h>

#include "membrane_law.h"
#include "util.h"

static double mu_of(const lm_material *mat)
{
    return mat->E / 3;
}

/* P(l) of the strip free across. */
static double strip(double mu, double l)
{
    return mu * (l - 1 / (l * l));
}

/* W(l) of the strip free across, per unstrained volume. */
static double strip_energy(double mu, double l)
{
    return 0.5 * mu * (l * l + 2 / l - 3);
}

static double stress(const lm_material *mat, double et)
{
    return strip(mu_of(mat), exp(et));
}

static void stress_biaxial(const lm_material *mat, double et, double eh, double *st,
                           double *sh)
{
    double mu = mu_of(mat), l1 = exp(et), l2 = exp(eh);
    double c = 1 / (l1 * l1 * l2 * l2);   /* l3^2 */
    *st = mu * (l1 - c / l1) / l2;        /* P1 / l2 */
    *sh = mu * (l2 - c / l2) / l1;        /* P2 / l1 */
}

static double stress_taut(const lm_material *mat, double e, double e_other)
{
    return strip(mu_of(mat), exp(e)) / exp(e_other);
}

static double energy(const lm_material *mat, double V, double et)
{
    double l = exp(et);
    return V / l * strip_energy(mu_of(mat), l);
}

/* W(l1, l2) V / (l1 l2); wrinkled (one_way, a stress of the full law < 0)
 * the strip's W along the taut direction, none when slack both ways. */
static double energy_biaxial(const lm_material *mat, double V, double et, double eh)
{
    double mu = mu_of(mat), l1 = exp(et), l2 = exp(eh), V0 = V / (l1 * l2);
    double st, sh;
    stress_biaxial(mat, et, eh, &st, &sh);
    if (!mat->one_way || (st >= 0 && sh >= 0))
        return V0 * 0.5 * mu * (l1 * l1 + l2 * l2 + 1 / (l1 * l1 * l2 * l2) - 3);
    double e = fmax(et, eh);
    return e > 0 ? V0 * strip_energy(mu, exp(e)) : 0;
}

static double energy_segment(const lm_material *mat, double L0, double eps)
{
    return L0 * mat->thickness * strip_energy(mu_of(mat), exp(eps));
}

static double wave_speed(const lm_material *mat)
{
    return sqrt(mat->E / mat->rho);
}

/* nu is not a parameter of an incompressible law: refused unless left
 * out (0, the membrane's default) or 1/2, what incompressibility gives. */
static int validate(const lm_material *mat, char *err, size_t errlen)
{
    if (mat->nu == 0 || mat->nu == 0.5) return 0;
    lu_err(err, errlen, "law \"neo_hookean\" is incompressible (nu = 0.5): leave nu out or "
           "give 0.5 (got %g)", mat->nu);
    return -1;
}

const lm_membrane_law lm_law_neo_hookean = {
    .name = "neo_hookean",
    .stress = stress,
    .szz = NULL,   /* the strip is free in depth: sigma_z = 0 */
    .stress_biaxial = stress_biaxial,
    .stress_taut = stress_taut,
    .energy = energy,
    .energy_biaxial = energy_biaxial,
    .energy_segment = energy_segment,
    .wave_speed = wave_speed,
    .validate = validate,
};
