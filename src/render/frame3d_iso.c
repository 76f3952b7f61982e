/* frame3d_iso.c - the surface f = level of a scalar on a node grid, by
 * marching tetrahedra (frame3d.h): each cell cut into the six tetrahedra
 * that share its main diagonal (corner 0 to corner 7), in which the
 * surface is one triangle (one corner apart from the other three) or two
 * (two and two). Unlike marching cubes this has no ambiguous cases, and
 * because neighbouring cells cut their shared face along the same
 * diagonal the pieces meet without cracks. A cut point on an edge is
 * interpolated from the edge's ends taken in the grid's node order, so
 * the two tetrahedra sharing it compute the same bits. The normal at a
 * cut point is the grid's gradient there (central differences at the
 * nodes, one-sided at the faces, interpolated along the edge). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "frame3d.h"
#include "util.h"

typedef struct out3 {
    double *xyz, *nrm;
    size_t n, cap, capn;    /* triangles */
    int failed;
} out3;

static const int TETS[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                               {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

static size_t idx(const lr_grid3d *g, int i, int j, int k)
{
    return ((size_t)k * (size_t)g->n[1] + (size_t)j) * (size_t)g->n[0] + (size_t)i;
}

/* The gradient at node (i, j, k). */
static void gradient(const lr_grid3d *g, const int ijk[3], double gr[3])
{
    for (int a = 0; a < 3; a++) {
        int lo[3] = {ijk[0], ijk[1], ijk[2]}, hi[3] = {ijk[0], ijk[1], ijk[2]};
        if (lo[a] > 0)
            lo[a]--;
        if (hi[a] < g->n[a] - 1)
            hi[a]++;
        double fl = g->f[idx(g, lo[0], lo[1], lo[2])], fh = g->f[idx(g, hi[0], hi[1], hi[2])];
        double d = (hi[a] - lo[a]) * g->h[a];
        gr[a] = d > 0 && isfinite(fl) && isfinite(fh) ? (fh - fl) / d : 0.0;
    }
}

typedef struct corner {
    size_t id;          /* node index */
    int ijk[3];
    double f;
} corner;

/* The cut point on edge a-b, ends in node order. */
static void cut(const lr_grid3d *g, const corner *a, const corner *b, double level,
                double p[3], double n[3])
{
    if (b->id < a->id) {
        const corner *t = a;
        a = b;
        b = t;
    }
    double t = (level - a->f) / (b->f - a->f);
    double ga[3], gb[3];
    gradient(g, a->ijk, ga);
    gradient(g, b->ijk, gb);
    for (int k = 0; k < 3; k++) {
        double xa = g->lo[k] + a->ijk[k] * g->h[k], xb = g->lo[k] + b->ijk[k] * g->h[k];
        p[k] = xa + t * (xb - xa);
        n[k] = ga[k] + t * (gb[k] - ga[k]);
    }
    double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; k++)
        n[k] = l > 0 ? n[k] / l : 0.0;
}

static void tri(out3 *o, const lr_grid3d *g, double level, const corner *a1,
                const corner *b1, const corner *a2, const corner *b2, const corner *a3,
                const corner *b3)
{
    if (o->failed)
        return;
    if (lu_reserve(&o->xyz, &o->cap, o->n + 1, 9 * sizeof *o->xyz, 256) != 0 ||
        lu_reserve(&o->nrm, &o->capn, o->n + 1, 9 * sizeof *o->nrm, 256) != 0) {
        o->failed = 1;
        return;
    }
    double *p = o->xyz + 9 * o->n, *n = o->nrm + 9 * o->n;
    cut(g, a1, b1, level, p, n);
    cut(g, a2, b2, level, p + 3, n + 3);
    cut(g, a3, b3, level, p + 6, n + 6);
    o->n++;
}

static void tet(out3 *o, const lr_grid3d *g, double level, const corner *c[4])
{
    const corner *in[4], *out[4];
    int ni = 0, no = 0;
    for (int k = 0; k < 4; k++) {
        if (c[k]->f > level)
            in[ni++] = c[k];
        else
            out[no++] = c[k];
    }
    if (ni == 0 || ni == 4)
        return;
    if (ni == 1)
        tri(o, g, level, in[0], out[0], in[0], out[1], in[0], out[2]);
    else if (ni == 3)
        tri(o, g, level, out[0], in[0], out[0], in[1], out[0], in[2]);
    else {          /* a quad: a-c, a-d, b-d, b-c */
        tri(o, g, level, in[0], out[0], in[0], out[1], in[1], out[1]);
        tri(o, g, level, in[0], out[0], in[1], out[1], in[1], out[0]);
    }
}

int lr_iso_triangles(const lr_grid3d *g, double level, double **xyz, double **normals,
                     size_t *ntri)
{
    *xyz = *normals = NULL;
    *ntri = 0;
    if (!g || !g->f || g->n[0] < 2 || g->n[1] < 2 || g->n[2] < 2 || !isfinite(level))
        return 0;
    out3 o = {NULL, NULL, 0, 0, 0, 0};
    for (int k = 0; k + 1 < g->n[2]; k++)
        for (int j = 0; j + 1 < g->n[1]; j++)
            for (int i = 0; i + 1 < g->n[0]; i++) {
                corner cs[8];
                int ok = 1, any_in = 0, any_out = 0;
                for (int m = 0; m < 8; m++) {
                    corner *c = &cs[m];
                    c->ijk[0] = i + (m & 1);
                    c->ijk[1] = j + ((m >> 1) & 1);
                    c->ijk[2] = k + ((m >> 2) & 1);
                    c->id = idx(g, c->ijk[0], c->ijk[1], c->ijk[2]);
                    c->f = g->f[c->id];
                    ok &= isfinite(c->f);
                    any_in |= c->f > level;
                    any_out |= !(c->f > level);
                }
                if (!ok || !any_in || !any_out)
                    continue;
                for (int t = 0; t < 6; t++) {
                    const corner *c4[4] = {&cs[TETS[t][0]], &cs[TETS[t][1]], &cs[TETS[t][2]],
                                           &cs[TETS[t][3]]};
                    tet(&o, g, level, c4);
                }
            }
    if (o.failed) {
        free(o.xyz);
        free(o.nrm);
        return -1;
    }
    *xyz = o.xyz;
    *normals = o.nrm;
    *ntri = o.n;
    return 0;
}
