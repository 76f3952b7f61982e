/* sim3_kernels2.h - the trilinear step's particle kernels with a stencil
 * row's two nodes side by side (simd2.h's two-double vectors; SSE2 on
 * every x86-64). Included by sim3_step.c only; its general kernels keep
 * the quadratic B-spline's rows of three.
 *
 * Each lane does the scalar kernel's operation on its node, and the
 * gathers add the two lanes' products into their sums in the scalar
 * order (node a = 0, then 1), so these give the bits of the scalar
 * kernels they replace (docs/3d.md "Speed": same state, fewer
 * instructions). */
#ifndef LAMINA_SIM3_KERNELS2_H
#define LAMINA_SIM3_KERNELS2_H

#include "mpm3.h"
#include "simd2.h"

static inline lm_v2d lm3_v2(double a) { return (lm_v2d){a, a}; }

/* Steps 1-2 on a row's two nodes i, i + 1: m, p and the force -(A g0 +
 * B w0) per component (sim3_step.c p2g_at). */
static inline void lm3_p2g_row2(const lm3_grid *g, long i, lm_v2d W0, lm_v2d G0, double wyz,
                                double m, const double mv[3], const double A[3],
                                const double B[3])
{
    const lm_v2d N = W0 * lm3_v2(wyz);
    lm_v2d_store(g->m + i, lm_v2d_load(g->m + i) + N * lm3_v2(m));
    for (int e = 0; e < 3; e++) {
        double *pe = g->p[e] + i, *fe = g->f[e] + i;
        lm_v2d_store(pe, lm_v2d_load(pe) + N * lm3_v2(mv[e]));
        lm_v2d_store(fe, lm_v2d_load(fe) - (lm3_v2(A[e]) * G0 + lm3_v2(B[e]) * W0));
    }
}

/* Step 4's sums on a row: acc[0..2] += N f, acc[3..5] += N v^L, node 0
 * then node 1. */
static inline void lm3_g2p_row2(const lm3_grid *g, long i, lm_v2d W0, double wyz,
                                double acc[6])
{
    const lm_v2d N = W0 * lm3_v2(wyz);
    for (int e = 0; e < 3; e++) {
        const lm_v2d a = N * lm_v2d_load(g->f[e] + i), u = N * lm_v2d_load(g->p[e] + i);
        acc[e] += a[0];
        acc[e] += a[1];
        acc[3 + e] += u[0];
        acc[3 + e] += u[1];
    }
}

/* Step 5's MUSL re-map on a row. */
static inline void lm3_remap_row2(const lm3_grid *g, long i, lm_v2d W0, double wyz,
                                  const double mv[3])
{
    const lm_v2d N = W0 * lm3_v2(wyz);
    for (int e = 0; e < 3; e++) {
        double *ve = g->v[e] + i;
        lm_v2d_store(ve, lm_v2d_load(ve) + N * lm3_v2(mv[e]));
    }
}

/* Step 7 on a row: S_e = v_e . g0, T_e = v_e . w0 over its two nodes. */
static inline void lm3_gradient_row2(const lm3_grid *g, long i, lm_v2d W0, lm_v2d G0,
                                     double S[3], double T[3])
{
    for (int e = 0; e < 3; e++) {
        const lm_v2d v = lm_v2d_load(g->v[e] + i), s = v * G0, t = v * W0;
        S[e] = s[0] + s[1];
        T[e] = t[0] + t[1];
    }
}

#endif
