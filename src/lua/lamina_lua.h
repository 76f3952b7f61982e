/* lamina_lua.h - the `lamina` Lua module: bindings only, no physics.
 *
 * The app creates a lamina_run (what was asked on the command line), opens a
 * sandboxed Lua state with lamina_open_state() and runs the script with
 * lamina_run_script(), which maps every outcome to docs/design.md's exit status:
 * 0 success, 1 the simulation failed, 2 the script or command line is wrong. */
#ifndef LAMINA_LUA_H
#define LAMINA_LUA_H

#include <stddef.h>
#include <stdio.h>

typedef struct lua_State lua_State;
struct lm_sim;

enum { LAMINA_EXIT_OK = 0, LAMINA_EXIT_SIM = 1, LAMINA_EXIT_USAGE = 2 };

/* Why a run stopped at a step boundary before its end (lamina_run.stopped). */
enum { LAMINA_STOP_NONE = 0, LAMINA_STOP_SIGINT, LAMINA_STOP_STEPS, LAMINA_STOP_POLL };

/* How a run ended early (lamina_run.failure; l_run_guard.c): an error in the
 * script's code (a callback, a pin's velocity function, a recorder's
 * value), the engine's step failing (NaN, an inverted particle, a tear),
 * a refused step (the Courant limit), a signal, a stop at a step boundary
 * asked by the workbench (--steps, a changed file), a failed write
 * (checkpoint, records). lamina_failure_status gives the exit status. */
enum { LAMINA_FAIL_NONE = 0, LAMINA_FAIL_SCRIPT, LAMINA_FAIL_UNSTABLE, LAMINA_FAIL_REFUSED,
       LAMINA_FAIL_SIGNAL, LAMINA_FAIL_STOPPED, LAMINA_FAIL_IO };

typedef struct lamina_set {
    const char *name, *value;   /* from --set name=value */
    int used;                   /* asked for by lamina.param */
} lamina_set;

/* lamina serve (src/app/serve_*.c): what a run tells a watcher in the same
 * process. Every call comes from the thread that runs the script. */
typedef struct lamina_observer {
    void *ud;
    /* After every step of a sim:run / sim:step, the sim at stack index sidx:
     * may block (a pause) and change live settings through
     * lamina_set_live / lamina_set_param; returns 1 when it changed
     * something the engine may have computed ahead. */
    int (*step)(void *ud, lua_State *L, int sidx, const struct lm_sim *sim);
    /* lamina.param answered `value` (as text; type is the default's Lua type) */
    void (*param)(void *ud, const char *name, int type, const char *value);
    /* an image was written at path */
    void (*image)(void *ud, const char *path);
    /* a recorder (id) took a row of ncols values; column k is named at
     * names + k * stride; label names the recorder (its file, or "record") */
    void (*record)(void *ud, const void *id, const char *label, int ncols,
                   const char *names, size_t stride, const double *row);
} lamina_observer;

typedef struct lamina_run {
    const char *script;         /* path as given */
    char script_hash[17];       /* FNV-1a of the script's bytes, hex */
    lamina_set *sets;
    int nsets;
    int quiet;
    int failure;                /* LAMINA_FAIL_* of the last failure a run recorded */
    char failure_msg[512];      /* its message */
    int failure_escaped;        /* the error that ended the script is that failure */
    const struct lm_sim *active;/* the simulation being stepped, for logs */
    const struct lm3_sim *active3; /* ... when it is a 3D one (l_sim3_run.c) */
    long frames;                /* PNGs written */
    char frame_dir[512];        /* folder of the last one */
    /* the workbench (lamina repl/watch/sweep, docs/workbench.md) */
    long steps;                 /* steps taken by every sim so far */
    double t_last;              /* time of the sim that stepped last */
    long max_steps;             /* > 0: stop after this many steps (watch --steps) */
    const char *(*poll)(void *ud);  /* between steps, every ~0.2 s: a reason stops the run */
    void *poll_ud;
    int stopped;                /* LAMINA_STOP_* of the last stop */
    const char *stop_why;       /* the poll's reason */
    int at_prompt;              /* the repl is running a line typed at its prompt */
    long changes;               /* live parameter changes logged */
    FILE *log;                  /* NULL, or a copy of the run log */
    const char *backend;        /* --backend NAME: sim:frame's default
                                   ("cairo", "osmesa", "egl", "gl"); NULL: cairo */
    const char *restart;        /* --restart FILE: a checkpoint to continue */
    int threads;                /* --threads N: lamina.sim's default thread
                                   count (0: LAMINA_THREADS, else 1) */
    const char *report_file;    /* --report FILE: lamina.report rewrites it */
    int restored;               /* it has been loaded */
    int nsims;                  /* lamina.sim calls so far */
    /* the Lua state's memory (l_alloc.c): a cap, bytes (0: the default,
     * LAMINA_LUA_MEM_DEFAULT_MB; lamina run --lua-mem MB), in use, peak */
    size_t lua_mem_limit, lua_mem_used, lua_mem_peak;
    const lamina_observer *observer;   /* lamina serve's, else NULL */
    const char *change_from;    /* set while a change from lamina serve's page
                                   is applied: the run log says so */
} lamina_run;

/* The default cap on a script's Lua memory, in MB: far above what any
 * script in scripts/ or tests/ uses (a few MB; the engine's particles and
 * grid are not Lua memory), far below what would make a machine swap. */
#define LAMINA_LUA_MEM_DEFAULT_MB 1024

/* A Lua state with the safe standard libraries and `lamina` as a global;
 * its memory is capped at run->lua_mem_limit (run must outlive it). */
/* n bytes of a script's text to f with its control characters written as
 * Lua escapes ("\27"): no terminal escape sequence gets through (l_print.c,
 * docs/security.md). */
void la_write_clean(FILE *f, const char *s, size_t n);

lua_State *lamina_open_state(lamina_run *run);
/* `lamina run --out-root DIR`: the folder every file a script writes must
 * stay in (else the working directory). 0, or -1 with err. */
int lamina_set_output_root(lua_State *L, const char *dir, char *err, size_t len);
/* 0 when path names a regular file (not /dev/zero, a FIFO, a folder), else
 * -1 with err "cannot read script 'PATH': why". */
int lamina_check_script_file(const char *path, char *err, size_t len);
/* Loads and runs run->script in L; prints errors with file:line and a
 * traceback to stderr; returns the exit status. */
int lamina_run_script(lua_State *L, lamina_run *run);
/* The exit status of a script that ended with an error (l_run_guard.c),
 * from the code of the failure it ended with: 1 the simulation failed, 128
 * + the number of a signal that stopped it, else 2. */
int lamina_failure_status(const lamina_run *run);
/* The message handler of every protected call of a script (run, watch,
 * repl): the message with a traceback; the message alone when upvalue 1 is
 * a lamina_run that was stopped (Ctrl-C, a watch's stop: it says where).
 * Push it as a C closure with the run as a light userdata, or bare. */
int lamina_msghandler(lua_State *L);

/* ---- the workbench: lamina repl / watch / sweep (docs/workbench.md) ---- */

/* l_interrupt.c: SIGINT sets a flag instead of ending the process; a run
 * stops at its next step boundary and Lua code at its next instruction (a
 * count hook on the registered threads, as lua.c does) with the error
 * "interrupted at t = ..., step ...". */
void lamina_interrupt_install(lua_State *L);
void lamina_interrupt_add_thread(lua_State *thread);
/* lamina run: SIGTERM too; the signal that stopped the run (SIGINT or
 * SIGTERM), whose 128 + number is lamina run's exit status then. */
void lamina_interrupt_install_term(void);
int lamina_interrupt_signal(void);
void lamina_interrupt_uninstall(void);
int lamina_interrupt_pending(void);
void lamina_interrupt_clear(void);

/* l_progress.c: forget a progress line left by a run that ended in error. */
void lamina_progress_reset(void);
/* Ends a progress line shown in place on a terminal, so that other output
 * starts on a fresh line. */
void lamina_progress_clear_line(void);

/* l_pause.c: the repl's script. Runs run->script in a coroutine up to its
 * first sim:run, or, when the script mentions lamina.pause, up to its first
 * lamina.pause() (else its end). At the pause the main chunk's locals become
 * globals and the paused simulation is `sim` (unless that name is taken).
 * Errors are printed; returns LAMINA_SCRIPT_*. */
enum { LAMINA_SCRIPT_PAUSED, LAMINA_SCRIPT_DONE, LAMINA_SCRIPT_FAILED, LAMINA_SCRIPT_BAD };
int lamina_script_start(lua_State *L, lamina_run *run);

/* l_session.c: runs run->script once for `lamina watch`: like
 * lamina_run_script, but a stop at a step boundary (--steps, a changed file,
 * Ctrl-C) is not an error (run->stopped says which). The first line of an
 * error goes to msg. Returns the exit status `lamina run` would give. */
int lamina_run_watched(lua_State *L, lamina_run *run, char *msg, size_t len);
/* "name = value, ..." of what the script reported through lamina.report. */
void lamina_report_line(lua_State *L, char *buf, size_t len);

/* l_param.c, for lamina serve: while a sim steps (from an observer's step),
 * lamina.param(name, ...) answers value from now on, converted to the type
 * of the default the script gave; the change is logged as a live change
 * ("param.NAME = value"). 0, or -1 with err (a name the script has not
 * read, a value of the wrong type). */
int lamina_set_param(lua_State *L, const char *name, const char *value, char *err,
                     size_t len);
/* Sets a live setting of the sim at sidx (dt, gravity "gx,gy", pic,
 * courant) through the same path as `sim.dt = ...` in a callback (checked,
 * logged). 0, or -1 with err. */
int lamina_set_live(lua_State *L, int sidx, const char *key, const char *value, char *err,
                    size_t len);
/* The live settings the page shows and lamina_set_live takes. */
extern const char *const lamina_live_settings[];

#endif
