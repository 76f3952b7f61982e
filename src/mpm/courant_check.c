/* courant_check.c - the Courant refusal (docs/design.md, docs/robustness.md):
 * a dt whose Courant number dt c_max / h exceeds the run's limit (courant
 * times the basis' factor, lm_sim_courant_limit) is refused with the limit
 * printed, naming the body whose wave speed sets it and the dt that would
 * pass. In the engine (issue 33 item 1), so a C caller of the step gets the
 * refusal the Lua layer reports: lm_sim_step checks before its first step
 * and again after anything that moves the number (dt, courant, a material,
 * a body, a membrane's force form, a restored state). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "step.h"

static void append(char *buf, size_t len, const char *text)
{
    size_t k = strlen(buf);
    if (k < len) snprintf(buf + k, len - k, "%s", text);
}

lm_status lm_sim_check_courant(lm_sim *sim)
{
    double c;
    int b;
    double cn = lm_sim_courant_body(sim, &c, &b);
    double limit = lm_sim_courant_limit(sim);
    if (!(cn > limit * (1 + 1e-12))) {
        sim->work->courant_checked = 1;
        return LM_OK;
    }
    double h = fmin(sim->grid.hx, sim->grid.hy);
    char basis[320] = "", who[96] = "", why[200] = "", part[200];
    double fb = lm_basis_courant_factor(sim->def.basis);
    if (fb != 1) {
        snprintf(part, sizeof part, " x %g for basis = \"%s\"", fb, lm_basis_name(sim->def.basis));
        append(basis, sizeof basis, part);
    }
    if (sim->def.scheme == LM_USL) {
        snprintf(part, sizeof part, " x %g for scheme = \"usl\" (USL divides each node's "
                 "momentum by its own mass: less stable than MUSL)", LM_USL_COURANT);
        append(basis, sizeof basis, part);
    }
    if (sim->def.mass == LM_MASS_CORRECTED) {
        snprintf(part, sizeof part, " x %g for mass = \"corrected\" (its highest grid mode "
                 "is faster)", LM_CORRECTED_COURANT);
        append(basis, sizeof basis, part);
    }
    if (b >= 0) {
        const lm_body *bd = &sim->bodies[b];
        lm_body_label(sim, b, who, sizeof who);
        if (bd->membrane && bd->force == LM_MFORCE_SEGMENT)
            snprintf(why, sizeof why, "; its tension acts along segments, stable to "
                     "dt*c/h = %g, so c counts as its wave speed / %g",
                     LM_SEGMENT_COURANT, LM_SEGMENT_COURANT);
    }
    snprintf(sim->err, sizeof sim->err,
             "dt = %g is too large: Courant number dt*c/h = %g exceeds "
             "courant = %g%s (c_max = %g from %s%s, h = %g); use dt <= %g or raise courant",
             sim->def.dt, cn, sim->def.courant, basis, c, b >= 0 ? who : "no body", why,
             h, limit * h / c);
    return LM_ERR_COURANT;
}

lm_status lm_sim_try_dt(lm_sim *sim, double dt)
{
    double old = sim->def.dt;
    int was = sim->work->courant_checked;
    lm_sim_set_dt(sim, dt);
    if (lm_sim_check_courant(sim) == LM_OK) return LM_OK;
    char why[sizeof sim->err];
    snprintf(why, sizeof why, "%s", sim->err);
    lm_sim_set_dt(sim, old);   /* the clock's base moves again: t stays exact */
    sim->work->courant_checked = was;
    snprintf(sim->err, sizeof sim->err, "%s", why);
    return LM_ERR_COURANT;
}
