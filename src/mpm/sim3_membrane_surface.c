/* sim3_membrane_surface.c - surfaces sampled into membrane points, each
 * with its area and a tangent frame (mpm3_membrane.h, docs/3d.md "3D
 * membranes"): the sphere, the parallelogram and the triangle mesh. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "edge_order.h"
#include "mpm3_membrane.h"
#include "util.h"

/* pi, as C99 gives no pi under _POSIX_C_SOURCE */
static const double pi = 3.14159265358979323846;

void lm3_msample_free(lm3_msample *s)
{
    if (!s) return;
    LU_FREE_ALL(s->x[0], s->x[1], s->x[2], s->A, s->t1[0], s->t1[1], s->t1[2], s->t2[0],
                s->t2[1], s->t2[2]);
    memset(s, 0, sizeof *s);
}

static int alloc(lm3_msample *s, size_t n, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    if (n == 0 || n > LM_MAX_PARTICLES) {
        snprintf(err, errlen, "the surface would have %zu points (1 to %d)", n,
                 LM_MAX_PARTICLES);
        return -1;
    }
    double **arr[] = {&s->x[0], &s->x[1], &s->x[2], &s->A, &s->t1[0], &s->t1[1],
                      &s->t1[2], &s->t2[0], &s->t2[1], &s->t2[2]};
    for (size_t k = 0; k < sizeof arr / sizeof *arr; k++) {
        *arr[k] = calloc(n, sizeof(double));
        if (!*arr[k]) {
            lm3_msample_free(s);
            snprintf(err, errlen, "out of memory for %zu surface points", n);
            return -1;
        }
    }
    s->n = n;
    return 0;
}

static int finite3(const double a[3])
{
    return isfinite(a[0]) && isfinite(a[1]) && isfinite(a[2]);
}

static double norm3(const double a[3])
{
    return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

static void cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static void set_point(lm3_msample *s, size_t k, const double x[3], double A, const double t1[3],
                      const double t2[3])
{
    for (int a = 0; a < 3; a++) {
        s->x[a][k] = x[a];
        s->t1[a][k] = t1[a];
        s->t2[a][k] = t2[a];
    }
    s->A[k] = A;
}

int lm3_sample_sphere(const double c[3], double r, double spacing, lm3_msample *s, char *err,
                      size_t errlen)
{
    if (!finite3(c) || !(r > 0) || !isfinite(r)) {
        snprintf(err, errlen, "sphere: radius = %g must be a positive number (centre finite)",
                 r);
        return -1;
    }
    if (!(spacing > 0) || !isfinite(spacing)) {
        snprintf(err, errlen, "spacing = %g: must be a positive number", spacing);
        return -1;
    }
    double area = 4 * pi * r * r, count = floor(area / (spacing * spacing) + 0.5);
    if (count > LM_MAX_PARTICLES) count = (double)LM_MAX_PARTICLES + 1;   /* refused below */
    size_t n = count < 12 ? 12 : (size_t)count;
    if (alloc(s, n, err, errlen) != 0) return -1;
    /* the golden angle pi (3 - sqrt 5): successive points as far apart in
     * azimuth as an irrational turn allows (Gonzalez 2010) */
    const double golden = pi * (3 - sqrt(5.0));
    for (size_t k = 0; k < n; k++) {
        double z = 1 - (2.0 * (double)k + 1) / (double)n, rho = sqrt(fmax(0, 1 - z * z));
        double phi = golden * (double)k, cp = cos(phi), sp = sin(phi);
        double nrm[3] = {rho * cp, rho * sp, z};
        double x[3] = {c[0] + r * nrm[0], c[1] + r * nrm[1], c[2] + r * nrm[2]};
        double t1[3] = {-sp, cp, 0}, t2[3];   /* e_phi: |z| < 1, never at a pole */
        cross3(nrm, t1, t2);                  /* -e_theta: t1 x t2 = n, outward */
        set_point(s, k, x, area / (double)n, t1, t2);
    }
    s->closed = 1;
    return 0;
}

int lm3_sample_rect3(const double origin[3], const double u[3], const double v[3],
                     double spacing, lm3_msample *s, char *err, size_t errlen)
{
    if (!finite3(origin) || !finite3(u) || !finite3(v)) {
        snprintf(err, errlen, "rect3: origin, u and v must be finite");
        return -1;
    }
    if (!(spacing > 0) || !isfinite(spacing)) {
        snprintf(err, errlen, "spacing = %g: must be a positive number", spacing);
        return -1;
    }
    double lu = norm3(u), w[3];
    cross3(u, v, w);
    double area = norm3(w);
    if (!(lu > 0) || !(area > 1e-12 * lu * norm3(v))) {
        snprintf(err, errlen, "rect3: u and v span no parallelogram (|u x v| = %g)", area);
        return -1;
    }
    double t1[3] = {u[0] / lu, u[1] / lu, u[2] / lu}, vp[3], t2[3];
    double vu = v[0] * t1[0] + v[1] * t1[1] + v[2] * t1[2];
    for (int a = 0; a < 3; a++) vp[a] = v[a] - vu * t1[a];
    double lvp = norm3(vp);
    for (int a = 0; a < 3; a++) t2[a] = vp[a] / lvp;
    double fu = ceil(lu / spacing - 1e-9), fv = ceil(lvp / spacing - 1e-9);
    if (fu * fv > LM_MAX_PARTICLES) {
        snprintf(err, errlen, "rect3: spacing %g gives %g points (more than %d)", spacing,
                 fu * fv, LM_MAX_PARTICLES);
        return -1;
    }
    size_t nu = fu < 1 ? 1 : (size_t)fu, nv = fv < 1 ? 1 : (size_t)fv;
    if (alloc(s, nu * nv, err, errlen) != 0) return -1;
    for (size_t j = 0; j < nv; j++)
        for (size_t i = 0; i < nu; i++) {
            double a = ((double)i + 0.5) / (double)nu, b = ((double)j + 0.5) / (double)nv;
            double x[3];
            for (int c = 0; c < 3; c++) x[c] = origin[c] + a * u[c] + b * v[c];
            set_point(s, j * nu + i, x, area / (double)(nu * nv), t1, t2);
        }
    s->closed = 0;
    return 0;
}

/* ---- triangle meshes ------------------------------------------------------ */

typedef struct edge { int32_t a, b; } edge;

static int edge_cmp(const void *p, const void *q)
{
    const edge *x = p, *y = q;
    return lm_edge_order(x->a, x->b, y->a, y->b);
}

/* Closed: every undirected edge in exactly two triangles. */
static int mesh_closed(const int32_t *tri, size_t nt, int *oom)
{
    *oom = 0;
    edge *e = malloc(3 * nt * sizeof *e);
    if (!e) {
        *oom = 1;
        return 0;
    }
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++) e[3 * t + k] = (edge){tri[3 * t + k], tri[3 * t + (k + 1) % 3]};
    qsort(e, 3 * nt, sizeof *e, edge_cmp);
    int closed = 1;
    for (size_t k = 0; k < 3 * nt && closed;) {
        size_t j = k + 1;
        while (j < 3 * nt && edge_cmp(&e[k], &e[j]) == 0) j++;
        if (j - k != 2) closed = 0;
        k = j;
    }
    free(e);
    return closed;
}

int lm3_sample_mesh(const double *xyz, size_t nv, const int32_t *tri, size_t nt,
                    lm3_msample *s, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    if (nv == 0 || nt == 0 || nv > LM_MAX_PARTICLES || nt > 4 * (size_t)LM_MAX_PARTICLES) {
        snprintf(err, errlen, "mesh: %zu vertices and %zu triangles (need some, at most %d "
                 "vertices)", nv, nt, LM_MAX_PARTICLES);
        return -1;
    }
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++)
            if (tri[3 * t + k] < 0 || (size_t)tri[3 * t + k] >= nv) {
                snprintf(err, errlen, "mesh: triangle %zu names vertex %d (there are %zu)",
                         t + 1, (int)tri[3 * t + k] + 1, nv);
                return -1;
            }
    double *acc = calloc(7 * nv, sizeof(double));   /* area, normal (3), first edge (3) */
    if (!acc) {
        snprintf(err, errlen, "out of memory for a mesh of %zu vertices", nv);
        return -1;
    }
    double vol6 = 0;
    for (size_t t = 0; t < nt; t++) {
        const double *p[3];
        for (int k = 0; k < 3; k++) p[k] = xyz + 3 * (size_t)tri[3 * t + k];
        double e1[3], e2[3], c[3];
        for (int a = 0; a < 3; a++) {
            e1[a] = p[1][a] - p[0][a];
            e2[a] = p[2][a] - p[0][a];
        }
        cross3(e1, e2, c);
        double A = 0.5 * norm3(c);
        if (!(A > 0) || !isfinite(A)) {
            free(acc);
            snprintf(err, errlen, "mesh: triangle %zu (vertices %d, %d, %d) has no area", t + 1,
                     (int)tri[3 * t] + 1, (int)tri[3 * t + 1] + 1, (int)tri[3 * t + 2] + 1);
            return -1;
        }
        /* signed volume of the tetrahedron (0, p0, p1, p2), times 6 */
        vol6 += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
                p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
        for (int k = 0; k < 3; k++) {
            size_t i = (size_t)tri[3 * t + k];
            const double *q = xyz + 3 * (size_t)tri[3 * t + (k + 1) % 3];
            acc[7 * i] += A / 3;
            for (int a = 0; a < 3; a++) acc[7 * i + 1 + a] += 0.5 * c[a];   /* area-weighted */
            if (acc[7 * i + 4] == 0 && acc[7 * i + 5] == 0 && acc[7 * i + 6] == 0)
                for (int a = 0; a < 3; a++) acc[7 * i + 4 + a] = q[a] - xyz[3 * i + a];
        }
    }
    for (size_t i = 0; i < nv; i++)
        if (acc[7 * i] == 0) {
            free(acc);
            snprintf(err, errlen, "mesh: vertex %zu is in no triangle", i + 1);
            return -1;
        }
    int oom, closed = mesh_closed(tri, nt, &oom);
    double flip = closed && vol6 < 0 ? -1 : 1;
    if (oom || alloc(s, nv, err, errlen) != 0) {
        free(acc);
        if (oom) snprintf(err, errlen, "out of memory for a mesh of %zu triangles", nt);
        return -1;
    }
    for (size_t i = 0; i < nv; i++) {
        double n[3] = {flip * acc[7 * i + 1], flip * acc[7 * i + 2], flip * acc[7 * i + 3]};
        double ln = norm3(n);
        if (!(ln > 0)) {
            free(acc);
            lm3_msample_free(s);
            snprintf(err, errlen, "mesh: the triangles around vertex %zu cancel (no normal)",
                     i + 1);
            return -1;
        }
        for (int a = 0; a < 3; a++) n[a] /= ln;
        double *e = acc + 7 * i + 4, en = e[0] * n[0] + e[1] * n[1] + e[2] * n[2], t1[3], t2[3];
        for (int a = 0; a < 3; a++) t1[a] = e[a] - en * n[a];
        double l1 = norm3(t1);
        if (!(l1 > 1e-9 * norm3(e))) {
            /* the first edge along the normal (a spike): any direction
             * across n, from the axis n is least along */
            int k = fabs(n[0]) <= fabs(n[1]) && fabs(n[0]) <= fabs(n[2]) ? 0
                    : fabs(n[1]) <= fabs(n[2])                          ? 1
                                                                          : 2;
            double ax[3] = {0, 0, 0};
            ax[k] = 1;
            cross3(ax, n, t1);
            l1 = norm3(t1);
        }
        for (int a = 0; a < 3; a++) t1[a] /= l1;
        cross3(n, t1, t2);
        set_point(s, i, xyz + 3 * i, acc[7 * i], t1, t2);
    }
    free(acc);
    s->closed = closed;
    return 0;
}
