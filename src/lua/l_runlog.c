/* l_runlog.c - the run log: live parameter changes, so a run can be
 * replayed (design.md, Conventions; issue 7, item 5).
 *
 * A change made while a simulation runs (from sim:at / sim:every callbacks)
 * or typed at the repl's prompt is echoed as one line
 *
 *   lamina: t = 0.5 step 500: material.E = 2000
 *
 * ("(at the prompt)" appended for the prompt's) to stderr, which is the run
 * log of `lamina run` and, in a sweep, the run's stderr.txt; and to
 * run->log when one is open. Changes made while a script sets itself up
 * (before any step) are not live and are not logged. Each logged change is
 * also kept for lamina.changes(). */
#include <stdio.h>
#include <string.h>

#include "l_internal.h"

#define LAST_SIM_KEY "lamina.last_sim"   /* registry: the sim that stepped last */
#define CHANGES_KEY "lamina.changes"     /* registry: array of changes */

void la_set_last_sim(lua_State *L, int sidx)
{
    lua_pushvalue(L, sidx);
    lua_setfield(L, LUA_REGISTRYINDEX, LAST_SIM_KEY);
}

const lm_sim *la_last_sim(lua_State *L)
{
    la_getfield(L, LUA_REGISTRYINDEX, LAST_SIM_KEY);
    la_sim *s = luaL_testudata(L, -1, LA_SIM);
    lua_pop(L, 1);
    return s ? s->sim : NULL;
}

static void record(lua_State *L, const lm_sim *sim, const char *what, const char *value,
                   int prompt)
{
    if (la_getfield(L, LUA_REGISTRYINDEX, CHANGES_KEY) != LUA_TTABLE) {
        lua_pop(L, 1);
        lua_newtable(L);
        lua_pushvalue(L, -1);
        lua_setfield(L, LUA_REGISTRYINDEX, CHANGES_KEY);
    }
    lua_createtable(L, 0, 5);
    if (sim) {
        lua_pushnumber(L, sim->t);
        lua_setfield(L, -2, "t");
        lua_pushinteger(L, sim->step);
        lua_setfield(L, -2, "step");
    }
    lua_pushstring(L, what);
    lua_setfield(L, -2, "what");
    lua_pushstring(L, value);
    lua_setfield(L, -2, "value");
    lua_pushboolean(L, prompt);
    lua_setfield(L, -2, "prompt");
    lua_seti(L, -2, (lua_Integer)luaL_len(L, -2) + 1);
    lua_pop(L, 1);
}

void la_log_change(lua_State *L, const char *what, const char *key, int validx)
{
    lamina_run *run = la_run(L);
    if (!run) return;
    const lm_sim *sim = run->active;
    int prompt = 0;
    if (!sim) {
        if (!run->at_prompt) return;   /* set-up, not a live change */
        prompt = 1;
        sim = la_last_sim(L);
    }
    validx = lua_absindex(L, validx);
    lua_pushfstring(L, "%s.%s", what, key);
    const char *name = lua_tostring(L, -1);
    const char *value = luaL_tolstring(L, validx, NULL);
    char line[512];
    if (sim)
        snprintf(line, sizeof line, "lamina: t = %.9g step %ld: %s = %s%s\n", sim->t,
                 sim->step, name, value, prompt ? " (at the prompt)" : "");
    else
        snprintf(line, sizeof line, "lamina: %s = %s%s\n", name, value,
                 prompt ? " (at the prompt)" : "");
    lamina_progress_clear_line();
    fputs(line, stderr);
    if (run->log) {
        fputs(line, run->log);
        fflush(run->log);
    }
    run->changes++;
    record(L, sim, name, value, prompt);
    lua_pop(L, 2);
}

/* lamina.changes(): a copy of the changes logged so far, oldest first, each
 * {t =, step =, what = "material.E", value = "2000", prompt = false}. */
int la_changes(lua_State *L)
{
    lua_newtable(L);
    if (la_getfield(L, LUA_REGISTRYINDEX, CHANGES_KEY) != LUA_TTABLE) {
        lua_pop(L, 1);
        return 1;
    }
    lua_Integer n = luaL_len(L, -1);
    for (lua_Integer i = 1; i <= n; i++) {
        lua_geti(L, -1, i);
        lua_newtable(L);
        lua_pushnil(L);
        while (lua_next(L, -3)) {
            lua_pushvalue(L, -2);
            lua_insert(L, -2);
            lua_settable(L, -4);
        }
        lua_remove(L, -2);
        lua_seti(L, -3, i);
    }
    lua_pop(L, 1);
    return 1;
}
