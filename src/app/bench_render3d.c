/* bench_render3d.c - `lamina bench render3d`: milliseconds per 3D frame
 * (frame3d.h) for each backend at 10^4 .. 10^6 particles (issue 34 item
 * 4: 10^6 points in under 150 ms through OSMesa or EGL).
 *
 * The scene: n particles on a cubic lattice filling the box [0, 1] x
 * [0, 1] x [0, 0.5], coloured by x + z through viridis with its colour
 * bar, the box's outline, seen from azimuth -60, elevation 25, in an
 * 800 x 800 frame; particles 1 px in radius from 2 x 10^5 on (l_frame3d's
 * default), 2.5 px below. Per frame the median of --runs of drawing and
 * reading the pixels back, in wall-clock time and in the process's CPU
 * time (every thread's: OpenGL's llvmpipe draws on several), so that a
 * loaded machine's number can be read beside an idle one's. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"
#include "frame3d.h"
#include "render.h"

#define MAX_COUNTS 8
#define MAX_RUNS 51

static double clock_ms(clockid_t id)
{
    struct timespec t;
    clock_gettime(id, &t);
    return 1e3 * (double)t.tv_sec + 1e-6 * (double)t.tv_nsec;
}

static double median(double *v, int n)
{
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0 && v[j - 1] > v[j]; j--) {
            double t = v[j];
            v[j] = v[j - 1];
            v[j - 1] = t;
        }
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static int usage(const char *why)
{
    fprintf(stderr, "lamina bench render3d: %s (usage: lamina bench render3d [--runs N] "
            "[--counts N,...] [--backend cairo|osmesa|egl|all])\n", why);
    return 2;
}

int bench_render3d(int argc, char **argv)
{
    size_t counts[MAX_COUNTS] = {10000, 100000, 1000000};
    int ncounts = 3, runs = 5, use[LR_BACKEND_COUNT] = {0, 1, 1};
    for (int i = 0; i < argc; i += 2) {     /* options and their values */
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!v)
            return usage("an option without its value");
        if (strcmp(a, "--runs") == 0) {
            runs = atoi(v);
            if (runs < 1 || runs > MAX_RUNS)
                return usage("--runs needs 1 .. 51");
        } else if (strcmp(a, "--counts") == 0) {
            ncounts = 0;
            for (const char *p = v; *p && ncounts < MAX_COUNTS;) {
                char *end;
                double x = strtod(p, &end);
                if (end == p || !(x >= 1 && x <= 1e8) || (*end && *end != ','))
                    return usage("--counts needs counts like 1e4,1e6 (1 .. 1e8)");
                counts[ncounts++] = (size_t)x;
                p = *end ? end + 1 : end;
            }
        } else if (strcmp(a, "--backend") == 0) {
            lr_backend b;
            char why[256];
            for (int k = 0; k < LR_BACKEND_COUNT; k++)
                use[k] = strcmp(v, "all") == 0;
            if (strcmp(v, "all") != 0) {
                if (lr_backend_parse(v, &b, why, sizeof why) != 0)
                    return usage(why);
                use[b] = 1;
            }
        } else {
            char why[160];
            snprintf(why, sizeof why, "unknown option '%.100s'", a);
            return usage(why);
        }
    }
    printf("lamina bench render3d: 800x800 3D frames, ms per frame (drawing and reading "
           "back), median of %d runs; wall / CPU of all threads\n\n", runs);
    printf("| particles | radius px |");
    for (int b = 0; b < LR_BACKEND_COUNT; b++)
        if (use[b])
            printf(" %s wall | %s CPU |", lr_backend_name((lr_backend)b),
                   lr_backend_name((lr_backend)b));
    printf("\n|---:|---:|");
    for (int b = 0; b < LR_BACKEND_COUNT; b++)
        if (use[b])
            printf("---:|---:|");
    printf("\n");
    int status = 0;
    for (int k = 0; k < ncounts && status == 0; k++) {
        size_t n = counts[k];
        /* a lattice of m x m x m/2 filling the half cube */
        size_t m = (size_t)ceil(cbrt(2.0 * (double)n));
        double *x = malloc(4 * n * sizeof *x);
        if (!x) {
            fprintf(stderr, "lamina bench render3d: out of memory for %zu particles\n", n);
            return 1;
        }
        double *y = x + n, *z = x + 2 * n, *val = x + 3 * n;
        for (size_t i = 0; i < n; i++) {
            x[i] = ((double)(i % m) + 0.5) / (double)m;
            y[i] = ((double)(i / m % m) + 0.5) / (double)m;
            z[i] = ((double)(i / (m * m)) + 0.5) / (double)m;
            val[i] = x[i] + z[i];
        }
        lr_cloud3d c = {n, x, y, z, val, NULL, n > 200000 ? 1.0 : 2.5};
        lr_panel3d p;
        memset(&p, 0, sizeof p);
        for (int a = 0; a < 3; a++)
            p.hi[a] = 1;
        p.box = 1;
        p.camera.azimuth = -60;
        p.camera.elevation = 25;
        p.clouds = &c;
        p.nclouds = 1;
        p.colourbar = 1;
        p.colourbar_label = "x + z";
        printf("| %zu | %.1f |", n, c.radius);
        for (int b = 0; b < LR_BACKEND_COUNT && status == 0; b++) {
            char why[512];
            if (!use[b])
                continue;
            if (lr_backend_check((lr_backend)b, why, sizeof why) != 0) {
                printf(" - | - |");
                continue;
            }
            lr_figure3d f = {800, 800, (lr_backend)b, &p, 1, 0, 0, NULL, NULL, NULL, 0};
            double wall[MAX_RUNS], cpu[MAX_RUNS];
            for (int r = 0; r < runs && status == 0; r++) {
                double w0 = clock_ms(CLOCK_MONOTONIC), c0 = clock_ms(CLOCK_PROCESS_CPUTIME_ID);
                unsigned char *img = lr_figure3d_render(&f, why, sizeof why);
                wall[r] = clock_ms(CLOCK_MONOTONIC) - w0;
                cpu[r] = clock_ms(CLOCK_PROCESS_CPUTIME_ID) - c0;
                if (!img) {
                    fprintf(stderr, "lamina bench render3d: %s: %s\n",
                            lr_backend_name((lr_backend)b), why);
                    status = 1;
                }
                free(img);
            }
            if (status == 0)
                printf(" %.1f | %.1f |", median(wall, runs), median(cpu, runs));
            fflush(stdout);
        }
        printf("\n");
        free(x);
    }
    lr_shutdown();
    return status;
}
