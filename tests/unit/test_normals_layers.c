/* test_normals_layers.c - the drawing layers of the normals figures
 * (src/render/include/layers.h): marching squares, the 2D and 3D views, and what
 * lands on the canvas (a contour where phi crosses the level, arrows,
 * circles, the cube's hidden edges). */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "layers.h"

typedef struct segs { int n; double x[64][4]; } segs;

static void collect(void *ctx, double x0, double y0, double x1, double y1)
{
    segs *s = ctx;
    if (s->n < 64) {
        s->x[s->n][0] = x0;
        s->x[s->n][1] = y0;
        s->x[s->n][2] = x1;
        s->x[s->n][3] = y1;
    }
    s->n++;
}

/* f = i - 1.25 on a 4 x 3 grid of cells: the level 0 is the vertical line
 * i = 1.25, one segment per row of cells. */
static void test_linear_field(void)
{
    enum { NX = 4, NY = 3 };
    double f[(NX + 1) * (NY + 1)];
    for (int j = 0; j <= NY; j++)
        for (int i = 0; i <= NX; i++)
            f[i + (NX + 1) * j] = i - 1.25;
    segs s = {0, {{0}}};
    CHECK(lr_marching_squares(f, NX, NY, 0.0, collect, &s) == NY);
    CHECK(s.n == NY);
    for (int k = 0; k < s.n && k < 64; k++) {
        CHECK_NEAR(s.x[k][0], 1.25, 1e-15);
        CHECK_NEAR(s.x[k][2], 1.25, 1e-15);
        CHECK_NEAR(fabs(s.x[k][3] - s.x[k][1]), 1.0, 1e-15);
    }
    /* a level outside the range: nothing */
    s.n = 0;
    CHECK(lr_marching_squares(f, NX, NY, 10.0, collect, &s) == 0);
}

/* A saddle cell: corners 1, 0, 1, 0 (counter-clockwise from (0,0)) with
 * the centre above 0.5 join the two high corners: the segments cut off
 * the low corners (1,0) and (0,1). */
static void test_saddle(void)
{
    double f[4] = {1, 0, 0, 1};   /* (0,0)=1 (1,0)=0 / (0,1)=0 (1,1)=1 */
    segs s = {0, {{0}}};
    CHECK(lr_marching_squares(f, 1, 1, 0.4, collect, &s) == 2);
    /* each segment joins two edge midpoints around one low corner */
    for (int k = 0; k < 2; k++) {
        double mx = 0.5 * (s.x[k][0] + s.x[k][2]), my = 0.5 * (s.x[k][1] + s.x[k][3]);
        int near_10 = mx > 0.5 && my < 0.5, near_01 = mx < 0.5 && my > 0.5;
        CHECK(near_10 || near_01);
    }
    /* centre below: the other pairing */
    double g[4] = {1, 0, 0, 1};
    s.n = 0;
    CHECK(lr_marching_squares(g, 1, 1, 0.6, collect, &s) == 2);
    for (int k = 0; k < 2; k++) {
        double mx = 0.5 * (s.x[k][0] + s.x[k][2]), my = 0.5 * (s.x[k][1] + s.x[k][3]);
        CHECK((mx < 0.5 && my < 0.5) || (mx > 0.5 && my > 0.5));
    }
    /* non-finite corners: the cell is skipped */
    double h[4] = {1, NAN, 0, 1};
    s.n = 0;
    CHECK(lr_marching_squares(h, 1, 1, 0.5, collect, &s) == 0);
}

static void test_views(void)
{
    lr_view v;
    /* a 2 x 1 window into 200 x 200 pixels: 100 px per unit, centred */
    lr_view_2d(&v, 0, 0, 200, 200, 0, 0, 2, 1);
    double p[3] = {0, 0, 0}, q[3] = {2, 1, 0}, x, y, x2, y2;
    lr_view_map(&v, p, &x, &y);
    lr_view_map(&v, q, &x2, &y2);
    CHECK_NEAR(x, 0, 1e-12);
    CHECK_NEAR(y, 150, 1e-12);
    CHECK_NEAR(x2, 200, 1e-12);
    CHECK_NEAR(y2, 50, 1e-12);
    /* 3D: every corner of the cube inside the panel, the centre in the
     * middle, z up on screen */
    double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    lr_view_3d(&v, 10, 20, 300, 200, lo, hi, -60, 25);
    for (int c = 0; c < 8; c++) {
        double k[3] = {(double)(c & 1), (double)((c >> 1) & 1), (double)((c >> 2) & 1)};
        lr_view_map(&v, k, &x, &y);
        CHECK(x >= 10 - 1e-9 && x <= 310 + 1e-9 && y >= 20 - 1e-9 && y <= 220 + 1e-9);
    }
    double m[3] = {0.5, 0.5, 0.5}, top[3] = {0.5, 0.5, 1};
    lr_view_map(&v, m, &x, &y);
    CHECK_NEAR(x, 160, 1e-9);
    CHECK_NEAR(y, 120, 1e-9);
    lr_view_map(&v, top, &x2, &y2);
    CHECK(y2 < y);
    CHECK_NEAR(x2, x, 1e-9);
}

static int dark(const unsigned char *img, int w, int x, int y)
{
    const unsigned char *p = img + 4 * ((size_t)y * w + x);
    return p[0] + p[1] + p[2] < 3 * 160;
}

/* The phi = level contour drawn where it belongs: phi = x on the unit
 * window, level 0.25 -> a vertical line at a quarter of the width. */
static void test_drawing(void)
{
    enum { W = 120, H = 120 };
    char err[128];
    lr_canvas *c = lr_canvas_cairo_new(W, H, err, sizeof err);
    CHECK(c != NULL);
    if (!c)
        return;
    lr_canvas_clear(c, (lr_rgba){1, 1, 1, 1});
    lr_view v;
    lr_view_2d(&v, 10, 10, 100, 100, 0, 0, 1, 1);
    enum { S = 20 };
    double f[(S + 1) * (S + 1)];
    for (int j = 0; j <= S; j++)
        for (int i = 0; i <= S; i++)
            f[i + (S + 1) * j] = (double)i / S;
    CHECK(lr_layer_contour(c, &v, f, S, S, 0, 0, 1, 1, 0.25, 2.0, (lr_rgba){0, 0, 0, 1}) ==
          S);
    /* an arrow from (0.7, 0.5) along +y, 0.3 long: pixels at x = 80 */
    double px[1] = {0.7}, py[1] = {0.5}, dx[1] = {0}, dy[1] = {1};
    const double *p[3] = {px, py, NULL}, *d[3] = {dx, dy, NULL};
    lr_layer_arrows(c, &v, 1, 2, p, d, 0.3, 2.0, 6, (lr_rgba){0, 0, 0, 1}, 0.0);
    double ox[1] = {0.5}, oy[1] = {0.2};
    const double *o[3] = {ox, oy, NULL};
    lr_layer_circles(c, &v, 1, 2, o, 5.0, 1.5, (lr_rgba){0, 0, 0, 1});
    unsigned char *img = lr_canvas_read_rgba(c);
    CHECK(img != NULL);
    if (img) {
        for (int y = 20; y < 100; y += 10)
            CHECK(dark(img, W, 35, y) || dark(img, W, 34, y));    /* x = 10 + 25 */
        CHECK(!dark(img, W, 50, 50));                             /* nothing there */
        CHECK(dark(img, W, 80, 50) || dark(img, W, 79, 50));      /* arrow shaft */
        CHECK(dark(img, W, 80, 35) || dark(img, W, 79, 35));
        CHECK(!dark(img, W, 80, 75));                             /* below its start */
        CHECK(dark(img, W, 65, 90) || dark(img, W, 64, 90));      /* circle rim, r 5 */
        CHECK(!dark(img, W, 60, 90));                             /* open: hollow */
        free(img);
    }
    lr_canvas_free(c);
}

/* Lines are clipped to the view's rectangle: a figure panel never draws
 * over its neighbours, its title or its caption. */
static void test_clip(void)
{
    enum { W = 100, H = 40 };
    char err[128];
    lr_canvas *c = lr_canvas_cairo_new(W, H, err, sizeof err);
    CHECK(c != NULL);
    if (!c)
        return;
    lr_canvas_clear(c, (lr_rgba){1, 1, 1, 1});
    lr_view v;
    lr_view_2d(&v, 0, 0, W, H, 0, 0, 1, 0.4);
    lr_view_clip(&v, 10, 0, 50, H);
    lr_view_line(c, &v, -20, 20.5, 140, 20.5, 3.0, (lr_rgba){0, 0, 0, 1}, 0.0);
    lr_view_line(c, &v, 60, 0, 90, 40, 3.0, (lr_rgba){0, 0, 0, 1}, 0.0);  /* all outside */
    unsigned char *img = lr_canvas_read_rgba(c);
    CHECK(img != NULL);
    if (img) {
        CHECK(dark(img, W, 30, 20));
        CHECK(dark(img, W, 12, 20));
        CHECK(!dark(img, W, 5, 20));
        CHECK(!dark(img, W, 60, 20));
        CHECK(!dark(img, W, 75, 20));
        free(img);
    }
    lr_canvas_free(c);
}

int main(void)
{
    test_linear_field();
    test_saddle();
    test_views();
    test_drawing();
    test_clip();
    return CHECK_DONE();
}
