/* sweep_json.c - reading a run's report.json (written by lamina.report,
 * src/lua/l_report.c):
 *
 *   {"script": "...", "script_hash": "...",
 *    "values": [{"name": "gap", "value": 0.12, "paper": ..., ...}, ...]}
 *
 * Read whole by the one JSON reader (lu_json_parse, src/util/lu_json.c);
 * only the name and value of each entry of the top-level "values" array are
 * kept. Numbers are kept as written (the report writes the shortest exact
 * form). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "read_file.h"
#include "sweep.h"
#include "util.h"

/* A scalar's text (numbers as written, strings decoded), malloc'd; NULL
 * for objects and arrays or when out of memory. */
static char *scalar_text(const lu_json *v)
{
    const char *t;
    switch (v->type) {
    case LU_JSON_NUMBER:
    case LU_JSON_STRING: t = v->text; break;
    case LU_JSON_BOOL: t = v->boolean ? "true" : "false"; break;
    case LU_JSON_NULL: t = "null"; break;
    default: return NULL;
    }
    size_t n = strlen(t);
    char *out = malloc(n + 1);
    if (out) memcpy(out, t, n + 1);
    return out;
}

/* Appends s to the list of n; the capacity doubles at every power of two
 * (one realloc per value made long reports quadratic). */
static int push(char ***list, int n, char *s)
{
    if ((n & (n - 1)) == 0) {
        char **l = realloc(*list, (size_t)(n ? 2 * n : 1) * sizeof *l);
        if (!l) return -1;
        *list = l;
    }
    (*list)[n] = s;
    return 0;
}

/* A regular file of at most LR_READ_MAX bytes (a report linked to
 * /dev/zero was read for ever), or NULL. */
static char *slurp(const char *path)
{
    char *text, err[64];
    return lr_read_file(path, LR_READ_MAX, &text, NULL, err, sizeof err) == 0 ? text : NULL;
}

/* The first member named key of an object, as scalar_text, or NULL. */
static char *member_text(const lu_json *obj, const char *key)
{
    const lu_json *v = lu_json_get(obj, key);
    return v ? scalar_text(v) : NULL;
}

int sw_report_read(const char *path, char ***names, char ***values, int *n)
{
    *names = *values = NULL;
    *n = 0;
    char *text = slurp(path), err[64];
    if (!text) return -1;
    lu_json *doc = lu_json_parse(text, err, sizeof err);
    free(text);
    if (!doc || doc->type != LU_JSON_OBJECT) {
        lu_json_free(doc);
        return -1;
    }
    const lu_json *vals = lu_json_get(doc, "values");
    for (size_t k = 0; vals && vals->type == LU_JSON_ARRAY && k < vals->n; k++) {
        const lu_json *e = &vals->kids[k];
        if (e->type != LU_JSON_OBJECT) continue;   /* only {"name":, "value":} entries */
        char *name = member_text(e, "name"), *val = member_text(e, "value");
        if (!name || !val || push(names, *n, name) || push(values, *n, val)) {
            free(name);
            free(val);
            continue;
        }
        (*n)++;
    }
    lu_json_free(doc);
    return 0;
}
