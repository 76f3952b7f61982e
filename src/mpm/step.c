/* step.c - one explicit MPM step, docs/physics.md §1, one phase per function.
 *
 * References: [F] = York, Sulsky & Schreyer 2000 (eqs 5-16), [M] = the 1999
 * membrane paper (eqs 10-13), [N] §7 (the USL summary).
 * The shape functions are evaluated once at x^k and used for every transfer
 * of the step ([F] eqs 13-14). */
#include <math.h>
#include <stdio.h>

#include "contact.h"
#include "step.h"
#include "step_kernels.h"
#include "threads.h"

void lm_step_shape(lm_sim *sim)
{
    lm_particles *p = &sim->p;
    const double rx = 1.0 / sim->grid.hx, ry = 1.0 / sim->grid.hy;
    long n = (long)p->n;
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) if (n >= LM_PARTICLE_LOOP_MIN)
    for (long q = 0; q < n; q++) lm_k_shape(sim, p, (size_t)q, rx, ry);
}

/* The three particle-to-grid sums of the step. */
typedef enum scatter_kind {
    SCATTER_MASS_MOMENTUM,   /* m_i, p_i (step 1) */
    SCATTER_FORCES,          /* f_i^int (step 2) */
    SCATTER_MOMENTUM,        /* the MUSL re-map of m_p v_p (step 5) */
    SCATTER_MASS_FORCES      /* steps 1 and 2 in one pass: m_i, p_i, f_i^int */
} scatter_kind;

/* The loops of each sum for a stencil W nodes wide (the kind is chosen
 * outside them: a switch per corner costs a fifth of the step). The
 * particle's values are read into locals once: the nodal sums are doubles
 * too, so the compiler could not otherwise keep them in registers across
 * the stores. Node (a, b) of the stencil is row b, column a (k = b W + a). */
static LM_FORCE_INLINE void scatter_w(const lm_sim *sim, scatter_kind kind, size_t a0,
                                      size_t b0, double *const *f, double *const *c,
                                      const lm_thread_share *sh, const int W, const int split)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    double *const f0 = f[0], *const f1 = f[1];
    double *const c0 = split ? c[0] : NULL, *const c1 = split ? c[1] : NULL;
    const long lo = split ? sh->lo : 0;
    const unsigned long span = split ? (unsigned long)(sh->hi - sh->lo) : 0;
    /* the bilinear and B-spline weights are made here from the point's
     * place (step.h), uGIMP's read */
    const double rx = 1.0 / g->hx, ry = 1.0 / g->hy;
    double Nl[9], Gxl[9], Gyl[9];
    switch (kind) {
    case SCATTER_MASS_MOMENTUM:
        for (size_t q = a0; q < b0; q++)
            lm_k_scatter_momentum(sim, q, f, c, lo, span, W, split, 1);
        break;
    case SCATTER_FORCES:
        for (size_t q = a0; q < b0; q++) {
            if (lm_k_segment_point(sim, q)) {
                /* the net tension of its segments, spread with N_ip
                 * (membrane_force.c) */
                const double fx = p->fpx[q], fy = p->fpy[q];
                const double *N = lm_k_weights_N(p, q, W, Nl);
                for (int b = 0; b < W; b++) {
                    const long row = lm_stencil_row(g, p->node[q], b);
                    for (int a = 0; a < W; a++) {
                        *lm_k_at(f0, c0, row + a, lo, span, split) += N[b * W + a] * fx;
                        *lm_k_at(f1, c1, row + a, lo, span, split) += N[b * W + a] * fy;
                    }
                }
                continue;
            }
            const double V = p->m[q] / p->rho[q];
            const double sxx = p->sxx[q], syy = p->syy[q], sxy = p->sxy[q];
            const double *Gx, *Gy;
            lm_k_weights_G(p, q, W, rx, ry, Gxl, Gyl, &Gx, &Gy);
            for (int b = 0; b < W; b++) {
                const long row = lm_stencil_row(g, p->node[q], b);
                for (int a = 0; a < W; a++) {
                    double gx = Gx[b * W + a], gy = Gy[b * W + a];
                    *lm_k_at(f0, c0, row + a, lo, span, split) -= V * (sxx * gx + sxy * gy);
                    *lm_k_at(f1, c1, row + a, lo, span, split) -= V * (sxy * gx + syy * gy);
                }
            }
        }
        break;
    case SCATTER_MASS_FORCES:
        /* each field gets the same terms in the same particle order as
         * the two passes did, so the same sums to the bit */
        for (size_t q = a0; q < b0; q++)
            lm_k_scatter_mass_forces(sim, q, rx, ry, f, c, lo, span, W, split, 1);
        break;
    case SCATTER_MOMENTUM:
        for (size_t q = a0; q < b0; q++) lm_k_scatter_momentum(sim, q, f, c, lo, span, W, split, 0);
        break;
    }
}

/* Particles [a, b) into the fields f, or, with copies c, into c at the
 * nodes other threads share (sh) and f elsewhere. */
static void scatter_range(const lm_sim *sim, scatter_kind kind, size_t a, size_t b,
                          double *const *f, double *const *c, const lm_thread_share *sh)
{
    /* (the loops above walk lm_stencil_node(g, W, node, k) row by row) */
    if (c) {
        if (sim->grid.sw == 2) scatter_w(sim, kind, a, b, f, c, sh, 2, 1);
        else scatter_w(sim, kind, a, b, f, c, sh, 3, 1);
    } else if (sim->grid.sw == 2) {
        scatter_w(sim, kind, a, b, f, NULL, sh, 2, 0);
    } else {
        scatter_w(sim, kind, a, b, f, NULL, sh, 3, 0);
    }
}

/* Adds one of the sums into the nf fields `out` (zeroed by the caller),
 * each thread over its own particles (threads.h); with a 3 x 3 basis the
 * ghost nodes' sums are then folded in at the walls (grid_walls.c), comp
 * saying what each field is. */
static void scatter(lm_sim *sim, scatter_kind kind, int nf, double *const *out,
                    const lm_comp *comp)
{
    int nt = lm_sim_threads(sim);
    if (nt == 1) {   /* the plain loop */
        scatter_range(sim, kind, 0, sim->p.n, out, NULL, NULL);
        lm_grid_fold(&sim->grid, nf, out, comp);
        return;
    }
    /* split as nt threads; few particles: all of them on one OS thread */
#pragma omp parallel num_threads(lm_sim_team(sim)) if (sim->p.n >= LM_PARTICLE_LOOP_MIN)
    {
        int team = LM_TEAM_SIZE();
        for (int t = LM_THREAD_ID(); t < nt; t += team) {
            size_t a, b;
            lm_thread_range(sim->p.n, t, nt, &a, &b);
            lm_thread_band(sim, t, a, b);
        }
#pragma omp barrier
        for (int t = LM_THREAD_ID(); t < nt; t += team) {
            size_t a, b;
            double *f[LM_SCATTER_FIELDS];
            lm_thread_share sh;
            lm_thread_range(sim->p.n, t, nt, &a, &b);
            lm_thread_fields(sim, t, nt, nf, f, &sh);
            /* runs of particles whose stencils do or do not reach a node
             * another thread touches (threads.h) */
            for (size_t q = a; q < b;) {
                int shared = lm_thread_shared(&sh, sim->p.node[q]);
                size_t e = q + 1;
                while (e < b && lm_thread_shared(&sh, sim->p.node[e]) == shared) e++;
                scatter_range(sim, kind, q, e, out, shared ? f : NULL, &sh);
                q = e;
            }
        }
    }
    lm_threads_reduce(sim, nt, nf, out);
    lm_grid_fold(&sim->grid, nf, out, comp);
}

/* Step 1: m_i = sum_p m_p N_ip, p_i = sum_p m_p v_p N_ip (lumped mass). */
void lm_step_p2g(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    double *const out[3] = {g->m, g->px, g->py};
    static const lm_comp comp[3] = {LM_COMP_SCALAR, LM_COMP_X, LM_COMP_Y};
    scatter(sim, SCATTER_MASS_MOMENTUM, 3, out, comp);
    lm_pin_p2g(sim);
}


/* Step 2: f_i^int = -sum_p V_p sigma_p . G_ip ([F] eq 9), f_i^ext = m_i g. */
void lm_step_forces(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    double *const out[2] = {g->fx, g->fy};
    static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
    lm_membrane_segment_forces(sim);
    if (sim->def.stress == LM_STRESS_CELL)
        lm_stress_cell_forces(sim);   /* [T] §5.4.3, stress_cell.c; linear basis only */
    else
        scatter(sim, SCATTER_FORCES, 2, out, comp);
    lm_step_forces_rest(sim);
}

/* Steps 1 and 2 in one pass over the particles (point stresses): the
 * particle's place, weights and stencil are read once for all five sums
 * (issue 17 item 1). The same sums as lm_step_p2g then lm_step_forces. */
void lm_step_p2g_forces(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    if (sim->def.stress == LM_STRESS_CELL) {
        lm_step_p2g(sim);
        lm_step_forces(sim);
        return;
    }
    lm_membrane_segment_forces(sim);   /* the segment points' net tension */
    double *const out[5] = {g->m, g->px, g->py, g->fx, g->fy};
    static const lm_comp comp[5] = {LM_COMP_SCALAR, LM_COMP_X, LM_COMP_Y, LM_COMP_X, LM_COMP_Y};
    scatter(sim, SCATTER_MASS_FORCES, 5, out, comp);
    lm_pin_p2g(sim);
    lm_step_forces_rest(sim);
}

/* What step 2 adds after the particles' own forces: the hoop, tethers,
 * gravity. */
void lm_step_forces_rest(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    if (sim->def.axisym) lm_axisym_forces(sim);   /* -V sigma_thth N / r (axisym.c) */
    lm_link_forces(sim);                          /* tethers (link.c) */
    size_t nn = lm_grid_nodes(g);
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) if (nn > LM_NODE_LOOP_MIN)
    for (long i = 0; i < (long)nn; i++) {
        g->fx[i] += g->m[i] * sim->def.gx;
        g->fy[i] += g->m[i] * sim->def.gy;
    }
}

/* Step 3: p_i^L = p_i + dt f_i ([F] eq 10); the boundary conditions act on
 * both p^L and f, so that step 4 sees the constrained accelerations. With
 * lamina.sim{damping = c} f_i first takes the implicit damping force
 * (damping.c); every path (USL, MUSL, fused, threaded) goes through here. */
void lm_step_grid_update(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    size_t nn = lm_grid_nodes(g);
    double dt = sim->def.dt;
    /* grid damping (damping.c): part of the force, so before the heavy end
     * points' solve and the walls, which then act on the damped force */
    const int damped = sim->def.damping > 0;
    if (damped) lm_damp_grid(sim);
    /* mass = "corrected": p_i, f_i towards the consistent mass, the heavy
     * points and point pins solved inside (mass_corrected.c; one field
     * only: not with contact's own fields). After the damping, as the
     * lumped path solves its constraints after it; without constraints the
     * correction is one linear map of p and f alike, which commutes with
     * the damping's node-by-node f - c p, so the order changes nothing. */
    const int corrected = lm_mass_corrects(sim);
    if (corrected && damped) lm_damp_keep_momentum(sim);   /* the account's p_i */
    if (corrected) lm_mass_correct_momentum_forces(sim);
    if (lm_constraint_active(sim)) {
        /* heavy end points, on p and f with the walls applied (the solve
         * leaves the walls' components alone: constraint.c) */
        lm_grid_apply_bc(g, g->px, g->py);
        lm_grid_apply_bc(g, g->fx, g->fy);
        if (!corrected) lm_constraint_grid(sim);
    }
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) if (nn > LM_NODE_LOOP_MIN)
    for (long i = 0; i < (long)nn; i++) {
        g->px[i] += dt * g->fx[i];
        g->py[i] += dt * g->fy[i];
    }
    lm_pin_grid(sim);   /* held nodes move with their pins (pin.c) */
    lm_grid_apply_bc(g, g->px, g->py);
    lm_grid_apply_bc(g, g->fx, g->fy);
    if (damped) lm_damp_account(sim);
}

/* Step 4's nodal values at every node (lm_k_g2p_node), ghost nodes filled. */
void lm_step_g2p_nodes(lm_sim *sim, double *ux, double *uy)
{
    lm_grid *g = &sim->grid;
    long nn = (long)lm_grid_nodes(g);
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) if (nn > LM_NODE_LOOP_MIN)
    for (long i = 0; i < nn; i++) lm_k_g2p_node(g, i, ux, uy);
    lm_step_fill_g2p_nodes(g, ux, uy);
}

/* The ghost nodes of step 4's nodal values (lm_k_g2p_node's four fields). */
void lm_step_fill_g2p_nodes(lm_grid *g, double *ux, double *uy)
{
    double *const fill[4] = {g->ax, g->ay, ux, uy};
    static const lm_comp comp[4] = {LM_COMP_X, LM_COMP_Y, LM_COMP_X, LM_COMP_Y};
    lm_grid_fill(g, 4, fill, comp);
}

/* Step 4 ([F] eq 12): FLIP velocity update from the nodal accelerations,
 * position from the Lagrangian grid velocity. Only zero-mass nodes are
 * skipped; dropping "small" ones would break momentum conservation. */
void lm_step_g2p(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    lm_particles *p = &sim->p;
    double dt = sim->def.dt, pic = sim->def.pic;
    lm_step_g2p_nodes(sim, g->vx, g->vy);
    long n = (long)p->n;
    if (g->sw == 2) {
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) if (n >= LM_PARTICLE_LOOP_MIN)
        for (long q = 0; q < n; q++) lm_k_g2p(g, p, (size_t)q, dt, pic, g->ax, g->ay, g->vx, g->vy, 2);
    } else {
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) if (n >= LM_PARTICLE_LOOP_MIN)
        for (long q = 0; q < n; q++) lm_k_g2p(g, p, (size_t)q, dt, pic, g->ax, g->ay, g->vx, g->vy, 3);
    }
    lm_pin_particles(sim);
}

/* The end of step 5 once (g->vx, g->vy) hold the strain velocities or,
 * remap, the re-mapped momenta m_i v_i (folded at the walls): divided by
 * m_i, then held nodes and boundary conditions, then the ghost nodes. */
void lm_step_strain_velocity_end(lm_sim *sim, int remap)
{
    lm_grid *g = &sim->grid;
    size_t nn = lm_grid_nodes(g);
    if (remap) {
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) if (nn > LM_NODE_LOOP_MIN)
        for (long i = 0; i < (long)nn; i++) {
            if (g->m[i] > 0) {
                g->vx[i] /= g->m[i];
                g->vy[i] /= g->m[i];
            }
        }
        /* scratch px, py: MUSL reads p_i^L no more this step (step 9
         * clears them) */
        if (lm_mass_corrects(sim)) lm_mass_correct_velocity(sim, g->px, g->py);
    }
    lm_pin_velocity(sim);
    lm_grid_apply_bc(g, g->vx, g->vy);
    /* heavy ends; with mass = "corrected" the re-map solved them already */
    if (lm_constraint_active(sim) &&
        !(remap && lm_mass_corrects(sim)))
        lm_constraint_velocity(sim);
    double *const fill[2] = {g->vx, g->vy};
    static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
    lm_grid_fill(g, 2, fill, comp);
}

/* Step 5. MUSL ([M] eqs 12-13, [F] eq 13): re-map the updated particle
 * velocities to the grid with the same N_ip and constrain them again.
 * USL ([N] §7): use v_i^L = p_i^L / m_i. */
void lm_step_strain_velocity(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    size_t nn = lm_grid_nodes(g);
    const int remap = sim->def.scheme == LM_MUSL;
    if (remap) {
        double *const out[2] = {g->vx, g->vy};
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) if (nn > LM_NODE_LOOP_MIN)
        for (long i = 0; i < (long)nn; i++) g->vx[i] = g->vy[i] = 0;
        static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
        scatter(sim, SCATTER_MOMENTUM, 2, out, comp);
        lm_constraint_remap(sim);   /* a heavy point's extra momentum off */
        lm_apic_remap(sim);         /* APIC's affine momenta (apic.c) */
    } else {
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) if (nn > LM_NODE_LOOP_MIN)
        for (long i = 0; i < (long)nn; i++) {
            g->vx[i] = g->m[i] > 0 ? g->px[i] / g->m[i] : 0;
            g->vy[i] = g->m[i] > 0 ? g->py[i] / g->m[i] : 0;
        }
    }
    lm_step_strain_velocity_end(sim, remap);
}

/* rx = 1 / hx, ry = 1 / hy: the caller's, once for all its points */
static inline void velocity_gradient(const lm_grid *g, const lm_particles *p, size_t q,
                                     double L[4], double rx, double ry)
{
    if (g->sw == 2) lm_k_velocity_gradient(g, p, q, g->vx, g->vy, L, rx, ry, 2);
    else lm_k_velocity_gradient(g, p, q, g->vx, g->vy, L, rx, ry, 3);
}
/* The same and the hoop rate (axisym.c) in one read of the stencil */
static inline double velocity_gradient_hoop(const lm_grid *g, const lm_particles *p, size_t q,
                                            double L[4], double rx, double ry)
{
    return g->sw == 2 ? lm_k_gradient_hoop(g, p, q, g->vx, g->vy, L, rx, ry, 2, 1)
                      : lm_k_gradient_hoop(g, p, q, g->vx, g->vy, L, rx, ry, 3, 1);
}

/* Phase 6c: the artificial viscosity of [F] eq 24 needs, before any gas
 * point is updated, the largest |div v| and the largest sound speed over
 * the gas of the step (0 when no gas uses it). */
void lm_step_gas_maxima(lm_sim *sim, double *max_div, double *c_max)
{
    const double rx = 1.0 / sim->grid.hx, ry = 1.0 / sim->grid.hy;
    const lm_particles *p = &sim->p;
    double md = 0, cm = 0;
    long n = (long)p->n;
    /* no such gas: no pass over the particles (nor a fork, issue 17) */
    int m = 0;
    while (m < sim->nmats && !(sim->mats[m]->kind == LM_GAS && sim->mats[m]->av)) m++;
    if (m == sim->nmats) n = 0;
    const int moved = lm_contact_moved(sim->contact);   /* bodies in own fields */
    /* maxima do not depend on the order they are taken in */
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) \
    reduction(max : md, cm) if (n >= LM_PARTICLE_LOOP_MIN)
    for (long q = 0; q < n; q++) {
        const lm_material *mat = sim->mats[p->mat[q]];
        if (mat->kind != LM_GAS || !mat->av) continue;
        double L[4], hoop = 0;
        if (sim->def.axisym) hoop = velocity_gradient_hoop(&sim->grid, p, (size_t)q, L, rx, ry);
        else velocity_gradient(&sim->grid, p, (size_t)q, L, rx, ry);
        if (moved) lm_contact_gradient_near(sim, (size_t)q, L);
        double div = fabs(sim->def.axisym ? L[0] + L[3] + hoop : L[0] + L[3]);
        double c = lm_gas_sound_speed(mat, p->e[q]);
        if (div > md) md = div;
        if (c > cm) cm = c;
    }
    *max_div = md;
    *c_max = cm;
}

/* Step 7 at particle q: L = sum_i v_i (x) G_ip, the strain increment
 * (dt/2)(L + L^T) and the spin (1/2)(L - L^T). */
static void rate_at(const lm_sim *sim, size_t q, lm_rate *r, int moved, double rx, double ry)
{
    r->hoop = 0;
    if (sim->def.axisym) r->hoop = velocity_gradient_hoop(&sim->grid, &sim->p, q, r->L, rx, ry);
    else velocity_gradient(&sim->grid, &sim->p, q, r->L, rx, ry);
    if (moved) lm_contact_gradient_near(sim, q, r->L);   /* contact.h */
    const double *L = r->L, dt = sim->def.dt;
    r->dexx = dt * L[0];
    r->deyy = dt * L[3];
    r->dexy = 0.5 * dt * (L[1] + L[2]);
    r->w = 0.5 * (L[1] - L[2]);
}

/* Steps 7-8 ([F] eqs 14-23): each particle's rate from the grid velocity
 * and its material's update; density rho / (1 + tr de) ([F] eq 16) or, for
 * a gas that asks, from the cells (phase 6b). A membrane with segment
 * forces takes its strain from its lengths after this (membrane_force.c). */
void lm_step_stress(lm_sim *sim, double max_div, double c_max)
{
    lm_step_stress_part(sim, max_div, c_max, 0);
}

/* The same for every particle but the membranes' (slow_only): multi-rate
 * stepping has updated those in its sub-steps (subcycle.c). */
void lm_step_stress_part(lm_sim *sim, double max_div, double c_max, int slow_only)
{
    const lm_grid *g = &sim->grid;
    double h = fmin(g->hx, g->hy);
    const double rx = 1.0 / g->hx, ry = 1.0 / g->hy;
    long n = (long)sim->p.n;
    const int moved = lm_contact_moved(sim->contact);   /* bodies in own fields */
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) if (n >= LM_PARTICLE_LOOP_MIN)
    for (long q = 0; q < n; q++) {
        if (lm_k_segment_point(sim, (size_t)q)) continue;   /* from lengths */
        if (slow_only && sim->bodies[sim->p.body[q]].membrane) continue;
        lm_rate r;
        rate_at(sim, (size_t)q, &r, moved, rx, ry);
        r.dt = sim->def.dt;
        r.max_div = max_div;
        r.c_max = c_max;
        r.h = h;
        lm_update_at(sim, (size_t)q, &r, sim->def.axisym);   /* step 8: material_update.c */
    }
}

/* Names the particle by its index within its body and the body by its
 * name, as the script knows them. */
static lm_status fail(lm_sim *sim, lm_status st, size_t q, const char *what,
                      const char *cause)
{
    const lm_particles *p = &sim->p;
    int b = p->body[q];
    char who[96];
    snprintf(sim->err, sizeof sim->err,
             "at t = %.6g (step %ld): %s %zu of %s %s at "
             "(%.6g, %.6g), velocity (%.6g, %.6g); likely cause: %s",
             sim->t, sim->step, sim->bodies[b].membrane ? "point" : "particle",
             q - sim->bodies[b].first + 1, lm_body_label(sim, b, who, sizeof who), what,
             p->x[q], p->y[q], p->vx[q], p->vy[q], cause);
    return st;
}

/* Stops the run at the first sign of trouble, naming the particle (the
 * lowest-numbered one, whatever the thread count), rather than letting NaN
 * spread through the grid. */
/* A body held by another's pins at a contact node (contact_correct.c,
 * held_check): a silent wrong answer (it cannot move there), so the run
 * stops naming both and the way out. */
static lm_status contact_held(lm_sim *sim)
{
    const lm_contact *c = sim->contact;
    const lm_grid *g = &sim->grid;
    long i = c->held_node;
    char who[96], pin[96];
    snprintf(sim->err, sizeof sim->err,
             "at t = %.6g (step %ld): %s is held at the node (%.6g, %.6g), where it has "
             "nearly all the mass, by the pins of %s, whose shape functions reach that far "
             "(contact); likely cause: the basis' stencil is wider than the contact "
             "layer (basis = \"bspline2\" reaches 1.5 cells): use basis = \"gimp\", or pin "
             "only points more than two cells from the other body",
             sim->t, sim->step, lm_body_label(sim, c->held_body, who, sizeof who),
             g->x0 + (double)(i % g->sx - g->pad) * g->hx,
             g->y0 + (double)(i / g->sx - g->pad) * g->hy,
             lm_body_label(sim, c->held_by, pin, sizeof pin));
    return LM_ERR_UNSTABLE;
}

lm_status lm_step_check(lm_sim *sim)
{
    long n = (long)sim->p.n, first = n;
    const lm_k_box box = lm_k_box_of(&sim->grid);
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) \
    reduction(min : first) if (n >= LM_PARTICLE_LOOP_MIN)
    for (long q = 0; q < n; q++)
        if (lm_k_check(&sim->p, (size_t)q, &box) && q < first) first = q;
    return lm_step_check_report(sim, (size_t)first);
}

lm_status lm_step_check_report(lm_sim *sim, size_t first)
{
    if (sim->contact && sim->contact->held_body >= 0) return contact_held(sim);
    if (first >= sim->p.n) return lm_membrane_check_torn(sim);
    /* a membrane that tore lets its points fly: the tear is the news */
    if (lm_membrane_check_torn(sim) != LM_OK) return LM_ERR_UNSTABLE;
    const lm_k_box box = lm_k_box_of(&sim->grid);
    /* USL divides a node's momentum and force by its own mass: a surface
     * particle on or a rounding past a cell edge gives a node a mass of
     * 1e-16 of its own and the velocity gradient a force divided by it,
     * at any dt ([T] §8.1, the dissertation's "division by a very small
     * grid mass", cured by the momentum form, MUSL). Measured: a disk at
     * cell 0.005 stepping h/60 a step lands on the edges and fails at step
     * 46 (docs/robustness.md, the 1-D bar's USL paragraphs). */
    const char *usl = sim->def.scheme == LM_USL
                          ? ", or, with scheme = \"usl\", a node of tiny mass (a surface "
                            "particle on or just past a cell edge) whose force USL divides "
                            "by that mass: scheme = \"musl\" does not"
                          : "";
    char cause[320];
    switch (lm_k_check(&sim->p, first, &box)) {
    case 1:
        snprintf(cause, sizeof cause, "the time step is too large (raise stability: "
                 "lower dt)%s a material parameter is extreme%s", *usl ? "," : " or", usl);
        return fail(sim, LM_ERR_UNSTABLE, first, "became NaN or infinite", cause);
    case 2:
        snprintf(cause, sizeof cause, "element inversion: the time step is too large or "
                 "the material too soft for the load%s", usl);
        return fail(sim, LM_ERR_UNSTABLE, first,
                    "was compressed to zero or negative volume", cause);
    default:
        return fail(sim, LM_ERR_DOMAIN, first, "left the domain",
                    "the domain is too small for the motion, or a "
                    "'free' side let the body out");
    }
}

void lm_sim_set_dt(lm_sim *sim, double dt)
{
    sim->t_base = sim->t;
    sim->step_base = sim->step;
    sim->def.dt = dt;
    sim->work->courant_checked = 0;
}

/* Marked prepared only when it succeeds (issue 33 item 1): a failure
 * (a membrane's normals) leaves the next step or drawing to try again,
 * e.g. after the script dropped or fixed the body. */
lm_status lm_sim_prepare(lm_sim *sim)
{
    lm_status st = lm_membrane_prepare(sim);
    sim->prepared = st == LM_OK;
    return st;
}

/* Step 9 of docs/physics.md §1 for the next step: empty fields on the same
 * grid. Only what is summed into needs zeroes; step 4 and 5 overwrite the
 * velocities and accelerations whole. */
void lm_step_clear(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    long nn = (long)lm_grid_nodes(g);
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) if (nn > LM_NODE_LOOP_MIN)
    for (long i = 0; i < nn; i++)
        g->m[i] = g->px[i] = g->py[i] = g->fx[i] = g->fy[i] = 0;
}

/* The clock, from the step count so that long runs do not accumulate dt's
 * rounding error; advanced in one place, once per step, whatever the step
 * found (the positions are at t^{k+1} from step 4 on). */
static void advance_clock(lm_sim *sim)
{
    sim->step++;
    sim->t = sim->t_base + (double)(sim->step - sim->step_base) * sim->def.dt;
}

/* Phases 6-8 at x^{k+1}: what the stresses need, then the stresses. */
static lm_status stress_phases(lm_sim *sim)
{
    lm_status st = lm_membrane_tangents(sim);   /* 6a: tangents, normals */
    if (st != LM_OK) return st;
    st = lm_gas_cell_density(sim);              /* 6b: for the gases that ask */
    if (st != LM_OK) return st;
    double max_div, c_max;
    lm_step_gas_maxima(sim, &max_div, &c_max);  /* 6c: [F] eq 24's maxima */
    lm_step_stress(sim, max_div, c_max);        /* 7-8 */
    lm_membrane_segment_strains(sim);           /* 8 for segment membranes */
    return LM_OK;
}

/* One step: the phases of docs/physics.md §1 in order. A plain run
 * (lm_step_fusable) does steps 4-8 and the check particle by particle,
 * and, when the caller says another step follows at once, that step's
 * steps 0-2 too (step_fused.c): the same states to the bit. */
lm_status lm_sim_step_then(lm_sim *sim, int more)
{
    if (sim->p.n == 0) {   /* nothing to move: the clock only */
        lm_sim_forget_ahead(sim);
        advance_clock(sim);
        return LM_OK;
    }
    /* the Courant refusal, for every caller (courant_check.c) */
    if (!sim->work->courant_checked && lm_sim_check_courant(sim) != LM_OK) return LM_ERR_COURANT;
    lm_status st = sim->prepared ? LM_OK : lm_sim_prepare(sim);
    if (st == LM_OK) st = lm_threads_reserve(sim);
    if (st == LM_OK) st = lm_apic_reserve(sim);   /* transfer = "apic" */
    if (st != LM_OK) return st;
    lm_pace_step(sim);                          /* the OS threads for this step */
    if (sim->def.substeps) {                    /* multi-rate (subcycle.c) */
        lm_sim_forget_ahead(sim);
        st = lm_subcycle_step(sim);
        advance_clock(sim);
        if (st != LM_OK) return st;
        st = lm_step_check(sim);
        return st != LM_OK ? st : lm_step_split(sim);
    }
    /* without the pass's arrays (out of memory) the step goes phase by phase */
    const int fused = lm_step_fusable(sim) && lm_ahead_reserve(sim) == LM_OK;
    if (!fused || !lm_step_take_ahead(sim)) {
        lm_sim_forget_ahead(sim);
        lm_step_clear(sim);                     /* 0: the grid's sums */
        lm_step_shape(sim);                     /* 0: N_ip, G_ip at x^k */
        lm_step_p2g_forces(sim);                /* 1-2: m_i, p_i; f_i */
        lm_apic_p2g(sim);                       /* 1: APIC's affine momenta */
    }
    if (sim->contact) {                         /* the paired bodies' own fields */
        st = lm_contact_sums(sim);
        if (st != LM_OK) return st;
    }
    lm_step_grid_update(sim);                   /* 3: p_i^L, boundary conditions */
    if (fused) {                                /* 4-8, the check (and 0-2 ahead) */
        size_t first = lm_step_fused_particles(sim, more, &st);
        advance_clock(sim);
        return st != LM_OK ? st : lm_step_check_report(sim, first);
    }
    if (sim->contact) lm_contact_correct(sim);
    lm_membrane_segment_hold(sim);              /* x^k of segment membranes */
    lm_step_g2p(sim);                           /* 4: v_p, x_p */
    lm_apic_g2p(sim);                           /* 4: APIC's v_p, C_p */
    if (sim->contact) lm_contact_g2p(sim);
    lm_step_strain_velocity(sim);               /* 5: v_i for the strain */
    if (sim->contact) lm_contact_strain_velocity(sim);
    lm_membrane_segment_move(sim);              /* 5: their x^{k+1} (MUSL) */
    st = stress_phases(sim);                    /* 6-8 */
    advance_clock(sim);
    if (st != LM_OK) return st;
    st = lm_step_check(sim);                    /* blow-up, tears */
    if (st != LM_OK) return st;
    return lm_step_split(sim);                  /* gas splitting, if asked */
}

lm_status lm_sim_step(lm_sim *sim)
{
    return lm_sim_step_then(sim, 0);
}
