/* canvas_gl_text.c - text in the GL backends (OSMesa, EGL).
 *
 * Each string is rasterised by cairo, with the face and options the cairo
 * backend uses (font.c), into an A8 coverage image that sits on the
 * canvas's pixel grid: the string keeps its sub-pixel origin inside the
 * image, and the image is drawn at whole-pixel offsets with nearest
 * sampling. So a label has the same glyph shapes, spacing and coverage
 * through either backend; only the final blend is GL's. A string per
 * texture rather than a glyph atlas: frames carry a handful of strings,
 * and whole strings keep cairo's own glyph placement. */
#include "canvas_gl.h"

#include <cairo.h>
#include <math.h>

/* A8 coverage of `text` with its origin at (x, y) in canvas pixels; the
 * image's top-left pixel is canvas pixel (*ox, *oy). NULL if there is no
 * ink or cairo fails. */
static cairo_surface_t *rasterise(double x, double y, double size,
                                  lr_align align, const char *text, int *ox, int *oy)
{
    cairo_surface_t *probe = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
    cairo_t *cr = cairo_create(probe);
    cairo_text_extents_t e = { 0 };
    if (lr_font_setup(cr) == 0) {
        cairo_set_font_size(cr, size);
        cairo_text_extents(cr, text, &e);
    }
    int ok = cairo_status(cr) == CAIRO_STATUS_SUCCESS && e.width > 0 && e.height > 0;
    cairo_destroy(cr);
    cairo_surface_destroy(probe);
    if (!ok)
        return NULL;
    if (align != LR_ALIGN_LEFT)
        x -= align == LR_ALIGN_CENTER ? e.x_advance / 2.0 : e.x_advance;
    /* the ink box, a pixel of room around it (antialiasing, rounding) */
    double x0 = floor(x + e.x_bearing) - 2, y0 = floor(y + e.y_bearing) - 2;
    double x1 = ceil(x + e.x_bearing + e.width) + 2;
    double y1 = ceil(y + e.y_bearing + e.height) + 2;
    if (!(x1 - x0 < 32768 && y1 - y0 < 32768))
        return NULL;
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_A8, (int)(x1 - x0),
                                                    (int)(y1 - y0));
    cr = cairo_create(s);
    if (lr_font_setup(cr) == 0) {
        cairo_set_font_size(cr, size);
        cairo_set_source_rgba(cr, 0, 0, 0, 1);
        cairo_move_to(cr, x - x0, y - y0);  /* whole-pixel shift: same glyphs */
        cairo_show_text(cr, text);
    }
    ok = cairo_status(cr) == CAIRO_STATUS_SUCCESS;
    cairo_destroy(cr);
    cairo_surface_flush(s);
    if (!ok || cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(s);
        return NULL;
    }
    *ox = (int)x0;
    *oy = (int)y0;
    return s;
}

void gl_blend_coverage(gl_canvas *c, GLuint tex, double x, double y, int w,
                       int h, int tw, int th, int flip, lr_rgba colour)
{
    /* texel (i, j) lands on canvas pixel (x + i, y + j): with x, y whole,
     * corners sit on pixel edges and each pixel centre samples one texel
     * centre */
    float x0 = (float)x, y0 = (float)y, x1 = x0 + (float)w, y1 = y0 + (float)h;
    float s1 = (float)w / (float)tw, th1 = (float)h / (float)th;
    float t0 = flip ? th1 : 0.0f, t1 = flip ? 0.0f : th1;
    const float pos[8] = { x0, y0, x1, y0, x1, y1, x0, y1 };
    const float uv[8] = { 0, t0, s1, t0, s1, t1, 0, t1 };
    glBindTexture(GL_TEXTURE_2D, tex);
    glUseProgram(c->gl.text_prog);
    glUniform4f(c->gl.text_col, (float)colour.r, (float)colour.g, (float)colour.b,
                (float)colour.a);
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, pos);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 0, uv);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    glDisableVertexAttribArray(0);
    glDisableVertexAttribArray(1);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void gl_text(lr_canvas *base, double x, double y, double size, lr_rgba colour,
             lr_align align, const char *text)
{
    gl_canvas *c = glc(base);
    int ox = 0, oy = 0;
    cairo_surface_t *s = rasterise(x, y, size, align, text, &ox, &oy);
    if (!s)
        return;
    int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
    gl_flush(c);
    glBindTexture(GL_TEXTURE_2D, c->gl.text_texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, cairo_image_surface_get_stride(s));
    glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, w, h, 0, GL_ALPHA, GL_UNSIGNED_BYTE,
                 cairo_image_surface_get_data(s));
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    cairo_surface_destroy(s);
    gl_blend_coverage(c, c->gl.text_texture, ox, oy, w, h, w, h, 0, colour);
}
