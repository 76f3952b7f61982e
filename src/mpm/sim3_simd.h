/* sim3_simd.h - the 3D step's kernels chosen at run time by what the
 * processor has (issue 34 item 6; docs/3d.md "Speed"), private to the
 * engine. The default build has no -march: the trilinear scatters use
 * SSE2's two lanes (sim3_kernels2.h) everywhere, and AVX-512F's eight
 * (sim3_simd512.c, the only file built with -mavx512f) where the
 * processor has it; there too g2p and the stress pass take eight
 * particles a call, one a lane, their nodal values gathered (perf34).
 * All give the same bits. */
#ifndef LAMINA_SIM3_SIMD_H
#define LAMINA_SIM3_SIMD_H

#include <stddef.h>

#include "mpm3.h"

/* Steps 0-2 (the place at x^k, then m, p, f) and the MUSL re-map, for the
 * trilinear basis, particles q0 .. q1 - 1 into the fields of g (the grid
 * or a thread's view, sim3_threads.c). Call only when lm3_simd_level()
 * says so. */
void lm3_p2g2_avx512(lm3_sim *sim, const lm3_grid *g, size_t q0, size_t q1);
void lm3_remap2_avx512(lm3_sim *sim, const lm3_grid *g, size_t q0, size_t q1);
/* Step 4 (sim3_step.c g2p_at, trilinear) at particles q .. q + 7 in eight
 * lanes, the scalar bits: 1, or 0 when a new position left the grid or a
 * new velocity is not finite. */
int lm3_g2p2_avx512(lm3_sim *sim, size_t q);
/* The trilinear stress pass (sim3_step.c) at particles q .. q + 7 in
 * eight lanes, the scalar pass's bits: 1, 0 when a particle's volume went
 * to nothing (that particle left as it was), -1 when the eight are not all
 * of one elastic material (nothing done). G, lam: each material's
 * moduli. */
int lm3_stress2_avx512(lm3_sim *sim, const double *G, const double *lam, size_t q);
/* 1 when sim3_simd512.c was built with AVX-512F (x86-64, a compiler with
 * -mavx512f) */
int lm3_avx512_built(void);

/* lm3_simd_level, lm3_simd_limit: mpm3.h */

#endif
