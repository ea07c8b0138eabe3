#!/usr/bin/env python3
"""The friction table of bench/compare.sh: cylroll's commands run as processes
(CPU of the process) beside heyoka cold and warm (bench/anchors/heyoka_friction.py),
with cylroll's library calls from `cargo bench --bench tasks -- t3_friction`
(divan, wall-time medians) where they exist, and the library's every-column /
θ-only pair timed in alternation (CPU, `CYLROLL_BENCH=cpu … -- T3friction_pair`).

Usage: python3 bench/anchors/friction_table.py RESULTS_DIR
reads RESULTS_DIR/heyoka_friction.json, RESULTS_DIR/cylroll_friction_divan.txt and
RESULTS_DIR/cylroll_friction_pair.jsonl (the last two where present).
"""
import json
import os
import re
import sys


def fmt(x):
    if x is None:
        return "-"
    if x < 1e-3:
        return f"{x * 1e6:.3g} µs"
    if x < 1:
        return f"{x * 1e3:.3g} ms"
    return f"{x:.3g} s"


UNIT = {"ns": 1e-9, "µs": 1e-6, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def divan(path):
    """{(bench, digits): median seconds} from divan's tree output."""
    out, bench = {}, None
    if not os.path.exists(path):
        return out
    for line in open(path, encoding="utf-8"):
        m = re.match(r"^[├╰]─ (\w+)\s", line)
        if m:
            bench = m.group(1)
            continue
        m = re.match(r"^[│ ]\s+[├╰]─ (\d+)\s+(.*)$", line)
        if m and bench:
            cells = [c.strip() for c in m.group(2).split("│")]
            if len(cells) >= 3:
                v, u = cells[2].split()
                out[(bench, int(m.group(1)))] = float(v) * UNIT[u]
    return out


def library_pairs(path):
    """{digits: the T3friction_pair record} from the benchmark's JSON lines."""
    out = {}
    if not os.path.exists(path):
        return out
    for line in open(path, encoding="utf-8"):
        line = line.strip()
        if line.startswith("{"):
            x = json.loads(line)
            if x.get("task") == "T3friction_pair":
                out[int(x["digits"])] = x
    return out


def main():
    r = sys.argv[1]
    res = json.load(open(os.path.join(r, "heyoka_friction.json")))
    lib = divan(os.path.join(r, "cylroll_friction_divan.txt"))
    print(f"heyoka {res['heyoka']}, {res['cylroll']}; case: {res['case']}; 1000 times t_i = i h, "
          f"h = {res['h']} (t_999 = {res['t_last']} = 0.99 t_s to 25 digits).")
    print()
    print("| task | digits | cylroll process CPU | heyoka cold CPU | heyoka warm CPU | cylroll / heyoka warm "
          "| heyoka cold / cylroll | digits agreeing | cylroll library (divan, wall) |")
    print("|---|---|---|---|---|---|---|---|---|")
    names = {"events": "events: slip onset + separation (`separation`)",
             "theta": "θ at 1000 times (`trajectory --times … --columns t,theta,mode`)",
             "rows": "1000 rows, every column (`trajectory --times`)"}
    lib_name = {"theta": "t3_friction", "rows": "t3_friction_rows"}
    digits = sorted(int(d) for d in res["per_digits"])
    for task in ("events", "theta", "rows"):
        for d in digits:
            row = res["per_digits"][str(d)].get(task)
            if row is None:
                continue
            lb = lib.get((lib_name.get(task, ""), d))
            if "error" in row:
                print(f"| {names[task]} | {d} | {fmt(row.get('cylroll_cpu_s'))} | {row['error'][:80]} | - | - | - "
                      f"| - | {fmt(lb)} |")
                continue
            cy, hc, hw = row["cylroll_cpu_s"], row["heyoka_cold_cpu_s"], row["heyoka_warm_cpu_s"]
            warm_n = f" ({row['heyoka_runs']} runs)" if row.get("heyoka_runs", 3) < 3 else ""
            print(f"| {names[task]} | {d} | {fmt(cy)} | {fmt(hc)} | {fmt(hw)}{warm_n} | {cy / hw:.2g} | {hc / cy:.2g} "
                  f"| {row['agreement_min']:.1f} | {fmt(lb)} |")
    alt = [(task, d, res["per_digits"][str(d)][task]["alternation"]) for task in ("events", "theta", "rows")
           for d in digits if "alternation" in res["per_digits"][str(d)].get(task, {})]
    if alt:
        print()
        print("| cylroll process / heyoka warm, timed in alternation | digits | pairs | cylroll process CPU "
              "| heyoka warm CPU | ratio of the medians | per pair, min–max |")
        print("|---|---|---|---|---|---|---|")
        for task, d, x in alt:
            print(f"| {names[task]} | {d} | {x['pairs']} | {fmt(x['cylroll_cpu_s'])} | {fmt(x['heyoka_warm_cpu_s'])} "
                  f"| {x['ratio']:.2f} | {x['ratio_min']:.2f}–{x['ratio_max']:.2f} |")
    paired = [(d, res["per_digits"][str(d)]["rows_over_theta"]) for d in digits
              if "rows_over_theta" in res["per_digits"][str(d)]]
    lib_pairs = library_pairs(os.path.join(r, "cylroll_friction_pair.jsonl"))
    if paired or lib_pairs:
        print()
        print("| every column / θ only, timed in alternation | digits | pairs | θ only | every column "
              "| ratio of the medians | per pair, min–max |")
        print("|---|---|---|---|---|---|---|")
        for d, x in paired:
            print(f"| cylroll process CPU | {d} | {x['pairs']} | {fmt(x['theta_cpu_s'])} | {fmt(x['rows_cpu_s'])} "
                  f"| {x['ratio']:.2f} | {x['ratio_min']:.2f}–{x['ratio_max']:.2f} |")
        for d, x in sorted(lib_pairs.items()):
            print(f"| cylroll library CPU (its own grid) | {d} | {x['pairs']} | {fmt(x['theta_cpu_median_s'])} "
                  f"| {fmt(x['rows_cpu_median_s'])} | {x['ratio']:.2f} "
                  f"| {x['pair_ratio_min']:.2f}–{x['pair_ratio_max']:.2f} |")
    print()
    print("cylroll process CPU: user + system of the command run as a process (median of "
          "its runs); it verifies every digit at two precisions, and `separation` also integrates "
          "the flight to the impact. heyoka: CPU of this process, cold = integrators built (JIT, "
          "caches emptied) + first run, warm = median of re-runs. Ratios above 1 in the first ratio "
          "column mean heyoka warm is faster; in the second, that cylroll's process is faster than "
          "heyoka's first call. In alternation: heyoka's warm run and the cylroll command one after "
          "the other in heyoka's process, the order swapped every pair (the same stretch of the machine). "
          "Digits agreeing: heyoka against cylroll's verified output (events: "
          "t and θ of both events; θ: all 1000 values; rows: every column, relative to the column's "
          "largest value). Library: divan's median wall time of the library call on its own grid "
          "(1000 times on [0, 4.920]), θ only (t3_friction) or every column (t3_friction_rows); the library pair: `oracle::theta_at_times` and `oracle::trajectory` on that grid, called in alternation in one process, on the command's allocator.")
    for d in digits:
        r_ = res["per_digits"][str(d)]
        for task in ("events", "theta", "rows"):
            if task in r_ and "agreement_digits" in r_[task]:
                ag = {k: ("exact" if v == 9999.0 else round(v, 1)) if isinstance(v, float) else v
                      for k, v in r_[task]["agreement_digits"].items()}
                print(f"- {task} {d}: {ag}")


if __name__ == "__main__":
    main()
