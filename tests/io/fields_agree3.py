"""One pressure in 3D (issue 34 item 1): reads what tests/io/fields_agree3.lua
wrote - its P lines (body:particles()), the particles' .vtu (through VTK's
own XML reader, not lamina's code) and the frame's lamina:range text chunk
(its colour bar's ends) - and checks that they give the same pressure, the
definition computed here from the particles' state: a gas particle's
(gamma - 1) rho e, a solid's -(sxx + syy + szz) / 3; and that the scene
tells the two apart (the gas's mean stress holds q > 0).

usage: fields_agree3.py REF_FILE OUT_DIR"""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from png_text import png_texts  # noqa: E402
from agree_checks import checks  # noqa: E402


fail, same = checks("fields_agree3")


def main():
    ref_file, out = sys.argv[1], sys.argv[2]
    rows = [[float(x) for x in line.split()[1:]] for line in open(ref_file)
            if line.startswith("P ")]
    if not rows:
        fail("no P lines")
    P = np.array(rows)
    body, pressure, p_alias = P[:, 0], P[:, 1], P[:, 2]
    sxx, syy, szz, rho, e, gamma = P[:, 3], P[:, 4], P[:, 5], P[:, 6], P[:, 7], P[:, 8]
    gas, ball = body == 1, body == 2
    eos = (gamma - 1) * rho * e
    mean = -(sxx + syy + szz) / 3
    same(pressure[gas], eos[gas], "particles().pressure of the gas = (gamma - 1) rho e")
    same(p_alias[gas], pressure[gas], "particles().p = particles().pressure", 0)
    worst = float(np.max(np.abs(mean[gas] - eos[gas])))
    if not worst > 0.05 * float(np.max(eos[gas])):
        fail(f"the scene does not tell the definitions apart (|mean stress - eos| {worst:g})")
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(os.path.join(out, "run_000000.vtu"))
    r.Update()
    vp = vtk_to_numpy(r.GetOutput().GetPointData().GetArray("pressure"))
    ref = np.where(gas, eos, mean)
    same(vp, ref, "VTK pressure = the gas's (gamma - 1) rho e, the ball's -tr sigma / 3")
    t = png_texts(os.path.join(out, "pressure.png")).get("lamina:range")
    if t is None:
        fail("pressure.png has no lamina:range")
    lo, hi = (float(x) for x in t.split())
    print(f"fields_agree3: frame range {lo:.9g} {hi:.9g}; particles' pressure "
          f"{ref.min():.9g}..{ref.max():.9g}; gas (gamma - 1) rho e {eos[gas].min():.9g}.."
          f"{eos[gas].max():.9g}, its mean stress differs by up to {worst:.6g}")
    same([lo, hi], [ref.min(), ref.max()], "frame colour-bar range = min, max of the pressure")
    print(f"fields_agree3: {int(gas.sum())} gas and {int(ball.sum())} ball particles: "
          "particles(), VTK and the frame's colour bar agree")


main()
