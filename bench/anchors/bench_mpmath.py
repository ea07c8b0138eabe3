#!/usr/bin/env python3
"""Anchor: mpmath (pure Python arbitrary precision) on the ideal tasks.

  T1   mp.quad (tanh-sinh) of dt/dv, theta = theta0 + v^2
  T2   mp.findroot (secant from 1.0) on the separation condition
  T3   mp.odefun (Taylor series with numerical derivatives) on theta'' = F(theta, theta'),
       evaluated at the 1000 times in increasing order (it keeps its expansions)
mp.dps = d; quad and odefun add their own guard digits.

Usage: python3 bench/anchors/bench_mpmath.py --out DIR [--digits 30,100,300,1000]
           [--t3-digits 30] [--tasks T1,T2,T2b,T3]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

common.in_venv(["mpmath"])
import mpmath as mp  # noqa: E402


def params(m2=1):
    k = mp.mpf(1) / 2
    return dict(k2=k, A=mp.mpf(m2) / ((1 + k) * (1 + m2)), gr=mp.mpf(1) / 2)


def rate(th0, P):
    k2, A, gr = P["k2"], P["A"], P["gr"]

    def f(v):
        h = v * v / 2
        M = 1 + k2 - A * (mp.cos(th0 + 2 * h) - k2) ** 2
        return 2 * mp.sqrt(M / (2 * gr * mp.sin(th0 + h) * mp.sinc(h)))
    return f


def sep_condition(P):
    k2, A, gr = P["k2"], P["A"], P["gr"]

    def G(x):
        c, s = mp.cos(x), mp.sin(x)
        M = 1 + k2 - A * (c - k2) ** 2
        w2 = 2 * gr * (1 - c) / M
        acc = (gr - A * (c - k2) * w2) * s / M
        return w2 - gr * c + A * s * ((c - k2) * acc - s * w2)
    return G


def t1():
    th0 = mp.mpf(1) / 10
    return mp.quad(rate(th0, params()), [0, mp.sqrt(mp.mpf(8) / 10)])


def t2(m2):
    return mp.findroot(sep_condition(params(m2)), mp.mpf(1))


def t3(t_end):
    P = params()
    k2, A, gr = P["k2"], P["A"], P["gr"]

    def F(t, y):
        th, w = y
        c, s = mp.cos(th), mp.sin(th)
        M = 1 + k2 - A * (c - k2) ** 2
        return [w, (gr - A * (c - k2) * w * w) * s / M]
    sol = mp.odefun(F, 0, [mp.mpf(1) / 10, mp.mpf(0)])
    T = mp.mpf(t_end)
    return [sol(T * i / 999)[0] for i in range(1000)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--digits", default="30,100,300,1000")
    ap.add_argument("--t3-digits", default="30")
    ap.add_argument("--tasks", default="T1,T2,T2b,T3")
    a = ap.parse_args()
    tasks = a.tasks.split(",")
    res = common.Results(a.out, "mpmath", f"mpmath {mp.__version__}")
    for d in common.digits_list(a.digits):
        mp.mp.dps = d
        if "T1" in tasks:
            v, c, _ = common.first_call(t1)
            v, cm, wm, n = common.measure(t1, max_runs=5 if d < 1000 else 3)
            res.add("T1", d, "quad tanh-sinh, theta = theta0 + v^2", mp.nstr(v, d + 5), c, cm, wm, n)
        for task, m2 in (("T2", 1), ("T2b", 2)):
            if task in tasks:
                v, c, _ = common.first_call(lambda: t2(m2))
                v, cm, wm, n = common.measure(lambda: t2(m2))
                res.add(task, d, "findroot secant from 1.0", mp.nstr(v, d + 5), c, cm, wm, n)
    if "T3" in tasks:
        t_end = common.load_ref()["T3"]["t_end"]
        for d in common.digits_list(a.t3_digits):
            mp.mp.dps = d
            tab, c, _ = common.first_call(lambda: t3(t_end))
            tab, cm, wm, n = common.measure(lambda: t3(t_end), min_runs=1, max_runs=3, budget_s=5)
            res.table(d, [mp.nstr(x, d + 5) for x in tab])
            res.add("T3", d, "odefun (Taylor), theta'' = F(theta, theta')", mp.nstr(tab[-1], d + 5), c, cm, wm, n)


if __name__ == "__main__":
    main()
