"""The model: exact inputs, validation, from_toml, replace, golden cases."""
from decimal import Decimal
from fractions import Fraction

import pytest

import cylroll


def test_defaults_are_the_paper_main_case():
    m = cylroll.Model()
    assert m.params == {
        "floor": "roll", "contact": "roll", "mu_floor": "inf", "mu_contact": "inf",
        "m1": "1", "m2": "1", "r1": "1", "r2": "1",
        "k1": "0.5", "k2": "0.5", "g": "1", "theta0": "0", "thetadot0": "0", "omega0": "0",
    }
    assert m.laws == {"floor": "roll", "contact": "roll", "mu_floor": "inf", "mu_contact": "inf"}
    assert m.friction is None
    assert repr(m).startswith("Model(floor='roll', contact='roll', mu_floor='inf'")


@pytest.mark.parametrize("theta0", ["1/10", "0.1", Fraction(1, 10), Decimal("0.1"),
                                    Decimal("1E-1")])
def test_exact_inputs_are_equal(theta0):
    m = cylroll.Model(theta0=theta0)
    assert m.params["theta0"] == "0.1"
    assert m == cylroll.Model(theta0="1/10")
    assert hash(m) == hash(cylroll.Model(theta0="1/10"))


def test_int_and_pi_angles():
    assert cylroll.Model(m1=3).params["m1"] == "3"
    assert cylroll.Model(theta0="pi/6").params["theta0"] == "1/6*pi"
    assert cylroll.Model(theta0="pi/6") == cylroll.Model(theta0="0.5*pi/3")


def test_float_needs_opt_in_and_is_taken_exactly():
    with pytest.raises(TypeError, match="allow_float"):
        cylroll.Model(theta0=0.1)
    m = cylroll.Model(theta0=0.1, allow_float=True)
    # the binary value of 0.1, not 1/10
    assert m != cylroll.Model(theta0="0.1")
    assert Fraction(0.1) == Fraction(3602879701896397, 36028797018963968)
    assert m == cylroll.Model(theta0=Fraction(0.1))
    assert cylroll.Model(m1=2.5, allow_float=True) == cylroll.Model(m1="2.5")


def test_replace_and_immutability():
    m = cylroll.Model(theta0="1/10")
    m2 = m.replace(m2=2, mu_contact="0.3")
    assert m2.params["m2"] == "2" and m2.friction == {"mu_floor": "inf", "mu_contact": "0.3"}
    assert m.params["m2"] == "1"
    assert m2.replace(mu_contact=None).friction is None
    with pytest.raises(AttributeError):
        m.m1 = 3
    with pytest.raises(TypeError):
        m.replace(mass=3)


def test_replace_a_law_replaces_its_coefficient():
    c = cylroll.Model(theta0="1/20", mu="0.3")
    # a new floor law drops the floor's coefficient, not the contact's
    r = c.replace(floor="roll")
    assert r.laws == {"floor": "roll", "contact": "coulomb", "mu_floor": "inf", "mu_contact": "0.3"}
    assert r == cylroll.Model(theta0="1/20", mu_contact="0.3")
    # a frictionless floor under a Coulomb model is that, not a contradiction
    s = c.replace(floor="slip")
    assert s == cylroll.Model(theta0="1/20", floor="slip", mu_contact="0.3")
    assert c.replace(contact="roll") == cylroll.Model(theta0="1/20", mu_floor="0.3")
    # a coefficient given in the same call is kept: the contradiction is refused
    with pytest.raises(cylroll.InvalidParameterError, match="contradicts"):
        c.replace(floor="slip", mu_floor="0.2")
    assert c.replace(floor="roll", mu_floor="0.2").laws["mu_floor"] == "0.2"
    # mu in the same call sets both, the law's too; a held floor takes none
    assert c.replace(contact="roll", mu="0.4").laws["mu_contact"] == "0.4"
    assert c.replace(floor="fixed", mu="0.5") == cylroll.Model(theta0="1/20", floor="fixed",
                                                              mu="0.5")
    # the law's type is named, as by the constructor
    with pytest.raises(TypeError, match="floor: expected"):
        c.replace(floor=1)


def test_friction_forms():
    m = cylroll.Model(theta0="1/10", mu_floor=("1/2", "3/10"), mu_contact="0.5,0.3")
    assert m.friction == {"mu_floor": "0.5,0.3", "mu_contact": "0.5,0.3"}
    # inf is exactly roll, 0 exactly slip: the ideal models
    assert cylroll.Model(mu_floor="inf", mu_contact="inf").friction is None
    assert cylroll.Model(mu_contact=0) == cylroll.Model(contact="slip")
    assert cylroll.Model(mu_contact=float("inf")).friction is None


def test_from_toml(tmp_path):
    p = tmp_path / "case.toml"
    p.write_text('floor = "fixed"\nk2 = "2/5"\ntheta0 = "1/20"\nm1 = 2\n')
    m = cylroll.Model.from_toml(p)
    assert m == cylroll.Model(floor="fixed", k2="2/5", theta0="1/20", m1=2)
    p.write_text("m1 = 0.3\n")
    with pytest.raises(cylroll.InvalidParameterError, match="as a string"):
        cylroll.Model.from_toml(p)
    with pytest.raises(cylroll.InputFileError) as e:
        cylroll.Model.from_toml(tmp_path / "missing.toml")
    assert isinstance(e.value, OSError) and e.value.exit_code == 2


def test_tiny_decimals_are_passed_and_quoted_as_written():
    m = cylroll.Model(theta0=Decimal("1E-5000"), k1=Decimal("2.5E-70"))
    assert m.params["theta0"] == "1e-5000" and m.params["k1"] == "2.5e-70"
    with pytest.raises(cylroll.InvalidParameterError) as e:
        cylroll.Model(m1=Decimal("-1E-5000"))
    assert '"-1E-5000"' in str(e.value) and len(str(e.value)) < 200


def test_from_toml_reads_every_golden_case_file(tmp_path, golden_dir):
    cases = sorted((golden_dir / "cases").glob("*.toml"))
    assert len(cases) == len(cylroll.golden.names())
    # a case file is a parameter file: its description and steps are not model keys
    for path in cases:
        assert cylroll.Model.from_toml(path) == cylroll.golden.case(path.stem), path.name
    # other unknown keys are still refused, naming the key and the file
    p = tmp_path / "p.toml"
    p.write_text('description = "x"\nsteps = 3\nmu = "0.3"\n')
    with pytest.raises(cylroll.InvalidParameterError, match="unknown key") as e:
        cylroll.Model.from_toml(p)
    assert '"mu"' in str(e.value) and "p.toml" in str(e.value)
    # TOML's inf is the word inf (rolling); nan is refused as the text "nan" is
    p.write_text("mu_floor = inf\n")
    assert cylroll.Model.from_toml(p) == cylroll.Model(mu_floor="inf")
    p.write_text("mu_contact = nan\n")
    with pytest.raises(cylroll.InvalidParameterError, match='"nan"'):
        cylroll.Model.from_toml(p)


def test_golden_cases():
    names = cylroll.golden.names()
    assert "mujoco_main" in names and "main_mu_0_3" in names and names == sorted(names)
    m = cylroll.golden.case("mujoco_main")
    assert m == cylroll.Model(theta0="1/10")
    assert "MuJoCo" in cylroll.golden.description("mujoco_main")
    assert cylroll.golden.steps("mujoco_main") == 40
    assert 'theta0 = "1/10"' in cylroll.golden.toml("mujoco_main")
    assert cylroll.golden.case("main_mu_0_3").friction == {"mu_floor": "0.3",
                                                           "mu_contact": "0.3"}
    with pytest.raises(cylroll.InvalidParameterError, match="unknown case"):
        cylroll.golden.case("nope")


def test_golden_cases_match_the_repository(golden_dir):
    files = sorted(p.stem for p in (golden_dir / "cases").glob("*.toml"))
    assert cylroll.golden.names() == files
    for name in files:
        assert cylroll.golden.toml(name) == (golden_dir / "cases" / f"{name}.toml").read_text()


def test_pickle_roundtrip():
    import pickle
    m = cylroll.Model(theta0="1/10", mu_contact="0.3")
    assert pickle.loads(pickle.dumps(m)) == m


def test_from_toml_names_the_file_for_a_value_out_of_range(tmp_path):
    # as the command line's --params names it: m1 (in FILE)
    f = tmp_path / "q.toml"
    f.write_text('m1 = "-1"\n')
    with pytest.raises(cylroll.InvalidParameterError) as e:
        cylroll.Model.from_toml(f)
    assert str(e.value) == f'invalid m1 (in {f}) = "-1": must be > 0'
