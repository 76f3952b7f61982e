/* canvas_osmesa.c - the lr_canvas interface over OSMesa (Mesa's off-screen
 * OpenGL, llvmpipe on Debian 12): the context, clearing, clipping, and
 * reading the pixels back.
 *
 * Points whose centre leaves the viewport are dropped whole by GL, even
 * when part of the sprite would show; so the viewport overhangs the canvas
 * by `pad` pixels on each side and a disc on the image's edge is drawn in
 * part, as cairo draws it. Pixels outside the canvas do not exist in the
 * buffer, so nothing lands there. */
#include "canvas_osmesa.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* How far discs may hang over the edge and still be drawn: the largest
 * sprite's half. */
#define VIEWPORT_PAD 128

static gl_canvas *current;      /* whose context is current on this thread */
static gl_engine spare;         /* the last canvas's context, for the next */
static const lr_canvas_ops osmesa_ops;

void gl_use(gl_canvas *c)
{
    if (current == c)
        return;
    OSMesaMakeCurrent(c->gl.ctx, c->buf, GL_UNSIGNED_BYTE, c->base.width,
                      c->base.height);
    current = c;
}

static void set_err(char *err, size_t errlen, const char *msg)
{
    if (err && errlen > 0)
        snprintf(err, errlen, "cannot create canvas: %s", msg);
}

/* Nothing stays bound to a buffer that is about to be freed. */
static void release_current(void)
{
    OSMesaMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0);
    current = NULL;
}

static void engine_destroy(gl_engine *e)
{
    if (e->ctx)
        OSMesaDestroyContext(e->ctx);   /* its programs and buffers with it */
    memset(e, 0, sizeof *e);
}

void lr_canvas_osmesa_release(void)
{
    if (current)
        release_current();
    engine_destroy(&spare);
}

/* keep: the context works and may serve the next canvas. */
static void destroy(gl_canvas *c, int keep)
{
    if (current == c)
        release_current();
    if (keep && c->gl.ctx && !spare.ctx) {
        spare = c->gl;
    } else {
        if (c->gl.ctx)
            release_current();
        engine_destroy(&c->gl);
    }
    free(c->verts);
    free(c->pxy);
    free(c->prgba);
    free(c->buf);
    free(c);
}

static void gl_destroy(lr_canvas *base)
{
    gl_canvas *c = glc(base);
    destroy(c, !c->failed);
}

/* The fixed state every drawing call relies on. */
static void initial_state(gl_canvas *c)
{
    int w = c->base.width, h = c->base.height;
    glViewport(-c->pad, -c->pad, w + 2 * c->pad, h + 2 * c->pad);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DITHER);           /* same pixels every time */
    glDisable(GL_MULTISAMPLE);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);   /* premultiplied OVER */
    glDisable(GL_POINT_SPRITE);     /* plain squares (see the point shader) */
    glDisable(GL_PROGRAM_POINT_SIZE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilMask(0xFF);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glClearStencil(0);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

/* The context: the spare one, or a new one with its programs compiled. */
static int engine_start(gl_canvas *c, char *err, size_t errlen)
{
    int fresh = !spare.ctx;
    if (!fresh) {
        c->gl = spare;
        memset(&spare, 0, sizeof spare);
    } else {
        /* 8 stencil bits for fills' winding numbers; no depth, no accumulation */
        c->gl.ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 8, 0, NULL);
        if (!c->gl.ctx) {
            set_err(err, errlen, "OSMesa cannot create a context");
            return -1;
        }
    }
    current = NULL;
    if (!OSMesaMakeCurrent(c->gl.ctx, c->buf, GL_UNSIGNED_BYTE, c->base.width,
                           c->base.height)) {
        set_err(err, errlen, "OSMesa cannot use the image buffer");
        return -1;
    }
    current = c;
    char why[512] = "";
    if (fresh && gl_programs_init(&c->gl, why, sizeof why) != 0) {
        set_err(err, errlen, why);
        return -1;
    }
    return 0;
}

lr_canvas *lr_canvas_osmesa_new(int width, int height, char *err, size_t errlen)
{
    if (width <= 0 || height <= 0 || width > LR_CANVAS_MAX_SIZE ||
        height > LR_CANVAS_MAX_SIZE) {
        char why[96];
        snprintf(why, sizeof why, "invalid size %dx%d (1..%d each)", width,
                 height, LR_CANVAS_MAX_SIZE);
        set_err(err, errlen, why);
        return NULL;
    }
    gl_canvas *c = calloc(1, sizeof *c);
    if (c)
        c->buf = malloc(4 * (size_t)width * (size_t)height);
    if (!c || !c->buf) {
        free(c);
        char why[80];   /* the size named, as the cairo canvas does */
        snprintf(why, sizeof why, "cannot create a %d x %d canvas: out of memory", width,
                 height);
        set_err(err, errlen, why);
        return NULL;
    }
    c->base.ops = &osmesa_ops;
    c->base.width = width;
    c->base.height = height;
    if (engine_start(c, err, errlen) != 0) {
        destroy(c, 0);
        return NULL;
    }
    GLint maxw = 0, maxh = 0, vp[2] = { 0, 0 };
    OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &maxw);
    OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &maxh);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, vp);
    if (width > maxw || height > maxh) {
        char why[96];
        snprintf(why, sizeof why, "OSMesa draws at most %dx%d pixels (asked "
                 "for %dx%d)", maxw, maxh, width, height);
        set_err(err, errlen, why);
        destroy(c, 1);
        return NULL;
    }
    int room_w = (vp[0] - width) / 2, room_h = (vp[1] - height) / 2;
    c->pad = VIEWPORT_PAD;
    if (room_w < c->pad)
        c->pad = room_w;
    if (room_h < c->pad)
        c->pad = room_h;
    if (c->pad < 0)
        c->pad = 0;
    gl_programs_viewport(c);
    initial_state(c);
    if (glGetError() != GL_NO_ERROR) {
        set_err(err, errlen, "OSMesa reported an error while setting up");
        destroy(c, 0);
        return NULL;
    }
    return &c->base;
}

static void gl_clear(lr_canvas *base, lr_rgba k)
{
    gl_canvas *c = glc(base);
    gl_flush(c);
    /* premultiplied, like everything in the buffer; SOURCE, not OVER */
    glClearColor((float)(k.r * k.a), (float)(k.g * k.a), (float)(k.b * k.a),
                 (float)k.a);
    glClear(GL_COLOR_BUFFER_BIT);
}

static void gl_clip(lr_canvas *base, int x, int y, int w, int h)
{
    gl_canvas *c = glc(base);
    gl_flush(c);
    if (w == 0) {
        glDisable(GL_SCISSOR_TEST);
        return;
    }
    if (w < 0)
        x = y = w = h = 0;
    glEnable(GL_SCISSOR_TEST);
    /* GL counts rows from the bottom */
    glScissor(x, c->base.height - (y + h), w, h);
}

/* Premultiplied to straight, rows flipped from GL's bottom-up order; the
 * same rounding as the cairo backend, so opaque colours come back exact. */
static void straighten(const unsigned char *src, unsigned char *dst, int w, int h)
{
    size_t row = 4 * (size_t)w;
    for (int y = 0; y < h; y++) {
        const unsigned char *s = src + (size_t)(h - 1 - y) * row;
        unsigned char *d = dst + (size_t)y * row;
        for (int x = 0; x < w; x++, s += 4, d += 4) {
            unsigned a = s[3];
            if (a == 255) {     /* the common case, and the formula's result */
                memcpy(d, s, 4);
                continue;
            }
            for (int k = 0; k < 3; k++) {
                unsigned v = a ? (s[k] * 255u + a / 2) / a : 0;
                d[k] = (unsigned char)(v > 255 ? 255 : v);
            }
            d[3] = (unsigned char)a;
        }
    }
}

static unsigned char *gl_read(lr_canvas *base)
{
    gl_canvas *c = glc(base);
    gl_flush(c);
    glFinish();
    if (c->failed || glGetError() != GL_NO_ERROR)
        return NULL;
    size_t n = 4 * (size_t)c->base.width * (size_t)c->base.height;
    unsigned char *raw = malloc(n), *out = malloc(n);
    if (!raw || !out) {
        free(raw);
        free(out);
        return NULL;
    }
    glReadPixels(0, 0, c->base.width, c->base.height, GL_RGBA, GL_UNSIGNED_BYTE, raw);
    if (glGetError() != GL_NO_ERROR) {
        free(raw);
        free(out);
        return NULL;
    }
    straighten(raw, out, c->base.width, c->base.height);
    free(raw);
    return out;
}

static const lr_canvas_ops osmesa_ops = {
    .backend = LR_BACKEND_OSMESA,
    .destroy = gl_destroy,
    .clear = gl_clear,
    .line = gl_line,
    .rect = gl_rect,
    .discs = gl_discs,
    .text = gl_text,
    .fill = gl_fill,
    .clip = gl_clip,
    .read_rgba = gl_read,
    .finish = NULL,
};
