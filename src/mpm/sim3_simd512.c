/* sim3_simd512.c - the trilinear step's scatters with a particle's whole
 * 2 x 2 x 2 stencil in one AVX-512 vector, and its gathers (g2p, the
 * stress pass) with eight particles in the lanes (issue 34 item 6;
 * docs/3d.md "Speed"), chosen at run time (sim3_simd.h): the build stays portable
 * (no -march; this file alone is compiled with -mavx512f, and its
 * functions run only where the processor says it has AVX-512F).
 *
 * Lane 2 r + a is node a of stencil row r = b + 2 c (the rows of
 * sim3_step.c's loops, c outer): each lane makes its node's term with
 * the operations, in the order, that sim3_step.c's p2g_at and remap_at
 * make it (N = w0[a] wyz, m N, N m v, -(A g0[a] + B w0[a]) with A, B from
 * the row's wyz, gyz, wgz), and each node of the stencil receives one
 * term a particle, so the sums at every node are the same bits as the
 * two-lane kernels' (sim3_kernels2.h) and the scalar ones'
 * (tests/unit/test_sim3_simd.c). Row r's two nodes are contiguous; the
 * four rows are loaded into and stored from the vector's 128-bit quarters.
 * No fused multiply-add: the build's -ffp-contract=off, and none is
 * written here. */
#include "sim3_simd.h"

#if defined(__AVX512F__)
#include <immintrin.h>
#include <math.h>

#include "sim3_shape.h"

/* The eight stencil nodes' values of one field: rows at p + o[0..3]. */
static inline __m512d load8(const double *p, const long o[4])
{
    __m256d lo = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p + o[0])),
                                      _mm_loadu_pd(p + o[1]), 1);
    __m256d hi = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p + o[2])),
                                      _mm_loadu_pd(p + o[3]), 1);
    return _mm512_insertf64x4(_mm512_castpd256_pd512(lo), hi, 1);
}

static inline void store8(double *p, const long o[4], __m512d v)
{
    __m256d lo = _mm512_castpd512_pd256(v), hi = _mm512_extractf64x4_pd(v, 1);
    _mm_storeu_pd(p + o[0], _mm256_castpd256_pd128(lo));
    _mm_storeu_pd(p + o[1], _mm256_extractf128_pd(lo, 1));
    _mm_storeu_pd(p + o[2], _mm256_castpd256_pd128(hi));
    _mm_storeu_pd(p + o[3], _mm256_extractf128_pd(hi, 1));
}

/* A particle's stencil: the rows' first nodes and the lanes' factors,
 * W0 = w0[a], G0 = g0[a], WYZ = w1[b] w2[c], GYZ = g1[b] w2[c],
 * WGZ = w1[b] g2[c] (sim3_step.c row_of). */
typedef struct stencil8 {
    long o[4];
    __m512d W0, G0, WYZ, GYZ, WGZ;
} stencil8;

/* Each lane's factor: lane 2 r + a, r = b + 2 c, takes w[0][a], w[1][b],
 * w[2][c] (and g likewise): a blend of two broadcasts by the lanes' bits
 * of a (0xAA), b (0xCC) or c (0xF0). The values are the scalar weights'
 * (lm_linear_1d: w = (1 - d, d), g = (-r, r)) moved, not recomputed. */
static inline __m512d lanes_of(double v0, double v1, __mmask8 bit)
{
    return _mm512_mask_blend_pd(bit, _mm512_set1_pd(v0), _mm512_set1_pd(v1));
}

static inline void stencil_of(const lm3_grid *g, int32_t node, const double d[3], stencil8 *s)
{
    const double r = 1.0 / g->h;
    const long n0 = node, s0 = g->s[0], s01 = g->s[0] * g->s[1];
    s->o[0] = n0;
    s->o[1] = n0 + s0;
    s->o[2] = n0 + s01;
    s->o[3] = n0 + s01 + s0;
    /* lanes 0..7: (a, b, c) = (0,0,0) (1,0,0) (0,1,0) (1,1,0) (0,0,1) ... */
    const __m512d W1 = lanes_of(1 - d[1], d[1], 0xCC), G1 = lanes_of(-r, r, 0xCC);
    const __m512d W2 = lanes_of(1 - d[2], d[2], 0xF0), G2 = lanes_of(-r, r, 0xF0);
    s->W0 = lanes_of(1 - d[0], d[0], 0xAA);
    s->G0 = lanes_of(-r, r, 0xAA);
    s->WYZ = _mm512_mul_pd(W1, W2);
    s->GYZ = _mm512_mul_pd(G1, W2);
    s->WGZ = _mm512_mul_pd(W1, G2);
}

/* Step 0 (sim3_shape.h lm3_place_w, W = 2) at the eight particles q ..
 * q + 7 in the lanes: f = (x - lo) / h as (x - lo) r, the cell floor(f)
 * (what the scalar (int) f or floor gives; out of range both clamp the
 * same way, (int) of a huge or NaN f being INT_MIN on x86 as the vector
 * conversion's), clamped to [0, n - 1], the offset f - i; the stencil's
 * first node (pad 0). Writes p->d and p->node as place_at does. */
static inline void place8(lm3_sim *sim, size_t q)
{
    lm3_particles *p = &sim->p;
    const lm3_grid *g = &sim->grid;
    const __m512d r = _mm512_set1_pd(1.0 / g->h);
    __m256i c[3];
    for (int a = 0; a < 3; a++) {
        const __m512d f =
            _mm512_mul_pd(_mm512_sub_pd(_mm512_loadu_pd(p->x[a] + q), _mm512_set1_pd(g->lo[a])), r);
        __m256i i = _mm512_cvttpd_epi32(_mm512_roundscale_pd(f, _MM_FROUND_TO_NEG_INF));
        i = _mm256_min_epi32(i, _mm256_set1_epi32(g->n[a] - 1));
        i = _mm256_max_epi32(i, _mm256_setzero_si256());
        c[a] = i;
        _mm512_storeu_pd(p->d[a] + q, _mm512_sub_pd(f, _mm512_cvtepi32_pd(i)));
    }
    const __m256i s0 = _mm256_set1_epi32((int)g->s[0]), s1 = _mm256_set1_epi32((int)g->s[1]);
    const __m256i node = _mm256_add_epi32(
        _mm256_mullo_epi32(_mm256_add_epi32(_mm256_mullo_epi32(c[2], s1), c[1]), s0), c[0]);
    _mm256_storeu_si256((__m256i *)(p->node + q), node);
}

/* f -= A g0 + B w0 with A = a WYZ, B = b GYZ + c WGZ (sim3_step.c p2g_at) */
static inline void force8(double *f, const stencil8 *s, double a, double b, double c)
{
    const __m512d A = _mm512_mul_pd(_mm512_set1_pd(a), s->WYZ);
    const __m512d B = _mm512_add_pd(_mm512_mul_pd(_mm512_set1_pd(b), s->GYZ),
                                    _mm512_mul_pd(_mm512_set1_pd(c), s->WGZ));
    const __m512d t = _mm512_add_pd(_mm512_mul_pd(A, s->G0), _mm512_mul_pd(B, s->W0));
    store8(f, s->o, _mm512_sub_pd(load8(f, s->o), t));
}

static inline void add8(double *f, const stencil8 *s, __m512d N, double a)
{
    store8(f, s->o, _mm512_add_pd(load8(f, s->o), _mm512_mul_pd(N, _mm512_set1_pd(a))));
}

/* Steps 1-2 (sim3_step.c p2g_at) at particle q, placed, with its mass m,
 * momenta mv[3] and V sigma (Voigt) vs[6] made */
static inline void p2g1(const lm3_particles *p, const lm3_grid *g, size_t q, double m,
                        const double mv[3], const double vs[6])
{
    const double d[3] = {p->d[0][q], p->d[1][q], p->d[2][q]};
    stencil8 s;
    stencil_of(g, p->node[q], d, &s);
    const __m512d N = _mm512_mul_pd(s.W0, s.WYZ);
    add8(g->m, &s, N, m);
    add8(g->p[0], &s, N, mv[0]);
    add8(g->p[1], &s, N, mv[1]);
    add8(g->p[2], &s, N, mv[2]);
    force8(g->f[0], &s, vs[0], vs[5], vs[4]);
    force8(g->f[1], &s, vs[5], vs[1], vs[3]);
    force8(g->f[2], &s, vs[4], vs[3], vs[2]);
}

void lm3_p2g2_avx512(lm3_sim *sim, const lm3_grid *g, size_t q0, size_t q1)
{
    lm3_particles *p = &sim->p;
    size_t q = q0;
    /* step 0 and each particle's m v and V sigma (V = m / rho, the same
     * products as p2g_at's) eight particles at a time, then each one's
     * sums in order */
    for (; q + 8 <= q1; q += 8) {
        place8(sim, q);
        double b[10][8] __attribute__((aligned(64)));
        const __m512d m = _mm512_loadu_pd(p->m + q);
        const __m512d V = _mm512_div_pd(m, _mm512_loadu_pd(p->rho + q));
        _mm512_store_pd(b[0], m);
        for (int e = 0; e < 3; e++)
            _mm512_store_pd(b[1 + e], _mm512_mul_pd(m, _mm512_loadu_pd(p->v[e] + q)));
        for (int e = 0; e < 6; e++)
            _mm512_store_pd(b[4 + e], _mm512_mul_pd(V, _mm512_loadu_pd(p->s[e] + q)));
        for (int l = 0; l < 8; l++) {
            const double mv[3] = {b[1][l], b[2][l], b[3][l]};
            const double vs[6] = {b[4][l], b[5][l], b[6][l], b[7][l], b[8][l], b[9][l]};
            p2g1(p, g, q + (size_t)l, b[0][l], mv, vs);
        }
    }
    for (; q < q1; q++) {
        /* step 0: the place at x^k (sim3_step.c place_at) */
        const double x[3] = {p->x[0][q], p->x[1][q], p->x[2][q]};
        double d[3];
        lm3_place_w(&sim->grid, x, &p->node[q], d, 2);
        p->d[0][q] = d[0];
        p->d[1][q] = d[1];
        p->d[2][q] = d[2];
        const double m = p->m[q], V = m / p->rho[q];
        const double mv[3] = {m * p->v[0][q], m * p->v[1][q], m * p->v[2][q]};
        const double vs[6] = {V * p->s[0][q], V * p->s[1][q], V * p->s[2][q],
                              V * p->s[3][q], V * p->s[4][q], V * p->s[5][q]};
        p2g1(p, g, q, m, mv, vs);
    }
}

void lm3_remap2_avx512(lm3_sim *sim, const lm3_grid *g, size_t q0, size_t q1)
{
    const lm3_particles *p = &sim->p;
    for (size_t q = q0; q < q1; q++) {
        const double d[3] = {p->d[0][q], p->d[1][q], p->d[2][q]};
        stencil8 s;
        stencil_of(g, p->node[q], d, &s);
        const double m = p->m[q];
        const __m512d N = _mm512_mul_pd(s.W0, s.WYZ);
        add8(g->v[0], &s, N, m * p->v[0][q]);
        add8(g->v[1], &s, N, m * p->v[1][q]);
        add8(g->v[2], &s, N, m * p->v[2][q]);
    }
}

/* The eight lanes' trilinear weights (lm_linear_1d) per axis: w[a] = (1 -
 * d, d), d the particles' offsets in their cells. */
static inline void linear_weights(const lm3_particles *p, size_t q, __m512d w[3][2])
{
    const __m512d one = _mm512_set1_pd(1);
    for (int a = 0; a < 3; a++) {
        const __m512d d = _mm512_loadu_pd(p->d[a] + q);
        w[a][0] = _mm512_sub_pd(one, d);
        w[a][1] = d;
    }
}

/* The lanes' node pair (i0, i0 + 1) of stencil row (b, c): the cell's
 * first node `node` moved b rows in y and c layers in z. */
static inline void row_nodes(const lm3_grid *g, __m256i node, int b, int c, __m256i *i0,
                             __m256i *i1)
{
    *i0 = _mm256_add_epi32(node, _mm256_set1_epi32((int)((c * g->s[1] + b) * g->s[0])));
    *i1 = _mm256_add_epi32(*i0, _mm256_set1_epi32(1));
}

/* Step 4 (sim3_step.c g2p_at with W = 2) at the eight particles q .. q + 7,
 * one a lane (perf34): each lane takes its particle's sums of N f and
 * N v^L in g2p_at's order (rows c outer, b inner, node 0 then node 1,
 * from 0), then v += dt a, x += dt u, so every lane's result is the
 * scalar one's bits; the 48 nodal values a particle reads are gathered
 * across the lanes. 1 when every new position is on the grid and every
 * new velocity finite, else 0 (g2p_at's answer). */
int lm3_g2p2_avx512(lm3_sim *sim, size_t q)
{
    lm3_particles *p = &sim->p;
    const lm3_grid *g = &sim->grid;
    const __m512d vdt = _mm512_set1_pd(sim->def.dt);
    __m512d w[3][2];
    linear_weights(p, q, w);
    const __m256i node = _mm256_loadu_si256((const __m256i *)(p->node + q));
    __m512d acc[6];
    for (int e = 0; e < 6; e++) acc[e] = _mm512_setzero_pd();
    for (int c = 0; c < 2; c++)
        for (int b = 0; b < 2; b++) {
            const __m512d wyz = _mm512_mul_pd(w[1][b], w[2][c]);
            const __m512d N0 = _mm512_mul_pd(w[0][0], wyz), N1 = _mm512_mul_pd(w[0][1], wyz);
            __m256i i0, i1;
            row_nodes(g, node, b, c, &i0, &i1);
            for (int e = 0; e < 3; e++) {
                const __m512d f0 = _mm512_i32gather_pd(i0, g->f[e], 8);
                const __m512d f1 = _mm512_i32gather_pd(i1, g->f[e], 8);
                const __m512d u0 = _mm512_i32gather_pd(i0, g->p[e], 8);
                const __m512d u1 = _mm512_i32gather_pd(i1, g->p[e], 8);
                acc[e] = _mm512_add_pd(acc[e], _mm512_mul_pd(N0, f0));
                acc[e] = _mm512_add_pd(acc[e], _mm512_mul_pd(N1, f1));
                acc[3 + e] = _mm512_add_pd(acc[3 + e], _mm512_mul_pd(N0, u0));
                acc[3 + e] = _mm512_add_pd(acc[3 + e], _mm512_mul_pd(N1, u1));
            }
        }
    __mmask8 ok = 0xff;
    const __m512d inf = _mm512_set1_pd(HUGE_VAL);
    for (int k = 0; k < 3; k++) {
        const __m512d v = _mm512_add_pd(_mm512_loadu_pd(p->v[k] + q), _mm512_mul_pd(vdt, acc[k]));
        const __m512d x =
            _mm512_add_pd(_mm512_loadu_pd(p->x[k] + q), _mm512_mul_pd(vdt, acc[3 + k]));
        _mm512_storeu_pd(p->v[k] + q, v);
        _mm512_storeu_pd(p->x[k] + q, x);
        const double lo = g->lo[k], hi = lo + g->n[k] * g->h;
        ok &= _mm512_cmp_pd_mask(x, _mm512_set1_pd(lo), _CMP_GE_OQ);
        ok &= _mm512_cmp_pd_mask(x, _mm512_set1_pd(hi), _CMP_LE_OQ);
        ok &= _mm512_cmp_pd_mask(_mm512_abs_pd(v), inf, _CMP_LT_OQ);
    }
    return ok == 0xff;
}

/* The trilinear stress pass (sim3_step.c stress_at with W = 2, an
 * elastic material) at the eight particles q .. q + 7, one a lane
 * (perf34; docs/3d.md "Speed"): each lane makes its particle's velocity
 * gradient, strain increment, spin and Jaumann update with the scalar
 * pass's operations in the scalar pass's order (gradient_at's rows c
 * outer, b inner, each row's S = v0 g0[0] + v1 g0[1] and T likewise with
 * w0, L += S wyz, T gyz, T wgz from 0; sim3_elastic.h's expressions), so
 * every lane's result is the scalar one's bits. The 24 nodal values a
 * particle reads (3 fields, 4 rows, 2 nodes) are gathered across the
 * lanes. A lane whose 1 + tr de is not positive is left as the scalar
 * pass leaves it (nothing written) and the answer is 0. -1 when the eight
 * are not all of one elastic material: nothing done, the caller takes
 * them one by one. G, lam: each material's moduli (sim3_elastic.h). */
int lm3_stress2_avx512(lm3_sim *sim, const double *G, const double *lam, size_t q)
{
    lm3_particles *p = &sim->p;
    const lm3_grid *g = &sim->grid;
    const uint8_t k = p->mat[q];
    if (sim->mats[k].kind == LM3_GAS) return -1;
    for (int l = 1; l < 8; l++)
        if (p->mat[q + l] != k) return -1;
    const double dt = sim->def.dt, r = 1.0 / g->h;
    const __m512d one = _mm512_set1_pd(1), zero = _mm512_setzero_pd(), vdt = _mm512_set1_pd(dt);
    /* lm_linear_1d: w = (1 - d, d), g = (-r, r) */
    __m512d w[3][2], gr[3][2];
    linear_weights(p, q, w);
    for (int a = 0; a < 3; a++) {
        gr[a][0] = _mm512_set1_pd(-r);
        gr[a][1] = _mm512_set1_pd(r);
    }
    const __m256i node = _mm256_loadu_si256((const __m256i *)(p->node + q));
    __m512d L[9];
    for (int e = 0; e < 9; e++) L[e] = zero;
    for (int c = 0; c < 2; c++)
        for (int b = 0; b < 2; b++) {
            const __m512d wyz = _mm512_mul_pd(w[1][b], w[2][c]);
            const __m512d gyz = _mm512_mul_pd(gr[1][b], w[2][c]);
            const __m512d wgz = _mm512_mul_pd(w[1][b], gr[2][c]);
            __m256i i0, i1;
            row_nodes(g, node, b, c, &i0, &i1);
            for (int e = 0; e < 3; e++) {
                const __m512d v0 = _mm512_i32gather_pd(i0, g->v[e], 8);
                const __m512d v1 = _mm512_i32gather_pd(i1, g->v[e], 8);
                const __m512d S = _mm512_add_pd(_mm512_mul_pd(v0, gr[0][0]),
                                                _mm512_mul_pd(v1, gr[0][1]));
                const __m512d T = _mm512_add_pd(_mm512_mul_pd(v0, w[0][0]),
                                                _mm512_mul_pd(v1, w[0][1]));
                L[3 * e] = _mm512_add_pd(L[3 * e], _mm512_mul_pd(S, wyz));
                L[3 * e + 1] = _mm512_add_pd(L[3 * e + 1], _mm512_mul_pd(T, gyz));
                L[3 * e + 2] = _mm512_add_pd(L[3 * e + 2], _mm512_mul_pd(T, wgz));
            }
        }
    /* stress_at: de's diagonal, J ([F] eq 16) */
    __m512d de[6];
    de[0] = _mm512_mul_pd(vdt, L[0]);
    de[1] = _mm512_mul_pd(vdt, L[4]);
    de[2] = _mm512_mul_pd(vdt, L[8]);
    const __m512d J = _mm512_add_pd(_mm512_add_pd(_mm512_add_pd(one, de[0]), de[1]), de[2]);
    const __mmask8 ok = _mm512_cmp_pd_mask(J, zero, _CMP_GT_OQ);
    __m512d rho = _mm512_loadu_pd(p->rho + q);
    rho = _mm512_div_pd(rho, J);
    _mm512_mask_storeu_pd(p->rho + q, ok, rho);
    /* shear_and_spin: de[3..5], W_xy, W_xz, W_yz */
    const __m512d hdt = _mm512_set1_pd(0.5 * dt), half = _mm512_set1_pd(0.5);
    de[3] = _mm512_mul_pd(hdt, _mm512_add_pd(L[5], L[7]));
    de[4] = _mm512_mul_pd(hdt, _mm512_add_pd(L[2], L[6]));
    de[5] = _mm512_mul_pd(hdt, _mm512_add_pd(L[1], L[3]));
    const __m512d a = _mm512_mul_pd(half, _mm512_sub_pd(L[1], L[3]));
    const __m512d bb = _mm512_mul_pd(half, _mm512_sub_pd(L[2], L[6]));
    const __m512d cc = _mm512_mul_pd(half, _mm512_sub_pd(L[5], L[7]));
    /* lm3_elastic_update_gl */
    __m512d s[6];
    for (int e = 0; e < 6; e++) s[e] = _mm512_loadu_pd(p->s[e] + q);
    const __m512d xx = s[0], yy = s[1], zz = s[2], yz = s[3], xz = s[4], xy = s[5];
    /* -a and -b as C's unary minus makes them (a zero's sign turned too) */
    const __m512d m1 = _mm512_set1_pd(-1);
    const __m512d na = _mm512_mul_pd(a, m1), nb = _mm512_mul_pd(bb, m1);
#define MUL _mm512_mul_pd
#define ADD _mm512_add_pd
#define SUB _mm512_sub_pd
    const __m512d M00 = ADD(MUL(a, xy), MUL(bb, xz)), M01 = ADD(MUL(a, yy), MUL(bb, yz));
    const __m512d M02 = ADD(MUL(a, yz), MUL(bb, zz));
    const __m512d M10 = ADD(MUL(na, xx), MUL(cc, xz)), M11 = ADD(MUL(na, xy), MUL(cc, yz));
    const __m512d M12 = ADD(MUL(na, xz), MUL(cc, zz));
    const __m512d M20 = SUB(MUL(nb, xx), MUL(cc, xy)), M21 = SUB(MUL(nb, xy), MUL(cc, yy));
    const __m512d M22 = SUB(MUL(nb, xz), MUL(cc, yz));
    const __m512d two = _mm512_set1_pd(2);
    const __m512d R[6] = {MUL(MUL(two, M00), vdt), MUL(MUL(two, M11), vdt),
                          MUL(MUL(two, M22), vdt), MUL(ADD(M12, M21), vdt),
                          MUL(ADD(M02, M20), vdt), MUL(ADD(M01, M10), vdt)};
    const __m512d tr = ADD(ADD(de[0], de[1]), de[2]);
    const __m512d ltr = MUL(_mm512_set1_pd(lam[k]), tr), G2 = _mm512_set1_pd(2 * G[k]);
    for (int e = 0; e < 3; e++)
        _mm512_mask_storeu_pd(p->s[e] + q, ok, ADD(s[e], ADD(ADD(R[e], ltr), MUL(G2, de[e]))));
    for (int e = 3; e < 6; e++)
        _mm512_mask_storeu_pd(p->s[e] + q, ok, ADD(s[e], ADD(R[e], MUL(G2, de[e]))));
#undef MUL
#undef ADD
#undef SUB
    return ok == 0xff;
}

int lm3_avx512_built(void)
{
    return 1;
}

#else

/* Built without -mavx512f (another processor, or a compiler without the
 * flag): never chosen (lm3_avx512_built is 0). */
void lm3_p2g2_avx512(lm3_sim *sim, const lm3_grid *g, size_t q0, size_t q1)
{
    (void)sim, (void)g, (void)q0, (void)q1;
}

void lm3_remap2_avx512(lm3_sim *sim, const lm3_grid *g, size_t q0, size_t q1)
{
    (void)sim, (void)g, (void)q0, (void)q1;
}

int lm3_stress2_avx512(lm3_sim *sim, const double *G, const double *lam, size_t q)
{
    (void)sim, (void)G, (void)lam, (void)q;
    return -1;
}

int lm3_g2p2_avx512(lm3_sim *sim, size_t q)
{
    (void)sim, (void)q;
    return 0;
}

int lm3_avx512_built(void)
{
    return 0;
}

#endif
