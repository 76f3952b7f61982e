/* l_normals.c - lamina.normals{...}: normals without connectivity for a
 * static set of points (docs/design.md's contract; the engine is normals.h).
 *
 *   lamina.normals{ points = {{x, y}, ...}, box = {x0, y0, x1, y1},
 *                   basis = "linear" | "quadratic", random_point = {x, y}
 *                   | seed = n, phi2_point = bool }
 *   -> { normals = {{nx, ny}, ...}, phi = {...}, cond = c, ... }
 *
 * 3D: points {x, y, z}, box {x0, y0, z0, x1, y1, z1}. Extensions (see
 * docs/api.md): solver, orient, cells (a grid over the box, with merging and
 * the hybrid basis), method (the dissertation's variants), cond_limit; the
 * result also has phi_at(x, y[, z]), nodes, rank, residual, random_point,
 * elements. Bindings only: every number comes from src/mpm/normals*.c. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "l_internal.h"
#include "l_normals.h"

static const char *const KEYS[] = {"points", "box", "basis", "random_point", "seed",
                                   "phi2_point", "solver", "orient", "cells",
                                   "method", "cond_limit", NULL};
static const char *const BASES[] = {"linear", "quadratic", "hybrid", NULL};
static const char *const SOLVERS[] = {"qr", "normal_equations", NULL};
static const char *const ORIENTS[] = {"none", "sequence", "neighbours", NULL};
static const char *const METHODS[] = {"isosurface", "colour", "quadratic_colour",
                                      "mass_matrix", "mass_matrix_global", "cubic_colour", NULL};
enum { M_ISO, M_COLOUR, M_QCOLOUR, M_MASS, M_MASS_GLOBAL, M_CCOLOUR };

static const char *FN = "lamina.normals";

/* ---- reading the arguments -------------------------------------------- */

/* {a, b, ...} of exactly `len` numbers at key (or at index idx if key is
 * NULL) into v. */
static void read_numbers(lua_State *L, int idx, const char *key, int len,
                         double *v, const char *what)
{
    if (key)
        la_getfield(L, idx, key);
    else
        lua_pushvalue(L, idx);
    if (!lua_istable(L, -1) || (int)lua_rawlen(L, -1) != len)
        luaL_error(L, "%s: %s must be a table of %d numbers", FN, what, len);
    for (int i = 0; i < len; i++) {
        lua_rawgeti(L, -1, i + 1);
        int isnum;
        v[i] = lua_tonumberx(L, -1, &isnum);
        if (!isnum)
            luaL_error(L, "%s: %s[%d] must be a number", FN, what, i + 1);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
}

/* box = {x0, y0, x1, y1} or {x0, y0, z0, x1, y1, z1}; returns the dimension. */
static int read_box(lua_State *L, double lo[3], double hi[3])
{
    la_getfield(L, 1, "box");
    if (lua_isnil(L, -1))
        luaL_error(L, "%s: 'box' is required ({x0, y0, x1, y1} or "
                   "{x0, y0, z0, x1, y1, z1})", FN);
    int len = lua_istable(L, -1) ? (int)lua_rawlen(L, -1) : 0;
    lua_pop(L, 1);
    if (len != 4 && len != 6)
        luaL_error(L, "%s: 'box' must be {x0, y0, x1, y1} (2D) or "
                   "{x0, y0, z0, x1, y1, z1} (3D)", FN);
    int dim = len / 2;
    double v[6];
    read_numbers(L, 1, "box", len, v, "'box'");
    lo[2] = hi[2] = 0.0;
    for (int a = 0; a < dim; a++) {
        lo[a] = v[a];
        hi[a] = v[dim + a];
        if (!isfinite(lo[a]) || !isfinite(hi[a]) || !(hi[a] > lo[a]))
            luaL_error(L, "%s: 'box' is empty along axis %d ([%f, %f])", FN, a + 1,
                       lo[a], hi[a]);
    }
    return dim;
}

/* points: n points of dim coordinates into three arrays kept alive as a
 * userdata on the stack (freed by the collector even after an error). */
static size_t read_points(lua_State *L, int dim, double *x[3])
{
    la_getfield(L, 1, "points");
    if (!lua_istable(L, -1))
        luaL_error(L, "%s: 'points' is required: a list of {x, y%s}", FN,
                   dim == 3 ? ", z" : "");
    size_t n = lua_rawlen(L, -1);
    if (n == 0)
        luaL_error(L, "%s: 'points' is empty: no membrane points", FN);
    double *buf = lua_newuserdatauv(L, sizeof(double) * 3 * n, 0);
    lua_insert(L, -2);                    /* keep the buffer below the list */
    for (int a = 0; a < 3; a++)
        x[a] = buf + (size_t)a * n;
    for (size_t i = 0; i < n; i++) {
        lua_rawgeti(L, -1, (lua_Integer)i + 1);
        if (!lua_istable(L, -1) || (int)lua_rawlen(L, -1) != dim)
            luaL_error(L, "%s: points[%d] must be {x, y%s}", FN, (int)i + 1,
                       dim == 3 ? ", z" : "");
        for (int a = 0; a < 3; a++) {
            x[a][i] = 0.0;
            if (a >= dim)
                continue;
            lua_rawgeti(L, -1, a + 1);
            int isnum;
            x[a][i] = lua_tonumberx(L, -1, &isnum);
            if (!isnum)
                luaL_error(L, "%s: points[%d][%d] must be a number", FN, (int)i + 1,
                           a + 1);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    lua_pop(L, 1);                        /* the list; the buffer stays */
    return n;
}

static int opt_choice(lua_State *L, const char *key, const char *def,
                      const char *const names[])
{
    const char *s = la_opt_string(L, 1, FN, key, def);
    return s ? la_option(L, FN, key, s, names) : -1;
}

/* seed = n: a whole number >= 0 (a 64-bit generator seed). */
static uint64_t read_seed(lua_State *L)
{
    double s = la_opt_number(L, 1, FN, "seed", 1);
    if (!(s >= 0) || s != floor(s) || s > 9007199254740992.0)
        luaL_error(L, "%s: 'seed' must be a whole number >= 0 (got %f)", FN, s);
    return (uint64_t)s;
}

/* orient = "none" | "sequence" | "neighbours" | {x, y[, z]} (away from it) */
static lm_norient read_orient(lua_State *L, int dim, double point[3])
{
    int t = la_getfield(L, 1, "orient");
    lua_pop(L, 1);
    point[0] = point[1] = point[2] = 0.0;
    if (t == LUA_TTABLE) {
        read_numbers(L, 1, "orient", dim, point, "'orient' (a point to point away from)");
        return LM_NORIENT_AWAY;
    }
    int k = opt_choice(L, "orient", "neighbours", ORIENTS);
    return k == 1 ? LM_NORIENT_SEQUENCE : k == 2 ? LM_NORIENT_NEIGHBOURS
                                                 : LM_NORIENT_NONE;
}

/* ---- the phi field userdata ------------------------------------------------ */

static la_nfield *new_field(lua_State *L, int dim, int nfits, long ncells)
{
    size_t size = sizeof(la_nfield) + sizeof(lm_nfit) * (size_t)(nfits ? nfits : 1) +
                  sizeof(int) * (size_t)(ncells > 0 ? ncells : 1);
    la_nfield *f = lua_newuserdatauv(L, size, 0);
    memset(f, 0, sizeof *f);
    f->dim = dim;
    f->nfits = nfits;
    f->fits = (lm_nfit *)(f + 1);
    f->cell_fit = (int *)(f->fits + (nfits ? nfits : 1));
    luaL_setmetatable(L, LA_NFIELD);
    return f;
}

double la_nfield_phi(const la_nfield *f, const double x[3])
{
    if (!f->grid)
        return f->nfits ? lm_nfit_phi(&f->fits[0], x) : NAN;
    int c[3];
    long id = lm_ngrid_cell(&f->g, x, c);
    if (id < 0 || f->cell_fit[id] < 0)
        return NAN;
    const lm_nfit *fit = &f->fits[f->cell_fit[id]];
    return fit->n > 0 ? lm_nfit_phi(fit, x) : NAN;
}

/* phi_at(x, y[, z]) -> phi, or nil where no element was fitted */
static int l_phi_at(lua_State *L)
{
    la_nfield *f = luaL_checkudata(L, lua_upvalueindex(1), LA_NFIELD);
    double x[3] = {luaL_checknumber(L, 1), luaL_checknumber(L, 2),
                   f->dim == 3 ? luaL_checknumber(L, 3) : 0.0};
    double v = la_nfield_phi(f, x);
    if (isnan(v))
        lua_pushnil(L);
    else
        lua_pushnumber(L, v);
    return 1;
}

la_nfield *la_to_nfield(lua_State *L, int idx)
{
    idx = lua_absindex(L, idx);
    int pushed = 0;
    if (lua_istable(L, idx)) {
        la_getfield(L, idx, "phi_at");
        idx = lua_gettop(L);
        pushed = 1;
    }
    la_nfield *f = NULL;
    if (lua_tocfunction(L, idx) == l_phi_at && lua_getupvalue(L, idx, 1)) {
        f = luaL_testudata(L, -1, LA_NFIELD);
        lua_pop(L, 1);
    }
    if (pushed)
        lua_pop(L, 1);
    return f;
}

/* ---- building the result ------------------------------------------------------ */

static void push_vec(lua_State *L, int dim, const double *v)
{
    lua_createtable(L, dim, 0);
    for (int a = 0; a < dim; a++) {
        lua_pushnumber(L, v[a]);
        lua_rawseti(L, -2, a + 1);
    }
}

static void set_number(lua_State *L, const char *k, double v)
{
    lua_pushnumber(L, v);
    lua_setfield(L, -2, k);
}

/* normals = {{nx, ny[, nz]}, ...} in input order */
static void push_normals(lua_State *L, int dim, size_t n, double *const nrm[3])
{
    lua_createtable(L, (int)n, 0);
    for (size_t i = 0; i < n; i++) {
        double v[3] = {nrm[0][i], nrm[1][i], dim == 3 ? nrm[2][i] : 0.0};
        push_vec(L, dim, v);
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    lua_setfield(L, -2, "normals");
}

/* What one fit knows: phi at its nodes, the nodes, cond, rank, points. */
static void push_fit_fields(lua_State *L, const lm_nfit *f)
{
    lua_createtable(L, f->n, 0);
    for (int I = 0; I < f->n; I++) {
        lua_pushnumber(L, f->phi[I]);
        lua_rawseti(L, -2, I + 1);
    }
    lua_setfield(L, -2, "phi");
    lua_createtable(L, f->n, 0);
    for (int I = 0; I < f->n; I++) {
        double xi[3], w[3];
        lm_nbasis_node(f->basis, f->dim, I, xi);
        lm_nbox_to_world(&f->box, xi, w);
        push_vec(L, f->dim, w);
        lua_rawseti(L, -2, I + 1);
    }
    lua_setfield(L, -2, "nodes");
    set_number(L, "cond", f->info.cond_t);
    set_number(L, "cond_rank", f->info.cond_t_rank);
    lua_pushinteger(L, f->info.rank);
    lua_setfield(L, -2, "rank");
    lua_pushinteger(L, f->n);
    lua_setfield(L, -2, "unknowns");
    lua_pushinteger(L, f->rows);
    lua_setfield(L, -2, "rows");
    lua_pushinteger(L, f->npoints);
    lua_setfield(L, -2, "points");
    lua_pushinteger(L, f->nunique);
    lua_setfield(L, -2, "unique");
    set_number(L, "residual", f->residual);
    lua_pushinteger(L, f->draws);
    lua_setfield(L, -2, "draws");
    lua_pushstring(L, BASES[f->basis - 1]);
    lua_setfield(L, -2, "basis");
    lua_pushboolean(L, (f->flags & LM_NF_UNDERDETERMINED) != 0);
    lua_setfield(L, -2, "underdetermined");
    lua_pushboolean(L, (f->flags & LM_NF_COINCIDENT) != 0);
    lua_setfield(L, -2, "coincident");
    push_vec(L, f->dim, f->q);
    lua_setfield(L, -2, "random_point");
    if (f->has_q2) {
        push_vec(L, f->dim, f->q2);
        lua_setfield(L, -2, "phi2_point");
    }
    double box[6];
    for (int a = 0; a < f->dim; a++) {
        box[a] = f->box.lo[a];
        box[f->dim + a] = f->box.hi[a];
    }
    push_vec(L, 2 * f->dim, box);
    lua_setfield(L, -2, "box");
}

/* phi_at as a closure over the field at the top of the stack (popped). */
static void set_phi_at(lua_State *L)
{
    lua_pushcclosure(L, l_phi_at, 1);
    lua_setfield(L, -2, "phi_at");
}

/* A normal the engine could not define is an error here: a script should
 * not plot or average a zero vector by accident. */
static void check_defined(lua_State *L, int dim, size_t n, const double *const x[3],
                          const unsigned char *flags)
{
    for (size_t i = 0; i < n; i++)
        if (flags[i] & LM_NF_UNDEFINED) {
            char at[128];    /* lua_pushfstring knows no %g */
            if (dim == 3)
                snprintf(at, sizeof at, "(%g, %g, %g)", x[0][i], x[1][i], x[2][i]);
            else
                snprintf(at, sizeof at, "(%g, %g)", x[0][i], x[1][i]);
            luaL_error(L, "%s: the normal at point %d %s is undefined: grad phi = 0 "
                       "there (phi is flat or has an extremum on the membrane, [N] §8); "
                       "try another seed or random_point, or phi2_point = true", FN,
                       (int)i + 1, at);
        }
}

/* ---- one element ------------------------------------------------------------ */

static int one_element(lua_State *L, int dim, const double lo[3], const double hi[3],
                       size_t n, double *x[3], double *nrm[3], unsigned char *flags)
{
    lm_nfit_opts o;
    lm_nfit_opts_default(&o);
    int b = opt_choice(L, "basis", "linear", BASES);
    if (b == 2)
        return luaL_error(L, "%s: basis = \"hybrid\" chooses per element: it needs "
                          "'cells'", FN);
    o.basis = b == 1 ? LM_NB_QUADRATIC : LM_NB_LINEAR;
    o.solver = opt_choice(L, "solver", "qr", SOLVERS) == 1 ? LM_NS_NORMAL : LM_NS_QR;
    o.cond_limit = la_opt_number(L, 1, FN, "cond_limit", 0);
    if (la_has(L, 1, "random_point")) {
        if (la_has(L, 1, "seed"))
            return luaL_error(L, "%s: give 'random_point' or 'seed', not both", FN);
        read_numbers(L, 1, "random_point", dim, o.random_point, "'random_point'");
        o.random_given = 1;
    }
    o.seed = read_seed(L);
    int t = la_getfield(L, 1, "phi2_point");
    if (t == LUA_TTABLE) {
        read_numbers(L, -1, NULL, dim, o.phi2_point, "'phi2_point'");
        o.phi2_given = 1;
    } else if (t == LUA_TBOOLEAN) {
        o.phi2 = lua_toboolean(L, -1) ? LM_PHI2_RANDOM : LM_PHI2_NONE;
    } else if (t != LUA_TNIL) {
        return luaL_error(L, "%s: 'phi2_point' must be true, false or a point", FN);
    }
    lua_pop(L, 1);
    double op[3];
    lm_norient how = read_orient(L, dim, op);

    la_nfield *f = new_field(L, dim, 1, 0);
    int fidx = lua_gettop(L);
    memcpy(f->lo, lo, sizeof f->lo);
    memcpy(f->hi, hi, sizeof f->hi);
    lm_nbox box = {dim, {lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
    char err[512];
    const double *const cx[3] = {x[0], x[1], x[2]};
    if (lm_nfit_element(&box, cx, NULL, n, &o, &f->fits[0], err, sizeof err))
        return luaL_error(L, "%s: %s", FN, err);
    for (size_t i = 0; i < n; i++) {
        double p[3] = {x[0][i], x[1][i], x[2][i]}, v[3];
        flags[i] = lm_nfit_normal(&f->fits[0], p, v) ? LM_NF_UNDEFINED : 0;
        for (int a = 0; a < 3; a++)
            nrm[a][i] = v[a];
    }
    check_defined(L, dim, n, cx, flags);
    lm_normals_orient(n, dim, cx, nrm, how, op);

    lua_newtable(L);
    push_normals(L, dim, n, nrm);
    push_fit_fields(L, &f->fits[0]);
    lua_pushstring(L, SOLVERS[o.solver]);
    lua_setfield(L, -2, "solver");
    lua_pushvalue(L, fidx);
    set_phi_at(L);
    return 1;
}

/* ---- a grid ------------------------------------------------------------------ */

#define LA_MAX_NORMAL_CELLS 4000000   /* 2000 x 2000, or 158^3 */

static void read_cells(lua_State *L, int dim, const double lo[3], const double hi[3],
                       lm_ngrid *g)
{
    memset(g, 0, sizeof *g);
    g->dim = dim;
    g->n[2] = 1;
    if (la_has(L, 1, "cells")) {
        double c[3];
        read_numbers(L, 1, "cells", dim, c, "'cells' ({nx, ny} or {nx, ny, nz})");
        for (int a = 0; a < dim; a++) {
            if (!(c[a] >= 1) || c[a] != floor(c[a]) || c[a] > 65536)
                luaL_error(L, "%s: 'cells' must be whole numbers in [1, 65536]", FN);
            g->n[a] = (int)c[a];
        }
        /* each axis alone passed 65536: {1000, 1000, 1000} is 1e9 cells */
        double total = (double)g->n[0] * g->n[1] * (dim == 3 ? g->n[2] : 1);
        if (total > LA_MAX_NORMAL_CELLS) {
            char m[64];   /* lua_pushfstring knows no %g */
            snprintf(m, sizeof m, "%.0f", total);
            luaL_error(L, "%s: 'cells' makes %s cells, more than the limit of %d", FN, m,
                       LA_MAX_NORMAL_CELLS);
        }
    } else {
        g->n[0] = g->n[1] = g->n[2] = 1;
    }
    for (int a = 0; a < dim; a++) {
        g->x0[a] = lo[a];
        g->h[a] = (hi[a] - lo[a]) / g->n[a];
    }
}

static void push_elements(lua_State *L, const lm_nreport *rep)
{
    lua_createtable(L, rep->nelem, 0);
    for (int k = 0; k < rep->nelem; k++) {
        const lm_nelem *el = &rep->elem[k];
        lua_newtable(L);
        if (el->fit.n > 0)
            push_fit_fields(L, &el->fit);
        double c[3] = {el->cell[0] + 1, el->cell[1] + 1, el->cell[2] + 1};
        double lo[3] = {el->lo[0] + 1, el->lo[1] + 1, el->lo[2] + 1};
        push_vec(L, el->fit.dim ? el->fit.dim : 2, c);
        lua_setfield(L, -2, "cell");
        push_vec(L, el->fit.dim ? el->fit.dim : 2, lo);
        lua_setfield(L, -2, "block");
        lua_pushinteger(L, el->size);
        lua_setfield(L, -2, "size");
        lua_pushboolean(L, (el->fit.flags & LM_NF_MERGED) != 0);
        lua_setfield(L, -2, "merged");
        lua_rawseti(L, -2, k + 1);
    }
    lua_setfield(L, -2, "elements");
}

static int grid_isosurface(lua_State *L, const lm_ngrid *g, int method, size_t n,
                           double *x[3], double *nrm[3], unsigned char *flags)
{
    int dim = g->dim;
    lm_nopts o;
    lm_nopts_default(&o);
    int b = opt_choice(L, "basis", method == M_MASS ? "linear" : "hybrid", BASES);
    o.basis = b == 0 ? LM_NB_LINEAR : b == 1 ? LM_NB_QUADRATIC : LM_NB_HYBRID;
    o.solver = opt_choice(L, "solver", method == M_MASS ? "normal_equations" : "qr",
                          SOLVERS) == 1 ? LM_NS_NORMAL : LM_NS_QR;
    if (la_has(L, 1, "random_point"))
        return luaL_error(L, "%s: 'random_point' is for one element; with 'cells' "
                          "every element draws its own from 'seed'", FN);
    o.seed = read_seed(L);
    o.cond_limit = la_opt_number(L, 1, FN, "cond_limit", 0);
    int t = la_getfield(L, 1, "phi2_point");
    if (t != LUA_TNIL && t != LUA_TBOOLEAN)
        return luaL_error(L, "%s: with 'cells', 'phi2_point' must be true or false", FN);
    o.phi2 = lua_toboolean(L, -1) ? LM_PHI2_RANDOM : LM_PHI2_NONE;
    lua_pop(L, 1);
    o.orient = read_orient(L, dim, o.orient_point);

    char err[512];
    lm_nreport rep;
    const double *const cx[3] = {x[0], x[1], x[2]};
    if (lm_normals_grid(g, n, cx, &o, nrm, flags, &rep, err, sizeof err))
        return luaL_error(L, "%s: %s", FN, err);
    long ncells = rep.ncells;
    la_nfield *f = new_field(L, dim, rep.nelem, ncells);
    int fidx = lua_gettop(L);
    f->grid = 1;
    f->g = *g;
    double mx = 0;
    for (int k = 0; k < rep.nelem; k++) {
        f->fits[k] = rep.elem[k].fit;
        if (rep.elem[k].fit.info.cond_t > mx)
            mx = rep.elem[k].fit.info.cond_t;
    }
    for (long c = 0; c < ncells; c++)
        f->cell_fit[c] = rep.cell_elem[c];
    for (int a = 0; a < dim; a++) {
        f->lo[a] = g->x0[a];
        f->hi[a] = g->x0[a] + g->n[a] * g->h[a];
    }
    lua_newtable(L);
    push_elements(L, &rep);
    lm_nreport_free(&rep);
    check_defined(L, dim, n, cx, flags);
    push_normals(L, dim, n, nrm);
    set_number(L, "cond", mx);
    lua_pushstring(L, SOLVERS[o.solver]);
    lua_setfield(L, -2, "solver");
    lua_pushvalue(L, fidx);
    set_phi_at(L);
    return 1;
}

static int grid_variant(lua_State *L, const lm_ngrid *g, int method, size_t n,
                        double *x[3], double *nrm[3], unsigned char *flags)
{
    static const char *const not_here[] = {"basis", "random_point", "solver",
                                           "cond_limit", NULL};
    for (int k = 0; not_here[k]; k++)
        if (la_has(L, 1, not_here[k]))
            return luaL_error(L, "%s: '%s' does not apply to method = \"%s\"", FN,
                              not_here[k], METHODS[method]);
    if (method != M_MASS_GLOBAL && la_has(L, 1, "phi2_point"))
        return luaL_error(L, "%s: 'phi2_point' does not apply to method = \"%s\"",
                          FN, METHODS[method]);
    lm_nopts o;
    lm_nopts_default(&o);
    o.seed = read_seed(L);
    o.phi2 = la_getfield(L, 1, "phi2_point") == LUA_TBOOLEAN && lua_toboolean(L, -1);
    lua_pop(L, 1);
    o.orient = read_orient(L, g->dim, o.orient_point);
    char err[512];
    double cond = NAN;
    const double *const cx[3] = {x[0], x[1], x[2]};
    lm_nerr e = method == M_COLOUR
                    ? lm_normals_colour(g, n, cx, nrm, flags, err, sizeof err)
                : method == M_QCOLOUR
                    ? lm_normals_quadratic_colour(g, n, cx, nrm, flags, err, sizeof err)
                : method == M_CCOLOUR
                    ? lm_normals_cubic_colour(g, n, cx, nrm, flags, err, sizeof err)
                    : lm_normals_mass_matrix_global(g, n, cx, &o, nrm, flags, &cond,
                                                    err, sizeof err);
    if (e)
        return luaL_error(L, "%s: %s", FN, err);
    check_defined(L, g->dim, n, cx, flags);
    if (method != M_MASS_GLOBAL)
        lm_normals_orient(n, g->dim, cx, nrm, o.orient, o.orient_point);
    lua_newtable(L);
    push_normals(L, g->dim, n, nrm);
    if (method == M_MASS_GLOBAL)
        set_number(L, "cond", cond);
    return 1;
}

int la_normals(lua_State *L)
{
    la_check_keys(L, 1, FN, KEYS);
    double lo[3], hi[3];
    int dim = read_box(L, lo, hi);
    double *x[3];
    size_t n = read_points(L, dim, x);
    double *out = lua_newuserdatauv(L, sizeof(double) * 3 * n + n, 0);
    double *nrm[3] = {out, out + n, out + 2 * n};
    unsigned char *flags = (unsigned char *)(out + 3 * n);
    memset(out, 0, sizeof(double) * 3 * n);
    int method = opt_choice(L, "method", "isosurface", METHODS);
    if (method == M_ISO && !la_has(L, 1, "cells"))
        return one_element(L, dim, lo, hi, n, x, nrm, flags);
    lm_ngrid g;
    read_cells(L, dim, lo, hi, &g);
    if (method == M_ISO || method == M_MASS)
        return grid_isosurface(L, &g, method, n, x, nrm, flags);
    return grid_variant(L, &g, method, n, x, nrm, flags);
}

void la_open_normals(lua_State *L)
{
    la_new_metatable(L, LA_NFIELD);
    lua_pop(L, 1);
    la_open_figure(L);
    lua_pushcfunction(L, la_normals);
    lua_setfield(L, -2, "normals");
    lua_pushcfunction(L, la_figure_new);
    lua_setfield(L, -2, "figure");
}
