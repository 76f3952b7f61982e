/* loop_ceiling.c - how fast can a plain C USL step go on this machine?
 * (issue 17 item 1; docs/performance.md "The step against a plain loop").
 *
 * The problem of ../shared/bench/ref_usl.c (two elastic disks, cell h, 4
 * points per cell, bilinear basis, lumped mass, small-strain linear
 * elasticity, plane strain), stepped three ways that give the same states
 * to the bit (the hash printed):
 *   passes - scatter, then a node pass, then gather and update: ref_usl's
 *            structure;
 *   fused  - one particle pass a step: gather, update, then the particle's
 *            share of the next step's sums into a second set of nodal
 *            arrays (what src/mpm/step_fused.c does for lamina);
 *   blocks - the fused pass 64 particles at a time: their updates, then
 *            their scatter;
 *   lanes  - the fused pass four particles at a time in GCC vector
 *            extensions (SSE2 pairs on baseline x86-64, AVX with
 *            -march=x86-64-v3); the scatter stays in particle order;
 *   cells  - two passes over runs of particles in one cell (the disks are
 *            seeded cell by cell): a run's nodal sums in registers, one
 *            update of each node per run, its nodal values loaded once
 *            (reassociated sums: not the same bits; it prints how far its
 *            positions and stresses are from the first form's).
 * Not part of lamina's build. Build and run, beside lamina's bench:
 *   gcc -O3 -ffp-contract=off -o /tmp/loop_ceiling scripts/measure/loop_ceiling.c -lm
 *   /tmp/loop_ceiling 0.005 300
 * prints M particle-steps/s and the state hash of each. dt is 1e-3 at
 * h = 0.005, in proportion at other cells; a run whose points leave the
 * grid stops with a message (checked between the timed steps). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define VL 4
typedef double vd __attribute__((vector_size(8 * VL)));
typedef long long vl __attribute__((vector_size(8 * VL)));

typedef struct prob {
    double h, ih, dt, lam, mu;
    int nx;
    size_t nn, n;
    double *x, *y, *vx, *vy, *m, *V, *sxx, *syy, *sxy;
    double *f[5], *next[5];     /* m, px, py, fx, fy: this step's, the next's */
    double *gax, *gay, *gvx, *gvy;
} prob;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void *zalloc(size_t n)
{
    void *p = calloc(n, sizeof(double));
    if (!p) exit(1);
    return p;
}

static void setup(prob *P, double h)
{
    memset(P, 0, sizeof *P);
    double E = 1000, nu = 0.3, rho0 = 1000;
    /* ref_usl's dt = 1e-3 at h = 0.005 (dt c / h = 0.23), and the same
     * Courant number at other cells: with dt = 1e-3 fixed, h = 0.00224
     * (dt c / h = 0.52) grew unstable within 100 steps and a point left
     * the grid (the scatter then wrote outside the nodal arrays) */
    P->h = h; P->ih = 1 / h; P->dt = 1e-3 * h / 0.005;
    P->lam = E * nu / ((1 + nu) * (1 - 2 * nu));
    P->mu = E / (2 * (1 + nu));
    P->nx = (int)(1.0 / h + 0.5);
    P->nn = (size_t)(P->nx + 1) * (size_t)(P->nx + 1);
    size_t cap = (size_t)(4.0 / (h * h)) + 16;
    double **pa[] = {&P->x, &P->y, &P->vx, &P->vy, &P->m, &P->V, &P->sxx, &P->syy, &P->sxy};
    for (size_t k = 0; k < 9; k++) *pa[k] = zalloc(cap);
    for (int k = 0; k < 5; k++) { P->f[k] = zalloc(P->nn); P->next[k] = zalloc(P->nn); }
    P->gax = zalloc(P->nn); P->gay = zalloc(P->nn); P->gvx = zalloc(P->nn); P->gvy = zalloc(P->nn);
    for (int d = 0; d < 2; d++) {
        double c = d ? 0.75 : 0.25, v = d ? -0.1 : 0.1;
        for (int i = 0; i < P->nx; i++)
            for (int j = 0; j < P->nx; j++)
                for (int a = 0; a < 2; a++)
                    for (int b = 0; b < 2; b++) {
                        double px = (i + 0.25 + 0.5 * a) * h, py = (j + 0.25 + 0.5 * b) * h;
                        if ((px - c) * (px - c) + (py - c) * (py - c) >= 0.04) continue;
                        size_t q = P->n++;
                        P->x[q] = px; P->y[q] = py; P->vx[q] = v; P->vy[q] = v;
                        P->V[q] = h * h / 4; P->m[q] = rho0 * P->V[q];
                    }
    }
}

/* particle q's share of the sums into f */
static inline void scatter_one(const prob *P, size_t q, double *const *f)
{
    double fx = P->x[q] * P->ih, fy = P->y[q] * P->ih;
    int i = (int)fx, j = (int)fy;
    double rx = fx - i, ry = fy - j, ih = P->ih;
    long k = (long)j * (P->nx + 1) + i, c[4] = {k, k + 1, k + P->nx + 1, k + P->nx + 2};
    double N[4] = {(1 - rx) * (1 - ry), rx * (1 - ry), (1 - rx) * ry, rx * ry};
    double Gx[4] = {-(1 - ry) * ih, (1 - ry) * ih, -ry * ih, ry * ih};
    double Gy[4] = {-(1 - rx) * ih, -rx * ih, (1 - rx) * ih, rx * ih};
    double m = P->m[q], V = P->V[q], s1 = P->sxx[q], s2 = P->syy[q], s3 = P->sxy[q];
    for (int a = 0; a < 4; a++) {
        double w = m * N[a];
        f[0][c[a]] += w; f[1][c[a]] += w * P->vx[q]; f[2][c[a]] += w * P->vy[q];
        f[3][c[a]] -= V * (s1 * Gx[a] + s3 * Gy[a]);
        f[4][c[a]] -= V * (s3 * Gx[a] + s2 * Gy[a]);
    }
}

/* the grid update and the nodal values the gather reads */
static void nodes(prob *P)
{
    for (size_t i = 0; i < P->nn; i++) {
        double r = P->f[0][i] > 0 ? 1 / P->f[0][i] : 0;
        P->gax[i] = P->f[3][i] * r;
        P->gay[i] = P->f[4][i] * r;
        P->gvx[i] = (P->f[1][i] + P->dt * P->f[3][i]) * r;
        P->gvy[i] = (P->f[2][i] + P->dt * P->f[4][i]) * r;
    }
}

/* gather, update at particle q */
static inline void update_one(prob *P, size_t q)
{
    double fx = P->x[q] * P->ih, fy = P->y[q] * P->ih, ih = P->ih, dt = P->dt;
    int i = (int)fx, j = (int)fy;
    double rx = fx - i, ry = fy - j;
    long k = (long)j * (P->nx + 1) + i, c[4] = {k, k + 1, k + P->nx + 1, k + P->nx + 2};
    double N[4] = {(1 - rx) * (1 - ry), rx * (1 - ry), (1 - rx) * ry, rx * ry};
    double Gx[4] = {-(1 - ry) * ih, (1 - ry) * ih, -ry * ih, ry * ih};
    double Gy[4] = {-(1 - rx) * ih, -rx * ih, (1 - rx) * ih, rx * ih};
    double ax = 0, ay = 0, ux = 0, uy = 0, l11 = 0, l12 = 0, l21 = 0, l22 = 0;
    for (int a = 0; a < 4; a++) {
        double wx = P->gvx[c[a]], wy = P->gvy[c[a]];
        ax += N[a] * P->gax[c[a]]; ay += N[a] * P->gay[c[a]];
        ux += N[a] * wx; uy += N[a] * wy;
        l11 += wx * Gx[a]; l12 += wx * Gy[a]; l21 += wy * Gx[a]; l22 += wy * Gy[a];
    }
    P->vx[q] += dt * ax; P->vy[q] += dt * ay;
    P->x[q] += dt * ux; P->y[q] += dt * uy;
    double exx = dt * l11, eyy = dt * l22, exy = 0.5 * dt * (l12 + l21);
    P->sxx[q] += P->lam * (exx + eyy) + 2 * P->mu * exx;
    P->syy[q] += P->lam * (exx + eyy) + 2 * P->mu * eyy;
    P->sxy[q] += 2 * P->mu * exy;
    P->V[q] *= 1 + exx + eyy;
}

static void swap_sums(prob *P)
{
    for (int k = 0; k < 5; k++) {
        double *t = P->f[k];
        P->f[k] = P->next[k];
        P->next[k] = t;
        memset(P->next[k], 0, P->nn * sizeof(double));
    }
}

/* Each step works on a local copy of the problem's scalars and pointers:
 * a store through a double pointer could otherwise alias P->dt, P->ih,
 * ..., and the compiler would reload them after every store. */
static void step_passes(prob *G)
{
    prob L = *G, *P = &L;
    for (int k = 0; k < 5; k++) memset(P->f[k], 0, P->nn * sizeof(double));
    for (size_t q = 0; q < P->n; q++) scatter_one(P, q, P->f);
    nodes(P);
    for (size_t q = 0; q < P->n; q++) update_one(P, q);
}

static void step_fused(prob *G)
{
    prob L = *G, *P = &L;
    nodes(P);
    for (size_t q = 0; q < P->n; q++) {
        update_one(P, q);
        scatter_one(P, q, P->next);
    }
    swap_sums(P);
    *G = L;
}

/* the fused pass in blocks of B particles: the block's updates, then its
 * scatter (a load from the gather's arrays never waits behind a store of
 * unknown address to the next sums) */
#define BLOCK 64
static void step_blocks(prob *G)
{
    prob L = *G, *P = &L;
    nodes(P);
    for (size_t q0 = 0; q0 < P->n; q0 += BLOCK) {
        size_t q1 = q0 + BLOCK < P->n ? q0 + BLOCK : P->n;
        for (size_t q = q0; q < q1; q++) update_one(P, q);
        for (size_t q = q0; q < q1; q++) scatter_one(P, q, P->next);
    }
    swap_sums(P);
    *G = L;
}

static inline vd vload(const double *p) { vd v; memcpy(&v, p, sizeof v); return v; }
static inline void vstore(double *p, vd v) { memcpy(p, &v, sizeof v); }

/* the fused pass VL particles at a time: each lane does the scalar pass's
 * operations, the scatter goes lane by lane (particle order) */
static void step_lanes(prob *G)
{
    prob L = *G, *P = &L;
    nodes(P);
    const vd one = (vd){0} + 1, ih = (vd){0} + P->ih, dt = (vd){0} + P->dt;
    const long sx = P->nx + 1, off[4] = {0, 1, sx, sx + 1};
    size_t nv = P->n / VL * VL;
    for (size_t q = 0; q < nv; q += VL) {
        vd X = vload(P->x + q), Y = vload(P->y + q), fx = X * ih, fy = Y * ih;
        vl I = __builtin_convertvector(fx, vl), J = __builtin_convertvector(fy, vl);
        vd rx = fx - __builtin_convertvector(I, vd), ry = fy - __builtin_convertvector(J, vd);
        vl K = J * sx + I;
        vd N[4] = {(one - rx) * (one - ry), rx * (one - ry), (one - rx) * ry, rx * ry};
        vd Gx[4] = {-(one - ry) * ih, (one - ry) * ih, -ry * ih, ry * ih};
        vd Gy[4] = {-(one - rx) * ih, -rx * ih, (one - rx) * ih, rx * ih};
        vd ax = {0}, ay = {0}, ux = {0}, uy = {0}, l11 = {0}, l12 = {0}, l21 = {0}, l22 = {0};
        for (int a = 0; a < 4; a++) {
            vd wx, wy, gx, gy;
            for (int l = 0; l < VL; l++) {
                long c = K[l] + off[a];
                wx[l] = P->gvx[c]; wy[l] = P->gvy[c]; gx[l] = P->gax[c]; gy[l] = P->gay[c];
            }
            ax += N[a] * gx; ay += N[a] * gy;
            ux += N[a] * wx; uy += N[a] * wy;
            l11 += wx * Gx[a]; l12 += wx * Gy[a]; l21 += wy * Gx[a]; l22 += wy * Gy[a];
        }
        vstore(P->vx + q, vload(P->vx + q) + dt * ax);
        vstore(P->vy + q, vload(P->vy + q) + dt * ay);
        vstore(P->x + q, X + dt * ux);
        vstore(P->y + q, Y + dt * uy);
        vd exx = dt * l11, eyy = dt * l22, exy = 0.5 * dt * (l12 + l21);
        vstore(P->sxx + q, vload(P->sxx + q) + (P->lam * (exx + eyy) + 2 * P->mu * exx));
        vstore(P->syy + q, vload(P->syy + q) + (P->lam * (exx + eyy) + 2 * P->mu * eyy));
        vstore(P->sxy + q, vload(P->sxy + q) + 2 * P->mu * exy);
        vstore(P->V + q, vload(P->V + q) * (one + exx + eyy));
        for (int l = 0; l < VL; l++) scatter_one(P, q + (size_t)l, P->next);
    }
    for (size_t q = nv; q < P->n; q++) {
        update_one(P, q);
        scatter_one(P, q, P->next);
    }
    swap_sums(P);
    *G = L;
}

/* two passes as ref_usl, each over runs of particles in one cell: the
 * run's 20 nodal sums in registers and one read-modify-write of each node
 * per run (the scatter); the run's 16 nodal values loaded once (the
 * gather). The sums are reassociated: not the same bits. */
static inline long cell_of(const prob *P, size_t q)
{
    int i = (int)(P->x[q] * P->ih), j = (int)(P->y[q] * P->ih);
    return (long)j * (P->nx + 1) + i;
}

static void step_cells(prob *G)
{
    prob L = *G, *P = &L;
    const double ih = P->ih, dt = P->dt, lam = P->lam, mu = P->mu;
    const long sx = P->nx + 1;
    for (int k = 0; k < 5; k++) memset(P->f[k], 0, P->nn * sizeof(double));
    double *f0 = P->f[0], *f1 = P->f[1], *f2 = P->f[2], *f3 = P->f[3], *f4 = P->f[4];
    for (size_t q = 0; q < P->n;) {
        long k = cell_of(P, q);
        size_t e = q + 1;
        while (e < P->n && cell_of(P, e) == k) e++;
        double x0 = (double)(k % sx), y0 = (double)(k / sx);
        double s[5][4] = {{0}};
        for (; q < e; q++) {
            double rx = P->x[q] * ih - x0, ry = P->y[q] * ih - y0;
            double N[4] = {(1 - rx) * (1 - ry), rx * (1 - ry), (1 - rx) * ry, rx * ry};
            double Gx[4] = {-(1 - ry) * ih, (1 - ry) * ih, -ry * ih, ry * ih};
            double Gy[4] = {-(1 - rx) * ih, -rx * ih, (1 - rx) * ih, rx * ih};
            double m = P->m[q], V = P->V[q], s1 = P->sxx[q], s2 = P->syy[q], s3 = P->sxy[q];
            double vx = P->vx[q], vy = P->vy[q];
            for (int a = 0; a < 4; a++) {
                double w = m * N[a];
                s[0][a] += w; s[1][a] += w * vx; s[2][a] += w * vy;
                s[3][a] -= V * (s1 * Gx[a] + s3 * Gy[a]);
                s[4][a] -= V * (s3 * Gx[a] + s2 * Gy[a]);
            }
        }
        long c[4] = {k, k + 1, k + sx, k + sx + 1};
        for (int a = 0; a < 4; a++) {
            f0[c[a]] += s[0][a]; f1[c[a]] += s[1][a]; f2[c[a]] += s[2][a];
            f3[c[a]] += s[3][a]; f4[c[a]] += s[4][a];
        }
    }
    nodes(P);
    for (size_t q = 0; q < P->n;) {
        long k = cell_of(P, q);
        size_t e = q + 1;
        while (e < P->n && cell_of(P, e) == k) e++;
        double x0 = (double)(k % sx), y0 = (double)(k / sx);
        long c[4] = {k, k + 1, k + sx, k + sx + 1};
        double wx[4], wy[4], gx[4], gy[4];
        for (int a = 0; a < 4; a++) {
            wx[a] = P->gvx[c[a]]; wy[a] = P->gvy[c[a]]; gx[a] = P->gax[c[a]]; gy[a] = P->gay[c[a]];
        }
        for (; q < e; q++) {
            double rx = P->x[q] * ih - x0, ry = P->y[q] * ih - y0;
            double N[4] = {(1 - rx) * (1 - ry), rx * (1 - ry), (1 - rx) * ry, rx * ry};
            double Gx[4] = {-(1 - ry) * ih, (1 - ry) * ih, -ry * ih, ry * ih};
            double Gy[4] = {-(1 - rx) * ih, -rx * ih, (1 - rx) * ih, rx * ih};
            double ax = 0, ay = 0, ux = 0, uy = 0, l11 = 0, l12 = 0, l21 = 0, l22 = 0;
            for (int a = 0; a < 4; a++) {
                ax += N[a] * gx[a]; ay += N[a] * gy[a];
                ux += N[a] * wx[a]; uy += N[a] * wy[a];
                l11 += wx[a] * Gx[a]; l12 += wx[a] * Gy[a]; l21 += wy[a] * Gx[a]; l22 += wy[a] * Gy[a];
            }
            P->vx[q] += dt * ax; P->vy[q] += dt * ay;
            P->x[q] += dt * ux; P->y[q] += dt * uy;
            double exx = dt * l11, eyy = dt * l22, exy = 0.5 * dt * (l12 + l21);
            P->sxx[q] += lam * (exx + eyy) + 2 * mu * exx;
            P->syy[q] += lam * (exx + eyy) + 2 * mu * eyy;
            P->sxy[q] += 2 * mu * exy;
            P->V[q] *= 1 + exx + eyy;
        }
    }
}

static uint64_t hash(const prob *P)
{
    uint64_t h = 1469598103934665603ull;
    const double *f[] = {P->x, P->y, P->vx, P->vy, P->sxx, P->syy, P->sxy, P->V};
    for (int k = 0; k < 8; k++) {
        const unsigned char *b = (const unsigned char *)f[k];
        for (size_t i = 0; i < P->n * sizeof(double); i++) h = (h ^ b[i]) * 1099511628211ull;
    }
    return h;
}

/* Every point inside the grid's cells [0, nx h)^2, where the stencils
 * stay within the nodal arrays? */
static int inside(const prob *P)
{
    double e = P->nx * P->h;
    for (size_t q = 0; q < P->n; q++)
        if (!(P->x[q] >= 0 && P->x[q] < e && P->y[q] >= 0 && P->y[q] < e)) return 0;
    return 1;
}

int main(int argc, char **argv)
{
    double h = argc > 1 ? atof(argv[1]) : 0.005;
    int steps = argc > 2 ? atoi(argv[2]) : 300;
    const char *names[5] = {"passes", "fused", "blocks", "lanes", "cells"};
    void (*fn[5])(prob *) = {step_passes, step_fused, step_blocks, step_lanes, step_cells};
    double *x0 = NULL, *s0 = NULL;   /* the first form's positions and stresses */
    for (int v = 0; v < 5; v++) {
        prob P;
        setup(&P, h);
        if (v > 0 && v < 4)   /* the first step's sums, for the fused passes to take up */
            for (size_t q = 0; q < P.n; q++) scatter_one(&P, q, P.f);
        double t0 = now(), out = 0;   /* out: the checks' time, not the steps' */
        for (int s = 0; s < steps; s++) {
            fn[v](&P);
            double c0 = now();
            if (!inside(&P)) {
                fprintf(stderr, "loop_ceiling: %s: a point left the grid at step %d (h %g, "
                        "dt %g): unstable\n", names[v], s + 1, h, P.dt);
                return 1;
            }
            out += now() - c0;
        }
        double t1 = now() - out;
        double dx = 0, ds = 0, smax = 0;
        if (!x0) {
            x0 = P.x;
            s0 = P.sxx;
        }
        for (size_t q = 0; q < P.n; q++) {
            dx = fmax(dx, fabs(P.x[q] - x0[q]));
            ds = fmax(ds, fabs(P.sxx[q] - s0[q]));
            smax = fmax(smax, fabs(s0[q]));
        }
        printf("%-7s %zu particles %d steps: %.2f M particle-steps/s, state %016llx, "
               "from passes' |dx| %.0e |dsxx| %.0e of %.2g\n", names[v], P.n, steps,
               (double)P.n * steps / (t1 - t0) / 1e6, (unsigned long long)hash(&P), dx, ds, smax);
    }
    return 0;
}
