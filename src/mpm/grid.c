/* grid.c - the background grid: nodal fields and boundary conditions. */
#include <string.h>

#include "step.h"

size_t lm_grid_nodes(const lm_grid *g)
{
    return (size_t)(g->nx + 1) * (size_t)(g->ny + 1);
}

/* fixed: both components zero on that side; symmetry (roller): the normal
 * component zero; free: nothing. Corners get both sides' constraints. */
void lm_grid_apply_bc(const lm_grid *g, double *ux, double *uy)
{
    int sx = g->nx + 1;
    for (int j = 0; j <= g->ny; j++) {
        int l = j * sx, r = j * sx + g->nx;
        if (g->bc[LM_LEFT] != LM_BC_FREE) ux[l] = 0;
        if (g->bc[LM_LEFT] == LM_BC_FIXED) uy[l] = 0;
        if (g->bc[LM_RIGHT] != LM_BC_FREE) ux[r] = 0;
        if (g->bc[LM_RIGHT] == LM_BC_FIXED) uy[r] = 0;
    }
    for (int i = 0; i <= g->nx; i++) {
        int b = i, t = g->ny * sx + i;
        if (g->bc[LM_BOTTOM] != LM_BC_FREE) uy[b] = 0;
        if (g->bc[LM_BOTTOM] == LM_BC_FIXED) ux[b] = 0;
        if (g->bc[LM_TOP] != LM_BC_FREE) uy[t] = 0;
        if (g->bc[LM_TOP] == LM_BC_FIXED) ux[t] = 0;
    }
}
