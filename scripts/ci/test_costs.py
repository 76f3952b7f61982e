#!/usr/bin/env python3
"""scripts/ci/test_costs.py - write tests/test_costs.tsv from measured times.

ctest -j starts tests in descending COST; on a clean clone there is no
Testing/Temporary/CTestCostData.txt, every cost is 0 and the tests start in
the order they are defined, so a long test defined late can start last
and run alone on one core while the other idles (the stage's wall time is
then that test's end, not the work divided by the cores).
tests/ci_sets.cmake sets COST from this file: the normal build's column in
build/, the sanitized column in build-asan/ and build-fuzz/.

Usage (after a ctest run in each tree):
  python3 scripts/ci/test_costs.py [build [build-asan]] [--asan-log SAVED_CTEST_OUTPUT]
Lists the tests taking at least 2 s in either tree; the rest keep cost 0
and fill the gaps.
"""
import argparse
import os
import re

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def read(tree):
    costs = {}
    path = os.path.join(tree, "Testing", "Temporary", "CTestCostData.txt")
    for line in open(path):
        parts = line.split()
        if len(parts) == 3:
            costs[parts[0]] = float(parts[2])
    return costs


def read_log(path):
    """`Test #N: name ... Passed 12.3 sec` lines of a saved ctest output."""
    return {m.group(1): float(m.group(2)) for m in
            re.finditer(r"Test +#\d+: (\S+) \.*\s+Passed\s+([0-9.]+) sec", open(path).read())}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("normal", nargs="?", default="build")
    ap.add_argument("sanitized", nargs="?", default="build-asan")
    ap.add_argument("--asan-log", action="append", default=[],
                    help="a saved ctest output from the sanitized tree (a partial run counts)")
    a = ap.parse_args()
    normal = read(os.path.join(ROOT, a.normal))
    asan = {}
    if os.path.exists(os.path.join(ROOT, a.sanitized, "Testing", "Temporary", "CTestCostData.txt")):
        asan = read(os.path.join(ROOT, a.sanitized))
    for log in a.asan_log:
        asan.update(read_log(log))
    # a test not measured sanitized: its normal seconds times the median ratio
    # of the tests of at least 0.5 s (a shorter one is mostly start-up)
    ratios = sorted(asan[n] / normal[n] for n in asan if normal.get(n, 0) >= 0.5)
    ratio = ratios[len(ratios) // 2] if ratios else 1.0
    for n in normal:
        asan.setdefault(n, normal[n] * ratio)
    names = sorted((n for n in set(normal) | set(asan)
                    if normal.get(n, 0) >= 2 or asan.get(n, 0) >= 2),
                   key=lambda n: -max(normal.get(n, 0), asan.get(n, 0)))
    out = os.path.join(ROOT, "tests", "test_costs.tsv")
    with open(out, "w") as f:
        f.write("# tests/test_costs.tsv - written by scripts/ci/test_costs.py; seconds a test took\n")
        f.write("# (ctest's averages) in the normal and the sanitized build, two cores; a test\n")
        f.write("# not measured sanitized: normal x %.2f (the median ratio of %d measured).\n"
                % (ratio, len(ratios)))
        f.write("# name\tnormal\tsanitized\n")
        for n in names:
            f.write("%s\t%.1f\t%.1f\n" % (n, normal.get(n, 0), asan.get(n, 0)))
    print("wrote %s: %d tests" % (os.path.relpath(out, ROOT), len(names)))


if __name__ == "__main__":
    main()
