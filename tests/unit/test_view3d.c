/* test_view3d.c - 3D views (src/render/include/view3d.h): the scene drawn through
 * cairo is what the layers draw; through OSMesa it is OpenGL with a depth
 * buffer - a sphere in front hides a line drawn after it, a later layer
 * wins a depth tie, the drawing stays in the view's clip rectangle, the
 * same scene gives the same bytes - and both backends put every mark on
 * the pixels of the same camera. Also the compositing of a drawn view
 * over an image (lr_rgba_over). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "layers.h"
#include "render.h"
#include "view3d.h"

enum { W = 200, H = 200 };

static const lr_rgba WHITE = {1, 1, 1, 1};
static const lr_rgba RED = {1, 0, 0, 1};
static const lr_rgba BLUE = {0, 0, 1, 1};
static const lr_rgba BLACK = {0, 0, 0, 1};

static const unsigned char *px(const unsigned char *img, int x, int y)
{
    return img + 4 * ((size_t)y * W + (size_t)x);
}

/* The unit cube seen as the normals figures see it. */
static lr_view cube_view(void)
{
    lr_view v;
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    lr_view_3d(&v, 10, 10, W - 20, H - 20, lo, hi, -60, 25);
    return v;
}

static unsigned char *draw(lr_backend b, const lr_view *v, const lr_scene3d *s)
{
    char err[256] = "";
    lr_canvas *c = lr_canvas_new(b, W, H, err, sizeof err);
    CHECK(c != NULL);
    if (!c) {
        fprintf(stderr, "%s\n", err);
        return NULL;
    }
    lr_canvas_clear(c, WHITE);
    int rc = lr_scene3d_draw(c, v, s, err, sizeof err);
    if (rc != 0)
        fprintf(stderr, "lr_scene3d_draw: %s\n", err);
    CHECK(rc == 0);
    unsigned char *img = lr_canvas_read_rgba(c);
    CHECK(img != NULL);
    lr_canvas_free(c);
    return img;
}

static int reddish(const unsigned char *p)
{
    return p[0] > 150 && p[1] < 60 && p[2] < 60;
}

static int blueish(const unsigned char *p)
{
    return p[2] > 150 && p[0] < 80 && p[1] < 120;
}

/* A point p moved by t along the direction towards the viewer. */
static void toward(const lr_view *v, const double p[3], double t, double q[3])
{
    for (int a = 0; a < 3; a++)
        q[a] = p[a] + t * v->toward[a];
}

/* A line through the pixel of p, at depth offset t, crossing the screen. */
static void line_through(lr_scene3d *s, const lr_view *v, const double p[3], double t,
                         lr_rgba k)
{
    double q[3], a[3], b[3];
    toward(v, p, t, q);
    for (int i = 0; i < 3; i++) {
        a[i] = q[i] - 0.3 * v->right[i];
        b[i] = q[i] + 0.3 * v->right[i];
    }
    CHECK(lr_scene3d_line(s, a, b, 5.0, k, 0.0) == 0);
}

static void test_scene_basics(void)
{
    lr_scene3d *s = lr_scene3d_new();
    CHECK(s != NULL);
    double x[3] = {0.1, NAN, 0.3}, y[3] = {0.2, 0.2, 0.2}, z[3] = {0.3, 0.3, 0.3};
    double dx[3] = {0, 1, 0}, dy[3] = {0, 0, 0}, dz[3] = {0, 0, 1};
    const double *const p[3] = {x, y, z}, *const d[3] = {dx, dy, dz};
    CHECK(lr_scene3d_circles(s, 3, p, 6, 1.4, BLACK) == 0);
    CHECK(lr_scene3d_count(s) == 2);                 /* the NaN point is skipped */
    CHECK(lr_scene3d_arrows(s, 3, p, d, 0.2, 1.5, 7, BLUE, 0) == 0);
    CHECK(lr_scene3d_count(s) == 3);                 /* zero direction, NaN point */
    CHECK(lr_scene3d_polyline(s, 3, p, 1, BLACK, 4) == 0);
    CHECK(lr_scene3d_count(s) == 3);                 /* broken at NaN: two 1-point pieces */
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    CHECK(lr_scene3d_box(s, lo, hi, 1.5, BLACK) == 0);
    CHECK(lr_scene3d_text(s, lo, 0, 5, 12, BLACK, LR_ALIGN_CENTER, "x") == 0);
    CHECK(lr_scene3d_text(s, lo, 0, 5, 12, BLACK, LR_ALIGN_CENTER, "") == 0);
    CHECK(lr_scene3d_count(s) == 5);
    /* a 2D view is refused */
    lr_view v2;
    lr_view_2d(&v2, 0, 0, W, H, 0, 0, 1, 1);
    char err[256] = "";
    lr_canvas *c = lr_canvas_new(LR_BACKEND_CAIRO, W, H, err, sizeof err);
    CHECK(lr_scene3d_draw(c, &v2, s, err, sizeof err) == -1);
    CHECK(strstr(err, "not a 3D one") != NULL);
    lr_canvas_free(c);
    lr_scene3d_free(s);
    lr_scene3d_free(NULL);
}

/* Through cairo the scene is the layers, call for call: the same bytes. */
static void test_painter_is_layers(void)
{
    lr_view v = cube_view();
    double x[2] = {0.3, 0.7}, y[2] = {0.6, 0.2}, z[2] = {0.4, 0.8};
    double dx[2] = {0, 0.6}, dy[2] = {0, 0.8}, dz[2] = {1, 0};
    const double *const p[3] = {x, y, z}, *const d[3] = {dx, dy, dz};
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1}, r[3] = {0.5, 0.5, 0.9};
    lr_scene3d *s = lr_scene3d_new();
    CHECK(lr_scene3d_box(s, lo, hi, 1.5, BLACK) == 0);
    CHECK(lr_scene3d_polyline(s, 2, p, 1.0, BLACK, 4.0) == 0);
    CHECK(lr_scene3d_arrows(s, 2, p, d, 0.25, 1.5, 7, RED, 5.0) == 0);
    CHECK(lr_scene3d_arrows(s, 2, p, d, 0.25, 1.8, 7, BLUE, 0.0) == 0);
    CHECK(lr_scene3d_circles(s, 2, p, 6, 1.4, BLACK) == 0);
    CHECK(lr_scene3d_asterisk(s, r, 14, 1.5, BLACK) == 0);
    unsigned char *a = draw(LR_BACKEND_CAIRO, &v, s);

    char err[256];
    lr_canvas *c = lr_canvas_new(LR_BACKEND_CAIRO, W, H, err, sizeof err);
    lr_canvas_clear(c, WHITE);
    lr_layer_box(c, &v, lo, hi, 1.5, BLACK);
    lr_layer_polyline(c, &v, 2, 3, p, 1.0, BLACK, 4.0);
    lr_layer_arrows(c, &v, 2, 3, p, d, 0.25, 1.5, 7, RED, 5.0);
    lr_layer_arrows(c, &v, 2, 3, p, d, 0.25, 1.8, 7, BLUE, 0.0);
    lr_layer_circles(c, &v, 2, 3, p, 6, 1.4, BLACK);
    lr_layer_asterisk(c, &v, r, 14, 1.5, BLACK);
    unsigned char *b = lr_canvas_read_rgba(c);
    lr_canvas_free(c);
    CHECK(a && b && memcmp(a, b, 4 * (size_t)W * H) == 0);
    free(a);
    free(b);
    lr_scene3d_free(s);
}

/* Both backends draw a point and an arrow where the camera puts them. */
static void test_same_camera(lr_backend be)
{
    lr_view v = cube_view();
    double x[1] = {0.5}, y[1] = {0.5}, z[1] = {0.5};
    double dx[1] = {0}, dy[1] = {0}, dz[1] = {1};
    double x2[1] = {0.2}, y2[1] = {0.8}, z2[1] = {0.2};
    const double *const p[3] = {x, y, z}, *const d[3] = {dx, dy, dz};
    const double *const q[3] = {x2, y2, z2};
    lr_scene3d *s = lr_scene3d_new();
    CHECK(lr_scene3d_dots(s, 1, p, 8, RED) == 0);
    CHECK(lr_scene3d_arrows(s, 1, q, d, 0.4, 3, 7, BLUE, 0) == 0);
    unsigned char *img = draw(be, &v, s);
    double cx, cy, mx, my;
    lr_view_map(&v, (double[3]){0.5, 0.5, 0.5}, &cx, &cy);
    lr_view_map(&v, (double[3]){0.2, 0.8, 0.35}, &mx, &my);   /* on the shaft */
    if (img) {
        const unsigned char *c = px(img, (int)cx, (int)cy), *m = px(img, (int)mx, (int)my);
        CHECK(reddish(c));
        CHECK(blueish(m));
        /* and white well away from both */
        CHECK(px(img, 5, 5)[0] == 255 && px(img, 5, 5)[1] == 255);
        if (!reddish(c) || !blueish(m))
            fprintf(stderr, "%s: centre %d,%d,%d shaft %d,%d,%d\n", lr_backend_name(be),
                    c[0], c[1], c[2], m[0], m[1], m[2]);
    }
    free(img);
    lr_scene3d_free(s);
}

/* The GL backend the depth, tie and clip tests run on (OSMesa, then EGL:
 * the same drawing code on two ways of getting a context). */
static lr_backend gl_backend = LR_BACKEND_OSMESA;

/* A sphere hides a line behind it even when the line comes later; painter's
 * order (cairo) draws the line over it. A line in front shows in both. */
static void test_depth(void)
{
    lr_view v = cube_view();
    const double c[3] = {0.5, 0.5, 0.5};
    double x[1] = {c[0]}, y[1] = {c[1]}, z[1] = {c[2]}, cx, cy;
    const double *const p[3] = {x, y, z};
    lr_view_map(&v, c, &cx, &cy);
    lr_scene3d *behind = lr_scene3d_new(), *front = lr_scene3d_new();
    CHECK(lr_scene3d_dots(behind, 1, p, 12, RED) == 0);
    line_through(behind, &v, c, -0.2, BLUE);
    line_through(front, &v, c, 0.2, BLUE);
    CHECK(lr_scene3d_dots(front, 1, p, 12, RED) == 0);

    unsigned char *g = draw(gl_backend, &v, behind);
    unsigned char *k = draw(LR_BACKEND_CAIRO, &v, behind);
    if (g && k) {
        CHECK(reddish(px(g, (int)cx, (int)cy)));      /* hidden behind the sphere */
        CHECK(blueish(px(k, (int)cx, (int)cy)));      /* painter: drawn over it */
        CHECK(blueish(px(g, (int)cx + 16, (int)cy)));  /* beside the sphere: seen */
    }
    free(g);
    free(k);
    g = draw(gl_backend, &v, front);
    if (g)
        CHECK(blueish(px(g, (int)cx, (int)cy)));      /* in front, drawn first */
    free(g);
    lr_scene3d_free(behind);
    lr_scene3d_free(front);
}

/* Coincident marks (an exact normal under a computed one): the later layer
 * is on top, as in painter's order; and the same scene, the same bytes. */
static void test_ties_and_determinism(void)
{
    lr_view v = cube_view();
    const double c[3] = {0.4, 0.6, 0.5};
    double cx, cy;
    lr_view_map(&v, c, &cx, &cy);
    lr_scene3d *rb = lr_scene3d_new(), *br = lr_scene3d_new();
    /* the later one a hair behind, as rounding may put it */
    line_through(rb, &v, c, 0.0, RED);
    line_through(rb, &v, c, -1e-6, BLUE);
    line_through(br, &v, c, 0.0, BLUE);
    line_through(br, &v, c, -1e-6, RED);
    unsigned char *a = draw(gl_backend, &v, rb);
    unsigned char *b = draw(gl_backend, &v, br);
    unsigned char *a2 = draw(gl_backend, &v, rb);
    if (a && b && a2) {
        CHECK(blueish(px(a, (int)cx, (int)cy)));
        CHECK(reddish(px(b, (int)cx, (int)cy)));
        CHECK(memcmp(a, a2, 4 * (size_t)W * H) == 0);
    }
    free(a);
    free(b);
    free(a2);
    lr_scene3d_free(rb);
    lr_scene3d_free(br);
}

/* The OpenGL drawing stays inside the view's clip rectangle; text items
 * are drawn after the geometry, on top. */
static void test_clip_and_text(void)
{
    lr_view v = cube_view();
    lr_view_clip(&v, 60, 60, 140, 140);
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1}, c[3] = {0.5, 0.5, 0.5};
    double x[1] = {0.5}, y[1] = {0.5}, z[1] = {0.5};
    const double *const p[3] = {x, y, z};
    lr_scene3d *s = lr_scene3d_new();
    CHECK(lr_scene3d_text(s, c, 0, 0, 40, BLUE, LR_ALIGN_CENTER, "\xe2\x96\x88") == 0);
    CHECK(lr_scene3d_box(s, lo, hi, 3, BLACK) == 0);
    CHECK(lr_scene3d_dots(s, 1, p, 30, RED) == 0);
    unsigned char *g = draw(gl_backend, &v, s);
    if (g) {
        int outside = 0;
        for (int j = 0; j < H; j++)
            for (int i = 0; i < W; i++)
                if ((i < 60 || i >= 140 || j < 60 || j >= 140) &&
                    memcmp(px(g, i, j), "\xff\xff\xff\xff", 4) != 0)
                    outside++;
        CHECK(outside == 0);
        double cx, cy;
        lr_view_map(&v, c, &cx, &cy);
        /* the full block glyph sits above its baseline at the point */
        CHECK(blueish(px(g, (int)cx, (int)cy - 8)));
    }
    free(g);
    lr_scene3d_free(s);
}

static void test_over(void)
{
    unsigned char dst[2 * 2 * 4], src[2 * 4];
    memset(dst, 255, sizeof dst);
    const unsigned char s0[8] = {255, 0, 0, 128, 0, 0, 255, 0};
    memcpy(src, s0, sizeof src);
    lr_rgba_over(dst, 2, 2, src, 2, 1, 0, 1);            /* onto the bottom row */
    CHECK(dst[8] == 255 && dst[9] == 127 && dst[10] == 127 && dst[11] == 255);
    CHECK(dst[12] == 255 && dst[13] == 255 && dst[14] == 255);   /* alpha 0: kept */
    CHECK(dst[0] == 255 && dst[1] == 255);                       /* top row untouched */
    /* onto transparent: the source as it is; half outside: the rest is left */
    memset(dst, 0, sizeof dst);
    lr_rgba_over(dst, 2, 2, src, 2, 1, -1, 0);
    CHECK(dst[0] == 0 && dst[3] == 0);                   /* src's second pixel, alpha 0 */
    lr_rgba_over(dst, 2, 2, src, 2, 1, 1, 0);
    CHECK(dst[4] == 255 && dst[5] == 0 && dst[6] == 0 && dst[7] == 128);
    lr_rgba_over(dst, 2, 2, src, 2, 1, 5, 5);            /* wholly outside: nothing */
    CHECK(dst[12] == 0);
}

/* Axis names off the box (lr_view_axis_places, lamina.figure's axes =
 * "outside"): seen from azimuth -60, elevation 25 the outline edges are
 * x's front bottom edge (y = 0, z = 0), y's right bottom one (x = 1,
 * z = 0) and z's left one (x = 0, y = 0); each name moves away from the
 * cube's centre along a unit direction. */
static void test_axis_places(void)
{
    lr_view v = cube_view();
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    double at[3][3], out[3][2];
    lr_view_axis_places(&v, lo, hi, at, out);
    const double want[3][3] = { {0.5, 0, 0}, {1, 0.5, 0}, {0, 0, 0.5} };
    for (int a = 0; a < 3; a++)
        for (int k = 0; k < 3; k++)
            CHECK(at[a][k] == want[a][k]);
    CHECK(out[0][1] > 0.5);                 /* x: down */
    CHECK(out[1][0] > 0.3 && out[1][1] > 0.3);   /* y: down and right */
    CHECK(out[2][0] < -0.9);                /* z: left */
    for (int a = 0; a < 3; a++)
        CHECK(fabs(hypot(out[a][0], out[a][1]) - 1) < 1e-12);
}

int main(void)
{
    test_axis_places();
    test_scene_basics();
    test_painter_is_layers();
    test_over();
    test_same_camera(LR_BACKEND_CAIRO);
    for (int b = LR_BACKEND_OSMESA; b < LR_BACKEND_COUNT; b++) {
        if (lr_backend_check((lr_backend)b, NULL, 0) != 0) {
            printf("%s not built or not starting: its 3D views are not tested\n",
                   lr_backend_name((lr_backend)b));
            continue;
        }
        gl_backend = (lr_backend)b;
        test_same_camera(gl_backend);
        test_depth();
        test_ties_and_determinism();
        test_clip_and_text();
    }
    lr_shutdown();
    return CHECK_DONE();
}
