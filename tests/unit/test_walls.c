/* test_walls.c - the walls of every basis (grid_walls.c, docs/decisions.md
 * "Walls for the wider bases"):
 *   - a particle anywhere inside, by any wall or corner of any kind, keeps
 *     a partition of unity (sum of its folded weights = 1) and sum G = 0,
 *     and nothing is left on the ghost nodes of a fixed or symmetry side;
 *     by a free side the internal forces still sum to zero;
 *   - symmetry: a body straddling x = 0 run on [-1, 1] x [0, 1] and its
 *     right half run on [0, 1] x [0, 1] with a symmetry wall at x = 0 give
 *     the same particle states to round-off (and the same about y = 0);
 *   - fixed: the velocity interpolated at a point on a fixed wall is
 *     exactly zero, and a membrane's end points on the walls do not move
 *     in 1000 steps under gravity. */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "step.h"

static const lm_basis bases[3] = {LM_BASIS_LINEAR, LM_BASIS_GIMP, LM_BASIS_BSPLINE2};

static lm_sim *new_sim(lm_basis b, double x0, double x1, double h, lm_bc bc)
{
    lm_sim_def d;
    lm_sim_def_default(&d);
    d.x0 = x0; d.x1 = x1; d.y0 = 0; d.y1 = 1;
    d.hx = d.hy = h;
    d.dt = 1e-3;
    d.basis = b;
    for (int s = 0; s < 4; s++) d.bc[s] = bc;
    char err[256];
    lm_sim *sim = lm_sim_new(&d, err, sizeof err);
    CHECK(sim != NULL);
    return sim;
}

static double rnd(void) { return rand() / (RAND_MAX + 1.0); }

/* One particle at a time near the walls: partition of unity, sum G = 0
 * (the gradients folded as a scalar field), empty ghosts on fixed and
 * symmetry sides, sum f = 0 by free sides. */
static void unity_by_walls(lm_basis b, lm_bc bc)
{
    lm_sim *sim = new_sim(b, 0, 1, 0.125, bc);
    lm_material mat = {.kind = LM_ELASTIC, .rho = 10, .E = 1e4, .nu = 0.3};
    int mi = lm_sim_add_material(sim, &mat);
    int bi = lm_sim_add_body(sim, mi);
    CHECK(lm_sim_add_particle(sim, bi, 0.5, 0.5, 0.3, -0.2, 2.0, 10) == LM_OK);
    lm_grid *g = &sim->grid;
    size_t nn = lm_grid_nodes(g);
    double *gx = calloc(2 * nn, sizeof *gx), *gy = gx + nn;
    for (int t = 0; t < 400; t++) {
        /* within two cells of a wall or a corner, or exactly on a wall */
        double u = 0.25 * rnd(), v = rnd();
        if (t % 4 == 1) u = 1 - u;
        if (t % 8 >= 4) { double w = u; u = v; v = w; }
        if (t % 16 == 15) v = t % 32 == 15 ? 0.2 * rnd() : 1 - 0.2 * rnd();
        if (t % 10 == 3) u = t % 20 == 3 ? 0 : 1;
        sim->p.x[0] = u;
        sim->p.y[0] = v;
        sim->p.sxx[0] = 100 * (rnd() - 0.5);
        sim->p.syy[0] = 100 * (rnd() - 0.5);
        sim->p.sxy[0] = 100 * (rnd() - 0.5);
        sim->p.lx[0] = sim->p.ly[0] = 0.125 / (2 + 6 * rnd());
        lm_step_clear(sim);
        lm_step_shape(sim);
        lm_step_p2g(sim);
        lm_step_forces(sim);
        double m = 0, fx = 0, fy = 0, fabs_sum = 0, ghost = 0;
        memset(gx, 0, 2 * nn * sizeof *gx);
        lm_weights wt;
        lm_weights_of(sim, 0, &wt);
        for (int k = 0; k < sim->p.ns; k++) {
            int i = lm_stencil_node(g, g->sw, sim->p.node[0], k);
            CHECK(i >= 0 && (size_t)i < nn);
            gx[i] += wt.Gx[k];
            gy[i] += wt.Gy[k];
        }
        double *const fg[2] = {gx, gy};
        static const lm_comp sc[2] = {LM_COMP_SCALAR, LM_COMP_SCALAR};
        lm_grid_fold(g, 2, fg, sc);
        double sgx = 0, sgy = 0;
        for (size_t i = 0; i < nn; i++) {
            m += g->m[i];
            fx += g->fx[i];
            fy += g->fy[i];
            fabs_sum += fabs(g->fx[i]) + fabs(g->fy[i]);
            sgx += gx[i];
            sgy += gy[i];
        }
        for (int j = -g->pad; j <= g->ny + g->pad; j++)
            for (int i = -g->pad; i <= g->nx + g->pad; i++) {
                int out = i < 0 || j < 0 || i > g->nx || j > g->ny;
                if (out && bc != LM_BC_FREE) ghost += fabs(g->m[lm_grid_node(g, i, j)]);
            }
        CHECK_NEAR(m, 2.0, 1e-14);
        CHECK_NEAR(sgx, 0, 1e-12 / 0.125);
        CHECK_NEAR(sgy, 0, 1e-12 / 0.125);
        CHECK(ghost == 0);
        if (bc == LM_BC_FREE) {
            CHECK_NEAR(fx, 0, 1e-13 * fabs_sum);
            CHECK_NEAR(fy, 0, 1e-13 * fabs_sum);
        }
    }
    free(gx);
    lm_sim_free(sim);
}

/* A body straddling x = 0 on the full domain, or its right half with a
 * symmetry wall at x = 0 (axis 0); or the same turned by 90 degrees, about
 * y = 0 with the symmetry wall at the bottom (axis 1). The mirror-symmetric
 * start has the normal velocity odd and the tangential even across the
 * line, gravity along it. Dyadic cells and positions, so both grids see
 * the same offsets exactly. `full` gets every particle. */
static lm_sim *straddling(lm_basis b, int full, int axis)
{
    double h = 0.125;
    lm_sim_def d;
    lm_sim_def_default(&d);
    d.x0 = axis == 0 && full ? -1 : 0; d.x1 = 1;
    d.y0 = axis == 1 && full ? -1 : 0; d.y1 = 1;
    d.hx = d.hy = h;
    d.dt = 1e-3;
    if (axis == 0) d.gy = -5; else d.gx = -5;
    d.basis = b;
    d.bc[axis == 0 ? LM_LEFT : LM_BOTTOM] = full ? LM_BC_FIXED : LM_BC_SYMMETRY;
    char err[256];
    lm_sim *sim = lm_sim_new(&d, err, sizeof err);
    CHECK(sim != NULL);
    static lm_material mat = {.kind = LM_ELASTIC, .rho = 10, .E = 1e4, .nu = 0.3};
    int bi = lm_sim_add_body(sim, lm_sim_add_material(sim, &mat));
    double s = h / 2;
    for (int j = 0; j < 6; j++)
        for (int i = -6; i < 6; i++) {
            double u = (i + 0.5) * s, v = 0.25 + (j + 0.5) * s;   /* across, along */
            if (!full && u < 0) continue;
            double vu = 0.5 * u, vv = -0.2 + u * u;
            double x = axis == 0 ? u : v, y = axis == 0 ? v : u;
            double vx = axis == 0 ? vu : vv, vy = axis == 0 ? vv : vu;
            CHECK(lm_sim_add_particle(sim, bi, x, y, vx, vy, 10 * s * s, 10) == LM_OK);
            /* uGIMP squares wider than the seeding's h/4, so that the
             * points next to the line reach past it */
            lm_sim_set_particle_size(sim, sim->p.n - 1, 0.4 * h, 0.4 * h);
        }
    return sim;
}

static void symmetry_equals_mirror(lm_basis b, int axis)
{
    lm_sim *f = straddling(b, 1, axis), *hf = straddling(b, 0, axis);
    for (int s = 0; s < 300; s++) {
        CHECK(lm_sim_step(f) == LM_OK);
        CHECK(lm_sim_step(hf) == LM_OK);
    }
    /* particle k of the half run is particle 6 + (k / 6) * 12 + k % 6 of
     * the full run (rows of 12, the six on the kept side of each) */
    double smax = 0, dx = 0, dv = 0, ds = 0, drho = 0;
    for (size_t k = 0; k < hf->p.n; k++) {
        size_t q = 6 + (k / 6) * 12 + k % 6;
        dx = fmax(dx, fmax(fabs(f->p.x[q] - hf->p.x[k]), fabs(f->p.y[q] - hf->p.y[k])));
        dv = fmax(dv, fmax(fabs(f->p.vx[q] - hf->p.vx[k]), fabs(f->p.vy[q] - hf->p.vy[k])));
        ds = fmax(ds, fmax(fabs(f->p.sxx[q] - hf->p.sxx[k]),
                           fmax(fabs(f->p.syy[q] - hf->p.syy[k]),
                                fabs(f->p.sxy[q] - hf->p.sxy[k]))));
        drho = fmax(drho, fabs(f->p.rho[q] - hf->p.rho[k]));
        smax = fmax(smax, fabs(f->p.sxx[q]) + fabs(f->p.syy[q]) + fabs(f->p.sxy[q]));
    }
    printf("symmetry wall %s, %s: |dx| %.2g |dv| %.2g |dsigma| %.2g of %.3g |drho| %.2g\n",
           axis == 0 ? "x = 0" : "y = 0", lm_basis_name(b), dx, dv, ds, smax, drho);
    CHECK(smax > 10);              /* the body is loaded ... */
    CHECK(dx < 1e-12);             /* ... and both runs agree */
    CHECK(dv < 1e-12);
    CHECK(ds < 1e-12 * smax);
    CHECK(drho < 1e-12 * 10);
    lm_sim_free(f);
    lm_sim_free(hf);
}

/* Random nodal velocities, constrained and filled as the step does: the
 * velocity interpolated at any point on a fixed wall is exactly zero. */
static void fixed_wall_zero(lm_basis b)
{
    lm_sim *sim = new_sim(b, 0, 1, 0.125, LM_BC_FIXED);
    lm_grid *g = &sim->grid;
    size_t nn = lm_grid_nodes(g);
    for (size_t i = 0; i < nn; i++) {
        g->vx[i] = rnd() - 0.5;
        g->vy[i] = rnd() - 0.5;
    }
    lm_grid_apply_bc(g, g->vx, g->vy);
    double *const f[2] = {g->vx, g->vy};
    static const lm_comp c[2] = {LM_COMP_X, LM_COMP_Y};
    lm_grid_fill(g, 2, f, c);
    lm_material mat = {.kind = LM_ELASTIC, .rho = 10, .E = 1e4, .nu = 0.3};
    int bi = lm_sim_add_body(sim, lm_sim_add_material(sim, &mat));
    CHECK(lm_sim_add_particle(sim, bi, 0, 0, 0, 0, 1, 10) == LM_OK);
    for (int t = 0; t < 400; t++) {
        double s = rnd(), x = 0, y = 0;
        switch (t % 4) {
        case 0: x = 0; y = s; break;
        case 1: x = 1; y = s; break;
        case 2: x = s; y = 0; break;
        default: x = s; y = 1; break;
        }
        sim->p.x[0] = x;
        sim->p.y[0] = y;
        int node;
        double N[9], Gx[9], Gy[9], ux = 0, uy = 0;
        lm_shape_particle(sim, 0, &node, N, Gx, Gy);
        /* summed as lm_step_g2p does: row by row for the 3 x 3 bases */
        for (int r = 0; r < g->sw; r++) {
            double rx = 0, ry = 0;
            for (int a = 0; a < g->sw; a++) {
                int k = r * g->sw + a, i = lm_stencil_node(g, g->sw, node, k);
                rx += N[k] * g->vx[i];
                ry += N[k] * g->vy[i];
            }
            ux += rx;
            uy += ry;
        }
        CHECK(ux == 0 && uy == 0);
    }
    lm_sim_free(sim);
}

/* A pre-tensioned string across the unit square, its ends on the fixed
 * side walls (or, vertical, on the bottom and top), sagging under a
 * sideways gravity: the end points stay exactly put. */
static void membrane_ends_fixed(lm_basis b, int vertical)
{
    lm_sim *sim = new_sim(b, 0, 1, 0.0625, LM_BC_FIXED);
    sim->def.gx = vertical ? 10 : 0;
    sim->def.gy = vertical ? 0 : -10;
    lm_material wire = {.kind = LM_MEMBRANE, .rho = 1, .E = 1e5, .nu = 0, .thickness = 0.01,
                        .law = LM_LAW_UNIAXIAL};
    sim->def.dt = 0.4 * 0.0625 / lm_material_wave_speed(&wire);
    int mb = lm_sim_add_membrane(sim, lm_sim_add_material(sim, &wire), 0);
    int n = 41;
    double ds = 1.0 / (n - 1);
    for (int k = 0; k < n; k++) {
        size_t q = sim->p.n;
        double u = k * ds, x = vertical ? 0.5 : u, y = vertical ? u : 0.5;
        CHECK(lm_sim_add_particle(sim, mb, x, y, 0, 0, wire.rho * wire.thickness * ds,
                                  wire.rho) == LM_OK);
        CHECK(lm_sim_set_membrane_point(sim, q, ds, 0.01) == LM_OK);
    }
    for (int s = 0; s < 1000; s++) CHECK(lm_sim_step(sim) == LM_OK);
    size_t last = sim->p.n - 1;
    double sag = vertical ? sim->p.x[n / 2] - 0.5 : 0.5 - sim->p.y[n / 2];
    printf("fixed wall, %s: end points at (%.17g, %.17g) and (%.17g, %.17g), middle sags "
           "by %.4f\n", lm_basis_name(b), sim->p.x[0], sim->p.y[0], sim->p.x[last],
           sim->p.y[last], sag);
    CHECK(sim->p.x[0] == (vertical ? 0.5 : 0) && sim->p.y[0] == (vertical ? 0 : 0.5));
    CHECK(sim->p.x[last] == (vertical ? 0.5 : 1) && sim->p.y[last] == (vertical ? 1 : 0.5));
    CHECK(sim->p.vx[0] == 0 && sim->p.vy[0] == 0 && sim->p.vx[last] == 0 && sim->p.vy[last] == 0);
    CHECK(sag > 1e-4);       /* the load acts */
    lm_sim_free(sim);
}

int main(void)
{
    srand(11);
    for (int k = 0; k < 3; k++) {
        unity_by_walls(bases[k], LM_BC_FIXED);
        unity_by_walls(bases[k], LM_BC_SYMMETRY);
        unity_by_walls(bases[k], LM_BC_FREE);
        symmetry_equals_mirror(bases[k], 0);
        symmetry_equals_mirror(bases[k], 1);
        fixed_wall_zero(bases[k]);
        membrane_ends_fixed(bases[k], 0);
        membrane_ends_fixed(bases[k], 1);
    }
    return CHECK_DONE();
}
