/* figure_bars.c - the colour bar beside a panel and the scale bar inside
 * it. Ticks use the plots' "nice" steps (plot.h), so a colour bar reads
 * like a plot axis. */
#include "figure_internal.h"
#include "plot.h"

#include <math.h>
#include <stdio.h>

#define MAX_BAR_TICKS 16

/* Sizes in fonts. */
#define BAR_GAP 0.6         /* between the panel and the bar */
#define BAR_WIDTH 0.9
#define TICK_LEN 0.3
#define TICK_FONT 0.8       /* tick labels, bar label, scale bar label */

static int bar_ticks(double vmin, double vmax, double *t, char (*labels)[LR_TICK_LABEL_MAX])
{
    double step;
    int n = lr_plot_ticks(vmin, vmax, 5, t, MAX_BAR_TICKS, &step);
    if (n > 0)
        lr_plot_tick_labels(t, n, step, labels);
    return n < 0 ? 0 : n;
}

double fig_colourbar_width(const lr_panel *p, double font, double vmin, double vmax)
{
    double t[MAX_BAR_TICKS];
    char labels[MAX_BAR_TICKS][LR_TICK_LABEL_MAX];
    int n = bar_ticks(vmin, vmax, t, labels);
    double widest = 0;
    for (int i = 0; i < n; i++)
        widest = fmax(widest, lr_text_width(TICK_FONT * font, labels[i]));
    double w = (BAR_GAP + BAR_WIDTH + TICK_LEN + 0.3) * font + widest + 0.2 * font;
    double lw = lr_text_width(TICK_FONT * font, p->colourbar_label) + 0.6 * font;
    return ceil(fmax(w, BAR_GAP * font + lw));
}

/* The bar in the strip starting at x, spanning rows y0..y1 (the window's
 * height); its label on top (from the bar's left edge: the strip is wide
 * enough for it), the values growing upwards. Rows are drawn
 * one pixel line each, so the gradient is as smooth as the image allows. */
void fig_draw_colourbar(lr_canvas *c, const lr_panel *p, double x, double y0,
                        double y1, double font, double vmin, double vmax)
{
    int bx0 = (int)lround(x + BAR_GAP * font);
    int bx1 = bx0 + (int)lround(BAR_WIDTH * font);
    double label_band = p->colourbar_label && *p->colourbar_label ? 1.5 * font : 0.0;
    int iy0 = (int)lround(y0 + label_band), iy1 = (int)lround(y1);
    if (iy1 - iy0 < 4)
        return;     /* no room */
    for (int py = iy0; py < iy1; py++) {
        double t = (iy1 - (py + 0.5)) / (iy1 - iy0);
        lr_canvas_line(c, bx0, py + 0.5, bx1, py + 0.5, 1.0,
                       lr_cmap_colour(p->cmap, t), 0.0);
    }
    lr_canvas_rect(c, bx0 - 0.5, iy0 - 0.5, bx1 - bx0 + 1, iy1 - iy0 + 1, 1.0,
                   LR_FIG_OUTLINE);
    double t[MAX_BAR_TICKS];
    char labels[MAX_BAR_TICKS][LR_TICK_LABEL_MAX];
    int n = bar_ticks(vmin, vmax, t, labels);
    for (int i = 0; i < n; i++) {
        double py = floor(iy1 - (t[i] - vmin) / (vmax - vmin) * (iy1 - iy0)) + 0.5;
        lr_canvas_line(c, bx1 + 0.5, py, bx1 + 0.5 + TICK_LEN * font, py, 1.0,
                       LR_FIG_OUTLINE, 0.0);
        lr_canvas_text(c, bx1 + (TICK_LEN + 0.3) * font, py + 0.3 * font,
                       TICK_FONT * font, LR_FIG_TEXT, LR_ALIGN_LEFT, labels[i]);
    }
    if (label_band > 0)
        lr_canvas_text(c, bx0, iy0 - 0.75 * font, TICK_FONT * font,
                       LR_FIG_TEXT, LR_ALIGN_LEFT, p->colourbar_label);
}

/* The largest 1, 2 or 5 x 10^k not above x. */
static double round_length(double x)
{
    double e = pow(10.0, floor(log10(x)));
    double m = x / e;
    return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * e;
}

void fig_draw_scalebar(lr_canvas *c, const fig_view *v, const lr_panel *p, double font)
{
    double len = p->scalebar;
    if (len < 0)
        len = round_length(0.2 * (v->wx1 - v->wx0));
    double px = len * v->s;
    if (!(len > 0) || !isfinite(px) || px < 4)
        return;
    double left, top, right, bottom;
    fig_to_pixel(v, v->wx0, v->wy1, &left, &top);
    fig_to_pixel(v, v->wx1, v->wy0, &right, &bottom);
    double thick = fmax(3.0, floor(0.25 * font));
    double x1 = floor(right - 0.8 * font), x0 = x1 - round(px);
    double y = floor(bottom - 0.8 * font) + (((long)thick % 2) ? 0.5 : 0.0);
    char text[64];
    snprintf(text, sizeof text, "%g%s%s", len, p->units && *p->units ? " " : "",
             p->units ? p->units : "");
    double tw = lr_text_width(TICK_FONT * font, text);
    /* a pale backing keeps the bar readable over particles */
    double bl = fmin(x0, 0.5 * (x0 + x1) - 0.5 * tw) - 0.3 * font;
    double br = fmax(x1, 0.5 * (x0 + x1) + 0.5 * tw) + 0.3 * font;
    double bt = y - thick - 1.3 * font, bb = y + thick;
    double box[8] = { bl, bt, br, bt, br, bb, bl, bb };
    size_t four = 4;
    const lr_rgba backing = { 1, 1, 1, 0.75 };
    lr_canvas_fill(c, 1, &four, box, backing);
    lr_canvas_line(c, x0, y, x1, y, thick, LR_FIG_TEXT, 0.0);
    lr_canvas_line(c, x0 + 0.5, y - thick, x0 + 0.5, y + 0.5 * thick, 1.0, LR_FIG_TEXT, 0.0);
    lr_canvas_line(c, x1 - 0.5, y - thick, x1 - 0.5, y + 0.5 * thick, 1.0, LR_FIG_TEXT, 0.0);
    lr_canvas_text(c, 0.5 * (x0 + x1), y - thick - 0.35 * font, TICK_FONT * font,
                   LR_FIG_TEXT, LR_ALIGN_CENTER, text);
}
