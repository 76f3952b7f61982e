/* bench_plain.c - the plain loop `lamina bench engine` holds the engine's
 * step against in the same run (issue 36 item 2: the quadratic B-spline
 * USL step at >= 0.75x this loop, the linear one at >= 1.0x).
 *
 * The problem and the algorithm of shared/bench/ref_usl.c, the issue's
 * yardstick, written here so that the ratio comes out of one process: the
 * two elastic disks of bench engine (radius 0.2 at (0.25, 0.25) and (0.75,
 * 0.75), 2 x 2 points a cell, cell h, velocities +-(0.1, 0.1)), on the
 * bilinear basis, lumped mass, small-strain linear elasticity in plane
 * strain, USL; structure of arrays; the weights made from the place in the
 * cell each pass; one pass scattering mass, momentum and force, a node
 * pass, one pass gathering and updating. No checks, no materials table,
 * no walls: a lower bound on what a step must do. dt is ref_usl's 1e-3 at
 * h = 0.005 and in proportion at other cells (the same Courant number,
 * 0.23: with 1e-3 at every cell the finest sizes grow unstable).
 * Compiled as the engine is (-O3 in the optimised builds,
 * CMakeLists.txt), so that the ratio compares code, not flags. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"

typedef struct plain {
    double h, ih, dt, lam, mu;
    int nx;
    size_t nn, n;
    double *x, *y, *vx, *vy, *m, *V, *sxx, *syy, *sxy;
    double *gm, *gpx, *gpy, *gfx, *gfy;
} plain;

static void plain_free(plain *P)
{
    double *a[] = {P->x, P->y, P->vx, P->vy, P->m, P->V, P->sxx, P->syy, P->sxy,
                   P->gm, P->gpx, P->gpy, P->gfx, P->gfy};
    for (size_t k = 0; k < sizeof a / sizeof a[0]; k++) free(a[k]);
}

/* The disks at cell h: 0, or -1 out of memory. */
static int plain_make(plain *P, double h)
{
    const double E = 1000, nu = 0.3, rho = 1000;
    memset(P, 0, sizeof *P);
    P->h = h;
    P->ih = 1 / h;
    P->dt = 1e-3 * h / 0.005;
    P->lam = E * nu / ((1 + nu) * (1 - 2 * nu));
    P->mu = E / (2 * (1 + nu));
    P->nx = (int)(1 / h + 0.5);
    P->nn = (size_t)(P->nx + 1) * (size_t)(P->nx + 1);
    size_t cap = (size_t)(4 * (double)P->nx * P->nx * 0.26) + 16;   /* 2 pi 0.2^2 of 1 */
    double **pa[] = {&P->x, &P->y, &P->vx, &P->vy, &P->m, &P->V, &P->sxx, &P->syy, &P->sxy};
    for (size_t k = 0; k < sizeof pa / sizeof pa[0]; k++)
        if (!(*pa[k] = calloc(cap, sizeof(double)))) return -1;
    double **ga[] = {&P->gm, &P->gpx, &P->gpy, &P->gfx, &P->gfy};
    for (size_t k = 0; k < sizeof ga / sizeof ga[0]; k++)
        if (!(*ga[k] = calloc(P->nn, sizeof(double)))) return -1;
    for (int d = 0; d < 2; d++) {
        double c = d ? 0.75 : 0.25, v = d ? -0.1 : 0.1;
        for (int i = 0; i < P->nx; i++)
            for (int j = 0; j < P->nx; j++)
                for (int b = 0; b < 2; b++)
                    for (int a = 0; a < 2; a++) {
                        double px = (i + 0.25 + 0.5 * a) * h, py = (j + 0.25 + 0.5 * b) * h;
                        if ((px - c) * (px - c) + (py - c) * (py - c) >= 0.04 || P->n >= cap)
                            continue;
                        size_t q = P->n++;
                        P->x[q] = px;
                        P->y[q] = py;
                        P->vx[q] = P->vy[q] = v;
                        P->V[q] = h * h / 4;
                        P->m[q] = rho * P->V[q];
                    }
    }
    return 0;
}

/* Point q's cell (lower-left node k) and bilinear weights and gradients. */
static inline long plain_weights(const plain *P, size_t q, double N[4], double Gx[4],
                                 double Gy[4])
{
    double fx = P->x[q] * P->ih, fy = P->y[q] * P->ih;
    int i = (int)fx, j = (int)fy;
    double rx = fx - i, ry = fy - j, ih = P->ih;
    N[0] = (1 - rx) * (1 - ry);
    N[1] = rx * (1 - ry);
    N[2] = (1 - rx) * ry;
    N[3] = rx * ry;
    Gx[0] = -(1 - ry) * ih;
    Gx[1] = (1 - ry) * ih;
    Gx[2] = -ry * ih;
    Gx[3] = ry * ih;
    Gy[0] = -(1 - rx) * ih;
    Gy[1] = -rx * ih;
    Gy[2] = (1 - rx) * ih;
    Gy[3] = rx * ih;
    return (long)j * (P->nx + 1) + i;
}

/* One USL step. Works on a copy of the problem's scalars and pointers (a
 * store through a double pointer could alias them otherwise, and the
 * compiler would reload them after each store). */
static void plain_step(const plain *G)
{
    const plain L = *G, *P = &L;
    const long s = P->nx + 1;
    const double dt = P->dt;
    size_t bytes = P->nn * sizeof(double);
    memset(P->gm, 0, bytes);
    memset(P->gpx, 0, bytes);
    memset(P->gpy, 0, bytes);
    memset(P->gfx, 0, bytes);
    memset(P->gfy, 0, bytes);
    for (size_t q = 0; q < P->n; q++) {
        double N[4], Gx[4], Gy[4];
        long k = plain_weights(P, q, N, Gx, Gy);
        const long c[4] = {k, k + 1, k + s, k + s + 1};
        const double m = P->m[q], V = P->V[q], vx = P->vx[q], vy = P->vy[q];
        const double sxx = P->sxx[q], syy = P->syy[q], sxy = P->sxy[q];
        for (int a = 0; a < 4; a++) {
            double w = m * N[a];
            P->gm[c[a]] += w;
            P->gpx[c[a]] += w * vx;
            P->gpy[c[a]] += w * vy;
            P->gfx[c[a]] -= V * (sxx * Gx[a] + sxy * Gy[a]);
            P->gfy[c[a]] -= V * (sxy * Gx[a] + syy * Gy[a]);
        }
    }
    for (size_t i = 0; i < P->nn; i++)
        if (P->gm[i] > 0) {
            P->gpx[i] += dt * P->gfx[i];
            P->gpy[i] += dt * P->gfy[i];
        }
    for (size_t q = 0; q < P->n; q++) {
        double N[4], Gx[4], Gy[4];
        long k = plain_weights(P, q, N, Gx, Gy);
        const long c[4] = {k, k + 1, k + s, k + s + 1};
        double ax = 0, ay = 0, ux = 0, uy = 0, l11 = 0, l12 = 0, l21 = 0, l22 = 0;
        for (int a = 0; a < 4; a++) {
            double mi = P->gm[c[a]];
            if (!(mi > 0)) continue;
            double wx = P->gpx[c[a]] / mi, wy = P->gpy[c[a]] / mi;
            ax += N[a] * dt * P->gfx[c[a]] / mi;
            ay += N[a] * dt * P->gfy[c[a]] / mi;
            ux += N[a] * wx;
            uy += N[a] * wy;
            l11 += wx * Gx[a];
            l12 += wx * Gy[a];
            l21 += wy * Gx[a];
            l22 += wy * Gy[a];
        }
        P->vx[q] += ax;
        P->vy[q] += ay;
        P->x[q] += dt * ux;
        P->y[q] += dt * uy;
        double exx = dt * l11, eyy = dt * l22, exy = 0.5 * dt * (l12 + l21);
        P->sxx[q] += P->lam * (exx + eyy) + 2 * P->mu * exx;
        P->syy[q] += P->lam * (exx + eyy) + 2 * P->mu * eyy;
        P->sxy[q] += 2 * P->mu * exy;
        P->V[q] *= 1 + exx + eyy;
    }
}

static double clock_s(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double bench_plain_rate(double particles, double work, size_t *np, double *cpu_rate)
{
    /* bench engine's disks: about 1.005 / h^2 particles */
    double h = sqrt(1.005 / particles), secs = 0, cpu = 0, done = 0;
    while (done < work) {
        plain P;
        if (plain_make(&P, h) != 0) {
            plain_free(&P);
            return -1;
        }
        *np = P.n;
        /* rebuilt before t = 0.8, as bench engine's disks (they meet near
         * t = 1.1) */
        long steps = (long)fmin(fmax(10, (work - done) / (double)P.n), 0.8 / P.dt);
        plain_step(&P);   /* warm-up */
        double t0 = clock_s(CLOCK_MONOTONIC), c0 = clock_s(CLOCK_PROCESS_CPUTIME_ID);
        for (long k = 0; k < steps; k++) plain_step(&P);
        secs += clock_s(CLOCK_MONOTONIC) - t0;
        cpu += clock_s(CLOCK_PROCESS_CPUTIME_ID) - c0;
        done += (double)P.n * (double)steps;
        plain_free(&P);
    }
    *cpu_rate = done / cpu;
    return done / secs;
}
