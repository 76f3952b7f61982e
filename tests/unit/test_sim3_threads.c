/* test_sim3_threads.c - the 3D step on threads (issue 34 item 1 "threads
 * and determinism as in 2D"; sim3_threads.c, docs/3d.md): the same thread
 * count gives the same bits, run after run; another count gives the same
 * state to rounding (the scatters' sums are taken in another order), held
 * against what one unit in the last place of the velocities grows into
 * in the same run. An
 * elastic block (trilinear MUSL, quadratic B-spline USL) and a gas with
 * the artificial viscosity, spinning and sheared, falling in a fixed box:
 * 8 000 particles, above the threads' minimum, 40 steps. Without OpenMP
 * every count runs on one thread, and the checks hold trivially. */
#include <math.h>
#include <string.h>

#include "block3_fixture.h"
#include "check.h"
#include "mpm3.h"

static lm3_sim *block(lm_basis basis, lm_scheme scheme, int gas, int threads, int nudge)
{
    lm3_sim *sim = block3_new(basis, scheme, gas, threads, NULL);
    block3_spin(sim);
    /* one unit in the last place of every particle's x velocity: how far
     * rounding differences everywhere grow in this flow */
    if (nudge)
        for (size_t q = 0; q < sim->p.n; q++) sim->p.v[0][q] = nextafter(sim->p.v[0][q], 1e9);
    for (int k = 0; k < 40; k++)
        if (lm3_step(sim) != LM_OK) {
            fprintf(stderr, "%s\n", sim->err);
            CHECK(!"step failed");
            break;
        }
    return sim;
}

/* 1 when every particle array of a and b holds the same bits */
static int same_bits(const lm3_sim *a, const lm3_sim *b)
{
    size_t n = a->p.n * sizeof(double);
    if (a->p.n != b->p.n) return 0;
    for (int k = 0; k < 3; k++)
        if (memcmp(a->p.x[k], b->p.x[k], n) || memcmp(a->p.v[k], b->p.v[k], n)) return 0;
    for (int c = 0; c < 6; c++)
        if (memcmp(a->p.s[c], b->p.s[c], n)) return 0;
    return !memcmp(a->p.rho, b->p.rho, n) && !memcmp(a->p.e, b->p.e, n);
}

/* the largest difference of position (m) and of stress (relative to the
 * largest stress) between a and b */
static void diff(const lm3_sim *a, const lm3_sim *b, double *dx, double *ds)
{
    double smax = 0;
    *dx = *ds = 0;
    for (size_t q = 0; q < a->p.n; q++) {
        for (int k = 0; k < 3; k++) *dx = fmax(*dx, fabs(a->p.x[k][q] - b->p.x[k][q]));
        for (int c = 0; c < 6; c++) {
            *ds = fmax(*ds, fabs(a->p.s[c][q] - b->p.s[c][q]));
            smax = fmax(smax, fabs(a->p.s[c][q]));
        }
    }
    *ds /= smax;
}

/* The thresholds: a state that differs from the one-thread state by no
 * more than 100 times what one unit in the last place of every particle's
 * x velocity grows into over the same steps (the scatters' sums in another order
 * are such rounding differences), and never by more than 1e-9 relative. */
static void case_(const char *name, lm_basis basis, lm_scheme scheme, int gas)
{
    lm3_sim *one = block(basis, scheme, gas, 1, 0), *two = block(basis, scheme, gas, 2, 0),
            *two_b = block(basis, scheme, gas, 2, 0), *three = block(basis, scheme, gas, 3, 0),
            *nudged = block(basis, scheme, gas, 1, 1);
    double dx2, ds2, dx3, ds3, dxn, dsn;
    diff(one, two, &dx2, &ds2);
    diff(one, three, &dx3, &ds3);
    diff(one, nudged, &dxn, &dsn);
    int s2 = same_bits(two, two_b);
    printf("%s: %zu particles, 40 steps: 2 threads twice %s; against one thread: 2 threads "
           "|dx| %.2g m, |d sigma| %.2g of the largest; 3 threads %.2g m, %.2g; one ulp of "
           "every v_x on one thread grows to %.2g m, %.2g\n", name, one->p.n,
           s2 ? "the same bits" : "DIFFER", dx2, ds2, dx3, ds3, dxn, dsn);
    CHECK(s2);
    CHECK(dxn > 0);   /* the nudge reached the state */
    double tx = fmin(fmax(100 * dxn, 1e-15), 1e-9), ts = fmin(fmax(100 * dsn, 1e-15), 1e-9);
    CHECK(dx2 <= tx && dx3 <= tx);
    CHECK(ds2 <= ts && ds3 <= ts);
    lm3_sim_free(one);
    lm3_sim_free(two);
    lm3_sim_free(two_b);
    lm3_sim_free(three);
    lm3_sim_free(nudged);
}

int main(void)
{
    case_("trilinear MUSL", LM_BASIS_LINEAR, LM_MUSL, 0);
    case_("bspline2 USL", LM_BASIS_BSPLINE2, LM_USL, 0);
    case_("gas trilinear MUSL", LM_BASIS_LINEAR, LM_MUSL, 1);
    return CHECK_DONE();
}
