/* cmd_bench.c - `lamina bench render`: milliseconds per frame for each
 * backend at 10^3 .. 10^6 particles (docs/design.md, "Performance targets": a
 * benchmark, not a timed test).
 *
 * The scene is a frame as sim:frame draws it: a 64 x 64 cell grid over the
 * unit square, n particles on a square lattice filling it, coloured by
 * four bodies, radius half the spacing (so they touch, as seeded particles
 * do), the time label. Two times per frame, each the median of --runs:
 * "draw" is canvas creation, drawing and reading the pixels back (what the
 * backend costs); "+PNG" adds writing the PNG file (zlib, the same for
 * both backends). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "app.h"
#include "bench.h"
#include "figure.h"
#include "render.h"

#define MAX_COUNTS 16
#define MAX_RUNS 101

typedef struct bench_opts {
    int width, height, runs;
    size_t counts[MAX_COUNTS];
    int ncounts;
    int backends[LR_BACKEND_COUNT]; /* which to run */
} bench_opts;

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return 1e3 * (double)t.tv_sec + 1e-6 * (double)t.tv_nsec;
}

/* ---- the scene ---------------------------------------------------------- */

typedef struct scene {
    double *x, *y;
    int *group;
    size_t n;
    lr_grid grid;
    lr_points pts;
    lr_panel panel;
    lr_figure fig;
} scene;

static int make_scene(scene *s, size_t n, int w, int h)
{
    memset(s, 0, sizeof *s);
    s->x = malloc(n * sizeof *s->x);
    s->y = malloc(n * sizeof *s->y);
    s->group = malloc(n * sizeof *s->group);
    if (!s->x || !s->y || !s->group)
        return -1;
    size_t m = (size_t)ceil(sqrt((double)n));
    double d = 1.0 / (double)m;
    for (size_t i = 0; i < n; i++) {
        s->x[i] = (i % m + 0.5) * d;
        s->y[i] = (i / m + 0.5) * d;
        s->group[i] = (int)(4 * i / n);
    }
    s->n = n;
    lr_grid g = { 0.0, 0.0, 1.0 / 64, 1.0 / 64, 64, 64 };
    s->grid = g;
    s->pts.n = n;
    s->pts.x = s->x;
    s->pts.y = s->y;
    s->pts.group = s->group;
    s->pts.radius = 0.5 * d;
    s->panel.wx1 = s->panel.wy1 = 1.0;
    s->panel.side[0].grid = &s->grid;
    s->panel.side[0].points = &s->pts;
    s->panel.side[0].npoints = 1;
    s->fig.width = w;
    s->fig.height = h;
    s->fig.panels = &s->panel;
    s->fig.npanels = 1;
    s->fig.label = "t = 1.0000   step 1000";
    return 0;
}

static void free_scene(scene *s)
{
    free(s->x);
    free(s->y);
    free(s->group);
}

/* The particle radius in pixels, as the frame draws it. */
static double radius_px(const scene *s)
{
    double margin = 0.04 * fmin(s->fig.width, s->fig.height);
    double font = fmax(12.0, s->fig.height / 40.0);
    double aw = s->fig.width - 2 * margin, ah = s->fig.height - 2 * margin - 1.5 * font;
    return fmax(1.0, s->pts.radius * fmin(aw, ah));
}

/* One backend, one count: median draw and draw+PNG times; -1 on failure. */
static int time_backend(scene *s, lr_backend b, int runs, const char *png,
                        double *draw, double *total)
{
    double t_draw[MAX_RUNS], t_total[MAX_RUNS];
    char err[512];
    s->fig.backend = b;
    for (int r = 0; r < runs; r++) {
        double t0 = now_ms();
        unsigned char *rgba = lr_figure_render(&s->fig, err, sizeof err);
        double t1 = now_ms();
        if (!rgba) {
            fprintf(stderr, "lamina bench: %s: %s\n", lr_backend_name(b), err);
            return -1;
        }
        int rc = lr_png_write(png, s->fig.width, s->fig.height, rgba, NULL, 0, err,
                              sizeof err);
        double t2 = now_ms();
        free(rgba);
        if (rc != 0) {
            fprintf(stderr, "lamina bench: %s\n", err);
            return -1;
        }
        t_draw[r] = t1 - t0;
        t_total[r] = t2 - t0;
    }
    *draw = bench_median(t_draw, runs);
    *total = bench_median(t_total, runs);
    return 0;
}

/* ---- the machine -------------------------------------------------------- */

static void cpu_model(char *buf, size_t n)
{
    snprintf(buf, n, "unknown CPU");
    FILE *fp = fopen("/proc/cpuinfo", "r");
    if (!fp)
        return;
    char line[512];
    while (fgets(line, sizeof line, fp))
        if (strncmp(line, "model name", 10) == 0) {
            char *colon = strchr(line, ':');
            if (colon) {
                colon++;
                while (*colon == ' ' || *colon == '\t')
                    colon++;
                colon[strcspn(colon, "\n")] = 0;
                snprintf(buf, n, "%s", colon);
            }
            break;
        }
    fclose(fp);
}

/* ---- command line ------------------------------------------------------- */

static int parse_counts(const char *v, bench_opts *o)
{
    o->ncounts = 0;
    const char *p = v;
    while (p && *p) {
        char *end;
        double x = strtod(p, &end);
        if (end == p || !(x >= 1 && x <= 1e8) || x != floor(x) || o->ncounts == MAX_COUNTS)
            return -1;
        o->counts[o->ncounts++] = (size_t)x;
        p = *end == ',' ? end + 1 : end;
        if (*end && *end != ',')
            return -1;
    }
    return o->ncounts > 0 ? 0 : -1;
}

static int parse_int(const char *opt, const char *v, int lo, int hi, int *out)
{
    char *end = NULL;
    long x = v ? strtol(v, &end, 10) : 0;
    if (!v || end == v || *end || x < lo || x > hi) {
        fprintf(stderr, "lamina bench render: %s needs a whole number in [%d, %d] "
                "(got '%s')\n", opt, lo, hi, v ? v : "");
        return -1;
    }
    *out = (int)x;
    return 0;
}

static int parse_args(int argc, char **argv, bench_opts *o)
{
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--width") == 0) {
            if (parse_int(a, v, 16, LR_CANVAS_MAX_SIZE, &o->width)) return -1;
            i++;
        } else if (strcmp(a, "--height") == 0) {
            if (parse_int(a, v, 16, LR_CANVAS_MAX_SIZE, &o->height)) return -1;
            i++;
        } else if (strcmp(a, "--runs") == 0) {
            if (parse_int(a, v, 1, MAX_RUNS, &o->runs)) return -1;
            i++;
        } else if (strcmp(a, "--counts") == 0) {
            if (!v || parse_counts(v, o) != 0) {
                fprintf(stderr, "lamina bench render: --counts needs particle counts "
                        "like 1000,1e4,100000 (1 .. 1e8, at most %d)\n", MAX_COUNTS);
                return -1;
            }
            i++;
        } else if (strcmp(a, "--backend") == 0) {
            lr_backend b;
            char why[512];
            if (v && strcmp(v, "all") == 0) {
                /* every backend this lamina has and that starts here */
                for (int k = 0; k < LR_BACKEND_COUNT; k++)
                    o->backends[k] = lr_backend_check((lr_backend)k, NULL, 0) == 0;
            } else if (!v || lr_backend_parse(v, &b, why, sizeof why) != 0) {
                fprintf(stderr, "lamina bench render: --backend: %s\n",
                        v ? why : "needs cairo, osmesa, egl, gl or all");
                return -1;
            } else if (lr_backend_check(b, why, sizeof why) != 0) {
                fprintf(stderr, "lamina bench render: --backend %s: %s\n", v, why);
                return -1;
            } else {
                for (int k = 0; k < LR_BACKEND_COUNT; k++)
                    o->backends[k] = k == (int)b;
            }
            i++;
        } else {
            fprintf(stderr, "lamina bench render: unknown option '%s' (try 'lamina help')\n", a);
            return -1;
        }
    }
    return 0;
}

static int bench_render(int argc, char **argv)
{
    bench_opts o = { 1024, 1024, 5, { 1000, 10000, 100000, 1000000 }, 4, { 1, 1, 1 } };
    for (int k = 1; k < LR_BACKEND_COUNT; k++)
        o.backends[k] = lr_backend_check((lr_backend)k, NULL, 0) == 0;
    if (parse_args(argc, argv, &o) != 0)
        return 2;
    const char *tmpdir = getenv("TMPDIR");
    char dir[512], png[600];
    snprintf(dir, sizeof dir, "%s/lamina-bench-XXXXXX", tmpdir && *tmpdir ? tmpdir : "/tmp");
    if (!mkdtemp(dir)) {
        perror("lamina bench render: temporary folder");
        return 1;
    }
    snprintf(png, sizeof png, "%s/frame.png", dir);
    char cpu[256];
    cpu_model(cpu, sizeof cpu);
    printf("lamina bench render: %dx%d frames, ms per frame, median of %d runs\n",
           o.width, o.height, o.runs);
    printf("machine: %ld CPUs (nproc), %s\n", sysconf(_SC_NPROCESSORS_ONLN), cpu);
    for (int k = 1; k < LR_BACKEND_COUNT; k++) {
        char why[512];
        if (lr_backend_check((lr_backend)k, why, sizeof why) != 0)
            printf("(no %s column: %s)\n", lr_backend_name((lr_backend)k), why);
    }
    printf("\n| particles | radius px |");
    for (int b = 0; b < LR_BACKEND_COUNT; b++)
        if (o.backends[b])
            printf(" %s draw | %s +PNG |", lr_backend_name((lr_backend)b),
                   lr_backend_name((lr_backend)b));
    printf("\n|---:|---:|");
    for (int b = 0; b < LR_BACKEND_COUNT; b++)
        if (o.backends[b])
            printf("---:|---:|");
    printf("\n");
    int status = 0;
    for (int k = 0; k < o.ncounts && status == 0; k++) {
        scene s;
        if (make_scene(&s, o.counts[k], o.width, o.height) != 0) {
            fprintf(stderr, "lamina bench render: out of memory for %zu particles\n",
                    o.counts[k]);
            free_scene(&s);
            status = 1;
            break;
        }
        printf("| %zu | %.2f |", s.n, radius_px(&s));
        fflush(stdout);
        for (int b = 0; b < LR_BACKEND_COUNT && status == 0; b++) {
            double draw, total;
            if (!o.backends[b])
                continue;
            if (time_backend(&s, (lr_backend)b, o.runs, png, &draw, &total) != 0)
                status = 1;
            else
                printf(" %.1f | %.1f |", draw, total);
            fflush(stdout);
        }
        printf("\n");
        free_scene(&s);
    }
    unlink(png);
    rmdir(dir);
    lr_shutdown();
    return status;
}


int cmd_bench(int argc, char **argv)
{
    if (argc >= 1 && strcmp(argv[0], "render") == 0)
        return bench_render(argc - 1, argv + 1);
    if (argc >= 1 && strcmp(argv[0], "engine") == 0) {
        for (int i = 1; i + 1 < argc; i++)   /* the 3D engine's table */
            if (strcmp(argv[i], "--dim") == 0 && strcmp(argv[i + 1], "2") != 0)
                return bench_engine3(argc - 1, argv + 1);
        return bench_engine(argc - 1, argv + 1);
    }
    if (argc >= 1 && strcmp(argv[0], "--dim") == 0)   /* lamina bench --dim 3 */
        return bench_engine3(argc, argv);
    if (argc >= 1 && strcmp(argv[0], "render3d") == 0)
        return bench_render3d(argc - 1, argv + 1);
    if (argc >= 1 && strcmp(argv[0], "threads") == 0)
        return bench_threads(argc - 1, argv + 1);
    if (argc >= 1 && strcmp(argv[0], "roofline") == 0)
        return bench_roofline(argc - 1, argv + 1);
    fprintf(stderr, "lamina bench: %s (usage: lamina bench render [--width W] "
            "[--height H] [--runs N] [--counts N,N,...] [--backend cairo|osmesa|egl|gl|all])\n",
            argc >= 1 ? "unknown benchmark" : "which benchmark?");
    if (argc >= 1)
        fprintf(stderr, "lamina bench: '%s' is not a benchmark; known: render, engine, threads, roofline, render3d\n", argv[0]);
    return 2;
}
