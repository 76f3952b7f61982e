/* contact.h - contact between bodies: release ([M] §4.1, [T] A.1.3) and
 * Coulomb friction (Bardenhagen et al. 2001), chosen per pair of bodies.
 *
 * Without a pair lamina's single velocity field is the papers' no-slip
 * contact ("stick"), and none of this runs: the default stays bit for bit.
 * With pairs, each body of a pair also gets its own grid mass, momentum and
 * force ([M] eqs 23-25); at a node where both bodies of a pair have mass the
 * bodies are compared with the centre-of-mass field and either move in it
 * (contact) or in their own (release), one sweep, no iteration (contact.c).
 *
 * The engine's phases stay as they are; step.c calls the four hooks below
 * at their points, and contact.c corrects the fields and the particles of
 * the paired bodies only. */
#ifndef LAMINA_CONTACT_H
#define LAMINA_CONTACT_H

#include <string.h>

#include "mpm.h"
#include "mpm_contact.h"   /* the public part: laws, node states, pairs */

typedef struct lm_contact_pair {
    int a, b;              /* indices into lm_contact.f */
    lm_contact_law law;
    double mu;
    lm_contact_test test;      /* LM_CTEST_EQ26: [M] eq 26 as printed */
    lm_contact_update update;  /* LM_CUPDATE_EQ21: [M] eqs 20-21 as printed */
} lm_contact_pair;

/* A rectangle of nodes in the grid's storage (ghost ring included): node
 * (i, j) is j * sx + i; empty when i0 > i1 or j0 > j1. The contact sums,
 * sweeps and clears run over such boxes, not the whole grid (below). */
typedef struct lm_cbox {
    int i0, i1, j0, j1;
} lm_cbox;

/* The grid fields of one body in a pair.
 *
 * Where they hold what (contact.c): m is the body's mass at every node
 * (zero outside `nodes`); the rest are only meant where pairs can meet,
 * lm_contact.box: there the sums are the whole body's, the normals and
 * own are this step's (nx, ny and own over lm_contact.met, the part of box
 * where pairs do meet, which is all that reads them). Outside `box` px ... fy hold partial sums and nx,
 * ny, own older values that nothing reads; px ... day are zero outside
 * lm_contact.dirty, and dv, da zero outside `box` but for the ghost
 * ring's images (what the particle gathers read). */
typedef struct lm_contact_field {
    int body;
    double *m, *px, *py;   /* step 1 sums; p^L after step 3; step 5 re-map */
    double *fx, *fy;       /* step 2: internal + gravity of this body */
    double *nx, *ny;       /* outward unit normal -grad chi ([M] eqs 27-28) */
    double *tx, *ty;       /* friction: the pair's common normal seen from it */
    double *s;             /* friction: share of its tangential slip kept */
    double *dvx, *dvy;     /* the body's velocity minus the shared field's
                              (step 3: v^L; step 5: the strain velocity) */
    double *dax, *day;     /* the same for the acceleration (step 4) */
    unsigned char *own;    /* 1: own field, 2: sliding, 0: shared */
    double *chi;           /* colour at cell centres, nx * ny */
    double mmax;           /* largest nodal mass of the body this step */
    lm_cbox nodes;         /* the nodes its particles' stencils reach */
    lm_cbox mbox;          /* where m may be non-zero (the last step's nodes) */
} lm_contact_field;

typedef struct lm_contact {
    lm_contact_pair *pairs;
    int npairs;
    lm_contact_field *f;
    int nf;
    int *of_body;          /* field of each body, -1: none (nbodies_alloc) */
    int nbodies_alloc;
    unsigned char *flag;   /* per field, scratch of the correction */
    int nflag;             /* fields it has room for */
    size_t nn;             /* nodes the fields were made for */
    unsigned char *state;  /* LM_CNODE_* per node, last step */
    int sx, sy;            /* the grid's storage: sx nodes a row, sy rows */
    double inv_sx;         /* 1 / sx (lm_cbox_ij) */
    lm_cbox box;           /* where pairs can meet: the union of the pairs'
                              overlaps of their bodies' nodes */
    lm_cbox met;           /* the nodes of box where a pair meets (both its
                              bodies have mass): the sweeps run over it */
    lm_cbox dirty;         /* where px ... day may be non-zero: box and the
                              nodes around that stencils reach (and, with
                              the ghost ring, the walls' images): 1 or 4 */
    lm_cbox near;          /* the nodes with a state (stick, release, slide) */
    lm_cbox moved;         /* the nodes of state release or slide */
    unsigned char *qflag;  /* per particle of a paired body, this step: 1 its
                              stencil reaches a node in near with a state,
                              2 one of state release or slide (nq of them) */
    int *qi, *qj;          /* per particle of a paired body, this step: the
                              column and row of its stencil's first node */
    size_t nq;
    /* Grid kinetic energy of the paired bodies' fields (and the rest of
     * the mass as one field) at the contact nodes, before and after the
     * correction of the last step: after <= before ([M] §4.1). */
    double ke_before, ke_after;
    long nodes_stick, nodes_release, nodes_slide;
    /* A node a pin holds where a pair meets and an unpinned partner has
     * almost all the mass (contact_correct.c, held_check): the partner is
     * held by another body's pins. The first such node and that body, or
     * -1; lm_step_check stops the run with them. */
    long held_node;
    int held_body, held_by;
} lm_contact;

/* Node idx's column i and row j in the storage (idx = j sx + i), with a
 * multiplication instead of a division: (idx + 1/2) / sx is at least
 * 1/(2 sx) from an integer, and the product's rounding error, (idx + 1/2)
 * / sx times 2^-52, is far below that for any grid (idx < 2^51). */
static inline void lm_cbox_ij(const lm_contact *c, long idx, int *i, int *j)
{
    long r = (long)(((double)idx + 0.5) * c->inv_sx);
    *j = (int)r;
    *i = (int)(idx - r * c->sx);
}

/* Does the W x W stencil whose first node is idx reach box b? */
static inline int lm_cbox_reaches(const lm_contact *c, const lm_cbox *b, long idx, int W)
{
    int i, j;
    lm_cbox_ij(c, idx, &i, &j);
    return i <= b->i1 && i + W - 1 >= b->i0 && j <= b->j1 && j + W - 1 >= b->j0;
}

static inline int lm_cbox_empty(const lm_cbox *b)
{
    return b->i0 > b->i1 || b->j0 > b->j1;
}

/* a grown to hold b too: the smallest box holding both (an empty one adds
 * nothing). The one join of the contact boxes (box, met, near, moved). */
static inline void lm_cbox_join(lm_cbox *a, const lm_cbox *b)
{
    if (lm_cbox_empty(b)) return;
    if (lm_cbox_empty(a)) {
        *a = *b;
        return;
    }
    if (b->i0 < a->i0) a->i0 = b->i0;
    if (b->i1 > a->i1) a->i1 = b->i1;
    if (b->j0 < a->j0) a->j0 = b->j0;
    if (b->j1 > a->j1) a->j1 = b->j1;
}

/* The walls' conditions (lm_grid_apply_bc) on ux, uy at the nodes of box b
 * only: the same zeroes there. */
static inline void lm_cbox_apply_bc(const lm_contact *c, const lm_grid *g, const lm_cbox *b,
                                    double *ux, double *uy)
{
    if (lm_cbox_empty(b)) return;
    int l = g->pad, r = g->nx + g->pad, bo = g->pad, t = g->ny + g->pad;
    for (int j = b->j0; j <= b->j1; j++) {
        long row = (long)j * c->sx;
        if (b->i0 <= l && l <= b->i1) {
            if (g->bc[LM_LEFT] != LM_BC_FREE) ux[row + l] = 0;
            if (g->bc[LM_LEFT] == LM_BC_FIXED) uy[row + l] = 0;
        }
        if (b->i0 <= r && r <= b->i1) {
            if (g->bc[LM_RIGHT] != LM_BC_FREE) ux[row + r] = 0;
            if (g->bc[LM_RIGHT] == LM_BC_FIXED) uy[row + r] = 0;
        }
    }
    for (int i = b->i0; i <= b->i1; i++) {
        if (b->j0 <= bo && bo <= b->j1) {
            long n = (long)bo * c->sx + i;
            if (g->bc[LM_BOTTOM] != LM_BC_FREE) uy[n] = 0;
            if (g->bc[LM_BOTTOM] == LM_BC_FIXED) ux[n] = 0;
        }
        if (b->j0 <= t && t <= b->j1) {
            long n = (long)t * c->sx + i;
            if (g->bc[LM_TOP] != LM_BC_FREE) uy[n] = 0;
            if (g->bc[LM_TOP] == LM_BC_FIXED) ux[n] = 0;
        }
    }
}

/* Does particle q's W x W stencil reach box b (qi, qj this step's)? */
static inline int lm_cbox_reaches_q(const lm_contact *c, const lm_cbox *b, size_t q, int W)
{
    int i = c->qi[q], j = c->qj[q];
    return i <= b->i1 && i + W - 1 >= b->i0 && j <= b->j1 && j + W - 1 >= b->j0;
}

/* Zeroes the n arrays a (doubles, one block n nodes apart when stride is
 * the node count, or any) over box b. */
static inline void lm_cbox_zero(const lm_contact *c, const lm_cbox *b, double *const *a, int n)
{
    if (lm_cbox_empty(b)) return;
    size_t w = (size_t)(b->i1 - b->i0 + 1) * sizeof(double);
    for (int k = 0; k < n; k++)
        for (int j = b->j0; j <= b->j1; j++) memset(a[k] + (long)j * c->sx + b->i0, 0, w);
}

/* Did any body move in its own field or slide in the last correction
 * (else lm_contact_gradient and lm_contact_velocity add nothing)? */
static inline int lm_contact_moved(const lm_contact *c)
{
    return c && c->npairs > 0 && !lm_cbox_empty(&c->moved);
}

/* lm_contact_gradient for the particles that need it: those of paired
 * bodies next to a node where one moved in its own field or slid (ask
 * lm_contact_moved once before a pass: the flags are this step's only
 * then). */
void lm_contact_gradient(const lm_sim *sim, size_t q, double L[4]);
static inline void lm_contact_gradient_near(const lm_sim *sim, size_t q, double L[4])
{
    const lm_contact *c = sim->contact;
    if (c->of_body[sim->p.body[q]] >= 0 && c->qflag[q] & 2) lm_contact_gradient(sim, q, L);
}

void lm_contact_free(lm_contact *c);

/* The hooks of the step (lm_sim_step), each a no-op without pairs:
 * after step 2, the paired bodies' own sums and normals; after step 3,
 * the release / friction correction of the fields; after step 4, the
 * paired bodies' particles moved by their fields; after step 5, their
 * strain velocities (MUSL re-map per body). */
lm_status lm_contact_sums(lm_sim *sim);
void lm_contact_correct(lm_sim *sim);
void lm_contact_g2p(lm_sim *sim);
void lm_contact_strain_velocity(lm_sim *sim);
/* In steps 6-8: adds particle q's share of the velocity gradient that its
 * own field differs by, sum_i dv_i (x) G_iq. */
void lm_contact_gradient(const lm_sim *sim, size_t q, double L[4]);
void lm_contact_velocity(const lm_sim *sim, size_t q, double *ux, double *uy);
/* Parts of lm_contact_sums in their own files: the normals at the nodes
 * where pairs meet (contact_normals.c), the release test (contact_correct.c). */
void lm_contact_body_normals(lm_sim *sim, lm_contact_field *f);
void lm_contact_release_test(lm_sim *sim);

#endif
