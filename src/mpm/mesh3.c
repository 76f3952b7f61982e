/* mesh3.c - OBJ and STL triangle meshes read with every allocation bounded
 * and every malformed input refused by file, line or triangle (mesh3.h).
 * The inside test and the closedness check are here too; the sampling of a
 * mesh into membrane points is sim3_membrane_surface.c's. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "edge_order.h"
#include "mesh3.h"
#include "util.h"

static const double pi = 3.14159265358979323846;

void lm3_mesh_free(lm3_mesh *m)
{
    if (!m) return;
    free(m->xyz);
    free(m->tri);
    memset(m, 0, sizeof *m);
}

/* ---- building: vertices and triangles, bounded -------------------------- */

typedef struct build {
    lm3_mesh m;
    size_t vcap, tcap;
} build;

static int add_vertex(build *b, const double x[3])
{
    if (b->m.nv >= LM3_MESH_MAX_VERTICES) return -1;
    if (lu_reserve(&b->m.xyz, &b->vcap, 3 * (b->m.nv + 1), sizeof(double), 3 * 256) != 0)
        return -2;
    memcpy(b->m.xyz + 3 * b->m.nv, x, 3 * sizeof(double));
    b->m.nv++;
    return 0;
}

static int add_triangle(build *b, int32_t i, int32_t j, int32_t k)
{
    if (b->m.nt >= LM3_MESH_MAX_TRIANGLES) return -1;
    if (lu_reserve(&b->m.tri, &b->tcap, 3 * (b->m.nt + 1), sizeof(int32_t), 3 * 256) != 0)
        return -2;
    int32_t *t = b->m.tri + 3 * b->m.nt++;
    t[0] = i;
    t[1] = j;
    t[2] = k;
    return 0;
}

/* The message for add_*'s failure. */
static void limit_err(int rc, const char *name, const char *where, char *err, size_t errlen)
{
    if (rc == -1)
        lu_err(err, errlen, "%s: %s: more than %zu vertices or %zu triangles", name, where,
               LM3_MESH_MAX_VERTICES, LM3_MESH_MAX_TRIANGLES);
    else
        lu_err(err, errlen, "%s: %s: out of memory", name, where);
}

/* ---- lines of text ---------------------------------------------------------- */

typedef struct cursor {
    const char *p, *end;
    size_t line;
} cursor;

/* The next line [*s, *e) without its newline (\n or \r\n); 0 at the end. */
static int next_line(cursor *c, const char **s, const char **e)
{
    if (c->p >= c->end) return 0;
    const char *q = memchr(c->p, '\n', (size_t)(c->end - c->p));
    const char *stop = q ? q : c->end;
    *s = c->p;
    *e = stop > c->p && stop[-1] == '\r' ? stop - 1 : stop;
    c->p = q ? q + 1 : c->end;
    c->line++;
    return 1;
}

static int is_space(char ch)
{
    return ch == ' ' || ch == '\t' || ch == '\f' || ch == '\v';
}

/* The next word of [*p, e) into w (at most wlen - 1 characters; longer
 * words are cut and flagged by the caller's parse): its length, 0 at the
 * line's end. */
static size_t word(const char **p, const char *e, char *w, size_t wlen)
{
    while (*p < e && is_space(**p)) (*p)++;
    size_t n = 0;
    while (*p < e && !is_space(**p)) {
        if (n + 1 < wlen) w[n] = **p;
        n++;
        (*p)++;
    }
    w[n + 1 < wlen ? n : wlen - 1] = 0;
    return n;
}

/* A finite number, the whole word: 0, else -1. */
static int number(const char *w, size_t n, double *v)
{
    if (n == 0 || n >= 64) return -1;
    char *end;
    errno = 0;
    *v = strtod(w, &end);
    if (end == w || *end != 0 || !isfinite(*v)) return -1;
    return 0;
}

/* ---- OBJ ------------------------------------------------------------------- */

/* One index of a face corner ("7", "7/2", "7//3", "-1/..."): the vertex,
 * from 0, or -1 with why. */
static long obj_index(const char *w, size_t nv, const char **why)
{
    char *end;
    errno = 0;
    long v = strtol(w, &end, 10);
    if (end == w || (*end != 0 && *end != '/') || errno) {
        *why = "not a vertex index";
        return -1;
    }
    if (v == 0) {
        *why = "vertex index 0 (OBJ counts from 1)";
        return -1;
    }
    long i = v > 0 ? v - 1 : (long)nv + v;
    if (i < 0 || (size_t)i >= nv) {
        *why = "names a vertex not defined before it";
        return -1;
    }
    return i;
}

static int parse_obj(const char *name, const char *buf, size_t len, build *b, char *err,
                     size_t errlen)
{
    static const char *const ignored[] = {"vt", "vn", "vp", "o", "g", "s", "usemtl",
                                          "mtllib", "l", "p"};
    cursor c = {buf, buf + len, 0};
    const char *s, *e;
    char w[72];
    while (next_line(&c, &s, &e)) {
        const char *p = s;
        size_t n = word(&p, e, w, sizeof w);
        if (n == 0 || w[0] == '#') continue;
        if (strcmp(w, "v") == 0) {
            double x[3];
            for (int a = 0; a < 3; a++) {
                n = word(&p, e, w, sizeof w);
                if (number(w, n, &x[a]) != 0) {
                    lu_err(err, errlen, "%s:%zu: vertex coordinate %d is %s'%.20s' (a finite "
                           "number expected)", name, c.line, a + 1, n ? "" : "missing: ", w);
                    return -1;
                }
            }
            /* an optional fourth (w) or colour values after: ignored */
            int rc = add_vertex(b, x);
            if (rc) {
                char where[32];
                snprintf(where, sizeof where, "line %zu", c.line);
                limit_err(rc, name, where, err, errlen);
                return -1;
            }
        } else if (strcmp(w, "f") == 0) {
            long first = -1, prev = -1;
            int k = 0;
            while ((n = word(&p, e, w, sizeof w)) > 0) {
                const char *why = NULL;
                long i = n < sizeof w - 1 ? obj_index(w, b->m.nv, &why) : -1;
                if (i < 0) {
                    lu_err(err, errlen, "%s:%zu: face corner %d '%.20s': %s", name, c.line, k + 1,
                           w, why ? why : "too long");
                    return -1;
                }
                if (k == 0) first = i;
                else if (k >= 2) {
                    int rc = add_triangle(b, (int32_t)first, (int32_t)prev, (int32_t)i);
                    if (rc) {
                        char where[32];
                        snprintf(where, sizeof where, "line %zu", c.line);
                        limit_err(rc, name, where, err, errlen);
                        return -1;
                    }
                }
                prev = i;
                k++;
            }
            if (k < 3) {
                lu_err(err, errlen, "%s:%zu: a face needs 3 or more corners (got %d)", name,
                       c.line, k);
                return -1;
            }
        } else {
            size_t i = 0, ni = sizeof ignored / sizeof *ignored;
            while (i < ni && strcmp(w, ignored[i]) != 0) i++;
            if (i == ni) {
                lu_err(err, errlen, "%s:%zu: unknown OBJ statement '%.20s' (v and f are read; "
                       "vt vn vp o g s usemtl mtllib l p ignored)", name, c.line, w);
                return -1;
            }
        }
    }
    return 0;
}

/* ---- STL -------------------------------------------------------------------- */

/* The next non-blank line's words must be exactly the keywords kw (and,
 * when nnum > 0, nnum numbers after them into v): 0, else -1 with err. */
static int stl_expect(const char *name, cursor *c, const char *kw, int nnum, double *v,
                      char *err, size_t errlen)
{
    const char *s, *e;
    char w[72];
    do {
        if (!next_line(c, &s, &e)) {
            lu_err(err, errlen, "%s:%zu: the file ends where '%s' was expected", name, c->line,
                   kw);
            return -1;
        }
        const char *p = s;
        if (word(&p, e, w, sizeof w) > 0) break;
    } while (1);
    const char *p = s, *k = kw;
    while (*k) {
        char want[24];
        size_t l = strcspn(k, " ");
        snprintf(want, sizeof want, "%.*s", (int)l, k);
        k += l;
        while (*k == ' ') k++;
        size_t n = word(&p, e, w, sizeof w);
        if (n == 0 || strcmp(w, want) != 0) {
            lu_err(err, errlen, "%s:%zu: '%.20s' where '%s' was expected", name, c->line,
                   n ? w : "(end of line)", kw);
            return -1;
        }
    }
    for (int a = 0; a < nnum; a++) {
        size_t n = word(&p, e, w, sizeof w);
        if (number(w, n, &v[a]) != 0) {
            lu_err(err, errlen, "%s:%zu: '%s' number %d is %s'%.20s' (a finite number "
                   "expected)", name, c->line, kw, a + 1, n ? "" : "missing: ", w);
            return -1;
        }
    }
    if (word(&p, e, w, sizeof w) > 0 && nnum > 0) {
        lu_err(err, errlen, "%s:%zu: '%.20s' after the %d numbers of '%s'", name, c->line, w,
               nnum, kw);
        return -1;
    }
    return 0;
}

static int parse_stl_ascii(const char *name, const char *buf, size_t len, build *b, char *err,
                           size_t errlen)
{
    cursor c = {buf, buf + len, 0};
    const char *s, *e;
    char w[72];
    if (!next_line(&c, &s, &e)) return -1;   /* "solid [name]": checked by the caller */
    for (;;) {
        /* facet normal nx ny nz, or endsolid */
        cursor save = c;
        const char *p;
        size_t n;
        do {
            if (!next_line(&c, &s, &e)) {
                lu_err(err, errlen, "%s:%zu: the file ends without 'endsolid'", name, c.line);
                return -1;
            }
            p = s;
            n = word(&p, e, w, sizeof w);
        } while (n == 0);
        if (strcmp(w, "endsolid") == 0) return 0;
        c = save;
        double nrm[3], x[3][3];
        if (stl_expect(name, &c, "facet normal", 3, nrm, err, errlen) ||
            stl_expect(name, &c, "outer loop", 0, NULL, err, errlen))
            return -1;
        for (int k = 0; k < 3; k++)
            if (stl_expect(name, &c, "vertex", 3, x[k], err, errlen)) return -1;
        if (stl_expect(name, &c, "endloop", 0, NULL, err, errlen) ||
            stl_expect(name, &c, "endfacet", 0, NULL, err, errlen))
            return -1;
        size_t v0 = b->m.nv;
        int rc = 0;
        for (int k = 0; k < 3 && !rc; k++) rc = add_vertex(b, x[k]);
        if (!rc) rc = add_triangle(b, (int32_t)v0, (int32_t)v0 + 1, (int32_t)v0 + 2);
        if (rc) {
            char where[32];
            snprintf(where, sizeof where, "line %zu", c.line);
            limit_err(rc, name, where, err, errlen);
            return -1;
        }
    }
}

static float le_float(const unsigned char *p)
{
    uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
                 (uint32_t)p[3] << 24;
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static uint32_t le_u32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static int parse_stl_binary(const char *name, const unsigned char *buf, size_t n, build *b,
                            char *err, size_t errlen)
{
    if (n > LM3_MESH_MAX_TRIANGLES) {
        lu_err(err, errlen, "%s: %zu triangles (at most %zu)", name, n, LM3_MESH_MAX_TRIANGLES);
        return -1;
    }
    for (size_t t = 0; t < n; t++) {
        const unsigned char *r = buf + 84 + 50 * t + 12;
        size_t v0 = b->m.nv;
        for (int k = 0; k < 3; k++) {
            double x[3];
            for (int a = 0; a < 3; a++) {
                x[a] = le_float(r + 12 * k + 4 * a);
                if (!isfinite(x[a])) {
                    lu_err(err, errlen, "%s: triangle %zu, vertex %d: coordinate %d is not a "
                           "finite number", name, t + 1, k + 1, a + 1);
                    return -1;
                }
            }
            int rc = add_vertex(b, x);
            if (rc) {
                char where[40];
                snprintf(where, sizeof where, "triangle %zu", t + 1);
                limit_err(rc, name, where, err, errlen);
                return -1;
            }
        }
        int rc = add_triangle(b, (int32_t)v0, (int32_t)v0 + 1, (int32_t)v0 + 2);
        if (rc) {
            limit_err(rc, name, "triangles", err, errlen);
            return -1;
        }
    }
    return 0;
}

/* STL's vertices merged where their coordinates are exactly equal (a
 * sort of the vertices by coordinates, then each triangle renumbered). */
typedef struct vkey { double x[3]; int32_t i; } vkey;

static int by_xyz(const void *a, const void *b)
{
    const vkey *p = a, *q = b;
    for (int k = 0; k < 3; k++)
        if (p->x[k] != q->x[k]) return p->x[k] < q->x[k] ? -1 : 1;
    return (p->i > q->i) - (p->i < q->i);
}

static int merge_vertices(lm3_mesh *m)
{
    size_t n = m->nv;
    vkey *key = malloc(n * sizeof *key);
    int32_t *map = malloc(n * sizeof *map);
    double *xyz = malloc(3 * n * sizeof *xyz);
    if (!key || !map || !xyz) {
        free(key);
        free(map);
        free(xyz);
        return -1;
    }
    for (size_t i = 0; i < n; i++) {
        memcpy(key[i].x, m->xyz + 3 * i, 3 * sizeof(double));
        key[i].i = (int32_t)i;
    }
    qsort(key, n, sizeof *key, by_xyz);
    size_t u = 0;
    for (size_t k = 0; k < n; k++) {
        const double *last = u ? xyz + 3 * (u - 1) : NULL;
        if (!last || key[k].x[0] != last[0] || key[k].x[1] != last[1] || key[k].x[2] != last[2]) {
            memcpy(xyz + 3 * u, key[k].x, 3 * sizeof(double));
            u++;
        }
        map[key[k].i] = (int32_t)(u - 1);
    }
    for (size_t t = 0; t < 3 * m->nt; t++) m->tri[t] = map[m->tri[t]];
    free(key);
    free(map);
    free(m->xyz);
    m->xyz = xyz;
    m->nv = u;
    return 0;
}

/* ---- reading ---------------------------------------------------------------- */

/* Checks every triangle names three different vertices. */
static int triangles_ok(const char *name, const lm3_mesh *m, char *err, size_t errlen)
{
    if (m->nt == 0) {
        lu_err(err, errlen, "%s: no triangles", name);
        return 0;
    }
    for (size_t t = 0; t < m->nt; t++) {
        const int32_t *v = m->tri + 3 * t;
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
            lu_err(err, errlen, "%s: triangle %zu repeats a vertex (%d, %d, %d)", name, t + 1,
                   (int)v[0] + 1, (int)v[1] + 1, (int)v[2] + 1);
            return 0;
        }
    }
    return 1;
}

static int starts_with_word(const char *buf, size_t len, const char *w)
{
    size_t i = 0, l = strlen(w);
    while (i < len && (is_space(buf[i]) || buf[i] == '\r' || buf[i] == '\n')) i++;
    return len - i >= l && memcmp(buf + i, w, l) == 0 &&
           (len - i == l || isspace((unsigned char)buf[i + l]));
}

int lm3_mesh_parse(const char *name, const char *buf, size_t len, lm3_mesh *m, char *err,
                   size_t errlen)
{
    memset(m, 0, sizeof *m);
    build b;
    memset(&b, 0, sizeof b);
    int rc, stl = 0;
    int solid = starts_with_word(buf, len, "solid");
    if (len >= 84 && (size_t)le_u32((const unsigned char *)buf + 80) ==
                         (len - 84) / 50 && (len - 84) % 50 == 0) {
        stl = 1;
        rc = parse_stl_binary(name, (const unsigned char *)buf, (len - 84) / 50, &b, err,
                              errlen);
    } else if (len >= 84 && memchr(buf, 0, len)) {
        /* binary, but its size does not fit its header's count; "solid" in
         * the header reads as an STL's (the ASCII keyword) */
        lu_err(err, errlen,
               solid ? "%s: a binary STL of %zu bytes cannot hold the %u triangles its "
                       "header counts (84 + 50 n bytes)"
                     : "%s: a binary file that is not an STL of 84 + 50 n bytes (%zu "
                       "bytes; the header counts %u triangles)",
               name, len, (unsigned)le_u32((const unsigned char *)buf + 80));
        rc = -1;
    } else if (solid) {
        stl = 1;
        rc = parse_stl_ascii(name, buf, len, &b, err, errlen);
    } else {
        rc = parse_obj(name, buf, len, &b, err, errlen);
    }
    if (rc == 0 && stl && merge_vertices(&b.m) != 0) {
        lu_err(err, errlen, "%s: out of memory merging %zu vertices", name, b.m.nv);
        rc = -1;
    }
    if (rc == 0 && !triangles_ok(name, &b.m, err, errlen)) rc = -1;
    if (rc != 0) {
        lm3_mesh_free(&b.m);
        return -1;
    }
    *m = b.m;
    return 0;
}

int lm3_mesh_read(const char *path, lm3_mesh *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    FILE *f = fopen(path, "rb");
    if (!f) {
        lu_err(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    /* read in blocks up to the bound: no size taken on trust */
    size_t cap = 0, len = 0;
    char *buf = NULL;
    for (;;) {
        if (lu_reserve(&buf, &cap, len + 65536, 1, 65536) != 0) {
            lu_err(err, errlen, "%s: out of memory reading it", path);
            goto fail;
        }
        size_t got = fread(buf + len, 1, 65536, f);
        len += got;
        if (len > LM3_MESH_MAX_BYTES) {
            lu_err(err, errlen, "%s: larger than %zu bytes", path, LM3_MESH_MAX_BYTES);
            goto fail;
        }
        if (got < 65536) break;
    }
    if (ferror(f)) {
        lu_err(err, errlen, "%s: read error", path);
        goto fail;
    }
    fclose(f);
    int rc = lm3_mesh_parse(path, buf, len, m, err, errlen);
    free(buf);
    return rc;
fail:
    fclose(f);
    free(buf);
    return -1;
}

/* ---- geometry ------------------------------------------------------------------ */

typedef struct dedge { int32_t a, b; size_t t; } dedge;

static int by_edge(const void *x, const void *y)
{
    const dedge *p = x, *q = y;
    int c = lm_edge_order(p->a, p->b, q->a, q->b);
    if (c) return c;
    return (p->t > q->t) - (p->t < q->t);
}

int lm3_mesh_closed(const char *name, const lm3_mesh *m, char *err, size_t errlen)
{
    size_t ne = 3 * m->nt;
    dedge *e = malloc(ne * sizeof *e);
    if (!e) {
        lu_err(err, errlen, "%s: out of memory checking its edges", name);
        return -1;
    }
    for (size_t t = 0; t < m->nt; t++)
        for (int k = 0; k < 3; k++)
            e[3 * t + k] = (dedge){m->tri[3 * t + k], m->tri[3 * t + (k + 1) % 3], t};
    qsort(e, ne, sizeof *e, by_edge);
    int ok = 1;
    for (size_t k = 0; k < ne && ok;) {
        size_t j = k + 1;
        while (j < ne && by_edge(&e[k], &(dedge){e[j].a, e[j].b, e[k].t}) == 0) j++;
        if (j - k != 2) {
            lu_err(err, errlen, "%s is not closed: the edge from vertex %d to %d is in %zu "
                   "triangle%s (triangle %zu%s), not 2", name, (int)e[k].a + 1, (int)e[k].b + 1,
                   j - k, j - k == 1 ? "" : "s", e[k].t + 1, j - k == 1 ? "" : ", ...");
            ok = 0;
        } else if (e[k].a == e[k + 1].a) {
            lu_err(err, errlen, "%s is not consistently wound: triangles %zu and %zu both run "
                   "from vertex %d to %d", name, e[k].t + 1, e[k + 1].t + 1, (int)e[k].a + 1,
                   (int)e[k].b + 1);
            ok = 0;
        }
        k = j;
    }
    free(e);
    return ok;
}

/* Corner k (0, 1, 2) of triangle t: its vertex's coordinates. */
static const double *corner(const lm3_mesh *m, size_t t, int k)
{
    return m->xyz + 3 * (size_t)m->tri[3 * t + k];
}

double lm3_mesh_volume6(const lm3_mesh *m)
{
    double v = 0;
    for (size_t t = 0; t < m->nt; t++) {
        const double *p = corner(m, t, 0), *q = corner(m, t, 1), *r = corner(m, t, 2);
        v += p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
             p[2] * (q[0] * r[1] - q[1] * r[0]);
    }
    return v;
}

double lm3_mesh_area(const lm3_mesh *m)
{
    double A = 0;
    for (size_t t = 0; t < m->nt; t++) {
        const double *p = corner(m, t, 0), *q = corner(m, t, 1), *r = corner(m, t, 2);
        double a[3], b[3];
        for (int k = 0; k < 3; k++) {
            a[k] = q[k] - p[k];
            b[k] = r[k] - p[k];
        }
        double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                       a[0] * b[1] - a[1] * b[0]};
        A += 0.5 * sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    }
    return A;
}

/* The solid angle of triangle (a, b, c) seen from the origin:
 * tan(Omega / 2) = a.(b x c) / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|)
 * (van Oosterom & Strackee 1983), signed by the winding. */
static double solid_angle(const double a[3], const double b[3], const double c[3])
{
    double la = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    double lb = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    double lc = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    double det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                 a[2] * (b[0] * c[1] - b[1] * c[0]);
    double ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    double ac = a[0] * c[0] + a[1] * c[1] + a[2] * c[2];
    double bc = b[0] * c[0] + b[1] * c[1] + b[2] * c[2];
    return 2 * atan2(det, la * lb * lc + ab * lc + ac * lb + bc * la);
}

int lm3_mesh_inside(const lm3_mesh *m, const double x[3])
{
    double w = 0;
    for (size_t t = 0; t < m->nt; t++) {
        double v[3][3];
        for (int k = 0; k < 3; k++)
            for (int a = 0; a < 3; a++) v[k][a] = corner(m, t, k)[a] - x[a];
        w += solid_angle(v[0], v[1], v[2]);
    }
    return fabs(w) / (4 * pi) > 0.5;
}
