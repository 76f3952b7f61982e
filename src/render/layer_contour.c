/* layer_contour.c - contour lines of a sampled field by marching squares
 * (Lorensen & Cline's marching cubes, 1987, in two dimensions): the level
 * phi = 1 through the membrane points, phi = 0 through the random point
 * ([N] Figs 3-10). */
#include <math.h>

#include "layers.h"

/* Corners of a cell counter-clockwise from (i, j): c0 (0,0), c1 (1,0),
 * c2 (1,1), c3 (0,1); edge k joins corner k and corner k+1. */
static const int corner_dx[4] = {0, 1, 1, 0};
static const int corner_dy[4] = {0, 0, 1, 1};

/* Where edge k of the cell crosses the level (index coordinates). */
static void crossing(const double v[4], int i, int j, int k, double level,
                     double *x, double *y)
{
    int a = k, b = (k + 1) & 3;
    double t = (level - v[a]) / (v[b] - v[a]);
    if (!(t >= 0.0))
        t = 0.0;
    if (t > 1.0)
        t = 1.0;
    *x = i + corner_dx[a] + t * (corner_dx[b] - corner_dx[a]);
    *y = j + corner_dy[a] + t * (corner_dy[b] - corner_dy[a]);
}

size_t lr_marching_squares(const double *f, int nx, int ny, double level,
                           lr_segment_fn emit, void *ctx)
{
    size_t count = 0;
    int sx = nx + 1;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            double v[4];
            int above[4], nabove = 0, finite = 1;
            for (int k = 0; k < 4; k++) {
                v[k] = f[(i + corner_dx[k]) + sx * (j + corner_dy[k])];
                finite &= isfinite(v[k]) != 0;
                above[k] = v[k] >= level;
                nabove += above[k];
            }
            if (!finite || nabove == 0 || nabove == 4)
                continue;
            double px[4], py[4];
            int cut[4];
            for (int k = 0; k < 4; k++) {
                cut[k] = above[k] != above[(k + 1) & 3];
                if (cut[k])
                    crossing(v, i, j, k, level, &px[k], &py[k]);
            }
            if (nabove == 2 && above[0] == above[2]) {
                /* a saddle: the centre decides which pair of corners is
                 * joined; each corner on the other side is cut off by the
                 * segment between its two edges (k-1 and k) */
                int centre = 0.25 * (v[0] + v[1] + v[2] + v[3]) >= level;
                for (int k = 0; k < 4; k++)
                    if (above[k] != centre) {
                        int e0 = (k + 3) & 3, e1 = k;
                        emit(ctx, px[e0], py[e0], px[e1], py[e1]);
                        count++;
                    }
                continue;
            }
            int e[2], ne = 0;
            for (int k = 0; k < 4 && ne < 2; k++)
                if (cut[k])
                    e[ne++] = k;
            emit(ctx, px[e[0]], py[e[0]], px[e[1]], py[e[1]]);
            count++;
        }
    return count;
}

typedef struct draw_ctx {
    lr_canvas *c;
    const lr_view *v;
    double x0, y0, dx, dy, width;
    lr_rgba colour;
} draw_ctx;

static void draw_segment(void *p, double i0, double j0, double i1, double j1)
{
    const draw_ctx *d = p;
    double a[3] = {d->x0 + i0 * d->dx, d->y0 + j0 * d->dy, 0.0};
    double b[3] = {d->x0 + i1 * d->dx, d->y0 + j1 * d->dy, 0.0};
    double ax, ay, bx, by;
    lr_view_map(d->v, a, &ax, &ay);
    lr_view_map(d->v, b, &bx, &by);
    /* a little overlap hides the joints between butt-capped segments */
    double len = hypot(bx - ax, by - ay);
    if (len > 0) {
        double ex = 0.25 * d->width * (bx - ax) / len;
        double ey = 0.25 * d->width * (by - ay) / len;
        ax -= ex;
        ay -= ey;
        bx += ex;
        by += ey;
    }
    lr_view_line(d->c, d->v, ax, ay, bx, by, d->width, d->colour, 0.0);
}

size_t lr_layer_contour(lr_canvas *c, const lr_view *v, const double *f,
                        int nx, int ny, double x0, double y0, double x1,
                        double y1, double level, double width, lr_rgba colour)
{
    if (nx < 1 || ny < 1)
        return 0;
    draw_ctx d = {c, v, x0, y0, (x1 - x0) / nx, (y1 - y0) / ny, width, colour};
    return lr_marching_squares(f, nx, ny, level, draw_segment, &d);
}
