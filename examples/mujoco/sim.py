#!/usr/bin/env python3
"""cylroll's main case in MuJoCo: a solid cylinder rolling on a solid cylinder on the floor.

Identical solid cylinders (m = r = g = 1, k = 1/2), both contacts with friction mu, upper
cylinder started at rest with its line of centres theta0 = 0.1 rad clockwise from vertical.

Frames. MuJoCo's z is up. The cylinder axes lie along the world y axis and MuJoCo's (x, z)
is the paper's (x, y). Seen with x to the right and z up, the paper's out-of-page axis is
MuJoCo's -y, so a hinge about +y turns clockwise in the paper's picture: the hinge angle of
cylinder 1 is the paper's phi1 directly (rolling to +x means phi1 > 0).

Planarity. Each body has slide-x, slide-z and hinge-y joints and nothing else; only the two
contacts (floor-cylinder 1, cylinder 1-cylinder 2) couple them.

Outputs: a CSV in cylroll's golden column names (t, theta, theta_dot, x1, x2, y2, phi1), a
second CSV with the contact forces (t, F1, N1, F21, N12), and a JSON of diagnostics (slip
velocities, penetrations, contact geometry, chatter, slip onset, separation).
"""
import argparse
import json
import math
import sys

import mujoco
import numpy as np

R1 = R2 = 1.0
M1 = M2 = 1.0
K1 = K2 = 0.5
G = 1.0
HALF = 0.5  # half-length of the cylinders along y (any value: the motion is planar)
JOINTS = ("x1", "z1", "phi1", "x2", "z2", "rot2")


def mjcf(a):
    i1 = K1 * M1 * R1 ** 2
    i2 = K2 * M2 * R2 ** 2
    # inertia about the two other axes: that of a solid cylinder (those rotations are not
    # degrees of freedom, so it does not enter the motion)
    o1 = M1 * (3 * R1 ** 2 + (2 * HALF) ** 2) / 12
    o2 = M2 * (3 * R2 ** 2 + (2 * HALF) ** 2) / 12
    if a.geom == "cylinder":
        s1 = f'type="cylinder" size="{R1} {HALF}" euler="90 0 0"'
        s2 = f'type="cylinder" size="{R2} {HALF}" euler="90 0 0"'
    elif a.geom == "capsule":
        s1 = f'type="capsule" size="{R1} {HALF}" euler="90 0 0"'
        s2 = f'type="capsule" size="{R2} {HALF}" euler="90 0 0"'
    elif a.geom == "sphere":
        s1 = f'type="sphere" size="{R1}"'
        s2 = f'type="sphere" size="{R2}"'
    else:
        raise SystemExit(f"unknown --geom {a.geom}")
    solref = a.solref if a.solref else f"{a.tc_steps * a.dt!r} 1"
    solimp = a.solimp if a.solimp else f"{a.impedance} {a.impedance} 0.001 0.5 2"
    friction = f"{a.mu} 0 0"  # no torsional or rolling friction (condim 4/6 would add them)
    return f"""<mujoco model="cylroll_main">
  <compiler angle="degree" autolimits="true"/>
  <option timestep="{a.dt!r}" gravity="0 0 {-G}" integrator="{a.integrator}"
          cone="{a.cone}" impratio="{a.impratio}" solver="Newton"
          iterations="100" tolerance="1e-12" ls_tolerance="1e-6"
          noslip_iterations="{a.noslip}" noslip_tolerance="1e-12">
    <flag energy="enable"/>
  </option>
  <default>
    <geom condim="{a.condim}" friction="{friction}" solref="{solref}" solimp="{solimp}"
          margin="0" gap="0"/>
    <joint damping="0" armature="0" limited="false"/>
  </default>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 1"/>
    <body name="c1" pos="0 0 {R1}">
      <joint name="x1" type="slide" axis="1 0 0"/>
      <joint name="z1" type="slide" axis="0 0 1"/>
      <joint name="phi1" type="hinge" axis="0 1 0"/>
      <inertial pos="0 0 0" mass="{M1}" diaginertia="{o1} {i1} {o1}"/>
      <geom name="g1" {s1}/>
    </body>
    <body name="c2" pos="0 0 {R1 + R1 + R2}">
      <joint name="x2" type="slide" axis="1 0 0"/>
      <joint name="z2" type="slide" axis="0 0 1"/>
      <joint name="rot2" type="hinge" axis="0 1 0"/>
      <inertial pos="0 0 0" mass="{M2}" diaginertia="{o2} {i2} {o2}"/>
      <geom name="g2" {s2}/>
    </body>
  </worldbody>
</mujoco>
"""


class Sim:
    def __init__(self, a):
        self.a = a
        self.xml = mjcf(a)
        self.m = mujoco.MjModel.from_xml_string(self.xml)
        if a.libccd:
            self.m.opt.disableflags |= mujoco.mjtDisableBit.mjDSBL_NATIVECCD
        self.d = mujoco.MjData(self.m)
        gid = lambda n: mujoco.mj_name2id(self.m, mujoco.mjtObj.mjOBJ_GEOM, n)
        self.gf, self.g1, self.g2 = gid("floor"), gid("g1"), gid("g2")
        jid = lambda n: mujoco.mj_name2id(self.m, mujoco.mjtObj.mjOBJ_JOINT, n)
        self.qa = {n: self.m.jnt_qposadr[jid(n)] for n in JOINTS}
        self.va = {n: self.m.jnt_dofadr[jid(n)] for n in JOINTS}
        self.f6 = np.zeros(6)

    def reset(self, pen_floor=0.0, pen_cyl=0.0):
        """Rest at theta0; optionally start the soft contacts pressed by the given depths."""
        m, d, a = self.m, self.d, self.a
        mujoco.mj_resetData(m, d)
        y1 = R1 - pen_floor
        rr = R1 + R2 - pen_cyl
        d.qpos[self.qa["z1"]] = y1 - R1
        d.qpos[self.qa["x2"]] = rr * math.sin(a.theta0)
        d.qpos[self.qa["z2"]] = y1 + rr * math.cos(a.theta0) - (R1 + R1 + R2)
        mujoco.mj_forward(m, d)

    def step(self):
        mujoco.mj_step(self.m, self.d)
        # mj_step leaves position-dependent quantities (xpos, contacts, contact forces) at
        # the state before the integration: recompute them at the new (qpos, qvel)
        mujoco.mj_forward(self.m, self.d)

    def state(self):
        """Everything in the paper's frame (x right, y = MuJoCo's z up)."""
        m, d = self.m, self.d
        q = lambda n: float(d.qpos[self.qa[n]])
        v = lambda n: float(d.qvel[self.va[n]])
        x1, y1 = q("x1"), R1 + q("z1")
        x2, y2 = q("x2"), R1 + R1 + R2 + q("z2")
        vx1, vy1, w1 = v("x1"), v("z1"), v("phi1")
        vx2, vy2, w2 = v("x2"), v("z2"), v("rot2")
        dx, dy = x2 - x1, y2 - y1
        rr = math.hypot(dx, dy)
        theta = math.atan2(dx, dy)
        theta_dot = (dy * (vx2 - vx1) - dx * (vy2 - vy1)) / rr ** 2
        n = np.array([math.sin(theta), math.cos(theta)])      # from centre 1 to centre 2
        tv = np.array([math.cos(theta), -math.sin(theta)])    # the direction of F21

        def point_velocity(vx, vy, w, rx, ry):
            # clockwise rate w: (rx, ry) -> w * (ry, -rx)
            return np.array([vx + w * ry, vy - w * rx])

        # slip velocities: floor contact point (x1, 0); cylinder contact point on the line of
        # centres, R1 from centre 1. Contact 1-2: velocity of 2's material point relative to
        # 1's along (cos theta, -sin theta).
        slip_floor = float(point_velocity(vx1, vy1, w1, 0.0, -y1)[0])
        p = np.array([x1, y1]) + R1 * n
        v1p = point_velocity(vx1, vy1, w1, p[0] - x1, p[1] - y1)
        v2p = point_velocity(vx2, vy2, w2, p[0] - x2, p[1] - y2)
        slip_contact = float((v2p - v1p) @ tv)
        F1 = N1 = F21 = N12 = 0.0
        n_floor = n_cyl = 0
        pen_floor = pen_cyl = 0.0
        offline = normal_err = 0.0
        for i in range(d.ncon):
            c = d.contact[i]
            mujoco.mj_contactForce(m, d, i, self.f6)
            frame = c.frame.reshape(3, 3)
            fw = frame.T @ self.f6[:3]  # force on geom2 from geom1, world frame
            pair = {c.geom1, c.geom2}
            if pair == {self.gf, self.g1}:
                sgn = 1.0 if c.geom2 == self.g1 else -1.0
                F1 += float(sgn * fw[0])
                N1 += float(sgn * fw[2])
                n_floor += 1
                pen_floor = max(pen_floor, -float(c.dist))
            elif pair == {self.g1, self.g2}:
                sgn = 1.0 if c.geom2 == self.g2 else -1.0
                f = sgn * np.array([fw[0], fw[2]])
                N12 += float(f @ n)
                F21 += float(f @ tv)
                n_cyl += 1
                pen_cyl = max(pen_cyl, -float(c.dist))
                cp = np.array([c.pos[0] - x1, c.pos[2] - y1])
                offline = max(offline, float(abs(cp @ tv)))
                nrm = sgn * np.array([frame[0][0], frame[0][2]])
                normal_err = max(normal_err, abs(math.atan2(nrm[0], nrm[1]) - theta))
        # MuJoCo's constraint-space acceleration J*qacc of the normal row of the first 1-2
        # contact (it has no J'*qvel term), next to the centripetal r*theta_dot^2 that the
        # true second derivative of the centre distance contains on top of it
        jn_qacc = None
        for i in range(d.ncon):
            c = d.contact[i]
            if {c.geom1, c.geom2} == {self.g1, self.g2} and c.efc_address >= 0:
                row = d.efc_J[c.efc_address * m.nv:(c.efc_address + 1) * m.nv] \
                    if not mujoco.mj_isSparse(m) else None
                if row is not None:
                    jn_qacc = float(np.dot(row, d.qacc))
                break
        return dict(t=float(d.time), theta=theta, theta_dot=theta_dot, x1=x1, x2=x2, y2=y2,
                    phi1=q("phi1"), F1=F1, N1=N1, F21=F21, N12=N12, n_floor=n_floor,
                    n_cyl=n_cyl, pen_floor=pen_floor, pen_cyl=pen_cyl, offline=offline,
                    normal_err=normal_err, slip_floor=slip_floor, slip_contact=slip_contact,
                    gap=rr - (R1 + R2), jn_qacc=jn_qacc, r_thd2=rr * theta_dot ** 2)


def preload(sim):
    """Depths at which the soft contacts hold the system near rest: run briefly from exact
    touching and average the penetrations over the second half."""
    sim.reset()
    n = max(1, round(0.2 / sim.a.dt))
    pf, pc = [], []
    for i in range(n):
        sim.step()
        if i >= n // 2:
            s = sim.state()
            pf.append(s["pen_floor"])
            pc.append(s["pen_cyl"])
    return float(np.mean(pf)), float(np.mean(pc))


def run(a):
    sim = Sim(a)
    pen0 = preload(sim) if a.preload else (0.0, 0.0)
    sim.reset(*pen0)
    d = sim.d
    every = max(1, round(a.every / a.dt))
    ncsv = round(a.t_csv / a.dt)
    nmax = round(a.t_max / a.dt)
    rows, trace, glitches = [], [], []
    dg = dict(max_abs_slip_floor=0.0, max_abs_slip_contact=0.0, max_pen_floor=0.0,
              max_pen_cyl=0.0, min_pen_cyl=math.inf, max_offline=0.0, max_normal_err=0.0,
              contacts_floor=set(), contacts_cyl=set(), flips=0, flips_total=0)
    seen = on_prev = False
    chatter = slip_onset = cone_onset = sep = phi1dot_zero = w1_prev = None
    last_on = prev = None
    e0 = None
    step = 0
    while True:
        s = sim.state()
        if e0 is None:
            e0 = float(d.energy[0] + d.energy[1])
        on = s["N12"] > 0.0
        if on:
            seen = True
            last_on = s
        if seen and on != on_prev:
            dg["flips_total"] += 1
            if step <= ncsv:
                dg["flips"] += 1
            if not on and chatter is None:
                chatter = dict(t=s["t"], theta=s["theta"], theta_dot=s["theta_dot"],
                               N12_before=prev["N12"])
        on_prev = on
        w1 = float(d.qvel[sim.va["phi1"]])
        if phi1dot_zero is None and on and w1_prev is not None and w1_prev < 0.0 <= w1:
            # cylinder 1 reverses (phi1 rate crosses zero): interpolate theta linearly
            f = w1_prev / (w1_prev - w1)
            phi1dot_zero = dict(theta=prev["theta"] + f * (s["theta"] - prev["theta"]),
                                t=prev["t"] + f * (s["t"] - prev["t"]))
        w1_prev = w1
        if s["normal_err"] > 1e-3:
            glitches.append(dict(t=s["t"], theta=s["theta"], err=s["normal_err"]))
        if slip_onset is None and on and abs(s["slip_contact"]) > a.slip_threshold:
            slip_onset = dict(t=s["t"], theta=s["theta"], slip=s["slip_contact"],
                              N12=s["N12"], F21=s["F21"])
        if cone_onset is None and on and abs(s["F21"]) >= (1 - 1e-3) * a.mu * s["N12"]:
            # friction at contact 1-2 reaches the cone: rolling needs more than mu from here
            cone_onset = dict(t=s["t"], theta=s["theta"], slip=s["slip_contact"],
                              N12=s["N12"], F21=s["F21"])
        if step <= ncsv:
            for k in ("slip_floor", "slip_contact"):
                dg["max_abs_" + k] = max(dg["max_abs_" + k], abs(s[k]))
            dg["max_pen_floor"] = max(dg["max_pen_floor"], s["pen_floor"])
            dg["max_pen_cyl"] = max(dg["max_pen_cyl"], s["pen_cyl"])
            if s["n_cyl"]:
                dg["min_pen_cyl"] = min(dg["min_pen_cyl"], s["pen_cyl"])
            dg["max_offline"] = max(dg["max_offline"], s["offline"])
            if s["normal_err"] <= 1e-3:
                dg["max_normal_err"] = max(dg["max_normal_err"], s["normal_err"])
            dg["contacts_floor"].add(s["n_floor"])
            dg["contacts_cyl"].add(s["n_cyl"])
            if step % every == 0:
                rows.append(s)
        if step % every == 0 or step == ncsv:
            trace.append({k: s[k] for k in ("t", "theta", "theta_dot", "slip_floor",
                                            "slip_contact", "pen_floor", "pen_cyl", "N12",
                                            "F21", "N1", "F1", "jn_qacc", "r_thd2")})
        if seen and s["gap"] > a.sep_gap:
            # apart for good: separation is the last state whose contact carried force
            sep = dict(t=last_on["t"], theta=last_on["theta"], theta_dot=last_on["theta_dot"],
                       N12=last_on["N12"], F21=last_on["F21"],
                       slip_contact=last_on["slip_contact"], t_gap=s["t"], gap=s["gap"])
            break
        if step >= nmax:
            break
        prev = s
        sim.step()
        step += 1
    dg["contacts_floor"] = sorted(dg["contacts_floor"])
    dg["contacts_cyl"] = sorted(dg["contacts_cyl"])
    if dg["min_pen_cyl"] == math.inf:
        dg["min_pen_cyl"] = None
    dg["normal_glitches"] = glitches[:20]
    dg["n_normal_glitches"] = len(glitches)
    dg["energy_change"] = float(d.energy[0] + d.energy[1]) - e0
    return sim, rows, dict(mujoco_version=mujoco.__version__, args=vars(a),
                           preload=dict(pen_floor=pen0[0], pen_cyl=pen0[1]),
                           t_last_row=rows[-1]["t"] if rows else None,
                           separation=sep, chatter_onset=chatter, slip_onset=slip_onset,
                           cone_onset=cone_onset, phi1dot_zero=phi1dot_zero,
                           diag=dg, trace=trace)


def fmt_t(t, dt):
    # the engine's own time, printed to the resolution of its step
    return repr(round(t, max(0, -math.floor(math.log10(dt))) + 3))


def parser():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dt", type=float, default=1e-3, help="time step")
    ap.add_argument("--theta0", type=float, default=0.1)
    ap.add_argument("--mu", type=float, default=10.0, help="friction at both contacts")
    ap.add_argument("--integrator", default="Euler", help="Euler | implicitfast | RK4")
    ap.add_argument("--cone", default="elliptic", help="elliptic | pyramidal")
    ap.add_argument("--condim", type=int, default=3)
    ap.add_argument("--impratio", type=float, default=1.0)
    ap.add_argument("--noslip", type=int, default=50, help="noslip_iterations")
    ap.add_argument("--impedance", type=float, default=0.5,
                    help="solimp d (dmin = dmax), unless --solimp is given")
    ap.add_argument("--solimp", default=None)
    ap.add_argument("--solref", default=None, help="default: 'TC_STEPS*dt 1'")
    ap.add_argument("--tc-steps", type=float, default=2.0,
                    help="contact time constant in time steps, unless --solref is given")
    ap.add_argument("--geom", default="capsule", help="capsule | cylinder | sphere")
    ap.add_argument("--libccd", action="store_true",
                    help="libccd instead of MuJoCo's native convex collider")
    ap.add_argument("--no-preload", dest="preload", action="store_false",
                    help="start exactly touching instead of at the contacts' static depths")
    ap.add_argument("--every", type=float, default=0.05, help="CSV row interval")
    ap.add_argument("--t-csv", type=float, default=5.1, help="last CSV time")
    ap.add_argument("--t-max", type=float, default=7.0)
    ap.add_argument("--sep-gap", type=float, default=1e-3,
                    help="surface gap taken as apart for good")
    ap.add_argument("--slip-threshold", type=float, default=1e-4,
                    help="|slip velocity| at contact 1-2 taken as the onset of slipping")
    ap.add_argument("--csv", default=None)
    ap.add_argument("--forces-csv", default=None)
    ap.add_argument("--json", default=None)
    ap.add_argument("--xml", default=None)
    ap.add_argument("--mujoco-defaults", action="store_true",
                    help="MuJoCo's default contact settings instead (solref 0.02 1, solimp "
                         "0.9 0.95 0.001 0.5 2, pyramidal cone, no noslip, no preload)")
    return ap


def settings(args=(), **overrides):
    """The settings namespace: sim.py's defaults (the report's main setup), then the
    command-line style ``args`` (e.g. ``["--geom", "cylinder"]``), then ``overrides``
    by attribute name (``dt=1e-4``, ``mu=0.3``, ``t_csv=4.9``)."""
    a = parser().parse_args([str(x) for x in args])
    for k, v in overrides.items():
        if not hasattr(a, k):
            raise TypeError(f"unknown setting {k!r}")
        setattr(a, k, v)
    if a.mujoco_defaults:
        a.solref, a.solimp, a.cone, a.noslip, a.preload = (
            "0.02 1", "0.9 0.95 0.001 0.5 2", "pyramidal", 0, False)
    return a


KINEMATICS = ("theta", "theta_dot", "x1", "x2", "y2", "phi1")
FORCES = ("F1", "N1", "F21", "N12")


def table(rows, dt, columns=KINEMATICS):
    """The rows as {"t": array, column: array, ...}, what cylroll.check takes; the times
    are the engine's own, rounded to the resolution of its step (as in the CSV files)."""
    out = {"t": np.array([float(fmt_t(s["t"], dt)) for s in rows])}
    out.update({k: np.array([s[k] for s in rows]) for k in columns})
    return out


def simulate(a):
    """Runs the simulation of settings ``a`` and writes the files it names (``a.csv``,
    ``a.forces_csv``, ``a.json``, ``a.xml``); returns (rows, diagnostics)."""
    sim, rows, out = run(a)
    if a.xml:
        with open(a.xml, "w") as f:
            f.write(sim.xml)
    if a.csv:
        with open(a.csv, "w") as f:
            f.write("t," + ",".join(KINEMATICS) + "\n")
            for s in rows:
                f.write(",".join([fmt_t(s["t"], a.dt)] + [repr(s[k]) for k in KINEMATICS])
                        + "\n")
    if a.forces_csv:
        with open(a.forces_csv, "w") as f:
            f.write("t," + ",".join(FORCES) + "\n")
            for s in rows:
                f.write(",".join([fmt_t(s["t"], a.dt)] + [repr(s[k]) for k in FORCES]) + "\n")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(out, f, indent=1)
    return rows, out


def main():
    a = settings(sys.argv[1:])
    rows, out = simulate(a)
    brief = {k: out[k] for k in ("preload", "t_last_row", "separation", "chatter_onset",
                                 "slip_onset", "cone_onset", "phi1dot_zero")}
    brief["diag"] = {k: v for k, v in out["diag"].items() if k != "normal_glitches"}
    print(json.dumps(brief, indent=1))


if __name__ == "__main__":
    main()
