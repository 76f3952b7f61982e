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

#endif
