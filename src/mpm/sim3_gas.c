/* sim3_gas.c - the compressible viscous gas in 3D ([F] §3.3 eqs 21-25,
 * [T] Ch. 4): material_gas.c's per-particle update with the whole 3 x 3
 * strain rate instead of the plane-strain one. The artificial viscosity
 * and the sound speed are material_gas.c's own functions (shared, not
 * copied), called through the 2D material they read; the sound speed's
 * one line is written out (below, why). */
#include <math.h>

#include "mpm3.h"
#include "step.h"

/* The 2D gas material with this one's constants: what lm_gas_av and
 * lm_gas_sound_speed read (gamma, av and its constants). */
static lm_material as_2d(const lm3_material *mat)
{
    lm_material m = {0};
    m.kind = LM_GAS;
    m.rho = mat->rho;
    m.gamma = mat->gamma;
    m.mu = mat->mu;
    m.e0 = mat->e0;
    m.av = mat->av;
    m.av_c1 = mat->av_c1;
    m.av_c2 = mat->av_c2;
    m.av_lambda = mat->av_lambda;
    m.av_g = mat->av_g;
    return m;
}

/* material_gas.c's lm_gas_sound_speed, [F] eq 22's c = sqrt(gamma p /
 * rho), written out: building the 2D material for it cost 6 % of a gas
 * step (the maxima ask it at every gas point). */
double lm3_gas_sound_speed(const lm3_material *mat, double e)
{
    return sqrt(mat->gamma * (mat->gamma - 1) * (e > 0 ? e : 0));
}

/* [F] eq 24 as material_gas.c reads it (docs/physics.md §2): q = c_max g
 * rho lambda |D| (c1 + c2 |D| / max|D|) in compression, D = div v; g's
 * default is the 2D one, sqrt(2) h (the paper's sqrt(2) dx), so that a
 * one-cell slab is the 2D run (test_sim3_gas.c). */
double lm3_gas_av(const lm3_material *mat, double rho, double div, double max_div,
                  double c_max, double h)
{
    if (!mat->av || !(div < 0)) return 0;
    lm_material m = as_2d(mat);
    return lm_gas_av(&m, rho, div, max_div, c_max, h);
}

/* material_gas.c's lm_gas_update with three rows: the rate D = sym L in
 * Voigt order xx, yy, zz, yz, xz, xy (tensor shears), the pressure from
 * e^k and rho^{k+1} (docs/physics.md §2), then [F] eq 23's work of the new
 * stress on dt D. The sums run in the 2D order with the z terms between
 * (zero in plane strain, so a slab's bits are the 2D ones). */
void lm3_gas_update(const lm3_material *mat, const double L[9], double dt, double rho,
                    double q, double *e, double s[6])
{
    const double mu = mat->mu;
    const double D[6] = {L[0], L[4], L[8], 0.5 * (L[5] + L[7]), 0.5 * (L[2] + L[6]),
                         0.5 * (L[1] + L[3])};
    const double tr = D[0] + D[1] + D[2];
    const double p = (mat->gamma - 1) * rho * *e;
    const double iso = -(2.0 / 3.0) * mu * tr - p - q;
    for (int c = 0; c < 3; c++) s[c] = 2 * mu * D[c] + iso;
    for (int c = 3; c < 6; c++) s[c] = 2 * mu * D[c];
    double work = s[0] * (dt * D[0]) + s[1] * (dt * D[1]) + s[2] * (dt * D[2]) +
                  2 * s[3] * (dt * D[3]) + 2 * s[4] * (dt * D[4]) + 2 * s[5] * (dt * D[5]);
    *e += work / rho;
}
