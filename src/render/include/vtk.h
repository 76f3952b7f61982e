/* vtk.h - VTK XML files for ParaView: unstructured grids (.vtu: the
 * particles, and the background grid as quads), and a collection
 * (.pvd) that makes a run a time series.
 *
 * Arrays go into one raw appended block (each array preceded by its byte
 * count as a little-endian UInt64: header_type="UInt64"), which ParaView and
 * meshio read. Every file is written whole or not at all (atomic_file.h).
 * Plain writers: the caller gathers the arrays. */
#ifndef LAMINA_VTK_H
#define LAMINA_VTK_H

#include <stddef.h>
#include <stdint.h>

/* VTK cell types used here */
enum { LR_VTK_VERTEX = 1, LR_VTK_LINE = 3, LR_VTK_QUAD = 9 };

typedef struct lr_vtk_field {
    const char *name;
    int ncomp;              /* 1 scalar, 3 vector, 6 symmetric tensor */
    const double *data;     /* n * ncomp values, point by point */
} lr_vtk_field;

typedef struct lr_vtk_cells {
    size_t n;               /* cells */
    const int64_t *conn;    /* point indices, cell after cell */
    const int64_t *offsets; /* end of each cell in conn */
    const uint8_t *types;   /* LR_VTK_* per cell */
} lr_vtk_cells;

/* Points xyz (3 per point), cells, point fields and cell fields (each
 * cell field has cells->n * ncomp values). 0, or -1 with err set. */
int lr_vtk_write_vtu(const char *path, size_t npts, const double *xyz,
                     const lr_vtk_cells *cells, const lr_vtk_field *pf, int npf,
                     const lr_vtk_field *cf, int ncf, char *err, size_t errlen);

/* A collection of n datasets: times[k] and file names (relative to the
 * .pvd's folder); part[k] numbers the datasets of one time step. */
int lr_vtk_write_pvd(const char *path, int n, const double *times, const int *part,
                     const char *const *files, char *err, size_t errlen);

#endif
