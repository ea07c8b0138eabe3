//! The oracle against an independent derivation: `tests/fixtures/independent.py`
//! derives the motion with sympy (its own Lagrangian and its own per-body KKT
//! system) and evaluates it with mpmath at 80 digits, sharing no code with
//! cylroll. Its output, `independent.toml`, covers 5 parameter sets × 6 contact
//! models; every value must agree to the digits compared here.

use cylroll::exact::Exact;
use cylroll::model::input::{model_from_pairs, Pairs};
use cylroll::numeric::decimal::to_sig;
use cylroll::oracle::{self, Options, Oracle, FORCE_KEYS};

/// `reference` (a longer decimal string) rounded to `digits` significant digits.
fn round(reference: &str, digits: u32) -> String {
    if reference == "0" {
        return "0".into();
    }
    let x = Exact::parse("ref", reference, false).unwrap().to_float(400);
    to_sig(&x, digits)
}

#[test]
fn agrees_with_the_independent_sympy_mpmath_derivation() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/fixtures/independent.toml"
    ))
    .unwrap();
    let doc: toml::Table = text.parse().unwrap();
    let cases = doc["case"].as_array().unwrap();
    assert_eq!(cases.len(), 30);
    for c in cases {
        let c = c.as_table().unwrap();
        let name = c["name"].as_str().unwrap();
        let mut pairs = Pairs::new();
        for (k, v) in c["params"].as_table().unwrap() {
            pairs.insert(k.clone(), v.as_str().unwrap().to_string());
        }
        pairs.insert("floor".into(), c["floor"].as_str().unwrap().into());
        pairs.insert("contact".into(), c["contact"].as_str().unwrap().into());
        // the limit θ0 → 0+
        let m = model_from_pairs(&pairs).unwrap().ideal().unwrap();
        let s = Oracle::new(&m, 45).unwrap().separation().unwrap();
        assert_eq!(
            s.theta_s.text,
            round(c["theta_s_limit"].as_str().unwrap(), 45),
            "{name} theta_s limit"
        );
        // from rest at θ0 = 1/10
        pairs.insert("theta0".into(), "1/10".into());
        let model = model_from_pairs(&pairs).unwrap();
        let m = model.ideal().unwrap();
        let mut o = Oracle::new(&m, 36).unwrap();
        let s = o.separation().unwrap();
        assert_eq!(
            s.theta_s.text,
            round(c["theta_s_0p1"].as_str().unwrap(), 36),
            "{name} theta_s"
        );
        assert_eq!(
            s.t_s.unwrap().text,
            round(c["t_s_0p1"].as_str().unwrap(), 36),
            "{name} t_s"
        );
        let half_angle = Exact::parse("theta", "1/2", false).unwrap();
        let f = o.forces_at(&half_angle).unwrap();
        let half = c["at_half"].as_table().unwrap();
        for (i, key) in FORCE_KEYS.iter().enumerate().take(6) {
            let r = half[*key].as_str().unwrap();
            assert_eq!(f[i].text, round(r, 36), "{name} {key} at theta = 1/2");
        }
        // the answers every law shares (the hybrid motion to its end, the
        // forces where θ first reaches 1/2) give the same digits
        let opts = Options::digits(36);
        let a = oracle::separation(&model, &opts).unwrap();
        for key in ["theta_s", "t_s"] {
            assert_eq!(
                a.value(key).unwrap().text,
                round(c[&format!("{key}_0p1")].as_str().unwrap(), 36),
                "{name} {key} of the motion"
            );
        }
        let fa = oracle::forces(&model, &half_angle, &opts).unwrap();
        for key in FORCE_KEYS.iter().take(6) {
            let r = half[*key].as_str().unwrap();
            assert_eq!(
                fa.value(key).unwrap().text,
                round(r, 36),
                "{name} {key} of the motion at theta = 1/2"
            );
        }
    }
}
