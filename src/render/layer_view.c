/* layer_view.c - world to pixels: a 2D window fit, or an orthographic
 * projection of a 3D box (the unit cube of [N] Figs 5 and 11). */
#include <math.h>

#include "layers.h"

#define DEG 0.017453292519943295769

void lr_view_2d(lr_view *v, double px, double py, double pw, double ph,
                double wx0, double wy0, double wx1, double wy1)
{
    double ww = wx1 - wx0, wh = wy1 - wy0;
    v->is3d = 0;
    v->persp = 0.0;
    v->clip[0] = v->clip[1] = v->clip[2] = v->clip[3] = 0.0;
    v->s = fmin(pw / ww, ph / wh);
    if (!(v->s > 0) || !isfinite(v->s))
        v->s = 1.0;
    v->ox = px + 0.5 * (pw - v->s * ww) - v->s * wx0;
    v->oy = py + 0.5 * (ph - v->s * wh) + v->s * wy1;
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void lr_view_3d(lr_view *v, double px, double py, double pw, double ph,
                const double lo[3], const double hi[3], double azimuth,
                double elevation)
{
    double a = azimuth * DEG, e = elevation * DEG;
    v->is3d = 1;
    v->persp = 0.0;
    v->clip[0] = v->clip[1] = v->clip[2] = v->clip[3] = 0.0;
    v->toward[0] = cos(e) * cos(a);
    v->toward[1] = cos(e) * sin(a);
    v->toward[2] = sin(e);
    v->right[0] = -sin(a);
    v->right[1] = cos(a);
    v->right[2] = 0.0;
    v->up[0] = -sin(e) * cos(a);
    v->up[1] = -sin(e) * sin(a);
    v->up[2] = cos(e);
    for (int k = 0; k < 3; k++)
        v->c[k] = 0.5 * (lo[k] + hi[k]);
    /* the projected box's extent around c sets the scale */
    double rx = 0, ry = 0;
    for (int corner = 0; corner < 8; corner++) {
        double p[3];
        for (int k = 0; k < 3; k++)
            p[k] = ((corner >> k) & 1 ? hi[k] : lo[k]) - v->c[k];
        rx = fmax(rx, fabs(dot3(p, v->right)));
        ry = fmax(ry, fabs(dot3(p, v->up)));
    }
    v->s = fmin(pw / (2 * rx), ph / (2 * ry));
    if (!(v->s > 0) || !isfinite(v->s))
        v->s = 1.0;
    v->ox = px + 0.5 * pw;
    v->oy = py + 0.5 * ph;
}

void lr_view_map(const lr_view *v, const double p[3], double *x, double *y)
{
    if (!v->is3d) {
        *x = v->ox + v->s * p[0];
        *y = v->oy - v->s * p[1];
        return;
    }
    double q[3] = {p[0] - v->c[0], p[1] - v->c[1], p[2] - v->c[2]};
    double k = v->s;
    if (v->persp > 0) {
        /* a pinhole at the eye: what is nearer is larger; points at or
         * behind the eye are put far off the picture */
        double d = v->persp - dot3(q, v->toward);
        k = d > 1e-9 * v->persp ? v->s * v->persp / d : v->s * 1e9;
    }
    *x = v->ox + k * dot3(q, v->right);
    *y = v->oy - k * dot3(q, v->up);
}

void lr_view_clip(lr_view *v, double x0, double y0, double x1, double y1)
{
    v->clip[0] = x0;
    v->clip[1] = y0;
    v->clip[2] = x1;
    v->clip[3] = y1;
}

/* Liang & Barsky (1984): the parameter range of a + t (b - a) inside the
 * rectangle, one edge at a time. */
void lr_view_line(lr_canvas *c, const lr_view *v, double ax, double ay, double bx,
                  double by, double width, lr_rgba colour, double dash)
{
    if (v->clip[2] > v->clip[0]) {
        double dx = bx - ax, dy = by - ay, t0 = 0.0, t1 = 1.0;
        double p[4] = {-dx, dx, -dy, dy};
        double q[4] = {ax - v->clip[0], v->clip[2] - ax, ay - v->clip[1], v->clip[3] - ay};
        for (int k = 0; k < 4; k++) {
            if (p[k] == 0.0) {
                if (q[k] < 0.0)
                    return;
                continue;
            }
            double t = q[k] / p[k];
            if (p[k] < 0.0) {
                if (t > t1)
                    return;
                if (t > t0)
                    t0 = t;
            } else {
                if (t < t0)
                    return;
                if (t < t1)
                    t1 = t;
            }
        }
        double x0 = ax + t0 * dx, y0 = ay + t0 * dy;
        bx = ax + t1 * dx;
        by = ay + t1 * dy;
        ax = x0;
        ay = y0;
    }
    lr_canvas_line(c, ax, ay, bx, by, width, colour, dash);
}

void lr_view_offset(lr_view *v, double dx, double dy)
{
    v->ox += dx;
    v->oy += dy;
    if (v->clip[2] > v->clip[0]) {
        v->clip[0] += dx;
        v->clip[1] += dy;
        v->clip[2] += dx;
        v->clip[3] += dy;
    }
}

/* Axis names off the data (issue 16 item 3; docs/gallery.md, "Legibility
 * checklist" 5): an edge of the box lies on the outline of its projection
 * when exactly one of the two faces meeting there faces the viewer. Of an
 * axis's four edges such an outline edge is taken - the lower one on the
 * screen for x and y, the left one for z, as plots put their axis names -
 * and the name goes beside its middle, away from the box's centre. */
void lr_view_axis_places(const lr_view *v, const double lo[3], const double hi[3],
                         double at[3][3], double out[3][2])
{
    double mid[3] = { 0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2]) };
    double cx, cy;
    lr_view_map(v, mid, &cx, &cy);
    for (int a = 0; a < 3; a++) {
        int b = (a + 1) % 3, c = (a + 2) % 3;
        double best = -INFINITY;
        for (int k = 0; k < 4; k++) {
            int sb = k & 1, sc = k >> 1;        /* 0: the lo side, 1: the hi side */
            /* a face's outward normal is -e or +e: visible when it points
             * towards the viewer */
            int vis_b = (sb ? v->toward[b] : -v->toward[b]) > 1e-9;
            int vis_c = (sc ? v->toward[c] : -v->toward[c]) > 1e-9;
            double q[3];
            q[a] = mid[a];
            q[b] = sb ? hi[b] : lo[b];
            q[c] = sc ? hi[c] : lo[c];
            double x, y;
            lr_view_map(v, q, &x, &y);
            /* outline edges first; then lowest (x, y) or leftmost (z) */
            double score = (vis_b != vis_c ? 1e9 : 0.0) + (a < 2 ? y : -x);
            if (score > best) {
                best = score;
                at[a][0] = q[0];
                at[a][1] = q[1];
                at[a][2] = q[2];
                double dx = x - cx, dy = y - cy, len = hypot(dx, dy);
                out[a][0] = len > 1e-9 ? dx / len : (a < 2 ? 0.0 : -1.0);
                out[a][1] = len > 1e-9 ? dy / len : (a < 2 ? 1.0 : 0.0);
            }
        }
    }
}
