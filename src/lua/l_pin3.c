/* l_pin3.c - body:pin{...} of a 3D body and the pin handle (the 2D names,
 * l_pin.c, with three components; the engine's form is sim3_pin.c):
 *
 *   local clamp = bar:pin{ points = function(x, y, z) return x < 0.1 end }
 *   local lid   = block:pin{ points = "all", velocity = function(t) return 0, 0, -0.1 * t end }
 *   print(clamp:reaction())                                   -- fx, fy, fz
 *
 * A velocity function is called once per step with the middle of the step,
 * t + dt/2, between steps (la_pins3_update). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "l_sim3.h"

#define LA_PIN3 "lamina.pin3"

typedef struct la_pin3 { int index; } la_pin3;

/* The velocity function at fidx called at t: three finite numbers. */
static void call_velocity3(lua_State *L, int fidx, double t, double v[3])
{
    lua_pushvalue(L, fidx);
    lua_pushnumber(L, t);
    lua_call(L, 1, 3);
    for (int a = 0; a < 3; a++) {
        int ok;
        v[a] = lua_tonumberx(L, a - 3, &ok);
        if (!ok || !isfinite(v[a]))
            luaL_error(L, "body:pin: the velocity function must return three finite numbers "
                       "vx, vy, vz (at t = %f)", t);
    }
    lua_pop(L, 3);
}

void la_pins3_update(lua_State *L, int sidx, la_sim *s)
{
    lm3_sim *sim = s->s3->sim;
    if (s->npinf > 0) {
        sidx = lua_absindex(L, sidx);
        lua_getiuservalue(L, sidx, 1);
        for (int k = 0; k < s->npinf; k++) {
            lua_rawgeti(L, -1, s->pinf[k].ref);
            double v[3];
            call_velocity3(L, lua_gettop(L), sim->t + 0.5 * sim->def.dt, v);
            lua_pop(L, 1);
            lm3_pin_set_velocity(sim, s->pinf[k].pin, v);   /* its own pin: exists */
        }
        lua_pop(L, 1);
    }
    lm3_pins_begin(sim);
}

/* body:pin{points, velocity} on the 3D body at 1 (first, n: its range). */
int la_body3_pin(lua_State *L, la_sim3 *s3, size_t first, size_t n)
{
    static const char *const keys[] = {"points", "velocity", NULL};
    const char *fn = "body:pin";
    la_check_keys(L, 2, fn, keys);
    lua_getiuservalue(L, 1, 1);
    int sidx = lua_gettop(L);
    la_sim *s = la_check_sim_any(L, sidx);
    if (s->running) return luaL_error(L, "%s: pins are added before a run", fn);
    lm3_sim *sim = s3->sim;
    size_t *idx = lua_newuserdatauv(L, (n ? n : 1) * sizeof *idx, 0);
    size_t k = 0;
    int t = la_getfield(L, 2, "points");
    if (t == LUA_TSTRING) {
        const char *p = lua_tostring(L, -1);
        if (strcmp(p, "ends") == 0)
            return luaL_error(L, "%s: points = \"ends\" is a membrane's; a 3D solid takes "
                              "\"all\", a list of indices or a function(x, y, z)", fn);
        if (strcmp(p, "all") != 0)
            return luaL_error(L, "%s: points = \"%s\" is not one of \"all\", a list of indices "
                              "or a function(x, y, z)", fn, p);
        for (size_t q = 0; q < n; q++) idx[k++] = first + q;
    } else if (t == LUA_TTABLE) {
        lua_Integer len = (lua_Integer)lua_rawlen(L, -1);
        if (len < 1 || (lua_Unsigned)len > n)
            return luaL_error(L, "%s: points must list 1 to %d indices (got %d)", fn, (int)n,
                              (int)len);
        for (lua_Integer i = 1; i <= len; i++) {
            lua_rawgeti(L, -1, i);
            int ok;
            lua_Integer v = lua_tointegerx(L, -1, &ok);
            if (!ok || v < 1 || (lua_Unsigned)v > n)
                return luaL_error(L, "%s: points[%d] must be a whole number from 1 to %d", fn,
                                  (int)i, (int)n);
            lua_pop(L, 1);
            idx[k++] = first + (size_t)(v - 1);
        }
    } else if (t == LUA_TFUNCTION) {
        int f = lua_gettop(L);
        for (size_t q = 0; q < n; q++) {
            lua_pushvalue(L, f);
            for (int a = 0; a < 3; a++) lua_pushnumber(L, sim->p.x[a][first + q]);
            lua_call(L, 3, 1);
            if (lua_toboolean(L, -1)) idx[k++] = first + q;
            lua_pop(L, 1);
        }
        if (k == 0) return luaL_error(L, "%s: the function holds no point of the body", fn);
    } else {
        return luaL_error(L, "%s: 'points' must be \"all\", a list of indices or a function(x, "
                          "y, z) -> boolean (got %s)", fn, luaL_typename(L, -1));
    }
    lua_pop(L, 1);
    double v[3] = {0, 0, 0};
    int vf = 0;
    if (la_getfield(L, 2, "velocity") == LUA_TFUNCTION) {
        vf = lua_gettop(L);
        call_velocity3(L, vf, sim->t + 0.5 * sim->def.dt, v);   /* checked now */
    } else {
        lua_pop(L, 1);
        la_triple(L, 2, fn, "velocity", v);
    }
    int pi = lm3_pin_add(sim, idx, k, v);
    if (pi < 0) return luaL_error(L, "%s: %s", fn, sim->err);
    if (vf) la_sim_add_pin_function(L, sidx, pi, vf);
    la_pin3 *h = lua_newuserdatauv(L, sizeof *h, 1);
    h->index = pi;
    luaL_setmetatable(L, LA_PIN3);
    lua_pushvalue(L, sidx);
    lua_setiuservalue(L, -2, 1);
    return 1;
}

static const lm3_pin *check_pin3(lua_State *L)
{
    la_pin3 *h = luaL_checkudata(L, 1, LA_PIN3);
    lua_getiuservalue(L, 1, 1);
    la_sim3 *s3 = la_check_sim3(L, -1, "pin");
    lua_pop(L, 1);
    return &s3->sim->pins->pin[h->index];
}

/* pin:reaction() -> fx, fy, fz: the force the pin exerted on the material
 * in the last step (0 before the first). */
static int pin3_reaction(lua_State *L)
{
    const lm3_pin *p = check_pin3(L);
    for (int a = 0; a < 3; a++) lua_pushnumber(L, p->reaction[a]);
    return 3;
}

static int pin3_len(lua_State *L)
{
    lua_pushinteger(L, (lua_Integer)check_pin3(L)->n);
    return 1;
}

static int pin3_tostring(lua_State *L)
{
    la_pin3 *h = luaL_checkudata(L, 1, LA_PIN3);
    return la_push_handle_name(L, "lamina.pin", h->index + 1);
}

void la_open_pin3(lua_State *L)
{
    static const luaL_Reg meta[] = {{"__len", pin3_len}, {"__tostring", pin3_tostring},
                                    {NULL, NULL}};
    static const luaL_Reg methods[] = {{"reaction", pin3_reaction}, {NULL, NULL}};
    la_new_class(L, LA_PIN3, meta, methods);
    lua_pop(L, 1);
}
