/* bench_bytes.c - the bytes a step moves per particle, counted from the
 * passes the step makes (issue 36 item 3, `lamina bench roofline`,
 * docs/performance.md "Roofline").
 *
 * Each pass over the particles is a list of the particle arrays it reads
 * and writes (read from step.c, step_fused.c, step_kernels.h and the
 * materials' *_update_at); an array is counted once per pass it appears
 * in, its element size for a read and again for a write (the STREAM
 * convention: a[i] = b[i] + s c[i] moves 3 doubles). Within one pass the
 * caches hold a particle's line between its reads, so a second read of the
 * same array in that pass is not counted. The sizes are the engine's own
 * (sizeof the element of each lm_particles array): the count follows the
 * arrays when they change; when a pass changes, its list here must too.
 *
 * Node traffic is counted apart ("stencil"): the stencil's node doubles a
 * particle reads or read-modify-writes; neighbouring particles share
 * nodes, so these come from the caches, not memory, on a sorted seeding. */
#include "bench.h"

/* The particle arrays the step touches (lm_particles, mpm.h). */
enum {
    A_X, A_Y, A_VX, A_VY, A_M, A_RHO, A_SXX, A_SYY, A_SXY, A_SZZ,
    A_ET, A_DS, A_TX, A_TY, A_E, A_Q, A_MAT, A_NODE, A_XI, A_ETA,
    A_N, A_GX, A_GY, A_LX, A_LY, A_COUNT
};

typedef struct pass {
    unsigned char r[A_COUNT], w[A_COUNT];
    int node_r, node_rw;   /* node arrays read / read-modified-written a stencil node */
} pass;

/* Element bytes of each array, as the engine declares them. */
static size_t elem_bytes(int a, int ns)
{
    const lm_particles *p = 0;
    switch (a) {
    case A_X: return sizeof *p->x;
    case A_Y: return sizeof *p->y;
    case A_VX: return sizeof *p->vx;
    case A_VY: return sizeof *p->vy;
    case A_M: return sizeof *p->m;
    case A_RHO: return sizeof *p->rho;
    case A_SXX: return sizeof *p->sxx;
    case A_SYY: return sizeof *p->syy;
    case A_SXY: return sizeof *p->sxy;
    case A_SZZ: return sizeof *p->szz;
    case A_ET: return sizeof *p->et;
    case A_DS: return sizeof *p->ds;
    case A_TX: return sizeof *p->tx;
    case A_TY: return sizeof *p->ty;
    case A_E: return sizeof *p->e;
    case A_Q: return sizeof *p->q;
    case A_MAT: return sizeof *p->mat;
    case A_NODE: return sizeof *p->node;
    case A_XI: return sizeof *p->xi;
    case A_ETA: return sizeof *p->eta;
    case A_N: return (size_t)ns * sizeof *p->N;   /* ns per particle */
    case A_GX: return (size_t)ns * sizeof *p->Gx;
    case A_GY: return (size_t)ns * sizeof *p->Gy;
    case A_LX: return sizeof *p->lx;
    case A_LY: return sizeof *p->ly;
    }
    return 0;
}

static void rd(pass *s, int a) { s->r[a] = 1; }
static void wr(pass *s, int a) { s->w[a] = 1; }

/* The shape the kernels read: weights N (bilinear and quadratic B-spline:
 * rebuilt from the place xi, eta; uGIMP: stored). */
static void read_N(pass *s, lm_basis b)
{
    rd(s, A_NODE);
    if (b != LM_BASIS_GIMP) { rd(s, A_XI); rd(s, A_ETA); } else rd(s, A_N);
}
static void read_G(pass *s, lm_basis b)
{
    rd(s, A_NODE);
    if (b != LM_BASIS_GIMP) { rd(s, A_XI); rd(s, A_ETA); } else { rd(s, A_GX); rd(s, A_GY); }
}
/* lm_k_shape: x, y (uGIMP: its half-sizes) in, the stencil's shape out */
static void shape(pass *s, lm_basis b)
{
    rd(s, A_X); rd(s, A_Y);
    wr(s, A_NODE);
    if (b != LM_BASIS_GIMP) { wr(s, A_XI); wr(s, A_ETA); return; }
    if (b == LM_BASIS_GIMP) { rd(s, A_LX); rd(s, A_LY); }
    wr(s, A_N); wr(s, A_GX); wr(s, A_GY);
}
/* lm_k_scatter_mass_forces (point quadrature): m, v, V = m / rho, stress;
 * the five nodal sums m, px, py, fx, fy */
static void scatter_mf(pass *s, lm_basis b)
{
    read_N(s, b); read_G(s, b);
    rd(s, A_M); rd(s, A_VX); rd(s, A_VY); rd(s, A_RHO);
    rd(s, A_SXX); rd(s, A_SYY); rd(s, A_SXY);
    s->node_rw += 5;
}
/* lm_k_g2p: v and x updated from the nodes' a and v^L */
static void g2p(pass *s, lm_basis b)
{
    read_N(s, b);
    rd(s, A_VX); rd(s, A_VY); rd(s, A_X); rd(s, A_Y);
    wr(s, A_VX); wr(s, A_VY); wr(s, A_X); wr(s, A_Y);
    s->node_r += 4;
}
/* the MUSL re-map, lm_k_scatter_momentum(mass = 0): m v N into 2 sums */
static void remap(pass *s, lm_basis b)
{
    read_N(s, b);
    rd(s, A_M); rd(s, A_VX); rd(s, A_VY);
    s->node_rw += 2;
}
/* the rate (L from the nodal v) and the material's update (step 8) */
static void stress(pass *s, lm_basis b, lm_kind k)
{
    read_G(s, b);
    rd(s, A_MAT);
    s->node_r += 2;
    switch (k) {
    case LM_ELASTIC:   /* lm_elastic_update_at: rho, the four stresses */
        rd(s, A_RHO); wr(s, A_RHO);
        rd(s, A_SXX); rd(s, A_SYY); rd(s, A_SXY); rd(s, A_SZZ);
        wr(s, A_SXX); wr(s, A_SYY); wr(s, A_SXY); wr(s, A_SZZ);
        break;
    case LM_GAS:       /* lm_gas_update_at (continuity density): rho, q, e, stress set */
        rd(s, A_RHO); wr(s, A_RHO); wr(s, A_Q); rd(s, A_E); wr(s, A_E);
        wr(s, A_SXX); wr(s, A_SYY); wr(s, A_SXY); wr(s, A_SZZ);
        break;
    case LM_MEMBRANE:  /* lm_membrane_update_at: the tangent, m, ds, eps_t; rho, stress set */
        rd(s, A_TX); rd(s, A_TY); rd(s, A_M); rd(s, A_DS); rd(s, A_ET); wr(s, A_ET);
        wr(s, A_RHO);
        wr(s, A_SXX); wr(s, A_SYY); wr(s, A_SXY); wr(s, A_SZZ);
        break;
    default: /* the linear fluid: as the elastic, ev for szz */
        rd(s, A_RHO); wr(s, A_RHO);
        wr(s, A_SXX); wr(s, A_SYY); wr(s, A_SXY); wr(s, A_SZZ);
        break;
    }
}
/* lm_k_check: x, y, v, the in-plane stress and rho */
static void check(pass *s)
{
    rd(s, A_X); rd(s, A_Y); rd(s, A_VX); rd(s, A_VY);
    rd(s, A_SXX); rd(s, A_SYY); rd(s, A_SXY); rd(s, A_RHO);
}

static void add_pass(const pass *s, int ns, bench_bytes *out)
{
    for (int a = 0; a < A_COUNT; a++)
        out->particle += (double)((s->r[a] + s->w[a]) * elem_bytes(a, ns));
    out->stencil += (double)ns * sizeof(double) * (s->node_r + 2 * s->node_rw);
    out->passes++;
}

int bench_bytes_count(lm_basis basis, lm_kind kind, lm_scheme scheme, int fused,
                      bench_bytes *out)
{
    const int ns = basis == LM_BASIS_LINEAR ? 4 : 9;   /* stencil 2 x 2 or 3 x 3 */
    bench_bytes z = {0, 0, 0};
    *out = z;
    if (basis > LM_BASIS_BSPLINE2 || kind < LM_ELASTIC || kind > LM_LINEAR_FLUID) return -1;
    const int membrane = kind == LM_MEMBRANE;
    if (membrane) {
        /* lm_membrane_tangents before the stresses, by connectivity and
         * oriented by the curve: the signed area (x, y), then the tangents */
        pass a = {{0}, {0}, 0, 0}, t = {{0}, {0}, 0, 0};
        rd(&a, A_X); rd(&a, A_Y);
        rd(&t, A_X); rd(&t, A_Y); wr(&t, A_TX); wr(&t, A_TY);
        add_pass(&a, ns, out);
        add_pass(&t, ns, out);
    }
    if (fused) {
        /* step_fused.c on one thread with the next step following: the
         * last pass makes the next step's shape and sums (steps 0-2) */
        pass p1 = {{0}, {0}, 0, 0};
        g2p(&p1, basis);
        if (scheme == LM_MUSL) remap(&p1, basis);
        const int one = scheme == LM_USL && !membrane;   /* one_pass() */
        pass p2 = {{0}, {0}, 0, 0};
        pass *last = one ? &p1 : &p2;
        stress(last, basis, kind);
        check(last);
        shape(last, basis);
        scatter_mf(last, basis);
        add_pass(&p1, ns, out);
        if (!one) add_pass(&p2, ns, out);
        return 0;
    }
    /* step.c's phases, one pass each */
    pass ps[6];
    for (int k = 0; k < 6; k++) {
        pass z0 = {{0}, {0}, 0, 0};
        ps[k] = z0;
    }
    shape(&ps[0], basis);          /* 0 */
    scatter_mf(&ps[1], basis);     /* 1-2 */
    g2p(&ps[2], basis);            /* 4 */
    int np = 3;
    if (scheme == LM_MUSL) remap(&ps[np++], basis);   /* 5 */
    stress(&ps[np++], basis, kind);                    /* 7-8 */
    check(&ps[np++]);
    for (int k = 0; k < np; k++) add_pass(&ps[k], ns, out);
    return 0;
}

/* The passes over the whole grid (every node, empty or not): lm_step_clear
 * or the fused path's memset of the sums made ahead (m, px, py, fx, fy
 * written), lm_step_forces_rest (fx, fy += m g), lm_step_grid_update
 * (px, py += dt f), lm_step_g2p_nodes (m, f, p in; a, v^L out), and step
 * 5: USL v = p / m; MUSL v zeroed, re-mapped, then divided by m. The
 * walls' folds and fills touch the edges only: not counted. */
double bench_bytes_grid(lm_scheme scheme)
{
    const lm_grid *g = 0;
    const double d = (double)sizeof *g->m;
    double n = 5;       /* clear */
    n += 3 + 2;         /* forces_rest: m, fx, fy read; fx, fy written */
    n += 4 + 2;         /* grid update: px, py, fx, fy read; px, py written */
    n += 5 + 4;         /* g2p nodes: m, fx, fy, px, py read; ax, ay, ux, uy written */
    if (scheme == LM_MUSL)
        n += 2 + 3 + 2; /* v zeroed; m, vx, vy read, vx, vy written */
    else
        n += 3 + 2;     /* m, px, py read; vx, vy written */
    return n * d;
}

/* The quadratic B-spline's own USL pass on one thread (step_bspline2.c,
 * every bench case without gas or membrane) sweeps the grid twice more:
 * its node records (a_x, a_y, v^L_x, v^L_y, v_x, v_y read; 8 doubles
 * written) and the next step's sums handed out (4 read, 4 written to the
 * grid's arrays, the 4 zeroed), and clears one of the five sums instead
 * of five: 14 + 12 - 4 = 22 doubles a node more. */
double bench_bytes_grid_pass(lm_basis basis, lm_scheme scheme)
{
    const lm_grid *g = 0;
    return basis == LM_BASIS_BSPLINE2 && scheme == LM_USL ? 22.0 * (double)sizeof *g->m : 0;
}
