/* sim3_state.c - a 3D run's state as bytes, for checkpoints and
 * `lamina run --restart` (src/lua/l_checkpoint.c frames it as it frames the
 * 2D engine's, checkpoint.c). What a step reads from the step before: the
 * clock, the live settings (dt, gravity, courant), the materials and every
 * particle's x, v, m, rho, sigma, material; the stencils (node, d) are
 * rebuilt by the next step's place phase and the grid is recomputed from
 * the particles, so a restarted run takes the same steps bit for bit.
 *
 * Layout: "LM3STATE", uint32 version, uint32 materials, uint64 particles,
 * uint64 the whole part's bytes, uint64 membrane points, uint32 membranes,
 * uint32 membrane pins (version 3: the membranes, issue 34 item 2), then
 * doubles (t, dt, gravity[3], courant, and per material its MAT_DOUBLES
 * constants, the kind among them), int64 nstep, ARRAYS arrays of n doubles
 * (x, v, m, rho, sigma, the gas's e), n material bytes, then the
 * membranes' part (sim3_membrane_state.c). Native byte order: a checkpoint
 * is read back on the machine that wrote it (as the 2D one). */
#include <stdio.h>
#include <string.h>

#include "mpm3.h"
#include "mpm3_membrane.h"

#define MAGIC "LM3STATE"
#define HEAD (8 + 4 + 4 + 8 + 8 + 8 + 4 + 4)
#define MAT_DOUBLES 12
#define ARRAYS 15

static size_t bytes_for(size_t nmat, size_t n)
{
    return HEAD + (6 + MAT_DOUBLES * nmat) * sizeof(double) + sizeof(int64_t) +
           n * (ARRAYS * sizeof(double) + 1);
}

size_t lm3_state_bytes(const lm3_sim *sim)
{
    uint64_t np;
    uint32_t nmem, npins;
    lm3_mstate_counts(sim, &np, &nmem, &npins);
    return bytes_for((size_t)sim->nmat, sim->p.n) + lm3_mstate_bytes(np, nmem, npins);
}

/* the particle arrays in their saved order */
static void arrays_of(const lm3_particles *p, double *a[ARRAYS])
{
    for (int k = 0; k < 3; k++) {
        a[k] = p->x[k];
        a[3 + k] = p->v[k];
    }
    a[6] = p->m;
    a[7] = p->rho;
    for (int c = 0; c < 6; c++) a[8 + c] = p->s[c];
    a[14] = p->e;
}

/* a material's constants as doubles (live: sim:material may change them) */
static void mat_pack(const lm3_material *m, double d[MAT_DOUBLES])
{
    double v[MAT_DOUBLES] = {m->rho, m->E, m->nu, (double)m->kind, m->gamma, m->mu, m->e0,
                             (double)m->av, m->av_c1, m->av_c2, m->av_lambda, m->av_g};
    memcpy(d, v, sizeof v);
}

static void mat_unpack(const double d[MAT_DOUBLES], lm3_material *m)
{
    m->rho = d[0];
    m->E = d[1];
    m->nu = d[2];
    m->kind = (lm3_kind)(int)d[3];
    m->gamma = d[4];
    m->mu = d[5];
    m->e0 = d[6];
    m->av = (int)d[7];
    m->av_c1 = d[8];
    m->av_c2 = d[9];
    m->av_lambda = d[10];
    m->av_g = d[11];
}

void lm3_state_save(const lm3_sim *sim, unsigned char *buf)
{
    unsigned char *b = buf;
    uint32_t version = LM3_STATE_VERSION, nmat = (uint32_t)sim->nmat;
    uint64_t n = sim->p.n, total = lm3_state_bytes(sim);
    memcpy(b, MAGIC, 8); b += 8;
    memcpy(b, &version, 4); b += 4;
    memcpy(b, &nmat, 4); b += 4;
    memcpy(b, &n, 8); b += 8;
    memcpy(b, &total, 8); b += 8;
    uint64_t np;
    uint32_t nmem, npins;
    lm3_mstate_counts(sim, &np, &nmem, &npins);
    memcpy(b, &np, 8); b += 8;
    memcpy(b, &nmem, 4); b += 4;
    memcpy(b, &npins, 4); b += 4;
    const lm3_def *d = &sim->def;
    double head[6] = {sim->t, d->dt, d->gravity[0], d->gravity[1], d->gravity[2], d->courant};
    memcpy(b, head, sizeof head); b += sizeof head;
    for (int k = 0; k < sim->nmat; k++) {
        double m[MAT_DOUBLES];
        mat_pack(&sim->mats[k], m);
        memcpy(b, m, sizeof m); b += sizeof m;
    }
    int64_t step = sim->nstep;
    memcpy(b, &step, sizeof step); b += sizeof step;
    double *a[ARRAYS];
    arrays_of(&sim->p, a);
    for (int k = 0; k < ARRAYS; k++) {
        if (n) memcpy(b, a[k], n * sizeof(double));
        b += n * sizeof(double);
    }
    if (n) memcpy(b, sim->p.mat, n);
    lm3_mstate_save(sim, b + n);
}

size_t lm3_state_claimed(const unsigned char *buf, size_t len)
{
    if (len < HEAD || memcmp(buf, MAGIC, 8) != 0) return 0;
    uint32_t version, nmat;
    uint64_t n, total;
    memcpy(&version, buf + 8, 4);
    memcpy(&nmat, buf + 12, 4);
    memcpy(&n, buf + 16, 8);
    memcpy(&total, buf + 24, 8);
    uint64_t np;
    uint32_t nmem, npins;
    memcpy(&np, buf + 32, 8);
    memcpy(&nmem, buf + 40, 4);
    memcpy(&npins, buf + 44, 4);
    if (version != LM3_STATE_VERSION || nmat > LM3_MAX_MATERIALS || nmem > LM3_MAX_MEMBRANES ||
        npins > LM3_MAX_MEMBRANES)
        return 0;
    /* the counts must be the ones the total implies (no overflow: n and np
     * are bounded by the total, itself bounded by the file's size) */
    size_t fixed = bytes_for(nmat, 0) + lm3_mstate_bytes(0, nmem, npins);
    if (total < fixed || n > (total - fixed) / (ARRAYS * sizeof(double) + 1) ||
        np > (total - fixed) / lm3_mstate_bytes(1, 0, 0) ||
        total != bytes_for(nmat, (size_t)n) + lm3_mstate_bytes(np, nmem, npins))
        return 0;
    return (size_t)total;
}

lm_status lm3_state_load(lm3_sim *sim, const unsigned char *buf, size_t len)
{
    size_t total = lm3_state_claimed(buf, len);
    if (total == 0 || total > len) {
        snprintf(sim->err, sizeof sim->err, "not a 3D simulation's state (or a damaged one)");
        return LM_ERR_INPUT;
    }
    uint32_t nmat, nmem, npins;
    uint64_t n, np;
    memcpy(&nmat, buf + 12, 4);
    memcpy(&n, buf + 16, 8);
    memcpy(&np, buf + 32, 8);
    memcpy(&nmem, buf + 40, 4);
    memcpy(&npins, buf + 44, 4);
    /* the script rebuilt its bodies before the state replaces them: the
     * same particles and materials, or it is another script */
    if (n != sim->p.n || (int)nmat != sim->nmat) {
        snprintf(sim->err, sizeof sim->err, "does not fit the script: it holds %llu particles "
                 "of %u materials, the script's simulation %zu of %d",
                 (unsigned long long)n, nmat, sim->p.n, sim->nmat);
        return LM_ERR_INPUT;
    }
    const unsigned char *b = buf + HEAD;
    double head[6];
    memcpy(head, b, sizeof head); b += sizeof head;
    lm3_material mats[LM3_MAX_MATERIALS];
    for (uint32_t k = 0; k < nmat; k++) {
        double m[MAT_DOUBLES];
        memcpy(m, b, sizeof m); b += sizeof m;
        mats[k] = sim->mats[k];
        mat_unpack(m, &mats[k]);
        if (mats[k].kind != sim->mats[k].kind) {
            snprintf(sim->err, sizeof sim->err, "does not fit the script: its material %u is "
                     "%s, the script's %s", k, mats[k].kind == LM3_GAS ? "a gas" : "a solid",
                     sim->mats[k].kind == LM3_GAS ? "a gas" : "a solid");
            return LM_ERR_INPUT;
        }
    }
    int64_t step;
    memcpy(&step, b, sizeof step); b += sizeof step;
    const unsigned char *mat = b + ARRAYS * n * sizeof(double);
    for (uint64_t q = 0; q < n; q++)
        if (mat[q] >= nmat) {
            snprintf(sim->err, sizeof sim->err, "is damaged: particle %llu has material %u of "
                     "%u", (unsigned long long)q, mat[q], nmat);
            return LM_ERR_INPUT;
        }
    /* the membranes, checked then replaced (nothing if refused); the
     * particles below are checked already */
    if (lm3_mstate_load(sim, mat + n, np, nmem, npins) != LM_OK) return LM_ERR_INPUT;
    /* checked: now replace */
    sim->t = head[0];
    sim->def.dt = head[1];
    for (int a = 0; a < 3; a++) sim->def.gravity[a] = head[2 + a];
    sim->def.courant = head[5];
    memcpy(sim->mats, mats, nmat * sizeof *mats);
    sim->nstep = (long)step;
    double *a[ARRAYS];
    arrays_of(&sim->p, a);
    for (int k = 0; k < ARRAYS; k++) {
        if (n) memcpy(a[k], b, n * sizeof(double));
        b += n * sizeof(double);
    }
    if (n) memcpy(sim->p.mat, b, n);
    sim->recheck = 1;      /* the particles moved: the next step looks at them */
    return LM_OK;
}
