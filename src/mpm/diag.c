/* diag.c - energies, centres of mass, momentum, the state hash. */
#include <string.h>

#include "step.h"

/* physics.md §1: kinetic sum 1/2 m v^2; strain sum V 1/2 sigma:C^-1:sigma
 * (from the stress, so it stays objective); potential -sum m g.x with the
 * initial positions as datum. */
lm_energy lm_sim_energy(const lm_sim *sim)
{
    lm_energy e = {0, 0, 0, 0, 0};
    const lm_particles *p = &sim->p;
    double gx = 0;
    for (size_t q = 0; q < p->n; q++) {
        e.kinetic += 0.5 * p->m[q] * (p->vx[q] * p->vx[q] + p->vy[q] * p->vy[q]);
        const lm_material *mat = sim->mats[p->mat[q]];
        double V = p->m[q] / p->rho[q];
        switch (mat->kind) {
        case LM_ELASTIC:
            e.strain += V * lm_elastic_energy_density(mat, p->sxx[q], p->syy[q],
                                                      p->sxy[q], p->szz[q]);
            break;
        case LM_MEMBRANE:
            e.strain += lm_membrane_energy(mat, V, p->et[q]);
            break;
        case LM_GAS:
            e.internal += p->m[q] * p->e[q];
            break;
        case LM_LINEAR_FLUID:
            /* stored energy of p = -beta div U: 1/2 beta ev^2 per unit of
             * the undeformed volume */
            e.strain += 0.5 * mat->beta * p->ev[q] * p->ev[q] * V / (1 + p->ev[q]);
            break;
        }
        gx += p->m[q] * (sim->def.gx * p->x[q] + sim->def.gy * p->y[q]);
    }
    e.potential = sim->pe_ref - gx;
    e.total = e.kinetic + e.strain + e.internal + e.potential;
    return e;
}

static void range(const lm_sim *sim, int body, size_t *a, size_t *b)
{
    if (body < 0) {
        *a = 0;
        *b = sim->p.n;
    } else {
        *a = sim->bodies[body].first;
        *b = *a + sim->bodies[body].count;
    }
}

double lm_body_mass(const lm_sim *sim, int body)
{
    size_t a, b;
    range(sim, body, &a, &b);
    double m = 0;
    for (size_t q = a; q < b; q++) m += sim->p.m[q];
    return m;
}

static void weighted(const lm_sim *sim, int body, const double *u,
                     const double *v, double *ou, double *ov)
{
    size_t a, b;
    range(sim, body, &a, &b);
    double m = 0, su = 0, sv = 0;
    for (size_t q = a; q < b; q++) {
        m += sim->p.m[q];
        su += sim->p.m[q] * u[q];
        sv += sim->p.m[q] * v[q];
    }
    *ou = m > 0 ? su / m : 0;
    *ov = m > 0 ? sv / m : 0;
}

void lm_body_com(const lm_sim *sim, int body, double *x, double *y)
{
    weighted(sim, body, sim->p.x, sim->p.y, x, y);
}

void lm_body_velocity(const lm_sim *sim, int body, double *vx, double *vy)
{
    weighted(sim, body, sim->p.vx, sim->p.vy, vx, vy);
}

void lm_sim_momentum(const lm_sim *sim, double *px, double *py)
{
    double sx = 0, sy = 0;
    for (size_t q = 0; q < sim->p.n; q++) {
        sx += sim->p.m[q] * sim->p.vx[q];
        sy += sim->p.m[q] * sim->p.vy[q];
    }
    *px = sx;
    *py = sy;
}

static uint64_t fnv1a(uint64_t h, const void *data, size_t n)
{
    const unsigned char *c = data;
    for (size_t k = 0; k < n; k++) {
        h ^= c[k];
        h *= 1099511628211ull;
    }
    return h;
}

uint64_t lm_sim_hash(const lm_sim *sim)
{
    const lm_particles *p = &sim->p;
    uint64_t h = 14695981039346656037ull;
    const double *f[] = {p->x, p->y, p->vx, p->vy, p->rho,
                         p->sxx, p->syy, p->sxy, p->szz, p->et, p->e, p->ev};
    for (size_t k = 0; k < sizeof f / sizeof f[0]; k++)
        if (p->n) h = fnv1a(h, f[k], p->n * sizeof(double));
    h = fnv1a(h, &sim->step, sizeof sim->step);
    return h;
}
