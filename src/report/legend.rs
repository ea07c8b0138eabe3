//! The legend (one order in every figure: curves, their marks, the branch
//! point, separation, the impact, limits, shading) and the colour bar, both
//! under the panels in either layout.

use super::canvas::{text_width, Canvas, Doc};
use super::marks::{draw_marker, own_text};
use super::model::{ColorBar, Figure, LegendEntry};
use super::render::{LABEL, MARK_R, TICK};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::cell::RefCell;
use std::rc::Rc;

/// The figure's legend entries: its labelled curves (first seen first),
/// then its own entries, sorted by kind ([`super::model::order`]), one
/// entry per distinct text and sample.
pub fn entries(fig: &Figure) -> Vec<LegendEntry> {
    let mut out: Vec<LegendEntry> = Vec::new();
    let mut push = |e: LegendEntry| {
        if !out.iter().any(|x| x.label == e.label) {
            out.push(e);
        }
    };
    for p in &fig.panels {
        let named = |s: &&super::model::Series| p.names_right && s.direct.is_some();
        for s in p
            .series
            .iter()
            .filter(|s| s.drawn && !s.label.is_empty() && !named(s))
        {
            push(LegendEntry {
                label: s.label.clone(),
                color: s.color,
                dash: Some(s.dash),
                shape: s.shape,
                filled: false,
                swatch: false,
                order: super::model::order::CURVE,
            });
        }
    }
    for e in &fig.legend {
        push(e.clone());
    }
    out.sort_by_key(|e| e.order);
    out
}

/// Width of an entry's sample (pt).
const SAMPLE: f64 = 17.0;
/// Line height of the legend (pt).
const LINE: f64 = LABEL * 1.35;

/// Where the entries go: (column, row of the first line, lines of text).
pub struct Placed {
    /// Total height (pt).
    pub height: f64,
    /// Width of a column (pt).
    pub col_w: f64,
    /// Per entry: column, y offset from the legend's top, wrapped lines.
    pub items: Vec<(usize, f64, Vec<String>)>,
}

/// Wraps `s` into lines of at most `w` pt.
pub fn wrap(s: &str, size: f64, w: f64) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    for word in s.split(' ') {
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
    out
}

/// Lays the entries out in as many columns as fit `w` (at most 3), row by
/// row in their order.
pub fn layout(entries: &[LegendEntry], w: f64) -> Placed {
    if entries.is_empty() {
        return Placed {
            height: 0.0,
            col_w: w,
            items: Vec::new(),
        };
    }
    let inner = w - 12.0;
    let widest = entries
        .iter()
        .map(|e| SAMPLE + 4.0 + text_width(&e.label, LABEL) + 10.0)
        .fold(0.0, f64::max);
    let cols = ((inner / widest).floor() as usize).clamp(1, 3);
    let cols = if widest > inner / 2.0 && entries.len() > 2 {
        cols.max(2).min(if w > 400.0 { 2 } else { 1 })
    } else {
        cols
    };
    let col_w = inner / cols as f64;
    let mut items = Vec::new();
    let mut y = 4.0;
    for row in entries.chunks(cols) {
        let mut tallest = 1;
        for (c, e) in row.iter().enumerate() {
            let lines = wrap(&e.label, LABEL, col_w - SAMPLE - 14.0);
            tallest = tallest.max(lines.len());
            items.push((c, y, lines));
        }
        y += tallest as f64 * LINE + 2.5;
    }
    Placed {
        height: y + 2.0,
        col_w,
        items,
    }
}

/// Draws the legend at `top` (pt).
pub fn draw(
    root: &DrawingArea<Canvas, Shift>,
    doc: &Rc<RefCell<Doc>>,
    entries: &[LegendEntry],
    p: &Placed,
    top: f64,
) {
    let u = |v: f64| (v * super::canvas::S).round() as i32;
    for (e, (c, dy, lines)) in entries.iter().zip(&p.items) {
        let x = 6.0 + *c as f64 * p.col_w;
        let y = top + dy;
        let cy = y + LINE / 2.0;
        if e.swatch {
            doc.borrow_mut().set("legend", "", "");
            let col = RGBColor(e.color.0, e.color.1, e.color.2);
            let _ = root.draw(&Rectangle::new(
                [
                    (u(x + 2.0), u(cy - 3.2)),
                    (u(x + SAMPLE - 2.0), u(cy + 3.2)),
                ],
                col.filled(),
            ));
        }
        if let Some(d) = e.dash {
            doc.borrow_mut().set("legend", d.array(), "");
            let col = RGBColor(e.color.0, e.color.1, e.color.2);
            let _ = root.draw(&PathElement::new(
                vec![(u(x), u(cy)), (u(x + SAMPLE), u(cy))],
                col.stroke_width(u(1.1) as u32),
            ));
        }
        if let Some(s) = e.shape {
            draw_marker(
                root,
                doc,
                "legend",
                (x + SAMPLE / 2.0, cy),
                s,
                MARK_R,
                e.color,
                e.filled,
                "",
            );
        }
        for (i, l) in lines.iter().enumerate() {
            let by = y + LINE * (i as f64 + 0.78);
            own_text(
                doc,
                (x + SAMPLE + 4.0, by),
                l,
                LABEL,
                "start",
                (0, 0, 0),
                false,
            );
        }
    }
}

/// The viridis colour at u ∈ [0, 1].
pub fn viridis(u: f64) -> (u8, u8, u8) {
    const V: [(u8, u8, u8); 9] = [
        (68, 1, 84),
        (71, 45, 123),
        (59, 82, 139),
        (44, 114, 142),
        (33, 145, 140),
        (40, 174, 128),
        (94, 201, 98),
        (173, 220, 48),
        (253, 231, 37),
    ];
    let u = if u.is_finite() {
        u.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let f = u * (V.len() - 1) as f64;
    let i = (f.floor() as usize).min(V.len() - 2);
    let t = f - i as f64;
    let l = |a: u8, b: u8| (f64::from(a) + t * (f64::from(b) - f64::from(a))).round() as u8;
    (
        l(V[i].0, V[i + 1].0),
        l(V[i].1, V[i + 1].1),
        l(V[i].2, V[i + 1].2),
    )
}

/// A horizontal colour bar at (x, y) of width `w`: the label, the bar (in
/// steps where the map is banded), its ticks, and the marked levels named
/// above the bar where they fit.
pub fn colorbar(doc: &Rc<RefCell<Doc>>, cb: &ColorBar, (x, y, w): (f64, f64, f64)) {
    use std::fmt::Write as _;
    let (lo, hi) = cb.range;
    let label_w = text_width(&cb.label, LABEL) + 8.0;
    let (bx, by, bw, bh) = (x + label_w, y + 12.0, w - label_w - 8.0, 7.0);
    own_text(
        doc,
        (x, by + bh - 0.5),
        &cb.label,
        LABEL,
        "start",
        (0, 0, 0),
        false,
    );
    let xp = |v: f64| bx + (v - lo) / (hi - lo).max(1e-300) * bw;
    let mut d = doc.borrow_mut();
    let mut edges: Vec<f64> = vec![lo];
    edges.extend(cb.steps.iter().copied().filter(|s| *s > lo && *s < hi));
    edges.push(hi);
    let smooth = cb.steps.is_empty();
    let parts = if smooth { 64 } else { edges.len() - 1 };
    for k in 0..parts {
        let (a, b) = if smooth {
            (
                lo + (hi - lo) * k as f64 / 64.0,
                lo + (hi - lo) * (k + 1) as f64 / 64.0,
            )
        } else {
            (edges[k], edges[k + 1])
        };
        let c = viridis(((a + b) / 2.0 - lo) / (hi - lo).max(1e-300));
        let _ = writeln!(
            d.body,
            "<rect class=\"legend\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{c}\" stroke=\"{c}\" stroke-width=\"0.3\"/>",
            super::canvas::n(xp(a)),
            super::canvas::n(by),
            super::canvas::n(xp(b) - xp(a)),
            super::canvas::n(bh),
            c = super::canvas::hex(c)
        );
    }
    let _ = writeln!(
        d.body,
        "<rect class=\"legend\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#282828\" stroke-width=\"0.5\"/>",
        super::canvas::n(bx),
        super::canvas::n(by),
        super::canvas::n(bw),
        super::canvas::n(bh)
    );
    drop(d);
    let (ticks, step) = super::axes::nice_ticks(lo, hi, ((bw / 40.0) as usize).clamp(3, 8));
    let dec = super::axes::decimals_for(step);
    let mut taken: Vec<(f64, f64)> = Vec::new();
    for t in ticks {
        let xt = xp(t);
        let s = super::model::tick_text(t, dec);
        let tw = text_width(&s, TICK);
        taken.push((xt - tw / 2.0 - 1.5, xt + tw / 2.0 + 1.5));
        own_text(
            doc,
            (xt, by + bh + TICK * 1.15),
            &s,
            TICK,
            "middle",
            (0, 0, 0),
            false,
        );
        tick(doc, xt, by + bh, by + bh + 2.0);
    }
    // marked levels: a line across the bar, the name above it where free
    let mut above: Vec<(f64, f64)> = Vec::new();
    for (v, name) in &cb.marks {
        if *v < lo || *v > hi {
            continue;
        }
        let xm = xp(*v);
        tick(doc, xm, by - 2.0, by + bh);
        let tw = text_width(name, LABEL);
        let (a, b) = (xm - tw / 2.0, xm + tw / 2.0);
        let (a, b) = if b > x + w {
            (x + w - tw, x + w)
        } else if a < bx {
            (bx, bx + tw)
        } else {
            (a, b)
        };
        if !name.is_empty() && above.iter().all(|r| b + 2.0 < r.0 || a - 2.0 > r.1) {
            own_text(
                doc,
                ((a + b) / 2.0, by - 3.0),
                name,
                LABEL,
                "middle",
                (0, 0, 0),
                false,
            );
            above.push((a, b));
        }
    }
}

fn tick(doc: &Rc<RefCell<Doc>>, x: f64, y0: f64, y1: f64) {
    use std::fmt::Write as _;
    let mut d = doc.borrow_mut();
    let _ = writeln!(
        d.body,
        "<path class=\"legend\" d=\"M{} {}L{} {}\" stroke=\"#282828\" stroke-width=\"0.6\"/>",
        super::canvas::n(x),
        super::canvas::n(y0),
        super::canvas::n(x),
        super::canvas::n(y1)
    );
}
