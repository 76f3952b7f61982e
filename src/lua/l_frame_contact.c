/* l_frame_contact.c - sim:frame{contact = true}: what contact did in the last
 * step, drawn over the particles (issue 14, item 4).
 *
 * At every node where a contact pair met (contact.h), each paired body with
 * mass there gets its outward grid normal, -grad chi ([M] eqs 27-28, the
 * normals of [M] Fig 19 and [T] Fig 101), as an arrow 0.6 cell long in the
 * body's colour; and the node a mark in the colour of what happened there:
 * dark grey - the pair moved in the centre-of-mass field (contact, stick);
 * green - a body moved in its own field (release); magenta - a friction
 * pair slid. Only the normals the correction used are drawn, as the papers
 * show only "the pertinent normals". */
#include <math.h>
#include <string.h>

#include "contact.h"
#include "l_frame_panel.h"
#include "step.h"

void la_frame_contact(lua_State *L, la_frame_ctx *ctx, lm_sim *sim, lr_layers *l)
{
    const lm_contact *c = sim->contact;
    if (!c || c->npairs == 0 || !c->state) return;
    const lm_grid *g = &sim->grid;
    double h = fmin(g->hx, g->hy);
    size_t nodes = (size_t)(g->nx + 1) * (size_t)(g->ny + 1);
    /* arrows: the old sets, one per paired body, three node marks */
    size_t nsets = l->narrows + (size_t)c->nf + 3;
    lr_arrows *sets = la_frame_scratch(L, ctx, nsets * sizeof *sets);
    if (l->narrows) memcpy(sets, l->arrows, l->narrows * sizeof *sets);
    size_t k = l->narrows;
    for (int f = 0; f < c->nf; f++, k++) {
        const lm_contact_field *cf = &c->f[f];
        double *buf = la_frame_scratch(L, ctx, 4 * nodes * sizeof *buf);
        double *x = buf, *y = buf + nodes, *ux = buf + 2 * nodes, *uy = buf + 3 * nodes;
        size_t n = 0;
        for (int j = 0; j <= g->ny; j++)
            for (int i = 0; i <= g->nx; i++) {
                long id = lm_grid_node(g, i, j);
                if (c->state[id] == LM_CNODE_NONE || cf->m[id] <= 0) continue;
                if (cf->nx[id] == 0 && cf->ny[id] == 0) continue;
                x[n] = g->x0 + i * g->hx;
                y[n] = g->y0 + j * g->hy;
                ux[n] = cf->nx[id];
                uy[n] = cf->ny[id];
                n++;
            }
        sets[k] = (lr_arrows){ .n = n, .x = x, .y = y, .ux = ux, .uy = uy, .length = 0.6 * h,
                               .width = 1.5, .head = 6.0, .colour = lr_palette(cf->body) };
    }
    static const lr_rgba mark[3] = { {0.25, 0.25, 0.25, 1}, {0.0, 0.6, 0.3, 1},
                                     {0.85, 0.1, 0.75, 1} };
    for (int s = 0; s < 3; s++, k++) {
        double *buf = la_frame_scratch(L, ctx, 4 * nodes * sizeof *buf);
        double *x = buf, *y = buf + nodes, *ux = buf + 2 * nodes, *uy = buf + 3 * nodes;
        size_t n = 0;
        for (int j = 0; j <= g->ny; j++)
            for (int i = 0; i <= g->nx; i++) {
                if (c->state[lm_grid_node(g, i, j)] != s + 1) continue;
                /* a short thick bar centred on the node: a square mark */
                x[n] = g->x0 + i * g->hx - 0.08 * h;
                y[n] = g->y0 + j * g->hy;
                ux[n] = 1;
                uy[n] = 0;
                n++;
            }
        sets[k] = (lr_arrows){ .n = n, .x = x, .y = y, .ux = ux, .uy = uy, .length = 0.16 * h,
                               .width = 5.0, .head = 0.0, .colour = mark[s] };
    }
    l->arrows = sets;
    l->narrows = nsets;
}
