/* normals_qr_pivot.c - step 1 of normals_qr.c, A P = Q R by Householder
 * reflections with column pivoting, its column operations four columns to
 * a vector (issue 36 item 4: the per-step triquadratic construction of the
 * 3D membranes, whose 27-column systems of 100-160 rows were two thirds of
 * the longest unit test, test_sim3_membrane; docs/performance.md "The test
 * command's time").
 *
 * Why the same bits. Every operation of the factorisation is a sum down a
 * column (w . c_j, or c_j . c_j for the pivot norms) or an update of a
 * column (c_j -= d_j w). The plain loops form each column's sum in the row
 * order i = k .. m-1 as one chain. Here A stays row-major (row i, columns j
 * .. j+3 side by side in memory) and a vector holds four columns' running
 * sums, one to a lane: lane j adds the same products in the same row order
 * as the plain loop for column j, and each lane's operation is the scalar
 * one, correctly rounded (no reassociation: no -ffast-math; no fused
 * multiply-add: -ffp-contract=off, CMakeLists.txt). So R, Q^T b and the
 * permutation are the same to the bit as those of the column-by-column
 * loops they replace (checked on random and on captured systems, every
 * shape the engine solves: docs/performance.md). What changes is how many
 * sums are in flight: up to sixteen columns at once instead of four
 * dependent chains, and the rows are read where they lie instead of copied
 * apart into columns and back.
 *
 * The vectors are GCC's vector extension: two SSE2 registers each in the
 * portable build, one AVX register where the processor has AVX2 (the same
 * function compiled for it and picked at run time, as step_bspline2.c
 * does); the lanes compute the same either way. */
#include <math.h>
#include <string.h>

#include "normals.h"
#include "normals_work.h"
#include "normals_qr_steps.h"   /* the reflection, the pivot: normals_qr.c's */

#if defined(__GNUC__)
#define QR_INLINE inline __attribute__((always_inline))
#else
#define QR_INLINE inline
#endif

#include "psabi_quiet.h"   /* the helpers are inlined: no call passes a vector */

/* Row i of the working copy: L = LM_QR_LD(n) doubles, a multiple of four,
 * so that every row starts a vector and a vector's columns lie in one row
 * (the columns n .. L-1 are zero padding). */
#define RowAt(A, i, L) ((A) + (size_t)(i) * (size_t)(L))

/* the portable build's width: two doubles, one SSE2 (or NEON) register;
 * eight vectors to a pass */
#define QR_W 2
#define QR_G 8
#define QR_NAME(f) f##_2
#include "normals_qr_lanes.h"

static void factor_default(int m, int n, double *A, double *b, int *perm, double *w,
                           double *acc, double *nrm)
{
    factor_2(m, n, A, b, perm, w, acc, nrm);
}

#if defined(__x86_64__) && defined(__GNUC__)
#define QR_DISPATCH 1
/* four doubles, one AVX register, in the function compiled for AVX2;
 * four vectors to a pass */
#define QR_W 4
#define QR_G 4
#define QR_NAME(f) f##_4
#include "normals_qr_lanes.h"

__attribute__((target("avx2"))) static void factor_avx2(int m, int n, double *A, double *b,
                                                        int *perm, double *w, double *acc,
                                                        double *nrm)
{
    factor_4(m, n, A, b, perm, w, acc, nrm);
}
#endif

/* -1: not asked yet; 1: AVX2 */
static int use_avx2 = -1;

void lm_qr_pivot_isa(int set)
{
    use_avx2 = set < 0 ? -1 : 0;
#ifdef QR_DISPATCH
    if (set > 0) {
        __builtin_cpu_init();
        use_avx2 = __builtin_cpu_supports("avx2") ? 1 : 0;
    }
#endif
}

void lm_qr_pivoted(int m, int n, double *A, double *b, int *perm, double *work)
{
    const int L = LM_QR_LD(n), kmax = m < n ? m : n;
    double *T = work, *w = T + (size_t)m * L, *acc = w + m, *nrm = acc + L;
    for (int i = 0; i < m; i++) {
        memcpy(RowAt(T, i, L), A + (size_t)i * n, sizeof(double) * (size_t)n);
        for (int j = n; j < L; j++)
            RowAt(T, i, L)[j] = 0.0;
    }
#ifdef QR_DISPATCH
    if (use_avx2 < 0) {
        __builtin_cpu_init();
        use_avx2 = __builtin_cpu_supports("avx2") ? 1 : 0;
    }
    if (use_avx2)
        factor_avx2(m, n, T, b, perm, w, acc, nrm);
    else
#endif
        factor_default(m, n, T, b, perm, w, acc, nrm);
    /* R into A's leading rows, all that is read after (A is scratch to
     * the caller below them) */
    for (int i = 0; i < kmax; i++)
        memcpy(A + (size_t)i * n, RowAt(T, i, L), sizeof(double) * (size_t)n);
}
