/* test_normals_work.c - the normals' workspace (normals_work.c) and the
 * faster pivoted QR (normals_qr.c) change no bit of a result (issue 17
 * item 3: the step's normals allocate nothing and cost less, the states
 * stay the same):
 *  - the QR against a plain row-major reference written the way the QR was
 *    before (one column at a time): the same solution, bit for bit;
 *  - the same on the 3D membranes' 27-column systems, with the portable
 *    and the AVX2 lanes of normals_qr_pivot.c;
 *  - lm_lsq_qr_ws (stack and caller's buffer) against lm_lsq_qr_cond;
 *  - one workspace reused over membranes of several sizes (growing and
 *    shrinking, every orientation) against a fresh lm_normals_grid;
 *  - the normals of two points at a time (lm_nfit_normal2, SSE2 lanes)
 *    against two calls of lm_nfit_normal: the same bits and flags, points
 *    on and a rounding outside the element, flat and NaN fits included. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "normals.h"
#include "normals_work.h"

#define AT(M, i, j, ld) ((M)[(size_t)(i) * (size_t)(ld) + (size_t)(j)])

/* ---- the reference: pivoted Householder QR, column by column ------------- */

static void ref_qr(int m, int n, double *A, double *b, double *x)
{
    int perm[LM_NMAX];
    double col[256], y[LM_NMAX];
    for (int j = 0; j < n; j++)
        perm[j] = j;
    for (int k = 0; k < n; k++) {
        int best = k;
        double bn = -1;
        for (int j = k; j < n; j++) {
            double s = 0;
            for (int i = k; i < m; i++)
                s += AT(A, i, j, n) * AT(A, i, j, n);
            if (s > bn) {
                bn = s;
                best = j;
            }
        }
        for (int i = 0; i < m; i++) {
            double t = AT(A, i, k, n);
            AT(A, i, k, n) = AT(A, i, best, n);
            AT(A, i, best, n) = t;
        }
        int t = perm[k];
        perm[k] = perm[best];
        perm[best] = t;
        double tail = 0;
        for (int i = k + 1; i < m; i++)
            tail += AT(A, i, k, n) * AT(A, i, k, n);
        double u0 = AT(A, k, k, n), alpha = u0;
        if (tail != 0.0) {
            double norm = sqrt(u0 * u0 + tail);
            alpha = u0 >= 0 ? -norm : norm;
            double w0 = u0 - alpha, tau = 2.0 / (w0 * w0 + tail);
            AT(A, k, k, n) = w0;
            for (int i = k; i < m; i++)
                col[i] = AT(A, i, k, n);
            for (int j = k + 1; j < n; j++) {
                double d = 0;
                for (int i = k; i < m; i++)
                    d += col[i] * AT(A, i, j, n);
                d *= tau;
                for (int i = k; i < m; i++)
                    AT(A, i, j, n) -= d * col[i];
            }
            double d = 0;
            for (int i = k; i < m; i++)
                d += col[i] * b[i];
            d *= tau;
            for (int i = k; i < m; i++)
                b[i] -= d * col[i];
        }
        AT(A, k, k, n) = alpha;
    }
    for (int k = n - 1; k >= 0; k--) {
        double s = b[k];
        for (int j = k + 1; j < n; j++)
            s -= AT(A, k, j, n) * y[j];
        y[k] = s / AT(A, k, k, n);
    }
    for (int j = 0; j < n; j++)
        x[perm[j]] = y[j];
}

static double urand(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (*s >> 8) / 16777216.0;
}

/* Rows like a fit's: the 2D quadratic basis at points near a curve, a
 * random point, and (smooth) the curvature rows. */
static int fit_like(unsigned *seed, int k, int smooth, double *A, double *b)
{
    lm_nbox box = {2, {0, 0, 0}, {1, 1, 0}};
    int m = 0;
    for (int p = 0; p <= k; p++, m++) {
        double t = urand(seed), xi[3] = {t, 0.5 + 0.1 * (t - 0.5) * (t - 0.5), 0};
        if (p == k) {
            xi[0] = urand(seed);
            xi[1] = urand(seed);
        }
        lm_nbasis_eval(LM_NB_QUADRATIC, 2, xi, A + m * 9, NULL);
        b[m] = p < k;
    }
    if (smooth) {
        int r = lm_nsmooth_rows(LM_NB_QUADRATIC, &box, 2e-3 * sqrt((double)m), A + m * 9);
        for (int q = 0; q < r; q++)
            b[m + q] = 0;
        m += r;
    }
    return m;
}

static void test_qr_bits(void)
{
    unsigned seed = 7;
    int same = 0, tried = 0;
    for (int c = 0; c < 200; c++) {
        double A[64 * 9], b[64], A1[64 * 9], b1[64], A2[64 * 9], b2[64], C[LM_QR_WORK(64, 9)];
        double x0[9], x1[9], x2[9];
        int m = fit_like(&seed, 9 + c % 20, c % 3 != 0, A, b);
        memcpy(A1, A, sizeof A);
        memcpy(b1, b, sizeof b);
        memcpy(A2, A, sizeof A);
        memcpy(b2, b, sizeof b);
        lm_lsq_info i1, i2;
        ref_qr(m, 9, A, b, x0);
        CHECK(lm_lsq_qr_cond(m, 9, A1, b1, x1, &i1, 0) == LM_NERR_NONE);
        CHECK(lm_lsq_qr_ws(m, 9, A2, b2, x2, &i2, 0, C) == LM_NERR_NONE);
        CHECK(memcmp(x1, x2, sizeof x1) == 0);
        if (i1.rank == 9) {      /* the reference has no rank-deficient branch */
            tried++;
            same += memcmp(x0, x1, sizeof x0) == 0;
        }
    }
    CHECK(tried > 100);
    CHECK(same == tried);
}

/* Rows like the 3D membranes' fits (sim3_membrane_normals.c, the systems
 * that made test_sim3_membrane the longest unit test): the 27 triquadratic
 * functions at k points near a sphere, a random point and the 63 curvature
 * rows (k = 20 .. 119: m = 84 .. 183 rows), and a few underdetermined
 * ones without the curvature rows (k < 26). The QR four columns to a
 * vector (normals_qr_pivot.c) with either instruction set against the
 * column-by-column reference: the same solution, bit for bit; the two
 * sets against each other on every system, rank-deficient ones too. */
static void test_qr_bits_3d(void)
{
    unsigned seed = 5;
    int tried = 0, same = 0, agree = 0;
    enum { MR = 120 + 1 + LM_NSMOOTH_MAXROWS };
    static double A[MR * 27], b[MR], Ai[2][MR * 27], bi[2][MR], C[LM_QR_WORK(MR, 27)];
    lm_nbox box = {3, {0, 0, 0}, {1, 1, 1}};
    for (int c = 0; c < 60; c++) {
        int k = c < 50 ? 20 + 2 * c : 5 + 4 * (c - 50) % 21, smooth = c < 50, m = 0;
        for (int p = 0; p <= k; p++, m++) {
            /* a point of the sphere of radius 0.8 about (0.5, 0.5, -0.3),
             * jittered by 1e-3; the last one anywhere in the box */
            double th = 0.3 + 0.4 * urand(&seed), ph = 1.2 + 0.6 * urand(&seed);
            double r = 0.8 + 1e-3 * (urand(&seed) - 0.5);
            double xi[3] = {0.5 + r * sin(th) * cos(ph) + 0.2, 0.5 + r * sin(th) * sin(ph) - 0.2,
                            -0.3 + r * cos(th) - 0.1};
            if (p == k)
                for (int a = 0; a < 3; a++)
                    xi[a] = urand(&seed);
            for (int a = 0; a < 3; a++)
                xi[a] = fmin(1, fmax(0, xi[a]));
            lm_nbasis_eval(LM_NB_QUADRATIC, 3, xi, A + (size_t)m * 27, NULL);
            b[m] = p < k;
        }
        if (smooth) {
            int r = lm_nsmooth_rows(LM_NB_QUADRATIC, &box, 2e-3 * sqrt((double)m),
                                    A + (size_t)m * 27);
            for (int q = 0; q < r; q++)
                b[m + q] = 0;
            m += r;
        }
        double x0[27], x[2][27];
        lm_lsq_info info[2];
        for (int isa = 0; isa < 2; isa++) {
            memcpy(Ai[isa], A, sizeof(double) * (size_t)m * 27);
            memcpy(bi[isa], b, sizeof(double) * (size_t)m);
            lm_qr_pivot_isa(isa);
            CHECK(lm_lsq_qr_ws(m, 27, Ai[isa], bi[isa], x[isa], &info[isa], 0, C) ==
                  LM_NERR_NONE);
        }
        lm_qr_pivot_isa(-1);
        agree += memcmp(x[0], x[1], sizeof x[0]) == 0 && info[0].rank == info[1].rank;
        if (info[0].rank == 27 && m <= 256) {   /* the reference: full rank, col[256] */
            ref_qr(m, 27, A, b, x0);
            tried++;
            same += memcmp(x0, x[0], sizeof x0) == 0;
        }
    }
    printf("3D fit-like systems: %d of 60 the same bits with both instruction sets; "
           "%d of %d full-rank ones the same bits as the column-by-column reference\n",
           agree, same, tried);
    CHECK(agree == 60);
    CHECK(tried >= 40);
    CHECK(same == tried);
}

/* Underdetermined and rank-deficient systems: the two entry points agree. */
static void test_qr_ws_deficient(void)
{
    unsigned seed = 11;
    for (int c = 0; c < 50; c++) {
        double A[8 * 9], b[8], A1[8 * 9], b1[8], C[LM_QR_WORK(8, 9)], x[9], x1[9];
        int m = 3 + c % 6;
        for (int i = 0; i < m; i++) {
            for (int j = 0; j < 9; j++)
                A[i * 9 + j] = j == 4 ? A[i * 9] : urand(&seed);   /* column 4 = column 0 */
            b[i] = urand(&seed);
        }
        memcpy(A1, A, sizeof A);
        memcpy(b1, b, sizeof b);
        lm_lsq_info i0, i1;
        CHECK(lm_lsq_qr_cond(m, 9, A, b, x, &i0, 1) == LM_NERR_NONE);
        CHECK(lm_lsq_qr_ws(m, 9, A1, b1, x1, &i1, 1, C) == LM_NERR_NONE);
        CHECK(memcmp(x, x1, sizeof x) == 0);
        CHECK(i0.rank == i1.rank && i0.rank < 9);
        CHECK(memcmp(&i0.cond_t, &i1.cond_t, sizeof i0.cond_t) == 0);
    }
}

/* ---- the workspace ---------------------------------------------------------- */

/* n points on a wavy circle about (0.5, 0.5) in the unit square. */
static void wavy_circle(size_t n, double *x, double *y)
{
    for (size_t k = 0; k < n; k++) {
        double a = 2 * 3.14159265358979323846 * (double)k / (double)n;
        double r = 0.3 + 0.01 * sin(7 * a);
        x[k] = 0.5 + r * cos(a);
        y[k] = 0.5 + r * sin(a);
    }
}

static void test_workspace_reuse(void)
{
    const lm_ngrid g = {2, {0, 0, 0}, {0.05, 0.05, 0}, {20, 20, 1}};
    const size_t sizes[] = {60, 400, 90, 400, 37};
    const lm_norient how[] = {LM_NORIENT_NONE, LM_NORIENT_NEIGHBOURS, LM_NORIENT_AWAY,
                              LM_NORIENT_SEQUENCE, LM_NORIENT_NEIGHBOURS};
    lm_nwork w;
    memset(&w, 0, sizeof w);
    for (int c = 0; c < 5; c++) {
        size_t n = sizes[c];
        double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
        double *a = calloc(4 * n, sizeof *a);
        unsigned char *fa = calloc(n, 1), *fb = calloc(n, 1);
        wavy_circle(n, x, y);
        const double *pts[3] = {x, y, NULL};
        double *na[3] = {a, a + n, NULL}, *nb[3] = {a + 2 * n, a + 3 * n, NULL};
        for (int centred = 0; centred < 2; centred++) {
            lm_nopts o;
            if (centred)
                lm_nopts_centred(&o);
            else
                lm_nopts_default(&o);
            o.orient = how[c];
            o.orient_point[0] = o.orient_point[1] = 0.5;
            o.skip_cond = c % 2;
            o.seed = 3 + (uint64_t)c;
            char err[256];
            CHECK(lm_normals_grid(&g, n, pts, &o, na, fa, NULL, err, sizeof err) ==
                  LM_NERR_NONE);
            CHECK(lm_normals_grid_ws(&g, n, pts, &o, nb, fb, NULL, &w, err, sizeof err) ==
                  LM_NERR_NONE);
            CHECK(memcmp(a, a + 2 * n, 2 * n * sizeof *a) == 0);
            CHECK(memcmp(fa, fb, n) == 0);
        }
        CHECK(w.cap >= n);
        free(x);
        free(y);
        free(a);
        free(fa);
        free(fb);
    }
    CHECK(w.cap == 400);          /* grown twice to the largest, never shrunk */
    lm_nwork_free(&w);
    CHECK(w.cap == 0 && w.idx == NULL);
}

/* lm_nfit_normal2 = two lm_nfit_normal, bit for bit: random quadratic
 * fits on boxes of random size and aspect, points inside, on the edges
 * and a little outside (the general path), fits flat enough to leave the
 * normal undefined, and a NaN coefficient. */
static void test_normal_pair_bits(void)
{
    unsigned seed = 12345;
    int tried = 0, same = 0, undefined = 0, outside = 0;
    for (int t = 0; t < 2000; t++) {
        lm_nfit f;
        memset(&f, 0, sizeof f);
        f.dim = 2;
        f.basis = LM_NB_QUADRATIC;
        f.n = 9;
        double x0 = urand(&seed) - 0.5, y0 = urand(&seed) - 0.5;
        double w = 0.01 + urand(&seed), hgt = w * (0.25 + 4 * urand(&seed));
        f.box = (lm_nbox){2, {x0, y0, 0}, {x0 + w, y0 + hgt, 0}};
        int flat = t % 7 == 0;          /* phi = 1 within 1e-13: no gradient */
        for (int I = 0; I < 9; I++)
            f.phi[I] = flat ? 1.0 + 1e-13 * urand(&seed) : 2 * urand(&seed) - 1;
        if (t % 97 == 0)
            f.phi[3] = NAN;
        double p[2][3];
        for (int l = 0; l < 2; l++) {
            double u = urand(&seed), v = urand(&seed);
            int k = (int)(urand(&seed) * 8);
            if (k == 0) u = 0.0;                        /* on an edge */
            if (k == 1) v = 1.0;
            if (k == 2) u = 1.0 + 1e-12;                /* a rounding outside */
            if (k == 3) v = -1e-9;
            p[l][0] = x0 + u * w;
            p[l][1] = y0 + v * hgt;
            p[l][2] = 0.0;
            outside += k == 2 || k == 3;
        }
        double na[3], nb[3], ra[3], rb[3];
        int bad[2];
        lm_nfit_normal2(&f, p[0], p[1], na, nb, bad);
        int ba = lm_nfit_normal(&f, p[0], ra), bb = lm_nfit_normal(&f, p[1], rb);
        tried++;
        same += memcmp(na, ra, sizeof na) == 0 && memcmp(nb, rb, sizeof nb) == 0 &&
                bad[0] == ba && bad[1] == bb;
        undefined += (ba != 0) + (bb != 0);
    }
    CHECK(same == tried);
    CHECK(undefined > 100);     /* the flat and NaN fits were reached */
    CHECK(outside > 100);       /* and the general path */
}

int main(void)
{
    test_qr_bits();
    test_qr_bits_3d();
    test_qr_ws_deficient();
    test_workspace_reuse();
    test_normal_pair_bits();
    return CHECK_DONE();
}
