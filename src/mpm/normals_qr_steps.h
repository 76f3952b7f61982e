/* normals_qr_steps.h - the pivoted QR's scalar steps shared by its column
 * loops (normals_qr.c) and its vector form (normals_qr_pivot.c): the same
 * operations in both, so the same bits. */
#ifndef LAMINA_NORMALS_QR_STEPS_H
#define LAMINA_NORMALS_QR_STEPS_H

#include <math.h>

/* The reflection H = I - tau w w^T with H u = alpha e_0 for u = (u_0, ...),
 * tail the sum of its squares after u_0 (summed by the caller in row
 * order): w_0 = u_0 - alpha overwrites u_0, returns tau; 0 when u is
 * already alpha e_0. */
static inline double lm_qr_householder(double *u, double tail, double *alpha)
{
    double u0 = u[0];
    if (tail == 0.0) {
        *alpha = u0;
        return 0.0;
    }
    double norm = sqrt(u0 * u0 + tail);
    *alpha = u0 >= 0 ? -norm : norm;
    double w0 = u0 - *alpha;
    u[0] = w0;
    return 2.0 / (w0 * w0 + tail);
}

/* The pivot: of columns k .. n-1 the one of largest norm nrm[j], the
 * first of ties. */
static inline int lm_qr_pivot(const double *nrm, int k, int n)
{
    int best = k;
    double bn = -1;
    for (int j = k; j < n; j++)
        if (nrm[j] > bn) {
            bn = nrm[j];
            best = j;
        }
    return best;
}

#endif
