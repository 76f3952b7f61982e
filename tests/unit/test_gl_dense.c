/* test_gl_dense.c - many discs of radius about a pixel, which the GL
 * backends gather into rectangles (canvas_gl_dense.c) instead of drawing
 * them as points, come out as cairo stamps them.
 *
 * One canvas, in drawing order: a grey background; a lattice of opaque
 * discs closer than a pixel, running off the canvas's edges; a short run
 * of a translucent colour (points, between the gathered runs); a
 * translucent run over part of the first, clipped; a pile of discs a few
 * pixels wide, a hundred to a pixel (gathered in layers of two, the last
 * few hundred as points); discs of radius 1.43 (points). Through OSMesa
 * and EGL (those built and starting here) the image must be the same as
 * cairo's within lr_diff's default tolerance, the same byte for byte when
 * drawn twice, and the same in OSMesa and EGL. */
#include "check.h"
#include "diff.h"
#include "render.h"

#include <stdlib.h>
#include <string.h>

enum { W = 320, H = 240, NMAX = 200000 };

static double xs[NMAX], ys[NMAX];
static lr_rgba cols[NMAX];

/* A small LCG: the same scene on every machine. */
static double rnd(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (*s >> 8) / 16777216.0;
}

static size_t lattice(size_t n, double x0, double y0, double x1, double y1,
                      double step, lr_rgba k, unsigned *seed)
{
    for (double y = y0; y < y1; y += step)
        for (double x = x0; x < x1 && n < NMAX; x += step) {
            xs[n] = x + 0.2 * rnd(seed);
            ys[n] = y + 0.2 * rnd(seed);
            cols[n++] = k;
        }
    return n;
}

static unsigned char *draw(lr_backend b)
{
    char err[512];
    lr_canvas *c = lr_canvas_new(b, W, H, err, sizeof err);
    if (!c) {
        fprintf(stderr, "test_gl_dense: %s\n", err);
        return NULL;
    }
    unsigned seed = 7;
    lr_canvas_clear(c, (lr_rgba){ 0.5, 0.55, 0.6, 1 });
    const lr_rgba orange = { 0.9, 0.62, 0.0, 1 }, blue = { 0.0, 0.45, 0.7, 0.6 },
                  pink = { 0.8, 0.2, 0.5, 0.5 }, green = { 0.1, 0.7, 0.3, 0.8 };
    size_t n = lattice(0, -3, -3, 200, 150, 0.9, orange, &seed);
    for (int i = 0; i < 200; i++, n++) {    /* a short run: points */
        xs[n] = 20 + 250 * rnd(&seed);
        ys[n] = 20 + 200 * rnd(&seed);
        cols[n] = pink;
    }
    lr_canvas_discs(c, n, xs, ys, 1.0, cols);
    lr_canvas_clip(c, 40, 30, 240, 180);
    n = lattice(0, 100, 80, W + 3, H + 3, 0.85, blue, &seed);
    lr_canvas_discs(c, n, xs, ys, 1.0, cols);
    lr_canvas_unclip(c);
    /* the pile: 4000 discs over 6 x 5 pixels */
    for (n = 0; n < 4000; n++) {
        xs[n] = 250 + 6 * rnd(&seed);
        ys[n] = 40 + 5 * rnd(&seed);
        cols[n] = green;
    }
    lr_canvas_discs(c, n, xs, ys, 0.9, cols);
    n = lattice(0, 10, 160, 90, 230, 2.0, orange, &seed);
    lr_canvas_discs(c, n, xs, ys, 1.43, cols);
    unsigned char *img = lr_canvas_read_rgba(c);
    lr_canvas_free(c);
    return img;
}

static void same_as(const unsigned char *want, const unsigned char *got, const char *what)
{
    lr_diff_opts o;
    lr_diff_defaults(&o);
    lr_diff_result res;
    char err[256], line[512];
    CHECK(lr_diff(want, got, W, H, &o, &res, NULL, err, sizeof err) == 0);
    lr_diff_summary(&res, &o, line, sizeof line);
    printf("%s: %s\n", what, line);
    CHECK(res.same);
}

int main(void)
{
    unsigned char *cairo = draw(LR_BACKEND_CAIRO);
    CHECK(cairo != NULL);
    unsigned char *gl[2] = { NULL, NULL };
    const lr_backend which[2] = { LR_BACKEND_OSMESA, LR_BACKEND_EGL };
    for (int k = 0; k < 2 && cairo; k++) {
        if (lr_backend_check(which[k], NULL, 0) != 0) {
            printf("%s: not here, skipped\n", lr_backend_name(which[k]));
            continue;
        }
        gl[k] = draw(which[k]);
        unsigned char *again = draw(which[k]);
        CHECK(gl[k] && again);
        if (!gl[k] || !again) {
            free(again);
            continue;
        }
        CHECK(memcmp(gl[k], again, 4 * (size_t)W * H) == 0);
        free(again);
        char what[64];
        snprintf(what, sizeof what, "cairo - %s", lr_backend_name(which[k]));
        same_as(cairo, gl[k], what);
    }
    if (gl[0] && gl[1])
        CHECK(memcmp(gl[0], gl[1], 4 * (size_t)W * H) == 0);
    free(gl[0]);
    free(gl[1]);
    free(cairo);
    lr_shutdown();
    return CHECK_DONE();
}
