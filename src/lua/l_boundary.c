/* l_boundary.c - lamina.sim{boundary = "fixed"} (every side or face) or
 * {NAME = "fixed" | "symmetry" | "free", ...}, one reading for the 2D sim
 * (l_sim.c) and the 3D one (l_sim3.c). */
#include <lauxlib.h>

#include "l_boundary.h"
#include "l_internal.h"

static const char *const bcs[] = {"fixed", "symmetry", "free", NULL};

void la_read_boundary(lua_State *L, const char *fn, const char *const names[],
                      const char *what, void (*refuse)(lua_State *L, const char *fn),
                      lm_bc *bc)
{
    int t = la_getfield(L, 1, "boundary");
    if (t == LUA_TSTRING) {
        int all = la_option(L, fn, "boundary", lua_tostring(L, -1), bcs);
        for (int s = 0; names[s]; s++) bc[s] = (lm_bc)all;
    } else if (t == LUA_TTABLE) {
        if (refuse) refuse(L, fn);
        la_check_keys(L, -1, "lamina.sim boundary", names);
        for (int s = 0; names[s]; s++) {
            const char *v = la_opt_string(L, -1, fn, names[s], NULL);
            if (v) bc[s] = (lm_bc)la_option(L, fn, names[s], v, bcs);
        }
    } else if (t != LUA_TNIL) {
        luaL_error(L, "%s: 'boundary' must be a string or a table of %s", fn, what);
    }
    lua_pop(L, 1);
}
