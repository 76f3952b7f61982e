/* l_alloc.c - the Lua state's allocator, with a cap.
 *
 * A script is untrusted input (docs/design.md): `local t = {} for i = 1, 1e10 do
 * t[i] = i end` must end in an error, not in the machine swapping. Every
 * allocation of the Lua state (tables, strings, closures, lamina's own
 * userdata) is counted against run->lua_mem_limit; past it the allocation
 * fails, Lua collects garbage once and retries, and then raises "not enough
 * memory", which lamina_run_script reports with the cap and how to raise it
 * (lamina run --lua-mem MB). The engine's arrays (particles, grid) are not
 * Lua's: their limits are the engine's. */
#include <stdio.h>
#include <stdlib.h>

#include "l_internal.h"

static void *capped_alloc(void *ud, void *ptr, size_t osize, size_t nsize)
{
    lamina_run *run = ud;
    if (!ptr) osize = 0;   /* then osize only says what kind of object */
    if (nsize == 0) {
        free(ptr);
        run->lua_mem_used -= osize;
        return NULL;
    }
    if (nsize > osize && run->lua_mem_used - osize + nsize > run->lua_mem_limit)
        return NULL;
    void *p = realloc(ptr, nsize);
    if (p) {
        run->lua_mem_used = run->lua_mem_used - osize + nsize;
        if (run->lua_mem_used > run->lua_mem_peak) run->lua_mem_peak = run->lua_mem_used;
    }
    return p;
}

static int panic(lua_State *L)
{
    const char *msg = lua_tostring(L, -1);
    fprintf(stderr, "lamina: unprotected Lua error: %s\n", msg ? msg : "(not a string)");
    return 0;   /* Lua aborts */
}

lua_State *la_new_state(lamina_run *run)
{
    if (!run) return luaL_newstate();
    if (run->lua_mem_limit == 0)
        run->lua_mem_limit = (size_t)LAMINA_LUA_MEM_DEFAULT_MB << 20;
    run->lua_mem_used = run->lua_mem_peak = 0;
    lua_State *L = lua_newstate(capped_alloc, run);
    if (L) lua_atpanic(L, panic);
    return L;
}
