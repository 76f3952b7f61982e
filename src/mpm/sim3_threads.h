/* sim3_threads.h - the 3D step on threads (sim3_threads.c), private to
 * the engine. */
#ifndef LAMINA_SIM3_THREADS_H
#define LAMINA_SIM3_THREADS_H

#include "mpm3.h"

/* Fewer particles than this run on one thread (as 2D's
 * LM_PARTICLE_LOOP_MIN): a team's start costs more than they do. */
#define LM3_THREAD_MIN 4096

/* The threads a step of sim uses: lm3_def.threads (0 or 1: one), one
 * when lamina is built without OpenMP or the particles are few. */
int lm3_threads(const lm3_sim *sim);

/* A scatter of nf nodal fields (dst[0..nf)) over the particles on `nt`
 * threads: thread t takes the t-th of nt equal contiguous ranges of
 * particles and scatters them with fn(sim, view, q0, q1) into its own
 * view of the grid - thread 0 into dst itself, the others into zeroed
 * private copies of the fields (lm3_sim.scratch) - and the copies are then
 * added into dst node by node in thread order. So the sums at a node are
 * taken in an order fixed by nt and the particles' order: the same thread
 * count gives the same bits (docs/3d.md "Threads and determinism").
 * view->m, p[], f[] or v[] point where the fields go, in the order
 * m, p0, p1, p2, f0, f1, f2 (nf = 7) or v0, v1, v2 (nf = 3).
 * 0, or -1 when the copies could not be allocated (nothing was done: the
 * caller runs the scatter on one thread). */
typedef void lm3_scatter_fn(lm3_sim *sim, const lm3_grid *view, size_t q0, size_t q1);
int lm3_scatter_threads(lm3_sim *sim, int nt, int nf, lm3_scatter_fn *fn);

#endif
