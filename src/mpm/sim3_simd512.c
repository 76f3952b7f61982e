/* sim3_simd512.c - the trilinear step's scatters with a particle's whole
 * 2 x 2 x 2 stencil in one AVX-512 vector (issue 34 item 6; docs/3d.md
 * "Speed"), chosen at run time (sim3_simd.h): the build stays portable
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

static inline void stencil_of(const lm3_grid *g, int32_t node, const double d[3], stencil8 *s)
{
    lm3_weights w;
    lm3_weights_w(g, node, d, &w, 2);
    const long n0 = w.node, s0 = g->s[0], s01 = g->s[0] * g->s[1];
    s->o[0] = n0;
    s->o[1] = n0 + s0;
    s->o[2] = n0 + s01;
    s->o[3] = n0 + s01 + s0;
    /* lanes 0..7: (a, b, c) = (0,0,0) (1,0,0) (0,1,0) (1,1,0) (0,0,1) ... */
    const __m512d W1 = _mm512_setr_pd(w.w[1][0], w.w[1][0], w.w[1][1], w.w[1][1], w.w[1][0],
                                      w.w[1][0], w.w[1][1], w.w[1][1]);
    const __m512d G1 = _mm512_setr_pd(w.g[1][0], w.g[1][0], w.g[1][1], w.g[1][1], w.g[1][0],
                                      w.g[1][0], w.g[1][1], w.g[1][1]);
    const __m512d W2 = _mm512_setr_pd(w.w[2][0], w.w[2][0], w.w[2][0], w.w[2][0], w.w[2][1],
                                      w.w[2][1], w.w[2][1], w.w[2][1]);
    const __m512d G2 = _mm512_setr_pd(w.g[2][0], w.g[2][0], w.g[2][0], w.g[2][0], w.g[2][1],
                                      w.g[2][1], w.g[2][1], w.g[2][1]);
    s->W0 = _mm512_setr_pd(w.w[0][0], w.w[0][1], w.w[0][0], w.w[0][1], w.w[0][0], w.w[0][1],
                           w.w[0][0], w.w[0][1]);
    s->G0 = _mm512_setr_pd(w.g[0][0], w.g[0][1], w.g[0][0], w.g[0][1], w.g[0][0], w.g[0][1],
                           w.g[0][0], w.g[0][1]);
    s->WYZ = _mm512_mul_pd(W1, W2);
    s->GYZ = _mm512_mul_pd(G1, W2);
    s->WGZ = _mm512_mul_pd(W1, G2);
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

void lm3_p2g2_avx512(lm3_sim *sim, const lm3_grid *g, size_t q0, size_t q1)
{
    lm3_particles *p = &sim->p;
    for (size_t q = q0; q < q1; q++) {
        /* step 0: the place at x^k (sim3_step.c place_at) */
        const double x[3] = {p->x[0][q], p->x[1][q], p->x[2][q]};
        double d[3];
        lm3_place_w(&sim->grid, x, &p->node[q], d, 2);
        p->d[0][q] = d[0];
        p->d[1][q] = d[1];
        p->d[2][q] = d[2];
        stencil8 s;
        stencil_of(g, p->node[q], d, &s);
        /* steps 1-2 (sim3_step.c p2g_at) */
        const double m = p->m[q], V = m / p->rho[q];
        const double sxx = V * p->s[0][q], syy = V * p->s[1][q], szz = V * p->s[2][q];
        const double syz = V * p->s[3][q], sxz = V * p->s[4][q], sxy = V * p->s[5][q];
        const __m512d N = _mm512_mul_pd(s.W0, s.WYZ);
        add8(g->m, &s, N, m);
        add8(g->p[0], &s, N, m * p->v[0][q]);
        add8(g->p[1], &s, N, m * p->v[1][q]);
        add8(g->p[2], &s, N, m * p->v[2][q]);
        force8(g->f[0], &s, sxx, sxy, sxz);
        force8(g->f[1], &s, sxy, syy, syz);
        force8(g->f[2], &s, sxz, syz, szz);
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

int lm3_avx512_built(void)
{
    return 0;
}

#endif
