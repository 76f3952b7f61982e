/* serve_http.c - `lamina serve`'s HTTP side, on libmicrohttpd (Debian's
 * libmicrohttpd-dev): the page, JSON, the frames, the controls.
 *
 * Threat model (docs/security.md, "lamina serve"): the server binds
 * 127.0.0.1 unless --host names another address and --allow-remote says
 * so. Every request must carry a Host header naming the bound address (or,
 * on a loopback bind, localhost; on a wildcard bind, an IP literal), which
 * a DNS-rebinding page cannot give; a control (POST) must also carry
 * X-Lamina-Control: 1, which a cross-site form cannot set and a cross-site
 * script cannot without a CORS preflight that is never answered. Bodies
 * are at most BODY_MAX bytes; connections are bounded in number (in all,
 * per client address), memory and idle time. Only files this run wrote
 * are served, looked up by their series name in the run's own table. */
#include <arpa/inet.h>
#include <microhttpd.h>
#include <netdb.h>
#include <netinet/in.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>

#include "serve.h"

#define BODY_MAX 4096          /* bytes of a control request's body */
#define CONN_MAX 32            /* connections at once */
#define CONN_PER_IP 8
#define CONN_TIMEOUT 15        /* s idle before a connection is closed */
#define CONN_MEMORY (128 * 1024)
#define LOG_MAX 20             /* libmicrohttpd's messages kept in the run log */

struct serve_http {
    struct MHD_Daemon *d;
    serve_state *st;
    char host[256];            /* as given to --host */
    unsigned port;
    int loopback, wildcard;
    int logged;                /* libmicrohttpd messages so far */
};

/* per request: the body read so far */
typedef struct request {
    char body[BODY_MAX + 1];
    size_t len;
} request;

/* ---- answers ---------------------------------------------------------- */

static enum MHD_Result answer(struct MHD_Connection *c, unsigned code, const char *type,
                              char *data, size_t len, int owned)
{
    struct MHD_Response *r =
        owned ? MHD_create_response_from_buffer(len, data, MHD_RESPMEM_MUST_FREE)
              : MHD_create_response_from_buffer(len, data, MHD_RESPMEM_PERSISTENT);
    if (!r) {
        if (owned) free(data);
        return MHD_NO;
    }
    MHD_add_response_header(r, MHD_HTTP_HEADER_CONTENT_TYPE, type);
    MHD_add_response_header(r, MHD_HTTP_HEADER_CACHE_CONTROL, "no-store");
    MHD_add_response_header(r, "X-Content-Type-Options", "nosniff");
    MHD_add_response_header(r, "X-Frame-Options", "DENY");
    MHD_add_response_header(r, "Referrer-Policy", "no-referrer");
    /* the page's own inline script and style, images and JSON from here,
     * nothing from anywhere else */
    MHD_add_response_header(r, "Content-Security-Policy",
                            "default-src 'none'; script-src 'unsafe-inline'; "
                            "style-src 'unsafe-inline'; img-src 'self'; connect-src 'self'; "
                            "base-uri 'none'; form-action 'none'; frame-ancestors 'none'");
    if (code == MHD_HTTP_METHOD_NOT_ALLOWED)
        MHD_add_response_header(r, MHD_HTTP_HEADER_ALLOW, "GET, HEAD, POST");
    enum MHD_Result rc = MHD_queue_response(c, code, r);
    MHD_destroy_response(r);
    return rc;
}

/* {"error": why} with the code */
static enum MHD_Result error(struct MHD_Connection *c, unsigned code, const char *why)
{
    sbuf b = {0};
    sb_str(&b, "{\"error\":");
    sb_json(&b, why);
    sb_str(&b, "}\n");
    if (b.bad) {
        free(b.s);
        return MHD_NO;
    }
    return answer(c, code, "application/json", b.s, b.n, 1);
}

static enum MHD_Result json(struct MHD_Connection *c, sbuf *b)
{
    sb_str(b, "\n");
    if (b->bad) {
        free(b->s);
        return error(c, MHD_HTTP_INTERNAL_SERVER_ERROR, "out of memory");
    }
    return answer(c, MHD_HTTP_OK, "application/json", b->s, b->n, 1);
}

/* ---- guards ----------------------------------------------------------- */

/* The Host header names this server: "NAME:PORT" with NAME the bound
 * address, or localhost / a loopback literal on a loopback bind, or any IP
 * literal on a wildcard bind (a rebinding attack needs a DNS name). */
static int host_ok(const serve_http *h, const char *host)
{
    if (!host) return 0;
    const char *colon = strrchr(host, ':');
    if (!colon || (strchr(host, ']') && colon < strchr(host, ']'))) return 0;
    char *end;
    unsigned long port = strtoul(colon + 1, &end, 10);
    if (*end || colon[1] == 0 || port != h->port) return 0;
    size_t n = (size_t)(colon - host);
    char name[256];
    if (n == 0 || n >= sizeof name) return 0;
    memcpy(name, host, n);
    name[n] = 0;
    if (strcmp(name, h->host) == 0) return 1;
    char bare[256];
    snprintf(bare, sizeof bare, "%s", name);
    if (bare[0] == '[' && n >= 2 && bare[n - 1] == ']') {
        memmove(bare, bare + 1, n - 2);
        bare[n - 2] = 0;
        if (strcmp(bare, h->host) == 0) return 1;
    }
    unsigned char addr[16];
    int v4 = inet_pton(AF_INET, bare, addr) == 1, v6 = inet_pton(AF_INET6, bare, addr) == 1;
    if (h->wildcard) return v4 || v6;
    if (h->loopback)
        return strcmp(bare, "localhost") == 0 || (v4 && addr[0] == 127) ||
               (v6 && strcmp(bare, "::1") == 0);
    return 0;
}

/* key's value in a form body "a=1&b=2", unescaped, into out; 0 when absent
 * or too long */
static int form_value(const char *body, const char *key, char *out, size_t len)
{
    size_t k = strlen(key);
    for (const char *p = body; p && *p;) {
        const char *amp = strchr(p, '&');
        size_t n = amp ? (size_t)(amp - p) : strlen(p);
        if (n > k && strncmp(p, key, k) == 0 && p[k] == '=') {
            size_t m = n - k - 1;
            if (m >= len) return 0;
            memcpy(out, p + k + 1, m);
            out[m] = 0;
            for (char *q = out; *q; q++)
                if (*q == '+') *q = ' ';
            MHD_http_unescape(out);
            return 1;
        }
        p = amp ? amp + 1 : NULL;
    }
    return 0;
}

/* a name or value from the page: printable ASCII only, non-empty */
static int plain(const char *s)
{
    if (!*s) return 0;
    for (const unsigned char *p = (const unsigned char *)s; *p; p++)
        if (*p < 0x20 || *p >= 0x7f) return 0;
    return 1;
}

/* ---- routes ----------------------------------------------------------- */

static enum MHD_Result get(serve_http *h, struct MHD_Connection *c, const char *url)
{
    if (strcmp(url, "/") == 0 || strcmp(url, "/index.html") == 0)
        return answer(c, MHD_HTTP_OK, "text/html; charset=us-ascii", (char *)serve_page_html,
                      serve_page_html_len, 0);
    sbuf b = {0};
    if (strcmp(url, "/api/state") == 0) {
        serve_json_state(h->st, &b);
        return json(c, &b);
    }
    if (strcmp(url, "/api/params") == 0) {
        serve_json_params(h->st, &b);
        return json(c, &b);
    }
    if (strcmp(url, "/api/records") == 0) {
        serve_json_records(h->st, &b);
        return json(c, &b);
    }
    if (strncmp(url, "/frame/", 7) == 0) {
        const char *name = url + 7;
        /* a frame is named by its series (its path, digits as '#'), looked
         * up in this run's table: nothing else on disk can be named; a
         * ".." or a control byte is refused before the look-up */
        if (!plain(name) || strstr(name, ".."))
            return error(c, MHD_HTTP_BAD_REQUEST, "a frame name is printable and has no '..'");
        char *data;
        size_t len;
        int rc = serve_frame_read(h->st, name, &data, &len);
        if (rc == -1) return error(c, MHD_HTTP_NOT_FOUND, "no frame of that name in this run");
        if (rc < 0) return error(c, MHD_HTTP_INTERNAL_SERVER_ERROR, "the frame cannot be read");
        return answer(c, MHD_HTTP_OK, "image/png", data, len, 1);
    }
    return error(c, MHD_HTTP_NOT_FOUND, "no such page");
}

static enum MHD_Result post(serve_http *h, struct MHD_Connection *c, const char *url,
                            const request *rq)
{
    char name[256], value[1024], err[600];
    if (strcmp(url, "/api/control") == 0) {
        if (!form_value(rq->body, "action", name, sizeof name))
            return error(c, MHD_HTTP_BAD_REQUEST, "action=pause|resume|step is expected");
        if (serve_control(h->st, name) != 0)
            return error(c, MHD_HTTP_BAD_REQUEST, "action must be pause, resume or step");
    } else {
        int kind = strcmp(url, "/api/param") == 0 ? CMD_PARAM : CMD_SETTING;
        if (!form_value(rq->body, "name", name, sizeof name) ||
            !form_value(rq->body, "value", value, sizeof value) || !plain(name) ||
            !plain(value))
            return error(c, MHD_HTTP_BAD_REQUEST,
                         "name=...&value=... (printable ASCII, not empty) is expected");
        if (serve_queue(h->st, kind, name, value, err, sizeof err) != 0)
            return error(c, MHD_HTTP_BAD_REQUEST, err);
    }
    sbuf b = {0};
    sb_str(&b, "{\"ok\":true}");
    return json(c, &b);
}

static int is_post_route(const char *url)
{
    return strcmp(url, "/api/control") == 0 || strcmp(url, "/api/param") == 0 ||
           strcmp(url, "/api/setting") == 0;
}

static enum MHD_Result handle(void *cls, struct MHD_Connection *c, const char *url,
                              const char *method, const char *version, const char *upload,
                              size_t *upload_size, void **ctx)
{
    (void)version;
    serve_http *h = cls;
    int is_get = strcmp(method, MHD_HTTP_METHOD_GET) == 0 ||
                 strcmp(method, MHD_HTTP_METHOD_HEAD) == 0;
    int is_post = strcmp(method, MHD_HTTP_METHOD_POST) == 0;
    if (!*ctx) {
        /* first call, headers only: refuse what needs no body first */
        request *rq = calloc(1, sizeof *rq);
        if (!rq) return MHD_NO;
        *ctx = rq;
        if (!host_ok(h, MHD_lookup_connection_value(c, MHD_HEADER_KIND, "Host")))
            return error(c, MHD_HTTP_FORBIDDEN, "the Host header does not name this server");
        if (!is_get && !is_post)
            return error(c, MHD_HTTP_METHOD_NOT_ALLOWED, "GET, HEAD or POST");
        if (is_post != is_post_route(url)) {
            int known = is_post_route(url) || strcmp(url, "/") == 0 ||
                        strncmp(url, "/api/", 5) == 0 || strncmp(url, "/frame/", 7) == 0;
            return known ? error(c, MHD_HTTP_METHOD_NOT_ALLOWED,
                                 is_post ? "this page takes GET" : "this control takes POST")
                         : error(c, MHD_HTTP_NOT_FOUND, "no such page");
        }
        if (is_post) {
            const char *ctl = MHD_lookup_connection_value(c, MHD_HEADER_KIND, "X-Lamina-Control");
            if (!ctl || strcmp(ctl, "1") != 0)
                return error(c, MHD_HTTP_FORBIDDEN, "a control needs the header X-Lamina-Control: 1");
            const char *cl = MHD_lookup_connection_value(c, MHD_HEADER_KIND,
                                                         MHD_HTTP_HEADER_CONTENT_LENGTH);
            if (cl && strtoull(cl, NULL, 10) > BODY_MAX)
                return error(c, MHD_HTTP_CONTENT_TOO_LARGE, "the body is over 4096 bytes");
        }
        return MHD_YES;
    }
    request *rq = *ctx;
    if (*upload_size) {
        if (rq->len + *upload_size > BODY_MAX) {
            /* a body without Content-Length (chunked) that grows past the
             * bound: libmicrohttpd takes no answer in the middle of a body,
             * so the connection is closed; the rest is never read */
            return MHD_NO;
        }
        memcpy(rq->body + rq->len, upload, *upload_size);
        rq->len += *upload_size;
        *upload_size = 0;
        return MHD_YES;
    }
    if (is_get) return get(h, c, url);
    rq->body[rq->len] = 0;
    if (memchr(rq->body, 0, rq->len))
        return error(c, MHD_HTTP_BAD_REQUEST, "the body holds a NUL byte");
    return post(h, c, url, rq);
}

static void completed(void *cls, struct MHD_Connection *c, void **ctx,
                      enum MHD_RequestTerminationCode why)
{
    (void)cls;
    (void)c;
    (void)why;
    free(*ctx);
    *ctx = NULL;
}

/* ---- the daemon ------------------------------------------------------- */

/* libmicrohttpd's own messages (a connection over the limit, a malformed
 * request) go to the run log as lines of their own, named, and at most
 * LOG_MAX of them: a flood of bad requests cannot flood the log. Called on
 * its thread only. */
static void mhd_log(void *cls, const char *fmt, va_list ap)
{
    serve_http *h = cls;
    if (h->logged > LOG_MAX) return;
    if (h->logged++ == LOG_MAX) {
        fprintf(stderr, "lamina serve: http: further messages of the HTTP library left out\n");
        return;
    }
    char buf[512];
    vsnprintf(buf, sizeof buf, fmt, ap);
    size_t n = strlen(buf);
    while (n && (buf[n - 1] == '\n' || buf[n - 1] == '\r')) buf[--n] = 0;
    for (char *p = buf; *p; p++)   /* it may quote what a client sent */
        if ((unsigned char)*p < 0x20 || (unsigned char)*p >= 0x7f) *p = '?';
    fprintf(stderr, "lamina serve: http: %s\n", buf);
}

static int resolve(const char *host, struct sockaddr_storage *ss, socklen_t *len)
{
    struct addrinfo hints, *res = NULL;
    memset(&hints, 0, sizeof hints);
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_flags = AI_PASSIVE;
    if (getaddrinfo(host, NULL, &hints, &res) != 0 || !res) return -1;
    memcpy(ss, res->ai_addr, res->ai_addrlen);
    *len = res->ai_addrlen;
    freeaddrinfo(res);
    return 0;
}

static int addr_loopback(const struct sockaddr_storage *ss)
{
    if (ss->ss_family == AF_INET)
        return (ntohl(((const struct sockaddr_in *)ss)->sin_addr.s_addr) >> 24) == 127;
    if (ss->ss_family == AF_INET6)
        return IN6_IS_ADDR_LOOPBACK(&((const struct sockaddr_in6 *)ss)->sin6_addr);
    return 0;
}

static int addr_wildcard(const struct sockaddr_storage *ss)
{
    if (ss->ss_family == AF_INET)
        return ((const struct sockaddr_in *)ss)->sin_addr.s_addr == htonl(INADDR_ANY);
    if (ss->ss_family == AF_INET6)
        return IN6_IS_ADDR_UNSPECIFIED(&((const struct sockaddr_in6 *)ss)->sin6_addr);
    return 0;
}

int serve_host_is_loopback(const char *host)
{
    struct sockaddr_storage ss;
    socklen_t len;
    if (resolve(host, &ss, &len) != 0) return -1;
    return addr_loopback(&ss);
}

serve_http *serve_http_start(serve_state *st, const serve_opts *o)
{
    serve_http *h = calloc(1, sizeof *h);
    if (!h) return NULL;
    h->st = st;
    snprintf(h->host, sizeof h->host, "%s", o->host);
    struct sockaddr_storage ss;
    socklen_t len;
    if (resolve(o->host, &ss, &len) != 0) {
        fprintf(stderr, "lamina serve: --host %s: not an address of this machine\n", o->host);
        free(h);
        return NULL;
    }
    h->loopback = addr_loopback(&ss);
    h->wildcard = addr_wildcard(&ss);
    if (ss.ss_family == AF_INET) ((struct sockaddr_in *)&ss)->sin_port = htons((uint16_t)o->port);
    else ((struct sockaddr_in6 *)&ss)->sin6_port = htons((uint16_t)o->port);
    unsigned flags = MHD_USE_AUTO | MHD_USE_INTERNAL_POLLING_THREAD | MHD_USE_ERROR_LOG;
    if (ss.ss_family == AF_INET6) flags |= MHD_USE_IPv6;
    h->d = MHD_start_daemon(flags, (uint16_t)o->port, NULL, NULL, handle, h,
                            /* first, so that every message goes through it */
                            MHD_OPTION_EXTERNAL_LOGGER, mhd_log, h,
                            MHD_OPTION_SOCK_ADDR, (struct sockaddr *)&ss,
                            MHD_OPTION_CONNECTION_LIMIT, (unsigned)CONN_MAX,
                            MHD_OPTION_PER_IP_CONNECTION_LIMIT, (unsigned)CONN_PER_IP,
                            MHD_OPTION_CONNECTION_TIMEOUT, (unsigned)CONN_TIMEOUT,
                            MHD_OPTION_CONNECTION_MEMORY_LIMIT, (size_t)CONN_MEMORY,
                            MHD_OPTION_NOTIFY_COMPLETED, completed, NULL,
                            MHD_OPTION_END);
    if (!h->d) {
        fprintf(stderr, "lamina serve: cannot listen on %s port %ld (in use, or not allowed)\n",
                o->host, o->port);
        free(h);
        return NULL;
    }
    const union MHD_DaemonInfo *info = MHD_get_daemon_info(h->d, MHD_DAEMON_INFO_BIND_PORT);
    h->port = info ? info->port : (unsigned)o->port;
    int v6 = ss.ss_family == AF_INET6;
    printf("lamina serve: http://%s%s%s:%u/\n", v6 ? "[" : "", o->host, v6 ? "]" : "", h->port);
    fflush(stdout);
    return h;
}

void serve_http_stop(serve_http *h)
{
    if (!h) return;
    MHD_stop_daemon(h->d);
    free(h);
}
