/* normals_rng.c - the seeded generator of the random points ([N] §4).
 *
 * SplitMix64 (G. Steele, D. Lea, C. Flood, "Fast splittable pseudorandom
 * number generators", OOPSLA 2014), written from its published recurrence:
 * a Weyl sequence with increment 0x9E3779B97F4A7C15 and a 64-bit finaliser.
 * Small, fast and good enough for placing one or two points per element;
 * nothing else in the normals depends on chance. */
#include "normals.h"

static uint64_t mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

void lm_nrng_seed(lm_nrng *r, uint64_t seed) { r->s = seed; }

uint64_t lm_nrng_next(lm_nrng *r)
{
    r->s += 0x9E3779B97F4A7C15ULL;
    return mix64(r->s);
}

double lm_nrng_uniform(lm_nrng *r)
{
    return (double)(lm_nrng_next(r) >> 11) * (1.0 / 9007199254740992.0);
}

uint64_t lm_nrng_mix(uint64_t seed, uint64_t key)
{
    return mix64(seed ^ mix64(key + 0x632BE59BD9B4E019ULL));
}
