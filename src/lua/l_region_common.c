/* l_region_common.c - the region userdata's making, shared by the 2D and
 * 3D region constructors (l_region.c, l_region3.c). */
#include <string.h>

#include <lauxlib.h>

#include "l_region_common.h"

void *la_region_new(lua_State *L, size_t size, const char *meta)
{
    void *r = lua_newuserdatauv(L, size, 0);
    memset(r, 0, size);
    luaL_setmetatable(L, meta);
    return r;
}
