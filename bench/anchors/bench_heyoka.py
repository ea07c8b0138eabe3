#!/usr/bin/env python3
"""Anchor: heyoka (Taylor integrator, LLVM JIT, fp_type=real: MPFR) on T3, the
ideal rolling motion from rest at theta0 = 1/10:
    theta'' = [g/r - A (cos theta - k2) theta'^2] sin theta / M(theta),
propagate_grid over the 1000 times t_i = t_end i / 999 (t_end from
ref/reference.json: the other tools also compute t(theta_s) first, about 1-5% of
their T3 time). p = ceil(d log2 10) + 1 bits, default tolerance, compact mode.
cold = building the integrator (JIT) + the first propagation, heyoka's caches
emptied; warm = the median of re-propagations (time and state reset).

Usage: python3 bench/anchors/bench_heyoka.py --out DIR [--digits 30,100]
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

common.in_venv(["heyoka", "numpy"])
import heyoka as hy  # noqa: E402
import numpy as np  # noqa: E402


def build(prec):
    R = lambda x: hy.real(x, prec)  # noqa: E731
    th, w = hy.make_vars("th", "w")
    k2, A, gr = R(1) / R(2), R(1) / R(3), R(1) / R(2)
    c, s = hy.cos(th), hy.sin(th)
    M = hy.expression(R(1)) + k2 - A * (c - k2) ** 2
    return hy.taylor_adaptive([(th, w), (w, (gr - A * (c - k2) * w * w) * s / M)], [R(1) / R(10), R(0)],
                              fp_type=hy.real, compact_mode=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--digits", default="30,100")
    a = ap.parse_args()
    hy.llvm_state.set_diskcache_enabled(False)
    res = common.Results(a.out, "heyoka", f"heyoka {hy.__version__} (fp_type=real, compact mode)")
    t_end = common.load_ref()["T3"]["t_end"]
    for d in common.digits_list(a.digits):
        p = math.ceil(d * math.log2(10)) + 1
        R = lambda x: hy.real(x, p)  # noqa: E731
        T = R(t_end)
        grid = np.array([T * R(i) / R(999) for i in range(1000)])
        box = {}

        def run():
            ta = box["ta"]
            ta.time = R(0)
            ta.state[:] = [R(1) / R(10), R(0)]
            return ta.propagate_grid(grid)[-1][:, 0]

        def cold():
            hy.llvm_state.clear_memcache()
            box["ta"] = build(p)
            return run()
        tab, c, _ = common.first_call(cold)
        tab, cm, wm, n = common.measure(run)
        res.table(d, [str(x) for x in tab])
        res.add("T3", d, f"taylor_adaptive order {box['ta'].order}, compact mode", str(tab[-1]), c, cm, wm, n)


if __name__ == "__main__":
    main()
