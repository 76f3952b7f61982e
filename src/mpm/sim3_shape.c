/* sim3_shape.c - the 3D bases: trilinear hats on a 2 x 2 x 2 stencil and
 * the node-centred quadratic B-spline on 3 x 3 x 3 (Steffen, Kirby &
 * Berzins 2008), both tensor products of the 1D factors the 2D step uses
 * (shape_1d.h).
 *
 * Why the weights are rebuilt and not stored: 27 weights and 81 gradient
 * components are 864 bytes a particle, twice the whole 3D budget of 400
 * bytes a particle with its grid (issue 34 item 6). A particle keeps its
 * stencil's first node and three offsets (28 bytes); each pass makes the
 * 3 x 3 factors from them (a dozen multiplications) and the 27 products
 * as it walks the stencil, as Taichi's MLS-MPM kernels do. */
#include <math.h>

#include "mpm3.h"
#include "shape_1d.h"
#include "step.h"

/* The stencil of a point: trilinear - the cell holding it and its place
 * there (a point on the far face belongs to the last cell); quadratic -
 * one node before the nearest node (lm_shape_nearest, as in 2D) and the
 * offset from that nearest node. */
void lm3_place(const lm3_grid *g, const double x[3], int32_t *node, double d[3])
{
    const double r = 1.0 / g->h;
    int c[3];
    for (int a = 0; a < 3; a++) {
        double f = (x[a] - g->lo[a]) * r;
        if (g->W == 2) {
            int i = f >= 0 ? (int)f : (int)floor(f);
            if (i >= g->n[a]) i = g->n[a] - 1;
            if (i < 0) i = 0;
            c[a] = i;
            d[a] = f - i;
        } else {
            c[a] = lm_shape_nearest(f, g->n[a], &d[a]) - 1;
        }
    }
    *node = (int32_t)lm3_node(g, c[0], c[1], c[2]);
}

void lm3_weights_at(const lm3_grid *g, int32_t node, const double d[3], lm3_weights *w)
{
    const double r = 1.0 / g->h;
    w->node = node;
    for (int a = 0; a < 3; a++) {
        if (g->W == 2) {
            lm_linear_1d(d[a], r, w->w[a], w->g[a]);
            w->w[a][2] = w->g[a][2] = 0;
        } else {
            lm_bspline2_1d(d[a], r, w->w[a], w->g[a]);
        }
    }
}
