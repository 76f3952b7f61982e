/* test_mesh3_inside.c - the inside test of many points (lm3_mesh_ray,
 * mesh3_inside.c) and the refinement of a mesh to a spacing
 * (lm3_mesh_refine, mesh3_refine.c): what lamina.mesh uses as a region and
 * as a membrane surface (docs/3d.md "Triangle meshes").
 *
 *  1. the unit cube (quads split into fans, so that the faces x = 0, 1
 *     have their diagonals on y = z): rays along y = z and y = 0.5 through
 *     those diagonals, and 20 000 random points, against the box's own
 *     test; the same with the winding reversed;
 *  2. the octahedron |x| + |y| + |z| = 1: rays exactly through its
 *     vertices (y = z = 0) and along its edges (z = 0), against the
 *     closed form; refined to spacings 0.3 and 0.07, 20 000 random points
 *     (more than 1e-9 off the surface) against the solid-angle test
 *     lm3_mesh_inside;
 *  3. the refined octahedron: closed, its area and volume the octahedron's
 *     (4 sqrt 3 and 4/3) to rounding, every edge within the spacing, the
 *     vertex count nv + ne (k - 1) + nt (k - 1)(k - 2) / 2, and its
 *     membrane sample's areas summing to the area;
 *  4. the cost: a sphere of 80 000 triangles (the octahedron cut 100 times,
 *     its vertices pushed onto the sphere), 10^6 points on a lattice asked
 *     row by row as a body's seeding does, against the solid angles at 200
 *     of them (timed, printed; 2000 of the lattice's points checked equal). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "check.h"
#include "mesh3.h"
#include "mpm3_membrane.h"

static const char cube_obj[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                               "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                               "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\n"
                               "f 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

static const char octa_obj[] = "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
                               "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\n"
                               "f 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";

static unsigned long long rng = 88172645463325252ULL;
static double uniform(double a, double b)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return a + (b - a) * (double)(rng >> 11) / 9007199254740992.0;
}

static void parse(const char *name, const char *text, lm3_mesh *m)
{
    char err[300];
    int rc = lm3_mesh_parse(name, text, strlen(text), m, err, sizeof err);
    if (rc != 0) printf("%s\n", err);
    CHECK(rc == 0);
}

static int in_box(const double x[3])
{
    return x[0] > 0 && x[0] < 1 && x[1] > 0 && x[1] < 1 && x[2] > 0 && x[2] < 1;
}

static void reverse(lm3_mesh *m)
{
    for (size_t t = 0; t < m->nt; t++) {
        int32_t a = m->tri[3 * t + 1];
        m->tri[3 * t + 1] = m->tri[3 * t + 2];
        m->tri[3 * t + 2] = a;
    }
}

static void cube(void)
{
    for (int flip = 0; flip < 2; flip++) {
        lm3_mesh m;
        parse("cube.obj", cube_obj, &m);
        if (flip) reverse(&m);
        lm3_mesh_ray r;
        char err[200];
        CHECK(lm3_mesh_ray_build(&m, &r, err, sizeof err) == 0);
        int wrong = 0, n = 0;
        /* rays through the faces' diagonals (y = z) and their midlines */
        const double yz[][2] = {{0.25, 0.25}, {0.5, 0.5}, {0.75, 0.75}, {0.5, 0.25},
                                {0.5, 0.75}, {0.25, 0.5}, {0.5, 1.5}, {-0.5, 0.5}};
        for (size_t k = 0; k < sizeof yz / sizeof *yz; k++)
            for (int i = 0; i < 40; i++) {
                double x[3] = {-0.4875 + 0.05 * i, yz[k][0], yz[k][1]};
                wrong += lm3_mesh_ray_inside(&r, x) != in_box(x);
                n++;
            }
        for (int i = 0; i < 20000; i++) {
            double x[3] = {uniform(-0.5, 1.5), uniform(-0.5, 1.5), uniform(-0.5, 1.5)};
            wrong += lm3_mesh_ray_inside(&r, x) != in_box(x);
            n++;
        }
        printf("cube%s: %d of %d points decided otherwise than the box\n",
               flip ? " (winding reversed)" : "", wrong, n);
        CHECK(wrong == 0);
        lm3_mesh_ray_free(&r);
        lm3_mesh_free(&m);
    }
}

static double l1(const double x[3]) { return fabs(x[0]) + fabs(x[1]) + fabs(x[2]); }

static void octahedron(void)
{
    lm3_mesh m;
    parse("octa.obj", octa_obj, &m);
    lm3_mesh_ray r;
    char err[300];
    CHECK(lm3_mesh_ray_build(&m, &r, err, sizeof err) == 0);
    /* through the vertices (+-1, 0, 0) and along the edges in z = 0 and y = 0 */
    int wrong = 0, n = 0;
    const double yz[][2] = {{0, 0}, {0.5, 0}, {-0.25, 0}, {0, 0.5}, {0, -0.75}};
    for (size_t k = 0; k < sizeof yz / sizeof *yz; k++)
        for (int i = 0; i < 50; i++) {
            double x[3] = {-1.49 + 0.06 * i, yz[k][0], yz[k][1]};
            if (fabs(l1(x) - 1) < 1e-9) continue;
            wrong += lm3_mesh_ray_inside(&r, x) != (l1(x) < 1);
            n++;
        }
    printf("octahedron: rays through vertices and edges: %d of %d wrong\n", wrong, n);
    CHECK(wrong == 0);
    lm3_mesh_ray_free(&r);

    const double area = 4 * sqrt(3.0), volume = 4.0 / 3;
    const double spacings[] = {0.3, 0.07};
    for (int s = 0; s < 2; s++) {
        int k;
        size_t nv, nt;
        CHECK(lm3_mesh_refine_counts(&m, spacings[s], 1000000, &k, &nv, &nt, err, sizeof err) ==
              0);
        lm3_mesh f;
        CHECK(lm3_mesh_refine(&m, spacings[s], 1000000, &f, err, sizeof err) == 0);
        /* the octahedron has 12 edges of length sqrt 2 */
        CHECK(k == (int)ceil(sqrt(2.0) / spacings[s]));
        CHECK(f.nv == nv && f.nt == nt);
        CHECK(nv == 6 + 12 * (size_t)(k - 1) + 8 * (size_t)(k - 1) * (size_t)(k - 2) / 2);
        CHECK(nt == 8 * (size_t)k * (size_t)k);
        CHECK(lm3_mesh_closed("fine", &f, err, sizeof err) == 1);
        double A = lm3_mesh_area(&f), V = lm3_mesh_volume6(&f) / 6, L = 0;
        for (size_t t = 0; t < f.nt; t++)
            for (int c = 0; c < 3; c++) {
                const double *a = f.xyz + 3 * (size_t)f.tri[3 * t + c];
                const double *b = f.xyz + 3 * (size_t)f.tri[3 * t + (c + 1) % 3];
                L = fmax(L, sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                                 (a[2] - b[2]) * (a[2] - b[2])));
            }
        lm3_msample smp;
        CHECK(lm3_sample_mesh(f.xyz, f.nv, f.tri, f.nt, &smp, err, sizeof err) == 0);
        double As = 0;
        for (size_t q = 0; q < smp.n; q++) As += smp.A[q];
        printf("refined to %.2f: k = %d, %zu vertices, %zu triangles, area %.3g off, volume %.3g "
               "off, longest edge %.4g, sample's area %.3g off\n", spacings[s], k, f.nv, f.nt,
               A / area - 1, V / volume - 1, L, As / area - 1);
        CHECK_NEAR(A, area, 1e-12 * area);
        CHECK_NEAR(V, volume, 1e-12);
        CHECK(L <= spacings[s] * (1 + 1e-12));
        CHECK_NEAR(As, area, 1e-12 * area);
        CHECK(smp.closed == 1);
        lm3_msample_free(&smp);

        CHECK(lm3_mesh_ray_build(&f, &r, err, sizeof err) == 0);
        int diff = 0, tried = 0;
        for (int i = 0; i < 20000; i++) {
            double x[3] = {uniform(-1.3, 1.3), uniform(-1.3, 1.3), uniform(-1.3, 1.3)};
            if (i % 4 == 0) x[2] = 0;           /* rays along edges of the fine mesh */
            if (i % 8 == 1) x[1] = x[2] = 0;    /* and through its vertices */
            if (fabs(l1(x) - 1) < 1e-9) continue;
            int a = lm3_mesh_ray_inside(&r, x), b = lm3_mesh_inside(&f, x);
            diff += a != b || a != (l1(x) < 1);
            tried++;
        }
        printf("  %d of %d points decided otherwise than the solid angles and |x|_1 < 1\n", diff,
               tried);
        CHECK(diff == 0);
        lm3_mesh_ray_free(&r);
        lm3_mesh_free(&f);
    }
    /* a spacing that would make too many points is refused before anything */
    int k;
    size_t nv, nt;
    CHECK(lm3_mesh_refine_counts(&m, 1e-4, 1000000, &k, &nv, &nt, err, sizeof err) == -1);
    printf("refused: %s\n", err);
    CHECK(strstr(err, "more than 1000000") != NULL);
    lm3_mesh_free(&m);
}

static double cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }

static void cost(void)
{
    lm3_mesh m, f;
    char err[300];
    parse("octa.obj", octa_obj, &m);
    CHECK(lm3_mesh_refine(&m, sqrt(2.0) / 100, 1000000, &f, err, sizeof err) == 0);
    for (size_t v = 0; v < f.nv; v++) {
        double *x = f.xyz + 3 * v, r = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        for (int a = 0; a < 3; a++) x[a] /= r;
    }
    lm3_mesh_ray r;
    double t0 = cpu();
    CHECK(lm3_mesh_ray_build(&f, &r, err, sizeof err) == 0);
    double t1 = cpu();
    const int N = 100;
    long inside = 0, checked = 0, diff = 0;
    for (int c = 0; c < N; c++)
        for (int b = 0; b < N; b++)
            for (int a = 0; a < N; a++) {
                double x[3] = {-1.1 + 2.2 * (a + 0.5) / N, -1.1 + 2.2 * (b + 0.5) / N,
                               -1.1 + 2.2 * (c + 0.5) / N};
                inside += lm3_mesh_ray_inside(&r, x);
            }
    double t2 = cpu();
    for (int i = 0; i < 200; i++) {
        double x[3] = {uniform(-1.1, 1.1), uniform(-1.1, 1.1), uniform(-1.1, 1.1)};
        (void)lm3_mesh_inside(&f, x);
    }
    double t3 = cpu();
    for (int i = 0; i < 2000; i++) {
        int a = (int)uniform(0, N), b = (int)uniform(0, N), c = (int)uniform(0, N);
        double x[3] = {-1.1 + 2.2 * (a + 0.5) / N, -1.1 + 2.2 * (b + 0.5) / N,
                       -1.1 + 2.2 * (c + 0.5) / N};
        diff += lm3_mesh_ray_inside(&r, x) != lm3_mesh_inside(&f, x);
        checked++;
    }
    printf("cost: %zu triangles, buckets built in %.3g s; 10^6 lattice points in %.3g s (%.3g "
           "us a point, %ld inside: %.4g of the cube, the sphere's share %.4g); solid angles "
           "%.3g ms a point (%.3g s for the lattice); %ld of %ld checked points differ\n",
           f.nt, t1 - t0, t2 - t1, (t2 - t1), inside, (double)inside / (N * N * N),
           4.0 / 3 * 3.14159265358979 / (2.2 * 2.2 * 2.2), (t3 - t2) / 200 * 1e3,
           (t3 - t2) / 200 * 1e6, diff, checked);
    CHECK(diff == 0);
    lm3_mesh_ray_free(&r);
    lm3_mesh_free(&f);
    lm3_mesh_free(&m);
}

int main(void)
{
    cube();
    octahedron();
    cost();
    CHECK_DONE();
}
