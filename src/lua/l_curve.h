/* l_curve.h - curves for sim:membrane (internal to the bindings). */
#ifndef LAMINA_L_CURVE_H
#define LAMINA_L_CURVE_H

#include "l_internal.h"

typedef enum la_curve_kind { LA_CURVE_POLYLINE, LA_CURVE_ARC } la_curve_kind;

typedef struct la_curve {
    la_curve_kind kind;
    int n;                  /* polyline vertices */
    double *xy;             /* x0, y0, x1, y1, ... */
    double cx, cy, r, a0, a1;   /* arc, degrees */
} la_curve;

/* A curve made ready for placing points: its length and whether it closes. */
typedef struct la_curve_points {
    const double *xy;       /* dense polyline (segments, polylines, functions) */
    int m;
    const la_curve *arc;    /* or an exact arc */
    double length;
    int closed;
} la_curve_points;

la_curve *la_test_curve(lua_State *L, int idx);
/* The curve at idx (a curve or a function; a function's samples are pushed
 * as a userdata that must stay on the stack). -1 if it is not a curve. */
int la_curve_sample(lua_State *L, int idx, la_curve_points *out);
void la_curve_place(const la_curve_points *cp, int n, double *px, double *py);
void la_open_curve(lua_State *L);
/* Adds segment, arc, polyline to the table on top of the stack. */
void la_register_curves(lua_State *L);

#endif
