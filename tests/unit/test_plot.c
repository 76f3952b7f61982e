/* test_plot.c - lr_plot_write and its parts: nice ticks and their labels, a
 * rendered plot (size, valid PNG, provenance, dashes, determinism), the CSV,
 * and degenerate input that must be drawn or refused, never crash. */
#include "check.h"
#include "test_files.h"
#include "plot.h"
#include "render.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char dir[] = "plot_test_XXXXXX";

/* Every file a test may create, removed at the end (missing ones too). */
static const char *const names[] = { "sine.png", "sine2.png", "line.png", "dash.png",
                                     "data.png", "data.csv", "folder.csv", "deg.png",
                                     "bad.png", "bad.csv", "best.png", NULL };

static const char *path(const char *name)
{
    static char buf[8][128];
    static int k;
    k = (k + 1) % 8;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

static int contains(const unsigned char *buf, long len, const char *s)
{
    size_t n = strlen(s);
    for (long i = 0; i + (long)n <= len; i++)
        if (memcmp(buf + i, s, n) == 0)
            return 1;
    return 0;
}

/* ---- ticks ------------------------------------------------------------ */

/* step = m x 10^k with m in {1, 2, 5} */
static int is_nice(double step)
{
    double k = floor(log10(step) + 1e-9);
    double m = step / pow(10.0, k);
    return fabs(m - 1.0) < 1e-9 || fabs(m - 2.0) < 1e-9 || fabs(m - 5.0) < 1e-9;
}

/* The general promises for any range. */
static void check_ticks(double lo, double hi, int intervals)
{
    double t[64], step = 0.0;
    int n = lr_plot_ticks(lo, hi, intervals, t, 64, &step);
    CHECK(n >= 1 && n <= intervals + 1);
    CHECK(step > 0.0 && is_nice(step));
    CHECK(step >= (hi - lo) / intervals * (1.0 - 1e-9));
    /* the smallest such step: the next smaller nice step gives too many */
    for (int i = 0; i < n; i++) {
        double k = t[i] / step;
        CHECK(fabs(k - round(k)) < 1e-6);
        CHECK(t[i] >= lo - 1e-9 * step && t[i] <= hi + 1e-9 * step);
        CHECK(i == 0 || fabs(t[i] - t[i - 1] - step) <= 1e-9 * fmax(1.0, fabs(t[i])));
        CHECK(!(t[i] == 0.0 && signbit(t[i])));     /* no -0 */
    }
    /* a multiple of step just outside is not missed at either end */
    CHECK(t[0] - step < lo);
    CHECK(t[n - 1] + step > hi);
}

static void expect_ticks(double lo, double hi, int intervals, double want_step,
                         int want_n, double first)
{
    double t[64], step = 0.0;
    int n = lr_plot_ticks(lo, hi, intervals, t, 64, &step);
    CHECK_NEAR(step, want_step, 1e-12 * want_step);
    CHECK(n == want_n);
    if (n > 0)
        CHECK_NEAR(t[0], first, 1e-12 * fmax(1.0, fabs(first)));
}

static void test_ticks(void)
{
    expect_ticks(0.0, 1.0, 5, 0.2, 6, 0.0);
    expect_ticks(0.0, 1.0, 10, 0.1, 11, 0.0);
    expect_ticks(0.0, 0.013, 5, 0.005, 3, 0.0);
    expect_ticks(-3.7, 12.2, 8, 2.0, 8, -2.0);
    expect_ticks(1e-6, 5e-6, 4, 1e-6, 5, 1e-6);
    expect_ticks(0.0, 2.5e5, 5, 5e4, 6, 0.0);
    expect_ticks(-0.012, 0.012, 6, 0.005, 5, -0.01);
    expect_ticks(998.0, 1003.0, 5, 1.0, 6, 998.0);
    expect_ticks(0.3, 0.35, 1, 0.05, 2, 0.3);   /* both ends are ticks */

    /* values are computed, not accumulated: 0.3 is the double 0.3 */
    double t[64], step;
    int n = lr_plot_ticks(0.0, 1.0, 10, t, 64, &step);
    CHECK(n == 11 && t[3] == 0.3 && t[7] == 0.7);
    n = lr_plot_ticks(-1.0, 1.0, 4, t, 64, &step);
    CHECK(n == 5 && t[2] == 0.0 && !signbit(t[2]));

    static const double ranges[][2] = {
        { 0, 1 }, { -1, 1 }, { 0, 0.05 }, { 1e-9, 3e-9 }, { -7.3e4, 2.2e5 },
        { 0.99, 1.01 }, { 1e12, 1e12 + 1e6 }, { -5e-3, -1e-3 }, { 3.14, 3.15 },
        { 0, 1e300 }, { -1e-300, 1e-300 }, { 12345.678, 12345.679 } };
    for (size_t i = 0; i < sizeof ranges / sizeof ranges[0]; i++)
        for (int k = 1; k <= 12; k += 3)
            check_ticks(ranges[i][0], ranges[i][1], k);

    /* refused: empty, reversed, non-finite, no intervals */
    CHECK(lr_plot_ticks(1.0, 1.0, 5, t, 64, &step) == -1);
    CHECK(lr_plot_ticks(2.0, 1.0, 5, t, 64, &step) == -1);
    CHECK(lr_plot_ticks(NAN, 1.0, 5, t, 64, &step) == -1);
    CHECK(lr_plot_ticks(0.0, INFINITY, 5, t, 64, &step) == -1);
    CHECK(lr_plot_ticks(-1e308, 1e308, 5, t, 64, &step) == -1);   /* span overflows */
    CHECK(lr_plot_ticks(0.0, 1.0, 0, t, 64, &step) == -1);
    /* cap is respected */
    CHECK(lr_plot_ticks(0.0, 1.0, 10, t, 3, &step) == 3);
}

static void expect_labels(const double *t, int n, double step, const char *const *want)
{
    char lab[16][LR_TICK_LABEL_MAX];
    lr_plot_tick_labels(t, n, step, lab);
    for (int i = 0; i < n; i++)
        if (strcmp(lab[i], want[i]) != 0) {
            fprintf(stderr, "tick %g (step %g): label '%s', want '%s'\n", t[i], step,
                    lab[i], want[i]);
            check_failures++;
        }
}

static void test_labels(void)
{
    const double a[] = { 0, 0.005, 0.01, 0.015 };
    expect_labels(a, 4, 0.005, (const char *const[]){ "0", "0.005", "0.01", "0.015" });
    const double b[] = { 0, 1e-5, 2e-5 };
    expect_labels(b, 3, 1e-5, (const char *const[]){ "0", "1e-05", "2e-05" });
    const double c[] = { 0, 5e4, 1e5, 1.5e5, 2e5, 2.5e5 };
    expect_labels(c, 6, 5e4, (const char *const[]){ "0", "5e+04", "1e+05", "1.5e+05",
                                                    "2e+05", "2.5e+05" });
    const double d[] = { -0.5, 0, 0.5, 1 };
    expect_labels(d, 4, 0.5, (const char *const[]){ "-0.5", "0", "0.5", "1" });
    const double e[] = { 10000, 20000, 30000 };
    expect_labels(e, 3, 10000, (const char *const[]){ "10000", "20000", "30000" });
    /* zero in any form is "0", never "-0" */
    const double f[] = { -0.0, -1e-18, 0.1 };
    expect_labels(f, 3, 0.1, (const char *const[]){ "0", "0", "0.1" });
    const double g[] = { -2.5e-7, 0, 2.5e-7 };
    expect_labels(g, 3, 2.5e-7, (const char *const[]){ "-2.5e-07", "0", "2.5e-07" });
    const double h[] = { 998, 999, 1000 };
    expect_labels(h, 3, 1, (const char *const[]){ "998", "999", "1000" });
}

/* ---- rendering -------------------------------------------------------- */

enum { N = 500 };
static double tx[N], sine[N], ref[N];

static const lr_text_chunk text[] = { { "Software", "lamina test" },
                                      { "lamina:script", "test_plot.c" } };

static lr_plot sine_plot(lr_plot_series s[2])
{
    for (int i = 0; i < N; i++) {
        tx[i] = 2.0 * i / (N - 1);
        sine[i] = sin(6.283185307179586 * tx[i]) * exp(-0.3 * tx[i]);
        ref[i] = sin(6.283185307179586 * tx[i]);
    }
    memset(s, 0, 2 * sizeof *s);
    s[0] = (lr_plot_series){ N, tx, sine, "MPM", 0, 0, 0, 0.0 };
    s[1] = (lr_plot_series){ N, tx, ref, "analytic", 7, 1, 0, 1.5 };
    lr_plot p;
    memset(&p, 0, sizeof p);
    p.width = 640;
    p.height = 400;
    p.title = "damped sine against the reference";
    p.xlabel = "t (s)";
    p.ylabel = "u (m)";
    p.nseries = 2;
    p.series = s;
    return p;
}

/* Reads a PNG we wrote; checks the signature and the size. */
static unsigned char *read_png(const char *p, int w, int h)
{
    long len = 0;
    unsigned char *raw = slurp(p, &len);
    static const unsigned char sig[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n' };
    CHECK(raw && len > 8 && memcmp(raw, sig, 8) == 0);
    free(raw);
    int rw = 0, rh = 0;
    unsigned char *img = NULL;
    char err[512] = "";
    CHECK(lr_png_read(p, &rw, &rh, &img, err, sizeof err) == 0);
    CHECK(rw == w && rh == h);
    if (!img || rw != w || rh != h) {
        fprintf(stderr, "%s: %s\n", p, err);
        free(img);
        return NULL;
    }
    return img;
}

static int near_colour(const unsigned char *px, lr_rgba k, int tol)
{
    return abs(px[0] - (int)lround(k.r * 255)) <= tol &&
           abs(px[1] - (int)lround(k.g * 255)) <= tol &&
           abs(px[2] - (int)lround(k.b * 255)) <= tol && px[3] == 255;
}

static int count_colour(const unsigned char *img, int w, int h, lr_rgba k)
{
    int n = 0;
    for (int i = 0; i < w * h; i++)
        n += near_colour(img + 4 * (size_t)i, k, 8);
    return n;
}

static void test_sine(void)
{
    lr_plot_series s[2];
    lr_plot p = sine_plot(s);
    char err[512] = "";
    CHECK(lr_plot_write(&p, path("sine.png"), text, 2, err, sizeof err) == 0);
    if (err[0])
        fprintf(stderr, "%s\n", err);
    unsigned char *img = read_png(path("sine.png"), 640, 400);
    if (img) {
        const unsigned char *corner = img;
        CHECK(corner[0] == 255 && corner[1] == 255 && corner[2] == 255);
        int blue = count_colour(img, 640, 400, lr_palette(0));
        int black = count_colour(img, 640, 400, lr_palette(7));
        CHECK(blue > 300);      /* the sine: full-colour pixels along it */
        CHECK(black > 300);     /* the dashed reference and the sample */
    }
    free(img);
    /* provenance */
    long len = 0;
    unsigned char *raw = slurp(path("sine.png"), &len);
    CHECK(raw && contains(raw, len, "tEXtSoftware") && contains(raw, len, "lamina test"));
    free(raw);
    /* the same plot twice: the same bytes */
    CHECK(lr_plot_write(&p, path("sine2.png"), text, 2, err, sizeof err) == 0);
    long na = -1, nb = -2;
    unsigned char *a = slurp(path("sine.png"), &na), *b = slurp(path("sine2.png"), &nb);
    CHECK(a && b && na == nb && memcmp(a, b, (size_t)na) == 0);
    free(a);
    free(b);
}

/* A horizontal line at y = 0.5 in a fixed [0, 1] window, scanned along its
 * row: a solid line has no gap, a dashed one many, with dashes that are
 * longer than a few pixels. */
static int line_gaps(int dashed, const char *name, int *longest_on)
{
    const double xs[2] = { 0.0, 1.0 }, ys[2] = { 0.5, 0.5 };
    lr_plot_series s = { 2, xs, ys, NULL, 1, dashed, 0, 2.0 };
    lr_plot p;
    memset(&p, 0, sizeof p);
    p.width = 300;
    p.height = 200;
    p.fixed_x = p.fixed_y = 1;
    p.x0 = 0.0;
    p.x1 = 1.0;
    p.y0 = 0.0;
    p.y1 = 1.0;
    p.nseries = 1;
    p.series = &s;
    char err[512] = "";
    CHECK(lr_plot_write(&p, path(name), NULL, 0, err, sizeof err) == 0);
    unsigned char *img = read_png(path(name), 300, 200);
    if (!img)
        return -1;
    lr_rgba k = lr_palette(1);
    int row = -1;
    for (int y = 0; y < 200 && row < 0; y++)     /* the line's row, mid-image */
        if (near_colour(img + 4 * ((size_t)y * 300 + 150), k, 8))
            row = y;
    if (row < 0)
        for (int y = 0; y < 200 && row < 0; y++)     /* dashed: look beside it */
            for (int x = 140; x < 160 && row < 0; x++)
                if (near_colour(img + 4 * ((size_t)y * 300 + x), k, 8))
                    row = y;
    CHECK(row >= 0);
    int gaps = 0, on = 0, run = 0;
    *longest_on = 0;
    for (int x = 90; x < 250 && row >= 0; x++) {
        int hit = near_colour(img + 4 * ((size_t)row * 300 + x), k, 40);
        if (hit) {
            run++;
            *longest_on = run > *longest_on ? run : *longest_on;
        } else {
            run = 0;
        }
        if (on && !hit)
            gaps++;
        on = hit;
    }
    free(img);
    return gaps;
}

static void test_dashes(void)
{
    int longest = 0;
    CHECK(line_gaps(0, "line.png", &longest) == 0);
    CHECK(longest >= 150);
    int gaps = line_gaps(1, "dash.png", &longest);
    CHECK(gaps >= 6);
    CHECK(longest >= 6 && longest < 20);
}

/* ---- CSV -------------------------------------------------------------- */

static void test_csv(void)
{
    const double x1[3] = { 0.0, 0.1, 0.2 }, y1[3] = { 1.0, NAN, -INFINITY };
    const double x2[2] = { 0.0, 1.0 / 3.0 }, y2[2] = { 5e-300, 2.5e10 };
    lr_plot_series s[2] = { { 3, x1, y1, "mass, end", 0, 0, 0, 0 },
                            { 2, x2, y2, NULL, 1, 1, 0, 0 } };
    lr_plot p;
    memset(&p, 0, sizeof p);
    p.width = 320;
    p.height = 240;
    p.nseries = 2;
    p.series = s;
    char csv_path[128];
    snprintf(csv_path, sizeof csv_path, "%s", path("data.csv"));
    p.csv = csv_path;
    char err[512] = "";
    CHECK(lr_plot_write(&p, path("data.png"), NULL, 0, err, sizeof err) == 0);
    long len = 0;
    char *csv = (char *)slurp(path("data.csv"), &len);
    CHECK(csv != NULL);
    if (csv) {
        const char *want =
            /* every header field quoted: the first line runs as neither
             * shell nor Python (issue 31 item 2) */
            "\"mass, end x\",\"mass, end y\",\"series 2 x\",\"series 2 y\"\n"
            "0,1,0,5e-300\n"
            "0.1,nan,0.3333333333333333,25000000000\n"
            "0.2,-inf,,\n";
        CHECK(strcmp(csv, want) == 0);
        if (strcmp(csv, want) != 0)
            fprintf(stderr, "CSV:\n%s\nwanted:\n%s\n", csv, want);
        /* the shortest text that reads back as the same double */
        CHECK(strtod("0.3333333333333333", NULL) == 1.0 / 3.0);
    }
    free(csv);

    /* a folder where the CSV should go is refused, and left alone */
    CHECK(mkdir(path("folder.csv"), 0777) == 0);
    CHECK(lr_plot_write_csv(&p, path("folder.csv"), err, sizeof err) == -1);
    CHECK(strstr(err, "not a regular file") != NULL);
    struct stat st;
    CHECK(stat(path("folder.csv"), &st) == 0 && S_ISDIR(st.st_mode));
    CHECK(rmdir(path("folder.csv")) == 0);
}

/* ---- degenerate input ------------------------------------------------- */

static void expect_ok(const lr_plot *p, const char *what)
{
    char err[512] = "";
    int rc = lr_plot_write(p, path("deg.png"), NULL, 0, err, sizeof err);
    if (rc != 0)
        fprintf(stderr, "%s: %s\n", what, err);
    CHECK(rc == 0);
    unsigned char *img = read_png(path("deg.png"), p->width, p->height);
    free(img);
}

static void expect_error(const lr_plot *p, const char *needle)
{
    char err[512] = "";
    CHECK(lr_plot_write(p, path("bad.png"), NULL, 0, err, sizeof err) == -1);
    if (!strstr(err, needle)) {
        fprintf(stderr, "error '%s' does not say '%s'\n", err, needle);
        check_failures++;
    }
    CHECK(!exists(path("bad.png")) && !exists(path("bad.csv")));
}

static void test_degenerate(void)
{
    const double cx[3] = { 1, 2, 3 }, cy[3] = { 5, 5, 5 }, zero[3] = { 0, 0, 0 };
    const double one_x = 2.5, one_y = -3.0;
    const double nx[6] = { 0, 1, NAN, 3, INFINITY, 5 }, ny[6] = { 1, 2, 3, NAN, 4, -INFINITY };
    const double allnan[2] = { NAN, NAN };
    const double huge[3] = { -1e300, 0, 1e300 }, vast[2] = { -1.7e308, 1.7e308 };
    lr_plot_series s;
    lr_plot p;
    memset(&p, 0, sizeof p);
    p.width = 320;
    p.height = 240;
    p.nseries = 1;
    p.series = &s;

    s = (lr_plot_series){ 3, cx, cy, "constant", 0, 0, 0, 0 };
    expect_ok(&p, "constant series");
    s = (lr_plot_series){ 3, zero, zero, "all zero", 0, 0, 0, 0 };
    expect_ok(&p, "all zero");
    s = (lr_plot_series){ 1, &one_x, &one_y, "one point", 0, 0, 0, 0 };
    expect_ok(&p, "single point");
    s.markers = 1;
    expect_ok(&p, "single marker");
    s = (lr_plot_series){ 6, nx, ny, "nan and inf", 0, 1, 0, 0 };
    expect_ok(&p, "NaN and inf");
    s = (lr_plot_series){ 2, allnan, allnan, "no finite point", 0, 0, 0, 0 };
    expect_ok(&p, "all NaN");
    s = (lr_plot_series){ 3, huge, huge, "huge", 0, 0, 0, 0 };
    expect_ok(&p, "huge values");
    /* a fixed window far from the data: nothing to draw, still a plot */
    p.fixed_x = p.fixed_y = 1;
    p.x0 = 1e6;
    p.x1 = 1e6 + 1e-3;
    p.y0 = -1.0;
    p.y1 = 1.0;
    expect_ok(&p, "window without data");
    p.fixed_x = p.fixed_y = 0;
    /* an invalid UTF-8 label must not poison the drawing */
    s = (lr_plot_series){ 3, cx, cy, "bad \xff\xfe label", 0, 0, 0, 0 };
    p.title = "\xc3\x28 title";
    expect_ok(&p, "invalid UTF-8");
    p.title = NULL;
    /* every legend position, and best */
    for (int pos = LR_LEGEND_TOP_RIGHT; pos <= LR_LEGEND_NONE; pos++) {
        p.legend = (lr_legend)pos;
        expect_ok(&p, "legend position");
    }
    p.legend = LR_LEGEND_TOP_RIGHT;

    /* refused, with a reason, and nothing written */
    s = (lr_plot_series){ 2, vast, vast, "vast", 0, 0, 0, 0 };
    expect_error(&p, "span more than a double");
    lr_plot_series two[2] = { { 3, cx, cy, "a", 0, 0, 0, 0 }, { 0, cx, cy, "b", 1, 0, 0, 0 } };
    p.series = two;
    p.nseries = 2;
    char bad_csv[128];     /* path()'s buffers are reused: keep a copy */
    snprintf(bad_csv, sizeof bad_csv, "%s", path("bad.csv"));
    p.csv = bad_csv;
    expect_error(&p, "series 2 ('b') is empty");
    two[1].n = 3;
    two[1].y = NULL;
    expect_error(&p, "series 2 ('b') has no x or y array");
    two[1].y = cy;
    p.fixed_x = 1;
    p.x0 = 1.0;
    p.x1 = 1.0;
    expect_error(&p, "x range");
    p.fixed_x = 0;
    p.width = 16;
    p.height = 16;
    expect_error(&p, "too small");
    p.width = 0;
    expect_error(&p, "invalid image size");
    p.width = 320;
    p.height = 240;
    p.nseries = 0;
    expect_error(&p, "at least one series");
    p.nseries = 2;
    char png_path[128];
    snprintf(png_path, sizeof png_path, "%s", path("bad.png"));
    p.csv = png_path;
    expect_error(&p, "CSV path");
    p.csv = NULL;
}

/* A long noisy series: fast, and its one spike survives the reduction to
 * a few points per pixel column. */
static void test_long_series(void)
{
    enum { M = 200000 };
    double *x = malloc(M * sizeof *x), *y = malloc(M * sizeof *y);
    if (!x || !y) {
        free(x);
        free(y);
        CHECK(!"out of memory");
        return;
    }
    for (int i = 0; i < M; i++) {
        x[i] = i;
        y[i] = sin(i * 1e-4) + 0.2 * sin(i * 0.7) + (i == M / 2 ? 20.0 : 0.0);
    }
    lr_plot_series s = { M, x, y, "noisy", 2, 0, 0, 1.0 };
    lr_plot p;
    memset(&p, 0, sizeof p);
    p.width = 400;
    p.height = 300;
    p.nseries = 1;
    p.series = &s;
    p.legend = LR_LEGEND_BEST;
    char err[512] = "";
    CHECK(lr_plot_write(&p, path("best.png"), NULL, 0, err, sizeof err) == 0);
    unsigned char *img = read_png(path("best.png"), 400, 300);
    if (img) {
        /* the spike reaches the top 15 % of the image somewhere */
        int top = 0;
        for (int yy = 0; yy < 45; yy++)
            for (int xx = 0; xx < 400; xx++)
                top += near_colour(img + 4 * ((size_t)yy * 400 + xx), lr_palette(2), 40);
        CHECK(top > 0);
    }
    free(img);
    s.markers = 1;
    CHECK(lr_plot_write(&p, path("best.png"), NULL, 0, err, sizeof err) == 0);
    free(x);
    free(y);
}

int main(void)
{
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    test_ticks();
    test_labels();
    test_sine();
    test_dashes();
    test_csv();
    test_degenerate();
    test_long_series();
    for (int i = 0; names[i]; i++)
        if (exists(path(names[i])))
            CHECK(unlink(path(names[i])) == 0);
    CHECK(rmdir(dir) == 0);     /* also: no temporary file was left behind */
    lr_shutdown();
    return CHECK_DONE();
}
