/* l_frame_contact.c - sim:frame{contact = true}: what contact did in the last
 * step, drawn over the particles (issue 14, item 4).
 *
 * At every node where a contact pair met (mpm_contact.h), each paired body with
 * mass there gets its outward grid normal, -grad chi ([M] eqs 27-28, the
 * normals of [M] Fig 19 and [T] Fig 101), as an arrow 0.6 cell long in the
 * body's colour; and the node a mark in the colour of what happened there:
 * dark grey - the pair moved in the centre-of-mass field (contact, stick);
 * green - a body moved in its own field (release); magenta - a friction
 * pair slid. Only the normals the correction used are drawn, as the papers
 * show only "the pertinent normals".
 *
 * contact = {every = k, scale = s} (issue 16 item 3, docs/gallery.md
 * "Legibility checklist" 2: single arrows must be judged): a node in each
 * k x k block of nodes (the first where a pair met, row by row), its arrows
 * s times as long, 2 px wide on a white outline, so that an arrow in one
 * body's colour reads over the other body's discs. contact = true keeps
 * its thin arrows, pixel for pixel. */
#include <math.h>
#include <string.h>

#include "l_frame_panel.h"
#include "mpm_contact.h"

/* The nodes shown: 1 at a node where a pair met and which is the first
 * such node of its every x every block. */
static unsigned char *shown_nodes(lua_State *L, la_frame_ctx *ctx, const lm_grid *g,
                                  const unsigned char *state, int every)
{
    int bx = g->nx / every + 1, by = g->ny / every + 1;
    /* indexed like state: ghost nodes included (lm_grid_node) */
    unsigned char *shown = la_frame_scratch(L, ctx, lm_grid_nodes(g));
    unsigned char *taken = la_frame_scratch(L, ctx, (size_t)bx * (size_t)by);
    for (int j = 0; j <= g->ny; j++)
        for (int i = 0; i <= g->nx; i++) {
            long id = lm_grid_node(g, i, j);
            size_t b = (size_t)(j / every) * (size_t)bx + (size_t)(i / every);
            if (state[id] == LM_CNODE_NONE || taken[b]) continue;
            taken[b] = 1;
            shown[id] = 1;
        }
    return shown;
}

/* Which shown nodes get an arrow and which way it points: a contact
 * field's outward normal where the body has mass and the normal is not
 * zero (nx set), or else a mark where the node's state is `state`, a bar
 * along +x moved back by dx to centre it on the node. */
typedef struct arrow_pick {
    const double *m, *nx, *ny;
    const unsigned char *state;
    int want;
    double dx;
} arrow_pick;

static int picked(const arrow_pick *a, long id, double *ux, double *uy)
{
    if (a->nx) {
        *ux = a->nx[id];
        *uy = a->ny[id];
        return !(a->m[id] <= 0) && (*ux != 0 || *uy != 0);
    }
    *ux = 1;
    *uy = 0;
    return a->state[id] == a->want;
}

/* The arrows of `look` (length, width, head, colour) at the shown nodes
 * `pick` takes, row by row, their points in frame scratch. */
static lr_arrows node_arrows(lua_State *L, la_frame_ctx *ctx, const lm_grid *g,
                             const unsigned char *shown, const arrow_pick *pick, lr_arrows look)
{
    size_t nodes = (size_t)(g->nx + 1) * (size_t)(g->ny + 1);
    double *buf = la_frame_scratch(L, ctx, 4 * nodes * sizeof *buf);
    double *x = buf, *y = buf + nodes, *ux = buf + 2 * nodes, *uy = buf + 3 * nodes;
    size_t n = 0;
    for (int j = 0; j <= g->ny; j++)
        for (int i = 0; i <= g->nx; i++) {
            long id = lm_grid_node(g, i, j);
            if (!shown[id] || !picked(pick, id, &ux[n], &uy[n])) continue;
            x[n] = g->x0 + i * g->hx - pick->dx;
            y[n] = g->y0 + j * g->hy;
            n++;
        }
    look.n = n;
    look.x = x;
    look.y = y;
    look.ux = ux;
    look.uy = uy;
    return look;
}

void la_frame_contact(lua_State *L, la_frame_ctx *ctx, lm_sim *sim, int every,
                      double scale, int outlined, lr_layers *l)
{
    const unsigned char *state = lm_sim_contact_state(sim);
    if (!state) return;
    int nf = lm_sim_contact_fields(sim);
    const lm_grid *g = &sim->grid;
    double h = fmin(g->hx, g->hy);
    const unsigned char *shown = shown_nodes(L, ctx, g, state, every);
    /* arrows: the old sets, one per paired body (each after its white
     * outline when outlined), three node marks */
    size_t nsets = l->narrows + (size_t)nf * (outlined ? 2 : 1) + 3;
    lr_arrows *sets = la_frame_scratch(L, ctx, nsets * sizeof *sets);
    if (l->narrows) memcpy(sets, l->arrows, l->narrows * sizeof *sets);
    size_t k = l->narrows;
    for (int f = 0; f < nf; f++, k++) {
        arrow_pick normals = { 0 };
        int body = lm_sim_contact_field(sim, f, &normals.m, &normals.nx, &normals.ny);
        sets[k] = node_arrows(L, ctx, g, shown, &normals,
                              (lr_arrows){ .length = 0.6 * h * scale, .width = 1.5, .head = 6.0,
                                           .colour = lr_palette(body) });
        if (outlined) {
            sets[k + 1] = sets[k];
            sets[k + 1].width = 2.0;
            sets[k + 1].head = 8.0;
            sets[k].width = 5.0;
            sets[k].head = 11.0;
            sets[k].colour = (lr_rgba){ 1, 1, 1, 0.9 };
            k++;
        }
    }
    static const lr_rgba mark[3] = { {0.25, 0.25, 0.25, 1}, {0.0, 0.6, 0.3, 1},
                                     {0.85, 0.1, 0.75, 1} };
    for (int s = 0; s < 3; s++, k++) {
        /* a short thick bar centred on the node: a square mark */
        const arrow_pick marks = { .state = state, .want = s + 1, .dx = 0.08 * h };
        sets[k] = node_arrows(L, ctx, g, shown, &marks,
                              (lr_arrows){ .length = 0.16 * h, .width = 5.0, .head = 0.0,
                                           .colour = mark[s] });
    }
    l->arrows = sets;
    l->narrows = nsets;
}
