/* step_bspline2.h - the fused USL pass for the quadratic B-spline on one
 * thread (step_bspline2.c), called by step_fused.c's pass in place of its
 * W = 3 loop when the basis keeps no weights. */
#ifndef LAMINA_STEP_BSPLINE2_H
#define LAMINA_STEP_BSPLINE2_H

#include "elastic_moduli.h"
#include "step.h"

/* doubles in the pass's record of a node: {a_x, a_y, v^L_x, v^L_y, v_x,
 * v_y, v_x, v_y} (a cache line) */
#define LM_B2_REC 8

/* Steps 4-8, the check, the shape at x^{k+1} and the next step's sums
 * (next: m, px, py, fx, fy, m zeroed by the caller) for every particle;
 * (ux, uy) step 4's v_i^L. rec (LM_B2_REC doubles a node) and sums (4 a node, zero before
 * the first pass; the pass leaves them zero) are
 * the pass's scratch. Returns the lowest-numbered particle in trouble, or
 * n. */
size_t lm_fused_bspline2_usl(lm_sim *sim, const double *ux, const double *uy, double *rec,
                             double *sums, double *const *next);

/* The instruction set the pass runs with: AVX2 where the processor has it
 * (x86-64, GCC or clang), else the portable form; the same bits either
 * way. lm_fused_bspline2_isa forces one (tests; -1: the processor's). */
enum { LM_B2_ISA_BASELINE = 0, LM_B2_ISA_AVX2 = 1 };
void lm_fused_bspline2_isa(int set);
int lm_fused_bspline2_isa_in_use(void);

#endif
