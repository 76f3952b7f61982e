/* grid.c - the background grid: nodal fields and boundary conditions. */
#include <string.h>

#include "step.h"

size_t lm_grid_nodes(const lm_grid *g)
{
    return (size_t)g->sx * (size_t)(g->ny + 1 + 2 * g->pad);
}

void lm_grid_layout(lm_grid *g, lm_basis basis)
{
    g->sw = basis == LM_BASIS_LINEAR ? 2 : 3;
    g->pad = basis == LM_BASIS_LINEAR ? 0 : 1;
    g->sx = g->nx + 1 + 2 * g->pad;
}

/* fixed: both components zero on that side; symmetry (roller): the normal
 * component zero; free: nothing. Corners get both sides' constraints. A
 * wall's line runs on through the ghost ring (where a free neighbour side
 * keeps live ghost nodes, grid_walls.c): a node on it is its own image. */
void lm_grid_apply_bc(const lm_grid *g, double *ux, double *uy)
{
    for (int j = -g->pad; j <= g->ny + g->pad; j++) {
        long l = lm_grid_node(g, 0, j), r = lm_grid_node(g, g->nx, j);
        if (g->bc[LM_LEFT] != LM_BC_FREE) ux[l] = 0;
        if (g->bc[LM_LEFT] == LM_BC_FIXED) uy[l] = 0;
        if (g->bc[LM_RIGHT] != LM_BC_FREE) ux[r] = 0;
        if (g->bc[LM_RIGHT] == LM_BC_FIXED) uy[r] = 0;
    }
    for (int i = -g->pad; i <= g->nx + g->pad; i++) {
        long b = lm_grid_node(g, i, 0), t = lm_grid_node(g, i, g->ny);
        if (g->bc[LM_BOTTOM] != LM_BC_FREE) uy[b] = 0;
        if (g->bc[LM_BOTTOM] == LM_BC_FIXED) ux[b] = 0;
        if (g->bc[LM_TOP] != LM_BC_FREE) uy[t] = 0;
        if (g->bc[LM_TOP] == LM_BC_FIXED) ux[t] = 0;
    }
}
