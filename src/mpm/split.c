/* split.c - splitting gas points that have thinned out (lamina's addition,
 * not in the papers; docs/decisions.md "Gas splitting").
 *
 * Why: a gas point carries a fixed mass, so where the gas expands the
 * points draw apart; once a cell holds too few of them the grid no longer
 * sees a continuum there (measured on the dog-bone at cell 0.05: viscous
 * heating thins the gas beside the membrane to a few points per cell, and
 * one slips past the membrane or is crushed). A gas point that stands for
 * more than 1/split of a cell becomes four, each of a quarter of its mass
 * at the centre of a quarter of its square (side sqrt(V)), with its
 * velocity, density, specific energy and stress. Mass, momentum, kinetic
 * and internal energy and the centre of mass are unchanged; so is the
 * density field, which is why the children do not split again at once. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "particles.h"
#include "step.h"
#include "util.h"

static void copy_particle(lm_particles *p, size_t to, size_t from)
{
    double *const d[] = {p->x, p->y, p->vx, p->vy, p->m, p->rho, p->sxx, p->syy, p->sxy,
                         p->szz, p->et, p->ds, p->tx, p->ty, p->e, p->q, p->ev,
                         p->L0, p->fpx, p->fpy, p->lx, p->ly, p->r0};
    for (size_t k = 0; k < sizeof d / sizeof d[0]; k++) d[k][to] = d[k][from];
    p->body[to] = p->body[from];
    p->mat[to] = p->mat[from];
    p->pin[to] = p->pin[from];
    p->node[to] = p->node[from];
    p->xi[to] = p->xi[from];
    p->eta[to] = p->eta[from];
    size_t ns = (size_t)p->ns;
    if (p->N) {   /* uGIMP's stored weights */
        memcpy(&p->N[ns * to], &p->N[ns * from], ns * sizeof(double));
        memcpy(&p->Gx[ns * to], &p->Gx[ns * from], ns * sizeof(double));
        memcpy(&p->Gy[ns * to], &p->Gy[ns * from], ns * sizeof(double));
    }
}

/* The membranes' segments binned by squares of side 2d, each segment in
 * every square its bounding box, grown by d, touches: a point closer than d
 * to a segment lies in that box, so the segments of the point's own square
 * are all it needs to test (side 2d: a segment a tenth of d long lands in
 * about four squares, and a square holds a few dozen). Built only in a step where
 * some gas point has thinned out; the test per segment is the same, so the
 * answer is the same as testing them all (measured on the dog-bone at cell
 * 0.05, the test against all 400 segments was a tenth of the run). */
typedef struct seg_bins {
    double x0, y0, d, w;   /* the distance asked, the bins' side */
    int nx, ny;
    size_t *start;     /* nx * ny + 1 offsets into seg */
    size_t *seg;       /* 2 particle indices per entry: a segment's ends */
    int built, failed;
} seg_bins;

static int bin_of(double v, double v0, double d, int n)
{
    double k = floor((v - v0) / d);
    return k < 0 ? 0 : k > n - 1 ? n - 1 : (int)k;
}

/* Calls fn(q, r, ctx) for every segment (q, r) of every membrane. */
static void each_segment(const lm_sim *sim, void (*fn)(const lm_sim *, size_t, size_t, void *),
                         void *ctx)
{
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        if (!bd->membrane || bd->count < 2) continue;
        size_t last = bd->first + bd->count - 1;
        for (size_t q = bd->first; q <= last; q++) {
            if (q == last && !bd->closed) break;
            fn(sim, q, q < last ? q + 1 : bd->first, ctx);
        }
    }
}

typedef struct bin_pass {
    seg_bins *bins;
    size_t *fill;      /* NULL: count into start; else the next free slot of each cell */
} bin_pass;

static void bin_segment(const lm_sim *sim, size_t q, size_t r, void *ctx)
{
    bin_pass *bp = ctx;
    seg_bins *sb = bp->bins;
    const lm_particles *p = &sim->p;
    double d = sb->d;
    /* floor((v - v0) / w) does not decrease as v grows, in floating point
     * too, so a point inside the grown box falls in one of these bins */
    int i0 = bin_of(fmin(p->x[q], p->x[r]) - d, sb->x0, sb->w, sb->nx);
    int i1 = bin_of(fmax(p->x[q], p->x[r]) + d, sb->x0, sb->w, sb->nx);
    int j0 = bin_of(fmin(p->y[q], p->y[r]) - d, sb->y0, sb->w, sb->ny);
    int j1 = bin_of(fmax(p->y[q], p->y[r]) + d, sb->y0, sb->w, sb->ny);
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
            size_t c = (size_t)j * (size_t)sb->nx + (size_t)i;
            if (!bp->fill) {
                sb->start[c + 1]++;
            } else {
                size_t k = bp->fill[c]++;
                sb->seg[2 * k] = q;
                sb->seg[2 * k + 1] = r;
            }
        }
}

static void bins_free(seg_bins *sb)
{
    free(sb->start);
    free(sb->seg);
}

/* 0, or -1 out of memory (then every segment is tested, as before). */
static int bins_build(const lm_sim *sim, seg_bins *sb, double d)
{
    const lm_grid *g = &sim->grid;
    sb->built = 1;
    sb->x0 = g->x0;
    sb->y0 = g->y0;
    sb->d = d;
    sb->w = 2 * d;
    sb->nx = (int)ceil(g->nx * g->hx / sb->w) + 1;
    sb->ny = (int)ceil(g->ny * g->hy / sb->w) + 1;
    size_t nc = (size_t)sb->nx * (size_t)sb->ny;
    sb->start = calloc(nc + 1, sizeof *sb->start);
    size_t *fill = malloc(nc * sizeof *fill);
    if (!sb->start || !fill) {
        free(fill);
        sb->failed = 1;
        return -1;
    }
    bin_pass count = {sb, NULL};
    each_segment(sim, bin_segment, &count);
    for (size_t c = 0; c < nc; c++) sb->start[c + 1] += sb->start[c];
    sb->seg = malloc(2 * (sb->start[nc] ? sb->start[nc] : 1) * sizeof *sb->seg);
    if (!sb->seg) {
        free(fill);
        sb->failed = 1;
        return -1;
    }
    memcpy(fill, sb->start, nc * sizeof *fill);
    bin_pass put = {sb, fill};
    each_segment(sim, bin_segment, &put);
    free(fill);
    return 0;
}

/* Is (x, y) closer than d to the segment (q, r)? */
static int near_segment(const lm_particles *p, size_t q, size_t r, double x, double y, double d)
{
    double cx = p->x[q], cy = p->y[q], dx = p->x[r] - cx, dy = p->y[r] - cy;
    double l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((x - cx) * dx + (y - cy) * dy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double ex = cx + t * dx - x, ey = cy + t * dy - y;
    return ex * ex + ey * ey < d * d;
}

typedef struct near_all {
    double x, y, d;
    int hit;
} near_all;

static void near_one(const lm_sim *sim, size_t q, size_t r, void *ctx)
{
    near_all *na = ctx;
    if (!na->hit) na->hit = near_segment(&sim->p, q, r, na->x, na->y, na->d);
}

/* Is (x, y) closer than d to a membrane's polyline? */
static int near_membrane(const lm_sim *sim, seg_bins *sb, double x, double y, double d)
{
    if (!sb->built) bins_build(sim, sb, d);
    if (sb->failed) {
        near_all na = {x, y, d, 0};
        each_segment(sim, near_one, &na);
        return na.hit;
    }
    size_t c = (size_t)bin_of(y, sb->y0, sb->w, sb->ny) * (size_t)sb->nx +
               (size_t)bin_of(x, sb->x0, sb->w, sb->nx);
    for (size_t k = sb->start[c]; k < sb->start[c + 1]; k++)
        if (near_segment(&sim->p, sb->seg[2 * k], sb->seg[2 * k + 1], x, y, d)) return 1;
    return 0;
}

static const double sx[4] = {-1, 1, -1, 1}, sy[4] = {-1, -1, 1, 1};

/* A thinned gas point at least a cell away from every membrane. */
static int wants_split(const lm_sim *sim, seg_bins *sb, size_t q)
{
    const lm_particles *p = &sim->p;
    const lm_material *mat = sim->mats[p->mat[q]];
    if (mat->kind != LM_GAS || !(mat->split > 0)) return 0;
    if (p->pin[q]) return 0;   /* a held point stays one: the pin lists it */
    double A = sim->grid.hx * sim->grid.hy;
    /* most points are far from thin: decided without the division (a
     * margin of 1e-9 over the rounding of either form, so the answer is
     * that of the exact test below) */
    if (p->m[q] * mat->split < A * p->rho[q] * (1 - 1e-9)) return 0;
    double V = p->m[q] / p->rho[q];
    if (!(V * mat->split > A)) return 0;
    /* gas within a cell of a membrane is left whole: its children, closer
     * to the membrane than the points it was seeded with, leak through it
     * (measured on the dog-bone at cell 0.2) */
    if (near_membrane(sim, sb, p->x[q], p->y[q], fmin(sim->grid.hx, sim->grid.hy))) return 0;
    return 1;
}

/* Particle q becomes the lower-left quarter; its three siblings go to
 * r, r + 1, r + 2. */
static void split_one(lm_sim *sim, size_t q, size_t r)
{
    lm_particles *p = &sim->p;
    const lm_grid *g = &sim->grid;
    double a = 0.25 * sqrt(p->m[q] / p->rho[q]);
    double x1 = g->x0 + g->nx * g->hx, y1 = g->y0 + g->ny * g->hy;
    double cx = p->x[q], cy = p->y[q];
    p->m[q] *= 0.25;
    p->lx[q] *= 0.5;     /* uGIMP: each child covers a quarter of the square */
    p->ly[q] *= 0.5;
    for (int k = 0; k < 4; k++) {
        size_t c = k == 0 ? q : r + (size_t)k - 1;
        if (k > 0) copy_particle(p, c, q);
        p->x[c] = fmin(fmax(cx + sx[k] * a, g->x0), x1);
        p->y[c] = fmin(fmax(cy + sy[k] * a, g->y0), y1);
    }
}

lm_status lm_step_split(lm_sim *sim)
{
    lm_particles *p = &sim->p;
    int any = 0;
    for (int m = 0; m < sim->nmats; m++)
        if (sim->mats[m]->kind == LM_GAS && sim->mats[m]->split > 0) any = 1;
    if (!any) return LM_OK;
    unsigned char *flag = malloc(p->n);
    if (!flag) {
        snprintf(sim->err, sizeof sim->err, "out of memory splitting gas points");
        return LM_ERR_MEMORY;
    }
    size_t total = 0;
    seg_bins bins = {0};
    for (size_t q = 0; q < p->n; q++) total += flag[q] = (unsigned char)wants_split(sim, &bins, q);
    bins_free(&bins);
    size_t n_new = p->n + 3 * total;
    if (n_new > LM_MAX_PARTICLES) {   /* splitting must not bypass the limit */
        free(flag);
        snprintf(sim->err, sizeof sim->err, "gas splitting would make %zu particles, more "
                 "than the limit of %d (a smaller split)", n_new, LM_MAX_PARTICLES);
        return LM_ERR_MEMORY;
    }
    if (total == 0 || (n_new > p->cap &&
                       lm_particles_reserve(p, n_new > 2 * p->cap ? n_new : 2 * p->cap))) {
        free(flag);
        if (total == 0) return LM_OK;
        snprintf(sim->err, sizeof sim->err, "no room splitting gas points (%zu): %s", n_new,
                 lu_budget_oom());
        return LM_ERR_MEMORY;
    }
    /* shift[b]: points inserted before body b. Bodies move up, the last
     * first, so nothing is overwritten before it has moved. */
    size_t before = 3 * total;
    for (int b = sim->nbodies - 1; b >= 0; b--) {
        lm_body *bd = &sim->bodies[b];
        size_t s = 0;
        for (size_t q = bd->first; q < bd->first + bd->count; q++) s += flag[q];
        before -= 3 * s;
        size_t nf = bd->first + before;
        if (before)
            for (size_t k = bd->count; k-- > 0;) copy_particle(p, nf + k, bd->first + k);
        size_t tail = nf + bd->count, j = 0;
        for (size_t k = 0; k < bd->count; k++)
            if (flag[bd->first + k]) split_one(sim, nf + k, tail + 3 * j++);
        bd->first = nf;
        bd->count += 3 * s;
    }
    p->n = n_new;
    free(flag);
    return LM_OK;
}
