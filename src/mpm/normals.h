/* normals.h - the normals construction's internals (private to the engine):
 * its random numbers, the 1D B-splines and the basis' derivatives, the dense
 * least squares, the curvature penalty and the fit options of an element.
 * The construction's public part (bases, fits, grids, reports, the
 * dissertation's variants) is include/mpm_normals.h, with the paper's
 * description of the method. */
#ifndef LAMINA_NORMALS_H
#define LAMINA_NORMALS_H

#include <stddef.h>
#include <stdint.h>

#include "mpm_normals.h"

/* ---- random numbers (normals_rng.c) ------------------------------------ */

/* SplitMix64 (Steele, Lea & Flood 2014): a tiny seeded generator; the
 * random points are its only use, so runs are reproducible. */
typedef struct lm_nrng { uint64_t s; } lm_nrng;
void lm_nrng_seed(lm_nrng *r, uint64_t seed);
uint64_t lm_nrng_next(lm_nrng *r);
double lm_nrng_uniform(lm_nrng *r);          /* [0, 1), 53 bits */
/* A stream for element `key` of a run seeded `seed`: independent of the
 * order in which elements are visited. */
uint64_t lm_nrng_mix(uint64_t seed, uint64_t key);

/* 1D B-splines of order 1 and 2 ([N] eq 6, §5) and their derivatives. */
double lm_bspline1(double t);
double lm_bspline1_d(double t);
double lm_bspline2(double t);
double lm_bspline2_d(double t);

/* s[I] = s(xi - I) and ds[I][a] = d s / d xi_a for every I. */
void lm_nbasis_eval(lm_nbasis b, int dim, const double xi[3],
                    double s[LM_NMAX], double ds[LM_NMAX][3]);
/* g_a = sum_I c_I ds_I/dxi_a for the 2D quadratic basis at xi (g[2] = 0):
 * the sum lm_nbasis_eval's ds would give, term for term in the order of I,
 * without the table. */
void lm_nbasis_grad_quadratic_2d(const double xi[3], const double c[9], double g[3]);

/* ---- dense least squares (normals_qr.c, normals_ne.c) --------------------- */

/* Relative tolerance on |R_kk| / |R_00| below which the pivoted QR treats
 * the rest as rank deficient: cond(R) up to 1e10 (cond(T) 1e20) is kept. */
#define LM_LSQ_RANK_TOL 1e-10

/* min |A x - b|, and among the minimisers the one of least |x|: A is m x n
 * row-major, overwritten, b (length m) overwritten. Householder
 * QR with column pivoting, then a complete orthogonal decomposition when
 * rank < n. Returns LM_NERR_NONE or LM_NERR_MEMORY. */
lm_nerr lm_lsq_qr(int m, int n, double *A, double *b, double *x,
                  lm_lsq_info *info);
/* The same; with want_cond = 0 the singular values are not computed
 * (cond_t and cond_t_rank are NAN): half the cost of a small fit, for the
 * per-step normals of a simulation, which never read cond(T). */
lm_nerr lm_lsq_qr_cond(int m, int n, double *A, double *b, double *x,
                       lm_lsq_info *info, int want_cond);
/* The normal equations (A^T A) x = A^T b by Gaussian elimination with
 * partial pivoting ([N] eq 13). A and b are not changed. An exactly zero
 * pivot gives LM_NERR_SINGULAR. */
lm_nerr lm_lsq_normal(int m, int n, const double *A, const double *b,
                      double *x, lm_lsq_info *info);
/* Singular values of the m x n row-major A (one-sided Jacobi), largest
 * first, into sv[n] (zeros when m < n). */
lm_nerr lm_singular_values(int m, int n, const double *A, double *sv);

/* Distinct points among idx[0..k) (closer than 1e-12 of the box per axis:
 * the same point). */
int lm_npoints_unique(const lm_nbox *b, const double *const x[3],
                      const size_t *idx, size_t k);

/* ---- the curvature penalty (normals_smooth.c) ------------------------------- */

/* Most rows lm_nsmooth_rows writes (3D quadratic: 27 + 36). */
#define LM_NSMOOTH_MAXROWS 63
/* Rows w (D_p - mean_q D_q) phi = 0 for every second difference D_p of the
 * quadratic coefficients along one axis (world-scaled), and w C phi = 0
 * for every mixed difference C, into S (rows of lm_nbasis_count(b, dim)
 * entries). Returns their number; 0 for the linear basis. A phi with
 * isotropic constant curvature - a + b.x + c |x|^2: planes, lines, circles,
 * spheres - makes every row zero. */
int lm_nsmooth_rows(lm_nbasis b, const lm_nbox *box, double w, double *S);

/* An element's fit options: the defaults, then the grid's solver, phi2,
 * cond_limit, smooth, clearance and skip_cond, and its seed mixed with key
 * (one random stream per element). */
void lm_nfit_opts_of(lm_nfit_opts *fo, const lm_nopts *o, uint64_t key);

/* The robust construction for dynamic runs (docs/normals.md, "Centred
 * elements"): the defaults with element = CENTRED, the quadratic basis,
 * smooth = LM_NSMOOTH and clearance = LM_NCLEARANCE. */
#define LM_NSMOOTH 2e-3
#define LM_NCLEARANCE 0.1
void lm_nopts_centred(lm_nopts *o);

#endif
