//! Real polynomials on `rug::Float` (coefficients in ascending order): Horner
//! evaluation, the roots with a sign change on an interval (derivative
//! cascade), and Newton refinement at doubling precision with a certified
//! bracket.
//!
//! Used for the separation angle, where N12·K(c)²/m2 is a polynomial of
//! degree ≤ 5 in c = cos θ (see `Dyn::n12_polynomial`): the roots of a
//! polynomial are isolated exactly by the monotone pieces between the roots of
//! its derivative, so no root pair can hide between scan points.
//!
//! Accuracy: the isolation runs at a low precision and is a search only; the
//! refined root comes back as a bracket across which the polynomial, evaluated
//! at the working precision, changes sign (*certified* as far as those signs
//! are right, which the precision ladder checks).

use crate::error::{Error, Result};
use rug::{Assign, Float};

/// p(x) by Horner's rule into `out` (at `out`'s precision).
pub fn horner(coef: &[Float], x: &Float, out: &mut Float) {
    out.assign(0u32);
    for c in coef.iter().rev() {
        *out *= x;
        *out += c;
    }
}

/// p(x) and p'(x) by Horner's rule (at the precision of `v`, `d`).
pub fn horner_d(coef: &[Float], x: &Float, v: &mut Float, d: &mut Float) {
    v.assign(0u32);
    d.assign(0u32);
    for c in coef.iter().rev() {
        *d *= x;
        *d += &*v;
        *v *= x;
        *v += c;
    }
}

/// The coefficients without trailing exact zeros (so the degree is exact).
pub fn trim(mut coef: Vec<Float>) -> Vec<Float> {
    while coef.last().is_some_and(|c| c.is_zero()) {
        coef.pop();
    }
    coef
}

fn derivative(coef: &[Float]) -> Vec<Float> {
    coef.iter()
        .enumerate()
        .skip(1)
        .map(|(k, c)| Float::with_val(c.prec(), c * k as u32))
        .collect()
}

/// Illinois regula falsi on [lo, hi] where p changes sign (p monotone there):
/// to the working precision of `lo`.
fn solve_monotone(coef: &[Float], lo: &Float, hi: &Float) -> Float {
    let p = lo.prec();
    let (mut a, mut b) = (lo.clone(), hi.clone());
    let (mut fa, mut fb) = (Float::new(p), Float::new(p));
    horner(coef, &a, &mut fa);
    horner(coef, &b, &mut fb);
    if fa.is_zero() {
        return a;
    }
    if fb.is_zero() {
        return b;
    }
    let mut x = Float::new(p);
    let mut fx = Float::new(p);
    let mut t = Float::new(p);
    let mut side = 0i32;
    for _ in 0..(4 * p as usize + 40) {
        // x = b − fb (b − a)/(fb − fa)
        t.assign(&b - &a);
        t *= &fb;
        x.assign(&fb - &fa);
        t /= &x;
        x.assign(&b - &t);
        if !(x > a && x < b) {
            x.assign(&a + &b);
            x >>= 1;
            if !(x > a && x < b) {
                break; // a and b are adjacent Floats
            }
        }
        horner(coef, &x, &mut fx);
        if fx.is_zero() {
            return x;
        }
        if fx.is_sign_negative() == fb.is_sign_negative() {
            std::mem::swap(&mut b, &mut x);
            std::mem::swap(&mut fb, &mut fx);
            if side == -1 {
                fa >>= 1;
            }
            side = -1;
        } else {
            std::mem::swap(&mut a, &mut x);
            std::mem::swap(&mut fa, &mut fx);
            if side == 1 {
                fb >>= 1;
            }
            side = 1;
        }
    }
    a += &b;
    a >>= 1;
    a
}

/// The roots of p in [a, b] at which p changes sign, ascending, at the
/// precision of `a` (a search: roots of even multiplicity are skipped, roots
/// closer than that precision resolves may be merged).
pub fn sign_change_roots(coef: &[Float], a: &Float, b: &Float) -> Vec<Float> {
    let coef = trim(coef.to_vec());
    let p = a.prec();
    if coef.len() <= 1 {
        return Vec::new();
    }
    if coef.len() == 2 {
        let x = Float::with_val(p, -&coef[0]) / &coef[1];
        return if x >= *a && x <= *b { vec![x] } else { vec![] };
    }
    let crit = sign_change_roots(&derivative(&coef), a, b);
    let mut pts = Vec::with_capacity(crit.len() + 2);
    pts.push(a.clone());
    pts.extend(crit.into_iter().filter(|x| x > a && x < b));
    pts.push(b.clone());
    let mut vals: Vec<Float> = Vec::with_capacity(pts.len());
    for x in &pts {
        let mut v = Float::new(p);
        horner(&coef, x, &mut v);
        vals.push(v);
    }
    // a sign change across an interval of non-zero ends, or across an
    // interior point where p is exactly 0 (then the neighbours decide)
    let mut roots = Vec::new();
    let mut last_sign: Option<bool> = None; // sign of the last non-zero value
    let mut pending_zero: Option<usize> = None;
    for i in 0..pts.len() {
        let v = &vals[i];
        if v.is_zero() {
            if i > 0 && i + 1 < pts.len() {
                pending_zero = Some(i);
            }
            continue;
        }
        let neg = v.is_sign_negative();
        if let Some(prev) = last_sign {
            if prev != neg {
                match pending_zero {
                    Some(z) => roots.push(pts[z].clone()),
                    None => roots.push(solve_monotone(&coef, &pts[i - 1], &pts[i])),
                }
            }
        }
        pending_zero = None;
        last_sign = Some(neg);
    }
    roots
}

/// A root refined at `prec` bits: `x0` (a simple root found at a lower
/// precision) improved by Newton steps at doubling precisions, then
/// bracketed: returns (x, ε) with p(x − ε) and p(x + ε) of opposite signs at
/// `prec` bits. `coef` must be given at (at least) `prec` bits.
///
/// Errors: [`Error::NoSignChange`] if no bracket of width up to 2^-(prec/2)·|x|
/// shows a sign change (not a simple root, or the coefficients too inexact).
pub fn refine_root(
    quantity: &str,
    coef: &[Float],
    x0: &Float,
    prec: u32,
) -> Result<(Float, Float)> {
    let mut schedule = vec![prec + 8];
    while *schedule.last().unwrap_or(&prec) / 2 > x0.prec().max(32) {
        let q = schedule.last().unwrap_or(&prec) / 2 + 4;
        schedule.push(q);
    }
    schedule.reverse();
    let mut x = Float::with_val(schedule[0], x0);
    let mut v = Float::new(prec + 8);
    let mut d = Float::new(prec + 8);
    // the last precision twice: the second step confirms the first
    schedule.push(prec + 8);
    for &q in &schedule {
        crate::cancel::check()?;
        x.set_prec(q);
        v.set_prec(q);
        d.set_prec(q);
        horner_d(coef, &x, &mut v, &mut d);
        if d.is_zero() || !d.is_finite() {
            break;
        }
        v /= &d;
        x -= &v;
    }
    let x = Float::with_val(prec, &x);
    // bracket: a few ulps, widened until p changes sign across it
    let mut eps = Float::with_val(prec, x.abs_ref()) >> (prec as i32 - 4);
    if eps.is_zero() {
        eps = Float::with_val(prec, 1u32) >> (prec as i32);
    }
    let (mut lo, mut hi) = (Float::new(prec), Float::new(prec));
    let (mut flo, mut fhi) = (Float::new(prec), Float::new(prec));
    for _ in 0..(prec / 2) {
        lo.assign(&x - &eps);
        hi.assign(&x + &eps);
        horner(coef, &lo, &mut flo);
        horner(coef, &hi, &mut fhi);
        if flo.is_zero() || fhi.is_zero() || flo.is_sign_negative() != fhi.is_sign_negative() {
            return Ok((x, eps));
        }
        eps <<= 1;
        if eps > Float::with_val(prec, x.abs_ref()) >> (prec as i32 / 2) {
            break;
        }
    }
    Err(Error::NoSignChange {
        quantity: quantity.to_string(),
        lo: lo.to_string_radix(10, Some(20)),
        hi: hi.to_string_radix(10, Some(20)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn poly(prec: u32, c: &[i64]) -> Vec<Float> {
        c.iter().map(|&v| Float::with_val(prec, v)).collect()
    }

    #[test]
    fn isolates_every_sign_change() {
        // (x − 1/4)(x − 1/3)(x − 1/2)(x² + 1)·24·... : roots 1/4, 1/3, 1/2 ; use
        // 24 (x − 1/4)(x − 1/3)(x − 1/2) = 24x³ − 26x² + 9x − 1
        let c = poly(64, &[-1, 9, -26, 24]);
        let a = Float::with_val(64, -1);
        let b = Float::with_val(64, 1);
        let r = sign_change_roots(&c, &a, &b);
        let want = [0.25, 1.0 / 3.0, 0.5];
        assert_eq!(r.len(), 3, "{r:?}");
        for (x, w) in r.iter().zip(want) {
            assert!((x.to_f64() - w).abs() < 1e-15, "{x} vs {w}");
        }
        // a double root has no sign change: (x − 1/2)² = x² − x + 1/4 → 4x² − 4x + 1
        let c = poly(64, &[1, -4, 4]);
        assert!(sign_change_roots(&c, &a, &b).is_empty());
    }

    #[test]
    fn refines_to_full_precision_with_a_bracket() {
        // x² − 2 on [0, 2]
        for prec in [100u32, 1000, 3400] {
            let c = poly(prec + 8, &[-2, 0, 1]);
            let c64 = poly(64, &[-2, 0, 1]);
            let r = sign_change_roots(&c64, &Float::new(64), &Float::with_val(64, 2));
            assert_eq!(r.len(), 1);
            let (x, eps) = refine_root("sqrt2", &c, &r[0], prec).unwrap();
            let exact = Float::with_val(prec, 2u32).sqrt();
            let err = Float::with_val(prec, &x - &exact).abs();
            assert!(err <= eps, "prec {prec}");
            assert!(
                eps <= Float::with_val(prec, 1u32) >> (prec as i32 - 8),
                "prec {prec}"
            );
        }
    }
}
