//! `cylroll check`: an honest f64 integrator passes, a perturbed one fails.

use assert_cmd::Command;
use std::fmt::Write;

/// θ̈(θ, θ̇) for the main case (identical solid cylinders, both rolling),
/// written from the paper's eq. (23), first form, which the audit confirms:
/// θ̈ = [g/r − A(cos θ − k2) θ̇²] sin θ / [1 + k2 − A(cos θ − k2)²], A = 1/3, k2 = 1/2, g/r = 1/2.
fn accel(th: f64, thd: f64) -> f64 {
    let (a, k2, gr) = (1.0 / 3.0, 0.5, 0.5);
    let c = th.cos();
    (gr - a * (c - k2) * thd * thd) * th.sin() / (1.0 + k2 - a * (c - k2) * (c - k2))
}

/// Classical RK4 from θ0 = 1/20 at rest, written at t = 0, 0.25, …, 6.
fn rk4_csv(perturb: f64) -> String {
    let h = 1.0 / 4096.0;
    let (mut th, mut thd) = (0.05f64, 0.0f64);
    let mut out = String::from("t,theta,theta_dot\n");
    let per_out = 1024; // 0.25 / h
    for n in 0..=24 * per_out {
        if n % per_out == 0 {
            let t = n as f64 * h;
            writeln!(out, "{t},{:e},{:e}", th * (1.0 + perturb), thd).unwrap();
        }
        let f = |y: (f64, f64)| (y.1, accel(y.0, y.1));
        let k1 = f((th, thd));
        let k2 = f((th + h / 2.0 * k1.0, thd + h / 2.0 * k1.1));
        let k3 = f((th + h / 2.0 * k2.0, thd + h / 2.0 * k2.1));
        let k4 = f((th + h * k3.0, thd + h * k3.1));
        th += h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
        thd += h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
    }
    out
}

fn run(csv: &str, extra: &[&str]) -> std::process::Output {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cand.csv");
    std::fs::write(&path, csv).unwrap();
    Command::cargo_bin("cylroll")
        .unwrap()
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(["check", path.to_str().unwrap(), "--case", "main_roll_roll"])
        .args(extra)
        .output()
        .unwrap()
}

#[test]
fn a_correct_f64_rk4_passes() {
    let out = run(&rk4_csv(0.0), &["--rtol", "1e-9", "--atol", "1e-11"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(text.contains("PASS"), "{text}");
    assert!(text.contains("theta_dot"));
}

#[test]
fn a_perturbed_candidate_fails_at_its_first_row() {
    let out = run(&rk4_csv(1e-6), &["--format", "json"]);
    assert_eq!(out.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["passed"], false);
    assert_eq!(v["first_failure"]["column"], "theta");
    assert_eq!(v["first_failure"]["row"], "1");
    let theta = v["columns"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["column"] == "theta")
        .unwrap();
    let rel: f64 = theta["max_rel"].as_str().unwrap().parse().unwrap();
    assert!((rel - 1e-6).abs() < 1e-8, "{rel}");
}

#[test]
fn malformed_candidates_are_named() {
    for (csv, needle) in [
        ("", "empty"),
        ("theta\n0.1\n", "column named t"),
        ("t,omega\n0,1\n", "unknown column"),
        ("t,theta\n0,abc\n", "not a number"),
        ("t,theta\n0,0.05,1\n", "fields"),
        ("t,theta\n0,nan\n", "not finite"),
        ("t,theta\n100,1\n", "after the first impact"),
    ] {
        let out = run(csv, &[]);
        assert_eq!(out.status.code(), Some(2), "{csv:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(needle), "{csv:?}: {err}");
    }
}
