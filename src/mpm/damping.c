/* damping.c - viscous damping of the grid velocities (issue 35 item 2),
 * lamina.sim{damping = c}: a nodal force -c m_i v_i, the grid's analogue
 * of LAMMPS' `fix viscous`, to bring a run to its static equilibrium in a
 * few ringing periods instead of waiting for the gas's viscosity.
 *
 * The force is mass-proportional (Rayleigh damping with the mass term
 * only): every mode of the grid's motion decays at the same rate, its
 * amplitude as exp(-c t / 2) (the equation of a damped oscillator
 * x'' + c x' + w^2 x = 0), whatever its frequency. It is no physical
 * dissipation: the motion it leaves is not the undamped one, only the
 * equilibrium it settles to is (where v = 0 the force vanishes).
 *
 * Integrated implicitly (backward Euler in the velocity), so that any c dt
 * is stable and a large c can never reverse a velocity:
 *     v^L = (v + dt f / m) / (1 + c dt),
 * i.e. the force handed to the rest of the step is
 *     f' = (f - c p) / (1 + c dt) = f - c p^L,
 * with p^L = p + dt f' the damped Lagrangian momentum. The explicit form
 * f - c p needs c dt < 2 and overshoots (reverses the velocity) past
 * c dt = 1. Writing the damping into f, not only into p^L, keeps FLIP's
 * particle update (v_p += dt sum N_ip f_i / m_i, [F] eq 12) consistent with
 * the grid's: a_i = f'_i / m_i and v^L_i = p^L_i / m_i differ by v_i / dt
 * exactly as undamped. The update is node by node, so the threaded and
 * the fused steps (which read the same f', p^L) give the same bits; c = 0
 * is never applied, so the undamped step is unchanged to the bit.
 *
 * The energy taken out: the node's kinetic energy changes by
 * (|p^L|^2 - |p|^2) / 2m = dt f' . (p^L + p) / 2m, the work of the force
 * over the step's mean velocity; the damping's part of f' is -c p^L, so
 * its share is exactly c dt p^L . (p^L + p) / 2m, p = p^L - dt f' (the
 * "exact kinetic-energy drop of the implicit update": for a body moving
 * freely it is all of the drop, tests/physics/damping_string.lua). The
 * simpler c dt |p^L|^2 / m (force times the displacement dt v^L) differs by
 * O(c dt) of it. lm_damp_account adds it up after the walls and pins (which
 * take the normal components and the held nodes over, p^L and f' alike)
 * into sim->damped: total + damped is the conserved sum
 * (sim:energy().damped).
 *
 * With lamina.sim{mass = "corrected" | "membrane"} step 3 replaces p_i by
 * its corrected value p_i^C (mass_corrected.c) after the damping force
 * was formed; the damping's part of the corrected f' is still -c p^L (the
 * correction is linear: C (f - c p_lumped^L) = C f - c p^L). But the
 * particles' momentum at node i over the step is not p^L - dt f'
 * (= p^C): it is sum_p m_p N_ip v_p = p_i, the lumped one, plus half the
 * step's change. So the account's mean momentum there is p_i + dt f' / 2
 * with p_i kept from before the correction (lm_damp_keep_momentum): with
 * p^C instead a string ringing on "membrane" counted its damping's work
 * 1 % wrong (total + damped drifted 4.9e-9 against the undamped run's
 * 4.6e-11, tests/physics/damping_string.lua). A uniform motion has
 * p^C = p (the correction keeps it), so the free body's account is the
 * same on every mass. */
#include <math.h>
#include <stdio.h>

#include "step.h"
#include "threads.h"

lm_status lm_sim_set_damping(lm_sim *sim, double c)
{
    if (!(c >= 0) || !isfinite(c)) {
        snprintf(sim->err, sizeof sim->err, "damping must be a finite number >= 0 (1/s) (got %g)", c);
        return LM_ERR_INPUT;
    }
    sim->def.damping = c;
    return LM_OK;
}

void lm_damp_forces(const lm_sim *sim, long first, long last, const double *px,
                    const double *py, double *fx, double *fy)
{
    const double c = sim->def.damping, r = 1.0 / (1.0 + c * sim->def.dt);
    for (long i = first; i < last; i++) {
        fx[i] = (fx[i] - c * px[i]) * r;
        fy[i] = (fy[i] - c * py[i]) * r;
    }
}

void lm_damp_grid(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    const long nn = (long)lm_grid_nodes(g);
    const double c = sim->def.damping, r = 1.0 / (1.0 + c * sim->def.dt);
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) if (nn > LM_NODE_LOOP_MIN)
    for (long i = 0; i < nn; i++) {
        g->fx[i] = (g->fx[i] - c * g->px[i]) * r;
        g->fy[i] = (g->fy[i] - c * g->py[i]) * r;
    }
}

/* Before step 3's mass correction: the lumped p_i, which the account
 * reads as the particles' own momentum at the node. */
void lm_damp_keep_momentum(lm_sim *sim)
{
    const lm_grid *g = &sim->grid;
    const size_t nn = lm_grid_nodes(g);
    double *p0 = sim->work->mass_p0;
    for (size_t i = 0; i < nn; i++) {
        p0[i] = g->px[i];
        p0[nn + i] = g->py[i];
    }
}

void lm_damp_account(lm_sim *sim)
{
    const lm_grid *g = &sim->grid;
    const size_t nn = lm_grid_nodes(g);
    double w = 0;
    /* one thread, in node order: the same sum whatever the thread count */
    const double dt = sim->def.dt;
    const double *p0 = lm_mass_corrects(sim) ? sim->work->mass_p0 : NULL;
    for (size_t i = 0; i < nn; i++) {
        if (!(g->m[i] > 0)) continue;
        /* p^L . (p^L + p) / 2 with p = p^L - dt f' (lumped); with the mass
         * correction p is the lumped p_i kept before it (above) */
        double ax = p0 ? p0[i] + 0.5 * dt * g->fx[i] : g->px[i] - 0.5 * dt * g->fx[i];
        double ay = p0 ? p0[nn + i] + 0.5 * dt * g->fy[i] : g->py[i] - 0.5 * dt * g->fy[i];
        w += (g->px[i] * ax + g->py[i] * ay) / g->m[i];
    }
    sim->damped += sim->def.damping * dt * w;
}
