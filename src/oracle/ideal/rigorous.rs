//! Proved enclosures (`--rigorous`): interval arithmetic with directed
//! rounding ([`crate::numeric::interval`]) on the closed forms of the ideal
//! models.
//!
//! - θs: N12·K²/m2 is a polynomial P(c) in c = cos θ whose coefficients are
//!   exact rationals and A_H (an interval). P(c_hi) > 0 > P(c_lo) at two
//!   points around the root (isolated at 64 bits, refined by Newton at the
//!   working precision), and P > 0 on (c_hi, cos θ0] — P' > 0 on a short
//!   piece [c_hi, c_hi + δ] (so P > P(c_hi) > 0 there), then bisection with
//!   interval Horner and its mean-value form on the rest, both at 64 bits
//!   with the coefficients rounded outwards — so by the intermediate value
//!   theorem the first zero of N12 after θ0 has cos θs in [c_lo, c_hi], and
//!   θs = arccos of it.
//! - forces, θ̇, θ̈ at a given θ: the closed forms of
//!   [`crate::mechanics::dynamics::Dyn`] evaluated in interval arithmetic,
//!   θ̇² = H/K with H = K(θ0)θ̇0² + 4(g/r) sin((θ+θ0)/2) sin((θ−θ0)/2).
//! - t(θ): the half-angle integral written in x = sin u (σ = Δσ x², so
//!   t = factor·∫_0^1 G(x) dx with G built from +, ×, ÷ and one square root:
//!   no trigonometric function at the nodes, `XForm`) by Clenshaw–Curtis
//!   quadrature ([`crate::numeric::ccrig`]: rules cached per (n, precision)).
//!   Theorem (Trefethen, *Approximation Theory and Approximation Practice*,
//!   Thm 8.2): if g is analytic in the open Bernstein ellipse E_ρ of the
//!   interval and |g| ≤ M there, the interpolant p_n in the n + 1 Chebyshev
//!   points satisfies ‖g − p_n‖∞ ≤ 4Mρ^(−n)/(ρ − 1); Clenshaw–Curtis
//!   integrates p_n exactly, so |∫g − Q_n| ≤ (b − a)/2 · 8Mρ^(−n)/(ρ − 1).
//!   Analyticity and M are proved by covering the closed ellipse (its upper
//!   half: the factors have real coefficients) with complex boxes at 64 bits
//!   on which every factor under the square root is bounded away from 0 (no
//!   zero, no pole, hence an analytic branch of the root) and bounding |G|
//!   above; ρ is taken just below the nearest singularity (closed forms in
//!   f64, only a choice: the covering proves), n from the bound; [0, 1] is
//!   split geometrically when a singularity is within 0.01 of x = 0. Nodes,
//!   weights (with an a-priori bound on their rounding) and the sum are
//!   enclosed.
//! - with friction, from a start where both contacts stick: the angle where
//!   sticking ends (the first slip onset, or the contact's abrupt opening)
//!   is the first root of R = μ²Ñ² − (1 − c²)F̃², a polynomial in c = cos θ
//!   built from the rolling model's closed forms; it is isolated like θs
//!   ([`Oracle::rigorous_stick_end`]), and t to it follows by the quadrature.
//!
//! Everything else (the integrated friction phases, a start from rest
//! exactly at the top, angles beyond 2π/3 for t) is not enclosed and says
//! so.

use super::{Oracle, FORCE_KEYS};
use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::mechanics::{PHI1, PSI2, X1};
use crate::model::{Contact, Floor};
use crate::numeric::ccrig;
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
    /// The proved value `name` with enclosure `iv`, showing the digits (up
    /// to `digits`) that every point of `iv` shares.
    pub fn new(name: &str, iv: Iv, digits: u32) -> Proved {
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
        let pr = self.route.work.params();
        let ri = |q: &Rational| Iv::rational(p, q);
        let arr = |a: &[Rational; 3]| [ri(&a[0]), ri(&a[1]), ri(&a[2])];
        let st = self.route.work.start();
        let th0 = Iv::exact(p, &st.theta0);
        let q = arr(&self.route.red.q);
        let c0 = th0.cos();
        let k0 = Iv::horner(&q, &c0);
        let td0 = ri(&st.thetadot0);
        let h0 = k0.mul(&td0.sqr());
        let r = ri(&pr.r());
        Consts {
            p,
            alpha: arr(&self.route.red.alpha),
            beta: arr(&self.route.red.beta),
            gamma: arr(&self.route.red.gamma),
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
            floor: self.route.work.floor(),
            contact: self.route.work.contact(),
        }
    }

    fn odd_iv(&self, x: Iv) -> Iv {
        if self.route.sign < 0 {
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
        let mids: Vec<Float> = coef.iter().map(|c| c.mid_rad().0).collect();
        let (c_star, eps0) = poly::refine_root("theta_s", &mids, &start, p)
            .unwrap_or_else(|_| (Float::with_val(p, &start), Float::with_val(p, 1e-12)));
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
            if plo.is_negative() && phi.is_positive() && positive_above(&coef, &hi, &c0.hi)? {
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

    /// t(θ) proved for an angle enclosure `th` in the working frame (θ0 < θ
    /// ≤ 2π/3), by Clenshaw–Curtis with the Bernstein-ellipse bound (module
    /// docs).
    ///
    /// Errors: a start from rest exactly at the top; θ beyond 2π/3; an
    /// ellipse on which analyticity could not be proved.
    pub fn rigorous_time_iv(&mut self, th: &Iv, p: u32) -> Result<Iv> {
        let k = self.consts(p);
        if self.route.work.starts_at_equilibrium() {
            return Err(self.route.infinite_time_error("the time"));
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
        let ig = XForm {
            s0,
            dsig: dsig.clone(),
            q: k.q.clone(),
            h0r,
            from_rest: k.from_rest,
        };
        // where the integrand of x is singular: x² = sin²u at the singular
        // points of the half-angle form (an f64 estimate; the covering proves)
        let x2_sing = {
            let e = self.route.engine(64)?;
            let ds = Float::with_val(64, &dsig.lo);
            e.half_singular_sin2(&ds)
        };
        let x_sing: Vec<(f64, f64)> = x2_sing
            .iter()
            .flat_map(|w| {
                let r = w.sqrt();
                [(r.re, r.im), (-r.re, -r.im)]
            })
            .filter(|(a, b)| a.is_finite() && b.is_finite())
            .collect();
        let lo64 = ig.at_bits(64);
        let integral = integrate_x(&ig, &lo64, &x_sing, p)?;
        // t = factor · ∫_0^1 G dx, factor = 2√Δσ/√(g/r) (from rest) or 2Δσ/√(g/r)
        let f = if k.from_rest { dsig.sqrt()? } else { dsig };
        let factor = f.mul(&Iv::int(p, 2)).div(&k.gr.sqrt()?)?;
        Ok(integral.mul(&factor))
    }
}

/// ∫_0^1 G(x) dx enclosed: [0, 1] split where a singularity is close to 0
/// (geometric pieces [0, h], [h, 2h], [2h, 4h], …), each piece by
/// Clenshaw–Curtis with the ellipse bound ([`crate::numeric::ccrig`]).
fn integrate_x(ig: &XForm, lo64: &XForm, x_sing: &[(f64, f64)], p: u32) -> Result<Iv> {
    // the nearest singularity's distance from 0 sets the first piece
    let dist0 = x_sing
        .iter()
        .map(|(a, b)| a.hypot(*b))
        .fold(f64::INFINITY, f64::min);
    let mut cuts: Vec<Rational> = vec![Rational::from(1)];
    if dist0 < 0.01 {
        // pieces [2^-(k+1), 2^-k] down to about the distance, then [0, 2^-K]
        let mut e = 1i64;
        while (0.5f64).powi(e as i32) > 2.0 * dist0 && e < 60 {
            cuts.push(Rational::from((1, 1i64 << e)));
            e += 1;
        }
    }
    cuts.push(Rational::from(0));
    cuts.reverse();
    let mut total = Iv::int(p, 0);
    for w in cuts.windows(2) {
        total = total.add(&integrate_piece(ig, lo64, x_sing, &w[0], &w[1], p)?);
    }
    Ok(total)
}

/// ∫_a^b G(x) dx enclosed by Clenshaw–Curtis: ρ below the nearest
/// singularity (f64 estimate), M proved on E_ρ by the box covering, n from
/// the bound for about p + 8 bits relative to the integral, then
/// Q_n ± h·8Mρ^(−n)/(ρ − 1).
fn integrate_piece(
    ig: &XForm,
    lo64: &XForm,
    x_sing: &[(f64, f64)],
    a: &Rational,
    b: &Rational,
    p: u32,
) -> Result<Iv> {
    let (af, bf) = (a.to_f64(), b.to_f64());
    let (mf, hf) = ((af + bf) / 2.0, (bf - af) / 2.0);
    let rho_max = x_sing
        .iter()
        .map(|(re, im)| ccrig::rho_through((re - mf) / hf, im / hf))
        .filter(|r| r.is_finite())
        .fold(f64::INFINITY, f64::min)
        .min(60.0);
    // the integral's size: h·2·G(m), for the relative tolerance
    let mid64 = Iv::rational(64, &(Rational::from(a + b) / 2u32));
    let g_mid = lo64
        .eval(&mid64)
        .map(|v| v.lo.to_f64())
        .unwrap_or(1e-3)
        .max(1e-300);
    // the tolerance 2^-(p+8) relative to the integral, as a log2
    let tol_log2 = p as f64 + 8.0 - (2.0 * hf * g_mid).log2();
    let (a64, b64) = (Iv::rational(64, a), Iv::rational(64, b));
    let half = Iv::rational(64, &Rational::from((1, 2)));
    let (m64, h64) = (a64.add(&b64).mul(&half), b64.sub(&a64).mul(&half));
    let mut best: Option<(f64, Float, usize)> = None;
    for frac in [0.95, 0.85, 0.7, 0.5, 0.3, 0.15] {
        let rho = 1.0 + (rho_max - 1.0) * frac;
        if rho <= 1.0 + 1e-6 || !rho.is_finite() {
            break;
        }
        let Some(m) = ccrig::ellipse_max(rho, |z| {
            // x = m + h z
            let x = Cx {
                re: z.re.mul(&h64).add(&m64),
                im: z.im.mul(&h64),
            };
            lo64.abs_bound(&x)
        }) else {
            continue;
        };
        let n = ccrig::n_for(hf, m.to_f64(), rho, tol_log2);
        if best.as_ref().is_none_or(|b| n < b.2) {
            best = Some((rho, m, n));
        } else {
            // a smaller ρ needing more points: the best is found
            break;
        }
        if p < 600 {
            // low precision: the first proved ellipse is near enough
            break;
        }
    }
    let (rho, m, n) = best.ok_or_else(|| {
        not_enclosed("t(theta): analyticity of the integrand on an ellipse could not be proved")
    })?;
    if n > 8 * p as usize + 64 {
        return Err(not_enclosed(
            "t(theta): too many quadrature points for the bound",
        ));
    }
    let rule = ccrig::rule(ccrig::round_n(n), p);
    let (ai, bi) = (Iv::rational(p, a), Iv::rational(p, b));
    let q = rule.apply(&ai, &bi, |x| ig.eval(x))?;
    let h_hi = Float::with_val_round(64, &h64.hi, Round::Up).0;
    let bound = ccrig::truncation_bound(&h_hi, &m, rho, rule.n);
    let bound = Float::with_val_round(p, &bound, Round::Up).0;
    Ok(q.add(&Iv::new(Float::with_val(p, -&bound), bound)))
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
        // φ2(0) = 0 for every contact model (README, "Conventions")
        let psi0 = k.th0.neg();
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

    /// t(θ) proved for an angle enclosure in the user's frame (see
    /// [`Oracle::rigorous_time_iv`]; the enclosure holds for every θ in it).
    ///
    /// Errors: as [`Oracle::rigorous_time_iv`].
    pub fn rigorous_time_user(&mut self, th: &Iv, p: u32) -> Result<Iv> {
        let w = self.odd_iv(th.clone());
        self.rigorous_time_iv(&w, p)
    }

    /// The time to the exact angle θ, proved.
    ///
    /// Errors: as [`Oracle::rigorous_time_iv`]; θ outside the motion.
    pub fn rigorous_time(&mut self, theta: &Exact, p: u32) -> Result<Proved> {
        // inside the motion (decided as the verified answer decides it, at
        // the scan's precision; the verified time itself is not needed)
        if self.route.work.starts_at_equilibrium() {
            return Err(self.route.infinite_time_error("the time to any angle"));
        }
        self.route.delta_of("to", theta, 64)?;
        let th = Iv::exact(p, &self.route.to_work(theta));
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

/// The half-angle integrand in x = sin u (σ = Δσ x², s = sin(θ/2) = s0 + σ,
/// c = cos θ = 1 − 2s²): ∫_0^{π/2} g(u) du = ∫_0^1 G(x) dx with
/// G = √(K(c)/((1 − s²)(s + s0))) from rest and
/// G = x·√(K(c)/((1 − s²)(σ(s + s0) + h0r))) otherwise — no trigonometric
/// function at the nodes, and G is analytic wherever the factors under the
/// root do not vanish (their zeros are the singularities of
/// [`crate::mechanics::dynamics::HalfAngleTime::singular_sin2`], x² = sin²u).
struct XForm {
    s0: Iv,
    dsig: Iv,
    q: [Iv; 3],
    h0r: Iv,
    from_rest: bool,
}

impl XForm {
    /// The same integrand with every constant rounded outwards to `p` bits.
    fn at_bits(&self, p: u32) -> XForm {
        XForm {
            s0: self.s0.outward(p),
            dsig: self.dsig.outward(p),
            q: [
                self.q[0].outward(p),
                self.q[1].outward(p),
                self.q[2].outward(p),
            ],
            h0r: self.h0r.outward(p),
            from_rest: self.from_rest,
        }
    }

    /// G(x) for a real interval x.
    fn eval(&self, x: &Iv) -> Result<Iv> {
        let p = x.prec();
        let sig = self.dsig.mul(&x.sqr());
        let s = self.s0.add(&sig);
        let s2 = s.sqr();
        let one = Iv::int(p, 1);
        let c = one.sub(&s2.mul(&Iv::int(p, 2)));
        let k = Iv::horner(&self.q, &c);
        let a = one.sub(&s2);
        let b = if self.from_rest {
            s.add(&self.s0)
        } else {
            sig.mul(&s.add(&self.s0)).add(&self.h0r)
        };
        let g = k.div(&a.mul(&b))?.sqrt()?;
        Ok(if self.from_rest { g } else { g.mul(x) })
    }

    /// An upper bound of |G| over the complex box x, or `None` when a factor
    /// under the root may vanish on it (so that no analytic branch is
    /// proved). |G| = √(|K|/(|1 − s²||B|)) (·|x|) for any branch of the root.
    fn abs_bound(&self, x: &Cx) -> Option<Float> {
        let p = x.re.prec();
        let one = Iv::int(p, 1);
        let sig = x.sqr().scale(&self.dsig);
        let s = sig.add_real(&self.s0);
        let s2 = s.sqr();
        let c = s2.scale(&Iv::int(p, -2)).add_real(&one);
        let k = c
            .scale(&self.q[2])
            .add_real(&self.q[1])
            .mul(&c)
            .add_real(&self.q[0]);
        let fa = s2.scale(&Iv::int(p, -1)).add_real(&one);
        let fb = if self.from_rest {
            s.add_real(&self.s0)
        } else {
            sig.mul(&s.add_real(&self.s0)).add_real(&self.h0r)
        };
        let (klo, alo, blo) = (k.abs_lo(), fa.abs_lo(), fb.abs_lo());
        if klo.is_zero() || alo.is_zero() || blo.is_zero() {
            return None;
        }
        let den = Float::with_val_round(p, &alo * &blo, Round::Down).0;
        let r = Float::with_val_round(p, &k.abs_hi() / &den, Round::Up).0;
        let mut g = Float::with_val_round(p, r.sqrt_ref(), Round::Up).0;
        if !self.from_rest {
            g = Float::with_val_round(p, &g * &x.abs_hi(), Round::Up).0;
        }
        Some(g)
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
fn positive_above(coef: &[Iv], a: &Float, b: &Float) -> Result<bool> {
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
        "proved enclosures cover the ideal models' theta_s, forces and t(theta) up to 2 pi/3, \
         and with friction (separation) where sticking ends; friction phases are verified only",
    )
}

/// Runs a proof at a working precision of the digits asked plus 32 bits,
/// then, if it proves fewer digits than asked (`short` of the result),
/// once more at twice that.
pub fn prove_with<T>(
    digits: u32,
    mut f: impl FnMut(u32) -> Result<T>,
    short: impl Fn(&T) -> bool,
) -> Result<T> {
    let p0 = crate::numeric::bits_for_digits(digits) + 32;
    let first = f(p0)?;
    if !short(&first) {
        return Ok(first);
    }
    f(2 * p0).or(Ok(first))
}

/// Why an enclosure failed, in a few words.
pub fn enclosure_why(e: &Error) -> String {
    match e {
        Error::NotConverged { detail, .. } => detail.clone(),
        other => other.to_string(),
    }
}

/// With friction, from a start where both contacts stick: the angle where
/// sticking ends ([`Oracle::rigorous_stick_end`]) and the time to it, proved.
/// For a first slip onset they are new values `theta_slip_onset` and
/// `t_slip_onset` (the verified event's, renamed); for an abrupt opening of
/// the contact (the first event a separation) they are theta_s and t_s.
/// Returns (index in `values` or None to append, verified value, proof) per
/// value, or why nothing is enclosed.
pub type ProvedSlots = Vec<(Option<usize>, Verified, Option<Proved>)>;

pub fn stick_end_proved(
    model: &crate::model::Model,
    ans: &crate::oracle::Answer,
    digits: u32,
) -> std::result::Result<ProvedSlots, String> {
    use crate::model::{Law, Which};
    use crate::motion::{Branch, Kind, Mode, State};
    let both_stick = Mode {
        floor: State::Stick,
        contact: State::Stick,
    };
    if ans.start_mode != Some(both_stick) {
        return Err(format!(
            "the start mode is {}: only a start where both contacts stick has closed forms",
            ans.start_mode
                .map_or_else(|| "undefined".to_string(), |m| m.to_string())
        ));
    }
    if ans.branch == Branch::Part && ans.events.iter().any(|e| e.kind == Kind::Indeterminate) {
        return Err("on the part branch the closed phase ends at the branch point".into());
    }
    let ev = ans
        .events
        .iter()
        .find(|e| e.kind != Kind::Indeterminate)
        .ok_or("no event")?;
    let floor_first = match (ev.kind, ev.which) {
        (Kind::SlipOnset, Some(w)) => w == Which::Floor,
        (Kind::Separation, Some(Which::Contact)) => false,
        _ => return Err("the first event is neither a slip onset nor the contact opening".into()),
    };
    let mu = |l: &Law| match l {
        Law::Coulomb { mu_s, .. } => Ok(Some(mu_s.clone())),
        Law::Rolling => Ok(None),
        Law::Frictionless | Law::Held => Err("a frictionless or held contact".to_string()),
    };
    let (mf, mc) = (mu(model.floor())?, mu(model.contact())?);
    let mut o = Oracle::new(&model.sticking(), digits).map_err(|e| e.to_string())?;
    let mut th_iv = None;
    let th = prove_with(
        digits,
        |p| {
            let iv =
                o.rigorous_stick_end([mf.as_ref(), mc.as_ref()], floor_first, &ev.theta.value, p)?;
            th_iv = Some(iv.clone());
            Ok(Proved::new("theta", iv, digits))
        },
        |v| v.shown.digits < digits,
    )
    .map_err(|e| enclosure_why(&e))?;
    let th_iv = th_iv.unwrap_or_else(|| th.iv.clone());
    let t = prove_with(
        digits,
        |p| {
            let x = th_iv.outward(p.min(th_iv.prec()));
            let x = crate::numeric::interval::Iv::new(
                rug::Float::with_val(p, &x.lo),
                rug::Float::with_val(p, &x.hi),
            );
            o.rigorous_time_user(&x, p)
                .map(|iv| Proved::new("t", iv, digits))
        },
        |v| v.shown.digits < digits,
    )
    .ok();
    let find = |name: &str| ans.values.iter().position(|v| v.name == name);
    let renamed = |v: &Verified, name: &str| {
        let mut v = v.clone();
        v.name = name.into();
        v
    };
    let with_name = |p: Option<Proved>, name: &str| {
        p.map(|mut p| {
            p.name = name.into();
            p.shown.name = name.into();
            p
        })
    };
    Ok(if ev.kind == Kind::SlipOnset {
        vec![
            (
                None,
                renamed(&ev.theta, "theta_slip_onset"),
                with_name(Some(th), "theta_slip_onset"),
            ),
            (
                None,
                renamed(&ev.t, "t_slip_onset"),
                with_name(t, "t_slip_onset"),
            ),
        ]
    } else {
        vec![
            (
                find("theta_s"),
                renamed(&ev.theta, "theta_s"),
                with_name(Some(th), "theta_s"),
            ),
            (find("t_s"), renamed(&ev.t, "t_s"), with_name(t, "t_s")),
        ]
    })
}
