/* test_normals_paper.c - the normals paper's static cases N1-N5
 * (docs/physics.md §6) on the engine: [N] Tables I-III, Figs 3-5, 7, 9-11.
 *
 * Where the paper leaves the placement of its points out, the placements
 * are those of scripts/paper/normals_fig*.lua (each says why). Criteria:
 *  - "exact": every normal within 1e-10 rad of the exact one;
 *  - "same order of magnitude" (Tables I-II): |log10(ours/paper)| < 1 for
 *    the median condition numbers;
 *  - "of the order of" a paper error (Table III, Fig 5): within a factor 2.
 * A paper number the code does not reach is printed as a KNOWN GAP with the
 * measured value and not counted: no tolerance is widened to pass. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "normals.h"

#define PI 3.14159265358979323846
#define DEG (180.0 / PI)

static void known_gap(int met, const char *what)
{
    fprintf(stderr, "%s: %s\n", met ? "known gap now met" : "KNOWN GAP (not counted)", what);
}

/* angle between two unit vectors, sign-blind, accurate near 0 */
static double angle(const double n[3], const double e[3])
{
    double d = fabs(n[0] * e[0] + n[1] * e[1] + n[2] * e[2]);
    double c0 = n[1] * e[2] - n[2] * e[1], c1 = n[2] * e[0] - n[0] * e[2];
    double c2 = n[0] * e[1] - n[1] * e[0];
    return atan2(sqrt(c0 * c0 + c1 * c1 + c2 * c2), d);
}

typedef struct errs { double max, rms, alt; int rank; double cond; } errs;

/* Fits one element and measures the normals against ex (k x 3). */
static errs measure(const lm_nbox *box, int k, double *x, double *y, double *z,
                    const double (*ex)[3], lm_nbasis basis, lm_nsolver solver,
                    uint64_t seed, const double *random_point)
{
    lm_nfit_opts o;
    lm_nfit_opts_default(&o);
    o.basis = basis;
    o.solver = solver;
    o.seed = seed;
    if (random_point) {
        o.random_given = 1;
        for (int a = 0; a < 3; a++)
            o.random_point[a] = random_point[a];
    }
    const double *const pts[3] = {x, y, z};
    lm_nfit f;
    char err[256];
    errs r = {0, 0, 0, 0, 0};
    if (lm_nfit_element(box, pts, NULL, (size_t)k, &o, &f, err, sizeof err)) {
        fprintf(stderr, "fit failed: %s\n", err);
        check_failures++;
        r.max = INFINITY;
        return r;
    }
    double s2 = 0;
    for (int i = 0; i < k; i++) {
        double p[3] = {x[i], y[i], z ? z[i] : 0}, n[3];
        if (lm_nfit_normal(&f, p, n)) {
            r.max = INFINITY;
            continue;
        }
        double a = angle(n, ex[i]);
        r.max = fmax(r.max, a);
        s2 += a * a;
    }
    r.rms = sqrt(s2 / k);
    r.alt = sqrt(s2) / k;       /* the paper's "rms", see test_table3 */
    r.rank = f.info.rank;
    r.cond = f.info.cond_t;
    return r;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static const lm_nbox unit2 = {2, {0, 0, 0}, {1, 1, 0}};
static const lm_nbox unit3 = {3, {0, 0, 0}, {1, 1, 1}};

/* ---- N1: lines, [N] Tables I-II, Fig 3 ------------------------------------ */

/* n points at chord fractions (k + 1/2)/n on the line of slope s through
 * the element centre. */
static void line(double s, int n, double *x, double *y, double (*ex)[3])
{
    double x0 = 0, x1 = 1;
    if (fabs(s) > 1) {
        double a = 0.5 - 0.5 / s, b = 0.5 + 0.5 / s;
        x0 = fmin(a, b);
        x1 = fmax(a, b);
    }
    for (int k = 0; k < n; k++) {
        x[k] = x0 + (k + 0.5) / n * (x1 - x0);
        y[k] = 0.5 + s * (x[k] - 0.5);
        double l = sqrt(1 + s * s);
        ex[k][0] = -s / l;
        ex[k][1] = 1 / l;
        ex[k][2] = 0;
    }
}

static void test_n1_lines(void)
{
    static const double slope[10] = {0.1, 0.5, 1, 2, 10, -10, -2, -1, -0.5, -0.1};
    static const double paper_median[10] = {5.0e3, 1.7e2, 5.9e1, 3.6e2, 5.4e3,
                                            5.3e3, 3.3e2, 6.1e1, 1.2e2, 6.0e3};
    /* Table II: slopes 1, 2, 10 with 4 and 8 points */
    static const double t2_slope[3] = {1, 2, 10};
    static const double t2_median[3][2] = {{7.9e1, 6.5e1}, {1.9e2, 3.4e2}, {5.8e3, 7.7e3}};
    double worst = 0, x[8], y[8], ex[8][3], c[100];
    printf("N1 / Table I: slope, median cond(T) ours vs paper\n");
    for (int s = 0; s < 10; s++) {
        line(slope[s], 3, x, y, ex);
        for (int t = 0; t < 100; t++) {
            errs e = measure(&unit2, 3, x, y, NULL, (const double (*)[3])ex, LM_NB_LINEAR,
                             LM_NS_QR, (uint64_t)t + 1, NULL);
            worst = fmax(worst, e.max);
            c[t] = e.cond;
        }
        double med = median(c, 100);
        printf("  %5.1f  %9.3g  %9.3g\n", slope[s], med, paper_median[s]);
        CHECK(fabs(log10(med / paper_median[s])) < 1.0);
    }
    printf("N1 / Table II: slope, points, median cond(T) ours vs paper\n");
    for (int s = 0; s < 3; s++)
        for (int q = 0; q < 2; q++) {
            int n = q ? 8 : 4;
            line(t2_slope[s], n, x, y, ex);
            for (int t = 0; t < 100; t++) {
                errs e = measure(&unit2, n, x, y, NULL, (const double (*)[3])ex,
                                 LM_NB_LINEAR, LM_NS_QR, (uint64_t)t + 1, NULL);
                worst = fmax(worst, e.max);
                c[t] = e.cond;
            }
            double med = median(c, 100);
            printf("  %5.1f  %d  %9.3g  %9.3g\n", t2_slope[s], n, med, t2_median[s][q]);
            CHECK(fabs(log10(med / t2_median[s][q])) < 1.0);
        }
    printf("N1: largest normal error over 1600 fits: %.2e rad\n", worst);
    CHECK(worst < 1e-10);
}

/* ---- N2: curves, [N] Fig 4, Table III ---------------------------------------- */

/* (a) xy + 0.1x + 0.3 = 0 in the element [-1, 0] x [0, 1] (the printed
 * curve never enters [0,1]^2): bilinear, so exact with the linear basis. */
static void test_n2_bilinear(void)
{
    const lm_nbox box = {2, {-1, 0, 0}, {0, 1, 0}};
    double x[3], y[3], ex[3][3], xe = -0.3 / 1.1, worst = 0;
    for (int k = 0; k < 3; k++) {
        x[k] = -1 + (k + 0.5) / 3 * (xe + 1);
        y[k] = -0.1 - 0.3 / x[k];
        double gx = y[k] + 0.1, gy = x[k], l = hypot(gx, gy);
        ex[k][0] = gx / l;
        ex[k][1] = gy / l;
        ex[k][2] = 0;
    }
    for (int t = 1; t <= 100; t++) {
        errs e = measure(&box, 3, x, y, NULL, (const double (*)[3])ex, LM_NB_LINEAR,
                         LM_NS_QR, (uint64_t)t, NULL);
        worst = fmax(worst, e.max);
    }
    printf("N2 / Fig 4(a): bilinear curve, worst of 100 random points %.2e rad\n", worst);
    CHECK(worst < 1e-10);
}

static void circle(int n, double *x, double *y, double (*ex)[3])
{
    for (int k = 0; k < n; k++) {
        double t = 0.5 * PI * k / (n - 1);
        x[k] = 0.8 * cos(t);
        y[k] = 0.8 * sin(t);
        ex[k][0] = cos(t);
        ex[k][1] = sin(t);
        ex[k][2] = 0;
    }
}

/* Table III: the circle x^2 + y^2 = 0.8^2, 3 ... 32 points, random point
 * fixed. The paper's "rms" cannot be a root mean square over the points:
 * rms >= max / sqrt(n), and its first row has 0.0571 < 0.1211 / sqrt(3) =
 * 0.0699 (Fig 5's 3 deg rms with 13 deg max over 8 points breaks it too).
 * Its numbers fit sqrt(sum e^2) / n ("alt"), which is what is compared;
 * the usual rms is checked to fall as well. */
static void test_n2_table3(void)
{
    static const int npts[5] = {3, 4, 8, 16, 32};
    static const double pmax[5] = {0.1211, 0.1091, 0.1177, 0.1261, 0.1308};
    static const double prms[5] = {0.0571, 0.0434, 0.0231, 0.0141, 0.0092};
    double x[32], y[32], ex[32][3], q[3];
    /* the random point of the 3-point fit with seed 1, then held */
    {
        lm_nfit_opts o;
        lm_nfit_opts_default(&o);
        lm_nfit f;
        circle(3, x, y, ex);
        const double *const p[3] = {x, y, NULL};
        CHECK(lm_nfit_element(&unit2, p, NULL, 3, &o, &f, NULL, 0) == LM_NERR_NONE);
        for (int a = 0; a < 3; a++)
            q[a] = f.q[a];
    }
    double last_rms = INFINITY, last_alt = INFINITY;
    printf("N2 / Table III: n, max, rms, sqrt(sum e^2)/n | paper max, rms (rad)\n");
    for (int i = 0; i < 5; i++) {
        circle(npts[i], x, y, ex);
        errs e = measure(&unit2, npts[i], x, y, NULL, (const double (*)[3])ex, LM_NB_LINEAR,
                         LM_NS_QR, 1, q);
        printf("  %2d  %.4f  %.4f  %.4f | %.4f  %.4f\n", npts[i], e.max, e.rms, e.alt, pmax[i],
               prms[i]);
        CHECK(e.max > 0.5 * pmax[i] && e.max < 2 * pmax[i]);
        CHECK(e.alt > 0.5 * prms[i] && e.alt < 2 * prms[i]);
        CHECK(e.rms < last_rms);
        CHECK(e.alt < last_alt);
        last_rms = e.rms;
        last_alt = e.alt;
    }
}

/* ---- N3: the linear basis' limit, [N] Fig 7 ------------------------------------ */

static void arc(const double *deg, int n, double *x, double *y, double (*ex)[3])
{
    for (int k = 0; k < n; k++) {
        double t = deg[k] / DEG;
        x[k] = 0.5 + 0.3 * cos(t);
        y[k] = 0.5 + 0.3 * sin(t);
        ex[k][0] = cos(t);
        ex[k][1] = sin(t);
        ex[k][2] = 0;
    }
}

static void spaced(double a0, double step, int n, double *deg)
{
    for (int k = 0; k < n; k++)
        deg[k] = a0 + step * k;
}

/* median over 100 random points of the max error, degrees */
static double median_error(const double *deg, int n, lm_nbasis b, lm_nsolver s)
{
    double x[16], y[16], ex[16][3], v[100];
    arc(deg, n, x, y, ex);
    for (int t = 0; t < 100; t++)
        v[t] = measure(&unit2, n, x, y, NULL, (const double (*)[3])ex, b, s,
                       (uint64_t)t + 1, NULL).max * DEG;
    return median(v, 100);
}

static void test_n3_shared_coordinate(void)
{
    double a[5], b[5];
    spaced(180, 22.5, 5, a);    /* distinct coordinates */
    spaced(225, 22.5, 5, b);    /* two pairs share y */
    double ea = median_error(a, 5, LM_NB_LINEAR, LM_NS_QR);
    double eb = median_error(b, 5, LM_NB_LINEAR, LM_NS_QR);
    printf("N3 / Fig 7: median max error (a) %.2f deg (paper 6), (b) %.2f deg (paper 34)\n", ea,
           eb);
    CHECK(eb > 2 * ea);           /* the limitation: much larger when y is shared */
    CHECK(ea < 2 * 6.0);          /* (a) of the order of the paper's 6 degrees */
    CHECK(eb > 0.5 * 34.0 && eb < 2 * 34.0);   /* (b) of the order of its 34 */
}

/* ---- N4: the quadratic basis, [N] Figs 9-10 ------------------------------------- */

static void test_n4_quadratic(void)
{
    double a[8], x[8], y[8], ex[8][3], worst = 0;
    /* (c), (d): 8 points 11.25 deg apart - 9 rows for 9 unknowns, exact */
    for (int c = 0; c < 2; c++) {
        spaced(c ? 225 : 180, 11.25, 8, a);
        arc(a, 8, x, y, ex);
        for (int t = 1; t <= 100; t++) {
            errs e = measure(&unit2, 8, x, y, NULL, (const double (*)[3])ex,
                             LM_NB_QUADRATIC, LM_NS_QR, (uint64_t)t, NULL);
            worst = fmax(worst, e.max);
            CHECK(e.rank == 9);
        }
    }
    printf("N4 / Fig 9(c-d): 8 points, worst of 200 fits %.2e rad\n", worst);
    CHECK(worst < 1e-10);

    /* 8 points symmetric about 225 deg: exactly singular (the biquadratic
     * restricted to the circle lacks sin 4 theta); QR finds rank 8 and the
     * minimum-norm solution stays close */
    spaced(180, 90.0 / 7, 8, a);
    arc(a, 8, x, y, ex);
    errs s = measure(&unit2, 8, x, y, NULL, (const double (*)[3])ex, LM_NB_QUADRATIC,
                     LM_NS_QR, 1, NULL);
    printf("N4: 8 symmetric points: rank %d, max error %.3f deg\n", s.rank, s.max * DEG);
    CHECK(s.rank == 8);
    CHECK(s.max * DEG < 1.0);

    /* Fig 9(b), underdetermined: QR (minimum norm) beats the normal
     * equations (paper: 19 deg -> < 1 deg); medians over 100 points */
    double b[5];
    spaced(225, 22.5, 5, b);
    double qr = median_error(b, 5, LM_NB_QUADRATIC, LM_NS_QR);
    double ne = median_error(b, 5, LM_NB_QUADRATIC, LM_NS_NORMAL);
    spaced(180, 22.5, 5, a);
    double qra = median_error(a, 5, LM_NB_QUADRATIC, LM_NS_QR);
    double nea = median_error(a, 5, LM_NB_QUADRATIC, LM_NS_NORMAL);
    printf("N4 / Fig 9(b): median max error QR %.2f deg, normal equations %.2f deg "
           "(paper < 1 and 19)\n", qr, ne);
    printf("N4 / Fig 9(a): median max error QR %.2f deg, normal equations %.2f deg "
           "(paper: -, 3)\n", qra, nea);
    CHECK(qr < ne);
    CHECK(qra < nea);
    known_gap(qr < 1.0, "Fig 9(b) by QR below 1 deg (median over random points)");
}

/* Fig 10: y = c x^2 (x - 1) + x + 0.5 on [0,1] x [0.5,1.5], 10 points. */
static void test_n4_cubic(void)
{
    const lm_nbox box = {2, {0, 0.5, 0}, {1, 1.5, 0}};
    double e[2];
    for (int i = 0; i < 2; i++) {
        double c = i ? 4 : 2, x[10], y[10], ex[10][3], v[100];
        for (int k = 0; k < 10; k++) {
            x[k] = k / 9.0;
            y[k] = c * x[k] * x[k] * (x[k] - 1) + x[k] + 0.5;
            double d = c * (3 * x[k] * x[k] - 2 * x[k]) + 1, l = sqrt(1 + d * d);
            ex[k][0] = -d / l;
            ex[k][1] = 1 / l;
            ex[k][2] = 0;
        }
        for (int t = 0; t < 100; t++)
            v[t] = measure(&box, 10, x, y, NULL, (const double (*)[3])ex, LM_NB_QUADRATIC,
                           LM_NS_QR, (uint64_t)t + 1, NULL).max * DEG;
        e[i] = median(v, 100);
    }
    printf("N4 / Fig 10: median max error c = 2: %.2f deg (paper 1), c = 4: %.2f deg "
           "(paper 32)\n", e[0], e[1]);
    CHECK(e[1] > 5 * e[0]);       /* unresolved curvature: far worse */
    CHECK(e[1] > 0.5 * 32);
    known_gap(e[0] < 2 * 1.0, "Fig 10(a) c = 2 within a factor 2 of 1 deg");
}

/* ---- N5: three dimensions, [N] Figs 5, 11 ---------------------------------------- */

static void plane_grid(int ni, int nj, double x0, double dx, double *x, double *y, double *z,
                       double (*ex)[3], int centred)
{
    double l = sqrt(0.25 + 0.0625 + 1);
    int k = 0;
    for (int i = 0; i < ni; i++)
        for (int j = 0; j < nj; j++, k++) {
            x[k] = centred ? (i + 0.5) / ni : x0 + dx * i;
            y[k] = centred ? (j + 0.5) / nj : x0 + dx * j;
            z[k] = 0.5 * x[k] + 0.25 * y[k];
            ex[k][0] = -0.5 / l;
            ex[k][1] = -0.25 / l;
            ex[k][2] = 1 / l;
        }
}

static void sphere(int n, double *x, double *y, double *z, double (*ex)[3])
{
    double golden = (3 - sqrt(5.0)) * PI;
    for (int k = 0; k < n; k++) {
        double c = (k + 0.5) / n, s = sqrt(1 - c * c);
        double ph = 0.5 * PI * fmod(k * golden, 1.0);
        ex[k][0] = s * cos(ph);
        ex[k][1] = s * sin(ph);
        ex[k][2] = c;
        x[k] = 0.8 * ex[k][0];
        y[k] = 0.8 * ex[k][1];
        z[k] = 0.8 * ex[k][2];
    }
}

static void test_n5_3d(void)
{
    double x[30], y[30], z[30], ex[30][3], worst_plane = 0, worst_sphere = 0;
    for (int t = 1; t <= 20; t++) {
        plane_grid(3, 3, 0.2, 0.3, x, y, z, ex, 0);
        worst_plane = fmax(worst_plane, measure(&unit3, 9, x, y, z, (const double (*)[3])ex,
                                                LM_NB_LINEAR, LM_NS_QR, (uint64_t)t, NULL).max);
        plane_grid(5, 6, 0, 0, x, y, z, ex, 1);
        errs q = measure(&unit3, 30, x, y, z, (const double (*)[3])ex, LM_NB_QUADRATIC,
                         LM_NS_QR, (uint64_t)t, NULL);
        worst_plane = fmax(worst_plane, q.max);
        CHECK(q.rank == 20);    /* plane x multilinear: 8 free */
        sphere(29, x, y, z, ex);
        errs s = measure(&unit3, 29, x, y, z, (const double (*)[3])ex, LM_NB_QUADRATIC,
                         LM_NS_QR, (uint64_t)t, NULL);
        worst_sphere = fmax(worst_sphere, s.max);
        CHECK(s.rank == 27);
    }
    printf("N5 / Figs 5(a), 11: plane (linear, quadratic) worst %.2e rad, sphere quadratic "
           "worst %.2e rad\n", worst_plane, worst_sphere);
    CHECK(worst_plane < 1e-10);
    CHECK(worst_sphere < 1e-10);

    sphere(8, x, y, z, ex);
    errs e = measure(&unit3, 8, x, y, z, (const double (*)[3])ex, LM_NB_LINEAR, LM_NS_QR, 1,
                     NULL);
    printf("N5 / Fig 5(b): sphere, 8 points, linear: max %.2f deg, rms %.2f deg, "
           "sqrt(sum e^2)/n %.2f deg (paper 13, 3)\n", e.max * DEG, e.rms * DEG, e.alt * DEG);
    CHECK(e.max * DEG <= 13.0);   /* within the paper's figures */
    CHECK(e.alt * DEG <= 3.0);
    known_gap(e.rms * DEG <= 3.0, "Fig 5(b) rms over the points <= 3 deg (the paper's "
              "3 deg is sqrt(sum e^2)/n; the usual rms is printed above)");
}

int main(void)
{
    test_n1_lines();
    test_n2_bilinear();
    test_n2_table3();
    test_n3_shared_coordinate();
    test_n4_quadratic();
    test_n4_cubic();
    test_n5_3d();
    return CHECK_DONE();
}
