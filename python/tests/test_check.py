"""cylroll.check and cylroll.testing.assert_conforms: the command line's scoring
core (per column, per phase, per event, per branch) from Python."""
import csv
import json
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import cylroll
from cylroll.testing import assert_conforms, assert_matches_oracle


def _golden_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    head = rows[0]
    return {c: [r[i] for r in rows[1:]] for i, c in enumerate(head)}


@pytest.mark.parametrize("name", ["mujoco_main", "fixed_slip", "bobbin", "main_mu_0_3",
                                  "main_static_kinetic", "main_roll_roll", "main_mu_10"])
def test_the_golden_csv_passes(golden_dir, name):
    rep = assert_conforms(golden_dir / "data" / f"{name}.csv", name, rtol=1e-15, atol=1e-18)
    assert rep.passed and rep.verdict == "pass" and rep.first_failure is None
    assert rep.rows == 41 and rep.case == name
    assert [c.column for c in rep.columns][-1] == "mode"
    assert all(p.passed for p in rep.phases)
    assert all(e.passed is not False for e in rep.events)
    assert rep.branch.lawful and rep.branch.followed != "part"
    assert "PASS" in str(rep)


def test_a_perturbed_candidate_fails_at_its_column_row_and_phase(golden_dir):
    cols = _golden_columns(golden_dir / "data" / "mujoco_main.csv")
    cand = {c: np.array([float(x) for x in v]) for c, v in cols.items() if c != "mode"}
    cand["theta_dot"][17] *= 1 + 1e-5
    with pytest.raises(AssertionError) as e:
        assert_conforms(cand, "mujoco_main", rtol=1e-8, atol=1e-10)
    msg = str(e.value)
    assert "FAIL: first at row 18" in msg and "column theta_dot" in msg
    rep = cylroll.check(cand, "mujoco_main", rtol=1e-8, atol=1e-10)
    assert not rep.passed and rep.verdict == "fail"
    assert rep.first_failure.row == 18 and rep.first_failure.column == "theta_dot"
    assert rep.first_failure.t == cols["t"][17]
    st = rep.column("theta_dot")
    assert st.failures == 1 and st.max_abs_t == cols["t"][17]
    assert st.max_rel == pytest.approx(1e-5, rel=1e-3)
    assert st.worst_err_over_limit > 1 and st.worst_bound == "rtol"
    # its phase fails, the other passes
    assert [p.mode for p in rep.phases] == ["stick/stick", "flight"]
    assert [p.passed for p in rep.phases] == [False, True]
    assert st.phases[0].failures == 1 and st.phases[1].failures == 0
    assert rep.column("theta").failures == 0 and rep.column("theta").max_abs < 1e-15
    # the float64 columns of the oracle itself pass at a float's accuracy
    del cand["theta_dot"]
    assert cylroll.check(cand, "mujoco_main", rtol=1e-15, atol=1e-16).passed
    # the attribute names are the JSON's
    d = rep.to_dict()
    assert d["columns"][1]["column"] == "theta_dot" == rep.columns[1].column
    assert d["columns"][1]["worst_err_over_limit"] == rep.columns[1].worst_err_over_limit
    assert rep.columns[1].name == "theta_dot"          # the earlier name, an alias


def test_candidate_forms(tmp_path):
    m = cylroll.Model(theta0="1/10")
    traj = m.trajectory(t_end=5, steps=10, digits=20)
    d = {"t": traj["t"], "theta": traj["theta"], "N12": traj["N12"]}
    assert cylroll.check(d, m, rtol=1e-14).passed
    assert cylroll.check(d, "mujoco_main", rtol=1e-14).passed   # the same model by name
    p = tmp_path / "cand.csv"
    traj.to_csv(str(p))
    assert cylroll.check(p, m, rtol=1e-18, atol=1e-18).passed
    assert cylroll.check(str(p), m, rtol=1e-18, atol=1e-18).passed
    pd = pytest.importorskip("pandas")
    df = pd.DataFrame(d)
    df.loc[3, "theta"] += 1e-3
    rep = cylroll.check(df, m, rtol=1e-6)
    assert not rep.passed and rep.first_failure.row == 4


def test_per_column_tolerances():
    m = cylroll.Model(theta0="1/10")
    traj = m.trajectory([0, 1, 2], digits=20)
    d = {"t": traj["t"], "theta": traj["theta"] * (1 + 1e-6), "N12": traj["N12"]}
    assert not cylroll.check(d, m).passed
    rep = cylroll.check(d, m, tol={"theta": 1e-5})
    assert rep.passed
    assert rep.column("theta").rtol == 1e-5 and rep.column("theta").tol_set
    assert rep.column("N12").rtol == 1e-8 and not rep.column("N12").tol_set
    # an atol in the column's own units; the default is atol x its scale ((m1 + m2) g = 2)
    rep = cylroll.check(d, m, tol={"theta": (0, 1e-5)})
    assert rep.passed and rep.column("theta").atol == 1e-5
    assert rep.column("N12").atol == pytest.approx(2e-10)
    with pytest.raises(cylroll.InvalidParameterError, match="does not have"):
        cylroll.check(d, m, tol={"x2": 1e-3})
    with pytest.raises(cylroll.InvalidParameterError, match="unknown column"):
        cylroll.check(d, m, tol={"omega": 1e-3})


def test_malformed_candidates_name_the_row():
    with pytest.raises(cylroll.InvalidParameterError, match="unknown column"):
        cylroll.check({"t": [0.0], "velocity": [1.0]}, "mujoco_main")
    with pytest.raises(cylroll.InvalidParameterError, match="column named t"):
        cylroll.check({"theta": [0.1]}, "mujoco_main")
    with pytest.raises(cylroll.InvalidParameterError, match="unknown case"):
        cylroll.check({"t": [0.0]}, "nope")
    with pytest.raises(cylroll.InvalidParameterError, match="rtol"):
        cylroll.check({"t": [0.0], "theta": [0.1]}, "mujoco_main", rtol=-1)
    with pytest.raises(cylroll.InvalidParameterError, match="the same length"):
        cylroll.check({"t": [0.0, 1.0], "theta": [0.1]}, "mujoco_main")
    with pytest.raises(TypeError):
        cylroll.check(42, "mujoco_main")
    with pytest.raises(cylroll.InvalidParameterError, match=r"row 3: t = 0.5 is before"):
        cylroll.check({"t": [0.0, 1.0, 0.5], "theta": [0.1] * 3}, "mujoco_main")
    with pytest.raises(cylroll.InvalidParameterError, match=r"row 2, column theta.*not finite"):
        cylroll.check({"t": [0.0, 1.0], "theta": [0.1, np.nan]}, "mujoco_main")
    with pytest.raises(cylroll.InvalidParameterError, match="past_end"):
        cylroll.check({"t": [0.0], "theta": [0.1]}, "mujoco_main", past_end="drop")


def test_a_file_is_named_in_its_refusals(tmp_path):
    # a file's refusal names the data row and its line (a blank line counts
    # in the line, not in the rows); arrays name the row alone (above)
    p = tmp_path / "engine.csv"
    p.write_text("t,theta\n0,0.1\n\n1,x\n")
    with pytest.raises(cylroll.InvalidParameterError) as e:
        cylroll.check(p, "mujoco_main")
    assert "engine.csv" in str(e.value) and "row 2 (line 4), column theta" in str(e.value)


def test_the_mode_column_is_compared(golden_dir):
    # a golden CSV carries a mode column: compared with the oracle's phase of each row
    rep = cylroll.check(golden_dir / "data" / "main_mu_1.csv", "main_mu_1", rtol=1e-15)
    assert rep.passed
    assert [c.column for c in rep.columns][-4:] == ["s1", "s12", "work", "mode"]
    assert rep.events_judged
    # a candidate that says flight while the contacts stick fails, at that row
    cols = _golden_columns(golden_dir / "data" / "main_mu_1.csv")
    cand = {"t": np.array([float(x) for x in cols["t"]]), "mode": list(cols["mode"])}
    cand["mode"][2] = "flight"
    rep = cylroll.check(cand, "main_mu_1")
    assert not rep.passed and rep.first_failure.row == 3
    assert rep.first_failure.column == "mode" and rep.first_failure.oracle == "stick/stick"
    assert rep.column("mode").failures == 1
    # and its changes of mode are events the reference does not have
    spurious = [e for e in rep.events if e.kind == "spurious"]
    assert [e.mode for e in spurious] == ["flight", "stick/stick"]
    assert all(e.passed is False for e in spurious)


def test_the_slip_onset_is_judged_as_an_event(golden_dir):
    rep = cylroll.check(golden_dir / "data" / "main_mu_0_3.csv", "main_mu_0_3")
    ev = rep.event("slip_onset", "contact")
    assert ev.passed and ev.error == 0.0 and ev.mode == "stick/slip+"
    assert ev.reference["theta"].startswith("0.58421602")
    assert ev.candidate["rows"] == [29, 30]


def test_a_candidate_that_parts_at_the_branch_point_is_judged_on_the_part_branch():
    m = cylroll.golden.case("main_roll_roll")
    star = m.separation(digits=20).theta_indeterminate
    times = [k / 64 for k in range(0, 64 * 7 + 1)]
    part = m.trajectory(times, digits=20, branch="part")
    cand = {"t": times, "theta": part["theta"], "y2": part["y2"], "mode": part.modes}
    rep = assert_conforms(cand, m, rtol=1e-12, atol=1e-14)
    assert rep.branch.requested == "auto" and rep.branch.followed == "part"
    assert rep.branch.window["theta_indeterminate"] == star.text
    assert "branch point" in rep.branch.why
    # judged against the closed branch instead, its flight fails
    rep = cylroll.check(cand, m, rtol=1e-12, atol=1e-14, branch="stay")
    assert not rep.passed and rep.phases[-1].mode == "flight" and not rep.phases[-1].passed


def test_rows_after_the_end_are_reported(golden_dir):
    cand = {"t": [0.0, 7.5, 8.0], "theta": [0.05, 1.0, 1.0]}
    rep = cylroll.check(cand, "main_roll_roll")
    assert rep.passed and rep.rows == 3 and rep.rows_after_end == 2
    assert rep.first_after_end == {"row": 2, "t": "7.5"}
    assert rep.end["event"] == "impact"
    assert "2 row(s) after the end of the model" in str(rep)
    with pytest.raises(cylroll.InvalidParameterError, match=r"row 2: t = 7.5 is after the end"):
        cylroll.check(cand, "main_roll_roll", past_end="refuse")


def test_an_rtol_finer_than_the_digits_is_refused_and_a_verdict_on_the_bound_is_open():
    cand = {"t": [0.0], "theta": [0.05]}
    with pytest.raises(cylroll.InvalidParameterError, match="20 significant digits"):
        cylroll.check(cand, "main_roll_roll", rtol=1e-19)
    assert cylroll.check(cand, "main_roll_roll", rtol=1e-25, digits=27).passed
    rep = cylroll.check(cand, "main_roll_roll", rtol=0, atol=0)
    assert not rep.passed and rep.verdict == "undecided"
    assert rep.first_failure is None and rep.first_undecided.row == 1
    with pytest.raises(AssertionError, match="did not verify"):
        assert_conforms(cand, "main_roll_roll", rtol=0, atol=0)


def test_tolerances_are_read_as_the_command_line_reads_them():
    cand = {"t": [0.0, 1.0], "theta": [0.1, 0.1]}
    m = cylroll.Model(theta0="1/10")
    # below 1e-300 is refused in every form, not read as 0 (binary64 would)
    for bad in ("1e-400", Decimal("1e-400"), Fraction(1, 10**400), -1, "abc", "inf"):
        with pytest.raises(cylroll.InvalidParameterError, match="^invalid rtol = "):
            cylroll.check(cand, m, rtol=bad)
    with pytest.raises(cylroll.InvalidParameterError, match="^invalid atol = "):
        cylroll.check(cand, m, atol=Decimal("-1e-9"))
    with pytest.raises(cylroll.InvalidParameterError, match="^invalid event_tol = "):
        cylroll.check(cand, m, event_tol="1e-999")
    with pytest.raises(cylroll.InvalidParameterError, match=r"^invalid tol\['theta'\] = "):
        cylroll.check(cand, m, tol={"theta": (1e-3, "1e-400")})
    for bad in (None, [1e-3], True):
        with pytest.raises(TypeError, match="rtol: expected a number"):
            cylroll.check(cand, m, rtol=bad)
    # the forms a number comes in are the same tolerance
    reps = [cylroll.check(cand, m, rtol=r, atol=0)
            for r in (1e-3, "1e-3", Decimal("0.001"), Fraction(1, 1000), np.float64(1e-3))]
    assert {r.column("theta").rtol for r in reps} == {1e-3}
    # max_rows: the command line's --max-rows, by its keyword
    with pytest.raises(cylroll.InvalidParameterError, match="raise max_rows"):
        cylroll.check(cand, m, max_rows=1)
    with pytest.raises(cylroll.InvalidParameterError, match="max_rows"):
        cylroll.check(cand, m, max_rows=0)
    assert cylroll.check(cand, m, max_rows=2, rtol=1, atol=1).passed


def test_the_earlier_helper_is_the_same_check(golden_dir):
    rep = assert_matches_oracle(golden_dir / "data" / "main_mu_0_3.csv", case="main_mu_0_3",
                                rtol=1e-12, atol=1e-14)
    assert rep.passed
    assert json.loads(json.dumps(rep.to_dict()))["case"] == "main_mu_0_3"


def test_exact_cells_are_judged_as_they_are():
    """Decimal, Fraction and longdouble cells went through float64: an exact
    25-digit candidate failed at rtol 1e-20, a Fraction time was judged at
    0.3333333333333333. Now a Decimal is its own text, a Fraction with a
    terminating decimal its exact decimal, any other Fraction refused."""
    import numpy as np
    from decimal import Decimal
    from fractions import Fraction

    m = cylroll.golden.case("mujoco_main")
    t = ["0", "0.5", "1"]
    th = [v.decimal() for v in m.trajectory(t, digits=30).values("theta")]
    assert all(isinstance(x, Decimal) for x in th)
    rep = cylroll.check({"t": t, "theta": th}, "mujoco_main", rtol=1e-20, atol=0, digits=25)
    assert rep.verdict == "pass", str(rep)
    ft = [Fraction(0), Fraction(1, 2), Fraction(1)]
    rep = cylroll.check({"t": ft, "theta": th}, "mujoco_main", rtol=1e-20, atol=0, digits=25)
    assert rep.verdict == "pass", str(rep)
    # as floats the same values fail there (what the cells were before)
    fl = [float(x) for x in th]
    assert cylroll.check({"t": t, "theta": fl}, "mujoco_main", rtol=1e-20, atol=0,
                         digits=25).verdict == "fail"
    with pytest.raises(ValueError, match="1/3 has no exact decimal"):
        cylroll.check({"t": [Fraction(1, 3)], "theta": ["0.1"]}, "mujoco_main")
    # a longdouble keeps its own digits (its shortest round-trip decimal)
    from cylroll._check import _cell
    assert _cell("theta", np.longdouble("0.1")) in ("1e-01", "0.1")


def test_an_unreadable_candidate_is_an_input_file_error(tmp_path):
    """A candidate path that cannot be read raised InvalidParameterError (a
    ValueError), so ``except OSError`` missed it; it is the documented
    InputFileError, as a parameter file's."""
    for bad in (tmp_path / "nonexistent.csv", tmp_path):
        with pytest.raises(cylroll.InputFileError, match="cannot be read") as e:
            cylroll.check(str(bad), "main_roll_roll")
        assert isinstance(e.value, OSError) and e.value.exit_code == 2


def test_cells_are_read_as_they_print_and_refused_by_row():
    m = cylroll.Model(theta0="1/10")
    tr = m.trajectory(["0", "0.1", "0.5"], digits=20)
    # float32 times and values: the decimals they print as, as a CSV file
    # written from them carries them (not their float64 widening)
    d32 = {"t": np.array([0, 0.1, 0.5], dtype=np.float32),
           "theta": tr["theta"].astype(np.float32)}
    csv_text = "t,theta\n" + "\n".join(f"{t!s},{x!s}" for t, x in zip(d32["t"], d32["theta"])) + "\n"
    a = cylroll.check(d32, m, rtol=1e-6, atol=0)
    import tempfile, os
    with tempfile.TemporaryDirectory() as tmp:
        p = os.path.join(tmp, "c.csv")
        with open(p, "w") as f:
            f.write(csv_text)
        b = cylroll.check(p, m, rtol=1e-6, atol=0)
    assert a.passed and b.passed
    assert a.column("theta").max_abs == b.column("theta").max_abs
    # a cell that is not a real number is refused naming its row and column
    for bad in (None, 1 + 2j, Fraction(1, 3), [1.0]):
        with pytest.raises(cylroll.InvalidParameterError, match=r"row 2, column theta"):
            cylroll.check({"t": [0, 0.1], "theta": np.array([0.1, bad], dtype=object)}, m)
    with pytest.raises(cylroll.InvalidParameterError, match="comma"):
        cylroll.check({"t": ["0", "0.1"], "theta": ["0.1", "0.1,2"]}, m)
    with pytest.raises(cylroll.InvalidParameterError, match="column name"):
        cylroll.check({"t": [0.0], "the,ta": [0.1]}, m)
    # part_at exactly, as the Model's methods take it; a wrong type named
    with pytest.raises(cylroll.InvalidParameterError, match="part_at"):
        cylroll.check({"t": [0.0], "theta": [0.1]}, m, part_at=Fraction(1, 10))
    with pytest.raises(TypeError, match="part_at"):
        cylroll.check({"t": [0.0], "theta": [0.1]}, m, part_at=[1])
    # the report speaks Python
    assert "--" not in cylroll.check({"t": [0.0], "theta": [0.1]}, m).text
    with pytest.raises(TypeError, match="name: expected a golden case name"):
        cylroll.golden.case(3)


def test_a_schema_1_candidate_is_judged_with_schema_1(golden_dir):
    # the first golden schema's phi2 (the paper's gauge: r1 theta0 / r2 = 0.1
    # below) in its 13 columns: judged as schema 2 it fails on phi2 with a
    # note; schema=1 judges it (the command line's --schema 1)
    cols = _golden_columns(golden_dir / "data" / "mujoco_main.csv")
    v1 = "t,theta,theta_dot,theta_ddot,phi1,phi2,x1,x2,y2,F1,N1,F21,N12".split(",")
    cand = {c: np.array([float(x) for x in cols[c]]) for c in v1}
    cand["phi2"] = cand["phi2"] - 0.1
    rep = cylroll.check(cand, "mujoco_main", rtol=1e-12, atol=1e-14)
    assert not rep.passed and rep.first_failure.column == "phi2"
    assert any("--schema 1" in n for n in rep.notes)
    rep = cylroll.check(cand, "mujoco_main", rtol=1e-12, atol=1e-14, schema=1)
    assert rep.passed, str(rep)
    with pytest.raises(cylroll.InvalidParameterError, match="schema"):
        cylroll.check(cand, "mujoco_main", schema=3)
