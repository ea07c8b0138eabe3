//! Interval arithmetic on MPFR floats with directed rounding: the kernel of
//! `--rigorous`.
//!
//! An [`Iv`] is a closed interval [lo, hi] of `rug::Float`s at one working
//! precision. Every operation returns an interval that contains the exact
//! result for every pair of points of its operands: MPFR rounds each
//! operation correctly in the direction asked (`Round::Down` for a lower
//! end, `Round::Up` for an upper end), so the enclosure of each elementary
//! operation is exact to implement. Transcendental functions use their
//! monotonicity (sqrt, acos, exp, sinh, cosh on a half-line) or, for sin and
//! cos, the mean value bound |f(x) − f(m)| ≤ |x − m| around the midpoint,
//! which is as tight as the operand for the narrow intervals used here.
//!
//! [`Cx`] is a rectangular complex interval, for bounding |f| of an analytic
//! integrand on a Bernstein ellipse (the error bound of the rigorous
//! quadrature).

use crate::error::{Error, Result};
use crate::exact::Exact;
use rug::float::{Constant, Round};
use rug::{Float, Rational};
use std::cmp::Ordering;

/// A closed interval [lo, hi] (lo ≤ hi) at one precision.
#[derive(Debug, Clone, PartialEq)]
pub struct Iv {
    /// Lower end.
    pub lo: Float,
    /// Upper end.
    pub hi: Float,
}

/// `x` rounded to `p` bits towards −∞ and towards +∞.
fn ends_of(p: u32, x: &Float) -> (Float, Float) {
    (
        Float::with_val_round(p, x, Round::Down).0,
        Float::with_val_round(p, x, Round::Up).0,
    )
}

impl Iv {
    /// The precision of the ends.
    pub fn prec(&self) -> u32 {
        self.lo.prec()
    }

    /// The interval containing the float `x`, at `p` bits.
    pub fn point(p: u32, x: &Float) -> Iv {
        let (lo, hi) = ends_of(p, x);
        Iv { lo, hi }
    }

    /// The interval containing the integer `n`.
    pub fn int(p: u32, n: i64) -> Iv {
        Iv {
            lo: Float::with_val_round(p, n, Round::Down).0,
            hi: Float::with_val_round(p, n, Round::Up).0,
        }
    }

    /// The interval containing the rational `q`.
    pub fn rational(p: u32, q: &Rational) -> Iv {
        Iv {
            lo: Float::with_val_round(p, q, Round::Down).0,
            hi: Float::with_val_round(p, q, Round::Up).0,
        }
    }

    /// π.
    pub fn pi(p: u32) -> Iv {
        Iv {
            lo: Float::with_val_round(p, Constant::Pi, Round::Down).0,
            hi: Float::with_val_round(p, Constant::Pi, Round::Up).0,
        }
    }

    /// An exact input (a rational, or a rational times π).
    pub fn exact(p: u32, e: &Exact) -> Iv {
        let q = Iv::rational(p, &e.coef);
        if e.times_pi {
            q.mul(&Iv::pi(p))
        } else {
            q
        }
    }

    /// [lo, hi] from two ends (checked lo ≤ hi).
    pub fn new(lo: Float, hi: Float) -> Iv {
        debug_assert!(lo <= hi, "{lo} > {hi}");
        Iv { lo, hi }
    }

    /// Whether `x` lies in the interval.
    pub fn contains(&self, x: &Float) -> bool {
        self.lo <= *x && *x <= self.hi
    }

    /// Whether 0 lies in the interval.
    pub fn contains_zero(&self) -> bool {
        self.lo <= 0 && self.hi >= 0
    }

    /// Every point is > 0.
    pub fn is_positive(&self) -> bool {
        self.lo > 0
    }

    /// Every point is < 0.
    pub fn is_negative(&self) -> bool {
        self.hi < 0
    }

    /// The width hi − lo, rounded up.
    pub fn width(&self) -> Float {
        Float::with_val_round(self.prec(), &self.hi - &self.lo, Round::Up).0
    }

    /// (mid, rad): the midpoint (to nearest) and a radius rounded up such
    /// that [mid − rad, mid + rad] contains the interval.
    pub fn mid_rad(&self) -> (Float, Float) {
        let p = self.prec();
        let mid = Float::with_val(p, &self.lo + &self.hi) / 2u32;
        let a = Float::with_val_round(p, &self.hi - &mid, Round::Up).0;
        let b = Float::with_val_round(p, &mid - &self.lo, Round::Up).0;
        let rad = if a > b { a } else { b };
        (mid, rad)
    }

    /// −x.
    pub fn neg(&self) -> Iv {
        Iv {
            lo: Float::with_val(self.prec(), -&self.hi),
            hi: Float::with_val(self.prec(), -&self.lo),
        }
    }

    /// x + y.
    pub fn add(&self, o: &Iv) -> Iv {
        let p = self.prec();
        Iv {
            lo: Float::with_val_round(p, &self.lo + &o.lo, Round::Down).0,
            hi: Float::with_val_round(p, &self.hi + &o.hi, Round::Up).0,
        }
    }

    /// x − y.
    pub fn sub(&self, o: &Iv) -> Iv {
        let p = self.prec();
        Iv {
            lo: Float::with_val_round(p, &self.lo - &o.hi, Round::Down).0,
            hi: Float::with_val_round(p, &self.hi - &o.lo, Round::Up).0,
        }
    }

    /// x·y: by the signs of the ends, the two end products that bound it
    /// (all four when both intervals straddle 0), rounded outwards.
    pub fn mul(&self, o: &Iv) -> Iv {
        let p = self.prec();
        let dn = |a: &Float, b: &Float| Float::with_val_round(p, a * b, Round::Down).0;
        let up = |a: &Float, b: &Float| Float::with_val_round(p, a * b, Round::Up).0;
        let (a, b, c, d) = (&self.lo, &self.hi, &o.lo, &o.hi);
        let nonneg = |x: &Float| !x.is_sign_negative() || x.is_zero();
        let nonpos = |x: &Float| x.is_sign_negative() || x.is_zero();
        let (lo, hi) = if nonneg(a) {
            if nonneg(c) {
                (dn(a, c), up(b, d))
            } else if nonpos(d) {
                (dn(b, c), up(a, d))
            } else {
                (dn(b, c), up(b, d))
            }
        } else if nonpos(b) {
            if nonneg(c) {
                (dn(a, d), up(b, c))
            } else if nonpos(d) {
                (dn(b, d), up(a, c))
            } else {
                (dn(a, d), up(a, c))
            }
        } else if nonneg(c) {
            (dn(a, d), up(b, d))
        } else if nonpos(d) {
            (dn(b, c), up(a, c))
        } else {
            let (l1, l2) = (dn(a, d), dn(b, c));
            let (h1, h2) = (up(a, c), up(b, d));
            (if l1 < l2 { l1 } else { l2 }, if h1 > h2 { h1 } else { h2 })
        };
        Iv { lo, hi }
    }

    /// x².
    pub fn sqr(&self) -> Iv {
        let p = self.prec();
        let a = Float::with_val(p, self.lo.abs_ref());
        let b = Float::with_val(p, self.hi.abs_ref());
        let (small, large) = if a < b { (a, b) } else { (b, a) };
        let lo = if self.lo <= 0 && self.hi >= 0 {
            Float::new(p)
        } else {
            Float::with_val_round(p, small.square_ref(), Round::Down).0
        };
        Iv {
            lo,
            hi: Float::with_val_round(p, large.square_ref(), Round::Up).0,
        }
    }

    /// x·q for a rational q.
    pub fn mul_q(&self, q: &Rational) -> Iv {
        self.mul(&Iv::rational(self.prec(), q))
    }

    /// x + q for a rational q.
    pub fn add_q(&self, q: &Rational) -> Iv {
        self.add(&Iv::rational(self.prec(), q))
    }

    /// 1/x.
    ///
    /// Errors: 0 in the interval.
    pub fn recip(&self) -> Result<Iv> {
        if self.lo <= 0 && self.hi >= 0 {
            return Err(not_enclosed("a division by an interval containing 0"));
        }
        let p = self.prec();
        Ok(Iv {
            lo: Float::with_val_round(p, self.hi.recip_ref(), Round::Down).0,
            hi: Float::with_val_round(p, self.lo.recip_ref(), Round::Up).0,
        })
    }

    /// x / y.
    ///
    /// Errors: 0 in y.
    pub fn div(&self, o: &Iv) -> Result<Iv> {
        if o.lo <= 0 && o.hi >= 0 {
            return Err(not_enclosed("a division by an interval containing 0"));
        }
        let p = self.prec();
        let mut lo: Option<Float> = None;
        let mut hi: Option<Float> = None;
        for a in [&self.lo, &self.hi] {
            for b in [&o.lo, &o.hi] {
                let d = Float::with_val_round(p, a / b, Round::Down).0;
                let u = Float::with_val_round(p, a / b, Round::Up).0;
                if lo.as_ref().is_none_or(|l| d < *l) {
                    lo = Some(d);
                }
                if hi.as_ref().is_none_or(|h| u > *h) {
                    hi = Some(u);
                }
            }
        }
        Ok(Iv {
            lo: lo.unwrap_or_else(|| Float::new(p)),
            hi: hi.unwrap_or_else(|| Float::new(p)),
        })
    }

    /// |x|.
    pub fn abs(&self) -> Iv {
        if self.lo >= 0 {
            self.clone()
        } else if self.hi <= 0 {
            self.neg()
        } else {
            let p = self.prec();
            let a = Float::with_val(p, -&self.lo);
            Iv {
                lo: Float::new(p),
                hi: if a > self.hi { a } else { self.hi.clone() },
            }
        }
    }

    /// √x.
    ///
    /// Errors: a negative lower end (√ of a value that may be < 0).
    pub fn sqrt(&self) -> Result<Iv> {
        if self.lo.is_sign_negative() && !self.lo.is_zero() {
            return Err(not_enclosed(
                "the square root of an interval reaching below 0",
            ));
        }
        let p = self.prec();
        Ok(Iv {
            lo: Float::with_val_round(p, self.lo.sqrt_ref(), Round::Down).0,
            hi: Float::with_val_round(p, self.hi.sqrt_ref(), Round::Up).0,
        })
    }

    /// The mean-value enclosure f([lo, hi]) ⊂ [f↓(m) − r, f↑(m) + r] of a
    /// 1-Lipschitz function f (sin, cos), clipped to [−1, 1].
    fn lipschitz1(&self, f: impl Fn(&mut Float, Round) -> Ordering) -> Iv {
        let p = self.prec();
        let (m, r) = self.mid_rad();
        let mut d = Float::with_val(p, &m);
        f(&mut d, Round::Down);
        let mut u = Float::with_val(p, &m);
        f(&mut u, Round::Up);
        let mut lo = Float::with_val_round(p, &d - &r, Round::Down).0;
        let mut hi = Float::with_val_round(p, &u + &r, Round::Up).0;
        if lo < -1 {
            lo = Float::with_val(p, -1);
        }
        if hi > 1 {
            hi = Float::with_val(p, 1);
        }
        Iv { lo, hi }
    }

    /// sin x.
    pub fn sin(&self) -> Iv {
        self.lipschitz1(|x, r| x.sin_round(r))
    }

    /// cos x.
    pub fn cos(&self) -> Iv {
        self.lipschitz1(|x, r| x.cos_round(r))
    }

    /// (sin x, cos x) from one MPFR `sin_cos` at the midpoint m, rounded to
    /// nearest: each result is within half an ulp of sin m (cos m), so within
    /// 2^(1−p)·|value| (≤ 2^(1−p)), and |sin x − sin m| ≤ |x − m| ≤ rad (both
    /// are 1-Lipschitz). Half the cost of [`Iv::sin`] and [`Iv::cos`], for
    /// the narrow intervals of quadrature nodes.
    pub fn sin_cos(&self) -> (Iv, Iv) {
        let p = self.prec();
        let (m, r) = self.mid_rad();
        let (s, c) = m.sin_cos(Float::new(p));
        let ulp = Float::with_val(p, 1u32) >> (p as i32 - 1);
        let widen = |v: Float| {
            // e = rad + 2^(1−p) (≥ half an ulp of any value ≤ 1 in size)
            let e = Float::with_val_round(p, &r + &ulp, Round::Up).0;
            let mut lo = Float::with_val_round(p, &v - &e, Round::Down).0;
            let mut hi = Float::with_val_round(p, &v + &e, Round::Up).0;
            if lo < -1 {
                lo = Float::with_val(p, -1);
            }
            if hi > 1 {
                hi = Float::with_val(p, 1);
            }
            Iv { lo, hi }
        };
        (widen(s), widen(c))
    }

    /// The interval rounded outwards to `p` bits (a superset).
    pub fn outward(&self, p: u32) -> Iv {
        Iv {
            lo: Float::with_val_round(p, &self.lo, Round::Down).0,
            hi: Float::with_val_round(p, &self.hi, Round::Up).0,
        }
    }

    /// arccos x, decreasing on [−1, 1]; ends beyond ±1 by rounding are
    /// clipped (the argument is a cosine).
    ///
    /// Errors: an interval wholly outside [−1, 1].
    pub fn acos(&self) -> Result<Iv> {
        let p = self.prec();
        if self.lo > 1 || self.hi < -1 {
            return Err(not_enclosed("arccos of an interval outside [-1, 1]"));
        }
        let one = Float::with_val(p, 1);
        let lo_arg = if self.hi > 1 {
            one.clone()
        } else {
            self.hi.clone()
        };
        let hi_arg = if self.lo < -1 { -one } else { self.lo.clone() };
        let mut lo = Float::with_val(p, &lo_arg);
        lo.acos_round(Round::Down);
        let mut hi = Float::with_val(p, &hi_arg);
        hi.acos_round(Round::Up);
        Ok(Iv { lo, hi })
    }

    /// e^x.
    pub fn exp(&self) -> Iv {
        let p = self.prec();
        let mut lo = Float::with_val(p, &self.lo);
        lo.exp_round(Round::Down);
        let mut hi = Float::with_val(p, &self.hi);
        hi.exp_round(Round::Up);
        Iv { lo, hi }
    }

    /// sinh x (increasing).
    pub fn sinh(&self) -> Iv {
        let p = self.prec();
        let mut lo = Float::with_val(p, &self.lo);
        lo.sinh_round(Round::Down);
        let mut hi = Float::with_val(p, &self.hi);
        hi.sinh_round(Round::Up);
        Iv { lo, hi }
    }

    /// cosh x (even, increasing on x ≥ 0).
    pub fn cosh(&self) -> Iv {
        let p = self.prec();
        let a = self.abs();
        let mut lo = Float::with_val(p, &a.lo);
        lo.cosh_round(Round::Down);
        let mut hi = Float::with_val(p, &a.hi);
        hi.cosh_round(Round::Up);
        Iv { lo, hi }
    }

    /// The hull of two intervals.
    pub fn hull(&self, o: &Iv) -> Iv {
        Iv {
            lo: if self.lo < o.lo {
                self.lo.clone()
            } else {
                o.lo.clone()
            },
            hi: if self.hi > o.hi {
                self.hi.clone()
            } else {
                o.hi.clone()
            },
        }
    }

    /// Horner's rule for Σ c_i x^i with interval coefficients.
    pub fn horner(coef: &[Iv], x: &Iv) -> Iv {
        let p = x.prec();
        let mut acc = Iv::int(p, 0);
        for c in coef.iter().rev() {
            acc = acc.mul(x).add(c);
        }
        acc
    }
}

/// The error of a quantity that interval arithmetic could not enclose.
pub fn not_enclosed(what: &str) -> Error {
    Error::NotConverged {
        quantity: "enclosure".into(),
        requested: 0,
        reached: "no enclosure".into(),
        detail: what.to_string(),
    }
}

/// A rectangular complex interval re + i·im.
#[derive(Debug, Clone)]
pub struct Cx {
    /// Real part.
    pub re: Iv,
    /// Imaginary part.
    pub im: Iv,
}

impl Cx {
    /// A real interval.
    pub fn real(x: Iv) -> Cx {
        let p = x.prec();
        Cx {
            re: x,
            im: Iv::int(p, 0),
        }
    }

    /// z + w.
    pub fn add(&self, o: &Cx) -> Cx {
        Cx {
            re: self.re.add(&o.re),
            im: self.im.add(&o.im),
        }
    }

    /// z − w.
    pub fn sub(&self, o: &Cx) -> Cx {
        Cx {
            re: self.re.sub(&o.re),
            im: self.im.sub(&o.im),
        }
    }

    /// z·w.
    pub fn mul(&self, o: &Cx) -> Cx {
        Cx {
            re: self.re.mul(&o.re).sub(&self.im.mul(&o.im)),
            im: self.re.mul(&o.im).add(&self.im.mul(&o.re)),
        }
    }

    /// z² = (x² − y²) + 2xy·i, with the squares of the parts enclosed
    /// tightly ([`Iv::sqr`]), not as products of independent factors.
    pub fn sqr(&self) -> Cx {
        let two = Iv::int(self.re.prec(), 2);
        Cx {
            re: self.re.sqr().sub(&self.im.sqr()),
            im: self.re.mul(&self.im).mul(&two),
        }
    }

    /// z·x for a real interval x.
    pub fn scale(&self, x: &Iv) -> Cx {
        Cx {
            re: self.re.mul(x),
            im: self.im.mul(x),
        }
    }

    /// z + x for a real interval x.
    pub fn add_real(&self, x: &Iv) -> Cx {
        Cx {
            re: self.re.add(x),
            im: self.im.clone(),
        }
    }

    /// sin z = sin x cosh y + i cos x sinh y.
    pub fn sin(&self) -> Cx {
        Cx {
            re: self.re.sin().mul(&self.im.cosh()),
            im: self.re.cos().mul(&self.im.sinh()),
        }
    }

    /// cos z = cos x cosh y − i sin x sinh y.
    pub fn cos(&self) -> Cx {
        Cx {
            re: self.re.cos().mul(&self.im.cosh()),
            im: self.re.sin().mul(&self.im.sinh()).neg(),
        }
    }

    /// An upper bound of |z| over the box.
    pub fn abs_hi(&self) -> Float {
        let p = self.re.prec();
        let s = self.re.sqr().add(&self.im.sqr());
        Float::with_val_round(p, s.hi.sqrt_ref(), Round::Up).0
    }

    /// A lower bound of |z| over the box (0 if it may contain 0).
    pub fn abs_lo(&self) -> Float {
        let p = self.re.prec();
        let dist = |iv: &Iv| -> Float {
            if iv.lo > 0 {
                iv.lo.clone()
            } else if iv.hi < 0 {
                Float::with_val(p, -&iv.hi)
            } else {
                Float::new(p)
            }
        };
        let (a, b) = (dist(&self.re), dist(&self.im));
        let a2 = Float::with_val_round(p, a.square_ref(), Round::Down).0;
        let b2 = Float::with_val_round(p, b.square_ref(), Round::Down).0;
        let s = Float::with_val_round(p, &a2 + &b2, Round::Down).0;
        Float::with_val_round(p, s.sqrt_ref(), Round::Down).0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const P: u32 = 96;
    const HI: u32 = 1024;

    /// Deterministic pseudo-random floats: wide exponents, both signs,
    /// values near 0 and near the branch points of the functions.
    fn samples() -> Vec<Float> {
        let mut out = Vec::new();
        let mut next = crate::numeric::xorshift(0x9e3779b97f4a7c15);
        for i in 0..300 {
            let s = next();
            let m = (s >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0;
            let e = (i % 41) - 20;
            out.push(Float::with_val(P, m) * Float::with_val(P, Float::i_exp(1, e)));
        }
        for x in [
            0.0,
            1.0,
            -1.0,
            1e-30,
            -1e-30,
            0.999999999999,
            -0.999999999999,
        ] {
            out.push(Float::with_val(P, x));
        }
        out.push(Float::with_val(P, Constant::Pi) / 2u32);
        out
    }

    /// An interval of radius `r` relative around x (x itself when r = 0).
    fn around(x: &Float, r: i32) -> Iv {
        if r == 0 {
            return Iv::point(P, x);
        }
        let d = Float::with_val(P, x.abs_ref()) >> r as u32;
        let d = if d.is_zero() {
            Float::with_val(P, 1) >> 100u32
        } else {
            d
        };
        Iv::new(
            Float::with_val_round(P, x - &d, Round::Down).0,
            Float::with_val_round(P, x + &d, Round::Up).0,
        )
    }

    /// Points of an interval to test: the ends and the middle, at HI bits.
    fn points(iv: &Iv) -> Vec<Float> {
        let m = Float::with_val(HI, &iv.lo + &iv.hi) / 2u32;
        vec![Float::with_val(HI, &iv.lo), m, Float::with_val(HI, &iv.hi)]
    }

    #[track_caller]
    fn holds(name: &str, iv: &Iv, exact: &Float) {
        assert!(
            iv.lo <= *exact && *exact <= iv.hi,
            "{name}: {exact} not in [{}, {}]",
            iv.lo,
            iv.hi
        );
    }

    #[test]
    fn every_operation_encloses_the_exact_result() {
        let xs = samples();
        for (k, x) in xs.iter().enumerate() {
            let y = &xs[(k * 7 + 3) % xs.len()];
            for r in [0, 40, 8] {
                let a = around(x, r);
                let b = around(y, r + 3);
                for pa in points(&a) {
                    for pb in points(&b) {
                        holds("add", &a.add(&b), &Float::with_val(HI, &pa + &pb));
                        holds("sub", &a.sub(&b), &Float::with_val(HI, &pa - &pb));
                        holds("mul", &a.mul(&b), &Float::with_val(HI, &pa * &pb));
                        if let Ok(d) = a.div(&b) {
                            holds("div", &d, &Float::with_val(HI, &pa / &pb));
                        }
                    }
                    holds("sqr", &a.sqr(), &Float::with_val(HI, pa.square_ref()));
                    holds("neg", &a.neg(), &Float::with_val(HI, -&pa));
                    holds("abs", &a.abs(), &Float::with_val(HI, pa.abs_ref()));
                    holds("sin", &a.sin(), &Float::with_val(HI, pa.sin_ref()));
                    holds("cos", &a.cos(), &Float::with_val(HI, pa.cos_ref()));
                    let (sn, cs) = a.sin_cos();
                    holds("sin_cos s", &sn, &Float::with_val(HI, pa.sin_ref()));
                    holds("sin_cos c", &cs, &Float::with_val(HI, pa.cos_ref()));
                    holds("outward", &a.outward(40), &pa);
                    if pa.clone().abs() < 30 {
                        holds("exp", &a.exp(), &Float::with_val(HI, pa.exp_ref()));
                        holds("sinh", &a.sinh(), &Float::with_val(HI, pa.sinh_ref()));
                        holds("cosh", &a.cosh(), &Float::with_val(HI, pa.cosh_ref()));
                    }
                    if let Ok(s) = a.sqrt() {
                        holds("sqrt", &s, &Float::with_val(HI, pa.sqrt_ref()));
                    }
                    if pa.clone().abs() <= 1 {
                        if let Ok(c) = a.acos() {
                            holds("acos", &c, &Float::with_val(HI, pa.acos_ref()));
                        }
                    }
                    if let Ok(rc) = a.recip() {
                        holds("recip", &rc, &Float::with_val(HI, pa.recip_ref()));
                    }
                }
            }
        }
    }

    #[test]
    fn cancellation_and_zero_are_enclosed() {
        // (1 + 2^-90) − 1 at 96 bits is exact; with a 2^-100 radius the
        // enclosure still contains the exact difference and has the width of
        // the operands, not of 1
        let one = Float::with_val(P, 1);
        let tiny = Float::with_val(P, 1) >> 90u32;
        let a = Iv::point(P, &Float::with_val(P, &one + &tiny));
        let d = a.sub(&Iv::point(P, &one));
        assert!(d.contains(&tiny));
        assert!(d.width() <= Float::with_val(P, 1) >> 96u32);
        // an interval around 0 cannot be divided by, nor have a square root
        let z = Iv::new(Float::with_val(P, -1e-40), Float::with_val(P, 1e-40));
        assert!(Iv::int(P, 1).div(&z).is_err());
        assert!(z.sqrt().is_err());
        // acos at the branch point 1 and beyond it by rounding
        let c = Iv::new(
            Float::with_val(P, 1) - (Float::with_val(P, 1) >> 80u32),
            Float::with_val(P, 1) + (Float::with_val(P, 1) >> 80u32),
        );
        let a = c.acos().unwrap();
        assert!(a.contains(&Float::new(P)));
        assert!(a.hi < 1e-11);
    }

    #[test]
    fn closed_forms_lie_inside() {
        for (c, want) in [("1/2", "pi/3"), ("4/7", "acos(4/7)"), ("2/3", "acos(2/3)")] {
            let q: Rational = c.parse().unwrap();
            let e = Iv::rational(P, &q).acos().unwrap();
            let exact = Float::with_val(HI, Float::with_val(HI, &q).acos_ref());
            holds(want, &e, &exact);
            assert!(e.width() < Float::with_val(P, 1) >> 90u32, "{want}");
        }
        let pi3 = Iv::pi(P).div(&Iv::int(P, 3)).unwrap();
        let exact = Float::with_val(HI, Constant::Pi) / 3u32;
        holds("pi/3", &pi3, &exact);
    }

    #[test]
    fn complex_sin_and_modulus_bounds_hold() {
        for (x, y) in [(0.3, 0.2), (-1.2, 0.7), (2.0, -0.05), (0.0, 1.5)] {
            let z = Cx {
                re: around(&Float::with_val(P, x), 30),
                im: around(&Float::with_val(P, y), 30),
            };
            // sin z and cos z by their power series in complex arithmetic
            // at HI bits (independent of the formula under test)
            let (mut sr, mut si) = (Float::new(HI), Float::new(HI));
            let (mut cr, mut ci) = (Float::new(HI), Float::new(HI));
            let (zr, zi) = (Float::with_val(HI, x), Float::with_val(HI, y));
            let (mut tr, mut ti) = (Float::with_val(HI, 1), Float::new(HI)); // z^k/k!
            for k in 0..400u32 {
                match k % 4 {
                    0 => {
                        cr += &tr;
                        ci += &ti;
                    }
                    1 => {
                        sr += &tr;
                        si += &ti;
                    }
                    2 => {
                        cr -= &tr;
                        ci -= &ti;
                    }
                    _ => {
                        sr -= &tr;
                        si -= &ti;
                    }
                }
                let nr = Float::with_val(HI, &tr * &zr) - Float::with_val(HI, &ti * &zi);
                let ni = Float::with_val(HI, &tr * &zi) + Float::with_val(HI, &ti * &zr);
                tr = nr / (k + 1);
                ti = ni / (k + 1);
            }
            let w = z.sin();
            holds("sin re", &w.re, &sr);
            holds("sin im", &w.im, &si);
            let w = z.cos();
            holds("cos re", &w.re, &cr);
            holds("cos im", &w.im, &ci);
            let m = (Float::with_val(HI, sr.square_ref()) + Float::with_val(HI, si.square_ref()))
                .sqrt();
            let ws = z.sin();
            assert!(ws.abs_hi() >= m && ws.abs_lo() <= m);
            // z² against the exact square of the box's points
            let sq = z.sqr();
            for pr in points(&z.re) {
                for pi in points(&z.im) {
                    let re =
                        Float::with_val(HI, pr.square_ref()) - Float::with_val(HI, pi.square_ref());
                    let im = Float::with_val(HI, &pr * &pi) * 2u32;
                    holds("sqr re", &sq.re, &re);
                    holds("sqr im", &sq.im, &im);
                }
            }
        }
    }
}
