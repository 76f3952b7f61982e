/* bench_args.c - what the `lamina bench` commands share (bench.h): their
 * options' parsing and messages, and the median of their timings. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

int bench_sizes(const char *cmd, const char *arg, double *sizes, int max)
{
    int n = 0;
    for (const char *s = arg; *s && n < max;) {
        char *end;
        double v = strtod(s, &end);
        if (end == s || !(v >= 100 && v <= 1e7)) {
            fprintf(stderr, "lamina bench %s: --sizes needs particle counts in [100, 1e7], "
                    "comma separated\n", cmd);
            return -1;
        }
        sizes[n++] = v;
        s = *end == ',' ? end + 1 : end;
    }
    return n;
}

int bench_whole(const char *cmd, const char *opt, const char *arg, long lo, long hi,
                long *out)
{
    long v = atol(arg);
    if (v < lo || v > hi) {
        fprintf(stderr, "lamina bench %s: %s needs a whole number from %ld to %ld\n", cmd, opt,
                lo, hi);
        return -1;
    }
    *out = v;
    return 0;
}

int bench_work(const char *cmd, const char *arg, double *work)
{
    double v = atof(arg);
    if (!(v >= 1e3 && v <= 1e10)) {
        fprintf(stderr, "lamina bench %s: --work needs a number in [1e3, 1e10]\n", cmd);
        return -1;
    }
    *work = v;
    return 0;
}

int bench_engine_opt(int argc, char **argv, int *i, double *work, int *threads,
                     double *sizes, int max, int *nsizes)
{
    const char *opt = argv[*i];
    if (*i + 1 >= argc) return 0;
    const char *arg = argv[*i + 1];
    if (strcmp(opt, "--work") == 0) {
        if (bench_work("engine", arg, work) != 0) return -1;
    } else if (strcmp(opt, "--threads") == 0) {
        long v;
        if (bench_whole("engine", "--threads", arg, 1, LM_MAX_THREADS, &v) != 0) return -1;
        *threads = (int)v;
    } else if (strcmp(opt, "--sizes") == 0) {
        if ((*nsizes = bench_sizes("engine", arg, sizes, max)) < 0) return -1;
    } else {
        return 0;
    }
    ++*i;
    return 1;
}

int bench_unknown(const char *cmd, const char *arg, const char *usage)
{
    fprintf(stderr, "lamina bench %s: unknown option '%s' (usage: lamina bench %s %s)\n", cmd,
            arg, cmd, usage);
    return 2;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double bench_median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, by_value);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
