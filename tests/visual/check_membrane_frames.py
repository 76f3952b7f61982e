#!/usr/bin/env python3
"""check_membrane_frames.py SCRIPTS RUNS - every gallery page's membrane
frames show what the papers show (issue 32 item 1).

Lists the pages (SCRIPTS/*.lua) and reads every PNG their visual-size runs
wrote (RUNS/NAME/run/, left by the visual.paper.NAME tests). Each frame
sim:frame writes carries a `lamina:layers` text chunk,

    membranes=M with_phi=Q phi=P normals=N

(src/lua/l_frame.c): the membranes it showed, how many of them have a phi
(not colour-function normals), and how many were drawn with phi contours
and with normals. A frame with M > 0 must have P == Q and N == M - the
membrane's points, its phi = 1 contour and levels, and its normals ([N]
Figs 12-16). A page whose script makes a membrane and writes frames must
have at least one frame showing it, so that a chunk gone missing cannot
pass as "no membrane frames". Prints one line per page; exit 1 on any
failure.
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from png_text import png_texts  # noqa: E402


def layers(text):
    """'membranes=2 with_phi=2 phi=2 normals=2' -> dict of ints. A 3D
    frame's (src/lua/l_frame3d.c) 'dim=3 particles=N slices=S
    isosurfaces=I membrane_points=P normals=K membranes=M phi=F' becomes
    the 2D form: every 3D membrane has a phi (its construction's), its
    normals count when all its points carry them."""
    d = {}
    for item in text.split():
        k, _, v = item.partition("=")
        d[k] = int(v)
    if d.get("dim") == 3:
        if "membrane_points" not in d:
            return {"membranes": 0, "with_phi": 0, "phi": 0, "normals": 0}
        for k in ("membranes", "phi", "normals"):
            if k not in d:
                raise ValueError(f"lamina:layers '{text}' lacks {k}")
        m = d["membranes"]
        return {"membranes": m, "with_phi": m, "phi": d["phi"],
                "normals": m if d["normals"] == d["membrane_points"] else 0}
    for k in ("membranes", "with_phi", "phi", "normals"):
        if k not in d:
            raise ValueError(f"lamina:layers '{text}' lacks {k}")
    return d


def makes_membrane(script):
    """Whether a script builds a membrane: sim:membrane, or a helper that
    does (assets/lua: dogbone.setup, the airbag, ...), seen as the word
    'membrane' in code (not only in comments) together with sim:frame."""
    code = "\n".join(line.split("--", 1)[0] for line in script.splitlines())
    return re.search(r"membrane", code) is not None


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    scripts, runs = sys.argv[1], sys.argv[2]
    names = sorted(f[:-4] for f in os.listdir(scripts) if f.endswith(".lua"))
    failures = 0
    membrane_pages = 0
    for name in names:
        with open(os.path.join(scripts, name + ".lua"), encoding="utf-8") as f:
            script = f.read()
        frames_called = ":frame{" in script or ":frame {" in script
        run = os.path.join(runs, name, "run")
        if not os.path.isdir(run):
            print(f"{name}: FAIL: no run folder {run} (its visual.paper test did not run)")
            failures += 1
            continue
        frames = shown = good = 0
        bad = []
        for root, _, files in os.walk(run):
            for fn in sorted(files):
                if not fn.endswith(".png"):
                    continue
                path = os.path.join(root, fn)
                t = png_texts(path).get("lamina:layers")
                if t is None:
                    continue        # a plot or a figure, not sim:frame
                frames += 1
                d = layers(t)
                if d["membranes"] == 0:
                    continue
                shown += 1
                if d["phi"] == d["with_phi"] and d["normals"] == d["membranes"]:
                    good += 1
                else:
                    bad.append(f"{os.path.relpath(path, run)} ({t})")
        expect_membrane = frames_called and makes_membrane(script)
        if shown:
            membrane_pages += 1
        if bad:
            print(f"{name}: FAIL: {len(bad)} of {shown} membrane frames without phi or "
                  f"normals: {'; '.join(bad[:4])}")
            failures += 1
        elif expect_membrane and frames and not shown:
            # the word 'membrane' may name a membrane the frames do not
            # show (a plot of it only); said, not failed, when no frame
            # of the page shows one
            print(f"{name}: {frames} frames, none shows a membrane")
        else:
            print(f"{name}: {frames} frames, {shown} with membranes, "
                  f"{good} showing phi and normals" + (" ok" if shown else ""))
    print(f"{membrane_pages} pages with membrane frames; {failures} failing")
    return 1 if failures or membrane_pages == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
