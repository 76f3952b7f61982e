/* sim3_query.c - what the Lua layer reads of a 3D run: a body's sums (its
 * particles are a contiguous range, as the 2D bodies'), the state's hash
 * and the bytes its arrays take (docs/3d.md "Memory"). */
#include <math.h>

#include "mpm3.h"
#include "mpm3_membrane.h"
#include "util.h"

void lm3_range_sums(const lm3_sim *sim, size_t first, size_t n, double *mass, double com[3],
                    double vel[3])
{
    const lm3_particles *p = &sim->p;
    double m = 0, mx[3] = {0, 0, 0}, mv[3] = {0, 0, 0};
    for (size_t q = first; q < first + n; q++) {
        m += p->m[q];
        for (int a = 0; a < 3; a++) {
            mx[a] += p->m[q] * p->x[a][q];
            mv[a] += p->m[q] * p->v[a][q];
        }
    }
    *mass = m;
    for (int a = 0; a < 3; a++) {
        com[a] = m > 0 ? mx[a] / m : 0;
        vel[a] = m > 0 ? mv[a] / m : 0;
    }
}

void lm3_range_energy(const lm3_sim *sim, size_t first, size_t n, lm3_energy *e)
{
    /* lm3_energy_of over a window of the arrays: the same sums in the same
     * order, so the bodies' energies add up to the sim's to rounding */
    lm3_sim view = *sim;
    lm3_particles *p = &view.p;
    for (int a = 0; a < 3; a++) {
        p->x[a] += first;
        p->v[a] += first;
    }
    for (int c = 0; c < 6; c++) p->s[c] += first;
    p->m += first;
    p->rho += first;
    p->e += first;
    p->mat += first;
    p->n = n;
    lm3_energy_of(&view, e);
}

uint64_t lm3_sim_hash(const lm3_sim *sim)
{
    const lm3_particles *p = &sim->p;
    uint64_t h = LU_FNV_SEED;
    const double *f[] = {p->x[0], p->x[1], p->x[2], p->v[0], p->v[1], p->v[2], p->rho,
                         p->s[0], p->s[1], p->s[2], p->s[3], p->s[4], p->s[5], p->e};
    for (size_t k = 0; k < sizeof f / sizeof f[0]; k++)
        if (p->n) h = lu_fnv1a(h, f[k], p->n * sizeof(double));
    /* the membrane points' state too (issue 34 item 2), folded only when
     * there are some, so a sim without membranes keeps its hash */
    const lm3_mpoints *q = sim->mem ? &sim->mem->p : NULL;
    if (q && q->n) {
        const double *g[] = {q->x[0], q->x[1], q->x[2], q->v[0], q->v[1], q->v[2],
                             q->e[0], q->e[1], q->e[2], q->s[0], q->s[1], q->s[2]};
        for (size_t k = 0; k < sizeof g / sizeof g[0]; k++)
            h = lu_fnv1a(h, g[k], q->n * sizeof(double));
    }
    h = lu_fnv1a(h, &sim->nstep, sizeof sim->nstep);
    return h;
}

size_t lm3_def_grid_bytes(const lm3_def *d)
{
    /* the node count lm3_sim_create will make (sim3.c: n cells, n + 1 nodes
     * and the ring of the quadratic B-spline each way); 0 when it will
     * refuse the definition anyway */
    if (!(d->cell > 0) || !isfinite(d->cell)) return 0;
    size_t nn = 1;
    int pad = d->basis == LM_BASIS_LINEAR ? 0 : 1;
    for (int a = 0; a < 3; a++) {
        double c = (d->hi[a] - d->lo[a]) / d->cell;
        if (!isfinite(c) || !(c >= 1) || c > 1e6) return 0;
        nn *= (size_t)floor(c + 0.5) + 1 + 2 * (size_t)pad;
        if (nn > LM3_MAX_NODES) return 0;
    }
    return 10 * nn * sizeof(double);
}

size_t lm3_grid_bytes(const lm3_sim *sim)
{
    return 10 * sim->grid.nn * sizeof(double);
}

size_t lm3_particle_bytes(size_t cap)
{
    /* x, v (6), m, rho, sigma (6), d (3): 17 doubles; node, material */
    return cap * (17 * sizeof(double) + sizeof(int32_t) + sizeof(uint8_t));
}
