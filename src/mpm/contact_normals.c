/* contact_normals.c - a body's grid normals from its colour function
 * ([M] eqs 27-28, [T] eqs 9.10-9.11, docs/physics.md §1 and §4).
 *
 * Every point of the body carries the colour 1. The colour is spread to
 * the cell centres with the quadratic B-spline (nine centres per point,
 * [M] eq 27), which smooths it over about a cell; the gradient at a node
 * is that of the bilinear interpolant of the four cell centres around it
 * (the dual cell of which the node is the centre, [M] eq 28). The colour
 * grows into the body, so the outward normal is n = -grad chi / |grad chi|
 * (docs/physics.md §4: [M] eq 26 prints "> 0" with the inward colour gradient,
 * the same rule as "< 0" with this outward n). A membrane's colour is a
 * ridge along it, so its normals point away from it on both sides, as
 * [T] Fig 101 shows. Where the gradient vanishes (deep inside a body) the
 * normal is zero, and the release test then keeps the bodies together. */
#include <math.h>
#include <string.h>

#include "contact.h"
#include "step.h"

/* Quadratic B-spline beta_2 ([N] §5, docs/physics.md §3). */
static double beta2(double x)
{
    x = fabs(x);
    if (x <= 0.5) return 0.75 - x * x;
    if (x <= 1.5) return 0.5 * (1.5 - x) * (1.5 - x);
    return 0;
}

/* The colour at cells [ci0, ci1] x [cj0, cj1] (within the grid): only the
 * points whose nine centres reach them, in the same order as all. */
/* floor(v) as an int (|v| < 2^31), without the library call */
static inline int ifloor(double v)
{
    int t = (int)v;
    return t > v ? t - 1 : t;
}

static void colour(const lm_sim *sim, lm_contact_field *f, int ci0, int ci1, int cj0, int cj1)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    const lm_body *bd = &sim->bodies[f->body];
    for (int j = cj0; j <= cj1; j++)
        memset(f->chi + (size_t)j * g->nx + ci0, 0, (size_t)(ci1 - ci0 + 1) * sizeof(double));
    for (size_t q = bd->first; q < bd->first + bd->count; q++) {
        /* position in cell-centre units: centre c sits at c + 1/2 cells */
        double fx = (p->x[q] - g->x0) / g->hx - 0.5, fy = (p->y[q] - g->y0) / g->hy - 0.5;
        int cx = ifloor(fx + 0.5), cy = ifloor(fy + 0.5);
        if (cx + 1 < ci0 || cx - 1 > ci1 || cy + 1 < cj0 || cy - 1 > cj1) continue;
        /* its centres within the cells wanted (inside the grid): each
         * weight once, the same products as over all nine */
        int a0 = cx - 1 < ci0 ? ci0 - cx : -1, a1 = cx + 1 > ci1 ? ci1 - cx : 1;
        int b0 = cy - 1 < cj0 ? cj0 - cy : -1, b1 = cy + 1 > cj1 ? cj1 - cy : 1;
        double wx[3];
        for (int a = a0; a <= a1; a++) wx[a + 1] = beta2(fx - (cx + a));
        for (int b = b0; b <= b1; b++) {
            int j = cy + b;
            double wy = beta2(fy - j);
            double *row = f->chi + (size_t)j * g->nx;
            for (int a = a0; a <= a1; a++) row[cx + a] += wy * wx[a + 1];
        }
    }
}

/* Colour of cell (i, j); 0 outside the grid. */
static double chi_at(const lm_grid *g, const double *chi, int i, int j)
{
    if (i < 0 || j < 0 || i >= g->nx || j >= g->ny) return 0;
    return chi[(size_t)j * g->nx + i];
}

/* The normals at the nodes where pairs meet (lm_contact.met), the only
 * ones read (the release test, the frames at nodes where pairs met); zero
 * at its ghost nodes. */
void lm_contact_body_normals(lm_sim *sim, lm_contact_field *f)
{
    const lm_grid *g = &sim->grid;
    const lm_contact *c = sim->contact;
    const lm_cbox *b = &c->met;
    if (lm_cbox_empty(b)) return;
    double *const n2[2] = {f->nx, f->ny};
    lm_cbox_zero(c, b, n2, 2);
    /* the box's grid nodes (i, j) where the body is (the normal is wanted
     * nowhere else), without the ghost ring */
    int i0 = b->i0 - g->pad, i1 = b->i1 - g->pad, j0 = b->j0 - g->pad, j1 = b->j1 - g->pad;
    if (i0 < 0) i0 = 0;
    if (j0 < 0) j0 = 0;
    if (i1 > g->nx) i1 = g->nx;
    if (j1 > g->ny) j1 = g->ny;
    int bi0 = i1 + 1, bi1 = i0 - 1, bj0 = j1 + 1, bj1 = j0 - 1;
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++)
            if (f->m[lm_grid_node(g, i, j)] > 0) {
                if (i < bi0) bi0 = i;
                if (i > bi1) bi1 = i;
                if (j < bj0) bj0 = j;
                if (j > bj1) bj1 = j;
            }
    i0 = bi0, i1 = bi1, j0 = bj0, j1 = bj1;
    if (i0 > i1 || j0 > j1) return;
    /* the cells around them */
    int ci0 = i0 - 1 < 0 ? 0 : i0 - 1, cj0 = j0 - 1 < 0 ? 0 : j0 - 1;
    int ci1 = i1 > g->nx - 1 ? g->nx - 1 : i1, cj1 = j1 > g->ny - 1 ? g->ny - 1 : j1;
    colour(sim, f, ci0, ci1, cj0, cj1);
    for (int j = j0; j <= j1; j++) {
        for (int i = i0; i <= i1; i++) {
            long n = lm_grid_node(g, i, j);
            if (f->m[n] <= 0) continue;   /* only where the body is */
            double ll = chi_at(g, f->chi, i - 1, j - 1), lr = chi_at(g, f->chi, i, j - 1);
            double ul = chi_at(g, f->chi, i - 1, j), ur = chi_at(g, f->chi, i, j);
            double gx = ((lr + ur) - (ll + ul)) / (2 * g->hx);
            double gy = ((ul + ur) - (ll + lr)) / (2 * g->hy);
            double len = hypot(gx, gy);
            /* below 1e-9 of a point's colour per cell the direction is
             * rounding: no normal */
            if (len * fmin(g->hx, g->hy) <= 1e-9) continue;
            f->nx[n] = -gx / len;
            f->ny[n] = -gy / len;
        }
    }
}
