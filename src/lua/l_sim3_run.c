/* l_sim3_run.c - sim:run, sim:step, sim:every, sim:at of a 3D run: the 2D
 * semantics (l_sim.c) over lm3_step. Callbacks run between steps with half
 * a step of tolerance; every way out of a run goes through the run guard
 * (l_run_guard.c: the records written, a failure recorded with its code);
 * the Courant check refuses dt before the first step; a step the engine
 * fails stops the run naming the time, the step, the particle and the
 * likely cause. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "l_sim3.h"

#define STEP_CAP 1e12   /* as sim:run in 2D */

int la_sim3_every(lua_State *L)
{
    la_sim3 *s3 = la_check_sim3(L, 1, "sim:every");
    double dt = luaL_checknumber(L, 2);
    la_check_interval(L, "sim:every", "interval", dt, s3->sim->t);
    la_sim_add_event(L, 1, s3->sim->t, dt, 3);
    return 0;
}

int la_sim3_at(lua_State *L)
{
    la_check_sim3(L, 1, "sim:at");
    double t = luaL_checknumber(L, 2);
    if (!isfinite(t)) return luaL_error(L, "sim:at: the time must be a finite number (got %f)", t);
    la_sim_add_event(L, 1, t, 0, 3);
    return 0;
}

/* What the engine's failure most likely means, after its own message (which
 * names the time, the step and the particle). */
static void raise_failure(lua_State *L, lm3_sim *sim, lm_status st)
{
    double c, cn = lm3_courant(sim, &c);
    char cause[512];
    if (st == LM_ERR_DOMAIN)
        snprintf(cause, sizeof cause, "likely cause: the body reached the domain's edge (a "
                 "free face, or a domain too small for the motion): enlarge the domain or make "
                 "that face fixed or symmetry");
    else
        snprintf(cause, sizeof cause, "likely cause: the step is unstable (dt c / h = %.3g "
                 "against the limit %.3g; a large deformation or a fast impact needs a smaller "
                 "dt)", cn, lm3_courant_limit(sim));
    la_fail_raisef(L, LAMINA_FAIL_UNSTABLE, "simulation failed: %s; %s", sim->err, cause);
}

/* After each step (l_progress.c's tick in 3D, without the progress line):
 * the run's step count, Ctrl-C and `--steps`. */
static void tick(lua_State *L, const lm3_sim *sim, long n, long nsteps)
{
    lamina_run *run = la_run(L);
    if (!run) return;
    run->steps++;
    run->t_last = sim->t;
    if (lamina_interrupt_pending()) {
        run->stopped = LAMINA_STOP_SIGINT;
        lamina_interrupt_clear();
        la_fail_raisef(L, LAMINA_FAIL_SIGNAL, "interrupted at t = %f, step %I", sim->t,
                       (lua_Integer)sim->nstep);
    }
    if (run->max_steps > 0 && run->steps >= run->max_steps && n + 1 < nsteps) {
        run->stopped = LAMINA_STOP_STEPS;
        la_fail_raisef(L, LAMINA_FAIL_STOPPED, "stopped after %I steps (--steps) at t = %f, "
                       "step %I", (lua_Integer)run->steps, sim->t, (lua_Integer)sim->nstep);
    }
}

/* The Courant refusal (before the first step, and after callbacks that may
 * have changed a material or courant), as in 2D: a refusal, exit 2. */
static void check_courant3(lua_State *L, lm3_sim *sim, const char *when)
{
    double c, cn = lm3_courant(sim, &c), lim = lm3_courant_limit(sim);
    if (!(cn > lim)) return;
    char msg[400];   /* lua_pushfstring has no %g */
    snprintf(msg, sizeof msg, "dt = %g: the Courant number dt c / h = %g (c = %g, h = %g) is "
             "above the limit %g%s; take dt <= %g or raise courant", sim->def.dt, cn, c,
             sim->grid.h, lim, when, lim * sim->grid.h / c);
    la_fail_raisef(L, LAMINA_FAIL_REFUSED, "%s", msg);
}

typedef struct run_arg {
    la_run_guard *guard;
    long nsteps;
} run_arg;

static int run_steps(lua_State *L)
{
    run_arg *a = lua_touserdata(L, 2);
    lua_settop(L, 1);
    la_sim *s = a->guard->s;
    lm3_sim *sim = s->s3->sim;
    /* the Courant refusal before any step (and any callback), as in 2D */
    check_courant3(L, sim, "");
    if (la_sim_fire_due(L, s)) check_courant3(L, sim, " after a live change");
    la_checkpoint_due(L, 1, s);   /* after the callbacks, as in 2D */
    la_option_warn3(sim);
    for (long n = 0; n < a->nsteps; n++) {
        la_pins3_update(L, 1, s);   /* driven pins, then the held points' velocities */
        lm_status st = lm3_step(sim);
        if (st == LM_ERR_INPUT) la_fail_raisef(L, LAMINA_FAIL_REFUSED, "%s", sim->err);
        if (st != LM_OK) raise_failure(L, sim, st);
        if (la_sim_fire_due(L, s)) check_courant3(L, sim, " after a live change");
        la_checkpoint_due(L, 1, s);
        tick(L, sim, n, a->nsteps);
    }
    return 0;
}

static void advance(lua_State *L, la_sim *s, long nsteps)
{
    if (s->running) luaL_error(L, "sim:run/sim:step called from inside a callback");
    la_run_guard g;
    la_run_guard_begin(L, &g, 1, s);
    /* the clock live changes are logged at (l_runlog.c) */
    lamina_run *run = la_run(L);
    const lm3_sim *outer3 = run ? run->active3 : NULL;
    if (run) run->active3 = s->s3->sim;
    run_arg a = {&g, nsteps};
    lua_pushcfunction(L, run_steps);
    lua_pushvalue(L, 1);
    lua_pushlightuserdata(L, &a);
    int failed = lua_pcall(L, 2, 0, 0) != LUA_OK;
    if (run) run->active3 = outer3;
    la_run_guard_end(L, &g, failed);
}

int la_sim3_run(lua_State *L)
{
    static const char *const keys[] = {"t_end", NULL};
    la_sim3 *s3 = la_check_sim3(L, 1, "sim:run");
    la_sim *s = la_check_sim_any(L, 1);
    la_check_keys(L, 2, "sim:run", keys);
    double t_end = la_number(L, 2, "sim:run", "t_end");
    if (!isfinite(t_end))
        return luaL_error(L, "sim:run: t_end must be a finite number (got %f)", t_end);
    if (!s->running) la_checkpoint_restore(L, 1, s);   /* --restart: before counting steps */
    /* the clock is nstep x dt (sim3_step.c): the steps to the one nearest
     * t_end, as in 2D */
    double n = floor((t_end - s3->sim->t) / s3->sim->def.dt + 0.5);
    if (n > STEP_CAP) return luaL_error(L, "sim:run: t_end = %f needs %f steps", t_end, n);
    advance(L, s, n > 0 ? (long)n : 0);
    return 0;
}

int la_sim3_step(lua_State *L)
{
    la_check_sim3(L, 1, "sim:step");
    la_sim *s = la_check_sim_any(L, 1);
    double nd = lua_isnoneornil(L, 2) ? 1 : luaL_checknumber(L, 2);
    if (!(nd >= 0 && nd <= STEP_CAP) || nd != floor(nd))
        return luaL_error(L, "sim:step: n must be a whole number from 0 to 1e12 (got %f)", nd);
    long n = (long)nd;
    if (!s->running) {
        /* --restart: the call's last step is the same; the steps the
         * checkpoint already took are not taken again (as in 2D) */
        long before = s->s3->sim->nstep;
        la_checkpoint_restore(L, 1, s);
        n -= s->s3->sim->nstep - before;
        if (n < 0) n = 0;
    }
    advance(L, s, n);
    return 0;
}
