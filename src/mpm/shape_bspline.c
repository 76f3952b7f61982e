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

/* The place and the products are step.h's (lm_bspline2_place,
 * lm_bspline2_1d): the step keeps only the place and rebuilds the weights
 * with the same operations, so this and the step agree to the bit. */
void lm_shape_bspline2(const lm_grid *g, double x, double y, int *node,
                       double N[9], double Gx[9], double Gy[9])
{
    double rx = 1.0 / g->hx, ry = 1.0 / g->hy, dx, dy;
    lm_bspline2_place(g, rx, ry, x, y, node, &dx, &dy);
    lm_bspline2_N(dx, dy, N);
    lm_bspline2_G_r(rx, ry, dx, dy, Gx, Gy);
}
