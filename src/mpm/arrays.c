/* arrays.c - staggered arrays (arrays.h): each a malloc'd block with room
 * for a page's worth of offset, the block's own address and size kept just
 * before the array so that lm_arr_free finds it and gives its bytes back
 * to the process's memory budget (src/util/lu_budget.c, issue 31 item 5:
 * the engine's arrays count against the one cap with the Lua heap). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "arrays.h"
#include "util.h"

#define PAGE 4096u

/* The block's header, just before the array. */
typedef struct head {
    size_t bytes;          /* the block's size, charged to the budget */
    unsigned char *raw;    /* the block */
} head;

/* Where array k goes in a block at raw: the first page start past room
 * for the header, then the array's offset in the page. */
static unsigned char *place(unsigned char *raw, int k)
{
    uintptr_t at = ((uintptr_t)raw + sizeof(head) + PAGE - 1) & ~(uintptr_t)(PAGE - 1);
    at += ((size_t)k * LM_ARR_STAGGER) % PAGE;
    return raw + (at - (uintptr_t)raw);
}

static head head_of(void *a)
{
    head h;
    memcpy(&h, (unsigned char *)a - sizeof h, sizeof h);
    return h;
}

static void set_head(unsigned char *a, unsigned char *raw, size_t bytes)
{
    head h = {bytes, raw};
    memcpy(a - sizeof h, &h, sizeof h);
}

static int too_big(size_t n, size_t size)
{
    return size && n > (SIZE_MAX - 2 * PAGE) / size;
}

void *lm_arr_alloc(size_t n, size_t size, int k, int zero)
{
    if (too_big(n, size)) return NULL;
    size_t bytes = n * size + 2 * PAGE;
    if (lu_budget_charge(LU_MEM_ENGINE, bytes) != 0) return NULL;
    unsigned char *raw = malloc(bytes);
    if (!raw) {
        lu_budget_release(LU_MEM_ENGINE, bytes);
        return NULL;
    }
    unsigned char *a = place(raw, k);
    set_head(a, raw, bytes);
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
    head h = head_of(a);
    size_t off = (size_t)((unsigned char *)a - h.raw), bytes = n * size + 2 * PAGE;
    if (bytes > h.bytes && lu_budget_charge(LU_MEM_ENGINE, bytes - h.bytes) != 0) return NULL;
    unsigned char *nr = realloc(h.raw, bytes);
    if (!nr) {
        if (bytes > h.bytes) lu_budget_release(LU_MEM_ENGINE, bytes - h.bytes);
        return NULL;
    }
    if (bytes < h.bytes) lu_budget_release(LU_MEM_ENGINE, h.bytes - bytes);
    unsigned char *b = place(nr, k);
    if (b != nr + off) memmove(b, nr + off, (old_n < n ? old_n : n) * size);
    set_head(b, nr, bytes);
    return b;
}

void lm_arr_free(void *a)
{
    if (!a) return;
    head h = head_of(a);
    free(h.raw);
    lu_budget_release(LU_MEM_ENGINE, h.bytes);
}
