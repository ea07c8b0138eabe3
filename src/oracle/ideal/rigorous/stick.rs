//! With friction, from a start where both contacts stick: the angle where
//! sticking ends, proved as the first root of the stick condition
//! R = μ²Ñ² − (1 − c²)F̃², an interval polynomial in c = cos θ built from
//! the rolling model's force polynomials, isolated like θs, with every
//! other condition proved positive up to it.

use super::theta_s::{positive_above, prove_positive};
use super::{Consts, Oracle};
use crate::error::Result;
use crate::model::{Contact, Floor};
use crate::numeric::interval::{not_enclosed, Iv};
use rug::float::Round;
use rug::{Float, Rational};

/// a·b for polynomials with interval coefficients (ascending).
fn pmul(a: &[Iv], b: &[Iv]) -> Vec<Iv> {
    let p = a[0].prec();
    let mut out = vec![Iv::int(p, 0); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] = out[i + j].add(&x.mul(y));
        }
    }
    out
}

/// a + b for polynomials with interval coefficients (ascending).
fn padd(a: &[Iv], b: &[Iv]) -> Vec<Iv> {
    let p = a[0].prec();
    (0..a.len().max(b.len()))
        .map(|i| {
            let z = Iv::int(p, 0);
            a.get(i).unwrap_or(&z).add(b.get(i).unwrap_or(&z))
        })
        .collect()
}

/// x·a for a polynomial a.
fn pscale(a: &[Iv], x: &Iv) -> Vec<Iv> {
    a.iter().map(|c| c.mul(x)).collect()
}

impl Oracle {
    /// The numerators of the tangential and normal force at the floor
    /// (`floor` true) or the contact, in the rolling phase, as interval
    /// polynomials in c = cos θ: F = sin θ·F̃(c)/K², N = Ñ(c)/K², from the
    /// exact polynomials of [`crate::mechanics::dynamics::ForcePolys`] and
    /// [`crate::mechanics::dynamics::N12Poly`] (P0 + A_H·P1, A_H enclosed).
    fn contact_polys(&mut self, k: &Consts, floor: bool) -> Result<(Vec<Iv>, Vec<Iv>)> {
        let a_h = k.h0.add(&k.gr.mul(&k.th0.cos()).mul(&Iv::int(k.p, 2)));
        let split = |(p0, p1): &(Vec<Rational>, Vec<Rational>)| -> Vec<Iv> {
            (0..p0.len().max(p1.len()).max(1))
                .map(|i| {
                    let mut v = Iv::int(k.p, 0);
                    if let Some(x) = p1.get(i) {
                        v = a_h.mul_q(x);
                    }
                    if let Some(x) = p0.get(i) {
                        v = v.add_q(x);
                    }
                    v
                })
                .collect()
        };
        let fp = self.route.force_polys();
        if floor {
            Ok((split(&fp.f1), split(&fp.n1)))
        } else {
            let n12 = self.n12_interval_coefficients(k)?;
            Ok((split(&fp.f21), pscale(&n12, &k.m2)))
        }
    }

    /// The stick condition of one contact as a polynomial in c = cos θ:
    /// R = μ²Ñ² − (1 − c²)F̃², so that (with Ñ > 0 and sin θ ≥ 0)
    /// |F| ≤ μN ⟺ R ≥ 0.
    fn stick_poly(&mut self, k: &Consts, floor: bool, mu: &Rational) -> Result<Vec<Iv>> {
        let p = k.p;
        let (ft, nt) = self.contact_polys(k, floor)?;
        let mu2 = Iv::rational(p, &Rational::from(mu * mu));
        let one_m_c2 = vec![Iv::int(p, 1), Iv::int(p, 0), Iv::int(p, -1)];
        Ok(padd(
            &pscale(&pmul(&nt, &nt), &mu2),
            &pscale(&pmul(&one_m_c2, &pmul(&ft, &ft)), &Iv::int(p, -1)),
        ))
    }

    /// The angle where a motion that starts with both contacts sticking
    /// (rolling) stops sticking — the first slip onset, or the contact's
    /// abrupt opening where |F21| reaches μN12 but no slipping mode is
    /// consistent — proved (user's frame), at `p` bits.
    ///
    /// While both contacts stick, the motion is the ideal rolling model's:
    /// θ̇² = H/K > 0 past the start (H = A_H − 2(g/r)c decreases in c and
    /// A_H ≥ 2(g/r) cos θ0), and the forces are the closed forms
    /// F = sin θ·F̃(c)/K², N = Ñ(c)/K² (`Oracle::contact_polys`); with
    /// sin θ ≥ 0 and Ñ > 0, |F| ≤ μN ⟺ R = μ²Ñ² − (1 − c²)F̃² ≥ 0, a
    /// polynomial in c. `mu` holds μs at the floor and at the contact (None:
    /// that contact never slips); `floor_first` says which contact's
    /// condition fails first (from the verified answer, as `theta_guess`,
    /// the verified angle).
    ///
    /// Theorem (intermediate value): if R_w(c_lo) < 0 < R_w(c_hi) for that
    /// contact w, R_w > 0 on (c_hi, cos θ0], and the other contact's R and
    /// Ñ1, Ñ12 are > 0 on [c_lo, cos θ0], then both contacts stick with
    /// N1, N12 > 0 up to θ = arccos c_hi, and sticking ends at w at some θ
    /// in [arccos c_hi, arccos c_lo] (the first zero of R_w).
    ///
    /// Errors: a model that is not the rolling one, a start that does not
    /// stick, or a proof that fails at this precision.
    pub fn rigorous_stick_end(
        &mut self,
        mu: [Option<&Rational>; 2],
        floor_first: bool,
        theta_guess: &Float,
        p: u32,
    ) -> Result<Iv> {
        use crate::numeric::poly;
        if self.route.work.floor() != Floor::Roll || self.route.work.contact() != Contact::Roll {
            return Err(not_enclosed(
                "stick end: the sticking phase must be the rolling model",
            ));
        }
        let Some(mu_w) = mu[if floor_first { 0 } else { 1 }] else {
            return Err(not_enclosed("stick end: that contact never slips"));
        };
        let k = self.consts(p);
        let r_w = self.stick_poly(&k, floor_first, mu_w)?;
        let c0 = k.th0.cos();
        let mids: Vec<Float> = r_w.iter().map(|c| c.mid_rad().0).collect();
        let guess = Float::with_val(p, self.route.odd(theta_guess.clone()).cos_ref());
        let (c_star, eps0) = poly::refine_root("stick end", &mids, &guess, p)?;
        let mut eps = Float::with_val(p, eps0 * 4u32);
        let min_eps = Float::with_val(p, 1u32) >> (p as i32 - 8);
        if eps < min_eps {
            eps = min_eps;
        }
        // the other conditions hold on [c_lo, c0], at 64 bits
        let mut others: Vec<Vec<Iv>> = vec![
            self.contact_polys(&k, true)?.1,
            self.contact_polys(&k, false)?.1,
        ];
        if let Some(mu_o) = mu[if floor_first { 1 } else { 0 }] {
            others.push(self.stick_poly(&k, !floor_first, mu_o)?);
        }
        let others: Vec<Vec<Iv>> = others
            .iter()
            .map(|c| c.iter().map(|x| x.outward(64)).collect())
            .collect();
        for _ in 0..24 {
            let lo = Float::with_val_round(p, &c_star - &eps, Round::Down).0;
            let hi = Float::with_val_round(p, &c_star + &eps, Round::Up).0;
            let plo = Iv::horner(&r_w, &Iv::point(p, &lo));
            let phi = Iv::horner(&r_w, &Iv::point(p, &hi));
            if plo.is_negative() && phi.is_positive() && positive_above(&r_w, &hi, &c0.hi)? {
                let lo64 = Float::with_val_round(64, &lo, Round::Down).0;
                let c0_64 = Float::with_val_round(64, &c0.hi, Round::Up).0;
                for o in &others {
                    if !prove_positive(o, &lo64, &c0_64)? {
                        return Err(not_enclosed(
                            "stick end: another event may come first (not proved)",
                        ));
                    }
                }
                let th = Iv::new(lo, hi).acos()?;
                return Ok(self.odd_iv(th));
            }
            eps <<= 2u32;
        }
        Err(not_enclosed(
            "stick end: the sign change of the stick condition could not be proved",
        ))
    }
}
