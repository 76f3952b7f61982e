/* step.h - the phases of one MPM step (docs/physics.md §1), exposed so that the
 * unit tests can check each one alone. lm_sim_step() calls them in order. */
#ifndef LAMINA_STEP_H
#define LAMINA_STEP_H

#include <math.h>

#include "mpm.h"
#include "shape_1d.h"  /* lm_bspline2_1d: the 1D factors, shared with 3D */
#include "sim_work.h"   /* the scratch behind lm_sim.work */

/* Bilinear basis at (x, y): lower-left node, weights and gradients in the
 * order (i,j) (i+1,j) (i,j+1) (i+1,j+1). The caller guarantees the point is
 * inside the grid. */
void lm_shape_bilinear(const lm_grid *g, double x, double y, int *node,
                       double N[4], double Gx[4], double Gy[4]);
/* The same split in two: the lower-left node and the place (xi, eta) in
 * the cell, then the weights and gradients from the place. Every bilinear
 * weight in lamina is made by these products, so a stored place and a
 * fresh evaluation give the same bits. */
void lm_cell_bilinear(const lm_grid *g, double x, double y, int *node, double *xi,
                      double *eta);
/* The same with rx = 1 / hx and ry = 1 / hy given (the same quotients, so
 * the same bits), for a loop over many points: inline, as the step's
 * passes call it once a particle. */
static inline void lm_cell_bilinear_r(const lm_grid *g, double rx, double ry, double x,
                                      double y, int *node, double *xi, double *eta)
{
    double fx = (x - g->x0) * rx, fy = (y - g->y0) * ry;
    /* truncation is floor for the non-negative values of points inside
     * the grid, and cheaper: floor() is a library call on baseline x86-64 */
    int i = fx >= 0 ? (int)fx : (int)floor(fx);
    int j = fy >= 0 ? (int)fy : (int)floor(fy);
    /* A point exactly on the far edge belongs to the last cell. */
    if (i >= g->nx) i = g->nx - 1;
    if (j >= g->ny) j = g->ny - 1;
    if (i < 0) i = 0;
    if (j < 0) j = 0;
    *xi = fx - i;
    *eta = fy - j;
    *node = j * (g->nx + 1) + i;
}
static inline void lm_bilinear_N(double xi, double eta, double N[4])
{
    N[0] = (1 - xi) * (1 - eta);
    N[1] = xi * (1 - eta);
    N[2] = (1 - xi) * eta;
    N[3] = xi * eta;
}
/* rx = 1 / hx, ry = 1 / hy, worked out by the caller once for many points
 * (the same quotient, so the same bits) */
static inline void lm_bilinear_G_r(double rx, double ry, double xi, double eta, double Gx[4],
                                   double Gy[4])
{
    Gx[0] = -(1 - eta) * rx;
    Gx[1] = (1 - eta) * rx;
    Gx[2] = -eta * rx;
    Gx[3] = eta * rx;
    Gy[0] = -(1 - xi) * ry;
    Gy[1] = -xi * ry;
    Gy[2] = (1 - xi) * ry;
    Gy[3] = xi * ry;
}
static inline void lm_bilinear_G(const lm_grid *g, double xi, double eta, double Gx[4],
                                 double Gy[4])
{
    lm_bilinear_G_r(1.0 / g->hx, 1.0 / g->hy, xi, eta, Gx, Gy);
}

/* The quadratic B-spline (shape_bspline.c) split the same way: a point d
 * cells from its nearest node (|d| <= 1/2) has the 1D weights of the nodes
 * c-1, c, c+1, beta at d + 1, d, d - 1, and their derivatives times r =
 * 1/h; the 2D weights are their products. Every B-spline weight in lamina
 * is made by these products, so the place (dx, dy) kept in the particle's
 * xi and eta and a fresh evaluation give the same bits (issue 36 item 2:
 * 216 bytes of stored weights a particle written and read back each step,
 * against 16). */
static inline void lm_bspline2_N(double dx, double dy, double N[9])
{
    double wx[3], wy[3], gx[3], gy[3];
    lm_bspline2_1d(dx, 1, wx, gx);
    lm_bspline2_1d(dy, 1, wy, gy);
    for (int b = 0; b < 3; b++)
        for (int a = 0; a < 3; a++) N[3 * b + a] = wx[a] * wy[b];
}
/* rx = 1 / hx, ry = 1 / hy, the caller's */
static inline void lm_bspline2_G_r(double rx, double ry, double dx, double dy, double Gx[9],
                                   double Gy[9])
{
    double wx[3], wy[3], gx[3], gy[3];
    lm_bspline2_1d(dx, rx, wx, gx);
    lm_bspline2_1d(dy, ry, wy, gy);
    for (int b = 0; b < 3; b++)
        for (int a = 0; a < 3; a++) {
            Gx[3 * b + a] = gx[a] * wy[b];
            Gy[3 * b + a] = wx[a] * gy[b];
        }
}

/* Particle q's weights (and gradients) at x^k as lm_step_shape left them:
 * pointers into uGIMP's arrays, or the bilinear or B-spline ones rebuilt
 * in the struct from the point's place. */
typedef struct lm_weights {
    const double *N, *Gx, *Gy;
    double n[9], gx[9], gy[9];
} lm_weights;
static inline void lm_weights_of(const lm_sim *sim, size_t q, lm_weights *w)
{
    const lm_particles *p = &sim->p;
    if (p->ns == 4) {
        lm_bilinear_N(p->xi[q], p->eta[q], w->n);
        lm_bilinear_G(&sim->grid, p->xi[q], p->eta[q], w->gx, w->gy);
        w->N = w->n;
        w->Gx = w->gx;
        w->Gy = w->gy;
    } else if (!p->N) {   /* the B-spline: no stored weights */
        lm_bspline2_N(p->xi[q], p->eta[q], w->n);
        lm_bspline2_G_r(1.0 / sim->grid.hx, 1.0 / sim->grid.hy, p->xi[q], p->eta[q], w->gx,
                        w->gy);
        w->N = w->n;
        w->Gx = w->gx;
        w->Gy = w->gy;
    } else {
        size_t o = (size_t)p->ns * q;
        w->N = p->N + o;
        w->Gx = p->Gx + o;
        w->Gy = p->Gy + o;
    }
}
/* The 3 x 3 bases at (x, y): the stencil's lower-left node (one left of
 * and one below the node nearest the point, on the padded grid), then 9
 * weights and gradients row by row, x fastest. uGIMP (shape_gimp.c) takes
 * the particle's half-sizes lx, ly <= h/2; the quadratic B-spline
 * (shape_bspline.c) none. The caller guarantees the point is inside. */
void lm_shape_gimp(const lm_grid *g, double x, double y, double lx, double ly, int *node,
                   double N[9], double Gx[9], double Gy[9]);
void lm_shape_bspline2(const lm_grid *g, double x, double y, int *node,
                       double N[9], double Gx[9], double Gy[9]);
/* Particle q's stencil at its present position by the sim's basis. */
void lm_shape_particle(const lm_sim *sim, size_t q, int *node, double *N, double *Gx,
                       double *Gy);

/* Node k (0 <= k < sw * sw, row by row) of the stencil whose lower-left
 * node is `node`, for a stencil sw nodes wide. */
static inline int lm_stencil_node(const lm_grid *g, int sw, int node, int k)
{
    return node + (k / sw) * g->sx + (k % sw);
}
/* The first node of row b of that stencil: node k = b sw + a is
 * lm_stencil_row(g, node, b) + a. */
static inline long lm_stencil_row(const lm_grid *g, int node, int b)
{
    return node + (long)b * g->sx;
}
/* The node nearest to a point f cells from the grid's origin along one
 * axis of n cells (clamped to 0..n), and the point's offset d from it in
 * cells, |d| <= 1/2: the centre of a 3 x 3 stencil. A point within 1e-9
 * of a cell of a wall is put on it, so that its two mirror weights are
 * equal to the last bit and a point on a fixed wall stays exactly put
 * (grid_walls.c). */
static inline int lm_shape_nearest(double f, int n, double *d)
{
    /* truncation is floor for the points inside, and cheaper (floor() is a
     * library call on baseline x86-64) */
    double u = f + 0.5;
    int c = u >= 0 ? (int)u : (int)floor(u);
    c = c < 0 ? 0 : c > n ? n : c;
    *d = f - c;
    if ((c == 0 || c == n) && fabs(*d) < 1e-9) *d = 0;
    return c;
}
/* The quadratic B-spline's place of a point (x, y): the stencil's
 * lower-left node and the offsets (dx, dy) from the nearest node, in cells
 * (rx = 1 / hx, ry = 1 / hy); lm_bspline2_N and lm_bspline2_G_r make the
 * weights from them. */
static inline void lm_bspline2_place(const lm_grid *g, double rx, double ry, double x,
                                     double y, int *node, double *dx, double *dy)
{
    int cx = lm_shape_nearest((x - g->x0) * rx, g->nx, dx);
    int cy = lm_shape_nearest((y - g->y0) * ry, g->ny, dy);
    *node = (int)lm_grid_node(g, cx - 1, cy - 1);
}

void lm_step_clear(lm_sim *sim);            /* 0. empty nodal sums (step 9) */
void lm_step_shape(lm_sim *sim);            /* N_ip, G_ip at x^k */
void lm_step_p2g(lm_sim *sim);              /* 1. m_i, p_i */
void lm_step_forces(lm_sim *sim);           /* 2. f_i^int + f_i^ext */
void lm_step_p2g_forces(lm_sim *sim);       /* 1 and 2 in one pass (point stresses) */
void lm_step_grid_update(lm_sim *sim);      /* 3. p_i^L, boundary conditions */
void lm_step_g2p(lm_sim *sim);              /* 4. v_p, x_p */
void lm_step_g2p_nodes(lm_sim *sim, double *ux, double *uy);   /* 4's a_i, v_i^L */
void lm_step_fill_g2p_nodes(lm_grid *g, double *ux, double *uy);   /* their ghosts */
void lm_step_strain_velocity(lm_sim *sim);  /* 5. MUSL re-map or USL */
void lm_step_strain_velocity_end(lm_sim *sim, int remap);   /* 5's divide, pins, walls */
/* 6a. membrane tangents and normals at x^{k+1}: lm_membrane_tangents */
lm_status lm_gas_cell_density(lm_sim *sim); /* 6b. [T] eqs 4.5-4.6 (density.c) */
void lm_step_gas_maxima(lm_sim *sim, double *max_div, double *c_max); /* 6c. [F] eq 24 */
void lm_step_stress(lm_sim *sim, double max_div, double c_max);     /* 7-8. rate, update */
/* 7-8 for all particles but the membranes' (slow_only != 0). */
void lm_step_stress_part(lm_sim *sim, double max_div, double c_max, int slow_only);
/* subcycle.c: one step with the membranes in sub-steps (steps 0-8, before
 * the clock, the check and splitting); its refusals name what it cannot do. */
lm_status lm_subcycle_step(lm_sim *sim);
void lm_subcycle_free(struct lm_subcycle *s);
lm_status lm_step_check(lm_sim *sim);       /* NaN, inversion, domain */
/* The check's verdict when particle `first` is the lowest-numbered one in
 * trouble (first >= n: none), with the contact's and the membranes' own. */
lm_status lm_step_check_report(lm_sim *sim, size_t first);
/* Step 2 after the particles' own forces: the hoop, tethers, gravity. */
void lm_step_forces_rest(lm_sim *sim);

/* damping.c (lamina.sim{damping = c}): f_i <- (f_i - c p_i) / (1 + c dt) on
 * the grid, or on nodes [first, last) of a body's own fields (contact), before
 * p_i^L = p_i + dt f_i; then the work the damping did, added to sim->damped. */
void lm_damp_grid(lm_sim *sim);
void lm_damp_forces(const lm_sim *sim, long first, long last, const double *px,
                    const double *py, double *fx, double *fy);
void lm_damp_account(lm_sim *sim);

/* step_fused.c: steps 4-8 and the check particle by particle, and the
 * next step's 0-2 in the same pass, for a plain run. */
int lm_step_fusable(const lm_sim *sim);     /* one thread, no pins, contact, ... */
lm_status lm_ahead_reserve(lm_sim *sim);    /* the pass's nodal arrays */
void lm_ahead_free(struct lm_ahead *a);
/* Steps 0-2 from the sums the last pass made ahead, if it did: 1, else 0. */
int lm_step_take_ahead(lm_sim *sim);
/* After step 3: steps 4-8 and the check; ahead: the next step's 0-2 too.
 * Returns the lowest-numbered particle in trouble, or n; *st the status
 * of what runs between its passes (membrane tangents, cell densities). */
size_t lm_step_fused_particles(lm_sim *sim, int ahead, lm_status *st);
lm_status lm_step_split(lm_sim *sim);       /* thinned gas points into four */

/* Zeroes the boundary-constrained components of a nodal vector field. */
void lm_grid_apply_bc(const lm_grid *g, double *ux, double *uy);
/* mass = "corrected" (mass_corrected.c): before step 3, p_i and f_i; in
 * step 5 (MUSL), the re-mapped velocities in (vx, vy), (sx, sy) scratch. */
void lm_mass_correct_momentum_forces(lm_sim *sim);
void lm_damp_keep_momentum(lm_sim *sim);   /* damping.c: p_i before the correction */
/* Whether the step applies that correction: mass = "corrected" or
 * "membrane", and no contact's own fields. */
int lm_mass_corrects(const lm_sim *sim);
void lm_mass_correct_velocity(lm_sim *sim, double *sx, double *sy);
/* Sets the ghost ring and stride for the basis (lm_sim_new). */
void lm_grid_layout(lm_grid *g, lm_basis basis);

/* The walls of the 3 x 3 bases (grid_walls.c): what a field's ghost nodes
 * mean. A scalar (mass) folds with +1; a vector's components fold and fill
 * with the image the wall stands for. */
typedef enum lm_comp { LM_COMP_SCALAR = 0, LM_COMP_X = 1, LM_COMP_Y = 2 } lm_comp;
/* After a scatter: adds each ghost node's sum into its mirror node (with
 * the image's sign) and zeroes it, on fixed and symmetry sides. */
void lm_grid_fold(const lm_grid *g, int nf, double *const *f, const lm_comp *comp);
/* Before a gather: sets each ghost node of a fixed or symmetry side to the
 * image of its mirror node. */
void lm_grid_fill(const lm_grid *g, int nf, double *const *f, const lm_comp *comp);

/* What a material's update reads at a particle (steps 6-7): the velocity
 * gradient L = sum_i v_i (x) G_ip ({xx, xy, yx, yy}), the strain increment
 * de = (dt/2)(L + L^T) and spin w = (L_xy - L_yx)/2, the hoop rate v_r / r
 * (axisymmetric form; 0 in the plane), dt, and the step's artificial-
 * viscosity maxima over the gas ([F] eq 24; lm_step_gas_maxima) with the
 * cell size they scale by. */
typedef struct lm_rate {
    double L[4];
    double dexx, deyy, dexy, w;
    double hoop;
    double dt;
    double max_div, c_max, h;
} lm_rate;

/* Every material's update of particle q from its rate (step 8) has this
 * signature; the steps pick it by the material's kind and the form
 * (plane, or axisymmetric: axisym.c) from one table. */
typedef void lm_update_fn(lm_sim *sim, size_t q, const lm_rate *r);
lm_update_fn lm_elastic_update_at;        /* material_elastic.c */
lm_update_fn lm_membrane_update_at;       /* membrane.c */
lm_update_fn lm_gas_update_at;            /* material_gas.c */
lm_update_fn lm_linear_fluid_update_at;   /* material_gas.c */
lm_update_fn lm_axisym_elastic_update_at; /* axisym.c: the same with the hoop terms */
lm_update_fn lm_axisym_membrane_update_at;
lm_update_fn lm_axisym_gas_update_at;
lm_update_fn lm_axisym_linear_fluid_update_at;
/* material_update.c: the table, by form (0 the plane, 1 axisymmetric) and
 * kind; the phased (step.c) and the fused step (step_fused.c) call it. */
extern lm_update_fn *const lm_material_updates[2][LM_LINEAR_FLUID + 1];
static inline void lm_update_at(lm_sim *sim, size_t q, const lm_rate *r, int axisym)
{
    lm_material_updates[axisym != 0][sim->mats[sim->p.mat[q]]->kind](sim, q, r);
}

/* Objective stress update of an elastic solid, [F] eq 19 (Jaumann rate). */
void lm_elastic_update(const lm_material *mat, double dexx, double deyy,
                       double dexy, double w, double dt, double *sxx,
                       double *syy, double *sxy, double *szz);
/* Strain energy density 1/2 sigma:C^-1:sigma, from the stress. */
double lm_elastic_energy_density(const lm_material *mat, double sxx,
                                 double syy, double sxy, double szz);

/* membrane.c: [M] §3, [T] §5.1, docs/physics.md §2 "Membrane". */
/* Unit tangents of every membrane point, by the body's normals method:
 * from its curve neighbours (connectivity, [F] §3.2: x_{p+1} - x_{p-1},
 * one-sided at open ends), or the normal of a construction without
 * connectivity (normals.h) turned -90 degrees. */
lm_status lm_membrane_tangents(lm_sim *sim);
/* sigma_t from eps_t by the material's law (membrane_law.c, the contract in
 * membrane_law.h; one-way: none in compression). */
double lm_membrane_stress(const lm_material *mat, double et);
/* eps_t += t.de.t with the current tangent; sigma rebuilt as sigma_t t(x)t;
 * the volume from the tangential stretch, kept as rho = m / V. */
void lm_membrane_update(const lm_material *mat, double dexx, double deyy, double dexy,
                        double tx, double ty, double m, double ds, double *et,
                        double *rho, double *sxx, double *syy, double *sxy, double *szz);
/* Sets eps_t and rebuilds sigma and the volume from it. */
void lm_membrane_set_strain(const lm_material *mat, double e, double tx, double ty, double m,
                            double ds, double *et, double *rho, double *sxx, double *syy,
                            double *sxy, double *szz);
/* Strain energy of a point of volume V by its law (membrane_law.c; the
 * papers' 1/2 V sigma_t eps_t for the linear laws). */
double lm_membrane_energy(const lm_material *mat, double V, double et);
/* Rebuilds the stress tensors of the membrane points from eps_t along the
 * current tangents (before the first step, once bodies are complete). */
lm_status lm_membrane_prepare(lm_sim *sim);

/* membrane_force.c: the tension integrated along segments (docs/physics.md
 * §5b) for membranes with force = LM_MFORCE_SEGMENT; the tear check for
 * every membrane. */
void lm_membrane_segment_prepare(lm_sim *sim);   /* L0 from x and eps_t */
void lm_membrane_segment_forces(lm_sim *sim);    /* fpx, fpy at x^k */
void lm_membrane_segment_hold(lm_sim *sim);      /* x^k, before step 4 (MUSL) */
void lm_membrane_segment_move(lm_sim *sim);      /* x^{k+1}, after step 5 (MUSL) */
void lm_membrane_segment_strains(lm_sim *sim);   /* eps_t, sigma at x^{k+1} */
double lm_membrane_segment_energy(const lm_sim *sim, int b);
lm_status lm_membrane_check_torn(lm_sim *sim);

/* link.c: step 2's link forces (after the scatter), their stored energy. */
void lm_link_forces(lm_sim *sim);
double lm_link_energy(const lm_sim *sim);
/* The same into (fx, fy), folded: every link, or only those with an end on
 * a membrane (multi-rate stepping's fast group), or only the others. */
enum { LM_LINKS_ALL, LM_LINKS_FAST, LM_LINKS_SLOW };
void lm_link_forces_into(lm_sim *sim, double *fx, double *fy, int which);

/* stress_cell.c: step 2's internal force from the cells' volume-weighted
 * mean stresses, gradients at the cell centres ([T] §5.4.3), for
 * def.stress = LM_STRESS_CELL; segment membranes' forces spread as usual.
 * Adds into g->fx, g->fy. */
void lm_stress_cell_forces(lm_sim *sim);

/* pin.c: held particles (lm_sim_add_pin). */
void lm_pin_p2g(lm_sim *sim);        /* step 1: the held nodes' weights */
void lm_pin_keep_start(lm_sim *sim); /* the pinned points' x, y before a move */
void lm_pin_grid(lm_sim *sim);       /* step 3: p^L and f at held nodes */
void lm_pin_particles(lm_sim *sim);  /* after step 4: v_p = v_pin */
/* A field's p^L = m v_pin at the nodes the pins hold (pin_w > 0, m > 0;
 * a held node of the shared grid always has mass), and the force f that
 * makes it so: lm_pin_grid's and each pinned body's own field's. */
void lm_pin_hold(const lm_sim *sim, const double *m, double *px, double *py, double *fx,
                 double *fy);
void lm_pin_velocity(lm_sim *sim);   /* step 5: the strain velocity */
/* Heavy end points: only a wire-sized share on the lumped grid, the rest
 * tied to the velocity at the point (constraint.c). */
int lm_constraint_active(const lm_sim *sim);   /* a heavy end point, no contact */
lm_status lm_constraint_reserve(lm_sim *sim);  /* room for every heavy point */
void lm_constraint_p2g(lm_sim *sim);       /* step 1: the extra mass off the grid */
/* the same off given sums (m may be NULL: momenta only) */
void lm_constraint_take_off(lm_sim *sim, double *m, double *ux, double *uy);
void lm_constraint_grid(lm_sim *sim);      /* step 3: shared on p and on f */
void lm_constraint_remap(lm_sim *sim);     /* step 5: the extra momentum off */
void lm_constraint_velocity(lm_sim *sim);  /* step 5: the strain velocities */
/* mass = "corrected" (mass_corrected.c): the constraint on a velocity
 * field inside the Neumann step; what: 0 momenta, 1 forces, 2 strain
 * velocities, 3 the correction (no targets); then the pins' reactions. */
void lm_constraint_field(lm_sim *sim, int what, double *ux, double *uy);
void lm_constraint_reactions(lm_sim *sim);
/* transfer = "apic" (apic.c): room for every point's C; step 1's affine
 * momenta; step 4's velocities and C; the MUSL re-map's affine momenta. */
int lm_apic_active(const lm_sim *sim);
lm_status lm_apic_reserve(lm_sim *sim);
void lm_apic_free(struct lm_apic *a);
void lm_apic_p2g(lm_sim *sim);
void lm_apic_g2p(lm_sim *sim);
void lm_apic_remap(lm_sim *sim);

/* material_gas.c: [F] §3.3 eqs 21-25, [F] eq 26. */
double lm_gas_sound_speed(const lm_material *mat, double e);
/* Wilkins artificial viscosity ([F] eqs 24-25, as reconstructed in
 * material_gas.c), zero unless the point is in compression. */
double lm_gas_av(const lm_material *mat, double rho, double div, double max_div,
                 double c_max, double h);
/* The shear viscosity a gas point's update uses: mat->mu, at most
 * kappa rho h^2 / dt when kappa > 0 (lamina.sim{viscous_limit}). */
double lm_gas_mu(const lm_material *mat, double kappa, double rho, double h, double dt);
/* sigma = 2 mu edot - 2/3 mu tr(edot) I - (p + q) I with p from e^k and
 * rho^{k+1}, edot the strain rate (sym L); then e += sigma:(dt edot) / rho
 * ([F] eq 23). */
void lm_gas_update(const lm_material *mat, double exx, double eyy, double exy,
                   double dt, double rho, double q, double *e, double *sxx, double *syy,
                   double *sxy, double *szz);
/* p = -beta div U: ev += tr de, sigma = -p I. */
void lm_linear_fluid_update(const lm_material *mat, double dexx, double deyy, double *ev,
                            double *sxx, double *syy, double *sxy, double *szz);

/* axisym.c: the axisymmetric form (lamina.sim{axisymmetric = true}). */
/* D_thth = sum_i N_ip v_ri / r_p at particle q (0 on the axis). */
double lm_axisym_hoop_rate(const lm_sim *sim, size_t q);
/* Step 2's hoop term f_ri -= V_p sigma_thth N_ip / r_p, added to g->fx. */
void lm_axisym_forces(lm_sim *sim);
/* The same into fx: every particle's, or (membranes != 0) the membranes'. */
void lm_axisym_forces_into(lm_sim *sim, double *fx, int membranes);
/* A membrane point's hoop strain ln(r / r0) (eps_t on the axis). */
double lm_axisym_membrane_hoop(const lm_particles *p, size_t q);
/* Sets eps_t of membrane point q, its stresses and volume (per radian). */
void lm_axisym_membrane_set(lm_sim *sim, size_t q, double et);
/* A new membrane point: r0 from its radius and initial strain. */
void lm_axisym_membrane_point(lm_sim *sim, size_t q);
/* Stresses and volumes of every membrane point (lm_membrane_prepare). */
void lm_axisym_membrane_prepare(lm_sim *sim);
/* The stored energy of membrane point q, a ring, by its law (1/2 V
 * (sigma_t eps_t + sigma_thth eps_thth) for the linear laws). */
double lm_axisym_membrane_energy(const lm_sim *sim, size_t q);
/* membrane_law.c: the in-surface law of a ring (axisymmetric form), by
 * the material's law: a plane-stress membrane is biaxial, sigma_t = E'
 * (eps_t + nu eps_h), sigma_h = E' (eps_h + nu eps_t), E' = E / (1 - nu^2)
 * ([T] eq 5.15 with the hoop strain); a string (uniaxial) carries sigma_t
 * = E eps_t only (meridional cords). One-way: the tension-field rule
 * (membrane_wrinkle.c). */
void lm_membrane_stress_biaxial(const lm_material *mat, double et, double eh, double *st,
                                double *sh);

/* v as Lua prints a float (%.14g, ".0" added to what looks like an
 * integer), for messages that the bindings used to format (sim.c). */
const char *lm_num_text(char *buf, size_t len, double v);

#endif
