"""cylroll.conformance: score a physics engine on the cylinder-on-cylinder problem.

One command runs an engine on golden cases at several time steps and holds it
against the reference::

    python -m cylroll.conformance pybullet --dt 2e-3,1e-3,5e-4 --out card
    cylroll-conformance mujoco --cases mujoco_main,main_mu_0_3

(``pip install './python[engines]'`` for PyBullet, Pymunk and MuJoCo.) It
writes ``card/scorecard.json`` and ``card/index.html`` and exits 0 when every
check passes, 1 when some fail, 2 on bad usage.

Your own engine is one small class (the :class:`~cylroll.conformance.adapter.Adapter`
protocol; conventions in :mod:`cylroll.conformance.adapter`)::

    from cylroll.conformance.adapter import initial_state

    class MyEngine:
        name, version = "myengine", "1.0"

        def build(self, case_params, settings):          # settings["dt"] is the step
            self.settings = dict(settings)
            pose, vel = initial_state(case_params)         # the common start
            self.sim = mylib.Scene(...)                     # two discs, a floor, the contact laws
        def step(self, dt):
            self.sim.step(dt)
        def poses(self):          # centres and clockwise rotation angles
            return (x1, y1, a1, x2, y2, a2)
        def velocities(self):     # centre velocities and clockwise rates
            return (vx1, vy1, w1, vx2, vy2, w2)
        def contact_forces(self): # world vectors, or None where not exposed
            return {"floor": (fx, fy), "contact": (fx, fy)}

and ``python -m cylroll.conformance mypackage.mymodule:MyEngine``.
:mod:`cylroll.conformance.examples` is a complete one (a penalty-contact
integrator in about fifty lines).

The pieces: :mod:`~cylroll.conformance.adapter` (the protocol, the case as
floats, the common start), the built-in adapters
(:mod:`~cylroll.conformance.pybullet_adapter`,
:mod:`~cylroll.conformance.pymunk_adapter`,
:mod:`~cylroll.conformance.mujoco_adapter`; each imports its engine lazily),
:mod:`~cylroll.conformance.kinematics` (θ, φ1, φ2, slip speeds, gaps, energy
from poses), :mod:`~cylroll.conformance.measure` (events and faults found in
the engine's own output), :mod:`~cylroll.conformance.runner`
(:func:`run_case`, :func:`observed_order`),
:mod:`~cylroll.conformance.reference` (everything asked of the reference, in
one place) and :mod:`~cylroll.conformance.scorecard`.
"""

from .adapter import Adapter, case_params, initial_state
from .kinematics import derive
from .runner import RunResult, observed_order, run_case

__all__ = ["Adapter", "case_params", "initial_state", "derive", "RunResult", "run_case",
           "observed_order"]
