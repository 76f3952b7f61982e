/* cmd_animate.h - the parts of `lamina animate` (cmd_animate*.c). */
#ifndef LAMINA_CMD_ANIMATE_H
#define LAMINA_CMD_ANIMATE_H

#include <stddef.h>

/* The path of an executable `ffmpeg` on PATH into path; -1 if there is none. */
int animate_find_ffmpeg(char *path, size_t n);
/* frames[0..n-1] (in order) as an H.264 MP4 at fps, written atomically to
 * out; -1 with the reason in why. */
int animate_mp4(const char *ffmpeg, char **frames, size_t n, double fps,
                const char *out, char *why, size_t len);

#endif
