//! The command line: each subcommand in each format, and bad input.

use assert_cmd::Command;

#[path = "support/run.rs"]
mod run;

fn cyl() -> Command {
    Command::cargo_bin("cylroll").unwrap()
}

fn json(args: &[&str]) -> serde_json::Value {
    serde_json::from_str(&json_text(args)).unwrap()
}

/// The command's JSON text, after a zero exit.
fn json_text(args: &[&str]) -> String {
    run::stdout_ok(&[args, &["--format", "json"][..]].concat())
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
    assert_eq!(v["model"]["contact"], "roll");
    assert_eq!(v["model"]["mu_floor"], "inf");
    assert_eq!(v["model"]["mu_contact"], "inf");
    assert_eq!(v["digits_requested"], "20");
    assert_eq!(v["digits_verified"]["theta_s"], "20");
    // every number is a string
    for (k, val) in v.as_object().unwrap() {
        assert!(!val.is_number(), "{k} is a JSON number");
    }
}

#[test]
fn separation_with_finite_time_and_mu() {
    let base = ["separation", "--theta0", "1/10", "--digits", "15"];
    let v = json(&base);
    assert_eq!(v["theta_s"], "1.05077206201851");
    assert!(v["t_s"].as_str().unwrap().starts_with("5.204959139244"));
    // the branch point before θs (the cylinders may stay together or part)
    assert!(v["theta_indeterminate"]
        .as_str()
        .unwrap()
        .starts_with("0.965713174981"));
    // --mu MU is Coulomb friction μ at both contacts: the same answer, byte
    // for byte, as --mu-floor MU --mu-contact MU
    let mu = json_text(&[&base[..], &["--mu", "0.2"]].concat());
    let both = json_text(&[&base[..], &["--mu-floor", "0.2", "--mu-contact", "0.2"]].concat());
    assert_eq!(mu, both);
    let v: serde_json::Value = serde_json::from_str(&mu).unwrap();
    assert_eq!(v["model"]["mu_floor"], "0.2");
    assert_eq!(v["model"]["mu_contact"], "0.2");
    // rolling needs more than μ = 0.2 before θs: the real motion's first
    // event is a slip onset, before the ideal separation angle
    let ev = &v["events"][0];
    assert_eq!(ev["kind"], "slip_onset", "{v}");
    let th: f64 = ev["theta"].as_str().unwrap().parse().unwrap();
    assert!(th > 0.1 && th < 1.05077206201851, "{th}");
    // a held lower cylinder keeps its floor: μ goes to the contact only
    let fixed = ["--floor", "fixed"];
    let a = json_text(&[&base[..], &fixed[..], &["--mu", "0.2"]].concat());
    let b = json_text(&[&base[..], &fixed[..], &["--mu-contact", "0.2"]].concat());
    assert_eq!(a, b);
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
        "t,theta,theta_dot,theta_ddot,phi1,phi2,x1,x2,y2,x1_dot,phi1_dot,x2_dot,y2_dot,\
         phi2_dot,F1,N1,F21,N12,s1,s12,work,mode"
    );
    assert_eq!(lines.len(), 6);
    // φ2 starts at 0 (the paper's φ2 is ours − r1 θ0/r2)
    assert!(
        lines[1].starts_with("0,0.1000000000,0,0.03519415980,0,0,0,"),
        "{}",
        lines[1]
    );
    assert!(lines[1].ends_with(",stick/stick"), "{}", lines[1]);
    assert!(lines[5].starts_with("2,"), "{}", lines[5]);
}

/// A time after separation is answered: the rows are the free flight, which
/// must be the projectile motion (cylinder 2 ballistic with its spin
/// constant; cylinder 1 rolling on at constant speed, since nothing pushes
/// it) through the state `separation` reports just before the first impact,
/// and that projectile must leave cylinder 1 at θs at t_s. After the impact,
/// refused.
#[test]
fn times_after_separation_are_answered_in_flight() {
    use rug::Float;
    let p = 256;
    let model = ["--theta0", "1/10"];
    let sep = json(&[&["separation", "--digits", "40"][..], &model[..]].concat());
    assert_eq!(sep["end"], "impact on the floor", "{sep}");
    let f = |s: &str| Float::with_val(p, Float::parse(s).unwrap());
    let s = |k: &str| f(sep[k].as_str().unwrap_or_else(|| panic!("no {k}: {sep}")));
    let (t_s, t_i) = (s("t_s"), s("t_impact"));
    let g = f("1");
    // the projectile through the impact state, at time t (r1 = r2 = 1)
    let flight = |t: &Float| {
        let tau = Float::with_val(p, t - &t_i);
        let x1 = s("x1_impact") + s("x1_dot_impact") * tau.clone();
        let x2 = s("x2_impact") + s("x2_dot_impact") * tau.clone();
        let y2 = s("y2_impact") + s("y2_dot_impact") * tau.clone()
            - g.clone() * tau.clone() * tau.clone() / 2u32;
        let y2_dot = s("y2_dot_impact") - g.clone() * tau.clone();
        (x1, x2, y2, y2_dot)
    };
    let close = |what: &str, a: &Float, b: &Float| {
        let d = Float::with_val(p, a - b).abs().to_f64();
        assert!(d < 1e-24, "{what}: {a} vs {b} ({d:e})");
    };
    // at t_s the projectile is where the cylinders part: on the line of
    // centres at θs, at the distance r = 2
    let (x1, x2, y2, _) = flight(&t_s);
    let theta_s = s("theta_s");
    close(
        "x2 - x1 at t_s",
        &(x2 - x1),
        &(theta_s.clone().sin() * 2u32),
    );
    close("y2 - r1 at t_s", &(y2 - 1u32), &(theta_s.cos() * 2u32));
    // rows in flight, between separation and the impact
    let times: Vec<Float> = ["0.25", "0.5"].iter().map(|d| t_s.clone() + f(d)).collect();
    assert!(times[1] < t_i);
    let texts: Vec<String> = times
        .iter()
        .map(|t| t.to_string_radix(10, Some(45)))
        .collect();
    let v = json(
        &[
            &["trajectory", "--digits", "30", "--times", &texts.join(",")][..],
            &model[..],
        ]
        .concat(),
    );
    let rows = v["rows"].as_array().unwrap();
    let get = |i: usize, k: &str| f(rows[i][k].as_str().unwrap());
    for (i, t) in times.iter().enumerate() {
        assert_eq!(rows[i]["mode"], "flight", "{t}");
        let (x1, x2, y2, y2_dot) = flight(&f(&texts[i]));
        let theta = Float::with_val(p, (x2.clone() - x1.clone()).atan2(&(y2.clone() - 1u32)));
        for (k, want) in [
            ("x1", x1),
            ("x2", x2),
            ("y2", y2),
            ("x1_dot", s("x1_dot_impact")),
            ("phi1_dot", s("phi1_dot_impact")),
            ("x2_dot", s("x2_dot_impact")),
            ("y2_dot", y2_dot),
            ("theta", theta),
            ("N1", g.clone()),
        ] {
            close(&format!("{k} at {t}"), &get(i, k), &want);
        }
        // ψ2 = φ2 − θ turns at the constant rate of the impact state
        close(
            &format!("psi2_dot at {t}"),
            &(get(i, "phi2_dot") - get(i, "theta_dot")),
            &s("psi2_dot_impact"),
        );
        for k in ["F1", "F21", "N12", "work"] {
            assert_eq!(rows[i][k], "0", "{k} at {t}");
        }
    }
    // φ1 and ψ2 advance linearly between the two rows
    let dt = f(&texts[1]) - f(&texts[0]);
    close(
        "phi1",
        &(get(1, "phi1") - get(0, "phi1")),
        &(s("phi1_dot_impact") * dt.clone()),
    );
    let psi2 = |i: usize| get(i, "phi2") - get(i, "theta");
    close("psi2", &(psi2(1) - psi2(0)), &(s("psi2_dot_impact") * dt));
    // after the first impact: refused
    let late = (t_i + f("0.01")).to_string_radix(10, Some(10));
    fails(
        &["trajectory", "--theta0", "1/10", "--times", &late],
        "after the first impact",
    );
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
            "1/3,1.0000000000000000000000000000005",
            "30",
            [
                "0.333333333333333333333333333333",
                "1.0000000000000000000000000000005",
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
        "after the first impact",
    );
    fails(&["trajectory", "--theta0", "0.1", "--times", "-1"], ">= 0");
    fails(
        &["trajectory", "--theta0", "0.1", "--times", "2,1"],
        "must be ascending",
    );
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
