/* axisym.c - the axisymmetric form of the step (lamina.sim{axisymmetric =
 * true}; docs/physics.md §1 "Axisymmetric form", [F] §2.2's remark on eq 14,
 * Sulsky & Schreyer 1996 = [F] ref 12).
 *
 * Coordinates: x is the radius r, y the axial z; the left side of the
 * domain is the axis r = 0 and is a symmetry wall (sim.c refuses any
 * other). Everything is per radian: a particle's mass is rho r dA (seeded
 * as rho r A_cell / ppc), its volume m / rho = r dA, so the nodal masses,
 * momenta and forces, the energies (diag.c) and a pin's reaction are per
 * radian too; multiply by 2 pi for the whole ring.
 *
 * With those, the weak form int sigma : grad w r dr dz gives the plane
 * form's sums plus one hoop term per particle, because grad w of a radial
 * test field w_r = N_i has the hoop component N_i / r:
 *   f_ri += -V_p sigma_thth,p N_ip / r_p          (lm_axisym_forces)
 * and its adjoint, the hoop strain rate at the particle from the same
 * nodal velocities the in-plane gradient uses:
 *   D_thth = sum_i N_ip v_ri / r_p,   de_thth = dt D_thth
 * so that the internal power sum_p V_p sigma : D equals -sum_i f_i . v_i,
 * as in the plane form. The hoop stress is kept in the particle's out-of-
 * plane slot szz (in the plane form sigma_zz), so the stress tensor is
 * (sigma_rr, sigma_zz, sigma_rz, sigma_thth) = (sxx, syy, sxy, szz).
 *
 * The axis. A seeded particle sits at r >= h / (2 sqrt(ppc)) > 0, so r_p
 * is never zero for solids and gas. A membrane may end on the axis (the
 * pole of a sphere); that point stays on it (its nodes' v_r are held at
 * zero by the symmetry wall and, for the 3 x 3 bases, cancelled by their
 * mirror images), and there the hoop rate v_r / r tends to dv_r/dr, which
 * is the meridional rate t.D.t of a surface meeting the axis at a right
 * angle: at a smooth pole the surface is stretched equally in every
 * direction. So a point on the axis takes eps_thth = eps_t, and its hoop
 * force, which would reach only nodes whose radial motion is held or
 * cancelled, is not computed (N_i / r is not formed there).
 * A membrane point's hoop strain is the ring's: ln(r / r0) with r0 its
 * unstrained radius, which follows the radius exactly in both the point
 * and the segment forms (membrane_force.c); no integration drift. */
#include <math.h>

#include "membrane_law.h"
#include "step_kernels.h"

/* sum_i N_ip v_ri / r_p with the strain velocity (step 5): the step's own
 * kernel (step_kernels.h), which the step reads with the velocity gradient */
double lm_axisym_hoop_rate(const lm_sim *sim, size_t q)
{
    const lm_grid *g = &sim->grid;
    const double rx = 1.0 / g->hx, ry = 1.0 / g->hy;
    double L[4];
    return g->sw == 2 ? lm_k_gradient_hoop(g, &sim->p, q, g->vx, g->vy, L, rx, ry, 2, 1)
                      : lm_k_gradient_hoop(g, &sim->p, q, g->vx, g->vy, L, rx, ry, 3, 1);
}

double lm_axisym_ring_radius(double r, double l)
{
    /* a point on the axis stands for the disc of its half segment, whose
     * centroid radius is l / 4 (int_0^{l/2} s ds / (l/2)) */
    return r > 0 ? r : 0.25 * l;
}


/* ---- membranes: a point is a ring ------------------------------------- */

double lm_axisym_membrane_hoop(const lm_particles *p, size_t q)
{
    /* at a pole the stretch is the same in every direction (above) */
    return p->r0[q] > 0 && p->x[q] > 0 ? log(p->x[q] / p->r0[q]) : p->et[q];
}

/* Sets eps_t, the stresses sigma_t t(x)t and sigma_thth (in szz) of the
 * biaxial law, and the volume thickness * l * R (l the point's meridional
 * length ds exp(eps_t), R its ring radius), kept as rho = m / V. */
void lm_axisym_membrane_set(lm_sim *sim, size_t q, double et)
{
    lm_particles *p = &sim->p;
    const lm_material *mat = sim->mats[p->mat[q]];
    p->et[q] = et;
    double st, sh;
    lm_membrane_stress_biaxial(mat, et, lm_axisym_membrane_hoop(p, q), &st, &sh);
    double tx = p->tx[q], ty = p->ty[q];
    p->sxx[q] = st * tx * tx;
    p->syy[q] = st * ty * ty;
    p->sxy[q] = st * tx * ty;
    p->szz[q] = sh;
    double l = p->ds[q] * exp(et);
    p->rho[q] = p->m[q] / (mat->thickness * l * lm_axisym_ring_radius(p->x[q], l));
}

void lm_axisym_membrane_point(lm_sim *sim, size_t q)
{
    lm_particles *p = &sim->p;
    /* an initial strain stretches the ring equally both ways (isotropic
     * prestrain, as a gas-filled sphere's) */
    p->r0[q] = p->x[q] > 0 ? p->x[q] * exp(-p->et[q]) : 0;
    lm_axisym_membrane_set(sim, q, p->et[q]);
}

void lm_axisym_membrane_prepare(lm_sim *sim)
{
    for (size_t q = 0; q < sim->p.n; q++)
        if (sim->mats[sim->p.mat[q]]->kind == LM_MEMBRANE)
            lm_axisym_membrane_set(sim, q, sim->p.et[q]);
}

double lm_axisym_membrane_energy(const lm_sim *sim, size_t q)
{
    const lm_particles *p = &sim->p;
    const lm_material *mat = sim->mats[p->mat[q]];
    return lm_membrane_ring_energy(mat, p->m[q] / p->rho[q], p->et[q],
                                   lm_axisym_membrane_hoop(p, q));
}

/* ---- step 2: the hoop term of the internal force ------------------------ */

void lm_axisym_forces(lm_sim *sim)
{
    lm_axisym_forces_into(sim, sim->grid.fx, 0);
}

/* The hoop terms into fx (folded): every particle's, or (membranes) only
 * the membranes' points' (multi-rate stepping's sub-steps, subcycle.c). */
void lm_axisym_forces_into(lm_sim *sim, double *fx, int membranes)
{
    lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const int W = g->sw;
    for (size_t q = 0; q < p->n; q++) {
        double r = p->x[q];
        if (!(r > 0)) continue;   /* on the axis: see the head of the file */
        const lm_material *mat = sim->mats[p->mat[q]];
        if (membranes && mat->kind != LM_MEMBRANE) continue;
        double c;
        if (mat->kind == LM_MEMBRANE) {
            /* V / r = thickness * l for a ring off the axis; a segment
             * point's eps_t is its segments' mean, its l their mean share */
            c = -p->szz[q] * mat->thickness * p->ds[q] * exp(p->et[q]);
        } else {
            c = -(p->m[q] / p->rho[q]) * p->szz[q] / r;
        }
        /* N alone, row by row: each node of the stencil once, so the
         * order of a node's sum (particle by particle) is unchanged */
        double Nl[9];
        const double *N = W == 2 ? lm_k_weights_N(p, q, 2, Nl) : lm_k_weights_N(p, q, 3, Nl);
        for (int b = 0; b < W; b++) {
            const long row = lm_stencil_row(g, p->node[q], b);
            for (int a = 0; a < W; a++) fx[row + a] += c * N[b * W + a];
        }
    }
    /* the ghost nodes were emptied by the in-plane scatter's fold: this
     * folds only the hoop terms (the x image is odd across the axis) */
    double *const f[1] = {fx};
    static const lm_comp comp[1] = {LM_COMP_X};
    lm_grid_fold(g, 1, f, comp);
}

/* ---- steps 6-8 for one particle ------------------------------------------ */

/* The isotropic elastic solid in 3D: the hoop strain makes the law the
 * full one ([T] eq 5.8 with eps_thth; plane strain / stress do not apply),
 * the Jaumann rotation acts in the r-z plane only (a spin about the hoop
 * axis leaves sigma_thth alone). */
static void elastic(const lm_material *mat, double dexx, double deyy, double dexy, double deh,
                    double w, double dt, double *sxx, double *syy, double *sxy, double *shh)
{
    double sx = *sxx, sy = *syy, s = *sxy;
    double E = mat->E, nu = mat->nu, G = E / (2 * (1 + nu));
    double lam = E * nu / ((1 + nu) * (1 - 2 * nu));
    double tr = dexx + deyy + deh;
    *sxx = sx + 2 * w * s * dt + lam * tr + 2 * G * dexx;
    *syy = sy - 2 * w * s * dt + lam * tr + 2 * G * deyy;
    *sxy = s + w * (sy - sx) * dt + 2 * G * dexy;
    *shh += lam * tr + 2 * G * deh;
}

/* The gas of [F] §3.3 with the hoop rate in the trace, the deviator and
 * the work ([F] eq 23): sigma = 2 mu edot - 2/3 mu tr(edot) I - (p + q) I. */
static void gas(const lm_material *mat, double exx, double eyy, double exy, double ehh,
                double dt, double rho, double q, double *e, double *sxx, double *syy,
                double *sxy, double *shh)
{
    double mu = mat->mu;
    double tr = exx + eyy + ehh;
    double pr = (mat->gamma - 1) * rho * *e;
    double iso = -(2.0 / 3.0) * mu * tr - pr - q;
    *sxx = 2 * mu * exx + iso;
    *syy = 2 * mu * eyy + iso;
    *sxy = 2 * mu * exy;
    *shh = 2 * mu * ehh + iso;
    double work = dt * (*sxx * exx + *syy * eyy + 2 * *sxy * exy + *shh * ehh);
    *e += work / rho;
}

/* Step 8 in the axisymmetric form: the plane updates with the hoop rate
 * v_r / r as a third normal strain rate (docs/physics.md, "Axisymmetric
 * form"); a membrane point's hoop strain follows its radius. */
void lm_axisym_elastic_update_at(lm_sim *sim, size_t q, const lm_rate *r)
{
    lm_particles *p = &sim->p;
    double deh = r->dt * r->hoop;
    p->rho[q] /= 1 + r->dexx + r->deyy + deh;
    elastic(sim->mats[p->mat[q]], r->dexx, r->deyy, r->dexy, deh, r->w, r->dt, &p->sxx[q],
            &p->syy[q], &p->sxy[q], &p->szz[q]);
}

void lm_axisym_membrane_update_at(lm_sim *sim, size_t q, const lm_rate *r)
{
    lm_particles *p = &sim->p;
    /* eps_t += t.de.t ([M] §3, docs/physics.md §2), the hoop from r */
    lm_axisym_membrane_set(sim, q, p->et[q] + p->tx[q] * p->tx[q] * r->dexx +
                                   2 * p->tx[q] * p->ty[q] * r->dexy +
                                   p->ty[q] * p->ty[q] * r->deyy);
}

void lm_axisym_gas_update_at(lm_sim *sim, size_t q, const lm_rate *r)
{
    lm_particles *p = &sim->p;
    const lm_material *mat = sim->mats[p->mat[q]];
    const double *L = r->L;
    double deh = r->dt * r->hoop;
    double div = L[0] + L[3] + r->hoop;
    p->rho[q] /= 1 + r->dexx + r->deyy + deh;   /* continuity only (sim.c) */
    p->q[q] = lm_gas_av(mat, p->rho[q], div, r->max_div, r->c_max, r->h);
    gas(mat, L[0], L[3], 0.5 * (L[1] + L[2]), r->hoop, r->dt, p->rho[q], p->q[q], &p->e[q],
        &p->sxx[q], &p->syy[q], &p->sxy[q], &p->szz[q]);
}

void lm_axisym_linear_fluid_update_at(lm_sim *sim, size_t q, const lm_rate *r)
{
    lm_particles *p = &sim->p;
    double deh = r->dt * r->hoop;
    p->rho[q] /= 1 + r->dexx + r->deyy + deh;
    p->ev[q] += r->dexx + r->deyy + deh;
    p->sxx[q] = p->syy[q] = p->szz[q] = sim->mats[p->mat[q]]->beta * p->ev[q];
    p->sxy[q] = 0;
}
