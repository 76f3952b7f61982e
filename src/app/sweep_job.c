/* sweep_job.c - one run of a sweep: an independent `lamina run` process in
 * its own folder.
 *
 * The process starts in the folder (relative frame paths land there), gets
 * the script by its absolute path (require() still finds modules beside
 * it), its parameters as --set, --set out=FOLDER when the script reads a
 * parameter "out", and --report FOLDER/report.json; its stdout and stderr
 * go to stdout.txt and stderr.txt. run.txt records the parameters, then the
 * exit status and wall time, so that `--collect` can rebuild the summary
 * from the folders alone (runs spread by GNU parallel or Slurm). */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "atomic_file.h"
#include "read_file.h"
#include "sweep.h"
#include "workbench.h"

/* Does the script read lamina.param("out", ...)? (its text, quoted with
 * either quote, spaces allowed) */
static int reads_out_param(const char *path)
{
    char *buf, err[64];
    int found = 0;
    if (lr_read_file(path, LR_READ_MAX, &buf, NULL, err, sizeof err) != 0) return 0;
    for (char *p = strstr(buf, "param"); p && !found; p = strstr(p + 5, "param")) {
        const char *q = p + 5;
        while (*q == ' ' || *q == '\t') q++;
        if (*q++ != '(') continue;
        while (*q == ' ' || *q == '\t') q++;
        char quote = *q;
        if (quote != '"' && quote != '\'') continue;
        found = strncmp(q + 1, "out", 3) == 0 && q[4] == quote;
    }
    free(buf);
    return found;
}

int sw_context_init(sw_context *c, const char *script, int user_sets_out, int quiet)
{
    memset(c, 0, sizeof *c);
    ssize_t n = readlink("/proc/self/exe", c->exe, sizeof c->exe - 1);
    if (n <= 0 || (size_t)n >= sizeof c->exe - 1) {
        fprintf(stderr, "lamina sweep: cannot find this program through /proc/self/exe: %s\n",
                strerror(errno));
        return -1;
    }
    c->exe[n] = 0;
    char *abs = wb_absolute(script);
    if (!abs || strlen(abs) >= sizeof c->script || access(abs, R_OK) != 0) {
        fprintf(stderr, "lamina sweep: cannot read script '%s': %s\n", script,
                strerror(!abs ? ENOMEM : strlen(abs) >= sizeof c->script ? ENAMETOOLONG : errno));
        free(abs);
        return -1;
    }
    strcpy(c->script, abs);
    free(abs);
    c->add_out = !user_sets_out && reads_out_param(c->script);
    c->quiet = quiet;
    return 0;
}

int sw_mkdirs(const char *path)
{
    char *p = strdup(path);
    if (!p) return -1;
    for (char *s = p + 1;; s++) {
        if (*s != '/' && *s != '\0') continue;
        char keep = *s;
        *s = '\0';
        if (mkdir(p, 0777) != 0 && errno != EEXIST) {
            free(p);
            return -1;
        }
        *s = keep;
        if (!keep) break;
    }
    free(p);
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode) ? 0 : -1;
}

static char *join(const char *folder, const char *file)
{
    size_t n = strlen(folder) + strlen(file) + 2;
    char *p = malloc(n);
    if (p) snprintf(p, n, "%s/%s", folder, file);
    return p;
}

static int write_record(const sw_context *c, const sw_job *job, const char *status,
                        double wall)
{
    char *path = join(job->folder, SW_RECORD);
    if (!path) return -1;
    char err[512];
    lr_atomic a;
    int rc = lr_atomic_open(&a, path, err, sizeof err);
    if (rc == 0) {
        fprintf(a.fp, "lamina sweep run\nscript %s\n", c->script);
        for (int i = 0; i < job->nsets; i++)
            fprintf(a.fp, "set %s=%s\n", job->sets[i].name, job->sets[i].value);
        fprintf(a.fp, "status %s\n", status);
        if (wall >= 0) fprintf(a.fp, "wall %.3f\n", wall);
        rc = lr_atomic_commit(&a, err, sizeof err);
    }
    if (rc) fprintf(stderr, "lamina sweep: %s\n", err);
    free(path);
    return rc;
}

/* argv of `lamina run` for the job (NULL-terminated, malloc'd strings). */
static char **run_argv(const sw_context *c, const sw_job *job)
{
    int max = 10 + 2 * job->nsets;   /* exe run script, --set pairs, out, report, quiet, NULL */
    char **argv = calloc((size_t)max, sizeof *argv);
    if (!argv) return NULL;
    int k = 0;
    argv[k++] = strdup(c->exe);
    argv[k++] = strdup("run");
    argv[k++] = strdup(c->script);
    for (int i = 0; i < job->nsets; i++) {
        size_t n = strlen(job->sets[i].name) + strlen(job->sets[i].value) + 2;
        argv[k++] = strdup("--set");
        if ((argv[k] = malloc(n)))
            snprintf(argv[k], n, "%s=%s", job->sets[i].name, job->sets[i].value);
        k++;
    }
    if (c->add_out) {
        size_t n = strlen(job->folder) + 5;
        argv[k++] = strdup("--set");
        if ((argv[k] = malloc(n))) snprintf(argv[k], n, "out=%s", job->folder);
        k++;
    }
    argv[k++] = strdup("--report");
    argv[k++] = join(job->folder, SW_REPORT);
    if (c->quiet) argv[k++] = strdup("--quiet");
    for (int i = 0; i < k; i++)
        if (!argv[i]) {
            for (int j = 0; j < k; j++) free(argv[j]);
            free(argv);
            return NULL;
        }
    return argv;
}

static void free_argv(char **argv)
{
    for (int i = 0; argv && argv[i]; i++) free(argv[i]);
    free(argv);
}

/* In the child: into the folder, output to its files, then exec. */
static void exec_child(const sw_job *job, char **argv)
{
    if (chdir(job->folder) != 0) _exit(127);
    int out = open(SW_STDOUT, O_WRONLY | O_CREAT | O_TRUNC, 0666);
    int err = open(SW_STDERR, O_WRONLY | O_CREAT | O_TRUNC, 0666);
    if (out < 0 || err < 0 || dup2(out, STDOUT_FILENO) < 0 || dup2(err, STDERR_FILENO) < 0)
        _exit(127);
    close(out);
    close(err);
    execv(argv[0], argv);
    fprintf(stderr, "lamina sweep: cannot execute '%s': %s\n", argv[0], strerror(errno));
    _exit(127);
}

int sw_job_start(const sw_context *c, sw_job *job)
{
    if (sw_mkdirs(job->folder) != 0) {
        fprintf(stderr, "lamina sweep: cannot create the folder '%s': %s\n", job->folder,
                strerror(errno));
        return -1;
    }
    char *report = join(job->folder, SW_REPORT);
    if (report) unlink(report);   /* a report from an earlier sweep is not this run's */
    free(report);
    if (write_record(c, job, "unfinished", -1)) return -1;
    char **argv = run_argv(c, job);
    if (!argv) {
        fprintf(stderr, "lamina sweep: out of memory\n");
        return -1;
    }
    fflush(stdout);
    fflush(stderr);
    job->start = wb_now();
    pid_t pid = fork();
    if (pid == 0) exec_child(job, argv);
    free_argv(argv);
    if (pid < 0) {
        fprintf(stderr, "lamina sweep: cannot start a run: %s\n", strerror(errno));
        return -1;
    }
    job->pid = pid;
    return 0;
}

void sw_job_finish(const sw_context *c, sw_job *job, int wstatus)
{
    job->wall = wb_now() - job->start;
    if (WIFEXITED(wstatus)) {
        snprintf(job->status, sizeof job->status, "%d", WEXITSTATUS(wstatus));
        job->ok = WEXITSTATUS(wstatus) == 0;
    } else {
        snprintf(job->status, sizeof job->status, "signal %d",
                 WIFSIGNALED(wstatus) ? WTERMSIG(wstatus) : 0);
        job->ok = 0;
    }
    job->pid = 0;
    write_record(c, job, job->status, job->wall);
}

/* Issue 31 item 2: a name that goes into a shell line (the jobs file,
 * whose line k is task k's command, and the sbatch script's header) may
 * hold no control character - a newline would start a line of its own,
 * run by `eval` or outside the comment it was meant for - and a file name
 * no quote (quotes = 0; a --set value may hold one: "it's yes").
 * Everything else is quoted by sw_shell_quote. 0, or -1 with the message
 * (the name shown with \ddd for control characters). */
int sw_shell_safe(const char *what, const char *s, int quotes)
{
    const char *p = s;
    while (*p && (unsigned char)*p >= 0x20 && *p != 0x7f &&
           (quotes || (*p != '\'' && *p != '"')))
        p++;
    if (!*p) return 0;
    fprintf(stderr, "lamina sweep: %s '", what);
    for (const char *q = s; *q; q++) {
        unsigned char ch = (unsigned char)*q;
        if (ch < 0x20 || ch == 0x7f) fprintf(stderr, "\\%d", ch);
        else fputc(ch, stderr);
    }
    fprintf(stderr, "' holds %s: refused, it would go into a shell line of the jobs\n",
            *p == '\'' || *p == '"' ? "a quote" : "a newline or another control character");
    return -1;
}

int sw_check_jobs(const sw_context *c, const sw_job *jobs, int njobs)
{
    if (sw_shell_safe("the program's path", c->exe, 0) ||
        sw_shell_safe("the script", c->script, 0))
        return -1;
    for (int i = 0; i < njobs; i++) {
        if (sw_shell_safe("a run's folder", jobs[i].folder, 0)) return -1;
        for (int k = 0; k < jobs[i].nsets; k++)
            if (sw_shell_safe("a --set name", jobs[i].sets[k].name, 1) ||
                sw_shell_safe("a --set value", jobs[i].sets[k].value, 1))
                return -1;
    }
    return 0;
}

void sw_shell_quote(FILE *out, const char *s)
{
    int plain = *s != '\0';
    for (const char *p = s; *p && plain; p++)
        plain = strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                       "_-+=,./:@%", *p) != NULL;
    if (plain) {
        fputs(s, out);
        return;
    }
    fputc('\'', out);
    for (const char *p = s; *p; p++) {
        if (*p == '\'') fputs("'\\''", out);
        else fputc(*p, out);
    }
    fputc('\'', out);
}

void sw_job_print_command(FILE *out, const sw_context *c, const sw_job *job)
{
    sw_shell_quote(out, c->exe);
    fputs(" sweep --job ", out);
    sw_shell_quote(out, job->folder);
    fputc(' ', out);
    sw_shell_quote(out, c->script);
    for (int i = 0; i < job->nsets; i++) {
        fputs(" --set ", out);
        size_t n = strlen(job->sets[i].name) + strlen(job->sets[i].value) + 2;
        char *kv = malloc(n);
        if (!kv) continue;
        snprintf(kv, n, "%s=%s", job->sets[i].name, job->sets[i].value);
        sw_shell_quote(out, kv);
        free(kv);
    }
    if (c->quiet) fputs(" --quiet", out);
    fputc('\n', out);
}
