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
 *            -march=x86-64-v3); the scatter stays in particle order.
 * Not part of lamina's build. Build and run, beside lamina's bench:
 *   gcc -O3 -ffp-contract=off -o /tmp/loop_ceiling scripts/measure/loop_ceiling.c -lm
 *   /tmp/loop_ceiling 0.005 300
 * prints M particle-steps/s and the state hash of each. */
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
    P->h = h; P->ih = 1 / h; P->dt = 1e-3;
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

int main(int argc, char **argv)
{
    double h = argc > 1 ? atof(argv[1]) : 0.005;
    int steps = argc > 2 ? atoi(argv[2]) : 300;
    const char *names[4] = {"passes", "fused", "blocks", "lanes"};
    void (*fn[4])(prob *) = {step_passes, step_fused, step_blocks, step_lanes};
    for (int v = 0; v < 4; v++) {
        prob P;
        setup(&P, h);
        if (v > 0)   /* the first step's sums, for the fused passes to take up */
            for (size_t q = 0; q < P.n; q++) scatter_one(&P, q, P.f);
        double t0 = now();
        for (int s = 0; s < steps; s++) fn[v](&P);
        double t1 = now();
        printf("%-7s %zu particles %d steps: %.2f M particle-steps/s, state %016llx\n", names[v],
               P.n, steps, (double)P.n * steps / (t1 - t0) / 1e6,
               (unsigned long long)hash(&P));
    }
    return 0;
}
