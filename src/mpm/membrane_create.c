/* membrane_create.c - a membrane from its definition (lm_membrane_def), all
 * or nothing, with the membrane rules checked here rather than in a
 * binding ([M] §3, docs/physics.md §2; issue 19: the engine is the only writer
 * of its state, as Box2D's b2CreateBody takes a b2BodyDef).
 *
 * The rules: neighbouring points at most a cell apart, to the rounding
 * LM_SPACING_SLACK allows (docs/physics.md §2: the grid must see the
 * membrane between them, or gas passes through); every
 * point inside the domain; in the axisymmetric form no point on or across
 * the axis but an open membrane's ends (a pole); logarithmic strains within
 * (-5, 5), so that exp(-e) stays a mass. A point placed ds apart with
 * strain e stands for ds exp(-e) of unstrained membrane: that is its mass
 * (a slack membrane carries its extra material) and its reference length;
 * axisymmetric masses are per radian, times the unstrained ring radius
 * (axisym.c). */
#include <math.h>
#include <stdio.h>

#include "step.h"

void lm_membrane_def_default(lm_membrane_def *def)
{
    *def = (lm_membrane_def){0};
    def->mat = -1;
    def->orient = LM_ORIENT_CENTROID;
}

/* v printed as Lua prints it, in a buffer that lives for the statement. */
typedef struct num { char s[40]; } num;
static num fmt(double v)
{
    num n;
    lm_num_text(n.s, sizeof n.s, v);
    return n;
}

/* "membrane 'skin'" or "membrane 3": the body the definition would be. */
static const char *label(const lm_sim *sim, const lm_membrane_def *def, char *buf, size_t len)
{
    if (def->name && def->name[0]) snprintf(buf, len, "membrane '%s'", def->name);
    else snprintf(buf, len, "membrane %d", sim->nbodies + 1);
    return buf;
}

/* The rules above, before anything is added. */
static lm_status check(lm_sim *sim, const lm_membrane_def *def)
{
    const lm_grid *g = &sim->grid;
    char what[96];
    label(sim, def, what, sizeof what);
    if (def->mat < 0 || def->mat >= sim->nmats || sim->mats[def->mat]->kind != LM_MEMBRANE) {
        snprintf(sim->err, sizeof sim->err, "%s: the material is not a membrane", what);
        return LM_ERR_INPUT;
    }
    if (def->n < 2 || !def->x || !def->y) {
        snprintf(sim->err, sizeof sim->err, "%s needs at least 2 points", what);
        return LM_ERR_INPUT;
    }
    double h = fmin(g->hx, g->hy);
    if (!(def->ds > 0) || def->ds > h * (1 + LM_SPACING_SLACK)) {
        snprintf(sim->err, sizeof sim->err,
                 "%s spacing %s is larger than a cell (%s) by more than 1 %%: neighbouring "
                 "points must stay within one cell or the membrane breaks", what,
                 fmt(def->ds).s, fmt(h).s);
        return LM_ERR_INPUT;
    }
    double x1 = g->x0 + g->nx * g->hx, y1 = g->y0 + g->ny * g->hy;
    for (size_t k = 0; sim->def.axisym && k < def->n; k++) {
        int end = !def->closed && (k == 0 || k == def->n - 1);
        if (def->x[k] < 0 || (def->x[k] == 0 && !end)) {
            snprintf(sim->err, sizeof sim->err,
                     "axisymmetric: %s crosses the axis r = 0 at point %zu (%s, %s); only an "
                     "end of an open membrane may lie on it", what, k + 1, fmt(def->x[k]).s,
                     fmt(def->y[k]).s);
            return LM_ERR_INPUT;
        }
    }
    for (size_t k = 0; k < def->n; k++) {
        if (!(def->x[k] >= g->x0 && def->x[k] <= x1 && def->y[k] >= g->y0 && def->y[k] <= y1)) {
            snprintf(sim->err, sizeof sim->err,
                     "%s leaves the domain: point %zu at (%s, %s) is outside {%s, %s, %s, %s}",
                     what, k + 1, fmt(def->x[k]).s, fmt(def->y[k]).s, fmt(g->x0).s,
                     fmt(g->y0).s, fmt(x1).s, fmt(y1).s);
            return LM_ERR_INPUT;
        }
    }
    for (size_t k = 0; def->strain && k < def->n; k++) {
        if (!(def->strain[k] > -5 && def->strain[k] < 5)) {
            snprintf(sim->err, sizeof sim->err,
                     "%s: 'initial_strain' %s at point %zu must lie in (-5, 5)", what,
                     fmt(def->strain[k]).s, k + 1);
            return LM_ERR_INPUT;
        }
    }
    for (size_t k = 0; (def->vx || def->vy) && k < def->n; k++) {
        double ux = def->vx ? def->vx[k] : 0, uy = def->vy ? def->vy[k] : 0;
        if (!isfinite(ux) || !isfinite(uy)) {
            snprintf(sim->err, sizeof sim->err,
                     "%s: the velocity of point %zu is not finite", what, k + 1);
            return LM_ERR_INPUT;
        }
    }
    if (def->end_mass < 0 || !isfinite(def->end_mass)) {
        snprintf(sim->err, sizeof sim->err, "%s: end_mass must be positive (got %s)", what,
                 fmt(def->end_mass).s);
        return LM_ERR_INPUT;
    }
    if (def->force != LM_MFORCE_POINT && def->force != LM_MFORCE_SEGMENT) {
        snprintf(sim->err, sizeof sim->err, "%s: unknown force form %d", what, (int)def->force);
        return LM_ERR_INPUT;
    }
    if ((int)def->normals < LM_NORMALS_CONNECTIVITY || def->normals > LM_NORMALS_CUBIC_COLOUR) {
        snprintf(sim->err, sizeof sim->err, "%s: unknown normals method %d", what,
                 (int)def->normals);
        return LM_ERR_INPUT;
    }
    if (def->colour_with) {
        int cb = def->colour_with - 1;
        if (def->normals != LM_NORMALS_COLOUR && def->normals != LM_NORMALS_QUADRATIC_COLOUR &&
            def->normals != LM_NORMALS_CUBIC_COLOUR) {
            snprintf(sim->err, sizeof sim->err, "%s: colour_points needs a colour-function "
                     "normals method (colour, quadratic_colour, cubic_colour)", what);
            return LM_ERR_INPUT;
        }
        if (cb < 0 || cb >= sim->nbodies || sim->bodies[cb].membrane) {
            snprintf(sim->err, sizeof sim->err, "%s: colour_points: body %d is not a body of "
                     "points (a membrane's or none)", what, cb + 1);
            return LM_ERR_INPUT;
        }
    }
    return LM_OK;
}

/* The points, each with its mass and unstrained length. */
static lm_status add_points(lm_sim *sim, int b, const lm_membrane_def *def)
{
    const lm_material *mat = sim->mats[def->mat];
    for (size_t k = 0; k < def->n; k++) {
        double e = def->strain ? def->strain[k] : 0;
        double ds_ref = def->ds * exp(-e);
        int heavy = k == def->n - 1 && def->end_mass > 0;
        double m = heavy ? def->end_mass : mat->rho * mat->thickness * ds_ref;
        if (sim->def.axisym && !heavy)
            m *= lm_axisym_ring_radius(def->x[k] * exp(-e), ds_ref);
        size_t q = sim->p.n;
        lm_status st = lm_sim_add_particle(sim, b, def->x[k], def->y[k],
                                           def->vx ? def->vx[k] : 0, def->vy ? def->vy[k] : 0,
                                           m, mat->rho);
        if (st == LM_OK) st = lm_sim_set_membrane_point(sim, q, ds_ref, e);
        if (st != LM_OK) return st;
    }
    return LM_OK;
}

/* Which way the normals point: as asked, or by the curve (LM_ORIENT_CURVE,
 * membrane.c): a closed membrane's out of the region it encloses, by its
 * winding, every step; an open one's to one side of its direction, chosen
 * here and kept: the side away from the points' centroid summed over the
 * points (outward for an arc, a quarter model's included), the left on a
 * tie (a straight string). Fixed by the curve, not by a point in space,
 * the sign cannot turn as the body moves. */
static void orient(lm_sim *sim, lm_body *bd, const lm_membrane_def *def)
{
    if (def->orient != LM_ORIENT_CENTROID) {
        bd->orient = def->orient;
        bd->ox = def->ox;
        bd->oy = def->oy;
        return;
    }
    bd->orient = LM_ORIENT_CURVE;
    bd->side = 1;
    if (bd->closed) return;
    const double *x = sim->p.x, *y = sim->p.y;
    size_t a = bd->first, n = bd->count;
    double cx = 0, cy = 0;
    for (size_t q = a; q < a + n; q++) {
        cx += x[q];
        cy += y[q];
    }
    cx /= (double)n;
    cy /= (double)n;
    double s = 0, scale = 0;
    for (size_t k = 0; k < n; k++) {
        size_t i = a + (k > 0 ? k - 1 : 0), j = a + (k + 1 < n ? k + 1 : n - 1);
        /* the left normal (-dy, dx) of the chord through the neighbours */
        double dx = x[j] - x[i], dy = y[j] - y[i];
        double wx = x[a + k] - cx, wy = y[a + k] - cy;
        s += -dy * wx + dx * wy;
        scale += sqrt(dx * dx + dy * dy) * sqrt(wx * wx + wy * wy);
    }
    if (s < -1e-9 * scale) bd->side = -1;
}

int lm_sim_create_membrane(lm_sim *sim, const lm_membrane_def *def)
{
    if (check(sim, def) != LM_OK) return -1;
    int b = lm_sim_add_membrane(sim, def->mat, def->closed);
    if (b < 0) {
        snprintf(sim->err, sizeof sim->err, "out of memory");
        return -1;
    }
    if (add_points(sim, b, def) != LM_OK) {
        lm_sim_drop_last_body(sim);
        return -1;
    }
    lm_body *bd = &sim->bodies[b];
    if (def->end_mass > 0 && def->force == LM_MFORCE_SEGMENT) {
        /* the wire's own share of the heavy point stays on the lumped
         * grid, the rest rides on its constraint (constraint.c) */
        const lm_material *mat = sim->mats[def->mat];
        double e = def->strain ? def->strain[def->n - 1] : 0;
        double ds_ref = def->ds * exp(-e);
        double mw = mat->rho * mat->thickness * ds_ref;
        if (sim->def.axisym) mw *= lm_axisym_ring_radius(def->x[def->n - 1] * exp(-e), ds_ref);
        if (def->end_mass > mw) bd->end_grid_mass = mw;
        if (lm_constraint_reserve(sim) != LM_OK) {
            lm_sim_drop_last_body(sim);
            return -1;
        }
    }
    bd->normals = def->normals;
    bd->force = def->force;
    bd->colour_with = def->colour_with;
    lm_sim_set_body_name(sim, b, def->name);
    orient(sim, bd, def);
    if (lm_sim_prepare(sim) != LM_OK) {
        lm_sim_drop_last_body(sim);
        return -1;
    }
    return b;
}
