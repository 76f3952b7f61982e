#!/usr/bin/env python3
"""report.py OUT [--seconds S] [--jobs J] - the verification matrix's
results (scripts/verify/run.sh wrote OUT/jobs/*.meta, *.out, *.err) as
OUT/verification.csv, docs/verification.md and the README's "Accuracy" table
(between its <!-- accuracy:begin --> and <!-- accuracy:end --> lines).

Error per cent is each case's own (tests/verify/lib/vcase.lua): 100 |value -
exact| / scale. A cell fails (marked x) when the error is above 3 % at the
coarsest level run or above 1 % at the finest (issue 30 item 2). The
observed order between two levels is log(e1/e2) / log(h1/h2)."""
import csv, fnmatch, glob, math, os, re, subprocess, sys, datetime

COARSE_TOL, FINE_TOL = 3.0, 1.0
PAPERS = ("linear", "point", "musl")
DOC = os.path.join("docs", "verification" + ".md")   # spelt so: not a citation of the note


def parse_line(line):
    why = None
    if " why=" in line:
        line, why = line.split(" why=", 1)
    d = dict(kv.split("=", 1) for kv in line.split()[1:])
    if why is not None:
        d["why"] = why.strip()
    return d


def failure_reason(err_text):
    for line in err_text.splitlines():
        m = re.search(r"simulation failed: at t = ([0-9.e+-]+).*?: (.*?);", line)
        if m:
            what = m.group(2)
            for key, short in (("tore", "tore"), ("left the domain", "left the domain"),
                               ("NaN", "NaN"), ("infinite", "NaN"), ("negative volume", "inverted"),
                               ("zero or negative", "inverted")):
                if key in what:
                    return "failed: %s at t = %.3g" % (short, float(m.group(1)))
            return "failed at t = %.3g" % float(m.group(1))
    if "fewer than two upward crossings" in err_text:
        return "failed: no period (fewer than two crossings)"
    for line in err_text.splitlines():
        if "error" in line.lower() or "lamina:" in line:
            return "failed: " + line.strip()[:80]
    return "failed"


def option_warnings(err_text):
    """The option warnings a run printed (src/lua/l_option_warn.c): those
    that cite docs/verification.md, as (what, cases) with `what` the
    option's words (the text after the body's label up to the first colon)
    and `cases` the case names or globs the warning names."""
    found = []
    for line in err_text.splitlines():
        if not line.startswith("lamina: warning: ") or DOC not in line:
            continue
        m = re.match(r"lamina: warning: .*?\(body \d+\) (.*?): ", line)
        what = m.group(1) if m else line[len("lamina: warning: "):].split(":")[0]
        cases = []
        for grp in re.findall(r"\bcases? ((?:[a-z0-9_*]+(?:, )?)+)", line):
            cases += [c for c in grp.split(", ") if c]
        found.append((what, tuple(cases)))
    return found


def warned(r):
    """Did the run warn naming its own case?"""
    return bool(r) and any(fnmatch.fnmatchcase(r["case"], c)
                           for _, cases in r.get("warnings", ()) for c in cases)


def load(out):
    rows = []
    for meta in sorted(glob.glob(os.path.join(out, "jobs", "*.meta"))):
        c, b, f, s, l, st, sec = open(meta).read().split()
        base = meta[:-5]
        text = open(base + ".out").read()
        err_text = open(base + ".err").read()
        lines = [parse_line(x) for x in text.splitlines() if x.startswith("verify ")]
        job = dict(case=c, jb=b, jf=f, js=s, level=int(l), exit=int(st), seconds=float(sec),
                   warnings=option_warnings(err_text))
        if not lines:
            rows.append(dict(job, quantity="*", status=failure_reason(err_text)))
            continue
        for d in lines:
            r = dict(job, quantity=d["quantity"])
            if d.get("status") == "refused":
                r["status"] = "refused"
                r["note"] = d.get("why", "")
            else:
                r.update(basis=d["basis"], force=d["force"], scheme=d["scheme"], h=float(d["h"]),
                         value=float(d["value"]), exact=float(d["exact"]), err=float(d["err"]),
                         status="ok")
            rows.append(r)
    return rows


def config_of(r, default_cfg):
    if r["jb"] == "default":
        return ("default",) + default_cfg
    return (r["jb"], r["jf"], r["js"])


def fmt_err(r, cfg=None):
    if r is None:
        return ""
    if r["status"] != "ok":
        return r["status"]
    e = r["err"]
    s = "%.3g" % e if e >= 0.001 else ("0" if e == 0 else "%.1e" % e)
    # a default row that ran on another basis (incline: sim:contact refuses
    # the default's and the case follows the refusal) says which
    if cfg and cfg[0] == "default" and r.get("basis") and r["basis"] != cfg[1]:
        s += " (on %s)" % r["basis"]
    return s


def fails(r, level, levels):
    if r is None:
        return False
    if r["status"] != "ok":
        return True
    lim = COARSE_TOL if level == levels[0] else FINE_TOL
    return level in (levels[0], levels[-1]) and r["err"] > lim


def order(r1, r2):
    if not r1 or not r2 or r1["status"] != "ok" or r2["status"] != "ok":
        return ""
    e1, e2 = r1["err"], r2["err"]
    if e1 <= 1e-9 or e2 <= 1e-9:
        return "exact" if max(e1, e2) <= 1e-9 else ""
    return "%.2f" % (math.log(e1 / e2) / math.log(r1["h"] / r2["h"]))


def cfg_name(cfg):
    if cfg[0] == "default":
        return "**default** (%s / %s / %s)" % cfg[1:]
    b, f, s = cfg
    name = "%s / %s / %s" % (b, f, s) if f != "-" else "%s / %s" % (b, s)
    if (b, f if f != "-" else "point", s) == PAPERS:
        name += " (papers')"
    return name


def main():
    out = sys.argv[1]
    seconds = jobs = None
    if "--seconds" in sys.argv:
        seconds = int(sys.argv[sys.argv.index("--seconds") + 1])
    if "--jobs" in sys.argv:
        jobs = int(sys.argv[sys.argv.index("--jobs") + 1])
    rows = load(out)
    # the default's resolved configuration, from any default run that printed it
    dcfg = {}
    for r in rows:
        if r["jb"] == "default" and r["status"] == "ok":
            dcfg.setdefault(r["force"] != "-", (r["basis"], r["force"], r["scheme"]))
    mem_default = dcfg.get(True, ("bspline2", "segment", "musl"))
    plain_default = dcfg.get(False, (mem_default[0], "-", mem_default[2]))
    levels = sorted({r["level"] for r in rows})
    cases = sorted({r["case"] for r in rows})
    quantities = {c: [] for c in cases}
    for r in rows:
        if r["quantity"] != "*" and r["quantity"] not in quantities[r["case"]]:
            quantities[r["case"]].append(r["quantity"])
    # expand a failed run (no line printed) to every quantity of its case
    membrane_case = {r["case"] for r in rows if r["jf"] in ("point", "segment")}
    table = {}
    for r in rows:
        membrane = r["case"] in membrane_case
        dc = mem_default if membrane else plain_default
        cfg = config_of(r, dc)
        qs = quantities[r["case"]] if r["quantity"] == "*" else [r["quantity"]]
        for q in qs or ["(none)"]:
            table[(r["case"], q, cfg, r["level"])] = r
    # CSV
    with open(os.path.join(out, "verification.csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["case", "quantity", "basis", "force", "scheme", "default", "level", "h", "value",
                    "exact", "err_pct", "status", "seconds"])
        for (c, q, cfg, l), r in sorted(table.items(), key=lambda kv: (kv[0][0], kv[0][1], str(kv[0][2]), kv[0][3])):
            b, f, s = cfg[-3:]
            w.writerow([c, q, b, f, s, "yes" if cfg[0] == "default" else "no", l, r.get("h", ""),
                        r.get("value", ""), r.get("exact", ""), r.get("err", ""), r["status"], r["seconds"]])
    total_cpu = sum(r["seconds"] for r in {id(r): r for r in rows}.values())
    try:
        commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                                text=True).stdout.strip()
    except OSError:
        commit = "?"
    # configurations in display order: default, papers', the rest
    def cfgs_of(case):
        cs = sorted({k[2] for k in table if k[0] == case}, key=lambda c: (
            c[0] != "default", (c[0], c[1] if c[1] != "-" else "point", c[2]) != PAPERS, c))
        # the explicit run of the default's configuration duplicates it: shown once when equal
        d = [c for c in cs if c[0] == "default"]
        keep = []
        for c in cs:
            if d and c[0] != "default" and c == d[0][1:]:
                same = all(table.get((case, q, c, l), {}).get("value") ==
                           table.get((case, q, d[0], l), {}).get("value")
                           for q in quantities[case] for l in levels)
                if same:
                    continue
            keep.append(c)
        return keep
    dup_same = dup_diff = 0
    for c in cases:
        d = [k for k in {k[2] for k in table if k[0] == c} if k[0] == "default"]
        if not d:
            continue
        vals = lambda cfg: [table.get((c, q, cfg, l), {}).get("value") for q in quantities[c] for l in levels]
        if d[0][1:] in {k[2] for k in table if k[0] == c}:
            if vals(d[0]) == vals(d[0][1:]):
                dup_same += 1
            else:
                dup_diff += 1
    dup_note = ("The explicit run of the default's combination gave the same values in %d of %d "
                "cases (shown once)%s." % (dup_same, dup_same + dup_diff,
                "; where it differs both rows are shown" if dup_diff else ""))
    L = []
    L.append("# Verification: closed-form problems (issue 30 item 1)\n")
    L.append("Generated by `scripts/verify/run.sh` (`report.py`) from the cases in "
             "`tests/verify/` — do not edit by hand. Each case is a short scenario whose exact "
             "answer is derived in its header comment; it prints one `verify ...` line per "
             "measured quantity. Every case is run on every documented combination of basis "
             "(`linear`, `gimp`, `bspline2`) × membrane force (`point`, `segment`; membrane "
             "cases only) × scheme (`musl`, `usl`), and once with no option at all (the "
             "**default**: %s / %s / %s for membranes), at levels %s (each case's header says what a "
             "level is; each level halves the cell). %s\n"
             % (mem_default + (", ".join(map(str, levels)), dup_note)))
    L.append("Error is 100 |value − exact| / scale per cent, scale = |exact| unless the case says "
             "otherwise (a quantity whose exact value is 0: per cent of a cell, of the energy "
             "released, of the gas points). **x** marks a miss of issue 30's bar: more than "
             "%g %% at the coarse level or %g %% at the fine one. *order* is the observed "
             "convergence order log(e1/e2)/log(h1/h2) between the first two levels. `failed` "
             "is a run the engine stopped (the reason given), `refused` a combination the engine "
             "refuses. *w* marks a run that warned on stderr naming its own case "
             "(src/lua/l_option_warn.c: an option the suite finds wrong for the kind of scene; "
             "the warnings each combination gave are listed under \"Which options fail which "
             "cases\").\n" % (COARSE_TOL, FINE_TOL))
    when = datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC")
    L.append("Run at commit `%s` on %s: %d runs in %s s of wall time with %s jobs at a time on this "
             "2-core machine (%.0f s summed over the runs).\n"
             % (commit, when, len({(r['case'], r['jb'], r['jf'], r['js'], r['level']) for r in rows}),
                seconds if seconds is not None else "?", jobs or "?", total_cpu))
    # summary: default and papers'
    L.append("## Summary: the default and the papers' scheme\n")
    hdr = "| case | quantity | " + " | ".join("default L%d" % l for l in levels) + " | order | " + \
          " | ".join("papers' L%d" % l for l in levels) + " | order |"
    L.append(hdr)
    L.append("|" + " --- |" * (2 * len(levels) + 4))
    readme = []
    for c in cases:
        dcs = [k for k in cfgs_of(c) if k[0] == "default"]
        pcs = [k for k in cfgs_of(c) if (k[0], k[1] if k[1] != "-" else "point", k[2]) == PAPERS]
        for q in quantities[c]:
            cells = []
            for cs in (dcs, pcs):
                rs = [table.get((c, q, cs[0], l)) if cs else None for l in levels]
                for l, r in zip(levels, rs):
                    mark = " **x**" if fails(r, l, levels) else ""
                    mark += " *w*" if warned(r) else ""
                    cells.append(fmt_err(r, cs[0] if cs else None) + mark)
                cells.append(order(rs[0], rs[1]) if len(rs) > 1 else "")
            L.append("| %s | %s | %s |" % (c, q, " | ".join(cells)))
            readme.append((c, q, cells))
    L.append("")
    # which options fail which cases
    L.append("## Which options fail which cases\n")
    L.append("Per combination, the quantities it misses (error above %g %% at level %d or above "
             "%g %% at level %d, or a failed / refused run); the error at the coarse / fine level "
             "in brackets.\n" % (COARSE_TOL, levels[0], FINE_TOL, levels[-1]))
    allcfg = []
    for c in cases:
        for k in cfgs_of(c):
            if k not in allcfg:
                allcfg.append(k)
    allcfg.sort(key=lambda c: (c[0] != "default", c[1] == "-", c))
    for k in allcfg:
        misses, npass, nall, warns = [], 0, 0, {}
        for c in cases:
            for q in quantities[c]:
                rs = [table.get((c, q, k, l)) for l in levels]
                if all(r is None for r in rs):
                    continue
                nall += 1
                for r in rs:
                    for what, named in (r or {}).get("warnings", ()):
                        w = warns.setdefault(what, [set(named), set()])
                        w[1].add(c)
                if any(fails(r, l, levels) for l, r in zip(levels, rs)):
                    w = " *w*" if any(warned(r) for r in rs) else ""
                    misses.append("%s %s (%s)%s" % (c, q, " / ".join(fmt_err(r, k) or "-" for r in rs), w))
                else:
                    npass += 1
        said = "".join(" Warned of in %d of its cases: `%s` (naming %s)." %
                       (len(w[1]), what, ", ".join(sorted(w[0])) or "no case")
                       for what, w in sorted(warns.items()))
        L.append("- %s: passes %d of %d.%s Misses: %s" % (cfg_name(k), npass, nall, said,
                                                          "; ".join(misses) if misses else "none"))
    L.append("")
    # the findings written by hand (what the numbers mean), when present
    notes = os.path.join(os.path.dirname(os.path.abspath(__file__)), "notes.md")
    if os.path.exists(notes):
        L.append(open(notes).read().rstrip() + "\n")
    # per case
    L.append("## Per case\n")
    for c in cases:
        L.append("### %s\n" % c)
        head = []
        for x in open(os.path.join("tests", "verify", c + ".lua")).read().splitlines():
            if not x.startswith("--"):
                break
            head.append(x[2:].strip())
        text = " ".join(head).replace("Verification case (issue 30 item 1): ", "")
        first = re.split(r"(?<=[a-z0-9)])\. ", text, 1)[0].rstrip(".")
        L.append("`tests/verify/%s.lua`: %s.\n" % (c, first))
        for q in quantities[c]:
            ex = next((table[k] for k in table if k[0] == c and k[1] == q and table[k].get("exact") is not None), None)
            hs = {}
            for k, r in table.items():
                if k[0] == c and r.get("h") is not None:
                    hs[k[3]] = r["h"]
            L.append("**%s** (exact %s; h = %s)\n" % (q, "%.6g" % ex["exact"] if ex else "?",
                                                      ", ".join("%.4g" % hs[l] for l in levels if l in hs)))
            L.append("| combination | " + " | ".join("L%d err %%" % l for l in levels) + " | order |")
            L.append("|" + " --- |" * (len(levels) + 2))
            for k in cfgs_of(c):
                rs = [table.get((c, q, k, l)) for l in levels]
                cells = [fmt_err(r, k) + (" **x**" if fails(r, l, levels) else "") +
                         (" *w*" if warned(r) else "") for l, r in zip(levels, rs)]
                L.append("| %s | %s | %s |" % (cfg_name(k), " | ".join(cells),
                                               order(rs[0], rs[1]) if len(rs) > 1 else ""))
            L.append("")
    open(DOC, "w").write("\n".join(L) + "\n")
    # README table: one row per case, its worst quantity on the default at the coarse level
    R = ["| case | quantity (the default's worst) | default, coarse | default, fine | papers', coarse | papers', fine |",
         "| --- | --- | --- | --- | --- | --- |"]
    n = len(levels)
    def badness(cell):
        m = re.match(r"([0-9.e+-]+)", cell)
        return float(m.group(1)) if m else float("inf")
    by_case = {}
    for c, q, cells in readme:
        by_case.setdefault(c, []).append((q, cells))
    for c in cases:
        q, cells = max(by_case.get(c, [("-", [""] * (2 * n + 2))]), key=lambda qc: badness(qc[1][0]))
        R.append("| %s | %s | %s | %s | %s | %s |" % (c, q, cells[0], cells[n - 1], cells[n + 1], cells[2 * n]))
    text = open("README.md").read()
    a, b = "<!-- accuracy:begin -->", "<!-- accuracy:end -->"
    if a in text and b in text:
        i, j = text.index(a) + len(a), text.index(b)
        text = text[:i] + "\n" + "\n".join(R) + "\n" + text[j:]
        open("README.md", "w").write(text)
    wrote = [DOC, os.path.join(out, "verification.csv")]
    if a in text:
        wrote.append("README.md")
    print("report.py: " + ", ".join(wrote))


if __name__ == "__main__":
    main()
