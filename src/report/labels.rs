//! Direct labels with obstacle avoidance: every text cylroll writes into a
//! plot (a curve's name, a reference line's value, an event's label, a
//! note) goes to the first candidate place where its box crosses no curve,
//! reference line, marker, other text or the plot's frame; where no place is
//! free the text is left out (the legend and the hover text still carry
//! it). The boxes are the font's (advance × ascent + descent), as the
//! browser's overlap test measures them.

use super::canvas::{ascent, descent, text_width};
use super::axes::clip_segment;

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
        !self.lines.iter().any(|l| {
            l.windows(2)
                .any(|w| clip_segment(w[0], w[1], g).is_some())
        })
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

/// Places down a vertical line at `x` from `top` to `bottom`: right of it,
/// then left of it.
pub fn down_vertical(x: f64, top: f64, bottom: f64, size: f64) -> Vec<(f64, f64, &'static str)> {
    let mut out = Vec::new();
    let step = size * 0.6;
    let mut y = top + ascent() * size + CLEAR + 0.5;
    while y < bottom {
        out.push((x + 2.0, y, "start"));
        out.push((x - 2.0, y, "end"));
        y += step;
    }
    out
}

/// Places along a horizontal line at `y` from `right` to `left`: above
/// it, then below it.
pub fn along_horizontal(y: f64, left: f64, right: f64, size: f64) -> Vec<(f64, f64, &'static str)> {
    let mut out = Vec::new();
    let step = (right - left) / 12.0;
    for k in 0..=12 {
        let x = right - 2.0 - k as f64 * step;
        out.push((x, y - 2.0 - descent() * size, "end"));
        out.push((x, y + 2.0 + ascent() * size, "end"));
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
