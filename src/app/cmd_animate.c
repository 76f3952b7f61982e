/* cmd_animate.c - `lamina animate FRAMES... [--out FILE] [--fps N]
 * [--loop N] [--quiet]`: a run's frames as one animated file.
 *
 * FRAMES are folders (their .png files, in name order: frame_%04d names
 * sort by step) or PNG files in the order given. The output is an APNG
 * written by lamina itself (apng.h) when FILE ends in .apng or .png, or an
 * MP4 when FILE ends in .mp4 and ffmpeg is on PATH. lamina writes only the
 * file it was asked for (issue 35 item 5): when the MP4 cannot be made it
 * says why and writes nothing (no APNG in its place, which could replace
 * an older animation), another name ending is refused, the output may not
 * be one of the frames, and the default name (FOLDER.apng, not asked for
 * by name) replaces only an earlier animation of lamina's. When no
 * animation can be written at all (an unreadable frame, an unwritable
 * target) the frames are left as they are - they are never touched - and
 * the message says why. Exit status: 0 written; 1 nothing written (a
 * frame or the target failed); 2 the command cannot be done as asked (a
 * wrong command line, a format that cannot be made, a file that would be
 * replaced without being named), nothing written. */
#include <dirent.h>
#include <errno.h>
#include <fnmatch.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "apng.h"
#include "app.h"
#include "cmd_animate.h"
#include "render.h"

typedef struct frames {
    char **path;
    size_t n, cap;
} frames;

typedef struct options {
    const char *out;
    double fps;
    unsigned loops;
    int quiet;
    const char *pattern;    /* --pattern GLOB: a folder's frames whose names match */
} options;

static int ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && strcasecmp(s + n - k, suffix) == 0;
}

static int add_frame(frames *f, const char *path)
{
    if (f->n == f->cap) {
        size_t cap = f->cap ? 2 * f->cap : 64;
        char **p = realloc(f->path, cap * sizeof *p);
        if (!p)
            return -1;
        f->path = p;
        f->cap = cap;
    }
    f->path[f->n] = strdup(path);
    if (!f->path[f->n])
        return -1;
    f->n++;
    return 0;
}

static void free_frames(frames *f)
{
    for (size_t i = 0; i < f->n; i++)
        free(f->path[i]);
    free(f->path);
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The folder's PNG files in name order; hidden files, lamina's
 * temporaries and the output itself are not frames. */
static int add_folder(frames *f, const char *dir, const char *out, const char *pattern)
{
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "lamina animate: cannot read folder '%s': %s\n", dir,
                strerror(errno));
        return -1;
    }
    size_t first = f->n;
    struct dirent *e;
    int rc = 0;
    while (rc == 0 && (e = readdir(d))) {
        if (e->d_name[0] == '.' || !ends_with(e->d_name, ".png") ||
            strstr(e->d_name, ".tmp.") || (pattern && fnmatch(pattern, e->d_name, 0) != 0))
            continue;
        char path[4096];
        size_t n = strlen(dir);
        snprintf(path, sizeof path, "%s%s%s", dir, n && dir[n - 1] == '/' ? "" : "/",
                 e->d_name);
        if (out && strcmp(path, out) == 0)
            continue;
        rc = add_frame(f, path);
    }
    closedir(d);
    if (rc != 0)   /* (an empty folder is not this: the caller says so) */
        fprintf(stderr, "lamina animate: out of memory\n");
    else if (f->n > first)   /* (no frames: f->path may be NULL) */
        qsort(f->path + first, f->n - first, sizeof *f->path, by_name);
    return rc;
}

/* A PNG's size from its header (the IHDR chunk opens every PNG); 0 or -1. */
static int png_size(const char *path, unsigned *w, unsigned *h)
{
    unsigned char b[24];
    FILE *fp = fopen(path, "rb");
    if (!fp) return -1;
    size_t n = fread(b, 1, sizeof b, fp);
    fclose(fp);
    static const unsigned char sig[8] = {137, 'P', 'N', 'G', 13, 10, 26, 10};
    if (n != sizeof b || memcmp(b, sig, 8) != 0 || memcmp(b + 12, "IHDR", 4) != 0) return -1;
    *w = (unsigned)b[16] << 24 | (unsigned)b[17] << 16 | (unsigned)b[18] << 8 | b[19];
    *h = (unsigned)b[20] << 24 | (unsigned)b[21] << 16 | (unsigned)b[22] << 8 | b[23];
    return 0;
}

/* An animation has one size: frames of another size than the first (a
 * folder holding a run's frames and a plot, say) are left out with a
 * warning instead of failing the whole animation. Unreadable files stay,
 * to fail later with their own message. */
static void keep_first_size(frames *f)
{
    unsigned w0, h0;
    if (f->n == 0 || png_size(f->path[0], &w0, &h0) != 0) return;
    size_t k = 1;
    for (size_t i = 1; i < f->n; i++) {
        unsigned w, h;
        if (png_size(f->path[i], &w, &h) == 0 && (w != w0 || h != h0)) {
            fprintf(stderr, "lamina animate: warning: '%s' is %ux%u, not %ux%u like '%s': "
                    "left out\n", f->path[i], w, h, w0, h0, f->path[0]);
            free(f->path[i]);
            continue;
        }
        f->path[k++] = f->path[i];
    }
    f->n = k;
}

static int parse_number(const char *opt, const char *v, double lo, double hi, double *out)
{
    char *end = NULL;
    double x = v ? strtod(v, &end) : 0;
    if (!v || end == v || *end || !(x >= lo && x <= hi)) {
        fprintf(stderr, "lamina animate: %s needs a number in [%g, %g] (got '%s')\n",
                opt, lo, hi, v ? v : "");
        return -1;
    }
    *out = x;
    return 0;
}

static int parse_args(int argc, char **argv, options *o, char ***inputs, int *ninputs)
{
    *inputs = calloc((size_t)argc + 1, sizeof **inputs);
    if (!*inputs)
        return -1;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        double x;
        if (strcmp(a, "--out") == 0 || strcmp(a, "-o") == 0) {
            if (!v || !*v) {
                fprintf(stderr, "lamina animate: --out needs a FILE\n");
                return -1;
            }
            o->out = v;
            i++;
        } else if (strcmp(a, "--fps") == 0) {
            if (parse_number("--fps", v, 0.02, 1000, &o->fps) != 0)
                return -1;
            i++;
        } else if (strcmp(a, "--loop") == 0) {
            if (parse_number("--loop", v, 0, 65535, &x) != 0)
                return -1;
            if (x != (unsigned)x) {
                fprintf(stderr, "lamina animate: --loop needs a whole number (got '%s')\n", v);
                return -1;
            }
            o->loops = (unsigned)x;
            i++;
        } else if (strcmp(a, "--pattern") == 0) {
            if (!v || !*v) {
                fprintf(stderr, "lamina animate: --pattern needs a name pattern (e.g. 'f*.png')\n");
                return -1;
            }
            o->pattern = v;
            i++;
        } else if (strcmp(a, "--quiet") == 0 || strcmp(a, "-q") == 0) {
            o->quiet = 1;
        } else if (a[0] == '-' && a[1]) {
            fprintf(stderr, "lamina animate: unknown option '%s' (try 'lamina help')\n", a);
            return -1;
        } else {
            (*inputs)[(*ninputs)++] = argv[i];
        }
    }
    if (*ninputs == 0) {
        fprintf(stderr, "lamina animate: no frames given (usage: lamina animate "
                "FOLDER|FRAME.png... [--out FILE])\n");
        return -1;
    }
    return 0;
}

/* FOLDER -> FOLDER.apng beside it; files -> their folder's name + .apng. */
static char *default_out(const char *input, int is_dir)
{
    char base[4096];
    snprintf(base, sizeof base, "%s", input);
    if (!is_dir) {
        char *slash = strrchr(base, '/');
        if (slash)
            *slash = 0;
        else
            snprintf(base, sizeof base, ".");
    }
    size_t n = strlen(base);
    while (n > 1 && base[n - 1] == '/')
        base[--n] = 0;
    char *out = malloc(n + 16);
    if (!out)
        return NULL;
    if (strcmp(base, ".") == 0 || strcmp(base, "/") == 0)
        snprintf(out, n + 16, "animation.apng");
    else
        snprintf(out, n + 16, "%s.apng", base);
    return out;
}

/* The asked format: 'a' APNG, 'm' MP4, 0 none lamina makes. */
static int out_format(const char *out)
{
    if (ends_with(out, ".apng") || ends_with(out, ".png"))
        return 'a';
    return ends_with(out, ".mp4") ? 'm' : 0;
}

/* 1 when path is an animation lamina wrote: its "lamina:frames" text
 * chunk (write_apng) comes before the image data, in the first bytes. */
static int written_by_lamina(const char *path)
{
    char b[4096];
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return 0;
    size_t n = fread(b, 1, sizeof b, fp);
    fclose(fp);
    static const char key[] = "lamina:frames";
    for (size_t i = 0; i + sizeof key - 1 <= n; i++)
        if (memcmp(b + i, key, sizeof key - 1) == 0)
            return 1;
    return 0;
}

/* 1 when a and b are the same file (a frame given as the output). */
static int same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

/* The checks before anything is written; 0, or 2 with the message said. */
static int may_write(const char *out, int named, const frames *f)
{
    if (!out_format(out)) {
        fprintf(stderr, "lamina animate: cannot make '%s': lamina writes an APNG (a name "
                "ending in .apng or .png) or an MP4 (.mp4, through ffmpeg); nothing "
                "written\n", out);
        return 2;
    }
    for (size_t i = 0; i < f->n; i++)
        if (same_file(out, f->path[i])) {
            fprintf(stderr, "lamina animate: the output '%s' is one of the frames; "
                    "name another file with --out (nothing written)\n", out);
            return 2;
        }
    struct stat st;
    if (!named && stat(out, &st) == 0 && !written_by_lamina(out)) {
        fprintf(stderr, "lamina animate: '%s' exists and is not an animation lamina "
                "wrote; name the output with --out to replace it (nothing written)\n",
                out);
        return 2;
    }
    return 0;
}

static int is_folder(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* Writes the APNG; -1 with the reason in why. */
static int write_apng(const frames *f, const options *o, const char *out,
                      char *why, size_t len, int *w, int *h)
{
    unsigned char *img = NULL;
    char err[512];
    if (lr_png_read(f->path[0], w, h, &img, err, sizeof err) != 0) {
        snprintf(why, len, "%s", err);
        return -1;
    }
    char ver[64], count[64];
    snprintf(ver, sizeof ver, "lamina %s", LAMINA_VERSION);
    snprintf(count, sizeof count, "%zu frames from %s", f->n, f->path[0]);
    lr_text_chunk text[] = { { "Software", ver }, { "lamina:frames", count } };
    lr_apng *a = lr_apng_open(out, *w, *h, (unsigned)f->n, o->fps, o->loops, text, 2,
                              err, sizeof err);
    if (!a) {
        free(img);
        snprintf(why, len, "%s", err);
        return -1;
    }
    for (size_t i = 0; i < f->n; i++) {
        int wi = *w, hi = *h;
        if (i > 0 && lr_png_read(f->path[i], &wi, &hi, &img, err, sizeof err) != 0) {
            snprintf(why, len, "%s", err);
            lr_apng_abort(a);
            return -1;
        }
        if (wi != *w || hi != *h) {
            snprintf(why, len, "'%s' is %dx%d but the first frame '%s' is %dx%d "
                     "(an animation needs one size)", f->path[i], wi, hi, f->path[0],
                     *w, *h);
            free(img);
            lr_apng_abort(a);
            return -1;
        }
        int rc = lr_apng_add(a, img, err, sizeof err);
        free(img);
        img = NULL;
        if (rc != 0) {
            snprintf(why, len, "%s", err);
            lr_apng_abort(a);
            return -1;
        }
    }
    if (lr_apng_close(a, err, sizeof err) != 0) {
        snprintf(why, len, "%s", err);
        return -1;
    }
    return 0;
}

static long file_size(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

int cmd_animate(int argc, char **argv)
{
    options o = { NULL, 10.0, 0, 0, NULL };
    char **inputs = NULL;
    int ninputs = 0;
    if (parse_args(argc, argv, &o, &inputs, &ninputs) != 0) {
        free(inputs);
        return 2;
    }
    char *out_owned = o.out ? NULL : default_out(inputs[0], is_folder(inputs[0]));
    const char *out = o.out ? o.out : out_owned;
    frames f = { NULL, 0, 0 };
    int status = out ? 0 : 1;
    for (int i = 0; i < ninputs && status == 0; i++) {
        if (is_folder(inputs[i])) {
            status = add_folder(&f, inputs[i], out, o.pattern) ? 2 : 0;
        } else if (access(inputs[i], R_OK) != 0) {
            fprintf(stderr, "lamina animate: cannot read '%s': %s\n", inputs[i],
                    strerror(errno));
            status = 2;
        } else if (add_frame(&f, inputs[i]) != 0) {
            status = 1;
        }
    }
    if (status == 0 && f.n == 0) {
        fprintf(stderr, "lamina animate: no .png frames in '%s'%s%s\n", inputs[0],
                o.pattern ? " matching " : "", o.pattern ? o.pattern : "");
        status = 2;
    }
    if (status == 0)
        keep_first_size(&f);
    if (status == 0)
        status = may_write(out, o.out != NULL, &f);
    const char *where = ninputs == 1 ? inputs[0] : "their files";
    char why[1024] = "";
    if (status == 0 && out_format(out) == 'm') {
        char ffmpeg[4096];
        if (animate_find_ffmpeg(ffmpeg, sizeof ffmpeg) != 0)
            snprintf(why, sizeof why, "ffmpeg is not installed (not on PATH)");
        else if (animate_mp4(ffmpeg, f.path, f.n, o.fps, out, why, sizeof why) == 0) {
            if (!o.quiet)
                fprintf(stderr, "lamina animate: %zu frames -> %s (MP4 by ffmpeg, %ld "
                        "bytes)\n", f.n, out, file_size(out));
            goto done;
        }
        /* No stand-in: an APNG under another name could replace a file
         * nobody asked to replace (issue 35 item 5). */
        fprintf(stderr, "lamina animate: cannot make the MP4 '%s': %s; nothing written "
                "(an APNG: --out NAME.apng)\n", out, why);
        status = 2;
        goto done;
    }
    if (status == 0) {
        int w = 0, h = 0;
        if (write_apng(&f, &o, out, why, sizeof why, &w, &h) != 0) {
            fprintf(stderr, "lamina animate: no animation written: %s; the %zu "
                    "frames stay in %s\n", why, f.n, where);
            status = 1;
        } else if (!o.quiet) {
            fprintf(stderr, "lamina animate: %zu frames (%dx%d, %g fps) -> %s (APNG, "
                    "%ld bytes)\n", f.n, w, h, o.fps, out, file_size(out));
        }
    }
done:
    free(out_owned);
    free_frames(&f);
    free(inputs);
    return status;
}
