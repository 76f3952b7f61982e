/* test_frame3d_phi.c - a 3D membrane's phi = 1 surface (issue 34 item 4;
 * sim3_membrane_phi.c, drawn by sim:frame through frame3d's triangles).
 *
 * A sphere of radius R = 0.3 sampled at spacing h/3 (h = 0.05, the
 * B-spline grid of test_sim3_membrane's balloon), its construction's phi
 * sampled element by element and contoured cube by cube as l_frame3d.c
 * does:
 *   - triquadratic ([N] Fig 11): every vertex of the surface within
 *     h / 100 of the sphere. Why that bound: a sphere departs from a
 *     quadric over an element by O(q^4 / R^3) ~ 1e-5 (q = h / 2), the
 *     marching tetrahedra's chords by at most d^2 / (8 R) = 1.6e-5 (d =
 *     h / 8, the node spacing), and the fit's curvature rows
 *     (normals_smooth.c) pull it by about the fit's residual; 5e-4 is
 *     ten times their sum, far below the trilinear fit's miss.
 *     The surface's area lies between 90 % and 100.5 % of 4 pi R^2 (cubes
 *     without points have no fit: small holes, measured below);
 *   - trilinear ([N] Fig 5): printed, and held to be farther off than the
 *     triquadratic (its phi = 1 bends where the points are flat, [N] Fig 7
 *     in 2D; the normals 83-89 degrees off at worst, test_sim3_membrane);
 *   - the same call twice gives the same bits;
 *   - a small figure of it (points, the see-through surface) against
 *     tests/unit/baselines/frame3d_phi_BACKEND.png per backend here
 *     (lamina diff's tolerance; `test_frame3d_phi baselines DIR --update`
 *     rewrites them). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "diff.h"
#include "frame3d.h"
#include "mpm3.h"
#include "mpm3_membrane.h"
#include "render.h"

static const double H = 0.05, R = 0.3, C[3] = {0.5, 0.5, 0.5};

static lm3_sim *sphere_sim(void)
{
    lm3_def d;
    memset(&d, 0, sizeof d);
    for (int a = 0; a < 3; a++) d.hi[a] = 1;
    d.cell = H;
    d.dt = 5e-4;
    d.basis = LM_BASIS_BSPLINE2;
    d.scheme = LM_MUSL;
    char err[256];
    lm3_sim *sim = lm3_sim_create(&d, err, sizeof err);
    if (!sim) {
        fprintf(stderr, "%s\n", err);
        return NULL;
    }
    lm3_msample smp;
    CHECK(lm3_sample_sphere(C, R, H / 3, &smp, err, sizeof err) == 0);
    lm3_mdef def;
    lm3_mdef_default(&def);
    memset(&def.mat, 0, sizeof def.mat);
    def.mat.kind = LM_MEMBRANE;
    def.mat.rho = 1000;
    def.mat.E = 1e6;
    def.mat.nu = 0.3;
    def.mat.thickness = 1e-3;
    def.mat.law = LM_LAW_PLANE_STRESS;
    CHECK(lm3_membrane_add(sim, &def, &smp) == 0);
    lm3_msample_free(&smp);
    return sim;
}

/* The surface as l_frame3d.c makes it: each cube contoured alone. The
 * arrays double when full, as there: grown by each cube's few triangles,
 * every realloc copied the whole surface under AddressSanitizer (which
 * cannot grow a block in place), 175 s of the sanitizer stage against
 * 0.8 s in the normal build (issue 36 item 4). */
static size_t contour(const lm3_phicubes *c, double **xyz, double **nrm)
{
    const int m = c->samples + 1;
    const size_t m3 = (size_t)m * m * m;
    size_t nt = 0, cap = 0;
    *xyz = NULL;
    *nrm = NULL;
    for (size_t e = 0; e < c->n; e++) {
        lr_grid3d g = {c->f + e * m3, {m, m, m}, {c->lo[3 * e], c->lo[3 * e + 1],
                                                  c->lo[3 * e + 2]}, {c->d, c->d, c->d}};
        double *t = NULL, *tn = NULL;
        size_t n = 0;
        CHECK(lr_iso_triangles(&g, 1.0, &t, &tn, &n) == 0);
        if (nt + n > cap) {
            cap = cap ? 2 * cap : 4096;
            while (cap < nt + n) cap *= 2;
            *xyz = realloc(*xyz, 9 * cap * sizeof **xyz);
            *nrm = realloc(*nrm, 9 * cap * sizeof **nrm);
            CHECK(*xyz && *nrm);
        }
        if (n) {
            memcpy(*xyz + 9 * nt, t, 9 * n * sizeof *t);
            memcpy(*nrm + 9 * nt, tn, 9 * n * sizeof *tn);
            nt += n;
        }
        free(t);
        free(tn);
    }
    return nt;
}

/* The largest |r - R| over the vertices, and the area's ratio to 4 pi R^2. */
static void measure(const double *xyz, size_t nt, double *dmax, double *area)
{
    *dmax = 0;
    *area = 0;
    for (size_t k = 0; k < nt; k++) {
        const double *p = xyz + 9 * k;
        for (int v = 0; v < 3; v++) {
            double r = 0;
            for (int a = 0; a < 3; a++) r += (p[3 * v + a] - C[a]) * (p[3 * v + a] - C[a]);
            *dmax = fmax(*dmax, fabs(sqrt(r) - R));
        }
        double u[3], w[3];
        for (int a = 0; a < 3; a++) {
            u[a] = p[3 + a] - p[a];
            w[a] = p[6 + a] - p[a];
        }
        double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2],
               z = u[0] * w[1] - u[1] * w[0];
        *area += 0.5 * sqrt(x * x + y * y + z * z);
    }
    *area /= 4 * 3.14159265358979323846 * R * R;
}

static void surfaces(void)
{
    lm3_sim *sim = sphere_sim();
    CHECK(sim != NULL);
    if (!sim) return;
    char err[256];
    double dq = 0, dl = 0;
    for (int b = 0; b < 2; b++) {
        lm3_mnormals basis = b ? LM3_MN_QUADRATIC : LM3_MN_LINEAR;
        lm3_phicubes c, c2;
        CHECK(lm3_membrane_phi(sim, 0, basis, 4, &c, err, sizeof err) == 0);
        CHECK(lm3_membrane_phi(sim, 0, basis, 4, &c2, err, sizeof err) == 0);
        const size_t m3 = 125;
        CHECK(c.n == c2.n && c.n > 0);
        CHECK(memcmp(c.f, c2.f, c.n * m3 * sizeof *c.f) == 0);
        CHECK(memcmp(c.lo, c2.lo, 3 * c.n * sizeof *c.lo) == 0);
        double *xyz, *nrm, d, area;
        size_t nt = contour(&c, &xyz, &nrm);
        measure(xyz, nt, &d, &area);
        printf("%s construction: %zu elements, %zu triangles; every vertex within %.3g of the "
               "sphere (h = %g), area %.4f of 4 pi R^2\n", b ? "triquadratic" : "trilinear", c.n,
               nt, d, H, area);
        if (b) {
            dq = d;
            CHECK(d < 5e-4);
            CHECK(area > 0.9 && area < 1.005);
        } else {
            dl = d;
        }
        free(xyz);
        free(nrm);
        lm3_phicubes_free(&c);
        lm3_phicubes_free(&c2);
    }
    CHECK(dl > dq);
    /* refusals: no such membrane, bad sample counts */
    lm3_phicubes c;
    CHECK(lm3_membrane_phi(sim, 1, LM3_MN_QUADRATIC, 4, &c, err, sizeof err) == -1);
    CHECK(strstr(err, "no membrane 2") != NULL);
    CHECK(lm3_membrane_phi(sim, 0, LM3_MN_QUADRATIC, 0, &c, err, sizeof err) == -1);
    CHECK(c.f == NULL && c.lo == NULL);
    lm3_sim_free(sim);
}

/* A small figure: the sphere's points and its triquadratic phi = 1,
 * close up (a quarter of the sphere's upper cap). */
static int baselines(const char *dir, int update)
{
    lm3_sim *sim = sphere_sim();
    CHECK(sim != NULL);
    if (!sim) return CHECK_DONE();
    char err[512] = "";
    lm3_phicubes c;
    CHECK(lm3_membrane_phi(sim, 0, LM3_MN_QUADRATIC, 4, &c, err, sizeof err) == 0);
    double *xyz, *nrm;
    size_t nt = contour(&c, &xyz, &nrm);
    const lm3_mpoints *p = &sim->mem->p;
    lr_membrane3d m;
    memset(&m, 0, sizeof m);
    m.n = p->n;
    m.x = p->x[0];
    m.y = p->x[1];
    m.z = p->x[2];
    m.colour = (lr_rgba){0.15, 0.35, 0.75, 1};
    m.radius = 1.5;
    m.spacing = H / 3;
    lr_tris3d t = {nt, xyz, nrm, {0.35, 0.75, 0.45, 0.4}};
    lr_panel3d pan;
    memset(&pan, 0, sizeof pan);
    const double lo[3] = {0.45, 0.45, 0.65}, hi[3] = {0.75, 0.75, 0.85};
    for (int a = 0; a < 3; a++) {
        pan.lo[a] = lo[a];
        pan.hi[a] = hi[a];
    }
    pan.box = 1;
    pan.camera.azimuth = -60;
    pan.camera.elevation = 25;
    pan.membranes = &m;
    pan.nmembranes = 1;
    pan.tris = &t;
    pan.ntris = 1;
    lr_figure3d f;
    memset(&f, 0, sizeof f);
    f.width = 240;
    f.height = 180;
    f.panels = &pan;
    f.npanels = 1;
    for (int b = 0; b < LR_BACKEND_COUNT; b++) {
        if (lr_backend_check((lr_backend)b, err, sizeof err) != 0) {
            printf("%s: not here, skipped\n", lr_backend_name((lr_backend)b));
            continue;
        }
        f.backend = (lr_backend)b;
        char base[512], got[128], diffp[128];
        snprintf(base, sizeof base, "%s/frame3d_phi_%s.png", dir, lr_backend_name((lr_backend)b));
        mkdir("out", 0777);
        snprintf(got, sizeof got, "out/frame3d_phi_%s.png", lr_backend_name((lr_backend)b));
        snprintf(diffp, sizeof diffp, "out/frame3d_phi_%s_diff.png",
                 lr_backend_name((lr_backend)b));
        /* twice: the same bytes */
        unsigned char *one = lr_figure3d_render(&f, err, sizeof err);
        unsigned char *two = lr_figure3d_render(&f, err, sizeof err);
        CHECK(one && two && memcmp(one, two, (size_t)f.width * f.height * 4) == 0);
        free(one);
        free(two);
        int rc = lr_figure3d_write(&f, update ? base : got, err, sizeof err);
        if (rc != 0) fprintf(stderr, "%s\n", err);
        CHECK(rc == 0);
        if (!update && rc == 0) {
            lr_diff_opts o;
            lr_diff_result r;
            lr_diff_defaults(&o);
            rc = lr_diff_files(base, got, &o, diffp, &r, err, sizeof err);
            if (rc != 0) fprintf(stderr, "%s\n", err);
            printf("%s: against %s: %s, %ld differing pixels, largest channel difference %d\n",
                   lr_backend_name((lr_backend)b), base, r.exact ? "identical" : r.same ?
                   "same within the tolerance" : "DIFFERENT", r.differing, r.max_channel);
            CHECK(rc == 0 && r.same);
        }
    }
    free(xyz);
    free(nrm);
    lm3_phicubes_free(&c);
    lm3_sim_free(sim);
    lr_shutdown();
    return CHECK_DONE();
}

int main(int argc, char **argv)
{
    if (argc > 2 && strcmp(argv[1], "baselines") == 0)
        return baselines(argv[2], argc > 3 && strcmp(argv[3], "--update") == 0);
    surfaces();
    return CHECK_DONE();
}
