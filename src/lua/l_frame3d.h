/* l_frame3d.h - sim:frame{...} of a 3D simulation (docs/api.md "3D
 * frames", docs/3d.md "Frames"). Until lamina.sim{dim = 3} lands, the
 * binding that holds an lm3_sim calls this from its sim:frame:
 *
 *     if (s->sim3) return l_frame3d(L, s->sim3, 2);
 *
 * The options table is at opts_index; returns 1 (the file's path pushed)
 * or raises a Lua error naming the key and the value. */
#ifndef LAMINA_L_FRAME3D_H
#define LAMINA_L_FRAME3D_H

#include <lua.h>

#include "mpm3.h"

int l_frame3d(lua_State *L, const lm3_sim *sim, int opts_index);

#endif
