/* stress_cell.c - the internal force from cell-centred stresses, [T] §5.4.3.
 *
 * [T] §5.4.3 traces the noise of points crossing cell edges to the
 * piecewise-constant gradient of the bilinear basis: the contribution
 * -V_p sigma_p . grad N_i(x_p) of a point that has just crossed changes
 * sign (App. A.2, Figs 103-104), and "an algorithm to use a cell-centered
 * stress to calculate the internal forces instead of using the stress of
 * each material point was somewhat successful". The text gives no formula;
 * lamina's form (sim{stress = "cell"}):
 *
 *   V_c = sum_{p in c} V_p,   sigma_c = sum_{p in c} V_p sigma_p / V_c,
 *   f_i^int = -sum_c V_c sigma_c . grad N_i(x_c),
 *
 * x_c the centre of cell c, "p in c" the cell holding x_p^k (the cell of
 * its shape functions). V_c sigma_c = sum V_p sigma_p, so this is the
 * papers' quadrature with each point's gradient replaced by the one at its
 * cell's centre: within a cell a point's force no longer depends on where
 * it sits, and the stress it carries is pooled with its cell-mates'.
 * Sum_i grad N_i = 0 at every x keeps sum_i f_i = 0 (momentum), and a
 * uniform stress over cells of equal volume leaves the interior nodes
 * without force (the four cells round a node send equal and opposite
 * shares). Membrane points with segment forces keep their own forces,
 * spread with N_ip as in step.c (docs/physics.md §5b).
 *
 * One thread: the cell sums are cheap beside the step, and one thread
 * keeps the state the same for every thread count. */
#include <string.h>

#include "step.h"

void lm_stress_cell_forces(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    size_t nc = (size_t)g->nx * (size_t)g->ny;
    /* per cell: sum V sigma_xx, sigma_xy, sigma_yy (V_c itself is not
     * needed: V_c sigma_c is the sum); allocated with the grid by
     * lm_sim_new, which reports a failure as its error */
    double *s = sim->work->cell_stress;
    memset(s, 0, 3 * nc * sizeof *s);
    int stride = g->nx + 1;
    for (size_t q = 0; q < p->n; q++) {
        const lm_body *bd = &sim->bodies[p->body[q]];
        int node = p->node[q];
        if (bd->membrane && bd->force == LM_MFORCE_SEGMENT) {
            static const int dx[4] = {0, 1, 0, 1}, dy[4] = {0, 0, 1, 1};
            double N[4];
            lm_bilinear_N(p->xi[q], p->eta[q], N);
            for (int k = 0; k < 4; k++) {
                int i = node + dy[k] * stride + dx[k];
                g->fx[i] += N[k] * p->fpx[q];
                g->fy[i] += N[k] * p->fpy[q];
            }
            continue;
        }
        size_t c = (size_t)(node / stride) * (size_t)g->nx + (size_t)(node % stride);
        double V = p->m[q] / p->rho[q];
        s[3 * c] += V * p->sxx[q];
        s[3 * c + 1] += V * p->sxy[q];
        s[3 * c + 2] += V * p->syy[q];
    }
    /* grad N at the centre of a cell, corners (i,j) (i+1,j) (i,j+1) (i+1,j+1) */
    double ax = 0.5 / g->hx, ay = 0.5 / g->hy;
    const double gx[4] = {-ax, ax, -ax, ax}, gy[4] = {-ay, -ay, ay, ay};
    for (int j = 0; j < g->ny; j++) {
        for (int i = 0; i < g->nx; i++) {
            size_t c = (size_t)j * (size_t)g->nx + (size_t)i;
            double sxx = s[3 * c], sxy = s[3 * c + 1], syy = s[3 * c + 2];
            if (sxx == 0 && sxy == 0 && syy == 0) continue;
            int node = j * stride + i;
            for (int k = 0; k < 4; k++) {
                int n = node + (k >> 1) * stride + (k & 1);
                g->fx[n] -= sxx * gx[k] + sxy * gy[k];
                g->fy[n] -= sxy * gx[k] + syy * gy[k];
            }
        }
    }
}
