/* test_diff.c - lr_diff: what must count as the same picture (identical
 * bytes, anti-aliasing from a sub-pixel shift, 1-LSB noise, a few mild
 * scattered pixels) and what must not (one moved particle, a cluster of
 * mild changes), the worst-window count, the diff image's colours, and the
 * errors of lr_diff_files (size mismatch, missing and corrupt files). */
#include "check.h"
#include "diff.h"
#include "render.h"

#include <cairo.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { W = 64, H = 64 };

typedef struct disc { double x, y, r; } disc;

/* Discs in Okabe-Ito blue on white, drawn by cairo with its default
 * anti-aliasing; returns straight RGBA8 (opaque, so premultiplication is
 * moot). */
static unsigned char *draw(int w, int h, const disc *d, int n)
{
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
    cairo_t *cr = cairo_create(s);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0x00 / 255.0, 0x72 / 255.0, 0xB2 / 255.0);
    for (int i = 0; i < n; i++) {
        cairo_new_sub_path(cr);
        cairo_arc(cr, d[i].x, d[i].y, d[i].r, 0, 6.283185307179586);
    }
    cairo_fill(cr);
    cairo_destroy(cr);
    cairo_surface_flush(s);
    unsigned char *out = malloc(4 * (size_t)w * h);
    const unsigned char *src = cairo_image_surface_get_data(s);
    int stride = cairo_image_surface_get_stride(s);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint32_t p;
            memcpy(&p, src + (size_t)y * stride + 4 * x, 4);
            unsigned char *q = out + 4 * ((size_t)y * w + x);
            q[0] = (unsigned char)(p >> 16);
            q[1] = (unsigned char)(p >> 8);
            q[2] = (unsigned char)p;
            q[3] = (unsigned char)(p >> 24);
        }
    cairo_surface_destroy(s);
    return out;
}

/* A block of particles like a frame shows them: radius 3, spacing 8. */
static int lattice(disc *d, double moved_dx)
{
    int n = 0;
    for (int j = 0; j < 5; j++)
        for (int i = 0; i < 5; i++) {
            d[n].x = 12 + 8 * i;
            d[n].y = 12 + 8 * j;
            d[n].r = 3;
            n++;
        }
    d[12].x += moved_dx;   /* the centre particle */
    return n;
}

static lr_diff_result compare(const unsigned char *a, const unsigned char *b, int w, int h,
                              unsigned char *diff)
{
    lr_diff_opts o;
    lr_diff_defaults(&o);
    lr_diff_result r;
    char err[256];
    CHECK(lr_diff(a, b, w, h, &o, &r, diff, err, sizeof err) == 0);
    return r;
}

static void test_identical(void)
{
    disc d[25];
    int n = lattice(d, 0);
    unsigned char *a = draw(W, H, d, n), *b = draw(W, H, d, n);
    lr_diff_result r = compare(a, b, W, H, NULL);
    CHECK(r.exact && r.same);
    CHECK(r.differing == 0 && r.aa == 0);
    free(a);
    free(b);
}

/* The same disc 0.3 px to the right (and then also down): only its rim
 * changes, and the rim is anti-aliasing. */
static void test_antialiasing_only(void)
{
    const double shifts[][2] = { { 0.3, 0 }, { 0.3, 0.3 }, { -0.3, 0.2 } };
    for (int k = 0; k < 3; k++) {
        disc d0 = { 31.5, 32.0, 12 }, d1 = { 31.5 + shifts[k][0], 32.0 + shifts[k][1], 12 };
        unsigned char *a = draw(W, H, &d0, 1), *b = draw(W, H, &d1, 1);
        lr_diff_result r = compare(a, b, W, H, NULL);
        CHECK(!r.exact);
        CHECK(r.aa > 0);
        CHECK(r.hard == 0);
        CHECK(r.same);
        if (!r.same) {
            char line[512];
            lr_diff_summary(&r, NULL, line, sizeof line);
            fprintf(stderr, "shift %g,%g: %s\n", shifts[k][0], shifts[k][1], line);
        }
        free(a);
        free(b);
    }
}

/* Every channel of every pixel nudged by at most one level: invisible. */
static void test_lsb_noise(void)
{
    disc d[25];
    int n = lattice(d, 0);
    unsigned char *a = draw(W, H, d, n), *b = draw(W, H, d, n);
    uint32_t seed = 12345;
    for (size_t i = 0; i < 4 * (size_t)W * H; i++) {
        if ((i & 3) == 3)
            continue;   /* keep it opaque */
        seed = seed * 1664525u + 1013904223u;
        int v = b[i] + (int)(seed >> 30) % 3 - 1;
        b[i] = (unsigned char)(v < 0 ? 0 : v > 255 ? 255 : v);
    }
    lr_diff_result r = compare(a, b, W, H, NULL);
    CHECK(!r.exact);
    CHECK(r.same);
    CHECK(r.differing == 0);
    CHECK(r.max_channel == 1);
    free(a);
    free(b);
}

/* One particle of 25 moved by 4 px: different, over the hard limit, and
 * red in the diff image where it was and where it is. */
static void test_moved_particle(void)
{
    disc d0[25], d1[25];
    int n = lattice(d0, 0);
    lattice(d1, 4);
    unsigned char *a = draw(W, H, d0, n), *b = draw(W, H, d1, n);
    unsigned char *diff = malloc(4 * (size_t)W * H);
    lr_diff_result r = compare(a, b, W, H, diff);
    CHECK(!r.same);
    CHECK(r.hard > 0);
    CHECK(r.differing > 0);
    CHECK(r.max_channel_differing > 64);
    /* the change fits one window, and the worst window holds it: it covers
     * where the particle was (centre 28,28) */
    CHECK(r.window_max == r.differing);
    CHECK(r.window_x <= 26 && r.window_x + LR_DIFF_WINDOW > 26);
    CHECK(r.window_y <= 28 && r.window_y + LR_DIFF_WINDOW > 28);
    /* where it was is now background: red */
    const unsigned char *p = diff + 4 * (28 * W + 26);
    CHECK(p[0] == 255 && p[1] == 0 && p[2] == 0 && p[3] == 255);
    /* an untouched particle: faded grey, lighter than the particle */
    p = diff + 4 * (12 * W + 12);
    CHECK(p[0] == p[1] && p[1] == p[2] && p[0] > 190 && p[0] < 255);
    /* the background: white stays white */
    p = diff + 4 * (2 * W + 2);
    CHECK(p[0] == 255 && p[1] == 255 && p[2] == 255);
    char line[512];
    lr_diff_summary(&r, NULL, line, sizeof line);
    CHECK(strncmp(line, "different: ", 11) == 0);
    free(a);
    free(b);
    free(diff);
}

/* Mild changes (a grey step of 40, visible but under the hard limit):
 * scattered they are tolerated up to max_pixels, clustered they are not. */
static void test_tolerances(void)
{
    unsigned char *a = malloc(4 * (size_t)W * H), *b = malloc(4 * (size_t)W * H);
    memset(a, 200, 4 * (size_t)W * H);
    for (size_t i = 3; i < 4 * (size_t)W * H; i += 4)
        a[i] = 255;
    memcpy(b, a, 4 * (size_t)W * H);
    /* 10 scattered pixels, each in its own window */
    for (int k = 0; k < 10; k++) {
        unsigned char *q = b + 4 * ((size_t)(3 + 6 * k) * W + (size_t)(5 + 5 * k) % W);
        q[0] = q[1] = q[2] = 160;
    }
    lr_diff_result r = compare(a, b, W, H, NULL);
    CHECK(r.differing == 10 && r.hard == 0 && r.aa == 0);
    CHECK(r.window_max <= 3);
    CHECK(r.same);

    /* 20 scattered: over max_pixels (16) */
    for (int k = 0; k < 10; k++) {
        unsigned char *q = b + 4 * ((size_t)(60 - 5 * k) * W + (size_t)(2 + 6 * k));
        q[0] = q[1] = q[2] = 160;
    }
    r = compare(a, b, W, H, NULL);
    CHECK(r.differing == 20);
    CHECK(!r.same);

    /* 9 in a 3x3 block: few overall, but a shape (max_window 8) */
    memcpy(b, a, 4 * (size_t)W * H);
    for (int y = 40; y < 43; y++)
        for (int x = 20; x < 23; x++) {
            unsigned char *q = b + 4 * ((size_t)y * W + x);
            q[0] = q[1] = q[2] = 160;
        }
    r = compare(a, b, W, H, NULL);
    CHECK(r.differing == 9 && r.window_max == 9);
    CHECK(r.window_x <= 20 && r.window_x + LR_DIFF_WINDOW >= 23);
    CHECK(r.window_y <= 40 && r.window_y + LR_DIFF_WINDOW >= 43);
    CHECK(!r.same);
    free(a);
    free(b);
}

/* Images smaller than the window: the window is the whole image. */
static void test_small_image(void)
{
    unsigned char a[4 * 3 * 2], b[4 * 3 * 2];
    memset(a, 255, sizeof a);
    memcpy(b, a, sizeof b);
    b[4 * 4] = 0;   /* pixel (1,1): white -> cyan, one hard pixel */
    lr_diff_result r = compare(a, b, 3, 2, NULL);
    CHECK(r.differing == 1 && r.hard == 1 && r.window_max == 1 && !r.same);
}

static void test_files(void)
{
    char dir[] = "diff_test_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char pa[64], pb[64], pc[64], pd[64], pbad[64], pnone[64];
    snprintf(pa, sizeof pa, "%s/a.png", dir);
    snprintf(pb, sizeof pb, "%s/b.png", dir);
    snprintf(pc, sizeof pc, "%s/c.png", dir);
    snprintf(pd, sizeof pd, "%s/d.png", dir);
    snprintf(pbad, sizeof pbad, "%s/bad.png", dir);
    snprintf(pnone, sizeof pnone, "%s/none.png", dir);
    disc d[25];
    int n = lattice(d, 0);
    unsigned char *a = draw(W, H, d, n), *c = draw(W, H / 2, d, n);
    char err[512];
    CHECK(lr_png_write(pa, W, H, a, NULL, 0, err, sizeof err) == 0);
    CHECK(lr_png_write(pb, W, H, a, NULL, 0, err, sizeof err) == 0);
    CHECK(lr_png_write(pc, W, H / 2, c, NULL, 0, err, sizeof err) == 0);
    FILE *f = fopen(pbad, "wb");
    if (f) {
        fputs("\x89PNG\r\n\x1a\n but then nothing sensible", f);
        fclose(f);
    }
    lr_diff_result r;
    CHECK(lr_diff_files(pa, pb, NULL, pd, &r, err, sizeof err) == 0);
    CHECK(r.exact && r.same);
    CHECK(access(pd, F_OK) == 0);

    CHECK(lr_diff_files(pa, pc, NULL, NULL, &r, err, sizeof err) == -1);
    CHECK(strstr(err, "size mismatch: 64x64 vs 64x32") != NULL);
    CHECK(lr_diff_files(pa, pnone, NULL, NULL, &r, err, sizeof err) == -1);
    CHECK(strstr(err, "none.png") && strstr(err, "No such file"));
    CHECK(lr_diff_files(pbad, pa, NULL, NULL, &r, err, sizeof err) == -1);
    CHECK(strstr(err, "bad.png") != NULL);

    unlink(pa);
    unlink(pb);
    unlink(pc);
    unlink(pd);
    unlink(pbad);
    CHECK(rmdir(dir) == 0);
    free(a);
    free(c);
}

/* Same inputs, same diff image bytes. */
static void test_deterministic(void)
{
    disc d0[25], d1[25];
    int n = lattice(d0, 0);
    lattice(d1, 2.5);
    unsigned char *a = draw(W, H, d0, n), *b = draw(W, H, d1, n);
    unsigned char *x = malloc(4 * (size_t)W * H), *y = malloc(4 * (size_t)W * H);
    lr_diff_result r1 = compare(a, b, W, H, x), r2 = compare(a, b, W, H, y);
    CHECK(memcmp(x, y, 4 * (size_t)W * H) == 0);
    CHECK(memcmp(&r1, &r2, sizeof r1) == 0);
    free(a);
    free(b);
    free(x);
    free(y);
}

int main(void)
{
    test_identical();
    test_antialiasing_only();
    test_lsb_noise();
    test_moved_particle();
    test_tolerances();
    test_small_image();
    test_files();
    test_deterministic();
    cairo_debug_reset_static_data();
    return CHECK_DONE();
}
