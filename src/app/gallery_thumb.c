/* gallery_thumb.c - small copies of figures for the index and the baselines.
 *
 * A box filter: every thumbnail pixel is the mean of the source area it
 * covers, each source pixel weighted by how much of it lies inside (so a
 * 512 -> 256 reduction averages 2x2 blocks and 800 -> 256 handles the
 * fractions). It keeps thin grid lines as light lines instead of dropping
 * or aliasing them. Colours are averaged premultiplied by alpha, so a
 * transparent pixel adds no colour. Separable: rows first, then columns. */
#include "gallery.h"

#include "render.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Weights of the source samples [first, first + count) for each of the
 * `dst` output samples over `src` input samples. */
typedef struct taps {
    int *first, *count;
    double *w;          /* count[i] weights per output sample, packed */
    int *offset;        /* into w */
} taps;

static void taps_make(taps *t, int src, int dst)
{
    double scale = (double)src / dst;
    t->first = g_alloc((size_t)dst * sizeof *t->first);
    t->count = g_alloc((size_t)dst * sizeof *t->count);
    t->offset = g_alloc((size_t)dst * sizeof *t->offset);
    t->w = g_alloc(((size_t)dst * ((size_t)ceil(scale) + 2)) * sizeof *t->w);
    int off = 0;
    for (int i = 0; i < dst; i++) {
        double a = i * scale, b = (i + 1) * scale;
        int k0 = (int)floor(a), k1 = (int)ceil(b);
        if (k1 > src)
            k1 = src;
        t->first[i] = k0;
        t->count[i] = k1 - k0;
        t->offset[i] = off;
        for (int k = k0; k < k1; k++) {
            double lo = k > a ? k : a, hi = k + 1 < b ? k + 1 : b;
            t->w[off++] = (hi - lo) / scale;
        }
    }
}

static void taps_free(taps *t)
{
    free(t->first);
    free(t->count);
    free(t->offset);
    free(t->w);
}

static unsigned char to_byte(double v)
{
    return (unsigned char)(v <= 0 ? 0 : v >= 255 ? 255 : (int)(v + 0.5));
}

static unsigned char *shrink(const unsigned char *src, int sw, int sh, int dw, int dh)
{
    taps tx, ty;
    taps_make(&tx, sw, dw);
    taps_make(&ty, sh, dh);
    /* rows: sh x dw, premultiplied, 4 doubles per pixel */
    double *rows = g_alloc((size_t)sh * dw * 4 * sizeof *rows);
    for (int y = 0; y < sh; y++)
        for (int x = 0; x < dw; x++) {
            double acc[4] = { 0, 0, 0, 0 };
            for (int k = 0; k < tx.count[x]; k++) {
                const unsigned char *p = src + 4 * ((size_t)y * sw + tx.first[x] + k);
                double w = tx.w[tx.offset[x] + k], a = p[3] / 255.0;
                acc[0] += w * p[0] * a;
                acc[1] += w * p[1] * a;
                acc[2] += w * p[2] * a;
                acc[3] += w * p[3];
            }
            memcpy(rows + 4 * ((size_t)y * dw + x), acc, sizeof acc);
        }
    unsigned char *out = g_alloc((size_t)dw * dh * 4);
    for (int y = 0; y < dh; y++)
        for (int x = 0; x < dw; x++) {
            double acc[4] = { 0, 0, 0, 0 };
            for (int k = 0; k < ty.count[y]; k++) {
                const double *p = rows + 4 * ((size_t)(ty.first[y] + k) * dw + x);
                double w = ty.w[ty.offset[y] + k];
                for (int c = 0; c < 4; c++)
                    acc[c] += w * p[c];
            }
            unsigned char *q = out + 4 * ((size_t)y * dw + x);
            double a = acc[3] / 255.0;
            for (int c = 0; c < 3; c++)
                q[c] = a > 0 ? to_byte(acc[c] / a) : 0;
            q[3] = to_byte(acc[3]);
        }
    free(rows);
    taps_free(&tx);
    taps_free(&ty);
    return out;
}

int g_thumbnail(const char *src, const char *dst, int max_width, char *err, size_t errlen)
{
    int w, h;
    unsigned char *px;
    if (lr_png_read(src, &w, &h, &px, err, errlen) != 0)
        return -1;
    int dw = w, dh = h;
    unsigned char *small = px;
    if (w > max_width) {
        dw = max_width;
        dh = (int)((double)h * dw / w + 0.5);
        if (dh < 1)
            dh = 1;
        small = shrink(px, w, h, dw, dh);
    }
    /* no version in the provenance: a thumbnail's bytes change only when its
     * pixels do, so committed thumbnails and baselines do not churn */
    const char *slash = strrchr(src, '/');
    const lr_text_chunk text[] = { { "Software", "lamina gallery" },
                                   { "lamina:thumbnail-of", slash ? slash + 1 : src } };
    int rc = lr_png_write(dst, dw, dh, small, text, 2, err, errlen);
    if (small != px)
        free(small);
    free(px);
    return rc;
}
