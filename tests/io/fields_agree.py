"""One pressure everywhere (issue 33 item 2): reads what
tests/io/fields_agree.lua wrote - its P lines (body:particles()), the
particles' .vtu (through VTK's own XML reader, not lamina's code), the two
frames' lamina:range text chunks (each coloured panel's colour-bar ends) -
and checks that they give the same pressure, and that it is the table's
definition computed here from the particles' state: a gas particle's
(gamma - 1) rho e, a solid's -(sxx + syy + szz) / 3. The gas has q > 0, so
the mean stress (the frame's pressure before issue 33) differs from its
pressure: that is checked too, so the test would fail on the old frames.

usage: fields_agree.py REF_FILE OUT_DIR"""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from png_text import png_texts  # noqa: E402
from agree_checks import checks  # noqa: E402


fail, same = checks("fields_agree")


def main():
    ref_file, out = sys.argv[1], sys.argv[2]
    rows, rec, meta = [], None, None
    for line in open(ref_file):
        w = line.split()
        if w and w[0] == "P":
            rows.append([float(x) for x in w[1:]])
        elif w and w[0] == "REC":
            rec = [float(x) for x in w[1:]]
        elif w and w[0] == "META":
            meta = float(w[2]), float(w[4])
    if not rows or rec is None or meta is None:
        fail("no P, REC or META lines")
    P = np.array(rows)
    body, idx, pressure, p_alias = P[:, 0], P[:, 1], P[:, 2], P[:, 3]
    sxx, syy, szz, rho, e, q, gamma = P[:, 4], P[:, 5], P[:, 6], P[:, 7], P[:, 8], P[:, 9], P[:, 10]
    gas, disk = body == 1, body == 2
    # the definition, computed here
    eos = (gamma - 1) * rho * e
    mean = -(sxx + syy + szz) / 3
    same(pressure[gas], eos[gas], "particles().pressure of the gas = (gamma - 1) rho e")
    same(pressure[disk], mean[disk], "particles().pressure of the disk = -tr sigma / 3")
    same(p_alias, pressure, "particles().p = particles().pressure", 0)
    # the case is one where the two differ (q > 0): the old frame's pressure
    # was the mean stress of the gas too
    worst = float(np.max(np.abs(mean[gas] - eos[gas])))
    if not (np.max(q[gas]) > 0 and worst > 0.05 * float(np.max(eos[gas]))):
        fail(f"the scene does not tell the definitions apart (max q {np.max(q[gas]):g}, "
             f"|mean stress - eos| {worst:g})")
    # sim:vtk, read by VTK: the particles in body order
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(os.path.join(out, "run_000000.vtu"))
    r.Update()
    pd = r.GetOutput().GetPointData()
    vp = vtk_to_numpy(pd.GetArray("pressure"))
    same(vp, pressure, "VTK pressure = particles().pressure", 0)
    # the frames' colour-bar ranges: the gas alone (colour = "pressure"
    # colours the fluid bodies), then the disk alone (colour_bodies)
    for png, sel in (("pressure.png", gas), ("disk_pressure.png", disk)):
        t = png_texts(os.path.join(out, png)).get("lamina:range")
        if t is None:
            fail(f"{png} has no lamina:range")
        lo, hi = (float(x) for x in t.split())
        same([lo, hi], [pressure[sel].min(), pressure[sel].max()],
             f"{png}: colour-bar range = min, max of particles().pressure", 0)
    # the recorder's field columns at the end of the run
    t_end, rec_t = meta
    if rec_t != t_end:
        fail(f"the recorder's last row is at t = {rec_t}, not {t_end}")
    same([rec[0]], pressure[gas & (idx == 7)], "recorder fields.p_gas = particles().pressure[7]", 0)
    same([rec[1]], szz[disk & (idx == 3)], "recorder fields.szz_disk = particles().szz[3]", 0)
    print(f"fields_agree: {int(gas.sum())} gas and {int(disk.sum())} disk particles: "
          f"particles(), VTK, both frames' colour bars and the recorder agree "
          f"(gas pressure {eos[gas].min():.6g}..{eos[gas].max():.6g}; its mean stress "
          f"differs by up to {worst:.6g}, max q {np.max(q[gas]):.6g})")


main()
