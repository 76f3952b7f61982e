/* l_sim3.c - lamina.sim{dim = 3, ...}: the 3D run behind the same handle as
 * a 2D one (docs/3d.md "Lua API"). The userdata is the la_sim of l_sim.c
 * with its 2D engine NULL and s3 set, so the events, the run guard and the
 * recorders' bookkeeping are the 2D ones; the methods that mean the same in
 * both dimensions have the same names and semantics here (docs/api.md
 * "Three dimensions"), and a 2D-only method called on a 3D sim is refused
 * naming it (la_sim3_refuse). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "l_boundary.h"
#include "l_frame3d.h"
#include "l_sim3.h"
#include "mpm3_membrane.h"
#include "util.h"

static const char *const schemes[] = {"musl", "usl", NULL};
/* in lm_basis order (mpm.h); gimp is refused by the engine, naming it */
static const char *const bases[] = {"linear", "gimp", "bspline2", NULL};
static const char *const faces[] = {"x0", "x1", "y0", "y1", "z0", "z1", NULL};
static const char *const sides2d[] = {"left", "right", "bottom", "top", NULL};

int la_sim3_refuse(lua_State *L)
{
    lua_Debug ar;
    const char *name = "this method";
    if (lua_getstack(L, 0, &ar) && lua_getinfo(L, "n", &ar) && ar.name) name = ar.name;
    return luaL_error(L, "sim:%s: not available for a 3D simulation (dim = 3) in this build "
                      "(issue 34; docs/api.md \"Three dimensions\" lists what is)", name);
}

la_sim3 *la_check_sim3(lua_State *L, int idx, const char *fn)
{
    la_sim *s = la_check_sim_any(L, idx);
    if (!s->s3) luaL_error(L, "%s: the simulation is 2D (this is the 3D form)", fn);
    return s->s3;
}

int la_triple(lua_State *L, int idx, const char *fn, const char *key, double v[3])
{
    int t = la_getfield(L, idx, key);
    if (t == LUA_TNIL) {
        lua_pop(L, 1);
        return 0;
    }
    if (t != LUA_TTABLE)
        luaL_error(L, "%s: '%s' must be three numbers {x, y, z} (got %s)", fn, key,
                   luaL_typename(L, -1));
    lua_Integer n = (lua_Integer)lua_rawlen(L, -1);
    if (n != 3)
        luaL_error(L, "%s: '%s' must be three numbers {x, y, z} in 3D (got %I)", fn, key, n);
    for (int i = 0; i < 3; i++) {
        lua_rawgeti(L, -1, i + 1);
        int ok;
        v[i] = lua_tonumberx(L, -1, &ok);
        if (!ok) luaL_error(L, "%s: '%s'[%d] must be a number", fn, key, i + 1);
        if (!isfinite(v[i]))
            luaL_error(L, "%s: '%s'[%d] must be finite (got %f)", fn, key, i + 1, v[i]);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    return 1;
}

void la_sim3_charge(lua_State *L, la_sim3 *s3, size_t bytes, const char *fn)
{
    if (bytes <= s3->charged) return;
    size_t more = bytes - s3->charged;
    if (lu_budget_charge(LU_MEM_ENGINE, more) != 0)
        luaL_error(L, "%s: %s", fn, lu_budget_oom());
    s3->charged = bytes;
}

void la_sim3_free(la_sim3 *s3)
{
    if (!s3) return;
    lm3_sim_free(s3->sim);
    if (s3->charged) lu_budget_release(LU_MEM_ENGINE, s3->charged);
    free(s3->bodies);
    free(s3);
}

/* domain = {x0, y0, z0, x1, y1, z1} */
static void read_domain(lua_State *L, const char *fn, lm3_def *d)
{
    if (la_getfield(L, 1, "domain") == LUA_TNIL) luaL_error(L, "%s: 'domain' is required", fn);
    if (!lua_istable(L, -1) || lua_rawlen(L, -1) != 6)
        luaL_error(L, "%s: 'domain' must be {x0, y0, z0, x1, y1, z1} in 3D (got %s of %I)",
                   fn, luaL_typename(L, -1),
                   (lua_Integer)(lua_istable(L, -1) ? lua_rawlen(L, -1) : 0));
    double v[6];
    for (int i = 0; i < 6; i++) {
        lua_rawgeti(L, -1, i + 1);
        int ok;
        v[i] = lua_tonumberx(L, -1, &ok);
        if (!ok || !isfinite(v[i]))
            luaL_error(L, "%s: 'domain'[%d] must be a finite number", fn, i + 1);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    for (int a = 0; a < 3; a++) {
        d->lo[a] = v[a];
        d->hi[a] = v[a + 3];
    }
}

static void refuse_sides2d(lua_State *L, const char *fn)
{
    for (int i = 0; sides2d[i]; i++)
        if (la_has(L, -1, sides2d[i]))
            luaL_error(L, "%s: boundary.%s is a 2D side; with dim = 3 the faces are x0, "
                       "x1, y0, y1, z0, z1", fn, sides2d[i]);
}

/* boundary = "fixed" (every face) or {x0 =, x1 =, y0 =, y1 =, z0 =, z1 =};
 * faces not named keep the default, fixed. The 2D side names are refused
 * by name: a script ported from 2D must not leave z unconstrained silently. */
static void read_boundary(lua_State *L, const char *fn, lm3_def *d)
{
    la_read_boundary(L, fn, faces, "faces", refuse_sides2d, d->bc);
}

int la_sim3_new(lua_State *L)
{
    static const char *const keys[] = {"dim", "domain", "cell", "dt", "scheme", "gravity",
                                       "boundary", "courant", "basis", NULL};
    /* the 2D keys with no 3D meaning yet, refused by name before the
     * generic unknown-key message */
    static const char *const keys2d[] = {"pic", "seed", "threads", "stress", "axisymmetric",
                                         "mass", "damping", "substeps", "transfer", NULL};
    const char *fn = "lamina.sim";
    la_check_table(L, 1, fn);
    for (int i = 0; keys2d[i]; i++)
        if (la_has(L, 1, keys2d[i]))
            luaL_error(L, "%s: '%s' is not available with dim = 3 in this build (3D takes: "
                       "dim, domain, cell, dt, basis, scheme, gravity, boundary, courant)", fn,
                       keys2d[i]);
    la_check_keys(L, 1, fn, keys);
    lm3_def d;
    memset(&d, 0, sizeof d);
    read_domain(L, fn, &d);
    if (la_getfield(L, 1, "cell") == LUA_TTABLE)
        luaL_error(L, "%s: 'cell' is one number with dim = 3 (the grid is cubic)", fn);
    lua_pop(L, 1);
    d.cell = la_number(L, 1, fn, "cell");
    d.dt = la_number(L, 1, fn, "dt");
    d.scheme = (lm_scheme)la_option(L, fn, "scheme", la_opt_string(L, 1, fn, "scheme", "musl"),
                                    schemes);
    d.basis = (lm_basis)la_option(L, fn, "basis", la_opt_string(L, 1, fn, "basis", "bspline2"),
                                  bases);
    la_triple(L, 1, fn, "gravity", d.gravity);
    for (int f = 0; f < LM3_FACES; f++) d.bc[f] = LM_BC_FIXED;
    read_boundary(L, fn, &d);
    d.courant = la_opt_number(L, 1, fn, "courant", 1.0);
    if (!(d.courant > 0) || !isfinite(d.courant))
        luaL_error(L, "%s: courant must be a positive number (got %f)", fn, d.courant);

    la_sim *s = lua_newuserdatauv(L, sizeof *s, 1);
    memset(s, 0, sizeof *s);
    lamina_run *run = la_run(L);
    s->index = run ? ++run->nsims : 1;
    luaL_setmetatable(L, LA_SIM);
    lua_newtable(L);
    lua_setiuservalue(L, -2, 1);
    s->s3 = calloc(1, sizeof *s->s3);
    if (!s->s3) luaL_error(L, "%s: out of memory", fn);
    char err[256];
    /* the grid's bytes are charged before it is made (the process's one
     * cap, docs/security.md "Memory"); def_ok's LM3_MAX_NODES bounds it.
     * A refused definition's charge is given back when the sim is
     * collected (la_sim3_free). */
    la_sim3_charge(L, s->s3, lm3_def_grid_bytes(&d), fn);
    s->s3->sim = lm3_sim_create(&d, err, sizeof err);
    if (!s->s3->sim) luaL_error(L, "%s: %s", fn, err);
    la_sim3_charge(L, s->s3, lm3_grid_bytes(s->s3->sim), fn);
    return 1;
}

/* ---- fields ---------------------------------------------------------- */

static void push_triple(lua_State *L, const double v[3])
{
    lua_createtable(L, 3, 0);
    for (int i = 0; i < 3; i++) {
        lua_pushnumber(L, v[i]);
        lua_rawseti(L, -2, i + 1);
    }
}

int la_sim3_index(lua_State *L)
{
    la_sim3 *s3 = la_check_sim3(L, 1, "sim");
    const char *k = luaL_checkstring(L, 2);
    const lm3_sim *m = s3->sim;
    if (strcmp(k, "t") == 0) lua_pushnumber(L, m->t);
    else if (strcmp(k, "nstep") == 0) lua_pushinteger(L, m->nstep);
    else if (strcmp(k, "dt") == 0) lua_pushnumber(L, m->def.dt);
    else if (strcmp(k, "cell") == 0) lua_pushnumber(L, m->grid.h);
    else if (strcmp(k, "n") == 0) lua_pushinteger(L, (lua_Integer)m->p.n);
    else if (strcmp(k, "dim") == 0) lua_pushinteger(L, 3);
    else if (strcmp(k, "scheme") == 0) lua_pushstring(L, schemes[m->def.scheme]);
    else if (strcmp(k, "basis") == 0) lua_pushstring(L, bases[m->def.basis]);
    else if (strcmp(k, "courant") == 0) lua_pushnumber(L, m->def.courant);
    else if (strcmp(k, "gravity") == 0) push_triple(L, m->def.gravity);
    else if (strcmp(k, "domain") == 0) {
        lua_createtable(L, 6, 0);
        for (int i = 0; i < 6; i++) {
            lua_pushnumber(L, i < 3 ? m->def.lo[i] : m->def.hi[i - 3]);
            lua_rawseti(L, -2, i + 1);
        }
    } else {
        luaL_getmetafield(L, 1, "methods3");
        if (la_getfield(L, -1, k) != LUA_TNIL) return 1;
        luaL_getmetafield(L, 1, "methods");
        if (la_getfield(L, -1, k) != LUA_TNIL)
            return luaL_error(L, "sim:%s: not available for a 3D simulation (dim = 3) in this "
                              "build (issue 34; docs/api.md \"Three dimensions\" lists what "
                              "is)", k);
        return luaL_error(L, "sim has no field or method '%s'", k);
    }
    return 1;
}

/* Live settings between steps, logged as in 2D: gravity and courant. dt is
 * fixed in 3D for now: the engine's clock is nstep x dt (sim3_step.c). */
int la_sim3_newindex(lua_State *L)
{
    la_sim3 *s3 = la_check_sim3(L, 1, "sim");
    const char *k = luaL_checkstring(L, 2);
    lm3_sim *m = s3->sim;
    if (strcmp(k, "gravity") == 0) {
        lua_settop(L, 3);
        lua_newtable(L);
        lua_pushvalue(L, 3);
        lua_setfield(L, -2, "gravity");
        double g[3];
        la_triple(L, 4, "sim.gravity", "gravity", g);
        lua_pop(L, 1);
        if (lm3_set_gravity(m, g) != LM_OK) return luaL_error(L, "sim.%s", m->err);
    } else if (strcmp(k, "courant") == 0) {
        if (lm3_set_courant(m, luaL_checknumber(L, 3)) != LM_OK)
            return luaL_error(L, "sim.%s", m->err);
    } else {
        return luaL_error(L, "sim.%s cannot be changed in 3D (changeable: gravity, courant)", k);
    }
    la_log_change(L, "sim", k, 3);
    return 0;
}

int la_sim3_tostring(lua_State *L)
{
    la_sim3 *s3 = la_check_sim3(L, 1, "sim");
    const lm3_sim *m = s3->sim;
    lua_pushfstring(L, "lamina.sim (dim = 3, %d x %d x %d cells, %d particles, t = %f)",
                    m->grid.n[0], m->grid.n[1], m->grid.n[2], (int)m->p.n, m->t);
    return 1;
}

/* A lamina.gas as the 3D engine's gas: the same constants (the 2D and 3D
 * laws share lm_gas_av, sim3_gas.c), so a 3D run of a gas is the 2D one's
 * material. */
lm3_material la_gas3(const lm_material *m)
{
    lm3_material g = {.rho = m->rho, .kind = LM3_GAS, .gamma = m->gamma, .mu = m->mu,
                      .e0 = m->e0, .av = m->av, .av_c1 = m->av_c1, .av_c2 = m->av_c2,
                      .av_lambda = m->av_lambda, .av_g = m->av_g};
    return g;
}

int la_sim3_set_material(la_sim3 *s3, int k, const lm_material *m)
{
    if (k < 0 || k >= s3->sim->nmat) return -1;
    /* the live constants over the engine's copy (its kind stays); a gas's
     * live keys (mu, av) reach it with the rest of its constants */
    lm3_material next = s3->sim->mats[k];
    if (next.kind == LM3_GAS) {
        next = la_gas3(m);
    } else {
        next.rho = m->rho;
        next.E = m->E;
        next.nu = m->nu;
    }
    return lm3_material_set(s3->sim, k, &next) == LM_OK ? 0 : -1;
}

/* ---- diagnostics ----------------------------------------------------- */

void la_sim3_push_energy(lua_State *L, const lm3_energy *e)
{
    lua_createtable(L, 0, 5);
    lua_pushnumber(L, e->kinetic); lua_setfield(L, -2, "kinetic");
    lua_pushnumber(L, e->strain); lua_setfield(L, -2, "strain");
    /* the gases' stored energy, sum m e ([F] eq 23), as in 2D */
    lua_pushnumber(L, e->internal); lua_setfield(L, -2, "internal");
    lua_pushnumber(L, e->potential); lua_setfield(L, -2, "potential");
    lua_pushnumber(L, e->total); lua_setfield(L, -2, "total");
}

static int sim3_energy(lua_State *L)
{
    la_sim3 *s3 = la_check_sim3(L, 1, "sim:energy");
    lm3_energy e;
    lm3_energy_of(s3->sim, &e);
    la_sim3_push_energy(L, &e);
    /* the membranes' damping work (not in total: total + damped is
     * conserved), as the 2D sim's grid damping reports its own */
    lua_pushnumber(L, lm3_membrane_damped(s3->sim));
    lua_setfield(L, -2, "damped");
    return 1;
}

static int sim3_momentum(lua_State *L)
{
    la_sim3 *s3 = la_check_sim3(L, 1, "sim:momentum");
    double P[3];
    lm3_momentum(s3->sim, P);
    for (int a = 0; a < 3; a++) lua_pushnumber(L, P[a]);
    return 3;
}

static int sim3_hash(lua_State *L)
{
    la_sim3 *s3 = la_check_sim3(L, 1, "sim:hash");
    char buf[17];
    snprintf(buf, sizeof buf, "%016llx", (unsigned long long)lm3_sim_hash(s3->sim));
    lua_pushstring(L, buf);
    return 1;
}

static int sim3_courant(lua_State *L)
{
    la_sim3 *s3 = la_check_sim3(L, 1, "sim:courant_number");
    double c;
    lua_pushnumber(L, lm3_courant(s3->sim, &c));
    lua_pushnumber(L, c);
    return 2;
}

/* a 3D frame: the camera's view of the box (l_frame3d.c, docs/api.md
 * "3D frames") */
static int sim3_frame(lua_State *L)
{
    la_sim3 *s3 = la_check_sim3(L, 1, "sim:frame");
    return l_frame3d(L, s3->sim, 2);
}

void la_sim3_methods(lua_State *L)
{
    static const luaL_Reg methods[] = {{"body", la_sim3_body},
                                       {"vtk", la_sim_vtk},   /* both dimensions (l_vtk.c) */
                                       {"record", la_sim_record},   /* (l_record.c) */
                                       {"checkpoint", la_sim3_checkpoint},   /* (l_membrane3.c) */
                                       {"membrane", la_sim3_membrane},   /* (l_membrane3.c) */
                                       {"every", la_sim3_every},
                                       {"at", la_sim3_at},
                                       {"run", la_sim3_run},
                                       {"step", la_sim3_step},
                                       {"energy", sim3_energy},
                                       {"momentum", sim3_momentum},
                                       {"hash", sim3_hash},
                                       {"courant_number", sim3_courant},
                                       {"frame", sim3_frame},
                                       {NULL, NULL}};
    luaL_newlib(L, methods);
}
