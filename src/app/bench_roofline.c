/* bench_roofline.c - `lamina bench roofline`: how close the step comes to
 * one core's memory bandwidth (issue 36 item 3, docs/performance.md
 * "Roofline").
 *
 * Three numbers side by side: the one-core triad a[i] = b[i] + s c[i] over
 * arrays far larger than the last-level cache (GB/s, best of five); the
 * bytes a particle-step moves, counted pass by pass from the engine's own
 * array sizes (bench_bytes.c); and the particle-steps per second of bench
 * engine's cases on one thread. Their product is the bandwidth the step
 * implies, and its fraction of the triad says how far the step is from the
 * roofline: near 1, fewer bytes is the only way on; far below, the step
 * is bound by its arithmetic or its latency, not by memory.
 *
 * Timings are wall clock on one thread: run it on a quiet machine. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "mpm.h"

double bench_triad_gbs(size_t n, int repeats)
{
    double *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b), *c = malloc(n * sizeof *c);
    if (!a || !b || !c) {
        free(a);
        free(b);
        free(c);
        return -1;
    }
    for (size_t i = 0; i < n; i++) {   /* touch every page before timing */
        a[i] = 0;
        b[i] = 1.0 + (double)(i & 7);
        c[i] = 2.0;
    }
    double best = 1e300;
    volatile double s = 3.0;   /* not a constant the compiler could fold */
    for (int r = 0; r < repeats; r++) {
        const double sc = s;
        double t0 = bench_wall_s();
        for (size_t i = 0; i < n; i++) a[i] = b[i] + sc * c[i];
        double t = bench_wall_s() - t0;
        if (t < best) best = t;
        s = a[n / 2] * 1e-300 + 3.0;   /* the result is used */
    }
    free(a);
    free(b);
    free(c);
    return 24.0 * (double)n / best / 1e9;
}

typedef struct rcase {
    const char *name;
    lm_scheme scheme;
    int gas;        /* the gas-filled membrane, else the two elastic disks */
    double t_max;   /* rebuilt before the simulated time passes it (bench_engine.c) */
} rcase;

/* Particles of each kind in sim (for the bytes of a mixed case). */
static void count_kinds(const lm_sim *sim, size_t count[5])
{
    memset(count, 0, 5 * sizeof *count);
    for (size_t q = 0; q < sim->p.n; q++) {
        int k = (int)sim->mats[sim->p.mat[q]]->kind;
        if (k >= 0 && k < 5) count[k]++;
    }
}

/* About `work` particle-steps of case c at about `particles` particles:
 * particle-steps per second into *rate, bytes per particle-step of its
 * particles (mixed by their kinds) into *bytes. */
static int run_case(const rcase *c, double particles, double work, lm_basis basis,
                    double *rate, bench_bytes *bytes, size_t *np, double *grid)
{
    double secs = 0, done = 0;
    size_t count[5] = {0};
    while (done < work) {
        lm_sim *sim = c->gas ? bench_gas_membrane(particles)
                             : bench_two_disks(particles, c->scheme, 1);
        if (!sim) return -1;
        size_t n = sim->p.n;
        *np = n;
        /* the grid's passes, shared out over the particles */
        *grid = (bench_bytes_grid(c->scheme) + (c->gas ? 0 : bench_bytes_grid_pass(basis, c->scheme))) *
                (double)lm_grid_nodes(&sim->grid) / (double)n;
        count_kinds(sim, count);
        long steps = (long)fmin(fmax(10, (work - done) / (double)n), c->t_max / sim->def.dt);
        if (steps < 1) steps = 1;
        if (lm_sim_step_then(sim, 1) != LM_OK) {   /* warm-up */
            fprintf(stderr, "lamina bench roofline: %s: %s\n", c->name, sim->err);
            lm_sim_free(sim);
            return -1;
        }
        double t0 = bench_wall_s();
        for (long s = 0; s < steps; s++)
            if (lm_sim_step_then(sim, s + 1 < steps) != LM_OK) {
                fprintf(stderr, "lamina bench roofline: %s: %s\n", c->name, sim->err);
                lm_sim_free(sim);
                return -1;
            }
        secs += bench_wall_s() - t0;
        done += (double)n * (double)steps;
        lm_sim_free(sim);
    }
    *rate = done / secs;
    /* the bytes of the fused path (one thread, a step following: what the
     * loop above runs), each kind's weighted by its particles */
    bench_bytes z = {0, 0, 0};
    *bytes = z;
    size_t total = 0;
    for (int k = LM_ELASTIC; k <= LM_LINEAR_FLUID; k++) total += count[k];
    for (int k = LM_ELASTIC; k <= LM_LINEAR_FLUID; k++) {
        if (!count[k]) continue;
        bench_bytes b;
        bench_bytes_count(basis, (lm_kind)k, c->scheme, 1, &b);
        double w = (double)count[k] / (double)total;
        bytes->particle += w * b.particle;
        bytes->stencil += w * b.stencil;
        if (b.passes > bytes->passes) bytes->passes = b.passes;
    }
    return 0;
}

static int parse_basis(const char *name, int *out)
{
    if (strcmp(name, "all") == 0) {
        *out = -1;
        return 0;
    }
    for (int b = 0; b <= LM_BASIS_BSPLINE2; b++)
        if (strcmp(name, lm_basis_name((lm_basis)b)) == 0) {
            *out = b;
            return 0;
        }
    fprintf(stderr, "lamina bench roofline: --basis '%s' is not one of linear, gimp, bspline2, "
            "all\n", name);
    return -1;
}

static void print_counts(void)
{
    static const char *kinds[] = {"", "elastic", "membrane", "gas"};
    printf("Bytes per particle-step, counted (bench_bytes.c): particle arrays [stencil node "
           "doubles], passes over the particles;\nand per node: %.0f (USL), %.0f (MUSL) in "
           "the passes over the whole grid (+%.0f the quadratic B-spline's USL pass)\n\n",
           bench_bytes_grid(LM_USL), bench_bytes_grid(LM_MUSL),
           bench_bytes_grid_pass(LM_BASIS_BSPLINE2, LM_USL));
    printf("| basis | material | USL fused | MUSL fused | USL phased | MUSL phased |\n");
    printf("|---|---|---:|---:|---:|---:|\n");
    for (int b = 0; b <= LM_BASIS_BSPLINE2; b++)
        for (int k = LM_ELASTIC; k <= LM_GAS; k++) {
            printf("| %s | %s |", lm_basis_name((lm_basis)b), kinds[k]);
            for (int ph = 0; ph < 2; ph++)
                for (int sc = 0; sc < 2; sc++) {
                    bench_bytes x;
                    bench_bytes_count((lm_basis)b, (lm_kind)k, sc ? LM_MUSL : LM_USL, !ph, &x);
                    printf(" %.0f [%.0f] %dp |", x.particle, x.stencil, x.passes);
                }
            printf("\n");
        }
}

int bench_roofline(int argc, char **argv)
{
    double particles = 2e5, work = 3e6;
    int which = -1;
    long mb = 128, repeats = 3;
    for (int i = 0; i < argc; i++) {
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(argv[i], "--particles") == 0 && v) {
            double s[1];
            if (bench_sizes("roofline", v, s, 1) != 1) return 2;
            particles = s[0];
            i++;
        } else if (strcmp(argv[i], "--work") == 0 && v) {
            if (bench_work("roofline", v, &work) != 0) return 2;
            i++;
        } else if (strcmp(argv[i], "--basis") == 0 && v) {
            if (parse_basis(v, &which) != 0) return 2;
            i++;
        } else if (strcmp(argv[i], "--repeats") == 0 && v) {
            if (bench_whole("roofline", "--repeats", v, 1, 100, &repeats) != 0) return 2;
            i++;
        } else if (strcmp(argv[i], "--triad-mb") == 0 && v) {
            if (bench_whole("roofline", "--triad-mb", v, 1, 4096, &mb) != 0) return 2;
            i++;
        } else {
            return bench_unknown("roofline", argv[i], "[--particles N] [--work PARTICLE_STEPS] "
                                 "[--basis linear|gimp|bspline2|all] [--repeats N] "
                                 "[--triad-mb MB]");
        }
    }
    print_counts();
    size_t n = (size_t)mb * 1024 * 1024 / sizeof(double);
    double triad = bench_triad_gbs(n, 5);
    if (triad <= 0) {
        fprintf(stderr, "lamina bench roofline: no memory for the triad's 3 x %ld MB\n", mb);
        return 1;
    }
    printf("\nOne-core triad a[i] = b[i] + s c[i], 3 x %ld MB, best of 5: %.2f GB/s\n\n", mb,
           triad);
    printf("One thread, fused path, about %.3g particle-steps a case, best of %ld:\n\n", work,
           repeats);
    printf("| basis | case | particles | M p-steps/s | particle B | grid B | bytes/p-step | "
           "stencil B | GB/s | of triad |\n");
    printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    static const rcase cases[] = {
        {"disks USL", LM_USL, 0, 0.8},
        {"disks MUSL", LM_MUSL, 0, 0.8},
        {"gas+membrane", LM_MUSL, 1, 0.002},
    };
    int bad = 0;
    for (int b = 0; b <= LM_BASIS_BSPLINE2; b++) {
        if (which >= 0 && b != which) continue;
        bench_set_basis((lm_basis)b);
        for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
            double rate;
            bench_bytes by = {0, 0, 0};
            size_t np = 0;
            double grid = 0;
            /* the best of `repeats` runs: the other jobs on a shared
             * machine only ever slow a run down */
            rate = 0;
            for (long r = 0; r < repeats; r++) {
                double one;
                if (run_case(&cases[k], particles, work, (lm_basis)b, &one, &by, &np, &grid)) {
                    rate = -1;
                    break;
                }
                if (one > rate) rate = one;
            }
            if (rate < 0) {
                bad = 1;
                continue;
            }
            double total = by.particle + grid, gbs = rate * total / 1e9;
            printf("| %s | %s | %zu | %.2f | %.0f | %.0f | %.0f | %.0f | %.2f | %.2f |\n",
                   lm_basis_name((lm_basis)b), cases[k].name, np, rate / 1e6, by.particle,
                   grid, total, by.stencil, gbs, gbs / triad);
            fflush(stdout);
        }
    }
    bench_set_basis(LM_BASIS_LINEAR);
    return bad;
}
