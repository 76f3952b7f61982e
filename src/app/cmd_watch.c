/* cmd_watch.c - `lamina watch SCRIPT.lua [--steps N] [--set name=value ...]`:
 * run a scenario, then again each time its file changes (docs/workbench.md).
 *
 * The file is polled (size, modification time and a hash of its bytes, so
 * that a save within the same clock tick is still seen) every --interval
 * seconds while waiting, and between steps while a run is in progress: a
 * change abandons that run at its next step boundary and starts the next.
 * Each run is a fresh Lua state in this process and ends with one summary
 * line on stdout: what happened, simulated time, steps, wall time, the
 * values the script reported through lamina.report, or its error with
 * file:line. --max-runs N (or --once) stops after N runs, with the last
 * run's exit status; otherwise Ctrl-C ends the watch. */
#include <lua.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app.h"
#include "render.h"
#include "workbench.h"

static const char usage_line[] =
    "usage: lamina watch SCRIPT.lua [--steps N] [--set name=value ...] [--max-runs N]\n"
    "                    [--once] [--interval SECONDS] [--log FILE] [--quiet]";

typedef struct watch_opts {
    lamina_run proto;    /* script, sets, quiet */
    long steps;          /* 0: the whole scenario */
    long max_runs;       /* 0: until Ctrl-C */
    double interval;
    const char *log;
} watch_opts;

/* What the poll between steps compares against. */
typedef struct watch_poll {
    const char *path;
    wb_file_sig sig;     /* the content this run started from */
    wb_file_sig now;     /* the changed content, when it changed */
} watch_poll;

static int parse_args(int argc, char **argv, watch_opts *o)
{
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *v;
        int got;
        if ((got = wb_option("watch", argc, argv, &i, "--set", &v))) {
            if (got < 0 || wb_add_set("watch", &o->proto, v)) return -1;
        } else if ((got = wb_option("watch", argc, argv, &i, "--steps", &v))) {
            if (got < 0 || wb_count("watch", "--steps", v, 1, 1000000000000L, &o->steps))
                return -1;
        } else if ((got = wb_option("watch", argc, argv, &i, "--max-runs", &v))) {
            if (got < 0 || wb_count("watch", "--max-runs", v, 1, 1000000000L, &o->max_runs))
                return -1;
        } else if ((got = wb_option("watch", argc, argv, &i, "--interval", &v))) {
            if (got < 0 || wb_number("watch", "--interval", v, 0.01, 3600, &o->interval))
                return -1;
        } else if ((got = wb_option("watch", argc, argv, &i, "--log", &v))) {
            if (got < 0) return -1;
            o->log = v;
        } else if (strcmp(a, "--once") == 0) {
            o->max_runs = 1;
        } else if (wb_word("watch", a, &o->proto.quiet, &o->proto.script, usage_line)) {
            return -1;
        }
    }
    if (!o->proto.script) {
        fprintf(stderr, "lamina watch: no script given\n%s\n", usage_line);
        return -1;
    }
    return 0;
}

static const char *poll_changed(void *ud)
{
    watch_poll *p = ud;
    wb_file_sig_read(p->path, &p->now);
    if (!p->now.ok || wb_file_sig_same(&p->now, &p->sig)) return NULL;
    return "the script changed";
}

static void clock_prefix(char *buf, size_t len)
{
    time_t t = time(NULL);
    struct tm tm;
    if (localtime_r(&t, &tm)) strftime(buf, len, "%H:%M:%S", &tm);
    else snprintf(buf, len, "--:--:--");
}

/* One run; returns its exit status, sets *stopped (LAMINA_STOP_*). */
static int run_once(const watch_opts *o, long k, watch_poll *poll, int *stopped)
{
    lamina_run run = o->proto;
    for (int i = 0; i < run.nsets; i++) run.sets[i].used = 0;
    run.max_steps = o->steps;
    run.poll = poll_changed;
    run.poll_ud = poll;
    snprintf(run.script_hash, sizeof run.script_hash, "%016llx",
             (unsigned long long)poll->sig.hash);
    if (o->log && !(run.log = fopen(o->log, "w"))) {
        fprintf(stderr, "lamina watch: cannot write the log '%s': %s\n", o->log,
                strerror(errno));
        return LAMINA_EXIT_USAGE;
    }
    lua_State *L = lamina_open_state(&run);
    if (!L) {
        fprintf(stderr, "lamina watch: cannot create a Lua state (out of memory)\n");
        if (run.log) fclose(run.log);
        return LAMINA_EXIT_USAGE;
    }
    lamina_interrupt_install(L);
    lamina_progress_reset();
    char msg[512], report[1024];
    double t0 = wb_now();
    int status = lamina_run_watched(L, &run, msg, sizeof msg);
    double wall = wb_now() - t0;
    lamina_report_line(L, report, sizeof report);
    lamina_interrupt_uninstall();
    lua_close(L);

    char when[16], what[96];
    clock_prefix(when, sizeof when);
    *stopped = run.stopped;
    if (run.stopped == LAMINA_STOP_POLL) snprintf(what, sizeof what, "abandoned (the script changed)");
    else if (run.stopped == LAMINA_STOP_SIGINT) snprintf(what, sizeof what, "interrupted");
    else if (status != LAMINA_EXIT_OK) snprintf(what, sizeof what, "failed (status %d)", status);
    else if (run.stopped == LAMINA_STOP_STEPS) snprintf(what, sizeof what, "ok (first %ld steps)", o->steps);
    else snprintf(what, sizeof what, "ok");
    char line[2048];
    char frames[48] = "";
    if (run.frames)
        snprintf(frames, sizeof frames, ", %ld frame%s", run.frames, run.frames == 1 ? "" : "s");
    int n = snprintf(line, sizeof line, "[%s] watch %ld: %s, t = %.6g, %ld steps%s, %.2f s",
                     when, k, what, run.t_last, run.steps, frames, wall);
    if (n > 0 && (size_t)n < sizeof line) {
        if (status != LAMINA_EXIT_OK && msg[0])
            snprintf(line + n, sizeof line - (size_t)n, ": %s", msg);
        else if (report[0])
            snprintf(line + n, sizeof line - (size_t)n, "; %s", report);
    }
    fflush(stderr);
    la_write_clean(stdout, line, strlen(line));   /* msg and report are the script's text */
    fputc('\n', stdout);
    fflush(stdout);
    if (run.log) {
        /* a log that could not be written (--log /dev/full) is an error,
         * not a silent loss: the run log is the record of live changes */
        fprintf(run.log, "%s\n", line);
        int bad = ferror(run.log);
        if (fclose(run.log) != 0) bad = 1;
        if (bad) {
            fprintf(stderr, "lamina watch: cannot write the log '%s': %s\n", o->log,
                    strerror(errno ? errno : EIO));
            if (status == LAMINA_EXIT_OK) status = LAMINA_EXIT_USAGE;
        }
    }
    return status;
}

/* Sleeps until the file differs from *sig (updating it). No run is in
 * progress here, so Ctrl-C has its default action: the watch ends. */
static void wait_for_change(const watch_opts *o, wb_file_sig *sig)
{
    int missing = 0;
    for (;;) {
        struct timespec ts = {(time_t)o->interval,
                              (long)((o->interval - (double)(time_t)o->interval) * 1e9)};
        nanosleep(&ts, NULL);
        wb_file_sig now;
        wb_file_sig_read(o->proto.script, &now);
        if (!now.ok) {
            if (!missing) fprintf(stderr, "lamina watch: waiting for '%s' to come back\n",
                                  o->proto.script);
            missing = 1;
            continue;
        }
        if (!wb_file_sig_same(&now, sig)) {
            *sig = now;
            return;
        }
    }
}

int cmd_watch(int argc, char **argv)
{
    watch_opts o;
    memset(&o, 0, sizeof o);
    o.interval = 0.25;
    o.proto.sets = calloc((size_t)argc + 1, sizeof *o.proto.sets);
    if (!o.proto.sets) return LAMINA_EXIT_USAGE;
    if (parse_args(argc, argv, &o)) {
        wb_free_sets(&o.proto);
        return LAMINA_EXIT_USAGE;
    }
    watch_poll poll = {.path = o.proto.script};
    wb_file_sig_read(o.proto.script, &poll.sig);
    if (!poll.sig.ok) {
        perror(o.proto.script);
        fprintf(stderr, "lamina watch: cannot read script '%s'\n", o.proto.script);
        wb_free_sets(&o.proto);
        return LAMINA_EXIT_USAGE;
    }
    fprintf(stderr, "lamina watch: running '%s' now and after every change (Ctrl-C ends)\n",
            o.proto.script);
    int status = LAMINA_EXIT_OK;
    for (long k = 1;; k++) {
        int stopped = LAMINA_STOP_NONE;
        status = run_once(&o, k, &poll, &stopped);
        if (stopped == LAMINA_STOP_SIGINT) {
            status = 130;
            break;
        }
        if (o.max_runs && k >= o.max_runs) break;
        if (stopped == LAMINA_STOP_POLL) poll.sig = poll.now;
        else wait_for_change(&o, &poll.sig);
    }
    wb_free_sets(&o.proto);
    lr_shutdown();
    return status;
}
