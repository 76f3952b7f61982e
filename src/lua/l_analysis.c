/* l_analysis.c - the lamina.analysis table and its circle fit.
 *
 *   local cx, cy, r, rms = lamina.analysis.circle_fit(xs, ys)
 *   local cx, cy, r, rms = lamina.analysis.circle_fit(membrane)
 *
 * The circle that minimises the sum of squared distances of the points
 * from it, sum_i (|p_i - c| - r)^2 (the geometric fit), and the rms of
 * those distances. Started from the algebraic fit (Kasa 1976: least
 * squares of x^2 + y^2 + D x + E y + F, a linear problem, exact for points
 * on a circle but biased towards small radii for an arc with noise), then
 * Gauss-Newton on the geometric residuals, which removes that bias. */
#include <math.h>
#include <string.h>

#include "l_analysis.h"

double *la_analysis_scratch(lua_State *L, size_t n)
{
    return lua_newuserdatauv(L, (n ? n : 1) * sizeof(double), 0);
}

double *la_analysis_array(lua_State *L, int idx, const char *fn, const char *what,
                          size_t *n)
{
    idx = lua_absindex(L, idx);
    if (lua_type(L, idx) != LUA_TTABLE)
        luaL_error(L, "%s: %s must be an array of numbers (got %s)", fn, what,
                   luaL_typename(L, idx));
    size_t len = (size_t)lua_rawlen(L, idx);
    double *a = la_analysis_scratch(L, len);
    for (size_t i = 0; i < len; i++) {
        lua_rawgeti(L, idx, (lua_Integer)i + 1);
        int ok = 0;
        double v = lua_tonumberx(L, -1, &ok);
        lua_pop(L, 1);
        if (!ok || !isfinite(v))
            luaL_error(L, "%s: %s[%d] is not a finite number", fn, what, (int)i + 1);
        a[i] = v;
    }
    *n = len;
    return a;
}

/* Solves the 3x3 system m x = b (Gaussian elimination with partial
 * pivoting); 0, or -1 when it is singular to working precision. */
static int solve3(double m[3][3], double b[3], double x[3])
{
    double scale = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            scale = fmax(scale, fabs(m[i][j]));
    for (int c = 0; c < 3; c++) {
        int p = c;
        for (int r = c + 1; r < 3; r++)
            if (fabs(m[r][c]) > fabs(m[p][c])) p = r;
        if (!(fabs(m[p][c]) > 1e-13 * scale)) return -1;
        for (int j = 0; j < 3; j++) {
            double t = m[c][j];
            m[c][j] = m[p][j];
            m[p][j] = t;
        }
        double t = b[c];
        b[c] = b[p];
        b[p] = t;
        for (int r = c + 1; r < 3; r++) {
            double f = m[r][c] / m[c][c];
            for (int j = c; j < 3; j++) m[r][j] -= f * m[c][j];
            b[r] -= f * b[c];
        }
    }
    for (int r = 2; r >= 0; r--) {
        double s = b[r];
        for (int j = r + 1; j < 3; j++) s -= m[r][j] * x[j];
        x[r] = s / m[r][r];
    }
    return 0;
}

static double rms_of(const double *x, const double *y, size_t n, double cx, double cy,
                     double r)
{
    double s = 0;
    for (size_t i = 0; i < n; i++) {
        double d = hypot(x[i] - cx, y[i] - cy) - r;
        s += d * d;
    }
    return sqrt(s / (double)n);
}

static int circle_fit(lua_State *L)
{
    const char *fn = "lamina.analysis.circle_fit";
    size_t n = 0, ny = 0;
    double *x, *y;
    if (lua_type(L, 1) == LUA_TUSERDATA) {   /* a body: its points */
        lm_sim *sim;
        int b = la_check_body(L, 1, &sim);
        const lm_body *bd = &sim->bodies[b];
        n = bd->count;
        x = la_analysis_scratch(L, n);
        y = la_analysis_scratch(L, n);
        memcpy(x, sim->p.x + bd->first, n * sizeof *x);
        memcpy(y, sim->p.y + bd->first, n * sizeof *y);
    } else {
        x = la_analysis_array(L, 1, fn, "xs", &n);
        y = la_analysis_array(L, 2, fn, "ys", &ny);
        if (ny != n)
            return luaL_error(L, "%s: xs has %d values, ys %d", fn, (int)n, (int)ny);
    }
    if (n < 3) return luaL_error(L, "%s: needs at least 3 points (got %d)", fn, (int)n);
    /* the algebraic fit about the centroid (for conditioning): with
     * u = x - mx, v = y - my, least squares of u^2 + v^2 + D u + E v + F */
    double mx = 0, my = 0;
    for (size_t i = 0; i < n; i++) {
        mx += x[i];
        my += y[i];
    }
    mx /= (double)n;
    my /= (double)n;
    double m[3][3] = {{0}}, b[3] = {0}, s[3];
    for (size_t i = 0; i < n; i++) {
        double u = x[i] - mx, v = y[i] - my, w = -(u * u + v * v);
        double row[3] = {u, v, 1};
        for (int a = 0; a < 3; a++) {
            for (int c = 0; c < 3; c++) m[a][c] += row[a] * row[c];
            b[a] += row[a] * w;
        }
    }
    if (solve3(m, b, s) != 0)
        return luaL_error(L, "%s: the points are on a line (or coincide): no circle", fn);
    double cx = -s[0] / 2, cy = -s[1] / 2, r2 = cx * cx + cy * cy - s[2];
    if (!(r2 > 0))
        return luaL_error(L, "%s: the points are on a line (or coincide): no circle", fn);
    double r = sqrt(r2);
    /* Gauss-Newton on d_i = |p_i - c| - r: the Jacobian row of d_i is
     * (-(u_i - cx)/rho_i, -(v_i - cy)/rho_i, -1); the step solves the
     * normal equations. Stops when the step is at rounding level. */
    double best = rms_of(x, y, n, cx + mx, cy + my, r);
    for (int it = 0; it < 100; it++) {
        double a[3][3] = {{0}}, g[3] = {0}, d[3];
        for (size_t i = 0; i < n; i++) {
            double u = x[i] - mx - cx, v = y[i] - my - cy, rho = hypot(u, v);
            if (!(rho > 0)) continue;
            double row[3] = {-u / rho, -v / rho, -1}, res = rho - r;
            for (int p = 0; p < 3; p++) {
                for (int q = 0; q < 3; q++) a[p][q] += row[p] * row[q];
                g[p] -= row[p] * res;
            }
        }
        if (solve3(a, g, d) != 0) break;
        double ncx = cx + d[0], ncy = cy + d[1], nr = r + d[2];
        double e = rms_of(x, y, n, ncx + mx, ncy + my, nr);
        if (!(e <= best)) break;   /* no better: the last is the minimum */
        cx = ncx;
        cy = ncy;
        r = nr;
        best = e;
        if (fabs(d[0]) + fabs(d[1]) + fabs(d[2]) <= 1e-15 * (r + hypot(cx, cy))) break;
    }
    lua_pushnumber(L, cx + mx);
    lua_pushnumber(L, cy + my);
    lua_pushnumber(L, fabs(r));
    lua_pushnumber(L, best);
    return 4;
}

void la_open_analysis(lua_State *L)
{
    static const luaL_Reg funcs[] = {{"period", la_analysis_period},
                                     {"frequency", la_analysis_frequency},
                                     {"circle_fit", circle_fit},
                                     {"crossing", la_analysis_crossing},
                                     {"gas_sides", la_analysis_gas_sides},
                                     {NULL, NULL}};
    luaL_newlib(L, funcs);
    lua_setfield(L, -2, "analysis");
}
