//! θ* proved: the branch point of an ideal model, where parting first
//! becomes lawful while the cylinders press on each other.
//!
//! Along the closed motion the free relative normal acceleration times K² is
//! Π(c) = r·H·K − g·c·K² (c = cos θ, H = A_H − 2(g/r)c): a polynomial in c
//! whose coefficients are exact rationals and powers of A_H (an interval).
//! The verified answer decides that Π < 0 at θ0 and that it changes sign
//! before θs (or that Π > 0 at θ0: then θ* = θ0 and t* = 0, proved by
//! Π(cos θ0) > 0 in interval arithmetic); the proof encloses the first sign
//! change exactly as θs is enclosed: Π(c_lo) > 0 > Π(c_hi) at two points
//! around the root (Newton at the working precision from the verified
//! root), and Π < 0 on (c_hi, cos θ0] (the positivity proof of −Π), with
//! c_hi at or below cos θ0's lower end, so by the intermediate value
//! theorem the first zero of Π after θ0 has cos θ* in [c_lo, c_hi]. The
//! enclosure must lie strictly before the proved θs (otherwise the two
//! coincide within the proof and nothing is claimed), and t* follows by the
//! proved quadrature.

use super::theta_s::first_root_below;
use super::{Oracle, Proved};
use crate::error::Result;
use crate::numeric::interval::{not_enclosed, Iv};
use rug::Float;

impl Oracle {
    /// The coefficients of Π(c) (the free normal acceleration times K²) as
    /// intervals at `p` bits (A_H enclosed).
    fn free_normal_interval_coefficients(&mut self, p: u32) -> Vec<Iv> {
        let k = self.consts(p);
        let hp = self.route.free_normal_poly();
        let a_h = k.h0.add(&k.gr.mul(&k.th0.cos()).mul(&Iv::int(p, 2)));
        let n = hp.parts.iter().map(Vec::len).max().unwrap_or(0);
        let mut out = vec![Iv::int(p, 0); n];
        let mut pow = Iv::int(p, 1);
        for part in &hp.parts {
            for (i, q) in part.iter().enumerate() {
                out[i] = out[i].add(&pow.mul_q(q));
            }
            pow = pow.mul(&a_h);
        }
        out
    }

    /// θ* (user's frame) and, when finite, t* proved at `p` bits, given the
    /// verified θ* (`start`, user's frame) and the proved θs.
    ///
    /// Errors: the signs, the negativity before the root or the order
    /// θ* < θs could not be proved at this precision.
    pub fn rigorous_branch_point(
        &mut self,
        start: &Float,
        theta_s: &Iv,
        p: u32,
    ) -> Result<(Proved, std::result::Result<Proved, String>)> {
        let coef = self.free_normal_interval_coefficients(p);
        // positive above the root: the free normal acceleration is negative
        // (the contact presses) from the start down to θ*
        let neg: Vec<Iv> = coef.iter().map(Iv::neg).collect();
        let th0 = self.consts(p).th0.clone();
        let c0 = th0.cos();
        let digits = self.digits;
        if Iv::horner(&coef, &c0).is_positive() {
            // parting lawful from the start, proved (the verified θ* is θ0):
            // θ* = θ0 and t* = 0, exactly
            if th0.hi >= theta_s.abs().lo {
                return Err(not_enclosed(
                    "theta_indeterminate: the order theta* < theta_s could not be proved",
                ));
            }
            return Ok((
                Proved::new("theta_indeterminate", self.odd_iv(th0), digits),
                Ok(Proved::new("t_indeterminate", Iv::int(p, 0), digits)),
            ));
        }
        let c_start = Float::with_val(p, start.clone().abs()).cos();
        let Some(c) = first_root_below(&neg, "theta_indeterminate", &c_start, &c0, p)? else {
            return Err(not_enclosed(
                "theta_indeterminate: the sign change of the free normal acceleration could not be proved",
            ));
        };
        let th = c.acos()?;
        if th.hi >= theta_s.abs().lo {
            return Err(not_enclosed(
                "theta_indeterminate: the order theta* < theta_s could not be proved",
            ));
        }
        let user = self.odd_iv(th);
        let t = if self.route.work.starts_at_equilibrium() {
            Err("t_indeterminate is infinite".to_string())
        } else {
            let w = self.odd_iv(user.clone());
            self.rigorous_time_iv(&w, p).map_err(|e| e.to_string())
        };
        Ok((
            Proved::new("theta_indeterminate", user, digits),
            t.map(|t| Proved::new("t_indeterminate", t, digits)),
        ))
    }
}
