/* l_mesh3.c - lamina.mesh{file, scale, translate} (l_mesh3.h): a triangle
 * mesh from an OBJ or STL file for a 3D run, as a region (a closed mesh)
 * and as a membrane surface. The file is untrusted input as the script is
 * (docs/security.md "Inputs"): its name confined to the script's folder or
 * the output root (la_check_asset_path), its size and triangles bounded, its
 * bytes and the mesh charged to the process's one memory cap, and a
 * malformed file refused naming the file and the line or triangle (the
 * reader's messages, src/mpm/mesh3.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "l_mesh3.h"
#include "l_sim3.h"
#include "read_file.h"
#include "util.h"

la_mesh3 *la_test_mesh3(lua_State *L, int idx)
{
    return luaL_testudata(L, idx, LA_MESH3);
}

static void charge(lua_State *L, la_mesh3 *u, size_t bytes, const char *fn)
{
    if (bytes > u->charged) {
        if (lu_budget_charge(LU_MEM_ENGINE, bytes - u->charged) != 0)
            luaL_error(L, "%s: %s", fn, lu_budget_oom());
    } else {
        lu_budget_release(LU_MEM_ENGINE, u->charged - bytes);
    }
    u->charged = bytes;
}

/* the mesh's arrays and, once it is a region, its inside test's buckets
 * (at most 16 entries a triangle and about one bucket a triangle) */
static size_t mesh_bytes(const lm3_mesh *m)
{
    return 24 * m->nv + 12 * m->nt + (16 * 4 + 8) * m->nt + ((size_t)1 << 19);
}

static int mesh_gc(lua_State *L)
{
    la_mesh3 *u = luaL_checkudata(L, 1, LA_MESH3);
    lm3_mesh_ray_free(&u->ray);
    lm3_mesh_free(&u->m);
    if (u->charged) lu_budget_release(LU_MEM_ENGINE, u->charged);
    u->charged = 0;
    u->ray_built = 0;
    return 0;
}

/* scale = s or {sx, sy, sz}: finite and not zero */
static void read_scale(lua_State *L, const char *fn, double s[3])
{
    int t = la_getfield(L, 1, "scale");
    if (t == LUA_TNIL) {
        s[0] = s[1] = s[2] = 1;
    } else if (t == LUA_TNUMBER) {
        s[0] = s[1] = s[2] = lua_tonumber(L, -1);
    } else if (t == LUA_TTABLE) {
        lua_pop(L, 1);
        la_triple(L, 1, fn, "scale", s);
        lua_pushnil(L);
    } else {
        luaL_error(L, "%s: 'scale' must be a number or {sx, sy, sz} (got %s)", fn,
                   luaL_typename(L, -1));
    }
    lua_pop(L, 1);
    for (int a = 0; a < 3; a++)
        if (!isfinite(s[a]) || s[a] == 0)
            luaL_error(L, "%s: 'scale' must be finite and not 0 (got %f)", fn, s[a]);
}

/* lamina.mesh{file = "part.obj" | "part.stl", scale = 1 | {sx, sy, sz},
 * translate = {0, 0, 0}}: x' = scale * x + translate */
int la_mesh(lua_State *L)
{
    static const char *const keys[] = {"file", "scale", "translate", NULL};
    const char *fn = "lamina.mesh";
    la_check_table(L, 1, fn);
    la_check_keys(L, 1, fn, keys);
    if (la_getfield(L, 1, "file") == LUA_TNIL) return luaL_error(L, "%s: 'file' is required", fn);
    char real[4096];
    size_t size = 0;
    const char *file = la_check_asset_path(L, fn, -1, LA_MESH_MAX_BYTES, real, &size);
    double s[3], tr[3] = {0, 0, 0};
    read_scale(L, fn, s);
    la_triple(L, 1, fn, "translate", tr);

    la_mesh3 *u = lua_newuserdatauv(L, sizeof *u, 0);
    memset(u, 0, sizeof *u);
    luaL_setmetatable(L, LA_MESH3);   /* from here __gc releases what is charged */
    snprintf(u->name, sizeof u->name, "%s", file);
    /* the file's bytes and what the reader may make of them (at most a
     * vertex's or a corner's 24 bytes for every 2 of text, a binary STL's
     * 48 bytes of triangle from 50), charged before anything is read */
    charge(L, u, 13 * size + 4096, fn);
    char *text, err[600];
    size_t len;
    if (lr_read_file(real, LA_MESH_MAX_BYTES, &text, &len, err, sizeof err) != 0)
        return luaL_error(L, "%s: '%s': %s", fn, file, err);
    int rc = lm3_mesh_parse(u->name, text, len, &u->m, err, sizeof err);
    free(text);
    if (rc != 0) return luaL_error(L, "%s: %s", fn, err);
    if (u->m.nt > LA_MESH_MAX_TRIANGLES)
        return luaL_error(L, "%s: %s: %zu triangles, more than the limit of %zu", fn, u->name,
                          u->m.nt, LA_MESH_MAX_TRIANGLES);
    charge(L, u, mesh_bytes(&u->m), fn);
    for (int a = 0; a < 3; a++) {
        u->lo[a] = INFINITY;
        u->hi[a] = -INFINITY;
    }
    for (size_t v = 0; v < u->m.nv; v++)
        for (int a = 0; a < 3; a++) {
            double x = s[a] * u->m.xyz[3 * v + a] + tr[a];
            if (!isfinite(x))
                return luaL_error(L, "%s: %s: vertex %zu is not finite once scaled and "
                                  "translated", fn, u->name, v + 1);
            u->m.xyz[3 * v + a] = x;
            u->lo[a] = fmin(u->lo[a], x);
            u->hi[a] = fmax(u->hi[a], x);
        }
    rc = lm3_mesh_closed(u->name, &u->m, u->why, sizeof u->why);
    if (rc < 0) return luaL_error(L, "%s: %s", fn, u->why);
    u->closed = rc;
    return 1;
}

lm3_mesh_ray *la_mesh3_region(lua_State *L, la_mesh3 *u, const char *fn)
{
    if (!u->closed)
        luaL_error(L, "%s: 'region': a region must be a closed mesh: %s", fn, u->why);
    if (!u->ray_built) {
        char err[200];
        if (lm3_mesh_ray_build(&u->m, &u->ray, err, sizeof err) != 0)
            luaL_error(L, "%s: %s: %s", fn, u->name, err);
        u->ray_built = 1;
    }
    return &u->ray;
}

size_t la_mesh3_points(const la_mesh3 *u, double spacing, char *err, size_t errlen)
{
    int k;
    size_t nv, nt;
    if (lm3_mesh_refine_counts(&u->m, spacing, LM_MAX_PARTICLES, &k, &nv, &nt, err, errlen) != 0)
        return 0;
    return nv;
}

/* the rim flags of the mesh the sample was made from (mesh m's vertices
 * are the sample's points, in order) */
static int rim_of(const lm3_mesh *m, uint8_t **rim, char *err, size_t errlen)
{
    if (!rim) return 0;
    *rim = malloc(m->nv ? m->nv : 1);
    if (!*rim || lm3_mesh_rim(m, *rim) < 0) {
        free(*rim);
        *rim = NULL;
        lu_err(err, errlen, "out of memory for the rim of %zu points", m->nv);
        return -1;
    }
    return 0;
}

int la_mesh3_sample(const la_mesh3 *u, double spacing, lm3_msample *s, uint8_t **rim,
                    char *err, size_t errlen)
{
    if (rim) *rim = NULL;
    char why[400];
    /* the file's own triangles first, so that a refusal (a triangle of no
     * area, a vertex in no triangle) names them as the file numbers them */
    if (lm3_sample_mesh(u->m.xyz, u->m.nv, u->m.tri, u->m.nt, s, why, sizeof why) != 0) {
        lu_err(err, errlen, "%s: %s", u->name, why);
        return -1;
    }
    int k;
    size_t nv, nt;
    if (lm3_mesh_refine_counts(&u->m, spacing, LM_MAX_PARTICLES, &k, &nv, &nt, why,
                               sizeof why) != 0) {
        lm3_msample_free(s);
        lu_err(err, errlen, "%s: %s", u->name, why);
        return -1;
    }
    if (k == 1) {   /* every edge within the spacing: a point a vertex */
        if (rim_of(&u->m, rim, err, errlen) == 0) return 0;
        lm3_msample_free(s);
        return -1;
    }
    lm3_msample_free(s);
    lm3_mesh fine;
    if (lm3_mesh_refine(&u->m, spacing, LM_MAX_PARTICLES, &fine, why, sizeof why) != 0) {
        lu_err(err, errlen, "%s: %s", u->name, why);
        return -1;
    }
    int rc = lm3_sample_mesh(fine.xyz, fine.nv, fine.tri, fine.nt, s, why, sizeof why);
    if (rc != 0) lu_err(err, errlen, "%s (cut to spacing %g): %s", u->name, spacing, why);
    else if (rim_of(&fine, rim, err, errlen) != 0) {
        lm3_msample_free(s);
        rc = -1;
    }
    lm3_mesh_free(&fine);
    return rc;
}

/* mesh:contains(x, y, z) on a closed mesh: the winding number, as a body
 * seeded in it decides */
static int mesh_contains(lua_State *L)
{
    la_mesh3 *u = luaL_checkudata(L, 1, LA_MESH3);
    double x[3] = {luaL_checknumber(L, 2), luaL_checknumber(L, 3), luaL_checknumber(L, 4)};
    lm3_mesh_ray *r = la_mesh3_region(L, u, "mesh:contains");
    int in = lm3_mesh_ray_inside(r, x);
    if (in < 0) return luaL_error(L, "mesh:contains: out of memory");
    lua_pushboolean(L, in);
    return 1;
}

/* mesh:vertex(i) -> x, y, z (scaled and translated); mesh:triangle(i) ->
 * the vertex numbers a, b, c (from 1, in the file's winding) */
static int mesh_vertex(lua_State *L)
{
    la_mesh3 *u = luaL_checkudata(L, 1, LA_MESH3);
    lua_Integer i = luaL_checkinteger(L, 2);
    if (i < 1 || (size_t)i > u->m.nv)
        return luaL_error(L, "mesh:vertex(%I): the mesh has %I vertices", i, (lua_Integer)u->m.nv);
    for (int a = 0; a < 3; a++) lua_pushnumber(L, u->m.xyz[3 * (size_t)(i - 1) + (size_t)a]);
    return 3;
}

static int mesh_triangle(lua_State *L)
{
    la_mesh3 *u = luaL_checkudata(L, 1, LA_MESH3);
    lua_Integer i = luaL_checkinteger(L, 2);
    if (i < 1 || (size_t)i > u->m.nt)
        return luaL_error(L, "mesh:triangle(%I): the mesh has %I triangles", i,
                          (lua_Integer)u->m.nt);
    for (int a = 0; a < 3; a++)
        lua_pushinteger(L, (lua_Integer)u->m.tri[3 * (size_t)(i - 1) + (size_t)a] + 1);
    return 3;
}

static int mesh_index(lua_State *L)
{
    la_mesh3 *u = luaL_checkudata(L, 1, LA_MESH3);
    const char *k = luaL_checkstring(L, 2);
    if (strcmp(k, "vertices") == 0) {
        lua_pushinteger(L, (lua_Integer)u->m.nv);
    } else if (strcmp(k, "triangles") == 0) {
        lua_pushinteger(L, (lua_Integer)u->m.nt);
    } else if (strcmp(k, "closed") == 0) {
        lua_pushboolean(L, u->closed);
    } else if (strcmp(k, "area") == 0) {
        lua_pushnumber(L, lm3_mesh_area(&u->m));
    } else if (strcmp(k, "volume") == 0) {   /* the enclosed volume of a closed mesh */
        if (!u->closed) return luaL_error(L, "mesh.volume: %s", u->why);
        lua_pushnumber(L, fabs(lm3_mesh_volume6(&u->m)) / 6);
    } else if (strcmp(k, "bounds") == 0) {
        lua_createtable(L, 6, 0);
        for (int a = 0; a < 6; a++) {
            lua_pushnumber(L, a < 3 ? u->lo[a] : u->hi[a - 3]);
            lua_rawseti(L, -2, a + 1);
        }
    } else if (strcmp(k, "file") == 0) {
        lua_pushstring(L, u->name);
    } else if (strcmp(k, "contains") == 0) {
        lua_pushcfunction(L, mesh_contains);
    } else if (strcmp(k, "vertex") == 0) {
        lua_pushcfunction(L, mesh_vertex);
    } else if (strcmp(k, "triangle") == 0) {
        lua_pushcfunction(L, mesh_triangle);
    } else {
        return luaL_error(L, "mesh has no field or method '%s' (vertices, triangles, closed, "
                          "area, volume, bounds, file, contains, vertex, triangle)", k);
    }
    return 1;
}

static int mesh_tostring(lua_State *L)
{
    la_mesh3 *u = luaL_checkudata(L, 1, LA_MESH3);
    lua_pushfstring(L, "lamina.mesh '%s' (%d vertices, %d triangles, %s)", u->name, (int)u->m.nv,
                    (int)u->m.nt, u->closed ? "closed" : "open");
    return 1;
}

void la_open_mesh3(lua_State *L)
{
    static const luaL_Reg meta[] = {{"__gc", mesh_gc},
                                    {"__index", mesh_index},
                                    {"__tostring", mesh_tostring},
                                    {NULL, NULL}};
    la_new_metatable(L, LA_MESH3);
    luaL_setfuncs(L, meta, 0);
    lua_pop(L, 1);
}
