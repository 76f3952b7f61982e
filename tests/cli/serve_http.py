"""serve_http.py LAMINA SRCDIR - `lamina serve` over HTTP (issue 35 item 1),
standard library only: the page, the JSON, frames, the controls through the
run log, every refusal (400, 403, 404, 405, 413), bounded connections, and
the server's end: SIGTERM (records written, 143) and the run's own end."""
import json
import os
import signal
import socket
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from serve_lib import Server, check, finish, wait_until  # noqa: E402

LAMINA, SRC = sys.argv[1], sys.argv[2]
SCENE = os.path.join(SRC, "serve_scene.lua")
W = os.path.join(os.getcwd(), "serve_http")

s = Server(LAMINA, SCENE, W, "--set", "t_end=100000", "--set", "every=0.02")

# the page: whole, ASCII, nothing from elsewhere
status, headers, page = s.request("GET", "/")
check(status == 200 and headers.get("Content-Type", "").startswith("text/html"), "GET / is the page")
check(all(b < 128 for b in page), "the page is ASCII")
low = page.lower()
check(b"<script" in low and b"src=" not in low.replace(b"img.src", b"").replace(b"fe.img.src", b"")
      and b"http://" not in low and b"https://" not in low and b"<link" not in low,
      "the page loads no external asset")
check("default-src 'none'" in headers.get("Content-Security-Policy", ""), "a strict CSP")

# progress and frames
st = wait_until(lambda: (lambda j: j if j and j["step"] > 0 and j["frames"] else None)(s.json("/api/state")))
check(st is not None, "/api/state shows steps and a frame")
if st:
    check(st["t"] > 0 and st["rate"] >= 0 and st["energy"] is not None and st["energy"]["total"] > 0,
          "state has t, rate, energy (%s)" % st.get("energy"))
    name = st["frames"][0]["name"]
    check(name == "out/f#.png", "a frame series is named by its path, digits as # (%s)" % name)
    status, headers, png = s.request("GET", "/frame/" + name.replace("#", "%23").replace("/", "%2F"))
    check(status == 200 and png[:8] == b"\x89PNG\r\n\x1a\n" and headers.get("Content-Type") == "image/png",
          "GET /frame/<name> is the latest PNG")
    later = wait_until(lambda: (lambda j: j if j and j["frames"][0]["count"] > st["frames"][0]["count"] else None)(s.json("/api/state")))
    check(later is not None, "the frame count grows as the run writes frames")

# names escaped: the scene reads a parameter named tag<b>"&'
status, _, raw = s.request("GET", "/api/params")
check(status == 200 and b"<" not in raw and b">" not in raw and b"&" not in raw and b"'" not in raw,
      "no < > & ' in the JSON bytes")
params = json.loads(raw)
names = [p["name"] for p in params["params"]]
check("tag<b>\"&'" in names and "amp" in names, "the names read back exactly (%s)" % names)
check([x["name"] for x in params["settings"]] == ["dt", "gravity", "pic", "courant", "damping"], "live settings listed")

# refusals
check(s.request("GET", "/nope")[0] == 404, "unknown page: 404")
check(s.request("GET", "/frame/out%2Fnone.png")[0] == 404, "a frame this run did not write: 404")
check(s.request("GET", "/frame/../../../etc/passwd")[0] == 400, "traversal in the path: 400")
check(s.request("GET", "/frame/..%2F..%2Fetc%2Fpasswd")[0] == 400, "escaped traversal: 400")
check(s.request("GET", "/frame/%2Fetc%2Fpasswd")[0] == 404, "an absolute path not written: 404")
check(s.request("DELETE", "/api/state")[0] == 405, "DELETE: 405")
check(s.request("GET", "/api/control")[0] == 405, "GET on a control: 405")
check(s.request("POST", "/api/state", "x=1", {"X-Lamina-Control": "1"})[0] == 405, "POST on a page: 405")
check(s.request("POST", "/api/param", "name=amp&value=3")[0] == 403, "a control without X-Lamina-Control: 403")
check(s.control("/api/param", "name=amp&value=3", {"X-Lamina-Control": "0"})[0] == 403, "X-Lamina-Control: 0 -> 403")
check(s.request("GET", "/api/state", host="evil.example:%d" % s.port)[0] == 403, "a foreign Host: 403 (DNS rebinding)")
check(s.request("GET", "/api/state", host="127.0.0.1:1")[0] == 403, "another port in Host: 403")
check(s.request("GET", "/api/state", host="localhost:%d" % s.port)[0] == 200, "Host localhost: 200")
check(s.control("/api/param", "name=amp&value=3", host="evil.example:%d" % s.port)[0] == 403, "a control from a foreign Host: 403")
check(s.control("/api/param", "value=3")[0] == 400, "a control without a name: 400")
check(s.control("/api/param", "name=nosuch&value=3")[0] == 400, "a parameter the script never read: 400")
check(s.control("/api/setting", "name=E&value=3")[0] == 400, "not a live setting: 400")
check(s.control("/api/control", "action=explode")[0] == 400, "an unknown action: 400")
check(s.control("/api/param", "name=amp&value=%01")[0] == 400, "a control byte in a value: 400")
check(s.control("/api/param", "name=amp&value=" + "9" * 5000)[0] == 413, "a body over 4096 bytes: 413")
status, _, _ = s.request("POST", "/api/param", None,
                         {"X-Lamina-Control": "1", "Content-Length": "100000000"})
check(status == 413, "Content-Length 1e8: 413 before the body")
# a chunked body (no Content-Length) that grows past the bound: the server
# closes the connection instead of reading on
c = socket.create_connection(("127.0.0.1", s.port), timeout=20)
c.sendall(("POST /api/param HTTP/1.1\r\nHost: %s\r\nX-Lamina-Control: 1\r\n"
           "Transfer-Encoding: chunked\r\n\r\n" % s.host).encode())
closed = False
try:
    for _ in range(4096):   # 4 MB at most
        c.sendall(b"400\r\n" + b"9" * 1024 + b"\r\n")
except OSError:
    closed = True
if not closed:
    try:
        c.settimeout(20)
        closed = c.recv(200) == b""
    except OSError:
        closed = True
c.close()
check(closed, "a chunked body over 4096 bytes: the connection is closed")
check(s.json("/api/state") is not None, "...and the server answers on")

# a malformed request line, and more idle connections than allowed from one
# address: refused or answered, never a crash; the server answers after
c = socket.create_connection(("127.0.0.1", s.port), timeout=10)
c.sendall(b"GARBAGE\r\n\r\n")
reply = c.recv(100)
c.close()
check(reply == b"" or reply.startswith(b"HTTP/1.1 400"), "a malformed request: 400 or closed (%r)" % reply[:20])
idle = [socket.create_connection(("127.0.0.1", s.port), timeout=10) for _ in range(12)]
refused = 0
for sk in idle[8:]:
    try:
        sk.settimeout(3)
        refused += sk.recv(10) == b""
    except (socket.timeout, OSError):
        pass
check(refused >= 1, "connections past the per-address limit are closed (%d of 4)" % refused)
for sk in idle:
    sk.close()
check(wait_until(lambda: s.json("/api/state"), 30) is not None, "the server answers after the flood")

check("lamina serve: http: Server reached connection limit" in s.stderr(),
      "libmicrohttpd's messages are named in the run log")

# a second server on a port in use: status 2, saying so
busy = subprocess.run([LAMINA, "serve", SCENE, "--port", str(s.port), "--set", "t_end=0.01"],
                      cwd=W, capture_output=True, text=True, timeout=60)
check(busy.returncode == 2 and "cannot listen on 127.0.0.1 port %d" % s.port in busy.stderr,
      "a port in use: status 2 (%d, %r)" % (busy.returncode, busy.stderr[-200:]))

# a parameter change: the same live-change log as the repl, seen by the script
check(s.control("/api/param", "name=amp&value=2.5")[0] == 200, "set amp = 2.5")
check(wait_until(lambda: s.column("amp")[-1:] == [2.5]) is not None and s.column("amp")[-1:] == [2.5],
      "the script's record shows amp = 2.5")
log = s.stderr()
check("param.amp = 2.5 (from the page)" in log, "the run log has the change")
check(s.control("/api/setting", "name=gravity&value=0,-2")[0] == 200, "set gravity")
check(s.control("/api/setting", "name=dt&value=abc")[0] == 200, "a bad dt is queued")
msgs = wait_until(lambda: (lambda j: j["msgs"] if j and any("refused" in m for m in j["msgs"]) else None)(s.json("/api/state")))
check(msgs and any("sim.gravity = 0,-2" in m for m in msgs) and any("refused: dt" in m for m in msgs),
      "the page's log: gravity applied, dt refused (%s)" % msgs)
check("sim.gravity = {0, -2} (from the page)" in s.stderr(), "the run log replays gravity")
check(s.control("/api/setting", "name=dt&value=1")[0] == 200, "a dt past the Courant limit is queued")
msgs = wait_until(lambda: (lambda j: j["msgs"] if j and any("Courant" in m for m in j["msgs"]) else None)(s.json("/api/state")))
check(msgs is not None, "...and refused by the Courant check, the run going on")
check(s.json("/api/params")["settings"][0]["value"] == "0.001", "dt unchanged (0.001)")

# pause, step, resume
check(s.control("/api/control", "action=pause")[0] == 200, "pause")
p = wait_until(lambda: (lambda j: j if j and j["waiting"] else None)(s.json("/api/state")))
check(p is not None, "the run waits at a step boundary")
if p:
    time.sleep(0.5)
    check(s.json("/api/state")["step"] == p["step"], "no step while paused")
    s.control("/api/control", "action=step")
    q = wait_until(lambda: (lambda j: j if j and j["waiting"] and j["step"] != p["step"] else None)(s.json("/api/state")))
    check(q is not None and q["step"] == p["step"] + 1, "step: exactly one step (%s -> %s)" % (p["step"], q and q["step"]))
    s.control("/api/control", "action=resume")
    check(wait_until(lambda: s.json("/api/state")["step"] > p["step"] + 10) is not None, "resume")

# SIGTERM while paused: the run stops at its step boundary, writes its
# records, exits 143
s.control("/api/control", "action=pause")
check(wait_until(lambda: s.json("/api/state")["waiting"]) is not None, "paused again")
s.proc.send_signal(signal.SIGTERM)
rc = s.wait()
check(rc == 143, "SIGTERM: exit status 143 (got %s)" % rc)
with open(os.path.join(W, "out", "amp.csv")) as f:
    rows = f.read().splitlines()
check(rows[0].startswith("t,step,") and rows[-1].split(",")[-1] == "2.5", "amp.csv written, last amp 2.5")
check(s.request("GET", "/api/state")[0] is None, "the server is gone")

# --host 0.0.0.0 --allow-remote: every interface; a Host must then be an IP
# literal with the port (a DNS name could be rebound)
s3 = Server(LAMINA, SCENE, W + "_remote", "--host", "0.0.0.0", "--allow-remote",
            "--set", "t_end=100000", "--set", "every=1", "--quiet")
check(s3.request("GET", "/api/state")[0] == 200, "wildcard bind: Host 127.0.0.1:PORT answered")
check(s3.request("GET", "/api/state", host="evil.example:%d" % s3.port)[0] == 403,
      "wildcard bind: a DNS name in Host refused (403)")
s3.proc.send_signal(signal.SIGTERM)
rc3 = s3.wait()
# once seen failing under the sanitizers at load (2026-12-05 CI, passed
# when re-run): the status and stderr's tail say why next time
check(rc3 == 143, "wildcard server ends on SIGTERM (got %s; stderr ends %r)"
      % (rc3, s3.stderr()[-600:]))

# a short run: the server stops at the run's end with its status
s2 = Server(LAMINA, SCENE, W + "_short", "--set", "t_end=0.05", "--quiet")
check(s2.wait() == 0, "the server ends with the run (status 0)")
check(os.path.exists(os.path.join(W + "_short", "out", "amp.csv")), "its records are written")
# --paused: the run waits after its first step until Resume
s4 = Server(LAMINA, SCENE, W + "_paused", "--paused", "--set", "t_end=0.05", "--quiet")
w = wait_until(lambda: (lambda j: j if j and j["waiting"] else None)(s4.json("/api/state")))
check(w is not None and w["step"] == 1 and w["paused"], "--paused: waits at step 1 (%s)" % (w and w["step"]))
time.sleep(0.3)
check(s4.proc.poll() is None, "...and stays")
s4.control("/api/control", "action=resume")
check(s4.wait() == 0, "Resume: the run goes to its end (status 0)")

# --keep: the last state is served after the run's end; controls are
# refused; SIGTERM ends it with the run's own status
s5 = Server(LAMINA, SCENE, W + "_keep", "--keep", "--set", "t_end=0.02", "--quiet")
f = wait_until(lambda: (lambda j: j if j and j["finished"] else None)(s5.json("/api/state")))
check(f is not None and f["status"] == 0 and f["step"] == 20, "--keep: the finished run is served (%s)" % (f and f["step"]))
st, _, body = s5.control("/api/param", "name=amp&value=2")
check(st == 400 and b"the run has ended" in body, "a change after the end: 400 (%s)" % body)
s5.proc.send_signal(signal.SIGTERM)
check(s5.wait() == 0, "--keep: SIGTERM ends the server with the run's status 0")
finish()
