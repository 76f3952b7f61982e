/* test_disc_stamps.c - cairo's stamped discs (canvas_cairo.c, "discs") are
 * the same pixels whichever loop draws them: the fast one (a stamp wholly
 * inside the canvas: its covered pixels only, two colour channels per
 * multiply) and the clipped one (a stamp reaching past the edge: every
 * mask pixel, one channel at a time). The same disc, at the same sub-pixel
 * phase, is drawn in the middle of one canvas and beside the left edge of
 * another (its box crosses the edge, its covered pixels do not), over a
 * grey background, in translucent and opaque colours and at several
 * radii; the pixels around both must agree byte for byte. */
#include "check.h"
#include "render.h"

#include <stdlib.h>

enum { W = 48, H = 48 };

static unsigned char *draw(double x, double y, double r, lr_rgba colour)
{
    char err[256];
    lr_canvas *c = lr_canvas_cairo_new(W, H, err, sizeof err);
    if (!c) {
        fprintf(stderr, "%s\n", err);
        return NULL;
    }
    lr_canvas_clear(c, (lr_rgba){ 0.5, 0.6, 0.7, 1 });
    /* two overlapping discs: the second blends over the first */
    double xs[2] = { x, x + 0.4 }, ys[2] = { y, y + 0.3 };
    lr_rgba cols[2] = { colour, { colour.b, colour.r, colour.g, 0.5 } };
    lr_canvas_discs(c, 2, xs, ys, r, cols);
    unsigned char *img = lr_canvas_read_rgba(c);
    lr_canvas_free(c);
    return img;
}

int main(void)
{
    const double radii[] = { 0.9, 1.0, 1.43, 2.2 };
    const lr_rgba colours[] = { { 0.9, 0.2, 0.1, 1 }, { 0.1, 0.4, 0.8, 0.6 },
                                { 0.3, 0.9, 0.2, 0.25 } };
    int compared = 0;
    for (size_t k = 0; k < sizeof radii / sizeof radii[0]; k++)
        for (size_t m = 0; m < sizeof colours / sizeof colours[0]; m++) {
            double r = radii[k];
            int reach = (int)ceil(r) + 1;
            /* the same fractional phase; the edge one starts a stamp column
             * left of the canvas but covers only pixels at x >= 0 */
            double fx = 0.31, fy = 0.62, xe = reach - 1 + fx;
            unsigned char *mid = draw(24 + fx, 24 + fy, r, colours[m]);
            unsigned char *edge = draw(xe, 24 + fy, r, colours[m]);
            CHECK(mid && edge);
            if (!mid || !edge) {
                free(mid);
                free(edge);
                continue;
            }
            int shift = 24 - (reach - 1);   /* mid's column for edge's column */
            for (int j = 24 - reach - 1; j <= 24 + reach + 2; j++)
                for (int i = 0; i <= 2 * reach + 2; i++) {
                    const unsigned char *a = mid + 4 * ((size_t)j * W + (size_t)(i + shift));
                    const unsigned char *b = edge + 4 * ((size_t)j * W + (size_t)i);
                    for (int ch = 0; ch < 4; ch++)
                        if (a[ch] != b[ch]) {
                            fprintf(stderr, "r %g colour %zu: pixel (%d, %d) channel %d: "
                                    "%d inside, %d at the edge\n", r, m, i, j, ch, a[ch], b[ch]);
                            check_failures++;
                            goto next;
                        }
                    compared++;
                }
        next:
            free(mid);
            free(edge);
        }
    printf("disc stamps: %d pixels compared, %d failures\n", compared, check_failures);
    CHECK(compared > 500);
    return check_failures != 0;
}
