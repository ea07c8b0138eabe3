//! θs proved: the first root of N12·K²/m2, a polynomial in c = cos θ with
//! interval coefficients, enclosed by a proved sign change and proved
//! positivity between it and cos θ0 (a monotone piece, then bisection with
//! interval Horner and its mean-value form); and θs with t_s together.

use super::{Consts, Oracle, Proved};
use crate::error::{Error, Result};
use crate::numeric::interval::{not_enclosed, Iv};
use rug::float::Round;
use rug::Float;

impl Oracle {
    /// θs proved (user's frame) at `p` bits.
    ///
    /// Errors: no enclosure (the signs or the positivity could not be
    /// proved at this precision).
    pub fn rigorous_theta_s(&mut self, p: u32) -> Result<Iv> {
        use crate::numeric::poly;
        // isolation as the verified answer does it (64 bits), then Newton on
        // the midpoints at p bits: only a starting point, the proof follows
        const ISO: u32 = 64;
        let c0_iso = self.route.engine(ISO)?.dynm.c0.clone();
        let coef_iso = self.route.n12_coefficients(ISO)?;
        let roots = poly::sign_change_roots(&coef_iso, &Float::with_val(ISO, -1), &c0_iso);
        let start = roots
            .into_iter()
            .rev()
            .find(|c| *c < c0_iso)
            .ok_or_else(|| {
                Error::not_physical(
                    "N12 stays positive up to theta = pi: the cylinders never separate",
                )
            })?;
        let k = self.consts(p);
        let coef = self.n12_interval_coefficients(&k)?;
        let c0 = k.th0.cos();
        // the start at its own 64 bits: Newton's schedule doubles from the
        // precision the start carries (at p bits it took two steps from a
        // 64-bit root, enough up to ~256 bits; beyond 78 digits the proof
        // fell back to a 1e-12 box around the start: 11 digits proved)
        match first_root_below(&coef, "theta_s", &start, &c0, p)? {
            Some(c) => Ok(self.odd_iv(c.acos()?)),
            None => Err(not_enclosed(
                "theta_s: the sign change of N12 could not be proved",
            )),
        }
    }

    /// The coefficients of N12·K²/m2 as intervals (A_H enclosed).
    pub(super) fn n12_interval_coefficients(&mut self, k: &Consts) -> Result<Vec<Iv>> {
        let poly = self
            .route
            .caches
            .n12_poly
            .get_or_insert_with(|| {
                crate::mechanics::dynamics::N12Poly::new(&self.route.red, self.route.work.params())
            })
            .clone();
        // A_H = K(θ0)θ̇0² + 2(g/r) cos θ0
        let a_h = k.h0.add(&k.gr.mul(&k.th0.cos()).mul(&Iv::int(k.p, 2)));
        let n = poly.base.len().max(poly.per_h.len());
        Ok((0..n)
            .map(|i| {
                let mut v = Iv::int(k.p, 0);
                if let Some(x) = poly.per_h.get(i) {
                    v = a_h.mul_q(x);
                }
                if let Some(x) = poly.base.get(i) {
                    v = v.add_q(x);
                }
                v
            })
            .collect())
    }

    /// θs and, when finite, t_s proved.
    ///
    /// Errors: as [`Oracle::rigorous_theta_s`]; t_s beyond 2π/3 is
    /// returned as `None` with the reason.
    pub fn rigorous_separation(
        &mut self,
        p: u32,
    ) -> Result<(Proved, std::result::Result<Proved, String>)> {
        let th = self.rigorous_theta_s(p)?;
        let ts = if self.route.work.starts_at_equilibrium() {
            Err("t_s is infinite".to_string())
        } else {
            let w = self.odd_iv(th.clone());
            match self.rigorous_time_iv(&w, p) {
                Ok(t) => Ok(Proved::new("t_s", t, self.digits)),
                Err(e) => Err(e.to_string()),
            }
        };
        Ok((Proved::new("theta_s", th, self.digits), ts))
    }
}

/// Proves P > 0 on (a, b] given P(a) > 0 (a ≤ b): P' > 0 on
/// [a, a + δ] (δ = 2^-24·max(1, |a|), interval Horner of P' at 64 bits) makes
/// P increasing there, so P > P(a) > 0 on (a, a + δ]; then P > 0 on
/// [a + δ, b] by [`prove_positive`] at 64 bits, where P is far from 0
/// compared with 64-bit rounding. Both steps use the coefficients rounded
/// outwards, so they hold for the exact ones. Falls back to
/// [`prove_positive`] at full precision if the derivative's sign is not
/// proved.
pub(super) fn positive_above(coef: &[Iv], a: &Float, b: &Float) -> Result<bool> {
    if a > b {
        return Ok(true);
    }
    let p = 64;
    let c64: Vec<Iv> = coef.iter().map(|c| c.outward(p)).collect();
    let deriv: Vec<Iv> = c64
        .iter()
        .enumerate()
        .skip(1)
        .map(|(i, c)| c.mul(&Iv::int(p, i as i64)))
        .collect();
    let scale = if Float::with_val(p, a.abs_ref()) > 1 {
        Float::with_val_round(p, a.abs_ref(), Round::Up).0
    } else {
        Float::with_val(p, 1)
    };
    let delta = scale >> 24u32;
    let a_dn = Float::with_val_round(p, a, Round::Down).0;
    let a_up = Float::with_val_round(p, a, Round::Up).0;
    let end = Float::with_val_round(p, &a_up + &delta, Round::Up).0;
    let end = if &end > b {
        Float::with_val_round(p, b, Round::Up).0
    } else {
        end
    };
    if Iv::horner(&deriv, &Iv::new(a_dn, end.clone())).is_positive() {
        // [a, end] ⊂ the monotone piece (end rounded up)
        if end >= *b {
            return Ok(true);
        }
        let b64 = Float::with_val_round(p, b, Round::Up).0;
        if prove_positive(&c64, &end, &b64)? {
            return Ok(true);
        }
    }
    prove_positive(coef, a, b)
}

/// Proves P > 0 on [a, b] (a ≤ b) by bisection: on each piece, interval
/// Horner or its mean-value form P(m) + P'([piece])·([piece] − m) must be
/// positive.
pub(super) fn prove_positive(coef: &[Iv], a: &Float, b: &Float) -> Result<bool> {
    if a > b {
        return Ok(true);
    }
    let p = coef.first().map_or(64, |c| c.prec());
    let deriv: Vec<Iv> = coef
        .iter()
        .enumerate()
        .skip(1)
        .map(|(i, c)| c.mul(&Iv::int(p, i as i64)))
        .collect();
    let mut stack = vec![(a.clone(), b.clone())];
    let mut pieces = 0usize;
    while let Some((lo, hi)) = stack.pop() {
        pieces += 1;
        if pieces > 20_000 {
            return Ok(false);
        }
        let x = Iv::new(lo.clone(), hi.clone());
        if Iv::horner(coef, &x).is_positive() {
            continue;
        }
        let m = Float::with_val(p, &lo + &hi) / 2u32;
        let mv = Iv::horner(coef, &Iv::point(p, &m))
            .add(&Iv::horner(&deriv, &x).mul(&x.sub(&Iv::point(p, &m))));
        if mv.is_positive() {
            continue;
        }
        if Iv::horner(coef, &Iv::point(p, &m)).hi <= 0 {
            return Ok(false);
        }
        if m <= lo || m >= hi {
            return Ok(false);
        }
        stack.push((lo, m.clone()));
        stack.push((m, hi));
    }
    Ok(true)
}

/// The first root below cos θ0 (enclosed by `c0`) of the interval
/// polynomial `q` in c = cos θ, enclosed: an interval [lo, hi] around the
/// Newton root of the midpoints near `start` (widened fourfold until it
/// works, 24 times at most) with q(lo) < 0 < q(hi) proved, hi ≤ c0's lower
/// end, and q > 0 proved on [hi, c0's upper end] — the root the motion meets
/// first as c falls from cos θ0. Without the order, a Newton root above cos
/// θ0 (a root before the start) passed: the positivity over the reversed
/// range held vacuously. Orient `q` so that it is positive above the root
/// (negate it otherwise). `name` for messages.
///
/// Errors: none of its own (Ok(None): not proved at this precision); those
/// of the positivity proof.
pub(super) fn first_root_below(
    q: &[Iv],
    name: &str,
    start: &Float,
    c0: &Iv,
    p: u32,
) -> Result<Option<Iv>> {
    use crate::numeric::poly;
    let mids: Vec<Float> = q.iter().map(|c| c.mid_rad().0).collect();
    let (c_star, eps0) = poly::refine_root(name, &mids, start, p)
        .unwrap_or_else(|_| (Float::with_val(p, start), Float::with_val(p, 1e-12)));
    let mut eps = Float::with_val(p, eps0 * 4u32);
    let min_eps = Float::with_val(p, 1u32) >> (p as i32 - 8);
    if eps < min_eps {
        eps = min_eps;
    }
    for _ in 0..24 {
        let lo = Float::with_val_round(p, &c_star - &eps, Round::Down).0;
        let hi = Float::with_val_round(p, &c_star + &eps, Round::Up).0;
        let qlo = Iv::horner(q, &Iv::point(p, &lo));
        let qhi = Iv::horner(q, &Iv::point(p, &hi));
        if hi > c0.lo {
            // the box reaches the start: no root after θ0 is enclosed here
            return Ok(None);
        }
        if qlo.is_negative() && qhi.is_positive() && positive_above(q, &hi, &c0.hi)? {
            return Ok(Some(Iv::new(lo, hi)));
        }
        eps <<= 2u32;
    }
    Ok(None)
}
