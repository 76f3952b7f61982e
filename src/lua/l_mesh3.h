/* l_mesh3.h - lamina.mesh{file, scale, translate}: a triangle mesh read
 * from an OBJ or STL file (src/mpm/mesh3.c) as a 3D region (closed meshes:
 * sim:body{region = mesh}) and as a membrane surface (sim:membrane{surface
 * = mesh}); docs/api.md "Three dimensions", docs/3d.md "Triangle meshes". */
#ifndef LAMINA_L_MESH3_H
#define LAMINA_L_MESH3_H

#include "l_internal.h"
#include "mesh3.h"
#include "mpm3_membrane.h"

#define LA_MESH3 "lamina.mesh3"

/* The Lua layer's bounds on a mesh file (docs/security.md "Inputs"): its
 * size, and the triangles it may hold (the reader's own bounds, mesh3.h,
 * are wider). */
#define LA_MESH_MAX_BYTES ((size_t)64 << 20)
#define LA_MESH_MAX_TRIANGLES ((size_t)1 << 22)

typedef struct la_mesh3 {
    lm3_mesh m;
    lm3_mesh_ray ray;           /* the inside test, built when first used as a region */
    int ray_built;
    int closed;                 /* every edge in two triangles, once each way */
    char why[320];              /* why not, naming an edge */
    char name[200];             /* the file as the script gave it, for messages */
    double lo[3], hi[3];        /* bounding box */
    size_t charged;             /* bytes charged to the process budget */
} la_mesh3;

int la_mesh(lua_State *L);                   /* lamina.mesh{...} */
void la_open_mesh3(lua_State *L);
la_mesh3 *la_test_mesh3(lua_State *L, int idx);
/* As a region: the inside test (a Lua error naming the file and the edge
 * when the mesh is open). */
lm3_mesh_ray *la_mesh3_region(lua_State *L, la_mesh3 *m, const char *fn);
/* As a membrane surface at `spacing`: the points it will make (0 with err
 * when too many), and the sample (0, or -1 with err naming the file and the
 * triangle or vertex as the file numbers them) with, when rim is not NULL,
 * *rim (malloc'd, a flag a point) marking the points on the rim of an open
 * mesh (pin = "edges"). */
size_t la_mesh3_points(const la_mesh3 *m, double spacing, char *err, size_t errlen);
int la_mesh3_sample(const la_mesh3 *m, double spacing, lm3_msample *s, uint8_t **rim,
                    char *err, size_t errlen);

#endif
