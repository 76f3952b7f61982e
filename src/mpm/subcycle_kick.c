/* subcycle_kick.c - the impulse forms' sub-steps after the kick sweep only
 * the nodes the membranes can change (multi-rate stepping, subcycle.c;
 * issue 36 item 1; docs/performance.md "The impulse sub-steps' cost").
 *
 * Why. With multirate = "impulse" (and "half") the slow group's force acts
 * in the first sub-step alone (weight k, then 0) and its nodal momentum is
 * the consistent re-map p^G = q^G + fold(C A) on every node (subcycle.c's
 * header). The first sub-step changes every node (the kick), so it is swept
 * whole. After it, at a node i no membrane stencil reaches, F_i = 0 f^G_i +
 * f^M_i = +0, so a_i = +0 and A_i no longer changes; A changes only on the
 * membranes' stencils (and their ghost images, filled from them). Then p^G_i
 * changes only where row i of C reads such a node, directly (offsets up to
 * W - 1) or through a ghost row folded into it. Every other node carries
 * constants through the remaining sub-steps:
 *     M = m^G + 0, F = 0 f^G + 0, P = p^G + 0, P += dt F, the walls,
 *     a = F / M, v = P / M, A += dt a, X += dt v, V = v,
 *     MUSL: v^R = (0 + p^G) / M, the walls, R += dt v^R,
 * with p^G as the kick's re-map left it (the same row sum of the same
 * operands gives the same bits every sub-step). The sub-steps after the
 * kick sweep the band (the nodes whose p^G can change) and every other node
 * runs that recurrence once a step (lm_kick_band_far): the same operations
 * in the same order on the same operands, so the same bits
 * (tests/physics/substeps_impulse_band.lua pins the state hashes computed
 * with the whole-grid sweep). On Box 9's dog-bone at 16 x that takes the
 * re-map's row products and the node sweeps of 15 sub-steps out of 16 from
 * the whole grid to the band.
 *
 * The band: S, the membranes' stencils at x^n widened by one node (their
 * motion within the step: less than a cell within the slow group's Courant
 * limit), closed under the walls' images; then the rows that read S: S
 * widened by W - 1 nodes each way, a ghost's mark folded into its mirror
 * (the re-map's fold) and filled back, twice for a corner's chain (as
 * subcycle_band.c's mark_band). Each sub-step checks every membrane
 * stencil's corner against S's core; should a point leave it, the nodes
 * outside the band are brought to that sub-step by the recurrence and the
 * rest of the step sweeps every node: the margin sets the time, never the
 * result. Ghost nodes outside the band: their A, X, V, R are their mirrors'
 * with the image's sign at the end (subcycle_band.c says why that is the
 * sweep's sum to the bit). */
#include <stdlib.h>
#include <string.h>

#include "subcycle_kick.h"

int lm_kick_banded(const lm_sim *sim)
{
    return sim->def.multirate == LM_MULTIRATE_IMPULSE || sim->def.multirate == LM_MULTIRATE_HALF;
}

/* in |= in widened by r nodes each way (a square); an index beyond a row's
 * end wraps to the next row's start: a few nodes more, never fewer. */
static void widen(lm_band *b, long sx, int r)
{
    const long nn = (long)b->nn;
    unsigned char *in = b->in, *t = b->old;
    memset(t, 0, b->nn);
    for (long i = 0; i < nn; i++) {
        if (!in[i]) continue;
        for (long d = -r; d <= r; d++)
            if (i + d >= 0 && i + d < nn) t[i + d] = 1;
    }
    for (long i = 0; i < nn; i++) {
        if (!t[i]) continue;
        for (long d = -r; d <= r; d++)
            if (i + d * sx >= 0 && i + d * sx < nn) in[i + d * sx] = 1;
    }
}

/* in closed under the walls' fold (a ghost's mark into its mirror) and fill
 * (a mirror's out to its ghost), twice for a corner's chain. */
static void close_images(lm_band *b, const lm_grid *g)
{
    double *m = b->mark;
    double *const f[1] = {m};
    static const lm_comp comp[1] = {LM_COMP_SCALAR};
    for (int pass = 0; pass < 2; pass++) {
        for (size_t i = 0; i < b->nn; i++) m[i] = b->in[i];
        lm_grid_fold(g, 1, f, comp);
        lm_grid_fill(g, 1, f, comp);
        for (size_t i = 0; i < b->nn; i++)
            if (m[i] > 0) b->in[i] = 1;
    }
}

void lm_kick_band_build(lm_band *b, const lm_sim *sim)
{
    const lm_grid *g = &sim->grid;
    lm_band_build(b, sim, 0);   /* in, core: S */
    widen(b, g->sx, g->sw - 1);
    close_images(b, g);
    b->n = 0;
    for (size_t i = 0; i < b->nn; i++)
        if (b->in[i]) b->idx[b->n++] = (long)i;
}

/* Does every membrane point's stencil lie in S? */
static int holds(const lm_band *b, const lm_sim *sim)
{
    const int *node = sim->p.node;
    unsigned char ok = 1;
    for (int k = 0; k < sim->nbodies; k++) {
        const lm_body *bd = &sim->bodies[k];
        if (!bd->membrane) continue;
        for (size_t q = bd->first; q < bd->first + bd->count; q++) ok &= b->core[node[q]];
    }
    return ok;
}

/* Node i (outside the band) through sub-steps [from, to) of dt, as
 * subcycle.c's sub_step sweeps it after the kick (see the header: m^M =
 * p^M = f^M = +0 there, the slow force's weight 0); the grid's arrays left
 * as the last of them left them. */
static void advance(lm_grid *g, const lm_band_nodes *a, double *Rx, double *Ry, unsigned char z,
                    long i, int from, int to, double dt, int musl)
{
    const double mG = a->mG[i], pGx = a->pGx[i], pGy = a->pGy[i];
    const int zx = z & 1, zy = z & 2;
    double Ax = a->Ax[i], Ay = a->Ay[i], Xx = a->Xx[i], Xy = a->Xy[i];
    double Rxi = Rx[i], Ryi = Ry[i];
    double m = g->m[i], px = g->px[i], py = g->py[i], fx = g->fx[i], fy = g->fy[i];
    double ax = g->ax[i], ay = g->ay[i], vx = a->Vx[i], vy = a->Vy[i];
    for (int s = from; s < to; s++) {
        m = mG + 0.0;                        /* M = m^G + m^M */
        px = pGx + 0.0;                      /* P = p^G + p^M */
        py = pGy + 0.0;
        fx = 0.0 * a->fGx[i] + 0.0;          /* F = w f^G + f^M, w = 0 */
        fy = 0.0 * a->fGy[i] + 0.0;
        px += dt * fx;                       /* lm_band_grid_update */
        py += dt * fy;
        if (zx) px = fx = 0;                 /* the walls on P and F */
        if (zy) py = fy = 0;
        const double r = m > 0 ? 1.0 / m : 0;   /* lm_band_g2p_nodes */
        ax = fx * r;
        ay = fy * r;
        vx = px * r;
        vy = py * r;
        Ax += dt * ax;                       /* sub_step's accumulation (p^G */
        Ay += dt * ay;                       /* is the re-map's: unchanged) */
        Xx += dt * vx;
        Xy += dt * vy;
        if (musl) {                          /* fast_remap's zero + p^G, */
            double ux = 0.0 + pGx, uy = 0.0 + pGy;   /* lm_band_remap_end */
            if (m > 0) {
                ux /= m;
                uy /= m;
            }
            if (zx) ux = 0;
            if (zy) uy = 0;
            Rxi += dt * ux;                  /* mr_remapped_displacement */
            Ryi += dt * uy;
        }
    }
    g->m[i] = m;
    g->px[i] = px;
    g->py[i] = py;
    g->fx[i] = fx;
    g->fy[i] = fy;
    g->ax[i] = ax;
    g->ay[i] = ay;
    a->Ax[i] = Ax;
    a->Ay[i] = Ay;
    a->Xx[i] = Xx;
    a->Xy[i] = Xy;
    a->Vx[i] = vx;
    a->Vy[i] = vy;
    Rx[i] = Rxi;
    Ry[i] = Ryi;
}

/* Every node outside the band through sub-steps [from, to), then the ghost
 * nodes' sums from their mirrors. */
static void advance_outside(lm_sim *sim, const lm_band *b, const lm_band_nodes *a, double *Rx,
                            double *Ry, int from, int to, double dt)
{
    lm_grid *g = &sim->grid;
    const int musl = sim->def.scheme == LM_MUSL;
    if (to > from)
        for (size_t i = 0; i < b->nn; i++)
            if (!b->in[i]) advance(g, a, Rx, Ry, b->zero[i], (long)i, from, to, dt, musl);
    double *const f[8] = {a->Ax, a->Ay, a->Xx, a->Xy, a->Vx, a->Vy, Rx, Ry};
    static const lm_comp comp[8] = {LM_COMP_X, LM_COMP_Y, LM_COMP_X, LM_COMP_Y,
                                    LM_COMP_X, LM_COMP_Y, LM_COMP_X, LM_COMP_Y};
    lm_grid_fill(g, musl ? 8 : 6, f, comp);
}

int lm_kick_band_grow(lm_band *b, lm_sim *sim, const lm_band_nodes *a, double *Rx, double *Ry,
                      int done, double dt)
{
    if (holds(b, sim)) return 0;
    advance_outside(sim, b, a, Rx, Ry, 1, done, dt);
    return 1;
}

void lm_kick_band_far(lm_sim *sim, const lm_band *b, const lm_band_nodes *a, double *Rx,
                      double *Ry, int k, double dt)
{
    advance_outside(sim, b, a, Rx, Ry, 1, k, dt);
}
