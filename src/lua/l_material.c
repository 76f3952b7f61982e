/* l_material.c - lamina.elastic{...} and live parameter changes.
 *
 * A material is a userdata holding an lm_material, the script's
 * definition; each simulation it is given to owns a copy (issue 33 item
 * 1). The userdata's uservalue is a weak-keyed table, sim -> the engine's
 * index of it there, so a change made from a callback (mat.E = 2000)
 * reaches every such engine, through lm_sim_set_material, at the next
 * step. Live changes are echoed to stderr with the time and step so that a
 * run can be replayed (docs/design.md, "Conventions"). */
#include <stdio.h>
#include <string.h>

#include "l_internal.h"
#include "l_sim3.h"

static const char *const planes[] = {"strain", "stress", NULL};
static const char *const densities[] = {"continuity", "cell", "quadratic", NULL};

la_material *la_check_material(lua_State *L, int idx)
{
    return luaL_checkudata(L, idx, LA_MATERIAL);
}

static void push_material(lua_State *L, const lm_material *def)
{
    la_material *u = lua_newuserdatauv(L, sizeof *u, 1);
    memset(u, 0, sizeof *u);
    u->def = *def;
    luaL_setmetatable(L, LA_MATERIAL);
    lua_newtable(L);                       /* sim -> index, the sims weakly */
    lua_createtable(L, 0, 1);
    lua_pushliteral(L, "k");
    lua_setfield(L, -2, "__mode");
    lua_setmetatable(L, -2);
    lua_setiuservalue(L, -2, 1);
}

/* The sims' list of their materials, by engine index (sim uservalue's
 * field "mats"), pushed; made when absent. */
static void push_sim_materials(lua_State *L, int sidx)
{
    lua_getiuservalue(L, sidx, 1);
    la_subtable(L, -1, "mats");
    lua_remove(L, -2);
}

int la_sim_material(lua_State *L, int sidx, int midx, const char *fn)
{
    sidx = lua_absindex(L, sidx);
    midx = lua_absindex(L, midx);
    la_sim *s = la_check_sim(L, sidx);
    la_material *u = la_check_material(L, midx);
    lua_getiuservalue(L, midx, 1);
    lua_pushvalue(L, sidx);
    if (lua_rawget(L, -2) == LUA_TNUMBER) {   /* given to this sim before */
        int k = (int)lua_tointeger(L, -1);
        lua_pop(L, 2);
        return k;
    }
    lua_pop(L, 1);
    int k = lm_sim_add_material(s->sim, &u->def);
    if (k < 0) return luaL_error(L, "%s: %s", fn, s->sim->err);
    lua_pushvalue(L, sidx);
    lua_pushinteger(L, k);
    lua_rawset(L, -3);
    lua_pop(L, 1);
    push_sim_materials(L, sidx);   /* the sim keeps the material, for restores */
    lua_pushvalue(L, midx);
    lua_rawseti(L, -2, k + 1);
    lua_pop(L, 1);
    return k;
}

/* Gives next to every sim the material at midx was given to (all or
 * nothing: each is checked before any changes), then to the material. */
static void set_everywhere(lua_State *L, int midx, const lm_material *next)
{
    la_material *u = la_check_material(L, midx);
    for (int pass = 0; pass < 2; pass++) {
        lua_getiuservalue(L, midx, 1);
        lua_pushnil(L);
        while (lua_next(L, -2)) {
            la_sim *s = lua_touserdata(L, -2);
            int k = (int)lua_tointeger(L, -1);
            lua_pop(L, 1);
            if (s && s->s3) {   /* a 3D run's copy (l_body3.c): E and nu */
                if (pass == 0 && next->plane != u->def.plane)
                    luaL_error(L, "material: plane has no meaning in 3D (sim %d is 3D)", s->index);
                if (pass == 1 && la_sim3_set_material(s->s3, k, next) != 0)
                    luaL_error(L, "material: %s", s->s3->sim->err);
                continue;
            }
            if (!s || !s->sim) continue;   /* collected, its key not yet cleared */
            const lm_material *now = s->sim->mats[k];
            if (pass == 0 && (next->kind != now->kind || next->rho != now->rho))
                luaL_error(L, "material: sim %d's copy has another kind or rho", s->index);
            if (pass == 1 && lm_sim_set_material(s->sim, k, next) != LM_OK)
                luaL_error(L, "material: %s", s->sim->err);
        }
        lua_pop(L, 1);
    }
    u->def = *next;
}

void la_material_sync(lua_State *L, int sidx)
{
    sidx = lua_absindex(L, sidx);
    la_sim *s = la_check_sim(L, sidx);
    push_sim_materials(L, sidx);
    for (int k = 0; k < s->sim->nmats; k++) {
        if (lua_rawgeti(L, -1, k + 1) == LUA_TUSERDATA) {
            lm_material now = *s->sim->mats[k];
            set_everywhere(L, lua_gettop(L), &now);
        }
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
}

/* A material constructor's start: its options (argument 1) checked
 * against keys, the definition with its kind and density rho. */
static lm_material new_material(lua_State *L, const char *fn, const char *const keys[],
                                lm_kind kind)
{
    la_check_keys(L, 1, fn, keys);
    lm_material m;
    memset(&m, 0, sizeof m);
    m.kind = kind;
    m.rho = la_number(L, 1, fn, "rho");
    return m;
}

/* The one place a Lua law name meets the engine's registry of membrane
 * laws (membrane_law.c): the name to its lm_law, refused with the list of
 * the laws there are. */
static lm_law law_option(lua_State *L, const char *fn, const char *value)
{
    const char *names[LM_LAW_COUNT + 1];
    for (int k = 0; k <= LM_LAW_COUNT; k++) names[k] = lm_law_name(k);
    return (lm_law)la_option(L, fn, "law", value, names);
}

static void validate(lua_State *L, const char *fn, const lm_material *m)
{
    char err[256];
    if (lm_material_validate(m, err, sizeof err))
        luaL_error(L, "%s: %s", fn, err);
}

/* A constructor's end: the definition checked and pushed as the material. */
static int push_new(lua_State *L, const char *fn, const lm_material *m)
{
    validate(L, fn, m);
    push_material(L, m);
    return 1;
}

int la_elastic(lua_State *L)
{
    static const char *const keys[] = {"rho", "E", "nu", "plane", NULL};
    const char *fn = "lamina.elastic";
    lm_material m = new_material(L, fn, keys, LM_ELASTIC);
    m.E = la_number(L, 1, fn, "E");
    m.nu = la_opt_number(L, 1, fn, "nu", 0.3);
    m.plane = (lm_plane)la_option(L, fn, "plane",
                                   la_opt_string(L, 1, fn, "plane", "strain"), planes);
    int plane_given = la_has(L, 1, "plane");
    push_new(L, fn, &m);
    la_check_material(L, -1)->plane_given = plane_given;
    return 1;
}

/* lamina.membrane{rho, E, nu, thickness, law, one_way} ([M] §3, [T] §5.1):
 * mass per unit length rho * thickness (per unit depth). */
int la_membrane_material(lua_State *L)
{
    static const char *const keys[] = {"rho", "E", "nu", "thickness", "law", "one_way", NULL};
    const char *fn = "lamina.membrane";
    lm_material m = new_material(L, fn, keys, LM_MEMBRANE);
    m.E = la_number(L, 1, fn, "E");
    m.nu = la_opt_number(L, 1, fn, "nu", 0);
    m.thickness = la_number(L, 1, fn, "thickness");
    m.law = law_option(L, fn, la_opt_string(L, 1, fn, "law", "uniaxial"));
    la_getfield(L, 1, "one_way");
    if (!lua_isnil(L, -1) && !lua_isboolean(L, -1))
        luaL_error(L, "%s: 'one_way' must be true or false", fn);
    m.one_way = lua_toboolean(L, -1);
    lua_pop(L, 1);
    return push_new(L, fn, &m);
}

/* lamina.gas{rho, e | p, gamma = 1.4, mu = 0, av} ([F] §3.3): av = true is
 * the paper's Sod artificial viscosity (c1 = c2 = 1, lambda = 0.75,
 * g = sqrt(2) h); a table {c1, c2, lambda, g} overrides; off when absent. */
int la_gas(lua_State *L)
{
    static const char *const keys[] = {"rho", "e", "p", "gamma", "mu", "av", "split",
                                       "density", NULL};
    static const char *const avkeys[] = {"c1", "c2", "lambda", "g", NULL};
    const char *fn = "lamina.gas";
    lm_material m = new_material(L, fn, keys, LM_GAS);
    m.gamma = la_opt_number(L, 1, fn, "gamma", 1.4);
    m.mu = la_opt_number(L, 1, fn, "mu", 0);
    m.split = la_opt_number(L, 1, fn, "split", 0);
    /* split = n keeps about n points per cell: past the particles-per-cell
     * limit (l_body.c) it would split every point at every step (1e308) */
    if (!(m.split >= 0) || !(m.split <= 4096))
        luaL_error(L, "%s: split must be >= 0 and at most 4096, the limit of points per "
                   "cell (got %f)", fn, m.split);
    m.density = (lm_density)la_option(L, fn, "density",
                                       la_opt_string(L, 1, fn, "density", "continuity"), densities);
    int has_e = la_has(L, 1, "e"), has_p = la_has(L, 1, "p");
    if (has_e == has_p) luaL_error(L, "%s: give exactly one of 'e' (specific internal "
                                   "energy) and 'p' (pressure)", fn);
    if (!(m.rho > 0)) luaL_error(L, "%s: rho must be positive (got %f)", fn, m.rho);
    if (!(m.gamma > 1)) luaL_error(L, "%s: gamma must be greater than 1 (got %f)", fn, m.gamma);
    if (has_e) {
        m.e0 = la_number(L, 1, fn, "e");
    } else {
        double pr = la_number(L, 1, fn, "p");
        if (!(pr >= 0)) luaL_error(L, "%s: p must be >= 0 (got %f)", fn, pr);
        m.e0 = pr / ((m.gamma - 1) * m.rho);   /* [F] eq 22 */
    }
    m.av_c1 = m.av_c2 = 1;
    m.av_lambda = 0.75;
    m.av_g = 0;
    int t = la_getfield(L, 1, "av");
    if (t == LUA_TBOOLEAN) {
        m.av = lua_toboolean(L, -1);
    } else if (t == LUA_TTABLE) {
        la_check_keys(L, -1, "lamina.gas av", avkeys);
        m.av = 1;
        m.av_c1 = la_opt_number(L, -1, fn, "c1", 1);
        m.av_c2 = la_opt_number(L, -1, fn, "c2", 1);
        m.av_lambda = la_opt_number(L, -1, fn, "lambda", 0.75);
        m.av_g = la_opt_number(L, -1, fn, "g", 0);
    } else if (t != LUA_TNIL) {
        luaL_error(L, "%s: 'av' must be true/false or {c1, c2, lambda, g}", fn);
    }
    lua_pop(L, 1);
    return push_new(L, fn, &m);
}

/* lamina.linear_fluid{rho, beta}: p = -beta div U ([F] eq 26). */
int la_linear_fluid(lua_State *L)
{
    static const char *const keys[] = {"rho", "beta", NULL};
    const char *fn = "lamina.linear_fluid";
    lm_material m = new_material(L, fn, keys, LM_LINEAR_FLUID);
    m.beta = la_number(L, 1, fn, "beta");
    return push_new(L, fn, &m);
}

static const char *kind_name(const lm_material *m)
{
    switch (m->kind) {
    case LM_MEMBRANE: return "membrane";
    case LM_GAS: return "gas";
    case LM_LINEAR_FLUID: return "linear_fluid";
    default: return "elastic";
    }
}

static int mat_index(lua_State *L)
{
    const lm_material *m = &la_check_material(L, 1)->def;
    const char *k = luaL_checkstring(L, 2);
    if (strcmp(k, "rho") == 0) lua_pushnumber(L, m->rho);
    else if (strcmp(k, "E") == 0) lua_pushnumber(L, m->E);
    else if (strcmp(k, "nu") == 0) lua_pushnumber(L, m->nu);
    else if (strcmp(k, "plane") == 0) lua_pushstring(L, planes[m->plane]);
    else if (strcmp(k, "kind") == 0) lua_pushstring(L, kind_name(m));
    else if (strcmp(k, "gamma") == 0 && m->kind == LM_GAS) lua_pushnumber(L, m->gamma);
    else if (strcmp(k, "mu") == 0 && m->kind == LM_GAS) lua_pushnumber(L, m->mu);
    else if (strcmp(k, "e") == 0 && m->kind == LM_GAS) lua_pushnumber(L, m->e0);
    else if (strcmp(k, "p") == 0 && m->kind == LM_GAS)
        lua_pushnumber(L, (m->gamma - 1) * m->rho * m->e0);
    else if (strcmp(k, "av") == 0 && m->kind == LM_GAS) lua_pushboolean(L, m->av);
    else if (strcmp(k, "density") == 0 && m->kind == LM_GAS) lua_pushstring(L, densities[m->density]);
    else if (strcmp(k, "beta") == 0 && m->kind == LM_LINEAR_FLUID) lua_pushnumber(L, m->beta);
    else if (strcmp(k, "thickness") == 0 && m->kind == LM_MEMBRANE) lua_pushnumber(L, m->thickness);
    else if (strcmp(k, "law") == 0 && m->kind == LM_MEMBRANE) lua_pushstring(L, lm_law_name(m->law));
    else if (strcmp(k, "one_way") == 0 && m->kind == LM_MEMBRANE) lua_pushboolean(L, m->one_way);
    else if (strcmp(k, "wave_speed") == 0) lua_pushnumber(L, lm_material_wave_speed(m));
    else return luaL_error(L, "material has no field '%s'", k);
    return 1;
}

/* rho is not live: particle masses were fixed from it at seeding. */
static int mat_newindex(lua_State *L)
{
    const lm_material *m = &la_check_material(L, 1)->def;
    const char *k = luaL_checkstring(L, 2);
    lm_material next = *m;
    if (strcmp(k, "mu") == 0 && m->kind == LM_GAS) next.mu = luaL_checknumber(L, 3);
    else if (strcmp(k, "av") == 0 && m->kind == LM_GAS) next.av = lua_toboolean(L, 3);
    else if (strcmp(k, "beta") == 0 && m->kind == LM_LINEAR_FLUID) next.beta = luaL_checknumber(L, 3);
    else if (strcmp(k, "E") == 0 && (m->kind == LM_ELASTIC || m->kind == LM_MEMBRANE))
        next.E = luaL_checknumber(L, 3);
    else if (strcmp(k, "nu") == 0 && (m->kind == LM_ELASTIC || m->kind == LM_MEMBRANE))
        next.nu = luaL_checknumber(L, 3);
    else if (strcmp(k, "plane") == 0 && m->kind == LM_ELASTIC)
        next.plane = (lm_plane)la_option(L, "material", "plane", luaL_checkstring(L, 3), planes);
    else if (strcmp(k, "one_way") == 0 && m->kind == LM_MEMBRANE)
        next.one_way = lua_toboolean(L, 3);
    else if (strcmp(k, "law") == 0 && m->kind == LM_MEMBRANE)
        next.law = law_option(L, "material", luaL_checkstring(L, 3));
    else
        return luaL_error(L, "material field '%s' cannot be changed (changeable: %s)", k,
                          m->kind == LM_MEMBRANE ? "E, nu, law, one_way"
                          : m->kind == LM_GAS ? "mu, av"
                          : m->kind == LM_LINEAR_FLUID ? "beta" : "E, nu, plane");
    validate(L, "material", &next);
    set_everywhere(L, 1, &next);
    la_log_change(L, "material", k, 3);   /* l_runlog.c: stderr and the run log */
    return 0;
}

static int mat_tostring(lua_State *L)
{
    const lm_material *m = &la_check_material(L, 1)->def;
    if (m->kind == LM_GAS) {
        lua_pushfstring(L, "lamina.gas{rho = %f, e = %f, gamma = %f, mu = %f, av = %s, "
                        "density = \"%s\"}", m->rho, m->e0, m->gamma, m->mu,
                        m->av ? "true" : "false", densities[m->density]);
        return 1;
    }
    if (m->kind == LM_LINEAR_FLUID) {
        lua_pushfstring(L, "lamina.linear_fluid{rho = %f, beta = %f}", m->rho, m->beta);
        return 1;
    }
    if (m->kind == LM_MEMBRANE) {
        lua_pushfstring(L, "lamina.membrane{rho = %f, E = %f, nu = %f, thickness = %f, "
                        "law = \"%s\", one_way = %s}", m->rho, m->E, m->nu, m->thickness,
                        lm_law_name(m->law), m->one_way ? "true" : "false");
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
    la_new_metatable(L, LA_MATERIAL);
    luaL_setfuncs(L, meta, 0);
    lua_pop(L, 1);
}
