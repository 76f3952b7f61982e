/* membrane.c - membranes and strings: one layer of points carrying stress in
 * their local tangent frame ([M] §3, [F] §3.2, [T] §5.1, physics.md §2).
 *
 * The objective form: eps_t accumulates t.de.t with the current unit tangent
 * (t.D.t is the stretching rate along the membrane); sigma is rebuilt from
 * sigma_t every step and never rotated as increments ([T] §5.1's warning).
 * Accumulating t.de.t = dl/l makes eps_t the logarithmic strain of the
 * point's length: l = ds exp(eps_t) for a point of unstrained length ds.
 * Its volume is thickness * ds * exp(eps_t) (physics.md writes the
 * small-strain form thickness * ds * (1 + eps_t); the two differ only for
 * large slack, such as the dog-bone's), never updated from tr(de), which
 * would include the gas's strain across the membrane. */
#include <math.h>

#include "step.h"

static void tangent_of(const lm_particles *p, size_t a, size_t b, double *tx, double *ty)
{
    double dx = p->x[b] - p->x[a], dy = p->y[b] - p->y[a];
    double l = sqrt(dx * dx + dy * dy);
    if (l > 0) {
        *tx = dx / l;
        *ty = dy / l;
    }
    /* coincident neighbours: keep the previous tangent */
}

void lm_membrane_tangents(lm_sim *sim)
{
    lm_particles *p = &sim->p;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        if (!bd->membrane || bd->count < 2) continue;
        size_t first = bd->first, last = bd->first + bd->count - 1;
        for (size_t q = first; q <= last; q++) {
            size_t prev = q > first ? q - 1 : (bd->closed ? last : q);
            size_t next = q < last ? q + 1 : (bd->closed ? first : q);
            tangent_of(p, prev, next, &p->tx[q], &p->ty[q]);
        }
    }
}

/* [T] eq 5.9 (uniaxial) and 5.15 (plane stress); [M] §3.2 / Fig 13 the
 * one-way law: E_t = 0 while eps_t < 0, the compressive strain kept. */
double lm_membrane_stress(const lm_material *mat, double et)
{
    if (mat->one_way && et < 0) return 0;
    if (mat->law == LM_LAW_PLANE_STRESS) return mat->E * et / (1 - mat->nu * mat->nu);
    return mat->E * et;
}

static void rebuild(const lm_material *mat, double st, double tx, double ty,
                    double *sxx, double *syy, double *sxy, double *szz)
{
    *sxx = st * tx * tx;
    *syy = st * ty * ty;
    *sxy = st * tx * ty;
    *szz = mat->law == LM_LAW_PLANE_STRESS ? mat->nu * st : 0;
}

void lm_membrane_update(const lm_material *mat, double dexx, double deyy, double dexy,
                        double tx, double ty, double m, double ds, double *et,
                        double *rho, double *sxx, double *syy, double *sxy, double *szz)
{
    *et += tx * tx * dexx + 2 * tx * ty * dexy + ty * ty * deyy;
    rebuild(mat, lm_membrane_stress(mat, *et), tx, ty, sxx, syy, sxy, szz);
    *rho = m / (mat->thickness * ds * exp(*et));
}

double lm_membrane_energy(const lm_material *mat, double V, double et)
{
    return 0.5 * V * lm_membrane_stress(mat, et) * et;
}

void lm_membrane_prepare(lm_sim *sim)
{
    lm_particles *p = &sim->p;
    lm_membrane_tangents(sim);
    for (size_t q = 0; q < p->n; q++) {
        const lm_material *mat = sim->mats[p->mat[q]];
        if (mat->kind != LM_MEMBRANE) continue;
        rebuild(mat, lm_membrane_stress(mat, p->et[q]), p->tx[q], p->ty[q],
                &p->sxx[q], &p->syy[q], &p->sxy[q], &p->szz[q]);
    }
}
