//! Events on a piece: which watched functions read more than θ, the first
//! sign change of each over the points (and samples of its interpolant
//! between them, so a graze is not missed), and its root, by Newton's
//! method on the interpolant corrected once by the exact value.

use super::piece::{Piece, Setup};
use crate::error::Result;
use crate::integrate::solve::{watch_value, Event, Sample, Watch};
use crate::mechanics::system::{self as sy, System};
use crate::numeric::cheb::ChebFit;
use crate::numeric::{max_exp, scaled_f64};
use rug::{Assign, Float};

/// Whether a watched function reads a coordinate other than θ.
pub(super) fn reads_positions(w: &Watch) -> bool {
    match w {
        Watch::Coord(i) | Watch::Reach { i, .. } => *i != sy::th(0),
        Watch::Lin(terms) => terms.iter().any(|(w, _)| reads_positions(w)),
        Watch::Height { th, .. } | Watch::FreeNormal { th, .. } => *th != sy::th(0),
        Watch::Multiplier(_) | Watch::Rate(_) => false,
    }
}

/// Interior samples per gap between two points where a watched function's
/// interpolant is looked at too (a graze that crosses zero and comes back
/// between two points).
const BETWEEN: usize = 4;

/// The Chebyshev coefficients, in f64, of the interpolant of values at the
/// N points (`asc`: ascending s, i.e. the points in reverse order), by the
/// direct cosine sum (`cos[m]` = cos(mπ/2N), m < 4N); of the values scaled
/// by 2^−e, e = [`max_exp`] of them, so that they hold in any units.
pub(super) fn coeffs64(asc: &[Float], cos: &[f64]) -> Vec<f64> {
    let n = asc.len();
    let e = max_exp(asc).unwrap_or(0);
    let f: Vec<f64> = asc.iter().rev().map(|v| scaled_f64(v, e)).collect();
    (0..n)
        .map(|k| {
            // the angle index k(2j + 1) mod 4N, stepped by 2k < 4N
            let mut sum = 0.0;
            let mut m = k;
            for fj in &f {
                sum += fj * cos[m];
                m += 2 * k;
                if m >= 4 * n {
                    m -= 4 * n;
                }
            }
            let c = 2.0 * sum / n as f64;
            if k == 0 {
                c / 2.0
            } else {
                c
            }
        })
        .collect()
}

/// The first sign change of a watched function over the piece: from its
/// value at s = 0 (None: on its boundary there, not watched), over the
/// points — and [`BETWEEN`] samples of its interpolant `c64` in each gap,
/// where values below 10^−12 of the largest count as 0 — to its value at
/// the end. `c64` is [`coeffs64`] of `vals` (in their scale 2^−e).
pub(super) fn first_bracket(
    nodes: &[&Float],
    len: &Float,
    start: Option<&Float>,
    vals: &[Float],
    end: &Float,
    c64: &[f64],
) -> Option<(Float, Float)> {
    let p = len.prec();
    let lenf = len.to_f64();
    // the interpolant's scale, coeffs64's
    let e = max_exp(vals).unwrap_or(0);
    let big = vals
        .iter()
        .map(|v| scaled_f64(v, e).abs())
        .fold(0.0, f64::max);
    let floor = 1e-12 * big;
    // the sequence of (s, sign, the point itself) with the interpolant's
    // samples between points
    let mut seq: Vec<(f64, bool, Option<&Float>)> =
        Vec::with_capacity((BETWEEN + 1) * vals.len() + 2);
    let zero = Float::new(p);
    if let Some(g) = start.filter(|g| !g.is_zero()) {
        seq.push((0.0, g.is_sign_negative(), Some(&zero)));
    }
    let mut last = 0.0;
    let mut first_point = true;
    let points = nodes.iter().copied().zip(vals).chain([(len, end)]);
    for (s, g) in points {
        if crate::cancel::cancelled() {
            // the caller's next check ends the computation
            return None;
        }
        let sf = s.to_f64();
        if !first_point {
            // the four samples of the gap evaluated side by side
            let xs: [f64; BETWEEN] =
                std::array::from_fn(|i| last + (sf - last) * (i + 1) as f64 / (BETWEEN + 1) as f64);
            let vs = ChebFit::eval_f64_at(c64, 0.0, lenf, xs);
            for (x, v) in xs.into_iter().zip(vs) {
                if v.abs() > floor {
                    seq.push((x, v < 0.0, None));
                }
            }
        }
        first_point = false;
        last = sf;
        if !g.is_zero() {
            seq.push((sf, g.is_sign_negative(), Some(s)));
        }
    }
    let at = |(x, _, s): &(f64, bool, Option<&Float>)| match s {
        Some(s) => (*s).clone(),
        None => Float::with_val(p, *x),
    };
    seq.windows(2)
        .find(|w| w[0].1 != w[1].1)
        .map(|w| (at(&w[0]), at(&w[1])))
}

/// A bracket of the interpolant's sign change in (lo, hi) of [0, len],
/// narrowed by bisection in f64 to a few units of f64's last place, on the
/// coefficients scaled by 2^−e ([`max_exp`], [`scaled_f64`]: the signs
/// hold in any units).
fn bisect64(fit: &ChebFit, len: &Float, lo: &Float, hi: &Float) -> (f64, f64) {
    let e = max_exp(&fit.c).unwrap_or(0);
    let c64: Vec<f64> = fit.c.iter().map(|c| scaled_f64(c, e)).collect();
    let lenf = len.to_f64();
    let g = |s: f64| ChebFit::eval_f64(&c64, 0.0, lenf, s);
    let (mut a, mut b) = (lo.to_f64(), hi.to_f64());
    let neg_a = g(a).is_sign_negative();
    for _ in 0..60 {
        let mid = 0.5 * (a + b);
        if mid <= a || mid >= b {
            break;
        }
        if g(mid).is_sign_negative() == neg_a {
            a = mid;
        } else {
            b = mid;
        }
    }
    (a, b)
}

impl Piece {
    /// The first root in (lo, hi) of a watched function, from its
    /// interpolant over the points (its values `vals` at the points,
    /// ascending), corrected once by the exact value.
    pub(super) fn root(
        &self,
        sys: &mut System,
        su: &Setup,
        ev: &Event,
        vals: &[Float],
        lo: &Float,
        hi: &Float,
    ) -> Result<(Float, Sample, Float)> {
        let p = sys.prec;
        // the interpolant wants the values in point order (descending s)
        let desc: Vec<Float> = vals.iter().rev().cloned().collect();
        let zero = Float::new(p);
        let fit = ChebFit::from_values(&zero, &self.len, su.roots, p, &desc);
        let d = fit.derivative();
        // bisection in f64 to a seed, then Newton at full precision
        let (a, b) = bisect64(&fit, &self.len, lo, hi);
        let seed = Float::with_val(p, 0.5 * (a + b)).max(lo).min(hi);
        let mut s = seed.clone();
        let stop = Float::with_val(p, &self.len) >> (p as i32 - 8);
        for _ in 0..40 {
            let step = fit.eval(&s, p) / d.eval(&s, p);
            s -= &step;
            if !step.is_finite() {
                break;
            }
            if step.abs() <= stop {
                break;
            }
        }
        if !s.is_finite() {
            s = seed;
        }
        s.assign(s.clone().max(lo).min(hi));
        // one correction by the exact value
        let smp = self.sample(sys, &s)?;
        let g = watch_value(&ev.watch, &smp);
        let dg = d.eval(&s, p);
        let ds = g / dg;
        let smp = if ds.is_finite() && !ds.is_zero() {
            let s2 = Float::with_val(p, &s - &ds);
            if s2 >= *lo && s2 <= *hi {
                s = s2;
                self.sample(sys, &s)?
            } else {
                smp
            }
        } else {
            smp
        };
        let t_err = Float::with_val(p, ds.abs_ref()) * self.rate.eval(&s, p)
            + Float::with_val(p, &su.sc.ts * su.tol);
        let t_err = if t_err.is_finite() {
            t_err
        } else {
            Float::with_val(p, &su.sc.ts * su.tol)
        };
        Ok((s, smp, t_err))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::cheb::Roots;

    /// The seed's bracket holds the root of an interpolant in any units:
    /// g(s) = s − 0.3 on [0, 1] scaled by 2^k, k = −1500 … 1500 (beyond
    /// f64's range both ways), brackets 0.3 to f64's precision.
    #[test]
    fn the_seed_brackets_the_root_in_any_units() {
        let p = 200;
        let roots = Roots::new(16, p);
        let (zero, len) = (Float::new(p), Float::with_val(p, 1u32));
        let pts = ChebFit::points(&zero, &len, &roots, p);
        let (lo, hi) = (Float::with_val(p, 0.1), Float::with_val(p, 0.9));
        for k in [-1500i32, -400, 0, 400, 1500] {
            let vals: Vec<Float> = pts
                .iter()
                .map(|s| Float::with_val(p, s - 0.3) << k)
                .collect();
            let fit = ChebFit::from_values(&zero, &len, &roots, p, &vals);
            let (a, b) = bisect64(&fit, &len, &lo, &hi);
            assert!(a <= 0.3 && 0.3 <= b && b - a < 1e-14, "2^{k}: [{a}, {b}]");
        }
    }
}
