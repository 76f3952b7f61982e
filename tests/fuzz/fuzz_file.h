/* fuzz_file.h - the fuzzer's bytes as a file, for readers that take a path
 * (lr_png_read, sw_report_read). One temporary per process, rewritten at
 * every input. */
#ifndef LAMINA_FUZZ_FILE_H
#define LAMINA_FUZZ_FILE_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static char fuzz_path[64];

static void fuzz_file_remove(void)
{
    unlink(fuzz_path);
}

static const char *fuzz_file(const uint8_t *data, size_t size)
{
    char *path = fuzz_path;
    if (!path[0]) {
        snprintf(path, sizeof fuzz_path, "/tmp/lamina-fuzz-XXXXXX");
        int fd = mkstemp(path);
        if (fd < 0) abort();
        close(fd);
        atexit(fuzz_file_remove);   /* (libFuzzer ends with exit) */
    }
    FILE *f = fopen(path, "wb");
    if (!f) abort();
    if (size && fwrite(data, 1, size, f) != size) abort();
    fclose(f);
    return path;
}

#endif
