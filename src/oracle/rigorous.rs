//! Proved enclosures (`--rigorous`): interval arithmetic with directed
//! rounding ([`crate::numeric::interval`]) on the closed forms of the ideal
//! models.
//!
//! - θs: N12·K²/m2 is a polynomial P(c) in c = cos θ whose coefficients are
//!   exact rationals and A_H (an interval). P(c_hi) > 0 > P(c_lo) at two
//!   points around the verified root, and P > 0 on [c_hi, cos θ0] (proved by
//!   bisection with interval Horner and its mean-value form), so by the
//!   intermediate value theorem the first zero of N12 after θ0 has cos θs in
//!   [c_lo, c_hi], and θs = arccos of it.
//! - forces, θ̇, θ̈ at a given θ: the closed forms of
//!   [`crate::mechanics::dynamics::Dyn`] evaluated in interval arithmetic,
//!   θ̇² = H/K with H = K(θ0)θ̇0² + 4(g/r) sin((θ+θ0)/2) sin((θ−θ0)/2).
//! - t(θ): the half-angle integral in u (σ = Δσ sin²u, analytic on
//!   [0, π/2]) by Clenshaw–Curtis quadrature with n + 1 points, which
//!   integrates exactly the polynomial interpolating g in the Chebyshev
//!   points. Theorem (Trefethen, *Approximation Theory and Approximation
//!   Practice*, Thm 8.2): if g is analytic in the open Bernstein ellipse
//!   E_ρ of the interval and |g| ≤ M there, the interpolant p_n satisfies
//!   ‖g − p_n‖∞ ≤ 4Mρ^(−n)/(ρ − 1); so |∫g − Q_n| ≤ (b − a)/2 · 8Mρ^(−n)/(ρ − 1).
//!   Analyticity and M are proved by covering the closed ellipse with complex
//!   boxes on which every factor under the square root is bounded away from
//!   0 (no zero, no pole, hence an analytic branch of the root) and bounding
//!   |g| above; nodes, weights and the sum are enclosed by interval
//!   arithmetic.
//!
//! Everything else (friction, a start from rest exactly at the top, angles
//! beyond 2π/3 for t) is not enclosed and says so.

use super::{Oracle, FORCE_KEYS};
use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::mechanics::{PHI1, PSI2, X1};
use crate::model::{Contact, Floor};
use crate::numeric::interval::{not_enclosed, Cx, Iv};
use crate::numeric::verify::Verified;
use rug::float::Round;
use rug::{Float, Rational};

/// One proved value: the enclosure and the digits it proves.
#[derive(Debug, Clone)]
pub struct Proved {
    /// Quantity name (as the verified key).
    pub name: String,
    /// The enclosure (user's frame).
    pub iv: Iv,
    /// The significant digits every point of the enclosure shares (up to the
    /// digits asked), as a [`Verified`] whose `digits` are the proved ones
    /// and `err_bound` the radius.
    pub shown: Verified,
}

impl Proved {
    fn new(name: &str, iv: Iv, digits: u32) -> Proved {
        let (mid, rad) = iv.mid_rad();
        if iv.lo.is_zero() && iv.hi.is_zero() {
            // exactly 0 (a frictionless contact's force)
            return Proved {
                name: name.to_string(),
                shown: Verified {
                    name: name.to_string(),
                    text: "0".into(),
                    value: mid,
                    digits,
                    err_bound: rad,
                    precs: (iv.prec(), iv.prec()),
                },
                iv,
            };
        }
        let shown = crate::numeric::verify::verified_from(name, mid.clone(), rad.clone(), digits)
            .unwrap_or_else(|_| Verified {
                name: name.to_string(),
                text: "?".into(),
                value: mid,
                digits: 0,
                err_bound: rad,
                precs: (iv.prec(), iv.prec()),
            });
        Proved {
            name: name.to_string(),
            iv,
            shown,
        }
    }
}

impl Proved {
    /// The enclosure as decimal text (mid, rad): mid to `digits` + 5
    /// significant digits, rad rounded up so that [mid − rad, mid + rad] as
    /// printed still contains the enclosure.
    pub fn texts(&self, digits: u32) -> (String, String) {
        let (mid, _) = self.iv.mid_rad();
        let mid_text = crate::numeric::decimal::to_sig(&mid, digits + 5);
        let mid_q = Exact::parse("mid", &mid_text, false)
            .map(|e| e.coef)
            .unwrap_or_default();
        let p = self.iv.prec();
        let lo_q = self.iv.lo.to_rational().unwrap_or_default();
        let hi_q = self.iv.hi.to_rational().unwrap_or_default();
        let a = Rational::from(&hi_q - &mid_q);
        let b = Rational::from(&mid_q - &lo_q);
        let r = if a > b { a } else { b };
        let r = Float::with_val_round(p, &r, Round::Up).0;
        // 2 significant digits rounded to nearest err by < 5%: print 6% more
        let r = Float::with_val_round(p, &r * 1.06f64, Round::Up).0;
        (mid_text, crate::numeric::decimal::short(&r))
    }
}

/// The model's constants as intervals at one precision.
struct Consts {
    p: u32,
    q: [Iv; 3],
    alpha: [Iv; 3],
    beta: [Iv; 3],
    gamma: [Iv; 3],
    gr: Iv,
    g: Iv,
    r: Iv,
    m1: Iv,
    m2: Iv,
    r2: Iv,
    i2: Iv,
    th0: Iv,
    /// K(θ0) θ̇0².
    h0: Iv,
    from_rest: bool,
    floor: Floor,
    contact: Contact,
}

impl Oracle {
    fn consts(&self, p: u32) -> Consts {
        let pr = self.work.params();
        let ri = |q: &Rational| Iv::rational(p, q);
        let arr = |a: &[Rational; 3]| [ri(&a[0]), ri(&a[1]), ri(&a[2])];
        let st = self.work.start();
        let th0 = Iv::exact(p, &st.theta0);
        let q = arr(&self.red.q);
        let c0 = th0.cos();
        let k0 = Iv::horner(&q, &c0);
        let td0 = ri(&st.thetadot0);
        let h0 = k0.mul(&td0.sqr());
        let r = ri(&pr.r());
        Consts {
            p,
            alpha: arr(&self.red.alpha),
            beta: arr(&self.red.beta),
            gamma: arr(&self.red.gamma),
            gr: ri(&Rational::from(&pr.g / &pr.r())),
            g: ri(&pr.g),
            r,
            m1: ri(&pr.m1),
            m2: ri(&pr.m2),
            r2: ri(&pr.r2),
            i2: ri(&(Rational::from(&pr.k2 * &pr.m2) * &pr.r2 * &pr.r2)),
            th0,
            h0,
            from_rest: st.thetadot0 == 0,
            q,
            floor: self.work.floor(),
            contact: self.work.contact(),
        }
    }

    fn odd_iv(&self, x: Iv) -> Iv {
        if self.sign < 0 {
            x.neg()
        } else {
            x
        }
    }

    /// θs proved (user's frame) at `p` bits.
    ///
    /// Errors: no enclosure (the signs or the positivity could not be
    /// proved at this precision).
    pub fn rigorous_theta_s(&mut self, p: u32) -> Result<Iv> {
        let v = self.separation_angle()?;
        let k = self.consts(p);
        let c_star = Float::with_val(p, self.odd(v.value.clone()).cos_ref());
        let coef = self.n12_interval_coefficients(&k)?;
        // the verified root refined at p bits (Newton on the midpoints)
        let mids: Vec<Float> = coef.iter().map(|c| c.mid_rad().0).collect();
        let (c_star, eps0) = crate::numeric::poly::refine_root("theta_s", &mids, &c_star, p)
            .unwrap_or((c_star, Float::with_val(p, &v.err_bound)));
        let c0 = k.th0.cos();
        let mut eps = Float::with_val(p, eps0 * 4u32);
        let min_eps = Float::with_val(p, 1u32) >> (p as i32 - 8);
        if eps < min_eps {
            eps = min_eps;
        }
        for _ in 0..24 {
            let lo = Float::with_val_round(p, &c_star - &eps, Round::Down).0;
            let hi = Float::with_val_round(p, &c_star + &eps, Round::Up).0;
            let plo = Iv::horner(&coef, &Iv::point(p, &lo));
            let phi = Iv::horner(&coef, &Iv::point(p, &hi));
            if plo.is_negative() && phi.is_positive() && prove_positive(&coef, &hi, &c0.hi)? {
                let th = Iv::new(lo, hi).acos()?;
                return Ok(self.odd_iv(th));
            }
            eps <<= 2u32;
        }
        Err(not_enclosed(
            "theta_s: the sign change of N12 could not be proved",
        ))
    }

    /// The coefficients of N12·K²/m2 as intervals (A_H enclosed).
    fn n12_interval_coefficients(&mut self, k: &Consts) -> Result<Vec<Iv>> {
        let poly = self
            .n12_poly
            .get_or_insert_with(|| {
                crate::mechanics::dynamics::N12Poly::new(&self.red, self.work.params())
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
        // inside the motion, as the verified answer decides
        self.forces_at(theta)?;
        let k = self.consts(p);
        let th = Iv::exact(p, &self.to_work(theta));
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

    /// t(θ) proved for an angle enclosure `th` in the working frame (θ0 < θ
    /// ≤ 2π/3), by Clenshaw–Curtis with the Bernstein-ellipse bound (module
    /// docs).
    ///
    /// Errors: a start from rest exactly at the top; θ beyond 2π/3; an
    /// ellipse on which analyticity could not be proved.
    pub fn rigorous_time_iv(&mut self, th: &Iv, p: u32) -> Result<Iv> {
        let k = self.consts(p);
        if self.work.starts_at_equilibrium() {
            return Err(self.infinite_time_error("the time"));
        }
        let two_thirds_pi = Iv::pi(p).mul_q(&Rational::from((2, 3)));
        if th.hi > two_thirds_pi.lo {
            return Err(not_enclosed(
                "t(theta) beyond 2 pi/3 is not enclosed (the half-angle form is used up to there)",
            ));
        }
        let half = Iv::rational(p, &Rational::from((1, 2)));
        let s0 = k.th0.mul(&half).sin();
        // Δσ = sin(θ/2) − sin(θ0/2) = 2 cos((θ+θ0)/4) sin((θ−θ0)/4)
        let quarter = Iv::rational(p, &Rational::from((1, 4)));
        let dsig = th
            .add(&k.th0)
            .mul(&quarter)
            .cos()
            .mul(&th.sub(&k.th0).mul(&quarter).sin())
            .mul(&Iv::int(p, 2));
        if !dsig.is_positive() {
            return Err(not_enclosed("t(theta): the angle is not past theta0"));
        }
        let gr4 = k.gr.mul(&Iv::int(p, 4));
        let h0r = k.h0.div(&gr4)?;
        let ig = Integrand {
            s0: s0.clone(),
            dsig: dsig.clone(),
            q: k.q.clone(),
            h0r: h0r.clone(),
            from_rest: k.from_rest,
        };
        // the ellipse: below the nearest singularity (the verified engine's
        // estimate, f64), then proved by the box covering
        let rho_max = {
            let e = self.engine(64)?;
            let ds = Float::with_val(64, &dsig.lo);
            crate::numeric::gauss::rho_sin2(&e.half_singular_sin2(&ds))
        };
        let rho_max = if rho_max.is_finite() {
            rho_max.min(50.0)
        } else {
            50.0
        };
        let mut last = None;
        for frac in [0.9, 0.75, 0.5, 0.25, 0.1] {
            let rho = 1.0 + (rho_max - 1.0) * frac;
            if rho <= 1.0 + 1e-6 {
                break;
            }
            match ig.bound_on_ellipse(rho) {
                Ok(m) => {
                    last = Some(self.cc_integral(&ig, rho, m, p)?);
                    break;
                }
                Err(e) => {
                    last = None;
                    let _ = e;
                }
            }
        }
        let integral = last.ok_or_else(|| {
            not_enclosed("t(theta): analyticity of the integrand on an ellipse could not be proved")
        })?;
        // t = factor · ∫_0^{π/2} g du, factor = 2√Δσ/√(g/r) (from rest) or 2Δσ/√(g/r)
        let f = if k.from_rest { dsig.sqrt()? } else { dsig };
        let factor = f.mul(&Iv::int(p, 2)).div(&k.gr.sqrt()?)?;
        Ok(integral.mul(&factor))
    }

    /// ∫_0^{π/2} g(u) du by Clenshaw–Curtis with the number of points the
    /// bound 8Mρ^(−n)/(ρ − 1)·(π/4) needs for `p` bits, plus that bound.
    fn cc_integral(&self, ig: &Integrand, rho: f64, m: f64, p: u32) -> Result<Iv> {
        // n from the bound, relative to the integral's size (≥ π/4·min g ~ 1e-3·M)
        let target = (p as f64 + 8.0) * std::f64::consts::LN_2;
        let num = (8.0 * m * std::f64::consts::FRAC_PI_4 / (rho - 1.0)).ln() + target;
        let mut n = (num / rho.ln()).ceil().max(8.0) as usize;
        n += n % 2;
        if n > 8 * p as usize + 64 {
            return Err(not_enclosed(
                "t(theta): too many quadrature points for the bound",
            ));
        }
        let pi = Iv::pi(p);
        // cos(2π m / (2n)) for m = 0..2n: nodes x_j = cos(jπ/n) and the
        // weights' cosines cos(2π kj/n) = table[2 (kj mod n)]
        let table: Vec<Iv> = (0..2 * n)
            .map(|m| pi.mul_q(&Rational::from((m as i64, n as i64))).cos())
            .collect();
        let mut sum = Iv::int(p, 0);
        let quarter_pi = pi.mul_q(&Rational::from((1, 4)));
        // b_k/(4k² − 1), enclosed once
        let coefs: Vec<Iv> = (1..=n / 2)
            .map(|kk| {
                let b = if 2 * kk == n { 1i64 } else { 2 };
                Iv::rational(p, &Rational::from((b, 4 * (kk * kk) as i64 - 1)))
            })
            .collect();
        for j in 0..=n {
            // w_j = (c_j/n)(1 − Σ_{k=1}^{n/2} b_k/(4k²−1) cos(2πkj/n))
            let mut acc = Iv::int(p, 1);
            for (i, coef) in coefs.iter().enumerate() {
                let kk = i + 1;
                let cosv = &table[(2 * ((kk * j) % n)) % (2 * n)];
                acc = acc.sub(&cosv.mul(coef));
            }
            let cj = if j == 0 || j == n { 1i64 } else { 2 };
            let w = acc.mul_q(&Rational::from((cj, n as i64)));
            let x = &table[j]; // cos(jπ/n)
            let u = quarter_pi.mul(&x.add_q(&Rational::from(1)));
            sum = sum.add(&w.mul(&ig.eval(&u)?));
        }
        let integral = sum.mul(&quarter_pi);
        // + the truncation bound (π/4)·8Mρ^(−n)/(ρ−1), rounded up
        let ln_b = (8.0 * m * std::f64::consts::FRAC_PI_4 / (rho - 1.0)).ln() - n as f64 * rho.ln();
        let bound = Float::with_val(p, ln_b * 1.0000001 + 1e-9).exp();
        let b = Iv::new(Float::with_val(p, -&bound), bound);
        Ok(integral.add(&b))
    }
}

impl Oracle {
    /// A trajectory row proved at time `t` (the columns of
    /// [`super::TRAJECTORY_COLUMNS`]): θ(t) is bracketed by two proved
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
            let th_v = Float::with_val(p, self.odd(v.value.clone()));
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
        let pr = self.work.params();
        let psi0 = match self.work.contact() {
            Contact::Roll => k.r.mul(&k.th0).div(&k.r2)?.neg(),
            Contact::Slip => k.th0.neg(),
        };
        let x1 = pos(X1);
        let phi1 = pos(PHI1);
        let phi2 = pos(PSI2).add(&psi0).add(&th);
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
        if !t.times_pi && super::terminating(&t.coef) {
            out[0].shown.text = crate::exact::rational_text(&t.coef);
        }
        Ok(out)
    }

    /// The time to the exact angle θ, proved.
    ///
    /// Errors: as [`Oracle::rigorous_time_iv`]; θ outside the motion.
    pub fn rigorous_time(&mut self, theta: &Exact, p: u32) -> Result<Proved> {
        self.time_at(theta)?;
        let th = Iv::exact(p, &self.to_work(theta));
        let t = self.rigorous_time_iv(&th, p)?;
        Ok(Proved::new("t", t, self.digits))
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
        let ts = if self.work.starts_at_equilibrium() {
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

/// The half-angle integrand in u of [`crate::mechanics::dynamics::HalfAngleTime::eval_u`]
/// over intervals and complex boxes.
struct Integrand {
    s0: Iv,
    dsig: Iv,
    q: [Iv; 3],
    h0r: Iv,
    from_rest: bool,
}

impl Integrand {
    /// g(u) for a real interval u.
    fn eval(&self, u: &Iv) -> Result<Iv> {
        let p = u.prec();
        let (su, cu) = (u.sin(), u.cos());
        let sig = self.dsig.mul(&su.sqr());
        let s = self.s0.add(&sig);
        let one = Iv::int(p, 1);
        let c = one.sub(&s.sqr().mul(&Iv::int(p, 2)));
        let k = Iv::horner(&self.q, &c);
        let a = one.sub(&s.sqr());
        let b = if self.from_rest {
            s.add(&self.s0)
        } else {
            sig.mul(&s.add(&self.s0)).add(&self.h0r)
        };
        let g = k.div(&a.mul(&b))?.sqrt()?.mul(&cu);
        Ok(if self.from_rest { g } else { g.mul(&su) })
    }

    /// An upper bound M of |g| on the closed Bernstein ellipse E_ρ of
    /// [0, π/2], after proving that no factor under the root vanishes on it
    /// (a covering by complex boxes, at 64 bits).
    ///
    /// Errors: a box on which a factor may vanish.
    fn bound_on_ellipse(&self, rho: f64) -> Result<f64> {
        let p = 64;
        let iv = |x: &Iv| {
            Iv::new(
                Float::with_val_round(p, &x.lo, Round::Down).0,
                Float::with_val_round(p, &x.hi, Round::Up).0,
            )
        };
        let s0 = Cx::real(iv(&self.s0));
        let dsig = iv(&self.dsig);
        let q: Vec<Cx> = self.q.iter().map(|x| Cx::real(iv(x))).collect();
        let h0r = Cx::real(iv(&self.h0r));
        let a = (rho + 1.0 / rho) / 2.0;
        let b = (rho - 1.0 / rho) / 2.0;
        let (nx, ny) = (64usize, 24usize);
        let quarter_pi = Iv::pi(p).mul_q(&Rational::from((1, 4)));
        let one = Cx::real(Iv::int(p, 1));
        let two = Iv::int(p, 2);
        let mut m = 0.0f64;
        for ix in 0..nx {
            for iy in 0..ny {
                let x0 = -a + 2.0 * a * ix as f64 / nx as f64;
                let x1 = -a + 2.0 * a * (ix + 1) as f64 / nx as f64;
                let y0 = -b + 2.0 * b * iy as f64 / ny as f64;
                let y1 = -b + 2.0 * b * (iy + 1) as f64 / ny as f64;
                // skip boxes wholly outside the ellipse
                let cx = if x0 > 0.0 {
                    x0
                } else if x1 < 0.0 {
                    x1
                } else {
                    0.0
                };
                let cy = if y0 > 0.0 {
                    y0
                } else if y1 < 0.0 {
                    y1
                } else {
                    0.0
                };
                if (cx / a).powi(2) + (cy / b).powi(2) > 1.0 + 1e-9 {
                    continue;
                }
                let zx = Iv::new(
                    Float::with_val_round(p, x0, Round::Down).0,
                    Float::with_val_round(p, x1, Round::Up).0,
                );
                let zy = Iv::new(
                    Float::with_val_round(p, y0, Round::Down).0,
                    Float::with_val_round(p, y1, Round::Up).0,
                );
                // u = π/4 (1 + z)
                let u = Cx {
                    re: zx.add_q(&Rational::from(1)).mul(&quarter_pi),
                    im: zy.mul(&quarter_pi),
                };
                let (su, cu) = (u.sin(), u.cos());
                let sig = su.mul(&su).scale(&dsig);
                let s = s0.add(&sig);
                let s2 = s.mul(&s);
                let c = one.sub(&s2.scale(&two));
                let k = q[0].add(&q[1].mul(&c)).add(&q[2].mul(&c).mul(&c));
                let fa = one.sub(&s2);
                let fb = if self.from_rest {
                    s.add(&s0)
                } else {
                    sig.mul(&s.add(&s0)).add(&h0r)
                };
                let (klo, alo, blo) = (k.abs_lo(), fa.abs_lo(), fb.abs_lo());
                if klo.is_zero() || alo.is_zero() || blo.is_zero() {
                    return Err(not_enclosed(
                        "a factor of the integrand may vanish on the ellipse",
                    ));
                }
                let mut g = k.abs_hi().to_f64_round(Round::Up)
                    / (alo.to_f64_round(Round::Down) * blo.to_f64_round(Round::Down));
                g = g.sqrt() * cu.abs_hi().to_f64_round(Round::Up);
                if !self.from_rest {
                    g *= su.abs_hi().to_f64_round(Round::Up);
                }
                // f64 roundings: a relative margin far above their size
                m = m.max(g * (1.0 + 1e-9));
            }
        }
        if !m.is_finite() {
            return Err(not_enclosed("an unbounded integrand on the ellipse"));
        }
        Ok(m)
    }
}

/// Proves P > 0 on [a, b] (a ≤ b) by bisection: on each piece, interval
/// Horner or its mean-value form P(m) + P'([piece])·([piece] − m) must be
/// positive.
fn prove_positive(coef: &[Iv], a: &Float, b: &Float) -> Result<bool> {
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

/// The error when `--rigorous` meets a model or quantity it cannot enclose.
pub fn unsupported(what: &str) -> Error {
    Error::invalid(
        "rigorous",
        what,
        "proved enclosures cover the ideal models' theta_s, forces and t(theta) up to 2 pi/3; \
         friction phases are verified only",
    )
}
