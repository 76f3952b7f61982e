/* elastic_moduli.h - the elastic solid's update ([F] eqs 18-20, [T] eq
 * 5.8; material_elastic.c) split in two: its moduli from (E, nu) once,
 * then the update of a particle's stress from them. lm_elastic_update and
 * the B-spline's fused pass (step_bspline2.c, which works the moduli out
 * once a pass instead of two divisions a particle) both use these, so the
 * two give the same bits. */
#ifndef LAMINA_ELASTIC_MODULI_H
#define LAMINA_ELASTIC_MODULI_H

#include "mpm.h"

typedef struct lm_elastic_moduli {
    int elastic;        /* an elastic solid */
    int strain;         /* plane strain (else plane stress) */
    double lam, lam2G;  /* plane strain: lambda, lambda + 2 G */
    double k, nu;       /* plane stress: E / (1 - nu^2), nu */
    double twoG;        /* 2 G, the shear's */
} lm_elastic_moduli;

static inline lm_elastic_moduli lm_elastic_moduli_of(const lm_material *mat)
{
    lm_elastic_moduli c = {0};
    double E = mat->E, nu = mat->nu, G = E / (2 * (1 + nu));
    c.elastic = mat->kind == LM_ELASTIC;
    c.strain = mat->plane == LM_PLANE_STRAIN;
    /* only the form's moduli: two divisions, as the update made them */
    if (c.strain) {
        c.lam = E * nu / ((1 + nu) * (1 - 2 * nu));
        c.lam2G = c.lam + 2 * G;
    } else {
        c.k = E / (1 - nu * nu);
    }
    c.nu = nu;
    c.twoG = 2 * G;
    return c;
}

/* sigma <- sigma + dt (W.sigma - sigma.W) + C : de, with L = dv/dx and
 * w = W_xy = (L_xy - L_yx)/2. Expanding the 2x2 products:
 * (W.s - s.W) = [[2w s_xy, w (s_yy - s_xx)], [., -2w s_xy]].
 * Check (docs/physics.md §1 step 8): a counter-clockwise spin omega has
 * w = -omega and turns diag(s, 0) into s_xy = +s omega dt. The rotation uses
 * the stress at the start of the step; sigma_zz is unchanged by a spin
 * about z. */
static inline void lm_elastic_update_moduli(const lm_elastic_moduli *c, double dexx,
                                            double deyy, double dexy, double w, double dt,
                                            double *sxx, double *syy, double *sxy,
                                            double *szz)
{
    double sx = *sxx, sy = *syy, s = *sxy;
    double rxx = 2 * w * s * dt, ryy = -2 * w * s * dt;
    double rxy = w * (sy - sx) * dt;
    double cxx, cyy, czz;
    if (c->strain) {
        cxx = c->lam2G * dexx + c->lam * deyy;
        cyy = c->lam * dexx + c->lam2G * deyy;
        czz = c->lam * (dexx + deyy);   /* eps_zz = 0: sigma_zz = nu(sxx+syy) */
    } else {
        cxx = c->k * (dexx + c->nu * deyy);
        cyy = c->k * (c->nu * dexx + deyy);
        czz = 0;
    }
    *sxx = sx + rxx + cxx;
    *syy = sy + ryy + cyy;
    *sxy = s + rxy + c->twoG * dexy;
    *szz += czz;
}

/* The moduli of the sim's first LM_FUSED_MATS materials (a pass's table;
 * materials past them use the update table). */
#define LM_FUSED_MATS 16
static inline void lm_elastic_moduli_table(const lm_sim *sim, lm_elastic_moduli *el)
{
    for (int m = 0; m < sim->nmats && m < LM_FUSED_MATS; m++)
        el[m] = lm_elastic_moduli_of(sim->mats[m]);
}

#endif
