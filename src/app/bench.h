/* bench.h - the engine benchmarks of `lamina bench` (cmd_bench.c). */
#ifndef LAMINA_BENCH_H
#define LAMINA_BENCH_H

#include "mpm.h"

/* `lamina bench engine` (bench_engine.c) */
int bench_engine(int argc, char **argv);
/* `lamina bench threads` (bench_threads.c) */
int bench_threads(int argc, char **argv);
/* The two elastic disks of bench engine at about `particles` particles on
 * nt threads, or NULL. */
lm_sim *bench_two_disks(double particles, lm_scheme scheme, int nt);
/* --sizes N,N,...: up to max particle counts in [100, 1e7] from arg into
 * sizes; their number, or -1 with the reason printed as `lamina bench CMD`. */
int bench_sizes(const char *cmd, const char *arg, double *sizes, int max);
/* (bench_args.c, with bench_sizes) A whole-number option's value arg in
 * [lo, hi] into *out; -1 with "OPT needs a whole number from LO to HI"
 * printed as `lamina bench CMD`. */
int bench_whole(const char *cmd, const char *opt, const char *arg, long lo, long hi,
                long *out);
/* Prints "unknown option 'ARG' (usage: lamina bench CMD USAGE)"; returns 2,
 * the exit status of a usage error. */
int bench_unknown(const char *cmd, const char *arg, const char *usage);
/* The median of v[0..n) (n >= 1; v is sorted in place). */
double bench_median(double *v, int n);

#endif
