/* test_normals_lsq.c - the dense least-squares solvers of the normals:
 * Householder QR with column pivoting and the minimum-norm solution by a
 * complete orthogonal decomposition (normals_qr.c), the normal equations
 * (normals_ne.c) and the condition number cond(T) = cond(R)^2. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "normals.h"

/* r = A^T (A x - b) */
static void gradient(int m, int n, const double *A, const double *b,
                     const double *x, double *r)
{
    for (int j = 0; j < n; j++)
        r[j] = 0;
    for (int i = 0; i < m; i++) {
        double e = -b[i];
        for (int j = 0; j < n; j++)
            e += A[i * n + j] * x[j];
        for (int j = 0; j < n; j++)
            r[j] += A[i * n + j] * e;
    }
}

/* A consistent overdetermined system: both solvers return its solution. */
static void test_full_rank(void)
{
    enum { M = 6, N = 3 };
    const double A0[M * N] = {1, 2, 0, 0, 1, 1, 3, 0, 1, 1, 1, 1, 2, -1, 0, 0, 0, 4};
    const double xs[N] = {0.5, -1.25, 2.0};
    double A[M * N], b[M], b0[M], x[N], y[N];
    for (int i = 0; i < M; i++) {
        b0[i] = 0;
        for (int j = 0; j < N; j++)
            b0[i] += A0[i * N + j] * xs[j];
    }
    memcpy(A, A0, sizeof A);
    memcpy(b, b0, sizeof b);
    lm_lsq_info info;
    CHECK(lm_lsq_qr(M, N, A, b, x, &info) == LM_NERR_NONE);
    CHECK(info.rank == 3);
    for (int j = 0; j < N; j++)
        CHECK_NEAR(x[j], xs[j], 1e-14);
    CHECK(lm_lsq_normal(M, N, A0, b0, y, &info) == LM_NERR_NONE);
    for (int j = 0; j < N; j++)
        CHECK_NEAR(y[j], xs[j], 1e-12);
}

/* An inconsistent system: QR's answer satisfies the normal equations. */
static void test_least_squares(void)
{
    enum { M = 5, N = 2 };
    const double A0[M * N] = {1, 0, 1, 1, 1, 2, 1, 3, 1, 4};
    const double b0[M] = {0.1, 0.9, 2.2, 2.8, 4.1};
    double A[M * N], b[M], x[N], r[N];
    memcpy(A, A0, sizeof A);
    memcpy(b, b0, sizeof b);
    CHECK(lm_lsq_qr(M, N, A, b, x, NULL) == LM_NERR_NONE);
    gradient(M, N, A0, b0, x, r);
    CHECK_NEAR(r[0], 0, 1e-13);
    CHECK_NEAR(r[1], 0, 1e-13);
    /* the line fit by hand: slope 0.99, intercept 0.04 */
    CHECK_NEAR(x[1], 0.99, 1e-13);
    CHECK_NEAR(x[0], 0.04, 1e-13);
}

/* Underdetermined x1 + x2 = 2: the minimum-norm solution is (1, 1). */
static void test_min_norm_simple(void)
{
    double A[2] = {1, 1}, b[1] = {2}, x[2];
    lm_lsq_info info;
    CHECK(lm_lsq_qr(1, 2, A, b, x, &info) == LM_NERR_NONE);
    CHECK(info.rank == 1);
    CHECK_NEAR(x[0], 1.0, 1e-15);
    CHECK_NEAR(x[1], 1.0, 1e-15);
    CHECK(isinf(info.cond_t));
}

/* A rank-2 matrix with 5 rows and 4 columns: A = B C, null(A) = null(C)
 * spanned by z1, z2. The minimum-norm least-squares x satisfies the normal
 * equations and is orthogonal to z1 and z2. */
static void test_min_norm_rank_deficient(void)
{
    enum { M = 5, N = 4 };
    const double B[M * 2] = {1, 0, 0, 1, 1, 1, 2, -1, 0.5, 3};
    const double C[2 * N] = {1, 0, 1, 2, 0, 1, -1, 1};
    const double z1[N] = {-1, 1, 1, 0}, z2[N] = {-2, -1, 0, 1};
    const double b0[M] = {1, 2, -1, 0.5, 3};
    double A0[M * N], A[M * N], b[M], x[N], r[N];
    for (int i = 0; i < M; i++)
        for (int j = 0; j < N; j++)
            A0[i * N + j] = B[i * 2] * C[j] + B[i * 2 + 1] * C[N + j];
    memcpy(A, A0, sizeof A);
    memcpy(b, b0, sizeof b);
    lm_lsq_info info;
    CHECK(lm_lsq_qr(M, N, A, b, x, &info) == LM_NERR_NONE);
    CHECK(info.rank == 2);
    gradient(M, N, A0, b0, x, r);
    for (int j = 0; j < N; j++)
        CHECK_NEAR(r[j], 0, 1e-12);
    double d1 = 0, d2 = 0;
    for (int j = 0; j < N; j++) {
        d1 += x[j] * z1[j];
        d2 += x[j] * z2[j];
    }
    CHECK_NEAR(d1, 0, 1e-13);
    CHECK_NEAR(d2, 0, 1e-13);
}

/* cond(T) of diag(1, 10, 100) is (100/1)^2 = 1e4; singular values sorted. */
static void test_condition(void)
{
    double A[9] = {10, 0, 0, 0, 1, 0, 0, 0, 100}, b[3] = {1, 1, 1}, x[3], sv[3];
    CHECK(lm_singular_values(3, 3, A, sv) == LM_NERR_NONE);
    CHECK_NEAR(sv[0], 100, 1e-12);
    CHECK_NEAR(sv[1], 10, 1e-13);
    CHECK_NEAR(sv[2], 1, 1e-14);
    lm_lsq_info info;
    CHECK(lm_lsq_qr(3, 3, A, b, x, &info) == LM_NERR_NONE);
    CHECK_NEAR(info.cond_t, 1e4, 1e-8);
    /* a rotated example: [[1, 1], [1, 1 + e]] has cond ~ 4/e */
    double e = 1e-6, R[4] = {1, 1, 1, 1 + e}, s2[2];
    CHECK(lm_singular_values(2, 2, R, s2) == LM_NERR_NONE);
    CHECK_NEAR(s2[0] / s2[1], 4 / e, 4 / e * 1e-5);
    /* wide: 2 x 3 has a zero singular value */
    double W[6] = {1, 2, 3, 4, 5, 6}, s3[3];
    CHECK(lm_singular_values(2, 3, W, s3) == LM_NERR_NONE);
    CHECK_NEAR(s3[2], 0, 0);
    CHECK(s3[0] > s3[1] && s3[1] > 0);
}

/* The normal equations stop only at an exactly zero pivot. */
static void test_normal_singular(void)
{
    double A[6] = {1, 0, 2, 0, 3, 0}, b[3] = {1, 2, 3}, x[2];
    lm_lsq_info info;
    CHECK(lm_lsq_normal(3, 2, A, b, x, &info) == LM_NERR_SINGULAR);
    double A2[6], b2[3] = {1, 2, 3}, y[2];
    memcpy(A2, A, sizeof A2);
    CHECK(lm_lsq_qr(3, 2, A2, b2, y, &info) == LM_NERR_NONE);   /* QR copes */
    CHECK(info.rank == 1);
    CHECK_NEAR(y[0], 1.0, 1e-15);
    CHECK_NEAR(y[1], 0.0, 0);
}

int main(void)
{
    test_full_rank();
    test_least_squares();
    test_min_norm_simple();
    test_min_norm_rank_deficient();
    test_condition();
    test_normal_singular();
    return CHECK_DONE();
}
