/* sim3_membrane_phi.c - the phi of a 3D membrane's construction sampled
 * element by element, for frames to draw its phi = 1 isosurface (issue 34
 * item 4; the normals paper draws phi = 1 through the points, [N] Figs
 * 3-16 in 2D, and its 3D construction is Figs 5 and 11).
 *
 * The construction ([N] eq 10) fits phi element by element: here the
 * centred elements of the running grid (sim3_membrane_normals.c), one per
 * site of the half-cell lattice holding points, each answering for the
 * points nearest its site. phi is piecewise, and so is what is drawn, as
 * in the 2D frames (l_frame_phi.c contours each centred element over the
 * half-cell square about its centre): each element's phi is sampled over
 * the half-cell cube about its site - these cubes tile space - including
 * the cube's faces, so that each cube is contoured on its own and the
 * pieces meet at the faces, with a step where two elements' phi = 1
 * disagree. (One node grid through all the cubes would draw a wall at
 * every such face: the nodes either side belong to different fits.) A
 * cube none of the points fell in has no fit and is left empty: a fit is
 * not extrapolated beyond its box (the linear basis' hats fall to 0
 * there), so where the surface clips such a cube the picture has a small
 * hole, as the construction has no phi there. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mpm3.h"
#include "mpm3_membrane.h"
#include "mpm_normals.h"

void lm3_phicubes_free(lm3_phicubes *c)
{
    if (!c) return;
    free(c->lo);
    free(c->f);
    memset(c, 0, sizeof *c);
}

int lm3_membrane_phi(const lm3_sim *sim, int k, lm3_mnormals basis, int samples,
                     lm3_phicubes *out, char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    const lm3_membranes *ms = sim->mem;
    if (!ms || k < 0 || k >= ms->nmem || samples < 1 || samples > 64) {
        snprintf(err, errlen, "phi: no membrane %d (or samples %d outside 1 .. 64)", k + 1,
                 samples);
        return -1;
    }
    size_t count = ms->mem[k].count ? ms->mem[k].count : 1;
    double *nrm[3] = {malloc(count * sizeof(double)), malloc(count * sizeof(double)),
                      malloc(count * sizeof(double))};
    lm_nreport rep;
    memset(&rep, 0, sizeof rep);
    int rc = -1;
    if (!nrm[0] || !nrm[1] || !nrm[2]) {
        snprintf(err, errlen, "phi of membrane %d: out of memory", k + 1);
        goto done;
    }
    if (lm3_membrane_construction(sim, k, basis, nrm, NULL, &rep, err, errlen) != 0)
        goto done;
    const size_t m = (size_t)samples + 1, m3 = m * m * m, n = (size_t)rep.nelem;
    out->lo = malloc((n ? 3 * n : 1) * sizeof *out->lo);
    out->f = malloc((n ? n * m3 : 1) * sizeof *out->f);
    if (!out->lo || !out->f) {
        snprintf(err, errlen, "phi of membrane %d: out of memory (%zu elements)", k + 1, n);
        goto done;
    }
    const lm3_grid *g = &sim->grid;
    const double q = 0.5 * g->h, d = q / samples;
    out->n = n;
    out->samples = samples;
    out->d = d;
    for (size_t e = 0; e < n; e++) {
        const lm_nelem *el = &rep.elem[e];
        double *lo = out->lo + 3 * e, *f = out->f + e * m3;
        /* site s's centre is lo + (s + 1) q (normals_centred.c); its cube
         * reaches q / 2 either side */
        for (int a = 0; a < 3; a++) lo[a] = g->lo[a] + (el->site[a] + 1) * q - 0.5 * q;
        size_t id = 0;
        for (size_t kz = 0; kz < m; kz++)
            for (size_t ky = 0; ky < m; ky++)
                for (size_t kx = 0; kx < m; kx++, id++) {
                    double x[3] = {lo[0] + kx * d, lo[1] + ky * d, lo[2] + kz * d};
                    f[id] = lm_nfit_phi(&el->fit, x);
                }
    }
    rc = 0;
done:
    if (rc != 0) lm3_phicubes_free(out);
    lm_nreport_free(&rep);
    for (int a = 0; a < 3; a++) free(nrm[a]);
    return rc;
}
