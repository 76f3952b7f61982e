/* pin.c - particles held fixed or driven at a prescribed velocity, wherever
 * they are (issue 13: pinning a membrane away from the walls; issue 30
 * item 3: holding only the point).
 *
 * Holding only the particle would not do: its neighbours share its nodes,
 * and the grid would carry them (and, through the nodes, the particle's own
 * strain) off. So a pin acts on the grid, but only as much as the point
 * needs: a pinned point is a point of infinite mass tied to the grid by
 * constraint.c (the heavy end point's consistent-mass constraint with
 * 1/M' = 0). Its lumped mass and momentum are taken off the nodes (an
 * infinite mass needs no lumped share; left on, its share of the nodes'
 * motion is thrown away each step when its velocity is reset to the pin's:
 * the trampoline gained 4.18 % in 3 s against 0.27 %), then the nodes get
 * the impulse lambda N_i that makes sum_i N_i p_i / m_i the point's
 * velocity, and the force lambda N_i that makes sum_i N_i f_i / m_i the
 * pin's acceleration, so FLIP (step 4) carries the constrained
 * accelerations to the neighbours; the MUSL strain velocity (step 5) is
 * projected the same way. The held particle's own velocity and position
 * are set to the pin's exactly (a point held at rest does not move at
 * all). The impulses, with the force that holds the point itself,
 * m_q (a_pin - g), are the reaction (constraint.c). On the defaults this
 * takes the pinned string from +4.59 / +3.67 % (modes 1 / 2, cell 1/32)
 * to the walled string's -0.25 / -0.99 % (docs/robustness.md).
 *
 * A pin whose points lie closer together than a stencil (a pinned edge, a
 * lid, "all": some node touched by two held points), and every pin with
 * sim:contact (each body its own field: contact.c, contact_correct.c),
 * still holds every node its points touch (N_ip > 0), as a wall does,
 * weighted by N_ip where two pins share a node: p_i^L = m_i v_pin in step
 * 3 with the force corrected to match, the strain velocity again in step
 * 5; the correction is the reaction. There the nodes may have no free mass
 * left once the held masses are off and the constraints' system is
 * singular (a block's lid of 1000 points: the Gauss-Seidel sweeps ran out
 * and the energy grew), and the constraint is not built for the bodies'
 * own fields. The choice is made each step (classify). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "step.h"
#include "util.h"


int lm_sim_add_pin(lm_sim *sim, int b, const size_t *idx, size_t n, double vx, double vy)
{
    if (b < 0 || b >= sim->nbodies || n == 0 || !isfinite(vx) || !isfinite(vy)) {
        snprintf(sim->err, sizeof sim->err,
                 "a pin needs a body, at least one point and a finite velocity");
        return -1;
    }
    const lm_body *bd = &sim->bodies[b];
    char who[96];
    for (size_t k = 0; k < n; k++) {
        if (idx[k] >= bd->count) {
            snprintf(sim->err, sizeof sim->err, "%s has %zu points; point %zu cannot be pinned",
                     lm_body_label(sim, b, who, sizeof who), bd->count, idx[k] + 1);
            return -1;
        }
        if (sim->p.pin[bd->first + idx[k]]) {
            snprintf(sim->err, sizeof sim->err, "point %zu of %s is pinned already",
                     idx[k] + 1, lm_body_label(sim, b, who, sizeof who));
            return -1;
        }
    }
    size_t nn = lm_grid_nodes(&sim->grid);
    if (!sim->work->pin_w) {
        sim->work->pin_w = calloc(3 * nn, sizeof(double));
        if (!sim->work->pin_w) goto oom;
        sim->work->pin_vx = sim->work->pin_w + nn;
        sim->work->pin_vy = sim->work->pin_w + 2 * nn;
    }
    lm_pin *pn = lu_push(&sim->pins, (size_t)sim->npins, sizeof *sim->pins);
    if (!pn) goto oom;
    pn->idx = malloc(n * sizeof *pn->idx);
    pn->x0 = malloc(2 * n * sizeof *pn->x0);
    if (!pn->idx || !pn->x0) {
        free(pn->idx);
        free(pn->x0);
        goto oom;
    }
    memcpy(pn->idx, idx, n * sizeof *idx);
    pn->body = b;
    pn->n = n;
    pn->vx = vx;
    pn->vy = vy;
    for (size_t k = 0; k < n; k++) sim->p.pin[bd->first + idx[k]] = sim->npins + 1;
    sim->npins++;
    if (lm_constraint_reserve(sim) != LM_OK) return -1;   /* sim->err says why */
    return sim->npins - 1;
oom:
    snprintf(sim->err, sizeof sim->err, "out of memory for a pin of %zu points", n);
    return -1;
}

void lm_sim_set_pin_velocity(lm_sim *sim, int pin, double vx, double vy)
{
    if (pin < 0 || pin >= sim->npins) return;
    sim->pins[pin].vx = vx;
    sim->pins[pin].vy = vy;
}

/* The stencil of pin pn's point j: its ns nodes in node[] and their
 * weights N_ip in w[], row by row (the order every loop here sums in). */
static void held_stencil(const lm_sim *sim, const lm_pin *pn, size_t j, int node[9],
                         double w[9])
{
    const lm_grid *g = &sim->grid;
    size_t q = sim->bodies[pn->body].first + pn->idx[j];
    lm_weights wt;
    lm_weights_of(sim, q, &wt);
    for (int c = 0; c < g->sw * g->sw; c++) {
        node[c] = lm_stencil_node(g, g->sw, sim->p.node[q], c);
        w[c] = wt.N[c];
    }
}

/* Does any pin hold its nodes this step? */
static int holds_nodes(const lm_sim *sim)
{
    for (int k = 0; k < sim->npins; k++)
        if (!sim->pins[k].point) return 1;
    return 0;
}

/* Which pins hold their points this step: those whose every point shares
 * no node with another held point (the string's ends, a sheet's corners,
 * the airbag's pole). Points packed closer (a pinned edge, a lid, "all")
 * hold their nodes: there every node they touch may have no free mass
 * left, and the constraints' system is singular (measured: a block's lid
 * of 1000 points, the Gauss-Seidel sweeps ran out and the energy grew).
 * With contact every pin holds its nodes. Counts in pin_w, zeroed after. */
static void classify(lm_sim *sim)
{
    const int ns = sim->grid.sw * sim->grid.sw;
    const int point = lm_constraint_active(sim);
    for (int pass = 0; pass < 3; pass++) {
        for (int k = 0; k < sim->npins; k++) {
            lm_pin *pn = &sim->pins[k];
            if (pass == 1) pn->point = point;
            for (size_t j = 0; j < pn->n && point; j++) {
                int node[9];
                double w[9];
                held_stencil(sim, pn, j, node, w);
                for (int c = 0; c < ns; c++) {
                    if (!(w[c] > 0)) continue;
                    int i = node[c];
                    if (pass == 0) sim->work->pin_w[i] += 1;
                    else if (pass == 1 && sim->work->pin_w[i] > 1) pn->point = 0;
                    else if (pass == 2) sim->work->pin_w[i] = 0;
                }
            }
        }
    }
}

/* The pinned points' positions before a move (step 1, and each of the
 * multi-rate sub-steps: subcycle_terms.c); lm_pin_particles moves them
 * with their pins from there. */
void lm_pin_keep_start(lm_sim *sim)
{
    for (int k = 0; k < sim->npins; k++) {
        lm_pin *pn = &sim->pins[k];
        size_t first = sim->bodies[pn->body].first;
        for (size_t j = 0; j < pn->n; j++) {
            pn->x0[2 * j] = sim->p.x[first + pn->idx[j]];
            pn->x0[2 * j + 1] = sim->p.y[first + pn->idx[j]];
        }
    }
}

/* Step 1: which pins hold their points; the held points' positions kept;
 * the heavy and point-held masses off the grid (constraint.c); for the
 * pins that hold nodes, w_i = sum N_ip and sum N_ip v_pin over their
 * particles. */
void lm_pin_p2g(lm_sim *sim)
{
    if (sim->npins) classify(sim);
    if (lm_constraint_active(sim)) lm_constraint_p2g(sim);   /* heavy ends, pins */
    lm_pin_keep_start(sim);
    if (!holds_nodes(sim)) return;
    size_t nn = lm_grid_nodes(&sim->grid);
    const int ns = sim->grid.sw * sim->grid.sw;
    memset(sim->work->pin_w, 0, 3 * nn * sizeof(double));
    for (int k = 0; k < sim->npins; k++) {
        const lm_pin *pn = &sim->pins[k];
        if (pn->point) continue;
        for (size_t j = 0; j < pn->n; j++) {
            int node[9];
            double w[9];
            held_stencil(sim, pn, j, node, w);
            for (int c = 0; c < ns; c++) {
                sim->work->pin_w[node[c]] += w[c];
                sim->work->pin_vx[node[c]] += w[c] * pn->vx;
                sim->work->pin_vy[node[c]] += w[c] * pn->vy;
            }
        }
    }
}

/* Step 3, before the walls: p_i^L = m_i v_pin at held nodes, f_i changed
 * by the same amount over dt; each pin's reaction is its share of those
 * changes. */
void lm_pin_grid(lm_sim *sim)
{
    if (!holds_nodes(sim)) return;
    lm_grid *g = &sim->grid;
    double dt = sim->def.dt;
    const int ns = g->sw * g->sw;
    for (int k = 0; k < sim->npins; k++) {
        lm_pin *pn = &sim->pins[k];
        if (pn->point) continue;   /* its reaction is constraint.c's */
        pn->rx = pn->ry = 0;
        for (size_t j = 0; j < pn->n; j++) {
            int node[9];
            double w[9];
            held_stencil(sim, pn, j, node, w);
            for (int c = 0; c < ns; c++) {
                int i = node[c];
                if (!(w[c] > 0)) continue;
                const double *pw = sim->work->pin_w;
                double s = w[c] / pw[i];
                pn->rx += s * (g->m[i] * sim->work->pin_vx[i] / pw[i] - g->px[i]) / dt;
                pn->ry += s * (g->m[i] * sim->work->pin_vy[i] / pw[i] - g->py[i]) / dt;
            }
        }
    }
    lm_pin_hold(sim, g->m, g->px, g->py, g->fx, g->fy);
}

void lm_pin_hold(const lm_sim *sim, const double *m, double *px, double *py, double *fx,
                 double *fy)
{
    size_t nn = lm_grid_nodes(&sim->grid);
    double dt = sim->def.dt;
    for (size_t i = 0; i < nn; i++) {
        if (!(sim->work->pin_w[i] > 0) || m[i] <= 0) continue;
        double hx = m[i] * sim->work->pin_vx[i] / sim->work->pin_w[i];
        double hy = m[i] * sim->work->pin_vy[i] / sim->work->pin_w[i];
        fx[i] += (hx - px[i]) / dt;
        fy[i] += (hy - py[i]) / dt;
        px[i] = hx;
        py[i] = hy;
    }
}

/* After step 4: the held particles take the pin's velocity exactly (FLIP
 * would carry the difference between their velocity and their nodes'),
 * and, held by the constraint, its move: the interpolated v^L is the
 * pin's only to rounding. */
void lm_pin_particles(lm_sim *sim)
{
    lm_particles *p = &sim->p;
    double dt = sim->def.dt;
    for (int k = 0; k < sim->npins; k++) {
        const lm_pin *pn = &sim->pins[k];
        size_t first = sim->bodies[pn->body].first;
        for (size_t j = 0; j < pn->n; j++) {
            size_t q = first + pn->idx[j];
            p->vx[q] = pn->vx;
            p->vy[q] = pn->vy;
            if (pn->point) {
                p->x[q] = pn->x0[2 * j] + dt * pn->vx;
                p->y[q] = pn->x0[2 * j + 1] + dt * pn->vy;
            }
        }
    }
}

/* Step 5, before the walls: the strain velocity at held nodes. */
void lm_pin_velocity(lm_sim *sim)
{
    if (!holds_nodes(sim)) return;   /* constraint.c projects the rest */
    lm_grid *g = &sim->grid;
    size_t nn = lm_grid_nodes(g);
    for (size_t i = 0; i < nn; i++) {
        if (!(sim->work->pin_w[i] > 0)) continue;
        g->vx[i] = sim->work->pin_vx[i] / sim->work->pin_w[i];
        g->vy[i] = sim->work->pin_vy[i] / sim->work->pin_w[i];
    }
}
