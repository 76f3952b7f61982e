/* canvas_gl_view3d.c - 3D views through OpenGL (view3d.h): the scene
 * drawn with a depth buffer, so what is behind is hidden, into an
 * off-screen framebuffer at 4 x 4 samples a pixel, averaged down and
 * blended onto the GL canvas (OSMesa or EGL) like any other drawing.
 *
 * The camera is the view's own: every vertex goes through lr_view_map (the
 * orthographic projection the cairo layers use) for its pixel position,
 * and its depth is its distance towards the viewer (lr_view.toward). So
 * both backends put every point, arrow and edge on the same pixels; only
 * the marks differ:
 *   - lines (edges, outlines, arrow shafts, asterisks) are screen-space
 *     quads of the layers' widths, dashed in the fragment shader with the
 *     layers' dash lengths (hidden cube edges thinner and dashed, as there);
 *   - points are spheres of the layers' radius in pixels: ray-cast
 *     impostors (a square, the sphere's depth written per sample), shaded,
 *     the open circle's ring in its colour around a pale body, so they
 *     read as the layers' circles;
 *   - arrow heads are shaded cones, 1.5 times as long as the layers' flat
 *     heads (with the same 25 degree half-angle).
 * Lighting is a fixed light from the upper left and in front, with a
 * little specular. Items added later win depth ties (a small bias per
 * layer, view3d.h), so a computed normal covers the exact one it
 * coincides with, as in painter's order.
 *
 * Deterministic: one draw call in the scene's order, fixed sample grid,
 * integer averaging. */
#include "canvas_gl.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "view3d_internal.h"

#define SUPERSAMPLE 4               /* samples per pixel along each axis */
#define SS_MAX_BYTES (512.0 * 1024 * 1024)   /* colour + depth + read-back */
#define V3_FLOATS 12                /* x y z, p0..p3, kind, r g b a */
#define CONE_SEGMENTS 24
#define HEAD_SCALE 1.5              /* cone length / the layers' head length */
#define TWO_PI 6.283185307179586476925286766559
/* Supersampling drops (4 x 4, 3 x 3 ...) until the clouds' splats cover
 * at most this many samples: 10^6 points of a pixel's radius at 2 x 2
 * (measured: docs/performance.md "3D frames") */
#define CLOUD_SAMPLES 1.6e7
/* ... and until the splat buffers (cleared, filled, handed to OpenGL:
 * 8 bytes a sample more than other scenes move) are at most this many
 * samples - 2 x 2 for an 800 x 800 panel: at 4 x 4 the buffers alone
 * cost some 200 ms (measured, docs/performance.md "3D frames") */
#define CLOUD_BUFFER 4.2e6

enum { K_LINE = 0, K_SPHERE = 1, K_LIT = 2, K_FLAT = 3, K_LIT2 = 4 };
enum { A_POS = 0, A_P = 1, A_KIND = 2, A_COL = 3 };

/* Vertices in supersampled pixels of the region (origin top-left, y
 * down) and NDC depth; the shader only maps them to clip space. */
static const char *const view3d_vs =
    "#version 120\n"
    "uniform vec2 u_size;\n"
    "attribute vec3 a_pos;\n"
    "attribute vec4 a_p;\n"
    "attribute float a_kind;\n"
    "attribute vec4 a_col;\n"
    "varying vec4 v_p;\n"
    "varying float v_kind;\n"
    "varying vec4 v_col;\n"
    "void main() {\n"
    "  v_p = a_p; v_kind = a_kind; v_col = a_col;\n"
    "  gl_Position = vec4(2.0 * a_pos.x / u_size.x - 1.0,\n"
    "                     1.0 - 2.0 * a_pos.y / u_size.y, a_pos.z, 1.0);\n"
    "}\n";

/* kind 0, a line: p.x the distance along it, p.y the dash (0: solid), in
 * pixels. kind 1, a sphere: p.xy the position in its disc (unit radius, y
 * up), p.z its radius in window depth, p.w where the ring starts (> 1:
 * none, the body in the colour). kind 2, a shaded surface: p.xyz its
 * normal in view space (x right, y up, z towards the viewer). kind 3, a
 * flat colour (slices). kind 4, kind 2 lit from either side (surfaces
 * seen from both, the isosurfaces). */
static const char *const view3d_fs =
    "#version 120\n"
    "varying vec4 v_p;\n"
    "varying float v_kind;\n"
    "varying vec4 v_col;\n"
    "const vec3 LIGHT = vec3(-0.39801, 0.59702, 0.69653);\n"
    "const vec3 HALFWAY = vec3(-0.21607, 0.32411, 0.92101);\n"
    "vec3 lit(vec3 base, vec3 n) {\n"
    "  float d = max(dot(n, LIGHT), 0.0);\n"
    "  float s = pow(max(dot(n, HALFWAY), 0.0), 40.0);\n"
    "  return min(base * (0.45 + 0.55 * d) + vec3(0.3 * s), vec3(1.0));\n"
    "}\n"
    "void main() {\n"
    "  vec3 rgb = v_col.rgb;\n"
    "  float depth = gl_FragCoord.z;\n"
    "  if (v_kind < 0.5) {\n"
    "    if (v_p.y > 0.0 && mod(v_p.x, 2.0 * v_p.y) >= v_p.y) discard;\n"
    "  } else if (v_kind < 1.5) {\n"
    "    float r2 = dot(v_p.xy, v_p.xy);\n"
    "    if (r2 > 1.0) discard;\n"
    "    float nz = sqrt(1.0 - r2);\n"
    "    depth -= v_p.z * nz;\n"
    "    if (v_p.w > 1.0) rgb = lit(v_col.rgb, vec3(v_p.xy, nz));\n"
    "    else if (r2 > v_p.w * v_p.w) rgb = v_col.rgb;\n"
    "    else rgb = lit(vec3(0.94), vec3(v_p.xy, nz));\n"
    "  } else if (v_kind < 2.5) {\n"
    "    rgb = lit(v_col.rgb, normalize(v_p.xyz));\n"
    "  } else if (v_kind > 3.5) {\n"
    "    vec3 n = normalize(v_p.xyz);\n"
    "    rgb = lit(v_col.rgb, n.z < 0.0 ? -n : n);\n"
    "  }\n"
    "  gl_FragDepth = depth;\n"
    "  gl_FragColor = vec4(rgb * v_col.a, v_col.a);\n"
    "}\n";

/* ---- geometry ------------------------------------------------------------ */

typedef struct geo {
    float *v;
    size_t n, cap;          /* vertices */
    int failed;
} geo;

typedef struct cam {
    const lr_view *v;
    double x0, y0;          /* the region's top-left, canvas pixels */
    double S;               /* samples per pixel along each axis */
    double zscale;          /* NDC depth per world unit */
    double eps;             /* NDC depth per layer, towards the viewer */
} cam;

static float *more(geo *g, size_t n)
{
    if (g->failed)
        return NULL;
    if (lu_reserve(&g->v, &g->cap, g->n + n, V3_FLOATS * sizeof *g->v, 1024) != 0) {
        g->failed = 1;
        return NULL;
    }
    float *f = g->v + g->n * V3_FLOATS;
    g->n += n;
    return f;
}

static void put(float *f, const double o[3], double p0, double p1, double p2,
                double p3, int kind, lr_rgba c)
{
    const double x[V3_FLOATS] = {o[0], o[1], o[2], p0, p1, p2, p3, kind,
                                 c.r, c.g, c.b, c.a};
    for (int i = 0; i < V3_FLOATS; i++)
        f[i] = (float)x[i];
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Distance of q towards the viewer from the view's centre. */
static double depth_of(const lr_view *v, const double q[3])
{
    const double d[3] = {q[0] - v->c[0], q[1] - v->c[1], q[2] - v->c[2]};
    return dot3(d, v->toward);
}

static void proj(const cam *k, const double q[3], int layer, double o[3])
{
    double x, y;
    lr_view_map(k->v, q, &x, &y);
    o[0] = (x - k->x0) * k->S;
    o[1] = (y - k->y0) * k->S;
    o[2] = -depth_of(k->v, q) * k->zscale - layer * k->eps;
}

/* A line between projected A and B, w pixels wide, dashed from `along`
 * pixels at A, its ends pushed out by ext pixels (closes joints). */
static void seg(geo *g, const cam *k, const double A[3], const double B[3], double w,
                double dash, double along, double ext, lr_rgba col)
{
    double dx = B[0] - A[0], dy = B[1] - A[1], len = hypot(dx, dy);
    if (!(len > 1e-9) || !(w > 0))
        return;
    double tx = dx / len, ty = dy / len, nx = -ty, ny = tx;
    double hw = 0.5 * w * k->S, e = ext * k->S, dz = (B[2] - A[2]) / len;
    const double a[3] = {A[0] - tx * e, A[1] - ty * e, A[2] - dz * e};
    const double b[3] = {B[0] + tx * e, B[1] + ty * e, B[2] + dz * e};
    double ua = along - ext, ub = along + len / k->S + ext;
    const double ap[3] = {a[0] + nx * hw, a[1] + ny * hw, a[2]};
    const double am[3] = {a[0] - nx * hw, a[1] - ny * hw, a[2]};
    const double bp[3] = {b[0] + nx * hw, b[1] + ny * hw, b[2]};
    const double bm[3] = {b[0] - nx * hw, b[1] - ny * hw, b[2]};
    float *f = more(g, 6);
    if (!f)
        return;
    put(f, ap, ua, dash, 0, 0, K_LINE, col);
    put(f + V3_FLOATS, am, ua, dash, 0, 0, K_LINE, col);
    put(f + 2 * V3_FLOATS, bp, ub, dash, 0, 0, K_LINE, col);
    put(f + 3 * V3_FLOATS, bp, ub, dash, 0, 0, K_LINE, col);
    put(f + 4 * V3_FLOATS, am, ua, dash, 0, 0, K_LINE, col);
    put(f + 5 * V3_FLOATS, bm, ub, dash, 0, 0, K_LINE, col);
}

static void world_seg(geo *g, const cam *k, const double a[3], const double b[3],
                      int layer, double w, double dash, double along, double ext,
                      lr_rgba col)
{
    double A[3], B[3];
    proj(k, a, layer, A);
    proj(k, b, layer, B);
    seg(g, k, A, B, w, dash, along, ext, col);
}

/* A sphere of r pixels at q; ring: where the ring starts (fraction of r),
 * > 1 for none. */
static void sphere(geo *g, const cam *k, const double q[3], int layer, double r,
                   double ring, lr_rgba col)
{
    if (!(r > 0))
        return;
    double o[3];
    proj(k, q, layer, o);
    double h = r * k->S, rz = 0.5 * (r / k->v->s) * k->zscale;
    const double c[4][2] = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}};   /* y up */
    static const int tri[6] = {0, 1, 2, 0, 2, 3};
    float *f = more(g, 6);
    if (!f)
        return;
    for (int i = 0; i < 6; i++) {
        const double *u = c[tri[i]];
        const double p[3] = {o[0] + u[0] * h, o[1] - u[1] * h, o[2]};
        put(f + i * V3_FLOATS, p, u[0], u[1], rz, ring, K_SPHERE, col);
    }
}

/* A world direction in view space (x right, y up, z towards the viewer). */
static void to_view(const lr_view *v, const double n[3], double o[3])
{
    o[0] = dot3(n, v->right);
    o[1] = dot3(n, v->up);
    o[2] = dot3(n, v->toward);
}

/* A shaded cone: its tip, the unit axis u from base to tip, length h and
 * base radius r (world units), with its base disc. */
static void cone(geo *g, const cam *k, const double tip[3], const double u[3],
                 double h, double r, int layer, lr_rgba col)
{
    /* e1, e2: a frame across the axis */
    int m = fabs(u[0]) <= fabs(u[1]) && fabs(u[0]) <= fabs(u[2]) ? 0
            : fabs(u[1]) <= fabs(u[2]) ? 1 : 2;
    double ax[3] = {0, 0, 0}, e1[3], e2[3];
    ax[m] = 1;
    e1[0] = u[1] * ax[2] - u[2] * ax[1];
    e1[1] = u[2] * ax[0] - u[0] * ax[2];
    e1[2] = u[0] * ax[1] - u[1] * ax[0];
    double l = sqrt(dot3(e1, e1));
    for (int a = 0; a < 3; a++)
        e1[a] /= l;
    e2[0] = u[1] * e1[2] - u[2] * e1[1];
    e2[1] = u[2] * e1[0] - u[0] * e1[2];
    e2[2] = u[0] * e1[1] - u[1] * e1[0];
    double sl = hypot(h, r), ca = h / sl, sa = r / sl;
    double base[3], T[3], Bc[3], down[3], nd[3];
    for (int a = 0; a < 3; a++) {
        base[a] = tip[a] - h * u[a];
        down[a] = -u[a];
    }
    proj(k, tip, layer, T);
    proj(k, base, layer, Bc);
    to_view(k->v, down, nd);
    float *f = more(g, 6 * CONE_SEGMENTS);
    if (!f)
        return;
    for (int i = 0; i < CONE_SEGMENTS; i++) {
        double t[3] = {TWO_PI * i / CONE_SEGMENTS, TWO_PI * (i + 0.5) / CONE_SEGMENTS,
                       TWO_PI * (i + 1) / CONE_SEGMENTS};
        double P[2][3], N[3][3];
        for (int j = 0; j < 3; j++) {
            double rad[3], n[3];
            for (int a = 0; a < 3; a++) {
                rad[a] = cos(t[j]) * e1[a] + sin(t[j]) * e2[a];
                n[a] = ca * rad[a] + sa * u[a];
            }
            to_view(k->v, n, N[j]);
            if (j != 1) {
                double q[3];
                for (int a = 0; a < 3; a++)
                    q[a] = base[a] + r * rad[a];
                proj(k, q, layer, P[j / 2]);
            }
        }
        float *s = f + 6 * i * V3_FLOATS;
        put(s, T, N[1][0], N[1][1], N[1][2], 0, K_LIT, col);
        put(s + V3_FLOATS, P[0], N[0][0], N[0][1], N[0][2], 0, K_LIT, col);
        put(s + 2 * V3_FLOATS, P[1], N[2][0], N[2][1], N[2][2], 0, K_LIT, col);
        put(s + 3 * V3_FLOATS, Bc, nd[0], nd[1], nd[2], 0, K_LIT, col);
        put(s + 4 * V3_FLOATS, P[1], nd[0], nd[1], nd[2], 0, K_LIT, col);
        put(s + 5 * V3_FLOATS, P[0], nd[0], nd[1], nd[2], 0, K_LIT, col);
    }
}

static void arrow(geo *g, const cam *k, const s3_item *it)
{
    const double *a = it->a;
    double u[3] = {it->b[0], it->b[1], it->b[2]}, tip[3], neck[3];
    double l = sqrt(dot3(u, u));
    if (!(l > 0) || !(it->length > 0))
        return;
    for (int i = 0; i < 3; i++)
        u[i] /= l;
    /* the head: a cone half as long again as the layers' flat head (a
     * smaller one shows no shading), at most 0.6 of the arrow */
    double h = fmin(HEAD_SCALE * it->head / k->v->s, 0.6 * it->length);
    for (int i = 0; i < 3; i++) {
        tip[i] = a[i] + it->length * u[i];
        neck[i] = tip[i] - 0.7 * h * u[i];     /* the shaft ends inside the cone */
    }
    world_seg(g, k, a, neck, it->layer, it->width, it->dash, 0.0, 0.0, it->colour);
    cone(g, k, tip, u, h, h * tan(S3_HEAD_ANGLE), it->layer, it->colour);
}

static void asterisk(geo *g, const cam *k, const s3_item *it)
{
    double o[3];
    proj(k, it->a, it->layer, o);
    double r = 0.5 * it->size * k->S;
    for (int j = 0; j < 3; j++) {
        double t = TWO_PI * (0.25 + j / 6.0);
        const double A[3] = {o[0] - r * cos(t), o[1] - r * sin(t), o[2]};
        const double B[3] = {o[0] + r * cos(t), o[1] + r * sin(t), o[2]};
        seg(g, k, A, B, it->width, 0.0, 0.0, 0.0, it->colour);
    }
}

/* The 12 edges; those behind both faces meeting there thinner and dashed,
 * as lr_layer_box draws them. */
static void box(geo *g, const cam *k, const s3_item *it)
{
    const double *lo = it->a, *hi = it->b;
    for (int e = 0; e < 3; e++) {
        int e1 = (e + 1) % 3, e2 = (e + 2) % 3;
        for (int s1 = 0; s1 < 2; s1++)
            for (int s2 = 0; s2 < 2; s2++) {
                double a[3], b[3];
                a[e] = lo[e];
                b[e] = hi[e];
                a[e1] = b[e1] = s1 ? hi[e1] : lo[e1];
                a[e2] = b[e2] = s2 ? hi[e2] : lo[e2];
                int hidden = !s3_facing(k->v, e1, s1) && !s3_facing(k->v, e2, s2);
                world_seg(g, k, a, b, it->layer, hidden ? 0.6 * it->width : it->width,
                          hidden ? 4.0 : 0.0, 0.0, hidden ? 0.0 : 0.5 * it->width,
                          it->colour);
            }
    }
}

/* A polyline; the dashes run on along it. */
static void polyline(geo *g, const cam *k, const lr_scene3d *s, const s3_item *it)
{
    const double *q = s->pts + 3 * it->first;
    double along = 0;
    for (size_t i = 0; i + 1 < it->count; i++, q += 3) {
        double A[3], B[3];
        proj(k, q, it->layer, A);
        proj(k, q + 3, it->layer, B);
        seg(g, k, A, B, it->width, it->dash, along, it->dash > 0 ? 0.0 : 0.25 * it->width,
            it->colour);
        along += hypot(B[0] - A[0], B[1] - A[1]) / k->S;
    }
}

/* The largest |depth| of anything in the scene, for the depth range. */
static double depth_extent(const lr_view *v, const lr_scene3d *s)
{
    double m = 0;
    for (size_t i = 0; i < s->n; i++) {
        const s3_item *it = &s->items[i];
        double r = 0, q[3];
        switch (it->kind) {
        case S3_POLYLINE:
            for (size_t j = 0; j < it->count; j++)
                m = fmax(m, fabs(depth_of(v, s->pts + 3 * (it->first + j))));
            continue;
        case S3_BOX:
            for (int c = 0; c < 8; c++) {
                for (int a = 0; a < 3; a++)
                    q[a] = (c >> a) & 1 ? it->b[a] : it->a[a];
                m = fmax(m, fabs(depth_of(v, q)));
            }
            continue;
        case S3_LINE:
            m = fmax(m, fabs(depth_of(v, it->b)));
            break;
        case S3_ARROW: {
            double l = sqrt(dot3(it->b, it->b));
            for (int a = 0; a < 3; a++)
                q[a] = it->a[a] + it->length * it->b[a] / l;
            m = fmax(m, fabs(depth_of(v, q)));
            break;
        }
        case S3_CIRCLE:
        case S3_DOT:
            r = it->size / v->s;
            break;
        case S3_CLOUD:
            for (size_t j = it->first; j < it->first + it->count; j++) {
                const float *f = s->cloud + 3 * j;
                const double w[3] = {f[0], f[1], f[2]};
                m = fmax(m, fabs(depth_of(v, w)) + it->size / v->s);
            }
            continue;
        case S3_TRIS:
            for (size_t j = it->first; j < it->first + it->count; j++) {
                const float *f = s->tri + S3_TRI_FLOATS * j;
                const double w[3] = {f[0], f[1], f[2]};
                m = fmax(m, fabs(depth_of(v, w)));
            }
            continue;
        default:
            break;
        }
        m = fmax(m, fabs(depth_of(v, it->a)) + r);
    }
    return m;
}

/* Triangles of item it: the opaque ones into g, the see-through ones
 * into t (sorted later, far first). */
static void tris(geo *g, geo *t, const cam *k, const lr_scene3d *s, const s3_item *it)
{
    for (size_t m = 0; m + 2 < it->count; m += 3) {
        const float *f = s->tri + S3_TRI_FLOATS * (it->first + m);
        int clear = f[9] < 1 || f[S3_TRI_FLOATS + 9] < 1 || f[2 * S3_TRI_FLOATS + 9] < 1;
        float *o = more(clear ? t : g, 3);
        if (!o)
            return;
        for (int j = 0; j < 3; j++) {
            const float *q = f + S3_TRI_FLOATS * j;
            const double w[3] = {q[0], q[1], q[2]}, n[3] = {q[3], q[4], q[5]};
            double P[3], N[3] = {0, 0, 1};
            proj(k, w, it->layer, P);
            if (it->lit)
                to_view(k->v, n, N);
            lr_rgba c = {q[6], q[7], q[8], q[9]};
            put(o + j * V3_FLOATS, P, N[0], N[1], N[2], 0, it->lit ? K_LIT2 : K_FLAT, c);
        }
    }
}

typedef struct far_key {
    float z;
    size_t k;
} far_key;

static int far_first(const void *a, const void *b)
{
    const far_key *x = a, *y = b;
    if (x->z != y->z)
        return x->z > y->z ? -1 : 1;
    return x->k < y->k ? -1 : x->k > y->k;
}

/* The see-through triangles far first (larger NDC depth first), so that
 * OVER composes them in order. */
static int sort_far_first(geo *t)
{
    size_t n = t->n / 3;
    if (n < 2)
        return 0;
    far_key *key = malloc(n * sizeof *key);
    float *v = malloc(t->n * V3_FLOATS * sizeof *v);
    if (!key || !v) {
        free(key);
        free(v);
        return -1;
    }
    for (size_t k = 0; k < n; k++) {
        const float *f = t->v + 3 * k * V3_FLOATS;
        key[k].z = f[2] + f[V3_FLOATS + 2] + f[2 * V3_FLOATS + 2];
        key[k].k = k;
    }
    qsort(key, n, sizeof *key, far_first);
    for (size_t k = 0; k < n; k++)
        memcpy(v + 3 * k * V3_FLOATS, t->v + 3 * key[k].k * V3_FLOATS,
               3 * V3_FLOATS * sizeof *v);
    free(t->v);
    t->v = v;
    t->cap = t->n;
    free(key);
    return 0;
}

static int build(geo *g, geo *t, const cam *k, const lr_scene3d *s)
{
    for (size_t i = 0; i < s->n; i++) {
        const s3_item *it = &s->items[i];
        switch (it->kind) {
        case S3_LINE:
            world_seg(g, k, it->a, it->b, it->layer, it->width, it->dash, 0.0, 0.0,
                      it->colour);
            break;
        case S3_POLYLINE:
            polyline(g, k, s, it);
            break;
        case S3_ARROW:
            arrow(g, k, it);
            break;
        case S3_CIRCLE:
            sphere(g, k, it->a, it->layer, it->size,
                   it->size > 0 ? fmax(0.0, 1.0 - it->width / it->size) : 2.0, it->colour);
            break;
        case S3_DOT:
            sphere(g, k, it->a, it->layer, it->size, 2.0, it->colour);
            break;
        case S3_ASTERISK:
            asterisk(g, k, it);
            break;
        case S3_BOX:
            box(g, k, it);
            break;
        case S3_TRIS:
            tris(g, t, k, s, it);
            break;
        case S3_TEXT:
        case S3_CLOUD:      /* splatted on the CPU (view3d_cloud.c) */
            break;
        }
    }
    if (g->failed || t->failed || sort_far_first(t) != 0)
        return -1;
    return 0;
}

/* ---- OpenGL ---------------------------------------------------------------- */

static int program(gl_canvas *c, char *err, size_t errlen)
{
    if (c->gl.view3d_prog)
        return 0;
    static const char *const attr[] = {"a_pos", "a_p", "a_kind", "a_col"};
    static const GLuint loc[] = {A_POS, A_P, A_KIND, A_COL};
    c->gl.view3d_prog = gl_link(view3d_vs, view3d_fs, attr, loc, 4, err, errlen);
    if (!c->gl.view3d_prog)
        return -1;
    c->gl.view3d_size = glGetUniformLocation(c->gl.view3d_prog, "u_size");
    return 0;
}

/* Draws g into a new W x H framebuffer with depth, reads it back (rows
 * bottom-up, premultiplied); NULL with a message on failure. */
static void draw_geo(const geo *g)
{
    const GLsizei stride = V3_FLOATS * sizeof(float);
    glVertexAttribPointer(A_POS, 3, GL_FLOAT, GL_FALSE, stride, g->v);
    glVertexAttribPointer(A_P, 4, GL_FLOAT, GL_FALSE, stride, g->v + 3);
    glVertexAttribPointer(A_KIND, 1, GL_FLOAT, GL_FALSE, stride, g->v + 7);
    glVertexAttribPointer(A_COL, 4, GL_FLOAT, GL_FALSE, stride, g->v + 8);
    if (g->n)
        glDrawArrays(GL_TRIANGLES, 0, (GLsizei)g->n);
}

/* The clouds' splats (view3d_cloud.c) as the framebuffer's first
 * content: their depth, then their colour. */
static void draw_splats(const unsigned char *rgba, const float *depth, int W, int H)
{
    glUseProgram(0);        /* pixels as they are, not through a canvas shader */
    glWindowPos2i(0, 0);
    glDepthFunc(GL_ALWAYS);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDrawPixels(W, H, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glDrawPixels(W, H, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
}

static unsigned char *render(gl_canvas *c, const geo *g, const geo *t,
                             const unsigned char *splat_rgba, const float *splat_depth,
                             int W, int H, char *err, size_t errlen)
{
    GLuint fbo = 0, rb[2] = {0, 0};
    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(2, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, W, H);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, W, H);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              rb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                              rb[1]);
    unsigned char *px = NULL;
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        snprintf(err, errlen, "3D view: OpenGL cannot make a %dx%d framebuffer", W, H);
    } else {
        GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
        glDisable(GL_SCISSOR_TEST);
        glViewport(0, 0, W, H);
        glClearColor(0, 0, 0, 0);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glDepthMask(GL_TRUE);
        if (splat_rgba)
            draw_splats(splat_rgba, splat_depth, W, H);
        glUseProgram(c->gl.view3d_prog);
        glUniform2f(c->gl.view3d_size, (float)W, (float)H);
        glEnableVertexAttribArray(A_POS);
        glEnableVertexAttribArray(A_P);
        glEnableVertexAttribArray(A_KIND);
        glEnableVertexAttribArray(A_COL);
        draw_geo(g);
        if (t->n) {     /* see-through, far first, hiding nothing */
            glDepthMask(GL_FALSE);
            draw_geo(t);
            glDepthMask(GL_TRUE);
        }
        glDisableVertexAttribArray(A_POS);
        glDisableVertexAttribArray(A_P);
        glDisableVertexAttribArray(A_KIND);
        glDisableVertexAttribArray(A_COL);
        glUseProgram(0);
        glDisable(GL_DEPTH_TEST);
        px = malloc(4 * (size_t)W * (size_t)H);
        if (px)
            glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
        else
            snprintf(err, errlen, "3D view: out of memory");
        if (scissor)
            glEnable(GL_SCISSOR_TEST);
        glViewport(-c->pad, -c->pad, c->base.width + 2 * c->pad,
                   c->base.height + 2 * c->pad);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, c->fbo);   /* the canvas (0 under OSMesa) */
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(2, rb);
    return px;
}

/* S x S blocks averaged, rounded: w x h from (w S) x (h S), in place-free. */
static void downsample(const unsigned char *ss, unsigned char *out, int w, int h, int S)
{
    size_t W = (size_t)w * (size_t)S;
    unsigned n = (unsigned)(S * S);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            unsigned sum[4] = {0, 0, 0, 0};
            for (int j = 0; j < S; j++) {
                const unsigned char *p = ss + 4 * (((size_t)y * S + j) * W + (size_t)x * S);
                for (int i = 0; i < S; i++, p += 4)
                    for (int k = 0; k < 4; k++)
                        sum[k] += p[k];
            }
            unsigned char *o = out + 4 * ((size_t)y * w + x);
            for (int k = 0; k < 4; k++)
                o[k] = (unsigned char)((sum[k] + n / 2) / n);
        }
}

int gl_view3d(lr_canvas *base, const lr_view *v, const lr_scene3d *s, char *err,
              size_t errlen)
{
    gl_canvas *c = glc(base);
    char dummy[8];
    if (!err || errlen == 0) {
        err = dummy;
        errlen = sizeof dummy;
    }
    /* the region: the view's clip rectangle, whole pixels, on the canvas */
    double r0 = 0, r1 = 0, r2 = base->width, r3 = base->height;
    if (v->clip[2] > v->clip[0]) {
        r0 = fmax(r0, floor(v->clip[0]));
        r1 = fmax(r1, floor(v->clip[1]));
        r2 = fmin(r2, ceil(v->clip[2]));
        r3 = fmin(r3, ceil(v->clip[3]));
    }
    if (!(r2 > r0 && r3 > r1) || s->n == 0)
        return 0;
    int x0 = (int)r0, y0 = (int)r1, w = (int)(r2 - r0), h = (int)(r3 - r1);
    gl_flush(c);            /* makes the context current, draws what is pending */
    GLint maxrb = 0, vp[2] = {0, 0};
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxrb);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, vp);
    int lim = maxrb < vp[0] ? maxrb : vp[0];
    lim = lim < vp[1] ? lim : vp[1];
    int S = SUPERSAMPLE;
    /* clouds: their buffers (8 bytes a sample more), and few enough
     * samples to splat in time (CLOUD_SAMPLES) */
    int clouds = s->ncloud > 0;
    double bytes = clouds ? 20.0 : 12.0;
    while (S > 1 && ((double)S * w > lim || (double)S * h > lim ||
                     bytes * S * S * (double)w * h > SS_MAX_BYTES ||
                     (clouds && (s3_cloud_samples(s, S) > CLOUD_SAMPLES ||
                                 (double)S * S * w * h > CLOUD_BUFFER))))
        S--;
    if (w > lim || h > lim) {
        snprintf(err, errlen, "3D view: %dx%d pixels is more than OpenGL draws (%d)", w,
                 h, lim);
        return -1;
    }
    double dmax = depth_extent(v, s);
    if (!(dmax > 0) || !isfinite(dmax))
        dmax = 1.0;
    cam k = {v, x0, y0, S, 0.9 / dmax, fmin(1e-4, 0.05 / (s->layers + 1))};
    geo g = {NULL, 0, 0, 0}, t = {NULL, 0, 0, 0};
    if (build(&g, &t, &k, s) != 0) {
        free(g.v);
        free(t.v);
        snprintf(err, errlen, "3D view: out of memory");
        return -1;
    }
    if (program(c, err, errlen) != 0) {
        free(g.v);
        free(t.v);
        c->failed = 1;
        return -1;
    }
    unsigned char *srgba = NULL;
    float *sdepth = NULL;
    if (clouds) {
        size_t N = (size_t)S * w * (size_t)S * h;
        srgba = malloc(4 * N);
        sdepth = malloc(N * sizeof *sdepth);
        if (!srgba || !sdepth) {
            free(g.v);
            free(t.v);
            free(srgba);
            free(sdepth);
            snprintf(err, errlen, "3D view: out of memory");
            return -1;
        }
        s3_cloud_raster(v, s, x0, y0, S, k.zscale, k.eps, S * w, S * h, srgba, sdepth);
    }
    unsigned char *ss = render(c, &g, &t, srgba, sdepth, S * w, S * h, err, errlen);
    free(g.v);
    free(t.v);
    free(srgba);
    free(sdepth);
    unsigned char *img = ss ? malloc(4 * (size_t)w * (size_t)h) : NULL;
    if (!img) {
        if (ss)
            snprintf(err, errlen, "3D view: out of memory");
        free(ss);
        return -1;
    }
    downsample(ss, img, w, h, S);
    free(ss);
    /* premultiplied OVER, as every drawing on the canvas; rows bottom-up
     * from the region's bottom edge (GL counts rows from the bottom) */
    glWindowPos2i(x0, base->height - (y0 + h));
    glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, img);
    free(img);
    if (glGetError() != GL_NO_ERROR) {
        c->failed = 1;
        snprintf(err, errlen, "3D view: OpenGL reported an error");
        return -1;
    }
    return 0;
}
