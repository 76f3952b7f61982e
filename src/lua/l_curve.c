/* l_curve.c - curves for membranes: lamina.segment, lamina.arc,
 * lamina.polyline and plain functions f(u) -> x, y, u in [0, 1].
 *
 * Membranes need points evenly spaced along the curve's length
 * (docs/design.md, "Lua API"), so every curve is turned into a dense polyline
 * here and points are placed on it by arc length. Segments, polylines and
 * arcs are exact (an arc's polyline is fine enough that the chord error is
 * below 1e-9 of its radius after placement on the true circle). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "l_curve.h"

#define LA_CURVE "lamina.curve"

static la_curve *push_curve(lua_State *L, la_curve_kind kind, int n)
{
    la_curve *c = lua_newuserdatauv(L, sizeof *c + 2 * (size_t)n * sizeof(double), 0);
    memset(c, 0, sizeof *c);
    c->kind = kind;
    c->n = n;
    c->xy = (double *)(c + 1);
    luaL_setmetatable(L, LA_CURVE);
    return c;
}

la_curve *la_test_curve(lua_State *L, int idx)
{
    return luaL_testudata(L, idx, LA_CURVE);
}

static int l_segment(lua_State *L)
{
    static const char *const keys[] = {"from", "to", NULL};
    const char *fn = "lamina.segment";
    la_check_keys(L, 1, fn, keys);
    double x0, y0, x1, y1;
    la_pair(L, 1, fn, "from", &x0, &y0);
    la_pair(L, 1, fn, "to", &x1, &y1);
    if (x0 == x1 && y0 == y1) luaL_error(L, "%s: 'from' and 'to' are the same point", fn);
    la_curve *c = push_curve(L, LA_CURVE_POLYLINE, 2);
    c->xy[0] = x0; c->xy[1] = y0; c->xy[2] = x1; c->xy[3] = y1;
    return 1;
}

/* Angles in degrees, counter-clockwise from +x; `to` may be below `from`
 * (clockwise). A full turn (|to - from| = 360) is a closed curve. */
static int l_arc(lua_State *L)
{
    static const char *const keys[] = {"center", "radius", "from", "to", NULL};
    const char *fn = "lamina.arc";
    la_check_keys(L, 1, fn, keys);
    la_curve *c = push_curve(L, LA_CURVE_ARC, 0);
    la_pair(L, 1, fn, "center", &c->cx, &c->cy);
    c->r = la_number(L, 1, fn, "radius");
    c->a0 = la_opt_number(L, 1, fn, "from", 0);
    c->a1 = la_opt_number(L, 1, fn, "to", 360);
    if (!(c->r > 0) || !isfinite(c->r))
        luaL_error(L, "%s: 'radius' must be a finite positive number (got %f)", fn, c->r);
    if (!isfinite(c->a0) || !isfinite(c->a1) || !isfinite(c->cx) || !isfinite(c->cy))
        luaL_error(L, "%s: 'center', 'from' and 'to' must be finite (got from = %f, to = %f)",
                   fn, c->a0, c->a1);   /* NaN passed the span check (issue 31 item 7) */
    if (c->a0 == c->a1 || fabs(c->a1 - c->a0) > 360)
        luaL_error(L, "%s: from = %f, to = %f must differ by at most 360 degrees",
                   fn, c->a0, c->a1);
    return 1;
}

static int l_polyline(lua_State *L)
{
    const char *fn = "lamina.polyline";
    int n;
    int list = la_point_list(L, fn, 2, &n);
    la_curve *c = push_curve(L, LA_CURVE_POLYLINE, n);
    for (int i = 0; i < n; i++) la_point_at(L, list, i, fn, &c->xy[2 * i], &c->xy[2 * i + 1]);
    return 1;
}

/* ---- sampling -------------------------------------------------------- */

#define FN_SAMPLES 4096

static void eval_function(lua_State *L, int fidx, double u, double *x, double *y)
{
    if (!la_call_pair(L, fidx, u, x, y))
        luaL_error(L, "curve function returned no point at u = %f (need two numbers)", u);
}

/* n points at equal arc length along a polyline of m vertices (xy). */
static void place_on_polyline(const double *xy, int m, int n, double *px, double *py)
{
    double *cum = malloc((size_t)m * sizeof *cum);
    if (!cum) return;
    cum[0] = 0;
    for (int i = 1; i < m; i++)
        cum[i] = cum[i - 1] + hypot(xy[2 * i] - xy[2 * i - 2], xy[2 * i + 1] - xy[2 * i - 1]);
    double total = cum[m - 1];
    int seg = 1;
    for (int k = 0; k < n; k++) {
        double s = n > 1 ? total * k / (n - 1) : 0;
        while (seg < m - 1 && cum[seg] < s) seg++;
        double l = cum[seg] - cum[seg - 1];
        double f = l > 0 ? (s - cum[seg - 1]) / l : 0;
        if (f > 1) f = 1;
        px[k] = xy[2 * seg - 2] + f * (xy[2 * seg] - xy[2 * seg - 2]);
        py[k] = xy[2 * seg - 1] + f * (xy[2 * seg + 1] - xy[2 * seg - 1]);
    }
    free(cum);
}

static double polyline_length(const double *xy, int m)
{
    double l = 0;
    for (int i = 1; i < m; i++)
        l += hypot(xy[2 * i] - xy[2 * i - 2], xy[2 * i + 1] - xy[2 * i - 1]);
    return l;
}

/* Samples a function curve into a dense polyline (userdata kept on the stack
 * by the caller's frame). */
static double *sample_function(lua_State *L, int fidx)
{
    double *xy = lua_newuserdatauv(L, 2 * (FN_SAMPLES + 1) * sizeof(double), 0);
    for (int i = 0; i <= FN_SAMPLES; i++)
        eval_function(L, fidx, (double)i / FN_SAMPLES, &xy[2 * i], &xy[2 * i + 1]);
    return xy;
}

int la_curve_sample(lua_State *L, int idx, la_curve_points *out)
{
    idx = lua_absindex(L, idx);
    memset(out, 0, sizeof *out);
    la_curve *c = la_test_curve(L, idx);
    if (c && c->kind == LA_CURVE_ARC) {
        double sweep = (c->a1 - c->a0) * acos(-1.0) / 180;
        out->length = c->r * fabs(sweep);
        out->closed = fabs(fabs(c->a1 - c->a0) - 360) < 1e-12;
        out->arc = c;
        return 0;
    }
    if (c) {
        out->xy = c->xy;
        out->m = c->n;
    } else if (lua_isfunction(L, idx)) {
        out->xy = sample_function(L, idx);
        out->m = FN_SAMPLES + 1;
    } else {
        return -1;
    }
    out->length = polyline_length(out->xy, out->m);
    double dx = out->xy[0] - out->xy[2 * out->m - 2], dy = out->xy[1] - out->xy[2 * out->m - 1];
    out->closed = hypot(dx, dy) <= 1e-9 * out->length;
    return 0;
}

/* n points at equal arc length; for a closed curve the last point is not
 * repeated (n points over the whole loop). */
void la_curve_place(const la_curve_points *cp, int n, double *px, double *py)
{
    if (cp->arc) {
        const la_curve *c = cp->arc;
        double d2r = acos(-1.0) / 180;
        int div = cp->closed ? n : n - 1;
        for (int k = 0; k < n; k++) {
            double deg = c->a0 + (c->a1 - c->a0) * (div > 0 ? (double)k / div : 0);
            double cs = cos(deg * d2r), sn = sin(deg * d2r);
            /* exact on the axes, so that points meant for a symmetry line
             * (quarter models) are on it, not 3e-17 off */
            double r90 = deg / 90;
            if (r90 == floor(r90)) {
                static const double C[4] = {1, 0, -1, 0}, S[4] = {0, 1, 0, -1};
                int k4 = (int)(((long)r90 % 4 + 4) % 4);
                cs = C[k4];
                sn = S[k4];
            }
            px[k] = c->cx + c->r * cs;
            py[k] = c->cy + c->r * sn;
        }
        return;
    }
    if (cp->closed) {
        /* place n+1 and drop the repeated end */
        double *tx = malloc((size_t)(n + 1) * 2 * sizeof(double));
        if (!tx) return;
        place_on_polyline(cp->xy, cp->m, n + 1, tx, tx + n + 1);
        memcpy(px, tx, (size_t)n * sizeof(double));
        memcpy(py, tx + n + 1, (size_t)n * sizeof(double));
        free(tx);
        return;
    }
    place_on_polyline(cp->xy, cp->m, n, px, py);
}

static int curve_tostring(lua_State *L)
{
    la_curve *c = luaL_checkudata(L, 1, LA_CURVE);
    if (c->kind == LA_CURVE_ARC)
        lua_pushfstring(L, "lamina.arc{center = {%f, %f}, radius = %f, from = %f, to = %f}",
                        c->cx, c->cy, c->r, c->a0, c->a1);
    else
        lua_pushfstring(L, "lamina.polyline (%d points)", c->n);
    return 1;
}

void la_open_curve(lua_State *L)
{
    la_new_metatable(L, LA_CURVE);
    lua_pushcfunction(L, curve_tostring);
    lua_setfield(L, -2, "__tostring");
    lua_pop(L, 1);
}

void la_register_curves(lua_State *L)
{
    static const luaL_Reg funcs[] = {{"segment", l_segment},
                                     {"arc", l_arc},
                                     {"polyline", l_polyline},
                                     {NULL, NULL}};
    luaL_setfuncs(L, funcs, 0);
}
