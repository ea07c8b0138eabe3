//! t(θ) proved: the half-angle integral in x = sin u ([`XForm`], no
//! trigonometric function at the nodes) by Clenshaw–Curtis quadrature with
//! the Bernstein-ellipse bound, analyticity and the bound M proved by
//! covering the ellipse with complex boxes; [0, 1] split geometrically when
//! a singularity is close to x = 0.

use super::{Oracle, Proved};
use crate::error::Result;
use crate::exact::Exact;
use crate::numeric::ccrig;
use crate::numeric::interval::{not_enclosed, Cx, Iv};
use rug::float::Round;
use rug::{Float, Rational};

impl Oracle {
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
        self.route.delta_of("to", theta, 64, 0)?;
        let th = Iv::exact(p, &self.route.to_work(theta));
        let t = self.rigorous_time_iv(&th, p)?;
        Ok(Proved::new("t", t, self.digits))
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
        crate::cancel::check()?;
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
    crate::cancel::check()?;
    let (ai, bi) = (Iv::rational(p, a), Iv::rational(p, b));
    let q = rule.apply(&ai, &bi, |x| ig.eval(x))?;
    // a cancelled rule or sum is cut short: never returned as a proof
    crate::cancel::check()?;
    let h_hi = Float::with_val_round(64, &h64.hi, Round::Up).0;
    let bound = ccrig::truncation_bound(&h_hi, &m, rho, rule.n);
    let bound = Float::with_val_round(p, &bound, Round::Up).0;
    Ok(q.add(&Iv::new(Float::with_val(p, -&bound), bound)))
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
