//! Verified answers with friction: the motion is computed at two working
//! precisions (each integrating with its own tolerance 2^−(p−8)), the two
//! event sequences (kinds, contacts, modes entered) must be identical, and
//! every number is judged by the precision ladder
//! ([`crate::numeric::verify`]): printed only to the digits that every
//! value within |v(p1) − v(p2)| + err(p2) shares. The energy balance
//! E(0) − E(t) = W(t) is checked along every run.

use super::flight::Surface;
use super::{columns, solve, Friction, Kind, Motion, Point, Which};
use crate::error::{Error, Result};
use crate::exact::{rational_text, Exact};
use crate::model::Model;
use crate::numeric::verify::{ladder_runs, ladder_table, precisions, Estimate, Verified};
use rug::Float;
use std::cell::RefCell;

/// One event with verified time and angle.
#[derive(Debug, Clone)]
pub struct VerifiedEvent {
    /// What happened.
    pub kind: Kind,
    /// The contact concerned (None for the impact).
    pub which: Option<Which>,
    /// The mode entered (`flight` after separation; None at the end).
    pub mode: Option<String>,
    /// Time.
    pub t: Verified,
    /// θ there.
    pub theta: Verified,
}

/// The answer of `separation` with friction.
#[derive(Debug, Clone)]
pub struct SeparationAnswer {
    /// The mode at t = 0 (`floor stick, contact stick` …).
    pub start_mode: String,
    /// The events in time order, the impact last.
    pub events: Vec<VerifiedEvent>,
    /// theta_s, t_s, work_s, then the impact: t_impact, x1, x2, y2 and the
    /// velocities just before it.
    pub values: Vec<Verified>,
    /// What cylinder 2 hits first.
    pub impact_surface: &'static str,
    /// Notes (energy balance, what is outside the model).
    pub notes: Vec<String>,
}

/// The answer of `trajectory` with friction.
#[derive(Debug, Clone)]
pub struct TrajectoryAnswer {
    /// One row per time, in [`columns`] order.
    pub rows: Vec<Vec<Verified>>,
    /// The mode of each row (`stick/slip+`, or `flight`).
    pub modes: Vec<String>,
}

/// Names of the separation values, in order.
pub const SEPARATION_KEYS: [&str; 12] = [
    "theta_s",
    "t_s",
    "work_s",
    "t_impact",
    "x1_impact",
    "x2_impact",
    "y2_impact",
    "x1_dot_impact",
    "phi1_dot_impact",
    "x2_dot_impact",
    "y2_dot_impact",
    "psi2_dot_impact",
];

/// The digits, and times ascending and ≥ 0.
fn check_times(digits: u32, times: &[Exact]) -> Result<()> {
    check_digits(digits)?;
    for w in times.windows(2) {
        if w[1].to_float(256) < w[0].to_float(256) {
            return Err(Error::invalid("times", &w[1], "must be ascending"));
        }
    }
    if let Some(t) = times.iter().find(|t| t.signum() < 0) {
        return Err(Error::invalid("times", t, "must be >= 0"));
    }
    Ok(())
}

fn check_digits(digits: u32) -> Result<()> {
    let max = crate::oracle::MAX_DIGITS;
    if digits == 0 || digits > max {
        return Err(Error::invalid(
            "digits",
            digits,
            format!("must be between 1 and {max}"),
        ));
    }
    Ok(())
}

fn signature(m: &Motion) -> Vec<String> {
    let mut s: Vec<String> = m
        .events
        .iter()
        .map(|e| {
            format!(
                "{} {} -> {}",
                e.kind.name(),
                e.which.map_or("", |w| w.name()),
                e.mode.map_or_else(|| "-".to_string(), |m| m.tag())
            )
        })
        .collect();
    s.push(m.start_mode.tag());
    s.extend(m.rows.iter().map(Point::mode_tag));
    s.extend(
        m.thetas
            .iter()
            .map(|(_, mode)| mode.map_or_else(|| "flight".to_string(), |m| m.tag())),
    );
    s
}

fn one(p: u32) -> Float {
    Float::with_val(p, 1u32)
}

/// An integrated value: its own error estimate is a few units of the
/// integrator's tolerance (the comparison of the two precisions carries
/// the real weight).
fn integrated(v: &Float, scale: Float) -> Estimate {
    let p = v.prec();
    let err = (Float::with_val(p, v.abs_ref()) + &scale) >> (p as i32 - 24);
    Estimate::new(v.clone(), err, scale)
}

fn event_estimates(m: &Motion, out: &mut Vec<Estimate>) {
    for e in &m.events {
        let p = e.at.t.prec();
        let t_err = Float::with_val(p, &e.t_err);
        let mut te = integrated(&e.at.t, one(p));
        te.err += &t_err;
        out.push(te);
        let mut th = integrated(&e.at.theta, one(p));
        th.err += Float::with_val(p, e.at.theta_dot.abs_ref()) * &t_err;
        out.push(th);
    }
}

fn check_balance(m: &Motion, digits: u32) -> Result<()> {
    // E(0) − E(t) = W(t) to well below the printed digits
    let p = m.energy_drift.prec();
    let lim = Float::with_val(p, Float::u_pow_u(10, digits + 2)).recip();
    if m.energy_drift > lim {
        return Err(Error::NotConverged {
            quantity: "energy balance".into(),
            requested: digits,
            reached: format!(
                "|E(0) - E(t) - W(t)| reached {} of m2 g r",
                crate::numeric::decimal::short(&m.energy_drift)
            ),
            detail: "the integration did not keep the energy balance".into(),
        });
    }
    Ok(())
}

/// Runs `solve` at both precisions of each rung, the first run's event
/// sequence fixing the names; the second must match it.
fn laddered<F>(
    digits: u32,
    first: Motion,
    names: &[String],
    rows: usize,
    mut again: F,
    est: impl Fn(&Motion) -> Result<Vec<Estimate>>,
) -> Result<Vec<Vec<Verified>>>
where
    F: FnMut(u32) -> Result<Motion>,
{
    let sig = signature(&first);
    let (p1, _) = precisions(digits, 0);
    let cache = RefCell::new(Some(first));
    let refs: Vec<&str> = names.iter().map(String::as_str).collect();
    let f = |p: u32, _run| -> Result<Vec<Estimate>> {
        let m = match (p == p1, cache.borrow_mut().take()) {
            (true, Some(m)) => m,
            _ => again(p)?,
        };
        if signature(&m) != sig {
            return Err(Error::NotConverged {
                quantity: "event sequence".into(),
                requested: digits,
                reached: "the two working precisions disagree on the sequence of modes".into(),
                detail: format!(
                    "{} bits: {}; {} bits: {}",
                    p1,
                    sig.join(", "),
                    p,
                    signature(&m).join(", ")
                ),
            });
        }
        check_balance(&m, digits)?;
        est(&m)
    };
    if rows == 1 {
        ladder_runs(digits, &refs, f).map(|r| vec![r])
    } else {
        ladder_table(digits, &refs, rows, f)
    }
}

/// Separation with friction: the event list from the start to the first
/// impact, θs and ts, the dissipated work at separation and the state just
/// before the impact.
///
/// Errors: see [`solve`].
pub fn separation(model: &Model, fr: &Friction, digits: u32) -> Result<SeparationAnswer> {
    check_digits(digits)?;
    let (p1, _) = precisions(digits, 0);
    let h64 = super::default_horizon(model);
    let horizon = |p: u32| Float::with_val(p, &h64);
    let first = solve(model, fr, p1, &[], true, &horizon(p1))?;
    if first.separation.is_none() {
        let (t, x2) = first
            .impact
            .as_ref()
            .map_or((f64::NAN, f64::NAN), |i| (i.t.to_f64(), i.x2.to_f64()));
        return Err(Error::not_physical(format!(
            "the cylinders do not part: cylinder 2 reaches the floor at t = {t:.12} (x2 = {x2:.12}) \
             while still touching cylinder 1, an impact the model does not continue through"
        )));
    }
    let mut names = Vec::new();
    for i in 1..=first.events.len() {
        names.push(format!("event{i}_t"));
        names.push(format!("event{i}_theta"));
    }
    names.extend(SEPARATION_KEYS.iter().map(|s| s.to_string()));
    let skel: Vec<(Kind, Option<Which>, Option<String>)> = first
        .events
        .iter()
        .map(|e| {
            (
                e.kind,
                e.which,
                match (e.kind, e.mode) {
                    (Kind::Separation, _) => Some("flight".to_string()),
                    (Kind::Impact, _) | (Kind::LiftOff, _) => None,
                    (_, Some(m)) => Some(m.to_string()),
                    (_, None) => Some("flight".to_string()),
                },
            )
        })
        .collect();
    let start_mode = first.start_mode.to_string();
    let surface = first.impact.as_ref().map_or("none", |i| i.surface.name());
    let drift = crate::numeric::decimal::short(&first.energy_drift);
    let abrupt = first.separation.as_ref().and_then(|sp| {
        let n = sp.n12.to_f64();
        (n.abs() > 1e-12).then(|| {
            format!(
                "the contact opens while N12 = {n:.6e} > 0 in the last closed mode: at that \
                 event no mode with the contact closed is consistent and the free motion \
                 separates, so the normal force drops to 0 at once (the rigid-body model's \
                 one consistent continuation)"
            )
        })
    });
    let n_ev = first.events.len();
    let vals = laddered(
        digits,
        first,
        &names,
        1,
        |p| solve(model, fr, p, &[], true, &horizon(p)),
        |m| {
            let mut out = Vec::new();
            event_estimates(m, &mut out);
            let (Some(sep), Some(imp)) = (m.separation.as_ref(), m.impact.as_ref()) else {
                return Err(Error::not_physical(
                    "the cylinders do not part: cylinder 2 reaches the floor while still on cylinder 1",
                ));
            };
            let p = sep.t.prec();
            out.push(integrated(&sep.theta, one(p)));
            let ev_sep = m
                .events
                .iter()
                .find(|e| e.kind == Kind::Separation)
                .map(|e| e.t_err.clone())
                .unwrap_or_else(|| Float::new(p));
            let mut ts = integrated(&sep.t, one(p));
            ts.err += &ev_sep;
            out.push(ts);
            out.push(integrated(&sep.work, one(p)));
            for v in [
                &imp.t,
                &imp.x1,
                &imp.x2,
                &imp.y2,
                &imp.vx1,
                &imp.phi1_dot,
                &imp.vx2,
                &imp.vy2,
                &imp.psi2_dot,
            ] {
                let mut e = integrated(v, one(p));
                e.err += Float::with_val(p, &ev_sep) * 16u32;
                out.push(e);
            }
            Ok(out)
        },
    )?;
    let mut vals = vals.into_iter().next().unwrap_or_default();
    let rest = vals.split_off(2 * n_ev);
    let mut events = Vec::new();
    for (i, (kind, which, mode)) in skel.into_iter().enumerate() {
        events.push(VerifiedEvent {
            kind,
            which,
            mode,
            t: vals[2 * i].clone(),
            theta: vals[2 * i + 1].clone(),
        });
    }
    let mut notes = vec![
        format!(
            "energy balance E(0) - E(t) = W(t) (W: work of sliding friction) held to {drift} of m2 g r along the motion"
        ),
        "the impact ends the model: impact laws are outside it".to_string(),
    ];
    notes.extend(abrupt);
    if surface == Surface::Cylinder.name() {
        notes.push("cylinder 2 touches cylinder 1 again before it reaches the floor".into());
    }
    Ok(SeparationAnswer {
        start_mode,
        events,
        values: rest,
        impact_surface: surface,
        notes,
    })
}

/// The trajectory with friction at the given times (through every mode and
/// the free flight, up to the first impact).
///
/// Errors: a time after the first impact or after lift-off; see [`solve`].
pub fn trajectory(
    model: &Model,
    fr: &Friction,
    digits: u32,
    times: &[Exact],
) -> Result<TrajectoryAnswer> {
    check_times(digits, times)?;
    let exact_t: Vec<Option<String>> = times
        .iter()
        .map(|t| {
            (!t.times_pi && crate::oracle::terminating(&t.coef)).then(|| rational_text(&t.coef))
        })
        .collect();
    let tf = |p: u32| -> Vec<Float> { times.iter().map(|t| t.to_float(p)).collect() };
    let (p1, _) = precisions(digits, 0);
    let h64 = super::default_horizon(model);
    let horizon = |p: u32| Float::with_val(p, &h64);
    let run = |p: u32| solve(model, fr, p, &tf(p), false, &horizon(p));
    let first = run(p1)?;
    let modes: Vec<String> = first.rows.iter().map(Point::mode_tag).collect();
    let names: Vec<String> = columns().iter().map(|s| s.to_string()).collect();
    let rows = laddered(digits, first, &names, times.len(), run, |m| {
        let mut out = Vec::new();
        for (pt, text) in m.rows.iter().zip(&exact_t) {
            let p = pt.t.prec();
            for (i, v) in pt.columns().into_iter().enumerate() {
                let mut e = integrated(&v, one(p));
                if i == 0 {
                    e.exact_text = text.clone();
                }
                out.push(e);
            }
        }
        Ok(out)
    })?;
    Ok(TrajectoryAnswer { rows, modes })
}

/// θ with friction at the given times (through every mode and the free
/// flight, up to the first impact), verified like [`trajectory`] but
/// without the other columns: the frictional counterpart of
/// [`crate::oracle::Oracle::theta_at_times`].
///
/// Errors: as [`trajectory`].
pub fn theta_at_times(
    model: &Model,
    fr: &Friction,
    digits: u32,
    times: &[Exact],
) -> Result<Vec<Verified>> {
    check_times(digits, times)?;
    let tf = |p: u32| -> Vec<Float> { times.iter().map(|t| t.to_float(p)).collect() };
    let (p1, _) = precisions(digits, 0);
    let h64 = super::default_horizon(model);
    let horizon = |p: u32| Float::with_val(p, &h64);
    let run = |p: u32| super::solve_theta(model, fr, p, &tf(p), &horizon(p));
    let first = run(p1)?;
    let rows = laddered(
        digits,
        first,
        &["theta".to_string()],
        times.len(),
        run,
        |m| {
            Ok(m.thetas
                .iter()
                .map(|(th, _)| integrated(th, one(th.prec())))
                .collect())
        },
    )?;
    Ok(rows
        .into_iter()
        .filter_map(|r| r.into_iter().next())
        .collect())
}

/// One quantity computed by the three integrators.
#[derive(Debug, Clone)]
pub struct CrossCheck {
    /// Quantity (`event2_t`, `theta_s`, …).
    pub name: String,
    /// By Chebyshev spectral integration in the angle (the answers' route).
    pub spectral: Float,
    /// By Gragg–Bulirsch–Stoer extrapolation.
    pub gbs: Float,
    /// By Gauss–Legendre collocation.
    pub collocation: Float,
    /// Significant digits on which the spectral route agrees with both
    /// time integrators (relative to max(|v|, 1)): the smaller of the two.
    pub digits: f64,
}

/// The three integrators on the same motion at the working precision of
/// `digits`: the event sequences must be identical; every event time and
/// angle and every separation and impact value is compared.
///
/// Errors: from any run; different event sequences; a mode that the
/// spectral route declined (it would not be an independent check).
pub fn cross_check(model: &Model, fr: &Friction, digits: u32) -> Result<Vec<CrossCheck>> {
    let (_, p2) = precisions(digits, 0);
    let h = super::default_horizon(model);
    let s = super::solve_with(model, fr, p2, &[], true, &h, super::Method::Spectral)?;
    let a = super::solve_with(model, fr, p2, &[], true, &h, super::Method::Gbs)?;
    let b = super::solve_with(model, fr, p2, &[], true, &h, super::Method::Collocation)?;
    if s.routes.iter().any(|r| *r != super::Method::Spectral) {
        return Err(Error::NotConverged {
            quantity: "spectral route".into(),
            requested: digits,
            reached: format!("modes integrated by {:?}", s.routes),
            detail: "the spectral route declined a mode".into(),
        });
    }
    for m in [&a, &b] {
        if signature(&s) != signature(m) {
            return Err(Error::NotConverged {
                quantity: "event sequence".into(),
                requested: digits,
                reached: "the integrators disagree on the sequence of modes".into(),
                detail: format!("{} / {}", signature(&s).join(", "), signature(m).join(", ")),
            });
        }
    }
    let vals = |m: &Motion| -> Vec<(String, Float)> {
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
    };
    let agree = |x: &Float, y: &Float| {
        let d = Float::with_val(p2, x - y).abs();
        let sc = Float::with_val(p2, x.abs_ref()).max(&Float::with_val(p2, 1u32));
        let r = (d / sc).to_f64();
        if r == 0.0 {
            f64::from(p2) * 0.301
        } else {
            -r.log10()
        }
    };
    Ok(vals(&s)
        .into_iter()
        .zip(vals(&a))
        .zip(vals(&b))
        .map(|(((name, x), (_, y)), (_, z))| CrossCheck {
            digits: agree(&x, &y).min(agree(&x, &z)),
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
/// again, a fixed lower cylinder.
pub fn verify_cases() -> Vec<(String, Model, Friction)> {
    use crate::model::{Contact, Floor, Params, Start};
    let th0 = Exact::rational(rug::Rational::from((1, 10)));
    let main = Model::paper_default(th0.clone());
    let law = |s: &str| super::Law::parse("mu", s).expect("built-in coefficient");
    let both = |f: &str, c: &str| Friction {
        floor: law(f),
        contact: law(c),
    };
    let mut heavy = Params::identical_solid();
    heavy.m2 = rug::Rational::from(3);
    let heavy = Model::new(heavy, Floor::Roll, Contact::Roll, Start::rest(th0.clone()))
        .expect("built-in model");
    let fixed = Model::new(
        Params::identical_solid(),
        Floor::Fixed,
        Contact::Roll,
        Start::rest(th0),
    )
    .expect("built-in model");
    vec![
        ("main_mu_0_3".into(), main.clone(), both("0.3", "0.3")),
        ("main_mu_1".into(), main.clone(), both("1", "1")),
        ("main_mu_10".into(), main.clone(), both("10", "10")),
        ("main_floor_slips".into(), main.clone(), both("0.05", "0.3")),
        (
            "main_static_kinetic".into(),
            main,
            both("0.5,0.3", "0.5,0.3"),
        ),
        ("heavy_upper_restick".into(), heavy, both("0.2", "0.4")),
        ("fixed_mu_0_3".into(), fixed, both("inf", "0.3")),
    ]
}

/// The keys of [`forces_at`]: those of the ideal `forces`
/// ([`crate::oracle::FORCE_KEYS`]: F1, N1, F21, N12, θ̇, θ̈, |F1|/N1,
/// |F21|/N12), then the slip speeds and the dissipated work
/// ([`super::EXTRA_COLUMNS`]).
pub fn force_keys() -> Vec<&'static str> {
    crate::oracle::FORCE_KEYS
        .iter()
        .chain(&super::EXTRA_COLUMNS)
        .copied()
        .collect()
}

fn at_angle(
    model: &Model,
    fr: &Friction,
    digits: u32,
    theta: &Exact,
    name: &str,
    keys: &[&str],
    est: impl Fn(&Point) -> Vec<Estimate>,
) -> Result<(Vec<Verified>, String)> {
    check_digits(digits)?;
    let (p1, _) = precisions(digits, 0);
    let h64 = super::default_horizon(model);
    let first = super::solve_to_angle(model, fr, p1, theta, name, &h64)?;
    let mode = first.target.as_ref().map_or_else(String::new, |t| {
        t.mode.map_or_else(String::new, |m| m.to_string())
    });
    let names: Vec<String> = keys.iter().map(|k| k.to_string()).collect();
    let rows = laddered(
        digits,
        first,
        &names,
        1,
        |p| super::solve_to_angle(model, fr, p, theta, name, &h64),
        |m| {
            m.target
                .as_ref()
                .map(&est)
                .ok_or_else(|| Error::not_physical("internal: the angle was not reached"))
        },
    )?;
    Ok((rows.into_iter().next().unwrap_or_default(), mode))
}

/// The time at which θ first reaches `theta`, with friction.
///
/// Errors: an angle behind the start or beyond the end of the contact
/// (`to`); see [`super::solve`].
pub fn time_at(
    model: &Model,
    fr: &Friction,
    digits: u32,
    theta: &Exact,
) -> Result<(Verified, String)> {
    let (mut v, mode) = at_angle(model, fr, digits, theta, "to", &["t"], |pt| {
        let p = pt.t.prec();
        // the time of a located event: the bracket enters through the ladder
        vec![integrated(&pt.t, one(p))]
    })?;
    Ok((v.remove(0), mode))
}

/// The forces, rates, friction ratios, slip speeds and dissipated work
/// where θ first reaches `theta`, with friction; and the mode there.
///
/// Errors: as [`time_at`] (parameter `theta`).
pub fn forces_at(
    model: &Model,
    fr: &Friction,
    digits: u32,
    theta: &Exact,
) -> Result<(Vec<Verified>, String)> {
    at_angle(model, fr, digits, theta, "theta", &force_keys(), |pt| {
        let p = pt.t.prec();
        let ratio = |f: &Float, n: &Float| {
            if n.is_zero() {
                Float::new(p)
            } else {
                Float::with_val(p, f.abs_ref()) / n
            }
        };
        [
            pt.f1.clone(),
            pt.n1.clone(),
            pt.f21.clone(),
            pt.n12.clone(),
            pt.theta_dot.clone(),
            pt.theta_ddot.clone(),
            ratio(&pt.f1, &pt.n1),
            ratio(&pt.f21, &pt.n12),
            pt.s1.clone(),
            pt.s12.clone(),
            pt.work.clone(),
        ]
        .iter()
        .map(|v| integrated(v, one(p)))
        .collect()
    })
}
