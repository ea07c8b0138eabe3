//! The report: figures and tables for the built-in cases (`cylroll report`).
//!
//! [`run`] writes into a directory:
//! - `index.html` and `README.md`: one page with a contents list, the tables
//!   and the figures in collapsible sections;
//! - for every figure `figures/NAME.svg` (178 mm, two journal columns) and
//!   `figures/NAME.narrow.svg` (85 mm, one column; the phone layout), a vector
//!   PDF beside each (`NAME.pdf`, `NAME.narrow.pdf`, the font embedded) and
//!   its data `figures/NAME.csv`;
//! - every table's numbers as CSV (`TABLE.csv`, and `plane.csv` with every
//!   point of the parameter plane), all CSVs in one tidy ASCII schema
//!   ([`csv`]);
//! - `engines.html`, generated from the committed conformance scorecards
//!   ([`engines`]), and `audit.html` from `audit.md` when present.
//!
//! **Drawing.** plotters is the drawing layer: it builds each panel's
//! coordinates, frame, ticks, tick labels, grid and axis titles and draws
//! the curves, shading, patches and markers, on cylroll's own
//! `DrawingBackend` ([`canvas`]), which writes SVG in points at 1/100 pt
//! (plotters' coordinates are whole numbers, so the canvas is 100× larger
//! than the figure and every coordinate is divided back), with a class,
//! a dash pattern and a hover `<title>` on what it draws. cylroll keeps
//! only what plotters lacks: the two layouts at print widths ([`render`]),
//! direct labels placed clear of every curve, marker, line and text
//! ([`labels`]), the legend in one order and the colour bar ([`legend`]).
//! Crates do the rest: `contour` (marching squares) for the map's
//! iso-lines, `svg2pdf`/`usvg` for the PDF with the embedded DejaVu Sans
//! (`src/report/font/`), `ttf-parser` to measure text with that font. No
//! raster: the map is one vector cell per computed node, so no PNG or
//! base64 is needed.
//!
//! Every plotted point is an oracle answer verified to
//! [`Config::plot_digits`] digits and only then rounded to `f64`; every
//! table entry is printed with exactly its verified digits. Time figures
//! are sampled at their events ([`track`]).
//!
//! Deterministic: the work runs on a few threads, but each result lands in a
//! fixed slot and nothing volatile is written (the engines page's stamp is
//! the source commit and its date), so two runs give byte-identical files.
//! The files are written as one set (each to a temporary file renamed over
//! the old one). Files of other tools in the directory are left alone.

pub mod axes;
pub mod branch;
pub mod canvas;
pub mod csv;
pub mod data;
pub mod diagram;
pub mod engines;
pub mod fig_main;
pub mod fig_plane;
pub mod fig_variants;
pub mod friction;
pub mod labels;
pub mod legend;
pub mod marks;
pub mod math;
pub mod model;
pub mod page;
pub mod pdf;
pub mod render;
pub mod tables;
pub mod tidy;
pub mod track;

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
    /// Where the conformance scorecards are (`golden/engines`).
    pub engines: std::path::PathBuf,
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
            engines: std::path::PathBuf::from("golden/engines"),
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
             the top); angles in radians (degrees in parentheses). θ is the line of centres measured clockwise from the vertical; φ₁ the clockwise rotation of \
             cylinder 1; φ₂ the paper's angle (eq. 2) counted from the start (φ₂ = 0 at t = 0; the paper's is φ₂ − r₁θ₀/r₂). F₁, N₁: the floor's force on cylinder 1 (the holder's when \
             it is fixed); F₂₁: the friction force of cylinder 1 on cylinder 2; N₁₂: the normal force between the \
             cylinders, which vanishes at separation θₛ. A start from rest exactly at the top takes infinitely \
             long, so the plots against time start from rest at θ₀ = {}; the plots against θ and the main tables \
             are the limit θ₀ → 0+.",
            "τ = √(r₁/g)",
            data::THETA0_TIME
        ),
        "Every figure is drawn for print at one journal column (85 mm) and two (178 mm), with a vector PDF of each \
         and its data as CSV; the page shows the one-column layout on a phone. Regenerate with \
         `cargo run --release -- report` (deterministic: a second run writes the same bytes)."
            .to_string(),
    ]
}

/// The Markdown documents of other tools that the report renders as pages
/// when they are present in its directory: (Markdown file, HTML file, title).
pub const DOCUMENTS: [(&str, &str, &str); 1] = [(
    "audit.md",
    "audit.html",
    "the audit of the paper's formulas, with its errata",
)];

/// The engines page's title in the index.
const ENGINES: &str = "physics engines held against the oracle (conformance scorecards)";

/// Writes the report into `dir` with the given configuration and returns a
/// summary: the files written and any problem met (points that could not be
/// verified, closed forms that disagree).
pub fn run_with(dir: &Path, cfg: &Config) -> Result<String> {
    // an unwritable destination is refused before the work
    crate::golden::fileset::check_writable(dir, &["", "figures"])?;
    let (pb, show) = progress_bar(cfg);
    let data = data::compute(cfg, &pb, show)?;
    pb.set_message("friction");
    let fdata = friction::compute(cfg);
    pb.set_message("branches");
    let stay = data
        .time
        .first()
        .and_then(|r| r.as_ref().ok())
        .map(|c| c.track.clone());
    let bdata = branch::compute(cfg.plot_digits, cfg.time_points.clamp(8, 60), stay);
    pb.set_message("drawing");
    let mut figs = figures(&data, &bdata, &fdata, cfg);
    let tabs = tables::tables(&data, cfg)?;
    let ftable = friction::table(&fdata);

    let (mut files, dropped) = figure_files(&mut figs)?;
    let mut all_tables = tabs.tables.clone();
    all_tables.push(ftable.clone());
    for t in &all_tables {
        if !t.csv.is_empty() {
            files.push((
                t.csv.clone().into(),
                csv::write(&tidy::table_records(t)).into_bytes(),
            ));
        }
    }
    files.push((
        "plane.csv".into(),
        csv::write(&tidy::plane_records(&data.plane)).into_bytes(),
    ));
    let blocks = page_blocks(&figs, &tabs, ftable);
    // other pages: the audit (when present) and the engines page
    let mut pages: page::Pages = Vec::new();
    for (md, html, title) in DOCUMENTS {
        if let Ok(text) = std::fs::read_to_string(dir.join(md)) {
            files.push((html.into(), page::markdown_page(&text, title).into_bytes()));
            pages.push((html.to_string(), title.to_string()));
        }
    }
    let (cards, card_problems) = engines::read(&cfg.engines);
    let shown = if cfg.engines.is_absolute() {
        "golden/engines".to_string()
    } else {
        cfg.engines.display().to_string()
    };
    files.push((
        "engines.html".into(),
        engines::page(&cards, &shown, &engines::report_stamp()).into_bytes(),
    ));
    pages.push((
        "engines.html".into(),
        if cards.is_empty() {
            format!("{ENGINES}: none committed yet")
        } else {
            format!(
                "{ENGINES}: {}",
                cards
                    .iter()
                    .map(|c| c.dir.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        },
    ));
    let intro = intro(cfg);
    let md = page::markdown(TITLE, &intro, &blocks, &pages);
    let html = page::html(TITLE, &intro, &blocks, &pages);
    for (name, text) in [("README.md", &md), ("index.html", &html)] {
        files.push((name.into(), text.as_bytes().to_vec()));
    }
    crate::golden::fileset::write_set(dir, &files)?;
    let stale = remove_stale_figures(dir, &files)?;
    pb.finish_and_clear();

    let mut out = format!(
        "report written to {}: index.html, README.md, engines.html ({} scorecards), {} other pages, {} table CSVs and {} figures (SVG and PDF at 178 and 85 mm, CSV) in figures/\n",
        dir.display(),
        cards.len(),
        pages.len() - 1,
        all_tables.len() + 1,
        figs.len()
    );
    let mut problems = tabs.problems.clone();
    problems.extend(card_problems);
    if let Err(e) = &bdata {
        problems.push(format!("the branch figure: {e}"));
    }
    if let Err(e) = &fdata.traj {
        problems.push(format!("the friction figure: {e}"));
    }
    if !stale.is_empty() {
        out.push_str(&format!(
            "removed {} figure files of an earlier report: {}\n",
            stale.len(),
            stale.join(", ")
        ));
    }
    for d in &dropped {
        out.push_str(&format!(
            "note: label left out for want of room (the legend and hover text carry it): {d}\n"
        ));
    }
    if problems.is_empty() {
        out.push_str("every table entry verified; every closed form agrees to all digits shown\n");
    } else {
        for p in &problems {
            out.push_str(&format!("problem: {p}\n"));
        }
    }
    Ok(out)
}

/// Every figure, in page order.
pub fn figures(
    data: &data::Data,
    bdata: &Result<branch::BranchData>,
    fdata: &friction::FrictionData,
    cfg: &Config,
) -> Vec<model::Figure> {
    let mut figs = vec![diagram::figure()];
    figs.extend(fig_main::main_motion(data));
    figs.extend(fig_main::main_forces(data));
    figs.extend(fig_main::main_friction(data));
    if let Ok(b) = bdata {
        figs.extend(fig_main::main_branch(b, cfg.plot_digits));
    }
    figs.extend(fig_variants::variants_motion(data));
    figs.extend(fig_variants::variants_forces(data));
    figs.push(fig_plane::plane_curves(data, cfg));
    figs.extend(fig_plane::plane_map(data, cfg));
    figs.extend(friction::figures(fdata, cfg.plot_digits));
    figs
}

/// Removes from `figures/` the figure files (`.svg`, `.pdf`, `.csv`,
/// `.png`) that this run did not write: figures of an earlier version of the
/// report. `figures/` is the report's own; nothing else is touched. Returns
/// their names.
fn remove_stale_figures(dir: &Path, files: &[File]) -> Result<Vec<String>> {
    let written: std::collections::BTreeSet<&std::path::Path> =
        files.iter().map(|f| f.0.as_path()).collect();
    let mut removed = Vec::new();
    let Ok(rd) = std::fs::read_dir(dir.join("figures")) else {
        return Ok(removed);
    };
    let mut names: Vec<String> = rd
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    for name in names {
        let rel = std::path::PathBuf::from("figures").join(&name);
        let ours = [".svg", ".pdf", ".csv", ".png"]
            .iter()
            .any(|x| name.ends_with(x));
        if ours && !name.starts_with('.') && !written.contains(rel.as_path()) {
            std::fs::remove_file(dir.join(&rel)).map_err(|e| crate::error::Error::Write {
                path: dir.join(&rel).display().to_string(),
                what: format!("removing a figure of an earlier report: {e}"),
            })?;
            removed.push(name);
        }
    }
    Ok(removed)
}

/// A file of the report: its path in the directory and its bytes.
type File = (std::path::PathBuf, Vec<u8>);

/// Every figure's SVG and PDF in both layouts, and its CSV; records the
/// sizes drawn in the figure. Also returns the labels left out for want of
/// a free place, by figure and layout.
fn figure_files(figs: &mut [model::Figure]) -> Result<(Vec<File>, Vec<String>)> {
    let mut files = Vec::new();
    let mut dropped = Vec::new();
    for f in figs.iter_mut() {
        for (k, layout) in [render::Layout::Wide, render::Layout::Narrow]
            .into_iter()
            .enumerate()
        {
            let r = render::render(f, layout);
            f.sizes[k] = r.size;
            for d in r.dropped {
                dropped.push(format!("{} ({layout:?}): {d}", f.stem));
            }
            let svg = r.svg;
            let pdf = pdf::pdf(&svg).map_err(|e| {
                crate::error::Error::not_physical(format!("{}: the PDF: {e}", f.stem))
            })?;
            let (svg_p, pdf_p) = (
                if k == 0 {
                    page::figure_path(f)
                } else {
                    page::narrow_path(f)
                },
                page::pdf_path(f, k == 1),
            );
            files.push((svg_p.into(), svg.into_bytes()));
            files.push((pdf_p.into(), pdf));
        }
        if let Some(c) = page::csv_path(f) {
            files.push((c.into(), csv::figure(f).into_bytes()));
        }
    }
    Ok((files, dropped))
}

/// The page in order: the sections with their tables and figures, then the
/// notes and the data files.
fn page_blocks(
    figs: &[model::Figure],
    tabs: &tables::Tables,
    ftable: page::Table,
) -> Vec<page::Block> {
    use page::Block;
    let fig = |stem: &str| -> Vec<Block> {
        figs.iter()
            .filter(|f| f.stem == stem)
            .cloned()
            .map(Block::Figure)
            .collect()
    };
    let table = |i: usize| tabs.tables.get(i).cloned().map(Block::Table);
    let mut b = vec![Block::Heading("Sign conventions".into())];
    b.extend(fig("conventions"));
    b.push(Block::Heading("Separation in every contact model".into()));
    b.extend((0..2).filter_map(table));
    b.push(Block::Heading(
        "The main case: both contacts rolling".into(),
    ));
    for s in ["main_motion", "main_forces"] {
        b.extend(fig(s));
    }
    b.extend((2..4).filter_map(table));
    for s in ["main_friction", "main_branch"] {
        b.extend(fig(s));
    }
    b.push(Block::Heading("All contact models".into()));
    for s in ["variants_motion", "variants_forces"] {
        b.extend(fig(s));
    }
    b.push(Block::Heading("The parameter plane".into()));
    b.extend((4..tabs.tables.len()).filter_map(table));
    for s in ["plane_curves", "plane_map"] {
        b.extend(fig(s));
    }
    b.push(Block::Heading("Finite Coulomb friction".into()));
    b.push(Block::Table(ftable));
    for s in ["friction_main", "friction_map", "friction_plane"] {
        b.extend(fig(s));
    }
    b.push(Block::Heading("Notes and data".into()));
    b.push(Block::Section(tabs.notes.clone()));
    b.push(Block::Section(data_files(figs, tabs)));
    b
}

/// The section "Data files": every CSV, in one schema.
fn data_files(figs: &[model::Figure], tabs: &tables::Tables) -> page::Section {
    let mut links: Vec<(String, String)> = tabs
        .tables
        .iter()
        .map(|t| (t.csv.clone(), format!("{}: {}", t.csv, t.title)))
        .collect();
    links.push((
        "friction-events.csv".into(),
        "friction-events.csv: the events of the main case with Coulomb friction".into(),
    ));
    links.push((
        "plane.csv".into(),
        "plane.csv: θₛ at every point of the parameter plane computed for the figures and tables"
            .into(),
    ));
    for f in figs {
        if let Some(c) = page::csv_path(f) {
            links.push((c.clone(), format!("{c}: the data of “{}”", f.title)));
        }
    }
    page::Section {
        title: "Data files".into(),
        paragraphs: vec![format!(
            "Every CSV has the same tidy ASCII schema, one value per row: `{}`. `case` names the curve or the table's row (key=value pairs joined by `;`), `point` numbers the samples of a curve, `phase` is the motion's phase there (floor/contact state, or flight), `quantity` and `unit` are ASCII (angles in rad, time in tau = sqrt(r1/g), forces in m1*g), `value` is a decimal and `digits` its verified significant digits (`exact` for an input such as a requested time, `15` for a closed form in double precision, `interpolated` for a contour between verified nodes).",
            csv::HEADER
        )],
        items: Vec::new(),
        links,
    }
}
