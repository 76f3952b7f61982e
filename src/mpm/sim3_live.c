/* sim3_live.c - a 3D run's live settings, changed between steps through
 * the engine (the one writer of its state, docs/design.md "Engine"; the 2D
 * setters are lm_sim_set_gravity, lm_sim_set_courant, lm_sim_set_material,
 * lm_sim_set_pin_velocity). Each checks what it is given; err says why not. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mpm3.h"

lm_status lm3_set_gravity(lm3_sim *sim, const double g[3])
{
    for (int a = 0; a < 3; a++)
        if (!isfinite(g[a])) {
            snprintf(sim->err, sizeof sim->err, "gravity: component %d is not finite", a + 1);
            return LM_ERR_INPUT;
        }
    memcpy(sim->def.gravity, g, sizeof sim->def.gravity);
    return LM_OK;
}

lm_status lm3_set_courant(lm3_sim *sim, double c)
{
    if (!(c > 0) || !isfinite(c)) {
        snprintf(sim->err, sizeof sim->err, "courant = %g: must be a positive number", c);
        return LM_ERR_INPUT;
    }
    sim->def.courant = c;
    return LM_OK;
}

lm_status lm3_material_set(lm3_sim *sim, int k, const lm3_material *m)
{
    if (k < 0 || k >= sim->nmat) {
        snprintf(sim->err, sizeof sim->err, "material %d: no such material", k);
        return LM_ERR_INPUT;
    }
    /* rho is not live: the particles' masses were fixed from it */
    if (m->rho != sim->mats[k].rho) {
        snprintf(sim->err, sizeof sim->err, "rho cannot be changed (the masses were set from it)");
        return LM_ERR_INPUT;
    }
    if (m->kind != sim->mats[k].kind) {
        snprintf(sim->err, sizeof sim->err, "the kind cannot be changed (the particles "
                 "were seeded as it)");
        return LM_ERR_INPUT;
    }
    /* a gas's live constants (mu, av: l_material.c) as lm3_material_add
     * checks them; a solid's E, nu */
    if (m->kind == LM3_GAS) {
        if (!(m->mu >= 0) || !isfinite(m->mu)) {
            snprintf(sim->err, sizeof sim->err, "mu = %g: must be >= 0", m->mu);
            return LM_ERR_INPUT;
        }
    } else if (!(m->E > 0) || !isfinite(m->E) || !(m->nu > -1 && m->nu < 0.5)) {
        snprintf(sim->err, sizeof sim->err, "E = %g, nu = %g: E must be positive and nu in "
                 "(-1, 0.5)", m->E, m->nu);
        return LM_ERR_INPUT;
    }
    sim->mats[k] = *m;
    return LM_OK;
}

lm_status lm3_pin_set_velocity(lm3_sim *sim, int pin, const double v[3])
{
    if (!sim->pins || pin < 0 || pin >= sim->pins->n) {
        snprintf(sim->err, sizeof sim->err, "pin %d: no such pin", pin);
        return LM_ERR_INPUT;
    }
    memcpy(sim->pins->pin[pin].v, v, sizeof sim->pins->pin[pin].v);
    return LM_OK;
}
