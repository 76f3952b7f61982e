/* l_pin3.c - body:pin{...} of a 3D body and the pin handle (the 2D names,
 * l_pin.c, with three components; the engine's form is sim3_pin.c):
 *
 *   local clamp = bar:pin{ points = function(x, y, z) return x < 0.1 end }
 *   local lid   = block:pin{ points = "all", velocity = function(t) return 0, 0, -0.1 * t end }
 *   print(clamp:reaction())                                   -- fx, fy, fz
 *
 * A velocity function is called once per step with the middle of the step,
 * t + dt/2, between steps (la_pins3_update). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "l_pin_common.h"
#include "l_sim3.h"

#define LA_PIN3 "lamina.pin3"

/* The velocity function at fidx called at t: three finite numbers. */
static void call_velocity3(lua_State *L, int fidx, double t, double v[3])
{
    if (!la_pin_velocity_call(L, fidx, t, 3, v))
        luaL_error(L, "body:pin: the velocity function must return three finite numbers "
                   "vx, vy, vz (at t = %f)", t);
}

static void drive3(lua_State *L, la_sim *s, int pin, int fidx)
{
    lm3_sim *sim = s->s3->sim;
    double v[3];
    call_velocity3(L, fidx, sim->t + 0.5 * sim->def.dt, v);
    lm3_pin_set_velocity(sim, pin, v);   /* its own pin: exists */
}

void la_pins3_update(lua_State *L, int sidx, la_sim *s)
{
    la_pins_drive(L, sidx, s, drive3);
    lm3_pins_begin(s->s3->sim);
}

/* A 3D body's points for la_pin_points_read (l_pin_common.c): the range
 * [first, first + n) of the engine's arrays, read afresh for every call. */
typedef struct points3 {
    const lm3_sim *sim;
    size_t first;
} points3;

static int push_point3(lua_State *L, void *ctx, size_t q)
{
    const points3 *c = ctx;
    for (int a = 0; a < 3; a++) lua_pushnumber(L, c->sim->p.x[a][c->first + q]);
    return 3;
}

/* body:pin{points, velocity} on the 3D body at 1 (first, n: its range). */
int la_body3_pin(lua_State *L, la_sim3 *s3, size_t first, size_t n)
{
    static const char *const keys[] = {"points", "velocity", NULL};
    const char *fn = "body:pin";
    la_check_keys(L, 2, fn, keys);
    lua_getiuservalue(L, 1, 1);
    int sidx = lua_gettop(L);
    la_sim *s = la_check_sim_any(L, sidx);
    if (s->running) return luaL_error(L, "%s: pins are added before a run", fn);
    lm3_sim *sim = s3->sim;
    points3 c = {sim, first};
    la_pin_points pp = {fn, n, first, "\"all\"", "x, y, z",
                        "is a membrane's; a 3D solid takes \"all\", a list of indices or a "
                        "function(x, y, z)",
                        "the function holds no point of the body", push_point3, NULL, &c};
    size_t k;
    size_t *idx = la_pin_points_read(L, 2, &pp, &k);
    double v[3] = {0, 0, 0};
    int vf = 0;
    if (la_getfield(L, 2, "velocity") == LUA_TFUNCTION) {
        vf = lua_gettop(L);
        call_velocity3(L, vf, sim->t + 0.5 * sim->def.dt, v);   /* checked now */
    } else {
        lua_pop(L, 1);
        la_triple(L, 2, fn, "velocity", v);
    }
    int pi = lm3_pin_add(sim, idx, k, v);
    if (pi < 0) return luaL_error(L, "%s: %s", fn, sim->err);
    if (vf) la_sim_add_pin_function(L, sidx, pi, vf);
    la_handle_push(L, LA_PIN3, sidx, pi, 1);
    return 1;
}

static const lm3_pin *check_pin3(lua_State *L)
{
    int pin = la_handle_check(L, 1, LA_PIN3);
    la_sim3 *s3 = la_check_sim3(L, -1, "pin");
    lua_pop(L, 1);
    return &s3->sim->pins->pin[pin];
}

/* pin:reaction() -> fx, fy, fz: the force the pin exerted on the material
 * in the last step (0 before the first). */
static int pin3_reaction(lua_State *L)
{
    const lm3_pin *p = check_pin3(L);
    for (int a = 0; a < 3; a++) lua_pushnumber(L, p->reaction[a]);
    return 3;
}

static int pin3_len(lua_State *L)
{
    lua_pushinteger(L, (lua_Integer)check_pin3(L)->n);
    return 1;
}

static int pin3_tostring(lua_State *L)
{
    return la_push_handle_name(L, "lamina.pin", la_handle_check(L, 1, LA_PIN3) + 1);
}

void la_open_pin3(lua_State *L)
{
    static const luaL_Reg meta[] = {{"__len", pin3_len}, {"__tostring", pin3_tostring},
                                    {NULL, NULL}};
    static const luaL_Reg methods[] = {{"reaction", pin3_reaction}, {NULL, NULL}};
    la_new_class(L, LA_PIN3, meta, methods);
    lua_pop(L, 1);
}
