/* test_normals_basis.c - the B-spline bases of the isosurface construction
 * ([N] eq 6, §5): counts, partition of unity, reproduction of polynomials,
 * derivatives against finite differences, and the element-side gradient of
 * the linear basis on the element's edges. */
#include "check.h"
#include "normals.h"

static const lm_nbasis bases[] = {LM_NB_LINEAR, LM_NB_QUADRATIC};

static void test_counts(void)
{
    CHECK(lm_nbasis_count(LM_NB_LINEAR, 2) == 4);
    CHECK(lm_nbasis_count(LM_NB_QUADRATIC, 2) == 9);
    CHECK(lm_nbasis_count(LM_NB_LINEAR, 3) == 8);
    CHECK(lm_nbasis_count(LM_NB_QUADRATIC, 3) == 27);
    double xi[3];
    lm_nbasis_node(LM_NB_QUADRATIC, 2, 0, xi);
    CHECK_NEAR(xi[0], -0.5, 0);
    CHECK_NEAR(xi[1], -0.5, 0);
    lm_nbasis_node(LM_NB_QUADRATIC, 3, 26, xi);
    CHECK_NEAR(xi[0] + xi[1] + xi[2], 4.5, 0);
    lm_nbasis_node(LM_NB_LINEAR, 3, 5, xi);     /* 5 = 1 + 2 * (0 + 2 * 1) */
    CHECK(xi[0] == 1 && xi[1] == 0 && xi[2] == 1);
}

/* [N] §5: beta_2 = 3/4 - t^2 on |t| <= 1/2, (3/2 - |t|)^2 / 2 to 3/2 */
static void test_bspline_values(void)
{
    CHECK_NEAR(lm_bspline2(0), 0.75, 0);
    CHECK_NEAR(lm_bspline2(0.5), 0.5, 1e-15);
    CHECK_NEAR(lm_bspline2(-0.5), 0.5, 1e-15);
    CHECK_NEAR(lm_bspline2(1.5), 0.0, 0);
    CHECK_NEAR(lm_bspline2(2.0), 0.0, 0);
    CHECK_NEAR(lm_bspline2(1.0), 0.125, 1e-15);
    CHECK_NEAR(lm_bspline1(0.25), 0.75, 0);
    CHECK_NEAR(lm_bspline1(-1.5), 0.0, 0);
    /* beta_2 is C1 at the joints */
    CHECK_NEAR(lm_bspline2_d(0.5 - 1e-12), lm_bspline2_d(0.5 + 1e-12), 1e-9);
    CHECK_NEAR(lm_bspline2_d(-1.5 + 1e-12), 0.0, 1e-9);
}

/* deterministic sample points in (0,1)^3, edges included */
static void sample(int k, double xi[3])
{
    static const double v[] = {0.0, 0.13, 0.5, 0.77, 1.0, 0.31, 0.92};
    xi[0] = v[k % 7];
    xi[1] = v[(k * 3 + 1) % 7];
    xi[2] = v[(k * 5 + 2) % 7];
}

static void test_partition_and_reproduction(void)
{
    for (int d = 2; d <= 3; d++)
        for (int b = 0; b < 2; b++)
            for (int k = 0; k < 30; k++) {
                double xi[3], s[LM_NMAX], ds[LM_NMAX][3];
                sample(k, xi);
                lm_nbasis_eval(bases[b], d, xi, s, ds);
                int n = lm_nbasis_count(bases[b], d);
                double sum = 0, g[3] = {0, 0, 0}, lin[3] = {0, 0, 0}, sq = 0;
                for (int I = 0; I < n; I++) {
                    double node[3];
                    lm_nbasis_node(bases[b], d, I, node);
                    sum += s[I];
                    for (int a = 0; a < 3; a++) {
                        g[a] += ds[I][a];
                        lin[a] += node[a] * s[I];
                    }
                    sq += node[0] * node[0] * s[I];
                }
                CHECK_NEAR(sum, 1.0, 1e-14);              /* partition of unity */
                for (int a = 0; a < d; a++) {
                    CHECK_NEAR(g[a], 0.0, 1e-14);         /* gradients sum to 0 */
                    CHECK_NEAR(lin[a], xi[a], 1e-14);     /* linear reproduction */
                }
                /* quadratic B-splines reproduce xi^2 up to 1/4 (sum i^2
                 * beta_2(x - i) = x^2 + 1/4); linear ones only at nodes */
                if (bases[b] == LM_NB_QUADRATIC)
                    CHECK_NEAR(sq, xi[0] * xi[0] + 0.25, 1e-14);
            }
}

static void test_derivatives(void)
{
    const double h = 1e-6;
    for (int d = 2; d <= 3; d++)
        for (int b = 0; b < 2; b++) {
            double xi[3] = {0.37, 0.61, 0.23}, s[LM_NMAX], ds[LM_NMAX][3];
            lm_nbasis_eval(bases[b], d, xi, s, ds);
            for (int a = 0; a < d; a++) {
                double xp[3] = {xi[0], xi[1], xi[2]}, xm[3] = {xi[0], xi[1], xi[2]};
                double sp[LM_NMAX], sm[LM_NMAX];
                xp[a] += h;
                xm[a] -= h;
                lm_nbasis_eval(bases[b], d, xp, sp, NULL);
                lm_nbasis_eval(bases[b], d, xm, sm, NULL);
                for (int I = 0; I < lm_nbasis_count(bases[b], d); I++)
                    CHECK_NEAR(ds[I][a], (sp[I] - sm[I]) / (2 * h), 1e-8);
            }
        }
}

/* On the element's edges (xi = 0 or 1) the linear basis gives the
 * element's own gradient, not the kink's value: a membrane point on an
 * edge must get the same normal as one just inside. */
static void test_linear_edges(void)
{
    double s[LM_NMAX], ds[LM_NMAX][3], xi[3] = {0.0, 1.0, 0.0};
    lm_nbasis_eval(LM_NB_LINEAR, 2, xi, s, ds);
    CHECK_NEAR(ds[0][0], -(1 - xi[1]), 0);   /* d/dxi (1 - xi)(1 - eta) */
    CHECK_NEAR(ds[1][0], 1 - xi[1], 0);
    CHECK_NEAR(ds[2][0], -xi[1], 0);
    CHECK_NEAR(ds[3][0], xi[1], 0);
    CHECK_NEAR(ds[2][1], 1 - xi[0], 0);      /* d/deta (1 - xi) eta */
}

static void test_box(void)
{
    lm_nbox b = {3, {-1, 0, 2}, {0, 2, 3}};
    double x[3] = {-0.25, 1.5, 2.5}, xi[3], y[3];
    lm_nbox_to_logical(&b, x, xi);
    CHECK_NEAR(xi[0], 0.75, 1e-15);
    CHECK_NEAR(xi[1], 0.75, 1e-15);
    CHECK_NEAR(xi[2], 0.5, 1e-15);
    lm_nbox_to_world(&b, xi, y);
    for (int a = 0; a < 3; a++)
        CHECK_NEAR(y[a], x[a], 1e-15);
}

int main(void)
{
    test_counts();
    test_bspline_values();
    test_partition_and_reproduction();
    test_derivatives();
    test_linear_edges();
    test_box();
    return CHECK_DONE();
}
