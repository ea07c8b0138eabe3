//! The report (`cylroll report`): the page references only files that exist,
//! two runs write the same bytes, the tables agree with the closed forms, and
//! the page renders in a headless browser where one is installed.
//!
//! These tests use `report::Config::quick()` (coarse curves, the same tables)
//! so they run in seconds.

use cylroll::report::{run_with, Config};
use rug::float::Constant;
use rug::Float;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// One quick report shared by the tests (generated once per test binary).
fn shared_report() -> &'static Path {
    static DIR: OnceLock<tempfile::TempDir> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = tempfile::tempdir().expect("tempdir");
        let summary = run_with(dir.path(), &Config::quick()).expect("the quick report runs");
        assert!(
            !summary.contains("problem:"),
            "the quick report met problems:\n{summary}"
        );
        dir
    })
    .path()
}

/// Every file under `dir`, by relative path, with its bytes.
fn snapshot(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    fn walk(root: &Path, dir: &Path, out: &mut BTreeMap<PathBuf, Vec<u8>>) {
        let mut entries: Vec<_> = std::fs::read_dir(dir)
            .expect("read_dir")
            .map(|e| e.expect("entry").path())
            .collect();
        entries.sort();
        for p in entries {
            if p.is_dir() {
                walk(root, &p, out);
            } else {
                let rel = p.strip_prefix(root).expect("prefix").to_path_buf();
                out.insert(rel, std::fs::read(&p).expect("read"));
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(dir, dir, &mut out);
    out
}

/// The values of every `attr="..."` in `html`.
fn attr_values(html: &str, attr: &str) -> Vec<String> {
    let pat = format!("{attr}=\"");
    let mut out = Vec::new();
    let mut rest = html;
    while let Some(i) = rest.find(&pat) {
        rest = &rest[i + pat.len()..];
        if let Some(j) = rest.find('"') {
            out.push(rest[..j].to_string());
            rest = &rest[j..];
        }
    }
    out
}

/// Relative link targets of a Markdown page: `](target)`.
fn md_links(md: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = md;
    while let Some(i) = rest.find("](") {
        rest = &rest[i + 2..];
        if let Some(j) = rest.find(')') {
            out.push(rest[..j].to_string());
            rest = &rest[j..];
        }
    }
    out
}

fn check_references(dir: &Path) {
    let html = std::fs::read_to_string(dir.join("index.html")).expect("index.html");
    let md = std::fs::read_to_string(dir.join("README.md")).expect("README.md");
    let mut targets: Vec<String> = attr_values(&html, "src");
    targets.extend(attr_values(&html, "href"));
    let n_img = attr_values(&html, "src").len();
    assert!(n_img >= 10, "index.html shows only {n_img} images");
    let ids = attr_values(&html, "id");
    for t in &targets {
        if let Some(anchor) = t.strip_prefix('#') {
            assert!(
                ids.iter().any(|i| i == anchor),
                "index.html: dangling anchor {t}"
            );
            continue;
        }
        assert!(
            !t.contains("://") && !t.starts_with('/'),
            "index.html: non-relative reference {t}"
        );
        assert!(
            dir.join(t).is_file(),
            "index.html references {t}, which does not exist"
        );
    }
    for t in md_links(&md) {
        if t.starts_with('#') {
            continue;
        }
        assert!(
            !t.contains("://") && !t.starts_with('/'),
            "README.md: non-relative link {t}"
        );
        assert!(
            dir.join(&t).is_file(),
            "README.md links {t}, which does not exist"
        );
    }
    // every figure written is shown
    for e in std::fs::read_dir(dir.join("figures")).expect("figures/") {
        let name = e.expect("entry").file_name().to_string_lossy().into_owned();
        let rel = format!("figures/{name}");
        assert!(targets.contains(&rel), "{rel} is not shown on index.html");
        assert!(md.contains(&rel), "{rel} is not shown in README.md");
    }
}

#[test]
fn page_references_only_files_that_exist() {
    check_references(shared_report());
}

#[test]
fn committed_report_references_only_files_that_exist() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("reports");
    if !dir.join("index.html").is_file() {
        eprintln!("note: no committed reports/index.html; skipped");
        return;
    }
    check_references(&dir);
}

#[test]
fn two_runs_write_the_same_bytes() {
    let first = shared_report();
    let dir = tempfile::tempdir().expect("tempdir");
    // write over an older report too: files are replaced whole
    std::fs::create_dir_all(dir.path().join("figures")).expect("mkdir");
    std::fs::write(dir.path().join("index.html"), "old").expect("write");
    run_with(dir.path(), &Config::quick()).expect("second run");
    let a = snapshot(first);
    let b = snapshot(dir.path());
    assert_eq!(
        a.keys().collect::<Vec<_>>(),
        b.keys().collect::<Vec<_>>(),
        "the two runs wrote different files"
    );
    for (k, v) in &a {
        assert!(b[k] == *v, "{} differs between two runs", k.display());
    }
    // no temporary files left behind
    for k in b.keys() {
        let name = k
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        assert!(
            !name.starts_with('.'),
            "temporary file left: {}",
            k.display()
        );
    }
    // SVGs carry nothing volatile and only fixed-format numbers
    for (k, v) in &a {
        if k.extension().is_some_and(|e| e == "svg") {
            let s = String::from_utf8(v.clone()).expect("utf8");
            assert!(s.starts_with("<svg"), "{}", k.display());
            assert!(
                !s.contains("NaN") && !s.contains("inf"),
                "{} has a non-finite number",
                k.display()
            );
        }
    }
}

/// The records of a tidy CSV (`case,point,phase,quantity,unit,value,digits`)
/// keyed by (case, quantity): (value, digits).
fn tidy(dir: &Path, name: &str) -> BTreeMap<(String, String), (String, String)> {
    let text = std::fs::read_to_string(dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("case,point,phase,quantity,unit,value,digits"),
        "{name}: header"
    );
    let mut out = BTreeMap::new();
    for l in lines {
        let c: Vec<&str> = l.split(',').collect();
        out.insert(
            (c[0].to_string(), c[3].to_string()),
            (c[5].to_string(), c[6].to_string()),
        );
    }
    out
}

fn round(x: &Float, digits: u32) -> String {
    cylroll::numeric::decimal::to_sig(x, digits)
}

#[test]
fn tables_agree_with_the_closed_forms() {
    let dir = shared_report();
    let mut rows = tidy(dir, "separation-top.csv");
    rows.extend(tidy(dir, "separation-start.csv"));
    let html = std::fs::read_to_string(dir.join("index.html")).expect("index.html");
    let p = 400;
    let pi = Float::with_val(p, Constant::Pi);
    let acos = |c: Float| c.acos();
    let k2 = Float::with_val(p, 0.5);
    let cases: Vec<((&str, &str, &str), Float, &str)> = vec![
        (
            ("roll", "roll", "0"),
            Float::with_val(p, &pi / 3u32),
            "pi/3: identical solid cylinders from rest at the top",
        ),
        (
            ("fixed", "roll", "0"),
            acos(Float::with_val(p, 2u32) / (Float::with_val(p, 3u32) + &k2)),
            "eq. (36): cos θs = 2/(3 + k2)",
        ),
        (
            ("fixed", "slip", "0"),
            acos(Float::with_val(p, 2u32) / 3u32),
            "cos θs = 2/3",
        ),
        (
            ("slip", "slip", "0"),
            acos(Float::with_val(p, 3u32).sqrt() - 1u32),
            "corrected eq. (43) with m1 = m2",
        ),
        (
            ("fixed", "roll", "1/100"),
            acos(
                Float::with_val(p, Float::with_val(p, 1u32) / 100u32).cos() * 2u32
                    / (Float::with_val(p, 3u32) + &k2),
            ),
            "cos θs = 2 cos θ0/(3 + k2)",
        ),
        (
            ("fixed", "slip", "1/20"),
            acos(Float::with_val(p, Float::with_val(p, 1u32) / 20u32).cos() * 2u32 / 3u32),
            "cos θs = 2 cos θ0/3",
        ),
    ];
    for ((f, c, t0), expected, what) in cases {
        let key = (
            format!("floor={f};contact={c};theta0={t0}"),
            "theta_s".to_string(),
        );
        let (value, digits) = rows
            .get(&key)
            .unwrap_or_else(|| panic!("no row for {key:?}"));
        let digits: u32 = digits.parse().expect("digits");
        assert!(digits >= 20, "{key:?}: only {digits} digits");
        let want = round(&expected, digits);
        assert_eq!(
            *value, want,
            "{key:?} ({what}): table says {value}, closed form {want}"
        );
        assert!(
            html.contains(&want),
            "index.html lacks θs = {want} for {key:?}"
        );
    }

    // the parameter plane: the fixed lower cylinder against arccos(2/(3 + k2))
    let mut checked = 0;
    for ((case, q), (value, digits)) in tidy(dir, "plane.csv") {
        if !case.starts_with("floor=fixed;") || q != "theta_s" || digits != "20" {
            continue;
        }
        let k2 = case
            .split(';')
            .find_map(|kv| kv.strip_prefix("k2="))
            .expect("k2");
        let k = cylroll::exact::Exact::parse("k2", k2, false)
            .expect("k2")
            .to_float(p);
        let want = round(&acos(Float::with_val(p, 2u32) / (k + 3u32)), 20);
        assert_eq!(value, want, "fixed lower cylinder, k2 = {k2}");
        assert!(html.contains(&want), "index.html lacks {want}");
        checked += 1;
    }
    assert!(checked >= 5, "only {checked} fixed-lower rows in plane.csv");
}

fn chromium() -> Option<PathBuf> {
    for p in [
        "/usr/bin/chromium",
        "/usr/bin/chromium-browser",
        "/usr/bin/google-chrome",
    ] {
        if Path::new(p).is_file() {
            return Some(PathBuf::from(p));
        }
    }
    None
}

#[test]
fn page_renders_in_headless_chromium() {
    let Some(browser) = chromium() else {
        eprintln!("note: no Chromium at /usr/bin/chromium; the rendering smoke test is skipped");
        return;
    };
    let dir = shared_report();
    let out = tempfile::tempdir().expect("tempdir");
    let png = out.path().join("page.png");
    let url = format!("file://{}", dir.join("index.html").display());
    let profile = tempfile::tempdir().expect("tempdir");
    let mut child = std::process::Command::new(&browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--hide-scrollbars",
            "--window-size=1280,3000",
            &format!("--user-data-dir={}", profile.path().display()),
            &format!("--screenshot={}", png.display()),
            &url,
        ])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("start chromium");
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(120);
    loop {
        match child.try_wait().expect("wait") {
            Some(_) => break,
            None if std::time::Instant::now() > deadline => {
                let _ = child.kill();
                let _ = child.wait();
                panic!("chromium did not finish within 120 s");
            }
            None => std::thread::sleep(std::time::Duration::from_millis(200)),
        }
    }
    let bytes = std::fs::read(&png).expect("chromium wrote no screenshot");
    assert!(bytes.starts_with(b"\x89PNG"), "not a PNG");
    assert!(
        bytes.len() > 20_000,
        "suspiciously small screenshot: {} bytes",
        bytes.len()
    );
}
