/* frame3d.h - a 3D run's frame (issue 34 item 4, docs/3d.md "Frames"):
 * panels of a box seen by a camera, each showing particles as shaded
 * spheres coloured by a field or by body, membranes as their points with
 * their normals as arrows thinned to the spacing, isosurfaces of a scalar
 * on a node grid (a membrane's phi = 1, see-through) and slices (a plane
 * through a node grid, e.g. the gas pressure, through a colour map), with
 * the figure language's titles, label and colour bars.
 *
 * Drawn through view3d.h's scene: OpenGL with a depth buffer through
 * OSMesa or EGL (particles splatted into it on the CPU, 10^6 in under
 * 150 ms: docs/performance.md), else cairo in painter's order (particles
 * and triangles sorted far to near). Deterministic per backend.
 *
 * Plain arrays in, nothing known about the engine (the Lua binding,
 * src/lua/l_frame3d.c, gathers them from an lm3_sim); errors are values
 * (0, or -1 with a one-line message in err[errlen]). */
#ifndef LAMINA_FRAME3D_H
#define LAMINA_FRAME3D_H

#include <stddef.h>

#include "figure.h"
#include "layers.h"
#include "render.h"

/* The camera: it looks at `target` from azimuth (degrees about z, from
 * +x) and elevation (degrees above the xy plane), `distance` away. */
typedef struct lr_camera3d {
    double azimuth, elevation;  /* as lamina.figure's 3D panels: -60, 25 */
    double distance;            /* world units; 0: the box fills the panel */
    double target[3];
    int has_target;             /* 0: the box's centre */
    double fov;                 /* degrees, in (0, 120): perspective;
                                   0: orthographic (the default). The
                                   picture shows 2 distance tan(fov / 2)
                                   across at the target (fov 30 for an
                                   orthographic camera's distance) */
} lr_camera3d;

/* Samples of a scalar at the nodes of a box grid, x fastest. */
typedef struct lr_grid3d {
    const double *f;            /* n[0] n[1] n[2] values; NaN: no value */
    int n[3];                   /* nodes per direction, >= 2 */
    double lo[3];               /* the first node */
    double h[3];                /* node spacing per direction, > 0 */
} lr_grid3d;

typedef struct lr_cloud3d {     /* particles as shaded spheres */
    size_t n;
    const double *x, *y, *z;
    const double *value;        /* non-NULL: colour by value through the
                                   panel's colour map */
    const int *group;           /* else the palette colour of group[i]
                                   (NULL: group 0) */
    double radius;              /* pixels, > 0 */
} lr_cloud3d;

typedef struct lr_membrane3d {  /* a membrane as its points */
    size_t n;
    const double *x, *y, *z;
    const double *nx, *ny, *nz; /* unit normals; NULL: none drawn */
    const double *value;        /* non-NULL: points coloured by value */
    lr_rgba colour;             /* else this colour */
    double radius;              /* pixels, > 0 */
    double spacing;             /* world distance between neighbouring
                                   points (for the arrows' thinning) */
    double arrow_px;            /* arrows at least this many pixels
                                   apart (and that long); 0: 16 */
    lr_rgba arrow_colour;
} lr_membrane3d;

typedef struct lr_iso3d {       /* the surface f = level, see-through */
    lr_grid3d grid;
    double level;
    lr_rgba colour;             /* alpha < 1 shows what is behind */
} lr_iso3d;

typedef struct lr_tris3d {      /* triangles made elsewhere, see-through
                                   when alpha < 1 (a membrane's phi = 1,
                                   contoured element by element) */
    size_t n;
    const double *xyz;          /* 9 n: the corners */
    const double *normals;      /* 9 n, a normal a corner; NULL: flat */
    lr_rgba colour;
} lr_tris3d;

typedef struct lr_slice3d {     /* the plane x_axis = at through a grid */
    lr_grid3d grid;
    int axis;                   /* 0 x, 1 y, 2 z */
    double at;                  /* world coordinate, inside the grid */
    lr_cmap cmap;
    double vmin, vmax;          /* vmax <= vmin: the slice's own range */
    int colourbar;              /* a colour bar of its own */
    const char *label;          /* its colour bar's label */
    double alpha;               /* 0 or 1: opaque; else see-through */
} lr_slice3d;

typedef struct lr_panel3d {
    double lo[3], hi[3];        /* the box shown; its outline when `box` */
    int box;
    lr_camera3d camera;
    const lr_cloud3d *clouds;
    size_t nclouds;
    const lr_membrane3d *membranes;
    size_t nmembranes;
    const lr_iso3d *isos;
    size_t nisos;
    const lr_tris3d *tris;
    size_t ntris;
    const lr_slice3d *slices;
    size_t nslices;
    const char *title;
    lr_cmap cmap;               /* the particles' values */
    double vmin, vmax;          /* vmax <= vmin: the data's (symmetric
                                   about 0 for a diverging map) */
    int colourbar;
    const char *colourbar_label;
} lr_panel3d;

typedef struct lr_figure3d {
    int width, height;
    lr_backend backend;
    const lr_panel3d *panels;
    size_t npanels;             /* at least 1 */
    int rows, cols;             /* 0, 0: one row */
    const char *title, *label;
    const lr_text_chunk *text;  /* into the PNG */
    size_t ntext;
} lr_figure3d;

/* The view of a panel's camera fitted into the pixel rectangle. */
void lr_camera3d_view(lr_view *v, const lr_camera3d *cam, double px, double py, double pw,
                      double ph, const double lo[3], const double hi[3]);

/* The value range the panel's particles are coloured over (and its colour
 * bar shows), never empty. */
void lr_panel3d_range(const lr_panel3d *p, double *lo, double *hi);

int lr_figure3d_draw(const lr_figure3d *f, lr_canvas *c, char *err, size_t errlen);
/* Straight RGBA8 through the figure's backend, malloc'd; NULL with err. */
unsigned char *lr_figure3d_render(const lr_figure3d *f, char *err, size_t errlen);
/* PNG, atomically; missing folders are created. */
int lr_figure3d_write(const lr_figure3d *f, const char *path, char *err, size_t errlen);

/* ---- isosurfaces (frame3d_iso.c) ---------------------------------------- */

/* The surface f = level by marching tetrahedra (each cell cut into six
 * tetrahedra about its main diagonal, so neighbouring cells share their
 * faces' cuts: the surface has no cracks); triangles as xyz[9 k + ...]
 * and a normal per vertex (the grid's gradient, central differences,
 * interpolated). Cells with a NaN node are left out. 0 with *xyz,
 * *normals malloc'd (NULL when no triangle), -1 on OOM. */
int lr_iso_triangles(const lr_grid3d *g, double level, double **xyz, double **normals,
                     size_t *ntri);

#endif
