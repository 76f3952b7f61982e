/* test_figure.c - figures (figure.h): panels, mirroring, the left/right
 * split, colour maps and bars, scale bars, SVG/PDF output, and the
 * promise that a one-panel figure is exactly the old frame. Pixels are
 * checked where the layout puts things, through every backend built. */
#include "check.h"
#include "figure.h"
#include "render.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char dir[] = "figure_test_XXXXXX";

static char *path(const char *name)
{
    static char buf[4][128];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

static const unsigned char *at(const unsigned char *img, int w, int x, int y)
{
    return img + 4 * ((size_t)y * (size_t)w + (size_t)x);
}

static int near(const unsigned char *p, lr_rgba k, int tol)
{
    return abs(p[0] - (int)(k.r * 255 + 0.5)) <= tol &&
           abs(p[1] - (int)(k.g * 255 + 0.5)) <= tol &&
           abs(p[2] - (int)(k.b * 255 + 0.5)) <= tol;
}

/* Pixels of colour k in the box x0..x1, y0..y1. */
static long count(const unsigned char *img, int w, int x0, int y0, int x1, int y1,
                  lr_rgba k)
{
    long n = 0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++)
            n += near(at(img, w, x, y), k, 3);
    return n;
}

static long file_size(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0 ? (long)st.st_size : -1;
}

static int backends(lr_backend b[2])
{
    b[0] = LR_BACKEND_CAIRO;
    b[1] = LR_BACKEND_OSMESA;
    return lr_backend_check(LR_BACKEND_OSMESA, NULL, 0) == 0 ? 2 : 1;
}

/* ---- the old frame, exactly --------------------------------------------- */

static void test_frame_is_figure(void)
{
    static const double x[] = { 0.3, 1.3, 1.7 }, y[] = { 0.3, 0.7, 0.3 };
    static const int g[] = { 0, 1, 0 };
    lr_grid grid = { 0, 0, 0.5, 0.5, 4, 2 };
    lr_frame f;
    memset(&f, 0, sizeof f);
    f.width = 200;
    f.height = 100;
    f.wx1 = 2;
    f.wy1 = 1;
    f.grid = &grid;
    f.n = 3;
    f.x = x;
    f.y = y;
    f.group = g;
    f.radius = 0.08;
    f.label = "t = 0.5";
    f.title = "title";
    char err[512] = "";
    CHECK(lr_frame_write(&f, path("frame.png"), err, sizeof err) == 0);
    lr_points pts = { 3, x, y, g, NULL, 0.08, NULL, 0, 0, NULL };
    lr_panel p;
    memset(&p, 0, sizeof p);
    p.wx1 = 2;
    p.wy1 = 1;
    p.side[0].grid = &grid;
    p.side[0].points = &pts;
    p.side[0].npoints = 1;
    lr_figure fig = { 200, 100, LR_BACKEND_CAIRO, &p, 1, 0, 0, "title", "t = 0.5", NULL, 0 };
    CHECK(lr_figure_write(&fig, path("figure.png"), err, sizeof err) == 0);
    int w, h, w2, h2;
    unsigned char *a = NULL, *b = NULL;
    CHECK(lr_png_read(path("frame.png"), &w, &h, &a, err, sizeof err) == 0);
    CHECK(lr_png_read(path("figure.png"), &w2, &h2, &b, err, sizeof err) == 0);
    CHECK(a && b && w == w2 && h == h2 && memcmp(a, b, 4 * (size_t)w * h) == 0);
    free(a);
    free(b);
    unlink(path("frame.png"));
    unlink(path("figure.png"));
}

/* ---- mirroring and splits ----------------------------------------------- */

/* One particle at (0.25, 0.25) of a quarter model on [0, 1]^2, mirrored in
 * x and y about the origin: four discs, at (+-0.25, +-0.25). */
static void test_mirror(lr_backend be)
{
    static const double x[] = { 0.25 }, y[] = { 0.25 };
    static const int g[] = { 1 };
    lr_points pts = { 1, x, y, g, NULL, 0.05, NULL, 0, 0, NULL };
    lr_grid grid = { 0, 0, 0.25, 0.25, 4, 4 };
    lr_panel p;
    memset(&p, 0, sizeof p);
    p.wx1 = p.wy1 = 1;
    p.mirror_x = p.mirror_y = 1;
    double win[4] = { 0, 0, 1, 1 };
    lr_panel_mirror_window(&p, win);
    CHECK(win[0] == -1 && win[1] == -1 && win[2] == 1 && win[3] == 1);
    p.wx0 = win[0];
    p.wy0 = win[1];
    p.side[0].grid = &grid;
    p.side[0].points = &pts;
    p.side[0].npoints = 1;
    lr_figure fig = { 200, 200, be, &p, 1, 0, 0, NULL, NULL, NULL, 0 };
    char err[512] = "";
    unsigned char *img = lr_figure_render(&fig, err, sizeof err);
    CHECK(img != NULL);
    if (!img)
        return;
    /* the window [-1, 1]^2 fills 200 - 2*8 px: 92 px per unit, origin at 100 */
    lr_rgba k = lr_palette(1);
    int found = 0;
    for (int sx = -1; sx <= 1; sx += 2)
        for (int sy = -1; sy <= 1; sy += 2) {
            int px = (int)(100 + sx * 0.25 * 92), py = (int)(100 - sy * 0.25 * 92);
            found += near(at(img, 200, px, py), k, 3);
        }
    CHECK(found == 4);
    CHECK(count(img, 200, 0, 0, 200, 200, k) < 4 * 60);
    free(img);
}

/* Bodies with radii of their own (lr_points.group_radius, sim:frame's
 * discs = "spacing"): group 1 drawn at 0.02, group 2 at 0.1, though the
 * common radius is 0.05; a group beyond ngroups keeps the common one. The
 * discs' pixel counts go as the radii squared (25 times apart). */
static void test_group_radius(lr_backend be)
{
    static const double x[] = { 0.25, 0.75, 0.5 }, y[] = { 0.5, 0.5, 0.2 };
    static const int g[] = { 1, 2, 3 };
    static const double gr[] = { 0.05, 0.02, 0.1 };
    lr_points pts = { 3, x, y, g, NULL, 0.05, gr, 3, 0, NULL };
    lr_panel p;
    memset(&p, 0, sizeof p);
    p.wx1 = p.wy1 = 1;
    p.side[0].points = &pts;
    p.side[0].npoints = 1;
    lr_figure fig = { 200, 200, be, &p, 1, 0, 0, NULL, NULL, NULL, 0 };
    char err[512] = "";
    unsigned char *img = lr_figure_render(&fig, err, sizeof err);
    CHECK(img != NULL);
    if (!img)
        return;
    int n1 = count(img, 200, 0, 0, 200, 200, lr_palette(1));
    int n2 = count(img, 200, 0, 0, 200, 200, lr_palette(2));
    int n3 = count(img, 200, 0, 0, 200, 200, lr_palette(3));
    CHECK(n1 > 0 && n2 > 15 * n1);        /* (0.1 / 0.02)^2 = 25, less the rims */
    CHECK(n3 > 3 * n1 && n3 < n2);        /* 0.05: between */
    free(img);
}

/* A band (lr_points.band, sim:frame's band = w): two points joined, each
 * half of the band in its own point's colour, by group and by value;
 * without the band only the small discs are there, and a point whose
 * next is -1 starts none. */
static long band_pixels(lr_backend be, double band, const double *v, lr_rgba left,
                        lr_rgba right, long *nright)
{
    static const double x[] = { 0.2, 0.8, 0.5 }, y[] = { 0.5, 0.5, 0.2 };
    static const int g[] = { 1, 2, 3 };
    static const long next[] = { 1, -1, -1 };
    lr_points pts = { 3, x, y, g, v, 0.02, NULL, 0, band, next };
    lr_panel p;
    memset(&p, 0, sizeof p);
    p.wx1 = p.wy1 = 1;
    p.vmin = 0;
    p.vmax = 1;
    p.side[0].points = &pts;
    p.side[0].npoints = 1;
    lr_figure fig = { 200, 200, be, &p, 1, 0, 0, NULL, NULL, NULL, 0 };
    char err[512] = "";
    unsigned char *img = lr_figure_render(&fig, err, sizeof err);
    CHECK(img != NULL);
    if (!img)
        return -1;
    long n = count(img, 200, 0, 0, 100, 200, left);
    *nright = count(img, 200, 100, 0, 200, 200, right);
    /* the third point's disc only: nothing between it and the others */
    CHECK(count(img, 200, 0, 0, 200, 200, lr_palette(3)) < 80);
    free(img);
    return n;
}

static void test_band(lr_backend be)
{
    long r0, r1;
    long l0 = band_pixels(be, 0, NULL, lr_palette(1), lr_palette(2), &r0);
    long l1 = band_pixels(be, 8, NULL, lr_palette(1), lr_palette(2), &r1);
    /* discs of radius ~4 px (~50 px each) against half bands ~55 x 8 px */
    CHECK(l0 > 10 && l0 < 80 && r0 > 10 && r0 < 80);
    CHECK(l1 > 5 * l0 && r1 > 5 * r0);
    static const double v[] = { 0.0, 1.0, 0.5 };
    lr_rgba lo = lr_cmap_colour(LR_CMAP_VIRIDIS, 0), hi = lr_cmap_colour(LR_CMAP_VIRIDIS, 1);
    long lv = band_pixels(be, 8, v, lo, hi, &r1);
    CHECK(lv > 5 * l0 && r1 > 5 * r0);
}

/* Two "runs" split at x = 0.5: the left shows only the first's particles,
 * the right only the second's, each side named. */
static void test_split(lr_backend be)
{
    static const double xa[] = { 0.25, 0.75 }, ya[] = { 0.5, 0.5 };
    static const int ga[] = { 0, 0 }, gb[] = { 1, 1 };
    lr_points a = { 2, xa, ya, ga, NULL, 0.06, NULL, 0, 0, NULL }, b = { 2, xa, ya, gb, NULL, 0.06, NULL, 0, 0, NULL };
    lr_panel p;
    memset(&p, 0, sizeof p);
    p.wx1 = p.wy1 = 1;
    p.split = 1;
    p.split_x = 0.5;
    p.side[0].points = &a;
    p.side[0].npoints = 1;
    p.side[0].name = "A";
    p.side[1].points = &b;
    p.side[1].npoints = 1;
    p.side[1].name = "B";
    lr_figure fig = { 200, 200, be, &p, 1, 0, 0, NULL, NULL, NULL, 0 };
    char err[512] = "";
    unsigned char *img = lr_figure_render(&fig, err, sizeof err);
    CHECK(img != NULL);
    if (!img)
        return;
    lr_rgba blue = lr_palette(0), red = lr_palette(1);
    CHECK(count(img, 200, 0, 0, 100, 200, blue) > 50);
    CHECK(count(img, 200, 0, 0, 100, 200, red) == 0);
    CHECK(count(img, 200, 100, 0, 200, 200, red) > 50);
    CHECK(count(img, 200, 100, 0, 200, 200, blue) == 0);
    free(img);
}

/* ---- panels, colour bars, scale bars ------------------------------------ */

static void test_panels_bars(lr_backend be)
{
    static const double x[] = { 0.2, 0.5, 0.8 }, y[] = { 0.5, 0.5, 0.5 };
    static const double v[] = { 0.0, 5.0, 10.0 };
    lr_points pts = { 3, x, y, NULL, v, 0.08, NULL, 0, 0, NULL };
    lr_panel p[2];
    memset(p, 0, sizeof p);
    for (int k = 0; k < 2; k++) {
        p[k].wx1 = p[k].wy1 = 1;
        p[k].side[0].points = &pts;
        p[k].side[0].npoints = 1;
        p[k].cmap = LR_CMAP_VIRIDIS;
        p[k].colourbar = 1;
        p[k].colourbar_label = "value";
    }
    p[0].title = "left";
    p[1].title = "right";
    p[1].vmin = 0;
    p[1].vmax = 20;          /* a fixed range: 10 is the middle */
    p[1].scalebar = 0.5;
    p[1].units = "m";
    lr_figure fig = { 600, 300, be, p, 2, 0, 0, "two panels", "label", NULL, 0 };
    char err[512] = "";
    unsigned char *img = lr_figure_render(&fig, err, sizeof err);
    CHECK(img != NULL);
    if (!img)
        return;
    lr_rgba lo = lr_cmap_colour(LR_CMAP_VIRIDIS, 0), hi = lr_cmap_colour(LR_CMAP_VIRIDIS, 1);
    lr_rgba mid = lr_cmap_colour(LR_CMAP_VIRIDIS, 0.5);
    /* the left panel's particles span the map, the right panel's top at
     * the middle; each colour bar holds both ends of the map */
    CHECK(count(img, 600, 0, 0, 300, 300, lo) > 60);
    CHECK(count(img, 600, 0, 0, 300, 300, hi) > 60);
    CHECK(count(img, 600, 300, 0, 600, 300, hi) > 0);      /* its bar */
    CHECK(count(img, 600, 300, 0, 600, 300, mid) > 40);
    /* the scale bar: a dark bar, 0.5 world units long, bottom right of
     * the right panel */
    int longest = 0;
    for (int yy = 150; yy < 300; yy++) {
        int run = 0;
        for (int xx = 300; xx < 600; xx++) {
            const unsigned char *q = at(img, 600, xx, yy);
            run = q[0] < 80 && q[1] < 80 && q[2] < 80 ? run + 1 : 0;
            if (run > longest)
                longest = run;
        }
    }
    CHECK(longest > 40 && longest < 200);
    free(img);
}

static void test_colormap(void)
{
    lr_rgba a = lr_cmap_colour(LR_CMAP_VIRIDIS, 0), b = lr_cmap_colour(LR_CMAP_VIRIDIS, 1);
    CHECK_NEAR(a.r * 255, 0x44, 1e-9);
    CHECK_NEAR(a.b * 255, 0x54, 1e-9);
    CHECK_NEAR(b.r * 255, 0xfd, 1e-9);
    CHECK_NEAR(b.g * 255, 0xe7, 1e-9);
    lr_rgba c = lr_cmap_colour(LR_CMAP_VIRIDIS, 2), n = lr_cmap_colour(LR_CMAP_RDBU, 0.0 / 0.0);
    CHECK(c.r == b.r && c.g == b.g);        /* clamped */
    CHECK(n.r == n.g && n.g == n.b);        /* NaN: grey */
    lr_rgba mid = lr_cmap_colour(LR_CMAP_RDBU, 0.5);
    CHECK_NEAR(mid.r * 255, 0xf7, 1e-9);
    lr_cmap m;
    char err[128] = "";
    CHECK(lr_cmap_parse("rdbu", &m, err, sizeof err) == 0 && m == LR_CMAP_RDBU);
    CHECK(lr_cmap_parse("jet", &m, err, sizeof err) == -1);
    CHECK(strstr(err, "unknown colour map 'jet'") != NULL);
}

/* ---- vector output and errors ------------------------------------------- */

static void test_vector_and_errors(void)
{
    static const double x[] = { 0.5 }, y[] = { 0.5 };
    lr_points pts = { 1, x, y, NULL, NULL, 0.1, NULL, 0, 0, NULL };
    lr_panel p;
    memset(&p, 0, sizeof p);
    p.wx1 = p.wy1 = 1;
    p.side[0].points = &pts;
    p.side[0].npoints = 1;
    p.scalebar = -1;
    lr_text_chunk text[] = { { "Software", "lamina test" } };
    lr_figure fig = { 300, 200, LR_BACKEND_CAIRO, &p, 1, 0, 0, "vector", "t", text, 1 };
    char err[512] = "";
    CHECK(lr_figure_write(&fig, path("f.svg"), err, sizeof err) == 0);
    CHECK(lr_figure_write(&fig, path("f.pdf"), err, sizeof err) == 0);
    CHECK(file_size(path("f.svg")) > 500);
    CHECK(file_size(path("f.pdf")) > 500);
    FILE *fp = fopen(path("f.svg"), "rb");
    char head[64] = "";
    if (fp) {
        CHECK(fread(head, 1, 63, fp) > 0);
        fclose(fp);
    }
    CHECK(strstr(head, "<?xml") != NULL);
    fp = fopen(path("f.pdf"), "rb");
    if (fp) {
        CHECK(fread(head, 1, 8, fp) == 8);
        fclose(fp);
    }
    CHECK(memcmp(head, "%PDF-", 5) == 0);
    unlink(path("f.svg"));
    unlink(path("f.pdf"));

    /* SVG through OSMesa: refused, nothing written */
    fig.backend = LR_BACKEND_OSMESA;
    CHECK(lr_figure_write(&fig, path("g.svg"), err, sizeof err) == -1);
    CHECK(strstr(err, "drawn by cairo") != NULL);
    CHECK(file_size(path("g.svg")) == -1);
    fig.backend = LR_BACKEND_CAIRO;

    /* an unwritable path: an error naming it, for vector files too */
    CHECK(lr_figure_write(&fig, "/proc/lamina/no.pdf", err, sizeof err) == -1);
    CHECK(strstr(err, "/proc/lamina/no.pdf") != NULL);

    /* bad figures */
    fig.width = 0;
    CHECK(lr_figure_write(&fig, path("h.png"), err, sizeof err) == -1);
    CHECK(strstr(err, "image size must be positive") != NULL);
    fig.width = 300;
    fig.rows = 1;
    fig.cols = 1;
    fig.npanels = 2;
    lr_panel two[2] = { p, p };
    fig.panels = two;
    CHECK(lr_figure_write(&fig, path("h.png"), err, sizeof err) == -1);
    CHECK(strstr(err, "fewer cells than panels") != NULL);
    fig.rows = fig.cols = 0;
    two[1].wx1 = two[1].wx0;
    CHECK(lr_figure_write(&fig, path("h.png"), err, sizeof err) == -1);
    CHECK(strstr(err, "world window") != NULL);
    CHECK(file_size(path("h.png")) == -1);
}

/* ---- filled contours ---------------------------------------------------- */

/* f = x on [0, 1]: the region f >= 0.5 is the right half. Through both
 * backends the two halves are cleanly coloured, with no seams between
 * the cells of the filled region. */
static void test_filled_contour(lr_backend be)
{
    enum { N = 10 };
    static double f[(N + 1) * (N + 1)];
    for (int j = 0; j <= N; j++)
        for (int i = 0; i <= N; i++)
            f[i + (N + 1) * j] = (double)i / N;
    double level = 0.5;
    lr_rgba red = { 1, 0, 0, 1 };
    lr_field fd = { f, N, N, 0, 0, 1, 1, &level, 1, &red };
    lr_panel p;
    memset(&p, 0, sizeof p);
    p.wx1 = p.wy1 = 1;
    p.side[0].fields = &fd;
    p.side[0].nfields = 1;
    lr_figure fig = { 116, 116, be, &p, 1, 0, 0, NULL, NULL, NULL, 0 };
    char err[256] = "";
    unsigned char *img = lr_figure_render(&fig, err, sizeof err);
    CHECK(img != NULL);
    if (!img)
        return;
    /* window 100 x 100 px from (8, 8): x = 0.5 at pixel 58 */
    CHECK(count(img, 116, 60, 10, 106, 106, red) == 46 * 96);
    CHECK(count(img, 116, 10, 10, 56, 106, red) == 0);
    free(img);
}

/* ---- overlays: clipped to the window, arrows thinned -------------------- */

/* Red pixels in row y between x0 and x1 that start a run (arrows crossed). */
static int runs(const unsigned char *img, int w, int y, int x0, int x1, lr_rgba k)
{
    int n = 0, in = 0;
    for (int x = x0; x < x1; x++) {
        int r = near(at(img, w, x, y), k, 60);
        n += r && !in;
        in = r;
    }
    return n;
}

/* An arrow and a curve that run out of the window end at its edge (issue
 * 32: they were drawn over the title and the next panel). In a 116 px
 * figure the window spans pixels 4.06 to 111.94 (margins 3.5 %). */
static void test_overlay_clip(lr_backend be)
{
    static const double ax[] = { 0.5 }, ay[] = { 0.3 }, ux[] = { 1 }, uy[] = { 0 };
    static const double cx[] = { 0.5, 3.0 }, cy[] = { 0.7, 0.7 };
    const lr_rgba red = { 1, 0, 0, 1 };
    lr_arrows a = { .n = 1, .x = ax, .y = ay, .ux = ux, .uy = uy, .length = 2.0,
                    .width = 3.0, .head = 6.0, .colour = red };
    lr_curve c = { .n = 2, .x = cx, .y = cy, .width = 3.0, .colour = red };
    lr_panel p;
    memset(&p, 0, sizeof p);
    p.wx1 = p.wy1 = 1;
    p.side[0].arrows = &a;
    p.side[0].narrows = 1;
    p.side[0].curves = &c;
    p.side[0].ncurves = 1;
    lr_figure fig = { 116, 116, be, &p, 1, 0, 0, NULL, NULL, NULL, 0 };
    char err[256] = "";
    unsigned char *img = lr_figure_render(&fig, err, sizeof err);
    CHECK(img != NULL);
    if (!img)
        return;
    CHECK(count(img, 116, 60, 70, 111, 80, red) > 45 * 2);     /* the arrow, y = 0.3 */
    CHECK(count(img, 116, 60, 30, 111, 40, red) > 45 * 2);     /* the curve, y = 0.7 */
    CHECK(count(img, 116, 112, 0, 116, 116, red) == 0);        /* nothing past x = 1 */
    free(img);
}

/* lr_arrows.thin: 17 arrows 0.05 apart (5.39 px at 107.88 px a unit),
 * thin 16 px: every 3rd (ceil(16 / 5.39)), each 3 spacings = 0.15 long. */
static void test_arrow_thinning(lr_backend be)
{
    enum { N = 17 };
    double x[N], y[N], ux[N], uy[N];
    for (int i = 0; i < N; i++) {
        x[i] = 0.1 + 0.05 * i;
        y[i] = 0.3;
        ux[i] = 0;
        uy[i] = 1;
    }
    const lr_rgba red = { 1, 0, 0, 1 };
    lr_arrows a = { .n = N, .x = x, .y = y, .ux = ux, .uy = uy, .length = 0.6,
                    .width = 2.0, .head = 5.0, .colour = red, .thin = 16, .spacing = 0.05 };
    lr_panel p;
    memset(&p, 0, sizeof p);
    p.wx1 = p.wy1 = 1;
    p.side[0].arrows = &a;
    p.side[0].narrows = 1;
    lr_figure fig = { 116, 116, be, &p, 1, 0, 0, NULL, NULL, NULL, 0 };
    char err[256] = "";
    unsigned char *img = lr_figure_render(&fig, err, sizeof err);
    CHECK(img != NULL);
    if (!img)
        return;
    /* shafts cross y = 0.35 (pixel 74); the heads end at y = 0.45 (pixel 63) */
    CHECK(runs(img, 116, 74, 4, 112, red) == 6);      /* points 0, 3, ..., 15 */
    CHECK(count(img, 116, 4, 4, 112, 58, red) == 0);  /* none reaches 0.5, let alone 0.9 */
    CHECK(count(img, 116, 4, 62, 112, 68, red) > 12); /* the heads, near 0.45 */
    free(img);
}

int main(void)
{
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    lr_backend be[2];
    int nb = backends(be);
    test_colormap();
    test_frame_is_figure();
    for (int i = 0; i < nb; i++) {
        test_mirror(be[i]);
        test_group_radius(be[i]);
        test_band(be[i]);
        test_split(be[i]);
        test_panels_bars(be[i]);
        test_filled_contour(be[i]);
        test_overlay_clip(be[i]);
        test_arrow_thinning(be[i]);
    }
    test_vector_and_errors();
    CHECK(rmdir(dir) == 0);
    lr_shutdown();
    return CHECK_DONE();
}
