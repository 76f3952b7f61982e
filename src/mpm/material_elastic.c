/* material_elastic.c - isotropic linear elastic solid, Jaumann rate.
 *
 * [F] eqs 18-20, [T] eq 5.8. Tensor shear: sigma_xy = 2G eps_xy. */
#include "elastic_moduli.h"
#include "step.h"

/* The update itself and its moduli: elastic_moduli.h (shared with the
 * B-spline's fused pass, step_bspline2.c). */
void lm_elastic_update(const lm_material *mat, double dexx, double deyy,
                       double dexy, double w, double dt, double *sxx,
                       double *syy, double *sxy, double *szz)
{
    lm_elastic_moduli c = lm_elastic_moduli_of(mat);
    lm_elastic_update_moduli(&c, dexx, deyy, dexy, w, dt, sxx, syy, sxy, szz);
}

/* Step 8 at particle q: rho / (1 + tr de) ([F] eq 16), then the stress. */
void lm_elastic_update_at(lm_sim *sim, size_t q, const lm_rate *r)
{
    lm_particles *p = &sim->p;
    p->rho[q] /= 1 + r->dexx + r->deyy;
    lm_elastic_update(sim->mats[p->mat[q]], r->dexx, r->deyy, r->dexy, r->w, r->dt, &p->sxx[q],
                      &p->syy[q], &p->sxy[q], &p->szz[q]);
}

/* 1/2 sigma : C^-1 : sigma from the full 3D compliance; in plane strain the
 * stored sigma_zz makes this equal to the 2D form, in plane stress it is 0. */
double lm_elastic_energy_density(const lm_material *mat, double sxx,
                                 double syy, double sxy, double szz)
{
    double E = mat->E, nu = mat->nu;
    return (sxx * sxx + syy * syy + szz * szz -
            2 * nu * (sxx * syy + syy * szz + szz * sxx) +
            2 * (1 + nu) * sxy * sxy) / (2 * E);
}
