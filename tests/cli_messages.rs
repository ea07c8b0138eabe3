//! Messages quote the input as it was given, name where it was given (file,
//! entry, line, key) and print only digits that were verified.

use assert_cmd::Command;

fn cyl() -> Command {
    Command::cargo_bin("cylroll").unwrap()
}

/// Runs the command, expects exit 2 and returns its one-line message.
fn refused(args: &[&str]) -> String {
    let out = cyl().args(args).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    err
}

fn has(err: &str, needles: &[&str]) {
    for n in needles {
        assert!(err.contains(n), "{n:?} is not in: {err}");
    }
}

#[test]
fn a_refused_entry_of_a_times_file_names_the_file_the_entry_and_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("t.txt");
    let path = f.to_str().unwrap();
    let run = |text: &str| {
        std::fs::write(&f, text).unwrap();
        refused(&[
            "trajectory",
            "--theta0",
            "0.1",
            "--digits",
            "5",
            "--times-file",
            path,
        ])
    };
    // not a number: the fourth entry, on line 2
    let err = run("0 0.5\n1,abc\n");
    has(
        &err,
        &[
            &format!("times-file {path}: entry 4 (line 2) = \"abc\""),
            "exact number",
        ],
    );
    // blank lines count as lines
    let err = run("0\n\n\n-1e-3\n");
    has(&err, &["entry 2 (line 4) = \"-1e-3\"", ">= 0"]);
    // out of order: the entry that goes back, and the one before it as given
    let err = run("0, 2e0\n1\n");
    has(&err, &["entry 3 (line 2) = \"1\"", "ascending", "2e0"]);
    // after the end of the motion (found by the oracle): quoted as given
    let err = run("0 0.5\n\n5,1e3\n");
    has(
        &err,
        &[
            &format!("times-file {path}: entry 4 (line 3) = \"1e3\""),
            "first impact",
        ],
    );
    assert!(!err.contains("1000"), "{err}");
    // --times names the entry too
    let err = refused(&["trajectory", "--theta0", "0.1", "--times", "0,1e3"]);
    has(&err, &["times: entry 2 = \"1e3\"", "first impact"]);
    assert!(!err.contains("1000"), "{err}");
}

#[test]
fn values_are_echoed_as_given_and_bounded() {
    // a refusal quotes the user's text, not the rational it parsed to
    for (flag, value) in [
        ("--m1", "-1e3"),
        ("--k1", "-1e-3000"),
        ("--theta0", "2e0"),
        ("--thetadot0", "-1e-2"),
    ] {
        let mut args = vec!["separation", flag, value];
        if flag == "--thetadot0" {
            args.extend(["--theta0", "0.1"]);
        }
        let err = refused(&args);
        has(&err, &[&format!("= \"{value}\"")]);
        assert!(err.len() < 200, "{err}");
    }
    let err = refused(&["time", "--theta0", "0.1", "--to", "1e1"]);
    has(&err, &["to = \"1e1\"", "after separation"]);
    // tiny and huge exact values are echoed in a few characters, still exactly
    for args in [
        ["--theta0", "1e-5000", "--m1", "1"],
        ["--mu-contact", "1e-100000", "--theta0", "0.1"],
    ] {
        let (flag, value) = (args[0], args[1]);
        let run = |format: &str| {
            let out = cyl()
                .arg("separation")
                .args(args)
                .args(["--digits", "5", "--format", format])
                .output()
                .unwrap();
            assert!(
                out.status.success(),
                "{}",
                String::from_utf8_lossy(&out.stderr)
            );
            String::from_utf8(out.stdout).unwrap()
        };
        let key = flag.trim_start_matches("--").replace('-', "_");
        let text = run("json");
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(v["model"][&key], value);
        assert!(text.len() < 20_000, "{} bytes", text.len());
        let text = run("text");
        let header = text.lines().next().unwrap();
        assert!(header.contains(&format!("{key}={value}")), "{header}");
        assert!(text.lines().all(|l| l.len() < 1000));
    }
    // the usual values keep their plain decimal form
    let out = cyl()
        .args([
            "separation",
            "--theta0",
            "1/20",
            "--m1",
            "1e3",
            "--format",
            "json",
        ])
        .args(["--digits", "5"])
        .output()
        .unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["model"]["theta0"], "0.05");
    assert_eq!(v["model"]["m1"], "1000");
    // a long given text is shortened, its length noted
    let long = format!("-0.{}", "1".repeat(5000));
    let err = refused(&["separation", "--m2", &long]);
    has(&err, &["m2", "(5003 characters)"]);
    assert!(err.len() < 300, "{err}");
}

#[test]
fn toml_non_finite_values_are_refused_as_the_flags_refuse_them() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("p.toml");
    let path = f.to_str().unwrap();
    let run = |text: &str| {
        std::fs::write(&f, text).unwrap();
        cyl()
            .args([
                "separation",
                "--params",
                path,
                "--theta0",
                "0.1",
                "--digits",
                "5",
            ])
            .output()
            .unwrap()
    };
    let err_of = |text: &str| {
        let out = run(text);
        let err = String::from_utf8_lossy(&out.stderr).to_string();
        assert_eq!(out.status.code(), Some(2), "{text}: {err}");
        err
    };
    for (line, key, given) in [
        ("mu_contact = nan", "mu_contact", "nan"),
        ("mu_floor = -inf", "mu_floor", "-inf"),
        ("m1 = inf", "m1", "inf"),
        ("k2 = nan", "k2", "nan"),
    ] {
        let err = err_of(line);
        // the key, the file, the value given, what is allowed
        has(&err, &[&format!("{key} (in {path}) = \"{given}\"")]);
        // no suggestion to write the same value as a string
        assert!(!err.contains("as a string"), "{err}");
        // the flag's message, word for word after the value
        let flag = format!("--{}", key.replace('_', "-"));
        let out = cyl()
            .args(["separation", &flag, given, "--theta0", "0.1"])
            .output()
            .unwrap();
        let flag_err = String::from_utf8_lossy(&out.stderr).to_string();
        let tail = |e: &str| e.split_once("\": ").map(|(_, t)| t.to_string()).unwrap();
        assert_eq!(tail(&err), tail(&flag_err), "{err} vs {flag_err}");
    }
    // theta0 from the file (no flag over it)
    std::fs::write(&f, "theta0 = inf\n").unwrap();
    let err = refused(&["separation", "--params", path]);
    has(&err, &["theta0 (in", "\"inf\"", "pi/6"]);
    // inf is rolling, exactly, as the flag's inf
    let out = run("mu_floor = inf\nmu_contact = inf\n");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // a binary float is refused with the text to write instead, short
    let err = err_of("theta0 = 1e300\n");
    has(&err, &["theta0 (in", "= \"1e300\"", "theta0 = \"1e300\""]);
    assert!(err.len() < 300, "{err}");
}

#[test]
fn golden_case_files_are_parameter_files_and_unknown_keys_are_named() {
    let root = env!("CARGO_MANIFEST_DIR");
    let case = format!("{root}/golden/cases/main_mu_0_3.toml");
    let out = cyl()
        .args([
            "separation",
            "--params",
            &case,
            "--digits",
            "5",
            "--format",
            "json",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["model"]["mu_contact"], "0.3");
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("p.toml");
    std::fs::write(&f, "description = \"x\"\nsteps = 3\nmu = \"0.3\"\n").unwrap();
    let err = refused(&["separation", "--params", f.to_str().unwrap()]);
    has(
        &err,
        &[
            &format!("params (in {})", f.display()),
            "\"mu\"",
            "unknown key",
            "mu_contact",
            "description, steps",
        ],
    );
}

#[test]
fn check_finds_the_built_in_cases_from_any_directory() {
    let dir = tempfile::tempdir().unwrap();
    // the oracle's own rows of the case, as a candidate
    let out = cyl()
        .current_dir(dir.path())
        .args([
            "trajectory",
            "--theta0",
            "1/20",
            "--t-end",
            "6",
            "--steps",
            "12",
        ])
        .args(["--digits", "25", "--format", "csv"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    std::fs::write(dir.path().join("c.csv"), &out.stdout).unwrap();
    let out = cyl()
        .current_dir(dir.path())
        .args(["check", "c.csv", "--case", "main_roll_roll"])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(text.contains("case main_roll_roll"), "{text}");
    // an unknown name lists the built-in ones
    let out = cyl()
        .current_dir(dir.path())
        .args(["check", "c.csv", "--case", "no_such_case"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    has(&err, &["no_such_case", "main_mu_0_3", "unknown case"]);
}

#[test]
fn check_quotes_the_candidates_times_as_given_and_the_parting_angle_it_used() {
    let dir = tempfile::tempdir().unwrap();
    let params = dir.path().join("m.toml");
    std::fs::write(&params, "theta0 = \"1/10\"\n").unwrap();
    // a candidate that parts inside the window (at theta = 1), then one row
    // long after the first impact
    let out = cyl()
        .args(["trajectory", "--theta0", "1/10", "--part-at", "1.0"])
        .args([
            "--t-end", "5.9", "--steps", "118", "--digits", "12", "--format", "csv",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let mut csv = String::from_utf8(out.stdout).unwrap();
    let last = csv.lines().last().unwrap().to_string();
    let rest = last.split_once(',').unwrap().1;
    csv.push_str(&format!("1e2,{rest}\n"));
    let cand = dir.path().join("c.csv");
    std::fs::write(&cand, csv).unwrap();
    let run = |extra: &[&str]| {
        cyl()
            .args(["check", cand.to_str().unwrap(), "--params"])
            .arg(&params)
            .args(extra)
            .output()
            .unwrap()
    };
    let out = run(&["--past-end", "refuse"]);
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(2), "{err}");
    // the row's time as written in the file; the branch by the angle the
    // reference parts at (the fit, within the 12-digit candidate's
    // resolution of 1)
    has(
        &err,
        &["row 120 (line 121): t = 1e2 is after", "on the part-at 1"],
    );
    let fitted: f64 = err
        .split("on the part-at ")
        .nth(1)
        .and_then(|r| r.split_whitespace().next())
        .and_then(|x| x.parse().ok())
        .unwrap();
    assert!((fitted - 1.0).abs() < 1e-11, "{err}");
    // the end of the model: the verified digits of its time, 20 by default
    let end = err
        .split("at t = ")
        .nth(1)
        .and_then(|r| r.split_whitespace().next())
        .unwrap();
    let digits = end.chars().filter(char::is_ascii_digit).count();
    assert_eq!(digits, 20, "{end}");
    // (the impact of the flight from theta = 1, to the fit's resolution)
    assert!(
        end.starts_with("5.9259224915362") || end.starts_with("5.9259224915363"),
        "{end}"
    );
    let out = run(&["--format", "json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["first_after_end"]["t"], "1e2", "{v}");
}

/// `--part-at` outside every window where parting is lawful is refused by
/// every subcommand, naming the window (or saying the motion is unique),
/// with nothing printed; inside it, the cylinders part there.
#[test]
fn part_at_outside_the_lawful_window_is_refused_by_every_subcommand() {
    let run = |args: &[&str]| {
        let out = Command::cargo_bin("cylroll")
            .unwrap()
            .args(args)
            .output()
            .unwrap();
        (
            String::from_utf8(out.stdout).unwrap(),
            String::from_utf8(out.stderr).unwrap(),
            out.status.code(),
        )
    };
    let base = ["--theta0", "0.1", "--digits", "12"];
    let cmds: [&[&str]; 4] = [
        &["separation"],
        &["trajectory", "--times", "1"],
        &["time", "--to", "0.5"],
        &["forces", "--theta", "0.5"],
    ];
    for cmd in cmds {
        for a in ["1e-5000", "0.05", "1.06", "3"] {
            let mut args: Vec<&str> = cmd.to_vec();
            args.extend(base);
            args.extend(["--part-at", a]);
            let (out, err, code) = run(&args);
            assert_eq!(code, Some(2), "{args:?}: {err}");
            assert!(out.is_empty(), "{args:?}");
            assert!(
                err.contains(&format!("invalid part-at = \"{a}\""))
                    && err.contains("theta in [≈0.96571")
                    && err.contains(", ≈1.0507"),
                "{args:?}: {err}"
            );
        }
    }
    // a unique motion (frictionless contact) has no window at all
    let (_, err, code) = run(&[
        "separation",
        "--theta0",
        "0.1",
        "--contact",
        "slip",
        "--part-at",
        "1",
    ]);
    assert_eq!(code, Some(2));
    assert!(err.contains("it is unique"), "{err}");
    // inside the window: parts there
    let (out, err, code) = run(&[
        "separation",
        "--theta0",
        "0.1",
        "--part-at",
        "1",
        "--digits",
        "12",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains("theta_s                 = 1.00000000000"),
        "{out}"
    );
}

/// Refusals that need no computation come before it: a candidate with more
/// rows than `--max-rows` (counted without parsing), an unwritable `report`
/// or `golden` destination. Each exits at once with nothing computed.
#[test]
fn refusals_that_need_no_computation_come_first() {
    let dir = tempfile::tempdir().unwrap();
    // 200 001 rows against --max-rows 200 000: judged row by row, the first
    // 200 000 would have been compared with the oracle before the refusal
    let path = dir.path().join("long.csv");
    let mut text = String::from("t,theta\n");
    for i in 0..=200_000u32 {
        text.push_str(&format!("{}e-6,0.1\n", i));
    }
    std::fs::write(&path, text).unwrap();
    let t0 = std::time::Instant::now();
    let out = Command::cargo_bin("cylroll")
        .unwrap()
        .args(["check", path.to_str().unwrap(), "--case", "main_roll_roll"])
        .args(["--max-rows", "200000"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("more than 200000 data rows"), "{err}");
    assert!(t0.elapsed().as_secs_f64() < 5.0, "{:?}", t0.elapsed());
    // a report whose destination is a file, not a directory
    let file = dir.path().join("plain");
    std::fs::write(&file, "x").unwrap();
    let t0 = std::time::Instant::now();
    let out = Command::cargo_bin("cylroll")
        .unwrap()
        .args(["report", "--quiet", "--out", file.to_str().unwrap()])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(4), "{err}");
    assert!(
        err.contains("cannot write") && err.contains("plain"),
        "{err}"
    );
    assert!(t0.elapsed().as_secs_f64() < 5.0, "{:?}", t0.elapsed());
    assert!(out.stdout.is_empty());
}
