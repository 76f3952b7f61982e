/* normals_orient.c - a consistent sign for the normals.
 *
 * grad phi points from the phi = 0 random point's side towards phi = 1 and
 * beyond, so its sign depends on where the random point fell: the paper
 * shows normals "flipped in direction from the majority" ([N] §8, Figs 12
 * and 14) and leaves it there. lamina fixes the sign afterwards, by one of:
 *  - SEQUENCE: each normal agrees (n_p . n_q >= 0) with the last defined
 *    normal before it in point order - for membranes generated in order;
 *  - NEIGHBOURS: no order needed. Starting from the first defined normal,
 *    the not-yet-oriented point nearest to any oriented one is oriented to
 *    agree with that nearest oriented point (Prim's order on distance, as in
 *    Hoppe et al.'s surface reconstruction, 1992); O(n^2), for static sets
 *    and membranes of a few thousand points;
 *  - AWAY: n_p . (x_p - c) >= 0 for a given interior point c (the centre of
 *    a gas-filled membrane).
 * Zero (undefined) normals are skipped. */
#include <math.h>
#include <stdlib.h>

#include "normals.h"
#include "normals_work.h"

static int defined(double *const nrm[3], int dim, size_t i)
{
    for (int a = 0; a < dim; a++)
        if (nrm[a][i] != 0.0)
            return 1;
    return 0;
}

static double dot_nn(double *const nrm[3], int dim, size_t i, size_t j)
{
    double d = 0;
    for (int a = 0; a < dim; a++)
        d += nrm[a][i] * nrm[a][j];
    return d;
}

static void flip(double *const nrm[3], int dim, size_t i)
{
    for (int a = 0; a < dim; a++)
        nrm[a][i] = -nrm[a][i];
}

static double dist2(const double *const x[3], int dim, size_t i, size_t j)
{
    double d = 0;
    for (int a = 0; a < dim; a++)
        d += (x[a][i] - x[a][j]) * (x[a][i] - x[a][j]);
    return d;
}

static void by_sequence(size_t n, int dim, double *const nrm[3])
{
    size_t last = n;
    for (size_t i = 0; i < n; i++) {
        if (!defined(nrm, dim, i))
            continue;
        if (last < n && dot_nn(nrm, dim, i, last) < 0)
            flip(nrm, dim, i);
        last = i;
    }
}

/* d, from and done: n entries of scratch each. */
static void by_neighbours(size_t n, int dim, const double *const x[3],
                          double *const nrm[3], double *d, size_t *from,
                          unsigned char *done)
{
    size_t todo = 0, start = n;
    for (size_t i = 0; i < n; i++) {
        d[i] = INFINITY;
        done[i] = 0;
        if (defined(nrm, dim, i)) {
            todo++;
            if (start == n)
                start = i;
        } else {
            done[i] = 1;
        }
    }
    size_t cur = start;
    while (todo > 0) {
        done[cur] = 1;
        todo--;
        /* relax distances to the newly oriented point, pick the nearest */
        size_t next = n;
        for (size_t i = 0; i < n; i++) {
            if (done[i])
                continue;
            double e = dist2(x, dim, i, cur);
            if (e < d[i]) {
                d[i] = e;
                from[i] = cur;
            }
            if (next == n || d[i] < d[next])
                next = i;
        }
        if (next == n)
            break;
        if (dot_nn(nrm, dim, next, from[next]) < 0)
            flip(nrm, dim, next);
        cur = next;
    }
}

/* by_neighbours in scratch of its own (a call without a workspace). */
static void by_neighbours_alloc(size_t n, int dim, const double *const x[3],
                                double *const nrm[3])
{
    double *d = malloc(sizeof *d * (n ? n : 1));
    size_t *from = malloc(sizeof *from * (n ? n : 1));
    unsigned char *done = malloc(n ? n : 1);
    if (d && from && done)
        by_neighbours(n, dim, x, nrm, d, from, done);
    else                              /* no memory: fall back to order */
        by_sequence(n, dim, nrm);
    free(d);
    free(from);
    free(done);
}

static void away_from(size_t n, int dim, const double *const x[3],
                      double *const nrm[3], const double c[3])
{
    for (size_t i = 0; i < n; i++) {
        double s = 0;
        for (int a = 0; a < dim; a++)
            s += nrm[a][i] * (x[a][i] - c[a]);
        if (s < 0)
            flip(nrm, dim, i);
    }
}

void lm_normals_orient(size_t n, int dim, const double *const x[3],
                       double *const nrm[3], lm_norient how,
                       const double point[3])
{
    lm_normals_orient_ws(n, dim, x, nrm, how, point, NULL);
}

void lm_normals_orient_ws(size_t n, int dim, const double *const x[3],
                          double *const nrm[3], lm_norient how,
                          const double point[3], lm_nwork *w)
{
    switch (how) {
    case LM_NORIENT_SEQUENCE:
        by_sequence(n, dim, nrm);
        break;
    case LM_NORIENT_NEIGHBOURS:
        if (w && w->cap >= n)
            by_neighbours(n, dim, x, nrm, w->dist, w->from, w->done);
        else
            by_neighbours_alloc(n, dim, x, nrm);
        break;
    case LM_NORIENT_AWAY:
        if (point)
            away_from(n, dim, x, nrm, point);
        break;
    case LM_NORIENT_NONE:
        break;
    }
}
