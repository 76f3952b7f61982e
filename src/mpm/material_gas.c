/* material_gas.c - compressible viscous gas ([F] §3.3, [T] Ch. 4) and the
 * linear fluid of the piston problem ([F] eq 26). */
#include <math.h>

#include "step.h"

/* c = sqrt(gamma p / rho) with p = (gamma - 1) rho e ([F] eq 22). */
double lm_gas_sound_speed(const lm_material *mat, double e)
{
    return sqrt(mat->gamma * (mat->gamma - 1) * (e > 0 ? e : 0));
}

/* [F] eq 24 prints q = sqrt(c_max^2 g) rho lambda D [c1 + c2 |div v| / max|div v|].
 * As printed its units are not a pressure (sqrt(c^2 g) is m^1.5/s); Wilkins'
 * linear term, which it follows, is rho c l |D|. We read the lost square as
 * sqrt(c_max^2 g^2) = c_max g, and use |D| so that q >= 0 (docs/physics.md §2,
 * reconstructed): q = c_max g rho lambda |D| [c1 + c2 |D| / max|D|], with D
 * = div v only in compression ([F] eq 25). The Sod test checks it. */
double lm_gas_av(const lm_material *mat, double rho, double div, double max_div,
                 double c_max, double h)
{
    if (!mat->av || !(div < 0)) return 0;
    double g = mat->av_g > 0 ? mat->av_g : sqrt(2.0) * h;
    double D = -div;
    double ratio = max_div > 0 ? D / max_div : 0;
    return c_max * g * rho * mat->av_lambda * D * (mat->av_c1 + mat->av_c2 * ratio);
}

/* The shear viscosity a gas point's update uses: the material's mu, or
 * with lamina.sim{viscous_limit = kappa} (kappa > 0) at most
 * kappa rho h^2 / dt. The viscous stress 2 mu edot is explicit: on the grid
 * it is a diffusion of the velocity with the kinematic viscosity mu / rho,
 * and a forward step of a diffusion is stable only while
 * (mu / rho) dt / h^2 stays below a bound of order 1/4 in 2-D (the von
 * Neumann limit of the forward-time centred-space heat equation, 1/2 per
 * dimension: Press et al., Numerical Recipes, 2nd ed., §19.2), less with
 * the viscous stress's 4/3 on a normal rate. The
 * Courant check counts sound speed and speed, not this: a gas point rarefied
 * near a membrane (Box 9's dog-bone at 8-16 x the deck's dt: rho 0.09, 14
 * neighbours within h, its nodes 2-13 % of a full cell's mass) crosses it
 * while the sound speed allows the step, and its velocity flips sign each
 * step, growing about 1.4 x a step until it inverts (docs/performance.md
 * "The gas's step beside a membrane"). The limit takes from such a point
 * only the viscosity the step cannot resolve; a point denser than
 * mu dt / (kappa h^2) keeps mu to the bit. */
double lm_gas_mu(const lm_material *mat, double kappa, double rho, double h, double dt)
{
    if (!(kappa > 0)) return mat->mu;
    double most = kappa * rho * h * h / dt;
    return mat->mu > most ? most : mat->mu;
}

void lm_gas_update(const lm_material *mat, double exx, double eyy, double exy,
                   double dt, double rho, double q, double *e, double *sxx, double *syy,
                   double *sxy, double *szz)
{
    double mu = mat->mu;
    double tr = exx + eyy;                  /* plane strain: edot_zz = 0 */
    double p = (mat->gamma - 1) * rho * *e; /* e^k, rho^{k+1} (docs/physics.md §2) */
    double iso = -(2.0 / 3.0) * mu * tr - p - q;
    *sxx = 2 * mu * exx + iso;
    *syy = 2 * mu * eyy + iso;
    *sxy = 2 * mu * exy;
    *szz = iso;
    /* [F] eq 23: the work of the new stress on the step's strain dt edot */
    double work = *sxx * (dt * exx) + *syy * (dt * eyy) + 2 * *sxy * (dt * exy);
    *e += work / rho;
}

/* Step 8 at a gas point: rho / (1 + tr de) unless the density comes from
 * the cells (density.c), the artificial viscosity from the step's maxima,
 * then the stress and e (with lamina.sim{viscous_limit}, the viscosity
 * lm_gas_mu allows at the point's density). */
void lm_gas_update_at(lm_sim *sim, size_t q, const lm_rate *r)
{
    lm_particles *p = &sim->p;
    const lm_material *mat = sim->mats[p->mat[q]];
    const double *L = r->L;
    if (mat->density == LM_DENSITY_CONTINUITY) p->rho[q] /= 1 + r->dexx + r->deyy;
    p->q[q] = lm_gas_av(mat, p->rho[q], L[0] + L[3], r->max_div, r->c_max, r->h);
    lm_material limited;
    double mu = lm_gas_mu(mat, sim->def.visc_limit, p->rho[q], r->h, r->dt);
    if (mu != mat->mu) {   /* a rarefied point: the material with its mu lowered */
        limited = *mat;
        limited.mu = mu;
        mat = &limited;
    }
    lm_gas_update(mat, L[0], L[3], 0.5 * (L[1] + L[2]), r->dt, p->rho[q], p->q[q], &p->e[q],
                  &p->sxx[q], &p->syy[q], &p->sxy[q], &p->szz[q]);
}

void lm_linear_fluid_update_at(lm_sim *sim, size_t q, const lm_rate *r)
{
    lm_particles *p = &sim->p;
    p->rho[q] /= 1 + r->dexx + r->deyy;
    lm_linear_fluid_update(sim->mats[p->mat[q]], r->dexx, r->deyy, &p->ev[q], &p->sxx[q],
                           &p->syy[q], &p->sxy[q], &p->szz[q]);
}

void lm_linear_fluid_update(const lm_material *mat, double dexx, double deyy, double *ev,
                            double *sxx, double *syy, double *sxy, double *szz)
{
    *ev += dexx + deyy;
    double p = -mat->beta * *ev;
    *sxx = *syy = *szz = -p;
    *sxy = 0;
}
