/* test_bench_bytes.c - the bytes a particle-step moves (bench_bytes.c,
 * `lamina bench roofline`, issue 36 item 3): not a timing test. The counts
 * are positive and ordered as the passes say they must be - a 3 x 3 basis
 * moves more than the bilinear one, a membrane point more than an elastic
 * one (its tangent, strain and length, and the tangent passes), the fused
 * passes fewer than the phases, MUSL's re-map more than USL - and two of
 * them and the grid's passes a node equal a count by hand (ours, from step_fused.c and
 * lm_elastic_update_at: see the sums below). */
#include "bench.h"
#include "check.h"

int main(void)
{
    const lm_kind kinds[] = {LM_ELASTIC, LM_MEMBRANE, LM_GAS, LM_LINEAR_FLUID};
    for (int f = 0; f < 2; f++)
        for (int s = 0; s < 2; s++) {
            lm_scheme sc = s ? LM_MUSL : LM_USL;
            for (int k = 0; k < 4; k++) {
                bench_bytes b[3];
                for (int ba = 0; ba < 3; ba++) {
                    CHECK(bench_bytes_count((lm_basis)ba, kinds[k], sc, f, &b[ba]) == 0);
                    CHECK(b[ba].particle > 0 && b[ba].stencil > 0 && b[ba].passes >= 1);
                    /* the phases read a particle more often than the fused passes */
                    bench_bytes ph;
                    bench_bytes_count((lm_basis)ba, kinds[k], sc, 0, &ph);
                    if (f) CHECK(b[ba].particle < ph.particle && b[ba].passes < ph.passes);
                    /* MUSL re-maps the momentum: m, v and N read again */
                    bench_bytes usl;
                    bench_bytes_count((lm_basis)ba, kinds[k], LM_USL, f, &usl);
                    if (s) CHECK(b[ba].particle > usl.particle && b[ba].stencil > usl.stencil);
                    /* a membrane adds its arrays (tx, ty, et, ds) and passes */
                    bench_bytes el;
                    bench_bytes_count((lm_basis)ba, LM_ELASTIC, sc, f, &el);
                    if (kinds[k] == LM_MEMBRANE)
                        CHECK(b[ba].particle > el.particle && b[ba].passes > el.passes);
                }
                /* the B-spline keeps its place as the bilinear basis does
                 * (issue 36 item 2): the same particle bytes, a wider
                 * stencil */
                CHECK(b[LM_BASIS_BSPLINE2].particle == b[LM_BASIS_LINEAR].particle);
                CHECK(b[LM_BASIS_BSPLINE2].stencil > b[LM_BASIS_LINEAR].stencil);
                /* uGIMP's 27 stored weights and gradients against xi, eta */
                CHECK(b[LM_BASIS_GIMP].particle > b[LM_BASIS_BSPLINE2].particle);
            }
        }
    /* By hand: the one fused pass of a bilinear elastic USL step reads and
     * writes x, y, vx, vy (g2p), rho and the four stresses (step 8), node,
     * xi, eta (the next step's shape); reads m (the scatter) and mat. */
    const double D = sizeof(double), I = sizeof(int);
    bench_bytes b;
    bench_bytes_count(LM_BASIS_LINEAR, LM_ELASTIC, LM_USL, 1, &b);
    CHECK(b.particle == 2 * (4 * D + 5 * D + 2 * D + I) + D + I);   /* 196 */
    CHECK(b.passes == 1);
    /* stencil: 4 nodes x (4 read by g2p + 2 by the rate + 5 updated twice) */
    CHECK(b.stencil == 4 * D * (4 + 2 + 2 * 5));
    /* the quadratic B-spline keeps xi, eta too (196); uGIMP stores N, Gx,
     * Gy (27 doubles) for them and reads its half-sizes lx, ly */
    bench_bytes_count(LM_BASIS_BSPLINE2, LM_ELASTIC, LM_USL, 1, &b);
    CHECK(b.particle == 2 * (4 * D + 5 * D + 2 * D + I) + D + I);   /* 196 */
    bench_bytes_count(LM_BASIS_GIMP, LM_ELASTIC, LM_USL, 1, &b);
    CHECK(b.particle == 2 * (4 * D + 5 * D + 27 * D + I) + D + I + 2 * D);  /* 612 */
    /* the grid's passes a node: clear 5, gravity 5, update 6, g2p nodes
     * 9, USL's v = p / m 5 doubles; MUSL's re-map 7 for those 5 */
    CHECK(bench_bytes_grid(LM_USL) == 30 * D);
    CHECK(bench_bytes_grid(LM_MUSL) == 32 * D);
    /* the B-spline's USL pass: records (6 read, 8 written), the sums
     * handed out (4 read, 4 written, 4 zeroed), 4 fewer cleared */
    CHECK(bench_bytes_grid_pass(LM_BASIS_BSPLINE2, LM_USL) == 22 * D);
    CHECK(bench_bytes_grid_pass(LM_BASIS_BSPLINE2, LM_MUSL) == 0);
    CHECK(bench_bytes_grid_pass(LM_BASIS_LINEAR, LM_USL) == 0);
    CHECK(bench_bytes_count((lm_basis)7, LM_ELASTIC, LM_USL, 1, &b) == -1);
    return CHECK_DONE();
}
