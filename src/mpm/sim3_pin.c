/* sim3_pin.c - body:pin in 3D: a pin holds the grid nodes its particles
 * touch, as a fixed wall holds its nodes (grid_walls.c, sim3_walls.c), at
 * the pin's velocity instead of zero. This is the form the 2D pins take
 * for a pinned region, an edge or "all" (pin.c, docs/api.md "body:pin":
 * "instead holds every grid node its points touch (N > 0; weighted by N
 * where two pins share a node), as a wall does, and the material within
 * their stencils moves with them"); the 2D constraint form for isolated
 * points (a point of infinite mass tied to the grid, constraint.c) is not
 * built in 3D.
 *
 * Per step: before it, the held particles take the pin's velocity
 * (lm3_pins_begin); after the grid update the held nodes' Lagrangian
 * velocity is the pins' (sum N v / sum N over the held points touching
 * the node) and their acceleration 0, the momentum this takes from the
 * nodes being the pins' reaction; after the strain velocity (MUSL's
 * re-map) the held nodes' velocity is the pins' again; the walls act
 * after the pins, so a wall keeps its components. The ghost ring is
 * refilled from the real nodes (sim3_walls.c). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mpm3.h"
#include "sim3_walls.h"
#include "util.h"

static int grow_node_arrays(lm3_sim *sim)
{
    lm3_pins *ps = sim->pins;
    if (ps->w) return 1;
    ps->w = calloc(4 * sim->grid.nn, sizeof(double));
    if (!ps->w) return 0;
    for (int a = 0; a < 3; a++) ps->wv[a] = ps->w + (1 + a) * sim->grid.nn;
    return 1;
}

int lm3_pin_add(lm3_sim *sim, const size_t *idx, size_t n, const double v[3])
{
    if (!sim->pins) {
        sim->pins = calloc(1, sizeof *sim->pins);
        if (!sim->pins) goto oom;
    }
    lm3_pins *ps = sim->pins;
    if (!ps->held || sim->p.n > 0) {
        /* the held flags cover every particle now (pins come after bodies) */
        uint8_t *h = realloc(ps->held, sim->p.n ? sim->p.n : 1);
        if (!h) goto oom;
        if (sim->p.n) memset(h, 0, sim->p.n);
        ps->held = h;
        for (int k = 0; k < ps->n; k++)
            for (size_t j = 0; j < ps->pin[k].n; j++) h[ps->pin[k].idx[j]] = 1;
    }
    for (size_t j = 0; j < n; j++) {
        if (idx[j] >= sim->p.n) {
            snprintf(sim->err, sizeof sim->err, "point %zu is not a particle", idx[j]);
            return -1;
        }
        if (ps->held[idx[j]]) {
            snprintf(sim->err, sizeof sim->err, "particle %zu is held by another pin already "
                     "(a particle can be held by one pin only)", idx[j]);
            return -1;
        }
    }
    if (!grow_node_arrays(sim)) goto oom;
    lm3_pin *pin = lu_push(&ps->pin, (size_t)ps->n, sizeof *ps->pin);
    if (!pin) goto oom;
    pin->idx = malloc((n ? n : 1) * sizeof *pin->idx);
    if (!pin->idx) goto oom;
    memcpy(pin->idx, idx, n * sizeof *idx);
    pin->n = n;
    memcpy(pin->v, v, sizeof pin->v);
    for (size_t j = 0; j < n; j++) ps->held[idx[j]] = 1;
    return ps->n++;
oom:
    snprintf(sim->err, sizeof sim->err, "out of memory for a pin");
    return -1;
}

void lm3_pins_free(lm3_sim *sim)
{
    lm3_pins *ps = sim->pins;
    if (!ps) return;
    for (int k = 0; k < ps->n; k++) free(ps->pin[k].idx);
    free(ps->pin);
    free(ps->w);
    free(ps->held);
    free(ps);
    sim->pins = NULL;
}

void lm3_pins_begin(lm3_sim *sim)
{
    lm3_pins *ps = sim->pins;
    for (int k = 0; ps && k < ps->n; k++)
        for (size_t j = 0; j < ps->pin[k].n; j++)
            for (int a = 0; a < 3; a++) sim->p.v[a][ps->pin[k].idx[j]] = ps->pin[k].v[a];
}

/* Is node i one of the grid's own (not the ghost ring)? */
static int real_node(const lm3_grid *g, long i)
{
    long ix = i % g->s[0], iy = i / g->s[0] % g->s[1], iz = i / (g->s[0] * g->s[1]);
    return ix >= g->pad && ix <= g->pad + g->n[0] && iy >= g->pad && iy <= g->pad + g->n[1] &&
           iz >= g->pad && iz <= g->pad + g->n[2];
}

/* Calls fn(sim, pin, node, N) for every stencil node of every held point
 * with N > 0 (the places of this step's p2g: node, d). */
static void each_held_node(lm3_sim *sim, void (*fn)(lm3_sim *, int, long, double))
{
    const lm3_grid *g = &sim->grid;
    lm3_pins *ps = sim->pins;
    for (int k = 0; k < ps->n; k++)
        for (size_t j = 0; j < ps->pin[k].n; j++) {
            size_t q = ps->pin[k].idx[j];
            double d[3] = {sim->p.d[0][q], sim->p.d[1][q], sim->p.d[2][q]};
            lm3_weights w;
            lm3_weights_at(g, sim->p.node[q], d, &w);
            for (int c = 0; c < g->W; c++)
                for (int b = 0; b < g->W; b++)
                    for (int a = 0; a < g->W; a++) {
                        double N = w.w[0][a] * w.w[1][b] * w.w[2][c];
                        long i = w.node + (c * g->s[1] + b) * g->s[0] + a;
                        if (N > 0 && real_node(g, i)) fn(sim, k, i, N);
                    }
        }
}

static void add_weight(lm3_sim *sim, int k, long i, double N)
{
    lm3_pins *ps = sim->pins;
    ps->w[i] += N;
    for (int a = 0; a < 3; a++) ps->wv[a][i] += N * ps->pin[k].v[a];
}

/* The reaction: each held node's momentum change, shared among the pins
 * touching it by their N. */
static void add_reaction(lm3_sim *sim, int k, long i, double N)
{
    lm3_pins *ps = sim->pins;
    const lm3_grid *g = &sim->grid;
    double share = N / ps->w[i];
    for (int a = 0; a < 3; a++)
        ps->pin[k].reaction[a] += share * g->m[i] * (ps->wv[a][i] / ps->w[i] - g->p[a][i]) /
                                  sim->def.dt;
}

static void hold(lm3_sim *sim, double *const u[3], double *const acc[3])
{
    lm3_pins *ps = sim->pins;
    lm3_grid *g = &sim->grid;
    for (size_t i = 0; i < g->nn; i++) {
        if (!(ps->w[i] > 0)) continue;
        for (int a = 0; a < 3; a++) {
            u[a][i] = ps->wv[a][i] / ps->w[i];
            if (acc) acc[a][i] = 0;
        }
    }
}

void lm3_pins_grid(lm3_sim *sim)
{
    lm3_pins *ps = sim->pins;
    lm3_grid *g = &sim->grid;
    memset(ps->w, 0, 4 * g->nn * sizeof(double));
    each_held_node(sim, add_weight);
    for (int k = 0; k < ps->n; k++)
        for (int a = 0; a < 3; a++) ps->pin[k].reaction[a] = 0;
    /* the velocity the step gave the held nodes (p holds v^L here), before
     * the pins replace it: what they took is their reaction */
    each_held_node(sim, add_reaction);
    hold(sim, g->p, g->f);
    lm3_grid_apply_bc(g, g->p);
    lm3_grid_apply_bc(g, g->f);
    double *const f[6] = {g->f[0], g->f[1], g->f[2], g->p[0], g->p[1], g->p[2]};
    static const int comp[6] = {0, 1, 2, 0, 1, 2};
    lm3_grid_fill(g, 6, f, comp);
}

void lm3_pins_strain(lm3_sim *sim)
{
    lm3_grid *g = &sim->grid;
    static const int comp[3] = {0, 1, 2};
    hold(sim, g->v, NULL);
    lm3_grid_apply_bc(g, g->v);
    lm3_grid_fill(g, 3, g->v, comp);
}
