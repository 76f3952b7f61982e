/* shape.c - the bilinear nodal basis N_i(x) and its gradient ([F] §2), and
 * the choice among the bases (lamina.sim{basis}). */
#include <math.h>

#include "step.h"

void lm_cell_bilinear(const lm_grid *g, double x, double y, int *node, double *xi,
                      double *eta)
{
    /* two divisions, then products: divisions dominate this function */
    lm_cell_bilinear_r(g, 1.0 / g->hx, 1.0 / g->hy, x, y, node, xi, eta);
}

void lm_shape_bilinear(const lm_grid *g, double x, double y, int *node,
                       double N[4], double Gx[4], double Gy[4])
{
    double xi, eta;
    lm_cell_bilinear(g, x, y, node, &xi, &eta);
    lm_bilinear_N(xi, eta, N);
    lm_bilinear_G(g, xi, eta, Gx, Gy);
}

void lm_shape_particle(const lm_sim *sim, size_t q, int *node, double *N, double *Gx,
                       double *Gy)
{
    const lm_particles *p = &sim->p;
    switch (sim->def.basis) {
    case LM_BASIS_GIMP:
        lm_shape_gimp(&sim->grid, p->x[q], p->y[q], p->lx[q], p->ly[q], node, N, Gx, Gy);
        break;
    case LM_BASIS_BSPLINE2:
        lm_shape_bspline2(&sim->grid, p->x[q], p->y[q], node, N, Gx, Gy);
        break;
    default:
        lm_shape_bilinear(&sim->grid, p->x[q], p->y[q], node, N, Gx, Gy);
        break;
    }
}

const char *lm_basis_name(lm_basis b)
{
    switch (b) {
    case LM_BASIS_GIMP: return "gimp";
    case LM_BASIS_BSPLINE2: return "bspline2";
    default: return "linear";
    }
}

/* The largest stable dt c / h of each basis on a 1D elastic bar under MUSL,
 * relative to the linear basis', the smallest ratio over 1, 4 and 9 points
 * per cell (scripts/measure/courant_basis.lua; docs/decisions.md "Shape
 * functions"): linear 1.97 / 1.72 / 1.66, gimp 1.99 / 1.72 / 1.67,
 * bspline2 1.99 / 2.30 / 2.23. No basis is less stable than the linear one,
 * so none tightens the check; the smoother ones' extra margin at 4 and 9
 * points per cell is not handed out, because at 1 point per cell (where
 * uGIMP and the B-spline coincide) it is gone. */
double lm_basis_courant_factor(lm_basis b)
{
    switch (b) {
    case LM_BASIS_GIMP: return 1.0;
    case LM_BASIS_BSPLINE2: return 1.0;
    default: return 1.0;
    }
}
