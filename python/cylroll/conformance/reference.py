"""Everything the scorecard asks of the reference, in one place.

This is the only module of :mod:`cylroll.conformance` that calls the
package's public API (``cylroll.golden``, ``cylroll.Model.trajectory``,
``.separation``, ``cylroll.check``). Every question takes the *branch* the
reference should follow where the rigid-body motion is not unique: ``"stay"``
(the cylinders stay together while they can, the default), ``"part"`` (they
part at the branch point θ*, as velocity-level complementarity engines do) or
a float angle (they part where θ reaches it, inside the window [θ*, θs]).
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

import cylroll

from .adapter import case_params

__all__ = ["model", "params", "events", "closed_end", "t_max", "rows_at", "branch_point",
           "window", "phases", "check_table", "phi2_start", "COLUMNS"]

#: Columns the reference gives at any time (every phase, up to the first impact).
COLUMNS = ("theta", "theta_dot", "phi1", "phi2", "x1", "x2", "y2", "x1_dot", "phi1_dot",
           "x2_dot", "y2_dot", "phi2_dot", "F1", "N1", "F21", "N12", "s1", "s12", "work")

DIGITS = 16

#: A branch: "stay", "part", or the angle where the cylinders part.
Branch = Union[str, float]


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


def _branch_args(branch: Branch) -> Dict[str, Any]:
    if isinstance(branch, str):
        return dict(branch=branch)
    # the angle as the decimal it prints as, read exactly
    return dict(branch="stay", part_at=repr(float(branch)))


def _key(branch: Branch) -> Tuple[str, Optional[str]]:
    a = _branch_args(branch)
    return a["branch"], a.get("part_at")


@lru_cache(maxsize=128)
def _separation(case: str, digits: int, key: Tuple[str, Optional[str]]):
    branch, part_at = key
    return model(case).separation(digits=digits, branch=branch, part_at=part_at)


def events(case: str, branch: Branch = "stay", digits: int = 12) -> List[Dict[str, Any]]:
    """The reference's events on a branch as dicts {kind, contact, mode, t, theta}:
    slip_onset, stick, slip_reversal, indeterminate (the branch point),
    separation, lift_off, impact — for every contact law."""
    sep = _separation(case, digits, _key(branch))
    return [dict(kind=e.kind, contact=e.contact, mode=e.mode,
                 t=None if e.t is None else float(e.t), theta=float(e.theta))
            for e in sep.events]


def _first(evs, kind):
    return next((e for e in evs if e["kind"] == kind), None)


def closed_end(case: str) -> Optional[Dict[str, Any]]:
    """The end of the closed branch: the separation of the ``stay`` branch."""
    return _first(events(case), "separation")


def branch_point(case: str) -> Optional[Dict[str, float]]:
    """θ*, t*: where parting first becomes lawful while the cylinders press on
    each other (the reference's ``indeterminate`` event), with N12 just
    there; None where the motion is unique."""
    e = _first(events(case), "indeterminate")
    if e is None:
        return None
    f = model(case).forces(repr(e["theta"]), digits=12)
    return dict(t=e["t"], theta=e["theta"], N12=float(f["N12"]))


def window(case: str) -> Optional[Tuple[float, float]]:
    """[θ*, θs]: where parting is lawful (None where the motion is unique)."""
    bp, end = branch_point(case), closed_end(case)
    if bp is None or end is None:
        return None
    return bp["theta"], end["theta"]


def t_max(case: str, branch: Branch = "stay") -> float:
    """The last time the reference answers on a branch: the first impact (or a
    lift-off, or the separation where nothing follows it)."""
    evs = events(case, branch)
    e = _first(evs, "impact") or _first(evs, "lift_off") or _first(evs, "separation")
    return float(e["t"])


def phases(case: str, branch: Branch = "stay") -> Dict[str, tuple]:
    """The phases' time spans [a, b) from the reference's events on a branch:
    ``before_slip`` (to the first slip onset or the separation), ``slipping``
    (from the first slip onset to the separation; from t = 0 where a contact is
    frictionless), ``after_parting`` (from the separation to the impact)."""
    p = params(case)
    evs = events(case, branch)
    sep = _first(evs, "separation")
    t_sep = sep["t"]
    slip = _first(evs, "slip_onset")
    frictionless = p["contact"] == "slip" or p["floor"] == "slip"
    t_slip = 0.0 if frictionless else (slip["t"] if slip and slip["t"] < t_sep else t_sep)
    out = {"before_slip": (0.0, t_slip), "slipping": (t_slip, t_sep)}
    imp = _first(evs, "impact")
    if imp is not None:
        out["after_parting"] = (t_sep, imp["t"])
    return {k: v for k, v in out.items() if v[1] > v[0]}


def rows_at(case: str, times: Sequence[float], branch: Branch = "stay",
            digits: int = DIGITS) -> Dict[str, np.ndarray]:
    """The reference on a branch at the given times (ascending; those past
    :func:`t_max` are dropped: ``t`` of the result says which were kept): every
    column of :data:`COLUMNS` (positions, rates, forces, slip speeds, work)."""
    tmax = t_max(case, branch)
    t = np.asarray([x for x in times if 0.0 <= x <= tmax * (1 - 1e-12)], dtype=float)
    if t.size == 0:
        return {"t": t}
    tr = model(case).trajectory([float(x) for x in t], digits=digits, **_branch_args(branch))
    out = {c: tr.column(c) for c in tr.columns}
    out["t"] = t
    return out


def phi2_start(case: str) -> float:
    """φ2 at t = 0 in the reference's gauge (0 for every contact law)."""
    return float(model(case).trajectory([0], digits=DIGITS).column("phi2")[0])


def check_table(case: str, table: Dict[str, np.ndarray], branch: Branch = "stay",
                rtol: float = 1e-3, atol: float = 1e-3, event_tol: float = 1e-2,
                digits: int = 12) -> Dict[str, Any]:
    """The scoring core of ``cylroll check`` (:func:`cylroll.check`) on an
    engine table (columns in the reference's names) against the reference on
    ``branch``: the verdict, and per column and per phase of the reference the
    largest absolute error and where (``atol`` in units of each column's
    scale; rows after the end of the motion are left out and counted)."""
    if isinstance(branch, str):
        kw: Dict[str, Any] = dict(branch=branch)
    else:
        kw = dict(part_at=repr(float(branch)))
    rep = cylroll.check(table, model(case), rtol=rtol, atol=atol, event_tol=event_tol,
                        digits=digits, **kw)
    ff = rep.first_failure
    return dict(
        verdict=rep.verdict, passed=rep.passed, rtol=rtol, atol=atol,
        branch=rep.branch.followed, rows=rep.rows, rows_after_end=rep.rows_after_end,
        columns={c.column: dict(max_abs=c.max_abs, at=c.max_abs_t, failures=c.failures)
                 for c in rep.columns},
        phases=[dict(mode=ph.mode, t_first=float(ph.t_first), t_last=float(ph.t_last),
                     rows=ph.rows, passed=ph.passed,
                     max_abs={c.column: c.phases[k].max_abs for c in rep.columns})
                for k, ph in enumerate(rep.phases)],
        first_failure=None if ff is None else dict(row=ff.row, t=float(ff.t), column=ff.column,
                                                   candidate=ff.candidate, oracle=ff.oracle))


def package_version() -> str:
    return getattr(cylroll, "__version__", "?")
