#!/usr/bin/env python3
"""The table of bench/compare.sh: cylroll's CPU times against the anchors', with
ratios (anchor time / cylroll time: above 1 means cylroll is faster).

Usage: python3 bench/ratios.py RESULTS_DIR
RESULTS_DIR holds cylroll.jsonl (benches/tasks.rs in CPU mode) and the files
the anchors of bench/anchors write (ts_mpfr.jsonl, boost.jsonl, flint.json,
mpmath.json, heyoka.json, T3_<tool>_<d>.txt), evals.json (ts_mpfr --count) and
mpfr_ops.md (this machine's MPFR costs, for the floor); reference.json and
T3_reference.txt are read from RESULTS_DIR, else from bench/anchors/ref.

For each anchor the fastest method whose value is correct to at least d - 5
digits is shown (methods that fail or lose digits are left out and listed).
cylroll's values were checked digit by digit against the references before
being timed (benches/tasks.rs), so every cylroll cell is correct.

T1r and T2r are cylroll's *proved* T1 and T2 (interval enclosures proving every
digit, `--rigorous`), compared with Arb's T1 and T2 (the only anchor whose
results are balls, i.e. proved); the other anchors are shown as n/a there.
"""

# proved tasks: the anchor task they are compared with, and the one anchor
# that proves its result
PROVED = {"T1r": "T1", "T2r": "T2"}
PROVED_TOOL = "flint"
import json
import os
import sys

import mpmath as mp

mp.mp.dps = 1200

TOOLS = [("c-mpfr", "C/MPFR tanh-sinh (ts_mpfr.c)"), ("boost", "Boost.Math"),
         ("flint", "Arb (python-flint)"), ("mpmath", "mpmath"), ("heyoka", "heyoka")]


def load(r):
    rows = []
    for tool in ("mpmath", "flint", "heyoka"):
        p = os.path.join(r, f"{tool}.json")
        if os.path.exists(p):
            rows += json.load(open(p))["rows"]
    p = os.path.join(r, "boost.jsonl")
    if os.path.exists(p):
        rows += [json.loads(l) for l in open(p) if l.startswith("{")]
    p = os.path.join(r, "ts_mpfr.jsonl")
    if os.path.exists(p):
        for l in open(p):
            if l.startswith("{"):
                j = json.loads(l)
                rows.append(dict(tool="c-mpfr", task="T1", digits=j["digits"],
                                 method=f"tanh-sinh raw+complement, {j['levels']} levels, {j['n_evals']} evals",
                                 value=j["value"], cpu_median_s=j["warm_cpu_s_best"],
                                 cold_s=j["cold_cpu_s"]))
    ours = {}
    p = os.path.join(r, "cylroll.jsonl")
    if os.path.exists(p):
        for l in open(p):
            if l.startswith("{"):
                j = json.loads(l)
                ours[(j["task"], j["digits"])] = j
    return rows, ours


def correct_digits(r, row, refs, t3ref):
    if row["task"] == "T3":
        p = os.path.join(r, f"T3_{row['tool']}_{row['digits']}.txt")
        if not os.path.exists(p):
            return None
        tab = [mp.mpf(x) for x in open(p)]
        if len(tab) != len(t3ref):
            return None
        e = max(abs(a - b) for a, b in zip(tab, t3ref))
        return 1300.0 if e == 0 else float(-mp.log10(e))
    try:
        v = mp.mpf(row["value"])
    except Exception:
        return None
    if not mp.isfinite(v):
        return None
    ref = refs[row["task"]]
    e = abs(v - ref) / abs(ref)
    return 1300.0 if e == 0 else float(-mp.log10(e))


def fmt(x):
    if x is None:
        return "-"
    if x < 1e-3:
        return f"{x * 1e6:.3g} µs"
    if x < 1:
        return f"{x * 1e3:.3g} ms"
    return f"{x:.3g} s"


def floor_ms(r):
    """Tanh-sinh floor of T1 on this machine: evaluations (dyadic h, raw
    integrand with exact complement, from evals.json) × (1 sin_cos + 1 sqrt +
    1 div + 12 mul) at this machine's MPFR costs (mpfr_ops.md)."""
    ev = os.path.join(r, "evals.json")
    ops = os.path.join(r, "mpfr_ops.md")
    if not (os.path.exists(ev) and os.path.exists(ops)):
        return {}
    counts = {row["digits"]: row["tsraw_dyadic_n"] for row in json.load(open(ev))["rows"]}
    cost = {}
    header = None
    for line in open(ops):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells and cells[0] == "digits":
            header = cells
            continue
        if header and cells and cells[0].isdigit():
            d = dict(zip(header, cells))
            ns = float(d["sin_cos ns"]) + float(d["sqrt ns"]) + float(d["div ns"]) + 12 * float(d["mul ns"])
            cost[int(cells[0])] = ns * 1e-9
    return {d: counts[d] * cost[d] for d in counts if d in cost}


ORDER = ["T1", "T2", "T2b", "T1r", "T2r", "T3", "T3rows"]


def anchor(best, task, d, tool):
    """The anchor's row for our task: for a proved task, Arb's row of the
    task it proves (None for the other tools)."""
    if task in PROVED:
        return best.get((PROVED[task], d, tool)) if tool == PROVED_TOOL else None
    return best.get((task, d, tool))


def print_header(cols):
    """A markdown table's header and rule."""
    print("| " + " | ".join(cols) + " |")
    print("|" + "---|" * len(cols))


REF_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "anchors", "ref")


def ref_file(r, name):
    p = os.path.join(r, name)
    return p if os.path.exists(p) else os.path.join(REF_DIR, name)


def main():
    r = sys.argv[1]
    ref = json.load(open(ref_file(r, "reference.json")))
    refs = {k: mp.mpf(ref[k]["mid"]) for k in ("T1", "T2", "T2b")}
    t3ref = [mp.mpf(x) for x in open(ref_file(r, "T3_reference.txt"))]
    rows, ours = load(r)
    floors = floor_ms(r)
    best = {}
    dropped = []
    for row in rows:
        if not row.get("cpu_median_s"):
            continue
        dig = correct_digits(r, row, refs, t3ref)
        key = (row["task"], row["digits"], row["tool"])
        if dig is None or dig < row["digits"] - 5:
            dropped.append((key, row["method"], dig))
            continue
        if key not in best or row["cpu_median_s"] < best[key]["cpu_median_s"]:
            best[key] = dict(row, correct=dig)
    if os.path.exists(os.path.join(r, "machine.txt")):
        print("```")
        print(open(os.path.join(r, "machine.txt")).read().strip())
        print("```")
        print()
    print("CPU time per task (median of warm repeats; C anchor: best of its repeats), and in")
    print("brackets the anchor's time over cylroll's: above 1 = cylroll faster.")
    print()
    print_header(["task", "digits", "cylroll"] + [name for _, name in TOOLS] + ["T1 tanh-sinh floor"])
    tasks = sorted({(t, d) for (t, d) in ours} | {(k[0], k[1]) for k in best},
                   key=lambda x: (ORDER.index(x[0]), x[1]))
    for task, d in tasks:
        o = ours.get((task, d))
        ot = o["cpu_median_s"] if o else None
        cells = [fmt(ot)]
        for tool, _ in TOOLS:
            b = anchor(best, task, d, tool)
            if task == "T3rows" or (task in PROVED and tool != PROVED_TOOL):
                # the anchors tabulate θ only; these rows add 12 verified columns
                cells.append("n/a")
            elif b is None:
                cells.append("-")
            else:
                ratio = f" (×{b['cpu_median_s'] / ot:.2g})" if ot else ""
                cells.append(fmt(b["cpu_median_s"]) + ratio)
        fl = floors.get(d) if task == "T1" else None
        cells.append(f"{fmt(fl)} (×{fl / ot:.2g})" if fl and ot else "-")
        name = {"T3": "T3 (θ only)", "T3rows": "T3 rows (13 columns)",
                "T1r": "T1 proved", "T2r": "T2 proved"}.get(task, task)
        print(f"| {name} | {d} | " + " | ".join(cells) + " |")
    print()
    print("T1 proved, T2 proved: cylroll's interval enclosures (`--rigorous`, every digit proved)")
    print("beside Arb's balls for T1 and T2; the other anchors prove nothing (n/a).")
    print()
    print("T3 rows: `Oracle::trajectory`, all 13 columns of `cylroll trajectory` (t, θ, θ̇, θ̈,")
    print("positions, F1, N1, F21, N12, energy…) verified at 1000 times; no anchor computes them,")
    print("so no ratio is given.")
    print()
    print("Cold: the first call in a fresh process state (cylroll: a fresh `Oracle`; C anchor: its")
    print("first integral, nodes generated; Boost: the integrator object built; Python anchors: the")
    print("first call, heyoka's including its JIT compilation), all CPU time, with the anchor's cold")
    print("over cylroll's cold.")
    print()
    print_header(["task", "digits", "cylroll cold"] + [name for _, name in TOOLS])
    for task, d in tasks:
        if task == "T3rows":
            continue
        o = ours.get((task, d))
        oc = o["cold_cpu_s"] if o else None
        cells = [fmt(oc)]
        for tool, _ in TOOLS:
            b = anchor(best, task, d, tool)
            c = (b.get("cold_s") or None) if b else None
            if c is None:
                cells.append("-")
            else:
                cells.append(fmt(c) + (f" (×{c / oc:.2g})" if oc else ""))
        name = {"T1r": "T1 proved", "T2r": "T2 proved"}.get(task, task)
        print(f"| {name} | {d} | " + " | ".join(cells) + " |")
    print()
    print("Anchor methods shown (fastest correct):")
    for (task, d, tool), b in sorted(best.items(), key=lambda x: (x[0][0], x[0][1], x[0][2])):
        print(f"- {task} {d} {tool}: {b['method']} ({b['correct']:.1f} correct digits)")
    if dropped:
        print()
        print("Left out (failed or fewer than d - 5 correct digits):")
        for (task, d, tool), m, dig in dropped:
            print(f"- {task} {d} {tool}: {m} ({'failed' if dig is None else f'{dig:.1f} digits'})")


if __name__ == "__main__":
    main()
