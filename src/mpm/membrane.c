/* membrane.c - membranes and strings: one layer of points carrying stress in
 * their local tangent frame ([M] §3, [F] §3.2, [T] §5.1, docs/physics.md §2).
 *
 * The objective form: eps_t accumulates t.de.t with the current unit tangent
 * (t.D.t is the stretching rate along the membrane); sigma is rebuilt from
 * sigma_t every step and never rotated as increments ([T] §5.1's warning).
 * Accumulating t.de.t = dl/l makes eps_t the logarithmic strain of the
 * point's length: l = ds exp(eps_t) for a point of unstrained length ds.
 * Its volume is thickness * ds * exp(eps_t) (docs/physics.md §2; the papers
 * write the small-strain form thickness * ds * (1 + eps_t); the two differ only for
 * large slack, such as the dog-bone's), never updated from tr(de), which
 * would include the gas's strain across the membrane. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "membrane_law.h"
#include "normals.h"
#include "normals_work.h"

#include "step.h"

static void tangent_of(const lm_particles *p, size_t a, size_t b, double *tx, double *ty)
{
    double dx = p->x[b] - p->x[a], dy = p->y[b] - p->y[a];
    double l = sqrt(dx * dx + dy * dy);
    if (l > 0) {
        *tx = dx / l;
        *ty = dy / l;
    }
    /* coincident neighbours: keep the previous tangent */
}

/* The neighbours of point q in curve order: wrapped on a closed curve,
 * the point itself at an open curve's ends (one-sided there). */
static void neighbours(const lm_body *bd, size_t q, size_t *prev, size_t *next)
{
    size_t first = bd->first, last = bd->first + bd->count - 1;
    *prev = q > first ? q - 1 : (bd->closed ? last : q);
    *next = q < last ? q + 1 : (bd->closed ? first : q);
}

/* Tangents along the curve's direction (sign +1) or against it (-1): the
 * normal, the tangent turned +90 degrees, is then the left of the curve's
 * direction or its right. */
static void connectivity(lm_particles *p, const lm_body *bd, int sign)
{
    for (size_t q = bd->first; q < bd->first + bd->count; q++) {
        size_t prev, next;
        neighbours(bd, q, &prev, &next);
        if (sign < 0) tangent_of(p, next, prev, &p->tx[q], &p->ty[q]);
        else tangent_of(p, prev, next, &p->tx[q], &p->ty[q]);
    }
}

/* Which side of the curve's direction LM_ORIENT_CURVE's normals take: +1
 * the left, -1 the right. A closed curve encloses its region on the left
 * when it runs counter-clockwise, i.e. when its signed area (the shoelace
 * sum, Green's theorem) is positive: its outward normals are then on the
 * right. The winding is the curve's own, so no centroid (which may lie
 * outside a non-convex membrane, or stay behind as it moves) enters. An
 * open curve keeps the side chosen at creation (membrane_create.c). */
static int curve_side(const lm_particles *p, const lm_body *bd)
{
    if (!bd->closed) return bd->side < 0 ? -1 : 1;
    double a2 = 0;
    size_t first = bd->first, n = bd->count;
    for (size_t k = 0, j = n - 1; k < n; j = k++)
        a2 += p->x[first + j] * p->y[first + k] - p->x[first + k] * p->y[first + j];
    return a2 > 0 ? -1 : 1;
}

/* The constructions without connectivity give each normal a sign of their
 * own (the random point's side, [N] §8). Under LM_ORIENT_CURVE each is
 * turned to agree with the curve's normal at the point (n . n_curve >= 0,
 * n_curve from its neighbours in curve order, on curve_side's side). Under
 * "neighbours" each agrees with its own normal of the last step (the first
 * step's: the curve's, outward on a closed membrane): neighbours in time.
 * Orienting the ring among itself each step instead (Prim's order on
 * distance, normals_orient.c) let the whole ring take either sign from step
 * to step (about 150 flips in 1.5 s, issue 30), and with the colour
 * methods' rougher normals broke the ring into pieces of either sign (22-36
 * of 100 samples more than half flipped on the falling balloon). Undefined
 * normals (flags) are skipped. */
static void orient_constructed(const lm_particles *p, const lm_body *bd, double *nx,
                               double *ny, const unsigned char *flags)
{
    size_t n = bd->count;
    if (bd->orient == LM_ORIENT_CURVE) {
        int s = curve_side(p, bd);
        for (size_t k = 0; k < n; k++) {
            size_t prev, next;
            neighbours(bd, bd->first + k, &prev, &next);
            double rx = -(p->y[next] - p->y[prev]), ry = p->x[next] - p->x[prev];
            if (s * (nx[k] * rx + ny[k] * ry) < 0) {
                nx[k] = -nx[k];
                ny[k] = -ny[k];
            }
        }
    } else if (bd->orient == LM_ORIENT_NEIGHBOURS) {
        for (size_t k = 0; k < n; k++) {
            if (flags[k] & LM_NF_UNDEFINED) continue;
            size_t q = bd->first + k;
            if (nx[k] * -p->ty[q] + ny[k] * p->tx[q] < 0) {   /* last step's normal */
                nx[k] = -nx[k];
                ny[k] = -ny[k];
            }
        }
    }
}

/* Turns tangents so that their normals point away from (ox, oy). */
static void orient_away(lm_particles *p, const lm_body *bd)
{
    for (size_t q = bd->first; q < bd->first + bd->count; q++) {
        if (-p->ty[q] * (p->x[q] - bd->ox) + p->tx[q] * (p->y[q] - bd->oy) < 0) {
            p->tx[q] = -p->tx[q];
            p->ty[q] = -p->ty[q];
        }
    }
}

/* The normals paper's construction (or a dissertation variant) on the
 * simulation's own grid, from the points alone: "isosurface" is the
 * construction on centred elements with the curvature rows
 * (normals_centred.c, docs/normals.md), "hybrid" the paper's per-cell rule
 * ([N] §8), "linear", "mass_matrix" and "mass_matrix_quadratic" per cell. The random points come
 * from the simulation's seed, the body and the step, so a run is
 * reproducible; cond(T) is not needed here and not computed. A point whose
 * normal is undefined keeps last step's tangent. The sign of the normal
 * does not matter to the stress (sigma_t t(x)t, t.de.t); it is oriented
 * (orient_constructed) only for drawing and for the scripts that read it. */
/* The construction's grid and options for body b as the step numbered
 * `step` uses them (its random points come from the sim's seed, the body
 * and the step, so the same inputs give the same fit). */
static void body_nopts(const lm_sim *sim, int b, lm_normals method, long step,
                       lm_ngrid *g, lm_nopts *o)
{
    const lm_body *bd = &sim->bodies[b];
    lm_ngrid gg = {2, {sim->grid.x0, sim->grid.y0, 0}, {sim->grid.hx, sim->grid.hy, 1},
                   {sim->grid.nx, sim->grid.ny, 1}};
    *g = gg;
    if (method == LM_NORMALS_ISOSURFACE)
        lm_nopts_centred(o);
    else
        lm_nopts_default(o);
    o->skip_cond = 1;
    o->seed = lm_nrng_mix(sim->def.seed, ((uint64_t)b << 40) ^ (uint64_t)step);
    /* "neighbours" and the curve's sign are applied after the construction
     * (orient_constructed) */
    o->orient = bd->orient == LM_ORIENT_AWAY ? LM_NORIENT_AWAY : LM_NORIENT_NONE;
    o->orient_point[0] = bd->ox;
    o->orient_point[1] = bd->oy;
    if (method != LM_NORMALS_ISOSURFACE)
        o->basis = method == LM_NORMALS_HYBRID ? LM_NB_HYBRID : LM_NB_LINEAR;
    if (method == LM_NORMALS_MASS_MATRIX_QUADRATIC) {
        /* [T] §7.7 (the run of Fig 87): the quadratic functions on the
         * nine cell centres in every cell with two points or more; "when a
         * single membrane material point was in a cell, the region
         * considered was expanded to a group of four cells and the mass
         * matrix method with linear shape functions was used" */
        o->basis = LM_NB_HYBRID;
        o->quad_min = 2;
        o->lin_min = 2;
        /* the same least squares as the mass matrix T phi = S^T phi0 ([T]
         * eq 7.12) by the pivoted QR: with 2-8 points a cell T (9 x 9) is
         * singular and the elimination stops at a zero pivot (the dog-bone
         * at cell 0.2, t = 0.256); [T] does not say how it solved those, the
         * QR gives the minimum-norm solution (normals_mass_matrix_arc's
         * Fig 85: 0.27 deg against the elimination's 2.7) */
    }
    /* the centred elements' quadratic fits by the normal equations ([N]
     * eq 13, T = L D L^T), the pivoted QR where T is near singular
     * (normals_fit.c): the QR's normals to 5e-9 degrees (measured on the
     * dog-bone) at a fraction of its cost (docs/performance.md, issue 17
     * item 3) */
    o->solver = method == LM_NORMALS_MASS_MATRIX ? LM_NS_NORMAL
              : method == LM_NORMALS_ISOSURFACE ? LM_NS_CHOLESKY : LM_NS_QR;
}

int lm_membrane_phi(const lm_sim *sim, int b, struct lm_nreport *rep, char *err, size_t errlen)
{
    const lm_body *bd = &sim->bodies[b];
    if (!bd->membrane || bd->count < 2 || bd->normals == LM_NORMALS_COLOUR ||
        bd->normals == LM_NORMALS_QUADRATIC_COLOUR || bd->normals == LM_NORMALS_CUBIC_COLOUR) {
        snprintf(err, errlen, "body %d has no phi (not a membrane, or a colour-function "
                 "method)", b + 1);
        return -1;
    }
    /* connectivity membranes: the isosurface construction on the present
     * points; the others: their own, as the last step ran it (its normals
     * were found at these positions, with the step number before the
     * count advanced) */
    lm_normals method = bd->normals == LM_NORMALS_CONNECTIVITY ? LM_NORMALS_ISOSURFACE
                                                                : bd->normals;
    long step = sim->step > 0 ? sim->step - 1 : 0;
    lm_ngrid g;
    lm_nopts o;
    body_nopts(sim, b, method, step, &g, &o);
    size_t n = bd->count;
    double *nx = malloc(2 * n * sizeof *nx);
    if (!nx) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    const double *x[3] = {sim->p.x + bd->first, sim->p.y + bd->first, NULL};
    double *nrm[3] = {nx, nx + n, NULL};
    lm_nerr e = lm_normals_grid(&g, n, x, &o, nrm, NULL, rep, err, errlen);
    free(nx);
    return e == LM_NERR_NONE ? 0 : -1;
}

/* The colour-function methods ([T] §7.1-7.3) on the membrane's points, and
 * with colour_with on another body's points too ([T] §7.5: "adding
 * material points interior to the membrane as in Fig. 66(b)"; each point
 * colour 1, so the colour marks the region the membrane holds): the
 * points handed over after the membrane's, their own normals dropped. That
 * case allocates its copy every step (the option of one comparison page). */
static lm_nerr colour_normals(const lm_sim *sim, const lm_body *bd, const lm_ngrid *g,
                              const double *const x[3], double *const nrm[3],
                              unsigned char *flags, char *why, size_t wl)
{
    lm_nerr (*method)(const lm_ngrid *, size_t, const double *const[3], double *const[3],
                      unsigned char *, char *, size_t) =
        bd->normals == LM_NORMALS_COLOUR ? lm_normals_colour
        : bd->normals == LM_NORMALS_QUADRATIC_COLOUR ? lm_normals_quadratic_colour
                                                     : lm_normals_cubic_colour;
    size_t n = bd->count;
    if (!bd->colour_with)
        return method(g, n, x, nrm, flags, why, wl);
    const lm_body *fb = &sim->bodies[bd->colour_with - 1];
    size_t m = n + fb->count;
    double *buf = malloc(4 * m * sizeof *buf);
    unsigned char *fl = malloc(m);
    if (!buf || !fl) {
        free(buf);
        free(fl);
        snprintf(why, wl, "out of memory for %zu colour points", m);
        return LM_NERR_MEMORY;
    }
    memcpy(buf, x[0], n * sizeof *buf);
    memcpy(buf + m, x[1], n * sizeof *buf);
    memcpy(buf + n, sim->p.x + fb->first, fb->count * sizeof *buf);
    memcpy(buf + m + n, sim->p.y + fb->first, fb->count * sizeof *buf);
    const double *ax[3] = {buf, buf + m, NULL};
    double *an[3] = {buf + 2 * m, buf + 3 * m, NULL};
    lm_nerr e = method(g, m, ax, an, fl, why, wl);
    if (e == LM_NERR_NONE) {
        memcpy(nrm[0], an[0], n * sizeof *buf);
        memcpy(nrm[1], an[1], n * sizeof *buf);
        memcpy(flags, fl, n);
    }
    free(buf);
    free(fl);
    return e;
}

static lm_status without_connectivity(lm_sim *sim, int b)
{
    const lm_body *bd = &sim->bodies[b];
    lm_particles *p = &sim->p;
    size_t n = bd->count;
    lm_ngrid g;
    lm_nopts o;
    body_nopts(sim, b, bd->normals, sim->step, &g, &o);
    /* the sim's workspace: allocated by the first step, grown only for a
     * larger membrane, so later steps allocate nothing here */
    if (!sim->work->nwork)
        sim->work->nwork = lm_nwork_new(sim->def.normals_compare);
    if (!sim->work->nwork || lm_nwork_reserve(sim->work->nwork, n)) {
        snprintf(sim->err, sizeof sim->err, "out of memory for the normals of body %d", b + 1);
        return LM_ERR_MEMORY;
    }
    double *nx = sim->work->nwork->nrm, *ny = nx + n;
    unsigned char *flags = sim->work->nwork->flags;
    const double *x[3] = {p->x + bd->first, p->y + bd->first, NULL};
    double *nrm[3] = {nx, ny, NULL};
    char why[256] = "";
    lm_nerr e;
    switch (bd->normals) {
    case LM_NORMALS_COLOUR:
    case LM_NORMALS_QUADRATIC_COLOUR:
    case LM_NORMALS_CUBIC_COLOUR:
        e = colour_normals(sim, bd, &g, x, nrm, flags, why, sizeof why);
        break;
    default:
        e = lm_normals_grid_ws(&g, n, x, &o, nrm, flags, NULL, sim->work->nwork, why, sizeof why);
        break;
    }
    if (e == LM_NERR_NONE && (bd->normals == LM_NORMALS_COLOUR ||
                              bd->normals == LM_NORMALS_QUADRATIC_COLOUR ||
                              bd->normals == LM_NORMALS_CUBIC_COLOUR) && bd->orient)
        lm_normals_orient(n, 2, x, nrm, o.orient, o.orient_point);
    if (e != LM_NERR_NONE) {
        snprintf(sim->err, sizeof sim->err,
                 "at t = %.6g (step %ld): the normals of membrane %d failed: %s; likely "
                 "cause: too few points in a cell region, or points outside the grid",
                 sim->t, sim->step, b + 1, why);
        return LM_ERR_UNSTABLE;
    }
    orient_constructed(p, bd, nx, ny, flags);
    for (size_t k = 0; k < n; k++) {
        if (flags[k] & LM_NF_UNDEFINED) continue;
        /* tangent = normal turned -90 degrees, so that normal = tangent
         * turned +90 as everywhere else */
        p->tx[bd->first + k] = ny[k];
        p->ty[bd->first + k] = -nx[k];
    }
    return LM_OK;
}

lm_status lm_membrane_tangents(lm_sim *sim)
{
    lm_particles *p = &sim->p;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        if (!bd->membrane || bd->count < 2) continue;
        /* "neighbours" on a closed curve: its neighbours in curve order
         * agree, outward as the default */
        int sign = bd->orient == LM_ORIENT_CURVE ||
                   (bd->orient == LM_ORIENT_NEIGHBOURS && bd->closed) ? curve_side(p, bd) : 1;
        if (bd->normals == LM_NORMALS_CONNECTIVITY) {
            connectivity(p, bd, sign);
            /* the curve's direction fixes the sign; asked to point away
             * from a point, turn the tangents (t(x)t does not change) */
            if (bd->orient == LM_ORIENT_AWAY)
                orient_away(p, bd);
        } else {
            /* a first guess for points whose normal is undefined, and
             * the reference "neighbours" keeps in time: outward on a
             * closed membrane whatever the orientation asked */
            if (!sim->prepared)
                connectivity(p, bd, bd->closed && bd->orient != LM_ORIENT_AWAY
                                        ? curve_side(p, bd) : sign);
            lm_status st = without_connectivity(sim, b);
            if (st != LM_OK) return st;
        }
    }
    return LM_OK;
}

int lm_sim_normals_compare(const lm_sim *sim, unsigned long *n, double *max_deg,
                           double *mean_deg, unsigned long *fallbacks)
{
    const lm_nwork *w = sim->work->nwork;
    if (!w || !w->cmp) return -1;
    *n = w->cmp_n;
    *max_deg = w->cmp_max;
    *mean_deg = w->cmp_n ? w->cmp_sum / (double)w->cmp_n : 0.0;
    *fallbacks = w->fit.fallbacks;
    return 0;
}

static void rebuild(const lm_material *mat, double st, double tx, double ty,
                    double *sxx, double *syy, double *sxy, double *szz)
{
    *sxx = st * tx * tx;
    *syy = st * ty * ty;
    *sxy = st * tx * ty;
    *szz = lm_membrane_szz(mat, st);
}

void lm_membrane_set_strain(const lm_material *mat, double e, double tx, double ty, double m,
                            double ds, double *et, double *rho, double *sxx, double *syy,
                            double *sxy, double *szz)
{
    *et = e;
    rebuild(mat, lm_membrane_stress(mat, e), tx, ty, sxx, syy, sxy, szz);
    *rho = m / (mat->thickness * ds * exp(e));
}

void lm_membrane_update(const lm_material *mat, double dexx, double deyy, double dexy,
                        double tx, double ty, double m, double ds, double *et,
                        double *rho, double *sxx, double *syy, double *sxy, double *szz)
{
    lm_membrane_set_strain(mat, *et + (tx * tx * dexx + 2 * tx * ty * dexy + ty * ty * deyy),
                           tx, ty, m, ds, et, rho, sxx, syy, sxy, szz);
}

/* Step 8 at a membrane point whose stress is its own (point quadrature):
 * eps_t += t.de.t along the tangent at x^{k+1}. */
void lm_membrane_update_at(lm_sim *sim, size_t q, const lm_rate *r)
{
    lm_particles *p = &sim->p;
    lm_membrane_update(sim->mats[p->mat[q]], r->dexx, r->deyy, r->dexy, p->tx[q], p->ty[q],
                       p->m[q], p->ds[q], &p->et[q], &p->rho[q], &p->sxx[q], &p->syy[q],
                       &p->sxy[q], &p->szz[q]);
}

lm_status lm_membrane_prepare(lm_sim *sim)
{
    lm_particles *p = &sim->p;
    lm_status st = lm_membrane_tangents(sim);
    if (st != LM_OK) return st;
    lm_membrane_segment_prepare(sim);
    if (sim->def.axisym) {
        lm_axisym_membrane_prepare(sim);   /* rings: the hoop too (axisym.c) */
        return LM_OK;
    }
    for (size_t q = 0; q < p->n; q++) {
        const lm_material *mat = sim->mats[p->mat[q]];
        if (mat->kind != LM_MEMBRANE) continue;
        rebuild(mat, lm_membrane_stress(mat, p->et[q]), p->tx[q], p->ty[q],
                &p->sxx[q], &p->syy[q], &p->sxy[q], &p->szz[q]);
    }
    return LM_OK;
}
