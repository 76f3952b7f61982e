/* test_figure_apng.c - animations: the APNG writer (apng.h) read back by a
 * small decoder written here from the APNG specification, frame by frame,
 * pixel-exact; the same frames give the same bytes; bad use is refused.
 * Then `lamina animate` itself when the binary is beside the tests: a
 * folder of frames becomes an APNG; frames of two sizes leave the frames
 * and say why; .mp4 without ffmpeg falls back to an APNG and says why;
 * with an ffmpeg on PATH (a stand-in script here) the MP4 path is taken. */
#include "apng.h"
#include "check.h"
#include "test_files.h"
#include "render.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

enum { W = 48, H = 32, NFRAMES = 5 };

static char dir[] = "apng_test_XXXXXX";

static char *path(const char *name)
{
    static char buf[4][160];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

/* Frame k: a square moving right over a fixed gradient; frame 3 equals
 * frame 2 (an unchanged frame is a case of its own). */
static void make_frame(int k, unsigned char *img)
{
    int m = k == 3 ? 2 : k;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            unsigned char *p = img + 4 * (y * W + x);
            p[0] = (unsigned char)(4 * x);
            p[1] = (unsigned char)(6 * y);
            p[2] = 128;
            p[3] = 255;
            if (x >= 5 + 6 * m && x < 15 + 6 * m && y >= 8 && y < 20) {
                p[0] = 250;
                p[1] = 20;
                p[2] = 20;
                p[3] = (unsigned char)(k == 4 ? 128 : 255);
            }
        }
}

/* ---- a decoder, from the specification ---------------------------------- */

static uint32_t be32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

static int paeth(int a, int b, int c)
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* Inflates z (n bytes) and unfilters a w x h RGBA region into canvas at
 * (x0, y0) (blend SOURCE). */
static int decode_region(const unsigned char *z, size_t n, int x0, int y0, int w,
                         int h, unsigned char *canvas)
{
    size_t stride = 4 * (size_t)w + 1, len = stride * (size_t)h;
    unsigned char *raw = malloc(len);
    uLongf got = (uLongf)len;
    if (!raw || uncompress(raw, &got, z, (uLong)n) != Z_OK || got != len) {
        free(raw);
        return -1;
    }
    for (int y = 0; y < h; y++) {
        unsigned char *row = raw + (size_t)y * stride + 1;
        const unsigned char *up = y ? row - stride : NULL;
        int t = row[-1];
        for (int i = 0; i < 4 * w; i++) {
            int a = i >= 4 ? row[i - 4] : 0, b = up ? up[i] : 0;
            int c = i >= 4 && up ? up[i - 4] : 0;
            int p = t == 1 ? a : t == 2 ? b : t == 3 ? (a + b) / 2 : t == 4 ? paeth(a, b, c) : 0;
            row[i] = (unsigned char)(row[i] + p);
        }
        memcpy(canvas + 4 * ((size_t)(y0 + y) * W + x0), row, 4 * (size_t)w);
    }
    free(raw);
    return 0;
}

/* Decodes the file and compares every frame with make_frame; returns the
 * number of frames that matched, -1 on a format error. */
static int check_file(const char *p, unsigned fps_den_expected)
{
    FILE *fp = fopen(p, "rb");
    if (!fp)
        return -1;
    static unsigned char file[1 << 20];
    size_t n = fread(file, 1, sizeof file, fp);
    fclose(fp);
    static const unsigned char sig[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
    if (n < 8 || memcmp(file, sig, 8) != 0)
        return -1;
    static unsigned char canvas[4 * W * H], want[4 * W * H];
    static unsigned char z[1 << 20];
    size_t nz = 0;
    int frames = 0, matched = 0, fx = 0, fy = 0, fw = 0, fh = 0, have = 0;
    uint32_t seq = 0, actl_frames = 0;
    for (size_t i = 8; i + 12 <= n;) {
        uint32_t len = be32(file + i);
        const unsigned char *type = file + i + 4, *data = file + i + 8;
        if (i + 12 + len > n)
            return -1;
        uLong crc = crc32(crc32(0L, Z_NULL, 0), type, 4 + len);
        if (crc != be32(data + len))
            return -1;
        int is_fctl = memcmp(type, "fcTL", 4) == 0, is_end = memcmp(type, "IEND", 4) == 0;
        if ((is_fctl || is_end) && have) {     /* the previous frame is complete */
            if (decode_region(z, nz, fx, fy, fw, fh, canvas) != 0)
                return -1;
            make_frame(frames, want);
            matched += memcmp(canvas, want, sizeof canvas) == 0;
            frames++;
            nz = 0;
            have = 0;
        }
        if (memcmp(type, "IHDR", 4) == 0) {
            if (be32(data) != W || be32(data + 4) != H || data[8] != 8 || data[9] != 6)
                return -1;
        } else if (memcmp(type, "acTL", 4) == 0) {
            actl_frames = be32(data);
        } else if (is_fctl) {
            if (be32(data) != seq++)
                return -1;
            fw = (int)be32(data + 4);
            fh = (int)be32(data + 8);
            fx = (int)be32(data + 12);
            fy = (int)be32(data + 16);
            if (fx + fw > W || fy + fh > H || (frames == 0 && (fw != W || fh != H)))
                return -1;
            if ((unsigned)(data[22] << 8 | data[23]) != fps_den_expected || data[24] || data[25])
                return -1;
            have = 1;
        } else if (memcmp(type, "IDAT", 4) == 0 || memcmp(type, "fdAT", 4) == 0) {
            int fd = type[0] == 'f';
            if (fd && be32(data) != seq++)
                return -1;
            memcpy(z + nz, data + 4 * fd, len - 4 * fd);
            nz += len - 4 * fd;
        }
        i += 12 + len;
    }
    return actl_frames == (uint32_t)frames ? matched : -1;
}

/* ---- the writer --------------------------------------------------------- */

static int write_anim(const char *p, unsigned nframes, int add)
{
    static unsigned char img[4 * W * H];
    char err[256] = "";
    lr_text_chunk text[] = { { "Software", "lamina test" } };
    lr_apng *a = lr_apng_open(p, W, H, nframes, 10.0, 0, text, 1, err, sizeof err);
    if (!a)
        return -1;
    for (int k = 0; k < add; k++) {
        make_frame(k, img);
        if (lr_apng_add(a, img, err, sizeof err) != 0) {
            lr_apng_abort(a);
            return -1;
        }
    }
    return lr_apng_close(a, err, sizeof err);
}

static void test_writer(void)
{
    CHECK(write_anim(path("a.png"), NFRAMES, NFRAMES) == 0);
    CHECK(check_file(path("a.png"), 1000) == NFRAMES);
    CHECK(write_anim(path("b.png"), NFRAMES, NFRAMES) == 0);
    long na = 0, nb = 1;
    unsigned char *a = slurp(path("a.png"), &na), *b = slurp(path("b.png"), &nb);
    CHECK(a && b && na == nb && memcmp(a, b, (size_t)na) == 0);     /* deterministic */
    free(a);
    free(b);
    /* any PNG reader sees the first frame */
    int w, h;
    unsigned char *first = NULL, want[4 * W * H];
    char err[256] = "";
    CHECK(lr_png_read(path("a.png"), &w, &h, &first, err, sizeof err) == 0);
    make_frame(0, want);
    CHECK(first && w == W && h == H && memcmp(first, want, sizeof want) == 0);
    free(first);
    /* fewer frames than announced: nothing is left behind */
    CHECK(write_anim(path("c.png"), NFRAMES, 2) == -1);
    CHECK(!exists(path("c.png")));
    /* bad arguments */
    CHECK(lr_apng_open(path("d.png"), 0, H, 1, 10, 0, NULL, 0, err, sizeof err) == NULL);
    CHECK(lr_apng_open(path("d.png"), W, H, 0, 10, 0, NULL, 0, err, sizeof err) == NULL);
    CHECK(strstr(err, "no frames") != NULL);
    CHECK(lr_apng_open(path("d.png"), W, H, 1, 0, 0, NULL, 0, err, sizeof err) == NULL);
    CHECK(lr_apng_open("/proc/lamina/x.png", W, H, 1, 10, 0, NULL, 0, err, sizeof err) == NULL);
    CHECK(strstr(err, "/proc/lamina/x.png") != NULL);
    unlink(path("a.png"));
    unlink(path("b.png"));
}

/* ---- `lamina animate` --------------------------------------------------- */

/* Runs the command with stderr into err.txt; the exit status. */
static int run(const char *cmd)
{
    char full[1024];
    snprintf(full, sizeof full, "%s 2>%s", cmd, path("err.txt"));
    int st = system(full);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static int said(const char *what)
{
    long n = 0;
    unsigned char *s = slurp(path("err.txt"), &n);
    int ok = s && (s[n] = 0, strstr((char *)s, what) != NULL);
    if (!ok)
        fprintf(stderr, "expected '%s' in: %s\n", what, s ? (char *)s : "(nothing)");
    free(s);
    return ok;
}

static void test_command(const char *lamina)
{
    static unsigned char img[4 * W * H];
    char err[256] = "", cmd[1024], name[64];
    mkdir(path("frames"), 0777);
    for (int k = 0; k < NFRAMES; k++) {
        make_frame(k, img);
        snprintf(name, sizeof name, "frames/frame_%04d.png", k * 10);
        CHECK(lr_png_write(path(name), W, H, img, NULL, 0, err, sizeof err) == 0);
    }
    /* a folder of frames -> FOLDER.apng beside it */
    snprintf(cmd, sizeof cmd, "%s animate %s", lamina, path("frames"));
    CHECK(run(cmd) == 0);
    CHECK(said("5 frames (48x32, 10 fps)"));
    CHECK(check_file(path("frames.apng"), 1000) == NFRAMES);

    /* .mp4 without ffmpeg: status 2, why, and nothing written - no APNG
     * in its place (issue 35 item 5) */
    snprintf(cmd, sizeof cmd, "PATH=/nonexistent %s animate %s --out %s --fps 10",
             lamina, path("frames"), path("movie.mp4"));
    CHECK(run(cmd) == 2);
    CHECK(said("ffmpeg is not installed"));
    CHECK(said("nothing written"));
    CHECK(!exists(path("movie.apng")));
    CHECK(!exists(path("movie.mp4")));

    /* an ffmpeg on PATH (a stand-in that writes its last argument) */
    mkdir(path("bin"), 0777);
    FILE *fp = fopen(path("bin/ffmpeg"), "w");
    if (fp) {
        fprintf(fp, "#!/bin/sh\nfor a; do last=$a; done\n"
                    "ls \"$(dirname \"$9\")\" | grep -c png > \"$last\"\n");
        fclose(fp);
        chmod(path("bin/ffmpeg"), 0755);
    }
    snprintf(cmd, sizeof cmd, "PATH=%s/bin:/usr/bin:/bin %s animate %s --out %s",
             dir, lamina, path("frames"), path("movie2.mp4"));
    CHECK(run(cmd) == 0);
    CHECK(said("MP4 by ffmpeg"));
    long n = 0;
    unsigned char *s = slurp(path("movie2.mp4"), &n);
    CHECK(s && n >= 1 && s[0] == '5');      /* the five linked frames */
    free(s);

    /* a frame of another size (a plot beside a run's frames): left out
     * with a warning, the animation made of the rest (issue 20 item 5) */
    unsigned char small[4 * 8 * 8] = { 0 };
    CHECK(lr_png_write(path("frames/frame_9999.png"), 8, 8, small, NULL, 0, err,
                       sizeof err) == 0);
    snprintf(cmd, sizeof cmd, "%s animate %s --out %s", lamina, path("frames"),
             path("mixed.apng"));
    CHECK(run(cmd) == 0);
    CHECK(said("is 8x8, not 48x32"));
    CHECK(said("left out"));
    CHECK(check_file(path("mixed.apng"), 1000) == NFRAMES);
    CHECK(exists(path("frames/frame_0000.png")));
    unlink(path("mixed.apng"));

    /* --pattern: only the frames whose names match */
    CHECK(lr_png_write(path("frames/other_0001.png"), W, H, img, NULL, 0, err,
                       sizeof err) == 0);
    snprintf(cmd, sizeof cmd, "%s animate %s --pattern 'frame_00*.png' --out %s", lamina,
             path("frames"), path("pattern.apng"));
    CHECK(run(cmd) == 0);
    CHECK(said("5 frames"));
    CHECK(check_file(path("pattern.apng"), 1000) == NFRAMES);
    unlink(path("pattern.apng"));
    snprintf(cmd, sizeof cmd, "%s animate %s --pattern 'none*.png'", lamina, path("frames"));
    CHECK(run(cmd) == 2);
    CHECK(said("matching none*.png"));

    /* a wrong command line */
    snprintf(cmd, sizeof cmd, "%s animate %s --fps 0", lamina, path("frames"));
    CHECK(run(cmd) == 2);
    CHECK(said("--fps needs a number"));
    snprintf(cmd, sizeof cmd, "%s animate %s", lamina, path("nothing_here"));
    CHECK(run(cmd) == 2);

    snprintf(cmd, sizeof cmd, "rm -rf %s/frames %s/bin", dir, dir);
    CHECK(system(cmd) == 0);
    unlink(path("frames.apng"));
    unlink(path("movie.apng"));
    unlink(path("movie2.mp4"));
    unlink(path("err.txt"));
}

int main(void)
{
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    test_writer();
    /* the unit tests run in build/tests; the command is build/lamina */
    if (access("../lamina", X_OK) == 0)
        test_command("../lamina");
    else
        printf("../lamina not found: the command's tests are skipped\n");
    CHECK(rmdir(dir) == 0);
    lr_shutdown();
    return CHECK_DONE();
}
