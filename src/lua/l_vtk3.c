/* l_vtk3.c - sim:vtk's pieces for a 3D run (l_vtk.c writes the series and
 * its .pvd for both dimensions): the particles as an unstructured grid of
 * vertices with their fields, the grid's nodes 0..n (without the ghost
 * ring) as hexahedra with the last step's nodal mass, velocity and force.
 * The field names are the 2D files' (velocity, stress, pressure, density,
 * mass, body), with three components and the whole symmetric tensor, so a
 * ParaView state made for a 2D run opens a 3D one. */
#include <stdio.h>
#include <stdlib.h>

#include "l_pressure3.h"
#include "l_sim3.h"
#include "vtk.h"

#define VTK_HEXAHEDRON 12   /* VTK's cell type (vtkCellType.h) */

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
    int64_t *offs = conn + n;
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
        conn[q] = (int64_t)q;
        offs[q] = (int64_t)q + 1;
        types[q] = LR_VTK_VERTEX;
    }
    for (int b = 0; b < s3->nbodies; b++)
        for (size_t q = s3->bodies[b].first; q < s3->bodies[b].first + s3->bodies[b].n; q++)
            body[q] = b + 1;
    lr_vtk_field pf[] = {{"velocity", 3, vel}, {"stress", 6, sig}, {"pressure", 1, pr},
                         {"density", 1, rho},  {"mass", 1, mass},  {"body", 1, body}};
    lr_vtk_field cf[] = {{"body", 1, body}};
    lr_vtk_cells cells = {n, conn, offs, types};
    int rc = lr_vtk_write_vtu(path, n, xyz, &cells, pf, 6, cf, 1, err, errlen);
    free(d);
    free(conn);
    free(types);
    return rc;
}

int la_vtk3_write_grid(const la_sim3 *s3, const char *path, char *err, size_t errlen)
{
    const lm3_grid *g = &s3->sim->grid;
    const int nx = g->n[0], ny = g->n[1], nz = g->n[2];
    size_t nn = (size_t)(nx + 1) * (size_t)(ny + 1) * (size_t)(nz + 1);
    size_t nc = (size_t)nx * (size_t)ny * (size_t)nz;
    double *d;
    int64_t *conn;
    uint8_t *types;
    if (la_vtk_arrays(10 * nn, 9 * nc, nc, &d, &conn, &types, path, err, errlen) != 0) return -1;
    double *vel = d + nn, *force = d + 4 * nn, *xyz = d + 7 * nn;
    int64_t *offs = conn + 8 * nc;
    size_t i = 0;
    for (int c = 0; c <= nz; c++)
        for (int b = 0; b <= ny; b++)
            for (int a = 0; a <= nx; a++, i++) {
                long k = lm3_node(g, a, b, c);
                d[i] = g->m[k];
                for (int e = 0; e < 3; e++) {
                    vel[3 * i + e] = g->v[e][k];
                    force[3 * i + e] = g->f[e][k];
                }
                xyz[3 * i] = g->lo[0] + a * g->h;
                xyz[3 * i + 1] = g->lo[1] + b * g->h;
                xyz[3 * i + 2] = g->lo[2] + c * g->h;
            }
    /* cell (a, b, c): the bottom face anticlockwise, then the top, as
     * VTK_HEXAHEDRON wants them */
    const int64_t sx = nx + 1, sxy = (int64_t)(nx + 1) * (ny + 1);
    size_t cell = 0;
    for (int c = 0; c < nz; c++)
        for (int b = 0; b < ny; b++)
            for (int a = 0; a < nx; a++, cell++) {
                int64_t n0 = c * sxy + b * sx + a, *q = conn + 8 * cell;
                q[0] = n0;
                q[1] = n0 + 1;
                q[2] = n0 + 1 + sx;
                q[3] = n0 + sx;
                for (int k = 0; k < 4; k++) q[4 + k] = q[k] + sxy;
                offs[cell] = 8 * (int64_t)(cell + 1);
                types[cell] = VTK_HEXAHEDRON;
            }
    return la_vtk_grid_write(path, nn, nc, d, conn, offs, types, err, errlen);
}
