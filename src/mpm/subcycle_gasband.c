/* subcycle_gasband.c - the gas points beside the membranes in the
 * sub-steps' fast group (lamina.sim{substeps, fast_band = w}; issue 36
 * item 1; docs/performance.md "The gas beside the membranes in the fast
 * group").
 *
 * Why. With the membranes alone in the fast group the interface between
 * the groups is the membrane itself: every node a membrane point reaches
 * also carries gas, whose force is held over the step (or kicked), and on
 * Box 9's dog-bone it is a gas point beside the membrane that goes
 * unstable (docs/performance.md "Multi-rate stepping"). Spatial
 * subcycling (Belytschko, Yen & Mullen 1979, "Mixed methods for time
 * integration", Comput. Methods Appl. Mech. Eng. 17/18: the mesh split
 * into a small-step and a large-step part, the interface nodes advanced
 * with the small step; Smolinski, Belytschko & Neal 1988 for its
 * stability) puts the interface where the solution is smooth: here the
 * fast group is the membranes plus every gas point in a band around
 * them, so that the nodes a membrane touches carry only fast points' forces,
 * remade every sub-step, and the held (or kicked) slow force meets the
 * fast group inside the gas, w cells or more from any membrane.
 *
 * Which points. At each step's start, with the stencils at x^n: a node's
 * distance is the number of cells (Chebyshev, on the node lattice) to the
 * nearest node a membrane point's stencil reaches; a gas point's is the
 * least over its own stencil's nodes (0: it shares a node with a membrane
 * point). It joins at distance <= w and leaves at > w + 1 (hysteresis, so
 * that a point at the edge does not change group every step). A point
 * changes group only between steps, when both groups stand at the same
 * time t^n with their whole state (x, v, stress, e, rho of t^n): nothing
 * is carried half-way.
 *
 * What a fast gas point does (subcycle.c calls these): it is in the fast
 * sums of every sub-step (mass, momentum, the force of its present stress),
 * moves with the sub-steps' FLIP update, is re-mapped with the membranes
 * (MUSL), and its stress, e and rho are updated every sub-step over dt / k
 * from the sub-step's strain velocity (material_gas.c's update, the same as
 * the plain step's at that dt); the slow group's end-of-step update leaves
 * it out.
 *
 * The far gas (held form). A node no fast point reaches in any sub-step has
 * only the slow gas's held force f^G: over the k sub-steps its velocity
 * change is A = Dt a (a = f^G / m^G, the walls applied) as the plain step's,
 * but its displacement X = sum_s dt v^L_s = Dt v + Dt^2 a (k + 1) / (2k),
 * where the plain step's is Dt v + Dt^2 a. With alpha = (k + 1) / (2k) < 1
 * a mode of frequency w of the slow group has |lambda|^2 = 1 + (1 - alpha)
 * (w Dt)^2 > 1 (docs/performance.md "Why the sub-steps fail here"): on Box
 * 9's dog-bone it inverted a gas point at the centre, far from the
 * membrane, once the band had cured the points beside it. So with
 * fast_band those nodes get the difference ((k - 1) / (2k)) Dt A and step as
 * the plain step at Dt (the lead's "kick's displacement" of that section,
 * which failed at the membrane's nodes; with the band no membrane node is
 * among them). The impulse forms' kick gives those nodes the plain step's
 * displacement already.
 *
 * Not with what reads the whole gas at once: the cells' density
 * (density.c) and the artificial viscosity's maxima ([F] eq 24), nor the
 * axisymmetric hoop term: refused by name. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "subcycle_gasband.h"
#include "step_kernels.h"
#include "util.h"

#define KEEP 7   /* rho, e, q, sxx, syy, sxy, szz */

void lm_gasband_free(lm_gasband *gb)
{
    if (!gb) return;
    LU_FREE_ALL(gb->fast, gb->idx, gb->keep, gb->dist, gb->reach, gb);
}

lm_status lm_gasband_reserve(lm_sim *sim, lm_gasband **gbp)
{
    lm_gasband *gb = *gbp;
    if (!sim->def.fast_band) {
        lm_gasband_free(gb);
        *gbp = NULL;
        return LM_OK;
    }
    if (!gb && !(gb = *gbp = calloc(1, sizeof *gb))) goto oom;
    gb->w = sim->def.fast_band_w;
    size_t n = sim->p.n, nn = lm_grid_nodes(&sim->grid);
    if (n > gb->cap) {
        unsigned char *f = realloc(gb->fast, n);
        if (!f) goto oom;
        memset(f + gb->cap, 0, n - gb->cap);   /* new points start slow */
        gb->fast = f;
        size_t *ix = realloc(gb->idx, n * sizeof *ix);
        if (!ix) goto oom;
        gb->idx = ix;
        double *k = realloc(gb->keep, KEEP * n * sizeof *k);
        if (!k) goto oom;
        gb->keep = k;
        gb->cap = n;
    }
    if (nn != gb->nn) {
        unsigned char *d = realloc(gb->dist, nn);
        if (!d) goto oom;
        gb->dist = d;
        unsigned char *r = realloc(gb->reach, nn);
        if (!r) goto oom;
        gb->reach = r;
        gb->nn = nn;
    }
    return LM_OK;
oom:
    snprintf(sim->err, sizeof sim->err, "out of memory for fast_band's %zu particles", sim->p.n);
    return LM_ERR_MEMORY;
}

const char *lm_gasband_refusal(const lm_sim *sim)
{
    if (!sim->def.fast_band) return NULL;
    if (sim->def.axisym) return "fast_band and axisymmetric = true (the gas's hoop term)";
    for (int m = 0; m < sim->nmats; m++) {
        const lm_material *mat = sim->mats[m];
        if (mat->kind != LM_GAS) continue;
        if (mat->av) return "fast_band and a gas with av (its maxima are over the whole gas)";
        if (mat->density != LM_DENSITY_CONTINUITY)
            return "fast_band and a gas with density from the cells (density.c)";
    }
    return NULL;
}

/* The nodes' distances: 0 where a membrane point's stencil reaches, then
 * one more cell each ring, up to w + 2 ("far"). */
static void node_distances(lm_gasband *gb, const lm_sim *sim)
{
    const lm_grid *g = &sim->grid;
    const int W = g->sw;
    const long sx = g->sx, rows = (long)(gb->nn / (size_t)sx);
    const unsigned char far = (unsigned char)(gb->w + 2);
    memset(gb->dist, far, gb->nn);
    const lm_particles *p = &sim->p;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        if (!bd->membrane) continue;
        for (size_t q = bd->first; q < bd->first + bd->count; q++)
            for (int r = 0; r < W; r++)
                for (int a = 0; a < W; a++) gb->dist[lm_stencil_row(g, p->node[q], r) + a] = 0;
    }
    for (int d = 1; d < far; d++)
        for (long j = 0; j < rows; j++)
            for (long i = 0; i < sx; i++) {
                if (gb->dist[j * sx + i] != d - 1) continue;
                for (long dj = -1; dj <= 1; dj++)
                    for (long di = -1; di <= 1; di++) {
                        long jj = j + dj, ii = i + di;
                        if (jj < 0 || jj >= rows || ii < 0 || ii >= sx) continue;
                        unsigned char *t = &gb->dist[jj * sx + ii];
                        if (*t > d) *t = (unsigned char)d;
                    }
            }
}

void lm_gasband_select(lm_gasband *gb, const lm_sim *sim)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const int W = g->sw;
    node_distances(gb, sim);
    gb->n = 0;
    for (size_t q = 0; q < p->n; q++) {
        if (sim->bodies[p->body[q]].membrane || sim->mats[p->mat[q]]->kind != LM_GAS) {
            gb->fast[q] = 0;
            continue;
        }
        int d = gb->w + 2;
        for (int r = 0; r < W; r++)
            for (int a = 0; a < W; a++) {
                int t = gb->dist[lm_stencil_row(g, p->node[q], r) + a];
                if (t < d) d = t;
            }
        gb->fast[q] = d <= gb->w || (gb->fast[q] && d <= gb->w + 1);
        if (gb->fast[q]) gb->idx[gb->n++] = q;
    }
    gb->steps += 1;
    gb->points += (double)gb->n;
}

void lm_gasband_reach(lm_gasband *gb, const double *mF, int start)
{
    if (start) memset(gb->reach, 0, gb->nn);
    for (size_t i = 0; i < gb->nn; i++) gb->reach[i] |= mF[i] != 0;
}

void lm_gasband_far_displacement(const lm_gasband *gb, const double *Ax, const double *Ay,
                                 double *Xx, double *Xy, int k, double Dt)
{
    const double c = (double)(k - 1) / (2.0 * k) * Dt;
    for (size_t i = 0; i < gb->nn; i++) {
        if (gb->reach[i]) continue;
        Xx[i] += c * Ax[i];
        Xy[i] += c * Ay[i];
    }
}

void lm_gasband_sums(const lm_sim *sim, const lm_gasband *gb, double *const *f)
{
    const double rx = 1.0 / sim->grid.hx, ry = 1.0 / sim->grid.hy;
    for (size_t r = 0; r < gb->n; r++) {
        if (sim->grid.sw == 2) lm_k_scatter_mass_forces(sim, gb->idx[r], rx, ry, f, NULL, 0, 0, 2, 0, 0);
        else lm_k_scatter_mass_forces(sim, gb->idx[r], rx, ry, f, NULL, 0, 0, 3, 0, 0);
    }
}

void lm_gasband_momentum(const lm_sim *sim, const lm_gasband *gb, double *const *f)
{
    for (size_t r = 0; r < gb->n; r++) {
        if (sim->grid.sw == 2) lm_k_scatter_momentum(sim, gb->idx[r], f, NULL, 0, 0, 2, 0, 0);
        else lm_k_scatter_momentum(sim, gb->idx[r], f, NULL, 0, 0, 3, 0, 0);
    }
}

void lm_gasband_shape(lm_sim *sim, const lm_gasband *gb)
{
    const double rx = 1.0 / sim->grid.hx, ry = 1.0 / sim->grid.hy;
    for (size_t r = 0; r < gb->n; r++) lm_k_shape(sim, &sim->p, gb->idx[r], rx, ry);
}

void lm_gasband_g2p(lm_sim *sim, const lm_gasband *gb, double dt, double pic)
{
    lm_grid *g = &sim->grid;
    for (size_t r = 0; r < gb->n; r++) {
        if (g->sw == 2) lm_k_g2p(g, &sim->p, gb->idx[r], dt, pic, g->ax, g->ay, g->vx, g->vy, 2);
        else lm_k_g2p(g, &sim->p, gb->idx[r], dt, pic, g->ax, g->ay, g->vx, g->vy, 3);
    }
}

/* Steps 7-8 for the fast gas points over dt: the plain step's rate (step.c
 * rate_at) without contact (refused by the sub-steps) or the hoop
 * (refused here), and no artificial viscosity (refused here). */
void lm_gasband_stress(lm_sim *sim, const lm_gasband *gb, double dt)
{
    const lm_grid *g = &sim->grid;
    const double rx = 1.0 / g->hx, ry = 1.0 / g->hy;
    for (size_t k = 0; k < gb->n; k++) {
        const size_t q = gb->idx[k];
        lm_rate r;
        memset(&r, 0, sizeof r);
        if (g->sw == 2) lm_k_velocity_gradient(g, &sim->p, q, g->vx, g->vy, r.L, rx, ry, 2);
        else lm_k_velocity_gradient(g, &sim->p, q, g->vx, g->vy, r.L, rx, ry, 3);
        r.dexx = dt * r.L[0];
        r.deyy = dt * r.L[3];
        r.dexy = 0.5 * dt * (r.L[1] + r.L[2]);
        r.w = 0.5 * (r.L[1] - r.L[2]);
        r.dt = dt;
        r.h = g->hx < g->hy ? g->hx : g->hy;
        lm_update_at(sim, q, &r, 0);
    }
}

void lm_gasband_keep(lm_sim *sim, lm_gasband *gb)
{
    const lm_particles *p = &sim->p;
    for (size_t k = 0; k < gb->n; k++) {
        const size_t q = gb->idx[k];
        double *s = gb->keep + KEEP * k;
        s[0] = p->rho[q];
        s[1] = p->e[q];
        s[2] = p->q[q];
        s[3] = p->sxx[q];
        s[4] = p->syy[q];
        s[5] = p->sxy[q];
        s[6] = p->szz[q];
    }
}

void lm_gasband_restore(lm_sim *sim, const lm_gasband *gb)
{
    lm_particles *p = &sim->p;
    for (size_t k = 0; k < gb->n; k++) {
        const size_t q = gb->idx[k];
        const double *s = gb->keep + KEEP * k;
        p->rho[q] = s[0];
        p->e[q] = s[1];
        p->q[q] = s[2];
        p->sxx[q] = s[3];
        p->syy[q] = s[4];
        p->sxy[q] = s[5];
        p->szz[q] = s[6];
    }
}
