"""Reads back every file sim:vtk wrote for a 3D run (tests/io/vtk3_export.lua)
through two readers that are not lamina's, VTK's XML reader (python3-vtk9)
and meshio (python3-meshio), as tests/io/vtk_check.py does for 2D: both must
read the same values; the last output's particles must equal lamina's REF
lines (points with three components, velocity, the symmetric stress in VTK's
order XX YY ZZ XY YZ XZ, pressure -tr/3, density, mass, body), and its grid
(hexahedra over the nodes 0..n) the nodal mass sum_p m_p N_i(x_p) and, at
interior nodes, MUSL's re-mapped velocity sum_p m_p v_p N_i / m_i computed
here with the trilinear hats from the PRE lines; the fixed faces' nodes 0.

usage: vtk3_check.py REF_FILE PREFIX"""
import sys
import xml.etree.ElementTree as ET

import numpy as np
# the 2D check's helpers (the same script's folder is on sys.path)
from vtk_check import close, fail
from vtk_check import read_both as vtk_check_read_both

MESHIO_TYPES = {"vertex": 1, "hexahedron": 12}


def read_both(path):
    """vtk_check.read_both with the 3D cell types."""
    return vtk_check_read_both(path, MESHIO_TYPES)


def main():
    ref_file, prefix = sys.argv[1], sys.argv[2]
    ref, pre, grid, t_end = [], [], None, None
    for line in open(ref_file):
        w = line.split()
        if w and w[0] == "REF":
            ref.append([float(x) for x in w[1:]])
        elif w and w[0] == "PRE":
            pre.append([float(x) for x in w[1:]])
        elif w and w[0] == "META":
            t_end = float(w[2])
        elif w and w[0] == "GRID":
            grid = dict(zip(w[1::2], (float(x) for x in w[2::2])))
    ref, pre = np.array(ref), np.array(pre)
    if ref.size == 0 or pre.shape[0] != ref.shape[0] or grid is None:
        fail("no REF, PRE or GRID lines")
    sets = ET.parse(prefix + ".pvd").getroot().findall("./Collection/DataSet")
    times = sorted({float(d.get("timestep")) for d in sets})
    close(times, [0.0, 0.001, 0.002, 0.003], "pvd times", 1e-9)
    close(times[-1], t_end, "last time", 1e-12)
    if len(sets) != 8:
        fail(f"pvd lists {len(sets)} datasets, expected 8")
    folder = prefix.rsplit("/", 1)[0] + "/" if "/" in prefix else ""
    read = {d.get("file"): read_both(folder + d.get("file")) for d in sets}
    last = [d for d in sets if float(d.get("timestep")) == times[-1]]
    vtu = [d.get("file") for d in last if d.get("part") == "0"][0]
    gridf = [d.get("file") for d in last if d.get("part") == "1"][0]

    pts, pd, cells = read[vtu]
    n = len(ref)
    if pts.shape != (n, 3):
        fail(f"points {pts.shape}, lamina has {n} particles")
    close(pts, ref[:, 1:4], "x, y, z")
    close(pd["velocity"], ref[:, 4:7], "velocity")
    sxx, syy, szz, syz, sxz, sxy = (ref[:, 7 + k] for k in range(6))
    close(pd["stress"], np.stack([sxx, syy, szz, sxy, syz, sxz], axis=1), "stress (VTK order)")
    close(pd["pressure"], -(sxx + syy + szz) / 3, "pressure")
    close(pd["density"], ref[:, 13], "density")
    close(pd["mass"], ref[:, 14], "mass")
    close(pd["body"], ref[:, 0], "body")
    if sorted(ids[0] for t, ids in cells if t == 1) != list(range(n)):
        fail("not one vertex cell per particle")
    # three distinct shears (the ball's velocity field): a mistake in the
    # tensor's order would show
    shear = np.abs(np.stack([sxy, syz, sxz])).max(axis=1)
    if min(shear) == 0 or len({f"{v:.3g}" for v in shear}) < 3:
        fail(f"the shears are not distinct ({shear}): the order check would be blind")

    nx, ny, nz, h = int(grid["nx"]), int(grid["ny"]), int(grid["nz"]), grid["h"]
    gpts, ga, gcells = read[gridf]
    nodes = (nx + 1) * (ny + 1) * (nz + 1)
    if gpts.shape[0] != nodes or len(gcells) != nx * ny * nz:
        fail(f"grid: {gpts.shape[0]} nodes, {len(gcells)} cells")
    idx = np.arange(nodes)
    ii, jj, kk = idx % (nx + 1), idx // (nx + 1) % (ny + 1), idx // ((nx + 1) * (ny + 1))
    close(gpts, np.stack([ii * h, jj * h, kk * h], axis=1), "grid nodes", 1e-15)
    sx, sxy_ = nx + 1, (nx + 1) * (ny + 1)
    for c, (t, ids) in enumerate(gcells):
        a, b, k = c % nx, c // nx % ny, c // (nx * ny)
        n0 = k * sxy_ + b * sx + a
        bottom = [n0, n0 + 1, n0 + 1 + sx, n0 + sx]
        if t != 12 or ids != bottom + [q + sxy_ for q in bottom]:
            fail(f"grid cell {c} is type {t} over {ids}, not the hexahedron of ({a}, {b}, {k})")
    m, p = np.zeros(nodes), np.zeros((nodes, 3))
    for (x, y, z, mp), v in zip(pre[:, 1:5], ref[:, 4:7]):
        i, j, k = int(x // h), int(y // h), int(z // h)
        f = (x / h - i, y / h - j, z / h - k)
        for da in (0, 1):
            for db in (0, 1):
                for dc in (0, 1):
                    w = ((f[0] if da else 1 - f[0]) * (f[1] if db else 1 - f[1])
                         * (f[2] if dc else 1 - f[2]))
                    q = (k + dc) * sxy_ + (j + db) * sx + i + da
                    m[q] += mp * w
                    p[q] += mp * w * v
    close(ga["mass"], m, "grid mass (sum m_p N_i, computed here)")
    inner = (ii > 0) & (ii < nx) & (jj > 0) & (jj < ny) & (kk > 0) & (kk < nz) & (m > 0)
    close(ga["velocity"][inner], p[inner] / m[inner, None], "interior grid velocity")
    wall = ~((ii > 0) & (ii < nx) & (jj > 0) & (jj < ny) & (kk > 0) & (kk < nz))
    close(ga["velocity"][wall], np.zeros_like(ga["velocity"][wall]), "fixed faces' velocity", 0)
    print(f"vtk3_check: {len(sets)} files read by VTK and meshio alike; {n} particles, "
          f"{nodes} nodes ({int(inner.sum())} interior with mass), {len(times)} times: every "
          f"value read back equals lamina's and the grid the trilinear map computed here")


if __name__ == "__main__":   # vtk3_membrane.py imports read_both
    main()
