/* normals_fit_ne.c - the 2D quadratic element's fit by the normal
 * equations ([N] eqs 12-13: T phi = S^T phi0, T = S^T S), the solve the
 * simulation's isosurface normals use (issue 17 item 3: the pivoted QR was
 * half of the construction). T is summed straight from the tensor-product
 * rows, factored as L D L^T without square roots; a fit whose pivot falls
 * below CHOL_PIVOT_TOL of its diagonal returns -1 and goes to the QR
 * (normals_fit.c, assemble_solve). Measured against the QR over 800 400
 * normals of the dog-bone: at most 5.3e-9 degrees apart (docs/performance.md). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "normals.h"
#include "normals_work.h"
#include "simd2.h"

/* A pivot d_j of T = L D L^T (Cholesky's L_jj^2: T_jj less what the
 * earlier unknowns explain) below this fraction of T_jj: the fit goes to
 * the QR. */
#define CHOL_PIVOT_TOL 1e-10

/* The quadratic B-splines of the centres -1/2, 1/2, 3/2 at xi ([N] §5,
 * lm_bspline2): on [0, 1], where an element's points lie, the three
 * pieces are 1/2 (1 - xi)^2, 3/4 - (xi - 1/2)^2 and 1/2 xi^2; a point a
 * rounding outside takes the general function. */
static inline void bspline2_three(double xi, double v[3])
{
    if (xi >= 0.0 && xi <= 1.0) {
        double u = 1.0 - xi, c = xi - 0.5;
        v[0] = 0.5 * u * u;
        v[1] = 0.75 - c * c;
        v[2] = 0.5 * xi * xi;
        return;
    }
    for (int i = 0; i < 3; i++)
        v[i] = lm_bspline2(xi - (i - 0.5));
}


/* T_IJ (I = i + 3 j, J = k + 3 l, J <= I, row by row) is the sum
 * G[pair(i, k)][pair(j, l)], pair (a, b) the index of the product b_a b_b
 * of one axis (0 .. 5 for (0,0) (0,1) (0,2) (1,1) (1,2) (2,2)): its place
 * in G (6 x 6). */
static const int GIDX[45] = {
#define G_AT(I, J) (PAIR_OF((I) % 3, (J) % 3) * 6 + PAIR_OF((I) / 3, (J) / 3))
#define PAIR_OF(a, b) ((a) <= (b) ? (a) * 3 - (a) * ((a) - 1) / 2 + (b) - (a) \
                                  : (b) * 3 - (b) * ((b) - 1) / 2 + (a) - (b))
    G_AT(0, 0),
    G_AT(1, 0), G_AT(1, 1),
    G_AT(2, 0), G_AT(2, 1), G_AT(2, 2),
    G_AT(3, 0), G_AT(3, 1), G_AT(3, 2), G_AT(3, 3),
    G_AT(4, 0), G_AT(4, 1), G_AT(4, 2), G_AT(4, 3), G_AT(4, 4),
    G_AT(5, 0), G_AT(5, 1), G_AT(5, 2), G_AT(5, 3), G_AT(5, 4), G_AT(5, 5),
    G_AT(6, 0), G_AT(6, 1), G_AT(6, 2), G_AT(6, 3), G_AT(6, 4), G_AT(6, 5), G_AT(6, 6),
    G_AT(7, 0), G_AT(7, 1), G_AT(7, 2), G_AT(7, 3), G_AT(7, 4), G_AT(7, 5), G_AT(7, 6),
    G_AT(7, 7),
    G_AT(8, 0), G_AT(8, 1), G_AT(8, 2), G_AT(8, 3), G_AT(8, 4), G_AT(8, 5), G_AT(8, 6),
    G_AT(8, 7), G_AT(8, 8)
#undef PAIR_OF
#undef G_AT
};

/* The products b_i b_k of one axis, in pair order. */
static void pair_products(const double v[3], double p[6])
{
    p[0] = v[0] * v[0];
    p[1] = v[0] * v[1];
    p[2] = v[0] * v[2];
    p[3] = v[1] * v[1];
    p[4] = v[1] * v[2];
    p[5] = v[2] * v[2];
}

/* The aspect h_y / h_x rounded to 40 significant bits, to nearest with
 * ties to even: ldexp(nearbyint(ldexp(m, 40)), e - 40) for the aspect
 * m 2^e, taken on its bits (it runs for every fit; the three libm calls
 * were most of smooth_ctc's time). The 13 low bits of the 52-bit fraction
 * go; a carry out of the fraction steps the exponent, as the rounding of
 * m 2^40 up to 2^40 does. The aspect is positive and normal (a box's
 * sides are finite and > 0, checked by the caller). */
static double aspect40(double r)
{
    uint64_t u;
    memcpy(&u, &r, sizeof u);
    uint64_t low = u & 0x1fffu, half = 0x1000u;
    u &= ~(uint64_t)0x1fffu;
    if (low > half || (low == half && (u & 0x2000u)))
        u += 0x2000u;
    memcpy(&r, &u, sizeof r);
    return r;
}

/* C^T C of the curvature rows at weight 1 for the element's aspect (the
 * rows depend on nothing else). The aspect h_y / h_x of a box differs from
 * box to box in its last bits (hi - lo rounds with the position), so it is
 * first rounded to 40 bits (a change of 1e-12 in weak rows: nothing a
 * normal shows) - a function of the box alone, so a run does not depend
 * on which element came first, and the grid's elements share one entry of
 * the cache: cache[0] the rounded aspect, cache[1] the number of rows (0:
 * nothing kept), cache[2..83) C^T C. Returns C^T C (the cache's, or own
 * when there is no cache) and its number of rows in *rows. */
static const double *smooth_ctc(const lm_nbox *box, double *cache, double own[81], int *rows)
{
    double aspect = aspect40((box->hi[1] - box->lo[1]) / (box->hi[0] - box->lo[0]));
    if (cache && cache[1] > 0 && cache[0] == aspect) {
        *rows = (int)cache[1];
        return cache + 2;
    }
    lm_nbox unit = {2, {0, 0, 0}, {1.0, aspect, 0}};
    double C[LM_NSMOOTH_MAXROWS * 9];
    int r = lm_nsmooth_rows(LM_NB_QUADRATIC, &unit, 1.0, C);
    double *ctc = cache ? cache + 2 : own;
    for (int I = 0; I < 9; I++)
        for (int J = 0; J < 9; J++) {
            double t = 0.0;
            for (int q = 0; q < r; q++)
                t += C[q * 9 + I] * C[q * 9 + J];
            ctc[I * 9 + J] = t;
        }
    if (cache) {
        cache[0] = aspect;
        cache[1] = r;
    }
    *rows = r;
    return ctc;
}

/* Step j of T = L D L^T (L unit lower triangular): the pivot d_j, column
 * j of L, and the update of the trailing lower triangle; -1 when d_j falls
 * below CHOL_PIVOT_TOL of the original T_jj (diag). Column j of L y = b is
 * taken at once (y_i -= L_ij y_j for i > j: y_j is final by now, and each
 * y_i gets its updates in the order of j, as a solve after the factoring
 * would give them), so that the forward solve's chain runs beside the
 * pivots' instead of after them. Called with j a constant, so that the
 * compiler knows every loop's bounds. */
static inline int ldlt9_step(double T[9][9], const double diag[9], double inv[9],
                             double y[9], int j)
{
    double d = T[j][j];
    if (!(d > CHOL_PIVOT_TOL * diag[j]))
        return -1;
    double r = 1.0 / d, col[9];
    inv[j] = r;
    for (int i = j + 1; i < 9; i++) {
        col[i] = T[i][j];           /* d_j L_ij */
        T[i][j] = col[i] * r;       /* L_ij */
    }
    for (int i = j + 1; i < 9; i++)
        y[i] -= T[i][j] * y[j];
    for (int i = j + 1; i < 9; i++) {
        double l = T[i][j];
        for (int c = j + 1; c <= i; c++)
            T[i][c] -= l * col[c];
    }
    return 0;
}

/* x_i -= L_ji x_j for i < j (L^T x = z, column j; j a constant). */
static inline void backward9(const double T[9][9], double x[9], int j)
{
    for (int i = 0; i < j; i++)
        x[i] -= T[j][i] * x[j];
}

/* T = L D L^T, then L D L^T x = b: Cholesky's factorisation without its
 * square roots (D holds the squares of Cholesky's pivots), right-looking,
 * so that each step's updates of the trailing matrix are independent of
 * one another instead of one chain of dot products; L y = b along with it
 * (ldlt9_step), then z = D^-1 y and L^T x = z, right-looking too: once x_j
 * is known it is taken off every earlier entry. -1, with x untouched, when
 * a pivot falls below CHOL_PIVOT_TOL of its T_jj. T's lower triangle is
 * overwritten. */
static int ldlt9(double T[9][9], const double b[9], double x[9])
{
    double diag[9], inv[9], y[9];
    for (int j = 0; j < 9; j++) {
        diag[j] = T[j][j];
        y[j] = b[j];
    }
    /* unrolled, so that each step's bounds are constants (GCC does not
     * unroll a loop of bodies this size by itself) */
#pragma GCC unroll 9
    for (int j = 0; j < 9; j++)
        if (ldlt9_step(T, diag, inv, y, j))
            return -1;
    for (int i = 0; i < 9; i++)
        x[i] = y[i] * inv[i];
#pragma GCC unroll 8
    for (int j = 8; j > 0; j--)
        backward9(T, x, j);
    return 0;
}

/* G[a][0..5] for a = a0 .. a0 + 2: the sums over the rows of PU_a PV_b,
 * point after point as before, three rows of G at a time (nine pairs of
 * sums and the point's PV in registers, where six rows' would not fit). */
static inline void g_rows3(const double *S, size_t n, int ld, int pu, int pv, int a0,
                           double G[6][6])
{
    lm_v2d s[3][3] = {{{0, 0}}};
    for (size_t i = 0; i < n; i++) {
        const double *r = S + i * (size_t)ld;
        lm_v2d q0 = lm_v2d_load(r + pv), q1 = lm_v2d_load(r + pv + 2), q2 = lm_v2d_load(r + pv + 4);
        for (int a = 0; a < 3; a++) {
            lm_v2d p = {r[pu + a0 + a], r[pu + a0 + a]};
            s[a][0] += p * q0;
            s[a][1] += p * q1;
            s[a][2] += p * q2;
        }
    }
    for (int a = 0; a < 3; a++)
        for (int m = 0; m < 3; m++)
            lm_v2d_store(&G[a0 + a][2 * m], s[a][m]);
}

/* A point's row at (xi, eta) = u: the three values of each axis (U, V)
 * and their six products (PU, PV), the two axes side by side in the lanes
 * of u - the scalar bspline2_three and pair_products lane by lane, so the
 * same bits; a point a rounding outside [0, 1] takes them one by one. */
static inline void row_2d(lm_v2d u, double *r)
{
    enum { PU = 0, PV = 6, U = 12, V = 15 };
    if (!(u[0] >= 0.0 && u[0] <= 1.0 && u[1] >= 0.0 && u[1] <= 1.0)) {
        bspline2_three(u[0], r + U);
        bspline2_three(u[1], r + V);
        pair_products(r + U, r + PU);
        pair_products(r + V, r + PV);
        return;
    }
    const lm_v2d half = {0.5, 0.5}, one = {1.0, 1.0}, q34 = {0.75, 0.75};
    lm_v2d m = one - u, c = u - half;
    lm_v2d b0 = half * m * m, b1 = q34 - c * c, b2 = half * u * u;
    /* (PU_a, PV_a) for the pairs (0,0) (0,1) (0,2) (1,1) (1,2) (2,2) */
    lm_v2d p0 = b0 * b0, p1 = b0 * b1, p2 = b0 * b2, p3 = b1 * b1, p4 = b1 * b2, p5 = b2 * b2;
    lm_v2d_store(r + PU, lm_v2d_lo(p0, p1));
    lm_v2d_store(r + PU + 2, lm_v2d_lo(p2, p3));
    lm_v2d_store(r + PU + 4, lm_v2d_lo(p4, p5));
    lm_v2d_store(r + PV, lm_v2d_hi(p0, p1));
    lm_v2d_store(r + PV + 2, lm_v2d_hi(p2, p3));
    lm_v2d_store(r + PV + 4, lm_v2d_hi(p4, p5));
    r[U] = b0[0];
    r[U + 1] = b1[0];
    r[U + 2] = b2[0];
    r[V] = b0[1];
    r[V + 1] = b1[1];
    r[V + 2] = b2[1];
}

/* Steps 2-5 for the 2D quadratic basis by the normal equations, the
 * curvature rows at weight smooth * sqrt(rows) as assemble_solve adds them.
 * Two passes over the points: the first writes each point's 1D values and
 * products into a row of sc->S, the second sums them with the sums held in
 * registers (G updated in memory point after point was a chain of loads
 * and stores). -1 when T is too near singular (f->phi is then untouched). */
int lm_nfit_quadratic_2d_ne(lm_nfit *f, const double *const x[3], const size_t *idx,
                            size_t k, lm_nfit_scratch *sc, double smooth)
{
    /* a row: PU, PV (the six products of each axis), U, V (the values);
     * 18 of the LM_NMAX places the scratch has for each row */
    enum { PU = 0, PV = 6, U = 12, V = 15, LD = 18 };
    const lm_nbox *b = &f->box;
    lm_v2d lo = {b->lo[0], b->lo[1]};
    lm_v2d w = {b->hi[0] - b->lo[0], b->hi[1] - b->lo[1]};
    double *S = sc->S;
    /* the k points (phi0 = 1), then the random point (phi0 = 0) */
    for (size_t i = 0; i <= k; i++) {
        lm_v2d p;
        if (i < k) {
            size_t q = idx ? idx[i] : i;
            p = (lm_v2d){x[0][q], x[1][q]};
        } else {
            p = (lm_v2d){f->q[0], f->q[1]};
        }
        row_2d((p - lo) / w, S + i * LD);
    }
    double G[6][6], rhs[9];
    g_rows3(S, k + 1, LD, PU, PV, 0, G);
    g_rows3(S, k + 1, LD, PU, PV, 3, G);
    /* rhs_I = sum over the points of b_i(xi) b_j(eta), I = i + 3 j */
    for (int j = 0; j < 3; j++) {
        double s0 = 0, s1 = 0, s2 = 0;
        for (size_t i = 0; i < k; i++) {
            const double *r = S + i * LD, vj = r[V + j];
            s0 += vj * r[U + 0];
            s1 += vj * r[U + 1];
            s2 += vj * r[U + 2];
        }
        rhs[3 * j] = s0;
        rhs[3 * j + 1] = s1;
        rhs[3 * j + 2] = s2;
    }
    static const double none[81];
    double own[81], w2 = 0.0;
    const double *ctc = none;
    f->smooth_rows = 0;
    if (smooth > 0) {
        double ws = smooth * sqrt((double)f->rows);
        ctc = smooth_ctc(b, sc->smooth, own, &f->smooth_rows);
        w2 = ws * ws;
    }
    double T[9][9];
    const double *g = &G[0][0];
#pragma GCC unroll 9
    for (int I = 0; I < 9; I++)
#pragma GCC unroll 9
        for (int J = 0; J <= I; J++)
            T[I][J] = g[GIDX[I * (I + 1) / 2 + J]] + w2 * ctc[I * 9 + J];
    if (ldlt9(T, rhs, f->phi))
        return -1;
    f->info.rank = 9;
    f->info.cond_t = f->info.cond_t_rank = NAN;
    return 0;
}
