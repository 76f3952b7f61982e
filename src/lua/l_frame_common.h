/* l_frame_common.h - what sim:frame reads and writes alike for a 2D sim
 * (l_frame.c, lr_figure) and a 3D one (l_frame3d.c, lr_figure3d): the
 * image's size, the panels' list, the layout's cells, and the text chunks
 * each image carries (provenance, lamina:layers, Title, lamina:range).
 * The panels themselves are each dimension's own. */
#ifndef LAMINA_L_FRAME_COMMON_H
#define LAMINA_L_FRAME_COMMON_H

#include <stddef.h>

#include "l_internal.h"
#include "render.h"

#define LA_FRAME_MAX_PANELS 64

/* width and height of the options at idx: whole numbers in [16, 16384],
 * 800 each when absent. */
void la_frame_size(lua_State *L, int idx, const char *fn, int *width, int *height);

/* The panels' list at idx: its length, 1 to LA_FRAME_MAX_PANELS. */
size_t la_frame_panel_count(lua_State *L, int idx, const char *fn);
/* panels[k + 1] of the list at idx pushed, checked to be a table with
 * the keys keys; name gets "FN: panels[k + 1]" for its messages. */
void la_frame_panel_at(lua_State *L, int idx, size_t k, const char *fn, const char *const keys[],
                       char name[48]);

/* layout = {rows, cols} as read (r, c): whole numbers from 1 to
 * LA_FRAME_MAX_PANELS with room for n panels. */
void la_frame_layout(lua_State *L, const char *fn, double r, double c, size_t n, int *rows,
                     int *cols);

/* lamina:range: each coloured panel's value range, the colour bar's ends
 * ("lo hi; lo hi ..."), so that a check can compare it with the fields the
 * other outputs write (tests/io/fields_agree.py). range(panels, k, lo, hi)
 * gives panel k's, or 0 when it has no colour bar. out is empty when none
 * has. */
#define LA_FRAME_RANGE_LEN (LA_FRAME_MAX_PANELS * 56)
void la_frame_range_text(char out[LA_FRAME_RANGE_LEN], const void *panels, size_t n,
                         int (*range)(const void *panels, size_t k, double *lo, double *hi));

/* The image's text chunks into text (7 at the most): the provenance, then
 * lamina:layers, the title as PNG's "Title" when there is one (what a
 * frame says it shows can be read back), lamina:range when not empty.
 * Returns how many. */
size_t la_frame_text(lr_text_chunk text[7], const la_prov *prov, const char *layers,
                     const char *title, const char *range);

#endif
