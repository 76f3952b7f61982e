/* lu_grow.c - growing arrays, and freeing many at once (util.h). */
#include "util.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int lu_reserve(void *array, size_t *cap, size_t need, size_t elem, size_t first)
{
    if (need <= *cap)
        return 0;
    size_t c = *cap ? *cap : first;
    while (c < need) {
        if (c > SIZE_MAX / 2 / elem)
            return -1;
        c *= 2;
    }
    void *p;
    memcpy(&p, array, sizeof p);    /* the caller's T *, whatever T */
    p = realloc(p, c * elem);
    if (!p)
        return -1;
    memcpy(array, &p, sizeof p);
    *cap = c;
    return 0;
}

void *lu_push(void *array, size_t n, size_t elem)
{
    if (n >= SIZE_MAX / elem - 1)
        return NULL;
    void *p;
    memcpy(&p, array, sizeof p);    /* the caller's T *, whatever T */
    p = realloc(p, (n + 1) * elem);
    if (!p)
        return NULL;
    memcpy(array, &p, sizeof p);
    unsigned char *at = (unsigned char *)p + n * elem;
    memset(at, 0, elem);
    return at;
}

void lu_free_each(void *const *p, size_t n)
{
    for (size_t i = 0; i < n; i++)
        free(p[i]);
}
