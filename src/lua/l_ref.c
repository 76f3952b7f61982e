/* l_ref.c - each body's reference positions X0, for sim:frame{scale = k}
 * (displacement exaggeration: a point drawn at X0 + k (x - X0); issue 35
 * item 4, docs/api.md "sim:frame").
 *
 * The engine keeps no initial positions, so the binding records them: a
 * body's points are captured when it first steps (the start of the
 * sim:run / sim:step after it was added: nothing moves a point between its
 * creation and a step), and before a --restart checkpoint replaces the
 * state (the script rebuilds its bodies as the first run did, so the
 * references are that run's). Points a body gains later - gas splitting
 * (src/mpm/split.c) appends a split point's three siblings at the body's
 * tail and keeps the other points' order - are captured at the next
 * sim:run / sim:step, at their positions then. A point without a
 * reference yet is drawn where it is. */
#include <stdlib.h>
#include <string.h>

#include "l_internal.h"

/* Grows body b's arrays to its present count, copying the new points. */
static int capture_body(const lm_sim *sim, int b, la_ref_body *r)
{
    const lm_body *bd = &sim->bodies[b];
    if (bd->count < r->n) r->n = 0;   /* the body was replaced: start again */
    if (bd->count == r->n) return 0;
    double *x = realloc(r->x, bd->count * sizeof *x);
    if (!x) return -1;
    r->x = x;
    double *y = realloc(r->y, bd->count * sizeof *y);
    if (!y) return -1;
    r->y = y;
    for (size_t k = r->n; k < bd->count; k++) {
        r->x[k] = sim->p.x[bd->first + k];
        r->y[k] = sim->p.y[bd->first + k];
    }
    r->n = bd->count;
    return 0;
}

void la_ref_capture(lua_State *L, la_sim *s)
{
    const lm_sim *sim = s->sim;
    while (s->nref > sim->nbodies) {   /* bodies taken out again */
        la_ref_body *r = &s->ref[--s->nref];
        free(r->x);
        free(r->y);
        memset(r, 0, sizeof *r);
    }
    if (s->nref < sim->nbodies) {
        la_ref_body *ref = realloc(s->ref, (size_t)sim->nbodies * sizeof *ref);
        if (!ref) luaL_error(L, "sim: out of memory for the reference positions");
        memset(ref + s->nref, 0, (size_t)(sim->nbodies - s->nref) * sizeof *ref);
        s->ref = ref;
        s->nref = sim->nbodies;
    }
    for (int b = 0; b < sim->nbodies; b++)
        if (capture_body(sim, b, &s->ref[b]))
            luaL_error(L, "sim: out of memory for the reference positions of %zu points",
                       sim->bodies[b].count);
}

void la_ref_scaled(const la_sim *s, double k, double *x, double *y)
{
    const lm_sim *sim = s->sim;
    memcpy(x, sim->p.x, sim->p.n * sizeof *x);
    memcpy(y, sim->p.y, sim->p.n * sizeof *y);
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        const la_ref_body *r = b < s->nref ? &s->ref[b] : NULL;
        for (size_t i = 0; i < bd->count; i++) {
            size_t q = bd->first + i;
            if (r && i < r->n) {
                x[q] = r->x[i] + k * (sim->p.x[q] - r->x[i]);
                y[q] = r->y[i] + k * (sim->p.y[q] - r->y[i]);
            } else {
                x[q] = sim->p.x[q];
                y[q] = sim->p.y[q];
            }
        }
    }
}

void la_ref_free(la_sim *s)
{
    for (int b = 0; b < s->nref; b++) {
        free(s->ref[b].x);
        free(s->ref[b].y);
    }
    free(s->ref);
    s->ref = NULL;
    s->nref = 0;
}
