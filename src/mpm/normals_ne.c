/* normals_ne.c - the normal equations of [N] eqs 12-13, kept for the
 * paper's comparison with QR ([N] §6: Fig 9(b) has a 19 degree error by the
 * normal equations and less than 1 degree by QR).
 *
 * [T]{phi} = [S]^T{phi0} with T = S^T S (the "mass matrix" of [T] eq 7.11)
 * is solved by Gaussian elimination with partial pivoting. The paper does
 * not say how it solved T; elimination is what a 1990s code would do, and
 * on a singular but consistent T (the underdetermined Fig 9(a-b)) it
 * returns whichever member of the solution family rounding selects, which
 * is the behaviour being compared. Only an exactly zero pivot stops it. */
#include <math.h>
#include <stdlib.h>

#include "normals.h"

#define AT(M, i, j, ld) ((M)[(size_t)(i) * (size_t)(ld) + (size_t)(j)])

lm_nerr lm_lsq_normal(int m, int n, const double *A, const double *b,
                      double *x, lm_lsq_info *info)
{
    if (m <= 0 || n <= 0)
        return LM_NERR_INPUT;
    double *T = malloc(sizeof(double) * (size_t)n * (size_t)(n + 1));
    double *sv = malloc(sizeof(double) * (size_t)n);
    if (!T || !sv) {
        free(T);
        free(sv);
        return LM_NERR_MEMORY;
    }
    int ld = n + 1;                       /* [T | S^T phi0] */
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < n; j++) {
            double s = 0;
            for (int p = 0; p < m; p++)
                s += AT(A, p, i, n) * AT(A, p, j, n);
            AT(T, i, j, ld) = s;          /* [N] eq 12 */
        }
        double s = 0;
        for (int p = 0; p < m; p++)
            s += AT(A, p, i, n) * b[p];
        AT(T, i, n, ld) = s;
    }
    lm_nerr e = LM_NERR_NONE;
    for (int k = 0; k < n && e == LM_NERR_NONE; k++) {
        int piv = k;
        for (int i = k + 1; i < n; i++)
            if (fabs(AT(T, i, k, ld)) > fabs(AT(T, piv, k, ld)))
                piv = i;
        if (AT(T, piv, k, ld) == 0.0) {
            e = LM_NERR_SINGULAR;
            break;
        }
        if (piv != k)
            for (int j = k; j <= n; j++) {
                double t = AT(T, k, j, ld);
                AT(T, k, j, ld) = AT(T, piv, j, ld);
                AT(T, piv, j, ld) = t;
            }
        for (int i = k + 1; i < n; i++) {
            double f = AT(T, i, k, ld) / AT(T, k, k, ld);
            for (int j = k; j <= n; j++)
                AT(T, i, j, ld) -= f * AT(T, k, j, ld);
        }
    }
    if (e == LM_NERR_NONE)
        for (int k = n - 1; k >= 0; k--) {
            double s = AT(T, k, n, ld);
            for (int j = k + 1; j < n; j++)
                s -= AT(T, k, j, ld) * x[j];
            x[k] = s / AT(T, k, k, ld);
        }
    if (info && e != LM_NERR_MEMORY) {
        if (lm_singular_values(m, n, A, sv) != LM_NERR_NONE) {
            e = LM_NERR_MEMORY;
        } else {
            int r = 0;
            while (r < n && sv[0] > 0 && sv[r] > LM_LSQ_RANK_TOL * sv[0])
                r++;
            info->rank = r;
            double c = sv[n - 1] > 0 ? sv[0] / sv[n - 1] : INFINITY;
            double cr = r > 0 ? sv[0] / sv[r - 1] : INFINITY;
            info->cond_t = c * c;
            info->cond_t_rank = cr * cr;
        }
    }
    free(T);
    free(sv);
    return e;
}
