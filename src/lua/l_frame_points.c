/* l_frame_points.c - the particles of one side of a sim:frame panel as
 * figure.h point layers: which bodies are drawn (particles = true |
 * "membranes"), which of them are coloured by the panel's field
 * (colour_bodies: the others keep their body colour, so one body's field
 * does not paint another in its range, docs/gallery.md "Legibility
 * checklist" 3) and, for band = w, which points a membrane's band joins.
 *
 * Without colour_bodies and band the layer is the engine's own arrays, or
 * for "membranes" the compacted copy it always was: frames that ask for
 * neither keep their pixels. */
#include <string.h>

#include "l_frame_panel.h"

static int included(const lm_body *bd, int which)
{
    return which == 0 || (which == 1 && bd->membrane);
}

/* next[] for a membrane body whose count points start at k in the layer:
 * each joined to the following one, the last to the first when closed. */
static void link_body(const lm_body *bd, size_t k, long *next)
{
    for (size_t i = 0; i < bd->count; i++)
        next[k + i] = !bd->membrane ? -1
                    : i + 1 < bd->count ? (long)(k + i + 1)
                    : bd->closed && bd->count > 2 ? (long)k : -1;
}

/* The points of the included bodies whose valued flag is want (every
 * included body when valued is NULL), in body order; values copied when
 * the layer shows the field. */
static void compact(lua_State *L, la_frame_ctx *ctx, const lm_sim *sim,
                    const double *value, const la_frame_points_opts *o, int want,
                    const lr_points *base, lr_points *pts)
{
    size_t n = 0;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        int v = o->valued && b < o->nvalued ? o->valued[b] : 0;
        if (included(bd, o->which) && (!o->valued || v == want)) n += bd->count;
    }
    size_t m = n ? n : 1;
    double *x = la_frame_scratch(L, ctx, m * sizeof *x);
    double *y = la_frame_scratch(L, ctx, m * sizeof *y);
    int *grp = la_frame_scratch(L, ctx, m * sizeof *grp);
    int with_value = value && (!o->valued || want);
    double *val = with_value ? la_frame_scratch(L, ctx, m * sizeof *val) : NULL;
    long *next = o->band > 0 ? la_frame_scratch(L, ctx, m * sizeof *next) : NULL;
    size_t k = 0;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        int v = o->valued && b < o->nvalued ? o->valued[b] : 0;
        if (!included(bd, o->which) || (o->valued && v != want)) continue;
        if (next) link_body(bd, k, next);
        for (size_t q = bd->first; q < bd->first + bd->count; q++, k++) {
            x[k] = base->x[q];   /* as drawn: scale = k moves them (l_ref.c) */
            y[k] = base->y[q];
            grp[k] = b;
            if (val) val[k] = value[q];
        }
    }
    pts->n = n;
    pts->x = x;
    pts->y = y;
    pts->group = grp;
    pts->value = val;
    pts->next = next;
    pts->band = next ? o->band : 0;
}

size_t la_frame_points(lua_State *L, la_frame_ctx *ctx, const lm_sim *sim,
                       const double *value, const la_frame_points_opts *o,
                       const lr_points *base, lr_points out[2])
{
    if (o->which == 2) return 0;
    out[0] = out[1] = *base;
    if (o->which == 0 && !o->valued) {
        out[0].value = value;
        if (o->band > 0) {
            long *next = la_frame_scratch(L, ctx, (sim->p.n ? sim->p.n : 1) * sizeof *next);
            for (size_t i = 0; i < sim->p.n; i++)
                next[i] = -1;
            for (int b = 0; b < sim->nbodies; b++)
                link_body(&sim->bodies[b], sim->bodies[b].first, next);
            out[0].next = next;
            out[0].band = o->band;
        }
        return 1;
    }
    compact(L, ctx, sim, value, o, 1, base, &out[0]);
    if (!o->valued) return 1;
    /* the bodies in their own colours over the field's */
    compact(L, ctx, sim, value, o, 0, base, &out[1]);
    return 2;
}
