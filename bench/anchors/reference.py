#!/usr/bin/env python3
"""The reference values of the ideal tasks, as Arb balls (python-flint), written
to bench/anchors/ref/: reference.json (T1, T2, T2b to 1100 digits with their
radii; T3's end time, last value and sum) and T3_reference.txt (T3's 1000
values, computed at 140 digits, printed to 135).

T3's end time t_end = 0.99 t(pi/3) (pi/3 is T2's root, the separation angle
for a start from theta = 0) is written with 135 digits; that decimal, taken as
exact, defines the grid t_i = t_end i / 999 that every anchor and cylroll's
benchmark use.

The files are committed; re-run only to regenerate them (about a minute):
    python3 bench/anchors/reference.py [--out bench/anchors/ref]
"""
import argparse
import json
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

common.in_venv(["flint"])
from flint import arb, ctx  # noqa: E402
import bench_flint as bf  # noqa: E402


def mid(x, d):
    return x.mid().str(d, radius=False)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", default=common.REF_DIR)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    start = time.time()
    out = {}
    ctx.dps = 1100
    th0 = arb(1) / 10
    v = bf.t1(th0, arb(9) / 10, bf.params())
    out["T1"] = dict(mid=mid(v, 1100), rad=v.rad().str(3, radius=False))
    r = bf.separation(bf.params())
    out["T2"] = dict(mid=mid(r, 1100), rad=r.rad().str(3, radius=False),
                     minus_pi_over_3=(r - arb.pi() / 3).str(3, radius=True))
    r = bf.separation(bf.params(2))
    out["T2b"] = dict(mid=mid(r, 1100), rad=r.rad().str(3, radius=False))
    ctx.dps = 200
    t_end = bf.t1(th0, arb.pi() / 3, bf.params()) * arb("0.99")
    t_end_s = mid(t_end, 135)
    print(f"T1, T2, T2b, t_end: {time.time() - start:.1f} s", file=sys.stderr)
    tab = bf.t3_table(t_end_s, 140, guard_bits=24)
    worst = max(x.rad() for x in tab)
    assert worst < arb(10) ** -137, worst
    ctx.dps = 150
    total = sum((arb(mid(x, 135)) for x in tab), arb(0))
    out["T3"] = dict(t_end=t_end_s, last=mid(tab[-1], 135), checksum_sum=mid(total, 135),
                     largest_radius=worst.str(3, radius=False),
                     table="T3_reference.txt (1000 lines, 135 significant digits, computed at 140 digits)")
    with open(os.path.join(a.out, "T3_reference.txt"), "w") as f:
        f.write("\n".join(mid(x, 135) for x in tab) + "\n")
    out["elapsed_s"] = round(time.time() - start, 1)
    with open(os.path.join(a.out, "reference.json"), "w") as f:
        json.dump(out, f, indent=1)
    print(f"done in {out['elapsed_s']} s", file=sys.stderr)


if __name__ == "__main__":
    main()
