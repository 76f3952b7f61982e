/* apng.c - the APNG writer: PNG chunks by hand, image data through zlib.
 *
 * Layout of the file (APNG specification 1.0, Mozilla 2008):
 *   signature, IHDR, acTL (frame count, plays), tEXt...,
 *   fcTL 0, IDAT...             - frame 0, also the still image
 *   fcTL n, fdAT n+1 ...        - every further frame
 *   IEND
 * fcTL and fdAT share one sequence number counter from 0. libpng has no
 * APNG support in Debian's build, so the chunks are written here; the
 * scanline filters and their per-row choice (the least sum of absolute
 * differences, as libpng does) are the PNG standard's. */
#include "apng.h"
#include "atomic_file.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>
#include "util.h"

#define ZLEVEL 9            /* animations are written once, watched often */
#define CHUNK_MAX (1u << 24) /* image data split into chunks of this size */

struct lr_apng {
    lr_atomic out;
    int w, h;
    unsigned nframes, added;
    uint32_t seq;               /* next sequence number */
    uint16_t delay_num, delay_den;
    unsigned char *prev;        /* the frame before, w*h*4 */
    unsigned char *rows;        /* filtered rows of a region */
    int failed;
    char why[256];
};

/* ---- chunks ------------------------------------------------------------- */

static void be32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

static void be16(unsigned char *p, uint16_t v)
{
    p[0] = (unsigned char)(v >> 8);
    p[1] = (unsigned char)v;
}

/* One chunk: length, type, data (an optional 4-byte prefix, then data),
 * CRC over type and data. */
static void chunk(lr_apng *a, const char type[4], const unsigned char *prefix,
                  size_t nprefix, const unsigned char *data, size_t n)
{
    if (a->failed)
        return;
    unsigned char head[8], crc[4];
    be32(head, (uint32_t)(nprefix + n));
    memcpy(head + 4, type, 4);
    uLong c = crc32(0L, Z_NULL, 0);
    c = crc32(c, (const Bytef *)type, 4);
    if (nprefix)
        c = crc32(c, prefix, (uInt)nprefix);
    if (n)
        c = crc32(c, data, (uInt)n);
    be32(crc, (uint32_t)c);
    FILE *fp = a->out.fp;
    errno = 0;
    if (fwrite(head, 1, 8, fp) != 8 || (nprefix && fwrite(prefix, 1, nprefix, fp) != nprefix) ||
        (n && fwrite(data, 1, n, fp) != n) || fwrite(crc, 1, 4, fp) != 4) {
        a->failed = 1;
        snprintf(a->why, sizeof a->why, "%s", errno ? strerror(errno) : "write error");
    }
}

static void fctl(lr_apng *a, int x, int y, int w, int h)
{
    unsigned char d[26];
    be32(d, a->seq++);
    be32(d + 4, (uint32_t)w);
    be32(d + 8, (uint32_t)h);
    be32(d + 12, (uint32_t)x);
    be32(d + 16, (uint32_t)y);
    be16(d + 20, a->delay_num);
    be16(d + 22, a->delay_den);
    d[24] = 0;      /* dispose: none - the next frame draws over this one */
    d[25] = 0;      /* blend: source - the rectangle is replaced */
    chunk(a, "fcTL", NULL, 0, d, sizeof d);
}

/* ---- filters ------------------------------------------------------------ */

static unsigned paeth(int a, int b, int c)
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    return (unsigned)(pa <= pb && pa <= pc ? a : pb <= pc ? b : c);
}

/* Filters row (n bytes, 4 per pixel; up = the row above or NULL) with
 * filter type t into out (n bytes); returns the sum of |signed bytes|. */
static unsigned long filter_row(int t, const unsigned char *row,
                                const unsigned char *up, size_t n, unsigned char *out)
{
    unsigned long sum = 0;
    for (size_t i = 0; i < n; i++) {
        int a = i >= 4 ? row[i - 4] : 0, b = up ? up[i] : 0;
        int c = i >= 4 && up ? up[i - 4] : 0;
        unsigned v;
        switch (t) {
        case 1: v = (unsigned)(row[i] - a); break;
        case 2: v = (unsigned)(row[i] - b); break;
        case 3: v = (unsigned)(row[i] - ((a + b) >> 1)); break;
        case 4: v = (unsigned)(row[i] - (int)paeth(a, b, c)); break;
        default: v = row[i]; break;
        }
        out[i] = (unsigned char)v;
        sum += (unsigned char)v < 128 ? (unsigned char)v : 256 - (unsigned char)v;
    }
    return sum;
}

/* The filtered scanlines of the region x, y, w, h of img into a->rows:
 * (1 + 4 w) bytes per row. */
static void filter_region(lr_apng *a, const unsigned char *img, int x, int y,
                          int w, int h, unsigned char *trial)
{
    size_t n = 4 * (size_t)w, stride = 4 * (size_t)a->w;
    for (int j = 0; j < h; j++) {
        const unsigned char *row = img + (size_t)(y + j) * stride + 4 * (size_t)x;
        const unsigned char *up = j ? row - stride : NULL;
        unsigned char *dst = a->rows + (size_t)j * (n + 1);
        unsigned long best = ~0ul;
        for (int t = 0; t < 5; t++) {
            unsigned long s = filter_row(t, row, up, n, trial);
            if (s < best) {
                best = s;
                dst[0] = (unsigned char)t;
                memcpy(dst + 1, trial, n);
            }
        }
    }
}

/* Compresses the region's rows and writes them as IDAT (first frame) or
 * fdAT chunks. */
static void write_data(lr_apng *a, size_t nbytes, int first)
{
    z_stream z;
    memset(&z, 0, sizeof z);
    if (deflateInit(&z, ZLEVEL) != Z_OK) {
        a->failed = 1;
        snprintf(a->why, sizeof a->why, "zlib cannot start");
        return;
    }
    size_t cap = deflateBound(&z, (uLong)nbytes);
    unsigned char *buf = malloc(cap);
    if (!buf) {
        deflateEnd(&z);
        a->failed = 1;
        snprintf(a->why, sizeof a->why, "out of memory");
        return;
    }
    z.next_in = a->rows;
    z.avail_in = (uInt)nbytes;
    z.next_out = buf;
    z.avail_out = (uInt)cap;
    int rc = deflate(&z, Z_FINISH);
    size_t len = cap - z.avail_out;
    deflateEnd(&z);
    if (rc != Z_STREAM_END) {
        a->failed = 1;
        snprintf(a->why, sizeof a->why, "zlib cannot compress");
    }
    for (size_t off = 0; off < len && !a->failed; off += CHUNK_MAX) {
        size_t n = len - off < CHUNK_MAX ? len - off : CHUNK_MAX;
        if (first) {
            chunk(a, "IDAT", NULL, 0, buf + off, n);
        } else {
            unsigned char s[4];
            be32(s, a->seq++);
            chunk(a, "fdAT", s, 4, buf + off, n);
        }
    }
    free(buf);
}

/* ---- the animation ------------------------------------------------------ */

lr_apng *lr_apng_open(const char *path, int w, int h, unsigned nframes, double fps,
                      unsigned loops, const lr_text_chunk *text, size_t ntext,
                      char *err, size_t errlen)
{
    if (w < 1 || h < 1 || w > LR_CANVAS_MAX_SIZE || h > LR_CANVAS_MAX_SIZE) {
        lu_err(err, errlen, "cannot write '%s': invalid frame size %dx%d", path, w, h);
        return NULL;
    }
    if (nframes < 1 || !(fps >= 0.02 && fps <= 1000)) {
        lu_err(err, errlen, "cannot write '%s': %s", path, nframes < 1 ?
                "no frames" : "fps must be in [0.02, 1000]");
        return NULL;
    }
    lr_apng *a = calloc(1, sizeof *a);
    size_t frame = 4 * (size_t)w * (size_t)h;
    if (a) {
        a->prev = malloc(frame);
        a->rows = malloc((4 * (size_t)w + 1) * (size_t)h + 4 * (size_t)w);
    }
    if (!a || !a->prev || !a->rows) {
        if (a) {
            free(a->prev);
            free(a->rows);
        }
        free(a);
        lu_err(err, errlen, "cannot write '%s': out of memory", path);
        return NULL;
    }
    a->w = w;
    a->h = h;
    a->nframes = nframes;
    /* delay in milliseconds as a fraction; a PNG counter is 16 bits */
    double ms = round(1000.0 / fps);
    a->delay_num = (uint16_t)(ms < 1 ? 1 : ms > 65535 ? 65535 : ms);
    a->delay_den = 1000;
    if (lr_atomic_open(&a->out, path, err, errlen) != 0) {
        free(a->prev);
        free(a->rows);
        free(a);
        return NULL;
    }
    static const unsigned char sig[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
    if (fwrite(sig, 1, 8, a->out.fp) != 8) {
        a->failed = 1;
        snprintf(a->why, sizeof a->why, "%s", strerror(errno));
    }
    unsigned char ihdr[13];
    be32(ihdr, (uint32_t)w);
    be32(ihdr + 4, (uint32_t)h);
    ihdr[8] = 8;        /* bits per channel */
    ihdr[9] = 6;        /* RGBA */
    ihdr[10] = ihdr[11] = ihdr[12] = 0;   /* deflate, adaptive filters, no interlace */
    chunk(a, "IHDR", NULL, 0, ihdr, sizeof ihdr);
    unsigned char actl[8];
    be32(actl, nframes);
    be32(actl + 4, loops);
    chunk(a, "acTL", NULL, 0, actl, sizeof actl);
    for (size_t i = 0; i < ntext; i++) {
        const char *k = text[i].key, *v = text[i].value ? text[i].value : "";
        size_t nk = k ? strlen(k) : 0;
        if (nk < 1 || nk > 79)
            continue;
        size_t nv = strlen(v);
        unsigned char *t = malloc(nk + 1 + nv);
        if (!t)
            continue;
        memcpy(t, k, nk);
        t[nk] = 0;
        memcpy(t + nk + 1, v, nv);
        chunk(a, "tEXt", NULL, 0, t, nk + 1 + nv);
        free(t);
    }
    return a;
}

/* The smallest rectangle holding every pixel that differs from a->prev;
 * 0 if none does. */
static int changed_box(const lr_apng *a, const unsigned char *img, int *x0, int *y0,
                       int *x1, int *y1)
{
    size_t stride = 4 * (size_t)a->w;
    *x0 = a->w;
    *y0 = a->h;
    *x1 = *y1 = -1;
    for (int y = 0; y < a->h; y++) {
        const unsigned char *p = img + (size_t)y * stride, *q = a->prev + (size_t)y * stride;
        if (memcmp(p, q, stride) == 0)
            continue;
        int l = 0, r = a->w - 1;
        while (memcmp(p + 4 * (size_t)l, q + 4 * (size_t)l, 4) == 0)
            l++;
        while (memcmp(p + 4 * (size_t)r, q + 4 * (size_t)r, 4) == 0)
            r--;
        if (y < *y0) *y0 = y;
        *y1 = y;
        if (l < *x0) *x0 = l;
        if (r > *x1) *x1 = r;
    }
    return *y1 >= 0;
}

int lr_apng_add(lr_apng *a, const unsigned char *rgba, char *err, size_t errlen)
{
    if (a->added >= a->nframes) {
        lu_err(err, errlen, "cannot write '%s': more frames than announced (%u)",
                a->out.path, a->nframes);
        return -1;
    }
    int x0 = 0, y0 = 0, x1 = a->w - 1, y1 = a->h - 1;
    int first = a->added == 0;
    if (!first && !changed_box(a, rgba, &x0, &y0, &x1, &y1))
        x1 = x0 = y1 = y0 = 0;      /* unchanged: one pixel, replaced by itself */
    int w = x1 - x0 + 1, h = y1 - y0 + 1;
    fctl(a, x0, y0, w, h);
    filter_region(a, rgba, x0, y0, w, h, a->rows + (4 * (size_t)a->w + 1) * (size_t)a->h);
    write_data(a, (4 * (size_t)w + 1) * (size_t)h, first);
    memcpy(a->prev, rgba, 4 * (size_t)a->w * (size_t)a->h);
    a->added++;
    if (a->failed) {
        lu_err(err, errlen, "cannot write '%s': %s", a->out.path, a->why);
        return -1;
    }
    return 0;
}

static void release(lr_apng *a)
{
    free(a->prev);
    free(a->rows);
    free(a);
}

void lr_apng_abort(lr_apng *a)
{
    if (!a)
        return;
    lr_atomic_abort(&a->out, "aborted", NULL, 0);
    release(a);
}

int lr_apng_close(lr_apng *a, char *err, size_t errlen)
{
    if (!a->failed && a->added != a->nframes) {
        a->failed = 1;
        snprintf(a->why, sizeof a->why, "%u of %u frames were added", a->added, a->nframes);
    }
    chunk(a, "IEND", NULL, 0, NULL, 0);
    int rc;
    if (a->failed)
        rc = lr_atomic_abort(&a->out, a->why, err, errlen);
    else
        rc = lr_atomic_commit(&a->out, err, errlen);
    release(a);
    return rc;
}
