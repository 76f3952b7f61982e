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

/* Weight and gradient (times r = 1/h) of a node xi cells from the
 * particle; written in |xi| so that the mirror nodes of a point on a wall
 * get equal weights to the last bit. */
static inline void gimp_1d(double xi, double l, double r, double *w, double *g)
{
    double a = fabs(xi), s = xi < 0 ? -1 : 1;
    if (a < l) {
        *w = 1 - (xi * xi + l * l) / (2 * l);
        *g = -xi / l * r;
    } else if (a <= 1 - l) {
        *w = 1 - a;
        *g = -s * r;
    } else if (a < 1 + l) {
        double u = 1 + l - a;
        *w = u * u / (4 * l);
        *g = -s * u / (2 * l) * r;
    } else {
        *w = 0;
        *g = 0;
    }
}

void lm_shape_gimp(const lm_grid *g, double x, double y, double lx, double ly, int *node,
                   double N[9], double Gx[9], double Gy[9])
{
    double rx = 1.0 / g->hx, ry = 1.0 / g->hy;
    double dx, dy, wx[3], wy[3], gx[3], gy[3];
    int cx = lm_shape_nearest((x - g->x0) * rx, g->nx, &dx);
    int cy = lm_shape_nearest((y - g->y0) * ry, g->ny, &dy);
    for (int a = 0; a < 3; a++) {
        gimp_1d(dx + 1 - a, lx * rx, rx, &wx[a], &gx[a]);
        gimp_1d(dy + 1 - a, ly * ry, ry, &wy[a], &gy[a]);
    }
    *node = (int)lm_grid_node(g, cx - 1, cy - 1);
    for (int b = 0; b < 3; b++)
        for (int a = 0; a < 3; a++) {
            N[3 * b + a] = wx[a] * wy[b];
            Gx[3 * b + a] = gx[a] * wy[b];
            Gy[3 * b + a] = wx[a] * gy[b];
        }
}
