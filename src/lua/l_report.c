/* l_report.c - lamina.report{name = value, ...}: the numbers a scenario
 * measured, for people (stdout) and for the gallery (JSON).
 *
 * Every value is printed as "report: name = value". When `lamina run` was
 * given --report FILE (cmd_run.c stores the path in the registry), the whole
 * report so far is rewritten to FILE after every call, atomically (a
 * lr_write_file): a run that fails later still leaves what it had
 * measured, and a reader never sees half a file.
 *
 * Order is deterministic: names within one call are sorted, calls append,
 * and reporting a name again replaces its value in place. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic_file.h"
#include "l_internal.h"

#define REPORT_KEY "lamina.report"          /* registry: array of entries */

static const char FN[] = "lamina.report";

/* A finite number, a string or a boolean; else a named error. */
static void check_scalar(lua_State *L, int idx, const char *name, const char *what)
{
    switch (lua_type(L, idx)) {
    case LUA_TNUMBER:
        if (!isfinite(lua_tonumber(L, idx)))
            luaL_error(L, "%s: '%s'%s must be a finite number (got %s)", FN, name, what,
                       lua_tostring(L, idx));
        return;
    case LUA_TSTRING:
    case LUA_TBOOLEAN:
        return;
    default:
        luaL_error(L, "%s: '%s'%s must be a number, string or boolean (got %s)", FN, name,
                   what, luaL_typename(L, idx));
    }
}

static void check_name(lua_State *L, const char *name)
{
    if (!*name)
        luaL_error(L, "%s: a name must not be empty", FN);
    for (const unsigned char *p = (const unsigned char *)name; *p; p++)
        if (*p < 0x20 || *p == 0x7f)
            luaL_error(L, "%s: name '%s' contains a control character", FN, name);
}

/* Pushes the entry {name=, value=[, paper=, ref=, unit=, tol=]} for the
 * value at idx: a scalar, or {value, paper = x, ref = y, unit = "...", tol =
 * t}. `paper` is a number the paper prints (its table or figure named in the
 * script); `ref` a reference lamina computes itself - an exact solution,
 * our FEM, p r / t of the same run (issue 16 item 2: never shown as the
 * paper's). `tol` is the agreement asked for: with the paper's value when
 * there is one, else with the reference. */
static void push_entry(lua_State *L, const char *name, int idx)
{
    idx = lua_absindex(L, idx);
    lua_createtable(L, 0, 6);
    lua_pushstring(L, name);
    lua_setfield(L, -2, "name");
    if (lua_type(L, idx) != LUA_TTABLE) {
        check_scalar(L, idx, name, "");
        lua_pushvalue(L, idx);
        lua_setfield(L, -2, "value");
        return;
    }
    lua_pushnil(L);
    while (lua_next(L, idx)) {
        lua_pop(L, 1);
        int ok = lua_isinteger(L, -1) && lua_tointeger(L, -1) == 1;
        if (lua_type(L, -1) == LUA_TSTRING) {
            const char *k = lua_tostring(L, -1);
            ok = !strcmp(k, "paper") || !strcmp(k, "ref") || !strcmp(k, "unit") ||
                 !strcmp(k, "tol");
        }
        if (!ok)
            luaL_error(L, "%s: '%s': unknown key '%s' (known: the value first, then "
                       "paper, ref, unit, tol)", FN, name, luaL_tolstring(L, -1, NULL));
    }
    if (lua_rawgeti(L, idx, 1) == LUA_TNIL)
        luaL_error(L, "%s: '%s': the value is missing (write {value, paper = ...})", FN,
                   name);
    check_scalar(L, -1, name, " (the value)");
    lua_setfield(L, -2, "value");
    if (la_getfield(L, idx, "paper") != LUA_TNIL)
        check_scalar(L, -1, name, ".paper");
    lua_setfield(L, -2, "paper");
    if (la_getfield(L, idx, "ref") != LUA_TNIL)
        check_scalar(L, -1, name, ".ref");
    lua_setfield(L, -2, "ref");
    int t = la_getfield(L, idx, "unit");
    if (t != LUA_TNIL && t != LUA_TSTRING)
        luaL_error(L, "%s: '%s'.unit must be a string (got %s)", FN, name,
                   luaL_typename(L, -1));
    lua_setfield(L, -2, "unit");
    t = la_getfield(L, idx, "tol");
    if (t != LUA_TNIL && (t != LUA_TNUMBER || !(lua_tonumber(L, -1) >= 0) ||
                          !isfinite(lua_tonumber(L, -1))))
        luaL_error(L, "%s: '%s'.tol must be a finite number >= 0", FN, name);
    lua_setfield(L, -2, "tol");
}

/* ---- text ------------------------------------------------------------- */

/* Shortest decimal that reads back as the same double: stable, exact and
 * readable (0.27, not 0.27000000000000002). */
static void format_number(lua_State *L, int idx, char *buf, size_t len)
{
    if (lua_isinteger(L, idx)) {
        snprintf(buf, len, "%lld", (long long)lua_tointeger(L, idx));
        return;
    }
    double v = lua_tonumber(L, idx);
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(buf, len, "%.*g", prec, v);
        if (strtod(buf, NULL) == v)
            return;
    }
}

static void add_scalar_text(lua_State *L, luaL_Buffer *b, int idx)
{
    char num[64];
    if (lua_type(L, idx) == LUA_TNUMBER) {
        if (lua_isinteger(L, idx))
            format_number(L, idx, num, sizeof num);
        else
            snprintf(num, sizeof num, "%.6g", lua_tonumber(L, idx));
        luaL_addstring(b, num);
    } else if (lua_type(L, idx) == LUA_TBOOLEAN) {
        luaL_addstring(b, lua_toboolean(L, idx) ? "true" : "false");
    } else {
        luaL_addstring(b, lua_tostring(L, idx));
    }
}

/* " unit" when the value at idx is one. */
static void add_unit(lua_State *L, luaL_Buffer *b, int idx)
{
    if (lua_isnil(L, idx)) return;
    luaL_addchar(b, ' ');
    luaL_addstring(b, lua_tostring(L, idx));
}

/* "report: name = value unit  (paper x unit, tol t)", or "(ours x unit,
 * tol t)" for a reference of lamina's own, on stdout. The
 * fields are pushed first: a luaL_Buffer must stay on top of the stack
 * while it is in use. */
static void print_entry(lua_State *L, int e)
{
    e = lua_absindex(L, e);
    la_getfield(L, e, "name");
    la_getfield(L, e, "value");
    la_getfield(L, e, "unit");
    la_getfield(L, e, "paper");
    la_getfield(L, e, "ref");
    la_getfield(L, e, "tol");
    int top = lua_gettop(L);
    int name = top - 5, value = top - 4, unit = top - 3, paper = top - 2, ref = top - 1,
        tol = top;
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    luaL_addstring(&b, "report: ");
    luaL_addstring(&b, lua_tostring(L, name));
    luaL_addstring(&b, " = ");
    add_scalar_text(L, &b, value);
    add_unit(L, &b, unit);
    for (int k = 0; k < 2; k++) {   /* the paper's value, then ours */
        int at = k == 0 ? paper : ref;
        if (lua_isnil(L, at)) continue;
        luaL_addstring(&b, k == 0 ? "  (paper " : "  (ours ");
        add_scalar_text(L, &b, at);
        add_unit(L, &b, unit);
        if (!lua_isnil(L, tol) && (k == 0 || lua_isnil(L, paper))) {
            luaL_addstring(&b, ", tol ");
            add_scalar_text(L, &b, tol);
        }
        luaL_addchar(&b, ')');
    }
    luaL_pushresult(&b);
    size_t len;
    const char *line = lua_tolstring(L, -1, &len);
    la_write_clean(stdout, line, len);   /* a value's text may hold escapes (l_print.c) */
    fputc('\n', stdout);
    lua_settop(L, top - 6);
}

/* ---- JSON ------------------------------------------------------------- */

static void add_json_string(luaL_Buffer *b, const char *s)
{
    luaL_addchar(b, '"');
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        char esc[8];
        if (*p == '"' || *p == '\\') {
            luaL_addchar(b, '\\');
            luaL_addchar(b, (char)*p);
        } else if (*p < 0x20 || *p == 0x7f) {
            snprintf(esc, sizeof esc, "\\u%04x", *p);
            luaL_addstring(b, esc);
        } else {
            luaL_addchar(b, (char)*p);
        }
    }
    luaL_addchar(b, '"');
}

/* The value at idx as JSON. Uses no stack slots above the buffer. */
static void add_json_value(lua_State *L, luaL_Buffer *b, int idx)
{
    char num[64];
    switch (lua_type(L, idx)) {
    case LUA_TNUMBER:
        format_number(L, idx, num, sizeof num);
        luaL_addstring(b, num);
        break;
    case LUA_TBOOLEAN:
        luaL_addstring(b, lua_toboolean(L, idx) ? "true" : "false");
        break;
    default:
        add_json_string(b, lua_tostring(L, idx));
    }
}

/* Pushes the whole report as JSON text. Entry fields are pushed below the
 * buffer (luaL_Buffer must stay on top while it is in use), so everything
 * is gathered first. */
static void push_json(lua_State *L, int report)
{
    static const char *const fields[] = { "name", "value", "paper", "ref", "unit", "tol" };
    enum { NF = sizeof fields / sizeof *fields };
    lamina_run *run = la_run(L);
    lua_Integer n = (lua_Integer)lua_rawlen(L, report);
    int base = lua_gettop(L);
    luaL_checkstack(L, (int)(NF * n) + 4, "report too large");
    for (lua_Integer i = 1; i <= n; i++) {
        lua_rawgeti(L, report, i);
        int e = lua_gettop(L);
        for (int f = 0; f < NF; f++)
            la_getfield(L, e, fields[f]);
        lua_remove(L, e);
    }
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    luaL_addstring(&b, "{\n  \"script\": ");
    add_json_string(&b, run && run->script ? run->script : "");
    luaL_addstring(&b, ",\n  \"script_hash\": ");
    add_json_string(&b, run ? run->script_hash : "");
    luaL_addstring(&b, ",\n  \"values\": [");
    for (lua_Integer i = 0; i < n; i++) {
        int at = base + 1 + NF * (int)i;
        luaL_addstring(&b, i ? ",\n    {" : "\n    {");
        for (int f = 0; f < NF; f++) {
            if (lua_isnil(L, at + f))
                continue;
            if (f)
                luaL_addstring(&b, ", ");
            add_json_string(&b, fields[f]);
            luaL_addstring(&b, ": ");
            add_json_value(L, &b, at + f);
        }
        luaL_addchar(&b, '}');
    }
    luaL_addstring(&b, n ? "\n  ]\n}\n" : "]\n}\n");
    luaL_pushresult(&b);
    lua_copy(L, -1, base + 1);   /* (lua_replace would drop it when n = 0) */
    lua_settop(L, base + 1);
}

/* --report FILE, from the run's configuration (lamina_run.report_file). */
static void write_report(lua_State *L, int report)
{
    const lamina_run *run = la_run(L);
    const char *path = run ? run->report_file : NULL;
    if (!path) return;
    push_json(L, report);
    size_t len;
    const char *text = lua_tolstring(L, -1, &len);
    char err[1024];
    if (lr_write_file(path, text, len, err, sizeof err) != 0)
        luaL_error(L, "%s: %s", FN, err);
    lua_pop(L, 1);
}

/* ---- lamina.report ---------------------------------------------------- */

static int by_name(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

int la_report(lua_State *L)
{
    la_check_table(L, 1, FN);
    lua_settop(L, 1);
    /* the names, sorted: a Lua table's order is not the script's order */
    size_t n = 0;
    lua_pushnil(L);
    while (lua_next(L, 1)) {
        lua_pop(L, 1);
        if (lua_type(L, -1) != LUA_TSTRING)
            return luaL_error(L, "%s: unexpected positional argument (write "
                              "lamina.report{name = value})", FN);
        n++;
    }
    const char **names = (const char **)lua_newuserdatauv(L, (n ? n : 1) * sizeof *names, 0);
    size_t k = 0;
    lua_pushnil(L);
    while (lua_next(L, 1)) {
        lua_pop(L, 1);
        names[k++] = lua_tostring(L, -1);   /* keys stay alive in the argument */
    }
    qsort(names, n, sizeof *names, by_name);

    /* every entry checked before any is stored: a call is all or nothing */
    int first = lua_gettop(L) + 1;
    for (size_t i = 0; i < n; i++) {
        /* each entry stays on the stack until all are checked, and a C
         * function is given only LUA_MINSTACK (20) slots: ~30 names wrote
         * past them (issue 31, SIGSEGV). The entry and push_entry's work
         * need 8; beyond Lua's stack limit this is an error, not a crash. */
        luaL_checkstack(L, 8, "lamina.report: too many names in one call");
        check_name(L, names[i]);
        la_getfield(L, 1, names[i]);
        push_entry(L, names[i], -1);
        lua_remove(L, -2);
    }
    la_subtable(L, LUA_REGISTRYINDEX, REPORT_KEY);
    int report = lua_gettop(L);
    lua_Integer len = (lua_Integer)lua_rawlen(L, report);
    for (size_t i = 0; i < n; i++) {
        lua_Integer slot = len + 1;
        for (lua_Integer j = 1; j <= len; j++) {
            lua_rawgeti(L, report, j);
            la_getfield(L, -1, "name");
            int same = strcmp(lua_tostring(L, -1), names[i]) == 0;
            lua_pop(L, 2);
            if (same) {
                slot = j;
                break;
            }
        }
        if (slot == len + 1)
            len++;
        lua_pushvalue(L, first + (int)i);
        lua_seti(L, report, slot);
        print_entry(L, first + (int)i);
    }
    fflush(stdout);
    write_report(L, report);
    return 0;
}
