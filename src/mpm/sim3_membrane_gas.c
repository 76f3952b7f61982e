/* sim3_membrane_gas.c - a gas inside a closed 3D membrane, measured
 * (docs/3d.md "A gas inside a 3D membrane"): the volume the membrane's
 * points enclose and the gas particles outside it, the 3D forms of the 2D
 * membrane's enclosed_area and escaped (l_body.c, diag_gas.c). */
#include <math.h>
#include <stdlib.h>

#include "mpm3.h"
#include "mpm3_membrane.h"

static double area_of(const lm3_mpoints *p, size_t q)
{
    return p->A0[q] * exp(p->e[0][q] + p->e[1][q]);
}

/* The divergence theorem over the closed surface the points sample: V =
 * (1/3) sum A (x - c) . n, each point its current area and normal (n out);
 * c the points' mean, so that the sum's terms are of the surface's size
 * whatever its distance from the origin (any c gives the same V on a
 * closed surface). */
double lm3_membrane_volume(const lm3_sim *sim, int k)
{
    const lm3_mpoints *p = &sim->mem->p;
    const lm3_membrane *mb = &sim->mem->mem[k];
    double c[3] = {0, 0, 0}, V = 0;
    for (size_t q = mb->first; q < mb->first + mb->count; q++)
        for (int a = 0; a < 3; a++) c[a] += p->x[a][q];
    for (int a = 0; a < 3; a++) c[a] /= (double)(mb->count ? mb->count : 1);
    for (size_t q = mb->first; q < mb->first + mb->count; q++) {
        double s = 0;
        for (int a = 0; a < 3; a++) s += (p->x[a][q] - c[a]) * p->nrm[a][q];
        V += area_of(p, q) * s;
    }
    return V / 3;
}

static long cell_of(const lm3_grid *g, const double x[3], int ijk[3])
{
    for (int a = 0; a < 3; a++) {
        long i = (long)floor((x[a] - g->lo[a]) / g->h);
        if (i < 0) i = 0;
        if (i >= g->n[a]) i = g->n[a] - 1;
        ijk[a] = (int)i;
    }
    return ((long)ijk[2] * g->n[1] + ijk[1]) * g->n[0] + ijk[0];
}

/* The gas points of [first, first + n) outside membrane k. Each point is
 * judged by the membrane point nearest it: the signed distance along that
 * point's normal (n out), for gas within a cell of the skin; beyond that,
 * by the cells: those a flood from the grid's boundary reaches without
 * coming within a cell of a membrane point are outside (a closed surface
 * keeps the flood out of what it encloses, as long as its points are no
 * more than a cell apart, which lm3_membrane_add holds), and a gas point
 * there is outside by its distance to the nearest membrane point. */
int lm3_membrane_escaped(const lm3_sim *sim, int k, size_t first, size_t n, double quarter,
                         lm3_escaped *out)
{
    const lm3_grid *g = &sim->grid;
    const lm3_mpoints *mp = &sim->mem->p;
    const lm3_membrane *mb = &sim->mem->mem[k];
    const lm3_particles *pp = &sim->p;
    const long nc = (long)g->n[0] * g->n[1] * g->n[2];
    long *start = calloc((size_t)nc + 1, sizeof *start);
    size_t *order = malloc((mb->count ? mb->count : 1) * sizeof *order);
    unsigned char *flag = calloc((size_t)nc, 1);   /* 1 near the skin, 2 outside */
    long *stack = malloc((size_t)nc * sizeof *stack);
    int rc = -1;
    if (!start || !order || !flag || !stack) goto done;
    /* the membrane's points bucketed by cell (a counting sort) */
    for (size_t q = mb->first; q < mb->first + mb->count; q++) {
        double x[3] = {mp->x[0][q], mp->x[1][q], mp->x[2][q]};
        int ijk[3];
        start[cell_of(g, x, ijk) + 1]++;
    }
    for (long c = 0; c < nc; c++) start[c + 1] += start[c];
    {
        long *fill = stack;   /* the stack's room as each cell's next slot */
        for (long c = 0; c < nc; c++) fill[c] = start[c];
        for (size_t q = mb->first; q < mb->first + mb->count; q++) {
            double x[3] = {mp->x[0][q], mp->x[1][q], mp->x[2][q]};
            int ijk[3];
            order[fill[cell_of(g, x, ijk)]++] = q;
        }
    }
    /* near the skin: a cell within one (26 neighbours) of a cell with points */
    for (int z = 0; z < g->n[2]; z++)
        for (int y = 0; y < g->n[1]; y++)
            for (int x = 0; x < g->n[0]; x++) {
                long c = ((long)z * g->n[1] + y) * g->n[0] + x;
                if (start[c + 1] == start[c]) continue;
                for (int dz = -1; dz <= 1; dz++)
                    for (int dy = -1; dy <= 1; dy++)
                        for (int dx = -1; dx <= 1; dx++) {
                            int X = x + dx, Y = y + dy, Z = z + dz;
                            if (X < 0 || Y < 0 || Z < 0 || X >= g->n[0] || Y >= g->n[1] ||
                                Z >= g->n[2])
                                continue;
                            flag[((long)Z * g->n[1] + Y) * g->n[0] + X] = 1;
                        }
            }
    /* the flood from the boundary's cells through faces */
    long top = 0;
    for (int z = 0; z < g->n[2]; z++)
        for (int y = 0; y < g->n[1]; y++)
            for (int x = 0; x < g->n[0]; x++) {
                if (x > 0 && y > 0 && z > 0 && x < g->n[0] - 1 && y < g->n[1] - 1 &&
                    z < g->n[2] - 1)
                    continue;
                long c = ((long)z * g->n[1] + y) * g->n[0] + x;
                if (flag[c] == 0) {
                    flag[c] = 2;
                    stack[top++] = c;
                }
            }
    while (top > 0) {
        long c = stack[--top];
        int ijk[3] = {(int)(c % g->n[0]), (int)(c / g->n[0] % g->n[1]),
                      (int)(c / ((long)g->n[0] * g->n[1]))};
        for (int a = 0; a < 3; a++)
            for (int s = -1; s <= 1; s += 2) {
                int m[3] = {ijk[0], ijk[1], ijk[2]};
                m[a] += s;
                if (m[a] < 0 || m[a] >= g->n[a]) continue;
                long d = ((long)m[2] * g->n[1] + m[1]) * g->n[0] + m[0];
                if (flag[d] == 0) {
                    flag[d] = 2;
                    stack[top++] = d;
                }
            }
    }
    out->beyond = out->grazing = 0;
    out->deepest = 0;
    for (size_t j = first; j < first + n; j++) {
        double x[3] = {pp->x[0][j], pp->x[1][j], pp->x[2][j]};
        int ijk[3];
        long c = cell_of(g, x, ijk);
        if (flag[c] == 0) continue;   /* enclosed, away from the skin */
        double best = INFINITY;
        size_t bq = 0;
        if (flag[c] == 1) {
            for (int dz = -1; dz <= 1; dz++)
                for (int dy = -1; dy <= 1; dy++)
                    for (int dx = -1; dx <= 1; dx++) {
                        int X = ijk[0] + dx, Y = ijk[1] + dy, Z = ijk[2] + dz;
                        if (X < 0 || Y < 0 || Z < 0 || X >= g->n[0] || Y >= g->n[1] ||
                            Z >= g->n[2])
                            continue;
                        long d = ((long)Z * g->n[1] + Y) * g->n[0] + X;
                        for (long i = start[d]; i < start[d + 1]; i++) {
                            size_t q = order[i];
                            double r2 = 0;
                            for (int a = 0; a < 3; a++)
                                r2 += (x[a] - mp->x[a][q]) * (x[a] - mp->x[a][q]);
                            if (r2 < best) best = r2, bq = q;
                        }
                    }
            double s = 0;
            for (int a = 0; a < 3; a++) s += (x[a] - mp->x[a][bq]) * mp->nrm[a][bq];
            if (s <= 0) continue;
            if (s > out->deepest) out->deepest = s;
            if (s > quarter) out->beyond++;
            else out->grazing++;
        } else {
            /* out where the flood reached: its distance from the skin */
            for (size_t q = mb->first; q < mb->first + mb->count; q++) {
                double r2 = 0;
                for (int a = 0; a < 3; a++) r2 += (x[a] - mp->x[a][q]) * (x[a] - mp->x[a][q]);
                if (r2 < best) best = r2;
            }
            double s = sqrt(best);
            if (s > out->deepest) out->deepest = s;
            out->beyond++;
        }
    }
    rc = 0;
done:
    free(start);
    free(order);
    free(flag);
    free(stack);
    return rc;
}
