//! Bracketed root finding on `rug::Float`: Illinois regula falsi with a
//! bisection safeguard, returning the final bracket.
//!
//! A root is *certified* by the sign change across the returned bracket, as
//! far as the signs of f at the bracket ends are right: near a simple root f's
//! rounding error is what limits that, which the precision ladder checks.

use crate::error::{Error, Result};
use rug::{Assign, Float};

/// A root as its bracket: f(lo) and f(hi) have opposite signs (or one is 0).
#[derive(Debug, Clone)]
pub struct Root {
    /// Lower end of the final bracket.
    pub lo: Float,
    /// Upper end of the final bracket.
    pub hi: Float,
    /// Function evaluations used.
    pub evals: u32,
}

impl Root {
    /// The midpoint of the bracket.
    pub fn mid(&self) -> Float {
        Float::with_val(self.lo.prec(), &self.lo + &self.hi) / 2u32
    }
    /// The bracket width.
    pub fn width(&self) -> Float {
        Float::with_val(self.lo.prec(), &self.hi - &self.lo)
    }
}

/// Finds a root of `f` in [a, b] (a < b, f(a)·f(b) ≤ 0) to a bracket no wider
/// than `tol` (absolute). `quantity` names the root in errors.
///
/// Errors: [`Error::NoSignChange`] if f(a) and f(b) have the same sign.
pub fn bracket<F>(quantity: &str, a: &Float, b: &Float, tol: &Float, mut f: F) -> Result<Root>
where
    F: FnMut(&Float) -> Float,
{
    let p = a.prec().max(b.prec());
    let mut lo = Float::with_val(p, a);
    let mut hi = Float::with_val(p, b);
    let mut flo = f(&lo);
    let mut fhi = f(&hi);
    let mut evals = 2;
    if flo.is_zero() {
        return Ok(Root {
            hi: lo.clone(),
            lo,
            evals,
        });
    }
    if fhi.is_zero() {
        return Ok(Root {
            lo: hi.clone(),
            hi,
            evals,
        });
    }
    if flo.is_sign_negative() == fhi.is_sign_negative() {
        return Err(Error::NoSignChange {
            quantity: quantity.to_string(),
            lo: lo.to_string_radix(10, Some(20)),
            hi: hi.to_string_radix(10, Some(20)),
        });
    }
    let mut side = 0i32; // which end was kept last: -1 lo, +1 hi
    let mut since_halving = 0u32;
    let mut last_width = Float::with_val(p, &hi - &lo);
    loop {
        crate::cancel::check()?;
        let width = Float::with_val(p, &hi - &lo);
        if width <= *tol {
            return Ok(Root { lo, hi, evals });
        }
        // secant (regula falsi) point, safeguarded into the interior
        let mut x = if since_halving >= 3 {
            since_halving = 0;
            last_width = width.clone();
            Float::with_val(p, &lo + &hi) / 2u32
        } else {
            let denom = Float::with_val(p, &fhi - &flo);
            let step = Float::with_val(p, &fhi * &width) / denom;
            Float::with_val(p, &hi - step)
        };
        let margin = Float::with_val(p, tol / 2u32);
        let lo_m = Float::with_val(p, &lo + &margin);
        let hi_m = Float::with_val(p, &hi - &margin);
        if !x.is_finite() || x < lo_m {
            x = lo_m;
        } else if x > hi_m {
            x = hi_m;
        }
        let fx = f(&x);
        evals += 1;
        if fx.is_zero() {
            return Ok(Root {
                lo: x.clone(),
                hi: x,
                evals,
            });
        }
        if fx.is_sign_negative() == fhi.is_sign_negative() {
            // root in [lo, x]; hi replaced; lo kept
            hi = x;
            fhi = fx;
            if side == -1 {
                // Illinois: halve the retained end's value so it moves next time
                flo /= 2u32;
            }
            side = -1;
        } else {
            lo = x;
            flo = fx;
            if side == 1 {
                fhi /= 2u32;
            }
            side = 1;
        }
        let new_width = Float::with_val(p, &hi - &lo);
        if new_width * 2u32 > last_width {
            since_halving += 1;
        } else {
            since_halving = 0;
            last_width = Float::with_val(p, &hi - &lo);
        }
    }
}

/// Scans [a, b] in `n` equal steps for the first sign change of f and returns
/// the sub-bracket, or `None` if f keeps one sign at all scan points.
pub fn first_sign_change<F>(a: &Float, b: &Float, n: u32, mut f: F) -> Option<(Float, Float)>
where
    F: FnMut(&Float) -> Float,
{
    let p = a.prec();
    let step = Float::with_val(p, b - a) / n;
    let mut x0 = a.clone();
    let mut f0 = f(&x0);
    for i in 1..=n {
        let x1 = if i == n {
            b.clone()
        } else {
            Float::with_val(p, &step * i) + a
        };
        let f1 = f(&x1);
        if f1.is_zero() || f0.is_sign_negative() != f1.is_sign_negative() {
            return Some((x0, x1));
        }
        x0 = x1;
        f0 = f1;
    }
    None
}

/// θ = acos c for c ∈ (−1, 1), at `prec` bits, with an error estimate:
/// Newton steps θ ← θ + (cos θ − c)/sin θ at doubling precision from an `f64`
/// seed (a starting point only), then the residual |cos θ − c|/sin θ at
/// `prec` + 8 bits plus a rounding unit. One `sin_cos` per step: cheaper than
/// MPFR's `acos` (which goes through `atan`) at every precision.
pub fn acos_newton(c: &Float, prec: u32) -> (Float, Float) {
    let pw = prec + 8;
    let mut schedule = vec![pw];
    while *schedule.last().unwrap_or(&pw) > 100 {
        let q = schedule.last().unwrap_or(&pw) / 2 + 4;
        schedule.push(q);
    }
    schedule.reverse();
    // within 2^-8 of ±1 cos θ − c cancels bits (up to half the f64 seed's
    // digits within 2^-26, 25 bits at θ = 4.8·10^-4: 953 of 1117 bits
    // returned), and at c = 1 −
    // 3·10^-16 it is 0, where sin θ = 0 made the first step NaN (a slip onset
    // 2.4·10^-8 after θ0 = 0 was dropped): there θ = 2 asin √((1 ∓ c)/2), from
    // 1 ∓ c exact at c's precision, and every step carries the bits that
    // cos θ − c cancels (−log2(1 ∓ c)), or a step undoes the seed's digits
    if *c == 1u32 {
        return (Float::new(prec), Float::new(prec));
    }
    let cf = c.to_f64();
    let (seed, lost) = if 1.0 - cf.abs() < 1.0 / 256.0 {
        let near_one = cf > 0.0;
        let d = if near_one {
            Float::with_val(c.prec(), 1u32 - c)
        } else {
            Float::with_val(c.prec(), 1u32 + c)
        };
        let d = d.max(&Float::new(c.prec()));
        let lost = d.get_exp().map_or(0, |e| e.unsigned_abs());
        let half = Float::with_val(64, &d / 2u32);
        let a = Float::with_val(64, half.sqrt().asin()) * 2u32;
        let th = if near_one {
            Float::with_val(pw + lost, &a)
        } else {
            Float::with_val(pw + lost, rug::float::Constant::Pi) - a
        };
        (th, lost)
    } else {
        (Float::with_val(pw, cf.clamp(-1.0, 1.0).acos()), 0)
    };
    let mut th = seed;
    let (mut s, mut co, mut t) = (Float::new(pw), Float::new(pw), Float::new(pw));
    let step = |q: u32, th: &mut Float, s: &mut Float, co: &mut Float, t: &mut Float| {
        for x in [&mut *s, &mut *co, &mut *t] {
            x.set_prec(q);
        }
        s.assign(&*th);
        s.sin_cos_mut(co);
        t.assign(&*co - c);
        *t /= &*s;
    };
    for &q in &schedule {
        th.set_prec(q + lost);
        step(q + lost, &mut th, &mut s, &mut co, &mut t);
        th += &t;
    }
    // residual at the final iterate
    step(pw + lost, &mut th, &mut s, &mut co, &mut t);
    let th_out = Float::with_val(prec, &th);
    let mut err = Float::with_val(prec, t.abs_ref());
    err += Float::with_val(prec, th_out.abs_ref()) >> (prec as i32 - 1);
    (th_out, err)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::float::Constant;

    #[test]
    fn finds_pi_over_3_to_full_precision() {
        for prec in [64u32, 333, 3400] {
            let a = Float::with_val(prec, 1u32);
            let b = Float::with_val(prec, 2u32);
            let tol = Float::with_val(prec, 1u32) >> (prec as i32 - 6);
            // cos x − 1/2 has its root at π/3
            let r = bracket("test", &a, &b, &tol, |x| {
                Float::with_val(prec, x.cos_ref()) - 0.5f64
            })
            .unwrap();
            let pi3 = Float::with_val(prec, Constant::Pi) / 3u32;
            assert!(r.lo <= pi3 && pi3 <= r.hi || (r.width() <= tol), "{prec}");
            let err = Float::with_val(prec, r.mid() - &pi3).abs();
            assert!(err <= tol, "prec {prec}: err {}", err.to_f64());
            assert!(r.evals < 60 + prec / 40, "prec {prec}: {} evals", r.evals);
        }
    }

    #[test]
    fn acos_by_newton() {
        for prec in [60u32, 200, 3400] {
            for num in [-9i32, -1, 0, 3, 7] {
                let c = Float::with_val(prec, num) / 10u32;
                let (th, err) = acos_newton(&c, prec);
                let exact = Float::with_val(prec + 20, &c).acos();
                let e = Float::with_val(prec + 20, &th - &exact).abs();
                assert!(e <= err, "prec {prec} c {num}/10");
                assert!(
                    err <= Float::with_val(prec, 1u32) >> (prec as i32 - 4),
                    "prec {prec}"
                );
            }
        }
    }

    #[test]
    fn no_sign_change_is_an_error() {
        let a = Float::with_val(64, 0u32);
        let b = Float::with_val(64, 1u32);
        let tol = Float::with_val(64, 1e-10);
        let e = bracket("q", &a, &b, &tol, |x| Float::with_val(64, x * x) + 1u32).unwrap_err();
        assert!(matches!(e, Error::NoSignChange { .. }));
    }

    #[test]
    fn scan_finds_first_of_several_roots() {
        let a = Float::with_val(64, 0.1);
        let b = Float::with_val(64, 10u32);
        let (lo, hi) =
            first_sign_change(&a, &b, 100, |x| Float::with_val(64, x.sin_ref())).unwrap();
        let pi = std::f64::consts::PI;
        assert!(lo.to_f64() <= pi && pi <= hi.to_f64());
    }
}
#[cfg(test)]
mod near_the_ends {
    /// acos c for c within 10^-14 … 10^-300 of ±1, against MPFR's acos: to
    /// the precision asked (relative to θ, or to π − θ), with an error
    /// bound that holds. The f64 seed was 0 at c = 1 − 3·10^-16 (a NaN
    /// step), and within 2^-26 of 1 the steps at low precision lost the
    /// bits cos θ − c cancels (17 of 20 digits verified for a slip onset
    /// at θ = 2.4·10^-7).
    #[test]
    fn acos_near_plus_and_minus_one_to_full_precision() {
        use rug::Float;
        for prec in [64u32, 100, 250, 1000] {
            for th in [
                "2.4075144508669810881e-7",
                "2.4e-8",
                "1e-150",
                "2e-4",
                "4.8e-4",
                "1e-3",
                "0.01",
                "0.05",
            ] {
                let th = Float::with_val(prec + 1200, Float::parse(th).unwrap());
                for far in [false, true] {
                    let x = if far {
                        Float::with_val(prec + 1200, rug::float::Constant::Pi) - &th
                    } else {
                        th.clone()
                    };
                    let c = Float::with_val(prec + 1200, x.cos_ref());
                    let (a, e) = super::acos_newton(&c, prec);
                    let want = Float::with_val(prec + 1200, c.acos_ref());
                    let diff = Float::with_val(prec + 1200, &a - &want).abs();
                    assert!(diff <= e, "{prec} {far}: {diff} > {e}");
                    let unit = Float::with_val(64, &want) >> (prec as i32 - 4);
                    assert!(e <= unit, "{prec} {far}: bound {e} against {unit}");
                }
            }
        }
    }
}
