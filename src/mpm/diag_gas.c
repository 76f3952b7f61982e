/* diag_gas.c - what a gas's diagnostics read: its pressure over the space it
 * fills, and its particles on the far side of a membrane (issue 30 item 5).
 *
 * Pressure. A gas particle pushes the grid with V_p p_p = (gamma - 1) m_p e_p
 * ([F] eq 21 in the internal force, docs/decisions.md "Gas pressure over the
 * space"); its density rho_p, which the continuity update carries, does not
 * enter the dynamics and drifts from the particles' spacing, so the mean of
 * (gamma - 1) rho_p e_p over the particles reads what no force balances
 * (+20 % at 4 particles a cell on a pressurised arc between two gases). The
 * pressure the grid sees at node i is the energy density there,
 *   P_i = (gamma - 1) sum_p m_p e_p N_ip / V_i,   V_i = hx hy,
 * exact wherever the node's whole support lies in the gas (partition of
 * unity: a uniform gas gives P_i = (gamma - 1) rho e). lamina averages P_i
 * over those nodes: [T] Table 5's note c, "calculated by averaging the final
 * pressure at interior grid points". A node is interior when every cell its
 * support reaches (sw - 1 cells each side) holds a particle of the gas and
 * none of another body; cells beyond a symmetry or fixed wall of a 3 x 3
 * basis are the mirror of those inside (the scatter folds the ghosts,
 * grid_walls.c), beyond a free side or the linear basis' walls they are
 * empty; nodes on the boundary are left out (the fold adds the ghosts'
 * sums, not the node's own image: they read half). Axisymmetric: V_i = r_i hx hy per radian, nodes whose support
 * reaches the axis left out.
 *
 * Far side. Which side of a membrane's polygon (closed through (cx, cy) when
 * open) each gas particle lies on, by ray crossings counted over the edges
 * that span its row of cells, and for those on the side asked for the
 * distance to the nearest edge, searched ring by ring over a cell binning of
 * the edges: O(particles + edges) for a contained gas. */
#include <math.h>
#include <stdlib.h>

#include "step.h"

static int cell_of(double x, double x0, double h, int n)
{
    int c = (int)floor((x - x0) / h);
    return c < 0 ? 0 : c >= n ? n - 1 : c;
}

/* Cell index c on one axis, mirrored into [0, n) across a side that images
 * (pad, not free); -1 when the cell lies beyond a side that does not. */
static int mirror_cell(const lm_grid *g, int c, int n, int lo, int hi)
{
    if (c < 0) return g->pad && g->bc[lo] != LM_BC_FREE && -1 - c < n ? -1 - c : -1;
    if (c >= n) return g->pad && g->bc[hi] != LM_BC_FREE && 2 * n - 1 - c >= 0 ? 2 * n - 1 - c : -1;
    return c;
}

double lm_gas_space_pressure(const lm_sim *sim, int body, size_t *nodes)
{
    const lm_body *b = &sim->bodies[body];
    const lm_material *mat = sim->mats[b->mat];
    const lm_grid *g = &sim->grid;
    const lm_particles *p = &sim->p;
    if (nodes) *nodes = 0;
    if (mat->kind != LM_GAS || b->count == 0) return 0;
    size_t nn = lm_grid_nodes(g), nc = (size_t)g->nx * g->ny;
    double *S = calloc(nn, sizeof *S);
    unsigned char *occ = calloc(nc, 1);
    if (!S || !occ) {
        free(S);
        free(occ);
        return NAN;
    }
    /* bit 0: the gas is in the cell; bit 1: another body is */
    for (size_t q = 0; q < p->n; q++) {
        size_t c = (size_t)cell_of(p->y[q], g->y0, g->hy, g->ny) * g->nx +
                   (size_t)cell_of(p->x[q], g->x0, g->hx, g->nx);
        occ[c] |= p->body[q] == body ? 1 : 2;
    }
    double E = 0;   /* sum m e: the fallback's numerator */
    double V = 0;   /* sum m / rho */
    for (size_t q = b->first; q < b->first + b->count; q++) {
        int node;
        double N[9], Gx[9], Gy[9];
        lm_shape_particle(sim, q, &node, N, Gx, Gy);
        double me = p->m[q] * p->e[q];
        for (int k = 0; k < p->ns; k++) S[lm_stencil_node(g, g->sw, node, k)] += me * N[k];
        E += me;
        V += p->m[q] / p->rho[q];
    }
    double *const f[1] = {S};
    static const lm_comp comp[1] = {LM_COMP_SCALAR};
    lm_grid_fold(g, 1, f, comp);
    int r = g->sw - 1;   /* cells the support reaches on each side */
    double sum = 0;
    size_t have = 0;
    for (int j = 0; j <= g->ny; j++)
        for (int i = 0; i <= g->nx; i++) {
            /* a node on the boundary: its own image is not folded in (only
             * the ghosts' are), so it reads half; never wholly in the gas */
            if (i == 0 || j == 0 || i == g->nx || j == g->ny) continue;
            if (sim->def.axisym && i <= r) continue;
            int ok = 1, empty = 0;
            for (int cj = j - r; ok && cj < j + r; cj++)
                for (int ci = i - r; ok && ci < i + r; ci++) {
                    int mi = mirror_cell(g, ci, g->nx, LM_LEFT, LM_RIGHT);
                    int mj = mirror_cell(g, cj, g->ny, LM_BOTTOM, LM_TOP);
                    ok = mi >= 0 && mj >= 0 && !(occ[(size_t)mj * g->nx + mi] & 2);
                    empty += ok && occ[(size_t)mj * g->nx + mi] == 0;
                }
            if (!ok || 4 * empty > 4 * r * r) continue;
            double vol = g->hx * g->hy * (sim->def.axisym ? g->x0 + i * g->hx : 1);
            sum += S[lm_grid_node(g, i, j)] / vol;
            have++;
        }
    free(S);
    free(occ);
    if (nodes) *nodes = have;
    /* no node wholly in the gas (a gas a few cells across): the volume-
     * weighted mean over the particles, sum V_p p_p / sum V_p */
    if (have == 0) return V > 0 ? (mat->gamma - 1) * E / V : 0;
    return (mat->gamma - 1) * sum / (double)have;
}

/* ---- the far side of a membrane --------------------------------------- */

typedef struct poly {
    size_t nv;
    double *x, *y;          /* vertices; edge k runs from k-1 (wrapped) to k */
    double x0, y0, h;       /* bins: squares of side h from (x0, y0) */
    int nbx, nby;
    size_t *row_start, *row_edge;    /* edges spanning each row of bins */
    size_t *bin_start, *bin_edge;    /* edges whose box meets each bin */
} poly;

static void poly_free(poly *P)
{
    free(P->x);
    free(P->row_start);
    free(P->row_edge);
    free(P->bin_start);
    free(P->bin_edge);
}

static void edge_box(const poly *P, size_t k, int *i0, int *i1, int *j0, int *j1)
{
    size_t a = k ? k - 1 : P->nv - 1;
    double xl = fmin(P->x[a], P->x[k]), xh = fmax(P->x[a], P->x[k]);
    double yl = fmin(P->y[a], P->y[k]), yh = fmax(P->y[a], P->y[k]);
    *i0 = (int)floor((xl - P->x0) / P->h);
    *i1 = (int)floor((xh - P->x0) / P->h);
    *j0 = (int)floor((yl - P->y0) / P->h);
    *j1 = (int)floor((yh - P->y0) / P->h);
}

/* The edges into rows (by y span) and bins (by box), by a counting sort:
 * counts, inclusive prefix sums (start[c] = the end of list c), then each
 * edge placed at --start[c], which leaves start[c] at the list's beginning
 * and start[c + 1] at its end. */
static int poly_bin(poly *P)
{
    double xl = INFINITY, xh = -INFINITY, yl = INFINITY, yh = -INFINITY;
    for (size_t k = 0; k < P->nv; k++) {
        xl = fmin(xl, P->x[k]);
        xh = fmax(xh, P->x[k]);
        yl = fmin(yl, P->y[k]);
        yh = fmax(yh, P->y[k]);
    }
    P->x0 = xl;
    P->y0 = yl;
    P->nbx = (int)floor((xh - xl) / P->h) + 1;
    P->nby = (int)floor((yh - yl) / P->h) + 1;
    size_t nr = (size_t)P->nby, nb = (size_t)P->nbx * P->nby;
    P->row_start = calloc(nr + 1, sizeof(size_t));
    P->bin_start = calloc(nb + 1, sizeof(size_t));
    if (!P->row_start || !P->bin_start) return -1;
    for (int pass = 0; pass < 2; pass++) {
        for (size_t k = 0; k < P->nv; k++) {
            int i0, i1, j0, j1;
            edge_box(P, k, &i0, &i1, &j0, &j1);
            for (int j = j0; j <= j1; j++) {
                if (pass) P->row_edge[--P->row_start[j]] = k;
                else P->row_start[j]++;
                for (int i = i0; i <= i1; i++) {
                    size_t c = (size_t)j * P->nbx + i;
                    if (pass) P->bin_edge[--P->bin_start[c]] = k;
                    else P->bin_start[c]++;
                }
            }
        }
        if (pass) break;
        for (size_t j = 1; j <= nr; j++) P->row_start[j] += P->row_start[j - 1];
        for (size_t c = 1; c <= nb; c++) P->bin_start[c] += P->bin_start[c - 1];
        P->row_edge = malloc((P->row_start[nr] + 1) * sizeof(size_t));
        P->bin_edge = malloc((P->bin_start[nb] + 1) * sizeof(size_t));
        if (!P->row_edge || !P->bin_edge) return -1;
    }
    return 0;
}

/* Inside the polygon (even-odd rule, ray towards +x). */
static int poly_inside(const poly *P, double px, double py)
{
    int j = (int)floor((py - P->y0) / P->h);
    if (j < 0 || j >= P->nby) return 0;
    int in = 0;
    for (size_t e = P->row_start[j]; e < P->row_start[j + 1]; e++) {
        size_t k = P->row_edge[e], a = k ? k - 1 : P->nv - 1;
        double xa = P->x[a], ya = P->y[a], xb = P->x[k], yb = P->y[k];
        if ((ya > py) != (yb > py)) {
            double xc = xa + (py - ya) * (xb - xa) / (yb - ya);
            if (px < xc) in = !in;
        }
    }
    return in;
}

static double seg_dist2(const poly *P, size_t k, double px, double py)
{
    size_t a = k ? k - 1 : P->nv - 1;
    double ex = P->x[k] - P->x[a], ey = P->y[k] - P->y[a];
    double wx = px - P->x[a], wy = py - P->y[a];
    double ee = ex * ex + ey * ey;
    double u = ee > 0 ? fmax(0, fmin(1, (wx * ex + wy * ey) / ee)) : 0;
    double dx = wx - u * ex, dy = wy - u * ey;
    return dx * dx + dy * dy;
}

/* Distance to the nearest edge: rings of bins about the point's bin until
 * the ring's inner distance exceeds the best found. */
static double poly_dist(const poly *P, double px, double py)
{
    int ci = (int)floor((px - P->x0) / P->h), cj = (int)floor((py - P->y0) / P->h);
    double best = INFINITY;
    int far = P->nbx + P->nby + abs(ci) + abs(cj) + 2;
    for (int ring = 0; ring <= far; ring++) {
        double inner = (ring - 1) * P->h;
        if (inner > 0 && inner * inner > best) break;
        for (int j = cj - ring; j <= cj + ring; j++)
            for (int i = ci - ring; i <= ci + ring; i++) {
                if (abs(i - ci) != ring && abs(j - cj) != ring) continue;
                if (i < 0 || j < 0 || i >= P->nbx || j >= P->nby) continue;
                size_t c = (size_t)j * P->nbx + i;
                for (size_t e = P->bin_start[c]; e < P->bin_start[c + 1]; e++)
                    best = fmin(best, seg_dist2(P, P->bin_edge[e], px, py));
            }
    }
    return sqrt(best);
}

int lm_gas_far_side(const lm_sim *sim, int gas, int membrane, double cx, double cy,
                    int inside, double beyond, lm_far *out)
{
    const lm_body *m = &sim->bodies[membrane], *g = &sim->bodies[gas];
    *out = (lm_far){0, 0, 0, 0};
    poly P = {0};
    P.nv = m->count + (m->closed ? 0 : 1);
    P.h = fmax(sim->grid.hx, sim->grid.hy);
    P.x = malloc(2 * P.nv * sizeof *P.x);
    if (!P.x || m->count < 2) {
        free(P.x);
        return -1;
    }
    P.y = P.x + P.nv;
    for (size_t k = 0; k < P.nv; k++) {
        P.x[k] = k < m->count ? sim->p.x[m->first + k] : cx;
        P.y[k] = k < m->count ? sim->p.y[m->first + k] : cy;
    }
    if (poly_bin(&P)) {
        poly_free(&P);
        return -1;
    }
    for (size_t q = g->first; q < g->first + g->count; q++) {
        double px = sim->p.x[q], py = sim->p.y[q];
        if (poly_inside(&P, px, py) != inside) {
            out->near++;
            continue;
        }
        double d = poly_dist(&P, px, py);
        out->depth = fmax(out->depth, d);
        if (d > beyond) out->beyond++;
        else out->within++;
    }
    poly_free(&P);
    return 0;
}
