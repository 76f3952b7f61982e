/* sim3_threads.c - the 3D step's scatters on threads, deterministically
 * (sim3_threads.h; docs/3d.md "Threads and determinism").
 *
 * The gathers (g2p, the strain rate, the stress) and the passes over the
 * nodes write only their own particle or node and run as plain parallel
 * loops in sim3_step.c. A scatter adds a particle's share into up to 27
 * nodes that other particles also reach, so each thread scatters its own
 * contiguous range of particles into its own copy of the fields and the
 * copies are added afterwards in thread order, as 2D's threads.c does for
 * the nodes threads share. Whole-grid copies rather than the shared band
 * of a z-sorted order: 3D particles are not kept sorted, and the copies
 * cost 8 bytes a node a field a thread to clear and add (the bench's
 * block: 32 bytes a particle-step for p2g's seven fields on two threads,
 * against about 500 the step moves). */
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "sim3_threads.h"

int lm3_threads(const lm3_sim *sim)
{
#ifdef _OPENMP
    int t = sim->def.threads > 1 ? sim->def.threads : 1;
    return sim->p.n >= LM3_THREAD_MIN ? t : 1;
#else
    (void)sim;
    return 1;
#endif
}

/* Room for (nt - 1) copies of nf fields, kept in sim between steps. */
static double *scratch(lm3_sim *sim, int nt, int nf)
{
    size_t need = (size_t)(nt - 1) * (size_t)nf * sim->grid.nn;
    if (need > sim->scratch_len) {
        double *s = realloc(sim->scratch, need * sizeof(double));
        if (!s) return NULL;
        sim->scratch = s;
        sim->scratch_len = need;
    }
    return sim->scratch;
}

/* The view of thread t's fields: the grid's own (t = 0) or copy t - 1. */
static lm3_grid view_of(const lm3_grid *g, double *copy, int t, int nf)
{
    lm3_grid v = *g;
    if (t == 0) return v;
    double *b = copy + (size_t)(t - 1) * (size_t)nf * g->nn;
    memset(b, 0, (size_t)nf * g->nn * sizeof(double));
    if (nf == 7) {
        v.m = b;
        for (int a = 0; a < 3; a++) {
            v.p[a] = b + (size_t)(1 + a) * g->nn;
            v.f[a] = b + (size_t)(4 + a) * g->nn;
        }
    } else {
        for (int a = 0; a < 3; a++) v.v[a] = b + (size_t)a * g->nn;
    }
    return v;
}

int lm3_scatter_threads(lm3_sim *sim, int nt, int nf, lm3_scatter_fn *fn)
{
    double *copy = scratch(sim, nt, nf);
    if (!copy) return -1;
    lm3_grid *g = &sim->grid;
    const size_t n = sim->p.n, nn = g->nn;
    int team = nt;
#ifdef _OPENMP
#pragma omp parallel num_threads(nt)
    {
        /* the split follows the team the runtime gave (nt unless it was
         * short of threads); the sums follow the split */
        int t = omp_get_thread_num(), k = omp_get_num_threads();
#pragma omp single
        team = k;
        lm3_grid v = view_of(g, copy, t, nf);
        fn(sim, &v, n * (size_t)t / (size_t)k, n * (size_t)(t + 1) / (size_t)k);
    }
#else
    team = 1;
    fn(sim, g, 0, n);
#endif
    if (team < 2) return 0;
    double *dst[7];
    if (nf == 7) {
        dst[0] = g->m;
        for (int a = 0; a < 3; a++) {
            dst[1 + a] = g->p[a];
            dst[4 + a] = g->f[a];
        }
    } else {
        for (int a = 0; a < 3; a++) dst[a] = g->v[a];
    }
    /* node by node, the copies in thread order */
    const long nl = (long)nn;
#ifdef _OPENMP
#pragma omp parallel for num_threads(nt) schedule(static)
#endif
    for (long i = 0; i < nl; i++)
        for (int f = 0; f < nf; f++) {
            double s = dst[f][i];
            for (int t = 1; t < team; t++) s += copy[((size_t)(t - 1) * nf + f) * nn + i];
            dst[f][i] = s;
        }
    return 0;
}
