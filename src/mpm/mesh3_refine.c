/* mesh3_refine.c - a triangle mesh cut finer, to a spacing (mesh3.h): the
 * surface a 3D membrane samples from lamina.mesh. A membrane point sits at
 * every vertex with a third of its fan's area (lm3_sample_mesh), so a mesh
 * whose triangles are larger than the membrane's spacing is cut first:
 * every triangle into k^2 by the lines at 1/k of its sides, one k for the
 * whole mesh so that the points on a shared edge are the same points for
 * both triangles (a closed mesh stays closed and its normals turn out).
 * The new points lie on the flat triangles: a mesh of a curved surface is
 * as faithful as its triangles, not more. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh3.h"
#include "util.h"

/* An undirected edge (a < b) and where it was met. */
typedef struct uedge { int32_t a, b; size_t t; int k; } uedge;

static int by_ends(const void *p, const void *q)
{
    const uedge *x = p, *y = q;
    if (x->a != y->a) return x->a < y->a ? -1 : 1;
    if (x->b != y->b) return x->b < y->b ? -1 : 1;
    return (x->t > y->t) - (x->t < y->t);
}

static double longest_edge(const lm3_mesh *m)
{
    double L = 0;
    for (size_t t = 0; t < m->nt; t++)
        for (int k = 0; k < 3; k++) {
            const double *a = m->xyz + 3 * (size_t)m->tri[3 * t + k];
            const double *b = m->xyz + 3 * (size_t)m->tri[3 * t + (k + 1) % 3];
            double d = sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                            (b[2] - a[2]) * (b[2] - a[2]));
            if (d > L) L = d;
        }
    return L;
}

/* The edges sorted by their ends; the count of distinct ones. NULL when
 * out of memory. */
static uedge *edges_of(const lm3_mesh *m, size_t *ne)
{
    uedge *e = malloc((m->nt ? 3 * m->nt : 1) * sizeof *e);
    if (!e) return NULL;
    for (size_t t = 0; t < m->nt; t++)
        for (int k = 0; k < 3; k++) {
            int32_t a = m->tri[3 * t + k], b = m->tri[3 * t + (k + 1) % 3];
            e[3 * t + k] = (uedge){a < b ? a : b, a < b ? b : a, t, k};
        }
    qsort(e, 3 * m->nt, sizeof *e, by_ends);
    size_t n = 0;
    for (size_t i = 0; i < 3 * m->nt; i++)
        if (i == 0 || e[i].a != e[i - 1].a || e[i].b != e[i - 1].b) n++;
    *ne = n;
    return e;
}

int lm3_mesh_refine_counts(const lm3_mesh *in, double spacing, size_t max_vertices, int *k,
                           size_t *nv, size_t *nt, char *err, size_t errlen)
{
    if (!(spacing > 0) || !isfinite(spacing)) {
        lu_err(err, errlen, "spacing = %g: must be a positive number", spacing);
        return -1;
    }
    double L = longest_edge(in), kk = ceil(L / spacing - 1e-9);
    if (kk < 1) kk = 1;
    size_t ne = 0;
    uedge *e = edges_of(in, &ne);
    if (!e) {
        lu_err(err, errlen, "out of memory for the edges of %zu triangles", in->nt);
        return -1;
    }
    free(e);
    /* in doubles first: no overflow on the way to the refusal */
    double v = (double)in->nv + (double)ne * (kk - 1) + (double)in->nt * (kk - 1) * (kk - 2) / 2;
    if (kk > 65536 || v > (double)max_vertices) {
        lu_err(err, errlen, "the mesh's longest edge %g cut to spacing %g (%g pieces) would make "
               "%.0f points, more than %zu", L, spacing, kk, v, max_vertices);
        return -1;
    }
    *k = (int)kk;
    *nv = (size_t)v;
    *nt = in->nt * (size_t)kk * (size_t)kk;
    return 0;
}

int lm3_mesh_refine(const lm3_mesh *in, double spacing, size_t max_vertices, lm3_mesh *out,
                    char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    int k;
    size_t nv, nt, ne;
    if (lm3_mesh_refine_counts(in, spacing, max_vertices, &k, &nv, &nt, err, errlen) != 0)
        return -1;
    uedge *e = edges_of(in, &ne);
    size_t *eid = malloc((in->nt ? 3 * in->nt : 1) * sizeof *eid);   /* per triangle side */
    size_t *loc = malloc((size_t)(k + 1) * (size_t)(k + 2) / 2 * sizeof *loc);
    out->xyz = malloc(3 * nv * sizeof *out->xyz);
    out->tri = malloc(3 * nt * sizeof *out->tri);
    if (!e || !eid || !loc || !out->xyz || !out->tri) {
        free(e);
        free(eid);
        free(loc);
        lm3_mesh_free(out);
        lu_err(err, errlen, "out of memory refining a mesh to %zu points", nv);
        return -1;
    }
    memcpy(out->xyz, in->xyz, 3 * in->nv * sizeof *out->xyz);
    size_t at = in->nv;
    /* the points inside each edge, from its lower vertex, once */
    for (size_t i = 0, id = 0; i < 3 * in->nt; i++) {
        if (i > 0 && e[i].a == e[i - 1].a && e[i].b == e[i - 1].b) {
            eid[3 * e[i].t + (size_t)e[i].k] = id - 1;
            continue;
        }
        eid[3 * e[i].t + (size_t)e[i].k] = id++;
        const double *a = in->xyz + 3 * (size_t)e[i].a, *b = in->xyz + 3 * (size_t)e[i].b;
        for (int p = 1; p < k; p++)
            for (int c = 0; c < 3; c++)
                out->xyz[3 * (at + (size_t)(p - 1)) + c] = a[c] + (double)p / k * (b[c] - a[c]);
        at += (size_t)(k - 1);
    }
    free(e);
    /* grid point (i, j) of a triangle A B C is A + i/k (B - A) + j/k (C - A),
     * i, j >= 0, i + j <= k; loc maps it to the point's number */
#define LOC(i, j) loc[(size_t)(j) * (size_t)(k + 1) - (size_t)(j) * (size_t)((j) - 1) / 2 + (size_t)(i)]
    size_t nt_out = 0;
    for (size_t t = 0; t < in->nt; t++) {
        const int32_t *v = in->tri + 3 * t;
        const double *A = in->xyz + 3 * (size_t)v[0], *B = in->xyz + 3 * (size_t)v[1],
                     *C = in->xyz + 3 * (size_t)v[2];
        /* the p-th point (0 .. k) along side s from v[s] to v[s+1] */
#define SIDE(s, p)                                                                            \
    ((p) == 0 ? (size_t)v[s]                                                                  \
     : (p) == k ? (size_t)v[((s) + 1) % 3]                                                   \
     : in->nv + eid[3 * t + (s)] * (size_t)(k - 1) +                                          \
           (size_t)((v[s] < v[((s) + 1) % 3] ? (p) : k - (p)) - 1))
        for (int j = 0; j <= k; j++)
            for (int i = 0; i + j <= k; i++) {
                size_t id;
                if (j == 0) id = SIDE(0, i);              /* A -> B */
                else if (i + j == k) id = SIDE(1, j);     /* B -> C */
                else if (i == 0) id = SIDE(2, k - j);     /* C -> A */
                else {
                    id = at++;
                    for (int c = 0; c < 3; c++)
                        out->xyz[3 * id + c] = A[c] + (double)i / k * (B[c] - A[c]) +
                                               (double)j / k * (C[c] - A[c]);
                }
                LOC(i, j) = id;
            }
        for (int j = 0; j < k; j++)
            for (int i = 0; i + j < k; i++) {
                int32_t *q = out->tri + 3 * nt_out++;
                q[0] = (int32_t)LOC(i, j);
                q[1] = (int32_t)LOC(i + 1, j);
                q[2] = (int32_t)LOC(i, j + 1);
                if (i + j < k - 1) {
                    q = out->tri + 3 * nt_out++;
                    q[0] = (int32_t)LOC(i + 1, j);
                    q[1] = (int32_t)LOC(i + 1, j + 1);
                    q[2] = (int32_t)LOC(i, j + 1);
                }
            }
#undef SIDE
    }
#undef LOC
    free(eid);
    free(loc);
    out->nv = at;
    out->nt = nt_out;
    return 0;
}

long lm3_mesh_rim(const lm3_mesh *m, uint8_t *rim)
{
    size_t ne;
    uedge *e = edges_of(m, &ne);
    if (!e) return -1;
    memset(rim, 0, m->nv);
    long n = 0;
    for (size_t i = 0; i < 3 * m->nt;) {
        size_t j = i + 1;
        while (j < 3 * m->nt && e[j].a == e[i].a && e[j].b == e[i].b) j++;
        if (j - i == 1)
            for (int k = 0; k < 2; k++) {
                int32_t v = k ? e[i].b : e[i].a;
                if (!rim[v]) n++;
                rim[v] = 1;
            }
        i = j;
    }
    free(e);
    return n;
}
