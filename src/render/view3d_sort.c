/* view3d_sort.c - cairo's painter's sort of a 3D scene's clouds and
 * triangles (view3d.h): cairo has no depth buffer, so every cloud point
 * and every triangle of the scene is drawn far to near in one sequence -
 * a particle behind a slice is covered by it, one in front covers it, as
 * OpenGL's depth test would have it, up to the painter's own limits (a
 * triangle's depth is its centroid's; long triangles that cross each
 * other are not split). Ties keep the order of adding. Points are discs
 * of their colour, flat; triangles are filled with their vertices' mean
 * colour, shaded by their mean normal when lit (s3_shade, the shader's
 * light). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "view3d_internal.h"

typedef struct key {
    double depth;
    size_t seq;             /* the order of adding, for ties */
    uint32_t item;          /* the scene's item */
    size_t k;               /* its point, or its triangle */
} key;

static int far_first(const void *a, const void *b)
{
    const key *x = a, *y = b;
    if (x->depth != y->depth)
        return x->depth < y->depth ? -1 : 1;
    return x->seq < y->seq ? -1 : x->seq > y->seq;
}

static double depth_of(const lr_view *v, const float *f)
{
    return (f[0] - v->c[0]) * v->toward[0] + (f[1] - v->c[1]) * v->toward[1] +
           (f[2] - v->c[2]) * v->toward[2];
}

static void fill_triangle(lr_canvas *c, const lr_view *v, const s3_item *it, const float *f)
{
    double xy[6], nrm[3] = {0, 0, 0};
    float base[4] = {0, 0, 0, 0};
    for (int j = 0; j < 3; j++) {
        const float *q = f + S3_TRI_FLOATS * j;
        const double w[3] = {q[0], q[1], q[2]};
        lr_view_map(v, w, &xy[2 * j], &xy[2 * j + 1]);
        for (int a = 0; a < 3; a++)
            nrm[a] += q[3 + a];
        for (int a = 0; a < 4; a++)
            base[a] += q[6 + a] / 3.0f;
    }
    lr_rgba k = {base[0], base[1], base[2], base[3]};
    double l = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (it->lit && l > 0) {
        double nv[3] = {0, 0, 0};
        for (int a = 0; a < 3; a++) {
            nv[0] += nrm[a] / l * v->right[a];
            nv[1] += nrm[a] / l * v->up[a];
            nv[2] += nrm[a] / l * v->toward[a];
        }
        if (nv[2] < 0)      /* either side faces the light */
            for (int a = 0; a < 3; a++)
                nv[a] = -nv[a];
        float out[3];
        s3_shade(base, nv, out);
        k.r = out[0];
        k.g = out[1];
        k.b = out[2];
    }
    if (k.a >= 1) {
        /* opaque: grown by a pixel about the centre, so that neighbours'
         * anti-aliased edges do not let the ground show through their
         * seams (a slice's cells) */
        double cx = (xy[0] + xy[2] + xy[4]) / 3, cy = (xy[1] + xy[3] + xy[5]) / 3;
        for (int j = 0; j < 3; j++) {
            double dx = xy[2 * j] - cx, dy = xy[2 * j + 1] - cy, r = hypot(dx, dy);
            if (r > 0) {
                xy[2 * j] += dx / r;
                xy[2 * j + 1] += dy / r;
            }
        }
    }
    size_t three = 3;
    lr_canvas_fill(c, 1, &three, xy, k);
}

/* Discs waiting to be drawn in one call (one radius). */
typedef struct batch {
    double *x, *y;
    lr_rgba *col;
    size_t n;
    double r;
} batch;

static void flush(lr_canvas *c, batch *b)
{
    if (b->n)
        lr_canvas_discs(c, b->n, b->x, b->y, b->r, b->col);
    b->n = 0;
}

int s3_sorted_painter(lr_canvas *c, const lr_view *v, const lr_scene3d *s)
{
    size_t n = 0;
    for (size_t i = 0; i < s->n; i++)
        n += s->items[i].kind == S3_CLOUD ? s->items[i].count
             : s->items[i].kind == S3_TRIS ? s->items[i].count / 3 : 0;
    key *keys = malloc((n ? n : 1) * sizeof *keys);
    batch b = {malloc((n ? n : 1) * sizeof(double)), malloc((n ? n : 1) * sizeof(double)),
               malloc((n ? n : 1) * sizeof(lr_rgba)), 0, 0};
    if (!keys || !b.x || !b.y || !b.col) {
        free(keys);
        free(b.x);
        free(b.y);
        free(b.col);
        return -1;
    }
    size_t m = 0;
    for (size_t i = 0; i < s->n; i++) {
        const s3_item *it = &s->items[i];
        if (it->kind == S3_CLOUD) {
            for (size_t k = 0; k < it->count; k++, m++)
                keys[m] = (key){depth_of(v, s->cloud + 3 * (it->first + k)), m, (uint32_t)i, k};
        } else if (it->kind == S3_TRIS) {
            for (size_t k = 0; k < it->count / 3; k++, m++) {
                const float *f = s->tri + S3_TRI_FLOATS * (it->first + 3 * k);
                double d = 0;
                for (int j = 0; j < 3; j++)
                    d += depth_of(v, f + S3_TRI_FLOATS * j);
                keys[m] = (key){d / 3, m, (uint32_t)i, k};
            }
        }
    }
    qsort(keys, n, sizeof *keys, far_first);
    int clip = v->clip[2] > v->clip[0];
    for (size_t j = 0; j < n; j++) {
        const s3_item *it = &s->items[keys[j].item];
        if (it->kind == S3_TRIS) {
            flush(c, &b);
            fill_triangle(c, v, it, s->tri + S3_TRI_FLOATS * (it->first + 3 * keys[j].k));
            continue;
        }
        size_t p = it->first + keys[j].k;
        const float *f = s->cloud + 3 * p;
        const double q[3] = {f[0], f[1], f[2]};
        double x, y;
        lr_view_map(v, q, &x, &y);
        if (clip && (x + it->size < v->clip[0] || x - it->size > v->clip[2] ||
                     y + it->size < v->clip[1] || y - it->size > v->clip[3]))
            continue;
        if (b.n && b.r != it->size)
            flush(c, &b);
        uint32_t u = s->cloud_rgba[p];
        b.r = it->size;
        b.x[b.n] = x;
        b.y[b.n] = y;
        b.col[b.n++] = (lr_rgba){(u & 255) / 255.0, ((u >> 8) & 255) / 255.0,
                                 ((u >> 16) & 255) / 255.0, (u >> 24) / 255.0};
    }
    flush(c, &b);
    free(keys);
    free(b.x);
    free(b.y);
    free(b.col);
    return 0;
}
