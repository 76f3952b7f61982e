/* test_sim3_membrane.c - membranes in the 3D engine (issue 34 item 2,
 * docs/3d.md "3D membranes", tests 4, 5 and 8 of its list).
 *
 * The sampled surfaces: areas summing to the surface's (exactly, by
 * construction), right-handed unit frames, normals out of a closed
 * surface.
 *
 * The pre-tensioned flat sheet (issue 34 item 2): a square sheet at
 * isotropic strain e0 = 1 %, its outer ring of points pinned, is in
 * equilibrium; in the discrete model the interior nodes' forces cancel
 * only as far as the point quadrature does, so the sheet must stay at rest
 * with its tension T0 = E t e0 / (1 - nu) within 0.5 % over 1 s, aligned
 * with the grid and turned 30 degrees about z.
 *
 * The square under pressure (test 5). A membrane under tension T (N/m)
 * and a small pressure p has the deflection w with T lap w = -p, w = 0 on
 * the edges (the pre-tensioned linear membrane; the stretching the
 * deflection adds, of order (w/a)^2, is kept far below e0). On the square
 * [0, a]^2, expanding -p in the sine series (16 p / pi^2) sum_{m,n odd}
 * sin(m pi x / a) sin(n pi y / a) / (m n) and dividing each term by
 * T (m^2 + n^2) pi^2 / a^2:
 *     w(x, y) = 16 p a^2 / (pi^4 T) sum_{m,n odd}
 *               sin(m pi x / a) sin(n pi y / a) / (m n (m^2 + n^2)),
 * at the centre w_c = 16 p a^2 / (pi^4 T) sum (-1)^((m + n)/2 - 1) /
 * (m n (m^2 + n^2)) = 0.07367 p a^2 / T (the sum is computed below, not
 * typed in). The edges are the grid's fixed walls x0, x1, y0, y1: they sit
 * on node planes, so the held boundary is exactly x = 0, a and y = 0, a.
 *
 * The balloon (test 4, without gas): a spherical membrane with pressure p
 * on its points (p A n) settles, damped, where its tension is p r / 2
 * (Laplace: 2 T / r = p for a sphere), r its radius then; within 2 %. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "mpm3.h"
#include "mpm3_membrane.h"

static const double PI = 3.14159265358979323846;

static lm_material sheet_material(void)
{
    lm_material m;
    memset(&m, 0, sizeof m);
    m.kind = LM_MEMBRANE;
    m.rho = 1000;
    m.E = 1e6;
    m.nu = 0.3;
    m.thickness = 1e-3;
    m.law = LM_LAW_PLANE_STRESS;
    return m;
}

static lm3_sim *make_sim(const double lo[3], const double hi[3], double h, double dt,
                         lm_basis basis, lm_bc side)
{
    lm3_def d;
    memset(&d, 0, sizeof d);
    for (int a = 0; a < 3; a++) {
        d.lo[a] = lo[a];
        d.hi[a] = hi[a];
    }
    d.cell = h;
    d.dt = dt;
    d.basis = basis;
    d.scheme = LM_MUSL;
    for (int f = 0; f < LM3_FACES; f++) d.bc[f] = side;
    d.bc[LM3_ZLO] = d.bc[LM3_ZHI] = LM_BC_FREE;
    char err[256];
    lm3_sim *sim = lm3_sim_create(&d, err, sizeof err);
    if (!sim) fprintf(stderr, "%s\n", err);
    return sim;
}

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Every point's frame unit and right-handed; returns the largest error. */
static double frame_error(const lm3_msample *s)
{
    double worst = 0;
    for (size_t q = 0; q < s->n; q++) {
        double t1[3] = {s->t1[0][q], s->t1[1][q], s->t1[2][q]};
        double t2[3] = {s->t2[0][q], s->t2[1][q], s->t2[2][q]};
        double e = fmax(fabs(dot(t1, t1) - 1), fmax(fabs(dot(t2, t2) - 1), fabs(dot(t1, t2))));
        if (e > worst) worst = e;
    }
    return worst;
}

static void samplers(void)
{
    char err[256];
    lm3_msample s;
    double c[3] = {0.5, 0.5, 0.5}, r = 0.3;
    CHECK(lm3_sample_sphere(c, r, 0.02, &s, err, sizeof err) == 0);
    double area = 0, worst_n = 0;
    for (size_t q = 0; q < s.n; q++) {
        area += s.A[q];
        double x[3] = {s.x[0][q] - c[0], s.x[1][q] - c[1], s.x[2][q] - c[2]};
        double t1[3] = {s.t1[0][q], s.t1[1][q], s.t1[2][q]};
        double t2[3] = {s.t2[0][q], s.t2[1][q], s.t2[2][q]};
        double n[3] = {t1[1] * t2[2] - t1[2] * t2[1], t1[2] * t2[0] - t1[0] * t2[2],
                       t1[0] * t2[1] - t1[1] * t2[0]};
        double e = fabs(dot(n, x) / r - 1);   /* n is the outward radial unit */
        if (e > worst_n) worst_n = e;
        CHECK_NEAR(sqrt(dot(x, x)), r, 1e-15);
    }
    CHECK_NEAR(area, 4 * PI * r * r, 1e-13);
    CHECK(worst_n < 1e-14);
    CHECK(frame_error(&s) < 1e-15);
    CHECK(s.closed == 1);
    /* mean nearest-neighbour distance near the spacing asked for */
    printf("sphere r = 0.3, spacing 0.02: %zu points\n", s.n);
    lm3_msample_free(&s);

    double o[3] = {0.1, 0.2, 0.3}, u[3] = {0.5, 0.2, 0}, v[3] = {-0.1, 0.4, 0.1};
    CHECK(lm3_sample_rect3(o, u, v, 0.05, &s, err, sizeof err) == 0);
    double uv[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                    u[0] * v[1] - u[1] * v[0]};
    area = 0;
    for (size_t q = 0; q < s.n; q++) area += s.A[q];
    CHECK_NEAR(area, sqrt(dot(uv, uv)), 1e-15);
    CHECK(frame_error(&s) < 1e-15);
    lm3_msample_free(&s);

    /* an octahedron, its triangles wound inwards: turned out */
    const double xyz[18] = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    const int32_t tri[24] = {0, 4, 2, 2, 4, 1, 1, 4, 3, 3, 4, 0,
                             0, 2, 5, 2, 1, 5, 1, 3, 5, 3, 0, 5};
    CHECK(lm3_sample_mesh(xyz, 6, tri, 8, &s, err, sizeof err) == 0);
    area = 0;
    for (size_t q = 0; q < s.n; q++) {
        area += s.A[q];
        double x[3] = {s.x[0][q], s.x[1][q], s.x[2][q]};
        double n[3] = {s.t1[1][q] * s.t2[2][q] - s.t1[2][q] * s.t2[1][q],
                       s.t1[2][q] * s.t2[0][q] - s.t1[0][q] * s.t2[2][q],
                       s.t1[0][q] * s.t2[1][q] - s.t1[1][q] * s.t2[0][q]};
        CHECK_NEAR(dot(n, x), 1, 1e-15);   /* each vertex's fan normal: radial, out */
    }
    CHECK_NEAR(area, 8 * sqrt(3) / 2, 1e-14);   /* 8 equilateral faces of side sqrt 2 */
    CHECK(s.closed == 1);
    lm3_msample_free(&s);
    /* refusals, naming what */
    const int32_t bad[3] = {0, 1, 7};
    CHECK(lm3_sample_mesh(xyz, 6, bad, 1, &s, err, sizeof err) != 0);
    CHECK(strstr(err, "triangle 1") && strstr(err, "vertex 8"));
    const int32_t flat[3] = {0, 1, 0};
    CHECK(lm3_sample_mesh(xyz, 6, flat, 1, &s, err, sizeof err) != 0);
    CHECK(strstr(err, "no area") != NULL);
    CHECK(lm3_sample_sphere(c, -1, 0.02, &s, err, sizeof err) != 0);
    CHECK(strstr(err, "radius") != NULL);
}

/* The outer ring of an nu x nv rect3 sample. */
static size_t ring(size_t nu, size_t nv, size_t *idx)
{
    size_t k = 0;
    for (size_t j = 0; j < nv; j++)
        for (size_t i = 0; i < nu; i++)
            if (i == 0 || j == 0 || i == nu - 1 || j == nv - 1) idx[k++] = j * nu + i;
    return k;
}

/* The pre-tensioned sheet, side 0.5, centred, turned deg degrees about z:
 * the largest deviation of the free points' tension from T0 over 1 s (and
 * of their mean), the largest speed, and the momentum balance with the
 * pins' reactions. */
static void flat_sheet(double deg, lm_basis basis, double ppc, double *dev_max, double *dev_mean,
                       double *vmax, double *balance)
{
    const double h = 1.0 / 16, dt = 1e-3, L = 0.5, e0 = 0.01;
    double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 0.25};
    lm3_sim *sim = make_sim(lo, hi, h, dt, basis, LM_BC_FIXED);
    CHECK(sim != NULL);
    if (!sim) return;
    double th = deg * PI / 180, c = cos(th), s = sin(th);
    double u[3] = {L * c, L * s, 0}, v[3] = {-L * s, L * c, 0};
    double o[3] = {0.5 - 0.5 * (u[0] + v[0]), 0.5 - 0.5 * (u[1] + v[1]), 0.11};
    lm3_msample smp;
    char err[256];
    CHECK(lm3_sample_rect3(o, u, v, h / ppc, &smp, err, sizeof err) == 0);
    lm3_mdef def;
    lm3_mdef_default(&def);
    def.mat = sheet_material();
    def.initial_strain = e0;
    int k = lm3_membrane_add(sim, &def, &smp);
    CHECK(k == 0);
    size_t nu = (size_t)ceil(L / (h / ppc) - 1e-9), nv = nu, *idx = malloc(smp.n * sizeof *idx);
    CHECK(smp.n == nu * nv);
    size_t np = ring(nu, nv, idx);
    CHECK(lm3_membrane_pin(sim, k, idx, np) == 0);
    lm3_msample_free(&smp);
    const double T0 = def.mat.E * def.mat.thickness * e0 / (1 - def.mat.nu);
    *dev_max = *dev_mean = *vmax = *balance = 0;
    const lm3_mpoints *p = &sim->mem->p;
    for (int n = 0; n < 1000; n++) {
        double P0[3] = {0, 0, 0}, P1[3] = {0, 0, 0};
        lm3_membrane_momentum(sim, P0);
        lm_status st = lm3_step(sim);
        CHECK(st == LM_OK);
        if (st != LM_OK) {
            fprintf(stderr, "%s\n", sim->err);
            break;
        }
        lm3_membrane_momentum(sim, P1);
        /* no gravity, no pressure: the free points' momentum changes by
         * dt times the reactions alone */
        for (int a = 0; a < 3; a++) {
            double r = fabs(P1[a] - P0[a] - dt * sim->mem->pins[0].reaction[a]);
            if (r > *balance) *balance = r;
        }
        double mean = 0;
        size_t nf = 0;
        for (size_t q = 0; q < p->n; q++) {
            if (p->pin[q]) continue;
            double T = lm3_membrane_tension(sim, q), d = fabs(T / T0 - 1);
            double sp = sqrt(p->v[0][q] * p->v[0][q] + p->v[1][q] * p->v[1][q] +
                             p->v[2][q] * p->v[2][q]);
            if (d > *dev_max) *dev_max = d;
            if (sp > *vmax) *vmax = sp;
            mean += T;
            nf++;
        }
        double dm = fabs(mean / nf / T0 - 1);
        if (dm > *dev_mean) *dev_mean = dm;
    }
    free(idx);
    lm3_sim_free(sim);
}

/* Aligned with the grid, at two points a cell, the interior nodes' forces
 * cancel exactly (every node sees its points in mirror pairs): the sheet
 * holds to rounding. At 30 degrees they cancel only as far as the point
 * quadrature does; measured over 1 s (h = 1/16, sheet 0.5 wide):
 *   spacing      trilinear: points / mean   bspline2: points / mean
 *   h / 2        36 %    / 1.45 %           3.3 %   / 0.013 %
 *   h / 3        20.5 %  / 0.42 %           0.80 %  / 4.5e-4 %
 *   h / 4        8.3 %   / 0.069 %          0.145 % / 1.0e-5 %
 * so the B-spline at four points a cell holds every point's tension
 * within 0.5 %, and the trilinear hats hold the mean but not the points
 * (their gradients jump at the cell faces the turned rows cross): that
 * one is an expected failure, `test_sim3_membrane trilinear_points`. */
static void flat_sheets(void)
{
    static const lm_basis bases[2] = {LM_BASIS_LINEAR, LM_BASIS_BSPLINE2};
    static const char *const names[2] = {"trilinear", "bspline2"};
    for (int b = 0; b < 2; b++)
        for (int k = 0; k < 2; k++) {
            double deg = k ? 30 : 0, ppc = k ? 4 : 2, dmax, dmean, vmax, bal;
            flat_sheet(deg, bases[b], ppc, &dmax, &dmean, &vmax, &bal);
            printf("flat sheet %s at %g deg, spacing h/%g, 1 s: tension off T0 by at most "
                   "%.3g (points), %.3g (mean); speed <= %.3g m/s; momentum balance %.3g\n",
                   names[b], deg, ppc, dmax, dmean, vmax, bal);
            CHECK(dmean < 0.005);
            if (k == 0 || b == 1) CHECK(dmax < 0.005);
            CHECK(bal < 1e-15);
        }
}

/* The expected failure: the trilinear sheet at 30 degrees, every point's
 * tension (8.3 % off at h / 4, measured). */
static void trilinear_points(void)
{
    double dmax, dmean, vmax, bal;
    flat_sheet(30, LM_BASIS_LINEAR, 4, &dmax, &dmean, &vmax, &bal);
    printf("trilinear sheet at 30 deg: every point's tension off by at most %.3g\n", dmax);
    CHECK(dmax < 0.005);
}

/* The series of the header at (x, y) on [0, a]^2, terms to m, n < 400. */
static double square_series(double p, double a, double T, double x, double y)
{
    double sum = 0;
    for (int m = 1; m < 400; m += 2)
        for (int n = 1; n < 400; n += 2)
            sum += sin(m * PI * x / a) * sin(n * PI * y / a) / (m * n * (double)(m * m + n * n));
    return 16 * p * a * a / (PI * PI * PI * PI * T) * sum;
}

/* The square [0, 1]^2 at z = z0, spacing h / 2, pre-strain 1 %, pressure
 * p, damped, 1.5 s: every point's deflection against the series at its
 * own (x, y); returns the largest error over w_c, the centre's. */
static double square_pressure(lm_basis basis, double h, double *wc_out)
{
    const double dt = 1e-3, e0 = 0.01, pr = 0.6, z0 = 0.13;
    double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 0.25};
    lm3_sim *sim = make_sim(lo, hi, h, dt, basis, LM_BC_FIXED);
    CHECK(sim != NULL);
    if (!sim) return INFINITY;
    double o[3] = {0, 0, z0}, u[3] = {1, 0, 0}, v[3] = {0, 1, 0};
    lm3_msample smp;
    char err[256];
    CHECK(lm3_sample_rect3(o, u, v, h / 2, &smp, err, sizeof err) == 0);
    lm3_mdef def;
    lm3_mdef_default(&def);
    def.mat = sheet_material();
    def.initial_strain = e0;
    def.pressure = pr;
    def.damping = 20;   /* the fundamental (16.8 rad/s) at 0.6 of critical */
    CHECK(lm3_membrane_add(sim, &def, &smp) == 0);
    const double T = def.mat.E * def.mat.thickness * e0 / (1 - def.mat.nu);
    const double wc = square_series(pr, 1, T, 0.5, 0.5);
    for (int n = 0; n < 1500; n++)
        if (lm3_step(sim) != LM_OK) {
            fprintf(stderr, "%s\n", sim->err);
            CHECK(0);
            break;
        }
    const lm3_mpoints *p = &sim->mem->p;
    double worst = 0, vmax = 0;
    for (size_t q = 0; q < p->n; q++) {
        double w = p->x[2][q] - z0, x = smp.x[0][q], y = smp.x[1][q];
        double e = fabs(w - square_series(pr, 1, T, x, y)) / wc;
        if (e > worst) worst = e;
        double sp = sqrt(p->v[0][q] * p->v[0][q] + p->v[1][q] * p->v[1][q] +
                         p->v[2][q] * p->v[2][q]);
        if (sp > vmax) vmax = sp;
    }
    printf("square under pressure, %s, h = 1/%g: w_c = %.6g (series), every point within "
           "%.3g of w_c; speed left %.2g m/s\n", basis == LM_BASIS_LINEAR ? "trilinear" : "bspline2",
           1 / h, wc, worst, vmax);
    *wc_out = wc;
    lm3_msample_free(&smp);
    lm3_sim_free(sim);
    return worst;
}

static void squares(void)
{
    double wc;
    /* the series itself: w_c = 0.07367 p a^2 / T (Timoshenko & Woinowsky-
     * Krieger's membrane analogy of the torsion of a square bar) */
    CHECK_NEAR(square_series(1, 1, 1, 0.5, 0.5), 0.07367, 5e-5);
    double e1 = square_pressure(LM_BASIS_LINEAR, 1.0 / 16, &wc);
    double e2 = square_pressure(LM_BASIS_BSPLINE2, 1.0 / 16, &wc);
    CHECK(e1 < 0.02);
    CHECK(e2 < 0.02);
}

/* The balloon without gas: a sphere of radius r0 = 0.3 with pressure p on
 * its points, damped, settles where 2 T / r = p. With T = E t e / (1 - nu)
 * at the logarithmic strain e = ln(r / r0), that radius solves
 * ln(r / r0) = p r (1 - nu) / (2 E t) (by fixed-point iteration below).
 * Returns the largest |T / (p r / 2) - 1| over the points at the end, r
 * each point's own distance from the centre; the mean radius's error
 * against the closed form in *rerr. If nrm_deg is given, the largest
 * angle (degrees) between the construction's normals, trilinear [0] and
 * triquadratic [1], and the radial direction, over the run's samples. */
static double balloon(lm_basis basis, lm3_mnormals normals, double ppc, int steps,
                      double *rerr, double *rms_out, double nrm_deg[2])
{
    const double h = 0.05, dt = 5e-4, r0 = 0.3, pr = 100;
    double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1}, c[3] = {0.5, 0.5, 0.5};
    lm3_sim *sim = make_sim(lo, hi, h, dt, basis, LM_BC_FIXED);
    CHECK(sim != NULL);
    if (!sim) return INFINITY;
    lm3_msample smp;
    char err[256];
    CHECK(lm3_sample_sphere(c, r0, h / ppc, &smp, err, sizeof err) == 0);
    lm3_mdef def;
    lm3_mdef_default(&def);
    def.mat = sheet_material();
    def.pressure = pr;
    def.damping = 200;   /* the breathing mode (176 rad/s) at 0.57 of critical */
    def.normals = normals;
    CHECK(lm3_membrane_add(sim, &def, &smp) == 0);
    lm3_msample_free(&smp);
    const double Et = def.mat.E * def.mat.thickness, nu = def.mat.nu;
    double req = r0;
    for (int k = 0; k < 100; k++) req = r0 * exp(pr * req * (1 - nu) / (2 * Et));
    const lm3_mpoints *p = &sim->mem->p;
    size_t n = p->n;
    double *nl[3], *nq[3];
    for (int a = 0; a < 3; a++) {
        nl[a] = malloc(n * sizeof(double));
        nq[a] = malloc(n * sizeof(double));
    }
    if (nrm_deg) nrm_deg[0] = nrm_deg[1] = 0;
    for (int s = 0; s <= steps; s++) {
        if (nrm_deg && s % 100 == 0) {
            /* the construction from the points alone, against radial */
            CHECK(lm3_membrane_construction_normals(sim, 0, LM3_MN_LINEAR, nl, NULL) == 0);
            CHECK(lm3_membrane_construction_normals(sim, 0, LM3_MN_QUADRATIC, nq, NULL) == 0);
            for (size_t q = 0; q < n; q++) {
                double x[3] = {p->x[0][q] - c[0], p->x[1][q] - c[1], p->x[2][q] - c[2]};
                double r = sqrt(dot(x, x));
                double a1[3] = {nl[0][q], nl[1][q], nl[2][q]}, a2[3] = {nq[0][q], nq[1][q], nq[2][q]};
                double d1 = acos(fmin(1, dot(a1, x) / r)) * 180 / PI;
                double d2 = acos(fmin(1, dot(a2, x) / r)) * 180 / PI;
                if (d1 > nrm_deg[0]) nrm_deg[0] = d1;
                if (d2 > nrm_deg[1]) nrm_deg[1] = d2;
            }
        }
        if (s == steps) break;
        if (lm3_step(sim) != LM_OK) {
            fprintf(stderr, "%s\n", sim->err);
            CHECK(0);
            break;
        }
    }
    double worst = 0, rm = 0, Tm = 0, rms = 0;
    for (size_t q = 0; q < n; q++) {
        double x[3] = {p->x[0][q] - c[0], p->x[1][q] - c[1], p->x[2][q] - c[2]};
        double r = sqrt(dot(x, x)), T = lm3_membrane_tension(sim, q);
        double e = fabs(T / (pr * r / 2) - 1);
        if (e > worst) worst = e;
        rms += e * e / n;
        rm += r / n;
        Tm += T / n;
    }
    *rms_out = sqrt(rms);
    *rerr = fabs(rm / req - 1);
    printf("balloon %s, spacing h/%g, normals %d: r = %.6g (closed form %.6g, %.2g off); "
           "mean T / (p r / 2) - 1 = %.3g, every point's within %.3g (rms %.3g)\n",
           basis == LM_BASIS_LINEAR ? "trilinear" : "bspline2", ppc, (int)normals, rm, req,
           *rerr, Tm / (pr * rm / 2) - 1, worst, *rms_out);
    worst = fabs(Tm / (pr * rm / 2) - 1);
    for (int a = 0; a < 3; a++) {
        free(nl[a]);
        free(nq[a]);
    }
    lm3_sim_free(sim);
    return worst;   /* the mean tension's error */
}

/* The balloon's numbers, measured at 0.15 s = 300 steps (mean T / (p r /
 * 2) - 1; every point's largest and rms; the radius against the closed
 * form; the construction's normals against radial, triquadratic /
 * trilinear fit, the worst of the samples every 100 steps):
 *   trilinear grid, h/2:  -0.95 %; 125 %, 33 %; 0.23 %
 *   bspline2 grid, h/3:   -8.5e-4 %; 3.3 %, 0.62 %; 1.3e-4 %; 0.060 / 87 deg
 * (since MUSL moves the points with the re-mapped velocity; before it
 * -0.94 %; 130 %, 34 %; 0.24 % and 1.1e-4 % for the radius) and at 0.3 s
 * (600 steps, measured before that change):
 *   trilinear grid, h/2:  -0.70 %; 155 %, 37 %; 0.33 %; 3.6 / 89 deg
 *   trilinear grid, h/4:  -0.065 %; 138 %, 12.5 %; 0.028 %; 0.65 / 90 deg
 *   bspline2 grid, h/2:   -2e-3 %; 9.3 %, 2.0 %; 1e-3 %; 0.056 / 83 deg
 * The mean tension and the radius hold under both bases; single points
 * under the trilinear hats carry a stress pattern their nodes do not feel
 * (more points than a cell's 8 nodes can constrain), the B-spline's wider
 * stencils much less. The trilinear fit of the construction ([N] Fig 5) is
 * never within 2 degrees (its phi = 1 surface in a cell is curved where
 * the points are nearly flat: [N] Fig 7 in 2D): an expected failure,
 * `test_sim3_membrane normals_linear`. */
static void balloons(void)
{
    double rerr, rms, deg[2];
    double e1 = balloon(LM_BASIS_LINEAR, LM3_MN_CONNECTIVITY, 2, 300, &rerr, &rms, NULL);
    CHECK(e1 < 0.02);
    CHECK(rerr < 0.02);
    double e2 = balloon(LM_BASIS_BSPLINE2, LM3_MN_CONNECTIVITY, 3, 300, &rerr, &rms, deg);
    printf("running sphere (bspline2 grid): construction normals within %.3g deg "
           "(trilinear fit), %.3g deg (triquadratic) of radial\n", deg[0], deg[1]);
    CHECK(e2 < 0.02);
    CHECK(rms < 0.02);
    CHECK(rerr < 0.02);
    CHECK(deg[1] < 2);
    /* the triquadratic construction deciding the tangent planes (spacing
     * h/2, 0.1 s: the construction every step is the cost) */
    double e3 = balloon(LM_BASIS_BSPLINE2, LM3_MN_QUADRATIC, 2, 200, &rerr, &rms, NULL);
    CHECK(e3 < 0.02);
    CHECK(rerr < 0.02);
}

/* The expected failure: the trilinear fit's normals on the running sphere. */
static void normals_linear(void)
{
    double rerr, rms, deg[2];
    balloon(LM_BASIS_BSPLINE2, LM3_MN_CONNECTIVITY, 3, 300, &rerr, &rms, deg);
    printf("trilinear fit's normals within %.3g deg of radial\n", deg[0]);
    CHECK(deg[0] < 2);
}

/* ---- the point update against closed forms ------------------------------
 * A sheet in the plane z = 0.5 (t1 = x, t2 = y), the grid's strain
 * velocity set to a linear field v = L (x - c) at every node (both bases
 * reproduce it exactly: sum G (x) x_i = I), one update: D_ab = t_a . D t_b,
 * the frame carried by L, the law in the frame. */
static lm3_sim *update_sim(lm_basis basis, const lm_material *mat, double e0)
{
    double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    lm3_sim *sim = make_sim(lo, hi, 0.1, 1e-3, basis, LM_BC_FREE);
    if (!sim) return NULL;
    double o[3] = {0.3, 0.3, 0.5}, u[3] = {0.4, 0, 0}, v[3] = {0, 0.4, 0};
    lm3_msample smp;
    char err[256];
    CHECK(lm3_sample_rect3(o, u, v, 0.05, &smp, err, sizeof err) == 0);
    lm3_mdef def;
    lm3_mdef_default(&def);
    def.mat = *mat;
    def.initial_strain = e0;
    CHECK(lm3_membrane_add(sim, &def, &smp) == 0);
    lm3_msample_free(&smp);
    lm3_membrane_p2g(sim);   /* places the points */
    return sim;
}

static void set_field(lm3_sim *sim, const double L[3][3])
{
    lm3_grid *g = &sim->grid;
    for (long k = 0; k < g->s[2]; k++)
        for (long j = 0; j < g->s[1]; j++)
            for (long i = 0; i < g->s[0]; i++) {
                long n = (k * g->s[1] + j) * g->s[0] + i;
                double x[3] = {(i - g->pad) * g->h - 0.5, (j - g->pad) * g->h - 0.5,
                               (k - g->pad) * g->h - 0.5};
                for (int a = 0; a < 3; a++)
                    g->v[a][n] = L[a][0] * x[0] + L[a][1] * x[1] + L[a][2] * x[2];
            }
}

static void point_update(void)
{
    lm_material mat = sheet_material();
    const double E = mat.E, nu = mat.nu, Ep = E / (1 - nu * nu), dt = 1e-3;
    for (int b = 0; b < 2; b++) {
        lm_basis basis = b ? LM_BASIS_BSPLINE2 : LM_BASIS_LINEAR;
        /* a stretch along a = (cos 25, sin 25, 0) and one across the sheet */
        double th = 25 * PI / 180, ca = cos(th), sa = sin(th), r = 2.0, rz = 5.0;
        double L[3][3] = {{r * ca * ca, r * ca * sa, 0}, {r * ca * sa, r * sa * sa, 0},
                          {0, 0, rz}};
        lm3_sim *sim = update_sim(basis, &mat, 0.01);
        CHECK(sim != NULL);
        if (!sim) return;
        set_field(sim, L);
        CHECK(lm3_membrane_update(sim) == LM_OK);
        const lm3_mpoints *p = &sim->mem->p;
        double worst = 0;
        for (size_t q = 0; q < p->n; q++) {
            double e11 = 0.01 + dt * r * ca * ca, e22 = 0.01 + dt * r * sa * sa;
            double e12 = dt * r * ca * sa;   /* w = -D12 times e11 - e22 = 0 at the start */
            double d[6] = {p->e[0][q] - e11, p->e[1][q] - e22, p->e[2][q] - e12,
                           p->s[0][q] - Ep * (e11 + nu * e22), p->s[1][q] - Ep * (e22 + nu * e11),
                           p->s[2][q] - E / (1 + nu) * e12};
            for (int k = 0; k < 3; k++) worst = fmax(worst, fabs(d[k]));
            for (int k = 3; k < 6; k++) worst = fmax(worst, fabs(d[k]) / E);
            /* t1 carried to (1 + dt L) x, normalised; the normal stays z */
            double t1[3] = {1 + dt * L[0][0], dt * L[1][0], 0}, l = hypot(t1[0], t1[1]);
            worst = fmax(worst, fabs(p->t1[0][q] - t1[0] / l) + fabs(p->t1[1][q] - t1[1] / l));
            worst = fmax(worst, fabs(p->nrm[2][q] - 1));
        }
        printf("point update (%s): stretch at 25 deg and across, one step: strain, stress / E "
               "and frame within %.2g of the closed forms\n", b ? "bspline2" : "trilinear",
               worst);
        CHECK(worst < 1e-12);
        lm3_sim_free(sim);

        /* a rigid spin about the normal and about an in-plane axis: no strain */
        double w1 = 3, w2 = 2;
        double S[3][3] = {{0, -w1, 0}, {w1, 0, -w2}, {0, w2, 0}};
        sim = update_sim(basis, &mat, 0.01);
        set_field(sim, S);
        for (int n = 0; n < 100; n++) CHECK(lm3_membrane_update(sim) == LM_OK);
        p = &sim->mem->p;
        worst = 0;
        for (size_t q = 0; q < p->n; q++)
            worst = fmax(worst, fmax(fabs(p->e[0][q] - 0.01),
                                     fmax(fabs(p->e[1][q] - 0.01), fabs(p->e[2][q]))));
        printf("point update (%s): 100 steps of a rigid spin, strain within %.2g of its "
               "start\n", b ? "bspline2" : "trilinear", worst);
        CHECK(worst < 1e-15);
        lm3_sim_free(sim);
    }
    /* the one-way law: wrinkled across (taut along the larger strain,
     * uniaxial: s = E e, the other 0) and slack (both strains < 0: none) */
    mat.one_way = 1;
    lm3_sim *sim = update_sim(LM_BASIS_BSPLINE2, &mat, 0);
    double U[3][3] = {{10, 0, 0}, {0, -5, 0}, {0, 0, 0}};
    set_field(sim, U);
    CHECK(lm3_membrane_update(sim) == LM_OK);
    const lm3_mpoints *p = &sim->mem->p;
    CHECK_NEAR(p->s[0][0], E * dt * 10, 1e-9 * E);
    CHECK_NEAR(p->s[1][0], 0, 1e-9 * E);
    lm3_sim_free(sim);
    sim = update_sim(LM_BASIS_BSPLINE2, &mat, -0.02);
    CHECK(sim->mem->p.s[0][0] == 0 && sim->mem->p.s[1][0] == 0);
    CHECK(sim->mem->p.m[0] > 0);
    /* a slack sheet's point stands for more material: A exp(+0.04) */
    CHECK_NEAR(sim->mem->p.A0[0], 0.05 * 0.05 * exp(0.04), 1e-15);
    lm3_sim_free(sim);
}

/* Refusals, each naming what it refused. */
static void refusals(void)
{
    double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1}, c[3] = {0.5, 0.5, 0.5};
    lm3_sim *sim = make_sim(lo, hi, 0.1, 5e-3, LM_BASIS_BSPLINE2, LM_BC_FIXED);
    lm3_msample smp;
    char err[256];
    CHECK(lm3_sample_sphere(c, 0.6, 0.05, &smp, err, sizeof err) == 0);
    lm3_mdef def;
    lm3_mdef_default(&def);
    def.mat = sheet_material();
    CHECK(lm3_membrane_add(sim, &def, &smp) == -1);   /* r = 0.6 leaves the unit box */
    CHECK(strstr(sim->err, "membrane 1 leaves the domain: point") != NULL);
    lm3_msample_free(&smp);
    CHECK(lm3_sample_sphere(c, 0.3, 0.05, &smp, err, sizeof err) == 0);
    def.mat.thickness = -1;
    CHECK(lm3_membrane_add(sim, &def, &smp) == -1);
    CHECK(strstr(sim->err, "membrane 1: ") && strstr(sim->err, "thickness"));
    def.mat = sheet_material();
    def.damping = 300;   /* c dt = 1.5 */
    CHECK(lm3_membrane_add(sim, &def, &smp) == -1);
    CHECK(strstr(sim->err, "damping = 300") != NULL);
    def.damping = 0;
    def.initial_strain = 6;
    CHECK(lm3_membrane_add(sim, &def, &smp) == -1);
    CHECK(strstr(sim->err, "initial_strain = 6") != NULL);
    def.initial_strain = 0;
    CHECK(lm3_membrane_add(sim, &def, &smp) == 0);
    size_t idx[2] = {3, 100000};
    CHECK(lm3_membrane_pin(sim, 0, idx, 2) == -1);
    CHECK(strstr(sim->err, "point 100001 cannot be pinned") != NULL);
    CHECK(lm3_membrane_pin(sim, 0, idx, 1) == 0);
    CHECK(lm3_membrane_pin(sim, 0, idx, 1) == -1);
    CHECK(strstr(sim->err, "point 4 of membrane 1 is pinned already") != NULL);
    /* the membrane's wave sqrt(E / ((1 - nu^2) rho)) = 33.2 m/s enters the
     * Courant check: dt c / h = 1.66 is refused before the first step */
    CHECK(lm3_step(sim) == LM_ERR_INPUT);
    CHECK(strstr(sim->err, "Courant number") != NULL);
    double cm;
    CHECK_NEAR(lm3_courant(sim, &cm), 5e-3 * sqrt(1e6 / (0.91 * 1000)) / 0.1, 1e-12);
    lm3_msample_free(&smp);
    lm3_sim_free(sim);
}

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "normals_linear") == 0) {
        normals_linear();
        return CHECK_DONE();
    }
    if (argc > 1 && strcmp(argv[1], "trilinear_points") == 0) {
        trilinear_points();
        return CHECK_DONE();
    }
    samplers();
    refusals();
    point_update();
    flat_sheets();
    squares();
    balloons();
    return CHECK_DONE();
}
