/* l_args.c - reading constructor tables with named errors. */
#include <math.h>
#include <string.h>

#include "l_internal.h"

/* Arguments are read raw: a metatable on a script's table (an __index
 * function) would otherwise run script code in the middle of a read and hand
 * back values that nothing references (a string made by the function is
 * collected once popped). Raw, every value read is held by its table, which
 * no script code can change while a binding reads it (l_sandbox.c: no
 * __gc). Non-tables (userdata) keep their metamethods. */
int la_getfield(lua_State *L, int idx, const char *key)
{
    if (lua_type(L, idx) != LUA_TTABLE) return lua_getfield(L, idx, key);
    idx = lua_absindex(L, idx);
    lua_pushstring(L, key);
    return lua_rawget(L, idx);
}

void la_check_table(lua_State *L, int idx, const char *fn)
{
    if (lua_type(L, idx) != LUA_TTABLE)
        luaL_error(L, "%s expects one table of named arguments, e.g. %s{...} (got %s)",
                   fn, fn, luaL_typename(L, idx));
}

void la_check_keys(lua_State *L, int idx, const char *fn, const char *const keys[])
{
    idx = lua_absindex(L, idx);
    la_check_table(L, idx, fn);
    lua_pushnil(L);
    while (lua_next(L, idx)) {
        lua_pop(L, 1);
        if (lua_type(L, -1) != LUA_TSTRING)
            luaL_error(L, "%s: unexpected positional argument (use named keys)", fn);
        const char *k = lua_tostring(L, -1);
        int ok = 0;
        for (int i = 0; keys[i]; i++)
            if (strcmp(k, keys[i]) == 0) ok = 1;
        if (!ok) {
            luaL_Buffer b;
            luaL_buffinit(L, &b);
            for (int i = 0; keys[i]; i++) {
                if (i) luaL_addstring(&b, ", ");
                luaL_addstring(&b, keys[i]);
            }
            luaL_pushresult(&b);
            luaL_error(L, "%s: unknown key '%s' (known keys: %s)", fn, k,
                       lua_tostring(L, -1));
        }
    }
}

int la_has(lua_State *L, int idx, const char *key)
{
    int t = la_getfield(L, idx, key);
    lua_pop(L, 1);
    return t != LUA_TNIL;
}

double la_opt_number(lua_State *L, int idx, const char *fn, const char *key, double def)
{
    int t = la_getfield(L, idx, key);
    double v = def;
    if (t != LUA_TNIL) {
        int isnum;
        v = lua_tonumberx(L, -1, &isnum);
        if (!isnum)
            luaL_error(L, "%s: '%s' must be a number (got %s)", fn, key,
                       luaL_typename(L, -1));
    }
    lua_pop(L, 1);
    return v;
}

double la_number(lua_State *L, int idx, const char *fn, const char *key)
{
    if (!la_has(L, idx, key)) luaL_error(L, "%s: '%s' is required", fn, key);
    return la_opt_number(L, idx, fn, key, 0);
}

const char *la_opt_string(lua_State *L, int idx, const char *fn, const char *key,
                          const char *def)
{
    int t = la_getfield(L, idx, key);
    const char *s = def;
    if (t != LUA_TNIL) {
        if (t != LUA_TSTRING)
            luaL_error(L, "%s: '%s' must be a string (got %s)", fn, key,
                       luaL_typename(L, -1));
        s = lua_tostring(L, -1);
    }
    lua_pop(L, 1);   /* the string stays alive: it is referenced by the table */
    return s;
}

int la_opt_velocity(lua_State *L, int idx, const char *fn, double *vx, double *vy)
{
    int vt = la_getfield(L, idx, "velocity");
    if (vt == LUA_TFUNCTION) return lua_gettop(L);
    lua_pop(L, 1);
    if (vt != LUA_TNIL) la_pair(L, idx, fn, "velocity", vx, vy);
    return 0;
}

void la_pair(lua_State *L, int idx, const char *fn, const char *key, double *a, double *b)
{
    la_getfield(L, idx, key);
    if (!lua_istable(L, -1) || lua_rawlen(L, -1) != 2)
        luaL_error(L, "%s: '%s' must be a pair {a, b}", fn, key);
    for (int i = 1; i <= 2; i++) {
        lua_rawgeti(L, -1, i);
        int isnum;
        double v = lua_tonumberx(L, -1, &isnum);
        if (!isnum) luaL_error(L, "%s: '%s'[%d] must be a number", fn, key, i);
        *(i == 1 ? a : b) = v;
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    /* no pair of lamina's means anything with NaN or infinity in it (a
     * velocity {1, 0/0} made every position NaN a step later, and was
     * blamed on the time step) */
    if (!isfinite(*a) || !isfinite(*b))
        luaL_error(L, "%s: '%s' must be two finite numbers (got {%f, %f})", fn, key, *a, *b);
}

int la_option(lua_State *L, const char *fn, const char *key, const char *value,
              const char *const names[])
{
    for (int i = 0; names[i]; i++)
        if (strcmp(value, names[i]) == 0) return i;
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    for (int i = 0; names[i]; i++) {
        if (i) luaL_addstring(&b, " | ");
        luaL_addchar(&b, '"');
        luaL_addstring(&b, names[i]);
        luaL_addchar(&b, '"');
    }
    luaL_pushresult(&b);
    return luaL_error(L, "%s: %s = \"%s\" is not one of %s", fn, key, value,
                      lua_tostring(L, -1));
}

int la_point_list(lua_State *L, const char *fn, int min, int *n)
{
    static const char *const keys[] = {"points", NULL};
    la_check_table(L, 1, fn);
    int list = 1;
    if (lua_rawlen(L, 1) == 0) {
        la_check_keys(L, 1, fn, keys);
        la_getfield(L, 1, "points");
        if (!lua_istable(L, -1)) luaL_error(L, "%s: 'points' must be a list of {x, y}", fn);
        list = lua_gettop(L);
    }
    *n = (int)lua_rawlen(L, list);
    if (*n < min) luaL_error(L, "%s: needs at least %d points (got %d)", fn, min, *n);
    return list;
}

void la_point_at(lua_State *L, int list, int i, const char *fn, double *x, double *y)
{
    lua_rawgeti(L, list, i + 1);
    if (!lua_istable(L, -1) || lua_rawlen(L, -1) != 2)
        luaL_error(L, "%s: point %d must be {x, y}", fn, i + 1);
    lua_rawgeti(L, -1, 1);
    lua_rawgeti(L, -2, 2);
    int okx, oky;
    *x = lua_tonumberx(L, -2, &okx);
    *y = lua_tonumberx(L, -1, &oky);
    if (!okx || !oky) luaL_error(L, "%s: point %d must be two numbers", fn, i + 1);
    lua_pop(L, 3);
}

lamina_run *la_run(lua_State *L)
{
    lua_getfield(L, LUA_REGISTRYINDEX, "lamina.run");
    lamina_run *run = lua_touserdata(L, -1);
    lua_pop(L, 1);
    return run;
}

/* Every lamina object's metatable: getmetatable() gives this string and
 * setmetatable() fails ("cannot change a protected metatable"), so a script
 * reaches neither __gc nor __index (docs/design.md: a script is untrusted). */
int la_call_pair(lua_State *L, int idx, double arg, double *a, double *b)
{
    lua_pushvalue(L, idx);
    lua_pushnumber(L, arg);
    lua_call(L, 1, 2);
    int oka, okb;
    *a = lua_tonumberx(L, -2, &oka);
    *b = lua_tonumberx(L, -1, &okb);
    lua_pop(L, 2);
    return oka && okb && isfinite(*a) && isfinite(*b);
}

int la_new_metatable(lua_State *L, const char *name)
{
    int fresh = luaL_newmetatable(L, name);
    lua_pushliteral(L, "locked");
    lua_setfield(L, -2, "__metatable");
    return fresh;
}

void la_new_class(lua_State *L, const char *name, const luaL_Reg *meta,
                  const luaL_Reg *methods)
{
    la_new_class_in(L, name, meta, methods, "__index");
}

void la_new_class_in(lua_State *L, const char *name, const luaL_Reg *meta,
                     const luaL_Reg *methods, const char *field)
{
    la_new_metatable(L, name);
    luaL_setfuncs(L, meta, 0);
    lua_newtable(L);
    luaL_setfuncs(L, methods, 0);
    lua_setfield(L, -2, field);
}

int la_push_handle_name(lua_State *L, const char *name, int index)
{
    lua_pushfstring(L, "%s %d", name, index + 1);
    return 1;
}
