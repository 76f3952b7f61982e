/* subcycle_band.h - the nodes the membranes' sub-steps sweep (subcycle_band.c;
 * multi-rate stepping, subcycle.c). */
#ifndef LAMINA_SUBCYCLE_BAND_H
#define LAMINA_SUBCYCLE_BAND_H

#include "step.h"

typedef struct lm_band {
    size_t nn;               /* the grid's nodes, ghosts included */
    long *idx;               /* the band's nodes, ascending */
    size_t n;
    unsigned char *in;       /* 1: in the band */
    unsigned char *old;      /* scratch: the band before it grew */
    unsigned char *core;     /* 1: a stencil with its lower-left node here
                                lies in the band with every node within
                                `need` of it */
    int need;
    unsigned char *zero;     /* bit 0: the walls zero a node's x component,
                                bit 1: its y component (lm_grid_apply_bc) */
    double *mark;            /* scratch, nn doubles */
} lm_band;

/* The scheme's nodal arrays (subcycle.c's lm_subcycle) that a node outside
 * the band reads and advances in its closed form. */
typedef struct lm_band_nodes {
    const double *mG, *fGx, *fGy;
    double *pGx, *pGy, *Ax, *Ay, *Xx, *Xy, *Vx, *Vy;
} lm_band_nodes;

lm_band *lm_band_new(const lm_grid *g);
void lm_band_free(lm_band *b);
/* The nodes the membranes' stencils reach now widened by need + 1 nodes
 * each way (need: how far beyond its stencils a sub-step reads; one more
 * for their motion within the step), with every ghost node's mirror across
 * a wall and back. */
void lm_band_build(lm_band *b, const lm_sim *sim, int need);
/* Every node (the sub-steps with the airbags' terms, subcycle.c). */
void lm_band_all(lm_band *b);
/* After `done` sub-steps of dt: if a membrane's stencil has come within
 * `need` of the band's edge, widen it around the stencils as lm_band_build
 * and bring the nodes taken in to sub-step `done` by the closed form (the
 * same bits as had they been swept). 1 if it grew. */
int lm_band_grow(lm_band *b, lm_sim *sim, const lm_band_nodes *a, int done, double dt);
/* f[0..nf) = 0 on the band. */
void lm_band_zero(const lm_band *b, int nf, double *const *f);
/* lm_step_grid_update, lm_step_g2p_nodes, lm_step_strain_velocity_end(sim,
 * 1) on the band (what multi-rate stepping allows: no damping, corrected
 * mass, pins or heavy ends, subcycle.c's refuse()). */
void lm_band_grid_update(lm_sim *sim, const lm_band *b);
void lm_band_g2p_nodes(lm_sim *sim, const lm_band *b, double *ux, double *uy);
void lm_band_remap_end(lm_sim *sim, const lm_band *b);
/* Every node outside the band through k sub-steps of dt at once. */
void lm_band_far(lm_sim *sim, const lm_band *b, const lm_band_nodes *a, int k, double dt);

#endif
