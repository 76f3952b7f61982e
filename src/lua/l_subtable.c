/* l_subtable.c - t[key], a table made on first use: the registry's lists
 * (lamina.param's values, the run log's changes, the report's entries) and
 * a sim's uservalue lists (its materials in 2D and 3D, its recorders). */
#include <lauxlib.h>

#include "l_internal.h"

void la_subtable(lua_State *L, int idx, const char *key)
{
    idx = lua_absindex(L, idx);
    if (la_getfield(L, idx, key) != LUA_TTABLE) {
        lua_pop(L, 1);
        lua_newtable(L);
        lua_pushvalue(L, -1);
        lua_setfield(L, idx, key);
    }
}
