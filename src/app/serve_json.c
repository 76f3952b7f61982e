/* serve_json.c - `lamina serve`'s JSON answers: /api/state, /api/params,
 * /api/records. Every name that reaches the page (a script's parameter,
 * a file, a column) is escaped here as a JSON string whose bytes are all
 * printable ASCII, < > & ' included, so that no answer can be read as
 * markup; the page itself writes them as text, never as HTML. */
#include <lua.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "serve.h"
#include "workbench.h"

void sb_add(sbuf *b, const char *s, size_t n)
{
    if (b->bad) return;
    if (b->n + n + 1 > b->cap) {
        size_t cap = b->cap ? b->cap : 1024;
        while (cap < b->n + n + 1) cap *= 2;
        char *p = realloc(b->s, cap);
        if (!p) {
            b->bad = 1;
            return;
        }
        b->s = p;
        b->cap = cap;
    }
    memcpy(b->s + b->n, s, n);
    b->n += n;
    b->s[b->n] = 0;
}

void sb_str(sbuf *b, const char *s)
{
    sb_add(b, s, strlen(s));
}

void sb_fmt(sbuf *b, const char *fmt, ...)
{
    char buf[512];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    if (n < 0) return;
    sb_add(b, buf, (size_t)n < sizeof buf ? (size_t)n : sizeof buf - 1);
}

void sb_json(sbuf *b, const char *s)
{
    sb_add(b, "\"", 1);
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        unsigned char c = *p;
        if (c == '"' || c == '\\') {
            char e[2] = {'\\', (char)c};
            sb_add(b, e, 2);
        } else if (c < 0x20 || c >= 0x7f || c == '<' || c == '>' || c == '&' || c == '\'') {
            /* a byte above 0x7f as the code point of the same number: the
             * name reads back byte for byte (Latin-1), never as invalid UTF-8 */
            char e[8];
            snprintf(e, sizeof e, "\\u%04x", c);
            sb_add(b, e, 6);
        } else {
            sb_add(b, (const char *)p, 1);
        }
    }
    sb_add(b, "\"", 1);
}

void sb_named(sbuf *b, int i, const char *name)
{
    sb_str(b, i ? ",{\"name\":" : "{\"name\":");
    sb_json(b, name);
}

void sb_num(sbuf *b, double v)
{
    if (isfinite(v)) sb_fmt(b, "%.10g", v);
    else sb_str(b, "null");
}

void serve_json_state(serve_state *st, sbuf *b)
{
    pthread_mutex_lock(&st->mu);
    sb_str(b, "{\"script\":");
    sb_json(b, st->script);
    sb_str(b, ",\"t\":");
    sb_num(b, st->t);
    sb_fmt(b, ",\"step\":%ld,\"dt\":", st->step);
    sb_num(b, st->dt);
    sb_str(b, ",\"rate\":");
    sb_num(b, st->rate);
    sb_str(b, ",\"wall\":");
    sb_num(b, wb_now() - st->wall0);
    if (st->have_energy) {
        sb_str(b, ",\"energy\":{\"kinetic\":");
        sb_num(b, st->energy.kinetic);
        sb_str(b, ",\"strain\":");
        sb_num(b, st->energy.strain);
        sb_str(b, ",\"internal\":");
        sb_num(b, st->energy.internal);
        sb_str(b, ",\"potential\":");
        sb_num(b, st->energy.potential);
        sb_str(b, ",\"total\":");
        sb_num(b, st->energy.total);
        sb_str(b, ",\"t\":");
        sb_num(b, st->energy_t);
        sb_str(b, "}");
    } else {
        sb_str(b, ",\"energy\":null");
    }
    sb_fmt(b, ",\"paused\":%s,\"waiting\":%s,\"finished\":%s,\"status\":%d,\"pending\":%d",
           st->paused ? "true" : "false", st->waiting ? "true" : "false",
           st->finished ? "true" : "false", st->status, st->ncmds);
    sb_str(b, ",\"frames\":[");
    for (int i = 0; i < st->nframes; i++) {
        sb_named(b, i, st->frames[i].name);
        sb_str(b, ",\"file\":");
        sb_json(b, st->frames[i].path);
        sb_fmt(b, ",\"count\":%ld}", st->frames[i].count);
    }
    sb_fmt(b, "],\"nmsgs\":%ld,\"msgs\":[", st->nmsgs);
    long first = st->nmsgs > SERVE_MAX_MSGS ? st->nmsgs - SERVE_MAX_MSGS : 0;
    for (long k = first; k < st->nmsgs; k++) {
        if (k > first) sb_str(b, ",");
        sb_json(b, st->msgs[k % SERVE_MAX_MSGS] ? st->msgs[k % SERVE_MAX_MSGS] : "");
    }
    sb_str(b, "]}");
    pthread_mutex_unlock(&st->mu);
}

void serve_json_params(serve_state *st, sbuf *b)
{
    pthread_mutex_lock(&st->mu);
    sb_str(b, "{\"params\":[");
    for (int i = 0; i < st->nparams; i++) {
        const serve_param *p = &st->params[i];
        sb_named(b, i, p->name);
        sb_str(b, ",\"type\":");
        sb_json(b, p->type == LUA_TNUMBER ? "number"
                   : p->type == LUA_TBOOLEAN ? "boolean" : "string");
        sb_str(b, ",\"value\":");
        sb_json(b, p->value ? p->value : "");
        sb_str(b, "}");
    }
    sb_str(b, "],\"settings\":[");
    for (int k = 0; st->have_settings && lamina_live_settings[k] && k < 5; k++) {
        sb_named(b, k, lamina_live_settings[k]);
        sb_str(b, ",\"value\":");
        sb_json(b, st->settings[k]);
        sb_str(b, "}");
    }
    sb_str(b, "]}");
    pthread_mutex_unlock(&st->mu);
}

void serve_json_records(serve_state *st, sbuf *b)
{
    pthread_mutex_lock(&st->mu);
    sb_str(b, "{\"records\":[");
    for (int i = 0; i < st->nseries; i++) {
        const serve_series *s = &st->series[i];
        sb_named(b, i, s->label);
        sb_fmt(b, ",\"every\":%ld,\"columns\":[", s->every);
        for (int c = 0; c < s->ncols; c++) {
            if (c) sb_str(b, ",");
            sb_json(b, s->names[c]);
        }
        sb_str(b, "],\"rows\":[");
        for (size_t r = 0; r < s->nrows; r++) {
            sb_str(b, r ? ",[" : "[");
            for (int c = 0; c < s->ncols; c++) {
                if (c) sb_str(b, ",");
                sb_num(b, s->rows[r * (size_t)s->ncols + (size_t)c]);
            }
            sb_str(b, "]");
        }
        sb_str(b, "]}");
    }
    sb_str(b, "]}");
    pthread_mutex_unlock(&st->mu);
}
