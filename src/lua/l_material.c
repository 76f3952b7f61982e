/* l_material.c - lamina.elastic{...} and live parameter changes.
 *
 * A material is a userdata holding an lm_material; simulations borrow a
 * pointer to it and keep the userdata alive through their uservalue, so a
 * change made from a callback (mat.E = 2000) reaches the engine at the next
 * step. Live changes are echoed to stderr with the time and step so that a
 * run can be replayed (design.md, Conventions). */
#include <stdio.h>
#include <string.h>

#include "l_internal.h"

static const char *const planes[] = {"strain", "stress", NULL};

lm_material *la_check_material(lua_State *L, int idx)
{
    return luaL_checkudata(L, idx, LA_MATERIAL);
}

static lm_material *push_material(lua_State *L)
{
    lm_material *m = lua_newuserdatauv(L, sizeof *m, 0);
    memset(m, 0, sizeof *m);
    luaL_setmetatable(L, LA_MATERIAL);
    return m;
}

static void validate(lua_State *L, const char *fn, const lm_material *m)
{
    char err[256];
    if (lm_material_validate(m, err, sizeof err))
        luaL_error(L, "%s: %s", fn, err);
}

int la_elastic(lua_State *L)
{
    static const char *const keys[] = {"rho", "E", "nu", "plane", NULL};
    const char *fn = "lamina.elastic";
    la_check_keys(L, 1, fn, keys);
    lm_material *m = push_material(L);
    m->kind = LM_ELASTIC;
    m->rho = la_number(L, 1, fn, "rho");
    m->E = la_number(L, 1, fn, "E");
    m->nu = la_opt_number(L, 1, fn, "nu", 0.3);
    m->plane = (lm_plane)la_option(L, fn, "plane",
                                   la_opt_string(L, 1, fn, "plane", "strain"), planes);
    validate(L, fn, m);
    return 1;
}

static int mat_index(lua_State *L)
{
    lm_material *m = la_check_material(L, 1);
    const char *k = luaL_checkstring(L, 2);
    if (strcmp(k, "rho") == 0) lua_pushnumber(L, m->rho);
    else if (strcmp(k, "E") == 0) lua_pushnumber(L, m->E);
    else if (strcmp(k, "nu") == 0) lua_pushnumber(L, m->nu);
    else if (strcmp(k, "plane") == 0) lua_pushstring(L, planes[m->plane]);
    else if (strcmp(k, "kind") == 0) lua_pushstring(L, "elastic");
    else if (strcmp(k, "wave_speed") == 0) lua_pushnumber(L, lm_material_wave_speed(m));
    else return luaL_error(L, "material has no field '%s'", k);
    return 1;
}

/* rho is not live: particle masses were fixed from it at seeding. */
static int mat_newindex(lua_State *L)
{
    lm_material *m = la_check_material(L, 1);
    const char *k = luaL_checkstring(L, 2);
    lm_material next = *m;
    if (strcmp(k, "E") == 0) next.E = luaL_checknumber(L, 3);
    else if (strcmp(k, "nu") == 0) next.nu = luaL_checknumber(L, 3);
    else if (strcmp(k, "plane") == 0)
        next.plane = (lm_plane)la_option(L, "material", "plane", luaL_checkstring(L, 3), planes);
    else
        return luaL_error(L, "material field '%s' cannot be changed (changeable: E, nu, plane)", k);
    validate(L, "material", &next);
    *m = next;
    lamina_run *run = la_run(L);
    if (run && run->active)
        fprintf(stderr, "lamina: t = %.9g step %ld: material.%s = %s\n",
                run->active->t, run->active->step, k, luaL_tolstring(L, 3, NULL));
    return 0;
}

static int mat_tostring(lua_State *L)
{
    lm_material *m = la_check_material(L, 1);
    lua_pushfstring(L, "lamina.elastic{rho = %f, E = %f, nu = %f, plane = \"%s\"}",
                    m->rho, m->E, m->nu, planes[m->plane]);
    return 1;
}

void la_open_material(lua_State *L)
{
    static const luaL_Reg meta[] = {{"__index", mat_index},
                                    {"__newindex", mat_newindex},
                                    {"__tostring", mat_tostring},
                                    {NULL, NULL}};
    luaL_newmetatable(L, LA_MATERIAL);
    luaL_setfuncs(L, meta, 0);
    lua_pop(L, 1);
}
