/* l_body.c - sim:body{...}: a region of one material filled with particles,
 * and the body handle (com, velocity, particles). */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fields.h"
#include "l_body_common.h"
#include "l_internal.h"

typedef struct la_body { int index; } la_body;

/* The body and, through its uservalue, the simulation it lives in: a body
 * handle keeps its simulation alive (l_body_common.c). */
static la_body check_body(lua_State *L, int idx, lm_sim **sim)
{
    la_body b = {la_handle_check(L, idx, LA_BODY)};
    *sim = la_check_sim(L, -1)->sim;
    lua_pop(L, 1);
    return b;
}

/* ppc = n (a square: 4 = 2x2, 16 = 4x4, as the papers count) or {nx, ny}:
 * what the script wrote, read here; the engine checks the pattern's limits
 * (LM_MAX_PPC, LM_MAX_TRIALS: body_create.c). A number over the limit is
 * named as written before it is asked to be a square. */
static void read_ppc(lua_State *L, const char *fn, int *npx, int *npy)
{
    int t = la_getfield(L, 2, "ppc");
    lua_pop(L, 1);
    if (t == LUA_TNIL) {
        *npx = *npy = 2;
    } else if (t == LUA_TTABLE) {
        double a, b;
        la_pair(L, 2, fn, "ppc", &a, &b);
        if (a < 1 || b < 1 || a != floor(a) || b != floor(b) || a > INT_MAX || b > INT_MAX)
            luaL_error(L, "%s: ppc = {%f, %f} must be two positive integers", fn, a, b);
        *npx = (int)a;
        *npy = (int)b;
    } else {
        double n = la_number(L, 2, fn, "ppc");
        double r = floor(sqrt(n) + 0.5);
        if (n > LM_MAX_PPC) {
            char m[48];
            snprintf(m, sizeof m, "ppc = %g", n);
            luaL_error(L, "%s: %s is more than the limit of %d points per cell", fn, m,
                       LM_MAX_PPC);
        }
        if (n < 1 || r * r != n)
            luaL_error(L, "%s: ppc = %s is not a square number (1, 4, 9, 16, ...); "
                       "use ppc = {nx, ny} for other patterns", fn,
                       (la_getfield(L, 2, "ppc"), lua_tostring(L, -1)));
        *npx = *npy = (int)r;
    }
}

/* The script's region and velocity functions as the engine's callbacks
 * (lm_body_def): each called protected; an error stays on the stack, the
 * callback returns -1, the engine takes the body out again and sim:body
 * raises that error, so a script that catches it with pcall runs on
 * without half a body. */
typedef struct fill_ctx { lua_State *L; int ridx, vidx; } fill_ctx;

static int region_fn(void *ctx, double x, double y)
{
    fill_ctx *c = ctx;
    if (la_body_call(c->L, c->ridx, (const double[]){x, y}, 2, 1)) return -1;
    int in = lua_toboolean(c->L, -1);
    lua_pop(c->L, 1);
    return in;
}

/* fill = "centres" (the papers' rule) or "clipped" (seed.c). */
static int read_fill(lua_State *L, const char *fn)
{
    static const char *const fills[] = {"centres", "clipped", NULL};
    la_getfield(L, 2, "fill");
    int clipped = 0;
    if (!lua_isnil(L, -1)) {
        const char *f = lua_tostring(L, -1);
        int k = -1;
        for (int i = 0; f && fills[i]; i++)
            if (strcmp(f, fills[i]) == 0) k = i;
        if (k < 0 || lua_type(L, -1) != LUA_TSTRING)
            luaL_error(L, "%s: 'fill' must be \"centres\" or \"clipped\" (got %s)", fn,
                       f ? f : luaL_typename(L, -1));
        clipped = k == 1;
    }
    lua_pop(L, 1);
    return clipped;
}

/* velocity = a function (x, y) -> vx, vy. */
static int velocity_fn(void *ctx, double x, double y, double *vx, double *vy)
{
    fill_ctx *c = ctx;
    lua_State *L = c->L;
    if (la_body_call(L, c->vidx, (const double[]){x, y}, 2, 2)) return -1;
    int ok1, ok2;
    *vx = lua_tonumberx(L, -2, &ok1);
    *vy = lua_tonumberx(L, -1, &ok2);
    if (!ok1 || !ok2 || !isfinite(*vx) || !isfinite(*vy)) {
        const char *a = luaL_tolstring(L, -2, NULL), *b = luaL_tolstring(L, -2, NULL);
        lua_pushfstring(L, "sim:body: the velocity function must return two finite numbers "
                        "(got %s, %s at (%f, %f))", a, b, x, y);
        return -1;
    }
    lua_pop(L, 2);
    return 0;
}

int la_sim_body(lua_State *L)
{
    static const char *const keys[] = {"material", "region", "ppc", "velocity", "name",
                                       "fill", NULL};
    const char *fn = "sim:body";
    la_sim *s = la_check_sim(L, 1);
    int midx = la_body_args(L, s, fn, keys);   /* the material, the region above it */
    lm_sim *sim = s->sim;
    int ridx = midx + 1;
    lm_region *region = la_test_region(L, ridx);
    if (!region && !lua_isfunction(L, ridx))
        return luaL_error(L, "%s: 'region' must be lamina.disk/rect/polygon or a "
                          "function(x, y) -> boolean (got %s)", fn, luaL_typename(L, ridx));

    int npx, npy;
    read_ppc(L, fn, &npx, &npy);
    int clipped = read_fill(L, fn);
    double vx0 = 0, vy0 = 0;
    int vidx = la_opt_velocity(L, 2, fn, &vx0, &vy0);

    /* the engine checks the body (body_create.c: the material's kind, the
     * pattern's limits, the axisymmetric gas's rules, an empty region) */
    lm_body_def def;
    lm_body_def_default(&def);
    def.mat = la_sim_material(L, 1, midx, fn);   /* the engine's copy */
    fill_ctx fc = { L, ridx, vidx };
    def.region = region;
    def.inside = region ? NULL : region_fn;
    def.npx = npx;
    def.npy = npy;
    def.clipped = clipped;
    def.vx = vx0;
    def.vy = vy0;
    def.velocity = vidx ? velocity_fn : NULL;
    def.ctx = &fc;
    int top = lua_gettop(L);
    int bi = lm_sim_create_body(sim, &def);
    if (bi < 0) {
        if (lua_gettop(L) > top) return lua_error(L);   /* the script's function's error */
        return luaL_error(L, "%s: %s", fn, sim->err);
    }
    la_getfield(L, 2, "name");
    la_push_body(L, 1, bi, lua_gettop(L));
    return 1;
}

void la_push_body(lua_State *L, int sidx, int bi, int nameidx)
{
    sidx = lua_absindex(L, sidx);
    if (nameidx) nameidx = lua_absindex(L, nameidx);
    la_body_handle_push(L, LA_BODY, sidx, bi, nameidx);
    if (nameidx && lua_type(L, nameidx) == LUA_TSTRING)   /* for the engine's messages */
        lm_sim_set_body_name(la_check_sim(L, sidx)->sim, bi, lua_tostring(L, nameidx));
}

int la_check_body(lua_State *L, int idx, lm_sim **sim)
{
    return check_body(L, idx, sim).index;
}

/* body:com() and body:velocity(): a pair of the engine's body sums. */
static int body_pair(lua_State *L, void (*of)(const lm_sim *, int, double *, double *))
{
    lm_sim *sim;
    la_body b = check_body(L, 1, &sim);
    double x, y;
    of(sim, b.index, &x, &y);
    lua_pushnumber(L, x);
    lua_pushnumber(L, y);
    return 2;
}

static int body_com(lua_State *L) { return body_pair(L, lm_body_com); }
static int body_velocity(lua_State *L) { return body_pair(L, lm_body_velocity); }

static int body_mass(lua_State *L)
{
    lm_sim *sim;
    la_body b = check_body(L, 1, &sim);
    lua_pushnumber(L, lm_body_mass(sim, b.index));
    return 1;
}

/* body:energy() - this body's share of sim:energy(). */
static int body_energy(lua_State *L)
{
    lm_sim *sim;
    la_body b = check_body(L, 1, &sim);
    la_push_energy(L, lm_body_energy(sim, b.index));
    return 1;
}

static void center_arg(lua_State *L, int idx, double *cx, double *cy);

/* A membrane's handle at idx, or an error naming the method. */
static la_body check_membrane(lua_State *L, int idx, lm_sim **sim, const char *method)
{
    la_body b = check_body(L, idx, sim);
    if (!(*sim)->bodies[b.index].membrane)
        luaL_error(L, "body:%s(): the body is not a membrane", method);
    return b;
}

/* gas:pressure() - the mean over the space the gas fills: the nodal
 * pressure at the nodes wholly in it (diag_gas.c), and how many nodes;
 * gas:pressure("particles") - the mass-weighted mean over the particles
 * (without q), whose continuity densities drift from their spacing;
 * gas:pressure(membrane [, {cx, cy}]) - the mean over the space the
 * membrane encloses, sum_p V_p p_p / A (docs/decisions.md); axisymmetric:
 * over its volume per radian, as V_p is. */
static int body_pressure(lua_State *L)
{
    lm_sim *sim, *sim2;
    la_body b = check_body(L, 1, &sim);
    if (sim->mats[sim->bodies[b.index].mat]->kind != LM_GAS)
        return luaL_error(L, "body:pressure(): the body is not a gas");
    if (lua_isnoneornil(L, 2)) {
        size_t nodes;
        double pr = lm_gas_space_pressure(sim, b.index, &nodes);
        if (isnan(pr)) return luaL_error(L, "gas:pressure(): out of memory");
        lua_pushnumber(L, pr);
        lua_pushinteger(L, (lua_Integer)nodes);
        return 2;
    }
    if (lua_type(L, 2) == LUA_TSTRING) {
        if (strcmp(lua_tostring(L, 2), "particles") != 0)
            return luaL_error(L, "gas:pressure('%s'): unknown option (the one known is "
                              "\"particles\")", lua_tostring(L, 2));
        lua_pushnumber(L, lm_body_mean_pressure(sim, b.index));
        return 1;
    }
    int m = la_check_body(L, 2, &sim2);
    if (sim != sim2 || !sim->bodies[m].membrane)
        return luaL_error(L, "gas:pressure(membrane): needs a membrane of the same sim");
    double cx, cy;
    center_arg(L, 3, &cx, &cy);
    double a = lm_membrane_enclosed_volume(sim, m, cx, cy);
    if (!(a > 0))
        return luaL_error(L, "gas:pressure(membrane): the membrane encloses no area");
    lua_pushnumber(L, lm_body_pressure_integral(sim, b.index) / a);
    return 1;
}

/* membrane:hoop_stress() - the mean tangential stress sigma_t. */
static int body_hoop_stress(lua_State *L)
{
    lm_sim *sim;
    la_body b = check_membrane(L, 1, &sim, "hoop_stress");
    lua_pushnumber(L, lm_body_mean_tangential_stress(sim, b.index));
    return 1;
}

static void center_arg(lua_State *L, int idx, double *cx, double *cy)
{
    *cx = *cy = 0;
    if (lua_isnoneornil(L, idx)) return;
    luaL_checktype(L, idx, LUA_TTABLE);
    lua_rawgeti(L, idx, 1);
    lua_rawgeti(L, idx, 2);
    *cx = luaL_checknumber(L, -2);
    *cy = luaL_checknumber(L, -1);
    lua_pop(L, 2);
}

/* membrane:radius_at(deg [, {cx, cy}]) - where the ray from the centre
 * (default the origin) at deg degrees meets the membrane; nil if it
 * misses. */
static int body_radius_at(lua_State *L)
{
    lm_sim *sim;
    la_body b = check_membrane(L, 1, &sim, "radius_at");
    double cx, cy;
    center_arg(L, 3, &cx, &cy);
    double r = lm_membrane_radius_at(sim, b.index, luaL_checknumber(L, 2), cx, cy);
    if (r < 0) lua_pushnil(L);
    else lua_pushnumber(L, r);
    return 1;
}

/* membrane:enclosed_area([{cx, cy}]) - the area of the membrane's polygon,
 * closed through the centre when open. */
static int body_enclosed_area(lua_State *L)
{
    lm_sim *sim;
    la_body b = check_membrane(L, 1, &sim, "enclosed_area");
    double cx, cy;
    center_arg(L, 2, &cx, &cy);
    lua_pushnumber(L, lm_membrane_enclosed_area(sim, b.index, cx, cy));
    return 1;
}

/* membrane:escaped(gas [, {cx, cy}]) - the gas particles outside the
 * membrane (closed through the centre when open: quarter models) by more
 * than a quarter cell, the deepest distance of any outside (length units),
 * and those outside within a quarter cell (skin-grazers). */
static int body_escaped(lua_State *L)
{
    lm_sim *sim, *sim2;
    la_body b = check_body(L, 1, &sim);
    int g = la_check_body(L, 2, &sim2);
    if (sim != sim2 || !sim->bodies[b.index].membrane ||
        sim->mats[sim->bodies[g].mat]->kind != LM_GAS)
        return luaL_error(L, "membrane:escaped(gas): needs a membrane and a gas of one sim");
    double cx, cy;
    center_arg(L, 3, &cx, &cy);
    lm_far far;
    if (lm_gas_far_side(sim, g, b.index, cx, cy, 0, 0.25 * fmin(sim->grid.hx, sim->grid.hy),
                        &far))
        return luaL_error(L, "membrane:escaped(gas): out of memory");
    lua_pushinteger(L, (lua_Integer)far.beyond);
    lua_pushnumber(L, far.depth);
    lua_pushinteger(L, (lua_Integer)far.within);
    return 3;
}

/* One component of a field over the body's particles, as key (and as
 * alias when it has one). */
static void push_field(lua_State *L, const lm_sim *sim, const lm_field *f, int comp,
                       size_t first, size_t n)
{
    lua_createtable(L, (int)n, 0);
    for (size_t i = 0; i < n; i++) {
        lua_pushnumber(L, lm_field_value(sim, f, comp, first + i));
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    if (f->ncomp == 1 && f->alias) {
        lua_pushvalue(L, -1);
        lua_setfield(L, -3, f->alias);
    }
    lua_setfield(L, -2, f->ncomp == 1 ? f->name : f->comp[comp]);
}

/* A table of arrays (docs/design.md): every field of the engine's table
 * (fields.c) the body's kind has, each component under its name (x, y,
 * vx, vy, mass, rho, the global Cauchy stress sxx, syy, szz, sxy, the
 * pressure, ...), and under the older key where it had one (p: a gas's
 * pressure; et: a membrane's strain), and n. */
static int body_particles(lua_State *L)
{
    lm_sim *sim;
    la_body b = check_body(L, 1, &sim);
    const lm_body *bd = &sim->bodies[b.index];
    size_t a = bd->first, n = bd->count;
    unsigned kind = 1u << sim->mats[bd->mat]->kind;
    lua_createtable(L, 0, 32);
    for (int i = 0; i < lm_field_count(); i++) {
        const lm_field *f = lm_field_get(i);
        for (int c = 0; (f->kinds & kind) && c < f->ncomp; c++)
            push_field(L, sim, f, c, a, n);
    }
    lua_pushinteger(L, (lua_Integer)n);
    lua_setfield(L, -2, "n");
    return 1;
}

static int body_index(lua_State *L)
{
    lm_sim *sim;
    la_body b = check_body(L, 1, &sim);
    const char *k = luaL_checkstring(L, 2);
    if (la_body_handle_field(L, b.index, k)) return 1;   /* name, index, a method */
    /* a membrane's force form, so a script can see which default it got */
    if (strcmp(k, "force") == 0 && sim->bodies[b.index].membrane) {
        lua_pushstring(L, sim->bodies[b.index].force == LM_MFORCE_SEGMENT ? "segment" : "point");
        return 1;
    }
    return luaL_error(L, "body has no field or method '%s'", k);
}

void la_open_body(lua_State *L)
{
    static const luaL_Reg meta[] = {{"__index", body_index},
                                    {"__len", la_body_len},
                                    {"__tostring", la_body_tostring},
                                    {NULL, NULL}};
    static const luaL_Reg methods[] = {{"com", body_com},
                                       {"velocity", body_velocity},
                                       {"mass", body_mass},
                                       {"particles", body_particles},
                                       {"pressure", body_pressure},
                                       {"energy", body_energy},
                                       {"hoop_stress", body_hoop_stress},
                                       {"radius_at", body_radius_at},
                                       {"escaped", body_escaped},
                                       {"enclosed_area", body_enclosed_area},
                                       {"pin", la_body_pin},
                                       {"phi", la_body_phi},
                                       {NULL, NULL}};
    la_new_class_in(L, LA_BODY, meta, methods, "methods");   /* body_index looks there */
    lua_pop(L, 1);
}
