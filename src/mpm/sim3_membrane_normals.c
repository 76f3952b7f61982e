/* sim3_membrane_normals.c - a 3D membrane's normals without connectivity
 * (issue 34 item 2): the normals paper's construction on the simulation's
 * grid, from the membrane points alone ([N] §3-4: phi fitted to 1 at the
 * points of each cell and 0 at one random point, n = grad phi / |grad phi|,
 * eqs 10-11 and 16), with the 8 x 8 trilinear system of [N] Fig 5 or the
 * 27 x 27 triquadratic one of Fig 11 per cell; a cell short of points is
 * solved on a merged block of cells ([N] §4, normals_grid.c). The solver
 * is the module's (mpm_normals.h), unchanged: the static points of the
 * paper's figures and a running membrane's points are the same input.
 *
 * The construction's sign is arbitrary ([N] §8). The orientation rule is
 * the 2D issue's: each normal agrees with the normal the surface gives
 * (n . (t1 x t2) >= 0), and the surface's frame was made to point out of
 * a closed surface when it was sampled (sim3_membrane_surface.c) and is
 * convected continuously since, so it still does. */
#include <stdio.h>
#include <stdlib.h>

#include "mpm3.h"
#include "mpm3_membrane.h"
#include "mpm_normals.h"
#include "normals.h"

int lm3_membrane_construction_normals(lm3_sim *sim, int k, lm3_mnormals basis,
                                      double *const nrm[3], size_t *undefined)
{
    return lm3_membrane_construction(sim, k, basis, nrm, undefined, NULL, sim->err,
                                     sizeof sim->err);
}

int lm3_membrane_construction(const lm3_sim *sim, int k, lm3_mnormals basis,
                              double *const nrm[3], size_t *undefined, lm_nreport *rep,
                              char *err, size_t errlen)
{
    const lm3_membranes *ms = sim->mem;
    if (!ms || k < 0 || k >= ms->nmem ||
        (basis != LM3_MN_LINEAR && basis != LM3_MN_QUADRATIC)) {
        snprintf(err, errlen, "construction normals: no membrane %d or basis %d",
                 k + 1, (int)basis);
        return -1;
    }
    const lm3_membrane *mb = &ms->mem[k];
    const lm3_mpoints *p = &ms->p;
    const lm3_grid *g = &sim->grid;
    lm_ngrid ng = {.dim = 3};
    for (int a = 0; a < 3; a++) {
        ng.x0[a] = g->lo[a];
        ng.h[a] = g->h;
        ng.n[a] = g->n[a];
    }
    /* the centred elements of the 2D per-step normals (normals_centred.c:
     * one-cell elements centred on the half-cell lattice site nearest each
     * point, so the surface crosses its element instead of clipping a
     * corner; the curvature rows and the random point's clearance), with
     * the basis asked for. Measured on the running sphere of
     * test_sim3_membrane (B-spline grid, 600 steps): triquadratic within
     * 0.06 degrees of radial against 75 degrees for the cells' own fits
     * (a few cells clipped at a corner), trilinear 83-89 degrees either
     * way (docs/3d.md). */
    lm_nopts o;
    lm_nopts_centred(&o);
    o.basis = basis == LM3_MN_LINEAR ? LM_NB_LINEAR : LM_NB_QUADRATIC;
    o.skip_cond = 1;
    const double *x[3] = {p->x[0] + mb->first, p->x[1] + mb->first, p->x[2] + mb->first};
    unsigned char *flags = malloc(mb->count);
    if (!flags) {
        snprintf(err, errlen, "out of memory for the normals of membrane %d", k + 1);
        return -1;
    }
    char why[200];
    lm_nerr e = lm_normals_grid(&ng, mb->count, x, &o, nrm, flags, rep, why, sizeof why);
    if (e != LM_NERR_NONE && e != LM_NERR_UNDEFINED) {
        free(flags);
        snprintf(err, errlen, "t = %g (step %ld): membrane %d's normals: %.120s",
                 sim->t, sim->nstep, k + 1, why);
        return -1;
    }
    size_t und = 0;
    for (size_t j = 0; j < mb->count; j++) {
        size_t q = mb->first + j;
        /* the frame's normal t1 x t2 */
        double f[3] = {p->t1[1][q] * p->t2[2][q] - p->t1[2][q] * p->t2[1][q],
                       p->t1[2][q] * p->t2[0][q] - p->t1[0][q] * p->t2[2][q],
                       p->t1[0][q] * p->t2[1][q] - p->t1[1][q] * p->t2[0][q]};
        if (flags[j] & LM_NF_UNDEFINED) {
            und++;
            for (int a = 0; a < 3; a++) nrm[a][j] = f[a];
            continue;
        }
        double s = nrm[0][j] * f[0] + nrm[1][j] * f[1] + nrm[2][j] * f[2];
        if (s < 0)
            for (int a = 0; a < 3; a++) nrm[a][j] = -nrm[a][j];
    }
    free(flags);
    if (undefined) *undefined = und;
    return 0;
}
