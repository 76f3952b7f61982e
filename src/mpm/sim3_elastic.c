/* sim3_elastic.c - the isotropic linear elastic solid in 3D, Jaumann rate:
 * the 2D law of material_elastic.c ([F] eqs 18-20, [T] eq 5.8) without the
 * plane assumption. Voigt order xx, yy, zz, yz, xz, xy; tensor shears
 * (sigma_xy = 2 G eps_xy). */
#include "mpm3.h"

/* Voigt index of the symmetric pair (i, j) */
static const int voigt[3][3] = {{0, 5, 4}, {5, 1, 3}, {4, 3, 2}};

/* sigma <- sigma + dt (W.sigma - sigma.W) + lambda tr(de) I + 2 G de, the
 * rotation with the stress at the start of the step, as in 2D. With
 * W = 1/2 (L - L^T), L_ab = dv_a/dx_b, a counter-clockwise spin omega
 * about z has W_xy = -omega and turns diag(s, 0, 0) into
 * sigma_xy = +s omega dt: the 2D check of docs/physics.md §1 step 8. */
void lm3_elastic_update(const lm3_material *mat, const double de[6], const double W[9],
                        double dt, double s[6])
{
    double S[9], R[6];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) S[3 * i + j] = s[voigt[i][j]];
    static const int pi[6] = {0, 1, 2, 1, 0, 0}, pj[6] = {0, 1, 2, 2, 2, 1};
    for (int c = 0; c < 6; c++) {
        int i = pi[c], j = pj[c];
        double r = 0;
        for (int k = 0; k < 3; k++) r += W[3 * i + k] * S[3 * k + j] - S[3 * i + k] * W[3 * k + j];
        R[c] = r * dt;
    }
    double E = mat->E, nu = mat->nu, G = E / (2 * (1 + nu));
    double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), tr = de[0] + de[1] + de[2];
    for (int c = 0; c < 3; c++) s[c] += R[c] + lam * tr + 2 * G * de[c];
    for (int c = 3; c < 6; c++) s[c] += R[c] + 2 * G * de[c];
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
