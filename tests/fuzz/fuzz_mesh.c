/* fuzz_mesh.c - libFuzzer target: the triangle-mesh reader (mesh3.h: OBJ,
 * ASCII and binary STL, issue 34's lamina.mesh{file}) on arbitrary bytes.
 * Either the parse fails with a message naming the input, or it returns a
 * mesh whose every triangle names three different vertices in range and
 * whose coordinates are finite; its closedness check, inside tests (the
 * solid angles, and the rays through buckets of mesh3_inside.c at its own
 * vertices and centroids, where rays meet edges and vertices), refinement
 * to a third of its longest edge (mesh3_refine.c: as closed as before) and
 * sampling into membrane points then run on it. Anything else, a crash or
 * a sanitizer report is a finding. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_target.h"
#include "mesh3.h"
#include "mpm3_membrane.h"

static int by_set(const void *p, const void *q)
{
    const int32_t *a = p, *b = q;
    for (int k = 0; k < 3; k++)
        if (a[k] != b[k]) return a[k] < b[k] ? -1 : 1;
    return 0;
}

/* Whether two triangles have the same three vertices (a sheet doubled on
 * itself: "closed" by its edges, but refining it makes the corner-cutting
 * edges of both halves coincide, four triangles an edge). */
static int doubled(const lm3_mesh *m)
{
    int32_t *s = malloc(3 * m->nt * sizeof *s);
    if (!s) return 1;
    for (size_t t = 0; t < m->nt; t++) {
        int32_t *v = s + 3 * t;
        memcpy(v, m->tri + 3 * t, 3 * sizeof *v);
        for (int i = 0; i < 2; i++)   /* sorted: the set */
            for (int j = 0; j < 2 - i; j++)
                if (v[j] > v[j + 1]) {
                    int32_t x = v[j];
                    v[j] = v[j + 1];
                    v[j + 1] = x;
                }
    }
    qsort(s, m->nt, 3 * sizeof *s, by_set);
    int d = 0;
    for (size_t t = 1; t < m->nt && !d; t++) d = by_set(s + 3 * (t - 1), s + 3 * t) == 0;
    free(s);
    return d;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[512] = "";
    lm3_mesh m;
    if (lm3_mesh_parse("fuzz.mesh", (const char *)data, size, &m, err, sizeof err) != 0) {
        if (!strstr(err, "fuzz.mesh")) {
            fprintf(stderr, "fuzz_mesh: a refusal not naming the input: %s\n", err);
            abort();
        }
        if (m.xyz || m.tri || m.nv || m.nt) abort();   /* nothing returned */
        return 0;
    }
    if (m.nt == 0 || m.nv == 0) abort();
    for (size_t k = 0; k < 3 * m.nv; k++)
        if (!isfinite(m.xyz[k])) abort();
    for (size_t t = 0; t < m.nt; t++) {
        const int32_t *v = m.tri + 3 * t;
        for (int k = 0; k < 3; k++)
            if (v[k] < 0 || (size_t)v[k] >= m.nv) abort();
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) abort();
    }
    if (m.nt <= 4096) {   /* the quadratic parts kept to small meshes */
        int closed = lm3_mesh_closed("fuzz.mesh", &m, err, sizeof err);
        if (closed == 1) {
            double x[3] = {0.25, 0.5, 0.75};
            (void)lm3_mesh_inside(&m, x);
            lm3_mesh_ray r;
            if (lm3_mesh_ray_build(&m, &r, err, sizeof err) == 0) {
                for (size_t t = 0; t < m.nt && t < 64; t++) {
                    const double *a = m.xyz + 3 * (size_t)m.tri[3 * t],
                                 *b = m.xyz + 3 * (size_t)m.tri[3 * t + 1],
                                 *c = m.xyz + 3 * (size_t)m.tri[3 * t + 2];
                    double g[3] = {(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3,
                                   (a[2] + b[2] + c[2]) / 3};
                    int i1 = lm3_mesh_ray_inside(&r, a), i2 = lm3_mesh_ray_inside(&r, g);
                    if (i1 < -1 || i1 > 1 || i2 < -1 || i2 > 1) abort();
                }
                if (lm3_mesh_ray_inside(&r, x) < -1) abort();
                lm3_mesh_ray_free(&r);
            }
        }
        int k;
        size_t nv, nt;
        double L = 0;
        for (size_t t = 0; t < m.nt; t++)
            for (int c = 0; c < 3; c++) {
                const double *a = m.xyz + 3 * (size_t)m.tri[3 * t + c],
                             *b = m.xyz + 3 * (size_t)m.tri[3 * t + (c + 1) % 3];
                L = fmax(L, fabs(a[0] - b[0]) + fabs(a[1] - b[1]) + fabs(a[2] - b[2]));
            }
        if (L > 0 && isfinite(L) &&
            lm3_mesh_refine_counts(&m, L / 3, 20000, &k, &nv, &nt, err, sizeof err) == 0) {
            lm3_mesh f;
            if (lm3_mesh_refine(&m, L / 3, 20000, &f, err, sizeof err) == 0) {
                if (f.nv != nv || f.nt != nt) abort();
                for (size_t q = 0; q < 3 * f.nt; q++)
                    if (f.tri[q] < 0 || (size_t)f.tri[q] >= f.nv) abort();
                if (closed == 1 && !doubled(&m) &&
                    lm3_mesh_closed("fuzz.mesh", &f, err, sizeof err) != 1)
                    abort();   /* refining keeps a closed mesh closed */
                lm3_mesh_free(&f);
            }
        }
        lm3_msample s;
        if (lm3_sample_mesh(m.xyz, m.nv, m.tri, m.nt, &s, err, sizeof err) == 0)
            lm3_msample_free(&s);
    }
    lm3_mesh_free(&m);
    return 0;
}
