//! The command line: each subcommand in each format, and bad input.

use assert_cmd::Command;

fn cyl() -> Command {
    Command::cargo_bin("cylroll").unwrap()
}

fn json(args: &[&str]) -> serde_json::Value {
    let out = cyl()
        .args(args)
        .args(["--format", "json"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

#[test]
fn separation_json_echoes_model_and_digits() {
    let v = json(&["separation", "--digits", "20"]);
    assert_eq!(v["theta_s"], "1.0471975511965977462");
    assert!(
        v.get("t_s").is_none(),
        "infinite time from rest at the top is not a number"
    );
    assert_eq!(v["model"]["k2"], "0.5");
    assert_eq!(v["model"]["floor"], "roll");
    assert_eq!(v["digits_requested"], "20");
    assert_eq!(v["digits_verified"]["theta_s"], "20");
    // every number is a string
    for (k, val) in v.as_object().unwrap() {
        assert!(!val.is_number(), "{k} is a JSON number");
    }
}

#[test]
fn separation_with_finite_time_and_mu() {
    let v = json(&[
        "separation",
        "--theta0",
        "1/10",
        "--mu",
        "0.2",
        "--digits",
        "15",
    ]);
    assert_eq!(v["theta_s"], "1.05077206201851");
    assert!(v["t_s"].as_str().unwrap().starts_with("5.204959139244"));
    // with mu = 0.2 the rolling contact needs more friction before separation
    assert!(v.get("theta_slip_contact").is_some(), "{v}");
}

#[test]
fn time_subcommand() {
    let v = json(&["time", "--theta0", "0.1", "--to", "0.9", "--digits", "25"]);
    assert_eq!(v["t"], "4.924315468243287509589439");
}

#[test]
fn forces_subcommand_all_keys() {
    let v = json(&[
        "forces", "--theta0", "0.1", "--theta", "1/2", "--digits", "12",
    ]);
    for k in [
        "F1",
        "N1",
        "F21",
        "N12",
        "theta_dot",
        "theta_ddot",
        "mu_floor",
        "mu_contact",
    ] {
        assert!(v[k].is_string(), "{k} missing: {v}");
    }
    // total vertical force: N1 = (m1+m2) g − m2 r (sinθ θ̈ + cosθ θ̇²) < 2 while the pair accelerates down
    let n1: f64 = v["N1"].as_str().unwrap().parse().unwrap();
    assert!(n1 > 0.0 && n1 < 2.0);
    // frictionless contact: F21 exactly 0
    let v = json(&["forces", "--contact", "slip", "--theta", "0.3"]);
    assert_eq!(v["F21"], "0");
    assert_eq!(v["mu_contact"], "0");
}

#[test]
fn trajectory_csv_has_header_and_rows() {
    let out = cyl()
        .args([
            "trajectory",
            "--theta0",
            "0.1",
            "--t-end",
            "2",
            "--steps",
            "4",
            "--format",
            "csv",
            "--digits",
            "10",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(
        lines[0],
        "t,theta,theta_dot,theta_ddot,phi1,phi2,x1,x2,y2,F1,N1,F21,N12"
    );
    assert_eq!(lines.len(), 6);
    assert!(
        lines[1].starts_with("0,0.1000000000,0,0.03519415980,0,-0.1000000000,0,"),
        "{}",
        lines[1]
    );
    assert!(lines[5].starts_with("2,"), "{}", lines[5]);
}

/// A time is an input and is echoed exactly when it is a terminating decimal:
/// 0.125 and 1.0000000000000000000000000000005 lie exactly halfway between two
/// roundings to the requested digits, a tie no error bound could settle (the
/// command used to stop with exit 3 there). A non-terminating time (1/3) is
/// rounded to the requested digits like every other column.
#[test]
fn terminating_times_are_echoed_exactly_even_at_a_rounding_tie() {
    for (times, digits, want) in [
        ("0.125,1/3", "2", ["0.125", "0.33"]),
        (
            "1.0000000000000000000000000000005,1/3",
            "30",
            [
                "1.0000000000000000000000000000005",
                "0.333333333333333333333333333333",
            ],
        ),
    ] {
        let out = cyl()
            .args(["trajectory", "--theta0", "0.1", "--times", times])
            .args(["--digits", digits, "--format", "csv"])
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{times}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = String::from_utf8(out.stdout).unwrap();
        let t: Vec<&str> = text
            .lines()
            .skip(1)
            .map(|l| l.split(',').next().unwrap())
            .collect();
        assert_eq!(t, want, "{times}");
    }
}

#[test]
fn text_format_marks_verified_digits() {
    let out = cyl()
        .args([
            "separation",
            "--floor",
            "fixed",
            "--k2",
            "2/5",
            "--digits",
            "12",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    // cos θs = 10/17
    assert!(text.contains("= 0.941921401300  [12 digits;"), "{text}"); // acos(10/17)
    assert!(text.contains("[12 digits;"), "{text}");
}

fn fails(args: &[&str], needle: &str) {
    let out = cyl().args(args).output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(2),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains(needle), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "no partial output on error");
    assert!(!err.contains("panicked"));
}

#[test]
fn bad_input_is_named_with_its_range() {
    fails(&["separation", "--m1", "0"], "m1");
    fails(&["separation", "--m2", "-1"], "must be > 0");
    fails(&["separation", "--r1", "abc"], "r1");
    fails(&["separation", "--k2", "-0.1"], "k2");
    fails(&["separation", "--g", "nan"], "g");
    fails(&["separation", "--theta0", "2"], "-pi/2 < theta0 < pi/2");
    fails(&["separation", "--theta0", "pi/2"], "theta0");
    fails(&["separation", "--floor", "ice"], "roll, slip or fixed");
    fails(
        &["separation", "--floor", "fixed", "--omega0", "1"],
        "omega0",
    );
    fails(&["separation", "--digits", "0"], "digits");
    fails(&["separation", "--digits", "100000"], "between 1 and 2000");
    fails(
        &["separation", "--theta0", "0.1", "--thetadot0", "-1"],
        "thetadot0",
    );
    fails(
        &["separation", "--theta0", "0.1", "--thetadot0", "100"],
        "part at once",
    );
    fails(&["time", "--to", "0.5"], "infinite");
    fails(
        &["time", "--theta0", "0.1", "--to", "1.2"],
        "after separation",
    );
    fails(
        &["time", "--theta0", "0.1", "--to", "0.05"],
        "before the start",
    );
    fails(&["forces", "--theta", "1.3"], "theta");
    fails(
        &["trajectory", "--theta0", "0.1", "--times", "0,100"],
        "separation time",
    );
    fails(&["trajectory", "--theta0", "0.1", "--times", "-1"], ">= 0");
    fails(&["trajectory", "--times", "1"], "infinite");
    fails(&["separation", "--mu", "-1"], "mu");
}

#[test]
fn params_file_is_read_exactly_and_validated() {
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("p.toml");
    std::fs::write(&good, "floor = \"fixed\"\nk2 = \"0.4\"\nm1 = 3\n").unwrap();
    let v = json(&[
        "separation",
        "--params",
        good.to_str().unwrap(),
        "--digits",
        "10",
    ]);
    assert_eq!(v["model"]["k2"], "0.4");
    // 10/17
    assert_eq!(v["theta_s"], "0.9419214013"); // acos(10/17), mpmath
    let bad = dir.path().join("b.toml");
    std::fs::write(&bad, "k2 = 0.4\n").unwrap();
    fails(
        &["separation", "--params", bad.to_str().unwrap()],
        "write it as a string",
    );
    std::fs::write(&bad, "mass = \"1\"\n").unwrap();
    fails(
        &["separation", "--params", bad.to_str().unwrap()],
        "unknown key",
    );
    std::fs::write(&bad, "this is = = not toml").unwrap();
    fails(&["separation", "--params", bad.to_str().unwrap()], "TOML");
}

#[test]
fn unreadable_input_files_exit_2() {
    fails(
        &["separation", "--params", "/nonexistent/p.toml"],
        "/nonexistent/p.toml",
    );
    let out = cyl()
        .args(["check", "/nonexistent/c.csv", "--case", "main_roll_roll"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn golden_run_writes_nothing_on_failure() {
    // a case directory with one bad case: no data file appears
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir_all(dir.path().join("cases")).unwrap();
    std::fs::write(
        dir.path().join("cases/a.toml"),
        "theta0 = \"1/10\"\nsteps = 2\n",
    )
    .unwrap();
    std::fs::write(dir.path().join("cases/b.toml"), "theta0 = \"0\"\n").unwrap(); // infinite times
    let out = cyl()
        .args(["golden", "--dir", dir.path().to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(!dir.path().join("data").exists());
}
