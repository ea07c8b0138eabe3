"""Pymunk (Chipmunk2D) adapter (``pip install './python[pymunk]'``).

Set-up (each choice is a setting, recorded in the scorecard):

- Chipmunk is planar with y up; its angles are counter-clockwise, so
  a = −body.angle and w = −body.angular_velocity.
- Two dynamic bodies with circles (mass m, moment k m r²); the floor a static
  segment; a held cylinder 1 a static body. Sleeping off, no damping
  (``damping`` 1), elasticity 0.
- **Friction combine rule**: Chipmunk multiplies the shapes' coefficients;
  here each contact's coefficient is set explicitly in a ``pre_solve``
  handler (``arbiter.friction``), so the rule does not matter. A rolling
  contact gets ``mu_roll`` (1e3).
- **The disc–disc contact chatters** with Chipmunk's defaults: Chipmunk makes
  a contact only while the circles overlap, and its impulses only push, so
  the centres drift apart by the curvature of the relative motion,
  about (r θ̇ dt)²/(2r) per step; the circles part by a hair, one step passes
  without contact (cylinder 2 in free fall, its weight off cylinder 1), the
  next closes it with an impact: hundreds of one-step losses before the
  parting at dt = 1e-3, ten times more at dt = 1e-4, with force spikes of
  2× and more. No solver setting changes that (``iterations``,
  ``collision_bias``, ``collision_slop``, ``collision_persistence`` were
  tried). What tames it is a **contact skin**: every circle and the floor
  are grown by ``skin``/2 (the floor segment moved down by as much), and
  ``collision_slop`` = ``skin``, so that Chipmunk sees the contact while the
  true surfaces are up to ``skin`` apart and pushes them out only where they
  truly overlap. The true gap then creeps open by the same drift (a first-order
  error, ~2.5e-4·r at dt = 1e-3, reported as the gap) instead of chattering.
  ``skin`` = ``skin_steps`` · dt · sqrt(g r) (default 1 step).
- ``iterations`` 100 (Chipmunk's default is 10), ``collision_bias`` Chipmunk's
  default (0.9^60 per second of the overlap beyond the slop remaining).
- Forces: ``arbiter.total_impulse`` in ``post_solve`` (the impulse on the
  first shape of the arbiter), divided by dt.
"""

from __future__ import annotations

import math
from typing import Any, Dict

from .adapter import engine_mu, initial_state


class PymunkAdapter:
    name = "pymunk"
    DEFAULTS: Dict[str, Any] = dict(
        mu_roll=1e3, mu_which="static", iterations=100, skin_steps=1.0, collision_bias=None,
        collision_persistence=3, floor_half_length=1e3,
        friction_combine="set per contact in pre_solve")

    def __init__(self) -> None:
        import pymunk  # lazy: an optional dependency
        self._pm = pymunk
        self.version = pymunk.version
        self.settings: Dict[str, Any] = {}

    def build(self, case_params: Dict[str, Any], settings: Dict[str, Any]) -> None:
        pm = self._pm
        s = {**self.DEFAULTS, **settings}
        p = self.p = dict(case_params)
        dt = s["dt"]
        skin = s["skin_steps"] * dt * math.sqrt(p["g"] * (p["r1"] + p["r2"]))
        s["skin"] = skin
        sp = self.space = pm.Space()
        sp.gravity = (0.0, -p["g"])
        sp.iterations = int(s["iterations"])
        sp.collision_slop = skin
        sp.collision_persistence = int(s["collision_persistence"])
        if s["collision_bias"] is not None:
            sp.collision_bias = s["collision_bias"]
        s["collision_bias"] = sp.collision_bias
        sp.sleep_time_threshold = float("inf")
        sp.damping = 1.0
        mu_f = engine_mu(p["mu_floor"], s["mu_roll"], s["mu_which"])
        mu_c = engine_mu(p["mu_contact"], s["mu_roll"], s["mu_which"])
        self.mu_engine = {"floor": mu_f, "contact": mu_c}
        pose, vel = initial_state(p)
        self.held = p["floor"] == "fixed"
        L = s["floor_half_length"]
        floor = pm.Segment(sp.static_body, (-L, -skin / 2), (L, -skin / 2), 0.0)
        floor.elasticity = 0.0
        floor.collision_type = 1
        if self.held:
            b1 = pm.Body(body_type=pm.Body.STATIC)
        else:
            b1 = pm.Body(p["m1"], p["k1"] * p["m1"] * p["r1"] ** 2)
        b2 = pm.Body(p["m2"], p["k2"] * p["m2"] * p["r2"] ** 2)
        self.b1, self.b2 = b1, b2
        c1 = pm.Circle(b1, p["r1"] + skin / 2)
        c2 = pm.Circle(b2, p["r2"] + skin / 2)
        c1.collision_type, c2.collision_type = 2, 3
        for c in (c1, c2):
            c.elasticity = 0.0
        b1.position = (pose[0], pose[1])
        b2.position = (pose[3], pose[4])
        b1.angle, b2.angle = -pose[2], -pose[5]
        if not self.held:
            b1.velocity = (vel[0], vel[1])
            b1.angular_velocity = -vel[2]
        b2.velocity = (vel[3], vel[4])
        b2.angular_velocity = -vel[5]
        sp.add(floor, b1, c1, b2, c2)
        self.c1, self.c2 = c1, c2
        mus = {frozenset((1, 2)): mu_f, frozenset((2, 3)): mu_c, frozenset((1, 3)): mu_f or mu_c}
        self.imp: Dict[frozenset, tuple] = {}

        def pre(arb, space, data):
            a, b = arb.shapes
            arb.friction = mus.get(frozenset((a.collision_type, b.collision_type)), 0.0)

        def post(arb, space, data):
            a, b = arb.shapes
            self.imp[frozenset((a.collision_type, b.collision_type))] = (a, arb.total_impulse)

        sp.on_collision(pre_solve=pre, post_solve=post)
        self.dt = dt
        self.settings = s

    def step(self, dt: float) -> None:
        self.imp.clear()
        self.space.step(dt)
        self.dt = dt

    def poses(self):
        b1, b2 = self.b1, self.b2
        return (float(b1.position.x), float(b1.position.y), -float(b1.angle),
                float(b2.position.x), float(b2.position.y), -float(b2.angle))

    def velocities(self):
        b1, b2 = self.b1, self.b2
        return (float(b1.velocity.x), float(b1.velocity.y), -float(b1.angular_velocity),
                float(b2.velocity.x), float(b2.velocity.y), -float(b2.angular_velocity))

    def _force_on(self, key, shape):
        hit = self.imp.get(key)
        if hit is None:
            return (0.0, 0.0)
        first, J = hit
        sg = 1.0 if first is shape else -1.0    # total_impulse acts on the arbiter's first shape
        return (sg * J.x / self.dt, sg * J.y / self.dt)

    def contact_forces(self):
        return {"floor": None if self.held else self._force_on(frozenset((1, 2)), self.c1),
                "contact": self._force_on(frozenset((2, 3)), self.c2)}
