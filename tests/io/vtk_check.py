"""Reads sim:vtk's files back (issue 20 item 1) and compares them with the
values lamina printed (tests/io/vtk_export.lua): the particles' .vtu with
meshio, an independent reader; the .vti and .pvd, which meshio does not
read, with Python's own XML parser and numpy (not lamina's code).

usage: vtk_check.py REF_FILE PREFIX"""
import sys
import xml.etree.ElementTree as ET

import meshio
import numpy as np


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


def appended_arrays(path):
    """{name: array} of a raw-appended VTK XML file (UInt64 headers)."""
    raw = open(path, "rb").read()
    start = raw.index(b"<AppendedData")
    start = raw.index(b"_", start) + 1
    head = raw[:raw.index(b"<AppendedData")].decode() + "</VTKFile>"
    for tag in ("</Piece>", "</ImageData>"):
        if tag not in head:
            head = head.replace("</VTKFile>", tag + "</VTKFile>")
    root = ET.fromstring(head)
    out = {}
    types = {"Float64": "<f8", "Int64": "<i8", "UInt8": "u1"}
    for da in root.iter("DataArray"):
        off = start + int(da.get("offset"))
        n = int(np.frombuffer(raw[off:off + 8], "<u8")[0])
        a = np.frombuffer(raw[off + 8:off + 8 + n], types[da.get("type")])
        k = int(da.get("NumberOfComponents", "1"))
        out[da.get("Name")] = a.reshape(-1, k) if k > 1 else a
    return root, out


def main():
    ref_file, prefix = sys.argv[1], sys.argv[2]
    ref, t_end, nmem = [], None, None
    for line in open(ref_file):
        w = line.split()
        if w and w[0] == "REF":
            ref.append([float(x) for x in w[1:]])
        elif w and w[0] == "META":
            t_end, nmem = float(w[2]), int(w[4])
    ref = np.array(ref)
    if ref.size == 0:
        fail("no REF lines")
    # the collection: four times, particles and grid at each
    pvd = ET.parse(prefix + ".pvd").getroot()
    sets = pvd.findall("./Collection/DataSet")
    times = sorted({float(d.get("timestep")) for d in sets})
    close(times, [0.0, 0.001, 0.002, 0.003], "pvd times", 1e-9)
    if len(sets) != 8:
        fail(f"pvd lists {len(sets)} datasets, expected 8")
    last = [d.get("file") for d in sets if float(d.get("timestep")) == times[-1]]
    close(times[-1], t_end, "last time", 1e-12)
    folder = prefix.rsplit("/", 1)[0] + "/" if "/" in prefix else ""
    vtu = [f for f in last if f.endswith(".vtu")][0]
    vti = [f for f in last if f.endswith(".vti")][0]

    mesh = meshio.read(folder + vtu)
    n = len(ref)
    if mesh.points.shape[0] != n:
        fail(f"{mesh.points.shape[0]} points, lamina has {n}")
    close(mesh.points[:, 0], ref[:, 1], "x")
    close(mesh.points[:, 1], ref[:, 2], "y")
    pd = mesh.point_data
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
    cells = {c.type: c.data for c in mesh.cells}
    if len(cells.get("vertex", [])) != int(np.sum(~mem)):
        fail("vertex cells do not match the solid and gas particles")
    lines = cells.get("line")
    if lines is None or len(lines) != nmem - 1:
        fail("the membrane is not one line per segment")
    first = int(np.argmax(mem))
    expect = np.array([[first + i, first + i + 1] for i in range(nmem - 1)])
    if not np.array_equal(lines, expect):
        fail("membrane lines are not in curve order")

    root, arrays = appended_arrays(folder + vti)
    ext = [int(x) for x in root.find("ImageData").get("WholeExtent").split()]
    nodes = (ext[1] + 1) * (ext[3] + 1)
    if arrays["mass"].shape[0] != nodes:
        fail("grid mass has the wrong node count")
    close(arrays["mass"].sum(), ref[:, 9].sum(), "grid mass = particle mass", 1e-12)
    print(f"vtk_check: {n} particles, {nmem} membrane points, {nodes} nodes, "
          f"{len(times)} times: every value read back equals lamina's")


main()
