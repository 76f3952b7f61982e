/* stale_temp.c - see stale_temp.h. */
#include "stale_temp.h"

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define MAX_SWEPT 64   /* folders remembered as swept; past that, no sweeping */

static const char *host(void)
{
    static char name[128];
    if (!name[0] && (gethostname(name, sizeof name - 1) != 0 || !name[0]))
        strcpy(name, "localhost");
    for (char *c = name; *c; c++)   /* a name part, whatever the host is called */
        if (*c == '/' || *c == ' ') *c = '_';
    return name;
}

char *lr_temp_template(const char *path)
{
    size_t n = strlen(path) + strlen(host()) + 48;
    char *t = malloc(n);
    if (t) snprintf(t, n, "%s.tmp.%s.%ld.XXXXXX", path, host(), (long)getpid());
    return t;
}

/* The pid of a temporary of this host named name, or 0. */
static long owner(const char *name)
{
    char marker[160];
    snprintf(marker, sizeof marker, ".tmp.%s.", host());
    const char *m = NULL;
    for (const char *p = strstr(name, marker); p; p = strstr(p + 1, marker)) m = p;
    if (!m) return 0;
    const char *d = m + strlen(marker);
    char *end;
    long pid = strtol(d, &end, 10);
    if (end == d || *end != '.' || strlen(end + 1) != 6 || pid <= 0) return 0;
    return pid;
}

static int swept(const char *dir)
{
    static char *seen[MAX_SWEPT];
    static int n;
    for (int i = 0; i < n; i++)
        if (strcmp(seen[i], dir) == 0) return 1;
    if (n == MAX_SWEPT) return 1;
    seen[n] = strdup(dir);
    if (seen[n]) n++;
    return 0;
}

void lr_remove_stale_temps(const char *path)
{
    const char *slash = strrchr(path, '/');
    char dir[4096];
    if (!slash) snprintf(dir, sizeof dir, ".");
    else if (slash == path) snprintf(dir, sizeof dir, "/");
    else snprintf(dir, sizeof dir, "%.*s", (int)(slash - path), path);
    if (swept(dir)) return;
    DIR *d = opendir(dir);
    if (!d) return;
    struct dirent *e;
    while ((e = readdir(d))) {
        long pid = owner(e->d_name);
        if (!pid || pid == (long)getpid()) continue;
        if (kill((pid_t)pid, 0) == 0 || errno != ESRCH) continue;   /* alive, or unknown */
        char file[8192];
        snprintf(file, sizeof file, "%s/%s", dir, e->d_name);
        struct stat st;
        if (lstat(file, &st) == 0 && S_ISREG(st.st_mode)) unlink(file);
    }
    closedir(d);
}
