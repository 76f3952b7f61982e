/* sim3_shape.h - a point's stencil and weights, inline for the step's
 * passes (sim3_step.c) with the stencil width W a compile-time constant,
 * so that the trilinear and quadratic loops are each specialised (the
 * public lm3_place / lm3_weights_at of sim3_shape.c call these with the
 * grid's W). Private to the engine. */
#ifndef LAMINA_SIM3_SHAPE_H
#define LAMINA_SIM3_SHAPE_H

#include <math.h>

#include "mpm3.h"
#include "shape_1d.h"
#include "step.h"

/* The stencil of a point: trilinear - the cell holding it and its place
 * there (a point on the far face belongs to the last cell); quadratic -
 * one node before the nearest node (lm_shape_nearest, as in 2D) and the
 * offset from that nearest node. */
static inline void lm3_place_w(const lm3_grid *g, const double x[3], int32_t *node,
                               double d[3], const int W)
{
    const double r = 1.0 / g->h;
    int c[3];
    for (int a = 0; a < 3; a++) {
        double f = (x[a] - g->lo[a]) * r;
        if (W == 2) {
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

static inline void lm3_weights_w(const lm3_grid *g, int32_t node, const double d[3],
                                 lm3_weights *w, const int W)
{
    const double r = 1.0 / g->h;
    w->node = node;
    for (int a = 0; a < 3; a++) {
        if (W == 2) {
            lm_linear_1d(d[a], r, w->w[a], w->g[a]);
            w->w[a][2] = w->g[a][2] = 0;
        } else {
            lm_bspline2_1d(d[a], r, w->w[a], w->g[a]);
        }
    }
}

#endif
