/* l_param.c - lamina.param(name, default), and the values `lamina serve`'s
 * page changes while the script runs (docs/workbench.md, "lamina serve").
 *
 * A value changed live is kept in the registry (PARAM_LIVE: name -> text)
 * and wins over --set from then on; the script sees it the next time it
 * calls lamina.param (in a sim:every callback, say). The change goes through
 * the run log like the repl's (l_runlog.c), as "param.NAME = value". */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "l_internal.h"

#define PARAM_LIVE "lamina.param_live"   /* registry: name -> text set live */
#define PARAM_SEEN "lamina.param_seen"   /* registry: name -> the default */

/* The text v as the type of the default at didx, pushed; NULL and an error
 * message pushed instead when it does not convert. */
static int convert(lua_State *L, int didx, const char *name, const char *v, const char *how)
{
    switch (lua_type(L, didx)) {
    case LUA_TNUMBER:
        if (!lua_stringtonumber(L, v)) {
            lua_pushfstring(L, "%s %s=%s: a number is expected", how, name, v);
            return 0;
        }
        return 1;
    case LUA_TBOOLEAN:
        if (strcmp(v, "true") == 0) lua_pushboolean(L, 1);
        else if (strcmp(v, "false") == 0) lua_pushboolean(L, 0);
        else {
            lua_pushfstring(L, "%s %s=%s: true or false is expected", how, name, v);
            return 0;
        }
        return 1;
    case LUA_TSTRING:
        lua_pushstring(L, v);
        return 1;
    default:
        lua_pushfstring(L, "lamina.param('%s', ...): the default must be a number, boolean "
                        "or string", name);
        return 0;
    }
}

/* registry[key], a table made on first use, pushed */
static void registry_table(lua_State *L, const char *key)
{
    la_subtable(L, LUA_REGISTRYINDEX, key);
}

/* lamina.param(name, default): the value set live (lamina serve), else the
 * --set value when given, converted to the default's type, else the
 * default. */
int la_param(lua_State *L)
{
    const char *name = luaL_checkstring(L, 1);
    luaL_checkany(L, 2);
    lua_settop(L, 2);
    lamina_run *run = la_run(L);
    const char *v = NULL, *how = "--set";
    registry_table(L, PARAM_LIVE);
    if (la_getfield(L, 3, name) == LUA_TSTRING) {
        v = lua_tostring(L, 4);
        how = "lamina serve:";
    }
    for (int i = 0; !v && run && i < run->nsets; i++)
        if (strcmp(run->sets[i].name, name) == 0) {
            v = run->sets[i].value;
            run->sets[i].used = 1;
        }
    if (v) {
        if (!convert(L, 2, name, v, how)) {
            luaL_where(L, 1);   /* file:line of the call, as luaL_error gives */
            lua_insert(L, -2);
            lua_concat(L, 2);
            return lua_error(L);
        }
    } else {
        lua_pushvalue(L, 2);
    }
    int res = lua_gettop(L);
    if (run && run->observer) {
        /* the default's type is what a live change must convert to */
        registry_table(L, PARAM_SEEN);
        lua_pushvalue(L, 2);
        lua_setfield(L, -2, name);
        lua_pop(L, 1);
        if (run->observer->param) {
            const char *text = luaL_tolstring(L, res, NULL);
            run->observer->param(run->observer->ud, name, lua_type(L, 2), text);
            lua_pop(L, 1);
        }
    }
    lua_settop(L, res);
    return 1;
}

int lamina_set_param(lua_State *L, const char *name, const char *value, char *err,
                     size_t len)
{
    int top = lua_gettop(L);
    registry_table(L, PARAM_SEEN);
    if (la_getfield(L, -1, name) == LUA_TNIL) {
        snprintf(err, len, "the script has not read the parameter '%s' "
                 "(lamina.param('%s', ...))", name, name);
        lua_settop(L, top);
        return -1;
    }
    int didx = lua_gettop(L);
    if (!convert(L, didx, name, value, "lamina serve:")) {
        snprintf(err, len, "%s", lua_tostring(L, -1));
        lua_settop(L, top);
        return -1;
    }
    registry_table(L, PARAM_LIVE);
    lua_pushstring(L, value);
    lua_setfield(L, -2, name);
    lua_pop(L, 1);
    la_log_change(L, "param", name, -1);   /* the converted value: as it replays */
    lua_settop(L, top);
    return 0;
}

const char *const lamina_live_settings[] = {"dt", "gravity", "pic", "courant", "damping", NULL};

/* sim[key] = value, under lua_pcall: sim, key, value are arguments 1-3 */
static int assign(lua_State *L)
{
    lua_settable(L, 1);
    return 0;
}

int lamina_set_live(lua_State *L, int sidx, const char *key, const char *value, char *err,
                    size_t len)
{
    int k = 0;
    while (lamina_live_settings[k] && strcmp(lamina_live_settings[k], key) != 0) k++;
    if (!lamina_live_settings[k]) {
        snprintf(err, len, "'%s' is not a live setting (dt, gravity, pic, courant, damping)", key);
        return -1;
    }
    sidx = lua_absindex(L, sidx);
    int top = lua_gettop(L);
    lua_pushcfunction(L, assign);
    lua_pushvalue(L, sidx);
    lua_pushstring(L, key);
    if (strcmp(key, "gravity") == 0) {
        /* "gx, gy" */
        char *end;
        double gx = strtod(value, &end);
        const char *p = end;
        while (*p == ' ') p++;
        double gy = 0;
        int ok = end != value && *p == ',';
        if (ok) {
            gy = strtod(p + 1, &end);
            ok = end != p + 1 && *end == 0;
        }
        if (!ok) {
            snprintf(err, len, "gravity: two numbers 'gx, gy' are expected (got '%s')", value);
            lua_settop(L, top);
            return -1;
        }
        lua_createtable(L, 2, 0);
        lua_pushnumber(L, gx);
        lua_rawseti(L, -2, 1);
        lua_pushnumber(L, gy);
        lua_rawseti(L, -2, 2);
    } else if (!lua_stringtonumber(L, value)) {
        snprintf(err, len, "%s: a number is expected (got '%s')", key, value);
        lua_settop(L, top);
        return -1;
    }
    if (lua_pcall(L, 3, 0, 0) != LUA_OK) {
        snprintf(err, len, "%s", lua_tostring(L, -1) ? lua_tostring(L, -1) : "error");
        lua_settop(L, top);
        return -1;
    }
    lua_settop(L, top);
    return 0;
}
