/* step_bspline2.c - the fused USL pass (step_fused.c) for the quadratic
 * B-spline on one thread, written for the default basis's speed (issue 36
 * item 2).
 *
 * What it does at a particle is exactly what pass_w does with W = 3 (step
 * 4, the rate and the stress, the check, the shape at x^{k+1} and the
 * next step's sums), in the same order: every nodal sum receives the same
 * terms in the same particle order, every term is the same product, so
 * the states are the same to the bit (tests/unit/test_step_fused.c). Only
 * the instructions differ:
 *
 *   - the sums that do not depend on each other run side by side in two
 *     lanes (simd2.h: each lane the scalar operation, correctly rounded):
 *     (a_x, a_y) and (v^L_x, v^L_y) in step 4, (L_xx, L_xy) and (L_yx,
 *     L_yy) in the rate, (p_x, p_y) and (f_x, f_y) in the scatter;
 *   - the nodal values the particle reads lie together in one record of 8
 *     doubles a node, {a_x, a_y, v^L_x, v^L_y, v_x, v_x, v_y, v_y} (one
 *     cache line; made by a sweep over the nodes before the pass), and the
 *     next step's momenta and forces are summed into records {p_x, p_y,
 *     f_x, f_y} and handed out to the grid's arrays after it, so a stencil
 *     node is one or two loads, not eight;
 *   - the 2D weights and gradients are the products of the six 1D values
 *     (lm_bspline2_1d) made where they are used, as lm_bspline2_N and
 *     lm_bspline2_G_r make them (the same products, the same bits);
 *   - an elastic solid's update (material_elastic.c) with its moduli
 *     worked out once a pass instead of two divisions a particle. */
#include <string.h>

#include "simd2.h"
#include "step.h"
#include "step_bspline2.h"
#include "step_kernels.h"

/* Four doubles side by side: one AVX register where the pass is compiled
 * for AVX2 (picked at run time), two SSE2 ones in the portable build;
 * each lane the scalar operation either way, so the same bits. */
typedef double v4d __attribute__((vector_size(32)));
#include "psabi_quiet.h"   /* the helpers are inlined: no call passes a vector */

static LM_FORCE_INLINE v4d v4_load(const double *p)
{
    v4d v;
    memcpy(&v, p, sizeof v);
    return v;
}
static LM_FORCE_INLINE void v4_store(double *p, v4d v)
{
    memcpy(p, &v, sizeof v);
}

/* The nodal record of the pass: after step 4's nodal values (ax, ay, ux,
 * uy: lm_step_g2p_nodes) and the strain velocities (g->vx, g->vy) are
 * final, ghosts included. */
static void pack_nodes(const lm_grid *g, const double *ux, const double *uy, double *rec,
                       size_t nn)
{
    for (size_t i = 0; i < nn; i++) {
        double *r = rec + LM_B2_REC * i;
        r[0] = g->ax[i];
        r[1] = g->ay[i];
        r[2] = ux[i];
        r[3] = uy[i];
        r[4] = r[6] = g->vx[i];
        r[5] = r[7] = g->vy[i];
    }
}

typedef struct pass_ctx {
    const double *rec;
    double *sums, *m0;
    const lm_elastic_moduli *el;
} pass_ctx;

/* The particle loop, inlined into one function per instruction set. */
static LM_FORCE_INLINE size_t particles(lm_sim *sim, const pass_ctx *c)
{
    const lm_grid *g = &sim->grid;
    lm_particles *p = &sim->p;
    const size_t n = p->n;
    const double dt = sim->def.dt, pic = sim->def.pic;
    const double rx = 1.0 / g->hx, ry = 1.0 / g->hy, h = fmin(g->hx, g->hy);
    const long sx = g->sx;
    const lm_k_box box = lm_k_box_of(g);
    const double *const rec = c->rec;
    double *const sums = c->sums, *const m0 = c->m0;
    const v4d one = {1, 1, 1, 1};
    /* one material, an elastic solid (the common case): no look-up */
    const lm_elastic_moduli *const el1 = sim->nmats == 1 && c->el[0].elastic ? c->el : NULL;
    size_t first = n;
    for (size_t q = 0; q < n; q++) {
        /* x^k: the place lm_k_shape kept, its 1D weights and gradients */
        double wx[3], gx[3], wy[3], gy[3];
        lm_bspline2_1d(p->xi[q], rx, wx, gx);
        lm_bspline2_1d(p->eta[q], ry, wy, gy);
        const long node = p->node[q];
        /* step 4 (lm_k_g2p, W = 3), lanes {a_x, a_y, v^L_x, v^L_y}: row by
         * row, then the rows; N = wx wy. The rate
         * (lm_k_velocity_gradient), lanes {L_xx, L_yx, L_xy, L_yy}: one
         * running sum; {G_x, G_x, G_y, G_y} = {gx, gx, wx, wx} {wy, wy, gy, gy} */
        v4d acc = {0, 0, 0, 0}, L = {0, 0, 0, 0};
        for (int b = 0; b < 3; b++) {
            const double *r = rec + LM_B2_REC * (node + b * sx);
            const v4d wyb = wy[b] * one, wgy = {wy[b], wy[b], gy[b], gy[b]};
            v4d ra = {0, 0, 0, 0};
            for (int a = 0; a < 3; a++) {
                const double *ra_ = r + LM_B2_REC * a;
                ra += (wx[a] * one * wyb) * v4_load(ra_);
                L += v4_load(ra_ + 4) * ((v4d){gx[a], gx[a], wx[a], wx[a]} * wgy);
            }
            acc += ra;
        }
        /* the particle's values in registers from here on (the arrays
         * could alias, so the compiler would reload them) */
        const double vx = (1 - pic) * (p->vx[q] + dt * acc[0]) + pic * acc[2];
        const double vy = (1 - pic) * (p->vy[q] + dt * acc[1]) + pic * acc[3];
        double x = p->x[q] + dt * acc[2], y = p->y[q] + dt * acc[3];
        p->vx[q] = vx;
        p->vy[q] = vy;
        /* steps 7-8 (stress_at in step_fused.c) */
        lm_rate rt;
        rt.L[0] = L[0];
        rt.L[1] = L[2];
        rt.L[2] = L[1];
        rt.L[3] = L[3];
        rt.dexx = dt * rt.L[0];
        rt.deyy = dt * rt.L[3];
        rt.dexy = 0.5 * dt * (rt.L[1] + rt.L[2]);
        rt.w = 0.5 * (rt.L[1] - rt.L[2]);
        const int mat = el1 ? 0 : p->mat[q];
        double rho, sxx, syy, sxy;
        if (el1 || (mat < LM_FUSED_MATS && c->el[mat].elastic)) {
            rho = p->rho[q] / (1 + rt.dexx + rt.deyy);
            sxx = p->sxx[q];
            syy = p->syy[q];
            sxy = p->sxy[q];
            lm_elastic_update_moduli(&c->el[mat], rt.dexx, rt.deyy, rt.dexy, rt.w, dt, &sxx,
                                     &syy, &sxy, &p->szz[q]);
            p->rho[q] = rho;
            p->sxx[q] = sxx;
            p->syy[q] = syy;
            p->sxy[q] = sxy;
        } else {
            rt.hoop = 0;
            rt.dt = dt;
            rt.max_div = 0;
            rt.c_max = 0;
            rt.h = h;
            p->x[q] = x;
            p->y[q] = y;
            lm_update_at(sim, q, &rt, 0);
            rho = p->rho[q];
            sxx = p->sxx[q];
            syy = p->syy[q];
            sxy = p->sxy[q];
        }
        if (lm_k_check_values(&x, &y, vx, vy, sxx, syy, sxy, rho, &box) && q < first) first = q;
        p->x[q] = x;
        p->y[q] = y;
        /* the shape at x^{k+1} and the next step's sums
         * (lm_k_scatter_mass_forces, no segment points here), lanes {p_x,
         * p_y, f_x, f_y}: X = {m, m, sxx, sxy} {N, N, Gx, Gx}, Y = {-0, -0,
         * sxy, syy} {1, 1, Gy, Gy}, (X + Y) {vx, vy, -V, -V} is {w vx, w vy,
         * -V (sxx Gx + sxy Gy), -V (sxy Gx + syy Gy)} (x + -0 = x; a
         * product's sign is exact), added to the sums (f + -t = f - t, the
         * forces' -=); m gets w = X[0] */
        int nd;
        double dx, dy;
        lm_bspline2_place(g, rx, ry, x, y, &nd, &dx, &dy);
        p->node[q] = nd;
        p->xi[q] = dx;
        p->eta[q] = dy;
        lm_bspline2_1d(dx, rx, wx, gx);
        lm_bspline2_1d(dy, ry, wy, gy);
        const double mq = p->m[q];
        const v4d s1 = {mq, mq, sxx, sxy}, s2 = {-0.0, -0.0, sxy, syy};
        const double V = mq / rho;
        const v4d u = {vx, vy, -V, -V};
        for (int b = 0; b < 3; b++) {
            double *const sr = sums + 4 * (nd + b * sx), *const mr = m0 + nd + b * sx;
            const v4d wyb = wy[b] * one, gyb = {1, 1, gy[b], gy[b]};
            for (int a = 0; a < 3; a++) {
                const v4d X = s1 * ((v4d){wx[a], wx[a], gx[a], gx[a]} * wyb);
                const v4d Y = s2 * ((v4d){1, 1, wx[a], wx[a]} * gyb);
                mr[a] += X[0];
                v4_store(sr + 4 * a, v4_load(sr + 4 * a) + (X + Y) * u);
            }
        }
    }
    return first;
}

static size_t particles_default(lm_sim *sim, const pass_ctx *c)
{
    return particles(sim, c);
}

#if defined(__x86_64__) && defined(__GNUC__)
#define LM_B2_DISPATCH 1
__attribute__((target("avx2"))) static size_t particles_avx2(lm_sim *sim, const pass_ctx *c)
{
    return particles(sim, c);
}
#endif

/* -1: not yet asked; else the instruction set the pass runs with */
static int isa = -1;
static int forced = -1;

void lm_fused_bspline2_isa(int set)
{
    forced = set;
}

int lm_fused_bspline2_isa_in_use(void)
{
    if (forced >= 0) return forced;
    if (isa < 0) {
        isa = LM_B2_ISA_BASELINE;
#ifdef LM_B2_DISPATCH
        __builtin_cpu_init();
        if (__builtin_cpu_supports("avx2")) isa = LM_B2_ISA_AVX2;
#endif
    }
    return isa;
}

size_t lm_fused_bspline2_usl(lm_sim *sim, const double *ux, const double *uy, double *rec,
                             double *sums, double *const *next)
{
    const lm_grid *g = &sim->grid;
    const size_t nn = lm_grid_nodes(g);
    lm_elastic_moduli el[LM_FUSED_MATS];
    lm_elastic_moduli_table(sim, el);
    pack_nodes(g, ux, uy, rec, nn);   /* (sums: all zero between passes) */
    const pass_ctx c = {rec, sums, next[0], el};
    size_t first;
#ifdef LM_B2_DISPATCH
    if (lm_fused_bspline2_isa_in_use() == LM_B2_ISA_AVX2) first = particles_avx2(sim, &c);
    else
#endif
        first = particles_default(sim, &c);
    /* the records' sums to the grid's arrays the next step takes up, and
     * the records zeroed for the next pass in the same sweep */
    for (size_t i = 0; i < nn; i++) {
        double *s = sums + 4 * i;
        next[1][i] = s[0];
        next[2][i] = s[1];
        next[3][i] = s[2];
        next[4][i] = s[3];
        s[0] = s[1] = s[2] = s[3] = 0;
    }
    return first;
}
