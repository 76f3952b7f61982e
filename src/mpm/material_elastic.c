/* material_elastic.c - isotropic linear elastic solid, Jaumann rate.
 *
 * [F] eqs 18-20, [T] eq 5.8. Tensor shear: sigma_xy = 2G eps_xy. */
#include "step.h"

/* sigma <- sigma + dt (W.sigma - sigma.W) + C : de, with L = dv/dx and
 * w = W_xy = (L_xy - L_yx)/2. Expanding the 2x2 products:
 * (W.s - s.W) = [[2w s_xy, w (s_yy - s_xx)], [., -2w s_xy]].
 * Check (docs/physics.md §1 step 8): a counter-clockwise spin omega has
 * w = -omega and turns diag(s, 0) into s_xy = +s omega dt. The rotation uses
 * the stress at the start of the step; sigma_zz is unchanged by a spin
 * about z. */
void lm_elastic_update(const lm_material *mat, double dexx, double deyy,
                       double dexy, double w, double dt, double *sxx,
                       double *syy, double *sxy, double *szz)
{
    double sx = *sxx, sy = *syy, s = *sxy;
    double rxx = 2 * w * s * dt, ryy = -2 * w * s * dt;
    double rxy = w * (sy - sx) * dt;
    double E = mat->E, nu = mat->nu, G = E / (2 * (1 + nu));
    double cxx, cyy, czz;
    if (mat->plane == LM_PLANE_STRAIN) {
        double lam = E * nu / ((1 + nu) * (1 - 2 * nu));
        cxx = (lam + 2 * G) * dexx + lam * deyy;
        cyy = lam * dexx + (lam + 2 * G) * deyy;
        czz = lam * (dexx + deyy);      /* eps_zz = 0: sigma_zz = nu(sxx+syy) */
    } else {
        double k = E / (1 - nu * nu);
        cxx = k * (dexx + nu * deyy);
        cyy = k * (nu * dexx + deyy);
        czz = 0;
    }
    *sxx = sx + rxx + cxx;
    *syy = sy + ryy + cyy;
    *sxy = s + rxy + 2 * G * dexy;
    *szz += czz;
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
