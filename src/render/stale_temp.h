/* stale_temp.h - the temporaries of atomic writes, and those left behind.
 *
 * A process killed with SIGKILL (or a crash, a power cut) leaves its
 * temporary "<target>.tmp.<host>.<pid>.XXXXXX" beside the target: it never
 * got to rename or remove it. The name says whose it was, so the next write
 * into the same folder - by any lamina on the same host - removes those
 * whose process is gone (kill(pid, 0) fails with ESRCH). A temporary of a
 * live process, or of another host sharing the folder, is left alone. */
#ifndef LAMINA_STALE_TEMP_H
#define LAMINA_STALE_TEMP_H

/* "<path>.tmp.<host>.<pid>.XXXXXX" for mkstemp (malloc'd), or NULL. */
char *lr_temp_template(const char *path);
/* Removes the stale temporaries in path's folder; each folder is swept
 * once per process (a run writing thousands of frames pays once). */
void lr_remove_stale_temps(const char *path);

#endif
