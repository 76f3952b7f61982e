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
static const char *const laws[] = {"uniaxial", "plane_stress", NULL};

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

/* lamina.membrane{rho, E, nu, thickness, law, one_way} ([M] §3, [T] §5.1):
 * mass per unit length rho * thickness (per unit depth). */
int la_membrane_material(lua_State *L)
{
    static const char *const keys[] = {"rho", "E", "nu", "thickness", "law", "one_way", NULL};
    const char *fn = "lamina.membrane";
    la_check_keys(L, 1, fn, keys);
    lm_material *m = push_material(L);
    m->kind = LM_MEMBRANE;
    m->rho = la_number(L, 1, fn, "rho");
    m->E = la_number(L, 1, fn, "E");
    m->nu = la_opt_number(L, 1, fn, "nu", 0);
    m->thickness = la_number(L, 1, fn, "thickness");
    m->law = (lm_law)la_option(L, fn, "law", la_opt_string(L, 1, fn, "law", "uniaxial"), laws);
    lua_getfield(L, 1, "one_way");
    if (!lua_isnil(L, -1) && !lua_isboolean(L, -1))
        luaL_error(L, "%s: 'one_way' must be true or false", fn);
    m->one_way = lua_toboolean(L, -1);
    lua_pop(L, 1);
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
    else if (strcmp(k, "kind") == 0)
        lua_pushstring(L, m->kind == LM_MEMBRANE ? "membrane" : "elastic");
    else if (strcmp(k, "thickness") == 0 && m->kind == LM_MEMBRANE) lua_pushnumber(L, m->thickness);
    else if (strcmp(k, "law") == 0 && m->kind == LM_MEMBRANE) lua_pushstring(L, laws[m->law]);
    else if (strcmp(k, "one_way") == 0 && m->kind == LM_MEMBRANE) lua_pushboolean(L, m->one_way);
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
    else if (strcmp(k, "plane") == 0 && m->kind == LM_ELASTIC)
        next.plane = (lm_plane)la_option(L, "material", "plane", luaL_checkstring(L, 3), planes);
    else if (strcmp(k, "one_way") == 0 && m->kind == LM_MEMBRANE)
        next.one_way = lua_toboolean(L, 3);
    else if (strcmp(k, "law") == 0 && m->kind == LM_MEMBRANE)
        next.law = (lm_law)la_option(L, "material", "law", luaL_checkstring(L, 3), laws);
    else
        return luaL_error(L, "material field '%s' cannot be changed (changeable: E, nu, %s)", k,
                          m->kind == LM_MEMBRANE ? "law, one_way" : "plane");
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
    if (m->kind == LM_MEMBRANE) {
        lua_pushfstring(L, "lamina.membrane{rho = %f, E = %f, nu = %f, thickness = %f, "
                        "law = \"%s\", one_way = %s}", m->rho, m->E, m->nu, m->thickness,
                        laws[m->law], m->one_way ? "true" : "false");
        return 1;
    }
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
