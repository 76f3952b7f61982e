/* threads.h - the step's loops over particles on sim->def.threads threads
 * (OpenMP when built with it; otherwise everything runs on one).
 *
 * Determinism (docs/design.md, "Engine"): a loop that writes only its own particle is the
 * same on any number of threads. A scatter to the grid gives each thread a
 * fixed, contiguous range of particles and its own copy of the nodal
 * fields; the copies are added in thread order. So the state depends on the
 * thread count only, never on timing, and one thread is the plain serial
 * loop. */
#ifndef LAMINA_THREADS_H
#define LAMINA_THREADS_H

#include "mpm.h"

#ifdef _OPENMP
#include <omp.h>
#define LM_THREAD_ID() omp_get_thread_num()
#else
#define LM_THREAD_ID() 0
#endif

/* Threads the step uses (1 without OpenMP). */
int lm_sim_threads(const lm_sim *sim);
/* Particle range [a, b) of thread t of nt. */
static inline void lm_thread_range(size_t n, int t, int nt, size_t *a, size_t *b)
{
    *a = n * (size_t)t / (size_t)nt;
    *b = n * (size_t)(t + 1) / (size_t)nt;
}
/* Makes room for the per-thread copies of up to LM_SCATTER_FIELDS nodal
 * fields; LM_ERR_MEMORY (message in sim->err) if it cannot. */
#define LM_SCATTER_FIELDS 3
/* Loops over nodes run on threads only above this many nodes: below it the
 * fork and join cost more than the loop (the dog-bone's grid has 289). */
#define LM_NODE_LOOP_MIN 4096
lm_status lm_threads_reserve(lm_sim *sim);
/* Thread t's copies of the nf fields `out` for scattering particles
 * [a, b): `out` itself for thread 0, private arrays for the others, zeroed
 * over the nodes those particles' stencils touch (2 x 2 or 3 x 3 by the
 * basis; particles are stored body by body
 * and seeded row by row, so a range touches a band of the grid, and large
 * grids cost no more than the particles' share). */
void lm_thread_fields(lm_sim *sim, int t, size_t a, size_t b, int nf, double *const *out,
                      double **mine);
/* out[f][i] += the other threads' copies over their bands, in thread order. */
void lm_threads_reduce(lm_sim *sim, int nt, int nf, double *const *out);

#endif
