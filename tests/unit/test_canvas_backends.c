/* test_canvas_backends.c - cairo, OSMesa and EGL draw the same pictures.
 *
 * The reference scene (a figure: grid, 4096 particles in five colours,
 * dashed and solid lines, normal arrows, a filled contour field, a star,
 * text, a colour bar, a scale bar) is rendered through every backend this
 * lamina has and compared with the diff tool (lr_diff): each GL backend
 * against cairo, and EGL against OSMesa; at most 0.5 % of the pixels may
 * differ beyond anti-aliasing (issues 5, 20). Measured on Debian 12 (cairo
 * 1.16.0, Mesa 22.3.6 llvmpipe):
 *   - cairo vs OSMesa and cairo vs EGL: 13 of 307200 pixels (0.004 %)
 *     differ beyond anti-aliasing, the largest channel difference is 51;
 *     15 % of the pixels differ at all, nearly all by 1 to 5 levels (8-bit
 *     blending rounds differently in GL and pixman);
 *   - OSMesa vs EGL: none beyond anti-aliasing; 160 pixels (0.05 %) differ
 *     at all, by one level: the same drawing code and rasteriser, into an
 *     OSMesa buffer or a framebuffer object; only lines' edges round
 *     differently (discs, fills and text alone come out byte for byte).
 *
 * Also, per backend: rows come back top to bottom (GL reads bottom-up),
 * premultiplied colour comes back straight, clips, the nonzero fill rule,
 * dashes, large discs; asking for a backend that is not built (or, EGL,
 * cannot start) is a clear error naming what to install; "gl" means EGL
 * where it starts; an OSMesa and an EGL canvas drawn in turns keep apart. */
#include "check.h"
#include "diff.h"
#include "figure.h"
#include "render.h"

#include <stdlib.h>
#include <string.h>

enum { W = 640, H = 480 };

static const lr_rgba WHITE = { 1, 1, 1, 1 };
static const lr_rgba RED = { 1, 0, 0, 1 };
static const lr_rgba BLUE = { 0, 0, 1, 1 };

static const unsigned char *px(const unsigned char *img, int w, int x, int y)
{
    return img + 4 * ((size_t)y * (size_t)w + (size_t)x);
}

static int is(const unsigned char *p, int r, int g, int b, int a, int tol)
{
    return abs(p[0] - r) <= tol && abs(p[1] - g) <= tol && abs(p[2] - b) <= tol &&
           abs(p[3] - a) <= tol;
}

/* ---- the reference scene ------------------------------------------------ */

enum { NP = 4096, NF = 40 };

typedef struct scene {
    double x[NP], y[NP];
    int group[NP];
    double ax[64], ay[64], aux[64], auy[64];
    double cx[97], cy[97];
    double field[(NF + 1) * (NF + 1)];
    double levels[3];
    lr_grid grid;
    lr_points pts;
    lr_arrows arrows;
    lr_curve curves[2];
    lr_field fill;
    lr_panel panel[2];
    lr_figure fig;
} scene;

/* A small LCG: the same scene on every machine. */
static double rnd(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (*s >> 8) / 16777216.0;
}

static void make_scene(scene *s)
{
    memset(s, 0, sizeof *s);
    unsigned seed = 12345;
    /* five blobs of lattice particles, a little jittered */
    for (int i = 0; i < NP; i++) {
        int g = i % 5, k = i / 5;
        double cx = 0.2 + 0.15 * g, cy = 0.3 + 0.1 * (g % 3);
        s->x[i] = cx + 0.012 * (k % 27 - 13) + 0.002 * rnd(&seed);
        s->y[i] = cy + 0.012 * (k / 27 - 15) + 0.002 * rnd(&seed);
        s->group[i] = g;
    }
    s->grid = (lr_grid){ 0.0, 0.0, 1.0 / 32, 1.0 / 24, 32, 24 };
    s->pts = (lr_points){ NP, s->x, s->y, s->group, NULL, 0.0045, NULL, 0, 0, NULL };
    for (int i = 0; i < 64; i++) {      /* normals round a circle */
        double a = 6.283185307179586 * i / 64;
        s->ax[i] = 0.5 + 0.3 * cos(a);
        s->ay[i] = 0.45 + 0.3 * sin(a);
        s->aux[i] = cos(a);
        s->auy[i] = sin(a);
    }
    const lr_rgba dark = { 0.1, 0.1, 0.1, 1 };
    s->arrows = (lr_arrows){ 64, s->ax, s->ay, s->aux, s->auy, 0.06, 1.5, 7.0, 0.0, dark, 0, 0 };
    for (int i = 0; i < 97; i++) {      /* a wavy line and a dashed circle */
        double t = i / 96.0;
        s->cx[i] = 0.05 + 0.9 * t;
        s->cy[i] = 0.9 + 0.04 * sin(18.0 * t);
    }
    const lr_rgba green = { 0.0, 0.55, 0.3, 1 }, grey = { 0.3, 0.3, 0.3, 1 };
    s->curves[0] = (lr_curve){ 97, s->cx, s->cy, 0, 2.0, 0.0, green, 0 };
    s->curves[1] = (lr_curve){ 64, s->ax, s->ay, 1, 1.0, 5.0, grey, 0 };
    for (int j = 0; j <= NF; j++)       /* a bump: filled contour bands */
        for (int i = 0; i <= NF; i++) {
            double x = (double)i / NF - 0.5, y = (double)j / NF - 0.5;
            s->field[i + (NF + 1) * j] = exp(-8.0 * (x * x + 2.0 * y * y));
        }
    s->levels[0] = 0.25;
    s->levels[1] = 0.5;
    s->levels[2] = 0.75;
    s->fill = (lr_field){ s->field, NF, NF, 0.55, 0.05, 0.95, 0.35, s->levels, 3, NULL };

    lr_panel *p = &s->panel[0];
    p->wx1 = 1.0;
    p->wy1 = 1.0;
    p->side[0].grid = &s->grid;
    p->side[0].points = &s->pts;
    p->side[0].npoints = 1;
    p->side[0].arrows = &s->arrows;
    p->side[0].narrows = 1;
    p->side[0].curves = s->curves;
    p->side[0].ncurves = 2;
    p->side[0].fields = &s->fill;
    p->side[0].nfields = 1;
    p->title = "reference";
    p->colourbar = 1;
    p->colourbar_label = "phi";
    p->vmin = 0.0;
    p->vmax = 1.0;
    p->scalebar = -1;
    p->units = "m";
    /* the second panel: the same particles mirrored about x = 0 */
    s->panel[1] = s->panel[0];
    s->panel[1].title = "mirrored";
    s->panel[1].colourbar = 0;
    s->panel[1].mirror_x = 1;
    s->panel[1].wx0 = -1.0;
    s->fig = (lr_figure){ W, H, LR_BACKEND_CAIRO, s->panel, 2, 0, 0,
                          "cairo and OSMesa", "t = 1.2345   step 678", NULL, 0 };
}

static unsigned char *render(scene *s, lr_backend b)
{
    char err[512] = "";
    s->fig.backend = b;
    unsigned char *img = lr_figure_render(&s->fig, err, sizeof err);
    if (!img)
        fprintf(stderr, "render (%s): %s\n", lr_backend_name(b), err);
    return img;
}

/* Holds b's picture to a's: at most 0.5 % of the pixels differ beyond
 * anti-aliasing, and the picture is not blank. */
static void compare(const char *an, const unsigned char *a, const char *bn,
                    const unsigned char *b)
{
    lr_diff_opts o;
    lr_diff_defaults(&o);
    o.max_pixels = (long)(0.005 * W * H);   /* 0.5 % */
    o.max_window = W * H;                   /* judged overall */
    o.hard_limit = 255;
    lr_diff_result r;
    char err[256] = "", line[512];
    CHECK(lr_diff(a, b, W, H, &o, &r, NULL, err, sizeof err) == 0);
    lr_diff_summary(&r, &o, line, sizeof line);
    printf("%s vs %s, reference scene %dx%d: %s\n", an, bn, W, H, line);
    printf("  beyond anti-aliasing: %ld pixels = %.3f %% (limit 0.5 %%)\n",
           r.differing, 100.0 * r.differing / (W * H));
    CHECK(r.differing <= o.max_pixels);
    CHECK(r.same);
    long ink = 0, ident = 0;
    for (long i = 0; i < (long)W * H; i++) {
        ink += b[4 * i] < 200;
        ident += memcmp(a + 4 * i, b + 4 * i, 4) == 0;
    }
    printf("  identical pixels: %ld of %ld\n", ident, (long)W * H);
    CHECK(ink > W * H / 20);
}

static void test_reference_scene(void)
{
    static scene s;
    make_scene(&s);
    unsigned char *img[LR_BACKEND_COUNT] = { NULL };
    char err[256] = "", path[64];
    for (int b = 0; b < LR_BACKEND_COUNT; b++) {
        if (lr_backend_check((lr_backend)b, NULL, 0) != 0)
            continue;
        img[b] = render(&s, (lr_backend)b);
        CHECK(img[b] != NULL);
        snprintf(path, sizeof path, "backends_reference_%s.png",
                 lr_backend_name((lr_backend)b));
        if (img[b])
            lr_png_write(path, W, H, img[b], NULL, 0, err, sizeof err);
    }
    const unsigned char *cairo = img[LR_BACKEND_CAIRO];
    const unsigned char *osmesa = img[LR_BACKEND_OSMESA], *egl = img[LR_BACKEND_EGL];
    if (cairo && osmesa)
        compare("cairo", cairo, "osmesa", osmesa);
    if (cairo && egl)
        compare("cairo", cairo, "egl", egl);
    /* the same GL code on the same Mesa: expected identical, held to the
     * same limit since another driver (a GPU) may round otherwise */
    if (osmesa && egl)
        compare("osmesa", osmesa, "egl", egl);
    for (int b = 0; b < LR_BACKEND_COUNT; b++)
        free(img[b]);
}

/* An OSMesa and an EGL canvas alive at once, drawn in turns: each one's
 * drawing lands in its own pixels (the two share Mesa's GL dispatch, and
 * canvas_gl.c must switch it between them). */
static void test_interleaved(void)
{
    char err[256] = "";
    lr_canvas *o = lr_canvas_new(LR_BACKEND_OSMESA, 32, 32, err, sizeof err);
    lr_canvas *e = lr_canvas_new(LR_BACKEND_EGL, 32, 32, err, sizeof err);
    CHECK(o != NULL && e != NULL);
    if (o && e) {
        lr_canvas_clear(o, WHITE);
        lr_canvas_clear(e, WHITE);
        double x = 8, y = 8, x2 = 24, y2 = 24;
        lr_canvas_discs(o, 1, &x, &y, 4.0, &RED);
        lr_canvas_discs(e, 1, &x2, &y2, 4.0, &BLUE);
        lr_canvas_line(o, 0, 30.5, 32, 30.5, 1.0, BLUE, 0.0);
        unsigned char *pe = lr_canvas_read_rgba(e), *po = lr_canvas_read_rgba(o);
        CHECK(po && pe);
        if (po && pe) {
            CHECK(is(px(po, 32, 8, 8), 255, 0, 0, 255, 0));
            CHECK(is(px(po, 32, 24, 24), 255, 255, 255, 255, 0));
            CHECK(is(px(po, 32, 16, 30), 0, 0, 255, 255, 0));
            CHECK(is(px(pe, 32, 24, 24), 0, 0, 255, 255, 0));
            CHECK(is(px(pe, 32, 8, 8), 255, 255, 255, 255, 0));
            CHECK(is(px(pe, 32, 16, 30), 255, 255, 255, 255, 0));
        }
        free(po);
        free(pe);
    }
    lr_canvas_free(o);
    lr_canvas_free(e);
}

/* ---- per backend -------------------------------------------------------- */

static void test_basics(lr_backend be)
{
    char err[256] = "";
    lr_canvas *c = lr_canvas_new(be, 64, 48, err, sizeof err);
    CHECK(c != NULL);
    if (!c) {
        fprintf(stderr, "%s\n", err);
        return;
    }
    CHECK(lr_canvas_backend(c) == be);
    lr_canvas_clear(c, WHITE);
    /* a red disc near the top left, a blue one near the bottom right */
    double x1 = 10, y1 = 8, x2 = 50, y2 = 38;
    lr_canvas_discs(c, 1, &x1, &y1, 4.0, &RED);
    lr_canvas_discs(c, 1, &x2, &y2, 4.0, &BLUE);
    /* half-transparent red over white: straight alpha back */
    lr_rgba half = { 1, 0, 0, 0.5 };
    double hx = 32.5, hy = 24.5;
    lr_canvas_discs(c, 1, &hx, &hy, 3.0, &half);
    /* a clip: nothing outside it */
    lr_canvas_clip(c, 0, 40, 20, 8);
    lr_canvas_line(c, 0, 44.5, 64, 44.5, 3.0, BLUE, 0.0);
    lr_canvas_unclip(c);
    unsigned char *img = lr_canvas_read_rgba(c);
    CHECK(img != NULL);
    if (img) {
        CHECK(is(px(img, 64, 10, 8), 255, 0, 0, 255, 0));      /* rows top down */
        CHECK(is(px(img, 64, 50, 38), 0, 0, 255, 255, 0));
        CHECK(is(px(img, 64, 10, 38), 255, 255, 255, 255, 0));
        CHECK(is(px(img, 64, 32, 24), 255, 128, 128, 255, 2)); /* half red on white */
        int inside = 0, outside = 0;
        for (int x = 0; x < 64; x++)
            for (int y = 28; y < 48; y++) {
                const unsigned char *p = px(img, 64, x, y);
                int blue = p[2] > 200 && p[0] < 100;
                if (x < 20 && y >= 40)
                    inside += blue;
                else if (!(x == 50 && y == 38) && (x < 45 || y < 33))
                    outside += blue;
            }
        CHECK(inside > 10);
        CHECK(outside == 0);
    }
    free(img);

    /* a translucent clear comes back straight */
    lr_rgba clear = { 0.0, 0.5, 1.0, 0.5 };
    lr_canvas_clear(c, clear);
    img = lr_canvas_read_rgba(c);
    CHECK(img && is(px(img, 64, 5, 5), 0, 128, 255, 128, 1));
    free(img);
    lr_canvas_free(c);
}

/* Nonzero winding: a ring (outer clockwise, inner anticlockwise) has a
 * hole; two overlapping rings of one orientation unite. Dashes leave gaps.
 * Large discs are drawn (GL: beyond the largest point sprite). */
static void test_fills_dashes(lr_backend be)
{
    char err[256] = "";
    lr_canvas *c = lr_canvas_new(be, 400, 300, err, sizeof err);
    CHECK(c != NULL);
    if (!c)
        return;
    lr_canvas_clear(c, WHITE);
    double ring[16] = { 10, 10, 110, 10, 110, 110, 10, 110,
                        40, 40, 40, 80, 80, 80, 80, 40 };
    size_t counts[2] = { 4, 4 };
    lr_canvas_fill(c, 2, counts, ring, BLUE);
    double two[16] = { 130, 10, 190, 10, 190, 70, 130, 70,
                       160, 40, 220, 40, 220, 100, 160, 100 };
    lr_canvas_fill(c, 2, counts, two, RED);
    lr_canvas_line(c, 10, 150.5, 210, 150.5, 1.0, BLUE, 10.0);
    double bx = 300, by = 200;
    lr_canvas_discs(c, 1, &bx, &by, 150.0, &RED);     /* covers the right part */
    unsigned char *img = lr_canvas_read_rgba(c);
    CHECK(img != NULL);
    if (img) {
        CHECK(is(px(img, 400, 20, 20), 0, 0, 255, 255, 0));
        CHECK(is(px(img, 400, 60, 60), 255, 255, 255, 255, 0));    /* the hole */
        CHECK(is(px(img, 400, 175, 55), 255, 0, 0, 255, 0));       /* the overlap */
        CHECK(is(px(img, 400, 15, 150), 0, 0, 255, 255, 0));       /* dash 0..10 */
        CHECK(is(px(img, 400, 25, 150), 255, 255, 255, 255, 0));   /* gap 10..20 */
        CHECK(is(px(img, 400, 35, 150), 0, 0, 255, 255, 0));
        CHECK(is(px(img, 400, 300, 200), 255, 0, 0, 255, 0));      /* big disc */
        CHECK(is(px(img, 400, 399, 299), 255, 0, 0, 255, 0));
        CHECK(is(px(img, 400, 140, 200), 255, 255, 255, 255, 0));  /* r = 150 */
    }
    free(img);
    lr_canvas_free(c);
}

/* A backend that is not built, or cannot start, is a clear error that
 * names what to install. */
static void test_unavailable(lr_backend b)
{
    char err[256] = "";
    lr_canvas *c = lr_canvas_new(b, 64, 64, err, sizeof err);
    CHECK(c == NULL);
    printf("%s: %s\n", lr_backend_name(b), err);
    CHECK(strstr(err, b == LR_BACKEND_OSMESA ? "built without OSMesa (install libosmesa6-dev"
                                             : "libegl-mesa0") != NULL);
    lr_canvas_free(c);
}

static void test_names(void)
{
    lr_backend b = LR_BACKEND_CAIRO;
    char err[256] = "";
    CHECK(lr_backend_parse("osmesa", &b, err, sizeof err) == 0 && b == LR_BACKEND_OSMESA);
    CHECK(lr_backend_parse("cairo", &b, err, sizeof err) == 0 && b == LR_BACKEND_CAIRO);
    CHECK(lr_backend_parse("vulkan", &b, err, sizeof err) == -1);
    CHECK(strstr(err, "unknown backend 'vulkan' (known: cairo, osmesa, egl, gl)") != NULL);
    CHECK(lr_backend_parse("egl", &b, err, sizeof err) == 0 && b == LR_BACKEND_EGL);
    CHECK(strcmp(lr_backend_name(LR_BACKEND_EGL), "egl") == 0);
    /* "gl": EGL when it starts, else OSMesa when built */
    CHECK(lr_backend_parse("gl", &b, err, sizeof err) == 0);
    if (lr_backend_check(LR_BACKEND_EGL, NULL, 0) == 0)
        CHECK(b == LR_BACKEND_EGL);
    else if (lr_backend_check(LR_BACKEND_OSMESA, NULL, 0) == 0)
        CHECK(b == LR_BACKEND_OSMESA);
    printf("gl means %s here\n", lr_backend_name(b));
    CHECK(lr_canvas_new(LR_BACKEND_CAIRO, 0, 10, err, sizeof err) == NULL);
    CHECK(strstr(err, "invalid size 0x10") != NULL);
    CHECK(lr_canvas_new(LR_BACKEND_CAIRO, 10, 16385, err, sizeof err) == NULL);
    CHECK(strstr(err, "1..16384") != NULL);
    CHECK(lr_format_of("a/b.SVG") == LR_FORMAT_SVG);
    CHECK(lr_format_of("b.pdf") == LR_FORMAT_PDF);
    CHECK(lr_format_of("b.png") == LR_FORMAT_PNG && lr_format_of("pdf") == LR_FORMAT_PNG);
}

int main(void)
{
    test_names();
    test_basics(LR_BACKEND_CAIRO);
    test_fills_dashes(LR_BACKEND_CAIRO);
    for (int b = LR_BACKEND_OSMESA; b < LR_BACKEND_COUNT; b++) {
        if (lr_backend_check((lr_backend)b, NULL, 0) == 0) {
            test_basics((lr_backend)b);
            test_fills_dashes((lr_backend)b);
        } else {
            printf("%s not built or not starting: checking that asking for it "
                   "is a clear error\n", lr_backend_name((lr_backend)b));
            test_unavailable((lr_backend)b);
        }
    }
    test_reference_scene();
    if (lr_backend_check(LR_BACKEND_OSMESA, NULL, 0) == 0 &&
        lr_backend_check(LR_BACKEND_EGL, NULL, 0) == 0)
        test_interleaved();
    lr_shutdown();
    return CHECK_DONE();
}
