/* read_file.h - reading a whole file that lamina did not necessarily write.
 *
 * report.json, meta.json, a run's log, a script: a path that is a link to
 * /dev/zero or a FIFO would be read for ever, and a huge file whole into
 * memory. So only regular files are read, up to a stated size. */
#ifndef LAMINA_READ_FILE_H
#define LAMINA_READ_FILE_H

#include <stddef.h>

/* The largest file read whole (reports, JSON, logs, scripts): 256 MB. */
#define LR_READ_MAX ((size_t)256 << 20)

/* The file's bytes plus a terminating NUL into *text (free it), its length
 * into *len (may be NULL). 0, or -1 with err "cannot read 'PATH': why"
 * (not a regular file, larger than max bytes, a system error). */
int lr_read_file(const char *path, size_t max, char **text, size_t *len, char *err,
                 size_t errlen);

#endif
