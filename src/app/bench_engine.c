/* bench_engine.c - `lamina bench engine`: particle-steps per second of the
 * engine alone (docs/design.md, "Performance targets"), on one thread or on
 * `--threads N` (lamina.sim{threads}; threads.h).
 *
 * Two standard problems at several sizes, built through the engine's C API
 * (no Lua, no drawing inside the timed loop):
 *   disks  - the two elastic disks of scripts/examples/two_disks.lua, the
 *            cell size chosen for the particle count, MUSL and USL, and
 *            MUSL with the disks a contact-release pair (sim:contact);
 *   gas    - the gas-filled quarter membrane of V6 (16 ppc gas, membrane
 *            points a third of a cell apart, connectivity normals), MUSL;
 *            and the same with the membrane's normals from the isosurface
 *            construction (normals "isosurface", normals_centred.c), whose
 *            cost over the row before is the construction's (issue 17
 *            item 3, docs/performance.md). And the first with multi-rate stepping
 *            (lamina.sim{substeps = 16}: the gas steps 16 times the
 *            membrane's dt, subcycle.c), its particle-steps counted as the
 *            16 a single-rate run takes: the row's rate over the first
 *            row's is the speed-up to the same simulated time.
 * `--basis NAME` runs them with that basis (lamina.sim{basis}: linear,
 * gimp, bspline2; default linear).
 * Each case runs for about `work` particle-steps (default 4e6) after one
 * warm-up step; the table gives particles, steps, seconds and millions of
 * particle-steps per second. Timings are wall clock: run it on an idle
 * machine, and compare runs of the same build. The last column is the
 * same rate per second of the process's CPU time (all threads together):
 * on a shared machine it moves less with the other jobs than the wall
 * clock does. Each size starts with the plain loop of bench_plain.c (the
 * disks, bilinear, USL, one thread: the issue 36 yardstick), and the last
 * two columns are each row's rate over the plain loop's, by the wall clock
 * and by CPU time. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "mpm.h"
#include "mpm_contact.h"

/* Seeds a region (disk of centre c and radius r, or a quarter disk when
 * quarter) of material m into a new body with 2^k x 2^k points per cell. */
static int seed_disk(lm_sim *sim, int mi, double cx, double cy, double r, int np,
                     double vx, double vy, double rho)
{
    int b = lm_sim_add_body(sim, mi);
    if (b < 0) return -1;
    lm_seed_range sr = lm_seed_range_for(&sim->grid, np, np, cx - r, cy - r, cx + r, cy + r);
    double mass = lm_seed_mass(&sim->grid, np, np, rho);
    for (size_t k = 0; k < lm_seed_count(&sr); k++) {
        double x, y;
        lm_seed_point(&sim->grid, &sr, k, &x, &y);
        if ((x - cx) * (x - cx) + (y - cy) * (y - cy) > r * r) continue;
        if (lm_sim_add_particle(sim, b, x, y, vx, vy, mass, rho) != LM_OK) return -1;
    }
    return b;
}

static int threads = 1;
static lm_basis basis = LM_BASIS_LINEAR;

static lm_sim *make_disks(double h, lm_scheme scheme, lm_material *mat, int nt)
{
    lm_sim_def d;
    lm_sim_def_default(&d);
    d.threads = nt;
    d.basis = basis;
    d.hx = d.hy = h;
    d.scheme = scheme;
    d.dt = 0.2 * h / lm_material_wave_speed(mat);
    char err[256];
    lm_sim *sim = lm_sim_new(&d, err, sizeof err);
    if (!sim) return NULL;
    int mi = lm_sim_add_material(sim, mat);
    if (mi < 0 || seed_disk(sim, mi, 0.25, 0.25, 0.2, 2, 0.1, 0.1, mat->rho) < 0 ||
        seed_disk(sim, mi, 0.75, 0.75, 0.2, 2, -0.1, -0.1, mat->rho) < 0) {
        lm_sim_free(sim);
        return NULL;
    }
    return sim;
}

/* substeps = k > 0: multi-rate stepping, the gas at k times the
 * membrane's dt and the membrane in k sub-steps of it (subcycle.c) */
static lm_sim *make_gas(double h, lm_material *gas, lm_material *skin, lm_normals normals,
                        int substeps)
{
    lm_sim_def d;
    lm_sim_def_default(&d);
    d.threads = threads;
    d.basis = basis;
    d.hx = d.hy = h;
    d.bc[LM_LEFT] = d.bc[LM_BOTTOM] = LM_BC_SYMMETRY;
    d.dt = 0.5 * h / lm_material_wave_speed(skin) * (substeps > 0 ? substeps : 1);
    d.substeps = substeps;
    char err[256];
    lm_sim *sim = lm_sim_new(&d, err, sizeof err);
    if (!sim) return NULL;
    int gi = lm_sim_add_material(sim, gas), si = lm_sim_add_material(sim, skin);
    if (gi < 0 || si < 0 || seed_disk(sim, gi, 0, 0, 0.5, 4, 0, 0, gas->rho) < 0) {
        lm_sim_free(sim);
        return NULL;
    }
    int b = lm_sim_add_membrane(sim, si, 0);
    if (b >= 0 && lm_sim_set_membrane_normals(sim, b, normals) != LM_OK) b = -1;
    int n = (int)ceil(0.25 * 3.14159265358979323846 * 0.5 / (h / 3)) + 1;
    double ds = 0.5 * (3.14159265358979323846 / 2) / (n - 1);
    for (int k = 0; b >= 0 && k < n; k++) {
        double a = (3.14159265358979323846 / 2) * k / (n - 1);
        double x = k == n - 1 ? 0 : 0.5 * cos(a), y = k == 0 ? 0 : 0.5 * sin(a);
        size_t q = sim->p.n;
        if (lm_sim_add_particle(sim, b, x, y, 0, 0, skin->rho * skin->thickness * ds,
                                skin->rho) != LM_OK ||
            lm_sim_set_membrane_point(sim, q, ds, 0) != LM_OK) {
            lm_sim_free(sim);
            return NULL;
        }
    }
    if (b < 0 || lm_sim_prepare(sim) != LM_OK) {
        lm_sim_free(sim);
        return NULL;
    }
    return sim;
}

typedef lm_sim *(*builder)(double h, void *ctx);

/* A 2D case for bench_time_case (bench_table.c): its builder at cell size h */
typedef struct case2 {
    builder make;
    double h;
    void *ctx;
} case2;

static void *build2(void *ctx)
{
    const case2 *c = ctx;
    return c->make(c->h, c->ctx);
}

static size_t particles2(const void *sim) { return ((const lm_sim *)sim)->p.n; }
static double dt2(const void *sim) { return ((const lm_sim *)sim)->def.dt; }
/* multi-rate: each step counts as the k steps a single-rate run would
 * take (the membrane's dt) */
static double counted2(const void *sim) { return lm_subcycle_count(sim); }
static int step2(void *sim, int more) { return lm_sim_step_then(sim, more) != LM_OK; }
static const char *error2(const void *sim) { return ((const lm_sim *)sim)->err; }

static void release2(void *sim, void *ctx, int stepped)
{
    (void)ctx;
    (void)stepped;
    lm_sim_free(sim);
}

/* Runs about `work` particle-steps, rebuilding the case whenever its
 * simulated time would pass t_max (the disks must not collide and the USL
 * run must not grow unstable); prints one row. plain, plain_cpu: the plain
 * loop's rates, wall clock and CPU time */
static int time_case(const char *name, builder make, double h, void *ctx, double t_max,
                     double work, double plain, double plain_cpu)
{
    case2 c = {make, h, ctx};
    bench_case k = {"engine", name, 12, t_max, 0, &c, build2, particles2, dt2, counted2,
                    step2, error2, release2};
    return bench_time_case(&k, work, plain, plain_cpu);
}

typedef struct bench_ctx {
    lm_material *a, *b;
    lm_scheme scheme;
    int contact;
    lm_normals normals;    /* the gas case's membrane */
    int substeps;          /* the gas case: lamina.sim{substeps} (0: off) */
} bench_ctx;

static lm_sim *build_disks(double h, void *ctx)
{
    bench_ctx *c = ctx;
    lm_sim *sim = make_disks(h, c->scheme, c->a, threads);
    /* the disks as a contact-release pair (contact.h). They do not meet
     * here, so this is what contact costs while no pair can meet (each
     * paired body's box of nodes, found every step); the cost where pairs
     * meet is measured by scripts/measure/contact_cost.lua */
    if (sim && c->contact && lm_sim_add_contact(sim, 0, 1, LM_CONTACT_RELEASE, 0) < 0) {
        lm_sim_free(sim);
        return NULL;
    }
    return sim;
}

static lm_sim *build_gas(double h, void *ctx)
{
    bench_ctx *c = ctx;
    return make_gas(h, c->a, c->b, c->normals, c->substeps);
}

static lm_material rubber = {.kind = LM_ELASTIC, .rho = 1000, .E = 1000, .nu = 0.3,
                              .plane = LM_PLANE_STRAIN};

void bench_set_basis(lm_basis b) { basis = b; }

/* the gas case's materials (bench engine's, file-wide so that
 * bench_gas_membrane's sim can keep pointers to them) */
static lm_material air = {.kind = LM_GAS, .rho = 1, .gamma = 1.4, .mu = 0.2,
                          .e0 = 1000 / (0.4 * 1)};
static lm_material skin = {.kind = LM_MEMBRANE, .rho = 0.5, .E = 1e6, .nu = 0.3,
                           .thickness = 0.1, .law = LM_LAW_PLANE_STRESS};

lm_sim *bench_gas_membrane(double particles)
{
    /* quarter disk of radius 0.5 at 16 ppc: about 3.14 / h^2 particles */
    return make_gas(sqrt(3.14 / particles), &air, &skin, LM_NORMALS_CONNECTIVITY, 0);
}

lm_sim *bench_two_disks(double particles, lm_scheme scheme, int nt)
{
    /* two disks of radius 0.2, 4 ppc: about 1.005 / h^2 particles */
    return make_disks(sqrt(1.005 / particles), scheme, &rubber, nt);
}

int bench_engine(int argc, char **argv)
{
    double work = 4e6;
    double sizes[8] = {1e3, 1e4, 1e5};
    int nsizes = 3;
    for (int i = 0; i < argc; i++) {
        int taken = bench_engine_opt(argc, argv, &i, &work, &threads, sizes, 8, &nsizes);
        if (taken < 0) return 2;
        if (taken) continue;   /* --work, --threads, --sizes */
        if (strcmp(argv[i], "--basis") == 0 && i + 1 < argc) {
            const char *name = argv[++i];
            int b = 0;
            while (b <= LM_BASIS_BSPLINE2 && strcmp(name, lm_basis_name((lm_basis)b)) != 0) b++;
            if (b > LM_BASIS_BSPLINE2) {
                fprintf(stderr, "lamina bench engine: --basis '%s' is not one of linear, gimp, "
                        "bspline2\n", name);
                return 2;
            }
            basis = (lm_basis)b;
        } else if (strcmp(argv[i], "--dim") == 0 && i + 1 < argc) {
            i++;   /* 2 (cmd_bench.c sends any other to bench_engine3.c) */
        } else {
            return bench_unknown("engine", argv[i], "[--dim 2|3] [--sizes N,N,...] "
                                 "[--work PARTICLE_STEPS] [--threads N] "
                                 "[--basis linear|gimp|bspline2]");
        }
    }
    printf("lamina bench engine: %d thread%s, basis %s, about %.3g particle-steps per case\n\n",
           threads, threads == 1 ? "" : "s", lm_basis_name(basis), work);
    bench_table_head(12);
    int bad = 0;
    for (int k = 0; k < nsizes; k++) {
        /* the plain loop on the same disks (bench_plain.c, bilinear, USL,
         * one thread), the last column's yardstick: each row's wall-clock
         * rate over its (issue 36 item 2) */
        double pc = 0, plain = bench_plain_row(12, sizes[k], work, &pc);
        if (plain <= 0) return 1;
        /* two disks of radius 0.2, 4 ppc: about 1.005 / h^2 particles */
        double h = sqrt(1.005 / sizes[k]);
        bench_ctx musl = {&rubber, NULL, LM_MUSL, 0, LM_NORMALS_CONNECTIVITY, 0};
        bench_ctx usl = {&rubber, NULL, LM_USL, 0, LM_NORMALS_CONNECTIVITY, 0};
        bench_ctx rel = {&rubber, NULL, LM_MUSL, 1, LM_NORMALS_CONNECTIVITY, 0};
        bad |= time_case("disks MUSL", build_disks, h, &musl, 0.8, work, plain, pc);
        bad |= time_case("disks USL", build_disks, h, &usl, 0.8, work, plain, pc);
        if (basis != LM_BASIS_BSPLINE2)   /* contact refuses it (contact.c) */
            bad |= time_case("disks release", build_disks, h, &rel, 0.8, work, plain, pc);
        /* quarter disk of radius 0.5 at 16 ppc: about 3.14 / h^2 */
        double hg = sqrt(3.14 / sizes[k]);
        bench_ctx gm = {&air, &skin, LM_MUSL, 0, LM_NORMALS_CONNECTIVITY, 0};
        bench_ctx gi = {&air, &skin, LM_MUSL, 0, LM_NORMALS_ISOSURFACE, 0};
        /* multi-rate: the gas at 16 times the membrane's dt (its Courant
         * number 16 x 0.5 x 37 / 1482 = 0.2), the membrane in 16 sub-steps */
        bench_ctx gs = {&air, &skin, LM_MUSL, 0, LM_NORMALS_CONNECTIVITY, 16};
        /* the papers' point forces, three membrane points a cell, on the
         * bilinear basis: the skin tears from t = 0.0032 at 1e5 particles
         * (0.0041 at 1e4, 0.009 at 1e3; segment forces or more points a
         * cell hold longer: docs/performance.md "The plot"), so the case
         * is rebuilt at t = 0.002, as the disks are before they meet */
        bad |= time_case("gas+membrane", build_gas, hg, &gm, 0.002, work, plain, pc);
        bad |= time_case("gas+isosurf", build_gas, hg, &gi, 0.002, work, plain, pc);
        bad |= time_case("gas+mem k=16", build_gas, hg, &gs, 0.002, work, plain, pc);
    }
    return bad ? 1 : 0;
}
