/* checkpoint.c - the state a run needs to continue bit for bit, as bytes
 * (the engine does no I/O: the binding writes and reads the file).
 *
 * What continues a run exactly: the clock (t, step, the base of the exact
 * t = t_base + (step - step_base) dt, dt itself), the settings a script can
 * change live (gravity, pic, courant), every material's parameters (a
 * callback may have changed them), each body's extent and flags (gas
 * splitting moves bodies and adds particles), the pins' velocities, and
 * every per-particle array the next step reads before writing. Not stored,
 * because each step rebuilds them before use: the grid's nodal fields, the
 * shape functions, the cell densities, the segment forces (fpx, fpy).
 *
 * Layout: a fixed header (magic, format version, sizes to check against
 * the simulation the script built), then little blocks in a fixed order.
 * Doubles and integers are copied in this machine's byte order; the header
 * records it, and a checkpoint from a machine of the other order is
 * refused.
 *
 * A checkpoint is untrusted input (issue 31 item 3: 16 of 343 mutated
 * checkpoints crashed the release build): lm_sim_state_load checks every
 * size against the bytes before reading (no n * size wraps), every body's
 * extent within the particles (no first + count wrap) and against the
 * script's scene (a body keeps its point count; only a splitting gas may
 * have more), every particle's body, material and pin index, every float
 * finite and in range (t >= 0, dt > 0, masses > 0, the materials' own
 * checks), and only then changes the simulation; a refusal names the first
 * difference. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "particles.h"
#include "step.h"
#include "util.h"

#define MAGIC 0x4b434d4cu   /* "LMCK" */

/* The per-particle double arrays, in file order. */
static int particle_doubles(lm_particles *p, double **a)
{
    double *const d[] = {p->x, p->y, p->vx, p->vy, p->m, p->rho, p->sxx, p->syy, p->sxy,
                         p->szz, p->et, p->ds, p->tx, p->ty, p->e, p->q, p->ev, p->lx, p->ly,
                         p->L0, p->r0};
    int n = (int)(sizeof d / sizeof d[0]);
    for (int k = 0; k < n; k++) a[k] = d[k];
    return n;
}
#define NDOUBLES 21

typedef struct header {
    uint32_t magic, version, endian, nmats;
    int32_t nbodies, npins, nx, ny, basis;
    uint32_t axisym;            /* the form: plane 0, axisymmetric 1 */
    int32_t nlinks, pad;        /* version 3 */
    uint64_t n;                 /* particles */
    double hx, hy;
} header;

typedef struct body_rec {
    uint64_t first, count;
    int32_t mat, membrane, closed, force, normals, orient, seg_ready, pad;   /* pad: side */
    double ox, oy, pe_ref;
} body_rec;

typedef struct clock_rec {
    double t, t_base, dt, pe_ref, gx, gy, pic, courant;
    int64_t step, step_base;
    int32_t prepared, pad;
} clock_rec;

typedef struct pin_rec {
    double vx, vy, rx, ry;   /* in this order: check_state and the restore read them by index */
} pin_rec;
_Static_assert(sizeof(pin_rec) == 4 * sizeof(double), "a pin's record is four doubles");

/* A link's state: a script may remove it (or change nothing else) mid-run. */
typedef struct link_rec {
    double k, L0;
    int32_t active, pad;
} link_rec;

static uint32_t endian_mark(void)
{
    const uint32_t one = 1;
    return *(const unsigned char *)&one ? 1u : 2u;
}

size_t lm_sim_state_bytes(const lm_sim *sim)
{
    size_t n = sim->p.n;
    return sizeof(header) + sizeof(clock_rec) + (size_t)sim->nmats * sizeof(lm_material) +
           (size_t)sim->nbodies * sizeof(body_rec) + (size_t)sim->npins * sizeof(pin_rec) +
           (size_t)sim->nlinks * sizeof(link_rec) + n * (NDOUBLES * sizeof(double) + 3 * sizeof(int32_t));
}

static unsigned char *put(unsigned char *b, const void *v, size_t n)
{
    memcpy(b, v, n);
    return b + n;
}

/* put's reverse, for the restore: n bytes at b into v, and the next place. */
static const unsigned char *take(void *v, const unsigned char *b, size_t n)
{
    memcpy(v, b, n);
    return b + n;
}

void lm_sim_state_save(const lm_sim *sim, unsigned char *buf)
{
    lm_particles *p = (lm_particles *)&sim->p;   /* read only: the arrays' addresses */
    header h = {MAGIC, LM_CHECKPOINT_VERSION, endian_mark(), (uint32_t)sim->nmats,
                sim->nbodies, sim->npins, sim->grid.nx, sim->grid.ny, (int32_t)sim->def.basis,
                (uint32_t)(sim->def.axisym != 0), sim->nlinks, 0, (uint64_t)p->n, sim->grid.hx,
                sim->grid.hy};
    unsigned char *b = put(buf, &h, sizeof h);
    clock_rec c = {sim->t, sim->t_base, sim->def.dt, sim->pe_ref, sim->def.gx, sim->def.gy,
                   sim->def.pic, sim->def.courant, sim->step, sim->step_base, sim->prepared, 0};
    b = put(b, &c, sizeof c);
    for (int k = 0; k < sim->nmats; k++) b = put(b, sim->mats[k], sizeof(lm_material));
    for (int k = 0; k < sim->nbodies; k++) {
        const lm_body *bd = &sim->bodies[k];
        body_rec r = {bd->first, bd->count, bd->mat, bd->membrane, bd->closed, (int32_t)bd->force,
                      (int32_t)bd->normals, bd->orient, bd->seg_ready, bd->side, bd->ox, bd->oy,
                      bd->pe_ref};
        b = put(b, &r, sizeof r);
    }
    for (int k = 0; k < sim->npins; k++) {
        pin_rec r = {sim->pins[k].vx, sim->pins[k].vy, sim->pins[k].rx, sim->pins[k].ry};
        b = put(b, &r, sizeof r);
    }
    for (int k = 0; k < sim->nlinks; k++) {
        link_rec r = {sim->links[k].k, sim->links[k].L0, sim->links[k].active, 0};
        b = put(b, &r, sizeof r);
    }
    double *a[NDOUBLES];
    int nd = particle_doubles(p, a);
    for (int k = 0; k < nd; k++) b = put(b, a[k], p->n * sizeof(double));
    const int *ia[3] = {p->body, p->mat, p->pin};
    for (int k = 0; k < 3; k++)
        for (size_t q = 0; q < p->n; q++) {
            int32_t v = ia[k][q];
            b = put(b, &v, sizeof v);
        }
}

static lm_status refuse(lm_sim *sim, const char *why)
{
    snprintf(sim->err, sizeof sim->err, "the checkpoint does not fit this simulation: %s", why);
    return LM_ERR_INPUT;
}

/* The bytes of the state of a header claiming n particles, or 0 when the
 * counts are out of range (so no product can wrap). */
static size_t state_bytes(const header *h)
{
    if (h->n > LM_MAX_PARTICLES || h->nmats > 4096 || h->nbodies < 0 || h->nbodies > 1 << 20 ||
        h->npins < 0 || h->npins > 1 << 20 || h->nlinks < 0 || h->nlinks > LM_MAX_LINKS)
        return 0;
    return sizeof *h + sizeof(clock_rec) + (size_t)h->nmats * sizeof(lm_material) +
           (size_t)h->nbodies * sizeof(body_rec) + (size_t)h->npins * sizeof(pin_rec) +
           (size_t)h->nlinks * sizeof(link_rec) +
           (size_t)h->n * (NDOUBLES * sizeof(double) + 3 * sizeof(int32_t));
}

size_t lm_sim_state_claimed(const unsigned char *buf, size_t len)
{
    header h;
    if (len < sizeof h) return 0;
    memcpy(&h, buf, sizeof h);
    if (h.magic != MAGIC || h.version != LM_CHECKPOINT_VERSION || h.endian != endian_mark())
        return 0;
    return state_bytes(&h);
}

static double get_double(const unsigned char *b, size_t k)
{
    double v;
    memcpy(&v, b + k * sizeof v, sizeof v);
    return v;
}

static int32_t get_int(const unsigned char *b, size_t k)
{
    int32_t v;
    memcpy(&v, b + k * sizeof v, sizeof v);
    return v;
}

/* The clock, materials, bodies, pins, links and particles at b (after the
 * header) checked against themselves and the script's sim, before any is
 * used: 0, or -1 with why (the first difference). */
static int check_state(const lm_sim *sim, const unsigned char *b, size_t n, char *why,
                       size_t wl)
{
    clock_rec c;
    memcpy(&c, b, sizeof c);
    b += sizeof c;
    if (!(isfinite(c.t) && c.t >= 0 && c.t < 1e15) || !isfinite(c.t_base) ||
        !(isfinite(c.dt) && c.dt > 0 && c.dt < 1e15) || !isfinite(c.pe_ref) ||
        !isfinite(c.gx) || !isfinite(c.gy) || !(c.pic >= 0 && c.pic <= 1) ||
        !(isfinite(c.courant) && c.courant > 0) || c.step < 0 || c.step_base < 0 ||
        c.step_base > c.step || (c.prepared != 0 && c.prepared != 1)) {
        snprintf(why, wl, "its clock is out of range (t = %g, dt = %g, step %lld, gravity "
                 "%g %g, pic %g, courant %g)", c.t, c.dt, (long long)c.step, c.gx, c.gy,
                 c.pic, c.courant);
        return -1;
    }
    if ((c.t - c.t_base) / c.dt > 1e13) {   /* the steps to come could not be counted */
        snprintf(why, wl, "its time %g is %g steps of dt = %g from its base", c.t,
                 (c.t - c.t_base) / c.dt, c.dt);
        return -1;
    }
    for (int k = 0; k < sim->nmats; k++, b += sizeof(lm_material)) {
        lm_material m;
        memcpy(&m, b, sizeof m);
        char e[160];
        if (m.kind != sim->mats[k]->kind) {
            snprintf(why, wl, "material %d is of another kind", k + 1);
            return -1;
        }
        /* the switches lm_material_validate leaves to the constructors */
        if ((unsigned)m.plane > LM_PLANE_STRESS || (unsigned)m.law >= LM_LAW_COUNT ||
            (unsigned)m.density > LM_DENSITY_QUADRATIC || (m.one_way != 0 && m.one_way != 1) ||
            (m.av != 0 && m.av != 1) || !(isfinite(m.split) && m.split >= 0) ||
            !isfinite(m.av_g) || !isfinite(m.av_c1) || !isfinite(m.av_c2) ||
            !isfinite(m.av_lambda)) {
            snprintf(why, wl, "material %d has settings out of range", k + 1);
            return -1;
        }
        if (lm_material_validate(&m, e, sizeof e) != 0) {
            snprintf(why, wl, "material %d: %s", k + 1, e);
            return -1;
        }
    }
    size_t total = 0;
    for (int k = 0; k < sim->nbodies; k++, b += sizeof(body_rec)) {
        body_rec r;
        memcpy(&r, b, sizeof r);
        const lm_body *bd = &sim->bodies[k];
        char who[96];
        lm_body_label(sim, k, who, sizeof who);
        int grows = sim->mats[bd->mat]->kind == LM_GAS;   /* gas splitting adds points */
        if (r.mat != bd->mat || r.membrane != bd->membrane || r.closed != bd->closed) {
            snprintf(why, wl, "%s differs (material, membrane or closed)", who);
            return -1;
        }
        if (r.first > n || r.count > n - r.first) {
            snprintf(why, wl, "%s lies outside its %zu particles (first %llu, count %llu)",
                     who, n, (unsigned long long)r.first, (unsigned long long)r.count);
            return -1;
        }
        if (grows ? r.count < bd->count : r.count != bd->count) {
            snprintf(why, wl, "%s has %llu particles; the script's has %zu%s", who,
                     (unsigned long long)r.count, bd->count,
                     grows ? " (a splitting gas may only gain points)" : "");
            return -1;
        }
        if (r.force < 0 || r.force > LM_MFORCE_SEGMENT || r.normals < 0 ||
            r.normals > LM_NORMALS_CUBIC_COLOUR || (r.seg_ready != 0 && r.seg_ready != 1) ||
            !isfinite(r.ox) || !isfinite(r.oy) || !isfinite(r.pe_ref)) {
            snprintf(why, wl, "%s has settings out of range", who);
            return -1;
        }
        total += (size_t)r.count;
    }
    if (total != n) {
        snprintf(why, wl, "its bodies hold %zu particles, its header says %zu", total, n);
        return -1;
    }
    const unsigned char *bodies = b - (size_t)sim->nbodies * sizeof(body_rec);
    for (int k = 0; k < sim->npins; k++, b += sizeof(pin_rec))
        for (int j = 0; j < 4; j++)
            if (!isfinite(get_double(b, (size_t)j))) {
                snprintf(why, wl, "pin %d has a velocity or reaction that is not finite", k + 1);
                return -1;
            }
    for (int k = 0; k < sim->nlinks; k++, b += sizeof(link_rec)) {
        link_rec r;
        memcpy(&r, b, sizeof r);
        if (!(isfinite(r.k) && r.k >= 0) || !(isfinite(r.L0) && r.L0 >= 0) ||
            (r.active != 0 && r.active != 1)) {
            snprintf(why, wl, "link %d is out of range (k = %g, L0 = %g)", k + 1, r.k, r.L0);
            return -1;
        }
    }
    static const char *const names[NDOUBLES] = {
        "x", "y", "vx", "vy", "m", "rho", "sxx", "syy", "sxy", "szz", "et", "ds", "tx", "ty",
        "e", "q", "ev", "lx", "ly", "L0", "r0"};
    for (int a = 0; a < NDOUBLES; a++, b += n * sizeof(double))
        for (size_t q = 0; q < n; q++) {
            double v = get_double(b, q);
            const lm_grid *g = &sim->grid;
            if (!isfinite(v) || ((a == 4 || a == 5) && !(v > 0))) {
                snprintf(why, wl, "particle %zu has %s = %g", q + 1, names[a], v);
                return -1;
            }
            /* positions inside the domain: a step reads the nodes around
             * each particle, and one far outside is an input error, not a
             * simulation that failed */
            if ((a == 0 && !(v >= g->x0 && v <= g->x0 + g->nx * g->hx)) ||
                (a == 1 && !(v >= g->y0 && v <= g->y0 + g->ny * g->hy))) {
                snprintf(why, wl, "particle %zu has %s = %g, outside the domain", q + 1,
                         names[a], v);
                return -1;
            }
        }
    const unsigned char *ibody = b, *imat = b + n * 4, *ipin = b + 2 * n * 4;
    for (int k = 0; k < sim->nbodies; k++) {
        body_rec r;
        memcpy(&r, bodies + (size_t)k * sizeof r, sizeof r);
        for (size_t q = (size_t)r.first; q < (size_t)(r.first + r.count); q++)
            if (get_int(ibody, q) != k || get_int(imat, q) != r.mat) {
                snprintf(why, wl, "particle %zu of body %d says body %d, material %d", q + 1,
                         k + 1, get_int(ibody, q) + 1, get_int(imat, q) + 1);
                return -1;
            }
    }
    for (size_t q = 0; q < n; q++)
        if (get_int(ipin, q) < 0 || get_int(ipin, q) > sim->npins) {
            snprintf(why, wl, "particle %zu has pin %d of %d", q + 1, get_int(ipin, q),
                     sim->npins);
            return -1;
        }
    return 0;
}

lm_status lm_sim_state_load(lm_sim *sim, const unsigned char *buf, size_t len)
{
    header h;
    if (len < sizeof h) return refuse(sim, "it is truncated");
    memcpy(&h, buf, sizeof h);
    char why[300];
    if (h.magic != MAGIC) return refuse(sim, "it is not a lamina checkpoint");
    if (h.version != LM_CHECKPOINT_VERSION) {
        snprintf(why, sizeof why, "it is format version %u, this lamina reads version %u",
                 h.version, LM_CHECKPOINT_VERSION);
        return refuse(sim, why);
    }
    if (h.endian != endian_mark()) return refuse(sim, "it was written on a machine of the other byte order");
    if (h.nlinks != sim->nlinks) {
        snprintf(why, sizeof why, "it has %d links; the script made %d", h.nlinks, sim->nlinks);
        return refuse(sim, why);
    }
    if ((int)h.nmats != sim->nmats || h.nbodies != sim->nbodies || h.npins != sim->npins) {
        snprintf(why, sizeof why, "it has %u materials, %d bodies and %d pins; the script made "
                 "%d, %d and %d", h.nmats, h.nbodies, h.npins, sim->nmats, sim->nbodies,
                 sim->npins);
        return refuse(sim, why);
    }
    if (h.nx != sim->grid.nx || h.ny != sim->grid.ny || h.hx != sim->grid.hx ||
        h.hy != sim->grid.hy || h.basis != (int32_t)sim->def.basis)
        return refuse(sim, "its grid or basis differs from the script's");
    if (h.axisym != (uint32_t)(sim->def.axisym != 0))
        return refuse(sim, "one of it and the script is axisymmetric, the other plane");
    size_t n = (size_t)h.n;
    size_t need = state_bytes(&h);
    if (need == 0) {
        snprintf(why, sizeof why, "its header claims %llu particles (at most %d)",
                 (unsigned long long)h.n, LM_MAX_PARTICLES);
        return refuse(sim, why);
    }
    if (len != need) return refuse(sim, "its size does not match its header (truncated?)");
    if (check_state(sim, buf + sizeof h, n, why, sizeof why) != 0) return refuse(sim, why);
    const unsigned char *b = buf + sizeof h;
    clock_rec c;
    b = take(&c, b, sizeof c);
    /* everything checked: from here on nothing can fail but memory */
    if (n > sim->p.cap && lm_particles_reserve(&sim->p, n)) {
        snprintf(sim->err, sizeof sim->err, "no room for the checkpoint's %zu particles: %s", n,
                 lu_budget_oom());
        return LM_ERR_MEMORY;
    }
    for (int k = 0; k < sim->nmats; k++) b = take(sim->mats[k], b, sizeof(lm_material));
    for (int k = 0; k < sim->nbodies; k++) {
        body_rec r;
        b = take(&r, b, sizeof r);
        lm_body *bd = &sim->bodies[k];
        bd->first = (size_t)r.first;
        bd->count = (size_t)r.count;
        bd->force = (lm_mforce)r.force;
        bd->normals = (lm_normals)r.normals;
        bd->orient = r.orient;
        bd->seg_ready = r.seg_ready;
        bd->side = r.pad;   /* LM_ORIENT_CURVE's side (0 before it existed) */
        bd->ox = r.ox;
        bd->oy = r.oy;
        bd->pe_ref = r.pe_ref;
    }
    /* a pin's record is its four doubles, read as check_state reads them */
    for (int k = 0; k < sim->npins; k++, b += sizeof(pin_rec)) {
        lm_pin *pn = &sim->pins[k];
        pn->vx = get_double(b, 0);
        pn->vy = get_double(b, 1);
        pn->rx = get_double(b, 2);
        pn->ry = get_double(b, 3);
    }
    for (int k = 0; k < sim->nlinks; k++) {
        link_rec r;
        b = take(&r, b, sizeof r);
        sim->links[k].k = r.k;
        sim->links[k].L0 = r.L0;
        sim->links[k].active = r.active;
    }
    lm_particles *p = &sim->p;
    p->n = n;
    double *a[NDOUBLES];
    int nd = particle_doubles(p, a);
    for (int k = 0; k < nd; k++) b = take(a[k], b, n * sizeof(double));
    int *ia[3] = {p->body, p->mat, p->pin};
    for (int k = 0; k < 3; k++)
        for (size_t q = 0; q < n; q++) {
            int32_t v;
            b = take(&v, b, sizeof v);
            ia[k][q] = v;
        }
    sim->t = c.t;
    sim->t_base = c.t_base;
    sim->def.dt = c.dt;
    sim->pe_ref = c.pe_ref;
    sim->def.gx = c.gx;
    sim->def.gy = c.gy;
    sim->def.pic = c.pic;
    sim->def.courant = c.courant;
    sim->step = (long)c.step;
    sim->step_base = (long)c.step_base;
    sim->prepared = c.prepared;
    sim->work->courant_checked = 0;   /* dt, courant and materials as restored */
    return LM_OK;
}
