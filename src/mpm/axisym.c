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

#include "step.h"

/* sum_i N_ip v_ri with the strain velocity (step 5), stencil W wide. */
static inline double radial_velocity(const lm_sim *sim, size_t q)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const int W = g->sw, NS = W * W;
    const double *N = p->N + (size_t)NS * q;
    double u = 0;
    for (int k = 0; k < NS; k++) u += N[k] * g->vx[lm_stencil_node(g, W, p->node[q], k)];
    return u;
}

double lm_axisym_hoop_rate(const lm_sim *sim, size_t q)
{
    double r = sim->p.x[q];
    return r > 0 ? radial_velocity(sim, q) / r : 0;
}

double lm_axisym_ring_radius(double r, double l)
{
    /* a point on the axis stands for the disc of its half segment, whose
     * centroid radius is l / 4 (int_0^{l/2} s ds / (l/2)) */
    return r > 0 ? r : 0.25 * l;
}

/* Is q a membrane point whose tension acts along segments? */
static int segment_point(const lm_sim *sim, size_t q)
{
    const lm_body *bd = &sim->bodies[sim->p.body[q]];
    return bd->membrane && bd->force == LM_MFORCE_SEGMENT;
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
    double et = p->et[q], eh = lm_axisym_membrane_hoop(p, q), st, sh;
    lm_membrane_stress_biaxial(mat, et, eh, &st, &sh);
    return 0.5 * (p->m[q] / p->rho[q]) * (st * et + sh * eh);
}

/* ---- step 2: the hoop term of the internal force ------------------------ */

void lm_axisym_forces(lm_sim *sim)
{
    lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const int W = g->sw, NS = W * W;
    for (size_t q = 0; q < p->n; q++) {
        double r = p->x[q];
        if (!(r > 0)) continue;   /* on the axis: see the head of the file */
        const lm_material *mat = sim->mats[p->mat[q]];
        double c;
        if (mat->kind == LM_MEMBRANE) {
            /* V / r = thickness * l for a ring off the axis; a segment
             * point's eps_t is its segments' mean, its l their mean share */
            c = -p->szz[q] * mat->thickness * p->ds[q] * exp(p->et[q]);
        } else {
            c = -(p->m[q] / p->rho[q]) * p->szz[q] / r;
        }
        const double *N = p->N + (size_t)NS * q;
        for (int k = 0; k < NS; k++) g->fx[lm_stencil_node(g, W, p->node[q], k)] += c * N[k];
    }
    /* the ghost nodes were emptied by the in-plane scatter's fold: this
     * folds only the hoop terms (the x image is odd across the axis) */
    double *const f[1] = {g->fx};
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

void lm_axisym_stress(lm_sim *sim, size_t q, const double L[4], double max_div, double c_max,
                      double h)
{
    lm_particles *p = &sim->p;
    const lm_material *mat = sim->mats[p->mat[q]];
    double dt = sim->def.dt;
    double Dh = lm_axisym_hoop_rate(sim, q);
    double dexx = dt * L[0], deyy = dt * L[3], deh = dt * Dh;
    double dexy = 0.5 * dt * (L[1] + L[2]);
    double w = 0.5 * (L[1] - L[2]);
    switch (mat->kind) {
    case LM_ELASTIC:
        p->rho[q] /= 1 + dexx + deyy + deh;
        elastic(mat, dexx, deyy, dexy, deh, w, dt, &p->sxx[q], &p->syy[q], &p->sxy[q],
                &p->szz[q]);
        break;
    case LM_MEMBRANE:
        if (segment_point(sim, q)) break;   /* from lengths (membrane_force.c) */
        /* eps_t += t.de.t ([M] §3, docs/physics.md §2), the hoop from r */
        lm_axisym_membrane_set(sim, q, p->et[q] + p->tx[q] * p->tx[q] * dexx +
                                       2 * p->tx[q] * p->ty[q] * dexy +
                                       p->ty[q] * p->ty[q] * deyy);
        break;
    case LM_GAS: {
        double div = L[0] + L[3] + Dh;
        p->rho[q] /= 1 + dexx + deyy + deh;   /* continuity only (l_body.c) */
        p->q[q] = lm_gas_av(mat, p->rho[q], div, max_div, c_max, h);
        gas(mat, L[0], L[3], 0.5 * (L[1] + L[2]), Dh, dt, p->rho[q], p->q[q], &p->e[q],
            &p->sxx[q], &p->syy[q], &p->sxy[q], &p->szz[q]);
        break;
    }
    case LM_LINEAR_FLUID:
        p->rho[q] /= 1 + dexx + deyy + deh;
        p->ev[q] += dexx + deyy + deh;
        p->sxx[q] = p->syy[q] = p->szz[q] = mat->beta * p->ev[q];
        p->sxy[q] = 0;
        break;
    }
}
