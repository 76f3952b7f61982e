/* particles.c - structure-of-arrays particle storage. */
#include <stdlib.h>
#include <string.h>

#include "arrays.h"
#include "mpm.h"
#include "particles.h"

/* Every array, with its element size: its place in the list is its
 * offset in the page (arrays.h). The stencil's weights and gradients (N,
 * Gx, Gy) hold ns per particle and exist for uGIMP only (lm_sim_new
 * sets ns and keep_weights from the basis before the first particle). */
typedef struct field {
    void **a;
    size_t size;
} field;

/* 25 arrays of doubles, 4 of ints, 3 of stencils: 32, a page's offsets */
enum { FIELDS_MAX = 32 };

static int fields(lm_particles *p, field f[FIELDS_MAX])
{
    size_t d = sizeof(double), ns = p->keep_weights ? (size_t)p->ns : 0;
    void **dbl[] = {(void **)&p->x, (void **)&p->y, (void **)&p->vx,
                    (void **)&p->vy, (void **)&p->m, (void **)&p->rho,
                    (void **)&p->sxx, (void **)&p->syy, (void **)&p->sxy,
                    (void **)&p->szz, (void **)&p->et, (void **)&p->ds,
                    (void **)&p->tx, (void **)&p->ty, (void **)&p->e,
                    (void **)&p->q, (void **)&p->ev, (void **)&p->L0,
                    (void **)&p->fpx, (void **)&p->fpy, (void **)&p->lx,
                    (void **)&p->ly, (void **)&p->r0, (void **)&p->xi,
                    (void **)&p->eta};
    int n = 0;
    for (size_t k = 0; k < sizeof dbl / sizeof dbl[0]; k++) f[n++] = (field){dbl[k], d};
    f[n++] = (field){(void **)&p->body, sizeof(int)};
    f[n++] = (field){(void **)&p->mat, sizeof(int)};
    f[n++] = (field){(void **)&p->node, sizeof(int)};
    f[n++] = (field){(void **)&p->pin, sizeof(int)};
    if (ns) {
        f[n++] = (field){(void **)&p->N, ns * d};
        f[n++] = (field){(void **)&p->Gx, ns * d};
        f[n++] = (field){(void **)&p->Gy, ns * d};
    }
    return n;
}

/* Grows every array together; on failure nothing is lost (the arrays
 * already grown keep the old contents in the larger block) and the
 * capacity is unchanged. */
int lm_particles_reserve(lm_particles *p, size_t cap)
{
    if (cap <= p->cap) return 0;
    field f[FIELDS_MAX];
    int n = fields(p, f);
    for (int k = 0; k < n; k++) {
        void *b = lm_arr_grow(*f[k].a, p->cap, cap, f[k].size, k);
        if (!b) return -1;
        *f[k].a = b;
    }
    p->cap = cap;
    return 0;
}

void lm_particles_free(lm_particles *p)
{
    field f[FIELDS_MAX];
    int n = fields(p, f);
    for (int k = 0; k < n; k++) lm_arr_free(*f[k].a);
    memset(p, 0, sizeof *p);
}
