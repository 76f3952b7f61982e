/* diag.c - energies, centres of mass, momentum, the state hash. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "step.h"
#include "util.h"

/* docs/physics.md §1: kinetic sum 1/2 m v^2; strain sum V 1/2 sigma:C^-1:sigma
 * (from the stress, so it stays objective); potential -sum m g.x with the
 * initial positions as datum. */
static lm_energy energy_of(const lm_sim *sim, size_t first, size_t last, double ref,
                           int links)
{
    lm_energy e = {0, 0, 0, 0, 0};
    const lm_particles *p = &sim->p;
    double gx = 0;
    for (size_t q = first; q < last; q++) {
        e.kinetic += 0.5 * p->m[q] * (p->vx[q] * p->vx[q] + p->vy[q] * p->vy[q]);
        const lm_material *mat = sim->mats[p->mat[q]];
        double V = p->m[q] / p->rho[q];
        switch (mat->kind) {
        case LM_ELASTIC:
            e.strain += V * lm_elastic_energy_density(mat, p->sxx[q], p->syy[q],
                                                      p->sxy[q], p->szz[q]);
            break;
        case LM_MEMBRANE:
            /* segment membranes: their segments' energy, added below */
            if (sim->bodies[p->body[q]].force != LM_MFORCE_SEGMENT)
                e.strain += sim->def.axisym ? lm_axisym_membrane_energy(sim, q)
                                            : lm_membrane_energy(mat, V, p->et[q]);
            break;
        case LM_GAS:
            e.internal += p->m[q] * p->e[q];
            break;
        case LM_LINEAR_FLUID:
            /* stored energy of p = -beta div U: 1/2 beta ev^2 per unit of
             * the undeformed volume */
            e.strain += 0.5 * mat->beta * p->ev[q] * p->ev[q] * V / (1 + p->ev[q]);
            break;
        }
        gx += p->m[q] * (sim->def.gx * p->x[q] + sim->def.gy * p->y[q]);
    }
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        if (bd->force == LM_MFORCE_SEGMENT && bd->first >= first &&
            bd->first + bd->count <= last)
            e.strain += lm_membrane_segment_energy(sim, b);
    }
    if (links) e.strain += lm_link_energy(sim);   /* the whole run's, not a body's */
    e.potential = ref - gx;
    e.total = e.kinetic + e.strain + e.internal + e.potential;
    return e;
}

/* The kinetic energy the grid sees: the particles' momentum mapped to the
 * nodes with the shape functions at their present positions ([F] eq 6),
 * sum 1/2 |p_i|^2 / m_i. By Jensen's inequality it is at most the
 * particles' sum 1/2 m v^2; the difference is velocity in the null space of
 * the map (FLIP's "hidden" velocity), which moves nothing: positions and
 * strains follow the grid. */
double lm_sim_grid_kinetic(const lm_sim *sim)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    size_t nn = lm_grid_nodes(g);
    double *m = calloc(3 * nn, sizeof *m);
    if (!m) return NAN;
    double *px = m + nn, *py = m + 2 * nn;
    for (size_t q = 0; q < p->n; q++) {
        int node;
        double N[9], Gx[9], Gy[9];
        lm_shape_particle(sim, q, &node, N, Gx, Gy);
        for (int k = 0; k < p->ns; k++) {
            int i = lm_stencil_node(g, g->sw, node, k);
            m[i] += p->m[q] * N[k];
            px[i] += p->m[q] * N[k] * p->vx[q];
            py[i] += p->m[q] * N[k] * p->vy[q];
        }
    }
    double *const f[3] = {m, px, py};
    static const lm_comp comp[3] = {LM_COMP_SCALAR, LM_COMP_X, LM_COMP_Y};
    lm_grid_fold(g, 3, f, comp);     /* the step's view at the walls */
    double ke = 0;
    for (size_t i = 0; i < nn; i++)
        if (m[i] > 0) ke += 0.5 * (px[i] * px[i] + py[i] * py[i]) / m[i];
    free(m);
    return ke;
}

/* docs/physics.md §1: kinetic sum 1/2 m v^2; strain sum V 1/2 sigma:C^-1:sigma
 * (from the stress, so it stays objective; membranes 1/2 V sigma_t eps_t);
 * gas internal sum m e; potential -sum m g.x with the initial positions as
 * datum. */
lm_energy lm_sim_energy(const lm_sim *sim)
{
    return energy_of(sim, 0, sim->p.n, sim->pe_ref, 1);
}

/* One body's share (its potential energy datum is its own seeding). */
lm_energy lm_body_energy(const lm_sim *sim, int body)
{
    const lm_body *b = &sim->bodies[body];
    return energy_of(sim, b->first, b->first + b->count, b->pe_ref, 0);
}

static void range(const lm_sim *sim, int body, size_t *a, size_t *b)
{
    if (body < 0) {
        *a = 0;
        *b = sim->p.n;
    } else {
        *a = sim->bodies[body].first;
        *b = *a + sim->bodies[body].count;
    }
}

double lm_body_mass(const lm_sim *sim, int body)
{
    size_t a, b;
    range(sim, body, &a, &b);
    double m = 0;
    for (size_t q = a; q < b; q++) m += sim->p.m[q];
    return m;
}

static void weighted(const lm_sim *sim, int body, const double *u,
                     const double *v, double *ou, double *ov)
{
    size_t a, b;
    range(sim, body, &a, &b);
    double m = 0, su = 0, sv = 0;
    for (size_t q = a; q < b; q++) {
        m += sim->p.m[q];
        su += sim->p.m[q] * u[q];
        sv += sim->p.m[q] * v[q];
    }
    *ou = m > 0 ? su / m : 0;
    *ov = m > 0 ? sv / m : 0;
}

void lm_body_com(const lm_sim *sim, int body, double *x, double *y)
{
    weighted(sim, body, sim->p.x, sim->p.y, x, y);
}

void lm_body_velocity(const lm_sim *sim, int body, double *vx, double *vy)
{
    weighted(sim, body, sim->p.vx, sim->p.vy, vx, vy);
}

void lm_sim_momentum(const lm_sim *sim, double *px, double *py)
{
    double sx = 0, sy = 0;
    for (size_t q = 0; q < sim->p.n; q++) {
        sx += sim->p.m[q] * sim->p.vx[q];
        sy += sim->p.m[q] * sim->p.vy[q];
    }
    *px = sx;
    *py = sy;
}

uint64_t lm_sim_hash(const lm_sim *sim)
{
    const lm_particles *p = &sim->p;
    uint64_t h = LU_FNV_SEED;
    const double *f[] = {p->x, p->y, p->vx, p->vy, p->rho,
                         p->sxx, p->syy, p->sxy, p->szz, p->et, p->e, p->ev};
    for (size_t k = 0; k < sizeof f / sizeof f[0]; k++)
        if (p->n) h = lu_fnv1a(h, f[k], p->n * sizeof(double));
    h = lu_fnv1a(h, &sim->step, sizeof sim->step);
    return h;
}

/* ---- gas and membrane diagnostics (issue 8: mean pressure, hoop stress,
 * radii at 0 and 90 degrees, containment) ------------------------------- */

double lm_body_mean_pressure(const lm_sim *sim, int body)
{
    const lm_body *b = &sim->bodies[body];
    const lm_material *mat = sim->mats[b->mat];
    if (mat->kind != LM_GAS || b->count == 0) return 0;
    /* mass-weighted: split points (split.c) count for their mass */
    double s = 0, m = 0;
    for (size_t q = b->first; q < b->first + b->count; q++) {
        s += sim->p.m[q] * (mat->gamma - 1) * sim->p.rho[q] * sim->p.e[q];
        m += sim->p.m[q];
    }
    return s / m;
}

/* V_p p_p = (m_p / rho_p) (gamma - 1) rho_p e_p: the particle density,
 * which the continuity update carries and which drifts from the particles'
 * spacing, cancels (docs/decisions.md "Gas pressure over the space"). */
double lm_body_pressure_integral(const lm_sim *sim, int body)
{
    const lm_body *b = &sim->bodies[body];
    const lm_material *mat = sim->mats[b->mat];
    if (mat->kind != LM_GAS) return 0;
    double s = 0;
    for (size_t q = b->first; q < b->first + b->count; q++)
        s += sim->p.m[q] * sim->p.e[q];
    return (mat->gamma - 1) * s;
}

/* Vertex k of a membrane's polygon: its points, then (cx, cy) when it is
 * open (quarter models close through the centre). */
static size_t polygon_size(const lm_body *m) { return m->count + (m->closed ? 0 : 1); }

static void polygon_vertex(const lm_sim *sim, const lm_body *m, size_t k, double cx,
                           double cy, double *x, double *y)
{
    *x = k < m->count ? sim->p.x[m->first + k] : cx;
    *y = k < m->count ? sim->p.y[m->first + k] : cy;
}

/* The polygon's sums by Green's theorem: *a = sum (x_j y_k - x_k y_j)
 * (twice the signed area) and *v = sum (x_j + x_k)(x_j y_k - x_k y_j)
 * (six times the first moment int x dA). */
static void polygon_sums(const lm_sim *sim, int body, double cx, double cy, double *a,
                         double *v)
{
    const lm_body *m = &sim->bodies[body];
    size_t nv = polygon_size(m);
    *a = *v = 0;
    for (size_t k = 0, j = nv - 1; k < nv; j = k++) {
        double xk, yk, xj, yj;
        polygon_vertex(sim, m, k, cx, cy, &xk, &yk);
        polygon_vertex(sim, m, j, cx, cy, &xj, &yj);
        *a += xj * yk - xk * yj;
        *v += (xj + xk) * (xj * yk - xk * yj);
    }
}

double lm_membrane_enclosed_area(const lm_sim *sim, int body, double cx, double cy)
{
    double a, v;
    polygon_sums(sim, body, cx, cy, &a, &v);
    return 0.5 * fabs(a);
}

double lm_membrane_enclosed_volume(const lm_sim *sim, int body, double cx, double cy)
{
    if (!sim->def.axisym) return lm_membrane_enclosed_area(sim, body, cx, cy);
    /* per radian: the polygon's first moment int x dA */
    double a, v;
    polygon_sums(sim, body, cx, cy, &a, &v);
    return fabs(v) / 6;
}

/* The mean of sigma_t over the membrane. In the plane every point of a
 * membrane stands for the same length ds, and the mean is over the
 * points. Axisymmetric, a point is a ring whose area (its volume m / rho
 * over the thickness, axisym.c) goes from l^2 / 4 at a pole to l R at the
 * equator, and the mean over the surface weights each point by it: the
 * points within a cell of the axis, 1.4 % of a sphere's surface but 12 of
 * its 96 points at 0.2 cells, carry the grid's boundary layer there
 * (docs/robustness.md "Point spacing"), and a count put them at par with
 * the rest (the sphere's mean -12 % at 0.2 cells and -15 % at 0.4; by
 * area within 1.2 % at 0.05-1 cell; issue 30 item 4). */
double lm_body_mean_tangential_stress(const lm_sim *sim, int body)
{
    const lm_body *b = &sim->bodies[body];
    const lm_material *mat = sim->mats[b->mat];
    if (mat->kind != LM_MEMBRANE || b->count == 0) return 0;
    double s = 0, w = 0;
    for (size_t q = b->first; q < b->first + b->count; q++) {
        if (sim->def.axisym) {   /* a ring: the biaxial law's sigma_t (axisym.c) */
            double st, sh, v = sim->p.m[q] / sim->p.rho[q];
            lm_membrane_stress_biaxial(mat, sim->p.et[q], lm_axisym_membrane_hoop(&sim->p, q),
                                       &st, &sh);
            s += v * st;
            w += v;
        } else {
            s += lm_membrane_stress(mat, sim->p.et[q]);
        }
    }
    return sim->def.axisym ? (w > 0 ? s / w : 0) : s / (double)b->count;
}

/* Where the ray from (cx, cy) at `deg` degrees crosses the membrane's
 * polyline: the distance to the first crossing, or -1 if none. */
double lm_membrane_radius_at(const lm_sim *sim, int body, double deg, double cx, double cy)
{
    const lm_body *b = &sim->bodies[body];
    const double *x = sim->p.x, *y = sim->p.y;
    double a = deg * acos(-1.0) / 180;
    double dx = cos(a), dy = sin(a);
    if (fabs(deg - 90 * floor(deg / 90 + 0.5)) < 1e-12) {   /* exact on the axes */
        long k = ((long)floor(deg / 90 + 0.5) % 4 + 4) % 4;
        dx = (k == 0) - (k == 2);
        dy = (k == 1) - (k == 3);
    }
    double best = -1;
    size_t n = b->count;
    for (size_t k = 0; k + 1 < n + (b->closed ? 1 : 0); k++) {
        size_t i = b->first + k, j = b->first + (k + 1) % n;
        double ex = x[j] - x[i], ey = y[j] - y[i];
        double wx = x[i] - cx, wy = y[i] - cy;
        double den = dx * ey - dy * ex;
        if (den == 0) continue;
        double t = (wx * ey - wy * ex) / den;     /* along the ray */
        double u = (wx * dy - wy * dx) / den;     /* along the segment */
        if (t >= 0 && u >= -1e-12 && u <= 1 + 1e-12 && (best < 0 || t < best)) best = t;
    }
    /* a quarter model's end point lies on the axis itself */
    for (size_t q = b->first; best < 0 && q < b->first + n; q++) {
        double wx = x[q] - cx, wy = y[q] - cy;
        double along = wx * dx + wy * dy, off = fabs(wx * dy - wy * dx);
        if (along > 0 && off <= 1e-9 * along) best = along;
    }
    return best;
}

/* The gas pressure as a grid field, for pressure contours ([T] Fig 56):
 * p_i = sum_p m_p p_p N_ip / sum_p m_p N_ip over the gas particles, p
 * without q. out has (nx+1)(ny+1) values, x fastest; a node no gas touches
 * gets NaN. Returns the number of nodes with a value. */
size_t lm_grid_gas_pressure(const lm_sim *sim, double *out)
{
    const lm_grid *g = &sim->grid;
    size_t nn = lm_grid_nodes(g);
    /* the sums run over the padded grid of a 3 x 3 basis (its ghost sums
     * folded in at the walls), and only the grid's own nodes go out */
    double *w = calloc(g->pad ? 2 * nn : nn, sizeof *w);
    if (!w) return 0;
    double *v = g->pad ? w + nn : out;
    if (!g->pad)
        for (size_t i = 0; i < nn; i++) out[i] = 0;
    const lm_particles *p = &sim->p;
    for (size_t q = 0; q < p->n; q++) {
        const lm_material *mat = sim->mats[p->mat[q]];
        if (mat->kind != LM_GAS) continue;
        int node;
        double N[9], Gx[9], Gy[9];
        lm_shape_particle(sim, q, &node, N, Gx, Gy);
        double pr = (mat->gamma - 1) * p->rho[q] * p->e[q];
        for (int k = 0; k < p->ns; k++) {
            size_t i = (size_t)lm_stencil_node(g, g->sw, node, k);
            v[i] += p->m[q] * N[k] * pr;
            w[i] += p->m[q] * N[k];
        }
    }
    double *const f[2] = {v, w};
    static const lm_comp comp[2] = {LM_COMP_SCALAR, LM_COMP_SCALAR};
    lm_grid_fold(g, 2, f, comp);
    size_t have = 0;
    for (int j = 0; j <= g->ny; j++)
        for (int i = 0; i <= g->nx; i++) {
            size_t a = (size_t)lm_grid_node(g, i, j), o = (size_t)j * (g->nx + 1) + i;
            if (w[a] > 0) {
                out[o] = v[a] / w[a];
                have++;
            } else {
                out[o] = NAN;
            }
        }
    free(w);
    return have;
}
