/* cmd_run.c - `lamina run SCRIPT.lua [--set name=value ...]`. */
#include <errno.h>
#include <lauxlib.h>
#include <lua.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "lamina_lua.h"
#include "mpm.h"
#include "render.h"
#include "util.h"
#include "workbench.h"

/* FNV-1a of the script's bytes: the provenance stamped into every PNG. */
static int hash_file(const char *path, char out[17])
{
    wb_file_sig sig;
    wb_file_sig_read(path, &sig);
    lu_hash_hex(sig.hash, out);
    return sig.ok ? 0 : -1;
}

/* A FILE or DIR option given once: 0, or -1 with the message. */
static int once(const char *opt, const char *v, const char *needs, const char **slot)
{
    if (!v || !*v || *slot) {
        fprintf(stderr, "lamina run: %s %s\n", opt, *slot ? "given twice" : needs);
        return -1;
    }
    *slot = v;
    return 0;
}

/* A size option in MB from lo to 1048576 (1 TB): its bytes into *bytes;
 * 0, or -1 with the message, which names the default def (and `also`,
 * where else it may come from). */
static int megabytes(const char *opt, const char *v, double lo, int def, const char *also,
                     size_t *bytes)
{
    char *end = NULL;
    double mb = v ? strtod(v, &end) : 0;
    if (!v || !*v || *end || !(mb >= lo && mb <= 1048576)) {
        fprintf(stderr, "lamina run: %s needs a size in MB from %.0f to 1048576 "
                "(default %d%s)\n", opt, lo, def, also);
        return -1;
    }
    *bytes = (size_t)(mb * 1048576.0);
    return 0;
}

static int parse_args(int argc, char **argv, lamina_run *run, const char **report,
                      const char **out_root)
{
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *v;
        if (lu_opt_value(argc, argv, &i, "--set", &v)) {
            if (wb_add_set("run", run, v ? v : "")) return -1;
        } else if (lu_opt_value(argc, argv, &i, "--report", &v)) {
            if (once("--report", v, "needs a FILE", report)) return -1;
        } else if (lu_opt_value(argc, argv, &i, "--out-root", &v)) {
            /* the folder the script's files must stay in (docs/api.md, "Sandbox") */
            if (once("--out-root", v, "needs a DIR", out_root)) return -1;
        } else if (lu_opt_value(argc, argv, &i, "--lua-mem", &v)) {
            /* the cap on the script's Lua memory (l_alloc.c), MB */
            if (megabytes("--lua-mem", v, 1, LAMINA_LUA_MEM_DEFAULT_MB, "",
                          &run->lua_mem_limit))
                return -1;
        } else if (lu_opt_value(argc, argv, &i, "--memory", &v)) {
            /* the process's one cap over the engine, the pictures and Lua
             * (src/util/lu_budget.c), MB; over LAMINA_MEMORY_MB */
            size_t bytes;
            if (megabytes("--memory", v, 16, LU_BUDGET_DEFAULT_MB, ", or LAMINA_MEMORY_MB",
                          &bytes))
                return -1;
            lu_budget_set_limit(bytes);
        } else if (lu_opt_value(argc, argv, &i, "--backend", &v)) {
            /* sim:frame's default renderer for this run (docs/rendering.md) */
            lr_backend which;
            char why[512];
            if (!v || !*v) {
                fprintf(stderr, "lamina run: --backend needs a NAME (cairo, osmesa, egl or gl)\n");
                return -1;
            }
            if (lr_backend_parse(v, &which, why, sizeof why) != 0 ||
                lr_backend_check(which, why, sizeof why) != 0) {
                fprintf(stderr, "lamina run: --backend %s: %s\n", v, why);
                return -1;
            }
            run->backend = v;
        } else if (lu_opt_value(argc, argv, &i, "--threads", &v)) {
            /* lamina.sim's default thread count for this run (docs/api.md) */
            char *end = NULL;
            long n = v ? strtol(v, &end, 10) : 0;
            if (!v || !*v || *end || n < 1 || n > LM_MAX_THREADS) {
                fprintf(stderr, "lamina run: --threads needs a whole number from 1 to %d\n",
                        LM_MAX_THREADS);
                return -1;
            }
            run->threads = (int)n;
        } else if (lu_opt_value(argc, argv, &i, "--restart", &v)) {
            /* continue from a checkpoint (sim:checkpoint, docs/api.md) */
            if (once("--restart", v, "needs a FILE", &run->restart)) return -1;
        } else if (wb_word("run", a, &run->quiet, &run->script, NULL)) {
            return -1;
        }
    }
    if (!run->script) {
        fprintf(stderr, "lamina run: no script given (usage: lamina run SCRIPT.lua)\n");
        return -1;
    }
    return 0;
}

/* --report FILE: lamina.report (l_report.c) rewrites FILE at every call.
 * An empty report is written first, so that an unwritable path fails
 * before the simulation instead of after it. */
static int init_report(lua_State *L, lamina_run *run, const char *path)
{
    run->report_file = path;
    lua_getglobal(L, "lamina");
    lua_getfield(L, -1, "report");
    lua_newtable(L);
    int rc = lua_pcall(L, 1, 0, 0);
    if (rc != LUA_OK)
        fprintf(stderr, "lamina run: --report: %s\n", lua_tostring(L, -1));
    lua_settop(L, 0);
    return rc == LUA_OK ? 0 : -1;
}

/* Everything between the command line and the end of the script; the
 * Lua state, once made, goes to *Lp for cmd_run to close. The exit status. */
static int run_script(int argc, char **argv, lamina_run *run, lua_State **Lp)
{
    const char *report = NULL, *out_root = NULL;
    if (parse_args(argc, argv, run, &report, &out_root)) return LAMINA_EXIT_USAGE;
    char why[1100];
    if (lamina_check_script_file(run->script, why, sizeof why) != 0) {   /* before reading it */
        fprintf(stderr, "lamina run: %s\n", why);
        return LAMINA_EXIT_USAGE;
    }
    if (hash_file(run->script, run->script_hash)) {
        perror(run->script);
        fprintf(stderr, "lamina run: cannot read script '%s'\n", run->script);
        return LAMINA_EXIT_USAGE;
    }
    lua_State *L = *Lp = lamina_open_state(run);
    if (!L) {
        fprintf(stderr, "lamina run: cannot create a Lua state (out of memory)\n");
        return LAMINA_EXIT_USAGE;
    }
    if (out_root && lamina_set_output_root(L, out_root, why, sizeof why) != 0) {
        fprintf(stderr, "lamina run: %s\n", why);
        return LAMINA_EXIT_USAGE;
    }
    if (report && init_report(L, run, report)) return LAMINA_EXIT_USAGE;
    /* SIGINT, SIGTERM: stop at the next step boundary (or Lua instruction),
     * write the records, exit 128 + the signal's number (docs/api.md; the
     * status comes from the run's recorded failure, l_run_guard.c) */
    lamina_interrupt_install(L);
    lamina_interrupt_install_term();
    int rc = lamina_run_script(L, run);
    /* what the script printed is output too: a full disk or a closed pipe
     * fails the run (issue 31: `lamina run s.lua > /dev/full` returned 0) */
    if ((fflush(stdout) != 0 || ferror(stdout)) && rc != 128 + SIGPIPE) {
        fprintf(stderr, "lamina run: cannot write the script's output to stdout: %s\n",
                strerror(errno ? errno : EIO));
        if (rc == 0) rc = LAMINA_EXIT_USAGE;
    }
    return rc;
}

/* One exit path (issue 33 item 4): whatever ended the run, the signal
 * handlers, the Lua state, the --set list and the renderer are released
 * here, once. */
int cmd_run(int argc, char **argv)
{
    lamina_run run;
    memset(&run, 0, sizeof run);
    lua_State *L = NULL;
    int rc = LAMINA_EXIT_USAGE;
    run.sets = calloc((size_t)argc + 1, sizeof *run.sets);
    if (run.sets) rc = run_script(argc, argv, &run, &L);
    lamina_interrupt_uninstall();
    if (L) lua_close(L);
    if (run.frames && !run.quiet)
        fprintf(stderr, "lamina: %ld frame%s written to %s\n", run.frames,
                run.frames == 1 ? "" : "s", run.frame_dir);
    wb_free_sets(&run);
    lr_shutdown();
    return rc;
}
