/* body_create.c - a body of one material from its definition (lm_body_def),
 * all or nothing, its rules checked here rather than in a binding (issue 33
 * item 1, as membrane_create.c does for membranes): a material that is not
 * a membrane's, at most LM_MAX_PPC trial points per cell and LM_MAX_TRIALS
 * per body (a script's ppc = 4096 on a 1000 x 1000 grid would be 4e9
 * points: refused before the first is made), a finite velocity, and a
 * region that holds particles. The seeding itself is seed.c's pattern; the
 * axisymmetric form's mass is per radian, rho r A with r the particle's
 * place (the sub-cell's centroid when clipped). */
#include <math.h>
#include <stdio.h>

#include "step.h"

void lm_body_def_default(lm_body_def *def)
{
    *def = (lm_body_def){0};
    def->mat = -1;
    def->npx = def->npy = 2;
}

/* The region test of a definition: its shape, or the caller's function,
 * whose failure (-1) is kept here and stops the seeding. */
typedef struct region_test {
    const lm_body_def *def;
    int failed;
} region_test;

static int inside(void *ctx, double x, double y)
{
    region_test *t = ctx;
    if (t->failed) return 0;
    if (t->def->region) return lm_region_contains(t->def->region, x, y);
    int in = t->def->inside(t->def->ctx, x, y);
    if (in < 0) t->failed = 1;
    return in > 0;
}

/* The rules above that need no seeding; total is the trial points. */
static lm_status check(lm_sim *sim, const lm_body_def *def, size_t total)
{
    char a[40], b[40];
    if (def->mat < 0 || def->mat >= sim->nmats) {
        snprintf(sim->err, sizeof sim->err, "material %d was not added", def->mat + 1);
        return LM_ERR_INPUT;
    }
    if (sim->mats[def->mat]->kind == LM_MEMBRANE) {
        snprintf(sim->err, sizeof sim->err,
                 "a membrane material goes into sim:membrane{...}");
        return LM_ERR_INPUT;
    }
    if (!def->region && !def->inside) {
        snprintf(sim->err, sizeof sim->err, "'region' is required");
        return LM_ERR_INPUT;
    }
    if (def->npx < 1 || def->npy < 1) {
        snprintf(sim->err, sizeof sim->err, "ppc = {%d, %d} must be two positive integers",
                 def->npx, def->npy);
        return LM_ERR_INPUT;
    }
    if ((double)def->npx * def->npy > LM_MAX_PPC) {
        snprintf(sim->err, sizeof sim->err,
                 "ppc = {%d, %d} gives %.0f points per cell, more than the limit of %d",
                 def->npx, def->npy, (double)def->npx * def->npy, LM_MAX_PPC);
        return LM_ERR_INPUT;
    }
    if (!isfinite(def->vx) || !isfinite(def->vy)) {
        snprintf(sim->err, sizeof sim->err, "'velocity' must be two finite numbers (got {%s, %s})",
                 lm_num_text(a, sizeof a, def->vx), lm_num_text(b, sizeof b, def->vy));
        return LM_ERR_INPUT;
    }
    if ((double)total > LM_MAX_TRIALS) {
        snprintf(sim->err, sizeof sim->err,
                 "the region's cells at ppc = %d hold %.0f trial points, more than the "
                 "limit of %d (a smaller ppc, region or domain)", def->npx * def->npy,
                 (double)total, LM_MAX_TRIALS);
        return LM_ERR_INPUT;
    }
    return LM_OK;
}

/* The particles of body bi: LM_OK, or why not (a callback failed: "stopped"). */
static lm_status seed(lm_sim *sim, int bi, const lm_body_def *def, const lm_seed_range *range,
                      size_t total)
{
    const lm_grid *g = &sim->grid;
    double rho = sim->mats[def->mat]->rho;
    double mass = lm_seed_mass(g, def->npx, def->npy, rho);
    region_test t = { def, 0 };
    for (size_t k = 0; k < total; k++) {
        double x, y, vx = def->vx, vy = def->vy;
        double part = 1;
        lm_seed_point(g, range, k, &x, &y);
        if (def->clipped) part = lm_seed_clip(g, def->npx, def->npy, x, y, inside, &t, &x, &y);
        else part = inside(&t, x, y);
        if (t.failed) break;
        if (part == 0) continue;
        if (def->velocity && def->velocity(def->ctx, x, y, &vx, &vy) != 0) {
            t.failed = 1;
            break;
        }
        /* axisymmetric: per radian, rho r A (x the sub-cell's centroid) */
        double m = sim->def.axisym ? part * mass * x : part * mass;
        lm_status st = lm_sim_add_particle(sim, bi, x, y, vx, vy, m, rho);
        if (st != LM_OK) return st;
        /* uGIMP: the particle's square is its share of the cell */
        lm_sim_set_particle_size(sim, sim->p.n - 1, 0.5 * g->hx / def->npx,
                                 0.5 * g->hy / def->npy);
    }
    if (t.failed) {
        snprintf(sim->err, sizeof sim->err, "stopped by the region or velocity function");
        return LM_ERR_INPUT;
    }
    return LM_OK;
}

int lm_sim_create_body(lm_sim *sim, const lm_body_def *def)
{
    const lm_grid *g = &sim->grid;
    const lm_region *r = def->region;
    lm_seed_range range = r
        ? lm_seed_range_for(g, def->npx, def->npy, r->x0, r->y0, r->x1, r->y1)
        : lm_seed_range_for(g, def->npx, def->npy, g->x0, g->y0, g->x0 + g->nx * g->hx,
                            g->y0 + g->ny * g->hy);
    size_t total = def->npx >= 1 && def->npy >= 1 ? lm_seed_count(&range) : 0;
    if (check(sim, def, total) != LM_OK) return -1;
    int bi = lm_sim_add_body(sim, def->mat);   /* the axisymmetric gas's rules (sim.c) */
    if (bi < 0) return -1;
    if (seed(sim, bi, def, &range, total) != LM_OK) {
        lm_sim_drop_last_body(sim);
        return -1;
    }
    if (sim->bodies[bi].count == 0) {
        lm_sim_drop_last_body(sim);
        snprintf(sim->err, sizeof sim->err,
                 "the region holds no particles at ppc = %d (is it inside the domain, and "
                 "larger than a cell?)", def->npx * def->npy);
        return -1;
    }
    if (def->name && def->name[0]) lm_sim_set_body_name(sim, bi, def->name);
    return bi;
}
