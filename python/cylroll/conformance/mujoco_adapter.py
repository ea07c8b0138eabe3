"""MuJoCo adapter (``pip install './python[mujoco]'``), set up as
``examples/mujoco/sim.py`` found works (details and evidence in
``reports/engines.md``):

- MuJoCo's z is up, the cylinder axes lie along y, MuJoCo's (x, z) is the
  paper's (x, y); a hinge about +y turns clockwise in the paper's picture, so
  the hinge angles are a1, a2 as they stand.
- Planar motion: slide-x, slide-z and hinge-y joints per body, nothing else;
  a held cylinder 1 is a static body. Inertia set explicitly (k m r² about the
  axis).
- Capsules, not cylinders (analytic capsule–plane and capsule–capsule
  colliders; the convex collider on parallel cylinders gives tilted normals
  and spurious deep contacts).
- Contacts as explicit pairs (so the friction of each contact is the case's,
  not MuJoCo's max-combination of two geoms): condim 3 (condim 1 where
  frictionless), elliptic cone (Coulomb's), impratio 1, Newton solver
  (tolerance 1e-12), noslip_iterations 50, solref (2·dt, 1), solimp (0.5, 0.5,
  0.001, 0.5, 2), margin 0; started at the soft contacts' resting depths
  (a 0.2 s pre-run). Stiffer impedances make the cylinder–cylinder contact
  chatter as the rolling speeds up (MuJoCo's contact acceleration leaves out
  r·θ̇²); MuJoCo's defaults are far too soft.
- A rolling contact gets ``mu_roll`` = 1e4: with μ = 10 (sim.py's) the cone
  is reached at θ = 1.037, 0.014 before the rolling reference parts.
- ``mj_forward`` after each ``mj_step`` (which leaves positions and forces at
  the state before the step).
"""

from __future__ import annotations

import math
from typing import Any, Dict

import numpy as np

from .adapter import engine_mu, initial_state

HALF = 0.5  # half-length of the capsules along y: any value, the motion is planar


class MujocoAdapter:
    name = "mujoco"
    DEFAULTS: Dict[str, Any] = dict(
        geom="capsule", mu_roll=1e4, mu_which="static", cone="elliptic", impratio=1.0,
        integrator="Euler", solver="Newton", iterations=100, tolerance=1e-12,
        noslip_iterations=50, noslip_tolerance=1e-12, tc_steps=2.0, impedance=0.5,
        solimp_width=0.001, preload=True, preload_time=0.2)

    def __init__(self) -> None:
        import mujoco  # lazy: an optional dependency
        self._mj = mujoco
        self.version = mujoco.__version__
        self.settings: Dict[str, Any] = {}

    def _xml(self, p: Dict[str, Any], s: Dict[str, Any]) -> str:
        dt = s["dt"]
        mu_f = engine_mu(p["mu_floor"], s["mu_roll"], s["mu_which"])
        mu_c = engine_mu(p["mu_contact"], s["mu_roll"], s["mu_which"])
        self.mu_engine = {"floor": mu_f, "contact": mu_c}
        solref = f"{s['tc_steps'] * dt!r} 1"
        d = s["impedance"]
        solimp = f"{d} {d} {s['solimp_width']} 0.5 2"

        def geom(name, r):
            if s["geom"] == "sphere":
                return f'<geom name="{name}" type="sphere" size="{r}" contype="0" conaffinity="0"/>'
            return (f'<geom name="{name}" type="{s["geom"]}" size="{r} {HALF}" euler="90 0 0" '
                    f'contype="0" conaffinity="0"/>')

        def pair(a, b, mu):
            cd = 3 if mu > 0 else 1
            return (f'<pair geom1="{a}" geom2="{b}" condim="{cd}" friction="{mu!r} {mu!r} 0 0 0" '
                    f'solref="{solref}" solimp="{solimp}" margin="0" gap="0"/>')

        def body(i, m, k, r, z):
            ia = k * m * r * r
            other = m * (3 * r * r + (2 * HALF) ** 2) / 12
            joints = "" if (i == 1 and p["floor"] == "fixed") else (
                f'<joint name="x{i}" type="slide" axis="1 0 0"/>'
                f'<joint name="z{i}" type="slide" axis="0 0 1"/>'
                f'<joint name="a{i}" type="hinge" axis="0 1 0"/>')
            return (f'<body name="c{i}" pos="0 0 {z!r}">{joints}'
                    f'<inertial pos="0 0 0" mass="{m!r}" diaginertia="{other!r} {ia!r} {other!r}"/>'
                    f'{geom("g%d" % i, r)}</body>')

        pairs = [pair("g1", "g2", mu_c), pair("floor", "g2", mu_f if mu_f else mu_c)]
        if p["floor"] != "fixed":
            pairs.insert(0, pair("floor", "g1", mu_f))
        return f"""<mujoco model="cylroll">
  <compiler angle="degree" autolimits="true"/>
  <option timestep="{dt!r}" gravity="0 0 {-p['g']!r}" integrator="{s['integrator']}"
          cone="{s['cone']}" impratio="{s['impratio']}" solver="{s['solver']}"
          iterations="{s['iterations']}" tolerance="{s['tolerance']}" ls_tolerance="1e-6"
          noslip_iterations="{s['noslip_iterations']}" noslip_tolerance="{s['noslip_tolerance']}"/>
  <default><joint damping="0" armature="0" limited="false"/></default>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 1" contype="0" conaffinity="0"/>
    {body(1, p['m1'], p['k1'], p['r1'], p['r1'] if p['floor'] == 'fixed' else 0.0)}
    {body(2, p['m2'], p['k2'], p['r2'], 0.0)}
  </worldbody>
  <contact>{''.join(pairs)}</contact>
</mujoco>"""

    def build(self, case_params: Dict[str, Any], settings: Dict[str, Any]) -> None:
        mj = self._mj
        s = {**self.DEFAULTS, **settings}
        p = self.p = dict(case_params)
        self.xml = self._xml(p, s)
        self.m = mj.MjModel.from_xml_string(self.xml)
        self.d = mj.MjData(self.m)
        self.held = p["floor"] == "fixed"
        gid = lambda n: mj.mj_name2id(self.m, mj.mjtObj.mjOBJ_GEOM, n)
        self.gf, self.g1, self.g2 = gid("floor"), gid("g1"), gid("g2")
        jid = lambda n: mj.mj_name2id(self.m, mj.mjtObj.mjOBJ_JOINT, n)
        names = ["x2", "z2", "a2"] if self.held else ["x1", "z1", "a1", "x2", "z2", "a2"]
        self.qa = {n: int(self.m.jnt_qposadr[jid(n)]) for n in names}
        self.va = {n: int(self.m.jnt_dofadr[jid(n)]) for n in names}
        self.f6 = np.zeros(6)
        pen = (0.0, 0.0)
        if s["preload"]:
            pen = self._preload(s)
        s["preload_depths"] = {"floor": pen[0], "contact": pen[1]}
        self._reset(pen)
        self.settings = s

    def _reset(self, pen) -> None:
        mj, p = self._mj, self.p
        mj.mj_resetData(self.m, self.d)
        pose, vel = initial_state(p)
        r = p["r1"] + p["r2"]
        y1 = p["r1"] - (0.0 if self.held else pen[0])
        rr = r - pen[1]
        th = p["theta0"]
        q = {"x1": pose[0], "z1": y1, "a1": pose[2], "x2": rr * math.sin(th),
             "z2": y1 + rr * math.cos(th), "a2": pose[5]}
        v = dict(zip(("x1", "z1", "a1", "x2", "z2", "a2"), vel))
        for n, a in self.qa.items():
            self.d.qpos[a] = q[n]
            self.d.qvel[self.va[n]] = v[n]
        mj.mj_forward(self.m, self.d)

    def _preload(self, s) -> tuple:
        """Depths at which the soft contacts hold the bodies near rest: a run from
        exact touching at rest, the penetrations averaged over its second half."""
        saved = self.p
        self.p = {**saved, "thetadot0": 0.0, "omega0": 0.0}
        self._reset((0.0, 0.0))
        n = max(2, round(s["preload_time"] / s["dt"]))
        pf, pc = [], []
        for i in range(n):
            self.step(s["dt"])
            if i >= n // 2:
                f, c = self._depths()
                pf.append(f)
                pc.append(c)
        self.p = saved
        return float(np.mean(pf)), float(np.mean(pc))

    def _depths(self):
        df = dc = 0.0
        for i in range(self.d.ncon):
            c = self.d.contact[i]
            pr = {c.geom1, c.geom2}
            if pr == {self.gf, self.g1}:
                df = max(df, -float(c.dist))
            elif pr == {self.g1, self.g2}:
                dc = max(dc, -float(c.dist))
        return df, dc

    def step(self, dt: float) -> None:
        self._mj.mj_step(self.m, self.d)
        self._mj.mj_forward(self.m, self.d)

    def _q(self, n, arr, adr):
        return float(arr[adr[n]]) if n in adr else 0.0

    def poses(self):
        q = lambda n: self._q(n, self.d.qpos, self.qa)
        return (q("x1"), self.p["r1"] + q("z1") if self.held else q("z1"), q("a1"),
                q("x2"), q("z2"), q("a2"))

    def velocities(self):
        v = lambda n: self._q(n, self.d.qvel, self.va)
        return (v("x1"), v("z1"), v("a1"), v("x2"), v("z2"), v("a2"))

    def contact_forces(self):
        floor = np.zeros(2)
        contact = np.zeros(2)
        for i in range(self.d.ncon):
            c = self.d.contact[i]
            self._mj.mj_contactForce(self.m, self.d, i, self.f6)
            fw = c.frame.reshape(3, 3).T @ self.f6[:3]   # on geom2 from geom1, world frame
            pr = {c.geom1, c.geom2}
            if pr == {self.gf, self.g1}:
                sg = 1.0 if c.geom2 == self.g1 else -1.0
                floor += sg * fw[[0, 2]]
            elif pr == {self.g1, self.g2}:
                sg = 1.0 if c.geom2 == self.g2 else -1.0
                contact += sg * fw[[0, 2]]
        return {"floor": None if self.held else (float(floor[0]), float(floor[1])),
                "contact": (float(contact[0]), float(contact[1]))}
