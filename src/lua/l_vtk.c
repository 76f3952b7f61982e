/* l_vtk.c - sim:vtk{file, every}: the run as a ParaView time series.
 *
 *   sim:vtk{ file = "out/run", every = 0.01 }
 *
 * writes, now and then every `every` of simulated time (once if `every` is
 * absent), out/run_000000.vtu (the particles: an unstructured grid whose
 * cells are one vertex per particle of a solid or gas body and one line
 * per segment of each membrane, in curve order), out/run_grid_000000.vtu
 * (the grid's nodal fields of the last step, its cells as quads), and
 * rewrites out/run.pvd,
 * the collection of every output so far with its time, so that ParaView
 * opens out/run.pvd as one time series (render/vtk.c writes the files).
 * A 3D run with membranes adds out/run_membranes_000000.vtu (part 2: the
 * membrane points, l_vtk3.c). */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fields.h"
#include "l_internal.h"
#include "l_sim3.h"
#include "util.h"
#include "vtk.h"

#define LA_VTK "lamina.vtk"
#define PREFIX_MAX 1024
#define NAME_MAX_LEN (PREFIX_MAX + 32)   /* prefix + "_membranes_NNNNNN.vtu" */

typedef struct la_vtk {
    char prefix[PREFIX_MAX];
    int count;              /* outputs written */
    double *times;
    unsigned char *mem;     /* per output: 1 when it has a membranes piece */
    int cap;
} la_vtk;

static int vtk_gc(lua_State *L)
{
    la_vtk *v = luaL_checkudata(L, 1, LA_VTK);
    LU_FREE_ALL(v->times, v->mem);
    v->times = NULL;
    v->mem = NULL;
    return 0;
}

/* The last path component of the prefix, for the .pvd's relative names. */
static const char *base_of(const char *prefix)
{
    const char *s = strrchr(prefix, '/');
    return s ? s + 1 : prefix;
}

/* The particles' cells: one vertex per particle of a solid or gas body, one
 * line per segment of each membrane in curve order. */
typedef struct cells_of {
    double *cbody;
    int64_t *conn, *offs;
    uint8_t *types;
    size_t ncells;
} cells_of;

static size_t cell_count(const lm_sim *sim)
{
    size_t n = 0;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        if (bd->membrane)
            n += bd->count > 1 ? bd->count - 1 + (bd->closed && bd->count > 2) : 0;
        else
            n += bd->count;
    }
    return n;
}

static void fill_cells(const lm_sim *sim, cells_of *g)
{
    size_t c = 0, k = 0;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        size_t last = bd->first + bd->count - 1;
        if (bd->membrane) {
            size_t nseg = bd->count > 1 ? bd->count - 1 + (bd->closed && bd->count > 2) : 0;
            for (size_t s = 0; s < nseg; s++) {
                size_t a = bd->first + s, z = a == last ? bd->first : a + 1;
                g->conn[k++] = (int64_t)a;
                g->conn[k++] = (int64_t)z;
                g->offs[c] = (int64_t)k;
                g->types[c] = LR_VTK_LINE;
                g->cbody[c++] = b + 1;
            }
        } else {
            for (size_t q = bd->first; q <= last && bd->count; q++) {
                g->conn[k++] = (int64_t)q;
                g->offs[c] = (int64_t)k;
                g->types[c] = LR_VTK_VERTEX;
                g->cbody[c++] = b + 1;
            }
        }
    }
}

/* VTK's width of a field: vectors in 3D (z = 0), the stress as the
 * symmetric tensor's 6 (XX, YY, ZZ, XY, then YZ = XZ = 0). */
static int vtk_width(const lm_field *f)
{
    return f->ncomp == 1 ? 1 : f->ncomp == 2 ? 3 : 6;
}

#define MAX_VTK_FIELDS 32

/* The point fields are the engine's table's (fields.c): every field with a
 * VTK name, in the table's order, each the engine's definition (a gas's
 * pressure its equation of state, as everywhere). */
static int write_particles(const lm_sim *sim, const char *path, char *err, size_t errlen)
{
    const lm_particles *p = &sim->p;
    size_t n = p->n, nc = cell_count(sim), width = 3;
    lr_vtk_field pf[MAX_VTK_FIELDS];
    const lm_field *tf[MAX_VTK_FIELDS];
    double *arr[MAX_VTK_FIELDS];
    int nf = 0;
    for (int i = 0; i < lm_field_count() && nf < MAX_VTK_FIELDS; i++)
        if (lm_field_get(i)->vtk) {
            tf[nf++] = lm_field_get(i);
            width += (size_t)vtk_width(tf[nf - 1]);
        }
    char *m = calloc(1, (n * width + nc + LM_FIELD_MAX_COMP * (n ? n : 1)) * sizeof(double) +
                            3 * nc * sizeof(int64_t) + nc + 8);
    if (!m) {
        snprintf(err, errlen, "cannot write '%s': out of memory", path);
        return -1;
    }
    double *d = (double *)m, *xyz = d, *tmp;
    d += 3 * n;
    for (int k = 0; k < nf; k++) {
        int w = vtk_width(tf[k]);
        pf[k].name = tf[k]->vtk;
        pf[k].ncomp = w;
        pf[k].data = arr[k] = d;
        d += (size_t)w * n;
    }
    tmp = d;
    d += LM_FIELD_MAX_COMP * (n ? n : 1);
    cells_of g;
    g.cbody = d;
    g.conn = (int64_t *)(d + nc);
    g.offs = g.conn + 2 * nc;
    g.types = (uint8_t *)(g.offs + nc);
    g.ncells = nc;
    for (size_t q = 0; q < n; q++) {
        xyz[3 * q] = p->x[q];
        xyz[3 * q + 1] = p->y[q];   /* z = 0 (calloc) */
    }
    for (int k = 0; k < nf; k++) {
        int nk = tf[k]->ncomp, w = vtk_width(tf[k]);
        lm_field_fill(sim, tf[k], -1, 0, n, tmp);
        for (size_t q = 0; q < n; q++)
            for (int c = 0; c < nk; c++)
                arr[k][(size_t)w * q + (size_t)c] = tmp[(size_t)nk * q + (size_t)c];
    }
    fill_cells(sim, &g);
    lr_vtk_field cf[] = {{"body", 1, g.cbody}};
    lr_vtk_cells cells = {g.ncells, g.conn, g.offs, g.types};
    int rc = lr_vtk_write_vtu(path, n, xyz, &cells, pf, nf, cf, 1, err, errlen);
    free(m);
    return rc;
}

/* A grid's last step as a .vtu and its arrays freed (2D and 3D alike). */
int la_vtk_grid_write(const char *path, la_vtk_grid *g, char *err, size_t errlen)
{
    lr_vtk_field pf[] = {{"mass", 1, g->mass}, {"velocity", 3, g->vel}, {"force", 3, g->force}};
    lr_vtk_cells cells = {g->nc, g->conn, g->offs, g->types};
    int rc = lr_vtk_write_vtu(path, g->nn, g->xyz, &cells, pf, 3, NULL, 0, err, errlen);
    free(g->mass);
    free(g->conn);
    free(g->types);
    return rc;
}

int la_vtk_grid_alloc(la_vtk_grid *g, size_t nn, size_t nc, int corners, const char *path,
                      char *err, size_t errlen)
{
    g->nn = nn;
    g->nc = nc;
    if (la_vtk_arrays(10 * nn, (size_t)(corners + 1) * nc, nc, &g->mass, &g->conn, &g->types,
                      path, err, errlen) != 0)
        return -1;
    g->vel = g->mass + nn;
    g->force = g->mass + 4 * nn;
    g->xyz = g->mass + 7 * nn;
    g->offs = g->conn + (size_t)corners * nc;
    return 0;
}

/* The three arrays of an unstructured grid for vtk.c, all or none: nd
 * doubles of points and data, nconn connectivity and offsets, ntypes cell
 * types (2D and 3D writers alike); -1 and err when memory ran out. */
int la_vtk_arrays(size_t nd, size_t nconn, size_t ntypes, double **d, int64_t **conn,
                  uint8_t **types, const char *path, char *err, size_t errlen)
{
    *d = malloc((nd + 1) * sizeof **d);
    *conn = malloc((nconn + 1) * sizeof **conn);
    *types = malloc(ntypes + 1);
    if (*d && *conn && *types) return 0;
    free(*d);
    free(*conn);
    free(*types);
    snprintf(err, errlen, "cannot write '%s': out of memory", path);
    return -1;
}

/* The grid as an unstructured grid of quads (VTK_QUAD) over its nodes:
 * image data (.vti) is smaller, but meshio reads neither .vti nor .vtr,
 * only .vtu among VTK's XML files, and a .pvd series must be XML, so the
 * one form ParaView, VTK's readers and meshio all read is this (issue 35
 * item 5). Nodes x fastest, as the .vti they replace had them. */
static int write_grid(const lm_sim *sim, const char *path, char *err, size_t errlen)
{
    const lm_grid *gr = &sim->grid;
    la_vtk_grid out;
    if (la_vtk_grid_alloc(&out, (size_t)(gr->nx + 1) * (size_t)(gr->ny + 1),
                          (size_t)gr->nx * (size_t)gr->ny, 4, path, err, errlen) != 0)
        return -1;
    /* the nodes 0..nx x 0..ny, without the wider bases' ghost ring */
    for (int j = 0, i = 0; j <= gr->ny; j++) {
        for (int a = 0; a <= gr->nx; a++, i++) {
            long k = (long)(j + gr->pad) * gr->sx + (a + gr->pad);
            out.mass[i] = gr->m[k];
            out.vel[3 * i] = gr->vx[k];
            out.vel[3 * i + 1] = gr->vy[k];
            out.vel[3 * i + 2] = 0;
            out.force[3 * i] = gr->fx[k];
            out.force[3 * i + 1] = gr->fy[k];
            out.force[3 * i + 2] = 0;
            out.xyz[3 * i] = gr->x0 + a * gr->hx;
            out.xyz[3 * i + 1] = gr->y0 + j * gr->hy;
            out.xyz[3 * i + 2] = 0;
        }
    }
    /* cell (a, j): its corners anticlockwise, as VTK_QUAD wants them */
    int64_t row = gr->nx + 1;
    for (int j = 0, c = 0; j < gr->ny; j++) {
        for (int a = 0; a < gr->nx; a++, c++) {
            int64_t n0 = (int64_t)j * row + a;
            int64_t *q = out.conn + 4 * (size_t)c;
            q[0] = n0;
            q[1] = n0 + 1;
            q[2] = n0 + 1 + row;
            q[3] = n0 + row;
            out.offs[c] = 4 * (int64_t)(c + 1);
            out.types[c] = LR_VTK_QUAD;
        }
    }
    return la_vtk_grid_write(path, &out, err, errlen);
}

/* The collection: every output so far, particles (part 0), grid (1) and
 * the membranes' points (2) where there are some. */
static int write_pvd(const la_vtk *v, char *err, size_t errlen)
{
    int n = 0;
    for (int k = 0; k < v->count; k++) n += 2 + v->mem[k];
    double *t = malloc((size_t)n * sizeof *t);
    int *part = malloc((size_t)n * sizeof *part);
    char *names = malloc((size_t)n * NAME_MAX_LEN);
    const char **files = malloc((size_t)n * sizeof *files);
    int rc = -1;
    char path[PREFIX_MAX + 8];
    if (!t || !part || !names || !files) {
        snprintf(err, errlen, "cannot write '%s.pvd': out of memory", v->prefix);
        goto done;
    }
    const char *base = base_of(v->prefix);
    static const char *const form[] = {"%s_%06d.vtu", "%s_grid_%06d.vtu",
                                       "%s_membranes_%06d.vtu"};
    for (int k = 0, i = 0; k < v->count; k++) {
        for (int s = 0; s < 2 + v->mem[k]; s++, i++) {
            char *nm = names + (size_t)i * NAME_MAX_LEN;
            snprintf(nm, NAME_MAX_LEN, form[s], base, k);
            files[i] = nm;
            t[i] = v->times[k];
            part[i] = s;
        }
    }
    snprintf(path, sizeof path, "%s.pvd", v->prefix);
    rc = lr_vtk_write_pvd(path, n, t, part, files, err, errlen);
done:
    free(t);
    free(part);
    free(names);
    free(files);
    return rc;
}

/* The event: upvalue 1 is the la_vtk state; argument 1 the sim. */
static int vtk_output(lua_State *L)
{
    la_vtk *v = luaL_checkudata(L, lua_upvalueindex(1), LA_VTK);
    la_sim *s = la_check_sim_any(L, 1);   /* 3D: l_vtk3.c writes the pieces */
    lm_sim *sim = s->sim;
    if (v->count == v->cap) {
        int cap = v->cap ? 2 * v->cap : 16;
        double *t = realloc(v->times, (size_t)cap * sizeof *t);
        if (!t) return luaL_error(L, "sim:vtk: out of memory");
        v->times = t;
        unsigned char *m = realloc(v->mem, (size_t)cap);
        if (!m) return luaL_error(L, "sim:vtk: out of memory");
        v->mem = m;
        v->cap = cap;
    }
    char path[PREFIX_MAX + 32], err[PREFIX_MAX + 128];
    /* each piece is checked as its series' name was (l_path.c): it may
     * not replace a file lamina did not write */
    snprintf(path, sizeof path, "%s_%06d.vtu", v->prefix, v->count);
    lua_pushstring(L, path);
    la_check_output_path(L, "sim:vtk", -1);
    snprintf(path, sizeof path, "%s_grid_%06d.vtu", v->prefix, v->count);
    lua_pushstring(L, path);
    la_check_output_path(L, "sim:vtk", -1);
    const int mem = s->s3 && la_vtk3_has_membranes(s->s3);
    char mpath[PREFIX_MAX + 32];
    snprintf(mpath, sizeof mpath, "%s_membranes_%06d.vtu", v->prefix, v->count);
    if (mem) {
        lua_pushstring(L, mpath);
        la_check_output_path(L, "sim:vtk", -1);
        lua_pop(L, 1);
    }
    lua_pop(L, 2);
    /* a series on disk is its .pvd and the pieces it lists: when a piece
     * or the .pvd cannot be written (a full disk), this output's pieces
     * are removed, and the .pvd of the outputs before stays (issue 31) */
    char grid[PREFIX_MAX + 32];
    snprintf(path, sizeof path, "%s_%06d.vtu", v->prefix, v->count);
    snprintf(grid, sizeof grid, "%s_grid_%06d.vtu", v->prefix, v->count);
    if (s->s3 ? la_vtk3_write_particles(s->s3, path, err, sizeof err)
              : write_particles(sim, path, err, sizeof err))
        return luaL_error(L, "sim:vtk: %s", err);
    if (s->s3 ? la_vtk3_write_grid(s->s3, grid, err, sizeof err)
              : write_grid(sim, grid, err, sizeof err)) {
        unlink(path);
        return luaL_error(L, "sim:vtk: %s", err);
    }
    if (mem && la_vtk3_write_membranes(s->s3, mpath, err, sizeof err)) {
        unlink(path);
        unlink(grid);
        return luaL_error(L, "sim:vtk: %s", err);
    }
    v->mem[v->count] = (unsigned char)mem;
    v->times[v->count++] = s->s3 ? s->s3->sim->t : sim->t;
    if (write_pvd(v, err, sizeof err)) {
        v->count--;
        unlink(path);
        unlink(grid);
        if (mem) unlink(mpath);
        return luaL_error(L, "sim:vtk: %s", err);
    }
    return 0;
}

int la_sim_vtk(lua_State *L)
{
    static const char *const keys[] = {"file", "every", NULL};
    const char *fn = "sim:vtk";
    la_sim *s = la_check_sim_any(L, 1);
    const double t = s->s3 ? s->s3->sim->t : s->sim->t;
    la_check_keys(L, 2, fn, keys);
    int ft = la_getfield(L, 2, "file");
    if (ft != LUA_TNIL && ft != LUA_TSTRING)   /* a number made "nan.pvd" (issue 31 item 7) */
        return luaL_error(L, "%s: 'file' must be a string (got %s)", fn, luaL_typename(L, -1));
    size_t len;
    const char *file = lua_tolstring(L, -1, &len);
    if (!file || len == 0) return luaL_error(L, "%s: 'file' (a path without extension) is required", fn);
    if (strlen(file) != len) return luaL_error(L, "%s: 'file' contains a NUL byte", fn);
    if (len >= PREFIX_MAX - 32) return luaL_error(L, "%s: 'file' is too long", fn);
    /* every file goes beside FILE.pvd: confined as every output is (l_path.c) */
    lua_pushfstring(L, "%s.pvd", file);
    la_check_output_path(L, fn, -1);
    lua_pop(L, 1);
    double every = la_opt_number(L, 2, fn, "every", 0);
    if (la_has(L, 2, "every")) la_check_interval(L, fn, "every", every, t);
    la_vtk *v = lua_newuserdatauv(L, sizeof *v, 0);
    memset(v, 0, sizeof *v);
    memcpy(v->prefix, file, len + 1);
    if (luaL_newmetatable(L, LA_VTK)) {
        lua_pushcfunction(L, vtk_gc);
        lua_setfield(L, -2, "__gc");
        lua_pushliteral(L, "lamina.vtk");
        lua_setfield(L, -2, "__metatable");
    }
    lua_setmetatable(L, -2);
    lua_pushcclosure(L, vtk_output, 1);
    int fidx = lua_gettop(L);
    if (every > 0) {
        la_sim_add_event(L, 1, t, every, fidx);
    } else {
        lua_pushvalue(L, fidx);
        lua_pushvalue(L, 1);
        lua_call(L, 1, 0);
    }
    return 0;
}
