/* normals_smooth.c - a curvature penalty for the quadratic fit (not in the
 * paper; used by the centred elements, docs/normals.md).
 *
 * Why. With one random point ([N] §4) the least squares pins phi at one
 * place off the membrane. Over the short arc an element holds, the nine
 * quadratic B-splines restricted to the points are nearly dependent, so
 * besides the wanted phi ~ 1 + signed distance there are functions that
 * are almost zero on the points and still 1 at the random point: ridges and
 * saddles whose gradient passes through zero along the membrane - the
 * "phi with the value 1 as the maximum" of [N] §8. Points that wrinkle by
 * a few 1e-4 pick such a function (residual 1e-7 instead of 1e-3) and a
 * normal turns by up to 90 degrees (measured on the dynamic circular
 * membrane, docs/normals.md).
 *
 * What. phi_xx = phi_yy (= phi_zz) and phi_xy = 0 everywhere means
 * phi = a + b.x + c |x|^2: planes, lines, circles and spheres, which the
 * quadratic basis holds exactly. Ridges and saddles are anisotropic. So
 * these rows ask, weakly, for isotropic constant curvature: for the
 * quadratic B-spline coefficients c (3 per axis) every second difference
 * along an axis, D_p c (world-scaled: / h_a^2), minus the mean of all of
 * them, and every mixed difference (/ h_a h_b), times the weight w. Any
 * phi that is exact for a circle or sphere meets them exactly, so those
 * stay exact (unit test); only the nearly free directions are steered. In
 * 2D: 6 + 4 rows, in 3D: 27 + 36. */
#include <string.h>

#include "normals.h"

int lm_nsmooth_rows(lm_nbasis b, const lm_nbox *box, double w, double *S)
{
    if (b != LM_NB_QUADRATIC || !(w > 0))
        return 0;
    const int a = 3, dim = box->dim, n = lm_nbasis_count(b, dim);
    const int nz = dim == 3 ? a : 1, st[3] = {1, a, a * a};
    double h[3];
    for (int ax = 0; ax < dim; ax++)
        h[ax] = (box->hi[ax] - box->lo[ax]) / (box->hi[0] - box->lo[0]);
    /* second differences along each axis, one per line of coefficients */
    double D[27][LM_NMAX], mean[LM_NMAX];
    int nd = 0, r = 0;
    memset(mean, 0, sizeof mean);
    for (int ax = 0; ax < dim; ax++)
        for (int k = 0; k < nz; k++)
            for (int j = 0; j < a; j++)
                for (int i = 0; i < a; i++) {
                    int c[3] = {i, j, k};
                    if (c[ax] != 0)
                        continue;
                    int I = i + a * (j + a * k);
                    double s = 1.0 / (h[ax] * h[ax]);
                    memset(D[nd], 0, sizeof D[nd]);
                    D[nd][I] = s;
                    D[nd][I + st[ax]] = -2 * s;
                    D[nd][I + 2 * st[ax]] = s;
                    nd++;
                }
    for (int q = 0; q < nd; q++)
        for (int I = 0; I < n; I++)
            mean[I] += D[q][I] / nd;
    for (int q = 0; q < nd; q++, r++)
        for (int I = 0; I < n; I++)
            S[(size_t)r * n + I] = w * (D[q][I] - mean[I]);
    /* mixed differences, one per 2x2 square of coefficients in each plane */
    for (int ax = 0; ax < dim; ax++)
        for (int bx = ax + 1; bx < dim; bx++)
            for (int k = 0; k < nz; k++)
                for (int j = 0; j < a; j++)
                    for (int i = 0; i < a; i++) {
                        int c[3] = {i, j, k};
                        if (c[ax] + 1 >= a || c[bx] + 1 >= a)
                            continue;
                        int I = i + a * (j + a * k);
                        double s = w / (h[ax] * h[bx]), *row = S + (size_t)r * n;
                        memset(row, 0, sizeof(double) * (size_t)n);
                        row[I] = s;
                        row[I + st[ax]] = -s;
                        row[I + st[bx]] = -s;
                        row[I + st[ax] + st[bx]] = s;
                        r++;
                    }
    return r;
}
