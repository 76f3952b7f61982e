/* gallery_json.c - the gallery's own JSON files: the report that
 * `lamina run --report` writes and each figure's meta.json, read through
 * the one reader (lu_json_parse, src/util/lu_json.c) and written here.
 * Numbers keep the text they were written with, so a value passes from
 * report.json into meta.json unchanged (no round trip through printf). */
#include "gallery.h"

#include <stdlib.h>
#include <string.h>

lu_json *gj_read(const char *path, char *err, size_t errlen)
{
    char *text;
    if (g_read_file(path, &text, NULL, err, errlen) != 0)
        return NULL;
    char why[256];
    lu_json *v = lu_json_parse(text, why, sizeof why);
    free(text);
    if (!v && err && errlen)
        snprintf(err, errlen, "%s: not valid JSON: %s", path, why);
    return v;
}

void gj_put_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '"' || *p == '\\')
            fprintf(f, "\\%c", *p);
        else if (*p == '\n')
            fputs("\\n", f);
        else if (*p < 0x20 || *p == 0x7f)
            fprintf(f, "\\u%04x", *p);
        else
            fputc(*p, f);
    }
    fputc('"', f);
}

/* Scalars and arrays of scalars-or-small-objects stay on one line; an
 * object holding arrays or objects gets one member per line. */
static int is_flat(const lu_json *v)
{
    for (size_t i = 0; i < v->n; i++)
        if (v->kids[i].type == LU_JSON_ARRAY || v->kids[i].type == LU_JSON_OBJECT)
            return 0;
    return 1;
}

void gj_put(FILE *f, const lu_json *v, int indent)
{
    switch (v->type) {
    case LU_JSON_NULL: fputs("null", f); return;
    case LU_JSON_BOOL: fputs(v->boolean ? "true" : "false", f); return;
    case LU_JSON_NUMBER: fputs(v->text, f); return;
    case LU_JSON_STRING: gj_put_string(f, v->text); return;
    case LU_JSON_ARRAY:
    case LU_JSON_OBJECT: break;
    }
    int obj = v->type == LU_JSON_OBJECT;
    int flat = is_flat(v);
    fputc(obj ? '{' : '[', f);
    for (size_t i = 0; i < v->n; i++) {
        if (i)
            fputc(',', f);
        if (flat)
            fputs(i ? " " : "", f);
        else
            fprintf(f, "\n%*s", indent + 2, "");
        if (obj) {
            gj_put_string(f, v->kids[i].key);
            fputs(": ", f);
        }
        gj_put(f, &v->kids[i], indent + 2);
    }
    if (!flat && v->n)
        fprintf(f, "\n%*s", indent, "");
    fputc(obj ? '}' : ']', f);
}
