/* atomic_file.h - files written whole or not at all.
 *
 * Every output of lamina (PNG frames, plots, CSV, reports) goes into a
 * temporary beside its target and is renamed over it only once written and
 * closed without error; on any failure the temporary is removed and the
 * target is untouched. Missing parent folders are created, and removed
 * again when the write fails (a failed deep path leaves no folders). A target that
 * exists and is not a regular file (a device, FIFO or folder) is refused:
 * rename(2) would replace it, and as root that could be /dev/null. */
#ifndef LAMINA_ATOMIC_FILE_H
#define LAMINA_ATOMIC_FILE_H

#include <stddef.h>
#include <stdio.h>

typedef struct lr_atomic {
    FILE *fp;           /* write here */
    char *tmp;          /* "<path>.tmp.<host>.<pid>.XXXXXX" (stale_temp.h) */
    const char *path;   /* the target (borrowed) */
    char *dir;          /* the folders created for it, "a/b/c" (or NULL) */
    size_t made;        /* ... from the prefix of this length down: a failed
                           write removes them again */
} lr_atomic;

/* 0, or -1 with err set ("cannot write 'PATH': why"). */
int lr_atomic_open(lr_atomic *a, const char *path, char *err, size_t errlen);
/* Flushes, closes and renames; on failure removes the temporary. */
int lr_atomic_commit(lr_atomic *a, char *err, size_t errlen);
/* Closes and removes the temporary; err says "cannot write 'PATH': why".
 * Always returns -1, for `return lr_atomic_abort(...)`. */
int lr_atomic_abort(lr_atomic *a, const char *why, char *err, size_t errlen);
/* The whole file in one call. */
int lr_write_file(const char *path, const void *data, size_t n, char *err, size_t errlen);

#endif
