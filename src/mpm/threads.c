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
    return sim->def.threads > 1 ? sim->def.threads : 1;
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

void lm_thread_fields(lm_sim *sim, int t, int nf, double *const *out, double **mine)
{
    size_t nn = lm_grid_nodes(&sim->grid);
    for (int f = 0; f < nf; f++) {
        if (t == 0) {
            mine[f] = out[f];
        } else {
            mine[f] = copy_of(&sim->grid, t, f);
            memset(mine[f], 0, nn * sizeof(double));
        }
    }
}

void lm_threads_reduce(lm_sim *sim, int nt, int nf, double *const *out)
{
    if (nt <= 1) return;
    lm_grid *g = &sim->grid;
    long nn = (long)lm_grid_nodes(g);
#pragma omp parallel for num_threads(nt) schedule(static)
    for (long i = 0; i < nn; i++)
        for (int t = 1; t < nt; t++)
            for (int f = 0; f < nf; f++)
                out[f][i] += copy_of(g, t, f)[i];
}
