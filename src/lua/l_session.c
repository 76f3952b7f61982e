/* l_session.c - one run of a script for `lamina watch`.
 *
 * Like lamina_run_script (l_module.c), with two differences the watch
 * needs: a stop at a step boundary (--steps, a changed script, Ctrl-C) ends
 * the run without being an error, and the first line of an error is handed
 * back for the watch's one-line summary. */
#include <stdio.h>
#include <string.h>

#include "l_internal.h"

/* The registry table l_report.c keeps: an array of {name =, value =, ...}. */
#define REPORT_KEY "lamina.report"

static void first_line(const char *text, char *msg, size_t len)
{
    if (!len) return;
    size_t n = strcspn(text ? text : "", "\n");
    if (n >= len) n = len - 1;
    memcpy(msg, text ? text : "", n);
    msg[n] = 0;
}

int lamina_run_watched(lua_State *L, lamina_run *run, char *msg, size_t len)
{
    first_line("", msg, len);
    run->stopped = LAMINA_STOP_NONE;
    run->stop_why = NULL;
    lua_pushlightuserdata(L, la_run(L));   /* a stop: no traceback */
    lua_pushcclosure(L, lamina_msghandler, 1);
    int base = lua_gettop(L);
    if (la_load_script(L, run->script) != LUA_OK) {
        fprintf(stderr, "lamina: %s\n", lua_tostring(L, -1));
        first_line(lua_tostring(L, -1), msg, len);
        lua_settop(L, base - 1);
        return LAMINA_EXIT_USAGE;
    }
    lua_pushstring(L, run->script);
    lua_setglobal(L, "SCRIPT");
    int rc = lua_pcall(L, 0, 0, base);
    int status = LAMINA_EXIT_OK;
    if (rc != LUA_OK) {
        const char *err = lua_tostring(L, -1);
        first_line(err, msg, len);
        if (!run->stopped) {
            lamina_progress_clear_line();
            fprintf(stderr, "lamina: %s\n", err ? err : "(error)");
            status = lamina_failure_status(run);
        }
    } else {
        for (int i = 0; i < run->nsets; i++) {
            if (run->sets[i].used) continue;
            fprintf(stderr, "lamina: --set %s: the script has no lamina.param('%s', ...)\n",
                    run->sets[i].name, run->sets[i].name);
            if (!msg[0])
                snprintf(msg, len, "--set %s: the script has no lamina.param('%s', ...)",
                         run->sets[i].name, run->sets[i].name);
            status = LAMINA_EXIT_USAGE;
        }
    }
    lua_settop(L, base - 1);
    return status;
}

static void add_value(lua_State *L, int idx, char *buf, size_t len)
{
    size_t n = strlen(buf);
    if (n + 1 >= len) return;
    if (lua_type(L, idx) == LUA_TNUMBER && !lua_isinteger(L, idx))
        snprintf(buf + n, len - n, "%.6g", lua_tonumber(L, idx));
    else if (lua_type(L, idx) == LUA_TBOOLEAN)
        snprintf(buf + n, len - n, "%s", lua_toboolean(L, idx) ? "true" : "false");
    else
        snprintf(buf + n, len - n, "%s", lua_isstring(L, idx) ? lua_tostring(L, idx) : "?");
}

void lamina_report_line(lua_State *L, char *buf, size_t len)
{
    if (!len) return;
    buf[0] = 0;
    if (la_getfield(L, LUA_REGISTRYINDEX, REPORT_KEY) != LUA_TTABLE) {
        lua_pop(L, 1);
        return;
    }
    lua_Integer n = luaL_len(L, -1);
    for (lua_Integer i = 1; i <= n; i++) {
        lua_geti(L, -1, i);
        if (lua_istable(L, -1)) {
            la_getfield(L, -1, "name");
            la_getfield(L, -2, "value");
            size_t used = strlen(buf);
            snprintf(buf + used, len - used, "%s%s = ", i > 1 ? ", " : "",
                     lua_isstring(L, -2) ? lua_tostring(L, -2) : "?");
            add_value(L, -1, buf, len);
            lua_pop(L, 2);
        }
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
}
