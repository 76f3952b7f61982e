/* fields.c - the table of particle quantities (fields.h, issue 33 item 2).
 *
 * One definition per quantity, read by frames, sim:vtk, sim:record and
 * body:particles(). The one that used to differ between them is the
 * pressure: a gas particle's is its equation of state, p = (gamma - 1)
 * rho e ([F] eq 22), without the artificial viscosity q, which is no state
 * of the gas but a term of the step's stress ([F] eq 24); its stress is
 * -(p^k + q) I plus the viscous part, so -tr sigma / 3 would add q and use
 * e of the step before. Every other body's pressure is the mean stress
 * -tr sigma / 3 (with sigma_zz: plane strain or the hoop stress), which
 * for the linear fluid is its p = -beta div U ([F] eq 26). */
#include <math.h>
#include <string.h>

#include "fields.h"
#include "step.h"

static void position(const lm_sim *s, size_t q, double *o)
{
    o[0] = s->p.x[q];
    o[1] = s->p.y[q];
}

static void velocity(const lm_sim *s, size_t q, double *o)
{
    o[0] = s->p.vx[q];
    o[1] = s->p.vy[q];
}

/* the global Cauchy stress, in VTK's order of the symmetric tensor's
 * first four components (XX, YY, ZZ, XY) */
static void stress(const lm_sim *s, size_t q, double *o)
{
    o[0] = s->p.sxx[q];
    o[1] = s->p.syy[q];
    o[2] = s->p.szz[q];
    o[3] = s->p.sxy[q];
}

static void pressure(const lm_sim *s, size_t q, double *o)
{
    const lm_particles *p = &s->p;
    const lm_material *mat = s->mats[p->mat[q]];
    o[0] = mat->kind == LM_GAS ? (mat->gamma - 1) * p->rho[q] * p->e[q]
                               : -(p->sxx[q] + p->syy[q] + p->szz[q]) / 3.0;
}

static void density(const lm_sim *s, size_t q, double *o) { o[0] = s->p.rho[q]; }
static void energy(const lm_sim *s, size_t q, double *o) { o[0] = s->p.e[q]; }
static void mass(const lm_sim *s, size_t q, double *o) { o[0] = s->p.m[q]; }
static void body(const lm_sim *s, size_t q, double *o) { o[0] = s->p.body[q] + 1; }
static void viscosity(const lm_sim *s, size_t q, double *o) { o[0] = s->p.q[q]; }
static void volumetric(const lm_sim *s, size_t q, double *o) { o[0] = s->p.ev[q]; }
static void strain(const lm_sim *s, size_t q, double *o) { o[0] = s->p.et[q]; }
static void length(const lm_sim *s, size_t q, double *o) { o[0] = s->p.ds[q]; }

/* the tangent turned +90 degrees ([M] section 3) */
static void normal(const lm_sim *s, size_t q, double *o)
{
    o[0] = -s->p.ty[q];
    o[1] = s->p.tx[q];
}

static void speed(const lm_sim *s, size_t q, double *o)
{
    o[0] = hypot(s->p.vx[q], s->p.vy[q]);
}

/* the in-plane principal stresses, s1 >= s2: the eigenvalues of the 2 x 2
 * block, centre (sxx + syy) / 2 plus or minus Mohr's radius */
static void principal(const lm_sim *s, size_t q, double *o)
{
    const lm_particles *p = &s->p;
    double c = 0.5 * (p->sxx[q] + p->syy[q]);
    double r = hypot(0.5 * (p->sxx[q] - p->syy[q]), p->sxy[q]);
    o[0] = c + r;
    o[1] = c - r;
}

/* t . sigma . t, a membrane point's tangential stress */
static double tangential(const lm_particles *p, size_t q)
{
    return p->tx[q] * p->tx[q] * p->sxx[q] + 2.0 * p->tx[q] * p->ty[q] * p->sxy[q] +
           p->ty[q] * p->ty[q] * p->syy[q];
}

static void membrane_stress(const lm_sim *s, size_t q, double *o)
{
    o[0] = tangential(&s->p, q);
}

/* force per length, sigma_t times the thickness: the engine's membrane
 * keeps its material thickness (its strain lives in its length,
 * docs/physics.md), the F = sigma_t thickness of the segment forces
 * (membrane_force.c) */
static void tension(const lm_sim *s, size_t q, double *o)
{
    o[0] = tangential(&s->p, q) * s->mats[s->p.mat[q]]->thickness;
}

static void kinetic_density(const lm_sim *s, size_t q, double *o)
{
    const lm_particles *p = &s->p;
    o[0] = 0.5 * p->rho[q] * (p->vx[q] * p->vx[q] + p->vy[q] * p->vy[q]);
}

/* the stored energy per current volume, as sim:energy() sums it (diag.c):
 * a solid's 1/2 sigma : C^-1 : sigma, a membrane point's by its law (the
 * point form, also for segment-force membranes, whose sim:energy() sums
 * the segments), the linear fluid's 1/2 beta ev^2 per undeformed volume */
static void strain_density(const lm_sim *s, size_t q, double *o)
{
    const lm_particles *p = &s->p;
    const lm_material *mat = s->mats[p->mat[q]];
    double V = p->m[q] / p->rho[q];
    switch (mat->kind) {
    case LM_ELASTIC:
        o[0] = lm_elastic_energy_density(mat, p->sxx[q], p->syy[q], p->sxy[q], p->szz[q]);
        break;
    case LM_MEMBRANE:
        o[0] = s->def.axisym ? lm_axisym_membrane_energy(s, q) / V
                             : lm_membrane_energy(mat, 1.0, p->et[q]);
        break;
    case LM_LINEAR_FLUID:
        o[0] = 0.5 * mat->beta * p->ev[q] * p->ev[q] / (1 + p->ev[q]);
        break;
    default:
        o[0] = 0;
    }
}

static void internal_density(const lm_sim *s, size_t q, double *o)
{
    o[0] = s->p.rho[q] * s->p.e[q];
}

#define ALL LM_FIELD_ALL
#define MEM LM_FIELD_MEMBRANE
/* name, unit, meaning, ncomp, components, alias, vtk, kinds, diverging,
 * tangents, evaluator */
static const lm_field table[] = {
    { "position", "L", "the particle's position", 2, { "x", "y" }, NULL, NULL, ALL, 0, 0,
      position },
    { "velocity", "L/T", "the particle's velocity", 2, { "vx", "vy" }, NULL, "velocity", ALL,
      1, 0, velocity },
    { "stress", "F/L^2",
      "the global Cauchy stress (szz out of plane; axisymmetric: the hoop stress)", 4,
      { "sxx", "syy", "szz", "sxy" }, NULL, "stress", ALL, 1, 0, stress },
    { "pressure", "F/L^2",
      "gas: its equation of state (gamma - 1) rho e, without q; other bodies: -tr sigma / 3",
      1, { NULL }, "p", "pressure", ALL, 0, 0, pressure },
    { "rho", "M/L^3", "the density (the volume is mass / rho)", 1, { NULL }, NULL, "density",
      ALL, 0, 0, density },
    { "e", "E/M", "the gas's specific internal energy", 1, { NULL }, NULL, "energy",
      LM_FIELD_GAS, 0, 0, energy },
    { "mass", "M", "the particle's mass", 1, { NULL }, NULL, "mass", ALL, 0, 0, mass },
    { "body", "1", "the body's index, 1-based", 1, { NULL }, NULL, "body", ALL, 0, 0, body },
    { "normal", "1", "a membrane's unit normal, the tangent turned +90 degrees", 2,
      { "nx", "ny" }, NULL, "normal", MEM, 1, 1, normal },
    { "speed", "L/T", "the magnitude of the velocity", 1, { NULL }, NULL, NULL, ALL, 0, 0,
      speed },
    { "principal", "F/L^2", "the in-plane principal stresses, s1 >= s2", 2, { "s1", "s2" },
      NULL, NULL, ALL, 1, 0, principal },
    { "q", "F/L^2", "the gas's artificial viscosity of the last step", 1, { NULL }, NULL,
      NULL, LM_FIELD_GAS, 0, 0, viscosity },
    { "ev", "1", "the linear fluid's volumetric strain div U", 1, { NULL }, NULL, NULL,
      LM_FIELD_FLUID, 1, 0, volumetric },
    { "strain", "1", "a membrane's tangential strain eps_t", 1, { NULL }, "et", NULL, MEM, 1,
      0, strain },
    { "ds", "L", "the length of membrane a point stands for", 1, { NULL }, NULL, NULL, MEM,
      0, 0, length },
    { "tension", "F/L", "a membrane's tension, t.sigma.t times its thickness", 1, { NULL },
      NULL, NULL, MEM, 1, 1, tension },
    { "membrane_stress", "F/L^2", "a membrane's tangential stress t.sigma.t", 1, { NULL },
      NULL, NULL, MEM, 1, 1, membrane_stress },
    { "kinetic_energy_density", "E/L^3", "1/2 rho v.v", 1, { NULL }, NULL, NULL, ALL, 0, 0,
      kinetic_density },
    { "strain_energy_density", "E/L^3",
      "stored energy per volume: a solid's 1/2 sigma:C^-1:sigma, a membrane point's by its "
      "law, the linear fluid's 1/2 beta ev^2 / (1 + ev)",
      1, { NULL }, NULL, NULL, LM_FIELD_ELASTIC | MEM | LM_FIELD_FLUID, 0, 0,
      strain_density },
    { "internal_energy_density", "E/L^3", "the gas's rho e", 1, { NULL }, NULL, NULL,
      LM_FIELD_GAS, 0, 0, internal_density },
};

int lm_field_count(void)
{
    return (int)(sizeof table / sizeof table[0]);
}

const lm_field *lm_field_get(int i)
{
    return i >= 0 && i < lm_field_count() ? &table[i] : NULL;
}

const lm_field *lm_field_find(const char *name, int *comp)
{
    for (int i = 0; i < lm_field_count(); i++) {
        const lm_field *f = &table[i];
        if (f->ncomp == 1 && strcmp(f->name, name) == 0) {
            if (comp) *comp = 0;
            return f;
        }
        for (int c = 0; f->ncomp > 1 && c < f->ncomp; c++)
            if (strcmp(f->comp[c], name) == 0) {
                if (comp) *comp = c;
                return f;
            }
    }
    return NULL;
}

int lm_field_has(const lm_sim *sim, const lm_field *f, size_t q)
{
    return (f->kinds >> sim->mats[sim->p.mat[q]]->kind) & 1u;
}

double lm_field_value(const lm_sim *sim, const lm_field *f, int comp, size_t q)
{
    double v[LM_FIELD_MAX_COMP];
    if (!lm_field_has(sim, f, q)) return 0;
    f->at(sim, q, v);
    return v[comp];
}

void lm_field_fill(const lm_sim *sim, const lm_field *f, int comp, size_t first, size_t n,
                   double *out)
{
    double v[LM_FIELD_MAX_COMP];
    for (size_t i = 0; i < n; i++) {
        size_t q = first + i;
        if (lm_field_has(sim, f, q)) f->at(sim, q, v);
        else memset(v, 0, sizeof v);
        if (comp >= 0) {
            out[i] = v[comp];
        } else {
            for (int c = 0; c < f->ncomp; c++) out[(size_t)f->ncomp * i + (size_t)c] = v[c];
        }
    }
}
