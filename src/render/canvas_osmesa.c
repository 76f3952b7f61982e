/* canvas_osmesa.c - the OSMesa platform of the GL backends (canvas_gl.h):
 * Mesa's off-screen OpenGL (llvmpipe on Debian 12), drawing into a buffer
 * the canvas owns. The only file that calls the OSMesa API. Mesa removed
 * OSMesa in 25.1; canvas_egl.c is its successor. */
#include "canvas_gl.h"

#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

#include "util.h"

static int create(gl_engine *e, char *err, size_t errlen)
{
    /* 8 stencil bits for fills' winding numbers; no depth, no accumulation */
    e->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 8, 0, NULL);
    if (!e->ctx) {
        snprintf(err, errlen, "OSMesa cannot create a context");
        return -1;
    }
    return 0;
}

static int target_new(gl_canvas *c, char *err, size_t errlen)
{
    int w = c->base.width, h = c->base.height;
    c->buf = malloc(4 * (size_t)w * (size_t)h);
    if (!c->buf) {   /* the size named, as the cairo canvas does */
        snprintf(err, errlen, "cannot create a %d x %d canvas: out of memory", w, h);
        return -1;
    }
    if (!OSMesaMakeCurrent(c->gl.ctx, c->buf, GL_UNSIGNED_BYTE, w, h)) {
        snprintf(err, errlen, "OSMesa cannot use the image buffer");
        return -1;
    }
    GLint maxw = 0, maxh = 0;
    OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &maxw);
    OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &maxh);
    if (w > maxw || h > maxh) {
        snprintf(err, errlen, "OSMesa draws at most %dx%d pixels (asked for "
                 "%dx%d)", maxw, maxh, w, h);
        return -1;
    }
    return 0;
}

static void use(gl_canvas *c)
{
    OSMesaMakeCurrent(c->gl.ctx, c->buf, GL_UNSIGNED_BYTE, c->base.width,
                      c->base.height);
}

/* The buffer is the canvas's, freed with it (canvas_gl.c). */
static void target_free(gl_canvas *c) { (void)c; }

/* Nothing stays bound to a buffer that is about to be freed. */
static void release(void)
{
    OSMesaMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0);
}

static void destroy(gl_engine *e)
{
    OSMesaDestroyContext(e->ctx);
}

GL_PLATFORM_DEFINE(gl_osmesa_platform, lr_canvas_osmesa_new, LR_BACKEND_OSMESA, 0)
