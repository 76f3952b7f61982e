/* sim3_membrane.c - a 3D simulation's membranes: added from sampled
 * surfaces, pinned, freed; their energies, momenta and wave speed
 * (mpm3_membrane.h, docs/3d.md "3D membranes"). The step's part is
 * sim3_membrane_step.c, the surfaces sim3_membrane_surface.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "membrane_law.h"
#include "step.h"
#include "mpm3.h"
#include "mpm3_membrane.h"
#include "util.h"

void lm3_mdef_default(lm3_mdef *d)
{
    memset(d, 0, sizeof *d);
    d->mat.kind = LM_MEMBRANE;
    d->mat.law = LM_LAW_PLANE_STRESS;
    d->normals = LM3_MN_CONNECTIVITY;
}

void lm3_membranes_free(lm3_membranes *m)
{
    if (!m) return;
    lm3_mpoints *p = &m->p;
    LU_FREE_ALL(p->x[0], p->x[1], p->x[2], p->v[0], p->v[1], p->v[2], p->m, p->A0, p->t1[0],
                p->t1[1], p->t1[2], p->t2[0], p->t2[1], p->t2[2], p->nrm[0], p->nrm[1],
                p->nrm[2], p->e[0], p->e[1], p->e[2], p->s[0], p->s[1], p->s[2], p->d[0],
                p->d[1], p->d[2], p->node, p->pin, p->mem);
    for (int k = 0; k < m->npins; k++) free(m->pins[k].idx);
    free(m->pins);
    free(m->mem);
    free(m->held);
    free(m);
}

/* Room for `more` points (lu_reserve per array; the common capacity is
 * raised only when every array has it). */
static int reserve(lm3_mpoints *p, size_t more)
{
    size_t need = p->n + more;
    if (need <= p->cap) return 1;
    void *arr[] = {&p->x[0], &p->x[1], &p->x[2], &p->v[0], &p->v[1], &p->v[2], &p->m,
                   &p->A0, &p->t1[0], &p->t1[1], &p->t1[2], &p->t2[0], &p->t2[1], &p->t2[2],
                   &p->nrm[0], &p->nrm[1], &p->nrm[2], &p->e[0], &p->e[1], &p->e[2],
                   &p->s[0], &p->s[1], &p->s[2], &p->d[0], &p->d[1], &p->d[2], &p->node,
                   &p->pin, &p->mem};
    size_t cap = p->cap;
    for (size_t i = 0; i < sizeof arr / sizeof *arr; i++) {
        size_t elem = i < 26 ? sizeof(double) : i == 26 ? sizeof(int32_t) : i == 27 ? 1 : 2;
        size_t c = p->cap;
        if (lu_reserve(arr[i], &c, need, elem, 1024) != 0) return 0;
        cap = c;
    }
    p->cap = cap;
    return 1;
}

static lm3_membranes *membranes_of(lm3_sim *sim)
{
    if (!sim->mem) sim->mem = calloc(1, sizeof *sim->mem);
    return sim->mem;
}

/* The membrane rules before anything is added (membrane_create.c's in 3D). */
static int def_ok(lm3_sim *sim, const lm3_mdef *def, const lm3_msample *s)
{
    char why[200];
    const lm3_grid *g = &sim->grid;
    int k = sim->mem ? sim->mem->nmem : 0;
    if (def->mat.kind != LM_MEMBRANE) {
        snprintf(sim->err, sizeof sim->err, "membrane %d: the material is not a membrane",
                 k + 1);
        return 0;
    }
    if (lm_material_validate(&def->mat, why, sizeof why) != 0) {
        snprintf(sim->err, sizeof sim->err, "membrane %d: %.150s", k + 1, why);
        return 0;
    }
    if (!(def->initial_strain > -5 && def->initial_strain < 5)) {
        snprintf(sim->err, sizeof sim->err,
                 "membrane %d: initial_strain = %g must lie in (-5, 5)", k + 1,
                 def->initial_strain);
        return 0;
    }
    if (!isfinite(def->pressure) || !(def->damping >= 0) || !isfinite(def->damping)) {
        snprintf(sim->err, sizeof sim->err,
                 "membrane %d: pressure = %g must be finite, damping = %g positive or 0", k + 1,
                 def->pressure, def->damping);
        return 0;
    }
    if (def->damping * sim->def.dt >= 1) {
        snprintf(sim->err, sizeof sim->err,
                 "membrane %d: damping = %g is 1/dt or more: the explicit force -c m v would "
                 "reverse the velocity in a step (dt = %g)", k + 1, def->damping, sim->def.dt);
        return 0;
    }
    if (def->normals != LM3_MN_CONNECTIVITY && def->normals != LM3_MN_LINEAR &&
        def->normals != LM3_MN_QUADRATIC) {
        snprintf(sim->err, sizeof sim->err, "membrane %d: unknown normals method %d", k + 1,
                 (int)def->normals);
        return 0;
    }
    if (!s || s->n == 0) {
        snprintf(sim->err, sizeof sim->err, "membrane %d has no points", k + 1);
        return 0;
    }
    for (size_t q = 0; q < s->n; q++) {
        double x[3] = {s->x[0][q], s->x[1][q], s->x[2][q]};
        for (int a = 0; a < 3; a++)
            if (!(x[a] >= g->lo[a] && x[a] <= g->lo[a] + g->n[a] * g->h)) {
                snprintf(sim->err, sizeof sim->err,
                         "membrane %d leaves the domain: point %zu at (%g, %g, %g) has %c "
                         "outside [%g, %g]", k + 1, q + 1, x[0], x[1], x[2], "xyz"[a],
                         g->lo[a], g->lo[a] + g->n[a] * g->h);
                return 0;
            }
        if (!(s->A[q] > 0) || !isfinite(s->A[q])) {
            snprintf(sim->err, sizeof sim->err, "membrane %d: point %zu has area %g", k + 1,
                     q + 1, s->A[q]);
            return 0;
        }
    }
    if (k >= LM3_MAX_MEMBRANES) {
        snprintf(sim->err, sizeof sim->err, "more than %d membranes", LM3_MAX_MEMBRANES);
        return 0;
    }
    return 1;
}

int lm3_membrane_add(lm3_sim *sim, const lm3_mdef *def, const lm3_msample *s)
{
    if (!def_ok(sim, def, s)) return -1;
    lm3_membranes *ms = membranes_of(sim);
    if (!ms) goto oom;
    lm3_membrane *mem = realloc(ms->mem, (size_t)(ms->nmem + 1) * sizeof *mem);
    if (!mem) goto oom;
    ms->mem = mem;
    lm3_mpoints *p = &ms->p;
    if (!reserve(p, s->n)) goto oom;
    int k = ms->nmem++;
    mem[k] = (lm3_membrane){.def = *def, .first = p->n, .count = s->n, .closed = s->closed};
    const double e0 = def->initial_strain, t = def->mat.thickness, rho = def->mat.rho;
    for (size_t j = 0; j < s->n; j++) {
        size_t q = p->n++;
        for (int a = 0; a < 3; a++) {
            p->x[a][q] = s->x[a][j];
            p->v[a][q] = def->v[a];
            p->t1[a][q] = s->t1[a][j];
            p->t2[a][q] = s->t2[a][j];
            p->d[a][q] = 0;
        }
        /* n = t1 x t2 */
        p->nrm[0][q] = p->t1[1][q] * p->t2[2][q] - p->t1[2][q] * p->t2[1][q];
        p->nrm[1][q] = p->t1[2][q] * p->t2[0][q] - p->t1[0][q] * p->t2[2][q];
        p->nrm[2][q] = p->t1[0][q] * p->t2[1][q] - p->t1[1][q] * p->t2[0][q];
        /* a point of current area A at isotropic strain e0 stands for
         * A exp(-2 e0) of unstrained sheet (the 2D ds exp(-e), twice) */
        p->A0[q] = s->A[j] * exp(-2 * e0);
        p->m[q] = rho * t * p->A0[q];
        p->e[0][q] = p->e[1][q] = e0;
        p->e[2][q] = 0;
        double s1, s2;
        lm_membrane_stress_biaxial(&def->mat, e0, e0, &s1, &s2);
        p->s[0][q] = s1;
        p->s[1][q] = s2;
        p->s[2][q] = 0;
        p->node[q] = 0;
        p->pin[q] = 0;
        p->mem[q] = (uint16_t)k;
    }
    return k;
oom:
    snprintf(sim->err, sizeof sim->err, "out of memory for a membrane of %zu points", s->n);
    return -1;
}

int lm3_membrane_pin(lm3_sim *sim, int k, const size_t *idx, size_t n)
{
    lm3_membranes *ms = sim->mem;
    if (!ms || k < 0 || k >= ms->nmem || n == 0 || !idx) {
        snprintf(sim->err, sizeof sim->err, "a pin needs a membrane and at least one point");
        return -1;
    }
    const lm3_membrane *mb = &ms->mem[k];
    for (size_t j = 0; j < n; j++) {
        if (idx[j] >= mb->count) {
            snprintf(sim->err, sizeof sim->err,
                     "membrane %d has %zu points; point %zu cannot be pinned", k + 1, mb->count,
                     idx[j] + 1);
            return -1;
        }
        if (ms->p.pin[mb->first + idx[j]]) {
            snprintf(sim->err, sizeof sim->err, "point %zu of membrane %d is pinned already",
                     idx[j] + 1, k + 1);
            return -1;
        }
    }
    if (!ms->held) {
        ms->held = calloc(sim->grid.nn, sizeof *ms->held);
        if (!ms->held) goto oom;
    }
    lm3_mpin *pn = lu_push(&ms->pins, (size_t)ms->npins, sizeof *ms->pins);
    if (!pn) goto oom;
    pn->idx = malloc(n * sizeof *pn->idx);
    if (!pn->idx) goto oom;
    pn->n = n;
    for (size_t j = 0; j < n; j++) {
        size_t q = mb->first + idx[j];
        pn->idx[j] = q;
        ms->p.pin[q] = 1;
        for (int a = 0; a < 3; a++) ms->p.v[a][q] = 0;
    }
    return ms->npins++;
oom:
    snprintf(sim->err, sizeof sim->err, "out of memory for a pin of %zu points", n);
    return -1;
}

double lm3_membrane_tension(const lm3_sim *sim, size_t q)
{
    const lm3_membranes *ms = sim->mem;
    const lm3_mpoints *p = &ms->p;
    return 0.5 * (p->s[0][q] + p->s[1][q]) * ms->mem[p->mem[q]].def.mat.thickness;
}

double lm3_membrane_wave_speed(const lm3_sim *sim)
{
    double c = 0;
    for (int k = 0; sim->mem && k < sim->mem->nmem; k++) {
        double ck = lm_membrane_wave_speed(&sim->mem->mem[k].def.mat);
        if (ck > c) c = ck;
    }
    return c;
}

/* The principal strains of the in-plane strain (e11, e22, e12). */
static void principal(double e11, double e22, double e12, double *e1, double *e2)
{
    double m = 0.5 * (e11 + e22), r = hypot(0.5 * (e11 - e22), e12);
    *e1 = m + r;
    *e2 = m - r;
}

void lm3_membrane_energy(const lm3_sim *sim, double *kinetic, double *strain,
                         double *potential)
{
    if (!sim->mem) return;
    const lm3_mpoints *p = &sim->mem->p;
    const double *gv = sim->def.gravity;
    for (size_t q = 0; q < p->n; q++) {
        const lm_material *mat = &sim->mem->mem[p->mem[q]].def.mat;
        double v2 = p->v[0][q] * p->v[0][q] + p->v[1][q] * p->v[1][q] + p->v[2][q] * p->v[2][q];
        double e1, e2;
        principal(p->e[0][q], p->e[1][q], p->e[2][q], &e1, &e2);
        double V = mat->thickness * p->A0[q] * exp(p->e[0][q] + p->e[1][q]);
        *kinetic += 0.5 * p->m[q] * v2;
        *strain += lm_membrane_ring_energy(mat, V, e1, e2);
        *potential -= p->m[q] * (gv[0] * p->x[0][q] + gv[1] * p->x[1][q] + gv[2] * p->x[2][q]);
    }
}

void lm3_membrane_momentum(const lm3_sim *sim, double P[3])
{
    if (!sim->mem) return;
    const lm3_mpoints *p = &sim->mem->p;
    for (int a = 0; a < 3; a++)
        for (size_t q = 0; q < p->n; q++) P[a] += p->m[q] * p->v[a][q];
}

double lm3_membrane_damped(const lm3_sim *sim)
{
    return sim->mem ? sim->mem->damped : 0;
}

double lm3_membrane_mass(const lm3_sim *sim)
{
    double m = 0;
    for (size_t q = 0; sim->mem && q < sim->mem->p.n; q++) m += sim->mem->p.m[q];
    return m;
}
