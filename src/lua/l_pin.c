/* l_pin.c - body:pin{...}: hold points of a body or membrane fixed, or
 * drive them at a prescribed velocity (pin.c), and read the reaction.
 *
 *   local ends = sheet:pin{ points = "ends" }             -- held at rest
 *   local lid  = block:pin{ points = function(x, y) return y > 0.9 end,
 *                           velocity = function(t) return 0.1 * t, 0 end }
 *   print(ends:reaction())                                -- fx, fy
 *
 * A velocity function is called once per step with the middle of the step,
 * t + dt/2 (the midpoint rule for the displacement), between steps. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "l_internal.h"

#define LA_PIN "lamina.pin"

typedef struct la_pin {
    int index;        /* the engine's pin */
} la_pin;

/* The points as 0-based indices within the body: "all", "ends" (a
 * membrane's first and last point), a list of 1-based indices, or a
 * function(x, y) -> boolean. Returns a malloc'd array (kept as userdata
 * on the stack so that an error frees it). */
static size_t *read_points(lua_State *L, const lm_sim *sim, int b, size_t *n)
{
    const char *fn = "body:pin";
    const lm_body *bd = &sim->bodies[b];
    size_t *idx = lua_newuserdatauv(L, (bd->count ? bd->count : 1) * sizeof *idx, 0);
    size_t k = 0;
    int t = la_getfield(L, 2, "points");
    if (t == LUA_TSTRING) {
        const char *s = lua_tostring(L, -1);
        if (strcmp(s, "all") == 0) {
            for (size_t q = 0; q < bd->count; q++) idx[k++] = q;
        } else if (strcmp(s, "ends") == 0) {
            if (!bd->membrane || bd->closed)
                luaL_error(L, "%s: points = \"ends\" needs an open membrane", fn);
            idx[k++] = 0;
            if (bd->count > 1) idx[k++] = bd->count - 1;
        } else {
            luaL_error(L, "%s: points = \"%s\" is not one of \"all\", \"ends\", a list of "
                       "indices or a function(x, y)", fn, s);
        }
    } else if (t == LUA_TTABLE) {
        lua_Integer len = luaL_len(L, -1);
        if (len < 1 || (lua_Unsigned)len > bd->count)
            luaL_error(L, "%s: points must list 1 to %d indices (got %d)", fn,
                       (int)bd->count, (int)len);
        for (lua_Integer i = 1; i <= len; i++) {
            lua_geti(L, -1, i);
            int ok;
            lua_Integer v = lua_tointegerx(L, -1, &ok);
            if (!ok || v < 1 || (lua_Unsigned)v > bd->count)
                luaL_error(L, "%s: points[%d] must be a whole number from 1 to %d", fn,
                           (int)i, (int)bd->count);
            lua_pop(L, 1);
            idx[k++] = (size_t)(v - 1);
        }
    } else if (t == LUA_TFUNCTION) {
        /* the function is the script's: it may add a body (sim->bodies and
         * the particle arrays move: bd and sim->p.x dangled, issue 31) or
         * run the sim. So the body's range is copied, the arrays are read
         * afresh for every call, and a changed range is refused after. */
        int f = lua_gettop(L);
        const size_t first = bd->first, count = bd->count;
        for (size_t q = 0; q < count; q++) {
            lua_pushvalue(L, f);
            lua_pushnumber(L, sim->p.x[first + q]);
            lua_pushnumber(L, sim->p.y[first + q]);
            lua_call(L, 2, 1);
            if (lua_toboolean(L, -1)) idx[k++] = q;
            lua_pop(L, 1);
            if (sim->bodies[b].first != first || sim->bodies[b].count != count)
                luaL_error(L, "%s: the points function changed the body's points", fn);
        }
        if (k == 0) luaL_error(L, "%s: the points function chose no point", fn);
    } else {
        luaL_error(L, "%s: 'points' must be \"all\", \"ends\", a list of indices or a "
                   "function(x, y) -> boolean (got %s)", fn, luaL_typename(L, -1));
    }
    lua_pop(L, 1);
    *n = k;
    return idx;
}

/* velocity: {vx, vy} or a function(t) -> vx, vy; the two numbers. */
static void call_velocity(lua_State *L, int f, double t, double *vx, double *vy)
{
    if (!la_call_pair(L, f, t, vx, vy))
        luaL_error(L, "body:pin: the velocity function must return two finite numbers");
}

int la_body_pin(lua_State *L)
{
    static const char *const keys[] = {"points", "velocity", NULL};
    const char *fn = "body:pin";
    lm_sim *sim;
    int b = la_check_body(L, 1, &sim);
    la_check_keys(L, 2, fn, keys);
    lua_getiuservalue(L, 1, 1);
    int sidx = lua_gettop(L);
    la_sim *s = la_check_sim(L, sidx);
    if (s->running) return luaL_error(L, "%s: pins cannot be added during a run", fn);
    size_t n;
    size_t *idx = read_points(L, sim, b, &n);
    double vx = 0, vy = 0;
    int fidx = 0;
    int vt = la_getfield(L, 2, "velocity");
    if (vt == LUA_TFUNCTION) {
        fidx = lua_gettop(L);
        call_velocity(L, fidx, sim->t + 0.5 * sim->def.dt, &vx, &vy);
    } else {
        lua_pop(L, 1);
        if (vt != LUA_TNIL) la_pair(L, 2, fn, "velocity", &vx, &vy);
        if (!isfinite(vx) || !isfinite(vy))
            return luaL_error(L, "%s: velocity must be finite", fn);
    }
    int pin = lm_sim_add_pin(sim, b, idx, n, vx, vy);
    if (pin < 0) return luaL_error(L, "%s: %s", fn, sim->err);
    if (fidx) la_sim_add_pin_function(L, sidx, pin, fidx);
    la_pin *h = lua_newuserdatauv(L, sizeof *h, 1);
    h->index = pin;
    luaL_setmetatable(L, LA_PIN);
    lua_pushvalue(L, sidx);
    lua_setiuservalue(L, -2, 1);
    return 1;
}

/* Before each step: the driven pins' velocities at the middle of the step. */
void la_pins_update(lua_State *L, int sidx, la_sim *s)
{
    if (s->npinf == 0) return;
    sidx = lua_absindex(L, sidx);
    lua_getiuservalue(L, sidx, 1);
    for (int k = 0; k < s->npinf; k++) {
        lua_rawgeti(L, -1, s->pinf[k].ref);
        double vx, vy;
        call_velocity(L, lua_gettop(L), s->sim->t + 0.5 * s->sim->def.dt, &vx, &vy);
        lua_pop(L, 1);
        lm_sim_set_pin_velocity(s->sim, s->pinf[k].pin, vx, vy);
    }
    lua_pop(L, 1);
}

/* pin:reaction() -> fx, fy: the force the pin exerted on the material in
 * the last step (per unit depth; 0, 0 before the first step). */
static int pin_reaction(lua_State *L)
{
    la_pin *h = luaL_checkudata(L, 1, LA_PIN);
    lua_getiuservalue(L, 1, 1);
    lm_sim *sim = la_check_sim(L, -1)->sim;
    const lm_pin *pn = &sim->pins[h->index];
    lua_pushnumber(L, pn->rx);
    lua_pushnumber(L, pn->ry);
    return 2;
}

static int pin_len(lua_State *L)
{
    la_pin *h = luaL_checkudata(L, 1, LA_PIN);
    lua_getiuservalue(L, 1, 1);
    lm_sim *sim = la_check_sim(L, -1)->sim;
    lua_pushinteger(L, (lua_Integer)sim->pins[h->index].n);
    return 1;
}

static int pin_tostring(lua_State *L)
{
    return la_push_handle_name(L, LA_PIN, ((la_pin *)luaL_checkudata(L, 1, LA_PIN))->index);
}

void la_open_pin(lua_State *L)
{
    static const luaL_Reg meta[] = {{"__len", pin_len}, {"__tostring", pin_tostring},
                                    {NULL, NULL}};
    static const luaL_Reg methods[] = {{"reaction", pin_reaction}, {NULL, NULL}};
    la_new_class(L, LA_PIN, meta, methods);
    lua_pushliteral(L, "lamina.pin");
    lua_setfield(L, -2, "__metatable");
    lua_pop(L, 1);
}
