/* test_sim3_threads_span.c - the threads' scatters add only the span of
 * nodes each thread's particles reached (sim3_threads.c, issue 34 item 6;
 * docs/3d.md "Threads and determinism"): nothing a thread scattered is
 * lost, and its copy of the fields is left all zero for the next scatter.
 *
 * An elastic block, spinning and sheared, away from the walls, on 2 and 3
 * threads, its particles in the seeded (z-major) order, where the
 * threads' spans barely overlap, and shuffled, where each span is the
 * whole block. After every step: the threads' copies are all zero; the
 * grid's mass is the particles' (sum m_i = sum m_p, the weights a
 * partition of unity); under MUSL the re-mapped momenta are the
 * particles' new ones (sum m_i v_i = sum m_p v_p^{k+1}). A node a thread
 * reached but the addition skipped would lose about an eighth of a
 * particle's share, 1e-5 of the sums here; the checks hold to 1e-12. At
 * the end the state is one thread's to rounding (1e-9), and the same
 * count twice gives the same bits. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "block3_fixture.h"
#include "check.h"
#include "mpm3.h"

static lm3_sim *block(lm_basis basis, lm_scheme scheme, int threads, int shuffle)
{
    lm3_sim *sim = block3_new(basis, scheme, 0, threads, NULL);
    const size_t n = sim->p.n;
    if (shuffle) {
        /* q -> 7919 q mod n, a permutation when n is not a multiple of
         * the prime 7919: the particles' places shuffled (all else is the
         * same at every particle of the seeded block) */
        CHECK(n % 7919 != 0);
        double *x[3];
        for (int k = 0; k < 3; k++) {
            x[k] = malloc(n * sizeof(double));
            memcpy(x[k], sim->p.x[k], n * sizeof(double));
        }
        for (size_t q = 0; q < n; q++)
            for (int k = 0; k < 3; k++) sim->p.x[k][q] = x[k][(q * 7919) % n];
        for (int k = 0; k < 3; k++) free(x[k]);
    }
    block3_spin(sim);
    return sim;
}

/* the checks after a step; 0 when one failed (printed) */
static int sums_hold(const lm3_sim *sim, const char *name, int step)
{
    const lm3_grid *g = &sim->grid;
    const lm3_particles *p = &sim->p;
    size_t nonzero = 0;
    for (size_t i = 0; i < sim->scratch_len; i++) nonzero += sim->scratch[i] != 0;
    double mg = 0, mp = 0, Pg[3] = {0, 0, 0}, Pp[3] = {0, 0, 0}, Pabs = 0;
    for (size_t i = 0; i < g->nn; i++) {
        mg += g->m[i];
        for (int a = 0; a < 3; a++) Pg[a] += g->m[i] * g->v[a][i];
    }
    for (size_t q = 0; q < p->n; q++) {
        mp += p->m[q];
        for (int a = 0; a < 3; a++) {
            Pp[a] += p->m[q] * p->v[a][q];
            Pabs += p->m[q] * fabs(p->v[a][q]);
        }
    }
    double dm = fabs(mg - mp) / mp, dP = 0;
    if (sim->def.scheme == LM_MUSL)
        for (int a = 0; a < 3; a++) dP = fmax(dP, fabs(Pg[a] - Pp[a]) / Pabs);
    int ok = nonzero == 0 && dm <= 1e-12 && dP <= 1e-12;
    if (!ok || step == 19)
        printf("%s, step %d: %zu nonzero doubles in the threads' copies (of %zu); "
               "|sum m_i - sum m_p| %.2g of it; |sum m_i v_i - sum m_p v_p| %.2g of "
               "sum m_p |v_p|\n", name, step, nonzero, sim->scratch_len, dm, dP);
    return ok;
}

static void case_(const char *name, lm_basis basis, lm_scheme scheme, int shuffle)
{
    lm3_sim *one = block(basis, scheme, 1, shuffle);
    for (int k = 0; k < 20; k++) CHECK(lm3_step(one) == LM_OK);
    for (int nt = 2; nt <= 3; nt++) {
        lm3_sim *a = block(basis, scheme, nt, shuffle), *b = block(basis, scheme, nt, shuffle);
        char label[128];
        snprintf(label, sizeof label, "%s, %s order, %d threads", name,
                 shuffle ? "shuffled" : "seeded", nt);
        int held = 1;
        for (int k = 0; k < 20; k++) {
            CHECK(lm3_step(a) == LM_OK && lm3_step(b) == LM_OK);
            held &= sums_hold(a, label, k);
        }
        CHECK(held);
#ifdef _OPENMP
        CHECK(a->scratch_len > 0);   /* the threads ran with copies */
#endif
        double dx = 0;
        int same = 1;
        for (int k = 0; k < 3; k++)
            for (size_t q = 0; q < a->p.n; q++) {
                dx = fmax(dx, fabs(a->p.x[k][q] - one->p.x[k][q]));
                same &= memcmp(&a->p.x[k][q], &b->p.x[k][q], sizeof(double)) == 0 &&
                        memcmp(&a->p.v[k][q], &b->p.v[k][q], sizeof(double)) == 0;
            }
        printf("%s: |dx| against one thread %.2g m; twice: %s\n", label, dx,
               same ? "the same bits" : "DIFFER");
        CHECK(dx <= 1e-9);
        CHECK(same);
        lm3_sim_free(a);
        lm3_sim_free(b);
    }
    lm3_sim_free(one);
}

int main(void)
{
    case_("trilinear MUSL", LM_BASIS_LINEAR, LM_MUSL, 0);
    case_("trilinear MUSL", LM_BASIS_LINEAR, LM_MUSL, 1);
    case_("bspline2 MUSL", LM_BASIS_BSPLINE2, LM_MUSL, 1);
    case_("trilinear USL", LM_BASIS_LINEAR, LM_USL, 1);
    return CHECK_DONE();
}
