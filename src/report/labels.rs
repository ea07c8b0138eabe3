//! Direct labels with obstacle avoidance: every text cylroll writes into a
//! plot (a curve's name, an event's label, a contour's level, a note) goes
//! to the first candidate place where its box crosses no curve, reference
//! line, marker, other text or the plot's frame; where no place is free the
//! text is left out (the legend and the hover text still carry it; the
//! curves of a panel are named all or none). Reference lines are labelled
//! outside the plot, where nothing else is drawn: a vertical line's label
//! in a strip over the plot ([`spread`]), a horizontal line's in a margin
//! right of it ([`stack`]), pushed apart so that none is ever left out.
//! The boxes are the font's (advance × ascent + descent), as the browser's
//! overlap test measures them.

use super::axes::clip_segment;
use super::canvas::{ascent, descent, text_width};

/// A box in pt: (x0, x1, y0, y1), y down.
pub type Rect = (f64, f64, f64, f64);

/// Clearance kept around every text, in pt.
pub const CLEAR: f64 = 1.2;

/// The box of a text with its baseline at `y`, anchored at `x`
/// (`start`, `middle`, `end`).
pub fn text_box(x: f64, y: f64, text: &str, size: f64, anchor: &str) -> Rect {
    let w = text_width(text, size);
    let x0 = match anchor {
        "end" => x - w,
        "middle" => x - w / 2.0,
        _ => x,
    };
    (x0, x0 + w, y - ascent() * size, y + descent() * size)
}

/// What a text in a plot must keep clear of.
#[derive(Debug, Default, Clone)]
pub struct Obstacles {
    /// Polylines in pt (curves, reference lines).
    pub lines: Vec<Vec<(f64, f64)>>,
    /// Boxes in pt (markers, texts already placed).
    pub boxes: Vec<Rect>,
    /// The plot area: a text lies wholly inside it (None: anywhere).
    pub area: Option<Rect>,
}

fn grow(b: Rect, m: f64) -> Rect {
    (b.0 - m, b.1 + m, b.2 - m, b.3 + m)
}

fn meets(a: Rect, b: Rect) -> bool {
    a.0 < b.1 && b.0 < a.1 && a.2 < b.3 && b.2 < a.3
}

impl Obstacles {
    /// Whether the box `b` is free.
    pub fn free(&self, b: Rect) -> bool {
        if let Some(a) = self.area {
            if b.0 < a.0 + CLEAR || b.1 > a.1 - CLEAR || b.2 < a.2 + CLEAR || b.3 > a.3 - CLEAR {
                return false;
            }
        }
        let g = grow(b, CLEAR);
        if self.boxes.iter().any(|o| meets(g, *o)) {
            return false;
        }
        !self
            .lines
            .iter()
            .any(|l| l.windows(2).any(|w| clip_segment(w[0], w[1], g).is_some()))
    }

    /// Takes the box `b` (a text placed, a marker drawn).
    pub fn take(&mut self, b: Rect) {
        self.boxes.push(b);
    }

    /// The first free place among `candidates` (x, baseline y, anchor) for
    /// `text` at `size`; takes it.
    pub fn place(
        &mut self,
        text: &str,
        size: f64,
        candidates: &[(f64, f64, &'static str)],
    ) -> Option<(f64, f64, &'static str)> {
        let found = candidates
            .iter()
            .copied()
            .find(|&(x, y, a)| self.free(text_box(x, y, text, size, a)))?;
        self.take(text_box(found.0, found.1, text, size, found.2));
        Some(found)
    }
}

/// Places around a point (a curve's end, a marker) at distance `d`: right,
/// upper right, lower right, above, below, upper left, lower left, left.
pub fn around(x: f64, y: f64, d: f64, size: f64) -> Vec<(f64, f64, &'static str)> {
    let mid = y + (ascent() - descent()) * size / 2.0;
    let up = y - d;
    let down = y + d + ascent() * size;
    vec![
        (x + d, mid, "start"),
        (x + d * 0.7, up, "start"),
        (x + d * 0.7, down, "start"),
        (x, up - 1.0, "middle"),
        (x, down + 1.0, "middle"),
        (x - d * 0.7, up, "end"),
        (x - d * 0.7, down, "end"),
        (x - d, mid, "end"),
    ]
}

/// Places along a polyline (pt) from its end backwards: at each of `n`
/// points, above and below it.
pub fn along(line: &[(f64, f64)], n: usize, size: f64) -> Vec<(f64, f64, &'static str)> {
    let mut out = Vec::new();
    if line.is_empty() {
        return out;
    }
    for k in 1..=n {
        let i = line.len().saturating_sub(1 + k * line.len() / (n + 1));
        let (x, y) = line[i.min(line.len() - 1)];
        out.extend(around(x, y, 3.0, size).into_iter().skip(1).take(6));
    }
    out
}

/// Baselines for labels in a margin beside the plot, one per height in
/// `ys` (pt, each label centred on its height where it can be), pushed
/// apart so that no two boxes meet and kept between `top` and `bottom`.
/// Returned in the order of `ys`.
pub fn stack(ys: &[f64], top: f64, bottom: f64, size: f64) -> Vec<f64> {
    let h = (ascent() + descent()) * size;
    let gap = h + 0.8;
    let mut order: Vec<usize> = (0..ys.len()).collect();
    order.sort_by(|&a, &b| ys[a].total_cmp(&ys[b]));
    // box centres, top down
    let mut c: Vec<f64> = order
        .iter()
        .map(|&i| ys[i].clamp(top + h / 2.0, bottom - h / 2.0))
        .collect();
    for k in 1..c.len() {
        c[k] = c[k].max(c[k - 1] + gap);
    }
    if let Some(&last) = c.last() {
        if last > bottom - h / 2.0 {
            let n = c.len();
            c[n - 1] = bottom - h / 2.0;
            for k in (0..n - 1).rev() {
                c[k] = c[k].min(c[k + 1] - gap);
            }
        }
    }
    let mut out = vec![0.0; ys.len()];
    for (k, &i) in order.iter().enumerate() {
        out[i] = c[k] + (ascent() - descent()) * size / 2.0;
    }
    out
}

/// Centres for labels of widths `ws` in a strip over the plot, one per
/// position in `xs` (pt, each label centred on its position where it can
/// be), pushed apart so that no two meet and kept between `left` and
/// `right`. Returned in the order of `xs`.
pub fn spread(xs: &[f64], ws: &[f64], left: f64, right: f64) -> Vec<f64> {
    let gap = 4.0;
    let mut order: Vec<usize> = (0..xs.len()).collect();
    order.sort_by(|&a, &b| xs[a].total_cmp(&xs[b]));
    let half = |k: usize| ws[order[k]] / 2.0;
    let mut c: Vec<f64> = (0..order.len())
        .map(|k| xs[order[k]].clamp(left + half(k), right - half(k)))
        .collect();
    for k in 1..c.len() {
        c[k] = c[k].max(c[k - 1] + half(k - 1) + half(k) + gap);
    }
    let n = c.len();
    if n > 0 && c[n - 1] > right - half(n - 1) {
        c[n - 1] = right - half(n - 1);
        for k in (0..n - 1).rev() {
            c[k] = c[k].min(c[k + 1] - half(k + 1) - half(k) - gap);
        }
    }
    let mut out = vec![0.0; xs.len()];
    for (k, &i) in order.iter().enumerate() {
        out[i] = c[k];
    }
    out
}

/// Places over a whole area, corners first (notes).
pub fn corners_then_grid(a: Rect, size: f64) -> Vec<(f64, f64, &'static str)> {
    let top = a.2 + ascent() * size + 2.5;
    let bottom = a.3 - descent() * size - 2.5;
    let mut out = vec![
        (a.0 + 3.0, top, "start"),
        (a.1 - 3.0, top, "end"),
        (a.0 + 3.0, bottom, "start"),
        (a.1 - 3.0, bottom, "end"),
    ];
    let rows = 10;
    for r in 0..=rows {
        let y = top + (bottom - top) * r as f64 / rows as f64;
        out.push((a.0 + 3.0, y, "start"));
        out.push((a.1 - 3.0, y, "end"));
        out.push(((a.0 + a.1) / 2.0, y, "middle"));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels_over_a_plot_are_spread_apart() {
        let c = spread(&[10.0, 12.0, 90.0], &[20.0, 30.0, 10.0], 0.0, 100.0);
        assert!(c[1] - c[0] >= 25.0, "{c:?}");
        assert!(c[0] - 10.0 >= 0.0 && c[2] + 5.0 <= 100.0, "{c:?}");
        assert_eq!(c[2], 90.0);
    }

    #[test]
    fn labels_in_a_margin_are_stacked_apart() {
        let ys = [50.0, 48.0, 10.0, 51.0];
        let b = stack(&ys, 0.0, 100.0, 7.0);
        let h = (ascent() + descent()) * 7.0;
        let mut sorted = b.clone();
        sorted.sort_by(f64::total_cmp);
        for w in sorted.windows(2) {
            assert!(w[1] - w[0] >= h, "{b:?}");
        }
        // the lone label stays at its line
        let mid = b[2] - (ascent() - descent()) * 7.0 / 2.0;
        assert!((mid - 10.0).abs() < 1e-9);
    }

    #[test]
    fn a_label_avoids_a_curve_and_other_labels() {
        let mut o = Obstacles {
            lines: vec![vec![(0.0, 50.0), (100.0, 50.0)]],
            boxes: Vec::new(),
            area: Some((0.0, 100.0, 0.0, 100.0)),
        };
        // a label centred on the line is refused, one above it accepted
        assert!(!o.free(text_box(10.0, 52.0, "μ = 0.05", 7.0, "start")));
        let c = o.place("μ = 0.05", 7.0, &around(50.0, 50.0, 3.0, 7.0));
        let (x, y, a) = c.expect("a free place");
        let b = text_box(x, y, "μ = 0.05", 7.0, a);
        assert!(b.3 < 50.0 || b.2 > 50.0, "{b:?} crosses the line");
        // the same text again goes elsewhere
        let d = o.place("μ = 0.05", 7.0, &around(50.0, 50.0, 3.0, 7.0));
        assert!(d.is_some() && d != c);
        // outside the area: refused
        assert!(!o.free(text_box(95.0, 10.0, "long text", 7.0, "start")));
    }
}
