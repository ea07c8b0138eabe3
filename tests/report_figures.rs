//! The report's figures and page as a reader gets them: smooth curves, hover
//! values, data and a PDF beside every figure, a page that fits a phone,
//! captions that say what the data shows, the figures sampled at their
//! events, and (where CI asks for it) the page checked in headless Chromium.
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
    let svg = read("figures/main_forces.svg");
    let curve = svg
        .lines()
        .find(|l| l.starts_with("<path class=\"c\" d=\"M") && l.contains("<title>F₁</title>"))
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
        for pdf in [
            format!("figures/{stem}.pdf"),
            format!("figures/{stem}.narrow.pdf"),
        ] {
            assert!(report().join(&pdf).is_file(), "{pdf} missing");
            assert!(
                html.contains(&format!("href=\"{pdf}\"")),
                "{pdf} not linked"
            );
        }
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
    let svg = read("figures/main_forces.svg");
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
    // the caption of the friction figure pairs each μ with its angle
    let fr = md
        .split("### Main case: the friction coefficient rolling needs")
        .nth(1)
        .expect("the friction figure");
    assert!(fr.contains("at μ = 0.05: 0.1"), "μ and θ paired: {fr}");
    // the branch figure names the command of the parting branch
    assert!(md.contains("cylroll separation --branch part"));
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
    assert!(audit.contains("<table class=\"data\">") && audit.contains("href=\"index.html\""));
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

/// One curve of a figure's CSV: (point, phase, x, y) in point order.
fn curve(csv: &str, case: &str) -> Vec<(usize, String, f64, f64)> {
    let mut pts: Vec<(usize, String, f64, f64)> = Vec::new();
    for l in csv.lines().skip(1) {
        let c: Vec<&str> = l.split(',').collect();
        if c[0] != case {
            continue;
        }
        let (p, v): (usize, f64) = (c[1].parse().expect("point"), c[5].parse().expect("value"));
        match pts.last_mut() {
            Some(last) if last.0 == p => last.3 = v,
            _ => pts.push((p, c[2].to_string(), v, f64::NAN)),
        }
    }
    pts
}

/// A reference line's position in a figure's CSV.
fn line_at(csv: &str, suffix: &str) -> f64 {
    csv.lines()
        .find(|l| l.split(',').next().is_some_and(|c| c.ends_with(suffix)))
        .and_then(|l| l.split(',').nth(5))
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("no line {suffix}"))
}

#[test]
fn friction_figures_are_sampled_at_their_events() {
    // the quick report verifies 8 digits: its samples lie 1e-6 from the
    // events (track::gap), far below what a figure shows
    let csv = read("figures/friction_main.csv");
    let ts = line_at(
        &csv,
        "panel=forces_between_the_cylinders;line=separation;contact=contact",
    );
    let onset = line_at(
        &csv,
        "panel=forces_between_the_cylinders;line=slip_onset;contact=contact",
    );
    // N12 reaches 0 at the separation, sampled there
    let n12 = curve(&csv, "panel=forces_between_the_cylinders;curve=N12");
    let at_s = n12
        .iter()
        .find(|p| (p.2 - ts).abs() < 1e-5 && p.1 != "flight")
        .expect("N12 sampled at t_s");
    assert!(at_s.3.abs() < 1e-4, "N12 at t_s = {}", at_s.3);
    // the slip speed between the cylinders ends at separation, none in flight
    let s12 = curve(&csv, "panel=slip_speeds;curve=s12");
    let last = s12.last().expect("s12");
    assert!(
        (last.2 - ts).abs() < 1e-5,
        "s12 ends at {} not t_s {ts}",
        last.2
    );
    assert!(last.3 > 0.05, "s12 at separation {}", last.3);
    assert!(s12.iter().all(|p| p.1 != "flight"), "s12 drawn in flight");
    // the slip onset is a sample on both sides, and the shading starts there
    let th = curve(&csv, "panel=theta_with_its_events;curve=theta");
    let before = th
        .iter()
        .find(|p| (p.2 - onset).abs() < 1e-5 && p.1 == "stick/stick");
    let after = th
        .iter()
        .find(|p| (p.2 - onset).abs() < 1e-5 && p.1.contains("slip"));
    assert!(
        before.is_some() && after.is_some(),
        "onset not sampled on both sides"
    );
    let svg = read("figures/friction_main.svg");
    assert!(
        svg.contains(&format!("t = {onset:.4} to {ts:.4}</title>")),
        "slip shading not from the onset {onset:.4} to t_s {ts:.4}"
    );
    // which contact slips is shown: one curve per contact in the map
    let map = read("figures/friction_map.csv");
    assert!(map.contains("first_slip;contact=cylinders"));
    assert!(map.contains("first_slip;contact=floor") || !map.contains("contact=floor,"));
}

#[test]
fn the_branch_figure_shows_both_branches() {
    let csv = read("figures/main_branch.csv");
    for key in ["branch=stay", "branch=part"] {
        assert!(csv.contains(&format!(";{key},")), "{key} missing");
        assert!(
            csv.contains(&format!("marker={key};impact")),
            "{key}: no impact"
        );
    }
    let star = line_at(&csv, "line=branch_point");
    // the part branch parts at the branch point: N12 is 0 from t* on
    let part = curve(&csv, "panel=b_N12_on_both_branches;branch=part");
    let stay = curve(&csv, "panel=b_N12_on_both_branches;branch=stay");
    assert!(!part.is_empty() && !stay.is_empty());
    let t_star = part
        .iter()
        .find(|p| p.1 == "flight")
        .map(|p| p.2)
        .expect("the part branch flies");
    let t_sep = stay
        .iter()
        .find(|p| p.1 == "flight")
        .map(|p| p.2)
        .expect("the stay branch flies");
    assert!(t_star < t_sep, "part parts at {t_star}, stay at {t_sep}");
    assert!(star > 0.9 && star < 1.0, "θ* = {star}");
}

#[test]
fn the_engines_page_shows_only_committed_scorecards() {
    let html = read("engines.html");
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("golden/engines");
    let committed = std::fs::read_dir(&root)
        .map(|rd| {
            rd.filter_map(|e| e.ok())
                .any(|e| e.path().join("scorecard.json").is_file())
        })
        .unwrap_or(false);
    if committed {
        assert!(!html.contains("No scorecards are committed"));
        assert!(html.contains("scorecard.json"));
    } else {
        assert!(html.contains("No scorecards are committed"), "{html}");
        assert!(html.contains("python -m cylroll.conformance ENGINE"));
        assert!(!html.contains("<table"), "a table without a scorecard");
    }
    assert!(html.contains("source commit"), "no stamp");
    let index = read("index.html");
    assert!(index.contains("href=\"engines.html\""));
}
