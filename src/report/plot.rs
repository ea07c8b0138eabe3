//! Figures as plain data, rendered to SVG with plotters.
//!
//! The one place of the crate where `f64` is used for numbers: the plotted
//! points are oracle values (already verified to the digits the report asks
//! for) rounded to `f64`.
//!
//! plotters' pitfalls, handled here (see `shared/DESIGN.md`):
//! - data outside the axis range is drawn along the frame, so every polyline
//!   is clipped to the axis box here (Liang–Barsky) before it is handed over,
//!   and markers and cells outside the box are dropped;
//! - label widths are guessed from UTF-8 byte length, so label areas and the
//!   legend strip are sized explicitly, never from the guess;
//! - font sizes are scaled by 1/1.24 in the SVG, so sizes are given as
//!   multiples of 1.24 ([`px`]).
//!
//! Tick positions and tick labels are computed here ([`nice_ticks`]) and
//! formatted with a fixed number of decimals, so the SVG text is a pure
//! function of the data: two runs write byte-identical files.

use crate::error::{Error, Result};
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::prelude::*;

/// A linear axis over [lo, hi] whose ticks (and grid lines) are exactly the
/// given values (plotters' own `WithKeyPoints` cannot take a label formatter
/// for `f64`).
#[derive(Debug, Clone)]
struct TickAxis {
    lo: f64,
    hi: f64,
    ticks: Vec<f64>,
}

impl Ranged for TickAxis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, v: &f64, limit: (i32, i32)) -> i32 {
        let span = self.hi - self.lo;
        if span == 0.0 || !v.is_finite() {
            return (limit.0 + limit.1) / 2;
        }
        let u = (v - self.lo) / span;
        let len = f64::from(limit.1 - limit.0);
        limit.0 + (len * u).round() as i32
    }

    fn key_points<H: KeyPointHint>(&self, hint: H) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            Vec::new()
        } else {
            self.ticks.clone()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }
}

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

/// Font family of every text.
const FONT: &str = "sans-serif";

/// A font size that comes out as `n` px in the SVG (plotters divides by 1.24).
pub fn px(n: u32) -> f64 {
    f64::from(n) * 1.24
}

/// How a line is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dash {
    /// Solid.
    Solid,
    /// Dashed (long dashes).
    Dashed,
    /// Dotted (short dashes).
    Dotted,
}

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
    pub width: u32,
    /// Points in data coordinates (x as given, also for a log axis).
    pub points: Vec<(f64, f64)>,
}

impl Series {
    /// A solid curve of width 2.
    pub fn new(label: impl Into<String>, color: Rgb, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.into(),
            color,
            dash: Dash::Solid,
            width: 2,
            points,
        }
    }

    /// The same curve with another line style.
    pub fn dashed(mut self, dash: Dash) -> Self {
        self.dash = dash;
        self
    }
}

/// A filled rectangle in data coordinates (heat maps).
#[derive(Debug, Clone)]
pub struct Cell {
    /// Lower-left corner.
    pub lo: (f64, f64),
    /// Upper-right corner.
    pub hi: (f64, f64),
    /// Fill colour.
    pub color: Rgb,
}

/// A marked point (e.g. separation).
#[derive(Debug, Clone)]
pub struct Marker {
    /// Position in data coordinates.
    pub at: (f64, f64),
    /// Fill colour.
    pub color: Rgb,
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
    /// Title over the chart.
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
    /// Legend text of the markers (None: not in the legend).
    pub marker_label: Option<String>,
    /// Filled cells, drawn first.
    pub cells: Vec<Cell>,
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
            marker_label: None,
            cells: Vec::new(),
        }
    }
}

/// A colour bar for a heat map, drawn in the figure's right strip.
#[derive(Debug, Clone)]
pub struct ColorBar {
    /// Label over the bar.
    pub label: String,
    /// Value range.
    pub range: (f64, f64),
    /// Levels marked with a black line across the bar (contour levels).
    pub marks: Vec<f64>,
}

/// A figure: a grid of panels, a title, and a right strip with the legend
/// (collected from the panels' labelled series) or a colour bar.
#[derive(Debug, Clone)]
pub struct Figure {
    /// File name (no directory), e.g. `theta_t.svg`.
    pub file: String,
    /// Title at the top.
    pub title: String,
    /// Width and height in px.
    pub size: (u32, u32),
    /// Rows and columns of panels.
    pub grid: (usize, usize),
    /// Panels, row by row.
    pub panels: Vec<Panel>,
    /// Width of the right strip in px (0: none).
    pub strip: u32,
    /// A colour bar in the strip instead of a legend.
    pub colorbar: Option<ColorBar>,
    /// Caption for the page (not drawn).
    pub caption: String,
}

fn draw_err(file: &str, e: impl std::fmt::Display) -> Error {
    Error::Io {
        path: file.to_string(),
        what: format!("drawing the figure: {e}"),
    }
}

fn rgb(c: Rgb) -> RGBColor {
    RGBColor(c.0, c.1, c.2)
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

/// A tick label with `dec` decimals (never "-0").
pub fn tick_text(v: f64, dec: usize) -> String {
    let s = format!("{v:.dec$}");
    if s.trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
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

/// A one-pixel-thin style with a colour.
fn thin(c: Rgb, w: u32) -> ShapeStyle {
    ShapeStyle {
        color: rgb(c).to_rgba(),
        filled: false,
        stroke_width: w,
    }
}

type Area<'a> = DrawingArea<SVGBackend<'a>, plotters::coord::Shift>;

/// Renders the figure to an SVG string.
pub fn render(fig: &Figure) -> Result<String> {
    let mut buf = String::new();
    {
        let file = fig.file.as_str();
        let root = SVGBackend::with_string(&mut buf, fig.size).into_drawing_area();
        root.fill(&WHITE).map_err(|e| draw_err(file, e))?;
        let body = root
            .titled(&fig.title, (FONT, px(20)).into_font())
            .map_err(|e| draw_err(file, e))?;
        let (charts, strip) = if fig.strip > 0 {
            let w = body.dim_in_pixel().0;
            body.split_horizontally(w.saturating_sub(fig.strip))
        } else {
            let w = body.dim_in_pixel().0;
            body.split_horizontally(w)
        };
        let cells = charts.split_evenly(fig.grid);
        for (panel, area) in fig.panels.iter().zip(cells.iter()) {
            draw_panel(file, panel, area)?;
        }
        if fig.strip > 0 {
            if let Some(cb) = &fig.colorbar {
                draw_colorbar(file, cb, &strip)?;
            } else {
                draw_legend(file, fig, &strip)?;
            }
        }
        root.present().map_err(|e| draw_err(file, e))?;
    }
    Ok(buf)
}

fn draw_panel(file: &str, p: &Panel, area: &Area<'_>) -> Result<()> {
    let ((dx0, dx1), (dy0, dy1)) = data_range(p);
    let log = p.xscale == Scale::Log;
    // x in chart coordinates: log10 for a log axis
    let tx = |x: f64| if log { x.log10() } else { x };
    let (xlo, xhi, xticks, xdec) = if log {
        let (a, b) = p.xrange.unwrap_or((dx0, dx1));
        let t = log_ticks(a, b).into_iter().map(|v| v.log10()).collect();
        (a, b, t, 0)
    } else {
        linear_axis(p.xrange, (dx0, dx1), 7)
    };
    let (ylo, yhi, yticks, ydec) = linear_axis(p.yrange, (dy0, dy1), 6);
    let (cx0, cx1) = (tx(xlo), tx(xhi));
    let ywidth = yticks
        .iter()
        .map(|v| tick_text(*v, ydec).len())
        .max()
        .unwrap_or(1);
    // tick labels at 12 px (~7 px per character) + the rotated axis label
    let y_area = (ywidth as u32) * 8 + 40;

    let mut chart = ChartBuilder::on(area)
        .caption(&p.title, (FONT, px(16)).into_font())
        .margin_left(8)
        .margin_right(18)
        .margin_top(6)
        .margin_bottom(6)
        .x_label_area_size(46)
        .y_label_area_size(y_area)
        .build_cartesian_2d(
            TickAxis {
                lo: cx0,
                hi: cx1,
                ticks: xticks,
            },
            TickAxis {
                lo: ylo,
                hi: yhi,
                ticks: yticks,
            },
        )
        .map_err(|e| draw_err(file, e))?;

    let xfmt = move |v: &f64| {
        if log {
            log_tick_text(*v)
        } else {
            tick_text(*v, xdec)
        }
    };
    let yfmt = move |v: &f64| tick_text(*v, ydec);
    chart
        .configure_mesh()
        .x_desc(p.xlabel.as_str())
        .y_desc(p.ylabel.as_str())
        .x_label_formatter(&xfmt)
        .y_label_formatter(&yfmt)
        .label_style((FONT, px(12)).into_font())
        .axis_desc_style((FONT, px(14)).into_font())
        .bold_line_style(thin((225, 225, 225), 1))
        .light_line_style(thin((255, 255, 255), 0))
        .axis_style(thin((60, 60, 60), 1))
        .draw()
        .map_err(|e| draw_err(file, e))?;

    // cells (clipped to the box)
    for c in &p.cells {
        let (a0, a1) = (tx(c.lo.0).max(cx0), tx(c.hi.0).min(cx1));
        let (b0, b1) = (c.lo.1.max(ylo), c.hi.1.min(yhi));
        if a0 < a1 && b0 < b1 {
            // filled, and outlined in the same colour so that scaled
            // renderings show no seams between neighbouring cells
            chart
                .draw_series([
                    Rectangle::new([(a0, b0), (a1, b1)], rgb(c.color).filled()),
                    Rectangle::new([(a0, b0), (a1, b1)], thin(c.color, 1)),
                ])
                .map_err(|e| draw_err(file, e))?;
        }
    }

    for s in &p.series {
        let pts: Vec<(f64, f64)> = s.points.iter().map(|&(x, y)| (tx(x), y)).collect();
        let style = thin(s.color, s.width);
        for piece in clip_polyline(&pts, cx0, cx1, ylo, yhi) {
            match s.dash {
                Dash::Solid => {
                    chart
                        .draw_series(LineSeries::new(piece, style))
                        .map_err(|e| draw_err(file, e))?;
                }
                Dash::Dashed | Dash::Dotted => {
                    let (len, gap) = if s.dash == Dash::Dashed {
                        (9, 5)
                    } else {
                        (3, 4)
                    };
                    chart
                        .draw_series(DashedLineSeries::new(piece, len, gap, style))
                        .map_err(|e| draw_err(file, e))?;
                }
            }
        }
    }

    for m in &p.markers {
        let x = tx(m.at.0);
        let y = m.at.1;
        if x >= cx0 && x <= cx1 && y >= ylo && y <= yhi && x.is_finite() && y.is_finite() {
            chart
                .draw_series(std::iter::once(Circle::new(
                    (x, y),
                    5,
                    rgb(m.color).filled(),
                )))
                .map_err(|e| draw_err(file, e))?;
            chart
                .draw_series(std::iter::once(Circle::new((x, y), 5, thin((0, 0, 0), 1))))
                .map_err(|e| draw_err(file, e))?;
        }
    }
    Ok(())
}

/// The legend: every labelled series of the figure once (first occurrence),
/// then the marker entry.
fn draw_legend(file: &str, fig: &Figure, area: &Area<'_>) -> Result<()> {
    let mut entries: Vec<(&str, Rgb, Dash)> = Vec::new();
    let mut marker: Option<&str> = None;
    for p in &fig.panels {
        for s in &p.series {
            if !s.label.is_empty() && !entries.iter().any(|e| e.0 == s.label) {
                entries.push((s.label.as_str(), s.color, s.dash));
            }
        }
        if marker.is_none() {
            marker = p.marker_label.as_deref();
        }
    }
    // the palette's order (variants, forces, families), whatever panel came first
    let rank = |c: Rgb| {
        PALETTE
            .iter()
            .position(|p| *p == c)
            .unwrap_or(PALETTE.len())
    };
    entries.sort_by_key(|e| rank(e.1));
    let font = (FONT, px(13)).into_font().color(&BLACK);
    let x = 4i32;
    let mut y = 48i32;
    for (label, color, dash) in entries {
        let style = thin(color, 3);
        match dash {
            Dash::Solid => area
                .draw(&PathElement::new(vec![(x, y), (x + 30, y)], style))
                .map_err(|e| draw_err(file, e))?,
            Dash::Dashed | Dash::Dotted => {
                let (len, gap) = if dash == Dash::Dashed { (8, 4) } else { (3, 4) };
                let mut a = x;
                while a < x + 30 {
                    let b = (a + len).min(x + 30);
                    area.draw(&PathElement::new(vec![(a, y), (b, y)], style))
                        .map_err(|e| draw_err(file, e))?;
                    a = b + gap;
                }
            }
        }
        for (i, line) in label.split('\n').enumerate() {
            area.draw(&Text::new(
                line.to_string(),
                (x + 38, y - 8 + 17 * i as i32),
                font.clone(),
            ))
            .map_err(|e| draw_err(file, e))?;
        }
        y += 12 + 17 * label.split('\n').count() as i32;
    }
    if let Some(m) = marker {
        area.draw(&Circle::new((x + 15, y), 5, WHITE.filled()))
            .map_err(|e| draw_err(file, e))?;
        area.draw(&Circle::new((x + 15, y), 5, thin((0, 0, 0), 1)))
            .map_err(|e| draw_err(file, e))?;
        for (i, line) in m.split('\n').enumerate() {
            area.draw(&Text::new(
                line.to_string(),
                (x + 38, y - 8 + 17 * i as i32),
                font.clone(),
            ))
            .map_err(|e| draw_err(file, e))?;
        }
    }
    Ok(())
}

/// A perceptually ordered colour map (viridis, by 9 anchors), u in [0, 1].
pub fn viridis(u: f64) -> Rgb {
    const A: [Rgb; 9] = [
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
    let u = if u.is_finite() {
        u.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let s = u * (A.len() - 1) as f64;
    let i = (s.floor() as usize).min(A.len() - 2);
    let f = s - i as f64;
    let mix = |a: u8, b: u8| (f64::from(a) + f * (f64::from(b) - f64::from(a))).round() as u8;
    (
        mix(A[i].0, A[i + 1].0),
        mix(A[i].1, A[i + 1].1),
        mix(A[i].2, A[i + 1].2),
    )
}

fn draw_colorbar(file: &str, cb: &ColorBar, area: &Area<'_>) -> Result<()> {
    let (w, h) = area.dim_in_pixel();
    let top = 60i32;
    let bottom = h as i32 - 70;
    let x0 = 10i32;
    let x1 = 34i32;
    let font = (FONT, px(13)).into_font().color(&BLACK);
    area.draw(&Text::new(cb.label.clone(), (x0, top - 34), font.clone()))
        .map_err(|e| draw_err(file, e))?;
    let n = (bottom - top).max(1);
    for i in 0..n {
        let u = 1.0 - (f64::from(i) + 0.5) / f64::from(n);
        area.draw(&Rectangle::new(
            [(x0, top + i), (x1, top + i + 1)],
            rgb(viridis(u)).filled(),
        ))
        .map_err(|e| draw_err(file, e))?;
    }
    area.draw(&Rectangle::new(
        [(x0, top), (x1, bottom)],
        thin((0, 0, 0), 1),
    ))
    .map_err(|e| draw_err(file, e))?;
    let (lo, hi) = cb.range;
    let ypix = |v: f64| -> i32 {
        let u = (v - lo) / (hi - lo);
        (f64::from(bottom) - u * f64::from(bottom - top)).round() as i32
    };
    let (ticks, step) = nice_ticks(lo, hi, 6);
    let dec = decimals_for(step);
    for t in ticks {
        let y = ypix(t);
        area.draw(&PathElement::new(
            vec![(x1, y), (x1 + 5, y)],
            thin((0, 0, 0), 1),
        ))
        .map_err(|e| draw_err(file, e))?;
        area.draw(&Text::new(tick_text(t, dec), (x1 + 8, y - 7), font.clone()))
            .map_err(|e| draw_err(file, e))?;
    }
    for m in &cb.marks {
        if *m > lo && *m < hi {
            let y = ypix(*m);
            area.draw(&PathElement::new(
                vec![(x0, y), (x1, y)],
                thin((0, 0, 0), 1),
            ))
            .map_err(|e| draw_err(file, e))?;
        }
    }
    let _ = w;
    Ok(())
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
    }
}
