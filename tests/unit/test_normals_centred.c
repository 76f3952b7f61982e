/* test_normals_centred.c - the centred elements (normals_centred.c) and
 * the curvature rows (normals_smooth.c): what sim:membrane{normals =
 * "isosurface"} computes every step. Exact for circles, spheres, lines and
 * planes; robust where the per-cell construction of [N] §8 is not (a
 * membrane wrinkled by 1e-4); deterministic; never NaN. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "normals.h"
#include "normals_fixture.h"

#define PI 3.14159265358979323846
#define DEG (180.0 / PI)

static const lm_ngrid grid10 = {2, {0, 0, 0}, {0.1, 0.1, 0}, {10, 10, 1}};

static double angle(double ax, double ay, double az, double bx, double by, double bz)
{
    double c = fabs(ax * bx + ay * by + az * bz) /
               sqrt((ax * ax + ay * ay + az * az) * (bx * bx + by * by + bz * bz));
    return acos(fmin(1.0, c)) * DEG;
}

/* Quadratic B-spline coefficients (centres -1/2, 1/2, 3/2 per axis) of
 * p = b0 xi + b1 eta + s (xi^2 + eta^2): c = p(t) - s/2 (a quadratic's
 * coefficient is p(t) - p''/8 per axis). */
static void isotropic_coefficients(double b0, double b1, double s, double c[9])
{
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++) {
            double t = i - 0.5, u = j - 0.5;
            c[i + 3 * j] = b0 * t + b1 * u + s * (t * t + u * u) - 0.5 * s;
        }
}

static void test_smooth_rows(void)
{
    lm_nbox box = {2, {0.3, 0.2, 0}, {0.5, 0.4, 0}};
    double S[LM_NSMOOTH_MAXROWS * 9], c[9];
    int r = lm_nsmooth_rows(LM_NB_QUADRATIC, &box, 1.0, S);
    CHECK(r == 10);
    isotropic_coefficients(0.3, -1.2, 2.5, c);
    double worst = 0;
    for (int k = 0; k < r; k++) {
        double v = 0;
        for (int I = 0; I < 9; I++)
            v += S[k * 9 + I] * c[I];
        worst = fmax(worst, fabs(v));
    }
    CHECK(worst < 1e-13);
    /* xi^2 alone (a ridge's curvature) is penalised */
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++)
            c[i + 3 * j] = (i - 0.5) * (i - 0.5) - 0.25;
    double some = 0;
    for (int k = 0; k < r; k++) {
        double v = 0;
        for (int I = 0; I < 9; I++)
            v += S[k * 9 + I] * c[I];
        some = fmax(some, fabs(v));
    }
    CHECK(some > 0.5);
    lm_nbox box3 = {3, {0, 0, 0}, {1, 1, 1}};
    double S3[LM_NSMOOTH_MAXROWS * 27];
    CHECK(lm_nsmooth_rows(LM_NB_QUADRATIC, &box3, 1.0, S3) == LM_NSMOOTH_MAXROWS);
    CHECK(lm_nsmooth_rows(LM_NB_LINEAR, &box, 1.0, S) == 0);
    CHECK(lm_nsmooth_rows(LM_NB_QUADRATIC, &box, 0.0, S) == 0);
}

/* Arcs of circles, all points including the two ends: exact. */
static void test_circles_exact(void)
{
    static const double R[] = {0.5, 0.3, 0.2, 0.7, 0.45};
    static const int NP[] = {91, 46, 23};
    double worst = 0;
    for (int ri = 0; ri < 5; ri++)
        for (int pi = 0; pi < 3; pi++) {
            int n = NP[pi];
            double x[91], y[91], nx[91], ny[91];
            double ox = ri >= 3 ? 0.013 : 0, oy = ri >= 3 ? 0.021 : 0;
            for (int k = 0; k < n; k++) {
                double t = 0.5 * PI * k / (n - 1);
                x[k] = ox + R[ri] * cos(t);
                y[k] = oy + R[ri] * sin(t);
            }
            for (int seed = 1; seed <= 5; seed++) {
                lm_nopts o;
                lm_nopts_centred(&o);
                o.seed = (uint64_t)seed;
                const double *p[3] = {x, y, NULL};
                double *nrm[3] = {nx, ny, NULL};
                char err[256];
                CHECK(lm_normals_grid(&grid10, (size_t)n, p, &o, nrm, NULL, NULL, err,
                                      sizeof err) == LM_NERR_NONE);
                for (int k = 0; k < n; k++)
                    worst = fmax(worst, angle(nx[k], ny[k], 0, x[k] - ox, y[k] - oy, 0));
            }
        }
    printf("centred elements, arcs of radius 0.2-0.7 with 23-91 points: max error %.2g deg\n",
           worst);
    CHECK(worst < 1e-5);     /* rounding: cond(T) of the small elements ~1e10 */
}

/* The sphere octant of the 3D grid test and a plane: exact. */
static void test_sphere_plane_exact(void)
{
    enum { N = 200 };
    double x[N], y[N], z[N], n0[N], n1[N], n2[N];
    sphere_octant(N, 0.8, x, y, z);
    const lm_ngrid g = {3, {0, 0, 0}, {0.5, 0.5, 0.5}, {2, 2, 2}};
    const double *p[3] = {x, y, z};
    double *nrm[3] = {n0, n1, n2};
    unsigned char fl[N];
    lm_nopts o;
    lm_nopts_centred(&o);
    lm_nreport rep;
    char err[256];
    CHECK(lm_normals_grid(&g, N, p, &o, nrm, fl, &rep, err, sizeof err) == LM_NERR_NONE);
    double worst = 0;
    for (int k = 0; k < N; k++)
        worst = fmax(worst, angle(n0[k], n1[k], n2[k], x[k], y[k], z[k]));
    printf("centred elements, 3D: 200 points on the sphere octant, %d elements: max error "
           "%.2g deg\n", rep.nelem, worst);
    CHECK(worst < 1e-5);
    CHECK(rep.nelem > 1 && rep.nquadratic == rep.nelem);
    CHECK(rep.cell_elem[0] == -1);
    lm_nreport_free(&rep);
    /* the plane 0.5 x + 0.25 y - z = -0.2 ([N] Fig 5(a)'s, lifted into the grid) */
    for (int k = 0; k < N; k++) {
        x[k] = fmod(k * 0.6180339887, 1.0);
        y[k] = fmod(k * 0.7548776662, 1.0);
        z[k] = 0.5 * x[k] + 0.25 * y[k] + 0.2;
    }
    CHECK(lm_normals_grid(&g, N, p, &o, nrm, fl, NULL, err, sizeof err) == LM_NERR_NONE);
    worst = 0;
    for (int k = 0; k < N; k++)
        worst = fmax(worst, angle(n0[k], n1[k], n2[k], 0.5, 0.25, -1));
    printf("centred elements, 3D plane, 200 points: max error %.2g deg\n", worst);
    CHECK(worst < 1e-5);
}

/* A circle wrinkled by 1e-4 (r = 0.5 + 1e-4 sin(30 theta + s)): the ridge
 * and saddle fits of [N] §8 turn single per-cell normals by tens of
 * degrees; the centred elements stay within half a degree of the exact
 * normal of the wrinkled curve. */
static void test_wrinkled_circle(void)
{
    enum { N = 91 };
    double x[N], y[N], nx[N], ny[N];
    double worst[2] = {0, 0};
    for (int mode = 0; mode < 2; mode++)
        for (int s = 1; s <= 50; s++) {
            for (int k = 0; k < N; k++) {
                double t = 0.5 * PI * k / (N - 1), r = 0.5 + 1e-4 * sin(30 * t + s);
                x[k] = r * cos(t);
                y[k] = r * sin(t);
            }
            lm_nopts o;
            if (mode)
                lm_nopts_centred(&o);
            else
                lm_nopts_default(&o);
            o.seed = (uint64_t)s;
            const double *p[3] = {x, y, NULL};
            double *nrm[3] = {nx, ny, NULL};
            CHECK(lm_normals_grid(&grid10, N, p, &o, nrm, NULL, NULL, NULL, 0) == LM_NERR_NONE);
            for (int k = 2; k < N - 2; k++) {
                double t = 0.5 * PI * k / (N - 1), r = 0.5 + 1e-4 * sin(30 * t + s);
                double dr = 30e-4 * cos(30 * t + s);
                double tx = dr * cos(t) - r * sin(t), ty = dr * sin(t) + r * cos(t);
                worst[mode] = fmax(worst[mode], angle(nx[k], ny[k], 0, -ty, tx, 0));
            }
        }
    printf("circle wrinkled by 1e-4, 50 seeds, away from the ends: per-cell hybrid max "
           "%.1f deg, centred elements max %.2f deg\n", worst[0], worst[1]);
    CHECK(worst[1] < 0.5);
}

/* The same seed gives bit-identical normals; the points in another order
 * give the same elements and random points (streams keyed by the site),
 * so the same normals up to the rounding of the rows' order. */
static void test_determinism(void)
{
    enum { N = 91 };
    double x[N], y[N], px[N], py[N], a[2][N], b[2][N];
    for (int k = 0; k < N; k++) {
        double t = 0.5 * PI * k / (N - 1), r = 0.5 + 2e-4 * sin(17 * t);
        x[k] = r * cos(t);
        y[k] = r * sin(t);
        px[N - 1 - k] = x[k];
        py[N - 1 - k] = y[k];
    }
    lm_nopts o;
    lm_nopts_centred(&o);
    o.seed = 12345;
    o.skip_cond = 1;
    const double *p[3] = {x, y, NULL}, *q[3] = {px, py, NULL};
    double *na[3] = {a[0], a[1], NULL}, *nb[3] = {b[0], b[1], NULL};
    CHECK(lm_normals_grid(&grid10, N, p, &o, na, NULL, NULL, NULL, 0) == LM_NERR_NONE);
    CHECK(lm_normals_grid(&grid10, N, p, &o, nb, NULL, NULL, NULL, 0) == LM_NERR_NONE);
    CHECK(memcmp(a, b, sizeof a) == 0);
    CHECK(lm_normals_grid(&grid10, N, q, &o, nb, NULL, NULL, NULL, 0) == LM_NERR_NONE);
    double worst = 0;
    for (int k = 0; k < N; k++)
        worst = fmax(worst, angle(a[0][k], a[1][k], 0, b[0][N - 1 - k], b[1][N - 1 - k], 0));
    printf("centred elements, points in reverse order: normals within %.1g deg\n", worst);
    CHECK(worst < 1e-4);
}

/* Degenerate sets (few points, lines, coincident points, points on cell
 * edges): an error or finite unit normals, flagged where undefined. */
static void test_never_nan(void)
{
    const lm_ngrid g = {2, {0, 0, 0}, {1, 1, 0}, {3, 3, 1}};
    lm_nrng rng;
    lm_nrng_seed(&rng, 7);
    int runs = 0;
    for (int trial = 0; trial < 400; trial++) {
        double x[20], y[20], nx[20], ny[20];
        int n = 1 + (int)(lm_nrng_uniform(&rng) * 20), kind = trial % 4;
        for (int k = 0; k < n; k++) {
            double u = lm_nrng_uniform(&rng) * 3, v = lm_nrng_uniform(&rng) * 3;
            if (kind == 1) v = 1.5;
            if (kind == 2 && k > 0) { u = x[0]; v = y[0]; }
            if (kind == 3) { u = floor(u); v = floor(v * 2) / 2; }
            x[k] = u;
            y[k] = v;
        }
        const double *p[3] = {x, y, NULL};
        double *nrm[3] = {nx, ny, NULL};
        unsigned char fl[20];
        lm_nopts o;
        lm_nopts_centred(&o);
        o.seed = (uint64_t)trial;
        o.basis = trial % 5 == 0 ? LM_NB_LINEAR : LM_NB_QUADRATIC;
        lm_nerr e = lm_normals_grid(&g, (size_t)n, p, &o, nrm, fl, NULL, NULL, 0);
        CHECK(e == LM_NERR_NONE || e == LM_NERR_TOO_FEW);
        if (e != LM_NERR_NONE)
            continue;
        runs++;
        for (int k = 0; k < n; k++) {
            double l = nx[k] * nx[k] + ny[k] * ny[k];
            CHECK(isfinite(nx[k]) && isfinite(ny[k]));
            CHECK((fl[k] & LM_NF_UNDEFINED) ? l == 0 : fabs(l - 1) < 1e-12);
        }
    }
    printf("centred elements never NaN: %d runs over degenerate sets\n", runs);
    CHECK(runs > 100);
}

/* One element: cond(T) skipped gives the same phi; the random point keeps
 * its clearance; the options are checked. */
static void test_fit_options(void)
{
    double x[12], y[12];
    for (int k = 0; k < 12; k++) {
        double t = 0.5 * PI * (k + 0.5) / 12;
        x[k] = 0.5 + 0.3 * cos(t);
        y[k] = 0.5 + 0.3 * sin(t);
    }
    const double *p[3] = {x, y, NULL};
    lm_nbox box = {2, {0.4, 0.4, 0}, {0.9, 0.9, 0}};
    lm_nfit_opts fo;
    lm_nfit_opts_default(&fo);
    fo.basis = LM_NB_QUADRATIC;
    fo.smooth = LM_NSMOOTH;
    fo.clearance = LM_NCLEARANCE;
    lm_nfit f1, f2;
    char err[256];
    CHECK(lm_nfit_element(&box, p, NULL, 12, &fo, &f1, err, sizeof err) == LM_NERR_NONE);
    fo.skip_cond = 1;
    CHECK(lm_nfit_element(&box, p, NULL, 12, &fo, &f2, err, sizeof err) == LM_NERR_NONE);
    CHECK(memcmp(f1.phi, f2.phi, sizeof f1.phi) == 0);
    CHECK(isfinite(f1.info.cond_t) && isnan(f2.info.cond_t));
    CHECK(f1.smooth_rows == 10);
    double dmin = 1e9;
    for (int k = 0; k < 12; k++)
        dmin = fmin(dmin, hypot((x[k] - f1.q[0]) / 0.5, (y[k] - f1.q[1]) / 0.5));
    CHECK(dmin >= LM_NCLEARANCE);
    lm_nopts o;
    lm_nopts_centred(&o);
    o.clearance = 0.6;
    double nx[12], ny[12];
    double *nrm[3] = {nx, ny, NULL};
    CHECK(lm_normals_grid(&grid10, 12, p, &o, nrm, NULL, NULL, err, sizeof err) ==
          LM_NERR_INPUT);
    o.clearance = 0.1;
    o.element = (lm_nelement)7;
    CHECK(lm_normals_grid(&grid10, 12, p, &o, nrm, NULL, NULL, err, sizeof err) ==
          LM_NERR_INPUT);
}

/* The angle between two 2D directions by atan2 (acos cannot resolve the
 * 1e-9 degrees compared here). */
static double angle_small(double ax, double ay, double bx, double by)
{
    return fabs(atan2(ax * by - ay * bx, ax * bx + ay * by)) * DEG;
}

/* LM_NS_CHOLESKY (the simulation's solver: the normal equations of [N] eq
 * 13 for the 2D quadratic fits, normals_fit.c) against the pivoted QR, the
 * same elements and random points: the same normals to far below a
 * degree's millionth on circles, wrinkled circles and off-centre arcs;
 * exact circles stay exact. Without the curvature rows a straight
 * membrane leaves T singular (phi is free off the line): every such fit
 * falls back to the QR (minimum norm), so the normals are the QR's bit
 * for bit. */
static void test_cholesky_matches_qr(void)
{
    enum { N = 91 };
    double x[N], y[N], a[2][N], b[2][N], worst = 0, exact = 0;
    for (int shape = 0; shape < 4; shape++)
        for (int s = 1; s <= 20; s++) {
            double R = shape == 2 ? 0.3 : 0.5, ox = shape == 2 ? 0.013 : 0;
            double oy = shape == 2 ? 0.021 : 0;
            int n = shape == 3 ? 40 : N;
            for (int k = 0; k < n; k++) {
                double t = 0.5 * PI * k / (N - 1);
                double r = R + (shape == 1 ? 1e-4 * sin(30 * t + s) : 0.0);
                x[k] = shape == 3 ? 0.05 + 0.9 * k / (n - 1) : ox + r * cos(t);
                y[k] = shape == 3 ? 0.4 : oy + r * sin(t);
            }
            lm_nopts o;
            lm_nopts_centred(&o);
            o.seed = (uint64_t)s;
            o.skip_cond = 1;
            const double *p[3] = {x, y, NULL};
            double *na[3] = {a[0], a[1], NULL}, *nb[3] = {b[0], b[1], NULL};
            o.solver = LM_NS_CHOLESKY;
            CHECK(lm_normals_grid(&grid10, (size_t)n, p, &o, na, NULL, NULL, NULL, 0) ==
                  LM_NERR_NONE);
            o.solver = LM_NS_QR;
            CHECK(lm_normals_grid(&grid10, (size_t)n, p, &o, nb, NULL, NULL, NULL, 0) ==
                  LM_NERR_NONE);
            for (int k = 0; k < n; k++) {
                worst = fmax(worst, angle_small(a[0][k], a[1][k], b[0][k], b[1][k]));
                if (shape == 0)
                    exact = fmax(exact, angle(a[0][k], a[1][k], 0, x[k], y[k], 0));
            }
        }
    printf("Cholesky against QR, circles, wrinkled and off-centre arcs, a line: "
           "max %.2g deg; circles by Cholesky: max error %.2g deg\n", worst, exact);
    CHECK(worst < 1e-6);
    CHECK(exact < 1e-5);
    for (int k = 0; k < 40; k++) {
        x[k] = 0.05 + 0.9 * k / 39.0;
        y[k] = 0.43;
    }
    lm_nopts o;
    lm_nopts_centred(&o);
    o.skip_cond = 1;
    o.smooth = 0;
    const double *p[3] = {x, y, NULL};
    double *na[3] = {a[0], a[1], NULL}, *nb[3] = {b[0], b[1], NULL};
    o.solver = LM_NS_CHOLESKY;
    CHECK(lm_normals_grid(&grid10, 40, p, &o, na, NULL, NULL, NULL, 0) == LM_NERR_NONE);
    o.solver = LM_NS_QR;
    CHECK(lm_normals_grid(&grid10, 40, p, &o, nb, NULL, NULL, NULL, 0) == LM_NERR_NONE);
    for (int k = 0; k < 40; k++)
        CHECK(a[0][k] == b[0][k] && a[1][k] == b[1][k]);
}

int main(void)
{
    test_smooth_rows();
    test_circles_exact();
    test_sphere_plane_exact();
    test_wrinkled_circle();
    test_determinism();
    test_never_nan();
    test_fit_options();
    test_cholesky_matches_qr();
    return CHECK_DONE();
}
