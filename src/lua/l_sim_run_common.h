/* l_sim_run_common.h - what sim:run, sim:step, sim:every and sim:at do
 * alike for a 2D sim (l_sim.c) and a 3D one (l_sim3_run.c): reading their
 * arguments against the sim's clock (a --restart's checkpoint restored
 * first) and running the steps protected under the run guard. The steps
 * themselves - each dimension's engine, callbacks and checks - stay in
 * those files. */
#ifndef LAMINA_L_SIM_RUN_COMMON_H
#define LAMINA_L_SIM_RUN_COMMON_H

#include "l_internal.h"

/* The most steps one sim:run or sim:step may take. */
#define LA_STEP_CAP 1e12

/* sim:every(interval, fn) and sim:at(t, fn) on the sim at 1, whose clock
 * reads now (docs/api.md). */
int la_sim_every_from(lua_State *L, double now);
int la_sim_at_time(lua_State *L);

/* sim:run{t_end}'s options at 2: t_end into *t_end and the steps to the
 * one nearest it at the current dt (0 when it is past), after a
 * --restart's checkpoint is restored; errors name "sim:run". */
long la_sim_run_steps(lua_State *L, la_sim *s, double *t_end);
/* sim:step([n])'s n (1 by default), less the steps a --restart's
 * checkpoint already took (the call's last step is the same). */
long la_sim_step_count(lua_State *L, la_sim *s);

/* What one run's steps are given: the run guard, set by
 * la_sim_run_protected; the steps to take; and (2D sim:run) the time to
 * end at, NAN to count steps instead (3D counts them always). */
typedef struct la_run_arg {
    la_run_guard *guard;
    long nsteps;
    double t_end;
} la_run_arg;

/* Runs steps(L) protected with the sim at 1 and arg as a light userdata
 * at 2, under the run guard (l_run_guard.c: every way out writes the
 * records; arg->guard points at it meanwhile); refused from inside a
 * callback. A 3D sim is the run's active3 meanwhile (the clock live
 * changes are logged at, l_runlog.c). */
void la_sim_run_protected(lua_State *L, la_sim *s, lua_CFunction steps, la_run_arg *arg);
/* In steps(L): its la_run_arg, the stack left with the sim alone at 1. */
la_run_arg *la_run_arg_take(lua_State *L);

#endif
