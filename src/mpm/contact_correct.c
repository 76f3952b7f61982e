/* contact_correct.c - the release and friction correction of the grid
 * fields ([M] §4.1 eqs 20-26, [T] A.1.3 eq 9.9; friction after
 * Bardenhagen, Brackbill & Sulsky 2001), and the particles moved by it.
 *
 * At a node where both bodies of a pair have mass, the pair separates iff
 * they move apart along the pair's normal n (out of a, into b):
 * (v^a - v^b) . n < 0, [T] eq 9.7, the same as [M] eq 26 "(v^I - v) . n^I
 * < 0 for both" with outward normals for two free bodies (docs/physics.md §4,
 * the reconstructed sign; the two-bar test, tests/physics/contact_two_bar.lua,
 * settles it: with the other sign the bars never part). A body moves in its
 * own field where all its pairs at the node separate, the papers' rule.
 *
 * One departure, for momentum: the papers have two bodies, so the other
 * body's own field and the centre-of-mass field are the same thing. With a
 * third body at the node (the wire between two disks), the bodies that
 * stay move in the centre-of-mass field of what is left once the released
 * bodies are taken out, so that the node's momentum and force are shared
 * exactly (to rounding) whatever mixes there. For two bodies this is the
 * papers' algorithm.
 *
 * Friction (law "friction"): a pair that does not separate keeps the
 * normal velocity of the shared field, and its relative tangential
 * velocity w_t is cut by at most mu times the normal one it lost,
 * w_t <- s w_t with s = max(0, 1 - mu w_n / |w_t|) (Coulomb); the
 * tangential acceleration follows with the same s, so s = 0 is the shared
 * field (stick) and mu = 0 free sliding. The normal is the pair's common
 * one, (n^a - n^b)/|n^a - n^b|, seen from each body with its sign, so that
 * the two corrections are equal and opposite (pair_normal). It acts where
 * the pair is all the mass of the node (else the pair sticks).
 *
 * The correction never raises the grid's kinetic energy: merging fields
 * into their centre of mass loses energy, and the slip keeps only the part
 * s |w_t| <= |w_t| of the relative motion. lm_contact.ke_before/ke_after
 * keep both sums for the tests.
 *
 * The shared arrays keep what the other particles use; each paired body
 * keeps its difference from them (dv, da), so the step's own loops run
 * unchanged and the paired particles get a second, small gather here. */
#include <math.h>
#include <string.h>

#include "contact.h"
#include "gather.h"
#include "step.h"

/* Mass below which a remainder is rounding (relative to the node's). */
#define REST_TOL 1e-12

static inline int pinned_node(const lm_sim *sim, long i)
{
    return sim->work->pin_w && sim->work->pin_w[i] > 0;
}

/* Is pair k present at node i (both bodies with mass)? */
static inline int pair_here(const lm_contact *c, int k, long i)
{
    return c->f[c->pairs[k].a].m[i] > 0 && c->f[c->pairs[k].b].m[i] > 0;
}

/* Share of a body's largest nodal mass below which the body only grazes a
 * node: see separating(). */
#define THIN 0.2

/* The pair's normal at node i, pointing out of a into b: the outward
 * normal of the body with more mass at the node (a's, or minus b's). The
 * colour normal of a body is tilted near its corners (45 degrees at a
 * square corner), and a block sliding on a plane would otherwise be pushed
 * back by the tilted normal of its leading corner even without friction;
 * the plane's own normal there is right. 0 if neither body has one. */
static int pair_normal(const lm_contact *c, int k, long i, double *nx, double *ny)
{
    const lm_contact_field *fa = &c->f[c->pairs[k].a], *fb = &c->f[c->pairs[k].b];
    int use_a = fa->m[i] >= fb->m[i];
    for (int t = 0; t < 2; t++, use_a = !use_a) {
        double x = use_a ? fa->nx[i] : -fb->nx[i], y = use_a ? fa->ny[i] : -fb->ny[i];
        if (x != 0 || y != 0) {
            *nx = x;
            *ny = y;
            return 1;
        }
    }
    return 0;
}

/* [M] eq 26 for pair k at node i, in the form of [T] eq 9.7 (the
 * dissertation finds both forms give the same result): do the bodies move
 * apart along the pair's normal, (v^a - v^b) . n < 0, with each body's
 * velocity p^I / m^I of whatever its arrays hold? For two free bodies this
 * is eq 26 for both at once (v^I - v is m^J/(m^a + m^b) of v^I - v^J); it
 * stays right when one body is held by a pin, whose velocity relative to
 * the shared field is then zero. A node that one body of the pair only
 * grazes counts as separating: there that body's own f/m is large and of
 * either sign from one step to the next (its particles' weights are small,
 * the gradients not), and a test that reads it makes the bars of [M] Fig 20
 * chatter between contact and release and gain energy. Grazing: less than
 * THIN of the pair's mass at the node and less than THIN of the body's own
 * largest nodal mass; the second condition keeps a light membrane against
 * a heavy disk in contact where it lies (with the first alone the ball of
 * contact_ball_net.lua passed through its net). Measured on the two-bar
 * impact at cell 0.25 with the first condition (left, right bar velocity
 * and E/E0 at t = 0.5): THIN 0 and 0.02 blow up (E/E0 4-6), 0.1: -0.15 /
 * 2.15, E/E0 1.61; 0.15: 0.08 / 1.92, 1.058; 0.2: 0.12 / 1.88, 0.995; 0.3:
 * 0.14 / 1.86, 0.954 (contact then starts late, the bars overlap a
 * particle spacing); the second changes nothing there.
 *
 * A node where BOTH bodies hold under THIN of their own largest nodal mass
 * is grazed by both and parts too, whatever their shares: with the
 * quadratic B-spline the two bars meet through a single column of nodes
 * 2.5 cells apart where each has only the tail of its stencil (weights
 * near 0.03) and the two tails are equal, so the share test above never
 * fires and the noisy f/m of both decides: the bars part late and slow.
 * Measured (e = (v_right - v_left) / v0 at t = 0.5, cells 0.25 / 0.125,
 * tests/physics/contact_two_bar_fem.lua; our FEM gives 0.889 / 0.915):
 * bspline2 0.46 / 0.31 without this test, 0.815 / 0.875 with it (in a box
 * padded by a cell, which its stencil then does not reach); uGIMP 0.870 /
 * 0.900 -> 0.868 / 0.900; bilinear 0.878 / 0.913 -> 0.874 / 0.905, whose
 * energy at t = 0.5, cell 0.125, is then 0.9955 of the start's instead of
 * 1.0245. */
static int separating(const lm_contact *c, int k, long i)
{
    const lm_contact_field *fa = &c->f[c->pairs[k].a], *fb = &c->f[c->pairs[k].b];
    double ma = fa->m[i], mb = fb->m[i];
    if (fmin(ma, mb) < THIN * (ma + mb) && (ma < THIN * fa->mmax || mb < THIN * fb->mmax))
        return 1;
    if (ma < THIN * fa->mmax && mb < THIN * fb->mmax)
        return 1;
    double nx, ny;
    if (!pair_normal(c, k, i, &nx, &ny)) return 0;
    return (fa->px[i] / ma - fb->px[i] / mb) * nx + (fa->py[i] / ma - fb->py[i] / mb) * ny < 0;
}

/* [M] eq 26 / [T] eq 9.8 as the papers print it (sim:contact{test =
 * "eq26"}), for the comparison with lamina's form above: each body's
 * velocity at time level k against the node's centre-of-mass velocity
 * (vx, vy) along its own outward normal, (v^I - v) . n^I < 0 for both
 * (the papers' "> 0" with the inward colour-gradient normal,
 * docs/physics.md §4); a body without a normal at the node does not part. No
 * grazing rule and no second test: called once, from
 * lm_contact_release_test, with the time-level-k momenta. */
static int separating_eq26(const lm_contact *c, int k, long i, double vx, double vy)
{
    for (int side = 0; side < 2; side++) {
        const lm_contact_field *f = &c->f[side ? c->pairs[k].b : c->pairs[k].a];
        double w = (f->px[i] / f->m[i] - vx) * f->nx[i] + (f->py[i] / f->m[i] - vy) * f->ny[i];
        if (!(w < 0)) return 0;
    }
    return 1;
}

/* Does a pair with [M] eqs 20-21's update (sim:contact{update = "eq21"})
 * hold field f at node i? */
static int eq21_here(const lm_contact *c, const lm_contact_field *f, long i)
{
    for (int k = 0; k < c->npairs; k++)
        if (c->pairs[k].update == LM_CUPDATE_EQ21 && pair_here(c, k, i) &&
            (&c->f[c->pairs[k].a] == f || &c->f[c->pairs[k].b] == f))
            return 1;
    return 0;
}

/* Friction of pair k at node i, neither body released: each body's
 * share s of its tangential slip against the shared field (vx, vy), and
 * the common normal seen from it (tx, ty). Returns 1 if either slides. */
static int friction(lm_contact *c, int k, long i, double vx, double vy)
{
    lm_contact_field *fa = &c->f[c->pairs[k].a], *fb = &c->f[c->pairs[k].b];
    double nx, ny;
    if (!pair_normal(c, k, i, &nx, &ny)) return 0;
    int slid = 0;
    for (int side = 0; side < 2; side++) {
        lm_contact_field *f = side ? fb : fa;
        double ux = side ? -nx : nx, uy = side ? -ny : ny;
        double wx = f->px[i] / f->m[i] - vx, wy = f->py[i] / f->m[i] - vy;
        double wn = wx * ux + wy * uy;
        double wt = hypot(wx - wn * ux, wy - wn * uy);
        double s = wt > 0 ? fmax(0, 1 - c->pairs[k].mu * fmax(wn, 0) / wt) : 0;
        f->tx[i] = ux;
        f->ty[i] = uy;
        f->s[i] = s;
        if (s > 0) {
            f->own[i] = 2;
            slid = 1;
        }
    }
    return slid;
}

/* [M] eq 26 at every node where a pair meets, first with the velocities
 * of time level k (p_i / m_i before the forces act, called from
 * lm_contact_sums): a body may move in its own field (own = 1) where it
 * meets a pair partner and every pair it meets there separates. The
 * correction tests again with the Lagrangian velocities; a body is
 * released only if both say so. Either test alone fails the two-bar
 * impact: with time level k alone the bars, whose facing velocities are
 * equal while they press on each other, are released in compression and
 * end near v0/2 (0.83 / 1.17 at t = 0.5); with the Lagrangian one alone
 * bars that part at time k but are pulled back for a step chatter. */
void lm_contact_release_test(lm_sim *sim)
{
    lm_contact *c = sim->contact;
    const lm_grid *g = &sim->grid;
    unsigned char *flag = c->flag;
    const lm_cbox *b = &c->met;   /* no pair meets outside it */
    if (lm_cbox_empty(b)) return;
    for (int k = 0; k < c->nf; k++)
        for (int j = b->j0; j <= b->j1; j++)
            memset(c->f[k].own + (long)j * c->sx + b->i0, 0, (size_t)(b->i1 - b->i0 + 1));
    for (int j = b->j0; j <= b->j1; j++)
    for (long i = (long)j * c->sx + b->i0; i <= (long)j * c->sx + b->i1; i++) {
        double mG = g->m[i];
        if (mG <= 0) continue;
        int any = 0;
        memset(flag, 0, (size_t)c->nf);
        for (int k = 0; k < c->npairs; k++) {
            if (!pair_here(c, k, i)) continue;
            int pa = c->pairs[k].a, pb = c->pairs[k].b;
            flag[pa] |= 1;
            flag[pb] |= 1;
            int part = c->pairs[k].test == LM_CTEST_EQ26
                           ? separating_eq26(c, k, i, g->px[i] / mG, g->py[i] / mG)
                           : separating(c, k, i);
            if (!part) flag[pa] |= 2, flag[pb] |= 2;
            any = 1;
        }
        if (any)
            for (int k = 0; k < c->nf; k++) c->f[k].own[i] = flag[k] == 1;
    }
}

/* lm_contact.qflag of the paired bodies' particles: does the stencil
 * reach a node where a pair met (1), one where a body moved in its own
 * field or slid (2)? Particles away from where pairs meet need no
 * correction, and most of a body is away from them. */
static void particle_flags(lm_sim *sim)
{
    lm_contact *c = sim->contact;
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const unsigned char *st = c->state;
    const int W = g->sw;
    if (lm_cbox_empty(&c->near)) return;   /* read only when it is not */
    for (int k = 0; k < c->nf; k++) {
        const lm_body *bd = &sim->bodies[c->f[k].body];
        for (size_t q = bd->first; q < bd->first + bd->count; q++) {
            unsigned char fl = 0;
            if (lm_cbox_reaches_q(c, &c->near, q, W))
                for (int j = 0; j < W * W; j++) {
                    unsigned char s = st[lm_stencil_node(g, W, p->node[q], j)];
                    if (s != LM_CNODE_NONE) fl |= 1;
                    if (s == LM_CNODE_RELEASE || s == LM_CNODE_SLIDE) fl |= 2;
                }
            c->qflag[q] = fl;
        }
    }
}

static int body_pinned(const lm_sim *sim, int b)
{
    for (int k = 0; k < sim->npins; k++)
        if (sim->pins[k].body == b) return 1;
    return 0;
}

/* A pin holds every node its points touch (pin.c). Where a pair meets at
 * such a node and an unpinned partner has nearly all of the node's mass,
 * the pin holds that partner, not its own body: with the quadratic
 * B-spline a pinned plane's stencil reaches 1.5 cells into a block lying
 * on it (its weight 0.03 at the second node row against the block's 0.97)
 * and the block cannot slide at all (measured: a = -0.003 where
 * g (sin - mu cos) = 2.40). The first such node is recorded for
 * lm_step_check, which stops the run naming both; a partner with at most
 * HELD of the mass shares the node with the pinned body, as at the
 * interface row of the linear and GIMP stencils, and is left to the
 * contact correction; so is a pinned body whose share is rounding (uGIMP's
 * weight at the edge of its support: 1e-30). */
#define HELD 0.9
static void held_check(lm_sim *sim, long i)
{
    lm_contact *c = sim->contact;
    if (c->held_body >= 0 || !pinned_node(sim, i)) return;
    int held = -1, by = -1;
    for (int k = 0; k < c->nf; k++) {
        const lm_contact_field *f = &c->f[k];
        if (!(f->m[i] > REST_TOL * sim->grid.m[i])) continue;   /* rounding: uGIMP's edge */
        if (body_pinned(sim, f->body)) by = f->body;
        else if (f->m[i] > HELD * sim->grid.m[i]) held = f->body;
    }
    if (held >= 0 && by >= 0) {
        c->held_node = i;
        c->held_body = held;
        c->held_by = by;
    }
}

/* The correction at node i. */
static void correct_node(lm_sim *sim, long i)
{
    lm_contact *c = sim->contact;
    lm_grid *g = &sim->grid;
    double mG = g->m[i];
    int any = 0;
    for (int k = 0; k < c->npairs && !any; k++) any = pair_here(c, k, i);
    if (!any) return;
    held_check(sim, i);
    double vGx = g->px[i] / mG, vGy = g->py[i] / mG;
    double aGx = g->fx[i] / mG, aGy = g->fy[i] / mG;
    /* the same test with the Lagrangian velocities p^L / m: a pair that
     * is pressed together by the step's forces stays in contact even if
     * it was parting at time k (a compressed bar released in its own field
     * would push into the other); [M] eq 26 as printed tests once */
    for (int k = 0; k < c->npairs; k++)
        if (c->pairs[k].test != LM_CTEST_EQ26 && pair_here(c, k, i) && !separating(c, k, i))
            c->f[c->pairs[k].a].own[i] = c->f[c->pairs[k].b].own[i] = 0;
    /* kinetic energy before: each paired body in its own field, the rest
     * of the node's mass as one */
    double before = 0, mC = 0, pCx = 0, pCy = 0;
    double mR = 0, pRx = 0, pRy = 0, fRx = 0, fRy = 0;
    for (int k = 0; k < c->nf; k++) {
        const lm_contact_field *f = &c->f[k];
        if (f->m[i] <= 0) continue;
        before += 0.5 * (f->px[i] * f->px[i] + f->py[i] * f->py[i]) / f->m[i];
        mC += f->m[i];
        pCx += f->px[i];
        pCy += f->py[i];
        if (f->own[i] == 1) {
            mR += f->m[i];
            pRx += f->px[i];
            pRy += f->py[i];
            fRx += f->fx[i];
            fRy += f->fy[i];
        }
    }
    double m0 = mG - mC;
    int rest0 = m0 > REST_TOL * mG && !pinned_node(sim, i);
    if (rest0) {
        double p0x = g->px[i] - pCx, p0y = g->py[i] - pCy;
        before += 0.5 * (p0x * p0x + p0y * p0y) / m0;
    }
    /* the field the others move in: what is left of the node */
    double vx = vGx, vy = vGy, ax = aGx, ay = aGy;
    int released = mR > 0;
    if (released && !pinned_node(sim, i) && mG - mR > REST_TOL * mG) {
        double ml = mG - mR;
        vx = (g->px[i] - pRx) / ml;
        vy = (g->py[i] - pRy) / ml;
        ax = (g->fx[i] - fRx) / ml;
        ay = (g->fy[i] - fRy) / ml;
        g->px[i] = mG * vx;
        g->py[i] = mG * vy;
        g->fx[i] = mG * ax;
        g->fy[i] = mG * ay;
    }
    int slid = 0;
    for (int k = 0; k < c->npairs; k++) {
        const lm_contact_pair *pr = &c->pairs[k];
        if (pr->law != LM_CONTACT_FRICTION || !pair_here(c, k, i)) continue;
        if (c->f[pr->a].own[i] || c->f[pr->b].own[i]) continue;
        double mab = c->f[pr->a].m[i] + c->f[pr->b].m[i];
        if (fabs(mG - mab) > 1e-9 * mG) continue;   /* not the pair alone */
        slid |= friction(c, k, i, vx, vy);
    }
    /* Each paired body's corrected Lagrangian velocity u: its own, the
     * shared one, or the shared one with the kept slip; dv = u - v and,
     * for the FLIP update, da = (u - v_k^I)/dt - a: a body that moves in
     * the shared field takes its velocity too, not only its acceleration
     * (with the acceleration alone, bodies that stick for a step keep
     * their relative velocity, the shared re-map of step 5 reads it as
     * strain, and the two bars of [M] Fig 20 gain energy at every such
     * step: measured six times the impact's). Bodies outside the pairs at
     * the node keep the plain shared field: then so do the paired ones. */
    double dt = sim->def.dt;
    for (int k = 0; k < c->nf; k++) {
        lm_contact_field *f = &c->f[k];
        if (f->m[i] <= 0 || (f->own[i] == 0 && rest0)) continue;
        double m = f->m[i];
        double ux = vx, uy = vy;
        if (f->own[i] == 1) {
            ux = f->px[i] / m;
            uy = f->py[i] / m;
        } else if (f->own[i] == 2) {
            double wx = f->px[i] / m - vx, wy = f->py[i] / m - vy;
            double wn = wx * f->tx[i] + wy * f->ty[i];
            ux += f->s[i] * (wx - wn * f->tx[i]);
            uy += f->s[i] * (wy - wn * f->ty[i]);
        }
        double vkx = (f->px[i] - dt * f->fx[i]) / m, vky = (f->py[i] - dt * f->fy[i]) / m;
        f->dvx[i] = ux - vx;
        f->dvy[i] = uy - vy;
        f->dax[i] = (ux - vkx) / dt - ax;
        f->day[i] = (uy - vky) / dt - ay;
        /* [M] eqs 20-21 as printed: the shared field's acceleration only */
        if (f->own[i] == 0 && eq21_here(c, f, i)) f->dax[i] = f->day[i] = 0;
    }
    /* kinetic energy after */
    double after = 0;
    for (int k = 0; k < c->nf; k++) {
        const lm_contact_field *f = &c->f[k];
        if (f->m[i] <= 0) continue;
        double ux = vx + f->dvx[i], uy = vy + f->dvy[i];
        after += 0.5 * f->m[i] * (ux * ux + uy * uy);
    }
    if (rest0) after += 0.5 * m0 * (vx * vx + vy * vy);
    c->ke_before += before;
    c->ke_after += after;
    c->state[i] = released ? LM_CNODE_RELEASE : slid ? LM_CNODE_SLIDE : LM_CNODE_STICK;
    if (released) c->nodes_release++;
    else if (slid) c->nodes_slide++;
    else c->nodes_stick++;
}

/* A pinned body's own field moves with its pins where they hold the grid,
 * as the shared field does (pin.c's lm_pin_hold, over the nodes where pairs meet):
 * p^L = m v_pin, the force to match. */
static void pin_field(const lm_sim *sim, lm_contact_field *f)
{
    int held = 0;
    for (int k = 0; k < sim->npins && !held; k++) held = sim->pins[k].body == f->body;
    if (!held) return;
    const lm_contact *c = sim->contact;
    const lm_cbox *b = &c->met;
    double dt = sim->def.dt;
    for (int j = b->j0; j <= b->j1; j++)
        for (long i = (long)j * c->sx + b->i0; i <= (long)j * c->sx + b->i1; i++) {
            if (!(sim->work->pin_w[i] > 0) || f->m[i] <= 0) continue;
            double hx = f->m[i] * sim->work->pin_vx[i] / sim->work->pin_w[i];
            double hy = f->m[i] * sim->work->pin_vy[i] / sim->work->pin_w[i];
            f->fx[i] += (hx - f->px[i]) / dt;
            f->fy[i] += (hy - f->py[i]) / dt;
            f->px[i] = hx;
            f->py[i] = hy;
        }
}

void lm_contact_correct(lm_sim *sim)
{
    lm_contact *c = sim->contact;
    if (!c || c->npairs == 0) return;
    lm_grid *g = &sim->grid;
    size_t nn = lm_grid_nodes(g);
    double dt = sim->def.dt;
    const lm_cbox *b = &c->met;   /* the fields are read there only */
    for (int k = 0; k < c->nf; k++) {
        lm_contact_field *f = &c->f[k];
        for (int j = b->j0; j <= b->j1; j++) {
            /* each body's own field damped as the shared one (damping.c) */
            if (sim->def.damping > 0)
                lm_damp_forces(sim, (long)j * c->sx + b->i0, (long)j * c->sx + b->i1 + 1, f->px,
                               f->py, f->fx, f->fy);
            for (long i = (long)j * c->sx + b->i0; i <= (long)j * c->sx + b->i1; i++) {
                f->px[i] += dt * f->fx[i];   /* [M] eq 24: p^L of the body */
                f->py[i] += dt * f->fy[i];
            }
        }
        pin_field(sim, f);
        lm_cbox_apply_bc(c, g, b, f->px, f->py);
        lm_cbox_apply_bc(c, g, b, f->fx, f->fy);
        /* s, tx, ty, dv and da are zero (lm_contact_sums cleared them) */
    }
    memset(c->state, 0, nn);
    c->ke_before = c->ke_after = 0;
    c->nodes_stick = c->nodes_release = c->nodes_slide = 0;
    /* the nodes where pairs met, and where a body moved in its own field
     * or slid: the particles near them are corrected */
    c->near = c->moved = (lm_cbox){0, -1, 0, -1};
    for (int j = b->j0; j <= b->j1; j++)
        for (int ii = b->i0; ii <= b->i1; ii++) {
            long i = (long)j * c->sx + ii;
            if (!(g->m[i] > 0)) continue;
            correct_node(sim, i);
            if (c->state[i] == LM_CNODE_NONE) continue;
            lm_cbox one = {ii, ii, j, j};
            lm_cbox_join(&c->near, &one);
            if (c->state[i] != LM_CNODE_STICK) lm_cbox_join(&c->moved, &one);
        }
    particle_flags(sim);
    static const lm_comp comp[4] = {LM_COMP_X, LM_COMP_Y, LM_COMP_X, LM_COMP_Y};
    for (int k = 0; k < c->nf; k++) {
        double *const d[4] = {c->f[k].dvx, c->f[k].dvy, c->f[k].dax, c->f[k].day};
        lm_grid_fill(g, 4, d, comp);
    }
}

/* sum_i N_iq d_i over particle q's stencil, for two nodal arrays. */
static void gather2(const lm_sim *sim, size_t q, const double *dx, const double *dy,
                    double *sx, double *sy)
{
    lm_weights wt;
    lm_weights_of(sim, q, &wt);
    *sx = lm_gather(&sim->grid, &wt, sim->p.node[q], dx);
    *sy = lm_gather(&sim->grid, &wt, sim->p.node[q], dy);
}

/* Step 4 for the paired bodies: the difference of their own fields from
 * the shared one, in the same FLIP (or blended) update; held particles
 * stay with their pins. */
void lm_contact_g2p(lm_sim *sim)
{
    lm_contact *c = sim->contact;
    if (!c || c->npairs == 0) return;
    lm_particles *p = &sim->p;
    double dt = sim->def.dt, pic = sim->def.pic;
    if (lm_cbox_empty(&c->near)) return;
    for (int k = 0; k < c->nf; k++) {
        const lm_contact_field *f = &c->f[k];
        const lm_body *bd = &sim->bodies[f->body];
        for (size_t q = bd->first; q < bd->first + bd->count; q++) {
            if (p->pin[q] || !(c->qflag[q] & 1)) continue;
            double ax, ay, ux, uy;
            gather2(sim, q, f->dax, f->day, &ax, &ay);
            gather2(sim, q, f->dvx, f->dvy, &ux, &uy);
            p->vx[q] += (1 - pic) * dt * ax + pic * ux;
            p->vy[q] += (1 - pic) * dt * ay + pic * uy;
            p->x[q] += dt * ux;
            p->y[q] += dt * uy;
        }
    }
}

/* Step 5 (MUSL) for the paired bodies: each body's re-mapped velocity
 * where it moved in its own field, the shared re-map (less the released
 * bodies) elsewhere; sliding bodies keep the share s of their tangential
 * difference. USL needs nothing: its strain velocity is v^L, whose
 * differences step 3 left in dv. */
void lm_contact_strain_velocity(lm_sim *sim)
{
    lm_contact *c = sim->contact;
    if (!c || c->npairs == 0 || sim->def.scheme != LM_MUSL) return;
    lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const int W = g->sw, NS = W * W;
    static const lm_comp comp[2] = {LM_COMP_X, LM_COMP_Y};
    const lm_cbox *mv = &c->moved;   /* where bodies moved apart or slid */
    for (int k = 0; k < c->nf; k++) {
        lm_contact_field *f = &c->f[k];
        const lm_body *bd = &sim->bodies[f->body];
        /* p^L and v^L - v cleared (they are zero outside dirty) */
        double *const z[4] = {f->px, f->py, f->dvx, f->dvy};
        lm_cbox_zero(c, &c->dirty, z, 4);
        if (lm_cbox_empty(mv)) continue;
        for (size_t q = bd->first; q < bd->first + bd->count; q++) {
            /* only where a body moved in its own field or slid */
            if (!(c->qflag[q] & 2)) continue;
            lm_weights wt;
            lm_weights_of(sim, q, &wt);
            const double *N = wt.N;
            for (int j = 0; j < NS; j++) {
                long i = lm_stencil_node(g, W, p->node[q], j);
                f->px[i] += p->m[q] * N[j] * p->vx[q];
                f->py[i] += p->m[q] * N[j] * p->vy[q];
            }
        }
        double *const out[2] = {f->px, f->py};
        lm_grid_fold(g, 2, out, comp);
        /* read below at the release and slide nodes only */
        for (int j = mv->j0; j <= mv->j1; j++)
            for (long i = (long)j * c->sx + mv->i0; i <= (long)j * c->sx + mv->i1; i++) {
                if (f->m[i] > 0) {
                    f->px[i] /= f->m[i];   /* now the body's velocity */
                    f->py[i] /= f->m[i];
                }
            }
        lm_cbox_apply_bc(c, g, mv, f->px, f->py);
    }
    for (int j = mv->j0; j <= mv->j1; j++)
    for (long i = (long)j * c->sx + mv->i0; i <= (long)j * c->sx + mv->i1; i++) {
        if (c->state[i] != LM_CNODE_RELEASE && c->state[i] != LM_CNODE_SLIDE) continue;
        double mG = g->m[i], mR = 0, pRx = 0, pRy = 0;
        for (int k = 0; k < c->nf; k++) {
            const lm_contact_field *f = &c->f[k];
            if (f->own[i] != 1) continue;
            mR += f->m[i];
            pRx += f->m[i] * f->px[i];
            pRy += f->m[i] * f->py[i];
        }
        double vx = g->vx[i], vy = g->vy[i];
        if (mR > 0 && !pinned_node(sim, i) && mG - mR > REST_TOL * mG) {
            vx = (mG * vx - pRx) / (mG - mR);
            vy = (mG * vy - pRy) / (mG - mR);
            g->vx[i] = vx;
            g->vy[i] = vy;
        }
        for (int k = 0; k < c->nf; k++) {
            lm_contact_field *f = &c->f[k];
            double wx = f->px[i] - vx, wy = f->py[i] - vy;
            if (f->own[i] == 1) {
                f->dvx[i] = wx;
                f->dvy[i] = wy;
            } else if (f->own[i] == 2) {
                double wn = wx * f->tx[i] + wy * f->ty[i];
                f->dvx[i] = f->s[i] * (wx - wn * f->tx[i]);
                f->dvy[i] = f->s[i] * (wy - wn * f->ty[i]);
            }
        }
    }
    double *const gv[2] = {g->vx, g->vy};
    lm_grid_fill(g, 2, gv, comp);
    for (int k = 0; k < c->nf; k++) {
        double *const d[2] = {c->f[k].dvx, c->f[k].dvy};
        lm_grid_fill(g, 2, d, comp);
    }
}

/* The body's strain velocity at particle q less the shared field's (MUSL,
 * after step 5), added to u: what lm_contact_gradient adds to L, for the
 * points that move with it (segment membranes, membrane_force.c). */
void lm_contact_velocity(const lm_sim *sim, size_t q, double *ux, double *uy)
{
    const lm_contact *c = sim->contact;
    const lm_particles *p = &sim->p;
    if (!c || c->npairs == 0 || p->pin[q]) return;
    int k = c->of_body[p->body[q]];
    if (k < 0 || lm_cbox_empty(&c->moved) || !(c->qflag[q] & 2)) return;
    double dx, dy;
    gather2(sim, q, c->f[k].dvx, c->f[k].dvy, &dx, &dy);
    *ux += dx;
    *uy += dy;
}

void lm_contact_gradient(const lm_sim *sim, size_t q, double L[4])
{
    const lm_contact *c = sim->contact;
    const lm_particles *p = &sim->p;
    if (!c || c->npairs == 0 || p->pin[q]) return;
    int k = c->of_body[p->body[q]];
    if (k < 0 || lm_cbox_empty(&c->moved) || !(c->qflag[q] & 2)) return;
    const lm_contact_field *f = &c->f[k];
    const lm_grid *g = &sim->grid;
    const int W = g->sw, NS = W * W;
    lm_weights wt;
    lm_weights_of(sim, q, &wt);
    const double *Gx = wt.Gx, *Gy = wt.Gy;
    for (int j = 0; j < NS; j++) {
        long i = lm_stencil_node(g, W, p->node[q], j);
        L[0] += f->dvx[i] * Gx[j];
        L[1] += f->dvx[i] * Gy[j];
        L[2] += f->dvy[i] * Gx[j];
        L[3] += f->dvy[i] * Gy[j];
    }
}
