#!/usr/bin/env python3
"""Anchor for the frictional motion: heyoka (Taylor integrator, LLVM JIT, MPFR
reals) beside the `cylroll` command, on this machine, in one run.

The case (cylroll's frictional main case): identical solid cylinders, m1 = m2 =
r1 = r2 = g = 1, k1 = k2 = 1/2, Coulomb friction mu = 3/10 at the floor and
between the cylinders, from rest at theta0 = 1/10 (x1 = phi1 = 0). Both
contacts stick at first; the contact between the cylinders reaches its cone
(F21 = -mu N12) and slips forward (s12 > 0) while the floor still sticks; then
N12 = 0: separation.

The equations are derived here (sympy, exact rationals): Newton-Euler for both
cylinders, eight unknowns (x1'', phi1'', theta'', psi2'', F1, N1, F21, N12), six
balance equations and two closures per mode (a sticking contact: its slip
acceleration is 0; a slipping one: F = -mu N sgn s). Each mode's accelerations
and forces are rational functions of sin theta, cos theta and theta'; heyoka gets
them with integer coefficients (exact at every precision).

What a heyoka user would write, timed as CPU time of this process (the machine
may be shared; CPU medians are the steadier figure):
  events  from the start to separation: mode "stick/stick" with terminal events
          for every way it can end (the contact cone either way, the floor cone
          either way, N12 = 0), then "stick/slip+" from the slip onset (N12 = 0,
          the floor cone, the slip speed s12 returning to 0); the times and
          angles of the slip onset and of separation
  theta   theta at 1000 times t_i = i h (h = 0.99 t_s / 999 cut to 25 digits,
          so every t_i is an exact short decimal) through the same modes
          (propagate_grid), state (theta, theta', s12)
  rows    the same times, every column `cylroll trajectory` prints (t, theta,
          theta', theta'', phi1, phi2, x1, x2, y2, F1, N1, F21, N12, s1, s12,
          work): the full state (9 variables, the dissipated work as one of
          them) and a compiled function (cfunc) per mode for the rest
"cold" is the first call: building the integrators (JIT compilation, heyoka's
caches emptied and its disk cache off) and the run; "warm" is the median of
repeated runs with the same integrators (time and state reset). Python start-up,
imports and the sympy derivation are not counted (reported once).

The `cylroll` commands are run as processes in the same run, CPU = user +
system of the child (as /usr/bin/time reports it), median of 15 repeats up to
100 digits (a 30 ms process measured 5 times on a shared machine could land
on a busy stretch: 26 ms and 33 ms were medians of the same command in one
run), 3 above:
  cylroll separation --theta0 1/10 --mu-floor 0.3 --mu-contact 0.3 --digits D --format json
  cylroll trajectory ... --times t0,t1,...,t999 --digits D --format csv --columns t,theta,mode
  cylroll trajectory ... --times t0,t1,...,t999 --digits D --format csv
The first (theta alone, no force computed) is the cylroll side of the theta task,
the second (every column) of the rows task. Each heyoka child then times its
warm run and the task's cylroll command in alternation (15 pairs up to 100
digits, 5 above; `--pairs`), so that the ratio of the two is read from one
stretch of the machine: the ratio of the medians and each pair's own.

Agreement: heyoka's event times and angles, its 1000 thetas and (rows) every
column against cylroll's verified digits; digits = -log10 of the largest error
(relative for t and theta, relative to the column's largest magnitude for the
other columns).

Precision: p = ceil(D log2 10) + 10 bits, heyoka's default tolerance (the
epsilon of p bits), compact mode.

Each heyoka measurement (a task at D digits) runs in a fresh interpreter, stopped
after --time-limit seconds (then the row says so).

Usage (from the project root; builds target/bench-venv on first use):
  python3 bench/anchors/heyoka_friction.py --digits 30,100,300,1000 [--rows-digits 30,100]
      [--tasks events,theta,rows] [--out FILE.json] [--cylroll-reps 15] [--pairs 15] [--time-limit 900]
Needs target/release/cylroll (cargo build --release) or CYLROLL_BIN.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

common.in_venv(["heyoka", "sympy", "mpmath", "numpy"])

import argparse  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import resource  # noqa: E402
import statistics  # noqa: E402
import subprocess  # noqa: E402
import time  # noqa: E402
from decimal import ROUND_DOWN, Decimal, localcontext  # noqa: E402

import heyoka as hy  # noqa: E402
import mpmath as mp  # noqa: E402
import numpy as np  # noqa: E402
import sympy as sp  # noqa: E402

CYLROLL = os.environ.get("CYLROLL_BIN", os.path.join(common.ROOT, "target", "release", "cylroll"))
CASE = ["--theta0", "1/10", "--mu-floor", "0.3", "--mu-contact", "0.3"]
NPOINTS = 1000
mp.mp.dps = 1100
GUARD_BITS = 10
COLUMNS = ["t", "theta", "theta_dot", "theta_ddot", "phi1", "phi2", "x1", "x2", "y2",
           "F1", "N1", "F21", "N12", "s1", "s12", "work"]

# ------------------------------------------------------------------ the mechanics

R = sp.Rational
PAR = dict(m1=1, m2=1, r1=1, r2=1, g=1, k1=R(1, 2), k2=R(1, 2), mu=R(3, 10))
S, C, W = sp.symbols("S C W")  # sin theta, cos theta, theta'
UNKNOWNS = sp.symbols("x1dd phi1dd thdd psi2dd F1 N1 F21 N12")


def mode_solution(mode):
    """Accelerations and forces of a mode as rational functions of S, C, W.

    Cylinder 2's centre is cylinder 1's plus r (S, C), r = r1 + r2; n = (S, C),
    t = (C, -S). Cylinder 1's force on 2 is N12 n + F21 t, at cylinder 2's point
    -r2 n; the floor's force on 1 is (F1, N1) at (0, -r1). phi1 turns clockwise,
    psi2 counter-clockwise. Slip speeds: s1 = x1' - r1 phi1' (floor) and
    s12 = r theta' + r2 psi2' - r1 phi1' (cylinder 2's contact point over 1's,
    along t)."""
    m1, m2, r1, r2, g, k1, k2, mu = (PAR[k] for k in ("m1", "m2", "r1", "r2", "g", "k1", "k2", "mu"))
    r = r1 + r2
    x1dd, phi1dd, thdd, psi2dd, F1, N1, F21, N12 = UNKNOWNS
    # cylinder 2's centre acceleration: (x1'', 0) + r (thdd t - W^2 n)
    a2x = x1dd + r * (thdd * C - W**2 * S)
    a2y = r * (-thdd * S - W**2 * C)
    eqs = [
        m2 * a2x - (N12 * S + F21 * C),               # cylinder 2, x
        m2 * a2y - (N12 * C - F21 * S - m2 * g),      # cylinder 2, y
        k2 * m2 * r2**2 * psi2dd - r2 * F21,          # cylinder 2 turns (ccw) under r2 F21
        m1 * x1dd - (F1 - N12 * S - F21 * C),         # cylinder 1, x
        N1 - m1 * g - N12 * C + F21 * S,              # cylinder 1 stays on the floor
        k1 * m1 * r1**2 * phi1dd + r1 * (F1 + F21),   # cylinder 1 turns (cw)
    ]
    floor, contact = mode
    eqs.append(x1dd - r1 * phi1dd if floor == "stick" else F1 + (mu * N1 if floor == "slip+" else -mu * N1))
    if contact == "stick":
        eqs.append(r * thdd + r2 * psi2dd - r1 * phi1dd)
    else:
        eqs.append(F21 + (mu * N12 if contact == "slip+" else -mu * N12))
    A, b = sp.linear_eq_to_matrix(eqs, UNKNOWNS)
    sol = A.LUsolve(b)
    return {str(u): sp.cancel(sp.together(sol[i])) for i, u in enumerate(UNKNOWNS)}


def integer_fraction(e):
    """e = num / den with num, den polynomials in S, C, W with integer coefficients."""
    num, den = sp.fraction(sp.cancel(sp.together(e)))
    cn, pn = sp.Poly(num, S, C, W).clear_denoms()  # pn = cn num
    cd, pd = sp.Poly(den, S, C, W).clear_denoms()  # pd = cd den
    return sp.Poly(pn.as_expr() * cd, S, C, W), sp.Poly(pd.as_expr() * cn, S, C, W)


def hy_poly(p, s, c, w):
    """A heyoka expression for an integer polynomial in S, C, W (exact coefficients)."""
    terms = []
    for (i, j, k), coef in p.terms():
        t = hy.expression(float(int(coef)))
        assert int(coef) == float(int(coef))
        for base, n in ((s, i), (c, j), (w, k)):
            if n:
                t = t * (base if n == 1 else base**n)
        terms.append(t)
    return hy.sum(terms) if len(terms) > 1 else terms[0]


def hy_rational(e, s, c, w, numerator_only=False):
    num, den = integer_fraction(e)
    n = hy_poly(num, s, c, w)
    return n if numerator_only else n / hy_poly(den, s, c, w)


MODES = {"stick/stick": ("stick", "stick"), "stick/slip+": ("stick", "slip+"), "stick/slip-": ("stick", "slip-")}


class Model:
    """Per mode: the sympy solution, heyoka right-hand sides and event functions."""

    def __init__(self):
        self.sol = {m: mode_solution(fc) for m, fc in MODES.items()}
        self.mu = PAR["mu"]

    def events(self, mode, s, c, w, s12):
        """(expression, direction, what happens) for every way the mode can end;
        numerators only (the denominators keep their sign)."""
        z = self.sol[mode]
        mu = self.mu
        ev = []
        if mode == "stick/stick":
            ev.append((z["F21"] + mu * z["N12"], None, ("slip_onset", "stick/slip+")))
            ev.append((z["F21"] - mu * z["N12"], None, ("slip_onset", "stick/slip-")))
        ev.append((z["F1"] + mu * z["N1"], None, ("floor slip_onset (not modelled here)", None)))
        ev.append((z["F1"] - mu * z["N1"], None, ("floor slip_onset (not modelled here)", None)))
        ev.append((z["N12"], None, ("separation", None)))
        out = [(hy_rational(e, s, c, w, numerator_only=True), d, what) for e, d, what in ev]
        if mode != "stick/stick":
            d = hy.event_direction.negative if mode == "stick/slip+" else hy.event_direction.positive
            out.append((s12, d, ("stick or slip reversal (not modelled here)", None)))
        return out


class Integrators:
    """heyoka integrators per mode at p bits, built on first use (the JIT)."""

    def __init__(self, model, prec, full):
        self.model, self.prec, self.full, self.ta, self.cf = model, prec, full, {}, {}
        self.what = {}

    def real(self, x):
        return hy.real(x, self.prec)

    def vars_and_rhs(self, mode):
        z = self.model.sol[mode]
        if not self.full:
            th, w, s12 = hy.make_vars("th", "w", "s12")
            s, c = hy.sin(th), hy.cos(th)
            rhs = [(th, w), (w, hy_rational(z["thdd"], s, c, w))]
            sv = s12
            if mode != "stick/stick":  # s12' = r thdd + r2 psi2dd - r1 phi1dd (r = 2)
                rhs.append((s12, hy_rational(2 * z["thdd"] + z["psi2dd"] - z["phi1dd"], s, c, w)))
            return rhs, (s, c, w, sv)
        th, w, x1, v1, p1, q1, y2, u2, wk = hy.make_vars("th", "w", "x1", "v1", "p1", "q1", "y2", "u2", "wk")
        s, c = hy.sin(th), hy.cos(th)
        sv = 2 * w + u2 - q1
        if mode == "stick/stick":
            dwork = hy.expression(0.)
        else:  # the work of sliding friction, mu N12 |s12| (s12 > 0 in slip+)
            sign = 1 if mode == "stick/slip+" else -1
            dwork = hy_rational(sign * self.model.mu * z["N12"], s, c, w) * sv
        rhs = [(th, w), (w, hy_rational(z["thdd"], s, c, w)), (x1, v1), (v1, hy_rational(z["x1dd"], s, c, w)),
               (p1, q1), (q1, hy_rational(z["phi1dd"], s, c, w)), (y2, u2), (u2, hy_rational(z["psi2dd"], s, c, w)),
               (wk, dwork)]
        return rhs, (s, c, w, sv)

    def get(self, mode):
        if mode not in self.ta:
            rhs, (s, c, w, sv) = self.vars_and_rhs(mode)
            evs, whats = [], []
            for e, d, what in self.model.events(mode, s, c, w, sv):
                kw = {} if d is None else {"direction": d}
                evs.append(hy.t_event(e, fp_type=hy.real, **kw))
                whats.append(what)
            n = len(rhs)
            self.ta[mode] = hy.taylor_adaptive(rhs, [self.real(0)] * n, fp_type=hy.real, compact_mode=True,
                                               t_events=evs)
            self.what[mode] = whats
        return self.ta[mode]

    def columns(self, mode):
        """A compiled function of the 9 state variables: the 16 columns but t."""
        if mode not in self.cf:
            z = self.model.sol[mode]
            th, w, x1, v1, p1, q1, y2, u2, wk = hy.make_vars("th", "w", "x1", "v1", "p1", "q1", "y2", "u2", "wk")
            s, c = hy.sin(th), hy.cos(th)
            f = lambda k: hy_rational(z[k], s, c, w)  # noqa: E731
            outs = [th, w, f("thdd"), p1, y2 + th, x1, x1 + 2. * s, 1. + 2. * c,
                    f("F1"), f("N1"), f("F21"), f("N12"), v1 - q1, 2. * w + u2 - q1, wk]
            self.cf[mode] = hy.cfunc(outs, [th, w, x1, v1, p1, q1, y2, u2, wk], fp_type=hy.real, prec=self.prec)
        return self.cf[mode]

    def start(self, ta):
        """Rest at theta0 = 1/10; x1 = phi1 = 0, phi2 = 0 (cylroll's gauge: every body angle
        counted from the start), so psi2 = phi2 - theta = -theta0."""
        st = [self.real("0.1"), self.real(0)]
        if self.full:
            st = [self.real("0.1"), self.real(0), self.real(0), self.real(0), self.real(0), self.real(0),
                  self.real("-0.1"), self.real(0), self.real(0)]
        ta.time = self.real(0)
        ta.state[:] = st
        ta.reset_cooldowns()

    def switch(self, ta, mode):
        """The next mode's integrator from the event's time and state (s12 = 0)."""
        nxt = self.get(mode)
        st = ta.state.copy()
        nxt.time = ta.time
        if not self.full:
            st = np.append(st[:2], self.real(0))
        nxt.state[:] = st
        nxt.reset_cooldowns()
        return nxt


def stopped_by(ints, mode, res):
    oc = int(res[0])
    if oc >= 0 or oc < -100:
        return None
    return ints.what[mode][-1 - oc]


def spurious(ints, ta, what, t_switch):
    """A slipping mode starts with s12 = 0 and s12' = 0 (the force is continuous
    at the slip onset): the slip-stop event may fire within rounding of the
    switch. Such a stop is skipped (heyoka then keeps the event in cooldown)."""
    if not what[0].startswith("stick or slip reversal") or t_switch is None:
        return False
    return mp.mpf(str(ta.time - t_switch)) < mp.mpf(2) ** (-ints.prec // 2)


def run_events(ints):
    mode, ta = "stick/stick", ints.get("stick/stick")
    ints.start(ta)
    events, t_switch = [], None
    while True:
        res = ta.propagate_until(ints.real(100))
        what = stopped_by(ints, mode, res)
        if what is None:
            raise RuntimeError(f"{mode}: no event before t = 100")
        if spurious(ints, ta, what, t_switch):
            continue
        events.append(dict(kind=what[0], t=ta.time, theta=ta.state[0], mode=mode))
        if what[1] is None:
            return events
        ta, mode, t_switch = ints.switch(ta, what[1]), what[1], ta.time


def run_grid(ints, grid_text):
    """State at the times (strings) through the modes; returns (states, modes)."""
    grid = np.array([ints.real(x) for x in grid_text])
    mode, ta = "stick/stick", ints.get("stick/stick")
    ints.start(ta)
    out, modes, i, t_switch = [], [], 0, None
    while i < len(grid):
        # heyoka's grid starts at the integrator's time
        first = i == 0
        res = ta.propagate_grid(grid[i:] if first else np.concatenate(([ta.time], grid[i:])))
        rows = res[-1] if first else res[-1][1:]
        what = stopped_by(ints, mode, res)
        n = len(grid) - i
        if what is not None:  # the rows before the event's time
            n = sum(1 for g in grid[i:] if g < ta.time)
        out.extend(rows[:n])
        modes.extend([mode] * n)
        i += n
        if what is None:
            break
        if spurious(ints, ta, what, t_switch):
            continue
        if what[1] is None:
            raise RuntimeError(f"{what[0]} at t = {ta.time} before the last time")
        ta, mode, t_switch = ints.switch(ta, what[1]), what[1], ta.time
    return out, modes


def run_theta(ints, grid_text):
    states, _ = run_grid(ints, grid_text)
    return [st[0] for st in states]


def run_rows(ints, grid_text):
    states, modes = run_grid(ints, grid_text)
    rows = [None] * len(states)
    for mode in sorted(set(modes)):
        idx = [k for k, m in enumerate(modes) if m == mode]
        inp = np.ascontiguousarray(np.array([states[k] for k in idx]).T)  # 9 x n
        vals = ints.columns(mode)(inp)
        for j, k in enumerate(idx):
            rows[k] = [grid_text[k]] + [vals[q][j] for q in range(vals.shape[0])] + [mode]
    return rows

# ------------------------------------------------------------------ cylroll, agreement


def cylroll(args):
    """(stdout, CPU s of the process, wall s)."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    w = time.perf_counter()
    cp = subprocess.run([CYLROLL] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - w
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if cp.returncode != 0:
        raise RuntimeError(f"cylroll {' '.join(args[:2])}: {cp.stderr[:500]}")
    return cp.stdout, (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime), wall


def cylroll_timed(args, reps):
    out, cpus, walls = None, [], []
    for _ in range(reps):
        out, c, w = cylroll(args)
        cpus.append(c)
        walls.append(w)
    return out, statistics.median(cpus), statistics.median(walls), reps


def grid(t_s):
    """h = 0.99 t_s / 999 cut to 25 significant digits; t_i = i h, exact decimals."""
    with localcontext() as ctx:
        ctx.prec = 80
        h = Decimal(t_s) * Decimal("0.99") / 999
        e = h.adjusted()
        h = h.quantize(Decimal(1).scaleb(e - 24), rounding=ROUND_DOWN)
        return str(h), [str(h * i) if i else "0" for i in range(NPOINTS)]


def agree(a, b, scale=None):
    """Digits of agreement: -log10 |a - b| / (|b| or scale)."""
    a, b = mp.mpf(str(a)), mp.mpf(str(b))
    d = abs(a - b) / (scale if scale is not None else abs(b))
    return 9999.0 if d == 0 else float(-mp.log10(d))


def parse_csv(text):
    lines = text.strip().splitlines()
    head = lines[0].split(",")
    return head, [ln.split(",") for ln in lines[1:]]


def agreement_rows(h_rows, csv_text, theta_only=False):
    head, rows = parse_csv(csv_text)
    assert len(rows) == len(h_rows) == NPOINTS, (len(rows), len(h_rows))
    cols = ["theta"] if theta_only else COLUMNS[1:]
    out = {}
    for name in cols:
        j = head.index(name)
        k = COLUMNS.index(name)
        ours = [mp.mpf(r[j]) for r in rows]
        if name == "theta":
            out[name] = min(agree(hr[k] if not theta_only else hr, o) for hr, o in zip(h_rows, ours))
        else:
            scale = max(max(abs(x) for x in ours), mp.mpf(1) / 10**6)
            out[name] = min(agree(hr[k], o, scale) for hr, o in zip(h_rows, ours))
    if not theta_only:
        jm = head.index("mode")
        out["modes_equal"] = all(r[jm] == hr[-1] for r, hr in zip(rows, h_rows))
    return out

# ------------------------------------------------------------------ main


def measure_task(build, task, cold_reps, min_runs, budget):
    """heyoka cold (median of cold_reps fresh builds) and warm (median of repeats)."""
    colds, ints, val = [], None, None
    for _ in range(cold_reps):
        hy.llvm_state.clear_memcache()
        c = common.cpu()
        ints = build()
        val = task(ints)
        colds.append(common.cpu() - c)
    val, cm, wm, n = common.measure(lambda: task(ints), min_runs=min_runs, max_runs=9, budget_s=budget)
    return val, statistics.median(colds), cm, n, ints


def alternate(run_heyoka, cyl_args, pairs):
    """heyoka's warm run and the cylroll command timed in alternation (heyoka
    first in the even pairs, cylroll in the odd ones), so that both figures
    sample the same stretch of a shared machine: CPU medians of each, the ratio
    of the medians, and each pair's own ratio's range."""
    hs, cs = [], []
    for k in range(pairs):
        for which in ((0, 1) if k % 2 == 0 else (1, 0)):
            if which == 0:
                c = common.cpu()
                run_heyoka()
                hs.append(common.cpu() - c)
            else:
                cs.append(cylroll(cyl_args)[1])
    per_pair = [c / h for c, h in zip(cs, hs)]
    return dict(pairs=pairs, heyoka_warm_cpu_s=statistics.median(hs), cylroll_cpu_s=statistics.median(cs),
                ratio=statistics.median(cs) / statistics.median(hs), ratio_min=min(per_pair),
                ratio_max=max(per_pair))


def child(d, task, times_file, out_file, cold_reps, cyl_file=None):
    """One heyoka measurement (a task at d digits) in its own process: the parent
    can stop it at its time limit. Writes the timings and the values as JSON;
    with `cyl_file` (the cylroll command's arguments and the pairs, as JSON),
    also heyoka's warm run and that command timed in alternation."""
    hy.llvm_state.set_diskcache_enabled(False)
    c = common.cpu()
    model = Model()
    derive_s = common.cpu() - c
    times = open(times_file).read().split(",")
    p = math.ceil(d * math.log2(10)) + GUARD_BITS
    min_runs = 3 if d <= 300 else 1
    budget = 15.0 if d <= 100 else 5.0
    full = task == "rows"
    fn = {"events": run_events, "theta": lambda i: run_theta(i, times), "rows": lambda i: run_rows(i, times)}[task]
    val, cold, warm, n, ints = measure_task(lambda: Integrators(model, p, full), fn, cold_reps, min_runs, budget)
    out = dict(prec_bits=p, order=int(ints.get("stick/stick").order), derivation_cpu_s=derive_s,
               heyoka_cold_cpu_s=cold, heyoka_cold_builds=cold_reps, heyoka_warm_cpu_s=warm, heyoka_runs=n)
    if cyl_file:
        spec = json.load(open(cyl_file))
        out["alternation"] = alternate(lambda: fn(ints), spec["args"], spec["pairs"])
    if task == "events":
        out["values"] = [dict(kind=e["kind"], mode=e["mode"], t=str(e["t"]), theta=str(e["theta"])) for e in val]
    elif task == "theta":
        out["values"] = [str(x) for x in val]
    else:
        out["values"] = [[str(x) for x in row] for row in val]
    with open(out_file, "w") as f:
        json.dump(out, f)


def heyoka_in_child(d, task, times_file, work, cold_reps, limit_s, cyl_args=None, pairs=0):
    """Runs child() in a fresh interpreter; (result dict or None, message). With
    `cyl_args` and `pairs` > 0, the child also times heyoka's warm run and that
    cylroll command in alternation."""
    out_file = os.path.join(work, f"heyoka_{task}_{d}.json")
    if os.path.exists(out_file):
        os.remove(out_file)
    cmd = [sys.executable, os.path.abspath(__file__), "--child", str(d), task, times_file, out_file, str(cold_reps)]
    if cyl_args and pairs > 0:
        cyl_file = os.path.join(work, f"cylroll_{task}_{d}.json")
        with open(cyl_file, "w") as f:
            json.dump(dict(args=cyl_args, pairs=pairs), f)
        cmd.append(cyl_file)
    try:
        cp = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=limit_s)
    except subprocess.TimeoutExpired:
        return None, f"heyoka did not finish within {limit_s:.0f} s (stopped)"
    if cp.returncode != 0 or not os.path.exists(out_file):
        return None, f"heyoka failed: {cp.stderr.strip().splitlines()[-1] if cp.stderr.strip() else cp.returncode}"
    return json.load(open(out_file)), None


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--child":
        d, task, times_file, out_file, cold_reps = sys.argv[2:7]
        cyl_file = sys.argv[7] if len(sys.argv) > 7 else None
        return child(int(d), task, times_file, out_file, int(cold_reps), cyl_file)
    ap = argparse.ArgumentParser()
    ap.add_argument("--digits", default="30,100,300,1000")
    ap.add_argument("--rows-digits", default="30,100")
    ap.add_argument("--tasks", default="events,theta,rows")
    ap.add_argument("--cold-reps", type=int, default=3, help="fresh builds per cold figure (1 above 100 digits)")
    ap.add_argument("--cylroll-reps", type=int, default=15, help="processes per cylroll figure (3 above 100 digits)")
    ap.add_argument("--pairs", type=int, default=15, help="alternating pairs for every column / θ only (a third above 100 digits)")
    ap.add_argument("--time-limit", type=float, default=900, help="seconds per heyoka measurement (a task at D digits)")
    ap.add_argument("--out", default=os.path.join(common.ROOT, "target", "bench-friction", "heyoka_friction.json"))
    a = ap.parse_args()
    work = os.path.dirname(os.path.abspath(a.out))
    os.makedirs(work, exist_ok=True)
    tasks = a.tasks.split(",")
    rows_digits = common.digits_list(a.rows_digits)

    def alt_pairs(d):
        # heyoka warm and the cylroll command in alternation: as many pairs as
        # the every-column / θ-only pairs (a third above 100 digits)
        return a.pairs if d <= 100 else max(3, a.pairs // 3)

    sep60 = json.loads(cylroll(["separation"] + CASE + ["--digits", "60", "--format", "json"])[0])
    h, times = grid(sep60["t_s"])
    times_file = os.path.join(work, "friction_times.txt")
    with open(times_file, "w") as f:
        f.write(",".join(times))
    res = dict(heyoka=hy.__version__, cylroll=cylroll(["--version"])[0].strip(), machine=os.uname().machine,
               ncpu=os.cpu_count(), case="m1=m2=r1=r2=g=1, k1=k2=1/2, mu=3/10 at both contacts, rest at theta0=1/10",
               t_s_60=sep60["t_s"], h=h, t_last=times[-1], guard_bits=GUARD_BITS, per_digits={})
    print(f"t_s = {sep60['t_s'][:25]}…, h = {h}", file=sys.stderr, flush=True)

    def save():
        with open(a.out, "w") as f:
            json.dump(res, f, indent=1)

    for d in common.digits_list(a.digits):
        cold_reps = a.cold_reps if d <= 100 else 1
        reps = a.cylroll_reps if d <= 100 else 3
        r = dict(prec_bits=math.ceil(d * math.log2(10)) + GUARD_BITS)
        res["per_digits"][str(d)] = r
        if "events" in tasks:
            ev_args = ["separation"] + CASE + ["--digits", str(d), "--format", "json"]
            out, cc, cw, cn = cylroll_timed(ev_args, reps)
            cev = json.loads(out)["events"]
            hv, err = heyoka_in_child(d, "events", times_file, work, cold_reps, a.time_limit, ev_args,
                                      alt_pairs(d))
            row = dict(cylroll_cpu_s=cc, cylroll_wall_s=cw, cylroll_runs=cn,
                       cylroll_events=[dict(kind=e["kind"], t=e["t"][:60], theta=e["theta"][:60]) for e in cev])
            if hv is None:
                row["error"] = err
            else:
                ev = hv.pop("values")
                ag = {}
                for k, name in enumerate(("slip", "sep")):
                    ag[f"t_{name}"] = agree(ev[k]["t"], cev[k]["t"])
                    ag[f"theta_{name}"] = agree(ev[k]["theta"], cev[k]["theta"])
                row.update(hv, heyoka_events=[dict(e, t=e["t"][:60], theta=e["theta"][:60]) for e in ev],
                           agreement_digits=ag, agreement_min=min(ag.values()))
            r["events"] = row
            print(f"{d} events: {json.dumps({k: v for k, v in row.items() if 'events' not in k})}",
                  file=sys.stderr, flush=True)
            save()
        for task in ("theta", "rows"):
            if task not in tasks or (task == "rows" and d not in rows_digits):
                continue
            # theta: `--columns t,theta,mode` (theta alone, no force); rows: every column
            key = f"trajectory_cmd_{task}"
            cols = ["--columns", "t,theta,mode"] if task == "theta" else []
            traj_args = ["trajectory"] + CASE + ["--times", ",".join(times), "--digits", str(d),
                                                 "--format", "csv"] + cols
            if key not in r:
                out, cc, cw, cn = cylroll_timed(traj_args, reps)
                r[key] = dict(cylroll_cpu_s=cc, cylroll_wall_s=cw, cylroll_runs=cn)
                traj_csv = out
            row = dict(r[key])
            hv, err = heyoka_in_child(d, task, times_file, work, cold_reps, a.time_limit, traj_args, alt_pairs(d))
            if hv is None:
                row["error"] = err
            else:
                vals = hv.pop("values")
                ag = agreement_rows(vals, traj_csv, theta_only=task == "theta")
                row.update(hv, agreement_digits=ag,
                           agreement_min=min(v for k, v in ag.items() if k != "modes_equal"))
            r[task] = row
            print(f"{d} {task}: {json.dumps(row)}", file=sys.stderr, flush=True)
            save()
        if "theta" in tasks and "rows" in tasks and d in rows_digits:
            # every column against θ only, the two commands run in alternation (A B A B …):
            # the ratio without the machine's drift between the two figures above
            pair = ["trajectory"] + CASE + ["--times", ",".join(times), "--digits", str(d), "--format", "csv"]
            th, al = [], []
            for _ in range(a.pairs if d <= 100 else max(3, a.pairs // 3)):
                th.append(cylroll(pair + ["--columns", "t,theta,mode"])[1])
                al.append(cylroll(pair)[1])
            r["rows_over_theta"] = dict(pairs=len(th), theta_cpu_s=statistics.median(th),
                                        rows_cpu_s=statistics.median(al),
                                        ratio=statistics.median(al) / statistics.median(th),
                                        ratio_min=min(x / y for x, y in zip(al, th)),
                                        ratio_max=max(x / y for x, y in zip(al, th)))
            print(f"{d} rows/theta paired: {json.dumps(r['rows_over_theta'])}", file=sys.stderr, flush=True)
            save()
    save()
    print(a.out)


if __name__ == "__main__":
    main()
