/* l_pin_common.h - what body:pin does alike for a 2D body (l_pin.c) and a
 * 3D one (l_pin3.c): reading `points`, calling a velocity function,
 * driving the pins' functions before each step (the pin handle:
 * la_handle_push, l_handle.c). The
 * dimension-specific parts (the engine's pin, its reaction) stay in those
 * files. */
#ifndef LAMINA_L_PIN_COMMON_H
#define LAMINA_L_PIN_COMMON_H

#include <stddef.h>

#include "l_internal.h"

/* How one dimension reads `points` (docs/api.md body:pin): the words it
 * names in its messages, and its points' coordinates for a function. */
typedef struct la_pin_points {
    const char *fn;             /* "body:pin" */
    size_t count;               /* the body's points */
    size_t first;               /* added to every index chosen (3D: the
                                   body's range in the engine's arrays) */
    const char *choices;        /* the words: "\"all\", \"ends\"" (2D) or
                                   "\"all\"" (3D) */
    const char *args;           /* the function's arguments: "x, y" or "x, y, z" */
    const char *ends_refused;   /* why points = "ends" cannot be, after
                                   'points = "ends" ' (NULL: allowed) */
    const char *none_chosen;    /* the message when the function chose none */
    /* pushes point q's coordinates, returns how many */
    int (*push_point)(lua_State *L, void *ctx, size_t q);
    /* after each call (may be NULL): nonzero when the script's function
     * changed the body's range (2D: it may add a body, issue 31) */
    int (*moved)(void *ctx);
    void *ctx;
} la_pin_points;

/* The points of the table at idx (key `points`): "all", "ends" (the first
 * and last point), a list of 1-based indices, or a function of the
 * coordinates -> boolean, as indices + pp->first. The array is a userdata
 * left on the stack (freed by the collector when an error unwinds). */
size_t *la_pin_points_read(lua_State *L, int idx, const la_pin_points *pp, size_t *n);

/* Calls the velocity function at fidx with t: 1 with its n results in v
 * when all are finite numbers, else 0 (the caller names the fault). */
int la_pin_velocity_call(lua_State *L, int fidx, double t, int n, double *v);

/* Before each step: drive(L, s, pin, fidx) for each driven pin of the sim
 * at sidx, its function at fidx (the sim's uservalue holds them). */
void la_pins_drive(lua_State *L, int sidx, la_sim *s,
                   void (*drive)(lua_State *L, la_sim *s, int pin, int fidx));

#endif
