/* normals_basis.c - the B-spline bases of the isosurface construction.
 *
 * Linear ([N] eq 6): beta_1(t) = 1 - |t| on |t| <= 1, on the element's
 * nodes, logical positions {0, 1} per axis.
 * Quadratic ([N] §5): beta_2(t) = 3/4 - t^2 on |t| <= 1/2,
 * (3/2 - |t|)^2 / 2 on 1/2 <= |t| <= 3/2, on element centres: for a point
 * in the element [0,1]^d the centres of the element and its neighbours,
 * at {-1/2, 1/2, 3/2} per axis ([N] §5: C = (i + 1/2, j + 1/2, k + 1/2)).
 * Tensor products give s(xi - I) ([N] eq 7); node I = i + a (j + a k). */
#include <math.h>

#include "normals.h"

double lm_bspline1(double t)
{
    double a = fabs(t);
    return a <= 1.0 ? 1.0 - a : 0.0;
}

double lm_bspline1_d(double t)
{
    if (t <= -1.0 || t >= 1.0)
        return 0.0;
    return t < 0.0 ? 1.0 : t > 0.0 ? -1.0 : 0.0;
}

double lm_bspline2(double t)
{
    double a = fabs(t);
    if (a <= 0.5)
        return 0.75 - a * a;
    if (a <= 1.5)
        return 0.5 * (1.5 - a) * (1.5 - a);
    return 0.0;
}

double lm_bspline2_d(double t)
{
    double a = fabs(t);
    if (a <= 0.5)
        return -2.0 * t;
    if (a <= 1.5)
        return t < 0.0 ? 1.5 - a : -(1.5 - a);
    return 0.0;
}

static int per_axis(lm_nbasis b) { return b == LM_NB_QUADRATIC ? 3 : 2; }

int lm_nbasis_count(lm_nbasis b, int dim)
{
    int a = per_axis(b);
    return dim == 3 ? a * a * a : a * a;
}

/* Logical position of the i-th node along one axis. */
static double node_1d(lm_nbasis b, int i)
{
    return b == LM_NB_QUADRATIC ? i - 0.5 : (double)i;
}

void lm_nbasis_node(lm_nbasis b, int dim, int I, double xi[3])
{
    int a = per_axis(b);
    xi[0] = node_1d(b, I % a);
    xi[1] = node_1d(b, (I / a) % a);
    xi[2] = dim == 3 ? node_1d(b, I / (a * a)) : 0.0;
}

/* The basis the step's centred elements evaluate (2D quadratic), written
 * out: the general loop below with the third axis' factor 1 (derivative
 * 0). x * 1.0 is x exactly and these factors are >= 0, so every value is
 * bit for bit the general loop's; it only skips its branches and the third
 * axis (the evaluations were the second cost of the per-step normals,
 * docs/performance.md). */
static void quadratic_2d(const double xi[3], double s[LM_NMAX],
                         double ds[LM_NMAX][3])
{
    double v0[3], v1[3], d0[3], d1[3];
    for (int i = 0; i < 3; i++) {
        double t0 = xi[0] - (i - 0.5), t1 = xi[1] - (i - 0.5);
        v0[i] = lm_bspline2(t0);
        v1[i] = lm_bspline2(t1);
        if (ds) {
            d0[i] = lm_bspline2_d(t0);
            d1[i] = lm_bspline2_d(t1);
        }
    }
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++) {
            int I = i + 3 * j;
            s[I] = v0[i] * v1[j];
            if (ds) {
                ds[I][0] = d0[i] * v1[j];
                ds[I][1] = v0[i] * d1[j];
                ds[I][2] = 0.0;
            }
        }
}

/* The step's normals need only grad phi at each point: the products of
 * quadratic_2d's ds, each times its coefficient and added in the order of
 * I, as grad_logical (normals_fit.c) adds them from the table. */
/* lm_bspline2 and lm_bspline2_d at t = x - (i - 1/2), i = 0, 1, 2, for x in
 * [0, 1] (a point in its element), without their branches: there t_0 lies
 * in [1/2, 3/2], t_1 in [-1/2, 1/2], t_2 in [-3/2, -1/2], so each takes
 * one piece; at the joins (x = 0 or 1) both pieces give the same value
 * exactly (1/2, and slope -1 or 1), and |t| (1.5 - |t|) are formed from
 * the same t, so every value is bit for bit the functions'. */
static void quadratic_1d(double x, double v[3], double d[3])
{
    if (!(x >= 0.0 && x <= 1.0)) {
        for (int i = 0; i < 3; i++) {
            v[i] = lm_bspline2(x - (i - 0.5));
            d[i] = lm_bspline2_d(x - (i - 0.5));
        }
        return;
    }
    double t0 = x - (0 - 0.5), t1 = x - (1 - 0.5), t2 = x - (2 - 0.5);
    double e0 = 1.5 - t0, e2 = 1.5 - (-t2);
    v[0] = 0.5 * e0 * e0;
    d[0] = -e0;
    v[1] = 0.75 - t1 * t1;
    d[1] = -2.0 * t1;
    v[2] = 0.5 * e2 * e2;
    d[2] = e2;
}

void lm_nbasis_grad_quadratic_2d(const double xi[3], const double c[9], double g[3])
{
    double v0[3], v1[3], d0[3], d1[3];
    quadratic_1d(xi[0], v0, d0);
    quadratic_1d(xi[1], v1, d1);
    double g0 = 0.0, g1 = 0.0;
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++) {
            int I = i + 3 * j;
            g0 += c[I] * (d0[i] * v1[j]);
            g1 += c[I] * (v0[i] * d1[j]);
        }
    g[0] = g0;
    g[1] = g1;
    g[2] = 0.0;
}

void lm_nbasis_eval(lm_nbasis b, int dim, const double xi[3],
                    double s[LM_NMAX], double ds[LM_NMAX][3])
{
    if (b == LM_NB_QUADRATIC && dim == 2) {
        quadratic_2d(xi, s, ds);
        return;
    }
    int a = per_axis(b);
    double v[3][3], d[3][3];     /* [axis][node] value and derivative */
    for (int ax = 0; ax < 3; ax++)
        for (int i = 0; i < a; i++) {
            if (ax == 2 && dim == 2) {
                v[ax][i] = 1.0;
                d[ax][i] = 0.0;
                continue;
            }
            double t = xi[ax] - node_1d(b, i);
            if (b == LM_NB_QUADRATIC) {
                v[ax][i] = lm_bspline2(t);
                d[ax][i] = lm_bspline2_d(t);   /* beta_2 is C1: no kinks */
            } else {
                v[ax][i] = lm_bspline1(t);
                /* beta_1 has kinks at the nodes: on the element's closed
                 * box take the element's own piece, 1 - xi or xi, so a
                 * point on an edge gets the element's gradient. */
                d[ax][i] = xi[ax] >= 0.0 && xi[ax] <= 1.0 ? (i ? 1.0 : -1.0)
                                                          : lm_bspline1_d(t);
            }
        }
    int nk = dim == 3 ? a : 1;
    for (int k = 0; k < nk; k++)
        for (int j = 0; j < a; j++)
            for (int i = 0; i < a; i++) {
                int I = i + a * (j + a * k);
                s[I] = v[0][i] * v[1][j] * v[2][k];
                if (ds) {
                    ds[I][0] = d[0][i] * v[1][j] * v[2][k];
                    ds[I][1] = v[0][i] * d[1][j] * v[2][k];
                    ds[I][2] = v[0][i] * v[1][j] * d[2][k];
                }
            }
}

/* Logical coordinates ([N] eq 4 on a rectangular element: the map is
 * affine per axis). */
void lm_nbox_to_logical(const lm_nbox *b, const double x[3], double xi[3])
{
    for (int a = 0; a < 3; a++)
        xi[a] = a < b->dim ? (x[a] - b->lo[a]) / (b->hi[a] - b->lo[a]) : 0.0;
}

void lm_nbox_to_world(const lm_nbox *b, const double xi[3], double x[3])
{
    for (int a = 0; a < 3; a++)
        x[a] = a < b->dim ? b->lo[a] + xi[a] * (b->hi[a] - b->lo[a]) : 0.0;
}
