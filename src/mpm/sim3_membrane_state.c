/* sim3_membrane_state.c - the membranes' part of a 3D run's state
 * (sim3_state.c frames it; checkpoints and `lamina run --restart`, issue
 * 34 item 2). What a step reads of a membrane from the step before: each
 * point's x, v, m, unstrained area A0, frame t1, t2, normal, strain and
 * stress; each membrane's count of undefined construction normals; each
 * pin's reaction of the last step. The stencils (node, d) and the held
 * nodes are rebuilt by the next step's p2g; the definitions (material,
 * pressure, damping, normals, the pins' points) are the script's, which
 * rebuilt them before the state replaces their values.
 *
 * Layout after the particles: per membrane uint64 count and undefined; per
 * pin uint64 count and 3 doubles; then MP_ARRAYS arrays of np doubles.
 * The file is untrusted (docs/security.md "Checkpoints"): the counts must
 * be the script's, every value finite, masses and areas positive and every
 * point inside the grid (a point outside would index past the grid's
 * arrays in p2g), or nothing is replaced. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mpm3.h"
#include "mpm3_membrane.h"

#define MP_ARRAYS 23

size_t lm3_mstate_bytes(uint64_t np, uint32_t nmem, uint32_t npins)
{
    return (size_t)nmem * 16 + (size_t)npins * 32 + (size_t)np * MP_ARRAYS * sizeof(double);
}

void lm3_mstate_counts(const lm3_sim *sim, uint64_t *np, uint32_t *nmem, uint32_t *npins)
{
    const lm3_membranes *ms = sim->mem;
    *np = ms ? ms->p.n : 0;
    *nmem = ms ? (uint32_t)ms->nmem : 0;
    *npins = ms ? (uint32_t)ms->npins : 0;
}

/* the point arrays in their saved order */
static void arrays_of(const lm3_mpoints *p, double *a[MP_ARRAYS])
{
    for (int k = 0; k < 3; k++) {
        a[k] = p->x[k];
        a[3 + k] = p->v[k];
        a[8 + k] = p->t1[k];
        a[11 + k] = p->t2[k];
        a[14 + k] = p->nrm[k];
        a[17 + k] = p->e[k];
        a[20 + k] = p->s[k];
    }
    a[6] = p->m;
    a[7] = p->A0;
}

unsigned char *lm3_mstate_save(const lm3_sim *sim, unsigned char *b)
{
    const lm3_membranes *ms = sim->mem;
    if (!ms) return b;
    for (int k = 0; k < ms->nmem; k++) {
        uint64_t c[2] = {ms->mem[k].count, ms->mem[k].undefined};
        memcpy(b, c, sizeof c);
        b += sizeof c;
    }
    for (int k = 0; k < ms->npins; k++) {
        uint64_t n = ms->pins[k].n;
        memcpy(b, &n, sizeof n);
        memcpy(b + 8, ms->pins[k].reaction, 3 * sizeof(double));
        b += 32;
    }
    double *a[MP_ARRAYS];
    arrays_of(&ms->p, a);
    const size_t np = ms->p.n;
    for (int k = 0; k < MP_ARRAYS; k++) {
        if (np) memcpy(b, a[k], np * sizeof(double));
        b += np * sizeof(double);
    }
    return b;
}

/* the value of array k at point q of the saved part (unaligned: copied) */
static double saved(const unsigned char *arr, uint64_t np, int k, uint64_t q)
{
    double v;
    memcpy(&v, arr + ((size_t)k * np + q) * sizeof(double), sizeof v);
    return v;
}

lm_status lm3_mstate_load(lm3_sim *sim, const unsigned char *b, uint64_t np, uint32_t nmem,
                          uint32_t npins)
{
    lm3_membranes *ms = sim->mem;
    uint64_t hp;
    uint32_t hm, hq;
    lm3_mstate_counts(sim, &hp, &hm, &hq);
    if (np != hp || nmem != hm || npins != hq) {
        snprintf(sim->err, sizeof sim->err, "does not fit the script: it holds %llu membrane "
                 "points in %u membranes with %u pins, the script's simulation %llu in %u with "
                 "%u", (unsigned long long)np, nmem, npins, (unsigned long long)hp, hm, hq);
        return LM_ERR_INPUT;
    }
    if (!ms) return LM_OK;
    const unsigned char *mb = b, *pb = b + (size_t)nmem * 16, *arr = pb + (size_t)npins * 32;
    for (uint32_t k = 0; k < nmem; k++) {
        uint64_t c[2];
        memcpy(c, mb + 16 * (size_t)k, sizeof c);
        if (c[0] != ms->mem[k].count || c[1] > c[0]) {
            snprintf(sim->err, sizeof sim->err, "does not fit the script: its membrane %u has "
                     "%llu points, the script's %zu", k + 1, (unsigned long long)c[0],
                     ms->mem[k].count);
            return LM_ERR_INPUT;
        }
    }
    for (uint32_t k = 0; k < npins; k++) {
        uint64_t n;
        double R[3];
        memcpy(&n, pb + 32 * (size_t)k, sizeof n);
        memcpy(R, pb + 32 * (size_t)k + 8, sizeof R);
        if (n != ms->pins[k].n || !isfinite(R[0]) || !isfinite(R[1]) || !isfinite(R[2])) {
            snprintf(sim->err, sizeof sim->err, "does not fit the script: its membrane pin %u "
                     "holds %llu points, the script's %zu (or its reaction is not finite)",
                     k + 1, (unsigned long long)n, ms->pins[k].n);
            return LM_ERR_INPUT;
        }
    }
    const lm3_grid *g = &sim->grid;
    for (uint64_t q = 0; q < np; q++) {
        for (int k = 0; k < MP_ARRAYS; k++)
            if (!isfinite(saved(arr, np, k, q))) {
                snprintf(sim->err, sizeof sim->err, "is damaged: membrane point %llu has a "
                         "value that is not finite (array %d)", (unsigned long long)q + 1, k + 1);
                return LM_ERR_INPUT;
            }
        for (int a = 0; a < 3; a++) {
            double x = saved(arr, np, a, q);
            if (!(x >= g->lo[a] && x <= g->lo[a] + g->n[a] * g->h)) {
                snprintf(sim->err, sizeof sim->err, "is damaged: membrane point %llu has %c = "
                         "%g outside the domain [%g, %g]", (unsigned long long)q + 1, "xyz"[a], x,
                         g->lo[a], g->lo[a] + g->n[a] * g->h);
                return LM_ERR_INPUT;
            }
        }
        if (!(saved(arr, np, 6, q) > 0) || !(saved(arr, np, 7, q) > 0)) {
            snprintf(sim->err, sizeof sim->err, "is damaged: membrane point %llu has mass %g and "
                     "area %g (both must be positive)", (unsigned long long)q + 1,
                     saved(arr, np, 6, q), saved(arr, np, 7, q));
            return LM_ERR_INPUT;
        }
    }
    /* checked: now replace */
    for (uint32_t k = 0; k < nmem; k++) {
        uint64_t c[2];
        memcpy(c, mb + 16 * (size_t)k, sizeof c);
        ms->mem[k].undefined = (size_t)c[1];
    }
    for (uint32_t k = 0; k < npins; k++) memcpy(ms->pins[k].reaction, pb + 32 * (size_t)k + 8, 24);
    double *a[MP_ARRAYS];
    arrays_of(&ms->p, a);
    for (int k = 0; k < MP_ARRAYS; k++)
        if (np) memcpy(a[k], arr + (size_t)k * np * sizeof(double), np * sizeof(double));
    return LM_OK;
}
