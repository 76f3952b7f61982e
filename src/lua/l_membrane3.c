/* l_membrane3.c - sim:membrane{...} of a 3D run (issue 34 item 2,
 * docs/api.md "Three dimensions"): a lamina.membrane material on a
 * surface (lamina.sphere, lamina.rect3) sampled by the engine's samplers
 * (mpm3_membrane.h), its pins, and the handle (#m, particles, tension,
 * reaction). The 3D state file holds the membrane points
 * (sim3_membrane_state.c), so checkpoints and --restart keep them. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "l_mesh3.h"
#include "l_sim3.h"
#include "mpm3_membrane.h"

#define LA_SURFACE3 "lamina.surface3"
#define LA_MEMBRANE3 "lamina.membrane3"

/* ---- surfaces -------------------------------------------------------- */

typedef struct la_surface3 {
    int kind;                   /* 0 sphere, 1 rect3 */
    double c[3], r;             /* sphere */
    double o[3], u[3], v[3];    /* parallelogram o + a u + b v */
} la_surface3;

/* lamina.sphere{center = {x, y, z}, radius = r} */
int la_sphere(lua_State *L)
{
    static const char *const keys[] = {"center", "radius", NULL};
    const char *fn = "lamina.sphere";
    la_check_table(L, 1, fn);
    la_check_keys(L, 1, fn, keys);
    la_surface3 *s = lua_newuserdatauv(L, sizeof *s, 0);
    memset(s, 0, sizeof *s);
    if (!la_triple(L, 1, fn, "center", s->c)) return luaL_error(L, "%s: 'center' is required", fn);
    s->r = la_number(L, 1, fn, "radius");
    if (!(s->r > 0) || !isfinite(s->r))
        return luaL_error(L, "%s: 'radius' must be a positive finite number (got %f)", fn, s->r);
    luaL_setmetatable(L, LA_SURFACE3);
    return 1;
}

/* lamina.rect3{origin = {x, y, z}, u = {...}, v = {...}}: the
 * parallelogram origin + a u + b v, (a, b) in [0, 1]^2; its normal u x v */
int la_rect3(lua_State *L)
{
    static const char *const keys[] = {"origin", "u", "v", NULL};
    const char *fn = "lamina.rect3";
    la_check_table(L, 1, fn);
    la_check_keys(L, 1, fn, keys);
    la_surface3 *s = lua_newuserdatauv(L, sizeof *s, 0);
    memset(s, 0, sizeof *s);
    s->kind = 1;
    if (!la_triple(L, 1, fn, "origin", s->o)) return luaL_error(L, "%s: 'origin' is required", fn);
    if (!la_triple(L, 1, fn, "u", s->u)) return luaL_error(L, "%s: 'u' is required", fn);
    if (!la_triple(L, 1, fn, "v", s->v)) return luaL_error(L, "%s: 'v' is required", fn);
    luaL_setmetatable(L, LA_SURFACE3);
    return 1;
}

static int surface3_tostring(lua_State *L)
{
    const la_surface3 *s = luaL_checkudata(L, 1, LA_SURFACE3);
    if (s->kind == 0)
        lua_pushfstring(L, "lamina.sphere{center = {%f, %f, %f}, radius = %f}", s->c[0], s->c[1],
                        s->c[2], s->r);
    else
        lua_pushfstring(L, "lamina.rect3{origin = {%f, %f, %f}, u = {%f, %f, %f}, v = {%f, %f, %f}}",
                        s->o[0], s->o[1], s->o[2], s->u[0], s->u[1], s->u[2], s->v[0], s->v[1],
                        s->v[2]);
    return 1;
}

/* ---- the handle ------------------------------------------------------ */

typedef struct la_membrane3 {
    int index;                  /* the engine's membrane */
    int pin;                    /* its pin, -1 none */
} la_membrane3;

static la_membrane3 *check_m3(lua_State *L, la_sim3 **s3)
{
    la_membrane3 *m = luaL_checkudata(L, 1, LA_MEMBRANE3);
    lua_getiuservalue(L, 1, 1);
    *s3 = la_check_sim3(L, -1, "membrane");
    lua_pop(L, 1);
    return m;
}

int la_check_membrane3(lua_State *L, int idx, la_sim3 **s3)
{
    la_membrane3 *m = luaL_checkudata(L, idx, LA_MEMBRANE3);
    lua_getiuservalue(L, idx, 1);
    *s3 = la_check_sim3(L, -1, "membrane");
    lua_pop(L, 1);
    return m->index;
}

static const lm3_membrane *rec_of(lua_State *L, la_sim3 **s3)
{
    la_membrane3 *m = check_m3(L, s3);
    return &(*s3)->sim->mem->mem[m->index];
}

static void push_array(lua_State *L, const char *key, const double *a, size_t first, size_t n,
                       double scale)
{
    lua_createtable(L, (int)n, 0);
    for (size_t i = 0; i < n; i++) {
        lua_pushnumber(L, scale * a[first + i]);
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    lua_setfield(L, -2, key);
}

/* columns: x, y, z, vx, vy, vz, nx, ny, nz, area (current: A0 exp(e11 +
 * e22)), mass, t11, t22, t12 (tension components, N/m: thickness times
 * the stress in the point's frame t1, t2) and tension (the mean,
 * lm3_membrane_tension) */
static int m3_particles(lua_State *L)
{
    la_sim3 *s3;
    const lm3_membrane *r = rec_of(L, &s3);
    const lm3_mpoints *p = &s3->sim->mem->p;
    const size_t f = r->first, n = r->count;
    const double th = r->def.mat.thickness;
    static const char *const xs[] = {"x", "y", "z"}, *const vs[] = {"vx", "vy", "vz"};
    static const char *const ns[] = {"nx", "ny", "nz"}, *const ts[] = {"t11", "t22", "t12"};
    /* the computed columns' values, kept on the stack below the result */
    double *col = lua_newuserdatauv(L, (n ? n : 1) * sizeof(double), 0);
    lua_createtable(L, 0, 18);
    for (int a = 0; a < 3; a++) push_array(L, xs[a], p->x[a], f, n, 1);
    for (int a = 0; a < 3; a++) push_array(L, vs[a], p->v[a], f, n, 1);
    for (int a = 0; a < 3; a++) push_array(L, ns[a], p->nrm[a], f, n, 1);
    for (int a = 0; a < 3; a++) push_array(L, ts[a], p->s[a], f, n, th);
    push_array(L, "mass", p->m, f, n, 1);
    for (size_t i = 0; i < n; i++) col[i] = p->A0[f + i] * exp(p->e[0][f + i] + p->e[1][f + i]);
    push_array(L, "area", col, 0, n, 1);
    for (size_t i = 0; i < n; i++) col[i] = lm3_membrane_tension(s3->sim, f + i);
    push_array(L, "tension", col, 0, n, 1);
    lua_pushinteger(L, (lua_Integer)n);
    lua_setfield(L, -2, "n");
    return 1;
}

/* the mean over the points of (s11 + s22) t / 2 (N/m) */
static int m3_tension(lua_State *L)
{
    la_sim3 *s3;
    const lm3_membrane *r = rec_of(L, &s3);
    double T = 0;
    for (size_t i = 0; i < r->count; i++) T += lm3_membrane_tension(s3->sim, r->first + i);
    lua_pushnumber(L, T / (double)r->count);
    return 1;
}

/* the pin's reaction of the last step {fx, fy, fz} (N) */
static int m3_reaction(lua_State *L)
{
    la_sim3 *s3;
    la_membrane3 *m = check_m3(L, &s3);
    if (m->pin < 0) return luaL_error(L, "membrane:reaction: this membrane has no pin (pin = ...)");
    const double *R = s3->sim->mem->pins[m->pin].reaction;
    lua_createtable(L, 3, 0);
    for (int a = 0; a < 3; a++) {
        lua_pushnumber(L, R[a]);
        lua_rawseti(L, -2, a + 1);
    }
    return 1;
}

/* m:normals("linear" | "quadratic") -> {nx, ny, nz, n, undefined}: the
 * construction's normals from the present points alone ([N] Fig 5's
 * trilinear or Fig 11's triquadratic fit on the running grid's centred
 * elements, lm3_membrane_construction), turned out as the step's are;
 * `undefined` counts the points given the frame's normal instead (zero
 * gradient). Whatever the membrane's own `normals`: the step is untouched. */
static int m3_normals(lua_State *L)
{
    la_sim3 *s3;
    la_membrane3 *m = check_m3(L, &s3);
    static const char *const bases[] = {"linear", "quadratic", NULL};
    int b = luaL_checkoption(L, 2, NULL, bases);
    const lm3_membrane *r = &s3->sim->mem->mem[m->index];
    size_t n = r->count;
    double *nrm[3];
    for (int a = 0; a < 3; a++) {
        nrm[a] = lua_newuserdatauv(L, (n ? n : 1) * sizeof(double), 0);  /* kept on the stack */
    }
    size_t und = 0;
    char err[256];
    if (lm3_membrane_construction(s3->sim, m->index, b ? LM3_MN_QUADRATIC : LM3_MN_LINEAR, nrm,
                                  &und, NULL, err, sizeof err) != 0)
        return luaL_error(L, "membrane:normals: %s", err);
    lua_createtable(L, 0, 5);
    static const char *const ns[] = {"nx", "ny", "nz"};
    for (int a = 0; a < 3; a++) push_array(L, ns[a], nrm[a], 0, n, 1.0);
    lua_pushinteger(L, (lua_Integer)n);
    lua_setfield(L, -2, "n");
    lua_pushinteger(L, (lua_Integer)und);
    lua_setfield(L, -2, "undefined");
    return 1;
}

static int m3_len(lua_State *L)
{
    la_sim3 *s3;
    lua_pushinteger(L, (lua_Integer)rec_of(L, &s3)->count);
    return 1;
}

static int m3_tostring(lua_State *L)
{
    la_sim3 *s3;
    la_membrane3 *m = check_m3(L, &s3);
    lua_pushfstring(L, "lamina.membrane %d (3D, %d points)", m->index + 1,
                    (int)s3->sim->mem->mem[m->index].count);
    return 1;
}

static int m3_index(lua_State *L)
{
    la_sim3 *s3;
    la_membrane3 *m = check_m3(L, &s3);
    const char *k = luaL_checkstring(L, 2);
    if (strcmp(k, "index") == 0) {
        lua_pushinteger(L, m->index + 1);
        return 1;
    }
    luaL_getmetafield(L, 1, "methods");
    if (la_getfield(L, -1, k) != LUA_TNIL) return 1;
    return luaL_error(L, "membrane has no field or method '%s' (3D: particles, tension, "
                      "reaction, normals)", k);
}

/* ---- sim:membrane ---------------------------------------------------- */

/* The bytes the membrane arrays hold at capacity cap (sim3_membrane.c's
 * lm3_mpoints: 26 doubles, a node index, a pin flag, a membrane index). */
static size_t mpoint_bytes(size_t cap)
{
    return cap * (26 * sizeof(double) + sizeof(int32_t) + sizeof(uint8_t) + sizeof(uint16_t));
}

size_t la_membrane3_bytes(const la_sim3 *s3)
{
    return s3->sim->mem ? mpoint_bytes(s3->sim->mem->p.cap) : 0;
}

/* The capacity after `more` points (sim3_membrane.c's lu_reserve doubling
 * from 1024), for charging before the arrays grow. */
static size_t cap_after(size_t cap, size_t need)
{
    size_t c = cap ? cap : 1024;
    while (c < need) c *= 2;
    return c;
}

/* The points the sampler will make, at least (ceil and round taken up by
 * one each way), for charging before it allocates; 0 when above the
 * engine's limit (the sampler refuses those by name). */
static size_t points_estimate(const la_surface3 *s, double spacing)
{
    double n;
    if (s->kind == 0) {
        n = fmax(12, floor(4 * 3.14159265358979323846 * s->r * s->r / (spacing * spacing)) + 1);
    } else {
        double uu = 0, uv = 0, vv = 0;
        for (int k = 0; k < 3; k++) {
            uu += s->u[k] * s->u[k];
            uv += s->u[k] * s->v[k];
            vv += s->v[k] * s->v[k];
        }
        double lu = sqrt(uu), lvp = uu > 0 ? sqrt(fmax(0, vv - uv * uv / uu)) : 0;
        n = (ceil(lu / spacing) + 1) * (ceil(lvp / spacing) + 1);
    }
    return n <= LM_MAX_PARTICLES ? (size_t)n : 0;
}

static void plane_coords(const la_surface3 *s, const double x[3], double *a, double *b)
{
    /* solve x - o = a u + b v in the plane (the 2 x 2 normal equations) */
    double d[3], uu = 0, uv = 0, vv = 0, du = 0, dv = 0;
    for (int k = 0; k < 3; k++) {
        d[k] = x[k] - s->o[k];
        uu += s->u[k] * s->u[k];
        uv += s->u[k] * s->v[k];
        vv += s->v[k] * s->v[k];
        du += d[k] * s->u[k];
        dv += d[k] * s->v[k];
    }
    double det = uu * vv - uv * uv;
    *a = (du * vv - dv * uv) / det;
    *b = (dv * uu - du * uv) / det;
}

/* pin = "edges" (rect3: the outermost row of points on each side) or a
 * function(x, y, z) -> boolean: the indices in *idx (malloc'd), their
 * count returned. The sample is freed on error by the caller's guard. */
static size_t pin_points(lua_State *L, int pidx, const la_surface3 *surf, const lm3_msample *smp,
                         const uint8_t *rim, size_t *idx, const char *fn)
{
    size_t np = 0;
    if (lua_type(L, pidx) == LUA_TSTRING) {
        const char *w = lua_tostring(L, pidx);
        if (strcmp(w, "edges") != 0)
            luaL_error(L, "%s: pin = \"%s\": the named set is \"edges\" (or a function(x, y, z) "
                       "-> boolean)", fn, w);
        if (!surf) {   /* a mesh: the points on its rim */
            for (size_t q = 0; rim && q < smp->n; q++)
                if (rim[q]) idx[np++] = q;
            if (np == 0)
                luaL_error(L, "%s: pin = \"edges\": the mesh is closed and has no edges", fn);
            return np;
        }
        if (surf->kind != 1)
            luaL_error(L, "%s: pin = \"edges\": a sphere is closed and has no edges", fn);
        double amin = INFINITY, amax = -INFINITY, bmin = INFINITY, bmax = -INFINITY;
        for (size_t q = 0; q < smp->n; q++) {
            double x[3] = {smp->x[0][q], smp->x[1][q], smp->x[2][q]}, a, b;
            plane_coords(surf, x, &a, &b);
            amin = fmin(amin, a);
            amax = fmax(amax, a);
            bmin = fmin(bmin, b);
            bmax = fmax(bmax, b);
        }
        /* the rows sit at the sub-parallelograms' centres: a point is on an
         * edge row within a small fraction of the row spacing */
        const double tol = 1e-9;
        for (size_t q = 0; q < smp->n; q++) {
            double x[3] = {smp->x[0][q], smp->x[1][q], smp->x[2][q]}, a, b;
            plane_coords(surf, x, &a, &b);
            if (a < amin + tol || a > amax - tol || b < bmin + tol || b > bmax - tol)
                idx[np++] = q;
        }
        return np;
    }
    for (size_t q = 0; q < smp->n; q++) {
        lua_pushvalue(L, pidx);
        for (int a = 0; a < 3; a++) lua_pushnumber(L, smp->x[a][q]);
        lua_call(L, 3, 1);
        if (lua_toboolean(L, -1)) idx[np++] = q;
        lua_pop(L, 1);
    }
    return np;
}

/* the sample's arrays, freed by __gc if an error unwinds past them */
typedef struct sample_guard { lm3_msample s; size_t *idx; uint8_t *rim; } sample_guard;

static void guard_free(sample_guard *g)
{
    lm3_msample_free(&g->s);
    memset(&g->s, 0, sizeof g->s);
    free(g->idx);
    g->idx = NULL;
    free(g->rim);
    g->rim = NULL;
}

static int guard_gc(lua_State *L)
{
    guard_free(lua_touserdata(L, 1));
    return 0;
}

int la_sim3_membrane(lua_State *L)
{
    static const char *const keys[] = {"material", "surface", "spacing", "pressure", "damping",
                                       "pin", "normals", "initial_strain", "velocity", "name",
                                       NULL};
    static const char *const normals[] = {"connectivity", "linear", "quadratic", NULL};
    const char *fn = "sim:membrane";
    la_sim3 *s3 = la_check_sim3(L, 1, fn);
    la_sim *s = la_check_sim_any(L, 1);
    la_check_table(L, 2, fn);
    if (la_has(L, 2, "curve"))
        return luaL_error(L, "%s: 'curve' is 2D only: a 3D membrane is a surface (surface = "
                          "lamina.sphere{...} or lamina.rect3{...})", fn);
    la_check_keys(L, 2, fn, keys);
    la_opt_string(L, 2, fn, "name", NULL);
    if (s->running) return luaL_error(L, "%s: membranes cannot be added during a run", fn);
    lm3_sim *sim = s3->sim;

    la_getfield(L, 2, "material");
    const la_material *mat = luaL_testudata(L, -1, LA_MATERIAL);
    if (!mat || mat->def.kind != LM_MEMBRANE)
        return luaL_error(L, "%s: 'material' must be lamina.membrane{...}", fn);
    la_getfield(L, 2, "surface");
    const la_surface3 *surf = luaL_testudata(L, -1, LA_SURFACE3);
    const la_mesh3 *mesh = la_test_mesh3(L, -1);   /* lamina.mesh (l_mesh3.c) */
    if (!surf && !mesh)
        return luaL_error(L, "%s: 'surface' must be lamina.sphere{center, radius}, "
                          "lamina.rect3{origin, u, v} or lamina.mesh{file} (got %s)", fn,
                          luaL_typename(L, -1));

    lm3_mdef def;
    lm3_mdef_default(&def);
    def.mat = mat->def;
    double spacing = la_opt_number(L, 2, fn, "spacing", sim->def.cell / 2);
    if (!(spacing > 0) || !isfinite(spacing))
        return luaL_error(L, "%s: 'spacing' must be a positive finite number (got %f)", fn,
                          spacing);
    def.pressure = la_opt_number(L, 2, fn, "pressure", 0);
    def.damping = la_opt_number(L, 2, fn, "damping", 0);
    if (!isfinite(def.pressure))
        return luaL_error(L, "%s: 'pressure' must be finite (got %f)", fn, def.pressure);
    if (!(def.damping >= 0) || !isfinite(def.damping))
        return luaL_error(L, "%s: 'damping' must be a finite number >= 0 (got %f)", fn,
                          def.damping);
    def.initial_strain = la_opt_number(L, 2, fn, "initial_strain", 0);
    if (!isfinite(def.initial_strain) || def.initial_strain <= -1)
        return luaL_error(L, "%s: 'initial_strain' must be a finite number above -1 (got %f)",
                          fn, def.initial_strain);
    la_triple(L, 2, fn, "velocity", def.v);
    def.normals = (lm3_mnormals)la_option(
        L, fn, "normals", la_opt_string(L, 2, fn, "normals", "connectivity"), normals);
    int pt = la_getfield(L, 2, "pin");
    int pidx = lua_gettop(L);
    if (pt != LUA_TNIL && pt != LUA_TSTRING && pt != LUA_TFUNCTION)
        return luaL_error(L, "%s: 'pin' must be \"edges\" or a function(x, y, z) -> boolean "
                          "(got %s)", fn, luaL_typename(L, pidx));

    /* charged before the sampler allocates: the process's one cap, with
     * the particles' and the grid's (l_body3.c charges the same sum) */
    size_t have = sim->mem ? sim->mem->p.n : 0, cap = sim->mem ? sim->mem->p.cap : 0;
    char err[600];
    size_t est = mesh ? la_mesh3_points(mesh, spacing, err, sizeof err)
                      : points_estimate(surf, spacing);
    if (mesh && est == 0) return luaL_error(L, "%s: 'surface': %s", fn, err);
    if (est)
        la_sim3_charge(L, s3, lm3_grid_bytes(sim) + lm3_particle_bytes(sim->p.cap) +
                                  mpoint_bytes(cap_after(cap, have + est)), fn);
    sample_guard *g = lua_newuserdatauv(L, sizeof *g, 0);
    memset(g, 0, sizeof *g);
    lua_createtable(L, 0, 1);
    lua_pushcfunction(L, guard_gc);
    lua_setfield(L, -2, "__gc");
    lua_setmetatable(L, -2);
    int rc = mesh ? la_mesh3_sample(mesh, spacing, &g->s, pt == LUA_TSTRING ? &g->rim : NULL,
                                    err, sizeof err)
             : surf->kind == 0
                 ? lm3_sample_sphere(surf->c, surf->r, spacing, &g->s, err, sizeof err)
                 : lm3_sample_rect3(surf->o, surf->u, surf->v, spacing, &g->s, err, sizeof err);
    if (rc != 0) return luaL_error(L, "%s: 'surface': %s", fn, err);
    size_t np = 0;
    if (pt != LUA_TNIL) {
        g->idx = malloc((g->s.n ? g->s.n : 1) * sizeof *g->idx);
        if (!g->idx) return luaL_error(L, "%s: out of memory", fn);
        np = pin_points(L, pidx, surf, &g->s, g->rim, g->idx, fn);
        if (np == 0) return luaL_error(L, "%s: 'pin' holds no point of the membrane", fn);
    }
    if (sim->mem && sim->mem->nmem >= LM3_MAX_MEMBRANES)
        return luaL_error(L, "%s: more than %d membranes", fn, LM3_MAX_MEMBRANES);
    /* and the count made (no more than estimated: no new charge) */
    la_sim3_charge(L, s3, lm3_grid_bytes(sim) + lm3_particle_bytes(sim->p.cap) +
                              mpoint_bytes(cap_after(cap, have + g->s.n)), fn);
    int k = lm3_membrane_add(sim, &def, &g->s);
    if (k < 0) return luaL_error(L, "%s: %s", fn, sim->err);
    int pin = -1;
    if (np) {
        pin = lm3_membrane_pin(sim, k, g->idx, np);
        if (pin < 0) return luaL_error(L, "%s: pin: %s", fn, sim->err);
    }
    guard_free(g);   /* the sample is copied: freed now (the guard's __gc then finds nothing) */

    la_membrane3 *m = lua_newuserdatauv(L, sizeof *m, 1);
    m->index = k;
    m->pin = pin;
    lua_pushvalue(L, 1);
    lua_setiuservalue(L, -2, 1);
    luaL_setmetatable(L, LA_MEMBRANE3);
    return 1;
}

/* sim:checkpoint on a 3D sim: the state file (sim3_state.c) holds the
 * membrane points too (sim3_membrane_state.c), so it is the 2D method's. */
int la_sim3_checkpoint(lua_State *L)
{
    la_check_sim3(L, 1, "sim:checkpoint");
    return la_sim_checkpoint(L);
}

void la_open_membrane3(lua_State *L)
{
    static const luaL_Reg smeta[] = {{"__tostring", surface3_tostring}, {NULL, NULL}};
    la_new_metatable(L, LA_SURFACE3);
    luaL_setfuncs(L, smeta, 0);
    lua_pop(L, 1);
    static const luaL_Reg meta[] = {{"__index", m3_index},
                                    {"__len", m3_len},
                                    {"__tostring", m3_tostring},
                                    {NULL, NULL}};
    static const luaL_Reg methods[] = {{"particles", m3_particles},
                                       {"tension", m3_tension},
                                       {"reaction", m3_reaction},
                                       /* l_membrane3_gas.c */
                                       {"enclosed_volume", la_membrane3_volume},
                                       {"escaped", la_membrane3_escaped},
                                       {"normals", m3_normals},
                                       {NULL, NULL}};
    la_new_class_in(L, LA_MEMBRANE3, meta, methods, "methods");   /* m3_index looks there */
    lua_pop(L, 1);
}
