/* canvas_gl_draw.c - lines and discs in GL.
 *
 * Lines are quads one pixel wider than the stroke on every side, their
 * vertices carrying the distance across and along the line; the fragment
 * shader box-filters those into coverage (exact for lines on the pixel
 * grid, so 1-px grid lines are as crisp as cairo's) and cuts the dashes.
 * Discs are point sprites whose shader knows each pixel's distance to the
 * centre (canvas_gl_shaders.c). */
#include "canvas_gl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void gl_line_quad(gl_canvas *c, double ax, double ay, double bx, double by,
                      double hw, double dash, enum lrgl_mode mode, lr_rgba k)
{
    double dx = bx - ax, dy = by - ay, len = hypot(dx, dy);
    if (!(len > 1e-9))
        return;     /* butt caps: a zero-length line draws nothing (cairo too) */
    double ux = dx / len, uy = dy / len, nx = -uy, ny = ux;
    double e = hw + 1.0;     /* room for the antialiased rim */
    float *v = gl_shape_verts(c, 6);
    if (!v)
        return;
    /* corners: (along, across) = (-1, -e), (len+1, -e), (len+1, e), (-1, e) */
    double s[4] = { -1.0, len + 1.0, len + 1.0, -1.0 };
    double t[4] = { -e, -e, e, e };
    static const int order[6] = { 0, 1, 2, 0, 2, 3 };
    for (int i = 0; i < 6; i++) {
        int q = order[i];
        gl_vert(v + LRGL_VERT_FLOATS * i, ax + ux * s[q] + nx * t[q],
                ay + uy * s[q] + ny * t[q], t[q], s[q], hw, len, dash, mode, k);
    }
}

void gl_line(lr_canvas *base, double x0, double y0, double x1, double y1,
             double width, lr_rgba colour, double dash)
{
    gl_line_quad(glc(base), x0, y0, x1, y1, 0.5 * width, dash, LRGL_STROKE, colour);
}

/* ---- discs ------------------------------------------------------------- */

/* Sprites up to this radius (the largest point is 255 px across, less the
 * rim); larger discs are quads. */
#define SPRITE_MAX_RADIUS 126.0

static void disc_quad(gl_canvas *c, double x, double y, double r, lr_rgba k)
{
    double e = r + 1.0;
    float *v = gl_shape_verts(c, 6);
    if (!v)
        return;
    static const double sx[6] = { -1, 1, 1, -1, 1, -1 }, sy[6] = { -1, -1, 1, -1, 1, 1 };
    for (int i = 0; i < 6; i++)
        gl_vert(v + LRGL_VERT_FLOATS * i, x + e * sx[i], y + e * sy[i], e * sx[i],
                e * sy[i], r, 0, 0, LRGL_DISC, k);
}

/* cairo stamps discs from 0.8 to 24 px radius at a quarter-pixel grid of
 * positions (canvas_cairo.c, STAMP_PHASES); the same discs here go to the
 * same positions, so that the backends differ only in coverage. */
#define STAMP_MIN_RADIUS 0.8
#define STAMP_MAX_RADIUS 24.0
#define STAMP_PHASES 4

static double stamp_position(double v)
{
    double f = floor(v);
    int q = (int)((v - f) * STAMP_PHASES);
    q = q < 0 ? 0 : q >= STAMP_PHASES ? STAMP_PHASES - 1 : q;
    return f + (q + 0.5) / STAMP_PHASES;
}

void gl_discs(lr_canvas *base, size_t n, const double *px, const double *py,
              double r, const lr_rgba *colours)
{
    gl_canvas *c = glc(base);
    double reach = r + 1.0;
    double w = c->base.width, h = c->base.height;
    int stamped = r >= STAMP_MIN_RADIUS && r <= STAMP_MAX_RADIUS;
    /* a million particles come in few colours: each converted once */
    lr_rgba last = { -1, -1, -1, -1 };
    unsigned char last8[4] = { 0, 0, 0, 0 };
    for (size_t i = 0; i < n && !c->failed; i++) {
        double x = px[i], y = py[i];
        if (!(x + reach >= 0 && y + reach >= 0 && x - reach <= w && y - reach <= h))
            continue;   /* off the canvas, or NaN */
        if (stamped) {
            x = stamp_position(x);
            y = stamp_position(y);
        }
        if (!(r <= SPRITE_MAX_RADIUS && x >= -c->pad && y >= -c->pad &&
              x <= w + c->pad && y <= h + c->pad)) {
            disc_quad(c, x, y, r, colours[i]);
            continue;
        }
        if ((c->batch != LRGL_BATCH_POINTS || c->point_r != r ||
             c->npoints >= c->cappoints) && gl_points_room(c, r, n - i) != 0)
            return;
        lr_rgba k = colours[i];
        if (k.r != last.r || k.g != last.g || k.b != last.b || k.a != last.a) {
            last = k;
            last8[0] = gl_to8(k.r);
            last8[1] = gl_to8(k.g);
            last8[2] = gl_to8(k.b);
            last8[3] = gl_to8(k.a);
        }
        c->pxy[2 * c->npoints] = (float)x;
        c->pxy[2 * c->npoints + 1] = (float)y;
        memcpy(c->prgba + 4 * c->npoints, last8, 4);
        c->npoints++;
    }
}
