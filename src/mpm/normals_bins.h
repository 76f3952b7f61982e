/* normals_bins.h - internal to the normals engine: membrane points binned
 * by grid cell (normals_grid.c), shared by the per-cell construction and
 * the centred elements (normals_centred.c). Not part of the API. */
#ifndef LAMINA_NORMALS_BINS_H
#define LAMINA_NORMALS_BINS_H

#include "normals.h"

typedef struct lm_nbins {
    long ncells;
    size_t *start;      /* ncells + 1: points of cell c are order[start[c]..] */
    size_t *order;      /* point indices sorted by cell, stable */
    long *cell;         /* per point */
    long *sum;          /* summed counts over cells (prefix sums, per axis) */
    size_t *fill;       /* ncells + 1: scratch of the counting sort */
    size_t cap_points, cap_cells, cap_sum;   /* what the arrays hold */
} lm_nbins;

/* Bins n points (errors: not finite, outside the grid, memory). b is
 * either zeroed or a previous lm_nbins_make's, whose arrays are reused
 * (grown when too small), so that a workspace's bins allocate only when
 * the grid or the point count grows. sums = 0 leaves out the summed
 * counts (sum), which only the per-cell merging reads. */
lm_nerr lm_nbins_make(const lm_ngrid *g, size_t n, const double *const x[3],
                      int sums, lm_nbins *b, char *err, size_t errlen);
void lm_nbins_free(lm_nbins *b);
/* Cell index of cell c (x fastest). */
long lm_nbins_cell_id(const lm_ngrid *g, const int c[3]);
/* Points of the cells lo .. lo + sz - 1 into idx (cell order); their count. */
size_t lm_nbins_gather(const lm_ngrid *g, const lm_nbins *b, const int lo[3],
                       const int sz[3], size_t *idx);
/* v if > 0, else d2 in 2D or d3 in 3D. */
int lm_nbins_default(const lm_ngrid *g, int v, int d2, int d3);

struct lm_nwork;

/* The centred elements (normals_centred.c): normals (not oriented) and
 * flags for every point; the elements fitted go to *els (malloc'ed, *nel of
 * them) when els is not NULL; *undefined counts undefined normals. w is the
 * workspace (normals_work.h), reserved for n points. */
lm_nerr lm_normals_centred(const lm_ngrid *g, const lm_nbins *b, size_t n,
                           const double *const x[3], const lm_nopts *o,
                           double *const nrm[3], unsigned char *flags,
                           lm_nelem **els, int *nel, size_t *undefined,
                           struct lm_nwork *w, char *err, size_t errlen);

#endif
