/* l_alloc.c - the Lua state's allocator, with two caps.
 *
 * A script is untrusted input (docs/design.md): `local t = {} for i = 1, 1e10 do
 * t[i] = i end` must end in an error, not in the machine swapping. Every
 * allocation of the Lua state (tables, strings, closures, lamina's own
 * userdata) is counted against run->lua_mem_limit; past it the allocation
 * fails, Lua collects garbage once and retries, and then raises "not enough
 * memory", which lamina_run_script reports with the cap and how to raise it
 * (lamina run --lua-mem MB).
 *
 * The same bytes are charged to the process's one memory budget
 * (src/util/lu_budget.c, issue 31 item 5), which also counts the engine's
 * arrays and the renderer's canvases: a script that keeps simulations or
 * figures stops at that cap with "memory limit N MB reached (engine: ..,
 * lua: .., render: ..)". A simulation is a small userdata to the collector
 * but may hold hundreds of MB, so before an engine or renderer charge is
 * refused the budget calls reclaim() below: a full collection, which
 * finalizes the simulations and figures the script dropped. */
#include <stdio.h>
#include <stdlib.h>

#include "l_internal.h"
#include "util.h"

static void *capped_alloc(void *ud, void *ptr, size_t osize, size_t nsize)
{
    lamina_run *run = ud;
    if (!ptr) osize = 0;   /* then osize only says what kind of object */
    if (nsize == 0) {
        free(ptr);
        run->lua_mem_used -= osize;
        lu_budget_release(LU_MEM_LUA, osize);
        return NULL;
    }
    if (nsize > osize) {
        if (run->lua_mem_used - osize + nsize > run->lua_mem_limit) {
            lu_budget_forget_refusal();   /* this cap, not the process's */
            return NULL;
        }
        /* no reclaim for Lua's own charges: no collection from inside the
         * allocator (Lua collects by itself when this fails) */
        if (lu_budget_charge(LU_MEM_LUA, nsize - osize) != 0) return NULL;
    }
    void *p = realloc(ptr, nsize);
    if (!p) {
        if (nsize > osize) lu_budget_release(LU_MEM_LUA, nsize - osize);
        return NULL;
    }
    if (nsize < osize) lu_budget_release(LU_MEM_LUA, osize - nsize);
    run->lua_mem_used = run->lua_mem_used - osize + nsize;
    if (run->lua_mem_used > run->lua_mem_peak) run->lua_mem_peak = run->lua_mem_used;
    return p;
}

static int panic(lua_State *L)
{
    const char *msg = lua_tostring(L, -1);
    fprintf(stderr, "lamina: unprotected Lua error: %s\n", msg ? msg : "(not a string)");
    return 0;   /* Lua aborts */
}

/* The budget's reclaim: runs on the main thread between two engine or
 * renderer allocations, where the binding could as well have made a Lua
 * object (so a collection step could have run there anyway). Scripts
 * cannot set __gc (l_sandbox.c): only lamina's finalizers run, and they
 * only free. */
static void reclaim(void *ud)
{
    lua_gc(ud, LUA_GCCOLLECT);
}

/* The registry's "lamina.budget" userdata: finalized when the state is
 * closed, it stops the budget from calling into a state that is gone. */
static int detach(lua_State *L)
{
    lua_State **main = lua_touserdata(L, 1);
    if (main) lu_budget_clear_reclaim(*main);
    return 0;
}

lua_State *la_new_state(lamina_run *run)
{
    if (!run) return luaL_newstate();
    if (run->lua_mem_limit == 0)
        run->lua_mem_limit = (size_t)LAMINA_LUA_MEM_DEFAULT_MB << 20;
    run->lua_mem_used = run->lua_mem_peak = 0;
    lua_State *L = lua_newstate(capped_alloc, run);
    if (!L) return NULL;
    lua_atpanic(L, panic);
    lua_State **main = lua_newuserdatauv(L, sizeof *main, 0);
    *main = L;
    lua_newtable(L);
    lua_pushcfunction(L, detach);
    lua_setfield(L, -2, "__gc");
    lua_setmetatable(L, -2);
    lua_setfield(L, LUA_REGISTRYINDEX, "lamina.budget");
    lu_budget_set_reclaim(reclaim, L);
    return L;
}
