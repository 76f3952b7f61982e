/* energy_watch.c - a run whose total energy grows says so (issue 33 item 1:
 * in the engine, so a C caller of the step can watch as sim:run does; the
 * Lua layer only prints the warning, once a sim).
 *
 * Nothing in lamina's models makes energy: gravity's work is in the
 * potential energy, the gas's in its internal energy, the springs' and
 * membranes' in their strain; contact and artificial viscosity only take it
 * away. So a total that rises by a tenth over one run with no pin driving
 * a body is the numerics feeding the motion. Measured (2026-12-02): an
 * elastic disk ringing a little while it flies across the grid at speed 1
 * (radius 1.5, E 1e4, cell 0.0625, bilinear basis, MUSL, Courant number
 * 0.42) gained 79 % in 8 s with no sign in its velocity; the ball of the
 * ball-and-net page at that cell nearly doubled its energy after leaving
 * the net. The bilinear basis' cell-crossing noise pumps the vibration of
 * a moving body (docs/robustness.md, "Energy growth of a moving body on the
 * bilinear basis"); the quadratic B-spline and uGIMP keep it.
 *
 * It is a warning, not a failure: the run's numbers may still serve, and
 * the caller may have put energy in itself (a callback that sets
 * velocities). Runs of fewer than WATCH_MIN_STEPS steps are not judged
 * (their energy is two O(N) sums, negligible beside that many steps). */
#include <math.h>
#include <stdio.h>

#include "mpm.h"

#define WATCH_MIN_STEPS 100
#define WATCH_RISE 0.1   /* of the energy's scale: see energy_scale */

/* The size the rise is judged against: the sum of the magnitudes of the
 * parts, the largest seen during the run (sampled every WATCH_EVERY steps
 * and at both ends), so that a pendulum caught near a turning point, or a
 * body started at rest under gravity (total 0), is judged against the
 * energy it has swung through. */
static double energy_scale(lm_energy e)
{
    return e.kinetic + fabs(e.strain) + fabs(e.internal) + fabs(e.potential);
}

/* Energies below this share of M c_max^2 (the whole mass moving at the
 * fastest wave speed) are rounding: a body at rest holds 1e-16 or so, and
 * its relative changes mean nothing. */
#define WATCH_FLOOR 1e-12
#define WATCH_EVERY 64

/* The energy the dynamics sees: the particles' kinetic energy as the grid
 * sees it (docs/api.md, sim:energy's grid_kinetic). Without a PIC blend,
 * FLIP's hidden velocity (which moves nothing) can grow in a run whose
 * motion keeps its energy (the pendulum of tests/physics/pendulum_flip.lua:
 * the angle within 0.025 degrees of the FEM while the particles' sum rose
 * by 7 % of the swing); that is not the growth this watch is for. */
static double seen_energy(const lm_sim *sim, lm_energy e)
{
    /* the grid damping's work is no loss to explain (damping.c): total +
     * damped is what the run keeps */
    return e.total - e.kinetic + lm_sim_grid_kinetic(sim) + sim->damped;
}

void lm_energy_watch_begin(const lm_sim *sim, lm_energy_watch *w)
{
    const lm_particles *p = &sim->p;
    double M = 0, c = 0;
    for (size_t q = 0; q < p->n; q++) M += p->m[q];
    lm_sim_courant(sim, &c);
    w->floor = WATCH_FLOOR * M * c * c;
    lm_energy e = lm_sim_energy(sim);
    w->seen0 = seen_energy(sim, e);
    w->scale = energy_scale(e);
    w->t0 = sim->t;
    w->step0 = sim->step;
    w->gx = sim->def.gx;
    w->gy = sim->def.gy;
    w->driven = 0;
}

/* Has the caller changed gravity since the run began? It did work on the
 * run: the potential energy's datum moved. */
static int gravity_changed(const lm_sim *sim, const lm_energy_watch *w)
{
    return sim->def.gx != w->gx || sim->def.gy != w->gy;
}

void lm_energy_watch_step(const lm_sim *sim, lm_energy_watch *w)
{
    for (int k = 0; k < sim->npins && !w->driven; k++)
        w->driven = sim->pins[k].vx != 0 || sim->pins[k].vy != 0;
    if (gravity_changed(sim, w)) w->driven = 1;
    if ((sim->step - w->step0) % WATCH_EVERY == 0)
        w->scale = fmax(w->scale, energy_scale(lm_sim_energy(sim)));
}

int lm_energy_watch_end(const lm_sim *sim, const lm_energy_watch *w, char *msg, size_t len)
{
    if (w->driven || gravity_changed(sim, w) || sim->step - w->step0 < WATCH_MIN_STEPS)
        return 0;
    lm_energy e1 = lm_sim_energy(sim);
    double seen1 = seen_energy(sim, e1);
    double scale = fmax(w->scale, energy_scale(e1));
    double rise = seen1 - w->seen0;
    if (!(rise > w->floor) || !(rise > WATCH_RISE * scale)) return 0;
    double cn = lm_sim_courant(sim, NULL);
    double usual = lm_basis_courant_factor(sim->def.basis) *
                   (sim->def.scheme == LM_USL ? LM_USL_COURANT : 1);
    char why[600];
    if (cn > usual)   /* the caller raised lamina.sim{courant} */
        snprintf(why, sizeof why, "a step past the stable limit (Courant number dt*c/h = %.3g, "
                 "above the %.3g lamina allows unless lamina.sim{courant} is raised): a "
                 "smaller dt", cn, usual);
    else if (sim->def.basis == LM_BASIS_LINEAR)
        snprintf(why, sizeof why, "the bilinear basis' cell-crossing noise feeding a moving "
                 "body's vibration (docs/robustness.md, \"Energy growth of a moving body on the "
                 "bilinear basis\"): basis = \"bspline2\" or \"gimp\" keeps it; or a step "
                 "too near the limit for points on cell sides (Courant number %.3g; [T] Ch. 8 "
                 "halves the limit there)", cn);
    else
        snprintf(why, sizeof why, "a step too near the stability limit (Courant number %.3g): "
                 "try a smaller dt", cn);
    snprintf(msg, len,
             "the total energy rose by %.1f %% of the most the run held (%.6g) "
             "during sim:run, from %.6g to %.6g between t = %.6g and %.6g (steps %ld to %ld), "
             "with no pin driving a body (kinetic energy as the grid sees it); likely cause: %s",
             100 * rise / scale, scale, w->seen0, seen1, w->t0, sim->t, w->step0, sim->step, why);
    return 1;
}
