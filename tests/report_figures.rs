//! The report's figures and page as a reader gets them: smooth curves, hover
//! values, data beside every figure, a page that fits a phone, captions that
//! say what the data shows, and (where CI asks for it) the page checked in
//! headless Chromium.
//!
//! Uses `report::Config::quick()` so that it runs in seconds.

use cylroll::report::{run_with, Config};
use std::path::Path;
use std::sync::OnceLock;

fn report() -> &'static Path {
    static DIR: OnceLock<tempfile::TempDir> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = tempfile::tempdir().expect("tempdir");
        std::fs::write(
            dir.path().join("audit.md"),
            "# Audit\n\n| a | b |\n|---|---|\n| 1 | 2 |\n",
        )
        .expect("audit.md");
        run_with(dir.path(), &Config::quick()).expect("the quick report runs");
        dir
    })
    .path()
}

fn read(rel: &str) -> String {
    std::fs::read_to_string(report().join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"))
}

fn svgs() -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(report().join("figures"))
        .expect("figures/")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".svg") && !n.ends_with(".narrow.svg"))
        .collect();
    v.sort();
    v
}

#[test]
fn curves_keep_sub_pixel_coordinates() {
    let svg = read("figures/main_forces_theta.svg");
    let curve = svg
        .lines()
        .find(|l| l.starts_with("<path d=\"M") && l.contains("<title>F₁</title>"))
        .expect("the F1 curve");
    let fractional = curve
        .split([' ', 'M', 'L', '"'])
        .filter(|t| t.contains('.') && t.parse::<f64>().is_ok())
        .count();
    assert!(fractional > 3, "curve on whole pixels: {curve}");
}

#[test]
fn every_figure_has_a_narrow_layout_data_and_a_page_entry() {
    let html = read("index.html");
    let md = read("README.md");
    for f in svgs() {
        let stem = f.trim_end_matches(".svg");
        assert!(
            html.contains(&format!("figures/{f}")),
            "{f} not on the page"
        );
        assert!(md.contains(&format!("figures/{f}")), "{f} not in README.md");
        if stem == "conventions" {
            continue;
        }
        let csv = format!("figures/{stem}.csv");
        assert!(report().join(&csv).is_file(), "{csv} missing");
        assert!(
            html.contains(&format!("href=\"{csv}\"")),
            "{csv} not linked"
        );
        let narrow = format!("figures/{stem}.narrow.svg");
        assert!(report().join(&narrow).is_file(), "{narrow} missing");
        let data = read(&csv);
        assert!(data.lines().count() > 2, "{csv} is empty");
    }
}

#[test]
fn figures_have_one_title_hover_values_and_true_minus_signs() {
    for f in svgs() {
        let svg = read(&format!("figures/{f}"));
        assert!(svg.contains("viewBox="), "{f}: no viewBox");
        assert!(svg.contains("<title>"), "{f}: no hover text");
        // tick labels use U+2212, never a hyphen before a digit
        for l in svg.lines().filter(|l| l.starts_with("<text")) {
            let text = l.rsplit_once("\">").map(|x| x.1).unwrap_or("");
            assert!(!text.starts_with('-'), "{f}: hyphen-minus in a label: {l}");
        }
    }
    // the separation markers of the main case carry their values
    let svg = read("figures/main_forces_theta.svg");
    assert!(svg.contains("N₁₂ at θₛ:"), "no hover value at separation");
    assert!(svg.contains("θₛ = 1.047"), "θs not labelled");
    // slip onsets are marked on the friction figure
    let fr = read("figures/main_friction.svg");
    assert!(
        fr.contains("starts to slip at θ ="),
        "no slip onset markers"
    );
}

#[test]
fn captions_say_what_the_data_shows() {
    let md = read("README.md");
    // F1 keeps its sign in the main case: no caption may say it changes
    assert!(
        !md.contains("where F1 changes sign") && !md.contains("where F₁ changes sign"),
        "a caption claims a sign change of F1"
    );
    assert!(
        md.contains("F₁ keeps its sign"),
        "the F1 sign finding is missing"
    );
    // no force units under kinematics figures
    let kin = md
        .split("### Main case (both contacts rolling)")
        .nth(1)
        .and_then(|s| s.split("\n\n").nth(2))
        .expect("kinematics caption");
    assert!(!kin.contains("forces in units"), "{kin}");
    // the findings are written for a reader, not as log lines
    let notes = md
        .split("### What the oracle reported")
        .nth(1)
        .expect("notes");
    for raw in ["theta_s", "phi1_dot", "!=", "->"] {
        assert!(
            !notes
                .split("### Data files")
                .next()
                .unwrap_or("")
                .contains(raw),
            "raw text {raw:?} in the findings"
        );
    }
    assert!(
        notes.contains("Cylinder 1 is held"),
        "held cylinder not said so"
    );
}

#[test]
fn the_page_fits_a_phone_and_aligns_numbers() {
    let html = read("index.html");
    assert!(html.contains("<meta name=\"viewport\""));
    assert!(html.contains("@media (max-width:700px)"));
    assert!(html.contains("td.num{text-align:right;font-family:'DejaVu Sans Mono'"));
    assert!(
        html.contains("data-label=\""),
        "no labels for the narrow table layout"
    );
    // other tools' documents become pages of the report, linked from the index
    assert!(html.contains("href=\"audit.html\""));
    let audit = read("audit.html");
    assert!(audit.contains("<table>") && audit.contains("href=\"index.html\""));
}

#[test]
fn the_diagram_shows_every_convention() {
    let svg = read("figures/conventions.svg");
    for t in ["θ", "φ₁", "φ₂ − θ", "F₁", "N₁", "F₂₁", "N₁₂"] {
        assert!(
            svg.contains(&format!(">{t}<")),
            "{t} missing from the diagram"
        );
    }
}

/// Renders the quick report in headless Chromium with `reports/check_browser.py`.
/// Runs when `CYLROLL_BROWSER_CHECK=1` (set by `.ci/run`); then a missing
/// browser is a failure, not a skip.
#[test]
fn the_page_passes_the_browser_check() {
    if std::env::var("CYLROLL_BROWSER_CHECK").as_deref() != Ok("1") {
        eprintln!("note: CYLROLL_BROWSER_CHECK is not 1; the browser check runs in .ci/run");
        return;
    }
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("reports/check_browser.py");
    let shots = tempfile::tempdir().expect("tempdir");
    let out = std::process::Command::new("python3")
        .arg(&script)
        .arg(report())
        .arg("--screenshots")
        .arg(shots.path())
        .output()
        .expect("python3 runs");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.status.success(), "browser check failed:\n{text}");
}
