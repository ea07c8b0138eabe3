//! Figures as plain data ([`Figure`], [`Panel`], [`Series`]), rendered to SVG
//! by [`render`].
//!
//! The one place of the crate where `f64` is used for numbers: the plotted
//! points are oracle values (already verified to the digits the report asks
//! for) rounded to `f64`.
//!
//! The SVG is written here directly (no plotting crate): coordinates keep
//! two decimals of a pixel, so a curve through verified points is drawn as
//! smooth as the points allow (plotters' SVG backend snaps every coordinate to
//! a whole pixel, which turned every curve into a staircase). Writing the SVG
//! ourselves also gives what a reader needs and plotters has no element for:
//! `<title>` hover text on every curve and marker, marker shapes that differ
//! per curve (legible in greyscale), direct labels, contour labels, a smooth
//! colour bar, and typography (Unicode subscripts, a true minus sign).
//!
//! Every figure is rendered in two layouts: [`Layout::Wide`] (panels in the
//! figure's grid, legend on the right) and [`Layout::Narrow`] (one column,
//! legend below) for phone-width pages.
//!
//! - data outside the axis range is never drawn: every polyline is clipped to
//!   the axis box (Liang–Barsky) and markers outside it are dropped;
//! - tick positions and labels are computed here ([`nice_ticks`]) with a
//!   fixed number of decimals, so the SVG text is a pure function of the
//!   data: two runs write byte-identical files.

use crate::error::Result;
use std::fmt::Write as _;

/// A colour, as 8-bit RGB.
pub type Rgb = (u8, u8, u8);

/// Colours of the Okabe–Ito palette (distinguishable with colour-blindness).
pub const PALETTE: [Rgb; 7] = [
    (0, 114, 178),   // blue
    (213, 94, 0),    // vermillion
    (0, 158, 115),   // bluish green
    (204, 121, 167), // reddish purple
    (230, 159, 0),   // orange
    (86, 180, 233),  // sky blue
    (0, 0, 0),       // black
];

/// Font family of every text (the figures and the page use the same).
pub const FONT: &str = "DejaVu Sans, Verdana, Arial, sans-serif";

/// How a line is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dash {
    /// Solid.
    Solid,
    /// Dashed (long dashes).
    Dashed,
    /// Dotted (short dashes).
    Dotted,
    /// Dash-dot.
    DashDot,
}

impl Dash {
    fn array(self) -> Option<&'static str> {
        match self {
            Dash::Solid => None,
            Dash::Dashed => Some("9 5"),
            Dash::Dotted => Some("2 3"),
            Dash::DashDot => Some("10 4 2 4"),
        }
    }
}

/// A marker shape: every curve of a panel gets its own, so that curves stay
/// apart in greyscale and for colour-blind readers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// ○
    Circle,
    /// □
    Square,
    /// △
    Triangle,
    /// ◇
    Diamond,
    /// ▽
    TriangleDown,
    /// ×
    Cross,
}

/// The shapes in the order curves get them.
pub const SHAPES: [Shape; 6] = [
    Shape::Circle,
    Shape::Square,
    Shape::Triangle,
    Shape::Diamond,
    Shape::TriangleDown,
    Shape::Cross,
];

/// One curve.
#[derive(Debug, Clone)]
pub struct Series {
    /// Legend text (empty: not in the legend).
    pub label: String,
    /// Colour.
    pub color: Rgb,
    /// Line style.
    pub dash: Dash,
    /// Line width in px.
    pub width: f64,
    /// Points in data coordinates (x as given, also for a log axis).
    pub points: Vec<(f64, f64)>,
    /// Marker shape of the curve (legend, periodic and end markers).
    pub shape: Option<Shape>,
    /// A marker every `every` points (0: none), starting at point `phase`.
    pub every: usize,
    /// Offset of the periodic markers.
    pub phase: usize,
    /// Hover text of a hollow marker at the curve's last point (None: no
    /// end marker). Used for the values at separation.
    pub end: Option<String>,
    /// A label written next to the curve's last point (direct labelling).
    pub direct: Option<String>,
}

impl Series {
    /// A solid curve of width 2.
    pub fn new(label: impl Into<String>, color: Rgb, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.into(),
            color,
            dash: Dash::Solid,
            width: 2.0,
            points,
            shape: None,
            every: 0,
            phase: 0,
            end: None,
            direct: None,
        }
    }

    /// The same curve with another line style.
    pub fn dashed(mut self, dash: Dash) -> Self {
        self.dash = dash;
        self
    }

    /// The same curve with a marker shape.
    pub fn shape(mut self, s: Shape) -> Self {
        self.shape = Some(s);
        self
    }

    /// The same curve with a hollow marker (its shape) at its last point.
    pub fn end_marker(mut self, title: impl Into<String>) -> Self {
        self.end = Some(title.into());
        self
    }

    /// The same curve with periodic markers.
    pub fn every(mut self, every: usize, phase: usize) -> Self {
        self.every = every;
        self.phase = phase;
        self
    }

    /// The same curve with a direct label at its end.
    pub fn direct(mut self, text: impl Into<String>) -> Self {
        self.direct = Some(text.into());
        self
    }
}

/// A filled rectangle in data coordinates (shaded phases).
#[derive(Debug, Clone)]
pub struct Cell {
    /// Lower-left corner.
    pub lo: (f64, f64),
    /// Upper-right corner.
    pub hi: (f64, f64),
    /// Fill colour.
    pub color: Rgb,
    /// Hover text.
    pub title: String,
}

/// A marked point (an event).
#[derive(Debug, Clone)]
pub struct Marker {
    /// Position in data coordinates.
    pub at: (f64, f64),
    /// Colour.
    pub color: Rgb,
    /// Shape.
    pub shape: Shape,
    /// Filled (else hollow: a coloured outline).
    pub filled: bool,
    /// Hover text.
    pub title: String,
    /// Text written beside the marker.
    pub label: Option<String>,
}

impl Marker {
    /// A filled circle with hover text.
    pub fn new(at: (f64, f64), color: Rgb, title: impl Into<String>) -> Self {
        Marker {
            at,
            color,
            shape: Shape::Circle,
            filled: true,
            title: title.into(),
            label: None,
        }
    }

    /// A filled marker of `shape`, with a text beside it if `label`.
    pub fn shaped(
        shape: Shape,
        at: (f64, f64),
        color: Rgb,
        title: String,
        label: Option<String>,
    ) -> Self {
        Marker {
            shape,
            label,
            ..Marker::new(at, color, title)
        }
    }
}

/// A vertical or horizontal reference line across the plot area, with a label
/// at its end.
#[derive(Debug, Clone)]
pub struct RefLine {
    /// x (vertical line) or y (horizontal line), data coordinates.
    pub at: f64,
    /// Vertical (x = at) or horizontal (y = at).
    pub vertical: bool,
    /// Colour.
    pub color: Rgb,
    /// Line style.
    pub dash: Dash,
    /// Label (at the top of a vertical line, the right end of a horizontal one).
    pub label: String,
}

/// A text in data coordinates on a white halo (contour labels).
#[derive(Debug, Clone)]
pub struct Label {
    /// Centre of the text.
    pub at: (f64, f64),
    /// Text.
    pub text: String,
}

/// An entry of the legend that no series provides (events, reference lines).
#[derive(Debug, Clone)]
pub struct LegendEntry {
    /// Text.
    pub label: String,
    /// Colour.
    pub color: Rgb,
    /// A line sample in this style (None: none).
    pub dash: Option<Dash>,
    /// A marker sample.
    pub shape: Option<Shape>,
    /// Whether the marker sample is filled.
    pub filled: bool,
}

impl LegendEntry {
    /// A line sample.
    pub fn line(label: impl Into<String>, color: Rgb, dash: Dash) -> Self {
        LegendEntry {
            label: label.into(),
            color,
            dash: Some(dash),
            shape: None,
            filled: false,
        }
    }

    /// A marker sample, filled or hollow.
    pub fn marker(label: impl Into<String>, color: Rgb, shape: Shape, filled: bool) -> Self {
        LegendEntry {
            label: label.into(),
            color,
            dash: None,
            shape: Some(shape),
            filled,
        }
    }
}

/// A raster image over a rectangle of the chart (a heat map), drawn smooth.
#[derive(Debug, Clone)]
pub struct Raster {
    /// x range in chart coordinates (log10 for a log axis).
    pub x: (f64, f64),
    /// y range.
    pub y: (f64, f64),
    /// Width and height in pixels.
    pub w: usize,
    /// Height.
    pub h: usize,
    /// Pixels, row by row from the top.
    pub pixels: Vec<Rgb>,
}

/// An axis scale.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// Linear.
    Linear,
    /// Base-10 logarithmic (positive data only).
    Log,
}

/// One chart: axes, curves, markers.
#[derive(Debug, Clone)]
pub struct Panel {
    /// Title over the chart (empty: none; a figure of one panel has its
    /// title on the page only).
    pub title: String,
    /// x-axis label.
    pub xlabel: String,
    /// y-axis label.
    pub ylabel: String,
    /// x scale.
    pub xscale: Scale,
    /// Fixed x range (None: from the data).
    pub xrange: Option<(f64, f64)>,
    /// Fixed y range (None: from the data, padded to whole ticks).
    pub yrange: Option<(f64, f64)>,
    /// Curves.
    pub series: Vec<Series>,
    /// Marked points, drawn over the curves.
    pub markers: Vec<Marker>,
    /// Reference lines.
    pub lines: Vec<RefLine>,
    /// Texts on a halo (contour labels).
    pub labels: Vec<Label>,
    /// Lines of text in the top-left corner of the plot area.
    pub notes: Vec<String>,
    /// Filled cells, drawn first.
    pub cells: Vec<Cell>,
    /// A heat-map raster, drawn first.
    pub raster: Option<Raster>,
    /// Legend entries beyond the labelled series.
    pub legend: Vec<LegendEntry>,
}

impl Panel {
    /// An empty linear panel.
    pub fn new(
        title: impl Into<String>,
        xlabel: impl Into<String>,
        ylabel: impl Into<String>,
    ) -> Self {
        Panel {
            title: title.into(),
            xlabel: xlabel.into(),
            ylabel: ylabel.into(),
            xscale: Scale::Linear,
            xrange: None,
            yrange: None,
            series: Vec::new(),
            markers: Vec::new(),
            lines: Vec::new(),
            labels: Vec::new(),
            notes: Vec::new(),
            cells: Vec::new(),
            raster: None,
            legend: Vec::new(),
        }
    }
}

/// A colour bar for a heat map, drawn in the figure's right strip.
#[derive(Debug, Clone)]
pub struct ColorBar {
    /// Label over the bar.
    pub label: String,
    /// Value range (the data's).
    pub range: (f64, f64),
    /// Levels marked with a line across the bar and their text.
    pub marks: Vec<(f64, String)>,
}

/// A figure: a grid of panels and a legend (collected from the panels'
/// labelled series and legend entries) or a colour bar. Its title and caption
/// are shown by the page, not drawn in the image.
#[derive(Debug, Clone)]
pub struct Figure {
    /// File name (no directory), e.g. `theta_t.svg`.
    pub file: String,
    /// Title (the page's heading of the figure).
    pub title: String,
    /// Width and height in px of the wide layout.
    pub size: (u32, u32),
    /// Rows and columns of panels (wide layout).
    pub grid: (usize, usize),
    /// Panels, row by row.
    pub panels: Vec<Panel>,
    /// Width of the right strip in px of the wide layout (0: none).
    pub strip: u32,
    /// A colour bar in the strip instead of a legend.
    pub colorbar: Option<ColorBar>,
    /// Caption for the page (not drawn).
    pub caption: String,
    /// The data behind the figure as CSV (None: generated from the curves
    /// and markers by [`figure_csv`]).
    pub csv: Option<String>,
    /// A drawing made elsewhere (a diagram), used for both layouts.
    pub raw_svg: Option<String>,
}

impl Figure {
    /// A figure of one panel, with a legend strip of `strip` px.
    pub fn single(file: &str, title: String, size: (u32, u32), panel: Panel, strip: u32) -> Self {
        Figure::new(file, title, size, (1, 1), vec![panel], strip)
    }

    /// A figure of a grid of panels, with a legend strip of `strip` px.
    pub fn new(
        file: &str,
        title: String,
        size: (u32, u32),
        grid: (usize, usize),
        panels: Vec<Panel>,
        strip: u32,
    ) -> Self {
        Figure {
            file: file.into(),
            title,
            size,
            grid,
            panels,
            strip,
            colorbar: None,
            caption: String::new(),
            csv: None,
            raw_svg: None,
        }
    }

    /// The same figure with a caption.
    pub fn caption(mut self, c: impl Into<String>) -> Self {
        self.caption = c.into();
        self
    }

    /// The CSV file's name, beside the SVG.
    pub fn csv_file(&self) -> String {
        format!("{}.csv", self.file.trim_end_matches(".svg"))
    }
}

/// "Nice" tick positions covering [lo, hi]: a step of 1, 2, 2.5 or 5 times a
/// power of ten giving about `target` intervals. Returns (ticks, step).
pub fn nice_ticks(lo: f64, hi: f64, target: usize) -> (Vec<f64>, f64) {
    let span = (hi - lo).abs().max(1e-300);
    let raw = span / target.max(1) as f64;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 2.5, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw * 0.999)
        .unwrap_or(10.0 * mag);
    let first = (lo / step - 1e-9).ceil() as i64;
    let last = (hi / step + 1e-9).floor() as i64;
    let ticks = (first..=last).map(|i| i as f64 * step).collect();
    (ticks, step)
}

/// Decimals needed to print multiples of `step` exactly.
pub fn decimals_for(step: f64) -> usize {
    for d in 0..10usize {
        let s = step * 10f64.powi(d as i32);
        if (s - s.round()).abs() < 1e-6 * s.abs().max(1.0) {
            return d;
        }
    }
    10
}

/// A tick label with `dec` decimals, with a true minus sign (−) and never
/// "−0".
pub fn tick_text(v: f64, dec: usize) -> String {
    let s = format!("{v:.dec$}");
    if s.trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        s.trim_start_matches('-').to_string()
    } else {
        minus(&s)
    }
}

/// `s` with ASCII hyphen-minus signs replaced by the minus sign U+2212.
pub fn minus(s: &str) -> String {
    s.replace('-', "\u{2212}")
}

/// The text of a log-axis tick at 10^e: 0.01, 0.2, 1, 50, …
fn log_tick_text(e: f64) -> String {
    let v = 10f64.powf(e);
    let dec = (-(v.log10().floor()) as i64).max(0) as usize;
    tick_text(v, dec)
}

/// Ticks of a log axis over [lo, hi] (values, not exponents): 1, 2, 5 per
/// decade when the range is short, powers of ten otherwise.
fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
    let d0 = lo.log10().floor() as i32;
    let d1 = hi.log10().ceil() as i32;
    let mults: &[f64] = if d1 - d0 <= 2 {
        &[1.0, 2.0, 5.0]
    } else {
        &[1.0]
    };
    let mut out = Vec::new();
    for d in d0..=d1 {
        for m in mults {
            let v = m * 10f64.powi(d);
            if v >= lo * (1.0 - 1e-9) && v <= hi * (1.0 + 1e-9) {
                out.push(v);
            }
        }
    }
    out
}

/// Clips the polyline `pts` to the box [x0,x1]×[y0,y1]; returns the visible
/// pieces (Liang–Barsky per segment, pieces joined where they touch).
pub fn clip_polyline(
    pts: &[(f64, f64)],
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut cur: Vec<(f64, f64)> = Vec::new();
    let inside = |p: (f64, f64)| p.0 >= x0 && p.0 <= x1 && p.1 >= y0 && p.1 <= y1;
    if pts.len() == 1 && inside(pts[0]) {
        return vec![pts.to_vec()];
    }
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        if !(a.0.is_finite() && a.1.is_finite() && b.0.is_finite() && b.1.is_finite()) {
            if cur.len() > 1 {
                out.push(std::mem::take(&mut cur));
            }
            cur.clear();
            continue;
        }
        match clip_segment(a, b, x0, x1, y0, y1) {
            None => {
                if cur.len() > 1 {
                    out.push(std::mem::take(&mut cur));
                }
                cur.clear();
            }
            Some((p, q)) => {
                let joined = cur.last().is_some_and(|l| *l == p);
                if !joined {
                    if cur.len() > 1 {
                        out.push(std::mem::take(&mut cur));
                    }
                    cur.clear();
                    cur.push(p);
                }
                cur.push(q);
                if q != b {
                    // left the box: this piece ends here
                    out.push(std::mem::take(&mut cur));
                }
            }
        }
    }
    if cur.len() > 1 {
        out.push(cur);
    }
    out
}

fn clip_segment(
    a: (f64, f64),
    b: (f64, f64),
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let mut t0 = 0.0f64;
    let mut t1 = 1.0f64;
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                if r > t1 {
                    return None;
                }
                t0 = t0.max(r);
            } else {
                if r < t0 {
                    return None;
                }
                t1 = t1.min(r);
            }
        }
    }
    let at = |t: f64| {
        if t == 0.0 {
            a
        } else if t == 1.0 {
            b
        } else {
            (a.0 + t * dx, a.1 + t * dy)
        }
    };
    Some((at(t0), at(t1)))
}

/// The data range of a panel's curves, markers and cells (x in data units).
fn data_range(p: &Panel) -> ((f64, f64), (f64, f64)) {
    let mut xs = (f64::INFINITY, f64::NEG_INFINITY);
    let mut ys = (f64::INFINITY, f64::NEG_INFINITY);
    let mut add = |x: f64, y: f64| {
        if x.is_finite() && y.is_finite() {
            xs = (xs.0.min(x), xs.1.max(x));
            ys = (ys.0.min(y), ys.1.max(y));
        }
    };
    for s in &p.series {
        for &(x, y) in &s.points {
            add(x, y);
        }
    }
    for m in &p.markers {
        add(m.at.0, m.at.1);
    }
    for c in &p.cells {
        add(c.lo.0, c.lo.1);
        add(c.hi.0, c.hi.1);
    }
    if !xs.0.is_finite() {
        xs = (0.0, 1.0);
    }
    if !ys.0.is_finite() {
        ys = (0.0, 1.0);
    }
    (xs, ys)
}

/// Range padded to whole ticks, never empty: (lo, hi, step).
fn padded(lo: f64, hi: f64, target: usize) -> (f64, f64, f64) {
    let (lo, hi) = if hi - lo < 1e-12 * lo.abs().max(1.0) {
        (lo - 0.5 * lo.abs().max(1e-3), hi + 0.5 * hi.abs().max(1e-3))
    } else {
        (lo, hi)
    };
    let (_, step) = nice_ticks(lo, hi, target);
    let a = (lo / step + 1e-9).floor() * step;
    let b = (hi / step - 1e-9).ceil() * step;
    (a, b, step)
}

/// Ticks at the multiples of `step` inside [lo, hi].
fn ticks_with_step(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    let first = (lo / step - 1e-9).ceil() as i64;
    let last = (hi / step + 1e-9).floor() as i64;
    (first..=last).map(|i| i as f64 * step).collect()
}

/// Range and ticks of a linear axis: the fixed range with nice ticks inside,
/// or the data range padded to whole ticks.
fn linear_axis(
    fixed: Option<(f64, f64)>,
    data: (f64, f64),
    target: usize,
) -> (f64, f64, Vec<f64>, usize) {
    let (lo, hi, step) = match fixed {
        Some((a, b)) => {
            let (_, s) = nice_ticks(a, b, target);
            (a, b, s)
        }
        None => padded(data.0, data.1, target),
    };
    (lo, hi, ticks_with_step(lo, hi, step), decimals_for(step))
}

// ---------------------------------------------------------------- SVG text

/// Font sizes in px.
const TICK_PX: f64 = 13.0;
const AXIS_PX: f64 = 14.0;
const TITLE_PX: f64 = 15.0;
const LEGEND_PX: f64 = 13.5;
const NOTE_PX: f64 = 12.5;
const GRID: Rgb = (226, 226, 226);
const AXIS: Rgb = (60, 60, 60);

/// Estimated width of `s` in px at `size` (DejaVu Sans metrics, roughly).
pub fn text_width(s: &str, size: f64) -> f64 {
    let em: f64 = s
        .chars()
        .map(|c| match c {
            'i' | 'l' | 'j' | '.' | ',' | ':' | ';' | '\'' | '|' | '!' => 0.3,
            ' ' | '(' | ')' | '[' | ']' | 'f' | 't' | 'r' | 'I' => 0.39,
            'm' | 'w' | 'M' | 'W' => 0.92,
            '\u{2080}'..='\u{209c}' => 0.4,
            'A'..='Z' => 0.7,
            '\u{2212}' | '=' | '+' | '<' | '>' | '≈' | '×' => 0.84,
            _ => 0.62,
        })
        .sum();
    em * size
}

/// XML escape.
pub fn xml(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn hex(c: Rgb) -> String {
    format!("#{:02x}{:02x}{:02x}", c.0, c.1, c.2)
}

/// A number for the SVG: two decimals, no "-0.00".
fn n(v: f64) -> String {
    let s = format!("{v:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.').to_string();
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

/// An SVG document under construction.
struct Svg {
    s: String,
}

impl Svg {
    fn new(w: f64, h: f64) -> Self {
        let mut s = String::new();
        let _ = write!(
            s,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" font-family=\"{}\" font-size=\"{}\">\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n",
            n(w),
            n(h),
            n(w),
            n(h),
            FONT,
            n(TICK_PX)
        );
        Svg { s }
    }

    fn finish(mut self) -> String {
        self.s.push_str("</svg>\n");
        self.s
    }

    fn title(t: &str) -> String {
        if t.is_empty() {
            String::new()
        } else {
            format!("<title>{}</title>", xml(t))
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn polyline(&mut self, pts: &[(f64, f64)], color: Rgb, width: f64, dash: Dash, title: &str) {
        if pts.len() < 2 {
            return;
        }
        let mut d = String::new();
        for (i, p) in pts.iter().enumerate() {
            let _ = write!(
                d,
                "{}{} {}",
                if i == 0 { "M" } else { " L" },
                n(p.0),
                n(p.1)
            );
        }
        let dash = dash
            .array()
            .map(|a| format!(" stroke-dasharray=\"{a}\""))
            .unwrap_or_default();
        let t = Svg::title(title);
        let _ = writeln!(
            self.s,
            "<path d=\"{d}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" stroke-linejoin=\"round\" stroke-linecap=\"round\"{dash}>{t}</path>",
            hex(color),
            n(width)
        );
    }

    fn line(&mut self, a: (f64, f64), b: (f64, f64), color: Rgb, width: f64, dash: Dash) {
        self.polyline(&[a, b], color, width, dash, "");
    }

    fn rect(&mut self, x: f64, y: f64, w: f64, h: f64, fill: &str, stroke: &str) {
        let _ = writeln!(
            self.s,
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{fill}\" stroke=\"{stroke}\"/>",
            n(x),
            n(y),
            n(w),
            n(h)
        );
    }

    /// Text; `anchor` start/middle/end; `halo` draws a white outline under it.
    #[allow(clippy::too_many_arguments)]
    fn text(
        &mut self,
        x: f64,
        y: f64,
        t: &str,
        size: f64,
        anchor: &str,
        color: Rgb,
        halo: bool,
        rotate: bool,
    ) {
        let rot = if rotate {
            format!(" transform=\"rotate(-90 {} {})\"", n(x), n(y))
        } else {
            String::new()
        };
        let halo = if halo {
            " stroke=\"#ffffff\" stroke-width=\"3.5\" stroke-linejoin=\"round\" paint-order=\"stroke\""
        } else {
            ""
        };
        let _ = writeln!(
            self.s,
            "<text x=\"{}\" y=\"{}\" font-size=\"{}\" text-anchor=\"{anchor}\" fill=\"{}\"{halo}{rot}>{}</text>",
            n(x),
            n(y),
            n(size),
            hex(color),
            xml(t)
        );
    }

    /// A marker of `shape` centred at (x, y) with radius `r`.
    #[allow(clippy::too_many_arguments)]
    fn marker(
        &mut self,
        x: f64,
        y: f64,
        r: f64,
        shape: Shape,
        color: Rgb,
        filled: bool,
        title: &str,
    ) {
        let (fill, stroke, sw) = if filled {
            (hex(color), "#000000".to_string(), 1.0)
        } else {
            ("none".to_string(), hex(color), 2.0)
        };
        let t = Svg::title(title);
        match shape {
            Shape::Circle => {
                let _ = writeln!(
                    self.s,
                    "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{fill}\" stroke=\"{stroke}\" stroke-width=\"{}\">{t}</circle>",
                    n(x),
                    n(y),
                    n(r),
                    n(sw)
                );
            }
            Shape::Cross => {
                let a = r * 0.85;
                let _ = writeln!(
                    self.s,
                    "<path d=\"M{} {}L{} {}M{} {}L{} {}\" stroke=\"{}\" stroke-width=\"2.2\">{t}</path>",
                    n(x - a),
                    n(y - a),
                    n(x + a),
                    n(y + a),
                    n(x - a),
                    n(y + a),
                    n(x + a),
                    n(y - a),
                    hex(color)
                );
            }
            _ => {
                let d = shape_path(shape, x, y, r);
                let _ = writeln!(
                    self.s,
                    "<path d=\"{d}\" fill=\"{fill}\" stroke=\"{stroke}\" stroke-width=\"{}\" stroke-linejoin=\"round\">{t}</path>",
                    n(sw)
                );
            }
        }
    }
}

/// The outline of a square, triangle or diamond marker as an SVG path.
fn shape_path(shape: Shape, x: f64, y: f64, r: f64) -> String {
    match shape {
        Shape::Square => {
            let a = r * 0.88;
            format!(
                "M{} {}h{}v{}h{}z",
                n(x - a),
                n(y - a),
                n(2.0 * a),
                n(2.0 * a),
                n(-2.0 * a)
            )
        }
        Shape::Triangle | Shape::TriangleDown => {
            let s = if shape == Shape::Triangle { 1.0 } else { -1.0 };
            let a = r * 1.15;
            format!(
                "M{} {}L{} {}L{} {}z",
                n(x),
                n(y - s * a),
                n(x + a * 0.866),
                n(y + s * a * 0.5),
                n(x - a * 0.866),
                n(y + s * a * 0.5)
            )
        }
        // a diamond (circles and crosses are not paths of this kind)
        _ => {
            let a = r * 1.2;
            format!(
                "M{} {}L{} {}L{} {}L{} {}z",
                n(x),
                n(y - a),
                n(x + a),
                n(y),
                n(x),
                n(y + a),
                n(x - a),
                n(y)
            )
        }
    }
}

// ---------------------------------------------------------------- layout

/// Which arrangement of a figure to draw.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layout {
    /// The figure's grid of panels, the legend or colour bar on the right.
    Wide,
    /// One column of panels, the legend below (phone-width pages).
    Narrow,
}

/// Width of the narrow layout in px.
pub const NARROW_W: f64 = 460.0;

/// A legend row: label lines and the sample.
fn legend_entries(fig: &Figure) -> Vec<LegendEntry> {
    let mut entries: Vec<LegendEntry> = Vec::new();
    let seen = |e: &LegendEntry, entries: &Vec<LegendEntry>| {
        entries
            .iter()
            .any(|x| x.label == e.label && x.color == e.color)
    };
    for p in &fig.panels {
        for s in &p.series {
            if s.label.is_empty() {
                continue;
            }
            let e = LegendEntry {
                label: s.label.clone(),
                color: s.color,
                dash: Some(s.dash),
                shape: s.shape,
                filled: false,
            };
            if !seen(&e, &entries) {
                entries.push(e);
            }
        }
    }
    for p in &fig.panels {
        for e in &p.legend {
            if !seen(e, &entries) {
                entries.push(e.clone());
            }
        }
    }
    entries
}

/// Wraps `label` (lines split at '\n') to lines of at most `w` px.
fn wrap(label: &str, size: f64, w: f64) -> Vec<String> {
    let mut out = Vec::new();
    for para in label.split('\n') {
        let mut cur = String::new();
        for word in para.split(' ') {
            let cand = if cur.is_empty() {
                word.to_string()
            } else {
                format!("{cur} {word}")
            };
            if text_width(&cand, size) > w && !cur.is_empty() {
                out.push(std::mem::take(&mut cur));
                cur = word.to_string();
            } else {
                cur = cand;
            }
        }
        out.push(cur);
    }
    out
}

const LEGEND_SAMPLE: f64 = 34.0;
const LEGEND_LINE: f64 = 17.0;

/// Height of the legend laid out `w` px wide.
fn legend_height(entries: &[LegendEntry], w: f64) -> f64 {
    entries
        .iter()
        .map(|e| {
            wrap(&e.label, LEGEND_PX, w - LEGEND_SAMPLE - 10.0).len() as f64 * LEGEND_LINE + 8.0
        })
        .sum::<f64>()
        + 8.0
}

fn draw_legend(svg: &mut Svg, entries: &[LegendEntry], x: f64, y0: f64, w: f64) {
    let mut y = y0;
    for e in entries {
        let lines = wrap(&e.label, LEGEND_PX, w - LEGEND_SAMPLE - 10.0);
        let cy = y + LEGEND_LINE * 0.5;
        if let Some(d) = e.dash {
            svg.line((x, cy), (x + LEGEND_SAMPLE - 4.0, cy), e.color, 2.5, d);
        }
        if let Some(s) = e.shape {
            svg.marker(
                x + (LEGEND_SAMPLE - 4.0) / 2.0,
                cy,
                5.0,
                s,
                e.color,
                e.filled,
                "",
            );
        }
        for (i, l) in lines.iter().enumerate() {
            svg.text(
                x + LEGEND_SAMPLE + 4.0,
                y + 13.0 + LEGEND_LINE * i as f64,
                l,
                LEGEND_PX,
                "start",
                (0, 0, 0),
                false,
                false,
            );
        }
        y += lines.len() as f64 * LEGEND_LINE + 8.0;
    }
}

/// Width, height and legend height of the narrow layout.
fn narrow_dims(fig: &Figure, entries: &[LegendEntry]) -> (f64, f64, f64) {
    let rows = fig.panels.len().max(1);
    let panel_h = (NARROW_W * 0.72).round();
    let lh = if fig.colorbar.is_some() {
        70.0
    } else if entries.is_empty() {
        0.0
    } else {
        legend_height(entries, NARROW_W - 16.0).ceil()
    };
    (NARROW_W, panel_h * rows as f64 + lh, lh)
}

/// Size in whole px of the narrow layout (for the page's aspect ratio).
pub fn narrow_size(fig: &Figure) -> (u32, u32) {
    let entries = if fig.colorbar.is_none() {
        legend_entries(fig)
    } else {
        Vec::new()
    };
    let (w, h, _) = narrow_dims(fig, &entries);
    (w.round() as u32, h.round() as u32)
}

/// Renders the figure in the wide layout.
pub fn render(fig: &Figure) -> Result<String> {
    Ok(render_layout(fig, Layout::Wide))
}

/// Renders the figure in a layout.
pub fn render_layout(fig: &Figure, layout: Layout) -> String {
    if let Some(raw) = &fig.raw_svg {
        return raw.clone();
    }
    let entries = if fig.colorbar.is_none() {
        legend_entries(fig)
    } else {
        Vec::new()
    };
    let (w, h, grid, strip, legend_h) = match layout {
        Layout::Wide => (
            f64::from(fig.size.0),
            f64::from(fig.size.1),
            fig.grid,
            f64::from(fig.strip),
            0.0,
        ),
        Layout::Narrow => {
            let rows = fig.panels.len().max(1);
            let (w, h, lh) = narrow_dims(fig, &entries);
            (w, h, (rows, 1), 0.0, lh)
        }
    };
    let mut svg = Svg::new(w, h);
    let charts_w = w - strip;
    let charts_h = h - legend_h;
    let (rows, cols) = (grid.0.max(1), grid.1.max(1));
    let (cw, ch) = (charts_w / cols as f64, charts_h / rows as f64);
    for (k, p) in fig.panels.iter().enumerate() {
        let (r, c) = (k / cols, k % cols);
        draw_panel(&mut svg, p, c as f64 * cw, r as f64 * ch, cw, ch);
    }
    match layout {
        Layout::Wide => {
            if strip > 0.0 {
                if let Some(cb) = &fig.colorbar {
                    draw_colorbar(&mut svg, cb, charts_w, 0.0, strip, h, false);
                } else {
                    draw_legend(&mut svg, &entries, charts_w + 4.0, 40.0, strip - 8.0);
                }
            }
        }
        Layout::Narrow => {
            if let Some(cb) = &fig.colorbar {
                draw_colorbar(&mut svg, cb, 0.0, charts_h, w, legend_h, true);
            } else {
                draw_legend(&mut svg, &entries, 14.0, charts_h + 4.0, w - 16.0);
            }
        }
    }
    svg.finish()
}

/// The pixel mapping of a panel.
struct Frame {
    ax: f64,
    ay: f64,
    aw: f64,
    ah: f64,
    x: (f64, f64),
    y: (f64, f64),
    log: bool,
}

impl Frame {
    fn tx(&self, x: f64) -> f64 {
        if self.log {
            x.log10()
        } else {
            x
        }
    }
    /// Pixel x of a chart coordinate (log10 already applied).
    fn cx(&self, c: f64) -> f64 {
        self.ax + (c - self.x.0) / (self.x.1 - self.x.0) * self.aw
    }
    fn px(&self, x: f64) -> f64 {
        self.cx(self.tx(x))
    }
    fn py(&self, y: f64) -> f64 {
        self.ay + self.ah - (y - self.y.0) / (self.y.1 - self.y.0) * self.ah
    }
    fn inside(&self, x: f64, y: f64) -> bool {
        let c = self.tx(x);
        c.is_finite()
            && y.is_finite()
            && c >= self.x.0 - 1e-12
            && c <= self.x.1 + 1e-12
            && y >= self.y.0 - 1e-12
            && y <= self.y.1 + 1e-12
    }
}

/// The ticks of a panel's axes and their texts.
struct Axes {
    xticks: Vec<f64>,
    xdec: usize,
    yticks: Vec<f64>,
    ylabels: Vec<String>,
}

/// The pixel frame and the ticks of panel `p` in the box (x0, y0, w, h).
fn panel_frame(p: &Panel, x0: f64, y0: f64, w: f64, h: f64) -> (Frame, Axes) {
    let ((dx0, dx1), (dy0, dy1)) = data_range(p);
    let log = p.xscale == Scale::Log;
    let tx = |x: f64| if log { x.log10() } else { x };
    let (xlo, xhi, xticks, xdec) = if log {
        let (a, b) = p.xrange.unwrap_or((dx0, dx1));
        let t = log_ticks(a, b).into_iter().map(|v| v.log10()).collect();
        (a, b, t, 0)
    } else {
        linear_axis(p.xrange, (dx0, dx1), (w / 110.0).clamp(4.0, 8.0) as usize)
    };
    let (ylo, yhi, yticks, ydec) = linear_axis(p.yrange, (dy0, dy1), 6);
    let ylabels: Vec<String> = yticks.iter().map(|v| tick_text(*v, ydec)).collect();
    let ywidth = ylabels
        .iter()
        .map(|t| text_width(t, TICK_PX))
        .fold(0.0, f64::max);
    let top = if p.title.is_empty() { 14.0 } else { 30.0 };
    let left = 10.0 + AXIS_PX + 10.0 + ywidth + 8.0;
    let bottom = 8.0 + TICK_PX + 8.0 + AXIS_PX + 8.0;
    let direct_w = p
        .series
        .iter()
        .filter_map(|s| s.direct.as_ref())
        .map(|t| text_width(t, NOTE_PX) + 12.0)
        .fold(0.0, f64::max);
    let right = 16.0 + direct_w;
    let f = Frame {
        ax: x0 + left,
        ay: y0 + top,
        aw: (w - left - right).max(20.0),
        ah: (h - top - bottom).max(20.0),
        x: (tx(xlo), tx(xhi)),
        y: (ylo, yhi),
        log,
    };
    let axes = Axes {
        xticks,
        xdec,
        yticks,
        ylabels,
    };
    (f, axes)
}

fn draw_panel(svg: &mut Svg, p: &Panel, x0: f64, y0: f64, w: f64, h: f64) {
    let (f, axes) = panel_frame(p, x0, y0, w, h);
    if !p.title.is_empty() {
        let x = f.ax + f.aw / 2.0;
        svg.text(
            x,
            y0 + 19.0,
            &p.title,
            TITLE_PX,
            "middle",
            (0, 0, 0),
            false,
            false,
        );
    }
    draw_raster(svg, p, &f);
    draw_cells(svg, p, &f);
    draw_grid(svg, &f, &axes);
    draw_ref_lines(svg, p, &f);
    draw_curves(svg, p, &f);
    draw_periodic_markers(svg, p, &f);
    draw_event_markers(svg, p, &f);
    draw_direct_labels(svg, p, &f);
    draw_halo_labels(svg, p, &f);
    for (i, t) in p.notes.iter().enumerate() {
        let y = f.ay + 18.0 + 16.0 * i as f64;
        svg.text(
            f.ax + 8.0,
            y,
            t,
            NOTE_PX,
            "start",
            (40, 40, 40),
            true,
            false,
        );
    }
    draw_axes(svg, p, &f, &axes, x0, y0, h);
}

fn draw_raster(svg: &mut Svg, p: &Panel, f: &Frame) {
    if let Some(r) = &p.raster {
        let (px0, px1) = (f.cx(r.x.0), f.cx(r.x.1));
        let (py0, py1) = (f.py(r.y.1), f.py(r.y.0));
        let _ = writeln!(
            svg.s,
            "<image x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" preserveAspectRatio=\"none\" href=\"data:image/png;base64,{}\"><title>colour: the value at each point, interpolated between the computed nodes (their values: the figure's CSV)</title></image>",
            n(px0),
            n(py0),
            n(px1 - px0),
            n(py1 - py0),
            base64(&png(r.w, r.h, &r.pixels))
        );
    }
}

fn draw_cells(svg: &mut Svg, p: &Panel, f: &Frame) {
    for c in &p.cells {
        let (a0, a1) = (f.tx(c.lo.0).max(f.x.0), f.tx(c.hi.0).min(f.x.1));
        let (b0, b1) = (c.lo.1.max(f.y.0), c.hi.1.min(f.y.1));
        if a0 < a1 && b0 < b1 {
            let (px0, px1) = (f.cx(a0), f.cx(a1));
            let (py0, py1) = (f.py(b1), f.py(b0));
            let _ = writeln!(
                svg.s,
                "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\" stroke=\"{}\" stroke-width=\"0.5\">{}</rect>",
                n(px0),
                n(py0),
                n(px1 - px0),
                n(py1 - py0),
                hex(c.color),
                hex(c.color),
                Svg::title(&c.title)
            );
        }
    }
}

fn draw_grid(svg: &mut Svg, f: &Frame, axes: &Axes) {
    for &t in &axes.xticks {
        let x = f.cx(t);
        svg.line((x, f.ay), (x, f.ay + f.ah), GRID, 1.0, Dash::Solid);
    }
    for &t in &axes.yticks {
        let y = f.py(t);
        svg.line((f.ax, y), (f.ax + f.aw, y), GRID, 1.0, Dash::Solid);
    }
}

/// A text's box in pixels: (x0, x1, y0, y1) for a baseline at `y`.
fn text_box(x: f64, y: f64, w: f64, anchor: &str) -> (f64, f64, f64, f64) {
    let x0 = match anchor {
        "end" => x - w,
        "middle" => x - w / 2.0,
        _ => x,
    };
    (x0, x0 + w, y - NOTE_PX * 0.8, y + NOTE_PX * 0.25)
}

/// The panel's curves in pixels, as drawn (clipped to the plot area).
fn curve_pixels(p: &Panel, f: &Frame) -> Vec<Vec<(f64, f64)>> {
    let mut out = Vec::new();
    for s in &p.series {
        let pts: Vec<(f64, f64)> = s.points.iter().map(|&(x, y)| (f.tx(x), y)).collect();
        for piece in clip_polyline(&pts, f.x.0, f.x.1, f.y.0, f.y.1) {
            out.push(piece.iter().map(|&(c, y)| (f.cx(c), f.py(y))).collect());
        }
    }
    out
}

/// Whether a box (x0, x1, y0, y1) in pixels, widened by a small margin,
/// crosses one of the curves or comes near one of the marked points.
fn box_hits(b: (f64, f64, f64, f64), curves: &[Vec<(f64, f64)>], points: &[(f64, f64)]) -> bool {
    let m = 3.0;
    let (x0, x1, y0, y1) = (b.0 - m, b.1 + m, b.2 - m, b.3 + m);
    let near = |q: &(f64, f64)| {
        let dx = (x0 - q.0).max(q.0 - x1).max(0.0);
        let dy = (y0 - q.1).max(q.1 - y1).max(0.0);
        dx.hypot(dy) < 7.0
    };
    points.iter().any(near)
        || curves.iter().any(|c| {
            c.windows(2)
                .any(|w| clip_segment(w[0], w[1], x0, x1, y0, y1).is_some())
        })
}

/// What a label must not cover: polylines and marked points, in pixels.
type Obstacles = (Vec<Vec<(f64, f64)>>, Vec<(f64, f64)>);

/// What a label placed in the plot area must not cover: the curves (and
/// horizontal reference lines) as polylines in pixels, and the marked points
/// (event markers, curves' ends).
fn obstacles(p: &Panel, f: &Frame) -> Obstacles {
    let mut curves = curve_pixels(p, f);
    for l in p.lines.iter().filter(|l| !l.vertical) {
        if l.at >= f.y.0 && l.at <= f.y.1 {
            let y = f.py(l.at);
            curves.push(vec![(f.ax, y), (f.ax + f.aw, y)]);
        }
    }
    let points = p
        .markers
        .iter()
        .map(|m| m.at)
        .chain(p.series.iter().filter_map(|s| s.points.last().copied()))
        .filter(|&(x, y)| f.inside(x, y))
        .map(|(x, y)| (f.px(x), f.py(y)))
        .collect();
    (curves, points)
}

/// Where the label of a vertical reference line at pixel `x` goes: at the
/// top, right of the line if it fits, else left of it; if a curve or a
/// marker is in the way there, the first free place down the line (right
/// side first), else the top after all. (baseline y, x, anchor)
fn vertical_label_place(
    f: &Frame,
    x: f64,
    label: &str,
    obstacles: &Obstacles,
) -> (f64, f64, &'static str) {
    let hits = |b| box_hits(b, &obstacles.0, &obstacles.1);
    let w = text_width(label, NOTE_PX);
    let fits_right = f.ax + f.aw - x > w + 8.0;
    let first = if fits_right {
        (x + 4.0, "start")
    } else {
        (x - 4.0, "end")
    };
    let top = f.ay + 14.0;
    if !hits(text_box(first.0, top, w, first.1)) {
        return (top, first.0, first.1);
    }
    let sides: Vec<(f64, &'static str)> = if fits_right {
        vec![(x + 4.0, "start"), (x - 4.0, "end")]
    } else {
        vec![(x - 4.0, "end")]
    };
    let step = NOTE_PX + 3.0;
    let mut y = top;
    while y <= f.ay + f.ah - 4.0 {
        for &(sx, anchor) in &sides {
            let b = text_box(sx, y, w, anchor);
            if b.0 >= f.ax && !hits(b) {
                return (y, sx, anchor);
            }
        }
        y += step;
    }
    (top, first.0, first.1)
}

fn draw_ref_lines(svg: &mut Svg, p: &Panel, f: &Frame) {
    let obstacles = obstacles(p, f);
    for l in &p.lines {
        if l.vertical {
            if !f.inside(l.at, f.y.0) {
                continue;
            }
            let x = f.px(l.at);
            svg.line((x, f.ay), (x, f.ay + f.ah), l.color, 1.3, l.dash);
            if !l.label.is_empty() {
                let (y, tx_, anchor) = vertical_label_place(f, x, &l.label, &obstacles);
                svg.text(tx_, y, &l.label, NOTE_PX, anchor, l.color, true, false);
            }
        } else {
            if l.at < f.y.0 || l.at > f.y.1 {
                continue;
            }
            let y = f.py(l.at);
            svg.line((f.ax, y), (f.ax + f.aw, y), l.color, 1.0, l.dash);
            if !l.label.is_empty() {
                let x = f.ax + f.aw - 4.0;
                svg.text(
                    x,
                    y - 4.0,
                    &l.label,
                    NOTE_PX - 1.0,
                    "end",
                    l.color,
                    true,
                    false,
                );
            }
        }
    }
}

fn draw_curves(svg: &mut Svg, p: &Panel, f: &Frame) {
    for s in &p.series {
        let pts: Vec<(f64, f64)> = s.points.iter().map(|&(x, y)| (f.tx(x), y)).collect();
        let title = if s.label.is_empty() {
            String::new()
        } else {
            s.label.replace('\n', " ")
        };
        for piece in clip_polyline(&pts, f.x.0, f.x.1, f.y.0, f.y.1) {
            let px: Vec<(f64, f64)> = piece.iter().map(|&(c, y)| (f.cx(c), f.py(y))).collect();
            svg.polyline(&px, s.color, s.width, s.dash, &title);
        }
    }
}

/// Periodic markers, never on (or under) an event marker or a curve's end.
fn draw_periodic_markers(svg: &mut Svg, p: &Panel, f: &Frame) {
    let taken: Vec<(f64, f64)> = p
        .markers
        .iter()
        .filter(|m| f.inside(m.at.0, m.at.1))
        .map(|m| (f.px(m.at.0), f.py(m.at.1)))
        .chain(p.series.iter().filter_map(|s| {
            let &(x, y) = s.points.last()?;
            (s.end.is_some() && f.inside(x, y)).then(|| (f.px(x), f.py(y)))
        }))
        .collect();
    let free = |x: f64, y: f64| taken.iter().all(|q| (q.0 - x).hypot(q.1 - y) > 11.0);
    for s in &p.series {
        let Some(shape) = s.shape.filter(|_| s.every > 0) else {
            continue;
        };
        let last = s.points.len().saturating_sub(1);
        let title = s.label.replace('\n', " ");
        for (i, &(x, y)) in s.points.iter().enumerate() {
            if i >= s.phase
                && (i - s.phase) % s.every == 0
                && i + s.every / 2 < last
                && f.inside(x, y)
                && free(f.px(x), f.py(y))
            {
                svg.marker(f.px(x), f.py(y), 4.0, shape, s.color, false, &title);
            }
        }
    }
}

/// End markers (hollow: several at one point stay visible), then the
/// event markers with their labels.
fn draw_event_markers(svg: &mut Svg, p: &Panel, f: &Frame) {
    for s in &p.series {
        if let (Some(t), Some(&(x, y))) = (&s.end, s.points.last()) {
            if f.inside(x, y) {
                let shape = s.shape.unwrap_or(Shape::Circle);
                svg.marker(f.px(x), f.py(y), 6.0, shape, s.color, false, t);
            }
        }
    }
    for m in &p.markers {
        if f.inside(m.at.0, m.at.1) {
            let (x, y) = (f.px(m.at.0), f.py(m.at.1));
            svg.marker(x, y, 5.5, m.shape, m.color, m.filled, &m.title);
            if let Some(l) = &m.label {
                let room = f.ax + f.aw - x;
                if room > text_width(l, NOTE_PX) + 12.0 {
                    svg.text(
                        x + 9.0,
                        y - 7.0,
                        l,
                        NOTE_PX,
                        "start",
                        (0, 0, 0),
                        true,
                        false,
                    );
                } else {
                    svg.text(x - 9.0, y - 7.0, l, NOTE_PX, "end", (0, 0, 0), true, false);
                }
            }
        }
    }
}

/// A direct label to place: where it wants to be and where it goes.
struct Placed {
    /// Where the label starts next to its curve's end.
    x0: f64,
    x: f64,
    want: f64,
    y: f64,
    w: f64,
}

/// Spreads labels (sorted by where they want to be) vertically so that no
/// two that overlap in x are closer than `gap`. Each label in turn is moved
/// down until it is free; if that leaves one outside [lo, hi] (or two still
/// clash), the labels are placed again: those that clash are stacked in a
/// block centred on their wishes and kept inside [lo, hi], written as one
/// column right of the block's rightmost curve end, and any two blocks that
/// then clash are merged with those between them.
fn spread_labels(items: &mut [Placed], gap: f64, lo: f64, hi: f64) {
    let clash = |a: &Placed, b: &Placed| {
        (a.y - b.y).abs() < gap - 1e-9 && a.x < b.x + b.w && b.x < a.x + a.w
    };
    let fine = |items: &[Placed]| {
        items.iter().all(|d| d.y >= lo && d.y <= hi)
            && (0..items.len()).all(|i| (i + 1..items.len()).all(|j| !clash(&items[i], &items[j])))
    };
    // first the simple way: each label in turn moved down until it is free
    for i in 0..items.len() {
        let mut tries = 0;
        while (0..i).any(|j| clash(&items[i], &items[j])) && tries < 20 {
            items[i].y += gap / 2.0;
            tries += 1;
        }
    }
    if fine(items) {
        return;
    }
    let mut order: Vec<usize> = (0..items.len()).collect();
    order.sort_by(|&a, &b| items[a].want.total_cmp(&items[b].want));
    // blocks of consecutive labels (in the order of their wishes)
    let mut blocks: Vec<Vec<usize>> = order.iter().map(|&i| vec![i]).collect();
    loop {
        for b in &mut blocks {
            // leaders that do not cross: of two ends at one height, the left
            // one gets the upper label
            let x = b.iter().map(|&i| items[i].x0).fold(f64::MIN, f64::max);
            let key = |i: usize| items[i].want - 0.5 * (x - items[i].x0);
            b.sort_by(|&i, &j| key(i).total_cmp(&key(j)));
            let n = b.len() as f64;
            let mean = b
                .iter()
                .enumerate()
                .map(|(k, &i)| items[i].want - k as f64 * gap)
                .sum::<f64>()
                / n;
            let top = mean.clamp(lo, (hi - (n - 1.0) * gap).max(lo));
            // a block is one column, right of its rightmost curve end
            for (k, &i) in b.iter().enumerate() {
                items[i].y = top + k as f64 * gap;
                items[i].x = if n > 1.0 { x } else { items[i].x0 };
            }
        }
        // any two blocks that clash are merged with every block between them
        let n = blocks.len();
        let merge = (0..n)
            .flat_map(|i| (i + 1..n).map(move |j| (i, j)))
            .find(|&(i, j)| {
                blocks[i]
                    .iter()
                    .any(|&a| blocks[j].iter().any(|&b| clash(&items[a], &items[b])))
            });
        match merge {
            Some((i, j)) => {
                let rest: Vec<usize> = blocks.drain(i + 1..=j).flatten().collect();
                blocks[i].extend(rest);
            }
            None => break,
        }
    }
}

/// Direct labels at the curves' ends, spread apart vertically inside the
/// plot area, with a leader line to a curve's end where its label moved.
fn draw_direct_labels(svg: &mut Svg, p: &Panel, f: &Frame) {
    let mut direct: Vec<(Placed, String, Rgb, (f64, f64))> = p
        .series
        .iter()
        .filter_map(|s| {
            let t = s.direct.as_ref()?;
            let &(x, y) = s.points.iter().rev().find(|&&(x, y)| f.inside(x, y))?;
            let (px, py) = (f.px(x), f.py(y));
            let want = py + 4.5;
            let w = text_width(t, NOTE_PX);
            let d = Placed {
                x0: px + 9.0,
                x: px + 9.0,
                want,
                y: want,
                w,
            };
            Some((d, t.clone(), s.color, (px, py)))
        })
        .collect();
    direct.sort_by(|a, b| a.0.want.total_cmp(&b.0.want));
    let mut placed: Vec<Placed> = direct
        .iter()
        .map(|d| Placed {
            x0: d.0.x0,
            x: d.0.x,
            want: d.0.want,
            y: d.0.y,
            w: d.0.w,
        })
        .collect();
    spread_labels(
        &mut placed,
        NOTE_PX + 2.0,
        f.ay + NOTE_PX,
        f.ay + f.ah - 3.0,
    );
    for (d, (_, t, c, end)) in placed.iter().zip(&direct) {
        if (d.y - d.want).abs() > 4.0 || d.x > d.x0 {
            let to = (d.x - 2.0, d.y - NOTE_PX * 0.3);
            svg.line((end.0 + 4.0, end.1), to, darker(*c), 0.8, Dash::Solid);
        }
        svg.text(d.x, d.y, t, NOTE_PX, "start", darker(*c), true, false);
    }
}

/// Labels on a halo (contours); one that would overlap a label already
/// written is left out.
fn draw_halo_labels(svg: &mut Svg, p: &Panel, f: &Frame) {
    let mut written: Vec<(f64, f64, f64)> = Vec::new();
    for l in &p.labels {
        if f.inside(l.at.0, l.at.1) {
            let (x, y, w) = (f.px(l.at.0), f.py(l.at.1), text_width(&l.text, NOTE_PX));
            if written.iter().any(|&(a, b, v)| {
                (a - x).abs() < (v + w) / 2.0 + 4.0 && (b - y).abs() < NOTE_PX + 2.0
            }) {
                continue;
            }
            written.push((x, y, w));
            svg.text(
                x,
                y + 4.0,
                &l.text,
                NOTE_PX - 0.5,
                "middle",
                (0, 0, 0),
                true,
                false,
            );
        }
    }
}

/// The frame, the ticks and their texts, the axis labels.
fn draw_axes(svg: &mut Svg, p: &Panel, f: &Frame, axes: &Axes, x0: f64, y0: f64, h: f64) {
    svg.rect(f.ax, f.ay, f.aw, f.ah, "none", &hex(AXIS));
    let black = (0, 0, 0);
    for &t in &axes.xticks {
        let x = f.cx(t);
        let bottom = f.ay + f.ah;
        svg.line((x, bottom), (x, bottom + 5.0), AXIS, 1.0, Dash::Solid);
        let label = if f.log {
            log_tick_text(t)
        } else {
            tick_text(t, axes.xdec)
        };
        svg.text(
            x,
            bottom + 8.0 + TICK_PX,
            &label,
            TICK_PX,
            "middle",
            black,
            false,
            false,
        );
    }
    for (t, label) in axes.yticks.iter().zip(&axes.ylabels) {
        let y = f.py(*t);
        svg.line((f.ax - 5.0, y), (f.ax, y), AXIS, 1.0, Dash::Solid);
        let ty = y + TICK_PX * 0.35;
        svg.text(f.ax - 8.0, ty, label, TICK_PX, "end", black, false, false);
    }
    let (xl, yl) = (f.ax + f.aw / 2.0, y0 + h - 9.0);
    svg.text(xl, yl, &p.xlabel, AXIS_PX, "middle", black, false, false);
    let (xl, yl) = (x0 + 10.0 + AXIS_PX, f.ay + f.ah / 2.0);
    svg.text(xl, yl, &p.ylabel, AXIS_PX, "middle", black, false, true);
}

/// A darker shade of `c` for text (the palette's light colours are too pale
/// for text on white).
fn darker(c: Rgb) -> Rgb {
    let f = |v: u8| (f64::from(v) * 0.7).round() as u8;
    (f(c.0), f(c.1), f(c.2))
}

/// A perceptually ordered colour map (viridis, by 9 anchors), u in [0, 1].
pub fn viridis(u: f64) -> Rgb {
    let u = if u.is_finite() {
        u.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let s = u * (VIRIDIS.len() - 1) as f64;
    let i = (s.floor() as usize).min(VIRIDIS.len() - 2);
    let f = s - i as f64;
    let a = VIRIDIS[i];
    let b = VIRIDIS[i + 1];
    let mix = |a: u8, b: u8| (f64::from(a) + f * (f64::from(b) - f64::from(a))).round() as u8;
    (mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

const VIRIDIS: [Rgb; 9] = [
    (68, 1, 84),
    (71, 44, 122),
    (59, 81, 139),
    (44, 113, 142),
    (33, 144, 141),
    (39, 173, 129),
    (92, 200, 99),
    (170, 220, 50),
    (253, 231, 37),
];

/// The colour bar: a smooth gradient (the colour map's anchors as stops),
/// vertical in the right strip or horizontal below the panels.
fn draw_colorbar(svg: &mut Svg, cb: &ColorBar, x0: f64, y0: f64, w: f64, h: f64, horizontal: bool) {
    let id = if horizontal { "cbh" } else { "cbv" };
    let (gx2, gy1) = if horizontal {
        ("100%", "0%")
    } else {
        ("0%", "100%")
    };
    let mut stops = String::new();
    for (i, c) in VIRIDIS.iter().enumerate() {
        let _ = write!(
            stops,
            "<stop offset=\"{}\" stop-color=\"{}\"/>",
            n(i as f64 / (VIRIDIS.len() - 1) as f64),
            hex(*c)
        );
    }
    let _ = writeln!(
        svg.s,
        "<defs><linearGradient id=\"{id}\" x1=\"0%\" y1=\"{gy1}\" x2=\"{gx2}\" y2=\"0%\">{stops}</linearGradient></defs>"
    );
    let fill = format!("url(#{id})");
    let (ticks, step) = nice_ticks(cb.range.0, cb.range.1, 6);
    let dec = decimals_for(step);
    let ticks: Vec<(f64, String)> = ticks.into_iter().map(|t| (t, tick_text(t, dec))).collect();
    if horizontal {
        colorbar_horizontal(svg, cb, &ticks, &fill, (x0, y0, w));
    } else {
        colorbar_vertical(svg, cb, &ticks, &fill, (x0, y0, w, h));
    }
}

/// A colour bar across the bottom of a narrow layout.
fn colorbar_horizontal(
    svg: &mut Svg,
    cb: &ColorBar,
    ticks: &[(f64, String)],
    fill: &str,
    (x0, y0, w): (f64, f64, f64),
) {
    let ((lo, hi), black) = (cb.range, (0, 0, 0));
    let (bx, by, bw, bh) = (x0 + 20.0, y0 + 28.0, w - 40.0, 14.0);
    svg.text(
        bx,
        y0 + 18.0,
        &cb.label,
        LEGEND_PX,
        "start",
        black,
        false,
        false,
    );
    svg.rect(bx, by, bw, bh, fill, "#000000");
    let xpix = |v: f64| bx + (v - lo) / (hi - lo) * bw;
    for (t, text) in ticks {
        let x = xpix(*t);
        svg.line((x, by + bh), (x, by + bh + 4.0), black, 1.0, Dash::Solid);
        let ty = by + bh + 17.0;
        svg.text(x, ty, text, TICK_PX, "middle", black, false, false);
    }
    for (m, _) in &cb.marks {
        if *m >= lo && *m <= hi {
            let x = xpix(*m);
            svg.line((x, by), (x, by + bh), (255, 255, 255), 2.0, Dash::Solid);
        }
    }
}

/// A colour bar in the right strip of a wide layout, with its marks named.
fn colorbar_vertical(
    svg: &mut Svg,
    cb: &ColorBar,
    ticks: &[(f64, String)],
    fill: &str,
    (x0, y0, w, h): (f64, f64, f64, f64),
) {
    let ((lo, hi), black) = (cb.range, (0, 0, 0));
    let (bx, by, bw, bh) = (x0 + 12.0, y0 + 60.0, 24.0, h - 140.0);
    for (i, l) in wrap(&cb.label, LEGEND_PX, w - 12.0).iter().enumerate() {
        let y = y0 + 24.0 + 17.0 * i as f64;
        svg.text(x0 + 8.0, y, l, LEGEND_PX, "start", black, false, false);
    }
    svg.rect(bx, by, bw, bh, fill, "#000000");
    let ypix = |v: f64| by + bh - (v - lo) / (hi - lo) * bh;
    for (t, text) in ticks {
        let y = ypix(*t);
        svg.line((bx + bw, y), (bx + bw + 5.0, y), black, 1.0, Dash::Solid);
        let (tx, ty) = (bx + bw + 8.0, y + 4.5);
        svg.text(tx, ty, text, TICK_PX, "start", black, false, false);
    }
    for (m, t) in &cb.marks {
        if *m >= lo && *m <= hi {
            let y = ypix(*m);
            svg.line(
                (bx - 4.0, y),
                (bx + bw, y),
                (255, 255, 255),
                2.0,
                Dash::Solid,
            );
            svg.line((bx - 6.0, y), (bx, y), black, 1.5, Dash::Solid);
            if !t.is_empty() {
                svg.text(
                    bx - 8.0,
                    y + 4.0,
                    t,
                    NOTE_PX - 1.5,
                    "end",
                    black,
                    false,
                    false,
                );
            }
        }
    }
}

/// Line segments of the contour `level` of values `z[j][i]` given at nodes
/// (xs[i], ys[j]) (marching squares; saddles resolved by the cell mean).
pub fn contour(xs: &[f64], ys: &[f64], z: &[Vec<f64>], level: f64) -> Vec<[(f64, f64); 2]> {
    let mut segs = Vec::new();
    for j in 0..ys.len().saturating_sub(1) {
        for i in 0..xs.len().saturating_sub(1) {
            // corners counter-clockwise: (i,j) (i+1,j) (i+1,j+1) (i,j+1)
            let c = [
                (xs[i], ys[j], z[j][i]),
                (xs[i + 1], ys[j], z[j][i + 1]),
                (xs[i + 1], ys[j + 1], z[j + 1][i + 1]),
                (xs[i], ys[j + 1], z[j + 1][i]),
            ];
            if c.iter().any(|p| !p.2.is_finite()) {
                continue;
            }
            let mut cross = Vec::new();
            for k in 0..4 {
                let a = c[k];
                let b = c[(k + 1) % 4];
                if (a.2 < level) != (b.2 < level) {
                    let t = (level - a.2) / (b.2 - a.2);
                    cross.push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
                }
            }
            match cross.len() {
                2 => segs.push([cross[0], cross[1]]),
                4 => {
                    let mean = c.iter().map(|p| p.2).sum::<f64>() / 4.0;
                    let first_low = c[0].2 < level;
                    if (mean < level) == first_low {
                        segs.push([cross[0], cross[3]]);
                        segs.push([cross[1], cross[2]]);
                    } else {
                        segs.push([cross[0], cross[1]]);
                        segs.push([cross[2], cross[3]]);
                    }
                }
                _ => {}
            }
        }
    }
    segs
}

/// Joins contour segments into polylines (segments sharing an end point).
pub fn chain(segs: &[[(f64, f64); 2]]) -> Vec<Vec<(f64, f64)>> {
    let close = |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9;
    let mut used = vec![false; segs.len()];
    let mut out = Vec::new();
    for s in 0..segs.len() {
        if used[s] {
            continue;
        }
        used[s] = true;
        let mut line = vec![segs[s][0], segs[s][1]];
        for forward in [true, false] {
            loop {
                let end = if forward {
                    line[line.len() - 1]
                } else {
                    line[0]
                };
                let next = (0..segs.len())
                    .find(|&k| !used[k] && (close(segs[k][0], end) || close(segs[k][1], end)));
                let Some(k) = next else { break };
                used[k] = true;
                let p = if close(segs[k][0], end) {
                    segs[k][1]
                } else {
                    segs[k][0]
                };
                if forward {
                    line.push(p);
                } else {
                    line.insert(0, p);
                }
            }
        }
        out.push(line);
    }
    out
}

/// A value with `sig` significant digits for a CSV file (plain decimal
/// notation unless very large or small).
pub fn csv_num(v: f64, sig: usize) -> String {
    if !v.is_finite() {
        return String::new();
    }
    if v == 0.0 {
        return "0".into();
    }
    let e = v.abs().log10().floor() as i32;
    if !(-6..=9).contains(&e) {
        return format!("{:.*e}", sig.saturating_sub(1), v);
    }
    let dec = (sig as i32 - 1 - e).max(0) as usize;
    let s = format!("{v:.dec$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

fn csv_field(s: &str) -> String {
    let s = s.replace('\n', " ");
    if s.contains(',') || s.contains('"') {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s
    }
}

/// The data behind a figure as CSV: one row per plotted point of every curve
/// and every marker (`panel, curve, x quantity, x, y quantity, y`), values
/// with `sig` significant digits (the digits verified for the plots).
pub fn figure_csv(fig: &Figure, sig: usize) -> String {
    if let Some(c) = &fig.csv {
        return c.clone();
    }
    let mut s = String::from("panel,curve,x_quantity,x,y_quantity,y\n");
    for (k, p) in fig.panels.iter().enumerate() {
        let panel = if p.title.is_empty() {
            format!("{}", k + 1)
        } else {
            p.title.clone()
        };
        for (i, ser) in p.series.iter().enumerate() {
            if ser.points.is_empty() {
                continue;
            }
            let name = if ser.label.is_empty() {
                format!("curve {}", i + 1)
            } else {
                ser.label.clone()
            };
            for &(x, y) in &ser.points {
                let _ = writeln!(
                    s,
                    "{},{},{},{},{},{}",
                    csv_field(&panel),
                    csv_field(&name),
                    csv_field(&p.xlabel),
                    csv_num(x, sig),
                    csv_field(&p.ylabel),
                    csv_num(y, sig)
                );
            }
        }
        for m in &p.markers {
            let _ = writeln!(
                s,
                "{},{},{},{},{},{}",
                csv_field(&panel),
                csv_field(&format!("marker: {}", m.title)),
                csv_field(&p.xlabel),
                csv_num(m.at.0, sig),
                csv_field(&p.ylabel),
                csv_num(m.at.1, sig)
            );
        }
    }
    s
}

// ---------------------------------------------------------------- PNG

fn crc32(data: &[u8]) -> u32 {
    let mut c = 0xffff_ffffu32;
    for &b in data {
        c ^= u32::from(b);
        for _ in 0..8 {
            c = if c & 1 != 0 {
                0xedb8_8320 ^ (c >> 1)
            } else {
                c >> 1
            };
        }
    }
    !c
}

fn adler32(data: &[u8]) -> u32 {
    let (mut a, mut b) = (1u32, 0u32);
    for &x in data {
        a = (a + u32::from(x)) % 65521;
        b = (b + a) % 65521;
    }
    (b << 16) | a
}

/// An RGB PNG (zlib with stored blocks: no compression, no dependency).
pub fn png(w: usize, h: usize, pixels: &[Rgb]) -> Vec<u8> {
    let mut raw = Vec::with_capacity(h * (1 + 3 * w));
    for r in 0..h {
        raw.push(0u8);
        for c in 0..w {
            let p = pixels.get(r * w + c).copied().unwrap_or((255, 255, 255));
            raw.extend_from_slice(&[p.0, p.1, p.2]);
        }
    }
    let mut z = vec![0x78u8, 0x01];
    let chunks: Vec<&[u8]> = raw.chunks(65535).collect();
    for (i, ch) in chunks.iter().enumerate() {
        z.push(u8::from(i + 1 == chunks.len()));
        let len = ch.len() as u16;
        z.extend_from_slice(&len.to_le_bytes());
        z.extend_from_slice(&(!len).to_le_bytes());
        z.extend_from_slice(ch);
    }
    z.extend_from_slice(&adler32(&raw).to_be_bytes());
    let mut out = vec![0x89, b'P', b'N', b'G', 0x0d, 0x0a, 0x1a, 0x0a];
    let mut chunk = |kind: &[u8], data: &[u8]| {
        out.extend_from_slice(&(data.len() as u32).to_be_bytes());
        let mut c = kind.to_vec();
        c.extend_from_slice(data);
        out.extend_from_slice(&c);
        out.extend_from_slice(&crc32(&c).to_be_bytes());
    };
    let mut ihdr = Vec::new();
    ihdr.extend_from_slice(&(w as u32).to_be_bytes());
    ihdr.extend_from_slice(&(h as u32).to_be_bytes());
    ihdr.extend_from_slice(&[8, 2, 0, 0, 0]);
    chunk(b"IHDR", &ihdr);
    chunk(b"IDAT", &z);
    chunk(b"IEND", &[]);
    out
}

/// Standard base64.
pub fn base64(data: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut s = String::with_capacity(data.len().div_ceil(3) * 4);
    for ch in data.chunks(3) {
        let b = [ch[0], *ch.get(1).unwrap_or(&0), *ch.get(2).unwrap_or(&0)];
        let v = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= ch.len() {
                s.push(A[((v >> (18 - 6 * k)) & 63) as usize] as char);
            } else {
                s.push('=');
            }
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_and_labels() {
        let (t, s) = nice_ticks(0.0, 1.047, 6);
        assert_eq!(s, 0.2);
        assert_eq!(t.len(), 6);
        assert_eq!(decimals_for(0.25), 2);
        assert_eq!(decimals_for(5.0), 0);
        assert_eq!(tick_text(-0.0000001, 2), "0.00");
        assert_eq!(tick_text(-0.5, 1), "\u{2212}0.5");
        assert_eq!(log_tick_text(-2.0), "0.01");
        assert_eq!(log_tick_text(2f64.log10()), "2");
        assert_eq!(log_ticks(0.1, 10.0).len(), 7);
    }

    #[test]
    fn clipping_keeps_only_the_inside() {
        let pts = vec![(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)];
        let pieces = clip_polyline(&pts, 0.0, 2.0, 0.0, 1.0);
        assert_eq!(pieces.len(), 2);
        for p in &pieces {
            for q in p {
                assert!(q.1 <= 1.0 + 1e-12 && q.1 >= 0.0);
            }
        }
        assert_eq!(pieces[0][0], (0.0, 0.0));
        assert!((pieces[0][1].0 - 0.5).abs() < 1e-12);
        let inside = clip_polyline(&[(0.1, 0.1), (0.2, 0.2), (0.3, 0.1)], 0.0, 1.0, 0.0, 1.0);
        assert_eq!(inside, vec![vec![(0.1, 0.1), (0.2, 0.2), (0.3, 0.1)]]);
    }

    #[test]
    fn contour_of_a_plane() {
        let xs = [0.0, 1.0, 2.0];
        let ys = [0.0, 1.0];
        let z = vec![vec![0.0, 1.0, 2.0], vec![0.0, 1.0, 2.0]];
        let s = contour(&xs, &ys, &z, 0.5);
        assert_eq!(s.len(), 1);
        assert!((s[0][0].0 - 0.5).abs() < 1e-12);
        let z3 = vec![vec![0.0, 1.0, 2.0]; 3];
        let segs = contour(&xs, &[0.0, 1.0, 2.0], &z3, 0.5);
        assert_eq!(chain(&segs).len(), 1);
        assert_eq!(chain(&segs)[0].len(), 3);
    }

    #[test]
    fn coordinates_keep_sub_pixel_precision() {
        let mut p = Panel::new("", "x", "y");
        p.xrange = Some((0.0, 1.0));
        p.yrange = Some((0.0, 1.0));
        let pts: Vec<(f64, f64)> = (0..=50)
            .map(|i| {
                let x = f64::from(i) / 50.0;
                (x, x * x)
            })
            .collect();
        p.series.push(Series::new("a", PALETTE[0], pts));
        let fig = Figure::single("t.svg", "t".into(), (400, 300), p, 0);
        let svg = render_layout(&fig, Layout::Wide);
        let path = svg
            .lines()
            .find(|l| l.starts_with("<path d=\"M") && l.contains("#0072b2"))
            .expect("the curve");
        // some coordinates are not whole pixels
        assert!(path.contains('.'), "{path}");
        assert!(svg.contains("<title>a</title>"));
    }

    #[test]
    fn png_and_base64_are_well_formed() {
        assert_eq!(base64(b"Man"), "TWFu");
        assert_eq!(base64(b"Ma"), "TWE=");
        assert_eq!(crc32(b"IEND"), 0xae42_6082);
        let p = png(2, 1, &[(255, 0, 0), (0, 0, 255)]);
        assert_eq!(&p[1..4], b"PNG");
        assert_eq!(csv_num(0.000_123_456_789, 4), "0.0001235");
        assert_eq!(csv_num(-2.5, 12), "-2.5");
    }
}
