/* shape_gimp.c - the uGIMP basis (Bardenhagen & Kober 2004, "The
 * generalized interpolation material point method"; lamina.sim{basis =
 * "gimp"}).
 *
 * GIMP gives a particle a domain, here a square of half-sizes lx, ly that
 * does not deform ("uniform" or "unchanged" GIMP), and weighs node i by
 * the mean of its bilinear hat N_i over that domain:
 *     S_ip = 1/|Omega_p| \int_{Omega_p} N_i(x) dx.
 * Along one axis, with xi = (x_p - x_i)/h and l = l_p/h (0 < l <= 1/2),
 * that integral is
 *     1 - (xi^2 + l^2) / (2 l)       |xi| < l
 *     1 - |xi|                       l <= |xi| <= 1 - l
 *     (1 + l - |xi|)^2 / (4 l)       1 - l < |xi| < 1 + l
 *     0                              beyond,
 * continuous with a continuous gradient: as with the B-spline, a particle
 * crossing a cell edge no longer flips its force (Bardenhagen & Kober's
 * motivation, and [T] A.2's). It reaches h + l_p <= 3h/2 from the particle,
 * so the three nodes around the nearest one carry every weight. The
 * weights sum to one because the hats do. */
#include "step.h"

/* The two outer nodes of the stencil lie a = 1 -+ d >= 1/2 >= l cells
 * from the particle: the middle or the outer piece of the weight. Returns
 * the weight and its derivative in a (times r = 1/h); il = 1/l. */
static inline void gimp_outer(double a, double l, double il, double r, double *w, double *dw)
{
    if (a <= 1 - l) {
        *w = 1 - a;
        *dw = -r;
    } else if (a < 1 + l) {
        double u = 1 + l - a;
        *w = 0.25 * u * u * il;
        *dw = -0.5 * u * il * r;
    } else {
        *w = 0;
        *dw = 0;
    }
}

/* Weights and x-gradients (times r = 1/h) of the nodes c-1, c, c+1 for a
 * particle d cells from the nearest node c (|d| <= 1/2), half-size l cells.
 * The middle node is within 1/2 <= 1 - l: the inner or the middle piece.
 * Written in the distances |xi|, so that the mirror nodes of a point on a
 * wall (d = 0) get equal weights to the last bit. */
static inline void gimp_1d(double d, double l, double r, double w[3], double g[3])
{
    double il = 1 / l, ad = fabs(d), dw;
    if (ad < l) {
        w[1] = 1 - 0.5 * (d * d + l * l) * il;
        g[1] = -d * il * r;
    } else {
        w[1] = 1 - ad;
        g[1] = d < 0 ? r : -r;
    }
    gimp_outer(1 + d, l, il, r, &w[0], &dw);    /* node c-1 at xi = +(1 + d) */
    g[0] = dw;
    gimp_outer(1 - d, l, il, r, &w[2], &dw);    /* node c+1 at xi = -(1 - d) */
    g[2] = -dw;
}

void lm_shape_gimp(const lm_grid *g, double x, double y, double lx, double ly, int *node,
                   double N[9], double Gx[9], double Gy[9])
{
    double rx = 1.0 / g->hx, ry = 1.0 / g->hy;
    double dx, dy, wx[3], wy[3], gx[3], gy[3];
    int cx = lm_shape_nearest((x - g->x0) * rx, g->nx, &dx);
    int cy = lm_shape_nearest((y - g->y0) * ry, g->ny, &dy);
    gimp_1d(dx, lx * rx, rx, wx, gx);
    gimp_1d(dy, ly * ry, ry, wy, gy);
    *node = (int)lm_grid_node(g, cx - 1, cy - 1);
    for (int b = 0; b < 3; b++)
        for (int a = 0; a < 3; a++) {
            N[3 * b + a] = wx[a] * wy[b];
            Gx[3 * b + a] = gx[a] * wy[b];
            Gy[3 * b + a] = wx[a] * gy[b];
        }
}
