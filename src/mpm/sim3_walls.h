/* sim3_walls.h - the 3D grid's walls, private to the engine (sim3_walls.c). */
#ifndef LAMINA_SIM3_WALLS_H
#define LAMINA_SIM3_WALLS_H

#include "mpm3.h"

/* What a nodal field is, for its image across a wall: a scalar (mass) or
 * the component along axis 0, 1, 2. */
enum { LM3_SCALAR = -1 };

/* fixed: every component zero on the face's node plane; symmetry: the
 * normal one; free: nothing. Over the whole plane, ghost ring included. */
void lm3_grid_apply_bc(const lm3_grid *g, double *const u[3]);
/* The ghost ring's sums folded into their mirror nodes (after a scatter)
 * and the ghosts filled from them (before a gather). comp[c] is
 * LM3_SCALAR or the axis of field c. No-ops with the trilinear basis. */
void lm3_grid_fold(const lm3_grid *g, int nf, double *const *f, const int *comp);
void lm3_grid_fill(const lm3_grid *g, int nf, double *const *f, const int *comp);

#endif
