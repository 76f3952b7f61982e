/* l_region_common.h - what the 2D regions (l_region.c: disk, rect,
 * polygon) and the 3D ones (l_region3.c: ball, box, cylinder) make alike. */
#ifndef LAMINA_L_REGION_COMMON_H
#define LAMINA_L_REGION_COMMON_H

#include <lua.h>
#include <stddef.h>

/* A new region userdata of size bytes, zeroed (no bounding box, no
 * vertices yet), with the class's metatable meta (LA_REGION, LA_REGION3);
 * left on the stack. */
void *la_region_new(lua_State *L, size_t size, const char *meta);

#endif
