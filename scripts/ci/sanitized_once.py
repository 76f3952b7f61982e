#!/usr/bin/env python3
"""sanitized_once.py - the tests .ci/test runs only in its sanitized stage.

Prints a ctest -E regex naming every test the sanitized stage ran (ctest's
selection in the sanitized tree, read from --show-only=json-v1) that the
normal stage need not run again: the same assertions at the same -O2, under
AddressSanitizer and UndefinedBehaviorSanitizer besides (docs/performance.md
"The test command's time"). Kept in both stages: a fixture's setup (the
tests after it need it in either tree), every `security` test (some run with
a memory limit only outside the sanitizers, tests/CMakeLists.txt) and every
test labelled `slow` (the sanitized stage leaves those out).

  python3 scripts/ci/sanitized_once.py BUILD_ASAN -L REGEX -LE REGEX
"""
import json
import re
import subprocess
import sys


def main():
    if len(sys.argv) != 6 or sys.argv[2] != "-L" or sys.argv[4] != "-LE":
        sys.exit(__doc__)
    tree, inc, exc = sys.argv[1], sys.argv[3], sys.argv[5]
    out = subprocess.run(["ctest", "--show-only=json-v1", "-L", inc, "-LE", exc], cwd=tree,
                         check=True, capture_output=True, text=True).stdout
    names = []
    for t in json.loads(out)["tests"]:
        props = {p["name"]: p["value"] for p in t.get("properties", [])}
        labels = props.get("LABELS", [])
        if "FIXTURES_SETUP" in props or "security" in labels or "slow" in labels:
            continue
        # ctest adds a selected test's fixture setups; only tests its labels select
        if not any(re.search(inc, l) for l in labels) or any(re.search(exc, l) for l in labels):
            continue
        names.append(re.escape(t["name"]))
    if not names:
        sys.exit("sanitized_once: no test selected in " + tree)
    print("^(" + "|".join(sorted(names)) + ")$")


if __name__ == "__main__":
    main()
