/* mass_corrected.c - lamina.sim{mass = "corrected"}: one Neumann step of
 * the consistent-mass solve on the grid (issue 30 item 2, docs/robustness.md
 * "Corrected mass").
 *
 * Step 1's nodal mass is the row sum of the consistent mass matrix
 * M_C = sum_p m_p N_ip N_jp ([F] eq 7's lumping, [M] eq 10). For the
 * quadratic B-spline that costs dispersion: in 1-D the stiffness symbol is
 * K(theta) = theta^2 (1 - theta^2 / 4) against a lumped mass of 1, so
 * omega_h / omega = 1 - theta^2 / 8 (theta = k h). M_C's symbol is
 * (66 + 52 cos theta + 2 cos 2 theta) / 120 = 1 - theta^2 / 4 + O(theta^4);
 * one Neumann step of M_C^-1 = (M_L - (M_L - M_C))^-1,
 *     u_C = u_L + M_L^-1 (M_L - M_C) u_L = 2 u_L - M_L^-1 (M_C u_L),
 * u_L = M_L^-1 r, has the symbol 2 - M_C(theta) = 1 + theta^2 / 4 + ...,
 * which cancels the theta^2 term: omega_h / omega = 1 + O(theta^4).
 * M_C u_L costs one gather of u_L to the particles and one scatter
 * m_p N_ip u_p back. M_L - M_C is positive semi-definite, so the corrected
 * inverse mass (2 - M_C(theta) in [1, 2)) stays positive, but the highest
 * mode's frequency rises (1-D theta = pi: x sqrt(1.87)): the Courant check
 * scales by LM_CORRECTED_COURANT.
 *
 * For a membrane with segment forces the lumped mass costs twice that
 * (docs/robustness.md "Where the string's dispersion comes from"): a
 * point's force reaches it through B = N^T M_L^-1 N and, under MUSL, it
 * moves with the re-mapped velocity B M_p v, so x'' = -B M_p B K x (K the
 * segments' stiffness). For the verification's string (points h/2 apart,
 * on the nodes and mid-cell: weight symbols a = (3 + cos theta)/4,
 * b = cos(theta/2)) B is rank one per Bloch wave and
 *     (omega_h / omega)^2 = 2 (a^2 + b^2)(a^2 + b^2 - 2 a b cos(theta/2)) / theta^2
 *                         = 1 - 25 theta^2 / 48 + ...,
 * each smoothing (a^2 + b^2)/2 ~ 1 - theta^2/4: mode 3 at 16 cells to the
 * string +9.49 % predicted, +10.1 % measured (tests/physics/
 * string_dispersion.lua checks both levels, modes 2 and 3). The Neumann
 * step below multiplies it by (2 - (a^2 + b^2)/2)^2: +1.06 % predicted,
 * +1.12 % measured; its highest mode is 1.44 times faster (a stable step
 * 0.694 as long; the walled string measured 0.695).
 *
 * Applied to the nodal momenta and forces before step 3 (so p_i^L, the
 * accelerations and every velocity built from them carry it) and to the
 * MUSL re-mapped velocities of step 5 (which move segment membranes'
 * points, [M] eq 13: their smoothing is the larger half of the string's
 * dispersion, docs/robustness.md). Uniform fields are kept exactly (the
 * N_ip sum to one: M_C 1 = M_L 1), and sum_i of the correction is zero,
 * so momentum is conserved. The loops are serial and in particle order:
 * same bits for the same script. */
#include <stdio.h>
#include <stdlib.h>

#include "gather.h"
#include "sim_work.h"

/* The grid's mass between steps (lamina.sim{mass = "auto"} resolves here
 * as a run starts: l_sim.c). A mass other than lumped needs the lumped
 * momenta the damping's account reads (damping.c lm_damp_keep_momentum),
 * made here as lm_sim_new makes them for a mass named at creation. */
lm_status lm_sim_set_mass(lm_sim *sim, lm_mass mass)
{
    if (mass != LM_MASS_LUMPED && mass != LM_MASS_CORRECTED && mass != LM_MASS_MEMBRANE) {
        snprintf(sim->err, sizeof sim->err, "unknown mass mode %d", (int)mass);
        return LM_ERR_INPUT;
    }
    if (mass != LM_MASS_LUMPED && !sim->work->mass_p0) {
        double *p0 = malloc(2 * lm_grid_nodes(&sim->grid) * sizeof *p0);
        if (!p0) {
            snprintf(sim->err, sizeof sim->err, "out of memory for the nodal momenta of a %d x %d grid",
                     sim->grid.nx, sim->grid.ny);
            return LM_ERR_MEMORY;
        }
        sim->work->mass_p0 = p0;
    }
    sim->def.mass = mass;
    return LM_OK;
}

/* mass = "membrane" with no membrane in the sim is the lumped step, to the
 * bit (and the step stays on the lumped path's constraint solves). */
int lm_mass_corrects(const lm_sim *sim)
{
    if (sim->def.mass == LM_MASS_LUMPED || sim->contact) return 0;
    if (sim->def.mass == LM_MASS_CORRECTED) return 1;
    for (int b = 0; b < sim->nbodies; b++)
        if (sim->bodies[b].membrane && sim->bodies[b].count > 0) return 1;
    return 0;
}

/* mass = "membrane": only the membranes' points take the consistent share;
 * every other point stays lumped. M_C' = M_L - sum_{p in membranes} m_p
 * (diag N_p - N_p N_p^T): symmetric, M_L - M_C' positive semi-definite as
 * before, M_C' 1 = M_L 1, and a loop over the membranes' points only (a gas
 * or solid beside them costs nothing more, and a scene without membranes
 * steps as on the lumped mass). */
static int membrane_only(const lm_sim *sim)
{
    return sim->def.mass == LM_MASS_MEMBRANE;
}

/* The nodes a correction visits: rows r0..r1, columns c0..c1 of the padded
 * arrays (row-major, as every loop here). mass = "corrected": all of them.
 * mass = "membrane": the box round the membranes' stencils and the pinned
 * points' (their constraint is solved inside the correction), two nodes
 * wider so that every ghost node the box holds has its mirror in it too;
 * elsewhere w is nothing and the sums keep their bits. Over every node the
 * trampoline (a sheet and a small ball) stepped at 1.66 x the lumped cost,
 * over the box 1.48 x (docs/robustness.md). */
typedef struct node_box {
    long r0, r1, c0, c1, sx;
} node_box;

#define BOX_FOR(bx_, i)                                                    \
    for (long r_ = (bx_)->r0; r_ <= (bx_)->r1; r_++)                       \
        for (long i = r_ * (bx_)->sx + (bx_)->c0, e_ = r_ * (bx_)->sx + (bx_)->c1; i <= e_; i++)

static void box_take(node_box *w, long node)
{
    long r = node / w->sx, c = node % w->sx;
    if (r < w->r0) w->r0 = r;
    if (r > w->r1) w->r1 = r;
    if (c < w->c0) w->c0 = c;
    if (c > w->c1) w->c1 = c;
}

static void box_of(const lm_sim *sim, node_box *w)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const long rows = (long)(lm_grid_nodes(g) / (size_t)g->sx);
    w->sx = g->sx;
    w->r0 = 0;
    w->r1 = rows - 1;
    w->c0 = 0;
    w->c1 = g->sx - 1;
    if (!membrane_only(sim)) return;
    w->r0 = w->c0 = rows + g->sx;
    w->r1 = w->c1 = -1;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        if (!bd->membrane) continue;
        for (size_t q = bd->first; q < bd->first + bd->count; q++) box_take(w, p->node[q]);
    }
    if (sim->npins)
        for (size_t q = 0; q < p->n; q++)
            if (p->pin[q]) box_take(w, p->node[q]);
    if (w->r1 < 0) return;   /* nothing: an empty box */
    const long d = 2;
    w->r0 = w->r0 - d < 0 ? 0 : w->r0 - d;
    w->c0 = w->c0 - d < 0 ? 0 : w->c0 - d;
    w->r1 = w->r1 + g->sw - 1 + d > rows - 1 ? rows - 1 : w->r1 + g->sw - 1 + d;
    w->c1 = w->c1 + g->sw - 1 + d > g->sx - 1 ? g->sx - 1 : w->c1 + g->sw - 1 + d;
}

/* Zeroes (bx, by) over the box and, with mass = "membrane", over the ghost
 * ring too: the fold reads every ghost node, and outside the box these
 * scratch arrays hold the last step's values. */
static void box_zero(const lm_sim *sim, const node_box *w, double *bx, double *by)
{
    BOX_FOR(w, i) bx[i] = by[i] = 0;
    const lm_grid *g = &sim->grid;
    if (!membrane_only(sim) || g->pad == 0) return;
    const long rows = (long)(lm_grid_nodes(g) / (size_t)g->sx), pad = g->pad;
    for (long r = 0; r < rows; r++) {
        const int edge = r < pad || r >= rows - pad;
        for (long c = 0; c < g->sx; c++) {
            if (!edge && c >= pad && c < g->sx - pad) c = g->sx - pad;   /* the row's far ghosts */
            bx[r * g->sx + c] = by[r * g->sx + c] = 0;
        }
    }
}

/* Point q's term of consistent_times (only: the difference form). */
static void consistent_point(const lm_sim *sim, size_t q, int only, const double *ux,
                             const double *uy, double *bx, double *by)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const int W = g->sw;
    /* a point-held pinned point's mass is off the grid (pin.c): not in
     * M_L, so not in M_C either (M_C 1 = M_L 1 keeps a uniform field) */
    if (p->pin[q] && sim->pins[p->pin[q] - 1].point) return;
    /* a heavy end point has only the wire's share on the grid
     * (constraint.c); its extra mass is the constraint's, so M_C takes the
     * same share (with all of it M_C 1 = M_L 1 broke and the correction
     * held the spring-mass's weight still) */
    double mq = p->m[q];
    const lm_body *bd = &sim->bodies[p->body[q]];
    if (bd->end_grid_mass > 0 && q == bd->first + bd->count - 1 && mq > bd->end_grid_mass &&
        lm_constraint_active(sim))
        mq = bd->end_grid_mass;
    lm_weights wt;
    lm_weights_of(sim, q, &wt);
    const double *N = wt.N;
    const double sx = lm_gather_rows(g, &wt, p->node[q], ux) * mq;
    const double sy = lm_gather_rows(g, &wt, p->node[q], uy) * mq;
    for (int b = 0; b < W; b++) {
        const long row = lm_stencil_row(g, p->node[q], b);
        for (int a = 0; a < W; a++) {
            if (only) {
                bx[row + a] += N[b * W + a] * (mq * ux[row + a] - sx);
                by[row + a] += N[b * W + a] * (mq * uy[row + a] - sy);
            } else {
                bx[row + a] += N[b * W + a] * sx;
                by[row + a] += N[b * W + a] * sy;
            }
        }
    }
}

/* (bx, by)_i = sum_p m_p N_ip sum_j N_jp (ux, uy)_j, the ghost sums folded
 * at the walls; (ux, uy) filled at the ghost nodes by the caller. Row by
 * row for the 3 x 3 stencils, as step 4 gathers. With mass = "membrane"
 * instead the difference (M_L - M_C') u over the membranes' points,
 * sum_p m_p N_ip (u_i - sum_j N_jp u_j), which is m_i w_i directly (a
 * ghost node's u is its mirror's with the sign the fold gives back, so
 * the folded difference is the real node's). */
static void consistent_times(const lm_sim *sim, const node_box *box, const double *ux,
                             const double *uy, double *bx, double *by)
{
    const int only = membrane_only(sim);
    box_zero(sim, box, bx, by);
    if (only) {   /* the membranes' points, body by body */
        for (int b = 0; b < sim->nbodies; b++) {
            const lm_body *bd = &sim->bodies[b];
            if (!bd->membrane) continue;
            for (size_t q = bd->first; q < bd->first + bd->count; q++)
                consistent_point(sim, q, 1, ux, uy, bx, by);
        }
    } else {
        for (size_t q = 0; q < sim->p.n; q++) consistent_point(sim, q, 0, ux, uy, bx, by);
    }
    double *const f[2] = {bx, by};
    static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
    lm_grid_fold(&sim->grid, 2, f, comp);
}

/* One mass-weighted field (rx, ry) (a momentum or a force) replaced by
 * M_L (u_L + w), u_L = r / m constrained as step 3 will constrain it, and
 * the correction w = u_L - M_L^-1 M_C u_L constrained the same way with no
 * targets (constraint.c lm_constraint_field: the Neumann step of the
 * constrained consistent mass). The constraints: the walls
 * (lm_grid_apply_bc); the heavy end points and the pins that hold their
 * point (constraint.c, what = 0 momenta, 1 forces); and, where pins hold
 * nodes (a pinned edge, sim:contact), at those nodes the pin's velocity
 * (momentum) or no acceleration (forces: a pin moves steadily within a
 * step; the impulse (v_pin - p_i / m_i) / dt with which pin.c holds the
 * node is no acceleration of the string, and fed to the neighbours through
 * M_C it made the pinned strings blow up, measured). (ux, uy), (bx, by) are
 * scratch. */
static void correct_weighted(lm_sim *sim, double *rx, double *ry, int what, double *ux,
                             double *uy, double *bx, double *by)
{
    lm_grid *g = &sim->grid;
    const int momentum = what == 0, con = lm_constraint_active(sim), only = membrane_only(sim);
    node_box box;
    box_of(sim, &box);
    BOX_FOR(&box, i) {
        double r = g->m[i] > 0 ? 1.0 / g->m[i] : 0;
        ux[i] = rx[i] * r;
        uy[i] = ry[i] * r;
        if (sim->npins && sim->work->pin_w[i] > 0) {
            double w = sim->work->pin_w[i];
            ux[i] = momentum ? sim->work->pin_vx[i] / w : 0;
            uy[i] = momentum ? sim->work->pin_vy[i] / w : 0;
        }
    }
    lm_grid_apply_bc(g, ux, uy);
    if (con) lm_constraint_field(sim, what, ux, uy);
    double *const fill[2] = {ux, uy};
    static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
    lm_grid_fill(g, 2, fill, comp);
    consistent_times(sim, &box, ux, uy, bx, by);
    /* (bx, by) becomes w; a held node keeps its own sums (below), so its w
     * is nothing */
    BOX_FOR(&box, i) {
        if (!(g->m[i] > 0) || (sim->npins && sim->work->pin_w[i] > 0)) {
            bx[i] = by[i] = 0;
            continue;
        }
        bx[i] = only ? bx[i] / g->m[i] : ux[i] - bx[i] / g->m[i];
        by[i] = only ? by[i] / g->m[i] : uy[i] - by[i] / g->m[i];
    }
    if (con) {
        lm_grid_apply_bc(g, bx, by);
        lm_constraint_field(sim, 3, bx, by);
    }
    BOX_FOR(&box, i) {
        /* a held node keeps its own sums: pin.c reads the reaction from
         * them (correcting them doubled a hanging chain's end tension,
         * measured: +100 %), and holds its momentum whatever they are */
        if (!(g->m[i] > 0) || (sim->npins && sim->work->pin_w[i] > 0)) continue;
        /* mass = "membrane": a node no membrane point reaches and no
         * constraint moved keeps its own sums, so a gas or solid away from
         * the membranes steps to the bit as on the lumped mass */
        if (only && bx[i] == 0 && by[i] == 0 && ux[i] == rx[i] * (1.0 / g->m[i]) &&
            uy[i] == ry[i] * (1.0 / g->m[i]))
            continue;
        rx[i] = g->m[i] * (ux[i] + bx[i]);
        ry[i] = g->m[i] * (uy[i] + by[i]);
    }
}

/* Step 3, after the damping: p_i and f_i corrected, the heavy points and
 * point pins solved inside (the momenta first: the forces' solve gives the
 * pins' reactions), so lm_step_grid_update does not call
 * lm_constraint_grid. Scratch: the step-4 arrays (ax, ay, vx, vy), which
 * step 4 overwrites whole (phase-by-phase path only: lm_step_fusable says
 * no when the option is on). pin.c's lm_pin_grid then holds the pinned
 * nodes as before. */
void lm_mass_correct_momentum_forces(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    correct_weighted(sim, g->px, g->py, 0, g->ax, g->ay, g->vx, g->vy);
    correct_weighted(sim, g->fx, g->fy, 1, g->ax, g->ay, g->vx, g->vy);
    if (lm_constraint_active(sim)) lm_constraint_reactions(sim);
}

/* Step 5, MUSL: the re-mapped velocities v_i = (sum_p m_p v_p N_ip) / m_i
 * in (vx, vy), constrained (node-held pins, walls, then constraint.c's
 * heavy points and point pins), then v + w with w = v - M_L^-1 M_C v
 * constrained with no targets, as in step 3; lm_step_strain_velocity_end
 * then does not call lm_constraint_velocity (a heavy point's share is not
 * a projection: twice would give it twice). Scratch: ax, ay (step 4 is
 * done) and one more pair, the caller's. */
void lm_mass_correct_velocity(lm_sim *sim, double *sx, double *sy)
{
    lm_grid *g = &sim->grid;
    const int con = lm_constraint_active(sim), only = membrane_only(sim);
    node_box box;
    box_of(sim, &box);
    lm_pin_velocity(sim);
    lm_grid_apply_bc(g, g->vx, g->vy);
    if (con) lm_constraint_field(sim, 2, g->vx, g->vy);
    BOX_FOR(&box, i) {
        g->ax[i] = g->vx[i];
        g->ay[i] = g->vy[i];
    }
    double *const fill[2] = {g->ax, g->ay};
    static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
    lm_grid_fill(g, 2, fill, comp);
    consistent_times(sim, &box, g->ax, g->ay, sx, sy);
    BOX_FOR(&box, i) {
        if (!(g->m[i] > 0)) {
            sx[i] = sy[i] = 0;
            continue;
        }
        sx[i] = only ? sx[i] / g->m[i] : g->vx[i] - sx[i] / g->m[i];
        sy[i] = only ? sy[i] / g->m[i] : g->vy[i] - sy[i] / g->m[i];
    }
    if (con) {
        lm_grid_apply_bc(g, sx, sy);
        lm_constraint_field(sim, 3, sx, sy);
    }
    BOX_FOR(&box, i) {
        g->vx[i] += sx[i];
        g->vy[i] += sy[i];
    }
}
