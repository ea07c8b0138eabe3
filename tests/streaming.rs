//! Long trajectories: computed and printed in blocks of rows (memory
//! bounded, the same bytes as one block, nothing printed on a refusal), and
//! `--columns` (only the columns asked, with the digits of the full table).

use assert_cmd::Command;
use std::process::Stdio;

fn cyl() -> Command {
    Command::cargo_bin("cylroll").unwrap()
}

/// stdout, stderr and exit code of the command with `block` rows per block.
fn run(args: &[&str], block: Option<usize>) -> (String, String, i32) {
    run_on(args, block, None)
}

/// [`run`] with `threads` blocks computed at once (`CYLROLL_THREADS`).
fn run_on(args: &[&str], block: Option<usize>, threads: Option<usize>) -> (String, String, i32) {
    let mut c = cyl();
    c.args(args);
    if let Some(b) = block {
        c.env("CYLROLL_BLOCK_ROWS", b.to_string());
    }
    if let Some(n) = threads {
        c.env("CYLROLL_THREADS", n.to_string());
    }
    let out = c.output().unwrap();
    (
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
        out.status.code().unwrap_or(-1),
    )
}

const CASES: [&[&str]; 3] = [
    &["--theta0", "1/10"],
    &["--theta0", "1/10", "--mu", "0.3"],
    &["--theta0", "1/10", "--mu", "10", "--branch", "part"],
];

#[test]
fn blocks_print_the_same_bytes_as_one_block() {
    for case in CASES {
        for format in ["text", "json", "csv"] {
            let mut args = vec!["trajectory"];
            args.extend_from_slice(case);
            args.extend(["--t-end", "5.7", "--steps", "23", "--digits", "18"]);
            args.extend(["--format", format]);
            let one = run(&args, None);
            assert_eq!(one.2, 0, "{args:?}: {}", one.1);
            // blocks of 4 rows: 6 blocks, the last one short, computed one
            // at a time, and 2 and 3 at once on threads of their own
            let blocks = run(&args, Some(4));
            assert_eq!(one, blocks, "{args:?}");
            for n in [1, 2, 3] {
                assert_eq!(
                    one,
                    run_on(&args, Some(4), Some(n)),
                    "{args:?} on {n} threads"
                );
            }
            if format == "json" {
                let v: serde_json::Value = serde_json::from_str(&blocks.0).unwrap();
                assert_eq!(v["rows"].as_array().unwrap().len(), 24);
            }
        }
    }
}

#[test]
fn a_time_past_the_end_is_refused_by_name_before_any_row_is_printed() {
    // the friction case ends at its first impact, t = 5.838...: the first
    // time past it is 5.9 (the 60th of 0, 0.1, ..., 6.5)
    let times: Vec<String> = (0..=65).map(|i| format!("{}", i as f64 / 10.0)).collect();
    let times = times.join(",");
    let args = [
        "trajectory",
        "--theta0",
        "1/10",
        "--mu",
        "0.3",
        "--digits",
        "12",
        "--times",
        &times,
    ];
    let one = run(&args, None);
    let blocks = run(&args, Some(7));
    assert_eq!(one.2, 2, "{}", one.1);
    assert_eq!(one, blocks);
    assert!(one.0.is_empty(), "partial output: {}", one.0);
    assert!(one.1.contains("\"5.9\""), "{}", one.1);
    assert_eq!(one.1.trim().lines().count(), 1, "{}", one.1);
}

/// The rows of a CSV table as maps column -> text.
fn csv_rows(text: &str) -> Vec<Vec<(String, String)>> {
    let mut lines = text.lines();
    let head: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    lines
        .map(|l| {
            head.iter()
                .cloned()
                .zip(l.split(',').map(String::from))
                .collect()
        })
        .collect()
}

#[test]
fn the_columns_asked_carry_the_digits_of_the_full_table() {
    for case in CASES {
        let mut base = vec!["trajectory"];
        base.extend_from_slice(case);
        base.extend([
            "--times",
            "0,0.5,2,3.25,4.4,4.9,5.2,5.5",
            "--digits",
            "25",
            "--format",
            "csv",
        ]);
        let full = run(&base, None);
        assert_eq!(full.2, 0, "{base:?}: {}", full.1);
        let full = csv_rows(&full.0);
        // theta alone (the route that computes no force), and a subset in
        // an order of its own
        for cols in ["t,theta", "theta", "mode,theta,N12,t,work", "F21,theta_dot"] {
            let mut args = base.clone();
            args.extend(["--columns", cols]);
            let part = run(&args, None);
            assert_eq!(part.2, 0, "{args:?}: {}", part.1);
            let part = csv_rows(&part.0);
            assert_eq!(part.len(), full.len());
            let names: Vec<&str> = cols.split(',').collect();
            for (p, f) in part.iter().zip(&full) {
                let got: Vec<&str> = p.iter().map(|(k, _)| k.as_str()).collect();
                assert_eq!(got, names, "column order");
                for (k, v) in p {
                    let want = &f.iter().find(|(c, _)| c == k).unwrap().1;
                    assert_eq!(v, want, "{case:?} {cols}: {k}");
                }
            }
        }
    }
}

#[test]
fn unknown_or_repeated_columns_are_refused_by_name() {
    for (cols, says) in [
        (
            "theta,foo",
            "invalid columns = \"foo\": must be among t, theta",
        ),
        (
            "theta,t,theta",
            "invalid columns = \"theta\": must be named only once",
        ),
        ("", "invalid columns = \"\""),
    ] {
        let (out, err, code) = run(
            &[
                "trajectory",
                "--theta0",
                "0.1",
                "--times",
                "1",
                "--columns",
                cols,
            ],
            None,
        );
        assert_eq!(code, 2, "{cols}: {err}");
        assert!(out.is_empty());
        assert!(err.contains(says), "{cols}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
    }
}

/// The peak resident memory (kB) of the command, its stdout counted (the
/// child is reaped by `wait4`, which also gives its resource usage).
#[allow(clippy::zombie_processes)]
fn peak_kb(args: &[&str], block: usize, threads: usize) -> (i64, usize) {
    let bin = assert_cmd::cargo::cargo_bin("cylroll");
    let mut child = std::process::Command::new(bin)
        .args(args)
        .env("CYLROLL_BLOCK_ROWS", block.to_string())
        .env("CYLROLL_THREADS", threads.to_string())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let pid = child.id() as libc::pid_t;
    let mut out = child.stdout.take().unwrap();
    let reader = std::thread::spawn(move || {
        let mut n = 0usize;
        let mut buf = vec![0u8; 1 << 16];
        loop {
            match std::io::Read::read(&mut out, &mut buf) {
                Ok(0) | Err(_) => return n,
                Ok(k) => n += k,
            }
        }
    });
    let mut status = 0;
    let mut ru: libc::rusage = unsafe { std::mem::zeroed() };
    // SAFETY: wait4 on our own child, with valid pointers
    let r = unsafe { libc::wait4(pid, &mut status, 0, &mut ru) };
    assert_eq!(r, pid);
    assert!(libc::WIFEXITED(status) && libc::WEXITSTATUS(status) == 0);
    (ru.ru_maxrss, reader.join().unwrap())
}

#[test]
fn memory_stays_bounded_however_many_rows() {
    // Held at once, the rows of every column took ~9 kB each: 48000 rows
    // over 400 MB. In blocks of 500 the process holds one block at a time
    // (or two at once, each on its thread with its own heap), the times
    // asked (~130 B each) and at most 8 MB of rendered text, so 44000 more
    // rows add a few tens of MB of resident memory. The bounds leave room
    // for the allocator's retention, which varies from run to run on two
    // threads (80–115 MB seen for the same table), and still fail by far
    // if the rows were held.
    let args = |steps: &'static str| {
        [
            "trajectory",
            "--theta0",
            "1/10",
            "--t-end",
            "5",
            "--steps",
            steps,
            "--digits",
            "20",
            "--format",
            "csv",
        ]
    };
    for threads in [1, 2] {
        let (kb, bytes) = peak_kb(&args("47999"), 500, threads);
        assert!(bytes > 48000 * 21 * 20, "{bytes} bytes printed");
        assert!(
            kb < 250_000,
            "peak {kb} kB for 48000 rows on {threads} threads"
        );
        let (kb_small, _) = peak_kb(&args("3999"), 500, threads);
        assert!(
            kb < kb_small + 100_000,
            "peak {kb} kB for 48000 rows against {kb_small} kB for 4000 on {threads} threads"
        );
    }
}

/// The two knobs of a long table, `CYLROLL_THREADS` and
/// `CYLROLL_BLOCK_ROWS`, set to a value they cannot take: a one-line error
/// naming the variable, what was given and what is allowed, exit 2, nothing
/// printed (they were ignored, the defaults taken silently).
#[test]
fn bad_block_knobs_are_refused_by_name() {
    let args = [
        "trajectory",
        "--theta0",
        "1/10",
        "--t-end",
        "1",
        "--steps",
        "3",
    ];
    for (var, value) in [
        ("CYLROLL_THREADS", "two"),
        ("CYLROLL_THREADS", "0"),
        ("CYLROLL_THREADS", "65"),
        ("CYLROLL_BLOCK_ROWS", "-3"),
        ("CYLROLL_BLOCK_ROWS", "0"),
    ] {
        let out = cyl().args(args).env(var, value).output().unwrap();
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(out.status.code(), Some(2), "{var}={value}: {err}");
        assert!(out.stdout.is_empty(), "{var}={value}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(
            err.contains(var)
                && err.contains(&format!("\"{value}\""))
                && err.contains("whole number"),
            "{err}"
        );
    }
}
