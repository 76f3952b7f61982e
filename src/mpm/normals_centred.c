/* normals_centred.c - centred elements: the isosurface construction as
 * lamina runs it every step of a simulation (sim:membrane{normals =
 * "isosurface"}; docs/normals.md, "Centred elements").
 *
 * Why. [N] §3: "any convenient subset of material points and corresponding
 * elements can be used to determine the normal to the surface". The
 * per-cell construction ([N] §8, normals_grid.c) gives a point the fit of
 * whichever cell it happens to lie in. Where the membrane clips a cell's
 * corner, or runs along a grid line, that cell holds a few points in a
 * sliver at its edge; its linear fit errs as [N] Fig 7 shows and its
 * quadratic fit is nearly singular (on the dynamic circular membrane single
 * normals turn by up to 73 degrees). Here a point's element is a box of
 * one cell centred on the point of the half-cell lattice - cell centres,
 * nodes, edge and face midpoints - nearest to it: the point lies in the
 * middle half of its element and the membrane crosses the element instead
 * of touching it.
 *
 * Steps:
 *  1. each point's lattice site: s_a = round(2 (x_a - x0_a) / h_a - 1),
 *     clamped to 0 .. 2 n_a - 2, centre x0_a + (s_a + 1) h_a / 2 (so a
 *     one-cell element never leaves the grid);
 *  2. the points sorted by site; one fit per site, for its points;
 *  3. the element: one cell per axis about the centre; with fewer than
 *     quad_min distinct points it grows to 2, 4, ... cells ([N] §4, and §6:
 *     "elements can be combined to form a larger element containing more
 *     points"), moved back inside the grid, up to the whole grid;
 *  4. the quadratic basis ([N] §5), linear if even the whole grid holds
 *     fewer than quad_min points (or when asked for), fitted by
 *     lm_nfit_element with the options' curvature rows and random-point
 *     clearance (normals_smooth.c, normals_fit.c); the random point comes
 *     from a stream keyed by the site;
 *  5. n = grad phi / |grad phi| at the site's points ([N] eq 16). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "normals.h"
#include "normals_bins.h"
#include "normals_work.h"

/* Site streams are kept apart from the per-cell streams (keyed by cell). */
#define SITE_STREAM ((uint64_t)1 << 62)

/* Site order, then point order: a total order, so any sort gives the same
 * sequence (the one qsort gave before the workspace). */
static int before(const lm_nsite *p, const lm_nsite *q)
{
    return p->key != q->key ? p->key < q->key : p->i < q->i;
}

/* Step 2's sort without allocation (qsort may malloc its buffer): a
 * bottom-up merge sort of a[0..n) with tmp (n entries) as scratch. */
static void sort_sites(lm_nsite *a, lm_nsite *tmp, size_t n)
{
    lm_nsite *src = a, *dst = tmp;
    for (size_t run = 1; run < n; run *= 2) {
        for (size_t lo = 0; lo < n; lo += 2 * run) {
            size_t mid = lo + run < n ? lo + run : n;
            size_t hi = lo + 2 * run < n ? lo + 2 * run : n;
            size_t i = lo, j = mid, k = lo;
            while (i < mid && j < hi)
                dst[k++] = before(&src[j], &src[i]) ? src[j++] : src[i++];
            while (i < mid)
                dst[k++] = src[i++];
            while (j < hi)
                dst[k++] = src[j++];
        }
        lm_nsite *t = src;
        src = dst;
        dst = t;
    }
    if (src != a)
        memcpy(a, src, sizeof *a * n);
}

/* Step 2's sort when a[0..n) is nearly in order already (the last step's
 * order with this step's sites: a few points change site each step), by
 * insertion, giving up after 8 n moves (then 0: the merge sort finishes
 * from there). Both give the one sequence of the total order, whatever
 * order a starts in, so the result does not depend on the last call. */
static int sort_nearly_sorted(lm_nsite *a, size_t n)
{
    size_t moves = 0, limit = 8 * n + 16;
    for (size_t i = 1; i < n; i++) {
        if (!before(&a[i], &a[i - 1]))
            continue;
        lm_nsite t = a[i];
        size_t j = i;
        while (j > 0 && before(&t, &a[j - 1])) {
            a[j] = a[j - 1];
            j--;
            if (++moves > limit) {
                a[j] = t;
                return 0;
            }
        }
        a[j] = t;
    }
    return 1;
}

/* (int)floor(v) and (int)ceil(v) for v within int's range, from the
 * truncating conversion (no call into libm: these run for every point and
 * element of every step). */
static inline int floor_int(double v)
{
    int i = (int)v;
    return i - (v < i);
}

static inline int ceil_int(double v)
{
    int i = (int)v;
    return i + (v > i);
}

/* Step 1: the lattice site of point i (per axis into s) and its key. */
static long site_of(const lm_ngrid *g, const double *const x[3], size_t i, int s[3])
{
    long key = 0, stride = 1;
    s[0] = s[1] = s[2] = 0;
    for (int a = 0; a < g->dim; a++) {
        int m = 2 * g->n[a] - 1;
        double f = 2.0 * (x[a][i] - g->x0[a]) / g->h[a] - 1.0;
        int v = floor_int(f + 0.5);
        s[a] = v < 0 ? 0 : v > m - 1 ? m - 1 : v;
        key += s[a] * stride;
        stride *= m;
    }
    return key;
}

/* Step 3: the element w cells wide about site s - its box and the cells it
 * overlaps (lo, sz). Returns 1 when it is the whole grid. */
static int element_box(const lm_ngrid *g, const int s[3], int w, lm_nbox *box,
                       int lo[3], int sz[3])
{
    int whole = 1;
    box->dim = g->dim;
    for (int a = 0; a < 3; a++) {
        if (a >= g->dim) {
            box->lo[a] = box->hi[a] = 0.0;
            lo[a] = 0;
            sz[a] = 1;
            continue;
        }
        double L = g->n[a] * g->h[a], width = w * g->h[a];
        if (w >= g->n[a])
            width = L;
        else
            whole = 0;
        double l = g->x0[a] + (s[a] + 1) * 0.5 * g->h[a] - 0.5 * width;
        if (l < g->x0[a])
            l = g->x0[a];
        if (l + width > g->x0[a] + L)
            l = g->x0[a] + L - width;
        box->lo[a] = l;
        box->hi[a] = l + width;
        int c0 = floor_int((l - g->x0[a]) / g->h[a] + 1e-9);
        int c1 = ceil_int((l + width - g->x0[a]) / g->h[a] - 1e-9) - 1;
        c0 = c0 < 0 ? 0 : c0;
        c1 = c1 > g->n[a] - 1 ? g->n[a] - 1 : c1;
        lo[a] = c0;
        sz[a] = c1 >= c0 ? c1 - c0 + 1 : 1;
    }
    return whole;
}

/* The points of idx[0..k) inside the (closed) box, into sel; their count. */
static size_t inside(const lm_nbox *box, const double *const x[3], const size_t *idx,
                     size_t k, size_t *sel)
{
    size_t m = 0;
    if (box->dim == 2) {
        /* without branches (a gathered point is in or out at random): the
         * same tests, so the same points in the same order */
        double lo0 = box->lo[0], hi0 = box->hi[0], lo1 = box->lo[1], hi1 = box->hi[1];
        for (size_t j = 0; j < k; j++) {
            size_t q = idx[j];
            double p0 = x[0][q], p1 = x[1][q];
            sel[m] = q;
            m += (size_t)((p0 >= lo0) & (p0 <= hi0) & (p1 >= lo1) & (p1 <= hi1));
        }
        return m;
    }
    for (size_t j = 0; j < k; j++) {
        int in = 1;
        for (int a = 0; a < box->dim && in; a++)
            in = x[a][idx[j]] >= box->lo[a] && x[a][idx[j]] <= box->hi[a];
        if (in)
            sel[m++] = idx[j];
    }
    return m;
}

/* Appends an element to the growing list (*els, *nel, *cap). */
static int push_elem(lm_nelem **els, int *nel, int *cap, const lm_nelem *el)
{
    if (*nel == *cap) {
        int c = *cap ? 2 * *cap : 16;
        lm_nelem *p = realloc(*els, sizeof *p * (size_t)c);
        if (!p)
            return -1;
        *els = p;
        *cap = c;
    }
    (*els)[(*nel)++] = *el;
    return 0;
}

/* LAMINA_NRM_CMP (normals_work.h): the fit again by the QR, and the angle
 * between its normal and the Cholesky fit's at each of the site's points. */
static void compare_qr(const lm_nbox *box, const double *const x[3], const size_t *sel,
                       size_t k, const lm_nfit_opts *fo, int unique, const lm_nfit *fit,
                       const lm_nsite *sp, size_t np, lm_nwork *w)
{
    lm_nfit_opts qo = *fo;
    lm_nfit qr;
    char err[256];
    qo.solver = LM_NS_QR;
    if (lm_nfit_element_ws(box, x, sel, k, &qo, LM_NFIT_LEAN | LM_NFIT_INSIDE, unique, &qr,
                           &w->fit, err, sizeof err))
        return;
    for (size_t q = 0; q < np; q++) {
        size_t i = sp[q].i;
        double p[3] = {x[0][i], x[1][i], box->dim == 3 ? x[2][i] : 0.0}, a[3], b[3];
        if (lm_nfit_normal(fit, p, a) || lm_nfit_normal(&qr, p, b))
            continue;
        double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                       a[0] * b[1] - a[1] * b[0]};
        double ang = atan2(sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]),
                           a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) * (180.0 / 3.14159265358979323846);
        w->cmp_max = ang > w->cmp_max ? ang : w->cmp_max;
        w->cmp_sum += ang;
        w->cmp_n++;
    }
}

lm_nerr lm_normals_centred(const lm_ngrid *g, const lm_nbins *b, size_t n,
                           const double *const x[3], const lm_nopts *o,
                           double *const nrm[3], unsigned char *flags,
                           lm_nelem **els, int *nel, size_t *undefined,
                           struct lm_nwork *w, char *err, size_t errlen)
{
    int quad_min = lm_nbins_default(g, o->quad_min, 7, 26);
    int lin_min = lm_nbins_default(g, o->lin_min, 3, 7);
    int linear = o->basis == LM_NB_LINEAR;
    lm_nsite *sp = w->sites;
    size_t *idx = w->idx, *sel = w->sel;
    int cap = 0;
    lm_nerr e = LM_NERR_NONE;
    if (w->sites_n == n) {
        /* the last call's order (points move little in a step), re-keyed */
        for (size_t q = 0; q < n; q++) {
            int s[3];
            sp[q].key = site_of(g, x, sp[q].i, s);
        }
    } else {
        for (size_t i = 0; i < n; i++) {
            int s[3];
            sp[i].key = site_of(g, x, i, s);
            sp[i].i = i;
        }
    }
    if (!sort_nearly_sorted(sp, n))
        sort_sites(sp, w->sites_tmp, n);
    w->sites_n = n;
    for (size_t a0 = 0, a1; a0 < n; a0 = a1) {
        for (a1 = a0 + 1; a1 < n && sp[a1].key == sp[a0].key; a1++)
            ;
        /* every field is written below: lo by element_box, fit by the
         * fit (which clears it first), size and cell after it */
        lm_nelem el;
        int s[3], wid = 1, whole, unique;
        size_t k;
        site_of(g, x, sp[a0].i, s);
        lm_nbox box;
        for (;; wid *= 2) {
            int sz[3];
            whole = element_box(g, s, wid, &box, el.lo, sz);
            k = inside(&box, x, idx, lm_nbins_gather(g, b, el.lo, sz, idx), sel);
            unique = lm_npoints_unique(&box, x, sel, k);
            if (unique >= (linear ? lin_min : quad_min) || whole)
                break;
        }
        lm_nfit_opts fo;
        lm_nfit_opts_of(&fo, o, SITE_STREAM | (uint64_t)sp[a0].key);
        fo.basis = !linear && unique >= quad_min ? LM_NB_QUADRATIC : LM_NB_LINEAR;
        /* sel holds the points inside the closed box (inside()) */
        e = lm_nfit_element_ws(&box, x, sel, k, &fo,
                               (els ? 0 : LM_NFIT_LEAN) | LM_NFIT_INSIDE, unique,
                               &el.fit, &w->fit, err, errlen);
        if (e == LM_NERR_TOO_FEW && whole)
            snprintf(err, errlen, "only %d distinct membrane point%s in the whole grid: "
                     "at least %d are needed for a normal in %dD", unique,
                     unique == 1 ? "" : "s", g->dim, g->dim);
        if (e)
            return e;
        if (w->cmp && fo.solver == LM_NS_CHOLESKY)
            compare_qr(&box, x, sel, k, &fo, unique, &el.fit, sp + a0, a1 - a0, w);
        if (wid > 1)
            el.fit.flags |= LM_NF_MERGED;
        el.size = wid;
        for (int a = 0; a < 3; a++)
            el.site[a] = s[a];
        for (int a = 0; a < 3; a++) {
            double c = a < g->dim ? 0.5 * (box.lo[a] + box.hi[a]) : 0.0;
            el.cell[a] = a < g->dim ? floor_int((c - g->x0[a]) / g->h[a]) : 0;
        }
        /* step 5, two points at a time (lm_nfit_normal2: the two chains
         * of divisions and square roots side by side) */
        for (size_t q = a0; q < a1; q += 2) {
            size_t m = q + 1 < a1 ? 2 : 1, is[2] = {sp[q].i, sp[q + m - 1].i};
            double p[2][3], nv[2][3];
            int bad[2];
            for (size_t l = 0; l < m; l++) {
                size_t i = is[l];
                p[l][0] = x[0][i];
                p[l][1] = x[1][i];
                p[l][2] = g->dim == 3 ? x[2][i] : 0.0;
            }
            if (m == 2)
                lm_nfit_normal2(&el.fit, p[0], p[1], nv[0], nv[1], bad);
            else
                bad[0] = lm_nfit_normal(&el.fit, p[0], nv[0]);
            for (size_t l = 0; l < m; l++) {
                size_t i = is[l];
                for (int a = 0; a < g->dim; a++)
                    nrm[a][i] = nv[l][a];
                *undefined += bad[l] != 0;
                if (flags)
                    flags[i] = (unsigned char)((el.fit.flags & ~LM_NF_UNDEFINED) |
                                               (bad[l] ? LM_NF_UNDEFINED : 0));
            }
        }
        if (els && push_elem(els, nel, &cap, &el)) {
            snprintf(err, errlen, "out of memory (report)");
            return LM_NERR_MEMORY;
        }
    }
    return e;
}
