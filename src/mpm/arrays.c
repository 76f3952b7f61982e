/* arrays.c - staggered arrays (arrays.h): each a malloc'd block with room
 * for a page's worth of offset, the block's own address kept just before
 * the array so that lm_arr_free finds it. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "arrays.h"

#define PAGE 4096u

/* Where array k goes in a block at raw: the first page start past room
 * for the block's address, then the array's offset in the page. */
static unsigned char *place(unsigned char *raw, int k)
{
    uintptr_t at = ((uintptr_t)raw + sizeof(void *) + PAGE - 1) & ~(uintptr_t)(PAGE - 1);
    at += ((size_t)k * LM_ARR_STAGGER) % PAGE;
    return raw + (at - (uintptr_t)raw);
}

static unsigned char *raw_of(void *a)
{
    unsigned char *raw;
    memcpy(&raw, (unsigned char *)a - sizeof(void *), sizeof raw);
    return raw;
}

static int too_big(size_t n, size_t size)
{
    return size && n > (SIZE_MAX - 2 * PAGE) / size;
}

void *lm_arr_alloc(size_t n, size_t size, int k, int zero)
{
    if (too_big(n, size)) return NULL;
    unsigned char *raw = malloc(n * size + 2 * PAGE);
    if (!raw) return NULL;
    unsigned char *a = place(raw, k);
    memcpy(a - sizeof(void *), &raw, sizeof raw);
    if (zero) memset(a, 0, n * size);
    return a;
}

/* By realloc, so that a large block grows in place (mremap: no copy and
 * no second block at once - a 10^7-particle run's peak memory); the
 * contents move only if the block's new address puts the array's page
 * offset elsewhere. */
void *lm_arr_grow(void *a, size_t old_n, size_t n, size_t size, int k)
{
    if (!a) return lm_arr_alloc(n, size, k, 0);
    if (too_big(n, size)) return NULL;
    unsigned char *raw = raw_of(a);
    size_t off = (size_t)((unsigned char *)a - raw);
    unsigned char *nr = realloc(raw, n * size + 2 * PAGE);
    if (!nr) return NULL;
    unsigned char *b = place(nr, k);
    if (b != nr + off) memmove(b, nr + off, (old_n < n ? old_n : n) * size);
    memcpy(b - sizeof(void *), &nr, sizeof nr);
    return b;
}

void lm_arr_free(void *a)
{
    if (a) free(raw_of(a));
}
