/* sim3_elastic.h - the 3D elastic update inline, for the step's stress
 * pass (sim3_step.c), private to the engine: the moduli made once a step
 * per material instead of once a particle (two divisions a particle), and
 * the update inlined so that the spin's six entries it does not read are
 * not made (docs/3d.md "Speed"). The same expressions as before, so the
 * same bits; lm3_elastic_update (sim3_elastic.c) is these two. */
#ifndef LAMINA_SIM3_ELASTIC_H
#define LAMINA_SIM3_ELASTIC_H

#include "mpm3.h"

/* shear modulus G and Lame's lambda of an elastic material */
static inline void lm3_elastic_moduli(const lm3_material *mat, double *G, double *lam)
{
    const double E = mat->E, nu = mat->nu;
    *G = E / (2 * (1 + nu));
    *lam = E * nu / ((1 + nu) * (1 - 2 * nu));
}

/* sigma <- sigma + dt (W.sigma - sigma.W) + lambda tr(de) I + 2 G de, the
 * rotation with the stress at the start of the step, as in 2D. With
 * W = 1/2 (L - L^T), L_ab = dv_a/dx_b, a counter-clockwise spin omega
 * about z has W_xy = -omega and turns diag(s, 0, 0) into
 * sigma_xy = +s omega dt: the 2D check of docs/physics.md §1 step 8.
 * W sigma - sigma W = M + M^T with M = W sigma (sigma symmetric, W
 * antisymmetric): M's nine entries from W's three, two products each,
 * instead of the 3 x 3 products of both (8 % of a step: docs/3d.md
 * "Speed"). */
static inline void lm3_elastic_update_gl(double G, double lam, const double de[6],
                                         const double W[9], double dt, double s[6])
{
    const double a = W[1], b = W[2], c = W[5];   /* W_xy, W_xz, W_yz */
    const double xx = s[0], yy = s[1], zz = s[2], yz = s[3], xz = s[4], xy = s[5];
    const double M00 = a * xy + b * xz, M01 = a * yy + b * yz, M02 = a * yz + b * zz;
    const double M10 = -a * xx + c * xz, M11 = -a * xy + c * yz, M12 = -a * xz + c * zz;
    const double M20 = -b * xx - c * xy, M21 = -b * xy - c * yy, M22 = -b * xz - c * yz;
    const double R[6] = {2 * M00 * dt, 2 * M11 * dt, 2 * M22 * dt, (M12 + M21) * dt,
                         (M02 + M20) * dt, (M01 + M10) * dt};
    const double tr = de[0] + de[1] + de[2];
    for (int k = 0; k < 3; k++) s[k] += R[k] + lam * tr + 2 * G * de[k];
    for (int k = 3; k < 6; k++) s[k] += R[k] + 2 * G * de[k];
}

#endif
