/* layer_glyphs.c - the marks of the normals figures ([N] Figs 3-11):
 * membrane points as open circles, the random point as an asterisk,
 * computed normals as solid arrows and exact normals dashed, the element
 * (a rectangle, or a cube in 3D) - all from lines, clipped to the view. */
#include <math.h>

#include "layers.h"

#define TWO_PI 6.283185307179586476925286766559
#define CIRCLE_SEGMENTS 28
#define HEAD_ANGLE 0.4363323129985824   /* 25 degrees */

static void point_at(const double *const p[3], int dim, size_t i, double q[3])
{
    q[0] = p[0][i];
    q[1] = p[1][i];
    q[2] = dim == 3 ? p[2][i] : 0.0;
}

/* A segment with its ends pushed out by `ext` pixels (closes joints). */
static void line_ext(lr_canvas *c, const lr_view *v, double ax, double ay, double bx,
                     double by, double width, lr_rgba k, double dash, double ext)
{
    double len = hypot(bx - ax, by - ay);
    if (len > 0 && ext > 0) {
        double ex = ext * (bx - ax) / len, ey = ext * (by - ay) / len;
        ax -= ex;
        ay -= ey;
        bx += ex;
        by += ey;
    }
    lr_view_line(c, v, ax, ay, bx, by, width, k, dash);
}

void lr_layer_circles(lr_canvas *c, const lr_view *v, size_t n, int dim,
                      const double *const p[3], double radius_px, double width,
                      lr_rgba colour)
{
    for (size_t i = 0; i < n; i++) {
        double q[3], x, y;
        point_at(p, dim, i, q);
        lr_view_map(v, q, &x, &y);
        for (int k = 0; k < CIRCLE_SEGMENTS; k++) {
            double a0 = TWO_PI * k / CIRCLE_SEGMENTS;
            double a1 = TWO_PI * (k + 1) / CIRCLE_SEGMENTS;
            line_ext(c, v, x + radius_px * cos(a0), y + radius_px * sin(a0),
                     x + radius_px * cos(a1), y + radius_px * sin(a1), width,
                     colour, 0.0, 0.25 * width);
        }
    }
}

void lr_layer_dots(lr_canvas *c, const lr_view *v, size_t n, int dim,
                   const double *const p[3], double radius_px, lr_rgba colour)
{
    for (size_t i = 0; i < n; i++) {
        double q[3], x, y;
        point_at(p, dim, i, q);
        lr_view_map(v, q, &x, &y);
        lr_canvas_discs(c, 1, &x, &y, radius_px, &colour);
    }
}

void lr_layer_asterisk(lr_canvas *c, const lr_view *v, const double p[3],
                       double size_px, double width, lr_rgba colour)
{
    double x, y, r = 0.5 * size_px;
    lr_view_map(v, p, &x, &y);
    for (int k = 0; k < 3; k++) {
        double a = TWO_PI * (0.25 + k / 6.0);
        lr_view_line(c, v, x - r * cos(a), y - r * sin(a), x + r * cos(a),
                     y + r * sin(a), width, colour, 0.0);
    }
}

void lr_layer_arrows(lr_canvas *c, const lr_view *v, size_t n, int dim,
                     const double *const p[3], const double *const d[3],
                     double length, double width, double head_px,
                     lr_rgba colour, double dash)
{
    for (size_t i = 0; i < n; i++) {
        double a[3], u[3], b[3], ax, ay, bx, by;
        point_at(p, dim, i, a);
        point_at(d, dim, i, u);
        if (u[0] == 0 && u[1] == 0 && u[2] == 0)
            continue;
        for (int k = 0; k < 3; k++)
            b[k] = a[k] + length * u[k];
        lr_view_map(v, a, &ax, &ay);
        lr_view_map(v, b, &bx, &by);
        double len = hypot(bx - ax, by - ay);
        if (!(len > 0))
            continue;
        lr_view_line(c, v, ax, ay, bx, by, width, colour, dash);
        double h = fmin(head_px, 0.6 * len);
        double ux = (ax - bx) / len, uy = (ay - by) / len;
        for (int s = -1; s <= 1; s += 2) {
            double ca = cos(HEAD_ANGLE), sa = s * sin(HEAD_ANGLE);
            double hx = ux * ca - uy * sa, hy = ux * sa + uy * ca;
            line_ext(c, v, bx, by, bx + h * hx, by + h * hy, width, colour, 0.0,
                     0.5 * width);
        }
    }
}

void lr_layer_polyline(lr_canvas *c, const lr_view *v, size_t n, int dim,
                       const double *const p[3], double width, lr_rgba colour,
                       double dash)
{
    for (size_t i = 0; i + 1 < n; i++) {
        double a[3], b[3], ax, ay, bx, by;
        point_at(p, dim, i, a);
        point_at(p, dim, i + 1, b);
        lr_view_map(v, a, &ax, &ay);
        lr_view_map(v, b, &bx, &by);
        line_ext(c, v, ax, ay, bx, by, width, colour, dash,
                 dash > 0 ? 0.0 : 0.25 * width);
    }
}

/* 3D: is the face of the box with outward normal +-e_axis facing us? */
static int facing(const lr_view *v, int axis, int high)
{
    double t = v->toward[axis];
    return high ? t > 0 : t < 0;
}

void lr_layer_box(lr_canvas *c, const lr_view *v, const double lo[3],
                  const double hi[3], double width, lr_rgba colour)
{
    if (!v->is3d) {
        double ax, ay, bx, by;
        double a[3] = {lo[0], lo[1], 0}, b[3] = {hi[0], hi[1], 0};
        lr_view_map(v, a, &ax, &ay);
        lr_view_map(v, b, &bx, &by);
        lr_canvas_rect(c, fmin(ax, bx), fmin(ay, by), fabs(bx - ax),
                       fabs(by - ay), width, colour);
        return;
    }
    /* an edge along axis k at fixed sides (s1, s2) of the other two axes
     * is hidden when neither face meeting there faces the viewer */
    for (int k = 0; k < 3; k++) {
        int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        for (int s1 = 0; s1 < 2; s1++)
            for (int s2 = 0; s2 < 2; s2++) {
                double a[3], b[3], ax, ay, bx, by;
                a[k] = lo[k];
                b[k] = hi[k];
                a[k1] = b[k1] = s1 ? hi[k1] : lo[k1];
                a[k2] = b[k2] = s2 ? hi[k2] : lo[k2];
                int hidden = !facing(v, k1, s1) && !facing(v, k2, s2);
                lr_view_map(v, a, &ax, &ay);
                lr_view_map(v, b, &bx, &by);
                line_ext(c, v, ax, ay, bx, by, hidden ? 0.6 * width : width,
                         colour, hidden ? 4.0 : 0.0, hidden ? 0.0 : 0.5 * width);
            }
    }
}
