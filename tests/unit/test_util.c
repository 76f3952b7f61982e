/* test_util.c - src/util: error messages (truncation, no buffer), FNV-1a
 * (the published test vectors), the JSON reader (values, escapes, errors
 * with line and column), option values, names, entities, growing arrays. */
#include "check.h"
#include "util.h"

#include <stdlib.h>
#include <string.h>

static void test_err(void)
{
    char err[8];
    lu_err(err, sizeof err, "%s %d", "abcdef", 42);
    CHECK(strcmp(err, "abcdef ") == 0);     /* cut, NUL-terminated */
    lu_err(NULL, 0, "%s", "nowhere");       /* no buffer: nothing */
    char one[1] = { 'x' };
    lu_err(one, 1, "long");
    CHECK(one[0] == '\0');
}

static void test_hash(void)
{
    /* FNV-1a 64 test vectors (Fowler, Noll, Vo) */
    CHECK(lu_fnv1a(LU_FNV_SEED, "", 0) == 0xcbf29ce484222325ull);
    CHECK(lu_fnv1a_str("a") == 0xaf63dc4c8601ec8cull);
    CHECK(lu_fnv1a_str("foobar") == 0x85944171f73967e8ull);
    /* continued in two pieces = at once */
    CHECK(lu_fnv1a(lu_fnv1a(LU_FNV_SEED, "foo", 3), "bar", 3) == lu_fnv1a_str("foobar"));
    char hex[17];
    lu_hash_hex(0xaf63dc4c8601ec8cull, hex);
    CHECK(strcmp(hex, "af63dc4c8601ec8c") == 0);
    lu_hash_hex(1, hex);
    CHECK(strcmp(hex, "0000000000000001") == 0);
}

static void test_json(void)
{
    char err[128] = "";
    lu_json *v = lu_json_parse(
        "{\"a\": 1.50, \"s\": \"x\\n\\u00e9\\ud83d\\ude00\", \"l\": [true, null, {}],"
        " \"a\": 2}", err, sizeof err);
    CHECK(v != NULL);
    if (v) {
        CHECK(v->type == LU_JSON_OBJECT && v->n == 4);
        CHECK(lu_json_number(v, "a", 0) == 1.5);                  /* the first "a" */
        CHECK(strcmp(lu_json_get(v, "a")->text, "1.50") == 0);    /* as written */
        CHECK(strcmp(lu_json_string(v, "s"), "x\n\xc3\xa9\xf0\x9f\x98\x80") == 0);
        const lu_json *l = lu_json_get(v, "l");
        CHECK(l && l->type == LU_JSON_ARRAY && l->n == 3);
        CHECK(l && l->kids[0].type == LU_JSON_BOOL && l->kids[0].boolean);
        CHECK(l && l->kids[1].type == LU_JSON_NULL && l->kids[2].type == LU_JSON_OBJECT);
        CHECK(lu_json_string(v, "a") == NULL && lu_json_number(v, "none", 7) == 7);
        lu_json_free(v);
    }
    static const struct { const char *text, *err; } bad[] = {
        { "{\"a\": 1,\n  \"b\" 2}", "line 2, column 7: expected ':'" },
        { "[1, 2", "line 1, column 6: expected ',' or ']'" },
        { "\"abc", "line 1, column 5: unterminated string" },
        { "\"a\\q\"", "line 1, column 4: bad escape in a string" },
        { "\"\\u12G4\"", "line 1, column 4: bad \\u escape" },
        { "1.2.3", "line 1, column 1: bad number" },
        { "{} x", "line 1, column 4: text after the value" },
        { "", "line 1, column 1: expected a value" },
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        err[0] = '\0';
        CHECK(lu_json_parse(bad[i].text, err, sizeof err) == NULL);
        if (strcmp(err, bad[i].err) != 0) {
            fprintf(stderr, "json '%s': got '%s', want '%s'\n", bad[i].text, err, bad[i].err);
            check_failures++;
        }
    }
    char deep[200];
    memset(deep, '[', sizeof deep - 1);
    deep[sizeof deep - 1] = '\0';
    CHECK(lu_json_parse(deep, err, sizeof err) == NULL && strstr(err, "nested too deeply"));
}

static void test_opt(void)
{
    char *argv[] = { "--out=a", "--out", "b", "--outer", "--out" };
    int argc = 5, i = 0;
    const char *v = NULL;
    CHECK(lu_opt_value(argc, argv, &i, "--out", &v) == 1 && strcmp(v, "a") == 0 && i == 0);
    i = 1;
    CHECK(lu_opt_value(argc, argv, &i, "--out", &v) == 1 && strcmp(v, "b") == 0 && i == 2);
    i = 3;
    CHECK(lu_opt_value(argc, argv, &i, "--out", &v) == 0 && i == 3);
    i = 4;
    CHECK(lu_opt_value(argc, argv, &i, "--out", &v) == 1 && v == NULL && i == 4);
}

static void test_text(void)
{
    static const char *const names[] = { "cairo", "osmesa", "egl" };
    CHECK(lu_name_index("egl", names, 3) == 2);
    CHECK(lu_name_index("gl", names, 3) == -1);
    CHECK(lu_name_index(NULL, names, 3) == -1);
    CHECK(strcmp(lu_xml_entity('&'), "&amp;") == 0 && strcmp(lu_xml_entity('"'), "&quot;") == 0);
    CHECK(lu_xml_entity('a') == NULL && lu_xml_entity('\'') == NULL);
}

static void test_reserve(void)
{
    double *a = NULL;
    size_t cap = 0;
    CHECK(lu_reserve(&a, &cap, 1, sizeof *a, 4) == 0 && a && cap == 4);
    CHECK(lu_reserve(&a, &cap, 4, sizeof *a, 4) == 0 && cap == 4);
    CHECK(lu_reserve(&a, &cap, 9, sizeof *a, 4) == 0 && cap == 16);
    a[15] = 1;
    double *before = a;
    CHECK(lu_reserve(&a, &cap, (size_t)-1 / 4, sizeof *a, 4) == -1 && a == before && cap == 16);
    free(a);
}

/* lu_push: each element added zeroed, the earlier ones kept; a count past
 * what size_t can hold refused with the array unchanged */
static void test_push(void)
{
    struct item { int a; double b; } *v = NULL;
    for (size_t n = 0; n < 5; n++) {
        struct item *it = lu_push(&v, n, sizeof *v);
        CHECK(it && it == &v[n] && it->a == 0 && it->b == 0);
        it->a = (int)n + 1;
        it->b = 0.5 * (double)n;
    }
    for (size_t n = 0; n < 5; n++) CHECK(v[n].a == (int)n + 1 && v[n].b == 0.5 * (double)n);
    struct item *before = v;
    CHECK(lu_push(&v, (size_t)-1 / sizeof *v, sizeof *v) == NULL && v == before);
    free(v);
}

int main(void)
{
    test_err();
    test_hash();
    test_json();
    test_opt();
    test_text();
    test_reserve();
    test_push();
    return CHECK_DONE();
}
