/* fuzz_mesh.c - libFuzzer target: the triangle-mesh reader (mesh3.h: OBJ,
 * ASCII and binary STL, issue 34's lamina.mesh{file}) on arbitrary bytes.
 * Either the parse fails with a message naming the input, or it returns a
 * mesh whose every triangle names three different vertices in range and
 * whose coordinates are finite; its closedness check, inside test and
 * sampling into membrane points then run on it. Anything else, a crash or
 * a sanitizer report is a finding. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_target.h"
#include "mesh3.h"
#include "mpm3_membrane.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[512] = "";
    lm3_mesh m;
    if (lm3_mesh_parse("fuzz.mesh", (const char *)data, size, &m, err, sizeof err) != 0) {
        if (!strstr(err, "fuzz.mesh")) {
            fprintf(stderr, "fuzz_mesh: a refusal not naming the input: %s\n", err);
            abort();
        }
        if (m.xyz || m.tri || m.nv || m.nt) abort();   /* nothing returned */
        return 0;
    }
    if (m.nt == 0 || m.nv == 0) abort();
    for (size_t k = 0; k < 3 * m.nv; k++)
        if (!isfinite(m.xyz[k])) abort();
    for (size_t t = 0; t < m.nt; t++) {
        const int32_t *v = m.tri + 3 * t;
        for (int k = 0; k < 3; k++)
            if (v[k] < 0 || (size_t)v[k] >= m.nv) abort();
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) abort();
    }
    if (m.nt <= 4096) {   /* the quadratic parts kept to small meshes */
        if (lm3_mesh_closed("fuzz.mesh", &m, err, sizeof err) == 1) {
            double x[3] = {0.25, 0.5, 0.75};
            (void)lm3_mesh_inside(&m, x);
        }
        lm3_msample s;
        if (lm3_sample_mesh(m.xyz, m.nv, m.tri, m.nt, &s, err, sizeof err) == 0)
            lm3_msample_free(&s);
    }
    lm3_mesh_free(&m);
    return 0;
}
