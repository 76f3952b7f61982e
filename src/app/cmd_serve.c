/* cmd_serve.c - `lamina serve SCRIPT.lua [--port N] [--host ADDR]
 * [--allow-remote] [--set name=value ...] [--paused] [--keep] [--quiet]`:
 * the workbench in a browser (docs/workbench.md, "lamina serve"; issue 35
 * item 1).
 *
 * The script runs as under `lamina run` (same engine path, same exit
 * status, SIGINT/SIGTERM stop it at a step boundary with its records
 * written); an HTTP thread (serve_http.c) serves one page and the run's
 * state, and queues the page's controls, which the run applies between
 * steps (serve_state.c). The server stops when the run ends, or with
 * --keep when Ctrl-C / SIGTERM comes after it. */
#include <lua.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app.h"
#include "render.h"
#include "serve.h"
#include "workbench.h"

static const char usage_line[] =
    "usage: lamina serve SCRIPT.lua [--port N] [--host ADDR] [--allow-remote]\n"
    "                    [--set name=value ...] [--paused] [--keep] [--quiet]";

#define DEFAULT_PORT 8035

typedef struct serve_args {
    serve_opts http;
    int paused, keep;
} serve_args;

static int parse_args(int argc, char **argv, lamina_run *run, serve_args *a)
{
    for (int i = 0; i < argc; i++) {
        const char *w = argv[i], *v;
        int got;
        if ((got = wb_option("serve", argc, argv, &i, "--set", &v))) {
            if (got < 0 || wb_add_set("serve", run, v)) return -1;
        } else if ((got = wb_option("serve", argc, argv, &i, "--port", &v))) {
            if (got < 0 || wb_count("serve", "--port", v, 0, 65535, &a->http.port)) return -1;
        } else if ((got = wb_option("serve", argc, argv, &i, "--host", &v))) {
            if (got < 0) return -1;
            if (!*v) {
                fprintf(stderr, "lamina serve: --host needs an address (got '')\n");
                return -1;
            }
            a->http.host = v;
        } else if (strcmp(w, "--allow-remote") == 0) {
            a->http.allow_remote = 1;
        } else if (strcmp(w, "--paused") == 0) {
            a->paused = 1;
        } else if (strcmp(w, "--keep") == 0) {
            a->keep = 1;
        } else if (wb_word("serve", w, &run->quiet, &run->script, usage_line)) {
            return -1;
        }
    }
    if (!run->script) {
        fprintf(stderr, "lamina serve: no script given\n%s\n", usage_line);
        return -1;
    }
    /* the page controls the run: only this machine unless asked */
    int lo = serve_host_is_loopback(a->http.host);
    if (lo < 0) {
        fprintf(stderr, "lamina serve: --host %s: not an address this machine can bind\n",
                a->http.host);
        return -1;
    }
    if (!lo && !a->http.allow_remote) {
        fprintf(stderr, "lamina serve: --host %s is not a loopback address: anyone who reaches "
                "it could control the run; add --allow-remote to mean it (docs/security.md)\n",
                a->http.host);
        return -1;
    }
    return 0;
}

int cmd_serve(int argc, char **argv)
{
    lamina_run run;
    memset(&run, 0, sizeof run);
    serve_args a = {{"127.0.0.1", DEFAULT_PORT, 0}, 0, 0};
    run.sets = calloc((size_t)argc + 1, sizeof *run.sets);
    if (!run.sets) return LAMINA_EXIT_USAGE;
    if (parse_args(argc, argv, &run, &a)) {
        wb_free_sets(&run);
        return LAMINA_EXIT_USAGE;
    }
    char why[1100] = "";
    wb_file_sig sig;
    if (lamina_check_script_file(run.script, why, sizeof why) != 0 ||
        (wb_file_sig_read(run.script, &sig), !sig.ok)) {
        fprintf(stderr, "lamina serve: %s\n",
                why[0] ? why : "cannot read the script");
        wb_free_sets(&run);
        return LAMINA_EXIT_USAGE;
    }
    snprintf(run.script_hash, sizeof run.script_hash, "%016llx", (unsigned long long)sig.hash);
    serve_state st;
    if (serve_state_init(&st, run.script) != 0) {
        wb_free_sets(&run);
        return LAMINA_EXIT_USAGE;
    }
    st.paused = a.paused;
    lamina_observer obs = serve_observer_proto;
    obs.ud = &st;
    run.observer = &obs;
    lua_State *L = lamina_open_state(&run);
    /* the stops before the server: a client that sees it answer may send
     * SIGTERM at once (cli.serve_http caught the default action, status
     * -15, when they came after) */
    if (L) {
        lamina_interrupt_install(L);
        lamina_interrupt_install_term();
    }
    serve_http *h = L ? serve_http_start(&st, &a.http) : NULL;
    if (!h) {
        if (!L) fprintf(stderr, "lamina serve: cannot create a Lua state (out of memory)\n");
        if (L) {
            lamina_interrupt_uninstall();
            lua_close(L);
        }
        serve_state_free(&st);
        wb_free_sets(&run);
        return LAMINA_EXIT_USAGE;
    }
    int rc = lamina_run_script(L, &run);
    if (run.stopped == LAMINA_STOP_SIGINT) rc = 128 + lamina_interrupt_signal();
    pthread_mutex_lock(&st.mu);
    st.finished = 1;
    st.status = rc;
    st.paused = 0;
    serve_msg(&st, "the run has ended (status %d)", rc);
    pthread_mutex_unlock(&st.mu);
    if (a.keep && run.stopped != LAMINA_STOP_SIGINT) {
        /* the final state stays on the page until Ctrl-C or SIGTERM */
        fprintf(stderr, "lamina serve: the run has ended (status %d); serving until Ctrl-C\n", rc);
        while (!lamina_interrupt_pending()) {
            struct timespec ts = {0, 100000000L};
            nanosleep(&ts, NULL);
        }
    }
    serve_http_stop(h);
    lamina_interrupt_uninstall();
    lua_close(L);
    if (run.frames && !run.quiet)
        fprintf(stderr, "lamina: %ld frame%s written to %s\n", run.frames,
                run.frames == 1 ? "" : "s", run.frame_dir);
    serve_state_free(&st);
    wb_free_sets(&run);
    lr_shutdown();
    return rc;
}
