/* test_png.c - lr_png_write / lr_png_read: round trip, tEXt, atomic and
 * deterministic writes, errors that name the path and leave nothing behind. */
#include "check.h"
#include "test_files.h"
#include "render.h"

#include <dirent.h>
#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

enum { W = 7, H = 5 };

static char dir[] = "render_test_XXXXXX";

/* dir/name, in a static buffer (one live result at a time per slot) */
static const char *in_dir(int slot, const char *name)
{
    static char buf[4][512];
    snprintf(buf[slot], sizeof buf[slot], "%s/%s", dir, name);
    return buf[slot];
}

/* Removes a directory tree created by this test. */
static void rm_tree(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0)
        return;
    if (S_ISDIR(st.st_mode)) {
        DIR *d = opendir(path);
        if (d) {
            struct dirent *e;
            while ((e = readdir(d)) != NULL) {
                if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
                    continue;
                char sub[1024];
                snprintf(sub, sizeof sub, "%s/%s", path, e->d_name);
                rm_tree(sub);
            }
            closedir(d);
        }
        CHECK(rmdir(path) == 0);
    } else {
        CHECK(unlink(path) == 0);
    }
}

static int count_entries(const char *path)
{
    DIR *d = opendir(path);
    if (!d)
        return -1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            n++;
    closedir(d);
    return n;
}

static int same_file(const char *a, const char *b)
{
    long na = -1, nb = -2;
    unsigned char *x = slurp(a, &na), *y = slurp(b, &nb);
    int same = x && y && na == nb && memcmp(x, y, (size_t)na) == 0;
    free(x);
    free(y);
    return same;
}

static int file_contains(const char *path, const char *word)
{
    long n = 0;
    unsigned char *buf = slurp(path, &n);
    size_t k = strlen(word);
    int found = 0;
    for (long i = 0; buf && !found && i + (long)k <= n; i++)
        found = memcmp(buf + i, word, k) == 0;
    free(buf);
    return found;
}

/* Every kind of value: alpha 0 with colour (straight RGBA keeps it). */
static void fill(unsigned char *rgba, int w, int h, int seed)
{
    for (int i = 0; i < 4 * w * h; i++)
        rgba[i] = (unsigned char)((i * 37 + seed * 11 + i / 4) & 0xFF);
    rgba[3] = 0;
}

/* The value of tEXt keyword `key`, read with libpng itself, copied into
 * out; 0 if found. */
static int read_text(const char *path, const char *key, char *out, size_t outlen)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return -1;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL,
                                             NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    volatile int rc = -1;   /* set after the setjmp */
    if (info && !setjmp(png_jmpbuf(png))) {
        png_init_io(png, fp);
        png_read_info(png, info);
        png_textp t = NULL;
        int nt = png_get_text(png, info, &t, NULL);
        for (int i = 0; i < nt; i++)
            if (!strcmp(t[i].key, key) &&
                t[i].compression == PNG_TEXT_COMPRESSION_NONE) {
                snprintf(out, outlen, "%s", t[i].text);
                rc = 0;
            }
    }
    png_destroy_read_struct(png ? &png : NULL, info ? &info : NULL, NULL);
    fclose(fp);
    return rc;
}

static void test_round_trip(void)
{
    unsigned char px[4 * W * H];
    fill(px, W, H, 1);
    lr_text_chunk text[] = { { "Software", "lamina test" },
                             { "lamina:set", "dt=0.5 n=3" } };
    char err[512] = "";
    const char *path = in_dir(0, "a/b/round.png");   /* parents created */
    CHECK(lr_png_write(path, W, H, px, text, 2, err, sizeof err) == 0);
    int w = 0, h = 0;
    unsigned char *back = NULL;
    CHECK(lr_png_read(path, &w, &h, &back, err, sizeof err) == 0);
    CHECK(w == W && h == H);
    CHECK(back && memcmp(back, px, sizeof px) == 0);
    free(back);

    char value[128] = "";
    CHECK(read_text(path, "lamina:set", value, sizeof value) == 0);
    CHECK(strcmp(value, "dt=0.5 n=3") == 0);
    CHECK(read_text(path, "Software", value, sizeof value) == 0);
    CHECK(strcmp(value, "lamina test") == 0);
    CHECK(!file_contains(path, "tIME"));
    CHECK(!file_contains(path, "zTXt"));
    CHECK(count_entries(in_dir(1, "a/b")) == 1);   /* no temporary left */
}

static void test_deterministic(void)
{
    unsigned char px[4 * W * H];
    fill(px, W, H, 2);
    lr_text_chunk text[] = { { "Software", "lamina test" } };
    char err[512] = "";
    const char *a = in_dir(0, "det1.png"), *b = in_dir(1, "det2.png");
    CHECK(lr_png_write(a, W, H, px, text, 1, err, sizeof err) == 0);
    CHECK(lr_png_write(b, W, H, px, text, 1, err, sizeof err) == 0);
    CHECK(same_file(a, b));
}

/* A big file replaced by a small one must not keep the big one's tail. */
static void test_overwrite(void)
{
    enum { BW = 64, BH = 64 };
    static unsigned char big[4 * BW * BH];
    unsigned char small[4 * 2 * 2];
    fill(big, BW, BH, 3);
    fill(small, 2, 2, 4);
    char err[512] = "";
    const char *path = in_dir(0, "over.png"), *ref = in_dir(1, "over_ref.png");
    CHECK(lr_png_write(path, BW, BH, big, NULL, 0, err, sizeof err) == 0);
    CHECK(lr_png_write(path, 2, 2, small, NULL, 0, err, sizeof err) == 0);
    CHECK(lr_png_write(ref, 2, 2, small, NULL, 0, err, sizeof err) == 0);
    CHECK(same_file(path, ref));
    int w = 0, h = 0;
    unsigned char *back = NULL;
    CHECK(lr_png_read(path, &w, &h, &back, err, sizeof err) == 0);
    CHECK(w == 2 && h == 2 && back && memcmp(back, small, sizeof small) == 0);
    free(back);
}

/* Fails with a message naming path; returns 1 if it did. */
static int fails_naming(const char *path, const unsigned char *px)
{
    char err[512] = "";
    int rc = lr_png_write(path, W, H, px, NULL, 0, err, sizeof err);
    if (rc == 0 || !strstr(err, path)) {
        fprintf(stderr, "expected failure for %s, got %d '%s'\n", path, rc, err);
        return 0;
    }
    return 1;
}

static void test_errors(void)
{
    unsigned char px[4 * W * H];
    fill(px, W, H, 5);
    struct stat st;
    char err[512] = "";

    const char *proc = "/proc/lamina_nope/x.png";
    CHECK(fails_naming(proc, px));
    CHECK(stat(proc, &st) != 0);

    /* a parent component that is a regular file */
    CHECK(mkdir(in_dir(0, "e1"), 0777) == 0);
    FILE *fp = fopen(in_dir(0, "e1/plain"), "w");
    CHECK(fp && fclose(fp) == 0);
    CHECK(fails_naming(in_dir(1, "e1/plain/x.png"), px));
    CHECK(count_entries(in_dir(0, "e1")) == 1);

    /* the target is a directory: refused, not replaced */
    CHECK(mkdir(in_dir(0, "e2"), 0777) == 0);
    CHECK(mkdir(in_dir(0, "e2/target.png"), 0777) == 0);
    CHECK(fails_naming(in_dir(1, "e2/target.png"), px));
    CHECK(count_entries(in_dir(0, "e2")) == 1);
    CHECK(stat(in_dir(0, "e2/target.png"), &st) == 0 && S_ISDIR(st.st_mode));

    /* libpng refuses the header (width over its 1e6 limit) after the
     * temporary was created: it must be gone, an old file untouched */
    const char *old = in_dir(0, "e2/old.png");
    CHECK(lr_png_write(old, W, H, px, NULL, 0, err, sizeof err) == 0);
    enum { WIDE = 1000001 };
    unsigned char *wide = calloc(4 * (size_t)WIDE, 1);
    CHECK(wide != NULL);
    CHECK(lr_png_write(old, WIDE, 1, wide, NULL, 0, err, sizeof err) == -1);
    CHECK(strstr(err, old) != NULL && strstr(err, "libpng") != NULL);
    free(wide);
    CHECK(count_entries(in_dir(1, "e2")) == 2);
    int w, h;
    unsigned char *back = NULL;
    CHECK(lr_png_read(old, &w, &h, &back, err, sizeof err) == 0);
    CHECK(w == W && h == H && back && memcmp(back, px, sizeof px) == 0);
    free(back);
    back = NULL;

    /* a bad keyword is refused before anything is created */
    lr_text_chunk bad[] = { { "", "empty keyword" } };
    CHECK(lr_png_write(in_dir(0, "e2/k.png"), W, H, px, bad, 1, err,
                       sizeof err) == -1);
    CHECK(count_entries(in_dir(0, "e2")) == 2);

    /* reading: a missing file and a file that is not a PNG */
    CHECK(lr_png_read(in_dir(0, "missing.png"), &w, &h, &back, err,
                      sizeof err) == -1);
    CHECK(strstr(err, in_dir(0, "missing.png")) != NULL);
    CHECK(lr_png_read(in_dir(0, "e1/plain"), &w, &h, &back, err,
                      sizeof err) == -1);
    CHECK(back == NULL);
}

int main(void)
{
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    test_round_trip();
    test_deterministic();
    test_overwrite();
    test_errors();
    rm_tree(dir);
    return CHECK_DONE();
}
