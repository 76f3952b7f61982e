/* l_body_common.c - sim:body's and the body handle's common layer for
 * both dimensions (l_body_common.h; l_body.c and l_body3.c keep what is
 * their own). */
#include <string.h>

#include "l_body_common.h"
#include "l_sim3.h"

int la_body_args(lua_State *L, const la_sim *s, const char *fn, const char *const keys[])
{
    la_check_keys(L, 2, fn, keys);
    la_opt_string(L, 2, fn, "name", NULL);
    if (s->running) return luaL_error(L, "%s: bodies cannot be added during a run", fn);
    if (la_getfield(L, 2, "material") == LUA_TNIL)
        return luaL_error(L, "%s: 'material' is required", fn);
    if (!luaL_testudata(L, -1, LA_MATERIAL))
        return luaL_error(L, "%s: 'material' must be a material (lamina.elastic{...})", fn);
    int midx = lua_gettop(L);
    la_getfield(L, 2, "region");
    return midx;
}

int la_body_call(lua_State *L, int fidx, const double *x, int dim, int nres)
{
    lua_pushvalue(L, fidx);
    for (int a = 0; a < dim; a++) lua_pushnumber(L, x[a]);
    return lua_pcall(L, dim, nres, 0) == LUA_OK ? 0 : -1;
}

void la_body_handle_push(lua_State *L, const char *meta, int sidx, int bi, int nameidx)
{
    if (nameidx) nameidx = lua_absindex(L, nameidx);
    la_handle_push(L, meta, sidx, bi, 2);   /* l_handle.c */
    if (nameidx) {
        lua_pushvalue(L, nameidx);
        lua_setiuservalue(L, -2, 2);
    }
}

/* The body handle at 1 of either dimension: its index, its particles'
 * count into *n, and whether it is a 3D body. */
static int any_body(lua_State *L, size_t *n, int *dim3)
{
    *dim3 = luaL_testudata(L, 1, LA_BODY3) != NULL;
    int bi = la_handle_check(L, 1, *dim3 ? LA_BODY3 : LA_BODY);
    la_sim *s = la_check_sim_any(L, -1);
    *n = *dim3 ? s->s3->bodies[bi].n : s->sim->bodies[bi].count;
    lua_pop(L, 1);
    return bi;
}

int la_body_len(lua_State *L)
{
    size_t n;
    int dim3;
    any_body(L, &n, &dim3);
    lua_pushinteger(L, (lua_Integer)n);
    return 1;
}

int la_body_tostring(lua_State *L)
{
    size_t n;
    int dim3;
    int bi = any_body(L, &n, &dim3);
    lua_getiuservalue(L, 1, 2);
    const char *name = lua_isstring(L, -1) ? lua_tostring(L, -1) : "";
    lua_pushfstring(L, "lamina.body %d%s%s (%s%d particles)", bi + 1, *name ? " " : "", name,
                    dim3 ? "3D, " : "", (int)n);
    return 1;
}

int la_body_handle_field(lua_State *L, int bi, const char *k)
{
    if (strcmp(k, "name") == 0) {
        lua_getiuservalue(L, 1, 2);
        return 1;
    }
    if (strcmp(k, "index") == 0) {
        lua_pushinteger(L, bi + 1);
        return 1;
    }
    luaL_getmetafield(L, 1, "methods");
    if (la_getfield(L, -1, k) != LUA_TNIL) return 1;
    lua_pop(L, 2);
    return 0;
}
