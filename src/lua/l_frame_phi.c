/* l_frame_phi.c - sim:frame's phi layer (on by default): the membranes'
 * phi contours, as the normals paper draws them ([N] Figs 3-16: phi = 1
 * bold through the points, other levels thin).
 *
 * The phi drawn is the construction's own (lm_membrane_phi): for the
 * methods without connectivity the very fit that gave the step's normals,
 * for connectivity membranes the isosurface construction on the present
 * points. phi is local to each element, so each element's phi is sampled
 * over the part of the plane it answers for - per-cell fits over the cells
 * that took their normals from it, centred elements over the half-cell
 * square about their centre (centres lie on the half-cell lattice, so
 * these squares tile the plane) - and contoured by marching squares
 * (render/layer_contour.c) into segments, one curve per level. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "l_frame_panel.h"
#include "layers.h"
#include "mpm_normals.h"

#define SAMPLES 12      /* intervals per side of a sampled square */
#define NLEVELS 4
/* phi = 1 last, so that it lies over the thin levels where they meet */
static const double levels[NLEVELS] = {0.0, 0.5, 1.5, 1.0};
#define BOLD (NLEVELS - 1)

typedef struct seg_buf {
    double *x, *y;      /* segment end points, pairs */
    size_t n, cap;
    double x0, y0, dx, dy;   /* index -> world of the square being contoured */
    int oom;
} seg_buf;

static void emit(void *ctx, double i0, double j0, double i1, double j1)
{
    seg_buf *b = ctx;
    if (b->n + 2 > b->cap) {
        size_t cap = b->cap ? 2 * b->cap : 1024;
        double *x = realloc(b->x, cap * sizeof *x), *y = x ? realloc(b->y, cap * sizeof *y) : NULL;
        if (x) b->x = x;
        if (!x || !y) {
            b->oom = 1;
            return;
        }
        b->y = y;
        b->cap = cap;
    }
    b->x[b->n] = b->x0 + i0 * b->dx;
    b->y[b->n++] = b->y0 + j0 * b->dy;
    b->x[b->n] = b->x0 + i1 * b->dx;
    b->y[b->n++] = b->y0 + j1 * b->dy;
}

/* Contours of fit f over the square [x0, x1] x [y0, y1], every level. */
static void contour_square(const lm_nfit *f, double x0, double y0, double x1, double y1,
                           seg_buf *buf)
{
    double v[(SAMPLES + 1) * (SAMPLES + 1)];
    double dx = (x1 - x0) / SAMPLES, dy = (y1 - y0) / SAMPLES;
    for (int j = 0; j <= SAMPLES; j++)
        for (int i = 0; i <= SAMPLES; i++) {
            double x[3] = {x0 + i * dx, y0 + j * dy, 0};
            v[j * (SAMPLES + 1) + i] = lm_nfit_phi(f, x);
        }
    for (int k = 0; k < NLEVELS; k++) {
        buf[k].x0 = x0;
        buf[k].y0 = y0;
        buf[k].dx = dx;
        buf[k].dy = dy;
        lr_marching_squares(v, SAMPLES, SAMPLES, levels[k], emit, &buf[k]);
    }
}

static void contour_body(const lm_sim *sim, const lm_nreport *rep, int centred, seg_buf *buf)
{
    const lm_grid *g = &sim->grid;
    if (!centred && rep->ncells > 0 && rep->cell_elem) {
        /* per-cell fits: each cell over the element it took its normals from */
        for (int c = 0; c < rep->ncells; c++) {
            int e = rep->cell_elem[c];
            if (e < 0) continue;
            int i = c % g->nx, j = c / g->nx;
            double x0 = g->x0 + i * g->hx, y0 = g->y0 + j * g->hy;
            contour_square(&rep->elem[e].fit, x0, y0, x0 + g->hx, y0 + g->hy, buf);
        }
        return;
    }
    for (int e = 0; e < rep->nelem; e++) {
        const lm_nbox *b = &rep->elem[e].fit.box;
        double cx = 0.5 * (b->lo[0] + b->hi[0]), cy = 0.5 * (b->lo[1] + b->hi[1]);
        contour_square(&rep->elem[e].fit, cx - 0.25 * g->hx, cy - 0.25 * g->hy,
                       cx + 0.25 * g->hx, cy + 0.25 * g->hy, buf);
    }
}

/* Whether the membrane's normals come from a construction with a phi
 * (lm_membrane_phi): not the colour-function methods. */
int la_membrane_has_phi(const lm_body *bd)
{
    return bd->membrane && bd->count >= 2 && bd->normals != LM_NORMALS_COLOUR &&
           bd->normals != LM_NORMALS_QUADRATIC_COLOUR && bd->normals != LM_NORMALS_CUBIC_COLOUR;
}

size_t la_frame_phi(lua_State *L, la_frame_ctx *ctx, lm_sim *sim, int strict, int hairline,
                    lr_curve **out)
{
    seg_buf buf[NLEVELS];
    memset(buf, 0, sizeof buf);
    char err[256];
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        if (!bd->membrane || bd->count < 2) continue;
        if (!strict && !la_membrane_has_phi(bd)) continue;  /* the default: where phi exists */
        lm_nreport rep;
        memset(&rep, 0, sizeof rep);
        if (lm_membrane_phi(sim, b, &rep, err, sizeof err) != 0) {
            lm_nreport_free(&rep);
            for (int k = 0; k < NLEVELS; k++) {
                free(buf[k].x);
                free(buf[k].y);
            }
            luaL_error(L, "%s: phi of membrane %d: %s", ctx->fn, b + 1, err);
        }
        /* isosurface (and connectivity, drawn with it) use centred elements */
        contour_body(sim, &rep, bd->normals == LM_NORMALS_ISOSURFACE ||
                                bd->normals == LM_NORMALS_CONNECTIVITY, buf);
        lm_nreport_free(&rep);
    }
    int oom = 0;
    for (int k = 0; k < NLEVELS; k++) oom |= buf[k].oom;
    /* the segments move into anchored memory, so a later Lua error in this
     * frame call leaks nothing */
    lr_curve *cv = la_frame_scratch(L, ctx, (NLEVELS + 1) * sizeof *cv);
    for (int k = 0; k < NLEVELS && !oom; k++) {
        double *xy = la_frame_scratch(L, ctx, 2 * (buf[k].n ? buf[k].n : 1) * sizeof *xy);
        if (buf[k].n) {
            memcpy(xy, buf[k].x, buf[k].n * sizeof *xy);
            memcpy(xy + buf[k].n, buf[k].y, buf[k].n * sizeof *xy);
        }
        const lr_rgba thin = {0.45, 0.45, 0.45, 0.9};
        cv[k] = (lr_curve){buf[k].n, xy, xy + buf[k].n, 0, 0.8,
                           levels[k] == 0.0 ? 3.0 : 0.0, thin, 1};
    }
    if (!oom) {
        /* phi = 1 runs through the points ([N] Figs 3-16): drawn over them,
         * dark on a white casing, so that it reads over discs of any colour
         * (issue 32: it was hidden under the membrane's discs) */
        const lr_rgba ink = {0.1, 0.1, 0.1, 1.0}, casing = {1.0, 1.0, 1.0, 0.85};
        cv[NLEVELS] = cv[BOLD];
        cv[NLEVELS].width = hairline ? 1.0 : 2.0;
        cv[NLEVELS].colour = ink;
        cv[BOLD].width = hairline ? 0.0 : 4.0;
        cv[BOLD].colour = casing;
        if (hairline) cv[BOLD].n = 0;   /* a band's colour stays readable */
    }
    for (int k = 0; k < NLEVELS; k++) {
        free(buf[k].x);
        free(buf[k].y);
    }
    if (oom) luaL_error(L, "%s: out of memory drawing phi", ctx->fn);
    *out = cv;
    return NLEVELS + 1;
}

/* The element of rep that answers for (x, y), as contour_body draws them;
 * NULL if none does. */
static const lm_nfit *fit_at(const lm_sim *sim, const lm_nreport *rep, int centred,
                             double x, double y)
{
    const lm_grid *g = &sim->grid;
    if (!centred) {
        int i = (int)floor((x - g->x0) / g->hx), j = (int)floor((y - g->y0) / g->hy);
        if (i < 0 || j < 0 || i >= g->nx || j >= g->ny || !rep->cell_elem) return NULL;
        int e = rep->cell_elem[j * g->nx + i];
        return e >= 0 ? &rep->elem[e].fit : NULL;
    }
    const lm_nfit *best = NULL;
    double bd = INFINITY;
    for (int e = 0; e < rep->nelem; e++) {
        const lm_nbox *b = &rep->elem[e].fit.box;
        double cx = 0.5 * (b->lo[0] + b->hi[0]), cy = 0.5 * (b->lo[1] + b->hi[1]);
        double dx = fabs(x - cx) / g->hx, dy = fabs(y - cy) / g->hy;
        if (dx > 0.25 + 1e-12 || dy > 0.25 + 1e-12) continue;
        if (dx + dy < bd) {
            bd = dx + dy;
            best = &rep->elem[e].fit;
        }
    }
    return best;
}

/* membrane:phi(x, y) -> the value of the phi drawn by sim:frame{phi =
 * true} at (x, y) (the construction's, element by element), or nil where
 * no element answers (far from the membrane). */
int la_body_phi(lua_State *L)
{
    lm_sim *sim;
    int b = la_check_body(L, 1, &sim);
    double x = luaL_checknumber(L, 2), y = luaL_checknumber(L, 3);
    const lm_body *bd = &sim->bodies[b];
    if (!bd->membrane) return luaL_error(L, "body:phi: body %d is not a membrane", b + 1);
    lm_nreport rep;
    memset(&rep, 0, sizeof rep);
    char err[256];
    if (lm_membrane_phi(sim, b, &rep, err, sizeof err) != 0) {
        lm_nreport_free(&rep);
        return luaL_error(L, "membrane:phi: %s", err);
    }
    const lm_nfit *f = fit_at(sim, &rep, bd->normals == LM_NORMALS_ISOSURFACE ||
                                             bd->normals == LM_NORMALS_CONNECTIVITY, x, y);
    if (f) {
        double p[3] = {x, y, 0};
        lua_pushnumber(L, lm_nfit_phi(f, p));
    } else {
        lua_pushnil(L);
    }
    lm_nreport_free(&rep);
    return 1;
}
