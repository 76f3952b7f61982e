/* gallery_run.c - one figure script run as `lamina run`, in a child process.
 *
 * A subprocess, not an in-process Lua state: a script that fails, leaks or
 * crashes takes only its own figure down, its output goes to its own log,
 * and what runs is exactly what a person gets from `lamina run`. The binary
 * is /proc/self/exe, this very program, whatever the PATH says. */
/* wait4(2), a child's own processor time (BSD and Linux; not in POSIX) */
#define _DEFAULT_SOURCE
#include "gallery.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double run_limit = G_RUN_LIMIT;

void g_run_set_limit(double seconds)
{
    run_limit = seconds;
}

double g_run_limit(void)
{
    return run_limit;
}

int g_run_start(const g_script *s, const char *out, const char *report, const char *log,
                const char *const *sets, int nsets, g_child *c, char *err, size_t errlen)
{
    /* everything the child needs is built before fork: after it, the child
     * may only call async-signal-safe functions */
    int argc = 0;
    char **argv = g_alloc((size_t)(12 + 2 * nsets) * sizeof *argv);
    char *set_out = g_fmt("out=%s", out);
    argv[argc++] = "lamina";
    argv[argc++] = "run";
    argv[argc++] = s->path;
    argv[argc++] = "--set";
    argv[argc++] = set_out;
    argv[argc++] = "--report";
    argv[argc++] = (char *)report;
    argv[argc++] = "--out-root";   /* the script writes into out, wherever it is */
    argv[argc++] = (char *)out;
    for (int i = 0; i < nsets; i++) {
        argv[argc++] = "--set";
        argv[argc++] = (char *)sets[i];
    }
    argv[argc++] = "--quiet";
    argv[argc] = NULL;

    int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) {
        snprintf(err, errlen, "cannot write '%s': %s", log, strerror(errno));
        free(argv);
        free(set_out);
        return -1;
    }
    fflush(NULL);   /* or the child would flush our buffered output again */
    c->t0 = now();
    c->sent = 0;
    pid_t pid = fork();
    if (pid == 0) {
        dup2(fd, STDOUT_FILENO);
        dup2(fd, STDERR_FILENO);
        execv("/proc/self/exe", argv);
        static const char msg[] = "lamina gallery: cannot run /proc/self/exe\n";
        ssize_t ignored = write(STDERR_FILENO, msg, sizeof msg - 1);
        (void)ignored;
        _exit(127);
    }
    int e = errno;
    close(fd);
    free(argv);
    free(set_out);
    if (pid < 0) {
        snprintf(err, errlen, "cannot start a process: %s", strerror(e));
        return -1;
    }
    c->pid = (int)pid;
    return 0;
}

int g_run_poll(g_child *c, g_run_result *r, char *err, size_t errlen)
{
    /* a figure has run_limit seconds: then SIGTERM (lamina run stops at a
     * step boundary and writes what it recorded), and SIGKILL 10 s later
     * for a script stuck where no step boundary comes */
    int status;
    struct rusage ru;
    pid_t got = wait4((pid_t)c->pid, &status, WNOHANG, &ru);
    if (got < 0 && errno != EINTR) {
        snprintf(err, errlen, "cannot wait for the run: %s", strerror(errno));
        return -1;
    }
    if (got != (pid_t)c->pid) {
        double t = now() - c->t0;
        if (!c->sent && t > run_limit) {
            kill((pid_t)c->pid, SIGTERM);
            c->sent = 1;
        } else if (c->sent == 1 && t > run_limit + 10) {
            kill((pid_t)c->pid, SIGKILL);
            c->sent = 2;
        }
        return 0;
    }
    r->seconds = now() - c->t0;
    /* the child's own processor time (its threads', not other figures'):
     * what the queue orders the next run by, whatever the load was */
    r->cpu_seconds = (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec +
                     (double)ru.ru_stime.tv_sec + 1e-6 * (double)ru.ru_stime.tv_usec;
    r->timed_out = c->sent > 0;
    r->status = WIFEXITED(status) ? WEXITSTATUS(status)
                                  : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    return 1;
}

void g_run_nap(void)
{
    struct timespec nap = {0, 20 * 1000 * 1000};
    nanosleep(&nap, NULL);
}

int g_run(const g_script *s, const char *out, const char *report, const char *log,
          const char *const *sets, int nsets, g_run_result *r, char *err, size_t errlen)
{
    g_child c;
    if (g_run_start(s, out, report, log, sets, nsets, &c, err, errlen) != 0)
        return -1;
    for (;;) {
        int done = g_run_poll(&c, r, err, errlen);
        if (done)
            return done < 0 ? -1 : 0;
        g_run_nap();
    }
}

void g_show_log_tail(const char *log, int lines)
{
    char *text;
    size_t len;
    if (g_read_file(log, &text, &len, NULL, 0) != 0)
        return;
    while (len && text[len - 1] == '\n')
        len--;
    size_t start = len;
    for (int k = 0; start > 0; start--)
        if (text[start - 1] == '\n' && ++k == lines)
            break;
    for (size_t i = start; i < len;) {
        size_t n = strcspn(text + i, "\n");
        if (i + n > len)
            n = len - i;
        fprintf(stderr, "    %.*s\n", (int)n, text + i);
        i += n + 1;
    }
    free(text);
}
