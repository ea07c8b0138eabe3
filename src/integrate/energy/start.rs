//! What holds at the start of a conservative phase: N12 and N1 there
//! decided (exactly where cos θ0 is rational), and the sign just after the
//! start of a polynomial in cos θ whose value there may be 0 or a hair from
//! it (the branch point's, N12's) — decisions made at the bits that resolve
//! them, the same for both runs of a request.

use super::roots::resolve_cap;
use super::{Route, SCAN_PREC};
use crate::error::{Error, Result};
use crate::mechanics::dynamics::{HPoly, N12Poly};
use rug::{Float, Rational};

/// Precision of the roots' isolation (the start's value is first read there).
const ISO: u32 = 64;

/// The refusal of a start that presses by `what` (N12 at the start): so
/// little that the parting lies a hair after it, closer than the search for
/// θs resolves.
fn too_close_to_parting(what: String) -> Error {
    Error::NotConverged {
        quantity: "N12 at the start".into(),
        requested: 0,
        reached: what,
        detail: "the start lies that close to the parting, closer than the search for theta_s \
                 resolves: not computed (move theta0 or thetadot0 off the parting)"
            .into(),
    }
}

impl Route {
    /// N12 and N1 at the start decided, and the start refused where the
    /// cylinders already part, cylinder 1 already lifts, or the start lies
    /// at or too close to the parting to compute; [`Route::n12_start`] set.
    ///
    /// Errors: those refusals.
    pub(super) fn check_start(&mut self) -> Result<()> {
        // N12 and N1 at the start, at a precision that resolves their
        // signs: a force within its terms' rounding is computed again at
        // twice the bits (a heavy upper cylinder on a light one on a
        // frictionless floor: N12 is of the order of m1 g, its terms of
        // m2 g — at m2 = 10^30 m1 the rounding at 96 bits gave N12 < 0 and
        // the start was refused as parting at once). The terms: N12 =
        // m2 (g c + ẍ1 s − r θ̇²), N1 = (m1 + m2) g + m2 r (θ̈ s + θ̇² c)
        let pr = self.work.params();
        let (m2, weight) = (pr.m2.clone(), Rational::from(&pr.m1 + &pr.m2) * &pr.g);
        let mut p = SCAN_PREC;
        let (n12, n1, floors) = loop {
            let e = self.engine(p)?;
            let st = e.dynm.state(&Float::new(p));
            let f = e.dynm.forces(&st);
            let g = Float::with_val(p, &e.dynm.r) * &e.dynm.gr;
            let td2 = Float::with_val(p, st.thetadot.square_ref()) * &e.dynm.r;
            let m2 = Float::with_val(p, &m2);
            let floor12 = (Float::with_val(p, st.a[0].abs_ref()) + &g + &td2) * &m2;
            let floor1 = Float::with_val(p, &weight)
                + (Float::with_val(p, st.thetaddot.abs_ref()) * &e.dynm.r + &td2) * &m2;
            let floors = [floor12 >> (p as i32 - 8), floor1 >> (p as i32 - 8)];
            let decided = |x: &Float, fl: &Float| Float::with_val(p, x.abs_ref()) > *fl;
            if (decided(&f.n12, &floors[0]) && decided(&f.n1, &floors[1])) || p >= 16 * SCAN_PREC {
                break (f.n12, f.n1, floors);
            }
            p *= 2;
        };
        if Float::with_val(p, n12.abs_ref()) <= floors[0] {
            // N12 within its rounding at 1536 bits: where cos θ0 is rational
            // (θ0 = 0, π/3) it is decided exactly, and a start exactly at the
            // parting (θ0 = 0 with r θ̇0² = g, for one) by N12's sign just
            // after it (its fall as c leaves c0): falling, the cylinders part
            // at once. The mode test read the rounding of 0 and called such a
            // start a Painlevé inconsistency. A start 10^-470 short of the
            // parting is not at it (its exact N12 > 0): refused as too close
            let hp = self.n12_hpoly();
            let exact = self.exact_start_value(&hp);
            if let Some(v) = exact.as_ref().filter(|v| **v != 0) {
                // not 0, exactly: past the parting by a hair, or short of it
                if *v < 0 {
                    return Err(Error::not_physical(
                        "the cylinders part at once: N12 < 0 at the start, exactly (within its \
                         rounding at 1536 bits: the start lies a hair past the parting)",
                    ));
                }
                return Err(too_close_to_parting(
                    "> 0 exactly, within its rounding at 1536 bits".into(),
                ));
            }
            if exact.is_some() {
                match self.sign_after_start(&hp, p)? {
                    Some(s) if s < 0 => {
                        return Err(Error::not_physical(
                            "the cylinders part at once: N12 = 0 at the start and negative just \
                             after it (the start lies at the parting: theta0, thetadot0 or omega0 \
                             at its limit)",
                        ));
                    }
                    Some(_) => {
                        return Err(Error::NotConverged {
                            quantity: "N12 at the start".into(),
                            requested: 0,
                            reached: "0 exactly, and rising after it".into(),
                            detail: "the start lies exactly at the parting (N12 = 0 there and \
                                     positive just after): such a start is not computed; move \
                                     theta0 or thetadot0 off it"
                                .into(),
                        });
                    }
                    None => {}
                }
            }
        }
        for ((name, x), floor) in [("N12", &n12), ("N1", &n1)].into_iter().zip(&floors) {
            if Float::with_val(p, x.abs_ref()) <= *floor {
                return Err(Error::NotConverged {
                    quantity: format!("{name} at the start"),
                    requested: 0,
                    reached: format!(
                        "0 to within its rounding at {p} bits (|{name}| <= {})",
                        crate::numeric::decimal::short(floor)
                    ),
                    detail: "whether the start holds cannot be decided (a start at the \
                             parting, or masses of very different orders)"
                        .into(),
                });
            }
        }
        if n12.is_sign_negative() {
            return Err(Error::not_physical(format!(
                "the cylinders part at once: N12 = {} <= 0 at the start (the start lies past \
                 the parting: theta0, thetadot0 or omega0 too large)",
                crate::numeric::decimal::to_sig(&n12, 4)
            )));
        }
        if n1.is_sign_negative() {
            return Err(Error::not_physical(format!(
                "cylinder 1 lifts off the floor at once: N1 = {} <= 0 at the start",
                crate::numeric::decimal::to_sig(&n1, 4)
            )));
        }
        let pr = self.work.params();
        let m2g = Float::with_val(64, Rational::from(&pr.m2 * &pr.g));
        self.n12_start = Float::with_val(64, &n12 / &m2g);
        // a start that presses, but by less than 2^-80 of the lighter
        // cylinder's weight: the parting lies a hair after it (θs ~ 10^-50
        // after θ0 = 0 at N12 = 2·10^-100 m2 g), closer than the scan for θs
        // at 96 bits resolves — `forces` answered an angle before θs as the
        // state at a θs found before it. Not computed
        let light = Float::with_val(64, pr.m1.clone().min(pr.m2.clone()) * &pr.g);
        if Float::with_val(64, &n12 / &light) < Float::with_val(64, 1u32) >> (SCAN_PREC - 16) {
            return Err(too_close_to_parting(format!(
                "{} m2 g > 0, below 2^-{} of the lighter cylinder's weight",
                crate::numeric::decimal::short_near(&self.n12_start),
                SCAN_PREC - 16
            )));
        }
        Ok(())
    }

    /// cos θ0 exactly where it is rational (working frame, 0 ≤ θ0 < π/2:
    /// θ0 = 0 or π/3): there a polynomial's value at the start is decided
    /// exactly, and a start 10^-470 from a root is not taken for one.
    fn exact_c0(&self) -> Option<Rational> {
        let th0 = &self.work.start().theta0;
        if th0.coef == 0 {
            Some(Rational::from(1))
        } else if th0.times_pi && Rational::from(th0.coef.abs_ref()) == Rational::from((1, 3)) {
            Some(Rational::from((1, 2)))
        } else {
            None
        }
    }

    /// `hp` at the start as an exact rational, where cos θ0 is rational
    /// (A_H = K(c0) θ̇0² + 2 (g/r) c0, every term rational).
    pub(super) fn exact_start_value(&self, hp: &HPoly) -> Option<Rational> {
        let c0 = self.exact_c0()?;
        let p = self.work.params();
        let q = &self.red.q;
        let k0 = Rational::from(&q[2] * &c0) + &q[1];
        let k0 = Rational::from(&k0 * &c0) + &q[0];
        let td0 = &self.work.start().thetadot0;
        let a_h = Rational::from(&k0 * td0) * td0
            + Rational::from(&p.g / &p.r()) * &c0 * Rational::from(2);
        let mut v = Rational::new();
        let mut pow = Rational::from(1);
        for part in &hp.parts {
            let mut s = Rational::new();
            for c in part.iter().rev() {
                s *= &c0;
                s += c;
            }
            v += Rational::from(&s * &pow);
            pow *= &a_h;
        }
        Some(v)
    }

    /// The most bits `hp`'s value at the start is resolved with: where cos θ0
    /// is rational and the value not 0, those that resolve its exact value
    /// (whatever its size: at θ0 = 0 a root's θ carries its own digits);
    /// else [`resolve_cap`] of the `digits` and 4 |log2 θ0| more under θ0 <
    /// 1 (a value within its rounding there puts a root within ~2^−(cap/2)
    /// of θ0 in c, θ0 to the digits asked relative to θ0 itself). The same
    /// for both runs of a request.
    pub(super) fn start_cap(&mut self, hp: &HPoly, digits: u32) -> Result<u32> {
        let cap = resolve_cap(digits);
        if let Some(v) = self.exact_start_value(hp) {
            if v == 0 {
                return Ok(cap);
            }
            let d = &self.engine(ISO)?.dynm;
            let size = Self::term_size(hp, &N12Poly::a_h(d), &d.c0);
            let v = Float::with_val(64, &v).abs();
            let need = size.get_exp().unwrap_or(0) - v.get_exp().unwrap_or(0) + 24 + ISO as i32;
            return Ok(cap.max(need.max(0).unsigned_abs()));
        }
        let th0 = self.work.start().theta0.to_float(64);
        let small = match th0.get_exp() {
            Some(e) if e < 0 => 4 * e.unsigned_abs(),
            _ => 0,
        };
        Ok(cap + small)
    }

    /// The sign of `hp` just after a start where its value is 0 (exactly,
    /// or to `cap` bits): that of its fall as c leaves c0 (−hp′(c0)), or
    /// None where that is 0 too.
    ///
    /// Errors: the dynamics at `cap` bits.
    pub fn sign_after_start(&mut self, hp: &HPoly, cap: u32) -> Result<Option<i32>> {
        let dhp = hp.deriv();
        if let Some(d) = self.exact_start_value(&dhp) {
            return Ok((d != 0).then(|| if d > 0 { -1 } else { 1 }));
        }
        Ok(match self.value_resolved(&dhp, None, cap, cap)? {
            (Some(d), _) => Some(if d.is_sign_positive() { -1 } else { 1 }),
            (None, _) => None,
        })
    }

    /// The sign of `hp` just after the start (working frame): +1, −1, or 0
    /// where not decided. Its value at θ0 — exactly where cos θ0 is
    /// rational, else resolved with up to the bits of `start_cap`; where
    /// that value is 0 (exactly, or to that precision: a root at the start to
    /// the digits asked), the sign of its rise as θ leaves θ0 (−hp′(c0): c
    /// falls). A start 10^-20 before the free motion would part had Π(c0)
    /// within 64 bits' rounding: its sign was taken at random and the branch
    /// point was missed.
    ///
    /// Errors: the dynamics at the precisions tried.
    pub fn sign_at_start(&mut self, hp: &HPoly, digits: u32) -> Result<i32> {
        if let Some(v) = self.exact_start_value(hp) {
            if v != 0 {
                return Ok(if v > 0 { 1 } else { -1 });
            }
            return Ok(self.sign_after_start(hp, ISO)?.unwrap_or(0));
        }
        let cap = self.start_cap(hp, digits)?;
        if let (Some(v), _) = self.value_resolved(hp, None, ISO, cap)? {
            return Ok(if v.is_sign_positive() { 1 } else { -1 });
        }
        Ok(self.sign_after_start(hp, cap)?.unwrap_or(0))
    }
}
