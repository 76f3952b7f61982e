/* mesh3.h - triangle meshes from files, for 3D regions and membrane
 * surfaces (issue 34 items 1 and 2: `lamina.mesh{file}`; docs/3d.md
 * "Triangle meshes").
 *
 * Formats: Wavefront OBJ (`v x y z`, `f a b c ...` with `a/b/c`, `a//c`
 * and negative indices; polygons split into fans; vt, vn, vp, o, g, s,
 * usemtl, mtllib and comments ignored, any other statement refused), STL
 * in ASCII (`solid` ... `endsolid`) and binary (80-byte header, a
 * little-endian triangle count, 50 bytes a triangle; the file's size must
 * be exactly 84 + 50 n). STL repeats each vertex in every triangle; the
 * reader merges exactly equal coordinates, so a closed STL solid is closed
 * here too.
 *
 * Every allocation is bounded: files above LM3_MESH_MAX_BYTES, more than
 * LM3_MESH_MAX_VERTICES vertices or LM3_MESH_MAX_TRIANGLES triangles are
 * refused before they are read. A malformed file is refused with a
 * message naming the file, the line (OBJ, ASCII STL) or the triangle
 * (binary STL) and what is wrong; nothing is returned then. */
#ifndef LAMINA_MESH3_H
#define LAMINA_MESH3_H

#include <stddef.h>
#include <stdint.h>

#define LM3_MESH_MAX_BYTES ((size_t)1 << 30)
#define LM3_MESH_MAX_VERTICES ((size_t)1 << 24)
#define LM3_MESH_MAX_TRIANGLES ((size_t)1 << 25)

typedef struct lm3_mesh {
    size_t nv, nt;
    double *xyz;           /* 3 nv coordinates */
    int32_t *tri;          /* 3 nt vertex indices from 0, in the file's winding */
} lm3_mesh;

/* Reads path (the format from its contents: binary STL by its size, ASCII
 * STL by "solid" followed by "facet", else OBJ). 0, or -1 with err. */
int lm3_mesh_read(const char *path, lm3_mesh *m, char *err, size_t errlen);
/* The same from a buffer; name is what the messages call it. */
int lm3_mesh_parse(const char *name, const char *buf, size_t len, lm3_mesh *m, char *err,
                   size_t errlen);
void lm3_mesh_free(lm3_mesh *m);

/* A closed, consistently wound mesh: every edge in exactly two triangles,
 * once in each direction. 1, or 0 with err naming an edge that is not
 * (and how many triangles hold it): what refuses an open mesh as a
 * region. -1 out of memory. */
int lm3_mesh_closed(const char *name, const lm3_mesh *m, char *err, size_t errlen);
/* Six times the signed volume (positive when the triangles wind
 * counter-clockwise seen from outside) and the area. */
double lm3_mesh_volume6(const lm3_mesh *m);
double lm3_mesh_area(const lm3_mesh *m);
/* Whether x is inside a closed mesh: the winding number, the sum of the
 * triangles' solid angles seen from x over 4 pi (van Oosterom & Strackee
 * 1983), is +-1 inside and 0 outside whichever way the mesh winds; x is
 * inside when its magnitude is above 1/2. O(triangles) a call. */
int lm3_mesh_inside(const lm3_mesh *m, const double x[3]);

/* ---- the inside test of many points (mesh3_inside.c) -------------------- */

/* The winding number along rays in +x: the triangles over a point's
 * (y, z), found through buckets of their (y, z) bounding boxes, each
 * crossing to the point's left counted with the sign of the triangle's
 * normal along x. A point on an edge or a vertex in (y, z) is given to
 * exactly one of the triangles there by a rule on the edge's direction
 * (the top-left rule of rasterisers), with every edge function computed
 * from its two vertices in one order whichever triangle asks, so the
 * count is the winding number for every ray, also one through an edge.
 * The crossings of the last ray are kept: a body's candidate points come
 * row by row along x, so a row costs one ray. Inside: a non-zero winding
 * number (either winding). Equal to lm3_mesh_inside away from the surface
 * (test_mesh3.c), and O(triangles in a bucket + log) a point. */
typedef struct lm3_mesh_ray {
    const lm3_mesh *m;
    double lo[2], cell[2];
    int n[2];
    size_t *start;         /* n[0] n[1] + 1 bucket starts */
    int32_t *tris;         /* the triangles of each bucket */
    int valid;             /* the cache holds the row (cy, cz) */
    double cy, cz;
    double *xs;            /* its crossings (x, sign) in pairs, sorted by x */
    size_t nx, capx;
} lm3_mesh_ray;

/* 0, or -1 with err (out of memory). The mesh must outlive r. */
int lm3_mesh_ray_build(const lm3_mesh *m, lm3_mesh_ray *r, char *err, size_t errlen);
/* 1 inside, 0 outside, -1 out of memory. */
int lm3_mesh_ray_inside(lm3_mesh_ray *r, const double x[3]);
void lm3_mesh_ray_free(lm3_mesh_ray *r);

/* ---- refining a mesh to a spacing (mesh3_refine.c) ---------------------- */

/* Every triangle cut into k^2 by the lines at 1/k of its sides, k =
 * ceil(longest edge / spacing) for the whole mesh, so that neighbours
 * share the points on their common edge (made once, from the edge's lower
 * vertex) and the result is as closed as the input: the surface a 3D
 * membrane samples (lamina.mesh as a surface). The counts first
 * (lm3_mesh_refine_counts: -1 with err when above max_vertices), then the
 * mesh. 0, or -1 with err. */
int lm3_mesh_refine_counts(const lm3_mesh *in, double spacing, size_t max_vertices, int *k,
                           size_t *nv, size_t *nt, char *err, size_t errlen);
int lm3_mesh_refine(const lm3_mesh *in, double spacing, size_t max_vertices, lm3_mesh *out,
                    char *err, size_t errlen);
/* The rim of an open mesh: rim[v] = 1 for every vertex on an edge that
 * only one triangle holds (a sheet's outline), else 0. The count of rim
 * vertices, or -1 out of memory. */
long lm3_mesh_rim(const lm3_mesh *m, uint8_t *rim);

#endif
