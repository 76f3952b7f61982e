/* subcycle_runs.c - the membranes' grid sums of a sub-step, point after
 * point along the curve (multi-rate stepping, subcycle.c; issue 36 item 1).
 *
 * Why. A membrane's points are seeded along its curve, many to a cell (Box
 * 9's dog-bone: 600 points 3.7e-3 apart on cells of 0.05, about 13 a
 * cell), so consecutive points mostly share their stencil. Added point by
 * point into the grid (lm_k_scatter_mass_forces), each of the 45 sums a
 * point makes is a load, an add and a store to the address the previous
 * point has just stored to: a chain through memory, and on the dog-bone
 * the membranes' sums were the largest part of a sub-step (14 % of the
 * whole run, docs/performance.md "The sub-steps' nodes"). Here a run of
 * points with the same stencil corner adds into the stencil's 45 sums held
 * in registers, loaded once from the grid and stored once when the corner
 * changes. Every node still receives the same additions in the same order
 * (its partial sum is loaded, the run's points add to it in particle
 * order, the result is stored before any later point's), with the same
 * expressions as step_kernels.h's: the same bits. */
#include "subcycle_runs.h"
#include "step_kernels.h"

/* The stencil's sums of the run in `acc`, nf fields, nodes at[]. */
static LM_FORCE_INLINE void load(double *const *f, int nf, double acc[5][9], const long at[9],
                                 const int NS)
{
    for (int c = 0; c < nf; c++)
        for (int k = 0; k < NS; k++) acc[c][k] = f[c][at[k]];
}
static LM_FORCE_INLINE void store(double *const *f, int nf, double acc[5][9], const long at[9],
                                  const int NS)
{
    for (int c = 0; c < nf; c++)
        for (int k = 0; k < NS; k++) f[c][at[k]] = acc[c][k];
}
static LM_FORCE_INLINE void corner(const lm_grid *g, int node, long at[9], const int W)
{
    for (int b = 0; b < W; b++)
        for (int a = 0; a < W; a++) at[b * W + a] = lm_stencil_row(g, node, b) + a;
}

/* forces = 1: the five sums of lm_k_scatter_mass_forces (segs = 1);
 * forces = 0: the two of lm_k_scatter_momentum (mass = 0). */
static LM_FORCE_INLINE void runs(const lm_sim *sim, double *const *f, const int W,
                                 const int forces)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const double rx = 1.0 / g->hx, ry = 1.0 / g->hy;
    const int NS = W * W, nf = forces ? 5 : 2;
    double acc[5][9];
    long at[9] = {0};
    int cur = -1;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        if (!bd->membrane) continue;
        for (size_t q = bd->first; q < bd->first + bd->count; q++) {
            if (p->node[q] != cur) {
                if (cur >= 0) store(f, nf, acc, at, NS);
                cur = p->node[q];
                corner(g, cur, at, W);
                load(f, nf, acc, at, NS);
            }
            double Nl[9], Gxl[9], Gyl[9];
            const double m = p->m[q], vx = p->vx[q], vy = p->vy[q];
            const double *N = lm_k_weights_N(p, q, W, Nl);
            if (!forces) {
                for (int k = 0; k < NS; k++) {
                    double w = m * N[k];
                    acc[0][k] += w * vx;
                    acc[1][k] += w * vy;
                }
                continue;
            }
            const int seg = lm_k_segment_point(sim, q);
            const lm_k_force_src s = lm_k_force_source(p, q, seg, W, rx, ry, Gxl, Gyl);
            for (int k = 0; k < NS; k++) {
                double w = m * N[k];
                acc[0][k] += w;
                acc[1][k] += w * vx;
                acc[2][k] += w * vy;
                if (seg) {
                    acc[3][k] += N[k] * s.fpx;
                    acc[4][k] += N[k] * s.fpy;
                } else {
                    double gx = s.Gx[k], gy = s.Gy[k];
                    acc[3][k] -= s.V * (s.sxx * gx + s.sxy * gy);
                    acc[4][k] -= s.V * (s.sxy * gx + s.syy * gy);
                }
            }
        }
    }
    if (cur >= 0) store(f, nf, acc, at, NS);
}

void lm_runs_mass_forces(const lm_sim *sim, double *const *f)
{
    if (sim->grid.sw == 2) runs(sim, f, 2, 1);
    else runs(sim, f, 3, 1);
}

void lm_runs_momentum(const lm_sim *sim, double *const *f)
{
    if (sim->grid.sw == 2) runs(sim, f, 2, 0);
    else runs(sim, f, 3, 0);
}
