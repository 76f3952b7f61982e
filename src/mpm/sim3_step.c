/* sim3_step.c - one explicit 3D MPM step: docs/physics.md §1 with a third
 * component, one phase per function as in step.c ([F] eqs 5-16, [M] eqs
 * 10-13 for MUSL, [N] §7 for USL). The weights are those at x^k, rebuilt
 * from the particle's place in each pass (sim3_shape.c). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mpm3.h"
#include "sim3_elastic.h"
#include "sim3_kernels2.h"
#include "sim3_shape.h"
#include "sim3_simd.h"
#include "sim3_threads.h"
#include "mpm3_membrane.h"
#include "sim3_walls.h"

#if defined(__GNUC__)
#define LM3_INLINE inline __attribute__((always_inline))
#else
#define LM3_INLINE inline
#endif

/* A loop over particles or nodes on the step's threads: each iteration
 * writes only its own particle or node, so any split gives the same bits
 * (the scatters are sim3_threads.c's). */
#ifdef _OPENMP
#define LM3_PAR(nt) _Pragma("omp parallel for num_threads(nt) schedule(static) if (nt > 1)")
#else
#define LM3_PAR(nt)
#endif

static const int comp_mpf[7] = {LM3_SCALAR, 0, 1, 2, 0, 1, 2};
static const int comp_vec[3] = {0, 1, 2};

/* Step 0 at one particle: its stencil at x^k, kept for the step's other
 * passes. */
static LM3_INLINE void place_at(lm3_sim *sim, size_t q, const int W)
{
    lm3_particles *p = &sim->p;
    double x[3] = {p->x[0][q], p->x[1][q], p->x[2][q]}, d[3];
    lm3_place_w(&sim->grid, x, &p->node[q], d, W);
    p->d[0][q] = d[0];
    p->d[1][q] = d[1];
    p->d[2][q] = d[2];
}

static LM3_INLINE void weights_of(const lm3_sim *sim, size_t q, lm3_weights *w, const int W)
{
    const lm3_particles *p = &sim->p;
    double d[3] = {p->d[0][q], p->d[1][q], p->d[2][q]};
    lm3_weights_w(&sim->grid, p->node[q], d, w, W);
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
 * f_i^int = -V_p sigma_p . G_ip ([F] eq 9). With G = (g0[a] wyz,
 * w0[a] gyz, w0[a] wgz) the force on node a of a row is
 * -(A g0[a] + B w0[a]) per component, A = V sigma_.x wyz and B =
 * V (sigma_.y gyz + sigma_.z wgz) made once a row: 2 multiplications and
 * an addition a component a node instead of 7 (docs/3d.md "Speed"; the
 * sum's order, not its terms, differs from the node-by-node form). */
static LM3_INLINE void p2g_at(const lm3_sim *sim, const lm3_grid *g, size_t q, const int W)
{
    const lm3_particles *p = &sim->p;
    lm3_weights w;
    weights_of(sim, q, &w, W);
    const double m = p->m[q], V = m / p->rho[q];
    const double mv0 = m * p->v[0][q], mv1 = m * p->v[1][q], mv2 = m * p->v[2][q];
    const double sxx = V * p->s[0][q], syy = V * p->s[1][q], szz = V * p->s[2][q];
    const double syz = V * p->s[3][q], sxz = V * p->s[4][q], sxy = V * p->s[5][q];
    double *const gm = g->m, *const p0 = g->p[0], *const p1 = g->p[1], *const p2 = g->p[2];
    double *const f0 = g->f[0], *const f1 = g->f[1], *const f2 = g->f[2];
    const lm_v2d W0 = {w.w[0][0], w.w[0][1]}, G0 = {w.g[0][0], w.g[0][1]};
    const double mv[3] = {mv0, mv1, mv2};
    for (int c = 0; c < W; c++)
        for (int b = 0; b < W; b++) {
            const row3 r = row_of(g, &w, b, c);
            const double A0 = sxx * r.wyz, B0 = sxy * r.gyz + sxz * r.wgz;
            const double A1 = sxy * r.wyz, B1 = syy * r.gyz + syz * r.wgz;
            const double A2 = sxz * r.wyz, B2 = syz * r.gyz + szz * r.wgz;
            if (W == 2) {   /* the row's two nodes side by side: sim3_kernels2.h */
                const double A[3] = {A0, A1, A2}, B[3] = {B0, B1, B2};
                lm3_p2g_row2(g, r.node, W0, G0, r.wyz, m, mv, A, B);
                continue;
            }
            for (int a = 0; a < W; a++) {
                const long i = r.node + a;
                const double N = w.w[0][a] * r.wyz, ga = w.g[0][a], wa = w.w[0][a];
                gm[i] += N * m;
                p0[i] += N * mv0;
                p1[i] += N * mv1;
                p2[i] += N * mv2;
                f0[i] -= A0 * ga + B0 * wa;
                f1[i] -= A1 * ga + B1 * wa;
                f2[i] -= A2 * ga + B2 * wa;
            }
        }
}

/* Steps 0-2 at the particles q0 .. q1 - 1 into the fields of view g (the
 * grid's or a thread's copy: sim3_threads.c). */
static void p2g_range(lm3_sim *sim, const lm3_grid *g, size_t q0, size_t q1)
{
    if (g->W == 2 && lm3_simd_level() == LM3_SIMD_AVX512) {
        lm3_p2g2_avx512(sim, g, q0, q1);   /* the same bits (sim3_simd512.c) */
    } else if (g->W == 2) {
        for (size_t q = q0; q < q1; q++) {
            place_at(sim, q, 2);
            p2g_at(sim, g, q, 2);
        }
    } else {
        for (size_t q = q0; q < q1; q++) {
            place_at(sim, q, 3);
            p2g_at(sim, g, q, 3);
        }
    }
}

/* Steps 0-2 in one pass over the particles (each particle's place, then
 * its sums), the ghosts folded. v is not cleared here: the MUSL re-map
 * clears it before its sums, USL copies v^L over it (step 5), and nothing
 * between reads it (perf34: three fields of the ten a pass less). */
static void step_p2g_forces(lm3_sim *sim, int nt)
{
    lm3_grid *g = &sim->grid;
    const long nn = (long)g->nn;
    LM3_PAR(nt)
    for (long i = 0; i < nn; i++) {
        g->m[i] = 0;
        for (int a = 0; a < 3; a++) g->p[a][i] = g->f[a][i] = 0;
    }
    if (nt < 2 || lm3_scatter_threads(sim, nt, 7, p2g_range) != 0)
        p2g_range(sim, g, 0, sim->p.n);
    lm3_membrane_p2g(sim);   /* membrane points (sim3_membrane_step.c) */
    double *const f[7] = {g->m, g->p[0], g->p[1], g->p[2], g->f[0], g->f[1], g->f[2]};
    lm3_grid_fold(g, 7, f, comp_mpf);
}

/* Step 2's f_i^ext = m_i g, then step 3: p_i^L = p_i + dt f_i ([F] eq
 * 10); a_i = f_i / m_i replaces f and v_i^L = p_i^L / m_i replaces p
 * (zero at massless nodes); then the walls on both, ghosts filled for the
 * gather. One pass over the nodes where there were three (perf34): each
 * node's operations are the ones, in the order, the three passes made,
 * and the walls, which only set components to zero, give the same zero
 * after the division (0 r = +0 for the finite r >= 0 of any node whose
 * mass is a normal number) as before it. */
static void step_grid_update(lm3_sim *sim, int nt)
{
    lm3_grid *g = &sim->grid;
    const double dt = sim->def.dt;
    const double *gv = sim->def.gravity;
    const long nn = (long)g->nn;
    LM3_PAR(nt)
    for (long i = 0; i < nn; i++) {
        const double m = g->m[i], r = m > 0 ? 1.0 / m : 0;
        for (int a = 0; a < 3; a++) {
            const double f = g->f[a][i] + m * gv[a];
            g->p[a][i] = (g->p[a][i] + dt * f) * r;
            g->f[a][i] = f * r;
        }
    }
    lm3_grid_apply_bc(g, g->p);
    lm3_grid_apply_bc(g, g->f);
    double *const f[6] = {g->f[0], g->f[1], g->f[2], g->p[0], g->p[1], g->p[2]};
    static const int comp[6] = {0, 1, 2, 0, 1, 2};
    lm3_grid_fill(g, 6, f, comp);
}

/* Step 4 ([F] eq 12) at one particle: FLIP velocity from the nodal
 * accelerations, position from the Lagrangian velocity. 0 when the new
 * position or velocity is not finite or the position left the grid (the
 * step's end names it: check()), so that no pass of its own looks. */
static LM3_INLINE int g2p_at(lm3_sim *sim, size_t q, const int W)
{
    lm3_particles *p = &sim->p;
    const lm3_grid *g = &sim->grid;
    const double dt = sim->def.dt;
    lm3_weights w;
    weights_of(sim, q, &w, W);
    double a0 = 0, a1 = 0, a2 = 0, u0 = 0, u1 = 0, u2 = 0;
    if (W == 2) {   /* sim3_kernels2.h: the same sums in the same order */
        const lm_v2d W0 = {w.w[0][0], w.w[0][1]};
        double acc[6] = {0, 0, 0, 0, 0, 0};
        for (int c = 0; c < 2; c++)
            for (int b = 0; b < 2; b++)
                lm3_g2p_row2(g, w.node + (c * g->s[1] + b) * g->s[0], W0,
                             w.w[1][b] * w.w[2][c], acc);
        a0 = acc[0], a1 = acc[1], a2 = acc[2], u0 = acc[3], u1 = acc[4], u2 = acc[5];
    } else {
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
    }
    p->v[0][q] += dt * a0;
    p->v[1][q] += dt * a1;
    p->v[2][q] += dt * a2;
    p->x[0][q] += dt * u0;
    p->x[1][q] += dt * u1;
    p->x[2][q] += dt * u2;
    int ok = 1;
    for (int k = 0; k < 3; k++) {
        const double x = p->x[k][q], lo = g->lo[k];
        ok &= x >= lo && x <= lo + g->n[k] * g->h && isfinite(p->v[k][q]);
    }
    return ok;
}

/* Step 5's MUSL re-map at one particle: m_p v_p^{k+1} N_ip into v. */
static LM3_INLINE void remap_at(const lm3_sim *sim, const lm3_grid *g, size_t q, const int W)
{
    const lm3_particles *p = &sim->p;
    lm3_weights w;
    weights_of(sim, q, &w, W);
    const double m = p->m[q];
    const double mv0 = m * p->v[0][q], mv1 = m * p->v[1][q], mv2 = m * p->v[2][q];
    const lm_v2d W0 = {w.w[0][0], w.w[0][1]};
    const double mv[3] = {mv0, mv1, mv2};
    for (int c = 0; c < W; c++)
        for (int b = 0; b < W; b++) {
            const long row = w.node + (c * g->s[1] + b) * g->s[0];
            const double wyz = w.w[1][b] * w.w[2][c];
            if (W == 2) {   /* sim3_kernels2.h */
                lm3_remap_row2(g, row, W0, wyz, mv);
                continue;
            }
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
 * and the re-map's three compete for the cache. Measured again with the
 * AVX-512 re-map (perf34): 7 % slower still. */
static void remap_range(lm3_sim *sim, const lm3_grid *g, size_t q0, size_t q1)
{
    if (g->W == 2 && lm3_simd_level() == LM3_SIMD_AVX512)
        lm3_remap2_avx512(sim, g, q0, q1);   /* the same bits (sim3_simd512.c) */
    else if (g->W == 2)
        for (size_t q = q0; q < q1; q++) remap_at(sim, g, q, 2);
    else
        for (size_t q = q0; q < q1; q++) remap_at(sim, g, q, 3);
}

static int step_g2p_remap(lm3_sim *sim, int nt)
{
    lm3_grid *g = &sim->grid;
    const long n = (long)sim->p.n, nn = (long)g->nn;
    int ok = 1;
    if (g->W == 2 && lm3_simd_level() == LM3_SIMD_AVX512) {
        /* eight particles a call, the same bits (sim3_simd512.c) */
        const long groups = n / 8;
#ifdef _OPENMP
#pragma omp parallel for num_threads(nt) schedule(static) reduction(& : ok) if (nt > 1)
#endif
        for (long k = 0; k < groups; k++) ok &= lm3_g2p2_avx512(sim, (size_t)k * 8);
        for (long q = groups * 8; q < n; q++) ok &= g2p_at(sim, (size_t)q, 2);
    } else {
#ifdef _OPENMP
#pragma omp parallel for num_threads(nt) schedule(static) reduction(& : ok) if (nt > 1)
#endif
        for (long q = 0; q < n; q++)
            ok &= g->W == 2 ? g2p_at(sim, (size_t)q, 2) : g2p_at(sim, (size_t)q, 3);
    }
    if (sim->def.scheme != LM_MUSL) return ok;
    LM3_PAR(nt)
    for (long i = 0; i < nn; i++) g->v[0][i] = g->v[1][i] = g->v[2][i] = 0;
    if (nt < 2 || lm3_scatter_threads(sim, nt, 3, remap_range) != 0)
        remap_range(sim, g, 0, sim->p.n);
    return ok;
}

/* The end of step 5: the velocity the strain rate reads. MUSL ([M] eqs
 * 12-13): the re-mapped momenta folded, over m_i, walls again. USL
 * ([N] §7): v_i^L itself. */
static void step_strain_velocity(lm3_sim *sim, int nt)
{
    lm3_grid *g = &sim->grid;
    const long nn = (long)g->nn;
    if (sim->def.scheme == LM_MUSL) {
        lm3_grid_fold(g, 3, g->v, comp_vec);
        LM3_PAR(nt)
        for (long i = 0; i < nn; i++)
            if (g->m[i] > 0)
                for (int a = 0; a < 3; a++) g->v[a][i] /= g->m[i];
    } else {
        /* on the step's threads, not one (perf34) */
        LM3_PAR(nt)
        for (long i = 0; i < nn; i++)
            for (int a = 0; a < 3; a++) g->v[a][i] = g->p[a][i];
    }
    lm3_grid_apply_bc(g, g->v);
    lm3_grid_fill(g, 3, g->v, comp_vec);
}

/* Step 7 at one particle: L_ab = sum_i v_a,i G_b,ip. A row's sums
 * S_e = sum_a v_e g0[a] and T_e = sum_a v_e w0[a] first, then L_ex +=
 * S_e wyz, L_ey += T_e gyz, L_ez += T_e wgz: the gradient's products
 * made once a row, not once a node (docs/3d.md "Speed"). */
static LM3_INLINE void gradient_at(const lm3_sim *sim, size_t q, double L[9], const int W)
{
    const lm3_grid *g = &sim->grid;
    lm3_weights w;
    weights_of(sim, q, &w, W);
    for (int k = 0; k < 9; k++) L[k] = 0;
    const lm_v2d W0 = {w.w[0][0], w.w[0][1]}, G0 = {w.g[0][0], w.g[0][1]};
    for (int c = 0; c < W; c++)
        for (int b = 0; b < W; b++) {
            const row3 r = row_of(g, &w, b, c);
            if (W == 2) {   /* sim3_kernels2.h: the same sums */
                double S[3], T[3];
                lm3_gradient_row2(g, r.node, W0, G0, S, T);
                for (int e = 0; e < 3; e++) {
                    L[3 * e] += S[e] * r.wyz;
                    L[3 * e + 1] += T[e] * r.gyz;
                    L[3 * e + 2] += T[e] * r.wgz;
                }
                continue;
            }
            for (int e = 0; e < 3; e++) {
                const double *v = g->v[e] + r.node;
                double S = 0, T = 0;
                for (int a = 0; a < W; a++) {
                    S += v[a] * w.g[0][a];
                    T += v[a] * w.w[0][a];
                }
                L[3 * e] += S * r.wyz;
                L[3 * e + 1] += T * r.gyz;
                L[3 * e + 2] += T * r.wgz;
            }
        }
}

/* Step 6c ([F] eq 24's maxima): the artificial viscosity needs, before
 * any gas point is updated, the largest |div v| and the largest sound
 * speed over the gas of the step, as in 2D (step.c lm_step_gas_maxima);
 * no pass at all when no gas uses it. */
static void step_gas_maxima(lm3_sim *sim, double *max_div, double *c_max, int nt)
{
    const lm3_particles *p = &sim->p;
    double md = 0, cm = 0;
    int k = 0;
    while (k < sim->nmat && !(sim->mats[k].kind == LM3_GAS && sim->mats[k].av)) k++;
    const long n = k < sim->nmat ? (long)p->n : 0;
    /* maxima do not depend on the order they are taken in */
#ifdef _OPENMP
#pragma omp parallel for num_threads(nt) schedule(static) reduction(max : md, cm) if (nt > 1)
#endif
    for (long qi = 0; qi < n; qi++) {
        const size_t q = (size_t)qi;
        const lm3_material *mat = &sim->mats[p->mat[q]];
        if (mat->kind != LM3_GAS || !mat->av) continue;
        double L[9];
        if (sim->grid.W == 2) gradient_at(sim, q, L, 2);
        else gradient_at(sim, q, L, 3);
        double div = fabs(L[0] + L[4] + L[8]), c = lm3_gas_sound_speed(mat, p->e[q]);
        if (div > md) md = div;
        if (c > cm) cm = c;
    }
    *max_div = md;
    *c_max = cm;
}

/* A solid's shear increments de[3..5] (Voigt yz, xz, xy of dt/2 (L + L^T))
 * and spin W = 1/2 (L - L^T): both stress passes' share of steps 7-8. */
static LM3_INLINE void shear_and_spin(const double L[9], double dt, double de[6], double W[9])
{
    de[3] = 0.5 * dt * (L[5] + L[7]);
    de[4] = 0.5 * dt * (L[2] + L[6]);
    de[5] = 0.5 * dt * (L[1] + L[3]);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) W[3 * i + j] = 0.5 * (L[3 * i + j] - L[3 * j + i]);
}

/* Steps 7-8 ([F] eqs 14-25): de = dt/2 (L + L^T), W = 1/2 (L - L^T),
 * rho / (1 + tr de) ([F] eq 16), then the material's law: the elastic
 * solid's Jaumann update, or the gas's stress from its rate, pressure and
 * artificial viscosity (sim3_gas.c). 0 when a particle's volume went to
 * nothing. */
typedef struct stress_ctx {
    double max_div, c_max;
    double G[LM3_MAX_MATERIALS], lam[LM3_MAX_MATERIALS];
} stress_ctx;

static LM3_INLINE int stress_at(lm3_sim *sim, size_t q, const stress_ctx *c, const int Ws)
{
    lm3_particles *p = &sim->p;
    const double dt = sim->def.dt;
    double L[9], W[9], de[6], s[6];
    gradient_at(sim, q, L, Ws);
    de[0] = dt * L[0];
    de[1] = dt * L[4];
    de[2] = dt * L[8];
    double J = 1 + de[0] + de[1] + de[2];
    if (!(J > 0)) return 0;
    p->rho[q] /= J;
    const int k = p->mat[q];
    const lm3_material *mat = &sim->mats[k];
    if (mat->kind == LM3_GAS) {
        double qv = lm3_gas_av(mat, p->rho[q], L[0] + L[4] + L[8], c->max_div, c->c_max,
                               sim->grid.h);
        lm3_gas_update(mat, L, dt, p->rho[q], qv, &p->e[q], s);
    } else {
        shear_and_spin(L, dt, de, W);
        for (int e = 0; e < 6; e++) s[e] = p->s[e][q];
        lm3_elastic_update_gl(c->G[k], c->lam[k], de, W, dt, s);
    }
    for (int e = 0; e < 6; e++) p->s[e][q] = s[e];
    return 1;
}

/* The trilinear stress pass: stress_at with the stencil width a constant,
 * the update inline and the moduli made once a step (sim3_elastic.h):
 * 5-8 % faster than the generic pass below (docs/3d.md "Speed"). */
static int stress_trilinear(lm3_sim *sim, const stress_ctx *c, int nt)
{
    const long n = (long)sim->p.n;
    int ok = 1;
    if (lm3_simd_level() == LM3_SIMD_AVX512) {
        /* eight particles a call, the scalar bits (sim3_simd512.c); a
         * group of mixed or gas materials, and the last n mod 8, one by
         * one */
        const long groups = n / 8;
#ifdef _OPENMP
#pragma omp parallel for num_threads(nt) schedule(static) reduction(& : ok) if (nt > 1)
#endif
        for (long k = 0; k < groups; k++) {
            const size_t q = (size_t)k * 8;
            const int r = lm3_stress2_avx512(sim, c->G, c->lam, q);
            if (r >= 0) ok &= r;
            else
                for (size_t l = q; l < q + 8; l++) ok &= stress_at(sim, l, c, 2);
        }
        for (long q = groups * 8; q < n; q++) ok &= stress_at(sim, (size_t)q, c, 2);
        return ok;
    }
#ifdef _OPENMP
#pragma omp parallel for num_threads(nt) schedule(static) reduction(& : ok) if (nt > 1)
#endif
    for (long q = 0; q < n; q++) ok &= stress_at(sim, (size_t)q, c, 2);
    return ok;
}

/* The quadratic B-spline's pass as it was: as stress_trilinear (with
 * W = 3) it was 5-7 % slower, 3.43-3.47 against 3.64-3.68 M particle-steps
 * per CPU-s in three alternating pairs (docs/3d.md "Speed") */
static int stress_generic(lm3_sim *sim, double max_div, double c_max, int nt)
{
    lm3_particles *p = &sim->p;
    const double dt = sim->def.dt;
    const long n = (long)p->n;
    int ok = 1;
#ifdef _OPENMP
#pragma omp parallel for num_threads(nt) schedule(static) reduction(& : ok) if (nt > 1)
#endif
    for (long qi = 0; qi < n; qi++) {
        const size_t q = (size_t)qi;
        double L[9], W[9], de[6], s[6];
        if (sim->grid.W == 2) gradient_at(sim, q, L, 2);
        else gradient_at(sim, q, L, 3);
        de[0] = dt * L[0];
        de[1] = dt * L[4];
        de[2] = dt * L[8];
        double J = 1 + de[0] + de[1] + de[2];
        if (!(J > 0)) {
            ok = 0;
            continue;
        }
        p->rho[q] /= J;
        const lm3_material *mat = &sim->mats[p->mat[q]];
        if (mat->kind == LM3_GAS) {
            double qv = lm3_gas_av(mat, p->rho[q], L[0] + L[4] + L[8], max_div, c_max,
                                   sim->grid.h);
            lm3_gas_update(mat, L, dt, p->rho[q], qv, &p->e[q], s);
        } else {
            shear_and_spin(L, dt, de, W);
            for (int c = 0; c < 6; c++) s[c] = p->s[c][q];
            lm3_elastic_update(mat, de, W, dt, s);
        }
        for (int c = 0; c < 6; c++) p->s[c][q] = s[c];
    }
    return ok;
}

static int step_stress(lm3_sim *sim, double max_div, double c_max, int nt)
{
    /* each elastic material's moduli, once a step (sim3_elastic.h) */
    stress_ctx c = {.max_div = max_div, .c_max = c_max};
    for (int k = 0; k < sim->nmat; k++)
        if (sim->mats[k].kind != LM3_GAS) lm3_elastic_moduli(&sim->mats[k], &c.G[k], &c.lam[k]);
    if (sim->grid.W != 2) return stress_generic(sim, max_div, c_max, nt);
    return stress_trilinear(sim, &c, nt);
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
        double ck;
        if (m->kind == LM3_GAS) {
            ck = lm3_gas_sound_speed(m, m->e0);
        } else {
            double G = m->E / (2 * (1 + m->nu)),
                   lam = m->E * m->nu / ((1 + m->nu) * (1 - 2 * m->nu));
            ck = sqrt((lam + 2 * G) / m->rho);
        }
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
    /* before the first step (and after a failed one) the particles are
     * looked at; otherwise each step's g2p looks at the positions it makes */
    if (sim->nstep == 0 || sim->recheck) {
        lm_status st = check(sim);
        if (st != LM_OK) return st;
        sim->recheck = 0;
    }
    const int nt = lm3_threads(sim);
    (void)lm3_simd_level();   /* asked here, before the threads ask it */
    step_p2g_forces(sim, nt);
    step_grid_update(sim, nt);
    if (sim->pins) lm3_pins_grid(sim);     /* body:pin (sim3_pin.c) */
    lm3_membrane_hold(sim);
    const int moved_ok = step_g2p_remap(sim, nt);
    lm3_membrane_g2p(sim);
    step_strain_velocity(sim, nt);
    if (sim->pins) lm3_pins_strain(sim);
    {
        /* the membranes' strain and stress; their points' check */
        lm_status st = lm3_membrane_update(sim);
        if (st != LM_OK) {
            sim->recheck = 1;
            return st;
        }
    }
    double max_div, c_max;
    step_gas_maxima(sim, &max_div, &c_max, nt);
    if (!step_stress(sim, max_div, c_max, nt)) {
        sim->recheck = 1;
        snprintf(sim->err, sizeof sim->err, "t = %g (step %ld): a particle's volume went to "
                 "nothing (1 + tr de <= 0): unstable", sim->t, sim->nstep);
        return LM_ERR_UNSTABLE;
    }
    sim->nstep++;
    sim->t = sim->nstep * sim->def.dt;   /* from the count, as in 2D */
    if (moved_ok) return LM_OK;
    sim->recheck = 1;
    return check(sim);
}
