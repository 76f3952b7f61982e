/* l_interrupt.c - Ctrl-C stops a run, not the program (lamina repl, watch).
 *
 * As lua.c does it: the SIGINT handler only sets a flag and arms a count
 * hook on the registered Lua threads (lua_sethook may be called from a
 * signal handler). A run notices the flag at its next step boundary
 * (la_progress_tick, called by advance()), so the simulation is left
 * between two steps, exactly as after a completed sim:step; plain Lua code
 * (a loop typed at the prompt) notices the hook at its next instruction.
 * Either raises an ordinary Lua error that the prompt catches. */
#include <signal.h>
#include <string.h>

#include "l_internal.h"

#define MAX_THREADS 4

static volatile sig_atomic_t pending;
static volatile sig_atomic_t last_signal;   /* SIGINT or SIGTERM, for the exit status */
static lua_State *volatile threads[MAX_THREADS];
static int installed, installed_term;
static struct sigaction saved;

/* The signals `lamina run` treats as SIGTERM (issue 31 item 6): a closed
 * terminal, a quit key, a reader gone from a pipe (`lamina run s.lua |
 * head`), a user's or a batch system's signals and limits - each killed a
 * run before its record CSV was written and left a temporary file. */
static const int term_signals[] = {SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGUSR1,
                                   SIGUSR2, SIGALRM, SIGXCPU, SIGXFSZ};
#define NTERM ((int)(sizeof term_signals / sizeof term_signals[0]))
static struct sigaction saved_term[NTERM];

static const char *signal_name(int sig)
{
    static const char *const names[] = {"SIGTERM", "SIGHUP", "SIGQUIT", "SIGPIPE", "SIGUSR1",
                                        "SIGUSR2", "SIGALRM", "SIGXCPU", "SIGXFSZ"};
    for (int i = 0; i < NTERM; i++)
        if (term_signals[i] == sig) return names[i];
    return NULL;
}

static void clear_hooks(void)
{
    for (int i = 0; i < MAX_THREADS; i++)
        if (threads[i]) lua_sethook(threads[i], NULL, 0, 0);
}

/* Raises the error for whatever stopped the run, after recording why in
 * run->stopped (the watch tells a stop from a failure by it): a signal is
 * LAMINA_FAIL_SIGNAL, the workbench's stops LAMINA_FAIL_STOPPED. */
int la_interrupt_raise(lua_State *L, const lm_sim *sim)
{
    lamina_run *run = la_run(L);
    int why = run && run->stopped ? run->stopped : LAMINA_STOP_SIGINT;
    if (run) run->stopped = why;
    pending = 0;
    clear_hooks();
    int code = why == LAMINA_STOP_SIGINT ? LAMINA_FAIL_SIGNAL : LAMINA_FAIL_STOPPED;
    if (!sim) return la_fail_raisef(L, code, "interrupted");
    if (why == LAMINA_STOP_STEPS)
        return la_fail_raisef(L, code, "stopped after %I steps (--steps) at t = %f, step %I",
                              (lua_Integer)run->steps, sim->t, (lua_Integer)sim->step);
    if (why == LAMINA_STOP_POLL)
        return la_fail_raisef(L, code, "stopped at t = %f, step %I: %s", sim->t,
                              (lua_Integer)sim->step, run->stop_why ? run->stop_why : "asked to stop");
    const char *name = signal_name(last_signal);
    return la_fail_raisef(L, code, "interrupted%s%s%s at t = %f, step %I", name ? " (" : "",
                           name ? name : "", name ? ")" : "", sim->t, (lua_Integer)sim->step);
}

/* The count hook: Lua code running when Ctrl-C came. Inside a run (a
 * callback between steps) the message names the simulation's clock. */
static void hook(lua_State *L, lua_Debug *ar)
{
    (void)ar;
    lua_sethook(L, NULL, 0, 0);
    if (!pending) return;
    lamina_run *run = la_run(L);
    if (run) run->stopped = LAMINA_STOP_SIGINT;
    if (run && run->active) {
        la_interrupt_raise(L, run->active);
        return;
    }
    pending = 0;
    clear_hooks();
    luaL_where(L, 0);   /* the line the code was at */
    lua_pushliteral(L, "interrupted");
    lua_concat(L, 2);
    la_fail_raise(L, LAMINA_FAIL_SIGNAL);
}

static void on_sigint(int sig)
{
    pending = 1;
    last_signal = sig;
    for (int i = 0; i < MAX_THREADS; i++)
        if (threads[i]) lua_sethook(threads[i], hook, LUA_MASKCOUNT, 1);
}

void lamina_interrupt_install(lua_State *L)
{
    memset((void *)threads, 0, sizeof threads);
    lamina_interrupt_add_thread(L);
    pending = 0;
    if (installed) return;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0;   /* no SA_RESTART: a blocking read at the prompt returns */
    if (sigaction(SIGINT, &sa, &saved) == 0) installed = 1;
}

/* lamina run: SIGTERM (kill, a batch system's time limit) and the others of
 * term_signals stop the run at a step boundary as Ctrl-C does, so its
 * records are written and it exits 128 + the signal's number; the repl
 * keeps the defaults (a SIGTERM ends it). */
void lamina_interrupt_install_term(void)
{
    if (installed_term) return;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    for (int i = 0; i < NTERM; i++) sigaction(term_signals[i], &sa, &saved_term[i]);
    installed_term = 1;
}

int lamina_interrupt_signal(void)
{
    return last_signal ? (int)last_signal : SIGINT;
}

void lamina_interrupt_add_thread(lua_State *thread)
{
    for (int i = 0; i < MAX_THREADS; i++)
        if (!threads[i] || threads[i] == thread) {
            threads[i] = thread;
            return;
        }
}

void lamina_interrupt_uninstall(void)
{
    if (installed) sigaction(SIGINT, &saved, NULL);
    if (installed_term)
        for (int i = 0; i < NTERM; i++) sigaction(term_signals[i], &saved_term[i], NULL);
    installed = installed_term = 0;
    clear_hooks();
    memset((void *)threads, 0, sizeof threads);
    pending = 0;
}

int lamina_interrupt_pending(void)
{
    return pending != 0;
}

void lamina_interrupt_clear(void)
{
    pending = 0;
    clear_hooks();
}
