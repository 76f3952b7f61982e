/* threads.c - per-thread copies of the nodal fields for the scatters of the
 * step (threads.h says why the results stay deterministic). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "step.h"
#include "threads.h"

int lm_sim_threads(const lm_sim *sim)
{
#ifdef _OPENMP
    int t = sim->def.threads > 1 ? sim->def.threads : 1;
    return t < LM_MAX_THREADS ? t : LM_MAX_THREADS;
#else
    (void)sim;
    return 1;
#endif
}

lm_status lm_threads_reserve(lm_sim *sim)
{
    int nt = lm_sim_threads(sim);
    size_t need = (size_t)(nt - 1) * LM_SCATTER_FIELDS * lm_grid_nodes(&sim->grid);
    if (need <= sim->grid.tcap) return LM_OK;
    double *b = realloc(sim->grid.tbuf, need * sizeof *b);
    if (!b) {
        snprintf(sim->err, sizeof sim->err,
                 "out of memory for the grid copies of %d threads", nt);
        return LM_ERR_MEMORY;
    }
    sim->grid.tbuf = b;
    sim->grid.tcap = need;
    return LM_OK;
}

static double *copy_of(lm_grid *g, int t, int f)
{
    size_t nn = lm_grid_nodes(g);
    return g->tbuf + ((size_t)(t - 1) * LM_SCATTER_FIELDS + (size_t)f) * nn;
}

void lm_thread_fields(lm_sim *sim, int t, size_t a, size_t b, int nf, double *const *out,
                      double **mine)
{
    lm_grid *g = &sim->grid;
    if (t == 0) {
        for (int f = 0; f < nf; f++) mine[f] = out[f];
        return;
    }
    long lo = (long)lm_grid_nodes(g), hi = -1;
    for (size_t q = a; q < b; q++) {
        long i = sim->p.node[q];
        if (i < lo) lo = i;
        if (i > hi) hi = i;
    }
    /* the upper-right node of the last particle's stencil (sw wide) */
    hi += (long)(g->sw - 1) * g->sx + (g->sw - 1);
    g->tlo[t] = lo;
    g->thi[t] = hi;
    for (int f = 0; f < nf; f++) {
        mine[f] = copy_of(g, t, f);
        if (hi >= lo) memset(mine[f] + lo, 0, (size_t)(hi - lo + 1) * sizeof(double));
    }
}

void lm_threads_reduce(lm_sim *sim, int nt, int nf, double *const *out)
{
    if (nt <= 1) return;
    lm_grid *g = &sim->grid;
    long lo = g->tlo[1], hi = g->thi[1];
    for (int t = 2; t < nt; t++) {
        if (g->tlo[t] < lo) lo = g->tlo[t];
        if (g->thi[t] > hi) hi = g->thi[t];
    }
#pragma omp parallel for num_threads(nt) schedule(static)
    for (long i = lo; i <= hi; i++)
        for (int t = 1; t < nt; t++)
            if (i >= g->tlo[t] && i <= g->thi[t])
                for (int f = 0; f < nf; f++)
                    out[f][i] += copy_of(g, t, f)[i];
}
