/* test_fields.c - the table of particle quantities (src/mpm/fields.c,
 * issue 33 item 2): every entry is whole (name, unit, meaning, components,
 * kinds, evaluator), every name is found once, and the evaluators agree
 * with closed forms on hand-made particles of each kind:
 *
 *   0 elastic, uniaxial stress s along a line at 30 degrees (plane stress):
 *     sxx = s c^2, syy = s s^2, sxy = s c s; principal s1 = s, s2 = 0;
 *     pressure -s/3; strain energy density s^2 / (2E)
 *   1 gas, rho e with q > 0 and the step's stress -(p + q) I: pressure
 *     (gamma - 1) rho e ([F] eq 22), not the mean stress p + q
 *   2 linear fluid, ev: pressure -beta ev ([F] eq 26); energy 1/2 beta
 *     ev^2 / (1 + ev)
 *   3 membrane, tangent at 60 degrees and strain et (linear law, [T] eq
 *     5.9): t.sigma.t = E et, tension E et thickness, normal (-ty, tx),
 *     energy density 1/2 E et^2
 *
 * With a path (docs/api.md) it checks instead that the doc's table of
 * particle fields is the one the table makes (row_of below), so the doc
 * cannot drift; a mismatch prints the rows to paste. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "fields.h"

#define N 4

static double col(const char *name, const lm_sim *sim, size_t q)
{
    int c;
    const lm_field *f = lm_field_find(name, &c);
    CHECK(f != NULL);
    if (!f) return NAN;
    double one;
    lm_field_fill(sim, f, c, q, 1, &one);
    CHECK(one == lm_field_value(sim, f, c, q));   /* the two readers agree */
    return one;
}

static void table_is_whole(void)
{
    int n = lm_field_count();
    CHECK(n > 10);
    CHECK(lm_field_get(-1) == NULL && lm_field_get(n) == NULL);
    const char *seen[64];
    int nseen = 0;
    for (int i = 0; i < n; i++) {
        const lm_field *f = lm_field_get(i);
        CHECK(f->name && *f->name && f->unit && *f->unit && f->meaning && *f->meaning);
        CHECK(f->ncomp >= 1 && f->ncomp <= LM_FIELD_MAX_COMP && f->at != NULL);
        CHECK(f->kinds != 0 && (f->kinds & ~(unsigned)LM_FIELD_ALL) == 0);
        for (int c = 0; c < f->ncomp; c++) {
            const char *nm = f->ncomp == 1 ? f->name : f->comp[c];
            CHECK(nm && *nm);
            if (!nm) continue;
            int cc = -1;
            CHECK(lm_field_find(nm, &cc) == f && cc == c);   /* found, and only there */
            for (int k = 0; k < nseen; k++) CHECK(strcmp(seen[k], nm) != 0);
            if (nseen < 64) seen[nseen++] = nm;
        }
        if (f->alias) {   /* an older key must not be another field's name */
            CHECK(f->ncomp == 1 && lm_field_find(f->alias, NULL) == NULL);
        }
    }
    CHECK(lm_field_find("no such field", NULL) == NULL);
    /* a vector's name is not a component: frames and records take "vx" */
    CHECK(lm_field_find("velocity", NULL) == NULL);
}

static const char *kinds_text(unsigned k)
{
    if (k == LM_FIELD_ALL) return "all";
    static char buf[96];
    buf[0] = 0;
    const char *names[] = {NULL, "elastic", "membrane", "gas", "linear fluid"};
    for (int i = 1; i <= 4; i++)
        if (k & (1u << i)) {
            if (buf[0]) strcat(buf, ", ");
            strcat(buf, names[i]);
        }
    return buf;
}

/* One row of docs/api.md's table: name (and the older particles() key),
 * components, unit, bodies, VTK array, meaning. */
static void row_of(const lm_field *f, char *out, size_t len)
{
    char name[96], comps[128] = "";
    if (f->alias) snprintf(name, sizeof name, "`%s` (`%s`)", f->name, f->alias);
    else snprintf(name, sizeof name, "`%s`", f->name);
    for (int c = 0; f->ncomp > 1 && c < f->ncomp; c++) {
        char one[40];
        snprintf(one, sizeof one, "%s`%s`", c ? ", " : "", f->comp[c]);
        strcat(comps, one);
    }
    char vtk[64];
    if (f->vtk) snprintf(vtk, sizeof vtk, "`%s`", f->vtk);
    else snprintf(vtk, sizeof vtk, "-");
    snprintf(out, len, "| %s | %s | %s | %s | %s | %s |", name, f->ncomp > 1 ? comps : "-",
             f->unit, kinds_text(f->kinds), vtk, f->meaning);
}

#define BEGIN "<!-- fields table: made by tests/unit/test_fields.c from src/mpm/fields.c -->"
#define END "<!-- fields table end -->"

static int doc_matches(const char *path)
{
    FILE *fp = fopen(path, "r");
    if (!fp) {
        fprintf(stderr, "test_fields: cannot open %s\n", path);
        return 1;
    }
    static char doc[1 << 20];
    size_t n = fread(doc, 1, sizeof doc - 1, fp);
    fclose(fp);
    doc[n] = 0;
    char *at = strstr(doc, BEGIN), *end = at ? strstr(at, END) : NULL;
    CHECK(at && end);
    if (!at || !end) return CHECK_DONE();
    /* past the marker and the two header lines */
    at = strchr(at, '\n');
    for (int k = 0; at && k < 2; k++) at = strchr(at + 1, '\n');
    CHECK(at != NULL);
    if (!at) return CHECK_DONE();
    at++;
    char want[1 << 14] = "", row[1024];
    for (int i = 0; i < lm_field_count(); i++) {
        row_of(lm_field_get(i), row, sizeof row);
        strcat(want, row);
        strcat(want, "\n");
    }
    size_t got = (size_t)(end - at);
    if (got != strlen(want) || strncmp(at, want, got) != 0) {
        fprintf(stderr, "test_fields: %s's table of particle fields is not the engine's; "
                        "its rows should read:\n%s", path, want);
        check_failures++;
    }
    return CHECK_DONE();
}

int main(int argc, char **argv)
{
    if (argc > 1) return doc_matches(argv[1]);
    table_is_whole();

    lm_material el = {.kind = LM_ELASTIC, .rho = 1000, .E = 1e5, .nu = 0.3,
                      .plane = LM_PLANE_STRESS};
    lm_material gas = {.kind = LM_GAS, .rho = 1, .gamma = 1.4};
    lm_material fl = {.kind = LM_LINEAR_FLUID, .rho = 1000, .beta = 1e3};
    lm_material mem = {.kind = LM_MEMBRANE, .rho = 500, .E = 2e6, .nu = 0.3,
                       .thickness = 0.01, .law = LM_LAW_UNIAXIAL};
    lm_material *mats[N] = {&el, &gas, &fl, &mem};
    double x[N] = {0.1, 0.2, 0.3, 0.4}, y[N] = {0.5, 0.6, 0.7, 0.8};
    double vx[N] = {3, 0, 0, 0}, vy[N] = {-4, 0, 0, 0};
    double m[N] = {2, 0.1, 1, 0.5}, rho[N] = {1000, 2, 990, 500};
    double sxx[N], syy[N], sxy[N], szz[N];
    double et[N] = {0, 0, 0, 0.02}, ds[N] = {0, 0, 0, 0.05}, tx[N] = {0}, ty[N] = {0};
    double e[N] = {0, 3, 0, 0}, qv[N] = {0, 0.7, 0, 0}, ev[N] = {0, 0, -0.01, 0};
    int body[N] = {0, 1, 2, 3}, mat[N] = {0, 1, 2, 3};

    /* 0: uniaxial stress s along 30 degrees */
    double s = 50, a = acos(-1.0) / 6, c = cos(a), sn = sin(a);
    sxx[0] = s * c * c; syy[0] = s * sn * sn; sxy[0] = s * c * sn; szz[0] = 0;
    /* 1: the gas's step stress -(p + q) I (no shear), p its equation of state */
    double p_gas = (1.4 - 1) * rho[1] * e[1];
    sxx[1] = syy[1] = szz[1] = -(p_gas + qv[1]); sxy[1] = 0;
    /* 2: the linear fluid's p = -beta ev in every direction */
    double p_fl = -fl.beta * ev[2];
    sxx[2] = syy[2] = szz[2] = -p_fl; sxy[2] = 0;
    /* 3: membrane along 60 degrees, sigma_t = E et as t t^T */
    double b = acos(-1.0) / 3, st = mem.E * et[3];
    tx[3] = cos(b); ty[3] = sin(b);
    sxx[3] = st * tx[3] * tx[3]; syy[3] = st * ty[3] * ty[3]; sxy[3] = st * tx[3] * ty[3];
    szz[3] = 0;

    lm_sim sim;
    memset(&sim, 0, sizeof sim);
    sim.mats = mats;
    sim.nmats = N;
    lm_particles *p = &sim.p;
    p->n = N;
    p->x = x; p->y = y; p->vx = vx; p->vy = vy; p->m = m; p->rho = rho;
    p->sxx = sxx; p->syy = syy; p->sxy = sxy; p->szz = szz;
    p->et = et; p->ds = ds; p->tx = tx; p->ty = ty;
    p->e = e; p->q = qv; p->ev = ev; p->body = body; p->mat = mat;

    const double tol = 1e-12;
    /* 0: elastic */
    CHECK_NEAR(col("s1", &sim, 0), s, tol * s);
    CHECK_NEAR(col("s2", &sim, 0), 0, tol * s);
    CHECK_NEAR(col("pressure", &sim, 0), -s / 3, tol * s);
    CHECK_NEAR(col("strain_energy_density", &sim, 0), s * s / (2 * el.E), tol);
    CHECK_NEAR(col("speed", &sim, 0), 5, tol);
    CHECK_NEAR(col("kinetic_energy_density", &sim, 0), 0.5 * 1000 * 25, tol);
    CHECK(col("x", &sim, 0) == 0.1 && col("vy", &sim, 0) == -4 && col("sxy", &sim, 0) == sxy[0]);
    CHECK(col("mass", &sim, 0) == 2 && col("rho", &sim, 0) == 1000 && col("body", &sim, 0) == 1);
    CHECK(col("e", &sim, 0) == 0 && col("tension", &sim, 0) == 0 && col("nx", &sim, 0) == 0);
    /* 1: gas - the equation of state, not the step's mean stress p + q */
    CHECK_NEAR(col("pressure", &sim, 1), 2.4, tol);
    CHECK(fabs(-(sxx[1] + syy[1] + szz[1]) / 3 - col("pressure", &sim, 1)) > 0.5);
    CHECK_NEAR(col("internal_energy_density", &sim, 1), 6, tol);
    CHECK(col("q", &sim, 1) == 0.7 && col("e", &sim, 1) == 3);
    /* a gas has no strain energy: its energy is internal */
    CHECK(col("strain_energy_density", &sim, 1) == 0);
    /* 2: linear fluid */
    CHECK_NEAR(col("pressure", &sim, 2), 10, tol);
    CHECK_NEAR(col("strain_energy_density", &sim, 2), 0.5 * 1e3 * 1e-4 / 0.99, tol);
    CHECK(col("ev", &sim, 2) == -0.01 && col("q", &sim, 2) == 0);
    /* 3: membrane */
    CHECK_NEAR(col("membrane_stress", &sim, 3), st, tol * st);
    CHECK_NEAR(col("tension", &sim, 3), st * mem.thickness, tol * st);
    CHECK_NEAR(col("nx", &sim, 3), -sin(b), tol);
    CHECK_NEAR(col("ny", &sim, 3), cos(b), tol);
    CHECK_NEAR(col("strain_energy_density", &sim, 3), 0.5 * mem.E * et[3] * et[3], tol * st);
    CHECK_NEAR(col("s1", &sim, 3), st, tol * st);   /* the tangent is a principal direction */
    CHECK(col("strain", &sim, 3) == 0.02 && col("ds", &sim, 3) == 0.05);
    /* which kinds have what */
    int comp;
    const lm_field *fe = lm_field_find("e", &comp);
    CHECK(lm_field_has(&sim, fe, 1) && !lm_field_has(&sim, fe, 0));
    CHECK(lm_field_has(&sim, lm_field_find("tension", &comp), 3) &&
          !lm_field_has(&sim, lm_field_find("tension", &comp), 2));
    /* all components at once, interleaved */
    double all[4 * N];
    lm_field_fill(&sim, lm_field_find("sxx", &comp), -1, 0, N, all);
    for (size_t q = 0; q < N; q++) {
        CHECK(all[4 * q] == sxx[q] && all[4 * q + 1] == syy[q]);
        CHECK(all[4 * q + 2] == szz[q] && all[4 * q + 3] == sxy[q]);
    }
    return CHECK_DONE();
}
