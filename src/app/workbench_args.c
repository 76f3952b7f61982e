/* workbench_args.c - command-line pieces shared by repl, watch and sweep. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "workbench.h"
#include "util.h"

int wb_option(const char *cmd, int argc, char **argv, int *i, const char *name,
              const char **val)
{
    const char *v;
    if (!lu_opt_value(argc, argv, i, name, &v)) return 0;
    if (!v) {
        fprintf(stderr, "lamina %s: %s needs a value (try 'lamina help')\n", cmd, name);
        return -1;
    }
    *val = v;
    return 1;
}

int wb_options(const char *cmd, int argc, char **argv, int *i, int n,
               const char *const names[], const char **const slots[])
{
    for (int k = 0; k < n; k++) {
        int got = wb_option(cmd, argc, argv, i, names[k], slots[k]);
        if (got) return got;
    }
    return 0;
}

int wb_word(const char *cmd, const char *a, int *quiet, const char **script,
            const char *usage)
{
    if (quiet && (strcmp(a, "--quiet") == 0 || strcmp(a, "-q") == 0)) {
        *quiet = 1;
    } else if (a[0] == '-' && a[1]) {
        if (usage)
            fprintf(stderr, "lamina %s: unknown option '%s'\n%s\n", cmd, a, usage);
        else
            fprintf(stderr, "lamina %s: unknown option '%s' (try 'lamina help')\n", cmd, a);
        return -1;
    } else if (*script) {
        fprintf(stderr, "lamina %s: more than one script given ('%s', '%s')\n", cmd, *script,
                a);
        return -1;
    } else {
        *script = a;
    }
    return 0;
}

int wb_add_set(const char *cmd, lamina_run *run, const char *kv)
{
    const char *eq = strchr(kv, '=');
    if (!eq || eq == kv) {
        fprintf(stderr, "lamina %s: --set needs name=value (got '%s')\n", cmd, kv);
        return -1;
    }
    size_t n = (size_t)(eq - kv);
    for (int k = 0; k < run->nsets; k++)
        if (strlen(run->sets[k].name) == n && strncmp(run->sets[k].name, kv, n) == 0) {
            fprintf(stderr, "lamina %s: --set %.*s given twice\n", cmd, (int)n, kv);
            return -1;
        }
    char *name = malloc(n + 1);
    if (!name) {
        fprintf(stderr, "lamina %s: out of memory\n", cmd);
        return -1;
    }
    memcpy(name, kv, n);
    name[n] = 0;
    lamina_set *s = &run->sets[run->nsets++];
    s->name = name;
    s->value = eq + 1;
    s->used = 0;
    return 0;
}

void wb_free_sets(lamina_run *run)
{
    for (int i = 0; i < run->nsets; i++) free((char *)run->sets[i].name);
    free(run->sets);
    run->sets = NULL;
    run->nsets = 0;
}

int wb_count(const char *cmd, const char *opt, const char *s, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (end == s || *end || errno || v < lo || v > hi) {
        fprintf(stderr, "lamina %s: %s must be a whole number in [%ld, %ld] (got '%s')\n",
                cmd, opt, lo, hi, s);
        return -1;
    }
    *out = v;
    return 0;
}

int wb_number(const char *cmd, const char *opt, const char *s, double lo, double hi,
              double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end || errno || !(v >= lo && v <= hi)) {
        fprintf(stderr, "lamina %s: %s must be a number in [%g, %g] (got '%s')\n", cmd, opt,
                lo, hi, s);
        return -1;
    }
    *out = v;
    return 0;
}

char *wb_absolute(const char *path)
{
    if (path[0] == '/') return strdup(path);
    char cwd[4096];
    if (!getcwd(cwd, sizeof cwd)) return NULL;
    const char *rel = strncmp(path, "./", 2) == 0 ? path + 2 : path;
    size_t n = strlen(cwd) + strlen(rel) + 2;
    char *p = malloc(n);
    if (p) snprintf(p, n, "%s/%s", cwd, rel);
    return p;
}

double wb_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void wb_file_sig_read(const char *path, wb_file_sig *sig)
{
    memset(sig, 0, sizeof *sig);
    struct stat st;
    FILE *f = fopen(path, "rb");
    if (!f) return;
    if (fstat(fileno(f), &st) != 0 || !S_ISREG(st.st_mode)) {
        fclose(f);
        return;
    }
    uint64_t h = LU_FNV_SEED;
    unsigned char buf[65536];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0)
        h = lu_fnv1a(h, buf, n);
    sig->ok = !ferror(f);
    fclose(f);
    sig->size = (long long)st.st_size;
    sig->mtime_ns = (long long)st.st_mtim.tv_sec * 1000000000ll + st.st_mtim.tv_nsec;
    sig->hash = h;
}

int wb_file_sig_same(const wb_file_sig *a, const wb_file_sig *b)
{
    return a->ok == b->ok && a->size == b->size && a->mtime_ns == b->mtime_ns &&
           a->hash == b->hash;
}
