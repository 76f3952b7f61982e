/* l_run_guard.c - the one way out of a run (issue 33 item 4).
 *
 * Everything that ends a sim:run / sim:step early - an error in a callback
 * (sim:every, sim:at, a recorder's value) or in a pin's velocity function, a
 * failed checkpoint or record write, a signal, a step the engine fails or
 * the Courant refusal - is a Lua error raised inside advance()'s protected
 * call (l_sim.c). la_run_guard_end() is where every run ends, failed or not:
 * it clears the running state, ends the progress line and writes the
 * records; a failure is recorded as a code and a message (lamina_run's
 * failure, failure_msg) before the error goes on - to a pcall in the script,
 * after which the sim steps again, or to the top, where the exit status is
 * taken from the code (lamina_failure_status), not from the message text.
 *
 * A failure is known by its error value: la_fail_raise() keeps the value
 * it raises in the registry, and the top-level message handler asks whether
 * the error that ends the script is that value (or the script's message
 * wrapped around it). A failure the script caught with pcall and followed
 * by an error of its own is the script's mistake (exit 2), as docs/api.md
 * says. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "l_internal.h"

#define FAIL_KEY "lamina.failure"
#define GUARD_KEY "lamina.run_guard"   /* the guard of the run in progress */

/* The error value on top becomes the run's recorded failure. */
static void record_failure(lua_State *L, int code)
{
    lua_pushvalue(L, -1);
    lua_setfield(L, LUA_REGISTRYINDEX, FAIL_KEY);
    lamina_run *run = la_run(L);
    if (!run) return;
    run->failure = code;
    run->failure_escaped = 0;
    /* a copy, so that lua_tostring does not turn a number on the stack
     * into a string */
    lua_pushvalue(L, -1);
    const char *m = lua_tostring(L, -1);
    snprintf(run->failure_msg, sizeof run->failure_msg, "%s",
             m ? m : "(error object is not a string)");
    lua_pop(L, 1);
}

/* Is the value at idx the failure recorded last? */
static int is_recorded(lua_State *L, int idx)
{
    idx = lua_absindex(L, idx);
    lua_getfield(L, LUA_REGISTRYINDEX, FAIL_KEY);
    int same = !lua_isnil(L, -1) && lua_rawequal(L, idx, -1);
    lua_pop(L, 1);
    return same;
}

int la_fail_raise(lua_State *L, int code)
{
    record_failure(L, code);
    return lua_error(L);
}

static la_run_guard *current(lua_State *L)
{
    lua_getfield(L, LUA_REGISTRYINDEX, GUARD_KEY);
    la_run_guard *g = lua_touserdata(L, -1);
    lua_pop(L, 1);
    return g;
}

static void set_current(lua_State *L, la_run_guard *g)
{
    if (g) lua_pushlightuserdata(L, g);
    else lua_pushnil(L);
    lua_setfield(L, LUA_REGISTRYINDEX, GUARD_KEY);
}

int la_fail_raisef(lua_State *L, int code, const char *fmt, ...)
{
    /* the steps run in a protected C call: luaL_where(L, 1) would name
     * that call, not the script's line */
    la_run_guard *g = current(L);
    if (g) lua_pushstring(L, g->where);
    else luaL_where(L, 1);
    va_list ap;
    va_start(ap, fmt);
    lua_pushvfstring(L, fmt, ap);
    va_end(ap);
    lua_concat(L, 2);
    return la_fail_raise(L, code);
}

void la_run_guard_begin(lua_State *L, la_run_guard *g, int sidx, la_sim *s)
{
    lamina_run *run = la_run(L);
    memset(g, 0, sizeof *g);
    g->s = s;
    g->sidx = lua_absindex(L, sidx);
    g->outer = run->active;   /* a callback of another sim's run runs this one */
    g->outer_guard = current(L);
    luaL_where(L, 1);
    snprintf(g->where, sizeof g->where, "%s", lua_tostring(L, -1));
    lua_pop(L, 1);
    set_current(L, g);
    s->running = 1;
    run->active = s->sim;
}

static int flush_records(lua_State *L)
{
    la_record_flush(L, 1);
    return 0;
}

/* Writes the records of the sim at g->sidx, protected: 0, or -1 with the
 * error on top. */
static int flush_protected(lua_State *L, const la_run_guard *g)
{
    lua_pushcfunction(L, flush_records);
    lua_pushvalue(L, g->sidx);
    return lua_pcall(L, 1, 0, 0) == LUA_OK ? 0 : -1;
}

void la_run_guard_end(lua_State *L, la_run_guard *g, int failed)
{
    lamina_run *run = la_run(L);
    g->s->running = 0;
    run->active = g->outer;
    if (g->progress) la_progress_end(L);
    g->progress = 0;
    if (!failed) {
        /* the records' write failing is the run's failure (la_fail_raise
         * in l_record.c recorded it as LAMINA_FAIL_IO) */
        int bad = flush_protected(L, g);
        set_current(L, g->outer_guard);
        if (bad) {
            if (!is_recorded(L, -1)) record_failure(L, LAMINA_FAIL_IO);
            lua_error(L);
        }
        return;
    }
    /* the error on top: a failure raised by la_fail_raise (here, or in a
     * nested run of another sim that it passed through), else the script's */
    if (!is_recorded(L, -1)) record_failure(L, LAMINA_FAIL_SCRIPT);
    /* what was recorded is kept; if that fails too, the first error wins
     * and the second is said (unless it is the same write failing again) */
    if (flush_protected(L, g)) {
        if (!lua_rawequal(L, -1, -2)) {
            char line[700];
            const char *m = lua_tostring(L, -1);
            snprintf(line, sizeof line, "lamina: warning: the records could not be written "
                     "after the run failed: %s\n", m ? m : "(error object is not a string)");
            la_warn(L, line);
        }
        lua_pop(L, 1);
    }
    set_current(L, g->outer_guard);
    lua_error(L);
}

/* Is the error at idx the recorded failure, or the script's message around
 * it ("the run stopped: " .. err, raised again: still the failure, issue 18,
 * tests/security/failure_rethrown.lua)? Its code gives the status either
 * way; the text only tells which error ended the script. */
static int carries_failure(lua_State *L, int idx)
{
    idx = lua_absindex(L, idx);
    if (is_recorded(L, idx)) return 1;
    if (lua_type(L, idx) != LUA_TSTRING) return 0;
    int found = 0;
    if (lua_getfield(L, LUA_REGISTRYINDEX, FAIL_KEY) == LUA_TSTRING)
        found = strstr(lua_tostring(L, idx), lua_tostring(L, -1)) != NULL;
    lua_pop(L, 1);
    return found;
}

void la_fail_note_escape(lua_State *L, int idx)
{
    lamina_run *run = la_run(L);
    if (run) run->failure_escaped = run->failure != LAMINA_FAIL_NONE && carries_failure(L, idx);
}

int lamina_failure_status(const lamina_run *run)
{
    /* a signal ends `lamina run` with 128 + its number even when the
     * script caught the error it raised (docs/api.md) */
    if (run->stopped == LAMINA_STOP_SIGINT) return 128 + lamina_interrupt_signal();
    if (!run->failure_escaped) return LAMINA_EXIT_USAGE;
    switch (run->failure) {
    case LAMINA_FAIL_UNSTABLE: return LAMINA_EXIT_SIM;
    case LAMINA_FAIL_STOPPED: return LAMINA_EXIT_OK;
    case LAMINA_FAIL_SIGNAL: return 128 + lamina_interrupt_signal();
    default: return LAMINA_EXIT_USAGE;   /* SCRIPT, IO, REFUSED */
    }
}
