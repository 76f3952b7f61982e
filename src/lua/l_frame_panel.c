/* l_frame_panel.c - one panel of sim:frame: which simulation(s), which
 * window, what colours, which extras (docs/api.md, "sim:frame").
 *
 * Only gathering happens here; src/render draws. Arrays the renderer needs
 * beyond the engine's own (values through a colour map, normal arrows) are
 * Lua userdata anchored for the call, so a Lua error leaks nothing. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fields.h"
#include "l_frame_panel.h"

void *la_frame_scratch(lua_State *L, la_frame_ctx *ctx, size_t n)
{
    void *p = lua_newuserdatauv(L, n ? n : 1, 0);
    memset(p, 0, n ? n : 1);
    lua_rawseti(L, ctx->anchor, ++ctx->nanchored);
    return p;
}

/* Pushes the value of key from the panel table, else the frame table. */
static int get(lua_State *L, int fidx, int pidx, const char *key)
{
    if (!fidx && !pidx) {
        lua_pushnil(L);
        return LUA_TNIL;
    }
    if (pidx) {
        int t = la_getfield(L, pidx, key);
        if (t != LUA_TNIL || !fidx)
            return t;
        lua_pop(L, 1);
    }
    return la_getfield(L, fidx, key);
}

/* ---- what particles show ------------------------------------------------ */

/* A colour: "body" (the palette, f = NULL) or a component of a field of
 * the engine's table (fields.h), by the component's name. */
typedef struct field {
    const lm_field *f;
    int comp;
} field;

#define MAX_COLOURS 64

static const char *comp_name(const lm_field *f, int c)
{
    return f->ncomp == 1 ? f->name : f->comp[c];
}

/* "body" (the palette; the table's field "body", the index, is what the
 * palette shows), then every component's name in the table's order but
 * the position's (where a point is drawn is no colour): the option list
 * of `colour` (and of its error message). */
static void colour_names(const char *names[MAX_COLOURS])
{
    int k = 0;
    names[k++] = "body";
    for (int i = 0; i < lm_field_count(); i++) {
        const lm_field *f = lm_field_get(i);
        if (strcmp(f->name, "position") == 0) continue;
        for (int c = 0; c < f->ncomp && k < MAX_COLOURS - 1; c++)
            if (strcmp(comp_name(f, c), "body") != 0) names[k++] = comp_name(f, c);
    }
    names[k] = NULL;
}

static int is_field(field f, const char *name)
{
    return f.f && strcmp(comp_name(f.f, f.comp), name) == 0;
}

/* The colour bar's label: the field, and for the two membrane fields the
 * unit, since both are called "tension" somewhere (issue 35 item 4). */
static const char *field_label(field f)
{
    return !f.f ? "pressure"
         : is_field(f, "tension") ? "tension (F/L)"
         : is_field(f, "membrane_stress") ? "stress (F/A)"
         : comp_name(f.f, f.comp);
}

/* Particle radius in world units: half the smallest particle spacing, from
 * the volume a particle started with. */
static double particle_radius(const lm_sim *sim)
{
    double r = 0;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        if (bd->count == 0) continue;
        size_t q = bd->first;
        double v = sim->p.m[q] / sim->mats[bd->mat]->rho;
        double rb = 0.5 * sqrt(v);
        if (r == 0 || rb < r) r = rb;
    }
    return r;
}

/* discs = "spacing": each body's own radius ([T]-style strings read as
 * points): a membrane's points a third of their spacing along it (the
 * spacing from the volume a point started with over the thickness, so
 * neighbours keep a gap), other bodies half their spacing as above. */
static double *body_radii(lua_State *L, la_frame_ctx *ctx, const lm_sim *sim)
{
    double *r = la_frame_scratch(L, ctx, (sim->nbodies ? sim->nbodies : 1) * sizeof *r);
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        const lm_material *mt = sim->mats[bd->mat];
        r[b] = 0;
        if (bd->count == 0) continue;
        double v = sim->p.m[bd->first] / mt->rho;
        r[b] = bd->membrane && mt->thickness > 0 ? v / mt->thickness / 3.0 : 0.5 * sqrt(v);
    }
    return r;
}

/* ---- a side: one simulation's layers ------------------------------------ */

typedef struct side_store {
    lr_grid grid;
    lr_points points[2];
    lr_arrows arrows;
    lr_field field;
} side_store;

/* Membrane normals (the tangent turned +90 degrees, [M] section 3) as
 * arrows one cell long, at every `every`-th point of each membrane. */
static void normals_every(lua_State *L, la_frame_ctx *ctx, lm_sim *sim, const double *px,
                          const double *py, int every, lr_arrows *a)
{
    /* tangents exist from the first step on; before it, from a prepare
     * (which sim:membrane has already run: it cannot fail here unless a
     * body added since cannot be prepared, which that sim:body reported) */
    if (!sim->prepared && lm_sim_prepare(sim) != LM_OK)
        luaL_error(L, "sim:frame: %s", sim->err);
    size_t n = 0;
    for (int b = 0; b < sim->nbodies; b++)
        if (sim->bodies[b].membrane)
            n += sim->bodies[b].count;
    double *buf = la_frame_scratch(L, ctx, 4 * (n ? n : 1) * sizeof *buf);
    double *x = buf, *y = buf + n, *ux = buf + 2 * n, *uy = buf + 3 * n;
    size_t k = 0;
    const lm_field *normal = lm_field_find("nx", NULL);   /* the engine's (fields.c) */
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        for (size_t q = bd->first; bd->membrane && q < bd->first + bd->count;
             q += (size_t)every, k++) {
            x[k] = px[q];
            y[k] = py[q];
            ux[k] = lm_field_value(sim, normal, 0, q);
            uy[k] = lm_field_value(sim, normal, 1, q);
        }
    }
    const lr_rgba dark = { 0.1, 0.1, 0.1, 1.0 };
    a->n = k;
    a->x = x;
    a->y = y;
    a->ux = ux;
    a->uy = uy;
    a->length = fmin(sim->grid.hx, sim->grid.hy);
    a->width = 1.5;
    a->head = 7.0;
    a->colour = dark;
}

#define NORMALS_GAP_PX 16.0   /* the default's least gap between drawn arrows */

/* The mean distance between a membrane's consecutive points as they are
 * drawn (stretched or not); 0 when it cannot be told. */
static double membrane_spacing(const double *px, const double *py, const lm_body *bd)
{
    if (bd->count < 2) return 0;
    double sum = 0;
    for (size_t q = bd->first + 1; q < bd->first + bd->count; q++)
        sum += hypot(px[q] - px[q - 1], py[q] - py[q - 1]);
    double s = sum / (double)(bd->count - 1);
    return isfinite(s) && s > 0 ? s : 0;
}

/* The default (normals = nil): one arrow set per membrane, thinned and
 * scaled to its spacing by the renderer (lr_arrows.thin): every k-th
 * point's, k the least with k spacings >= NORMALS_GAP_PX pixels, each
 * arrow as long as that gap, so that single arrows can be judged at any
 * zoom (docs/gallery.md, legibility 2). Sets l's arrows (one: the store
 * of a single set). */
static void normals_auto(lua_State *L, la_frame_ctx *ctx, lm_sim *sim, const double *px,
                         const double *py, lr_layers *l, lr_arrows *one)
{
    int nm = 0;
    for (int b = 0; b < sim->nbodies; b++)
        nm += sim->bodies[b].membrane && sim->bodies[b].count > 0;
    if (nm == 0) return;
    lr_arrows *sets = nm == 1 ? one : la_frame_scratch(L, ctx, (size_t)nm * sizeof *sets);
    lr_arrows all;
    normals_every(L, ctx, sim, px, py, 1, &all);
    size_t at = 0;
    int k = 0;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        if (!bd->membrane || bd->count == 0) continue;
        lr_arrows *a = &sets[k++];
        *a = all;
        a->n = bd->count;
        a->x = all.x + at;
        a->y = all.y + at;
        a->ux = all.ux + at;
        a->uy = all.uy + at;
        a->spacing = membrane_spacing(px, py, bd);
        a->thin = a->spacing > 0 ? NORMALS_GAP_PX : 0;   /* else one cell, every point */
        at += bd->count;
    }
    l->arrows = sets;
    l->narrows = (size_t)nm;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Filled pressure contours from the gas pressure interpolated to the grid
 * ([T] Fig 56), drawn under the particles, only where the gas is
 * (l_frame_gas_mask.c). When the contours own the panel's colour (colour = "body"), the
 * bands span the panel's range if it has one, else the 5th-95th percentile
 * of the nodal values, which then becomes the panel's range (so the other
 * half of a split panel and the colour bar use the same), in the panel's
 * colour map; otherwise (the particles show a field) their own percentile
 * range, in viridis, without a bar. */
static void pressure_contours(lua_State *L, la_frame_ctx *ctx, lm_sim *sim, int nlevels,
                              lr_field *fd, lr_panel *p, int own)
{
    const lm_grid *g = &sim->grid;
    size_t nn = (size_t)(g->nx + 1) * (size_t)(g->ny + 1);
    double *f = la_frame_scratch(L, ctx, nn * sizeof *f);
    memset(fd, 0, sizeof *fd);
    if (lm_grid_gas_pressure(sim, f) == 0) return;
    /* the bands span the 5th to 95th percentile of the nodal values, so a
     * few extreme nodes (a corner, a shock) do not flatten the rest */
    double *sorted = la_frame_scratch(L, ctx, nn * sizeof *sorted);
    size_t m = 0;
    for (size_t i = 0; i < nn; i++)
        if (isfinite(f[i])) sorted[m++] = f[i];
    qsort(sorted, m, sizeof *sorted, cmp_double);
    double lo = sorted[(size_t)(0.05 * (double)(m - 1))];
    double hi = sorted[(size_t)(0.95 * (double)(m - 1))];
    if (!(hi > lo)) hi = lo + fmax(1e-12, fabs(lo) * 1e-6);
    lr_cmap cmap = LR_CMAP_VIRIDIS;
    if (own) {
        if (p->vmax > p->vmin) {
            lo = p->vmin;
            hi = p->vmax;
        } else {
            p->vmin = lo;
            p->vmax = hi;
        }
        cmap = p->cmap;
    }
    for (size_t i = 0; i < nn; i++)
        if (!isfinite(f[i])) f[i] = -HUGE_VAL;   /* below every level: not filled */
    double *levels = la_frame_scratch(L, ctx, (size_t)nlevels * sizeof *levels);
    lr_rgba *colours = la_frame_scratch(L, ctx, (size_t)nlevels * sizeof *colours);
    for (int k = 0; k < nlevels; k++) {
        /* the first band covers every node the gas touches */
        levels[k] = k == 0 ? fmin(sorted[0], lo) : lo + (hi - lo) * k / nlevels;
        colours[k] = lr_cmap_colour(cmap, (double)k / (nlevels > 1 ? nlevels - 1 : 1));
        colours[k].a = 0.85;
    }
    fd->f = f;
    fd->nx = g->nx;
    fd->ny = g->ny;
    /* the bands only where the gas is, not a cell past it (issue 32 item 6) */
    la_frame_gas_mask(L, ctx, sim, f, fd);
    fd->x0 = g->x0;
    fd->y0 = g->y0;
    fd->x1 = g->x0 + g->nx * g->hx;
    fd->y1 = g->y0 + g->ny * g->hy;
    fd->levels = levels;
    fd->nlevels = nlevels;
    fd->colours = colours;
}

/* What a panel asks of each side beyond its colour. */
typedef struct side_opts {
    int grid;
    field f;
    int normals;                /* 0 none, -1 the default (thinned to the
                                   spacing), k every k-th point's */
    int contour_levels;         /* 0: no pressure contours */
    int phi;                    /* 0 none, 1 asked (strict), -1 the default */
    int contact_every;          /* 0: no contact arrows */
    double contact_scale;
    int contact_outlined;       /* the table form */
    int own_discs;
    la_frame_points_opts pts;   /* which bodies, coloured how, band */
} side_opts;

static void fill_side(lua_State *L, la_frame_ctx *ctx, la_sim *ls, const side_opts *o,
                      lr_panel *p, lr_layers *l)
{
    lm_sim *sim = ls->sim;
    side_store *st = la_frame_scratch(L, ctx, sizeof *st);
    /* the positions drawn: the points' own, or with scale = k about their
     * reference positions (l_ref.c); normals and bands follow them */
    const double *px = sim->p.x, *py = sim->p.y;
    if (ctx->scale != 1) {
        size_t n = sim->p.n ? sim->p.n : 1;
        double *x = la_frame_scratch(L, ctx, n * sizeof *x);
        double *y = la_frame_scratch(L, ctx, n * sizeof *y);
        la_ref_scaled(ls, ctx->scale, x, y);
        px = x;
        py = y;
    }
    if (o->contour_levels > 0) {
        pressure_contours(L, ctx, sim, o->contour_levels, &st->field, p, !o->f.f);
        if (st->field.f) {
            l->fields = &st->field;
            l->nfields = 1;
        }
    }
    const lm_grid *g = &sim->grid;
    st->grid.x0 = g->x0;
    st->grid.y0 = g->y0;
    st->grid.hx = g->hx;
    st->grid.hy = g->hy;
    st->grid.nx = g->nx;
    st->grid.ny = g->ny;
    l->grid = o->grid ? &st->grid : NULL;
    lr_points base;
    memset(&base, 0, sizeof base);
    base.n = sim->p.n;
    base.x = px;
    base.y = py;
    base.group = sim->p.body;
    base.radius = particle_radius(sim);
    base.group_radius = o->own_discs ? body_radii(L, ctx, sim) : NULL;
    base.ngroups = o->own_discs ? sim->nbodies : 0;
    if (o->f.f && o->f.f->tangents && !sim->prepared && lm_sim_prepare(sim) != LM_OK)
        luaL_error(L, "sim:frame: %s", sim->err);   /* tangents before the first step */
    double *v = NULL;
    if (o->f.f) {   /* the engine's definition (fields.c), 0 where a kind lacks it */
        v = la_frame_scratch(L, ctx, (sim->p.n ? sim->p.n : 1) * sizeof *v);
        lm_field_fill(sim, o->f.f, o->f.comp, 0, sim->p.n, v);
    }
    l->points = st->points;
    l->npoints = la_frame_points(L, ctx, sim, v, &o->pts, &base, st->points);
    int nm = 0, nphi = 0;
    for (int b = 0; b < sim->nbodies; b++) {
        nm += sim->bodies[b].membrane && sim->bodies[b].count > 0;
        nphi += la_membrane_has_phi(&sim->bodies[b]);
    }
    ctx->membranes += nm;
    ctx->with_phi += nphi;
    ctx->normals += o->normals ? nm : 0;
    ctx->phi += o->phi ? nphi : 0;
    if (o->normals > 0) {
        normals_every(L, ctx, sim, px, py, o->normals, &st->arrows);
        l->arrows = &st->arrows;
        l->narrows = 1;
    } else if (o->normals < 0) {
        normals_auto(L, ctx, sim, px, py, l, &st->arrows);
    }
    if (o->phi) {
        lr_curve *cv;
        l->ncurves = la_frame_phi(L, ctx, sim, o->phi > 0, o->pts.band > 0, &cv);
        l->curves = cv;
    }
    if (o->contact_every)
        la_frame_contact(L, ctx, sim, o->contact_every, o->contact_scale, o->contact_outlined,
                         l);
}

/* ---- the keys ----------------------------------------------------------- */

static la_sim *sim_at(lua_State *L, const la_frame_ctx *ctx, int idx, const char *key)
{
    la_sim *s = luaL_testudata(L, idx, LA_SIM);
    if (!s)
        luaL_error(L, "%s: '%s' must be a simulation (lamina.sim), got %s", ctx->fn,
                   key, luaL_typename(L, idx));
    return la_check_sim(L, idx);   /* and not freed */
}

/* Pushes key's value (get); 1 when it is of type `type`, 0 when nil, else
 * an error: '<key>' must be <must>. */
static int typed(lua_State *L, const la_frame_ctx *ctx, int fidx, int pidx, const char *key,
                 int type, const char *must)
{
    int t = get(L, fidx, pidx, key);
    if (t != type && t != LUA_TNIL)
        luaL_error(L, "%s: '%s' must be %s (got %s)", ctx->fn, key, must,
                   luaL_typename(L, -1));
    return t == type;
}

static int boolean(lua_State *L, const la_frame_ctx *ctx, int fidx, int pidx,
                   const char *key, int def)
{
    int v = typed(L, ctx, fidx, pidx, key, LUA_TBOOLEAN, "true or false")
                ? lua_toboolean(L, -1) : def;
    lua_pop(L, 1);
    return v;
}

/* A string kept alive by its table (which outlives the call). */
static const char *string(lua_State *L, const la_frame_ctx *ctx, int fidx, int pidx,
                          const char *key)
{
    const char *s = typed(L, ctx, fidx, pidx, key, LUA_TSTRING, "a string")
                        ? lua_tostring(L, -1) : NULL;
    lua_pop(L, 1);
    return s;
}

/* {a, b, ...}: n numbers. */
static void numbers(lua_State *L, const la_frame_ctx *ctx, int idx, const char *key,
                    const char *shape, int n, double *v)
{
    if (!lua_istable(L, idx) || (int)lua_rawlen(L, idx) != n)
        luaL_error(L, "%s: '%s' must be %s", ctx->fn, key, shape);
    for (int i = 0; i < n; i++) {
        lua_rawgeti(L, idx, i + 1);
        int isnum;
        v[i] = lua_tonumberx(L, -1, &isnum);
        if (!isnum || !isfinite(v[i]))
            luaL_error(L, "%s: '%s' must be %s of finite numbers", ctx->fn, key, shape);
        lua_pop(L, 1);
    }
}

static void window(lua_State *L, const la_frame_ctx *ctx, int fidx, int pidx,
                   const lm_sim *sim, lr_panel *p)
{
    const lm_grid *g = &sim->grid;
    double w[4] = { g->x0, g->y0, g->x0 + g->nx * g->hx, g->y0 + g->ny * g->hy };
    if (get(L, fidx, pidx, "window") != LUA_TNIL) {
        numbers(L, ctx, lua_gettop(L), "window", "{x0, y0, x1, y1}", 4, w);
        if (!(w[2] > w[0]) || !(w[3] > w[1]))
            luaL_error(L, "%s: 'window' is empty", ctx->fn);
    } else {
        lr_panel_mirror_window(p, w);   /* the domain and its mirror images */
    }
    lua_pop(L, 1);
    p->wx0 = w[0];
    p->wy0 = w[1];
    p->wx1 = w[2];
    p->wy1 = w[3];
}

/* "x", "y", "xy" (about the domain's left / bottom side, where a symmetry
 * wall of a quarter model lies), or {x = a, y = b} (about those lines). */
static void mirror(lua_State *L, const la_frame_ctx *ctx, int fidx, int pidx,
                   const lm_sim *sim, lr_panel *p)
{
    int t = get(L, fidx, pidx, "mirror");
    p->mirror_ax = sim->grid.x0;
    p->mirror_ay = sim->grid.y0;
    if (t == LUA_TSTRING) {
        const char *s = lua_tostring(L, -1);
        static const char *const names[] = { "x", "y", "xy", NULL };
        int k = la_option(L, ctx->fn, "mirror", s, names);
        p->mirror_x = k == 0 || k == 2;
        p->mirror_y = k == 1 || k == 2;
    } else if (t == LUA_TTABLE) {
        int idx = lua_gettop(L);
        static const char *const keys[] = { "x", "y", NULL };
        la_check_keys(L, idx, "sim:frame: mirror", keys);
        if (la_has(L, idx, "x")) {
            p->mirror_x = 1;
            p->mirror_ax = la_opt_number(L, idx, "sim:frame: mirror", "x", 0);
        }
        if (la_has(L, idx, "y")) {
            p->mirror_y = 1;
            p->mirror_ay = la_opt_number(L, idx, "sim:frame: mirror", "y", 0);
        }
    } else if (t != LUA_TNIL && !(t == LUA_TBOOLEAN && !lua_toboolean(L, -1))) {
        luaL_error(L, "%s: 'mirror' must be \"x\", \"y\", \"xy\" or {x = ..., y = ...}",
                   ctx->fn);
    }
    lua_pop(L, 1);
}

/* colour, colourmap, range, colourbar; contours: the pressure contours may
 * own the colour (and the bar) when the particles show none */
static field colours(lua_State *L, const la_frame_ctx *ctx, int fidx, int pidx,
                     lr_panel *p, int contours)
{
    const char *name = string(L, ctx, fidx, pidx, "colour");
    field f = { NULL, 0 };
    if (name) {
        const char *names[MAX_COLOURS];
        colour_names(names);
        if (la_option(L, ctx->fn, "colour", name, names) > 0)
            f.f = lm_field_find(name, &f.comp);
    }
    /* Signed quantities get the diverging map by default (zero in the
     * middle). Pressure does not: it colours gas, whose pressure is
     * positive, and on a scale symmetric about 0 gas at p = 10 came out
     * pale (issue 35 item 4). */
    p->cmap = f.f && f.f->diverging ? LR_CMAP_RDBU : LR_CMAP_VIRIDIS;
    const char *map = string(L, ctx, fidx, pidx, "colourmap");
    char why[128];
    if (map && lr_cmap_parse(map, &p->cmap, why, sizeof why) != 0)
        luaL_error(L, "%s: 'colourmap': %s", ctx->fn, why);
    if (get(L, fidx, pidx, "range") != LUA_TNIL) {
        double r[2];
        numbers(L, ctx, lua_gettop(L), "range", "{min, max}", 2, r);
        if (!(r[1] > r[0]))
            luaL_error(L, "%s: 'range' must have max > min (got {%f, %f})", ctx->fn,
                       r[0], r[1]);
        p->vmin = r[0];
        p->vmax = r[1];
    }
    lua_pop(L, 1);
    p->colourbar = boolean(L, ctx, fidx, pidx, "colourbar", f.f || contours);
    if (p->colourbar && !f.f && !contours)
        luaL_error(L, "%s: 'colourbar' needs colour = a field (e.g. \"speed\"), "
                   "not \"body\"", ctx->fn);
    p->colourbar_label = field_label(f);
    return f;
}

static void scalebar(lua_State *L, const la_frame_ctx *ctx, int fidx, int pidx,
                     lr_panel *p)
{
    int t = get(L, fidx, pidx, "scalebar");
    if (t == LUA_TBOOLEAN)
        p->scalebar = lua_toboolean(L, -1) ? -1.0 : 0.0;
    else if (t == LUA_TNUMBER) {
        p->scalebar = lua_tonumber(L, -1);
        if (!(p->scalebar > 0) || !isfinite(p->scalebar))
            luaL_error(L, "%s: 'scalebar' must be true or a length > 0", ctx->fn);
    } else if (t != LUA_TNIL)
        luaL_error(L, "%s: 'scalebar' must be true or a length > 0 (got %s)", ctx->fn,
                   luaL_typename(L, -1));
    lua_pop(L, 1);
    p->units = string(L, ctx, fidx, pidx, "units");
}

/* split = other sim: its particles right of split_at; names = {left, right} */
static la_sim *split(lua_State *L, const la_frame_ctx *ctx, int fidx, int pidx,
                     lr_panel *p)
{
    la_sim *other = NULL;
    if (get(L, fidx, pidx, "split") != LUA_TNIL) {
        other = sim_at(L, ctx, lua_gettop(L), "split");
        p->split = 1;
    }
    lua_pop(L, 1);
    if (get(L, fidx, pidx, "names") != LUA_TNIL) {
        int idx = lua_gettop(L);
        if (!lua_istable(L, idx) || lua_rawlen(L, idx) != 2)
            luaL_error(L, "%s: 'names' must be {left, right}", ctx->fn);
        for (int i = 0; i < 2; i++) {
            if (lua_rawgeti(L, idx, i + 1) != LUA_TSTRING)
                luaL_error(L, "%s: 'names' must be two strings", ctx->fn);
            p->side[i].name = lua_tostring(L, -1);  /* alive in its table */
            lua_pop(L, 1);
        }
    }
    lua_pop(L, 1);
    if (!other && (p->side[0].name || p->side[1].name))
        luaL_error(L, "%s: 'names' needs 'split' (the other simulation)", ctx->fn);
    return other;
}

/* contact = true | false | {every = k, scale = s} */
static void contact_opt(lua_State *L, const la_frame_ctx *ctx, int fidx, int pidx,
                        side_opts *o)
{
    int t = get(L, fidx, pidx, "contact");
    o->contact_every = 0;
    o->contact_scale = 1.0;
    if (t == LUA_TBOOLEAN) {
        o->contact_every = lua_toboolean(L, -1);
    } else if (t == LUA_TTABLE) {
        int idx = lua_gettop(L);
        static const char *const keys[] = { "every", "scale", NULL };
        o->contact_outlined = 1;
        la_check_keys(L, idx, "sim:frame: contact", keys);
        double k = la_opt_number(L, idx, "sim:frame: contact", "every", 1);
        if (!(k >= 1 && k <= 1e6) || k != floor(k))
            luaL_error(L, "%s: contact's 'every' must be a whole number k >= 1 (a node "
                          "of each k x k block of nodes)", ctx->fn);
        o->contact_every = (int)k;
        o->contact_scale = la_opt_number(L, idx, "sim:frame: contact", "scale", 1);
        if (!(o->contact_scale > 0 && o->contact_scale <= 100))
            luaL_error(L, "%s: contact's 'scale' must be a number in (0, 100]", ctx->fn);
    } else if (t != LUA_TNIL) {
        luaL_error(L, "%s: 'contact' must be true, false or {every = k, scale = s} (got %s)",
                   ctx->fn, luaL_typename(L, -1));
    }
    lua_pop(L, 1);
}

/* band = w: membranes drawn as bands w pixels wide, in (0, 64] */
static double band_opt(lua_State *L, const la_frame_ctx *ctx, int fidx, int pidx)
{
    double w = 0;
    if (get(L, fidx, pidx, "band") != LUA_TNIL) {
        int isnum;
        w = lua_tonumberx(L, -1, &isnum);
        if (!isnum || !(w > 0 && w <= 64))
            luaL_error(L, "%s: 'band' must be a width in pixels in (0, 64]", ctx->fn);
    }
    lua_pop(L, 1);
    return w;
}

/* colour_bodies = {body, ...}: the bodies coloured by the field, by index
 * (bodies of the panel's simulation or of its split one: a split panel's
 * two runs are built alike). NULL when absent. */
static unsigned char *colour_bodies(lua_State *L, la_frame_ctx *ctx, int fidx, int pidx,
                                    const lm_sim *sim, const lm_sim *other, field f,
                                    int *nvalued)
{
    unsigned char *valued = NULL;
    *nvalued = 0;
    if (get(L, fidx, pidx, "colour_bodies") != LUA_TNIL) {
        int idx = lua_gettop(L);
        size_t n = lua_istable(L, idx) ? lua_rawlen(L, idx) : 0;
        if (n == 0)
            luaL_error(L, "%s: 'colour_bodies' must be a list of bodies", ctx->fn);
        if (!f.f)
            luaL_error(L, "%s: 'colour_bodies' needs colour = a field (e.g. \"pressure\")",
                       ctx->fn);
        int nb = sim->nbodies;
        if (other && other->nbodies > nb) nb = other->nbodies;
        valued = la_frame_scratch(L, ctx, (size_t)(nb ? nb : 1));
        for (size_t i = 0; i < n; i++) {
            lua_rawgeti(L, idx, (lua_Integer)i + 1);
            if (!luaL_testudata(L, -1, LA_BODY))
                luaL_error(L, "%s: colour_bodies[%d] must be a body (got %s)", ctx->fn,
                           (int)i + 1, luaL_typename(L, -1));
            lm_sim *owner;
            int b = la_check_body(L, -1, &owner);
            if (owner != sim && owner != other)
                luaL_error(L, "%s: colour_bodies[%d] is a body of a simulation this panel "
                              "does not show", ctx->fn, (int)i + 1);
            valued[b] = 1;
            lua_pop(L, 1);
        }
        *nvalued = nb;
    }
    lua_pop(L, 1);
    return valued;
}

/* colour = "pressure" without colour_bodies: the fluid bodies (gas and
 * linear fluid) coloured, the others in their body colours (issue 35 item
 * 4: a membrane's stress is no pressure to put on the gas's scale; a
 * membrane field is asked for by name). NULL when neither simulation has
 * a fluid body: then every body's pressure (a solid's mean stress) shows. */
static unsigned char *fluid_bodies(lua_State *L, la_frame_ctx *ctx, const lm_sim *sim,
                                   const lm_sim *other, int *nvalued)
{
    int nb = sim->nbodies;
    if (other && other->nbodies > nb) nb = other->nbodies;
    unsigned char *valued = la_frame_scratch(L, ctx, (size_t)(nb ? nb : 1));
    int any = 0;
    for (int k = 0; k < 2; k++) {
        const lm_sim *sm = k == 0 ? sim : other;
        for (int b = 0; sm && b < sm->nbodies; b++) {
            lm_kind kind = sm->mats[sm->bodies[b].mat]->kind;
            if (kind == LM_GAS || kind == LM_LINEAR_FLUID) valued[b] = 1, any = 1;
        }
    }
    *nvalued = any ? nb : 0;
    return any ? valued : NULL;
}

/* With scale = k the points are drawn away from where they are: the layers
 * that are fields of the grid (pressure contours, contact normals, the phi
 * contours) cannot follow them and are refused by name; phi, on by
 * default, is then off by default. */
static void scale_refuse(lua_State *L, const la_frame_ctx *ctx, const char *what)
{
    if (ctx->scale != 1)
        luaL_error(L, "%s: %s is a field of the grid, drawn where the points are: it cannot "
                      "be drawn with 'scale' = %f (about the reference positions)", ctx->fn,
                   what, ctx->scale);
}

void la_frame_panel(lua_State *L, la_frame_ctx *ctx, int fidx, int pidx, int sidx,
                    lr_panel *p)
{
    memset(p, 0, sizeof *p);
    la_sim *ls;
    if (pidx && get(L, fidx, pidx, "sim") != LUA_TNIL)
        ls = sim_at(L, ctx, lua_gettop(L), "sim");
    else
        ls = la_check_sim(L, sidx);
    lm_sim *sim = ls->sim;
    if (pidx)
        lua_pop(L, 1);
    if (pidx)
        p->title = string(L, ctx, 0, pidx, "title");
    mirror(L, ctx, fidx, pidx, sim, p);
    window(L, ctx, fidx, pidx, sim, p);
    /* contours = "pressure": the gas pressure's filled contours */
    const char *contours = string(L, ctx, fidx, pidx, "contours");
    if (contours && strcmp(contours, "pressure") != 0)
        luaL_error(L, "%s: contours = \"%s\" is not one of \"pressure\"", ctx->fn, contours);
    field f = colours(L, ctx, fidx, pidx, p, contours != NULL);
    scalebar(L, ctx, fidx, pidx, p);
    la_sim *lother = split(L, ctx, fidx, pidx, p);
    lm_sim *other = lother ? lother->sim : NULL;
    /* grid = true | false (issue 31 item 7: any type was taken for true) */
    int grid = boolean(L, ctx, fidx, pidx, "grid", 1);
    /* normals = true | false | k (every k-th point's); nil: thinned to the
     * spacing (issue 32: a frame shows what the papers show by default) */
    int with_normals = -1;
    int nt = get(L, fidx, pidx, "normals");
    if (nt == LUA_TBOOLEAN) {
        with_normals = lua_toboolean(L, -1);
    } else if (nt != LUA_TNIL) {
        int isnum;
        double k = lua_tonumberx(L, -1, &isnum);
        if (!isnum || k < 1 || k > 1e6 || k != floor(k))
            luaL_error(L, "%s: 'normals' must be true, false or a whole number k >= 1 "
                          "(every k-th point's)", ctx->fn);
        with_normals = (int)k;
    }
    lua_pop(L, 1);
    /* discs = "smallest" | "spacing" */
    const char *discs = string(L, ctx, fidx, pidx, "discs");
    if (discs && strcmp(discs, "smallest") != 0 && strcmp(discs, "spacing") != 0)
        luaL_error(L, "%s: discs = \"%s\" is not one of \"smallest\" | \"spacing\"",
                   ctx->fn, discs);
    side_opts o;
    memset(&o, 0, sizeof o);
    o.own_discs = discs && strcmp(discs, "spacing") == 0;
    o.phi = boolean(L, ctx, fidx, pidx, "phi", ctx->scale != 1 ? 0 : -1);
    contact_opt(L, ctx, fidx, pidx, &o);
    if (contours) scale_refuse(L, ctx, "contours = \"pressure\"");
    if (o.contact_every) scale_refuse(L, ctx, "contact");
    if (o.phi > 0) scale_refuse(L, ctx, "phi");
    o.pts.band = band_opt(L, ctx, fidx, pidx);
    o.pts.valued = colour_bodies(L, ctx, fidx, pidx, sim, other, f, &o.pts.nvalued);
    if (is_field(f, "pressure") && !o.pts.valued)
        o.pts.valued = fluid_bodies(L, ctx, sim, other, &o.pts.nvalued);
    p->split_x = 0.5 * (p->wx0 + p->wx1);
    if (get(L, fidx, pidx, "split_at") != LUA_TNIL) {
        int isnum;
        p->split_x = lua_tonumberx(L, -1, &isnum);
        if (!isnum || !isfinite(p->split_x))
            luaL_error(L, "%s: 'split_at' must be a number", ctx->fn);
        if (!other)
            luaL_error(L, "%s: 'split_at' needs 'split' (the other simulation)", ctx->fn);
    }
    lua_pop(L, 1);
    /* contour_levels: checked also without contours (issue 31 item 7: any
     * value passed unseen), where it is refused as meaningless */
    int nlevels = contours ? 10 : 0;
    if (get(L, fidx, pidx, "contour_levels") != LUA_TNIL) {
        int isnum;
        double v = lua_tonumberx(L, -1, &isnum);
        if (!isnum || !(v >= 2 && v <= 64) || v != floor(v))
            luaL_error(L, "%s: 'contour_levels' must be a whole number in [2, 64] (got %s)",
                       ctx->fn, isnum ? lua_tostring(L, -1) : luaL_typename(L, -1));
        if (!contours)
            luaL_error(L, "%s: 'contour_levels' needs contours = \"pressure\"", ctx->fn);
        nlevels = (int)v;
    }
    lua_pop(L, 1);
    /* particles = true | false | "membranes" */
    int which = 0;
    int pt = get(L, fidx, pidx, "particles");
    if (pt == LUA_TBOOLEAN) which = lua_toboolean(L, -1) ? 0 : 2;
    else if (pt == LUA_TSTRING && strcmp(lua_tostring(L, -1), "membranes") == 0) which = 1;
    else if (pt != LUA_TNIL)
        luaL_error(L, "%s: 'particles' must be true, false or \"membranes\"", ctx->fn);
    lua_pop(L, 1);
    o.grid = grid;
    o.f = f;
    o.normals = with_normals;
    o.contour_levels = nlevels;
    o.pts.which = which;
    fill_side(L, ctx, ls, &o, p, &p->side[0]);
    if (other)
        fill_side(L, ctx, lother, &o, p, &p->side[1]);
}
