/* normals_qr.c - least squares by Householder QR on [S] itself ([N] §6:
 * "Using a QR-decomposition to solve the least squares problem leads to a
 * better conditioned system"), with the minimum-norm solution for the
 * underdetermined systems the quadratic basis meets ([N] §6, Fig 9(a-b)).
 *
 * Method (Golub & Van Loan, "Matrix Computations", §5.4, used for ideas
 * only; nothing here is copied from LAPACK):
 *  1. Householder QR with column pivoting (Businger-Golub): at step k the
 *     remaining column of largest norm is moved to position k, so |R_kk|
 *     does not increase and the numerical rank r is the number of
 *     |R_kk| > LM_LSQ_RANK_TOL |R_00|. (From 16 columns up in
 *     normals_qr_pivot.c: the column operations four columns to a vector,
 *     the same bits as the column loops here.)
 *  2. r = n: back substitution, R x = Q^T b.
 *  3. r < n (rank deficient, or fewer rows than unknowns): a complete
 *     orthogonal decomposition. Householder reflections applied from the
 *     right turn [R11 R12] into [T11 0]; then x = P Z^T (T11^-1 c1, 0), the
 *     least-squares solution of least Euclidean norm.
 * The condition number is computed from the singular values of R (one-sided
 * Jacobi, exact to rounding for these small matrices), and reported for
 * T = S^T S as the paper's tables do: cond(T) = cond(R)^2. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "normals_qr_steps.h"
#include "normals.h"
#include "normals_work.h"

#define AT(M, i, j, ld) ((M)[(size_t)(i) * (size_t)(ld) + (size_t)(j)])

/* ---- singular values ------------------------------------------------------ */

/* One-sided Jacobi (Hestenes): rotate pairs of columns of the rows x cols
 * matrix G (column-major here: column c at G + c*rows) until all are
 * orthogonal; the column norms are then the singular values. */
static void jacobi_columns(int rows, int cols, double *G)
{
    for (int sweep = 0; sweep < 80; sweep++) {
        int rotated = 0;
        for (int p = 0; p < cols - 1; p++)
            for (int q = p + 1; q < cols; q++) {
                double *cp = G + (size_t)p * rows, *cq = G + (size_t)q * rows;
                double a = 0, b = 0, g = 0;
                for (int i = 0; i < rows; i++) {
                    a += cp[i] * cp[i];
                    b += cq[i] * cq[i];
                    g += cp[i] * cq[i];
                }
                if (g == 0.0 || fabs(g) <= DBL_EPSILON * sqrt(a * b))
                    continue;
                double zeta = (b - a) / (2.0 * g);
                double t = (zeta >= 0 ? 1.0 : -1.0) /
                           (fabs(zeta) + sqrt(1.0 + zeta * zeta));
                double c = 1.0 / sqrt(1.0 + t * t), s = c * t;
                for (int i = 0; i < rows; i++) {
                    double u = cp[i], v = cq[i];
                    cp[i] = c * u - s * v;
                    cq[i] = s * u + c * v;
                }
                rotated = 1;
            }
        if (!rotated)
            break;
    }
}

static int descending(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? 1 : x > y ? -1 : 0;
}

lm_nerr lm_singular_values(int m, int n, const double *A, double *sv)
{
    /* orthogonalise the shorter side: columns of A if m >= n, else of A^T */
    int rows = m >= n ? m : n, cols = m >= n ? n : m;
    /* R of a fit (at most LM_NMAX square) fits on the stack */
    double small[LM_NMAX * LM_NMAX];
    size_t size = (size_t)rows * (size_t)(cols ? cols : 1);
    double *G = size <= LM_NMAX * LM_NMAX ? small : malloc(sizeof(double) * size);
    if (!G)
        return LM_NERR_MEMORY;
    for (int c = 0; c < cols; c++)
        for (int i = 0; i < rows; i++)
            G[(size_t)c * rows + i] = m >= n ? AT(A, i, c, n) : AT(A, c, i, n);
    jacobi_columns(rows, cols, G);
    for (int c = 0; c < n; c++) {
        double s = 0;
        if (c < cols)
            for (int i = 0; i < rows; i++)
                s += G[(size_t)c * rows + i] * G[(size_t)c * rows + i];
        sv[c] = sqrt(s);
    }
    if (G != small)
        free(G);
    qsort(sv, (size_t)n, sizeof *sv, descending);
    return LM_NERR_NONE;
}

/* cond(T) over all n singular values and over the first r. */
static void condition(const double *sv, int n, int r, lm_lsq_info *info)
{
    double c = sv[n - 1] > 0 ? sv[0] / sv[n - 1] : INFINITY;
    double cr = r > 0 && sv[r - 1] > 0 ? sv[0] / sv[r - 1] : INFINITY;
    info->cond_t = c * c;
    info->cond_t_rank = cr * cr;
}

/* ---- Householder reflections ------------------------------------------------ */

/* The reflection H = I - tau w w^T with H u = alpha e_0 for the vector u
 * (len entries, stride apart): w overwrites u (w_0 = u_0 - alpha), returns
 * tau; tau = 0 when u is already alpha e_0. */
static double householder(double *u, int len, int stride, double *alpha)
{
    double tail = 0;
    for (int i = 1; i < len; i++)
        tail += u[(size_t)i * stride] * u[(size_t)i * stride];
    return lm_qr_householder(u, tail, alpha);
}

/* ---- QR with column pivoting ------------------------------------------------ */

#if defined(__GNUC__)
#define QR_GROUP_INLINE inline __attribute__((always_inline))
#else
#define QR_GROUP_INLINE inline
#endif

/* The sums of column_sums for the K (1, 2 or 4) columns from C0 (column q
 * at C0 + q m), one running sum a column, into acc[0 .. K-1]. K is a
 * constant at each call, so the sums stay in registers. */
static QR_GROUP_INLINE void sums_group(int K, int m, int k, const double *C0,
                                       const double *u, double *acc)
{
    double s[4] = {0, 0, 0, 0};
    if (u)
        for (int i = k; i < m; i++)
            for (int q = 0; q < K; q++)
                s[q] += u[i] * C0[(size_t)q * m + i];
    else
        for (int i = k; i < m; i++)
            for (int q = 0; q < K; q++)
                s[q] += C0[(size_t)q * m + i] * C0[(size_t)q * m + i];
    for (int q = 0; q < K; q++)
        acc[q] = s[q];
}

/* Sums over i = k .. m-1 for the columns j0 .. n-1 of C (column j at
 * C + j m): with u, acc_j = sum u_i C_ij; without, acc_j = sum C_ij^2.
 * Each column's sum adds its terms in the order i = k .. m-1, as a plain
 * loop would, so the sums are bit for bit the same; four (then two)
 * columns go together so that four running sums are in flight instead of
 * one chain of dependent additions. */
static void column_sums(int m, int n, int k, int j0, const double *C,
                        const double *u, double *acc)
{
    int j = j0;
    for (; j + 4 <= n; j += 4)
        sums_group(4, m, k, C + (size_t)j * m, u, acc + j);
    for (; j + 2 <= n; j += 2)
        sums_group(2, m, k, C + (size_t)j * m, u, acc + j);
    for (; j < n; j++)
        sums_group(1, m, k, C + (size_t)j * m, u, acc + j);
}

/* The reflection's update of the columns j0 .. n-1, c_j -= d_j w over rows
 * k .. m-1 (d_j = tau w.c_j in d), and with it the next step's pivot norms:
 * nrm_j = sum over i = k+1 .. m-1 of the updated c_ij^2. That sum is the one
 * the next step would form - the same terms in the same order - taken while
 * the values are at hand instead of in a pass of its own; four columns go
 * together so that their sums do not wait on one another. */
static void reflect(int m, int n, int k, int j0, double *C, const double *restrict w,
                    const double *d, double *nrm)
{
    int j = j0;
    for (; j + 4 <= n; j += 4) {
        double *restrict c0 = C + (size_t)j * m, *restrict c1 = c0 + m;
        double *restrict c2 = c1 + m, *restrict c3 = c2 + m;
        double d0 = d[j], d1 = d[j + 1], d2 = d[j + 2], d3 = d[j + 3];
        double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
        c0[k] -= d0 * w[k];
        c1[k] -= d1 * w[k];
        c2[k] -= d2 * w[k];
        c3[k] -= d3 * w[k];
        for (int i = k + 1; i < m; i++) {
            double wi = w[i];
            double v0 = c0[i] - d0 * wi, v1 = c1[i] - d1 * wi;
            double v2 = c2[i] - d2 * wi, v3 = c3[i] - d3 * wi;
            c0[i] = v0;
            c1[i] = v1;
            c2[i] = v2;
            c3[i] = v3;
            s0 += v0 * v0;
            s1 += v1 * v1;
            s2 += v2 * v2;
            s3 += v3 * v3;
        }
        nrm[j] = s0;
        nrm[j + 1] = s1;
        nrm[j + 2] = s2;
        nrm[j + 3] = s3;
    }
    for (; j < n; j++) {
        double *restrict c0 = C + (size_t)j * m, d0 = d[j], s0 = 0;
        c0[k] -= d0 * w[k];
        for (int i = k + 1; i < m; i++) {
            double v0 = c0[i] - d0 * w[i];
            c0[i] = v0;
            s0 += v0 * v0;
        }
        nrm[j] = s0;
    }
}

/* Step 1: A P = Q R in place (R in the upper triangle, the Householder
 * vectors are not kept: Q^T is applied to b on the way). C (m n) holds A's
 * columns apart while the reflections work on them, acc n sums.
 *
 * Why the columns apart: every operation here runs down columns, which in
 * the row-major A are n apart; one column after another in C they are
 * contiguous and a pivot swap moves one block. The arithmetic - each
 * element's operations and their order - is that of the plain column loops
 * on A, so R, Q^T b and the permutation are bit for bit the same. (The QR
 * was half the cost of the per-step normals, docs/performance.md.) */
static void qr_pivoted(int m, int n, double *A, double *b, int *perm,
                       double *C, double *acc, double *nrm)
{
    for (int j = 0; j < n; j++)
        for (int i = 0; i < m; i++)
            C[(size_t)j * m + i] = AT(A, i, j, n);
    int kmax = m < n ? m : n, have_norms = 0;
    for (int k = 0; k < kmax; k++) {
        /* the pivot: the remaining column of largest norm (first of ties);
         * the last reflection has left the norms in nrm */
        if (!have_norms)
            column_sums(m, n, k, k, C, NULL, nrm);
        int best = lm_qr_pivot(nrm, k, n);
        double *ck = C + (size_t)k * m;
        if (best != k) {
            double *cb = C + (size_t)best * m;
            for (int i = 0; i < m; i++) {
                double t = ck[i];
                ck[i] = cb[i];
                cb[i] = t;
            }
            int t = perm[k];
            perm[k] = perm[best];
            perm[best] = t;
        }
        double alpha;
        double tau = householder(ck + k, m - k, 1, &alpha);
        if (tau != 0.0) {
            /* H = I - tau w w^T (w in ck[k..m)) on the columns right of k
             * and on b: d_j = tau w.c_j, then c_j -= d_j w */
            column_sums(m, n, k, k + 1, C, ck, acc);
            double db = 0;
            for (int i = k; i < m; i++)
                db += ck[i] * b[i];
            for (int j = k + 1; j < n; j++)
                acc[j] *= tau;
            reflect(m, n, k, k + 1, C, ck, acc, nrm);
            db *= tau;
            for (int i = k; i < m; i++)
                b[i] -= db * ck[i];
        }
        have_norms = tau != 0.0;
        ck[k] = alpha;
        for (int i = k + 1; i < m; i++)
            ck[i] = 0.0;
    }
    /* R back into A's leading rows, all that is read after (the rows
     * below are zero in R and A is scratch to the caller) */
    for (int i = 0; i < kmax; i++)
        for (int j = 0; j < n; j++)
            AT(A, i, j, n) = C[(size_t)j * m + i];
}

/* Back substitution with the r x r upper triangle of R (leading dim n). */
static void back_substitute(int r, int n, const double *R, const double *c,
                            double *y)
{
    for (int k = r - 1; k >= 0; k--) {
        double s = c[k];
        for (int j = k + 1; j < r; j++)
            s -= AT(R, k, j, n) * y[j];
        y[k] = s / AT(R, k, k, n);
    }
}

/* Step 3: [R11 R12] Z^T = [T11 0] by reflections from the right, row by row
 * from the last; W (r x (1 + n - r)) keeps each reflection's vector, tau
 * its factor. Row k's reflection acts on columns k and r..n-1 of rows
 * 0..k (rows below are already zero there). */
static void cod_right(int r, int n, double *R, double *W, double *tau)
{
    int len = 1 + n - r;
    for (int k = r - 1; k >= 0; k--) {
        double *w = W + (size_t)k * len;
        w[0] = AT(R, k, k, n);
        for (int j = r; j < n; j++)
            w[1 + j - r] = AT(R, k, j, n);
        double alpha;
        tau[k] = householder(w, len, 1, &alpha);
        if (tau[k] == 0.0)
            continue;
        for (int i = 0; i <= k; i++) {
            double d = w[0] * AT(R, i, k, n);
            for (int j = r; j < n; j++)
                d += w[1 + j - r] * AT(R, i, j, n);
            d *= tau[k];
            AT(R, i, k, n) -= d * w[0];
            for (int j = r; j < n; j++)
                AT(R, i, j, n) -= d * w[1 + j - r];
        }
    }
}

/* y <- Z^T y: the reflections in the order H_0, H_1, ..., H_{r-1}. */
static void cod_apply(int r, int n, const double *W, const double *tau,
                      double *y)
{
    int len = 1 + n - r;
    for (int k = 0; k < r; k++) {
        if (tau[k] == 0.0)
            continue;
        const double *w = W + (size_t)k * len;
        double d = w[0] * y[k];
        for (int j = r; j < n; j++)
            d += w[1 + j - r] * y[j];
        d *= tau[k];
        y[k] -= d * w[0];
        for (int j = r; j < n; j++)
            y[j] -= d * w[1 + j - r];
    }
}

lm_nerr lm_lsq_qr(int m, int n, double *A, double *b, double *x,
                  lm_lsq_info *info)
{
    return lm_lsq_qr_cond(m, n, A, b, x, info, 1);
}

/* Steps 1-3 in the caller's buffers: perm and y (n), C (LM_QR_WORK), sv (n), W
 * (min(m, n) (1 + n)) and tau (min(m, n)). */
static lm_nerr qr_solve(int m, int n, double *A, double *b, double *x,
                        lm_lsq_info *info, int want_cond, int *perm, double *C,
                        double *y, double *sv, double *W, double *tau)
{
    lm_lsq_info dummy;
    if (!info)
        info = &dummy;
    memset(info, 0, sizeof *info);
    if (m <= 0 || n <= 0)
        return LM_NERR_INPUT;
    int kmax = m < n ? m : n;
    for (int j = 0; j < n; j++)
        perm[j] = j;
    /* step 1: the 3D quadratic fits' 27 columns four to a vector
     * (normals_qr_pivot.c); fewer columns (2D, linear) column by column
     * here, where the vectors' padding and start-up cost more than they
     * save (9 columns: the same time with AVX2, 15-20 % more without; 4:
     * 20 % more). The same bits either way. sv and y: scratch until the
     * solve (then y starts from 0) */
    if (n >= LM_QR_VECTOR_COLS)
        lm_qr_pivoted(m, n, A, b, perm, C);
    else
        qr_pivoted(m, n, A, b, perm, C, sv, y);
    for (int j = 0; j < n; j++)
        y[j] = 0.0;

    int r = 0;
    double r00 = fabs(AT(A, 0, 0, n));
    while (r < kmax && r00 > 0 && fabs(AT(A, r, r, n)) > LM_LSQ_RANK_TOL * r00)
        r++;
    info->rank = r;
    /* cond from R's leading kmax rows (the rest of R is zero) */
    if (!want_cond) {
        info->cond_t = info->cond_t_rank = NAN;
    } else {
        lm_nerr e = lm_singular_values(kmax, n, A, sv);
        if (e != LM_NERR_NONE)
            return e;
        condition(sv, n, r, info);
    }

    if (r == n) {
        back_substitute(n, n, A, b, y);
    } else if (r > 0) {
        cod_right(r, n, A, W, tau);
        back_substitute(r, n, A, b, y);
        for (int j = r; j < n; j++)
            y[j] = 0.0;
        cod_apply(r, n, W, tau, y);
    }
    for (int j = 0; j < n; j++)
        x[perm[j]] = y[j];
    return LM_NERR_NONE;
}

lm_nerr lm_lsq_qr_cond(int m, int n, double *A, double *b, double *x,
                       lm_lsq_info *info, int want_cond)
{
    if (m <= 0 || n <= 0) {
        if (info)
            memset(info, 0, sizeof *info);
        return LM_NERR_INPUT;
    }
    int kmax = m < n ? m : n;
    size_t len = (size_t)(1 + n);
    int *perm = malloc(sizeof(int) * (size_t)n);
    double *C = malloc(sizeof(double) * LM_QR_WORK(m, n));
    double *y = malloc(sizeof(double) * (size_t)n);
    double *sv = malloc(sizeof(double) * (size_t)n);
    double *W = malloc(sizeof(double) * (size_t)kmax * len);
    double *tau = malloc(sizeof(double) * (size_t)kmax);
    lm_nerr e;
    if (!perm || !C || !y || !sv || !W || !tau) {
        if (info)
            memset(info, 0, sizeof *info);
        e = LM_NERR_MEMORY;
    } else {
        e = qr_solve(m, n, A, b, x, info, want_cond, perm, C, y, sv, W, tau);
    }
    free(perm);
    free(C);
    free(y);
    free(sv);
    free(W);
    free(tau);
    return e;
}

lm_nerr lm_lsq_qr_ws(int m, int n, double *A, double *b, double *x,
                     lm_lsq_info *info, int want_cond, double *C)
{
    if (n > LM_NMAX)
        return lm_lsq_qr_cond(m, n, A, b, x, info, want_cond);
    /* every buffer but C is bounded by LM_NMAX: the stack */
    int perm[LM_NMAX];
    double y[LM_NMAX], sv[LM_NMAX], W[LM_NMAX * (LM_NMAX + 1)], tau[LM_NMAX];
    return qr_solve(m, n, A, b, x, info, want_cond, perm, C, y, sv, W, tau);
}
