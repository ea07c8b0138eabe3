"""PyBullet adapter (``pip install './python[pybullet]'``).

Set-up (each choice is a setting, recorded in the scorecard):

- Bullet's z is up; the paper's (x, y) is Bullet's (x, z), cylinder axes along
  y. A revolute joint about +y turns clockwise in the paper's picture (seen
  with x right and z up the viewer looks along +y), so joint angles are a1, a2
  as they stand.
- Planar motion by joints, not by symmetry: each cylinder is a multibody with a
  fixed, massless base and a chain prismatic-x, prismatic-z, revolute-y (the
  first two links massless and without shapes), so only the contacts couple
  the two bodies (reduced coordinates, Featherstone). A held cylinder 1 is a
  static multibody. The joints' default velocity motors (which act as joint
  friction) are switched off; linear, angular and joint damping are 0.
- Shapes: **spheres** of the cylinders' radii (``geom="sphere"``): in the
  plane of motion they are the same circles, and sphere–sphere and
  sphere–plane contacts are analytic (one point on the line of centres, exact
  normal); Bullet's cylinder–cylinder contacts go through GJK/EPA. The mass
  and the inertia k m r² about the axis are set explicitly.
- Contacts: restitution 0, rolling and spinning friction 0, cone friction on
  (``enableConeFriction``: a Coulomb cone instead of two independent
  directions). **Friction combine rule**: Bullet multiplies the two bodies'
  coefficients and clamps the product to 10 (``btManifoldResult``), so the
  floor gets μ_floor, cylinder 1 gets 1 and cylinder 2 gets μ_contact; a
  rolling contact gets ``mu_roll`` = 10, the largest Bullet allows.
- Solver: sequential impulses, ``numSolverIterations`` 200,
  ``solverResidualThreshold`` 1e-10, contact ERP (``contactERP``) 0.2 and
  ``erp`` 0.2 (Bullet's defaults), no split impulse for multibodies
  (Bullet's multibody solver has none), ``fixedTimeStep`` = dt with no
  sub-steps, deterministic overlapping pairs, ``contactSlop`` 1e-5 (Bullet's
  default: the contacts settle 1e-5 deep, and the start's first steps fall
  through it; with 0 or 1e-7 the contact force chatters, hundreds of spikes,
  and θ̇ is off by 1e-3).
- Forces: ``getContactPoints``: normalForce along the contact normal on B,
  the two lateral frictions along their directions (Bullet reports the
  applied impulses divided by the step); the friction's sign is the
  manifold's, see :meth:`PybulletAdapter._force_on_a`.
"""

from __future__ import annotations

import math
from typing import Any, Dict

from .adapter import engine_mu, initial_state


class PybulletAdapter:
    name = "pybullet"
    DEFAULTS: Dict[str, Any] = dict(
        geom="sphere", mu_roll=10.0, mu_which="static", numSolverIterations=200,
        solverResidualThreshold=1e-10, contactERP=0.2, erp=0.2, frictionERP=0.2,
        enableConeFriction=1, restitution=0.0, contactBreakingThreshold=0.02,
        constraintSolverType="SI", globalCFM=0.0, contactSlop=1e-5, friction_combine="product, clamped to 10")

    def __init__(self) -> None:
        import pybullet  # lazy: an optional dependency
        self._pb = pybullet
        self.version = str(pybullet.getAPIVersion())
        try:
            from importlib.metadata import version
            self.version = version("pybullet")
        except Exception:  # pragma: no cover
            pass
        self.cid = None
        self.settings: Dict[str, Any] = {}

    def __del__(self) -> None:
        try:
            if self.cid is not None:
                self._pb.disconnect(physicsClientId=self.cid)
        except Exception:
            pass

    def build(self, case_params: Dict[str, Any], settings: Dict[str, Any]) -> None:
        pb = self._pb
        s = {**self.DEFAULTS, **settings}
        p = self.p = dict(case_params)
        if self.cid is None:
            self.cid = pb.connect(pb.DIRECT)
        c = self.cid
        pb.resetSimulation(physicsClientId=c)
        pb.setGravity(0, 0, -p["g"], physicsClientId=c)
        solvers = {"SI": pb.CONSTRAINT_SOLVER_LCP_SI, "PGS": pb.CONSTRAINT_SOLVER_LCP_PGS,
                   "DANTZIG": pb.CONSTRAINT_SOLVER_LCP_DANTZIG}
        pb.setPhysicsEngineParameter(
            fixedTimeStep=s["dt"], numSubSteps=0, numSolverIterations=int(s["numSolverIterations"]),
            solverResidualThreshold=s["solverResidualThreshold"], contactERP=s["contactERP"],
            erp=s["erp"], frictionERP=s["frictionERP"], enableConeFriction=int(s["enableConeFriction"]),
            deterministicOverlappingPairs=1, restitutionVelocityThreshold=0.0,
            contactBreakingThreshold=s["contactBreakingThreshold"],
            constraintSolverType=solvers[s["constraintSolverType"]], globalCFM=s["globalCFM"],
            contactSlop=s["contactSlop"],
            physicsClientId=c)
        mu_f = engine_mu(p["mu_floor"], s["mu_roll"], s["mu_which"])
        mu_c = engine_mu(p["mu_contact"], s["mu_roll"], s["mu_which"])
        self.mu_engine = {"floor": min(mu_f, 10.0), "contact": min(mu_c, 10.0)}
        plane = pb.createCollisionShape(pb.GEOM_PLANE, physicsClientId=c)
        self.floor = pb.createMultiBody(0, plane, physicsClientId=c)
        self.held = p["floor"] == "fixed"
        pose, vel = initial_state(p)
        self.b1 = self._cylinder(p["m1"], p["r1"], p["k1"], 1.0, s, fixed=self.held)
        self.b2 = self._cylinder(p["m2"], p["r2"], p["k2"], mu_c, s)
        self._dyn(self.floor, -1, mu_f, s)
        # start: joint coordinates are the centre's x, z and the clockwise angle
        if self.held:
            pass
        else:
            for j, (q, v) in enumerate(zip((pose[0], pose[1], pose[2]), vel[:3])):
                pb.resetJointState(self.b1, j, q, v, physicsClientId=c)
        for j, (q, v) in enumerate(zip(pose[3:], vel[3:])):
            pb.resetJointState(self.b2, j, q, v, physicsClientId=c)
        self.settings = s

    def _dyn(self, body, link, mu, s):
        self._pb.changeDynamics(body, link, lateralFriction=mu, rollingFriction=0.0,
                                spinningFriction=0.0, restitution=s["restitution"],
                                linearDamping=0.0, angularDamping=0.0, jointDamping=0.0,
                                frictionAnchor=0, physicsClientId=self.cid)

    def _cylinder(self, m, r, k, mu, s, fixed=False):
        pb, c = self._pb, self.cid
        if s["geom"] == "sphere":
            shape = pb.createCollisionShape(pb.GEOM_SPHERE, radius=r, physicsClientId=c)
        else:   # a cylinder along y (Bullet's cylinders lie along z)
            shape = pb.createCollisionShape(pb.GEOM_CYLINDER, radius=r, height=1.0,
                                            collisionFrameOrientation=pb.getQuaternionFromEuler(
                                                [math.pi / 2, 0, 0]), physicsClientId=c)
        other = m * (3 * r * r + 1.0) / 12
        if fixed:
            b = pb.createMultiBody(0, shape, basePosition=[0, 0, r], physicsClientId=c)
            self._dyn(b, -1, mu, s)
            return b
        b = pb.createMultiBody(
            baseMass=0, baseCollisionShapeIndex=-1, basePosition=[0, 0, 0],
            linkMasses=[0, 0, m], linkCollisionShapeIndices=[-1, -1, shape],
            linkVisualShapeIndices=[-1, -1, -1], linkPositions=[[0, 0, 0]] * 3,
            linkOrientations=[[0, 0, 0, 1]] * 3, linkInertialFramePositions=[[0, 0, 0]] * 3,
            linkInertialFrameOrientations=[[0, 0, 0, 1]] * 3, linkParentIndices=[0, 1, 2],
            linkJointTypes=[pb.JOINT_PRISMATIC, pb.JOINT_PRISMATIC, pb.JOINT_REVOLUTE],
            linkJointAxis=[[1, 0, 0], [0, 0, 1], [0, 1, 0]], physicsClientId=c)
        pb.changeDynamics(b, 2, mass=m, localInertiaDiagonal=[other, k * m * r * r, other],
                          physicsClientId=c)
        pb.setJointMotorControlArray(b, [0, 1, 2], pb.VELOCITY_CONTROL, forces=[0, 0, 0],
                                     physicsClientId=c)
        for link in (-1, 0, 1, 2):
            self._dyn(b, link, mu, s)
        return b

    def step(self, dt: float) -> None:
        self._pb.stepSimulation(physicsClientId=self.cid)

    def _states(self):
        pb, c = self._pb, self.cid
        s2 = pb.getJointStates(self.b2, [0, 1, 2], physicsClientId=c)
        if self.held:
            s1 = ((0.0, 0.0), (self.p["r1"], 0.0), (0.0, 0.0))
        else:
            s1 = pb.getJointStates(self.b1, [0, 1, 2], physicsClientId=c)
        return s1, s2

    def poses(self):
        s1, s2 = self._states()
        return tuple(float(s[0]) for s in (*s1, *s2))

    def velocities(self):
        s1, s2 = self._states()
        return tuple(float(s[1]) for s in (*s1, *s2))

    def _force_on_a(self, a, b, friction_sign):
        """The force on ``a`` from ``b``. PyBullet reports the normal for the order
        asked (contactNormalOnB points from b to a), but the lateral friction
        directions in the manifold's own order, in which the friction acts with
        +direction on the manifold's first body: for a sphere on the plane that
        is the sphere, for two spheres the one created first (cylinder 1). So
        ``friction_sign`` is +1 where ``a`` is that body, −1 otherwise (checked
        by the momentum balance in the tests)."""
        fx = fz = 0.0
        for cp in self._pb.getContactPoints(a, b, physicsClientId=self.cid):
            n, fn = cp[7], cp[9]
            f1, d1, f2, d2 = cp[10], cp[11], cp[12], cp[13]
            fx += fn * n[0] + friction_sign * (f1 * d1[0] + f2 * d2[0])
            fz += fn * n[2] + friction_sign * (f1 * d1[2] + f2 * d2[2])
        return fx, fz

    def contact_forces(self):
        f = self._force_on_a(self.b2, self.b1, -1.0)
        return {"floor": None if self.held else self._force_on_a(self.b1, self.floor, 1.0),
                "contact": (float(f[0]), float(f[1]))}
