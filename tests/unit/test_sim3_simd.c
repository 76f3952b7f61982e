/* test_sim3_simd.c - the 3D trilinear scatters and stress pass in
 * AVX-512's eight lanes (sim3_simd512.c, chosen at run time) give the bits
 * of the two-lane SSE2 and scalar kernels (issue 34 item 6; docs/3d.md
 * "Speed"): an elastic block and a gas spinning, sheared and falling in a
 * fixed box, 8 000 particles, 40 steps, MUSL (both scatters: p2g and the
 * re-map) and USL, on one and two threads, run with the kernels limited
 * to SSE2 and with the processor's best; every particle array and the
 * state hash the same bits. Two more for the stress pass's groups of
 * eight (perf34): the block with a second elastic material on every fifth
 * particle and a gas on every seventh, three particles more (groups of
 * mixed materials and a tail taken one by one), and the block with one
 * particle thrown at 10^5 m/s, whose first step fails (1 + tr de <= 0 at
 * some particles: the lanes of those left as they were). On a
 * processor without AVX-512F (or a build without it) both runs take the
 * same kernels: the test says so and its checks hold trivially. */
#include <stdint.h>
#include <string.h>

#include "block3_fixture.h"
#include "check.h"
#include "mpm3.h"
#include "sim3_simd.h"

/* kind: 0 elastic, 1 gas, 2 mixed materials and a tail, 3 a failing step */
static lm3_sim *run(lm_scheme scheme, int kind, int threads, int level)
{
    const int gas = kind == 1;
    lm3_simd_limit(level);
    char err[256];
    int mi;
    lm3_sim *sim = block3_new(LM_BASIS_LINEAR, scheme, gas, threads, &mi);
    if (kind == 2) {
        lm3_material m2 = {.rho = 1000, .E = 2e6, .nu = 0.25};
        lm3_material g = {.rho = 1000, .kind = LM3_GAS, .gamma = 1.4, .mu = 0.1, .av = 1,
                          .av_c1 = 1, .av_c2 = 1, .av_lambda = 0.75, .e0 = 1.35e3 / 0.56};
        int m2i = lm3_material_add(sim, &m2, err, sizeof err),
            gi = lm3_material_add(sim, &g, err, sizeof err);
        CHECK(m2i > 0 && gi > 0);
        for (size_t q = 0; q < sim->p.n; q++)
            if (q % 7 == 3) sim->p.mat[q] = (uint8_t)gi;
            else if (q % 5 == 1) sim->p.mat[q] = (uint8_t)m2i;
        for (int k = 0; k < 3; k++) {
            const double x[3] = {0.3 + 0.1 * k, 0.5, 0.5}, v0[3] = {0, 0, 0};
            CHECK(lm3_particle_add(sim, mi, x, v0, 1.5e-5) == LM_OK);
        }
        CHECK(sim->p.n % 8 != 0);
    }
    block3_spin(sim);
    if (kind == 3) {
        sim->p.v[0][4321] = -1e5;
        CHECK(lm3_step(sim) == LM_ERR_UNSTABLE);
        CHECK(strstr(sim->err, "volume went to nothing") != NULL);
        lm3_simd_limit(LM3_SIMD_AVX512);
        return sim;
    }
    for (int k = 0; k < 40; k++)
        if (lm3_step(sim) != LM_OK) {
            fprintf(stderr, "%s\n", sim->err);
            CHECK(!"step failed");
            break;
        }
    lm3_simd_limit(LM3_SIMD_AVX512);
    return sim;
}

/* 1 when every particle array of a and b holds the same bits */
static int same_bits(const lm3_sim *a, const lm3_sim *b)
{
    size_t n = a->p.n * sizeof(double);
    if (a->p.n != b->p.n || lm3_sim_hash(a) != lm3_sim_hash(b)) return 0;
    for (int k = 0; k < 3; k++)
        if (memcmp(a->p.x[k], b->p.x[k], n) || memcmp(a->p.v[k], b->p.v[k], n)) return 0;
    for (int c = 0; c < 6; c++)
        if (memcmp(a->p.s[c], b->p.s[c], n)) return 0;
    return !memcmp(a->p.rho, b->p.rho, n) && !memcmp(a->p.e, b->p.e, n);
}

static void case_(const char *name, lm_scheme scheme, int kind, int threads)
{
    lm3_sim *sse2 = run(scheme, kind, threads, LM3_SIMD_SSE2),
            *best = run(scheme, kind, threads, LM3_SIMD_AVX512);
    int same = same_bits(sse2, best);
    printf("%s, %d thread%s, %zu particles, %d steps: AVX-512 against SSE2: %s\n", name,
           threads, threads > 1 ? "s" : "", sse2->p.n, kind == 3 ? 1 : 40,
           same ? "the same bits" : "DIFFER");
    CHECK(same);
    lm3_sim_free(sse2);
    lm3_sim_free(best);
}

int main(void)
{
    printf("kernels: %s\n", lm3_simd_level() == LM3_SIMD_AVX512
                                ? "AVX-512F (built and the processor has it)"
                                : "SSE2 only (no AVX-512F here): the runs below compare SSE2 "
                                  "with itself");
    for (int t = 1; t <= 2; t++) {
        case_("trilinear MUSL", LM_MUSL, 0, t);
        case_("trilinear USL", LM_USL, 0, t);
        case_("gas trilinear MUSL", LM_MUSL, 1, t);
        case_("two solids and a gas, trilinear MUSL", LM_MUSL, 2, t);
        case_("a failing first step, trilinear USL", LM_USL, 3, t);
    }
    return CHECK_DONE();
}
