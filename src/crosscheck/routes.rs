//! The hybrid motion by independent integrators: the spectral route in θ
//! against two time integrators (Gragg–Bulirsch–Stoer extrapolation and
//! Gauss–Legendre collocation), and the energy route of a conservative
//! first phase against the spectral route.

use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::model::{Law, Model, Params, Start};
use crate::motion::{self, Caches, Method, Motion, Request, Until};
use crate::numeric::verify::{precisions, Run};
use rug::Float;

/// One quantity computed by several routes.
#[derive(Debug, Clone)]
pub struct CrossCheck {
    /// Quantity (`event2_t`, `work_s`, …).
    pub name: String,
    /// By the answers' routes (the energy route for a conservative first
    /// phase, the spectral route in the angle after it).
    pub spectral: Float,
    /// By Gragg–Bulirsch–Stoer extrapolation.
    pub gbs: Float,
    /// By Gauss–Legendre collocation.
    pub collocation: Float,
    /// Significant digits on which the answers' route agrees with both
    /// time integrators (relative to max(|v|, 1)): the smaller of the two.
    pub digits: f64,
}

/// The motion of `model` to its end by `method` at `prec` bits.
///
/// Errors: see [`motion::run`].
pub fn motion_by(model: &Model, method: Method, prec: u32, horizon: &Float) -> Result<Motion> {
    let req = Request {
        times: Vec::new(),
        until: Until::End,
        theta_only: false,
        branch: motion::Branch::Stay,
        method,
        horizon: Some(horizon.clone()),
        run: Run::High,
        digits: 0,
        sides: Vec::new(),
        target_side: None,
        low_deltas: Vec::new(),
        derived_at_high: false,
    };
    motion::run(model, &req, prec, &mut Caches::default())
}

fn signature(m: &Motion) -> Vec<String> {
    crate::oracle::ladder::signature(m)
}

/// The values compared: every event's time and angle, the work and θ̇ at
/// separation, and the impact.
pub fn compared_values(m: &Motion) -> Vec<(String, Float)> {
    let mut out = Vec::new();
    for (i, e) in m.events.iter().enumerate() {
        out.push((format!("event{}_t", i + 1), e.at.t.clone()));
        out.push((format!("event{}_theta", i + 1), e.at.theta.clone()));
    }
    if let (Some(s), Some(i)) = (&m.separation, &m.impact) {
        out.push(("work_s".into(), s.work.clone()));
        out.push(("theta_dot_s".into(), s.theta_dot.clone()));
        out.push(("x1_impact".into(), i.x1.clone()));
        out.push(("x2_impact".into(), i.x2.clone()));
        out.push(("x2_dot_impact".into(), i.vx2.clone()));
        out.push(("psi2_dot_impact".into(), i.psi2_dot.clone()));
    }
    out
}

/// Significant digits on which x and y agree, relative to max(|x|, 1).
pub fn agree(x: &Float, y: &Float, prec: u32) -> f64 {
    let d = Float::with_val(prec, x - y).abs();
    let sc = Float::with_val(prec, x.abs_ref()).max(&Float::with_val(prec, 1u32));
    let r = (d / sc).to_f64();
    if r == 0.0 {
        f64::from(prec) * 0.301
    } else {
        -r.log10()
    }
}

/// The three integrators on the same motion at the working precision of
/// `digits`: the event sequences must be identical; every event time and
/// angle and every separation and impact value is compared.
///
/// Errors: from any run; different event sequences; a contact phase that
/// the spectral route declined (it would not be an independent check).
pub fn cross_check(model: &Model, digits: u32) -> Result<Vec<CrossCheck>> {
    let (_, p2) = precisions(digits, 0);
    let h = motion::default_horizon(model);
    let s = motion_by(model, Method::Auto, p2, &h)?;
    let a = motion_by(model, Method::Gbs, p2, &h)?;
    let b = motion_by(model, Method::Collocation, p2, &h)?;
    if s.routes.contains(&motion::Route::Gbs) {
        return Err(Error::NotConverged {
            quantity: "spectral route".into(),
            requested: digits,
            reached: format!("phases integrated by {:?}", s.routes),
            detail: "the spectral route declined a mode".into(),
        });
    }
    for m in [&a, &b] {
        if signature(&s) != signature(m) {
            return Err(Error::NotConverged {
                quantity: "event sequence".into(),
                requested: digits,
                reached: "the integrators disagree on the sequence of phases".into(),
                detail: format!("{} / {}", signature(&s).join(", "), signature(m).join(", ")),
            });
        }
    }
    Ok(compared_values(&s)
        .into_iter()
        .zip(compared_values(&a))
        .zip(compared_values(&b))
        .map(|(((name, x), (_, y)), (_, z))| CrossCheck {
            digits: agree(&x, &y, p2).min(agree(&x, &z, p2)),
            name,
            spectral: x,
            gbs: y,
            collocation: z,
        })
        .collect())
}

/// The built-in friction cases of `cylroll verify`: the main case from
/// θ0 = 1/10 at μ = 0.3, 1 and 10 at both contacts, the floor slipping
/// first, static above kinetic, a heavy upper cylinder whose floor sticks
/// again, a held lower cylinder.
pub fn friction_cases() -> Vec<(String, Model)> {
    let th0 = Exact::rational(rug::Rational::from((1, 10)));
    let law = |s: &str| Law::parse_mu("mu", s).expect("built-in coefficient");
    let with = |p: Params, f: Law, c: Law| {
        Model::new(p, f, c, Start::rest(th0.clone())).expect("built-in model")
    };
    let both = |f: &str, c: &str| with(Params::identical_solid(), law(f), law(c));
    let mut heavy = Params::identical_solid();
    heavy.m2 = rug::Rational::from(3);
    vec![
        ("main_mu_0_3".into(), both("0.3", "0.3")),
        ("main_mu_1".into(), both("1", "1")),
        ("main_mu_10".into(), both("10", "10")),
        ("main_floor_slips".into(), both("0.05", "0.3")),
        ("main_static_kinetic".into(), both("0.5,0.3", "0.5,0.3")),
        (
            "heavy_upper_restick".into(),
            with(heavy, law("0.2"), law("0.4")),
        ),
        (
            "fixed_mu_0_3".into(),
            with(Params::identical_solid(), Law::Held, law("0.3")),
        ),
    ]
}
