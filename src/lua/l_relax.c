/* l_relax.c - sim:relax{...} (issue 35 item 2): run with the grid damping
 * (src/mpm/damping.c) until the motion has died down, for a static
 * equilibrium in a few ringing periods.
 *
 *   local ok, t, ratio = sim:relax{ damping = 140, t_end = 1, tol = 1e-2 }
 *
 * Steps in chunks of `every` (a time, default 20 dt) up to t_end and stops
 * once the largest kinetic energy sampled over the last 4 pi / c is at or
 * below tol times the largest since the call began (or below
 * 1e-12 M c_max^2, rounding: a body at rest). The kinetic energy is the
 * grid's view (sim:energy().grid_kinetic): FLIP's hidden particle velocity
 * moves nothing and the grid damping cannot reach it, so the particles' own
 * sum may never fall that far. A damping given here holds for the call
 * only; without one the sim's own (lamina.sim{damping}) is used, and there
 * must be one. Recorders, callbacks, checkpoints and the progress line run as
 * in sim:step. Returns whether it got there, the time, and the ratio.
 * tol defaults to 1e-2: the noise of a gas's points crossing cells keeps
 * some motion going that no damping removes (the gas arc of
 * tests/physics/damping_arc.lua: about 0.5 % of the peak). */
#include <math.h>

#include "l_internal.h"

#define RING 1024   /* kinetic energy samples of the window, at most */

static int sim_relax(lua_State *L)
{
    static const char *const keys[] = {"damping", "t_end", "tol", "every", NULL};
    const char *fn = "sim:relax";
    la_sim *s = la_check_sim(L, 1);
    la_check_keys(L, 2, fn, keys);
    lm_sim *sim = s->sim;
    if (s->running) return luaL_error(L, "%s: called from inside a callback", fn);
    double t_end = la_number(L, 2, fn, "t_end");
    if (!isfinite(t_end)) return luaL_error(L, "%s: t_end must be a finite number (got %f)", fn, t_end);
    double tol = la_opt_number(L, 2, fn, "tol", 1e-2);
    if (!(tol > 0 && tol < 1)) return luaL_error(L, "%s: tol must lie in (0, 1) (got %f)", fn, tol);
    double every = la_opt_number(L, 2, fn, "every", 20 * sim->def.dt);
    if (!(every > 0) || !isfinite(every))
        return luaL_error(L, "%s: every must be a positive time (got %f)", fn, every);
    double was = sim->def.damping;
    if (la_has(L, 2, "damping")) {
        double c = la_number(L, 2, fn, "damping");
        if (c == 0) return luaL_error(L, "%s: damping must be > 0 to relax (got 0)", fn);
        if (lm_sim_set_damping(sim, c) != LM_OK) return luaL_error(L, "%s: %s", fn, sim->err);
    } else if (!(was > 0)) {
        return luaL_error(L, "%s: no damping: give damping = c or set lamina.sim{damping = c}", fn);
    }
    la_checkpoint_restore(L, 1, s);   /* --restart: as sim:run */
    /* a body at rest holds rounding only: below the energy watch's floor,
     * 1e-12 M c_max^2 (src/mpm/energy_watch.c), the motion counts as gone */
    double M = 0, cm = 0;
    for (size_t q = 0; q < sim->p.n; q++) M += sim->p.m[q];
    lm_sim_courant(sim, &cm);
    const double floor_ke = 1e-12 * M * cm * cm;
    /* The kinetic energy is 0 at every turning point of a ringing mode, so
     * one sample says nothing: the test is on the largest sample over the
     * last 4 pi / c, the period of the mode c damps critically (c = 2 w),
     * at most RING samples of it kept. */
    const double window = 4 * acos(-1.0) / sim->def.damping;
    double chunk = fmax(1, floor(every / sim->def.dt + 0.5));
    chunk = fmax(chunk, ceil(window / sim->def.dt / RING));
    const int nwin = (int)fmax(1, ceil(window / (chunk * sim->def.dt)));
    double ring[RING];
    long nring = 0;
    double ke = lm_sim_grid_kinetic(sim), peak = ke, wmax = ke;
    int done = 0;
    for (;;) {
        double left = floor((t_end - sim->t) / sim->def.dt + 0.5);
        if (!(left >= 1)) break;
        /* (an error inside leaves the call's damping set: the run stops) */
        la_sim_advance(L, s, (long)fmin(chunk, left));
        ke = lm_sim_grid_kinetic(sim);
        peak = fmax(peak, ke);
        ring[nring++ % RING] = ke;
        if (nring < nwin) continue;   /* not a whole window yet */
        wmax = 0;
        for (int k = 0; k < nwin; k++) wmax = fmax(wmax, ring[(nring - 1 - k) % RING]);
        if (wmax <= tol * peak || wmax <= floor_ke) {
            done = 1;
            break;
        }
    }
    lm_sim_set_damping(sim, was);   /* the sim's own, checked when set */
    lua_pushboolean(L, done);
    lua_pushnumber(L, sim->t);
    lua_pushnumber(L, peak > 0 ? wmax / peak : 0);
    return 3;
}

void la_relax_methods(lua_State *L)
{
    lua_pushcfunction(L, sim_relax);
    lua_setfield(L, -2, "relax");
}
