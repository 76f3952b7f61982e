/* test_figure_bench.c - `lamina bench render` runs and prints its table
 * (a tiny one: the timings themselves are a benchmark, never a test), and
 * refuses bad options with status 2. Runs when the binary is beside the
 * tests (build/lamina, the tests run in build/tests). */
#include "check.h"

#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

static char out[] = "bench_test_XXXXXX";

static int run(const char *args, char *text, size_t len)
{
    char cmd[512];
    snprintf(cmd, sizeof cmd, "../lamina bench %s >%s 2>&1", args, out);
    int st = system(cmd);
    FILE *fp = fopen(out, "rb");
    size_t n = fp ? fread(text, 1, len - 1, fp) : 0;
    text[n] = 0;
    if (fp)
        fclose(fp);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

int main(void)
{
    if (access("../lamina", X_OK) != 0) {
        printf("../lamina not found: skipped\n");
        return 0;
    }
    int fd = mkstemp(out);
    if (fd < 0) {
        perror("mkstemp");
        return 1;
    }
    close(fd);
    char text[4096];
    CHECK(run("render --width 64 --height 48 --runs 1 --counts 100,400", text, sizeof text) == 0);
    CHECK(strstr(text, "64x48 frames") != NULL);
    CHECK(strstr(text, "| particles | radius px | cairo draw | cairo +PNG |") != NULL);
    CHECK(strstr(text, "| 100 |") != NULL && strstr(text, "| 400 |") != NULL);
    CHECK(strstr(text, "machine: ") != NULL);
    CHECK(run("render --runs 0", text, sizeof text) == 2);
    CHECK(strstr(text, "--runs needs a whole number in [1, 101]") != NULL);
    CHECK(run("render --counts 12x", text, sizeof text) == 2);
    CHECK(run("render --backend vulkan", text, sizeof text) == 2);
    CHECK(strstr(text, "unknown backend 'vulkan'") != NULL);
    CHECK(run("render --frob", text, sizeof text) == 2);
    CHECK(strstr(text, "unknown option '--frob'") != NULL);
    CHECK(run("gpu", text, sizeof text) == 2);
    CHECK(strstr(text, "'gpu' is not a benchmark; known: render, engine") != NULL);
    CHECK(run("", text, sizeof text) == 2);
    unlink(out);
    return CHECK_DONE();
}
