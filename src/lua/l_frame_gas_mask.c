/* l_frame_gas_mask.c - the pressure contours confined to where the gas is
 * (issue 32 item 6).
 *
 * The gas pressure interpolated to the grid ([T] §6.2.4: "both pressure and
 * stress are interpolated to grid points from material points", Fig 56;
 * [F] Fig 12) has a value at every node a gas point's shape functions
 * reach: up to a cell beyond the gas, so bands filled from the nodes alone
 * run past the membrane that holds the gas (issue 32: "pressure bands
 * outside the membrane"); a gas pressure belongs where the gas is. Here the nodal field is resampled on a
 * grid k times finer (each sample bilinear in its cell's nodes, from the
 * nodes that have gas) and every sample outside the squares the gas
 * points fill (their tents' sum below one half, below) is set far below
 * every band (OUTSIDE), so the filled contours (figure_fill.c) end on the
 * samples just inside, cutting a sample cell's corner diagonally rather
 * than in steps. A point's spacing s is the side of the square its volume
 * m / rho fills (per radian in the axisymmetric form, so divided by its
 * radius); the gas's outermost points lie up to half a spacing inside the
 * membrane, so the squares' edge is the membrane's line. k makes the
 * samples at most a quarter of the smallest spacing apart. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "l_frame_panel.h"

/* At most this many samples (about 32 MB of doubles): k is lowered to fit. */
#define MAX_SAMPLES ((size_t)4 << 20)
#define MAX_K 32
#define WIDTH 2.0
/* below every band, finite so the fill interpolates to it (to the inside
 * sample: the crossing's fraction is ~1e-297) instead of dropping the cell */
#define OUTSIDE (-1e300)

static double spacing(const lm_sim *sim, size_t q)
{
    const lm_particles *p = &sim->p;
    double v = p->rho[q] > 0 ? p->m[q] / p->rho[q] : 0;
    if (sim->def.axisym)
        v = p->x[q] > 0 ? v / p->x[q] : 0;
    return v > 0 ? sqrt(v) : 0;
}

static double bilinear(const double *f, int sx, int i, int j, double a, double b)
{
    const double w[4] = { (1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b };
    const double v[4] = { f[i + (size_t)sx * j], f[i + 1 + (size_t)sx * j],
                          f[i + (size_t)sx * (j + 1)], f[i + 1 + (size_t)sx * (j + 1)] };
    double s = 0, ws = 0;
    for (int c = 0; c < 4; c++)
        if (isfinite(v[c]) && w[c] > 0) {
            s += w[c] * v[c];
            ws += w[c];
        }
    return ws > 0 ? s / ws : NAN;
}

/* Adds the tent of half-width r and height w at (x, y) (from the grid's
 * corner) to the samples it reaches. */
static void spread(double *cover, int sx, int fx, int fy, double dx, double dy, double x,
                   double y, double r, double w)
{
    int i0 = (int)ceil((x - r) / dx), i1 = (int)floor((x + r) / dx);
    int j0 = (int)ceil((y - r) / dy), j1 = (int)floor((y + r) / dy);
    if (i0 < 0) i0 = 0;
    if (j0 < 0) j0 = 0;
    if (i1 > fx) i1 = fx;
    if (j1 > fy) j1 = fy;
    for (int j = j0; j <= j1; j++) {
        double wy = 1 - fabs(j * dy - y) / r;
        if (wy <= 0)
            continue;
        for (int i = i0; i <= i1; i++) {
            double wx = 1 - fabs(i * dx - x) / r;
            if (wx > 0)
                cover[i + (size_t)sx * j] += w * wx * wy;
        }
    }
}

int la_frame_gas_mask(lua_State *L, la_frame_ctx *ctx, const lm_sim *sim, const double *f,
                      lr_field *fd)
{
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    double smin = HUGE_VAL;
    size_t ngas = 0;
    for (size_t q = 0; q < p->n; q++) {
        if (sim->mats[p->mat[q]]->kind != LM_GAS)
            continue;
        double s = spacing(sim, q);
        if (s > 0 && s < smin)
            smin = s;
        ngas++;
    }
    if (ngas == 0 || !(smin < HUGE_VAL))
        return 0;
    double h = fmax(g->hx, g->hy);
    int k = (int)ceil(4 * h / smin);
    if (k < 1) k = 1;
    if (k > MAX_K) k = MAX_K;
    while (k > 1 && (size_t)(g->nx * k + 1) * (size_t)(g->ny * k + 1) > MAX_SAMPLES)
        k--;
    int fx = g->nx * k, fy = g->ny * k, sx = fx + 1;
    size_t ns = (size_t)sx * (size_t)(fy + 1);
    double dx = g->hx / k, dy = g->hy / k;
    /* how much of each sample the gas covers: each point spreads a tent
     * (s / r)^2 (1 - |dx| / r)(1 - |dy| / r) over +-r, s its spacing, r =
     * WIDTH s: on a lattice of spacing s the tents sum to 1 (the tent's
     * integral is s^2, the lattice's area per point), and at a straight
     * edge of the gas to 0.5 at half a spacing past the last row, the edge
     * of that row's own squares (any symmetric tent gives the half there);
     * a tent wider than the spacing bridges the gaps of a gas whose
     * points have drifted apart (continuity densities that no longer match
     * the spacing, gas_dogbone_contours) and rounds corners over r */
    double *cover = la_frame_scratch(L, ctx, ns * sizeof *cover);
    double X = fx * dx, Y = fy * dy;
    for (size_t q = 0; q < p->n; q++) {
        if (sim->mats[p->mat[q]]->kind != LM_GAS)
            continue;
        double sq = spacing(sim, q), r = WIDTH * sq;
        if (!(r > 0))
            continue;
        double x = p->x[q] - g->x0, y = p->y[q] - g->y0;
        /* a point within r of the grid's side also spreads its mirror
         * image's tent, as the walls mirror the grid (a symmetry plane's
         * gas reaches the plane, not half a spacing short of it) */
        double xs[3] = { x, -x, 2 * X - x }, ys[3] = { y, -y, 2 * Y - y };
        int ix[3] = { 1, x < r, X - x < r }, iy[3] = { 1, y < r, Y - y < r };
        for (int a = 0; a < 3; a++)
            for (int c = 0; c < 3; c++)
                if (ix[a] && iy[c])
                    spread(cover, sx, fx, fy, dx, dy, xs[a], ys[c], r, sq * sq / (r * r));
    }
    double *out = la_frame_scratch(L, ctx, ns * sizeof *out);
    for (int j = 0; j <= fy; j++) {
        int cj = j / k < g->ny ? j / k : g->ny - 1;
        double b = (double)(j - cj * k) / k;
        for (int i = 0; i <= fx; i++) {
            size_t o = i + (size_t)sx * j;
            if (cover[o] < 0.5) {
                out[o] = OUTSIDE;
                continue;
            }
            int ci = i / k < g->nx ? i / k : g->nx - 1;
            double v = bilinear(f, g->nx + 1, ci, cj, (double)(i - ci * k) / k, b);
            out[o] = isfinite(v) ? v : OUTSIDE;
        }
    }
    fd->f = out;
    fd->nx = fx;
    fd->ny = fy;
    return k;
}
