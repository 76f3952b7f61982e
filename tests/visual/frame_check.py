#!/usr/bin/env python3
"""frame_check.py LAMINA SCENES RESTART WORK - sim:frame's displacement exaggeration,
tension colour bar and pressure colours, read back from the pixels (issue 35
item 4; docs/api.md "sim:frame").

Runs SCENES (tests/visual/frame_scenes.lua) with LAMINA under WORK, reads
the "fact NAME VALUE" lines it prints and the PNGs it writes (a small PNG
reader below: 8-bit RGB / RGBA, the only kinds lamina writes), and checks:

1. scale = 100: the string's middle, displaced by a (the run's own value,
   0.2 % of its length), is drawn k a P pixels away from where it was
   drawn before the run, P the pixels per length measured on the frame
   itself; without scale it moves a P (under a pixel: a straight line).
   The frames' Title text says "displacements x 100".
2. colour = "tension" with the automatic range draws the same pixels as
   with range = {-sigma t, sigma t} (sigma the string's hoop stress, t its
   thickness, from the run), and other pixels than range = {-sigma, sigma}.
3. colour = "pressure": gas at p = 10 is far from white (the pale end of
   the diverging map it used to be on), the membrane keeps its body colour;
   the old drawing (every body, diverging map) fails the same test.
4. RESTART (tests/visual/frame_restart.lua) run whole, then again with
   --restart from its checkpoint half way: the scale = 100 frames at the
   end are the same pixels (the references are the script's build, not
   the checkpoint's state: captured after the restore instead, 1293
   pixels differed).

Prints one line per check; exit 1 on any failure.
"""
import os
import shutil
import struct
import subprocess
import sys
import zlib

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
FAILED = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        FAILED.append(what)


def read_png(path):
    """(width, height, rows of (r, g, b) tuples, text chunks)"""
    with open(path, "rb") as f:
        data = f.read()
    if not data.startswith(PNG_MAGIC):
        raise ValueError(f"{path}: not a PNG")
    at, idat, text = len(PNG_MAGIC), [], {}
    width = height = ctype = None
    while at + 8 <= len(data):
        (length,) = struct.unpack(">I", data[at:at + 4])
        kind = data[at + 4:at + 8]
        body = data[at + 8:at + 8 + length]
        at += 12 + length
        if kind == b"IHDR":
            width, height, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or ctype not in (2, 6) or interlace:
                raise ValueError(f"{path}: not 8-bit RGB / RGBA, non-interlaced")
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"tEXt":
            key, _, value = body.partition(b"\0")
            text[key.decode("latin-1")] = value.decode("latin-1")
    bpp = 3 if ctype == 2 else 4
    raw = zlib.decompress(b"".join(idat))
    stride = width * bpp
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(height):
        ftype, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if ftype == 1:
                line[x] = (line[x] + a) & 255
            elif ftype == 2:
                line[x] = (line[x] + b) & 255
            elif ftype == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif ftype == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[x] = (line[x] + pred) & 255
        rows.append([tuple(line[x:x + 3]) for x in range(0, stride, bpp)])
        prev = line
    return width, height, rows, text


def saturated(px):
    """a body's or a colour map's ink: neither the white / grey ground nor
    the title's dark grey text"""
    return max(px) - min(px) > 60


def ink(rows):
    return [(x, y) for y, row in enumerate(rows) for x, px in enumerate(row) if saturated(px)]


def middle_y(pts, xc, half):
    ys = [y for x, y in pts if abs(x - xc) <= half]
    return sum(ys) / len(ys) if ys else float("nan")


def scale_checks(work, facts):
    k, a = 100.0, facts["amplitude"]
    check(abs(a / facts["length"] - 0.002) < 0.0002,
          f"the string rings at {100 * a / facts['length']:.4f} % of its length (0.2 % asked)")
    _, _, r0, _ = read_png(os.path.join(work, "s0_k100.png"))
    _, _, r1, t1 = read_png(os.path.join(work, "s1_k100.png"))
    _, _, r0p, t0p = read_png(os.path.join(work, "s0_k1.png"))
    _, _, r1p, _ = read_png(os.path.join(work, "s1_k1.png"))
    _, _, _, tt = read_png(os.path.join(work, "s1_titled.png"))
    p0 = ink(r0)
    xs = [x for x, _ in p0]
    x0, x1 = min(xs), max(xs)
    xc = 0.5 * (x0 + x1)
    # the line's thickness at the middle before the run: a disc's diameter,
    # taken off the inked width to get the end points' distance in pixels
    mid = [y for x, y in p0 if abs(x - xc) <= 3]
    diam = max(mid) - min(mid) + 1
    ppl = (x1 - x0 + 1 - diam) / (facts["x_last"] - facts["x_first"])
    d100 = middle_y(p0, xc, 6) - middle_y(ink(r1), xc, 6)    # pixel y grows downwards
    want = k * a * ppl
    check(abs(d100 - want) <= 1.5,
          f"scale = 100: the middle moved {d100:.2f} px; k a P = 100 x {a:.4g} x {ppl:.2f} px = "
          f"{want:.2f} px (tolerance 1.5 px: the discs' centres)")
    p0p = ink(r0p)
    xsp = [x for x, _ in p0p]
    xcp = 0.5 * (min(xsp) + max(xsp))
    d1 = middle_y(p0p, xcp, 6) - middle_y(ink(r1p), xcp, 6)
    check(abs(d1 - a * ppl) <= 1.0 and abs(d1) < 2.0,
          f"scale = 1: the middle moved {d1:.2f} px (a P = {a * ppl:.2f} px): a straight line")
    check(t1.get("Title") == "displacements x 100",
          f"scale = 100: Title is {t1.get('Title')!r} (want 'displacements x 100')")
    check(tt.get("Title") == "string - displacements x 100",
          f"scale = 100 with a title: Title is {tt.get('Title')!r}")
    check(t0p.get("Title") == "plain", f"scale = 1: Title is {t0p.get('Title')!r} (no suffix)")


def differing(ra, rb, level=2):
    return sum(1 for a, b in zip(ra, rb) for pa, pb in zip(a, b)
               if max(abs(u - v) for u, v in zip(pa, pb)) > level)


def tension_checks(work, facts):
    st = facts["sigma"] * facts["thickness"]
    _, _, auto, _ = read_png(os.path.join(work, "tension_auto.png"))
    _, _, sigt, _ = read_png(os.path.join(work, "tension_sigma_t.png"))
    _, _, sig, _ = read_png(os.path.join(work, "tension_sigma.png"))
    n = differing(auto, sigt)
    check(n == 0, f"tension, automatic range: {n} pixels differ from range = +-sigma t = "
                  f"+-{st:.6g} (sigma {facts['sigma']:.6g} x t {facts['thickness']:g}, the run's)")
    m = differing(auto, sig)
    check(m > 100, f"tension, automatic range: {m} pixels differ from range = +-sigma = "
                   f"+-{facts['sigma']:.6g} (the stress's range: must differ)")


def pressure_checks(work, facts):
    _, _, body, _ = read_png(os.path.join(work, "gas_body.png"))
    _, _, pres, _ = read_png(os.path.join(work, "gas_pressure.png"))
    _, _, old, _ = read_png(os.path.join(work, "gas_pressure_old.png"))
    counts = {}
    for row in body:
        for px in row:
            if saturated(px):
                counts[px] = counts.get(px, 0) + 1
    (gas, _), (skin, _) = sorted(counts.items(), key=lambda kv: -kv[1])[:2]
    at_gas = [(x, y) for y, row in enumerate(body) for x, px in enumerate(row) if px == gas]
    at_skin = [(x, y) for y, row in enumerate(body) for x, px in enumerate(row) if px == skin]

    def deficit(rows):   # how far from white: 0 white, 765 black
        return sum(765 - sum(rows[y][x]) for x, y in at_gas) / len(at_gas)

    dp, do = deficit(pres), deficit(old)
    check(facts["gas_pressure"] > 9.99 and facts["gas_pressure"] < 10.01,
          f"the gas is at p = {facts['gas_pressure']:.6g}")
    check(dp >= 150, f"pressure: the gas's colour is {dp:.0f} below white (>= 150: not pale)")
    check(sum(1 for x, y in at_gas if pres[y][x] == gas) == 0,
          "pressure: the gas is coloured by its pressure, not in its body colour")
    kept = sum(1 for x, y in at_skin if pres[y][x] == skin) / len(at_skin)
    check(kept >= 0.95, f"pressure: {100 * kept:.1f} % of the membrane's pixels keep its body "
                        f"colour (stress {facts['membrane_stress']:.4g}, not on the gas's scale)")
    check(do < 150, f"negative control (every body, diverging map): the gas is {do:.0f} below "
                    f"white (< 150: pale, as issue 35 found)")


def run_script(lamina, script, work, out, *extra):
    run = subprocess.run([lamina, "run", script, "--quiet", "--out-root", work,
                          "--set", "out=" + out, *extra], capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout + run.stderr)
        print(f"FAIL  {script} exited with status {run.returncode}")
        sys.exit(1)
    return run


def restart_checks(lamina, script, work):
    first, again = os.path.join(work, "restart_first"), os.path.join(work, "restart_again")
    run_script(lamina, script, work, first)
    run_script(lamina, script, work, again, "--restart", os.path.join(first, "half.ckpt"))
    _, _, ra, ta = read_png(os.path.join(first, "end.png"))
    _, _, rb, tb = read_png(os.path.join(again, "end.png"))
    n = differing(ra, rb)
    check(n == 0 and ta.get("Title") == tb.get("Title") == "displacements x 100",
          f"scale = 100 after --restart: {n} pixels differ from the whole run's frame")


def main():
    lamina, scenes, restart, work = sys.argv[1:5]
    if os.path.isdir(work):
        shutil.rmtree(work)
    os.makedirs(work)
    out = os.path.join(work, "out")
    run = run_script(lamina, scenes, work, out)
    facts = {}
    for line in run.stdout.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[0] == "fact":
            facts[parts[1]] = float(parts[2])
    scale_checks(out, facts)
    tension_checks(out, facts)
    pressure_checks(out, facts)
    restart_checks(lamina, restart, work)
    print(f"frame_check: {len(FAILED)} failed")
    return 1 if FAILED else 0


if __name__ == "__main__":
    sys.exit(main())
