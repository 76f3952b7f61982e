/* canvas_egl.c - the EGL platform of the GL backends (canvas_gl.h): a
 * desktop OpenGL context on EGL's surfaceless platform (Mesa's llvmpipe
 * on a machine without a GPU; the GPU's driver when there is one),
 * drawing into a framebuffer object, since a surfaceless context has no
 * window or buffer of its own. The only file that calls the EGL API.
 *
 * EGL is OSMesa's successor: Mesa 25.1 removed OSMesa, and the drawing
 * code (canvas_gl_*.c) runs unchanged on either. */
#include "canvas_gl.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util.h"

/* One display for the process, opened by the first EGL canvas or probe. */
static EGLDisplay dpy = EGL_NO_DISPLAY;
static const char *dpy_kind = "";     /* which EGL platform it came from */
static int no_config;                 /* EGL_KHR_no_config_context */

/* Is ext one of the space-separated names in list? */
static int has_ext(const char *list, const char *ext)
{
    size_t n = strlen(ext);
    for (const char *p = list; p && (p = strstr(p, ext)) != NULL; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return 1;
    return 0;
}

static EGLDisplay try_display(EGLDisplay d, const char *kind)
{
    EGLint major = 0, minor = 0;
    if (d == EGL_NO_DISPLAY || !eglInitialize(d, &major, &minor))
        return EGL_NO_DISPLAY;
    dpy_kind = kind;
    return d;
}

/* The surfaceless platform first (no window system, no device file
 * needed), then the first device, then whatever the default display is. */
static int display_open(char *err, size_t errlen)
{
    if (dpy != EGL_NO_DISPLAY)
        return 0;
    /* NULL without EGL_EXT_client_extensions: then only eglGetDisplay */
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (get_platform_display && has_ext(client, "EGL_MESA_platform_surfaceless"))
        dpy = try_display(get_platform_display(EGL_PLATFORM_SURFACELESS_MESA,
                                               EGL_DEFAULT_DISPLAY, NULL),
                          "surfaceless");
    PFNEGLQUERYDEVICESEXTPROC query_devices =
        (PFNEGLQUERYDEVICESEXTPROC)eglGetProcAddress("eglQueryDevicesEXT");
    if (dpy == EGL_NO_DISPLAY && get_platform_display && query_devices &&
        has_ext(client, "EGL_EXT_platform_device")) {
        EGLDeviceEXT dev;
        EGLint ndev = 0;
        if (query_devices(1, &dev, &ndev) && ndev > 0)
            dpy = try_display(get_platform_display(EGL_PLATFORM_DEVICE_EXT, dev,
                                                   NULL), "device");
    }
    if (dpy == EGL_NO_DISPLAY)
        dpy = try_display(eglGetDisplay(EGL_DEFAULT_DISPLAY), "default");
    if (dpy == EGL_NO_DISPLAY) {
        snprintf(err, errlen, "EGL has no display (error 0x%x; Debian: install "
                 "libegl-mesa0 for Mesa's surfaceless platform)", eglGetError());
        return -1;
    }
    const char *ext = eglQueryString(dpy, EGL_EXTENSIONS);
    if (!has_ext(ext, "EGL_KHR_surfaceless_context")) {
        snprintf(err, errlen, "EGL's %s display cannot make a context current "
                 "without a surface (no EGL_KHR_surfaceless_context)", dpy_kind);
        gl_egl_terminate();
        return -1;
    }
    no_config = has_ext(ext, "EGL_KHR_no_config_context");
    return 0;
}

/* At shutdown the display is left initialised, only unbound: Mesa's EGL
 * driver, terminated, frees all but 112 bytes and unloads the module that
 * allocated them, so LeakSanitizer reports them with no module to name
 * (and no suppression can match); initialised, they stay reachable. */
void gl_egl_park(void)
{
    if (dpy == EGL_NO_DISPLAY)
        return;
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglReleaseThread();
}

void gl_egl_terminate(void)
{
    if (dpy == EGL_NO_DISPLAY)
        return;
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglTerminate(dpy);
    eglReleaseThread();
    dpy = EGL_NO_DISPLAY;
}

/* A compatibility (not core) context: the drawing code is GLSL 1.20 with
 * point sizes and client-side vertex arrays, as under OSMesa. */
static int create(gl_engine *e, char *err, size_t errlen)
{
    if (display_open(err, errlen) != 0)
        return -1;
    if (!eglBindAPI(EGL_OPENGL_API)) {
        snprintf(err, errlen, "EGL's %s display has no desktop OpenGL", dpy_kind);
        return -1;
    }
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!no_config) {
        /* any config that renders OpenGL: the framebuffer object decides
         * the pixel format, not the config */
        const EGLint want[] = { EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                EGL_SURFACE_TYPE, 0, EGL_NONE };
        EGLint n = 0;
        if (!eglChooseConfig(dpy, want, &config, 1, &n) || n < 1) {
            snprintf(err, errlen, "EGL's %s display has no OpenGL config", dpy_kind);
            return -1;
        }
    }
    e->ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
    if (e->ctx == EGL_NO_CONTEXT) {
        e->ctx = NULL;
        snprintf(err, errlen, "EGL cannot create an OpenGL context (error 0x%x)",
                 eglGetError());
        return -1;
    }
    return 0;
}

static void use(gl_canvas *c)
{
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, c->gl.ctx);
    glBindFramebuffer(GL_FRAMEBUFFER, c->fbo);
}

/* The canvas's pixels: RGBA8 colour and a depth-stencil buffer (OSMesa's
 * buffer has 8 stencil bits; the packed format is the one every driver
 * has), bottom-up like OSMesa's, so reading back is the same. */
static int target_new(gl_canvas *c, char *err, size_t errlen)
{
    int w = c->base.width, h = c->base.height;
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, c->gl.ctx)) {
        snprintf(err, errlen, "EGL cannot make its context current (error 0x%x)",
                 eglGetError());
        return -1;
    }
    /* The GL entry points lamina links must reach this context: a build
     * that also has OSMesa calls Mesa's, which another vendor's EGL (a
     * GPU driver) does not serve. */
    const char *version = (const char *)glGetString(GL_VERSION);
    int major = 0, minor = 0;
    if (!version || sscanf(version, "%d.%d", &major, &minor) != 2) {
        snprintf(err, errlen, "EGL's OpenGL context does not answer through the "
                 "GL library lamina is linked with (a non-Mesa EGL in a build "
                 "with OSMesa? build with -DLAMINA_OSMESA=OFF)");
        return -1;
    }
    if (major < 2 || (major == 2 && minor < 1)) {
        snprintf(err, errlen, "EGL gives OpenGL %d.%d; lamina needs 2.1", major, minor);
        return -1;
    }
    GLint maxrb = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxrb);
    if (w > maxrb || h > maxrb) {
        snprintf(err, errlen, "EGL's OpenGL draws at most %dx%d pixels (asked "
                 "for %dx%d)", maxrb, maxrb, w, h);
        return -1;
    }
    glGenFramebuffers(1, &c->fbo);
    glGenRenderbuffers(2, c->rb);
    glBindRenderbuffer(GL_RENDERBUFFER, c->rb[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, c->rb[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, c->fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                              GL_RENDERBUFFER, c->rb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT,
                              GL_RENDERBUFFER, c->rb[1]);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        snprintf(err, errlen, "EGL's OpenGL cannot make a %dx%d framebuffer", w, h);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &c->fbo);
        glDeleteRenderbuffers(2, c->rb);
        c->fbo = c->rb[0] = c->rb[1] = 0;
        return -1;
    }
    return 0;
}

static void target_free(gl_canvas *c)
{
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (c->fbo)
        glDeleteFramebuffers(1, &c->fbo);
    if (c->rb[0])
        glDeleteRenderbuffers(2, c->rb);
    c->fbo = c->rb[0] = c->rb[1] = 0;
}

static void release(void)
{
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

static void destroy(gl_engine *e)
{
    eglDestroyContext(dpy, e->ctx);
}

GL_PLATFORM_DEFINE(gl_egl_platform, lr_canvas_egl_new, LR_BACKEND_EGL, 1)

/* Whether EGL works here, found once: a display, a context, and a pixel
 * drawn and read back through the GL lamina is linked with. */
int lr_canvas_egl_probe(char *err, size_t errlen)
{
    static int state;           /* 0: not tried; 1: works; -1: does not */
    static char why[512];
    if (state == 0) {
        char e[400] = "";
        lr_canvas *c = lr_canvas_egl_new(1, 1, e, sizeof e);
        unsigned char *px = NULL;
        if (c) {
            lr_canvas_clear(c, (lr_rgba){ 1, 0, 0, 1 });
            px = lr_canvas_read_rgba(c);
            if (!px || px[0] != 255 || px[1] != 0 || px[3] != 255)
                snprintf(e, sizeof e, "EGL's OpenGL context draws nothing "
                         "lamina can read back");
        }
        state = c && px && !e[0] ? 1 : -1;
        const char *prefix = "cannot create canvas: ";
        const char *msg = strncmp(e, prefix, strlen(prefix)) == 0 ? e + strlen(prefix) : e;
        if (state < 0)
            snprintf(why, sizeof why, "EGL cannot start: %s", msg);
        free(px);
        lr_canvas_free(c);      /* its context is kept for the next canvas */
    }
    if (state < 0 && err && errlen > 0)
        snprintf(err, errlen, "%s", why);
    return state > 0 ? 0 : -1;
}
