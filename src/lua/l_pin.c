/* l_pin.c - body:pin{...}: hold points of a body or membrane fixed, or
 * drive them at a prescribed velocity (pin.c), and read the reaction.
 *
 *   local ends = sheet:pin{ points = "ends" }             -- held at rest
 *   local lid  = block:pin{ points = function(x, y) return y > 0.9 end,
 *                           velocity = function(t) return 0.1 * t, 0 end }
 *   print(ends:reaction())                                -- fx, fy
 *
 * A velocity function is called once per step with the middle of the step,
 * t + dt/2 (the midpoint rule for the displacement), between steps. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "l_internal.h"
#include "l_pin_common.h"

#define LA_PIN "lamina.pin"

/* A 2D body's points for la_pin_points_read: the body's range is copied
 * (the script's function may add a body: sim->bodies and the particle
 * arrays move, issue 31), the arrays read afresh for every call, and a
 * changed range refused after. */
typedef struct points2 {
    const lm_sim *sim;
    int b;
    size_t first, count;
} points2;

static int push_point2(lua_State *L, void *ctx, size_t q)
{
    const points2 *c = ctx;
    lua_pushnumber(L, c->sim->p.x[c->first + q]);
    lua_pushnumber(L, c->sim->p.y[c->first + q]);
    return 2;
}

static int moved2(void *ctx)
{
    const points2 *c = ctx;
    return c->sim->bodies[c->b].first != c->first || c->sim->bodies[c->b].count != c->count;
}

/* The points as 0-based indices within the body: "all", "ends" (a
 * membrane's first and last point), a list of 1-based indices, or a
 * function(x, y) -> boolean (l_pin_common.c). */
static size_t *read_points(lua_State *L, const lm_sim *sim, int b, size_t *n)
{
    const lm_body *bd = &sim->bodies[b];
    points2 c = {sim, b, bd->first, bd->count};
    la_pin_points pp = {"body:pin", bd->count, 0, "\"all\", \"ends\"", "x, y",
                        !bd->membrane || bd->closed ? "needs an open membrane" : NULL,
                        "the points function chose no point", push_point2, moved2, &c};
    return la_pin_points_read(L, 2, &pp, n);
}

/* velocity: {vx, vy} or a function(t) -> vx, vy; the two numbers. */
static void call_velocity(lua_State *L, int f, double t, double *vx, double *vy)
{
    double v[2];
    if (!la_pin_velocity_call(L, f, t, 2, v))
        luaL_error(L, "body:pin: the velocity function must return two finite numbers");
    *vx = v[0];
    *vy = v[1];
}

int la_body_pin(lua_State *L)
{
    static const char *const keys[] = {"points", "velocity", NULL};
    const char *fn = "body:pin";
    lm_sim *sim;
    int b = la_check_body(L, 1, &sim);
    la_check_keys(L, 2, fn, keys);
    lua_getiuservalue(L, 1, 1);
    int sidx = lua_gettop(L);
    la_sim *s = la_check_sim(L, sidx);
    if (s->running) return luaL_error(L, "%s: pins cannot be added during a run", fn);
    size_t n;
    size_t *idx = read_points(L, sim, b, &n);
    double vx = 0, vy = 0;
    int fidx = 0;
    int vt = la_getfield(L, 2, "velocity");
    if (vt == LUA_TFUNCTION) {
        fidx = lua_gettop(L);
        call_velocity(L, fidx, sim->t + 0.5 * sim->def.dt, &vx, &vy);
    } else {
        lua_pop(L, 1);
        if (vt != LUA_TNIL) la_pair(L, 2, fn, "velocity", &vx, &vy);
        if (!isfinite(vx) || !isfinite(vy))
            return luaL_error(L, "%s: velocity must be finite", fn);
    }
    int pin = lm_sim_add_pin(sim, b, idx, n, vx, vy);
    if (pin < 0) return luaL_error(L, "%s: %s", fn, sim->err);
    if (fidx) la_sim_add_pin_function(L, sidx, pin, fidx);
    la_handle_push(L, LA_PIN, sidx, pin, 1);
    return 1;
}

static void drive2(lua_State *L, la_sim *s, int pin, int fidx)
{
    double vx, vy;
    call_velocity(L, fidx, s->sim->t + 0.5 * s->sim->def.dt, &vx, &vy);
    lm_sim_set_pin_velocity(s->sim, pin, vx, vy);
}

/* Before each step: the driven pins' velocities at the middle of the step. */
void la_pins_update(lua_State *L, int sidx, la_sim *s)
{
    la_pins_drive(L, sidx, s, drive2);
}

/* pin:reaction() -> fx, fy: the force the pin exerted on the material in
 * the last step (per unit depth; 0, 0 before the first step). */
static int pin_reaction(lua_State *L)
{
    int pin = la_handle_check(L, 1, LA_PIN);
    lm_sim *sim = la_check_sim(L, -1)->sim;
    const lm_pin *pn = &sim->pins[pin];
    lua_pushnumber(L, pn->rx);
    lua_pushnumber(L, pn->ry);
    return 2;
}

static int pin_len(lua_State *L)
{
    int pin = la_handle_check(L, 1, LA_PIN);
    lm_sim *sim = la_check_sim(L, -1)->sim;
    lua_pushinteger(L, (lua_Integer)sim->pins[pin].n);
    return 1;
}

static int pin_tostring(lua_State *L)
{
    return la_push_handle_name(L, LA_PIN, la_handle_check(L, 1, LA_PIN));
}

void la_open_pin(lua_State *L)
{
    static const luaL_Reg meta[] = {{"__len", pin_len}, {"__tostring", pin_tostring},
                                    {NULL, NULL}};
    static const luaL_Reg methods[] = {{"reaction", pin_reaction}, {NULL, NULL}};
    la_new_class(L, LA_PIN, meta, methods);
    lua_pushliteral(L, "lamina.pin");
    lua_setfield(L, -2, "__metatable");
    lua_pop(L, 1);
}
