/* l_body3.c - sim:body{...} of a 3D run and its handle (com, velocity,
 * mass, energy, particles): the 2D names and meanings (l_body.c) with a
 * third component. A body is a contiguous range of the engine's particles
 * (la_body3rec); a handle keeps its simulation alive. */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "l_body_common.h"
#include "l_mesh3.h"
#include "l_pressure3.h"
#include "l_sim3.h"

typedef struct la_body3 { int index; } la_body3;

static la_body3 check_body3(lua_State *L, int idx, la_sim3 **s3)
{
    la_body3 b = {la_handle_check(L, idx, LA_BODY3)};   /* l_handle.c */
    *s3 = la_check_sim3(L, -1, "body");
    lua_pop(L, 1);
    return b;
}

/* ppc = n (a cube: 1, 8, 27, 64, ...) or {nx, ny, nz}; 8 (2 x 2 x 2), the
 * 2D default's 2 x 2 with a third direction, when absent. */
static void read_ppc3(lua_State *L, const char *fn, int k[3])
{
    int t = la_getfield(L, 2, "ppc");
    if (t == LUA_TNIL) {
        k[0] = k[1] = k[2] = 2;
    } else if (t == LUA_TTABLE) {
        if (lua_rawlen(L, -1) != 3)
            luaL_error(L, "%s: ppc = {nx, ny, nz}: three whole numbers in 3D (got %I)", fn,
                       (lua_Integer)lua_rawlen(L, -1));
        for (int a = 0; a < 3; a++) {
            lua_rawgeti(L, -1, a + 1);
            int ok;
            double v = lua_tonumberx(L, -1, &ok);
            if (!ok || v < 1 || v > LM3_MAX_PPC_DIR || v != floor(v))
                luaL_error(L, "%s: ppc[%d] must be a whole number from 1 to %d", fn, a + 1,
                           LM3_MAX_PPC_DIR);
            k[a] = (int)v;
            lua_pop(L, 1);
        }
    } else {
        int ok;
        double n = lua_tonumberx(L, -1, &ok);
        if (!ok) luaL_error(L, "%s: ppc must be a number or {nx, ny, nz} (got %s)", fn,
                            luaL_typename(L, -1));
        double r = floor(cbrt(n) + 0.5);
        if (!(n >= 1) || r * r * r != n || r > LM3_MAX_PPC_DIR)
            luaL_error(L, "%s: ppc = %f is not a cube number from 1 to %d (1, 8, 27, 64, ...) in "
                       "3D; use ppc = {nx, ny, nz} for other patterns", fn, n,
                       LM3_MAX_PPC_DIR * LM3_MAX_PPC_DIR * LM3_MAX_PPC_DIR);
        k[0] = k[1] = k[2] = (int)r;
    }
    lua_pop(L, 1);
}

/* The script's region and velocity functions as the engine's callbacks,
 * each called protected: an error stays on the stack, the callback
 * returns -1, the engine takes the body out again and sim:body raises it. */
typedef struct fill3 {
    lua_State *L;
    int ridx, vidx;
    const lm3_region *region;
    lm3_mesh_ray *mesh;         /* lamina.mesh: its inside test (l_mesh3.c) */
} fill3;

static int inside3(void *ctx, const double x[3])
{
    fill3 *c = ctx;
    if (c->region) return lm3_region_contains(c->region, x);
    lua_State *L = c->L;
    if (c->mesh) {
        int in = lm3_mesh_ray_inside(c->mesh, x);
        if (in < 0) lua_pushliteral(L, "sim:body: out of memory in the mesh's inside test");
        return in;
    }
    if (la_body_call(L, c->ridx, x, 3, 1)) return -1;
    int in = lua_toboolean(L, -1);
    lua_pop(L, 1);
    return in;
}

static int velocity3(void *ctx, const double x[3], double v[3])
{
    fill3 *c = ctx;
    lua_State *L = c->L;
    if (la_body_call(L, c->vidx, x, 3, 3)) return -1;
    for (int a = 0; a < 3; a++) {
        int ok;
        v[a] = lua_tonumberx(L, a - 3, &ok);
        if (!ok || !isfinite(v[a])) {
            lua_pushfstring(L, "sim:body: the velocity function must return three finite "
                            "numbers vx, vy, vz (at (%f, %f, %f))", x[0], x[1], x[2]);
            return -1;
        }
    }
    lua_pop(L, 3);
    return 0;
}

/* A lamina.gas's keys with no 3D form, refused by name: the 3D engine
 * finds rho_p by continuity only (sim3_step.c, rho /= det F) and does not
 * split points. */
static void gas_keys3(lua_State *L, const lm_material *m, const char *fn)
{
    if (m->density != LM_DENSITY_CONTINUITY)
        luaL_error(L, "%s: 'material': lamina.gas{density = ...}: 3D has density = "
                   "\"continuity\" only in this build", fn);
    if (m->split != 0)
        luaL_error(L, "%s: 'material': lamina.gas{split = %f}: 3D does not split points in "
                   "this build (leave split out)", fn, m->split);
}

/* The engine's index of the material at midx in this sim (added the first
 * time; the sim's uservalue table "mats3" maps material -> index). */
static int material3(lua_State *L, la_sim3 *s3, int midx, const char *fn)
{
    la_material *u = la_check_material(L, midx);
    if (u->def.kind != LM_ELASTIC && u->def.kind != LM_GAS)
        luaL_error(L, "%s: 'material': 3D has lamina.elastic solids and lamina.gas in this "
                   "build (membranes in 3D: issue 34)", fn);
    if (u->def.kind == LM_GAS) gas_keys3(L, &u->def, fn);
    if (u->def.kind == LM_ELASTIC && u->plane_given)
        luaL_error(L, "%s: 'material' has 'plane' set: a 3D solid has no plane assumption "
                   "(leave plane out of lamina.elastic{} for a 3D sim)", fn);
    lua_getiuservalue(L, 1, 1);
    la_subtable(L, -1, "mats3");
    lua_pushvalue(L, midx);
    if (lua_rawget(L, -2) == LUA_TNUMBER) {
        int k = (int)lua_tointeger(L, -1);
        lua_pop(L, 3);
        return k;
    }
    lua_pop(L, 1);
    lm3_material m = u->def.kind == LM_GAS ? la_gas3(&u->def)
                     : (lm3_material){.rho = u->def.rho, .E = u->def.E, .nu = u->def.nu,
                                      .kind = LM3_ELASTIC};
    char err[256];
    int k = lm3_material_add(s3->sim, &m, err, sizeof err);
    if (k < 0) luaL_error(L, "%s: material: %s", fn, err);
    lua_pushvalue(L, midx);
    lua_pushinteger(L, k);
    lua_rawset(L, -3);
    lua_pop(L, 2);
    /* and the material knows the sim (weakly), so that a live change
     * (mat.E = ...) reaches this copy too (l_material.c set_everywhere) */
    lua_getiuservalue(L, midx, 1);
    lua_pushvalue(L, 1);
    lua_pushinteger(L, k);
    lua_rawset(L, -3);
    lua_pop(L, 1);
    return k;
}

/* The arrays' capacity after n particles more (lu_reserve's doubling from
 * 1024, sim3.c), for charging the budget before they grow. */
static size_t cap_after(size_t cap, size_t need)
{
    size_t c = cap ? cap : 1024;
    while (c < need) c *= 2;
    return c;
}

int la_sim3_body(lua_State *L)
{
    static const char *const keys[] = {"material", "region", "ppc", "velocity", "name", NULL};
    const char *fn = "sim:body";
    la_sim3 *s3 = la_check_sim3(L, 1, fn);
    la_sim *s = la_check_sim_any(L, 1);
    if (la_has(L, 2, "fill"))
        luaL_error(L, "%s: 'fill' is 2D only (3D fills the sub-cell centres, the papers' rule)",
                   fn);
    int midx = la_body_args(L, s, fn, keys);   /* the material, the region above it */
    lm3_sim *sim = s3->sim;
    int ridx = midx + 1;
    fill3 fc = {L, ridx, 0, la_test_region3(L, ridx), NULL};
    la_mesh3 *mesh = la_test_mesh3(L, ridx);
    if (mesh) fc.mesh = la_mesh3_region(L, mesh, fn);   /* refused when open */
    if (la_test_region(L, ridx))
        return luaL_error(L, "%s: 'region' is a 2D region (lamina.disk/rect/polygon); with "
                          "dim = 3 use lamina.ball/box/cylinder or a function(x, y, z)", fn);
    if (!fc.region && !fc.mesh && !lua_isfunction(L, ridx))
        return luaL_error(L, "%s: 'region' must be lamina.ball/box/cylinder/mesh or a "
                          "function(x, y, z) -> boolean (got %s)", fn, luaL_typename(L, ridx));

    lm3_seed_def d;
    memset(&d, 0, sizeof d);
    read_ppc3(L, fn, d.k);
    if (la_getfield(L, 2, "velocity") == LUA_TFUNCTION) {
        fc.vidx = lua_gettop(L);
        d.velocity = velocity3;
    } else {
        lua_pop(L, 1);
        la_triple(L, 2, fn, "velocity", d.v0);
    }
    d.mat = material3(L, s3, midx, fn);
    for (int a = 0; a < 3; a++) {
        d.lo[a] = fc.region ? fc.region->lo[a] : mesh ? mesh->lo[a] : sim->def.lo[a];
        d.hi[a] = fc.region ? fc.region->hi[a] : mesh ? mesh->hi[a] : sim->def.hi[a];
    }
    d.inside = inside3;
    d.ctx = &fc;
    int top = lua_gettop(L);
    long count = lm3_seed_count(sim, &d);
    if (count < 0) {
        if (lua_gettop(L) > top) return lua_error(L);   /* the region function's error */
        return luaL_error(L, "%s: bad ppc", fn);
    }
    if (count == 0)
        return luaL_error(L, "%s: the region holds no particle (no sub-cell centre of ppc = "
                          "{%d, %d, %d} lies in it and in the domain)", fn, d.k[0], d.k[1],
                          d.k[2]);
    if ((size_t)count > LM_MAX_PARTICLES - sim->p.n)
        return luaL_error(L, "%s: %I particles more than the limit of %d", fn,
                          (lua_Integer)count, LM_MAX_PARTICLES);
    /* charged before the arrays grow: the process's one cap */
    la_sim3_charge(L, s3, lm3_grid_bytes(sim) +
                              lm3_particle_bytes(cap_after(sim->p.cap, sim->p.n + count)) +
                              la_membrane3_bytes(s3), fn);
    if (s3->nbodies == s3->capbodies) {
        int cap = s3->capbodies ? 2 * s3->capbodies : 8;
        la_body3rec *nb = realloc(s3->bodies, (size_t)cap * sizeof *nb);
        if (!nb) return luaL_error(L, "%s: out of memory", fn);
        s3->bodies = nb;
        s3->capbodies = cap;
    }
    size_t first = sim->p.n;
    long added = lm3_seed(sim, &d);
    if (added < 0) {
        if (lua_gettop(L) > top) return lua_error(L);
        return luaL_error(L, "%s: out of memory for %I particles", fn, (lua_Integer)count);
    }
    la_body3rec *rec = &s3->bodies[s3->nbodies];
    rec->first = first;
    rec->n = (size_t)added;
    rec->mat = d.mat;
    int bi = s3->nbodies++;

    la_getfield(L, 2, "name");
    la_body_handle_push(L, LA_BODY3, 1, bi, lua_gettop(L));
    return 1;
}

/* ---- the handle ------------------------------------------------------ */

static const la_body3rec *rec_of(lua_State *L, la_sim3 **s3)
{
    la_body3 b = check_body3(L, 1, s3);
    return &(*s3)->bodies[b.index];
}

const la_body3rec *la_check_body3(lua_State *L, int idx, la_sim3 **s3)
{
    la_body3 b = check_body3(L, idx, s3);
    return &(*s3)->bodies[b.index];
}

static int body3_triple(lua_State *L, int which)
{
    la_sim3 *s3;
    const la_body3rec *r = rec_of(L, &s3);
    double m, com[3], vel[3];
    lm3_range_sums(s3->sim, r->first, r->n, &m, com, vel);
    for (int a = 0; a < 3; a++) lua_pushnumber(L, which ? vel[a] : com[a]);
    return 3;
}

static int body3_com(lua_State *L) { return body3_triple(L, 0); }
static int body3_velocity(lua_State *L) { return body3_triple(L, 1); }

static int body3_mass(lua_State *L)
{
    la_sim3 *s3;
    const la_body3rec *r = rec_of(L, &s3);
    double m, com[3], vel[3];
    lm3_range_sums(s3->sim, r->first, r->n, &m, com, vel);
    lua_pushnumber(L, m);
    return 1;
}

static int body3_energy(lua_State *L)
{
    la_sim3 *s3;
    const la_body3rec *r = rec_of(L, &s3);
    lm3_energy e;
    lm3_range_energy(s3->sim, r->first, r->n, &e);
    la_sim3_push_energy(L, &e);
    return 1;
}

static void push_array(lua_State *L, const char *name, const double *a, size_t first,
                       size_t n)
{
    lua_createtable(L, (int)n, 0);
    for (size_t i = 0; i < n; i++) {
        lua_pushnumber(L, a[first + i]);
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    lua_setfield(L, -2, name);
}

/* body:particles(): arrays x, y, z, vx, vy, vz, mass, rho, the global
 * Cauchy stress sxx, syy, szz, syz, sxz, sxy, and n (the 2D names with the
 * third component's added); a gas body's also e and pressure (= p). */
static int body3_particles(lua_State *L)
{
    la_sim3 *s3;
    const la_body3rec *r = rec_of(L, &s3);
    const lm3_particles *p = &s3->sim->p;
    static const char *const xs[] = {"x", "y", "z"}, *const vs[] = {"vx", "vy", "vz"};
    static const char *const ss[] = {"sxx", "syy", "szz", "syz", "sxz", "sxy"};
    lua_createtable(L, 0, 16);
    for (int a = 0; a < 3; a++) push_array(L, xs[a], p->x[a], r->first, r->n);
    for (int a = 0; a < 3; a++) push_array(L, vs[a], p->v[a], r->first, r->n);
    push_array(L, "mass", p->m, r->first, r->n);
    push_array(L, "rho", p->rho, r->first, r->n);
    for (int c = 0; c < 6; c++) push_array(L, ss[c], p->s[c], r->first, r->n);
    const lm3_material *mat = &s3->sim->mats[r->mat];
    if (mat->kind == LM3_GAS) {
        /* a gas body's e and its equation of state's pressure (gamma - 1)
         * rho e ([F] eq 22; the 2D field table's "pressure", without q) */
        push_array(L, "e", p->e, r->first, r->n);
        lua_createtable(L, (int)r->n, 0);
        for (size_t i = 0; i < r->n; i++) {
            lua_pushnumber(L, la_pressure3(s3->sim, r->first + i));
            lua_rawseti(L, -2, (lua_Integer)i + 1);
        }
        lua_pushvalue(L, -1);
        lua_setfield(L, -3, "p");   /* the 2D handle's older key, the same array */
        lua_setfield(L, -2, "pressure");
    }
    lua_pushinteger(L, (lua_Integer)r->n);
    lua_setfield(L, -2, "n");
    return 1;
}

static int body3_pin(lua_State *L)
{
    la_sim3 *s3;
    const la_body3rec *r = rec_of(L, &s3);
    return la_body3_pin(L, s3, r->first, r->n);
}

static int body3_index(lua_State *L)
{
    la_sim3 *s3;
    la_body3 b = check_body3(L, 1, &s3);
    const char *k = luaL_checkstring(L, 2);
    if (la_body_handle_field(L, b.index, k)) return 1;   /* name, index, a method */
    /* the 2D handle's methods with no 3D form yet, named */
    luaL_getmetatable(L, LA_BODY);
    if (lua_istable(L, -1) && la_getfield(L, -1, "methods") == LUA_TTABLE &&
        la_getfield(L, -1, k) != LUA_TNIL)
        return luaL_error(L, "body:%s: not available for a 3D body in this build (issue 34)", k);
    return luaL_error(L, "body has no field or method '%s'", k);
}

void la_open_body3(lua_State *L)
{
    static const luaL_Reg meta[] = {{"__index", body3_index},
                                    {"__len", la_body_len},
                                    {"__tostring", la_body_tostring},
                                    {NULL, NULL}};
    static const luaL_Reg methods[] = {{"com", body3_com},
                                       {"velocity", body3_velocity},
                                       {"mass", body3_mass},
                                       {"energy", body3_energy},
                                       {"particles", body3_particles},
                                       {"pin", body3_pin},
                                       {"pressure", la_gas3_pressure},   /* l_membrane3_gas.c */
                                       {NULL, NULL}};
    la_new_class_in(L, LA_BODY3, meta, methods, "methods");   /* body3_index looks there */
    lua_pop(L, 1);
}
