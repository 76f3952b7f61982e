/* lamina_lua.h - the `lamina` Lua module: bindings only, no physics.
 *
 * The app creates a lamina_run (what was asked on the command line), opens a
 * sandboxed Lua state with lamina_open_state() and runs the script with
 * lamina_run_script(), which maps every outcome to design.md's exit status:
 * 0 success, 1 the simulation failed, 2 the script or command line is wrong. */
#ifndef LAMINA_LUA_H
#define LAMINA_LUA_H

#include <stddef.h>

typedef struct lua_State lua_State;
struct lm_sim;

enum { LAMINA_EXIT_OK = 0, LAMINA_EXIT_SIM = 1, LAMINA_EXIT_USAGE = 2 };

typedef struct lamina_set {
    const char *name, *value;   /* from --set name=value */
    int used;                   /* asked for by lamina.param */
} lamina_set;

typedef struct lamina_run {
    const char *script;         /* path as given */
    char script_hash[17];       /* FNV-1a of the script's bytes, hex */
    lamina_set *sets;
    int nsets;
    int quiet;
    int sim_failed;             /* set when an engine error was raised */
    const struct lm_sim *active;/* the simulation being stepped, for logs */
    long frames;                /* PNGs written */
    char frame_dir[512];        /* folder of the last one */
} lamina_run;

/* A Lua state with the safe standard libraries and `lamina` as a global. */
lua_State *lamina_open_state(lamina_run *run);
/* Loads and runs run->script in L; prints errors with file:line and a
 * traceback to stderr; returns the exit status. */
int lamina_run_script(lua_State *L, lamina_run *run);

#endif
