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

#endif
