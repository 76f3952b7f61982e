/* repl_eval.c - compiling and running what is typed at the prompt, the way
 * lua.c does it (a model, not a copy): an expression prints its values, a
 * statement that is not finished asks for more lines, and an error prints
 * its message and leaves the session and the simulation as they were. */
#include <lauxlib.h>
#include <lua.h>
#include <stdio.h>
#include <string.h>

#include "workbench.h"

#define CHUNKNAME "=stdin"

/* A syntax error at <eof>: the statement continues on the next line. */
static int incomplete(lua_State *L)
{
    size_t len;
    const char *msg = lua_tolstring(L, -1, &len);
    static const char mark[] = "<eof>";
    size_t m = sizeof mark - 1;
    return msg && len >= m && strcmp(msg + len - m, mark) == 0;
}

int repl_compile(lua_State *L, const char *code)
{
    lua_pushfstring(L, "return %s;", code);
    size_t len;
    const char *ret = lua_tolstring(L, -1, &len);
    int rc = luaL_loadbufferx(L, ret, len, CHUNKNAME, "t");
    lua_remove(L, -2);
    if (rc == LUA_OK) return REPL_OK;
    lua_pop(L, 1);
    rc = luaL_loadbufferx(L, code, strlen(code), CHUNKNAME, "t");
    if (rc == LUA_OK) return REPL_OK;
    if (rc == LUA_ERRSYNTAX && incomplete(L)) {
        lua_pop(L, 1);
        return REPL_INCOMPLETE;
    }
    return REPL_ERROR;
}

int repl_call(lua_State *L, lamina_run *run)
{
    int fn = lua_gettop(L);
    lua_pushlightuserdata(L, run);
    lua_pushcclosure(L, lamina_msghandler, 1);   /* Ctrl-C: the message says where */
    lua_insert(L, fn);
    run->stopped = LAMINA_STOP_NONE;
    run->at_prompt = 1;
    int rc = lua_pcall(L, 0, LUA_MULTRET, fn);
    run->at_prompt = 0;
    lamina_progress_reset();
    if (rc != LUA_OK) {
        fflush(stdout);
        size_t len = 0;
        const char *msg = lua_tolstring(L, -1, &len);
        if (msg) la_write_clean(stderr, msg, len);   /* the script's text: no escapes */
        fputc('\n', stderr);
        fflush(stderr);
        lua_settop(L, fn - 1);
        return REPL_ERROR;
    }
    int n = lua_gettop(L) - fn;
    if (n > 0) {
        luaL_checkstack(L, LUA_MINSTACK, "too many results to print");
        lua_getglobal(L, "print");
        lua_insert(L, fn + 1);
        if (lua_pcall(L, n, 0, 0) != LUA_OK) {
            fprintf(stderr, "error calling 'print' (%s)\n", lua_tostring(L, -1));
            lua_settop(L, fn - 1);
            return REPL_ERROR;
        }
    }
    lua_settop(L, fn - 1);
    fflush(stdout);
    return REPL_OK;
}
