"""cylroll.check and cylroll.testing.assert_matches_oracle."""
import csv

import numpy as np
import pytest

import cylroll
from cylroll.testing import assert_matches_oracle


def _golden_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    head = rows[0]
    return {c: [r[i] for r in rows[1:]] for i, c in enumerate(head)}


@pytest.mark.parametrize("name", ["mujoco_main", "fixed_slip", "bobbin", "main_mu_0_3",
                                  "main_static_kinetic"])
def test_the_golden_csv_passes(golden_dir, name):
    rep = assert_matches_oracle(golden_dir / "data" / f"{name}.csv", case=name,
                                rtol=1e-15, atol=1e-18)
    assert rep.passed and rep.first_failure is None and rep.rows == 41
    assert rep.case == name
    assert "PASS" in str(rep)


def test_a_perturbed_candidate_fails(golden_dir):
    cols = _golden_columns(golden_dir / "data" / "mujoco_main.csv")
    cand = {c: np.array([float(x) for x in v]) for c, v in cols.items() if c != "mode"}
    cand["theta_dot"][17] *= 1 + 1e-5
    with pytest.raises(AssertionError) as e:
        assert_matches_oracle(cand, case="mujoco_main", rtol=1e-8, atol=1e-10)
    msg = str(e.value)
    assert "FAIL: first at row 18" in msg and "column theta_dot" in msg
    rep = cylroll.check(cand, "mujoco_main", rtol=1e-8, atol=1e-10)
    assert not rep.passed
    assert rep.first_failure.row == 18 and rep.first_failure.column == "theta_dot"
    assert rep.first_failure.t == cols["t"][17]
    st = rep.column("theta_dot")
    assert st.failures == 1 and st.max_abs_t == cols["t"][17]
    assert st.max_rel == pytest.approx(1e-5, rel=1e-3)
    assert rep.column("theta").failures == 0 and rep.column("theta").max_abs < 1e-15
    # the float64 columns of the oracle itself pass at a float's accuracy
    del cand["theta_dot"]
    assert cylroll.check(cand, "mujoco_main", rtol=1e-15, atol=1e-16).passed


def test_candidate_forms(golden_dir, tmp_path):
    m = cylroll.Model(theta0="1/10")
    traj = m.trajectory(t_end=5, steps=10, digits=20)
    d = {"t": traj["t"], "theta": traj["theta"], "N12": traj["N12"]}
    assert cylroll.check(d, m, rtol=1e-14).passed
    assert cylroll.check(d, "mujoco_main", rtol=1e-14).passed   # the same model by name
    p = tmp_path / "cand.csv"
    traj.to_csv(str(p))
    assert cylroll.check(p, m, rtol=1e-18, atol=0).passed
    assert cylroll.check(str(p), m, rtol=1e-18, atol=0).passed
    pd = pytest.importorskip("pandas")
    df = pd.DataFrame(d)
    df.loc[3, "theta"] += 1e-3
    rep = cylroll.check(df, m, rtol=1e-6)
    assert not rep.passed and rep.first_failure.row == 4


def test_malformed_candidates():
    with pytest.raises(cylroll.InvalidParameterError, match="unknown column"):
        cylroll.check({"t": [0.0], "velocity": [1.0]}, "mujoco_main")
    with pytest.raises(cylroll.InvalidParameterError, match="column named t"):
        cylroll.check({"theta": [0.1]}, "mujoco_main")
    with pytest.raises(cylroll.InvalidParameterError, match="unknown case"):
        cylroll.check({"t": [0.0]}, "nope")
    with pytest.raises(cylroll.InvalidParameterError, match="rtol"):
        cylroll.check({"t": [0.0], "theta": [0.1]}, "mujoco_main", rtol=-1)
    with pytest.raises(ValueError, match="different lengths"):
        cylroll.check({"t": [0.0, 1.0], "theta": [0.1]}, "mujoco_main")
    with pytest.raises(TypeError):
        cylroll.check(42, "mujoco_main")


def test_the_mode_column_is_compared(golden_dir):
    # a golden CSV carries a mode column: compared with the oracle's phase of each row
    rep = cylroll.check(golden_dir / "data" / "main_mu_1.csv", "main_mu_1", rtol=1e-15)
    assert rep.passed
    assert [c.name for c in rep.columns][-4:] == ["s1", "s12", "work", "mode"]
    # a candidate that says flight while the contacts stick fails, at that row
    cols = _golden_columns(golden_dir / "data" / "main_mu_1.csv")
    cand = {"t": np.array([float(x) for x in cols["t"]]), "mode": list(cols["mode"])}
    cand["mode"][2] = "flight"
    rep = cylroll.check(cand, "main_mu_1")
    assert not rep.passed and rep.first_failure.row == 3
    assert rep.first_failure.column == "mode" and rep.first_failure.oracle == "stick/stick"
