"""Reads every file sim:vtk wrote back (issue 20 item 1, issue 35 item 5)
and compares it with the values lamina printed (tests/io/vtk_export.lua),
through two readers that are not lamina's code:

- VTK's own XML reader (vtkXMLUnstructuredGridReader, Debian python3-vtk9),
  which ParaView uses;
- meshio (Debian python3-meshio), the reader of many Python users.

Every .vtu the .pvd lists (particles and grid, at every time) must open in
both with the same values. The last output is compared with lamina's own
numbers: the particles with the REF lines, the grid with a reference
computed here from the PRE lines (the positions at the start of the last
step): nodal mass sum_p m_p N_i(x_p) with the bilinear hat functions and,
at interior nodes, velocity sum_p m_p v_p N_i(x_p) / m_i (MUSL's re-mapped
velocity, from the particles' velocities after the step); the fixed walls'
nodes hold 0. The .pvd (which neither reader opens: ParaView's own) is
read with Python's XML parser.

usage: vtk_check.py REF_FILE PREFIX"""
import sys
import xml.etree.ElementTree as ET

import meshio
import numpy as np
# only the XML reader's module (not `import vtk`, which loads rendering,
# Qt and MPI too)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader


def fail(msg):
    print("vtk_check: FAILED:", msg)
    sys.exit(1)


def close(a, b, what, tol=1e-12):
    a, b = np.asarray(a, float), np.asarray(b, float)
    if a.shape != b.shape:
        fail(f"{what}: shape {a.shape} vs {b.shape}")
    scale = max(1.0, float(np.max(np.abs(b))) if b.size else 1.0)
    err = float(np.max(np.abs(a - b))) if a.size else 0.0
    if err > tol * scale:
        fail(f"{what}: differs by {err:g}")


def read_vtk(path):
    """(points, {name: array}, cells as [(vtk type, point ids)]) by VTK."""
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    if r.GetErrorCode() != 0:
        fail(f"VTK cannot read {path} (error code {r.GetErrorCode()})")
    g = r.GetOutput()
    if g is None or g.GetNumberOfPoints() == 0:
        fail(f"VTK read no points from {path}")
    pts = vtk_to_numpy(g.GetPoints().GetData())
    pd = g.GetPointData()
    arrays = {pd.GetArrayName(i): vtk_to_numpy(pd.GetArray(i))
              for i in range(pd.GetNumberOfArrays())}
    cells = []
    for c in range(g.GetNumberOfCells()):
        ids = g.GetCell(c).GetPointIds()
        cells.append((g.GetCellType(c), [ids.GetId(k) for k in range(ids.GetNumberOfIds())]))
    return pts, arrays, cells


MESHIO_TYPES = {"vertex": 1, "line": 3, "quad": 9}


def read_both(path, types=MESHIO_TYPES):
    """Reads path with VTK and meshio; they must agree (meshio's cell types
    named to VTK's numbers by types); VTK's result."""
    pts, arrays, cells = read_vtk(path)
    try:
        mesh = meshio.read(path)
    except Exception as e:   # noqa: BLE001 - any failure is the finding
        fail(f"meshio cannot read {path}: {type(e).__name__}: {e}")
    close(mesh.points, pts, f"{path}: points (meshio vs VTK)", 0)
    if set(mesh.point_data) != set(arrays):
        fail(f"{path}: meshio has {sorted(mesh.point_data)}, VTK {sorted(arrays)}")
    for name, a in arrays.items():
        close(np.asarray(mesh.point_data[name]).reshape(a.shape), a,
              f"{path}: {name} (meshio vs VTK)", 0)
    mcells = [(types[b.type], list(row)) for b in mesh.cells for row in b.data]
    if sorted(mcells) != sorted(cells):
        fail(f"{path}: meshio's cells differ from VTK's")
    return pts, arrays, cells


def grid_reference(pre, ref, h, nx, ny):
    """Nodal mass and momentum of the last step's particle-to-grid map."""
    nn = (nx + 1) * (ny + 1)
    m, p = np.zeros(nn), np.zeros((nn, 2))
    for (x, y, mp), v in zip(pre[:, 1:4], ref[:, 3:5]):
        i, j = int(x // h), int(y // h)
        fx, fy = x / h - i, y / h - j
        for da, wa in ((0, 1 - fx), (1, fx)):
            for db, wb in ((0, 1 - fy), (1, fy)):
                k = (j + db) * (nx + 1) + i + da
                m[k] += mp * wa * wb
                p[k] += mp * wa * wb * v
    return m, p


def main():
    ref_file, prefix = sys.argv[1], sys.argv[2]
    ref, pre, t_end, nmem, grid = [], [], None, None, None
    for line in open(ref_file):
        w = line.split()
        if w and w[0] == "REF":
            ref.append([float(x) for x in w[1:]])
        elif w and w[0] == "PRE":
            pre.append([float(x) for x in w[1:]])
        elif w and w[0] == "META":
            t_end, nmem = float(w[2]), int(w[4])
        elif w and w[0] == "GRID":
            grid = dict(zip(w[1::2], (float(x) for x in w[2::2])))
    ref, pre = np.array(ref), np.array(pre)
    if ref.size == 0 or pre.shape[0] != ref.shape[0] or grid is None:
        fail("no REF, PRE or GRID lines")
    # the collection: four times, particles and grid at each
    pvd = ET.parse(prefix + ".pvd").getroot()
    sets = pvd.findall("./Collection/DataSet")
    times = sorted({float(d.get("timestep")) for d in sets})
    close(times, [0.0, 0.001, 0.002, 0.003], "pvd times", 1e-9)
    if len(sets) != 8:
        fail(f"pvd lists {len(sets)} datasets, expected 8")
    close(times[-1], t_end, "last time", 1e-12)
    folder = prefix.rsplit("/", 1)[0] + "/" if "/" in prefix else ""
    # every file of the series opens in both readers, and they agree
    read = {}
    for d in sets:
        read[d.get("file")] = read_both(folder + d.get("file"))
    last = [d.get("file") for d in sets if float(d.get("timestep")) == times[-1]]
    part = {d.get("file"): d.get("part") for d in sets}
    vtu = [f for f in last if part[f] == "0"][0]
    gridf = [f for f in last if part[f] == "1"][0]

    # the particles
    pts, pd, cells = read[vtu]
    n = len(ref)
    if pts.shape[0] != n:
        fail(f"{pts.shape[0]} points, lamina has {n}")
    close(pts[:, 0], ref[:, 1], "x")
    close(pts[:, 1], ref[:, 2], "y")
    close(pd["velocity"][:, 0], ref[:, 3], "vx")
    close(pd["velocity"][:, 1], ref[:, 4], "vy")
    close(pd["stress"][:, 0], ref[:, 5], "sxx")
    close(pd["stress"][:, 1], ref[:, 6], "syy")
    close(pd["stress"][:, 3], ref[:, 7], "sxy")
    close(pd["density"], ref[:, 8], "density")
    close(pd["mass"], ref[:, 9], "mass")
    close(pd["body"], ref[:, 0], "body")
    gas = ref[:, 0] == 2
    close(pd["pressure"][gas], ref[gas, 10], "gas pressure")
    mem = ref[:, 0] == 3
    close(pd["normal"][mem, 0], ref[mem, 11], "membrane nx")
    close(pd["normal"][mem, 1], ref[mem, 12], "membrane ny")
    # cells: a vertex per solid/gas particle, the membrane as lines in order
    verts = [ids for t, ids in cells if t == 1]
    lines = [ids for t, ids in cells if t == 3]
    if len(verts) != int(np.sum(~mem)):
        fail("vertex cells do not match the solid and gas particles")
    first = int(np.argmax(mem))
    if lines != [[first + i, first + i + 1] for i in range(nmem - 1)]:
        fail("the membrane is not one line per segment in curve order")

    # the grid: nodes, quads, and the last step's nodal values
    nx, ny, h = int(grid["nx"]), int(grid["ny"]), grid["h"]
    gpts, ga, gcells = read[gridf]
    nodes = (nx + 1) * (ny + 1)
    if gpts.shape[0] != nodes or len(gcells) != nx * ny:
        fail(f"grid: {gpts.shape[0]} nodes and {len(gcells)} cells, "
             f"expected {nodes} and {nx * ny}")
    ii, jj = np.arange(nodes) % (nx + 1), np.arange(nodes) // (nx + 1)
    close(gpts[:, 0], grid["x0"] + ii * h, "grid node x", 1e-15)
    close(gpts[:, 1], grid["y0"] + jj * h, "grid node y", 1e-15)
    for c, (t, ids) in enumerate(gcells):
        a, j = c % nx, c // nx
        n0 = j * (nx + 1) + a
        if t != 9 or ids != [n0, n0 + 1, n0 + nx + 2, n0 + nx + 1]:
            fail(f"grid cell {c} is type {t} over {ids}, not the quad of cell ({a}, {j})")
    m, p = grid_reference(pre, ref, h, nx, ny)
    close(ga["mass"], m, "grid mass (sum m_p N_i, computed here)")
    close(ga["mass"].sum(), ref[:, 9].sum(), "grid mass = particle mass")
    inner = (ii > 0) & (ii < nx) & (jj > 0) & (jj < ny) & (m > 0)
    close(ga["velocity"][inner, :2], p[inner] / m[inner, None],
          "interior grid velocity (sum m_p v_p N_i / m_i, computed here)")
    wall = ~((ii > 0) & (ii < nx) & (jj > 0) & (jj < ny))
    close(ga["velocity"][wall], np.zeros_like(ga["velocity"][wall]), "fixed walls' velocity", 0)
    print(f"vtk_check: {len(sets)} files read by VTK and meshio alike; {n} particles, "
          f"{nmem} membrane points, {nodes} nodes ({int(inner.sum())} interior), "
          f"{len(times)} times: every value read back equals lamina's and the grid "
          f"equals the particle-to-grid map computed here")


if __name__ == "__main__":   # vtk3_check.py imports the helpers
    main()
