"""A complete adapter of a tiny engine, as a template for your own.

:class:`PenaltyDiscs` is a reference-free integrator of two discs on a floor:
penalty contacts (a spring and damper on the depth for the normal force, a
stiff viscous friction capped at μN for the tangential one) and semi-implicit
Euler. Its stiffnesses scale with the step (ω·dt = ``omega_dt``), so it
converges as dt → 0. Run it with ``python -m cylroll.conformance example``.
"""

from __future__ import annotations

import math
from typing import Any, Dict

import numpy as np

from .adapter import engine_mu, initial_state


class PenaltyDiscs:
    """Two discs, penalty contacts, semi-implicit Euler (clockwise angles)."""

    name = "penalty-discs"
    version = "1"
    DEFAULTS = dict(omega_dt=0.2, zeta=1.0, friction_rate=0.3, mu_roll=1e6)

    def __init__(self) -> None:
        self.settings: Dict[str, Any] = {}

    def build(self, p: Dict[str, Any], settings: Dict[str, Any]) -> None:
        self.settings = s = {**self.DEFAULTS, **settings}
        self.p, dt = p, s["dt"]
        self.m = np.array([p["m1"], p["m2"]])
        self.I = np.array([p["k1"] * p["m1"] * p["r1"] ** 2, p["k2"] * p["m2"] * p["r2"] ** 2])
        self.kn = (s["omega_dt"] / dt) ** 2 * p["m2"]                  # normal stiffness
        self.cn = 2 * s["zeta"] * math.sqrt(self.kn * p["m2"])        # and damping
        self.ct = s["friction_rate"] * p["m2"] / dt                   # viscous friction
        self.mu_engine = {c: engine_mu(p["mu_" + c], s["mu_roll"]) for c in ("floor", "contact")}
        pose, vel = initial_state(p)
        self.x, self.v = np.array(pose, float), np.array(vel, float)  # (x1 y1 a1 x2 y2 a2)
        self.f = {"floor": (0.0, 0.0), "contact": (0.0, 0.0)}

    def _contact(self, depth, depth_rate, slip, mu):
        N = max(0.0, self.kn * depth + self.cn * depth_rate) if depth > 0 else 0.0
        return N, -max(-mu * N, min(mu * N, self.ct * slip))

    def step(self, dt: float) -> None:
        (x1, y1, _, x2, y2, _), (u1, v1, w1, u2, v2, w2) = self.x, self.v
        p, F = self.p, np.zeros(6)
        if p["floor"] != "fixed":                   # floor on 1: normal +y, tangent +x
            N, T = self._contact(p["r1"] - y1, -v1, u1 - p["r1"] * w1, self.mu_engine["floor"])
            F[:3] += (T, N, -p["r1"] * T)
            self.f["floor"] = (T, N)
        d = np.array([x2 - x1, y2 - y1])
        rho = math.hypot(*d)
        n, tg = d / rho, np.array([d[1], -d[0]]) / rho              # (sin, cos), (cos, -sin)
        rate = -(n @ [u2 - u1, v2 - v1])
        # material points at the contact; a clockwise rate w moves offset (rx, ry) by w (ry, -rx)
        pv1 = np.array([u1, v1]) + w1 * p["r1"] * np.array([n[1], -n[0]])
        pv2 = np.array([u2, v2]) - w2 * p["r2"] * np.array([n[1], -n[0]])
        N, T = self._contact(p["r1"] + p["r2"] - rho, rate, (pv2 - pv1) @ tg,
                             self.mu_engine["contact"])
        f2 = N * n + T * tg                                          # 1 on 2
        F[3:] += (f2[0], f2[1], -p["r2"] * T)                         # clockwise torque of T at -r2 n
        F[:3] += (-f2[0], -f2[1], -p["r1"] * T)                       # and of -T at +r1 n on 1
        self.f["contact"] = (float(f2[0]), float(f2[1]))
        mass = np.array([self.m[0], self.m[0], self.I[0], self.m[1], self.m[1], self.I[1]])
        acc = F / mass - np.array([0, p["g"], 0, 0, p["g"], 0])
        if p["floor"] == "fixed":
            acc[:3] = 0.0
        self.v = self.v + dt * acc
        self.x = self.x + dt * self.v

    def poses(self):
        return tuple(self.x)

    def velocities(self):
        return tuple(self.v)

    def contact_forces(self):
        return dict(self.f)
