/* canvas_gl_shaders.c - the GL backends' shaders and vertex batches.
 *
 * GLSL 1.20 (OpenGL 2.1), which every OSMesa since Mesa 7 provides and every
 * desktop OpenGL context that EGL makes (canvas_egl.c). Three
 * programs: shapes (lines, fills, large discs; coverage from interpolated
 * distances), points (discs as point sprites; coverage from gl_PointCoord)
 * and text (a coverage texture rasterised by cairo). All output
 * premultiplied colour times coverage. */
#include "canvas_gl.h"
#include "util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Vertices are given in canvas pixels (origin top-left, y down); u_vp is
 * (offset x, offset y, viewport width, viewport height): normally the
 * offsets are the pad by which the viewport overhangs the canvas on every
 * side (canvas_gl.c says why); fills move them (canvas_gl_fill.c). */
#define TO_CLIP                                                              \
    "vec4 to_clip(vec2 p) {\n"                                               \
    "  return vec4(2.0 * (p.x + u_vp.x) / u_vp.z - 1.0,\n"                   \
    "              1.0 - 2.0 * (p.y + u_vp.y) / u_vp.w, 0.0, 1.0);\n"        \
    "}\n"

static const char *const shape_vs =
    "#version 120\n"
    "uniform vec4 u_vp;\n"
    "attribute vec2 a_pos;\n"
    "attribute vec4 a_e;\n"
    "attribute vec2 a_m;\n"
    "attribute vec4 a_col;\n"
    "varying vec4 v_e;\n"
    "varying vec2 v_m;\n"
    "varying vec4 v_col;\n"
    TO_CLIP
    "void main() {\n"
    "  v_e = a_e; v_m = a_m; v_col = a_col;\n"
    "  gl_Position = to_clip(a_pos);\n"
    "}\n";

/* The area of the pixel whose centre is at d from the centre of a disc of
 * radius r: 1 or 0 away from the rim; on the rim the pixel is cut into 4
 * columns and each column's chord through the disc is clipped to the pixel
 * (a midpoint rule in x, exact in y). Close to cairo's coverage, which is
 * an area too: against cairo this takes the pixels that differ beyond
 * anti-aliasing in test_canvas_backends from 0.37 % (r + 0.5 - distance)
 * to 0.004 %; 8 columns gain nothing more. */
#define DISC_COVERAGE                                                        \
    "float disc(vec2 d, float r) {\n"                                        \
    "  float l = length(d);\n"                                               \
    "  if (l <= r - 0.7072) return 1.0;\n"                                   \
    "  if (l >= r + 0.7072) return 0.0;\n"                                   \
    "  float a = 0.0;\n"                                                     \
    "  for (int k = 0; k < 4; k++) {\n"                                      \
    "    float x = d.x - 0.5 + (float(k) + 0.5) / 4.0;\n"                    \
    "    float h = sqrt(max(r * r - x * x, 0.0));\n"                         \
    "    a += max(0.0, min(d.y + 0.5, h) - max(d.y - 0.5, -h));\n"           \
    "  }\n"                                                                  \
    "  return a / 4.0;\n"                                                    \
    "}\n"

/* span(): how much of the pixel [c - 0.5, c + 0.5] lies in [lo, hi] - a box
 * filter, exact for edges along the pixel grid. A dash pattern is "on" for
 * d, "off" for d, from the line's start, as cairo's {d} dash array. */
static const char *const shape_fs =
    "#version 120\n"
    "varying vec4 v_e;\n"
    "varying vec2 v_m;\n"
    "varying vec4 v_col;\n"
    DISC_COVERAGE
    "float span(float lo, float hi, float c) {\n"
    "  return max(0.0, min(c + 0.5, hi) - max(c - 0.5, lo));\n"
    "}\n"
    "float along(float v, float len, float d) {\n"
    "  if (d <= 0.0) return span(0.0, len, v);\n"
    "  if (d < 0.5) return 0.5 * span(0.0, len, v);\n"
    "  float p = 2.0 * d;\n"
    "  float a = floor((v - 0.5) / p) * p;\n"
    "  float c = 0.0;\n"
    "  for (int i = 0; i < 2; i++) {\n"
    "    float s0 = max(a, 0.0), s1 = min(a + d, len);\n"
    "    if (s1 > s0) c += span(s0, s1, v);\n"
    "    a += p;\n"
    "  }\n"
    "  return min(c, 1.0);\n"
    "}\n"
    "void main() {\n"
    "  float cov;\n"
    "  if (v_m.y < 0.5) cov = span(-v_e.z, v_e.z, v_e.x) * along(v_e.y, v_e.w, v_m.x);\n"
    "  else if (v_m.y < 1.5) {\n"
    "    cov = clamp(0.5 - abs(v_e.x), 0.0, 1.0);\n"
    "    if (cov <= 0.0) discard;\n"    /* leaves the stencil for another edge */
    "  } else if (v_m.y < 2.5) cov = 1.0;\n"
    "  else cov = disc(v_e.xy, v_e.z);\n"
    "  gl_FragColor = vec4(v_col.rgb * v_col.a, v_col.a) * cov;\n"
    "}\n";

static const char *const point_vs =
    "#version 120\n"
    "uniform vec4 u_vp;\n"
    "attribute vec2 a_pos;\n"
    "attribute vec4 a_col;\n"
    "varying vec4 v_col;\n"
    "varying vec2 v_c;\n"
    TO_CLIP
    "void main() {\n"
    "  v_col = a_col;\n"
    "  v_c = a_pos;\n"
    "  gl_Position = to_clip(a_pos);\n"
    "}\n";

/* A point is a square (glPointSize) round its centre v_c (canvas pixels);
 * gl_FragCoord is the pixel centre in window coordinates (y up, u_h the
 * canvas height), so d is the exact offset of the pixel centre from the
 * disc centre. (Not gl_PointCoord: point sprites cost llvmpipe a third
 * more per point.) u_dot: a disc smaller than a pixel is the one pixel
 * holding its centre, as in cairo's stamps. */
static const char *const point_fs =
    "#version 120\n"
    "uniform float u_r;\n"
    "uniform float u_h;\n"
    "uniform float u_dot;\n"
    "varying vec4 v_col;\n"
    "varying vec2 v_c;\n"
    DISC_COVERAGE
    "void main() {\n"
    "  float cov = 1.0;\n"
    "  if (u_dot < 0.5) {\n"
    "    cov = disc(vec2(gl_FragCoord.x, u_h - gl_FragCoord.y) - v_c, u_r);\n"
    "    if (cov <= 0.0) discard;\n"
    "  }\n"
    "  gl_FragColor = vec4(v_col.rgb * v_col.a, v_col.a) * cov;\n"
    "}\n";

static const char *const text_vs =
    "#version 120\n"
    "uniform vec4 u_vp;\n"
    "attribute vec2 a_pos;\n"
    "attribute vec2 a_uv;\n"
    "varying vec2 v_uv;\n"
    TO_CLIP
    "void main() {\n"
    "  v_uv = a_uv;\n"
    "  gl_Position = to_clip(a_pos);\n"
    "}\n";

static const char *const text_fs =
    "#version 120\n"
    "uniform sampler2D u_tex;\n"
    "uniform vec4 u_col;\n"
    "varying vec2 v_uv;\n"
    "void main() {\n"
    "  float cov = texture2D(u_tex, v_uv).a;\n"
    "  gl_FragColor = vec4(u_col.rgb * u_col.a, u_col.a) * cov;\n"
    "}\n";

/* Attribute locations, fixed before linking so the batches need no lookup. */
enum { A_POS = 0, A_E = 1, A_M = 2, A_COL = 3, A_UV = 1 };

/* obj when it compiled (a shader) or linked (a program); else 0, with
 * OpenGL's log in err and obj deleted. */
static GLuint built(GLuint obj, int program, char *err, size_t errlen)
{
    GLint ok = 0;
    char log[512] = "";
    if (program)
        glGetProgramiv(obj, GL_LINK_STATUS, &ok);
    else
        glGetShaderiv(obj, GL_COMPILE_STATUS, &ok);
    if (ok)
        return obj;
    if (program) {
        glGetProgramInfoLog(obj, sizeof log, NULL, log);
        glDeleteProgram(obj);
    } else {
        glGetShaderInfoLog(obj, sizeof log, NULL, log);
        glDeleteShader(obj);
    }
    snprintf(err, errlen, "OpenGL: a shader %s: %s",
             program ? "program does not link" : "does not compile", log);
    return 0;
}

static GLuint compile(GLenum type, const char *src, char *err, size_t errlen)
{
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    return built(s, 0, err, errlen);
}

GLuint gl_link(const char *vs, const char *fs, const char *const *attribs,
               const GLuint *locs, int nattribs, char *err, size_t errlen)
{
    GLuint v = compile(GL_VERTEX_SHADER, vs, err, errlen);
    GLuint f = v ? compile(GL_FRAGMENT_SHADER, fs, err, errlen) : 0;
    if (!f) {
        glDeleteShader(v);
        return 0;
    }
    GLuint p = glCreateProgram();
    glAttachShader(p, v);
    glAttachShader(p, f);
    for (int i = 0; i < nattribs; i++)
        glBindAttribLocation(p, locs[i], attribs[i]);
    glLinkProgram(p);
    glDeleteShader(v);      /* flagged; freed with the program */
    glDeleteShader(f);
    return built(p, 1, err, errlen);
}

int gl_programs_init(gl_engine *e, char *err, size_t errlen)
{
    static const char *const shape_attr[] = { "a_pos", "a_e", "a_m", "a_col" };
    static const GLuint shape_loc[] = { A_POS, A_E, A_M, A_COL };
    static const char *const point_attr[] = { "a_pos", "a_col" };
    static const GLuint point_loc[] = { A_POS, A_COL };
    static const char *const text_attr[] = { "a_pos", "a_uv" };
    static const GLuint text_loc[] = { A_POS, A_UV };
    e->shape_prog = gl_link(shape_vs, shape_fs, shape_attr, shape_loc, 4, err, errlen);
    if (e->shape_prog)
        e->point_prog = gl_link(point_vs, point_fs, point_attr, point_loc, 2, err, errlen);
    if (e->point_prog)
        e->text_prog = gl_link(text_vs, text_fs, text_attr, text_loc, 2, err, errlen);
    if (!e->text_prog)
        return -1;
    e->shape_vp = glGetUniformLocation(e->shape_prog, "u_vp");
    e->point_vp = glGetUniformLocation(e->point_prog, "u_vp");
    e->point_r = glGetUniformLocation(e->point_prog, "u_r");
    e->point_h = glGetUniformLocation(e->point_prog, "u_h");
    e->point_dot = glGetUniformLocation(e->point_prog, "u_dot");
    e->text_vp = glGetUniformLocation(e->text_prog, "u_vp");
    e->text_col = glGetUniformLocation(e->text_prog, "u_col");
    e->text_tex = glGetUniformLocation(e->text_prog, "u_tex");
    glUseProgram(e->text_prog);
    glUniform1i(e->text_tex, 0);
    glUseProgram(0);
    glGenTextures(1, &e->text_texture);
    return 0;
}

void gl_programs_viewport(gl_canvas *c)
{
    float vp[4] = { (float)c->pad, (float)c->pad, (float)(c->base.width + 2 * c->pad),
                    (float)(c->base.height + 2 * c->pad) };
    glUseProgram(c->gl.shape_prog);
    glUniform4fv(c->gl.shape_vp, 1, vp);
    glUseProgram(c->gl.point_prog);
    glUniform4fv(c->gl.point_vp, 1, vp);
    glUniform1f(c->gl.point_h, (float)c->base.height);
    glUseProgram(c->gl.text_prog);
    glUniform4fv(c->gl.text_vp, 1, vp);
    glUseProgram(0);
}

void gl_programs_free(gl_engine *e)
{
    glDeleteProgram(e->shape_prog);     /* 0 is ignored */
    glDeleteProgram(e->point_prog);
    glDeleteProgram(e->text_prog);
    glDeleteProgram(e->view3d_prog);
    glDeleteProgram(e->dense_prog);
    glDeleteTextures(2, e->dense_tex);     /* 0 is ignored */
    if (e->text_texture)
        glDeleteTextures(1, &e->text_texture);
    gl_fill_free(e);
}

/* ---- batches ----------------------------------------------------------- */

void gl_vert(float *v, double x, double y, double across, double along,
             double hw, double len, double dash, enum lrgl_mode mode, lr_rgba k)
{
    v[0] = (float)x;
    v[1] = (float)y;
    v[2] = (float)across;
    v[3] = (float)along;
    v[4] = (float)hw;
    v[5] = (float)len;
    v[6] = (float)dash;
    v[7] = (float)mode;
    v[8] = (float)k.r;
    v[9] = (float)k.g;
    v[10] = (float)k.b;
    v[11] = (float)k.a;
}

void gl_draw_triangles(gl_canvas *c, const float *v, size_t n)
{
    if (n == 0)
        return;
    const GLsizei stride = LRGL_VERT_FLOATS * sizeof(float);
    glUseProgram(c->gl.shape_prog);
    glEnableVertexAttribArray(A_POS);
    glEnableVertexAttribArray(A_E);
    glEnableVertexAttribArray(A_M);
    glEnableVertexAttribArray(A_COL);
    glVertexAttribPointer(A_POS, 2, GL_FLOAT, GL_FALSE, stride, v);
    glVertexAttribPointer(A_E, 4, GL_FLOAT, GL_FALSE, stride, v + 2);
    glVertexAttribPointer(A_M, 2, GL_FLOAT, GL_FALSE, stride, v + 6);
    glVertexAttribPointer(A_COL, 4, GL_FLOAT, GL_FALSE, stride, v + 8);
    glDrawArrays(GL_TRIANGLES, 0, (GLsizei)n);
    glDisableVertexAttribArray(A_POS);
    glDisableVertexAttribArray(A_E);
    glDisableVertexAttribArray(A_M);
    glDisableVertexAttribArray(A_COL);
}

/* Sprites are squares of this side; beyond it discs are drawn as quads
 * (llvmpipe's largest point is 255 px). */
#define POINT_MAX_SIZE 255.0
/* Below this radius a disc is the pixel holding its centre (as cairo's
 * stamps do: DISC_MIN_ARC_RADIUS there). */
#define DOT_RADIUS 0.8

/* The point program set for the pending batch's radius and arrays. */
static void points_begin(gl_canvas *c)
{
    double r = c->point_r;
    int dot = r < DOT_RADIUS;
    /* The square must hold every pixel the disc reaches into: those whose
     * centre is within r + 0.5 of its centre along x and y. A 64th more
     * keeps those when GL snaps the centre to its sub-pixel grid; any
     * pixel more has coverage 0 and is discarded. (2r + 2, the size
     * before, cost llvmpipe a quarter more fragments at r = 1.) */
    double size = dot ? 1.0 : 2.0 * r + 1.0 + 1.0 / 32.0;
    glUseProgram(c->gl.point_prog);
    glUniform1f(c->gl.point_r, (float)r);
    glUniform1f(c->gl.point_dot, dot ? 1.0f : 0.0f);
    glPointSize((float)size);
    glEnableVertexAttribArray(A_POS);
    glEnableVertexAttribArray(A_COL);
    glVertexAttribPointer(A_POS, 2, GL_FLOAT, GL_FALSE, 0, c->pxy);
    glVertexAttribPointer(A_COL, 4, GL_UNSIGNED_BYTE, GL_TRUE, 0, c->prgba);
}

static void points_end(void)
{
    glDisableVertexAttribArray(A_POS);
    glDisableVertexAttribArray(A_COL);
}

void gl_draw_points(gl_canvas *c, size_t first, size_t count)
{
    points_begin(c);
    glDrawArrays(GL_POINTS, (GLint)first, (GLsizei)count);
    points_end();
}

void gl_draw_point_list(gl_canvas *c, const uint32_t *list, size_t n)
{
    points_begin(c);
    glDrawElements(GL_POINTS, (GLsizei)n, GL_UNSIGNED_INT, list);
    points_end();
}

void gl_flush(gl_canvas *c)
{
    gl_use(c);
    if (c->batch == LRGL_BATCH_SHAPES)
        gl_draw_triangles(c, c->verts, c->nverts);
    else if (c->batch == LRGL_BATCH_POINTS && c->npoints > 0 && !gl_dense_flush(c))
        gl_draw_points(c, 0, c->npoints);
    c->batch = LRGL_BATCH_NONE;
    c->nverts = 0;
    c->npoints = 0;
}

/* A batch is drawn when it gets this big, to bound its memory. */
#define BATCH_MAX_VERTS (6u << 16)

/* The batches grow by doubling from this many items (lu_reserve). */
#define BATCH_FIRST 1024

float *gl_shape_verts(gl_canvas *c, size_t n)
{
    if (c->batch != LRGL_BATCH_SHAPES || c->nverts + n > BATCH_MAX_VERTS)
        gl_flush(c);
    c->batch = LRGL_BATCH_SHAPES;
    if (lu_reserve(&c->verts, &c->capverts, c->nverts + n, LRGL_VERT_FLOATS * sizeof(float),
                   BATCH_FIRST)) {
        c->failed = 1;
        return NULL;
    }
    float *v = c->verts + c->nverts * LRGL_VERT_FLOATS;
    c->nverts += n;
    return v;
}

int gl_points_room(gl_canvas *c, double r, size_t n)
{
    if (c->batch != LRGL_BATCH_POINTS || c->point_r != r ||
        c->npoints == BATCH_MAX_POINTS)
        gl_flush(c);
    c->batch = LRGL_BATCH_POINTS;
    c->point_r = r;
    size_t need = c->npoints + (n ? n : 1);
    if (need > BATCH_MAX_POINTS)
        need = BATCH_MAX_POINTS;
    if (need > c->cappoints) {
        size_t cap = c->cappoints, cap2 = c->cappoints;   /* one capacity for both */
        if (lu_reserve(&c->pxy, &cap, need, 2 * sizeof(float), BATCH_FIRST) ||
            lu_reserve(&c->prgba, &cap2, need, 4, BATCH_FIRST)) {
            c->failed = 1;
            return -1;
        }
        c->cappoints = cap;
    }
    return 0;
}
