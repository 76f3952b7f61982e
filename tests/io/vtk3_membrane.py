"""Reads back the membranes' pieces sim:vtk wrote for a 3D run
(tests/io/vtk3_membrane.lua) with VTK's XML reader (python3-vtk9) and meshio
(python3-meshio), as vtk3_check.py does for the particles: both readers
must agree on every piece the .pvd lists (three parts an output: particles,
grid, membranes); the last membranes' piece must equal lamina's MREF lines
(points, velocity, normal, tension, area, mass, membrane number), its
tension tensor must be the frame's (trace t11 + t22, the normal its null
vector, the invariant t11 t22 - t12^2 in the plane: computed here), the
tangents orthonormal and t1 x t2 = +-normal, and `pinned` must mark the
sheet's outer ring (the pinned points stand still: zero velocity).

usage: vtk3_membrane.py REF_FILE PREFIX"""
import sys
import xml.etree.ElementTree as ET

import numpy as np
from vtk3_check import read_both
from vtk_check import close, fail


def main():
    ref_file, prefix = sys.argv[1], sys.argv[2]
    ref, t_end = [], None
    for line in open(ref_file):
        w = line.split()
        if w and w[0] == "MREF":
            ref.append([float(x) for x in w[1:]])
        elif w and w[0] == "META":
            t_end = float(w[2])
    ref = np.array(ref)
    if ref.size == 0:
        fail("no MREF lines")
    sets = ET.parse(prefix + ".pvd").getroot().findall("./Collection/DataSet")
    times = sorted({float(d.get("timestep")) for d in sets})
    close(times, [0.0, 0.001, 0.002], "pvd times", 1e-9)
    close(times[-1], t_end, "last time", 1e-12)
    parts = sorted(d.get("part") for d in sets)
    if parts != ["0"] * 3 + ["1"] * 3 + ["2"] * 3:
        fail(f"pvd parts {parts}: expected particles, grid and membranes at each of 3 times")
    folder = prefix.rsplit("/", 1)[0] + "/" if "/" in prefix else ""
    read = {d.get("file"): read_both(folder + d.get("file")) for d in sets}
    last = [d.get("file") for d in sets
            if float(d.get("timestep")) == times[-1] and d.get("part") == "2"][0]
    if "_membranes_" not in last:
        fail(f"the membranes' piece is {last}")
    pts, pd, cells = read[last]
    n = len(ref)
    if pts.shape != (n, 3) or len(cells) != n or any(c[0] != 1 for c in cells):
        fail(f"points {pts.shape}, {len(cells)} cells: lamina has {n} membrane points as vertices")
    close(pts, ref[:, 1:4], "x, y, z")
    close(pd["velocity"], ref[:, 4:7], "velocity")
    close(pd["normal"], ref[:, 7:10], "normal")
    close(pd["tension"], ref[:, 10], "tension")
    close(pd["area"], ref[:, 11], "area")
    close(pd["mass"], ref[:, 12], "mass")
    close(pd["membrane"], ref[:, 0], "membrane")
    t11, t22, t12 = ref[:, 13], ref[:, 14], ref[:, 15]
    close((t11 + t22) / 2, ref[:, 10], "tension = (t11 + t22) / 2 (lamina's own columns)")
    T = pd["tension_tensor"]   # XX YY ZZ XY YZ XZ
    M = np.stack([np.stack([T[:, 0], T[:, 3], T[:, 5]], 1),
                  np.stack([T[:, 3], T[:, 1], T[:, 4]], 1),
                  np.stack([T[:, 5], T[:, 4], T[:, 2]], 1)], 1)
    close(np.trace(M, axis1=1, axis2=2), t11 + t22, "trace of the tension tensor")
    t1, t2 = pd["t1"], pd["t2"]
    close(np.einsum("qi,qi->q", t1, t1), np.ones(n), "|t1|")
    close(np.einsum("qi,qi->q", t2, t2), np.ones(n), "|t2|")
    close(np.einsum("qi,qi->q", t1, t2), np.zeros(n), "t1 . t2")
    # the tensor in the frame: t_a . M t_b
    close(np.einsum("qi,qij,qj->q", t1, M, t1), t11, "t1 . T t1 = t11")
    close(np.einsum("qi,qij,qj->q", t2, M, t2), t22, "t2 . T t2 = t22")
    close(np.einsum("qi,qij,qj->q", t1, M, t2), t12, "t1 . T t2 = t12")
    nf = np.cross(t1, t2)
    close(np.einsum("qij,qj->qi", M, nf), np.zeros((n, 3)), "T (t1 x t2) = 0")
    # the sheet's normals are its frame's (connectivity); the balloon's the
    # construction's, within a few degrees of the frame's
    sheet, balloon = ref[:, 0] == 2, ref[:, 0] == 1
    close(nf[sheet], ref[sheet, 7:10], "the sheet's normal = t1 x t2")
    cosang = np.einsum("qi,qi->q", nf[balloon], ref[balloon, 7:10])
    if cosang.min() < np.cos(np.radians(10)):
        fail(f"a balloon normal {np.degrees(np.arccos(cosang.min())):.3g} deg off its frame's")
    pinned = pd["pinned"] == 1
    if not pinned.any() or pinned[balloon].any():
        fail("pinned: the sheet's edge points only")
    close(pd["velocity"][pinned], np.zeros((pinned.sum(), 3)), "pinned points at rest", 0)
    print(f"vtk3_membrane: {n} membrane points ({balloon.sum()} balloon, {sheet.sum()} sheet, "
          f"{pinned.sum()} pinned) read back by VTK and meshio; fields equal lamina's; the "
          f"tension tensor the frame's (worst balloon normal vs frame "
          f"{np.degrees(np.arccos(min(1.0, cosang.min()))):.3g} deg)")


if __name__ == "__main__":
    main()
