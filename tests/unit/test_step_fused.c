/* test_step_fused.c - the fused particle pass (step_fused.c, issue 17
 * item 1) against the step made phase by phase (the order of
 * docs/physics.md §1, called here one function at a time):
 *   - the same particle states and nodal fields to the bit, for each basis,
 *     USL and MUSL, fixed, symmetry and free walls, gravity, a PIC blend,
 *     an elastic solid beside a linear fluid, and a gas in a membrane
 *     (artificial viscosity and connectivity normals; cell densities and
 *     isosurface normals: the two-pass forms), whether the pass makes the
 *     next step's sums ahead (lm_sim_step_then(sim, 1)) or not;
 *   - a state changed between steps after lm_sim_forget_ahead, or a
 *     particle added, is stepped from the new state;
 *   - a run that blows up stops at the same step naming the same particle
 *     with the same words;
 *   - on 2 or 3 threads, the same bits whatever the OS team that runs them
 *     (lm_sim_fix_team: one OS thread doing every part; threads.h);
 *   - with the grid damping (damping.c), the same bits and the same damped
 *     energy;
 *   - the quadratic B-spline's own USL pass (step_bspline2.c) forced to
 *     each instruction set it has (portable, AVX2): the same bits. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "sim_fixture.h"
#include "step.h"
#include "step_bspline2.h"
#include "threads.h"

typedef struct setup {
    lm_basis basis;
    lm_scheme scheme;
    lm_bc bc[4];
    double pic, dt;
    int threads;
    int scene;   /* 0 solid and fluid; 1 gas (viscosity) in a membrane
                    (connectivity); 2 the same with cell densities and
                    isosurface normals */
    double cell;   /* 0: 1/16 */
    double damping;   /* lamina.sim{damping} (damping.c) */
} setup;

static lm_material solid = {.kind = LM_ELASTIC, .rho = 10, .E = 1e4, .nu = 0.3};
static lm_material fluid = {.kind = LM_LINEAR_FLUID, .rho = 5, .beta = 2e3};
static lm_material skin = {.kind = LM_MEMBRANE, .rho = 0.5, .E = 1e3, .nu = 0.3,
                           .thickness = 0.05, .law = LM_LAW_PLANE_STRESS};

/* A gas disk of radius 0.3 about (0.5, 0.5) in a closed membrane of the
 * same radius, the gas at rest but for a seeded jitter. */
static int gas_in_membrane(lm_sim *sim, lm_material *gas, lm_normals normals)
{
    if (fixture_block(sim, gas, 0.25, 0.25, 0.75, 0.75, 2, 0, 0, 0.5, 3) < 0) return -1;
    /* a square of gas inside the circle: a test of the pass, not of the
     * physics */
    int mi = lm_sim_add_material(sim, &skin);
    int b = lm_sim_add_membrane(sim, mi, 1);
    if (b < 0 || lm_sim_set_membrane_normals(sim, b, normals) != LM_OK) return -1;
    int n = 96;
    double ds = 2 * 3.14159265358979323846 * 0.42 / n;
    for (int k = 0; k < n; k++) {
        double a = 2 * 3.14159265358979323846 * k / n;
        size_t q = sim->p.n;
        if (lm_sim_add_particle(sim, b, 0.5 + 0.42 * cos(a), 0.5 + 0.42 * sin(a), 0, 0,
                                skin.rho * skin.thickness * ds, skin.rho) != LM_OK ||
            lm_sim_set_membrane_point(sim, q, ds, 0.01) != LM_OK)
            return -1;
    }
    return lm_sim_prepare(sim) == LM_OK ? 0 : -1;
}

static lm_sim *build(const setup *s)
{
    lm_sim_def d;
    lm_sim_def_default(&d);
    d.x0 = 0; d.x1 = 1; d.y0 = 0; d.y1 = 1;
    d.hx = d.hy = s->cell > 0 ? s->cell : 0.0625;
    d.dt = s->dt;
    d.basis = s->basis;
    d.scheme = s->scheme;
    d.pic = s->pic;
    d.threads = s->threads;
    d.damping = s->damping;
    d.gy = -9.81;
    memcpy(d.bc, s->bc, sizeof d.bc);
    char err[256];
    lm_sim *sim = lm_sim_new(&d, err, sizeof err);
    CHECK(sim != NULL);
    if (!sim) return NULL;
    if (s->scene >= 3) {
        /* elastic solids only: two moduli, plane strain (3) or plane
         * stress (4) */
        static lm_material hard[2] = {{.kind = LM_ELASTIC, .rho = 10, .E = 2e4, .nu = 0.25},
                                      {.kind = LM_ELASTIC, .rho = 10, .E = 2e4, .nu = 0.25,
                                       .plane = LM_PLANE_STRESS}};
        static lm_material soft[2] = {{.kind = LM_ELASTIC, .rho = 8, .E = 5e3, .nu = 0.35},
                                      {.kind = LM_ELASTIC, .rho = 8, .E = 5e3, .nu = 0.35,
                                       .plane = LM_PLANE_STRESS}};
        int k = s->scene - 3;
        CHECK(fixture_block(sim, &hard[k], 0.02, 0.03, 0.45, 0.4, 2, -0.6, -0.4, 0.3, 5) >= 0);
        CHECK(fixture_block(sim, &soft[k], 0.5, 0.05, 0.93, 0.52, 2, 0.3, 0.2, 0.3, 9) >= 0);
        CHECK(lm_sim_add_particle(sim, sim->nbodies - 1, 0.7, 0.7, 0.1, 0, 0.01, 8) == LM_OK);
        return sim;
    }
    if (s->scene == 0) {
        /* a block moving into the lower-left corner, a fluid column beside it */
        CHECK(fixture_block(sim, &solid, 0.02, 0.03, 0.45, 0.4, 2, -0.6, -0.4, 0.3, 7) >= 0);
        CHECK(fixture_block(sim, &fluid, 0.55, 0.01, 0.9, 0.5, 2, 0.2, 0.1, 0.2, 11) >= 0);
        return sim;
    }
    static lm_material gas[2] = {
        /* the artificial viscosity's constants as lamina.gas{av = true} sets
         * them (the engine checks a material it is given) */
        {.kind = LM_GAS, .rho = 1, .gamma = 1.4, .mu = 0.02, .e0 = 2.5, .av = 1, .av_c1 = 1,
         .av_c2 = 1, .av_lambda = 0.75},
        {.kind = LM_GAS, .rho = 1, .gamma = 1.4, .mu = 0.02, .e0 = 2.5,
         .density = LM_DENSITY_CELL},
    };
    CHECK(gas_in_membrane(sim, &gas[s->scene - 1], s->scene == 1 ? LM_NORMALS_CONNECTIVITY
                                                                 : LM_NORMALS_ISOSURFACE) == 0);
    return sim;
}

/* The step phase by phase, as lm_sim_step makes it without the pass. */
static lm_status reference_step(lm_sim *sim)
{
    if (lm_threads_reserve(sim) != LM_OK) return LM_ERR_MEMORY;   /* the threads' copies */
    lm_step_clear(sim);
    lm_step_shape(sim);
    lm_step_p2g_forces(sim);
    lm_step_grid_update(sim);
    lm_membrane_segment_hold(sim);
    lm_step_g2p(sim);
    lm_step_strain_velocity(sim);
    lm_membrane_segment_move(sim);
    lm_status st = lm_membrane_tangents(sim);
    if (st == LM_OK) st = lm_gas_cell_density(sim);
    double md = 0, cm = 0;
    if (st == LM_OK) {
        lm_step_gas_maxima(sim, &md, &cm);
        lm_step_stress(sim, md, cm);
        lm_membrane_segment_strains(sim);
    }
    sim->step++;
    sim->t = sim->t_base + (double)(sim->step - sim->step_base) * sim->def.dt;
    if (st != LM_OK) return st;
    st = lm_step_check(sim);
    return st != LM_OK ? st : lm_step_split(sim);
}

static int same_fields(const lm_sim *a, const lm_sim *b)
{
    size_t nn = lm_grid_nodes(&a->grid);
    const lm_grid *ga = &a->grid, *gb = &b->grid;
    const double *fa[] = {ga->m, ga->px, ga->py, ga->fx, ga->fy, ga->vx, ga->vy, ga->ax, ga->ay};
    const double *fb[] = {gb->m, gb->px, gb->py, gb->fx, gb->fy, gb->vx, gb->vy, gb->ax, gb->ay};
    for (int k = 0; k < 9; k++)
        if (memcmp(fa[k], fb[k], nn * sizeof(double)) != 0) return 0;
    return 1;
}

/* steps by the reference, by lm_sim_step, and by lm_sim_step_then ahead */
static void compare(const setup *s, int steps)
{
    lm_sim *ref = build(s), *plain = build(s), *ahead = build(s), *solo = build(s);
    if (!ref || !plain || !ahead || !solo) return;
    lm_sim_fix_team(solo, 1);
    CHECK(lm_step_fusable(plain));
    CHECK(s->threads == 1 || ref->p.n >= 4096);   /* split among the threads */
    uint64_t h0 = lm_sim_hash(ref);
    for (int k = 0; k < steps; k++) {
        lm_status a = reference_step(ref), b = lm_sim_step(plain),
                  c = lm_sim_step_then(ahead, k + 1 < steps), d = lm_sim_step(solo);
        CHECK(a == LM_OK && b == LM_OK && c == LM_OK && d == LM_OK);
        if (a != LM_OK || b != LM_OK || c != LM_OK) {
            fprintf(stderr, "  scene %d, step %d: %s\n", s->scene, k, ref->err);
            break;
        }
    }
    CHECK(lm_sim_hash(ref) != h0);   /* the state moved */
    CHECK(lm_sim_hash(plain) == lm_sim_hash(ref));
    CHECK(lm_sim_hash(ahead) == lm_sim_hash(ref));
    CHECK(lm_sim_hash(solo) == lm_sim_hash(ref));
    CHECK(same_fields(plain, ref));
    CHECK(same_fields(ahead, ref));
    CHECK(plain->damped == ref->damped && ahead->damped == ref->damped &&
          solo->damped == ref->damped);
    CHECK((s->damping > 0) == (ref->damped > 0));
    if (lm_sim_hash(ahead) != lm_sim_hash(ref))
        fprintf(stderr, "  scene %d basis %d scheme %d bc %d%d%d%d pic %g: states differ\n",
                s->scene, s->basis, s->scheme, s->bc[0], s->bc[1], s->bc[2], s->bc[3], s->pic);
    lm_sim_free(ref);
    lm_sim_free(plain);
    lm_sim_free(ahead);
    lm_sim_free(solo);
}

/* A promise broken after lm_sim_forget_ahead, and a particle added without
 * it: each steps from the state as it is. */
static void edits_between_steps(void)
{
    setup s = {LM_BASIS_LINEAR, LM_USL, {LM_BC_FIXED, LM_BC_FIXED, LM_BC_FIXED, LM_BC_FIXED},
               0, 1e-4, 1, 0, 0, 0};
    lm_sim *ref = build(&s), *ahead = build(&s);
    for (int k = 0; k < 20; k++) {
        CHECK(reference_step(ref) == LM_OK);
        CHECK(lm_sim_step_then(ahead, 1) == LM_OK);
    }
    ref->p.vx[5] = ahead->p.vx[5] = 1.5;
    lm_sim_forget_ahead(ahead);
    for (int k = 0; k < 20; k++) {
        CHECK(reference_step(ref) == LM_OK);
        CHECK(lm_sim_step_then(ahead, 1) == LM_OK);
    }
    CHECK(lm_sim_hash(ahead) == lm_sim_hash(ref));
    int b = ref->nbodies - 1;
    CHECK(lm_sim_add_particle(ref, b, 0.7, 0.7, 0, 0, 0.01, fluid.rho) == LM_OK);
    CHECK(lm_sim_add_particle(ahead, b, 0.7, 0.7, 0, 0, 0.01, fluid.rho) == LM_OK);
    for (int k = 0; k < 20; k++) {
        CHECK(reference_step(ref) == LM_OK);
        CHECK(lm_sim_step_then(ahead, 1) == LM_OK);
    }
    CHECK(lm_sim_hash(ahead) == lm_sim_hash(ref));
    lm_sim_free(ref);
    lm_sim_free(ahead);
}

/* dt far past the Courant limit: the same step, particle and words. */
static void blow_up(lm_scheme scheme)
{
    setup s = {LM_BASIS_LINEAR, scheme, {LM_BC_FIXED, LM_BC_FIXED, LM_BC_FIXED, LM_BC_FIXED},
               0, 0.05, 1, 0, 0, 0};
    lm_sim *ref = build(&s), *ahead = build(&s);
    /* the engine refuses such a dt before its first step (courant_check.c):
     * the limit raised out of the way, the step itself is what is compared */
    CHECK(lm_sim_check_courant(ahead) == LM_ERR_COURANT);
    CHECK(lm_sim_set_courant(ahead, 1e9) == LM_OK);
    lm_status a = LM_OK, b = LM_OK;
    int ka = -1, kb = -1;
    for (int k = 0; k < 400 && (a == LM_OK || b == LM_OK); k++) {
        if (a == LM_OK && (a = reference_step(ref)) != LM_OK) ka = k;
        if (b == LM_OK && (b = lm_sim_step_then(ahead, 1)) != LM_OK) kb = k;
    }
    CHECK(a != LM_OK);
    CHECK(a == b);
    CHECK(ka == kb);
    CHECK(strcmp(ref->err, ahead->err) == 0);
    if (strcmp(ref->err, ahead->err) != 0) fprintf(stderr, "  %s\n  %s\n", ref->err, ahead->err);
    lm_sim_free(ref);
    lm_sim_free(ahead);
}

int main(void)
{
    const lm_basis bases[3] = {LM_BASIS_LINEAR, LM_BASIS_GIMP, LM_BASIS_BSPLINE2};
    const lm_bc walls[3][4] = {
        {LM_BC_FIXED, LM_BC_FIXED, LM_BC_FIXED, LM_BC_FIXED},
        {LM_BC_SYMMETRY, LM_BC_FREE, LM_BC_SYMMETRY, LM_BC_FREE},
        {LM_BC_FREE, LM_BC_SYMMETRY, LM_BC_FIXED, LM_BC_FREE},
    };
    for (int b = 0; b < 3; b++)
        for (int sc = 0; sc < 2; sc++)
            for (int w = 0; w < 3; w++) {
                setup s = {bases[b], sc ? LM_USL : LM_MUSL, {0}, w == 2 ? 0.3 : 0, 1e-4, 1, 0, 0, 0};
                memcpy(s.bc, walls[w], sizeof s.bc);
                compare(&s, 150);
            }
    /* the B-spline's USL pass (step_bspline2.c) in each instruction set
     * it has, forced: the phases' bits from both (issue 36 item 2) */
    for (int set = LM_B2_ISA_BASELINE; set <= LM_B2_ISA_AVX2; set++) {
#if defined(__x86_64__) && defined(__GNUC__)
        __builtin_cpu_init();
        if (set == LM_B2_ISA_AVX2 && !__builtin_cpu_supports("avx2")) continue;
#else
        if (set == LM_B2_ISA_AVX2) continue;
#endif
        lm_fused_bspline2_isa(set);
        for (int w = 0; w < 3; w++) {
            setup s = {LM_BASIS_BSPLINE2, LM_USL, {0}, w == 2 ? 0.3 : 0, 1e-4, 1, 0, 0, 0};
            memcpy(s.bc, walls[w], sizeof s.bc);
            compare(&s, 150);
        }
        lm_fused_bspline2_isa(-1);
    }
    for (int scene = 1; scene <= 2; scene++)
        for (int b = 0; b < 3; b++)
            for (int sc = 0; sc < 2; sc++) {
                setup s = {bases[b], sc ? LM_USL : LM_MUSL, {0}, 0, 5e-5, 1, scene, 0, 0};
                memcpy(s.bc, walls[b], sizeof s.bc);
                compare(&s, 60);
            }
    for (int scene = 3; scene <= 4; scene++)
        for (int b = 0; b < 3; b++)
            for (int sc = 0; sc < 2; sc++) {
                setup s = {bases[b], sc ? LM_USL : LM_MUSL, {0}, scene == 3 ? 0.2 : 0, 1e-4, 1,
                           scene, 0, 0};
                memcpy(s.bc, walls[scene - 3], sizeof s.bc);
                compare(&s, 100);
            }
    /* two and three threads: each pass a parallel loop, nothing ahead; the
     * scenes large enough to be split (LM_PARTICLE_LOOP_MIN) */
    for (int nt = 2; nt <= 3; nt++)
        for (int scene = 0; scene <= 2; scene++)
            for (int sc = 0; sc < 2; sc++) {
                setup s = {bases[(scene + sc) % 3], sc ? LM_USL : LM_MUSL, {0}, 0, 5e-5, nt,
                           scene, 0.015625, 0};
                memcpy(s.bc, walls[scene], sizeof s.bc);
                compare(&s, 30);
            }
    /* grid damping (issue 35 item 2): the pass reads the damped forces as
     * the phases do, on one thread and on two */
    for (int nt = 1; nt <= 2; nt++)
        for (int scene = 0; scene <= 1; scene++)
            for (int sc = 0; sc < 2; sc++) {
                setup s = {bases[(scene + sc + 2) % 3], sc ? LM_USL : LM_MUSL, {0}, 0, 5e-5, nt,
                           scene, nt > 1 ? 0.015625 : 0, 50};
                memcpy(s.bc, walls[scene], sizeof s.bc);
                compare(&s, 30);
            }
    edits_between_steps();
    blow_up(LM_USL);
    blow_up(LM_MUSL);
    return CHECK_DONE();
}
