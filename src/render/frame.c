/* frame.c - one simulation frame as a picture: grid, particles, label.
 *
 * A frame is the simplest figure (figure.h): one panel showing the world
 * window with its grid and particles coloured by body, the time label
 * bottom-left and the title on top. The layout and drawing live in
 * figure*.c; this file keeps the palette and the lr_frame entry point. */
#include "figure.h"
#include "render.h"

#include <string.h>

/* Okabe & Ito (2008), readable with every common colour-vision deficiency.
 * Blue and vermilion first: the two most distinct, for the common case of
 * two bodies. Yellow and black last: weakest on white, and black would
 * hide among the text and outline. */
static const lr_rgba palette[] = {
    { 0x00 / 255.0, 0x72 / 255.0, 0xB2 / 255.0, 1.0 },   /* blue */
    { 0xD5 / 255.0, 0x5E / 255.0, 0x00 / 255.0, 1.0 },   /* vermilion */
    { 0x00 / 255.0, 0x9E / 255.0, 0x73 / 255.0, 1.0 },   /* bluish green */
    { 0xE6 / 255.0, 0x9F / 255.0, 0x00 / 255.0, 1.0 },   /* orange */
    { 0x56 / 255.0, 0xB4 / 255.0, 0xE9 / 255.0, 1.0 },   /* sky blue */
    { 0xCC / 255.0, 0x79 / 255.0, 0xA7 / 255.0, 1.0 },   /* reddish purple */
    { 0xF0 / 255.0, 0xE4 / 255.0, 0x42 / 255.0, 1.0 },   /* yellow */
    { 0x00 / 255.0, 0x00 / 255.0, 0x00 / 255.0, 1.0 },   /* black */
};
#define NPALETTE ((int)(sizeof palette / sizeof palette[0]))

lr_rgba lr_palette(int g)
{
    int k = g % NPALETTE;
    return palette[k < 0 ? k + NPALETTE : k];
}

int lr_frame_write(const lr_frame *f, const char *path, char *err, size_t errlen)
{
    if (!f)
        return lr_figure_write(NULL, path, err, errlen);
    /* one panel of one points layer; what is not named is zero */
    lr_points pts = { .n = f->n, .x = f->x, .y = f->y, .group = f->group,
                      .radius = f->radius };
    lr_panel panel = { .wx0 = f->wx0, .wy0 = f->wy0, .wx1 = f->wx1, .wy1 = f->wy1,
                       .side[0] = { .grid = f->grid, .points = &pts, .npoints = 1 } };
    lr_figure fig = { .width = f->width, .height = f->height, .backend = f->backend,
                      .panels = &panel, .npanels = 1, .title = f->title, .label = f->label,
                      .text = f->text, .ntext = f->ntext };
    return lr_figure_write(&fig, path, err, errlen);
}
