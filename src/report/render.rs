//! A [`Figure`] drawn in one of its two layouts: plotters builds every
//! panel (the chart's coordinates, the frame, ticks, tick labels, grid and
//! axis titles, the curves, shading and patches, the markers) on cylroll's
//! [`Canvas`]; cylroll's own code adds what plotters lacks: the layouts at
//! print widths, the direct labels placed clear of everything
//! ([`super::labels`]), the legend in one order and the colour bar
//! ([`super::legend`]).

use super::axes::{self, clip_polyline, Axis};
use super::canvas::{svg_document, Canvas, Doc, Rgb, S};
use super::labels::{self, text_box, Obstacles, Rect};
use super::legend;
use super::marks::{darker, draw_marker, own_text, rgb, width};
use super::model::{Figure, Panel, RefLine, Series, Shape};
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::cell::RefCell;
use std::rc::Rc;

/// Which arrangement of a figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layout {
    /// Two journal columns (178 mm): the figure's grid of panels.
    Wide,
    /// One journal column (85 mm): one column of panels.
    Narrow,
}

/// Millimetres to points.
pub fn mm(v: f64) -> f64 {
    v / 25.4 * 72.0
}

impl Layout {
    /// Width in pt: 178 mm and 85 mm.
    pub fn width(self) -> f64 {
        match self {
            Layout::Wide => mm(178.0),
            Layout::Narrow => mm(85.0),
        }
    }
}

/// Font sizes in pt at print size (none below 7 pt).
pub const TICK: f64 = 7.0;
/// Axis titles.
pub const AXIS: f64 = 7.5;
/// Panel titles.
pub const TITLE: f64 = 8.0;
/// Texts in the plot (labels, notes) and the legend.
pub const LABEL: f64 = 7.0;
/// Line width of curves (pt).
pub const CURVE_W: f64 = 1.1;
/// Marker radius (pt).
pub const MARK_R: f64 = 2.4;

const GRID: RGBColor = RGBColor(225, 225, 225);
const INK: RGBColor = RGBColor(40, 40, 40);

fn font(size: f64) -> TextStyle<'static> {
    ("DejaVu Sans", size * S).into_font().color(&INK)
}

/// The axes of every panel, ranges shared where the figure says so.
fn panel_axes(fig: &Figure, layout: Layout) -> Vec<(Axis, Axis)> {
    let union = |x: bool| {
        fig.panels
            .iter()
            .filter_map(|p| {
                let fixed = if x { p.xrange } else { p.yrange };
                fixed.or_else(|| axes::data_range(p, x))
            })
            .fold(None, |acc: Option<(f64, f64)>, r| {
                Some(acc.map_or(r, |a| (a.0.min(r.0), a.1.max(r.1))))
            })
    };
    let (ux, uy) = (union(true), union(false));
    let cols = match layout {
        Layout::Wide => fig.cols,
        Layout::Narrow => 1,
    };
    let pw = layout.width() / cols as f64;
    let xt = ((pw - 40.0) / 38.0).clamp(4.0, 7.0) as usize;
    fig.panels
        .iter()
        .map(|p| {
            let xd = if fig.share_x {
                ux
            } else {
                axes::data_range(p, true)
            };
            let yd = if fig.share_y {
                uy
            } else {
                axes::data_range(p, false)
            };
            let xf = if fig.share_x && p.xrange.is_none() {
                None
            } else {
                p.xrange
            };
            let yf = if fig.share_y && p.yrange.is_none() {
                None
            } else {
                p.yrange
            };
            let x = if p.xlog {
                axes::logarithmic(xf.or(if fig.share_x { ux } else { None }), xd, xf.is_none())
            } else {
                axes::linear(xf, xd, xt)
            };
            let y = if p.ylog {
                axes::logarithmic(yf.or(if fig.share_y { uy } else { None }), yd, yf.is_none())
            } else {
                axes::linear(yf, yd, 5)
            };
            (x, y)
        })
        .collect()
}

/// A figure drawn in one layout.
#[derive(Debug, Clone)]
pub struct Rendered {
    /// The SVG document.
    pub svg: String,
    /// Width and height in pt.
    pub size: (f64, f64),
    /// Direct labels, notes and event labels left out for want of a free
    /// place (the legend and the hover texts still carry them).
    pub dropped: Vec<String>,
}

/// Renders `fig` in `layout`.
pub fn render(fig: &Figure, layout: Layout) -> Rendered {
    if let Some((wide, narrow)) = &fig.raw {
        let s = if layout == Layout::Wide { wide } else { narrow };
        return Rendered {
            svg: s.clone(),
            size: svg_size(s),
            dropped: Vec::new(),
        };
    }
    let w = layout.width();
    let cols = match layout {
        Layout::Wide => fig.cols,
        Layout::Narrow => 1,
    };
    let ph = match layout {
        Layout::Wide => fig.panel_h.0,
        Layout::Narrow => fig.panel_h.1,
    };
    let rows = fig.panels.len().div_ceil(cols).max(1);
    let entries = legend::entries(fig);
    let leg = legend::layout(&entries, w);
    let cb_h = if fig.colorbar.is_some() { 44.0 } else { 0.0 };
    let h = (rows as f64 * ph + leg.height + cb_h + 4.0).ceil();
    let doc = Rc::new(RefCell::new(Doc::default()));
    {
        let root = Canvas::new(doc.clone(), w, h).into_drawing_area();
        let margins = label_margins(fig);
        let all_axes = panel_axes(fig, layout);
        // the room for tick labels and axis titles: the widest of each
        // column and row, so that the frames of a column (and of a row) line up
        let own: Vec<(f64, f64)> = fig
            .panels
            .iter()
            .zip(&all_axes)
            .map(|(p, ax)| label_areas(ax, p))
            .collect();
        let areas: Vec<(f64, f64)> = (0..own.len())
            .map(|k| {
                let col = (0..own.len()).filter(|j| j % cols == k % cols);
                let row = (0..own.len()).filter(|j| j / cols == k / cols);
                (
                    col.map(|j| own[j].0).fold(0.0, f64::max),
                    row.map(|j| own[j].1).fold(0.0, f64::max),
                )
            })
            .collect();
        let pw = w / cols as f64;
        for (k, (p, ax)) in fig.panels.iter().zip(&all_axes).enumerate() {
            let (r, c) = (k / cols, k % cols);
            let area = root.clone().shrink(
                ((c as f64 * pw * S) as i32, (r as f64 * ph * S) as i32),
                ((pw * S) as u32, (ph * S) as u32),
            );
            draw_panel(&root, &area, &doc, p, ax, margins, areas[k]);
        }
        let top = rows as f64 * ph;
        legend::draw(&root, &doc, &entries, &leg, top);
        if let Some(cb) = &fig.colorbar {
            legend::colorbar(&doc, cb, (6.0, top + leg.height + 2.0, w - 12.0));
        }
    }
    let body = std::mem::take(&mut doc.borrow_mut().body);
    let dropped = std::mem::take(&mut doc.borrow_mut().dropped);
    Rendered {
        svg: svg_document(w, h, &body),
        size: (w, h),
        dropped,
    }
}

/// The width and height of an SVG's root (pt).
pub fn svg_size(svg: &str) -> (f64, f64) {
    let attr = |name: &str| {
        let pat = format!(" {name}=\"");
        svg.find(&pat)
            .and_then(|i| {
                let rest = &svg[i + pat.len()..];
                rest[..rest.find('"')?]
                    .trim_end_matches("pt")
                    .parse::<f64>()
                    .ok()
            })
            .unwrap_or(100.0)
    };
    (attr("width"), attr("height"))
}

/// The strip over every plot for the labels of vertical reference lines,
/// and the margin right of every plot for those of horizontal ones (pt):
/// the same in every panel of a figure, so that panels side by side keep
/// their frames aligned.
fn label_margins(fig: &Figure) -> (f64, f64) {
    let lines = || fig.panels.iter().flat_map(|p| &p.lines);
    let strip = if lines().any(|l| l.vertical && !l.label.is_empty()) {
        LABEL * 1.3
    } else {
        0.0
    };
    let names = fig
        .panels
        .iter()
        .filter(|p| p.names_right)
        .flat_map(|p| p.series.iter().filter_map(|s| s.direct.as_ref()));
    let gutter = lines()
        .filter(|l| !l.vertical && !l.label.is_empty())
        .map(|l| &l.label)
        .chain(names)
        .map(|t| super::canvas::text_width(t, LABEL) + 4.0)
        .fold(0.0, f64::max);
    (strip, gutter)
}

/// Room for the y tick labels and title, and the x ones (pt).
fn label_areas(ax: &(Axis, Axis), p: &Panel) -> (f64, f64) {
    let yw =
        ax.1.texts
            .iter()
            .map(|t| super::canvas::text_width(t, TICK))
            .fold(0.0, f64::max);
    let ytitle = if p.yq.label.is_empty() {
        0.0
    } else {
        AXIS * 1.3
    };
    let xtitle = if p.xq.label.is_empty() {
        0.0
    } else {
        AXIS * 1.3
    };
    (yw + 6.0 + ytitle + 2.0, TICK * 1.2 + 5.0 + xtitle + 2.0)
}

/// A linear axis whose ticks are the ones cylroll chose ([`Axis`]).
#[derive(Clone)]
pub struct Ticked {
    lo: f64,
    hi: f64,
    ticks: Vec<f64>,
}

impl Ranged for Ticked {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, v: &f64, limit: (i32, i32)) -> i32 {
        RangedCoordf64::from(self.lo..self.hi).map(v, limit)
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

fn ticked(a: &Axis) -> Ticked {
    Ticked {
        lo: a.range.0,
        hi: a.range.1,
        ticks: a.ticks.clone(),
    }
}

type Chart<'a> = ChartContext<'a, Canvas, Cartesian2d<Ticked, Ticked>>;

/// One panel: plotters' chart, then cylroll's labels.
fn draw_panel(
    root: &DrawingArea<Canvas, Shift>,
    area: &DrawingArea<Canvas, Shift>,
    doc: &Rc<RefCell<Doc>>,
    p: &Panel,
    ax: &(Axis, Axis),
    margins: (f64, f64),
    (ylab, xlab): (f64, f64),
) {
    let (x, y) = ax;
    let (strip, gutter) = margins;
    let top = strip
        + if p.title.is_empty() {
            6.0
        } else {
            TITLE * 1.6 + 2.0
        };
    let built = ChartBuilder::on(area)
        .margin_top((top * S) as i32)
        .margin_right(((7.0 + gutter) * S) as i32)
        .margin_left((2.0 * S) as i32)
        .x_label_area_size((xlab * S) as i32)
        .y_label_area_size((ylab * S) as i32)
        .build_cartesian_2d(ticked(x), ticked(y));
    let Ok(mut chart) = built else { return };
    let plot = plot_rect(&chart);
    // patches and shaded bands under everything
    for pa in &p.patches {
        doc.borrow_mut().set("patch", "", &pa.title);
        let style = rgb(pa.color).filled();
        let _ = chart.draw_series(std::iter::once(Polygon::new(pa.outline.clone(), style)));
    }
    for b in &p.bands {
        let (x0, x1) = (x.c(b.x.0).max(x.range.0), x.c(b.x.1).min(x.range.1));
        if x0 < x1 {
            doc.borrow_mut().set("band", "", &b.title);
            let style = rgb(b.color).filled();
            let _ = chart.draw_series(std::iter::once(Rectangle::new(
                [(x0, y.range.0), (x1, y.range.1)],
                style,
            )));
        }
    }
    // the mesh: grid, axes, ticks, tick labels, axis titles
    doc.borrow_mut().set("axis", "", "");
    let xf = |v: &f64| tick_for(x, *v);
    let yf = |v: &f64| tick_for(y, *v);
    let _ = chart
        .configure_mesh()
        .bold_line_style(if p.grid {
            GRID.stroke_width(width(0.4))
        } else {
            TRANSPARENT.stroke_width(0)
        })
        .light_line_style(TRANSPARENT)
        .axis_style(INK.stroke_width(width(0.6)))
        .set_all_tick_mark_size((2.5 * S) as i32)
        .label_style(font(TICK))
        .axis_desc_style(font(AXIS))
        .x_labels(x.ticks.len() + 2)
        .y_labels(y.ticks.len() + 2)
        .x_label_formatter(&xf)
        .y_label_formatter(&yf)
        .x_desc(p.xq.label.clone())
        .y_desc(p.yq.label.clone())
        .draw();
    // the frame
    doc.borrow_mut().set("frame", "", "");
    let _ = chart.draw_series(std::iter::once(Rectangle::new(
        [(x.range.0, y.range.0), (x.range.1, y.range.1)],
        INK.stroke_width(width(0.6)),
    )));
    if !p.title.is_empty() {
        own_text(
            doc,
            ((plot.0 + plot.1) / 2.0, plot.2 - 4.0 - strip),
            &p.title,
            TITLE,
            "middle",
            (0, 0, 0),
            false,
        );
    }
    let mut obst = Obstacles {
        area: Some(plot),
        ..Default::default()
    };
    let to_pt = |chart: &Chart, cx: f64, cy: f64| {
        let b = chart.backend_coord(&(cx, cy));
        (f64::from(b.0) / S, f64::from(b.1) / S)
    };
    // curves, clipped, as drawn (pt), for the obstacles
    let pieces: Vec<Vec<Vec<(f64, f64)>>> = p
        .series
        .iter()
        .map(|s| {
            let pts: Vec<(f64, f64)> = s.points.iter().map(|&(a, b)| (x.c(a), y.c(b))).collect();
            if s.drawn {
                clip_polyline(&pts, x.range.0, x.range.1, y.range.0, y.range.1)
            } else {
                Vec::new()
            }
        })
        .collect();
    let mut px_pieces: Vec<Vec<Vec<(f64, f64)>>> = pieces
        .iter()
        .map(|ps| {
            ps.iter()
                .map(|q| q.iter().map(|&(a, b)| to_pt(&chart, a, b)).collect())
                .collect()
        })
        .collect();
    // reference lines
    let mut ref_px = Vec::new();
    for l in &p.lines {
        let (a, b) = if l.vertical {
            let cx = x.c(l.at);
            if cx < x.range.0 || cx > x.range.1 {
                continue;
            }
            ((cx, y.range.0), (cx, y.range.1))
        } else {
            let cy = y.c(l.at);
            if cy < y.range.0 || cy > y.range.1 {
                continue;
            }
            ((x.range.0, cy), (x.range.1, cy))
        };
        doc.borrow_mut().set("r", l.dash.array(), &l.title);
        let _ = chart.draw_series(std::iter::once(PathElement::new(
            vec![a, b],
            rgb(l.color).stroke_width(width(0.8)),
        )));
        let line = vec![to_pt(&chart, a.0, a.1), to_pt(&chart, b.0, b.1)];
        obst.lines.push(line.clone());
        ref_px.push((l, line));
    }
    for ps in &px_pieces {
        obst.lines.extend(ps.iter().cloned());
    }
    // inline labels (contour levels) cut a gap into their own line
    let mut inline_texts = Vec::new();
    for (i, s) in p.series.iter().enumerate() {
        let Some(t) = s
            .direct
            .as_ref()
            .filter(|_| s.width < 0.9 && s.key.starts_with("contour"))
        else {
            continue;
        };
        let own: Vec<Vec<(f64, f64)>> = px_pieces[i].clone();
        let mut others = obst.clone();
        others.lines.retain(|l| !own.contains(l));
        let cands: Vec<(f64, f64, &'static str)> = own
            .iter()
            .flat_map(|l| {
                let m = l.len() / 2;
                let order: Vec<usize> = (0..l.len())
                    .map(|k| {
                        if k % 2 == 0 {
                            m + k / 2
                        } else {
                            m.saturating_sub(k / 2 + 1)
                        }
                    })
                    .filter(|&j| j < l.len())
                    .collect();
                order
                    .into_iter()
                    .map(|j| {
                        (
                            l[j].0,
                            l[j].1
                                + (super::canvas::ascent() - super::canvas::descent()) * LABEL
                                    / 2.0,
                            "middle",
                        )
                    })
                    .collect::<Vec<_>>()
            })
            .collect();
        if let Some(pl) = others.place(t, LABEL, &cands) {
            let b = text_box(pl.0, pl.1, t, LABEL, pl.2);
            obst.take(b);
            px_pieces[i] = px_pieces[i]
                .iter()
                .flat_map(|l| cut(l, grow(b, 1.0)))
                .collect();
            inline_texts.push((pl, t.clone(), s.color));
        }
    }
    // the curves
    for (s, ps) in p.series.iter().zip(&px_pieces) {
        if !s.drawn {
            continue;
        }
        let title = if s.label.is_empty() {
            s.key.clone()
        } else {
            s.label.replace('\n', " ")
        };
        doc.borrow_mut().set("c", s.dash.array(), &title);
        for piece in ps {
            let pts: Vec<(i32, i32)> = piece
                .iter()
                .map(|&(a, b)| ((a * S).round() as i32, (b * S).round() as i32))
                .collect();
            let _ = root.draw(&PathElement::new(
                pts,
                rgb(s.color).stroke_width(width(s.width)),
            ));
        }
    }
    for (pl, t, c) in &inline_texts {
        own_text(doc, (pl.0, pl.1), t, LABEL, pl.2, darker(*c), true);
    }
    // markers: end markers, event markers, periodic markers where free
    let mut marks: Vec<Mark> = Vec::new();
    for s in p.series.iter().filter(|s| s.drawn) {
        if let (Some(t), Some(&(a, b))) = (
            &s.end,
            s.points
                .iter()
                .rev()
                .find(|q| q.0.is_finite() && q.1.is_finite()),
        ) {
            if inside(x, y, a, b) {
                marks.push((
                    to_pt(&chart, x.c(a), y.c(b)),
                    s.shape.unwrap_or(Shape::Circle),
                    s.color,
                    false,
                    t.clone(),
                    None,
                ));
            }
        }
    }
    for m in &p.markers {
        if inside(x, y, m.at.0, m.at.1) {
            marks.push((
                to_pt(&chart, x.c(m.at.0), y.c(m.at.1)),
                m.shape,
                m.color,
                m.filled,
                m.title.clone(),
                m.label.clone(),
            ));
        }
    }
    let taken: Vec<(f64, f64)> = marks.iter().map(|m| m.0).collect();
    for s in p.series.iter().filter(|s| s.drawn && s.every > 0) {
        let Some(shape) = s.shape else { continue };
        let last = s.points.len().saturating_sub(1);
        for (i, &(a, b)) in s.points.iter().enumerate() {
            if i >= s.offset
                && (i - s.offset) % s.every == 0
                && i + s.every / 2 < last
                && inside(x, y, a, b)
            {
                let q = to_pt(&chart, x.c(a), y.c(b));
                if taken
                    .iter()
                    .all(|t| (t.0 - q.0).hypot(t.1 - q.1) > 3.0 * MARK_R)
                {
                    marks.push((q, shape, s.color, false, s.label.clone(), None));
                }
            }
        }
    }
    for m in &marks {
        let r = if m.3 { MARK_R * 1.1 } else { MARK_R };
        draw_marker(root, doc, "m", m.0, m.1, r, m.2, m.3, &m.4);
        obst.take((
            m.0 .0 - r - 0.6,
            m.0 .0 + r + 0.6,
            m.0 .1 - r - 0.6,
            m.0 .1 + r + 0.6,
        ));
    }
    // labels: events, reference lines, curves' ends, notes
    for m in &marks {
        if let Some(l) = &m.5 {
            match obst.place(
                l,
                LABEL,
                &labels::around(m.0 .0, m.0 .1, MARK_R + 2.0, LABEL),
            ) {
                Some(pl) => own_text(doc, (pl.0, pl.1), l, LABEL, pl.2, (0, 0, 0), true),
                None => doc.borrow_mut().dropped.push(l.clone()),
            }
        }
    }
    let over: Vec<(f64, &RefLine)> = ref_px
        .iter()
        .filter(|(l, _)| l.vertical && !l.label.is_empty())
        .map(|(l, line)| (line[0].0, *l))
        .collect();
    let widths: Vec<f64> = over
        .iter()
        .map(|(_, l)| super::canvas::text_width(&l.label, LABEL))
        .collect();
    let xs: Vec<f64> = over.iter().map(|o| o.0).collect();
    let baseline = plot.2 - 2.0 - super::canvas::descent() * LABEL;
    for ((_, l), cx) in over
        .iter()
        .zip(labels::spread(&xs, &widths, plot.0, plot.1 + 6.0))
    {
        own_text(
            doc,
            (cx, baseline),
            &l.label,
            LABEL,
            "middle",
            darker(l.color),
            false,
        );
    }
    // in the margin right of the plot: horizontal lines' labels, and the
    // curves' names where the panel puts them there, each at its height
    let mut side: Vec<(f64, &str, Rgb)> = ref_px
        .iter()
        .filter(|(l, _)| !l.vertical && !l.label.is_empty())
        .map(|(l, line)| (line[0].1, l.label.as_str(), darker(l.color)))
        .collect();
    if p.names_right {
        for (s, ps) in p.series.iter().zip(&px_pieces) {
            if let (Some(t), Some(&end)) = (&s.direct, ps.last().and_then(|l| l.last())) {
                side.push((end.1, t.as_str(), darker(s.color)));
            }
        }
    }
    let ys: Vec<f64> = side.iter().map(|s| s.0).collect();
    for ((_, t, c), by) in side
        .iter()
        .zip(labels::stack(&ys, plot.2, plot.3 + 4.0, LABEL))
    {
        own_text(doc, (plot.1 + 3.0, by), t, LABEL, "start", *c, false);
    }
    // curves' names at their ends: every curve of the panel or none (the
    // legend names them all), never a few of them
    let mut trial = obst.clone();
    let mut named = Vec::new();
    let mut missing = Vec::new();
    for (s, ps) in p.series.iter().zip(&px_pieces) {
        let Some(t) = s
            .direct
            .as_ref()
            .filter(|_| !is_contour(s) && !p.names_right)
        else {
            continue;
        };
        let Some(last) = ps.last() else { continue };
        let &(ex, ey) = last.last().unwrap_or(&(0.0, 0.0));
        let mut cands = labels::around(ex, ey, MARK_R + 2.5, LABEL);
        cands.extend(labels::along(last, 12, LABEL));
        match trial.place(t, LABEL, &cands) {
            Some(pl) => named.push((pl, t.clone(), s.color)),
            None => missing.push(t.clone()),
        }
    }
    if missing.is_empty() {
        obst = trial;
        for (pl, t, c) in named {
            own_text(doc, (pl.0, pl.1), &t, LABEL, pl.2, darker(c), true);
        }
    } else {
        doc.borrow_mut().dropped.push(format!(
            "the curves' names ({} of {} fit)",
            named.len(),
            named.len() + missing.len()
        ));
    }
    for note in &p.notes {
        match obst.place(note, LABEL, &labels::corners_then_grid(plot, LABEL)) {
            Some(pl) => own_text(doc, (pl.0, pl.1), note, LABEL, pl.2, (40, 40, 40), true),
            None => doc.borrow_mut().dropped.push(note.clone()),
        }
    }
}

/// A marker to draw: its centre (pt), shape, colour, filled, hover text and
/// label.
type Mark = ((f64, f64), Shape, Rgb, bool, String, Option<String>);

fn inside(x: &Axis, y: &Axis, a: f64, b: f64) -> bool {
    let (c, d) = (x.c(a), y.c(b));
    c.is_finite()
        && d.is_finite()
        && c >= x.range.0
        && c <= x.range.1
        && d >= y.range.0
        && d <= y.range.1
}

/// The plot area (pt) of a chart.
fn plot_rect(chart: &Chart) -> Rect {
    let (xr, yr) = chart.plotting_area().get_pixel_range();
    (
        f64::from(xr.start) / S,
        f64::from(xr.end) / S,
        f64::from(yr.start) / S,
        f64::from(yr.end) / S,
    )
}

fn grow(b: Rect, m: f64) -> Rect {
    (b.0 - m, b.1 + m, b.2 - m, b.3 + m)
}

/// The pieces of polyline `l` outside box `b`.
fn cut(l: &[(f64, f64)], b: Rect) -> Vec<Vec<(f64, f64)>> {
    let inb = |q: &(f64, f64)| q.0 > b.0 && q.0 < b.1 && q.1 > b.2 && q.1 < b.3;
    let mut out = Vec::new();
    let mut cur: Vec<(f64, f64)> = Vec::new();
    for w in l.windows(2) {
        let (a, c) = (w[0], w[1]);
        match axes::clip_segment(a, c, b) {
            None => {
                if cur.is_empty() {
                    cur.push(a);
                }
                cur.push(c);
            }
            Some((p, q)) => {
                if !inb(&a) {
                    if cur.is_empty() {
                        cur.push(a);
                    }
                    cur.push(p);
                }
                if cur.len() > 1 {
                    out.push(std::mem::take(&mut cur));
                }
                cur.clear();
                if !inb(&c) {
                    cur.push(q);
                    cur.push(c);
                }
            }
        }
    }
    if cur.len() > 1 {
        out.push(cur);
    }
    out
}

/// The tick text of chart value `v` (the axis's own text where `v` is a
/// tick).
fn tick_for(a: &Axis, v: f64) -> String {
    a.ticks
        .iter()
        .position(|t| (t - v).abs() <= 1e-9 * (1.0 + t.abs()))
        .and_then(|i| a.texts.get(i).cloned())
        .unwrap_or_else(|| super::model::tick_text(v, 2))
}

/// Whether a series is a contour line (drawn thin, labelled on the line).
pub fn is_contour(s: &Series) -> bool {
    s.key.starts_with("contour")
}
