/* l_link.c - sim:link{...}: a force-displacement link between two material
 * points (link.c; [F] §4.4's suggestion for the airbag's tether), and its
 * handle.
 *
 *   local tether = sim:link{ a = {bag, 1}, b = {bag, #bag}, stiffness = 5e4 }
 *   sim:every(0.05, function() tether:remove() end)
 *   print(tether:length(), tether:tension())
 *
 * a and b name a body and a point of it (1-based, in the body's order:
 * a membrane's curve order); the link pulls them together with
 * T = stiffness (l - length), length defaulting to their present distance;
 * law "cable" (default) carries no compression, "spring" does. */
#include <math.h>
#include <string.h>

#include "l_internal.h"

#define LA_LINK "lamina.link"

typedef struct la_link {
    int index;        /* the engine's link */
} la_link;

static const char *const laws[] = {"cable", "spring", NULL};

/* t[key] = {body, i}: the body's index and the point's 0-based index. */
static void read_end(lua_State *L, int idx, const char *key, lm_sim *sim, int *b, size_t *i)
{
    const char *fn = "sim:link";
    if (la_getfield(L, idx, key) != LUA_TTABLE)
        luaL_error(L, "%s: %s must be {body, point} (got %s)", fn, key, luaL_typename(L, -1));
    int t = lua_gettop(L);
    lua_geti(L, t, 1);
    if (!luaL_testudata(L, -1, LA_BODY))
        luaL_error(L, "%s: %s[1] must be a body (got %s)", fn, key, luaL_typename(L, -1));
    lm_sim *owner;
    *b = la_check_body(L, -1, &owner);
    if (owner != sim) luaL_error(L, "%s: %s is a body of another simulation", fn, key);
    lua_geti(L, t, 2);
    int ok;
    lua_Integer v = lua_tointegerx(L, -1, &ok);
    size_t count = sim->bodies[*b].count;
    if (!ok || v < 1 || (lua_Unsigned)v > count)
        luaL_error(L, "%s: %s[2] must be a point of the body, a whole number from 1 to %d",
                   fn, key, (int)count);
    *i = (size_t)(v - 1);
    lua_pop(L, 3);
}

static int sim_link(lua_State *L)
{
    static const char *const keys[] = {"a", "b", "stiffness", "length", "law", NULL};
    const char *fn = "sim:link";
    la_sim *s = la_check_sim(L, 1);
    la_check_keys(L, 2, fn, keys);
    if (s->running) return luaL_error(L, "%s: links cannot be added during a run", fn);
    lm_sim *sim = s->sim;
    int ba, bb;
    size_t ia, ib;
    read_end(L, 2, "a", sim, &ba, &ia);
    read_end(L, 2, "b", sim, &bb, &ib);
    double k = la_number(L, 2, fn, "stiffness");
    size_t qa = sim->bodies[ba].first + ia, qb = sim->bodies[bb].first + ib;
    double now = hypot(sim->p.x[qb] - sim->p.x[qa], sim->p.y[qb] - sim->p.y[qa]);
    double L0 = la_opt_number(L, 2, fn, "length", now);
    int law = la_option(L, fn, "law", la_opt_string(L, 2, fn, "law", "cable"), laws);
    int k_link = lm_sim_add_link(sim, ba, ia, bb, ib, k, L0, law == 0);
    if (k_link < 0) return luaL_error(L, "%s: %s", fn, sim->err);
    la_link *h = lua_newuserdatauv(L, sizeof *h, 1);
    h->index = k_link;
    luaL_setmetatable(L, LA_LINK);
    lua_pushvalue(L, 1);
    lua_setiuservalue(L, -2, 1);
    return 1;
}

static lm_sim *link_sim(lua_State *L, la_link **h)
{
    *h = luaL_checkudata(L, 1, LA_LINK);
    lua_getiuservalue(L, 1, 1);
    lm_sim *sim = la_check_sim(L, -1)->sim;
    lua_pop(L, 1);
    return sim;
}

/* link:remove(): no force and no stored energy from the next step on (the
 * airbag's tether, cut when the probe starts). */
static int link_remove(lua_State *L)
{
    la_link *h;
    lm_sim *sim = link_sim(L, &h);
    lm_sim_set_link_active(sim, h->index, 0);
    return 0;
}

static int link_active(lua_State *L)
{
    la_link *h;
    lm_sim *sim = link_sim(L, &h);
    lua_pushboolean(L, sim->links[h->index].active);
    return 1;
}

static int link_length(lua_State *L)
{
    la_link *h;
    lm_sim *sim = link_sim(L, &h);
    lua_pushnumber(L, lm_link_length(sim, h->index));
    return 1;
}

/* link:tension(): k (l - L0) now (the whole link's, not per radian); 0 if
 * removed or a slack cable. */
static int link_tension(lua_State *L)
{
    la_link *h;
    lm_sim *sim = link_sim(L, &h);
    lua_pushnumber(L, lm_link_tension(sim, h->index));
    return 1;
}

static int link_tostring(lua_State *L)
{
    return la_push_handle_name(L, LA_LINK, ((la_link *)luaL_checkudata(L, 1, LA_LINK))->index);
}

void la_link_methods(lua_State *L)
{
    lua_pushcfunction(L, sim_link);
    lua_setfield(L, -2, "link");
}

void la_open_link(lua_State *L)
{
    static const luaL_Reg meta[] = {{"__tostring", link_tostring}, {NULL, NULL}};
    static const luaL_Reg methods[] = {{"remove", link_remove},   {"active", link_active},
                                       {"length", link_length},   {"tension", link_tension},
                                       {NULL, NULL}};
    la_new_class(L, LA_LINK, meta, methods);
    lua_pushliteral(L, "lamina.link");
    lua_setfield(L, -2, "__metatable");
    lua_pop(L, 1);
}
