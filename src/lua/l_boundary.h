/* l_boundary.h - lamina.sim{boundary = ...}, read alike in 2D (l_sim.c,
 * the sides) and 3D (l_sim3.c, the faces). */
#ifndef LAMINA_L_BOUNDARY_H
#define LAMINA_L_BOUNDARY_H

#include <lua.h>

#include "mpm.h"

/* The boundary key of the table at 1: a condition for every one of names
 * (NULL-terminated, bc[] in their order) or a table of them by name; names
 * not given keep bc's value. `what` names them in the error ("sides",
 * "faces"); refuse, if not NULL, sees the table (at -1) first and raises
 * on a key it will not take. */
void la_read_boundary(lua_State *L, const char *fn, const char *const names[],
                      const char *what, void (*refuse)(lua_State *L, const char *fn),
                      lm_bc *bc);

#endif
