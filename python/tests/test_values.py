"""The values the Rust tests hold, held again through the Python API."""
import csv
import re
import json
from decimal import Decimal, localcontext
from fractions import Fraction

import numpy as np
import pytest

import cylroll

from _decimal_math import cos, pi, round_sig


def test_theta_s_is_pi_over_3_to_all_digits():
    # identical solid cylinders from rest at the top: θs = π/3 (the paper's main result)
    for digits in (30, 200):
        sep = cylroll.Model().separation(digits=digits)
        with localcontext() as c:
            c.prec = digits + 20
            expect = round_sig(pi(digits + 20) / 3, digits)
        assert sep.theta_s.text == expect
        assert sep.theta_s.digits == digits
        assert sep.t_s is None          # infinite from rest at the top
        assert sep.theta_s.err < Decimal(10) ** (-digits)
        # no event has a finite time; both contacts roll (stick) from the start
        assert sep.events == [] and sep.start_mode == "stick/stick" and not sep.friction


@pytest.mark.parametrize("k2, cos_s", [("0", Fraction(2, 3)), ("1/2", Fraction(4, 7)),
                                       ("2/5", Fraction(10, 17))])
def test_fixed_lower_cylinder_closed_form(k2, cos_s):
    # cos θs = 2/(3 + k2) with the lower cylinder held (paper footnote 8)
    sep = cylroll.Model(floor="fixed", k2=k2).separation(digits=60)
    c = cos(sep.theta_s.decimal(), 80)
    with localcontext() as ctx:
        ctx.prec = 80
        assert abs(c - Decimal(cos_s.numerator) / cos_s.denominator) < Decimal("1e-58")


def test_fixed_lower_cylinder_forces_closed_form():
    # fixed floor, rolling contact, from rest at θ0: (1 + k2) r θ̇² = 2 g (cos θ0 − cos θ),
    # N12 = m2 g cos θ − m2 r θ̇²
    m = cylroll.Model(floor="fixed", theta0="1/10", k2="1/2")
    f = m.forces("0.7", digits=40)
    with localcontext() as ctx:
        ctx.prec = 60
        r, k2 = Decimal(2), Decimal("0.5")
        th2 = 2 * (cos(Decimal("0.1"), 60) - cos(Decimal("0.7"), 60)) / (r * (1 + k2))
        n12 = cos(Decimal("0.7"), 60) - r * th2
        assert abs(f.theta_dot.decimal() ** 2 - th2) < Decimal("1e-38")
        assert abs(f["N12"].decimal() - n12) < Decimal("1e-38")
    assert f["F1"].text == "0" or f.F1.digits > 0
    assert f.mode == "held/stick"
    assert list(f) == ["F1", "N1", "F21", "N12", "theta_dot", "theta_ddot", "mu_floor",
                       "mu_contact", "s1", "s12", "work", "theta_mu_floor_max",
                       "mu_floor_max", "theta_mu_contact_max", "mu_contact_max"]
    # a rolling contact does not slip, and nothing is dissipated
    assert (f["s1"].text, f["s12"].text, f["work"].text) == ("0", "0", "0")


def test_friction_needed_so_far_bounds_a_scan():
    # the most friction the held floor and the rolling contact need over [θ0, θ]: no
    # sampled |F|/N exceeds it, the best sample comes close, and it is reached where said
    m = cylroll.Model(floor="fixed", theta0="1/10", k2="1/2")
    f = m.forces("0.7", digits=25)
    samples = [m.forces(f"{k / 100}", digits=12) for k in range(10, 71)]
    for key in ("mu_floor", "mu_contact"):
        best = max(s[key].decimal() for s in samples)
        top = f[f"{key}_max"].decimal()
        assert best <= top + Decimal("1e-11")
        assert top - best < Decimal("2e-3")
        at = m.forces(f[f"theta_{key}_max"].text, digits=25)
        assert abs(at[key].decimal() - top) < Decimal("1e-23")
    # the contact's need grows to the end here: reached at θ itself
    assert f["theta_mu_contact_max"].text == "0.7" + "0" * 24


def test_time_and_trajectory_agree():
    m = cylroll.Model(theta0="1/10")
    t = m.time("0.9", digits=30)
    assert t.digits == 30 and t.name == "t" and t.mode == "stick/stick"
    row = m.trajectory([t.text], digits=30)
    assert abs(row.values("theta")[0].decimal() - Decimal("0.9")) < Decimal("1e-28")
    assert float(t) == pytest.approx(4.9, abs=0.2)


def test_trajectory_reproduces_the_golden_csv(golden_dir):
    # the golden data were written by the command line (`cylroll golden`) at 30 digits
    for name in ("mujoco_main", "main_mu_1"):
        with open(golden_dir / "data" / f"{name}.csv", newline="") as f:
            rows = list(csv.reader(f))
        head, data = rows[0], rows[1:]
        times = [r[0] for r in data[::8]]
        traj = cylroll.golden.case(name).trajectory(times, digits=30)
        want_cols = [c for c in head if c != "mode"]
        assert traj.columns == want_cols
        for i, r in enumerate(data[::8]):
            assert [v.text for v in traj.rows[i]] == r[:len(want_cols)]
            if "mode" in head:
                assert traj.modes[i] == r[-1]


def test_separation_reproduces_the_golden_json(golden_dir):
    doc = json.loads((golden_dir / "data" / "main_mu_0_3.json").read_text())
    sep = cylroll.golden.case("main_mu_0_3").separation(digits=30)
    assert sep.start_mode == doc["start_mode"]
    assert [(e.kind, e.contact, e.mode, e.t.text, e.theta.text) for e in sep.events] == [
        (e["kind"], e["contact"], e["mode"], e["t"], e["theta"]) for e in doc["events"]]
    for k, v in doc["scalars"].items():
        if k in sep:
            assert sep[k].text == v


def _energy(p, row):
    """Total energy of the roll/roll system from one trajectory row, from the README's
    conventions: x1 = r1 φ1, (x2, y2) = (x1 + r sin θ, r1 + r cos θ), φ2 − θ the
    counter-clockwise rotation of cylinder 2 with r2 φ2 = r1(φ1 − θ + θ0) (φ2 = 0 at
    t = 0). With T the kinetic
    energy in (φ1, θ), the momentum conjugate to φ1 is
        p = r1² D φ̇1 − m2 r1 r θ̇ (k2 − cos θ),  D = m1 (1 + k1) + m2 (1 + k2),
    conserved (φ1 is cyclic) and equal to r1² D ω0 (ω0 = φ̇1 where θ̇ = 0), so
        φ̇1 = ω0 + m2 r θ̇ (k2 − cos θ) / (r1 D).
    cos θ and sin θ are taken from the position columns, not from θ."""
    m1, m2, r1, r2, k1, k2, g, w0 = (p[k] for k in ("m1", "m2", "r1", "r2", "k1", "k2", "g",
                                                    "omega0"))
    r = r1 + r2
    th_d, x1, x2, y2 = row["theta_dot"], row["x1"], row["x2"], row["y2"]
    c = (y2 - r1) / r
    s = (x2 - x1) / r
    D = m1 * (1 + k1) + m2 * (1 + k2)
    phi1_d = w0 + m2 * r * th_d * (k2 - c) / (r1 * D)
    vx2 = r1 * phi1_d + r * c * th_d
    vy2 = -r * s * th_d
    psi2_d = (r1 * phi1_d - r * th_d) / r2
    T = (m1 * (1 + k1) * r1 ** 2 * phi1_d ** 2 + m2 * (vx2 ** 2 + vy2 ** 2)
         + k2 * m2 * r2 ** 2 * psi2_d ** 2) / 2
    return T + m2 * g * y2, phi1_d


def test_energy_is_conserved_along_a_trajectory():
    kw = dict(m1=2, m2=1, r1=1, r2="1/2", k1="1/2", k2="2/5", g="9.81", theta0="1/5",
              thetadot0="1/10", omega0="1/3")
    m = cylroll.Model(**kw)
    p = {k: Decimal(Fraction(v).numerator) / Fraction(v).denominator
         for k, v in ((k, Fraction(str(v))) for k, v in kw.items())}
    t_s = m.separation(digits=20).t_s
    steps = 40
    traj = m.trajectory(t_end=Decimal(t_s.text) * Decimal("0.999"), steps=steps, digits=30)
    assert len(traj) == steps + 1
    with localcontext() as ctx:
        ctx.prec = 60
        cols = {c: [v.decimal() for v in traj.values(c)] for c in traj.columns}
        rows = [{c: cols[c][i] for c in cols} for i in range(len(traj))]
        energies = [_energy(p, r)[0] for r in rows]
        e0 = energies[0]
        scale = p["m2"] * p["g"] * (p["r1"] + p["r2"])
        drift = max(abs(e - e0) for e in energies) / scale
        assert drift < Decimal("1e-26"), drift
        # the derivation's φ̇1 against the phi1_dot column, and against the phi1
        # column by central differences (O(h²))
        h = Decimal(t_s.text) * Decimal("0.999") / steps
        for i in range(1, len(rows) - 1):
            fd = (rows[i + 1]["phi1"] - rows[i - 1]["phi1"]) / (2 * h)
            assert abs(fd - _energy(p, rows[i])[1]) < Decimal("1e-2") * (1 + abs(fd))
        for r in rows:
            assert abs(r["phi1_dot"] - _energy(p, r)[1]) < Decimal("1e-27")
        # the constraints the columns obey (φ2 counted from 0 at t = 0)
        for r in rows:
            assert abs(r["x1"] - p["r1"] * r["phi1"]) < Decimal("1e-28")
            assert abs(r["x1_dot"] - p["r1"] * r["phi1_dot"]) < Decimal("1e-27")
            assert abs(p["r2"] * r["phi2"]
                       - p["r1"] * (r["phi1"] - r["theta"] + p["theta0"])) < Decimal("1e-28")
            assert abs(p["r2"] * r["phi2_dot"]
                       - p["r1"] * (r["phi1_dot"] - r["theta_dot"])) < Decimal("1e-27")
    # the same energy in float64 from the NumPy columns
    a = {c: traj.column(c) for c in traj.columns}
    pf = {k: float(v) for k, v in p.items()}
    ef = np.array([_energy(pf, {c: a[c][i] for c in a})[0] for i in range(len(traj))])
    assert np.ptp(ef) / float(scale) < 1e-13


def test_friction_events_and_columns():
    m = cylroll.Model(theta0="1/10", mu_floor="0.3", mu_contact="0.3")
    sep = m.separation(digits=12)
    assert sep.friction and sep.start_mode == "stick/stick"
    assert [e.kind for e in sep.events] == ["slip_onset", "separation", "impact"]
    onset = sep.events[0]
    assert onset.contact == "contact" and onset.mode == "stick/slip+"
    assert onset.theta.text == "0.584216022929"
    assert sep.events[1].t.text == sep.t_s.text and sep.events[1].theta.text == sep.theta_s.text
    assert sep.impact_surface == "floor"
    assert list(sep)[:3] == ["theta_s", "t_s", "work_s"]
    assert "event 1: slip_onset (contact)" in str(sep)
    traj = m.trajectory(t_end="5.5", steps=11, digits=12)
    assert traj.columns == list(cylroll.COLUMNS)
    assert traj.modes[0] == "stick/stick" and traj.modes[-1] == "flight"
    assert traj.column("work")[-1] == pytest.approx(float(sep["work_s"]), rel=1e-9)
    f = m.forces("0.7", digits=12)
    assert f.mode == "stick/slip+" and float(f["s12"]) > 0
    t = m.time("0.7", digits=12)
    assert t.mode == "stick/slip+"


def test_value_type():
    v = cylroll.Model(theta0="1/10").time("pi/4", digits=25)
    assert isinstance(v.decimal(), Decimal) and str(v) == v.text
    assert float(v) == float(v.text)
    assert len(v.text.replace(".", "").lstrip("0")) == 25 == v.digits
    assert "Value('t', '4.680205009695901966571853'" in repr(v)


def test_trajectory_table_api():
    m = cylroll.Model(theta0="1/10")
    traj = m.trajectory(np.linspace(0, 5, 11), digits=20)
    assert traj.values("t")[1].text == "0.5"           # floats read as they print
    arr = traj.to_numpy()
    assert arr.shape == (11, 21) and arr.dtype == np.float64
    assert np.array_equal(arr[:, 1], traj.column("theta"))
    assert np.array_equal(traj["theta"], traj.column("theta"))
    assert (traj.errors("theta") < 1e-19).all()
    assert traj.to_csv().splitlines()[0] == ",".join(cylroll.COLUMNS + ("mode",))
    assert set(traj.to_dict()) == set(traj.columns)
    with pytest.raises(KeyError):
        traj.column("nope")
    assert "Trajectory: 11 rows x 21 columns" in str(traj)
    grid = m.trajectory(t_end="1/3", steps=3, digits=10)
    assert [v.text for v in grid.values("t")][0] == "0"


def test_trajectory_columns_carry_the_digits_of_the_full_table():
    # with friction, slip onset then parting: theta alone (no force computed)
    # and a subset in an order of its own give the full table's digits
    m = cylroll.Model(theta0="1/10", mu="0.3")
    times = ["0", "0.5", "2", "4.4", "4.9", "5.5"]
    full = m.trajectory(times, digits=25)
    for cols in (["t", "theta"], ["theta"], ["N12", "theta", "work"]):
        part = m.trajectory(times, digits=25, columns=cols)
        assert part.columns == cols
        assert part.modes == full.modes
        for c in cols:
            assert [v.text for v in part.values(c)] == [v.text for v in full.values(c)], c
        assert part.to_numpy().shape == (len(times), len(cols))
        # its text shows the columns it has (it raised ValueError for a
        # table without t, theta_dot or N12, so pytest could not show it)
        text = repr(part)
        assert text.startswith(f"Trajectory: {len(times)} rows x {len(cols)} columns")
        shown = [c for c in ("t", "theta", "theta_dot", "N12") if c in cols] or cols[:4]
        assert text.splitlines()[1].split() == shown + ["mode"]
    with pytest.raises(cylroll.InvalidParameterError, match="columns"):
        m.trajectory(times, digits=10, columns=["theta", "nope"])
    with pytest.raises(cylroll.InvalidParameterError, match="only once"):
        m.trajectory(times, digits=10, columns=["theta", "theta"])
    with pytest.raises(TypeError):
        m.trajectory(times, digits=10, columns="theta")


def test_to_pandas():
    pd = pytest.importorskip("pandas")
    m = cylroll.Model(theta0="1/10", mu_contact="0.3")
    df = m.trajectory(t_end=5, steps=5, digits=10).to_pandas()
    assert isinstance(df, pd.DataFrame) and df["mode"].iloc[0] == "stick/stick"
    assert df["theta"].dtype == np.float64


def test_mu_is_coulomb_friction_at_both_contacts():
    m = cylroll.Model(theta0="1/10", mu="0.3")
    assert m == cylroll.Model(theta0="1/10", mu_floor="0.3", mu_contact="0.3")
    assert m.laws == {"floor": "coulomb", "contact": "coulomb", "mu_floor": "0.3",
                      "mu_contact": "0.3"}
    # a held cylinder keeps its floor
    assert cylroll.Model(floor="fixed", mu="0.3").laws["mu_floor"] == "none"
    # the first event is where rolling first needs mu: the ideal rolling model's
    # |F21|/N12 is 0.3 exactly there
    ev = m.separation(digits=20).events[0]
    assert ev.kind == "slip_onset" and ev.contact == "contact"
    need = cylroll.Model(theta0="1/10").forces(ev.theta.text, digits=25)["mu_contact"]
    assert abs(need.decimal() - Decimal("0.3")) < Decimal("1e-18")
    with pytest.raises(TypeError):
        cylroll.Model(mu="0.3", mu_floor="0.2")


def test_print_of_the_default_separation():
    text = str(cylroll.Model().separation())
    assert text.startswith("Separation (30 digits requested")
    assert re.search(r"theta_s +=  ?1\.04719755119659774615421446109 ", text), text


def test_at_separation_the_contact_friction_is_only_bounded_below():
    # identical solid cylinders from the top separate at theta = pi/3 exactly:
    # N12 = 0 there to within an absolute bound, |F21|/N12 has no finite value
    f = cylroll.Model().forces("pi/3", digits=12)
    n12 = f["N12"]
    assert n12.text == "0" and n12.digits == 0 and 0 < n12.err < 1e-12
    mu = f["mu_contact"]
    assert mu.is_lower_bound and mu.lower_bound > 1e12
    with pytest.raises(ValueError, match="lower bound"):
        float(mu)
    assert "a lower bound" in repr(f)
    # an ordinary value is not
    assert not f["N1"].is_lower_bound and f["N1"].lower_bound is None
    assert abs(float(f["N1"]) - 7 / 6) < 1e-11


def test_enclosures_contain_the_closed_forms_and_the_verified_values():
    # theta_s = pi/3 for identical solid cylinders from the top: proved
    # (and the branch point theta_indeterminate: from the top t* is infinite)
    th, star = cylroll.Model().enclose("separation", digits=40)
    assert th.name == "theta_s" and th.digits == 40
    assert star.name == "theta_indeterminate" and star.interval()[1] < th.interval()[0]
    with localcontext() as ctx:
        ctx.prec = 80
        assert pi(80) / 3 in th
    # fixed lower cylinder: cos theta_s = 2/(3 + k2)
    (th,) = cylroll.Model(floor="fixed", k2="2/5").enclose("separation", digits=30)
    lo, hi = th.interval()
    with localcontext() as ctx:
        ctx.prec = 60
        # cos decreases on [0, pi]: theta_s in [lo, hi] <=> cos(hi) <= 10/17 <= cos(lo)
        assert cos(hi, 60) <= Decimal(10) / 17 <= cos(lo, 60)
    # t and the forces at an angle contain the values verified at more digits
    m = cylroll.Model(theta0="1/10")
    (t,) = m.enclose("time", theta="9/10", digits=25)
    assert t.digits == 25 and m.time("9/10", digits=50).text in t
    f = m.forces("1/2", digits=50)
    for e in m.enclose("forces", theta="1/2", digits=25):
        assert f[e.name].text in e, e.name
    with pytest.raises(cylroll.InvalidParameterError):
        m.enclose("time")


def test_where_sticking_ends_is_enclosed_with_friction():
    # from rest both contacts stick until |F21|/N12 of the rolling model reaches mu:
    # the enclosures contain the verified event at more digits, and the rolling
    # model needs exactly mu = 3/10 there
    fm = cylroll.Model(theta0="1/10", mu_floor="0.3", mu_contact="0.3")
    th, t = fm.enclose("separation", digits=25)
    assert (th.name, t.name) == ("theta_slip_onset", "t_slip_onset")
    assert th.digits == 25 and t.digits == 25
    ev = fm.separation(digits=40).events[0]
    assert ev.kind == "slip_onset" and ev.contact == "contact"
    assert ev.theta.text in th and ev.t.text in t
    need = cylroll.Model(theta0="1/10").forces(th.text, digits=30)["mu_contact"].decimal()
    assert abs(need - Decimal("0.3")) < Decimal("1e-22")
    # the phases after it are integrated, verified only: refused, not approximated
    with pytest.raises(cylroll.InvalidParameterError, match="^invalid what = \"time with friction\""):
        fm.enclose("time", theta="1/2")
    # a start that slips at once has nothing enclosed, and says so
    with pytest.raises(cylroll.NotPhysicalError, match="nothing is enclosed"):
        cylroll.Model(theta0="1/10", mu_contact="0.001").enclose("separation")


def test_the_branch_point_is_enclosed():
    """θ* of the main case from θ0 = 1/10 (0.96571317498136093557878…, an
    independent Newton–Euler derivation: tests/fixtures/branch_independent.toml)
    lies inside its proved enclosure, which comes before θs's."""
    enc = {e.name: e for e in cylroll.Model(theta0="1/10").enclose("separation", digits=30)}
    star = enc["theta_indeterminate"]
    assert Decimal("0.9657131749813609355787809944794260198402") in star
    assert star.digits == 30 and "t_indeterminate" in enc
    lo_s, _ = enc["theta_s"].interval()
    _, hi_star = star.interval()
    assert hi_star < lo_s


def test_a_table_by_column_is_the_table_by_row():
    # the table crosses by column and its rows' Values are made on first
    # use: every access gives the same digits and bounds
    m = cylroll.Model(theta0="1/10", mu="0.3")
    tr = m.trajectory(t_end="5", steps=50, digits=25)
    assert len(tr) == 51 == len(tr.rows) == len(tr.modes)
    arr = tr.to_numpy()
    for j, c in enumerate(tr.columns):
        vals = tr.values(c)
        assert [r[j] for r in tr.rows] == vals
        assert np.array_equal(arr[:, j], tr.column(c))
        assert np.array_equal(tr.errors(c), [v.err for v in vals])
        for v in vals:
            # the float bound is rounded up, as its text: both are bounds
            assert (v.err == 0) == (v.err_text == "0")
            assert v.err <= float(v.err_text)
    lines = tr.to_csv().splitlines()
    assert lines[0] == ",".join(tr.columns + ["mode"])
    assert lines[7] == ",".join([v.text for v in tr.rows[6]] + [tr.modes[6]])


def test_a_lower_bound_has_no_finite_error_bound():
    # the friction a contact needs at θs, |F21|/N12 with N12 = 0 within its
    # bound, is a lower bound: its error bound is infinite, printed so
    m = cylroll.Model(theta0="1/10")
    ths = m.separation(digits=20).theta_s.text
    v = m.forces(ths, digits=20)["mu_contact"]
    assert v.text.startswith(">=") and v.err == float("inf") and v.err_text == "inf"
    # the float lower bound is still below the decimal X; to_dict says why it
    # cannot give this value, texts() can
    assert Fraction(v.lower_bound) <= Fraction(v.text[2:])
    f = m.forces(ths, digits=20)
    with pytest.raises(ValueError, match="only the lower bound"):
        f.to_dict()
    assert f.texts()["mu_contact"] == v.text


def test_narrow_floats_are_the_decimals_they_print_as():
    # a float32 0.3 is 3/10, as check() and a CSV file read it (it was
    # its float64 value 0.30000001192092896: another angle, another time)
    np = pytest.importorskip("numpy")
    m = cylroll.Model(theta0="0.1")
    assert m.time(np.float32(0.3), digits=12).text == m.time("0.3", digits=12).text
    assert m.time(np.float16(0.25), digits=12).text == m.time("0.25", digits=12).text
    tr = m.trajectory(np.array([0.1, 0.7], np.float32), digits=10)
    assert tr.values("t")[0].text == "0.1" and tr.values("t")[1].text == "0.7"
    grid = m.trajectory(t_end=np.float32(0.3), steps=3, digits=10)
    assert [v.text for v in grid.values("t")] == ["0", "0.1", "0.2", "0.3"]


def test_time_and_forces_carry_the_notes_of_the_command_line():
    m = cylroll.Model(theta0="0.1")
    # past θs within the digits asked: answered at θs, and said so
    v = m.time("1.0507720620185106481", digits=20)
    assert any("past theta_s by less than the digits asked" in n for n in v.notes)
    f = m.forces("0.98", digits=10)
    assert any("branch point" in n for n in f.notes)
    assert "note: " in str(f)
    assert m.time("0.5", digits=10).notes == []


def test_theta_s_is_none_where_the_model_ends_before_parting():
    s = cylroll.Model(theta0="0.0001", r1="1e-5").separation(digits=8)
    assert s.theta_s is None and s.t_s is None
    assert s.end is not None and "floor" in s.end


def test_to_csv_of_chosen_columns_is_the_command_lines():
    # `--columns` prints those columns alone, in their order, with `mode`
    # only where asked (it was always added last)
    m = cylroll.Model(theta0="1/10")
    full = m.trajectory(["0", "1"], digits=5)
    for cols in (["theta", "t"], ["mode", "theta"], ["theta", "t", "mode"], [" theta ", " t"]):
        tr = m.trajectory(["0", "1"], digits=5, columns=cols)
        rows = [",".join(full.modes[i] if c.strip() == "mode" else full.values(c.strip())[i].text
                         for c in cols) for i in range(2)]
        cols = [c.strip() for c in cols]
        assert tr.to_csv() == "\n".join([",".join(cols)] + rows) + "\n", cols
    assert full.to_csv().splitlines()[0].endswith(",work,mode")


def test_a_scalar_for_times_names_times():
    with pytest.raises(TypeError, match="times: expected a sequence"):
        cylroll.Model(theta0="1/10").trajectory(0.5)
