/* threads.h - the step's loops over particles on sim->def.threads threads
 * (OpenMP when built with it; otherwise everything runs on one).
 *
 * Determinism (docs/design.md, "Engine"): a loop that writes only its own particle is the
 * same on any number of threads. A scatter to the grid gives each thread a
 * fixed, contiguous range of particles and, where its nodes meet another
 * thread's, its own copy of the nodal fields; the copies are added in
 * thread order. So the state depends on the thread count only, never on
 * timing, and one thread is the plain serial loop. */
#ifndef LAMINA_THREADS_H
#define LAMINA_THREADS_H

#include "mpm.h"

#ifdef _OPENMP
#include <omp.h>
#define LM_THREAD_ID() omp_get_thread_num()
#define LM_TEAM_SIZE() omp_get_num_threads()
#else
#define LM_THREAD_ID() 0
#define LM_TEAM_SIZE() 1
#endif

/* Threads the step's work is split for (1 without OpenMP): the state
 * depends on this number only. */
int lm_sim_threads(const lm_sim *sim);
/* OS threads its parallel loops run on now, 1 <= team <= threads: fewer
 * while other processes hold the cores (lm_pace_step). A split part is
 * then done by another OS thread of the team, so the state is the same
 * (one OS thread may do several of a scatter's parts, in order). */
int lm_sim_team(const lm_sim *sim);
/* Before each step: the team for it (issue 17 item 2). The whole team's
 * steps are timed in windows of LM_PACE_PROBE; while the process gets its
 * cores (processor time at least threads - 1/4 times the wall time: idle,
 * two threads get ~1.9 of 2) it stays. Otherwise (beside a busy process
 * ~1.4: the team waits at every barrier for its thread that shares a
 * core; or a step with long serial parts) LM_PACE_PROBE_ONE steps are
 * timed on one OS thread, and the faster (one thread only if 5 % faster)
 * runs the next LM_PACE_HOLD_STEPS steps. */
#define LM_PACE_PROBE 32
#define LM_PACE_PROBE_ONE 16
#define LM_PACE_HOLD_STEPS 256
enum { LM_PACE_FULL = 0, LM_PACE_ONE = 1, LM_PACE_HOLD = 2 };
void lm_pace_step(lm_sim *sim);
/* Holds the team at `team` threads (0: adapt again); for tests. */
void lm_sim_fix_team(lm_sim *sim, int team);
/* Particle range [a, b) of thread t of nt. */
static inline void lm_thread_range(size_t n, int t, int nt, size_t *a, size_t *b)
{
    *a = n * (size_t)t / (size_t)nt;
    *b = n * (size_t)(t + 1) / (size_t)nt;
}
/* Makes room for the per-thread copies of up to LM_SCATTER_FIELDS nodal
 * fields; LM_ERR_MEMORY (message in sim->err) if it cannot. */
#define LM_SCATTER_FIELDS 5
/* Loops over nodes run on threads only above this many nodes: below it the
 * fork and join cost more than the loop (the dog-bone's grid has 289). */
#define LM_NODE_LOOP_MIN 4096
/* Loops over particles likewise (issue 17 item 2): a waiting thread spins
 * about 50 us and then sleeps (app/wait_policy.c), and waking it costs
 * about 0.1 ms here, more than half a loop over fewer particles saves.
 * Below it the step runs on one OS thread; the scatters still split their
 * sums as sim->def.threads threads would, so the state is the same. */
#define LM_PARTICLE_LOOP_MIN 4096
lm_status lm_threads_reserve(lm_sim *sim);

/* The scatters write straight into the fields wherever no other thread
 * touches the same nodes, and into thread copies only where they meet
 * (issue 17 item 2: zeroing and adding whole bands of copies cost a tenth
 * of a two-thread step; particles are stored body by body and seeded row
 * by row, so neighbouring threads share a row or two of nodes). A node's
 * sums go to one place on each thread, in particle order, so the state is
 * bit-identical to copying whole bands, and one thread is the plain loop.
 *
 * In a parallel region, for each of the nt threads t of the split (one OS
 * thread may do several, in order) with particles [a, b): lm_thread_band;
 * then a barrier; then lm_thread_fields; a particle whose
 * stencil reaches a shared node (lm_thread_shared) writes its shared
 * nodes to the copies and the others to the fields; after the region,
 * lm_threads_reduce. */
typedef struct lm_thread_share {
    long lo, hi;   /* the nodes other threads also touch (lo > hi: none) */
    long ext;      /* a stencil's last node minus its first */
} lm_thread_share;
/* Records the nodes particles [a, b) touch (the band of thread t). */
void lm_thread_band(lm_sim *sim, int t, size_t a, size_t b);
/* Thread t's copies `mine` of nf scattered fields, zeroed over the nodes
 * its band shares with the others' (*sh; none for thread 0). */
void lm_thread_fields(lm_sim *sim, int t, int nt, int nf, double **mine, lm_thread_share *sh);
/* Does a stencil whose first node is `node` reach a shared node? */
static inline int lm_thread_shared(const lm_thread_share *sh, long node)
{
    return node + sh->ext >= sh->lo && node <= sh->hi;
}
/* out[f][i] += the other threads' copies where they have them, in thread
 * order. */
void lm_threads_reduce(lm_sim *sim, int nt, int nf, double *const *out);

#endif
