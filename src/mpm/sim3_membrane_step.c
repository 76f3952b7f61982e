/* sim3_membrane_step.c - the membrane points' part of the 3D step
 * (mpm3_membrane.h, docs/3d.md "3D membranes"), called by sim3_step.c at
 * four places: p2g (before the ghosts fold), after the grid update (pins),
 * after the particles' g2p and re-map, after the strain velocity.
 *
 * A point's membrane stress s (components 11, 22, 12 in its frame t1, t2)
 * is the global tensor S = s_ab t_a (x) t_b, which has no component along
 * the normal: plane stress through the thickness ([T] eq 5.15). Its force
 * on node i is the 2D point quadrature's in 3D, f_i = -V S . G_ip with V =
 * thickness x current area ([F] eq 9 with the membrane's volume, [M] §3).
 *
 * The strain is objective in the convected frame: the frame's tangents are
 * carried by the grid's velocity gradient (t <- t + dt L t), t1 first and
 * t2 re-orthonormalised against it (Gram-Schmidt), so a rigid rotation
 * carries the frame exactly and the components are unchanged. In a shear
 * the frame turns in its plane faster than the material spin by D12 (t1
 * follows a material line, the spin is the mean of the two lines'), so the
 * components take the corotational correction of a frame turning at the
 * spin (the Jaumann rate of membrane.c in 2D has no in-plane rotation to
 * correct): with w = -D12,
 *     e11 += dt (D11 - 2 w e12), e22 += dt (D22 + 2 w e12),
 *     e12 += dt (D12 + w (e11 - e22)).
 * D_ab = t_a . D t_b is the projection of L's symmetric part on the
 * tangent plane, P L P with P = I - n n^T: the stretching across the
 * thickness never enters. The law is the registry's biaxial stress at the
 * principal strains (membrane_law.h), turned back into the frame.
 *
 * MUSL: a point's strain, frame and area follow the re-mapped velocity
 * ([M] eqs 12-13), so the point moves with that velocity too, x^{k+1} =
 * x^k + dt sum_i N_ip v_i (weights at x^k), not with v_i^L as the
 * particles do; the 2D segment membrane moves its points so for the same
 * reason (membrane_force.c). Moved with v_i^L, the points drift from the
 * surface their areas and frames describe, and the mismatch feeds a motion
 * the damping does not hold: a soft sphere (E = 1e5, t = 0.01, r0 = 0.3)
 * under 1130 Pa, points h/2 apart, took 0.92 J of kinetic energy at 0.15 s
 * and 144 J at 0.4 s, its areas 72 % short of the sphere the points span;
 * moved with the re-mapped velocity, 0.087 J and 0.22 J, 0.03 % short
 * (docs/3d.md "MUSL: the skin's points move with the re-mapped
 * velocity"). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "membrane_law.h"
#include "step.h"
#include "mpm3.h"
#include "mpm3_membrane.h"
#include "sim3_walls.h"

static void place_at(lm3_sim *sim, size_t q)
{
    lm3_mpoints *p = &sim->mem->p;
    double x[3] = {p->x[0][q], p->x[1][q], p->x[2][q]}, d[3];
    lm3_place(&sim->grid, x, &p->node[q], d);
    for (int a = 0; a < 3; a++) p->d[a][q] = d[a];
}

static void weights_of(const lm3_sim *sim, size_t q, lm3_weights *w)
{
    const lm3_mpoints *p = &sim->mem->p;
    double d[3] = {p->d[0][q], p->d[1][q], p->d[2][q]};
    lm3_weights_at(&sim->grid, p->node[q], d, w);
}

/* Node (a, b, c) of a stencil, its N and gradient. */
static long stencil_node(const lm3_grid *g, const lm3_weights *w, int a, int b, int c,
                         double *N, double G[3])
{
    *N = w->w[0][a] * w->w[1][b] * w->w[2][c];
    G[0] = w->g[0][a] * w->w[1][b] * w->w[2][c];
    G[1] = w->w[0][a] * w->g[1][b] * w->w[2][c];
    G[2] = w->w[0][a] * w->w[1][b] * w->g[2][c];
    return w->node + (c * g->s[1] + b) * g->s[0] + a;
}

static double area_of(const lm3_mpoints *p, size_t q)
{
    return p->A0[q] * exp(p->e[0][q] + p->e[1][q]);
}

void lm3_membrane_p2g(lm3_sim *sim)
{
    if (!sim->mem) return;
    lm3_mpoints *p = &sim->mem->p;
    lm3_grid *g = &sim->grid;
    const int W = g->W;
    for (size_t q = 0; q < p->n; q++) {
        const lm3_mdef *def = &sim->mem->mem[p->mem[q]].def;
        place_at(sim, q);
        lm3_weights w;
        weights_of(sim, q, &w);
        const double m = p->m[q], A = area_of(p, q), V = A * def->mat.thickness;
        const double v[3] = {p->v[0][q], p->v[1][q], p->v[2][q]};
        const double t1[3] = {p->t1[0][q], p->t1[1][q], p->t1[2][q]};
        const double t2[3] = {p->t2[0][q], p->t2[1][q], p->t2[2][q]};
        const double s11 = p->s[0][q], s22 = p->s[1][q], s12 = p->s[2][q];
        double S[3][3];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                S[i][j] = s11 * t1[i] * t1[j] + s22 * t2[i] * t2[j] +
                          s12 * (t1[i] * t2[j] + t2[i] * t1[j]);
        /* the load: pressure along the normal, the damping against the motion */
        double fe[3];
        for (int a = 0; a < 3; a++)
            fe[a] = def->pressure * A * p->nrm[a][q] - def->damping * m * v[a];
        for (int c = 0; c < W; c++)
            for (int b = 0; b < W; b++)
                for (int a = 0; a < W; a++) {
                    double N, G[3];
                    long i = stencil_node(g, &w, a, b, c, &N, G);
                    g->m[i] += N * m;
                    for (int e = 0; e < 3; e++) {
                        g->p[e][i] += N * m * v[e];
                        g->f[e][i] += N * fe[e] -
                                      V * (S[e][0] * G[0] + S[e][1] * G[1] + S[e][2] * G[2]);
                    }
                }
    }
}

/* The nodes the pins hold: held[i] = the first pin (1-based) whose points
 * reach node i. */
static void mark_held(lm3_sim *sim)
{
    lm3_membranes *ms = sim->mem;
    const lm3_grid *g = &sim->grid;
    memset(ms->held, 0, g->nn * sizeof *ms->held);
    for (int k = 0; k < ms->npins; k++)
        for (size_t j = 0; j < ms->pins[k].n; j++) {
            lm3_weights w;
            weights_of(sim, ms->pins[k].idx[j], &w);
            for (int c = 0; c < g->W; c++)
                for (int b = 0; b < g->W; b++)
                    for (int a = 0; a < g->W; a++) {
                        double N, G[3];
                        long i = stencil_node(g, &w, a, b, c, &N, G);
                        if (N > 0 && !ms->held[i]) ms->held[i] = k + 1;
                    }
        }
}

static void refill(lm3_grid *g, double *const *f, int nf)
{
    static const int comp[6] = {0, 1, 2, 0, 1, 2};
    lm3_grid_fill(g, nf, f, comp);
}

void lm3_membrane_hold(lm3_sim *sim)
{
    lm3_membranes *ms = sim->mem;
    if (!ms || ms->npins == 0) return;
    lm3_grid *g = &sim->grid;
    mark_held(sim);
    for (int k = 0; k < ms->npins; k++)
        for (int a = 0; a < 3; a++) ms->pins[k].reaction[a] = 0;
    /* here f holds a_i = f_i / m_i and p holds v_i^L (step_grid_update) */
    for (size_t i = 0; i < g->nn; i++) {
        if (!ms->held[i]) continue;
        lm3_mpin *pn = &ms->pins[ms->held[i] - 1];
        for (int a = 0; a < 3; a++) {
            pn->reaction[a] -= g->m[i] * g->f[a][i];
            g->f[a][i] = 0;
            g->p[a][i] = 0;
        }
    }
    double *const f[6] = {g->f[0], g->f[1], g->f[2], g->p[0], g->p[1], g->p[2]};
    refill(g, f, 6);
}

void lm3_membrane_g2p(lm3_sim *sim)
{
    if (!sim->mem) return;
    lm3_mpoints *p = &sim->mem->p;
    lm3_grid *g = &sim->grid;
    const double dt = sim->def.dt;
    const int W = g->W, musl = sim->def.scheme == LM_MUSL;
    for (size_t q = 0; q < p->n; q++) {
        lm3_weights w;
        weights_of(sim, q, &w);
        if (!p->pin[q]) {
            double acc[3] = {0, 0, 0}, u[3] = {0, 0, 0};
            for (int c = 0; c < W; c++)
                for (int b = 0; b < W; b++)
                    for (int a = 0; a < W; a++) {
                        double N, G[3];
                        long i = stencil_node(g, &w, a, b, c, &N, G);
                        for (int e = 0; e < 3; e++) {
                            acc[e] += N * g->f[e][i];
                            u[e] += N * g->p[e][i];
                        }
                    }
            /* the damping load's work over the step: its force -c m v^k
             * (p2g's) times the point's displacement at the grid's mean
             * velocity over the step, u - dt a / 2 (v_i^k = v_i^L - dt a_i);
             * under MUSL the point moves later (update_point), and is
             * accounted there */
            const double c = sim->mem->mem[p->mem[q]].def.damping;
            if (c > 0 && !musl) {
                double vu = 0;
                for (int e = 0; e < 3; e++) vu += p->v[e][q] * (u[e] - 0.5 * dt * acc[e]);
                sim->mem->damped += c * p->m[q] * vu * dt;
            }
            for (int e = 0; e < 3; e++) {
                p->v[e][q] += dt * acc[e];
                if (!musl) p->x[e][q] += dt * u[e];
            }
        }
        if (!musl) continue;
        const double m = p->m[q];
        for (int c = 0; c < W; c++)
            for (int b = 0; b < W; b++)
                for (int a = 0; a < W; a++) {
                    double N, G[3];
                    long i = stencil_node(g, &w, a, b, c, &N, G);
                    for (int e = 0; e < 3; e++) g->v[e][i] += N * m * p->v[e][q];
                }
    }
}

static void normalise(double t[3])
{
    double l = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    if (l > 0)
        for (int a = 0; a < 3; a++) t[a] /= l;
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* t2 made a unit vector across t1 in their plane (Gram-Schmidt). */
static void orthonormalise(double t1[3], double t2[3])
{
    normalise(t1);
    double c = dot3(t1, t2);
    for (int a = 0; a < 3; a++) t2[a] -= c * t1[a];
    normalise(t2);
}

/* The law at the principal strains, turned back into the frame. */
static void stress_of(const lm_material *mat, const double e[3], double s[3])
{
    double m = 0.5 * (e[0] + e[1]), h = 0.5 * (e[0] - e[1]), r = hypot(h, e[2]);
    double e1 = m + r, e2 = m - r, s1, s2;
    lm_membrane_stress_biaxial(mat, e1, e2, &s1, &s2);
    /* principal direction 1 at angle th in the frame: cos 2th = h / r,
     * sin 2th = e12 / r (none when r = 0: isotropic, any frame) */
    double c2 = r > 0 ? h / r : 1, s2t = r > 0 ? e[2] / r : 0;
    double sm = 0.5 * (s1 + s2), sh = 0.5 * (s1 - s2);
    s[0] = sm + sh * c2;
    s[1] = sm - sh * c2;
    s[2] = sh * s2t;
}

/* One point: L from the grid's strain velocity with the weights at x^k
 * (under MUSL also the point's move with that velocity), then the strain,
 * the frame and the stress (the header's formulas). */
static void update_point(lm3_sim *sim, size_t q)
{
    lm3_mpoints *p = &sim->mem->p;
    const lm3_grid *g = &sim->grid;
    const double dt = sim->def.dt;
    lm3_weights w;
    weights_of(sim, q, &w);
    double L[3][3] = {{0}}, u[3] = {0, 0, 0}, acc[3] = {0, 0, 0};
    for (int c = 0; c < g->W; c++)
        for (int b = 0; b < g->W; b++)
            for (int a = 0; a < g->W; a++) {
                double N, G[3];
                long i = stencil_node(g, &w, a, b, c, &N, G);
                for (int r = 0; r < 3; r++) {
                    u[r] += N * g->v[r][i];
                    acc[r] += N * g->f[r][i];
                    for (int k = 0; k < 3; k++) L[r][k] += g->v[r][i] * G[k];
                }
            }
    if (sim->def.scheme == LM_MUSL) {
        /* the point moves with the re-mapped velocity its strain is taken
         * from (the header's "MUSL"); the damping load -c m v^k works
         * along that displacement, v^k = v^{k+1} - dt a (g2p's) */
        const double c = sim->mem->mem[p->mem[q]].def.damping;
        if (c > 0) {
            double vu = 0;
            for (int r = 0; r < 3; r++) vu += (p->v[r][q] - dt * acc[r]) * u[r];
            sim->mem->damped += c * p->m[q] * vu * dt;
        }
        for (int r = 0; r < 3; r++) p->x[r][q] += dt * u[r];
    }
    double t1[3] = {p->t1[0][q], p->t1[1][q], p->t1[2][q]};
    double t2[3] = {p->t2[0][q], p->t2[1][q], p->t2[2][q]};
    double Lt1[3], Lt2[3];
    for (int r = 0; r < 3; r++) {
        Lt1[r] = L[r][0] * t1[0] + L[r][1] * t1[1] + L[r][2] * t1[2];
        Lt2[r] = L[r][0] * t2[0] + L[r][1] * t2[1] + L[r][2] * t2[2];
    }
    double D11 = dot3(t1, Lt1), D22 = dot3(t2, Lt2), D12 = 0.5 * (dot3(t1, Lt2) + dot3(t2, Lt1));
    double e[3] = {p->e[0][q], p->e[1][q], p->e[2][q]}, wr = -D12;
    p->e[0][q] = e[0] + dt * (D11 - 2 * wr * e[2]);
    p->e[1][q] = e[1] + dt * (D22 + 2 * wr * e[2]);
    p->e[2][q] = e[2] + dt * (D12 + wr * (e[0] - e[1]));
    for (int a = 0; a < 3; a++) {
        t1[a] += dt * Lt1[a];
        t2[a] += dt * Lt2[a];
    }
    orthonormalise(t1, t2);
    for (int a = 0; a < 3; a++) {
        p->t1[a][q] = t1[a];
        p->t2[a][q] = t2[a];
    }
    const lm_material *mat = &sim->mem->mem[p->mem[q]].def.mat;
    double en[3] = {p->e[0][q], p->e[1][q], p->e[2][q]}, s[3];
    stress_of(mat, en, s);
    for (int k = 0; k < 3; k++) p->s[k][q] = s[k];
}

/* The frame's normal t1 x t2. */
static void frame_normals(lm3_mpoints *p, size_t first, size_t count)
{
    for (size_t q = first; q < first + count; q++) {
        p->nrm[0][q] = p->t1[1][q] * p->t2[2][q] - p->t1[2][q] * p->t2[1][q];
        p->nrm[1][q] = p->t1[2][q] * p->t2[0][q] - p->t1[0][q] * p->t2[2][q];
        p->nrm[2][q] = p->t1[0][q] * p->t2[1][q] - p->t1[1][q] * p->t2[0][q];
    }
}

/* The frame turned into the plane across the construction's normal n
 * (t1 projected on it, t2 = n x t1): the construction then decides the
 * tangent plane the law and the force see, as the 2D membranes' normals
 * without connectivity decide their tangent. */
static void frame_to_normal(lm3_mpoints *p, size_t q)
{
    double n[3] = {p->nrm[0][q], p->nrm[1][q], p->nrm[2][q]};
    double t1[3] = {p->t1[0][q], p->t1[1][q], p->t1[2][q]}, c = dot3(t1, n);
    for (int a = 0; a < 3; a++) t1[a] -= c * n[a];
    normalise(t1);
    p->t1[0][q] = t1[0];
    p->t1[1][q] = t1[1];
    p->t1[2][q] = t1[2];
    p->t2[0][q] = n[1] * t1[2] - n[2] * t1[1];
    p->t2[1][q] = n[2] * t1[0] - n[0] * t1[2];
    p->t2[2][q] = n[0] * t1[1] - n[1] * t1[0];
}

static lm_status check_point(lm3_sim *sim, size_t q)
{
    const lm3_mpoints *p = &sim->mem->p;
    const lm3_grid *g = &sim->grid;
    int k = p->mem[q];
    size_t j = q - sim->mem->mem[k].first;
    for (int a = 0; a < 3; a++) {
        double x = p->x[a][q];
        if (!isfinite(x) || !isfinite(p->v[a][q]) || !isfinite(p->e[a][q])) {
            snprintf(sim->err, sizeof sim->err,
                     "t = %g (step %ld): point %zu of membrane %d has a non-finite position, "
                     "velocity or strain: unstable (dt above the stable step?)", sim->t,
                     sim->nstep, j + 1, k + 1);
            return LM_ERR_UNSTABLE;
        }
        if (!(x >= g->lo[a] && x <= g->lo[a] + g->n[a] * g->h)) {
            snprintf(sim->err, sizeof sim->err,
                     "t = %g (step %ld): point %zu of membrane %d left the grid at %c = %g "
                     "(the domain is %g to %g)", sim->t, sim->nstep, j + 1, k + 1, "xyz"[a], x,
                     g->lo[a], g->lo[a] + g->n[a] * g->h);
            return LM_ERR_DOMAIN;
        }
    }
    return LM_OK;
}

lm_status lm3_membrane_update(lm3_sim *sim)
{
    lm3_membranes *ms = sim->mem;
    if (!ms) return LM_OK;
    lm3_grid *g = &sim->grid;
    if (ms->npins > 0) {
        for (size_t i = 0; i < g->nn; i++)
            if (ms->held[i])
                for (int a = 0; a < 3; a++) g->v[a][i] = 0;
        refill(g, g->v, 3);
    }
    lm3_mpoints *p = &ms->p;
    for (size_t q = 0; q < p->n; q++) {
        if (!p->pin[q]) update_point(sim, q);
        lm_status st = check_point(sim, q);
        if (st != LM_OK) return st;
    }
    for (int k = 0; k < ms->nmem; k++) {
        lm3_membrane *mb = &ms->mem[k];
        frame_normals(p, mb->first, mb->count);
        if (mb->def.normals == LM3_MN_CONNECTIVITY) continue;
        double *nrm[3] = {p->nrm[0] + mb->first, p->nrm[1] + mb->first, p->nrm[2] + mb->first};
        if (lm3_membrane_construction_normals(sim, k, mb->def.normals, nrm, &mb->undefined) != 0)
            return LM_ERR_INPUT;
        for (size_t q = mb->first; q < mb->first + mb->count; q++)
            if (!p->pin[q]) frame_to_normal(p, q);
    }
    return LM_OK;
}
