/* test_sim3_slab.c - a 3D run one cell thick between two symmetry faces is
 * the 2D plane-strain run (issue 34 item 3, "the 2D cases as one-cell-thick
 * slabs agree with the 2D runs", here at the engine's level; docs/3d.md).
 *
 * Why it must agree to rounding: every column of the slab holds particles
 * in the same (x, y) state, so each node layer's v = p / m is the 2D one;
 * the symmetry faces hold v_z = 0 on both node planes (and their ghosts'
 * images), so de_zz = 0 (plane strain) and the z factors of the weights
 * sum to one in every x-y gradient. The 2D engine (lm_sim) and the 3D core
 * (lm3_sim) share no step code, so this checks the 3D step, walls and law
 * against the 2D ones. The block spreads in x, falls onto a fixed floor
 * and is stressed by it. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "mpm3.h"
#include "sim_fixture.h"

static void slab(lm_basis basis)
{
    const double h = 0.1, dt = 1e-3, g = -9.81;
    const int steps = 300;
    lm_sim_def d2;
    lm_sim_def_default(&d2);
    d2.x0 = 0; d2.y0 = 0; d2.x1 = 1; d2.y1 = 1;
    d2.hx = d2.hy = h;
    d2.dt = dt;
    d2.gy = g;
    d2.basis = basis;
    for (int s = 0; s < 4; s++) d2.bc[s] = LM_BC_FREE;
    d2.bc[LM_BOTTOM] = LM_BC_FIXED;
    char err[256];
    lm_sim *a = lm_sim_new(&d2, err, sizeof err);
    CHECK(a != NULL);
    if (!a) return;
    lm_material m2 = {.kind = LM_ELASTIC, .rho = 1000, .E = 1e5, .nu = 0.3,
                      .plane = LM_PLANE_STRAIN};
    CHECK(fixture_block(a, &m2, 0.3, 0.1, 0.7, 0.4, 2, 0, 0, 0, 1) >= 0);
    for (size_t q = 0; q < a->p.n; q++) a->p.vx[q] = a->p.x[q] - 0.5;

    lm3_def d3;
    memset(&d3, 0, sizeof d3);
    d3.hi[0] = d3.hi[1] = 1;
    d3.hi[2] = h;
    d3.cell = h;
    d3.dt = dt;
    d3.gravity[1] = g;
    d3.basis = basis;
    d3.scheme = LM_MUSL;
    for (int f = 0; f < LM3_FACES; f++) d3.bc[f] = LM_BC_FREE;
    d3.bc[LM3_YLO] = LM_BC_FIXED;
    d3.bc[LM3_ZLO] = d3.bc[LM3_ZHI] = LM_BC_SYMMETRY;
    lm3_sim *b = lm3_sim_create(&d3, err, sizeof err);
    lm3_material m3 = {.rho = 1000, .E = 1e5, .nu = 0.3};
    int mi = lm3_material_add(b, &m3, err, sizeof err);
    double lo[3] = {0.3, 0.1, 0}, hi[3] = {0.7, 0.4, h}, v[3] = {0, 0, 0};
    CHECK(lm3_seed_box(b, mi, lo, hi, 2, v) == 2 * (long)a->p.n);
    for (size_t q = 0; q < b->p.n; q++) b->p.v[0][q] = b->p.x[0][q] - 0.5;

    for (int k = 0; k < steps; k++) {
        CHECK(lm_sim_step(a) == LM_OK);
        CHECK(lm3_step(b) == LM_OK);
    }
    /* each 3D particle against the 2D particle that started where it did
     * in x-y (seeded in the same order: the 3D box's layers are z-outer) */
    double dx = 0, ds = 0, dzz = 0, smax = 0, vz = 0;
    size_t n2 = a->p.n, matched = 0;
    for (size_t q = 0; q < b->p.n; q++) {
        size_t r = q % n2;
        dx = fmax(dx, fmax(fabs(b->p.x[0][q] - a->p.x[r]), fabs(b->p.x[1][q] - a->p.y[r])));
        ds = fmax(ds, fabs(b->p.s[0][q] - a->p.sxx[r]));
        ds = fmax(ds, fabs(b->p.s[1][q] - a->p.syy[r]));
        ds = fmax(ds, fabs(b->p.s[5][q] - a->p.sxy[r]));
        dzz = fmax(dzz, fabs(b->p.s[2][q] - a->p.szz[r]));
        smax = fmax(smax, fmax(fabs(a->p.syy[r]), fabs(a->p.sxx[r])));
        vz = fmax(vz, fabs(b->p.v[2][q]));
        matched++;
    }
    printf("slab %s: %zu 3D particles against %zu 2D ones after %d steps: |dx| %.2g m, "
           "|d sigma| %.2g Pa, |d sigma_zz| %.2g Pa of %.3g, |v_z| %.2g m/s\n",
           basis == LM_BASIS_LINEAR ? "trilinear" : "bspline2", b->p.n, n2, steps, dx, ds, dzz,
           smax, vz);
    CHECK(matched == 2 * n2);
    CHECK(smax > 100);   /* the floor was reached */
    CHECK(dx < 1e-12);
    CHECK(ds < 1e-9 * smax);
    CHECK(dzz < 1e-9 * smax);
    CHECK(vz == 0);
    lm_sim_free(a);
    lm3_sim_free(b);
}

int main(void)
{
    slab(LM_BASIS_LINEAR);
    slab(LM_BASIS_BSPLINE2);
    return CHECK_DONE();
}
