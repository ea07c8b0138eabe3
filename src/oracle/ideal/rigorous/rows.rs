//! The state, the forces and the trajectory's rows proved: the closed forms
//! of the ideal models in interval arithmetic at an angle enclosure, and a
//! row at a time t from θ(t) bracketed between two proved times.

use super::{Consts, Oracle, Proved};
use crate::error::Result;
use crate::exact::Exact;
use crate::mechanics::{PHI1, PSI2, X1};
use crate::model::{Contact, Floor};
use crate::numeric::interval::{not_enclosed, Iv};
use crate::oracle::ideal::FORCE_KEYS;
use rug::float::Round;
use rug::{Float, Rational};

impl Oracle {
    /// The state and forces at an angle enclosure `th` (working frame):
    /// FORCE_KEYS' quantities in order (work frame), plus θ̇ and positions'
    /// rates for the rows.
    fn rigorous_state(&self, k: &Consts, th: &Iv) -> Result<Vec<Option<Iv>>> {
        let p = k.p;
        let two = Iv::int(p, 2);
        let half = Iv::rational(p, &Rational::from((1, 2)));
        let delta = th.sub(&k.th0);
        let (s, c) = (th.sin(), th.cos());
        // H = h0 + 4 (g/r) sin((θ+θ0)/2) sin(δ/2)
        let sm = th.add(&k.th0).mul(&half).sin();
        let sh = delta.mul(&half).sin();
        let h = k.h0.add(&k.gr.mul(&Iv::int(p, 4)).mul(&sm).mul(&sh));
        let kk = Iv::horner(&k.q, &c);
        let mut td2 = h.div(&kk)?;
        // θ̇² ≥ 0 inside the motion (H ≥ K(θ0)θ̇0² ≥ 0 for θ ≥ θ0): an
        // enclosure reaching below 0 only by its width is cut at 0
        if td2.lo.is_sign_negative() && td2.hi.is_sign_positive() {
            td2.lo = Float::new(p);
        }
        let td = td2.sqrt()?;
        // θ̈ = sin θ ((g/r) + ½ K'(c) θ̇²)/K
        let dk = k.q[1].add(&k.q[2].mul(&c).mul(&two));
        let tdd = s.mul(&k.gr.add(&dk.mul(&td2).mul(&half))).div(&kk)?;
        let lin = |i: usize| k.alpha[i].add(&k.beta[i].mul(&c));
        let acc = |i: usize| lin(i).mul(&tdd).sub(&k.beta[i].mul(&s).mul(&td2));
        let ax = acc(X1);
        let n12 = k.g.mul(&c).add(&ax.mul(&s)).sub(&k.r.mul(&td2)).mul(&k.m2);
        let f21 = match k.contact {
            Contact::Roll => k.i2.mul(&acc(PSI2)).div(&k.r2)?,
            Contact::Slip => Iv::int(p, 0),
        };
        let m12 = k.m1.add(&k.m2);
        let f1 = match k.floor {
            Floor::Slip => Iv::int(p, 0),
            _ => m12
                .mul(&ax)
                .add(&c.mul(&tdd).sub(&s.mul(&td2)).mul(&k.r).mul(&k.m2)),
        };
        let n1 = m12
            .mul(&k.g)
            .sub(&s.mul(&tdd).add(&c.mul(&td2)).mul(&k.r).mul(&k.m2));
        // a ratio whose normal force may be 0 (at θs) has no enclosure
        let mu_floor = if k.floor == Floor::Slip {
            Some(Iv::int(p, 0))
        } else {
            f1.abs().div(&n1).ok()
        };
        let mu_contact = if k.contact == Contact::Slip {
            Some(Iv::int(p, 0))
        } else {
            f21.abs().div(&n12).ok()
        };
        Ok(vec![
            Some(f1),
            Some(n1),
            Some(f21),
            Some(n12),
            Some(td),
            Some(tdd),
            mu_floor,
            mu_contact,
        ])
    }

    /// The quantities of [`Oracle::forces_at`] proved at the exact angle θ.
    ///
    /// Errors: θ outside the motion; an enclosure that cannot be formed (a
    /// normal force whose enclosure contains 0 for its ratio, at θs).
    pub fn rigorous_forces(&mut self, theta: &Exact, p: u32) -> Result<Vec<Option<Proved>>> {
        // inside the motion, as the verified answer decides; an angle past
        // θs, which the verified answer takes as θs to the digits asked, is
        // refused here: the proof is of the angle itself
        self.route.delta_of("theta", theta, 64, 0)?;
        self.forces_at(theta)?;
        let k = self.consts(p);
        let th = Iv::exact(p, &self.route.to_work(theta));
        let vals = self.rigorous_state(&k, &th)?;
        let odd = [true, false, true, false, true, true, false, false];
        Ok(vals
            .into_iter()
            .zip(FORCE_KEYS)
            .zip(odd)
            .map(|((v, name), o)| {
                v.map(|v| {
                    let v = if o { self.odd_iv(v) } else { v };
                    Proved::new(name, v, self.digits)
                })
            })
            .collect())
    }

    /// A trajectory row proved at time `t` (the columns of
    /// [`crate::oracle::ideal::TRAJECTORY_COLUMNS`]): θ(t) is bracketed by two proved
    /// times, t(θ−) < t < t(θ+) around the verified θ (θ increases with t,
    /// so θ(t) ∈ [θ−, θ+]); every column follows from the closed forms over
    /// that interval.
    ///
    /// Errors: as [`Oracle::rigorous_time_iv`]; a bracket that cannot be
    /// proved.
    pub fn rigorous_row(&mut self, t: &Exact, p: u32) -> Result<Vec<Proved>> {
        let k = self.consts(p);
        let tv = Iv::exact(p, t);
        let th = if t.is_zero() {
            k.th0.clone()
        } else {
            let v = self.theta_at_times(std::slice::from_ref(t))?.remove(0);
            let th_v = Float::with_val(p, self.route.odd(v.value.clone()));
            let mut w = Float::with_val(p, &v.err_bound * 4u32)
                + (Float::with_val(p, th_v.abs_ref()) >> (p as i32 - 8));
            let mut found = None;
            for _ in 0..6 {
                let lo = Float::with_val_round(p, &th_v - &w, Round::Down).0;
                let hi = Float::with_val_round(p, &th_v + &w, Round::Up).0;
                let t_lo = self.rigorous_time_iv(&Iv::point(p, &lo), p)?;
                let t_hi = self.rigorous_time_iv(&Iv::point(p, &hi), p)?;
                if t_lo.hi < tv.lo && t_hi.lo > tv.hi {
                    found = Some(Iv::new(lo, hi));
                    break;
                }
                w <<= 4u32;
            }
            found.ok_or_else(|| not_enclosed("theta(t): the bracket could not be proved"))?
        };
        let st: Vec<Iv> = self
            .rigorous_state(&k, &th)?
            .into_iter()
            .take(6)
            .map(|v| v.ok_or_else(|| not_enclosed("a force")))
            .collect::<Result<_>>()?;
        // positions: x_i = γ_i t + α_i δ + β_i (sin θ − sin θ0) (+ψ2(0))
        let delta = th.sub(&k.th0);
        let ds = th.sin().sub(&k.th0.sin());
        let pos = |i: usize| {
            k.gamma[i]
                .mul(&tv)
                .add(&k.alpha[i].mul(&delta))
                .add(&k.beta[i].mul(&ds))
        };
        let pr = self.route.work.params();
        // φ2(0) = 0 for every contact model (README, "Conventions"):
        // ψ0 = −θ0, so φ2 = ψ2 + θ = (ψ2 − ψ0) + δ, the constants cancelled
        // exactly rather than by two interval sums
        let x1 = pos(X1);
        let phi1 = pos(PHI1);
        let phi2 = pos(PSI2).add(&delta);
        let x2 = k.r.mul(&th.sin()).add(&x1);
        let y2 = k.r.mul(&th.cos()).add_q(&pr.r1);
        let cols = [
            ("t", tv, false),
            ("theta", th, true),
            ("theta_dot", st[4].clone(), true),
            ("theta_ddot", st[5].clone(), true),
            ("phi1", phi1, true),
            ("phi2", phi2, true),
            ("x1", x1, true),
            ("x2", x2, true),
            ("y2", y2, false),
            ("F1", st[0].clone(), true),
            ("N1", st[1].clone(), false),
            ("F21", st[2].clone(), true),
            ("N12", st[3].clone(), false),
        ];
        let mut out: Vec<Proved> = cols
            .into_iter()
            .map(|(name, v, odd)| {
                let v = if odd { self.odd_iv(v) } else { v };
                Proved::new(name, v, self.digits)
            })
            .collect();
        // the time is an input: echoed exactly when it is a terminating decimal
        if let Some(text) = t.terminating_text() {
            out[0].shown.text = text;
        }
        Ok(out)
    }
}
