/* mpm_contact.h - contact between bodies, the engine's public part: the
 * laws a pair can have, adding a pair, and what contact did in the last
 * step, read-only (frames, sim:contact_info, warnings). The fields and the
 * step's hooks are the engine's own (src/mpm/contact.h). */
#ifndef LAMINA_MPM_CONTACT_H
#define LAMINA_MPM_CONTACT_H

#include "mpm.h"

typedef enum lm_contact_law {
    LM_CONTACT_RELEASE = 1,    /* [M] eq 26: own field when separating */
    LM_CONTACT_FRICTION = 2    /* release, and Coulomb sliding when pressed */
} lm_contact_law;

/* What a node did in the last step (for frames and tests). */
enum {
    LM_CNODE_NONE = 0,     /* no pair meets here */
    LM_CNODE_STICK = 1,    /* a pair met and moved in the centre-of-mass field */
    LM_CNODE_RELEASE = 2,  /* a body moved in its own field */
    LM_CNODE_SLIDE = 3     /* a friction pair slid along its common tangent */
};

/* Adds a pair (bodies a != b); -1 with sim->err naming the key if the
 * input is bad. mu only for friction (>= 0). */
int lm_sim_add_contact(lm_sim *sim, int a, int b, lm_contact_law law, double mu);

/* The release test of a pair (sim:contact's `test`): lamina's (default:
 * the pair's relative velocity along the heavier body's normal, at time
 * level k and again with the Lagrangian velocities, grazing nodes parting)
 * or [M] eq 26 / [T] eq 9.8 as printed: once, at time level k, each body's
 * velocity against the node's centre-of-mass velocity along its own
 * outward normal, release only if both part. */
typedef enum lm_contact_test {
    LM_CTEST_LAMINA = 0,
    LM_CTEST_EQ26 = 1
} lm_contact_test;
/* What a body of the pair takes where it stays in the centre-of-mass
 * field (sim:contact's `update`): lamina's (default: its velocity and
 * acceleration) or [M] eqs 20-21 / [T] eqs 9.1-9.2 as printed: its
 * acceleration only, so that its particles keep their velocity relative
 * to it (FLIP). */
typedef enum lm_contact_update {
    LM_CUPDATE_LAMINA = 0,
    LM_CUPDATE_EQ21 = 1
} lm_contact_update;
/* Sets pair k's (lm_sim_add_contact's return) test and update; -1 with
 * sim->err if k is not a pair. */
int lm_sim_contact_form(lm_sim *sim, int k, lm_contact_test test, lm_contact_update update);

/* The last step's contact (contact_view.c): the nodes of each state and
 * the grid kinetic energy at the contact nodes before and after the
 * correction (after <= before, [M] §4.1). 0 when the sim has pairs, -1
 * (and *out zeroed) when it has none. */
typedef struct lm_contact_info {
    long stick, release, slide;
    double ke_before, ke_after;
} lm_contact_info;
int lm_sim_contact_info(const lm_sim *sim, lm_contact_info *out);

/* Per node of the grid's arrays (lm_grid_node), what it did in the last
 * step (LM_CNODE_*); NULL without pairs or before the first step. */
const unsigned char *lm_sim_contact_state(const lm_sim *sim);
/* The paired bodies' own grid fields: how many (0 without pairs), and
 * field f's body, with its nodal mass and outward unit normal arrays
 * (indexed like the state) in *m, *nx, *ny. */
int lm_sim_contact_fields(const lm_sim *sim);
int lm_sim_contact_field(const lm_sim *sim, int f, const double **m, const double **nx,
                         const double **ny);
/* The first body of a pair with law LM_CONTACT_FRICTION, or -1. */
int lm_sim_contact_friction_body(const lm_sim *sim);

#endif
