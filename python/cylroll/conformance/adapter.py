"""The adapter protocol: what an engine provides to be scored.

An adapter is one small class (see :mod:`cylroll.conformance.examples` for a
complete one of about fifty lines)::

    class MyEngine:
        name = "myengine"
        version = "1.2"
        settings = {}                     # filled by build(): everything that shaped the run

        def build(self, case_params, settings):   # settings always holds "dt"
            ...
        def step(self, dt): ...
        def poses(self):       return (x1, y1, a1, x2, y2, a2)
        def velocities(self):  return (vx1, vy1, w1, vx2, vy2, w2)
        def contact_forces(self):
            return {"floor": (fx, fy) or None, "contact": (fx, fy) or None}

Conventions (the paper's frame, README "Conventions"):

- x to the right, y up, the floor is y = 0; (x1, y1), (x2, y2) are the centres
  of cylinder 1 (lower) and 2 (upper).
- ``a1``, ``a2`` are the bodies' rotation angles, **clockwise positive** (the
  sense of the README's φ1: a cylinder rolling to +x on the floor turns with
  a1 increasing, x1 = r1·a1). Any constant offset is allowed: the kinematics
  measure rotations from their values at t = 0. ``w1``, ``w2`` are the
  clockwise angular velocities, ``vx*``, ``vy*`` the centres' velocities.
- ``contact_forces()``: world-frame vectors (x, y components) of the floor's
  force on cylinder 1 (``"floor"``; for a held cylinder 1, the holder's force
  or None) and of cylinder 1's force on cylinder 2 (``"contact"``), averaged
  over the last step (impulse / dt for impulse-based engines); ``None`` for a
  force the engine does not expose. The runner turns them into the README's
  F1, N1 (x and y of the floor force), N12 (normal, positive while pressing)
  and F21 (along (cos θ, −sin θ)).
- ``step(dt)`` advances the engine by dt; after it, ``poses()``,
  ``velocities()`` and ``contact_forces()`` describe the state at the new time
  (an engine that lags, such as MuJoCo's ``mj_step``, must recompute).

Optional: ``mu_engine = {"floor": μ, "contact": μ}``, the coefficients the
engine really uses (a rolling contact's "very large μ"), for the cone
violation of rolling contacts.

``case_params`` is the dict of :func:`case_params` (floats, the contact laws
and the start): build the scene at the start state of :func:`initial_state`,
so that every engine starts from the same bodies' positions and velocities.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any, Dict, Optional, Protocol, Tuple, runtime_checkable

import numpy as np

__all__ = ["Adapter", "case_params", "initial_state", "mu_pair", "engine_mu",
           "parse_exact", "Pose", "Velocity"]

Pose = Tuple[float, float, float, float, float, float]
Velocity = Tuple[float, float, float, float, float, float]
Vec = Optional[Tuple[float, float]]


@runtime_checkable
class Adapter(Protocol):
    """The protocol an engine adapter satisfies (structural: no base class is
    needed). ``settings`` is the dict recorded in the scorecard: after
    :meth:`build` it holds every setting that shaped the run, with ``dt``."""

    name: str
    version: str
    settings: Dict[str, Any]

    def build(self, case_params: Dict[str, Any], settings: Dict[str, Any]) -> None:
        """Builds the two-cylinder planar scene of ``case_params`` at its start
        (:func:`initial_state`). ``settings`` overrides the adapter's defaults
        and always holds ``dt``, the step :meth:`step` will be called with."""

    def step(self, dt: float) -> None:
        """Advances by ``dt``."""

    def poses(self) -> Pose:
        """(x1, y1, a1, x2, y2, a2): centres and clockwise rotation angles."""

    def velocities(self) -> Velocity:
        """(vx1, vy1, w1, vx2, vy2, w2): centre velocities, clockwise rates."""

    def contact_forces(self) -> Dict[str, Vec]:
        """{"floor": (fx, fy) on cylinder 1, "contact": (fx, fy) on cylinder 2
        from cylinder 1}, world frame; ``None`` where not exposed."""


# --- the case as floats -------------------------------------------------------------------

def parse_exact(text: str) -> float:
    """The float of an exact number as the package writes it: ``"1/10"``,
    ``"0.3"``, ``"1e-3"``, ``"pi/6"``, ``"2*pi/3"``, ``"-pi"``."""
    t = str(text).strip().lower().replace(" ", "")
    if t in ("inf", "+inf"):
        return math.inf
    if "pi" in t:
        num, _, den = t.partition("/")
        coef = num.replace("*pi", "").replace("pi", "")
        c = 1.0 if coef in ("", "+") else (-1.0 if coef == "-" else float(Fraction(coef)))
        return c * math.pi / (float(Fraction(den)) if den else 1.0)
    if "/" in t:
        a, b = t.split("/", 1)
        return float(Fraction(a) / Fraction(b))
    return float(Fraction(t))


def mu_pair(text: Optional[str]) -> Tuple[float, float]:
    """(μs, μk) of a friction text: ``"inf"``, ``"0.3"``, ``"0.5,0.3"``."""
    if text is None:
        return (math.inf, math.inf)
    parts = [p for p in str(text).split(",") if p.strip()]
    s = parse_exact(parts[0])
    k = parse_exact(parts[1]) if len(parts) > 1 else s
    return (s, k)


def case_params(model: Any, name: Optional[str] = None) -> Dict[str, Any]:
    """The parameters an adapter builds from, out of a :class:`cylroll.Model`
    (``model.params``: the law keywords and coefficient texts), as floats:

    ``m1, m2, r1, r2, k1, k2, g, theta0, thetadot0, omega0``; ``floor``: one of
    ``"roll"`` (no slip), ``"slip"`` (frictionless), ``"fixed"`` (cylinder 1
    held), ``"coulomb"``; ``contact``: ``"roll"``, ``"slip"``, ``"coulomb"``;
    ``mu_floor``, ``mu_contact``: (μs, μk), ``inf`` for rolling, 0 for
    frictionless (``None`` for a held cylinder 1); ``name``.
    """
    p = model.params
    out: Dict[str, Any] = {k: parse_exact(p[k]) for k in
                           ("m1", "m2", "r1", "r2", "k1", "k2", "g", "theta0",
                            "thetadot0", "omega0")}
    floor, contact = p["floor"], p["contact"]

    def law(which: str, keyword: str) -> Optional[Tuple[float, float]]:
        # the model's own law keyword and coefficient text (``params``
        # carries both for every law: "roll"/"inf", "slip"/"0", "coulomb"/"0.5,0.3")
        text = p.get(which)
        if keyword == "fixed" or text in (None, "none"):
            return None
        if keyword == "roll":
            return (math.inf, math.inf)
        if keyword == "slip":
            return (0.0, 0.0)
        return mu_pair(text)

    mf = law("mu_floor", floor)
    mc = law("mu_contact", contact)
    out.update(floor=floor, contact=contact, mu_floor=mf, mu_contact=mc,
               name=name or "model")
    return out


def engine_mu(mu: Optional[Tuple[float, float]], mu_roll: float, which: str = "static") -> float:
    """The single friction coefficient an engine with one coefficient gets:
    ``mu_roll`` (the adapter's "very large μ") for a rolling contact, 0 for a
    frictionless one, else μs (``which="static"``) or μk (``"kinetic"``)."""
    if mu is None:
        return 0.0
    s, k = mu
    if math.isinf(s):
        return float(mu_roll)
    return float(s if which == "static" else k)


# --- the start, the same for every engine ---------------------------------------------------

def _reduced_jacobian(p: Dict[str, Any], theta: float) -> Tuple[np.ndarray, list]:
    """J with V = J q̇ for V = (vx1, vy1, w1, vx2, vy2, w2) (w clockwise) and
    q = (θ, cyclic coordinates of the contact model): the bodies' velocities of
    the constrained motion. Returns J and the cyclic coordinates' names."""
    r1, r2 = p["r1"], p["r2"]
    r = r1 + r2
    floor, contact = p["floor"], p["contact"]
    names = []
    if floor in ("roll", "coulomb"):
        names.append("a1")      # x1 = r1 a1
    elif floor == "slip":
        names += ["x1", "a1"]
    if contact == "slip":
        names.append("a2")
    n = 1 + len(names)
    J = np.zeros((6, n))
    c, s = math.cos(theta), math.sin(theta)
    # vx1, w1
    if "x1" in names:
        J[0, 1 + names.index("x1")] = 1.0
    if "a1" in names:
        ia = 1 + names.index("a1")
        J[2, ia] = 1.0
        if "x1" not in names:
            J[0, ia] = r1
    # centre 2 = centre 1 + r (sin θ, cos θ)
    J[3, :] = J[0, :]
    J[3, 0] += r * c
    J[4, 0] = -r * s
    # w2: rolling between the cylinders, r2 φ2 = r1 (φ1 − θ) with φ2 = θ − a2 (+ const):
    # a2 = θ − (r1/r2)(a1 − θ); frictionless: a2 free
    if contact == "slip":
        J[5, 1 + names.index("a2")] = 1.0
    else:
        J[5, 0] = r / r2
        J[5, :] -= (r1 / r2) * J[2, :]
    return J, names


def initial_state(p: Dict[str, Any]) -> Tuple[Pose, Velocity]:
    """The start of the case as the bodies' poses and velocities (the
    conventions of :class:`Adapter`): cylinder 1 at x1 = 0 on the floor,
    cylinder 2 touching it along θ0, rotation angles 0; velocities of the
    constrained motion with θ̇ = θ̇0 and the conserved momenta of the cyclic
    coordinates fixed by ω0 (README: the value φ̇1 takes whenever θ̇ = 0; with a
    frictionless floor ẋ1 = r1 ω0 then too; a frictionless contact's spin is
    taken as the rolling one there, w2 = −(r1/r2) ω0).

    A Coulomb contact starts as if rolling (the reference's start mode for the
    golden cases)."""
    r1, r2, th, thd, w0 = p["r1"], p["r2"], p["theta0"], p["thetadot0"], p["omega0"]
    r = r1 + r2
    pose = (0.0, r1, 0.0, r * math.sin(th), r1 + r * math.cos(th), 0.0)
    J, names = _reduced_jacobian(p, th)
    I1 = p["k1"] * p["m1"] * r1 ** 2
    I2 = p["k2"] * p["m2"] * r2 ** 2
    M = np.diag([p["m1"], p["m1"], I1, p["m2"], p["m2"], I2])
    ref = {"a1": w0, "x1": r1 * w0, "a2": -(r1 / r2) * w0}
    cdot = np.array([ref[n] for n in names])
    if names and thd != 0.0:
        K = J.T @ M @ J
        cdot = cdot - np.linalg.solve(K[1:, 1:], K[1:, 0] * thd)
    qdot = np.concatenate([[thd], cdot])
    v = J @ qdot
    return pose, tuple(float(x) for x in v)  # type: ignore[return-value]
