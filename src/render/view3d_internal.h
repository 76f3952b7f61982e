/* view3d_internal.h - the items of an lr_scene3d, shared by view3d.c (the
 * scene, cairo's painter) and canvas_gl_view3d.c (OpenGL). Private to
 * src/render. */
#ifndef LAMINA_VIEW3D_INTERNAL_H
#define LAMINA_VIEW3D_INTERNAL_H

#include "view3d.h"

typedef enum s3_kind {
    S3_LINE,            /* a .. b */
    S3_POLYLINE,        /* pts[first .. first + count) */
    S3_ARROW,           /* from a along unit b, `length` long */
    S3_CIRCLE,          /* a point at a: open circle / sphere */
    S3_DOT,             /* a point at a: disc / filled sphere */
    S3_ASTERISK,        /* at a, `size` px across */
    S3_BOX,             /* lo = a, hi = b */
    S3_TEXT             /* at a + (dx, dy) px */
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
    size_t first, count;        /* polylines: points 3 * first ... */
    char *text;                 /* text items: owned */
} s3_item;

struct lr_scene3d {
    s3_item *items;
    size_t n, cap;
    double *pts;                /* polyline points, x y z each */
    size_t npts, cappts;
    int layers;                 /* add calls so far */
};

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
