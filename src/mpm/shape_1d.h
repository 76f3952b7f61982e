/* shape_1d.h - the one-dimensional factors of the tensor-product bases,
 * shared by the 2D step (shape_bspline.c) and the 3D core (sim3_shape.c):
 * a 2D or 3D weight is the product of these per direction, so both
 * dimensions evaluate the same 1D numbers with the same operations. */
#ifndef LAMINA_SHAPE_1D_H
#define LAMINA_SHAPE_1D_H

/* The quadratic B-spline, node-centred (Steffen, Kirby & Berzins 2008):
 *     beta(xi) = 3/4 - xi^2             |xi| <= 1/2
 *              = 1/2 (3/2 - |xi|)^2     1/2 <= |xi| <= 3/2
 * Weights and gradients (times r = 1/h) of the nodes c-1, c, c+1 for a
 * point d cells from the nearest node c: beta at xi = d + 1, d, d - 1. */
static inline void lm_bspline2_1d(double d, double r, double w[3], double g[3])
{
    double a = 0.5 - d, b = 0.5 + d;
    w[0] = 0.5 * a * a;
    w[1] = 0.75 - d * d;
    w[2] = 0.5 * b * b;
    g[0] = -a * r;
    g[1] = -2 * d * r;
    g[2] = b * r;
}

/* The linear hat: weights and gradients (times r) of the nodes c, c+1 for
 * a point a fraction xi of the cell from node c. */
static inline void lm_linear_1d(double xi, double r, double w[2], double g[2])
{
    w[0] = 1 - xi;
    w[1] = xi;
    g[0] = -r;
    g[1] = r;
}

#endif
