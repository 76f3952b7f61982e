/* l_frame_panel.h - sim:frame's panels: from the keys of a panel table (or
 * of the frame table itself) to a figure.h lr_panel (private to l_frame*.c). */
#ifndef LAMINA_L_FRAME_PANEL_H
#define LAMINA_L_FRAME_PANEL_H

#include "figure.h"
#include "l_internal.h"

/* The keys a panel understands; a frame table also takes them (as the one
 * panel, or as defaults for every table in `panels`). */
#define LA_PANEL_KEYS "window", "grid", "colour", "range", "colourmap", \
    "colourbar", "scalebar", "units", "mirror", "split", "split_at", "names", \
    "normals", "contours", "contour_levels", "particles", "phi", "contact", "discs", \
    "band", "colour_bodies"

typedef struct la_frame_ctx {
    const char *fn;     /* "sim:frame", for messages */
    int anchor;         /* stack index of a table keeping scratch buffers alive */
    int nanchored;
    /* what the panels drew, for the frame's lamina:layers text (the
     * gallery's check that membrane frames show phi and normals) */
    int membranes;      /* membranes shown (both sides of a split panel) */
    int with_phi;       /* of them, those whose normals' construction has a phi */
    int phi, normals;   /* of them, those drawn with phi contours / normals */
    double scale;       /* scale = k: points at X0 + k (x - X0) (l_ref.c); 1: as they are */
} la_frame_ctx;

/* Scratch memory that lives as long as the anchor table (freed by Lua's
 * collector, so a Lua error in between leaks nothing). Zeroed. */
void *la_frame_scratch(lua_State *L, la_frame_ctx *ctx, size_t n);

/* Fills *p from the panel table at pidx (0: none), each key looked up there
 * first and then in the frame table at fidx; the simulation is the panel's
 * `sim`, else the one at sidx. Raises a Lua error naming a bad key. */
/* l_frame_phi.c: the membranes' phi contours as curves, one per level
 * (phi = 1 twice: its casing, then its ink), in scratch memory; returns
 * their count. strict (phi = true): a membrane without a phi (colour-
 * function normals) is an error; else (the default) it is passed over.
 * hairline: phi = 1 a 1 px line without its casing, over a membrane drawn
 * as a band (`band`), whose colour is what is read. */
size_t la_frame_phi(lua_State *L, la_frame_ctx *ctx, lm_sim *sim, int strict, int hairline,
                    lr_curve **out);
/* Whether a body is a membrane whose normals' construction has a phi. */
int la_membrane_has_phi(const lm_body *bd);

/* l_frame_points.c: a side's particles as point layers. */
typedef struct la_frame_points_opts {
    int which;                  /* 0 every body, 1 membranes only, 2 none */
    const unsigned char *valued;/* non-NULL: valued[b] for bodies b < nvalued
                                   coloured by the field, the others (and
                                   bodies beyond) in their body colour */
    int nvalued;
    double band;                /* pixels; > 0: membranes joined by a band */
} la_frame_points_opts;

/* Fills out[] from base (positions, groups and radii of every particle)
 * and value (the field per particle, or NULL); returns the layer count:
 * 0 (which = 2), 1, or 2 with valued (the field's bodies, then the
 * others over them). */
size_t la_frame_points(lua_State *L, la_frame_ctx *ctx, const lm_sim *sim,
                       const double *value, const la_frame_points_opts *o,
                       const lr_points *base, lr_points out[2]);

void la_frame_panel(lua_State *L, la_frame_ctx *ctx, int fidx, int pidx, int sidx,
                    lr_panel *p);

/* l_frame_gas_mask.c: the nodal field f (the grid's (nx+1) x (ny+1) nodes)
 * resampled k times finer, far below every band farther than 0.75 of a
 * gas point's spacing from every gas point, into fd's samples (f, nx, ny; the
 * box is the grid's); returns k, or 0 (no gas: fd untouched). */
int la_frame_gas_mask(lua_State *L, la_frame_ctx *ctx, const lm_sim *sim, const double *f,
                      lr_field *fd);

/* l_frame_contact.c: contact = true, the grid normals and node states of
 * the last step's contact correction appended to the side's arrows; at one
 * node of each every x every block of nodes, the arrows scale times their
 * usual length, outlined in white when outlined (contact = {every = ,
 * scale = }; 1, 1 and not outlined for true). */
void la_frame_contact(lua_State *L, la_frame_ctx *ctx, lm_sim *sim, int every,
                      double scale, int outlined, lr_layers *l);

#endif
