/* l_pause.c - the repl's script: run up to a pause, keep the state, resume.
 *
 * `lamina repl SCRIPT.lua` runs the script in a coroutine. Where it stops:
 *  - a script that mentions lamina.pause (its code, not its comments or
 *    strings) runs until it calls lamina.pause(), or to its end;
 *  - any other script runs its set-up: the first sim:run pauses before it
 *    steps (sim:run is wrapped until then), so the prompt starts where the
 *    simulation would have.
 * A pause is a yield: the coroutine keeps the script's stack, and
 * lamina.resume() at the prompt continues it (the paused sim:run then runs).
 *
 * Locals are not visible to code typed at the prompt, so at each pause the
 * main chunk's active locals are copied into globals (values: a number is a
 * copy, a sim or material handle is the same object), and `sim` names the
 * simulation that paused or stepped last unless the script set `sim`. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "l_internal.h"

#define SESSION_KEY "lamina.session"
#define THREAD_KEY "lamina.session.thread"

enum { WHY_NONE, WHY_RUN, WHY_CALL };

typedef struct session {
    lua_State *co;       /* the script's coroutine (anchored at THREAD_KEY) */
    int pause_at_run;    /* the next sim:run on co pauses */
    int why;             /* WHY_* of the last yield */
    int paused;          /* co is suspended at a pause */
} session;

static session *get_session(lua_State *L)
{
    la_getfield(L, LUA_REGISTRYINDEX, SESSION_KEY);
    session *s = lua_touserdata(L, -1);
    lua_pop(L, 1);
    return s;
}

/* ---- does the script mention lamina.pause? ----------------------------- */

/* Length of the long bracket "[[", "[==[" at p (0: not one). */
static size_t long_bracket(const char *p, int *level)
{
    if (*p != '[') return 0;
    size_t n = 1;
    while (p[n] == '=') n++;
    if (p[n] != '[') return 0;
    *level = (int)n - 1;
    return n + 1;
}

/* Skips a long string or comment body after its opening bracket. */
static const char *skip_long(const char *p, int level)
{
    for (; *p; p++) {
        if (*p != ']') continue;
        int n = 0;
        while (p[1 + n] == '=') n++;
        if (n == level && p[1 + n] == ']') return p + 2 + n;
    }
    return p;
}

static int ident_char(int c)
{
    return isalnum(c) || c == '_';
}

/* Scans Lua source for the code `lamina.pause` (spaces allowed around the
 * dot), skipping comments and strings. */
static int mentions_pause(const char *src)
{
    const char *p = src;
    int level;
    size_t n;
    while (*p) {
        if (p[0] == '-' && p[1] == '-') {
            p += 2;
            if ((n = long_bracket(p, &level)) > 0) p = skip_long(p + n, level);
            else while (*p && *p != '\n') p++;
        } else if ((n = long_bracket(p, &level)) > 0) {
            p = skip_long(p + n, level);
        } else if (*p == '"' || *p == '\'') {
            char q = *p++;
            while (*p && *p != q && *p != '\n') p += (*p == '\\' && p[1]) ? 2 : 1;
            if (*p) p++;
        } else if (ident_char((unsigned char)*p)) {
            const char *w = p;
            while (ident_char((unsigned char)*p)) p++;
            if (p - w != 6 || strncmp(w, "lamina", 6) != 0) continue;
            const char *q = p;
            while (isspace((unsigned char)*q)) q++;
            if (*q != '.') continue;
            q++;
            while (isspace((unsigned char)*q)) q++;
            if (strncmp(q, "pause", 5) == 0 && !ident_char((unsigned char)q[5])) return 1;
        } else {
            p++;
        }
    }
    return 0;
}

static int script_mentions_pause(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    size_t cap = 4096, len = 0;
    char *buf = malloc(cap);
    size_t got;
    while (buf && (got = fread(buf + len, 1, cap - len - 1, f)) > 0) {
        len += got;
        if (cap - len - 1 == 0) {
            char *b = realloc(buf, 2 * cap);
            if (!b) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = b;
            cap *= 2;
        }
    }
    fclose(f);
    if (!buf) return 0;
    buf[len] = 0;
    int yes = mentions_pause(buf);
    free(buf);
    return yes;
}

/* ---- pausing --------------------------------------------------------- */

/* lamina.pause(): in the repl's script, stop here and give the prompt; in
 * `lamina run`, or typed at the prompt, nothing happens. */
int la_pause(lua_State *L)
{
    session *s = get_session(L);
    if (!s || L != s->co) return 0;
    if (!lua_isyieldable(L))
        return luaL_error(L, "lamina.pause: cannot pause inside a callback or a "
                          "metamethod (call it from the script's own code)");
    s->why = WHY_CALL;
    return lua_yield(L, 0);
}

/* The continuation of the wrapped sim:run: the original method. */
static int run_original(lua_State *L, int status, lua_KContext ctx)
{
    (void)status;
    (void)ctx;
    int n = lua_gettop(L);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, n, LUA_MULTRET);
    return lua_gettop(L);
}

static void restore_run(lua_State *L)
{
    luaL_getmetatable(L, LA_SIM);
    la_getfield(L, -1, "methods");
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_setfield(L, -2, "run");
    lua_pop(L, 2);
}

/* sim:run while the script sets itself up: the first call on the script's
 * coroutine pauses before stepping. */
static int run_pausing(lua_State *L)
{
    session *s = get_session(L);
    if (s && s->pause_at_run && L == s->co && lua_isyieldable(L) &&
        luaL_testudata(L, 1, LA_SIM)) {
        s->pause_at_run = 0;
        s->why = WHY_RUN;
        restore_run(L);   /* runs typed at the prompt report their own lines */
        la_set_last_sim(L, 1);
        return lua_yieldk(L, 0, 0, run_original);
    }
    return run_original(L, LUA_OK, 0);
}

static void wrap_run(lua_State *L)
{
    luaL_getmetatable(L, LA_SIM);
    la_getfield(L, -1, "methods");
    la_getfield(L, -1, "run");
    lua_pushcclosure(L, run_pausing, 1);
    lua_setfield(L, -2, "run");
    lua_pop(L, 2);
}

/* ---- at a pause -------------------------------------------------------- */

/* Copies the active locals of the script's main chunk into globals and
 * appends their names to b. */
static void expose_locals(lua_State *L, lua_State *co, luaL_Buffer *b)
{
    lua_Debug ar;
    int count = 0;
    for (int level = 0; lua_getstack(co, level, &ar); level++) {
        lua_getinfo(co, "S", &ar);
        if (strcmp(ar.what, "main") != 0) continue;
        const char *name;
        for (int i = 1; (name = lua_getlocal(co, &ar, i)) != NULL; i++) {
            if (name[0] == '(') {
                lua_pop(co, 1);
                continue;
            }
            lua_xmove(co, L, 1);
            lua_setglobal(L, name);
            luaL_addstring(b, count++ ? ", " : "");
            luaL_addstring(b, name);
        }
        break;
    }
    if (!count) luaL_addstring(b, "(none)");
}

/* "file:line" of the innermost Lua function on co's stack. */
static void where(lua_State *co, char *buf, size_t len)
{
    lua_Debug ar;
    snprintf(buf, len, "?");
    for (int level = 0; lua_getstack(co, level, &ar); level++) {
        lua_getinfo(co, "Sl", &ar);
        if (ar.currentline > 0) {
            snprintf(buf, len, "%s:%d", ar.short_src, ar.currentline);
            return;
        }
    }
}

static void announce_pause(lua_State *L, session *s)
{
    char at[256];
    where(s->co, at, sizeof at);
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    expose_locals(L, s->co, &b);
    luaL_pushresult(&b);
    int named = lua_getglobal(L, "sim") != LUA_TNIL;
    lua_pop(L, 1);
    const lm_sim *sim = la_last_sim(L);
    if (!named && sim) {
        la_getfield(L, LUA_REGISTRYINDEX, "lamina.last_sim");
        lua_setglobal(L, "sim");
    }
    lamina_progress_clear_line();
    fprintf(stderr, "lamina repl: paused %s at %s", s->why == WHY_RUN ?
            "before the first sim:run" : s->why == WHY_CALL ? "by lamina.pause()" :
            "(the script yielded)", at);
    if (sim) fprintf(stderr, " (t = %.9g, step %ld)", sim->t, sim->step);
    fprintf(stderr, "\nlamina repl: the script's locals are globals now: %s\n",
            lua_tostring(L, -1));
    if (!named && sim)
        fprintf(stderr, "lamina repl: `sim` is the simulation %s\n",
                s->why == WHY_RUN ? "whose run paused" : "that stepped last");
    lua_pop(L, 1);
}

/* Resumes the script; prints what became of it; returns LAMINA_SCRIPT_*.
 * On failure the message (with the script's traceback) is left on L. */
static int resume_script(lua_State *L, session *s)
{
    int nres = 0;
    s->why = WHY_NONE;
    s->paused = 0;
    int rc = lua_resume(s->co, L, 0, &nres);
    if (rc == LUA_YIELD) {
        lua_pop(s->co, nres);
        s->paused = 1;
        announce_pause(L, s);
        return LAMINA_SCRIPT_PAUSED;
    }
    if (rc == LUA_OK) {
        lua_pop(s->co, nres);
        lamina_progress_clear_line();
        fprintf(stderr, "lamina repl: the script ran to its end\n");
        return LAMINA_SCRIPT_DONE;
    }
    const char *msg = lua_tostring(s->co, -1);
    luaL_traceback(L, s->co, msg ? msg : "(error object is not a string)", 0);
    return LAMINA_SCRIPT_FAILED;
}

int lamina_script_start(lua_State *L, lamina_run *run)
{
    session *s = lua_newuserdatauv(L, sizeof *s, 0);
    memset(s, 0, sizeof *s);
    lua_setfield(L, LUA_REGISTRYINDEX, SESSION_KEY);
    s->co = lua_newthread(L);
    lua_setfield(L, LUA_REGISTRYINDEX, THREAD_KEY);
    lamina_interrupt_add_thread(s->co);
    if (la_load_script(s->co, run->script) != LUA_OK) {
        fprintf(stderr, "lamina: %s\n", lua_tostring(s->co, -1));
        lua_settop(s->co, 0);
        return LAMINA_SCRIPT_BAD;
    }
    lua_pushstring(L, run->script);
    lua_setglobal(L, "SCRIPT");
    s->pause_at_run = !script_mentions_pause(run->script);
    if (s->pause_at_run) wrap_run(L);
    int rc = resume_script(L, s);
    if (rc == LAMINA_SCRIPT_FAILED) {
        lamina_progress_clear_line();
        fprintf(stderr, "lamina: %s\nlamina repl: the script stopped with an error; its "
                "state so far is kept\n", lua_tostring(L, -1));
        lua_pop(L, 1);
    }
    if (s->pause_at_run) {   /* it never ran: put sim:run back */
        s->pause_at_run = 0;
        luaL_getmetatable(L, LA_SIM);
        la_getfield(L, -1, "methods");
        la_getfield(L, -1, "run");
        if (lua_tocfunction(L, -1) == run_pausing) {
            lua_getupvalue(L, -1, 1);
            lua_setfield(L, -3, "run");
        }
        lua_pop(L, 3);
    }
    return rc;
}

/* lamina.resume(): continues the repl's paused script up to its next pause
 * or its end. An error in the script is raised at the prompt. */
int la_resume(lua_State *L)
{
    session *s = get_session(L);
    if (!s || !s->paused)
        return luaL_error(L, "lamina.resume: no paused script (%s)", !s ?
                          "only a script started by `lamina repl SCRIPT.lua` can be resumed"
                          : "it has run to its end or stopped with an error");
    if (L == s->co) return luaL_error(L, "lamina.resume: the script cannot resume itself");
    lamina_run *run = la_run(L);
    int prompt = run ? run->at_prompt : 0;
    if (run) run->at_prompt = 0;   /* the script's own changes are logged as in a run */
    int rc = resume_script(L, s);
    if (run) run->at_prompt = prompt;
    if (rc == LAMINA_SCRIPT_FAILED)
        return luaL_error(L, "the script stopped (it cannot be resumed): %s",
                          lua_tostring(L, -1));
    return 0;
}
