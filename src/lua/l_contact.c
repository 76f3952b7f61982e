/* l_contact.c - sim:contact{a, b, law = ..., mu = ...}: contact between two
 * bodies (contact.h), and sim:contact_info() for what it did.
 *
 *   sim:contact{ bar1, bar2, law = "release" }            -- [M] §4.1
 *   sim:contact{ block, plane, law = "friction", mu = 0.3 }
 *   sim:contact{ bar1, bar2, test = "eq26", update = "eq21" } -- as printed
 *
 * Without a pair the bodies share one velocity field: the papers' no-slip
 * contact, lamina's default. */
#include <math.h>
#include <string.h>

#include "mpm_contact.h"
#include "l_internal.h"

static const char *const laws[] = {"release", "friction", NULL};
/* the release test and the update of a staying body: lamina's, or the
 * papers' as printed ([M] eq 26, eqs 20-21; mpm_contact.h) */
static const char *const tests[] = {"lamina", "eq26", NULL};
static const char *const updates[] = {"lamina", "eq21", NULL};

/* Only the two bodies by position, and the named keys. */
static void check_contact_keys(lua_State *L, int idx, const char *fn)
{
    la_check_table(L, idx, fn);
    lua_pushnil(L);
    while (lua_next(L, idx)) {
        lua_pop(L, 1);
        if (lua_type(L, -1) == LUA_TNUMBER) {
            lua_Integer k = lua_tointeger(L, -1);
            if (k == 1 || k == 2) continue;
            luaL_error(L, "%s: takes two bodies by position, then law and mu by name", fn);
        }
        const char *k = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "?";
        if (strcmp(k, "law") && strcmp(k, "mu") && strcmp(k, "test") && strcmp(k, "update"))
            luaL_error(L, "%s: unknown key '%s' (known keys: the two bodies, law, mu, test, update)",
                       fn, k);
    }
}

static int sim_contact(lua_State *L)
{
    const char *fn = "sim:contact";
    la_sim *s = la_check_sim(L, 1);
    check_contact_keys(L, 2, fn);
    if (s->running) return luaL_error(L, "%s: contact cannot be added during a run", fn);
    int b[2];
    for (int k = 0; k < 2; k++) {
        lua_geti(L, 2, k + 1);
        if (lua_isnil(L, -1))
            return luaL_error(L, "%s: needs two bodies, a and b (body %s is missing)", fn,
                              k ? "b" : "a");
        if (!luaL_testudata(L, -1, LA_BODY))
            return luaL_error(L, "%s: %s must be a body (got %s)", fn, k ? "b" : "a",
                              luaL_typename(L, -1));
        lm_sim *owner;
        b[k] = la_check_body(L, -1, &owner);
        if (owner != s->sim)
            return luaL_error(L, "%s: %s is a body of another simulation", fn, k ? "b" : "a");
        lua_pop(L, 1);
    }
    const char *law_name = la_opt_string(L, 2, fn, "law", "release");
    int law = la_option(L, fn, "law", law_name, laws);
    double mu = 0;
    if (la_has(L, 2, "mu")) {
        if (law != 1)
            return luaL_error(L, "%s: mu is for law = \"friction\" (law is \"%s\")", fn,
                              law_name);
        mu = la_number(L, 2, fn, "mu");
        if (!(mu >= 0) || !isfinite(mu))
            return luaL_error(L, "%s: mu must be a finite number >= 0 (got %f)", fn, mu);
    } else if (law == 1) {
        return luaL_error(L, "%s: law = \"friction\" needs mu, the friction coefficient", fn);
    }
    int test = la_option(L, fn, "test", la_opt_string(L, 2, fn, "test", "lamina"), tests);
    int update = la_option(L, fn, "update", la_opt_string(L, 2, fn, "update", "lamina"), updates);
    lm_contact_law cl = law == 1 ? LM_CONTACT_FRICTION : LM_CONTACT_RELEASE;
    int k = lm_sim_add_contact(s->sim, b[0], b[1], cl, mu);
    if (k < 0 || lm_sim_contact_form(s->sim, k, test ? LM_CTEST_EQ26 : LM_CTEST_LAMINA,
                                     update ? LM_CUPDATE_EQ21 : LM_CUPDATE_LAMINA) < 0)
        return luaL_error(L, "%s: %s", fn, s->sim->err);
    return 0;
}

/* sim:contact_info() -> {stick, release, slide = nodes of the last step,
 * ke_before, ke_after = the grid kinetic energy at those nodes around the
 * correction}; nil without contact pairs. */
static int sim_contact_info(lua_State *L)
{
    la_sim *s = la_check_sim(L, 1);
    lm_contact_info c;
    if (lm_sim_contact_info(s->sim, &c) != 0) {
        lua_pushnil(L);
        return 1;
    }
    static const char *const states[] = {"stick", "release", "slide"};
    const long nodes[] = {c.stick, c.release, c.slide};
    lua_createtable(L, 0, 5);
    for (int k = 0; k < 3; k++) {   /* the nodes of each state */
        lua_pushinteger(L, nodes[k]);
        lua_setfield(L, -2, states[k]);
    }
    lua_pushnumber(L, c.ke_before); lua_setfield(L, -2, "ke_before");
    lua_pushnumber(L, c.ke_after); lua_setfield(L, -2, "ke_after");
    return 1;
}

/* sim:contact_normals(body) -> {x, y, nx, ny}: the body's outward grid
 * normals ([M] eqs 27-28, what sim:frame{contact = true} draws) at the
 * nodes where a pair met in the last step and the body has mass and a
 * normal, row by row; nil before the first step. */
static int sim_contact_normals(lua_State *L)
{
    const char *fn = "sim:contact_normals";
    la_sim *s = la_check_sim(L, 1);
    if (!luaL_testudata(L, 2, LA_BODY))
        return luaL_error(L, "%s: takes a body (got %s)", fn, luaL_typename(L, 2));
    lm_sim *owner;
    int b = la_check_body(L, 2, &owner);
    if (owner != s->sim) return luaL_error(L, "%s: the body is of another simulation", fn);
    int f = -1, nf = lm_sim_contact_fields(s->sim);
    const double *m = NULL, *nx = NULL, *ny = NULL;
    for (int k = 0; k < nf && f < 0; k++)
        if (lm_sim_contact_field(s->sim, k, &m, &nx, &ny) == b) f = k;
    if (f < 0) return luaL_error(L, "%s: the body is in no contact pair (sim:contact)", fn);
    const unsigned char *state = lm_sim_contact_state(s->sim);
    if (!state) {
        lua_pushnil(L);
        return 1;
    }
    const lm_grid *g = &s->sim->grid;
    static const char *const keys[] = {"x", "y", "nx", "ny"};
    lua_createtable(L, 0, 4);
    for (int k = 0; k < 4; k++) {
        lua_newtable(L);
        lua_setfield(L, -2, keys[k]);
    }
    lua_Integer n = 0;
    for (int j = 0; j <= g->ny; j++)
        for (int i = 0; i <= g->nx; i++) {
            long id = lm_grid_node(g, i, j);
            if (state[id] == LM_CNODE_NONE || !(m[id] > 0) || (nx[id] == 0 && ny[id] == 0))
                continue;
            const double v[4] = {g->x0 + i * g->hx, g->y0 + j * g->hy, nx[id], ny[id]};
            n++;
            for (int k = 0; k < 4; k++) {
                lua_getfield(L, -1, keys[k]);
                lua_pushnumber(L, v[k]);
                lua_rawseti(L, -2, n);
                lua_pop(L, 1);
            }
        }
    return 1;
}

/* Adds the methods to the sim's method table at the top of the stack. */
void la_contact_methods(lua_State *L)
{
    lua_pushcfunction(L, sim_contact_normals);
    lua_setfield(L, -2, "contact_normals");
    lua_pushcfunction(L, sim_contact);
    lua_setfield(L, -2, "contact");
    lua_pushcfunction(L, sim_contact_info);
    lua_setfield(L, -2, "contact_info");
}
