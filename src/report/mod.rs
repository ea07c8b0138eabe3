//! The report: figures and tables for the built-in cases (`cylroll report`).
//!
//! [`run`] writes into a directory:
//! - `figures/*.svg`: θ(t), dθ/dt, φ1(t), φ2(t) and the contact forces F1,
//!   N1, F21, N12 against t and against θ for the paper's main case and for
//!   every contact model (overlaid where comparison is the point), the
//!   friction coefficient needed, and θs over the (m2/m1, k2) plane with the
//!   fixed-lower closed form;
//! - `index.html` and `README.md`: one page with every figure and the tables
//!   (separation angles and times per contact model with verified digits and
//!   their closed forms, forces, slip angles, the parameter plane);
//! - `separation.csv`, `plane.csv`: the tables' numbers as decimal strings.
//!
//! Every plotted point is an oracle answer verified to
//! [`Config::plot_digits`] digits and only then rounded to `f64`; every table
//! entry is printed with exactly its verified digits.
//!
//! Deterministic: the work runs on a few threads, but each result lands in a
//! fixed slot, tick labels are formatted with fixed decimals and nothing
//! volatile is written, so two runs give byte-identical files. Each file is
//! written to a temporary file in the same directory and renamed over the old
//! one, so an interrupted run leaves the previous files intact. Files of
//! other tools in the directory (e.g. `audit.md`) are left alone.

pub mod data;
pub mod diagram;
pub mod figures;
pub mod friction;
pub mod page;
pub mod plot;
pub mod tables;

use crate::error::Result;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::path::Path;

/// What the report computes, and how finely.
#[derive(Debug, Clone)]
pub struct Config {
    /// Significant digits of the tables.
    pub digits: u32,
    /// Significant digits verified for every plotted point.
    pub plot_digits: u32,
    /// Intervals of each trajectory (time plots): points = intervals + 1.
    pub time_points: usize,
    /// Intervals of each curve against θ.
    pub theta_points: usize,
    /// Decades of m2/m1 of the curves θs(m2/m1): 10^lo ..= 10^hi.
    pub ratio_range: (i32, i32),
    /// Points per decade of those curves.
    pub ratio_per_decade: usize,
    /// Intervals of k2 over [0, 2] of the curves θs(k2).
    pub k2_steps: usize,
    /// Decades of m2/m1 of the heat map.
    pub heat_ratio_range: (i32, i32),
    /// Nodes per decade of the heat map.
    pub heat_per_decade: usize,
    /// Intervals of k2 over [0, 2] of the heat map.
    pub heat_k2_steps: usize,
    /// Significant digits of the parameter-plane table.
    pub plane_table_digits: u32,
    /// Points per decade of μ in the friction map (0.01 to 100).
    pub friction_per_decade: usize,
    /// Points per decade of each coefficient in the (μ_floor, μ_contact) map.
    pub friction_plane_per_decade: usize,
    /// Worker threads (the result does not depend on it).
    pub threads: usize,
    /// Show progress bars (only when stderr is a terminal).
    pub progress: bool,
}

impl Config {
    /// The configuration of `cylroll report`.
    pub fn full() -> Self {
        Config {
            digits: 20,
            plot_digits: 12,
            time_points: 120,
            theta_points: 180,
            ratio_range: (-2, 2),
            ratio_per_decade: 8,
            k2_steps: 24,
            heat_ratio_range: (-2, 2),
            heat_per_decade: 12,
            heat_k2_steps: 40,
            plane_table_digits: 15,
            friction_per_decade: 8,
            friction_plane_per_decade: 3,
            threads: default_threads(),
            progress: false,
        }
    }

    /// A small configuration for tests: the same files, coarser curves.
    pub fn quick() -> Self {
        Config {
            plot_digits: 8,
            time_points: 8,
            theta_points: 10,
            ratio_range: (-1, 1),
            ratio_per_decade: 1,
            k2_steps: 4,
            heat_ratio_range: (-1, 1),
            heat_per_decade: 1,
            heat_k2_steps: 4,
            plane_table_digits: 12,
            friction_per_decade: 1,
            friction_plane_per_decade: 1,
            ..Config::full()
        }
    }
}

impl Default for Config {
    fn default() -> Self {
        Config::full()
    }
}

fn default_threads() -> usize {
    std::thread::available_parallelism()
        .map(|n| n.get())
        .unwrap_or(1)
        .min(8)
}

/// Writes the report (figures, README.md, index.html) into `reports_dir` and
/// returns a summary to print. `progress` shows a progress bar on stderr when
/// it is a terminal.
pub fn run(reports_dir: &Path, progress: bool) -> Result<String> {
    let mut cfg = Config::full();
    cfg.progress = progress;
    run_with(reports_dir, &cfg)
}

/// A progress bar that draws nothing until [`show_progress`] is called (so
/// that it never shows an empty 0/0 bar), and never unless asked for and
/// stderr is a terminal.
fn progress_bar(cfg: &Config) -> (ProgressBar, bool) {
    let show = cfg.progress && std::io::stderr().is_terminal();
    let pb = ProgressBar::with_draw_target(Some(0), ProgressDrawTarget::hidden());
    if let Ok(style) =
        ProgressStyle::with_template("{prefix} [{bar:30}] {pos}/{len} {elapsed} (eta {eta}) {msg}")
    {
        pb.set_style(style.progress_chars("=> "));
    }
    pb.set_prefix("cylroll report");
    (pb, show)
}

/// Starts drawing `pb` on stderr if `show`.
pub(crate) fn show_progress(pb: &ProgressBar, show: bool) {
    if show {
        pb.set_draw_target(ProgressDrawTarget::stderr());
    }
}

/// The page's title.
const TITLE: &str = "cylroll report: a cylinder rolling on a rolling cylinder";

fn intro(cfg: &Config) -> Vec<String> {
    vec![
        "Figures and tables computed by cylroll, the arbitrary-precision reference oracle for the problem of \
         K. T. McDonald's \"Cylinder Rolling on Another Rolling Cylinder\": cylinder 2 rolls on cylinder 1, which \
         stands on a horizontal floor, from near the top until the two separate. Six contact models are shown: \
         the floor rolling (no slip), frictionless (slip) or holding cylinder 1 fixed, times the contact between \
         the cylinders rolling or frictionless."
            .to_string(),
        format!(
            "Every number in a table is printed with exactly the digits the oracle verified ({} significant \
             digits unless a table says otherwise): each was computed at two working precisions together with \
             the method's own error estimate, and is printed only when every value inside the error bound rounds \
             to the same digits (an estimate, not a rigorous enclosure: see the project README, \"Guarantees\"). \
             Every plotted point is an oracle answer verified to {} digits, rounded to double precision for \
             drawing only.",
            cfg.digits, cfg.plot_digits
        ),
        format!(
            "Units and conventions: unless said otherwise m₁ = m₂ = r₁ = r₂ = g = 1 and k₁ = k₂ = 1/2 (identical \
             solid cylinders); time in units of {} and forces in units of m₁g (so N₁ = 2 and N₁₂ = 1 at rest at \
             the top). θ is the line of centres measured clockwise from the vertical; φ₁ the clockwise rotation of \
             cylinder 1; φ₂ the paper's angle (eq. 2). F₁, N₁: the floor's force on cylinder 1 (the holder's when \
             it is fixed); F₂₁: the friction force of cylinder 1 on cylinder 2; N₁₂: the normal force between the \
             cylinders, which vanishes at separation θₛ. A start from rest exactly at the top takes infinitely \
             long, so the plots against time start from rest at θ₀ = {}; the plots against θ and the main tables \
             are the limit θ₀ → 0+.",
            figures::TAU,
            data::THETA0_TIME
        ),
        "Regenerate with `cargo run --release -- report` (deterministic: a second run writes the same bytes)."
            .to_string(),
    ]
}

/// The Markdown documents of other tools that the report renders as pages
/// when they are present in its directory: (Markdown file, HTML file, title).
pub const DOCUMENTS: [(&str, &str, &str); 2] = [
    (
        "audit.md",
        "audit.html",
        "the audit of the paper's formulas, with its errata",
    ),
    (
        "engines.md",
        "engines.html",
        "physics engines held against the oracle",
    ),
];

/// Writes the report into `dir` with the given configuration and returns a
/// summary: the files written and any problem met (points that could not be
/// verified, closed forms that disagree).
pub fn run_with(dir: &Path, cfg: &Config) -> Result<String> {
    let (pb, show) = progress_bar(cfg);
    let data = data::compute(cfg, &pb, show)?;
    pb.set_message("friction");
    let fdata = friction::compute(cfg);
    pb.set_message("drawing");
    let mut figs = figures::figures(&data, cfg);
    figs.extend(friction::figures(&fdata));
    let tabs = tables::tables(&data, cfg)?;

    // the page, its tables and its figures change as one set
    let mut files = figure_files(&figs, cfg);
    let blocks = page_blocks(&figs, &tabs, &fdata, cfg);
    // other tools' documents, rendered as pages of the report
    let mut pages: page::Pages = Vec::new();
    for (md, html, title) in DOCUMENTS {
        if let Ok(text) = std::fs::read_to_string(dir.join(md)) {
            files.push((html.into(), page::markdown_page(&text, title).into_bytes()));
            pages.push((html.to_string(), title.to_string()));
        }
    }
    let intro = intro(cfg);
    let md = page::markdown(TITLE, &intro, &blocks, &pages);
    let html = page::html(TITLE, &intro, &blocks, &pages);
    for (name, text) in [
        ("separation.csv", &tabs.separation_csv),
        ("plane.csv", &tabs.plane_csv),
        ("README.md", &md),
        ("index.html", &html),
    ] {
        files.push((name.into(), text.as_bytes().to_vec()));
    }
    crate::golden::fileset::write_set(dir, &files)?;
    pb.finish_and_clear();

    let mut out = format!(
        "report written to {}: index.html, README.md, {} pages, separation.csv, plane.csv and {} figures (SVG, narrow SVG, CSV) in figures/\n",
        dir.display(),
        pages.len(),
        figs.len()
    );
    if tabs.problems.is_empty() {
        out.push_str("every table entry verified; every closed form agrees to all digits shown\n");
    } else {
        for p in &tabs.problems {
            out.push_str(&format!("problem: {p}\n"));
        }
    }
    Ok(out)
}

/// A file of the report: its path in the directory and its bytes.
type File = (std::path::PathBuf, Vec<u8>);

/// Every figure's SVG, narrow SVG and CSV.
fn figure_files(figs: &[plot::Figure], cfg: &Config) -> Vec<File> {
    let mut files = Vec::new();
    let sig = cfg.plot_digits as usize;
    for f in figs {
        files.push((
            Path::new("figures").join(&f.file),
            plot::render_layout(f, plot::Layout::Wide).into_bytes(),
        ));
        if let Some(n) = page::narrow_path(f) {
            files.push((
                n.into(),
                plot::render_layout(f, plot::Layout::Narrow).into_bytes(),
            ));
        }
        if let Some(c) = page::csv_path(f) {
            files.push((c.into(), plot::figure_csv(f, sig).into_bytes()));
        }
    }
    files
}

/// The page in order: the sections with their tables and figures, then the
/// notes and the data files.
fn page_blocks(
    figs: &[plot::Figure],
    tabs: &tables::Tables,
    fdata: &friction::FrictionData,
    cfg: &Config,
) -> Vec<page::Block> {
    use page::Block;
    let with_prefix = |p: &str| -> Vec<Block> {
        figs.iter()
            .filter(|f| f.file.starts_with(p))
            .cloned()
            .map(Block::Figure)
            .collect()
    };
    let table = |i: usize| tabs.tables.get(i).cloned().map(Block::Table);
    let mut blocks = vec![Block::Heading("Sign conventions".into())];
    blocks.extend(with_prefix("conventions.svg"));
    blocks.push(Block::Heading("Tables".into()));
    blocks.extend((0..2).filter_map(table));
    blocks.push(Block::Heading(
        "The main case: both contacts rolling".into(),
    ));
    // the tables after the first two, but the last (the parameter plane)
    let last = tabs.tables.len().saturating_sub(1);
    blocks.extend((2..last).filter_map(table));
    blocks.extend(with_prefix("main_"));
    blocks.push(Block::Heading("All contact models".into()));
    blocks.extend(with_prefix("variants_"));
    blocks.extend(with_prefix("variant_"));
    blocks.push(Block::Heading("The parameter plane".into()));
    blocks.extend((last.max(2)..tabs.tables.len()).filter_map(table));
    blocks.extend(with_prefix("plane_"));
    blocks.push(Block::Heading("Finite Coulomb friction".into()));
    blocks.push(Block::Table(friction::table(fdata)));
    blocks.extend(with_prefix("friction_"));
    blocks.push(Block::Heading("Notes and data".into()));
    blocks.push(Block::Section(tabs.notes.clone()));
    blocks.push(Block::Section(data_files(figs, cfg)));
    blocks
}

/// The section "Data files": the tables' CSV files and every figure's.
fn data_files(figs: &[plot::Figure], cfg: &Config) -> page::Section {
    let mut links = vec![
        (
            "separation.csv".to_string(),
            "separation.csv: θₛ, tₛ and F₂₁ at separation per contact model and start, with the closed forms"
                .to_string(),
        ),
        (
            "plane.csv".to_string(),
            "plane.csv: θₛ at every point of the parameter plane computed for the figures and the table"
                .to_string(),
        ),
    ];
    for f in figs {
        if let Some(c) = page::csv_path(f) {
            links.push((c.clone(), format!("{c}: the data of “{}”", f.title)));
        }
    }
    page::Section {
        title: "Data files".into(),
        paragraphs: vec![format!(
            "The tables' numbers as CSV (decimal strings with only verified digits), and beside every figure the data it \
             plots (`figures/NAME.csv`: one row per plotted point, values to the {} digits verified for the plots).",
            cfg.plot_digits
        )],
        items: Vec::new(),
        links,
    }
}
