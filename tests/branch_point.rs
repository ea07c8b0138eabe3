//! The branch point and both branches, case by case, against an independent
//! derivation: `tests/fixtures/branch_independent.toml` (Newton–Euler of each
//! body per contact mode, Gragg–Bulirsch–Stoer in time in mpmath, its own
//! event and mode logic; 40 digits confirmed at two precisions; see
//! `tests/fixtures/branch_derivation.md`). Every golden case and four more
//! (unequal cylinders on a frictionless floor, a sliding floor under a
//! rolling or μ = 10 contact, μ = 1000) are held to it:
//!
//! - on the default `stay` branch: θ*, t* (or none where the motion is
//!   unique), θ̇, N12 and F21 there, the continuations consistent there, the
//!   end of the closed branch θs, t_s and its first impact;
//! - on the `part` branch: the cylinders part at θ*, t*, and the first impact
//!   (surface, time, both bodies' positions and velocities just before it);
//! - a closed-branch state before θ* (every coordinate, rate and force);
//! - `--part-at` inside the window parts there; outside it is refused.
//!
//! Each value must agree with the fixture to every digit cylroll prints
//! (half a unit of the last printed digit plus its error bound).

use cylroll::exact::Exact;
use cylroll::model::input::model_from_pairs;
use cylroll::model::Model;
use cylroll::motion::{Branch, Kind};
use cylroll::numeric::verify::Verified;
use cylroll::oracle::{self, Answer, Options};
use rug::ops::Pow;
use rug::Float;
use std::collections::BTreeMap;

const FIXTURE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/fixtures/branch_independent.toml"
);
const DIGITS: u32 = 30;
const P: u32 = 256;

fn fixture() -> toml::Table {
    toml::from_str(&std::fs::read_to_string(FIXTURE).unwrap()).unwrap()
}

fn model_of(text: &str) -> Model {
    let pairs: BTreeMap<String, String> = text
        .split(", ")
        .filter_map(|kv| kv.split_once(" = "))
        .map(|(k, v)| (k.trim().to_string(), v.trim().to_string()))
        .collect();
    model_from_pairs(&pairs).unwrap_or_else(|e| panic!("{text}: {e}"))
}

/// `v` agrees with the decimal `want` to every digit it prints.
fn agrees(case: &str, what: &str, v: &Verified, want: &str) {
    let w = Float::with_val(P, Float::parse(want).unwrap());
    let diff = Float::with_val(P, &v.value - &w).abs();
    // half a unit of the last printed digit, plus the bound
    let mag = Float::with_val(P, v.value.abs_ref());
    let exp = if mag.is_zero() {
        0
    } else {
        mag.log10().floor().to_f64() as i32
    };
    let half_ulp =
        Float::with_val(P, Float::i_pow_u(10, 1)).pow(exp - v.digits.max(1) as i32 + 1) / 2u32;
    let lim = half_ulp + Float::with_val(P, &v.err_bound);
    assert!(
        diff <= lim,
        "[{case}] {what}: cylroll {} ({} digits, err {}) vs independent {want}: differ by {:.3e}",
        v.text,
        v.digits,
        v.err_text(),
        diff.to_f64()
    );
    assert!(
        v.digits >= 20 || v.text == "0",
        "[{case}] {what}: only {} digits",
        v.digits
    );
}

fn value<'a>(a: &'a Answer, name: &str, case: &str) -> &'a Verified {
    a.value(name)
        .unwrap_or_else(|| panic!("[{case}] no {name} in {:?}", a.notes))
}

fn sep(m: &Model, branch: Branch) -> cylroll::error::Result<Answer> {
    oracle::separation(
        m,
        &Options {
            branch,
            ..Options::digits(DIGITS)
        },
    )
}

fn s<'a>(t: &'a toml::Table, key: &str) -> &'a str {
    t.get(key)
        .and_then(|v| v.as_str())
        .unwrap_or_else(|| panic!("no {key}"))
}

/// The fixture's mode text "floor=stick,contact=slip+" as cylroll's tag.
fn tag(mode: &str) -> String {
    fn st(x: &str) -> &str {
        match x {
            "free" => "slip",
            "fixed" => "held",
            o => o,
        }
    }
    let mut parts = mode.split(',').map(|kv| kv.split_once('=').unwrap().1);
    let f = st(parts.next().unwrap());
    let c = st(parts.next().unwrap());
    format!("{f}/{c}")
}

/// The continuations the fixture records as consistent at t*: `part`, and
/// `slide_<contact>_<slide±>` from the mode there.
fn alternatives_at_star(t: &toml::Table, t_star: &str) -> Vec<String> {
    let star = Float::with_val(P, Float::parse(t_star).unwrap());
    let mut out = Vec::new();
    for a in t["alternatives"].as_array().unwrap() {
        let a = a.as_table().unwrap();
        let at = Float::with_val(P, Float::parse(s(a, "t")).unwrap());
        if Float::with_val(P, &at - &star).abs() > 1e-15 {
            continue;
        }
        let kind = s(a, "kind");
        if kind == "part" {
            out.push("part".to_string());
        } else if let Some(rest) = kind.strip_prefix("slide_") {
            let (which, how) = rest.split_once('_').unwrap();
            let sign = how.strip_prefix("slide").unwrap();
            let mode = tag(s(a, "in_mode"));
            let (f, c) = mode.split_once('/').unwrap();
            let new = if which == "floor" {
                format!("slip{sign}/{c}")
            } else {
                format!("{f}/slip{sign}")
            };
            out.push(new);
        }
    }
    out.sort();
    out
}

#[test]
fn every_case_has_the_branch_point_and_both_branches_of_the_independent_derivation() {
    let all = fixture();
    let mut checked = 0;
    let mut with_star = 0;
    for (name, t) in &all {
        let Some(t) = t.as_table() else { continue };
        if name == "polynomials" {
            continue;
        }
        let m = model_of(s(t, "model"));
        let stay = sep(&m, Branch::Stay).unwrap_or_else(|e| panic!("[{name}] {e}"));
        let star = s(t, "theta_star");
        // the end of the closed branch and its impact
        agrees(
            name,
            "theta_s",
            value(&stay, "theta_s", name),
            s(t, "theta_s"),
        );
        agrees(name, "t_s", value(&stay, "t_s", name), s(t, "t_s"));
        if let Some(ti) = t.get("closed_end_t_impact").and_then(|v| v.as_str()) {
            agrees(name, "t_impact", value(&stay, "t_impact", name), ti);
        }
        checked += 1;
        if star == "none" {
            assert!(
                stay.value("theta_indeterminate").is_none()
                    && stay.event(Kind::Indeterminate).is_none(),
                "[{name}] a branch point where the motion is unique: {:?}",
                stay.notes
            );
            continue;
        }
        with_star += 1;
        for (key, want) in [
            ("theta_indeterminate", "theta_star"),
            ("t_indeterminate", "t_star"),
            ("theta_dot_indeterminate", "theta_dot_star"),
            ("N12_indeterminate", "N12_star"),
            ("F21_indeterminate", "F21_star"),
        ] {
            agrees(name, key, value(&stay, key, name), s(t, want));
        }
        let ev = stay.event(Kind::Indeterminate).unwrap();
        agrees(name, "event theta", &ev.theta, star);
        assert_eq!(
            ev.phase.and_then(|p| p.mode()).map(|m| m.tag()),
            Some(tag(s(t, "branch_mode"))),
            "[{name}] the mode at the branch point"
        );
        let mut also = ev.also.clone();
        also.sort();
        assert_eq!(
            also,
            alternatives_at_star(t, s(t, "t_star")),
            "[{name}] the continuations consistent at the branch point"
        );
        // the part branch: parting at θ*, the flight, the first impact
        let part = sep(&m, Branch::Part).unwrap_or_else(|e| panic!("[{name}] part: {e}"));
        agrees(name, "part theta_s", value(&part, "theta_s", name), star);
        agrees(name, "part t_s", value(&part, "t_s", name), s(t, "t_star"));
        for (key, want) in [
            ("t_impact", "part_t_impact"),
            ("x1_impact", "part_x1"),
            ("x1_dot_impact", "part_x1_dot"),
            ("phi1_dot_impact", "part_phi1_dot"),
            ("x2_impact", "part_x2"),
            ("y2_impact", "part_y2"),
            ("x2_dot_impact", "part_x2_dot"),
            ("y2_dot_impact", "part_y2_dot"),
            ("psi2_dot_impact", "part_psi2_dot"),
        ] {
            agrees(name, key, value(&part, key, name), s(t, want));
        }
        let surface = s(t, "part_impact_surface");
        let end = part.end.map(|e| e.name()).unwrap_or_default();
        assert!(
            end.contains(if surface == "floor" {
                "floor"
            } else {
                "cylinder"
            }),
            "[{name}] part branch ends at {end}, the derivation on the {surface}"
        );
        // the closed branch before θ*: every coordinate, rate and force
        let pre_t = Exact::parse("t", s(t, "pre_t"), false).unwrap();
        let traj = oracle::trajectory(&m, &[pre_t], &Options::digits(DIGITS)).unwrap();
        let row = &traj.rows[0];
        let col = |c: &str| &row.values[cylroll::motion::point::column_index(c).unwrap()];
        for (c, want) in [
            ("theta", "pre_theta"),
            ("theta_dot", "pre_theta_dot"),
            ("x1", "pre_x1"),
            ("x1_dot", "pre_x1_dot"),
            ("phi1", "pre_phi1"),
            ("phi1_dot", "pre_phi1_dot"),
            ("N12", "pre_N12"),
            ("F21", "pre_F21"),
            ("N1", "pre_N1"),
            ("F1", "pre_F1"),
        ] {
            agrees(name, c, col(c), s(t, want));
        }
        // ψ2 = φ2 − θ, cylinder 2's counter-clockwise rotation with ψ2(0) = −θ0;
        // the fixture counts it in the paper's gauge, r1 θ0/r2 lower where the
        // contact starts rolling
        let psi2 = Float::with_val(P, &col("phi2").value - &col("theta").value);
        let pr = m.params();
        let shift = if *m.contact() == cylroll::model::Law::Frictionless {
            Float::new(P)
        } else {
            Float::with_val(P, &pr.r1) * m.start().theta0.to_float(P) / Float::with_val(P, &pr.r2)
        };
        let want = Float::with_val(P, Float::parse(s(t, "pre_psi2")).unwrap()) + shift;
        assert!(
            Float::with_val(P, &psi2 - &want).abs() < 1e-25,
            "[{name}] psi2 {psi2} vs {want}"
        );
        // --part-at: inside the window it parts there; before θ* it is refused
        let th_s = value(&stay, "theta_s", name).value.to_f64();
        let th_star = value(&stay, "theta_indeterminate", name).value.to_f64();
        let mid = format!("{:.6}", 0.5 * (th_s + th_star));
        let at = sep(
            &m,
            Branch::PartAt(Exact::parse("part_at", &mid, true).unwrap()),
        )
        .unwrap_or_else(|e| panic!("[{name}] part-at {mid}: {e}"));
        agrees(name, "part-at theta_s", value(&at, "theta_s", name), &mid);
        let before = format!("{:.6}", th_star - 0.01);
        let err = sep(
            &m,
            Branch::PartAt(Exact::parse("part_at", &before, true).unwrap()),
        )
        .unwrap_err()
        .to_string();
        assert!(err.contains("part-at"), "[{name}] part-at {before}: {err}");
        // past the end of the closed branch, or behind the start: refused too,
        // naming the window (before, such an angle was never reached and the
        // motion silently stayed together)
        let th0 = m.start().theta0.to_float(P).to_f64();
        for out in [th_s + 0.01, th_s + 1.0, th0 * 0.5, -1.0] {
            let a = format!("{out:.6}");
            let err = sep(
                &m,
                Branch::PartAt(Exact::parse("part_at", &a, true).unwrap()),
            )
            .unwrap_err()
            .to_string();
            assert!(
                err.contains("invalid part-at") && err.contains("theta in [≈"),
                "[{name}] part-at {a}: {err}"
            );
        }
    }
    assert!(
        checked >= 23 && with_star >= 13,
        "{checked} cases, {with_star} with a branch point"
    );
}

/// The committed golden files carry the branch point and the state there
/// (`theta_indeterminate`, `t_indeterminate`, `theta_dot_`, `N12_`,
/// `F21_indeterminate`) exactly where the independent derivation has one, and
/// every printed digit agrees with it (the files are read as text, not
/// recomputed).
#[test]
fn the_golden_files_carry_the_branch_point_of_the_independent_derivation() {
    let fx = fixture();
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("golden/data");
    let mut seen = 0;
    for (case, t) in fx.iter() {
        let Some(t) = t.as_table() else { continue };
        let path = dir.join(format!("{case}.json"));
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        let d: serde_json::Value = serde_json::from_str(&text).unwrap();
        let sc = &d["scalars"];
        let er = &d["scalar_error_bounds"];
        if s(t, "theta_star") == "none" {
            assert!(
                sc.get("theta_indeterminate").is_none(),
                "[{case}] the golden file has a branch point the derivation does not"
            );
            continue;
        }
        seen += 1;
        for (key, fkey) in [
            ("theta_indeterminate", "theta_star"),
            ("t_indeterminate", "t_star"),
            ("theta_dot_indeterminate", "theta_dot_star"),
            ("N12_indeterminate", "N12_star"),
            ("F21_indeterminate", "F21_star"),
        ] {
            let got = sc[key]
                .as_str()
                .unwrap_or_else(|| panic!("[{case}] golden file lacks {key}"));
            let bound = er[key]
                .as_str()
                .unwrap_or_else(|| panic!("[{case}] golden file lacks the bound of {key}"));
            let g = Float::with_val(P, Float::parse(got).unwrap());
            let w = Float::with_val(P, Float::parse(s(t, fkey)).unwrap());
            let digits = got
                .trim_start_matches('-')
                .trim_start_matches(['0', '.'])
                .chars()
                .filter(|c| c.is_ascii_digit())
                .count() as i32;
            let exp = Float::with_val(P, g.abs_ref()).log10().floor().to_f64() as i32;
            let lim = Float::with_val(P, 10u32).pow(exp - digits + 1) / 2u32
                + Float::with_val(P, Float::parse(bound).unwrap());
            let diff = Float::with_val(P, &g - &w).abs();
            assert!(
                diff <= lim,
                "[{case}] golden {key} = {got} vs independent {}: differ by {:.3e}",
                s(t, fkey),
                diff.to_f64()
            );
            assert!(digits >= 25, "[{case}] golden {key} has {digits} digits");
        }
    }
    assert!(seen >= 8, "only {seen} golden cases with a branch point");
}

/// `--rigorous`: θ* and t* of every ideal case with a branch point are
/// enclosed (the sign change of the free normal acceleration proved, and
/// proved to come before θs), each enclosure contains the independent
/// derivation's value, and proves every digit asked.
#[test]
fn the_branch_point_of_the_ideal_models_is_proved_and_contains_the_independent_value() {
    use cylroll::oracle::ideal::Oracle as Ideal;
    let fx = fixture();
    let mut seen = 0;
    for (case, t) in fx.iter() {
        let Some(t) = t.as_table() else { continue };
        let Some(model) = t.get("model").and_then(|m| m.as_str()) else {
            continue;
        };
        let m = model_of(model);
        let Some(ideal) = m.ideal() else { continue };
        if s(t, "theta_star") == "none" {
            continue;
        }
        seen += 1;
        let mut o = Ideal::new(&ideal, DIGITS).unwrap();
        let start = o.branch_point().unwrap().expect("a branch point");
        let p = cylroll::numeric::bits_for_digits(DIGITS) + 32;
        let (ths, _) = o.rigorous_separation(p).unwrap();
        let (th, tt) = o
            .rigorous_branch_point(&start.value, &ths.iv, p)
            .unwrap_or_else(|e| panic!("[{case}] {e}"));
        let want = Float::with_val(P, Float::parse(s(t, "theta_star")).unwrap());
        assert!(
            th.iv.contains(&Float::with_val(th.iv.prec(), &want)),
            "[{case}] theta* enclosure {:?} misses {want}",
            th.iv
        );
        assert!(
            th.shown.digits >= DIGITS,
            "[{case}] {} digits",
            th.shown.digits
        );
        assert!(th.iv.hi < ths.iv.lo, "[{case}] theta* not before theta_s");
        let tt = tt.unwrap_or_else(|e| panic!("[{case}] t*: {e}"));
        let want_t = Float::with_val(P, Float::parse(s(t, "t_star")).unwrap());
        assert!(
            tt.iv.contains(&Float::with_val(tt.iv.prec(), &want_t)),
            "[{case}] t* enclosure {:?} misses {want_t}",
            tt.iv
        );
        assert!(
            tt.shown.digits >= DIGITS,
            "[{case}] t*: {} digits",
            tt.shown.digits
        );
    }
    assert!(seen >= 6, "only {seen} ideal cases with a branch point");
}
