/* png_io.c - 8-bit RGBA PNG files through libpng, written atomically.
 *
 * A frame is either the complete new image or the old file: the PNG goes
 * into a temporary beside the target and is renamed over it only after it
 * was written and closed without error. Output is deterministic (no tIME
 * chunk, fixed zlib level) so identical pixels give identical bytes, which
 * the regression tests and the gallery rely on.
 *
 * libpng reports errors by longjmp. Each setjmp lives in a small function
 * that changes none of its own locals after the setjmp, and all state that
 * an error handler writes is owned by the caller, so nothing is left
 * indeterminate after the jump. */
#include "atomic_file.h"
#include "render.h"

#include <errno.h>
#include <limits.h>
#include <png.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "util.h"

/* zlib level: fixed so that output bytes do not depend on libpng defaults */
#define PNG_LEVEL 6

/* What the libpng callbacks learned; filled in on failure. */
typedef struct png_io {
    FILE *fp;
    int sys_errno;          /* errno of a failed read/write, 0 if none */
    int truncated;          /* read hit end of file */
    char msg[200];          /* libpng's error message */
} png_io;

/* The reason for a failure inside libpng, in words. */
static const char *io_reason(const png_io *io)
{
    if (io->sys_errno)
        return strerror(io->sys_errno);
    if (io->truncated)
        return "file is truncated";
    return io->msg[0] ? io->msg : "libpng error";
}

static void on_error(png_structp png, png_const_charp msg)
{
    png_io *io = png_get_error_ptr(png);
    snprintf(io->msg, sizeof io->msg, "libpng: %s", msg ? msg : "error");
    png_longjmp(png, 1);
}

/* Warnings (e.g. an unknown ancillary chunk in a file we read) do not make
 * the image wrong, and the library has no channel to report them. */
static void on_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

static void io_write(png_structp png, png_bytep data, size_t len)
{
    png_io *io = png_get_io_ptr(png);
    errno = 0;
    if (fwrite(data, 1, len, io->fp) != len) {
        io->sys_errno = errno ? errno : EIO;
        png_error(png, "write failed");
    }
}

static void io_flush(png_structp png)
{
    png_io *io = png_get_io_ptr(png);
    if (fflush(io->fp) != 0) {
        io->sys_errno = errno ? errno : EIO;
        png_error(png, "flush failed");
    }
}

static void io_read(png_structp png, png_bytep data, size_t len)
{
    png_io *io = png_get_io_ptr(png);
    errno = 0;
    if (fread(data, 1, len, io->fp) != len) {
        if (ferror(io->fp))
            io->sys_errno = errno ? errno : EIO;
        else
            io->truncated = 1;
        png_error(png, "read failed");
    }
}

/* ---- writing ---------------------------------------------------------- */

static int check_text(const lr_text_chunk *text, size_t ntext, const char *path,
                      char *err, size_t errlen)
{
    if (ntext > 0 && !text) {
        lu_err(err, errlen, "cannot write '%s': text chunks missing", path);
        return -1;
    }
    if (ntext > INT_MAX) {
        lu_err(err, errlen, "cannot write '%s': too many text chunks", path);
        return -1;
    }
    for (size_t i = 0; i < ntext; i++) {
        /* PNG keywords are 1-79 bytes (ISO 8859-1; libpng checks the rest) */
        size_t n = text[i].key ? strlen(text[i].key) : 0;
        if (n < 1 || n > 79) {
            lu_err(err, errlen, "cannot write '%s': text chunk %zu: keyword "
                    "must be 1 to 79 characters", path, i + 1);
            return -1;
        }
    }
    return 0;
}

/* libpng's png_text wants non-const pointers; it does not write through them. */
static png_text *make_png_text(const lr_text_chunk *text, size_t ntext)
{
    png_text *t = calloc(ntext ? ntext : 1, sizeof *t);
    if (!t)
        return NULL;
    for (size_t i = 0; i < ntext; i++) {
        t[i].compression = PNG_TEXT_COMPRESSION_NONE;   /* tEXt, not zTXt */
        t[i].key = (png_charp)(uintptr_t)text[i].key;
        t[i].text = (png_charp)(uintptr_t)(text[i].value ? text[i].value : "");
    }
    return t;
}

/* Encodes the image into io->fp. */
static int encode(png_io *io, int width, int height, const unsigned char *rgba,
                  png_text *text, int ntext)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, io,
                                              on_error, on_warning);
    if (!png) {
        snprintf(io->msg, sizeof io->msg, "out of memory");
        return -1;
    }
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        snprintf(io->msg, sizeof io->msg, "out of memory");
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return -1;
    }
    png_set_write_fn(png, io, io_write, io_flush);
    png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, 8,
                 PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(png, PNG_LEVEL);
    if (ntext > 0)
        png_set_text(png, info, text, ntext);
    png_write_info(png, info);
    size_t row = 4 * (size_t)width;
    for (int y = 0; y < height; y++)
        png_write_row(png, rgba + (size_t)y * row);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return 0;
}


static int check_image(const char *path, int width, int height,
                       const unsigned char *rgba, char *err, size_t errlen)
{
    if (!path || !*path) {
        lu_err(err, errlen, "cannot write PNG: empty path");
        return -1;
    }
    /* rows are addressed with size_t and libpng stores 31-bit sizes */
    if (width <= 0 || height <= 0 || (size_t)width > PNG_UINT_31_MAX / 4) {
        lu_err(err, errlen, "cannot write '%s': invalid size %dx%d", path,
                width, height);
        return -1;
    }
    if (!rgba) {
        lu_err(err, errlen, "cannot write '%s': no pixels", path);
        return -1;
    }
    return 0;
}

int lr_png_write(const char *path, int width, int height,
                 const unsigned char *rgba, const lr_text_chunk *text,
                 size_t ntext, char *err, size_t errlen)
{
    if (check_image(path, width, height, rgba, err, errlen) != 0 ||
        check_text(text, ntext, path, err, errlen) != 0)
        return -1;
    png_text *pt = make_png_text(text, ntext);
    if (!pt) {
        lu_err(err, errlen, "cannot write '%s': out of memory", path);
        return -1;
    }
    lr_atomic out;
    if (lr_atomic_open(&out, path, err, errlen) != 0) {
        free(pt);
        return -1;
    }
    png_io io = { 0 };
    io.fp = out.fp;
    if (encode(&io, width, height, rgba, pt, (int)ntext) != 0) {
        free(pt);
        return lr_atomic_abort(&out, io_reason(&io), err, errlen);
    }
    free(pt);
    return lr_atomic_commit(&out, err, errlen);
}

/* ---- reading ---------------------------------------------------------- */

/* Asks libpng to deliver any PNG as 8-bit RGBA. Gamma is left alone: the
 * files this program reads are its own, written without gAMA. */
static void request_rgba8(png_structp png, png_infop info)
{
    int type = png_get_color_type(png, info);
    int depth = png_get_bit_depth(png, info);
    int trns = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
    if (type == PNG_COLOR_TYPE_PALETTE)
        png_set_palette_to_rgb(png);
    if (type == PNG_COLOR_TYPE_GRAY && depth < 8)
        png_set_expand_gray_1_2_4_to_8(png);
    if (trns)
        png_set_tRNS_to_alpha(png);
    if (depth == 16)
        png_set_scale_16(png);
    if (type == PNG_COLOR_TYPE_GRAY || type == PNG_COLOR_TYPE_GRAY_ALPHA)
        png_set_gray_to_rgb(png);
    if (!(type & PNG_COLOR_MASK_ALPHA) && !trns)
        png_set_filler(png, 0xFF, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
}

/* Reads the header and sets up the conversion; the size goes to *w, *h. */
static int decode_header(png_io *io, png_structp png, png_infop info,
                         png_uint_32 *w, png_uint_32 *h)
{
    if (setjmp(png_jmpbuf(png)))
        return -1;
    png_read_info(png, info);
    request_rgba8(png, info);
    png_read_update_info(png, info);
    *w = png_get_image_width(png, info);
    *h = png_get_image_height(png, info);
    if (png_get_bit_depth(png, info) != 8 || png_get_channels(png, info) != 4 ||
        png_get_rowbytes(png, info) != 4 * (size_t)*w) {
        snprintf(io->msg, sizeof io->msg, "unsupported PNG format");
        return -1;
    }
    return 0;
}

static int decode_pixels(png_structp png, png_infop info, png_bytepp rows)
{
    if (setjmp(png_jmpbuf(png)))
        return -1;
    png_read_image(png, rows);
    png_read_end(png, info);
    return 0;
}

#define LR_PNG_MAX_PIXELS (16384.0 * 16384.0)

/* Decodes io->fp (signature already consumed) into a new RGBA buffer. */
static int decode(png_io *io, int *width, int *height, unsigned char **rgba)
{
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, io,
                                             on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info) {
        png_destroy_read_struct(png ? &png : NULL, NULL, NULL);
        snprintf(io->msg, sizeof io->msg, "out of memory");
        return -1;
    }
    png_set_read_fn(png, io, io_read);
    png_set_sig_bytes(png, 8);
    png_uint_32 w = 0, h = 0;
    unsigned char *buf = NULL;
    png_bytep *rows = NULL;
    int rc = decode_header(io, png, info, &w, &h);
    /* checked on the header, before allocating: a 6 MB file declaring
     * 40000 x 40000 pixels asked for 6.4 GB */
    if (rc == 0 && (w > INT_MAX || h > INT_MAX || (double)w * h > LR_PNG_MAX_PIXELS)) {
        snprintf(io->msg, sizeof io->msg, "the image is %lu x %lu pixels, more than the "
                 "limit of %.0f pixels (16384 x 16384, the largest lamina writes)",
                 (unsigned long)w, (unsigned long)h, LR_PNG_MAX_PIXELS);
        rc = -1;
    }
    if (rc == 0) {
        buf = malloc(4 * (size_t)w * h);
        rows = malloc(h * sizeof *rows);
        if (!buf || !rows) {
            snprintf(io->msg, sizeof io->msg, "out of memory for a %lu x %lu image",
                     (unsigned long)w, (unsigned long)h);
            rc = -1;
        }
    }
    if (rc == 0) {
        for (png_uint_32 y = 0; y < h; y++)
            rows[y] = buf + (size_t)y * 4 * w;
        rc = decode_pixels(png, info, rows);
    }
    png_destroy_read_struct(&png, &info, NULL);
    free(rows);
    if (rc != 0) {
        free(buf);
        return -1;
    }
    *width = (int)w;
    *height = (int)h;
    *rgba = buf;
    return 0;
}

int lr_png_read(const char *path, int *width, int *height,
                unsigned char **rgba, char *err, size_t errlen)
{
    if (!path || !width || !height || !rgba) {
        lu_err(err, errlen, "cannot read PNG: missing argument");
        return -1;
    }
    *rgba = NULL;
    png_io io = { 0 };
    io.fp = fopen(path, "rb");
    if (!io.fp) {
        lu_err(err, errlen, "cannot read '%s': %s", path, strerror(errno));
        return -1;
    }
    unsigned char sig[8];
    errno = 0;
    size_t got = fread(sig, 1, sizeof sig, io.fp);
    int rc;
    if (got != sizeof sig || png_sig_cmp(sig, 0, sizeof sig) != 0) {
        if (ferror(io.fp))
            io.sys_errno = errno ? errno : EIO;
        else
            snprintf(io.msg, sizeof io.msg, "not a PNG file");
        rc = -1;
    } else {
        rc = decode(&io, width, height, rgba);
    }
    if (fclose(io.fp) != 0 && rc == 0) {
        io.sys_errno = errno;
        free(*rgba);
        *rgba = NULL;
        rc = -1;
    }
    if (rc != 0)
        lu_err(err, errlen, "cannot read '%s': %s", path, io_reason(&io));
    return rc;
}
