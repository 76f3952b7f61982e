/* read_file.c - see read_file.h. */
#include "read_file.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int lr_read_file(const char *path, size_t max, char **text, size_t *len, char *err,
                 size_t errlen)
{
    *text = NULL;
    FILE *f = fopen(path, "rb");
    struct stat st;
    const char *why = NULL;
    if (!f) {
        snprintf(err, errlen, "cannot read '%s': %s", path, strerror(errno));
        return -1;
    }
    if (fstat(fileno(f), &st) != 0) why = strerror(errno);
    else if (!S_ISREG(st.st_mode)) why = "not a regular file";
    else if ((size_t)st.st_size > max) why = "larger than the limit of 256 MB";
    char *buf = NULL;
    size_t n = 0;
    if (!why) {
        /* the size may change under us: read at most max + 1 bytes */
        size_t cap = (size_t)st.st_size + 1;
        buf = malloc(cap + 1);
        if (!buf) why = "out of memory";
        while (buf) {
            size_t got = fread(buf + n, 1, cap - n, f);
            n += got;
            if (got == 0) break;
            if (n > max) {
                why = "larger than the limit of 256 MB";
                break;
            }
            if (n == cap) {
                char *b = realloc(buf, 2 * cap + 1);
                if (!b) {
                    why = "out of memory";
                    break;
                }
                buf = b;
                cap *= 2;
            }
        }
        if (!why && ferror(f)) why = strerror(errno ? errno : EIO);
    }
    fclose(f);
    if (why) {
        free(buf);
        snprintf(err, errlen, "cannot read '%s': %s", path, why);
        return -1;
    }
    buf[n] = '\0';
    *text = buf;
    if (len) *len = n;
    return 0;
}
