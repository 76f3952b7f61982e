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
 * It holds the core: the grid with walls per face, the linear (trilinear)
 * and quadratic B-spline bases, MUSL and USL, gravity, the isotropic
 * elastic solid (Jaumann rate), the viscous gamma-law gas with the
 * paper's artificial viscosity, energies and momenta. Membranes, pins and
 * the Lua API follow (docs/3d.md "Order of work"). */
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
    int threads;           /* threads a step uses (sim3_threads.c); 0 or 1: one.
                              The same count gives the same bits */
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

/* What a 3D material is. The elastic solid is 0 so that a material
 * written {rho, E, nu} (the first core's callers) stays one. */
typedef enum lm3_kind { LM3_ELASTIC = 0, LM3_GAS = 1 } lm3_kind;

/* The isotropic linear elastic solid ([F] eqs 18-20 in their 3D form), or
 * the viscous gamma-law gas ([F] §3.3 eqs 21-25; sim3_gas.c) with the 2D
 * gas's constants (mpm.h lm_material): p = (gamma - 1) rho e, shear
 * viscosity mu, initial specific internal energy e0, and when av is set
 * the paper's artificial viscosity (c1, c2, lambda, g; g <= 0 means
 * sqrt(2) h as in 2D, the paper's g = sqrt(2) dx). */
typedef struct lm3_material {
    double rho, E, nu;     /* rho: reference density; E, nu: elastic only */
    lm3_kind kind;
    double gamma, mu, e0;  /* gas */
    int av;
    double av_c1, av_c2, av_lambda, av_g;
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
    double *e;             /* gas: specific internal energy ([F] eq 23); 0 otherwise */
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
    struct lm3_pins *pins; /* body:pin in 3D (sim3_pin.c); NULL: none */
    double *scratch;       /* the threads' private copies of nodal fields */
    size_t scratch_len;    /* (sim3_threads.c), in doubles */
    int recheck;           /* look at every particle before the next step: set
                              after a failed step, and by a caller that moves
                              particles between steps (lm3_step otherwise
                              looks only at the positions its g2p makes) */
} lm3_sim;

/* strain: the elastic solids' 1/2 sigma : C^-1 : sigma V; internal: the
 * gases' sum m e (their stored energy, [F] eq 23). */
typedef struct lm3_energy {
    double kinetic, strain, potential, total, internal;
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
 * sqrt((lambda + 2 G) / rho) (docs/physics.md §5 in 3D), a gas's sound
 * speed sqrt(gamma (gamma - 1) e0); and the largest
 * value the run accepts: courant x LM3_COURANT_FACTOR (x LM_USL_COURANT
 * under USL). */
double lm3_courant(const lm3_sim *sim, double *c_max);
double lm3_courant_limit(const lm3_sim *sim);

void lm3_energy_of(const lm3_sim *sim, lm3_energy *e);
/* The bytes the simulation holds (issue 34 item 6, docs/3d.md "Memory"):
 * its particle arrays at their capacity into *particles (at the count
 * into *exact when not NULL), its grid's nodal fields and the threads'
 * copies of them into *grid; the sum is returned. */
size_t lm3_memory(const lm3_sim *sim, size_t *particles, size_t *exact, size_t *grid);
/* The trilinear scatters' kernels (sim3_simd.c): LM3_SIMD_AVX512 (eight
 * lanes, a particle's whole stencil) when lamina was built with them and
 * the processor has AVX-512F, else LM3_SIMD_SSE2 (two lanes); the same
 * bits either way (docs/3d.md "Speed"). lm3_simd_limit(LM3_SIMD_SSE2)
 * holds the whole process to two lanes (the test of the same bits,
 * `lamina bench --dim 3 --simd sse2`); call it between steps. */
enum { LM3_SIMD_SSE2 = 0, LM3_SIMD_AVX512 = 1 };
int lm3_simd_level(void);
void lm3_simd_limit(int level);
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
/* The gas (sim3_gas.c): c = sqrt(gamma (gamma - 1) e); the artificial
 * viscosity q of a point of density rho and velocity divergence div given
 * the step's maxima over the gas (material_gas.c's lm_gas_av, shared);
 * and the update from the velocity gradient L (row major, L_ab =
 * dv_a/dx_b): sigma = 2 mu D - 2/3 mu tr(D) I - (p + q) I with D = sym L,
 * p = (gamma - 1) rho e^k, then e += sigma : (dt D) / rho. */
double lm3_gas_sound_speed(const lm3_material *mat, double e);
double lm3_gas_av(const lm3_material *mat, double rho, double div, double max_div,
                  double c_max, double h);
void lm3_gas_update(const lm3_material *mat, const double L[9], double dt, double rho,
                    double q, double *e, double s[6]);


/* ---- regions, seeding and sums for the Lua layer (sim3_region.c,
 * sim3_query.c; docs/3d.md "Lua API") ---- */

/* A solid region: a ball (c, r), an axis-aligned box [lo, hi], or a
 * cylinder of radius r about the segment a -> b (flat ends). lo, hi is
 * the bounding box for every kind. */
typedef enum lm3_region_kind { LM3_BALL, LM3_BOX, LM3_CYLINDER } lm3_region_kind;
typedef struct lm3_region {
    lm3_region_kind kind;
    double c[3], r;        /* ball: centre and radius; cylinder: radius */
    double a[3], b[3];     /* cylinder: the axis' ends */
    double lo[3], hi[3];   /* the bounding box */
} lm3_region;
int lm3_region_contains(const lm3_region *r, const double x[3]);

/* Seeding a region by a predicate: the sub-cell centres of an nx x ny x nz
 * pattern per cell (the papers' counting, as lm3_seed_box) that lie in
 * [lo, hi], in the domain and where inside(ctx, x) is nonzero. */
typedef struct lm3_seed_def {
    int mat;
    int k[3];              /* points per cell per direction, 1..LM3_MAX_PPC_DIR */
    double lo[3], hi[3];   /* the region's bounding box */
    /* 1 in, 0 out, -1 stops (an error the caller keeps) */
    int (*inside)(void *ctx, const double x[3]);
    /* the velocity at x, or NULL for v0; 0 or -1 to stop */
    int (*velocity)(void *ctx, const double x[3], double v[3]);
    double v0[3];
    void *ctx;
} lm3_seed_def;
#define LM3_MAX_PPC_DIR 8
/* How many points the definition gives (inside() is called for each
 * candidate): >= 0, or -1 when inside() stopped or k is out of range. */
long lm3_seed_count(const lm3_sim *sim, const lm3_seed_def *d);
/* Adds them: the count added, or -1 (inside/velocity stopped, memory: the
 * particles added so far are taken out again, so a failed body leaves
 * nothing). */
long lm3_seed(lm3_sim *sim, const lm3_seed_def *d);

/* Sums over the particles [first, first + n): mass, centre of mass and
 * the mass-weighted mean velocity; the energies of the range as
 * lm3_energy_of. */
void lm3_range_sums(const lm3_sim *sim, size_t first, size_t n, double *mass, double com[3],
                    double vel[3]);
void lm3_range_energy(const lm3_sim *sim, size_t first, size_t n, lm3_energy *e);
/* FNV-1a over the particles' state and the step count: equal hashes,
 * equal bits (determinism tests). */
uint64_t lm3_sim_hash(const lm3_sim *sim);
/* Bytes the grid and `cap` particles' arrays take (the process budget,
 * docs/security.md "Memory"). */
size_t lm3_grid_bytes(const lm3_sim *sim);
/* ... and those a definition's grid will take, before it is made (0 when
 * lm3_sim_create will refuse it) */
size_t lm3_def_grid_bytes(const lm3_def *d);
size_t lm3_particle_bytes(size_t cap);


/* A run's state as bytes (sim3_state.c): checkpoints and --restart. bytes
 * the size, save writes that many; claimed is the size a buffer's own
 * header gives (0 when it is not a 3D state); load replaces the clock,
 * live settings, materials and particles of a sim the script built with
 * the same particle count (LM_ERR_INPUT and err otherwise). */
#define LM3_STATE_VERSION 3   /* 3: the membranes (sim3_membrane_state.c) */
size_t lm3_state_bytes(const lm3_sim *sim);
void lm3_state_save(const lm3_sim *sim, unsigned char *buf);
size_t lm3_state_claimed(const unsigned char *buf, size_t len);
lm_status lm3_state_load(lm3_sim *sim, const unsigned char *buf, size_t len);


/* Pins (sim3_pin.c; docs/api.md "Three dimensions"): a pin holds the grid
 * nodes its particles' stencils touch (N > 0) at its velocity, as a wall
 * holds its nodes: the Lagrangian velocity there is the pin's (weighted by
 * N where pins share a node), the acceleration 0, the strain velocity the
 * pin's; its particles take its velocity before each step. The walls act
 * after the pins. lm3_pin_add: the pin's index, or -1 with err (a point
 * out of range or already held). */
typedef struct lm3_pin {
    size_t *idx, n;        /* the held particles */
    double v[3];           /* its velocity, set before each step */
    double reaction[3];    /* the force it exerted in the last step */
} lm3_pin;
typedef struct lm3_pins {
    lm3_pin *pin;
    int n;
    double *w, *wv[3];     /* per node: sum of N over held points, and of N v */
    uint8_t *held;         /* per particle: held by a pin */
} lm3_pins;
int lm3_pin_add(lm3_sim *sim, const size_t *idx, size_t n, const double v[3]);
void lm3_pins_free(lm3_sim *sim);
/* before a step: the held particles take their pins' velocities */
void lm3_pins_begin(lm3_sim *sim);
/* in the step (sim3_step.c): after the grid update, and after the strain
 * velocity */
void lm3_pins_grid(lm3_sim *sim);
void lm3_pins_strain(lm3_sim *sim);


/* Live settings between steps (sim3_live.c): LM_ERR_INPUT and err when a
 * value is refused (not finite, rho changed, nu out of range, no such
 * material or pin). */
lm_status lm3_set_gravity(lm3_sim *sim, const double g[3]);
lm_status lm3_set_courant(lm3_sim *sim, double c);
lm_status lm3_material_set(lm3_sim *sim, int k, const lm3_material *m);
lm_status lm3_pin_set_velocity(lm3_sim *sim, int pin, const double v[3]);

#endif
