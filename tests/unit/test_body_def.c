/* test_body_def.c - issue 33 item 1: a body of one material is created
 * from its definition (lm_body_def) and checked in the engine, all or
 * nothing, as a membrane is from lm_membrane_def. A C caller gets the
 * refusals sim:body gives (the same messages, without the "sim:body: "
 * the binding puts before them), and a refused or stopped body leaves
 * the simulation as it was. Sees only the public header. */
#include <string.h>

#include "check.h"
#include "mpm.h"

static lm_sim *scene(int *el, int *skin)
{
    lm_sim_def d;
    lm_sim_def_default(&d);   /* unit square, cell 0.1 */
    d.dt = 1e-3;
    char err[256];
    lm_sim *sim = lm_sim_new(&d, err, sizeof err);
    if (!sim) return NULL;
    static lm_material rubber = {.kind = LM_ELASTIC, .rho = 1000, .E = 1000, .nu = 0.3};
    static lm_material sheet = {.kind = LM_MEMBRANE, .rho = 0.5, .E = 1e6, .nu = 0.3,
                         .thickness = 0.01};
    *el = lm_sim_add_material(sim, &rubber);
    *skin = lm_sim_add_material(sim, &sheet);
    return sim;
}

/* The region test of the rectangle below, as a caller's function; it
 * fails (-1) from its `fail_at`-th call on when that is > 0. */
typedef struct calls { int n, fail_at; } calls;
static int in_rect(void *ctx, double x, double y)
{
    calls *c = ctx;
    if (c->fail_at > 0 && ++c->n >= c->fail_at) return -1;
    return x > 0.2 && x < 0.6 && y > 0.3 && y < 0.5;
}

static int refused(lm_sim *sim, const lm_body_def *def, const char *msg)
{
    size_t n = sim->p.n;
    int nb = sim->nbodies;
    int b = lm_sim_create_body(sim, def);
    int ok = b == -1 && strstr(sim->err, msg) != NULL && sim->p.n == n && sim->nbodies == nb;
    if (!ok) fprintf(stderr, "expected \"%s\", got %d \"%s\"\n", msg, b, sim->err);
    return ok;
}

int main(void)
{
    int el = -1, skin = -1;
    lm_sim *sim = scene(&el, &skin);
    CHECK(sim != NULL);

    /* a rectangle on cell edges: 4 x 2 cells, 2 x 2 points a cell; its
     * mass is rho times its area exactly (1000 x 0.4 x 0.2 = 80) */
    lm_region rect = {.kind = LM_REGION_RECT, .x0 = 0.2, .y0 = 0.3, .x1 = 0.6, .y1 = 0.5};
    lm_body_def def;
    lm_body_def_default(&def);
    def.mat = el;
    def.region = &rect;
    def.vx = 0.5;
    def.name = "block";
    int b = lm_sim_create_body(sim, &def);
    CHECK(b == 0 && sim->bodies[0].count == 32);
    CHECK_NEAR(lm_body_mass(sim, 0), 80.0, 1e-12);
    CHECK(sim->p.vx[0] == 0.5 && sim->p.vy[0] == 0);
    char who[96];
    CHECK(strcmp(lm_body_label(sim, 0, who, sizeof who), "body 'block' (body 1)") == 0);

    /* the same rectangle as a function: the same particles */
    calls c = {0, 0};
    lm_body_def byfn = def;
    byfn.region = NULL;
    byfn.inside = in_rect;
    byfn.ctx = &c;
    byfn.name = NULL;
    CHECK(lm_sim_create_body(sim, &byfn) == 1 && sim->bodies[1].count == 32);
    CHECK(memcmp(sim->p.x, sim->p.x + 32, 32 * sizeof *sim->p.x) == 0);
    CHECK(memcmp(sim->p.y, sim->p.y + 32, 32 * sizeof *sim->p.y) == 0);

    /* the refusals, each leaving the simulation as it was */
    lm_body_def bad = def;
    bad.mat = skin;
    CHECK(refused(sim, &bad, "a membrane material goes into sim:membrane{...}"));
    bad = def;
    bad.npx = 128;
    bad.npy = 64;
    CHECK(refused(sim, &bad, "ppc = {128, 64} gives 8192 points per cell, more than the "
                             "limit of 4096"));
    bad = def;
    bad.npx = 0;
    CHECK(refused(sim, &bad, "ppc = {0, 2} must be two positive integers"));
    bad = def;
    bad.vy = NAN;
    CHECK(refused(sim, &bad, "'velocity' must be two finite numbers"));
    lm_region far = {.kind = LM_REGION_DISK, .cx = 5, .cy = 5, .r = 0.2,
                     .x0 = 4.8, .y0 = 4.8, .x1 = 5.2, .y1 = 5.2};
    bad = def;
    bad.region = &far;
    CHECK(refused(sim, &bad, "the region holds no particles at ppc = 4"));
    bad = def;
    bad.region = NULL;
    CHECK(refused(sim, &bad, "'region' is required"));
    /* a caller's function failing part-way: no half body */
    c = (calls){0, 20};
    CHECK(refused(sim, &byfn, "stopped by the region or velocity function"));
    CHECK(c.n == 20);   /* not called again after it failed */
    /* clipped: the same */
    c = (calls){0, 7};
    byfn.clipped = 1;
    CHECK(refused(sim, &byfn, "stopped by the region or velocity function"));

    /* and the simulation steps on with the two bodies it has */
    CHECK(lm_sim_step(sim) == LM_OK);
    lm_sim_free(sim);
    return CHECK_DONE();
}
