/* canvas_gl.c - the lr_canvas interface shared by the GL backends (OSMesa,
 * EGL): making a canvas on a platform's context, clearing, clipping,
 * reading the pixels back, and keeping a context for the next canvas.
 *
 * Points whose centre leaves the viewport are dropped whole by GL, even
 * when part of the sprite would show; so the viewport overhangs the canvas
 * by `pad` pixels on each side and a disc on the image's edge is drawn in
 * part, as cairo draws it. Pixels outside the canvas do not exist in the
 * target, so nothing lands there. */
#include "canvas_gl.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "util.h"

/* How far discs may hang over the edge and still be drawn: the largest
 * sprite's half. */
#define VIEWPORT_PAD 128

static gl_canvas *current;      /* whose context is current on this thread */
/* The platform that made a context current last: OSMesa and Mesa's EGL
 * share one dispatch (libglapi), and a switch between them must release
 * the other's context first, or GL calls keep going to the old one. */
static const gl_platform *current_plat;
static gl_engine spare[2];      /* per platform slot: the last canvas's context */
static const lr_canvas_ops osmesa_ops, egl_ops;

static void release_current(void)
{
    if (current_plat)
        current_plat->release();
    current = NULL;
    current_plat = NULL;
}

void gl_use(gl_canvas *c)
{
    if (current == c)
        return;
    if (current_plat && current_plat != c->plat)
        release_current();
    c->plat->use(c);
    current = c;
    current_plat = c->plat;
}

static void engine_destroy(const gl_platform *p, gl_engine *e)
{
    if (e->ctx)
        p->destroy(e);      /* its programs and buffers with it */
    gl_dense_release(e);
    free(e->kept_pxy);
    free(e->kept_prgba);
    free(e->readback);
    memset(e, 0, sizeof *e);
}

void lr_canvas_gl_release(void)
{
    release_current();
#ifdef LAMINA_HAVE_OSMESA
    engine_destroy(&gl_osmesa_platform, &spare[gl_osmesa_platform.slot]);
#endif
#ifdef LAMINA_HAVE_EGL
    engine_destroy(&gl_egl_platform, &spare[gl_egl_platform.slot]);
    gl_egl_park();
#endif
}

/* keep: the context works and may serve the next canvas. has_target: the
 * platform's target_new succeeded. */
static void destroy(gl_canvas *c, int keep, int has_target)
{
    const gl_platform *p = c->plat;
    if (has_target) {
        gl_use(c);          /* GL objects are deleted in their own context */
        p->target_free(c);
    }
    if (current == c || current_plat == p)
        release_current();
    gl_engine *s = &spare[p->slot];
    if (keep && c->gl.ctx && !s->ctx) {
        /* the point arrays go with it: a frame of 10^6 particles would
         * otherwise grow them again from nothing, page by page */
        c->gl.kept_pxy = c->pxy;
        c->gl.kept_prgba = c->prgba;
        c->gl.kept_cap = c->cappoints;
        c->pxy = NULL;
        c->prgba = NULL;
        *s = c->gl;
    } else
        engine_destroy(p, &c->gl);
    free(c->verts);
    free(c->pxy);
    free(c->prgba);
    free(c->buf);
    free(c);
}

static void gl_destroy(lr_canvas *base)
{
    gl_canvas *c = glc(base);
    destroy(c, !c->failed, 1);
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

/* The context: the spare one, or a new one. *fresh: its programs are
 * still to be compiled. */
static int engine_start(gl_canvas *c, int *fresh, char *err, size_t errlen)
{
    gl_engine *s = &spare[c->plat->slot];
    *fresh = !s->ctx;
    if (!*fresh) {
        c->gl = *s;
        memset(s, 0, sizeof *s);
        c->pxy = c->gl.kept_pxy;
        c->prgba = c->gl.kept_prgba;
        c->cappoints = c->gl.kept_cap;
        c->gl.kept_pxy = NULL;
        c->gl.kept_prgba = NULL;
        c->gl.kept_cap = 0;
        return 0;
    }
    char why[512] = "";
    if (c->plat->create(&c->gl, why, sizeof why) != 0) {
        lu_err(err, errlen, "cannot create canvas: %s", why);
        return -1;
    }
    return 0;
}

lr_canvas *gl_canvas_new(const gl_platform *p, int width, int height, char *err,
                         size_t errlen)
{
    if (width <= 0 || height <= 0 || width > LR_CANVAS_MAX_SIZE ||
        height > LR_CANVAS_MAX_SIZE) {
        char why[96];
        snprintf(why, sizeof why, "invalid size %dx%d (1..%d each)", width,
                 height, LR_CANVAS_MAX_SIZE);
        lu_err(err, errlen, "cannot create canvas: %s", why);
        return NULL;
    }
    gl_canvas *c = calloc(1, sizeof *c);
    if (!c) {
        lu_err(err, errlen, "cannot create canvas: %s", "out of memory");
        return NULL;
    }
    c->base.ops = p->backend == LR_BACKEND_EGL ? &egl_ops : &osmesa_ops;
    c->base.width = width;
    c->base.height = height;
    c->plat = p;
    int fresh = 0;
    if (engine_start(c, &fresh, err, errlen) != 0) {
        destroy(c, 0, 0);
        return NULL;
    }
    /* the platform makes its own context current: leave the other's */
    if (current_plat && current_plat != p)
        release_current();
    char why[512] = "";
    if (p->target_new(c, why, sizeof why) != 0) {
        lu_err(err, errlen, "cannot create canvas: %s", why);
        current = NULL;
        current_plat = p;
        /* a size it cannot draw: the context is fine, and kept once its
         * programs are compiled */
        destroy(c, !fresh, 0);
        return NULL;
    }
    current = c;
    current_plat = p;
    if (fresh && gl_programs_init(&c->gl, why, sizeof why) != 0) {
        lu_err(err, errlen, "cannot create canvas: %s", why);
        destroy(c, 0, 1);
        return NULL;
    }
    GLint vp[2] = { 0, 0 };
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, vp);
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
        lu_err(err, errlen, "cannot create canvas: %s", "OpenGL reported an error while setting up");
        destroy(c, 0, 1);
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

/* The canvas's own framebuffer (bound by gl_use) is what glReadPixels
 * reads: OSMesa's buffer or EGL's framebuffer object, both bottom-up. */
static unsigned char *gl_read(lr_canvas *base)
{
    gl_canvas *c = glc(base);
    gl_flush(c);
    glFinish();
    if (c->failed || glGetError() != GL_NO_ERROR)
        return NULL;
    size_t n = 4 * (size_t)c->base.width * (size_t)c->base.height;
    if (c->gl.readcap < n) {    /* kept with the context, like the points */
        free(c->gl.readback);
        c->gl.readback = malloc(n);
        c->gl.readcap = c->gl.readback ? n : 0;
    }
    unsigned char *raw = c->gl.readback, *out = malloc(n);
    if (!raw || !out) {
        free(out);
        return NULL;
    }
    glReadPixels(0, 0, c->base.width, c->base.height, GL_RGBA, GL_UNSIGNED_BYTE, raw);
    if (glGetError() != GL_NO_ERROR) {
        free(out);
        return NULL;
    }
    straighten(raw, out, c->base.width, c->base.height);
    return out;
}

#define GL_OPS(which)                                                       \
    {                                                                       \
        .backend = which, .destroy = gl_destroy, .clear = gl_clear,         \
        .line = gl_line, .rect = gl_rect, .discs = gl_discs,                \
        .text = gl_text, .fill = gl_fill, .clip = gl_clip,                  \
        .read_rgba = gl_read, .finish = NULL,                               \
    }
static const lr_canvas_ops osmesa_ops = GL_OPS(LR_BACKEND_OSMESA);
static const lr_canvas_ops egl_ops = GL_OPS(LR_BACKEND_EGL);

lr_canvas *gl_canvas_new_charged(const gl_platform *p, int width, int height, char *err,
                                 size_t errlen)
{
    size_t charged;
    if (lr_canvas_charge(width, height, &charged, err, errlen) != 0)
        return NULL;
    lr_canvas *c = gl_canvas_new(p, width, height, err, errlen);
    if (c)
        c->charged = charged;
    else
        lu_budget_release(LU_MEM_RENDER, charged);
    return c;
}
