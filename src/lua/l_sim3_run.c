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
#include "l_sim_run_common.h"

/* sim:every, sim:at, and the arguments of sim:run and sim:step are read
 * as in 2D (l_sim_run_common.c) */
int la_sim3_every(lua_State *L)
{
    return la_sim_every_from(L, la_check_sim3(L, 1, "sim:every")->sim->t);
}

int la_sim3_at(lua_State *L)
{
    la_check_sim3(L, 1, "sim:at");
    return la_sim_at_time(L);
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

static int run_steps(lua_State *L)
{
    la_run_arg *a = la_run_arg_take(L);
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
    la_run_arg a = {NULL, nsteps, NAN};
    /* the guard, and the clock live changes are logged at (l_runlog.c) */
    la_sim_run_protected(L, s, run_steps, &a);
}

int la_sim3_run(lua_State *L)
{
    la_check_sim3(L, 1, "sim:run");
    la_sim *s = la_check_sim_any(L, 1);
    double t_end;   /* the clock is nstep x dt (sim3_step.c) */
    advance(L, s, la_sim_run_steps(L, s, &t_end));
    return 0;
}

int la_sim3_step(lua_State *L)
{
    la_check_sim3(L, 1, "sim:step");
    la_sim *s = la_check_sim_any(L, 1);
    advance(L, s, la_sim_step_count(L, s));
    return 0;
}
