/* subcycle_band.c - the membranes' sub-steps sweep only the nodes near the
 * membranes (multi-rate stepping, subcycle.c; issue 36 item 1).
 *
 * Why. Within a step of the slow group (subcycle.c's header), a sub-step
 * changes a node's sums only where a membrane's stencil reaches it: every
 * other node has m^M = p^M = f^M = 0 throughout, so it carries the slow
 * group's held m^G, f^G and its own p^G, and its sub-step s is
 *     P = p^G + dt f^G (the walls zero components), a = F / M, v = P / M,
 *     p^G += dt m^G a,  A += dt a,  X += dt v,  V = v
 * with nothing from any other node (the walls act node by node; a ghost
 * node takes its mirror's value, below). Sweeping the whole grid k times a
 * step (about 20 arrays of every node) for that was about 7 % of Box 9's
 * dog-bone run at 16 x (docs/performance.md, "The sub-steps' nodes": the
 * rest of a sub-step is the membrane points' own arithmetic, which no band
 * shrinks). Here the sub-steps sweep the band, a list of the nodes the
 * membranes' stencils can reach within the step, and every other node runs
 * the same k-fold recurrence once a step in one tight loop (lm_band_far):
 * the same operations in the same order on the same operands, so the same
 * bits (tests/physics/substeps_band.lua pins the state hashes computed with
 * the whole-grid sweep). Not the closed form A = Dt a: that differs from k
 * additions of dt a in the last bits and would change every state hash.
 *
 * The band. What a sub-step reads at a node the membranes do not reach:
 * with USL nothing (the membranes' G2P, strain and sums are on their
 * stencils); with MUSL the slow group's re-map (subcycle.c, slow_remap)
 * reads A up to W - 1 nodes beyond the stencils (its consistent mass
 * couples the nodes of a particle's stencil; what it writes further out no
 * membrane reads, and the step's end overwrites it). That is `need`, 0 or
 * W - 1. The band: the stencils of the membrane points at x^n widened by
 * need + 1 nodes each way, the one for their motion (a point moves less
 * than a cell in a step within the slow group's Courant limit, so its
 * stencil's corner moves at most one node), then closed under the walls'
 * images: a ghost node and its mirror (and a corner's chain of them) are
 * in the band together, as the folds add ghosts into mirrors and the fills
 * copy mirrors out (grid_walls.c). Every sub-step checks each stencil's
 * corner against the core (a stencil from there lies in the band with all
 * within `need` of it: one look-up a point); should a
 * point move further (a violent run), lm_band_grow widens the band within
 * the step and brings the nodes it takes in to the present sub-step by the
 * same recurrence, so the result never depends on the margin, only the
 * time does (tests/physics/substeps_band.lua's falling arc).
 *
 * A ghost node outside the band: the recurrence gives it nothing (it has
 * no mass behind a wall); at the step's end A, X and V are filled from the
 * mirrors, which is what the sweep's accumulation of the filled a, v gave
 * (each term's sign flips exactly, so the sum is the mirror's with the
 * image's sign, to the bit). */
#include <stdlib.h>
#include <string.h>

#include "step.h"
#include "step_kernels.h"
#include "subcycle_band.h"
#include "util.h"

lm_band *lm_band_new(const lm_grid *g)
{
    size_t nn = lm_grid_nodes(g);
    lm_band *b = calloc(1, sizeof *b);
    if (!b) return NULL;
    b->nn = nn;
    b->idx = malloc(nn * sizeof *b->idx);
    b->in = calloc(nn, 1);
    b->old = calloc(nn, 1);
    b->core = calloc(nn, 1);
    b->zero = calloc(nn, 1);
    b->mark = malloc(2 * nn * sizeof *b->mark);
    if (!b->idx || !b->in || !b->old || !b->core || !b->zero || !b->mark) {
        lm_band_free(b);
        return NULL;
    }
    /* which components the walls zero, node by node */
    double *ux = b->mark, *uy = b->mark + nn;
    for (size_t i = 0; i < nn; i++) ux[i] = uy[i] = 1;
    lm_grid_apply_bc(g, ux, uy);
    for (size_t i = 0; i < nn; i++)
        b->zero[i] = (unsigned char)((ux[i] == 0 ? 1 : 0) | (uy[i] == 0 ? 2 : 0));
    return b;
}

void lm_band_free(lm_band *b)
{
    if (!b) return;
    LU_FREE_ALL(b->idx, b->in, b->old, b->core, b->zero, b->mark, b);
}

/* in = the membranes' present stencils widened by reach, closed under the
 * walls' images. */
static void mark_band(lm_band *b, const lm_sim *sim, int reach)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const long nn = (long)b->nn, sx = g->sx;
    const int W = g->sw;
    unsigned char *in = b->in, *t = b->old;   /* old: scratch here */
    memset(in, 0, b->nn);
    for (int k = 0; k < sim->nbodies; k++) {
        const lm_body *bd = &sim->bodies[k];
        if (!bd->membrane) continue;
        for (size_t q = bd->first; q < bd->first + bd->count; q++)
            for (int r = 0; r < W; r++) {
                const long row = lm_stencil_row(g, p->node[q], r);
                for (int a = 0; a < W; a++) in[row + a] = 1;
            }
    }
    /* widen along x, then along y (a square of 2 reach + 1 nodes); an
     * index beyond a row's end wraps to the next row's start: a few nodes
     * more, never fewer */
    memset(t, 0, b->nn);
    for (long i = 0; i < nn; i++) {
        if (!in[i]) continue;
        for (long d = -reach; d <= reach; d++)
            if (i + d >= 0 && i + d < nn) t[i + d] = 1;
    }
    memset(in, 0, b->nn);
    for (long i = 0; i < nn; i++) {
        if (!t[i]) continue;
        for (long d = -reach; d <= reach; d++)
            if (i + d * sx >= 0 && i + d * sx < nn) in[i + d * sx] = 1;
    }
    /* the walls' images: a scalar folded (mirror += ghost) and filled back
     * (ghost = mirror) marks both of every pair, corners through their
     * chain (x sides first, then y, as grid_walls.c); twice, so that a
     * chain marked from its far end closes too */
    double *m = b->mark;
    double *const f[1] = {m};
    static const lm_comp comp[1] = {LM_COMP_SCALAR};
    for (int pass = 0; pass < 2; pass++) {
        for (long i = 0; i < nn; i++) m[i] = in[i];
        lm_grid_fold(g, 1, f, comp);
        lm_grid_fill(g, 1, f, comp);
        for (long i = 0; i < nn; i++)
            if (m[i] > 0) in[i] = 1;
    }
}

/* The list, and the core: `in` narrowed to the corners of W x W stencils
 * whose nodes all have every node within need in the band, i.e. along x
 * and then along y the nodes i with [i - need, i + W - 1 + need] in it. An
 * index beyond the grid's ends counts as in (no such node, nothing reads
 * it: a stencil on the ghost ring is not held to nodes that do not exist);
 * one beyond a row's end wraps to the next row, which is only stricter. */
static void list_band(lm_band *b, long sx, int W)
{
    const long nn = (long)b->nn, lo = -b->need, hi = W - 1 + b->need;
    unsigned char *t = b->old;   /* scratch */
    for (long i = 0; i < nn; i++) {
        unsigned char c = 1;
        for (long d = lo; d <= hi && c; d++) c = i + d < 0 || i + d >= nn || b->in[i + d];
        t[i] = c;
    }
    for (long i = 0; i < nn; i++) {
        unsigned char c = 1;
        for (long d = lo; d <= hi && c; d++)
            c = i + d * sx < 0 || i + d * sx >= nn || t[i + d * sx];
        b->core[i] = c;
    }
    b->n = 0;
    for (long i = 0; i < nn; i++)
        if (b->in[i]) b->idx[b->n++] = i;
}

void lm_band_build(lm_band *b, const lm_sim *sim, int need)
{
    b->need = need;
    mark_band(b, sim, need + 1);
    list_band(b, sim->grid.sx, sim->grid.sw);
}

/* Nodes[0..nb) (nb <= LM_BAND_BLOCK) through n sub-steps of dt, as
 * subcycle.c's sub_step sweeps a node no membrane reaches (m^M = p^M = f^M
 * = +0: the same additions, so the same bits); the grid's arrays left as
 * the last of them left them. A block at a time: each node's sums are a
 * chain of dependent additions, and the nodes of a block interleave. */
#define LM_BAND_BLOCK 8
static void advance(lm_grid *g, const lm_band_nodes *a, const unsigned char *zero,
                    const long *nodes, int nb, int n, double dt)
{
    double mG[LM_BAND_BLOCK], fGx[LM_BAND_BLOCK], fGy[LM_BAND_BLOCK];
    double pGx[LM_BAND_BLOCK], pGy[LM_BAND_BLOCK], Ax[LM_BAND_BLOCK], Ay[LM_BAND_BLOCK];
    double Xx[LM_BAND_BLOCK], Xy[LM_BAND_BLOCK], vx[LM_BAND_BLOCK], vy[LM_BAND_BLOCK];
    double m[LM_BAND_BLOCK], px[LM_BAND_BLOCK], py[LM_BAND_BLOCK], fx[LM_BAND_BLOCK];
    double fy[LM_BAND_BLOCK], ax[LM_BAND_BLOCK], ay[LM_BAND_BLOCK];
    int zx[LM_BAND_BLOCK], zy[LM_BAND_BLOCK];
    if (n <= 0) return;
    for (int j = 0; j < nb; j++) {
        const long i = nodes[j];
        mG[j] = a->mG[i];
        fGx[j] = a->fGx[i];
        fGy[j] = a->fGy[i];
        zx[j] = zero[i] & 1;
        zy[j] = zero[i] & 2;
        pGx[j] = a->pGx[i];
        pGy[j] = a->pGy[i];
        Ax[j] = a->Ax[i];
        Ay[j] = a->Ay[i];
        Xx[j] = a->Xx[i];
        Xy[j] = a->Xy[i];
    }
    /* what does not change from sub-step to sub-step, worked out once by
     * the same operations: M, F after the walls, 1 / M, a */
    double r[LM_BAND_BLOCK];
    for (int j = 0; j < nb; j++) {
        m[j] = mG[j] + 0.0;                 /* M = m^G + m^M */
        fx[j] = zx[j] ? 0 : fGx[j] + 0.0;   /* F = f^G + f^M, the walls */
        fy[j] = zy[j] ? 0 : fGy[j] + 0.0;
        r[j] = m[j] > 0 ? 1.0 / m[j] : 0;   /* lm_step_g2p_nodes */
        ax[j] = fx[j] * r[j];
        ay[j] = fy[j] * r[j];
    }
    for (int s = 0; s < n; s++)
        for (int j = 0; j < nb; j++) {
            px[j] = pGx[j] + 0.0;           /* P = p^G + p^M */
            py[j] = pGy[j] + 0.0;
            px[j] += dt * fx[j];            /* lm_step_grid_update (F is zeroed */
            py[j] += dt * fy[j];            /* only where P is, just below) */
            if (zx[j]) px[j] = 0;           /* lm_grid_apply_bc on P */
            if (zy[j]) py[j] = 0;
            vx[j] = px[j] * r[j];
            vy[j] = py[j] * r[j];
            pGx[j] += dt * mG[j] * ax[j];   /* sub_step's accumulation */
            pGy[j] += dt * mG[j] * ay[j];
            Ax[j] += dt * ax[j];
            Ay[j] += dt * ay[j];
            Xx[j] += dt * vx[j];
            Xy[j] += dt * vy[j];
        }
    for (int j = 0; j < nb; j++) {
        const long i = nodes[j];
        g->m[i] = m[j];
        g->px[i] = px[j];
        g->py[i] = py[j];
        g->fx[i] = fx[j];
        g->fy[i] = fy[j];
        g->ax[i] = ax[j];
        g->ay[i] = ay[j];
        a->pGx[i] = pGx[j];
        a->pGy[i] = pGy[j];
        a->Ax[i] = Ax[j];
        a->Ay[i] = Ay[j];
        a->Xx[i] = Xx[j];
        a->Xy[i] = Xy[j];
        a->Vx[i] = vx[j];
        a->Vy[i] = vy[j];
    }
}

/* Every node outside `in` through n sub-steps, in blocks. */
static void advance_outside(lm_grid *g, const lm_band_nodes *a, const unsigned char *zero,
                            const unsigned char *in, size_t nn, int n, double dt)
{
    long blk[LM_BAND_BLOCK];
    int nb = 0;
    for (size_t i = 0; i < nn; i++) {
        if (in[i]) continue;
        blk[nb++] = (long)i;
        if (nb == LM_BAND_BLOCK) {
            advance(g, a, zero, blk, nb, n, dt);
            nb = 0;
        }
    }
    if (nb) advance(g, a, zero, blk, nb, n, dt);
}

/* A, X, V of the ghost nodes from their mirrors (see the header). */
static void fill_ghosts(const lm_grid *g, const lm_band_nodes *a)
{
    double *const f[6] = {a->Ax, a->Ay, a->Xx, a->Xy, a->Vx, a->Vy};
    static const lm_comp comp[6] = {LM_COMP_X, LM_COMP_Y, LM_COMP_X, LM_COMP_Y, LM_COMP_X,
                                    LM_COMP_Y};
    lm_grid_fill(g, 6, f, comp);
}

/* Does every membrane point's stencil, widened by need, lie in the band? */
static int holds(const lm_band *b, const lm_sim *sim)
{
    const int *node = sim->p.node;
    for (int k = 0; k < sim->nbodies; k++) {
        const lm_body *bd = &sim->bodies[k];
        if (!bd->membrane) continue;
        unsigned char ok = 1;
        for (size_t q = bd->first; q < bd->first + bd->count; q++) ok &= b->core[node[q]];
        if (!ok) return 0;
    }
    return 1;
}

int lm_band_grow(lm_band *b, lm_sim *sim, const lm_band_nodes *a, int done, double dt)
{
    if (holds(b, sim)) return 0;
    unsigned char *was = malloc(b->nn);
    if (!was) {   /* no room to compare: take every node in (still exact) */
        advance_outside(&sim->grid, a, b->zero, b->in, b->nn, done, dt);
        memset(b->in, 1, b->nn);
    } else {
        memcpy(was, b->in, b->nn);
        mark_band(b, sim, b->need + 1);
        for (size_t i = 0; i < b->nn; i++) {   /* was: the nodes to leave */
            if (was[i]) b->in[i] = 1;
            else was[i] = !b->in[i];
        }
        advance_outside(&sim->grid, a, b->zero, was, b->nn, done, dt);
        free(was);
    }
    fill_ghosts(&sim->grid, a);
    list_band(b, sim->grid.sx, sim->grid.sw);
    return 1;
}

void lm_band_zero(const lm_band *b, int nf, double *const *f)
{
    for (int c = 0; c < nf; c++)
        for (size_t r = 0; r < b->n; r++) f[c][b->idx[r]] = 0;
}

void lm_band_grid_update(lm_sim *sim, const lm_band *b)
{
    lm_grid *g = &sim->grid;
    const double dt = sim->def.dt;
    for (size_t r = 0; r < b->n; r++) {
        const long i = b->idx[r];
        g->px[i] += dt * g->fx[i];
        g->py[i] += dt * g->fy[i];
    }
    lm_grid_apply_bc(g, g->px, g->py);
    lm_grid_apply_bc(g, g->fx, g->fy);
}

void lm_band_g2p_nodes(lm_sim *sim, const lm_band *b, double *ux, double *uy)
{
    lm_grid *g = &sim->grid;
    for (size_t r = 0; r < b->n; r++) lm_k_g2p_node(g, b->idx[r], ux, uy);
    lm_step_fill_g2p_nodes(g, ux, uy);
}

void lm_band_remap_end(lm_sim *sim, const lm_band *b)
{
    lm_grid *g = &sim->grid;
    for (size_t r = 0; r < b->n; r++) {
        const long i = b->idx[r];
        if (g->m[i] > 0) {
            g->vx[i] /= g->m[i];
            g->vy[i] /= g->m[i];
        }
    }
    lm_grid_apply_bc(g, g->vx, g->vy);
    double *const fill[2] = {g->vx, g->vy};
    static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
    lm_grid_fill(g, 2, fill, comp);
}

void lm_band_far(lm_sim *sim, const lm_band *b, const lm_band_nodes *a, int k, double dt)
{
    lm_grid *g = &sim->grid;
    advance_outside(g, a, b->zero, b->in, b->nn, k, dt);
    fill_ghosts(g, a);
}

void lm_band_all(lm_band *b)
{
    for (size_t i = 0; i < b->nn; i++) {
        b->in[i] = 1;
        b->core[i] = 1;
        b->idx[i] = (long)i;
    }
    b->n = b->nn;
}
