/* canvas_gl.h - the GL canvas backends' parts (private).
 *
 * Two backends draw with the same OpenGL code: OSMesa (canvas_osmesa.c)
 * and EGL on the surfaceless platform (canvas_egl.c). They differ only in
 * how a context is made and where its pixels go, which a gl_platform
 * describes; canvas_gl.c holds the lr_canvas calls they share (clear,
 * clip, read-back) and the handing on of a context from one canvas to the
 * next; the drawing (canvas_gl_*.c) sees only a current context drawing
 * into the canvas's framebuffer (c->fbo: 0 under OSMesa, whose default
 * framebuffer is the canvas's buffer; an RGBA8 + stencil framebuffer
 * object under EGL, which has no surface).
 *
 * One context at a time per canvas; the context (with its compiled
 * shaders) passes on to the next canvas of the same backend. Colours are
 * premultiplied in GL (blend ONE,
 * ONE_MINUS_SRC_ALPHA), as in cairo's image surfaces, and straightened on
 * read-back, so a translucent clear colour or particle composites the way
 * it does through cairo.
 *
 * Antialiasing of lines and discs is computed, not sampled: the fragment
 * shader knows the pixel centre's offset from the shape (interpolated along
 * with the vertices, or from gl_FragCoord) and turns it into the pixel's
 * coverage. Fills sample the winding number 16 times a pixel
 * (canvas_gl_fill.c); text is cairo's coverage (canvas_gl_text.c).
 * Small shapes are batched: consecutive lines share one draw call,
 * consecutive discs of one radius another; a call of another kind, a clip,
 * a fill, text or a read flushes the batch first, so drawing order is
 * kept. Long dense runs of discs of about a pixel's radius are gathered
 * into rectangles instead of drawn as points (canvas_gl_dense.c). */
#ifndef LAMINA_CANVAS_GL_H
#define LAMINA_CANVAS_GL_H

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <math.h>
#include <stdint.h>

#include "canvas_backend.h"

/* A colour channel in 8 bits, as GL normalises it back. */
static inline unsigned char gl_to8(double v)
{
    return v <= 0 ? 0 : v >= 1 ? 255 : (unsigned char)lround(v * 255.0);
}

/* Shape vertex: x, y (pixels), e (across, along, half width, length, in
 * pixels), m (dash length, mode), straight RGBA. */
#define LRGL_VERT_FLOATS 12

enum lrgl_mode {
    LRGL_STROKE = 0,     /* a line: box-filtered across and along, dashes */
    LRGL_FRINGE = 1,     /* a fill's outside edge: 0.5 - |distance| */
    LRGL_SOLID = 2,      /* full coverage (fill cover, stencil passes) */
    LRGL_DISC = 3        /* a large disc: the pixel's area inside it */
};

enum lrgl_batch { LRGL_BATCH_NONE = 0, LRGL_BATCH_SHAPES, LRGL_BATCH_POINTS };

/* What outlives a canvas: the context with its compiled programs (llvmpipe
 * compiles shaders to machine code per context, which costs more than a
 * small frame), kept for the next canvas by canvas_gl.c. */
typedef struct gl_engine {
    void *ctx;                  /* the platform's context (OSMesaContext, EGLContext) */
    /* programs and their uniform locations */
    GLuint shape_prog, point_prog, text_prog;
    GLint shape_vp, point_vp, point_r, point_h, point_dot, text_vp, text_col,
          text_tex;
    GLuint text_texture;
    /* fills: an off-screen coverage buffer (canvas_gl_fill.c) */
    GLuint fill_fbo, fill_tex, fill_stencil;
    int fill_w, fill_h;
    /* 3D views (canvas_gl_view3d.c): compiled at the first one */
    GLuint view3d_prog;
    GLint view3d_size;
    /* gathered discs (canvas_gl_dense.c): compiled at the first run */
    int dense_state;            /* 0: not tried; 1: ready; -1: no GLSL 1.30 */
    GLuint dense_prog, dense_tex[2];    /* the cells, the coverage table */
    int dense_tw, dense_th;     /* the cells' texture size */
    GLint dense_vp, dense_h, dense_rgb, dense_org, dense_max;
    double dense_r, dense_a;    /* what the table is for */
    uint16_t *dense_cells;      /* a layer's cells, zero between layers */
    size_t dense_cap;
    uint32_t *dense_more, *dense_list;  /* discs for the next layer */
    size_t dense_morecap, dense_listcap;
    /* the last canvas's point arrays (gl_canvas.pxy, prgba) and read-back
     * buffer, for the next: a frame's worth of memory stays allocated */
    float *kept_pxy;
    unsigned char *kept_prgba;
    size_t kept_cap;
    unsigned char *readback;
    size_t readcap;
} gl_engine;

typedef struct gl_platform gl_platform;

typedef struct gl_canvas {
    lr_canvas base;
    const gl_platform *plat;
    gl_engine gl;
    unsigned char *buf;         /* OSMesa's colour buffer, rows bottom-up */
    GLuint fbo, rb[2];          /* EGL's framebuffer: colour, depth-stencil */
    int pad;                    /* viewport overhang (canvas_gl.c) */
    int failed;                 /* a GL error or OOM: read_rgba gives NULL */
    /* the pending batch */
    enum lrgl_batch batch;
    float *verts;               /* shapes: LRGL_VERT_FLOATS per vertex */
    size_t nverts, capverts;
    float *pxy;                 /* points: x, y */
    unsigned char *prgba;       /* points: straight RGBA8 */
    size_t npoints, cappoints;
    double point_r;             /* the radius of the pending points */
} gl_canvas;

static inline gl_canvas *glc(lr_canvas *c) { return (gl_canvas *)c; }

/* How one way of getting a GL context works (canvas_osmesa.c,
 * canvas_egl.c). Messages go to err without a prefix. */
struct gl_platform {
    lr_backend backend;
    int slot;                   /* which spare context is its own: 0, 1 */
    /* A new context in e->ctx, not current yet. */
    int (*create)(gl_engine *e, char *err, size_t errlen);
    /* Makes c's context current drawing into a new target of c's size (a
     * buffer or a framebuffer object); checks the size against the
     * implementation's limits. */
    int (*target_new)(gl_canvas *c, char *err, size_t errlen);
    /* Makes c's context current with its target (once target_new worked). */
    void (*use)(gl_canvas *c);
    /* Frees c's target (c's context is current). */
    void (*target_free)(gl_canvas *c);
    /* Makes no context of this platform current. */
    void (*release)(void);
    void (*destroy)(gl_engine *e);
};

/* Defines a platform's table `var` from the hooks its file names create,
 * target_new, use, target_free, release and destroy (static there), and
 * its public constructor `ctor` (width, height, err, errlen) -> a canvas
 * of it: the one set-up of canvas_osmesa.c and canvas_egl.c. */
#define GL_PLATFORM_DEFINE(var, ctor, backend_, slot_)                          \
    const gl_platform var = {                                                   \
        .backend = (backend_), .slot = (slot_), .create = create,              \
        .target_new = target_new, .use = use, .target_free = target_free,      \
        .release = release, .destroy = destroy,                                \
    };                                                                          \
    lr_canvas *ctor(int width, int height, char *err, size_t errlen)           \
    {                                                                           \
        return gl_canvas_new_charged(&var, width, height, err, errlen);         \
    }

/* canvas_gl.c */
/* A canvas of platform p; NULL with "cannot create canvas: ..." in err. */
lr_canvas *gl_canvas_new(const gl_platform *p, int width, int height, char *err,
                         size_t errlen);
/* gl_canvas_new with its pixels counted against the memory cap
 * (lr_canvas_charge, canvas.c), released again if it fails. */
lr_canvas *gl_canvas_new_charged(const gl_platform *p, int width, int height, char *err,
                                 size_t errlen);
/* Makes c's context current (one per thread at a time; cheap when it
 * already is). */
void gl_use(gl_canvas *c);

/* canvas_gl_shaders.c */
int gl_programs_init(gl_engine *e, char *err, size_t errlen);
/* Compiles and links a program with the attributes at fixed locations; 0
 * with a message on failure. */
GLuint gl_link(const char *vs, const char *fs, const char *const *attribs,
               const GLuint *locs, int nattribs, char *err, size_t errlen);
void gl_programs_free(gl_engine *e);
/* Points the programs at c's size (its viewport and pad). */
void gl_programs_viewport(gl_canvas *c);
/* Draws and empties the pending batch. */
void gl_flush(gl_canvas *c);
/* Room for n more shape vertices in the batch (flushing another kind
 * first); NULL on OOM (c->failed is set). */
float *gl_shape_verts(gl_canvas *c, size_t n);
/* Makes the batch one of points of radius r (flushing another kind or
 * radius, or a full one) with room for 1 .. n more; -1 on OOM (c->failed
 * is set). The caller appends at c->npoints. */
int gl_points_room(gl_canvas *c, double r, size_t n);
/* A batch of points is drawn when it gets this big, to bound its memory. */
#define BATCH_MAX_POINTS (1u << 22)
/* Draws n shape vertices at once as triangles, without batching (for the
 * stencil passes of fills). */
void gl_draw_triangles(gl_canvas *c, const float *v, size_t n);
/* One vertex of a shape. */
void gl_vert(float *v, double x, double y, double across, double along,
             double hw, double len, double dash, enum lrgl_mode mode, lr_rgba k);

/* Draws points first .. first + count of the pending batch as points. */
void gl_draw_points(gl_canvas *c, size_t first, size_t count);
/* Draws the pending batch's points listed (n indices) as points. */
void gl_draw_point_list(gl_canvas *c, const uint32_t *list, size_t n);

/* canvas_gl_dense.c */
/* Draws the pending points if they are discs it gathers (then 1; short
 * runs among them as points, in order), else 0 and draws nothing. */
int gl_dense_flush(gl_canvas *c);
/* Frees the engine's CPU-side buffers (its GL objects go with the
 * context). */
void gl_dense_release(gl_engine *e);

/* canvas_gl_draw.c */
/* A line from a to b (pixels) of half width hw as two triangles. */
void gl_line_quad(gl_canvas *c, double ax, double ay, double bx, double by,
                  double hw, double dash, enum lrgl_mode mode, lr_rgba k);
void gl_line(lr_canvas *c, double x0, double y0, double x1, double y1,
             double width, lr_rgba colour, double dash);
void gl_discs(lr_canvas *c, size_t n, const double *px, const double *py,
              double r, const lr_rgba *colours);

/* canvas_gl_fill.c */
void gl_fill(lr_canvas *c, size_t npoly, const size_t *counts,
             const double *xy, lr_rgba colour);
void gl_rect(lr_canvas *c, double x, double y, double w, double h,
             double line_width, lr_rgba stroke);
void gl_fill_free(gl_engine *e);

/* canvas_gl_text.c */
/* Blends colour through the coverage in the alpha of texels 0..w-1,
 * 0..h-1 of texture tex (tw x th) onto canvas pixels x .. x+w, y .. y+h;
 * flip: the texture's rows run bottom-up (rendered by GL). */
void gl_blend_coverage(gl_canvas *c, GLuint tex, double x, double y, int w,
                       int h, int tw, int th, int flip, lr_rgba colour);

/* canvas_gl_text.c */
void gl_text(lr_canvas *c, double x, double y, double size, lr_rgba colour,
             lr_align align, const char *text);

/* canvas_osmesa.c, canvas_egl.c (when built) */
extern const gl_platform gl_osmesa_platform;
extern const gl_platform gl_egl_platform;
/* canvas_egl.c: lets go of the EGL display (after its contexts). */
void gl_egl_terminate(void);
/* Unbinds the display at shutdown without terminating it (canvas_egl.c). */
void gl_egl_park(void);

#endif
