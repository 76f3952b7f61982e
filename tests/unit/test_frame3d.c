/* test_frame3d.c - 3D frames (src/render/include/frame3d.h, issue 34
 * item 4) of a 3D run built through mpm3.h: particles by speed and by
 * body, a membrane's points and normals, the phi = 1 isosurface, a slice
 * of a scalar, two cameras, panels and colour bars.
 *
 *   - the isosurface of phi = |x - c| / R against the sphere: every
 *     vertex within the interpolation error of radius R, its area against
 *     4 pi R^2;
 *   - depth: of two particles on one line of sight the nearer is seen,
 *     whatever order they were given in (OpenGL and cairo's painter's
 *     sort);
 *   - the camera: the target at the panel's centre; perspective makes the
 *     near end of a bar longer than the far one; `distance` zooms;
 *   - a slice of a uniform field shows the colour map's colour there;
 *   - a particle below a slice is hidden by it, above it is not (OpenGL:
 *     the splats' depth meets the triangles'; cairo: painter's sort);
 *   - every backend here draws the same figure to the same bytes twice
 *     (written to out/frame3d_*.png to be looked at).
 *
 * `test_frame3d baselines DIR [--update]` compares a small figure per
 * backend with tests/unit/baselines/frame3d_BACKEND.png (test
 * unit.frame3d_baselines). `test_frame3d bench [n [backend]]` times n (10^6) particles a frame per
 * backend
 * (docs/performance.md "3D frames"). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "check.h"
#include "diff.h"
#include "frame3d.h"
#include "mpm3.h"
#include "render.h"

#define PI 3.14159265358979323846

static lm3_sim *make_sim(void)
{
    lm3_def d;
    memset(&d, 0, sizeof d);
    for (int a = 0; a < 3; a++) {
        d.lo[a] = 0;
        d.hi[a] = 1;
    }
    d.cell = 0.1;
    d.dt = 1e-4;
    d.basis = LM_BASIS_LINEAR;
    d.scheme = LM_MUSL;
    char err[256];
    lm3_sim *s = lm3_sim_create(&d, err, sizeof err);
    if (!s) {
        fprintf(stderr, "lm3_sim_create: %s\n", err);
        return NULL;
    }
    lm3_material m = {.rho = 1000, .E = 1e6, .nu = 0.3, .kind = LM3_ELASTIC};
    int k = lm3_material_add(s, &m, err, sizeof err);
    const double lo[3] = {0.2, 0.2, 0.1}, hi[3] = {0.8, 0.5, 0.4};
    const double lo2[3] = {0.3, 0.6, 0.5}, hi2[3] = {0.6, 0.9, 0.8};
    const double v0[3] = {0, 0, 0};
    CHECK(lm3_seed_box(s, k, lo, hi, 2, v0) > 0);
    CHECK(lm3_seed_box(s, k, lo2, hi2, 2, v0) > 0);
    /* a velocity field to colour by: a rotation about the box's axis */
    for (size_t i = 0; i < s->p.n; i++) {
        s->p.v[0][i] = -(s->p.x[1][i] - 0.5);
        s->p.v[1][i] = s->p.x[0][i] - 0.5;
        s->p.v[2][i] = 0.2 * s->p.x[2][i];
    }
    return s;
}

/* phi = |x - c| / R at the nodes of a grid of n nodes a side over [0, 1]^3 */
static double *sphere_phi(int n, const double c[3], double R, lr_grid3d *g)
{
    double *f = malloc((size_t)n * n * n * sizeof *f);
    for (int k = 0; k < n; k++)
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                double h = 1.0 / (n - 1);
                double d[3] = {i * h - c[0], j * h - c[1], k * h - c[2]};
                f[((size_t)k * n + j) * n + i] =
                    sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / R;
            }
    memset(g, 0, sizeof *g);
    g->f = f;
    for (int a = 0; a < 3; a++) {
        g->n[a] = n;
        g->lo[a] = 0;
        g->h[a] = 1.0 / (n - 1);
    }
    return f;
}

static void test_iso(void)
{
    const double c[3] = {0.47, 0.52, 0.5}, R = 0.3;
    for (int n = 21; n <= 41; n += 20) {
        lr_grid3d g;
        double *f = sphere_phi(n, c, R, &g);
        double *xyz, *nrm;
        size_t nt;
        CHECK(lr_iso_triangles(&g, 1.0, &xyz, &nrm, &nt) == 0);
        double h = 1.0 / (n - 1), worst = 0, area = 0, worst_n = 0;
        for (size_t k = 0; k < nt; k++) {
            double *p = xyz + 9 * k;
            for (int j = 0; j < 3; j++) {
                double d[3] = {p[3 * j] - c[0], p[3 * j + 1] - c[1], p[3 * j + 2] - c[2]};
                double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                worst = fmax(worst, fabs(r - R));
                double *q = nrm + 9 * k + 3 * j;
                double cosang = (q[0] * d[0] + q[1] * d[1] + q[2] * d[2]) / r;
                worst_n = fmax(worst_n, acos(fmin(1.0, cosang)) * 180 / PI);
            }
            double u[3], v[3], w[3];
            for (int a = 0; a < 3; a++) {
                u[a] = p[3 + a] - p[a];
                v[a] = p[6 + a] - p[a];
            }
            w[0] = u[1] * v[2] - u[2] * v[1];
            w[1] = u[2] * v[0] - u[0] * v[2];
            w[2] = u[0] * v[1] - u[1] * v[0];
            area += 0.5 * sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        }
        /* phi is linear along an edge only approximately: the chord's
         * sag, at most h^2 / (8 R) for an edge of length h (sqrt(3) h on
         * the tetrahedra's diagonals: 3 h^2 / (8 R)) */
        double sag = 3 * h * h / (8 * R);
        double rel = area / (4 * PI * R * R) - 1;
        printf("iso: %d^3 nodes, h = %.4f: %zu triangles, |r - R| <= %.3g (bound %.3g), "
               "area %+.3f %%, normals within %.2f deg of radial\n",
               n, h, nt, worst, sag, 100 * rel, worst_n);
        CHECK(nt > 100);
        CHECK(worst <= sag);
        /* the area of an inscribed triangulation falls short by O(h^2);
         * measured: -0.72 % at h = 0.05, -0.18 % at h = 0.025 */
        CHECK(rel < 0 && rel > (n == 21 ? -0.015 : -0.004));
        CHECK(worst_n < (n == 21 ? 3.0 : 1.5));
        free(xyz);
        free(nrm);
        free(f);
    }
}

/* ---- figures --------------------------------------------------------------- */

typedef struct demo {
    lm3_sim *sim;
    double *speed;
    int *group;
    lr_grid3d phi, pressure;
    double *phi_f, *p_f;
    double *mx, *my, *mz, *mnx, *mny, *mnz;
    size_t mn;
    lr_cloud3d cloud[2];
    lr_membrane3d mem;
    lr_iso3d iso;
    lr_slice3d slice;
    lr_panel3d panels[2];
    lr_figure3d fig;
} demo;

static void demo_build(demo *d, lr_backend b)
{
    memset(d, 0, sizeof *d);
    d->sim = make_sim();
    lm3_sim *s = d->sim;
    size_t n = s->p.n;
    d->speed = malloc(n * sizeof *d->speed);
    d->group = malloc(n * sizeof *d->group);
    for (size_t i = 0; i < n; i++) {
        d->speed[i] = sqrt(s->p.v[0][i] * s->p.v[0][i] + s->p.v[1][i] * s->p.v[1][i] +
                           s->p.v[2][i] * s->p.v[2][i]);
        d->group[i] = s->p.x[2][i] > 0.45;
    }
    /* a membrane: points on a sphere (a Fibonacci lattice), normals radial */
    const double c[3] = {0.5, 0.5, 0.55}, R = 0.22;
    d->mn = 600;
    double *m = malloc(6 * d->mn * sizeof *m);
    d->mx = m;
    d->my = m + d->mn;
    d->mz = m + 2 * d->mn;
    d->mnx = m + 3 * d->mn;
    d->mny = m + 4 * d->mn;
    d->mnz = m + 5 * d->mn;
    for (size_t i = 0; i < d->mn; i++) {
        double z = 1 - 2 * (i + 0.5) / d->mn, r = sqrt(1 - z * z);
        double t = PI * (3 - sqrt(5.0)) * i;
        d->mnx[i] = r * cos(t);
        d->mny[i] = r * sin(t);
        d->mnz[i] = z;
        d->mx[i] = c[0] + R * d->mnx[i];
        d->my[i] = c[1] + R * d->mny[i];
        d->mz[i] = c[2] + R * d->mnz[i];
    }
    d->phi_f = sphere_phi(31, c, R, &d->phi);
    /* a "pressure": higher inside the sphere, falling off */
    d->p_f = sphere_phi(31, c, R, &d->pressure);
    for (size_t i = 0; i < 31 * 31 * 31; i++)
        d->p_f[i] = 1e5 * (1 + 0.3 * exp(-d->p_f[i] * d->p_f[i]));

    d->cloud[0] = (lr_cloud3d){n, s->p.x[0], s->p.x[1], s->p.x[2], d->speed, NULL, 2.5};
    d->cloud[1] = (lr_cloud3d){n, s->p.x[0], s->p.x[1], s->p.x[2], NULL, d->group, 2.5};
    d->mem = (lr_membrane3d){d->mn, d->mx, d->my, d->mz, d->mnx, d->mny, d->mnz, NULL,
                             {0.1, 0.1, 0.1, 1}, 2.0, sqrt(4 * PI * R * R / d->mn), 18.0,
                             {0.0, 0.447, 0.698, 1}};
    d->iso = (lr_iso3d){d->phi, 1.0, {0.85, 0.55, 0.35, 0.45}};
    d->slice = (lr_slice3d){d->pressure, 1, 0.55, LR_CMAP_VIRIDIS, 0, 0, 1, "pressure",
                            0};
    lr_panel3d *p = d->panels;
    for (int k = 0; k < 2; k++) {
        for (int a = 0; a < 3; a++) {
            p[k].lo[a] = 0;
            p[k].hi[a] = 1;
        }
        p[k].box = 1;
        p[k].camera.azimuth = -60;
        p[k].camera.elevation = 25;
    }
    p[0].clouds = &d->cloud[0];
    p[0].nclouds = 1;
    p[0].membranes = &d->mem;
    p[0].nmembranes = 1;
    p[0].isos = &d->iso;
    p[0].nisos = 1;
    p[0].title = "speed, membrane, phi = 1";
    p[0].cmap = LR_CMAP_VIRIDIS;
    p[0].colourbar = 1;
    p[0].colourbar_label = "speed";
    p[1].clouds = &d->cloud[1];
    p[1].nclouds = 1;
    p[1].slices = &d->slice;
    p[1].nslices = 1;
    p[1].camera.fov = 40;
    p[1].camera.azimuth = -30;
    p[1].title = "bodies, pressure slice (perspective)";
    d->fig = (lr_figure3d){900, 460, b, d->panels, 2, 0, 0, "3D frame", "t = 0.0000   step 0",
                           NULL, 0};
}

static void demo_free(demo *d)
{
    lm3_sim_free(d->sim);
    free(d->speed);
    free(d->group);
    free(d->mx);
    free(d->phi_f);
    free(d->p_f);
}

static int backend_ok(lr_backend b)
{
    char err[256];
    return lr_backend_check(b, err, sizeof err) == 0;
}

static void test_figure(lr_backend b)
{
    demo d;
    demo_build(&d, b);
    char err[512] = "", path[96];
    unsigned char *one = lr_figure3d_render(&d.fig, err, sizeof err);
    unsigned char *two = lr_figure3d_render(&d.fig, err, sizeof err);
    if (!one || !two)
        fprintf(stderr, "%s: %s\n", lr_backend_name(b), err);
    CHECK(one && two);
    if (one && two) {
        size_t bytes = 4 * (size_t)d.fig.width * d.fig.height;
        CHECK(memcmp(one, two, bytes) == 0);
        /* something of every layer is drawn: not a blank panel */
        size_t ink = 0;
        for (size_t i = 0; i < bytes; i += 4)
            ink += one[i] < 200 || one[i + 1] < 200 || one[i + 2] < 200;
        printf("%s: %zu pixels not white of %d\n", lr_backend_name(b), ink,
               d.fig.width * d.fig.height);
        CHECK(ink > 40000);
    }
    mkdir("out", 0777);
    snprintf(path, sizeof path, "out/frame3d_%s.png", lr_backend_name(b));
    CHECK(lr_figure3d_write(&d.fig, path, err, sizeof err) == 0);
    free(one);
    free(two);
    demo_free(&d);
}

/* ---- depth, camera, slice colours ------------------------------------------ */

static unsigned char *draw_one(lr_backend b, const lr_panel3d *p, int W, int H)
{
    lr_figure3d f = {W, H, b, p, 1, 0, 0, NULL, NULL, NULL, 0};
    char err[256] = "";
    unsigned char *img = lr_figure3d_render(&f, err, sizeof err);
    if (!img)
        fprintf(stderr, "%s: %s\n", lr_backend_name(b), err);
    CHECK(img != NULL);
    return img;
}

/* The panel's view as lr_figure3d_draw makes it (one panel, no text). */
static void panel_view(const lr_panel3d *p, int W, int H, lr_view *v)
{
    double m = 0.04 * (W < H ? W : H);
    lr_camera3d_view(v, &p->camera, m, m, W - 2 * m, H - 2 * m, p->lo, p->hi);
}

static void test_depth(lr_backend b)
{
    enum { W = 200, H = 200 };
    lr_panel3d p;
    memset(&p, 0, sizeof p);
    for (int a = 0; a < 3; a++) {
        p.lo[a] = 0;
        p.hi[a] = 1;
    }
    p.camera.azimuth = -60;
    p.camera.elevation = 25;
    lr_view v;
    panel_view(&p, W, H, &v);
    /* two points on the line of sight through the centre: near (group 1,
     * orange) given first, far (group 0, blue) after it */
    double x[2], y[2], z[2];
    for (int k = 0; k < 2; k++) {
        double t = k == 0 ? 0.3 : -0.3;
        x[k] = 0.5 + t * v.toward[0];
        y[k] = 0.5 + t * v.toward[1];
        z[k] = 0.5 + t * v.toward[2];
    }
    const int group[2] = {1, 0};
    lr_cloud3d c = {2, x, y, z, NULL, group, 6.0};
    p.clouds = &c;
    p.nclouds = 1;
    unsigned char *img = draw_one(b, &p, W, H);
    if (!img)
        return;
    double px, py;
    const double mid[3] = {0.5, 0.5, 0.5};
    lr_view_map(&v, mid, &px, &py);
    const unsigned char *q = img + 4 * ((size_t)py * W + (size_t)px);
    lr_rgba near = lr_palette(1), far = lr_palette(0);
    /* the centre of a sphere faces the viewer: lit, not its base colour;
     * which one it is shows in the ratio of the channels */
    double dn = fabs(q[0] / 255.0 - near.r) + fabs(q[2] / 255.0 - near.b);
    double df = fabs(q[0] / 255.0 - far.r) + fabs(q[2] / 255.0 - far.b);
    printf("%s: depth: centre pixel %d %d %d (near colour %.2f %.2f %.2f)\n",
           lr_backend_name(b), q[0], q[1], q[2], near.r, near.g, near.b);
    CHECK(dn < df);
    /* the target is at the panel's centre */
    CHECK_NEAR(px, 0.5 * W, 1e-9);
    CHECK_NEAR(py, 0.5 * H, 1e-9);
    free(img);
}

/* A particle and a slice (an opaque triangle pair) seen from above: the
 * particle above the plane is seen, below it is hidden - through OpenGL,
 * where the splats' depth goes into the depth buffer before the
 * triangles are drawn, and through cairo, whose painter's sort draws the
 * particles and triangles far to near together. */
static void test_depth_mixed(lr_backend b)
{
    enum { W = 160, H = 160 };
    double f[8] = {1, 1, 1, 1, 1, 1, 1, 1};
    lr_slice3d sl;
    memset(&sl, 0, sizeof sl);
    sl.grid.f = f;
    for (int a = 0; a < 3; a++) {
        sl.grid.n[a] = 2;
        sl.grid.h[a] = 1;
    }
    sl.axis = 2;
    sl.at = 0.5;
    sl.cmap = LR_CMAP_VIRIDIS;
    sl.vmin = 0;
    sl.vmax = 2;    /* the map's middle: a teal */
    for (int above = 0; above < 2; above++) {
        double x = 0.5, y = 0.5, z = above ? 0.8 : 0.2;
        const int group = 1;        /* orange */
        lr_cloud3d c = {1, &x, &y, &z, NULL, &group, 12.0};
        lr_panel3d p;
        memset(&p, 0, sizeof p);
        for (int a = 0; a < 3; a++)
            p.hi[a] = 1;
        p.camera.elevation = 90;
        p.slices = &sl;
        p.nslices = 1;
        p.clouds = &c;
        p.nclouds = 1;
        unsigned char *img = draw_one(b, &p, W, H);
        if (!img)
            return;
        const unsigned char *q = img + 4 * ((size_t)(H / 2) * W + W / 2);
        int orange = q[0] > 150 && q[2] < 80;
        printf("%s: particle %s the slice: centre %d %d %d\n", lr_backend_name(b),
               above ? "above" : "below", q[0], q[1], q[2]);
        CHECK(orange == above);
        free(img);
    }
}

static void test_camera(void)
{
    lr_panel3d p;
    memset(&p, 0, sizeof p);
    for (int a = 0; a < 3; a++) {
        p.lo[a] = 0;
        p.hi[a] = 1;
    }
    p.camera.azimuth = 0;       /* looking along -x */
    p.camera.elevation = 0;
    p.camera.target[0] = 0.5;
    p.camera.target[1] = 0.2;
    p.camera.target[2] = 0.7;
    p.camera.has_target = 1;
    p.camera.distance = 2.0;
    lr_view v;
    panel_view(&p, 400, 400, &v);
    double x, y;
    lr_view_map(&v, p.camera.target, &x, &y);
    CHECK_NEAR(x, 200, 1e-9);
    CHECK_NEAR(y, 200, 1e-9);
    /* orthographic, distance 2 and the reference fov 30: 2 * 2 tan 15 deg
     * across the panel's 368 px */
    const double q[3] = {0.5, 0.2 + 1.0, 0.7};
    lr_view_map(&v, q, &x, &y);
    CHECK_NEAR(x - 200, 184 / (2.0 * tan(15 * PI / 180)), 1e-9);
    /* perspective: a bar across the view at the near side looks longer
     * than the same bar at the far side, by (d + 0.5) / (d - 0.5) */
    p.camera.fov = 30;
    panel_view(&p, 400, 400, &v);
    double a[3] = {1.0, 0.2, 0.7}, bb[3] = {1.0, 0.3, 0.7};
    double xa, xb, ya;
    lr_view_map(&v, a, &xa, &ya);
    lr_view_map(&v, bb, &xb, &ya);
    double near = xb - xa;
    a[0] = bb[0] = 0.0;
    lr_view_map(&v, a, &xa, &ya);
    lr_view_map(&v, bb, &xb, &ya);
    double far = xb - xa;
    CHECK_NEAR(near / far, 2.5 / 1.5, 1e-12);
}

static void test_slice_colour(lr_backend b)
{
    enum { W = 160, H = 160 };
    int n = 5;
    double f[125];
    for (int i = 0; i < 125; i++)
        f[i] = 3.0;
    lr_slice3d s;
    memset(&s, 0, sizeof s);
    s.grid.f = f;
    for (int a = 0; a < 3; a++) {
        s.grid.n[a] = n;
        s.grid.h[a] = 0.25;
    }
    s.axis = 2;
    s.at = 0.5;
    s.cmap = LR_CMAP_VIRIDIS;
    s.vmin = 0;
    s.vmax = 4;
    lr_panel3d p;
    memset(&p, 0, sizeof p);
    for (int a = 0; a < 3; a++)
        p.hi[a] = 1;
    p.camera.elevation = 90;    /* from above: the plane fills the view */
    p.slices = &s;
    p.nslices = 1;
    unsigned char *img = draw_one(b, &p, W, H);
    if (!img)
        return;
    lr_rgba k = lr_cmap_colour(LR_CMAP_VIRIDIS, 0.75);
    const unsigned char *q = img + 4 * ((size_t)(H / 2) * W + W / 2);
    printf("%s: slice pixel %d %d %d, colour map %.0f %.0f %.0f\n", lr_backend_name(b),
           q[0], q[1], q[2], 255 * k.r, 255 * k.g, 255 * k.b);
    CHECK(abs(q[0] - (int)lround(255 * k.r)) <= 2);
    CHECK(abs(q[1] - (int)lround(255 * k.g)) <= 2);
    CHECK(abs(q[2] - (int)lround(255 * k.b)) <= 2);
    free(img);
}

static void test_refusals(void)
{
    lr_panel3d p;
    memset(&p, 0, sizeof p);
    p.hi[0] = p.hi[1] = 1;      /* z empty */
    lr_figure3d f = {100, 100, LR_BACKEND_CAIRO, &p, 1, 0, 0, NULL, NULL, NULL, 0};
    char err[256] = "";
    CHECK(lr_figure3d_render(&f, err, sizeof err) == NULL);
    CHECK(strstr(err, "box") != NULL);
    p.hi[2] = 1;
    p.camera.fov = 150;
    CHECK(lr_figure3d_render(&f, err, sizeof err) == NULL);
    CHECK(strstr(err, "fov") != NULL);
    p.camera.fov = 0;
    CHECK(lr_figure3d_write(&f, "out/x.svg", err, sizeof err) != 0);
    CHECK(strstr(err, "PNG") != NULL);
}

/* ---- speed ---------------------------------------------------------------- */

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double cpu(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int bench(size_t n, const char *only)
{
    double *x = malloc(4 * n * sizeof *x), *y = x + n, *z = x + 2 * n, *val = x + 3 * n;
    unsigned long long r = 88172645463325252ull;
    for (size_t i = 0; i < n; i++) {
        double u[3];
        for (int a = 0; a < 3; a++) {
            r ^= r << 13;
            r ^= r >> 7;
            r ^= r << 17;
            u[a] = (double)(r >> 11) / 9007199254740992.0;
        }
        x[i] = u[0];
        y[i] = u[1];
        z[i] = 0.5 * u[2];
        val[i] = x[i] + z[i];
    }
    lr_cloud3d c = {n, x, y, z, val, NULL, 1.0};
    lr_panel3d p;
    memset(&p, 0, sizeof p);
    for (int a = 0; a < 3; a++)
        p.hi[a] = 1;
    p.box = 1;
    p.camera.azimuth = -60;
    p.camera.elevation = 25;
    p.clouds = &c;
    p.nclouds = 1;
    p.colourbar = 1;
    for (int b = 0; b < LR_BACKEND_COUNT; b++) {
        if (!backend_ok((lr_backend)b) ||
            (only && strcmp(only, lr_backend_name((lr_backend)b)) != 0))
            continue;
        lr_figure3d f = {800, 800, (lr_backend)b, &p, 1, 0, 0, NULL, NULL, NULL, 0};
        char err[256];
        char path[64];
        snprintf(path, sizeof path, "out/frame3d_bench_%s.png", lr_backend_name((lr_backend)b));
        mkdir("out", 0777);
        double best = 1e9, best_cpu = 1e9;
        for (int k = 0; k < 3; k++) {
            double t0 = now(), c0 = cpu();
            unsigned char *img = lr_figure3d_render(&f, err, sizeof err);
            double t = now() - t0;
            best_cpu = fmin(best_cpu, cpu() - c0);
            if (!img) {
                fprintf(stderr, "%s\n", err);
                break;
            }
            free(img);
            best = fmin(best, t);
        }
        lr_figure3d_write(&f, path, err, sizeof err);
        printf("bench: %zu points, 800 x 800, %s: %.1f ms a frame wall, %.1f ms CPU of "
               "all threads (best of 3, drawing and reading back)\n", n,
               lr_backend_name((lr_backend)b), 1e3 * best, 1e3 * best_cpu);
    }
    free(x);
    return 0;
}

/* `test_frame3d baselines DIR [--update]`: the demo figure, small, per
 * backend here against DIR/frame3d_BACKEND.png (lamina diff's default
 * tolerance); --update rewrites them. */
static int baselines(const char *dir, int update)
{
    for (int b = 0; b < LR_BACKEND_COUNT; b++) {
        if (!backend_ok((lr_backend)b)) {
            printf("%s: not here, skipped\n", lr_backend_name((lr_backend)b));
            continue;
        }
        demo d;
        demo_build(&d, (lr_backend)b);
        d.fig.width = 480;
        d.fig.height = 250;
        char base[512], got[128], diffp[128], err[512] = "";
        snprintf(base, sizeof base, "%s/frame3d_%s.png", dir, lr_backend_name((lr_backend)b));
        mkdir("out", 0777);
        snprintf(got, sizeof got, "out/frame3d_small_%s.png", lr_backend_name((lr_backend)b));
        snprintf(diffp, sizeof diffp, "out/frame3d_small_%s_diff.png",
                 lr_backend_name((lr_backend)b));
        int rc = lr_figure3d_write(&d.fig, update ? base : got, err, sizeof err);
        if (rc != 0)
            fprintf(stderr, "%s\n", err);
        CHECK(rc == 0);
        if (!update && rc == 0) {
            lr_diff_opts o;
            lr_diff_result r;
            lr_diff_defaults(&o);
            rc = lr_diff_files(base, got, &o, diffp, &r, err, sizeof err);
            if (rc != 0)
                fprintf(stderr, "%s\n", err);
            printf("%s: against %s: %s, %ld differing pixels, largest channel difference %d\n",
                   lr_backend_name((lr_backend)b), base, r.exact ? "identical" : r.same ?
                   "same within the tolerance" : "DIFFERENT", r.differing, r.max_channel);
            CHECK(rc == 0 && r.same);
        }
        demo_free(&d);
    }
    lr_shutdown();
    return CHECK_DONE();
}

int main(int argc, char **argv)
{
    if (argc > 2 && strcmp(argv[1], "baselines") == 0)
        return baselines(argv[2], argc > 3 && strcmp(argv[3], "--update") == 0);
    if (argc > 1 && strcmp(argv[1], "bench") == 0)
        return bench(argc > 2 ? (size_t)atof(argv[2]) : 1000000, argc > 3 ? argv[3] : NULL);
    test_iso();
    test_camera();
    test_refusals();
    for (int b = 0; b < LR_BACKEND_COUNT; b++) {
        if (!backend_ok((lr_backend)b)) {
            printf("%s: not here, skipped\n", lr_backend_name((lr_backend)b));
            continue;
        }
        test_figure((lr_backend)b);
        test_depth((lr_backend)b);
        test_slice_colour((lr_backend)b);
        test_depth_mixed((lr_backend)b);
    }
    lr_shutdown();
    return CHECK_DONE();
}
