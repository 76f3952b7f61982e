/* particles.c - structure-of-arrays particle storage. */
#include <stdlib.h>
#include <string.h>

#include "mpm.h"
#include "particles.h"

/* Grows every array together; on failure nothing is lost (realloc keeps the
 * old block) and the capacity is unchanged. */
static int grow(void **a, size_t size, size_t cap)
{
    void *q = realloc(*a, size * cap);
    if (!q) return -1;
    *a = q;
    return 0;
}

int lm_particles_reserve(lm_particles *p, size_t cap)
{
    if (cap <= p->cap) return 0;
    size_t d = sizeof(double);
    void **dbl[] = {(void **)&p->x, (void **)&p->y, (void **)&p->vx,
                    (void **)&p->vy, (void **)&p->m, (void **)&p->rho,
                    (void **)&p->sxx, (void **)&p->syy, (void **)&p->sxy,
                    (void **)&p->szz, (void **)&p->et, (void **)&p->ds,
                    (void **)&p->tx, (void **)&p->ty, (void **)&p->e,
                    (void **)&p->q, (void **)&p->ev, (void **)&p->L0,
                    (void **)&p->fpx, (void **)&p->fpy, (void **)&p->lx,
                    (void **)&p->ly, (void **)&p->r0};
    for (size_t k = 0; k < sizeof dbl / sizeof dbl[0]; k++)
        if (grow(dbl[k], d, cap)) return -1;
    /* the stencil's weights and gradients: ns per particle (lm_sim_new
     * sets it from the basis before the first particle) */
    size_t ns = p->ns > 0 ? (size_t)p->ns : 4;
    if (ns > 4 && (grow((void **)&p->N, ns * d, cap) || grow((void **)&p->Gx, ns * d, cap) ||
                   grow((void **)&p->Gy, ns * d, cap)))
        return -1;
    if (grow((void **)&p->xi, d, cap) || grow((void **)&p->eta, d, cap) ||
        grow((void **)&p->body, sizeof(int), cap) ||
        grow((void **)&p->mat, sizeof(int), cap) ||
        grow((void **)&p->node, sizeof(int), cap) ||
        grow((void **)&p->pin, sizeof(int), cap))
        return -1;
    p->cap = cap;
    return 0;
}

void lm_particles_free(lm_particles *p)
{
    free(p->x); free(p->y); free(p->vx); free(p->vy); free(p->m);
    free(p->rho); free(p->sxx); free(p->syy); free(p->sxy); free(p->szz);
    free(p->et); free(p->ds); free(p->tx); free(p->ty);
    free(p->e); free(p->q); free(p->ev); free(p->lx); free(p->ly);
    free(p->L0); free(p->fpx); free(p->fpy); free(p->pin); free(p->r0);
    free(p->N); free(p->Gx); free(p->Gy); free(p->xi); free(p->eta);
    free(p->body); free(p->mat); free(p->node);
    memset(p, 0, sizeof *p);
}
