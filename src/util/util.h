/* util.h - the helpers every layer shares: error formatting, hashing,
 * JSON reading and option values. Pure: no I/O, no Lua, no drawing, so the
 * engine (src/mpm) may use it as freely as the layers above it. */
#ifndef LAMINA_UTIL_H
#define LAMINA_UTIL_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

/* ---- lu_err.c: error messages into a caller's buffer --------------------- */

/* printf into err[errlen]; nothing when err is NULL or errlen is 0. */
void lu_err(char *err, size_t errlen, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
void lu_verr(char *err, size_t errlen, const char *fmt, va_list ap)
    __attribute__((format(printf, 3, 0)));

/* ---- lu_hash.c: FNV-1a (64 bit) ------------------------------------------ */

#define LU_FNV_SEED 14695981039346656037ull

/* h continued over n bytes of data (start from LU_FNV_SEED). */
uint64_t lu_fnv1a(uint64_t h, const void *data, size_t n);
/* of a NUL-terminated string, from the seed */
uint64_t lu_fnv1a_str(const char *s);
/* h as 16 lower-case hex digits, the form stamped into PNGs */
void lu_hash_hex(uint64_t h, char out[17]);

/* ---- lu_json.c: a strict JSON reader into a small tree ------------------- */

typedef enum lu_json_type {
    LU_JSON_NULL, LU_JSON_BOOL, LU_JSON_NUMBER, LU_JSON_STRING, LU_JSON_ARRAY, LU_JSON_OBJECT
} lu_json_type;

typedef struct lu_json {
    lu_json_type type;
    int boolean;
    double number;
    char *text;             /* STRING: the string (UTF-8); NUMBER: as written */
    char *key;              /* member name, inside an object */
    struct lu_json *kids;   /* ARRAY / OBJECT */
    size_t n;
} lu_json;

/* The value of text, or NULL with "line L, column C: what" in err. */
lu_json *lu_json_parse(const char *text, char *err, size_t errlen);
void lu_json_free(lu_json *v);
const lu_json *lu_json_get(const lu_json *obj, const char *key);  /* first member named key */
const char *lu_json_string(const lu_json *obj, const char *key);  /* NULL unless a string */
double lu_json_number(const lu_json *obj, const char *key, double def);

/* ---- lu_text.c: names and escapes -------------------------------------- */

/* The index of name among names[0..n-1], or -1 (also for a NULL name). */
int lu_name_index(const char *name, const char *const names[], int n);
/* The XML/HTML entity that stands for c in text and attribute values
 * ("&amp;", "&lt;", "&gt;", "&quot;"), or NULL when c stands for itself. */
const char *lu_xml_entity(char c);

/* ---- lu_grow.c: growing arrays ------------------------------------------ */

/* Room for need elements of elem bytes in the array *(T **)array of
 * capacity *cap, which doubles from first: 0, or -1 when out of memory or
 * too large (the array and *cap unchanged). */
int lu_reserve(void *array, size_t *cap, size_t need, size_t elem, size_t first);
/* Element n of the array *(T **)array of n elements, grown by one
 * (realloc) and zeroed: its address, or NULL out of memory (the array
 * unchanged). For lists that grow one at a time (pins, contact fields,
 * record columns). */
void *lu_push(void *array, size_t n, size_t elem);
/* Frees the n arrays p[0..n) (any may be NULL); LU_FREE_ALL(a, b, ...)
 * frees the arrays named, for a struct that owns many. */
void lu_free_each(void *const *p, size_t n);
#define LU_FREE_ALL(...) \
    lu_free_each((void *const[]){__VA_ARGS__}, sizeof((void *const[]){__VA_ARGS__}) / sizeof(void *))

/* ---- lu_opt.c: option values of a command line --------------------------- */

/* Whether argv[*i] is the option name, as "--name=value" or "--name value":
 * 0 if not; else 1, with *value the value, or NULL when "--name" is the
 * last word (*i moves past a separate value). */
int lu_opt_value(int argc, char **argv, int *i, const char *name, const char **value);

/* ---- lu_budget.c: one memory cap over Lua, the engine and the renderer --- */

/* What charged the memory: the engine's arrays, the Lua state, canvases. */
typedef enum lu_mem_kind { LU_MEM_ENGINE, LU_MEM_LUA, LU_MEM_RENDER, LU_MEM_KINDS } lu_mem_kind;

/* The process-wide cap unless LAMINA_MEMORY_MB or `lamina run --memory MB`
 * says otherwise (docs/security.md "Memory"): a 10^7-particle run takes
 * 2.6 GB (docs/performance.md), a 16384^2 canvas 1 GiB. */
#define LU_BUDGET_DEFAULT_MB 4096

void lu_budget_set_limit(size_t bytes);
size_t lu_budget_limit(void);
size_t lu_budget_used(lu_mem_kind k);
size_t lu_budget_total(void);
/* 0 with `bytes` counted, or -1 when they would pass the cap (after one
 * reclaim, for the engine and the renderer): the caller fails as out of
 * memory and reports lu_budget_oom(). */
int lu_budget_charge(lu_mem_kind k, size_t bytes);
void lu_budget_release(lu_mem_kind k, size_t bytes);
/* fn(ud) frees what it can (the Lua state's full collection); called only
 * on the registering thread, before an engine or renderer charge is
 * refused. Cleared by lu_budget_clear_reclaim(ud). */
void lu_budget_set_reclaim(void (*fn)(void *), void *ud);
void lu_budget_clear_reclaim(void *ud);
/* Whether a charge of this thread was refused since the last
 * lu_budget_forget_refusal(), and why: "memory limit N MB reached (engine:
 * .., lua: .., render: ..; KIND asked for M MB more)", or "out of memory"
 * when none was. */
int lu_budget_refused(void);
const char *lu_budget_oom(void);
void lu_budget_forget_refusal(void);

#endif
