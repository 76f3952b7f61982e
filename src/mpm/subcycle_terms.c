/* subcycle_terms.c - multi-rate stepping (subcycle.c) with what the
 * airbags need: the axisymmetric hoop term, links and point pins (issue 36
 * item 1; assets/lua/airbag.lua has all three).
 *
 * subcycle.c splits the grid's sums into the membranes' (the fast group,
 * re-summed at every sub-step of dt_s = dt / k) and the rest's, held over
 * the step: f^G = f - f^M with f the plain step's step-2 force. Each term
 * below is put in the group whose motion changes it within the step, so
 * that f^G holds only what does not move until the step's end.
 *
 * The hoop term (axisym.c: f_ri += -V_p sigma_thth,p N_ip / r_p) is one
 * particle's own: its stress and its radius. A membrane point's
 * sigma_thth follows its radius (ln(r / r0), re-set at every sub-step with
 * its strain) and its point moves in every sub-step, so its hoop force is
 * in f^M and re-summed each sub-step (lm_axisym_forces_into, membranes
 * only). The gas's and a solid's hoop stress change with their strain,
 * which is updated once at the step's end, so their hoop force is part of
 * the held f^G. Energy, as in the plane form (subcycle.c's header): the
 * slow group's hoop rate at the end is D_thth = sum_i N_ip X_ri / (r_p dt)
 * from the same displacements X_i as its in-plane rate, so
 * sum_p V_p sigma_thth D_thth dt = -sum_i f^hoop_i . X_i: what its held
 * hoop force did on the nodes is what its hoop stress works; a ring's
 * hoop energy is exchanged with the nodes every sub-step as in the
 * single-rate step. Momentum: the hoop term is per radian and radial, not
 * an action-reaction pair (a ring's tension pulls it to the axis); the
 * axial momentum is exchanged between the groups exactly as in the plane
 * form, and the radial changes by the hoop forces of each group, each
 * applied over the time its stress holds.
 *
 * A link (link.c) pulls its two points along the line between them with
 * T(l) e, the gradient of its stored energy; with an end on a membrane
 * that end moves in every sub-step, so its force is re-computed at every
 * sub-step at the points' present places (a slow end stays at x^n until
 * the step's end) and goes into f^M; a link between two slow bodies stays
 * in f^G. Momentum: its two forces are equal and opposite at every
 * sub-step, so the exchange balances as the membrane's own forces do (in
 * the axisymmetric form a link along the axis, the airbag's tether,
 * likewise). Energy: its force is -dU/dx at the sub-step's places, the
 * single-rate step's for the sub-step.
 *
 * A point pin (pin.c, constraint.c) holds a membrane point: its mass and
 * momentum are taken off the membranes' sums at every sub-step as step 1
 * takes them off the grid (so m^G = m - m^M is the slow group's exactly),
 * lm_step_grid_update solves the constraint on the sub-step's P and F
 * (sim->def.dt is dt_s there), and after the move the held point takes
 * the pin's velocity and x + dt_s v_pin (lm_pin_particles from its place
 * before the sub-step). The slow group's nodes near the pin get the
 * constrained accelerations (A_i, and their momentum share) as they would
 * in a plain step of dt_s; its strain velocity X_i / dt is constrained
 * again at the end (lm_step_strain_velocity_end: the held point's
 * interpolated velocity is the pin's). The reaction reported
 * (pin:reaction()) is the mean of the sub-steps' forces, the impulse over
 * the step divided by dt. Refused: a pin on a gas or solid (its velocity
 * is set only at the step's end while its nodes are held at every
 * sub-step: not derived here) and a pin that holds its nodes (points
 * sharing nodes, pin.c's classify): not measured; and heavy end points.
 *
 * k = 1: every term is added once, in the plain step's order (the hoop,
 * the links, the pins' take-off, gravity), the pin's move and velocity
 * after the membranes' step-4 update, the reaction the sub-step's: the
 * plain step to rounding (tests/physics/substeps_axisym.lua,
 * substeps_pins.lua). */
#include <stdio.h>

#include "subcycle_terms.h"

int lm_subcycle_terms_active(const lm_sim *sim)
{
    return sim->def.axisym || sim->nlinks > 0 || sim->npins > 0;
}

int lm_subcycle_heavy_point(const lm_sim *sim)
{
    for (int b = 0; b < sim->nbodies; b++)
        if (sim->bodies[b].end_grid_mass > 0) return 1;
    return 0;
}

lm_status lm_subcycle_check_pins(lm_sim *sim)
{
    for (int k = 0; k < sim->npins; k++) {
        const lm_pin *pn = &sim->pins[k];
        char who[96];
        const char *why = NULL;
        if (!sim->bodies[pn->body].membrane) why = "a pin on a body that is not a membrane";
        else if (!pn->point)
            why = "a pin whose points share grid nodes (it holds its nodes: pin.c)";
        if (!why) continue;
        snprintf(sim->err, sizeof sim->err,
                 "substeps (multi-rate stepping) does not work with %s (the simulation's pin %d, "
                 "on %s); leave substeps out",
                 why, k + 1, lm_body_label(sim, pn->body, who, sizeof who));
        return LM_ERR_INPUT;
    }
    return LM_OK;
}

void lm_subcycle_fast_terms(lm_sim *sim, double *m, double *px, double *py, double *fx,
                            double *fy)
{
    if (sim->def.axisym) lm_axisym_forces_into(sim, fx, 1);   /* the rings' hoop */
    lm_link_forces_into(sim, fx, fy, LM_LINKS_FAST);
    if (sim->npins) lm_constraint_take_off(sim, m, px, py);   /* held points */
}

void lm_subcycle_pins_start(lm_sim *sim)
{
    lm_pin_keep_start(sim);
}

void lm_subcycle_pins_moved(lm_sim *sim)
{
    if (sim->npins) lm_pin_particles(sim);   /* with sim->def.dt = dt_s */
}

void lm_subcycle_pins_react(lm_sim *sim, int j, int k)
{
    for (int a = 0; a < sim->npins; a++) {
        lm_pin *pn = &sim->pins[a];
        pn->sx = j ? pn->sx + pn->rx : pn->rx;
        pn->sy = j ? pn->sy + pn->ry : pn->ry;
        if (j == k - 1) {
            pn->rx = pn->sx / k;
            pn->ry = pn->sy / k;
        }
    }
}
