/* l_analysis_membrane.c - where a membrane is, read off its points in curve
 * order (the chords between neighbours, closing chord too when closed).
 *
 *   local x, y, s, n = lamina.analysis.crossing(string, {0.5, 0}, {0.5, 1})
 *   local plus, minus, on = lamina.analysis.gas_sides(gas, membrane)
 *
 * crossing: where the membrane crosses the segment from p0 to p1: the
 * crossing nearest p0, its distance s from p0 along the segment, and the
 * number of crossings n; nil and why when there is none. (A membrane's
 * height at x: the segment from (x, bottom) to (x, top).)
 *
 * gas_sides: how many points of a body lie on each side of a membrane's
 * chords: `plus` on its left as the curve runs from point 1 to point n
 * (the side of the tangent turned +90 degrees: above a membrane laid out
 * left to right; outside a closed anticlockwise one), `minus` on the
 * right, `on` exactly on it. A point's side is that of its nearest chord;
 * when the nearest spot is a point shared by two chords, the sum of their
 * normals decides (the pseudo-normal: right for convex and concave
 * corners alike); beyond an open membrane's ends the end chord's line
 * decides. For gas that leaked through an open membrane, or a check that
 * none did. */
#include <math.h>

#include "l_analysis.h"

/* The membrane's points (x, y) and chord count; a membrane body or error. */
static const lm_body *membrane_arg(lua_State *L, int idx, const char *fn, lm_sim **sim,
                                   size_t *nseg)
{
    int b = la_check_body(L, idx, sim);
    const lm_body *bd = &(*sim)->bodies[b];
    if (!bd->membrane)
        luaL_error(L, "%s: argument %d must be a membrane (body %d is not)", fn, idx, b + 1);
    if (bd->count < 2)
        luaL_error(L, "%s: the membrane has %d point%s: no chord", fn, (int)bd->count,
                   bd->count == 1 ? "" : "s");
    *nseg = bd->count - 1 + (bd->closed && bd->count > 2);
    return bd;
}

static void point_arg(lua_State *L, int idx, const char *fn, const char *what, double *x,
                      double *y)
{
    if (lua_type(L, idx) != LUA_TTABLE)
        luaL_error(L, "%s: %s must be a point {x, y}", fn, what);
    for (int k = 1; k <= 2; k++) {
        lua_rawgeti(L, idx, k);
        int ok = 0;
        double v = lua_tonumberx(L, -1, &ok);
        lua_pop(L, 1);
        if (!ok || !isfinite(v))
            luaL_error(L, "%s: %s[%d] is not a finite number", fn, what, k);
        *(k == 1 ? x : y) = v;
    }
}

int la_analysis_crossing(lua_State *L)
{
    const char *fn = "lamina.analysis.crossing";
    lm_sim *sim;
    size_t nseg;
    const lm_body *bd = membrane_arg(L, 1, fn, &sim, &nseg);
    double x0, y0, x1, y1;
    point_arg(L, 2, fn, "p0", &x0, &y0);
    point_arg(L, 3, fn, "p1", &x1, &y1);
    double dx = x1 - x0, dy = y1 - y0, len = hypot(dx, dy);
    if (!(len > 0)) return luaL_error(L, "%s: p0 and p1 are the same point", fn);
    const double *px = sim->p.x + bd->first, *py = sim->p.y + bd->first;
    double best = HUGE_VAL, bx = 0, by = 0;
    int count = 0;
    for (size_t k = 0; k < nseg; k++) {
        size_t j = k + 1 == bd->count ? 0 : k + 1;
        double ex = px[j] - px[k], ey = py[j] - py[k];
        double den = dx * ey - dy * ex;   /* cross(d, e) */
        if (den == 0) continue;           /* parallel: no single crossing */
        double wx = px[k] - x0, wy = py[k] - y0;
        double s = (wx * ey - wy * ex) / den;   /* along p0 -> p1, 0..1 */
        double u = (wx * dy - wy * dx) / den;   /* along the chord, 0..1 */
        /* a chord owns its start, not its end (the next chord's start), so
         * a line through a point counts once; an open membrane's last
         * chord owns its end too */
        int last = !bd->closed && k + 1 == nseg;
        if (s < 0 || s > 1 || u < 0 || (last ? u > 1 : u >= 1)) continue;
        count++;
        if (s < best) {
            best = s;
            bx = x0 + s * dx;
            by = y0 + s * dy;
        }
    }
    if (count == 0) {
        lua_pushnil(L);
        lua_pushfstring(L, "%s: the membrane does not cross the segment from (%f, %f) to "
                        "(%f, %f)", fn, x0, y0, x1, y1);
        return 2;
    }
    lua_pushnumber(L, bx);
    lua_pushnumber(L, by);
    lua_pushnumber(L, best * len);
    lua_pushinteger(L, count);
    return 4;
}

/* The side of (x, y): +1 left of the curve, -1 right, 0 on it. */
static int side_of(const double *px, const double *py, size_t npts, size_t nseg, double x,
                   double y)
{
    double best = HUGE_VAL, nx = 0, ny = 0, qx = 0, qy = 0;
    for (size_t k = 0; k < nseg; k++) {
        size_t j = k + 1 == npts ? 0 : k + 1;
        double ex = px[j] - px[k], ey = py[j] - py[k], l2 = ex * ex + ey * ey;
        if (!(l2 > 0)) continue;
        double u = ((x - px[k]) * ex + (y - py[k]) * ey) / l2;
        /* the ends exactly (not px[k] + 1 * ex), so that two chords
         * meeting at a point find the very same nearest spot */
        double cx = u <= 0 ? px[k] : u >= 1 ? px[j] : px[k] + u * ex;
        double cy = u <= 0 ? py[k] : u >= 1 ? py[j] : py[k] + u * ey;
        double d2 = (x - cx) * (x - cx) + (y - cy) * (y - cy);
        double l = sqrt(l2), sx = -ey / l, sy = ex / l;   /* left normal */
        if (d2 < best) {
            best = d2;
            nx = sx;
            ny = sy;
            qx = cx;
            qy = cy;
        } else if (d2 == best && cx == qx && cy == qy) {
            /* the same nearest spot, a point shared with the chord
             * before: the pseudo-normal */
            nx += sx;
            ny += sy;
        }
    }
    /* (a closed membrane's first point is met by chord 0 and by the
     * closing chord: the branch above adds both; an open membrane's end
     * points have one chord, whose line decides) */
    double d = (x - qx) * nx + (y - qy) * ny;
    return d > 0 ? 1 : d < 0 ? -1 : 0;
}

int la_analysis_gas_sides(lua_State *L)
{
    const char *fn = "lamina.analysis.gas_sides";
    lm_sim *sim, *sim2;
    int g = la_check_body(L, 1, &sim);
    size_t nseg;
    const lm_body *m = membrane_arg(L, 2, fn, &sim2, &nseg);
    if (sim2 != sim) return luaL_error(L, "%s: the body and the membrane are of different sims", fn);
    const lm_body *gb = &sim->bodies[g];
    if (gb == m) return luaL_error(L, "%s: the body is the membrane itself", fn);
    const double *px = sim->p.x + m->first, *py = sim->p.y + m->first;
    long plus = 0, minus = 0, on = 0;
    for (size_t q = gb->first; q < gb->first + gb->count; q++) {
        int s = side_of(px, py, m->count, nseg, sim->p.x[q], sim->p.y[q]);
        if (s > 0) plus++;
        else if (s < 0) minus++;
        else on++;
    }
    lua_pushinteger(L, plus);
    lua_pushinteger(L, minus);
    lua_pushinteger(L, on);
    return 3;
}
