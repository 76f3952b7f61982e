/* mpm3_membrane.h - membranes in the 3D engine (issue 34 item 2,
 * docs/3d.md "3D membranes").
 *
 * A membrane is a surface sampled into points, each carrying its area, two
 * unit tangents t1, t2 spanning its tangent plane and its membrane strain
 * and stress in that plane (three components each, in the frame t1, t2).
 * The points live in their own arrays beside the solid particles
 * (lm3_sim.mem) and share the grid with them: they add mass, momentum and
 * force to the nodes in the p2g pass and take their velocity back in the
 * g2p pass (the hooks below, called by sim3_step.c). The law is the 2D
 * engine's registry (membrane_law.h): lm_membrane_stress_biaxial at the
 * principal strains, the same functions a 2D axisymmetric ring calls, so
 * plane stress, the one-way wrinkle rule and slack mean the same thing.
 *
 * Surfaces are sampled by lm3_sample_* into an lm3_msample, which
 * lm3_membrane_add copies into the simulation. */
#ifndef LAMINA_MPM3_MEMBRANE_H
#define LAMINA_MPM3_MEMBRANE_H

#include <stddef.h>
#include <stdint.h>

#include "mpm.h"

struct lm3_sim;

/* A sampled surface: n points with area A (summing to the surface's area)
 * and a right-handed tangent frame (t1 x t2 is the normal the surface
 * gives: out of a closed surface, u x v on a parallelogram). */
typedef struct lm3_msample {
    size_t n;
    double *x[3], *A, *t1[3], *t2[3];
    int closed;            /* a closed surface (sphere, closed mesh) */
} lm3_msample;

void lm3_msample_free(lm3_msample *s);

/* The sphere |x - c| = r: the Fibonacci lattice of N = round(4 pi r^2 /
 * spacing^2) points (at least 12), point k at height z_k = 1 - (2k + 1)/N
 * (times r), azimuth k times the golden angle. By Archimedes' hat-box
 * theorem the bands between heights 1 - 2k/N and 1 - 2(k + 1)/N have equal
 * areas 4 pi r^2 / N, and point k sits at its band's middle height, so each
 * point's area is exactly that (they sum to 4 pi r^2 to rounding). t1 is
 * the azimuthal direction e_phi, t2 = n x t1 (n radial, outward). 0, or -1
 * with err (bad numbers, too many points: more than LM_MAX_PARTICLES). */
int lm3_sample_sphere(const double c[3], double r, double spacing, lm3_msample *s, char *err,
                      size_t errlen);
/* The parallelogram origin + a u + b v, (a, b) in [0, 1]^2: a grid of nu x
 * nv points, nu = ceil(|u| / spacing), nv = ceil(|v_perp| / spacing) with
 * v_perp the part of v across u, at the centres of the nu x nv equal
 * sub-parallelograms, each of area |u x v| / (nu nv) (exact). Point (i, j)
 * is index j nu + i. t1 = u / |u|, t2 = v_perp / |v_perp|. */
int lm3_sample_rect3(const double origin[3], const double u[3], const double v[3],
                     double spacing, lm3_msample *s, char *err, size_t errlen);
/* A triangle mesh: nv vertices xyz[3 nv], nt triangles tri[3 nt] (vertex
 * indices from 0, counter-clockwise seen from the side the normal points
 * to). A point at every vertex used, its area a third of the areas of the
 * triangles around it (the barycentric share of its fan: they sum to the
 * mesh's area exactly), its normal the area-weighted normal of the fan,
 * t1 the first fan edge projected on the tangent plane. A closed mesh
 * (every edge in exactly two triangles) whose signed volume is negative is
 * turned inside out, so its normals point out. Degenerate triangles (zero
 * area) and unused vertices are refused naming them. */
int lm3_sample_mesh(const double *xyz, size_t nv, const int32_t *tri, size_t nt,
                    lm3_msample *s, char *err, size_t errlen);

/* How a membrane's normals are found each step. */
typedef enum lm3_mnormals {
    LM3_MN_CONNECTIVITY = 0,   /* t1 x t2 of the convected frame */
    LM3_MN_LINEAR = 1,         /* [N] Fig 5: the 8 x 8 trilinear system per cell */
    LM3_MN_QUADRATIC = 2       /* [N] Fig 11: the 27 x 27 triquadratic system */
} lm3_mnormals;

typedef struct lm3_mdef {
    lm_material mat;        /* kind LM_MEMBRANE: rho, E, nu, thickness, law, one_way */
    double initial_strain;  /* isotropic in-plane strain at creation (log): the
                               points stand for A exp(-2 e0) of unstrained sheet */
    double pressure;        /* p A n on every point (n out of a closed surface) */
    double damping;         /* c: a force -c m v on every point (1/s; 0: none) */
    double v[3];            /* initial velocity */
    lm3_mnormals normals;
} lm3_mdef;

void lm3_mdef_default(lm3_mdef *d);

/* One membrane: its points first .. first + count - 1 of the arrays. */
typedef struct lm3_membrane {
    lm3_mdef def;
    size_t first, count;
    int closed;
    size_t undefined;       /* construction normals left undefined in the
                               last step (the frame's normal kept there) */
} lm3_membrane;

/* A set of points held at rest. A pin holds every node its points reach
 * (N_ip > 0), as a fixed wall holds its nodes: the points then cannot
 * move and neither can the grid at them. The reaction is the force the
 * held nodes would have had, -sum f_i there (internal, gravity, pressure,
 * damping), so that the free points' momentum changes by exactly
 * dt (external forces + reactions) (test_sim3_membrane.c checks it). A
 * node reached by two pins counts for the first. */
typedef struct lm3_mpin {
    size_t n;
    size_t *idx;            /* points (indices into the membrane arrays) */
    double reaction[3];     /* of the last step, N */
} lm3_mpin;

/* All the membrane points of a simulation (structure of arrays). e and s
 * are the in-plane strain and stress in the frame (t1, t2): components
 * 11, 22, 12 (tensor shear). A0 is the unstrained area; the current area
 * is A0 exp(e11 + e22), and a point's volume thickness * that, as in 2D
 * (membrane_law.h: the stress is the tension per current length over the
 * unstrained thickness). */
typedef struct lm3_mpoints {
    size_t n, cap;
    double *x[3], *v[3], *m, *A0;
    double *t1[3], *t2[3], *nrm[3];
    double *e[3], *s[3];
    double *d[3];           /* place in the stencil (sim3_shape.c) */
    int32_t *node;
    uint8_t *pin;           /* 1: held */
    uint16_t *mem;          /* which membrane */
} lm3_mpoints;

#define LM3_MAX_MEMBRANES 65535

typedef struct lm3_membranes {
    lm3_mpoints p;
    lm3_membrane *mem;
    int nmem;
    lm3_mpin *pins;
    int npins;
    int32_t *held;          /* per node: the pin (1-based) holding it, 0 free */
    double damped;          /* work the damping loads took out so far, J (lm3_membrane_g2p) */
} lm3_membranes;

/* A membrane from a sampled surface: its index, or -1 with sim->err
 * (bad material, spacing above a cell, a point outside the domain). The
 * samples' spacing is checked by the caller's sampler; here every point
 * must lie in the domain. */
int lm3_membrane_add(struct lm3_sim *sim, const lm3_mdef *def, const lm3_msample *s);
/* Holds points idx[0..n) (indices within membrane k) at rest: the pin's
 * index or -1 with sim->err. */
int lm3_membrane_pin(struct lm3_sim *sim, int k, const size_t *idx, size_t n);
void lm3_membranes_free(lm3_membranes *m);

/* The membrane's tension, thickness times the mean of the point's
 * principal stresses, (s11 + s22) t / 2, at point q (N/m). */
double lm3_membrane_tension(const struct lm3_sim *sim, size_t q);
/* The fastest membrane wave, sqrt(E / ((1 - nu^2) rho)) for plane stress
 * (the registry's wave_speed): 0 without membranes. */
double lm3_membrane_wave_speed(const struct lm3_sim *sim);
/* Kinetic, stored (the registry's biaxial energy at the principal
 * strains) and gravity's potential energy of the membrane points, added. */
void lm3_membrane_energy(const struct lm3_sim *sim, double *kinetic, double *strain,
                         double *potential);
void lm3_membrane_momentum(const struct lm3_sim *sim, double P[3]);
double lm3_membrane_mass(const struct lm3_sim *sim);
/* The energy the membranes' damping loads (-c m v) have taken out since
 * the simulation was made, J: 0 without membranes or damping; total +
 * damped is what the step conserves (docs/3d.md "A gas inside a 3D
 * membrane"). */
double lm3_membrane_damped(const struct lm3_sim *sim);

/* A gas inside a closed membrane, measured (sim3_membrane_gas.c; docs/3d.md
 * "A gas inside a 3D membrane"). The volume membrane k's points enclose:
 * (1/3) sum A (x - c) . n over them (the divergence theorem; current areas,
 * normals out), meaningful for a closed surface. */
double lm3_membrane_volume(const struct lm3_sim *sim, int k);
typedef struct lm3_escaped {
    size_t beyond;     /* particles outside by more than `quarter` */
    size_t grazing;    /* outside by at most `quarter` */
    double deepest;    /* the largest distance outside (0 when none is) */
} lm3_escaped;
/* The particles first .. first + n - 1 outside closed membrane k (the 2D
 * membrane:escaped's three numbers): 0, or -1 when out of memory. */
int lm3_membrane_escaped(const struct lm3_sim *sim, int k, size_t first, size_t n,
                         double quarter, lm3_escaped *out);

/* ---- the step's hooks (sim3_step.c calls them; sim3_membrane_step.c) ---- */

/* Place, then m, m v, the internal force -A t sum s_ab (t_a x t_b) . G_ip,
 * the pressure p A n and the damping -c m v onto the nodes (before the
 * ghosts are folded). */
void lm3_membrane_p2g(struct lm3_sim *sim);
/* After the grid update: the pins' nodes held at rest, their reactions. */
void lm3_membrane_hold(struct lm3_sim *sim);
/* After the particles' g2p and MUSL re-map: the points' own (their
 * velocity; their position too under USL, under MUSL in the update). */
void lm3_membrane_g2p(struct lm3_sim *sim);
/* After the strain velocity: held nodes at rest again, then each point's
 * position under MUSL (the re-mapped velocity), L projected on its tangent
 * plane, strain, tangents, law, normals. A
 * status other than LM_OK with sim->err naming the point. */
lm_status lm3_membrane_update(struct lm3_sim *sim);

/* The construction's normals ([N] eqs 10-11, 16) of membrane k's points
 * from their positions alone, on the simulation's grid, basis LM3_MN_LINEAR
 * or LM3_MN_QUADRATIC, each turned to agree with the frame's t1 x t2 (the
 * orientation rule of the 2D issue: out of a closed surface). nrm[3][count]
 * receives them; *undefined (optional) counts points left with the frame's
 * normal. 0, or -1 with sim->err. */
int lm3_membrane_construction_normals(struct lm3_sim *sim, int k, lm3_mnormals basis,
                                      double *const nrm[3], size_t *undefined);

/* ---- the membranes in a run's state (sim3_membrane_state.c; framed by
 * sim3_state.c for checkpoints and --restart) ---- */
size_t lm3_mstate_bytes(uint64_t np, uint32_t nmem, uint32_t npins);
void lm3_mstate_counts(const struct lm3_sim *sim, uint64_t *np, uint32_t *nmem,
                       uint32_t *npins);
/* Writes lm3_mstate_bytes(counts) bytes at b; returns b past them. */
unsigned char *lm3_mstate_save(const struct lm3_sim *sim, unsigned char *b);
/* Checks the part at b (of those counts) against the script's membranes
 * and replaces their values, or changes nothing: LM_ERR_INPUT with
 * sim->err. */
lm_status lm3_mstate_load(struct lm3_sim *sim, const unsigned char *b, uint64_t np,
                          uint32_t nmem, uint32_t npins);

struct lm_nreport;
/* The same, with the elements' fits (optional rep: mpm_normals.h's
 * report, centred elements, freed with lm_nreport_free) and the message
 * in err instead of sim->err, so that a frame can ask for it of a const
 * simulation. */
int lm3_membrane_construction(const struct lm3_sim *sim, int k, lm3_mnormals basis,
                              double *const nrm[3], size_t *undefined,
                              struct lm_nreport *rep, char *err, size_t errlen);

/* phi of membrane k's construction (basis LM3_MN_LINEAR or
 * LM3_MN_QUADRATIC), for its phi = 1 isosurface (sim3_membrane_phi.c):
 * the very fits that give lm3_membrane_construction's normals, each
 * element's phi sampled over the half-cell cube about its lattice site
 * (the cubes tile space; each element answers for the points nearest its
 * site) at (samples + 1)^3 nodes h / (2 samples) apart, cube c's node
 * (i, j, k) at f[c m^3 + (k m + j) m + i], m = samples + 1, position
 * lo[3 c ..] + (i, j, k) d. Contoured cube by cube the surface is
 * piecewise, as phi is ([N] eq 10 per element). Arrays malloc'd
 * (lm3_phicubes_free). */
typedef struct lm3_phicubes {
    size_t n;               /* cubes: the elements fitted */
    int samples;
    double d;               /* node spacing */
    double *lo;             /* 3 n: each cube's first node */
    double *f;              /* n (samples + 1)^3 */
} lm3_phicubes;

int lm3_membrane_phi(const struct lm3_sim *sim, int k, lm3_mnormals basis, int samples,
                     lm3_phicubes *out, char *err, size_t errlen);
void lm3_phicubes_free(lm3_phicubes *c);

#endif
