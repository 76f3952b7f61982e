/* serve_state.c - what `lamina serve`'s run shows its page, and what the
 * page asks of the run (docs/workbench.md, "lamina serve").
 *
 * The run's thread calls the observer hooks (lamina_observer): after every
 * step it refreshes the progress (energy and settings at most every
 * REFRESH s, since the energy is a sum over particles), applies the changes
 * the page queued - through lamina_set_param / lamina_set_live, the same
 * path and run log as a change typed at the repl's prompt - and waits there
 * while the page has paused the run. The HTTP thread only reads this state
 * and queues; neither touches the other's Lua. */
#include <ctype.h>
#include <lauxlib.h>
#include <lua.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "serve.h"
#include "workbench.h"

#define REFRESH 0.25           /* s between energy / settings refreshes */
#define FRAME_MAX (64 << 20)   /* bytes: a frame file larger is not served */

int serve_state_init(serve_state *st, const char *script)
{
    memset(st, 0, sizeof *st);
    st->script = script;
    st->wall0 = st->rate_wall = wb_now();
    if (pthread_mutex_init(&st->mu, NULL) != 0) return -1;
    if (pthread_cond_init(&st->cv, NULL) != 0) {
        pthread_mutex_destroy(&st->mu);
        return -1;
    }
    return 0;
}

void serve_state_free(serve_state *st)
{
    for (int i = 0; i < st->nframes; i++) {
        free(st->frames[i].name);
        free(st->frames[i].path);
    }
    for (int i = 0; i < st->nparams; i++) {
        free(st->params[i].name);
        free(st->params[i].value);
    }
    for (int i = 0; i < st->nseries; i++) {
        free(st->series[i].label);
        for (int c = 0; c < st->series[i].ncols; c++) free(st->series[i].names[c]);
        free(st->series[i].rows);
    }
    for (int i = 0; i < st->ncmds; i++) {
        free(st->cmds[i].name);
        free(st->cmds[i].value);
    }
    for (int i = 0; i < SERVE_MAX_MSGS; i++) free(st->msgs[i]);
    pthread_cond_destroy(&st->cv);
    pthread_mutex_destroy(&st->mu);
}

void serve_msg(serve_state *st, const char *fmt, ...)
{
    char buf[600];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    char **slot = &st->msgs[st->nmsgs % SERVE_MAX_MSGS];
    free(*slot);
    *slot = strdup(buf);
    st->nmsgs++;
}

/* ---- the hooks of the run's thread ---------------------------------- */

/* sim[key] as text for the page: numbers with %.9g, {gx, gy} as "gx, gy" */
static void setting_text(lua_State *L, int sidx, const char *key, char *out, size_t len)
{
    lua_getfield(L, sidx, key);
    if (lua_type(L, -1) == LUA_TNUMBER) {
        snprintf(out, len, "%.9g", lua_tonumber(L, -1));
    } else if (lua_type(L, -1) == LUA_TTABLE) {
        lua_rawgeti(L, -1, 1);
        lua_rawgeti(L, -2, 2);
        snprintf(out, len, "%.9g, %.9g", lua_tonumber(L, -2), lua_tonumber(L, -1));
        lua_pop(L, 2);
    } else {
        snprintf(out, len, "%s", luaL_typename(L, -1));
    }
    lua_pop(L, 1);
}

/* The page's queued changes, applied at this step boundary; 1 when one
 * was. A refused change (wrong type, a failed Courant check) is logged
 * for the page and the run goes on. */
static int apply_queued(serve_state *st, lua_State *L, int sidx)
{
    lamina_run *run = NULL;
    lua_getfield(L, LUA_REGISTRYINDEX, "lamina.run");
    run = lua_touserdata(L, -1);
    lua_pop(L, 1);
    /* the queue is taken whole first: an error thrown through here (out of
     * Lua memory) leaves it empty, not half applied twice */
    serve_cmd cmds[SERVE_MAX_CMDS];
    int n = st->ncmds;
    memcpy(cmds, st->cmds, (size_t)n * sizeof *cmds);
    st->ncmds = 0;
    int changed = 0;
    for (int i = 0; i < n; i++) {
        serve_cmd *c = &cmds[i];
        char err[600];
        if (run) run->change_from = "from the page";
        int rc = c->kind == CMD_PARAM
                     ? lamina_set_param(L, c->name, c->value, err, sizeof err)
                     : lamina_set_live(L, sidx, c->name, c->value, err, sizeof err);
        if (run) run->change_from = NULL;
        if (rc == 0) {
            serve_msg(st, "t = %.9g step %ld: %s%s = %s", st->t, st->step,
                      c->kind == CMD_PARAM ? "param." : "sim.", c->name, c->value);
            changed = 1;
        } else {
            serve_msg(st, "refused: %s", err);
        }
        free(c->name);
        free(c->value);
    }
    return changed;
}

static void refresh(serve_state *st, lua_State *L, int sidx, const lm_sim *sim, double now)
{
    st->energy = lm_sim_energy(sim);
    st->energy_t = sim->t;
    st->have_energy = 1;
    for (int k = 0; lamina_live_settings[k] && k < 5; k++)
        setting_text(L, sidx, lamina_live_settings[k], st->settings[k], sizeof st->settings[k]);
    st->have_settings = 1;
    if (now > st->rate_wall) {
        st->rate = (double)(sim->step - st->rate_step) / (now - st->rate_wall);
        if (st->rate < 0) st->rate = 0;
    }
    st->rate_wall = now;
    st->rate_step = sim->step;
    st->last_refresh = now;
}

/* What the run's thread does in Lua at a step boundary, under lua_pcall
 * (with the lock held: an error must not leave it locked). */
typedef struct step_job {
    serve_state *st;
    const lm_sim *sim;
    int refresh, changed;
} step_job;

static int step_job_run(lua_State *L)
{
    step_job *j = lua_touserdata(L, 1);   /* the sim is argument 2 */
    if (j->st->ncmds && apply_queued(j->st, L, 2)) j->changed = 1;
    if (j->refresh || j->changed) refresh(j->st, L, 2, j->sim, wb_now());
    return 0;
}

static void run_job(serve_state *st, lua_State *L, int sidx, step_job *j)
{
    if (!lua_checkstack(L, 4)) return;
    lua_pushcfunction(L, step_job_run);
    lua_pushlightuserdata(L, j);
    lua_pushvalue(L, sidx);
    if (lua_pcall(L, 2, 0, 0) != LUA_OK) {
        serve_msg(st, "error: %s", lua_tostring(L, -1) ? lua_tostring(L, -1) : "?");
        lua_pop(L, 1);
    }
}

static int on_step(void *ud, lua_State *L, int sidx, const lm_sim *sim)
{
    serve_state *st = ud;
    sidx = lua_absindex(L, sidx);
    pthread_mutex_lock(&st->mu);
    st->t = sim->t;
    st->step = sim->step;
    st->dt = sim->def.dt;
    step_job j = {st, sim, wb_now() - st->last_refresh >= REFRESH, 0};
    if (j.refresh || st->ncmds) run_job(st, L, sidx, &j);
    if (st->paused && st->step_budget > 0) {
        st->step_budget--;   /* "step": this one was it */
    }
    while (st->paused && st->step_budget == 0 && !lamina_interrupt_pending()) {
        if (!st->waiting) {
            j.refresh = 1;   /* the page sees where it waits */
            run_job(st, L, sidx, &j);
        }
        st->waiting = 1;
        struct timespec ts;
        clock_gettime(CLOCK_REALTIME, &ts);
        ts.tv_nsec += 100000000L;   /* Ctrl-C and SIGTERM are seen within 0.1 s */
        if (ts.tv_nsec >= 1000000000L) {
            ts.tv_sec++;
            ts.tv_nsec -= 1000000000L;
        }
        pthread_cond_timedwait(&st->cv, &st->mu, &ts);
        if (st->ncmds) {
            j.refresh = 0;
            run_job(st, L, sidx, &j);
        }
    }
    if (st->waiting) {
        st->waiting = 0;
        st->rate_wall = wb_now();   /* the pause is not slowness */
        st->rate_step = sim->step;
    }
    pthread_mutex_unlock(&st->mu);
    return j.changed;
}

static void on_param(void *ud, const char *name, int type, const char *value)
{
    serve_state *st = ud;
    pthread_mutex_lock(&st->mu);
    int i = 0;
    while (i < st->nparams && strcmp(st->params[i].name, name) != 0) i++;
    if (i == st->nparams && i < SERVE_MAX_PARAMS) {
        st->params[i].name = strdup(name);
        st->params[i].value = NULL;
        if (st->params[i].name) st->nparams++;
    }
    if (i < st->nparams) {
        char *v = strdup(value);
        if (v) {
            free(st->params[i].value);
            st->params[i].value = v;
        }
        st->params[i].type = type;
    }
    pthread_mutex_unlock(&st->mu);
}

/* out/f000120.png -> out/f#.png */
static char *frame_name(const char *path)
{
    size_t n = strlen(path);
    char *s = malloc(n + 1), *o = s;
    if (!s) return NULL;
    for (const char *p = path; *p;) {
        if (isdigit((unsigned char)*p)) {
            *o++ = '#';
            while (isdigit((unsigned char)*p)) p++;
        } else {
            *o++ = *p++;
        }
    }
    *o = 0;
    return s;
}

static void on_image(void *ud, const char *path)
{
    serve_state *st = ud;
    char *name = frame_name(path), *copy = strdup(path);
    if (!name || !copy) {
        free(name);
        free(copy);
        return;
    }
    pthread_mutex_lock(&st->mu);
    int i = 0;
    while (i < st->nframes && strcmp(st->frames[i].name, name) != 0) i++;
    if (i < st->nframes) {
        free(name);
        free(st->frames[i].path);
        st->frames[i].path = copy;
        st->frames[i].count++;
    } else if (i < SERVE_MAX_FRAMES) {
        st->frames[i] = (serve_frame){name, copy, 1};
        st->nframes++;
    } else {
        free(name);
        free(copy);
    }
    pthread_mutex_unlock(&st->mu);
}

static serve_series *find_series(serve_state *st, const void *id, const char *label, int ncols,
                                 const char *names, size_t stride)
{
    for (int i = 0; i < st->nseries; i++)
        if (st->series[i].id == id && st->series[i].ncols == ncols) return &st->series[i];
    if (st->nseries == SERVE_MAX_SERIES) return NULL;
    serve_series *s = &st->series[st->nseries];
    memset(s, 0, sizeof *s);
    s->ncols = ncols < SERVE_MAX_COLS ? ncols : SERVE_MAX_COLS;
    s->rows = malloc((size_t)SERVE_MAX_ROWS * (size_t)s->ncols * sizeof *s->rows);
    s->label = strdup(label);
    int ok = s->rows && s->label;
    for (int c = 0; ok && c < s->ncols; c++) ok = (s->names[c] = strdup(names + (size_t)c * stride)) != NULL;
    if (!ok) {
        free(s->rows);
        free(s->label);
        for (int c = 0; c < s->ncols; c++) free(s->names[c]);
        return NULL;
    }
    s->id = id;
    s->every = 1;
    st->nseries++;
    return s;
}

static void on_record(void *ud, const void *id, const char *label, int ncols, const char *names,
                      size_t stride, const double *row)
{
    serve_state *st = ud;
    pthread_mutex_lock(&st->mu);
    serve_series *s = find_series(st, id, label, ncols, names, stride);
    if (s && s->seen++ % s->every == 0) {
        if (s->nrows == SERVE_MAX_ROWS) {
            /* thin: keep rows 0, 2, 4, ... and one in twice as many from now on */
            size_t w = (size_t)s->ncols;
            for (size_t i = 0; 2 * i < s->nrows; i++)
                memmove(s->rows + i * w, s->rows + 2 * i * w, w * sizeof *s->rows);
            s->nrows = (s->nrows + 1) / 2;
            s->every *= 2;
            s->seen = 1;
        }
        memcpy(s->rows + s->nrows * (size_t)s->ncols, row, (size_t)s->ncols * sizeof *row);
        s->nrows++;
    }
    pthread_mutex_unlock(&st->mu);
}

const lamina_observer serve_observer_proto = {NULL, on_step, on_param, on_image, on_record};

/* ---- what the HTTP thread asks -------------------------------------- */

int serve_queue(serve_state *st, int kind, const char *name, const char *value, char *err,
                size_t len)
{
    if (kind == CMD_SETTING) {
        int k = 0;
        while (lamina_live_settings[k] && strcmp(lamina_live_settings[k], name) != 0) k++;
        if (!lamina_live_settings[k]) {
            snprintf(err, len, "'%s' is not a live setting (dt, gravity, pic, courant, damping)", name);
            return -1;
        }
    }
    pthread_mutex_lock(&st->mu);
    int rc = -1;
    if (kind == CMD_PARAM) {
        int i = 0;
        while (i < st->nparams && strcmp(st->params[i].name, name) != 0) i++;
        if (i == st->nparams) {
            snprintf(err, len, "the script has not read a parameter '%s'", name);
            goto out;
        }
    }
    if (st->finished) {
        snprintf(err, len, "the run has ended");
        goto out;
    }
    if (st->ncmds == SERVE_MAX_CMDS) {
        snprintf(err, len, "too many changes waiting for the next step");
        goto out;
    }
    serve_cmd *c = &st->cmds[st->ncmds];
    c->kind = kind;
    c->name = strdup(name);
    c->value = strdup(value);
    if (!c->name || !c->value) {
        free(c->name);
        free(c->value);
        snprintf(err, len, "out of memory");
        goto out;
    }
    st->ncmds++;
    pthread_cond_broadcast(&st->cv);
    rc = 0;
out:
    pthread_mutex_unlock(&st->mu);
    return rc;
}

int serve_control(serve_state *st, const char *action)
{
    int rc = 0;
    pthread_mutex_lock(&st->mu);
    if (strcmp(action, "pause") == 0) {
        st->paused = 1;
        st->step_budget = 0;
    } else if (strcmp(action, "resume") == 0) {
        st->paused = 0;
        st->step_budget = 0;
    } else if (strcmp(action, "step") == 0) {
        st->paused = 1;
        if (st->step_budget < 1000000) st->step_budget++;
    } else {
        rc = -1;
    }
    pthread_cond_broadcast(&st->cv);
    pthread_mutex_unlock(&st->mu);
    return rc;
}

int serve_frame_read(serve_state *st, const char *name, char **data, size_t *len)
{
    char *path = NULL;
    pthread_mutex_lock(&st->mu);
    for (int i = 0; i < st->nframes; i++)
        if (strcmp(st->frames[i].name, name) == 0) path = strdup(st->frames[i].path);
    pthread_mutex_unlock(&st->mu);
    if (!path) return -1;
    /* the file this run wrote under that name, read whole: images are
     * written to a temporary and renamed (atomic_file.h), never seen half */
    FILE *f = fopen(path, "rb");
    free(path);
    if (!f) return -2;
    struct stat sb;
    if (fstat(fileno(f), &sb) != 0 || !S_ISREG(sb.st_mode) || sb.st_size > FRAME_MAX) {
        fclose(f);
        return -2;
    }
    size_t n = (size_t)sb.st_size;
    char *buf = malloc(n ? n : 1);
    if (!buf || fread(buf, 1, n, f) != n) {
        free(buf);
        fclose(f);
        return -2;
    }
    fclose(f);
    *data = buf;
    *len = n;
    return 0;
}
