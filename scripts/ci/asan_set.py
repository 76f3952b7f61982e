#!/usr/bin/env python3
"""scripts/ci/asan_set.py - choose the tests .ci/test runs under the sanitizers.

The sanitizer stage (ASan + UBSan) runs every test a second time, 2-5x
slower. A sanitizer can only report on code that runs, so a test earns its
place there by the lines of src/ it executes. This script measures, per
test, the lines it covers (gcc --coverage build, gcov's JSON), and picks
among the physics / visual / analysis tests the set of least ASan time
whose lines, together with the tests that always run sanitized, cover
every line the whole former set covered (greedy weighted set cover, then
a pass dropping any pick the others make redundant).

Always sanitized, not chosen here: every test labelled unit, bad,
security, cli or io (the untrusted-input checks) and the fuzz targets.
Never sanitized: tests labelled slow (the normal stage runs them).

Writes tests/asan_set.tsv: one line per assessed test, `name<TAB>asan`
(run sanitized: tests/CMakeLists.txt gives it the `asan` label) or
`name<TAB>covered` (its lines are all run by the sanitized set), with a
header saying how many lines the set keeps. unit.asan_set_assessed fails
when a physics / visual / analysis test is missing from the file, so a new
test is assessed (this script re-run) before it can be left out.

Usage (from the repository root; minutes on two cores):
  python3 scripts/ci/asan_set.py [--asan-costs build-asan] [--jobs 2]
The ASan times come from build-asan/Testing/Temporary/CTestCostData.txt
(run `ctest -L "unit|bad|security|physics|cli|visual|io|analysis" -LE slow`
there once first) and from saved ctest outputs (--asan-log); a test not
measured there is weighted by its coverage-run seconds times the median
ASan / coverage ratio of the tests measured in both.
"""
import argparse
import concurrent.futures
import json
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
ALWAYS = {"unit", "bad", "security", "cli", "io"}   # untrusted input: always sanitized
CHOSEN = {"physics", "visual", "analysis"}          # chosen among by their lines
NEVER = {"slow"}


def labels_of(test):
    for p in test.get("properties", []):
        if p["name"] == "LABELS":
            return set(p["value"])
    return set()


def prop(test, name, default=None):
    for p in test.get("properties", []):
        if p["name"] == name:
            return p["value"]
    return default


def build_coverage_tree(bdir, jobs):
    if not os.path.exists(os.path.join(bdir, "CMakeCache.txt")):
        subprocess.run(["cmake", "-S", ROOT, "-B", bdir, "-DCMAKE_BUILD_TYPE=RelWithDebInfo",
                        "-DCMAKE_C_FLAGS=--coverage", "-DCMAKE_EXE_LINKER_FLAGS=--coverage",
                        "-DCMAKE_SHARED_LINKER_FLAGS=--coverage"],
                       check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", bdir, "-j%d" % jobs, "--", "--no-print-directory"],
                   check=True, stdout=subprocess.DEVNULL)


def covered_lines(prefix, bdir):
    """The (file, line) pairs of src/ executed by the runs whose .gcda files
    libgcov wrote under prefix (GCOV_PREFIX): gcov reads each .gcda beside
    its .gcno, copied in from the build tree."""
    lines = set()
    gcdas = []
    for d, _, files in os.walk(prefix):
        for f in files:
            if f.endswith(".gcda"):
                gcda = os.path.join(d, f)
                gcno = os.path.join("/", os.path.relpath(gcda, prefix))[:-5] + ".gcno"
                if os.path.exists(gcno):
                    shutil.copyfile(gcno, gcda[:-5] + ".gcno")
                    gcdas.append(gcda)
    src = os.path.join(ROOT, "src") + os.sep
    for i in range(0, len(gcdas), 64):
        out = subprocess.run(["gcov", "--json-format", "--stdout"] + gcdas[i:i + 64],
                             cwd=bdir, check=True, capture_output=True, text=True).stdout
        for doc in out.splitlines():
            if not doc.strip():
                continue
            for f in json.loads(doc)["files"]:
                path = os.path.normpath(os.path.join(bdir, f["file"]))
                if not path.startswith(src):
                    continue
                rel = os.path.relpath(path, ROOT)
                for ln in f["lines"]:
                    if ln["count"] > 0:
                        lines.add((rel, ln["line_number"]))
    return lines


def run_one(test, prefix):
    """Runs one test's command as ctest would (its directory and
    environment), with its coverage written under prefix."""
    env = dict(os.environ, GCOV_PREFIX=prefix, GCOV_PREFIX_STRIP="0")
    for kv in prop(test, "ENVIRONMENT", []) or []:
        k, _, v = kv.partition("=")
        env[k] = v
    t0 = time.time()
    r = subprocess.run(test["command"], cwd=prop(test, "WORKING_DIRECTORY", None), env=env,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       timeout=float(prop(test, "TIMEOUT", 1500) or 1500) * 3)
    return r.returncode, time.time() - t0


def asan_costs(adir, logs):
    """Seconds per test under the sanitizers: ctest's CTestCostData.txt in
    the sanitized tree, and the `Test #N: name ... Passed 12.3 sec` lines
    of any saved ctest outputs (a partial run counts too)."""
    costs = {}
    path = os.path.join(adir, "Testing", "Temporary", "CTestCostData.txt")
    if os.path.exists(path):
        for line in open(path):
            parts = line.split()
            if len(parts) == 3:
                costs[parts[0]] = float(parts[2])
    for log in logs:
        for m in re.finditer(r"Test +#\d+: (\S+) \.*\s+Passed\s+([0-9.]+) sec", open(log).read()):
            costs[m.group(1)] = float(m.group(2))
    return costs


def weights(names, asan, seconds):
    """A test's ASan seconds where measured, else its coverage-build seconds
    times the median ratio of the two over the tests measured in both."""
    ratios = sorted(asan[n] / seconds[n] for n in names if n in asan and seconds.get(n, 0) >= 0.5)
    ratio = ratios[len(ratios) // 2] if ratios else 1.0
    return {n: max(asan.get(n, seconds[n] * ratio), 0.01) for n in names}, ratio, len(ratios)


def choose(candidates, cov, must, weight):
    """Greedy weighted set cover of (union of all) - must, then drop picks
    whose lines the others already cover (heaviest first)."""
    todo = set().union(*(cov[t] for t in candidates)) - must
    picked = []
    while todo:
        best = max(candidates, key=lambda t: (len(cov[t] & todo) / weight[t], t))
        gain = cov[best] & todo
        if not gain:
            break
        picked.append(best)
        todo -= gain
    for t in sorted(picked, key=lambda t: -weight[t]):
        rest = must.union(*(cov[u] for u in picked if u != t))
        if cov[t] <= rest:
            picked.remove(t)
    return picked


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build-cov"),
                    help="the coverage build tree (made when missing)")
    ap.add_argument("--asan-costs", default=os.path.join(ROOT, "build-asan"),
                    help="the sanitized build tree: its tests (only those are measured)"
                         " and its CTestCostData.txt (the ASan times)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--out", default=os.path.join(ROOT, "tests", "asan_set.tsv"))
    ap.add_argument("--asan-log", action="append", default=[],
                    help="a saved output of ctest -V or --output-on-failure in the sanitized tree")
    ap.add_argument("--reuse", action="store_true",
                    help="choose again from the last run's measured lines (new ASan times)")
    a = ap.parse_args()
    bdir = os.path.abspath(a.build)
    cache = os.path.join(bdir, "asan-set-lines.json")
    if a.reuse:
        with open(cache) as f:
            saved = json.load(f)
        must = {tuple(x) for x in saved["always"]}
        cov = {n: {tuple(x) for x in v} for n, v in saved["lines"].items()}
        seconds = saved["seconds"]
    else:
        must, cov, seconds = measure(bdir, a.jobs, os.path.abspath(a.asan_costs))
        with open(cache, "w") as f:
            json.dump({"always": sorted(must), "seconds": seconds,
                       "lines": {n: sorted(v) for n, v in cov.items()}}, f)
    write(a, must, cov, seconds)


def listing_of(tree):
    out = subprocess.run(["ctest", "--show-only=json-v1"], cwd=tree, check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)["tests"]


def measure(bdir, jobs, adir):
    """Lines of src/ run by the always-sanitized tests together, and by
    each candidate alone; the candidates' seconds in the coverage build.
    A test the sanitized build does not define (security.frame_oom_names_size:
    `ulimit -v` cannot hold the sanitizers' reservations) is left out."""
    build_coverage_tree(bdir, jobs)
    tests = [t for t in listing_of(bdir)
             if labels_of(t) & (ALWAYS | CHOSEN) and not labels_of(t) & NEVER]
    absent = []
    if os.path.exists(os.path.join(adir, "CTestTestfile.cmake")):
        there = {t["name"] for t in listing_of(adir)}
        absent = sorted(t["name"] for t in tests if t["name"] not in there)
        tests = [t for t in tests if t["name"] in there]
    always = [t for t in tests if labels_of(t) & ALWAYS]
    cands = [t for t in tests if not labels_of(t) & ALWAYS]
    covdir = os.path.join(bdir, "asan-set-coverage")
    shutil.rmtree(covdir, ignore_errors=True)
    shutil.rmtree(os.path.join(bdir, "tests", "out"), ignore_errors=True)
    shutil.rmtree(os.path.join(bdir, "tests", ".lamina-outputs"), ignore_errors=True)

    # The always-sanitized tests: one union is all that is needed, so ctest
    # runs them together (fixtures and all) with one GCOV_PREFIX.
    print("asan_set: %d always-sanitized tests, %d to choose among" % (len(always), len(cands)),
          flush=True)
    env = dict(os.environ, GCOV_PREFIX=os.path.join(covdir, "_always"), GCOV_PREFIX_STRIP="0")
    regex = "|".join(sorted(ALWAYS))
    skip = ["-E", "^(%s)$" % "|".join(re.escape(n) for n in absent)] if absent else []
    r = subprocess.run(["ctest", "-j%d" % jobs, "-L", regex, "-LE", "|".join(NEVER)] + skip,
                       cwd=bdir, env=env, stdout=subprocess.DEVNULL)
    if r.returncode:
        print("asan_set: warning: some always-sanitized tests failed in the coverage build",
              file=sys.stderr)
    must = covered_lines(os.path.join(covdir, "_always"), bdir)

    # Each candidate alone, with its own GCOV_PREFIX (run_one), jobs at a time;
    # those needing another test first (DEPENDS, a fixture: the gallery
    # checks read what visual.gallery_render wrote) in a second wave.
    seconds, cov = {}, {}
    later = [t for t in cands if prop(t, "DEPENDS") or prop(t, "FIXTURES_REQUIRED")]
    for wave in ([t for t in cands if t not in later], later):
        with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
            futs = {pool.submit(run_one, t, os.path.join(covdir, t["name"])): t for t in wave}
            for f in concurrent.futures.as_completed(futs):
                t = futs[f]
                rc, secs = f.result()
                seconds[t["name"]] = secs
                if rc != 0 and not prop(t, "WILL_FAIL", False) \
                        and not prop(t, "PASS_REGULAR_EXPRESSION"):
                    print("asan_set: warning: %s exited %d in the coverage build"
                          % (t["name"], rc), file=sys.stderr)
    for t in cands:
        cov[t["name"]] = covered_lines(os.path.join(covdir, t["name"]), bdir)
    return must, cov, seconds


def write(a, must, cov, seconds):
    names = sorted(cov)
    weight, ratio, both = weights(names, asan_costs(a.asan_costs, a.asan_log), seconds)
    picked = set(choose(names, cov, must, weight))
    full = must.union(*cov.values())
    kept = must.union(*(cov[n] for n in picked))
    assert kept == full
    head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT,
                          capture_output=True, text=True).stdout.strip()
    with open(a.out, "w") as out:
        out.write("# tests/asan_set.tsv - written by scripts/ci/asan_set.py at %s; do not edit.\n"
                  % head)
        out.write("# asan: run under ASan+UBSan (label asan); covered: its src/ lines are all run\n")
        out.write("# by the sanitized set. The sanitized set (unit|bad|security|cli|io + asan)\n")
        out.write("# covers %d of the %d src/ lines the full set covers (%.1f %%);\n"
                  % (len(kept), len(full), 100.0 * len(kept) / len(full)))
        out.write("# the always-sanitized tests alone cover %d; ASan time of the %d picks %.0f s\n"
                  % (len(must), len(picked), sum(weight[n] for n in picked)))
        out.write("# of the %d candidates' %.0f s (ASan seconds measured for %d of them; the\n"
                  % (len(names), sum(weight.values()), both))
        out.write("# rest estimated as coverage-build seconds x %.2f, the median ratio).\n" % ratio)
        for n in names:
            out.write("%s\t%s\n" % (n, "asan" if n in picked else "covered"))
    print("asan_set: %d of %d lines kept; %d of %d candidates picked, ASan %.0f s of %.0f s"
          % (len(kept), len(full), len(picked), len(names),
             sum(weight[n] for n in picked), sum(weight.values())))
    print("asan_set: wrote %s" % os.path.relpath(a.out, ROOT))


if __name__ == "__main__":
    main()
