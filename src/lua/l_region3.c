/* l_region3.c - the 3D solid regions lamina.ball, lamina.box and
 * lamina.cylinder (sim3_region.c decides what is inside); a plain
 * function f(x, y, z) -> bool is handled where regions are used
 * (l_body3.c). */
#include <math.h>
#include <string.h>

#include "l_region_common.h"
#include "l_sim3.h"

lm3_region *la_test_region3(lua_State *L, int idx)
{
    return luaL_testudata(L, idx, LA_REGION3);
}

static lm3_region *push_region3(lua_State *L, lm3_region_kind kind)
{
    lm3_region *r = la_region_new(L, sizeof *r, LA_REGION3);
    r->kind = kind;
    return r;
}

static void need_triple(lua_State *L, const char *fn, const char *key, double v[3])
{
    if (!la_triple(L, 1, fn, key, v)) luaL_error(L, "%s: '%s' is required", fn, key);
}

static double positive(lua_State *L, const char *fn, const char *key)
{
    double r = la_number(L, 1, fn, key);
    if (!(r > 0) || !isfinite(r))
        luaL_error(L, "%s: '%s' must be a finite positive number (got %f)", fn, key, r);
    return r;
}

/* lamina.ball{center = {x, y, z}, radius = r} */
int la_ball(lua_State *L)
{
    static const char *const keys[] = {"center", "radius", NULL};
    const char *fn = "lamina.ball";
    la_check_keys(L, 1, fn, keys);
    double c[3];
    need_triple(L, fn, "center", c);
    double r = positive(L, fn, "radius");
    lm3_region *g = push_region3(L, LM3_BALL);
    g->r = r;
    for (int a = 0; a < 3; a++) {
        g->c[a] = c[a];
        g->lo[a] = c[a] - r;
        g->hi[a] = c[a] + r;
    }
    return 1;
}

/* lamina.box{x0, y0, z0, x1, y1, z1} or {min = {x, y, z}, max = {x, y, z}} */
int la_box(lua_State *L)
{
    static const char *const keys[] = {"x0", "y0", "z0", "x1", "y1", "z1", "min", "max", NULL};
    static const char *const corner[] = {"x0", "y0", "z0", "x1", "y1", "z1"};
    const char *fn = "lamina.box";
    la_check_keys(L, 1, fn, keys);
    double lo[3], hi[3];
    if (la_has(L, 1, "min") || la_has(L, 1, "max")) {
        need_triple(L, fn, "min", lo);
        need_triple(L, fn, "max", hi);
    } else {
        for (int a = 0; a < 3; a++) {
            lo[a] = la_number(L, 1, fn, corner[a]);
            hi[a] = la_number(L, 1, fn, corner[a + 3]);
            if (!isfinite(lo[a]) || !isfinite(hi[a]))
                luaL_error(L, "%s: '%s' and '%s' must be finite (got %f, %f)", fn, corner[a],
                           corner[a + 3], lo[a], hi[a]);
        }
    }
    for (int a = 0; a < 3; a++)
        if (!(hi[a] > lo[a]))
            luaL_error(L, "%s: empty box (need '%s' > '%s', got %f and %f)", fn, corner[a + 3],
                       corner[a], hi[a], lo[a]);
    lm3_region *g = push_region3(L, LM3_BOX);
    memcpy(g->lo, lo, sizeof lo);
    memcpy(g->hi, hi, sizeof hi);
    return 1;
}

/* lamina.cylinder{from = {x, y, z}, to = {x, y, z}, radius = r}: flat ends */
int la_cylinder(lua_State *L)
{
    static const char *const keys[] = {"from", "to", "radius", NULL};
    const char *fn = "lamina.cylinder";
    la_check_keys(L, 1, fn, keys);
    double a[3], b[3];
    need_triple(L, fn, "from", a);
    need_triple(L, fn, "to", b);
    double r = positive(L, fn, "radius");
    double len2 = 0;
    for (int e = 0; e < 3; e++) len2 += (b[e] - a[e]) * (b[e] - a[e]);
    if (!(len2 > 0)) luaL_error(L, "%s: 'from' and 'to' are the same point", fn);
    lm3_region *g = push_region3(L, LM3_CYLINDER);
    g->r = r;
    for (int e = 0; e < 3; e++) {
        g->a[e] = a[e];
        g->b[e] = b[e];
        /* the ends' discs lie within r of the axis' ends */
        g->lo[e] = fmin(a[e], b[e]) - r;
        g->hi[e] = fmax(a[e], b[e]) + r;
    }
    return 1;
}

/* region:contains(x, y, z) */
static int region3_contains(lua_State *L)
{
    lm3_region *r = luaL_checkudata(L, 1, LA_REGION3);
    double x[3] = {luaL_checknumber(L, 2), luaL_checknumber(L, 3), luaL_checknumber(L, 4)};
    lua_pushboolean(L, lm3_region_contains(r, x));
    return 1;
}

static int region3_tostring(lua_State *L)
{
    static const char *const names[] = {"ball", "box", "cylinder"};
    lm3_region *r = luaL_checkudata(L, 1, LA_REGION3);
    lua_pushfstring(L, "lamina.%s (bounding box %f, %f, %f .. %f, %f, %f)", names[r->kind],
                    r->lo[0], r->lo[1], r->lo[2], r->hi[0], r->hi[1], r->hi[2]);
    return 1;
}

void la_open_region3(lua_State *L)
{
    static const luaL_Reg meta[] = {{"__tostring", region3_tostring}, {NULL, NULL}};
    static const luaL_Reg methods[] = {{"contains", region3_contains}, {NULL, NULL}};
    la_new_class(L, LA_REGION3, meta, methods);
    lua_pop(L, 1);
}
