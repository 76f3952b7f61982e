/* subcycle.c - multi-rate stepping: the membranes take k sub-steps of
 * dt / k inside each step of the gas and solids (lamina.sim{substeps},
 * docs/api.md; issue 36 item 1).
 *
 * Why. A membrane is light and stiff: Box 9's (rho 0.5, E 1e6) carries
 * waves at c_M = sqrt(E / ((1 - nu^2) rho)) = 1482, its gas sound at
 * c_G = 11.8. One explicit step for all must keep dt c_M / h under the
 * Courant limit (docs/physics.md §5), 125 times smaller than the gas
 * needs, while the gas is 95 % of the particles. Here the slow group (every
 * body that is not a membrane) steps dt and the fast group (the membranes)
 * dt / k, k chosen so that the membranes' own Courant number is within the
 * limit (the check is made per group: lm_sim_courant_body counts a
 * membrane's speed as c_M / k).
 *
 * The step (subcycling of the fast group's nodes, a node-based multi-rate
 * explicit scheme; cf. Belytschko, Yen & Mullen 1979 for finite elements,
 * here on the MPM grid where the groups share nodes):
 *
 *  0. Shape functions of all particles at x^n, their grid sums m_i, p_i,
 *     f_i (the standard steps 0-2, gravity included), and the membranes'
 *     own sums m^M_i, p^M_i, f^M_i. The slow group's share is the
 *     difference: m^G = m - m^M, p^G = p - p^M, f^G = f - f^M. f^G (its
 *     stress divergence and gravity) is held for the whole step: the slow
 *     group's stresses change on its own time scale.
 *  1. Sub-step s = 0..k-1 with dt_s = dt / k: the membranes' sums m^M, p^M,
 *     f^M at their present positions (s > 0: shape functions again); the
 *     node carries M_i = m^G_i + m^M_i, P_i = p^G_i + p^M_i and
 *     F_i = f^G_i + f^M_i; the standard step 3 (P^L = P + dt_s F, the walls)
 *     and 4 (a_i = F_i / M_i, v^L_i = P^L_i / M_i); the membrane points'
 *     FLIP update v_p += dt_s sum_i N_ip a_i, x_p += dt_s sum_i N_ip v^L_i,
 *     their strain velocity (MUSL: the re-map of their new momenta plus
 *     the slow group's, over M_i; USL: v^L) and their stress update over
 *     dt_s. The slow group's particles do not move within the step, so its
 *     re-map after the velocity change A so far is p^G(x^n) + C A with C
 *     its consistent mass matrix sum_p m_p N_ip N_jp, built once a step on
 *     the rows the membranes can reach: the re-map without visiting its
 *     particles, and with k = 1 the plain step's. The slow group's nodal momentum moves with
 *     the node, by its share of the nodal impulse: p^G_i += dt_s m^G_i a_i;
 *     the step keeps A_i = sum_s dt_s a_i (its velocity change) and
 *     X_i = sum_s dt_s v^L_i (its displacement).
 *  2. The slow group's particles at the end, with their shape functions of
 *     x^n: v_p += sum_i N_ip A_i, x_p += sum_i N_ip X_i (PIC blend, if
 *     asked, towards sum_i N_ip X_i / dt); their strain velocity (MUSL:
 *     the re-map of every particle's mean velocity over the step,
 *     (x^{n+1} - x^n) / dt, over the last sub-step's M_i; USL: X_i / dt)
 *     and their stress update over dt. Not the end velocities: beside a
 *     membrane the nodes ring at the membrane's frequency within the step,
 *     and a strain from their velocity at its end (one phase of the
 *     ringing, times dt) does not match the work f^G . X the held force
 *     did: on Box 9's dog-bone that mismatch fed the gas's FLIP noise
 *     until a gas point inverted (k = 4 at t = 0.86, k = 5 at t = 0.72);
 *     strained by the displacement k = 4 runs to t = 5.1 (phase 2 below,
 *     docs/performance.md "Multi-rate stepping").
 *
 * What is conserved. Momentum: the membranes gain sum_s sum_i m^M_i a_i
 * dt_s (sum_p m_p N_ip = m^M_i, lumped mass), the slow group
 * sum_p m_p sum_i N_ip A_i = sum_i m^G_i A_i = sum_s sum_i m^G_i a_i dt_s,
 * together sum_s sum_i M_i a_i dt_s = sum_s dt_s sum_i (f^G_i + f^M_i): the
 * internal forces of each group sum to zero at every sub-step, so the
 * exchange between the groups balances exactly over the step (what the
 * slow group receives through A_i is what the nodes took from the
 * membranes), and only the walls and gravity change the total, as in the
 * single-rate step. With k = 1 and USL the scheme is the single-rate step
 * (tests/physics/substeps.lua); with MUSL it differs in the slow group's
 * strain, re-mapped from the mean velocities (phase 2).
 * Energy: the slow group's stress works on the displacement X_i it is
 * given (-sum_p V_p sigma_p : sym(sum_i X_i (x) G_ip) = sum_i f^G_i . X_i,
 * USL; MUSL the same displacements re-mapped), and the held force f^G does
 * that work on the nodes during the sub-steps, so what the gas loses as
 * internal energy the nodes receive as work; the membrane's strain energy is exchanged with the nodes every
 * sub-step as in the single-rate step. sim:energy() sums the particles'
 * energies, all at t^{n+1} after the step: no term is left half-way.
 *
 * Why it is stable. Each sub-step is the single-rate explicit step for a
 * system whose stiff part is the membrane alone (the slow group's force is
 * a held load, not a stiffness, within the step), on nodes at least as
 * heavy as the membrane's share: dt_s c_M / h within the Courant limit
 * bounds it as it bounds the single-rate step. The slow group's update is
 * the single-rate step with dt for a material whose waves c_G satisfy
 * dt c_G / h within the limit; the coupling lags by at most one step the
 * slow group's response to the membrane's motion, a force change of order
 * dt c_G / h of the pressure, which the same limit keeps small. What it
 * costs: the held force's energy error is the slow group's at its own
 * (k times longer) step, first order in dt per unit time as any explicit
 * step's (tests/physics/substeps_energy.lua: +0.030 % over 0.05 s with
 * k = 4 where the plain step gains +0.0042 %); where the slow group's own
 * particle speeds approach its Courant limit (the dog-bone's FLIP noise)
 * that error grows until a point inverts. dt must be chosen for the slow
 * group's sound speed plus its particles' speeds.
 *
 * The axisymmetric hoop term, links and point pins on membranes: each in
 * the group whose motion changes it (subcycle_terms.c says how and why).
 *
 * The forms (lamina.sim{multirate}; docs/performance.md "Multi-rate
 * stepping: impulse forms"). The above is "held": f^G in every sub-step,
 * p^G carried lumped while the membranes' MUSL strain reads the consistent
 * p^G(x^n) + C A, so the carried and the strained momenta differ and the
 * sub-step is the symplectic Euler step of no mass matrix: the energy
 * drifts (+5.4 % over t = 1 on the ringing circle with k = 10). "impulse"
 * gives the step's whole Dt f^G in the first sub-step (r-RESPA / Verlet-I's
 * kick, Tuckerman, Berne & Martyna 1992), carries p^G as the consistent
 * re-map on every node (mr_consistent: what a P2G of all particles would
 * give) and strains the gas (MUSL) by the sum of the sub-steps' re-mapped
 * velocities R (the velocities that strained the membranes): each sub-step
 * is then the plain FLIP-MUSL step with the gas's stress frozen, on a frozen
 * grid the symplectic Euler step for the mass matrix M C^-1 M, and the kick
 * composed with them is symplectic too: no drift (the plain step's trend),
 * an oscillation of first order in dt. Its price: the loaded membrane
 * swings at the step's rate (the kick arrives before the tension that
 * balances it), and on Box 9's dog-bone a gas point beside it goes
 * unstable (t = 0.43 at 16 x, 0.82 at 8 x). The other forms are the
 * screened variants (mr_weight, mr_split_force, mr_hybrid_force,
 * mr_end_kick).
 *
 * fast_band (lamina.sim{fast_band = w}, subcycle_gasband.c): the gas points
 * within w cells of the membranes' stencils join the fast group, wherever
 * this file says "the membranes" of the sub-steps (their sums, moves,
 * re-map and stress), so that the groups meet inside the gas; with "held"
 * the nodes no fast point reaches take the plain step's displacement.
 *
 * Not with what changes the grid's forces by the node (contact's own
 * fields, pins that hold nodes, heavy end points, damping, the corrected
 * mass, the cell stress): refused by name. Segment
 * membranes (membrane_force.c) take their net tension, hold and move in
 * every sub-step as in the single-rate step. Deterministic: every sum in particle order, the threads' split
 * only in the standard steps (the same bits per thread count). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gather.h"
#include "step.h"
#include "sim_work.h"
#include "simd2.h"
#include "step_kernels.h"
#include "subcycle_band.h"
#include "subcycle_gasband.h"
#include "subcycle_kick.h"
#include "subcycle_runs.h"
#include "subcycle_terms.h"
#include "threads.h"
#include "util.h"

/* The nodal arrays of the scheme (nn nodes each, ghosts included). */
typedef struct lm_subcycle {
    size_t nn;
    double *buf;
    double *mG, *pGx, *pGy, *fGx, *fGy;   /* the slow group's share */
    double *Ax, *Ay, *Xx, *Xy;            /* its velocity change, displacement */
    double *mM, *pMx, *pMy, *fMx, *fMy;   /* the membranes' sums of a sub-step */
    double *qGx, *qGy;                    /* p^G at x^n; its re-map's change */
    double *Vx, *Vy;                      /* v^L of the last sub-step */
    double *Rx, *Ry;                      /* the impulse forms' (MUSL) re-mapped
                                             displacement sum_s dt_s v^R_s */
    double *fPx, *fPy;                    /* SPLIT: the last step's f^G */
    int fP_set;                           /* fP holds a step's f^G */
    int k;                                /* the step's sub-steps */
    double *C;                            /* the slow group's consistent mass
                                             sum_p m_p N_ip N_jp, B x B a node */
    int B;                                /* 2 sw - 1: the offsets j - i */
    double *xs;                           /* every particle's x^n, y^n, and a
                                             membrane point's x, y before the
                                             last sub-step (4 a particle) */
    size_t xcap;
    unsigned char *near;                  /* rows of C the membranes can read */
    long *rows;                           /* those nodes, in order */
    size_t nrows;
    int whole;                            /* the band is every node: the
                                             standard steps sweep them */
    int kick;                             /* the impulse forms' band after
                                             the kick (subcycle_kick.c) */
    lm_band *band;                        /* the nodes the sub-steps sweep
                                             (subcycle_band.c) */
    lm_gasband *gb;                       /* fast_band: the gas points in the
                                             fast group (subcycle_gasband.c) */
} lm_subcycle;

void lm_subcycle_free(lm_subcycle *s)
{
    if (!s) return;
    LU_FREE_ALL(s->buf, s->near, s->rows, s->xs);
    lm_band_free(s->band);
    lm_gasband_free(s->gb);
    free(s);
}

/* Room for 4 doubles a particle. */
static lm_status reserve_points(lm_sim *sim, lm_subcycle *s)
{
    size_t n = sim->p.n;
    lm_status st = lm_gasband_reserve(sim, &s->gb);
    if (st != LM_OK) return st;
    if (n <= s->xcap) return LM_OK;
    double *x = realloc(s->xs, 4 * n * sizeof *x);
    if (!x) {
        snprintf(sim->err, sizeof sim->err, "out of memory for multi-rate stepping's %zu "
                 "particles", n);
        return LM_ERR_MEMORY;
    }
    s->xs = x;
    s->xcap = n;
    return LM_OK;
}

static lm_status reserve(lm_sim *sim)
{
    size_t nn = lm_grid_nodes(&sim->grid);
    if (sim->work->sub && sim->work->sub->nn == nn) return reserve_points(sim, sim->work->sub);
    lm_subcycle_free(sim->work->sub);
    sim->work->sub = NULL;
    lm_subcycle *s = calloc(1, sizeof *s);
    const int B = 2 * sim->grid.sw - 1;
    double *b = s ? calloc((22 + (size_t)(B * B)) * nn, sizeof *b) : NULL;
    unsigned char *near = b ? calloc(nn, 1) : NULL;
    long *rows = near ? calloc(nn, sizeof *rows) : NULL;
    lm_band *band = rows ? lm_band_new(&sim->grid) : NULL;
    if (!band) {
        free(rows);
        free(near);
        free(b);
        free(s);
        snprintf(sim->err, sizeof sim->err, "out of memory for multi-rate stepping's %zu nodes",
                 nn);
        return LM_ERR_MEMORY;
    }
    s->nn = nn;
    s->buf = b;
    double **f[] = {&s->mG, &s->pGx, &s->pGy, &s->fGx, &s->fGy, &s->Ax, &s->Ay,
                    &s->Xx, &s->Xy, &s->mM, &s->pMx, &s->pMy, &s->fMx, &s->fMy,
                    &s->qGx, &s->qGy, &s->Vx, &s->Vy, &s->Rx, &s->Ry, &s->fPx, &s->fPy};
    for (size_t k = 0; k < 22; k++) *f[k] = b + k * nn;
    s->C = b + 22 * nn;
    s->near = near;
    s->rows = rows;
    s->band = band;
    s->B = B;
    sim->work->sub = s;
    return reserve_points(sim, s);
}

/* The fastest membrane wave of the sim (0: no membrane). */
static double membrane_speed(const lm_sim *sim)
{
    double c = 0;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        if (!bd->membrane || bd->count == 0) continue;
        double cb = lm_material_wave_speed(sim->mats[bd->mat]);
        if (bd->force == LM_MFORCE_SEGMENT) cb /= LM_SEGMENT_COURANT;
        if (cb > c) c = cb;
    }
    return c;
}

int lm_subcycle_count(const lm_sim *sim)
{
    int k = sim->def.substeps;
    if (k == 0) return 1;
    if (k > 0) return k;
    /* auto: the fewest sub-steps that put the membranes within the limit */
    double c = membrane_speed(sim), h = fmin(sim->grid.hx, sim->grid.hy);
    double n = ceil(sim->def.dt * c / (h * lm_sim_courant_limit(sim)) * (1 - 1e-12));
    return n < 1 ? 1 : n > LM_SUBSTEPS_MAX ? LM_SUBSTEPS_MAX : (int)n;
}

long lm_subcycle_fast_gas(const lm_sim *sim)
{
    const lm_subcycle *s = sim->work ? sim->work->sub : NULL;
    return s && s->gb ? (long)s->gb->n : 0;
}

/* What the scheme cannot do, by name (the header says why). */
static lm_status refuse(lm_sim *sim)
{
    const char *what = NULL;
    if (sim->contact) what = "contact (sim:contact)";
    else if (lm_subcycle_heavy_point(sim)) what = "a heavy end point (end_mass)";
    else if (sim->def.stress == LM_STRESS_CELL) what = "stress = \"cell\"";
    else if (sim->def.mass == LM_MASS_CORRECTED) what = "mass = \"corrected\"";
    else if (sim->def.mass == LM_MASS_MEMBRANE) what = "mass = \"membrane\"";
    else if (sim->def.damping > 0) what = "damping";
    else if (sim->def.apic) what = "transfer = \"apic\"";   /* its transfers are FLIP's */
    else what = lm_gasband_refusal(sim);
    if (!what) return LM_OK;
    snprintf(sim->err, sizeof sim->err,
             "substeps (multi-rate stepping) does not work with %s; leave substeps out", what);
    return LM_ERR_INPUT;
}

/* for (q over every membrane point, in particle order) */
#define FOR_FAST(sim, q)                                                          \
    for (int b_ = 0; b_ < (sim)->nbodies; b_++)                                   \
        if ((sim)->bodies[b_].membrane)                                           \
            for (size_t q = (sim)->bodies[b_].first;                              \
                 q < (sim)->bodies[b_].first + (sim)->bodies[b_].count; q++)

/* The membranes' m^M, p^M, f^M (internal force and gravity) at their
 * stored shape functions, folded at the walls; a segment membrane's net
 * tension as lm_membrane_segment_forces left it (membrane_force.c). */
static void fast_sums(lm_sim *sim, lm_subcycle *s, const lm_band *band)
{
    const lm_grid *g = &sim->grid;
    double *const f[5] = {s->mM, s->pMx, s->pMy, s->fMx, s->fMy};
    if (band) lm_band_zero(band, 5, f);   /* a sub-step's: the rest stays 0 */
    else for (int k = 0; k < 5; k++) memset(f[k], 0, s->nn * sizeof *f[k]);
    lm_runs_mass_forces(sim, f);   /* lm_k_scatter_mass_forces's, by runs */
    if (s->gb) lm_gasband_sums(sim, s->gb, f);
    static const lm_comp comp[5] = {LM_COMP_SCALAR, LM_COMP_X, LM_COMP_Y, LM_COMP_X, LM_COMP_Y};
    lm_grid_fold(g, 5, f, comp);
    if (s->gb) lm_gasband_reach(s->gb, s->mM, band == NULL);   /* band NULL: the step's start */
    lm_subcycle_fast_terms(sim, s->mM, s->pMx, s->pMy, s->fMx, s->fMy);   /* hoop, links, pins */
    const size_t n = band ? band->n : s->nn;
    for (size_t r = 0; r < n; r++) {
        const size_t i = band ? (size_t)band->idx[r] : r;
        s->fMx[i] += s->mM[i] * sim->def.gx;
        s->fMy[i] += s->mM[i] * sim->def.gy;
    }
}

/* The membranes' re-mapped momenta m_p v_p N_ip into (ux, uy), folded. */
static void fast_remap(lm_sim *sim, const lm_subcycle *s, double *ux, double *uy,
                       const lm_band *band)
{
    double *const f[2] = {ux, uy};
    lm_band_zero(band, 2, f);
    lm_runs_momentum(sim, f);      /* lm_k_scatter_momentum's, by runs */
    if (s->gb) lm_gasband_momentum(sim, s->gb, f);
    static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
    lm_grid_fold(&sim->grid, 2, f, comp);
}

/* The slow group's consistent mass matrix C_ij = sum_p m_p N_ip N_jp
 * (unfolded, ghosts included), row i holding its B x B offsets j - i: with
 * it the MUSL re-map of the slow group's particles after a velocity change
 * sum_j N_jp A_j is p^G + C A without visiting them (they do not move
 * within the step). */
static LM_FORCE_INLINE void consistent_rows(const lm_sim *sim, lm_subcycle *s, size_t q,
                                            const int W)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const int B = 2 * W - 1;
    double Nl[9];   /* the B-spline's rebuilt from its place (step_kernels.h) */
    const double *N = lm_k_weights_N(p, q, W, Nl);
    const double m = p->m[q];
    for (int b1 = 0; b1 < W; b1++)
        for (int a1 = 0; a1 < W; a1++) {
            const long i = lm_stencil_row(g, p->node[q], b1) + a1;
            if (!s->near[i]) continue;
            const double w = m * N[b1 * W + a1];
            double *row = s->C + (size_t)i * (size_t)(B * B);
            for (int b2 = 0; b2 < W; b2++) {
                /* d[a2] += w N[b2 W + a2]: two at once, each lane the
                 * scalar's product and sum (simd2.h: the same bits) */
                double *d = row + (b2 - b1 + W - 1) * B + W - 1 - a1;
                const double *n = N + b2 * W;
                lm_v2d_store(d, lm_v2d_load(d) + w * lm_v2d_load(n));
                if (W == 3) d[2] += w * n[2];
            }
        }
}

/* Does particle q's stencil reach a node the membranes may read? */
static int touches_near(const lm_sim *sim, const lm_subcycle *s, size_t q)
{
    const lm_grid *g = &sim->grid;
    const int W = g->sw;
    for (int b = 0; b < W; b++) {
        long row = lm_stencil_row(g, sim->p.node[q], b);
        for (int a = 0; a < W; a++)
            if (s->near[row + a]) return 1;
    }
    return 0;
}

/* C's rows where the membranes' re-map can look within the step: the
 * nodes the membranes touch at x^n widened by two nodes each way (a
 * membrane moves less than a cell in a step within the slow group's
 * Courant limit, and a ghost node's image lies two nodes in); every row
 * there whole, as every particle reaching it is summed. */
static void slow_consistent_mass(lm_sim *sim, lm_subcycle *s, int all)
{
    const lm_particles *p = &sim->p;
    const lm_grid *g = &sim->grid;
    const long nn = (long)s->nn, sx = g->sx;
    memset(s->near, all, s->nn);
    for (long i = 0; i < nn && !all; i++) {
        if (!(s->mM[i] > 0)) continue;
        for (long dy = -2; dy <= 2; dy++)
            for (long dx = -2; dx <= 2; dx++) {
                long j = i + dy * sx + dx;
                if (j >= 0 && j < nn) s->near[j] = 1;
            }
    }
    s->nrows = 0;
    const size_t BB = (size_t)(s->B * s->B);
    for (long i = 0; i < nn; i++) {
        if (!s->near[i]) continue;
        s->rows[s->nrows++] = i;
        memset(s->C + (size_t)i * BB, 0, BB * sizeof *s->C);
    }
    for (size_t q = 0; q < p->n; q++) {
        if (lm_gasband_fast(s->gb, sim, q) || !touches_near(sim, s, q)) continue;
        if (g->sw == 2) consistent_rows(sim, s, q, 2);
        else consistent_rows(sim, s, q, 3);
    }
}

/* Rows i and i + 1 of C A into u[i], u[i + 1]: each lane row i's or row
 * i + 1's sum in slow_remap_rows's order (its A one node apart, so the two
 * read neighbouring A: one load), a zero entry adding nothing as there (its
 * product masked to +0, and a sum that starts at +0 is never -0): the same
 * bits (simd2.h). o: the offset of the row's first entry. */
typedef long long lm_v2l __attribute__((vector_size(16)));
static LM_FORCE_INLINE void slow_remap_pair(const lm_subcycle *s, const double *row, long i,
                                            int B, long o, long sx, double *ux, double *uy)
{
    const size_t BB = (size_t)(B * B);
    lm_v2d ax = {0, 0}, ay = {0, 0};
    for (int dy = 0; dy < B; dy++)
        for (int dx = 0; dx < B; dx++) {
            const lm_v2d c = {row[dy * B + dx], row[BB + (size_t)(dy * B + dx)]};
            const lm_v2l nz = c != 0;
            const long j = i + (long)dy * sx + dx - o;
            ax += (lm_v2d)((lm_v2l)(c * lm_v2d_load(s->Ax + j)) & nz);
            ay += (lm_v2d)((lm_v2l)(c * lm_v2d_load(s->Ay + j)) & nz);
        }
    lm_v2d_store(ux + i, ax);
    lm_v2d_store(uy + i, ay);
}

/* (ux, uy) = p^G(x^n) + fold(C A): the slow group's particles' re-mapped
 * momenta had they taken the velocity change A so far. */
static void slow_remap_rows(const lm_sim *sim, const lm_subcycle *s, double *ux, double *uy,
                            const long *rows, size_t nrows)
{
    const lm_grid *g = &sim->grid;
    const int W = g->sw, B = s->B;
    const lm_band *band = s->band;   /* its rows and what they read */
    double *const f[2] = {ux, uy};
    lm_band_zero(band, 2, f);
    for (size_t r = 0; r < nrows; r++) {
        const long i = rows[r];
        const double *row = s->C + (size_t)i * (size_t)(B * B);
        if (r + 1 < nrows && rows[r + 1] == i + 1) {   /* rows i, i + 1 together */
            slow_remap_pair(s, row, i, B, (long)(W - 1) * (g->sx + 1), g->sx, ux, uy);
            r++;
            continue;
        }
        double sx = 0, sy = 0;
        for (int dy = 0; dy < B; dy++)
            for (int dx = 0; dx < B; dx++) {
                double c = row[dy * B + dx];
                if (c == 0) continue;
                long j = i + (long)(dy - W + 1) * g->sx + (dx - W + 1);
                sx += c * s->Ax[j];
                sy += c * s->Ay[j];
            }
        ux[i] = sx;
        uy[i] = sy;
    }
    static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
    lm_grid_fold(g, 2, f, comp);
    for (size_t r = 0; r < band->n; r++) {
        const long i = band->idx[r];
        ux[i] += s->qGx[i];
        uy[i] += s->qGy[i];
    }
}

static void slow_remap(const lm_sim *sim, const lm_subcycle *s, double *ux, double *uy)
{
    slow_remap_rows(sim, s, ux, uy, s->rows, s->nrows);
}

/* The consistent carry p^G = p^G(x^n) + C A: on every row, or after the
 * impulse forms' kick on the band's alone (subcycle_kick.c: p^G elsewhere
 * stays what the kick's re-map made it), through f^M (spent: scratch) so
 * that the fold of the rows outside the band leaves p^G there alone. */
static void slow_carry(const lm_sim *sim, lm_subcycle *s)
{
    const lm_band *band = s->band;
    if (s->whole) {
        slow_remap(sim, s, s->pGx, s->pGy);
        return;
    }
    slow_remap_rows(sim, s, s->fMx, s->fMy, band->idx, band->n);
    for (size_t r = 0; r < band->n; r++) {
        const long i = band->idx[r];
        s->pGx[i] = s->fMx[i];
        s->pGy[i] = s->fMy[i];
    }
}

/* The membrane points' stress over dt from the grid's strain velocity
 * (step 7-8 for them: de = (dt / 2)(L + L^T) along their tangents). */
static void fast_stress(lm_sim *sim, double dt)
{
    const lm_grid *g = &sim->grid;
    lm_particles *p = &sim->p;
    const double rx = 1.0 / g->hx, ry = 1.0 / g->hy;
    FOR_FAST(sim, q) {
        if (lm_k_segment_point(sim, q)) continue;   /* from lengths */
        lm_rate r;
        memset(&r, 0, sizeof r);
        if (g->sw == 2) lm_k_velocity_gradient(g, p, q, g->vx, g->vy, r.L, rx, ry, 2);
        else lm_k_velocity_gradient(g, p, q, g->vx, g->vy, r.L, rx, ry, 3);
        r.dexx = dt * r.L[0];
        r.deyy = dt * r.L[3];
        r.dexy = 0.5 * dt * (r.L[1] + r.L[2]);
        r.w = 0.5 * (r.L[1] - r.L[2]);
        r.dt = dt;
        r.h = fmin(g->hx, g->hy);
        lm_update_at(sim, q, &r, sim->def.axisym);   /* a ring's hoop from its radius */
    }
}

/* What the sub-steps read beyond the membranes' stencils (subcycle_band.c
 * says why): MUSL's re-map of the slow group reads A W - 1 nodes beyond
 * them; USL nothing. */
static int band_need(const lm_sim *sim)
{
    return sim->def.scheme == LM_MUSL ? sim->grid.sw - 1 : 0;
}

static lm_band_nodes band_nodes(lm_subcycle *s)
{
    lm_band_nodes a = {s->mG, s->fGx, s->fGy, s->pGx, s->pGy, s->Ax, s->Ay,
                       s->Xx, s->Xy, s->Vx, s->Vy};
    return a;
}

/* The impulse forms (lamina.sim{multirate}; docs/performance.md
 * "Multi-rate stepping", "Impulse forms"). HELD spreads the slow force
 * evenly, f^G in every sub-step; IMPULSE puts the step's whole impulse
 * Dt f^G in the first (weight k: r-RESPA / Verlet-I's kick, Tuckerman,
 * Berne & Martyna 1992, so that the sub-steps between two kicks are the
 * fast system's own symplectic steps); HALF half of it in the first and
 * half, as a velocity change alone, after the last (mr_end_kick). */
static double mr_weight(const lm_sim *sim, int j, int k)
{
    switch (sim->def.multirate) {
    case LM_MULTIRATE_IMPULSE:
    case LM_MULTIRATE_SPLIT:
    case LM_MULTIRATE_IMPULSE_LUMPED: return j == 0 ? (double)k : 0.0;
    case LM_MULTIRATE_HALF:
    case LM_MULTIRATE_HALF_LUMPED: return j == 0 ? 0.5 * k : 0.0;
    case LM_MULTIRATE_HYBRID: return 0.0;   /* mr_hybrid_force */
    default: return 1.0;
    }
}

/* The slow group's nodal momentum carried as its particles' consistent
 * re-map p^G(x^n) + C A on every node (what a P2G of all particles would
 * give each sub-step), not lumped p^G += dt m^G a. */
static int mr_consistent(const lm_sim *sim)
{
    return sim->def.multirate == LM_MULTIRATE_IMPULSE || sim->def.multirate == LM_MULTIRATE_HALF ||
           sim->def.multirate == LM_MULTIRATE_HELD_CONSISTENT ||
           sim->def.multirate == LM_MULTIRATE_SPLIT || sim->def.multirate == LM_MULTIRATE_HYBRID;
}

/* R += dt v^R, the re-mapped velocities MUSL strained the membranes with
 * (on the band; the kick's far nodes: subcycle_kick.c) */
static void mr_remapped_displacement(lm_subcycle *s, const lm_grid *g, double dt)
{
    for (size_t r = 0; r < s->band->n; r++) {
        const long i = s->band->idx[r];
        s->Rx[i] += dt * g->vx[i];
        s->Ry[i] += dt * g->vy[i];
    }
}

/* HALF's second half kick: the velocity change (Dt / 2) f^G / M_i (the last
 * sub-step's M_i, the walls applied) to the slow group's A and to the
 * membrane points at their last shape functions; no displacement. */
static void mr_end_kick(lm_sim *sim, lm_subcycle *s, double Dt)
{
    lm_grid *g = &sim->grid;
    lm_particles *p = &sim->p;
    for (size_t i = 0; i < s->nn; i++) {
        double r = g->m[i] > 0 ? 0.5 * Dt / g->m[i] : 0;
        g->ax[i] = s->fGx[i] * r;
        g->ay[i] = s->fGy[i] * r;
    }
    lm_grid_apply_bc(g, g->ax, g->ay);
    double *const fill[2] = {g->ax, g->ay};
    static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
    lm_grid_fill(g, 2, fill, comp);
    for (size_t i = 0; i < s->nn; i++) {
        s->Ax[i] += g->ax[i];
        s->Ay[i] += g->ay[i];
    }
    FOR_FAST(sim, q) {
        lm_weights w;
        lm_weights_of(sim, q, &w);
        p->vx[q] += lm_gather_rows(g, &w, p->node[q], g->ax);
        p->vy[q] += lm_gather_rows(g, &w, p->node[q], g->ay);
    }
    for (size_t r = 0; s->gb && r < s->gb->n; r++) {
        const size_t q = s->gb->idx[r];
        lm_weights w;
        lm_weights_of(sim, q, &w);
        p->vx[q] += lm_gather_rows(g, &w, p->node[q], g->ax);
        p->vy[q] += lm_gather_rows(g, &w, p->node[q], g->ay);
    }
}

/* SPLIT: the last step's slow force f^P held over the sub-steps and the
 * change f^G - f^P kicked in the first: F = k f^G + (1 - k) f^P + f^M there,
 * f^P + f^M after (the grid's forces already hold wG f^G + f^M). */
static void mr_split_force(lm_sim *sim, lm_subcycle *s, int first)
{
    lm_grid *g = &sim->grid;
    const double w = first ? 1 - (double)s->k : 1;
    for (size_t i = 0; i < s->nn; i++) {
        g->fx[i] += w * s->fPx[i];
        g->fy[i] += w * s->fPy[i];
    }
}

/* HYBRID: f^G kicked (weight k in the first sub-step, 0 after) where the
 * membranes had no mass at the step's start (fPx: 1 there, 0 elsewhere),
 * held (weight 1 in every sub-step) where they had; the grid's forces hold
 * f^M alone (wG = 0) when this is called. */
static void mr_hybrid_force(lm_sim *sim, lm_subcycle *s, int first)
{
    lm_grid *g = &sim->grid;
    const double k = (double)s->k;
    for (size_t i = 0; i < s->nn; i++) {
        double w = s->fPx[i] > 0 ? (first ? k : 0) : 1;
        g->fx[i] += w * s->fGx[i];
        g->fy[i] += w * s->fGy[i];
    }
}

/* One sub-step of dt for the membranes (phase 1 of the header): the band's
 * nodes (subcycle_band.c); the rest follow at the step's end. wG: the
 * slow force's weight in it (mr_weight). */
static lm_status sub_step(lm_sim *sim, lm_subcycle *s, int j, double dt, double wG)
{
    lm_grid *g = &sim->grid;
    lm_particles *p = &sim->p;
    const lm_band *band = s->band;   /* the nodes swept (subcycle_band.c) */
    if (j > 0) {
        const double rx = 1.0 / g->hx, ry = 1.0 / g->hy;
        FOR_FAST(sim, q) lm_k_shape(sim, p, q, rx, ry);
        if (s->gb) lm_gasband_shape(sim, s->gb);
        lm_band_nodes bn = band_nodes(s);
        if (s->kick && !s->whole && lm_kick_band_grow(s->band, sim, &bn, s->Rx, s->Ry, j, dt)) {
            lm_band_all(s->band);   /* a stencil left S: every node from here */
            s->whole = 1;
        } else if (!s->whole && !s->kick) {
            lm_band_grow(s->band, sim, &bn, j, dt);
        }
        lm_membrane_segment_forces(sim);
        fast_sums(sim, s, band);
    }
    for (size_t r = 0; r < band->n; r++) {
        const long i = band->idx[r];
        g->m[i] = s->mG[i] + s->mM[i];
        g->px[i] = s->pGx[i] + s->pMx[i];
        g->py[i] = s->pGy[i] + s->pMy[i];
        g->fx[i] = wG * s->fGx[i] + s->fMx[i];   /* wG: mr_weight */
        g->fy[i] = wG * s->fGy[i] + s->fMy[i];
    }
    if (sim->def.multirate == LM_MULTIRATE_SPLIT) mr_split_force(sim, s, j == 0);
    if (sim->def.multirate == LM_MULTIRATE_HYBRID) mr_hybrid_force(sim, s, j == 0);
    if (s->whole) {
        lm_step_grid_update(sim);              /* 3: P^L, the walls, pins */
        lm_step_g2p_nodes(sim, g->vx, g->vy);  /* 4: a_i, v^L_i, ghosts filled */
    } else {
        lm_band_grid_update(sim, band);
        lm_band_g2p_nodes(sim, band, g->vx, g->vy);
    }
    for (size_t r = 0; r < band->n; r++) {
        const long i = band->idx[r];
        s->pGx[i] += dt * s->mG[i] * g->ax[i];   /* the slow group's share */
        s->pGy[i] += dt * s->mG[i] * g->ay[i];
        s->Ax[i] += dt * g->ax[i];
        s->Ay[i] += dt * g->ay[i];
        s->Xx[i] += dt * g->vx[i];
        s->Xy[i] += dt * g->vy[i];
        s->Vx[i] = g->vx[i];
        s->Vy[i] = g->vy[i];
    }
    if (mr_consistent(sim)) slow_carry(sim, s);   /* p^G(x^n) + C A */
    const double pic = sim->def.pic;
    FOR_FAST(sim, q) {   /* x before this sub-step (the last one's is kept) */
        s->xs[4 * q + 2] = p->x[q];
        s->xs[4 * q + 3] = p->y[q];
    }
    for (size_t r = 0; s->gb && r < s->gb->n; r++) {
        const size_t q = s->gb->idx[r];
        s->xs[4 * q + 2] = p->x[q];
        s->xs[4 * q + 3] = p->y[q];
    }
    lm_membrane_segment_hold(sim);               /* x^k of segment membranes */
    lm_subcycle_pins_start(sim);
    if (g->sw == 2) {
        FOR_FAST(sim, q) lm_k_g2p(g, p, q, dt, pic, g->ax, g->ay, g->vx, g->vy, 2);
    } else {
        FOR_FAST(sim, q) lm_k_g2p(g, p, q, dt, pic, g->ax, g->ay, g->vx, g->vy, 3);
    }
    if (s->gb) lm_gasband_g2p(sim, s->gb, dt, pic);
    lm_subcycle_pins_moved(sim);                 /* held points: the pin's */
    if (sim->def.scheme == LM_MUSL) {            /* 5: re-map, all particles */
        if (mr_consistent(sim)) {                /* the carry is that re-map */
            memcpy(s->fMx, s->pGx, s->nn * sizeof *s->fMx);
            memcpy(s->fMy, s->pGy, s->nn * sizeof *s->fMy);
        } else {
            slow_remap(sim, s, s->fMx, s->fMy);  /* (f^M is spent: scratch) */
        }
        fast_remap(sim, s, g->vx, g->vy, band);
        for (size_t r = 0; r < band->n; r++) {
            const long i = band->idx[r];
            g->vx[i] += s->fMx[i];
            g->vy[i] += s->fMy[i];
        }
        if (s->whole) {
            lm_constraint_remap(sim);            /* held points' momenta off */
            lm_step_strain_velocity_end(sim, 1);
        } else {
            lm_band_remap_end(sim, band);
        }
        if (sim->def.multirate != LM_MULTIRATE_HELD) mr_remapped_displacement(s, g, dt);
    } else {
        lm_step_strain_velocity_end(sim, 0);     /* v^L as step 4 left it */
    }
    lm_membrane_segment_move(sim);               /* their x^{k+1} (MUSL) */
    lm_status st = lm_membrane_tangents(sim);    /* 6a */
    if (st != LM_OK) return st;
    fast_stress(sim, dt);                        /* 7-8 */
    if (s->gb) lm_gasband_stress(sim, s->gb, dt);   /* the fast gas points' */
    lm_membrane_segment_strains(sim);
    return LM_OK;
}

lm_status lm_subcycle_step(lm_sim *sim)
{
    lm_status st = refuse(sim);
    if (st == LM_OK) st = reserve(sim);
    if (st != LM_OK) return st;
    lm_subcycle *s = sim->work->sub;
    lm_grid *g = &sim->grid;
    lm_particles *p = &sim->p;
    const size_t nn = s->nn;
    const double Dt = sim->def.dt;
    const int k = lm_subcycle_count(sim);
    const double dt = Dt / k;
    s->k = k;

    lm_step_clear(sim);                         /* 0 */
    lm_step_shape(sim);
    lm_step_p2g_forces(sim);                    /* 1-2: all particles */
    st = lm_subcycle_check_pins(sim);           /* pin.c has classified them */
    if (st != LM_OK) return st;
    if (s->gb) lm_gasband_select(s->gb, sim);   /* the fast gas points at x^n */
    fast_sums(sim, s, NULL);
    /* the slow group's share; a node the membranes alone reach keeps a
     * rounding error of their sums: zero */
    for (size_t i = 0; i < nn; i++) {
        double mG = g->m[i] - s->mM[i];
        if (fabs(mG) <= 1e-12 * g->m[i]) {
            s->mG[i] = s->pGx[i] = s->pGy[i] = s->fGx[i] = s->fGy[i] = 0;
        } else {
            s->mG[i] = mG;
            s->pGx[i] = g->px[i] - s->pMx[i];
            s->pGy[i] = g->py[i] - s->pMy[i];
            s->fGx[i] = g->fx[i] - s->fMx[i];
            s->fGy[i] = g->fy[i] - s->fMy[i];
        }
        s->Ax[i] = s->Ay[i] = s->Xx[i] = s->Xy[i] = s->Rx[i] = s->Ry[i] = 0;
        s->qGx[i] = s->pGx[i];
        s->qGy[i] = s->pGy[i];
    }
    if (sim->def.scheme == LM_MUSL || mr_consistent(sim))
        slow_consistent_mass(sim, s, mr_consistent(sim));
    if (sim->def.multirate == LM_MULTIRATE_HYBRID)   /* the kicked nodes */
        for (size_t i = 0; i < nn; i++) s->fPx[i] = s->mM[i] > 0 ? 0 : 1;
    if (sim->def.multirate == LM_MULTIRATE_SPLIT && !s->fP_set) {
        memcpy(s->fPx, s->fGx, nn * sizeof *s->fPx);   /* the first step: held */
        memcpy(s->fPy, s->fGy, nn * sizeof *s->fPy);
        s->fP_set = 1;
    }

    if (sim->def.scheme == LM_MUSL && sim->def.multirate == LM_MULTIRATE_HELD)
        for (size_t q = 0; q < p->n; q++) {   /* x^n: read by held's MUSL strain alone */
            s->xs[4 * q] = p->x[q];
            s->xs[4 * q + 1] = p->y[q];
        }
    /* the band's loops are the plain ones without the terms the airbags
     * add (a link's far end, a pin's solve in step 3) and with the slow
     * force held in every sub-step (a far node's closed form): otherwise
     * every node is swept by the standard steps */
    s->whole = lm_subcycle_terms_active(sim) || sim->def.multirate != LM_MULTIRATE_HELD ||
               s->gb;   /* the band's nodes are the membranes' (subcycle_band.c) */
    s->kick = !lm_subcycle_terms_active(sim) && lm_kick_banded(sim) && k > 1 &&
              !s->gb;   /* fast_band's gas points change the carry too */
    if (s->whole) lm_band_all(s->band);
    else lm_band_build(s->band, sim, band_need(sim));   /* the stencils at x^n */
    sim->def.dt = dt;                           /* what the phases read */
    for (int j = 0; j < k && st == LM_OK; j++) {
        st = sub_step(sim, s, j, dt, mr_weight(sim, j, k));
        lm_subcycle_pins_react(sim, j, k);
        if (j == 0 && s->kick) {   /* after the kick: the band (subcycle_kick.c) */
            lm_kick_band_build(s->band, sim);
            s->whole = 0;
        }
    }
    sim->def.dt = Dt;
    if (st != LM_OK) return st;
    lm_band_nodes bn = band_nodes(s);
    if (!s->whole && s->kick) lm_kick_band_far(sim, s->band, &bn, s->Rx, s->Ry, k, dt);
    else if (!s->whole) lm_band_far(sim, s->band, &bn, k, dt);   /* the nodes no membrane reached */
    if (s->gb && sim->def.multirate == LM_MULTIRATE_HELD) {   /* the far gas: the plain step's X */
        lm_gasband_far_displacement(s->gb, s->Ax, s->Ay, s->Xx, s->Xy, k, Dt);
        double *const fill[2] = {s->Xx, s->Xy};   /* a ghost node: its mirror's image */
        static const lm_comp xy[2] = {LM_COMP_X, LM_COMP_Y};
        lm_grid_fill(g, 2, fill, xy);
    }
    if (sim->def.multirate == LM_MULTIRATE_HALF || sim->def.multirate == LM_MULTIRATE_HALF_LUMPED)
        mr_end_kick(sim, s, Dt);
    if (sim->def.multirate == LM_MULTIRATE_SPLIT) {
        memcpy(s->fPx, s->fGx, nn * sizeof *s->fPx);
        memcpy(s->fPy, s->fGy, nn * sizeof *s->fPy);
    }

    /* 2: the slow group with its shape functions of x^n */
    const double r = 1.0 / Dt, pic = sim->def.pic;
    for (size_t i = 0; i < nn; i++) {
        g->ax[i] = s->Ax[i] * r;
        g->ay[i] = s->Ay[i] * r;
        g->vx[i] = s->Xx[i] * r;
        g->vy[i] = s->Xy[i] * r;
    }
    long n = (long)p->n;
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) if (n >= LM_PARTICLE_LOOP_MIN)
    for (long q = 0; q < n; q++) {
        if (lm_gasband_fast(s->gb, sim, (size_t)q)) continue;
        if (g->sw == 2) lm_k_g2p(g, p, (size_t)q, Dt, pic, g->ax, g->ay, g->vx, g->vy, 2);
        else lm_k_g2p(g, p, (size_t)q, Dt, pic, g->ax, g->ay, g->vx, g->vy, 3);
    }
    if (sim->def.scheme == LM_MUSL && sim->def.multirate != LM_MULTIRATE_HELD) {
        /* the impulse forms: the slow group strained as each sub-step
         * strained the membranes, by the re-mapped velocities' sum */
        for (size_t i = 0; i < nn; i++) {
            g->vx[i] = s->Rx[i] * r;
            g->vy[i] = s->Ry[i] * r;
        }
        lm_step_strain_velocity_end(sim, 0);
    } else if (sim->def.scheme == LM_MUSL) {
        /* MUSL's re-map (over the last sub-step's M_i, g->m) of every
         * particle's new velocity with the grid's part of it taken over the
         * whole step instead of at its end: v_p + (dx_p / dt - u_p), u_p
         * the grid velocity that moved it last (the slow group's
         * sum_i N_ip V_i, a membrane point's last sub-step's), dx_p its
         * displacement over the step. The strain then follows where the
         * nodes went, the work f^G . X the held force did, not one phase
         * of the membrane's ringing; with k = 1 it is v_p, the plain step */
        const double rs = (double)k / Dt;
        for (size_t q = 0; q < p->n; q++) {
            double dx = p->x[q] - s->xs[4 * q], dy = p->y[q] - s->xs[4 * q + 1], ux, uy;
            if (lm_gasband_fast(s->gb, sim, q)) {
                ux = (p->x[q] - s->xs[4 * q + 2]) * rs;
                uy = (p->y[q] - s->xs[4 * q + 3]) * rs;
            } else {
                lm_weights w;
                lm_weights_of(sim, q, &w);
                ux = lm_gather_rows(g, &w, p->node[q], s->Vx);
                uy = lm_gather_rows(g, &w, p->node[q], s->Vy);
            }
            s->xs[4 * q] = p->vx[q];
            s->xs[4 * q + 1] = p->vy[q];
            p->vx[q] += dx * r - ux;
            p->vy[q] += dy * r - uy;
        }
        lm_step_strain_velocity(sim);
        for (size_t q = 0; q < p->n; q++) {
            p->vx[q] = s->xs[4 * q];
            p->vy[q] = s->xs[4 * q + 1];
        }
    } else {
        lm_step_strain_velocity_end(sim, 0);    /* X_i / dt */
    }
    st = lm_gas_cell_density(sim);              /* 6b */
    if (st != LM_OK) return st;
    double max_div, c_max;
    lm_step_gas_maxima(sim, &max_div, &c_max);  /* 6c */
    if (s->gb) lm_gasband_keep(sim, s->gb);     /* updated in the sub-steps */
    lm_step_stress_part(sim, max_div, c_max, 1);
    if (s->gb) lm_gasband_restore(sim, s->gb);
    return LM_OK;
}
