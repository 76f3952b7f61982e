/* l_csv.c - lamina.read_csv(path): a CSV that lamina wrote (sim:record,
 * lamina.plot{csv = true}) read back into Lua, so that a script can overlay
 * a sweep's histories in one plot (issue 20 item 5).
 *
 *   local h, names, n = lamina.read_csv("sw/E=1000/energy.csv")
 *   -- h.t, h.step, h.total: the columns as arrays of n numbers;
 *   -- names = {"t", "step", "total"} in file order
 *
 * The first line names the columns; every other line holds numbers (empty
 * lines and lines starting with '#' are skipped). Reading is confined as
 * writing is (l_path.c: under the working directory or --out-root) and
 * bounded (a regular file of at most 256 MB, render/read_file.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "l_internal.h"
#include "read_file.h"

#define MAX_COLUMNS 4096

/* The next field of line s (up to ',' or the line's end), unquoted:
 * start and length; returns where the following field starts or NULL at
 * the line's end. */
static const char *field(const char *s, const char *end, const char **f, size_t *n)
{
    const char *c = s;
    while (c < end && *c != ',') c++;
    const char *a = s, *b = c;
    while (a < b && (*a == ' ' || *a == '\t')) a++;
    while (b > a && (b[-1] == ' ' || b[-1] == '\t' || b[-1] == '\r')) b--;
    if (b - a >= 2 && *a == '"' && b[-1] == '"') {
        a++;
        b--;
    }
    *f = a;
    *n = (size_t)(b - a);
    return c < end ? c + 1 : NULL;
}

int la_read_csv(lua_State *L)
{
    const char *fn = "lamina.read_csv";
    luaL_checktype(L, 1, LUA_TSTRING);
    const char *path = la_check_input_path(L, fn, 1);
    char *text, err[600];
    size_t len;
    if (lr_read_file(path, LR_READ_MAX, &text, &len, err, sizeof err))
        return luaL_error(L, "%s: %s", fn, err);
    /* the text goes into a userdata so that an error below frees it */
    char *buf = lua_newuserdatauv(L, len + 1, 0);
    memcpy(buf, text, len + 1);
    free(text);
    const char *p = buf, *end = buf + len;
    int ncols = 0, line = 0;
    lua_newtable(L);                      /* the result */
    int res = lua_gettop(L);
    lua_newtable(L);                      /* names */
    int names = lua_gettop(L);
    lua_Integer rows = 0;
    while (p < end) {
        const char *eol = memchr(p, '\n', (size_t)(end - p));
        if (!eol) eol = end;
        line++;
        const char *q = p;
        p = eol + (eol < end);
        if (eol == q || *q == '#' || (eol - q == 1 && *q == '\r')) continue;
        if (ncols == 0) {                 /* the header */
            const char *s = q;
            while (s) {
                const char *f;
                size_t n;
                s = field(s, eol, &f, &n);
                if (n == 0) return luaL_error(L, "%s: '%s' line %d: an empty column name", fn, path, line);
                if (++ncols > MAX_COLUMNS)
                    return luaL_error(L, "%s: '%s' has more than %d columns", fn, path, MAX_COLUMNS);
                lua_pushlstring(L, f, n);
                lua_rawseti(L, names, ncols);
                lua_pushlstring(L, f, n);
                lua_newtable(L);
                lua_rawset(L, res);
            }
            continue;
        }
        rows++;
        const char *s = q;
        for (int c = 1; c <= ncols; c++) {
            if (!s)
                return luaL_error(L, "%s: '%s' line %d has %d values, the header names %d", fn,
                                  path, line, c - 1, ncols);
            const char *f;
            size_t n;
            s = field(s, eol, &f, &n);
            lua_pushlstring(L, f, n);
            const char *field_text = lua_tostring(L, -1);
            int isnum = lua_stringtonumber(L, field_text) != 0;
            /* 1e999 reads as inf: refused as NaN is (issue 31 item 8); the
             * value shown is the field (it was "(null)": the message read
             * a stack slot that depended on argument order) */
            if (!isnum || n == 0 || !isfinite(lua_tonumber(L, -1))) {
                lua_rawgeti(L, names, c);
                return luaL_error(L, "%s: '%s' line %d, column '%s': '%s' is not a finite "
                                  "number", fn, path, line, lua_tostring(L, -1), field_text);
            }
            lua_remove(L, -2);            /* the string; the number stays */
            lua_rawgeti(L, names, c);
            lua_rawget(L, res);           /* the column's table */
            lua_insert(L, -2);
            lua_rawseti(L, -2, rows);
            lua_pop(L, 1);
        }
        if (s)
            return luaL_error(L, "%s: '%s' line %d has more values than the header's %d names",
                              fn, path, line, ncols);
    }
    if (ncols == 0) return luaL_error(L, "%s: '%s' has no header line", fn, path);
    lua_pushvalue(L, res);
    lua_pushvalue(L, names);
    lua_pushinteger(L, rows);
    return 3;
}
