#!/usr/bin/env python3
"""engine_writes.py - only the engine writes its state (ctest unit.engine_writes).

Issue 19 item 1 and docs/design.md, "Engine": the engine (src/mpm) is the one
writer of a simulation's state. The other layers (src/lua, src/app,
src/render) read it, and change it only through the engine's functions:
definitions (lm_membrane_def, lm_sim_def) and setters (lm_sim_set_dt,
lm_sim_set_gravity, lm_sim_set_membrane_force, ...), which check what they
are given.

This test reads the other layers' C files and fails on any assignment
(=, +=, ..., ++, --) whose target goes through the engine's structs: a
variable declared as a pointer to a non-const lm_sim, lm_body,
lm_particles, lm_grid, lm_pin, lm_link or lm_material, or a path through
`->sim->` (the Lua layer's handle on its engine). A pointer declared const cannot be
written through, so the way to pass it is to read through const pointers.
Declaring an engine struct by value (lm_sim_def d; lm_membrane_def def) to
fill it and hand it to the engine is the intended use and is allowed.

Usage: engine_writes.py [REPO_ROOT]   (default: this file's ../)
       engine_writes.py --self-test     (a source with six writes and three
                                         reads must fail with those six) """
import os
import re
import sys

# the 3D engine's too (mpm3.h: lm3_sim, lm3_particles, ...; issue 34)
ENGINE_TYPES = (r"(?:lm_sim|lm_body|lm_particles|lm_grid|lm_pin|lm_link|lm_material"
                r"|lm3_sim|lm3_particles|lm3_grid|lm3_pin|lm3_pins|lm3_material)")
# Files that still write engine state, each with the change that ends it
# (none now: since issue 33 item 1 the engine owns copies of its materials,
# and a script's material is a definition, la_material, changed live
# through lm_sim_set_material).
PENDING = {}
# `lm_body *bd`, `lm_sim *sim = ...`, `lm_particles *const p` - not `const lm_body *`
DECL = re.compile(r"(?<![\w])(?<!const )" + ENGINE_TYPES + r"\s*\*\s*(?:const\s+)?(\w+)")
PATHS = re.compile(r"->sim->")   # la_sim's engine pointer
CONTROL = re.compile(r"^(?:else\s+)?(?:if|while|for|switch)\s*\(")
ASSIGN = re.compile(r"(?<![=!<>+\-*/%&|^])(?:[+\-*/%&|^]|<<|>>)?=(?!=)")


def strip(text):
    """Comments and string literals out, line numbers kept."""
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    return re.sub(r'"(?:\\.|[^"\\\n])*"', '""', text)


def statements(text):
    """(line, statement) pairs: the text between ; { } at depth 0 of ()."""
    out, start, depth, line, start_line = [], 0, 0, 1, 1
    for i, c in enumerate(text):
        if c == "\n":
            line += 1
        elif c == "(":
            depth += 1
        elif c == ")":
            depth -= 1
        elif c in ";{}" and depth == 0:
            out.append((start_line, text[start:i]))
            start, start_line = i + 1, line
    return out


def skip_control(st):
    """st without its leading `else`, or `if (...)`/`while (...)`/... head."""
    if st.startswith("else "):
        return st[5:].lstrip()
    i = st.index("(")
    depth = 0
    for j in range(i, len(st)):
        depth += {"(": 1, ")": -1}.get(st[j], 0)
        if depth == 0:
            return st[j + 1:].lstrip()
    return ""


def writes(path, text):
    """The statements of text that write engine state: (path:line, statement)."""
    text = strip(text)
    names = set(DECL.findall(text))
    found = []
    for line, st in statements(text):
        st = " ".join(st.split())
        if not st or st.startswith("#"):
            continue
        while CONTROL.match(st) or st.startswith("else "):
            st = skip_control(st)
        # the target: left of the first assignment operator, or ++/-- operands
        m = ASSIGN.search(st)
        targets = []
        if m:
            lhs = st[: m.start()]
            if "(" in lhs and not re.search(r"\)\s*(->|\.|\[)", lhs):
                lhs = lhs.split("(")[-1]          # an assignment inside a call or for (...)
            targets.append(lhs)
        targets += re.findall(r"([\w\->\.\[\]]+)\s*(?:\+\+|--)", st)
        targets += re.findall(r"(?:\+\+|--)\s*([\w\->\.\[\]]+)", st)
        for t in targets:
            t = t.strip()
            if re.search(r"\b" + ENGINE_TYPES + r"\b", t):
                continue                      # a declaration: `lm_sim *sim = ...`
            root = re.match(r"\*?\s*(\w+)\s*(->|\.|\[)", t)
            through_name = root and root.group(1) in names and root.group(2) != "."
            if through_name or PATHS.search(t):
                found.append("%s:%d: %s" % (path, line, st[:120]))
                break
    return found


SELF_TEST = """
static void f(lm_sim *sim, const lm_sim *view, la_sim *s, lm_body *bd,
              lm_material *mat, const lm_material *seen)
{
    sim->t = 1;                         /* write 1 */
    s->sim->def.pic = 0.5;              /* write 2 */
    bd->orient++;                       /* write 3 */
    double x = view->p.x[0];            /* read */
    if (sim->prepared == 0) x += 1;     /* read */
    lm_sim_def d;
    d.dt = 1e-3;                        /* a definition by value: allowed */
    for (int b = 0; b < sim->nbodies; b++) x += sim->bodies[b].count;   /* read */
    s->sim->bodies[0].force = 1;        /* write 4 */
    mat->E = 2 * seen->E;               /* write 5: a material's field */
    sim->mats[0]->nu = 0.3;             /* write 6 */
}
"""


def main():
    if "--self-test" in sys.argv:
        got = writes("self", SELF_TEST)
        lines = [int(l.split(":")[1]) for l in got]
        ok = lines == [4, 5, 6, 12, 13, 14]   # the six writes' lines
        print("\n".join(got))
        print("engine_writes self-test: lines %s, expected [4, 5, 6, 12, 13, 14]: %s"
              % (lines, "ok" if ok else "FAILED"))
        return 0 if ok else 1
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    root = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), ".."))
    found, pending, files = [], [], 0
    for layer in ("lua", "app", "render"):
        base = os.path.join(root, "src", layer)
        for dirpath, _, names in os.walk(base):
            for n in sorted(names):
                if not n.endswith(".c"):
                    continue
                p = os.path.join(dirpath, n)
                rel = os.path.relpath(p, root)
                with open(p, encoding="utf-8") as f:
                    got = writes(rel, f.read())
                if rel in PENDING:
                    pending.append("%s: %d writes, pending: %s" % (rel, len(got), PENDING[rel]))
                else:
                    found += got
                files += 1
    for w in found + pending:
        print(w)
    print("engine_writes: %d files of src/lua, src/app, src/render; %d writes to engine state"
          % (files, len(found)))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
