/* membrane_law.h - the contract every membrane law keeps (issue 33 item 3).
 *
 * A law is one file, membrane_law_NAME.c, defining one lm_membrane_law,
 * and one line of the registry (membrane_law.c) that gives it its lm_law
 * number and its name in Lua (lamina.membrane{law = NAME}). The engine
 * asks only the registry's functions below: the step's stress (membrane.c,
 * axisym.c, membrane_force.c), the energies (diag.c, axisym.c,
 * membrane_force.c), the seeding (sim.c) and the Courant check
 * (material.c). No other file tests which law a material has.
 *
 * Strains are logarithmic: a point's length is l = ds exp(eps_t), so the
 * stretch is lambda = exp(eps_t) (membrane.c). The stress a law returns is
 * the one the engine stores: the engine's volume of a point is thickness *
 * (its current length, and its current ring radius in the axisymmetric
 * form) with the unstrained thickness, so a law's stress is the tension per
 * unit of current length (per unit depth in the plane form) divided by the
 * unstrained thickness. For small strains this is the Cauchy stress; at
 * large strain it is the nominal (first Piola) stress of the strip in the
 * plane form (membrane_law_neo_hookean.c derives it).
 *
 * The wrinkle rule (one_way, [M] §3.2) is not a law's: the registry
 * applies it to every law (membrane_wrinkle.c). */
#ifndef LAMINA_MEMBRANE_LAW_H
#define LAMINA_MEMBRANE_LAW_H

#include "mpm.h"

typedef struct lm_membrane_law {
    /* Its name in Lua and in messages. */
    const char *name;
    /* The plane form: sigma_t of a membrane stretched along its tangent
     * to strain et (the out-of-plane direction as the law says: a string
     * free across, a plane-stress sheet held in depth). */
    double (*stress)(const lm_material *mat, double et);
    /* The out-of-plane stress stored with sigma_t = st in the plane form
     * (szz; 0 for a law free across). */
    double (*szz)(const lm_material *mat, double st);
    /* The axisymmetric form: both in-surface stresses of a ring from its
     * meridional and hoop strains. NULL: the law carries sigma_t only
     * (meridional cords): sigma_t = stress(et), sigma_h = 0. */
    void (*stress_biaxial)(const lm_material *mat, double et, double eh, double *st,
                           double *sh);
    /* The tension field of a wrinkled ring (membrane_wrinkle.c): sigma
     * along the taut direction at strain e, the other direction (strain
     * e_other) free of stress. Needed when stress_biaxial is given. */
    double (*stress_taut)(const lm_material *mat, double e, double e_other);
    /* Stored energy of a point of volume V (the engine's, above) at
     * strain et: plane form, point quadrature. */
    double (*energy)(const lm_material *mat, double V, double et);
    /* The same of a ring point (axisymmetric form) at strains et, eh. */
    double (*energy_biaxial)(const lm_material *mat, double V, double et, double eh);
    /* Stored energy of a straight segment of unstrained length L0 at
     * strain eps (the segment form, membrane_force.c): thickness * L0 *
     * W(lambda), W the energy per unstrained volume, whose derivative
     * dW/dlambda is stress(): the segment's force is the work's. */
    double (*energy_segment)(const lm_material *mat, double L0, double eps);
    /* The fastest wave along the membrane at rest, sqrt(modulus / rho):
     * the Courant check and the time-step advice (docs/physics.md §5). */
    double (*wave_speed)(const lm_material *mat);
    /* The law's own parameter rules beyond every membrane's (material.c);
     * NULL: none. 0 if fine, else -1 with why in err. */
    int (*validate)(const lm_material *mat, char *err, size_t errlen);
} lm_membrane_law;

/* The laws (membrane_law_*.c). */
extern const lm_membrane_law lm_law_uniaxial;
extern const lm_membrane_law lm_law_plane_stress;
extern const lm_membrane_law lm_law_neo_hookean;

/* The registry (membrane_law.c): the law of an lm_law, NULL if none. */
const lm_membrane_law *lm_membrane_law_of(lm_law law);

/* What the engine calls. Each applies the wrinkle rule when the material
 * asks for it (one_way): no stress while et < 0, the compressive strain
 * kept; rings by the tension-field rule (membrane_wrinkle.c). */
/* lm_membrane_stress, lm_membrane_stress_biaxial, lm_membrane_energy:
 * step.h. */
double lm_membrane_szz(const lm_material *mat, double st);
double lm_membrane_ring_energy(const lm_material *mat, double V, double et, double eh);
double lm_membrane_segment_energy_of(const lm_material *mat, double L0, double eps);
double lm_membrane_wave_speed(const lm_material *mat);
int lm_membrane_law_validate(const lm_material *mat, char *err, size_t errlen);

/* For the laws linear in the strain (membrane_law.c): the papers' point
 * energy 1/2 V sigma_t eps_t, a ring's 1/2 V (sigma_t eps_t + sigma_h
 * eps_h), and a segment's exact energy under sigma = Ep eps. */
double lm_membrane_energy_linear(const lm_material *mat, double V, double et);
double lm_membrane_ring_energy_linear(const lm_material *mat, double V, double et, double eh);
double lm_membrane_segment_energy_linear(const lm_material *mat, double Ep, double L0,
                                         double eps);

/* membrane_wrinkle.c: the tension-field rule of a ring whose biaxial
 * stresses (st, sh) are not both >= 0. */
void lm_membrane_wrinkle(const lm_membrane_law *law, const lm_material *mat, double et,
                         double eh, double *st, double *sh);

#endif
