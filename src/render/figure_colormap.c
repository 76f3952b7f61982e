/* figure_colormap.c - colour maps for particles coloured by a value.
 *
 * viridis (van der Walt & Smith, matplotlib 1.5, 2015) is given by its
 * published eleven samples at t = 0, 0.1, ..., 1 (#440154 ... #fde725),
 * interpolated linearly in sRGB: at this spacing the map stays monotone in
 * lightness and readable in grey and with colour-vision deficiencies, which
 * is what it was designed for. rdbu is ColorBrewer's 11-class RdBu
 * (Brewer, colorbrewer2.org), reversed so that negative values are blue:
 * for signed fields (stress components, velocity components) around zero. */
#include "figure.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "util.h"

#define NSAMPLES 11

static const unsigned char viridis[NSAMPLES][3] = {
    { 0x44, 0x01, 0x54 }, { 0x48, 0x24, 0x75 }, { 0x41, 0x44, 0x87 },
    { 0x35, 0x5f, 0x8d }, { 0x2a, 0x78, 0x8e }, { 0x21, 0x91, 0x8c },
    { 0x22, 0xa8, 0x84 }, { 0x44, 0xbf, 0x70 }, { 0x7a, 0xd1, 0x51 },
    { 0xbd, 0xdf, 0x26 }, { 0xfd, 0xe7, 0x25 },
};

static const unsigned char rdbu[NSAMPLES][3] = {
    { 0x05, 0x30, 0x61 }, { 0x21, 0x66, 0xac }, { 0x43, 0x93, 0xc3 },
    { 0x92, 0xc5, 0xde }, { 0xd1, 0xe5, 0xf0 }, { 0xf7, 0xf7, 0xf7 },
    { 0xfd, 0xdb, 0xc7 }, { 0xf4, 0xa5, 0x82 }, { 0xd6, 0x60, 0x4d },
    { 0xb2, 0x18, 0x2b }, { 0x67, 0x00, 0x1f },
};

static const char *const names[] = { "viridis", "rdbu" };

int lr_cmap_parse(const char *name, lr_cmap *m, char *err, size_t errlen)
{
    int i = lu_name_index(name, names, 2);
    if (i >= 0) {
        *m = (lr_cmap)i;
        return 0;
    }
    lu_err(err, errlen, "unknown colour map '%s' (known: viridis, rdbu)", name ? name : "");
    return -1;
}

const char *lr_cmap_name(lr_cmap m)
{
    return m == LR_CMAP_RDBU ? "rdbu" : "viridis";
}

lr_rgba lr_cmap_colour(lr_cmap m, double t)
{
    if (isnan(t)) {
        lr_rgba grey = { 0.6, 0.6, 0.6, 1.0 };
        return grey;
    }
    const unsigned char (*table)[3] = m == LR_CMAP_RDBU ? rdbu : viridis;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double u = t * (NSAMPLES - 1);
    int i = (int)u;
    if (i >= NSAMPLES - 1)
        i = NSAMPLES - 2;
    double f = u - i;
    lr_rgba k;
    k.r = ((1 - f) * table[i][0] + f * table[i + 1][0]) / 255.0;
    k.g = ((1 - f) * table[i][1] + f * table[i + 1][1]) / 255.0;
    k.b = ((1 - f) * table[i][2] + f * table[i + 1][2]) / 255.0;
    k.a = 1.0;
    return k;
}
