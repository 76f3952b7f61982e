/* l_normals.h - shared by l_normals.c (lamina.normals) and
 * l_normals_figure.c (lamina.figure): the phi field a result carries, so a
 * figure can contour it without calling back into Lua. Private. */
#ifndef LAMINA_L_NORMALS_H
#define LAMINA_L_NORMALS_H

#include <lua.h>

#include "mpm_normals.h"

#define LA_NFIELD "lamina.nfield"
#define LA_FIGURE "lamina.figure"

/* The fits of one lamina.normals call: one element, or a grid's elements
 * with the cell -> element map. */
typedef struct la_nfield {
    int dim;
    int nfits;
    lm_nfit *fits;
    int grid;                   /* 1: cells below are in use */
    lm_ngrid g;
    int *cell_fit;              /* per cell: index into fits, or -1 */
    double lo[3], hi[3];        /* the box the result covers */
} la_nfield;

/* The field of a lamina.normals result (the table, or its phi_at
 * function) at stack index idx; NULL if it is neither. */
la_nfield *la_to_nfield(lua_State *L, int idx);
/* phi at x: the element holding x (grids), NaN where there is none. */
double la_nfield_phi(const la_nfield *f, const double x[3]);

int la_normals(lua_State *L);
int la_figure_new(lua_State *L);
void la_open_figure(lua_State *L);

#endif
