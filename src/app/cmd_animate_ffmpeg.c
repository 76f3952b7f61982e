/* cmd_animate_ffmpeg.c - an MP4 of a run's frames through ffmpeg, when it
 * is installed (lamina never installs it: it is optional, docs/rendering.md).
 *
 * ffmpeg reads numbered frames best, and a run's frames may be named any
 * way: so they are linked into a temporary folder as 000000.png,
 * 000001.png, ... in order. The video goes into a temporary file beside
 * the target and is renamed over it only when ffmpeg succeeded, like every
 * other output of lamina. Sizes are padded to even numbers (H.264 in
 * yuv420p needs them). */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "atomic_file.h"
#include "cmd_animate.h"

int animate_find_ffmpeg(char *path, size_t n)
{
    const char *env = getenv("PATH");
    if (!env || !*env)
        return -1;
    const char *p = env;
    while (*p) {
        const char *colon = strchr(p, ':');
        size_t len = colon ? (size_t)(colon - p) : strlen(p);
        if (len == 0)       /* an empty entry is the current directory */
            snprintf(path, n, "./ffmpeg");
        else
            snprintf(path, n, "%.*s/ffmpeg", (int)len, p);
        struct stat st;
        if (stat(path, &st) == 0 && S_ISREG(st.st_mode) && access(path, X_OK) == 0)
            return 0;
        p += len + (colon ? 1 : 0);
    }
    return -1;
}

/* Removes the links and the folder. */
static void remove_links(const char *dir, size_t n)
{
    char link[PATH_MAX];
    for (size_t i = 0; i < n; i++)
        if (snprintf(link, sizeof link, "%s/%06zu.png", dir, i) < (int)sizeof link)
            unlink(link);
    rmdir(dir);
}

/* Links frame i as dir/%06d.png; frame paths made absolute first. */
static int link_frames(const char *dir, char **frames, size_t n, char *why, size_t len)
{
    char cwd[PATH_MAX], target[2 * PATH_MAX], link[PATH_MAX];
    if (!getcwd(cwd, sizeof cwd)) {
        snprintf(why, len, "cannot read the current folder: %s", strerror(errno));
        return -1;
    }
    for (size_t i = 0; i < n; i++) {
        if (frames[i][0] == '/')
            snprintf(target, sizeof target, "%s", frames[i]);
        else
            snprintf(target, sizeof target, "%s/%s", cwd, frames[i]);
        if (snprintf(link, sizeof link, "%s/%06zu.png", dir, i) >= (int)sizeof link) {
            snprintf(why, len, "the temporary folder's name is too long");
            remove_links(dir, i);
            return -1;
        }
        if (symlink(target, link) != 0) {
            snprintf(why, len, "cannot link '%s' into '%s': %s", frames[i], dir,
                     strerror(errno));
            remove_links(dir, i);
            return -1;
        }
    }
    return 0;
}

static int run_ffmpeg(const char *ffmpeg, const char *pattern, double fps,
                      const char *out, char *why, size_t len)
{
    char rate[32];
    snprintf(rate, sizeof rate, "%g", fps);
    char *argv[] = { (char *)ffmpeg, "-hide_banner", "-loglevel", "error", "-nostdin",
                     "-y", "-framerate", rate, "-i", (char *)pattern,
                     "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                     "-c:v", "libx264", "-pix_fmt", "yuv420p",
                     "-movflags", "+faststart", "-f", "mp4", (char *)out, NULL };
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) {
        snprintf(why, len, "cannot start ffmpeg: %s", strerror(errno));
        return -1;
    }
    if (pid == 0) {
        execv(ffmpeg, argv);
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) {
            snprintf(why, len, "cannot wait for ffmpeg: %s", strerror(errno));
            return -1;
        }
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
        return 0;
    if (WIFEXITED(status))
        snprintf(why, len, "ffmpeg failed (exit status %d)", WEXITSTATUS(status));
    else
        snprintf(why, len, "ffmpeg was stopped by signal %d", WTERMSIG(status));
    return -1;
}

int animate_mp4(const char *ffmpeg, char **frames, size_t n, double fps,
                const char *out, char *why, size_t len)
{
    const char *tmpdir = getenv("TMPDIR");
    char dir[PATH_MAX], pattern[PATH_MAX + 16];
    snprintf(dir, sizeof dir, "%s/lamina-animate-XXXXXX",
             tmpdir && *tmpdir ? tmpdir : "/tmp");
    if (!mkdtemp(dir)) {
        snprintf(why, len, "cannot make a temporary folder: %s", strerror(errno));
        return -1;
    }
    if (link_frames(dir, frames, n, why, len) != 0)
        return -1;
    snprintf(pattern, sizeof pattern, "%s/%%06d.png", dir);
    lr_atomic a;
    char err[512];
    int rc = -1;
    if (lr_atomic_open(&a, out, err, sizeof err) != 0) {
        snprintf(why, len, "%s", err);
    } else if (run_ffmpeg(ffmpeg, pattern, fps, a.tmp, why, len) != 0) {
        lr_atomic_abort(&a, why, NULL, 0);
    } else if (lr_atomic_commit(&a, err, sizeof err) != 0) {
        snprintf(why, len, "%s", err);
    } else {
        rc = 0;
    }
    remove_links(dir, n);
    return rc;
}
