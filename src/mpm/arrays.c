/* arrays.c - staggered arrays (arrays.h): each a malloc'd block with room
 * for a page's worth of offset, the block's own address kept just before
 * the array so that lm_arr_free finds it. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "arrays.h"

#define PAGE 4096u

void *lm_arr_alloc(size_t n, size_t size, int k, int zero)
{
    if (size && n > (SIZE_MAX - 2 * PAGE) / size) return NULL;
    size_t bytes = n * size;
    unsigned char *raw = malloc(bytes + 2 * PAGE);
    if (!raw) return NULL;
    /* the first page start past room for the block's address, then the
     * array's offset in it */
    uintptr_t at = ((uintptr_t)raw + sizeof(void *) + PAGE - 1) & ~(uintptr_t)(PAGE - 1);
    at += ((size_t)k * LM_ARR_STAGGER) % PAGE;
    unsigned char *a = raw + (at - (uintptr_t)raw);
    memcpy(a - sizeof(void *), &raw, sizeof raw);
    if (zero) memset(a, 0, bytes);
    return a;
}

void *lm_arr_grow(void *a, size_t old_n, size_t n, size_t size, int k)
{
    void *b = lm_arr_alloc(n, size, k, 0);
    if (!b) return NULL;
    if (a) memcpy(b, a, (old_n < n ? old_n : n) * size);
    lm_arr_free(a);
    return b;
}

void lm_arr_free(void *a)
{
    if (!a) return;
    void *raw;
    memcpy(&raw, (unsigned char *)a - sizeof(void *), sizeof raw);
    free(raw);
}
