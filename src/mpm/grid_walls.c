/* grid_walls.c - walls for the 3 x 3 bases (uGIMP, quadratic B-spline).
 *
 * A particle within 3h/2 of a wall has stencil nodes one node beyond it.
 * The grid keeps them as a ring of ghost nodes (lm_grid.pad = 1), and what
 * a ghost node means depends on the side (docs/decisions.md "Walls for the
 * wider bases"):
 *
 *   symmetry - the mirror image. The run is the half of a full-domain run
 *     with the mirrored body: the mirrored particle's share at node i is
 *     the real particle's at the ghost node i' beyond the wall, with the
 *     normal components of momentum and force reversed. So each ghost sum
 *     folds into its mirror node (mass +1, normal component -1, tangential
 *     +1), and before a gather each ghost takes its mirror's value with the
 *     same signs. The wall node keeps its roller condition (its normal
 *     component is zero in the full run by symmetry).
 *   fixed - the antisymmetric image: the ghost's velocity is minus its
 *     mirror's (both components; mass +1). With the wall node held at zero,
 *     the velocity interpolated at any point on the wall is
 *     N_{i'} (-v_i) + N_i v_i = 0 exactly, because a point on the wall has
 *     equal weights at mirror nodes: a point on a fixed wall stays put for
 *     every basis, as with the bilinear hats. (Folding the ghost masses
 *     with zero velocity instead would let a point on the wall move.)
 *   free - no image: the ghost nodes are ordinary nodes beyond the edge,
 *     unconstrained, and the basis stays the full-space one (partition of
 *     unity, sum G = 0, momentum conserved up to the edge).
 *
 * Scatters fold (the transpose of the gather's fill, so p2g and g2p stay
 * adjoint and mass stays positive), gathers fill. Sides are treated x
 * first, then y, over the whole ring, so a corner ghost gets both images.
 * With pad = 0 (the linear basis) both are no-ops. */
#include "grid_mirror.h"
#include "step.h"

/* The sign of a field's image across a side whose normal is x (nx = 1) or
 * y (nx = 0). */
static double image_sign(lm_bc bc, int normal_x, lm_comp comp)
{
    if (comp == LM_COMP_SCALAR) return 1;
    if (bc == LM_BC_FIXED) return -1;
    return (comp == LM_COMP_X) == (normal_x != 0) ? -1 : 1;   /* symmetry */
}

/* Ghost node and mirror node of `side` at position k along it. */
static void ghost_pair(const lm_grid *g, int side, int k, long *ghost, long *mirror)
{
    switch (side) {
    case LM_LEFT:
        *ghost = lm_grid_node(g, -1, k);
        *mirror = lm_grid_node(g, 1, k);
        break;
    case LM_RIGHT:
        *ghost = lm_grid_node(g, g->nx + 1, k);
        *mirror = lm_grid_node(g, g->nx - 1, k);
        break;
    case LM_BOTTOM:
        *ghost = lm_grid_node(g, k, -1);
        *mirror = lm_grid_node(g, k, 1);
        break;
    default:
        *ghost = lm_grid_node(g, k, g->ny + 1);
        *mirror = lm_grid_node(g, k, g->ny - 1);
        break;
    }
}

/* fold = 1: f[mirror] += s f[ghost], f[ghost] = 0; fold = 0: f[ghost] =
 * s f[mirror]. */
static void walls(const lm_grid *g, int nf, double *const *f, const lm_comp *comp, int fold)
{
    if (g->pad == 0) return;
    for (int side = 0; side < 4; side++) {
        lm_bc bc = g->bc[side];
        if (bc == LM_BC_FREE) continue;
        int normal_x = side == LM_LEFT || side == LM_RIGHT;
        int len = normal_x ? g->ny : g->nx;
        double s[8];
        for (int c = 0; c < nf; c++) s[c] = image_sign(bc, normal_x, comp[c]);
        for (int k = -1; k <= len + 1; k++) {
            long gh, mi;
            ghost_pair(g, side, k, &gh, &mi);
            lm_grid_mirror(nf, f, s, gh, mi, fold);
        }
    }
}

void lm_grid_fold(const lm_grid *g, int nf, double *const *f, const lm_comp *comp)
{
    walls(g, nf, f, comp, 1);
}

void lm_grid_fill(const lm_grid *g, int nf, double *const *f, const lm_comp *comp)
{
    walls(g, nf, f, comp, 0);
}
