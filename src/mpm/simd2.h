/* simd2.h - two doubles side by side, for the isosurface normals' hot
 * loops (normals_fit.c, normals_fit_ne.c; issue 17 item 3).
 *
 * Each lane does exactly the scalar operation (+ - * / and the square
 * root are correctly rounded, lane by lane), so code written with these
 * gives the bits of the scalar code it replaces; only the number of
 * instructions changes. GCC's and clang's vector extension; SSE2, which
 * every x86-64 has, for the square root and the lane shuffles, with plain
 * C where there is no SSE2. */
#ifndef LAMINA_SIMD2_H
#define LAMINA_SIMD2_H

#include <math.h>
#include <string.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

typedef double lm_v2d __attribute__((vector_size(16)));

/* {p[0], p[1]} from memory of any alignment. */
static inline lm_v2d lm_v2d_load(const double *p)
{
    lm_v2d v;
    memcpy(&v, p, sizeof v);
    return v;
}

/* p[0..1] = v, to memory of any alignment. */
static inline void lm_v2d_store(double *p, lm_v2d v)
{
    memcpy(p, &v, sizeof v);
}

/* {sqrt a[0], sqrt a[1]}, both in one instruction. */
static inline lm_v2d lm_v2d_sqrt(lm_v2d a)
{
#if defined(__SSE2__)
    return (lm_v2d)_mm_sqrt_pd((__m128d)a);
#else
    return (lm_v2d){sqrt(a[0]), sqrt(a[1])};
#endif
}

/* {a[0], b[0]}: the first lanes of two vectors. */
static inline lm_v2d lm_v2d_lo(lm_v2d a, lm_v2d b)
{
#if defined(__SSE2__)
    return (lm_v2d)_mm_unpacklo_pd((__m128d)a, (__m128d)b);
#else
    return (lm_v2d){a[0], b[0]};
#endif
}

/* {a[1], b[1]}: the second lanes of two vectors. */
static inline lm_v2d lm_v2d_hi(lm_v2d a, lm_v2d b)
{
#if defined(__SSE2__)
    return (lm_v2d)_mm_unpackhi_pd((__m128d)a, (__m128d)b);
#else
    return (lm_v2d){a[1], b[1]};
#endif
}

#endif
