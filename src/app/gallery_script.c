/* gallery_script.c - the figure scripts: which there are, what their header
 * comment says, and a hash that says when a figure must be made again.
 *
 * The header is the comment block at the top of the script:
 *
 *   -- title: Membrane inflation under gas pressure
 *   -- source: York, Sulsky & Schreyer 2000, Fig. 7
 *   -- look: the membrane bulges into a circular arc; ...
 *   --   (a line without a key continues the field above)
 *   -- checks: the final radius against the paper's 0.61
 *
 * Keys: title, source, look, checks, assumed, thumb, visual. A key given
 * twice continues too; an empty comment line ends a field; the header ends
 * at the first line that is not a comment. */
#include "gallery.h"
#include "util.h"

#include <ctype.h>
#include <fnmatch.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Appends text to *field, a space between. */
static void append(char **field, const char *text, size_t n)
{
    char *old = *field;
    *field = old ? g_fmt("%s %.*s", old, (int)n, text) : g_fmt("%.*s", (int)n, text);
    free(old);
}

/* The field a "key:" names, or NULL when the line starts with no known key. */
static char **field_for(g_header *h, const char *line, size_t n, size_t *skip)
{
    static const char *const keys[] = { "title", "source", "look", "checks",
                                        "assumed", "thumb", "visual", "heavy" };
    char **fields[] = { &h->title, &h->source, &h->look, &h->checks,
                        &h->assumed, &h->thumb, &h->visual, &h->heavy };
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++) {
        size_t m = strlen(keys[k]);
        if (n > m && strncmp(line, keys[k], m) == 0 && line[m] == ':') {
            *skip = m + 1;
            return fields[k];
        }
    }
    return NULL;
}

static void parse_header(const char *text, g_header *h)
{
    const char *p = text;
    char **current = NULL;
    if (p[0] == '#')                        /* a #! line, which Lua skips too */
        p += strcspn(p, "\n") + (p[strcspn(p, "\n")] == '\n');
    while (p[0] == '-' && p[1] == '-' && strncmp(p, "--[[", 4) != 0) {
        size_t len = strcspn(p, "\n");
        const char *line = p + 2;
        size_t n = len - 2;
        while (n && (*line == ' ' || *line == '\t')) {
            line++;
            n--;
        }
        while (n && isspace((unsigned char)line[n - 1]))
            n--;
        size_t skip = 0;
        char **f = field_for(h, line, n, &skip);
        if (f) {
            current = f;
            line += skip;
            n -= skip;
            while (n && (*line == ' ' || *line == '\t')) {
                line++;
                n--;
            }
            if (n)
                append(current, line, n);
        } else if (n == 0) {
            current = NULL;
        } else if (current) {
            append(current, line, n);
        }
        p += len + (p[len] == '\n');
    }
}

static int load(g_script *s, char *err, size_t errlen)
{
    char *text;
    size_t len;
    if (g_read_file(s->path, &text, &len, err, errlen) != 0)
        return -1;
    parse_header(text, &s->h);
    /* the same FNV-1a as `lamina run` stamps into every PNG */
    uint64_t h = lu_fnv1a(LU_FNV_SEED, text, len);
    lu_hash_hex(h, s->script_hash);
    static const char version[] = "\nlamina " LAMINA_VERSION;
    h = lu_fnv1a(h, version, sizeof version - 1);
    lu_hash_hex(h, s->hash);
    free(text);
    return 0;
}

int g_find_scripts(const char *dir, const char *only, g_scripts *out, char *err,
                   size_t errlen)
{
    memset(out, 0, sizeof *out);
    if (!g_is_dir(dir)) {
        snprintf(err, errlen, "scripts folder '%s' does not exist", dir);
        return -1;
    }
    g_strs files = { 0 };
    if (g_list_files(dir, &files, err, errlen) != 0)
        return -1;
    out->v = g_alloc((files.n ? files.n : 1) * sizeof *out->v);
    int rc = 0;
    for (size_t i = 0; rc == 0 && i < files.n; i++) {
        const char *f = files.v[i];
        /* the folder itself only: helpers in sub-folders are not figures */
        if (strchr(f, '/') || !g_has_suffix(f, ".lua") || f[0] == '.')
            continue;
        char *stem = g_fmt("%.*s", (int)(strlen(f) - 4), f);
        if (only && fnmatch(only, stem, 0) != 0) {
            free(stem);
            continue;
        }
        g_script *s = &out->v[out->n++];
        s->stem = stem;
        s->path = g_fmt("%s/%s", dir, f);
        rc = load(s, err, errlen);
    }
    g_strs_free(&files);
    if (rc != 0)
        g_scripts_free(out);
    return rc;
}

void g_scripts_free(g_scripts *s)
{
    for (size_t i = 0; i < s->n; i++) {
        g_script *x = &s->v[i];
        free(x->stem);
        free(x->path);
        free(x->h.title);
        free(x->h.source);
        free(x->h.look);
        free(x->h.checks);
        free(x->h.assumed);
        free(x->h.thumb);
        free(x->h.visual);
        free(x->h.heavy);
    }
    free(s->v);
    s->v = NULL;
    s->n = 0;
}

void g_visual_sets(const g_script *s, g_strs *out)
{
    const char *p = s->h.visual;
    while (p && *p) {
        p += strspn(p, " \t,");
        size_t n = strcspn(p, " \t,");
        if (n)
            g_strs_add(out, g_fmt("%.*s", (int)n, p));
        p += n;
    }
}
