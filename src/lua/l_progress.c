/* l_progress.c - what happens at every step boundary of a run, besides the
 * events: counting steps, a progress line, stop requests.
 *
 * A run (one sim:run or sim:step call) that has lasted more than
 * PROGRESS_AFTER seconds shows on stderr its step, simulated time, steps per
 * second and the time left to its t_end: on a terminal one line rewritten
 * in place (\r) a few times a second, otherwise a plain line at each tenth
 * of the run, so that logs stay readable. `--quiet` (run->quiet) silences
 * it. Every progress line is a line of its own beginning "lamina: progress",
 * which keeps it out of the way of anything that matches other messages.
 *
 * LAMINA_PROGRESS_AFTER (seconds, in the environment) moves the threshold;
 * the tests set it to 0.
 *
 * The tick also decides whether the run must stop here: Ctrl-C
 * (l_interrupt.c), a step budget (watch --steps) or the run's poll function
 * (watch: the script changed). advance() then raises the error. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

#include "l_internal.h"

#define PROGRESS_AFTER 3.0   /* seconds before the first progress line (default) */
#define TTY_EVERY 0.25       /* seconds between updates in place */
#define POLL_EVERY 0.2       /* seconds between calls of run->poll */

static struct {
    int active;              /* a run is being tracked */
    int nested;              /* runs of other sims inside its callbacks */
    const lm_sim *sim;
    long step0, nsteps;      /* the run: sim->step at its start, its length */
    double t_end;
    double start, last_show, last_poll;
    double after;            /* PROGRESS_AFTER or LAMINA_PROGRESS_AFTER */
    int tty, shown, decile;
} P;

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void lamina_progress_clear_line(void)
{
    if (P.tty && P.shown) {
        fputs("\r\033[K", stderr);
        fflush(stderr);
    }
    P.shown = 0;
}

void lamina_progress_reset(void)
{
    lamina_progress_clear_line();
    P.active = 0;
    P.nested = 0;
}

void la_progress_begin(lua_State *L, int sidx, long nsteps)
{
    la_sim *s = la_check_sim(L, sidx);
    la_set_last_sim(L, sidx);
    lamina_run *run = la_run(L);
    if (run && run->max_steps > 0 && run->steps >= run->max_steps && nsteps > 0) {
        /* the step budget is spent: stop before stepping (advance()'s run
         * guard clears the running state) */
        run->stopped = LAMINA_STOP_STEPS;
        la_interrupt_raise(L, s->sim);
    }
    if (P.active && P.sim != s->sim) {
        P.nested++;   /* a callback runs another sim: the outer run keeps the line */
        return;
    }
    /* P.active with the same sim: left by a run that ended in an error */
    lamina_progress_clear_line();
    P.active = 1;
    P.nested = 0;
    P.sim = s->sim;
    P.step0 = s->sim->step;
    P.nsteps = nsteps;
    P.t_end = s->sim->t + (double)nsteps * s->sim->def.dt;
    P.start = P.last_poll = now_s();
    P.last_show = 0;
    P.tty = isatty(STDERR_FILENO);
    P.decile = 0;
    const char *env = getenv("LAMINA_PROGRESS_AFTER");
    char *end;
    P.after = env && *env ? strtod(env, &end) : PROGRESS_AFTER;
    if (!env || !*env || *end || !(P.after >= 0)) P.after = PROGRESS_AFTER;
}

void la_progress_end(lua_State *L)
{
    (void)L;
    if (P.nested > 0) {
        P.nested--;
        return;
    }
    lamina_progress_clear_line();
    P.active = 0;
}

/* "8.5 s", "42 s", "3 min 20 s", "2 h 05 min" */
static void format_eta(double s, char *buf, size_t len)
{
    if (s < 10) snprintf(buf, len, "%.1f s", s);
    else if (s < 60) snprintf(buf, len, "%.0f s", s);
    else if (s < 3600) snprintf(buf, len, "%d min %02d s", (int)(s / 60), (int)s % 60);
    else if (s < 1e9) snprintf(buf, len, "%d h %02d min", (int)(s / 3600), (int)(s / 60) % 60);
    else snprintf(buf, len, "%.3g h", s / 3600);
}

static void show(double now, long done)
{
    double elapsed = now - P.start;
    double rate = elapsed > 0 ? (double)done / elapsed : 0;
    double eta = rate > 0 ? (double)(P.nsteps - done) / rate : 0;
    char line[256], left[32];
    format_eta(eta, left, sizeof left);
    snprintf(line, sizeof line,
             "lamina: progress %d %%: step %ld of %ld, t = %.6g of %.6g, %.0f steps/s, "
             "ETA %s", (int)(100.0 * (double)done / (double)P.nsteps), P.step0 + done,
             P.step0 + P.nsteps, P.sim->t, P.t_end, rate, left);
    if (P.tty) {
        fprintf(stderr, "\r%s\033[K", line);
        P.shown = 1;
    } else {
        fprintf(stderr, "%s\n", line);
    }
    fflush(stderr);
    P.last_show = now;
}

int la_progress_tick(lua_State *L, const lm_sim *sim)
{
    lamina_run *run = la_run(L);
    if (!run) return 0;
    run->steps++;
    run->t_last = sim->t;
    if (lamina_interrupt_pending()) {
        run->stopped = LAMINA_STOP_SIGINT;
        return 1;
    }
    if (run->max_steps > 0 && run->steps >= run->max_steps) {
        /* the last step of this call anyway: let it end normally, so a
         * scenario of exactly N steps completes (the next call stops) */
        int last = P.active && !P.nested && sim == P.sim && sim->step - P.step0 >= P.nsteps;
        if (!last) {
            run->stopped = LAMINA_STOP_STEPS;
            return 1;
        }
    }
    if (!P.active) return 0;
    double now = now_s();
    if (run->poll && now - P.last_poll >= POLL_EVERY) {
        P.last_poll = now;
        const char *why = run->poll(run->poll_ud);
        if (why) {
            run->stopped = LAMINA_STOP_POLL;
            run->stop_why = why;
            return 1;
        }
    }
    if (P.nested || sim != P.sim || P.nsteps <= 0) return 0;
    long done = sim->step - P.step0;
    int decile = (int)(10 * done / P.nsteps);
    int new_decile = decile > P.decile;
    P.decile = decile;
    if (run->quiet || now - P.start < P.after || done >= P.nsteps) return 0;
    if (P.tty ? now - P.last_show >= TTY_EVERY : new_decile) show(now, done);
    return 0;
}
