//! Print-ready figures, checked on the files the report writes: no text
//! of a figure overlaps another text, a curve, a reference line or a marker,
//! or crosses a plot's frame; every text is at least 7 pt at print size;
//! every figure has a PDF one (85 mm) or two (178 mm) journal columns wide;
//! every CSV has the one tidy ASCII schema.
//!
//! The boxes are measured here from the SVG as written (each text's
//! position, size and anchor, measured with the report's embedded font), not
//! taken from the code that placed them. `reports/check_browser.py` makes
//! the same test with the browser's own boxes at 400 and 1400 px.
//!
//! Runs on a fresh quick report (`report::Config::quick()`) and on the
//! committed `reports/` when it is there (the full report).

use cylroll::report::labels::{text_box, Rect};
use cylroll::report::{run_with, Config};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

fn quick_report() -> &'static Path {
    static DIR: OnceLock<tempfile::TempDir> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = tempfile::tempdir().expect("tempdir");
        run_with(dir.path(), &Config::quick()).expect("the quick report runs");
        dir
    })
    .path()
}

fn committed_report() -> Option<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("reports");
    dir.join("figures").is_dir().then_some(dir)
}

/// Tolerance in pt: boxes may touch.
const TOL: f64 = 0.25;
/// Smallest text at print size, pt.
const MIN_PT: f64 = 7.0;

/// The value of attribute `name` in the start tag `tag`.
fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let pat = format!(" {name}=\"");
    let i = tag.find(&pat)? + pat.len();
    let j = tag[i..].find('"')?;
    Some(&tag[i..i + j])
}

fn num(tag: &str, name: &str) -> Option<f64> {
    attr(tag, name)?.trim_end_matches("pt").parse().ok()
}

fn unescape(s: &str) -> String {
    s.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&amp;", "&")
}

/// A text of a figure: its content and box (pt, y down).
struct Text {
    s: String,
    b: Rect,
    size: f64,
}

/// What a figure draws, as the overlap test needs it.
#[derive(Default)]
struct Drawing {
    /// The viewBox width over the print width (1 for the plots, whose
    /// viewBox is in pt).
    scale: f64,
    texts: Vec<Text>,
    /// Curves and reference lines (polylines), with their hover text.
    lines: Vec<(String, Vec<(f64, f64)>)>,
    /// Markers: hover text and box.
    marks: Vec<(String, Rect)>,
    /// Plot frames.
    frames: Vec<Rect>,
}

/// The points of a path's `d` made of M, L, H, V and Z (the report's paths).
fn path_points(d: &str) -> Vec<(f64, f64)> {
    let mut pts = Vec::new();
    let mut cmd = 'M';
    let mut nums: Vec<f64> = Vec::new();
    let flush = |cmd: char, nums: &mut Vec<f64>, pts: &mut Vec<(f64, f64)>| {
        match cmd {
            'M' | 'L' => {
                for c in nums.chunks(2) {
                    if c.len() == 2 {
                        pts.push((c[0], c[1]));
                    }
                }
            }
            'H' => {
                if let Some(&(_, y)) = pts.last() {
                    pts.extend(nums.iter().map(|&x| (x, y)));
                }
            }
            'V' => {
                if let Some(&(x, _)) = pts.last() {
                    pts.extend(nums.iter().map(|&y| (x, y)));
                }
            }
            _ => {}
        }
        nums.clear();
    };
    let mut tok = String::new();
    for ch in d.chars().chain(std::iter::once(' ')) {
        if ch.is_ascii_alphabetic() && ch != 'e' {
            if !tok.is_empty() {
                nums.push(tok.parse().unwrap_or(f64::NAN));
                tok.clear();
            }
            flush(cmd, &mut nums, &mut pts);
            cmd = ch;
        } else if ch == ' ' || ch == ',' || (ch == '-' && !tok.is_empty() && !tok.ends_with('e')) {
            if !tok.is_empty() {
                nums.push(tok.parse().unwrap_or(f64::NAN));
                tok.clear();
            }
            if ch == '-' {
                tok.push(ch);
            }
        } else {
            tok.push(ch);
        }
    }
    flush(cmd, &mut nums, &mut pts);
    pts
}

fn bbox(pts: &[(f64, f64)]) -> Rect {
    pts.iter().fold(
        (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ),
        |b, p| (b.0.min(p.0), b.1.max(p.0), b.2.min(p.1), b.3.max(p.1)),
    )
}

fn title_of(line: &str) -> String {
    line.split("<title>")
        .nth(1)
        .and_then(|t| t.split("</title>").next())
        .map(unescape)
        .unwrap_or_default()
}

/// Reads a figure's SVG (one element per line, as the report writes it).
fn drawing(svg: &str) -> Drawing {
    let root = svg.lines().next().unwrap_or("");
    let print_w = num(root, "width").unwrap_or(1.0);
    let vb_w = attr(root, "viewBox")
        .and_then(|v| v.split_whitespace().nth(2))
        .and_then(|v| v.parse::<f64>().ok())
        .unwrap_or(print_w);
    let mut d = Drawing {
        scale: print_w / vb_w,
        ..Default::default()
    };
    let default_size = num(root, "font-size").unwrap_or(16.0);
    for line in svg.lines() {
        let t = line.trim_start();
        if let Some(rest) = t.strip_prefix("<text") {
            let close = rest.find('>').unwrap_or(0);
            let tag = &rest[..close];
            let content = rest[close + 1..]
                .split("</text>")
                .next()
                .map(unescape)
                .unwrap_or_default();
            if content.trim().is_empty() {
                continue;
            }
            let (x, y) = (num(tag, "x").unwrap_or(0.0), num(tag, "y").unwrap_or(0.0));
            let size = num(tag, "font-size").unwrap_or(default_size);
            let anchor = attr(tag, "text-anchor").unwrap_or("start");
            let mut b = text_box(x, y, &content, size, anchor);
            if let Some(tr) = attr(tag, "transform") {
                // rotate(±90 x y): the box turned about the anchor point
                let a: Vec<f64> = tr
                    .trim_start_matches("rotate(")
                    .trim_end_matches(')')
                    .split_whitespace()
                    .filter_map(|v| v.parse().ok())
                    .collect();
                if a.len() == 3 && (a[0].abs() - 90.0).abs() < 1e-9 {
                    let (cx, cy) = (a[1], a[2]);
                    let s = a[0].signum();
                    let corners = [(b.0, b.2), (b.1, b.2), (b.0, b.3), (b.1, b.3)]
                        .map(|(px, py)| (cx - s * (py - cy), cy + s * (px - cx)));
                    b = bbox(&corners);
                }
            }
            d.texts.push(Text {
                s: content,
                b,
                size,
            });
            continue;
        }
        let class = attr(t, "class").unwrap_or("");
        match class {
            "c" | "r" if t.starts_with("<path") => {
                let pts = path_points(attr(t, "d").unwrap_or(""));
                d.lines.push((title_of(t), pts));
            }
            "m" => {
                let b = if t.starts_with("<circle") {
                    let (cx, cy, r) = (
                        num(t, "cx").unwrap_or(0.0),
                        num(t, "cy").unwrap_or(0.0),
                        num(t, "r").unwrap_or(0.0),
                    );
                    (cx - r, cx + r, cy - r, cy + r)
                } else {
                    bbox(&path_points(attr(t, "d").unwrap_or("")))
                };
                if b.0.is_finite() {
                    d.marks.push((title_of(t), b));
                }
            }
            "frame" if t.starts_with("<rect") => {
                let (x, y, w, h) = (
                    num(t, "x").unwrap_or(0.0),
                    num(t, "y").unwrap_or(0.0),
                    num(t, "width").unwrap_or(0.0),
                    num(t, "height").unwrap_or(0.0),
                );
                d.frames.push((x, x + w, y, y + h));
            }
            _ => {}
        }
    }
    d
}

fn meets(a: Rect, b: Rect, tol: f64) -> bool {
    a.0 + tol < b.1 && b.0 + tol < a.1 && a.2 + tol < b.3 && b.2 + tol < a.3
}

fn within(a: Rect, b: Rect, tol: f64) -> bool {
    a.0 >= b.0 - tol && a.1 <= b.1 + tol && a.2 >= b.2 - tol && a.3 <= b.3 + tol
}

/// Whether segment pq passes through the inside of box b.
fn crosses(p: (f64, f64), q: (f64, f64), b: Rect) -> bool {
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    let (dx, dy) = (q.0 - p.0, q.1 - p.1);
    for (pp, qq) in [
        (-dx, p.0 - b.0),
        (dx, b.1 - p.0),
        (-dy, p.1 - b.2),
        (dy, b.3 - p.1),
    ] {
        if pp == 0.0 {
            if qq <= 0.0 {
                return false;
            }
        } else {
            let r = qq / pp;
            if pp < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    t0 < t1
}

/// Every overlap in one figure.
fn overlaps(d: &Drawing) -> Vec<String> {
    let mut bad = Vec::new();
    for (i, t) in d.texts.iter().enumerate() {
        for u in &d.texts[i + 1..] {
            if meets(t.b, u.b, TOL) {
                bad.push(format!("text {:?} overlaps text {:?}", t.s, u.s));
            }
        }
        let inner = (t.b.0 + TOL, t.b.1 - TOL, t.b.2 + TOL, t.b.3 - TOL);
        for (title, pts) in &d.lines {
            if pts.windows(2).any(|w| crosses(w[0], w[1], inner)) {
                bad.push(format!("text {:?} overlaps the line {title:?}", t.s));
            }
        }
        for (title, m) in &d.marks {
            if meets(t.b, *m, TOL) {
                bad.push(format!("text {:?} overlaps the marker {title:?}", t.s));
            }
        }
        for f in &d.frames {
            if meets(t.b, *f, TOL) && !within(t.b, *f, TOL) {
                bad.push(format!("text {:?} crosses a plot's frame", t.s));
            }
        }
    }
    bad
}

fn figure_svgs(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir.join("figures"))
        .expect("figures/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .collect();
    v.sort();
    v
}

fn check_dir(dir: &Path) {
    let svgs = figure_svgs(dir);
    assert!(
        svgs.len() >= 20,
        "only {} SVGs in {}",
        svgs.len(),
        dir.display()
    );
    let mut failures = Vec::new();
    let mut texts = 0;
    for p in &svgs {
        let name = p
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let svg = std::fs::read_to_string(p).expect("svg");
        let d = drawing(&svg);
        texts += d.texts.len();
        for b in overlaps(&d) {
            failures.push(format!("{name}: {b}"));
        }
        for t in &d.texts {
            let pt = t.size * d.scale;
            if pt < MIN_PT - 1e-6 {
                failures.push(format!(
                    "{name}: text {:?} is {pt:.2} pt at print size",
                    t.s
                ));
            }
        }
        // print size: one column (85 mm) or two (178 mm), and a PDF of the same size
        let w_mm = num(svg.lines().next().unwrap_or(""), "width").unwrap_or(0.0) / 72.0 * 25.4;
        assert!(
            (w_mm - 85.0).abs() < 0.05 || (w_mm - 178.0).abs() < 0.05,
            "{name} is {w_mm:.2} mm wide"
        );
        let pdf = p.with_extension("pdf");
        let bytes = std::fs::read(&pdf).unwrap_or_else(|e| panic!("{}: {e}", pdf.display()));
        let (pw, _) = cylroll::report::pdf::media_box(&bytes).expect("a MediaBox");
        assert!(
            (pw / 72.0 * 25.4 - w_mm).abs() < 0.05,
            "{}: page {pw} pt, the SVG {w_mm:.2} mm",
            pdf.display()
        );
        let text = String::from_utf8_lossy(&bytes);
        assert!(
            text.contains("/FontFile2"),
            "{}: no embedded font",
            pdf.display()
        );
    }
    assert!(
        texts > 500,
        "only {texts} texts read: is the SVG reader broken?"
    );
    assert!(
        failures.is_empty(),
        "{} problems in {}:\n{}",
        failures.len(),
        dir.display(),
        failures.join("\n")
    );
}

#[test]
fn figures_of_a_fresh_report_have_no_overlaps_and_print_at_journal_sizes() {
    check_dir(quick_report());
}

#[test]
fn figures_of_the_committed_report_have_no_overlaps_and_print_at_journal_sizes() {
    let Some(dir) = committed_report() else {
        eprintln!("note: no committed reports/figures; skipped");
        return;
    };
    check_dir(&dir);
}

#[test]
fn the_overlap_test_finds_overlaps() {
    // a label across a curve, a label on a marker, two labels on each other,
    // a tick label across the frame
    let svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100pt\" height=\"100pt\" viewBox=\"0 0 100 100\">\n\
<rect class=\"frame\" x=\"10\" y=\"10\" width=\"80\" height=\"80\" fill=\"none\"/>\n\
<path class=\"c\" d=\"M10 50L90 50\" stroke=\"#000\"><title>curve</title></path>\n\
<circle class=\"m\" cx=\"70\" cy=\"30\" r=\"2.4\"><title>marker</title></circle>\n\
<text class=\"t\" x=\"20\" y=\"52\" font-size=\"7\" text-anchor=\"start\">on the curve</text>\n\
<text class=\"t\" x=\"70\" y=\"32\" font-size=\"7\" text-anchor=\"middle\">on the marker</text>\n\
<text class=\"t\" x=\"20\" y=\"20\" font-size=\"7\" text-anchor=\"start\">first</text>\n\
<text class=\"t\" x=\"22\" y=\"21\" font-size=\"7\" text-anchor=\"start\">second</text>\n\
<text class=\"t\" x=\"10\" y=\"95\" font-size=\"7\" text-anchor=\"middle\">0.00</text>\n\
</svg>\n";
    let bad = overlaps(&drawing(svg));
    let all = bad.join("\n");
    for want in [
        "\"on the curve\" overlaps the line \"curve\"",
        "\"on the marker\" overlaps the marker \"marker\"",
        "\"first\" overlaps text \"second\"",
        "\"0.00\" crosses a plot's frame",
    ] {
        assert!(all.contains(want), "not found: {want}\n{all}");
    }
    // a label clear of everything passes
    let ok = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100pt\" height=\"100pt\" viewBox=\"0 0 100 100\">\n\
<rect class=\"frame\" x=\"10\" y=\"10\" width=\"80\" height=\"80\" fill=\"none\"/>\n\
<path class=\"c\" d=\"M10 50L90 50\" stroke=\"#000\"><title>curve</title></path>\n\
<text class=\"t\" x=\"20\" y=\"40\" font-size=\"7\" text-anchor=\"start\">clear</text>\n\
</svg>\n";
    assert!(overlaps(&drawing(ok)).is_empty());
}

#[test]
fn every_csv_has_the_tidy_ascii_schema() {
    let dir = quick_report();
    let mut csvs: Vec<PathBuf> = Vec::new();
    for sub in [dir.to_path_buf(), dir.join("figures")] {
        for e in std::fs::read_dir(&sub).expect("dir") {
            let p = e.expect("entry").path();
            if p.extension().is_some_and(|x| x == "csv") {
                csvs.push(p);
            }
        }
    }
    assert!(csvs.len() >= 18, "only {} CSVs", csvs.len());
    for p in csvs {
        let text = std::fs::read_to_string(&p).expect("csv");
        assert!(text.is_ascii(), "{}: not ASCII", p.display());
        let mut lines = text.lines();
        assert_eq!(
            lines.next(),
            Some(cylroll::report::csv::HEADER),
            "{}: header",
            p.display()
        );
        let mut n = 0;
        for l in lines {
            n += 1;
            let c: Vec<&str> = l.split(',').collect();
            assert!(c.len() >= 7, "{}: {l}", p.display());
            let digits = c[c.len() - 1];
            assert!(
                digits.parse::<u32>().is_ok() || ["exact", "interpolated"].contains(&digits),
                "{}: digits {digits:?} in {l}",
                p.display()
            );
            let value = c[c.len() - 2];
            assert!(
                value.parse::<f64>().is_ok(),
                "{}: value {value:?} in {l}",
                p.display()
            );
            assert!(
                !c[c.len() - 3].is_empty(),
                "{}: no unit in {l}",
                p.display()
            );
        }
        assert!(n > 0, "{}: no rows", p.display());
    }
}
