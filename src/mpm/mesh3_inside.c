/* mesh3_inside.c - whether many points lie inside a closed triangle mesh,
 * by the winding number along rays in +x (mesh3.h, lm3_mesh_ray). The
 * solid-angle sum of lm3_mesh_inside visits every triangle for every
 * point; a body seeded in a mesh asks for every sub-cell centre in the
 * mesh's bounding box, so that would be (points x triangles). Here a
 * point asks only the triangles whose (y, z) bounding box holds its (y, z),
 * and a row of points along x shares one ray. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh3.h"
#include "util.h"

void lm3_mesh_ray_free(lm3_mesh_ray *r)
{
    if (!r) return;
    free(r->start);
    free(r->tris);
    free(r->xs);
    memset(r, 0, sizeof *r);
}

static int bucket_of(const lm3_mesh_ray *r, int a, double v)
{
    double f = floor((v - r->lo[a]) / r->cell[a]);
    if (!(f >= 0)) return 0;
    if (f >= r->n[a]) return r->n[a] - 1;
    return (int)f;
}

/* a triangle's bucket range in (y, z) */
static void tri_range(const lm3_mesh_ray *r, size_t t, int b0[2], int b1[2])
{
    const lm3_mesh *m = r->m;
    for (int a = 0; a < 2; a++) {
        double lo = INFINITY, hi = -INFINITY;
        for (int k = 0; k < 3; k++) {
            double v = m->xyz[3 * (size_t)m->tri[3 * t + k] + 1 + a];
            lo = fmin(lo, v);
            hi = fmax(hi, v);
        }
        b0[a] = bucket_of(r, a, lo);
        b1[a] = bucket_of(r, a, hi);
    }
}

/* Fills start and tris for n buckets a side: the entries' total, or 0
 * when above limit (nothing kept), or (size_t)-1 out of memory. */
static size_t fill(lm3_mesh_ray *r, int n, size_t limit)
{
    const lm3_mesh *m = r->m;
    double hi[2] = {-INFINITY, -INFINITY};
    r->lo[0] = r->lo[1] = INFINITY;
    for (size_t v = 0; v < m->nv; v++)
        for (int a = 0; a < 2; a++) {
            r->lo[a] = fmin(r->lo[a], m->xyz[3 * v + 1 + a]);
            hi[a] = fmax(hi[a], m->xyz[3 * v + 1 + a]);
        }
    for (int a = 0; a < 2; a++) {
        r->n[a] = n;
        r->cell[a] = hi[a] > r->lo[a] ? (hi[a] - r->lo[a]) / n : 1;
    }
    size_t nb = (size_t)n * (size_t)n, total = 0;
    size_t *start = calloc(nb + 1, sizeof *start);
    if (!start) return (size_t)-1;
    for (size_t t = 0; t < m->nt; t++) {
        int b0[2], b1[2];
        tri_range(r, t, b0, b1);
        size_t c = (size_t)(b1[0] - b0[0] + 1) * (size_t)(b1[1] - b0[1] + 1);
        total += c;
        if (total > limit) {
            free(start);
            return 0;
        }
        for (int j = b0[1]; j <= b1[1]; j++)
            for (int i = b0[0]; i <= b1[0]; i++) start[(size_t)j * n + i + 1]++;
    }
    for (size_t b = 0; b < nb; b++) start[b + 1] += start[b];
    int32_t *tris = malloc((total ? total : 1) * sizeof *tris);
    size_t *at = malloc((nb ? nb : 1) * sizeof *at);
    if (!tris || !at) {
        free(start);
        free(tris);
        free(at);
        return (size_t)-1;
    }
    memcpy(at, start, nb * sizeof *at);
    for (size_t t = 0; t < m->nt; t++) {
        int b0[2], b1[2];
        tri_range(r, t, b0, b1);
        for (int j = b0[1]; j <= b1[1]; j++)
            for (int i = b0[0]; i <= b1[0]; i++) tris[at[(size_t)j * n + i]++] = (int32_t)t;
    }
    free(at);
    r->start = start;
    r->tris = tris;
    return total;
}

int lm3_mesh_ray_build(const lm3_mesh *m, lm3_mesh_ray *r, char *err, size_t errlen)
{
    memset(r, 0, sizeof *r);
    r->m = m;
    /* about one triangle a bucket; fewer buckets when large triangles
     * would fill too many (the entries stay within 16 a triangle) */
    int n = (int)fmin(1024, fmax(1, ceil(sqrt((double)m->nt))));
    size_t limit = 16 * m->nt + ((size_t)1 << 16);
    for (;;) {
        size_t got = fill(r, n, limit);
        if (got == (size_t)-1) {
            lu_err(err, errlen, "out of memory for the inside test of %zu triangles", m->nt);
            return -1;
        }
        if (got > 0 || m->nt == 0) break;
        n = n / 2 > 1 ? n / 2 : 1;
        if (n == 1) limit = (size_t)-2;
    }
    return 0;
}

/* The edge function of the edge from vertex ia to ib at (y, z): twice the
 * signed area of (a, b, p) in the (y, z) plane, computed from the lower
 * index first, so that the two triangles sharing an edge get the same
 * number with opposite signs, bit for bit. */
static double edgef(const lm3_mesh *m, int32_t ia, int32_t ib, double y, double z)
{
    int32_t lo = ia < ib ? ia : ib, hi = ia < ib ? ib : ia;
    const double *a = m->xyz + 3 * (size_t)lo, *b = m->xyz + 3 * (size_t)hi;
    double e = (b[1] - a[1]) * (z - a[2]) - (b[2] - a[2]) * (y - a[1]);
    return ia < ib ? e : -e;
}

/* A point on the edge a -> b (of a triangle of orientation s in (y, z))
 * belongs to it when the edge, turned counter-clockwise, points up (or
 * right when level): opposite answers for the two directions of an edge,
 * so of two triangles on either side exactly one takes the point, and two
 * folded over each other (a silhouette) both or neither, their signs
 * cancelling. */
static int owns(const lm3_mesh *m, int32_t ia, int32_t ib, int s)
{
    const double *a = m->xyz + 3 * (size_t)ia, *b = m->xyz + 3 * (size_t)ib;
    double dy = s * (b[1] - a[1]), dz = s * (b[2] - a[2]);
    return dy > 0 || (dy == 0 && dz > 0);
}

static int by_x(const void *p, const void *q)
{
    double a = *(const double *)p, b = *(const double *)q;
    return (a > b) - (a < b);
}

/* The crossings of the ray along x through (y, z), sorted by x. */
static int row(lm3_mesh_ray *r, double y, double z)
{
    const lm3_mesh *m = r->m;
    r->nx = 0;
    r->valid = 1;
    r->cy = y;
    r->cz = z;
    if (!(y >= r->lo[0] && y <= r->lo[0] + r->n[0] * r->cell[0] && z >= r->lo[1] &&
          z <= r->lo[1] + r->n[1] * r->cell[1]))
        return 0;
    size_t b = (size_t)bucket_of(r, 1, z) * (size_t)r->n[0] + (size_t)bucket_of(r, 0, y);
    for (size_t k = r->start[b]; k < r->start[b + 1]; k++) {
        const int32_t *v = m->tri + 3 * (size_t)r->tris[k];
        double e[3] = {edgef(m, v[1], v[2], y, z), edgef(m, v[2], v[0], y, z),
                       edgef(m, v[0], v[1], y, z)};
        int pos = e[0] > 0 || e[1] > 0 || e[2] > 0, neg = e[0] < 0 || e[1] < 0 || e[2] < 0;
        if (pos == neg) continue;   /* outside, or a triangle seen edge-on */
        int s = pos ? 1 : -1, in = 1;
        /* e[k] is the edge opposite vertex k: from v[k+1] to v[k+2] */
        for (int c = 0; c < 3 && in; c++)
            if (e[c] == 0) in = owns(m, v[(c + 1) % 3], v[(c + 2) % 3], s);
        if (!in) continue;
        double sum = e[0] + e[1] + e[2], x = 0;
        for (int c = 0; c < 3; c++) x += e[c] * m->xyz[3 * (size_t)v[c]];
        x /= sum;
        if (r->nx == r->capx) {
            size_t cap = r->capx ? 2 * r->capx : 16;
            double *xs = realloc(r->xs, 2 * cap * sizeof *xs);
            if (!xs) return -1;
            r->xs = xs;
            r->capx = cap;
        }
        r->xs[2 * r->nx] = x;       /* (x, sign) pairs */
        r->xs[2 * r->nx + 1] = s;
        r->nx++;
    }
    if (r->nx > 1) qsort(r->xs, r->nx, 2 * sizeof *r->xs, by_x);
    return 0;
}

int lm3_mesh_ray_inside(lm3_mesh_ray *r, const double x[3])
{
    if (r->m->nt == 0) return 0;
    if (!r->valid || r->cy != x[1] || r->cz != x[2]) {
        if (row(r, x[1], x[2]) != 0) {
            r->valid = 0;
            return -1;
        }
    }
    long w = 0;
    for (size_t k = 0; k < r->nx && r->xs[2 * k] < x[0]; k++) w += (long)r->xs[2 * k + 1];
    return w != 0;
}
