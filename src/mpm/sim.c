/* sim.c - creating a simulation, its bodies and particles. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "arrays.h"
#include "membrane_law.h"
#include "contact.h"
#include "mpm.h"
#include "normals_work.h"
#include "particles.h"
#include "step.h"
#include "util.h"

void lm_sim_def_default(lm_sim_def *def)
{
    memset(def, 0, sizeof *def);
    def->x1 = def->y1 = 1;
    def->hx = def->hy = 0.1;
    def->dt = 1e-3;
    def->scheme = LM_MUSL;
    for (int s = 0; s < 4; s++) def->bc[s] = LM_BC_FIXED;
    def->courant = 1;
    def->seed = 1;
    def->threads = 1;
}

/* Whole cells cover the domain; a domain that is a multiple of the cell
 * size up to rounding gets exactly that many. */
static double cells(double len, double h)
{
    double n = len / h;
    double r = floor(n + 0.5);
    return fabs(n - r) < 1e-9 * (r > 1 ? r : 1) ? r : ceil(n);
}

/* The nine nodal fields, zeroed, at offsets 0..8 of arrays.h's staggering
 * (the sums made ahead take 9..15: step_fused.c). */
static int grid_alloc(lm_grid *g)
{
    size_t n = lm_grid_nodes(g);
    double **f[] = {&g->m, &g->px, &g->py, &g->fx, &g->fy, &g->vx, &g->vy, &g->ax, &g->ay};
    for (size_t k = 0; k < sizeof f / sizeof f[0]; k++) {
        *f[k] = lm_arr_alloc(n, sizeof(double), (int)k, 1);
        if (!*f[k]) return -1;
    }
    return 0;
}

static void grid_free(lm_grid *g)
{
    double *f[] = {g->m, g->px, g->py, g->fx, g->fy, g->vx, g->vy, g->ax, g->ay};
    for (size_t k = 0; k < sizeof f / sizeof f[0]; k++) lm_arr_free(f[k]);
    free(g->tbuf);
    lu_budget_release(LU_MEM_ENGINE, g->tcap * sizeof(double));   /* threads.c */
}

lm_sim *lm_sim_new(const lm_sim_def *def, char *err, size_t errlen)
{
    if (!(def->x1 > def->x0) || !(def->y1 > def->y0)) {
        snprintf(err, errlen, "domain {%g, %g, %g, %g} is empty: need x1 > x0 and y1 > y0",
                 def->x0, def->y0, def->x1, def->y1);
        return NULL;
    }
    if (!(def->hx > 0) || !(def->hy > 0) || !isfinite(def->hx) || !isfinite(def->hy)) {
        snprintf(err, errlen, "cell size must be positive (got %g x %g)", def->hx, def->hy);
        return NULL;
    }
    if (!(def->dt > 0) || !isfinite(def->dt)) {
        snprintf(err, errlen, "dt must be positive (got %g)", def->dt);
        return NULL;
    }
    if (def->basis != LM_BASIS_LINEAR && def->basis != LM_BASIS_GIMP &&
        def->basis != LM_BASIS_BSPLINE2) {
        snprintf(err, errlen, "unknown basis %d (linear, gimp, bspline2)", (int)def->basis);
        return NULL;
    }
    if (!(def->courant > 0) || !isfinite(def->courant)) {   /* inf: no check at all */
        snprintf(err, errlen, "courant must be positive and finite (got %g)", def->courant);
        return NULL;
    }
    /* The axisymmetric form (axisym.c): the left side is the axis. */
    if (def->axisym && def->x0 < 0) {
        snprintf(err, errlen, "axisymmetric: the domain reaches r = %g < 0; x is the radius, "
                 "so the domain must start on the axis (x0 = 0)", def->x0);
        return NULL;
    }
    if (def->axisym && def->x0 > 0) {
        snprintf(err, errlen, "axisymmetric: the domain starts at r = %g; its left side must "
                 "be the axis (x0 = 0)", def->x0);
        return NULL;
    }
    if (def->axisym && def->bc[LM_LEFT] != LM_BC_SYMMETRY) {
        snprintf(err, errlen, "axisymmetric: the left side is the axis r = 0 and must be "
                 "boundary \"symmetry\" (it is \"%s\")",
                 def->bc[LM_LEFT] == LM_BC_FIXED ? "fixed" : "free");
        return NULL;
    }
    if (def->axisym && def->stress == LM_STRESS_CELL) {
        snprintf(err, errlen, "axisymmetric: stress = \"cell\" is a plane construction; "
                 "use stress = \"points\"");
        return NULL;
    }
    /* the product of the rounded counts: unequal cells (1e9 x 1e-8 before
     * rounding, 1e9 x 1 after) must not pass as 10 cells */
    double cx = cells(def->x1 - def->x0, def->hx), cy = cells(def->y1 - def->y0, def->hy);
    if (cx * cy > 1e8) {
        snprintf(err, errlen, "grid of %.0f x %.0f = %.3g cells is too large (limit 1e8)",
                 cx, cy, cx * cy);
        return NULL;
    }
    lm_sim *sim = calloc(1, sizeof *sim);
    lm_work *work = calloc(1, sizeof *work);   /* the scratch (sim_work.h) */
    if (!sim || !work) {
        LU_FREE_ALL(sim, work);
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    sim->work = work;
    sim->def = *def;
    lm_grid *g = &sim->grid;
    g->x0 = def->x0;
    g->y0 = def->y0;
    g->hx = def->hx;
    g->hy = def->hy;
    g->nx = (int)cx;
    g->ny = (int)cy;
    memcpy(g->bc, def->bc, sizeof g->bc);
    lm_grid_layout(g, def->basis);
    sim->p.ns = g->sw * g->sw;
    sim->p.keep_weights = def->basis == LM_BASIS_GIMP;
    if (grid_alloc(g)) {
        /* the message before the free: g is inside sim (the old message
         * read it after, a use-after-free ASan found once the memory cap
         * made this path common) */
        snprintf(err, errlen, "cannot make a %d x %d grid: %s", g->nx, g->ny, lu_budget_oom());
        lm_sim_free(sim);
        return NULL;
    }
    /* stress = "cell": the per-cell sums of stress_cell.c, made here so that
     * the step has no failure of its own to report */
    if (def->stress == LM_STRESS_CELL &&
        !(work->cell_stress = malloc(3 * (size_t)g->nx * (size_t)g->ny * sizeof *work->cell_stress))) {
        lm_sim_free(sim);
        snprintf(err, errlen, "out of memory for the cell stresses of a %d x %d grid", g->nx,
                 g->ny);
        return NULL;
    }
    /* mass = "corrected" / "membrane": the momenta the damping's account
     * reads (damping.c lm_damp_keep_momentum), made here for the same reason */
    if (def->mass != LM_MASS_LUMPED &&
        !(work->mass_p0 = malloc(2 * lm_grid_nodes(g) * sizeof *work->mass_p0))) {
        lm_sim_free(sim);
        snprintf(err, errlen, "out of memory for the nodal momenta of a %d x %d grid", g->nx,
                 g->ny);
        return NULL;
    }
    return sim;
}

void lm_sim_free(lm_sim *sim)
{
    if (!sim) return;
    grid_free(&sim->grid);
    lm_particles_free(&sim->p);
    for (int k = 0; k < sim->npins; k++) LU_FREE_ALL(sim->pins[k].idx, sim->pins[k].x0);
    lm_contact_free(sim->contact);
    lm_work *w = sim->work;
    lm_nwork_delete(w->nwork);
    lm_ahead_free(w->ahead);
    lm_subcycle_free(w->sub);
    lm_apic_free(w->apic);
    for (int k = 0; k < sim->nmats; k++) free(sim->mats[k]);
    LU_FREE_ALL(sim->mats, sim->bodies, w->cell_rho, w->cell_stress, sim->pins, sim->links,
                w->pin_w, w->mass_p0, w->cons, w, sim);
}

/* The sim owns its materials: each is a copy, checked, and changes only
 * through lm_sim_set_material (issue 33 item 1). */
int lm_sim_add_material(lm_sim *sim, const lm_material *mat)
{
    char why[256];
    if (lm_material_validate(mat, why, sizeof why)) {
        snprintf(sim->err, sizeof sim->err, "%s", why);
        return -1;
    }
    if (sim->nmats == sim->capmats) {
        int cap = sim->capmats ? 2 * sim->capmats : 4;
        lm_material **q = realloc(sim->mats, cap * sizeof *q);
        if (!q) {
            snprintf(sim->err, sizeof sim->err, "out of memory");
            return -1;
        }
        sim->mats = q;
        sim->capmats = cap;
    }
    lm_material *own = malloc(sizeof *own);
    if (!own) {
        snprintf(sim->err, sizeof sim->err, "out of memory");
        return -1;
    }
    *own = *mat;
    sim->mats[sim->nmats] = own;
    return sim->nmats++;
}

lm_status lm_sim_set_material(lm_sim *sim, int k, const lm_material *mat)
{
    char why[256];
    if (k < 0 || k >= sim->nmats) {
        snprintf(sim->err, sizeof sim->err, "material %d was not added", k + 1);
        return LM_ERR_INPUT;
    }
    const lm_material *now = sim->mats[k];
    if (mat->kind != now->kind) {
        snprintf(sim->err, sizeof sim->err, "material %d cannot change its kind", k + 1);
        return LM_ERR_INPUT;
    }
    if (mat->rho != now->rho) {   /* the particles' masses were seeded from it */
        snprintf(sim->err, sizeof sim->err, "material %d cannot change rho", k + 1);
        return LM_ERR_INPUT;
    }
    if (lm_material_validate(mat, why, sizeof why)) {
        snprintf(sim->err, sizeof sim->err, "%s", why);
        return LM_ERR_INPUT;
    }
    /* a change of the wave speed moves the Courant number (a gas's mu or
     * av, which do not, leave the check as it was) */
    if (lm_material_wave_speed(mat) != lm_material_wave_speed(now))
        sim->work->courant_checked = 0;
    *sim->mats[k] = *mat;
    return LM_OK;
}

/* The axisymmetric form counts a gas's mass per radian, r dA: the cell
 * densities ([T] eqs 4.5-4.6) and splitting count plane area, so they are
 * refused there (axisym.c). */
static int body_rules(lm_sim *sim, const lm_material *m)
{
    if (!sim->def.axisym || m->kind != LM_GAS) return 0;
    if (m->density != LM_DENSITY_CONTINUITY) {
        snprintf(sim->err, sizeof sim->err,
                 "axisymmetric: a gas's density must come from the continuity equation "
                 "(density = \"continuity\"); the cell densities are plane");
        return -1;
    }
    if (m->split > 0) {
        char a[40];
        snprintf(sim->err, sizeof sim->err, "axisymmetric: gas splitting (split = %s) is plane only",
                 lm_num_text(a, sizeof a, m->split));
        return -1;
    }
    return 0;
}

int lm_sim_add_body(lm_sim *sim, int mat)
{
    if (mat < 0 || mat >= sim->nmats) {
        snprintf(sim->err, sizeof sim->err, "material %d was not added", mat + 1);
        return -1;
    }
    if (body_rules(sim, sim->mats[mat])) return -1;
    if (sim->nbodies == sim->capbodies) {
        int cap = sim->capbodies ? 2 * sim->capbodies : 4;
        lm_body *q = realloc(sim->bodies, cap * sizeof *q);
        if (!q) {
            snprintf(sim->err, sizeof sim->err, "out of memory");
            return -1;
        }
        sim->bodies = q;
        sim->capbodies = cap;
    }
    lm_body *b = &sim->bodies[sim->nbodies];
    memset(b, 0, sizeof *b);
    sim->work->courant_checked = 0;   /* its material's wave speed counts now */
    b->mat = mat;
    b->first = sim->p.n;
    b->count = 0;
    return sim->nbodies++;
}

int lm_sim_add_membrane(lm_sim *sim, int mat, int closed)
{
    if (mat < 0 || mat >= sim->nmats || sim->mats[mat]->kind != LM_MEMBRANE) return -1;
    int b = lm_sim_add_body(sim, mat);
    if (b < 0) return -1;
    sim->bodies[b].membrane = 1;
    sim->prepared = 0;
    sim->bodies[b].closed = closed;
    return b;
}

/* ds is the point's unstrained length. The point's volume is
 * thickness * ds * exp(eps_t) (membrane.c, docs/physics.md §2), kept
 * as rho = m / V so that the force loop treats every particle alike; the
 * initial stress follows the law from the initial strain. */
lm_status lm_sim_set_membrane_point(lm_sim *sim, size_t q, double ds, double et)
{
    lm_particles *p = &sim->p;
    const lm_material *mat = q < p->n ? sim->mats[p->mat[q]] : NULL;
    if (!mat || mat->kind != LM_MEMBRANE || !(ds > 0) || !isfinite(et)) {
        snprintf(sim->err, sizeof sim->err,
                 "membrane point %zu: ds = %g and strain = %g (need ds > 0, a finite strain)",
                 q + 1, ds, et);
        return LM_ERR_INPUT;
    }
    p->ds[q] = ds;
    p->et[q] = et;
    p->rho[q] = p->m[q] / (mat->thickness * ds * exp(et));
    double st = lm_membrane_stress(mat, et);
    p->sxx[q] = p->syy[q] = p->sxy[q] = 0;
    p->szz[q] = lm_membrane_szz(mat, st);
    if (sim->def.axisym) lm_axisym_membrane_point(sim, q);   /* a ring (axisym.c) */
    /* the tangent is not known until the body is complete: the stress
     * tensor is rebuilt from eps_t at the first step (lm_membrane_prepare) */
    return LM_OK;
}

lm_status lm_sim_add_particle(lm_sim *sim, int body, double x, double y,
                              double vx, double vy, double mass, double rho)
{
    lm_particles *p = &sim->p;
    if (body != sim->nbodies - 1) {
        snprintf(sim->err, sizeof sim->err,
                 "particles can only be added to the newest body");
        return LM_ERR_INPUT;
    }
    if (!(mass > 0) || !(rho > 0)) {
        snprintf(sim->err, sizeof sim->err,
                 "particle mass and density must be positive (got %g, %g)", mass, rho);
        return LM_ERR_INPUT;
    }
    if (p->n >= LM_MAX_PARTICLES) {   /* bodies and membranes alike */
        snprintf(sim->err, sizeof sim->err,
                 "the simulation would have more than the limit of %d particles",
                 LM_MAX_PARTICLES);
        return LM_ERR_INPUT;
    }
    if (p->n == p->cap &&
        lm_particles_reserve(p, p->cap ? 2 * p->cap : 1024)) {
        snprintf(sim->err, sizeof sim->err, "no room for %zu particles: %s", p->n + 1,
                 lu_budget_oom());
        return LM_ERR_MEMORY;
    }
    size_t q = p->n++;
    p->x[q] = x;
    p->y[q] = y;
    p->vx[q] = vx;
    p->vy[q] = vy;
    p->m[q] = mass;
    p->rho[q] = rho;
    p->sxx[q] = p->syy[q] = p->sxy[q] = p->szz[q] = 0;
    p->et[q] = p->ds[q] = p->tx[q] = p->ty[q] = 0;
    p->e[q] = p->q[q] = p->ev[q] = 0;
    p->L0[q] = p->fpx[q] = p->fpy[q] = 0;
    p->r0[q] = 0;
    p->pin[q] = 0;
    p->body[q] = body;
    p->mat[q] = sim->bodies[body].mat;
    p->node[q] = 0;
    /* uGIMP's domain of a 2 x 2-seeded point until told otherwise */
    p->lx[q] = 0.25 * sim->grid.hx;
    p->ly[q] = 0.25 * sim->grid.hy;
    const lm_material *mat = sim->mats[p->mat[q]];
    if (mat->kind == LM_GAS) {
        /* the initial pressure as an isotropic stress, [F] eq 21 at rest */
        p->e[q] = mat->e0;
        double pr = (mat->gamma - 1) * rho * mat->e0;
        p->sxx[q] = p->syy[q] = p->szz[q] = -pr;
    }
    sim->bodies[body].count++;
    sim->pe_ref += mass * (sim->def.gx * x + sim->def.gy * y);
    sim->bodies[body].pe_ref += mass * (sim->def.gx * x + sim->def.gy * y);
    return LM_OK;
}

void lm_sim_set_particle_size(lm_sim *sim, size_t q, double lx, double ly)
{
    if (q >= sim->p.n) return;
    double hx = 0.5 * sim->grid.hx, hy = 0.5 * sim->grid.hy;
    sim->p.lx[q] = lx > 0 && lx < hx ? lx : hx;
    sim->p.ly[q] = ly > 0 && ly < hy ? ly : hy;
}

double lm_sim_courant_limit(const lm_sim *sim)
{
    double usl = sim->def.scheme == LM_USL ? LM_USL_COURANT : 1;
    double mass = sim->def.mass == LM_MASS_CORRECTED ? LM_CORRECTED_COURANT : 1;
    return sim->def.courant * lm_basis_courant_factor(sim->def.basis) * usl * mass;
}

/* docs/physics.md §5: dt_c = h / c_max; the number is dt / dt_c. A gas's
 * speed is its particles' sound speed plus their speed, at this moment.
 * A membrane whose tension acts along its segments is stable only to
 * dt c / h = LM_SEGMENT_COURANT (measured, docs/robustness.md: its strain
 * follows the points, moved with the Lagrangian grid velocity as in USL,
 * not the MUSL re-map), so its speed counts as c / LM_SEGMENT_COURANT. */
double lm_sim_courant(const lm_sim *sim, double *c_max)
{
    return lm_sim_courant_body(sim, c_max, NULL);
}

double lm_sim_courant_body(const lm_sim *sim, double *c_max, int *body)
{
    double c = 0;
    if (body) *body = -1;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        const lm_material *mat = sim->mats[bd->mat];
        double cb = lm_material_wave_speed(mat);
        if (mat->kind == LM_GAS) {
            for (size_t q = bd->first; q < bd->first + bd->count; q++) {
                double cq = lm_gas_sound_speed(mat, sim->p.e[q]) +
                            hypot(sim->p.vx[q], sim->p.vy[q]);
                if (cq > cb) cb = cq;
            }
        }
        if (bd->membrane && bd->force == LM_MFORCE_SEGMENT) cb /= LM_SEGMENT_COURANT;
        /* multi-rate stepping: a membrane steps dt / k (subcycle.c) */
        if (bd->membrane) cb /= lm_subcycle_count(sim);
        if (cb > c) {
            c = cb;
            if (body) *body = b;
        }
    }
    if (c_max) *c_max = c;
    double h = sim->grid.hx < sim->grid.hy ? sim->grid.hx : sim->grid.hy;
    return sim->def.dt * c / h;
}

void lm_sim_set_body_name(lm_sim *sim, int b, const char *name)
{
    if (b < 0 || b >= sim->nbodies) return;
    snprintf(sim->bodies[b].name, sizeof sim->bodies[b].name, "%s", name ? name : "");
}

const char *lm_num_text(char *buf, size_t len, double v)
{
    snprintf(buf, len, "%.14g", v);
    if (isfinite(v) && !strpbrk(buf, ".eE") && strlen(buf) + 2 < len) strcat(buf, ".0");
    return buf;
}

lm_status lm_sim_set_gravity(lm_sim *sim, double gx, double gy)
{
    if (!isfinite(gx) || !isfinite(gy)) {
        char a[40], b[40];
        snprintf(sim->err, sizeof sim->err, "gravity must be two finite numbers (got {%s, %s})",
                 lm_num_text(a, sizeof a, gx), lm_num_text(b, sizeof b, gy));
        return LM_ERR_INPUT;
    }
    sim->def.gx = gx;
    sim->def.gy = gy;
    return LM_OK;
}

/* "pic must lie in [0, 1] (got 2.0)": a setting refused by its rule. */
static lm_status refuse_setting(lm_sim *sim, const char *rule, double v)
{
    char a[40];
    snprintf(sim->err, sizeof sim->err, "%s (got %s)", rule, lm_num_text(a, sizeof a, v));
    return LM_ERR_INPUT;
}

lm_status lm_sim_set_pic(lm_sim *sim, double pic)
{
    if (!(pic >= 0 && pic <= 1)) return refuse_setting(sim, "pic must lie in [0, 1]", pic);
    sim->def.pic = pic;
    return LM_OK;
}

lm_status lm_sim_set_courant(lm_sim *sim, double courant)
{
    if (!(courant > 0) || !isfinite(courant))
        return refuse_setting(sim, "courant must be positive and finite", courant);
    sim->def.courant = courant;
    sim->work->courant_checked = 0;
    return LM_OK;
}

lm_status lm_sim_set_membrane_force(lm_sim *sim, int b, lm_mforce force)
{
    if (b < 0 || b >= sim->nbodies || !sim->bodies[b].membrane ||
        (force != LM_MFORCE_POINT && force != LM_MFORCE_SEGMENT)) {
        snprintf(sim->err, sizeof sim->err, "body %d is not a membrane", b + 1);
        return LM_ERR_INPUT;
    }
    sim->bodies[b].force = force;
    sim->prepared = 0;   /* segments' rest lengths are found by the next prepare */
    sim->work->courant_checked = 0;   /* a segment form's c counts / LM_SEGMENT_COURANT */
    return LM_OK;
}

lm_status lm_sim_set_membrane_normals(lm_sim *sim, int b, lm_normals normals)
{
    if (b < 0 || b >= sim->nbodies || !sim->bodies[b].membrane ||
        normals < LM_NORMALS_CONNECTIVITY || normals > LM_NORMALS_CUBIC_COLOUR) {
        snprintf(sim->err, sizeof sim->err, "body %d is not a membrane, or normals %d is "
                 "not a method", b + 1, (int)normals);
        return LM_ERR_INPUT;
    }
    sim->bodies[b].normals = normals;
    return LM_OK;
}

const char *lm_body_label(const lm_sim *sim, int b, char *buf, size_t len)
{
    const lm_body *bd = &sim->bodies[b];
    const char *kind = bd->membrane ? "membrane" : "body";
    if (bd->name[0])
        snprintf(buf, len, "%s '%s' (body %d)", kind, bd->name, b + 1);
    else
        snprintf(buf, len, "%s %d", kind, b + 1);
    return buf;
}

lm_status lm_sim_drop_last_body(lm_sim *sim)
{
    if (sim->nbodies == 0) {
        snprintf(sim->err, sizeof sim->err, "no body to take out");
        return LM_ERR_INPUT;
    }
    lm_body *bd = &sim->bodies[sim->nbodies - 1];
    for (int k = 0; k < sim->npins; k++)
        if (sim->pins[k].body == sim->nbodies - 1) {
            snprintf(sim->err, sizeof sim->err, "the body is pinned");
            return LM_ERR_INPUT;
        }
    sim->p.n = bd->first;
    sim->pe_ref -= bd->pe_ref;
    sim->nbodies--;
    return LM_OK;
}
