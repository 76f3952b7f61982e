/* lu_hash.c - FNV-1a, 64 bit (Fowler, Noll, Vo): the state hash of the
 * engine, the provenance stamped into PNGs, the sweep's index (util.h). */
#include "util.h"

#include <stdio.h>

#define FNV_PRIME 1099511628211ull

uint64_t lu_fnv1a(uint64_t h, const void *data, size_t n)
{
    const unsigned char *c = data;
    for (size_t k = 0; k < n; k++) {
        h ^= c[k];
        h *= FNV_PRIME;
    }
    return h;
}

uint64_t lu_fnv1a_str(const char *s)
{
    uint64_t h = LU_FNV_SEED;
    for (; *s; s++) {
        h ^= (unsigned char)*s;
        h *= FNV_PRIME;
    }
    return h;
}

void lu_hash_hex(uint64_t h, char out[17])
{
    snprintf(out, 17, "%016llx", (unsigned long long)h);
}
