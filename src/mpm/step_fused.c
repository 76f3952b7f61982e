/* step_fused.c - the step's particle phases in one or two passes (issue 17
 * item 1).
 *
 * In a plain run (no contact, pin, link, axisymmetric form, cell
 * stresses, gas splitting or membrane with segment forces) what the
 * step does at a particle after the grid update needs only that particle
 * and the grid, apart from what needs all particles moved first: the
 * MUSL re-map ([M] eqs 12-13), the membranes' tangents (from their
 * neighbours at x^{k+1}), the gas's cell densities and its artificial
 * viscosity's maxima ([F] eq 24). So the step makes
 *   - one pass (USL, no membrane, no gas that needs those): step 4, the
 *     rate and the stress (7-8), the check;
 *   - else two: step 4 (with the MUSL re-map), then those, then the rate,
 *     the stress and the check;
 * each pass one parallel loop on more threads; and on one thread, when
 * the caller promises that the next step follows at once
 * (lm_sim_step_then), its last pass adds each particle's shape at x^{k+1}
 * and its share of the next step's mass, momentum and force (steps 0-2)
 * into a second set of nodal sums, taken up by that step instead of its
 * own passes. The phase-by-phase step reads a particle six times a step.
 *
 * Each nodal sum receives the same terms in the same particle order as in
 * step.c and each particle the same operations (step_kernels.h): the
 * states are the same to the bit (tests/unit/test_step_fused.c). */
#include <stdlib.h>
#include <string.h>

#include "arrays.h"
#include "step.h"
#include "step_bspline2.h"
#include "step_kernels.h"
#include "threads.h"

struct lm_ahead {
    double *f[5];     /* the next step's m, px, py, fx, fy, scattered ahead */
    double *ux, *uy;  /* step 4's v_i^L = p_i^L (1 / m_i): not the same bits as
                         the USL strain velocity p_i^L / m_i, so kept apart */
    double *rec, *sums;   /* the B-spline pass's node records (step_bspline2.c) */
    size_t nn;        /* nodes of the arrays */
    size_t n;         /* particles when the sums were made */
    int valid;        /* f holds the sums of the particles as they are now */
};

int lm_step_fusable(const lm_sim *sim)
{
    if (sim->contact || sim->npins || sim->nlinks || sim->def.axisym ||
        sim->def.stress == LM_STRESS_CELL || lm_constraint_active(sim) ||
        lm_mass_corrects(sim) || sim->def.apic)
        return 0;
    for (int m = 0; m < sim->nmats; m++)
        if (sim->mats[m]->kind == LM_GAS && sim->mats[m]->split > 0) return 0;
    for (int b = 0; b < sim->nbodies; b++)
        if (sim->bodies[b].membrane && sim->bodies[b].force == LM_MFORCE_SEGMENT) return 0;
    return 1;
}

/* Can steps 4-8 go in one pass: nothing needs all particles moved before
 * a rate? */
static int one_pass(const lm_sim *sim)
{
    if (sim->def.scheme != LM_USL) return 0;
    for (int m = 0; m < sim->nmats; m++) {
        const lm_material *mat = sim->mats[m];
        if (mat->kind == LM_GAS && (mat->av || mat->density != LM_DENSITY_CONTINUITY)) return 0;
    }
    for (int b = 0; b < sim->nbodies; b++)
        if (sim->bodies[b].membrane) return 0;
    return 1;
}

/* Does the one-thread pass that makes the next step's sums take the
 * quadratic B-spline's own form (step_bspline2.c)? */
static int bspline2_pass(const lm_sim *sim)
{
    return sim->def.basis == LM_BASIS_BSPLINE2 && sim->work->ahead->rec &&
           sim->def.scheme == LM_USL && one_pass(sim);
}

void lm_ahead_free(struct lm_ahead *a)
{
    if (!a) return;
    for (int k = 0; k < 5; k++) lm_arr_free(a->f[k]);
    lm_arr_free(a->ux);
    lm_arr_free(a->uy);
    lm_arr_free(a->rec);
    lm_arr_free(a->sums);
    free(a);
}

void lm_sim_forget_ahead(lm_sim *sim)
{
    if (sim->work->ahead) sim->work->ahead->valid = 0;
}

/* The arrays for the grid as it is: made once (seven nodal fields, as
 * bounded as the grid's own nine). */
lm_status lm_ahead_reserve(lm_sim *sim)
{
    size_t nn = lm_grid_nodes(&sim->grid);
    struct lm_ahead *a = sim->work->ahead;
    if (a && a->nn == nn) return LM_OK;
    lm_ahead_free(a);
    sim->work->ahead = a = calloc(1, sizeof *a);
    if (!a) return LM_ERR_MEMORY;
    a->nn = nn;
    int ok = 1;
    /* offsets 9..15, after the grid's nine (sim.c, grid_alloc): the two
     * sets trade places step by step and stay apart */
    for (int k = 0; k < 5; k++) ok &= (a->f[k] = lm_arr_alloc(nn, sizeof(double), 9 + k, 1)) != NULL;
    ok &= (a->ux = lm_arr_alloc(nn, sizeof(double), 14, 1)) != NULL;
    ok &= (a->uy = lm_arr_alloc(nn, sizeof(double), 15, 1)) != NULL;
    if (sim->def.basis == LM_BASIS_BSPLINE2) {
        ok &= (a->rec = lm_arr_alloc(nn, LM_B2_REC * sizeof(double), 16, 0)) != NULL;
        ok &= (a->sums = lm_arr_alloc(nn, 4 * sizeof(double), 17, 1)) != NULL;
    }
    if (ok) return LM_OK;
    lm_ahead_free(a);
    sim->work->ahead = NULL;
    return LM_ERR_MEMORY;
}

/* Steps 0-2 from the last pass's sums, when it made them for these
 * particles: the arrays trade places with the grid's (the grid's old ones
 * are the next pass's to fill), then what lm_step_p2g_forces does after
 * its scatter. 0: the step must make its own. */
int lm_step_take_ahead(lm_sim *sim)
{
    struct lm_ahead *a = sim->work->ahead;
    lm_grid *g = &sim->grid;
    /* made on one thread (a split scatter would sum in another order) */
    if (!a || !a->valid || a->n != sim->p.n || a->nn != lm_grid_nodes(g) ||
        lm_sim_threads(sim) != 1)
        return 0;
    a->valid = 0;
    double **own[5] = {&g->m, &g->px, &g->py, &g->fx, &g->fy};
    for (int k = 0; k < 5; k++) {
        double *t = *own[k];
        *own[k] = a->f[k];
        a->f[k] = t;
    }
    double *const out[5] = {g->m, g->px, g->py, g->fx, g->fy};
    static const lm_comp comp[5] = {LM_COMP_SCALAR, LM_COMP_X, LM_COMP_Y, LM_COMP_X, LM_COMP_Y};
    lm_grid_fold(g, 5, out, comp);
    lm_step_forces_rest(sim);
    return 1;
}

/* Steps 7-8 at particle q: lm_step_stress's rate and update in the plane
 * (no contact here), with the gas's maxima of the step (md, cm); an
 * elastic solid's update from the moduli el worked out once a pass
 * (elastic_moduli.h: the same bits as its row of the table; el NULL: the
 * table for every material). */
static LM_FORCE_INLINE void stress_at(lm_sim *sim, size_t q, double rx, double ry, double h,
                                      double md, double cm, const lm_elastic_moduli *el,
                                      const int W)
{
    lm_rate r;
    lm_k_velocity_gradient(&sim->grid, &sim->p, q, sim->grid.vx, sim->grid.vy, r.L, rx, ry, W);
    const double *L = r.L, dt = sim->def.dt;
    r.dexx = dt * L[0];
    r.deyy = dt * L[3];
    r.dexy = 0.5 * dt * (L[1] + L[2]);
    r.w = 0.5 * (L[1] - L[2]);
    const int m = sim->p.mat[q];
    if (el && m < LM_FUSED_MATS && el[m].elastic) {
        lm_particles *p = &sim->p;
        p->rho[q] /= 1 + r.dexx + r.deyy;
        lm_elastic_update_moduli(&el[m], r.dexx, r.deyy, r.dexy, r.w, dt, &p->sxx[q],
                                 &p->syy[q], &p->sxy[q], &p->szz[q]);
        return;
    }
    r.hoop = 0;
    r.dt = dt;
    r.max_div = md;
    r.c_max = cm;
    r.h = h;
    lm_update_at(sim, q, &r, 0);   /* the plane form's row (material_update.c) */
}

/* After the stress at particle q: the check, then (ahead) its shape at
 * x^{k+1} and the next step's sums. Returns the check's verdict. */
static LM_FORCE_INLINE int finish_at(lm_sim *sim, size_t q, double rx, double ry,
                                     const lm_k_box *box, double *const *next, const int W)
{
    int bad = lm_k_check(&sim->p, q, box);
    if (next) {   /* no membranes here: no segment points */
        lm_k_shape(sim, &sim->p, q, rx, ry);
        lm_k_scatter_mass_forces(sim, q, rx, ry, next, NULL, 0, 0, W, 0, 0);
    }
    return bad;
}

/* What lm_sim_step does between step 4 and the stresses when it needs
 * all particles moved (stress_phases, step.c): tangents, cell densities,
 * the viscosity's maxima. */
static lm_status between_passes(lm_sim *sim, double *md, double *cm)
{
    lm_status st = lm_membrane_tangents(sim);
    if (st == LM_OK) st = lm_gas_cell_density(sim);
    if (st == LM_OK) lm_step_gas_maxima(sim, md, cm);
    return st;
}

/* The passes on more than one thread: each a parallel loop over the
 * particles, one loop per stencil width with the width a constant (GCC
 * outlines an OpenMP loop before it inlines, so inside pass_w the width
 * would be a variable there and nothing unrolled). */
typedef enum mt_kind {
    MT_USL,      /* step 4, the rate and stress, the check */
    MT_G2P,      /* step 4 */
    MT_STRESS    /* the rate and stress, the check */
} mt_kind;
typedef struct mt_ctx {
    double dt, pic, rx, ry, h, md, cm;
    const double *ux, *uy;
    lm_k_box box;
} mt_ctx;

static LM_FORCE_INLINE int mt_particle(lm_sim *sim, mt_kind k, const mt_ctx *c, size_t q,
                                       const int W)
{
    if (k != MT_STRESS)
        lm_k_g2p(&sim->grid, &sim->p, q, c->dt, c->pic, sim->grid.ax, sim->grid.ay, c->ux,
                 c->uy, W);
    if (k == MT_G2P) return 0;
    stress_at(sim, q, c->rx, c->ry, c->h, c->md, c->cm, NULL, W);
    return lm_k_check(&sim->p, q, &c->box);
}

/* Returns the lowest-numbered particle in trouble, or n. */
static size_t mt_pass(lm_sim *sim, mt_kind k, const mt_ctx *c)
{
    long n = (long)sim->p.n, first = n;
    if (sim->grid.sw == 2) {
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) reduction(min : first) \
    if (n >= LM_PARTICLE_LOOP_MIN)
        for (long q = 0; q < n; q++)
            if (mt_particle(sim, k, c, (size_t)q, 2) && q < first) first = q;
    } else {
#pragma omp parallel for num_threads(lm_sim_team(sim)) schedule(static) reduction(min : first) \
    if (n >= LM_PARTICLE_LOOP_MIN)
        for (long q = 0; q < n; q++)
            if (mt_particle(sim, k, c, (size_t)q, 3) && q < first) first = q;
    }
    return (size_t)first;
}

/* Steps 4-8 and the check on one thread for a stencil W wide (the last
 * pass making the next step's sums when next is not NULL); *st says
 * whether what runs between the passes failed. Returns the
 * lowest-numbered particle in trouble, or n. */
static LM_FORCE_INLINE size_t pass_w(lm_sim *sim, double *const *next, lm_status *st,
                                     const int W)
{
    lm_grid *g = &sim->grid;
    lm_particles *p = &sim->p;
    const struct lm_ahead *a = sim->work->ahead;
    const size_t n = p->n, nn = lm_grid_nodes(g);
    const double dt = sim->def.dt, pic = sim->def.pic;
    const double rx = 1.0 / g->hx, ry = 1.0 / g->hy, h = fmin(g->hx, g->hy);
    const lm_k_box box = lm_k_box_of(g);
    lm_elastic_moduli el[LM_FUSED_MATS];
    lm_elastic_moduli_table(sim, el);
    size_t first = n;
    if (sim->def.scheme == LM_USL && one_pass(sim)) {
        if (W == 3 && next && bspline2_pass(sim))
            return lm_fused_bspline2_usl(sim, a->ux, a->uy, a->rec, a->sums, next);
        for (size_t q = 0; q < n; q++) {
            lm_k_g2p(g, p, q, dt, pic, g->ax, g->ay, a->ux, a->uy, W);
            stress_at(sim, q, rx, ry, h, 0, 0, el, W);
            if (finish_at(sim, q, rx, ry, &box, next, W) && q < first) first = q;
        }
        return first;
    }
    if (sim->def.scheme == LM_USL) {
        for (size_t q = 0; q < n; q++) lm_k_g2p(g, p, q, dt, pic, g->ax, g->ay, a->ux, a->uy, W);
    } else {
        /* step 4 and the re-map of m_p v_p in one pass, then as
         * lm_step_strain_velocity after its scatter */
        memset(g->vx, 0, nn * sizeof(double));
        memset(g->vy, 0, nn * sizeof(double));
        double *const remap[2] = {g->vx, g->vy};
        for (size_t q = 0; q < n; q++) {
            lm_k_g2p(g, p, q, dt, pic, g->ax, g->ay, a->ux, a->uy, W);
            lm_k_scatter_momentum(sim, q, remap, NULL, 0, 0, W, 0, 0);
        }
        static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
        lm_grid_fold(g, 2, remap, comp);
        lm_step_strain_velocity_end(sim, 1);
    }
    double md = 0, cm = 0;
    if ((*st = between_passes(sim, &md, &cm)) != LM_OK) return n;
    for (size_t q = 0; q < n; q++) {
        stress_at(sim, q, rx, ry, h, md, cm, el, W);
        if (finish_at(sim, q, rx, ry, &box, next, W) && q < first) first = q;
    }
    return first;
}

/* The same on more threads, pass by pass (nothing made ahead). */
static size_t passes_mt(lm_sim *sim, lm_status *st)
{
    const lm_grid *g = &sim->grid;
    mt_ctx c = {sim->def.dt, sim->def.pic, 1.0 / g->hx, 1.0 / g->hy, fmin(g->hx, g->hy), 0, 0,
                sim->work->ahead->ux, sim->work->ahead->uy, lm_k_box_of(g)};
    if (sim->def.scheme == LM_USL && one_pass(sim)) return mt_pass(sim, MT_USL, &c);
    mt_pass(sim, MT_G2P, &c);
    if (sim->def.scheme == LM_MUSL) lm_step_strain_velocity(sim);   /* the re-map */
    if ((*st = between_passes(sim, &c.md, &c.cm)) != LM_OK) return sim->p.n;
    return mt_pass(sim, MT_STRESS, &c);
}

size_t lm_step_fused_particles(lm_sim *sim, int ahead, lm_status *st)
{
    struct lm_ahead *a = sim->work->ahead;
    const int one = lm_sim_threads(sim) == 1;
    double *const *next = ahead && one ? a->f : NULL;
    *st = LM_OK;
    /* (the B-spline's pass writes the next step's momenta and forces
     * whole: step_bspline2.c) */
    const int whole = bspline2_pass(sim);
    if (next)
        for (int k = 0; k < (whole ? 1 : 5); k++) memset(a->f[k], 0, a->nn * sizeof(double));
    lm_step_g2p_nodes(sim, a->ux, a->uy);
    /* [N] §7: the USL strain from v_i^L = p_i^L / m_i, before any pass */
    if (sim->def.scheme == LM_USL) lm_step_strain_velocity(sim);
    size_t first = !one ? passes_mt(sim, st)
                   : sim->grid.sw == 2 ? pass_w(sim, next, st, 2) : pass_w(sim, next, st, 3);
    a->n = sim->p.n;
    a->valid = next && first == sim->p.n && *st == LM_OK;
    return first;
}
