/* fuzz_json.c - libFuzzer target: lamina's JSON reader on arbitrary bytes,
 * directly (lu_json_parse, src/util: the gallery's report.json and
 * meta.json) and through the sweep (sw_report_read: the values of
 * report.json, read from a file). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_file.h"
#include "gallery.h"
#include "sweep.h"
#include "fuzz_target.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text) return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    char err[256];
    lu_json *v = lu_json_parse(text, err, sizeof err);
    if (v) {
        const lu_json *vals = lu_json_get(v, "values");
        (void)vals;
        lu_json_free(v);
    }
    free(text);

    char **names = NULL, **values = NULL;
    int n = 0;
    if (sw_report_read(fuzz_file(data, size), &names, &values, &n) == 0) {
        for (int i = 0; i < n; i++) {
            if (!names[i] || !values[i]) abort();
            free(names[i]);
            free(values[i]);
        }
    }
    free(names);
    free(values);
    return 0;
}
