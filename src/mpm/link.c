/* link.c - a force-displacement link between two material points: [F]
 * §4.4's closing suggestion for the airbag's tether ("prescribe a
 * force-displacement relationship between two material points ... This
 * force would be interpolated to the grid at the two particle locations
 * and included as an external force").
 *
 * A link pulls its two points toward each other with the tension
 * T = k (l - L0) of a bar or cable of stiffness k (force per unit
 * extension) and rest length L0; a "cable" carries no compression (T = 0
 * for l < L0), a "spring" pushes too. Step 2 adds T e to one point and -T e
 * to the other (e the unit vector between them), spread to the nodes with
 * N_ip like any external force; its stored energy k (l - L0)^2 / 2 counts
 * as strain energy. The force is the gradient of that energy, so a link
 * conserves energy as a segment does (membrane_force.c). In the
 * axisymmetric form k is the whole link's and forces are per radian, so a
 * link contributes T / (2 pi): along the axis (a tether between two poles)
 * it is the real tether; between two rings it is a cone of cords. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact.h"
#include "step.h"

static const double TWO_PI = 6.283185307179586;

static size_t point_of(const lm_sim *sim, const lm_link *lk, int end)
{
    return sim->bodies[lk->body[end]].first + lk->idx[end];
}

/* Present length of link k. */
double lm_link_length(const lm_sim *sim, int k)
{
    const lm_link *lk = &sim->links[k];
    size_t a = point_of(sim, lk, 0), b = point_of(sim, lk, 1);
    return hypot(sim->p.x[b] - sim->p.x[a], sim->p.y[b] - sim->p.y[a]);
}

/* Tension of link k at length l (0 when inactive or a slack cable). */
static double tension_at(const lm_link *lk, double l)
{
    double s = l - lk->L0;
    if (!lk->active || (lk->cable && s < 0)) return 0;
    return lk->k * s;
}

double lm_link_tension(const lm_sim *sim, int k)
{
    return tension_at(&sim->links[k], lm_link_length(sim, k));
}

static int in_contact(const lm_sim *sim, int b)
{
    const lm_contact *c = sim->contact;
    return c && b < c->nbodies_alloc && c->of_body[b] >= 0;
}

int lm_sim_add_link(lm_sim *sim, int ba, size_t ia, int bb, size_t ib, double k, double L0,
                    int cable)
{
    char who[96];
    int bs[2] = {ba, bb};
    size_t is[2] = {ia, ib};
    for (int e = 0; e < 2; e++) {
        if (bs[e] < 0 || bs[e] >= sim->nbodies) {
            snprintf(sim->err, sizeof sim->err, "a link joins two points of this simulation's bodies");
            return -1;
        }
        const lm_body *bd = &sim->bodies[bs[e]];
        if (is[e] >= bd->count) {
            snprintf(sim->err, sizeof sim->err, "%s has %zu points; it has no point %zu",
                     lm_body_label(sim, bs[e], who, sizeof who), bd->count, is[e] + 1);
            return -1;
        }
        if (in_contact(sim, bs[e])) {
            /* the pairs' own fields would not see the link's force */
            snprintf(sim->err, sizeof sim->err,
                     "%s is in a contact pair: links and contact do not mix yet",
                     lm_body_label(sim, bs[e], who, sizeof who));
            return -1;
        }
    }
    if (ba == bb && ia == ib) {
        snprintf(sim->err, sizeof sim->err, "a link needs two different points");
        return -1;
    }
    if (!(k > 0) || !isfinite(k)) {
        snprintf(sim->err, sizeof sim->err, "stiffness must be a finite number > 0 (got %g)", k);
        return -1;
    }
    if (!(L0 >= 0) || !isfinite(L0)) {
        snprintf(sim->err, sizeof sim->err, "length must be a finite number >= 0 (got %g)", L0);
        return -1;
    }
    if (sim->nlinks >= LM_MAX_LINKS) {
        snprintf(sim->err, sizeof sim->err, "at most %d links", LM_MAX_LINKS);
        return -1;
    }
    lm_link *links = realloc(sim->links, (size_t)(sim->nlinks + 1) * sizeof *links);
    if (!links) {
        snprintf(sim->err, sizeof sim->err, "out of memory for a link");
        return -1;
    }
    sim->links = links;
    lm_link *lk = &links[sim->nlinks];
    memset(lk, 0, sizeof *lk);
    lk->body[0] = ba;
    lk->body[1] = bb;
    lk->idx[0] = ia;
    lk->idx[1] = ib;
    lk->k = k;
    lk->L0 = L0;
    lk->cable = cable != 0;
    lk->active = 1;
    return sim->nlinks++;
}

void lm_sim_set_link_active(lm_sim *sim, int k, int on)
{
    if (k >= 0 && k < sim->nlinks) sim->links[k].active = on != 0;
}

/* Does link lk touch a membrane (multi-rate stepping's fast group)? */
static int touches_membrane(const lm_sim *sim, const lm_link *lk)
{
    return sim->bodies[lk->body[0]].membrane || sim->bodies[lk->body[1]].membrane;
}

/* Each active link's pull on its two points, spread with N_ip into
 * (fx, fy), folded; which: LM_LINKS_ALL, or only those that touch a
 * membrane (LM_LINKS_FAST) or none (LM_LINKS_SLOW). */
void lm_link_forces_into(lm_sim *sim, double *fx, double *fy, int which)
{
    if (sim->nlinks == 0) return;
    lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const int W = g->sw, NS = W * W;
    double per = sim->def.axisym ? 1 / TWO_PI : 1;
    int any = 0;
    for (int k = 0; k < sim->nlinks; k++) {
        const lm_link *lk = &sim->links[k];
        if (which != LM_LINKS_ALL && touches_membrane(sim, lk) != (which == LM_LINKS_FAST))
            continue;
        double l = lm_link_length(sim, k), T = tension_at(lk, l) * per;
        if (T == 0 || !(l > 0)) continue;
        size_t a = point_of(sim, lk, 0), b = point_of(sim, lk, 1);
        double ex = (p->x[b] - p->x[a]) / l, ey = (p->y[b] - p->y[a]) / l;
        for (int e = 0; e < 2; e++) {
            size_t q = e ? b : a;
            double s = e ? -T : T;   /* a is pulled toward b, b toward a */
            lm_weights wt;
            lm_weights_of(sim, q, &wt);
            const double *N = wt.N;
            for (int j = 0; j < NS; j++) {
                long i = lm_stencil_node(g, W, p->node[q], j);
                fx[i] += s * ex * N[j];
                fy[i] += s * ey * N[j];
            }
        }
        any = 1;
    }
    if (!any) return;
    /* the scatter's fold emptied the ghost nodes; fold the links' share */
    double *const f[2] = {fx, fy};
    static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
    lm_grid_fold(g, 2, f, comp);
}

/* Step 2: each active link's pull on its two points, spread with N_ip. */
void lm_link_forces(lm_sim *sim)
{
    lm_link_forces_into(sim, sim->grid.fx, sim->grid.fy, LM_LINKS_ALL);
}

/* Stored energy of the active links (per radian in the axisymmetric
 * form, as every energy there). */
double lm_link_energy(const lm_sim *sim)
{
    double w = 0, per = sim->def.axisym ? 1 / TWO_PI : 1;
    for (int k = 0; k < sim->nlinks; k++) {
        double T = lm_link_tension(sim, k);
        if (T != 0) w += 0.5 * T * T / sim->links[k].k * per;
    }
    return w;
}
