/* view3d.c - the 3D scene (view3d.h): items kept in the order they were
 * added, drawn through cairo's painter's order with the layers of
 * layer_glyphs.c, or handed to OpenGL (canvas_gl_view3d.c) when the
 * canvas is a GL one (OSMesa or EGL); and compositing a drawn view into
 * an image. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "view3d_internal.h"
#include "util.h"

lr_scene3d *lr_scene3d_new(void)
{
    return calloc(1, sizeof(lr_scene3d));
}

void lr_scene3d_free(lr_scene3d *s)
{
    if (!s)
        return;
    for (size_t i = 0; i < s->n; i++)
        free(s->items[i].text);
    LU_FREE_ALL(s->items, s->pts, s->cloud, s->cloud_rgba, s->tri, s);
}

size_t lr_scene3d_count(const lr_scene3d *s)
{
    return s ? s->n : 0;
}

/* Room for `more` items; -1 on OOM. */
static int reserve(lr_scene3d *s, size_t more)
{
    return lu_reserve(&s->items, &s->cap, s->n + more, sizeof *s->items, 64);
}

/* An item of this layer (room reserved): its kind, points a and b (NULL:
 * none), line width and colour; the other fields zero. */
static s3_item *push(lr_scene3d *s, s3_kind kind, const double a[3], const double b[3],
                     double width, lr_rgba colour)
{
    s3_item *it = &s->items[s->n++];
    memset(it, 0, sizeof *it);
    it->kind = kind;
    it->layer = s->layers;
    if (a)
        memcpy(it->a, a, sizeof it->a);
    if (b)
        memcpy(it->b, b, sizeof it->b);
    it->width = width;
    it->colour = colour;
    return it;
}

static int finite3(const double q[3])
{
    return isfinite(q[0]) && isfinite(q[1]) && isfinite(q[2]);
}

static void at(const double *const p[3], size_t i, double q[3])
{
    for (int a = 0; a < 3; a++)
        q[a] = p[a][i];
}

static int points(lr_scene3d *s, s3_kind kind, size_t n, const double *const p[3],
                  double radius_px, double width, lr_rgba colour)
{
    if (!s || reserve(s, n) != 0)
        return -1;
    for (size_t i = 0; i < n; i++) {
        double q[3];
        at(p, i, q);
        if (!finite3(q))
            continue;
        push(s, kind, q, NULL, width, colour)->size = radius_px;
    }
    s->layers++;
    return 0;
}

int lr_scene3d_circles(lr_scene3d *s, size_t n, const double *const p[3],
                       double radius_px, double width, lr_rgba colour)
{
    return points(s, S3_CIRCLE, n, p, radius_px, width, colour);
}

int lr_scene3d_dots(lr_scene3d *s, size_t n, const double *const p[3],
                    double radius_px, lr_rgba colour)
{
    return points(s, S3_DOT, n, p, radius_px, 0.0, colour);
}

int lr_scene3d_asterisk(lr_scene3d *s, const double p[3], double size_px,
                        double width, lr_rgba colour)
{
    if (!s || reserve(s, 1) != 0)
        return -1;
    if (finite3(p))
        push(s, S3_ASTERISK, p, NULL, width, colour)->size = size_px;
    s->layers++;
    return 0;
}

int lr_scene3d_arrows(lr_scene3d *s, size_t n, const double *const p[3],
                      const double *const d[3], double length, double width,
                      double head_px, lr_rgba colour, double dash)
{
    if (!s || reserve(s, n) != 0)
        return -1;
    for (size_t i = 0; i < n; i++) {
        double a[3], u[3];
        at(p, i, a);
        at(d, i, u);
        if (!finite3(a) || !finite3(u) || (u[0] == 0 && u[1] == 0 && u[2] == 0) ||
            !isfinite(length))
            continue;
        s3_item *it = push(s, S3_ARROW, a, u, width, colour);
        it->length = length;
        it->head = head_px;
        it->dash = dash;
    }
    s->layers++;
    return 0;
}

int lr_scene3d_polyline(lr_scene3d *s, size_t n, const double *const p[3],
                        double width, lr_rgba colour, double dash)
{
    if (!s || reserve(s, 1) != 0)
        return -1;
    if (n > ((size_t)-1) / 8 / sizeof(double) - s->npts ||
        lu_reserve(&s->pts, &s->cappts, s->npts + n, 3 * sizeof *s->pts, 256) != 0)
        return -1;
    /* a non-finite point breaks the line in two, as it would break the
     * layer's segments */
    size_t start = s->npts;
    for (size_t i = 0; i <= n; i++) {
        double q[3] = {0, 0, 0};
        int ok = i < n;
        if (ok) {
            at(p, i, q);
            ok = finite3(q);
        }
        if (ok) {
            memcpy(s->pts + 3 * s->npts, q, sizeof q);
            s->npts++;
            continue;
        }
        if (s->npts - start >= 2) {
            if (reserve(s, 1) != 0)
                return -1;
            s3_item *it = push(s, S3_POLYLINE, NULL, NULL, width, colour);
            it->first = start;
            it->count = s->npts - start;
            it->dash = dash;
        }
        start = s->npts;
    }
    s->layers++;
    return 0;
}

int lr_scene3d_line(lr_scene3d *s, const double a[3], const double b[3],
                    double width, lr_rgba colour, double dash)
{
    if (!s || reserve(s, 1) != 0)
        return -1;
    if (finite3(a) && finite3(b))
        push(s, S3_LINE, a, b, width, colour)->dash = dash;
    s->layers++;
    return 0;
}

int lr_scene3d_box(lr_scene3d *s, const double lo[3], const double hi[3],
                   double width, lr_rgba colour)
{
    if (!s || reserve(s, 1) != 0)
        return -1;
    if (finite3(lo) && finite3(hi))
        push(s, S3_BOX, lo, hi, width, colour);
    s->layers++;
    return 0;
}

int lr_scene3d_text(lr_scene3d *s, const double p[3], double dx, double dy,
                    double size, lr_rgba colour, lr_align align, const char *text)
{
    if (!s || reserve(s, 1) != 0)
        return -1;
    if (!text || !*text || !finite3(p))
        return 0;
    char *copy = strdup(text);
    if (!copy)
        return -1;
    s3_item *it = push(s, S3_TEXT, p, NULL, 0.0, colour);
    it->dx = dx;
    it->dy = dy;
    it->size = size;
    it->align = align;
    it->text = copy;
    s->layers++;
    return 0;
}

uint32_t lr_rgba_pack(lr_rgba k)
{
    const double c[4] = {k.r, k.g, k.b, k.a};
    uint32_t u = 0;
    for (int i = 0; i < 4; i++) {
        double x = c[i] < 0 ? 0 : c[i] > 1 ? 1 : c[i];     /* NaN: 1 */
        u |= (uint32_t)(255.0 * x + 0.5) << (8 * i);
    }
    return u;
}

static int cloud(lr_scene3d *s, size_t n, const double *const p[3], const lr_rgba *colours,
                 lr_rgba colour, const uint32_t *rgba8, double radius_px)
{
    if (!s || reserve(s, 1) != 0)
        return -1;
    if (n > ((size_t)-1) / 32 - s->ncloud ||
        lu_reserve(&s->cloud, &s->capcloud, s->ncloud + n, 3 * sizeof *s->cloud, 1024) != 0 ||
        lu_reserve(&s->cloud_rgba, &s->caprgba, s->ncloud + n, sizeof *s->cloud_rgba,
                   1024) != 0)
        return -1;
    size_t first = s->ncloud;
    uint32_t one = lr_rgba_pack(colour);
    for (size_t i = 0; i < n; i++) {
        const double q[3] = {p[0][i], p[1][i], p[2][i]};
        if (!finite3(q))
            continue;
        float *f = s->cloud + 3 * s->ncloud;
        for (int a = 0; a < 3; a++)
            f[a] = (float)q[a];
        s->cloud_rgba[s->ncloud++] = rgba8 ? rgba8[i] : colours ? lr_rgba_pack(colours[i]) : one;
    }
    if (s->ncloud > first && radius_px > 0) {
        s3_item *it = push(s, S3_CLOUD, NULL, NULL, 0.0, colour);
        it->first = first;
        it->count = s->ncloud - first;
        it->size = radius_px;
    }
    s->layers++;
    return 0;
}

int lr_scene3d_cloud(lr_scene3d *s, size_t n, const double *const p[3],
                     const lr_rgba *colours, lr_rgba colour, double radius_px)
{
    return cloud(s, n, p, colours, colour, NULL, radius_px);
}

int lr_scene3d_cloud_rgba8(lr_scene3d *s, size_t n, const double *const p[3],
                           const uint32_t *rgba8, double radius_px)
{
    const lr_rgba none = {0, 0, 0, 1};
    return cloud(s, n, p, NULL, none, rgba8, radius_px);
}

int lr_scene3d_triangles(lr_scene3d *s, size_t n, const double *xyz,
                         const double *normals, const lr_rgba *colours,
                         lr_rgba colour)
{
    if (!s || reserve(s, 1) != 0)
        return -1;
    if (n > ((size_t)-1) / 64 / S3_TRI_FLOATS - s->ntri ||
        lu_reserve(&s->tri, &s->captri, s->ntri + 3 * n, S3_TRI_FLOATS * sizeof *s->tri,
                   3072) != 0)
        return -1;
    size_t first = s->ntri;
    int clear = 0;
    for (size_t k = 0; k < n; k++) {
        const double *q = xyz + 9 * k;
        if (!finite3(q) || !finite3(q + 3) || !finite3(q + 6))
            continue;
        for (int j = 0; j < 3; j++) {
            float *f = s->tri + S3_TRI_FLOATS * s->ntri++;
            lr_rgba k3 = colours ? colours[3 * k + (size_t)j] : colour;
            const double *nn = normals ? normals + 9 * k + 3 * j : NULL;
            for (int a = 0; a < 3; a++) {
                f[a] = (float)q[3 * j + a];
                f[3 + a] = nn && isfinite(nn[a]) ? (float)nn[a] : 0.0f;
            }
            f[6] = (float)k3.r;
            f[7] = (float)k3.g;
            f[8] = (float)k3.b;
            f[9] = (float)k3.a;
            clear |= k3.a < 1;
        }
    }
    if (s->ntri > first) {
        s3_item *it = push(s, S3_TRIS, NULL, NULL, 0.0, colour);
        it->first = first;
        it->count = s->ntri - first;
        it->lit = normals != NULL;
        it->see_through = clear;
    }
    s->layers++;
    return 0;
}

/* ---- drawing ------------------------------------------------------------- */

static void draw_text(lr_canvas *c, const lr_view *v, const s3_item *it)
{
    double x, y;
    lr_view_map(v, it->a, &x, &y);
    lr_canvas_text(c, x + it->dx, y + it->dy, it->size, it->colour, it->align,
                   it->text);
}

/* cairo: the layers, item by item, in order; every cloud and triangle of
 * the scene together, sorted far to near, where the first of them is
 * (view3d_sort.c). */
static int painter(lr_canvas *c, const lr_view *v, const lr_scene3d *s)
{
    int sorted = 0;
    for (size_t i = 0; i < s->n; i++) {
        const s3_item *it = &s->items[i];
        const double *const pa[3] = {&it->a[0], &it->a[1], &it->a[2]};
        const double *const pb[3] = {&it->b[0], &it->b[1], &it->b[2]};
        switch (it->kind) {
        case S3_LINE: {
            double ax, ay, bx, by;
            lr_view_map(v, it->a, &ax, &ay);
            lr_view_map(v, it->b, &bx, &by);
            lr_view_line(c, v, ax, ay, bx, by, it->width, it->colour, it->dash);
            break;
        }
        case S3_POLYLINE: {
            /* segment by segment, as lr_layer_polyline draws them */
            const double *q = s->pts + 3 * it->first;
            for (size_t k = 0; k + 1 < it->count; k++, q += 3) {
                double xs[2] = {q[0], q[3]}, ys[2] = {q[1], q[4]}, zs[2] = {q[2], q[5]};
                const double *const two[3] = {xs, ys, zs};
                lr_layer_polyline(c, v, 2, 3, two, it->width, it->colour, it->dash);
            }
            break;
        }
        case S3_ARROW:
            lr_layer_arrows(c, v, 1, 3, pa, pb, it->length, it->width, it->head,
                            it->colour, it->dash);
            break;
        case S3_CIRCLE:
            lr_layer_circles(c, v, 1, 3, pa, it->size, it->width, it->colour);
            break;
        case S3_DOT:
            lr_layer_dots(c, v, 1, 3, pa, it->size, it->colour);
            break;
        case S3_ASTERISK:
            lr_layer_asterisk(c, v, it->a, it->size, it->width, it->colour);
            break;
        case S3_BOX:
            lr_layer_box(c, v, it->a, it->b, it->width, it->colour);
            break;
        case S3_TEXT:
            draw_text(c, v, it);
            break;
        case S3_CLOUD:
        case S3_TRIS:
            if (!sorted && s3_sorted_painter(c, v, s) != 0)
                return -1;
            sorted = 1;
            break;
        }
    }
    return 0;
}

int lr_scene3d_draw(lr_canvas *c, const lr_view *v, const lr_scene3d *s, char *err,
                    size_t errlen)
{
    if (!c || !v || !s) {
        lu_err(err, errlen, "3D view: no canvas, view or scene");
        return -1;
    }
    if (!v->is3d) {
        lu_err(err, errlen, "3D view: the view is not a 3D one (lr_view_3d)");
        return -1;
    }
    lr_backend b = lr_canvas_backend(c);
    if (b != LR_BACKEND_OSMESA && b != LR_BACKEND_EGL) {
        if (painter(c, v, s) != 0) {
            lu_err(err, errlen, "3D view: out of memory");
            return -1;
        }
        return 0;
    }
#ifdef LAMINA_HAVE_GL
    if (gl_view3d(c, v, s, err, errlen) != 0)
        return -1;
    for (size_t i = 0; i < s->n; i++)
        if (s->items[i].kind == S3_TEXT)
            draw_text(c, v, &s->items[i]);
    return 0;
#else
    lu_err(err, errlen, "3D view: this lamina was built without OpenGL (OSMesa or EGL)");
    return -1;
#endif
}

/* ---- compositing ----------------------------------------------------------- */

void lr_rgba_over(unsigned char *dst, int dw, int dh, const unsigned char *src,
                  int sw, int sh, int x, int y)
{
    int i0 = x < 0 ? -x : 0, j0 = y < 0 ? -y : 0;
    int i1 = sw, j1 = sh;
    if (x + i1 > dw)
        i1 = dw - x;
    if (y + j1 > dh)
        j1 = dh - y;
    for (int j = j0; j < j1; j++)
        for (int i = i0; i < i1; i++) {
            const unsigned char *s = src + 4 * ((size_t)j * (size_t)sw + (size_t)i);
            unsigned char *d = dst + 4 * ((size_t)(y + j) * (size_t)dw + (size_t)(x + i));
            unsigned sa = s[3];
            if (sa == 0)
                continue;
            if (sa == 255) {
                memcpy(d, s, 4);
                continue;
            }
            /* straight alpha: a = sa + da (1 - sa), c = (sc sa + dc da (1 - sa)) / a,
             * in units of 255 * 255 */
            unsigned da = d[3];
            unsigned long wd = (unsigned long)da * (255u - sa);    /* / 255^2 */
            unsigned long ws = (unsigned long)sa * 255u;
            unsigned long wa = ws + wd;
            for (int k = 0; k < 3; k++)
                d[k] = (unsigned char)((s[k] * ws + d[k] * wd + wa / 2) / wa);
            d[3] = (unsigned char)((wa + 127) / 255);
        }
}
