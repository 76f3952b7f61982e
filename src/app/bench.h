/* bench.h - the engine benchmarks of `lamina bench` (cmd_bench.c). */
#ifndef LAMINA_BENCH_H
#define LAMINA_BENCH_H

#include "mpm.h"

/* `lamina bench engine` (bench_engine.c) */
int bench_engine(int argc, char **argv);
/* `lamina bench engine --dim 3`, also `lamina bench --dim 3`
 * (bench_engine3.c) */
int bench_engine3(int argc, char **argv);
/* `lamina bench threads` (bench_threads.c) */
int bench_threads(int argc, char **argv);
/* The two elastic disks of bench engine at about `particles` particles on
 * nt threads, or NULL. */
lm_sim *bench_two_disks(double particles, lm_scheme scheme, int nt);
/* The basis bench engine's cases use (bench_engine.c; default linear). */
void bench_set_basis(lm_basis b);
/* bench engine's gas-filled quarter membrane (connectivity normals, MUSL)
 * at about `particles` particles, or NULL. */
lm_sim *bench_gas_membrane(double particles);
/* The plain loop (bench_plain.c: ref_usl's USL step on bench engine's
 * disks, bilinear) at about `particles` particles for about `work`
 * particle-steps: particle-steps per wall-clock second (per second of
 * the process's CPU time into *cpu_rate), the particles in *np; -1 out of
 * memory. */
double bench_plain_rate(double particles, double work, size_t *np, double *cpu_rate);
/* `lamina bench render3d` (bench_render3d.c): 3D frames, issue 34 */
int bench_render3d(int argc, char **argv);
/* `lamina bench roofline` (bench_roofline.c) */
int bench_roofline(int argc, char **argv);
/* One-core triad a[i] = b[i] + s c[i] over n doubles an array, best of
 * `repeats`: GB/s counting 24 bytes an element (STREAM's convention). */
double bench_triad_gbs(size_t n, int repeats);

/* Bytes a step moves per particle (bench_bytes.c): `particle` bytes of the
 * particle arrays over all passes (each array once a pass it is read in,
 * once more a pass it is written in), `stencil` the node doubles its
 * stencil reads or updates (from the caches, mostly), `passes` over the
 * particles. */
typedef struct bench_bytes {
    double particle, stencil;
    int passes;
} bench_bytes;
/* A particle of material `kind` stepped with `basis` and `scheme`, by the
 * fused passes (fused: step_fused.c, one thread, next step following) or
 * phase by phase (step.c). 0, or -1 for an unknown basis or kind. */
int bench_bytes_count(lm_basis basis, lm_kind kind, lm_scheme scheme, int fused,
                      bench_bytes *out);

/* Bytes a step moves per grid node in its passes over the whole grid
 * (bench_bytes.c; the same on the fused and the phased paths). */
double bench_bytes_grid(lm_scheme scheme);
/* What a basis's own fused pass adds to that a node (bench_bytes.c). */
double bench_bytes_grid_pass(lm_basis basis, lm_scheme scheme);

/* --sizes N,N,...: up to max particle counts in [100, 1e7] from arg into
 * sizes; their number, or -1 with the reason printed as `lamina bench CMD`. */
int bench_sizes(const char *cmd, const char *arg, double *sizes, int max);
/* (bench_args.c, with bench_sizes) A whole-number option's value arg in
 * [lo, hi] into *out; -1 with "OPT needs a whole number from LO to HI"
 * printed as `lamina bench CMD`. */
int bench_whole(const char *cmd, const char *opt, const char *arg, long lo, long hi,
                long *out);
/* (bench_args.c) --work: a particle-step count in [1e3, 1e10] from arg into
 * *work; -1 with the reason printed as `lamina bench CMD`. */
int bench_work(const char *cmd, const char *arg, double *work);
/* (bench_args.c) The options bench engine's 2D and 3D tables share, at
 * argv[*i] with its value after it: --work, --threads (1 to
 * LM_MAX_THREADS), --sizes (at most max). 1 taken (*i on its value), 0 not
 * one of them (or no value follows), -1 a bad value (said on stderr). */
int bench_engine_opt(int argc, char **argv, int *i, double *work, int *threads,
                     double *sizes, int max, int *nsizes);
/* Prints "unknown option 'ARG' (usage: lamina bench CMD USAGE)"; returns 2,
 * the exit status of a usage error. */
int bench_unknown(const char *cmd, const char *arg, const char *usage);
/* bench engine's table (bench_table.c), its case column `width` wide:
 * the header; a row of n particles stepped `steps` times over secs of wall
 * clock and cpu of CPU time, `done` particle-steps, against the plain
 * loop's rates plain and plain_cpu; and the plain loop's own row at about
 * `particles` (its rate, its CPU-time rate in *plain_cpu; -1 out of
 * memory, said on stderr). The clocks: wall (monotonic) and the process's
 * CPU time, in seconds. */
void bench_table_head(int width);
void bench_table_row(int width, const char *name, size_t n, long steps, double secs,
                     double cpu, double done, double plain, double plain_cpu);
double bench_plain_row(int width, double particles, double work, double *plain_cpu);
double bench_wall_s(void);
double bench_cpu_s(void);
/* A case of bench engine's tables, its engine (2D or 3D) behind the
 * callbacks. bench_time_case runs it for about `work` particle-steps after
 * a warm-up step each build, rebuilding it whenever its simulated time
 * would pass t_max or it has run steps_max steps (the cost per step does
 * not depend on it), and prints
 * its row; 0, or -1 with the reason on stderr as `lamina bench CMD`. */
typedef struct bench_case {
    const char *cmd, *name;  /* "engine" or "engine --dim 3"; the row's */
    int width;               /* the table's case column */
    double t_max;
    long steps_max;          /* rebuilt after this many steps too (0: no cap) */
    void *ctx;
    void *(*build)(void *ctx);   /* a fresh case, or NULL */
    size_t (*particles)(const void *sim);
    double (*dt)(const void *sim);
    /* after the steps: the single-rate steps one step counts as */
    double (*counted)(const void *sim);
    /* one step, `more` when another follows; 0 or not with error(sim) */
    int (*step)(void *sim, int more);
    const char *(*error)(const void *sim);
    /* frees the case, after the steps (stepped) or a failed one */
    void (*release)(void *sim, void *ctx, int stepped);
} bench_case;
int bench_time_case(const bench_case *k, double work, double plain, double plain_cpu);
/* The median of v[0..n) (n >= 1; v is sorted in place). */
double bench_median(double *v, int n);

#endif
