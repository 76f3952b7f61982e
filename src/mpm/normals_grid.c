/* normals_grid.c - the isosurface construction element by element over a
 * grid ([N] §3: "Equation 12 can also be solved element-by-element since
 * only a local description of the surface is necessary").
 *
 * Steps:
 *  1. bin the points into cells (a point on the far edge of the grid
 *     belongs to the last cell, as everywhere in lamina);
 *  2. for each occupied cell, in cell order, choose the basis: the one
 *     asked for, or the hybrid rule of [N] §8 - quadratic with at least
 *     quad_min distinct points, linear with at least lin_min;
 *  3. a cell short of points joins neighbouring cells into a 2x2 block
 *     (2x2x2 in 3D), then 4x4, ... until the block has lin_min points
 *     ([N] §4: "a group of four elements can be joined together ... If not,
 *     the process can be repeated"); the block solved is the one holding
 *     the most points, ties broken by nearness of its centre to the cell's
 *     points. Only the short cell's points take normals from that block
 *     ([T] §7.7: "Only the normal for the single membrane point was
 *     calculated using the expanded cell");
 *  4. fit (normals_fit.c) with a random point from a stream keyed by the
 *     cell, so the result does not depend on visiting order;
 *  5. normals at the cell's points, then one orientation pass.
 *
 * With element = LM_NELEM_CENTRED step 2 on is normals_centred.c instead
 * (one-cell elements centred near each point; what simulations use).
 *
 * The 7-point case of the hybrid rule: 7 points + 1 random point are 8 rows
 * for 9 quadratic unknowns (docs/physics.md §3). lamina keeps the paper's
 * threshold and solves that system by the minimum-norm QR solution (the
 * QR solver's complete orthogonal decomposition); with phi2 set, the
 * phi = 2 point makes it square. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "normals.h"
#include "normals_bins.h"
#include "util.h"
#include "normals_work.h"

void lm_nopts_default(lm_nopts *o)
{
    memset(o, 0, sizeof *o);
    o->basis = LM_NB_HYBRID;
    o->solver = LM_NS_QR;
    o->seed = 1;
    o->merge = 1;
    o->orient = LM_NORIENT_NONE;
}

void lm_nopts_centred(lm_nopts *o)
{
    lm_nopts_default(o);
    o->element = LM_NELEM_CENTRED;
    o->basis = LM_NB_QUADRATIC;
    o->smooth = LM_NSMOOTH;
    o->clearance = LM_NCLEARANCE;
}

void lm_nreport_free(lm_nreport *r)
{
    if (!r)
        return;
    free(r->elem);
    free(r->cell_elem);
    memset(r, 0, sizeof *r);
}

long lm_ngrid_cell(const lm_ngrid *g, const double x[3], int c[3])
{
    long id = 0, stride = 1;
    c[0] = c[1] = c[2] = 0;
    for (int a = 0; a < g->dim; a++) {
        double f = (x[a] - g->x0[a]) / g->h[a];
        double t = 1e-9 * g->n[a];
        if (!(f >= -t && f <= g->n[a] + t))
            return -1;
        int i = (int)f;
        i -= f < i;                 /* floor(f): f is within int's range */
        if (i >= g->n[a])
            i = g->n[a] - 1;
        if (i < 0)
            i = 0;
        c[a] = i;
        id += i * stride;
        stride *= g->n[a];
    }
    return id;
}

/* ---- step 1: binning (normals_bins.h) ------------------------------------ */

void lm_nbins_free(lm_nbins *b)
{
    LU_FREE_ALL(b->start, b->order, b->cell, b->sum, b->fill);
    memset(b, 0, sizeof *b);
}

/* The bins' arrays grow by doubling from this many items (lu_reserve). */
#define BINS_FIRST 64

long lm_nbins_cell_id(const lm_ngrid *g, const int c[3])
{
    return c[0] + (long)g->n[0] * (c[1] + (long)g->n[1] * (g->dim == 3 ? c[2] : 0));
}

/* The summed-count table has (n0+1)(n1+1)(n2+1) entries: sum[i][j][k] =
 * points in cells [0,i) x [0,j) x [0,k); any block count is then O(1). */
static long sum_at(const lm_ngrid *g, const long *sum, int i, int j, int k)
{
    return sum[i + (long)(g->n[0] + 1) * (j + (long)(g->n[1] + 1) * k)];
}

static long block_count(const lm_ngrid *g, const long *sum, const int lo[3],
                        const int sz[3])
{
    int a0 = lo[0], a1 = lo[0] + sz[0], b0 = lo[1], b1 = lo[1] + sz[1];
    if (g->dim == 2)
        return sum_at(g, sum, a1, b1, 1) - sum_at(g, sum, a0, b1, 1) -
               sum_at(g, sum, a1, b0, 1) + sum_at(g, sum, a0, b0, 1);
    int c0 = lo[2], c1 = lo[2] + sz[2];
    return sum_at(g, sum, a1, b1, c1) - sum_at(g, sum, a0, b1, c1) -
           sum_at(g, sum, a1, b0, c1) - sum_at(g, sum, a1, b1, c0) +
           sum_at(g, sum, a0, b0, c1) + sum_at(g, sum, a0, b1, c0) +
           sum_at(g, sum, a1, b0, c0) - sum_at(g, sum, a0, b0, c0);
}

lm_nerr lm_nbins_make(const lm_ngrid *g, size_t n, const double *const x[3],
                      int sums, lm_nbins *b, char *err, size_t errlen)
{
    int nz = g->dim == 3 ? g->n[2] : 1;
    b->ncells = (long)g->n[0] * g->n[1] * nz;
    size_t nsum = (size_t)(g->n[0] + 1) * (size_t)(g->n[1] + 1) * (size_t)(nz + 1);
    /* start and fill share one capacity, order and cell another: each pair
     * grows from the same capacity to the same size */
    size_t ncap = b->cap_cells, pcap = b->cap_points, np = n ? n : 1;
    if (lu_reserve(&b->start, &ncap, (size_t)b->ncells + 1, sizeof *b->start, BINS_FIRST) ||
        lu_reserve(&b->fill, &b->cap_cells, (size_t)b->ncells + 1, sizeof *b->fill, BINS_FIRST) ||
        lu_reserve(&b->order, &pcap, np, sizeof *b->order, BINS_FIRST) ||
        lu_reserve(&b->cell, &b->cap_points, np, sizeof *b->cell, BINS_FIRST) ||
        lu_reserve(&b->sum, &b->cap_sum, nsum, sizeof *b->sum, BINS_FIRST)) {
        snprintf(err, errlen, "out of memory binning %zu points", n);
        return LM_NERR_MEMORY;
    }
    memset(b->start, 0, sizeof *b->start * ((size_t)b->ncells + 1));
    if (sums)
        memset(b->sum, 0, sizeof *b->sum * nsum);
    for (size_t i = 0; i < n; i++) {
        double p[3] = {x[0][i], x[1][i], g->dim == 3 ? x[2][i] : 0.0};
        int c[3];
        for (int a = 0; a < g->dim; a++)
            if (!isfinite(p[a])) {
                snprintf(err, errlen, "point %zu is not finite", i + 1);
                return LM_NERR_NOT_FINITE;
            }
        long id = lm_ngrid_cell(g, p, c);
        if (id < 0) {
            if (g->dim == 3)
                snprintf(err, errlen, "point %zu (%g, %g, %g) lies outside the grid",
                         i + 1, p[0], p[1], p[2]);
            else
                snprintf(err, errlen, "point %zu (%g, %g) lies outside the grid",
                         i + 1, p[0], p[1]);
            return LM_NERR_OUTSIDE;
        }
        b->cell[i] = id;
        b->start[id + 1]++;
        int k = g->dim == 3 ? c[2] : 0;
        if (sums)
            b->sum[(c[0] + 1) + (long)(g->n[0] + 1) * ((c[1] + 1) + (long)(g->n[1] + 1) * (k + 1))]++;
    }
    for (long c = 0; c < b->ncells; c++)
        b->start[c + 1] += b->start[c];
    size_t *fill = b->fill;
    memcpy(fill, b->start, sizeof *fill * ((size_t)b->ncells + 1));
    for (size_t i = 0; i < n; i++)
        b->order[fill[b->cell[i]]++] = i;
    if (!sums)
        return LM_NERR_NONE;
    /* prefix sums along each axis turn counts into summed counts */
    int N0 = g->n[0] + 1, N1 = g->n[1] + 1, N2 = nz + 1;
    for (int k = 0; k < N2; k++)
        for (int j = 0; j < N1; j++)
            for (int i = 0; i < N0; i++) {
                long at = i + (long)N0 * (j + (long)N1 * k);
                if (i > 0) b->sum[at] += b->sum[at - 1];
            }
    for (int k = 0; k < N2; k++)
        for (int j = 1; j < N1; j++)
            for (int i = 0; i < N0; i++) {
                long at = i + (long)N0 * (j + (long)N1 * k);
                b->sum[at] += b->sum[at - N0];
            }
    if (g->dim == 3)
        for (int k = 1; k < N2; k++)
            for (long at = (long)N0 * N1 * k; at < (long)N0 * N1 * (k + 1); at++)
                b->sum[at] += b->sum[at - (long)N0 * N1];
    return LM_NERR_NONE;
}

/* ---- step 3: merging --------------------------------------------------------- */

/* Points of the block lo..lo+sz into idx (cell order); returns the count. */
size_t lm_nbins_gather(const lm_ngrid *g, const lm_nbins *b, const int lo[3],
                       const int sz[3], size_t *idx)
{
    size_t k = 0;
    int nz = g->dim == 3 ? sz[2] : 1;
    for (int dk = 0; dk < nz; dk++)
        for (int dj = 0; dj < sz[1]; dj++)
            for (int di = 0; di < sz[0]; di++) {
                int c[3] = {lo[0] + di, lo[1] + dj, g->dim == 3 ? lo[2] + dk : 0};
                long id = lm_nbins_cell_id(g, c);
                for (size_t q = b->start[id]; q < b->start[id + 1]; q++)
                    idx[k++] = b->order[q];
            }
    return k;
}

/* Among the blocks of B cells per axis holding cell c, the one with the
 * most points; ties: the block centre nearest the centroid of the cell's
 * points (then the first found). */
static void best_block(const lm_ngrid *g, const lm_nbins *b, const int c[3], int B,
                       const double centroid[3], int lo[3], int sz[3])
{
    int first[3] = {0, 0, 0}, last[3] = {0, 0, 0};
    for (int a = 0; a < 3; a++) {
        if (a >= g->dim) {
            sz[a] = 1;
            lo[a] = first[a] = last[a] = 0;
            continue;
        }
        sz[a] = B < g->n[a] ? B : g->n[a];
        first[a] = c[a] - sz[a] + 1 > 0 ? c[a] - sz[a] + 1 : 0;
        last[a] = c[a] < g->n[a] - sz[a] ? c[a] : g->n[a] - sz[a];
    }
    long best = -1;
    double bestd = 0;
    int t[3];
    for (t[2] = first[2]; t[2] <= last[2]; t[2]++)
        for (t[1] = first[1]; t[1] <= last[1]; t[1]++)
            for (t[0] = first[0]; t[0] <= last[0]; t[0]++) {
                long cnt = block_count(g, b->sum, t, sz);
                double d = 0;
                for (int a = 0; a < g->dim; a++) {
                    double mid = g->x0[a] + (t[a] + 0.5 * sz[a]) * g->h[a];
                    d += (mid - centroid[a]) * (mid - centroid[a]);
                }
                if (cnt > best || (cnt == best && d < bestd)) {
                    best = cnt;
                    bestd = d;
                    memcpy(lo, t, sizeof t);
                }
            }
}

static void block_box(const lm_ngrid *g, const int lo[3], const int sz[3],
                      lm_nbox *box)
{
    box->dim = g->dim;
    for (int a = 0; a < 3; a++) {
        box->lo[a] = a < g->dim ? g->x0[a] + lo[a] * g->h[a] : 0.0;
        box->hi[a] = a < g->dim ? g->x0[a] + (lo[a] + sz[a]) * g->h[a] : 0.0;
    }
}

/* ---- the whole grid -------------------------------------------------------- */

int lm_nbins_default(const lm_ngrid *g, int v, int d2, int d3)
{
    return v > 0 ? v : g->dim == 3 ? d3 : d2;
}

static lm_nerr check_grid(const lm_ngrid *g, const lm_nopts *o, char *err,
                          size_t errlen)
{
    if (!g || (g->dim != 2 && g->dim != 3)) {
        snprintf(err, errlen, "the grid must be 2D or 3D");
        return LM_NERR_INPUT;
    }
    for (int a = 0; a < g->dim; a++)
        if (g->n[a] < 1 || !(g->h[a] > 0) || !isfinite(g->h[a]) || !isfinite(g->x0[a])) {
            snprintf(err, errlen, "the grid needs at least one cell of finite size "
                     "> 0 per axis (axis %d: %d cells of %g)", a, g->n[a], g->h[a]);
            return LM_NERR_INPUT;
        }
    if (o->basis != LM_NB_LINEAR && o->basis != LM_NB_QUADRATIC &&
        o->basis != LM_NB_HYBRID) {
        snprintf(err, errlen, "unknown basis %d", (int)o->basis);
        return LM_NERR_INPUT;
    }
    if (o->element != LM_NELEM_CELL && o->element != LM_NELEM_CENTRED) {
        snprintf(err, errlen, "unknown element choice %d", (int)o->element);
        return LM_NERR_INPUT;
    }
    if (!(o->smooth >= 0) || !isfinite(o->smooth) || !(o->clearance >= 0) ||
        !(o->clearance < 0.5)) {
        snprintf(err, errlen, "smooth must be finite and >= 0 (got %g), clearance in "
                 "[0, 0.5) of an element (got %g)", o->smooth, o->clearance);
        return LM_NERR_INPUT;
    }
    return LM_NERR_NONE;
}

/* Steps 2-4 for one occupied cell; the chosen element goes to *el. */
static lm_nerr solve_cell(const lm_ngrid *g, const lm_nbins *b, const double *const x[3],
                          const lm_nopts *o, const int c[3], size_t *idx,
                          lm_nfit_scratch *sc, int lean, lm_nelem *el,
                          char *err, size_t errlen)
{
    long id = lm_nbins_cell_id(g, c);
    size_t k0 = b->start[id], k1 = b->start[id + 1], k = k1 - k0;
    int quad_min = lm_nbins_default(g, o->quad_min, 7, 26);
    int lin_min = lm_nbins_default(g, o->lin_min, 3, 7);
    lm_nbox box;
    int lo[3] = {c[0], c[1], c[2]}, sz[3] = {1, 1, 1};
    block_box(g, lo, sz, &box);
    int unique = lm_npoints_unique(&box, x, b->order + k0, k);

    lm_nfit_opts fo;
    lm_nfit_opts_of(&fo, o, (uint64_t)id);
    if (o->basis == LM_NB_HYBRID)
        fo.basis = unique >= quad_min ? LM_NB_QUADRATIC : LM_NB_LINEAR;
    else
        fo.basis = o->basis;

    memcpy(idx, b->order + k0, sizeof *idx * k);
    size_t kb = k;
    int merged = 0, whole = 0;
    if (unique < lin_min && o->merge) {
        double centroid[3] = {0, 0, 0};
        for (size_t q = k0; q < k1; q++)
            for (int a = 0; a < g->dim; a++)
                centroid[a] += x[a][b->order[q]] / (double)k;
        for (int B = 2; unique < lin_min && !whole; B *= 2) {
            best_block(g, b, c, B, centroid, lo, sz);
            block_box(g, lo, sz, &box);
            kb = lm_nbins_gather(g, b, lo, sz, idx);
            unique = lm_npoints_unique(&box, x, idx, kb);
            whole = 1;
            for (int a = 0; a < g->dim; a++)
                whole &= sz[a] >= g->n[a];
        }
        merged = 1;
        if (o->basis == LM_NB_HYBRID)
            fo.basis = LM_NB_LINEAR;       /* [N] §8: merged blocks are linear */
    }
    el->cell[0] = c[0];
    el->cell[1] = c[1];
    el->cell[2] = c[2];
    memcpy(el->lo, lo, sizeof lo);
    el->size = sz[0];
    lm_nerr e = lm_nfit_element_ws(&box, x, idx, kb, &fo, lean, unique, &el->fit, sc,
                                   err, errlen);
    if (merged)
        el->fit.flags |= LM_NF_MERGED;
    if (e == LM_NERR_TOO_FEW && merged && whole)
        snprintf(err, errlen, "only %d distinct membrane point%s in the whole grid: "
                 "at least %d are needed for a normal in %dD, and no merge can add "
                 "more", unique, unique == 1 ? "" : "s", g->dim, g->dim);
    return e;
}

/* Steps 2-5 over every occupied cell, in cell order: the elements go to
 * *elsp (*nelp of them) when elsp is not NULL (a report), undefined normals
 * are counted in *undefp. */
static lm_nerr cells_pass(const lm_ngrid *g, const lm_nbins *b,
                          const double *const x[3], const lm_nopts *o,
                          double *const nrm[3], unsigned char *flags, lm_nelem **elsp,
                          int *nelp, size_t *undefp, lm_nwork *w, char *err,
                          size_t errlen)
{
    lm_nelem one, *els = NULL;
    if (elsp) {
        long occupied = 0;
        for (long c = 0; c < b->ncells; c++)
            occupied += b->start[c + 1] > b->start[c];
        els = calloc((size_t)(occupied ? occupied : 1), sizeof *els);
        *elsp = els;
        if (!els) {
            snprintf(err, errlen, "out of memory (%ld elements)", occupied);
            return LM_NERR_MEMORY;
        }
    }
    for (long id = 0; id < b->ncells; id++) {
        if (b->start[id + 1] == b->start[id])
            continue;
        int c[3] = {(int)(id % g->n[0]), (int)((id / g->n[0]) % g->n[1]),
                    g->dim == 3 ? (int)(id / ((long)g->n[0] * g->n[1])) : 0};
        /* without a report one element at a time is enough */
        lm_nelem *el = els ? &els[*nelp] : &one;
        if (!els)
            memset(el, 0, sizeof *el);
        lm_nerr ce = solve_cell(g, b, x, o, c, w->idx, &w->fit, !elsp, el, err, errlen);
        if (ce == LM_NERR_TOO_FEW && !(el->fit.flags & LM_NF_MERGED) && !o->merge) {
            /* no merging allowed: these points keep no normal */
            for (size_t q = b->start[id]; q < b->start[id + 1]; q++) {
                (*undefp)++;
                if (flags)
                    flags[b->order[q]] |= LM_NF_UNDEFINED;
            }
            el->fit.n = 0;
            (*nelp)++;
            continue;
        }
        if (ce)
            return ce;
        (*nelp)++;
        for (size_t q = b->start[id]; q < b->start[id + 1]; q++) {
            size_t i = b->order[q];
            double p[3] = {x[0][i], x[1][i], g->dim == 3 ? x[2][i] : 0.0}, nv[3];
            int bad = lm_nfit_normal(&el->fit, p, nv);
            for (int a = 0; a < g->dim; a++)
                nrm[a][i] = nv[a];
            *undefp += bad != 0;
            if (flags)
                flags[i] = (unsigned char)((el->fit.flags & ~LM_NF_UNDEFINED) |
                                           (bad ? LM_NF_UNDEFINED : 0));
        }
    }
    return LM_NERR_NONE;
}

lm_nerr lm_normals_grid(const lm_ngrid *g, size_t n, const double *const x[3],
                        const lm_nopts *o, double *const nrm[3],
                        unsigned char *flags, lm_nreport *rep, char *err,
                        size_t errlen)
{
    lm_nwork w;
    memset(&w, 0, sizeof w);
    lm_nerr e = lm_normals_grid_ws(g, n, x, o, nrm, flags, rep, &w, err, errlen);
    lm_nwork_free(&w);
    return e;
}

lm_nerr lm_normals_grid_ws(const lm_ngrid *g, size_t n, const double *const x[3],
                           const lm_nopts *o, double *const nrm[3],
                           unsigned char *flags, lm_nreport *rep, lm_nwork *w,
                           char *err, size_t errlen)
{
    char dummy[8];
    if (!err || !errlen) {
        err = dummy;
        errlen = sizeof dummy;
    }
    err[0] = 0;
    lm_nerr e = check_grid(g, o, err, errlen);
    if (e)
        return e;
    if (rep)
        memset(rep, 0, sizeof *rep);
    for (size_t i = 0; i < n; i++) {
        for (int a = 0; a < g->dim; a++)
            nrm[a][i] = 0.0;
        if (flags)
            flags[i] = 0;
    }
    lm_nelem *els = NULL;
    int nel = 0;
    if (lm_nwork_reserve(w, n)) {
        snprintf(err, errlen, "out of memory (%zu points)", n);
        return LM_NERR_MEMORY;
    }
    lm_nbins *b = &w->bins;
    if ((e = lm_nbins_make(g, n, x, o->element != LM_NELEM_CENTRED, b, err, errlen)))
        goto out;
    size_t undefined = 0;
    if (o->element == LM_NELEM_CENTRED)
        e = lm_normals_centred(g, b, n, x, o, nrm, flags, rep ? &els : NULL, &nel,
                               &undefined, w, err, errlen);
    else
        e = cells_pass(g, b, x, o, nrm, flags, rep ? &els : NULL, &nel, &undefined, w,
                       err, errlen);
    if (e)
        goto out;
    lm_normals_orient_ws(n, g->dim, x, nrm, o->orient, o->orient_point, w);
    if (rep) {
        rep->nundefined = undefined;
        rep->ncells = (int)b->ncells;
        rep->cell_elem = malloc(sizeof *rep->cell_elem * (size_t)b->ncells);
        if (!rep->cell_elem) {
            snprintf(err, errlen, "out of memory (report)");
            e = LM_NERR_MEMORY;
            goto out;
        }
        for (long id = 0; id < b->ncells; id++)
            rep->cell_elem[id] = -1;
        for (int k = 0; k < nel; k++) {
            const lm_nelem *el = &els[k];
            if (o->element != LM_NELEM_CENTRED)
                rep->cell_elem[lm_nbins_cell_id(g, el->cell)] = k;
            rep->nmerged += (el->fit.flags & LM_NF_MERGED) != 0;
            rep->nunder += (el->fit.flags & LM_NF_UNDERDETERMINED) != 0;
            rep->ncoincident += (el->fit.flags & LM_NF_COINCIDENT) != 0;
            rep->nquadratic += el->fit.n > 0 && el->fit.basis == LM_NB_QUADRATIC;
            rep->nlinear += el->fit.n > 0 && el->fit.basis == LM_NB_LINEAR;
        }
        rep->elem = els;
        rep->nelem = nel;
        els = NULL;
    }
out:
    free(els);
    return e;
}
