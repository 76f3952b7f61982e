/* test_normals_grid.c - normals over a grid, element by element ([N] §3,
 * §8): the hybrid rule, 2x2 merging, orientation, determinism, bad input
 * (issue 4 item 7: a clear error or a reported fallback, never a NaN
 * normal), the dissertation's variants ([T] Ch. 7) and 3D. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "normals.h"
#include "normals_fixture.h"

#define PI 3.14159265358979323846
#define DEG (180.0 / PI)

/* The quarter circle of radius 0.5 about the origin in 10 x 10 cells of
 * 0.1: the gas-filled membrane of [N] Fig 12 (91 points), here static. */
enum { NC = 91 };
static double cx[NC], cy[NC];
static const lm_ngrid grid10 = {2, {0, 0, 0}, {0.1, 0.1, 0}, {10, 10, 1}};

static void make_circle(void)
{
    for (int k = 0; k < NC; k++) {
        double t = 0.5 * PI * k / (NC - 1);
        cx[k] = 0.5 * cos(t);
        cy[k] = 0.5 * sin(t);
    }
}

/* radial error in degrees, sign-blind; *outward counts n . x > 0 */
static double circle_error(const double *nx, const double *ny, int k)
{
    double ex = cx[k] / 0.5, ey = cy[k] / 0.5;
    return atan2(fabs(nx[k] * ey - ny[k] * ex), fabs(nx[k] * ex + ny[k] * ey)) * DEG;
}

static const lm_nelem *element_at(const lm_nreport *r, int i, int j)
{
    for (int k = 0; k < r->nelem; k++)
        if (r->elem[k].cell[0] == i && r->elem[k].cell[1] == j)
            return &r->elem[k];
    return NULL;
}

static int finite_unit_or_flagged(size_t n, int dim, double *const nrm[3],
                                  const unsigned char *flags)
{
    for (size_t i = 0; i < n; i++) {
        double l = 0;
        for (int a = 0; a < dim; a++) {
            if (!isfinite(nrm[a][i]))
                return 0;
            l += nrm[a][i] * nrm[a][i];
        }
        if (flags && (flags[i] & LM_NF_UNDEFINED) ? l != 0 : fabs(l - 1) > 1e-12)
            return 0;
    }
    return 1;
}

/* The V6 geometry: quadratic where a cell has >= 7 points, the two end
 * points (each alone in a cell, on the edge x = 0.5 or y = 0.5) merged
 * into 2x2 linear blocks. */
static void test_hybrid_circle(void)
{
    double nx[NC], ny[NC];
    double *nrm[3] = {nx, ny, NULL};
    const double *x[3] = {cx, cy, NULL};
    unsigned char fl[NC];
    lm_nopts o;
    lm_nopts_default(&o);
    o.orient = LM_NORIENT_AWAY;
    lm_nreport rep;
    char err[256];
    CHECK(lm_normals_grid(&grid10, NC, x, &o, nrm, fl, &rep, err, sizeof err) == LM_NERR_NONE);
    CHECK(finite_unit_or_flagged(NC, 2, nrm, fl));
    CHECK(rep.nelem == 9 && rep.nmerged == 2 && rep.nquadratic == 7 && rep.nlinear == 2);
    const lm_nelem *end = element_at(&rep, 5, 0);
    CHECK(end && (end->fit.flags & LM_NF_MERGED) && end->size == 2 && end->lo[0] == 4 &&
          end->lo[1] == 0 && end->fit.basis == LM_NB_LINEAR && end->fit.npoints == 24);
    double inner = 0, ends = 0;
    int outward = 0;
    for (int k = 0; k < NC; k++) {
        double e = circle_error(nx, ny, k);
        if (k >= 3 && k < NC - 3)
            inner = fmax(inner, e);
        else
            ends = fmax(ends, e);
        outward += nx[k] * cx[k] + ny[k] * cy[k] > 0;
    }
    printf("hybrid, 91 points on r = 0.5, cells 0.1: max error %.2e deg away from the ends, "
           "%.2f deg at the ends\n", inner, ends);
    CHECK(inner < 1e-8);          /* the circle is biquadratic: exact */
    CHECK(ends < 10);
    CHECK(outward == NC);         /* orientation: away from the centre */
    lm_nreport_free(&rep);
}

/* The rule itself, cell by cell: 8 points -> quadratic (square 9 x 9),
 * 7 -> quadratic by the minimum-norm solution (8 rows), 4 -> linear,
 * 1 -> merged with the neighbour that has the points. */
static void test_hybrid_rule(void)
{
    const lm_ngrid g = {2, {0, 0, 0}, {1, 1, 0}, {4, 1, 1}};
    double x[20], y[20], nx[20], ny[20];
    int n = 0;
    const int counts[4] = {8, 7, 4, 1};
    for (int c = 0; c < 4; c++)
        for (int k = 0; k < counts[c]; k++, n++) {
            double t = (200 + 80.0 * k / (counts[c] > 1 ? counts[c] - 1 : 1) + 3 * c) / DEG;
            x[n] = c + 0.5 + 0.3 * cos(t);
            y[n] = 0.5 + 0.3 * sin(t);
        }
    const double *p[3] = {x, y, NULL};
    double *nrm[3] = {nx, ny, NULL};
    unsigned char fl[20];
    lm_nopts o;
    lm_nopts_default(&o);
    lm_nreport rep;
    char err[256];
    CHECK(lm_normals_grid(&g, (size_t)n, p, &o, nrm, fl, &rep, err, sizeof err) ==
          LM_NERR_NONE);
    CHECK(finite_unit_or_flagged((size_t)n, 2, nrm, fl));
    const lm_nelem *e8 = element_at(&rep, 0, 0), *e7 = element_at(&rep, 1, 0);
    const lm_nelem *e4 = element_at(&rep, 2, 0), *e1 = element_at(&rep, 3, 0);
    CHECK(e8 && e8->fit.basis == LM_NB_QUADRATIC && e8->fit.info.rank == 9);
    CHECK(e7 && e7->fit.basis == LM_NB_QUADRATIC && e7->fit.info.rank == 8 &&
          (e7->fit.flags & LM_NF_UNDERDETERMINED));
    CHECK(e4 && e4->fit.basis == LM_NB_LINEAR && !(e4->fit.flags & LM_NF_MERGED));
    CHECK(e1 && (e1->fit.flags & LM_NF_MERGED) && e1->lo[0] == 2 && e1->size == 2 &&
          e1->fit.npoints == 5 && e1->fit.basis == LM_NB_LINEAR);
    CHECK(fl[n - 1] & LM_NF_MERGED);
    /* the 8- and 7-point cells are on a circle: exact (7: minimum norm) */
    double worst = 0;
    for (int k = 0; k < 15; k++) {
        double ex = x[k] - (k < 8 ? 0.5 : 1.5), ey = y[k] - 0.5, l = hypot(ex, ey);
        worst = fmax(worst, atan2(fabs(nx[k] * ey - ny[k] * ex) / l,
                                  fabs(nx[k] * ex + ny[k] * ey) / l) * DEG);
    }
    printf("hybrid rule: 8 and 7 points on arcs, max error %.2e deg\n", worst);
    CHECK(worst < 0.5);
    lm_nreport_free(&rep);
}

/* Orientation without order: shuffled points, NEIGHBOURS makes every
 * normal agree with its curve neighbours; SEQUENCE in curve order. */
static void test_orientation(void)
{
    double sx[NC], sy[NC], nx[NC], ny[NC];
    int perm[NC];
    for (int k = 0; k < NC; k++)
        perm[k] = (k * 37) % NC;        /* 37 is prime to 91: a permutation */
    for (int k = 0; k < NC; k++) {
        sx[k] = cx[perm[k]];
        sy[k] = cy[perm[k]];
    }
    const double *p[3] = {sx, sy, NULL};
    double *nrm[3] = {nx, ny, NULL};
    lm_nopts o;
    lm_nopts_default(&o);
    o.orient = LM_NORIENT_NEIGHBOURS;
    CHECK(lm_normals_grid(&grid10, NC, p, &o, nrm, NULL, NULL, NULL, 0) == LM_NERR_NONE);
    int out = 0;
    for (int k = 0; k < NC; k++)
        out += nx[k] * sx[k] + ny[k] * sy[k] > 0;
    CHECK(out == 0 || out == NC);       /* one sign for all */
    const double *q[3] = {cx, cy, NULL};
    o.orient = LM_NORIENT_SEQUENCE;
    CHECK(lm_normals_grid(&grid10, NC, q, &o, nrm, NULL, NULL, NULL, 0) == LM_NERR_NONE);
    out = 0;
    for (int k = 0; k < NC; k++)
        out += nx[k] * cx[k] + ny[k] * cy[k] > 0;
    CHECK(out == 0 || out == NC);
    /* NONE keeps grad phi's sign: with random points on both sides some
     * elements point in and some out - the paper's "flipped" normals */
    o.orient = LM_NORIENT_NONE;
    int mixed = 0;
    for (uint64_t s = 1; s <= 20 && !mixed; s++) {
        o.seed = s;
        CHECK(lm_normals_grid(&grid10, NC, q, &o, nrm, NULL, NULL, NULL, 0) == LM_NERR_NONE);
        out = 0;
        for (int k = 0; k < NC; k++)
            out += nx[k] * cx[k] + ny[k] * cy[k] > 0;
        mixed = out > 0 && out < NC;
    }
    CHECK(mixed);
}

static void test_determinism(void)
{
    double a[2][NC], b[2][NC];
    const double *p[3] = {cx, cy, NULL};
    double *na[3] = {a[0], a[1], NULL}, *nb[3] = {b[0], b[1], NULL};
    lm_nopts o;
    lm_nopts_default(&o);
    o.seed = 12345;
    CHECK(lm_normals_grid(&grid10, NC, p, &o, na, NULL, NULL, NULL, 0) == LM_NERR_NONE);
    CHECK(lm_normals_grid(&grid10, NC, p, &o, nb, NULL, NULL, NULL, 0) == LM_NERR_NONE);
    CHECK(memcmp(a, b, sizeof a) == 0);
    o.seed = 12346;   /* another seed: other random points, other phi */
    CHECK(lm_normals_grid(&grid10, NC, p, &o, nb, NULL, NULL, NULL, 0) == LM_NERR_NONE);
    lm_nreport r1, r2;
    o.seed = 1;
    lm_normals_grid(&grid10, NC, p, &o, na, NULL, &r1, NULL, 0);
    o.seed = 2;
    lm_normals_grid(&grid10, NC, p, &o, nb, NULL, &r2, NULL, 0);
    CHECK(r1.elem[0].fit.q[0] != r2.elem[0].fit.q[0]);
    lm_nreport_free(&r1);
    lm_nreport_free(&r2);
}

/* Issue 4 item 7. */
static void test_bad_input(void)
{
    char err[256];
    lm_nopts o;
    lm_nopts_default(&o);
    double x[4] = {0.2, 0.4, 1.7, 0.5}, y[4] = {0.2, 0.3, 0.5, 0.5}, nx[4], ny[4];
    const double *p[3] = {x, y, NULL};
    double *nrm[3] = {nx, ny, NULL};
    const lm_ngrid g = {2, {0, 0, 0}, {0.5, 0.5, 0}, {2, 2, 1}};
    CHECK(lm_normals_grid(&g, 4, p, &o, nrm, NULL, NULL, err, sizeof err) == LM_NERR_OUTSIDE);
    CHECK(strstr(err, "point 3") && strstr(err, "outside"));
    x[2] = NAN;
    CHECK(lm_normals_grid(&g, 4, p, &o, nrm, NULL, NULL, err, sizeof err) ==
          LM_NERR_NOT_FINITE);
    CHECK(strstr(err, "point 3") != NULL);
    /* one distinct point in the whole grid: no merge can help */
    double one[3] = {0.3, 0.3, 0.3};
    const double *q[3] = {one, one, NULL};
    CHECK(lm_normals_grid(&g, 3, q, &o, nrm, NULL, NULL, err, sizeof err) == LM_NERR_TOO_FEW);
    CHECK(strstr(err, "whole grid") != NULL);
    /* a single element: one point is too few; a point outside is named */
    lm_nfit_opts fo;
    lm_nfit_opts_default(&fo);
    lm_nfit f;
    const lm_nbox box = {2, {0, 0, 0}, {1, 1, 0}};
    CHECK(lm_nfit_element(&box, q, NULL, 3, &fo, &f, err, sizeof err) == LM_NERR_TOO_FEW);
    CHECK(strstr(err, "distinct") != NULL);
    double ox[2] = {0.5, 1.5}, oy[2] = {0.5, 0.5};
    const double *op[3] = {ox, oy, NULL};
    CHECK(lm_nfit_element(&box, op, NULL, 2, &fo, &f, err, sizeof err) == LM_NERR_OUTSIDE);
    CHECK(strstr(err, "point 2 (1.5, 0.5)") != NULL);
    CHECK(lm_nfit_element(&box, op, NULL, 0, &fo, &f, err, sizeof err) == LM_NERR_TOO_FEW);
    /* coincident points: reported, normals still finite */
    double cxp[4] = {0.2, 0.2, 0.5, 0.8}, cyp[4] = {0.2, 0.2, 0.5, 0.8};
    const double *cp[3] = {cxp, cyp, NULL};
    CHECK(lm_nfit_element(&box, cp, NULL, 4, &fo, &f, err, sizeof err) == LM_NERR_NONE);
    CHECK(f.flags & LM_NF_COINCIDENT);
    CHECK(f.nunique == 3);
    double nv[3], pt[3] = {0.5, 0.5, 0};
    CHECK(lm_nfit_normal(&f, pt, nv) == 0);
    CHECK_NEAR(fabs(nv[0] + nv[1]) / sqrt(2.0), 0, 1e-10);   /* normal to y = x */
    /* the normal equations on an exactly singular system say so */
    fo.solver = LM_NS_NORMAL;
    fo.basis = LM_NB_QUADRATIC;
    double hx[3] = {0.0, 0.5, 1.0}, hy[3] = {0.5, 0.5, 0.5};
    const double *hp[3] = {hx, hy, NULL};
    lm_nerr e = lm_nfit_element(&box, hp, NULL, 3, &fo, &f, err, sizeof err);
    CHECK(e == LM_NERR_NONE || e == LM_NERR_SINGULAR);
    if (e == LM_NERR_SINGULAR)
        CHECK(strstr(err, "QR") != NULL);
}

/* Random small configurations, degenerate ones included (duplicates,
 * horizontal lines, points on cell edges): never a NaN normal; a normal is
 * a unit vector or zero and flagged undefined. */
static void test_never_nan(void)
{
    const lm_ngrid g = {2, {0, 0, 0}, {1, 1, 0}, {3, 3, 1}};
    lm_nrng rng;
    lm_nrng_seed(&rng, 99);
    int undefined = 0, runs = 0;
    for (int trial = 0; trial < 300; trial++) {
        double x[12], y[12], nx[12], ny[12];
        int n = 1 + (int)(lm_nrng_uniform(&rng) * 12);
        int kind = trial % 4;
        for (int k = 0; k < n; k++) {
            double u = lm_nrng_uniform(&rng) * 3, v = lm_nrng_uniform(&rng) * 3;
            if (kind == 1) v = 1.5;                        /* horizontal line */
            if (kind == 2 && k > 0) { u = x[0]; v = y[0]; } /* all coincident */
            if (kind == 3) { u = floor(u); v = floor(v * 2) / 2; }   /* on edges */
            x[k] = u;
            y[k] = v;
        }
        const double *p[3] = {x, y, NULL};
        double *nrm[3] = {nx, ny, NULL};
        unsigned char fl[12];
        for (int b = 1; b <= 3; b++)
            for (int s = 0; s < 2; s++) {
                lm_nopts o;
                lm_nopts_default(&o);
                o.basis = (lm_nbasis)b;
                o.solver = (lm_nsolver)s;
                o.seed = (uint64_t)trial;
                o.phi2 = trial % 3 == 0;
                lm_nerr e = lm_normals_grid(&g, (size_t)n, p, &o, nrm, fl, NULL, NULL, 0);
                CHECK(e == LM_NERR_NONE || e == LM_NERR_TOO_FEW || e == LM_NERR_SINGULAR);
                if (e == LM_NERR_NONE) {
                    runs++;
                    CHECK(finite_unit_or_flagged((size_t)n, 2, nrm, fl));
                    for (int k = 0; k < n; k++)
                        undefined += (fl[k] & LM_NF_UNDEFINED) != 0;
                }
            }
    }
    printf("never NaN: %d grid runs over degenerate sets, %d undefined normals flagged\n",
           runs, undefined);
}

/* [T] Ch. 7 on the static circle: the colour functions are far off (the
 * dissertation: "unacceptable"), the mass matrix per cell is the linear
 * isosurface construction; the global solve with random points on both
 * sides of the membrane makes phi = 1 a ridge ([N] §8) and fails. */
static void test_variants(void)
{
    double nx[NC], ny[NC];
    double *nrm[3] = {nx, ny, NULL};
    const double *p[3] = {cx, cy, NULL};
    unsigned char fl[NC];
    char err[256];
    lm_nopts o;
    lm_nopts_default(&o);
    double worst[4] = {0, 0, 0, 0}, cond = 0;
    const char *name[4] = {"colour", "quadratic colour", "mass matrix per cell",
                           "mass matrix global"};
    for (int v = 0; v < 4; v++) {
        lm_nerr e;
        if (v == 0)
            e = lm_normals_colour(&grid10, NC, p, nrm, fl, err, sizeof err);
        else if (v == 1)
            e = lm_normals_quadratic_colour(&grid10, NC, p, nrm, fl, err, sizeof err);
        else if (v == 2) {
            o.basis = LM_NB_LINEAR;
            o.solver = LM_NS_NORMAL;
            e = lm_normals_grid(&grid10, NC, p, &o, nrm, fl, NULL, err, sizeof err);
        } else {
            lm_nopts_default(&o);
            e = lm_normals_mass_matrix_global(&grid10, NC, p, &o, nrm, fl, &cond, err,
                                              sizeof err);
        }
        CHECK(e == LM_NERR_NONE);
        CHECK(finite_unit_or_flagged(NC, 2, nrm, fl));
        for (int k = 0; k < NC; k++)
            worst[v] = fmax(worst[v], circle_error(nx, ny, k));
        printf("[T] Ch. 7 %-22s max error %6.2f deg\n", name[v], worst[v]);
    }
    CHECK(worst[0] > 20 && worst[1] > 20);
    CHECK(worst[2] < 6);
    double bad[2] = {1, NAN};
    const double *bp[3] = {bad, bad, NULL};
    CHECK(lm_normals_colour(&grid10, 2, bp, nrm, fl, err, sizeof err) == LM_NERR_NOT_FINITE);
}

/* 3D: the sphere octant of radius 0.8 in 2 x 2 x 2 cells of 0.5. */
static void test_grid_3d(void)
{
    enum { N = 200 };
    double x[N], y[N], z[N], n0[N], n1[N], n2[N];
    sphere_octant(N, 0.8, x, y, z);
    const lm_ngrid g = {3, {0, 0, 0}, {0.5, 0.5, 0.5}, {2, 2, 2}};
    const double *p[3] = {x, y, z};
    double *nrm[3] = {n0, n1, n2};
    unsigned char fl[N];
    lm_nopts o;
    lm_nopts_default(&o);
    o.orient = LM_NORIENT_AWAY;
    lm_nreport rep;
    char err[256];
    CHECK(lm_normals_grid(&g, N, p, &o, nrm, fl, &rep, err, sizeof err) == LM_NERR_NONE);
    CHECK(finite_unit_or_flagged(N, 3, nrm, fl));
    double worst = 0;
    int out = 0;
    for (int k = 0; k < N; k++) {
        double d = (n0[k] * x[k] + n1[k] * y[k] + n2[k] * z[k]) / 0.8;
        worst = fmax(worst, acos(fmin(1.0, fabs(d))) * DEG);
        out += d > 0;
    }
    printf("3D hybrid, 200 points on the sphere octant, 8 cells: max error %.2f deg, "
           "%d quadratic and %d linear elements\n", worst, rep.nquadratic, rep.nlinear);
    CHECK(out == N);
    CHECK(rep.nquadratic > 0);
    lm_nreport_free(&rep);
}

int main(void)
{
    make_circle();
    test_hybrid_circle();
    test_hybrid_rule();
    test_orientation();
    test_determinism();
    test_bad_input();
    test_never_nan();
    test_variants();
    test_grid_3d();
    return CHECK_DONE();
}
