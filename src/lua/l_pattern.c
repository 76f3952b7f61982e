/* l_pattern.c - a cap on the work of Lua's pattern matcher (issue 31 item 4).
 *
 * string.find, match, gmatch and gsub run in C: no instruction-count hook
 * fires inside them, so Ctrl-C and SIGTERM (l_interrupt.c, which stop a
 * script through such a hook) cannot stop a backtracking match such as
 * ("a"):rep(3e4):find("a*a*a*b"), which takes ~n^4 steps. So before the
 * matcher runs, its worst case is bounded and a call past the bound is
 * refused, naming the function, the bound and the sizes.
 *
 * The bound. Lua's matcher backtracks only at the items that can match a
 * varying length: a single-character class quantified by * + - ?, a %b
 * balance and a back-reference %1-%9. A quantified class C takes a run of
 * characters in C, so it has at most r_C + 1 choices, r_C the longest such
 * run in the subject (n for '.', %b and %1). One match attempt takes at most
 * m * prod(r_i + 1) steps for a pattern of m bytes, and there are n + 1
 * starts (one with an anchor ^): W = (n + 1) m prod(r_i + 1). A quantified
 * item with nothing but closing captures after it never backtracks (what it
 * took is the match), so it is not counted: "[^,]+" is linear, and so is
 * "(%d+)%.(%d+)" on numbers of a few digits. A call is refused when
 * W > 1e8, under a second of matching (1.5e8 steps a second measured);
 * find with plain = true is not a pattern and is never refused. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "l_internal.h"

#define MAX_WORK 1e8   /* ~1.5e8 steps a second measured: "a*b" on 31000 "a" took 3.2 s */

/* The length of the single-character class at p (end e): %x, [set], or one
 * character; 0 when p starts no such class. */
static size_t class_len(const char *p, const char *e)
{
    if (p >= e) return 0;
    if (*p == '%') return p + 1 < e ? 2 : 1;
    if (*p != '[') return 1;
    const char *q = p + 1;
    if (q < e && *q == '^') q++;
    do {   /* the first ']' of a set is a member, as Lua reads it */
        if (q >= e) return (size_t)(e - p);   /* malformed: Lua's own error */
        if (*q == '%' && q + 1 < e) q++;
        q++;
    } while (q < e && *q != ']');
    return (size_t)((q < e ? q + 1 : e) - p);
}

/* Does only ')' (closing captures) follow q? */
static int nothing_after(const char *q, const char *e)
{
    while (q < e && *q == ')') q++;
    return q == e;
}

/* Is c in the class %l (Lua's letters; others stand for themselves)? */
static int in_class(unsigned char c, unsigned char l)
{
    int r;
    switch (tolower(l)) {
    case 'a': r = isalpha(c); break;
    case 'c': r = iscntrl(c); break;
    case 'd': r = isdigit(c); break;
    case 'g': r = isgraph(c); break;
    case 'l': r = islower(c); break;
    case 'p': r = ispunct(c); break;
    case 's': r = isspace(c); break;
    case 'u': r = isupper(c); break;
    case 'w': r = isalnum(c); break;
    case 'x': r = isxdigit(c); break;
    default: return c == l;
    }
    return isupper(l) ? !r : r != 0;
}

/* Does c match the single-character class at p (length len)? */
static int matches(unsigned char c, const char *p, size_t len)
{
    if (*p == '.') return 1;
    if (*p == '%') return len > 1 ? in_class(c, (unsigned char)p[1]) : 0;
    if (*p != '[') return c == (unsigned char)*p;
    const char *q = p + 1, *end = p + len - 1;   /* end: the closing ']' */
    int neg = q < end && *q == '^';
    if (neg) q++;
    int in = 0;
    for (; q < end && !in; q++) {
        if (*q == '%' && q + 1 < end) {
            in = in_class(c, (unsigned char)*++q);
        } else if (q + 2 < end && q[1] == '-') {
            in = (unsigned char)q[0] <= c && c <= (unsigned char)q[2];
            q += 2;
        } else {
            in = c == (unsigned char)*q;
        }
    }
    return neg ? !in : in;
}

/* The longest run of subject characters in the class at p. */
static double longest_run(const char *s, size_t n, const char *p, size_t len)
{
    size_t best = 0, run = 0;
    for (size_t i = 0; i < n; i++) {
        run = matches((unsigned char)s[i], p, len) ? run + 1 : 0;
        if (run > best) best = run;
    }
    return (double)best;
}

/* The worst-case steps of one match attempt over subject s (n bytes), per
 * byte of the pattern: prod(r_i + 1) over the items that may backtrack;
 * *anchored when the pattern starts with ^. */
static double choices(const char *s, size_t n, const char *p, size_t m, int *nitems,
                      int *anchored)
{
    const char *e = p + m;
    double w = 1;
    *nitems = 0;
    *anchored = m > 0 && *p == '^';
    if (*anchored) p++;
    while (p < e && w <= MAX_WORK) {
        if (*p == '(' || *p == ')') {
            p++;
            continue;
        }
        if (*p == '$' && p + 1 == e) break;
        if (*p == '%' && p + 1 < e && p[1] == 'b') {   /* %bxy: a scan of any length */
            p += 4;
            if (!nothing_after(p < e ? p : e, e)) w *= (double)n + 1, ++*nitems;
            continue;
        }
        if (*p == '%' && p + 1 < e && p[1] == 'f') {   /* %f[set]: no width */
            p += 2;
            p += class_len(p, e);
            continue;
        }
        if (*p == '%' && p + 1 < e && p[1] >= '0' && p[1] <= '9') {   /* %1 */
            p += 2;
            if (!nothing_after(p, e)) w *= (double)n + 1, ++*nitems;
            continue;
        }
        size_t c = class_len(p, e);
        if (!c) c = 1;
        const char *cls = p;
        p += c;
        if (p < e && strchr("*+-?", *p)) {
            int one = *p == '?';
            p++;
            if (!nothing_after(p, e)) {
                w *= one ? 2 : longest_run(s, n, cls, c) + 1;
                ++*nitems;
            }
        }
    }
    return w;
}

/* Upvalue 1: the original function; argument 1 the subject, 2 the pattern,
 * 3 init (find, match, gmatch), 4 plain (find). */
static int guarded(lua_State *L)
{
    const char *fn = lua_tostring(L, lua_upvalueindex(2));
    size_t n, m;
    const char *s = luaL_checklstring(L, 1, &n);
    const char *p = luaL_checklstring(L, 2, &m);
    int is_find = strcmp(fn, "string.find") == 0;
    if (!(is_find && lua_toboolean(L, 4))) {
        if (strcmp(fn, "string.gsub") != 0 && lua_type(L, 3) == LUA_TNUMBER) {
            lua_Integer init = lua_tointeger(L, 3);   /* only the subject from init on */
            if (init > 1 && (size_t)init <= n) n -= (size_t)init - 1;
            else if (init < 0 && (size_t)-init < n) n = (size_t)-init;
        }
        int anchored, q;
        double w = choices(s + (lua_rawlen(L, 1) - n), n, p, m, &q, &anchored);
        double work = (anchored ? 1 : (double)n + 1) * (double)(m ? m : 1) * w;
        if (work > MAX_WORK) {
            char msg[400];
            snprintf(msg, sizeof msg, "%s: the pattern '%.60s%s' on %zu bytes could take up "
                     "to %.3g steps (%d backtracking item%s; at most %.0e, about a second, "
                     "since the matcher cannot be interrupted): shorten the text or simplify "
                     "the pattern", fn, p, m > 60 ? "..." : "", n, work, q, q == 1 ? "" : "s",
                     MAX_WORK);
            return luaL_error(L, "%s", msg);
        }
    }
    int nargs = lua_gettop(L);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, nargs, LUA_MULTRET);
    return lua_gettop(L);
}

void la_guard_patterns(lua_State *L)
{
    static const char *const names[] = {"find", "match", "gmatch", "gsub", NULL};
    lua_getglobal(L, "string");
    for (int i = 0; names[i]; i++) {
        lua_getfield(L, -1, names[i]);
        lua_pushfstring(L, "string.%s", names[i]);
        lua_pushcclosure(L, guarded, 2);
        lua_setfield(L, -2, names[i]);
    }
    lua_pop(L, 1);
}
