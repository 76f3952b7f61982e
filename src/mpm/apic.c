/* apic.c - lamina.sim{transfer = "apic"}: the affine particle-in-cell
 * transfer (Jiang, Schroeder, Selle, Teran and Stomakhin, "The affine
 * particle-in-cell method", ACM Trans. Graph. 34(4) 51, 2015), for the
 * bulk bodies (solids and gases; membranes keep FLIP and their
 * constraints, against their own nodal field: below) on the quadratic
 * B-spline basis.
 *
 * Why (issue 30 item 2, tests/verify/spinning_disk.lua): FLIP's transfers
 * lose a rigidly spinning disk's angular momentum into ringing strain
 * energy (85.4 % kept by t = 0.3 at cell 0.1, the virial's mean stress
 * -13.7 %). APIC carries with each point an affine velocity field C_p as
 * well as v_p, so the grid gets p_i = sum_p m_p N_ip (v_p + C_p (x_i - x_p))
 * and a rigid rotation goes to the grid and back whole: angular momentum is
 * conserved by both transfers (Jiang et al. §5.3). Back from the grid,
 *   v_p = sum_i N_ip v_i,   C_p = (sum_i N_ip v_i (x_i - x_p)^T) D^-1,
 * with D = sum_i N_ip (x_i - x_p)(x_i - x_p)^T = diag(hx^2, hy^2) / 4 for
 * the quadratic B-spline whatever x_p (Jiang et al. §5.1), which is why only that
 * basis is offered (the bilinear and uGIMP D vary with x_p). The velocity
 * is the grid's (PIC's), not FLIP's increment: APIC's affine part keeps
 * the information PIC loses (Jiang et al. §1). The MUSL re-map (step 5) scatters
 * the same affine momentum. x_p is the point's place when the weights were
 * made, x^k = sum_i N_ip x_i (the B-spline reproduces linear fields), also
 * after step 4 moved it.
 *
 * Membranes keep FLIP: on APIC a taut string loses its vibration to the
 * transfers (measured, the walled string over 10 periods at 16 cells:
 * mode 1 7.1 %, mode 2 44.5 %, mode 3 86 % of its energy; at 32 cells 1.0 /
 * 7.1 / 22 %), which FLIP keeps (0.02 / 0.16 / 0.44 %). But FLIP beside
 * APIC on one grid does not conserve momentum: with
 *   v_p' = sum_i N_ip v_i^L + a_p (v_p - sum_i N_ip v_i)
 * (a_p = 1 FLIP, 0 APIC) the step ends with
 *   sum_i p_i + dt sum_i f_i + sum_p a_p m_p (v_p - sum_i N_ip v_i),
 * and the last sum vanishes for a common a_p (sum_p m_p N_ip v_p = p_i; the
 * affine part adds nothing to the total, the B-spline reproducing linear
 * fields) but not over the membranes alone: a skin moving unlike the gas at
 * its nodes hands the gas its velocity and keeps it too. Measured with that
 * coupling: the gas-filled circle at 0.4 cells' spacing (cell 0.05) gained
 * 37.9 % of its energy by t = 0.1 and missed its hoop stress by 37.6 %,
 * the axisymmetric sphere at 0.2 cells 65.9 % and 27.6 % (and inverted at
 * cell 0.025). So a membrane point's FLIP remainder is taken against the
 * membranes' own nodal velocity v^M_i = p^M_i / m^M_i (their points' share
 * of step 1's sums) rather than the shared one:
 *   v_p' = sum_i N_ip v_i^L + (v_p - sum_i N_ip v^M_i)
 *        = FLIP's v_p + dt sum_i N_ip a_i + sum_i N_ip (v_i - v^M_i),
 * whose remainders sum to sum_i (p^M_i - m^M_i v^M_i) = 0: momentum is
 * conserved, and a node no bulk body shares has v_i = v^M_i, so a membrane
 * alone is FLIP to the bit. (With the membranes on APIC as well the circle
 * and sphere pass too, but the strings lose their energy as above.)
 *
 * C_p lives here, one 2 x 2 per point in particle order, zero for a point
 * added since (a split gas point starts without its parent's C). It is not
 * in the checkpoint: sim:checkpoint refuses a sim with this option. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gather.h"
#include "step.h"
#include "util.h"

struct lm_apic {
    double *c;      /* cxx, cxy, cyx, cyy per point */
    size_t n, cap;  /* points with a C; room */
    size_t fresh;   /* the first point added since the last step (n: none) */
    double *mm, *dx, *dy;   /* per node: the membranes' mass, then v_i - v^M_i */
    size_t nodes;           /* room in mm, dx, dy */
    int shared;             /* 1: this step's dx, dy are in use (a membrane
                               and a bulk body on the grid) */
};

int lm_apic_active(const lm_sim *sim)
{
    return sim->def.apic && !sim->contact;
}

void lm_apic_free(struct lm_apic *a)
{
    if (!a) return;
    LU_FREE_ALL(a->c, a->mm, a->dx, a->dy, a);   /* a last: the list is read first */
}

/* Point q takes the affine transfer: not a membrane's, not a pinned one
 * (a pin sets its velocity, and a point-held pin's mass is off the grid:
 * pin.c). */
static int takes(const lm_sim *sim, size_t q)
{
    return !sim->bodies[sim->p.body[q]].membrane && !sim->p.pin[q];
}

lm_status lm_apic_reserve(lm_sim *sim)
{
    if (!lm_apic_active(sim)) return LM_OK;
    if (!sim->work->apic) {
        sim->work->apic = calloc(1, sizeof *sim->work->apic);
        if (!sim->work->apic) goto oom;
    }
    struct lm_apic *a = sim->work->apic;
    size_t n = sim->p.n;
    if (n > a->cap) {
        double *c = realloc(a->c, 4 * n * sizeof *c);
        if (!c) goto oom;
        a->c = c;
        a->cap = n;
    }
    if (n > a->n) memset(a->c + 4 * a->n, 0, 4 * (n - a->n) * sizeof *a->c);
    a->fresh = n > a->n ? a->n : n;
    a->n = n;
    size_t nn = lm_grid_nodes(&sim->grid);
    if (nn > a->nodes) {
        double *f[3] = {realloc(a->mm, nn * sizeof *a->mm), NULL, NULL};
        if (f[0]) a->mm = f[0];
        f[1] = f[0] ? realloc(a->dx, nn * sizeof *a->dx) : NULL;
        if (f[1]) a->dx = f[1];
        f[2] = f[1] ? realloc(a->dy, nn * sizeof *a->dy) : NULL;
        if (!f[2]) goto oom;
        a->dy = f[2];
        a->nodes = nn;
    }
    return LM_OK;
oom:
    snprintf(sim->err, sizeof sim->err, "out of memory for the affine transfer of %zu points",
             sim->p.n);
    return LM_ERR_MEMORY;
}

/* Node i's place. */
static void node_at(const lm_grid *g, int i, double *x, double *y)
{
    *x = g->x0 + (i % g->sx - g->pad) * g->hx;
    *y = g->y0 + (i / g->sx - g->pad) * g->hy;
}

/* x^k = sum_i N_ip x_i: where the weights were made. */
static void weights_place(const lm_grid *g, const lm_weights *wt, int node, double *x, double *y)
{
    const int W = g->sw;
    double sx = 0, sy = 0;
    for (int k = 0; k < W * W; k++) {
        double xi, yi;
        node_at(g, lm_stencil_node(g, W, node, k), &xi, &yi);
        sx += wt->N[k] * xi;
        sy += wt->N[k] * yi;
    }
    *x = sx;
    *y = sy;
}

/* Adds sum_p m_p N_ip C_p (x_i - x_p) to the nodal momenta (ux, uy),
 * folded at the walls: step 1's p_i and MUSL's re-map. */
static void scatter_affine(lm_sim *sim, double *ux, double *uy)
{
    lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const int W = g->sw;
    const double *C = sim->work->apic->c;
    size_t nn = lm_grid_nodes(g);
    /* the ghost nodes of walled sides are zero after the fold that ended
     * the scatter: what lands there now is this sum's alone */
    for (size_t q = 0; q < p->n; q++) {
        if (!takes(sim, q)) continue;
        const double *c = C + 4 * q;
        if (c[0] == 0 && c[1] == 0 && c[2] == 0 && c[3] == 0) continue;
        lm_weights wt;
        lm_weights_of(sim, q, &wt);
        double xp, yp;
        weights_place(g, &wt, p->node[q], &xp, &yp);
        for (int k = 0; k < W * W; k++) {
            int i = lm_stencil_node(g, W, p->node[q], k);
            double xi, yi;
            node_at(g, i, &xi, &yi);
            double dx = xi - xp, dy = yi - yp, mN = p->m[q] * wt.N[k];
            ux[i] += mN * (c[0] * dx + c[1] * dy);
            uy[i] += mN * (c[2] * dx + c[3] * dy);
        }
    }
    (void)nn;
    double *const f[2] = {ux, uy};
    static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
    lm_grid_fold(g, 2, f, comp);
}

/* The affine fit of point q from the nodal velocities (vx, vy) (ghosts
 * filled): its velocity into *vx, *vy (NULL: not wanted), its C into c. */
static void fit(const lm_sim *sim, size_t q, const double *ux, const double *uy, double *vx,
                double *vy, double *c)
{
    const lm_grid *g = &sim->grid;
    const int W = g->sw;
    const double rx = 4 / (g->hx * g->hx), ry = 4 / (g->hy * g->hy);   /* D^-1 */
    lm_weights wt;
    lm_weights_of(sim, q, &wt);
    double xp, yp;
    weights_place(g, &wt, sim->p.node[q], &xp, &yp);
    double sx = 0, sy = 0, bxx = 0, bxy = 0, byx = 0, byy = 0;
    for (int k = 0; k < W * W; k++) {
        int i = lm_stencil_node(g, W, sim->p.node[q], k);
        double xi, yi;
        node_at(g, i, &xi, &yi);
        double N = wt.N[k], dx = xi - xp, dy = yi - yp;
        sx += N * ux[i];
        sy += N * uy[i];
        bxx += N * ux[i] * dx;
        bxy += N * ux[i] * dy;
        byx += N * uy[i] * dx;
        byy += N * uy[i] * dy;
    }
    if (vx) *vx = sx;
    if (vy) *vy = sy;
    c[0] = bxx * rx;
    c[1] = bxy * ry;
    c[2] = byx * rx;
    c[3] = byy * ry;
}

/* A membrane point whose velocity and mass step 1 put on the grid: not a
 * point-held pinned one (its mass is off the grid, its velocity the pin's:
 * pin.c). Its mass there is the wire's share for a heavy end point (the
 * rest is the constraint's, constraint.c). */
static double membrane_mass(const lm_sim *sim, size_t q)
{
    const lm_particles *p = &sim->p;
    const lm_body *bd = &sim->bodies[p->body[q]];
    if (p->pin[q] && sim->pins[p->pin[q] - 1].point) return 0;
    double m = p->m[q];
    if (bd->end_grid_mass > 0 && q == bd->first + bd->count - 1 && m > bd->end_grid_mass &&
        lm_constraint_active(sim))
        m = bd->end_grid_mass;
    return m;
}

/* Step 1, after every scatter (the grid's m_i, p_i whole): the membranes'
 * own nodal velocity v^M_i and, where a bulk body shares the node,
 * v_i - v^M_i into (dx, dy), ghosts filled for step 4's gather; zero where
 * only membranes are (the header says why). */
static void membrane_field(lm_sim *sim)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    struct lm_apic *a = sim->work->apic;
    const int W = g->sw;
    int mem = 0, bulk = 0;
    for (int b = 0; b < sim->nbodies; b++) {
        if (sim->bodies[b].membrane) mem = 1;
        else bulk = 1;
    }
    a->shared = mem && bulk;
    if (!a->shared) return;
    size_t nn = lm_grid_nodes(g);
    for (size_t i = 0; i < nn; i++) a->mm[i] = a->dx[i] = a->dy[i] = 0;
    for (size_t q = 0; q < p->n; q++) {
        if (!sim->bodies[p->body[q]].membrane) continue;
        double m = membrane_mass(sim, q);
        if (!(m > 0)) continue;
        lm_weights wt;
        lm_weights_of(sim, q, &wt);
        for (int k = 0; k < W * W; k++) {
            int i = lm_stencil_node(g, W, p->node[q], k);
            double mN = m * wt.N[k];
            a->mm[i] += mN;
            a->dx[i] += mN * p->vx[q];
            a->dy[i] += mN * p->vy[q];
        }
    }
    double *const f[3] = {a->mm, a->dx, a->dy};
    static const lm_comp comp[3] = {LM_COMP_SCALAR, LM_COMP_X, LM_COMP_Y};
    lm_grid_fold(g, 3, f, comp);
    for (size_t i = 0; i < nn; i++) {
        /* only membranes here (to rounding): FLIP as it is */
        if (!(a->mm[i] > 0) || !(g->m[i] - a->mm[i] > 1e-9 * g->m[i])) {
            a->dx[i] = a->dy[i] = 0;
            continue;
        }
        a->dx[i] = g->px[i] / g->m[i] - a->dx[i] / a->mm[i];
        a->dy[i] = g->py[i] / g->m[i] - a->dy[i] / a->mm[i];
    }
    double *const d[2] = {a->dx, a->dy};
    static const lm_comp dcomp[2] = {LM_COMP_X, LM_COMP_Y};
    lm_grid_fill(g, 2, d, dcomp);
}

/* Step 1, after the scatter. A point new to the sim (its first step) has
 * no C yet: a body set moving in a rigid rotation or any linear field with
 * C = 0 would lose the field's share that the lumped nodal mass smooths
 * away at its edges (v_i = A x-bar_i, x-bar_i the mass centre of the
 * points at node i, pulled inwards at a free edge: the spinning disk lost
 * 5.6 % of its angular momentum in its first step, measured). So the new
 * points' C is first fitted to the field their velocities make on the grid,
 * a few times over (a linear field v = A x is a fixed point: C = A
 * reproduces p_i = m_i A x_i exactly), the momenta then scattered with it.
 * Scratch: (ax, ay) keep the momenta without the affine part, (vx, vy) the
 * trial velocities; step 4 writes both afresh. */
void lm_apic_p2g(lm_sim *sim)
{
    if (!lm_apic_active(sim)) return;
    lm_grid *g = &sim->grid;
    struct lm_apic *a = sim->work->apic;
    size_t nn = lm_grid_nodes(g);
    if (a->fresh < a->n) {
        for (size_t i = 0; i < nn; i++) {
            g->ax[i] = g->px[i];
            g->ay[i] = g->py[i];
        }
        for (int it = 0; it < 8; it++) {
            for (size_t i = 0; i < nn; i++) {
                g->px[i] = g->ax[i];
                g->py[i] = g->ay[i];
            }
            scatter_affine(sim, g->px, g->py);
            for (size_t i = 0; i < nn; i++) {
                g->vx[i] = g->m[i] > 0 ? g->px[i] / g->m[i] : 0;
                g->vy[i] = g->m[i] > 0 ? g->py[i] / g->m[i] : 0;
            }
            double *const f[2] = {g->vx, g->vy};
            static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
            lm_grid_fill(g, 2, f, comp);
            for (size_t q = a->fresh; q < a->n; q++)
                if (takes(sim, q)) fit(sim, q, g->vx, g->vy, NULL, NULL, a->c + 4 * q);
        }
        for (size_t i = 0; i < nn; i++) {
            g->px[i] = g->ax[i];
            g->py[i] = g->ay[i];
        }
        a->fresh = a->n;
    }
    scatter_affine(sim, g->px, g->py);
    membrane_field(sim);
}

void lm_apic_remap(lm_sim *sim)
{
    if (lm_apic_active(sim)) scatter_affine(sim, sim->grid.vx, sim->grid.vy);
}

/* After step 4 (v^L_i in the grid's vx, vy, ghosts filled): each bulk
 * point's velocity is the grid's at it, and its C the affine fit; a
 * membrane point's FLIP remainder is taken against the membranes' own
 * field (the header), scaled as FLIP's share is by sim.pic. */
void lm_apic_g2p(lm_sim *sim)
{
    if (!lm_apic_active(sim)) return;
    const lm_grid *g = &sim->grid;
    lm_particles *p = &sim->p;
    const struct lm_apic *a = sim->work->apic;
    const double flip = 1 - sim->def.pic;
    for (size_t q = 0; q < p->n; q++) {
        if (takes(sim, q)) {
            fit(sim, q, g->vx, g->vy, &p->vx[q], &p->vy[q], a->c + 4 * q);
            continue;
        }
        if (!a->shared || !sim->bodies[p->body[q]].membrane || p->pin[q]) continue;
        lm_weights wt;
        lm_weights_of(sim, q, &wt);
        p->vx[q] += flip * lm_gather_rows(g, &wt, p->node[q], a->dx);
        p->vy[q] += flip * lm_gather_rows(g, &wt, p->node[q], a->dy);
    }
}
