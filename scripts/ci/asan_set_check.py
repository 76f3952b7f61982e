#!/usr/bin/env python3
"""scripts/ci/asan_set_check.py - ctest unit.asan_set_assessed.

Fails when a test the sanitizer stage could leave out (labelled physics,
visual or analysis; not unit, bad, security, cli or io, which always run
sanitized; not slow) is missing from tests/asan_set.tsv, or when the file
names a test that no longer exists: a new test is left out of the
sanitizer stage only after scripts/ci/asan_set.py has measured that the
sanitized set already runs all its lines of src/.

Usage: asan_set_check.py CTEST BUILD_DIR TSV     (run by ctest)
       asan_set_check.py --self-test              (the check's own negative test)
"""
import json
import subprocess
import sys

ALWAYS = {"unit", "bad", "security", "cli", "io"}
CHOSEN = {"physics", "visual", "analysis"}


def assessable(listing):
    names = set()
    for t in listing["tests"]:
        labels = set()
        for p in t.get("properties", []):
            if p["name"] == "LABELS":
                labels = set(p["value"])
        if labels & CHOSEN and not labels & ALWAYS and "slow" not in labels:
            names.add(t["name"])
    return names


def assessed(lines):
    names = {}
    for n, line in enumerate(lines, 1):
        if not line.strip() or line.startswith("#"):
            continue
        fields = line.rstrip("\n").split("\t")
        if len(fields) != 2 or fields[1] not in ("asan", "covered"):
            raise ValueError("line %d: expected NAME<TAB>asan|covered, got %r" % (n, line.rstrip()))
        names[fields[0]] = fields[1]
    return names


def problems(listing, lines, tsv="tests/asan_set.tsv"):
    want = assessable(listing)
    have = assessed(lines)
    out = []
    for n in sorted(want - set(have)):
        out.append("%s: not assessed in %s (new test? run python3 scripts/ci/asan_set.py)"
                   % (n, tsv))
    for n in sorted(set(have) - want):
        out.append("%s: in %s but no such physics/visual/analysis test (remove the line or "
                   "re-run python3 scripts/ci/asan_set.py)" % (n, tsv))
    return out


def self_test():
    def test(name, *labels):
        return {"name": name, "properties": [{"name": "LABELS", "value": list(labels)}]}
    listing = {"tests": [test("physics.a", "physics"), test("visual.b", "visual"),
                         test("physics.c", "physics", "slow"), test("unit.d", "unit", "visual")]}
    good = ["# header\n", "physics.a\tasan\n", "visual.b\tcovered\n"]
    assert problems(listing, good) == [], problems(listing, good)
    missing = problems(listing, good[:2])
    assert len(missing) == 1 and missing[0].startswith("visual.b: not assessed"), missing
    stale = problems(listing, good + ["physics.gone\tcovered\n"])
    assert len(stale) == 1 and stale[0].startswith("physics.gone:"), stale
    try:
        assessed(["physics.a asan\n"])
    except ValueError as e:
        assert "line 1" in str(e)
    else:
        raise AssertionError("a line without a tab was accepted")
    print("asan_set_check self-test: ok")


def main():
    if sys.argv[1:] == ["--self-test"]:
        self_test()
        return 0
    ctest, build, tsv = sys.argv[1:4]
    listing = json.loads(subprocess.run([ctest, "--show-only=json-v1"], cwd=build, check=True,
                                        capture_output=True, text=True).stdout)
    with open(tsv) as f:
        found = problems(listing, f.readlines(), tsv)
    for p in found:
        print(p)
    if found:
        return 1
    print("every physics/visual/analysis test is assessed in %s" % tsv)
    return 0


if __name__ == "__main__":
    sys.exit(main())
