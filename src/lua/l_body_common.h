/* l_body_common.h - what sim:body and the body handle do alike in 2D
 * (l_body.c) and 3D (l_body3.c): sim:body's common arguments, calling the
 * script's region and velocity functions, and the handle (its index and
 * sim, name, index, __tostring, method lookup, class). What differs by
 * dimension - the engine's body, its sums, its particles' arrays - stays
 * in those files. */
#ifndef LAMINA_L_BODY_COMMON_H
#define LAMINA_L_BODY_COMMON_H

#include <stddef.h>

#include "l_internal.h"

/* sim:body's options at 2 checked against keys (name: text or nothing,
 * issue 31 item 7), refused during a run; then 'material' (required, a
 * material), whose stack index is returned, and 'region' pushed above
 * it (its index is the material's + 1). */
int la_body_args(lua_State *L, const la_sim *s, const char *fn, const char *const keys[]);

/* Calls the script's function at fidx with the dim coordinates x,
 * protected, for nres results: 0 with them on the stack, or -1 with the
 * error on it (the engine's callbacks return -1 and sim:body raises it). */
int la_body_call(lua_State *L, int fidx, const double *x, int dim, int nres);

/* A body handle of class meta (la_handle_push, l_handle.c): index bi of
 * the sim at sidx, and the name at nameidx (uservalue 2; 0: none); read
 * back with la_handle_check. */
void la_body_handle_push(lua_State *L, const char *meta, int sidx, int bi, int nameidx);
/* Both classes' __len (the body's particles) and __tostring ("lamina.body
 * N[ NAME] ([3D, ]n particles)"). */
int la_body_len(lua_State *L);
int la_body_tostring(lua_State *L);
/* __index's common keys of the handle at 1: name and index (1: pushed),
 * or a method of its class (1: pushed); 0: none of them (the caller says
 * what else its dimension has, or the error). */
int la_body_handle_field(lua_State *L, int bi, const char *k);
#endif
