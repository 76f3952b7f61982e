/* l_region.c - lamina.disk, lamina.rect, lamina.polygon (and, handled where
 * regions are used, a plain function f(x, y) -> bool). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "l_internal.h"
#include "l_region_common.h"

lm_region *la_test_region(lua_State *L, int idx)
{
    return luaL_testudata(L, idx, LA_REGION);
}

static lm_region *push_region(lua_State *L, lm_region_kind kind)
{
    lm_region *r = la_region_new(L, sizeof *r, LA_REGION);
    r->kind = kind;
    return r;
}

int la_disk(lua_State *L)
{
    static const char *const keys[] = {"center", "radius", NULL};
    const char *fn = "lamina.disk";
    la_check_keys(L, 1, fn, keys);
    double cx, cy;
    la_pair(L, 1, fn, "center", &cx, &cy);
    double r = la_number(L, 1, fn, "radius");
    if (!(r > 0) || !isfinite(r) || !isfinite(cx) || !isfinite(cy))   /* issue 31 item 7 */
        luaL_error(L, "%s: 'radius' must be a finite positive number and 'center' finite "
                   "(got radius %f at {%f, %f})", fn, r, cx, cy);
    lm_region *g = push_region(L, LM_REGION_DISK);
    g->cx = cx;
    g->cy = cy;
    g->r = r;
    g->x0 = cx - r; g->x1 = cx + r;
    g->y0 = cy - r; g->y1 = cy + r;
    return 1;
}

/* lamina.rect{x0, y0, x1, y1} or {min = {x, y}, max = {x, y}}. */
int la_rect(lua_State *L)
{
    static const char *const keys[] = {"x0", "y0", "x1", "y1", "min", "max", NULL};
    const char *fn = "lamina.rect";
    la_check_keys(L, 1, fn, keys);
    double x0, y0, x1, y1;
    if (la_has(L, 1, "min") || la_has(L, 1, "max")) {
        la_pair(L, 1, fn, "min", &x0, &y0);
        la_pair(L, 1, fn, "max", &x1, &y1);
    } else {
        x0 = la_number(L, 1, fn, "x0");
        y0 = la_number(L, 1, fn, "y0");
        x1 = la_number(L, 1, fn, "x1");
        y1 = la_number(L, 1, fn, "y1");
    }
    if (!isfinite(x0) || !isfinite(y0) || !isfinite(x1) || !isfinite(y1))   /* issue 31 item 7 */
        luaL_error(L, "%s: 'x0', 'y0', 'x1', 'y1' must be finite (got {%f, %f, %f, %f})", fn,
                   x0, y0, x1, y1);
    if (!(x1 > x0) || !(y1 > y0))
        luaL_error(L, "%s: empty rectangle (need 'x1' > 'x0' and 'y1' > 'y0')", fn);
    lm_region *g = push_region(L, LM_REGION_RECT);
    g->x0 = x0; g->y0 = y0; g->x1 = x1; g->y1 = y1;
    return 1;
}

/* lamina.polygon{points = {{x, y}, ...}} (also accepts the list directly). */
int la_polygon(lua_State *L)
{
    const char *fn = "lamina.polygon";
    int n;
    int list = la_point_list(L, fn, 3, &n);
    lm_region *g = push_region(L, LM_REGION_POLYGON);
    g->vx = malloc(n * sizeof(double));
    g->vy = malloc(n * sizeof(double));
    if (!g->vx || !g->vy) luaL_error(L, "%s: out of memory", fn);
    g->nv = n;
    for (int i = 0; i < n; i++) {
        la_point_at(L, list, i, fn, &g->vx[i], &g->vy[i]);
        if (i == 0 || g->vx[i] < g->x0) g->x0 = g->vx[i];
        if (i == 0 || g->vx[i] > g->x1) g->x1 = g->vx[i];
        if (i == 0 || g->vy[i] < g->y0) g->y0 = g->vy[i];
        if (i == 0 || g->vy[i] > g->y1) g->y1 = g->vy[i];
    }
    return 1;
}

static int region_gc(lua_State *L)
{
    lm_region *r = luaL_checkudata(L, 1, LA_REGION);
    free(r->vx);
    free(r->vy);
    r->vx = r->vy = NULL;
    r->nv = 0;   /* idempotent, and a freed polygon contains nothing */
    return 0;
}

/* region:contains(x, y), so scripts can combine shapes in plain functions. */
static int region_contains(lua_State *L)
{
    lm_region *r = luaL_checkudata(L, 1, LA_REGION);
    lua_pushboolean(L, lm_region_contains(r, luaL_checknumber(L, 2), luaL_checknumber(L, 3)));
    return 1;
}

static int region_tostring(lua_State *L)
{
    static const char *const names[] = {"disk", "rect", "polygon"};
    lm_region *r = luaL_checkudata(L, 1, LA_REGION);
    lua_pushfstring(L, "lamina.%s (bounding box %f, %f .. %f, %f)", names[r->kind],
                    r->x0, r->y0, r->x1, r->y1);
    return 1;
}

void la_open_region(lua_State *L)
{
    static const luaL_Reg meta[] = {{"__gc", region_gc},
                                    {"__tostring", region_tostring},
                                    {NULL, NULL}};
    static const luaL_Reg methods[] = {{"contains", region_contains}, {NULL, NULL}};
    la_new_class(L, LA_REGION, meta, methods);
    lua_pop(L, 1);
}
