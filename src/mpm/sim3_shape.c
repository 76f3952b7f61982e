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
 * as it walks the stencil, as Taichi's MLS-MPM kernels do. The bodies are
 * sim3_shape.h's, inline in the step with W a constant. */
#include "sim3_shape.h"

void lm3_place(const lm3_grid *g, const double x[3], int32_t *node, double d[3])
{
    if (g->W == 2) lm3_place_w(g, x, node, d, 2);
    else lm3_place_w(g, x, node, d, 3);
}

void lm3_weights_at(const lm3_grid *g, int32_t node, const double d[3], lm3_weights *w)
{
    if (g->W == 2) lm3_weights_w(g, node, d, w, 2);
    else lm3_weights_w(g, node, d, w, 3);
}
