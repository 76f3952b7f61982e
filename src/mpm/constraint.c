/* constraint.c - a heavy end point moves the nodes it shares with the
 * wire only as much as its velocity needs (issue 30 item 2), and a pinned
 * point, the same constraint with an infinite mass, only as much as the
 * pin's velocity needs (issue 30 item 3; pin.c).
 *
 * [M] §3.1.1's spring-mass hangs a heavy point (end_mass) on a wire. With
 * the lumped mass of every MPM scheme its mass spreads over every node of
 * its stencil, and the wire's points sharing those nodes ride rigidly with
 * it: the spring acts shorter. Measured (k = AE/L = 2.5e5, m = 5, cell 0.1,
 * default quadratic B-spline and segment forces): period -9.0 % at 3
 * points a cell, -8.3 % at 1, and still -2.4 % at cell 0.025; the wider the
 * stencil, the worse (the papers' bilinear hats: -0.5 %).
 *
 * Here only a wire-sized share m_w (the mass the point would have without
 * end_mass, rho t ds) of the point's mass M goes on the lumped grid. The
 * rest, M' = M - m_w, is the consistent mass M' N N^T of that one point: it
 * adds to the lumped matrix only in the direction N of the point's own
 * weights. Solving (M_L + M' N N^T) u = r by Sherman-Morrison is a
 * constraint with a finite mass: the nodes get the impulse lambda N_i,
 *   lambda = (V - sum_i N_i r_i / m_i) / (sum_i N_i^2 / m_i + 1 / M'),
 * with V the velocity M' brings (or, for forces, its own acceleration g),
 * so that momentum is conserved and only the velocity interpolated at the
 * point is tied to M'. It is solved for the momenta (the consistent p2g:
 * M' shares its momentum) and, separately, for the forces (M' accelerates
 * with the nodes at it), so that FLIP (step 4) carries the constrained
 * accelerations only, as for every other particle: the point's own FLIP
 * increment is then the acceleration of the whole mass M, and its move the
 * constrained v^L. (Putting the projection into the forces too gave the
 * point the grid's fresh velocity each step, an inelastic collision that
 * lost 0.5 % of the energy a period.) The MUSL re-map (step 5) takes the
 * extra momentum off again and shares it the same way. Several heavy
 * points that share nodes are solved by Gauss-Seidel sweeps in body order
 * to a relative 1e-12.
 *
 * The walls are the grid's own constraints: the weights are those the
 * gather sees, ghost nodes folded into their mirrors with the image's sign
 * (grid_walls.c), and a component a wall holds at zero is not changed (an
 * infinite mass there). Runs with contact keep the lumped heavy point and
 * the node-holding pins (the bodies' own fields would need the same
 * split). The papers' point-force
 * membranes keep it too: [M] §3.1.1 and [T] App. A.2 lump it, and their
 * pages (V1, the noise spring) reproduce what that gives. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "step.h"

/* One heavy or pinned point of the step. */
typedef struct lm_con {
    size_t q;
    double vx, vy;      /* what M' brings: its velocity or its acceleration */
    double minv;        /* 1 / M' (0: a pin, an infinite mass) */
    int pin;            /* the pin holding q, or -1: a heavy point */
    double jx, jy;      /* the impulse (or force) the solve put on the nodes */
} lm_con;

/* A node's weight for particle q as the gather sees it, per velocity
 * component (0 where a wall holds the component). */
typedef struct cw {
    long i;
    double wx, wy;
} cw;

int lm_constraint_active(const lm_sim *sim)
{
    if (sim->contact) return 0;
    if (sim->npins) return 1;   /* pins hold their points (pin.c) */
    for (int b = 0; b < sim->nbodies; b++)
        if (sim->bodies[b].end_grid_mass > 0) return 1;
    return 0;
}

/* The image of grid index k across the walls of an axis of n cells:
 * k itself inside, -k or 2n - k beyond a walled side (sign of the image
 * for x and y in *sx, *sy). */
static int image(const lm_grid *g, int k, int n, int lo, int hi, int normal_x, double *sx,
                 double *sy)
{
    int side = k < 0 ? lo : k > n ? hi : -1;
    if (side < 0 || g->bc[side] == LM_BC_FREE) return k;
    if (g->bc[side] == LM_BC_FIXED) {
        *sx = -*sx;
        *sy = -*sy;
    } else if (normal_x) {
        *sx = -*sx;
    } else {
        *sy = -*sy;
    }
    return k < 0 ? -k : 2 * n - k;
}

/* Is component x (cx = 1) or y of node (ix, iy) held at zero by a wall? */
static int held(const lm_grid *g, int ix, int iy, int cx)
{
    if (ix == 0 && g->bc[LM_LEFT] != LM_BC_FREE && (cx || g->bc[LM_LEFT] == LM_BC_FIXED)) return 1;
    if (ix == g->nx && g->bc[LM_RIGHT] != LM_BC_FREE && (cx || g->bc[LM_RIGHT] == LM_BC_FIXED))
        return 1;
    if (iy == 0 && g->bc[LM_BOTTOM] != LM_BC_FREE && (!cx || g->bc[LM_BOTTOM] == LM_BC_FIXED))
        return 1;
    if (iy == g->ny && g->bc[LM_TOP] != LM_BC_FREE && (!cx || g->bc[LM_TOP] == LM_BC_FIXED))
        return 1;
    return 0;
}

/* Particle q's folded weights, merged by node: the count. */
static int weights(const lm_sim *sim, size_t q, cw *w)
{
    const lm_grid *g = &sim->grid;
    const int ns = g->sw * g->sw;
    lm_weights wt;
    lm_weights_of(sim, q, &wt);
    int n = 0;
    for (int c = 0; c < ns; c++) {
        double N = wt.N[c];
        if (N == 0) continue;
        int i = lm_stencil_node(g, g->sw, sim->p.node[q], c);
        int ix = i % g->sx - g->pad, iy = i / g->sx - g->pad;
        double sx = 1, sy = 1;
        ix = image(g, ix, g->nx, LM_LEFT, LM_RIGHT, 1, &sx, &sy);
        iy = image(g, iy, g->ny, LM_BOTTOM, LM_TOP, 0, &sx, &sy);
        long j = lm_grid_node(g, ix, iy);
        double wx = held(g, ix, iy, 1) ? 0 : sx * N, wy = held(g, ix, iy, 0) ? 0 : sy * N;
        int k = 0;
        while (k < n && w[k].i != j) k++;
        if (k == n) w[n++] = (cw){j, 0, 0};
        w[k].wx += wx;
        w[k].wy += wy;
    }
    return n;
}

/* The mass beyond the wire's share of body b's heavy end point (0: none). */
static double heavy_extra(const lm_sim *sim, int b, size_t *q)
{
    const lm_body *bd = &sim->bodies[b];
    if (!(bd->end_grid_mass > 0) || bd->count == 0) return 0;
    *q = bd->first + bd->count - 1;
    double e = sim->p.m[*q] - bd->end_grid_mass;
    return e > 0 ? e : 0;
}

/* Takes each heavy point's extra mass M' and momentum M' v off what a
 * scatter put on the nodes (m may be NULL: the re-map's momenta only).
 * The walls' folds are the gather's transpose, so the image weights with
 * the wall's own component left in are what the scatter added (the wall
 * zeroes that component afterwards). */
static void take_off_point(lm_sim *sim, size_t q, double e, double *m, double *ux, double *uy)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const int ns = g->sw * g->sw;
    lm_weights wt;
    lm_weights_of(sim, q, &wt);
    for (int c = 0; c < ns; c++) {
        double N = wt.N[c];
        int i = lm_stencil_node(g, g->sw, p->node[q], c);
        int ix = i % g->sx - g->pad, iy = i / g->sx - g->pad;
        double sx = 1, sy = 1;
        ix = image(g, ix, g->nx, LM_LEFT, LM_RIGHT, 1, &sx, &sy);
        iy = image(g, iy, g->ny, LM_BOTTOM, LM_TOP, 0, &sx, &sy);
        long j = lm_grid_node(g, ix, iy);
        if (m) {
            double before = m[j];
            m[j] -= e * N;
            /* what the rest put there, or rounding: nothing */
            if (!(m[j] > 1e-12 * before)) m[j] = 0;
        }
        ux[j] -= e * p->vx[q] * sx * N;
        uy[j] -= e * p->vy[q] * sy * N;
    }
}

/* The heavy points' extra mass, and the pinned points' whole mass: an
 * infinite mass needs no lumped share, and a lumped share left on the
 * nodes would be thrown away each step (its particle velocity reset to
 * the pin's) and re-scattered: measured +4.18 % on the trampoline's energy
 * in 3 s against +0.27 % with it off (docs/robustness.md). */
static void take_off(lm_sim *sim, double *m, double *ux, double *uy)
{
    for (int b = 0; b < sim->nbodies; b++) {
        size_t q;
        double e = heavy_extra(sim, b, &q);
        if (e > 0 && !sim->p.pin[q]) take_off_point(sim, q, e, m, ux, uy);
    }
    for (int k = 0; k < sim->npins; k++) {
        const lm_pin *pn = &sim->pins[k];
        size_t first = sim->bodies[pn->body].first;
        for (size_t j = 0; j < pn->n && pn->point; j++) {
            size_t q = first + pn->idx[j];
            take_off_point(sim, q, sim->p.m[q], m, ux, uy);
        }
    }
}

/* Step 1, after the scatter. */
void lm_constraint_p2g(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    take_off(sim, g->m, g->px, g->py);
}

/* The same off the given sums (multi-rate stepping's membrane sums,
 * subcycle_terms.c). */
void lm_constraint_take_off(lm_sim *sim, double *m, double *ux, double *uy)
{
    take_off(sim, m, ux, uy);
}

/* Step 5 (MUSL), after the re-map's scatter of m_p v_p. */
void lm_constraint_remap(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    if (lm_constraint_active(sim)) take_off(sim, NULL, g->vx, g->vy);
}

static size_t count(const lm_sim *sim)
{
    size_t n = 0;
    for (int b = 0; b < sim->nbodies; b++) n += sim->bodies[b].end_grid_mass > 0;
    for (int k = 0; k < sim->npins; k++) n += sim->pins[k].n;
    return n;
}

/* Made when a heavy point or a pin is added, so that a step needs no
 * memory of its own. */
lm_status lm_constraint_reserve(lm_sim *sim)
{
    size_t n = count(sim);
    if (n <= sim->work->capcons) return LM_OK;
    lm_con *c = realloc(sim->work->cons, n * sizeof *c);
    if (!c) {
        snprintf(sim->err, sizeof sim->err, "out of memory for %zu heavy points", n);
        return LM_ERR_MEMORY;
    }
    sim->work->cons = c;
    sim->work->capcons = n;
    return LM_OK;
}

/* The step's heavy points, then the pinned points (a pinned heavy point
 * is the pin's). */
static void gather(lm_sim *sim)
{
    lm_con *c = sim->work->cons;
    size_t j = 0, cap = sim->work->capcons;
    for (int b = 0; b < sim->nbodies && j < cap; b++) {
        size_t q;
        double e = heavy_extra(sim, b, &q);
        if (!(e > 0) || sim->p.pin[q]) continue;
        c[j++] = (lm_con){q, 0, 0, 1 / e, -1, 0, 0};
    }
    for (int k = 0; k < sim->npins; k++) {
        const lm_pin *pn = &sim->pins[k];
        size_t first = sim->bodies[pn->body].first;
        for (size_t i = 0; i < pn->n && j < cap && pn->point; i++)
            c[j++] = (lm_con){first + pn->idx[i], 0, 0, 0, k, 0, 0};
    }
    sim->work->ncons = j;
}

/* What M' brings to the field solved next: its velocity, or its own
 * acceleration, gravity (the grid no longer carries its weight). A pinned
 * point brings its velocity (the pin's of the last step), then the
 * acceleration to this step's pin velocity, so that the interpolated
 * p^L / m is the pin's velocity at the point. */
static void targets(lm_sim *sim, int accel)
{
    const lm_particles *p = &sim->p;
    double dt = sim->def.dt;
    for (size_t a = 0; a < sim->work->ncons; a++) {
        lm_con *c = &sim->work->cons[a];
        const lm_pin *pn = c->pin >= 0 ? &sim->pins[c->pin] : NULL;
        if (!accel) {
            c->vx = p->vx[c->q];
            c->vy = p->vy[c->q];
        } else if (pn) {
            c->vx = (pn->vx - p->vx[c->q]) / dt;
            c->vy = (pn->vy - p->vy[c->q]) / dt;
        } else {
            c->vx = sim->def.gx;
            c->vy = sim->def.gy;
        }
        c->jx = c->jy = 0;
    }
}

/* Gauss-Seidel over the heavy points on a nodal field u with the lumped
 * masses m: momenta or forces (vel = 0: the field is m_i times what is
 * interpolated) or velocities (vel = 1). */
static void solve(lm_sim *sim, int vel, double *ux, double *uy)
{
    const double *m = sim->grid.m;
    lm_con *c = sim->work->cons;
    double scale = 0;
    for (size_t a = 0; a < sim->work->ncons; a++)
        scale = fmax(scale, fmax(fabs(c[a].vx), fabs(c[a].vy)));
    for (int sweep = 0; sweep < 1000; sweep++) {
        double worst = 0;
        for (size_t a = 0; a < sim->work->ncons; a++) {
            cw w[16];
            int n = weights(sim, c[a].q, w);
            double sx = 0, sy = 0, Sx = 0, Sy = 0;
            for (int k = 0; k < n; k++) {
                double mi = m[w[k].i];
                if (!(mi > 0)) continue;
                double r = vel ? 1 : 1 / mi;
                sx += w[k].wx * ux[w[k].i] * r;
                sy += w[k].wy * uy[w[k].i] * r;
                Sx += w[k].wx * w[k].wx / mi;
                Sy += w[k].wy * w[k].wy / mi;
            }
            scale = fmax(scale, fmax(fabs(sx), fabs(sy)));
            double minv = c[a].minv;
            double rx = c[a].vx - sx, ry = c[a].vy - sy;
            /* a pinned component no free node reaches (on a wall, or its
             * nodes' mass all held): nothing to hold */
            double dx = Sx + minv > 0 ? rx / (Sx + minv) : 0;
            double dy = Sy + minv > 0 ? ry / (Sy + minv) : 0;
            if (Sx + minv > 0) worst = fmax(worst, fabs(rx));
            if (Sy + minv > 0) worst = fmax(worst, fabs(ry));
            for (int k = 0; k < n; k++) {
                long i = w[k].i;
                double mi = m[i];
                if (!(mi > 0)) continue;
                double r = vel ? 1 / mi : 1;
                ux[i] += dx * w[k].wx * r;
                uy[i] += dy * w[k].wy * r;
                c[a].jx += dx * w[k].wx;
                c[a].jy += dy * w[k].wy;
            }
            c[a].vx -= dx * minv;
            c[a].vy -= dy * minv;
        }
        /* one point: its residual is rounding after one sweep */
        if (sim->work->ncons < 2 || !(worst > 1e-12 * scale)) break;
    }
}

/* Step 3 with the walls applied to p and f, before p^L = p + dt f. Each
 * pin's reaction, the force it exerted on the material this step, is what
 * changes the particles' momentum (FLIP, step 4, carries the forces only):
 * the force solve's lambda N_i, what held the point itself,
 * m_q (a_pin - g) (its weight is on no node), and the force at the nodes
 * only held points reach (massless_share). The momentum solve's impulse
 * is not in it: it makes the grid's velocity at the point the point's,
 * which moves the material and its strain, but no particle's momentum
 * (sum m_p dv_p = dt (reactions + weight) to rounding: measured on a
 * string under gravity driven at one end). */
/* At the nodes left without mass: pass 0 zeroes the scratch W, pass 1
 * counts each pinned point's weight W_j, pass 2 gives each pin's reaction
 * its share N_qj / W_j of the force there, which only held points put
 * there and the pin absorbs (a node without mass is not moved). */
static void massless_share(lm_sim *sim, double *W, int pass)
{
    const lm_grid *g = &sim->grid;
    const int ns = g->sw * g->sw;
    for (size_t a = 0; a < sim->work->ncons; a++) {
        const lm_con *c = &sim->work->cons[a];
        if (c->pin < 0) continue;
        lm_pin *pn = &sim->pins[c->pin];
        lm_weights wt;
        lm_weights_of(sim, c->q, &wt);
        for (int k = 0; k < ns; k++) {
            double N = wt.N[k];
            int i = lm_stencil_node(g, g->sw, sim->p.node[c->q], k);
            int ix = i % g->sx - g->pad, iy = i / g->sx - g->pad;
            double sx = 1, sy = 1;
            ix = image(g, ix, g->nx, LM_LEFT, LM_RIGHT, 1, &sx, &sy);
            iy = image(g, iy, g->ny, LM_BOTTOM, LM_TOP, 0, &sx, &sy);
            long j = lm_grid_node(g, ix, iy);
            if (g->m[j] > 0 || !(N > 0)) continue;
            if (pass == 0) {
                W[j] = 0;
            } else if (pass == 1) {
                W[j] += N;
            } else if (W[j] > 0) {
                pn->rx -= g->fx[j] * N / W[j];
                pn->ry -= g->fy[j] * N / W[j];
            }
        }
    }
}

/* The point pins' reactions from the force solve(s) of the step. */
static void reactions(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    double dt = sim->def.dt;
    for (size_t a = 0; a < sim->work->ncons; a++) {
        const lm_con *c = &sim->work->cons[a];
        if (c->pin < 0) continue;
        lm_pin *pn = &sim->pins[c->pin];
        double mq = p->m[c->q];
        pn->rx += c->jx + mq * ((pn->vx - p->vx[c->q]) / dt - sim->def.gx);
        pn->ry += c->jy + mq * ((pn->vy - p->vy[c->q]) / dt - sim->def.gy);
    }
    if (sim->npins) {
        /* scratch: step 4 writes every node's ax afresh */
        for (int pass = 0; pass < 3; pass++) massless_share(sim, g->ax, pass);
    }
}

/* Before the force solve: the point pins' reactions start from zero. */
static void reactions_clear(lm_sim *sim)
{
    for (int k = 0; k < sim->npins; k++)
        if (sim->pins[k].point) sim->pins[k].rx = sim->pins[k].ry = 0;
}

void lm_constraint_grid(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    gather(sim);
    targets(sim, 0);
    solve(sim, 0, g->px, g->py);
    reactions_clear(sim);
    targets(sim, 1);
    solve(sim, 0, g->fx, g->fy);
    reactions(sim);
}

/* mass = "corrected" (mass_corrected.c). The Neumann step
 * u = u_L + M_L^-1 (M_L - M_C) u_L is the consistent mass's only if u_L
 * and the correction are both solved with the constraint: with K the
 * lumped mass plus the heavy points' M' N N^T (or a pin's projection),
 * u = K^-1 r + K^-1 (M_L - M_C) K^-1 r, symmetric as a mass's inverse
 * must be. Correcting first and constraining after (as before) gave
 * P (2 M_L^-1 - M_L^-1 M_C M_L^-1), which is not symmetric: the pinned
 * string gained 22.6 % of its kinetic energy in 3 periods of mode 1 (cell
 * 1/16) and a pinned string at rest moved 0.64 % of a cell. So the
 * correction calls this on the velocity u_L (vel = 1 form) with the
 * field's own targets, then on the correction with none (M' brings
 * nothing to it): the reaction is the sum of both force solves' impulses.
 * what: 0 momenta (the step's points gathered first), 1 forces (the point
 * pins' reactions restart), 2 the strain velocities (step 5), 3 the
 * correction (no targets; the impulses add to the last field's). */
void lm_constraint_field(lm_sim *sim, int what, double *ux, double *uy)
{
    if (what == 0) gather(sim);
    if (what == 1) reactions_clear(sim);
    if (what == 3) {
        for (size_t a = 0; a < sim->work->ncons; a++) sim->work->cons[a].vx = sim->work->cons[a].vy = 0;
    } else {
        targets(sim, what == 1);
    }
    solve(sim, 1, ux, uy);
}

/* mass = "corrected": after the force field's two solves. */
void lm_constraint_reactions(lm_sim *sim)
{
    reactions(sim);
}

/* Step 5, after the walls: the strain velocities share M' v the same way. */
void lm_constraint_velocity(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    targets(sim, 0);
    solve(sim, 1, g->vx, g->vy);
}
