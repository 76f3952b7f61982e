/* diff.c - perceptual image comparison with anti-aliasing detection.
 *
 * The idea (not the code) follows pixelmatch (Mapbox): YIQ distance per
 * pixel with the weights of Kotsarenko & Ramos (2010), and the
 * anti-aliasing test of Vysniauskas (2009) - an edge pixel sits between a
 * darker and a brighter neighbour, and those neighbours belong to flat
 * areas in both images. Everything here is integer or plain double
 * arithmetic in a fixed order, so the same two images give the same
 * result and the same diff image on every run. */
#include "diff.h"

#include "render.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "util.h"

/* The distance below, for black against white: the scale the threshold
 * (0..1, squared) is measured against. */
#define YIQ_MAX 35215.0
/* How much of the expected image's tone survives in the diff image:
 * enough to see where things are, faint enough that red and yellow stand out. */
#define FADE 0.25

void lr_diff_defaults(lr_diff_opts *o)
{
    o->threshold = 0.1;
    o->hard_limit = 64;
    o->max_pixels = 16;
    o->max_window = 8;
}

typedef struct image {
    const unsigned char *p;
    int w, h;
} image;

static const unsigned char *at(const image *m, int x, int y)
{
    return m->p + 4 * ((size_t)y * (size_t)m->w + (size_t)x);
}

static int same_pixel(const unsigned char *a, const unsigned char *b)
{
    return memcmp(a, b, 4) == 0;
}

/* The pixel as seen on a white page: transparency must not hide a change. */
static void over_white(const unsigned char *q, double rgb[3])
{
    double a = q[3] / 255.0;
    for (int c = 0; c < 3; c++)
        rgb[c] = 255.0 + (q[c] - 255.0) * a;
}

static double luma(const double c[3])
{
    return 0.29889531 * c[0] + 0.58662247 * c[1] + 0.11448223 * c[2];
}

static double brightness(const unsigned char *q)
{
    double c[3];
    over_white(q, c);
    return luma(c);
}

/* Squared YIQ distance, weighted for perception (0 .. YIQ_MAX). */
static double yiq_distance(const unsigned char *a, const unsigned char *b)
{
    double ca[3], cb[3];
    over_white(a, ca);
    over_white(b, cb);
    double dy = luma(ca) - luma(cb);
    double di = (0.59597799 * ca[0] - 0.27417610 * ca[1] - 0.32180189 * ca[2]) -
                (0.59597799 * cb[0] - 0.27417610 * cb[1] - 0.32180189 * cb[2]);
    double dq = (0.21147017 * ca[0] - 0.52261711 * ca[1] + 0.31114694 * ca[2]) -
                (0.21147017 * cb[0] - 0.52261711 * cb[1] + 0.31114694 * cb[2]);
    return 0.5053 * dy * dy + 0.299 * di * di + 0.1957 * dq * dq;
}

static int largest_channel_difference(const unsigned char *a, const unsigned char *b)
{
    int m = 0;
    for (int c = 0; c < 4; c++) {
        int d = a[c] > b[c] ? a[c] - b[c] : b[c] - a[c];
        if (d > m)
            m = d;
    }
    return m;
}

/* Inside a flat area: at least three of the eight neighbours are the very
 * same colour. Neighbours beyond the border count as the same, since a
 * shape cut by the border is still flat there. */
static int is_flat(const image *m, int x, int y)
{
    const unsigned char *c = at(m, x, y);
    int same = 0;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            if (!dx && !dy)
                continue;
            int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= m->w || ny >= m->h || same_pixel(at(m, nx, ny), c))
                same++;
        }
    return same >= 3;
}

/* Is (x, y) in m an anti-aliased edge pixel? It must not be part of a flat
 * run itself (at most two identical neighbours), it must lie strictly
 * between its darkest and its brightest neighbour in brightness, and one of
 * those two must sit in a flat area in both images - the solid shapes on
 * either side of the edge, present in both pictures. */
static int is_edge(const image *m, const image *other, int x, int y)
{
    const unsigned char *c = at(m, x, y);
    double yc = brightness(c);
    int same = 0;
    double lo = 0, hi = 0;
    int lx = -1, ly = -1, hx = -1, hy = -1;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int nx = x + dx, ny = y + dy;
            if ((!dx && !dy) || nx < 0 || ny < 0 || nx >= m->w || ny >= m->h)
                continue;
            const unsigned char *n = at(m, nx, ny);
            if (same_pixel(n, c)) {
                if (++same > 2)
                    return 0;
                continue;
            }
            double d = brightness(n) - yc;
            if (d < lo) {
                lo = d;
                lx = nx;
                ly = ny;
            }
            if (d > hi) {
                hi = d;
                hx = nx;
                hy = ny;
            }
        }
    if (lx < 0 || hx < 0)
        return 0;
    return (is_flat(m, lx, ly) && is_flat(other, lx, ly)) ||
           (is_flat(m, hx, hy) && is_flat(other, hx, hy));
}

static void paint(unsigned char *q, int r, int g, int b)
{
    q[0] = (unsigned char)r;
    q[1] = (unsigned char)g;
    q[2] = (unsigned char)b;
    q[3] = 255;
}

static void paint_faded(unsigned char *q, const unsigned char *expected)
{
    double v = 255.0 - (255.0 - brightness(expected)) * FADE;
    int g = (int)(v + 0.5);
    paint(q, g, g, g);
}

/* The most set entries of mask in any ww x wh window, by sliding column
 * sums down the rows (memory O(w), whatever the image size). Ties go to
 * the first window in reading order. */
static int worst_window(const unsigned char *mask, int w, int h, lr_diff_result *r)
{
    int ww = w < LR_DIFF_WINDOW ? w : LR_DIFF_WINDOW;
    int wh = h < LR_DIFF_WINDOW ? h : LR_DIFF_WINDOW;
    int *col = calloc((size_t)w, sizeof *col);
    if (!col)
        return -1;
    for (int y = 0; y < h; y++) {
        for (int x = 0; x < w; x++) {
            col[x] += mask[(size_t)y * w + x];
            if (y >= wh)
                col[x] -= mask[(size_t)(y - wh) * w + x];
        }
        if (y < wh - 1)
            continue;
        long sum = 0;
        for (int x = 0; x < w; x++) {
            sum += col[x];
            if (x >= ww)
                sum -= col[x - ww];
            if (x >= ww - 1 && sum > r->window_max) {
                r->window_max = sum;
                r->window_x = x - ww + 1;
                r->window_y = y - wh + 1;
            }
        }
    }
    free(col);
    return 0;
}

int lr_diff(const unsigned char *expected, const unsigned char *actual, int w, int h,
            const lr_diff_opts *opts, lr_diff_result *res, unsigned char *diff_rgba,
            char *err, size_t errlen)
{
    lr_diff_opts defaults;
    if (!opts) {
        lr_diff_defaults(&defaults);
        opts = &defaults;
    }
    if (!expected || !actual || !res) {
        lu_err(err, errlen, "diff: missing image");
        return -1;
    }
    if (w <= 0 || h <= 0 || (size_t)w > SIZE_MAX / 4 / (size_t)h) {
        lu_err(err, errlen, "diff: invalid size %dx%d", w, h);
        return -1;
    }
    memset(res, 0, sizeof *res);
    res->width = w;
    res->height = h;
    size_t n = (size_t)w * (size_t)h;
    if (memcmp(expected, actual, 4 * n) == 0) {
        res->exact = res->same = 1;
        for (size_t i = 0; diff_rgba && i < n; i++)
            paint_faded(diff_rgba + 4 * i, expected + 4 * i);
        return 0;
    }
    unsigned char *mask = calloc(n, 1);
    if (!mask) {
        lu_err(err, errlen, "diff: out of memory for %dx%d", w, h);
        return -1;
    }
    image e = { expected, w, h }, a = { actual, w, h };
    double limit = YIQ_MAX * opts->threshold * opts->threshold;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            const unsigned char *pe = expected + 4 * i, *pa = actual + 4 * i;
            unsigned char *q = diff_rgba ? diff_rgba + 4 * i : NULL;
            int ch = largest_channel_difference(pe, pa);
            if (ch > res->max_channel)
                res->max_channel = ch;
            if (ch == 0 || !(yiq_distance(pe, pa) > limit)) {
                if (q)
                    paint_faded(q, pe);
            } else if (is_edge(&e, &a, x, y) || is_edge(&a, &e, x, y)) {
                res->aa++;
                if (q)
                    paint(q, 255, 255, 0);
            } else {
                res->differing++;
                mask[i] = 1;
                if (ch > res->max_channel_differing)
                    res->max_channel_differing = ch;
                if (ch > opts->hard_limit)
                    res->hard++;
                if (q)
                    paint(q, 255, 0, 0);
            }
        }
    int rc = worst_window(mask, w, h, res);
    free(mask);
    if (rc != 0) {
        lu_err(err, errlen, "diff: out of memory for %dx%d", w, h);
        return -1;
    }
    res->same = res->hard == 0 && res->differing <= opts->max_pixels &&
                res->window_max <= opts->max_window;
    return 0;
}

int lr_diff_files(const char *expected, const char *actual, const lr_diff_opts *opts,
                  const char *diff_path, lr_diff_result *res, char *err, size_t errlen)
{
    int we = 0, he = 0, wa = 0, ha = 0;
    unsigned char *pe = NULL, *pa = NULL, *pd = NULL;
    int rc = lr_png_read(expected, &we, &he, &pe, err, errlen);
    if (rc == 0)
        rc = lr_png_read(actual, &wa, &ha, &pa, err, errlen);
    if (rc == 0 && (we != wa || he != ha)) {
        lu_err(err, errlen, "size mismatch: %dx%d vs %dx%d ('%s' vs '%s')", we, he, wa,
                ha, expected, actual);
        rc = -1;
    }
    if (rc == 0 && diff_path) {
        pd = malloc(4 * (size_t)we * (size_t)he);
        if (!pd) {
            lu_err(err, errlen, "diff: out of memory for %dx%d", we, he);
            rc = -1;
        }
    }
    if (rc == 0)
        rc = lr_diff(pe, pa, we, he, opts, res, pd, err, errlen);
    if (rc == 0 && diff_path) {
        const lr_text_chunk text[] = { { "Software", "lamina " LAMINA_VERSION " diff" } };
        rc = lr_png_write(diff_path, we, he, pd, text, 1, err, errlen);
    }
    free(pe);
    free(pa);
    free(pd);
    return rc;
}

void lr_diff_summary(const lr_diff_result *r, const lr_diff_opts *opts, char *buf,
                     size_t len)
{
    lr_diff_opts defaults;
    if (!opts) {
        lr_diff_defaults(&defaults);
        opts = &defaults;
    }
    if (r->exact) {
        snprintf(buf, len, "same: identical pixels (%dx%d)", r->width, r->height);
        return;
    }
    snprintf(buf, len,
             "%s: %ld differing pixel%s (limit %ld), %ld in the worst %dx%d window at "
             "%d,%d (limit %ld), %ld over the hard limit %d; %ld anti-aliased; largest "
             "channel difference %d (%dx%d)",
             r->same ? "same" : "different", r->differing, r->differing == 1 ? "" : "s",
             opts->max_pixels, r->window_max, LR_DIFF_WINDOW, LR_DIFF_WINDOW, r->window_x,
             r->window_y, opts->max_window, r->hard, opts->hard_limit, r->aa,
             r->max_channel, r->width, r->height);
}
