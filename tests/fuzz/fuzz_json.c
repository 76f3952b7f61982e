/* fuzz_json.c - libFuzzer target: lamina's two JSON readers on arbitrary
 * bytes: the gallery's (lu_json_parse: report.json, meta.json) and the sweep's
 * (sw_report_read: the values of report.json). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_file.h"
#include "gallery.h"
#include "sweep.h"

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
