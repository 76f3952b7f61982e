/* density.c - a gas point's density from the cells around it, the
 * dissertation's alternatives to the continuity equation ([T] §4, eqs
 * 4.5-4.7; lamina.gas{density}).
 *
 * cell (eq 4.5): rho_c = sum of the gas masses in cell c / its area, and
 *   every gas point in c takes rho_c.
 * quadratic (eq 4.6): rho_p = sum_c S_c(x_p) rho_c over the 3 x 3 cells
 *   around the point's own, S the quadratic B-spline on the cell centres
 *   (support one cell either side of the point's cell, [T] App. 3.2).
 *   Cells beyond the grid have no density: the weights left are scaled
 *   to sum to one, so a wall does not read as vacuum.
 * Every gas material's points count towards rho_c (the two states of a
 * shock tube share the cells at their contact); a membrane's do not. The
 * density follows the points' spacing, where the continuity update can
 * drift from it (docs/decisions.md "Gas pressure over the space"), but a
 * cell the gas only partly fills - beside a membrane or a free surface -
 * reads low. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "step.h"

/* The point's cell and its offset from the cell centre, in cells. */
static void cell_of(const lm_grid *g, double x, double y, int *i, int *j,
                    double *dx, double *dy)
{
    double u = (x - g->x0) / g->hx, v = (y - g->y0) / g->hy;
    double fu = floor(u), fv = floor(v);
    /* clamped before the conversion to int: a point gone NaN or far off in
     * an unstable step reaches here before the step reports it (UBSan,
     * found by fuzzing: tests/fuzz) */
    *i = !(fu > 0) ? 0 : fu >= g->nx - 1 ? g->nx - 1 : (int)fu;
    *j = !(fv > 0) ? 0 : fv >= g->ny - 1 ? g->ny - 1 : (int)fv;
    *dx = u - *i - 0.5;
    *dy = v - *j - 0.5;
}

/* Quadratic B-spline weights of the cells left, own, right of a point d
 * cells from its own cell's centre (|d| <= 1/2). */
static void quadratic_weights(double d, double w[3])
{
    w[0] = 0.5 * (0.5 - d) * (0.5 - d);
    w[1] = 0.75 - d * d;
    w[2] = 0.5 * (0.5 + d) * (0.5 + d);
}

static double quadratic_density(const lm_grid *g, const double *rc, double x, double y)
{
    int i, j;
    double dx, dy, wx[3], wy[3], s = 0, w = 0;
    cell_of(g, x, y, &i, &j, &dx, &dy);
    quadratic_weights(dx, wx);
    quadratic_weights(dy, wy);
    for (int b = -1; b <= 1; b++) {
        if (j + b < 0 || j + b >= g->ny) continue;
        for (int a = -1; a <= 1; a++) {
            if (i + a < 0 || i + a >= g->nx) continue;
            double wab = wx[a + 1] * wy[b + 1];
            s += wab * rc[(size_t)(j + b) * g->nx + (i + a)];
            w += wab;
        }
    }
    return s / w;
}

lm_status lm_gas_cell_density(lm_sim *sim)
{
    lm_particles *p = &sim->p;
    const lm_grid *g = &sim->grid;
    int wanted = 0;
    for (int k = 0; k < sim->nmats; k++)
        wanted |= sim->mats[k]->kind == LM_GAS && sim->mats[k]->density != LM_DENSITY_CONTINUITY;
    if (!wanted) return LM_OK;
    size_t nc = (size_t)g->nx * g->ny;
    if (!sim->work->cell_rho && !(sim->work->cell_rho = malloc(nc * sizeof *sim->work->cell_rho))) {
        snprintf(sim->err, sizeof sim->err, "out of memory for the cell densities");
        return LM_ERR_MEMORY;
    }
    double *rc = sim->work->cell_rho;
    memset(rc, 0, nc * sizeof *rc);
    for (size_t q = 0; q < p->n; q++) {
        if (sim->mats[p->mat[q]]->kind != LM_GAS) continue;
        int i, j;
        double dx, dy;
        cell_of(g, p->x[q], p->y[q], &i, &j, &dx, &dy);
        rc[(size_t)j * g->nx + i] += p->m[q];
    }
    for (size_t c = 0; c < nc; c++) rc[c] /= g->hx * g->hy;      /* eq 4.5 */
    for (size_t q = 0; q < p->n; q++) {
        const lm_material *mat = sim->mats[p->mat[q]];
        if (mat->kind != LM_GAS || mat->density == LM_DENSITY_CONTINUITY) continue;
        if (mat->density == LM_DENSITY_QUADRATIC) {
            p->rho[q] = quadratic_density(g, rc, p->x[q], p->y[q]);   /* eq 4.6 */
        } else {
            int i, j;
            double dx, dy;
            cell_of(g, p->x[q], p->y[q], &i, &j, &dx, &dy);
            p->rho[q] = rc[(size_t)j * g->nx + i];
        }
    }
    return LM_OK;
}
