/* subcycle_runs.h - the membranes' grid sums of a sub-step, point after
 * point along the curve (subcycle_runs.c; multi-rate stepping, subcycle.c). */
#ifndef LAMINA_SUBCYCLE_RUNS_H
#define LAMINA_SUBCYCLE_RUNS_H

#include "step.h"

/* m_p N_ip, m_p v_p N_ip and the internal force (the stress divergence or a
 * segment point's net tension) of every membrane point added into
 * f[0..5) (unfolded), as lm_k_scatter_mass_forces adds them, the same bits. */
void lm_runs_mass_forces(const lm_sim *sim, double *const *f);
/* m_p v_p N_ip into f[0], f[1] (MUSL's re-map), as lm_k_scatter_momentum. */
void lm_runs_momentum(const lm_sim *sim, double *const *f);

#endif
