/* threads.c - per-thread copies of the nodal fields for the scatters of the
 * step, where threads meet (threads.h says why the results stay
 * deterministic). */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "step.h"
#include "threads.h"
#include "util.h"

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

int lm_sim_team(const lm_sim *sim)
{
    int nt = lm_sim_threads(sim);
    if (sim->work->pace.fixed > 0) return sim->work->pace.fixed < nt ? sim->work->pace.fixed : nt;
    return sim->work->pace.team >= 1 && sim->work->pace.team < nt ? sim->work->pace.team : nt;
}

void lm_sim_fix_team(lm_sim *sim, int team)
{
    sim->work->pace.fixed = team > 0 ? team : 0;
}

static double clock_of(clockid_t id)
{
    struct timespec ts;
    if (clock_gettime(id, &ts) != 0) return 0;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* A window of `steps` steps on `team` OS threads, timed. */
static void window(lm_sim *sim, int team, int phase, int steps)
{
    sim->work->pace.team = team;
    sim->work->pace.phase = phase;
    sim->work->pace.left = steps;
    sim->work->pace.wall0 = clock_of(CLOCK_MONOTONIC);
    sim->work->pace.cpu0 = clock_of(CLOCK_PROCESS_CPUTIME_ID);
}

void lm_pace_step(lm_sim *sim)
{
    int nt = lm_sim_threads(sim);
    if (nt == 1 || sim->work->pace.fixed > 0 || sim->p.n < LM_PARTICLE_LOOP_MIN) return;
    if (sim->work->pace.team == 0) {
        window(sim, nt, LM_PACE_FULL, LM_PACE_PROBE);
        return;
    }
    if (--sim->work->pace.left > 0) return;
    double wall = clock_of(CLOCK_MONOTONIC) - sim->work->pace.wall0;
    double cpu = clock_of(CLOCK_PROCESS_CPUTIME_ID) - sim->work->pace.cpu0;
    switch (sim->work->pace.phase) {
    case LM_PACE_FULL:
        /* the team got its cores (idle: two threads ~1.9 of 2): go on;
         * else (beside a busy process ~1.4, or a step with long serial
         * parts) time one OS thread too */
        if (!(cpu < (nt - 0.25) * wall)) {
            window(sim, nt, LM_PACE_FULL, LM_PACE_PROBE);
        } else {
            sim->work->pace.t_full = wall / LM_PACE_PROBE;
            window(sim, 1, LM_PACE_ONE, LM_PACE_PROBE_ONE);
        }
        break;
    case LM_PACE_ONE:   /* keep the faster, one thread only if clearly so */
        sim->work->pace.team = wall / LM_PACE_PROBE_ONE < 0.95 * sim->work->pace.t_full ? 1 : nt;
        sim->work->pace.phase = LM_PACE_HOLD;
        sim->work->pace.left = LM_PACE_HOLD_STEPS;
        break;
    default:            /* the hold is over: time the whole team again */
        window(sim, nt, LM_PACE_FULL, LM_PACE_PROBE);
        break;
    }
}

lm_status lm_threads_reserve(lm_sim *sim)
{
    int nt = lm_sim_threads(sim);
    size_t need = (size_t)(nt - 1) * LM_SCATTER_FIELDS * lm_grid_nodes(&sim->grid);
    if (need <= sim->grid.tcap) return LM_OK;
    /* counted against the process's memory cap (lu_budget.c): with 8
     * threads the copies are larger than the grid itself */
    size_t more = (need - sim->grid.tcap) * sizeof(double);
    double *b = NULL;
    if (lu_budget_charge(LU_MEM_ENGINE, more) == 0) {
        b = realloc(sim->grid.tbuf, need * sizeof *b);
        if (!b) lu_budget_release(LU_MEM_ENGINE, more);
    }
    if (!b) {
        snprintf(sim->err, sizeof sim->err,
                 "cannot make the grid copies of %d threads: %s", nt, lu_budget_oom());
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

/* (the upper-right node of a stencil sw wide is ext past its first) */
static long stencil_ext(const lm_grid *g)
{
    return (long)(g->sw - 1) * g->sx + (g->sw - 1);
}

void lm_thread_band(lm_sim *sim, int t, size_t a, size_t b)
{
    lm_grid *g = &sim->grid;
    long lo = LONG_MAX, hi = LONG_MIN;
    for (size_t q = a; q < b; q++) {
        long i = sim->p.node[q];
        if (i < lo) lo = i;
        if (i > hi) hi = i;
    }
    g->blo[t] = lo;
    g->bhi[t] = hi == LONG_MIN ? hi : hi + stencil_ext(g);
}

void lm_thread_fields(lm_sim *sim, int t, int nt, int nf, double **mine, lm_thread_share *sh)
{
    lm_grid *g = &sim->grid;
    /* the hull of where my band meets the others' (none for thread 0) */
    sh->lo = LONG_MAX;
    sh->hi = LONG_MIN;
    sh->ext = stencil_ext(g);
    for (int s = 0; s < nt && t > 0; s++) {
        if (s == t) continue;
        long lo = g->blo[s] > g->blo[t] ? g->blo[s] : g->blo[t];
        long hi = g->bhi[s] < g->bhi[t] ? g->bhi[s] : g->bhi[t];
        if (lo > hi) continue;
        if (lo < sh->lo) sh->lo = lo;
        if (hi > sh->hi) sh->hi = hi;
    }
    g->tlo[t] = sh->lo;
    g->thi[t] = sh->hi;
    for (int f = 0; f < nf && t > 0; f++) {
        mine[f] = copy_of(g, t, f);
        if (sh->hi >= sh->lo)
            memset(mine[f] + sh->lo, 0, (size_t)(sh->hi - sh->lo + 1) * sizeof(double));
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
    if (lo > hi) return;   /* no thread met another */
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) if (hi - lo > LM_NODE_LOOP_MIN)
    for (long i = lo; i <= hi; i++)
        for (int t = 1; t < nt; t++)
            if (i >= g->tlo[t] && i <= g->thi[t])
                for (int f = 0; f < nf; f++)
                    out[f][i] += copy_of(g, t, f)[i];
}
