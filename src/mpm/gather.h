/* gather.h - the stencil gathers of the engine's particle-side sums:
 * sum_i N_iq a_i over particle q's W x W stencil, for one nodal array a.
 * Two orders, because floating-point sums depend on the order and every
 * caller keeps the bits it always had: node by node (k = 0 .. W^2 - 1,
 * the axisymmetric hoop rate and the contact fields' corrections), and row
 * by row (each row's sum added in turn, the order step 4 gathers in: the
 * remapped velocity of the segment form, the corrected mass). A caller
 * with two arrays calls one twice: the two sums are independent, so the
 * result is the bits of one loop over both. */
#ifndef LAMINA_MPM_GATHER_H
#define LAMINA_MPM_GATHER_H

#include "step.h"

/* Node by node over the stencil whose lower-left node is `node`. */
static inline double lm_gather(const lm_grid *g, const lm_weights *wt, int node,
                               const double *a)
{
    const int W = g->sw, NS = W * W;
    double s = 0;
    for (int k = 0; k < NS; k++) s += wt->N[k] * a[lm_stencil_node(g, W, node, k)];
    return s;
}

/* Row by row: the sum of the rows' sums. */
static inline double lm_gather_rows(const lm_grid *g, const lm_weights *wt, int node,
                                    const double *a)
{
    const int W = g->sw;
    double s = 0;
    for (int b = 0; b < W; b++) {
        const long row = lm_stencil_row(g, node, b);
        double r = 0;
        for (int c = 0; c < W; c++) r += wt->N[b * W + c] * a[row + c];
        s += r;
    }
    return s;
}

#endif
