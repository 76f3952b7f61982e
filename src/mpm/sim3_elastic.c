/* sim3_elastic.c - the isotropic linear elastic solid in 3D, Jaumann rate:
 * the 2D law of material_elastic.c ([F] eqs 18-20, [T] eq 5.8) without the
 * plane assumption. Voigt order xx, yy, zz, yz, xz, xy; tensor shears
 * (sigma_xy = 2 G eps_xy). */
#include "mpm3.h"
#include "sim3_elastic.h"

/* The update of sim3_elastic.h, the moduli made from the material. */
void lm3_elastic_update(const lm3_material *mat, const double de[6], const double W[9],
                        double dt, double s[6])
{
    double G, lam;
    lm3_elastic_moduli(mat, &G, &lam);
    lm3_elastic_update_gl(G, lam, de, W, dt, s);
}

/* 1/2 sigma : C^-1 : sigma: material_elastic.c's full 3D compliance with
 * all three shears. */
double lm3_elastic_energy_density(const lm3_material *mat, const double s[6])
{
    double E = mat->E, nu = mat->nu;
    return (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] -
            2 * nu * (s[0] * s[1] + s[1] * s[2] + s[2] * s[0]) +
            2 * (1 + nu) * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])) / (2 * E);
}
