#!/usr/bin/env python3
"""docs_citations.py - every documentation citation resolves (ctest unit.docs_citations).

The sources cite the notes in docs/ as `docs/<name>.md`, optionally with a
place in it:

    docs/physics.md §5b          a numbered section: a heading "## 5b. ..."
    docs/physics.md §1 and §4    each number
    docs/physics.md V3           a row of physics.md §6's table: "| V3 |"
    docs/decisions.md "Threads"  a heading or a bold lead ("- **Threads.**")
    docs/api.md, "Sandbox"       the same, after a comma

In src/, tests/, scripts/, assets/ and CMakeLists.txt the note must be
named with its folder (docs/physics.md, not physics.md), so that every
citation is a path in the repository. In docs/ itself and the README a
note names its sibling as the link does (physics.md §2 within docs/).
Comments broken over lines are joined before matching ("Shape\n *
functions"). Exit 0 when all resolve; 1 with one line per failure.

Usage: docs_citations.py [REPO_ROOT]   (default: this file's ../)
       docs_citations.py --self-test     (the negative control: a source
                                          with six bad citations must fail
                                          with exactly those six) """
import os
import re
import sys

ARGS = [a for a in sys.argv[1:] if not a.startswith("--")]
ROOT = os.path.abspath(ARGS[0] if ARGS else os.path.join(os.path.dirname(__file__), ".."))
DOCS = os.path.join(ROOT, "docs")
CODE_DIRS = ["src", "tests", "scripts", "assets"]
CODE_EXT = (".c", ".h", ".lua", ".txt", ".sh", ".py", ".cmake", ".md")
SELF = os.path.abspath(__file__)

NOTE = r"(?P<name>[a-z_0-9]+)\.md"
# a place after the note: §N [and §M ...], a V/N row, or "Heading"
PLACE = re.compile(
    r"""\s*,?\s*(?:
        (?P<secs>§\w+(?:\s*(?:,|and|or)\s*§\w+)*)
      | (?P<row>[VN]\d+)\b
      | "(?P<head>[^"\n]{2,80})"
    )""", re.X)


def flatten(text):
    """Joins comment continuation lines so a citation broken over two lines
    reads as one: a newline, indentation and a comment leader become one
    space."""
    return re.sub(r"\n[ \t]*(?:\*(?!/)|--|//|#)?[ \t]*", " ", text)


def norm(s):
    s = re.sub(r"[`*_]", "", s).lower()
    return re.sub(r"\s+", " ", s).strip()


class Note:
    def __init__(self, path):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        self.sections = set()
        self.headings = []
        self.rows = set()
        for line in text.splitlines():
            m = re.match(r"#{1,6}\s+(.*)", line)
            if m:
                h = m.group(1).strip()
                self.headings.append(norm(h))
                s = re.match(r"§?(\d+[a-z]?)[.)]?\s", h + " ")
                if s:
                    self.sections.add(s.group(1))
            for b in re.findall(r"^\s*(?:[-*]\s+)?\*\*(.+?)\*\*", line):
                self.headings.append(norm(b))
            r = re.match(r"\|\s*([VN]\d+)\s*\|", line)
            if r:
                self.rows.add(r.group(1))

    def has_heading(self, name):
        n = norm(name)
        return any(h.startswith(n) or n in h for h in self.headings)


notes = {}


def note(name):
    if name not in notes:
        p = os.path.join(DOCS, name + ".md")
        notes[name] = Note(p) if os.path.isfile(p) else None
    return notes[name]


def check_text(rel, text, prefix_required, problems):
    flat = flatten(text)
    known = {f[:-3] for f in os.listdir(DOCS) if f.endswith(".md")}
    # every docs/<name>.md must exist
    for m in re.finditer(r"docs/" + NOTE, flat):
        if note(m.group("name")) is None:
            problems.append(f"{rel}: docs/{m.group('name')}.md does not exist")
    # a bare note name where the folder is required
    if prefix_required:
        for m in re.finditer(r"(?<![\w/.-])" + NOTE, flat):
            if m.group("name") in known:
                problems.append(f"{rel}: '{m.group(0)}' should be cited as "
                                f"'docs/{m.group(0)}'")
    # places within a note
    for m in re.finditer(r"(?<![\w.-])(?:docs/)?" + NOTE, flat):
        name = m.group("name")
        if name not in known:
            continue
        n = note(name)
        p = PLACE.match(flat, m.end())
        if not p:
            continue
        cite = f"{name}.md {flat[m.end():p.end()].strip(' ,')}"
        if p.group("secs"):
            for sec in re.findall(r"§(\w+)", p.group("secs")):
                if sec not in n.sections:
                    problems.append(f"{rel}: {cite}: no section §{sec} in docs/{name}.md")
        elif p.group("row"):
            if p.group("row") not in n.rows:
                problems.append(f"{rel}: {cite}: no row {p.group('row')} in docs/{name}.md")
        elif p.group("head"):
            if not n.has_heading(p.group("head")):
                problems.append(f"{rel}: {cite}: no heading or bold lead "
                                f"\"{p.group('head')}\" in docs/{name}.md")


BAD_SOURCE = """/* (docs/physics.md §9) (docs/nosuch.md) (physics.md §1)
 * (docs/decisions.md "No such
 * lead") (docs/physics.md V12) (docs/physics.md §1 and §8)
 * resolving: (docs/decisions.md "Shape
 * functions") (docs/normals.md, "Centred elements") (docs/physics.md §5b) */
"""


def self_test():
    import shutil
    import subprocess
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copytree(DOCS, os.path.join(tmp, "docs"))
        os.mkdir(os.path.join(tmp, "src"))
        with open(os.path.join(tmp, "src", "bad.c"), "w", encoding="utf-8") as f:
            f.write(BAD_SOURCE)
        r = subprocess.run([sys.executable, SELF, tmp], capture_output=True, text=True)
    bad = [l for l in r.stdout.splitlines() if l.startswith("src/bad.c: ")]
    print(r.stdout, end="")
    if r.returncode != 1 or len(bad) != 6:
        print(f"self-test FAILED: status {r.returncode}, {len(bad)} problems (want 1, 6)")
        return 1
    print("self-test: the six bad citations were found, the three good ones passed")
    return 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    problems = []
    count = 0
    files = [(os.path.join(ROOT, "CMakeLists.txt"), True),
             (os.path.join(ROOT, "README.md"), False)]
    for d in CODE_DIRS:
        for dirpath, dirnames, filenames in os.walk(os.path.join(ROOT, d)):
            dirnames[:] = [x for x in dirnames if x not in ("corpus", "baselines")]
            for f in sorted(filenames):
                if f.endswith(CODE_EXT) or f == "CMakeLists.txt":
                    files.append((os.path.join(dirpath, f), True))
    for f in sorted(os.listdir(DOCS)):
        if f.endswith(".md"):
            files.append((os.path.join(DOCS, f), False))
    for path, prefix_required in files:
        if os.path.abspath(path) == SELF or not os.path.isfile(path):
            continue
        with open(path, encoding="utf-8", errors="replace") as fh:
            text = fh.read()
        count += 1
        check_text(os.path.relpath(path, ROOT), text, prefix_required, problems)
    for p in problems:
        print(p)
    print(f"docs_citations: {count} files, {len(problems)} unresolved citation(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
