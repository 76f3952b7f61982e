/* l_plot.c - lamina.plot{...}: time-series plots to PNG (and CSV).
 *
 * The binding reads and checks the script's tables and hands plain arrays
 * to src/render's lr_plot_write; the drawing is there. Every level of the
 * table (the plot, each series) rejects unknown keys by name, because a
 * misspelt `dashed` or `label` would otherwise be silently ignored and the
 * figure quietly wrong. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "l_internal.h"
#include "plot.h"

static const char *const plot_keys[] = {"file", "width", "height", "title", "xlabel",
                                        "ylabel", "xrange", "yrange", "legend", "csv",
                                        "series", NULL};
static const char *const series_keys[] = {"x", "y", "label", "dashed", "color", "width",
                                          "markers", NULL};
/* in the order of lr_legend */
static const char *const legend_names[] = {"top right", "top left", "top",
                                           "bottom right", "bottom left", "bottom",
                                           "left", "right", "center", "best", NULL};


/* A number for a message, as a person writes it (10.5, 1, 1e-07): Lua's
 * own %f would print 1.0. */
static const char *num(char buf[32], double v)
{
    snprintf(buf, 32, "%.10g", v);
    return buf;
}

/* An optional boolean field; nil is false. */
static int opt_flag(lua_State *L, int idx, const char *fn, const char *key)
{
    int t = la_getfield(L, idx, key);
    if (t != LUA_TNIL && t != LUA_TBOOLEAN)
        luaL_error(L, "%s: '%s' must be true or false (got %s)", fn, key,
                   luaL_typename(L, -1));
    int v = lua_toboolean(L, -1);
    lua_pop(L, 1);
    return v;
}

/* An optional {a, b} range with a < b, both finite. */
static int opt_range(lua_State *L, int idx, const char *fn, const char *key, double *a,
                     double *b)
{
    if (!la_has(L, idx, key))
        return 0;
    la_pair(L, idx, fn, key, a, b);
    char sa[32], sb[32];
    if (!(isfinite(*a) && isfinite(*b) && *a < *b))
        luaL_error(L, "%s: '%s' = {%s, %s} must be finite with the first below the "
                   "second", fn, key, num(sa, *a), num(sb, *b));
    return 1;
}

static lr_legend legend_option(lua_State *L, int idx, const char *fn)
{
    int t = la_getfield(L, idx, "legend");
    lr_legend pos = LR_LEGEND_TOP_RIGHT;
    if (t == LUA_TBOOLEAN)
        pos = lua_toboolean(L, -1) ? LR_LEGEND_TOP_RIGHT : LR_LEGEND_NONE;
    else if (t == LUA_TSTRING)
        pos = (lr_legend)la_option(L, fn, "legend", lua_tostring(L, -1), legend_names);
    else if (t != LUA_TNIL)
        luaL_error(L, "%s: 'legend' must be a position such as \"top left\", or false "
                   "(got %s)", fn, luaL_typename(L, -1));
    lua_pop(L, 1);
    return pos;
}

/* The CSV path: a string, or true for the image's path with .csv in place
 * of .png (appended when the name does not end in .png). Pushed when made
 * here, so it lives until the binding returns. */
static const char *csv_option(lua_State *L, int idx, const char *fn, const char *file)
{
    int t = la_getfield(L, idx, "csv");
    const char *csv = NULL;
    if (t == LUA_TSTRING) {
        csv = lua_tostring(L, -1);
        if (!*csv) luaL_error(L, "%s: 'csv' must not be empty", fn);
        la_check_output_path(L, fn, -1);
    } else if (t == LUA_TBOOLEAN) {
        if (lua_toboolean(L, -1)) {
            size_t n = strlen(file);
            const char *ext = n >= 4 ? file + n - 4 : "";
            int png = ext[0] == '.' && (ext[1] | 0x20) == 'p' && (ext[2] | 0x20) == 'n' &&
                      (ext[3] | 0x20) == 'g';
            lua_pushlstring(L, file, png ? n - 4 : n);
            lua_pushliteral(L, ".csv");
            lua_concat(L, 2);
            csv = la_check_output_path(L, fn, -1);
            lua_insert(L, -2);  /* keep the path, drop the field below it */
        }
    } else if (t != LUA_TNIL) {
        luaL_error(L, "%s: 'csv' must be a path or true (got %s)", fn,
                   luaL_typename(L, -1));
    }
    lua_pop(L, 1);   /* a string field stays alive in the argument table */
    return csv;
}

/* Reads array `key` of the series at sidx into out[0..n). */
static void read_values(lua_State *L, int sidx, const char *sfn, const char *key,
                        double *out, size_t n)
{
    la_getfield(L, sidx, key);
    for (size_t i = 0; i < n; i++) {
        lua_rawgeti(L, -1, (lua_Integer)i + 1);
        int isnum;
        out[i] = lua_tonumberx(L, -1, &isnum);
        if (!isnum)
            luaL_error(L, "%s: %s[%d] must be a number (got %s)", sfn, key, (int)i + 1,
                       luaL_typename(L, -1));
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
}

/* The length of array `key` of the series at sidx (an error if missing). */
static size_t values_length(lua_State *L, int sidx, const char *sfn, const char *key)
{
    int t = la_getfield(L, sidx, key);
    if (t == LUA_TNIL)
        luaL_error(L, "%s: '%s' is required (an array of numbers)", sfn, key);
    if (t != LUA_TTABLE)
        luaL_error(L, "%s: '%s' must be an array of numbers (got %s)", sfn, key,
                   luaL_typename(L, -1));
    size_t n = (size_t)lua_rawlen(L, -1);
    lua_pop(L, 1);
    return n;
}

/* Fills s from the series table at sidx (the k-th, 1-based). The data go
 * into a userdata anchored in the table at aidx, so that an error raised
 * later frees them with the garbage collector. */
static void read_series(lua_State *L, int sidx, int k, int aidx, lr_plot_series *s)
{
    int t = la_getfield(L, sidx, "label");
    if (t != LUA_TNIL && t != LUA_TSTRING)
        luaL_error(L, "lamina.plot: series %d: 'label' must be a string (got %s)", k,
                   luaL_typename(L, -1));
    s->label = lua_tostring(L, -1);   /* alive: referenced by the series table */
    if (s->label) {   /* a CSV header field too, quoted (plot_csv.c): nothing may expand */
        la_check_text(L, "lamina.plot", "series label", s->label);
        const char *bad = strpbrk(s->label, "\"$`\\");
        if (bad)
            luaL_error(L, "lamina.plot: series %d: label '%s' may not hold '%c' (it heads a "
                       "CSV column, where a shell would expand it)", k, s->label, *bad);
    }
    lua_pop(L, 1);
    const char *sfn = s->label ? lua_pushfstring(L, "lamina.plot: series %d ('%s')", k,
                                                 s->label)
                               : lua_pushfstring(L, "lamina.plot: series %d", k);
    la_check_keys(L, sidx, sfn, series_keys);
    size_t nx = values_length(L, sidx, sfn, "x"), ny = values_length(L, sidx, sfn, "y");
    if (nx != ny)
        luaL_error(L, "%s: x and y must have the same length (x has %d values, y has "
                   "%d)", sfn, (int)nx, (int)ny);
    if (nx == 0)
        luaL_error(L, "%s is empty (x and y have no values)", sfn);
    if (nx > ((size_t)-1) / (2 * sizeof(double)))
        luaL_error(L, "%s is too long", sfn);
    double *buf = lua_newuserdatauv(L, 2 * nx * sizeof(double), 0);
    lua_rawseti(L, aidx, k);
    read_values(L, sidx, sfn, "x", buf, nx);
    read_values(L, sidx, sfn, "y", buf + nx, nx);
    s->n = nx;
    s->x = buf;
    s->y = buf + nx;
    s->dashed = opt_flag(L, sidx, sfn, "dashed");
    s->markers = opt_flag(L, sidx, sfn, "markers");
    char sv[32];
    double c = la_opt_number(L, sidx, sfn, "color", k);
    if (!(c >= 1 && c <= 1e6) || c != floor(c))
        luaL_error(L, "%s: 'color' must be a whole number >= 1 (1 = blue, 2 = "
                   "vermilion, ... 8 = black; got %s)", sfn, num(sv, c));
    s->colour = (int)c - 1;
    s->width = la_opt_number(L, sidx, sfn, "width", 1.5);
    if (!(s->width > 0 && s->width <= 100))
        luaL_error(L, "%s: 'width' must be a line width in pixels in (0, 100] (got %s)",
                   sfn, num(sv, s->width));
    lua_pop(L, 1);   /* sfn */
}

int la_plot(lua_State *L)
{
    const char *fn = "lamina.plot";
    la_check_keys(L, 1, fn, plot_keys);
    lr_plot p;
    memset(&p, 0, sizeof p);
    const char *file = la_opt_output_path(L, 1, fn, "file");
    if (!file || !*file) return luaL_error(L, "%s: 'file' is required (a PNG path)", fn);
    double w = la_opt_number(L, 1, fn, "width", 800);
    double h = la_opt_number(L, 1, fn, "height", 500);
    char sw[32], sh[32];
    if (!(w >= 16 && w <= 16384) || !(h >= 16 && h <= 16384) || w != floor(w) ||
        h != floor(h))
        return luaL_error(L, "%s: width and height must be whole numbers in [16, 16384] "
                          "(got %s x %s)", fn, num(sw, w), num(sh, h));
    p.width = (int)w;
    p.height = (int)h;
    p.title = la_opt_string(L, 1, fn, "title", NULL);
    p.xlabel = la_opt_string(L, 1, fn, "xlabel", NULL);
    p.ylabel = la_opt_string(L, 1, fn, "ylabel", NULL);
    p.fixed_x = opt_range(L, 1, fn, "xrange", &p.x0, &p.x1);
    p.fixed_y = opt_range(L, 1, fn, "yrange", &p.y0, &p.y1);
    p.legend = legend_option(L, 1, fn);
    p.csv = csv_option(L, 1, fn, file);   /* may push the derived path */
    if (p.csv && strcmp(p.csv, file) == 0)
        return luaL_error(L, "%s: 'csv' = '%s' is the image's own path", fn, p.csv);

    if (la_getfield(L, 1, "series") != LUA_TTABLE)
        return luaL_error(L, "%s: 'series' is required: a list of series, "
                          "{ {x = {...}, y = {...}, label = \"...\"}, ... }", fn);
    int list = lua_gettop(L);
    lua_Integer n = (lua_Integer)lua_rawlen(L, list);
    /* a list, not a single series or a table with names */
    lua_pushnil(L);
    while (lua_next(L, list)) {
        lua_pop(L, 1);
        if (!lua_isinteger(L, -1) || lua_tointeger(L, -1) < 1 ||
            lua_tointeger(L, -1) > n)
            return luaL_error(L, "%s: 'series' must be a list of series tables, "
                              "{ {x = ..., y = ...}, ... } (found key '%s')", fn,
                              luaL_tolstring(L, -1, NULL));
    }
    if (n < 1)
        return luaL_error(L, "%s: 'series' is empty: give at least one series", fn);
    if ((size_t)n > ((size_t)-1) / sizeof(lr_plot_series))
        return luaL_error(L, "%s: too many series", fn);
    lr_plot_series *series = lua_newuserdatauv(L, (size_t)n * sizeof *series, 0);
    memset(series, 0, (size_t)n * sizeof *series);
    lua_createtable(L, (int)(n < 1000000 ? n : 1000000), 0);   /* anchors the data */
    int anchor = lua_gettop(L);
    for (lua_Integer k = 1; k <= n; k++) {
        if (lua_rawgeti(L, list, k) != LUA_TTABLE)
            return luaL_error(L, "%s: series %d must be a table {x = ..., y = ...} "
                              "(got %s)", fn, (int)k, luaL_typename(L, -1));
        read_series(L, lua_gettop(L), (int)k, anchor, &series[k - 1]);
        lua_pop(L, 1);
    }
    p.nseries = (size_t)n;
    p.series = series;

    la_prov prov;
    la_provenance(L, &prov);
    char err[1024];
    if (lr_plot_write(&p, file, prov.text, 4, err, sizeof err))
        return luaL_error(L, "%s: %s", fn, err);
    lua_pushstring(L, file);
    if (!p.csv) return 1;
    lua_pushstring(L, p.csv);
    return 2;
}
