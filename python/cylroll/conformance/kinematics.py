"""The reference's coordinates from the bodies' poses and velocities.

From (x1, y1, a1, x2, y2, a2) and (vx1, vy1, w1, vx2, vy2, w2) in the
conventions of :mod:`cylroll.conformance.adapter` (clockwise angles):

- θ = atan2(x2 − x1, y2 − y1): the line of centres, clockwise from vertical;
  θ̇ = ((y2 − y1)(vx2 − vx1) − (x2 − x1)(vy2 − vy1)) / |C2 − C1|².
- φ1 = a1 − a1(0): cylinder 1's clockwise rotation, 0 at t = 0; φ̇1 = w1.
- ψ2 = −(a2 − a2(0)) + ψ2(0): cylinder 2's counter-clockwise rotation, and
  φ2 = θ + ψ2 (README: φ2 − θ is the counter-clockwise rotation of cylinder
  2), in the gauge φ2(0) = ``phi2_0`` (0 by default: φ1(0) = φ2(0) = 0);
  φ̇2 = θ̇ − w2.
- s1 = ẋ1 − r1 φ̇1 (floor slip speed), s12 = r θ̇ + r2 ψ̇2 − r1 φ̇1 with
  r = r1 + r2 (slip speed of cylinder 2's contact point over cylinder 1's along
  (cos θ, −sin θ)).
- gap = |C2 − C1| − r (negative: penetration), floor gaps y1 − r1, y2 − r2.
- E = kinetic + potential energy of both bodies (I = k m r²).
- forces: F1, N1 (x, y of the floor's force on 1), N12 = f·n, F21 = f·(cos θ,
  −sin θ) for f the force of 1 on 2 and n = (sin θ, cos θ).
"""

from __future__ import annotations

from typing import Any, Dict, Mapping

import numpy as np

__all__ = ["derive", "energy"]


def energy(p: Mapping[str, Any], y1, y2, vx1, vy1, w1, vx2, vy2, w2) -> np.ndarray:
    """E = kinetic + potential energy of both bodies (potential 0 at y = 0)."""
    I1 = p["k1"] * p["m1"] * p["r1"] ** 2
    I2 = p["k2"] * p["m2"] * p["r2"] ** 2
    g = p["g"]
    return (0.5 * p["m1"] * (np.square(vx1) + np.square(vy1)) + 0.5 * I1 * np.square(w1)
            + 0.5 * p["m2"] * (np.square(vx2) + np.square(vy2)) + 0.5 * I2 * np.square(w2)
            + p["m1"] * g * np.asarray(y1) + p["m2"] * g * np.asarray(y2))


def derive(p: Mapping[str, Any], pose: np.ndarray, vel: np.ndarray,
           forces: np.ndarray = None, phi2_0: float = 0.0) -> Dict[str, np.ndarray]:
    """The derived quantities as arrays.

    ``pose``, ``vel``: arrays of shape (n, 6) (rows of :meth:`Adapter.poses`,
    :meth:`Adapter.velocities`); ``forces``: shape (n, 4) (floor fx, fy; contact
    fx, fy; NaN where not exposed) or None; ``phi2_0``: φ2 at the first row.
    """
    pose = np.atleast_2d(np.asarray(pose, dtype=float))
    vel = np.atleast_2d(np.asarray(vel, dtype=float))
    x1, y1, a1, x2, y2, a2 = pose.T
    vx1, vy1, w1, vx2, vy2, w2 = vel.T
    r1, r2 = p["r1"], p["r2"]
    r = r1 + r2
    dx, dy = x2 - x1, y2 - y1
    dvx, dvy = vx2 - vx1, vy2 - vy1
    rho2 = dx * dx + dy * dy
    theta = np.unwrap(np.arctan2(dx, dy))
    theta_dot = (dy * dvx - dx * dvy) / rho2
    phi1 = a1 - a1[0]
    psi2 = -(a2 - a2[0]) + (phi2_0 - theta[0])
    phi2 = theta + psi2
    psi2_dot = -w2
    out = dict(theta=theta, theta_dot=theta_dot, x1=x1, y1=y1, x2=x2, y2=y2,
               phi1=phi1, phi2=phi2, psi2=psi2,
               x1_dot=vx1, y1_dot=vy1, phi1_dot=w1, phi2_dot=theta_dot + psi2_dot,
               psi2_dot=psi2_dot, x2_dot=vx2, y2_dot=vy2,
               s1=vx1 - r1 * w1,
               s12=r * theta_dot + r2 * psi2_dot - r1 * w1,
               gap=np.sqrt(rho2) - r, floor_gap1=y1 - r1, floor_gap2=y2 - r2,
               energy=energy(p, y1, y2, vx1, vy1, w1, vx2, vy2, w2))
    n = len(theta)
    if forces is None:
        forces = np.full((n, 4), np.nan)
    forces = np.atleast_2d(np.asarray(forces, dtype=float))
    fx1, fy1, fx2, fy2 = forces.T
    s, c = np.sin(theta), np.cos(theta)
    out.update(F1=fx1, N1=fy1, N12=fx2 * s + fy2 * c, F21=fx2 * c - fy2 * s)
    return out
