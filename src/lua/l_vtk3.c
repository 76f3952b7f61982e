/* l_vtk3.c - sim:vtk's pieces for a 3D run (l_vtk.c writes the series and
 * its .pvd for both dimensions): the particles as an unstructured grid of
 * vertices with their fields, the grid's nodes 0..n (without the ghost
 * ring) as hexahedra with the last step's nodal mass, velocity and force.
 * The field names are the 2D files' (velocity, stress, pressure, density,
 * mass, body), with three components and the whole symmetric tensor, so a
 * ParaView state made for a 2D run opens a 3D one. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "l_pressure3.h"
#include "l_sim3.h"
#include "mpm3_membrane.h"
#include "vtk.h"

#define VTK_HEXAHEDRON 12   /* VTK's cell type (vtkCellType.h) */

/* Points as one vertex cell each, written with their fields; frees the
 * buffers la_vtk_arrays gave (d holds xyz, conn the cells and offsets). */
static int write_points(const char *path, size_t n, double *d, const double *xyz, int64_t *conn,
                        uint8_t *types, const lr_vtk_field *pf, int npf, const lr_vtk_field *cf,
                        char *err, size_t errlen)
{
    int64_t *offs = conn + n;
    for (size_t q = 0; q < n; q++) {
        conn[q] = (int64_t)q;
        offs[q] = (int64_t)q + 1;
        types[q] = LR_VTK_VERTEX;
    }
    lr_vtk_cells cells = {n, conn, offs, types};
    int rc = lr_vtk_write_vtu(path, n, xyz, &cells, pf, npf, cf, 1, err, errlen);
    free(d);
    free(conn);
    free(types);
    return rc;
}

int la_vtk3_write_particles(const la_sim3 *s3, const char *path, char *err, size_t errlen)
{
    const lm3_particles *p = &s3->sim->p;
    size_t n = p->n;
    /* xyz 3, velocity 3, stress 6, pressure, density, mass, body; cells */
    double *d;
    int64_t *conn;
    uint8_t *types;
    if (la_vtk_arrays(16 * n, 2 * n, n, &d, &conn, &types, path, err, errlen) != 0) return -1;
    double *xyz = d, *vel = d + 3 * n, *sig = d + 6 * n, *pr = d + 12 * n, *rho = d + 13 * n,
           *mass = d + 14 * n, *body = d + 15 * n;
    /* VTK's symmetric tensor order XX, YY, ZZ, XY, YZ, XZ from the engine's
     * Voigt order xx, yy, zz, yz, xz, xy */
    static const int voigt[6] = {0, 1, 2, 5, 3, 4};
    for (size_t q = 0; q < n; q++) {
        for (int a = 0; a < 3; a++) {
            xyz[3 * q + a] = p->x[a][q];
            vel[3 * q + a] = p->v[a][q];
        }
        for (int c = 0; c < 6; c++) sig[6 * q + c] = p->s[voigt[c]][q];
        pr[q] = la_pressure3(s3->sim, q);   /* a gas's (gamma - 1) rho e */
        rho[q] = p->rho[q];
        mass[q] = p->m[q];
    }
    for (int b = 0; b < s3->nbodies; b++)
        for (size_t q = s3->bodies[b].first; q < s3->bodies[b].first + s3->bodies[b].n; q++)
            body[q] = b + 1;
    lr_vtk_field pf[] = {{"velocity", 3, vel}, {"stress", 6, sig}, {"pressure", 1, pr},
                         {"density", 1, rho},  {"mass", 1, mass},  {"body", 1, body}};
    lr_vtk_field cf[] = {{"body", 1, body}};
    return write_points(path, n, d, xyz, conn, types, pf, 6, cf, err, errlen);
}

int la_vtk3_write_grid(const la_sim3 *s3, const char *path, char *err, size_t errlen)
{
    const lm3_grid *g = &s3->sim->grid;
    const int nx = g->n[0], ny = g->n[1], nz = g->n[2];
    la_vtk_grid out;
    if (la_vtk_grid_alloc(&out, (size_t)(nx + 1) * (size_t)(ny + 1) * (size_t)(nz + 1),
                          (size_t)nx * (size_t)ny * (size_t)nz, 8, path, err, errlen) != 0)
        return -1;
    size_t i = 0;
    for (int c = 0; c <= nz; c++)
        for (int b = 0; b <= ny; b++)
            for (int a = 0; a <= nx; a++, i++) {
                long k = lm3_node(g, a, b, c);
                out.mass[i] = g->m[k];
                for (int e = 0; e < 3; e++) {
                    out.vel[3 * i + e] = g->v[e][k];
                    out.force[3 * i + e] = g->f[e][k];
                }
                out.xyz[3 * i] = g->lo[0] + a * g->h;
                out.xyz[3 * i + 1] = g->lo[1] + b * g->h;
                out.xyz[3 * i + 2] = g->lo[2] + c * g->h;
            }
    /* cell (a, b, c): the bottom face anticlockwise, then the top, as
     * VTK_HEXAHEDRON wants them */
    const int64_t sx = nx + 1, sxy = (int64_t)(nx + 1) * (ny + 1);
    size_t cell = 0;
    for (int c = 0; c < nz; c++)
        for (int b = 0; b < ny; b++)
            for (int a = 0; a < nx; a++, cell++) {
                int64_t n0 = c * sxy + b * sx + a, *q = out.conn + 8 * cell;
                q[0] = n0;
                q[1] = n0 + 1;
                q[2] = n0 + 1 + sx;
                q[3] = n0 + sx;
                for (int k = 0; k < 4; k++) q[4 + k] = q[k] + sxy;
                out.offs[cell] = 8 * (int64_t)(cell + 1);
                out.types[cell] = VTK_HEXAHEDRON;
            }
    return la_vtk_grid_write(path, &out, err, errlen);
}

/* The membranes' points (issue 34 item 2) as their own piece, beside the
 * particles' (part 2 of the series; written only when the sim has
 * membranes): vertices with the point fields velocity, normal (the
 * membrane's current one: its frame's t1 x t2 or the construction's),
 * tension (the mean (t11 + t22) / 2, N/m, lm3_membrane_tension), the
 * tension as a symmetric tensor in the global frame (thickness times s_ab
 * t_a (x) t_b, VTK's order XX, YY, ZZ, XY, YZ, XZ: ParaView's tensor
 * glyphs), the tangents t1 and t2, area (current, A0 exp(e11 + e22)),
 * mass, membrane (its number from 1, also a cell field) and pinned (1 or
 * 0). The names follow the particles' piece where they mean the same. */
int la_vtk3_write_membranes(const la_sim3 *s3, const char *path, char *err, size_t errlen)
{
    const lm3_membranes *ms = s3->sim->mem;
    const lm3_mpoints *p = &ms->p;
    const size_t n = p->n;
    /* xyz 3, velocity 3, normal 3, tension 1, tensor 6, t1 3, t2 3, area,
     * mass, membrane, pinned */
    double *d;
    int64_t *conn;
    uint8_t *types;
    if (la_vtk_arrays(26 * n, 2 * n, n, &d, &conn, &types, path, err, errlen) != 0) return -1;
    double *xyz = d, *vel = d + 3 * n, *nrm = d + 6 * n, *ten = d + 9 * n, *tt = d + 10 * n,
           *t1 = d + 16 * n, *t2 = d + 19 * n, *area = d + 22 * n, *mass = d + 23 * n,
           *mem = d + 24 * n, *pin = d + 25 * n;
    /* VTK's order of a symmetric tensor's components as (i, j) */
    static const int ij[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
    for (size_t q = 0; q < n; q++) {
        const double th = ms->mem[p->mem[q]].def.mat.thickness;
        double a[3], b[3];
        for (int k = 0; k < 3; k++) {
            xyz[3 * q + k] = p->x[k][q];
            vel[3 * q + k] = p->v[k][q];
            nrm[3 * q + k] = p->nrm[k][q];
            t1[3 * q + k] = a[k] = p->t1[k][q];
            t2[3 * q + k] = b[k] = p->t2[k][q];
        }
        for (int c = 0; c < 6; c++) {
            int i = ij[c][0], j = ij[c][1];
            tt[6 * q + c] = th * (p->s[0][q] * a[i] * a[j] + p->s[1][q] * b[i] * b[j] +
                                  p->s[2][q] * (a[i] * b[j] + b[i] * a[j]));
        }
        ten[q] = lm3_membrane_tension(s3->sim, q);
        area[q] = p->A0[q] * exp(p->e[0][q] + p->e[1][q]);
        mass[q] = p->m[q];
        mem[q] = p->mem[q] + 1;
        pin[q] = p->pin[q];
    }
    lr_vtk_field pf[] = {{"velocity", 3, vel}, {"normal", 3, nrm},  {"tension", 1, ten},
                         {"tension_tensor", 6, tt}, {"t1", 3, t1}, {"t2", 3, t2},
                         {"area", 1, area},     {"mass", 1, mass},  {"membrane", 1, mem},
                         {"pinned", 1, pin}};
    lr_vtk_field cf[] = {{"membrane", 1, mem}};
    return write_points(path, n, d, xyz, conn, types, pf, 10, cf, err, errlen);
}

int la_vtk3_has_membranes(const la_sim3 *s3)
{
    return s3 && s3->sim->mem && s3->sim->mem->p.n > 0;
}
