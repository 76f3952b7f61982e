/* canvas_gl_dense.c - many discs of about a pixel's radius, gathered.
 *
 * llvmpipe spends about a quarter of a microsecond on every primitive
 * (vertex fetch, point setup, binning, a few hundred bytes of scene
 * memory, then rasterising it), so 10^6 particles cost a quarter of a
 * second as points however few pixels each covers. Discs of radius up to
 * 9/8 px sit on cairo's quarter-pixel stamp grid (canvas_gl_draw.c), so
 * every pixel such a disc reaches lies in the 3 x 3 pixels round the one
 * holding its centre. A long, dense run of discs of one colour is
 * therefore drawn as one rectangle: the discs go into a texture by the
 * pixel holding their centre (up to two per pixel, as a pair of position
 * codes), and the fragment shader reads the 9 texels round its pixel and
 * multiplies what each pair leaves uncovered of it.
 *
 * For discs of one colour k that is what drawing them in turn gives:
 * whatever the order, OVER leaves k (1 - prod(1 - a_i)) + dst prod(1 - a_i)
 * (a_i: the colour's alpha times disc i's coverage of the pixel). GL
 * rounds that to 8 bits once instead of after every disc, so pixels may
 * differ from the points' by a level or so (docs/rendering.md). For the
 * same reason a third disc in a pixel may come after the rest: those are
 * gathered again, or drawn as points when few. Runs of another colour
 * keep their place: a batch is drawn run by run, in order, and short or
 * thinly spread runs still go as points.
 *
 * Coverage is the points' (DISC_COVERAGE in canvas_gl_shaders.c), taken
 * for the 16 positions x 9 neighbours once per radius and alpha and given
 * to the shader as a table of what a pair of discs leaves uncovered.
 * Needs GLSL 1.30 (integer textures); an older context draws points. */
#include "canvas_gl.h"
#include "util.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Discs on the stamp grid (canvas_gl_draw.c) that reach no further than
 * the neighbouring pixels: centre (q + 1/2) / 4 past a pixel's edge,
 * reach r <= 1 + 1/8. */
#define DENSE_MIN_RADIUS 0.8
#define DENSE_MAX_RADIUS 1.125
/* Discs are gathered when there are this many and they number at least
 * 1 / DENSE_FILL of their bounding box's pixels: below that the
 * rectangle's pixels cost more than the points (measured on one core: a
 * point of radius 1 about 0.25 us, a gathered pixel about 0.05). */
#define DENSE_MIN_RUN 2048
#define DENSE_FILL 4
#define CODES 17                /* 0: no disc; 1 + qx + 4 qy */
#define CELLS 0                 /* dense_tex[]: the discs by pixel */
#define TABLE 1                 /* ... the coverage table */
#define PAIRS (CODES * CODES)   /* a texel: code a + CODES * code b */

static const char *const dense_vs =
    "#version 130\n"
    "uniform vec4 u_vp;\n"
    "in vec2 a_pos;\n"
    "vec4 to_clip(vec2 p) {\n"
    "  return vec4(2.0 * (p.x + u_vp.x) / u_vp.z - 1.0,\n"
    "              1.0 - 2.0 * (p.y + u_vp.y) / u_vp.w, 0.0, 1.0);\n"
    "}\n"
    "void main() { gl_Position = to_clip(a_pos); }\n";

/* The cells hold the discs by the pixel holding their centre, with a
 * pixel of margin round them (layer()), so pixel p's neighbours are
 * texels p - u_org + (0..2, 0..2), none outside the texture. u_keep at
 * (pair, n): what that pair of discs in neighbour n leaves of this pixel,
 * 1 - alpha coverage for each. */
static const char *const dense_fs =
    "#version 130\n"
    "uniform usampler2D u_cells;\n"
    "uniform sampler2D u_keep;\n"
    "uniform vec3 u_rgb;\n"
    "uniform float u_h;\n"
    "uniform ivec2 u_org;\n"
    "out vec4 o_col;\n"
    "void main() {\n"
    "  ivec2 p = ivec2(int(gl_FragCoord.x), int(u_h - gl_FragCoord.y)) - u_org;\n"
    "  float keep = 1.0;\n"
    "  for (int n = 0; n < 9; n++) {\n"
    "    uint v = texelFetch(u_cells, p + ivec2(n - 3 * (n / 3), n / 3), 0).r;\n"
    "    keep *= texelFetch(u_keep, ivec2(int(v), n), 0).r;\n"
    "  }\n"
    "  float a = 1.0 - keep;\n"
    "  o_col = vec4(u_rgb * a, a);\n"
    "}\n";

/* DISC_COVERAGE (canvas_gl_shaders.c) for one pixel: d is the pixel
 * centre's offset from the disc centre. */
static double disc_coverage(double dx, double dy, double r)
{
    double l = hypot(dx, dy);
    if (l <= r - 0.7072)
        return 1.0;
    if (l >= r + 0.7072)
        return 0.0;
    double a = 0.0;
    for (int k = 0; k < 4; k++) {
        double x = dx - 0.5 + (k + 0.5) / 4.0;
        double h = sqrt(fmax(r * r - x * x, 0.0));
        a += fmax(0.0, fmin(dy + 0.5, h) - fmax(dy - 0.5, -h));
    }
    return a / 4.0;
}

void gl_dense_release(gl_engine *e)
{
    free(e->dense_cells);
    free(e->dense_more);
    free(e->dense_list);
    e->dense_cells = NULL;
    e->dense_more = e->dense_list = NULL;
    e->dense_cap = e->dense_morecap = e->dense_listcap = 0;
}

static int compile(gl_engine *e)
{
    const char *v = (const char *)glGetString(GL_SHADING_LANGUAGE_VERSION);
    int major = 0, minor = 0;
    char err[512];
    static const char *const attr[] = { "a_pos" };
    static const GLuint loc[] = { 0 };
    if (!v || sscanf(v, "%d.%d", &major, &minor) != 2 || major * 100 + minor < 130)
        return -1;
    e->dense_prog = gl_link(dense_vs, dense_fs, attr, loc, 1, err, sizeof err);
    if (!e->dense_prog)
        return -1;
    e->dense_vp = glGetUniformLocation(e->dense_prog, "u_vp");
    e->dense_h = glGetUniformLocation(e->dense_prog, "u_h");
    e->dense_rgb = glGetUniformLocation(e->dense_prog, "u_rgb");
    e->dense_org = glGetUniformLocation(e->dense_prog, "u_org");
    glUseProgram(e->dense_prog);
    glUniform1i(glGetUniformLocation(e->dense_prog, "u_cells"), 0);
    glUniform1i(glGetUniformLocation(e->dense_prog, "u_keep"), 1);
    glGenTextures(2, e->dense_tex);
    for (int i = 0; i < 2; i++) {
        glBindTexture(GL_TEXTURE_2D, e->dense_tex[i]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, PAIRS, 9, 0, GL_RED, GL_FLOAT, NULL);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &e->dense_max);
    e->dense_r = e->dense_a = -1.0;
    return 0;
}

/* The program; -1 when this context has no GLSL 1.30 (remembered). */
static int ready(gl_canvas *c)
{
    gl_engine *e = &c->gl;
    if (e->dense_state == 0) {
        e->dense_state = compile(e) == 0 ? 1 : -1;
        glGetError();       /* a context that cannot is not the canvas's error */
    }
    return e->dense_state > 0 ? 0 : -1;
}

/* The table for radius r and alpha a (kept while they stay). */
static void table(gl_engine *e, double r, double a)
{
    if (e->dense_r == r && e->dense_a == a)
        return;
    float t[9 * PAIRS];    /* 10 kB */
    for (int n = 0; n < 9; n++) {
        double keep[CODES];
        keep[0] = 1.0;
        for (int q = 0; q < 16; q++) {
            /* a disc (qx + 1/2) / 4 into the pixel one left of (above)
             * neighbour column (row) n % 3 (n / 3): the cells' margin */
            double fx = ((q & 3) + 0.5) / 4.0, fy = ((q >> 2) + 0.5) / 4.0;
            keep[1 + q] = 1.0 - a * disc_coverage(1.5 - n % 3 - fx, 1.5 - n / 3 - fy, r);
        }
        for (int p = 0; p < PAIRS; p++)
            t[PAIRS * n + p] = (float)(keep[p % CODES] * keep[p / CODES]);
    }
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, e->dense_tex[TABLE]);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, PAIRS, 9, GL_RED, GL_FLOAT, t);
    glActiveTexture(GL_TEXTURE0);
    e->dense_r = r;
    e->dense_a = a;
}

/* Keeps point i for later (its pixel has two). */
static int defer(gl_engine *e, uint32_t i, size_t *nmore)
{
    if (lu_reserve(&e->dense_more, &e->dense_morecap, *nmore + 1, sizeof *e->dense_more,
                   4096) != 0)
        return -1;
    e->dense_more[(*nmore)++] = i;
    return 0;
}

/* floor for the canvas's range (|v| < 2^31), without a call */
static inline float floor_small(float v)
{
    float f = (float)(int)v;
    return f > v ? f - 1.0f : f;
}

typedef struct box { float x0, y0, x1, y1; } box;

static void box_add(box *b, float x, float y)
{
    b->x0 = x < b->x0 ? x : b->x0;
    b->x1 = x > b->x1 ? x : b->x1;
    b->y0 = y < b->y0 ? y : b->y0;
    b->y1 = y > b->y1 ? y : b->y1;
}

/* Whether n discs spread over box b are worth a rectangle (and its
 * texture is not larger than GL allows). */
static int dense_enough(const gl_canvas *c, const box *b, size_t n)
{
    double w = (double)b->x1 - b->x0 + 3.0, h = (double)b->y1 - b->y0 + 3.0;
    return n >= DENSE_MIN_RUN && (double)n * DENSE_FILL >= w * h &&
           w + 3 <= c->gl.dense_max && h + 3 <= c->gl.dense_max;
}

/* Where a layer's discs go: texel (x, y) of the cells holds the discs
 * centred in canvas pixel (x0 + x - 1, y0 + y - 1), so pixel p reads
 * texels p - (x0, y0) + (0..2, 0..2); the pixels drawn are x0 .. x1,
 * y0 .. y1, those the discs in box b can reach. 0 when none. */
typedef struct region { int x0, y0, x1, y1, w, h; } region;

static int region_of(const gl_canvas *c, const box *b, region *g)
{
    int cw = c->base.width, ch = c->base.height;
    /* the texels of the box's corners, t = floor + 1: pixel t - 1 holds
     * the centre, pixels t - 2 .. t are reached */
    float fx0 = b->x0 < -1.0f ? -1.0f : b->x0, fy0 = b->y0 < -1.0f ? -1.0f : b->y0;
    int tx0 = (int)floor_small(fx0) + 1, ty0 = (int)floor_small(fy0) + 1;
    int tx1 = b->x1 >= (float)cw ? cw + 1 : (int)floor_small(b->x1) + 1;
    int ty1 = b->y1 >= (float)ch ? ch + 1 : (int)floor_small(b->y1) + 1;
    g->x0 = tx0 - 2 < 0 ? 0 : tx0 - 2;
    g->y0 = ty0 - 2 < 0 ? 0 : ty0 - 2;
    g->x1 = tx1 > cw - 1 ? cw - 1 : tx1;
    g->y1 = ty1 > ch - 1 ? ch - 1 : ty1;
    g->w = g->x1 - g->x0 + 3;
    g->h = g->y1 - g->y0 + 3;
    return g->x0 <= g->x1 && g->y0 <= g->y1;
}

/* The discs listed (indices into the batch, or first .. first + n when
 * list is NULL), in box b, as one rectangle, two per pixel; the others
 * listed in e->dense_more (*nmore), their box in *more. */
static int layer(gl_canvas *c, const uint32_t *list, size_t first, size_t n,
                 const box *b, size_t *nmore, box *more)
{
    gl_engine *e = &c->gl;
    region g;
    if (!region_of(c, b, &g))
        return 0;
    size_t ncells = (size_t)g.w * (size_t)g.h;
    if (e->dense_cap < ncells) {
        free(e->dense_cells);
        e->dense_cells = calloc(ncells, sizeof *e->dense_cells);
        e->dense_cap = e->dense_cells ? ncells : 0;
        if (!e->dense_cells)
            return -1;
    }
    /* discs centred outside -1 <= x < width + 1 reach no pixel */
    float xmax = (float)(c->base.width + 1), ymax = (float)(c->base.height + 1);
    for (size_t k = 0; k < n; k++) {
        size_t i = list ? list[k] : first + k;
        float x = c->pxy[2 * i], y = c->pxy[2 * i + 1];
        if (!(x >= -1.0f && y >= -1.0f && x < xmax && y < ymax))
            continue;
        float fx = floor_small(x), fy = floor_small(y);
        int tx = (int)fx + 1 - g.x0, ty = (int)fy + 1 - g.y0;
        /* the stamp grid puts the centre at (q + 1/2) / 4 into its pixel */
        int code = 1 + ((int)((x - fx) * 4.0f) & 3) + 4 * ((int)((y - fy) * 4.0f) & 3);
        uint16_t *cell = &e->dense_cells[(size_t)ty * g.w + tx];
        if (*cell >= CODES) {
            if (defer(e, (uint32_t)i, nmore) != 0)
                return -1;
            box_add(more, x, y);
            continue;
        }
        *cell = *cell ? (uint16_t)(*cell + CODES * code) : (uint16_t)code;
    }
    /* (llvmpipe makes this upload wait for the previous run's rectangle,
     * which reads the texture; a texture per run measured no faster) */
    glBindTexture(GL_TEXTURE_2D, e->dense_tex[CELLS]);
    if (e->dense_tw < g.w || e->dense_th < g.h) {
        int tw = e->dense_tw > g.w ? e->dense_tw : g.w;
        int th = e->dense_th > g.h ? e->dense_th : g.h;
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R16UI, tw, th, 0, GL_RED_INTEGER,
                     GL_UNSIGNED_SHORT, NULL);
        e->dense_tw = tw;
        e->dense_th = th;
    }
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, g.w, g.h, GL_RED_INTEGER, GL_UNSIGNED_SHORT,
                    e->dense_cells);
    glUniform2i(e->dense_org, g.x0, g.y0);
    float x0 = (float)g.x0, y0 = (float)g.y0, x1 = (float)g.x1 + 1, y1 = (float)g.y1 + 1;
    const float quad[12] = { x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1 };
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, quad);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glDisableVertexAttribArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    memset(e->dense_cells, 0, ncells * sizeof *e->dense_cells);
    return 0;
}

/* The dense program set for c and colour q (straight RGBA8), radius r. */
static void use_program(gl_canvas *c, const unsigned char *q, double r)
{
    gl_engine *e = &c->gl;
    glUseProgram(e->dense_prog);
    float vp[4] = { (float)c->pad, (float)c->pad, (float)(c->base.width + 2 * c->pad),
                    (float)(c->base.height + 2 * c->pad) };
    glUniform4fv(e->dense_vp, 1, vp);
    glUniform1f(e->dense_h, (float)c->base.height);
    glUniform3f(e->dense_rgb, (float)(q[0] / 255.0), (float)(q[1] / 255.0),
                (float)(q[2] / 255.0));
    table(e, r, q[3] / 255.0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, e->dense_tex[TABLE]);
    glActiveTexture(GL_TEXTURE0);
}

/* The run first .. first + n (one colour, so the order of its discs does
 * not matter): rectangles while the discs left over are dense, then the
 * rest as points. */
static int gather(gl_canvas *c, size_t first, size_t n, box b)
{
    gl_engine *e = &c->gl;
    const unsigned char *q = c->prgba + 4 * first;
    const uint32_t *list = NULL;
    int rc = 0;
    for (;;) {
        size_t nmore = 0;
        box more = { INFINITY, INFINITY, -INFINITY, -INFINITY };
        use_program(c, q, c->point_r);
        rc = layer(c, list, first, n, &b, &nmore, &more);
        if (rc != 0 || nmore == 0)
            break;
        /* the deferred become the list; the next layer defers afresh */
        uint32_t *t = e->dense_list;
        size_t cap = e->dense_listcap;
        e->dense_list = e->dense_more;
        e->dense_listcap = e->dense_morecap;
        e->dense_more = t;
        e->dense_morecap = cap;
        list = e->dense_list;
        n = nmore;
        b = more;
        if (!dense_enough(c, &b, n)) {
            gl_draw_point_list(c, list, n);
            break;
        }
    }
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    if (rc != 0)        /* the cells must be zero for the next run */
        memset(e->dense_cells, 0, e->dense_cap * sizeof *e->dense_cells);
    return rc;
}

static uint32_t colour_of(const gl_canvas *c, size_t i)
{
    uint32_t k;
    memcpy(&k, c->prgba + 4 * i, 4);
    return k;
}

int gl_dense_flush(gl_canvas *c)
{
    double r = c->point_r;
    if (!(r >= DENSE_MIN_RADIUS && r <= DENSE_MAX_RADIUS) || c->npoints < DENSE_MIN_RUN ||
        ready(c) != 0)
        return 0;
    size_t pending = 0;     /* points before the run not drawn yet */
    for (size_t start = 0; start < c->npoints;) {
        uint32_t k = colour_of(c, start);
        box b = { INFINITY, INFINITY, -INFINITY, -INFINITY };
        size_t end = start;
        do {
            box_add(&b, c->pxy[2 * end], c->pxy[2 * end + 1]);
            end++;
        } while (end < c->npoints && colour_of(c, end) == k);
        if (dense_enough(c, &b, end - start)) {
            if (start > pending)
                gl_draw_points(c, pending, start - pending);
            if (gather(c, start, end - start, b) != 0) {
                c->failed = 1;
                return 1;
            }
            pending = end;
        }
        start = end;
    }
    if (c->npoints > pending)
        gl_draw_points(c, pending, c->npoints - pending);
    return 1;
}
