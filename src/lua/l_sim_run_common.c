/* l_sim_run_common.c - the run calls' common layer for 2D and 3D sims
 * (l_sim_run_common.h). */
#include <math.h>

#include "l_sim3.h"
#include "l_sim_run_common.h"

/* The sim's clock: its time, step and dt, whichever its dimension. */
static double clock_time(const la_sim *s) { return s->s3 ? s->s3->sim->t : s->sim->t; }
static double clock_dt(const la_sim *s)
{
    return s->s3 ? s->s3->sim->def.dt : s->sim->def.dt;
}
static long clock_step(const la_sim *s) { return s->s3 ? s->s3->sim->nstep : s->sim->step; }

int la_sim_every_from(lua_State *L, double now)
{
    double dt = luaL_checknumber(L, 2);
    la_check_interval(L, "sim:every", "interval", dt, now);
    la_sim_add_event(L, 1, now, dt, 3);
    return 0;
}

int la_sim_at_time(lua_State *L)
{
    double t = luaL_checknumber(L, 2);
    if (!isfinite(t))   /* NaN compares false: it never fired (issue 31) */
        return luaL_error(L, "sim:at: the time must be a finite number (got %f)", t);
    la_sim_add_event(L, 1, t, 0, 3);
    return 0;
}

long la_sim_run_steps(lua_State *L, la_sim *s, double *t_end)
{
    static const char *const keys[] = {"t_end", NULL};
    la_check_keys(L, 2, "sim:run", keys);
    *t_end = la_number(L, 2, "sim:run", "t_end");
    if (!isfinite(*t_end))   /* NaN compared false everywhere: 0 steps, exit 0 */
        return luaL_error(L, "sim:run: t_end must be a finite number (got %f)", *t_end);
    if (!s->running) la_checkpoint_restore(L, 1, s);   /* --restart: before counting steps */
    /* the clock is step x dt: the steps to the one nearest t_end */
    double n = floor((*t_end - clock_time(s)) / clock_dt(s) + 0.5);
    if (n > LA_STEP_CAP)
        return luaL_error(L, "sim:run: t_end = %f needs %f steps", *t_end, n);
    return n > 0 ? (long)n : 0;
}

long la_sim_step_count(lua_State *L, la_sim *s)
{
    /* read as a number: luaL_optinteger said "bad argument #1 to 'step'
     * (number has no integer representation)" of NaN (issue 31 item 7) */
    double nd = lua_isnoneornil(L, 2) ? 1 : luaL_checknumber(L, 2);
    if (!(nd >= 0 && nd <= LA_STEP_CAP) || nd != floor(nd))
        return luaL_error(L, "sim:step: n must be a whole number from 0 to 1e12 (got %f)", nd);
    long n = (long)nd;
    if (!s->running) {
        /* --restart: the call's last step is the same; the steps the
         * checkpoint already took are not taken again */
        long before = clock_step(s);
        la_checkpoint_restore(L, 1, s);
        n -= clock_step(s) - before;
        if (n < 0) n = 0;
    }
    return n;
}

la_run_arg *la_run_arg_take(lua_State *L)
{
    la_run_arg *a = lua_touserdata(L, 2);
    lua_settop(L, 1);
    return a;
}

void la_sim_run_protected(lua_State *L, la_sim *s, lua_CFunction steps, la_run_arg *arg)
{
    /* not the guard's: the run in progress goes on (a pcall may catch this) */
    if (s->running) luaL_error(L, "sim:run/sim:step called from inside a callback");
    la_run_guard g;
    la_run_guard_begin(L, &g, 1, s);
    arg->guard = &g;
    lamina_run *run = s->s3 ? la_run(L) : NULL;
    const struct lm3_sim *outer3 = run ? run->active3 : NULL;
    if (run) run->active3 = s->s3->sim;
    lua_pushcfunction(L, steps);
    lua_pushvalue(L, 1);
    lua_pushlightuserdata(L, arg);
    int failed = lua_pcall(L, 2, 0, 0) != LUA_OK;
    if (run) run->active3 = outer3;
    la_run_guard_end(L, &g, failed);
}
