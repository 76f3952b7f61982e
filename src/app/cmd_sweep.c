/* cmd_sweep.c - `lamina sweep`: a scenario over the Cartesian product of
 * parameter values, each run an independent `lamina run` process in its
 * own folder, and a table of what the runs reported (docs/workbench.md).
 *
 *   lamina sweep SCRIPT.lua --set name=v1,v2,... [--set ...] [--jobs N]
 *                [--out DIR] [--emit-jobs] [--quiet]
 *   lamina sweep --collect DIR
 *   lamina sweep --job FOLDER SCRIPT.lua [--set name=value ...] [--quiet]
 *
 * --emit-jobs prints one `--job` command per run instead of running them
 * (for GNU parallel or a Slurm job array); `--collect DIR` then builds the
 * summary from the folders. A failed run does not stop the others. Exit
 * status: 0 every run succeeded, 1 some failed, 2 a command-line mistake. */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "app.h"
#include "sweep.h"
#include "workbench.h"

static const char usage_text[] =
    "usage: lamina sweep SCRIPT.lua --set name=v1,v2,... [--set ...] [--jobs N]\n"
    "                    [--out DIR] [--emit-jobs | --slurm FILE] [--quiet]\n"
    "       lamina sweep --collect DIR\n"
    "       lamina sweep --job FOLDER SCRIPT.lua [--set name=value ...] [--quiet]";

typedef struct sweep_param {
    const char *name;    /* points into nameval */
    char *nameval;       /* "name\0v1\0v2..." */
    const char **values;
    int n;
} sweep_param;

typedef struct sweep_opts {
    const char *script, *out, *collect, *job;
    sweep_param *params;
    int np;
    long jobs;
    int emit, quiet, has_jobs;
    const char *slurm;      /* --slurm FILE: an sbatch script instead of running */
} sweep_opts;

static int usage_error(const char *what, const char *arg)
{
    fprintf(stderr, "lamina sweep: ");
    fprintf(stderr, what, arg);
    fprintf(stderr, "\n%s\n", usage_text);
    return -1;
}

/* --set name=v1,v2,... (split: no in --job mode, where a value is whole). */
static int add_param(sweep_opts *o, const char *kv, int split)
{
    const char *eq = strchr(kv, '=');
    if (!eq || eq == kv) return usage_error("--set needs name=value (got '%s')", kv);
    if (strpbrk(kv, "\n\r")) return usage_error("--set %s: a line break is not allowed", kv);
    sweep_param *p = &o->params[o->np];
    memset(p, 0, sizeof *p);
    p->nameval = strdup(kv);
    p->values = calloc(strlen(kv) + 1, sizeof *p->values);
    if (!p->nameval || !p->values) {
        free(p->nameval);
        free(p->values);
        return usage_error("%s", "out of memory");
    }
    o->np++;
    char *s = p->nameval;
    s[eq - kv] = 0;
    p->name = s;
    for (int i = 0; i < o->np - 1; i++)
        if (strcmp(o->params[i].name, p->name) == 0)
            return usage_error("--set %s given twice", p->name);
    char *v = s + (eq - kv) + 1;
    p->values[p->n++] = v;
    for (; split && *v; v++)
        if (*v == ',') {
            *v = 0;
            p->values[p->n++] = v + 1;
        }
    return 0;
}

static void free_opts(sweep_opts *o)
{
    for (int i = 0; i < o->np; i++) {
        free(o->params[i].nameval);
        free(o->params[i].values);
    }
    free(o->params);
}

static int parse_args(int argc, char **argv, sweep_opts *o)
{
    static const char *const names[] = { "--out", "--collect", "--job", "--slurm" };
    const char **const slots[] = { &o->out, &o->collect, &o->job, &o->slurm };
    int job_mode = 0;
    for (int i = 0; i < argc; i++)
        if (strcmp(argv[i], "--job") == 0 || strncmp(argv[i], "--job=", 6) == 0) job_mode = 1;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *v;
        int got;
        if ((got = wb_option("sweep", argc, argv, &i, "--set", &v))) {
            if (got < 0 || add_param(o, v, !job_mode)) return -1;
        } else if ((got = wb_option("sweep", argc, argv, &i, "--jobs", &v))) {
            if (got < 0 || wb_count("sweep", "--jobs", v, 1, 4096, &o->jobs)) return -1;
            o->has_jobs = 1;
        } else if ((got = wb_options("sweep", argc, argv, &i, 4, names, slots))) {
            if (got < 0) return -1;
        } else if (strcmp(a, "--emit-jobs") == 0) {
            o->emit = 1;
        } else if (strcmp(a, "--quiet") == 0 || strcmp(a, "-q") == 0) {
            o->quiet = 1;
        } else if (a[0] == '-' && a[1]) {
            return usage_error("unknown option '%s'", a);
        } else if (!o->script) {
            o->script = a;
        } else {
            return usage_error("more than one script given ('%s')", a);
        }
    }
    if (o->collect) {
        if (o->script || o->np || o->job || o->emit || o->out || o->has_jobs || o->slurm)
            return usage_error("%s", "--collect DIR takes no script or other option");
        return 0;
    }
    if (!o->script) return usage_error("%s", "no script given");
    if (o->job && (o->emit || o->out || o->has_jobs || o->slurm))
        return usage_error("%s", "--job runs one run: --emit-jobs, --slurm, --out, --jobs do "
                                 "not apply");
    if (o->emit && o->slurm)
        return usage_error("%s", "give one of --emit-jobs and --slurm FILE");
    if (!o->job && !o->np) return usage_error("%s", "nothing to sweep: give --set name=v1,v2,...");
    return 0;
}

/* "name=value,..." of the swept parameters (those with several values),
 * characters other than letters, digits and ._+=,- replaced by _. */
static char *label_of(const sweep_opts *o, const int *pick)
{
    size_t n = 8;
    for (int i = 0; i < o->np; i++)
        n += strlen(o->params[i].name) + strlen(o->params[i].values[pick[i]]) + 2;
    char *s = malloc(n);
    if (!s) return NULL;
    s[0] = 0;
    for (int i = 0; i < o->np; i++) {
        if (o->params[i].n < 2) continue;
        if (s[0]) strcat(s, ",");
        strcat(s, o->params[i].name);
        strcat(s, "=");
        strcat(s, o->params[i].values[pick[i]]);
    }
    if (!s[0]) strcpy(s, "run");
    for (char *c = s; *c; c++)
        if (!strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._+=,-", *c))
            *c = '_';
    return s;
}

static void free_jobs(sw_job *jobs, int n)
{
    for (int i = 0; i < n; i++) {
        free(jobs[i].folder);
        free(jobs[i].sets);
    }
    free(jobs);
}

/* The Cartesian product, the first parameter varying slowest. */
static sw_job *plan(const sweep_opts *o, const char *outdir, int *njobs)
{
    long total = 1;
    for (int i = 0; i < o->np; i++) {
        total *= o->params[i].n;
        if (total > 100000) {
            usage_error("%s", "more than 100000 runs: is that meant?");
            return NULL;
        }
    }
    sw_job *jobs = calloc((size_t)total, sizeof *jobs);
    int *pick = calloc((size_t)o->np + 1, sizeof *pick);
    if (!jobs || !pick) {
        free(jobs);
        free(pick);
        return NULL;
    }
    for (long k = 0; k < total; k++) {
        sw_job *j = &jobs[k];
        char *label = label_of(o, pick);
        size_t n = strlen(outdir) + (label ? strlen(label) : 0) + 2;
        j->folder = label ? malloc(n) : NULL;
        j->sets = calloc((size_t)o->np + 1, sizeof *j->sets);
        if (!j->folder || !j->sets) {
            free(label);
            free(pick);
            free_jobs(jobs, (int)k + 1);
            return NULL;
        }
        snprintf(j->folder, n, "%s/%s", outdir, label);
        free(label);
        for (int i = 0; i < o->np; i++) {
            j->sets[i].name = o->params[i].name;
            j->sets[i].value = o->params[i].values[pick[i]];
        }
        j->nsets = o->np;
        for (long m = 0; m < k; m++)
            if (strcmp(jobs[m].folder, j->folder) == 0) {
                fprintf(stderr, "lamina sweep: two runs would share the folder '%s' (values "
                        "that differ only in characters a folder name cannot keep)\n",
                        j->folder);
                free(pick);
                free_jobs(jobs, (int)k + 1);
                return NULL;
            }
        for (int i = o->np - 1; i >= 0; i--) {   /* odometer */
            if (++pick[i] < o->params[i].n) break;
            pick[i] = 0;
        }
    }
    free(pick);
    *njobs = (int)total;
    return jobs;
}

static const char *base_name(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

static void say_done(const sw_job *j, int k, int n, int quiet)
{
    if (quiet) return;
    char prefix[32] = "";
    if (n > 0) snprintf(prefix, sizeof prefix, "[%d/%d] ", k, n);
    if (j->ok) {
        fprintf(stderr, "sweep: %s%s: ok in %.2f s\n", prefix, base_name(j->folder), j->wall);
        return;
    }
    sw_row row;
    int have = sw_row_load(j->folder, &row) == 0;
    fprintf(stderr, "sweep: %s%s: failed (status %s) in %.2f s%s%s\n", prefix,
            base_name(j->folder), j->status, j->wall, have && row.error ? ": " : "",
            have && row.error ? row.error : "");
    if (have) sw_row_free(&row);
}

/* SIGINT or SIGTERM to the sweep: no more runs start, the running ones get
 * SIGTERM (each stops at a step boundary and writes its records), the
 * sweep waits for them, writes its summary and exits 128 + the signal.
 * (A SIGTERM left the children running; issue 18.) */
static volatile sig_atomic_t stop_sig;

static void on_stop(int sig)
{
    stop_sig = sig;
}

static void catch_stops(struct sigaction *old_int, struct sigaction *old_term)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0;   /* no SA_RESTART: waitpid returns EINTR */
    sigaction(SIGINT, &sa, old_int);
    sigaction(SIGTERM, &sa, old_term);
}

/* Runs the jobs, at most `parallel` at a time; returns how many failed. */
static int run_all(const sw_context *c, sw_job *jobs, int n, long parallel, int quiet)
{
    int next = 0, running = 0, done = 0, failed = 0, forwarded = 0;
    struct sigaction old_int, old_term;
    catch_stops(&old_int, &old_term);
    while (done < n) {
        if (stop_sig && !forwarded) {
            for (int i = 0; i < n; i++)
                if (jobs[i].pid > 0) kill(jobs[i].pid, SIGTERM);
            forwarded = 1;
            /* even with --quiet: it says why runs are missing */
            fprintf(stderr, "sweep: stopping (%s): %d run%s stopped, %d not started\n",
                    stop_sig == SIGTERM ? "SIGTERM" : "SIGINT", running,
                    running == 1 ? "" : "s", n - next);
        }
        while (!stop_sig && running < parallel && next < n) {
            sw_job *j = &jobs[next++];
            if (sw_job_start(c, j) == 0) {
                running++;
            } else {
                snprintf(j->status, sizeof j->status, "not started");
                failed++;
                done++;
            }
        }
        if (!running) break;
        int ws;
        pid_t pid = waitpid(-1, &ws, 0);
        if (pid < 0) {
            if (errno == EINTR) continue;
            fprintf(stderr, "lamina sweep: waitpid: %s\n", strerror(errno));
            break;
        }
        for (int i = 0; i < n; i++) {
            if (jobs[i].pid != pid) continue;
            sw_job_finish(c, &jobs[i], ws);
            running--;
            done++;
            failed += !jobs[i].ok;
            say_done(&jobs[i], done, n, quiet);
            break;
        }
    }
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    return failed;
}

/* The table from the given folders (in this order). */
static int summarize(const char *outdir, const char *title, sw_job *jobs, int n)
{
    sw_row *rows = calloc((size_t)n + 1, sizeof *rows);
    if (!rows) return -1;
    int k = 0;
    for (int i = 0; i < n; i++)
        if (sw_row_load(jobs[i].folder, &rows[k]) == 0) k++;
    int rc = sw_summary_write(outdir, title, rows, k, stdout);
    for (int i = 0; i < k; i++) sw_row_free(&rows[i]);
    free(rows);
    return rc;
}

/* Does the folder hold a run record (even one that cannot be read)?
 * errno is left as access(2) sets it. */
static int has_record(const char *folder)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/%s", folder, SW_RECORD);
    struct stat st;
    if (lstat(path, &st) != 0) return 0;
    errno = 0;
    if (access(path, R_OK) == 0 && S_ISREG(st.st_mode)) errno = EFBIG;   /* over 1 MB */
    return 1;
}

static int collect(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "lamina sweep: --collect: cannot read the folder '%s': %s\n", dir,
                strerror(errno));
        return LAMINA_EXIT_USAGE;
    }
    sw_row *rows = NULL;
    int n = 0, cap = 0, failed = 0, unreadable = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.') continue;
        size_t len = strlen(dir) + strlen(e->d_name) + 2;
        char *folder = malloc(len);
        if (!folder) break;
        snprintf(folder, len, "%s/%s", dir, e->d_name);
        if (n == cap) {
            cap = cap ? 2 * cap : 16;
            sw_row *r = realloc(rows, (size_t)cap * sizeof *r);
            if (!r) {
                free(folder);
                break;
            }
            rows = r;
        }
        if (sw_row_load(folder, &rows[n]) == 0) {
            failed += !rows[n++].ok;
        } else if (has_record(folder)) {
            /* a run whose record cannot be read is not a success: it was
             * skipped and the sweep said "0 failed" (issue 18) */
            fprintf(stderr, "lamina sweep: --collect: cannot read '%s/%s': %s\n", folder,
                    SW_RECORD, errno ? strerror(errno) : "not a regular file");
            unreadable++;
        }
        free(folder);
    }
    closedir(d);
    if (!n) {
        free(rows);
        fprintf(stderr, "lamina sweep: --collect: no %srun folders (with %s) in '%s'\n",
                unreadable ? "readable " : "", SW_RECORD, dir);
        return LAMINA_EXIT_USAGE;
    }
    sw_rows_sort(rows, n);
    char title[512];
    snprintf(title, sizeof title, "Sweep in %s", dir);
    int rc = sw_summary_write(dir, title, rows, n, stdout);
    for (int i = 0; i < n; i++) sw_row_free(&rows[i]);
    free(rows);
    fprintf(stderr, "sweep: %d run%s, %d failed or unfinished%s; summary in %s/summary.md "
            "and summary.csv\n", n + unreadable, n + unreadable == 1 ? "" : "s",
            failed + unreadable, unreadable ? " (some unreadable)" : "", dir);
    if (rc) return LAMINA_EXIT_USAGE;
    return failed || unreadable ? 1 : 0;
}

/* --job FOLDER: one run, as --emit-jobs prints it. */
static int one_job(const sweep_opts *o, const sw_context *c)
{
    sw_job job;
    memset(&job, 0, sizeof job);
    job.folder = wb_absolute(o->job);
    job.sets = calloc((size_t)o->np + 1, sizeof *job.sets);
    if (!job.folder || !job.sets) {
        free(job.folder);
        free(job.sets);
        return LAMINA_EXIT_USAGE;
    }
    for (int i = 0; i < o->np; i++) {
        job.sets[i].name = o->params[i].name;
        job.sets[i].value = o->params[i].values[0];
    }
    job.nsets = o->np;
    int status = 1;
    if (sw_job_start(c, &job) == 0) {
        int ws;
        while (waitpid(job.pid, &ws, 0) < 0 && errno == EINTR) {}
        sw_job_finish(c, &job, ws);
        say_done(&job, 0, 0, o->quiet);
        status = WIFEXITED(ws) ? WEXITSTATUS(ws) : 1;
    }
    free(job.folder);
    free(job.sets);
    return status;
}

int cmd_sweep(int argc, char **argv)
{
    sweep_opts o;
    memset(&o, 0, sizeof o);
    o.params = calloc((size_t)argc + 1, sizeof *o.params);
    if (!o.params) return LAMINA_EXIT_USAGE;
    int status = LAMINA_EXIT_USAGE;
    int user_out = 0;
    sw_context c;
    char *outdir = NULL;
    sw_job *jobs = NULL;
    int njobs = 0;
    if (parse_args(argc, argv, &o)) goto done;
    if (o.collect) {
        status = collect(o.collect);
        goto done;
    }
    for (int i = 0; i < o.np; i++) user_out |= strcmp(o.params[i].name, "out") == 0;
    if (sw_context_init(&c, o.script, user_out, o.quiet)) goto done;
    if (o.job) {
        status = one_job(&o, &c);
        goto done;
    }
    if (o.out) {
        outdir = wb_absolute(o.out);
    } else {
        char def[512];
        snprintf(def, sizeof def, "sweep-%s", base_name(o.script));
        char *dot = strrchr(def, '.');
        if (dot && strcmp(dot, ".lua") == 0) *dot = 0;
        outdir = wb_absolute(def);
    }
    if (!outdir || !(jobs = plan(&o, outdir, &njobs))) goto done;
    /* the job lines are shell: refuse what quoting cannot carry (issue 31) */
    if ((o.emit || o.slurm) && sw_check_jobs(&c, jobs, njobs)) goto done;
    if (o.emit) {
        for (int i = 0; i < njobs; i++) sw_job_print_command(stdout, &c, &jobs[i]);
        status = fflush(stdout) == 0 ? 0 : LAMINA_EXIT_USAGE;
        goto done;
    }
    if (o.slurm) {
        status = sw_write_slurm(o.slurm, &c, jobs, njobs, outdir) == 0 ? 0 : LAMINA_EXIT_USAGE;
        goto done;
    }
    long parallel = o.has_jobs ? o.jobs : sysconf(_SC_NPROCESSORS_ONLN);
    if (parallel < 1) parallel = 1;
    if (!o.quiet)
        fprintf(stderr, "sweep: %d run%s of %s, %ld at a time, in %s\n", njobs,
                njobs == 1 ? "" : "s", base_name(c.script), parallel, outdir);
    int failed = run_all(&c, jobs, njobs, parallel, o.quiet);
    char title[4200];
    snprintf(title, sizeof title, "Sweep of %s", base_name(c.script));
    if (sw_mkdirs(outdir) != 0 || summarize(outdir, title, jobs, njobs) != 0) {
        status = LAMINA_EXIT_USAGE;
        goto done;
    }
    fprintf(stderr, "sweep: %d run%s, %d failed; summary in %s/summary.md and summary.csv\n",
            njobs, njobs == 1 ? "" : "s", failed, outdir);
    status = stop_sig ? 128 + stop_sig : failed ? 1 : 0;
done:
    free_jobs(jobs, njobs);
    free(outdir);
    free_opts(&o);
    return status;
}
