/* normals_work.c - the normals engine's workspace (normals_work.h): sized
 * before the element loop, so that the loop itself never allocates. */
#include <stdlib.h>
#include <string.h>

#include "normals_work.h"
#include "util.h"

/* *p grown to hold n items of size sz (kept as is when it does). */
static int grow(void **p, size_t n, size_t sz)
{
    void *q = realloc(*p, (n ? n : 1) * sz);
    if (!q)
        return -1;
    *p = q;
    return 0;
}

lm_nerr lm_nwork_reserve(lm_nwork *w, size_t n)
{
    if (n <= w->cap && w->fit.S)
        return LM_NERR_NONE;
    /* a fit's rows: its points, the phi = 0 and phi = 2 points and the
     * curvature rows (normals_fit.c); an element holds at most all n */
    size_t rows = n + 2 + LM_NSMOOTH_MAXROWS;
    if (grow((void **)&w->idx, n, sizeof *w->idx) ||
        grow((void **)&w->sel, n, sizeof *w->sel) ||
        grow((void **)&w->sites, n, sizeof *w->sites) ||
        grow((void **)&w->sites_tmp, n, sizeof *w->sites_tmp) ||
        grow((void **)&w->nrm, 3 * n, sizeof *w->nrm) ||
        grow((void **)&w->flags, n, sizeof *w->flags) ||
        grow((void **)&w->dist, n, sizeof *w->dist) ||
        grow((void **)&w->from, n, sizeof *w->from) ||
        grow((void **)&w->done, n, sizeof *w->done) ||
        grow((void **)&w->fit.S, rows * LM_NMAX, sizeof *w->fit.S) ||
        grow((void **)&w->fit.rhs, rows, sizeof *w->fit.rhs) ||
        grow((void **)&w->fit.cols, LM_QR_WORK(rows, LM_NMAX), sizeof *w->fit.cols))
        return LM_NERR_MEMORY;
    if (!w->fit.smooth) {
        /* empty: smooth[1] = 0 says no aspect is kept yet */
        w->fit.smooth = calloc(LM_NSMOOTH_CACHE, sizeof *w->fit.smooth);
        if (!w->fit.smooth)
            return LM_NERR_MEMORY;
    }
    w->cap = n;
    w->fit.rows = rows;
    return LM_NERR_NONE;
}

void lm_nwork_free(lm_nwork *w)
{
    if (!w)
        return;
    LU_FREE_ALL(w->idx, w->sel, w->sites, w->sites_tmp, w->nrm, w->flags, w->dist, w->from,
                w->done, w->fit.S, w->fit.rhs, w->fit.cols, w->fit.smooth);
    lm_nbins_free(&w->bins);
    memset(w, 0, sizeof *w);
}

lm_nwork *lm_nwork_new(int cmp)
{
    lm_nwork *w = calloc(1, sizeof(lm_nwork));
    if (w)
        w->cmp = cmp != 0;
    return w;
}

void lm_nwork_delete(lm_nwork *w)
{
    lm_nwork_free(w);
    free(w);
}
