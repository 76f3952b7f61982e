/* subcycle_kick.h - the impulse forms' sub-steps after the kick sweep only
 * the nodes the membranes can change (subcycle_kick.c; multi-rate stepping,
 * subcycle.c). */
#ifndef LAMINA_SUBCYCLE_KICK_H
#define LAMINA_SUBCYCLE_KICK_H

#include "subcycle_band.h"

/* The forms whose slow force acts in the first sub-step alone and whose
 * slow momentum is the consistent re-map (multirate = "impulse", "half"). */
int lm_kick_banded(const lm_sim *sim);
/* After the first sub-step (the kick, swept on every node): the band of the
 * sub-steps that follow. b->core: the corners of the stencils that lie in
 * S, the membranes' stencils at x^n widened by one node, closed under the
 * walls' images (where A can change); b->in, idx: every node whose
 * consistent re-map reads S, directly or through a ghost row's fold. */
void lm_kick_band_build(lm_band *b, const lm_sim *sim);
/* Before sub-step `done` (>= 1): 1 if a membrane's stencil has left S; then
 * the nodes outside the band have been brought to sub-step `done` and the
 * caller sweeps every node from here on (lm_band_all). */
int lm_kick_band_grow(lm_band *b, lm_sim *sim, const lm_band_nodes *a, double *Rx, double *Ry,
                      int done, double dt);
/* Every node outside the band through sub-steps 1 .. k - 1 of dt at once,
 * and the ghost nodes' A, X, V (and R, MUSL) from their mirrors. */
void lm_kick_band_far(lm_sim *sim, const lm_band *b, const lm_band_nodes *a, double *Rx,
                      double *Ry, int k, double dt);

#endif
