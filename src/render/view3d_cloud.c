/* view3d_cloud.c - many points as shaded spheres (view3d.h,
 * lr_scene3d_cloud): splatted on the CPU for the OpenGL path (cairo's
 * discs, far ones first, are view3d_sort.c's).
 *
 * Why the CPU: llvmpipe spends about a quarter of a microsecond on every
 * primitive whatever its size (canvas_gl_dense.c measured it), so 10^6
 * impostor spheres cost a quarter of a second before a pixel is shaded -
 * above issue 34's 150 ms for a 3D frame of 10^6 points. A sphere of a
 * pixel or two is a handful of samples; the loop below visits each once
 * (a few nanoseconds), writes the nearest into a colour and a depth
 * buffer, and canvas_gl_view3d.c hands both to OpenGL before the rest of
 * the scene is drawn with the depth test - so arrows, isosurfaces and
 * boxes are hidden by particles in front of them and hide those behind,
 * exactly as with the impostors. The shading, the depth of the sphere's
 * surface and the tie rule (a later layer wins) are the shader's
 * (canvas_gl_view3d.c), done in double precision in a fixed order:
 * deterministic. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "view3d_internal.h"

double s3_cloud_samples(const lr_scene3d *s, double S)
{
    double n = 0;
    for (size_t i = 0; s && i < s->n; i++) {
        const s3_item *it = &s->items[i];
        if (it->kind != S3_CLOUD)
            continue;
        double R = it->size * S + 0.5;
        n += (double)it->count * 3.14159265358979 * R * R;
    }
    return n;
}

/* h^40 by squaring (the shader's pow(h, 40)) */
static double pow40(double h)
{
    double h2 = h * h, h4 = h2 * h2, h8 = h4 * h4, h16 = h8 * h8, h32 = h16 * h16;
    return h32 * h8;
}

static void splat(uint32_t rgba, double R, double rz,
                  double sx, double sy, double wz, int W, int H, unsigned char *px,
                  float *depth)
{
    static const double L[3] = {-0.39801, 0.59702, 0.69653};
    static const double Hh[3] = {-0.21607, 0.32411, 0.92101};
    double a = (double)(rgba >> 24) / 255.0;
    if (a <= 0)
        return;
    /* the colour premultiplied, in units of 1/255 */
    double base[3] = {(double)(rgba & 255) * a, (double)((rgba >> 8) & 255) * a,
                      (double)((rgba >> 16) & 255) * a};
    double top = 255.0 * a, spec_k = 0.3 * top;
    unsigned char alpha = (unsigned char)(rgba >> 24);
    int j0 = (int)ceil(sy - R - 0.5), j1 = (int)floor(sy + R - 0.5);
    int i0 = (int)ceil(sx - R - 0.5), i1 = (int)floor(sx + R - 0.5);
    if (j0 < 0)
        j0 = 0;
    if (i0 < 0)
        i0 = 0;
    if (j1 > H - 1)
        j1 = H - 1;
    if (i1 > W - 1)
        i1 = W - 1;
    double inv = 1.0 / R;
    float front = (float)(wz - rz);
    for (int j = j0; j <= j1; j++) {
        double dy = (j + 0.5 - sy) * inv;        /* screen y down */
        size_t row = (size_t)(H - 1 - j) * (size_t)W;
        for (int i = i0; i <= i1; i++) {
            double dx = (i + 0.5 - sx) * inv;
            double r2 = dx * dx + dy * dy;
            size_t k = row + (size_t)i;
            /* hidden even at the sphere's nearest point: no root needed */
            if (r2 > 1.0 || !(front <= depth[k]))
                continue;
            double nz = sqrt(1.0 - r2);
            float d = (float)(wz - rz * nz);
            if (!(d <= depth[k]))
                continue;
            depth[k] = d;
            /* the shader's lit(): n = (dx, -dy, nz) in view space, y up */
            double dd = dx * L[0] - dy * L[1] + nz * L[2];
            double hh = dx * Hh[0] - dy * Hh[1] + nz * Hh[2];
            double spec = spec_k * pow40(hh > 0 ? hh : 0);
            double diff = 0.45 + 0.55 * (dd > 0 ? dd : 0);
            unsigned char *o = px + 4 * k;
            for (int c = 0; c < 3; c++) {
                double x = base[c] * diff + spec;   /* min(lit, 1) a, x 255 */
                x = x < top ? x : top;
                o[c] = (unsigned char)(x + 0.5);
            }
            o[3] = alpha;
        }
    }
}

int s3_cloud_raster(const lr_view *v, const lr_scene3d *s, double x0, double y0, double S,
                    double zscale, double eps, int W, int H, unsigned char *rgba,
                    float *depth)
{
    size_t N = (size_t)W * (size_t)H;
    memset(rgba, 0, 4 * N);
    for (size_t k = 0; k < N; k++)
        depth[k] = 1.0f;
    for (size_t i = 0; i < s->n; i++) {
        const s3_item *it = &s->items[i];
        if (it->kind != S3_CLOUD)
            continue;
        double R = it->size * S;
        double rz = 0.5 * (it->size / v->s) * zscale;
        for (size_t m = it->first; m < it->first + it->count; m++) {
            const float *f = s->cloud + 3 * m;
            const double q[3] = {f[0], f[1], f[2]};
            double x, y, dep;
            if (v->persp > 0) {
                lr_view_map(v, q, &x, &y);
                dep = (q[0] - v->c[0]) * v->toward[0] + (q[1] - v->c[1]) * v->toward[1] +
                      (q[2] - v->c[2]) * v->toward[2];
            } else {    /* lr_view_map's orthographic case, inline */
                const double d[3] = {q[0] - v->c[0], q[1] - v->c[1], q[2] - v->c[2]};
                x = v->ox + v->s * (d[0] * v->right[0] + d[1] * v->right[1] + d[2] * v->right[2]);
                y = v->oy - v->s * (d[0] * v->up[0] + d[1] * v->up[1] + d[2] * v->up[2]);
                dep = d[0] * v->toward[0] + d[1] * v->toward[1] + d[2] * v->toward[2];
            }
            double ndc = -dep * zscale - it->layer * eps;
            splat(s->cloud_rgba[m], R, rz, (x - x0) * S, (y - y0) * S,
                  0.5 * ndc + 0.5, W, H, rgba, depth);
        }
    }
    return 0;
}
