/* contact.c - pairs of bodies in contact and their own grid fields
 * ([M] eqs 23-25, [T] eqs 9.4-9.6).
 *
 * Only bodies named in a pair get fields, so memory grows with them, not
 * with the bodies of the run. Time grows with where the pairs meet: each
 * step finds the nodes each paired body's stencils reach (a box), and the
 * union of the pairs' overlaps of those boxes (lm_contact.box). Momentum
 * and force are summed only from the particles whose stencils reach it, so
 * that at its nodes the sums are whole; mass from every particle of the
 * body (the release test needs its largest nodal mass). The normals, the
 * release test and the correction run over the nodes where a pair does
 * meet (lm_contact.met), the particle corrections over the particles next
 * to them; arrays are cleared only where the last step wrote
 * (lm_contact.dirty). While no pair can meet only the boxes are found.
 * The values that are read are the same operations in the same order as
 * over the whole grid, so the results are bit for bit those of the
 * whole-grid sweeps (docs/performance.md, "Contact's cost"). The sums are
 * done serially, body by body and particle by particle in storage order:
 * the same on every thread count (threads.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact.h"
#include "step.h"
#include "util.h"

static const lm_cbox EMPTY = {0, -1, 0, -1};

static void field_free(lm_contact_field *f)
{
    free(f->m);   /* one block: see field_alloc */
    free(f->own);
    free(f->chi);
    memset(f, 0, sizeof *f);
}

void lm_contact_free(lm_contact *c)
{
    if (!c) return;
    for (int k = 0; k < c->nf; k++) field_free(&c->f[k]);
    LU_FREE_ALL(c->f, c->pairs, c->of_body, c->flag, c->state, c->qflag, c->qi, c);
}

/* Field index of body b, adding one if new; -1 on no memory. */
static int field_of(lm_contact *c, int b)
{
    for (int k = 0; k < c->nf; k++)
        if (c->f[k].body == b) return k;
    lm_contact_field *f = lu_push(&c->f, (size_t)c->nf, sizeof *c->f);
    if (!f) return -1;
    f->body = b;
    return c->nf++;
}

int lm_sim_add_contact(lm_sim *sim, int a, int b, lm_contact_law law, double mu)
{
    char wa[96], wb[96];
    if (a < 0 || b < 0 || a >= sim->nbodies || b >= sim->nbodies) {
        snprintf(sim->err, sizeof sim->err, "a and b must be bodies of this simulation");
        return -1;
    }
    if (a == b) {
        snprintf(sim->err, sizeof sim->err,
                 "a and b are the same body (%s): contact is between two bodies",
                 lm_body_label(sim, a, wa, sizeof wa));
        return -1;
    }
    if (law != LM_CONTACT_RELEASE && law != LM_CONTACT_FRICTION) {
        snprintf(sim->err, sizeof sim->err, "law must be \"release\" or \"friction\"");
        return -1;
    }
    if (!(mu >= 0) || !isfinite(mu)) {
        snprintf(sim->err, sizeof sim->err,
                 "mu must be a finite number >= 0 (got %g)", mu);
        return -1;
    }
    /* The quadratic B-spline's stencil (1.5 cells) reaches past the layer
     * where two bodies meet, and the release test then misjudges: the
     * two-bar impact of [M] §4.2 parts with e = 0.815 / 0.875 at cells
     * 0.25 / 0.125 where uGIMP gives 0.87 / 0.90 and the bilinear basis
     * 0.874 / 0.905 (our finite-element reference 0.889 / 0.915: 0.07 and
     * 0.04 short, outside the test's 0.02; 0.46 / 0.31 before both-tails
     * grazing, contact_correct.c), and the pins of a pinned plane hold the
     * nodes one cell into a block lying on it. Refused, not run wrong. */
    if (sim->def.basis == LM_BASIS_BSPLINE2) {
        snprintf(sim->err, sizeof sim->err,
                 "basis = \"bspline2\" (the default) is not supported with contact: its "
                 "stencil, 1.5 cells wide, reaches past the contact layer and the release test "
                 "misjudges it (the two-bar impact parts with e = 0.875 at cell 0.125 where "
                 "\"gimp\" gives 0.90 and a finite-element reference 0.915); use "
                 "lamina.sim{basis = \"gimp\"} or \"linear\"");
        return -1;
    }
    for (int k = 0; k < sim->nlinks; k++)
        for (int e = 0; e < 2; e++)
            if (sim->links[k].body[e] == a || sim->links[k].body[e] == b) {
                /* the pairs' own fields would not see the link's force */
                snprintf(sim->err, sizeof sim->err,
                         "%s has a link: links and contact do not mix yet",
                         lm_body_label(sim, sim->links[k].body[e], wa, sizeof wa));
                return -1;
            }
    if (sim->def.stress == LM_STRESS_CELL) {
        /* the cell stresses mix the bodies of a cell: no force per body */
        snprintf(sim->err, sizeof sim->err,
                 "contact needs stress = \"points\": stress = \"cell\" forms one "
                 "force from every body in a cell, so a body's own force is unknown");
        return -1;
    }
    if (!sim->contact) {
        sim->contact = calloc(1, sizeof *sim->contact);
        if (!sim->contact) goto oom;
        lm_contact *n = sim->contact;
        n->box = n->met = n->dirty = n->near = n->moved = EMPTY;
        n->held_node = n->held_body = n->held_by = -1;
    }
    lm_contact *c = sim->contact;
    for (int k = 0; k < c->npairs; k++) {
        int pa = c->f[c->pairs[k].a].body, pb = c->f[c->pairs[k].b].body;
        if ((pa == a && pb == b) || (pa == b && pb == a)) {
            snprintf(sim->err, sizeof sim->err, "%s and %s are a contact pair already",
                     lm_body_label(sim, a, wa, sizeof wa),
                     lm_body_label(sim, b, wb, sizeof wb));
            return -1;
        }
    }
    int fa = field_of(c, a), fb = field_of(c, b);
    if (fa < 0 || fb < 0) goto oom;
    lm_contact_pair *p = realloc(c->pairs, (size_t)(c->npairs + 1) * sizeof *p);
    if (!p) goto oom;
    c->pairs = p;
    p[c->npairs].a = fa;
    p[c->npairs].b = fb;
    p[c->npairs].law = law;
    p[c->npairs].mu = law == LM_CONTACT_FRICTION ? mu : 0;
    p[c->npairs].test = LM_CTEST_LAMINA;
    p[c->npairs].update = LM_CUPDATE_LAMINA;
    return c->npairs++;
oom:
    snprintf(sim->err, sizeof sim->err, "out of memory for a contact pair");
    return -1;
}

int lm_sim_contact_form(lm_sim *sim, int k, lm_contact_test test, lm_contact_update update)
{
    if (!sim->contact || k < 0 || k >= sim->contact->npairs) {
        snprintf(sim->err, sizeof sim->err, "no contact pair %d", k);
        return -1;
    }
    if ((test != LM_CTEST_LAMINA && test != LM_CTEST_EQ26) ||
        (update != LM_CUPDATE_LAMINA && update != LM_CUPDATE_EQ21)) {
        snprintf(sim->err, sizeof sim->err,
                 "test must be \"lamina\" or \"eq26\", update \"lamina\" or \"eq21\"");
        return -1;
    }
    sim->contact->pairs[k].test = test;
    sim->contact->pairs[k].update = update;
    return 0;
}

/* The nodal arrays of a field: 14 doubles per node in one block. */
static lm_status field_alloc(lm_contact_field *f, size_t nn, size_t ncells)
{
    double *blk = calloc(14 * nn, sizeof(double));
    unsigned char *own = calloc(nn, 1);
    double *chi = calloc(ncells, sizeof(double));
    if (!blk || !own || !chi) {
        free(blk); free(own); free(chi);
        return LM_ERR_MEMORY;
    }
    double **arr[15] = {&f->m, &f->px, &f->py, &f->fx, &f->fy, &f->nx, &f->ny, &f->tx,
                        &f->ty, &f->s, &f->dvx, &f->dvy, &f->dax, &f->day, NULL};
    for (int k = 0; arr[k]; k++) *arr[k] = blk + (size_t)k * nn;
    f->own = own;
    f->chi = chi;
    return LM_OK;
}

/* Makes the fields for the grid and the body-to-field map (bodies can be
 * added between runs), and the particles' scratch. */
static lm_status reserve(lm_sim *sim)
{
    lm_contact *c = sim->contact;
    size_t nn = lm_grid_nodes(&sim->grid);
    size_t ncells = (size_t)sim->grid.nx * (size_t)sim->grid.ny;
    if (c->nn != nn || c->sx != sim->grid.sx) {
        free(c->state);
        c->state = calloc(nn, 1);
        if (!c->state) goto oom;
        for (int k = 0; k < c->nf; k++) {
            int b = c->f[k].body;
            field_free(&c->f[k]);
            c->f[k].body = b;
        }
        c->nn = nn;
        c->sx = sim->grid.sx;
        c->sy = (int)(nn / (size_t)sim->grid.sx);
        c->inv_sx = 1.0 / c->sx;
        c->dirty = EMPTY;
    }
    for (int k = 0; k < c->nf; k++) {
        if (c->f[k].m) continue;
        if (field_alloc(&c->f[k], nn, ncells) != LM_OK) goto oom;
        c->f[k].mbox = EMPTY;   /* all zero */
    }
    if (c->nbodies_alloc != sim->nbodies) {
        int *ob = realloc(c->of_body, (size_t)sim->nbodies * sizeof *ob);
        if (!ob) goto oom;
        c->of_body = ob;
        c->nbodies_alloc = sim->nbodies;
    }
    if (c->nflag != c->nf) {   /* not every step: no allocation in a step */
        unsigned char *fl = realloc(c->flag, (size_t)c->nf);
        if (!fl) goto oom;
        c->flag = fl;
        c->nflag = c->nf;
    }
    if (c->nq != sim->p.n) {
        size_t n = sim->p.n ? sim->p.n : 1;
        unsigned char *qf = realloc(c->qflag, n);
        if (!qf) goto oom;
        c->qflag = qf;
        int *ij = realloc(c->qi, 2 * n * sizeof *ij);   /* qi, then qj */
        if (!ij) goto oom;
        c->qi = ij;
        c->qj = ij + n;
        c->nq = sim->p.n;
    }
    for (int b = 0; b < sim->nbodies; b++) c->of_body[b] = -1;
    for (int k = 0; k < c->nf; k++) c->of_body[c->f[k].body] = k;
    return LM_OK;
oom:
    snprintf(sim->err, sizeof sim->err, "out of memory for the contact fields");
    return LM_ERR_MEMORY;
}

static lm_cbox box_meet(const lm_cbox *a, const lm_cbox *b)
{
    lm_cbox r = {a->i0 > b->i0 ? a->i0 : b->i0, a->i1 < b->i1 ? a->i1 : b->i1,
                 a->j0 > b->j0 ? a->j0 : b->j0, a->j1 < b->j1 ? a->j1 : b->j1};
    return lm_cbox_empty(&r) ? EMPTY : r;
}

/* b and r nodes around it, within the storage. */
static lm_cbox box_grow(const lm_contact *c, const lm_cbox *b, int r)
{
    if (lm_cbox_empty(b)) return EMPTY;
    lm_cbox g = {b->i0 - r, b->i1 + r, b->j0 - r, b->j1 + r};
    if (g.i0 < 0) g.i0 = 0;
    if (g.j0 < 0) g.j0 = 0;
    if (g.i1 > c->sx - 1) g.i1 = c->sx - 1;
    if (g.j1 > c->sy - 1) g.j1 = c->sy - 1;
    return g;
}

/* The nodes the stencils of the body's particles reach (walls fold a ghost
 * node's sum into a mirror node two nodes in, which the same stencil
 * reaches: the box holds the body's sums whole). */
static lm_cbox body_box(const lm_sim *sim, const lm_contact_field *f)
{
    lm_contact *c = sim->contact;
    const lm_body *bd = &sim->bodies[f->body];
    const int *node = sim->p.node;
    if (bd->count == 0) return EMPTY;
    int i0 = c->sx, i1 = -1, j0 = c->sy, j1 = -1;
    for (size_t q = bd->first; q < bd->first + bd->count; q++) {
        int i, j;
        lm_cbox_ij(c, node[q], &i, &j);
        c->qi[q] = i;
        c->qj[q] = j;
        if (i < i0) i0 = i;
        if (i > i1) i1 = i;
        if (j < j0) j0 = j;
        if (j > j1) j1 = j;
    }
    lm_cbox b = {i0, i1 + sim->grid.sw - 1, j0, j1 + sim->grid.sw - 1};
    return b;
}

/* Is q a membrane point whose tension reaches the grid along segments? */
static int segment_point(const lm_sim *sim, size_t q)
{
    const lm_body *bd = &sim->bodies[sim->p.body[q]];
    return bd->membrane && bd->force == LM_MFORCE_SEGMENT;
}

#if defined(__GNUC__)
#define LM_FORCE_INLINE inline __attribute__((always_inline))
#else
#define LM_FORCE_INLINE inline
#endif

/* body_sums' particle loop for a stencil W nodes wide: the mass of every
 * particle (for mmax), momentum and force only of those whose stencils
 * reach the contact box, so that the sums at its nodes are whole, in the
 * same order as over all of them. */
static LM_FORCE_INLINE void body_sums_w(lm_sim *sim, lm_contact_field *f, const int W)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const lm_contact *c = sim->contact;
    const lm_body *bd = &sim->bodies[f->body];
    const int NS = W * W;
    double *const fm = f->m;
    for (size_t q = bd->first; q < bd->first + bd->count; q++) {
        lm_weights wt;
        lm_weights_of(sim, q, &wt);
        const double *N = wt.N;
        const int node = p->node[q];
        const double m = p->m[q];
        if (!lm_cbox_reaches_q(c, &c->box, q, W)) {
            for (int b = 0; b < W; b++) {
                const long row = lm_stencil_row(g, node, b);
                for (int a = 0; a < W; a++) fm[row + a] += m * N[b * W + a];
            }
            continue;
        }
        const double *Gx = wt.Gx, *Gy = wt.Gy;
        const int seg = segment_point(sim, q);
        const double V = m / p->rho[q];
        for (int k = 0; k < NS; k++) {
            long i = lm_stencil_node(g, W, node, k);
            double w = m * N[k];
            fm[i] += w;
            f->px[i] += w * p->vx[q];
            f->py[i] += w * p->vy[q];
            if (seg) {
                f->fx[i] += N[k] * p->fpx[q];
                f->fy[i] += N[k] * p->fpy[q];
            } else {
                f->fx[i] -= V * (p->sxx[q] * Gx[k] + p->sxy[q] * Gy[k]);
                f->fy[i] -= V * (p->sxy[q] * Gx[k] + p->syy[q] * Gy[k]);
            }
        }
    }
}

/* f's mass zeroed where the last step left it; from now it may be
 * non-zero over the body's present nodes. */
static void mass_to_nodes(const lm_contact *c, lm_contact_field *f)
{
    double *const mz[1] = {f->m};
    lm_cbox_zero(c, &f->mbox, mz, 1);
    f->mbox = f->nodes;
}

/* Steps 1-2 for one body alone: m^I, p^I and f^I = f^int,I + m^I g, the
 * same sums as step.c's over the body's particles only ([M] eqs 23, 25),
 * then folded at the walls like the shared field; m everywhere, the rest
 * whole in the contact box (px ... fy are zero outside `dirty` here). */
static void body_sums(lm_sim *sim, lm_contact_field *f)
{
    const lm_grid *g = &sim->grid;
    lm_contact *c = sim->contact;
    mass_to_nodes(c, f);
    if (g->sw == 2) body_sums_w(sim, f, 2);
    else body_sums_w(sim, f, 3);
    double *const out[5] = {f->m, f->px, f->py, f->fx, f->fy};
    static const lm_comp comp[5] = {LM_COMP_SCALAR, LM_COMP_X, LM_COMP_Y, LM_COMP_X,
                                    LM_COMP_Y};
    lm_grid_fold(g, 5, out, comp);
    const lm_cbox *b = &c->box;
    for (int j = b->j0; j <= b->j1; j++)
        for (long i = (long)j * c->sx + b->i0; i <= (long)j * c->sx + b->i1; i++) {
            f->fx[i] += f->m[i] * sim->def.gx;
            f->fy[i] += f->m[i] * sim->def.gy;
        }
}

/* The sums of the field f as the shared field's less every other field's
 * (all bodies are paired): the mass over the body's nodes, the rest over
 * the contact box. Mass below 1e-12 of the node's is rounding: the body is
 * not there (outside its nodes the difference is that rounding, so zero). */
static void rest_sums(lm_sim *sim, lm_contact_field *f)
{
    const lm_grid *g = &sim->grid;
    lm_contact *c = sim->contact;
    mass_to_nodes(c, f);
    const lm_cbox *b = &f->nodes;
    for (int j = b->j0; j <= b->j1; j++)
        for (long i = (long)j * c->sx + b->i0; i <= (long)j * c->sx + b->i1; i++) {
            double m = g->m[i];
            for (int k = 0; k < c->nf; k++)
                if (&c->f[k] != f) m -= c->f[k].m[i];
            f->m[i] = m <= 1e-12 * g->m[i] ? 0 : m;
        }
    b = &c->box;
    for (int j = b->j0; j <= b->j1; j++)
        for (long i = (long)j * c->sx + b->i0; i <= (long)j * c->sx + b->i1; i++) {
            double px = g->px[i], py = g->py[i], fx = g->fx[i], fy = g->fy[i];
            for (int k = 0; k < c->nf; k++) {
                const lm_contact_field *o = &c->f[k];
                if (o == f) continue;
                px -= o->px[i];
                py -= o->py[i];
                fx -= o->fx[i];
                fy -= o->fy[i];
            }
            if (f->m[i] <= 1e-12 * g->m[i]) px = py = fx = fy = 0;
            f->px[i] = px;
            f->py[i] = py;
            f->fx[i] = fx;
            f->fy[i] = fy;
        }
}

lm_status lm_contact_sums(lm_sim *sim)
{
    if (!sim->contact || sim->contact->npairs == 0) return LM_OK;
    lm_status st = reserve(sim);
    if (st != LM_OK) return st;
    lm_contact *c = sim->contact;
    /* what the last step left in px ... day, cleared (tx, ty, s only
     * friction writes) */
    int friction = 0;
    for (int k = 0; k < c->npairs; k++) friction |= c->pairs[k].law == LM_CONTACT_FRICTION;
    for (int k = 0; k < c->nf; k++) {
        lm_contact_field *f = &c->f[k];
        double *const a[11] = {f->px, f->py, f->fx, f->fy, f->dvx, f->dvy,
                               f->dax, f->day, f->tx, f->ty, f->s};
        lm_cbox_zero(c, &c->dirty, a, friction ? 11 : 8);
    }
    /* where pairs can meet: both bodies of a pair reach the node */
    for (int k = 0; k < c->nf; k++) c->f[k].nodes = body_box(sim, &c->f[k]);
    c->box = EMPTY;
    for (int k = 0; k < c->npairs; k++) {
        lm_cbox m = box_meet(&c->f[c->pairs[k].a].nodes, &c->f[c->pairs[k].b].nodes);
        lm_cbox_join(&c->box, &m);
    }
    /* what the stencils of particles that reach box reach (sw - 1 nodes
     * on), and where the walls fold their ghost nodes (2 nodes in) */
    c->dirty = box_grow(c, &c->box, sim->grid.sw - 1 + 2 * sim->grid.pad);
    if (lm_cbox_empty(&c->box)) {
        /* no pair can meet: nothing below would be read (the fields keep
         * their old values, m zero outside mbox) */
        c->met = EMPTY;
        return LM_OK;
    }
    /* when every body is in a pair, the last one's sums are the shared
     * field's less the others': one scatter saved. Not with pins: at a
     * node a held body barely reaches, its true mass may be below the
     * rounding of the difference, and the node, held by the pin, would then
     * hold the other body too (measured: the block of
     * tests/physics/contact_friction.lua stuck to its pinned plane). */
    int last = c->nf == sim->nbodies && sim->npins == 0 ? c->nf - 1 : -1;
    for (int k = 0; k < c->nf; k++)
        if (k != last) body_sums(sim, &c->f[k]);
    if (last >= 0) rest_sums(sim, &c->f[last]);
    /* the nodes where a pair does meet: the rest of box needs no sweep */
    c->met = EMPTY;
    const lm_cbox *b = &c->box;
    for (int j = b->j0; j <= b->j1; j++)
        for (int ii = b->i0; ii <= b->i1; ii++) {
            long i = (long)j * c->sx + ii;
            for (int k = 0; k < c->npairs; k++)
                if (c->f[c->pairs[k].a].m[i] > 0 && c->f[c->pairs[k].b].m[i] > 0) {
                    lm_cbox one = {ii, ii, j, j};
                    lm_cbox_join(&c->met, &one);
                    break;
                }
        }
    for (int k = 0; k < c->nf; k++) {
        lm_contact_field *f = &c->f[k];
        f->mmax = 0;   /* m is zero outside its nodes */
        const lm_cbox *n = &f->nodes;
        for (int j = n->j0; j <= n->j1; j++)
            for (long i = (long)j * c->sx + n->i0; i <= (long)j * c->sx + n->i1; i++)
                if (f->m[i] > f->mmax) f->mmax = f->m[i];   /* fmax: m is a number */
        lm_contact_body_normals(sim, f);
    }
    lm_contact_release_test(sim);
    return LM_OK;
}
