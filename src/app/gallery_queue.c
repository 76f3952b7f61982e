/* gallery_queue.c - several figures' runs at once, the longest first.
 *
 * The gallery's time is the sum of its figures' runs; on a machine with
 * more than one core, running them one after another leaves the others
 * idle whenever a figure is single-threaded (most are) and during the
 * serial parts of the two-threaded heavy ones. So `lamina gallery` keeps
 * up to --jobs runs going (default: the cores online), each a `lamina run`
 * subprocess as before (gallery_run.c). Order: longest processing time
 * first (Graham 1969: within 4/3 of the best schedule on identical
 * machines), by what each figure cost last time (meta.json); a figure
 * never run goes first, as nothing says it is short.
 *
 * A run's numbers do not depend on what runs beside it: its state depends
 * on its script's fixed thread count only (docs/design.md, "Engine"), and
 * a two-threaded run beside a busy core drops to one OS thread for a
 * while without changing a bit (src/mpm/threads.h, lm_pace_step). Each
 * figure writes only into its own folder (its --out-root); the index is
 * written after all have ended. */
#include "gallery.h"

#include <stdlib.h>
#include <time.h>
#include <unistd.h>

double g_last_cost(const char *meta_path)
{
    lu_json *m = gj_read(meta_path, NULL, 0);
    if (!m)
        return -1;
    double c = lu_json_number(m, "cpu_seconds", -1);
    if (!(c >= 0))
        c = lu_json_number(m, "seconds", -1);
    lu_json_free(m);
    return c >= 0 ? c : -1;
}

int g_default_jobs(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n >= 1 ? (n > 64 ? 64 : (int)n) : 1;
}

/* index order: the costliest first, unknown (< 0) before any, then as given */
static const g_job *sort_base;
static int by_cost(const void *a, const void *b)
{
    size_t i = *(const size_t *)a, j = *(const size_t *)b;
    double ci = sort_base[i].cost, cj = sort_base[j].cost;
    int ui = ci < 0, uj = cj < 0;
    if (ui != uj)
        return uj - ui;
    if (!ui && ci != cj)
        return ci > cj ? -1 : 1;
    return i < j ? -1 : i > j;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int g_queue_run(g_job *jobs, size_t n, int max_jobs, const g_queue_ops *ops, void *ctx,
                g_queue_stats *st)
{
    double t0 = now();
    size_t *order = g_alloc((n ? n : 1) * sizeof *order);
    size_t *running = g_alloc((size_t)(max_jobs > 0 ? max_jobs : 1) * sizeof *running);
    for (size_t i = 0; i < n; i++)
        order[i] = i;
    sort_base = jobs;
    qsort(order, n, sizeof *order, by_cost);
    size_t next = 0, nrun = 0;
    int broken = 0;
    while ((next < n && !broken) || nrun > 0) {
        /* fill the free slots */
        while (!broken && next < n && nrun < (size_t)(max_jobs > 0 ? max_jobs : 1)) {
            g_job *j = &jobs[order[next++]];
            int rc = ops->start(ctx, j);
            if (rc == 0)
                running[nrun++] = (size_t)(j - jobs);
            else if (rc > 0) {
                st->ran++;
                st->failed++;
            } else
                broken = 1;
        }
        /* reap what ended; in slot order, so one pass is deterministic */
        int ended = 0;
        for (size_t k = 0; k < nrun;) {
            g_job *j = &jobs[running[k]];
            g_run_result r = { 0 };
            char err[1024] = "";
            int p = g_run_poll(&j->child, &r, err, sizeof err);
            if (p == 0) {
                k++;
                continue;
            }
            int rc = ops->finish(ctx, j, p, &r, err);
            st->ran += rc >= 0;
            st->failed += rc == 1;
            st->cpu += p > 0 ? r.cpu_seconds : 0;
            broken |= rc < 0;
            running[k] = running[--nrun];
            ended = 1;
        }
        if (!ended && nrun > 0)
            g_run_nap();
    }
    st->wall += now() - t0;
    free(running);
    free(order);
    return broken ? -1 : 0;
}
