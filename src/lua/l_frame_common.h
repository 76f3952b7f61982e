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

/* The panels' value ranges for lamina:range: range(panels, k, lo, hi)
 * gives panel k's colour bar's ends, or 0 when it has none. */
typedef struct la_frame_ranges {
    const void *panels;
    size_t n;
    int (*range)(const void *panels, size_t k, double *lo, double *hi);
} la_frame_ranges;

/* What an image's text chunks point into: kept by the caller until the
 * image is written. */
#define LA_FRAME_RANGE_LEN (LA_FRAME_MAX_PANELS * 56)
typedef struct la_frame_texts {
    la_prov prov;
    char range[LA_FRAME_RANGE_LEN];
    lr_text_chunk text[7];
} la_frame_texts;

/* The image's text chunks into t->text: the provenance (la_provenance: it
 * pushes a string that stays on the stack), then lamina:layers, the title
 * as PNG's "Title" when there is one (what a frame says it shows can be
 * read back), and lamina:range - each coloured panel's "lo hi; ...", so
 * that a check can compare it with the fields the other outputs write
 * (tests/io/fields_agree.py) - when a panel has a colour bar. Returns how
 * many. */
size_t la_frame_text(lua_State *L, la_frame_texts *t, const char *layers, const char *title,
                     la_frame_ranges r);

/* After the writer's rc (0: written) and err: the file noted and its name
 * returned to the script (1 result), or a Lua error naming fn. */
int la_frame_written(lua_State *L, const char *fn, const char *file, int rc, const char *err);

#endif
