/* l_runlog.c - the run log: live parameter changes, so a run can be
 * replayed (docs/design.md, "Conventions"; issue 7, item 5).
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
#include <stdlib.h>
#include <string.h>

#include "l_internal.h"
#include "mpm3.h"

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

/* The clock a change is logged at: the 2D run's, else the 3D one's
 * (run->active3), else none (has 0). */
typedef struct log_clock {
    int has;
    double t;
    long step;
} log_clock;

static void record(lua_State *L, const log_clock *sim, const char *what, const char *value,
                   int prompt)
{
    la_subtable(L, LUA_REGISTRYINDEX, CHANGES_KEY);
    lua_createtable(L, 0, 5);
    if (sim->has) {
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
    const lamina_run *run = la_run(L);
    if (run && run->change_from) {   /* lamina serve's page */
        lua_pushstring(L, run->change_from);
        lua_setfield(L, -2, "from");
    }
    lua_seti(L, -2, (lua_Integer)luaL_len(L, -2) + 1);
    lua_pop(L, 1);
}

/* The value as Lua source that gives it back (issue 20 item 5: a gravity
 * change was logged as "table: 0x..."): numbers with every digit, strings
 * quoted, booleans, and arrays of those as {a, b, ...}; anything else as
 * tostring does. Pushes the string. */
static const char *replayable(lua_State *L, int idx, int depth)
{
    idx = lua_absindex(L, idx);
    switch (lua_type(L, idx)) {
    case LUA_TNUMBER:
        if (lua_isinteger(L, idx)) return lua_pushfstring(L, "%I", lua_tointeger(L, idx));
        {
            /* the fewest digits that read back as the same double */
            double v = lua_tonumber(L, idx);
            char buf[40];
            for (int prec = 15; prec <= 17; prec++) {
                snprintf(buf, sizeof buf, "%.*g", prec, v);
                if (strtod(buf, NULL) == v) break;
            }
            return lua_pushstring(L, buf);
        }
    case LUA_TSTRING: {
        luaL_Buffer b;
        luaL_buffinit(L, &b);
        luaL_addchar(&b, '"');
        size_t n;
        const char *s = lua_tolstring(L, idx, &n);
        for (size_t i = 0; i < n; i++) {
            unsigned char c = (unsigned char)s[i];
            if (c == '"' || c == '\\') {
                luaL_addchar(&b, '\\');
                luaL_addchar(&b, (char)c);
            } else if (c < 32 || c == 127) {
                char esc[8];
                snprintf(esc, sizeof esc, "\\%03d", c);
                luaL_addstring(&b, esc);
            } else {
                luaL_addchar(&b, (char)c);
            }
        }
        luaL_addchar(&b, '"');
        luaL_pushresult(&b);
        return lua_tostring(L, -1);
    }
    case LUA_TTABLE:
        if (depth < 2) {
            lua_Integer n = (lua_Integer)lua_rawlen(L, idx);
            if (n > 64) n = 64;
            int pieces = 1;
            lua_pushliteral(L, "{");
            for (lua_Integer i = 1; i <= n; i++) {
                lua_rawgeti(L, idx, i);
                replayable(L, -1, depth + 1);
                lua_remove(L, -2);
                pieces++;
                if (i < n) {
                    lua_pushliteral(L, ", ");
                    pieces++;
                }
            }
            lua_pushliteral(L, "}");
            lua_concat(L, pieces + 1);
            break;
        }
        /* fall through */
    default:
        luaL_tolstring(L, idx, NULL);
        break;
    }
    return lua_tostring(L, -1);
}

void la_log_change(lua_State *L, const char *what, const char *key, int validx)
{
    lamina_run *run = la_run(L);
    if (!run) return;
    const lm_sim *active = run->active;
    int prompt = 0;
    if (!active && !run->active3) {
        if (!run->at_prompt) return;   /* set-up, not a live change */
        prompt = 1;
        active = la_last_sim(L);
    }
    log_clock clk = {0, 0, 0}, *sim = &clk;
    if (active) clk = (log_clock){1, active->t, active->step};
    else if (run->active3) clk = (log_clock){1, run->active3->t, run->active3->nstep};
    validx = lua_absindex(L, validx);
    lua_pushfstring(L, "%s.%s", what, key);
    const char *name = lua_tostring(L, -1);
    const char *value = replayable(L, validx, 0);
    char line[512];
    /* where the change came from when not the script: the repl's prompt or
     * lamina serve's page */
    char from[64] = "";
    if (run->change_from) snprintf(from, sizeof from, " (%s)", run->change_from);
    else if (prompt) snprintf(from, sizeof from, " (at the prompt)");
    if (sim->has)
        snprintf(line, sizeof line, "lamina: t = %.9g step %ld: %s = %s%s\n", sim->t,
                 sim->step, name, value, from);
    else
        snprintf(line, sizeof line, "lamina: %s = %s%s\n", name, value, from);
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
