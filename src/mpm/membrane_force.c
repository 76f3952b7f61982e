/* membrane_force.c - a membrane's tension integrated along its segments
 * (lamina's remedy for cell-crossing noise; docs/physics.md §5b, issue 13).
 *
 * The papers send a membrane point's stress to the grid by point
 * quadrature, f_i = -V_p sigma_p . G_ip ([M] eq 9, [F] eq 9). With the
 * bilinear basis G_ip jumps when a point crosses a cell edge ([T] §5.4.3,
 * A.2), and a straight membrane at rest is not in discrete equilibrium:
 * the nodal forces of its points do not cancel.
 *
 * Here the membrane between neighbouring points a, b is a straight segment
 * carrying the tension F = sigma_t(eps) * thickness (per unit depth) of its
 * own logarithmic strain eps = ln(l / L0). The internal force is
 *   f_i = -int F t (t . grad N_i) ds = -F t [N_i(b) - N_i(a)],
 * so each point gets the net pull of its two segments, g_a = F_ab t_ab -
 * F_za t_za, spread to the nodes with N_ia. For a uniformly stretched
 * straight membrane g vanishes at every interior point (the sums
 * telescope), so only the ends load the grid; and since N_i is continuous
 * where grad N_i jumps, a point crossing a cell edge gives no kick. The
 * order of the points (connectivity) is used for the force only; the
 * normals can still come from the construction without it.
 *
 * The strain is the segment's length, not an accumulation of t.de.t, so it
 * is objective and holds no drift; the one-way (wrinkle) law applies to it
 * as to the points' ([M] §3.2). A point's eps_t, stress and volume, which
 * diagnostics and drawing read, are the mean of its segments'. */
#include <math.h>
#include <stdio.h>

#include "contact.h"
#include "gather.h"
#include "membrane_law.h"
#include "step.h"

/* Neighbour after q in curve order, or SIZE_MAX at an open end. */
static size_t next_of(const lm_body *bd, size_t q)
{
    size_t last = bd->first + bd->count - 1;
    if (q < last) return q + 1;
    return bd->closed && bd->count > 2 ? bd->first : (size_t)-1;
}

static double seg_len(const lm_particles *p, size_t a, size_t b)
{
    return hypot(p->x[b] - p->x[a], p->y[b] - p->y[a]);
}

static int segment_body(const lm_sim *sim, int b)
{
    const lm_body *bd = &sim->bodies[b];
    return bd->membrane && bd->force == LM_MFORCE_SEGMENT && bd->count >= 2;
}

/* Each segment's unstrained length from the present length and the two
 * points' initial strains (strains are logarithmic: l = L0 exp(eps)),
 * once per body: a later prepare (another body added) keeps them. */
void lm_membrane_segment_prepare(lm_sim *sim)
{
    lm_particles *p = &sim->p;
    for (int b = 0; b < sim->nbodies; b++) {
        if (!segment_body(sim, b) || sim->bodies[b].seg_ready) continue;
        lm_body *bd = &sim->bodies[b];
        bd->seg_ready = 1;
        for (size_t q = bd->first; q < bd->first + bd->count; q++) {
            size_t r = next_of(bd, q);
            p->L0[q] = r == (size_t)-1 ? 0
                     : seg_len(p, q, r) * exp(-0.5 * (p->et[q] + p->et[r]));
        }
    }
}

/* Axisymmetric form (axisym.c): the segment is a conical band; its
 * tension per radian is sigma_t thickness r_m at its mid radius r_m, with
 * sigma_t of the biaxial law at its own meridional strain ln(l / L0) and
 * hoop strain ln(r_m / r0_m) (r0 the points' unstrained ring radii; a
 * segment ending on the axis has r0_m > 0). The hoop stress's own pull
 * toward the axis is the point term of lm_axisym_forces. */
static double segment_ring_tension(const lm_particles *p, const lm_material *mat, size_t q,
                                   size_t r, double l)
{
    double rm = 0.5 * (p->x[q] + p->x[r]), r0m = 0.5 * (p->r0[q] + p->r0[r]);
    double et = log(l / p->L0[q]), st, sh;
    lm_membrane_stress_biaxial(mat, et, r0m > 0 && rm > 0 ? log(rm / r0m) : et, &st, &sh);
    return st * mat->thickness * rm;
}

/* Runs `pass` on every segment body with its material: the force and the
 * strain passes visit the same bodies. */
static void each_segment_body(lm_sim *sim,
                              void (*pass)(lm_sim *, const lm_body *, const lm_material *))
{
    for (int b = 0; b < sim->nbodies; b++)
        if (segment_body(sim, b)) pass(sim, &sim->bodies[b], sim->mats[sim->bodies[b].mat]);
}

/* The net tension of each point's two segments at x^k: (fpx, fpy). */
static void body_forces(lm_sim *sim, const lm_body *bd, const lm_material *mat)
{
    lm_particles *p = &sim->p;
    for (size_t q = bd->first; q < bd->first + bd->count; q++) p->fpx[q] = p->fpy[q] = 0;
    for (size_t q = bd->first; q < bd->first + bd->count; q++) {
        size_t r = next_of(bd, q);
        if (r == (size_t)-1 || !(p->L0[q] > 0)) continue;
        double l = seg_len(p, q, r);
        if (!(l > 0)) continue;   /* coincident points: no direction */
        double F = lm_membrane_stress(mat, log(l / p->L0[q])) * mat->thickness;
        if (sim->def.axisym) F = segment_ring_tension(p, mat, q, r, l);
        double tx = (p->x[r] - p->x[q]) / l, ty = (p->y[r] - p->y[q]) / l;
        p->fpx[q] += F * tx;
        p->fpy[q] += F * ty;
        p->fpx[r] -= F * tx;
        p->fpy[r] -= F * ty;
    }
}

void lm_membrane_segment_forces(lm_sim *sim)
{
    each_segment_body(sim, body_forces);
}

/* MUSL moves a point with the Lagrangian grid velocity v^L (step 4) but
 * carries into the next step, through FLIP and the re-map, a velocity
 * whose nodal increment is smoothed by the consistent-to-lumped mass ratio
 * M_L^-1 (sum_p N_ip m_p N_jp) < 1 for the short waves. The papers' point
 * strain follows the re-mapped velocity (step 5, [M] eqs 12-13), so its
 * work matches the kinetic energy the particles keep; a segment's strain
 * follows the positions, and moving them with v^L instead loses the
 * difference every step: a free string ringing lengthwise lost 7 % of its
 * energy in 0.1 s, a slack dog-bone 14 % as it snapped taut
 * (docs/robustness.md). So under MUSL a segment membrane's points move with
 * the re-mapped velocity, the one whose gradient gives the point form its
 * strain: (fpx, fpy), spent once step 2 spread them, keep x^k until then. */
static int musl_moves(const lm_sim *sim, int b)
{
    return sim->def.scheme == LM_MUSL && segment_body(sim, b);
}

void lm_membrane_segment_hold(lm_sim *sim)
{
    lm_particles *p = &sim->p;
    for (int b = 0; b < sim->nbodies; b++) {
        if (!musl_moves(sim, b)) continue;
        const lm_body *bd = &sim->bodies[b];
        for (size_t q = bd->first; q < bd->first + bd->count; q++) {
            p->fpx[q] = p->x[q];
            p->fpy[q] = p->y[q];
        }
    }
}

/* sum_i N_iq v_i, row by row for the 3 x 3 stencils as step 4 sums (a
 * point on a fixed wall then stays put to the last bit). */
static void remapped_velocity(const lm_sim *sim, size_t q, double *ux, double *uy)
{
    const lm_grid *g = &sim->grid;
    lm_weights wt;
    lm_weights_of(sim, q, &wt);
    *ux = lm_gather_rows(g, &wt, sim->p.node[q], g->vx);
    *uy = lm_gather_rows(g, &wt, sim->p.node[q], g->vy);
}

void lm_membrane_segment_move(lm_sim *sim)
{
    lm_particles *p = &sim->p;
    double dt = sim->def.dt;
    const int moved = lm_contact_moved(sim->contact);   /* bodies in own fields */
    for (int b = 0; b < sim->nbodies; b++) {
        if (!musl_moves(sim, b)) continue;
        const lm_body *bd = &sim->bodies[b];
        for (size_t q = bd->first; q < bd->first + bd->count; q++) {
            double ux, uy;
            remapped_velocity(sim, q, &ux, &uy);
            if (moved) lm_contact_velocity(sim, q, &ux, &uy);
            if (p->pin[q] && sim->pins[p->pin[q] - 1].point) {
                /* a pinned point moves with its pin exactly (pin.c) */
                ux = p->vx[q];
                uy = p->vy[q];
            }
            p->x[q] = p->fpx[q] + dt * ux;
            p->y[q] = p->fpy[q] + dt * uy;
        }
    }
}

/* After the positions moved: each point's eps_t is the mean of its
 * segments' strains, its stress sigma_t t(x)t along its tangent and its
 * volume thickness * ds * exp(eps_t), for diagnostics and drawing. */
static void body_strains(lm_sim *sim, const lm_body *bd, const lm_material *mat)
{
    lm_particles *p = &sim->p;
    size_t last = bd->first + bd->count - 1;
    for (size_t q = bd->first; q <= last; q++) {
        double sum = 0;
        int k = 0;
        size_t r = next_of(bd, q);
        if (r != (size_t)-1 && p->L0[q] > 0) {
            sum += log(seg_len(p, q, r) / p->L0[q]);
            k++;
        }
        size_t z = q > bd->first ? q - 1 : (bd->closed && bd->count > 2 ? last : (size_t)-1);
        if (z != (size_t)-1 && p->L0[z] > 0) {
            sum += log(seg_len(p, z, q) / p->L0[z]);
            k++;
        }
        if (k == 0 || !isfinite(sum)) continue;
        double et = sum / k;
        if (sim->def.axisym) {   /* a ring: the hoop too (axisym.c) */
            lm_axisym_membrane_set(sim, q, et);
            continue;
        }
        lm_membrane_set_strain(mat, et, p->tx[q], p->ty[q], p->m[q], p->ds[q], &p->et[q],
                               &p->rho[q], &p->sxx[q], &p->syy[q], &p->sxy[q], &p->szz[q]);
    }
}

void lm_membrane_segment_strains(lm_sim *sim)
{
    each_segment_body(sim, body_strains);
}

/* Stored energy of the segments: thickness * int sigma(eps) dl with
 * l = L0 exp(eps), the work of the force F = sigma thickness, as the law
 * gives it (membrane_law.h: thickness L0 W(lambda); for the linear law
 * E' L0 thickness [(eps - 1) e^eps + 1] ~ 1/2 E' A L0 eps^2). */
double lm_membrane_segment_energy(const lm_sim *sim, int b)
{
    if (!segment_body(sim, b)) return 0;
    if (sim->def.axisym) {
        /* rings: the points' biaxial energy (lm_axisym_membrane_energy), the
         * small-strain form of the band's */
        double w = 0;
        const lm_body *bd = &sim->bodies[b];
        for (size_t q = bd->first; q < bd->first + bd->count; q++)
            w += lm_axisym_membrane_energy(sim, q);
        return w;
    }
    const lm_particles *p = &sim->p;
    const lm_body *bd = &sim->bodies[b];
    const lm_material *mat = sim->mats[bd->mat];
    double w = 0;
    for (size_t q = bd->first; q < bd->first + bd->count; q++) {
        size_t r = next_of(bd, q);
        if (r == (size_t)-1 || !(p->L0[q] > 0)) continue;
        double eps = log(seg_len(p, q, r) / p->L0[q]);
        w += lm_membrane_segment_energy_of(mat, p->L0[q], eps);
    }
    return w;
}

/* The points of segment membrane b slack by more than 1 % (eps_t < -0.01),
 * and in *taut those stretched. The grid moves a cell's points affinely,
 * so points bunched closer than it resolves stay bunched, and their
 * segments carry nothing while the rest hold the load (docs/robustness.md
 * "The dog-bone with segment forces"): many slack points beside taut ones
 * is that sign. 0 for other bodies. */
size_t lm_membrane_segment_slack(const lm_sim *sim, int b, size_t *taut)
{
    size_t slack = 0;
    *taut = 0;
    if (b < 0 || b >= sim->nbodies || !segment_body(sim, b)) return 0;
    const lm_body *bd = &sim->bodies[b];
    for (size_t q = bd->first; q < bd->first + bd->count; q++) {
        slack += sim->p.et[q] < -0.01;
        *taut += sim->p.et[q] > 0;
    }
    return slack;
}

/* docs/physics.md §2: neighbouring membrane points must never be more than a
 * cell or so apart, or the grid no longer sees the membrane between them
 * and gas passes through. Two cells apart is reported as a tear. */
lm_status lm_membrane_check_torn(lm_sim *sim)
{
    const lm_particles *p = &sim->p;
    double lim = 2 * fmax(sim->grid.hx, sim->grid.hy);
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        if (!bd->membrane || bd->count < 2) continue;
        for (size_t q = bd->first; q < bd->first + bd->count; q++) {
            size_t r = next_of(bd, q);
            if (r == (size_t)-1) continue;
            double l = seg_len(p, q, r);
            if (!(l > lim)) continue;
            char who[96];
            snprintf(sim->err, sizeof sim->err,
                     "at t = %.6g (step %ld): %s tore between its points %zu and %zu "
                     "(%.3g cells apart, at (%.6g, %.6g) and (%.6g, %.6g)); likely cause: "
                     "cell-crossing noise or a load the membrane cannot carry (try "
                     "sim:membrane{force = \"segment\"}, a smaller dt or a finer spacing)",
                     sim->t, sim->step, lm_body_label(sim, b, who, sizeof who),
                     q - bd->first + 1, r - bd->first + 1,
                     l / fmax(sim->grid.hx, sim->grid.hy), p->x[q], p->y[q], p->x[r], p->y[r]);
            return LM_ERR_UNSTABLE;
        }
    }
    return LM_OK;
}
