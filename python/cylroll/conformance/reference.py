"""Everything the scorecard asks of the reference, in one place.

This is the only module of :mod:`cylroll.conformance` that calls the
package's public API (``cylroll.golden``, ``cylroll.Model.trajectory``,
``.separation``, ``cylroll.check``); that API is about to change (velocity
columns, the branch point, one scoring core shared with ``cylroll check``),
and then only these small functions change.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any, Dict, List, Optional, Sequence

import numpy as np

import cylroll

from .adapter import case_params

__all__ = ["model", "params", "events", "closed_end", "t_max", "rows_at", "branch_point",
           "phases", "check_table", "POSITION_COLUMNS", "RATE_COLUMNS"]

#: Columns the reference gives directly.
POSITION_COLUMNS = ("theta", "theta_dot", "phi1", "phi2", "x1", "x2", "y2",
                    "F1", "N1", "F21", "N12")
#: Rates the reference does not give yet: differentiated here (a stopgap).
RATE_COLUMNS = ("x1_dot", "phi1_dot", "phi2_dot", "x2_dot", "y2_dot")

DIGITS = 16


def model(case: str) -> "cylroll.Model":
    """The golden case's model."""
    return cylroll.golden.case(case)


def params(case: str) -> Dict[str, Any]:
    """The adapter's parameters of a golden case (floats and contact laws) and
    the exact ones (``exact``: ``model.params`` with the friction laws)."""
    m = model(case)
    p = case_params(m, case)
    exact = dict(m.params)
    if m.friction:
        exact.update(m.friction)
    p["exact"] = exact
    return p


@lru_cache(maxsize=64)
def _separation(case: str, digits: int):
    return model(case).separation(digits=digits)


def events(case: str, digits: int = 12) -> List[Dict[str, Any]]:
    """The reference's events as dicts {kind, contact, t, theta}: with friction
    the event list (slip_onset, stick, slip_reversal, separation, lift_off,
    impact); for the ideal models the separation (θs, t_s)."""
    sep = _separation(case, digits)
    if sep.friction:
        return [dict(kind=e.kind, contact=e.contact, mode=e.mode, t=float(e.t),
                     theta=float(e.theta)) for e in sep.events]
    t_s = sep.t_s
    return [dict(kind="separation", contact="contact", mode=None,
                 t=None if t_s is None else float(t_s), theta=float(sep.theta_s))]


def _first(evs, kind):
    return next((e for e in evs if e["kind"] == kind), None)


def closed_end(case: str) -> Optional[Dict[str, Any]]:
    """The end of the closed branch: the reference's separation event."""
    return _first(events(case), "separation")


def t_max(case: str) -> float:
    """The last time the reference answers: the impact (friction) or t_s (ideal
    models, whose trajectory stops at separation)."""
    evs = events(case)
    e = _first(evs, "impact") or _first(evs, "lift_off") or _first(evs, "separation")
    return float(e["t"])


def phases(case: str) -> Dict[str, tuple]:
    """The phases' time spans [a, b) from the reference's events:
    ``before_slip`` (to the first slip onset or the separation), ``slipping``
    (from the first slip onset to the separation; from t = 0 where a contact is
    frictionless), ``after_parting`` (from the separation to the impact, only
    where the reference has the flight)."""
    p = params(case)
    evs = events(case)
    sep = _first(evs, "separation")
    t_sep = sep["t"]
    slip = _first(evs, "slip_onset")
    frictionless = p["contact"] == "slip" or p["floor"] == "slip"
    t_slip = 0.0 if frictionless else (slip["t"] if slip else t_sep)
    out = {"before_slip": (0.0, t_slip), "slipping": (t_slip, t_sep)}
    imp = _first(evs, "impact")
    if imp is not None:
        out["after_parting"] = (t_sep, imp["t"])
    return {k: v for k, v in out.items() if v[1] > v[0]}


def _traj(case: str, times: Sequence[float], digits: int) -> Dict[str, np.ndarray]:
    tr = model(case).trajectory([float(x) for x in times], digits=digits)
    return {c: tr.column(c) for c in tr.columns}


def rows_at(case: str, times: Sequence[float], digits: int = DIGITS,
            h: float = 1e-5) -> Dict[str, np.ndarray]:
    """The reference at the given times (ascending; those past :func:`t_max`
    are dropped: ``t`` of the result says which were kept): the columns it has
    (θ, θ̇, φ1, φ2, x1, x2, y2, forces; with friction s1, s12, work) and the
    rates of :data:`RATE_COLUMNS`.

    STOPGAP: the reference has no velocity columns yet, so ẋ1, φ̇1, φ̇2, ẋ2,
    ẏ2 are differentiated here (central differences with step ``h``, one-sided
    at the ends of the valid range), and s1, s12 of the ideal models are made
    from them. Replace with the reference's own columns when it has them."""
    tmax = t_max(case)
    t = np.asarray([x for x in times if 0.0 <= x <= tmax * (1 - 1e-12)], dtype=float)
    if t.size == 0:
        return {"t": t}
    # stencil: t-h, t, t+h, shifted inside [0, tmax)
    lo = np.maximum(t - h, 0.0)
    hi = np.minimum(t + h, tmax * (1 - 1e-12))
    grid = np.unique(np.concatenate([lo, t, hi]))
    d = _traj(case, grid, digits)
    idx = lambda x: np.searchsorted(grid, x)
    it, il, ih = idx(t), idx(lo), idx(hi)
    out = {c: d[c][it] for c in d}
    for c, src in (("x1_dot", "x1"), ("phi1_dot", "phi1"), ("phi2_dot", "phi2"),
                   ("x2_dot", "x2"), ("y2_dot", "y2")):
        out[c] = (d[src][ih] - d[src][il]) / (grid[ih] - grid[il])
    if "s1" not in out:
        p = params(case)
        r1, r2 = p["r1"], p["r2"]
        psi2_dot = out["phi2_dot"] - out["theta_dot"]
        out["s1"] = out["x1_dot"] - r1 * out["phi1_dot"]
        out["s12"] = (r1 + r2) * out["theta_dot"] + r2 * psi2_dot - r1 * out["phi1_dot"]
    out["t"] = t
    return out


def phi2_start(case: str) -> float:
    """φ2 at t = 0 in the reference's gauge (to measure the engine's φ2 in it)."""
    return float(_traj(case, [0.0], DIGITS)["phi2"][0])


@lru_cache(maxsize=64)
def branch_point(case: str) -> Optional[Dict[str, float]]:
    """θ*, t*: where, on the reference's closed motion, the free relative normal
    acceleration r θ̇² − g cos θ − ẍ1_free sin θ turns positive while N12 > 0
    (from there the cylinders may also part). ẍ1_free is cylinder 1's
    acceleration under its floor law alone: 0 unless the floor slides with
    Coulomb friction (−μk g sgn s1). None when it does not happen before the
    closed branch ends (or only at its end, as at a frictionless contact)."""
    p = params(case)
    sep = closed_end(case)
    if sep is None or sep["t"] is None:
        return None
    t_end = sep["t"]
    r, g = p["r1"] + p["r2"], p["g"]
    muk = p["mu_floor"][1] if p["floor"] == "coulomb" else 0.0

    def f(times):
        d = _traj(case, times, 14)
        acc = np.zeros_like(d["theta"])
        if muk and "s1" in d:
            acc = -muk * g * np.sign(np.where(np.abs(d["s1"]) > 1e-12, d["s1"], 0.0))
        val = r * d["theta_dot"] ** 2 - g * np.cos(d["theta"]) - acc * np.sin(d["theta"])
        return val, d

    times = np.linspace(0.0, t_end * (1 - 1e-9), 401)
    val, d = f(times)
    ok = (val > 0) & (d["N12"] > 1e-9 * p["m2"] * g)
    k = int(np.argmax(ok)) if np.any(ok) else None
    if k is None or k == 0:
        return None
    a, b = times[k - 1], times[k]
    for _ in range(4):
        sub = np.linspace(a, b, 21)
        v, _ = f(sub)
        j = int(np.argmax(v > 0))
        a, b = sub[j - 1], sub[j]
    tb = 0.5 * (a + b)
    dd = _traj(case, [tb], 14)
    th = float(dd["theta"][0])
    if abs(th - sep["theta"]) < 1e-6:
        return None
    return dict(t=float(tb), theta=th, N12=float(dd["N12"][0]))


def check_table(case: str, table: Dict[str, np.ndarray], rtol: float = 1e-3,
                atol: float = 1e-6) -> Dict[str, Any]:
    """``cylroll.check`` of an engine table (columns in the reference's names,
    times within :func:`t_max`): passed, and per column the largest absolute
    error and where."""
    rep = cylroll.check(table, model(case), rtol=rtol, atol=atol, digits=12)
    return dict(passed=rep.passed, rtol=rtol, atol=atol,
                columns={c.name: dict(max_abs=c.max_abs, at=c.max_abs_t, failures=c.failures)
                         for c in rep.columns})


def package_version() -> str:
    return getattr(cylroll, "__version__", "?")
