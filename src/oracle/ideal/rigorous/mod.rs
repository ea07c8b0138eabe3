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
//! - θ*, the branch point (where parting first becomes lawful while the
//!   cylinders press): the first sign change of the free relative normal
//!   acceleration times K², a polynomial in c like N12·K², enclosed the same
//!   way and proved to come before θs ([`Oracle::rigorous_branch_point`]).
//!
//! Everything else (the integrated friction phases, a start from rest
//! exactly at the top, angles beyond 2π/3 for t) is not enclosed and says
//! so.

mod branch;
mod rows;
mod stick;
mod theta_s;
mod time;

use super::Oracle;
use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::model::{Contact, Floor};
use crate::numeric::interval::Iv;
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
    /// significant digits, rad (from the printed mid) rounded up so that
    /// [mid − rad, mid + rad] as printed still contains the enclosure.
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
        // printed with 2 significant digits rounded up
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
