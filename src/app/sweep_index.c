/* sweep_index.c - names to positions, in constant time (sweep.h).
 *
 * A report may hold hundreds of thousands of values; finding each column
 * in each row by a linear search made `lamina sweep --collect` quadratic
 * (200 000 values took more than a minute, issue 18). Open addressing,
 * FNV-1a, the table at most half full. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sweep.h"
#include "util.h"

static size_t slot_of(const sw_index *ix, const char *key)
{
    size_t mask = ix->cap - 1, i = (size_t)lu_fnv1a_str(key) & mask;
    while (ix->key[i] && strcmp(ix->key[i], key) != 0) i = (i + 1) & mask;
    return i;
}

int sw_index_get(const sw_index *ix, const char *key)
{
    if (!ix->cap) return -1;
    size_t i = slot_of(ix, key);
    return ix->key[i] ? ix->val[i] : -1;
}

static int grow(sw_index *ix)
{
    size_t cap = ix->cap ? 2 * ix->cap : 64;
    sw_index big = {calloc(cap, sizeof *big.key), calloc(cap, sizeof *big.val), cap, 0};
    if (!big.key || !big.val) {
        free(big.key);
        free(big.val);
        return -1;
    }
    for (size_t i = 0; i < ix->cap; i++)
        if (ix->key[i]) {
            size_t j = slot_of(&big, ix->key[i]);
            big.key[j] = ix->key[i];
            big.val[j] = ix->val[i];
            big.n++;
        }
    free(ix->key);
    free(ix->val);
    *ix = big;
    return 0;
}

int sw_index_put(sw_index *ix, const char *key, int val)
{
    if (2 * (ix->n + 1) > ix->cap && grow(ix) != 0) return -1;
    size_t i = slot_of(ix, key);
    if (ix->key[i]) return 0;   /* the first position stays */
    ix->key[i] = key;
    ix->val[i] = val;
    ix->n++;
    return 0;
}

void sw_index_free(sw_index *ix)
{
    free(ix->key);
    free(ix->val);
    memset(ix, 0, sizeof *ix);
}
