/* lu_json.c - a strict JSON reader into a small tree (util.h): the
 * gallery's report.json and meta.json, the sweep's report values.
 *
 * Recursive descent. Numbers keep the text they were written with, so a
 * value passes from one file into another unchanged (no round trip through
 * printf). Strings are kept as UTF-8; \u escapes are decoded, surrogate
 * pairs included. */
#include "util.h"

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
    lu_err(r->err, r->errlen, "line %d, column %d: %s", line, col, what);
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

/* cp as UTF-8 at o; returns the end */
static char *put_utf8(char *o, unsigned cp)
{
    if (cp < 0x80) {
        *o++ = (char)cp;
    } else if (cp < 0x800) {
        *o++ = (char)(0xC0 | (cp >> 6));
        *o++ = (char)(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        *o++ = (char)(0xE0 | (cp >> 12));
        *o++ = (char)(0x80 | ((cp >> 6) & 0x3F));
        *o++ = (char)(0x80 | (cp & 0x3F));
    } else {
        *o++ = (char)(0xF0 | (cp >> 18));
        *o++ = (char)(0x80 | ((cp >> 12) & 0x3F));
        *o++ = (char)(0x80 | ((cp >> 6) & 0x3F));
        *o++ = (char)(0x80 | (cp & 0x3F));
    }
    return o;
}

/* At the opening quote; returns the decoded string (malloc'd) or NULL. The
 * decoded text is never longer than the written one (\uXXXX: 6 bytes
 * written, at most 4 decoded), so one buffer of that length holds it. */
static char *read_string(reader *r)
{
    r->p++;
    size_t n = 0;
    while (r->p[n] && r->p[n] != '"')
        n += (r->p[n] == '\\' && r->p[n + 1]) ? 2 : 1;
    char *out = malloc(n + 1), *o = out;
    if (!out) {
        fail(r, "out of memory");
        return NULL;
    }
    while (*r->p != '"') {
        unsigned char c = (unsigned char)*r->p;
        if (c == '\0' || c < 0x20) {
            fail(r, c ? "control character in a string" : "unterminated string");
            break;
        }
        if (c != '\\') {
            *o++ = (char)c;
            r->p++;
            continue;
        }
        char e = r->p[1];
        r->p += 2;
        switch (e) {
        case '"': *o++ = '"'; break;
        case '\\': *o++ = '\\'; break;
        case '/': *o++ = '/'; break;
        case 'b': *o++ = '\b'; break;
        case 'f': *o++ = '\f'; break;
        case 'n': *o++ = '\n'; break;
        case 'r': *o++ = '\r'; break;
        case 't': *o++ = '\t'; break;
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
            o = put_utf8(o, cp);
            break;
        }
        default:
            r->p--;
            fail(r, "bad escape in a string");
        }
        if (r->failed)
            break;
    }
    if (r->failed) {
        free(out);
        return NULL;
    }
    *o = '\0';
    r->p++;
    return out;
}

static void read_value(reader *r, lu_json *v, int depth);

static void read_members(reader *r, lu_json *v, int depth, char close)
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
            lu_json *k = realloc(v->kids, cap * sizeof *k);
            if (!k) {
                fail(r, "out of memory");
                return;
            }
            v->kids = k;
        }
        lu_json *kid = &v->kids[v->n];
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

static void read_number(reader *r, lu_json *v)
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
    v->type = LU_JSON_NUMBER;
    size_t n = (size_t)(r->p - s);
    v->text = malloc(n + 1);
    if (!v->text) {
        fail(r, "out of memory");
        return;
    }
    memcpy(v->text, s, n);
    v->text[n] = '\0';
    char *end;
    v->number = strtod(v->text, &end);
    if (*end) {
        r->p = s;
        fail(r, "bad number");
    }
}

static void read_value(reader *r, lu_json *v, int depth)
{
    skip_space(r);
    if (depth > MAX_DEPTH) {
        fail(r, "nested too deeply");
        return;
    }
    switch (*r->p) {
    case '{':
        v->type = LU_JSON_OBJECT;
        read_members(r, v, depth, '}');
        return;
    case '[':
        v->type = LU_JSON_ARRAY;
        read_members(r, v, depth, ']');
        return;
    case '"':
        v->type = LU_JSON_STRING;
        v->text = read_string(r);
        return;
    }
    if (strncmp(r->p, "true", 4) == 0 || strncmp(r->p, "false", 5) == 0) {
        v->type = LU_JSON_BOOL;
        v->boolean = r->p[0] == 't';
        r->p += v->boolean ? 4 : 5;
    } else if (strncmp(r->p, "null", 4) == 0) {
        v->type = LU_JSON_NULL;
        r->p += 4;
    } else {
        read_number(r, v);
    }
}

static void free_kids(lu_json *v)
{
    for (size_t i = 0; i < v->n; i++)
        free_kids(&v->kids[i]);
    free(v->kids);
    free(v->text);
    free(v->key);
}

void lu_json_free(lu_json *v)
{
    if (!v)
        return;
    free_kids(v);
    free(v);
}

lu_json *lu_json_parse(const char *text, char *err, size_t errlen)
{
    reader r = { text, text, err, errlen, 0 };
    lu_json *v = calloc(1, sizeof *v);
    if (!v) {
        fail(&r, "out of memory");
        return NULL;
    }
    read_value(&r, v, 0);
    skip_space(&r);
    if (!r.failed && *r.p)
        fail(&r, "text after the value");
    if (r.failed) {
        lu_json_free(v);
        return NULL;
    }
    return v;
}

const lu_json *lu_json_get(const lu_json *obj, const char *key)
{
    if (!obj || obj->type != LU_JSON_OBJECT)
        return NULL;
    for (size_t i = 0; i < obj->n; i++)
        if (strcmp(obj->kids[i].key, key) == 0)
            return &obj->kids[i];
    return NULL;
}

const char *lu_json_string(const lu_json *obj, const char *key)
{
    const lu_json *v = lu_json_get(obj, key);
    return v && v->type == LU_JSON_STRING ? v->text : NULL;
}

double lu_json_number(const lu_json *obj, const char *key, double def)
{
    const lu_json *v = lu_json_get(obj, key);
    return v && v->type == LU_JSON_NUMBER ? v->number : def;
}
