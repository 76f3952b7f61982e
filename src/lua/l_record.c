/* l_record.c - sim:record{...}: a history of chosen quantities, kept in
 * memory, readable from Lua, and written as CSV at the end of every
 * run/step call (whole or not at all: atomic_file.h).
 *
 *   local rec = sim:record{ file = "out/h.csv", every = 1e-4, energy = true,
 *                           points = { mass = {string, -1} },   -- x, y of a point
 *                           angle = { theta = string },         -- first -> last point
 *                           values = { d = function(s) return ... end },
 *                           average = 0.01 }                    -- running means
 *
 * Columns come in a fixed order (t, step, energies, then points, angles and
 * values sorted by name) so that the same script writes the same file. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "atomic_file.h"
#include "fields.h"
#include "l_internal.h"
#include "l_sim3.h"
#include "util.h"

#define LA_RECORD "lamina.record"

enum { SRC_T, SRC_STEP, SRC_ENERGY, SRC_FIELD, SRC_ANGLE, SRC_VALUE };

typedef struct la_column {
    char name[64];
    int src;
    int body;           /* points, fields, angles */
    long index;         /* points, fields: particle within the body (0-based) */
    int which;          /* energy component; value: ref in the uservalue;
                           field: the component */
    const lm_field *field;  /* points (position) and fields: the engine's
                               table (fields.c) */
} la_column;

typedef struct la_record {
    la_column *cols;
    int ncols;
    double *rows;       /* nrows * ncols */
    size_t nrows, cap;
    double average;     /* running-mean window in time, 0: none */
    int energy;         /* has energy columns: the sum over particles is
                           taken only then */
    int has_file;
    int dirty;
    int freed;          /* by rec_gc: every method refuses it */
} la_record;

static la_record *check_record(lua_State *L, int idx)
{
    la_record *r = luaL_checkudata(L, idx, LA_RECORD);
    if (r->freed) luaL_error(L, "the recorder has been freed");
    return r;
}

/* uservalue slots: 1 the sim, 2 a table {file = ..., fns = {...}} */

static la_column *add_column(lua_State *L, la_record *r, const char *name, int src)
{
    la_column *c = lu_push(&r->cols, (size_t)r->ncols, sizeof *r->cols);
    if (!c) luaL_error(L, "sim:record: out of memory");
    r->ncols++;
    if (strlen(name) >= sizeof c->name)
        luaL_error(L, "sim:record: column name '%s' is too long", name);
    /* a CSV header field: nothing that runs as shell or Python (l_path.c) */
    la_check_csv_name(L, "sim:record", "column name", name);
    for (int i = 0; i < r->ncols - 1; i++)
        if (strcmp(r->cols[i].name, name) == 0)
            luaL_error(L, "sim:record: column '%s' is given twice", name);
    strcpy(c->name, name);
    c->src = src;
    return c;
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* The string keys of the table at idx, sorted (Lua's order is not fixed). */
static int sorted_keys(lua_State *L, int idx, const char *what, const char ***out)
{
    idx = lua_absindex(L, idx);
    if (!lua_istable(L, idx))   /* lua_next on a non-table crashes liblua */
        luaL_error(L, "sim:record: '%s' must be a table of named entries (got %s)", what,
                   luaL_typename(L, idx));
    int n = 0;
    lua_pushnil(L);
    while (lua_next(L, idx)) {
        lua_pop(L, 1);
        if (lua_type(L, -1) != LUA_TSTRING)
            luaL_error(L, "sim:record: '%s' must be a table of named entries", what);
        n++;
    }
    const char **k = lua_newuserdatauv(L, (size_t)(n ? n : 1) * sizeof *k, 0);
    int i = 0;
    lua_pushnil(L);
    while (lua_next(L, idx)) {
        lua_pop(L, 1);
        k[i++] = lua_tostring(L, -1);   /* alive: the table holds the key */
    }
    qsort(k, (size_t)n, sizeof *k, cmp_str);
    *out = k;
    return n;
}

/* What the readers of sim:record's named tables share. */
typedef struct entries {
    la_record *r;
    lm_sim *sim;
    int fns;                    /* the recorder's function table (values) */
} entries;

/* Calls one(L, e, name) for each entry of option table `what` (argument 2)
 * in name order, with the entry on top of the stack; one may push more,
 * the stack is put back after it. Nothing when the option is absent. */
static void each_entry(lua_State *L, const char *what, const entries *e,
                       void (*one)(lua_State *L, const entries *e, const char *name))
{
    if (la_getfield(L, 2, what) == LUA_TNIL) { lua_pop(L, 1); return; }
    int t = lua_gettop(L);
    const char **k;
    int n = sorted_keys(L, t, what, &k);
    for (int i = 0; i < n; i++) {
        int top = lua_gettop(L);
        la_getfield(L, t, k[i]);
        one(L, e, k[i]);
        lua_settop(L, top);
    }
    lua_pop(L, 2);
}

/* {body, index, ...} on top (option `what`, entry `name`, `shape` for the
 * message): the body and the particle within it (0-based). */
static long point_of(lua_State *L, const entries *e, const char *what, const char *name,
                     const char *shape, int len, int *body)
{
    if (!lua_istable(L, -1) || lua_rawlen(L, -1) != (size_t)len)
        luaL_error(L, "sim:record: %s.%s must be %s", what, name, shape);
    lua_rawgeti(L, -1, 1);
    lm_sim *bs;
    int b = la_check_body(L, -1, &bs);
    if (bs != e->sim)
        luaL_error(L, "sim:record: %s.%s: the body belongs to another sim", what, name);
    lua_rawgeti(L, -2, 2);
    /* a number, shown as given: luaL_checkinteger said "bad argument #-1
     * to '?'" of NaN and (int) made 1e18 -1486618624 (issue 31 item 7) */
    int isnum;
    double v = lua_tonumberx(L, -1, &isnum);
    long count = (long)e->sim->bodies[b].count;
    if (!isnum || v != floor(v) || !(fabs(v) <= (double)count))
        luaL_error(L, "sim:record: %s.%s: index %s is not a point of the body: a whole "
                   "number from 1 to %d, or from -1 back to -%d", what, name,
                   isnum ? lua_tostring(L, -1) : luaL_typename(L, -1), (int)count,
                   (int)count);   /* at most LM_MAX_PARTICLES: an int */
    long idx = (long)v;
    long q = idx < 0 ? count + idx : idx - 1;
    if (q < 0 || q >= count)
        luaL_error(L, "sim:record: %s.%s: index %d is outside the body's %d points",
                   what, name, (int)idx, (int)count);   /* |idx| <= count: an int */
    lua_pop(L, 2);
    *body = b;
    return q;
}

static la_column *field_column(lua_State *L, const entries *e, const char *col, int b,
                               long q, const lm_field *f, int comp)
{
    la_column *c = add_column(L, e->r, col, SRC_FIELD);
    c->body = b;
    c->index = q;
    c->field = f;
    c->which = comp;
    return c;
}

/* points.NAME = {body, index}: columns NAME_x, NAME_y (the table's
 * position). */
static void read_point(lua_State *L, const entries *e, const char *name)
{
    int b;
    long q = point_of(L, e, "points", name, "{body, index}", 2, &b);
    int comp;
    const lm_field *pos = lm_field_find("x", &comp);
    char col[64];
    snprintf(col, sizeof col, "%s_x", name);
    field_column(L, e, col, b, q, pos, 0);
    snprintf(col, sizeof col, "%s_y", name);
    field_column(L, e, col, b, q, pos, 1);
}

/* fields.NAME = {body, index, field}: column NAME, the field (a name or a
 * component's name of the engine's table, as body:particles() gives it)
 * at that point; the body's kind must have it. */
static void read_field(lua_State *L, const entries *e, const char *name)
{
    int b;
    long q = point_of(L, e, "fields", name, "{body, index, field}", 3, &b);
    if (lua_rawgeti(L, -1, 3) != LUA_TSTRING)
        luaL_error(L, "sim:record: fields.%s: the field must be a name such as \"pressure\" "
                   "(got %s)", name, luaL_typename(L, -1));
    const char *fname = lua_tostring(L, -1);
    int comp;
    const lm_field *f = lm_field_find(fname, &comp);
    if (!f)
        luaL_error(L, "sim:record: fields.%s: no field '%s' (docs/api.md, \"Particle "
                   "fields\")", name, fname);
    lm_sim *sim = e->sim;
    size_t at = sim->bodies[b].first + (size_t)q;
    if (!lm_field_has(sim, f, at))
        luaL_error(L, "sim:record: fields.%s: body %d has no field '%s' (not a quantity of "
                   "its kind)", name, b + 1, fname);
    field_column(L, e, name, b, q, f, comp);
}

/* angle.NAME = body: the line through its first and last points. */
static void read_angle(lua_State *L, const entries *e, const char *name)
{
    lm_sim *bs;
    int b = la_check_body(L, -1, &bs);
    if (bs != e->sim || e->sim->bodies[b].count < 2)
        luaL_error(L, "sim:record: angle.%s needs a body of this sim with 2 or more points", name);
    add_column(L, e->r, name, SRC_ANGLE)->body = b;
}

/* values.NAME = function(sim) -> number, kept in the function table. */
static void read_value(lua_State *L, const entries *e, const char *name)
{
    if (!lua_isfunction(L, -1))
        luaL_error(L, "sim:record: values.%s must be a function(sim) -> number", name);
    la_column *c = add_column(L, e->r, name, SRC_VALUE);
    c->which = luaL_ref(L, e->fns);
}

/* ---- sampling -------------------------------------------------------- */

/* What a row's t, step and energy columns read, from either dimension's
 * engine (a 3D run, l_sim3.c, has the columns t, step, energy, values). */
typedef struct row_clock {
    double t, step, energy[6];  /* kinetic, strain, internal, potential, total, damped */
} row_clock;

static double sample(lua_State *L, const la_column *c, lm_sim *sim, const row_clock *k)
{
    switch (c->src) {
    case SRC_T: return k->t;
    case SRC_STEP: return k->step;
    case SRC_ENERGY: return k->energy[c->which];
    default: break;
    }
    switch (c->src) {
    case SRC_FIELD:
        /* the tangents before the first step, as frames want them */
        if (c->field->tangents && !sim->prepared && lm_sim_prepare(sim) != LM_OK)
            luaL_error(L, "sim:record: %s", sim->err);
        return lm_field_value(sim, c->field, c->which,
                              sim->bodies[c->body].first + (size_t)c->index);
    case SRC_ANGLE: {
        /* [M] §3.1.2: the line joining the first and last points, in
         * degrees from the downward vertical, positive towards +x */
        const lm_particles *p = &sim->p;
        const lm_body *b = &sim->bodies[c->body];
        size_t a = b->first, z = b->first + b->count - 1;
        return atan2(p->x[z] - p->x[a], -(p->y[z] - p->y[a])) * 180 / acos(-1.0);
    }
    case SRC_VALUE: {
        lua_getiuservalue(L, lua_upvalueindex(1), 2);
        la_getfield(L, -1, "fns");
        lua_rawgeti(L, -1, c->which);
        lua_pushvalue(L, 1);    /* the sim */
        lua_call(L, 1, 1);
        int ok;
        double v = lua_tonumberx(L, -1, &ok);
        if (!ok) luaL_error(L, "sim:record: values.%s returned %s, not a number",
                            c->name, luaL_typename(L, -1));
        lua_pop(L, 3);
        return v;
    }
    }
    return 0;
}

/* The event function: upvalue 1 is the recorder, argument 1 the sim. */
static int record_sample(lua_State *L)
{
    la_record *r = check_record(L, lua_upvalueindex(1));
    la_sim *s = la_check_sim_any(L, 1);
    lm_sim *sim = s->sim;
    if (r->nrows == r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 256;
        double *rows = realloc(r->rows, cap * (size_t)r->ncols * sizeof *rows);
        if (!rows) return luaL_error(L, "sim:record: out of memory");
        r->rows = rows;
        r->cap = cap;
    }
    row_clock k;
    memset(&k, 0, sizeof k);
    if (s->s3) {
        lm3_energy e3 = {0, 0, 0, 0, 0};
        if (r->energy) lm3_energy_of(s->s3->sim, &e3);
        k.t = s->s3->sim->t;
        k.step = (double)s->s3->sim->nstep;
        const double v[6] = {e3.kinetic, e3.strain, e3.internal, e3.potential, e3.total, 0};
        memcpy(k.energy, v, sizeof v);
    } else {
        lm_energy e = {0, 0, 0, 0, 0};
        if (r->energy) e = lm_sim_energy(sim);
        k.t = sim->t;
        k.step = (double)sim->step;
        const double v[6] = {e.kinetic, e.strain, e.internal, e.potential, e.total, sim->damped};
        memcpy(k.energy, v, sizeof v);
    }
    double *row = r->rows + r->nrows * (size_t)r->ncols;
    for (int i = 0; i < r->ncols; i++) row[i] = sample(L, &r->cols[i], sim, &k);
    r->nrows++;
    const lamina_run *run = la_run(L);
    if (run && run->observer && run->observer->record && r->ncols > 0) {
        /* lamina serve plots the series live: named by the recorder's file */
        const char *label = "record";
        int top = lua_gettop(L);
        lua_getiuservalue(L, lua_upvalueindex(1), 2);
        if (lua_type(L, -1) == LUA_TTABLE && la_getfield(L, -1, "file") == LUA_TSTRING)
            label = lua_tostring(L, -1);
        run->observer->record(run->observer->ud, r, label, r->ncols, r->cols[0].name,
                              sizeof r->cols[0], row);
        lua_settop(L, top);
    }
    r->dirty = 1;
    return 0;
}

/* ---- reading back ---------------------------------------------------- */

static int find_column(const la_record *r, const char *name)
{
    for (int i = 0; i < r->ncols; i++)
        if (strcmp(r->cols[i].name, name) == 0) return i;
    return -1;
}

/* Running mean of column c over the window (t - average, t]. */
static void running_mean(const la_record *r, int c, double *out)
{
    double sum = 0;
    size_t lo = 0;
    for (size_t i = 0; i < r->nrows; i++) {
        sum += r->rows[i * r->ncols + c];
        double t = r->rows[i * r->ncols];
        /* the window always holds row i: with an average below t's
         * resolution t - average == t, and lo ran past i and off the
         * rows (issue 31: average = 1e-18, heap overflow) */
        while (lo < i && r->rows[lo * r->ncols] <= t - r->average) {
            sum -= r->rows[lo * r->ncols + c];
            lo++;
        }
        out[i] = sum / (double)(i - lo + 1);
    }
}

/* rec:column(name) -> array; "<name>_avg" gives the running mean. */
static int rec_column(lua_State *L)
{
    la_record *r = check_record(L, 1);
    const char *name = luaL_checkstring(L, 2);
    int c = find_column(r, name);
    int avg = 0;
    size_t n = strlen(name);
    if (c < 0 && r->average > 0 && n > 4 && strcmp(name + n - 4, "_avg") == 0) {
        lua_pushlstring(L, name, n - 4);
        c = find_column(r, lua_tostring(L, -1));
        lua_pop(L, 1);
        avg = 1;
    }
    if (c < 0) return luaL_error(L, "rec:column: no column '%s'", name);
    double *m = NULL;
    if (avg) {   /* stays on the stack, below the result, until we return */
        m = lua_newuserdatauv(L, (r->nrows ? r->nrows : 1) * sizeof *m, 0);
        running_mean(r, c, m);
    }
    lua_createtable(L, (int)r->nrows, 0);
    for (size_t i = 0; i < r->nrows; i++) {
        lua_pushnumber(L, avg ? m[i] : r->rows[i * r->ncols + c]);
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    return 1;
}

/* rec:mean(name, t0, t1): the time average of a column over [t0, t1]
 * (trapezoidal in t), for quantities that ring. */
static int rec_mean(lua_State *L)
{
    la_record *r = check_record(L, 1);
    const char *name = luaL_checkstring(L, 2);
    int c = find_column(r, name);
    if (c < 0) return luaL_error(L, "rec:mean: no column '%s'", name);
    double t0 = luaL_optnumber(L, 3, -HUGE_VAL), t1 = luaL_optnumber(L, 4, HUGE_VAL);
    if (isnan(t0) || isnan(t1))   /* NaN compared false: the whole record (issue 31 item 7) */
        return luaL_error(L, "rec:mean: the times must be numbers, not NaN (got %f, %f)", t0, t1);
    double area = 0, span = 0;
    for (size_t i = 1; i < r->nrows; i++) {
        double ta = r->rows[(i - 1) * r->ncols], tb = r->rows[i * r->ncols];
        if (ta < t0 || tb > t1) continue;
        area += 0.5 * (tb - ta) * (r->rows[(i - 1) * r->ncols + c] + r->rows[i * r->ncols + c]);
        span += tb - ta;
    }
    if (!(span > 0)) return luaL_error(L, "rec:mean: no samples between %f and %f", t0, t1);
    lua_pushnumber(L, area / span);
    return 1;
}

static int rec_columns(lua_State *L)
{
    la_record *r = check_record(L, 1);
    lua_createtable(L, r->ncols, 0);
    for (int i = 0; i < r->ncols; i++) {
        lua_pushstring(L, r->cols[i].name);
        lua_rawseti(L, -2, i + 1);
    }
    return 1;
}

static int rec_len(lua_State *L)
{
    lua_pushinteger(L, (lua_Integer)check_record(L, 1)->nrows);
    return 1;
}

/* ---- CSV ------------------------------------------------------------- */

static void csv_number(luaL_Buffer *b, double v)
{
    char s[32];
    snprintf(s, sizeof s, "%.10g", v);
    luaL_addstring(b, s);
}

/* Builds the CSV text; `file` from the uservalue. Returns 0 if no file. */
static int write_csv(lua_State *L, int ridx)
{
    la_record *r = check_record(L, ridx);
    if (!r->has_file) return 0;
    lua_getiuservalue(L, ridx, 2);
    la_getfield(L, -1, "file");
    const char *file = lua_tostring(L, -1);
    double *avg = NULL;
    int nav = r->average > 0 ? r->ncols - 2 : 0;
    if (nav > 0) {
        avg = lua_newuserdatauv(L, (size_t)nav * (r->nrows ? r->nrows : 1) * sizeof *avg, 0);
        for (int c = 0; c < nav; c++) running_mean(r, c + 2, avg + (size_t)c * r->nrows);
    }
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    for (int c = 0; c < r->ncols; c++) {
        if (c) luaL_addchar(&b, ',');
        luaL_addstring(&b, r->cols[c].name);
    }
    for (int c = 0; c < nav; c++) {
        luaL_addchar(&b, ',');
        luaL_addstring(&b, r->cols[c + 2].name);
        luaL_addstring(&b, "_avg");
    }
    luaL_addchar(&b, '\n');
    for (size_t i = 0; i < r->nrows; i++) {
        for (int c = 0; c < r->ncols; c++) {
            if (c) luaL_addchar(&b, ',');
            csv_number(&b, r->rows[i * r->ncols + c]);
        }
        for (int c = 0; c < nav; c++) {
            luaL_addchar(&b, ',');
            csv_number(&b, avg[(size_t)c * r->nrows + i]);
        }
        luaL_addchar(&b, '\n');
    }
    luaL_pushresult(&b);
    size_t len;
    const char *text = lua_tolstring(L, -1, &len);
    char err[512];
    if (lr_write_file(file, text, len, err, sizeof err) != 0) {
        return la_fail_raisef(L, LAMINA_FAIL_IO, "sim:record: %s", err);
    }
    r->dirty = 0;
    lua_pop(L, nav > 0 ? 4 : 3);
    return 1;
}

static int rec_write(lua_State *L)
{
    check_record(L, 1);
    write_csv(L, 1);
    return 0;
}

void la_record_flush(lua_State *L, int sidx)
{
    sidx = lua_absindex(L, sidx);
    lua_getiuservalue(L, sidx, 1);
    if (la_getfield(L, -1, "recorders") == LUA_TTABLE) {
        int t = lua_gettop(L);
        lua_Integer n = (lua_Integer)lua_rawlen(L, t);
        for (lua_Integer i = 1; i <= n; i++) {
            lua_rawgeti(L, t, i);
            la_record *r = luaL_checkudata(L, -1, LA_RECORD);
            if (!r->freed && r->dirty) write_csv(L, lua_gettop(L));
            lua_pop(L, 1);
        }
    }
    lua_pop(L, 2);
}

/* Only the collector calls this (locked metatable); idempotent anyway. */
static int rec_gc(lua_State *L)
{
    la_record *r = luaL_checkudata(L, 1, LA_RECORD);
    LU_FREE_ALL(r->cols, r->rows);
    r->cols = NULL;
    r->rows = NULL;
    r->ncols = 0;
    r->nrows = r->cap = 0;
    r->dirty = 0;
    r->freed = 1;
    return 0;
}

/* ---- the constructor ------------------------------------------------- */

int la_sim_record(lua_State *L)
{
    static const char *const keys[] = {"file", "every", "energy", "points", "angle",
                                       "values", "average", "fields", NULL};
    static const char *const energies[] = {"kinetic", "strain", "internal", "potential", "total",
                                           "damped"};
    const char *fn = "sim:record";
    la_sim *s = la_check_sim_any(L, 1);
    la_check_keys(L, 2, fn, keys);
    /* a 3D run records t, step, energy and values (the point, field and
     * angle columns read the 2D engine's bodies) */
    static const char *const only2d[] = {"points", "fields", "angle", NULL};
    for (int i = 0; s->s3 && only2d[i]; i++)
        if (la_has(L, 2, only2d[i]))
            return luaL_error(L, "%s: '%s' is not available for a 3D simulation in this build "
                              "(3D records t, step, energy and values)", fn, only2d[i]);
    const double t_now = s->s3 ? s->s3->sim->t : s->sim->t;
    double every = la_opt_number(L, 2, fn, "every", s->s3 ? s->s3->sim->def.dt : s->sim->def.dt);
    la_check_interval(L, fn, "every", every, t_now);
    const char *file = la_opt_output_path(L, 2, fn, "file");

    la_record *r = lua_newuserdatauv(L, sizeof *r, 2);
    memset(r, 0, sizeof *r);
    luaL_setmetatable(L, LA_RECORD);
    int ridx = lua_gettop(L);
    lua_pushvalue(L, 1);
    lua_setiuservalue(L, ridx, 1);
    lua_createtable(L, 0, 2);
    lua_newtable(L);
    lua_setfield(L, -2, "fns");
    if (file) {
        lua_pushstring(L, file);
        lua_setfield(L, -2, "file");
        r->has_file = 1;
    }
    lua_setiuservalue(L, ridx, 2);
    r->average = la_opt_number(L, 2, fn, "average", 0);
    if (!(r->average >= 0) || !isfinite(r->average))
        return luaL_error(L, "%s: average must be a finite time >= 0 (got %f)", fn, r->average);

    add_column(L, r, "t", SRC_T);
    add_column(L, r, "step", SRC_STEP);
    int et = la_getfield(L, 2, "energy");
    if (et != LUA_TNIL && et != LUA_TBOOLEAN)   /* issue 31 item 7: any type was taken */
        luaL_error(L, "%s: 'energy' must be true or false (got %s)", fn, luaL_typename(L, -1));
    int energy = lua_toboolean(L, -1);
    lua_pop(L, 1);
    r->energy = energy;
    /* "damped" (the grid damping's work, damping.c) only when the sim is
     * damped as the recorder is made: undamped runs keep their columns */
    int nen = !s->s3 && s->sim->def.damping > 0 ? 6 : 5;
    for (int i = 0; energy && i < nen; i++) add_column(L, r, energies[i], SRC_ENERGY)->which = i;
    lua_getiuservalue(L, ridx, 2);
    la_getfield(L, -1, "fns");
    const entries e = {r, s->sim, lua_gettop(L)};
    each_entry(L, "points", &e, read_point);
    each_entry(L, "fields", &e, read_field);
    each_entry(L, "angle", &e, read_angle);
    each_entry(L, "values", &e, read_value);
    lua_pop(L, 2);

    /* the sim keeps its recorders (to flush them); the event samples */
    lua_getiuservalue(L, 1, 1);
    la_subtable(L, -1, "recorders");
    lua_pushvalue(L, ridx);
    lua_rawseti(L, -2, (lua_Integer)lua_rawlen(L, -2) + 1);
    lua_pop(L, 2);
    lua_pushvalue(L, ridx);
    lua_pushcclosure(L, record_sample, 1);
    la_sim_add_event(L, 1, t_now, every, -1);
    lua_pop(L, 1);
    lua_settop(L, ridx);
    return 1;
}

void la_open_record(lua_State *L)
{
    static const luaL_Reg meta[] = {{"__gc", rec_gc}, {"__len", rec_len}, {NULL, NULL}};
    static const luaL_Reg methods[] = {{"column", rec_column},
                                       {"columns", rec_columns},
                                       {"mean", rec_mean},
                                       {"write", rec_write},
                                       {NULL, NULL}};
    la_new_class(L, LA_RECORD, meta, methods);
    lua_pop(L, 1);
}

/* ---- checkpoints (l_checkpoint.c) -------------------------------------- */

/* Recorder i (1-based, creation order) of the sim at sidx, or NULL. */
static la_record *nth_record(lua_State *L, int sidx, int i)
{
    sidx = lua_absindex(L, sidx);
    la_record *r = NULL;
    lua_getiuservalue(L, sidx, 1);
    if (lua_getfield(L, -1, "recorders") == LUA_TTABLE && lua_rawgeti(L, -1, i) == LUA_TUSERDATA)
        r = luaL_testudata(L, -1, LA_RECORD);
    lua_pop(L, 3);
    return r;
}

int la_record_count(lua_State *L, int sidx)
{
    sidx = lua_absindex(L, sidx);
    lua_getiuservalue(L, sidx, 1);
    int n = lua_getfield(L, -1, "recorders") == LUA_TTABLE ? (int)lua_rawlen(L, -1) : 0;
    lua_pop(L, 2);
    return n;
}

void la_record_rows(lua_State *L, int sidx, int i, int *ncols, size_t *nrows,
                    const double **rows)
{
    la_record *r = nth_record(L, sidx, i);
    *ncols = r ? r->ncols : 0;
    *nrows = r ? r->nrows : 0;
    *rows = r ? r->rows : NULL;
}

int la_record_set_rows(lua_State *L, int sidx, int i, int ncols, size_t nrows,
                       const double *rows)
{
    la_record *r = nth_record(L, sidx, i);
    if (!r || r->ncols != ncols) return -1;
    if (nrows > r->cap) {
        double *q = realloc(r->rows, nrows * (size_t)ncols * sizeof *q);
        if (!q) luaL_error(L, "out of memory restoring a recorder's rows");
        r->rows = q;
        r->cap = nrows;
    }
    if (nrows) memcpy(r->rows, rows, nrows * (size_t)ncols * sizeof *rows);
    r->nrows = nrows;
    r->dirty = 1;
    return 0;
}
