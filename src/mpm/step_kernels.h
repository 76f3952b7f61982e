/* step_kernels.h - what the step does at one particle, shared by the
 * phase-by-phase step (step.c) and the fused particle pass (step_fused.c),
 * so that both make the same sums in the same order: the same bits.
 *
 * The step's loops over a particle's stencil come in two widths, chosen
 * outside the particle loops: 2 x 2 for the linear basis (the papers' code
 * path, unchanged to the last bit) and 3 x 3 for uGIMP and the quadratic
 * B-spline. Each kernel is written once for a stencil width W and inlined
 * with W a constant, so the compiler unrolls both. Node (a, b) of the
 * stencil is row b, column a (k = b W + a). */
#ifndef LAMINA_STEP_KERNELS_H
#define LAMINA_STEP_KERNELS_H

#include <math.h>

#include "step.h"

#if defined(__GNUC__)
#define LM_FORCE_INLINE inline __attribute__((always_inline))
#else
#define LM_FORCE_INLINE inline
#endif

/* Is q a point of a membrane whose tension acts along its segments? */
static inline int lm_k_segment_point(const lm_sim *sim, size_t q)
{
    const lm_body *bd = &sim->bodies[sim->p.body[q]];
    return bd->membrane && bd->force == LM_MFORCE_SEGMENT;
}

/* Particle q's weights (gradients) for a stencil W wide: the bilinear and
 * B-spline ones rebuilt into buf from the point's place (step.h), uGIMP's
 * where lm_step_shape stored them (p->N is NULL for the other two: one
 * well-predicted test a particle). */
static LM_FORCE_INLINE const double *lm_k_weights_N(const lm_particles *p, size_t q,
                                                    const int W, double buf[9])
{
    if (W == 2) {
        lm_bilinear_N(p->xi[q], p->eta[q], buf);
        return buf;
    }
    if (p->N) return p->N + (size_t)(W * W) * q;
    lm_bspline2_N(p->xi[q], p->eta[q], buf);
    return buf;
}
/* rx = 1 / hx, ry = 1 / hy, the caller's for all its points */
static LM_FORCE_INLINE void lm_k_weights_G(const lm_particles *p, size_t q, const int W,
                                           double rx, double ry, double gx[9], double gy[9],
                                           const double **Gx, const double **Gy)
{
    if (W == 2) {
        lm_bilinear_G_r(rx, ry, p->xi[q], p->eta[q], gx, gy);
    } else if (p->Gx) {
        *Gx = p->Gx + (size_t)(W * W) * q;
        *Gy = p->Gy + (size_t)(W * W) * q;
        return;
    } else {
        lm_bspline2_G_r(rx, ry, p->xi[q], p->eta[q], gx, gy);
    }
    *Gx = gx;
    *Gy = gy;
}

/* Particle q's place in the grid at its present position (the step's
 * shape pass, step 0): the bilinear basis keeps the lower-left node and
 * (xi, eta), the B-spline the lower-left node and the offsets from the
 * nearest node, uGIMP its 9 weights and gradients. */
static LM_FORCE_INLINE void lm_k_shape(const lm_sim *sim, lm_particles *p, size_t q,
                                       double rx, double ry)
{
    const lm_grid *g = &sim->grid;
    switch (sim->def.basis) {
    case LM_BASIS_LINEAR:
        lm_cell_bilinear_r(g, rx, ry, p->x[q], p->y[q], &p->node[q], &p->xi[q], &p->eta[q]);
        break;
    case LM_BASIS_GIMP:
        lm_shape_gimp(g, p->x[q], p->y[q], p->lx[q], p->ly[q], &p->node[q], &p->N[9 * q],
                      &p->Gx[9 * q], &p->Gy[9 * q]);
        break;
    case LM_BASIS_BSPLINE2:
        lm_bspline2_place(g, rx, ry, p->x[q], p->y[q], &p->node[q], &p->xi[q], &p->eta[q]);
        break;
    }
}

/* Where a thread's sum at node j goes (threads.h): to its copy c when
 * another thread touches j too (lo <= j <= lo + span), else to the field f
 * itself. split is a constant: 0 on the plain path. */
static LM_FORCE_INLINE double *lm_k_at(double *f, double *c, long j, long lo,
                                       unsigned long span, const int split)
{
    return split && (unsigned long)(j - lo) <= span ? c + j : f + j;
}

/* Step 4's values at node i, per node once, not per particle corner:
 * a_i = f_i / m_i into (ax, ay) and v_i^L = p_i^L (1 / m_i) into (ux, uy);
 * a node without mass gets zeros. */
static LM_FORCE_INLINE void lm_k_g2p_node(lm_grid *g, long i, double *ux, double *uy)
{
    double r = g->m[i] > 0 ? 1.0 / g->m[i] : 0;
    g->ax[i] = g->fx[i] * r;
    g->ay[i] = g->fy[i] * r;
    ux[i] = g->px[i] * r;
    uy[i] = g->py[i] * r;
}

/* What particle q gives the nodal forces ([F] eq 9): a segment membrane
 * point (seg) its net tension, spread with N_ip; any other its volume and
 * stress, with the weights' gradients (into gx, gy when they are made
 * here). */
typedef struct lm_k_force_src {
    double V, sxx, syy, sxy, fpx, fpy;
    const double *Gx, *Gy;
} lm_k_force_src;

static LM_FORCE_INLINE lm_k_force_src lm_k_force_source(const lm_particles *p, size_t q,
                                                        const int seg, const int W, double rx,
                                                        double ry, double gx[9], double gy[9])
{
    lm_k_force_src s = {0, 0, 0, 0, 0, 0, NULL, NULL};
    if (seg) {
        s.fpx = p->fpx[q];
        s.fpy = p->fpy[q];
    } else {
        s.V = p->m[q] / p->rho[q];
        s.sxx = p->sxx[q];
        s.syy = p->syy[q];
        s.sxy = p->sxy[q];
        lm_k_weights_G(p, q, W, rx, ry, gx, gy, &s.Gx, &s.Gy);
    }
    return s;
}

/* Steps 1 and 2 at particle q: m_p N_ip, m_p v_p N_ip and the internal
 * force -V_p sigma_p . G_ip ([F] eq 9; a segment membrane point's net
 * tension spread with N_ip instead; segs = 0: the caller knows there is
 * none) added into the five fields f (m, px, py, fx, fy), or into the
 * copies c where another thread shares the node.
 * The particle's values are read into locals once: the nodal sums are
 * doubles too, so the compiler could not otherwise keep them in registers
 * across the stores. */
static LM_FORCE_INLINE void lm_k_scatter_mass_forces(const lm_sim *sim, size_t q, double rx,
                                                     double ry, double *const *f,
                                                     double *const *c, long lo,
                                                     unsigned long span, const int W,
                                                     const int split, const int segs)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    double Nl[9], Gxl[9], Gyl[9];
    const double m = p->m[q], vx = p->vx[q], vy = p->vy[q];
    const double *N = lm_k_weights_N(p, q, W, Nl);
    const int seg = segs && lm_k_segment_point(sim, q);
    const lm_k_force_src s = lm_k_force_source(p, q, seg, W, rx, ry, Gxl, Gyl);
    for (int b = 0; b < W; b++) {
        const long row = lm_stencil_row(g, p->node[q], b);
        for (int a = 0; a < W; a++) {
            double w = m * N[b * W + a];
            *lm_k_at(f[0], split ? c[0] : NULL, row + a, lo, span, split) += w;
            *lm_k_at(f[1], split ? c[1] : NULL, row + a, lo, span, split) += w * vx;
            *lm_k_at(f[2], split ? c[2] : NULL, row + a, lo, span, split) += w * vy;
            if (seg) {
                *lm_k_at(f[3], split ? c[3] : NULL, row + a, lo, span, split) +=
                    N[b * W + a] * s.fpx;
                *lm_k_at(f[4], split ? c[4] : NULL, row + a, lo, span, split) +=
                    N[b * W + a] * s.fpy;
            } else {
                double gx = s.Gx[b * W + a], gy = s.Gy[b * W + a];
                *lm_k_at(f[3], split ? c[3] : NULL, row + a, lo, span, split) -=
                    s.V * (s.sxx * gx + s.sxy * gy);
                *lm_k_at(f[4], split ? c[4] : NULL, row + a, lo, span, split) -=
                    s.V * (s.sxy * gx + s.syy * gy);
            }
        }
    }
}

/* Step 1 at particle q (mass = 1): m_p N_ip and m_p v_p N_ip added into
 * (f[0], f[1], f[2]); the MUSL re-map (mass = 0, [M] eqs 12-13): m_p v_p
 * N_ip into (f[0], f[1]); or into the copies c where another thread
 * shares the node. */
static LM_FORCE_INLINE void lm_k_scatter_momentum(const lm_sim *sim, size_t q,
                                                  double *const *f, double *const *c, long lo,
                                                  unsigned long span, const int W,
                                                  const int split, const int mass)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    double Nl[9];
    const double m = p->m[q], vx = p->vx[q], vy = p->vy[q];
    const double *N = lm_k_weights_N(p, q, W, Nl);
    double *const *fp = mass ? f + 1 : f, *const *cp = split && mass ? c + 1 : c;
    for (int b = 0; b < W; b++) {
        const long row = lm_stencil_row(g, p->node[q], b);
        for (int a = 0; a < W; a++) {
            double w = m * N[b * W + a];
            if (mass) *lm_k_at(f[0], split ? c[0] : NULL, row + a, lo, span, split) += w;
            *lm_k_at(fp[0], split ? cp[0] : NULL, row + a, lo, span, split) += w * vx;
            *lm_k_at(fp[1], split ? cp[1] : NULL, row + a, lo, span, split) += w * vy;
        }
    }
}

/* Step 4 at particle q ([F] eq 12): FLIP velocity update from the nodal
 * accelerations (ax, ay), optionally blended with the PIC velocity
 * sum_i N_ip v_i^L (pic = 0, the papers' scheme, by default), position
 * from the Lagrangian grid velocity (ux, uy). */
static LM_FORCE_INLINE void lm_k_g2p(const lm_grid *g, lm_particles *p, size_t q, double dt,
                                     double pic, const double *gax, const double *gay,
                                     const double *gux, const double *guy, const int W)
{
    const int NS = W * W;
    double Nl[9];
    const double *N = lm_k_weights_N(p, q, W, Nl);
    double ax = 0, ay = 0, ux = 0, uy = 0;
    if (W == 2) {
        /* one running sum over the corners: the papers' code path, to the
         * last bit */
        for (int k = 0; k < NS; k++) {
            int i = lm_stencil_node(g, W, p->node[q], k);
            ax += N[k] * gax[i];
            ay += N[k] * gay[i];
            ux += N[k] * gux[i];
            uy += N[k] * guy[i];
        }
    } else {
        /* row by row, then the rows: at a point on a fixed wall the
         * antisymmetric ghost row (or column) cancels its mirror exactly
         * (grid_walls.c), so the point does not move by a rounding error */
        for (int b = 0; b < W; b++) {
            const long row = lm_stencil_row(g, p->node[q], b);
            double rax = 0, ray = 0, rux = 0, ruy = 0;
            for (int a = 0; a < W; a++) {
                double w = N[b * W + a];
                rax += w * gax[row + a];
                ray += w * gay[row + a];
                rux += w * gux[row + a];
                ruy += w * guy[row + a];
            }
            ax += rax;
            ay += ray;
            ux += rux;
            uy += ruy;
        }
    }
    p->vx[q] = (1 - pic) * (p->vx[q] + dt * ax) + pic * ux;
    p->vy[q] = (1 - pic) * (p->vy[q] + dt * ay) + pic * uy;
    p->x[q] += dt * ux;
    p->y[q] += dt * uy;
}

/* L = sum_i v_i (x) G_ip (L = dv/dx) at particle q from the nodal
 * velocities (vx, vy), stencil W wide; with hoop (the axisymmetric form,
 * axisym.c) also sum_i N_ip v_ri / r_p, returned (0 on the axis, r_p = 0),
 * from the same read of the nodes: each sum in its own order, so the bits
 * of the two apart. */
static LM_FORCE_INLINE double lm_k_gradient_hoop(const lm_grid *g, const lm_particles *p,
                                                 size_t q, const double *gvx,
                                                 const double *gvy, double L[4], double rx,
                                                 double ry, const int W, const int hoop)
{
    double Nl[9], Gxl[9], Gyl[9];
    const double *N = hoop ? lm_k_weights_N(p, q, W, Nl) : NULL, *Gx, *Gy;
    lm_k_weights_G(p, q, W, rx, ry, Gxl, Gyl, &Gx, &Gy);
    double Lxx = 0, Lxy = 0, Lyx = 0, Lyy = 0, s = 0;
    for (int b = 0; b < W; b++) {
        const long row = lm_stencil_row(g, p->node[q], b);
        for (int a = 0; a < W; a++) {
            double gx = Gx[b * W + a], gy = Gy[b * W + a];
            double vx = gvx[row + a], vy = gvy[row + a];
            Lxx += vx * gx;
            Lxy += vx * gy;
            Lyx += vy * gx;
            Lyy += vy * gy;
            if (hoop) s += N[b * W + a] * vx;
        }
    }
    L[0] = Lxx; L[1] = Lxy; L[2] = Lyx; L[3] = Lyy;
    double r = p->x[q];
    return hoop && r > 0 ? s / r : 0;
}

/* L alone (lm_k_gradient_hoop without the hoop sum). */
static LM_FORCE_INLINE void lm_k_velocity_gradient(const lm_grid *g, const lm_particles *p,
                                                   size_t q, const double *gvx,
                                                   const double *gvy, double L[4], double rx,
                                                   double ry, const int W)
{
    (void)lm_k_gradient_hoop(g, p, q, gvx, gvy, L, rx, ry, W, 0);
}

/* The domain the check holds the particles to, worked out once a pass
 * (the particles' stores could alias the grid's doubles, so the compiler
 * would work it out once a particle). */
typedef struct lm_k_box {
    double x0, y0, x1, y1;   /* the grid's edges */
    double tx, ty;           /* a rounding stray's allowance past them */
} lm_k_box;
static inline lm_k_box lm_k_box_of(const lm_grid *g)
{
    lm_k_box b = {g->x0, g->y0, g->x0 + g->nx * g->hx, g->y0 + g->ny * g->hy, 1e-6 * g->hx,
                  1e-6 * g->hy};
    return b;
}

/* 0 if a particle at (*x, *y) with these values is sound (a rounding
 * stray past a wall is put back in *x, *y), else what is wrong with it:
 * 1 NaN, 2 no volume, 3 out of the domain. From values a pass holds in
 * registers (step_bspline2.c) or from the arrays (lm_k_check). */
static inline int lm_k_check_values(double *x, double *y, double vx, double vy, double sxx,
                                    double syy, double sxy, double rho, const lm_k_box *b)
{
    /* a sum is finite unless a term is NaN or infinite (or it overflows,
     * which is trouble too): one test where seven would do */
    double sum = *x + *y + vx + vy + sxx + syy + sxy;
    if (!isfinite(sum)) return 1;
    if (!(rho > 0) || !isfinite(rho)) return 2;
    if (*x < b->x0 || *x > b->x1 || *y < b->y0 || *y > b->y1) {
        /* A point on a wall or symmetry line can stray by rounding (1e-17
         * of a cell per step); that is put back, not reported. */
        if (*x < b->x0 - b->tx || *x > b->x1 + b->tx || *y < b->y0 - b->ty ||
            *y > b->y1 + b->ty)
            return 3;
        *x = fmin(fmax(*x, b->x0), b->x1);
        *y = fmin(fmax(*y, b->y0), b->y1);
    }
    return 0;
}
/* The same for particle q from its arrays. */
static inline int lm_k_check(lm_particles *p, size_t q, const lm_k_box *b)
{
    return lm_k_check_values(&p->x[q], &p->y[q], p->vx[q], p->vy[q], p->sxx[q], p->syy[q],
                             p->sxy[q], p->rho[q], b);
}

#endif
