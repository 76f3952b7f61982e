/* shape_bspline.c - the quadratic B-spline basis, node-centred (Steffen,
 * Kirby & Berzins 2008, "Analysis and reduction of quadrature errors in the
 * material point method"; lamina.sim{basis = "bspline2"}).
 *
 * Why: the bilinear hat's gradient jumps where a particle crosses a cell
 * edge, so the force a particle sends to a node jumps too (the cell-
 * crossing noise of [T] A.2, docs/physics.md §5b). The quadratic B-spline
 *     beta(xi) = 3/4 - xi^2             |xi| <= 1/2
 *              = 1/2 (3/2 - |xi|)^2     1/2 <= |xi| <= 3/2
 * (xi = (x - x_i) / h) has a continuous gradient: the force changes
 * smoothly as the particle moves. It spans three nodes per direction: the
 * node nearest the particle and its two neighbours. In 2D the basis is the
 * tensor product beta(xi_x) beta(xi_y). */
#include "shape_1d.h"
#include "step.h"

void lm_shape_bspline2(const lm_grid *g, double x, double y, int *node,
                       double N[9], double Gx[9], double Gy[9])
{
    double rx = 1.0 / g->hx, ry = 1.0 / g->hy;
    double dx, dy, wx[3], wy[3], gx[3], gy[3];
    int cx = lm_shape_nearest((x - g->x0) * rx, g->nx, &dx);
    int cy = lm_shape_nearest((y - g->y0) * ry, g->ny, &dy);
    lm_bspline2_1d(dx, rx, wx, gx);
    lm_bspline2_1d(dy, ry, wy, gy);
    *node = (int)lm_grid_node(g, cx - 1, cy - 1);
    for (int b = 0; b < 3; b++)
        for (int a = 0; a < 3; a++) {
            N[3 * b + a] = wx[a] * wy[b];
            Gx[3 * b + a] = gx[a] * wy[b];
            Gy[3 * b + a] = wx[a] * gy[b];
        }
}
