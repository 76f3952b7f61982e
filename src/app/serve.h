/* serve.h - `lamina serve` (docs/workbench.md, "lamina serve"): the run's
 * thread and the HTTP thread share one serve_state under its mutex. */
#ifndef LAMINA_SERVE_H
#define LAMINA_SERVE_H

#include <pthread.h>
#include <stddef.h>

#include "lamina_lua.h"
#include "mpm.h"

/* A growing string (JSON answers); on out of memory it stays short and
 * bad is set: the answer is then a 500. */
typedef struct sbuf {
    char *s;
    size_t n, cap;
    int bad;
} sbuf;
void sb_add(sbuf *b, const char *s, size_t n);
void sb_str(sbuf *b, const char *s);
void sb_fmt(sbuf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* s as a JSON string, quotes included: every byte that is not printable
 * ASCII, and < > & ' (the answer may be shown as HTML), as \u00XX */
void sb_json(sbuf *b, const char *s);
/* the opening of a list's object number i (from 0) with its name:
 * {"name":NAME, with a comma before it but the first */
void sb_named(sbuf *b, int i, const char *name);
/* a number as JSON (null when not finite) */
void sb_num(sbuf *b, double v);

enum { SERVE_MAX_FRAMES = 64, SERVE_MAX_PARAMS = 64, SERVE_MAX_SERIES = 16,
       SERVE_MAX_COLS = 32, SERVE_MAX_ROWS = 2000, SERVE_MAX_CMDS = 64,
       SERVE_MAX_MSGS = 50 };

/* A frame file series: the images whose paths differ only in digits
 * (out/f000010.png, out/f000020.png, ...) are one panel, named by the path
 * with its digit runs as '#'. */
typedef struct serve_frame {
    char *name, *path;   /* the name; the latest file written */
    long count;          /* images written under the name */
} serve_frame;

typedef struct serve_param {
    char *name, *value;
    int type;            /* LUA_TNUMBER, LUA_TBOOLEAN, LUA_TSTRING */
} serve_param;

/* A recorder's rows, thinned to at most SERVE_MAX_ROWS: when full, every
 * other row is dropped and from then on one row in `every` is kept. */
typedef struct serve_series {
    const void *id;
    char *label;
    int ncols;
    char *names[SERVE_MAX_COLS];
    double *rows;        /* SERVE_MAX_ROWS * ncols */
    size_t nrows;
    long every, seen;
} serve_series;

enum { CMD_PARAM, CMD_SETTING };
typedef struct serve_cmd {
    int kind;
    char *name, *value;
} serve_cmd;

typedef struct serve_state {
    pthread_mutex_t mu;
    pthread_cond_t cv;
    const char *script;
    /* progress, refreshed by the run's thread */
    double t, dt, rate, wall0, rate_wall;
    long step, rate_step;
    lm_energy energy;
    int have_energy;
    double energy_t;        /* the time the energy was summed at (refreshed every REFRESH s) */
    double last_refresh;
    char settings[5][96];   /* lamina_live_settings' values, as text */
    int have_settings;
    /* control */
    int paused, waiting;     /* asked to pause; the run waits at a step */
    long step_budget;        /* steps to take while paused */
    int finished, status;    /* the script ended, with its exit status */
    serve_cmd cmds[SERVE_MAX_CMDS];
    int ncmds;
    /* what the run showed */
    serve_frame frames[SERVE_MAX_FRAMES];
    int nframes;
    serve_param params[SERVE_MAX_PARAMS];
    int nparams;
    serve_series series[SERVE_MAX_SERIES];
    int nseries;
    char *msgs[SERVE_MAX_MSGS];   /* the page's log: changes applied, refusals */
    long nmsgs;                   /* ever added; the last SERVE_MAX_MSGS kept */
} serve_state;

int serve_state_init(serve_state *st, const char *script);
void serve_state_free(serve_state *st);
/* the hooks the run calls (lamina_observer) */
extern const lamina_observer serve_observer_proto;
/* a message for the page's log (under the lock) */
void serve_msg(serve_state *st, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* JSON answers (take the lock themselves) */
void serve_json_state(serve_state *st, sbuf *b);
void serve_json_params(serve_state *st, sbuf *b);
void serve_json_records(serve_state *st, sbuf *b);
/* The latest file of the frame series `name`, read whole (at most 64 MB);
 * 0, -1 when no such series (404), -2 when it cannot be read (500). */
int serve_frame_read(serve_state *st, const char *name, char **data, size_t *len);
/* Queues a change for the run's next step boundary: 0, or -1 with err
 * (queue full, a name that is not a parameter or setting). */
int serve_queue(serve_state *st, int kind, const char *name, const char *value, char *err,
                size_t len);
/* pause, resume, step */
int serve_control(serve_state *st, const char *action);

/* serve_http.c: the daemon */
typedef struct serve_http serve_http;
typedef struct serve_opts {
    const char *host;   /* default 127.0.0.1 */
    long port;          /* 0: any free port */
    int allow_remote;
} serve_opts;
/* Binds and starts serving; prints the address on stdout. NULL with a
 * message on stderr when it cannot. */
serve_http *serve_http_start(serve_state *st, const serve_opts *o);
void serve_http_stop(serve_http *h);
/* 1 when host (an address or name, as given to --host) is a loopback
 * address; -1 when it does not resolve */
int serve_host_is_loopback(const char *host);

extern const char serve_page_html[];
extern const size_t serve_page_html_len;

#endif
