//! The audit of the paper: every verdict is a reviewed snapshot; errata fail
//! by far more than rounding and their corrections hold to ≥ 55 digits; the
//! corrected separation equations reproduce the oracle's θs.

use cylroll::audit::finding::{hold_tol, Verdict};
use cylroll::audit::truth::{self, Case, StartKind, PREC};
use cylroll::audit::{self, points, Row};
use cylroll::model::{Contact, Floor};
use cylroll::paper::X;
use rug::Float;
use std::sync::OnceLock;

fn rows() -> &'static Vec<Row> {
    static ROWS: OnceLock<Vec<Row>> = OnceLock::new();
    ROWS.get_or_init(|| audit::audit_all().expect("the audit runs"))
}

fn row(id: &str) -> &'static Row {
    rows()
        .iter()
        .find(|r| r.id == id)
        .unwrap_or_else(|| panic!("no row {id}"))
}

fn ten_to(e: i32) -> X {
    let t = Float::with_val(PREC, Float::i_pow_u(10, e.unsigned_abs()));
    X(if e < 0 { t.recip() } else { t })
}

#[test]
fn verdict_table_is_the_reviewed_one() {
    let table = audit::verdict_table(rows());
    insta::with_settings!({snapshot_path => "../golden/audit", prepend_module_to_snapshot => false}, {
        insta::assert_snapshot!("verdicts", table)
    });
}

#[test]
fn every_equation_has_a_row_and_a_verdict() {
    let ids = audit::ids();
    for n in 1..=114 {
        let id = n.to_string();
        assert!(ids.contains(&id.as_str()), "equation ({n}) missing");
    }
    for r in rows() {
        assert_ne!(
            r.verdict(),
            Verdict::Unresolved,
            "{}: {:#?}",
            r.id,
            r.finding
        );
        assert_eq!(r.printed.id, r.id);
    }
}

#[test]
fn errata_fail_by_more_than_1e_3_and_their_corrections_hold_to_55_digits() {
    let big = ten_to(-3);
    let tol = ten_to(-55);
    let mut n = 0;
    for r in rows().iter().filter(|r| r.verdict() == Verdict::Erratum) {
        n += 1;
        let failing = r.finding.printed.failing();
        assert!(!failing.is_empty(), "{}", r.id);
        for f in failing {
            assert!(
                f.max > big,
                "{} form '{}' fails only by {} at {}",
                r.id,
                f.label,
                f.max.to_f64(),
                f.at
            );
        }
        let (text, t) = r.finding.corrected.as_ref().expect("a corrected form");
        for f in &t.forms {
            assert!(
                f.max <= tol,
                "{} corrected '{}' ({}): residual {} at {}",
                r.id,
                text,
                f.label,
                f.max.to_f64(),
                f.at
            );
        }
    }
    assert!(n >= 10, "only {n} errata");
}

#[test]
fn holding_forms_hold_to_55_digits() {
    let tol = hold_tol();
    for r in rows().iter().filter(|r| {
        matches!(
            r.verdict(),
            Verdict::Holds | Verdict::Convention | Verdict::Reading
        )
    }) {
        for f in &r.finding.printed.forms {
            assert!(
                f.max <= tol,
                "{} '{}': {} at {}",
                r.id,
                f.label,
                f.max.to_f64(),
                f.at
            );
        }
    }
}

#[test]
fn the_errata_found_are_the_expected_ones() {
    for id in [
        "21", "23", "29", "33", "34", "43", "50", "64", "84", "85", "86", "98", "99", "fn6",
        "p-steady",
    ] {
        assert_eq!(row(id).verdict(), Verdict::Erratum, "{id}");
    }
    for id in ["28", "31", "32"] {
        assert_eq!(row(id).verdict(), Verdict::Convention, "{id}");
    }
    // the first form of (23) holds for any start; only the second is wrong
    let f23 = &row("23").finding.printed;
    assert!(f23
        .forms
        .iter()
        .any(|f| f.label.starts_with("first") && f.max <= hold_tol()));
}

/// |a − b| ≤ 1e-55 |b|.
fn same_angle(a: &X, b: &X) -> bool {
    (a - b).abs() <= hold_tol() * b
}

#[test]
fn corrected_separation_equations_give_the_oracles_theta_s() {
    for id in ["34", "43", "50"] {
        let r = row(id);
        assert!(!r.finding.roots.is_empty(), "{id}");
        for root in &r.finding.roots {
            let c = root.corrected.as_ref().expect("a corrected root");
            assert!(
                same_angle(c, &root.oracle),
                "({id}) {}: corrected {} vs oracle {}",
                root.case,
                c.to_f64(),
                root.oracle.to_f64()
            );
            let p = root.printed.as_ref().expect("a printed root");
            let off = (p - &root.oracle).abs();
            assert!(
                off > ten_to(-3),
                "({id}) {}: printed root {} is not off",
                root.case,
                p.to_f64()
            );
        }
    }
    // (36), (37), (42), (49), (55), (89) as printed
    for id in ["36", "37", "42", "49", "55", "89", "p-fixed-slip"] {
        for root in &row(id).finding.roots {
            let p = root.printed.as_ref().expect("a root");
            assert!(
                same_angle(p, &root.oracle),
                "({id}) {}: {} vs {}",
                root.case,
                p.to_f64(),
                root.oracle.to_f64()
            );
        }
    }
    // m1 = m2 with no friction: cos θs = √3 − 1 (corrected 43)
    let s = row("43")
        .finding
        .roots
        .iter()
        .find(|r| r.case.starts_with("S "))
        .expect("S");
    let c = X(Float::with_val(PREC, 3u32).sqrt() - 1u32);
    assert!(same_angle(&s.oracle, &c.acos()));
}

#[test]
fn truth_kinetic_energy_matches_the_core_energy() {
    // the audit's body-by-body T against the mechanics' energy (T + m2 g r cos θ)
    for p in points::all().iter().filter(|p| p.random) {
        for (floor, contact) in [
            (Floor::Roll, Contact::Roll),
            (Floor::Slip, Contact::Roll),
            (Floor::Roll, Contact::Slip),
            (Floor::Slip, Contact::Slip),
        ] {
            let case = Case::new(p, floor, contact, StartKind::General, false).unwrap();
            for d in &case.deltas {
                let st = case.dynm.state(&Float::with_val(PREC, d));
                let y = case.sym(&st, &Float::new(PREC)).unwrap();
                let e = X(case.dynm.energy(&st));
                let v = &y.m2 * &y.g * y.rsum() * &y.c;
                let t = truth::t(&y);
                let res = (e - v - &t).abs() / &case.scales.energy;
                assert!(res <= hold_tol(), "{}: {}", case.name, res.to_f64());
            }
        }
    }
}

#[test]
fn the_report_is_deterministic_and_equation_mode_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let summary = audit::run(None, dir.path()).unwrap();
    assert!(summary.contains("errata"), "{summary}");
    let written = std::fs::read_to_string(dir.path().join("audit.md")).unwrap();
    assert_eq!(written, audit::render_report(rows()));
    assert!(written.starts_with("# Audit of the paper's formulas\n"));
    assert!(written.contains("## Errata"));
    assert!(written.contains("`cylroll audit --equation 43`"));

    let other = tempfile::tempdir().unwrap();
    let one = audit::run(Some("(43)"), other.path()).unwrap();
    assert!(one.contains("verdict:  erratum"), "{one}");
    assert!(one.contains("m2 cos³θs"), "{one}");
    assert!(!other.path().join("audit.md").exists());
    assert!(audit::run(Some("eq. 115"), other.path()).is_err());
}

#[test]
fn cli_audit_one_equation() {
    let out = assert_cmd::Command::cargo_bin("cylroll")
        .unwrap()
        .args(["audit", "--equation", "fn6"])
        .assert()
        .success();
    let text = String::from_utf8(out.get_output().stdout.clone()).unwrap();
    assert!(text.contains("12 g (1 − cos θ)"), "{text}");
    assert_cmd::Command::cargo_bin("cylroll")
        .unwrap()
        .args(["audit", "--equation", "nope"])
        .assert()
        .code(2);
}

/// Beside eq. (36): the branch point of the paper's cases from the top,
/// against the roots of the closed-form cubics of
/// tests/fixtures/branch_derivation.md (mpmath, c0 = 1, ν0 = 0):
/// roll/roll 0.96220953928886545930, slip/roll 0.85061907623976005918; the
/// frictionless contacts and the held cylinder have none.
#[test]
fn the_branch_point_is_stated_beside_eq_36_and_among_the_omissions() {
    let notes = row("36").finding.notes.join(" ");
    assert!(
        notes.contains("roll/roll: θ* = 0.962209539289 < θs = 1.04719755120"),
        "{notes}"
    );
    assert!(
        notes.contains("slip/roll: θ* = 0.850619076240 < θs"),
        "{notes}"
    );
    for none in ["roll/slip: none", "slip/slip: none", "fixed/roll: none"] {
        assert!(notes.contains(none), "{none}: {notes}");
    }
    let md = audit::render_report(rows());
    assert!(md.contains("## What the paper does not say") && md.contains("θ* = 0.962209539289"));
}
