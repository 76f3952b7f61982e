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
/* Prints "unknown option 'ARG' (usage: lamina bench CMD USAGE)"; returns 2,
 * the exit status of a usage error. */
int bench_unknown(const char *cmd, const char *arg, const char *usage);
/* The median of v[0..n) (n >= 1; v is sorted in place). */
double bench_median(double *v, int n);

#endif
