/* l_pin_common.c - body:pin's reading of `points` and of a velocity
 * function and the driven pins' loop, for both dimensions
 * (l_pin_common.h; l_pin.c and l_pin3.c hold each one's engine calls). */
#include <math.h>
#include <string.h>

#include "l_pin_common.h"

/* The list's and the string's cases; tables are read raw (no metamethods,
 * as la_getfield: l_args.c). */
size_t *la_pin_points_read(lua_State *L, int idx, const la_pin_points *pp, size_t *n)
{
    const char *fn = pp->fn;
    const size_t count = pp->count;
    size_t *out = lua_newuserdatauv(L, (count ? count : 1) * sizeof *out, 0);
    size_t k = 0;
    int t = la_getfield(L, idx, "points");
    if (t == LUA_TSTRING) {
        const char *s = lua_tostring(L, -1);
        if (strcmp(s, "all") == 0) {
            for (size_t q = 0; q < count; q++) out[k++] = pp->first + q;
        } else if (strcmp(s, "ends") == 0) {
            if (pp->ends_refused) luaL_error(L, "%s: points = \"ends\" %s", fn, pp->ends_refused);
            out[k++] = pp->first;
            if (count > 1) out[k++] = pp->first + count - 1;
        } else {
            luaL_error(L, "%s: points = \"%s\" is not one of %s, a list of indices or a "
                       "function(%s)", fn, s, pp->choices, pp->args);
        }
    } else if (t == LUA_TTABLE) {
        lua_Integer len = (lua_Integer)lua_rawlen(L, -1);
        if (len < 1 || (lua_Unsigned)len > count)
            luaL_error(L, "%s: points must list 1 to %d indices (got %d)", fn, (int)count,
                       (int)len);
        for (lua_Integer i = 1; i <= len; i++) {
            lua_rawgeti(L, -1, i);
            int ok;
            lua_Integer v = lua_tointegerx(L, -1, &ok);
            if (!ok || v < 1 || (lua_Unsigned)v > count)
                luaL_error(L, "%s: points[%d] must be a whole number from 1 to %d", fn, (int)i,
                           (int)count);
            lua_pop(L, 1);
            out[k++] = pp->first + (size_t)(v - 1);
        }
    } else if (t == LUA_TFUNCTION) {
        /* the function is the script's: push_point reads the coordinates
         * afresh for every call, and moved() refuses a changed body */
        int f = lua_gettop(L);
        for (size_t q = 0; q < count; q++) {
            lua_pushvalue(L, f);
            lua_call(L, pp->push_point(L, pp->ctx, q), 1);
            if (lua_toboolean(L, -1)) out[k++] = pp->first + q;
            lua_pop(L, 1);
            if (pp->moved && pp->moved(pp->ctx))
                luaL_error(L, "%s: the points function changed the body's points", fn);
        }
        if (k == 0) luaL_error(L, "%s: %s", fn, pp->none_chosen);
    } else {
        luaL_error(L, "%s: 'points' must be %s, a list of indices or a function(%s) -> boolean "
                   "(got %s)", fn, pp->choices, pp->args, luaL_typename(L, -1));
    }
    lua_pop(L, 1);
    *n = k;
    return out;
}

int la_pin_velocity_call(lua_State *L, int fidx, double t, int n, double *v)
{
    lua_pushvalue(L, fidx);
    lua_pushnumber(L, t);
    lua_call(L, 1, n);
    int ok = 1;
    for (int a = 0; a < n; a++) {
        int num;
        v[a] = lua_tonumberx(L, a - n, &num);
        ok = ok && num && isfinite(v[a]);
    }
    lua_pop(L, n);
    return ok;
}

void la_pins_drive(lua_State *L, int sidx, la_sim *s,
                   void (*drive)(lua_State *L, la_sim *s, int pin, int fidx))
{
    if (s->npinf == 0) return;
    sidx = lua_absindex(L, sidx);
    lua_getiuservalue(L, sidx, 1);
    for (int k = 0; k < s->npinf; k++) {
        lua_rawgeti(L, -1, s->pinf[k].ref);
        drive(L, s, s->pinf[k].pin, lua_gettop(L));
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
}
