/* normals_variants.c - the dissertation's ways to normals without
 * connectivity, for comparison with the isosurface construction ([T] Ch. 7,
 * in the order it presents them, least to most effective):
 *  - the simple colour function ([T] §7.1, eqs 7.2-7.3), judged unacceptable
 *    there (Fig 67);
 *  - the colour interpolated to cell centres by the quadratic B-spline and
 *    differentiated at the nodes ([T] §7.2, eqs 7.4-7.5);
 *  - the mass matrix method ([T] §7.4, eqs 7.8-7.12) solved globally; solved
 *    per cell it is the linear isosurface construction with the normal
 *    equations, lm_normals_grid(LM_NB_LINEAR, LM_NS_NORMAL).
 *  - the cubic method ([T] §7.3, eqs 7.6-7.7): the colour on the vertices
 *    by a cubic weighting, each point reaching 16 of them (2D), and the
 *    normals its "cubic gradient" at the points. Its equations are lost in
 *    the text we have; read as the cubic B-spline, the quadratic method's
 *    B-spline one degree up (its support, 4 x 4 vertices, is the 16).
 * The OCR also lost eqs 7.2-7.12; the forms below are those the
 * surrounding text describes (docs/physics.md §3) with chi_p = 1 for every
 * membrane point. Signs do not matter: every normal is normalised and the
 * orientation is a separate pass. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "normals.h"

typedef struct nodes {
    int N[3];          /* nodes per axis */
    long count;
} nodes;

static nodes grid_nodes(const lm_ngrid *g)
{
    nodes s;
    s.N[0] = g->n[0] + 1;
    s.N[1] = g->n[1] + 1;
    s.N[2] = g->dim == 3 ? g->n[2] + 1 : 1;
    s.count = (long)s.N[0] * s.N[1] * s.N[2];
    return s;
}

static void cell_box(const lm_ngrid *g, const int c[3], lm_nbox *b)
{
    b->dim = g->dim;
    for (int a = 0; a < 3; a++) {
        b->lo[a] = a < g->dim ? g->x0[a] + c[a] * g->h[a] : 0.0;
        b->hi[a] = a < g->dim ? b->lo[a] + g->h[a] : 0.0;
    }
}

/* Global index of local linear node I (i + 2 (j + 2 k)) of cell c. */
static long node_of(const nodes *s, int dim, const int c[3], int I)
{
    int i = I & 1, j = (I >> 1) & 1, k = dim == 3 ? (I >> 2) & 1 : 0;
    return (c[0] + i) + (long)s->N[0] * ((c[1] + j) + (long)s->N[1] * (c[2] + k));
}

static lm_nerr locate(const lm_ngrid *g, const double *const x[3], size_t i,
                      double p[3], int c[3], char *err, size_t errlen)
{
    p[0] = x[0][i];
    p[1] = x[1][i];
    p[2] = g->dim == 3 ? x[2][i] : 0.0;
    for (int a = 0; a < g->dim; a++)
        if (!isfinite(p[a])) {
            snprintf(err, errlen, "point %zu is not finite", i + 1);
            return LM_NERR_NOT_FINITE;
        }
    if (lm_ngrid_cell(g, p, c) < 0) {
        snprintf(err, errlen, "point %zu (%g, %g%s) lies outside the grid", i + 1,
                 p[0], p[1], g->dim == 3 ? ", z" : "");
        return LM_NERR_OUTSIDE;
    }
    return LM_NERR_NONE;
}

/* N_I(x_p) and grad N_I(x_p) (world units) of the point's cell. */
static void linear_at(const lm_ngrid *g, const double p[3], const int c[3],
                      double s[LM_NMAX], double ds[LM_NMAX][3])
{
    lm_nbox b;
    double xi[3];
    cell_box(g, c, &b);
    lm_nbox_to_logical(&b, p, xi);
    lm_nbasis_eval(LM_NB_LINEAR, g->dim, xi, s, ds);
    for (int I = 0; I < lm_nbasis_count(LM_NB_LINEAR, g->dim); I++)
        for (int a = 0; a < g->dim; a++)
            ds[I][a] /= g->h[a];
}

/* n_p = sum_i n_i N_ip ([T] eq 7.3), normalised; flags the zero ones. */
/* Point i's normal is v / |v|; a zero or non-finite v leaves it 0 and
 * flagged undefined (every variant ends this way). */
static void put_unit(int dim, const double v[3], size_t i, double *const nrm[3],
                     unsigned char *flags)
{
    double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    int ok = len > 0 && isfinite(len);
    for (int a = 0; a < dim; a++)
        nrm[a][i] = ok ? v[a] / len : 0.0;
    if (flags)
        flags[i] = ok ? 0 : LM_NF_UNDEFINED;
}

static void nodes_to_points(const lm_ngrid *g, const nodes *s, size_t n,
                            const double *const x[3], const double *nn,
                            double *const nrm[3], unsigned char *flags)
{
    int cnt = lm_nbasis_count(LM_NB_LINEAR, g->dim);
    for (size_t i = 0; i < n; i++) {
        double p[3] = {x[0][i], x[1][i], g->dim == 3 ? x[2][i] : 0.0};
        double w[LM_NMAX], dw[LM_NMAX][3], v[3] = {0, 0, 0};
        int c[3];
        lm_ngrid_cell(g, p, c);
        linear_at(g, p, c, w, dw);
        for (int I = 0; I < cnt; I++) {
            long k = node_of(s, g->dim, c, I);
            for (int a = 0; a < g->dim; a++)
                v[a] += nn[3 * k + a] * w[I];
        }
        put_unit(g->dim, v, i, nrm, flags);
    }
}

/* The colour methods' lattices (cell centres, quadratic; vertices, cubic)
 * with a ring of ghosts: n + extra per axis (1 across a 2D grid), into D;
 * their count. */
static long ghost_lattice(const lm_ngrid *g, int extra, int D[3])
{
    D[0] = g->n[0] + extra;
    D[1] = g->n[1] + extra;
    D[2] = g->dim == 3 ? g->n[2] + extra : 1;
    return (long)D[0] * D[1] * D[2];
}

/* (i, j, k)'s index in such a lattice of dimensions D (k = 0 in 2D) */
static long ghost_at(const int D[3], int i, int j, int k)
{
    return i + (long)D[0] * (j + (long)D[1] * k);
}

static lm_nerr check_all(const lm_ngrid *g, size_t n, const double *const x[3],
                         char *err, size_t errlen)
{
    if (!g || (g->dim != 2 && g->dim != 3)) {
        snprintf(err, errlen, "the grid must be 2D or 3D");
        return LM_NERR_INPUT;
    }
    for (int a = 0; a < g->dim; a++)
        if (g->n[a] < 1 || !(g->h[a] > 0)) {
            snprintf(err, errlen, "the grid needs cells of size > 0");
            return LM_NERR_INPUT;
        }
    if (n == 0) {
        snprintf(err, errlen, "no membrane points");
        return LM_NERR_TOO_FEW;
    }
    for (size_t i = 0; i < n; i++) {
        double p[3];
        int c[3];
        lm_nerr e = locate(g, x, i, p, c, err, errlen);
        if (e)
            return e;
    }
    return LM_NERR_NONE;
}

lm_nerr lm_normals_colour(const lm_ngrid *g, size_t n, const double *const x[3],
                          double *const nrm[3], unsigned char *flags,
                          char *err, size_t errlen)
{
    lm_nerr e = check_all(g, n, x, err, errlen);
    if (e)
        return e;
    nodes s = grid_nodes(g);
    double *nn = calloc((size_t)s.count * 3, sizeof *nn);
    if (!nn) {
        snprintf(err, errlen, "out of memory (%ld nodes)", s.count);
        return LM_NERR_MEMORY;
    }
    int cnt = lm_nbasis_count(LM_NB_LINEAR, g->dim);
    for (size_t i = 0; i < n; i++) {        /* n_i = sum_p chi_p G_ip, eq 7.2 */
        double p[3], w[LM_NMAX], dw[LM_NMAX][3];
        int c[3];
        locate(g, x, i, p, c, err, errlen);
        linear_at(g, p, c, w, dw);
        for (int I = 0; I < cnt; I++) {
            long k = node_of(&s, g->dim, c, I);
            for (int a = 0; a < g->dim; a++)
                nn[3 * k + a] += dw[I][a];
        }
    }
    nodes_to_points(g, &s, n, x, nn, nrm, flags);
    free(nn);
    return LM_NERR_NONE;
}

lm_nerr lm_normals_quadratic_colour(const lm_ngrid *g, size_t n,
                                    const double *const x[3],
                                    double *const nrm[3], unsigned char *flags,
                                    char *err, size_t errlen)
{
    lm_nerr e = check_all(g, n, x, err, errlen);
    if (e)
        return e;
    /* cell centres with a ring of ghost cells: index c + 1, c in -1..n */
    int C[3];
    long ncent = ghost_lattice(g, 2, C);
    nodes s = grid_nodes(g);
    double *chi = calloc((size_t)ncent, sizeof *chi);
    double *nn = calloc((size_t)s.count * 3, sizeof *nn);
    if (!chi || !nn) {
        free(chi);
        free(nn);
        snprintf(err, errlen, "out of memory (%ld cells)", ncent);
        return LM_NERR_MEMORY;
    }
    int q = lm_nbasis_count(LM_NB_QUADRATIC, g->dim);
    for (size_t i = 0; i < n; i++) {        /* chi_c = sum_p S2(x_p - x_c), 7.4 */
        double p[3], xi[3], w[LM_NMAX];
        int c[3];
        lm_nbox b;
        locate(g, x, i, p, c, err, errlen);
        cell_box(g, c, &b);
        lm_nbox_to_logical(&b, p, xi);
        lm_nbasis_eval(LM_NB_QUADRATIC, g->dim, xi, w, NULL);
        for (int I = 0; I < q; I++) {
            /* centre I sits at cell c + (I's offset) - 1, ghost index + 1 */
            int di = I % 3, dj = (I / 3) % 3, dk = g->dim == 3 ? I / 9 : 1;
            chi[ghost_at(C, c[0] + di, c[1] + dj, g->dim == 3 ? c[2] + dk : 0)] += w[I];
        }
    }
    /* n_i = sum_c chi_c grad N_i(x_c) over the cells around node i (7.5):
     * at a cell centre the corner's bilinear has gradient +-1/2 (2D) or
     * +-1/4 (3D) per axis, over h */
    double half = g->dim == 3 ? 0.25 : 0.5;
    for (long k = 0; k < s.count; k++) {
        int ni[3] = {(int)(k % s.N[0]), (int)((k / s.N[0]) % s.N[1]),
                     (int)(k / ((long)s.N[0] * s.N[1]))};
        int nk = g->dim == 3 ? 2 : 1;
        for (int ck = 0; ck < nk; ck++)
            for (int cj = 0; cj < 2; cj++)
                for (int ci = 0; ci < 2; ci++) {
                    /* cell (ni - 1 + ci, ...): its ghost index is ni + ci */
                    long at = ghost_at(C, ni[0] + ci, ni[1] + cj, g->dim == 3 ? ni[2] + ck : 0);
                    int side[3] = {ci, cj, ck};
                    for (int a = 0; a < g->dim; a++)
                        /* side 0: the cell lies below the node, whose
                         * bilinear rises as xi: +; side 1: above, 1 - xi: - */
                        nn[3 * k + a] += chi[at] * (side[a] ? -half : half) / g->h[a];
                }
    }
    nodes_to_points(g, &s, n, x, nn, nrm, flags);
    free(chi);
    free(nn);
    return LM_NERR_NONE;
}

lm_nerr lm_normals_mass_matrix_global(const lm_ngrid *g, size_t n,
                                      const double *const x[3],
                                      const lm_nopts *o, double *const nrm[3],
                                      unsigned char *flags, double *cond_t,
                                      char *err, size_t errlen)
{
    lm_nerr e = check_all(g, n, x, err, errlen);
    if (e)
        return e;
    nodes s = grid_nodes(g);
    long ncells = (long)g->n[0] * g->n[1] * (g->dim == 3 ? g->n[2] : 1);
    long *col = malloc(sizeof *col * (size_t)s.count);
    long *cellpts = calloc((size_t)ncells, sizeof *cellpts);
    if (!col || !cellpts) {
        free(col);
        free(cellpts);
        snprintf(err, errlen, "out of memory");
        return LM_NERR_MEMORY;
    }
    int cnt = lm_nbasis_count(LM_NB_LINEAR, g->dim);
    for (long k = 0; k < s.count; k++)
        col[k] = -1;
    long N = 0, occupied = 0;
    for (size_t i = 0; i < n; i++) {        /* unknowns: nodes of occupied cells */
        double p[3];
        int c[3];
        locate(g, x, i, p, c, err, errlen);
        long id = lm_ngrid_cell(g, p, c);
        occupied += cellpts[id]++ == 0;
        for (int I = 0; I < cnt; I++) {
            long k = node_of(&s, g->dim, c, I);
            if (col[k] < 0)
                col[k] = N++;
        }
    }
    int extra = o && o->phi2 ? 2 : 1;
    long m = (long)n + extra * occupied;
    double *S = calloc((size_t)m * (size_t)N, sizeof *S);
    double *rhs = calloc((size_t)m, sizeof *rhs);
    double *phi = calloc((size_t)N, sizeof *phi);
    double *nn = calloc((size_t)s.count * 3, sizeof *nn);
    if (!S || !rhs || !phi || !nn) {
        snprintf(err, errlen, "out of memory (a %ld x %ld system)", m, N);
        e = LM_NERR_MEMORY;
        goto out;
    }
    long r = 0;
    for (size_t i = 0; i < n; i++, r++) {   /* phi = 1 at every point, 7.8 */
        double p[3], w[LM_NMAX], dw[LM_NMAX][3];
        int c[3];
        locate(g, x, i, p, c, err, errlen);
        linear_at(g, p, c, w, dw);
        for (int I = 0; I < cnt; I++)
            S[r * N + col[node_of(&s, g->dim, c, I)]] = w[I];
        rhs[r] = 1.0;
    }
    for (long id = 0; id < ncells; id++) {  /* phi = 0 (and 2) per cell */
        if (!cellpts[id])
            continue;
        int c[3] = {(int)(id % g->n[0]), (int)((id / g->n[0]) % g->n[1]),
                    g->dim == 3 ? (int)(id / ((long)g->n[0] * g->n[1])) : 0};
        lm_nrng rng;
        lm_nrng_seed(&rng, lm_nrng_mix(o ? o->seed : 1, (uint64_t)id));
        for (int t = 0; t < extra; t++, r++) {
            double xi[3] = {0, 0, 0}, w[LM_NMAX];
            for (int a = 0; a < g->dim; a++)
                xi[a] = lm_nrng_uniform(&rng);
            lm_nbasis_eval(LM_NB_LINEAR, g->dim, xi, w, NULL);
            for (int I = 0; I < cnt; I++)
                S[r * N + col[node_of(&s, g->dim, c, I)]] = w[I];
            rhs[r] = t == 0 ? 0.0 : 2.0;
        }
    }
    lm_lsq_info info;
    if ((e = lm_lsq_qr((int)m, (int)N, S, rhs, phi, &info))) {
        snprintf(err, errlen, "out of memory (a %ld x %ld system)", m, N);
        goto out;
    }
    if (cond_t)
        *cond_t = info.cond_t;
    for (size_t i = 0; i < n; i++) {        /* n_p = sum_i phi_i grad N_i, 7.9 */
        double p[3], w[LM_NMAX], dw[LM_NMAX][3], v[3] = {0, 0, 0};
        int c[3];
        locate(g, x, i, p, c, err, errlen);
        linear_at(g, p, c, w, dw);
        for (int I = 0; I < cnt; I++) {
            double f = phi[col[node_of(&s, g->dim, c, I)]];
            for (int a = 0; a < g->dim; a++)
                v[a] += f * dw[I][a];
        }
        double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        int ok = len > 1e-10 && isfinite(len);
        for (int a = 0; a < g->dim; a++)
            nrm[a][i] = ok ? v[a] / len : 0.0;
        if (flags)
            flags[i] = ok ? 0 : LM_NF_UNDEFINED;
    }
    if (o)
        lm_normals_orient(n, g->dim, x, nrm, o->orient, o->orient_point);
out:
    free(col);
    free(cellpts);
    free(S);
    free(rhs);
    free(phi);
    free(nn);
    return e;
}

/* The cubic B-spline of r cells and its derivative (support |r| < 2). */
static double bspline3(double r)
{
    double a = fabs(r);
    if (a < 1)
        return 2.0 / 3.0 - a * a + 0.5 * a * a * a;
    return a < 2 ? (2 - a) * (2 - a) * (2 - a) / 6.0 : 0.0;
}

static double bspline3_d(double r)
{
    double a = fabs(r), sg = r < 0 ? -1.0 : 1.0;
    if (a < 1)
        return sg * (-2 * a + 1.5 * a * a);
    return a < 2 ? -0.5 * sg * (2 - a) * (2 - a) : 0.0;
}

/* The four vertices per axis a point reaches, from its cell c - 1 (the
 * ghost ring's index + 1 = c), their weights and derivatives (per world
 * unit); unused axes weigh 1 at their one vertex. */
static void cubic_weights(const lm_ngrid *g, const double p[3], const int c[3],
                          double w[3][4], double dw[3][4])
{
    for (int a = 0; a < 3; a++)
        for (int k = 0; k < 4; k++) {
            if (a >= g->dim) {
                w[a][k] = k == 0;
                dw[a][k] = 0;
                continue;
            }
            double r = (p[a] - g->x0[a]) / g->h[a] - (c[a] - 1 + k);
            w[a][k] = bspline3(r);
            dw[a][k] = bspline3_d(r) / g->h[a];
        }
}

lm_nerr lm_normals_cubic_colour(const lm_ngrid *g, size_t n, const double *const x[3],
                                double *const nrm[3], unsigned char *flags,
                                char *err, size_t errlen)
{
    lm_nerr e = check_all(g, n, x, err, errlen);
    if (e)
        return e;
    /* vertices -1 .. n + 1 per axis (a ring of ghosts: a point on the grid's
     * edge reaches one vertex past it), index v + 1 */
    int V[3], K[3] = {4, 4, g->dim == 3 ? 4 : 1};
    long nv = ghost_lattice(g, 3, V);
    double *chi = calloc((size_t)nv, sizeof *chi);
    if (!chi) {
        snprintf(err, errlen, "out of memory (%ld vertices)", nv);
        return LM_NERR_MEMORY;
    }
    for (size_t i = 0; i < n; i++) {        /* chi_v = sum_p S3(x_p - x_v), 7.6 as read */
        double p[3], w[3][4], dw[3][4];
        int c[3];
        locate(g, x, i, p, c, err, errlen);
        cubic_weights(g, p, c, w, dw);
        for (int k = 0; k < K[2]; k++)
            for (int j = 0; j < K[1]; j++)
                for (int l = 0; l < K[0]; l++)
                    chi[ghost_at(V, c[0] + l, c[1] + j, c[2] + k)] += w[0][l] * w[1][j] * w[2][k];
    }
    for (size_t i = 0; i < n; i++) {        /* n_p = -grad sum_v chi_v S3, 7.7 as read */
        double p[3], w[3][4], dw[3][4], v[3] = {0, 0, 0};
        int c[3];
        locate(g, x, i, p, c, err, errlen);
        cubic_weights(g, p, c, w, dw);
        for (int k = 0; k < K[2]; k++)
            for (int j = 0; j < K[1]; j++)
                for (int l = 0; l < K[0]; l++) {
                    double f = chi[ghost_at(V, c[0] + l, c[1] + j, c[2] + k)];
                    v[0] -= f * dw[0][l] * w[1][j] * w[2][k];
                    v[1] -= f * w[0][l] * dw[1][j] * w[2][k];
                    v[2] -= f * w[0][l] * w[1][j] * dw[2][k];
                }
        put_unit(g->dim, v, i, nrm, flags);
    }
    free(chi);
    return LM_NERR_NONE;
}
