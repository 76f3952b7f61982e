/* l_leak_watch.c - a run whose gas crosses a membrane says so (issue 30
 * item 5).
 *
 * The grid moves gas and membrane with one velocity field, so in the limit
 * no gas crosses; but the membrane is a row of points, and the gas between
 * two of them moves with the grid, not with the chord: a soft balloon
 * (tests/physics/gas_leak_warning.lua: p 3, E t 20, dropped 0.25 onto the
 * floor, 4 particles a cell) keeps its gas with its points half a cell
 * apart, but with them a cell apart (what docs/api.md suggested for a taut
 * sheet) lets gas through from t = 0.84, 1.01 cells deep by t = 2 (3.3
 * cells with 16 particles a cell; docs/robustness.md has the table). A gas particle more than a quarter cell
 * on the wrong side of a closed membrane is such a leak (a skin-grazer,
 * 0.02 cells out, is not: the last row of gas stands half a spacing from
 * the points and the chords cut corners); the first one seen is said once
 * a script, naming both bodies, the time and the depth.
 *
 * Which side is the gas's: judged the first time the pair is seen, at the
 * start of a run: every particle inside (or within a quarter cell outside)
 * - the gas is the membrane's; every particle outside - the gas is around
 * it; both - a gas on both sides by design, not watched. Open membranes
 * (quarter models) enclose nothing by themselves and are not watched.
 * Cost: a side test per gas particle over the edges spanning its row of
 * cells, a distance only for the particles on the far side
 * (lm_gas_far_side), every LA_LEAK_EVERY steps (and before a run's first
 * step when a body is new):
 * +3 % run time on the soft balloon (1.20 s of user time against 1.15 s
 * unchecked; 484 gas points, 76 membrane points; checked every step:
 * +28 %). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "l_internal.h"

enum { SIDE_UNKNOWN = 0, SIDE_INSIDE = 1, SIDE_OUTSIDE = 2, SIDE_NONE = 3 };

static signed char *sides(la_sim *s)
{
    int nb = s->sim->nbodies;
    if (nb > s->leak_nb) {
        signed char *t = calloc((size_t)nb * nb, 1);
        if (!t) return NULL;
        for (int g = 0; g < s->leak_nb; g++)
            for (int m = 0; m < s->leak_nb; m++) t[g * nb + m] = s->leak_side[g * s->leak_nb + m];
        free(s->leak_side);
        s->leak_side = t;
        s->leak_nb = nb;
    }
    return s->leak_side;
}

/* The side the gas keeps, from its particles now. */
static int judge(const lm_sim *sim, int g, int m, double quarter)
{
    lm_far far;
    if (lm_gas_far_side(sim, g, m, 0, 0, 0, quarter, &far)) return SIDE_NONE;
    if (far.beyond == 0) return SIDE_INSIDE;
    if (far.near == 0 && lm_gas_far_side(sim, g, m, 0, 0, 1, quarter, &far) == 0 &&
        far.beyond == 0)
        return SIDE_OUTSIDE;
    return SIDE_NONE;
}

void la_leak_watch(lua_State *L, la_sim *s)
{
    const lm_sim *sim = s->sim;
    if (s->warned_leak) return;
    if (sim->nbodies <= s->leak_nb && sim->step - s->leak_step < LA_LEAK_EVERY) return;
    s->leak_step = sim->step;
    signed char *side = sides(s);
    if (!side) return;
    int nb = s->leak_nb;
    double h = fmin(sim->grid.hx, sim->grid.hy), quarter = 0.25 * h;
    for (int g = 0; g < sim->nbodies; g++) {
        if (sim->mats[sim->bodies[g].mat]->kind != LM_GAS || sim->bodies[g].count == 0) continue;
        for (int m = 0; m < sim->nbodies; m++) {
            const lm_body *mb = &sim->bodies[m];
            if (!mb->membrane || !mb->closed || mb->count < 3) continue;
            signed char *sd = &side[g * nb + m];
            if (*sd == SIDE_UNKNOWN) *sd = (signed char)judge(sim, g, m, quarter);
            if (*sd == SIDE_NONE) continue;
            lm_far far;
            if (lm_gas_far_side(sim, g, m, 0, 0, *sd == SIDE_OUTSIDE, quarter, &far) ||
                far.beyond == 0)
                continue;
            s->warned_leak = 1;
            char gas[96], mem[96], line[768];
            snprintf(line, sizeof line,
                     "lamina: warning: at t = %.6g (step %ld): %zu particles of %s are %s %s by "
                     "more than a quarter cell, the deepest %.3g cells (%.6g) - the gas leaks "
                     "through it (%zu more within a quarter cell); space the membrane's points "
                     "closer (at most about 0.75 cells apart at their loaded length), or refine "
                     "(docs/robustness.md, \"Gas through a membrane\")\n",
                     sim->t, sim->step, far.beyond, lm_body_label(sim, g, gas, sizeof gas),
                     *sd == SIDE_OUTSIDE ? "inside" : "outside",
                     lm_body_label(sim, m, mem, sizeof mem), far.depth / h, far.depth,
                     far.within);
            la_warn(L, line);
            return;
        }
    }
}
