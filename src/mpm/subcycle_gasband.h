/* subcycle_gasband.h - the gas points beside the membranes in the
 * sub-steps' fast group (lamina.sim{fast_band = w}; subcycle_gasband.c
 * says why and how; called by subcycle.c). */
#ifndef LM_SUBCYCLE_GASBAND_H
#define LM_SUBCYCLE_GASBAND_H

#include "step.h"

typedef struct lm_gasband {
    int w;                   /* join at distance <= w cells, leave at > w + 1 */
    unsigned char *fast;     /* a particle's flag: 1 a fast gas point */
    size_t cap;              /* particles the flags and keep have room for */
    size_t *idx;             /* the fast gas points, ascending */
    size_t n;
    double *keep;            /* their state around the slow group's update */
    unsigned char *dist;     /* a node's distance in cells to the nodes the
                                membranes' stencils reach, capped */
    unsigned char *reach;    /* 1: a fast point reached the node in some
                                sub-step of this step */
    size_t nn;
    double steps, points;    /* steps taken, fast gas points summed over them */
} lm_gasband;

/* NULL and LM_OK when fast_band is off; else the band, grown to the sim. */
lm_status lm_gasband_reserve(lm_sim *sim, lm_gasband **gb);
void lm_gasband_free(lm_gasband *gb);
/* What the band cannot do, by name (NULL: none). */
const char *lm_gasband_refusal(const lm_sim *sim);
/* At the step's start (the stencils at x^n): the fast gas points, with
 * hysteresis against their flags of the last step. */
void lm_gasband_select(lm_gasband *gb, const lm_sim *sim);
/* A particle's flag: membrane or fast gas point. */
static inline int lm_gasband_fast(const lm_gasband *gb, const lm_sim *sim, size_t q)
{
    return sim->bodies[sim->p.body[q]].membrane || (gb && gb->fast[q]);
}
/* The fast gas points' shares in a sub-step's sums, unfolded: m, px, py,
 * fx, fy (mass_forces) or px, py (momentum, MUSL's re-map). */
void lm_gasband_sums(const lm_sim *sim, const lm_gasband *gb, double *const *f);
void lm_gasband_momentum(const lm_sim *sim, const lm_gasband *gb, double *const *f);
/* After a sub-step's fast sums (start: the step's first, which resets):
 * the nodes with fast mass marked. */
void lm_gasband_reach(lm_gasband *gb, const double *mF, int start);
/* HELD's displacement on the nodes no fast point reached in the step: the
 * k sub-steps under the held force moved them by Dt v + Dt^2 a (k + 1) / (2k)
 * where the plain step moves them by Dt v + Dt^2 a; add the difference,
 * ((k - 1) / (2k)) Dt A (A = Dt a there), so that the slow gas away from the
 * band steps as the plain step at Dt (subcycle_gasband.c says why). */
void lm_gasband_far_displacement(const lm_gasband *gb, const double *Ax, const double *Ay,
                                 double *Xx, double *Xy, int k, double Dt);
/* Their shape functions at their present place, FLIP update, and stress
 * over dt from the grid's strain velocity (g->vx, g->vy). */
void lm_gasband_shape(lm_sim *sim, const lm_gasband *gb);
void lm_gasband_g2p(lm_sim *sim, const lm_gasband *gb, double dt, double pic);
void lm_gasband_stress(lm_sim *sim, const lm_gasband *gb, double dt);
/* Their state kept before the slow group's stress update and put back
 * after it (that update visits every point but the membranes'). */
void lm_gasband_keep(lm_sim *sim, lm_gasband *gb);
void lm_gasband_restore(lm_sim *sim, const lm_gasband *gb);

#endif
