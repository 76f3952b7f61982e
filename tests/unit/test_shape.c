/* test_shape.c - every basis (linear, uGIMP, quadratic B-spline): partition
 * of unity, zero-sum gradients, linear completeness (sum N_i x_i = x and
 * sum G_i x_i = the unit gradient), gradients equal to finite differences
 * of the weights, and the bases' own values at known points. */
#include <stdlib.h>

#include "check.h"
#include "step.h"

/* The basis at (x, y) with uGIMP half-sizes lx, ly; returns ns. */
static int eval(const lm_grid *g, lm_basis b, double x, double y, double lx, double ly,
                int *node, double *N, double *Gx, double *Gy)
{
    switch (b) {
    case LM_BASIS_GIMP:
        lm_shape_gimp(g, x, y, lx, ly, node, N, Gx, Gy);
        return 9;
    case LM_BASIS_BSPLINE2:
        lm_shape_bspline2(g, x, y, node, N, Gx, Gy);
        return 9;
    default:
        lm_shape_bilinear(g, x, y, node, N, Gx, Gy);
        return 4;
    }
}

/* Grid coordinates (i, j) of node index n. */
static void node_ij(const lm_grid *g, long n, int *i, int *j)
{
    *i = (int)(n % g->sx) - g->pad;
    *j = (int)(n / g->sx) - g->pad;
}

static void one_basis(lm_basis b)
{
    lm_grid g = {0};
    g.x0 = -0.3; g.y0 = 0.2; g.hx = 0.05; g.hy = 0.08; g.nx = 20; g.ny = 10;
    lm_grid_layout(&g, b);
    CHECK(g.sw * g.sw == (b == LM_BASIS_LINEAR ? 4 : 9));
    srand(7);
    for (int t = 0; t < 2000; t++) {
        double x = g.x0 + g.nx * g.hx * (rand() / (RAND_MAX + 1.0));
        double y = g.y0 + g.ny * g.hy * (rand() / (RAND_MAX + 1.0));
        /* uGIMP half-sizes from ppc 1 (h/2) to ppc 64 (h/16) */
        double lx = g.hx / (2 + 14 * (rand() / (RAND_MAX + 1.0)));
        double ly = g.hy / (2 + 14 * (rand() / (RAND_MAX + 1.0)));
        int node;
        double N[9], Gx[9], Gy[9];
        int ns = eval(&g, b, x, y, lx, ly, &node, N, Gx, Gy);
        double s = 0, sx = 0, sy = 0, rx = 0, ry = 0, gxx = 0, gxy = 0, gyx = 0, gyy = 0;
        for (int k = 0; k < ns; k++) {
            int i, j;
            node_ij(&g, lm_stencil_node(&g, g.sw, node, k), &i, &j);
            CHECK(i >= -g.pad && i <= g.nx + g.pad && j >= -g.pad && j <= g.ny + g.pad);
            double xi = g.x0 + i * g.hx, yj = g.y0 + j * g.hy;
            s += N[k];
            sx += Gx[k];
            sy += Gy[k];
            CHECK(N[k] >= 0 && N[k] <= 1);
            rx += N[k] * xi;
            ry += N[k] * yj;
            gxx += Gx[k] * xi;
            gxy += Gx[k] * yj;
            gyx += Gy[k] * xi;
            gyy += Gy[k] * yj;
        }
        CHECK_NEAR(s, 1.0, 1e-14);
        CHECK_NEAR(sx, 0.0, 1e-12);
        CHECK_NEAR(sy, 0.0, 1e-12);
        /* linear completeness: sum N_i x_i = x, and the gradient of the
         * interpolated field x is (1, 0) */
        CHECK_NEAR(rx, x, 1e-13);
        CHECK_NEAR(ry, y, 1e-13);
        CHECK_NEAR(gxx, 1, 1e-12);
        CHECK_NEAR(gxy, 0, 1e-12);
        CHECK_NEAR(gyx, 0, 1e-12);
        CHECK_NEAR(gyy, 1, 1e-12);
        /* gradients against central differences, on the same stencil */
        double ex = 1e-7 * g.hx, ey = 1e-7 * g.hy;
        int n2, n3;
        double Np[9], Nm[9], Gd[9];
        eval(&g, b, x + ex, y, lx, ly, &n2, Np, Gd, Gd);
        eval(&g, b, x - ex, y, lx, ly, &n3, Nm, Gd, Gd);
        if (n2 == node && n3 == node)
            for (int k = 0; k < ns; k++) CHECK_NEAR((Np[k] - Nm[k]) / (2 * ex), Gx[k], 2e-6 / g.hx);
        eval(&g, b, x, y + ey, lx, ly, &n2, Np, Gd, Gd);
        eval(&g, b, x, y - ey, lx, ly, &n3, Nm, Gd, Gd);
        if (n2 == node && n3 == node)
            for (int k = 0; k < ns; k++) CHECK_NEAR((Np[k] - Nm[k]) / (2 * ey), Gy[k], 2e-6 / g.hy);
    }
}

/* Known values: at a node the B-spline is 3/4 there and 1/8 at each
 * neighbour; uGIMP with l = h/4 at a node is 1 - l/(2h) = 7/8 there and
 * (l/h)^2 / (4 l/h) = 1/16 at each neighbour. */
static void known_values(void)
{
    lm_grid g = {0};
    g.hx = g.hy = 0.5; g.nx = g.ny = 8;
    lm_grid_layout(&g, LM_BASIS_BSPLINE2);
    int node;
    double N[9], Gx[9], Gy[9];
    lm_shape_bspline2(&g, 1.5, 2.0, &node, N, Gx, Gy);
    CHECK(node == (int)lm_grid_node(&g, 2, 3));
    CHECK_NEAR(N[4], 0.75 * 0.75, 1e-15);
    CHECK_NEAR(N[3], 0.125 * 0.75, 1e-15);
    CHECK_NEAR(N[0], 0.125 * 0.125, 1e-15);
    CHECK_NEAR(Gx[4], 0, 1e-15);
    CHECK_NEAR(Gx[5], 0.75 * 0.5 / 0.5, 1e-15);    /* beta'(-1) = 1/2, per h */
    lm_shape_gimp(&g, 1.5, 2.0, 0.125, 0.125, &node, N, Gx, Gy);
    CHECK_NEAR(N[4], (1 - 0.125) * (1 - 0.125), 1e-15);
    CHECK_NEAR(N[3], 0.0625 * (1 - 0.125), 1e-15);
    /* uGIMP with l = h/2 (ppc 1: the particle fills its cell) is the
     * quadratic B-spline: the mean of a hat over a cell-wide window */
    double Nb[9], Gb[9], Gc[9];
    lm_shape_gimp(&g, 1.37, 2.21, 0.25, 0.25, &node, N, Gx, Gy);
    lm_shape_bspline2(&g, 1.37, 2.21, &node, Nb, Gb, Gc);
    for (int k = 0; k < 9; k++) {
        CHECK_NEAR(N[k], Nb[k], 1e-15);
        CHECK_NEAR(Gx[k], Gb[k], 1e-14);
        CHECK_NEAR(Gy[k], Gc[k], 1e-14);
    }
}

int main(void)
{
    one_basis(LM_BASIS_LINEAR);
    one_basis(LM_BASIS_GIMP);
    one_basis(LM_BASIS_BSPLINE2);
    known_values();
    return CHECK_DONE();
}
