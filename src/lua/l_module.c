/* l_module.c - the `lamina` table, the sandboxed state and running a script.
 *
 * Errors are reported as lua.c does: one protected call with a message
 * handler that appends a traceback; syntax errors carry file:line from the
 * loader. The exit status tells a failed simulation (1) from a wrong script
 * or command line (2). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "l_analysis.h"
#include "l_curve.h"
#include "l_mesh3.h"
#include "l_sim3.h"
#include "util.h"

/* lamina.clock(): wall-clock seconds from an arbitrary start (monotonic),
 * for timing a run; os.clock counts processor time, which threads add up. */
static int l_clock(lua_State *L)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    lua_pushnumber(L, (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec);
    return 1;
}

static int luaopen_lamina(lua_State *L)
{
    static const luaL_Reg funcs[] = {{"param", la_param},
                                     {"clock", l_clock},
                                     {"read_csv", la_read_csv},
                                     {"sim", la_sim_new},
                                     {"elastic", la_elastic},
                                     {"membrane", la_membrane_material},
                                     {"gas", la_gas},
                                     {"linear_fluid", la_linear_fluid},
                                     {"disk", la_disk},
                                     {"rect", la_rect},
                                     {"polygon", la_polygon},
                                     {"ball", la_ball},
                                     {"box", la_box},
                                     {"cylinder", la_cylinder},
                                     {"sphere", la_sphere},   /* 3D membrane surfaces */
                                     {"rect3", la_rect3},
                                     {"mesh", la_mesh},       /* OBJ / STL (l_mesh3.c) */
                                     {"plot", la_plot},
                                     {"report", la_report},
                                     {"pause", la_pause},
                                     {"resume", la_resume},
                                     {"changes", la_changes},
                                     {NULL, NULL}};
    la_open_material(L);
    la_open_region(L);
    la_open_sim(L);
    la_open_body(L);
    la_open_region3(L);         /* lamina.ball/box/cylinder (l_region3.c) */
    la_open_body3(L);
    la_open_membrane3(L);       /* a 3D sim's membranes (l_membrane3.c) */           /* a 3D sim's bodies (l_body3.c) */
    la_open_pin3(L);            /* their pins (l_pin3.c) */
    la_open_mesh3(L);           /* lamina.mesh (l_mesh3.c) */
    la_open_pin(L);
    la_open_link(L);
    la_open_curve(L);
    la_open_record(L);
    luaL_newlib(L, funcs);
    la_register_curves(L);
    la_open_normals(L);         /* lamina.normals, lamina.figure */
    la_open_analysis(L);        /* lamina.analysis (l_analysis*.c) */
    lua_pushstring(L, LAMINA_VERSION);
    lua_setfield(L, -2, "version");
    return 1;
}

lua_State *lamina_open_state(lamina_run *run)
{
    lua_State *L = la_new_state(run);
    if (!L) return NULL;
    lua_pushlightuserdata(L, run);
    lua_setfield(L, LUA_REGISTRYINDEX, "lamina.run");
    la_open_sandbox(L, run ? run->script : NULL);   /* l_sandbox.c */
    luaL_requiref(L, "lamina", luaopen_lamina, 1);
    lua_pop(L, 1);
    return L;
}

int lamina_msghandler(lua_State *L)
{
    const char *msg = lua_tostring(L, 1);
    if (msg == NULL) {
        if (luaL_callmeta(L, 1, "__tostring") && lua_type(L, -1) == LUA_TSTRING)
            return 1;
        msg = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
    }
    la_fail_note_escape(L, 1);   /* the exit status: is this the run's failure? */
    const lamina_run *run = lua_touserdata(L, lua_upvalueindex(1));
    if (run && run->stopped) return 1;
    luaL_traceback(L, L, msg, 1);
    return 1;
}

/* A --set name the script never asked for is almost always a typo. */
static int check_sets(const lamina_run *run)
{
    int bad = 0;
    for (int i = 0; i < run->nsets; i++) {
        if (run->sets[i].used) continue;
        fprintf(stderr, "lamina: --set %s: the script has no lamina.param('%s', ...)\n",
                run->sets[i].name, run->sets[i].name);
        bad = 1;
    }
    return bad;
}

/* How the process's memory cap is raised (lu_budget.c, docs/security.md). */
static void la_budget_hint(void)
{
    if (lu_budget_refused())
        fprintf(stderr, "lamina: the cap counts the engine's arrays, the pictures and the "
                "Lua heap together (LAMINA_MEMORY_MB=N or lamina run --memory N raises it)\n");
}

int lamina_run_script(lua_State *L, lamina_run *run)
{
    lu_budget_forget_refusal();
    lua_pushcfunction(L, lamina_msghandler);
    int base = lua_gettop(L);
    if (la_load_script(L, run->script) != LUA_OK) {
        fprintf(stderr, "lamina: %s\n", lua_tostring(L, -1));
        lua_settop(L, 0);
        return LAMINA_EXIT_USAGE;
    }
    lua_pushstring(L, run->script);
    lua_setglobal(L, "SCRIPT");
    int rc = lua_pcall(L, 0, 0, base);
    if (rc == LUA_ERRMEM) {   /* no traceback: the handler is not called */
        lamina_progress_clear_line();
        if (lu_budget_refused())   /* the process's cap, not the Lua state's */
            fprintf(stderr, "lamina: %s: %s\n", run->script, lu_budget_oom());
        else
            fprintf(stderr, "lamina: %s: the script's Lua memory reached its cap of %zu MB "
                    "(lamina run --lua-mem MB raises it)\n", run->script,
                    run->lua_mem_limit >> 20);
        la_budget_hint();
        lua_settop(L, 0);
        return LAMINA_EXIT_USAGE;
    }
    if (rc != LUA_OK) {
        lamina_progress_clear_line();   /* the message starts a line of its own */
        size_t len = 0;
        const char *msg = lua_tolstring(L, -1, &len);
        fputs("lamina: ", stderr);   /* the script's text, without terminal escapes */
        if (msg) la_write_clean(stderr, msg, len);
        else fputs("(error object is not a string)", stderr);
        fputc('\n', stderr);
        if (msg && strstr(msg, "memory limit"))
            la_budget_hint();
        else if (msg && strstr(msg, "not enough memory") && lu_budget_refused())
            fprintf(stderr, "lamina: %s\n", lu_budget_oom());   /* raised again by a callback */
        else if (msg && strstr(msg, "not enough memory"))
            fprintf(stderr, "lamina: the script's Lua memory is capped at %zu MB "
                    "(lamina run --lua-mem MB raises it)\n", run->lua_mem_limit >> 20);
        int status = lamina_failure_status(run);
        lua_settop(L, 0);
        return status;
    }
    lua_settop(L, 0);
    /* a signal the script caught still ends `lamina run` with its status */
    if (run->stopped == LAMINA_STOP_SIGINT) return lamina_failure_status(run);
    if (run->restart && !run->restored) {
        /* the checkpoint's simulation never ran: nothing was continued */
        fprintf(stderr, "lamina: --restart %s: the script never ran the simulation it was "
                "taken from\n", run->restart);
        return LAMINA_EXIT_USAGE;
    }
    return check_sets(run) ? LAMINA_EXIT_USAGE : LAMINA_EXIT_OK;
}
