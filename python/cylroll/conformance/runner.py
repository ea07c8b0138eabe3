"""Running an adapter on a case, on the engine's own time grid."""

from __future__ import annotations

import math
import time as _time
from typing import Any, Dict, Mapping, Optional, Sequence

import numpy as np

from . import kinematics, measure

__all__ = ["RunResult", "run_case", "observed_order", "SERIES"]

#: The arrays of a run (besides ``t``), in the scorecard's order.
SERIES = ("theta", "theta_dot", "x1", "x1_dot", "phi1", "phi1_dot", "phi2", "phi2_dot",
          "x2", "x2_dot", "y2", "y2_dot", "s1", "s12", "F1", "N1", "F21", "N12",
          "gap", "floor_gap1", "floor_gap2", "energy")


class RunResult:
    """One run: ``t`` (the engine's own times, t = k·dt), ``q`` (arrays of
    :data:`SERIES` and more, see :func:`cylroll.conformance.kinematics.derive`),
    ``measurements`` (:func:`cylroll.conformance.measure.measure`), ``dt``,
    ``settings`` (the adapter's, after build), ``wall`` (seconds), ``stopped``
    (why the run ended)."""

    def __init__(self, t, q, measurements, dt, settings, wall, stopped, has_forces):
        self.t = t
        self.q = q
        self.measurements = measurements
        self.dt = dt
        self.settings = settings
        self.wall = wall
        self.stopped = stopped
        self.has_forces = has_forces

    def __getitem__(self, name: str) -> np.ndarray:
        return self.t if name == "t" else self.q[name]

    def arrays(self) -> Dict[str, np.ndarray]:
        return {"t": self.t, **{k: self.q[k] for k in SERIES}}

    def event(self, kind: str, contact: Optional[str] = None) -> Optional[Dict[str, Any]]:
        for e in self.measurements["events"]:
            if e["kind"] == kind and (contact is None or e.get("contact") == contact):
                return e
        return None


def _vec(f) -> Sequence[float]:
    return (math.nan, math.nan) if f is None else (float(f[0]), float(f[1]))


def run_case(adapter: Any, case_params: Mapping[str, Any], dt: float, t_end: float,
             settings: Optional[Mapping[str, Any]] = None, *, stop_after_impact: float = 0.05,
             thresholds: Optional[Mapping[str, float]] = None,
             phi2_0: float = 0.0) -> RunResult:
    """Builds ``case_params`` in ``adapter`` with ``settings`` (plus ``dt``),
    steps it to ``t_end`` and returns a :class:`RunResult`: the arrays on the
    engine's grid t_k = k·dt (t, θ, x1, φ1, φ2, x2, y2 and their rates, s1, s12,
    the forces F1, N1, F21, N12, the gaps, the energy) and the measurements.

    The run stops early ``stop_after_impact`` seconds after cylinder 2 reaches
    the floor, or cylinder 1 again after the cylinders have been apart (the
    motion after an impact is outside the reference). ``phi2_0``: the gauge of
    φ2 (its value at t = 0)."""
    s = dict(settings or {})
    s["dt"] = float(dt)
    wall0 = _time.perf_counter()
    adapter.build(dict(case_params), s)
    n = int(math.floor(t_end / dt + 1e-9))
    poses = np.empty((n + 1, 6))
    vels = np.empty((n + 1, 6))
    forces = np.empty((n + 1, 4))
    r = case_params["r1"] + case_params["r2"]
    r2 = case_params["r2"]
    x_open = 1e-3 * r
    apart_since = None
    impact_at = None
    stopped = "t_end"
    k_last = n
    for k in range(n + 1):
        if k:
            adapter.step(dt)
        pz = adapter.poses()
        poses[k] = pz
        vels[k] = adapter.velocities()
        f = adapter.contact_forces() or {}
        forces[k, :2] = _vec(f.get("floor"))
        forces[k, 2:] = _vec(f.get("contact"))
        # the stop: cheap online checks of an impact
        if impact_at is None:
            gap = math.hypot(pz[3] - pz[0], pz[4] - pz[1]) - r
            if gap > x_open:
                apart_since = k if apart_since is None else apart_since
            elif apart_since is not None and gap <= 0.0:
                impact_at = k
            if pz[4] - r2 <= 0.0:
                impact_at = k
        elif (k - impact_at) * dt >= stop_after_impact:
            stopped = "impact"
            k_last = k
            break
    m = k_last + 1
    t = np.arange(m) * float(dt)
    # the forces of row 0 belong to no step: not compared
    forces[0] = np.nan
    has_forces = (bool(np.all(np.isfinite(forces[1:m, :2]))),
                  bool(np.all(np.isfinite(forces[1:m, 2:]))))
    q = kinematics.derive(case_params, poses[:m], vels[:m], forces[:m], phi2_0=phi2_0)
    mu_engine = getattr(adapter, "mu_engine", None)
    meas = measure.measure(case_params, t, q, has_forces, mu_engine, thresholds)
    wall = _time.perf_counter() - wall0
    return RunResult(t, q, meas, float(dt), dict(getattr(adapter, "settings", {}) or {}),
                     wall, stopped, has_forces)


def observed_order(errors_by_dt: Mapping[float, float]) -> Optional[float]:
    """The observed order of convergence: the least-squares slope of
    log(error) against log(dt) over the dt values with a finite positive error;
    None with fewer than 3 of them."""
    pts = [(float(h), float(e)) for h, e in errors_by_dt.items()
           if h is not None and e is not None and h > 0 and np.isfinite(e) and e > 0]
    if len(pts) < 3:
        return None
    x = np.log([h for h, _ in pts])
    y = np.log([e for _, e in pts])
    A = np.vstack([x, np.ones_like(x)]).T
    slope, _ = np.linalg.lstsq(A, y, rcond=None)[0]
    return float(slope)
