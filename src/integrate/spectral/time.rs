//! Times on a piece: s where t(s) equals a given time, by Newton's method
//! in f64, then on lower-precision copies of t(s) and dt/ds (precision
//! doubling), then at full precision; and s(t) as an interpolant of its
//! own when many outputs fall inside one piece.

use super::piece::{within, Piece};
use crate::numeric::cheb::fixed_sums::{FixedSums, LazySums};
use crate::numeric::cheb::{ChebFit, Roots};
use crate::numeric::scaled_f64;
use rug::{Assign, Float};

/// `f` rounded to q bits without the trailing coefficients below
/// 2^−(q+8) of the largest.
fn cut(f: &ChebFit, q: u32) -> ChebFit {
    let mut g = f.rounded(q);
    let big =
        g.c.iter()
            .map(|c| c.clone().abs())
            .fold(Float::new(q), |a, b| a.max(&b));
    let small = big >> (q as i32 + 8);
    while g.c.len() > 2 && g.c.last().is_some_and(|c| c.clone().abs() < small) {
        g.c.pop();
    }
    g
}

/// A lower-precision copy of t(s) − t0 and dt/ds, for the first Newton
/// steps of an inversion (precision doubling).
pub(super) struct Lower {
    /// Its precision.
    q: u32,
    dt: ChebFit,
    rate: ChebFit,
    /// The two summed in fixed point for q bits.
    fixed: LazySums,
}

/// The lower copies of `dt` and `rate` at [`lower_precisions`] (then one or
/// two full steps end an inversion).
pub(super) fn lower_copies(dt: &ChebFit, rate: &ChebFit, p: u32, fx: u32) -> Vec<Lower> {
    lower_precisions(p, fx)
        .map(|q| Lower {
            q,
            dt: cut(dt, q),
            rate: cut(rate, q),
            fixed: LazySums::at(q),
        })
        .collect()
}

/// 128, 256, … bits up to 3/4 p, and then, where the last of them is below
/// p/2 + 16, one at p/2 + 16 rounded up to whole limbs if its fixed-point
/// sums take fewer limbs than the full steps' (built for `fx` bits):
/// Newton converged there leaves a full-precision step below
/// 2^−(p/2+4) L, so that one full step ends the inversion.
fn lower_precisions(p: u32, fx: u32) -> impl Iterator<Item = u32> {
    let pow: Vec<u32> = std::iter::successors(Some(128u32), |q| q.checked_mul(2))
        .take_while(|q| 4 * q <= 3 * p)
        .collect();
    let half = (p / 2 + 16).div_ceil(64) * 64;
    let last = pow.last().copied().unwrap_or(0);
    // the sums' own limb counts (with the rounding up to an instantiated
    // size): a copy that takes as many limbs saves nothing
    let limbs = |q: u32| FixedSums::limbs(q).unwrap_or(usize::MAX);
    let extra = (last < p / 2 + 16 && half > last && limbs(half) < limbs(fx)).then_some(half);
    pow.into_iter().chain(extra)
}

impl Piece {
    /// s where t(s) = tau, bracketed among the points first.
    pub(super) fn invert_at(&self, tau: &Float) -> Float {
        let p = tau.prec();
        let k = self.nodes.partition_point(|(_, smp)| smp.t < *tau);
        let lo = match k {
            0 => (Float::new(p), self.t0.clone()),
            _ => (self.nodes[k - 1].0.clone(), self.nodes[k - 1].1.t.clone()),
        };
        let hi = match self.nodes.get(k) {
            Some((s, smp)) => (s.clone(), smp.t.clone()),
            None => (self.len.clone(), self.t_end()),
        };
        self.invert(tau, &lo, &hi)
    }

    /// s(t) on [t0, t1] as an interpolant (None: it does not converge to
    /// `tol` L with the points of `roots`), without the trailing
    /// coefficients whose sum stays below that tolerance.
    pub(super) fn inverse(&self, roots: &Roots, t1: &Float, tol: &Float) -> Option<ChebFit> {
        let p = self.len.prec();
        let ts = ChebFit::points(&self.t0, t1, roots, p);
        let ss: Vec<Float> = ts.iter().map(|t| self.invert_at(t)).collect();
        let mut f = ChebFit::from_values(&self.t0, t1, roots, p, &ss);
        if !within(&f, tol, &self.len, &mut 0) {
            return None;
        }
        let each = Float::with_val(p, &self.len * tol) / (roots.n() as u64);
        while f.c.len() > 2
            && f.c
                .last()
                .is_some_and(|c| c.cmp_abs(&each) == Some(std::cmp::Ordering::Less))
        {
            f.c.pop();
        }
        Some(f)
    }

    /// s in [0, L] where t(s) = tau (t increasing in s): Newton's method in
    /// f64 from the bracket's linear interpolation, then on the lower copies
    /// of t(s) and dt/ds (precision doubling, [`lower_precisions`]), then at
    /// full precision until a step is below 2^−(p/2+4) L.
    pub(super) fn invert(&self, tau: &Float, lo: &(Float, Float), hi: &(Float, Float)) -> Float {
        let p = tau.prec();
        let mut sc = self.scratch.borrow_mut();
        let (low, full) = &mut *sc;
        let target = Float::with_val(p, tau - &self.t0);
        let (a, b) = (lo.0.to_f64(), hi.0.to_f64());
        let len = self.len.to_f64();
        // times in f64 in the scale of dt64 (any unit of time)
        let tg = scaled_f64(&target, self.t64_exp);
        // the bracket's linear interpolation, its ratio of times in MPFR
        let width = Float::with_val(p, &hi.1 - &lo.1);
        let mut s = if width.is_sign_positive() && !width.is_zero() {
            a + (b - a) * (Float::with_val(p, tau - &lo.1) / &width).to_f64()
        } else {
            a
        };
        for _ in 0..30 {
            let f = ChebFit::eval_f64(&self.dt64, 0.0, len, s) - tg;
            let d = ChebFit::eval_f64(&self.rate64, 0.0, len, s);
            let step = f / d;
            if !step.is_finite() {
                break;
            }
            s = (s - step).clamp(a, b);
            if step.abs() <= 1e-15 * len {
                break;
            }
        }
        let zero = Float::new(p);
        let stop = Float::with_val(p, &self.len) >> (p as i32 / 2 + 4);
        // precision doubling: Newton steps on the lower copies (sums in
        // fixed point where they apply, else in MPFR), one on each and more
        // on a copy that can take s to p/2 + 8 bits (about 50 from the f64
        // steps, twice as many after each step, at most q − 10 on a copy of
        // q bits), after which one full step ends it
        let mut s = Float::with_val(p, s);
        let mut good = 50u32;
        let enough = p / 2 + 8;
        for c in &self.lower {
            let q = c.q;
            let zero_q = Float::new(q);
            let target_q = Float::with_val(q, &target);
            let mut out = [Float::new(q), Float::new(q)];
            let mut steps = 0;
            while good < q - 10 && (steps == 0 || (q - 10 >= enough && good < enough)) {
                let sq = Float::with_val(q, &s);
                if !c
                    .fixed
                    .eval(&[&c.dt, &c.rate], &zero_q, &c.dt.b, &sq, &mut out)
                {
                    ChebFit::basis_into(&zero_q, &c.dt.b, &sq, c.dt.c.len(), q, low);
                    out = [c.dt.dot(low), c.rate.dot(low)];
                }
                let step = Float::with_val(q, &out[0] - &target_q) / &out[1];
                if !step.is_finite() {
                    break;
                }
                s -= &step;
                s.assign(s.clone().max(&lo.0).min(&hi.0));
                good = (2 * good).min(q - 10);
                steps += 1;
            }
        }
        // full precision: t(s) and dt/ds summed in fixed point where it
        // applies (several times cheaper than MPFR's: FixedSums, built for
        // 16 bits beyond the interpolants' tolerance, `fixed_prec`, each in
        // its own scale), else in MPFR. Only output rows and the state at
        // the last time asked read s.
        let fits = [&self.dt, &self.rate];
        let mut fd = [Float::new(p), Float::new(p)];
        let after_lower = s.clone();
        if let Some(s) = newton(s, lo, hi, &stop, |s| {
            self.fixed_time
                .eval(&fits, &zero, &self.len, s, &mut fd)
                .then(|| (Float::with_val(p, &fd[0] - &target), fd[1].clone()))
        }) {
            return s;
        }
        let n = self.dt.c.len();
        newton(after_lower.clone(), lo, hi, &stop, |s| {
            ChebFit::basis_into(&zero, &self.len, s, n, p, full);
            Some((self.dt.dot(full) - &target, self.rate.dot(full)))
        })
        .unwrap_or(after_lower)
    }
}

/// Newton's method from `s` inside [lo.0, hi.0] on f with `f_df(s)` =
/// (f(s), f'(s)) at full precision, until a step is at most `stop` (20 steps
/// at most); `None` where `f_df` does not apply at some step.
fn newton(
    mut s: Float,
    lo: &(Float, Float),
    hi: &(Float, Float),
    stop: &Float,
    mut f_df: impl FnMut(&Float) -> Option<(Float, Float)>,
) -> Option<Float> {
    let p = s.prec();
    for _ in 0..20 {
        let (f, d) = f_df(&s)?;
        let step = Float::with_val(p, &f / &d);
        if !step.is_finite() {
            break;
        }
        s -= &step;
        s.assign(s.clone().max(&lo.0).min(&hi.0));
        if step.abs() <= *stop {
            break;
        }
    }
    Some(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The lower precisions: powers of two up to 3/4 p, then one at
    /// p/2 + 16 rounded up to whole limbs where the powers stop short of
    /// it and its sums take fewer limbs than the full precision's.
    #[test]
    fn lower_precisions_reach_half_the_precision_where_it_pays() {
        // the full steps' sums built for 16 bits beyond a tolerance 8 bits
        // below the answer precision, the working precision some 55 above it
        let of = |p: u32, fx: u32| lower_precisions(p, fx).collect::<Vec<_>>();
        // 30 digits: working precisions 171 and 226 bits, full sums for 132
        // and 179 (a 192-bit copy would sum in as many limbs)
        assert_eq!(of(171, 132), [128]);
        assert_eq!(of(226, 179), [128]);
        // 100 digits: 439 and 515 bits, full sums for 365 and 441
        assert_eq!(of(439, 365), [128, 256]);
        assert_eq!(of(515, 441), [128, 256, 320]);
        assert_eq!(of(515, 300), [128, 256]);
        assert_eq!(of(1000, 900), [128, 256, 512, 576]);
        assert!(of(150, 120).is_empty());
        for p in (64..4000).step_by(7) {
            let qs = of(p, p);
            assert!(qs.windows(2).all(|w| w[0] < w[1]), "{p}: {qs:?}");
            assert!(qs.iter().all(|&q| q + 32 < p), "{p}: {qs:?}");
        }
    }
}
