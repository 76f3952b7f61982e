/* l_frame_common.c - sim:frame's pieces common to 2D and 3D
 * (l_frame_common.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "l_frame_common.h"

void la_frame_size(lua_State *L, int idx, const char *fn, int *width, int *height)
{
    double w = la_opt_number(L, idx, fn, "width", 800);
    double h = la_opt_number(L, idx, fn, "height", 800);
    if (!(w >= 16 && w <= 16384) || !(h >= 16 && h <= 16384) || w != (int)w || h != (int)h)
        luaL_error(L, "%s: width and height must be whole numbers in [16, 16384] (got %f x %f)",
                   fn, w, h);
    *width = (int)w;
    *height = (int)h;
}

size_t la_frame_panel_count(lua_State *L, int idx, const char *fn)
{
    size_t n = lua_istable(L, idx) ? lua_rawlen(L, idx) : 0;
    if (n < 1 || n > LA_FRAME_MAX_PANELS)
        luaL_error(L, "%s: 'panels' must be a list of 1 to %d panel tables", fn,
                   LA_FRAME_MAX_PANELS);
    return n;
}

void la_frame_panel_at(lua_State *L, int idx, size_t k, const char *fn, const char *const keys[],
                       char name[48])
{
    snprintf(name, 48, "%s: panels[%zu]", fn, k + 1);
    if (lua_rawgeti(L, idx, (lua_Integer)k + 1) != LUA_TTABLE)
        luaL_error(L, "%s must be a table", name);
    la_check_keys(L, -1, name, keys);
}

void la_frame_layout(lua_State *L, const char *fn, double r, double c, size_t n, int *rows,
                     int *cols)
{
    if (!(r >= 1 && c >= 1 && r <= LA_FRAME_MAX_PANELS && c <= LA_FRAME_MAX_PANELS) ||
        r != floor(r) || c != floor(c))
        luaL_error(L, "%s: 'layout' must be {rows, cols}, whole numbers >= 1", fn);
    if (r * c < (double)n)
        luaL_error(L, "%s: 'layout' {%d, %d} has fewer cells than the %d panels", fn, (int)r,
                   (int)c, (int)n);
    *rows = (int)r;
    *cols = (int)c;
}

static void range_text(char out[LA_FRAME_RANGE_LEN], la_frame_ranges r)
{
    size_t used = 0;
    out[0] = 0;
    for (size_t k = 0; k < r.n; k++) {
        double lo, hi;
        if (used >= LA_FRAME_RANGE_LEN - 1 || !r.range(r.panels, k, &lo, &hi)) continue;
        int len = snprintf(out + used, LA_FRAME_RANGE_LEN - used, "%s%.17g %.17g",
                           used ? "; " : "", lo, hi);
        used = len > 0 ? used + (size_t)len : used;
    }
}

size_t la_frame_text(lua_State *L, la_frame_texts *t, const char *layers, const char *title,
                     la_frame_ranges r)
{
    la_provenance(L, &t->prov);
    range_text(t->range, r);
    lr_text_chunk *text = t->text;
    const char *range = t->range;
    memcpy(text, t->prov.text, sizeof t->prov.text);
    size_t n = 4;
    text[n].key = "lamina:layers";
    text[n++].value = layers;
    if (title && *title) {
        text[n].key = "Title";
        text[n++].value = title;
    }
    if (range[0]) {
        text[n].key = "lamina:range";
        text[n++].value = range;
    }
    return n;
}

int la_frame_written(lua_State *L, const char *fn, const char *file, int rc, const char *err)
{
    if (rc != 0) return luaL_error(L, "%s: %s", fn, err);
    la_note_image(L, file);
    lua_pushstring(L, file);
    return 1;
}
