/* cmd_diff.c - `lamina diff EXPECTED.png ACTUAL.png [--out DIFF.png] ...`.
 *
 * A thin command over lr_diff_files (src/render/diff.c): exit 0 when the
 * pictures are the same within tolerance, 1 when they differ, 2 when they
 * cannot be compared (unreadable, corrupt, different sizes, bad options). */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "diff.h"
#include "util.h"

static const char usage_line[] =
    "usage: lamina diff EXPECTED.png ACTUAL.png [--out DIFF.png] [--threshold T]\n"
    "                   [--max-pixels N] [--max-window N] [--hard-limit L] [--quiet]";

/* "--name value" or "--name=value": the value, or NULL when a was not --name. */
static const char *option_value(int argc, char **argv, int *i, const char *name, int *missing)
{
    const char *v;
    if (!lu_opt_value(argc, argv, i, name, &v))
        return NULL;
    if (!v)
        *missing = 1;
    return v;
}

static int parse_number(const char *opt, const char *s, double lo, double hi, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end || errno || !(v >= lo && v <= hi)) {
        fprintf(stderr, "lamina diff: %s must be a number in [%g, %g] (got '%s')\n", opt,
                lo, hi, s);
        return -1;
    }
    *out = v;
    return 0;
}

static int parse_count(const char *opt, const char *s, long max, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (end == s || *end || errno || v < 0 || v > max) {
        fprintf(stderr, "lamina diff: %s must be a whole number in [0, %ld] (got '%s')\n",
                opt, max, s);
        return -1;
    }
    *out = v;
    return 0;
}

typedef struct diff_args {
    const char *expected, *actual, *out;
    int quiet;
    lr_diff_opts opts;
} diff_args;

static int parse_args(int argc, char **argv, diff_args *d)
{
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *v;
        int missing = 0;
        long count;
        if (strcmp(a, "--quiet") == 0 || strcmp(a, "-q") == 0) {
            d->quiet = 1;
        } else if ((v = option_value(argc, argv, &i, "--out", &missing))) {
            d->out = v;
        } else if ((v = option_value(argc, argv, &i, "--threshold", &missing))) {
            if (parse_number("--threshold", v, 0, 1, &d->opts.threshold)) return -1;
        } else if ((v = option_value(argc, argv, &i, "--max-pixels", &missing))) {
            if (parse_count("--max-pixels", v, LONG_MAX, &d->opts.max_pixels)) return -1;
        } else if ((v = option_value(argc, argv, &i, "--max-window", &missing))) {
            if (parse_count("--max-window", v, LR_DIFF_WINDOW * LR_DIFF_WINDOW,
                            &d->opts.max_window))
                return -1;
        } else if ((v = option_value(argc, argv, &i, "--hard-limit", &missing))) {
            if (parse_count("--hard-limit", v, 255, &count)) return -1;
            d->opts.hard_limit = (int)count;
        } else if (missing) {
            fprintf(stderr, "lamina diff: %s needs a value\n%s\n", a, usage_line);
            return -1;
        } else if (a[0] == '-' && a[1]) {
            fprintf(stderr, "lamina diff: unknown option '%s'\n%s\n", a, usage_line);
            return -1;
        } else if (!d->expected) {
            d->expected = a;
        } else if (!d->actual) {
            d->actual = a;
        } else {
            fprintf(stderr, "lamina diff: more than two images given ('%s')\n%s\n", a,
                    usage_line);
            return -1;
        }
    }
    if (!d->actual) {
        fprintf(stderr, "lamina diff: needs two PNG files, EXPECTED and ACTUAL\n%s\n",
                usage_line);
        return -1;
    }
    return 0;
}

int cmd_diff(int argc, char **argv)
{
    diff_args d;
    memset(&d, 0, sizeof d);
    lr_diff_defaults(&d.opts);
    if (parse_args(argc, argv, &d))
        return 2;
    lr_diff_result r;
    char err[1024];
    if (lr_diff_files(d.expected, d.actual, &d.opts, d.out, &r, err, sizeof err) != 0) {
        fprintf(stderr, "lamina diff: %s\n", err);
        return 2;
    }
    if (!d.quiet) {
        char line[512];
        lr_diff_summary(&r, &d.opts, line, sizeof line);
        printf("%s\n", line);
        if (d.out)
            printf("diff image: %s\n", d.out);
    }
    return r.same ? 0 : 1;
}
