#!/usr/bin/env python3
"""Issue 31 item 3: a checkpoint is untrusted input. 16 of 343 mutated
checkpoints crashed the release build (body and material indices unchecked,
first + count wrapping), t or dt = 1e300 hung, NaN ended the run half-way
with status 0, a checkpoint of another scene (a disk of radius 0.2 restarted
in a script with 0.1) was accepted, a FIFO blocked.

This writes the checkpoint of tests/security/scripts/ck_scene.lua, then one
mutation per field a reader must check, and restarts from each: every one
must be refused with exit status 2 and a message naming what is wrong,
within the timeout. The unmutated checkpoint must restart to the same hash
as the uninterrupted run.

usage: checkpoint_untrusted.py LAMINA SCENE_SCRIPT   (run in build/tests)
"""
import math
import os
import struct
import subprocess
import sys

lamina, scene = sys.argv[1], sys.argv[2]
out = "out/security/ck_untrusted"
os.makedirs(out, exist_ok=True)
ck = out + "/good.ck"


def run(args, timeout=60):
    p = subprocess.run([lamina, "run", scene] + args, capture_output=True, text=True,
                       timeout=timeout)
    return p.returncode, p.stdout, p.stderr


st, whole, err = run(["--set", "ck=" + ck])
assert st == 0, err
data = open(ck, "rb").read()
off = data.index(b"\n\n") + 2
head = dict(line.split(" ", 1) for line in data[:off - 2].decode().split("\n")[1:])
eb = int(head["engine"])
# the engine's header (checkpoint.c, struct header) and clock (clock_rec)
nmats, nbodies, npins = struct.unpack_from("<Iii", data, off + 12)
nlinks = struct.unpack_from("<i", data, off + 40)[0]
n = struct.unpack_from("<Q", data, off + 48)[0]
HEADER, CLOCK, BODY, PIN, LINK = 72, 88, 72, 32, 24
per_particle = 21 * 8 + 3 * 4
mat_size = (eb - HEADER - CLOCK - nbodies * BODY - npins * PIN - nlinks * LINK -
            n * per_particle) // nmats
clock = off + HEADER
mats = clock + CLOCK
bodies = mats + nmats * mat_size
doubles = bodies + nbodies * BODY + npins * PIN + nlinks * LINK
ints = doubles + 21 * 8 * n          # body[], then mat[], then pin[]
records = off + eb


def put(buf, fmt, at, *v):
    b = bytearray(buf)
    struct.pack_into(fmt, b, at, *v)
    return bytes(b)


mutations = [
    ("t = NaN", put(data, "<d", clock, math.nan), "clock is out of range"),
    ("t = 1e300", put(data, "<d", clock, 1e300), "clock is out of range"),
    ("dt = 1e300", put(data, "<d", clock + 16, 1e300), "clock is out of range"),
    ("dt = -1", put(data, "<d", clock + 16, -1.0), "clock is out of range"),
    ("step < 0", put(data, "<q", clock + 64, -5), "clock is out of range"),
    ("n = 2^62", put(data, "<Q", off + 48, 1 << 62), "damaged"),
    ("n + 1", put(data, "<Q", off + 48, n + 1), "damaged"),
    ("body first wraps", put(data, "<Q", bodies, (1 << 64) - 1), "lies outside"),
    ("body count + 1", put(data, "<Q", bodies + 8, struct.unpack_from("<Q", data, bodies + 8)[0] + 1),
     "particles; the script's has"),
    ("body material 99", put(data, "<i", bodies + 16, 99), "differs"),
    ("particle body 99", put(data, "<i", ints, 99), "particle 1 of body 1 says body 100"),
    ("particle material -7", put(data, "<i", ints + 4 * n, -7), "says body 1, material -6"),
    ("particle pin 1000", put(data, "<i", ints + 8 * n, 1000), "has pin 1000"),
    ("particle mass -1", put(data, "<d", doubles + 4 * 8 * n, -1.0), "has m = -1"),
    ("particle x inf", put(data, "<d", doubles, math.inf), "has x = inf"),
    ("particle y 1e10", put(data, "<d", doubles + 8 * n, 1e10), "has y = 1e+10, outside the domain"),
    ("material rho NaN", put(data, "<d", mats + 8, math.nan), "material 1: rho"),
    ("material kind", put(data, "<i", mats, 3), "material 1 is of another kind"),
    ("truncated", data[:len(data) - 100], "truncated"),
    ("one byte more", data + b"\0", "truncated or damaged"),
    ("engine size", data.replace(b"engine %d" % eb, b"engine %d" % (eb + 8), 1), "damaged"),
    ("record rows huge", put(data, "<Q", records + 4, 1 << 60), "truncated or damaged"),
    ("recorders 5", data.replace(b"recorders 1", b"recorders 5", 1), "truncated or damaged"),
    ("not a checkpoint", b"#!/bin/sh\necho hi\n", "is not a lamina checkpoint"),
]
fail = 0
for name, blob, want in mutations:
    path = "%s/%s.ck" % (out, name.replace(" ", "_").replace("^", ""))
    open(path, "wb").write(blob)
    st, so, se = run(["--restart", path, "--set", "ck=%s/again.ck" % out])
    if st != 2 or want not in se:
        print("FAIL: %s: status %d, stderr: %s" % (name, st, se.strip()[-400:]))
        fail = 1
    else:
        print("ok: %s: %s" % (name, se.strip().splitlines()[0][-160:]))
# another scene: the disk's radius differs
st, so, se = run(["--restart", ck, "--set", "r=0.2", "--set", "ck=%s/again.ck" % out])
if st != 2 or "has" not in se or "the script's has" not in se:
    print("FAIL: another scene: status %d: %s" % (st, se.strip()[-300:]))
    fail = 1
else:
    print("ok: another scene: " + se.strip().splitlines()[0][-160:])
# a FIFO is refused at once, not read for ever
fifo = out + "/fifo.ck"
if os.path.exists(fifo):
    os.unlink(fifo)
os.mkfifo(fifo)
try:
    st, so, se = run(["--restart", fifo, "--set", "ck=%s/again.ck" % out], timeout=20)
    if st != 2 or "not a regular file" not in se:
        print("FAIL: FIFO: status %d: %s" % (st, se.strip()[-300:]))
        fail = 1
    else:
        print("ok: FIFO refused")
except subprocess.TimeoutExpired:
    print("FAIL: --restart on a FIFO blocked")
    fail = 1
# the good checkpoint still restarts to the uninterrupted run's state
st, so, se = run(["--restart", ck, "--set", "ck=%s/again.ck" % out])
if st != 0 or so.strip() != whole.strip():
    print("FAIL: the restart differs: %s / %s %s" % (whole.strip(), so.strip(), se.strip()))
    fail = 1
else:
    print("ok: restart: " + so.strip())
sys.exit(fail)
