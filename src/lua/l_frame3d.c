/* l_frame3d.c - sim:frame{...} of a 3D simulation (l_frame3d.h): the
 * keys of docs/api.md "3D frames" read into frame3d.h's figure, the
 * particles' fields and the grid fields of slices and isosurfaces taken
 * from the lm3_sim, the drawing left to src/render/frame3d.c.
 *
 * A grid field (slice, isosurface) is the particles' field carried to the
 * grid's nodes as the step carries momentum: mass-weighted with the
 * trilinear weights, f_i = sum_p N_ip m_p f_p / sum_p N_ip m_p; nodes no
 * particle reaches have no value (the slice leaves them out). "mass" is
 * the nodal mass over a cell's volume, m_i / h^3 - a body's density,
 * whose isosurface at half the material's density is its surface.
 *
 * Bindings only. Every scratch array lives in a userdata anchored in a
 * table on the stack, so a Lua error in between leaks nothing. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "frame3d.h"
#include "l_frame3d.h"
#include "l_frame_common.h"
#include "l_internal.h"
#include "l_pressure3.h"
#include "mpm3_membrane.h"
#include "render.h"

#define MAX_SLICES 8

#define PANEL3_KEYS "colour", "colourmap", "range", "colourbar", "azimuth", "elevation", \
    "distance", "target", "fov", "box", "outline", "particles", "radius", "slice", \
    "isosurface", "membranes", "normals", "phi"

typedef struct ctx3 {
    const char *fn;
    const lm3_sim *sim;
    int anchor, nanchored;
    int fidx;
    size_t particles, slices, isos;     /* drawn, for lamina:layers */
    size_t mpoints, marrows;            /* membrane points drawn, and with normals */
    size_t mmem, mphi;                  /* membranes drawn, and with their phi = 1 */
} ctx3;

/* luaL_error with printf's formats (%g, which Lua's lacks). */
static int fail(lua_State *L, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int fail(lua_State *L, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return luaL_error(L, "%s", msg);
}

static void *scratch(lua_State *L, ctx3 *c, size_t n)
{
    void *p = lua_newuserdatauv(L, n ? n : 1, 0);
    memset(p, 0, n ? n : 1);
    lua_rawseti(L, c->anchor, ++c->nanchored);
    return p;
}

/* ---- fields ---------------------------------------------------------------- */

enum {
    F_BODY = 0, F_SPEED, F_VX, F_VY, F_VZ, F_PRESSURE, F_SXX, F_SYY, F_SZZ, F_SYZ, F_SXZ,
    F_SXY, F_MISES, F_RHO, F_MASS, F_COUNT
};
static const char *const FIELD_NAMES[F_COUNT] = {
    "body", "speed", "vx", "vy", "vz", "pressure", "sxx", "syy", "szz", "syz", "sxz", "sxy",
    "mises", "rho", "mass"
};
/* signed fields take the diverging map by default */
static const unsigned char SIGNED[F_COUNT] = {0, 0, 1, 1, 1, 0, 1, 1, 1, 1, 1, 1, 0, 0, 0};

static int field_id(lua_State *L, const char *fn, const char *key, const char *name)
{
    for (int k = 0; k < F_COUNT; k++)
        if (strcmp(name, FIELD_NAMES[k]) == 0)
            return k;
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    for (int k = 0; k < F_COUNT; k++) {
        luaL_addstring(&b, k ? ", " : "");
        luaL_addstring(&b, FIELD_NAMES[k]);
    }
    luaL_pushresult(&b);
    return luaL_error(L, "%s: %s = \"%s\": unknown field (known: %s)", fn, key, name,
                      lua_tostring(L, -1));
}

static double field_at(const lm3_sim *s, int f, size_t i)
{
    const lm3_particles *p = &s->p;
    switch (f) {
    case F_SPEED:
        return sqrt(p->v[0][i] * p->v[0][i] + p->v[1][i] * p->v[1][i] + p->v[2][i] * p->v[2][i]);
    case F_VX:
    case F_VY:
    case F_VZ:
        return p->v[f - F_VX][i];
    case F_PRESSURE:    /* a gas's (gamma - 1) rho e, others' -tr sigma / 3 */
        return la_pressure3(s, i);
    case F_SXX:
    case F_SYY:
    case F_SZZ:
    case F_SYZ:
    case F_SXZ:
    case F_SXY:
        return p->s[f - F_SXX][i];
    case F_MISES: {
        const double a = p->s[0][i], b = p->s[1][i], c = p->s[2][i];
        const double t = p->s[3][i] * p->s[3][i] + p->s[4][i] * p->s[4][i] +
                         p->s[5][i] * p->s[5][i];
        return sqrt(0.5 * ((a - b) * (a - b) + (b - c) * (b - c) + (c - a) * (c - a)) +
                    3.0 * t);
    }
    case F_RHO:
        return p->rho[i];
    case F_MASS:
        return p->m[i];
    default:
        return p->mat[i];
    }
}

/* The field at the grid's nodes (no ghosts), mass-weighted (the file's
 * comment); "mass": m_i / h^3. */
static void nodal(lua_State *L, ctx3 *c, int f, lr_grid3d *g)
{
    const lm3_grid *G = &c->sim->grid;
    int n[3] = {G->n[0] + 1, G->n[1] + 1, G->n[2] + 1};
    size_t nn = (size_t)n[0] * n[1] * n[2];
    double *num = scratch(L, c, nn * sizeof *num);
    double *den = malloc(nn * sizeof *den);
    if (!den)
        luaL_error(L, "%s: out of memory", c->fn);
    memset(den, 0, nn * sizeof *den);
    const lm3_particles *p = &c->sim->p;
    for (size_t i = 0; i < p->n; i++) {
        int base[3];
        double t[3];
        for (int a = 0; a < 3; a++) {
            double u = (p->x[a][i] - G->lo[a]) / G->h;
            int k = (int)floor(u);
            k = k < 0 ? 0 : k > n[a] - 2 ? n[a] - 2 : k;
            base[a] = k;
            t[a] = u - k;
            t[a] = t[a] < 0 ? 0 : t[a] > 1 ? 1 : t[a];
        }
        double v = f == F_MASS ? 0.0 : field_at(c->sim, f, i), m = p->m[i];
        for (int q = 0; q < 8; q++) {
            double w = 1;
            for (int a = 0; a < 3; a++)
                w *= (q >> a) & 1 ? t[a] : 1 - t[a];
            size_t id = ((size_t)(base[2] + ((q >> 2) & 1)) * n[1] +
                         (size_t)(base[1] + ((q >> 1) & 1))) * n[0] +
                        (size_t)(base[0] + (q & 1));
            den[id] += w * m;
            num[id] += w * m * v;
        }
    }
    double vol = G->h * G->h * G->h;
    for (size_t k = 0; k < nn; k++)
        num[k] = f == F_MASS ? den[k] / vol : den[k] > 0 ? num[k] / den[k] : NAN;
    free(den);
    g->f = num;
    for (int a = 0; a < 3; a++) {
        g->n[a] = n[a];
        g->lo[a] = G->lo[a];
        g->h[a] = G->h;
    }
}

/* ---- keys ----------------------------------------------------------------- */

/* Pushes the panel's value of key, else the frame's (nil when neither). */
static int get(lua_State *L, const ctx3 *c, int pidx, const char *key)
{
    if (pidx) {
        int t = la_getfield(L, pidx, key);
        if (t != LUA_TNIL)
            return t;
        lua_pop(L, 1);
    }
    return la_getfield(L, c->fidx, key);
}

static double num_key(lua_State *L, const ctx3 *c, const char *where, int pidx,
                      const char *key, double def)
{
    double v = def;
    int t = get(L, c, pidx, key);
    if (t != LUA_TNIL) {
        if (t != LUA_TNUMBER || !isfinite(lua_tonumber(L, -1)))
            luaL_error(L, "%s: '%s' must be a finite number (got %s)", where, key,
                       luaL_typename(L, -1));
        v = lua_tonumber(L, -1);
    }
    lua_pop(L, 1);
    return v;
}

static int bool_key(lua_State *L, const ctx3 *c, const char *where, int pidx,
                    const char *key, int def)
{
    int t = get(L, c, pidx, key), v = def;
    if (t != LUA_TNIL) {
        if (t != LUA_TBOOLEAN)
            luaL_error(L, "%s: '%s' must be true or false (got %s)", where, key,
                       luaL_typename(L, -1));
        v = lua_toboolean(L, -1);
    }
    lua_pop(L, 1);
    return v;
}

/* A list of exactly n finite numbers at the top of the stack into out. */
static void numbers(lua_State *L, const char *where, const char *key, int n, double *out)
{
    if (!lua_istable(L, -1) || (int)lua_rawlen(L, -1) != n)
        luaL_error(L, "%s: '%s' must be a list of %d numbers", where, key, n);
    for (int k = 0; k < n; k++) {
        lua_rawgeti(L, -1, k + 1);
        if (!lua_isnumber(L, -1) || !isfinite(lua_tonumber(L, -1)))
            luaL_error(L, "%s: '%s'[%d] must be a finite number", where, key, k + 1);
        out[k] = lua_tonumber(L, -1);
        lua_pop(L, 1);
    }
}

static lr_cmap cmap_key(lua_State *L, const ctx3 *c, const char *where, int idx, int pidx,
                        lr_cmap def)
{
    int t = idx ? la_getfield(L, idx, "colourmap") : get(L, c, pidx, "colourmap");
    lr_cmap m = def;
    if (t != LUA_TNIL) {
        char why[256];
        if (t != LUA_TSTRING || lr_cmap_parse(lua_tostring(L, -1), &m, why, sizeof why) != 0)
            luaL_error(L, "%s: 'colourmap': %s", where,
                       t == LUA_TSTRING ? why : "must be \"viridis\" or \"rdbu\"");
    }
    lua_pop(L, 1);
    return m;
}

/* range = {min, max} from the table at idx (0: the panel's keys) */
static void range_key(lua_State *L, const ctx3 *c, const char *where, int idx, int pidx,
                      double *lo, double *hi)
{
    int t = idx ? la_getfield(L, idx, "range") : get(L, c, pidx, "range");
    *lo = *hi = 0;
    if (t != LUA_TNIL) {
        double r[2];
        numbers(L, where, "range", 2, r);
        if (!(r[1] > r[0]))
            fail(L, "%s: 'range' {%g, %g} must have min < max", where, r[0], r[1]);
        *lo = r[0];
        *hi = r[1];
    }
    lua_pop(L, 1);
}

/* slice = {axis = "x" | "y" | "z", at = w, field = "pressure", range,
 * colourmap, alpha, colourbar} */
static void slice_key(lua_State *L, ctx3 *c, const char *where, int idx, void *out)
{
    lr_slice3d *s = out;
    static const char *const keys[] = {"axis", "at", "field", "range", "colourmap",
                                       "alpha", "colourbar", NULL};
    la_check_keys(L, idx, where, keys);
    memset(s, 0, sizeof *s);
    const char *axis = la_opt_string(L, idx, where, "axis", "z");
    if (strlen(axis) != 1 || axis[0] < 'x' || axis[0] > 'z')
        luaL_error(L, "%s: axis = \"%s\": must be \"x\", \"y\" or \"z\"", where, axis);
    s->axis = axis[0] - 'x';
    const lm3_grid *G = &c->sim->grid;
    double lo = G->lo[s->axis], hi = lo + G->n[s->axis] * G->h;
    s->at = la_opt_number(L, idx, where, "at", 0.5 * (lo + hi));
    if (!(s->at >= lo && s->at <= hi))
        fail(L, "%s: at = %g is outside the domain's %s range [%g, %g]", where, s->at,
                   axis, lo, hi);
    const char *name = la_opt_string(L, idx, where, "field", "pressure");
    int f = field_id(L, where, "field", name);
    if (f == F_BODY)
        luaL_error(L, "%s: field = \"body\" is not a grid field", where);
    nodal(L, c, f, &s->grid);
    s->cmap = cmap_key(L, c, where, idx, 0, SIGNED[f] ? LR_CMAP_RDBU : LR_CMAP_VIRIDIS);
    range_key(L, c, where, idx, 0, &s->vmin, &s->vmax);
    s->alpha = la_opt_number(L, idx, where, "alpha", 1.0);
    if (!(s->alpha > 0 && s->alpha <= 1))
        fail(L, "%s: alpha = %g must be in (0, 1]", where, s->alpha);
    s->label = name;
    s->colourbar = 1;
    if (la_getfield(L, idx, "colourbar") != LUA_TNIL)
        s->colourbar = lua_toboolean(L, -1);
    lua_pop(L, 1);
}

/* isosurface = {field = "mass", level = x, colour = {r, g, b, a}} */
static void iso_key(lua_State *L, ctx3 *c, const char *where, int idx, void *out)
{
    lr_iso3d *s = out;
    static const char *const keys[] = {"field", "level", "colour", NULL};
    la_check_keys(L, idx, where, keys);
    memset(s, 0, sizeof *s);
    const char *name = la_opt_string(L, idx, where, "field", "mass");
    int f = field_id(L, where, "field", name);
    if (f == F_BODY)
        luaL_error(L, "%s: field = \"body\" is not a grid field", where);
    if (!la_has(L, idx, "level"))
        luaL_error(L, "%s: 'level' is required (the value the surface is drawn at)", where);
    s->level = la_number(L, idx, where, "level");
    nodal(L, c, f, &s->grid);
    s->colour = (lr_rgba){0.85, 0.55, 0.35, 0.45};
    if (la_getfield(L, idx, "colour") != LUA_TNIL) {
        double k[4];
        numbers(L, where, "colour", 4, k);
        for (int a = 0; a < 4; a++)
            if (!(k[a] >= 0 && k[a] <= 1))
                fail(L, "%s: colour[%d] = %g must be in [0, 1]", where, a + 1, k[a]);
        s->colour = (lr_rgba){k[0], k[1], k[2], k[3]};
    }
    lua_pop(L, 1);
}

/* One table or a list of them at the top of the stack: their indices
 * (absolute) into idx[], at most max; the count. */
static int tables(lua_State *L, const char *where, const char *key, int max, int idx[])
{
    int top = lua_gettop(L);
    if (!lua_istable(L, top))
        luaL_error(L, "%s: '%s' must be a table or a list of tables", where, key);
    if (lua_rawlen(L, top) == 0) {
        idx[0] = top;
        return 1;
    }
    int n = (int)lua_rawlen(L, top);
    if (n > max)
        luaL_error(L, "%s: '%s': at most %d", where, key, max);
    for (int k = 0; k < n; k++) {
        if (lua_rawgeti(L, top, k + 1) != LUA_TTABLE)
            luaL_error(L, "%s: '%s'[%d] must be a table", where, key, k + 1);
        idx[k] = lua_gettop(L);
    }
    return n;
}

typedef void (*layer_fn)(lua_State *L, ctx3 *c, const char *where, int idx, void *out);

/* The panel's `key` (a table or a list of them) read by fn into an array
 * of `size`-byte layers in scratch memory; NULL and 0 when absent. */
static void *layers(lua_State *L, ctx3 *c, int pidx, const char *where, const char *key,
                    size_t size, layer_fn fn, size_t *count)
{
    int top = lua_gettop(L), idx[MAX_SLICES];
    char *out = NULL;
    *count = 0;
    if (get(L, c, pidx, key) != LUA_TNIL) {
        int n = tables(L, where, key, MAX_SLICES, idx);
        out = scratch(L, c, (size_t)n * size);
        for (int k = 0; k < n; k++) {
            char w[96];
            snprintf(w, sizeof w, "%s: %s[%d]", where, key, k + 1);
            fn(L, c, w, idx[k], out + (size_t)k * size);
        }
        *count = (size_t)n;
    }
    lua_settop(L, top);
    return out;
}

/* ---- membranes: the construction's normals and phi ---------------------- */

enum { SHOW_NONE = 0, SHOW_OWN, SHOW_LINEAR, SHOW_QUADRATIC };

/* normals / phi = true (the membrane's own), false, "linear" ([N] Fig 5's
 * trilinear construction) or "quadratic" ([N] Fig 11's triquadratic) */
static int construction_key(lua_State *L, const ctx3 *c, const char *where, int pidx,
                            const char *key)
{
    int t = get(L, c, pidx, key), v = SHOW_OWN;
    if (t == LUA_TBOOLEAN) {
        v = lua_toboolean(L, -1) ? SHOW_OWN : SHOW_NONE;
    } else if (t == LUA_TSTRING && strcmp(lua_tostring(L, -1), "linear") == 0) {
        v = SHOW_LINEAR;
    } else if (t == LUA_TSTRING && strcmp(lua_tostring(L, -1), "quadratic") == 0) {
        v = SHOW_QUADRATIC;
    } else if (t != LUA_TNIL) {
        luaL_error(L, "%s: %s = %s: must be true, false, \"linear\" or \"quadratic\"", where,
                   key, t == LUA_TSTRING ? lua_tostring(L, -1) : luaL_typename(L, -1));
    }
    lua_pop(L, 1);
    return v;
}

/* The construction's normals of membrane k on its present points, turned
 * out as the step's are (lm3_membrane_construction), into scratch. */
static void construction_normals(lua_State *L, ctx3 *c, int k, lm3_mnormals b,
                                 lr_membrane3d *m)
{
    double *n[3];
    for (int a = 0; a < 3; a++) n[a] = scratch(L, c, (m->n ? m->n : 1) * sizeof(double));
    char err[256];
    if (lm3_membrane_construction(c->sim, k, b, n, NULL, NULL, err, sizeof err) != 0)
        luaL_error(L, "%s: normals of membrane %d: %s", c->fn, k + 1, err);
    m->nx = n[0];
    m->ny = n[1];
    m->nz = n[2];
}

/* The phi = 1 surface of membrane k's construction: the fits of its
 * normals, each over the half-cell cube its element answers for, 4 nodes
 * a cube edge (sim3_membrane_phi.c), contoured cube by cube by marching
 * tetrahedra (frame3d_iso.c) into one list of triangles. */
static void phi_surface(lua_State *L, ctx3 *c, int k, lm3_mnormals b, lr_tris3d *tris)
{
    lm3_phicubes cubes;
    char err[256];
    if (lm3_membrane_phi(c->sim, k, b, 4, &cubes, err, sizeof err) != 0)
        luaL_error(L, "%s: phi of membrane %d: %s", c->fn, k + 1, err);
    const int m = cubes.samples + 1;
    const size_t m3 = (size_t)m * m * m;
    double *xyz = NULL, *nrm = NULL;
    size_t nt = 0, cap = 0;
    int oom = 0;
    for (size_t e = 0; e < cubes.n && !oom; e++) {
        lr_grid3d g = {cubes.f + e * m3, {m, m, m}, {0, 0, 0}, {cubes.d, cubes.d, cubes.d}};
        for (int a = 0; a < 3; a++) g.lo[a] = cubes.lo[3 * e + a];
        double *t = NULL, *tn = NULL;
        size_t n = 0;
        if (lr_iso_triangles(&g, 1.0, &t, &tn, &n) != 0) {
            oom = 1;
            break;
        }
        if (n && nt + n > cap) {
            size_t nc = cap ? 2 * cap : 4096;
            while (nc < nt + n) nc *= 2;
            double *x2 = realloc(xyz, 9 * nc * sizeof *x2);
            if (x2) xyz = x2;
            double *n2 = x2 ? realloc(nrm, 9 * nc * sizeof *n2) : NULL;
            if (n2) nrm = n2;
            if (!x2 || !n2) oom = 1;
            else cap = nc;
        }
        if (n && !oom) {
            memcpy(xyz + 9 * nt, t, 9 * n * sizeof *xyz);
            memcpy(nrm + 9 * nt, tn, 9 * n * sizeof *nrm);
            nt += n;
        }
        free(t);
        free(tn);
    }
    lm3_phicubes_free(&cubes);
    if (oom) {
        free(xyz);
        free(nrm);
        luaL_error(L, "%s: phi of membrane %d: out of memory", c->fn, k + 1);
    }
    /* into anchored memory, so that a later Lua error in this frame leaks
     * nothing (only Lua's own out-of-memory error between here and the
     * frees below would leak the two buffers) */
    double *ax = nt ? lua_newuserdatauv(L, 9 * nt * sizeof *ax, 0) : NULL;
    if (ax) {
        memcpy(ax, xyz, 9 * nt * sizeof *ax);
        lua_rawseti(L, c->anchor, ++c->nanchored);
    }
    double *an = nt ? lua_newuserdatauv(L, 9 * nt * sizeof *an, 0) : NULL;
    if (an) {
        memcpy(an, nrm, 9 * nt * sizeof *an);
        lua_rawseti(L, c->anchor, ++c->nanchored);
    }
    free(xyz);
    free(nrm);
    memset(tris, 0, sizeof *tris);
    tris->n = nt;
    tris->xyz = ax;
    tris->normals = an;
    /* see-through green: apart from the blue points and red arrows */
    tris->colour = (lr_rgba){0.35, 0.75, 0.45, 0.4};
}

static void panel(lua_State *L, ctx3 *c, int pidx, const char *where, lr_panel3d *p)
{
    const lm3_sim *s = c->sim;
    memset(p, 0, sizeof *p);
    for (int a = 0; a < 3; a++) {
        p->lo[a] = s->grid.lo[a];
        p->hi[a] = s->grid.lo[a] + s->grid.n[a] * s->grid.h;
    }
    if (get(L, c, pidx, "box") != LUA_TNIL) {
        double b[6];
        numbers(L, where, "box", 6, b);
        for (int a = 0; a < 3; a++) {
            if (!(b[3 + a] > b[a]))
                luaL_error(L, "%s: 'box' {x0, y0, z0, x1, y1, z1} must have x0 < x1, y0 < y1, "
                           "z0 < z1", where);
            p->lo[a] = b[a];
            p->hi[a] = b[3 + a];
        }
    }
    lua_pop(L, 1);
    p->box = bool_key(L, c, where, pidx, "outline", 1);
    lr_camera3d *cam = &p->camera;
    cam->azimuth = num_key(L, c, where, pidx, "azimuth", -60);
    cam->elevation = num_key(L, c, where, pidx, "elevation", 25);
    cam->distance = num_key(L, c, where, pidx, "distance", 0);
    if (cam->distance < 0)
        fail(L, "%s: 'distance' must be > 0 (got %g)", where, cam->distance);
    cam->fov = num_key(L, c, where, pidx, "fov", 0);
    if (!(cam->fov >= 0 && cam->fov < 120))
        fail(L, "%s: 'fov' must be in (0, 120) degrees, or 0 for an orthographic "
                   "camera (got %g)", where, cam->fov);
    if (get(L, c, pidx, "target") != LUA_TNIL) {
        numbers(L, where, "target", 3, cam->target);
        cam->has_target = 1;
    }
    lua_pop(L, 1);

    /* particles */
    int f = F_BODY;
    if (get(L, c, pidx, "colour") != LUA_TNIL) {
        if (!lua_isstring(L, -1))
            luaL_error(L, "%s: 'colour' must be a field name", where);
        f = field_id(L, where, "colour", lua_tostring(L, -1));
    }
    lua_pop(L, 1);
    p->cmap = cmap_key(L, c, where, 0, pidx, SIGNED[f] ? LR_CMAP_RDBU : LR_CMAP_VIRIDIS);
    range_key(L, c, where, 0, pidx, &p->vmin, &p->vmax);
    p->colourbar = bool_key(L, c, where, pidx, "colourbar", f != F_BODY) && f != F_BODY;
    p->colourbar_label = FIELD_NAMES[f];
    double radius = num_key(L, c, where, pidx, "radius", s->p.n > 200000 ? 1.0 : 2.5);
    if (!(radius > 0 && radius <= 64))
        fail(L, "%s: 'radius' (pixels) must be in (0, 64] (got %g)", where, radius);
    if (bool_key(L, c, where, pidx, "particles", 1) && s->p.n > 0) {
        lr_cloud3d *cl = scratch(L, c, sizeof *cl);
        cl->n = s->p.n;
        cl->x = s->p.x[0];
        cl->y = s->p.x[1];
        cl->z = s->p.x[2];
        cl->radius = radius;
        if (f == F_BODY) {
            int *g = scratch(L, c, s->p.n * sizeof *g);
            for (size_t i = 0; i < s->p.n; i++)
                g[i] = s->p.mat[i];
            cl->group = g;
        } else {
            double *v = scratch(L, c, s->p.n * sizeof *v);
            for (size_t i = 0; i < s->p.n; i++)
                v[i] = field_at(s, f, i);
            cl->value = v;
        }
        p->clouds = cl;
        p->nclouds = 1;
        c->particles += s->p.n;
    }

    /* membranes (sim:membrane in 3D): their points, their normals as
     * arrows thinned to about 16 pixels apart (frame3d.c add_membrane),
     * and the phi = 1 isosurface of their construction, see-through */
    const lm3_membranes *ms = s->mem;
    int show_m = bool_key(L, c, where, pidx, "membranes", 1);
    int show_n = construction_key(L, c, where, pidx, "normals");
    int show_phi = construction_key(L, c, where, pidx, "phi");
    lr_tris3d *phis = NULL;
    size_t nphi = 0;
    if (ms && ms->nmem > 0 && show_m) {
        lr_membrane3d *m = scratch(L, c, (size_t)ms->nmem * sizeof *m);
        if (show_phi) phis = scratch(L, c, (size_t)ms->nmem * sizeof *phis);
        for (int k = 0; k < ms->nmem; k++) {
            const size_t q0 = ms->mem[k].first;
            memset(&m[k], 0, sizeof m[k]);
            m[k].n = ms->mem[k].count;
            m[k].x = ms->p.x[0] + q0;
            m[k].y = ms->p.x[1] + q0;
            m[k].z = ms->p.x[2] + q0;
            if (show_n == SHOW_OWN) {
                m[k].nx = ms->p.nrm[0] + q0;
                m[k].ny = ms->p.nrm[1] + q0;
                m[k].nz = ms->p.nrm[2] + q0;
            } else if (show_n) {
                construction_normals(L, c, k, show_n == SHOW_LINEAR ? LM3_MN_LINEAR
                                                                    : LM3_MN_QUADRATIC, &m[k]);
            }
            m[k].colour = (lr_rgba){0.15, 0.35, 0.75, 1};
            m[k].radius = radius;
            m[k].spacing = m[k].n ? sqrt(ms->p.A0[q0]) : 0;   /* the sampler's spacing */
            m[k].arrow_colour = (lr_rgba){0.8, 0.15, 0.1, 1};
            c->mpoints += m[k].n;
            if (show_n) c->marrows += m[k].n;
            if (show_phi && m[k].n >= 3) {
                lm3_mnormals b = show_phi == SHOW_LINEAR ? LM3_MN_LINEAR
                               : show_phi == SHOW_QUADRATIC ? LM3_MN_QUADRATIC
                               /* the membrane's own construction; connectivity
                                * membranes the triquadratic one ([N] Fig 11),
                                * whose phi = 1 is the surface ([N] §6) */
                               : ms->mem[k].def.normals == LM3_MN_LINEAR ? LM3_MN_LINEAR
                               : LM3_MN_QUADRATIC;
                phi_surface(L, c, k, b, &phis[nphi++]);
            }
        }
        p->membranes = m;
        p->nmembranes = (size_t)ms->nmem;
        c->mphi += nphi;
        c->mmem += (size_t)ms->nmem;
    }

    /* slices and isosurfaces */
    p->slices = layers(L, c, pidx, where, "slice", sizeof *p->slices, slice_key, &p->nslices);
    c->slices += p->nslices;
    p->isos = layers(L, c, pidx, where, "isosurface", sizeof *p->isos, iso_key, &p->nisos);
    c->isos += p->nisos;   /* the asked ones: lamina:layers counts phi apart */
    p->tris = phis;
    p->ntris = nphi;
}

/* A panel's colour bar's ends, for lamina:range (0: it has none). */
static int panel3_range(const void *panels, size_t k, double *lo, double *hi)
{
    const lr_panel3d *p = (const lr_panel3d *)panels + k;
    if (!p->colourbar) return 0;
    lr_panel3d_range(p, lo, hi);
    return 1;
}

int l_frame3d(lua_State *L, const lm3_sim *sim, int opts_index)
{
    static const char *const keys[] = {"file", "width", "height", "title", "label", "backend",
                                       "layout", "panels", PANEL3_KEYS, NULL};
    static const char *const panel_keys[] = {"title", PANEL3_KEYS, NULL};
    const char *fn = "sim:frame";
    int fidx = lua_absindex(L, opts_index);
    la_check_table(L, fidx, fn);
    la_check_keys(L, fidx, fn, keys);
    const char *file = la_opt_output_path(L, fidx, fn, "file");
    if (!file)
        return luaL_error(L, "%s: 'file' is required", fn);
    if (lr_format_of(file) != LR_FORMAT_PNG)
        return luaL_error(L, "%s: file '%s': a 3D frame is written as PNG", fn, file);
    lr_figure3d f;
    memset(&f, 0, sizeof f);
    la_frame_size(L, fidx, fn, &f.width, &f.height);   /* l_frame_common.c */
    f.backend = la_frame_backend(L, fidx, fn, NULL);   /* PNG only (l_frame.c) */
    ctx3 c = {fn, sim, 0, 0, fidx, 0, 0, 0, 0, 0, 0, 0};
    lua_newtable(L);
    c.anchor = lua_gettop(L);

    lr_panel3d *p;
    if (la_getfield(L, fidx, "panels") == LUA_TNIL) {
        lua_pop(L, 1);
        p = scratch(L, &c, sizeof *p);
        panel(L, &c, 0, fn, p);
        f.npanels = 1;
    } else {
        int idx = lua_gettop(L);
        size_t n = la_frame_panel_count(L, idx, fn);
        p = scratch(L, &c, n * sizeof *p);
        for (size_t k = 0; k < n; k++) {
            char name[48];
            la_frame_panel_at(L, idx, k, fn, panel_keys, name);
            panel(L, &c, lua_gettop(L), name, &p[k]);
            p[k].title = la_opt_string(L, -1, name, "title", NULL);
            /* the title string stays alive in the panel table, held by
             * the panels list until we return */
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
        f.npanels = n;
    }
    f.panels = p;
    if (la_getfield(L, fidx, "layout") != LUA_TNIL) {
        double rc[2];
        numbers(L, fn, "layout", 2, rc);
        la_frame_layout(L, fn, rc[0], rc[1], f.npanels, &f.rows, &f.cols);
    }
    lua_pop(L, 1);
    f.title = la_opt_string(L, fidx, fn, "title", NULL);
    f.label = la_frame_label(L, fidx, fn, sim->t, sim->nstep);
    /* label and title strings stay on the stack until we return */

    char layers[192];
    int used_l = snprintf(layers, sizeof layers, "dim=3 particles=%zu slices=%zu isosurfaces=%zu",
                          c.particles, c.slices, c.isos);
    /* only when there are some, so the frames without membranes keep
     * their bytes */
    if (c.mpoints && used_l > 0 && (size_t)used_l < sizeof layers)
        snprintf(layers + used_l, sizeof layers - (size_t)used_l,
                 " membrane_points=%zu normals=%zu membranes=%zu phi=%zu", c.mpoints,
                 c.marrows, c.mmem, c.mphi);
    la_frame_texts tx;   /* the provenance, layers, title, lamina:range */
    f.ntext = la_frame_text(L, &tx, layers, f.title,
                            (la_frame_ranges){p, f.npanels, panel3_range});
    f.text = tx.text;
    char err[512];
    return la_frame_written(L, fn, file, lr_figure3d_write(&f, file, err, sizeof err), err);
}
