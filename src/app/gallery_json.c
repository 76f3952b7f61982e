/* gallery_json.c - just enough JSON for the gallery's own files: the
 * report that `lamina run --report` writes and each figure's meta.json.
 *
 * A recursive-descent reader into a small tree, and a writer. Numbers keep
 * the text they were written with, so a value passes from report.json into
 * meta.json unchanged (no round trip through printf). Strings are kept as
 * UTF-8; \u escapes are decoded, surrogate pairs included. */
#include "gallery.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#define MAX_DEPTH 64    /* our files nest three deep; this only stops a bad file */

typedef struct reader {
    const char *p, *start;
    char *err;
    size_t errlen;
    int failed;
} reader;

static void fail(reader *r, const char *what)
{
    if (r->failed)
        return;
    r->failed = 1;
    /* line and column, for a person fixing the file */
    int line = 1, col = 1;
    for (const char *q = r->start; q < r->p; q++) {
        if (*q == '\n') {
            line++;
            col = 1;
        } else {
            col++;
        }
    }
    if (r->err && r->errlen)
        snprintf(r->err, r->errlen, "line %d, column %d: %s", line, col, what);
}

static void skip_space(reader *r)
{
    while (*r->p == ' ' || *r->p == '\t' || *r->p == '\n' || *r->p == '\r')
        r->p++;
}

static int hex4(const char *p, unsigned *out)
{
    unsigned v = 0;
    for (int i = 0; i < 4; i++) {
        char c = p[i];
        v <<= 4;
        if (c >= '0' && c <= '9') v |= (unsigned)(c - '0');
        else if (c >= 'a' && c <= 'f') v |= (unsigned)(c - 'a' + 10);
        else if (c >= 'A' && c <= 'F') v |= (unsigned)(c - 'A' + 10);
        else return -1;
    }
    *out = v;
    return 0;
}

static void put_utf8(FILE *f, unsigned cp)
{
    if (cp < 0x80) {
        fputc((int)cp, f);
    } else if (cp < 0x800) {
        fputc((int)(0xC0 | (cp >> 6)), f);
        fputc((int)(0x80 | (cp & 0x3F)), f);
    } else if (cp < 0x10000) {
        fputc((int)(0xE0 | (cp >> 12)), f);
        fputc((int)(0x80 | ((cp >> 6) & 0x3F)), f);
        fputc((int)(0x80 | (cp & 0x3F)), f);
    } else {
        fputc((int)(0xF0 | (cp >> 18)), f);
        fputc((int)(0x80 | ((cp >> 12) & 0x3F)), f);
        fputc((int)(0x80 | ((cp >> 6) & 0x3F)), f);
        fputc((int)(0x80 | (cp & 0x3F)), f);
    }
}

/* At the opening quote; returns the decoded string (malloc'd) or NULL. */
static char *read_string(reader *r)
{
    r->p++;
    g_text t;
    g_text_open(&t);
    while (*r->p != '"') {
        unsigned char c = (unsigned char)*r->p;
        if (c == '\0' || c < 0x20) {
            fail(r, c ? "control character in a string" : "unterminated string");
            break;
        }
        if (c != '\\') {
            fputc(c, t.f);
            r->p++;
            continue;
        }
        char e = r->p[1];
        r->p += 2;
        switch (e) {
        case '"': fputc('"', t.f); break;
        case '\\': fputc('\\', t.f); break;
        case '/': fputc('/', t.f); break;
        case 'b': fputc('\b', t.f); break;
        case 'f': fputc('\f', t.f); break;
        case 'n': fputc('\n', t.f); break;
        case 'r': fputc('\r', t.f); break;
        case 't': fputc('\t', t.f); break;
        case 'u': {
            unsigned cp, lo;
            if (hex4(r->p, &cp) != 0) {
                fail(r, "bad \\u escape");
                break;
            }
            r->p += 4;
            if (cp >= 0xD800 && cp < 0xDC00 && r->p[0] == '\\' && r->p[1] == 'u' &&
                hex4(r->p + 2, &lo) == 0 && lo >= 0xDC00 && lo < 0xE000) {
                cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                r->p += 6;
            }
            put_utf8(t.f, cp);
            break;
        }
        default:
            r->p--;
            fail(r, "bad escape in a string");
        }
        if (r->failed)
            break;
    }
    g_text_close(&t);
    if (r->failed) {
        free(t.buf);
        return NULL;
    }
    r->p++;
    return t.buf;
}

static void read_value(reader *r, gj *v, int depth);

static void read_members(reader *r, gj *v, int depth, char close)
{
    size_t cap = 0;
    r->p++;
    skip_space(r);
    if (*r->p == close) {
        r->p++;
        return;
    }
    for (;;) {
        if (v->n == cap) {
            cap = cap ? 2 * cap : 8;
            gj *k = realloc(v->kids, cap * sizeof *k);
            if (!k) {
                fail(r, "out of memory");
                return;
            }
            v->kids = k;
        }
        gj *kid = &v->kids[v->n];
        memset(kid, 0, sizeof *kid);
        v->n++;
        skip_space(r);
        if (close == '}') {
            if (*r->p != '"') {
                fail(r, "expected a member name in quotes");
                return;
            }
            kid->key = read_string(r);
            if (!kid->key)
                return;
            skip_space(r);
            if (*r->p != ':') {
                fail(r, "expected ':'");
                return;
            }
            r->p++;
        }
        read_value(r, kid, depth + 1);
        if (r->failed)
            return;
        skip_space(r);
        if (*r->p == ',') {
            r->p++;
            continue;
        }
        if (*r->p == close) {
            r->p++;
            return;
        }
        fail(r, close == '}' ? "expected ',' or '}'" : "expected ',' or ']'");
        return;
    }
}

static void read_number(reader *r, gj *v)
{
    const char *s = r->p;
    if (*r->p == '-')
        r->p++;
    if (*r->p < '0' || *r->p > '9') {
        fail(r, "expected a value");
        return;
    }
    while ((*r->p >= '0' && *r->p <= '9') || *r->p == '.' || *r->p == 'e' ||
           *r->p == 'E' || *r->p == '+' || *r->p == '-')
        r->p++;
    v->type = GJ_NUMBER;
    v->text = g_fmt("%.*s", (int)(r->p - s), s);
    char *end;
    v->number = strtod(v->text, &end);
    if (*end) {
        r->p = s;
        fail(r, "bad number");
    }
}

static void read_value(reader *r, gj *v, int depth)
{
    skip_space(r);
    if (depth > MAX_DEPTH) {
        fail(r, "nested too deeply");
        return;
    }
    switch (*r->p) {
    case '{':
        v->type = GJ_OBJECT;
        read_members(r, v, depth, '}');
        return;
    case '[':
        v->type = GJ_ARRAY;
        read_members(r, v, depth, ']');
        return;
    case '"':
        v->type = GJ_STRING;
        v->text = read_string(r);
        return;
    }
    if (strncmp(r->p, "true", 4) == 0 || strncmp(r->p, "false", 5) == 0) {
        v->type = GJ_BOOL;
        v->boolean = r->p[0] == 't';
        r->p += v->boolean ? 4 : 5;
    } else if (strncmp(r->p, "null", 4) == 0) {
        v->type = GJ_NULL;
        r->p += 4;
    } else {
        read_number(r, v);
    }
}

static void free_kids(gj *v)
{
    for (size_t i = 0; i < v->n; i++)
        free_kids(&v->kids[i]);
    free(v->kids);
    free(v->text);
    free(v->key);
}

void gj_free(gj *v)
{
    if (!v)
        return;
    free_kids(v);
    free(v);
}

gj *gj_parse(const char *text, char *err, size_t errlen)
{
    reader r = { text, text, err, errlen, 0 };
    gj *v = g_alloc(sizeof *v);
    read_value(&r, v, 0);
    skip_space(&r);
    if (!r.failed && *r.p)
        fail(&r, "text after the value");
    if (r.failed) {
        gj_free(v);
        return NULL;
    }
    return v;
}

gj *gj_read(const char *path, char *err, size_t errlen)
{
    char *text;
    if (g_read_file(path, &text, NULL, err, errlen) != 0)
        return NULL;
    char why[256];
    gj *v = gj_parse(text, why, sizeof why);
    free(text);
    if (!v && err && errlen)
        snprintf(err, errlen, "%s: not valid JSON: %s", path, why);
    return v;
}

const gj *gj_get(const gj *obj, const char *key)
{
    if (!obj || obj->type != GJ_OBJECT)
        return NULL;
    for (size_t i = 0; i < obj->n; i++)
        if (strcmp(obj->kids[i].key, key) == 0)
            return &obj->kids[i];
    return NULL;
}

const char *gj_string(const gj *obj, const char *key)
{
    const gj *v = gj_get(obj, key);
    return v && v->type == GJ_STRING ? v->text : NULL;
}

double gj_number(const gj *obj, const char *key, double def)
{
    const gj *v = gj_get(obj, key);
    return v && v->type == GJ_NUMBER ? v->number : def;
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
static int is_flat(const gj *v)
{
    for (size_t i = 0; i < v->n; i++)
        if (v->kids[i].type == GJ_ARRAY || v->kids[i].type == GJ_OBJECT)
            return 0;
    return 1;
}

void gj_put(FILE *f, const gj *v, int indent)
{
    switch (v->type) {
    case GJ_NULL: fputs("null", f); return;
    case GJ_BOOL: fputs(v->boolean ? "true" : "false", f); return;
    case GJ_NUMBER: fputs(v->text, f); return;
    case GJ_STRING: gj_put_string(f, v->text); return;
    case GJ_ARRAY:
    case GJ_OBJECT: break;
    }
    int obj = v->type == GJ_OBJECT;
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
