/* test_frame.c - lr_frame_write: layout, colours, grid, label, determinism;
 * and the canvas behaviour frames rely on (straight alpha, robust text). */
#include "check.h"
#include "test_files.h"
#include "render.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

enum { W = 200, H = 100 };

static char dir[] = "render_test_XXXXXX";
static char path_a[64], path_b[64], path_bad[64];

/* The layout frame.c promises for this frame (label, no title): margin 4%
 * of the smaller side, a label band of 1.5 x 12 px, the 2x1 window fitted
 * and centred in the rest: 74 px per unit, world origin at pixel (26, 78).
 * The checks below search a few pixels around these, so a small change of
 * margins does not break them; the colour checks sit well inside discs. */
static void expected_pixel(double x, double y, int *px, int *py)
{
    const double s = 74.0, ox = 26.0, oy = 78.0;
    *px = (int)(ox + s * x);
    *py = (int)(oy - s * y);
}

static const lr_grid grid = { 0.0, 0.0, 0.5, 0.5, 4, 2 };
static const double px_[] = { 0.3, 1.3, 1.7 };
static const double py_[] = { 0.3, 0.7, 0.3 };
static const int group[] = { 0, 1, 0 };
static const lr_text_chunk text[] = { { "Software", "lamina test" } };

static lr_frame test_frame(void)
{
    lr_frame f;
    memset(&f, 0, sizeof f);
    f.width = W;
    f.height = H;
    f.wx0 = 0.0;
    f.wy0 = 0.0;
    f.wx1 = 2.0;
    f.wy1 = 1.0;
    f.grid = &grid;
    f.n = 3;
    f.x = px_;
    f.y = py_;
    f.group = group;
    f.radius = 0.08;        /* about 6 px: the centre pixel is fully covered */
    f.label = "t = 0.5000";
    f.text = text;
    f.ntext = 1;
    return f;
}

static const unsigned char *at(const unsigned char *img, int x, int y)
{
    return img + 4 * ((size_t)y * W + (size_t)x);
}

static int is_white(const unsigned char *p)
{
    return p[0] == 255 && p[1] == 255 && p[2] == 255 && p[3] == 255;
}

/* Opaque grey, r = g = b in [lo, hi]. */
static int is_grey(const unsigned char *p, int lo, int hi)
{
    return p[0] == p[1] && p[1] == p[2] && p[3] == 255 && p[0] >= lo &&
           p[0] <= hi;
}

static void check_colour(const unsigned char *p, lr_rgba want)
{
    CHECK_NEAR(p[0], want.r * 255.0, 2.0);
    CHECK_NEAR(p[1], want.g * 255.0, 2.0);
    CHECK_NEAR(p[2], want.b * 255.0, 2.0);
    CHECK(p[3] == 255);
}

static void test_palette(void)
{
    lr_rgba a = lr_palette(0), b = lr_palette(1), c = lr_palette(8);
    lr_rgba d = lr_palette(-1), e = lr_palette(7);
    CHECK(a.r != b.r || a.g != b.g || a.b != b.b);
    CHECK(a.r == c.r && a.g == c.g && a.b == c.b);      /* cycled */
    CHECK(d.r == e.r && d.g == e.g && d.b == e.b);      /* negative too */
    CHECK(a.a == 1.0 && b.a == 1.0);
}

/* Where the dark outline crosses row y (first, last column); -1 if not. */
static void dark_span_row(const unsigned char *img, int y, int *first, int *last)
{
    *first = *last = -1;
    for (int x = 0; x < W; x++)
        if (is_grey(at(img, x, y), 0, 140)) {
            if (*first < 0)
                *first = x;
            *last = x;
        }
}

static void dark_span_col(const unsigned char *img, int x, int *first, int *last)
{
    *first = *last = -1;
    for (int y = 0; y < H; y++)
        if (is_grey(at(img, x, y), 0, 140)) {
            if (*first < 0)
                *first = y;
            *last = y;
        }
}

static void check_layout(const unsigned char *img)
{
    /* the domain outline: a 2x1 box, centred, inside the margins */
    int x0, x1, y0, y1;
    dark_span_row(img, 20, &x0, &x1);
    dark_span_col(img, 140, &y0, &y1);
    CHECK(x0 > 0 && x1 < W - 1 && y0 > 0 && y1 < H - 12);
    CHECK_NEAR(0.5 * (x0 + x1), 0.5 * W, 1.0);
    CHECK_NEAR((double)(x1 - x0) / (y1 - y0), 2.0, 0.05);

    /* light grey cell lines at world x = 1 and y = 0.5 */
    int px, py, found = 0;
    expected_pixel(1.0, 0.5, &px, &py);
    for (int x = px - 3; x <= px + 3; x++)
        found += is_grey(at(img, x, 20), 200, 235);
    CHECK(found == 1);      /* crisp: one pixel wide */
    found = 0;
    for (int y = py - 3; y <= py + 3; y++)
        found += is_grey(at(img, 40, y), 200, 235);
    CHECK(found == 1);

    /* the label: dark text somewhere in the bottom-left band */
    int dark = 0;
    for (int y = y1 + 2; y < H; y++)
        for (int x = 0; x < W / 2; x++)
            dark += at(img, x, y)[0] < 100;
    CHECK(dark > 20);
}

static void check_frame_pixels(const char *path)
{
    int w = 0, h = 0;
    unsigned char *img = NULL;
    char err[512] = "";
    CHECK(lr_png_read(path, &w, &h, &img, err, sizeof err) == 0);
    CHECK(w == W && h == H);
    if (!img || w != W || h != H) {
        fprintf(stderr, "%s\n", err);
        free(img);
        return;
    }
    CHECK(is_white(at(img, 0, 0)));
    CHECK(is_white(at(img, W - 1, 0)));
    CHECK(is_white(at(img, W - 1, H - 1)));
    for (int i = 0; i < 3; i++) {
        int px, py;
        expected_pixel(px_[i], py_[i], &px, &py);
        check_colour(at(img, px, py), lr_palette(group[i]));
    }
    check_layout(img);
    free(img);
}

static void test_frame_write(void)
{
    lr_frame f = test_frame();
    char err[512] = "";
    CHECK(lr_frame_write(&f, path_a, err, sizeof err) == 0);
    check_frame_pixels(path_a);

    /* the same frame twice: the same bytes */
    CHECK(lr_frame_write(&f, path_b, err, sizeof err) == 0);
    long na = -1, nb = -2;
    unsigned char *a = slurp(path_a, &na), *b = slurp(path_b, &nb);
    CHECK(a && b && na == nb && memcmp(a, b, (size_t)na) == 0);
    free(a);
    free(b);
}

/* A zero radius is still drawn (at least 1 px); bad frames are refused. */
static void test_edges(void)
{
    lr_frame f = test_frame();
    char err[512] = "";
    f.radius = 0.0;
    f.title = "a title";
    CHECK(lr_frame_write(&f, path_b, err, sizeof err) == 0);
    int w, h, found = 0;
    unsigned char *img = NULL;
    CHECK(lr_png_read(path_b, &w, &h, &img, err, sizeof err) == 0);
    for (int i = 0; img && i < 4 * W * H; i += 4)
        found += img[i] < 60 && img[i + 2] > 100;     /* blue-ish */
    CHECK(found >= 2);
    free(img);

    f = test_frame();
    f.wx1 = f.wx0;
    struct stat st;
    CHECK(lr_frame_write(&f, path_bad, err, sizeof err) == -1);
    CHECK(strstr(err, path_bad) != NULL);
    CHECK(stat(path_bad, &st) != 0);
}

static void test_canvas(void)
{
    char err[256] = "";
    lr_canvas *c = lr_canvas_cairo_new(4, 3, err, sizeof err);
    CHECK(c != NULL);
    if (!c)
        return;
    CHECK(lr_canvas_width(c) == 4 && lr_canvas_height(c) == 3);
    lr_rgba half_red = { 1.0, 0.0, 0.0, 0.5 };
    lr_canvas_clear(c, half_red);
    /* a bad byte in a label must not break the canvas (cairo errors stick) */
    lr_rgba black = { 0, 0, 0, 1 };
    lr_canvas_text(c, 0, 2, 2, black, LR_ALIGN_RIGHT, "bad \xff\xfe utf-8");
    unsigned char *px = lr_canvas_read_rgba(c);
    CHECK(px != NULL);
    if (px) {   /* straight alpha: full red at half opacity */
        const unsigned char *p = px + 4 * (4 * 2 + 3);
        CHECK(p[0] == 255 && p[1] == 0 && p[2] == 0 && p[3] == 128);
    }
    free(px);
    lr_canvas_free(c);
    CHECK(lr_canvas_cairo_new(0, 3, err, sizeof err) == NULL);
    CHECK(err[0] != '\0');
}

int main(void)
{
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    snprintf(path_a, sizeof path_a, "%s/a.png", dir);
    snprintf(path_b, sizeof path_b, "%s/b.png", dir);
    snprintf(path_bad, sizeof path_bad, "%s/bad.png", dir);
    test_palette();
    test_canvas();
    test_frame_write();
    test_edges();
    CHECK(unlink(path_a) == 0);
    CHECK(unlink(path_b) == 0);
    CHECK(rmdir(dir) == 0);
    lr_shutdown();      /* so the leak checker sees only our memory */
    return CHECK_DONE();
}
