/* subcycle_terms.h - multi-rate stepping's terms for the axisymmetric
 * form, pins and links (subcycle_terms.c; called by subcycle.c). */
#ifndef LM_SUBCYCLE_TERMS_H
#define LM_SUBCYCLE_TERMS_H

#include "step.h"

/* The axisymmetric form, links or pins: terms that reach nodes or steps
 * the sub-steps' band does not (a link's far end, a pin's solve in step
 * 3), so every node is swept (subcycle.c). */
int lm_subcycle_terms_active(const lm_sim *sim);
/* A heavy end point (end_mass) on some body: still refused. */
int lm_subcycle_heavy_point(const lm_sim *sim);
/* After step 1's pins (pin.c's classify): only point pins on membranes. */
lm_status lm_subcycle_check_pins(lm_sim *sim);
/* The membranes' sums' extra terms (after their fold, before gravity): the
 * membrane points' hoop forces, the links with an end on a membrane, the
 * pinned points' mass and momentum off. */
void lm_subcycle_fast_terms(lm_sim *sim, double *m, double *px, double *py, double *fx,
                            double *fy);
/* Around a sub-step's membrane move: the pinned points' start (before) and
 * their pin's velocity and move (after). */
void lm_subcycle_pins_start(lm_sim *sim);
void lm_subcycle_pins_moved(lm_sim *sim);
/* After sub-step j of k: the point pins' reactions summed; after the last
 * their mean, the force over the step. */
void lm_subcycle_pins_react(lm_sim *sim, int j, int k);

#endif
