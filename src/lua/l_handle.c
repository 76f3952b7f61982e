/* l_handle.c - the handles a sim gives out (bodies: l_body_common.c; pins:
 * l_pin_common.c): the engine's index, and the sim as uservalue so that a
 * handle keeps its sim alive. */
#include "l_internal.h"

typedef struct la_handle { int index; } la_handle;

void la_handle_push(lua_State *L, const char *meta, int sidx, int index, int nuv)
{
    sidx = lua_absindex(L, sidx);
    la_handle *h = lua_newuserdatauv(L, sizeof *h, nuv);
    h->index = index;
    luaL_setmetatable(L, meta);
    lua_pushvalue(L, sidx);
    lua_setiuservalue(L, -2, 1);
}

int la_handle_check(lua_State *L, int idx, const char *meta)
{
    la_handle *h = luaL_checkudata(L, idx, meta);
    lua_getiuservalue(L, idx, 1);
    return h->index;
}
