/* mpm3.h - the 3D engine's public face (docs/3d.md).
 *
 * A 3D simulation is its own struct, lm3_sim, beside the 2D lm_sim rather
 * than a dimension-generic lm_sim: the 2D step keeps its 2 x 2 / 3 x 3
 * kernels, field table and state hashes bit for bit and pays nothing for
 * a third component, and the 3D one is written for its own layout (27-node
 * stencils whose weights are rebuilt from three 1D factors instead of
 * stored: docs/3d.md "Memory"). What the two share - the enums of mpm.h,
 * the 1D factors of the bases (shape_1d.h), the materials' constants - is
 * shared, not copied.
 *
 * This first step holds the core: the grid with walls per face, the linear
 * (trilinear) and quadratic B-spline bases, MUSL and USL, gravity, the
 * isotropic elastic solid (Jaumann rate), energies and momenta. Gas,
 * membranes, pins, threads and the Lua API follow (docs/3d.md "Order of
 * work"). */
#ifndef LAMINA_MPM3_H
#define LAMINA_MPM3_H

#include <stddef.h>
#include <stdint.h>

#include "mpm.h"

/* The six faces of the box, in the order of lamina.sim{boundary} in 3D. */
enum { LM3_XLO = 0, LM3_XHI, LM3_YLO, LM3_YHI, LM3_ZLO, LM3_ZHI, LM3_FACES };

#define LM3_MAX_MATERIALS 16
/* A bound on the grid a definition may ask for (nodes with the ghost
 * ring): 2^28 nodes of 10 doubles are 20 GB, more than any machine this
 * runs on; the engine refuses instead of failing to allocate. */
#define LM3_MAX_NODES ((size_t)1 << 28)

typedef struct lm3_def {
    double lo[3], hi[3];   /* the domain, a whole number of cells each way */
    double cell;           /* h: the grid is cubic */
    double dt;
    lm_basis basis;        /* LM_BASIS_LINEAR (trilinear) or LM_BASIS_BSPLINE2 */
    lm_scheme scheme;      /* LM_MUSL (default) or LM_USL */
    double gravity[3];
    lm_bc bc[LM3_FACES];   /* per face, LM3_XLO ... LM3_ZHI */
    double courant;        /* the largest dt c / h accepted (times the factors
                              below); 0 means the 2D default, 1 */
} lm3_def;

/* The 3D limit relative to the 1D one that `courant` is stated for
 * (docs/decisions.md "Shape functions"). One might expect 1/sqrt(3) (the
 * fastest mode along the cube's diagonal); measured, it is not needed: the
 * largest stable dt c / h of a block filling a fixed box, random
 * velocities, 600 steps (`test_sim3 courant_scan`, docs/3d.md) is under
 * MUSL linear 2.05 / 1.80 at 1 / 8 points per cell, bspline2 2.05 / 2.40,
 * under USL 0.75 / 0.75 and 0.75 / 1.30 - the 1D bar's numbers (linear
 * 1.97 / 1.72, bspline2 1.99 / 2.30, USL 0.75). So 1, as in 2D; USL's
 * factor is the 2D one, LM_USL_COURANT. */
#define LM3_COURANT_FACTOR 1.0

/* The isotropic linear elastic solid ([F] eqs 18-20 in their 3D form). */
typedef struct lm3_material {
    double rho, E, nu;
} lm3_material;

/* The grid: (n[0]+1) x (n[1]+1) x (n[2]+1) nodes plus a ghost ring of
 * `pad` nodes for the quadratic B-spline (sim3_walls.c), x fastest. */
typedef struct lm3_grid {
    double lo[3], h;
    int n[3];              /* cells per direction */
    int pad;               /* 0 (trilinear) or 1 (quadratic B-spline) */
    int W;                 /* stencil width per direction: 2 or 3 */
    long s[3];             /* node counts per direction with the ring */
    size_t nn;             /* all nodes */
    lm_bc bc[LM3_FACES];
    /* mass, momentum (then the Lagrangian velocity), force (then the
     * acceleration), the velocity the strain rate reads */
    double *m, *p[3], *f[3], *v[3];
} lm3_grid;

/* Structure of arrays. Stress in Voigt order xx, yy, zz, yz, xz, xy (the
 * global Cauchy stress). A particle's place at x^k (the start of the
 * step) is its stencil's first node and its offset there per direction:
 * the 27 (or 8) weights are rebuilt from it in each pass. */
typedef struct lm3_particles {
    size_t n, cap;
    double *x[3], *v[3], *m, *rho, *s[6];
    double *d[3];          /* offset in the stencil (sim3_shape.c) */
    int32_t *node;         /* the stencil's first node */
    uint8_t *mat;
} lm3_particles;

typedef struct lm3_sim {
    lm3_def def;
    lm3_grid grid;
    lm3_particles p;
    lm3_material mats[LM3_MAX_MATERIALS];
    int nmat;
    long nstep;
    double t;
    struct lm3_membranes *mem;   /* membrane points (mpm3_membrane.h); NULL: none */
    char err[256];         /* why the last call failed */
} lm3_sim;

typedef struct lm3_energy {
    double kinetic, strain, potential, total;
} lm3_energy;

/* A new simulation, or NULL with the reason in err (naming the key and
 * the value). */
lm3_sim *lm3_sim_create(const lm3_def *def, char *err, size_t errlen);
void lm3_sim_free(lm3_sim *sim);
/* The material's index, or -1 (bad values or too many: err says which). */
int lm3_material_add(lm3_sim *sim, const lm3_material *mat, char *err, size_t errlen);
/* One particle of volume V at x with velocity v. */
lm_status lm3_particle_add(lm3_sim *sim, int mat, const double x[3], const double v[3],
                           double V);
/* The box [lo, hi] filled with k x k x k particles a cell (at the centres
 * of the sub-cells that lie in the box and the domain, the papers'
 * counting), velocity v: the count added (0 when none), or -1 when k is
 * not in 1..8 or memory ran out. */
long lm3_seed_box(lm3_sim *sim, int mat, const double lo[3], const double hi[3], int k,
                  const double v[3]);
/* One step (docs/3d.md "The step"); LM_ERR_DOMAIN when a particle left the
 * grid, LM_ERR_UNSTABLE at NaN or a cell compressed to nothing, and before
 * the first step LM_ERR_INPUT when dt is above the Courant limit; sim->err
 * names the time, the step, the particle and the numbers. */
lm_status lm3_step(lm3_sim *sim);
/* dt c_max / h, c_max the fastest material's dilatational wave speed
 * sqrt((lambda + 2 G) / rho) (docs/physics.md §5 in 3D); and the largest
 * value the run accepts: courant x LM3_COURANT_FACTOR (x LM_USL_COURANT
 * under USL). */
double lm3_courant(const lm3_sim *sim, double *c_max);
double lm3_courant_limit(const lm3_sim *sim);

void lm3_energy_of(const lm3_sim *sim, lm3_energy *e);
void lm3_momentum(const lm3_sim *sim, double P[3]);
double lm3_mass(const lm3_sim *sim);

/* ---- the pieces, for tests and the later Lua layer ---- */

/* A stencil's weights: the first node and, per direction, W factors and
 * their derivatives (times 1/h). N at node (a, b, c) of the stencil is
 * w[0][a] w[1][b] w[2][c]. */
typedef struct lm3_weights {
    long node;
    double w[3][3], g[3][3];
} lm3_weights;
/* The stencil of a point at x (stores the place in node, d) */
void lm3_place(const lm3_grid *g, const double x[3], int32_t *node, double d[3]);
/* ... and the weights at a place */
void lm3_weights_at(const lm3_grid *g, int32_t node, const double d[3], lm3_weights *w);
/* The node (i, j, k) of the grid, -pad <= i <= n[0] + pad */
static inline long lm3_node(const lm3_grid *g, int i, int j, int k)
{
    return ((long)(k + g->pad) * g->s[1] + (j + g->pad)) * g->s[0] + (i + g->pad);
}
/* The elastic update: sigma <- sigma + dt (W sigma - sigma W) + C : de for
 * the strain increment de (Voigt, tensor shears) and the spin W (3x3, row
 * major); and the strain energy density 1/2 sigma : C^-1 : sigma. */
void lm3_elastic_update(const lm3_material *mat, const double de[6], const double W[9],
                        double dt, double s[6]);
double lm3_elastic_energy_density(const lm3_material *mat, const double s[6]);

#endif
