/* test_files.h - reading back what a test wrote. */
#ifndef LAMINA_TEST_FILES_H
#define LAMINA_TEST_FILES_H

#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

static inline int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* The whole file, malloc'd and NUL-terminated (so text can be searched);
 * NULL if it cannot be read. */
static inline unsigned char *slurp(const char *path, long *len)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return NULL;
    unsigned char *buf = NULL;
    if (fseek(fp, 0, SEEK_END) == 0 && (*len = ftell(fp)) >= 0 &&
        fseek(fp, 0, SEEK_SET) == 0 && (buf = malloc((size_t)*len + 1)) &&
        fread(buf, 1, (size_t)*len, fp) != (size_t)*len) {
        free(buf);
        buf = NULL;
    }
    if (buf)
        buf[*len] = '\0';
    fclose(fp);
    return buf;
}

#endif
