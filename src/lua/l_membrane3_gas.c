/* l_membrane3_gas.c - a gas inside a closed 3D membrane, measured from
 * Lua (docs/api.md "Three dimensions", docs/3d.md "A gas inside a 3D
 * membrane"): the 2D handles' enclosed_area, escaped and pressure(membrane)
 * (l_body.c) in their 3D forms, over the engine's sim3_membrane_gas.c. */
#include <math.h>

#include "l_sim3.h"
#include "mpm3_membrane.h"

/* membrane:enclosed_volume() - the volume its points enclose (m^3; a
 * closed surface: (1/3) sum A (x - c) . n). */
int la_membrane3_volume(lua_State *L)
{
    la_sim3 *s3;
    int k = la_check_membrane3(L, 1, &s3);
    lua_pushnumber(L, lm3_membrane_volume(s3->sim, k));
    return 1;
}

static const la_body3rec *gas_arg(lua_State *L, int idx, const la_sim3 *s3, const char *fn)
{
    la_sim3 *s3b;
    if (!luaL_testudata(L, idx, LA_BODY3))
        luaL_error(L, "%s: argument %d must be a gas body of the same 3D sim (got %s)", fn, idx,
                   luaL_typename(L, idx));
    const la_body3rec *r = la_check_body3(L, idx, &s3b);
    if (s3b != s3) luaL_error(L, "%s: the gas and the membrane are of different sims", fn);
    if (s3->sim->mats[r->mat].kind != LM3_GAS)
        luaL_error(L, "%s: argument %d is not a gas body (lamina.gas)", fn, idx);
    return r;
}

/* membrane:escaped(gas) - the gas particles outside the membrane by more
 * than a quarter cell, the largest distance of any outside (m; 0 when
 * none is), and those outside within a quarter cell: the 2D method's
 * three values. */
int la_membrane3_escaped(lua_State *L)
{
    la_sim3 *s3;
    int k = la_check_membrane3(L, 1, &s3);
    const la_body3rec *r = gas_arg(L, 2, s3, "membrane:escaped(gas)");
    lm3_escaped e;
    if (lm3_membrane_escaped(s3->sim, k, r->first, r->n, 0.25 * s3->sim->grid.h, &e) != 0)
        return luaL_error(L, "membrane:escaped(gas): out of memory");
    lua_pushinteger(L, (lua_Integer)e.beyond);
    lua_pushnumber(L, e.deepest);
    lua_pushinteger(L, (lua_Integer)e.grazing);
    return 3;
}

/* gas:pressure(membrane) - the gas's pressure over the space the membrane
 * encloses, (gamma - 1) sum m e / V: the sum the internal forces use
 * (sum V_p p_p), over the enclosed volume, as the 2D gas:pressure(membrane)
 * over its polygon's area. Without a membrane it is refused: the 2D
 * handle's nodal mean has no 3D form in this build. */
int la_gas3_pressure(lua_State *L)
{
    if (lua_isnoneornil(L, 2))
        return luaL_error(L, "gas:pressure: in 3D give the membrane that encloses the gas, "
                          "gas:pressure(membrane) (the nodal mean of the 2D form is not "
                          "available for a 3D body in this build)");
    la_sim3 *s3;
    int k = la_check_membrane3(L, 2, &s3);
    const la_body3rec *r = gas_arg(L, 1, s3, "gas:pressure(membrane)");
    const lm3_material *mat = &s3->sim->mats[r->mat];
    const lm3_particles *p = &s3->sim->p;
    double me = 0;
    for (size_t q = r->first; q < r->first + r->n; q++) me += p->m[q] * p->e[q];
    lua_pushnumber(L, (mat->gamma - 1) * me / lm3_membrane_volume(s3->sim, k));
    return 1;
}
