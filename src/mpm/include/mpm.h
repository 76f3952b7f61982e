/* mpm.h - lamina's engine: the material point method in 2D.
 *
 * One lm_sim owns the background grid, the particles (structure of arrays),
 * the bodies and pointers to the materials. The step follows docs/physics.md §1
 * one phase per function (step.c), so the paper can be read beside it.
 *
 * No Lua, no drawing, no file I/O here. Errors are values: functions return
 * LM_OK or an lm_status and leave a one-line message in sim->err naming the
 * time, step, particle and body and the likely cause.
 *
 * Fields of the structs below are readable by the bindings and the renderer;
 * only the engine writes them. */
#ifndef LAMINA_MPM_H
#define LAMINA_MPM_H

#include <stddef.h>
#include <stdint.h>

typedef enum lm_status {
    LM_OK = 0,
    LM_ERR_INPUT,      /* a bad value given to the engine */
    LM_ERR_UNSTABLE,   /* NaN/inf, or a cell compressed to nothing */
    LM_ERR_DOMAIN,     /* a particle left the grid */
    LM_ERR_MEMORY,
    LM_ERR_COURANT     /* dt past the Courant limit (courant_check.c): refused */
} lm_status;

typedef enum lm_scheme { LM_MUSL = 0, LM_USL = 1 } lm_scheme;
/* The grid's mass: lumped (row sums, [F] eq 7), or lumped with one Neumann
 * step towards the consistent mass (mass_corrected.c), of every point's
 * share or of the membranes' points' only (LM_MASS_MEMBRANE: the rest
 * lumped). */
typedef enum lm_mass { LM_MASS_LUMPED = 0, LM_MASS_CORRECTED = 1, LM_MASS_MEMBRANE = 2 } lm_mass;

/* Shape functions of the step (lamina.sim{basis}; docs/decisions.md
 * "Shape functions"): the bilinear hats of the papers (shape.c, a 2 x 2
 * stencil), uGIMP (Bardenhagen & Kober 2004, shape_gimp.c) and the
 * node-centred quadratic B-spline (Steffen, Kirby & Berzins 2008,
 * shape_bspline.c), both on a 3 x 3 stencil. */
typedef enum lm_basis { LM_BASIS_LINEAR = 0, LM_BASIS_GIMP = 1, LM_BASIS_BSPLINE2 = 2 } lm_basis;

/* Per-side boundary condition on the grid's outer nodes. */
typedef enum lm_bc { LM_BC_FIXED = 0, LM_BC_SYMMETRY = 1, LM_BC_FREE = 2 } lm_bc;
enum { LM_LEFT = 0, LM_RIGHT = 1, LM_BOTTOM = 2, LM_TOP = 3 };

/* ---- materials (material.c, material_elastic.c) ---------------------- */

typedef enum lm_kind {
    LM_ELASTIC = 1,
    LM_MEMBRANE = 2,
    LM_GAS = 3,            /* compressible viscous gas, [F] §3.3 */
    LM_LINEAR_FLUID = 4    /* p = -beta div U, the piston problem, [F] eq 26 */
} lm_kind;
typedef enum lm_plane { LM_PLANE_STRAIN = 0, LM_PLANE_STRESS = 1 } lm_plane;
/* Membrane laws, one file each (membrane_law_*.c, the contract in
 * membrane_law.h): a string/wire carries only the tangential stress ([T]
 * eq 5.9); a plane-stress membrane also sigma_z = nu sigma_t ([T] eq
 * 5.15); the incompressible neo-Hookean membrane, W = mu/2 (l1^2 + l2^2 +
 * 1/(l1 l2)^2 - 3) with mu = E/3, for large stretch. */
typedef enum lm_law {
    LM_LAW_UNIAXIAL = 0, LM_LAW_PLANE_STRESS = 1, LM_LAW_NEO_HOOKEAN = 2,
    LM_LAW_COUNT
} lm_law;
/* The registry (membrane_law.c): a law's name in Lua ("uniaxial",
 * "plane_stress", "neo_hookean"; NULL past the last). */
const char *lm_law_name(int law);

/* How a gas point's density is found ([T] §4): the continuity equation
 * (eq 4.7, the papers' runs), the gas mass of its cell (eq 4.5), or that
 * cell density interpolated quadratically over the 3 x 3 cells around it
 * (eq 4.6); density.c. */
typedef enum lm_density {
    LM_DENSITY_CONTINUITY = 0, LM_DENSITY_CELL = 1, LM_DENSITY_QUADRATIC = 2
} lm_density;

typedef struct lm_material {
    lm_kind kind;
    double rho;            /* reference density */
    double E, nu;          /* elastic solid and membrane */
    lm_plane plane;        /* elastic solid */
    double thickness;      /* membrane: mass per length is rho * thickness */
    lm_law law;            /* membrane */
    int one_way;           /* membrane: no stress in compression ([M] §3.2) */
    double gamma, mu;      /* gas: ratio of specific heats, shear viscosity */
    double e0;             /* gas: initial specific internal energy */
    int av;                /* gas: Wilkins artificial viscosity on ([F] eq 24) */
    double av_c1, av_c2, av_lambda, av_g;   /* its constants; g <= 0: sqrt(2) h */
    double beta;           /* linear fluid: bulk modulus */
    double split;          /* gas: a point standing for more than 1/split
                              of a cell becomes four (split.c); 0: never */
    lm_density density;    /* gas: how rho_p is found (density.c) */
} lm_material;

/* Fastest wave speed of the material (docs/physics.md §5), for the Courant check. */
double lm_material_wave_speed(const lm_material *mat);
/* Checks the parameters; 0 if fine, else writes why into err. */
int lm_material_validate(const lm_material *mat, char *err, size_t errlen);

/* Most threads a step can use (lamina.sim{threads}; threads.h). */
#define LM_MAX_THREADS 256

/* Most particles of a simulation, however they come (seeding, gas
 * splitting): fifty times the largest size the engine benchmark runs,
 * 10^6 (docs/design.md, "Performance targets"). */
#define LM_MAX_PARTICLES 50000000

/* ---- grid (grid.c) ----------------------------------------------------- */

typedef struct lm_grid {
    double x0, y0;         /* lower-left node */
    double hx, hy;         /* cell size */
    int nx, ny;            /* cells; nodes (0..nx) x (0..ny) */
    /* The 3 x 3 bases reach one node past each side: the nodal arrays then
     * carry a ring of pad = 1 ghost nodes (grid_walls.c), node (i, j) at
     * (j + pad) * sx + (i + pad) for i in -pad..nx+pad. The linear basis
     * has pad = 0 and sx = nx + 1: the papers' layout, row-major in x. */
    int pad, sx;
    int sw;                /* stencil width of the basis: 2 or 3 nodes */
    lm_bc bc[4];           /* LM_LEFT, LM_RIGHT, LM_BOTTOM, LM_TOP */
    double *m;             /* lumped nodal mass */
    double *px, *py;       /* momentum p_i, then p_i^L */
    double *fx, *fy;       /* total nodal force */
    double *vx, *vy;       /* velocity used for the strain (step 5); in
                              step 4 first v_i^L = p_i^L / m_i */
    double *ax, *ay;       /* step 4: acceleration f_i / m_i */
    double *tbuf;          /* other threads' copies of scattered fields */
    size_t tcap;           /* (threads.c), and the band of nodes each */
    long tlo[LM_MAX_THREADS], thi[LM_MAX_THREADS];   /* thread's copy covers */
    long blo[LM_MAX_THREADS], bhi[LM_MAX_THREADS];   /* and its particles touch */
} lm_grid;

/* Node (i, j) of the grid's arrays, -pad <= i <= nx + pad. */
static inline long lm_grid_node(const lm_grid *g, int i, int j)
{
    return (long)(j + g->pad) * g->sx + (i + g->pad);
}
/* Nodes of the arrays, ghosts included. */
size_t lm_grid_nodes(const lm_grid *g);

/* ---- particles (particles.c) -------------------------------------------- */

typedef struct lm_particles {
    size_t n, cap;
    double *x, *y;         /* position */
    double *vx, *vy;       /* velocity */
    double *m;             /* mass (constant) */
    double *rho;           /* density; volume = m / rho */
    double *sxx, *syy, *sxy, *szz;  /* Cauchy stress, global axes */
    /* Membrane points only (zero elsewhere): tangential strain eps_t, the
     * length of membrane Delta s a point stands for, and the unit tangent
     * of the step (the normal is the tangent turned +90 degrees). */
    double *et, *ds, *tx, *ty;
    /* Gas: specific internal energy e and the artificial viscosity q of the
     * step (pressure p = (gamma - 1) rho e is reported without q). Linear
     * fluid: ev, the accumulated volumetric strain div U. */
    double *e, *q, *ev;
    int *body;             /* owning body index */
    int *mat;              /* material index into sim->mats */
    /* uGIMP: the half-sizes of the particle's square domain, from its
     * seeding (h / (2 sqrt(ppc)) per direction; h / 4 for membrane points
     * and particles added without a ppc; docs/decisions.md). */
    double *lx, *ly;
    /* Shape functions of the step, evaluated once at x^k ([F] eqs 13-14):
     * the stencil's lower-left node, then ns = sw * sw weights and gradients
     * row by row, x fastest: for the linear basis (ns = 4) the order
     * (i,j) (i+1,j) (i,j+1) (i+1,j+1). Node k of particle q is
     * lm_stencil_node(grid, sw, node[q], k) (step.h). */
    int ns;
    int *node;
    /* uGIMP only (keep_weights = 1, set by lm_sim_new: its weights depend
     * on the particle's size as well); NULL otherwise */
    int keep_weights;
    double *N, *Gx, *Gy;
    /* The bilinear basis keeps the point's place in its cell instead, xi
     * and eta in [0, 1]: its weights and gradients are a few products of
     * them (lm_bilinear_N, lm_bilinear_G in step.h), cheaper to redo than
     * to store and read back (issue 17 item 1: 96 bytes a particle written
     * and read by four passes). The quadratic B-spline likewise keeps the
     * offsets from the nearest node in cells, |xi|, |eta| <= 1/2
     * (lm_bspline2_N, lm_bspline2_G_r; issue 36 item 2: 216 bytes). */
    double *xi, *eta;
    /* Membranes with segment forces (membrane_force.c): L0 is the
     * unstrained length of the segment from this point to the next in
     * curve order (0: none), and (fpx, fpy) the net tension of the point's
     * segments, spread to the nodes with N_ip in step 2; spent then, they
     * keep the point's x^k until MUSL's step 5 moves it (membrane_force.c). */
    double *L0, *fpx, *fpy;
    /* Pins (pin.c): 1 + the index of the pin holding the particle, else 0. */
    int *pin;
    /* Axisymmetric membranes (axisym.c): the point's unstrained ring radius
     * r0 (0 for a point on the axis); its hoop strain is ln(r / r0). */
    double *r0;
} lm_particles;

/* How a membrane finds its normals (docs/physics.md §3). */
typedef enum lm_normals {
    LM_NORMALS_CONNECTIVITY = 0, /* neighbours in curve order ([F] §3.2) */
    LM_NORMALS_ISOSURFACE,       /* phi = 1 on centred elements (normals_centred.c) */
    LM_NORMALS_HYBRID,           /* [N] §8: quadratic / linear / merged by count */
    LM_NORMALS_LINEAR,           /* per-cell linear fit ([N] §4) */
    LM_NORMALS_COLOUR,           /* [T] §7.1 simple colour function */
    LM_NORMALS_QUADRATIC_COLOUR, /* [T] §7.2 */
    LM_NORMALS_MASS_MATRIX,      /* [T] §7.4 per cell (linear, normal equations) */
    LM_NORMALS_MASS_MATRIX_QUADRATIC, /* [T] §7.7: quadratic per cell, a lone
                                       * point's 2 x 2 block linear (Fig 87) */
    LM_NORMALS_CUBIC_COLOUR           /* [T] §7.3, read as the cubic B-spline */
} lm_normals;

/* How a membrane's tangential stress reaches the grid. "point" is the
 * papers' quadrature, f_i = -V_p sigma_p . G_ip at each point ([M] eq 9);
 * "segment" integrates the tension along the straight segments between
 * neighbouring points, f_i = -F t [N_i(b) - N_i(a)] (docs/physics.md §5b),
 * which is continuous as points cross cell edges and exactly zero at the
 * interior nodes of a uniformly stretched membrane (membrane_force.c). */
typedef enum lm_mforce { LM_MFORCE_POINT = 0, LM_MFORCE_SEGMENT = 1 } lm_mforce;

/* Which way a membrane's normals point (the stress does not depend on it:
 * sigma_t t(x)t and t.de.t are even in t; drawing does). LM_ORIENT_CENTROID
 * is for definitions only, the default: it becomes LM_ORIENT_CURVE. */
typedef enum lm_orient {
    LM_ORIENT_CENTROID = -1,
    LM_ORIENT_NONE = 0,       /* as the method finds them (unoriented) */
    LM_ORIENT_AWAY = 1,       /* away from (ox, oy) */
    LM_ORIENT_NEIGHBOURS = 2, /* agree with their neighbours, and in time */
    /* by the curve, for every normals method (membrane.c): a closed
     * membrane's point out of the region it encloses, by the sign of its
     * signed area, every step; an open one's to the side `side` of the
     * curve's direction (+1 left, -1 right), fixed at creation */
    LM_ORIENT_CURVE = 3
} lm_orient;

#define LM_NAME_MAX 64

typedef struct lm_body {
    int mat;               /* index into sim->mats */
    size_t first, count;   /* particles [first, first+count) */
    int membrane;          /* points in curve order, tangents from neighbours */
    int closed;            /* membrane: the last point neighbours the first */
    lm_normals normals;
    int orient;            /* normals' sign: lm_orient */
    double ox, oy;
    int side;              /* LM_ORIENT_CURVE, open: +1 left, -1 right */
    double pe_ref;         /* this body's share of sim->pe_ref */
    lm_mforce force;       /* membrane: how its stress reaches the grid */
    int colour_with;       /* membrane, colour-function normals: 1 + the body
                              whose points carry the colour too ([T] §7.5,
                              Fig 66(b)); 0: the membrane's points alone */
    int seg_ready;         /* segment rest lengths set (membrane_force.c) */
    double end_grid_mass;  /* > 0: the last point is a heavy end point whose
                              mass beyond this wire share rides off the lumped
                              grid, tied to it by constraint.c */
    char name[LM_NAME_MAX];/* for messages; "" = unnamed */
} lm_body;

/* A pin holds a set of particles to a prescribed velocity (pin.c): the
 * grid's velocity interpolated at each held particle is the pin's
 * (constraint.c; with sim:contact every node a held particle touches
 * moves with it); the force the pin needed is its reaction. */
typedef struct lm_pin {
    int body;
    size_t n;
    size_t *idx;           /* the particles held, by index within the body
                              (bodies move in memory when gas splits) */
    double *x0;            /* their x, y at the step's start (2 n) */
    int point;             /* this step: held by the point constraint (1)
                              or by its nodes (0: pin.c) */
    double vx, vy;         /* the prescribed velocity of this step */
    double rx, ry;         /* reaction of the last step: the force the pin
                              exerted on the material (per unit depth) */
    double sx, sy;         /* multi-rate stepping: its sub-steps' sum */
} lm_pin;

/* A force-displacement link between two material points (link.c): [F]
 * §4.4's suggestion for the airbag's tether. */
#define LM_MAX_LINKS 4096
typedef struct lm_link {
    int body[2];
    size_t idx[2];         /* its two points, by index within their bodies */
    double k, L0;          /* tension k (l - L0): stiffness, rest length */
    int cable;             /* 1: no compression (T = 0 for l < L0) */
    int active;            /* 0: removed (no force, no energy) */
} lm_link;

/* ---- the simulation (sim.c) ---------------------------------------------- */

/* Which stress forms the internal force ([T] §5.4.3): each point's own,
 * f_i = -sum_p V_p sigma_p . grad N_i(x_p) (the papers' quadrature), or
 * the volume-weighted mean stress of each cell with the gradient at the
 * cell centre (stress_cell.c), the dissertation's "somewhat successful"
 * remedy for the noise of points crossing cell edges. */
typedef enum lm_stress { LM_STRESS_POINTS = 0, LM_STRESS_CELL = 1 } lm_stress;

/* Multi-rate stepping's forms (lamina.sim{multirate}, subcycle.c and
 * docs/performance.md "Multi-rate stepping"): HELD, the slow group's force
 * spread evenly over the sub-steps, its nodal momentum carried lumped (the
 * default); IMPULSE, the slow force's whole step's impulse in the first
 * sub-step (r-RESPA's kick), the slow group's momentum carried as its
 * consistent re-map; HALF, half the impulse at each end; the _LUMPED forms
 * carry it lumped; HELD_CONSISTENT, HELD's force with IMPULSE's carry;
 * SPLIT, the last step's slow force held and this step's change of it
 * kicked, with IMPULSE's carry; HYBRID, IMPULSE's kick on the nodes the
 * membranes do not touch at the step's start, HELD's force on those they
 * do, with IMPULSE's carry. */
typedef enum {
    LM_MULTIRATE_HELD = 0,
    LM_MULTIRATE_IMPULSE,
    LM_MULTIRATE_IMPULSE_LUMPED,
    LM_MULTIRATE_HALF,
    LM_MULTIRATE_HALF_LUMPED,
    LM_MULTIRATE_HELD_CONSISTENT,
    LM_MULTIRATE_SPLIT,
    LM_MULTIRATE_HYBRID
} lm_multirate;

typedef struct lm_sim_def {
    double x0, y0, x1, y1; /* domain */
    double hx, hy;         /* cell size (the domain is rounded up to whole cells) */
    double dt;
    lm_scheme scheme;
    double gx, gy;         /* gravity */
    lm_bc bc[4];
    double courant;        /* largest allowed dt*c_max/h */
    double pic;            /* 0: FLIP velocity update (the papers'); 1: PIC;
                              between: a blend that damps particle noise */
    uint64_t seed;         /* random points of the normals construction */
    int threads;           /* threads of the step (<= 1: one); the state is
                              bit-identical for the same count (threads.h) */
    lm_basis basis;        /* shape functions (default linear) */
    lm_stress stress;      /* internal force from point or cell stresses */
    lm_mass mass;          /* lumped (default) or corrected (mass_corrected.c) */
    int apic;              /* 1: the affine transfer for bulk bodies (apic.c) */
    int axisym;            /* the axisymmetric form (axisym.c): x is r, y is
                              z, the left side is the axis r = 0; masses,
                              volumes, forces and energies per radian */
    double damping;        /* c >= 0 (1/s): viscous damping of the grid
                              velocities, force -c m_i v_i (damping.c);
                              0: none, the undamped step to the bit */
    int normals_compare;   /* a measurement (docs/performance.md): every
                              Cholesky fit of the centred normals solved
                              again by the QR and the two compared
                              (lm_sim_normals_compare); the run is the same */
    int substeps;          /* multi-rate stepping (subcycle.c): 0 off; k > 0:
                              each step the membranes take k sub-steps of
                              dt / k; LM_SUBSTEPS_AUTO: k from the membranes'
                              Courant limit, step by step */
    lm_multirate multirate;   /* with substeps: how the slow group's force
                              enters the sub-steps and what its nodal
                              momentum carries (subcycle.c) */
    double visc_limit;     /* kappa >= 0: a gas point's shear viscosity at
                              most kappa rho_p h^2 / dt, the explicit
                              step's diffusion limit at its density
                              (material_gas.c, lm_gas_mu); 0: off, the
                              material's mu everywhere */
    int fast_band;         /* with substeps: 1, the gas points within
                              fast_band_w cells of the membranes' stencils
                              take the sub-steps too (subcycle_gasband.c);
                              0 (default): the membranes alone */
    int fast_band_w;
} lm_sim_def;

#define LM_SUBSTEPS_AUTO (-1)
/* Most sub-steps a step may take (a typo's 10^9 would hang the run). */
#define LM_SUBSTEPS_MAX 100000

/* Fills a definition with lamina's defaults (unit square, cell 0.1, MUSL,
 * no gravity, fixed walls, courant 1). */
void lm_sim_def_default(lm_sim_def *def);

typedef struct lm_sim {
    lm_sim_def def;
    lm_grid grid;
    lm_particles p;
    lm_material **mats;    /* the sim's own copies (lm_sim_add_material) */
    int nmats, capmats;
    lm_body *bodies;
    int nbodies, capbodies;
    double t;
    long step;
    double t_base;         /* t = t_base + (step - step_base) dt: exact */
    long step_base;        /* multiples of dt, and dt can change mid-run */
    double pe_ref;         /* sum m g.x at seeding: potential energy datum */
    double damped;         /* the work the grid damping took out so far
                              (damping.c); not in the checkpoint */
    int prepared;          /* membrane stresses built from eps_t */
    lm_pin *pins;          /* pin.c */
    int npins;
    lm_link *links;        /* link.c */
    int nlinks;
    struct lm_contact *contact;   /* pairs in contact (contact.h); NULL: none */
    struct lm_work *work;         /* the step's scratch: work arrays, the
                                     threads' timing (private to the engine,
                                     src/mpm/sim_work.h) */
    char err[1024];        /* the Courant refusal names the limit's factors */
} lm_sim;

lm_sim *lm_sim_new(const lm_sim_def *def, char *err, size_t errlen);
void lm_sim_free(lm_sim *sim);

/* Registers a copy of mat, which the sim owns (checked by
 * lm_material_validate); returns its index, or -1 with sim->err. Each call
 * adds one: a caller that gives two bodies one material keeps its index. */
int lm_sim_add_material(lm_sim *sim, const lm_material *mat);
/* Replaces material k's parameters between steps (a live change: mat.E =
 * 2000 from a callback), checked as lm_sim_add_material; its kind and rho
 * cannot change (the particles' masses were seeded from rho). LM_ERR_INPUT
 * with sim->err and the material unchanged otherwise. */
lm_status lm_sim_set_material(lm_sim *sim, int k, const lm_material *mat);
/* Starts a body of material index `mat`; returns its index or -1. */
int lm_sim_add_body(lm_sim *sim, int mat);
/* Appends one particle to the last body (bodies are contiguous). */
lm_status lm_sim_add_particle(lm_sim *sim, int body, double x, double y,
                              double vx, double vy, double mass, double rho);
/* Sets particle q's uGIMP half-sizes (clamped to (0, h/2]: the domain then
 * never reaches past the 3 x 3 stencil). */
void lm_sim_set_particle_size(lm_sim *sim, size_t q, double lx, double ly);
/* The basis' name ("linear", "gimp", "bspline2"). */
const char *lm_basis_name(lm_basis b);
/* Largest stable dt c / h of the basis relative to the linear one's
 * (measured on a 1D bar, docs/decisions.md "Shape functions"). */
double lm_basis_courant_factor(lm_basis b);

/* Starts a membrane body: its points, added in curve order, keep that
 * order, so connectivity normals (docs/physics.md §3) can use neighbours. */
int lm_sim_add_membrane(lm_sim *sim, int mat, int closed);
/* Sets a membrane point's reference length ds and initial tangential
 * strain; mass stays as given (the heavy end point has its own). */
lm_status lm_sim_set_membrane_point(lm_sim *sim, size_t q, double ds, double et);

/* Takes the newest body out again with its particles (a body whose
 * creation failed part-way: creating one is all or nothing). */
lm_status lm_sim_drop_last_body(lm_sim *sim);
/* Axisymmetric form (axisym.c): the radius a membrane point of length l
 * at radius r stands for as a ring (r, or l / 4 for a point on the axis). */
double lm_axisym_ring_radius(double r, double l);

/* A membrane as one layer of points along a curve ([M] §3), everything
 * the engine needs to create it (as Box2D's b2BodyDef): start from
 * lm_membrane_def_default and set what differs. The arrays are read during
 * lm_sim_create_membrane only. */
typedef struct lm_membrane_def {
    int mat;                  /* from lm_sim_add_material: a membrane material */
    int closed;               /* the last point neighbours the first */
    size_t n;                 /* points, in curve order */
    const double *x, *y;      /* their positions */
    double ds;                /* the spacing along the curve, as placed */
    const double *strain;     /* initial logarithmic strain per point (NULL: 0) */
    const double *vx, *vy;    /* initial velocity per point (NULL: 0) */
    double end_mass;          /* > 0: the last point's mass ([M] §4.1's heavy point) */
    lm_normals normals;
    lm_orient orient;
    double ox, oy;            /* LM_ORIENT_AWAY: from this point */
    lm_mforce force;
    int colour_with;          /* colour-function normals only: 1 + the index of a
                                 (non-membrane) body whose points carry the
                                 colour too, [T] §7.5's "material points interior
                                 to the membrane" (Fig 66(b)); 0: none */
    const char *name;         /* for messages; NULL or "" = unnamed */
} lm_membrane_def;

void lm_membrane_def_default(lm_membrane_def *def);
/* Creates the membrane of def, all or nothing (membrane_create.c checks
 * the membrane rules first: spacing within a cell, points inside the
 * domain and off the axis, strains within (-5, 5)); returns the body's
 * index, or -1 with sim->err set (naming the membrane) and the
 * simulation as it was. */
int lm_sim_create_membrane(lm_sim *sim, const lm_membrane_def *def);

/* Names body b for messages (truncated to LM_NAME_MAX - 1 bytes). */
void lm_sim_set_body_name(lm_sim *sim, int b, const char *name);
/* Chooses how membrane body b's stress reaches the grid (before the first
 * step); LM_ERR_INPUT for a body that is not a membrane. */
lm_status lm_sim_set_membrane_force(lm_sim *sim, int b, lm_mforce force);
/* Chooses how membrane body b finds its normals (lm_membrane_def.normals,
 * for membranes built point by point); LM_ERR_INPUT for a body that is not
 * a membrane or a method that is not one of lm_normals. */
lm_status lm_sim_set_membrane_normals(lm_sim *sim, int b, lm_normals normals);
/* "membrane 'skin'" or "body 3": how messages name body b. */
const char *lm_body_label(const lm_sim *sim, int b, char *buf, size_t len);

/* Holds particles idx[0..n) of body b (indices within the body) at
 * velocity (vx, vy) from the next step on; returns the pin's index, or -1
 * with sim->err set. A particle can be held by one pin only. */
int lm_sim_add_pin(lm_sim *sim, int b, const size_t *idx, size_t n, double vx, double vy);
/* Changes a pin's velocity between steps. */
void lm_sim_set_pin_velocity(lm_sim *sim, int pin, double vx, double vy);

/* Links point ia of body ba to point ib of body bb (indices within the
 * bodies) with tension k (l - L0), none in compression if cable; returns
 * the link's index, or -1 with sim->err set (link.c). */
int lm_sim_add_link(lm_sim *sim, int ba, size_t ia, int bb, size_t ib, double k, double L0,
                    int cable);
/* Removes (on = 0) or restores a link between steps. */
void lm_sim_set_link_active(lm_sim *sim, int k, int on);
double lm_link_length(const lm_sim *sim, int k);
double lm_link_tension(const lm_sim *sim, int k);   /* 0 when removed */
/* Points of segment membrane b slack by more than 1 %; *taut: stretched
 * ones (membrane_force.c; bunched points, docs/robustness.md). */
size_t lm_membrane_segment_slack(const lm_sim *sim, int b, size_t *taut);

/* The phi of membrane body b's normals construction ([N] §3) at its
 * present points, element by element, into rep (mpm_normals.h; free with
 * lm_nreport_free): for "isosurface", "hybrid", "linear" and
 * "mass_matrix" the fit the last step made (same points, same random
 * points: the same fit); for connectivity membranes the isosurface
 * construction on the present points. 0, or -1 with err (the colour
 * methods have no phi). */
struct lm_nreport;
int lm_membrane_phi(const lm_sim *sim, int b, struct lm_nreport *rep, char *err,
                    size_t errlen);

/* Builds what depends on whole bodies (membrane tangents and stresses from
 * their strains); called by the first step, and by anyone who needs the
 * tangents before it. The sim is marked prepared only when it succeeds. */
lm_status lm_sim_prepare(lm_sim *sim);

/* Neighbouring membrane points may be at most a cell apart (docs/physics.md
 * §2); a spacing up to this fraction over a cell is rounding (a count
 * that puts points 1.0003 cells apart) and is accepted: the tear check
 * stops a run only at two cells (issue 30 item 4, docs/robustness.md
 * "Point spacing"). */
#define LM_SPACING_SLACK 0.01

/* Courant number dt * c_max / min(hx, hy) over the materials in use. */
double lm_sim_courant(const lm_sim *sim, double *c_max);
/* The same, and the body whose speed is c_max (-1: none). */
double lm_sim_courant_body(const lm_sim *sim, double *c_max, int *body);
/* Largest stable dt c / h of a membrane with segment forces, measured on
 * a pinned sheet under gravity with 2 to 8 points per cell (it grows
 * between 0.75 and 0.8; 0.85 with one point per cell). */
#define LM_SEGMENT_COURANT 0.75
/* USL divides each node's momentum by its own mass ([T] §8.1), so it is
 * less stable than MUSL: [T] Ch. 8's bar with one point per cell at the
 * centres first grows at dt c / h = 0.75 (MUSL: 2.15; docs/robustness.md
 * "The 1-D bar"). The check scales `courant` by this for USL. */
#define LM_USL_COURANT 0.7
/* mass = "corrected" (mass_corrected.c) raises the highest grid mode's
 * frequency (1-D estimate for the B-spline's grid step alone: sqrt(2 -
 * M_C(pi)) = sqrt(1.867); the step-5 correction adds to it). Measured on
 * the 1-D bar (scripts/measure/courant_basis.lua --set mass=corrected,
 * docs/robustness.md "Corrected mass"): the largest stable dt c / h over
 * 1, 4, 9 points per cell is linear 1.27 / 1.09 / 1.06, uGIMP 1.26 /
 * 1.10 / 1.07, bspline2 1.26 / 1.54 / 1.46, against the lumped linear
 * basis' 1.97 / 1.72 / 1.66 that `courant` is stated for: the smallest
 * ratio, 0.634. */
#define LM_CORRECTED_COURANT 0.63
/* The largest Courant number the run accepts: `courant` (stated for the
 * linear basis and MUSL) times the basis' factor, and LM_USL_COURANT for
 * USL. */
double lm_sim_courant_limit(const lm_sim *sim);
/* The Courant refusal (courant_check.c): LM_OK, or LM_ERR_COURANT with
 * sim->err "dt = ... is too large: Courant number dt*c/h = ... exceeds
 * courant = ... (c_max = ... from <body>, h = ...); use dt <= ... or raise
 * courant". lm_sim_step makes it before its first step and again after
 * anything that moves the number (dt, courant, a material's wave speed, a
 * body, a membrane's force form, a restored state), and refuses to step;
 * sim:run makes it at every start. */
lm_status lm_sim_check_courant(lm_sim *sim);
/* Changes dt between steps if the new one passes the Courant check; else
 * LM_ERR_COURANT with sim->err and dt as it was (sim.dt = ...). */
lm_status lm_sim_try_dt(lm_sim *sim, double dt);

/* Multi-rate stepping (lamina.sim{substeps}, subcycle.c): the sub-steps
 * the membranes take in a step of the present dt (1 when off or when there
 * is no membrane). */
int lm_subcycle_count(const lm_sim *sim);
/* With fast_band: the gas points in the sub-steps' fast group in the last
 * step (subcycle_gasband.c); 0 when off or before the first step. */
long lm_subcycle_fast_gas(const lm_sim *sim);

/* Changes the time step between steps (the clock keeps counting exactly). */
void lm_sim_set_dt(lm_sim *sim, double dt);
/* The settings a script may change between steps, checked here: gravity
 * (two finite numbers), the PIC fraction (in [0, 1]), the Courant limit
 * (positive). LM_ERR_INPUT with sim->err ("pic must lie in [0, 1] (got
 * 2)") and the setting unchanged otherwise. */
lm_status lm_sim_set_gravity(lm_sim *sim, double gx, double gy);
lm_status lm_sim_set_pic(lm_sim *sim, double pic);
lm_status lm_sim_set_courant(lm_sim *sim, double courant);
/* The grid damping c (1/s, finite, >= 0; damping.c). */
lm_status lm_sim_set_damping(lm_sim *sim, double c);
/* The grid's mass (lm_mass) between steps; LM_ERR_MEMORY when the
 * momenta a non-lumped mass keeps cannot be made (mass_corrected.c). */
lm_status lm_sim_set_mass(lm_sim *sim, lm_mass mass);

/* One step of docs/physics.md §1. On failure sim->err says why. */
lm_status lm_sim_step(lm_sim *sim);
/* The same step with a promise: more != 0 says the caller's next call on
 * this sim is lm_sim_step or lm_sim_step_then, with nothing changing the
 * particles, bodies, materials or grid in between. A plain run may then
 * make the next step's grid sums in this step's pass over the particles
 * (step_fused.c); the states are the same to the bit either way. A caller
 * that breaks the promise calls lm_sim_forget_ahead first. */
lm_status lm_sim_step_then(lm_sim *sim, int more);
void lm_sim_forget_ahead(lm_sim *sim);

/* ---- checkpoints (checkpoint.c) ------------------------------------------
 * The state that continues a run bit for bit, as bytes (the binding writes
 * and reads the file). Loading checks the simulation the script built
 * against the checkpoint's (materials, bodies, pins, grid, basis) and
 * refuses, with sim->err saying why, one that does not fit. */
#define LM_CHECKPOINT_VERSION 3   /* 2: r0 (axisymmetric membranes); 3: links */
size_t lm_sim_state_bytes(const lm_sim *sim);
void lm_sim_state_save(const lm_sim *sim, unsigned char *buf);
lm_status lm_sim_state_load(lm_sim *sim, const unsigned char *buf, size_t len);
/* The state's size a checkpoint's header (its first bytes) claims, computed
 * without overflow; 0 when it is no header of this format or its counts are
 * out of range: a reader checks it against the file before reading it. */
size_t lm_sim_state_claimed(const unsigned char *buf, size_t len);

/* ---- seeding (seed.c, region.c) ----------------------------------------- */

typedef enum lm_region_kind { LM_REGION_DISK, LM_REGION_RECT, LM_REGION_POLYGON } lm_region_kind;

typedef struct lm_region {
    lm_region_kind kind;
    double cx, cy, r;          /* disk */
    double x0, y0, x1, y1;     /* rect; for every kind, the bounding box */
    int nv;                    /* polygon vertices */
    double *vx, *vy;
} lm_region;

int lm_region_contains(const lm_region *r, double x, double y);

/* Trial points of seeding: npx*npy per cell on a regular pattern (the cell
 * split into npx*npy sub-cells, a point at each centre; normals paper §2).
 * Cells [i0,i1) x [j0,j1) are visited row by row; point k of that range: */
typedef struct lm_seed_range { int i0, i1, j0, j1, npx, npy; } lm_seed_range;
/* The cell range covering the box (clipped to the grid). */
lm_seed_range lm_seed_range_for(const lm_grid *g, int npx, int npy,
                                double x0, double y0, double x1, double y1);
size_t lm_seed_count(const lm_seed_range *r);
void lm_seed_point(const lm_grid *g, const lm_seed_range *r, size_t k,
                   double *x, double *y);
/* Mass of one seeded particle of density rho (per unit depth). */
double lm_seed_mass(const lm_grid *g, int npx, int npy, double rho);
/* fill = "clipped": the part of the sub-cell centred at (x, y) that lies
 * inside the region, as an area fraction in [0, 1] and its centroid
 * (cx, cy); inside(ctx, x, y) is the region test. */
typedef int (*lm_inside_fn)(void *ctx, double x, double y);
double lm_seed_clip(const lm_grid *g, int npx, int npy, double x, double y,
                    lm_inside_fn inside, void *ctx, double *cx, double *cy);

/* ---- bodies of one material (body_create.c) ---------------------------- */

/* A body of one material filled with particles (sim:body): the trial
 * points of the seeding pattern (npx x npy per cell, lm_seed_range) that
 * lie in the region each become a particle of mass rho times its share of
 * the cell, the papers' rule (fill = "centres"), or with clipped the part
 * of each sub-cell inside the region at that part's centroid (seed.c).
 * Everything the engine needs to create it, as lm_membrane_def: start from
 * lm_body_def_default and set what differs. The callbacks are called
 * during lm_sim_create_body only; one that fails returns -1 (its own error
 * kept by the caller) and the creation stops, leaving nothing behind. */
typedef int (*lm_velocity_fn)(void *ctx, double x, double y, double *vx, double *vy);
/* Trial points of one body at most: 2e8 (the particles of a simulation are
 * at most LM_MAX_PARTICLES, checked as they are added). */
#define LM_MAX_TRIALS 200000000
/* Trial points per cell at most (ppc = 64 x 64). */
#define LM_MAX_PPC 4096
typedef struct lm_body_def {
    int mat;                  /* from lm_sim_add_material: not a membrane */
    const lm_region *region;  /* the shape, or NULL: inside(ctx, x, y) */
    lm_inside_fn inside;      /* 1 inside, 0 outside, -1 failed */
    int npx, npy;             /* trial points per cell (default 2 x 2) */
    int clipped;              /* fill = "clipped" (seed.c) */
    double vx, vy;            /* the velocity of every particle ... */
    lm_velocity_fn velocity;  /* ... unless given per point: 0, or -1 failed */
    void *ctx;                /* for inside and velocity */
    const char *name;         /* for messages; NULL or "" = unnamed */
} lm_body_def;

void lm_body_def_default(lm_body_def *def);
/* Creates the body of def, all or nothing (body_create.c checks the
 * material, the pattern's limits, the velocity and that the region holds
 * particles); returns the body's index, or -1 with sim->err set and the
 * simulation as it was. */
int lm_sim_create_body(lm_sim *sim, const lm_body_def *def);

/* ---- diagnostics (diag.c) ------------------------------------------------ */

typedef struct lm_energy {
    double kinetic, strain, internal, potential, total;
} lm_energy;

lm_energy lm_sim_energy(const lm_sim *sim);
/* Kinetic energy of the particles' momentum mapped to the grid (at most the
 * particles' own; the rest is velocity the grid cannot see). */
double lm_sim_grid_kinetic(const lm_sim *sim);
lm_energy lm_body_energy(const lm_sim *sim, int body);
/* Mass-weighted centre and velocity of a body (body < 0: all particles). */
void lm_body_com(const lm_sim *sim, int body, double *x, double *y);
void lm_body_velocity(const lm_sim *sim, int body, double *vx, double *vy);
double lm_body_mass(const lm_sim *sim, int body);
/* Linear momentum of all particles. */
void lm_sim_momentum(const lm_sim *sim, double *px, double *py);
/* Mean gas pressure (gamma - 1) rho e, without q, over a gas body's
 * particles, mass-weighted (gas:pressure("particles")). */
double lm_body_mean_pressure(const lm_sim *sim, int body);
/* The pressure integral over a gas body, sum_p V_p p_p = (gamma - 1)
 * sum_p m_p e_p (without q): the quadrature the internal forces use. */
double lm_body_pressure_integral(const lm_sim *sim, int body);
/* Area of the membrane's polygon (closed through (cx, cy) if open). */
double lm_membrane_enclosed_area(const lm_sim *sim, int body, double cx, double cy);
/* The space it encloses: its area, or when axisymmetric its volume per
 * radian (int r dA over the polygon). */
double lm_membrane_enclosed_volume(const lm_sim *sim, int body, double cx, double cy);
/* Mean tangential (hoop) stress sigma_t over a membrane. */
double lm_body_mean_tangential_stress(const lm_sim *sim, int body);
/* Distance from (cx, cy) to the membrane along the ray at `deg` degrees;
 * -1 if the ray misses it. */
double lm_membrane_radius_at(const lm_sim *sim, int body, double deg, double cx, double cy);
/* A gas's particles against a membrane's polygon (closed through (cx, cy)
 * if open; diag_gas.c): on the near side, and on the far side (outside
 * when inside = 0, inside when 1) within `beyond` of the polygon or beyond
 * it, with the deepest distance on the far side (length units). */
typedef struct lm_far {
    size_t near, within, beyond;
    double depth;
} lm_far;
int lm_gas_far_side(const lm_sim *sim, int gas, int membrane, double cx, double cy,
                    int inside, double beyond, lm_far *out);
/* The gas's pressure over the space it fills: the mean of the nodal
 * pressure (gamma - 1) sum_p m_p e_p N_ip / V_i over the nodes whose
 * support lies wholly in it (diag_gas.c); *nodes how many (0: none, and the
 * volume-weighted particle mean is returned). */
double lm_gas_space_pressure(const lm_sim *sim, int body, size_t *nodes);
/* The gas pressure interpolated to the grid nodes (mass-weighted; NaN
 * where no gas is): (nx+1)(ny+1) values, x fastest. */
size_t lm_grid_gas_pressure(const lm_sim *sim, double *out);
/* A run whose total energy grows (energy_watch.c): nothing in lamina's
 * models makes energy, so a rise of the energy the grid sees by a tenth
 * of the most the run held, over 100 steps or more, with no pin driving a
 * body and gravity unchanged, is the numerics feeding the motion. begin
 * at the run's start, step before each step (after the pins' velocities
 * are set), end after the last: 1 with the warning's text in msg (no
 * "warning:" before it, no newline), else 0. */
typedef struct lm_energy_watch {
    double seen0;               /* the energy at the start, as the grid sees it */
    double scale;               /* the most energy in play so far */
    double floor;               /* rounding: M c_max^2 x 1e-12 */
    double t0;
    long step0;
    double gx, gy;              /* gravity at the start: a change does work */
    int driven;                 /* a pin drove a body, or gravity changed */
} lm_energy_watch;
void lm_energy_watch_begin(const lm_sim *sim, lm_energy_watch *w);
void lm_energy_watch_step(const lm_sim *sim, lm_energy_watch *w);
int lm_energy_watch_end(const lm_sim *sim, const lm_energy_watch *w, char *msg, size_t len);
/* FNV-1a hash of the particle state: equal hashes, equal states. */
uint64_t lm_sim_hash(const lm_sim *sim);
/* def.normals_compare's measurement so far: the normals compared, the
 * largest and the mean angle between the Cholesky and the QR fit's
 * (degrees), the Cholesky fits that fell back to the QR. 0, or -1 when it
 * was not asked for or no normals were computed. */
int lm_sim_normals_compare(const lm_sim *sim, unsigned long *n, double *max_deg,
                           double *mean_deg, unsigned long *fallbacks);

#endif
