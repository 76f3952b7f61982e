/* sweep_json.c - reading a run's report.json (written by lamina.report,
 * src/lua/l_report.c):
 *
 *   {"script": "...", "script_hash": "...",
 *    "values": [{"name": "gap", "value": 0.12, "paper": ..., ...}, ...]}
 *
 * A small strict JSON reader: it walks any JSON value and keeps only the
 * name and value of each entry of the top-level "values" array. Numbers are
 * kept as written (the report writes the shortest exact form). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "read_file.h"
#include "sweep.h"

typedef struct reader {
    const char *p;
    int bad;
} reader;

static void ws(reader *r)
{
    while (*r->p == ' ' || *r->p == '\t' || *r->p == '\n' || *r->p == '\r') r->p++;
}

/* Steps over c, or marks the input bad (never past its end). */
static void expect(reader *r, char c)
{
    if (*r->p == c) r->p++;
    else r->bad = 1;
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

static void put_utf8(char **o, unsigned c)
{
    if (c < 0x80) {
        *(*o)++ = (char)c;
    } else if (c < 0x800) {
        *(*o)++ = (char)(0xc0 | (c >> 6));
        *(*o)++ = (char)(0x80 | (c & 0x3f));
    } else if (c < 0x10000) {
        *(*o)++ = (char)(0xe0 | (c >> 12));
        *(*o)++ = (char)(0x80 | ((c >> 6) & 0x3f));
        *(*o)++ = (char)(0x80 | (c & 0x3f));
    } else {
        *(*o)++ = (char)(0xf0 | (c >> 18));
        *(*o)++ = (char)(0x80 | ((c >> 12) & 0x3f));
        *(*o)++ = (char)(0x80 | ((c >> 6) & 0x3f));
        *(*o)++ = (char)(0x80 | (c & 0x3f));
    }
}

/* A string at r->p (after ws): decoded, malloc'd; NULL on error. */
static char *string(reader *r)
{
    if (*r->p != '"') {
        r->bad = 1;
        return NULL;
    }
    const char *s = ++r->p;
    size_t n = 0;
    while (s[n] && s[n] != '"') n += (s[n] == '\\' && s[n + 1]) ? 2 : 1;
    char *out = malloc(n + 1), *o = out;
    if (!out) {
        r->bad = 1;
        return NULL;
    }
    while (*r->p && *r->p != '"') {
        char c = *r->p++;
        if (c != '\\') {
            *o++ = c;
            continue;
        }
        unsigned u, lo;
        if (!*r->p) goto fail;
        switch (c = *r->p++) {
        case 'n': *o++ = '\n'; break;
        case 't': *o++ = '\t'; break;
        case 'r': *o++ = '\r'; break;
        case 'b': *o++ = '\b'; break;
        case 'f': *o++ = '\f'; break;
        case '"': case '\\': case '/': *o++ = c; break;
        case 'u':
            if (hex4(r->p, &u)) goto fail;
            r->p += 4;
            if (u >= 0xd800 && u < 0xdc00 && r->p[0] == '\\' && r->p[1] == 'u' &&
                hex4(r->p + 2, &lo) == 0 && lo >= 0xdc00 && lo < 0xe000) {
                u = 0x10000 + ((u - 0xd800) << 10) + (lo - 0xdc00);
                r->p += 6;
            }
            put_utf8(&o, u);   /* \uXXXX takes 6 bytes and writes at most 4 */
            break;
        default:
            goto fail;
        }
    }
    if (*r->p != '"') goto fail;
    r->p++;
    *o = 0;
    return out;
fail:
    free(out);
    r->bad = 1;
    return NULL;
}

/* A scalar's text (numbers as written, strings decoded); NULL for
 * objects and arrays, which are skipped. */
static char *value(reader *r, int depth);

static void skip_container(reader *r, int depth)
{
    char open = *r->p++, close = open == '{' ? '}' : ']';
    ws(r);
    if (*r->p == close) {
        r->p++;
        return;
    }
    for (;;) {
        if (open == '{') {
            free(string(r));
            ws(r);
            expect(r, ':');
        }
        free(value(r, depth + 1));
        ws(r);
        if (r->bad) return;
        if (*r->p == ',') {
            r->p++;
            ws(r);
            continue;
        }
        expect(r, close);
        return;
    }
}

static char *value(reader *r, int depth)
{
    ws(r);
    if (depth > 64) {
        r->bad = 1;
        return NULL;
    }
    if (*r->p == '"') return string(r);
    if (*r->p == '{' || *r->p == '[') {
        skip_container(r, depth);
        return NULL;
    }
    const char *s = r->p;
    while (*r->p && strchr("+-.0123456789eEtruefalsn", *r->p)) r->p++;
    size_t n = (size_t)(r->p - s);
    if (!n) {
        r->bad = 1;
        return NULL;
    }
    char *out = malloc(n + 1);
    if (!out) {
        r->bad = 1;
        return NULL;
    }
    memcpy(out, s, n);
    out[n] = 0;
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

/* One entry of "values": {"name": ..., "value": ..., ...}. */
static void entry(reader *r, char ***names, char ***values, int *n)
{
    ws(r);
    if (*r->p != '{') {
        free(value(r, 1));
        return;
    }
    r->p++;
    char *name = NULL, *val = NULL;
    ws(r);
    while (!r->bad && *r->p != '}') {
        char *key = string(r);
        ws(r);
        expect(r, ':');
        char *v = r->bad ? NULL : value(r, 2);
        if (key && !strcmp(key, "name") && !name) name = v;
        else if (key && !strcmp(key, "value") && !val) val = v;
        else free(v);
        free(key);
        ws(r);
        if (*r->p == ',') {
            r->p++;
            ws(r);
        } else if (*r->p != '}') {
            r->bad = 1;
        }
    }
    if (!r->bad) r->p++;
    if (r->bad || !name || !val || push(names, *n, name) || push(values, *n, val)) {
        free(name);
        free(val);
        return;
    }
    (*n)++;
}

/* A regular file of at most LR_READ_MAX bytes (a report linked to
 * /dev/zero was read for ever), or NULL. */
static char *slurp(const char *path)
{
    char *text, err[64];
    return lr_read_file(path, LR_READ_MAX, &text, NULL, err, sizeof err) == 0 ? text : NULL;
}

int sw_report_read(const char *path, char ***names, char ***values, int *n)
{
    *names = *values = NULL;
    *n = 0;
    char *text = slurp(path);
    if (!text) return -1;
    reader r = {text, 0};
    ws(&r);
    expect(&r, '{');
    ws(&r);
    while (!r.bad && *r.p != '}') {
        char *key = string(&r);
        ws(&r);
        expect(&r, ':');
        ws(&r);
        if (!r.bad && key && !strcmp(key, "values") && *r.p == '[') {
            r.p++;
            ws(&r);
            while (!r.bad && *r.p != ']') {
                entry(&r, names, values, n);
                ws(&r);
                if (*r.p == ',') r.p++;
                else if (*r.p != ']') r.bad = 1;
            }
            if (!r.bad) r.p++;
        } else if (!r.bad) {
            free(value(&r, 1));
        }
        free(key);
        ws(&r);
        if (*r.p == ',') {
            r.p++;
            ws(&r);
        } else if (*r.p != '}') {
            r.bad = 1;
        }
    }
    free(text);
    if (r.bad) {
        for (int i = 0; i < *n; i++) {
            free((*names)[i]);
            free((*values)[i]);
        }
        free(*names);
        free(*values);
        *names = *values = NULL;
        *n = 0;
        return -1;
    }
    return 0;
}
