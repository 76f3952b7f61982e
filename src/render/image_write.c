/* image_write.c - the one writer of drawn pictures (render.h): frames,
 * plots and figures hand it their pixels and the path, and it picks the
 * file format from the path (lr_format_of). PNG is the one raster format;
 * SVG and PDF are drawn by cairo's vector surfaces from the drawing itself
 * (lr_canvas_vector_new), which pixels cannot be turned back into, so a
 * vector name given pixels is refused by name rather than written as PNG
 * bytes under a .svg / .pdf name. A new raster format is added here. */
#include "render.h"
#include "util.h"

int lr_image_write(const char *path, int width, int height, const unsigned char *rgba,
                   const lr_text_chunk *text, size_t ntext, char *err, size_t errlen)
{
    switch (lr_format_of(path)) {
    case LR_FORMAT_PNG:
        return lr_png_write(path, width, height, rgba, text, ntext, err, errlen);
    case LR_FORMAT_SVG:
    case LR_FORMAT_PDF:
        break;
    }
    lu_err(err, errlen, "cannot write '%s': this picture is pixels, written as PNG only "
           "(name it .png)", path);
    return -1;
}
