/* normals_work.h - internal to the normals engine: scratch memory kept
 * between calls, so that the normals of a simulation step allocate nothing
 * once the first step has sized it (issue 17 item 3: "no allocation inside
 * the step"). A simulation owns one (lm_sim.work->nwork, made with the first
 * isosurface step, grown only when a membrane holds more points than any
 * before; freed with the sim). The normals run on one thread, body after
 * body, so one workspace serves every body. Not part of the API. */
#ifndef LAMINA_NORMALS_WORK_H
#define LAMINA_NORMALS_WORK_H

#include "normals.h"
#include "normals_bins.h"

/* A point and its lattice site (normals_centred.c). */
typedef struct lm_nsite {
    long key;
    size_t i;
} lm_nsite;

/* One fit's scratch (normals_fit.c): the system [S]{phi} = {phi0} of up
 * to `rows` rows of LM_NMAX columns, and cols the QR's scratch for as many
 * rows (LM_QR_WORK(rows, LM_NMAX): its padded copy of S). smooth (NULL: none kept) holds LM_NSMOOTH_CACHE doubles: the
 * curvature rows' own S^T S (weight 1) for the last element aspect the
 * Cholesky fits met, so that it is not rebuilt for every fit. */
#define LM_NSMOOTH_CACHE (2 + 81)
typedef struct lm_nfit_scratch {
    double *S, *rhs, *cols;
    double *smooth;
    size_t rows;
    /* LM_NS_CHOLESKY fits that fell back to the QR (counted, not reset) */
    unsigned long fallbacks;
} lm_nfit_scratch;

typedef struct lm_nwork {
    size_t cap;                     /* points the per-point arrays hold */
    size_t *idx, *sel;              /* a gathered block; its points in a box */
    lm_nsite *sites, *sites_tmp;    /* centred: points by site; merge scratch */
    size_t sites_n;                 /* points sites holds from the last call
                                       (0: none), its order a starting point */
    double *nrm;                    /* 3 cap: the normals (membrane.c) */
    unsigned char *flags;           /* cap: their flags (membrane.c) */
    double *dist;                   /* orientation by neighbours: cap each */
    size_t *from;
    unsigned char *done;
    lm_nfit_scratch fit;            /* rows for cap points (+ 2 + smoothing) */
    lm_nbins bins;                  /* grown by lm_nbins_make */
    /* A measurement (docs/performance.md): when the workspace is made with
     * cmp (lm_sim_def.normals_compare, which the binding sets from
     * LAMINA_NRM_CMP), every LM_NS_CHOLESKY fit of the centred elements is
     * solved again by the QR and the angle between the two normals taken
     * at each of its points: the largest, the sum and the count, which the
     * caller reads (lm_sim_normals_compare) and prints. The normals used
     * are the Cholesky ones, so the run is the same. */
    int cmp;
    double cmp_max, cmp_sum;
    unsigned long cmp_n;
} lm_nwork;

/* Makes sure w holds n points (and the fits of up to n points); grows,
 * never shrinks. LM_NERR_MEMORY when it cannot. */
lm_nerr lm_nwork_reserve(lm_nwork *w, size_t n);
/* Frees what w holds and empties it (w itself is the caller's). */
void lm_nwork_free(lm_nwork *w);
/* A workspace on the heap, empty (cmp: the measurement above); NULL
 * without memory. */
lm_nwork *lm_nwork_new(int cmp);
void lm_nwork_delete(lm_nwork *w);

/* lm_normals_grid with the caller's workspace. */
lm_nerr lm_normals_grid_ws(const lm_ngrid *g, size_t n, const double *const x[3],
                           const lm_nopts *o, double *const nrm[3],
                           unsigned char *flags, lm_nreport *rep, lm_nwork *w,
                           char *err, size_t errlen);
/* lm_normals_orient with the scratch of w (NULL: its own). */
void lm_normals_orient_ws(size_t n, int dim, const double *const x[3],
                          double *const nrm[3], lm_norient how,
                          const double point[3], lm_nwork *w);
/* lm_nfit_element in the scratch sc (rows >= k + 2, + LM_NSMOOTH_MAXROWS
 * with smoothing). nunique >= 0: the caller has counted the distinct points
 * already (the same box and points), so they are not counted again.
 * lean & LM_NFIT_LEAN leaves out the residual (0), which only a report
 * reads; lean & LM_NFIT_INSIDE says the caller chose the points as those
 * inside the closed box (so they are finite and inside), and they are not
 * checked again. */
enum { LM_NFIT_LEAN = 1, LM_NFIT_INSIDE = 2 };
lm_nerr lm_nfit_element_ws(const lm_nbox *box, const double *const x[3],
                           const size_t *idx, size_t k, const lm_nfit_opts *o,
                           int lean, int nunique, lm_nfit *fit,
                           lm_nfit_scratch *sc, char *err, size_t errlen);
/* The 2D quadratic element's fit (f->phi) by the normal equations
 * (normals_fit_ne.c): the k points of idx with phi0 = 1 and the random
 * point with 0, plus the curvature rows when smooth > 0; -1 when T is too
 * near singular (f->phi untouched: solve by the QR instead). */
int lm_nfit_quadratic_2d_ne(lm_nfit *f, const double *const x[3], const size_t *idx,
                            size_t k, lm_nfit_scratch *sc, double smooth);
/* lm_nfit_normal at two points of the same fit (bad[l] its return value
 * for each), the two side by side: the same bits as two calls. */
void lm_nfit_normal2(const lm_nfit *f, const double a[3], const double b[3],
                     double na[3], double nb[3], int bad[2]);
/* lm_lsq_qr_cond for n <= LM_NMAX with C (LM_QR_WORK(m, n) entries)
 * given: no allocation. */
lm_nerr lm_lsq_qr_ws(int m, int n, double *A, double *b, double *x,
                     lm_lsq_info *info, int want_cond, double *C);

/* Step 1 of the QR solve (normals_qr.c): A (m x n, row-major) becomes R
 * in its leading min(m, n) rows (A P = Q R, Householder with column
 * pivoting), b becomes Q^T b, perm (0 .. n-1 on entry) the column order P;
 * work holds LM_QR_WORK(m, n) doubles of scratch. normals_qr_pivot.c. */
#define LM_QR_LD(n) (((n) + 3) / 4 * 4)
/* normals_qr.c calls it for systems of at least this many columns */
#define LM_QR_VECTOR_COLS 16
#define LM_QR_WORK(m, n) ((size_t)(m) * (LM_QR_LD(n) + 1) + 2 * (size_t)LM_QR_LD(n))
void lm_qr_pivoted(int m, int n, double *A, double *b, int *perm, double *work);
/* The instruction set lm_qr_pivoted uses: 0 the portable build's, 1 AVX2
 * (only where the processor has it), -1 the processor's best (the
 * default). The results are the same bits either way; for tests. */
void lm_qr_pivot_isa(int set);

#endif
