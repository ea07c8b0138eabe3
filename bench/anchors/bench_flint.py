#!/usr/bin/env python3
"""Anchor: Arb (ball arithmetic, through python-flint) on the ideal tasks.

  T1   acb.integral of dt/dv, where theta = theta0 + v^2 (the square root at the
       start becomes analytic: cos th0 - cos th = 2 sin(th0 + h) sin h, h = v^2/2)
  T2   the separation condition G(theta) = 0: a bracket by sign changes at 53
       bits, then Newton steps on a length-2 arb_series, the root's ball checked
       by the signs of G at its ends
  T3   Arb has no ODE solver: theta(t_i) by Newton in v on t(v), integrating
       from the previous point each time (acb.integral), 10 guard bits
Also the functions reference.py uses for the references.

Usage: python3 bench/anchors/bench_flint.py --out DIR [--digits 30,100,300,1000]
           [--t3-digits 30,100] [--tasks T1,T2,T2b,T3]
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

common.in_venv(["flint"])
import flint  # noqa: E402
from flint import acb, arb, arb_series, ctx  # noqa: E402


def params(m2=1):
    """Identical solid cylinders (m1 = r1 = r2 = g = 1, k = 1/2), upper mass m2:
    k2, A = m2/((1+k1)m1 + (1+k2)m2) and g/r."""
    k = arb(1) / 2
    A = arb(m2) / ((1 + k) + (1 + k) * m2)
    return dict(k2=k, A=A, gr=arb(1) / 2)


def rate(th0, P):
    """dt/dv along the rolling motion from rest at th0, theta = th0 + v^2:
    2 sqrt(M / (2 (g/r) sin(th0 + h) sinc h)), h = v^2 / 2 (analytic at v = 0)."""
    k2, A, gr = P["k2"], P["A"], P["gr"]

    def f(v, analytic=False):
        h = v * v / 2
        c = (th0 + 2 * h).cos()
        M = 1 + k2 - A * (c - k2) ** 2
        return 2 * (M / (2 * gr * (th0 + h).sin() * h.sinc())).sqrt(analytic=analytic)
    return f


def sep_condition(x, P):
    """The separation condition (paper eq. 37 over r) for a start from rest at 0;
    x an arb or an arb_series."""
    k2, A, gr = P["k2"], P["A"], P["gr"]
    c, s = x.cos(), x.sin()
    M = 1 + k2 - A * (c - k2) ** 2
    w2 = 2 * gr * (1 - c) / M
    acc = (gr - A * (c - k2) * w2) * s / M
    return w2 - gr * c + A * s * ((c - k2) * acc - s * w2)


def t1(th0, th1, P):
    f = rate(th0, P)
    return acb.integral(lambda z, a: f(z, a), 0, (th1 - th0).sqrt()).real


def separation(P):
    """theta_s as a ball: bracket, Newton at the working precision, then the
    ball [x - e, x + e] checked by a sign change of G at its ends."""
    prec = ctx.prec
    ctx.prec = 53
    try:
        lo, hi, n = arb("0.5"), arb("1.5"), 64
        xs = [lo + (hi - lo) * i / n for i in range(n + 1)]
        g = [sep_condition(x, P) for x in xs]
        br = [i for i in range(n) if (g[i] < 0 and g[i + 1] > 0) or (g[i] > 0 and g[i + 1] < 0)]
        assert len(br) == 1, "one sign change expected"
        x = float((xs[br[0]] + xs[br[0] + 1]).mid()) / 2
    finally:
        ctx.prec = prec
    x = arb(x)
    for _ in range(200):
        s = sep_condition(arb_series([x, 1], prec=2), P).coeffs()
        step = (s[0] / s[1]).mid()
        x = arb(x.mid() - step)
        if abs(float(step)) < 2.0 ** (-prec + 8) or step == 0:
            break
    e = arb(2) ** (-prec + 12)
    ga, gb = sep_condition(x - e, P), sep_condition(x + e, P)
    if not ((ga < 0 and gb > 0) or (ga > 0 and gb < 0)):
        raise ArithmeticError("no sign change around the Newton root")
    return arb(x.mid(), e)


class Theta:
    """theta at increasing times by Newton in v on t(v), incremental quadrature."""

    def __init__(self, th0, P):
        self.th0, self.f = th0, rate(th0, P)
        self.v, self.t = arb(0), arb(0)
        self.hist = []  # the last points (t, v), for the seed

    def seed(self, t):
        h = self.hist
        if len(h) >= 3:  # quadratic extrapolation in t
            (ta, va), (tb, vb), (tc, vc) = h[-3:]
            v = (va * (t - tb) * (t - tc) / ((ta - tb) * (ta - tc))
                 + vb * (t - ta) * (t - tc) / ((tb - ta) * (tb - tc))
                 + vc * (t - ta) * (t - tb) / ((tc - ta) * (tc - tb)))
        else:  # one Euler step
            v = self.v + (t - self.t) / self.f(acb(self.v)).real
        return arb(v.mid())

    def at(self, t, tol):
        f, v0, t0 = self.f, self.v, self.t
        if t == 0:
            self.hist.append((t, arb(0)))
            return self.th0
        v = self.seed(t)
        for _ in range(60):
            piece = acb.integral(lambda z, a: f(z, a), v0, v).real
            rate_v = f(acb(v)).real
            step = ((t0 + piece - t) / rate_v).mid()
            if abs(step) < tol:
                # t(v - step) = t(v) - step t'(v) + O(step^2): no further quadrature
                self.v, self.t = arb(v.mid() - step), t0 + piece - step * rate_v
                break
            v = arb(v.mid() - step)
        else:
            raise ArithmeticError("Newton did not converge")
        self.hist = self.hist[-2:] + [(t, self.v)]
        return self.th0 + self.v * self.v


def t3_table(t_end, d, guard_bits=10, points=1000):
    ctx.prec = math.ceil(d * math.log2(10)) + guard_bits
    th = Theta(arb(1) / 10, params())
    T = arb(t_end)
    tol = arb(10) ** (-(d + 2))
    return [th.at(T * i / (points - 1), tol) for i in range(points)]


def text(x, d):
    return x.mid().str(d + 5, radius=False)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--digits", default="30,100,300,1000")
    ap.add_argument("--t3-digits", default="30,100")
    ap.add_argument("--tasks", default="T1,T2,T2b,T3")
    a = ap.parse_args()
    tasks = a.tasks.split(",")
    res = common.Results(a.out, "flint", f"python-flint {flint.__version__}")
    for d in common.digits_list(a.digits):
        if "T1" in tasks:
            ctx.dps = d
            P, th0, th1 = params(), arb(1) / 10, arb(9) / 10
            v, c, _ = common.first_call(lambda: t1(th0, th1, P))
            v, cm, wm, n = common.measure(lambda: t1(th0, th1, P))
            res.add("T1", d, "acb.integral, theta = theta0 + v^2", text(v, d), c, cm, wm, n,
                    radius=v.rad().str(3, radius=False))
        for task, m2 in (("T2", 1), ("T2b", 2)):
            if task in tasks:
                ctx.dps = d
                P = params(m2)
                v, c, _ = common.first_call(lambda: separation(P))
                v, cm, wm, n = common.measure(lambda: separation(P))
                res.add(task, d, "bracket + Newton on arb_series, sign check", text(v, d), c, cm, wm, n,
                        radius=v.rad().str(3, radius=False))
    if "T3" in tasks:
        t_end = common.load_ref()["T3"]["t_end"]
        for d in common.digits_list(a.t3_digits):
            tab, c, _ = common.first_call(lambda: t3_table(t_end, d))
            tab, cm, wm, n = common.measure(lambda: t3_table(t_end, d), min_runs=1, max_runs=3, budget_s=5)
            res.table(d, [text(x, d) for x in tab])
            res.add("T3", d, "Newton in v on incremental acb.integral, 10 guard bits",
                    text(tab[-1], d), c, cm, wm, n)
    ctx.dps = 15


if __name__ == "__main__":
    main()
