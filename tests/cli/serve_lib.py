"""serve_lib.py - shared by the `lamina serve` tests (tests/cli/serve_*.py):
start a server on a free port in a fresh folder, talk to it with the
standard library only. Every wait is bounded: a hang becomes a failure."""
import atexit
import http.client
import json
import os
import shutil
import subprocess
import sys
import time

FAILS = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what, flush=True)
    if not cond:
        FAILS.append(what)
    return cond


def finish():
    if FAILS:
        print("%d check(s) failed" % len(FAILS))
        sys.exit(1)
    print("all checks passed")
    sys.exit(0)


def wait_until(fn, seconds=60, every=0.1):
    """fn() until it returns something true, at most `seconds`."""
    end = time.monotonic() + seconds
    while True:
        v = fn()
        if v or time.monotonic() > end:
            return v
        time.sleep(every)


class Server:
    def __init__(self, lamina, script, folder, *args):
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        self.folder = folder
        self.err = open(os.path.join(folder, "stderr.txt"), "w+")
        self.proc = subprocess.Popen([lamina, "serve", script, "--port", "0"] + list(args),
                                     cwd=folder, stdout=subprocess.PIPE, stderr=self.err,
                                     text=True)
        atexit.register(self.kill)   # a test that fails midway leaves no server
        line = self.proc.stdout.readline()   # "lamina serve: http://127.0.0.1:PORT/"
        if not line.startswith("lamina serve: http://"):
            self.proc.kill()
            raise SystemExit("FAIL: no address line from lamina serve (got %r)" % line)
        self.port = int(line.rsplit(":", 1)[1].strip().strip("/"))
        self.host = "127.0.0.1:%d" % self.port

    def request(self, method, path, body=None, headers=None, host=None):
        """(status, headers dict, body bytes); (None, {}, b'') when refused."""
        c = http.client.HTTPConnection("127.0.0.1", self.port, timeout=30)
        h = {"Host": host or self.host}
        h.update(headers or {})
        try:
            c.putrequest(method, path, skip_host=True, skip_accept_encoding=True)
            for k, v in h.items():
                c.putheader(k, v)
            data = body.encode() if isinstance(body, str) else body
            if data is not None and "Content-Length" not in h:
                c.putheader("Content-Length", str(len(data)))
            c.endheaders()
            if data is not None:
                c.send(data)
            r = c.getresponse()
            return r.status, dict(r.getheaders()), r.read()
        except (ConnectionError, OSError):
            return None, {}, b""
        finally:
            c.close()

    def json(self, path):
        status, _, body = self.request("GET", path)
        return json.loads(body) if status == 200 else None

    def control(self, path, body, headers=None, host=None):
        h = {"X-Lamina-Control": "1", "Content-Type": "application/x-www-form-urlencoded"}
        h.update(headers or {})
        return self.request("POST", path, body, h, host)

    def kill(self):
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()

    def column(self, name):
        """the values of record column `name` so far"""
        j = self.json("/api/records")
        for rec in (j or {}).get("records", []):
            if name in rec["columns"]:
                k = rec["columns"].index(name)
                return [row[k] for row in rec["rows"]]
        return []

    def stderr(self):
        self.err.flush()
        with open(self.err.name) as f:
            return f.read()

    def wait(self, seconds=60):
        try:
            return self.proc.wait(seconds)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
            return None
