/* view3d_internal.h - the items of an lr_scene3d, shared by view3d.c (the
 * scene, cairo's painter) and canvas_gl_view3d.c (OpenGL). Private to
 * src/render. */
#ifndef LAMINA_VIEW3D_INTERNAL_H
#define LAMINA_VIEW3D_INTERNAL_H

#include <math.h>
#include <stdint.h>

#include "view3d.h"

typedef enum s3_kind {
    S3_LINE,            /* a .. b */
    S3_POLYLINE,        /* pts[first .. first + count) */
    S3_ARROW,           /* from a along unit b, `length` long */
    S3_CIRCLE,          /* a point at a: open circle / sphere */
    S3_DOT,             /* a point at a: disc / filled sphere */
    S3_ASTERISK,        /* at a, `size` px across */
    S3_BOX,             /* lo = a, hi = b */
    S3_TEXT,            /* at a + (dx, dy) px */
    S3_CLOUD,           /* cloud points [first, first + count), spheres of
                           `size` px, each its own colour (view3d_cloud.c) */
    S3_TRIS             /* triangle vertices [first, first + count) */
} s3_kind;

typedef struct s3_item {
    s3_kind kind;
    int layer;                  /* the add call it came from, 0, 1, ... */
    double a[3], b[3];
    double length;              /* arrows: world units */
    double width;               /* line width, px */
    double size;                /* point radius or asterisk size, px */
    double head;                /* arrow head, px */
    double dash;                /* 0 solid, else the dash length, px */
    double dx, dy;              /* text offset, px */
    lr_rgba colour;
    lr_align align;
    size_t first, count;        /* polylines: points 3 * first ...; clouds:
                                   points; triangles: vertices */
    int lit;                    /* triangles: shaded by their normals */
    int see_through;            /* triangles: some vertex has alpha < 1 */
    char *text;                 /* text items: owned */
} s3_item;

struct lr_scene3d {
    s3_item *items;
    size_t n, cap;
    double *pts;                /* polyline points, x y z each */
    size_t npts, cappts;
    int layers;                 /* add calls so far */
    float *cloud;               /* cloud points, x y z each */
    uint32_t *cloud_rgba;       /* their straight RGBA8, r in the low byte */
    size_t ncloud, capcloud, caprgba;
    float *tri;                 /* triangle vertices, S3_TRI_FLOATS each */
    size_t ntri, captri;
};

/* A triangle vertex: x y z, its normal (zero: none), straight r g b a. */
#define S3_TRI_FLOATS 10

/* The lighting of canvas_gl_view3d.c's shader, for the CPU paths (cloud
 * splats, cairo's triangles): a fixed light from the upper left and in
 * front, a little specular; n a unit normal in view space (x right, y up,
 * z towards the viewer). */
static inline void s3_shade(const float base[3], const double n[3], float out[3])
{
    static const double L[3] = {-0.39801, 0.59702, 0.69653};
    static const double Hh[3] = {-0.21607, 0.32411, 0.92101};
    double d = n[0] * L[0] + n[1] * L[1] + n[2] * L[2];
    double h = n[0] * Hh[0] + n[1] * Hh[1] + n[2] * Hh[2];
    d = d > 0 ? d : 0;
    h = h > 0 ? h : 0;
    double spec = 0.3 * pow(h, 40.0);
    for (int k = 0; k < 3; k++) {
        double c = base[k] * (0.45 + 0.55 * d) + spec;
        out[k] = (float)(c < 1 ? c : 1);
    }
}

/* view3d_cloud.c: the clouds of s splatted on the CPU into a W x H sample
 * buffer (rows bottom-up, as OpenGL's), premultiplied RGBA8 and window
 * depth in [0, 1] (1: nothing): each point a sphere of its radius times S
 * samples, shaded as the shader shades spheres, nearest wins. A view
 * pixel (x, y) is sample ((x - x0) S, (y - y0) S); depth is the GL path's
 * (canvas_gl_view3d.c: NDC -zscale (toward . (q - c)) - eps layer).
 * 0, or -1 when memory runs out. */
int s3_cloud_raster(const lr_view *v, const lr_scene3d *s, double x0, double y0, double S,
                    double zscale, double eps, int W, int H, unsigned char *rgba,
                    float *depth);
/* The samples the clouds cover at S samples a pixel (for choosing S). */
double s3_cloud_samples(const lr_scene3d *s, double S);
/* view3d_sort.c, cairo: every cloud point and triangle of s, far ones
 * first (painter's sort). 0, or -1 when memory runs out. */
int s3_sorted_painter(lr_canvas *c, const lr_view *v, const lr_scene3d *s);

#define S3_HEAD_ANGLE 0.4363323129985824   /* 25 degrees, as layer_glyphs.c */

/* 3D: does the face of the box with outward normal +-e_axis face us? An
 * edge is hidden (drawn dashed) when neither face meeting there does. */
static inline int s3_facing(const lr_view *v, int axis, int high)
{
    double t = v->toward[axis];
    return high ? t > 0 : t < 0;
}

#ifdef LAMINA_HAVE_GL
/* canvas_gl_view3d.c: the geometry of s through OpenGL with depth,
 * composited onto the GL canvas c (text items are left to the caller). */
int gl_view3d(lr_canvas *c, const lr_view *v, const lr_scene3d *s, char *err,
              size_t errlen);
#endif

#endif
