/* l_membrane.c - sim:membrane{...}: a membrane or string as one layer of
 * points along a curve ([M] §3, [F] §3.2).
 *
 * Points are evenly spaced along the curve including both ends; the count
 * is rounded up from length / spacing (docs/design.md). Each point stands for
 * ds = length / intervals of membrane (ds exp(-e) unstrained, with an
 * initial logarithmic strain e) and weighs rho * thickness * ds exp(-e) per
 * unit depth; `end_mass` replaces the last point's mass (the papers' heavy
 * point). Points keep their curve order for connectivity normals. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "l_curve.h"

/* In the order of lm_normals (mpm.h). */
static const char *const normal_methods[] = {"connectivity", "isosurface", "hybrid", "linear",
                                             "colour", "quadratic_colour", "mass_matrix",
                                             "mass_matrix_quadratic", "cubic_colour", NULL};

/* initial_strain: a number for every point, or a function (u, i) -> strain
 * of the curve parameter u in [0, 1] and the point's index i (1-based). */
static double strain_at(lua_State *L, int sidx, double u, int i)
{
    if (sidx == 0) return 0;
    if (lua_isnumber(L, sidx)) return lua_tonumber(L, sidx);
    lua_pushvalue(L, sidx);
    lua_pushnumber(L, u);
    lua_pushinteger(L, i);
    lua_call(L, 2, 1);
    int ok;
    double e = lua_tonumberx(L, -1, &ok);
    if (!ok) luaL_error(L, "sim:membrane: initial_strain function must return a number");
    lua_pop(L, 1);
    return e;
}

/* "membrane 'skin'" or "membrane 3" for messages. */
static const char *label(lua_State *L, int nameidx, int body)
{
    if (nameidx && lua_isstring(L, nameidx))
        return lua_pushfstring(L, "membrane '%s'", lua_tostring(L, nameidx));
    return lua_pushfstring(L, "membrane %d", body + 1);
}

#define LA_MAX_MEMBRANE_POINTS 10000000

static int point_count(lua_State *L, const char *fn, const la_curve_points *cp, double h,
                       const char **what)
{
    double count = la_opt_number(L, 2, fn, "count", 0);
    int have_spacing = la_has(L, 2, "spacing");
    if ((count > 0) == have_spacing)
        luaL_error(L, "%s: give exactly one of 'spacing' and 'count'", fn);
    /* counted in double first: spacing = 1e-12 or count = 1e12 overflowed
     * an int and came out as one interval ("spacing 0.8 is larger than a
     * cell") */
    double iv;
    if (have_spacing) {
        double sp = la_number(L, 2, fn, "spacing");
        if (!(sp > 0)) luaL_error(L, "%s: spacing must be positive (got %f)", fn, sp);
        if (sp > h * (1 + LM_SPACING_SLACK))   /* 1.0003 cells is rounding: accepted */
            luaL_error(L, "%s: %s spacing %f is larger than a cell (%f) by more than 1 %%: "
                       "neighbouring points must stay within one cell or the membrane breaks",
                       fn, *what, sp, h);
        iv = ceil(cp->length / sp - 1e-9);
    } else {
        if (count != floor(count) || count < 2)
            luaL_error(L, "%s: count must be a whole number >= 2 (got %f)", fn, count);
        iv = cp->closed ? count : count - 1;
    }
    if (!(iv <= LA_MAX_MEMBRANE_POINTS)) {
        char m[64];   /* lua_pushfstring knows no %.0f */
        snprintf(m, sizeof m, "%.0f", cp->closed ? iv : iv + 1);
        luaL_error(L, "%s: %s would have %s points, more than the limit of %d per membrane",
                   fn, *what, m, LA_MAX_MEMBRANE_POINTS);
    }
    int intervals = iv < 1 ? 1 : (int)iv;
    return intervals;
}

int la_sim_membrane(lua_State *L)
{
    static const char *const keys[] = {"material", "curve", "spacing", "count", "normals",
                                       "initial_strain", "end_mass", "velocity", "name",
                                       "orient", "force", "colour_points", NULL};
    const char *fn = "sim:membrane";
    la_sim *s = la_check_sim(L, 1);
    la_check_keys(L, 2, fn, keys);
    la_opt_string(L, 2, fn, "name", NULL);   /* text or nothing (issue 31 item 7) */
    if (s->running) return luaL_error(L, "%s: membranes cannot be added during a run", fn);
    lm_sim *sim = s->sim;
    const lm_grid *g = &sim->grid;

    la_getfield(L, 2, "material");
    const la_material *mat = luaL_testudata(L, -1, LA_MATERIAL);
    if (!mat || mat->def.kind != LM_MEMBRANE)
        return luaL_error(L, "%s: 'material' must be lamina.membrane{...}", fn);
    int midx = lua_gettop(L);
    la_getfield(L, 2, "name");
    int nameidx = lua_gettop(L);
    const char *what = label(L, nameidx, sim->nbodies);

    la_getfield(L, 2, "curve");
    int cidx = lua_gettop(L);
    la_curve_points cp;
    if (la_curve_sample(L, cidx, &cp))
        return luaL_error(L, "%s: 'curve' must be lamina.segment/arc/polyline or a "
                          "function(u) -> x, y (got %s)", fn, luaL_typename(L, cidx));
    if (!(cp.length > 0)) return luaL_error(L, "%s: %s has zero length", fn, what);
    double h = fmin(g->hx, g->hy);
    int intervals = point_count(L, fn, &cp, h, &what);
    int n = cp.closed ? intervals : intervals + 1;
    double ds = cp.length / intervals;   /* within a cell: the engine checks */
    /* force: how the tension reaches the grid (membrane_force.c); "point"
     * is the papers' quadrature, "segment" the default: a stretched
     * membrane at rest stays at rest with it at any angle and spacing
     * (issue 13 item 2; docs/robustness.md "Which default") */
    static const char *const forces[] = {"point", "segment", NULL};
    int force = la_option(L, fn, "force", la_opt_string(L, 2, fn, "force", "segment"), forces);
    int method = la_option(L, fn, "normals",
                           la_opt_string(L, 2, fn, "normals", "connectivity"), normal_methods);
    /* orient = {x, y}: normals point away from that point (the gas's
     * centre); "neighbours": agree with their neighbours; default: away
     * from the curve's centroid for the constructions without connectivity */
    int orient = 0;
    double ox = 0, oy = 0;
    int ot = la_getfield(L, 2, "orient");
    lua_pop(L, 1);
    if (ot == LUA_TTABLE) {
        la_pair(L, 2, fn, "orient", &ox, &oy);
        orient = 1;
    } else if (ot == LUA_TSTRING) {
        static const char *const orients[] = {"none", "away", "neighbours", NULL};
        orient = la_option(L, fn, "orient", la_opt_string(L, 2, fn, "orient", "none"), orients);
        if (orient == 1) luaL_error(L, "%s: orient = \"away\" needs a point: orient = {x, y}", fn);
    } else if (ot != LUA_TNIL) {
        luaL_error(L, "%s: 'orient' must be {x, y} or \"neighbours\" or \"none\"", fn);
    }

    /* colour_points = body: the colour-function methods' colour carried on
     * that body's points too ([T] §7.5, Fig 66(b): fluid inside) */
    int colour_with = 0;
    if (la_getfield(L, 2, "colour_points") != LUA_TNIL) {
        lm_sim *cs = NULL;
        if (!luaL_testudata(L, -1, LA_BODY))
            return luaL_error(L, "%s: colour_points must be a body of this simulation (got %s)",
                              fn, luaL_typename(L, -1));
        int cb = la_check_body(L, lua_gettop(L), &cs);
        if (cs != sim)
            return luaL_error(L, "%s: colour_points must be a body of this simulation", fn);
        colour_with = cb + 1;
    }
    lua_pop(L, 1);
    double end_mass = la_opt_number(L, 2, fn, "end_mass", 0);
    if (la_has(L, 2, "end_mass") && !(end_mass > 0))
        return luaL_error(L, "%s: end_mass must be positive (got %f)", fn, end_mass);
    double vx = 0, vy = 0;
    int vidx = la_opt_velocity(L, 2, fn, &vx, &vy);
    int sidx = 0;
    int st = la_getfield(L, 2, "initial_strain");
    if (st == LUA_TNUMBER || st == LUA_TFUNCTION) sidx = lua_gettop(L);
    else if (st != LUA_TNIL)
        return luaL_error(L, "%s: initial_strain must be a number or a function(u, i)", fn);

    double *px = lua_newuserdatauv(L, 2 * (size_t)n * sizeof(double), 0);
    double *py = px + n;
    la_curve_place(&cp, n, px, py);

    /* The script's functions run first (any may fail): every point's strain
     * and velocity, before the engine is touched; the engine then checks
     * the membrane rules and creates it all or nothing. */
    double *pe = lua_newuserdatauv(L, 3 * (size_t)n * sizeof(double), 0);
    double *pux = pe + n, *puy = pe + 2 * (size_t)n;
    for (int k = 0; k < n; k++) {
        double u = cp.closed ? (double)k / n : (n > 1 ? (double)k / (n - 1) : 0);
        double ux = vx, uy = vy;
        pe[k] = strain_at(L, sidx, u, k + 1);
        if (vidx) {
            lua_pushvalue(L, vidx);
            lua_pushnumber(L, u);
            lua_pushinteger(L, k + 1);
            lua_call(L, 2, 2);
            int ok1, ok2;
            ux = lua_tonumberx(L, -2, &ok1);
            uy = lua_tonumberx(L, -1, &ok2);
            if (!ok1 || !ok2 || !isfinite(ux) || !isfinite(uy))
                return luaL_error(L, "%s: the velocity function must return two finite "
                                  "numbers", fn);
            lua_pop(L, 2);
        }
        pux[k] = ux;
        puy[k] = uy;
    }
    int mi = la_sim_material(L, 1, midx, fn);   /* the engine's copy */
    lm_membrane_def def;
    lm_membrane_def_default(&def);
    def.mat = mi;
    def.closed = cp.closed;
    def.n = (size_t)n;
    def.x = px;
    def.y = py;
    def.ds = ds;
    def.strain = pe;
    def.vx = pux;
    def.vy = puy;
    def.end_mass = end_mass;
    def.normals = (lm_normals)method;
    def.force = (lm_mforce)force;
    def.colour_with = colour_with;
    def.name = nameidx && lua_type(L, nameidx) == LUA_TSTRING ? lua_tostring(L, nameidx) : NULL;
    if (ot != LUA_TNIL) {
        def.orient = (lm_orient)orient;
        def.ox = ox;
        def.oy = oy;
    }
    int bi = lm_sim_create_membrane(sim, &def);
    if (bi < 0) return luaL_error(L, "%s: %s", fn, sim->err);
    la_push_body(L, 1, bi, nameidx);
    return 1;
}
