/* canvas_gl_fill.c - filled polygons (and stroked rectangles) in GL.
 *
 * The stencil method counts winding numbers: the fan of each ring adds one
 * where its triangles face front and takes one where they face back, so
 * any polygon, concave or holed, fills by the nonzero rule as cairo fills
 * it, and rings of one orientation unite without seams (filled contour
 * cells). Antialiasing is by 16 samples per pixel: the fill is repeated at
 * 16 sub-pixel offsets into an off-screen coverage buffer (a framebuffer
 * object the size of the fill's bounding box), each pass adding 1/16 where
 * the winding number is not zero, and that coverage is then blended onto
 * the canvas with the fill colour. The offsets form a 16-rooks pattern
 * (every row and column of a 16 x 16 sub-grid used once), so edges along
 * either axis get 16 levels of coverage, like cairo's. */
#include "canvas_gl.h"

#include <math.h>
#include <stdlib.h>

#define SAMPLES 16

void gl_fill_free(gl_engine *e)
{
    if (e->fill_fbo)
        glDeleteFramebuffers(1, &e->fill_fbo);
    if (e->fill_tex)
        glDeleteTextures(1, &e->fill_tex);
    if (e->fill_stencil)
        glDeleteRenderbuffers(1, &e->fill_stencil);
    e->fill_fbo = e->fill_tex = e->fill_stencil = 0;
    e->fill_w = e->fill_h = 0;
}

/* A coverage buffer of at least w x h; -1 if GL cannot make one. */
static int coverage_buffer(gl_canvas *c, int w, int h)
{
    if (c->gl.fill_fbo && c->gl.fill_w >= w && c->gl.fill_h >= h)
        return 0;
    if (c->gl.fill_w > w)
        w = c->gl.fill_w;
    if (c->gl.fill_h > h)
        h = c->gl.fill_h;
    gl_fill_free(&c->gl);
    glGenTextures(1, &c->gl.fill_tex);
    glBindTexture(GL_TEXTURE_2D, c->gl.fill_tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenRenderbuffers(1, &c->gl.fill_stencil);
    glBindRenderbuffer(GL_RENDERBUFFER, c->gl.fill_stencil);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glGenFramebuffers(1, &c->gl.fill_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, c->gl.fill_fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                           c->gl.fill_tex, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT,
                              GL_RENDERBUFFER, c->gl.fill_stencil);
    GLenum st = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, c->fbo);   /* the canvas (0 under OSMesa) */
    if (st != GL_FRAMEBUFFER_COMPLETE) {
        gl_fill_free(&c->gl);
        return -1;
    }
    c->gl.fill_w = w;
    c->gl.fill_h = h;
    return 0;
}

/* The fans of all rings (3 vertices per triangle), in canvas pixels. */
static float *fans(size_t npoly, const size_t *counts, const double *xy, size_t *nverts)
{
    size_t ntri = 0;
    for (size_t p = 0; p < npoly; p++)
        if (counts[p] >= 3)
            ntri += counts[p] - 2;
    *nverts = 3 * ntri;
    float *v = malloc((ntri ? 3 * ntri : 1) * LRGL_VERT_FLOATS * sizeof *v);
    if (!v)
        return NULL;
    const lr_rgba none = { 0, 0, 0, 0 };
    float *w = v;
    const double *r = xy;
    for (size_t p = 0; p < npoly; p++) {
        for (size_t i = 1; counts[p] >= 3 && i + 1 < counts[p]; i++) {
            const double *q[3] = { r, r + 2 * i, r + 2 * i + 2 };
            for (int j = 0; j < 3; j++, w += LRGL_VERT_FLOATS)
                gl_vert(w, q[j][0], q[j][1], 0, 0, 0, 0, 0, LRGL_SOLID, none);
        }
        r += 2 * counts[p];
    }
    return v;
}

/* Accumulates the coverage of the fans over the box x0, y0, w, h (canvas
 * pixels) into the coverage buffer's texels 0..w-1, 0..h-1. */
static void accumulate(gl_canvas *c, const float *fan, size_t nfan, int x0,
                       int y0, int w, int h)
{
    const lr_rgba step = { 1, 1, 1, 1.0 / SAMPLES };
    float box[6 * LRGL_VERT_FLOATS];
    const double bx[6] = { x0 - 1, x0 + w + 1, x0 + w + 1, x0 - 1, x0 + w + 1, x0 - 1 };
    const double by[6] = { y0 - 1, y0 - 1, y0 + h + 1, y0 - 1, y0 + h + 1, y0 + h + 1 };
    for (int i = 0; i < 6; i++)
        gl_vert(box + LRGL_VERT_FLOATS * i, bx[i], by[i], 0, 0, 0, 0, 0, LRGL_SOLID, step);

    glBindFramebuffer(GL_FRAMEBUFFER, c->gl.fill_fbo);
    glViewport(0, 0, w, h);
    glEnable(GL_SCISSOR_TEST);      /* the buffer may be larger than the box */
    glScissor(0, 0, w, h);
    glClearColor(0, 0, 0, 0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glBlendFunc(GL_ONE, GL_ONE);    /* coverage adds up */
    glUseProgram(c->gl.shape_prog);
    for (int k = 0; k < SAMPLES; k++) {
        /* sample k at ((k + 0.5) / 16, ((7k + 3) mod 16 + 0.5) / 16) of
         * each pixel: the pixel centre samples the fans moved by the
         * opposite of its offset from the centre */
        double sx = (k + 0.5) / SAMPLES - 0.5;
        double sy = ((7 * k + 3) % SAMPLES + 0.5) / SAMPLES - 0.5;
        glUniform4f(c->gl.shape_vp, (float)(-x0 - sx), (float)(-y0 - sy), (float)w,
                    (float)h);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
        glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
        gl_draw_triangles(c, fan, nfan);
        /* add 1/16 where the winding number is not zero, zeroing it all */
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
        glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
        gl_draw_triangles(c, box, 6);
    }
    glDisable(GL_STENCIL_TEST);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glUniform4f(c->gl.shape_vp, (float)c->pad, (float)c->pad,
                (float)(c->base.width + 2 * c->pad), (float)(c->base.height + 2 * c->pad));
    glBindFramebuffer(GL_FRAMEBUFFER, c->fbo);   /* the canvas (0 under OSMesa) */
    glViewport(-c->pad, -c->pad, c->base.width + 2 * c->pad, c->base.height + 2 * c->pad);
}

void gl_fill(lr_canvas *base, size_t npoly, const size_t *counts,
             const double *xy, lr_rgba colour)
{
    gl_canvas *c = glc(base);
    double b[4] = { INFINITY, INFINITY, -INFINITY, -INFINITY };
    size_t total = 0;
    for (size_t k = 0; k < npoly; k++)
        total += counts[k];
    for (size_t i = 0; i < total; i++) {
        b[0] = fmin(b[0], xy[2 * i]);
        b[1] = fmin(b[1], xy[2 * i + 1]);
        b[2] = fmax(b[2], xy[2 * i]);
        b[3] = fmax(b[3], xy[2 * i + 1]);
    }
    /* the box on the canvas, whole pixels */
    int x0 = (int)fmax(0.0, floor(b[0])), y0 = (int)fmax(0.0, floor(b[1]));
    int x1 = (int)fmin((double)c->base.width, ceil(b[2]));
    int y1 = (int)fmin((double)c->base.height, ceil(b[3]));
    if (!(b[2] >= b[0]) || x1 <= x0 || y1 <= y0)
        return;     /* nothing, or nothing on the canvas */
    size_t nfan;
    float *fan = fans(npoly, counts, xy, &nfan);
    if (!fan) {
        c->failed = 1;
        return;
    }
    gl_flush(c);
    if (nfan > 0) {
        GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
        GLint clip[4];
        glGetIntegerv(GL_SCISSOR_BOX, clip);
        int ok = coverage_buffer(c, x1 - x0, y1 - y0) == 0;
        if (ok)
            accumulate(c, fan, nfan, x0, y0, x1 - x0, y1 - y0);
        /* the canvas's own clip back, for the blend */
        if (scissor)
            glScissor(clip[0], clip[1], clip[2], clip[3]);
        else
            glDisable(GL_SCISSOR_TEST);
        if (ok)
            gl_blend_coverage(c, c->gl.fill_tex, x0, y0, x1 - x0, y1 - y0, c->gl.fill_w,
                              c->gl.fill_h, 1, colour);
        else
            c->failed = 1;
    }
    free(fan);
}

/* cairo strokes a rectangle with mitred corners: the ring between the
 * outer and the inner rectangle, which the nonzero rule gives from two
 * rings of opposite orientation. */
void gl_rect(lr_canvas *base, double x, double y, double w, double h,
             double line_width, lr_rgba stroke)
{
    double x0 = fmin(x, x + w), x1 = fmax(x, x + w);
    double y0 = fmin(y, y + h), y1 = fmax(y, y + h), e = 0.5 * line_width;
    double xy[16] = { x0 - e, y0 - e, x1 + e, y0 - e, x1 + e, y1 + e, x0 - e, y1 + e,
                      x0 + e, y0 + e, x0 + e, y1 - e, x1 - e, y1 - e, x1 - e, y0 + e };
    size_t counts[2] = { 4, 4 };
    int hollow = x1 - x0 > 2 * e && y1 - y0 > 2 * e;
    gl_fill(base, hollow ? 2 : 1, counts, xy, stroke);
}
