/* sim3_step.c - one explicit 3D MPM step: docs/physics.md §1 with a third
 * component, one phase per function as in step.c ([F] eqs 5-16, [M] eqs
 * 10-13 for MUSL, [N] §7 for USL). The weights are those at x^k, rebuilt
 * from the particle's place in each pass (sim3_shape.c). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mpm3.h"
#include "mpm3_membrane.h"
#include "sim3_walls.h"

#if defined(__GNUC__)
#define LM3_INLINE inline __attribute__((always_inline))
#else
#define LM3_INLINE inline
#endif

static const int comp_mpf[7] = {LM3_SCALAR, 0, 1, 2, 0, 1, 2};
static const int comp_vec[3] = {0, 1, 2};

/* Step 0 at one particle: its stencil at x^k, kept for the step's other
 * passes. */
static LM3_INLINE void place_at(lm3_sim *sim, size_t q)
{
    lm3_particles *p = &sim->p;
    double x[3] = {p->x[0][q], p->x[1][q], p->x[2][q]}, d[3];
    lm3_place(&sim->grid, x, &p->node[q], d);
    p->d[0][q] = d[0];
    p->d[1][q] = d[1];
    p->d[2][q] = d[2];
}

static LM3_INLINE void weights_of(const lm3_sim *sim, size_t q, lm3_weights *w)
{
    const lm3_particles *p = &sim->p;
    double d[3] = {p->d[0][q], p->d[1][q], p->d[2][q]};
    lm3_weights_at(&sim->grid, p->node[q], d, w);
}

/* Row (b, c) of a stencil: its first node and the y-z factors of N and of
 * the gradient's three components; node (a, b, c) is row.node + a, with
 * N = w[0][a] wyz and G = (g[0][a] wyz, w[0][a] gyz, w[0][a] wgz). */
typedef struct row3 {
    long node;
    double wyz, gyz, wgz;
} row3;
static LM3_INLINE row3 row_of(const lm3_grid *g, const lm3_weights *w, int b, int c)
{
    row3 r;
    r.node = w->node + (c * g->s[1] + b) * g->s[0];
    r.wyz = w->w[1][b] * w->w[2][c];
    r.gyz = w->g[1][b] * w->w[2][c];
    r.wgz = w->w[1][b] * w->g[2][c];
    return r;
}

/* Steps 1-2 at one particle, stencil W wide: m_i, p_i and
 * f_i^int = -V_p sigma_p . G_ip ([F] eq 9). */
static LM3_INLINE void p2g_at(const lm3_sim *sim, size_t q, const int W)
{
    const lm3_particles *p = &sim->p;
    const lm3_grid *g = &sim->grid;
    lm3_weights w;
    weights_of(sim, q, &w);
    const double m = p->m[q], V = m / p->rho[q];
    const double mv0 = m * p->v[0][q], mv1 = m * p->v[1][q], mv2 = m * p->v[2][q];
    const double sxx = p->s[0][q], syy = p->s[1][q], szz = p->s[2][q];
    const double syz = p->s[3][q], sxz = p->s[4][q], sxy = p->s[5][q];
    for (int c = 0; c < W; c++)
        for (int b = 0; b < W; b++) {
            const row3 r = row_of(g, &w, b, c);
            for (int a = 0; a < W; a++) {
                const long i = r.node + a;
                const double N = w.w[0][a] * r.wyz;
                const double gx = w.g[0][a] * r.wyz, gy = w.w[0][a] * r.gyz,
                             gz = w.w[0][a] * r.wgz;
                g->m[i] += N * m;
                g->p[0][i] += N * mv0;
                g->p[1][i] += N * mv1;
                g->p[2][i] += N * mv2;
                g->f[0][i] -= V * (sxx * gx + sxy * gy + sxz * gz);
                g->f[1][i] -= V * (sxy * gx + syy * gy + syz * gz);
                g->f[2][i] -= V * (sxz * gx + syz * gy + szz * gz);
            }
        }
}

/* Steps 0-2 in one pass over the particles (each particle's place, then
 * its sums), the ghosts folded, then f_i^ext = m_i g. */
static void step_p2g_forces(lm3_sim *sim)
{
    lm3_grid *g = &sim->grid;
    memset(g->m, 0, 10 * g->nn * sizeof(double));
    if (g->W == 2) {
        for (size_t q = 0; q < sim->p.n; q++) {
            place_at(sim, q);
            p2g_at(sim, q, 2);
        }
    } else {
        for (size_t q = 0; q < sim->p.n; q++) {
            place_at(sim, q);
            p2g_at(sim, q, 3);
        }
    }
    lm3_membrane_p2g(sim);   /* membrane points (sim3_membrane_step.c) */
    double *const f[7] = {g->m, g->p[0], g->p[1], g->p[2], g->f[0], g->f[1], g->f[2]};
    lm3_grid_fold(g, 7, f, comp_mpf);
    const double *gv = sim->def.gravity;
    for (size_t i = 0; i < g->nn; i++) {
        g->f[0][i] += g->m[i] * gv[0];
        g->f[1][i] += g->m[i] * gv[1];
        g->f[2][i] += g->m[i] * gv[2];
    }
}

/* Step 3: p_i^L = p_i + dt f_i ([F] eq 10); the walls act on both, then
 * a_i = f_i / m_i replaces f and v_i^L = p_i^L / m_i replaces p (zero at
 * massless nodes), ghosts filled for the gather. */
static void step_grid_update(lm3_sim *sim)
{
    lm3_grid *g = &sim->grid;
    const double dt = sim->def.dt;
    for (int a = 0; a < 3; a++)
        for (size_t i = 0; i < g->nn; i++) g->p[a][i] += dt * g->f[a][i];
    lm3_grid_apply_bc(g, g->p);
    lm3_grid_apply_bc(g, g->f);
    for (size_t i = 0; i < g->nn; i++) {
        double r = g->m[i] > 0 ? 1.0 / g->m[i] : 0;
        for (int a = 0; a < 3; a++) {
            g->f[a][i] *= r;
            g->p[a][i] *= r;
        }
    }
    double *const f[6] = {g->f[0], g->f[1], g->f[2], g->p[0], g->p[1], g->p[2]};
    static const int comp[6] = {0, 1, 2, 0, 1, 2};
    lm3_grid_fill(g, 6, f, comp);
}

/* Step 4 ([F] eq 12) at one particle: FLIP velocity from the nodal
 * accelerations, position from the Lagrangian velocity. */
static LM3_INLINE void g2p_at(lm3_sim *sim, size_t q, const int W)
{
    lm3_particles *p = &sim->p;
    const lm3_grid *g = &sim->grid;
    const double dt = sim->def.dt;
    lm3_weights w;
    weights_of(sim, q, &w);
    double a0 = 0, a1 = 0, a2 = 0, u0 = 0, u1 = 0, u2 = 0;
    for (int c = 0; c < W; c++)
        for (int b = 0; b < W; b++) {
            const long row = w.node + (c * g->s[1] + b) * g->s[0];
            const double wyz = w.w[1][b] * w.w[2][c];
            for (int a = 0; a < W; a++) {
                const long i = row + a;
                const double N = w.w[0][a] * wyz;
                a0 += N * g->f[0][i];
                a1 += N * g->f[1][i];
                a2 += N * g->f[2][i];
                u0 += N * g->p[0][i];
                u1 += N * g->p[1][i];
                u2 += N * g->p[2][i];
            }
        }
    p->v[0][q] += dt * a0;
    p->v[1][q] += dt * a1;
    p->v[2][q] += dt * a2;
    p->x[0][q] += dt * u0;
    p->x[1][q] += dt * u1;
    p->x[2][q] += dt * u2;
}

/* Step 5's MUSL re-map at one particle: m_p v_p^{k+1} N_ip into v. */
static LM3_INLINE void remap_at(lm3_sim *sim, size_t q, const int W)
{
    const lm3_particles *p = &sim->p;
    const lm3_grid *g = &sim->grid;
    lm3_weights w;
    weights_of(sim, q, &w);
    const double m = p->m[q];
    const double mv0 = m * p->v[0][q], mv1 = m * p->v[1][q], mv2 = m * p->v[2][q];
    for (int c = 0; c < W; c++)
        for (int b = 0; b < W; b++) {
            const long row = w.node + (c * g->s[1] + b) * g->s[0];
            const double wyz = w.w[1][b] * w.w[2][c];
            for (int a = 0; a < W; a++) {
                const double N = w.w[0][a] * wyz;
                g->v[0][row + a] += N * mv0;
                g->v[1][row + a] += N * mv1;
                g->v[2][row + a] += N * mv2;
            }
        }
}

/* Step 4 over the particles, then under MUSL step 5's re-map in a pass of
 * its own: one pass doing both (a particle's re-map needs only its own
 * new velocity) was measured slower, 5.1 against 5.3 M particle-steps/s
 * of CPU time (trilinear, docs/3d.md "Speed"): the gather's six fields
 * and the re-map's three compete for the cache. */
static void step_g2p_remap(lm3_sim *sim)
{
    lm3_grid *g = &sim->grid;
    const size_t n = sim->p.n;
    if (g->W == 2)
        for (size_t q = 0; q < n; q++) g2p_at(sim, q, 2);
    else
        for (size_t q = 0; q < n; q++) g2p_at(sim, q, 3);
    if (sim->def.scheme != LM_MUSL) return;
    memset(g->v[0], 0, 3 * g->nn * sizeof(double));
    if (g->W == 2)
        for (size_t q = 0; q < n; q++) remap_at(sim, q, 2);
    else
        for (size_t q = 0; q < n; q++) remap_at(sim, q, 3);
}

/* The end of step 5: the velocity the strain rate reads. MUSL ([M] eqs
 * 12-13): the re-mapped momenta folded, over m_i, walls again. USL
 * ([N] §7): v_i^L itself. */
static void step_strain_velocity(lm3_sim *sim)
{
    lm3_grid *g = &sim->grid;
    if (sim->def.scheme == LM_MUSL) {
        lm3_grid_fold(g, 3, g->v, comp_vec);
        for (size_t i = 0; i < g->nn; i++)
            if (g->m[i] > 0)
                for (int a = 0; a < 3; a++) g->v[a][i] /= g->m[i];
    } else {
        for (int a = 0; a < 3; a++) memcpy(g->v[a], g->p[a], g->nn * sizeof(double));
    }
    lm3_grid_apply_bc(g, g->v);
    lm3_grid_fill(g, 3, g->v, comp_vec);
}

/* Step 7 at one particle: L_ab = sum_i v_a,i G_b,ip. */
static LM3_INLINE void gradient_at(const lm3_sim *sim, size_t q, double L[9], const int W)
{
    const lm3_grid *g = &sim->grid;
    lm3_weights w;
    weights_of(sim, q, &w);
    for (int k = 0; k < 9; k++) L[k] = 0;
    for (int c = 0; c < W; c++)
        for (int b = 0; b < W; b++) {
            const row3 r = row_of(g, &w, b, c);
            for (int a = 0; a < W; a++) {
                const long i = r.node + a;
                const double G[3] = {w.g[0][a] * r.wyz, w.w[0][a] * r.gyz, w.w[0][a] * r.wgz};
                for (int e = 0; e < 3; e++) {
                    const double v = g->v[e][i];
                    L[3 * e] += v * G[0];
                    L[3 * e + 1] += v * G[1];
                    L[3 * e + 2] += v * G[2];
                }
            }
        }
}

/* Steps 7-8 ([F] eqs 14-20): de = dt/2 (L + L^T), W = 1/2 (L - L^T),
 * rho / (1 + tr de) ([F] eq 16), then the elastic law. 0 when a
 * particle's volume went to nothing. */
static int step_stress(lm3_sim *sim)
{
    lm3_particles *p = &sim->p;
    const double dt = sim->def.dt;
    for (size_t q = 0; q < p->n; q++) {
        double L[9], W[9], de[6], s[6];
        if (sim->grid.W == 2) gradient_at(sim, q, L, 2);
        else gradient_at(sim, q, L, 3);
        de[0] = dt * L[0];
        de[1] = dt * L[4];
        de[2] = dt * L[8];
        de[3] = 0.5 * dt * (L[5] + L[7]);
        de[4] = 0.5 * dt * (L[2] + L[6]);
        de[5] = 0.5 * dt * (L[1] + L[3]);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) W[3 * i + j] = 0.5 * (L[3 * i + j] - L[3 * j + i]);
        double J = 1 + de[0] + de[1] + de[2];
        if (!(J > 0)) return 0;
        p->rho[q] /= J;
        for (int c = 0; c < 6; c++) s[c] = p->s[c][q];
        lm3_elastic_update(&sim->mats[p->mat[q]], de, W, dt, s);
        for (int c = 0; c < 6; c++) p->s[c][q] = s[c];
    }
    return 1;
}

/* Every particle finite and inside the grid (the stencils of the next
 * step must lie on it); the message names the particle, where and when. */
static lm_status check(lm3_sim *sim)
{
    const lm3_particles *p = &sim->p;
    const lm3_grid *g = &sim->grid;
    for (size_t q = 0; q < p->n; q++)
        for (int a = 0; a < 3; a++) {
            double x = p->x[a][q];
            if (!isfinite(x) || !isfinite(p->v[a][q])) {
                snprintf(sim->err, sizeof sim->err,
                         "t = %g (step %ld): particle %zu has a non-finite position or "
                         "velocity: unstable (dt above the stable step?)", sim->t, sim->nstep, q);
                return LM_ERR_UNSTABLE;
            }
            if (!(x >= g->lo[a] && x <= g->lo[a] + g->n[a] * g->h)) {
                snprintf(sim->err, sizeof sim->err,
                         "t = %g (step %ld): particle %zu left the grid at %c = %g "
                         "(the domain is %g to %g)", sim->t, sim->nstep, q, "xyz"[a], x,
                         g->lo[a], g->lo[a] + g->n[a] * g->h);
                return LM_ERR_DOMAIN;
            }
        }
    return LM_OK;
}

double lm3_courant_limit(const lm3_sim *sim)
{
    double c = sim->def.courant > 0 ? sim->def.courant : 1.0;
    return c * LM3_COURANT_FACTOR * (sim->def.scheme == LM_USL ? LM_USL_COURANT : 1);
}

double lm3_courant(const lm3_sim *sim, double *c_max)
{
    double c = 0;
    for (int k = 0; k < sim->nmat; k++) {
        const lm3_material *m = &sim->mats[k];
        double G = m->E / (2 * (1 + m->nu)), lam = m->E * m->nu / ((1 + m->nu) * (1 - 2 * m->nu));
        double ck = sqrt((lam + 2 * G) / m->rho);
        if (ck > c) c = ck;
    }
    double cm = lm3_membrane_wave_speed(sim);
    if (cm > c) c = cm;
    if (c_max) *c_max = c;
    return sim->def.dt * c / sim->grid.h;
}

lm_status lm3_step(lm3_sim *sim)
{
    if (sim->nstep == 0) {
        double c, cn = lm3_courant(sim, &c), lim = lm3_courant_limit(sim);
        if (cn > lim) {
            snprintf(sim->err, sizeof sim->err,
                     "dt = %g: the Courant number dt c / h = %g (c = %g, h = %g) is above the "
                     "limit %g; take dt <= %g or raise courant", sim->def.dt, cn, c,
                     sim->grid.h, lim, lim * sim->grid.h / c);
            return LM_ERR_INPUT;
        }
    }
    lm_status st = check(sim);
    if (st != LM_OK) return st;
    step_p2g_forces(sim);
    step_grid_update(sim);
    lm3_membrane_hold(sim);
    step_g2p_remap(sim);
    lm3_membrane_g2p(sim);
    step_strain_velocity(sim);
    st = lm3_membrane_update(sim);
    if (st != LM_OK) return st;
    if (!step_stress(sim)) {
        snprintf(sim->err, sizeof sim->err, "t = %g (step %ld): a particle's volume went to "
                 "nothing (1 + tr de <= 0): unstable", sim->t, sim->nstep);
        return LM_ERR_UNSTABLE;
    }
    sim->nstep++;
    sim->t = sim->nstep * sim->def.dt;   /* from the count, as in 2D */
    return check(sim);
}
