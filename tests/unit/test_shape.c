/* test_shape.c - the bilinear basis: partition of unity, zero-sum gradients,
 * gradients equal to finite differences of the weights. */
#include <stdlib.h>

#include "check.h"
#include "step.h"

int main(void)
{
    lm_grid g = {0};
    g.x0 = -0.3; g.y0 = 0.2; g.hx = 0.05; g.hy = 0.08; g.nx = 20; g.ny = 10;
    srand(7);
    for (int t = 0; t < 1000; t++) {
        double x = g.x0 + g.nx * g.hx * (rand() / (RAND_MAX + 1.0));
        double y = g.y0 + g.ny * g.hy * (rand() / (RAND_MAX + 1.0));
        int node;
        double N[4], Gx[4], Gy[4];
        lm_shape_bilinear(&g, x, y, &node, N, Gx, Gy);
        double s = 0, sx = 0, sy = 0, rx = 0, ry = 0;
        for (int k = 0; k < 4; k++) {
            s += N[k];
            sx += Gx[k];
            sy += Gy[k];
            CHECK(N[k] >= 0 && N[k] <= 1);
        }
        CHECK_NEAR(s, 1.0, 1e-14);
        CHECK_NEAR(sx, 0.0, 1e-12);
        CHECK_NEAR(sy, 0.0, 1e-12);
        /* linear completeness: sum N_i x_i = x */
        int i = node % (g.nx + 1), j = node / (g.nx + 1);
        for (int k = 0; k < 4; k++) {
            rx += N[k] * (g.x0 + (i + (k & 1)) * g.hx);
            ry += N[k] * (g.y0 + (j + (k >> 1)) * g.hy);
        }
        CHECK_NEAR(rx, x, 1e-13);
        CHECK_NEAR(ry, y, 1e-13);
        /* gradients against central differences inside the same cell */
        double e = 1e-7 * g.hx;
        double xi = (x - g.x0) / g.hx - i, eta = (y - g.y0) / g.hy - j;
        if (xi > 0.01 && xi < 0.99 && eta > 0.01 && eta < 0.99) {
            int n2;
            double Np[4], Nm[4], Gd[4];
            lm_shape_bilinear(&g, x + e, y, &n2, Np, Gd, Gd);
            lm_shape_bilinear(&g, x - e, y, &n2, Nm, Gd, Gd);
            for (int k = 0; k < 4; k++) CHECK_NEAR((Np[k] - Nm[k]) / (2 * e), Gx[k], 1e-6);
            lm_shape_bilinear(&g, x, y + e, &n2, Np, Gd, Gd);
            lm_shape_bilinear(&g, x, y - e, &n2, Nm, Gd, Gd);
            for (int k = 0; k < 4; k++) CHECK_NEAR((Np[k] - Nm[k]) / (2 * e), Gy[k], 1e-6);
        }
    }
    return CHECK_DONE();
}
