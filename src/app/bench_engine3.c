/* bench_engine3.c - `lamina bench engine --dim 3` (also `lamina bench
 * --dim 3`): particle-steps per second of the 3D engine alone (issue 34
 * item 6; docs/3d.md "Speed", docs/performance.md "3D"), the table of
 * `lamina bench engine` (bench_engine.c) with the same columns.
 *
 * The scene is docs/3d.md's speed scene scaled to the particle count: an
 * elastic block (rho 1000, E 1e6, nu 0.3) of 2 x 2 x 2 points a cell
 * filling the middle 0.6 of a unit cube's every side, fixed faces,
 * gravity, spinning about z and sheared so that its stress moves; dt =
 * 0.2 h / c. Cases: trilinear and quadratic B-spline under MUSL, trilinear
 * under USL, and a gamma-law gas with the paper's artificial viscosity
 * filling the cube (trilinear, MUSL). Each runs about `work` particle-steps (at
 * least 10 steps) after one warm-up step, rebuilt after 50 steps or when
 * its simulated time would pass 0.05 s (before the block reaches the floor),
 * whichever is first (BENCH3_STEPS_MAX). Timings as in
 * bench_engine.c: wall clock, and CPU time of the process (on a shared
 * machine the steadier one); the plain loop's row (bench_plain.c, the 2D
 * yardstick at the same count) gives the last two columns. Below the
 * table, each size's memory: bytes a particle with its grid, at the
 * arrays' capacity and at the count (lm3_memory). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "mpm3.h"

typedef struct case3 {
    const char *name;
    lm_basis basis;
    lm_scheme scheme;
    int gas;
} case3;

static int threads3 = 1;

/* Steps a build runs before the case is rebuilt. The sheared block's
 * outer points start to cross cell edges after some tens of steps; on the
 * trilinear hats under USL a node that a crossing point reaches first
 * carries a sliver of mass, its velocity p/m takes the neighbours' forces
 * whole and the point's volume inverts (the small-mass node failure MUSL's
 * re-map avoids): measured at step 72 at 10^5 particles (--work 1e7).
 * Rebuilding after 50 steps keeps every case's timing on the block's
 * well-posed start at every size. */
#define BENCH3_STEPS_MAX 50

/* The block at about `particles` particles: n^3 cells with 8 x 0.216 n^3
 * particles; the gas fills the whole cube (8 n^3), since a gas block
 * would expand into the empty cells with a front at 2 c / (gamma - 1) =
 * 5 c, past the Courant limit of dt = 0.2 h / c (it failed at 10^4
 * particles, step 19). */
static int everywhere(void *ctx, const double x[3])
{
    (void)ctx; (void)x;
    return 1;
}

/* a spin about z and a shear: every stress component moves */
static int spin_shear(void *ctx, const double x[3], double v[3])
{
    (void)ctx;
    const double dx = x[0] - 0.5, dy = x[1] - 0.5, dz = x[2] - 0.5;
    v[0] = -2 * dy + 0.5 * dz;
    v[1] = 2 * dx;
    v[2] = 0.3 * dx;
    return 0;
}

static lm3_sim *make_block(double particles, const case3 *c)
{
    int n = (int)lround(cbrt(particles / (c->gas ? 8 : 8 * 0.216)));
    if (n < 4) n = 4;
    lm3_def d;
    memset(&d, 0, sizeof d);
    d.hi[0] = d.hi[1] = d.hi[2] = 1;
    d.cell = 1.0 / n;
    d.basis = c->basis;
    d.scheme = c->scheme;
    d.gravity[2] = -9.81;
    d.threads = threads3;
    for (int f = 0; f < LM3_FACES; f++) d.bc[f] = LM_BC_FIXED;
    lm3_material m = {.rho = 1000, .E = 1e6, .nu = 0.3};
    if (c->gas) {
        /* a gas of about the solid's wave speed, c^2 = gamma (gamma - 1) e0 */
        lm3_material g = {.rho = 1000, .kind = LM3_GAS, .gamma = 1.4, .mu = 0.1, .av = 1,
                          .av_c1 = 1, .av_c2 = 1, .av_lambda = 0.75};
        g.e0 = 1.35e3 / (g.gamma * (g.gamma - 1));   /* c = 36.7 m/s, the solid's */
        m = g;
    }
    double cs = c->gas ? sqrt(m.gamma * (m.gamma - 1) * m.e0)
                       : sqrt(m.E * (1 - m.nu) / ((1 + m.nu) * (1 - 2 * m.nu) * m.rho));
    d.dt = 0.2 * d.cell / cs;
    char err[256];
    lm3_sim *sim = lm3_sim_create(&d, err, sizeof err);
    if (!sim) return NULL;
    int mi = lm3_material_add(sim, &m, err, sizeof err);
    const double a = c->gas ? 0 : 0.2;
    lm3_seed_def sd = {.mat = mi, .k = {2, 2, 2}, .lo = {a, a, a}, .hi = {1 - a, 1 - a, 1 - a},
                       .inside = everywhere, .velocity = spin_shear};
    if (mi < 0 || lm3_seed(sim, &sd) <= 0) {
        lm3_sim_free(sim);
        return NULL;
    }
    return sim;
}

/* A 3D case for bench_time_case (bench_table.c), and the memory of its
 * last build: bytes a particle with its grid, at the arrays' capacity and
 * at the count */
typedef struct run3 {
    const case3 *c;
    double particles;
    double bytes, bytes_exact;
} run3;

static void *build3(void *ctx)
{
    const run3 *r = ctx;
    return make_block(r->particles, r->c);
}

static size_t particles3(const void *sim) { return ((const lm3_sim *)sim)->p.n; }
static double dt3(const void *sim) { return ((const lm3_sim *)sim)->def.dt; }
static double counted3(const void *sim) { (void)sim; return 1; }

static int step3(void *sim, int more)
{
    (void)more;
    return lm3_step(sim) != LM_OK;
}

static const char *error3(const void *sim) { return ((const lm3_sim *)sim)->err; }

static void release3(void *sim, void *ctx, int stepped)
{
    if (stepped) {
        /* after the steps: with the threads' copies and the sums made
         * ahead, which the steps allocate */
        run3 *r = ctx;
        size_t pb, pe, gb, n = particles3(sim);
        lm3_memory(sim, &pb, &pe, &gb);
        r->bytes = (double)(pb + gb) / (double)n;
        r->bytes_exact = (double)(pe + gb) / (double)n;
    }
    lm3_sim_free(sim);
}

/* One row; the memory of the last build into *bytes, *bytes_exact. */
static int time_case3(const case3 *c, double particles, double work, double plain,
                      double plain_cpu, double *bytes, double *bytes_exact)
{
    run3 r = {c, particles, *bytes, *bytes_exact};
    bench_case k = {"engine --dim 3", c->name, 13, 0.05, BENCH3_STEPS_MAX, &r, build3,
                    particles3, dt3, counted3, step3, error3, release3};
    int rc = bench_time_case(&k, work, plain, plain_cpu);
    *bytes = r.bytes;
    *bytes_exact = r.bytes_exact;
    return rc;
}

int bench_engine3(int argc, char **argv)
{
    double work = 4e6;
    double sizes[8] = {1e4, 1e5};
    int nsizes = 2, only = -1;
    static const case3 cases[] = {
        {"linear MUSL", LM_BASIS_LINEAR, LM_MUSL, 0},
        {"bspline2 MUSL", LM_BASIS_BSPLINE2, LM_MUSL, 0},
        {"linear USL", LM_BASIS_LINEAR, LM_USL, 0},
        {"gas linear", LM_BASIS_LINEAR, LM_MUSL, 1},
    };
    const int ncases = (int)(sizeof cases / sizeof *cases);
    const char *usage = "--dim 3 [--sizes N,N,...] [--work PARTICLE_STEPS] [--threads N] "
                        "[--basis linear|bspline2] [--simd sse2|best]";
    for (int i = 0; i < argc; i++) {
        int taken = bench_engine_opt(argc, argv, &i, &work, &threads3, sizes, 8, &nsizes);
        if (taken < 0) return 2;
        if (taken) continue;   /* --work, --threads, --sizes */
        if (strcmp(argv[i], "--dim") == 0 && i + 1 < argc) {
            if (strcmp(argv[++i], "3") != 0) {
                fprintf(stderr, "lamina bench engine: --dim '%s': 3 here (2 is the default "
                        "without --dim)\n", argv[i]);
                return 2;
            }
        } else if (strcmp(argv[i], "--basis") == 0 && i + 1 < argc) {
            const char *b = argv[++i];
            if (strcmp(b, "linear") == 0) only = LM_BASIS_LINEAR;
            else if (strcmp(b, "bspline2") == 0) only = LM_BASIS_BSPLINE2;
            else {
                fprintf(stderr, "lamina bench engine --dim 3: --basis '%s': 3D has linear and "
                        "bspline2\n", b);
                return 2;
            }
        } else if (strcmp(argv[i], "--simd") == 0 && i + 1 < argc) {
            const char *f = argv[++i];
            if (strcmp(f, "sse2") == 0) lm3_simd_limit(LM3_SIMD_SSE2);
            else if (strcmp(f, "best") == 0) lm3_simd_limit(LM3_SIMD_AVX512);
            else {
                fprintf(stderr, "lamina bench engine --dim 3: --simd '%s': sse2 (two lanes "
                        "everywhere) or best (the default: AVX-512F where the processor has "
                        "it)\n", f);
                return 2;
            }
        } else {
            return bench_unknown("engine", argv[i], usage);
        }
    }
    printf("lamina bench engine --dim 3: %d thread%s, about %.3g particle-steps per case, "
           "trilinear scatters in %s\n\n", threads3, threads3 == 1 ? "" : "s", work,
           lm3_simd_level() == LM3_SIMD_AVX512 ? "AVX-512F" : "SSE2");
    bench_table_head(13);
    int bad = 0;
    double mem[8][2] = {{0}};
    size_t counts[8] = {0};
    for (int k = 0; k < nsizes; k++) {
        double pc = 0, plain = bench_plain_row(13, sizes[k], work, &pc);
        if (plain <= 0) return 1;
        for (int c = 0; c < ncases; c++) {
            if (only >= 0 && (int)cases[c].basis != only) continue;
            double b = 0, be = 0;
            bad |= time_case3(&cases[c], sizes[k], work, plain, pc, &b, &be) != 0;
            if (c == 0 || (only == LM_BASIS_BSPLINE2 && c == 1)) {
                mem[k][0] = b;
                mem[k][1] = be;
                lm3_sim *s = make_block(sizes[k], &cases[c]);
                counts[k] = s ? s->p.n : 0;
                lm3_sim_free(s);
            }
        }
    }
    printf("\nmemory (lm3_memory: particle arrays and grid, bytes a particle):\n");
    for (int k = 0; k < nsizes; k++)
        printf("  %zu particles: %.0f at the arrays' capacity, %.0f at the count\n", counts[k],
               mem[k][0], mem[k][1]);
    return bad ? 1 : 0;
}
