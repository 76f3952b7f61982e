/* cmd_run.c - `lamina run SCRIPT.lua [--set name=value ...]`. */
#include <lauxlib.h>
#include <lua.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "lamina_lua.h"
#include "mpm.h"
#include "render.h"
#include "util.h"

/* FNV-1a of the script's bytes: the provenance stamped into every PNG. */
static int hash_file(const char *path, char out[17])
{
    FILE *f = fopen(path, "rb");
    if (!f) return -1;
    uint64_t h = LU_FNV_SEED;
    unsigned char buf[65536];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0)
        h = lu_fnv1a(h, buf, n);
    int bad = ferror(f);
    fclose(f);
    lu_hash_hex(h, out);
    return bad ? -1 : 0;
}

static int parse_args(int argc, char **argv, lamina_run *run, const char **report,
                      const char **out_root)
{
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--set") == 0 || strncmp(a, "--set=", 6) == 0) {
            const char *kv = a[5] == '=' ? a + 6 : (i + 1 < argc ? argv[++i] : NULL);
            const char *eq = kv ? strchr(kv, '=') : NULL;
            if (!eq || eq == kv) {
                fprintf(stderr, "lamina run: --set needs name=value (got '%s')\n",
                        kv ? kv : "");
                return -1;
            }
            lamina_set *s = &run->sets[run->nsets++];
            size_t n = (size_t)(eq - kv);
            char *name = malloc(n + 1);
            if (!name) return -1;
            memcpy(name, kv, n);
            name[n] = 0;
            s->name = name;
            s->value = eq + 1;
            s->used = 0;
            for (int k = 0; k < run->nsets - 1; k++)
                if (strcmp(run->sets[k].name, name) == 0) {
                    fprintf(stderr, "lamina run: --set %s given twice\n", name);
                    return -1;
                }
        } else if (strcmp(a, "--report") == 0 || strncmp(a, "--report=", 9) == 0) {
            const char *f = a[8] == '=' ? a + 9 : (i + 1 < argc ? argv[++i] : NULL);
            if (!f || !*f || *report) {
                fprintf(stderr, "lamina run: %s\n", *report ? "--report given twice"
                                                            : "--report needs a FILE");
                return -1;
            }
            *report = f;
        } else if (strcmp(a, "--out-root") == 0 || strncmp(a, "--out-root=", 11) == 0) {
            /* the folder the script's files must stay in (docs/api.md, Sandbox) */
            const char *d = a[10] == '=' ? a + 11 : (i + 1 < argc ? argv[++i] : NULL);
            if (!d || !*d || *out_root) {
                fprintf(stderr, "lamina run: %s\n", *out_root ? "--out-root given twice"
                                                              : "--out-root needs a DIR");
                return -1;
            }
            *out_root = d;
        } else if (strcmp(a, "--lua-mem") == 0 || strncmp(a, "--lua-mem=", 10) == 0) {
            /* the cap on the script's Lua memory (l_alloc.c), MB */
            const char *v = a[9] == '=' ? a + 10 : (i + 1 < argc ? argv[++i] : NULL);
            char *end = NULL;
            double mb = v ? strtod(v, &end) : 0;
            if (!v || !*v || *end || !(mb >= 1 && mb <= 1048576)) {
                fprintf(stderr, "lamina run: --lua-mem needs a size in MB from 1 to 1048576 "
                        "(default %d)\n", LAMINA_LUA_MEM_DEFAULT_MB);
                return -1;
            }
            run->lua_mem_limit = (size_t)(mb * 1048576.0);
        } else if (strcmp(a, "--backend") == 0 || strncmp(a, "--backend=", 10) == 0) {
            /* sim:frame's default renderer for this run (docs/rendering.md) */
            const char *b = a[9] == '=' ? a + 10 : (i + 1 < argc ? argv[++i] : NULL);
            lr_backend which;
            char why[512];
            if (!b || !*b) {
                fprintf(stderr, "lamina run: --backend needs a NAME (cairo, osmesa, egl or gl)\n");
                return -1;
            }
            if (lr_backend_parse(b, &which, why, sizeof why) != 0 ||
                lr_backend_check(which, why, sizeof why) != 0) {
                fprintf(stderr, "lamina run: --backend %s: %s\n", b, why);
                return -1;
            }
            run->backend = b;
        } else if (strcmp(a, "--threads") == 0 || strncmp(a, "--threads=", 10) == 0) {
            /* lamina.sim's default thread count for this run (docs/api.md) */
            const char *v = a[9] == '=' ? a + 10 : (i + 1 < argc ? argv[++i] : NULL);
            char *end = NULL;
            long n = v ? strtol(v, &end, 10) : 0;
            if (!v || !*v || *end || n < 1 || n > LM_MAX_THREADS) {
                fprintf(stderr, "lamina run: --threads needs a whole number from 1 to %d\n",
                        LM_MAX_THREADS);
                return -1;
            }
            setenv("LAMINA_THREADS", v, 1);
        } else if (strcmp(a, "--restart") == 0 || strncmp(a, "--restart=", 10) == 0) {
            /* continue from a checkpoint (sim:checkpoint, docs/api.md) */
            const char *f = a[9] == '=' ? a + 10 : (i + 1 < argc ? argv[++i] : NULL);
            if (!f || !*f || run->restart) {
                fprintf(stderr, "lamina run: %s\n", run->restart ? "--restart given twice"
                                                                 : "--restart needs a FILE");
                return -1;
            }
            run->restart = f;
        } else if (strcmp(a, "--quiet") == 0 || strcmp(a, "-q") == 0) {
            run->quiet = 1;
        } else if (a[0] == '-' && a[1]) {
            fprintf(stderr, "lamina run: unknown option '%s' (try 'lamina help')\n", a);
            return -1;
        } else if (!run->script) {
            run->script = a;
        } else {
            fprintf(stderr, "lamina run: more than one script given ('%s', '%s')\n",
                    run->script, a);
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
static int init_report(lua_State *L, const char *path)
{
    lua_pushstring(L, path);
    lua_setfield(L, LUA_REGISTRYINDEX, "lamina.report.file");
    lua_getglobal(L, "lamina");
    lua_getfield(L, -1, "report");
    lua_newtable(L);
    int rc = lua_pcall(L, 1, 0, 0);
    if (rc != LUA_OK)
        fprintf(stderr, "lamina run: --report: %s\n", lua_tostring(L, -1));
    lua_settop(L, 0);
    return rc == LUA_OK ? 0 : -1;
}

static void free_sets(lamina_run *run)
{
    for (int i = 0; i < run->nsets; i++) free((char *)run->sets[i].name);
    free(run->sets);
}

int cmd_run(int argc, char **argv)
{
    lamina_run run;
    memset(&run, 0, sizeof run);
    run.sets = calloc((size_t)argc + 1, sizeof *run.sets);
    if (!run.sets) return LAMINA_EXIT_USAGE;
    const char *report = NULL, *out_root = NULL;
    if (parse_args(argc, argv, &run, &report, &out_root)) {
        free_sets(&run);
        return LAMINA_EXIT_USAGE;
    }
    char why[1100];
    if (lamina_check_script_file(run.script, why, sizeof why) != 0) {   /* before reading it */
        fprintf(stderr, "lamina run: %s\n", why);
        free_sets(&run);
        return LAMINA_EXIT_USAGE;
    }
    if (hash_file(run.script, run.script_hash)) {
        perror(run.script);
        fprintf(stderr, "lamina run: cannot read script '%s'\n", run.script);
        free_sets(&run);
        return LAMINA_EXIT_USAGE;
    }
    lua_State *L = lamina_open_state(&run);
    if (!L) {
        fprintf(stderr, "lamina run: cannot create a Lua state (out of memory)\n");
        free_sets(&run);
        return LAMINA_EXIT_USAGE;
    }
    if (out_root && lamina_set_output_root(L, out_root, why, sizeof why) != 0) {
        fprintf(stderr, "lamina run: %s\n", why);
        lua_close(L);
        free_sets(&run);
        return LAMINA_EXIT_USAGE;
    }
    if (report && init_report(L, report)) {
        lua_close(L);
        free_sets(&run);
        lr_shutdown();
        return LAMINA_EXIT_USAGE;
    }
    /* SIGINT, SIGTERM: stop at the next step boundary (or Lua instruction),
     * write the records, exit 128 + the signal's number (docs/api.md) */
    lamina_interrupt_install(L);
    lamina_interrupt_install_term();
    int rc = lamina_run_script(L, &run);
    if (run.stopped == LAMINA_STOP_SIGINT) rc = 128 + lamina_interrupt_signal();
    lamina_interrupt_uninstall();
    lua_close(L);
    if (run.frames && !run.quiet)
        fprintf(stderr, "lamina: %ld frame%s written to %s\n", run.frames,
                run.frames == 1 ? "" : "s", run.frame_dir);
    free_sets(&run);
    lr_shutdown();
    return rc;
}
