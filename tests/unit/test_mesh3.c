/* test_mesh3.c - triangle meshes from OBJ and STL files (mesh3.h, issue 34:
 * `lamina.mesh{file}` as a region and a membrane surface; docs/3d.md
 * "Triangle meshes"): the unit cube in OBJ (quads split into fans), a
 * tetrahedron in ASCII and binary STL (vertices merged), their areas,
 * volumes, closedness and inside tests against the solids' own numbers;
 * a mesh sampled into membrane points; and malformed files refused naming
 * the file, the line or triangle and what is wrong. The files are written
 * under the current directory and removed. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "mesh3.h"
#include "mpm3_membrane.h"

static const char *write_file(const char *name, const void *data, size_t len)
{
    FILE *f = fopen(name, "wb");
    CHECK(f != NULL);
    if (!f) return name;
    CHECK(fwrite(data, 1, len, f) == len);
    fclose(f);
    return name;
}

static const char cube_obj[] =
    "# the unit cube, faces wound counter-clockwise seen from outside\n"
    "o cube\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "vn 0 0 -1\n"
    "f 1//1 4//1 3//1 2//1\n"
    "f 5 6 7 8\n"
    "f 1/1 2/1 6/1 5/1\n"
    "f -5 -1 -2 -6\n"      /* 4 8 7 3, by negative indices */
    "f 1 5 8 4\r\n"        /* a CRLF line */
    "f 2 3 7 6\n";

/* The tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), outward. */
static const double tet[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
static const int tet_tri[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

static size_t tet_ascii(char *buf, size_t len)
{
    size_t n = (size_t)snprintf(buf, len, "solid tet\n");
    for (int t = 0; t < 4; t++) {
        n += (size_t)snprintf(buf + n, len - n, "  facet normal 0 0 0\n    outer loop\n");
        for (int k = 0; k < 3; k++) {
            const double *v = tet[tet_tri[t][k]];
            n += (size_t)snprintf(buf + n, len - n, "      vertex %g %g %g\n", v[0], v[1], v[2]);
        }
        n += (size_t)snprintf(buf + n, len - n, "    endloop\n  endfacet\n");
    }
    n += (size_t)snprintf(buf + n, len - n, "endsolid tet\n");
    return n;
}

static void put_f32(unsigned char *p, float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    for (int k = 0; k < 4; k++) p[k] = (unsigned char)(u >> (8 * k));
}

static size_t tet_binary(unsigned char *buf)
{
    memset(buf, 0, 84 + 50 * 4);
    memcpy(buf, "binary tetrahedron", 18);
    buf[80] = 4;
    for (int t = 0; t < 4; t++)
        for (int k = 0; k < 3; k++)
            for (int a = 0; a < 3; a++)
                put_f32(buf + 84 + 50 * t + 12 + 12 * k + 4 * a, (float)tet[tet_tri[t][k]][a]);
    return 84 + 50 * 4;
}

static void good_files(void)
{
    char err[512];
    lm3_mesh m;
    const char *f = write_file("mesh3_cube.obj", cube_obj, sizeof cube_obj - 1);
    CHECK(lm3_mesh_read(f, &m, err, sizeof err) == 0);
    CHECK(m.nv == 8 && m.nt == 12);
    CHECK(lm3_mesh_closed(f, &m, err, sizeof err) == 1);
    CHECK_NEAR(lm3_mesh_area(&m), 6, 1e-15);
    CHECK_NEAR(lm3_mesh_volume6(&m) / 6, 1, 1e-15);
    double in[3] = {0.5, 0.5, 0.5}, in2[3] = {0.99, 0.01, 0.5}, out[3] = {1.01, 0.5, 0.5},
           far[3] = {-3, 7, 2};
    CHECK(lm3_mesh_inside(&m, in) && lm3_mesh_inside(&m, in2));
    CHECK(!lm3_mesh_inside(&m, out) && !lm3_mesh_inside(&m, far));
    /* the cube as a membrane surface: areas sum to 6, normals out */
    lm3_msample s;
    CHECK(lm3_sample_mesh(m.xyz, m.nv, m.tri, m.nt, &s, err, sizeof err) == 0);
    double A = 0;
    for (size_t q = 0; q < s.n; q++) {
        A += s.A[q];
        double n[3] = {s.t1[1][q] * s.t2[2][q] - s.t1[2][q] * s.t2[1][q],
                       s.t1[2][q] * s.t2[0][q] - s.t1[0][q] * s.t2[2][q],
                       s.t1[0][q] * s.t2[1][q] - s.t1[1][q] * s.t2[0][q]};
        double r = (s.x[0][q] - 0.5) * n[0] + (s.x[1][q] - 0.5) * n[1] + (s.x[2][q] - 0.5) * n[2];
        CHECK(r > 0);
    }
    CHECK_NEAR(A, 6, 1e-14);
    CHECK(s.closed);
    lm3_msample_free(&s);
    lm3_mesh_free(&m);
    remove(f);

    char buf[4096];
    size_t n = tet_ascii(buf, sizeof buf);
    f = write_file("mesh3_tet.stl", buf, n);
    CHECK(lm3_mesh_read(f, &m, err, sizeof err) == 0);
    CHECK(m.nv == 4 && m.nt == 4);   /* 12 vertices in the file, merged */
    CHECK(lm3_mesh_closed(f, &m, err, sizeof err) == 1);
    CHECK_NEAR(lm3_mesh_volume6(&m), 1, 1e-15);   /* 1/6 */
    CHECK_NEAR(lm3_mesh_area(&m), 1.5 + sqrt(3) / 2, 1e-15);
    double t_in[3] = {0.2, 0.2, 0.2}, t_out[3] = {0.4, 0.4, 0.4};   /* x + y + z = 1.2 > 1 */
    CHECK(lm3_mesh_inside(&m, t_in) && !lm3_mesh_inside(&m, t_out));
    lm3_mesh_free(&m);
    remove(f);

    unsigned char bin[84 + 50 * 4];
    n = tet_binary(bin);
    f = write_file("mesh3_tet_bin.stl", bin, n);
    CHECK(lm3_mesh_read(f, &m, err, sizeof err) == 0);
    CHECK(m.nv == 4 && m.nt == 4);
    CHECK(lm3_mesh_closed(f, &m, err, sizeof err) == 1);
    CHECK_NEAR(lm3_mesh_volume6(&m), 1, 1e-15);
    lm3_mesh_free(&m);
    remove(f);
}

/* A malformed buffer refused, the message holding every piece of want. */
static void refused(const char *name, const char *text, size_t len, const char *want1,
                    const char *want2)
{
    char err[512] = "";
    lm3_mesh m;
    int rc = lm3_mesh_parse(name, text, len, &m, err, sizeof err);
    CHECK(rc == -1);
    CHECK(m.xyz == NULL && m.tri == NULL && m.nv == 0 && m.nt == 0);
    int ok = strstr(err, want1) && (!want2 || strstr(err, want2));
    if (!ok) fprintf(stderr, "%s: got '%s', wanted '%s' and '%s'\n", name, err, want1,
                     want2 ? want2 : "");
    CHECK(ok);
}

#define REFUSED(name, text, w1, w2) refused(name, text, sizeof text - 1, w1, w2)

static void bad_files(void)
{
    REFUSED("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "a.obj:4", "face corner 3");
    REFUSED("a.obj", "v 0 0 0\nv 1 x 0\n", "a.obj:2", "coordinate 2 is 'x'");
    REFUSED("a.obj", "v 0 0\n", "a.obj:1", "coordinate 3 is missing");
    REFUSED("a.obj", "v 0 0 nan\n", "a.obj:1", "coordinate 3 is 'nan'");
    REFUSED("a.obj", "v 0 0 1e999\n", "a.obj:1", "finite");
    REFUSED("a.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", "a.obj:3", "3 or more corners (got 2)");
    REFUSED("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "a.obj:4", "index 0");
    REFUSED("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", "a.obj:4", "not defined");
    REFUSED("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3x\n", "a.obj:4", "'3x'");
    REFUSED("a.obj", "v 0 0 0\ncurv 1 2\n", "a.obj:2", "unknown OBJ statement 'curv'");
    REFUSED("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n", "a.obj", "triangle 1 repeats");
    REFUSED("a.obj", "# nothing\n", "a.obj", "no triangles");
    REFUSED("a.obj", "", "a.obj", "no triangles");
    REFUSED("b.stl", "solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n"
            " endloop\n", "b.stl:6", "'endloop' where 'vertex' was expected");
    REFUSED("b.stl", "solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n"
            " vertex 0 1\n", "b.stl:6", "'vertex' number 3 is missing");
    REFUSED("b.stl", "solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n"
            " vertex 0 1 0\n endloop\n endfacet\n", "b.stl:8", "without 'endsolid'");
    REFUSED("b.stl", "solid x\n facet 0 0 1\n", "b.stl:2", "where 'facet normal' was expected");
    /* binary: a header counting more triangles than the file holds */
    unsigned char bin[84 + 50 * 4];
    tet_binary(bin);
    refused("c.stl", (const char *)bin, sizeof bin - 50, "c.stl", "not an STL of 84 + 50 n");
    memcpy(bin, "solid binary", 12);
    refused("c.stl", (const char *)bin, sizeof bin - 50, "c.stl", "cannot hold the 4 triangles");
    tet_binary(bin);
    put_f32(bin + 84 + 50 * 2 + 12 + 12 * 1 + 4 * 2, NAN);
    refused("c.stl", (const char *)bin, sizeof bin, "c.stl: triangle 3, vertex 2",
            "coordinate 3 is not a finite number");
    /* a file that is not there */
    char err[512];
    lm3_mesh m;
    CHECK(lm3_mesh_read("mesh3_no_such_file.obj", &m, err, sizeof err) == -1);
    CHECK(strstr(err, "mesh3_no_such_file.obj: cannot open") != NULL);
}

/* An open mesh refused as a region, naming an edge; an inconsistently
 * wound one too. */
static void open_meshes(void)
{
    char err[512];
    lm3_mesh m;
    /* the cube without its top */
    static const char open_cube[] =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
        "f 1 4 3 2\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";
    CHECK(lm3_mesh_parse("open.obj", open_cube, sizeof open_cube - 1, &m, err, sizeof err) == 0);
    CHECK(lm3_mesh_closed("open.obj", &m, err, sizeof err) == 0);
    CHECK(strstr(err, "open.obj is not closed: the edge from vertex") && strstr(err, "in 1 triangle"));
    lm3_mesh_free(&m);
    static const char flipped[] =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
        "f 1 4 3 2\nf 8 7 6 5\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";
    CHECK(lm3_mesh_parse("flip.obj", flipped, sizeof flipped - 1, &m, err, sizeof err) == 0);
    CHECK(lm3_mesh_closed("flip.obj", &m, err, sizeof err) == 0);
    CHECK(strstr(err, "not consistently wound") != NULL);
    lm3_mesh_free(&m);
}

int main(void)
{
    good_files();
    bad_files();
    open_meshes();
    return CHECK_DONE();
}
