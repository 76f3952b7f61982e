/* sim3_simd.c - which of the 3D step's kernels the processor runs
 * (sim3_simd.h). */
#include "sim3_simd.h"

static int limit = LM3_SIMD_AVX512;

/* what the processor has, asked once (the answer never changes; two
 * threads asking at once write the same value) */
static int have(void)
{
    static int cached = -1;
    if (cached < 0) {
        int h = LM3_SIMD_SSE2;
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
        /* the processor first: no function of sim3_simd512.c runs
         * where it lacks AVX-512F */
        if (__builtin_cpu_supports("avx512f") && lm3_avx512_built()) h = LM3_SIMD_AVX512;
#endif
        cached = h;
    }
    return cached;
}

int lm3_simd_level(void)
{
    int h = have();
    return h < limit ? h : limit;
}

void lm3_simd_limit(int level)
{
    limit = level;
}
