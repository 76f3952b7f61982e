/* sim3.c - a 3D simulation's life: its definition checked, its grid and
 * particle arrays, materials, seeding (docs/3d.md). The step is
 * sim3_step.c, the bases sim3_shape.c, the walls sim3_walls.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mpm3.h"
#include "mpm3_membrane.h"
#include "util.h"

static const char *const face_name[LM3_FACES] = {"x0", "x1", "y0", "y1", "z0", "z1"};

/* The definition, checked key by key: the message names the key and the
 * value it refused. */
static int def_ok(const lm3_def *d, int n[3], char *err, size_t len)
{
    static const char axis[3] = {'x', 'y', 'z'};
    if (!(d->cell > 0) || !isfinite(d->cell)) {
        snprintf(err, len, "cell = %g: must be a positive number", d->cell);
        return 0;
    }
    if (!(d->dt > 0) || !isfinite(d->dt)) {
        snprintf(err, len, "dt = %g: must be a positive number", d->dt);
        return 0;
    }
    if (d->basis != LM_BASIS_LINEAR && d->basis != LM_BASIS_BSPLINE2) {
        snprintf(err, len, "basis = %s: 3D has \"linear\" and \"bspline2\"",
                 d->basis == LM_BASIS_GIMP ? "gimp" : "?");
        return 0;
    }
    if (d->scheme != LM_MUSL && d->scheme != LM_USL) {
        snprintf(err, len, "scheme: must be musl or usl");
        return 0;
    }
    size_t nodes = 1;
    for (int a = 0; a < 3; a++) {
        double span = d->hi[a] - d->lo[a], c = span / d->cell;
        if (!isfinite(span) || !(span > 0)) {
            snprintf(err, len, "domain: %c1 = %g must exceed %c0 = %g", axis[a], d->hi[a],
                     axis[a], d->lo[a]);
            return 0;
        }
        /* a whole number of cells, as in 2D (the walls sit on nodes) */
        if (fabs(c - floor(c + 0.5)) > 1e-9 * c || c < 1 || c > 1e6) {
            snprintf(err, len, "domain: %c extent %g is not a whole number of cells %g "
                     "(or more than 10^6 of them)", axis[a], span, d->cell);
            return 0;
        }
        n[a] = (int)floor(c + 0.5);
        nodes *= (size_t)n[a] + 3;
        if (nodes > LM3_MAX_NODES) {
            snprintf(err, len, "domain / cell: more than %zu grid nodes", LM3_MAX_NODES);
            return 0;
        }
    }
    for (int f = 0; f < LM3_FACES; f++)
        if (d->bc[f] != LM_BC_FIXED && d->bc[f] != LM_BC_SYMMETRY && d->bc[f] != LM_BC_FREE) {
            snprintf(err, len, "boundary.%s: must be fixed, symmetry or free", face_name[f]);
            return 0;
        }
    if (!(d->courant >= 0) || !isfinite(d->courant)) {
        snprintf(err, len, "courant = %g: must be a positive number", d->courant);
        return 0;
    }
    if (d->threads < 0 || d->threads > LM_MAX_THREADS) {
        snprintf(err, len, "threads = %d: must be 1 to %d", d->threads, LM_MAX_THREADS);
        return 0;
    }
    for (int a = 0; a < 3; a++)
        if (!isfinite(d->gravity[a])) {
            snprintf(err, len, "gravity: component %d is not finite", a + 1);
            return 0;
        }
    return 1;
}

lm3_sim *lm3_sim_create(const lm3_def *def, char *err, size_t errlen)
{
    int n[3];
    if (!def_ok(def, n, err, errlen)) return NULL;
    lm3_sim *sim = calloc(1, sizeof *sim);
    if (!sim) goto oom;
    sim->def = *def;
    lm3_grid *g = &sim->grid;
    g->h = def->cell;
    g->pad = def->basis == LM_BASIS_LINEAR ? 0 : 1;
    g->W = def->basis == LM_BASIS_LINEAR ? 2 : 3;
    g->nn = 1;
    for (int a = 0; a < 3; a++) {
        g->lo[a] = def->lo[a];
        g->n[a] = n[a];
        g->s[a] = n[a] + 1 + 2 * g->pad;
        g->nn *= (size_t)g->s[a];
    }
    memcpy(g->bc, def->bc, sizeof g->bc);
    /* one block for the ten nodal fields */
    g->m = calloc(10 * g->nn, sizeof(double));
    if (!g->m) goto oom;
    for (int a = 0; a < 3; a++) {
        g->p[a] = g->m + (1 + a) * g->nn;
        g->f[a] = g->m + (4 + a) * g->nn;
        g->v[a] = g->m + (7 + a) * g->nn;
    }
    return sim;
oom:
    snprintf(err, errlen, "out of memory for the grid");
    lm3_sim_free(sim);
    return NULL;
}

void lm3_sim_free(lm3_sim *sim)
{
    if (!sim) return;
    lm3_pins_free(sim);
    lm3_particles *p = &sim->p;
    LU_FREE_ALL(p->x[0], p->x[1], p->x[2], p->v[0], p->v[1], p->v[2], p->m, p->rho, p->s[0],
                p->s[1], p->s[2], p->s[3], p->s[4], p->s[5], p->e, p->d[0], p->d[1], p->d[2],
                p->node, p->mat, sim->grid.m, sim->scratch);
    lm3_membranes_free(sim->mem);
    free(sim);
}

/* A gas's constants, checked as lm_material_validate checks the 2D gas's. */
static int gas_ok(const lm3_material *mat, char *err, size_t errlen)
{
    if (!(mat->gamma > 1) || !isfinite(mat->gamma)) {
        snprintf(err, errlen, "gamma = %g: must be greater than 1", mat->gamma);
        return 0;
    }
    if (!(mat->e0 >= 0) || !isfinite(mat->e0)) {
        snprintf(err, errlen, "e = %g: the internal energy must be >= 0", mat->e0);
        return 0;
    }
    if (!(mat->mu >= 0) || !isfinite(mat->mu)) {
        snprintf(err, errlen, "mu = %g: must be >= 0", mat->mu);
        return 0;
    }
    if (mat->av && !(mat->av_lambda > 0 && mat->av_c1 >= 0 && mat->av_c2 >= 0 &&
                     isfinite(mat->av_lambda + mat->av_c1 + mat->av_c2 + mat->av_g))) {
        snprintf(err, errlen, "av: the artificial viscosity needs lambda > 0, c1 >= 0, "
                 "c2 >= 0 (got lambda = %g, c1 = %g, c2 = %g)", mat->av_lambda, mat->av_c1,
                 mat->av_c2);
        return 0;
    }
    return 1;
}

int lm3_material_add(lm3_sim *sim, const lm3_material *mat, char *err, size_t errlen)
{
    if (!(mat->rho > 0) || !isfinite(mat->rho)) {
        snprintf(err, errlen, "rho = %g: must be a positive number", mat->rho);
        return -1;
    }
    if (mat->kind == LM3_GAS) {
        if (!gas_ok(mat, err, errlen)) return -1;
    } else if (mat->kind != LM3_ELASTIC) {
        snprintf(err, errlen, "kind = %d: 3D has elastic and gas", (int)mat->kind);
        return -1;
    } else if (!(mat->E > 0) || !isfinite(mat->E)) {
        snprintf(err, errlen, "E = %g: must be a positive number", mat->E);
        return -1;
    } else if (!(mat->nu > -1 && mat->nu < 0.5)) {
        snprintf(err, errlen, "nu = %g: must lie in (-1, 0.5)", mat->nu);
        return -1;
    }
    if (sim->nmat >= LM3_MAX_MATERIALS) {
        snprintf(err, errlen, "more than %d materials", LM3_MAX_MATERIALS);
        return -1;
    }
    sim->mats[sim->nmat] = *mat;
    return sim->nmat++;
}

/* Room for `more` particles: each array grown with lu_reserve (the old
 * ones stay valid when one fails; the common capacity is raised only when
 * all have it). */
static int reserve(lm3_particles *p, size_t more)
{
    size_t need = p->n + more;
    if (need <= p->cap) return 1;
    void *arr[] = {&p->x[0], &p->x[1], &p->x[2], &p->v[0], &p->v[1], &p->v[2], &p->m,
                   &p->rho, &p->s[0], &p->s[1], &p->s[2], &p->s[3], &p->s[4], &p->s[5],
                   &p->e, &p->d[0], &p->d[1], &p->d[2], &p->node, &p->mat};
    size_t elem[] = {8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, sizeof(int32_t), 1};
    size_t cap = p->cap;
    for (size_t i = 0; i < sizeof arr / sizeof *arr; i++) {
        size_t c = p->cap;
        if (lu_reserve(arr[i], &c, need, elem[i], 1024) != 0) return 0;
        cap = c;
    }
    p->cap = cap;
    return 1;
}

static int inside(const lm3_sim *sim, const double x[3])
{
    const lm3_grid *g = &sim->grid;
    for (int a = 0; a < 3; a++)
        if (!(x[a] >= g->lo[a] && x[a] <= g->lo[a] + g->n[a] * g->h)) return 0;
    return 1;
}

lm_status lm3_particle_add(lm3_sim *sim, int mat, const double x[3], const double v[3],
                           double V)
{
    if (mat < 0 || mat >= sim->nmat || !(V > 0) || !inside(sim, x)) return LM_ERR_INPUT;
    lm3_particles *p = &sim->p;
    if (!reserve(p, 1)) return LM_ERR_MEMORY;
    size_t q = p->n++;
    for (int a = 0; a < 3; a++) {
        p->x[a][q] = x[a];
        p->v[a][q] = v[a];
        p->d[a][q] = 0;
    }
    const lm3_material *mt = &sim->mats[mat];
    p->rho[q] = mt->rho;
    p->m[q] = p->rho[q] * V;
    /* a gas starts at its pressure as an isotropic stress ([F] eq 21 at
     * rest), as 2D seeding does (sim.c) */
    p->e[q] = mt->kind == LM3_GAS ? mt->e0 : 0;
    double pr = mt->kind == LM3_GAS ? (mt->gamma - 1) * p->rho[q] * mt->e0 : 0;
    for (int c = 0; c < 6; c++) p->s[c][q] = c < 3 ? -pr : 0;
    p->node[q] = 0;
    p->mat[q] = (uint8_t)mat;
    sim->recheck = 1;      /* a new particle: the next step looks at it */
    return LM_OK;
}

long lm3_seed_box(lm3_sim *sim, int mat, const double lo[3], const double hi[3], int k,
                  const double v[3])
{
    const lm3_grid *g = &sim->grid;
    if (k < 1 || k > 8) return -1;
    /* the sub-cells of the grid's cells whose centres lie in the box */
    double s = g->h / k;
    long i0[3], i1[3];
    for (int a = 0; a < 3; a++) {
        i0[a] = (long)ceil((lo[a] - g->lo[a]) / s - 0.5);
        i1[a] = (long)floor((hi[a] - g->lo[a]) / s - 0.5);
        if (i0[a] < 0) i0[a] = 0;
        if (i1[a] > (long)g->n[a] * k - 1) i1[a] = (long)g->n[a] * k - 1;
        if (i1[a] < i0[a]) return 0;
    }
    size_t count = (size_t)(i1[0] - i0[0] + 1) * (size_t)(i1[1] - i0[1] + 1) *
                   (size_t)(i1[2] - i0[2] + 1);
    if (!reserve(&sim->p, count)) return -1;
    for (long c = i0[2]; c <= i1[2]; c++)
        for (long b = i0[1]; b <= i1[1]; b++)
            for (long a = i0[0]; a <= i1[0]; a++) {
                double x[3] = {g->lo[0] + (a + 0.5) * s, g->lo[1] + (b + 0.5) * s,
                               g->lo[2] + (c + 0.5) * s};
                if (lm3_particle_add(sim, mat, x, v, s * s * s) != LM_OK) return -1;
            }
    return (long)count;
}

void lm3_energy_of(const lm3_sim *sim, lm3_energy *e)
{
    const lm3_particles *p = &sim->p;
    const double *gv = sim->def.gravity;
    double k = 0, w = 0, u = 0, in = 0;
    for (size_t q = 0; q < p->n; q++) {
        double v2 = p->v[0][q] * p->v[0][q] + p->v[1][q] * p->v[1][q] + p->v[2][q] * p->v[2][q];
        k += 0.5 * p->m[q] * v2;
        const lm3_material *mt = &sim->mats[p->mat[q]];
        if (mt->kind == LM3_GAS) {
            in += p->m[q] * p->e[q];   /* [F] eq 23's stored energy */
        } else {
            double s[6];
            for (int c = 0; c < 6; c++) s[c] = p->s[c][q];
            w += p->m[q] / p->rho[q] * lm3_elastic_energy_density(mt, s);
        }
        /* potential of the uniform field: -m g . x */
        u -= p->m[q] * (gv[0] * p->x[0][q] + gv[1] * p->x[1][q] + gv[2] * p->x[2][q]);
    }
    lm3_membrane_energy(sim, &k, &w, &u);
    e->kinetic = k;
    e->strain = w;
    e->potential = u;
    e->internal = in;
    e->total = k + w + in + u;
}

/* x, v (6), m, rho, sigma (6), e, d (3): 18 doubles; node (int32) and
 * mat (uint8) - the arrays reserve() grows; the grid's ten doubles a node
 * (lm3_sim_create) */
#define LM3_PARTICLE_BYTES (18 * sizeof(double) + sizeof(int32_t) + sizeof(uint8_t))

size_t lm3_memory(const lm3_sim *sim, size_t *particles, size_t *exact, size_t *grid)
{
    /* the grid's fields and the threads' copies of them (sim3_threads.c) */
    size_t pb = sim->p.cap * LM3_PARTICLE_BYTES,
           gb = (10 * sim->grid.nn + sim->scratch_len) * sizeof(double);
    if (particles) *particles = pb;
    if (exact) *exact = sim->p.n * LM3_PARTICLE_BYTES;
    if (grid) *grid = gb;
    return pb + gb;
}

void lm3_momentum(const lm3_sim *sim, double P[3])
{
    const lm3_particles *p = &sim->p;
    for (int a = 0; a < 3; a++) {
        P[a] = 0;
        for (size_t q = 0; q < p->n; q++) P[a] += p->m[q] * p->v[a][q];
    }
    lm3_membrane_momentum(sim, P);
}

double lm3_mass(const lm3_sim *sim)
{
    double m = 0;
    for (size_t q = 0; q < sim->p.n; q++) m += sim->p.m[q];
    return m + lm3_membrane_mass(sim);
}
