/* mpm_normals.h - membrane normals without connectivity: the isosurface
 * construction of the normals paper ([N] §3-6) and the dissertation's
 * variants ([T] Ch. 7), in 2D and 3D. This is the public part, what
 * lamina.normals and its figures call; the random numbers, the dense least
 * squares and the curvature penalty behind it are the engine's own
 * (src/mpm/normals.h).
 *
 * The idea ([N] §3): regard the membrane as the isosurface phi = 1 of
 *     phi(x) = sum_I phi_I S(x - x_I),                       [N] eq 10
 * fit the phi_I to the membrane points in the least-squares sense, with one
 * random point of phi = 0 so that the constant phi = 1 is not the answer
 * ([N] §4), and take the normal as the normalised gradient
 *     n_p = sum_I phi_I grad S(x - x_I) |x_p                 [N] eq 11, 16.
 *
 * Bases, over one element mapped to logical coordinates xi in [0,1]^d:
 *   linear    (LM_NB_LINEAR):    tensor B-splines beta_1 on the nodes,
 *                                2^d unknowns (4 in 2D, 8 in 3D; [N] eq 6);
 *   quadratic (LM_NB_QUADRATIC): tensor B-splines beta_2 on the centres of
 *                                the element and its neighbours, 3^d
 *                                unknowns (9 in 2D, 27 in 3D; [N] §5).
 *
 * Solvers ([N] §6): Householder QR with column pivoting on [S] itself, and
 * for any rank-deficient or underdetermined system the minimum-norm
 * least-squares solution through a complete orthogonal decomposition
 * (LM_NS_QR, the default); or the normal equations [T]{phi} = [S]^T{phi0},
 * T = S^T S ([N] eq 13), by Gaussian elimination with partial pivoting
 * (LM_NS_NORMAL, kept for the paper's comparison). The condition number
 * reported is that of T, as in the paper's Tables I-II: cond(T) = cond(R)^2
 * = (sigma_max / sigma_min)^2 from the singular values of S.
 *
 * Nothing here does I/O, Lua or drawing. Errors are values (lm_nerr) with a
 * one-line message in err[errlen]; no function returns a NaN normal: a
 * normal that is undefined (zero gradient) is returned as the zero vector
 * and flagged LM_NF_UNDEFINED. */
#ifndef LAMINA_MPM_NORMALS_H
#define LAMINA_MPM_NORMALS_H

#include <stddef.h>
#include <stdint.h>

#define LM_NMAX 27          /* unknowns of the largest basis (3D quadratic) */

typedef enum lm_nbasis {
    LM_NB_LINEAR = 1,
    LM_NB_QUADRATIC = 2,
    LM_NB_HYBRID = 3        /* grids only: [N] §8's rule, see lm_nopts */
} lm_nbasis;

/* LM_NS_CHOLESKY: the normal equations [N] eq 13 by Cholesky for the 2D
 * quadratic fits of the centred elements (the simulation's per-step
 * normals, normals_fit.c), the pivoted QR wherever T is too near singular
 * for them and for every other fit. */
typedef enum lm_nsolver { LM_NS_QR = 0, LM_NS_NORMAL = 1, LM_NS_CHOLESKY = 2 } lm_nsolver;

typedef enum lm_nerr {
    LM_NERR_NONE = 0,
    LM_NERR_INPUT,          /* a bad argument (dimension, box, option) */
    LM_NERR_NOT_FINITE,     /* a coordinate is NaN or infinite */
    LM_NERR_OUTSIDE,        /* a point lies outside the element or grid */
    LM_NERR_TOO_FEW,        /* too few distinct points, no merge possible */
    LM_NERR_SINGULAR,       /* normal equations: an exactly zero pivot */
    LM_NERR_UNDEFINED,      /* a normal is undefined (zero gradient) */
    LM_NERR_MEMORY
} lm_nerr;

/* Per-point flags (lm_normals_grid) and per-element flags (lm_nfit). */
enum {
    LM_NF_UNDEFINED = 1,        /* |grad phi| = 0 there: normal left 0 */
    LM_NF_MERGED = 2,           /* solved on a merged 2x2 (or larger) block */
    LM_NF_UNDERDETERMINED = 4,  /* rank < unknowns: minimum-norm solution */
    LM_NF_COINCIDENT = 8,       /* the element holds coincident points */
    LM_NF_REDRAWN = 16          /* the random point was drawn again */
};

/* ---- bases (normals_basis.c) --------------------------------------------- */

/* Unknowns of a basis in dimension dim (2 or 3): 4, 9, 8, 27. */
int lm_nbasis_count(lm_nbasis b, int dim);
/* Logical position of basis node I (I = i + a (j + a k), a = 2 or 3):
 * linear nodes at {0, 1}^d, quadratic centres at {-1/2, 1/2, 3/2}^d. */
void lm_nbasis_node(lm_nbasis b, int dim, int I, double xi[3]);
/* An element (or a merged block of elements): a box, [N] eq 4 restricted
 * to rectangular elements. */
typedef struct lm_nbox { int dim; double lo[3], hi[3]; } lm_nbox;
void lm_nbox_to_logical(const lm_nbox *b, const double x[3], double xi[3]);
void lm_nbox_to_world(const lm_nbox *b, const double xi[3], double x[3]);

/* ---- dense least squares (normals_qr.c, normals_ne.c; normals.h) ---------- */

/* What a fit's solve reports (lm_nfit.info). */
typedef struct lm_lsq_info {
    int rank;               /* numerical rank found by the pivoted QR */
    double cond_t;          /* cond(T) = (smax/smin)^2; inf if rank < n */
    double cond_t_rank;     /* the same over the rank-r part */
} lm_lsq_info;

/* ---- one element: the fit (normals_fit.c) -------------------------------- */

/* The extra point that keeps phi = 1 from being a maximum ([N] §8): a
 * second random point with phi = 2. It lands on the phi = 0 point's side
 * about half the time; the least squares then cannot honour both, and the
 * fit degrades (measured in docs/normals.md). Off by default. */
enum { LM_PHI2_NONE = 0, LM_PHI2_RANDOM = 1 };

typedef struct lm_nfit_opts {
    lm_nbasis basis;            /* LINEAR or QUADRATIC */
    lm_nsolver solver;
    int random_given;           /* use random_point, else draw from seed */
    double random_point[3];
    uint64_t seed;
    int phi2;                   /* LM_PHI2_*: an extra point above phi = 1 */
    int phi2_given;             /* use phi2_point (value 2) */
    double phi2_point[3];
    double cond_limit;          /* > 0: redraw the random point while
                                   cond(T) exceeds it ([N] §4 suggests it) */
    int min_points;             /* fewer distinct points: LM_NERR_TOO_FEW
                                   (0: the dimension, 2 in 2D, 3 in 3D) */
    /* Not in the paper; 0 (the default) leaves its construction as is.
     * Used together by the centred elements of lm_normals_grid. */
    double smooth;              /* > 0: rows penalising the anisotropic part
                                   of phi's curvature, weight smooth * sqrt(
                                   rows) (quadratic basis; normals_smooth.c) */
    double clearance;           /* > 0: the random point at least this far
                                   (in the element's logical units) from
                                   every membrane point, else redrawn */
    int skip_cond;              /* 1: cond(T) not computed (NAN) */
} lm_nfit_opts;

void lm_nfit_opts_default(lm_nfit_opts *o);

typedef struct lm_nfit {
    int dim;
    lm_nbasis basis;
    lm_nbox box;
    int n;                      /* unknowns */
    double phi[LM_NMAX];        /* phi_I at the basis nodes */
    double q[3];                /* the phi = 0 point */
    int has_q2;
    double q2[3];               /* the phi = 2 point */
    int rows;                   /* equations: points + 1 (+ 1) */
    int smooth_rows;            /* penalty rows added (opts.smooth > 0) */
    int npoints, nunique;       /* membrane points, distinct ones */
    lm_lsq_info info;
    lm_nsolver solver;
    double residual;            /* max |phi(x_p) - 1| over the points */
    int draws;                  /* random points drawn */
    int flags;                  /* LM_NF_* */
} lm_nfit;

/* Fits phi on the element `box` to the k points idx[0..k) of the point set
 * x[0..dim) (structure of arrays; idx NULL: points 0..k-1): rows phi = 1
 * at the points, phi = 0 at the random point, phi = 2 at the optional
 * extra point ([N] eq 10, §4, §8). Points must lie in the box (1e-9 of its
 * size allowed outside). */
lm_nerr lm_nfit_element(const lm_nbox *box, const double *const x[3],
                        const size_t *idx, size_t k, const lm_nfit_opts *o,
                        lm_nfit *fit, char *err, size_t errlen);
/* phi anywhere: the sum over this element's basis functions (a local
 * B-spline function; it decays to 0 away from the element). */
double lm_nfit_phi(const lm_nfit *f, const double x[3]);
/* grad phi in world units. */
void lm_nfit_grad(const lm_nfit *f, const double x[3], double g[3]);
/* The unit normal grad phi / |grad phi| ([N] eq 11, 16); 0 if defined,
 * else -1 with n = 0 (|grad phi| below 1e-10 of phi's scale). */
int lm_nfit_normal(const lm_nfit *f, const double x[3], double n[3]);

/* ---- a grid: per-element assembly, merging, hybrid (normals_grid.c) ------- */

typedef struct lm_ngrid {
    int dim;
    double x0[3];               /* lower corner */
    double h[3];                /* cell size */
    int n[3];                   /* cells per axis (n[2] = 1 in 2D) */
} lm_ngrid;

typedef enum lm_norient {
    LM_NORIENT_NONE = 0,        /* the sign of grad phi (arbitrary, [N] §8) */
    LM_NORIENT_SEQUENCE,        /* agree with the previous point in order */
    LM_NORIENT_NEIGHBOURS,      /* agree with the nearest already-oriented
                                   point, grown from point 0 (no order) */
    LM_NORIENT_AWAY             /* point away from orient_point */
} lm_norient;

/* Which elements the points take their normals from. */
typedef enum lm_nelement {
    LM_NELEM_CELL = 0,          /* each cell's own fit, merged 2x2, 4x4 ...
                                   when short of points ([N] §3-4, §8) */
    LM_NELEM_CENTRED = 1        /* one-cell elements centred on the half-cell
                                   lattice nearest each point (normals_centred.c) */
} lm_nelement;

typedef struct lm_nopts {
    lm_nbasis basis;            /* LINEAR, QUADRATIC or HYBRID */
    lm_nsolver solver;
    uint64_t seed;
    int phi2;                   /* LM_PHI2_* in every element */
    int quad_min;               /* HYBRID: quadratic from this many distinct
                                   points (0: 7 in 2D as [N] §8, 26 in 3D) */
    int lin_min;                /* fewer: merge blocks (0: 3 in 2D, 7 in 3D) */
    int merge;                  /* merge 2x2 blocks when short of points */
    double cond_limit;          /* see lm_nfit_opts */
    lm_norient orient;
    double orient_point[3];
    lm_nelement element;        /* CELL (default) or CENTRED */
    double smooth, clearance;   /* for every fit: see lm_nfit_opts */
    int skip_cond;              /* for every fit: cond(T) not computed */
} lm_nopts;

void lm_nopts_default(lm_nopts *o);

typedef struct lm_nelem {
    int cell[3];                /* the cell whose points take this normal
                                   (CENTRED: the cell holding its centre) */
    int lo[3], size;            /* the block solved: lower cell, cells/axis
                                   (CENTRED: the cells it overlaps from lo;
                                   size = its width in cells) */
    int site[3];                /* CENTRED: the half-cell lattice site whose
                                   points took this fit (centre x0 + (s + 1)
                                   h / 2 per axis); 0 for per-cell fits */
    lm_nfit fit;
} lm_nelem;

typedef struct lm_nreport {
    lm_nelem *elem;             /* one per occupied cell (CENTRED: per
                                   element fitted) */
    int nelem;
    int *cell_elem;             /* per cell: index into elem, or -1
                                   (CENTRED: -1 everywhere) */
    int ncells;
    size_t nundefined;          /* points with an undefined normal */
    int nmerged, nunder, ncoincident, nquadratic, nlinear;
} lm_nreport;

void lm_nreport_free(lm_nreport *r);

/* Normals at n points x[0..dim) in the grid g, one element at a time
 * (element = CELL; for CENTRED see normals_centred.c):
 * each occupied cell's points are fitted on that cell (basis by the
 * options; HYBRID: quadratic with >= quad_min distinct points, linear with
 * >= lin_min), and a cell with fewer than lin_min distinct points joins a
 * 2x2 block of cells, then 4x4, ... ([N] §4), solved with the linear basis
 * under HYBRID ([N] §8) or the fixed basis otherwise; the cell's points
 * take the normal of that fit. nrm[0..dim) receives unit normals; flags[n] (optional) LM_NF_*
 * per point; rep (optional) the elements, to be freed with
 * lm_nreport_free. Points outside the grid, non-finite coordinates, or a
 * grid with fewer distinct points than the dimension are errors. */
lm_nerr lm_normals_grid(const lm_ngrid *g, size_t n, const double *const x[3],
                        const lm_nopts *o, double *const nrm[3],
                        unsigned char *flags, lm_nreport *rep, char *err,
                        size_t errlen);

/* The cell holding x (a point on the far edge belongs to the last cell);
 * -1 outside. */
long lm_ngrid_cell(const lm_ngrid *g, const double x[3], int c[3]);

/* ---- orientation (normals_orient.c) ---------------------------------------- */

/* Fixes the arbitrary sign of grad phi ([N] §8: "normal vectors flipped in
 * direction from the majority"). Zero normals are left alone. */
void lm_normals_orient(size_t n, int dim, const double *const x[3],
                       double *const nrm[3], lm_norient how,
                       const double point[3]);

/* ---- the dissertation's variants ([T] Ch. 7; normals_variants.c) ---------- */

/* [T] §7.1: the simple colour function, n_i = sum_p chi_p G_ip at the
 * nodes, n_p = sum_i n_i N_ip (linear basis, chi_p = 1). */
lm_nerr lm_normals_colour(const lm_ngrid *g, size_t n, const double *const x[3],
                          double *const nrm[3], unsigned char *flags,
                          char *err, size_t errlen);
/* [T] §7.2: colour at cell centres by the quadratic B-spline,
 * chi_c = sum_p chi_p S2(x_p - x_c); nodal gradient n_i = sum_c chi_c
 * grad N_i(x_c); n_p = sum_i n_i N_ip. */
lm_nerr lm_normals_quadratic_colour(const lm_ngrid *g, size_t n,
                                    const double *const x[3],
                                    double *const nrm[3], unsigned char *flags,
                                    char *err, size_t errlen);
/* [T] §7.3, its eqs 7.6-7.7 lost in the text and read as the cubic
 * B-spline (normals_variants.c): chi_v = sum_p S3(x_p - x_v) on the
 * vertices (16 a point in 2D, 64 in 3D; a ring of ghost vertices past the
 * grid's edge), n_p = -grad sum_v chi_v S3(x - x_v) at x_p, normalised. */
lm_nerr lm_normals_cubic_colour(const lm_ngrid *g, size_t n, const double *const x[3],
                                double *const nrm[3], unsigned char *flags,
                                char *err, size_t errlen);
/* [T] §7.4 solved globally: one least-squares system over all the nodes of
 * the occupied cells (linear basis), rows phi = 1 at every point and
 * phi = 0 at one random point per occupied cell; dense QR, minimum norm.
 * Cost O(m N^2) for m rows and N nodes: meant for comparisons. The
 * per-cell mass matrix method is lm_normals_grid with LM_NB_LINEAR and
 * LM_NS_NORMAL ([T] §7.4, 7.7: a 4 x 4 system per cell, 2 x 2 cells for a
 * lone point). cond_t (optional) receives cond(T). */
lm_nerr lm_normals_mass_matrix_global(const lm_ngrid *g, size_t n,
                                      const double *const x[3],
                                      const lm_nopts *o, double *const nrm[3],
                                      unsigned char *flags, double *cond_t,
                                      char *err, size_t errlen);

#endif
