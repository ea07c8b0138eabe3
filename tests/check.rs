//! `cylroll check`: an honest f64 integrator passes, a perturbed one fails;
//! the oracle's own golden files pass; a wrong value or mode fails at its
//! column and row, in its phase; a candidate that parts at the branch point
//! is judged against the part branch; refusals name the file and the row.

use assert_cmd::Command;

#[path = "support/run.rs"]
mod run;
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
        ("t,theta\n100,1\n", "every row, from row 1, is after it"),
        ("t,theta\n0,0.05\n1,abc\n", "row 2 (line 3), column theta"),
        ("t,theta\n0,0.05\n1,1/3\n", "row 2 (line 3), column theta"),
        (
            "t,theta\n0,0.05\n0.5,0.05\n0.25,0.05\n",
            "row 3 (line 4): t = 0.25 is before",
        ),
        (
            "t,theta\n-1,0.05\n",
            "row 1 (line 2): t = -1 is before the start",
        ),
        // blank lines are skipped, and counted in the line named
        (
            "\nt,theta\n\n0,0.05\n\n1,abc\n",
            "row 2 (line 6), column theta",
        ),
        (
            "t,theta\n0,0.05\n\n1,0.05,7\n",
            "row 2 (line 4) has 3 fields",
        ),
    ] {
        let out = run(csv, &[]);
        assert_eq!(out.status.code(), Some(2), "{csv:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        // the file is named, and the row where one is at fault
        assert!(
            err.contains(needle) && err.contains("cand.csv"),
            "{csv:?}: {err}"
        );
    }
}

/// Runs `cylroll check FILE ARGS…` from the repository.
fn check_file(path: &std::path::Path, args: &[&str]) -> std::process::Output {
    Command::cargo_bin("cylroll")
        .unwrap()
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .arg("check")
        .arg(path)
        .args(args)
        .output()
        .unwrap()
}

/// The oracle's own table of golden case `case` (`trajectory --params
/// golden/cases/CASE.toml --format csv` and `args`), which must succeed.
fn oracle_csv(case: &str, args: &[&str]) -> String {
    let out = Command::cargo_bin("cylroll")
        .unwrap()
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args([
            "trajectory",
            "--params",
            &format!("golden/cases/{case}.toml"),
        ])
        .args(["--format", "csv"])
        .args(args)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{case} {args:?}");
    String::from_utf8(out.stdout).unwrap()
}

fn json(out: &std::process::Output) -> serde_json::Value {
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "{e}: {}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        )
    })
}

fn golden_names() -> Vec<String> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/golden/cases");
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| {
            let p = e.unwrap().path();
            (p.extension()? == "toml").then(|| p.file_stem()?.to_str().map(String::from))?
        })
        .collect();
    names.sort();
    names
}

fn golden_csv(name: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("golden/data/{name}.csv"))
}

#[test]
fn every_golden_file_passes_its_own_case_mode_column_included() {
    let names = golden_names();
    assert!(names.len() >= 19, "{names:?}");
    for name in &names {
        let out = check_file(&golden_csv(name), &["--case", name, "--format", "json"]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{name}: {}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        let v = json(&out);
        assert_eq!(v["verdict"], "pass", "{name}");
        // every column of the schema is judged, the mode column too
        let cols: Vec<&str> = v["columns"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| c["column"].as_str().unwrap())
            .collect();
        assert_eq!(cols.len(), 21, "{name}: {cols:?}");
        assert_eq!(cols.last(), Some(&"mode"), "{name}");
        // every phase passes, and every event the candidate's rows bracket
        assert!(v["phases"]
            .as_array()
            .unwrap()
            .iter()
            .all(|p| p["passed"] == true));
        assert!(v["events"]
            .as_array()
            .unwrap()
            .iter()
            .all(|e| e["passed"] != false && e["kind"] != "spurious"));
        // a file that parts at the end of the closed branch is judged on it
        assert!(v["branch"]["lawful"] == true, "{name}");
        assert_ne!(v["branch"]["followed"], "part", "{name}: {}", v["branch"]);
    }
    // the issue's example, and the same model as a parameter file
    for args in [
        ["--case", "main_mu_0_3"],
        ["--params", "golden/cases/main_mu_0_3.toml"],
    ] {
        let out = check_file(&golden_csv("main_mu_0_3"), &args);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.contains("phase 2 stick/slip+"), "{text}");
        assert!(text.contains("slip_onset"), "{text}");
    }
}

/// The golden CSV of `name` with one cell changed by `f` (row is 1-based).
fn edited(name: &str, row: usize, column: &str, f: impl Fn(&str) -> String) -> tempfile::TempDir {
    let text = std::fs::read_to_string(golden_csv(name)).unwrap();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let k = lines[0].split(',').position(|c| c == column).unwrap();
    let mut cells: Vec<String> = lines[row].split(',').map(String::from).collect();
    cells[k] = f(&cells[k]);
    lines[row] = cells.join(",");
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("cand.csv"), lines.join("\n") + "\n").unwrap();
    dir
}

#[test]
fn a_perturbed_column_fails_at_its_column_row_and_phase() {
    // x2 at row 12 (t = 1.60325, sticking) of main_mu_0_3, off by 1e-6 relative
    let dir = edited("main_mu_0_3", 12, "x2", |c| {
        format!("{:e}", c.parse::<f64>().unwrap() * (1.0 + 1e-6))
    });
    let out = check_file(
        &dir.path().join("cand.csv"),
        &["--case", "main_mu_0_3", "--format", "json"],
    );
    assert_eq!(out.status.code(), Some(1));
    let v = json(&out);
    assert_eq!(v["verdict"], "fail");
    assert_eq!(v["first_failure"]["column"], "x2");
    assert_eq!(v["first_failure"]["row"], "12");
    assert_eq!(v["first_failure"]["t"], "1.60325");
    let x2 = v["columns"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["column"] == "x2")
        .unwrap();
    assert_eq!(x2["failures"], "1");
    // the column's tolerance: rtol 1e-8, atol 1e-10 x its scale r = 2
    assert_eq!(x2["rtol"], "1e-8");
    assert_eq!(x2["atol"], "2.000e-10");
    // the failure is in the first phase (sticking); the others pass
    let phases = v["phases"].as_array().unwrap();
    assert_eq!(phases[0]["mode"], "stick/stick");
    assert_eq!(phases[0]["passed"], false);
    assert!(
        phases[1..].iter().all(|p| p["passed"] == true),
        "{phases:?}"
    );
    assert_eq!(x2["phases"][0]["failures"], "1");
    assert_eq!(x2["phases"][1]["failures"], "0");
    // a per-column tolerance lets it through
    let out = check_file(
        &dir.path().join("cand.csv"),
        &["--case", "main_mu_0_3", "--tol", "x2=1e-5"],
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
}

#[test]
fn a_wrong_mode_fails_at_its_row_and_as_an_event() {
    // row 5 (t = 0.583) says flight where the contacts stick
    let dir = edited("main_mu_0_3", 5, "mode", |_| "flight".into());
    let out = check_file(
        &dir.path().join("cand.csv"),
        &["--case", "main_mu_0_3", "--format", "json"],
    );
    assert_eq!(out.status.code(), Some(1));
    let v = json(&out);
    assert_eq!(v["first_failure"]["column"], "mode");
    assert_eq!(v["first_failure"]["row"], "5");
    assert_eq!(v["first_failure"]["candidate"], "flight");
    assert_eq!(v["first_failure"]["oracle"], "stick/stick");
    // its changes of mode are events the reference does not have
    let spurious: Vec<&serde_json::Value> = v["events"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["kind"] == "spurious")
        .collect();
    assert_eq!(spurious.len(), 2, "{}", v["events"]);
    assert_eq!(spurious[0]["mode"], "flight");
    assert_eq!(spurious[0]["passed"], false);
    // a slip onset at the wrong row: the mode column and the event fail
    let dir = edited("main_mu_0_3", 29, "mode", |_| "stick/slip+".into());
    let out = check_file(&dir.path().join("cand.csv"), &["--case", "main_mu_0_3"]);
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("FAIL: first at row 29 (t = 4.081), column mode"),
        "{text}"
    );
}

/// The main case (identical solid cylinders, both rolling, from rest at
/// θ0 = 1/20) as an engine that parts where parting first becomes lawful:
/// classical RK4 of eq. (23) while the free relative normal acceleration
/// r θ̇² − g cos θ of the released cylinders is negative, then the flight of
/// the released bodies in closed form. `part_at_theta` parts instead where θ
/// reaches that angle. Rows every 1/64 (exact decimals) up to `t_last`, with
/// the columns t, theta, theta_dot, y2 and mode.
///
/// The flight, derived here: with φ1 cyclic and at rest at the start, p_φ1 = 0
/// gives cylinder 1's rolling rate ω1 = θ̇ (1 − 2 cos θ)/3 (clockwise, r1 = 1),
/// its centre V1 = (ω1, 0) kept after parting (a free rolling cylinder), and
/// cylinder 2's centre V2 = V1 + r θ̇ (cos θ, −sin θ) (r = 2), ballistic after
/// parting (g = 1); θ in flight is the direction of the line of centres.
fn parting_engine(part_at_theta: Option<f64>, t_last: f64) -> String {
    let (g, r) = (1.0f64, 2.0f64);
    let h = 1.0 / 4096.0;
    let f = |y: (f64, f64)| (y.1, accel(y.0, y.1));
    let rk4 = |y: (f64, f64), h: f64| {
        let k1 = f(y);
        let k2 = f((y.0 + h / 2.0 * k1.0, y.1 + h / 2.0 * k1.1));
        let k3 = f((y.0 + h / 2.0 * k2.0, y.1 + h / 2.0 * k2.1));
        let k4 = f((y.0 + h * k3.0, y.1 + h * k3.1));
        (
            y.0 + h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0),
            y.1 + h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1),
        )
    };
    // parting: the first zero of this function of the closed state
    let part = |y: (f64, f64)| match part_at_theta {
        Some(a) => y.0 - a,
        None => r * y.1 * y.1 - g * y.0.cos(),
    };
    let mut out = String::from("t,theta,theta_dot,y2,mode\n");
    let per_row = 64; // 1/64 per row, 1/4096 per step
    let mut y = (0.05f64, 0.0f64);
    let mut n = 0usize;
    let mut parted: Option<(f64, (f64, f64))> = None;
    loop {
        let t = n as f64 * h;
        if t > t_last {
            break;
        }
        if parted.is_none() {
            let next = rk4(y, h);
            if part(y) < 0.0 && part(next) >= 0.0 {
                // the zero inside the step, by bisection on RK4 sub-steps
                let (mut a, mut b) = (0.0, h);
                for _ in 0..60 {
                    let m = 0.5 * (a + b);
                    if part(rk4(y, m)) < 0.0 {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                parted = Some((t + b, rk4(y, b)));
            }
        }
        if n % per_row == 0 {
            let t_text = format!("{}", (n / per_row) as f64 / 64.0);
            match parted {
                Some((tp, (th, thd))) if t >= tp => {
                    // the flight from the parting state
                    let w1 = thd * (1.0 - 2.0 * th.cos()) / 3.0;
                    let (vx2, vy2) = (w1 + r * thd * th.cos(), -r * thd * th.sin());
                    let tau = t - tp;
                    let dx = r * th.sin() + (vx2 - w1) * tau;
                    let dy = r * th.cos() + vy2 * tau - 0.5 * g * tau * tau;
                    let (dvx, dvy) = (vx2 - w1, vy2 - g * tau);
                    let theta = dx.atan2(dy);
                    let theta_dot = (dy * dvx - dx * dvy) / (dx * dx + dy * dy);
                    writeln!(
                        out,
                        "{t_text},{theta:e},{theta_dot:e},{:e},flight",
                        1.0 + dy
                    )
                    .unwrap();
                }
                _ => {
                    let y2 = 1.0 + r * y.0.cos();
                    writeln!(out, "{t_text},{:e},{:e},{y2:e},stick/stick", y.0, y.1).unwrap();
                }
            }
        }
        if parted.is_none() || t < parted.unwrap().0 {
            y = rk4(y, h);
        }
        n += 1;
    }
    assert!(parted.is_some(), "the engine never parts");
    out
}

#[test]
fn a_candidate_that_parts_at_the_branch_point_is_judged_on_the_part_branch() {
    // up to t = 7.0, before the part branch's first impact (7.084)
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cand.csv");
    std::fs::write(&path, parting_engine(None, 7.0)).unwrap();
    let tol = ["--rtol", "1e-7", "--atol", "1e-9", "--format", "json"];
    let args = |extra: &[&'static str]| {
        let mut a = vec!["--case", "main_roll_roll"];
        a.extend_from_slice(&tol);
        a.extend_from_slice(extra);
        a
    };
    let out = check_file(&path, &args(&[]));
    let v = json(&out);
    assert_eq!(out.status.code(), Some(0), "{v:#}");
    assert_eq!(v["branch"]["requested"], "auto");
    assert_eq!(v["branch"]["followed"], "part", "{}", v["branch"]);
    assert_eq!(v["branch"]["parting"]["found_by"], "mode");
    // θ* as `cylroll separation` reports it (theta_indeterminate), inside the
    // candidate's bracket: the event is matched with no error
    let sep = Command::cargo_bin("cylroll")
        .unwrap()
        .args(["separation", "--params", "golden/cases/main_roll_roll.toml"])
        .args(["--digits", "20", "--format", "json"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let sep = json(&sep);
    let star = sep["theta_indeterminate"].as_str().unwrap();
    assert_eq!(v["branch"]["window"]["theta_indeterminate"], star);
    let star: f64 = star.parse().unwrap();
    let theta = &v["branch"]["parting"]["theta"];
    let (a, b): (f64, f64) = (
        theta[0].as_str().unwrap().parse().unwrap(),
        theta[1].as_str().unwrap().parse().unwrap(),
    );
    assert!(a < star && star < b, "{a} {star} {b}");
    let ev = v["events"]
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e["mode"] == "flight" && e["passed"] == true)
        .unwrap_or_else(|| panic!("{}", v["events"]));
    assert_eq!(ev["error"], "0.000e0");
    // the same rows judged against the closed branch fail in the flight
    let out = check_file(&path, &args(&["--branch", "stay"]));
    assert_eq!(out.status.code(), Some(1));
    let v = json(&out);
    let last = v["phases"].as_array().unwrap().last().unwrap().clone();
    assert_eq!(last["mode"], "flight");
    assert_eq!(last["passed"], false);
    // and --branch part agrees with auto
    let out = check_file(&path, &args(&["--branch", "part"]));
    assert_eq!(out.status.code(), Some(0));
}

#[test]
fn a_candidate_that_parts_inside_the_window_or_before_it_is_judged_so() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cand.csv");
    // inside the window [0.963, 1.048], at θ = 1: the reference that parts at
    // the angle its flight rows fit, found to ~1e-12, and it passes
    std::fs::write(&path, parting_engine(Some(1.0), 7.0)).unwrap();
    let out = check_file(
        &path,
        &[
            "--case",
            "main_roll_roll",
            "--rtol",
            "1e-7",
            "--atol",
            "1e-9",
            "--format",
            "json",
        ],
    );
    let v = json(&out);
    assert_eq!(out.status.code(), Some(0), "{v:#}");
    let followed = v["branch"]["followed"].as_str().unwrap();
    let at: f64 = followed.strip_prefix("part-at ").unwrap().parse().unwrap();
    assert!((at - 1.0).abs() < 1e-9, "{followed}");
    assert!(v["branch"]["why"]
        .as_str()
        .unwrap()
        .contains("inside the window"));
    // before the branch point: not lawful, a failure whatever the values
    std::fs::write(&path, parting_engine(Some(0.8), 6.0)).unwrap();
    let out = check_file(
        &path,
        &[
            "--case",
            "main_roll_roll",
            "--rtol",
            "1",
            "--atol",
            "1",
            "--format",
            "json",
        ],
    );
    assert_eq!(out.status.code(), Some(1));
    let v = json(&out);
    assert_eq!(v["branch"]["lawful"], false);
    assert!(
        v["branch"]["why"]
            .as_str()
            .unwrap()
            .contains("before the branch point"),
        "{}",
        v["branch"]
    );
}

#[test]
fn rows_after_the_end_of_the_model_are_reported_not_refused() {
    // main_roll_roll ends with the impact at t = 7.0982
    let csv = "t,theta\n0,0.05\n7.5,1\n8,1\n";
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cand.csv");
    std::fs::write(&path, csv).unwrap();
    let out = check_file(&path, &["--case", "main_roll_roll", "--format", "json"]);
    assert_eq!(out.status.code(), Some(0));
    let v = json(&out);
    assert_eq!(v["rows"], "3");
    assert_eq!(v["rows_after_end"], "2");
    assert_eq!(v["first_after_end"]["row"], "2");
    assert_eq!(v["first_after_end"]["t"], "7.5");
    assert_eq!(v["end"]["event"], "impact");
    let out = check_file(&path, &["--case", "main_roll_roll"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("2 row(s) after the end of the model (the impact at t = 7.098"),
        "{text}"
    );
    // refused on request, naming the file and the row
    let out = check_file(&path, &["--case", "main_roll_roll", "--past-end", "refuse"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("cand.csv") && err.contains("row 2 (line 3): t = 7.5 is after the end"),
        "{err}"
    );
    // a blank line counts in the line named, not in the rows
    std::fs::write(&path, "t,theta\n0,0.05\n\n7.5,1\n").unwrap();
    let out = check_file(&path, &["--case", "main_roll_roll", "--past-end", "refuse"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("row 2 (line 4): t = 7.5 is after the end"),
        "{err}"
    );
}

#[test]
fn an_rtol_finer_than_the_oracle_digits_is_refused_and_a_verdict_on_its_bound_left_open() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cand.csv");
    std::fs::write(&path, "t,theta\n0,0.05\n").unwrap();
    for (args, needle) in [
        (vec!["--rtol", "1e-19"], "invalid rtol = \"1e-19\""),
        (
            vec!["--rtol", "1e-25", "--digits", "20"],
            "give --digits 27 or more",
        ),
        (
            vec!["--tol", "theta=1e-30"],
            "invalid tol = \"theta=1e-30\"",
        ),
    ] {
        let mut a = vec!["--case", "main_roll_roll"];
        a.extend(args);
        let out = check_file(&path, &a);
        assert_eq!(out.status.code(), Some(2), "{a:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains(needle) && err.contains("20 significant digits"),
            "{err}"
        );
    }
    // the same rtol with the digits to judge it
    let out = check_file(
        &path,
        &[
            "--case",
            "main_roll_roll",
            "--rtol",
            "1e-25",
            "--digits",
            "27",
        ],
    );
    assert_eq!(out.status.code(), Some(0));
    // a zero tolerance: the oracle's value is known to within its error
    // bound only, so equality is a verdict left open (exit 3), not a pass
    let out = check_file(
        &path,
        &[
            "--case",
            "main_roll_roll",
            "--rtol",
            "0",
            "--atol",
            "0",
            "--format",
            "json",
        ],
    );
    assert_eq!(out.status.code(), Some(3));
    let v = json(&out);
    assert_eq!(v["verdict"], "undecided");
    assert_eq!(v["first_undecided"]["row"], "1");
    assert_eq!(v["first_failure"], serde_json::Value::Null);
}

/// Tolerances that cannot be held, and a `mode` cell that is not a mode,
/// are refused (exit 2, one line, nothing on standard output): `--rtol
/// 1e-400` was read as 0 and the check passed, `banana` was judged as a
/// change of mode. And a row in another mode, or a zero limit (`--rtol 0
/// --atol 0`, an undecided verdict), has no err/limit: printed `-` (it was
/// `inf` in the text, JSON and CSV reports).
#[test]
fn unjudgeable_tolerances_and_unknown_modes_are_refused() {
    let good = golden_csv("main_mu_0_3");
    for (args, needle) in [
        (&["--rtol", "1e-400"][..], "--rtol"),
        (&["--atol", "1e-320"][..], "--atol"),
        (&["--tol", "theta=1e-400"][..], "1e-400"),
    ] {
        let mut all = vec!["--case", "main_mu_0_3"];
        all.extend_from_slice(args);
        let out = check_file(&good, &all);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
    // zero written as zero is a tolerance (atol alone, rtol alone): judged,
    // not refused (atol 0 left the flight's F1, "0 within 2.8e-48",
    // undecided: exit 3; a structural zero is exact now, and the oracle's
    // own table passes)
    for (args, code) in [(&["--rtol", "0"][..], 0), (&["--atol", "0e5"][..], 0)] {
        let mut all = vec!["--case", "main_mu_0_3"];
        all.extend_from_slice(args);
        let out = check_file(&good, &all);
        assert_eq!(
            out.status.code(),
            Some(code),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let dir = edited("main_mu_0_3", 5, "mode", |_| "banana".into());
    let out = check_file(&dir.path().join("cand.csv"), &["--case", "main_mu_0_3"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(out.stdout.is_empty());
    assert!(
        err.contains("row 5") && err.contains("\"banana\" is not a mode"),
        "{err}"
    );
    // a row in another mode, a zero limit: no `inf` in any format
    let dir = edited("main_mu_0_3", 5, "mode", |_| "flight".into());
    let cand = dir.path().join("cand.csv");
    for (args, code) in [(&[][..], 1), (&["--rtol", "0", "--atol", "0"][..], 3)] {
        for fmt in ["text", "json", "csv"] {
            let mut all = vec!["--case", "main_mu_0_3", "--format", fmt];
            all.extend_from_slice(args);
            let out = check_file(if code == 1 { &cand } else { &good }, &all);
            // a zero limit: a golden row's 20 digits differ from the oracle's
            // (fail) or lie within its bound (undecided)
            let got = out.status.code();
            assert!(
                got == Some(code) || (code == 3 && got == Some(1)),
                "{args:?} {fmt}: {got:?}"
            );
            let text = String::from_utf8_lossy(&out.stdout);
            assert!(!text.contains("inf"), "{args:?} {fmt}: {text}");
        }
    }
}

/// A lawful parting inside the window, on a grid whose parting bracket
/// holds θ* or θs as well: `--branch auto` fits the parting in the bracket
/// and passes the candidate, as on finer and coarser grids. It was taken
/// for that end's branch unseen (stay for θs, part for θ*) and failed: the
/// verdict on one lawful motion depended on the grid. The oracle's own
/// rows of each branch pass on every grid, followed by that branch.
#[test]
fn a_lawful_parting_passes_on_every_grid() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cand.csv");
    let traj = |branch: &[&str], steps: &str| {
        let out = Command::cargo_bin("cylroll")
            .unwrap()
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .args(["trajectory", "--params", "golden/cases/main_roll_roll.toml"])
            .args(branch)
            .args([
                "--t-end", "7.08", "--steps", steps, "--format", "csv", "--digits", "25",
            ])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0));
        std::fs::write(&path, &out.stdout).unwrap();
    };
    // θ* ≈ 0.963, θs ≈ 1.048: grids of 35 and 70 steps bracket the parting
    // at θ = 1 with θs, at 0.97 with θ* (35 steps)
    for (branch, followed) in [
        (&["--part-at", "1"][..], "part-at"),
        (&["--part-at", "0.97"][..], "part-at"),
        (&["--branch", "stay"][..], "stay"),
        (&["--branch", "part"][..], "part"),
    ] {
        for steps in ["7", "35", "70", "700"] {
            traj(branch, steps);
            let out = check_file(&path, &["--case", "main_roll_roll", "--format", "json"]);
            let v = json(&out);
            assert_eq!(
                out.status.code(),
                Some(0),
                "{branch:?} {steps} steps: {}",
                v["branch"]
            );
            let f = v["branch"]["followed"]
                .as_str()
                .unwrap_or_default()
                .to_string();
            let same = if followed == "part-at" {
                f.starts_with("part-at ")
            } else {
                f == followed
            };
            assert!(same, "{branch:?} {steps}: {}", v["branch"]);
        }
    }
}

/// A schema-1 φ2 is judged in the reference's gauge (φ2 + r1 θ0 / r2), and
/// its failure quotes it so, with the file's value beside: the reference's
/// own file read as schema 1 fails by r1 θ0 / r2 = 0.1 at its first row,
/// and the message showed "candidate 0 vs oracle 0" for an error of 0.1.
#[test]
fn a_schema_1_failure_quotes_phi2_in_the_gauge_it_was_judged_in() {
    let out = check_file(
        &golden_csv("main_mu_0_3"),
        &["--case", "main_mu_0_3", "--schema", "1"],
    );
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains(
            "column phi2: candidate 0.10000000000000000 (schema 1: 0) vs oracle 0; |err| > 1.000e-10"
        ),
        "{text}"
    );
}

/// A candidate whose header is the first schema's full column list (the 13
/// columns the golden data's README listed) is judged as schema 2 unless
/// `--schema 1` is given: the oracle's own table in those columns failed on
/// φ2 in every row (read as schema 1, shifted by r1 θ0/r2 = 0.1), and
/// Python's `check` had no way out. The same table in the first schema's
/// gauge (φ2 − r1 θ0/r2, written independently here) fails without
/// `--schema 1`, with a note that names it, and passes with it.
#[test]
fn a_schema_1_header_is_judged_as_schema_2_unless_asked() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cand.csv");
    let table = oracle_csv(
        "mujoco_main",
        &[
            "--t-end",
            "5.2",
            "--steps",
            "52",
            "--digits",
            "25",
            "--columns",
            "t,theta,theta_dot,theta_ddot,phi1,phi2,x1,x2,y2,F1,N1,F21,N12",
        ],
    );
    std::fs::write(&path, &table).unwrap();
    let out = check_file(&path, &["--case", "mujoco_main"]);
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert_eq!(out.status.code(), Some(0), "{text}");
    assert!(!text.contains("NOTE"), "{text}");
    // φ2 in the first schema's gauge: r1 θ0 / r2 = 1 · (1/10) / 1 below
    let mut lines = table.lines();
    let header = lines.next().unwrap();
    let at = header.split(',').position(|c| c == "phi2").unwrap();
    let mut v1 = format!("{header}\n");
    for l in lines {
        let mut cells: Vec<String> = l.split(',').map(str::to_string).collect();
        let phi2: f64 = cells[at].parse().unwrap();
        cells[at] = format!("{:.17e}", phi2 - 0.1);
        v1 += &(cells.join(",") + "\n");
    }
    std::fs::write(&path, v1).unwrap();
    let out = check_file(&path, &["--case", "mujoco_main"]);
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(text.contains("column phi2"), "{text}");
    assert!(
        text.contains("NOTE: the header is a full column list of the first golden schema")
            && text.contains("--schema 1"),
        "{text}"
    );
    let out = check_file(
        &path,
        &["--case", "mujoco_main", "--schema", "1", "--rtol", "1e-14"],
    );
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert_eq!(out.status.code(), Some(0), "{text}");
}

/// Without a `mode` or `N12` column (t and θ alone, as an engine's test
/// often writes) `--branch auto` follows the branch the rows took: it fell
/// back to the closed branch, and a candidate that parts at θ* (PyBullet's
/// branch) failed after its parting. And a parting inside the window is
/// fitted to binary64 resolution: an exact candidate parting at
/// 1.0123456789012345 failed `--rtol 1e-10` on its velocities against the
/// fitted angle rounded to 10 digits.
#[test]
fn auto_finds_the_branch_from_theta_alone_and_fits_a_parting_to_binary64() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cand.csv");
    for (branch, columns, followed, tight) in [
        (&["--branch", "part"][..], "t,theta", "part", false),
        (&["--branch", "stay"][..], "t,theta", "stay", false),
        (
            &["--part-at", "1.0123456789012345"][..],
            "t,theta",
            "part-at 1.01234567890123",
            false,
        ),
        (
            &["--part-at", "1.0123456789012345"][..],
            "t,theta,theta_dot,x1_dot,x2,mode",
            "part-at 1.01234567890123",
            true,
        ),
    ] {
        let grid = [
            "--t-end",
            "5.9",
            "--steps",
            "59",
            "--digits",
            "25",
            "--columns",
            columns,
        ];
        std::fs::write(
            &path,
            oracle_csv("mujoco_main", &[branch, &grid[..]].concat()),
        )
        .unwrap();
        let mut args = vec!["--case", "mujoco_main", "--format", "json"];
        if tight {
            args.extend_from_slice(&["--rtol", "1e-10", "--atol", "1e-12"]);
        }
        let out = check_file(&path, &args);
        let v = json(&out);
        assert_eq!(out.status.code(), Some(0), "{branch:?} {columns}: {v}");
        let f = v["branch"]["followed"].as_str().unwrap_or_default();
        assert!(
            f.starts_with(followed),
            "{branch:?} {columns}: {}",
            v["branch"]
        );
    }
}

/// A row's `mode` within `--event-tol` of the reference's change of mode
/// may read the mode on either side: a fine table whose first flight row
/// still reads stick/stick (the separation 2.4e-5 rad of θ before it)
/// failed on that row while its separation event passed. Far from the
/// event the wrong mode still fails.
#[test]
fn a_mode_one_row_late_at_an_event_is_judged_by_the_event() {
    let dir = tempfile::tempdir().unwrap();
    let table = oracle_csv(
        "mujoco_main",
        &[
            "--t-end",
            "5.5",
            "--steps",
            "5500",
            "--digits",
            "20",
            "--columns",
            "t,theta,mode",
        ],
    );
    let relabel = |n: usize| {
        let mut k = 0;
        let mut s = String::new();
        for l in table.lines() {
            if l.ends_with(",flight") && k < n {
                k += 1;
                s += &l.replace(",flight", ",stick/stick");
            } else {
                s += l;
            }
            s.push('\n');
        }
        assert_eq!(k, n);
        s
    };
    let path = dir.path().join("late.csv");
    std::fs::write(&path, relabel(1)).unwrap();
    let out = check_file(&path, &["--case", "mujoco_main"]);
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert_eq!(out.status.code(), Some(0), "{text}");
    std::fs::write(&path, relabel(200)).unwrap();
    let out = check_file(&path, &["--case", "mujoco_main"]);
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(
        text.contains("column mode: candidate stick/stick vs oracle flight"),
        "{text}"
    );
}

/// In the flight F1 is 0 by structure where the floor does not slide
/// (rolling alone, held, frictionless): an exact zero, as F21 and N12 are;
/// so are a held cylinder 1's position and rates, and φ1, φ̇1 where both
/// contacts are frictionless and ω0 = 0.
/// It was "0 within 2.8e-48", so a purely relative check (`--atol 0`) of
/// the oracle's own table was undecided at every --digits.
#[test]
fn the_flight_floor_force_is_an_exact_zero_and_atol_0_decides() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("own.csv");
    for case in ["mujoco_main", "fixed_roll", "slip_slip"] {
        let params = format!("golden/cases/{case}.toml");
        let sep = Command::cargo_bin("cylroll")
            .unwrap()
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .args(["separation", "--params", &params, "--format", "csv"])
            .args(["--digits", "12"])
            .output()
            .unwrap();
        let sep = String::from_utf8(sep.stdout).unwrap();
        let value = |k: &str| -> f64 {
            let l = sep
                .lines()
                .find(|l| l.starts_with(&format!("{k},")))
                .unwrap();
            l.split(',').nth(1).unwrap().parse().unwrap()
        };
        // midway through the flight
        let t = format!("{:.6}", (value("t_s") + value("t_impact")) / 2.0);
        let out = Command::cargo_bin("cylroll")
            .unwrap()
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .args(["trajectory", "--params", &params])
            .args([
                "--times",
                &format!("0.5,{t}"),
                "--digits",
                "25",
                "--format",
                "json",
            ])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0));
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let last = &v["rows"][1];
        assert_eq!(last["mode"], "flight", "{case}: {last}");
        assert_eq!(last["F1"], "0", "{case}: {last}");
        // and where cylinder 1 is held (fixed_roll: x1, phi1 and their rates
        // read "0 within 1.7e-55") or nothing ever spins it (slip_slip from
        // rest: phi1, phi1_dot), those are exact zeros too
        assert!(last.get("zero_within").is_none(), "{case}: {last}");
    }
    let table = oracle_csv(
        "mujoco_main",
        &["--t-end", "5.9", "--steps", "59", "--digits", "25"],
    );
    std::fs::write(&path, table).unwrap();
    let out = check_file(
        &path,
        &["--case", "mujoco_main", "--atol", "0", "--digits", "40"],
    );
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert_eq!(out.status.code(), Some(0), "{text}");
}

/// Small refusals say what is wrong: a file whose lines end in CR alone
/// (it read as one header: `unknown column "theta\r0"`), an unknown key in
/// `--params` named as params (it said `invalid case`), and an rtol too
/// tight for `--digits 1` offers more digits only (it offered "an rtol of
/// at least 1e1").
#[test]
fn small_refusals_of_check_name_what_is_wrong() {
    let dir = tempfile::tempdir().unwrap();
    let refusal = |path: &std::path::Path, args: &[&str]| {
        let out = check_file(path, args);
        assert_eq!(out.status.code(), Some(2));
        assert!(out.stdout.is_empty());
        String::from_utf8_lossy(&out.stderr).to_string()
    };
    let cr = dir.path().join("cr.csv");
    std::fs::write(&cr, "t,theta\r0,0.1\r1,0.2\r").unwrap();
    let err = refusal(&cr, &["--case", "mujoco_main"]);
    assert!(err.contains("lines end in CR alone"), "{err}");
    let crlf = dir.path().join("crlf.csv");
    std::fs::write(&crlf, "t,theta\r\n0,0.1\r\n").unwrap();
    assert_eq!(
        check_file(&crlf, &["--case", "mujoco_main"]).status.code(),
        Some(0)
    );
    let params = dir.path().join("p.toml");
    std::fs::write(&params, "theta0 = \"1/10\"\nfoo = 1\n").unwrap();
    let err = refusal(&crlf, &["--params", params.to_str().unwrap()]);
    assert!(err.starts_with("error: invalid params (in "), "{err}");
    assert!(err.contains("\"foo\": unknown key"), "{err}");
    let err = refusal(&crlf, &["--case", "mujoco_main", "--digits", "1"]);
    assert!(
        err.contains("give --digits 10 or more") && !err.contains("or an rtol"),
        "{err}"
    );
    let err = refusal(&crlf, &["--case", "mujoco_main", "--digits", "5"]);
    assert!(err.contains("or an rtol of at least 1e-3"), "{err}");
}

/// An unsigned `slip` in a candidate's mode cell matches the reference's
/// slide either way (the golden table with its `slip+` and `slip-` written
/// `slip` failed every sliding row and its slip onsets).
#[test]
fn an_unsigned_slip_matches_a_slide_either_way() {
    let table = std::fs::read_to_string(golden_csv("heavy_upper_restick")).unwrap();
    assert!(table.contains("slip+") && table.contains("slip-"));
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("unsigned.csv");
    std::fs::write(
        &path,
        table.replace("slip+", "slip").replace("slip-", "slip"),
    )
    .unwrap();
    let out = check_file(&path, &["--case", "heavy_upper_restick"]);
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert_eq!(out.status.code(), Some(0), "{text}");
    // a wrong state is still wrong
    std::fs::write(&path, table.replace("slip-/slip+", "slip-/stick")).unwrap();
    let code = check_file(&path, &["--case", "heavy_upper_restick"])
        .status
        .code();
    assert_eq!(code, Some(1));
}

/// The fitted parting of low-precision tables (a review's cases): a fit a
/// hair inside θs, rounded to the candidate's resolution, fell past it and
/// the check was refused ("invalid part-at", exit 2, for a flag never
/// given); a parting 1.0003e-3 before θs was dropped once the refined fit
/// came within event-tol of θs, and the table failed against stay. And a
/// signed slide against the reference's unsigned frictionless one is not
/// taken as matching (s12 > 0 written slip- passed).
#[test]
fn low_precision_partings_fit_inside_the_window_and_signs_still_count() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cand.csv");
    let table = |args: &[&str]| {
        let csv = oracle_csv("main_roll_roll", &[&["--t-end", "7.06"][..], args].concat());
        std::fs::write(&path, csv).unwrap();
    };
    table(&["--steps", "35", "--digits", "7", "--columns", "t,theta"]);
    let args = [
        "--case",
        "main_roll_roll",
        "--rtol",
        "1e-5",
        "--atol",
        "1e-6",
    ];
    let out = check_file(&path, &args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    table(&[
        "--part-at",
        "1.047",
        "--steps",
        "700",
        "--digits",
        "6",
        "--columns",
        "t,theta,x2,mode",
    ]);
    let args = [
        "--case",
        "main_roll_roll",
        "--rtol",
        "1e-5",
        "--atol",
        "1e-5",
    ];
    let out = check_file(&path, &[&args[..], &["--format", "json"]].concat());
    let v = json(&out);
    assert_eq!(out.status.code(), Some(0), "{}", v["branch"]);
    let f = v["branch"]["followed"].as_str().unwrap_or_default();
    assert!(f.starts_with("part-at 1.0470"), "{}", v["branch"]);
    let golden = std::fs::read_to_string(golden_csv("roll_slip")).unwrap();
    assert!(golden.contains("stick/slip\n"));
    std::fs::write(&path, golden.replace("stick/slip\n", "stick/slip-\n")).unwrap();
    assert_eq!(
        check_file(&path, &["--case", "roll_slip"]).status.code(),
        Some(1)
    );
}

/// A line too long to read is refused naming its data row and line (or
/// the header), as every refusal names them (it said only "has a line
/// longer than 65536 bytes").
#[test]
fn a_line_too_long_is_named_by_row_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("long.csv");
    std::fs::write(&p, format!("t,theta\n0,0.1\n\n1,{}\n", "1".repeat(70_000))).unwrap();
    let out = check_file(&p, &["--case", "main_mu_0_3"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("row 2 (line 4) is longer than 65536 bytes"),
        "{err}"
    );
    std::fs::write(&p, format!("t,{}\n0,0.1\n", "x".repeat(70_000))).unwrap();
    let err =
        String::from_utf8_lossy(&check_file(&p, &["--case", "main_mu_0_3"]).stderr).to_string();
    assert!(err.contains("the header row (line 1) is longer"), "{err}");
}

/// An event just past the candidate's bracket (its last row 1e-16 s before
/// the separation, already in flight) is outside it: judged by the times as
/// written, not in binary64, where it was "inside the candidate's bracket"
/// with error 0 and passed at `--event-tol 0`.
#[test]
fn an_event_a_hair_past_the_bracket_is_not_inside_it() {
    use cylroll::exact::Exact;
    let cyl = || {
        let mut c = Command::cargo_bin("cylroll").unwrap();
        c.current_dir(env!("CARGO_MANIFEST_DIR"));
        c
    };
    let case = "golden/cases/main_mu_0_3.toml";
    let sep = cyl()
        .args(["separation", "--params", case, "--digits", "40"])
        .output()
        .unwrap();
    let sep = String::from_utf8_lossy(&sep.stdout).to_string();
    let ts = sep
        .lines()
        .find_map(|l| l.strip_prefix("t_s "))
        .and_then(|l| l.split('=').nth(1))
        .and_then(|l| l.split_whitespace().next())
        .unwrap()
        .to_string();
    let before = |k: u32| {
        let q = Exact::parse("t", &ts, false).unwrap().coef
            - rug::Rational::from((k, rug::Integer::from(rug::Integer::u_pow_u(10, 16))));
        rug::Float::with_val(400, q).to_string_radix(10, Some(60))
    };
    let after = {
        let q = Exact::parse("t", &ts, false).unwrap().coef + rug::Rational::from((1, 1000));
        rug::Float::with_val(400, q).to_string_radix(10, Some(60))
    };
    let times = format!("0,{},{},{after}", before(2), before(1));
    let out = cyl()
        .args(["trajectory", "--params", case, "--times", &times])
        .args([
            "--format",
            "csv",
            "--digits",
            "25",
            "--columns",
            "t,theta,mode",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    // the third row enters the flight 1e-16 s early (the fourth is in it)
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let (head, _) = lines[3].rsplit_once(',').unwrap();
    lines[3] = format!("{head},flight");
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("ev.csv");
    std::fs::write(&p, lines.join("\n") + "\n").unwrap();
    let out = check_file(&p, &["--case", "main_mu_0_3", "--event-tol", "0"]);
    let report = String::from_utf8_lossy(&out.stdout);
    let sep_line = report
        .lines()
        .find(|l| l.starts_with("separation"))
        .unwrap_or_else(|| panic!("{report}"));
    assert!(
        sep_line.contains("FAIL (the candidate's bracket is before the event by less than"),
        "{sep_line}"
    );
    assert_eq!(out.status.code(), Some(1), "{report}");
}

/// A row at the end of the model at its time as the oracle prints it (the
/// impact's t to 20 digits, rounded to nearest: past the end by less than
/// half a unit of the 20th digit, beyond the end's error bound) is the state
/// at the end, as `trajectory` answers it: judged, not refused as after the
/// end (it was, with a message quoting the same number as the end).
#[test]
fn a_row_at_the_end_as_printed_is_judged_not_refused() {
    let cyl = run::stdout_ok;
    let case = [
        "--params",
        "golden/cases/mujoco_main.toml",
        "--digits",
        "20",
    ];
    let sep = cyl(&[&["separation", "--format", "csv"][..], &case].concat());
    let ti = sep
        .lines()
        .find_map(|l| l.strip_prefix("t_impact,"))
        .and_then(|l| l.split(',').next())
        .unwrap()
        .to_string();
    let times = format!("0,1,5,{ti}");
    let csv = cyl(&[
        &[
            "trajectory",
            "--times",
            &times,
            "--columns",
            "t,theta,mode",
            "--format",
            "csv",
        ][..],
        &case,
    ]
    .concat());
    assert!(csv.lines().last().unwrap().ends_with(",flight"), "{csv}");
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("end.csv");
    std::fs::write(&path, &csv).unwrap();
    let out = check_file(&path, &["--case", "mujoco_main", "--past-end", "refuse"]);
    assert!(
        out.status.success(),
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("phase 2 flight       rows 4-4"), "{text}");
}
