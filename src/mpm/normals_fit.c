/* normals_fit.c - one element: assemble [S]{phi} = {phi0}, solve, evaluate.
 *
 * Steps, as the paper builds them:
 *  1. logical coordinates of every point in the element ([N] eq 4);
 *  2. one row per membrane point, S_pI = S(x_p - x_I), phi0_p = 1
 *     ([N] eq 10);
 *  3. one random point q in the element with phi0 = 0, so that phi = 1
 *     everywhere is no longer a solution ([N] §4, "One Dimension");
 *  4. optionally a second random point with phi0 = 2, so that 1 is not a
 *     maximum of phi ([N] §8);
 *  5. least squares by QR (minimum norm when underdetermined) or by the
 *     normal equations ([N] eq 13, §6); optionally (not the paper's) with
 *     weak curvature rows (normals_smooth.c) and a random point kept clear
 *     of the membrane, for the centred elements of normals_centred.c;
 *  6. n_p = grad phi(x_p) / |grad phi(x_p)| ([N] eq 11, 16). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "normals.h"
#include "normals_work.h"
#include "simd2.h"
#include "util.h"

/* A random point closer than this (relative to the element) to a membrane
 * point would make the system inconsistent: it is drawn again. */
#define RANDOM_CLEARANCE 1e-6
/* Points closer than this (relative) are the same point. */
#define COINCIDENT_TOL 1e-12
/* Allowed outside the element, relative to its size (rounding). */
#define OUTSIDE_TOL 1e-9
/* Draws of the random point when cond_limit asks for redraws. */
#define MAX_DRAWS 100

void lm_nfit_opts_default(lm_nfit_opts *o)
{
    memset(o, 0, sizeof *o);
    o->basis = LM_NB_LINEAR;
    o->solver = LM_NS_QR;
    o->seed = 1;
}

void lm_nfit_opts_of(lm_nfit_opts *fo, const lm_nopts *o, uint64_t key)
{
    lm_nfit_opts_default(fo);
    fo->solver = o->solver;
    fo->phi2 = o->phi2;
    fo->cond_limit = o->cond_limit;
    fo->smooth = o->smooth;
    fo->clearance = o->clearance;
    fo->skip_cond = o->skip_cond;
    fo->seed = lm_nrng_mix(o->seed, key);
}

/* "(x, y)" or "(x, y, z)" */
static const char *fmt_point(char *buf, size_t len, int dim, const double p[3])
{
    if (dim == 3)
        snprintf(buf, len, "(%g, %g, %g)", p[0], p[1], p[2]);
    else
        snprintf(buf, len, "(%g, %g)", p[0], p[1]);
    return buf;
}

static void point_of(const double *const x[3], int dim, size_t i, double p[3])
{
    for (int a = 0; a < 3; a++)
        p[a] = a < dim ? x[a][i] : 0.0;
}

static lm_nerr check_box(const lm_nbox *b, char *err, size_t errlen)
{
    if (!b || (b->dim != 2 && b->dim != 3)) {
        lu_err(err, errlen, "the element must be 2D or 3D");
        return LM_NERR_INPUT;
    }
    for (int a = 0; a < b->dim; a++)
        if (!isfinite(b->lo[a]) || !isfinite(b->hi[a]) || !(b->hi[a] > b->lo[a])) {
            lu_err(err, errlen, "the element is empty or not finite "
                   "(axis %d: [%g, %g])", a, b->lo[a], b->hi[a]);
            return LM_NERR_INPUT;
        }
    return LM_NERR_NONE;
}

/* Step 1 checks: every point finite and inside the element. */
static lm_nerr check_points(const lm_nbox *b, const double *const x[3],
                            const size_t *idx, size_t k, char *err, size_t errlen)
{
    /* the bounds with their allowance, worked out once (the same values
     * for every point) */
    double lo[3], hi[3];
    for (int a = 0; a < b->dim; a++) {
        double t = OUTSIDE_TOL * (b->hi[a] - b->lo[a]);
        lo[a] = b->lo[a] - t;
        hi[a] = b->hi[a] + t;
    }
    for (size_t i = 0; i < k; i++) {
        size_t q = idx ? idx[i] : i;
        double p[3];
        point_of(x, b->dim, q, p);
        char buf[96];
        for (int a = 0; a < b->dim; a++) {
            if (!isfinite(p[a])) {
                lu_err(err, errlen, "point %zu %s is not finite", q + 1,
                       fmt_point(buf, sizeof buf, b->dim, p));
                return LM_NERR_NOT_FINITE;
            }
        }
        for (int a = 0; a < b->dim; a++) {
            if (p[a] < lo[a] || p[a] > hi[a]) {
                if (err && errlen) {
                    char from[96], to[96];
                    snprintf(err, errlen, "point %zu %s lies outside the element "
                             "from %s to %s", q + 1,
                             fmt_point(buf, sizeof buf, b->dim, p),
                             fmt_point(from, sizeof from, b->dim, b->lo),
                             fmt_point(to, sizeof to, b->dim, b->hi));
                }
                return LM_NERR_OUTSIDE;
            }
        }
    }
    return LM_NERR_NONE;
}

/* Two points are the same when |p_a - q_a| <= COINCIDENT_TOL (hi_a - lo_a)
 * on every axis; the tolerances are worked out once and the coordinates
 * read in place (this runs over every pair of an element's points each
 * step). */
int lm_npoints_unique(const lm_nbox *b, const double *const x[3],
                        const size_t *idx, size_t k)
{
    double tol[3] = {0, 0, 0};
    for (int a = 0; a < b->dim; a++)
        tol[a] = COINCIDENT_TOL * (b->hi[a] - b->lo[a]);
    const double *x0 = x[0], *x1 = x[1], *x2 = b->dim == 3 ? x[2] : NULL;
    int u = 0;
    if (idx && !x2) {
        /* the centred elements' case (2D, an index list), written apart so
         * that the loop tests neither: the same comparisons in the same
         * order */
        for (size_t i = 0; i < k; i++) {
            double p0 = x0[idx[i]], p1 = x1[idx[i]];
            size_t j = 0;
            while (j < i && (fabs(p0 - x0[idx[j]]) > tol[0] ||
                             fabs(p1 - x1[idx[j]]) > tol[1]))
                j++;
            u += j == i;
        }
        return u;
    }
    for (size_t i = 0; i < k; i++) {
        size_t pi = idx ? idx[i] : i;
        double p0 = x0[pi], p1 = x1[pi], p2 = x2 ? x2[pi] : 0.0;
        int seen = 0;
        for (size_t j = 0; j < i; j++) {
            size_t pj = idx ? idx[j] : j;
            if (fabs(p0 - x0[pj]) > tol[0] || fabs(p1 - x1[pj]) > tol[1] ||
                (x2 && fabs(p2 - x2[pj]) > tol[2]))
                continue;
            seen = 1;
            break;
        }
        u += !seen;
    }
    return u;
}

/* Steps 3-4: a uniform point in the element, clear of the membrane points
 * (by 1e-6 of the element per axis). With clearance > 0 also at least that
 * far (logical units) from every point; when no draw of MAX_DRAWS is, the
 * farthest one. A random point right beside the membrane asks phi to drop
 * from 1 to 0 within a hair, which the fit can only do by bending its
 * isosurface (measured: up to 11 degrees in the dynamic circle). */
static void draw_point(const lm_nbox *b, lm_nrng *rng, const double *const x[3],
                       const size_t *idx, size_t k, double clearance, double q[3])
{
    double best[3] = {0, 0, 0}, bestd = -1;
    /* the element's sizes and the clearance test's tolerances (|p_a - q_a|
     * <= RANDOM_CLEARANCE (hi_a - lo_a) on every axis: the same point),
     * worked out once */
    double size[3] = {1, 1, 1}, tol[3] = {0, 0, 0};
    for (int a = 0; a < b->dim; a++) {
        size[a] = b->hi[a] - b->lo[a];
        tol[a] = RANDOM_CLEARANCE * size[a];
    }
    for (int attempt = 0; attempt < MAX_DRAWS; attempt++) {
        double xi[3] = {0, 0, 0};
        for (int a = 0; a < b->dim; a++)
            xi[a] = lm_nrng_uniform(rng);
        lm_nbox_to_world(b, xi, q);
        int clear = 1;
        double dmin = INFINITY;
        if (b->dim == 2 && clearance > 0) {
            /* the general loop's tests and sums, the two axes side by
             * side (one division for both) */
            lm_v2d qq = {q[0], q[1]}, sz = {size[0], size[1]};
            for (size_t i = 0; i < k && clear; i++) {
                size_t pi = idx ? idx[i] : i;
                lm_v2d e = (lm_v2d){x[0][pi], x[1][pi]} - qq, t = e / sz;
                clear = fabs(e[0]) > tol[0] || fabs(e[1]) > tol[1];
                double d = t[0] * t[0] + t[1] * t[1];
                dmin = d < dmin ? d : dmin;
            }
        } else {
            for (size_t i = 0; i < k && clear; i++) {
                size_t pi = idx ? idx[i] : i;
                int near = 1;
                double d = 0;
                for (int a = 0; a < b->dim; a++) {
                    double e = x[a][pi] - q[a];
                    near &= !(fabs(e) > tol[a]);
                    if (clearance > 0) {
                        double t = e / size[a];
                        d += t * t;
                    }
                }
                clear = !near;
                if (clearance > 0)
                    dmin = d < dmin ? d : dmin;
            }
        }
        if (!(clearance > 0)) {
            if (clear)
                return;
            continue;
        }
        if (clear && dmin >= clearance * clearance)
            return;
        if (clear && dmin > bestd) {
            bestd = dmin;
            memcpy(best, q, sizeof best);
        }
    }
    if (clearance > 0 && bestd >= 0)
        memcpy(q, best, sizeof best);
}

/* Step 2: one row of [S] (the basis writes its n values straight in). */
static void row(const lm_nfit *f, const double p[3], double *s)
{
    double xi[3];
    lm_nbox_to_logical(&f->box, p, xi);
    lm_nbasis_eval(f->basis, f->dim, xi, s, NULL);
}

/* ---- step 5 by the normal equations (LM_NS_CHOLESKY) ----------------------
 *
 * Why. The per-step normals of a simulation fit 30-40 elements a step, each
 * a 2D quadratic (9 unknowns) to about 12 points, the random point and the
 * 10 curvature rows; the pivoted QR of that 23 x 9 system was half of the
 * construction's cost (docs/performance.md). The fit's T = S^T S ([N] eq
 * 12-13) is formed here straight from the points, without [S]:
 *  - a row is a tensor product, S_pI = b_i(xi_p) b_j(eta_p) for I = i + 3 j
 *    ([N] eq 7, §5), so T_IJ = sum_p (b_i b_k)(xi_p) (b_j b_l)(eta_p) with
 *    J = k + 3 l: 36 distinct sums (6 products per axis, i <= k and
 *    j <= l) instead of 45 of the 81 entries from the 9-wide rows;
 *  - the right-hand side [S]^T{phi0} has phi0 = 1 at the membrane points
 *    and 0 at the random point and on the curvature rows ([N] eq 10, §4):
 *    the sum of the points' rows;
 *  - the curvature rows (normals_smooth.c) are w C with C fixed by the
 *    element's aspect, so they add w^2 C^T C; C^T C is kept in the
 *    scratch per aspect (the elements of a grid share one).
 * T is then factored, T = L D L^T (Cholesky without the square roots),
 * and L D L^T phi = S^T phi0 solved.
 *
 * Accuracy. The normal equations square the condition number ([N] §6 and
 * Fig 9: the paper's 19 degree error by the normal equations came from a
 * singular T). Here the curvature rows and the random point make T
 * regular; a pivot below CHOL_PIVOT_TOL of its diagonal says it is not
 * (cond(T) of order 1e10: ten of sixteen digits gone), and that fit is
 * solved by the pivoted QR on [S] as before. Measured against the QR on
 * the dog-bone, every normal of every step (docs/performance.md). */

/* Steps 2-5 for the current random point(s); smooth > 0 appends the
 * curvature rows (normals_smooth.c) with weight smooth * sqrt(rows), so
 * that their share does not fall as points are added. */
static lm_nerr assemble_solve(lm_nfit *f, const double *const x[3],
                              const size_t *idx, size_t k, lm_nfit_scratch *sc,
                              double smooth, int want_cond)
{
    double *S = sc->S, *rhs = sc->rhs;
    int n = f->n;
    if (f->solver == LM_NS_CHOLESKY && f->basis == LM_NB_QUADRATIC && f->dim == 2 &&
        !f->has_q2 && !want_cond) {
        if (lm_nfit_quadratic_2d_ne(f, x, idx, k, sc, smooth) == 0)
            return LM_NERR_NONE;
        sc->fallbacks++;
    }
    for (size_t i = 0; i < k; i++) {
        double p[3];
        point_of(x, f->dim, idx ? idx[i] : i, p);
        row(f, p, S + i * (size_t)n);
        rhs[i] = 1.0;
    }
    row(f, f->q, S + k * (size_t)n);
    rhs[k] = 0.0;
    if (f->has_q2) {
        row(f, f->q2, S + (k + 1) * (size_t)n);
        rhs[k + 1] = 2.0;
    }
    int m = f->rows;
    f->smooth_rows = lm_nsmooth_rows(f->basis, &f->box, smooth * sqrt((double)m),
                                     S + (size_t)m * n);
    for (int r = 0; r < f->smooth_rows; r++)
        rhs[m + r] = 0.0;
    m += f->smooth_rows;
    if (f->solver == LM_NS_NORMAL)
        return lm_lsq_normal(m, n, S, rhs, f->phi, &f->info);
    return lm_lsq_qr_ws(m, n, S, rhs, f->phi, &f->info, want_cond, sc->cols);
}

lm_nerr lm_nfit_element(const lm_nbox *box, const double *const x[3],
                        const size_t *idx, size_t k, const lm_nfit_opts *o,
                        lm_nfit *fit, char *err, size_t errlen)
{
    /* one fit's scratch, for callers without a workspace */
    lm_nfit_scratch sc;
    sc.rows = k + 2 + (o->smooth > 0 ? LM_NSMOOTH_MAXROWS : 0);
    sc.S = malloc(sizeof(double) * sc.rows * LM_NMAX);
    sc.rhs = malloc(sizeof(double) * sc.rows);
    sc.cols = malloc(sizeof(double) * LM_QR_WORK(sc.rows, LM_NMAX));
    sc.smooth = NULL;
    sc.fallbacks = 0;
    lm_nerr e;
    if (!sc.S || !sc.rhs || !sc.cols) {
        lu_err(err, errlen, "out of memory (%zu x %d system)", sc.rows, LM_NMAX);
        e = LM_NERR_MEMORY;
    } else {
        e = lm_nfit_element_ws(box, x, idx, k, o, 0, -1, fit, &sc, err, errlen);
    }
    free(sc.S);
    free(sc.rhs);
    free(sc.cols);
    return e;
}

lm_nerr lm_nfit_element_ws(const lm_nbox *box, const double *const x[3],
                           const size_t *idx, size_t k, const lm_nfit_opts *o,
                           int lean, int nunique, lm_nfit *fit,
                           lm_nfit_scratch *sc, char *err, size_t errlen)
{
    lm_nerr e = check_box(box, err, errlen);
    if (e)
        return e;
    if (o->basis != LM_NB_LINEAR && o->basis != LM_NB_QUADRATIC) {
        lu_err(err, errlen, "an element is fitted with the linear or the "
               "quadratic basis");
        return LM_NERR_INPUT;
    }
    if (k == 0) {
        lu_err(err, errlen, "no membrane points in the element");
        return LM_NERR_TOO_FEW;
    }
    if (!(lean & LM_NFIT_INSIDE) && (e = check_points(box, x, idx, k, err, errlen)))
        return e;
    memset(fit, 0, sizeof *fit);
    fit->dim = box->dim;
    fit->basis = o->basis;
    fit->box = *box;
    fit->n = lm_nbasis_count(o->basis, box->dim);
    fit->solver = o->solver;
    fit->npoints = (int)k;
    fit->nunique = nunique >= 0 ? nunique : lm_npoints_unique(box, x, idx, k);
    int need = o->min_points > 0 ? o->min_points : box->dim;
    if (fit->nunique < need) {
        lu_err(err, errlen, "only %d distinct membrane point%s in the element: "
               "at least %d are needed for a normal in %dD", fit->nunique,
               fit->nunique == 1 ? "" : "s", need, box->dim);
        return LM_NERR_TOO_FEW;
    }
    if (fit->nunique < fit->npoints)
        fit->flags |= LM_NF_COINCIDENT;
    fit->has_q2 = o->phi2 != LM_PHI2_NONE || o->phi2_given;
    fit->rows = (int)k + 1 + fit->has_q2;

    int extra = o->smooth > 0 ? LM_NSMOOTH_MAXROWS : 0;
    if ((size_t)(fit->rows + extra) > sc->rows) {
        lu_err(err, errlen, "a %d x %d system in scratch for %zu rows", fit->rows + extra,
               fit->n, sc->rows);
        return LM_NERR_MEMORY;
    }
    lm_nrng rng;
    lm_nrng_seed(&rng, o->seed);
    for (;;) {
        if (o->random_given)
            memcpy(fit->q, o->random_point, sizeof fit->q);
        else
            draw_point(box, &rng, x, idx, k, o->clearance, fit->q);
        if (o->phi2_given)
            memcpy(fit->q2, o->phi2_point, sizeof fit->q2);
        else if (o->phi2 == LM_PHI2_RANDOM)
            draw_point(box, &rng, x, idx, k, o->clearance, fit->q2);
        fit->draws++;
        e = assemble_solve(fit, x, idx, k, sc, o->smooth, !o->skip_cond);
        if (e || o->random_given || !(o->cond_limit > 0) ||
            !(fit->info.cond_t > o->cond_limit) || fit->draws >= MAX_DRAWS)
            break;
    }
    if (e == LM_NERR_SINGULAR) {
        lu_err(err, errlen, "the normal equations are singular (a zero pivot): "
               "%d points, %d unknowns; use the QR solver", (int)k, fit->n);
        return e;
    }
    if (e) {
        lu_err(err, errlen, "out of memory solving a %d x %d system", fit->rows,
               fit->n);
        return e;
    }
    if (fit->draws > 1)
        fit->flags |= LM_NF_REDRAWN;
    if (fit->info.rank < fit->n)
        fit->flags |= LM_NF_UNDERDETERMINED;
    for (size_t i = 0; i < k && !(lean & LM_NFIT_LEAN); i++) {
        double p[3];
        point_of(x, fit->dim, idx ? idx[i] : i, p);
        double r = fabs(lm_nfit_phi(fit, p) - 1.0);
        if (!(r <= fit->residual))
            fit->residual = r;
    }
    return LM_NERR_NONE;
}

double lm_nfit_phi(const lm_nfit *f, const double x[3])
{
    double xi[3], s[LM_NMAX];
    lm_nbox_to_logical(&f->box, x, xi);
    lm_nbasis_eval(f->basis, f->dim, xi, s, NULL);
    double v = 0;
    for (int I = 0; I < f->n; I++)
        v += f->phi[I] * s[I];
    return v;
}

/* grad phi in logical coordinates. */
static void grad_logical(const lm_nfit *f, const double x[3], double g[3])
{
    double xi[3], s[LM_NMAX], ds[LM_NMAX][3];
    lm_nbox_to_logical(&f->box, x, xi);
    if (f->basis == LM_NB_QUADRATIC && f->dim == 2) {
        lm_nbasis_grad_quadratic_2d(xi, f->phi, g);   /* the same sums */
        return;
    }
    lm_nbasis_eval(f->basis, f->dim, xi, s, ds);
    g[0] = g[1] = g[2] = 0.0;
    for (int I = 0; I < f->n; I++)
        for (int a = 0; a < f->dim; a++)
            g[a] += f->phi[I] * ds[I][a];
}

void lm_nfit_grad(const lm_nfit *f, const double x[3], double g[3])
{
    grad_logical(f, x, g);
    for (int a = 0; a < f->dim; a++)
        g[a] /= f->box.hi[a] - f->box.lo[a];
}

/* The three quadratic B-splines of the centres -1/2, 1/2, 3/2 and their
 * derivatives at xi in [0, 1] (lm_bspline2's pieces written out: the same
 * operations, so the same bits). */
static inline void bspline2_three_d(double xi, double v[3], double d[3])
{
    double t = xi - (0 - 0.5), e = 1.5 - t;
    v[0] = 0.5 * e * e;
    d[0] = -e;
    t = xi - (1 - 0.5);
    v[1] = 0.75 - t * t;
    d[1] = -2.0 * t;
    t = xi - (2 - 0.5);
    e = 1.5 - (-t);
    v[2] = 0.5 * e * e;
    d[2] = e;
}

/* lm_nfit_normal for the 2D quadratic fit of a point inside its element
 * (the per-step normals: 200 a step on the dog-bone), in one piece: the
 * logical coordinates, the 1D pieces of beta_2 and their slopes (as
 * lm_nbasis_grad_quadratic_2d takes them there), grad phi summed in the
 * order of I, and the checks and scalings of lm_nfit_normal - the same
 * operations in the same order, so the same bits, without the calls and
 * the general loops. The two axes go side by side (one division for xi
 * and eta, one for the two scalings, one for the two components, one
 * square root for both lengths). */
static int normal_quadratic_2d_at(const lm_nfit *f, const double x[3], double n[3])
{
    double w0 = f->box.hi[0] - f->box.lo[0], w1 = f->box.hi[1] - f->box.lo[1];
    double xi = (x[0] - f->box.lo[0]) / w0, eta = (x[1] - f->box.lo[1]) / w1;
    lm_v2d w = {w0, w1};
    if (!(xi >= 0.0 && xi <= 1.0 && eta >= 0.0 && eta <= 1.0))
        return 1;                      /* not inside: the general path */
    double v0[3], d0[3], v1[3], d1[3];
    bspline2_three_d(xi, v0, d0);
    bspline2_three_d(eta, v1, d1);
    const double *c = f->phi;
    lm_v2d gl = {0.0, 0.0};
    double scale = 1.0;
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++) {
            lm_v2d cc = {c[i + 3 * j], c[i + 3 * j]};
            gl += cc * ((lm_v2d){d0[i], v0[i]} * (lm_v2d){v1[j], d1[j]});
        }
    for (int I = 0; I < 9; I++)
        if (fabs(c[I]) > scale)
            scale = fabs(c[I]);
    lm_v2d g = gl / w;
    lm_v2d gg = g * g, ll = gl * gl;
    lm_v2d sq = {gg[0] + gg[1], ll[0] + ll[1]};
    sq = lm_v2d_sqrt(sq);
    double len = sq[0], llen = sq[1];
    n[0] = n[1] = n[2] = 0.0;
    if (!(llen > 1e-10 * scale) || !isfinite(len))
        return -1;
    lm_v2d nn = g / (lm_v2d){len, len};
    n[0] = nn[0];
    n[1] = nn[1];
    return 0;
}

int lm_nfit_normal(const lm_nfit *f, const double x[3], double n[3])
{
    if (f->basis == LM_NB_QUADRATIC && f->dim == 2) {
        int r = normal_quadratic_2d_at(f, x, n);
        if (r <= 0)
            return r;
    }
    double gl[3], scale = 1.0;
    grad_logical(f, x, gl);
    for (int I = 0; I < f->n; I++)
        if (fabs(f->phi[I]) > scale)
            scale = fabs(f->phi[I]);
    double g[3] = {0, 0, 0}, len = 0;
    for (int a = 0; a < f->dim; a++) {
        g[a] = gl[a] / (f->box.hi[a] - f->box.lo[a]);
        len += g[a] * g[a];
    }
    len = sqrt(len);
    double llen = sqrt(gl[0] * gl[0] + gl[1] * gl[1] + gl[2] * gl[2]);
    n[0] = n[1] = n[2] = 0.0;
    if (!(llen > 1e-10 * scale) || !isfinite(len))
        return -1;
    for (int a = 0; a < f->dim; a++)
        n[a] = g[a] / len;
    return 0;
}

/* The 2D quadratic normal at two points of one element, each in a lane:
 * normal_quadratic_2d_at's operations lane by lane (so the bits of one
 * point at a time), the two chains of divisions and square roots side by
 * side. 1 when a point is not inside the element (nothing written). */
static int normal_quadratic_2d_pair(const lm_nfit *f, const double a[3], const double b[3],
                                    double na[3], double nb[3], int bad[2])
{
    double w0 = f->box.hi[0] - f->box.lo[0], w1 = f->box.hi[1] - f->box.lo[1];
    lm_v2d W0 = {w0, w0}, W1 = {w1, w1};
    lm_v2d xi = ((lm_v2d){a[0], b[0]} - f->box.lo[0]) / W0;
    lm_v2d eta = ((lm_v2d){a[1], b[1]} - f->box.lo[1]) / W1;
    for (int l = 0; l < 2; l++)
        if (!(xi[l] >= 0.0 && xi[l] <= 1.0 && eta[l] >= 0.0 && eta[l] <= 1.0))
            return 1;
    /* bspline2_three_d lane by lane */
    const lm_v2d m05 = {0 - 0.5, 0 - 0.5}, p05 = {1 - 0.5, 1 - 0.5}, p15 = {2 - 0.5, 2 - 0.5};
    const lm_v2d c15 = {1.5, 1.5}, h = {0.5, 0.5}, q34 = {0.75, 0.75}, two = {2.0, 2.0};
    lm_v2d v0[3], d0[3], v1[3], d1[3];
    for (int ax = 0; ax < 2; ax++) {
        lm_v2d u = ax ? eta : xi, *v = ax ? v1 : v0, *d = ax ? d1 : d0;
        lm_v2d t = u - m05, e = c15 - t;
        v[0] = h * e * e;
        d[0] = -e;
        t = u - p05;
        v[1] = q34 - t * t;
        d[1] = -two * t;
        t = u - p15;
        e = c15 - (-t);
        v[2] = h * e * e;
        d[2] = e;
    }
    const double *c = f->phi;
    lm_v2d gl0 = {0.0, 0.0}, gl1 = {0.0, 0.0};
    double scale = 1.0;
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++) {
            lm_v2d cc = {c[i + 3 * j], c[i + 3 * j]};
            gl0 += cc * (d0[i] * v1[j]);
            gl1 += cc * (v0[i] * d1[j]);
        }
    for (int I = 0; I < 9; I++)
        if (fabs(c[I]) > scale)
            scale = fabs(c[I]);
    lm_v2d g0 = gl0 / W0, g1 = gl1 / W1;
    lm_v2d len = lm_v2d_sqrt(g0 * g0 + g1 * g1), llen = lm_v2d_sqrt(gl0 * gl0 + gl1 * gl1);
    lm_v2d n0 = g0 / len, n1 = g1 / len;
    double *n[2] = {na, nb};
    for (int l = 0; l < 2; l++) {
        n[l][0] = n[l][1] = n[l][2] = 0.0;
        bad[l] = !(llen[l] > 1e-10 * scale) || !isfinite(len[l]);
        if (bad[l])
            continue;
        n[l][0] = n0[l];
        n[l][1] = n1[l];
    }
    return 0;
}

void lm_nfit_normal2(const lm_nfit *f, const double a[3], const double b[3],
                     double na[3], double nb[3], int bad[2])
{
    if (f->basis == LM_NB_QUADRATIC && f->dim == 2 &&
        normal_quadratic_2d_pair(f, a, b, na, nb, bad) == 0) {
        bad[0] = -bad[0];
        bad[1] = -bad[1];
        return;
    }
    bad[0] = lm_nfit_normal(f, a, na);
    bad[1] = lm_nfit_normal(f, b, nb);
}
