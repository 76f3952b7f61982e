/* vtk.c - VTK XML writers (vtk.h): UnstructuredGrid and Collection.
 *
 * The format is VTK's "XML file formats" with raw appended data: the XML
 * header names each DataArray with format="appended" and its offset into
 * the block that follows "<AppendedData encoding="raw">_"; each array in
 * the block is a UInt64 byte count followed by the bytes (little-endian,
 * as this machine writes them: the header says byte_order). The block ends
 * with a newline before </AppendedData>, which readers that split the
 * block at it (meshio) expect. */
#include <stdio.h>
#include <string.h>

#include "atomic_file.h"
#include "vtk.h"
#include "util.h"

/* One array of the appended block. */
typedef struct block {
    const void *data;
    uint64_t bytes;
} block;

static int little_endian(void)
{
    const uint16_t one = 1;
    return *(const uint8_t *)&one == 1;
}

static void header_open(FILE *fp, const char *type)
{
    fprintf(fp, "<?xml version=\"1.0\"?>\n<VTKFile type=\"%s\" version=\"1.0\" "
            "byte_order=\"%s\" header_type=\"UInt64\">\n", type,
            little_endian() ? "LittleEndian" : "BigEndian");
}

/* Declares a DataArray at the block's end and queues its data. */
static void data_array(FILE *fp, const char *vtype, const char *name, int ncomp,
                       const void *data, uint64_t bytes, block *bl, int *nb, uint64_t *off)
{
    fprintf(fp, "        <DataArray type=\"%s\"", vtype);
    if (name) fprintf(fp, " Name=\"%s\"", name);
    if (ncomp > 1) fprintf(fp, " NumberOfComponents=\"%d\"", ncomp);
    fprintf(fp, " format=\"appended\" offset=\"%llu\"/>\n", (unsigned long long)*off);
    bl[*nb].data = data;
    bl[*nb].bytes = bytes;
    (*nb)++;
    *off += sizeof(uint64_t) + bytes;
}

static void fields(FILE *fp, const char *tag, const lr_vtk_field *f, int nf, size_t n,
                   block *bl, int *nb, uint64_t *off)
{
    fprintf(fp, "      <%s>\n", tag);
    for (int k = 0; k < nf; k++)
        data_array(fp, "Float64", f[k].name, f[k].ncomp, f[k].data,
                   (uint64_t)n * (uint64_t)f[k].ncomp * sizeof(double), bl, nb, off);
    fprintf(fp, "      </%s>\n", tag);
}

static int appended(lr_atomic *a, const block *bl, int nb, char *err, size_t errlen)
{
    fputs("  <AppendedData encoding=\"raw\">\n_", a->fp);
    for (int k = 0; k < nb; k++) {
        if (fwrite(&bl[k].bytes, sizeof bl[k].bytes, 1, a->fp) != 1 ||
            (bl[k].bytes && fwrite(bl[k].data, 1, bl[k].bytes, a->fp) != bl[k].bytes))
            return lr_atomic_abort(a, "write failed", err, errlen);
    }
    fputs("\n  </AppendedData>\n</VTKFile>\n", a->fp);
    return lr_atomic_commit(a, err, errlen);
}

#define MAX_ARRAYS 64

/* Opens path for a file of `type` with narrays arrays; 0, or -1 with err. */
static int vtk_open(lr_atomic *a, const char *path, const char *type, int narrays, char *err,
                    size_t errlen)
{
    if (narrays > MAX_ARRAYS) {
        snprintf(err, errlen, "cannot write '%s': too many fields", path);
        return -1;
    }
    if (lr_atomic_open(a, path, err, errlen)) return -1;
    header_open(a->fp, type);
    return 0;
}

int lr_vtk_write_vtu(const char *path, size_t npts, const double *xyz,
                     const lr_vtk_cells *cells, const lr_vtk_field *pf, int npf,
                     const lr_vtk_field *cf, int ncf, char *err, size_t errlen)
{
    lr_atomic a;
    if (vtk_open(&a, path, "UnstructuredGrid", npf + ncf + 4, err, errlen)) return -1;
    block bl[MAX_ARRAYS];
    int nb = 0;
    uint64_t off = 0;
    fprintf(a.fp, "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"%zu\" "
            "NumberOfCells=\"%zu\">\n", npts, cells->n);
    fields(a.fp, "PointData", pf, npf, npts, bl, &nb, &off);
    fields(a.fp, "CellData", cf, ncf, cells->n, bl, &nb, &off);
    fputs("      <Points>\n", a.fp);
    data_array(a.fp, "Float64", "Points", 3, xyz, 3 * (uint64_t)npts * sizeof(double),
               bl, &nb, &off);
    fputs("      </Points>\n      <Cells>\n", a.fp);
    uint64_t nconn = cells->n ? (uint64_t)cells->offsets[cells->n - 1] : 0;
    data_array(a.fp, "Int64", "connectivity", 1, cells->conn, nconn * sizeof(int64_t),
               bl, &nb, &off);
    data_array(a.fp, "Int64", "offsets", 1, cells->offsets, cells->n * sizeof(int64_t),
               bl, &nb, &off);
    data_array(a.fp, "UInt8", "types", 1, cells->types, cells->n, bl, &nb, &off);
    fputs("      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n", a.fp);
    return appended(&a, bl, nb, err, errlen);
}

/* A file name as an XML attribute value. */
static void xml_attr(FILE *fp, const char *s)
{
    for (; *s; s++) {
        const char *e = lu_xml_entity(*s);
        if (e)
            fputs(e, fp);
        else
            fputc(*s, fp);
    }
}

int lr_vtk_write_pvd(const char *path, int n, const double *times, const int *part,
                     const char *const *files, char *err, size_t errlen)
{
    lr_atomic a;
    if (lr_atomic_open(&a, path, err, errlen)) return -1;
    fputs("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\">\n"
          "  <Collection>\n", a.fp);
    for (int k = 0; k < n; k++) {
        fprintf(a.fp, "    <DataSet timestep=\"%.17g\" part=\"%d\" file=\"", times[k], part[k]);
        xml_attr(a.fp, files[k]);
        fputs("\"/>\n", a.fp);
    }
    fputs("  </Collection>\n</VTKFile>\n", a.fp);
    return lr_atomic_commit(&a, err, errlen);
}
