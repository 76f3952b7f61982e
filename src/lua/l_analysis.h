/* l_analysis.h - lamina.analysis (issue 35 item 3): what users wrote by hand
 * in Lua to read a run's numbers, done once and tested against exact
 * answers: a series' period and frequency (l_analysis_period.c), a
 * least-squares circle fit (l_analysis.c), a membrane's crossing with a
 * line and the gas on each side of it (l_analysis_membrane.c). */
#ifndef LAMINA_L_ANALYSIS_H
#define LAMINA_L_ANALYSIS_H

#include <stddef.h>

#include "l_internal.h"

/* The array of numbers at idx (a Lua sequence, e.g. rec:column's) as a
 * scratch copy that lives on the Lua stack (collected with it, so an error
 * leaks nothing); *n its length. Errors name fn, what and the index. */
double *la_analysis_array(lua_State *L, int idx, const char *fn, const char *what,
                          size_t *n);
/* A scratch block of n doubles pushed on the stack (as above). */
double *la_analysis_scratch(lua_State *L, size_t n);

int la_analysis_period(lua_State *L);
int la_analysis_frequency(lua_State *L);
int la_analysis_crossing(lua_State *L);
int la_analysis_gas_sides(lua_State *L);

/* Sets lamina.analysis in the table on top of the stack. */
void la_open_analysis(lua_State *L);

#endif
