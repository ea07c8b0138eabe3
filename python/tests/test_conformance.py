"""cylroll.conformance: kinematics, event finders, observed order, the adapters'
conventions and one short real run per installed engine."""

import json
import math

import numpy as np
import pytest

import cylroll
from cylroll.conformance import adapter as ad
from cylroll.conformance import kinematics, measure, reference
from cylroll.conformance.cli import main as cli_main
from cylroll.conformance.examples import PenaltyDiscs
from cylroll.conformance.runner import observed_order, run_case

MAIN = dict(m1=1.0, m2=1.0, r1=1.0, r2=1.0, k1=0.5, k2=0.5, g=1.0, theta0=0.1, thetadot0=0.0,
            omega0=0.0, floor="roll", contact="roll", mu_floor=(math.inf, math.inf),
            mu_contact=(math.inf, math.inf), name="main")


# --- the case as floats, the start --------------------------------------------------------

def test_parse_exact_and_mu():
    assert ad.parse_exact("1/10") == 0.1
    assert ad.parse_exact("pi/6") == pytest.approx(math.pi / 6)
    assert ad.parse_exact("2*pi/3") == pytest.approx(2 * math.pi / 3)
    assert ad.parse_exact("-pi") == pytest.approx(-math.pi)
    assert ad.parse_exact("1e-3") == 1e-3
    assert ad.mu_pair("0.5,0.3") == (0.5, 0.3)
    assert ad.mu_pair("inf") == (math.inf, math.inf)


def test_case_params_of_golden_cases():
    p = ad.case_params(cylroll.golden.case("main_mu_0_3"))
    assert (p["floor"], p["contact"]) == ("coulomb", "coulomb")
    assert p["mu_contact"] == (0.3, 0.3) and p["theta0"] == 0.1
    p = ad.case_params(cylroll.golden.case("fixed_roll"))
    assert p["floor"] == "fixed" and p["mu_floor"] is None
    p = ad.case_params(cylroll.golden.case("slip_slip"))
    assert p["mu_contact"] == (0.0, 0.0) and p["mu_floor"] == (0.0, 0.0)
    p = ad.case_params(cylroll.golden.case("main_static_kinetic"))
    assert p["mu_floor"] == (0.5, 0.3)


def test_initial_state_matches_the_reference_rates():
    """θ̇0 and the conserved momentum of ω0 give the bodies' start velocities; the
    reference's velocity columns agree."""
    p = reference.params("moving_start")
    pose, vel = ad.initial_state(p)
    ref = reference.rows_at("moving_start", [0.0])
    assert vel[2] == pytest.approx(ref["phi1_dot"][0], abs=1e-12)
    assert vel[0] == pytest.approx(ref["x1_dot"][0], abs=1e-12)
    assert vel[3] == pytest.approx(ref["x2_dot"][0], abs=1e-12)
    assert vel[4] == pytest.approx(ref["y2_dot"][0], abs=1e-12)
    assert ref["phi2"][0] == 0.0 and reference.phi2_start("moving_start") == 0.0
    assert pose[3] == pytest.approx(ref["x2"][0], abs=1e-12)
    q = kinematics.derive(p, [pose], [vel])
    assert q["theta_dot"][0] == pytest.approx(0.1, abs=1e-12)
    assert q["s1"][0] == pytest.approx(0.0, abs=1e-12)
    assert q["s12"][0] == pytest.approx(0.0, abs=1e-12)


# --- kinematics against closed forms ---------------------------------------------------------

def _rolling_motion(t, r1=1.0, r2=0.5):
    """A synthetic motion obeying both rolling constraints: φ1(t), θ(t) given."""
    r = r1 + r2
    th, thd = 0.2 + 0.3 * t ** 2, 0.6 * t
    a1, w1 = -0.1 * t + 0.05 * t ** 3, -0.1 + 0.15 * t ** 2
    x1, vx1 = r1 * a1, r1 * w1
    x2, vx2 = x1 + r * np.sin(th), vx1 + r * np.cos(th) * thd
    y2, vy2 = r1 + r * np.cos(th), -r * np.sin(th) * thd
    # rolling between them: a2 = θ − (r1/r2)(a1 − θ) (clockwise), so φ2 − θ = −a2 + const
    a2 = th - (r1 / r2) * (a1 - th)
    w2 = thd - (r1 / r2) * (w1 - thd)
    y1 = np.full_like(t, r1)
    pose = np.stack([x1, y1, a1 + 3.0, x2, y2, a2 - 1.0], axis=1)   # arbitrary angle offsets
    vel = np.stack([vx1, 0 * t, w1, vx2, vy2, w2], axis=1)
    return pose, vel, th, thd, a1, w1


def test_kinematics_closed_forms_rolling():
    t = np.linspace(0, 1, 11)
    p = dict(MAIN, r1=1.0, r2=0.5)
    pose, vel, th, thd, a1, w1 = _rolling_motion(t)
    q = kinematics.derive(p, pose, vel, phi2_0=-2.0 * 0.2)
    np.testing.assert_allclose(q["theta"], th, atol=1e-14)
    np.testing.assert_allclose(q["theta_dot"], thd, atol=1e-13)
    np.testing.assert_allclose(q["phi1"], a1 - a1[0], atol=1e-14)
    np.testing.assert_allclose(q["phi1_dot"], w1, atol=1e-14)
    # the paper's rolling relation r2 φ2 = r1 (φ1 − θ), in the paper's gauge φ2(0) = −r1 θ0 / r2
    np.testing.assert_allclose(0.5 * q["phi2"], 1.0 * (q["phi1"] - q["theta"]), atol=1e-13)
    np.testing.assert_allclose(0.5 * q["phi2_dot"], q["phi1_dot"] - q["theta_dot"], atol=1e-13)
    np.testing.assert_allclose(q["s1"], 0.0, atol=1e-14)
    np.testing.assert_allclose(q["s12"], 0.0, atol=1e-13)
    np.testing.assert_allclose(q["gap"], 0.0, atol=1e-14)
    np.testing.assert_allclose(q["floor_gap1"], 0.0, atol=1e-15)


def test_kinematics_gauge_slip_gap_energy():
    p = dict(MAIN)
    # cylinder 2 1e-3 off the surface at θ = 0.3, spinning clockwise at 2 while at rest
    th = 0.3
    pose = [(0.0, 1.0, 0.7, 2.001 * math.sin(th), 1 + 2.001 * math.cos(th), 5.0)]
    vel = [(0.5, 0.0, 0.2, 0.5, 0.0, 2.0)]
    q = kinematics.derive(p, pose, vel)
    assert q["phi1"][0] == 0.0 and q["phi2"][0] == 0.0       # default gauge: both 0 at t = 0
    assert q["gap"][0] == pytest.approx(1e-3)
    assert q["s1"][0] == pytest.approx(0.5 - 0.2)
    # s12 = r θ̇ + r2 ψ̇2 − r1 φ̇1 with θ̇ = 0 (same velocities), ψ̇2 = −w2
    assert q["s12"][0] == pytest.approx(-2.0 - 0.2)
    E = 0.5 * 0.25 + 0.5 * 0.5 * 0.04 + 0.5 * 0.25 + 0.5 * 0.5 * 4 + 1.0 + pose[0][4]
    assert q["energy"][0] == pytest.approx(E)
    # forces: a push of 1 on cylinder 2 along the line of centres is N12 = 1, F21 = 0
    f = [(0.2, 2.0, math.sin(th), math.cos(th))]
    q = kinematics.derive(p, pose, vel, f)
    assert (q["N12"][0], q["F21"][0], q["F1"][0], q["N1"][0]) == pytest.approx((1, 0, 0.2, 2))


# --- the event finders on synthetic noisy signals -----------------------------------------------

def test_slip_onset_by_speed_ignores_chatter():
    rng = np.random.default_rng(1)
    t = np.arange(0, 2, 1e-3)
    s = 1e-7 * rng.standard_normal(t.size)
    s[[300, 301, 700]] = 5e-3                      # single-step spikes: not an onset
    s += np.where(t > 1.2, 0.5 * (t - 1.2), 0.0)   # slipping from t = 1.2
    F = N = np.full(t.size, np.nan)
    so = measure.slip_onset(t, s, F, N, None, None, 1.0, 1.0)
    assert so["method"] == "speed"
    assert abs(t[so["index"]] - 1.2) < 2e-3


def test_slip_onset_by_cone_extends_to_the_cone():
    rng = np.random.default_rng(2)
    t = np.arange(0, 2, 1e-3)
    N = 1.0 + 1e-5 * rng.standard_normal(t.size)
    ratio = np.minimum(1.0, 0.5 + 0.5 * t / 1.3)          # reaches the cone at t = 1.3
    F = 0.3 * ratio * N
    F[500] = 0.3 * N[500]                                 # one noisy sample on the cone
    so = measure.slip_onset(t, np.zeros_like(t), F, N, 0.3, None, 1.0, 1.0)
    assert so["method"] == "cone"
    assert abs(so["t"] - 1.3) < 1e-3


def test_parting_losses_and_impact():
    t = np.arange(0, 3, 1e-3)
    closed = t < 2.0
    closed[[500, 501, 900]] = False          # spurious losses before the parting
    gap = np.where(t < 2.0, 0.0, 0.5 * (t - 2.0) ** 2)
    part = measure.parting(t, closed, gap, 1.0)
    assert part["losses"] == 2
    assert abs(t[part["index"]] - 2.0) <= 1e-3
    fg = 1.0 - t * 0.5                        # reaches the floor at t = 2
    fg[t < 2.5] = 0.1
    fg[t >= 2.5] = -0.1
    imp = measure.impact(t, closed, fg, part["index"])
    assert imp["surface"] == "floor" and abs(t[imp["index"]] - 2.5) < 1e-9
    # never apart for good: no parting
    assert measure.parting(t, np.ones_like(closed), gap, 1.0)["index"] is None


def test_cone_violation_and_chatter():
    N = np.ones(200)
    F = 0.3 * np.ones(200)
    F[50] = 0.33
    assert measure.cone_violation(F, N, 0.3, np.ones(200, bool), 1.0) == pytest.approx(0.1)
    assert measure.cone_violation(F, N, math.inf, np.ones(200, bool), 1.0) is None
    N2 = N.copy()
    N2[[60, 120]] = 5.0
    ch = measure.force_chatter(N2, None, 1.0)
    assert ch["spikes"] == 2 and ch["max_ratio"] == pytest.approx(5.0)


def test_observed_order():
    assert observed_order({1e-3: 2e-4, 5e-4: 1e-4, 2.5e-4: 5e-5}) == pytest.approx(1.0)
    assert observed_order({0.1: 3e-2, 0.05: 7.5e-3, 0.025: 1.875e-3}) == pytest.approx(2.0)
    rng = np.random.default_rng(3)
    dts = [4e-3, 2e-3, 1e-3, 5e-4]
    errs = {h: 7 * h * (1 + 0.05 * rng.standard_normal()) for h in dts}
    assert abs(observed_order(errs) - 1.0) < 0.1
    assert observed_order({1e-3: 1e-4, 5e-4: 5e-5}) is None
    assert observed_order({1e-3: 1e-4, 5e-4: 0.0, 2e-4: float("nan")}) is None


# --- adapters: conventions, forces, a real run ---------------------------------------------------

ENGINES = ["pybullet", "pymunk", "mujoco"]


def _adapter(name):
    if name == "example":
        return PenaltyDiscs()
    pytest.importorskip(name)
    from cylroll.conformance.cli import load_adapter
    return load_adapter(name)


def test_the_example_adapter_satisfies_the_protocol():
    assert isinstance(PenaltyDiscs(), ad.Adapter)


@pytest.mark.parametrize("engine", ENGINES + ["example"])
def test_adapter_sign_conventions(engine):
    """θ grows clockwise (the upper centre moves to +x); a cylinder 1 rolling to +x
    has φ1 > 0 with x1 = r1 φ1; both from the case moving_start (ω0 = 0.5)."""
    a = _adapter(engine)
    p = reference.params("moving_start")
    dt = 1e-3
    run = run_case(a, p, dt, 0.5, phi2_0=reference.phi2_start("moving_start"))
    q = run.q
    assert q["theta"][0] == pytest.approx(0.2, abs=1e-4)
    assert q["theta"][-1] > 0.2 + 0.04 and q["theta_dot"][-1] > 0.1
    assert q["x2"][-1] > q["x2"][0]
    assert q["x1"][-1] > 0.1 and q["phi1"][-1] > 0.1
    assert q["x1"][-1] == pytest.approx(q["phi1"][-1], abs=2e-3)
    ref = reference.rows_at("moving_start", [0.5])
    for k in ("theta", "x1", "phi1", "phi2", "x2", "y2"):
        assert q[k][-1] == pytest.approx(ref[k][0], abs=5e-3), k


@pytest.mark.parametrize("engine", ENGINES + ["example"])
def test_adapter_forces_balance_the_momentum(engine):
    """The exposed forces are those the engine applied: m2 Δv2/dt = f(1 on 2) + m2 g
    and m1 Δv1/dt = f(floor) − f(1 on 2) + m1 g, over the first second."""
    a = _adapter(engine)
    p = reference.params("main_mu_0_3")
    dt = 1e-3
    run = run_case(a, p, dt, 1.0)
    q = run.q
    th = q["theta"]
    fx2 = q["N12"] * np.sin(th) + q["F21"] * np.cos(th)
    fy2 = q["N12"] * np.cos(th) - q["F21"] * np.sin(th)
    k = slice(10, None)     # after the contacts have formed
    ax2 = np.diff(q["x2_dot"])[k] / dt
    ay2 = np.diff(q["y2_dot"])[k] / dt
    ax1 = np.diff(q["x1_dot"])[k] / dt
    tol = 2e-3 if engine == "mujoco" else 1e-9       # MuJoCo: its soft contact's own solve
    np.testing.assert_allclose(ax2, fx2[1:][k], atol=tol)
    np.testing.assert_allclose(ay2, fy2[1:][k] - 1.0, atol=tol)
    np.testing.assert_allclose(ax1, (q["F1"] - fx2)[1:][k], atol=tol)


@pytest.mark.parametrize("engine", ENGINES)
def test_slip_onset_at_mu_0_3_matches_the_reference(engine):
    a = _adapter(engine)
    onset = next(e for e in cylroll.golden.case("main_mu_0_3").separation(digits=12).events
                 if e.kind == "slip_onset")
    p = reference.params("main_mu_0_3")
    run = run_case(a, p, 5e-4, float(onset.t) + 0.1)
    e = run.event("slip_onset", "contact")
    assert e is not None
    assert abs(e["theta"] - float(onset.theta)) < 1e-3


# --- the reference side and the command -----------------------------------------------------------

def test_branch_point_of_the_main_case():
    """θ*, t* and θs of the main case (tests/fixtures/branch_independent.toml,
    an independent Newton–Euler derivation); a frictionless pair is unique."""
    bp = reference.branch_point("mujoco_main")
    assert bp["theta"] == pytest.approx(0.9657131749813609, abs=1e-12)
    assert bp["t"] == pytest.approx(5.051573457307166, abs=1e-10)   # events at 12 digits
    assert bp["N12"] > 0.05
    a, b = reference.window("mujoco_main")
    assert (a, b) == pytest.approx((0.9657131749813609, 1.0507720620185106), abs=1e-10)
    assert reference.branch_point("slip_slip") is None and reference.window("slip_slip") is None


def test_the_reference_on_each_branch():
    """On the part branch the cylinders part at θ* and fly (N12 = F21 = 0) while
    the stay branch still presses; parting at an angle inside the window parts
    there; both end at their first impact."""
    t_star = reference.branch_point("mujoco_main")["t"]
    t_s = reference.closed_end("mujoco_main")["t"]
    tm = 0.5 * (t_star + t_s)
    stay = reference.rows_at("mujoco_main", [tm])
    part = reference.rows_at("mujoco_main", [tm], "part")
    assert stay["N12"][0] > 0.01 and part["N12"][0] == 0.0 and part["F21"][0] == 0.0
    sep = [e for e in reference.events("mujoco_main", "part") if e["kind"] == "separation"]
    assert sep[0]["theta"] == pytest.approx(0.9657131749813609, abs=1e-12)
    at = [e for e in reference.events("mujoco_main", 1.0) if e["kind"] == "separation"]
    assert at[0]["theta"] == pytest.approx(1.0, abs=1e-12)
    assert reference.t_max("mujoco_main", "part") != reference.t_max("mujoco_main")
    ph = reference.phases("mujoco_main", "part")
    assert ph["after_parting"][0] == pytest.approx(t_star, abs=1e-12)


class _Run:
    def __init__(self, theta):
        self._theta = theta

    def event(self, kind, contact=None):
        return None if self._theta is None else dict(t=1.0, theta=self._theta)


def test_the_branch_an_engine_took():
    """Where the motion is not unique the engine is judged on the branch it took:
    near θ* the part branch, near θs the closed one, inside the window the
    reference parting at the engine's angle, before θ* not lawful."""
    from cylroll.conformance.scorecard import _branch
    win = (0.9657, 1.0508)
    assert _branch(_Run(0.9660), win) == ("part", "part")
    assert _branch(_Run(1.0500), win) == ("stay", "stay")
    assert _branch(_Run(1.0), win) == ("part_at", 1.0)
    assert _branch(_Run(0.90), win) == ("outside", "stay")
    assert _branch(_Run(None), win) == (None, "stay")
    assert _branch(_Run(0.9660), None) == (None, "stay")


def test_command_usage_errors(tmp_path, capsys):
    assert cli_main(["nosuchengine", "--out", str(tmp_path)]) == 2
    assert cli_main(["example", "--cases", "nosuchcase", "--out", str(tmp_path)]) == 2
    assert cli_main(["example", "--dt", "1e-3,x", "--out", str(tmp_path)]) == 2
    assert cli_main(["example", "--set", "novalue", "--out", str(tmp_path)]) == 2
    assert cli_main(["--bogus-flag"]) == 2
    # too few rows would leave theta's error unmeasured: one row (t = 0) read
    # error 0 and passed an engine with gravity 20% off
    for n in ["0", "1", "19", "-5", "x", "2.5", "1000001"]:
        assert cli_main(["example", "--max-rows", n, "--out", str(tmp_path)]) == 2
        assert "--max-rows" in capsys.readouterr().err
    from cylroll.conformance.scorecard import score_case
    from cylroll.conformance.examples import PenaltyDiscs
    for bad in (1, 10**7, 20.0, True):
        with pytest.raises(ValueError, match="max_rows"):
            score_case(PenaltyDiscs(), "slip_slip", [1e-3], max_rows=bad)


def test_command_writes_the_scorecard(tmp_path):
    rc = cli_main(["example", "--cases", "slip_slip", "--dt", "4e-3,2e-3,1e-3",
                   "--out", str(tmp_path), "-q"])
    assert rc in (0, 1)
    card = json.loads((tmp_path / "scorecard.json").read_text())
    assert (tmp_path / "index.html").read_text().startswith("<!doctype html>")
    assert card["engine"]["name"] == "penalty-discs" and "omega_dt" in card["engine"]["settings"]
    c = card["cases"][0]
    assert c["case"] == "slip_slip" and c["params"]["contact"] == "slip"
    assert [r["dt"] for r in c["runs"]] == [4e-3, 2e-3, 1e-3]
    run = c["runs"][-1]
    assert set(run["errors"]["theta"]) <= {"before_slip", "slipping", "after_parting"}
    sep = next(e for e in run["events"] if e["kind"] == "separation")
    assert abs(sep["error"]) < 1e-2 and set(sep["reference"]) == {"t", "theta"}
    assert c["order"]["theta"] == pytest.approx(1.0, abs=0.3)
    assert all({"name", "value", "tolerance", "pass", "why"} <= set(ch) for ch in c["checks"])
    # every run also carries the verdict of cylroll check's scoring core, per
    # phase of the reference (frictionless: sliding, then the flight)
    ck = run["check"]
    assert "error" not in ck, ck
    assert ck["verdict"] in ("pass", "fail") and ck["branch"] == "stay"
    assert [p["mode"] for p in ck["phases"]][:1] == ["slip/slip"]
    assert ck["columns"]["theta"]["max_abs"] == pytest.approx(
        max(run["errors"]["theta"].values()), rel=1e-6, abs=1e-12)
    assert card["core_tolerances"]["rtol"] == 1e-3
    assert rc == (0 if card["passed"] else 1)
