//! Several Chebyshev sums at one point, in fixed point: the sums a dense
//! grid of output times asks of a piece's interpolants (every state
//! coordinate at every time).
//!
//! At a few limbs MPFR spends most of a multiply-add in call overhead and
//! temporaries (about 600 instructions at 3–4 limbs, measured with
//! callgrind); the fixed-point numbers of [`crate::numeric::fixed`] take a
//! few per limb product. The coefficients are converted once; at each point
//! the basis T_k(x) comes from the three-term recurrence in fixed point and
//! each sum from one exact accumulation, rounded once.
//!
//! Accuracy: each fit is summed in its own scale. Its coefficients are
//! multiplied by 2^−e (exactly), e the exponent of the largest, so that the
//! largest lies in [1/2, 1); the sum is multiplied back by 2^e (exactly).
//! With F = 64(L − 1) fraction bits chosen ≥ the precision asked for,
//! prec, plus 8, the point x and the scaled coefficients are rounded to
//! 2^−F; the recurrence (stable for |x| ≤ 1: an error made at step j
//! reaches T_k multiplied by U_{k−j−1}(x), |U_m| ≤ m + 1) leaves T_k within
//! k²·2^−F; the accumulation truncates once. A scaled sum is within
//! (n² + n)·2^−F·max(1, Σ|c_k|2^−e) of the exact one, and since
//! 2^e ≤ 2 max|c_k| ≤ 2 Σ|c_k|, every sum is within
//! 2^−(prec−10)·Σ|c_k| of the exact sum of the coefficients for the
//! n ≤ 256 allowed: relative to the fit's own scale, whatever that scale
//! (a time unit of 10^−10 s, forces of 10^20 N), never an absolute floor.
//! The spectral route asks for 16 bits beyond its interpolants' tolerance
//! 2^−b, which is relative to each interpolant's scale
//! ([`crate::integrate::solve::Opts::for_prec`]; `fixed_prec` in
//! `integrate/spectral/piece.rs`): the sums add at most 2^−6 of that
//! tolerance, to values only read (the rows of a trajectory, their times,
//! the state at the last time asked), never carried on into the motion.

use super::ChebFit;
use crate::numeric::fixed::{self, Acc, Conv, Fx};
use rug::{Assign, Float};

/// The fits' coefficients in fixed point, for their sums at many points of
/// their common interval.
#[derive(Debug, Clone)]
pub struct FixedSums {
    /// Limbs per number (one of them the integer limb).
    limbs: usize,
    /// The fits' lengths.
    lens: Vec<usize>,
    /// The longest fit.
    n: usize,
    /// Magnitudes, fit after fit, coefficient after coefficient, `limbs`
    /// limbs each (least significant first).
    mags: Vec<u64>,
    /// Signs, in the same order.
    negs: Vec<bool>,
    /// Significant limbs, in the same order.
    sig: Vec<u16>,
    /// Each fit's scale exponent e (its coefficients are held as c·2^−e).
    exps: Vec<i32>,
    conv: Conv,
    /// The working precision.
    prec: u32,
}

/// The limb counts instantiated (beyond them the caller sums in MPFR).
macro_rules! with_limbs {
    ($l:expr, $f:ident, $($args:expr),*) => {
        match $l {
            3 => $f::<3>($($args),*),
            4 => $f::<4>($($args),*),
            5 => $f::<5>($($args),*),
            6 => $f::<6>($($args),*),
            7 => $f::<7>($($args),*),
            8 => $f::<8>($($args),*),
            9 => $f::<9>($($args),*),
            10 => $f::<10>($($args),*),
            12 => $f::<12>($($args),*),
            14 => $f::<14>($($args),*),
            16 => $f::<16>($($args),*),
            _ => None,
        }
    };
}

impl FixedSums {
    /// The coefficients of `fits` (one interval; working precision
    /// `prec`) in fixed point, each fit in its own scale; `None` where
    /// fixed point does not apply (a precision beyond the instantiated
    /// sizes, a coefficient not finite, a fit longer than 256).
    pub fn new(fits: &[&ChebFit], prec: u32) -> Option<Self> {
        let limbs = Self::limbs(prec)?;
        let lens: Vec<usize> = fits.iter().map(|f| f.c.len()).collect();
        let n = lens.iter().copied().max()?.max(2);
        if n > 256 {
            return None;
        }
        if fits.iter().flat_map(|f| f.c.iter()).any(|c| !c.is_finite()) {
            return None;
        }
        // the exponent of each fit's largest coefficient (0 for a zero fit)
        let exps = fits
            .iter()
            .map(|f| crate::numeric::max_exp(&f.c).unwrap_or(0))
            .collect();
        let mut s = FixedSums {
            limbs,
            lens,
            n,
            mags: Vec::new(),
            negs: Vec::new(),
            sig: Vec::new(),
            exps,
            conv: Conv::new(prec),
            prec,
        };
        with_limbs!(limbs, convert, &mut s, fits)?;
        Some(s)
    }

    /// The limbs of sums built for `prec` bits (8 more fraction bits, one
    /// integer limb, rounded up to an instantiated size; `None` beyond).
    pub fn limbs(prec: u32) -> Option<usize> {
        fixed::limbs_for((prec as usize + 8).div_ceil(64) + 1)
    }

    /// The sum of each fit at `v` of the interval [a, b] into `out` (one per
    /// fit, each rounded to its own precision); `false` (out unspecified)
    /// where a value left the fixed-point range.
    pub fn eval(&mut self, a: &Float, b: &Float, v: &Float, out: &mut [Float]) -> bool {
        // x to the fixed point's own fraction bits (at least the precision)
        let p = self.prec.max(64 * (self.limbs as u32 - 1));
        // x = (2v − a − b)/(b − a), as ChebFit::basis_into
        let mut x = Float::with_val(p, v * 2u32);
        x -= a;
        x -= b;
        x /= Float::with_val(p, b - a);
        if x > 1u32 || x < -1i32 {
            return false;
        }
        with_limbs!(self.limbs, sums, self, &x, out).unwrap_or(false)
    }
}

/// [`FixedSums`] built at the first sum asked, for fits that do not change
/// (a piece's interpolants): every call sums the same fits.
#[derive(Debug)]
pub struct LazySums {
    sums: std::cell::RefCell<Option<Option<FixedSums>>>,
    /// The precision the sums are built for.
    prec: u32,
}

impl LazySums {
    /// Sums built for precision `prec` ([`FixedSums::new`]): within
    /// 2^−(prec−10)·Σ|c_k| of each fit, whatever the point's precision.
    pub fn at(prec: u32) -> Self {
        LazySums {
            sums: Default::default(),
            prec,
        }
    }

    /// [`FixedSums::eval`] of `fits` at `v` of [a, b] (built at the first
    /// call, for [`LazySums::at`]'s precision); `false` (out
    /// unspecified) where fixed point does not apply, there or for these
    /// fits at all.
    pub fn eval(
        &self,
        fits: &[&ChebFit],
        a: &Float,
        b: &Float,
        v: &Float,
        out: &mut [Float],
    ) -> bool {
        let mut fx = self.sums.borrow_mut();
        fx.get_or_insert_with(|| FixedSums::new(fits, self.prec))
            .as_mut()
            .is_some_and(|fx| fx.eval(a, b, v, out))
    }
}

fn convert<const L: usize>(s: &mut FixedSums, fits: &[&ChebFit]) -> Option<()> {
    let mut scaled = Float::new(s.prec);
    for (f, &e) in fits.iter().zip(&s.exps) {
        for c in &f.c {
            if scaled.prec() != c.prec() {
                scaled.set_prec(c.prec());
            }
            scaled.assign(c >> e);
            let v: Fx<L> = s.conv.to_fx(&scaled);
            s.mags.extend_from_slice(&v.m);
            s.negs.push(v.neg);
            s.sig.push(v.len);
        }
    }
    Some(())
}

fn coef<const L: usize>(s: &FixedSums, at: usize) -> Fx<L> {
    let mut m = [0u64; L];
    m.copy_from_slice(&s.mags[at * L..(at + 1) * L]);
    Fx {
        m,
        len: s.sig[at],
        neg: s.negs[at],
    }
}

fn sums<const L: usize>(s: &mut FixedSums, x: &Float, out: &mut [Float]) -> Option<bool> {
    let xf: Fx<L> = s.conv.to_fx(x);
    let x2 = xf.mul_small(2);
    let mut one = [0u64; L];
    one[L - 1] = 1;
    let mut basis: Vec<Fx<L>> = Vec::with_capacity(s.n);
    basis.push(Fx {
        m: one,
        len: L as u16,
        neg: false,
    });
    basis.push(xf);
    let mut acc = Acc::<L>::new();
    for k in 2..s.n {
        // T_k = 2x T_{k−1} − T_{k−2}
        acc.clear();
        acc.mac(&x2, &basis[k - 1]);
        let mut back = basis[k - 2];
        back.neg = !back.neg && back.len > 0;
        acc.add(&back);
        basis.push(acc.finish(1));
    }
    let mut at = 0;
    for (i, o) in out.iter_mut().enumerate() {
        acc.clear();
        let len = s.lens.get(i).copied().unwrap_or(0);
        for (k, t) in basis.iter().enumerate().take(len) {
            acc.mac(&coef::<L>(s, at + k), t);
        }
        at += len;
        let r = acc.finish(1);
        s.conv.to_float(&r, o);
        *o <<= s.exps.get(i).copied().unwrap_or(0);
    }
    Some(!acc.overflow)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::ops::Pow;

    /// The fixed-point sums against MPFR's, for fits of several lengths and
    /// magnitudes at several precisions, far inside the working precision.
    #[test]
    fn agree_with_the_floating_point_sums() {
        for &p in &[64u32, 171, 226, 400, 700] {
            let a = Float::with_val(p, 0u32);
            let b = Float::with_val(p, 3) / 7u32;
            let fits: Vec<ChebFit> = [(40usize, 1.0f64), (61, -3.5e3), (61, 2.0e-9)]
                .iter()
                .map(|&(n, scale)| {
                    let c = (0..n)
                        .map(|k| {
                            // decaying, alternating, irrational-ish coefficients
                            let mut v = Float::with_val(p, k as u32 + 2).sqrt() * scale;
                            v /= Float::with_val(p, 1.7f64).pow(k as u32);
                            if k % 3 == 1 {
                                -v
                            } else {
                                v
                            }
                        })
                        .collect();
                    ChebFit {
                        a: a.clone(),
                        b: b.clone(),
                        c,
                        fmax: Float::with_val(p, scale.abs()),
                    }
                })
                .collect();
            let refs: Vec<&ChebFit> = fits.iter().collect();
            let mut fx = FixedSums::new(&refs, p).expect("fixed point applies");
            for j in 0..9u32 {
                let v = Float::with_val(p, &b * j) / 8u32;
                let mut out = vec![Float::new(p); fits.len()];
                assert!(fx.eval(&a, &b, &v, &mut out));
                let mut basis = Vec::new();
                ChebFit::basis_into(&a, &b, &v, 61, p, &mut basis);
                for (f, o) in fits.iter().zip(&out) {
                    let want = f.dot(&basis);
                    let tol = (Float::with_val(p, want.abs_ref()) + 1u32) >> (p as i32 - 6);
                    let diff = Float::with_val(p, o - &want).abs();
                    assert!(diff <= tol, "p {p} v {j}/8: {o} vs {want}");
                }
            }
        }
    }

    /// Each fit summed in its own scale: fits of one shape at scales from
    /// 2^−300 to 2^200 (beyond the integer limb), summed together, each
    /// within 2^−(prec−10)·Σ|c_k| of MPFR's sum at twice the precision —
    /// relative to the fit, where one absolute error for all gave the small
    /// fits none of their digits and declined the large ones.
    #[test]
    fn sums_each_fit_in_its_own_scale() {
        for &p in &[128u32, 171, 400] {
            let hp = 2 * p;
            let a = Float::with_val(p, 0u32);
            let b = Float::with_val(p, 5u32) / 3u32;
            let shape: Vec<Float> = (0..48u32)
                .map(|k| {
                    let v =
                        Float::with_val(p, 2 * k + 3).sqrt() / Float::with_val(p, 1.9f64).pow(k);
                    if k % 2 == 1 {
                        -v
                    } else {
                        v
                    }
                })
                .collect();
            let exps = [-300i32, -40, 0, 61, 200];
            let fits: Vec<ChebFit> = exps
                .iter()
                .map(|&e| ChebFit {
                    a: a.clone(),
                    b: b.clone(),
                    c: shape.iter().map(|c| Float::with_val(p, c << e)).collect(),
                    fmax: Float::with_val(p, 1u32) << e,
                })
                .collect();
            let refs: Vec<&ChebFit> = fits.iter().collect();
            let mut fx = FixedSums::new(&refs, p).expect("fixed point applies at any scale");
            for j in 0..7u32 {
                let v = Float::with_val(p, &b * j) / 6u32;
                let mut out = vec![Float::new(p); fits.len()];
                assert!(fx.eval(&a, &b, &v, &mut out));
                let mut basis = Vec::new();
                ChebFit::basis_into(&a, &b, &Float::with_val(hp, &v), 48, hp, &mut basis);
                for ((f, o), e) in fits.iter().zip(&out).zip(exps) {
                    let want = f.dot(&basis);
                    let total = f.c.iter().fold(Float::new(hp), |s, c| s + c.clone().abs());
                    let tol = total >> (p as i32 - 10);
                    let diff = Float::with_val(hp, o - &want).abs();
                    assert!(diff <= tol, "p {p}, scale 2^{e}, v {j}/6: {o} vs {want}");
                }
            }
        }
    }
}
