//! Axes: ranges with padding, ticks that plotters draws where they are
//! given, and clipping of curves to the plot area.

use super::model::Panel;

/// "Nice" ticks covering [lo, hi]: steps of 1, 2, 2.5 or 5 × 10^k giving
/// about `target` intervals. Returns (ticks, step).
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
    let ticks = (first..=last)
        .map(|i| {
            let v = i as f64 * step;
            if v.abs() < step * 1e-9 {
                0.0
            } else {
                v
            }
        })
        .collect();
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

/// Ticks of a log axis over [lo, hi] (values): 1, 2, 5 per decade over
/// at most two decades, powers of ten otherwise.
pub fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
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

/// The text of a log tick at value `v`: 0.01, 0.2, 1, 50, 100.
pub fn log_tick_text(v: f64) -> String {
    let dec = (-(v.log10().floor()) as i64).max(0) as usize;
    super::model::tick_text(v, dec)
}

/// One axis as plotters draws it: the range in chart coordinates (log10
/// for a log axis), the ticks there and their texts.
#[derive(Debug, Clone)]
pub struct Axis {
    /// Range (chart coordinates).
    pub range: (f64, f64),
    /// Tick positions (chart coordinates).
    pub ticks: Vec<f64>,
    /// Tick texts.
    pub texts: Vec<String>,
    /// log10 applied to data.
    pub log: bool,
}

impl Axis {
    /// Chart coordinate of a data value.
    pub fn c(&self, v: f64) -> f64 {
        if self.log {
            v.log10()
        } else {
            v
        }
    }
}

/// The data range of a panel's curves, markers, bands and patches along x
/// (`x` true) or y, in data coordinates.
/// Along y only the points within the panel's fixed x range count (a
/// panel that zooms into part of its curves fits their visible part).
pub fn data_range(p: &Panel, x: bool) -> Option<(f64, f64)> {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    let mut add = |v: f64| {
        if v.is_finite() {
            lo = lo.min(v);
            hi = hi.max(v);
        }
    };
    let shown = |a: f64| x || p.xrange.is_none_or(|(l, h)| a >= l && a <= h);
    for s in &p.series {
        for q in &s.points {
            if q.0.is_finite() && q.1.is_finite() && shown(q.0) {
                add(if x { q.0 } else { q.1 });
            }
        }
    }
    for m in p.markers.iter().filter(|m| shown(m.at.0)) {
        add(if x { m.at.0 } else { m.at.1 });
    }
    for l in &p.lines {
        if l.vertical == x {
            add(l.at);
        }
    }
    if x {
        for b in &p.bands {
            add(b.x.0);
            add(b.x.1);
        }
    }
    (lo.is_finite() && hi.is_finite()).then_some((lo, hi))
}

/// A linear axis over `fixed` or the data range padded by 4 % on each
/// side (so that nothing runs along the frame), with about `target` ticks.
pub fn linear(fixed: Option<(f64, f64)>, data: Option<(f64, f64)>, target: usize) -> Axis {
    let (lo, hi) = match (fixed, data) {
        (Some(r), _) => r,
        (None, Some((a, b))) => {
            let span = if b - a > 1e-12 * a.abs().max(b.abs()).max(1e-300) {
                b - a
            } else {
                a.abs().max(1.0) * 0.1
            };
            (a - 0.04 * span, b + 0.04 * span)
        }
        (None, None) => (0.0, 1.0),
    };
    let (ticks, step) = nice_ticks(lo, hi, target);
    let dec = decimals_for(step);
    let texts = ticks
        .iter()
        .map(|v| super::model::tick_text(*v, dec))
        .collect();
    Axis {
        range: (lo, hi),
        ticks,
        texts,
        log: false,
    }
}

/// A log axis over `fixed` (values) or the data's, padded by 3 % of the
/// decades on each side.
pub fn logarithmic(fixed: Option<(f64, f64)>, data: Option<(f64, f64)>, pad: bool) -> Axis {
    let (a, b) = fixed.or(data).unwrap_or((1.0, 10.0));
    let (la, lb) = (a.log10(), b.log10());
    let p = if pad { 0.03 * (lb - la) } else { 0.0 };
    let ticks_v = log_ticks(a, b);
    Axis {
        range: (la - p, lb + p),
        ticks: ticks_v.iter().map(|v| v.log10()).collect(),
        texts: ticks_v.iter().map(|v| log_tick_text(*v)).collect(),
        log: true,
    }
}

/// The edges of the cells around nodes `g` (at least two, increasing):
/// each cell reaches halfway to its neighbours, the outer ones as far out
/// as in. `g.len() + 1` edges.
pub fn cell_edges(g: &[f64]) -> Vec<f64> {
    let n = g.len();
    let mut e = Vec::with_capacity(n + 1);
    e.push(g[0] - (g[1] - g[0]) / 2.0);
    for w in g.windows(2) {
        e.push((w[0] + w[1]) / 2.0);
    }
    e.push(g[n - 1] + (g[n - 1] - g[n - 2]) / 2.0);
    e
}

/// Clips the polyline `pts` to `[x0,x1]×[y0,y1]`: the visible pieces
/// (Liang–Barsky per segment; a non-finite point breaks the line).
pub fn clip_polyline(
    pts: &[(f64, f64)],
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut cur: Vec<(f64, f64)> = Vec::new();
    let flush = |cur: &mut Vec<(f64, f64)>, out: &mut Vec<Vec<(f64, f64)>>| {
        if cur.len() > 1 {
            out.push(std::mem::take(cur));
        }
        cur.clear();
    };
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        if !(a.0.is_finite() && a.1.is_finite() && b.0.is_finite() && b.1.is_finite()) {
            flush(&mut cur, &mut out);
            continue;
        }
        match clip_segment(a, b, (x0, x1, y0, y1)) {
            None => flush(&mut cur, &mut out),
            Some((p, q)) => {
                if cur.last() != Some(&p) {
                    flush(&mut cur, &mut out);
                    cur.push(p);
                }
                cur.push(q);
                if q != b {
                    flush(&mut cur, &mut out);
                }
            }
        }
    }
    flush(&mut cur, &mut out);
    out
}

/// The part of segment ab inside the box (x0, x1, y0, y1), if any.
pub fn clip_segment(
    a: (f64, f64),
    b: (f64, f64),
    (x0, x1, y0, y1): (f64, f64, f64, f64),
) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_padding_and_clipping() {
        let (t, s) = nice_ticks(0.0, 1.047, 6);
        assert_eq!(s, 0.2);
        assert_eq!(t.len(), 6);
        assert_eq!(decimals_for(0.25), 2);
        let a = linear(None, Some((0.0, 2.0)), 5);
        assert!(a.range.0 < 0.0 && a.range.1 > 2.0, "padded");
        assert_eq!(log_tick_text(0.01), "0.01");
        assert_eq!(log_ticks(0.1, 10.0).len(), 7);
        let pieces = clip_polyline(&[(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)], 0.0, 2.0, 0.0, 1.0);
        assert_eq!(pieces.len(), 2);
        let broken = clip_polyline(
            &[
                (0.1, 0.1),
                (0.2, 0.2),
                (f64::NAN, f64::NAN),
                (0.3, 0.1),
                (0.4, 0.2),
            ],
            0.0,
            1.0,
            0.0,
            1.0,
        );
        assert_eq!(broken.len(), 2, "a NaN point breaks the line");
    }
}
