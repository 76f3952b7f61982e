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
 * of a z-sorted order: 3D particles are not kept sorted.
 *
 * Only the span of nodes a thread's particles reached is added and
 * cleared (issue 34 item 6, perf34): the copies stay zero between
 * scatters (zeroed when allocated, and each node cleared by the addition
 * that takes it up), and after its scatter each thread takes the least
 * and greatest first node of its particles' stencils, so the addition
 * runs over that span only. Outside it a copy holds +0, and the old
 * whole-grid addition left the grid's value there as it was (a sum begun
 * at +0 is never -0, so x + 0 is x): the same bits. On the bench's block,
 * seeded z-major, thread 1's span is the upper half of the block, under a
 * third of the grid's nodes, where a memset and an addition over all of
 * them ran before. */
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

/* Room for (nt - 1) copies of nf fields, kept in sim between steps and
 * all zero between scatters: what a growth adds is zeroed here. */
static double *scratch(lm3_sim *sim, int nt, int nf)
{
    size_t need = (size_t)(nt - 1) * (size_t)nf * sim->grid.nn;
    if (need > sim->scratch_len) {
        double *s = realloc(sim->scratch, need * sizeof(double));
        if (!s) return NULL;
        memset(s + sim->scratch_len, 0, (need - sim->scratch_len) * sizeof(double));
        sim->scratch = s;
        sim->scratch_len = need;
    }
    return sim->scratch;
}

/* The nodes the stencils of particles q0 .. q1 - 1 reach, [*lo, *hi):
 * their first nodes' least and greatest, the last W - 1 nodes further on
 * in each direction. An empty range reaches nothing (lo = hi). */
static void reach(const lm3_sim *sim, size_t q0, size_t q1, long *lo, long *hi)
{
    const lm3_grid *g = &sim->grid;
    const int32_t *node = sim->p.node;
    if (q1 <= q0) {
        *lo = *hi = 0;
        return;
    }
    int32_t a = node[q0], b = node[q0];
    for (size_t q = q0 + 1; q < q1; q++) {
        a = node[q] < a ? node[q] : a;
        b = node[q] > b ? node[q] : b;
    }
    *lo = a;
    *hi = (long)b + (long)(g->W - 1) * (1 + g->s[0] + g->s[0] * g->s[1]) + 1;
    if (*hi > (long)g->nn) *hi = (long)g->nn;
}

/* The view of thread t's fields: the grid's own (t = 0) or copy t - 1. */
static lm3_grid view_of(const lm3_grid *g, double *copy, int t, int nf)
{
    lm3_grid v = *g;
    if (t == 0) return v;
    double *b = copy + (size_t)(t - 1) * (size_t)nf * g->nn;   /* zero (scratch) */
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
    long lo[LM_MAX_THREADS], hi[LM_MAX_THREADS];
#ifdef _OPENMP
#pragma omp parallel num_threads(nt)
    {
        /* the split follows the team the runtime gave (nt unless it was
         * short of threads); the sums follow the split */
        int t = omp_get_thread_num(), k = omp_get_num_threads();
#pragma omp single
        team = k;
        lm3_grid v = view_of(g, copy, t, nf);
        const size_t q0 = n * (size_t)t / (size_t)k, q1 = n * (size_t)(t + 1) / (size_t)k;
        fn(sim, &v, q0, q1);
        reach(sim, q0, q1, &lo[t], &hi[t]);
    }
#else
    team = 1;
    fn(sim, g, 0, n);
#endif
    if (team < 2) return 0;
    /* the union of the copies' spans, split among the threads */
    long from = (long)nn, to = 0;
    for (int t = 1; t < team; t++)
        if (lo[t] < hi[t]) {
            from = lo[t] < from ? lo[t] : from;
            to = hi[t] > to ? hi[t] : to;
        }
    if (from >= to) return 0;
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
    /* The copies in thread order, each over the span it reached (zero
     * elsewhere, and x + 0 is x), each node of a copy cleared as it is
     * taken up. Each thread takes a slice of the nodes and adds field by
     * field, copy by copy: two streams a loop, which the compiler
     * vectorises and the prefetchers follow (node by node, the fourteen
     * streams of p2g's seven fields were bound by the misses: perf34,
     * docs/3d.md "Threads and determinism"). At every node the sum is
     * dst + copy 1 + copy 2 ..., the old order. */
#ifdef _OPENMP
#pragma omp parallel num_threads(nt)
    {
        const long t0 = omp_get_thread_num(), k = omp_get_num_threads();
#else
    {
        const long t0 = 0, k = 1;
#endif
        const long s0 = from + (to - from) * t0 / k, s1 = from + (to - from) * (t0 + 1) / k;
        for (int f = 0; f < nf; f++)
            for (int t = 1; t < team; t++) {
                const long i0 = lo[t] > s0 ? lo[t] : s0, i1 = hi[t] < s1 ? hi[t] : s1;
                double *restrict d = dst[f];
                double *restrict c = copy + ((size_t)(t - 1) * nf + f) * nn;
                for (long i = i0; i < i1; i++) {
                    d[i] += c[i];
                    c[i] = 0;
                }
            }
    }
    return 0;
}
