/* edge_order.h - the order of undirected mesh edges by their vertices, the
 * lower first, which a closed-mesh check sorts by so that the two
 * triangles sharing an edge sit side by side: the mesh reader's check
 * (mesh3.c, lm3_mesh_closed) and the membrane surface's
 * (sim3_membrane_surface.c). */
#ifndef LAMINA_EDGE_ORDER_H
#define LAMINA_EDGE_ORDER_H

#include <stdint.h>

/* <0, 0, >0 as the edge a0-b0 comes before, with, after a1-b1 */
static inline int lm_edge_order(int32_t a0, int32_t b0, int32_t a1, int32_t b1)
{
    int32_t lo0 = a0 < b0 ? a0 : b0, hi0 = a0 < b0 ? b0 : a0;
    int32_t lo1 = a1 < b1 ? a1 : b1, hi1 = a1 < b1 ? b1 : a1;
    if (lo0 != lo1) return lo0 < lo1 ? -1 : 1;
    if (hi0 != hi1) return hi0 < hi1 ? -1 : 1;
    return 0;
}

#endif
