//! The questions users ask, answered with verified digits, for every
//! contact law: one typed [`Answer`].
//!
//! * [`separation`]: the motion to its end — the events (slip onsets,
//!   sticks, reversals, the branch point, separation), the free flight and
//!   the first impact (or a lift-off, or cylinder 2 reaching the floor while
//!   still on cylinder 1); θs, t_s and, for the ideal models, the findings
//!   of the paper's closed forms over the closed branch.
//! * [`time`], [`forces`]: where θ first reaches an angle.
//! * [`trajectory`]: every column at given times, through every phase.
//!
//! Each is the hybrid motion of [`crate::motion`] computed at the two
//! working precisions of the precision ladder ([`ladder`](mod@ladder)). Where the
//! question stays inside a conservative phase of an ideal model (`time`
//! and `forces` before the cylinders part, on the `stay` branch) the
//! energy route of [`ideal::Oracle`] answers directly: the same numbers,
//! by the same route, with its own ladder.

pub mod answer;
pub mod ideal;
pub use ideal::rigorous;
pub mod ladder;
mod trajectory;

pub use answer::{Answer, EventAnswer, Question, Row};
pub use ideal::{friction_ratio, Oracle, Separation, FORCE_KEYS, MAX_DIGITS, TRAJECTORY_COLUMNS};
pub use trajectory::{
    all_columns, parse_columns, theta_at_times, trajectory, trajectory_in_blocks, trajectory_of,
};

use crate::error::{Error, Result};
use crate::exact::{Exact, RoundedTimes, TableTimes};
use crate::model::{Law, Model, Which};
use crate::motion::point::col;
use crate::motion::{self, Branch, Caches, Kind, Method, Motion, Phase, Request, Until};
use crate::numeric::verify::{ladder, precisions, Estimate, Run, Verified};
use ladder::{event_estimates, event_names, events_of, integrated, laddered, Runs};
use rug::Float;

/// How to answer.
#[derive(Debug, Clone)]
pub struct Options {
    /// Significant digits (1 to [`MAX_DIGITS`]).
    pub digits: u32,
    /// The branch to follow where the motion is not unique.
    pub branch: Branch,
    /// The integrators ([`Method::Auto`]: the fastest verified route per
    /// phase).
    pub method: Method,
}

impl Options {
    /// `digits` digits on the default branch and routes.
    pub fn digits(digits: u32) -> Self {
        Options {
            digits,
            branch: Branch::Stay,
            method: Method::Auto,
        }
    }
}

/// The keys of `forces`, for every law: F1, N1, F21, N12, θ̇, θ̈, the
/// friction each contact needs (|F1|/N1, |F21|/N12), the slip speeds and
/// the work dissipated.
pub const FORCES_KEYS: [&str; 11] = [
    "F1",
    "N1",
    "F21",
    "N12",
    "theta_dot",
    "theta_ddot",
    "mu_floor",
    "mu_contact",
    "s1",
    "s12",
    "work",
];

/// The impact keys of `separation`: the state just before the first impact.
pub const IMPACT_KEYS: [&str; 9] = [
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

/// `digits` within 1..=[`MAX_DIGITS`], else the one-line refusal naming it.
pub(crate) fn check_digits(digits: u32) -> Result<()> {
    if digits == 0 || digits > MAX_DIGITS {
        return Err(Error::invalid(
            "digits",
            digits,
            format!("must be between 1 and {MAX_DIGITS}"),
        ));
    }
    Ok(())
}

fn check_times(times: &[Exact]) -> Result<()> {
    check_times_rounded(times, None)
}

/// [`check_times`], the order of two neighbours read from their roundings
/// to odd where these differ (`rounded`, of these times: a rounding to odd
/// is monotone, so unequal roundings order their times), else exactly.
fn check_times_rounded(times: &[Exact], rounded: Option<&RoundedTimes>) -> Result<()> {
    let rounded = rounded.filter(|r| r.len() == times.len());
    for (i, w) in times.windows(2).enumerate() {
        let known = rounded.and_then(|r| r.order(i, i + 1));
        // exactly where both are rational or both multiples of π (no
        // conversion, and no two times too close for a float to order)
        let descending = if let Some(o) = known {
            o == std::cmp::Ordering::Greater
        } else if w[0].times_pi == w[1].times_pi {
            w[1].coef < w[0].coef
        } else {
            w[1].to_float(256) < w[0].to_float(256)
        };
        if descending {
            // named as the command line names an entry (1-based)
            return Err(Error::invalid(
                &format!("times: entry {}", i + 2),
                &w[1],
                format!(
                    "must be ascending: it is before the entry before it, {}",
                    w[0]
                ),
            ));
        }
    }
    if let Some((i, t)) = times.iter().enumerate().find(|(_, t)| t.signum() < 0) {
        return Err(Error::invalid(
            &format!("times: entry {}", i + 1),
            t,
            "must be >= 0 (the start is at t = 0)",
        ));
    }
    Ok(())
}

fn infinite(model: &Model, what: &str) -> Error {
    crate::integrate::energy::infinite_time_error(what, model.has_coulomb())
}

fn runs<'a>(model: &'a Model, opts: &Options, times: Vec<Exact>, until: Until) -> Runs<'a> {
    // the times rounded to odd once, above the first rung's precisions
    // (its runs' and the Taylor route's time precision for both, set by
    // the lower run: `Route::deltas_at`): each run rounds them from these
    // (a climb above converts them itself)
    let rounded = (times.len() > 1).then(|| {
        let (p1, _) = crate::numeric::verify::precisions(opts.digits, 0);
        let top = crate::numeric::taylor::time_prec_for(p1 + p1 / 8 + 40, 0) + 2;
        std::sync::Arc::new(RoundedTimes::new(&times, top))
    });
    Runs {
        model,
        req: Request {
            times,
            until,
            theta_only: false,
            branch: opts.branch.clone(),
            method: opts.method,
            horizon: None,
            run: Run::Low,
            digits: opts.digits,
            sides: Vec::new(),
            target_side: None,
            low_deltas: Vec::new(),
            derived_at_high: false,
        },
        caches: Caches {
            times: TableTimes::new(rounded),
            ..Caches::default()
        },
        at_events: Vec::new(),
        target_at: None,
        side_bits: 0,
        target_kind: None,
    }
}

fn empty_answer(question: Question, model: &Model, opts: &Options) -> Answer {
    Answer {
        question,
        model: model.clone(),
        digits: opts.digits,
        branch: opts.branch.clone(),
        start_mode: None,
        events: Vec::new(),
        end: None,
        values: Vec::new(),
        proved: Vec::new(),
        columns: Vec::new(),
        rows: Vec::new(),
        proved_rows: Vec::new(),
        phase: None,
        routes: Vec::new(),
        notes: Vec::new(),
    }
}

/// The note on the energy balance of a dissipative motion.
fn energy_note((drift, unit): &(Float, Float)) -> String {
    let mut note = format!(
        "energy balance E(0) - E(t) = W(t) (W: work of sliding friction) held to {} of m2 g r along the motion",
        crate::numeric::decimal::short(drift)
    );
    if *unit > 1u32 {
        // the balance was verified relative to the energy's own scale
        note.push_str(&format!(
            ", the energy itself |E(0)| = {} m2 g r (E's zero at cylinder 1's centre)",
            crate::numeric::decimal::short_near(unit)
        ));
    }
    note
}

/// A `--part-at` angle must lie where parting is lawful: inside a window of
/// the `stay` motion between a branch point and the end of the closed branch
/// (or of the window). Checked on the whole motion at the first working
/// precision, so that an angle behind the start or past the end of the
/// closed branch is refused rather than silently never reached.
///
/// Errors: [`Error::InvalidParameter`] naming `part-at`; a run's.
fn check_part_at(model: &Model, opts: &Options) -> Result<()> {
    let Branch::PartAt(a) = &opts.branch else {
        return Ok(());
    };
    if model.starts_at_equilibrium() {
        return Ok(());
    }
    let stay = Options {
        branch: Branch::Stay,
        ..opts.clone()
    };
    let mut r = runs(model, &stay, Vec::new(), Until::End);
    let (p1, _) = precisions(opts.digits, 0);
    let m = r.at(p1, Run::Low)?;
    let af = a.to_float(p1);
    // the end of the closed branch: where the contact opens, or the motion's end
    let closed_end = m
        .events
        .iter()
        .find(|e| e.kind == Kind::Separation)
        .or(m.events.last())
        .map(|e| e.at.theta.clone());
    let tol = Float::with_val(p1, af.abs_ref()).max(&Float::with_val(p1, 1u32)) * 1e-9f64;
    let inside = m.windows.iter().any(|(lo, hi)| {
        let Some(hi) = hi.clone().or_else(|| closed_end.clone()) else {
            return false;
        };
        let (a0, b0) = if *lo <= hi {
            (lo.clone(), hi)
        } else {
            (hi, lo.clone())
        };
        Float::with_val(p1, &a0 - &tol) <= af && af <= Float::with_val(p1, &b0 + &tol)
    });
    if inside {
        return Ok(());
    }
    // the windows, quoted to the digits the first precision holds
    let q = crate::numeric::decimal::approx_text;
    let wins: Vec<String> = m
        .windows
        .iter()
        .filter_map(|(lo, hi)| {
            let hi = hi.clone().or_else(|| closed_end.clone())?;
            Some(format!("[≈{}, ≈{}]", q(lo), q(&hi)))
        })
        .collect();
    let allowed = if wins.is_empty() {
        "must lie where parting is lawful, and this motion has no such angle: it is unique \
         (no branch point before the contact opens); drop --part-at"
            .to_string()
    } else {
        format!(
            "must lie where parting is lawful: theta in {} (from the branch point \
             theta_indeterminate to the end of the closed branch)",
            wins.join(" or ")
        )
    };
    Err(Error::invalid("part-at", a, allowed))
}

/// The notes every motion answer carries: the energy balance where work
/// was dissipated, the routes, the window where parting was lawful.
fn motion_notes(first: &Motion, opts: &Options) -> Vec<String> {
    let mut notes: Vec<String> = energy_drift(first).iter().map(energy_note).collect();
    notes.extend(branch_notes(first, opts));
    notes
}

/// The largest energy drift |E(0) − E(t) − W(t)| along a dissipative motion
/// and the energy's scale ([`Motion::energy_unit`]), both in units of m2 g r
/// (None for a conservative motion, whose energy integral is exact).
fn energy_drift(first: &Motion) -> Option<(Float, Float)> {
    let dissipative = first
        .routes
        .iter()
        .any(|r| *r != motion::Route::Energy && *r != motion::Route::Flight)
        || first
            .events
            .iter()
            .any(|e| e.at.work.is_sign_positive() && !e.at.work.is_zero());
    dissipative.then(|| (first.energy_drift.clone(), first.energy_unit.clone()))
}

/// The notes on where the motion is not unique and the branch followed.
fn branch_notes(first: &Motion, opts: &Options) -> Vec<String> {
    let mut notes = Vec::new();
    if first.events.iter().any(|e| e.kind == Kind::Indeterminate) {
        let on = match &opts.branch {
            Branch::Stay => "the cylinders stay together (the branch followed, the limit of stiff \
                             compliant contact); parting is lawful from theta_indeterminate to the \
                             end of the closed branch (velocity-level complementarity engines part \
                             at theta_indeterminate: --branch part)"
                .to_string(),
            Branch::Part => "the cylinders part at the first instant they may (--branch part, as \
                             velocity-level complementarity engines do)"
                .to_string(),
            Branch::PartAt(a) => format!("the cylinders part where theta reaches {a} (--part-at)"),
        };
        notes.push(format!(
            "the rigid-body motion is not unique from the branch point theta_indeterminate: the \
             free relative normal acceleration r thetadot^2 - g cos(theta) - x1ddot_free sin(theta) \
             turns positive while N12 > 0, so the cylinders may stay together or part; {on}"
        ));
    } else if first.merged_branch {
        notes.push(
            "the free relative normal acceleration turns positive while N12 > 0 (a branch point, \
             where parting becomes lawful) before theta_s, but within the digits asked of it: the \
             window where the cylinders may part is narrower than these digits resolve, and the \
             motion is reported unique to them (more --digits tell the branch point apart)"
                .into(),
        );
    }
    notes
}

/// The motion to its end, verified: the events, θs, t_s, the work
/// dissipated, the branch point, the first impact; for an ideal model on
/// the `stay` branch also the closed forms' findings over the closed
/// branch (the least N1, the most friction needed, sign changes of φ̇1, φ1,
/// F21 at θs).
///
/// Errors: bad digits; a start at rest exactly at the top with Coulomb
/// friction (every time and event angle is infinite or a limit); see
/// [`motion::run`].
pub fn separation(model: &Model, opts: &Options) -> Result<Answer> {
    check_digits(opts.digits)?;
    check_part_at(model, opts)?;
    let digits = opts.digits;
    let mut ans = empty_answer(Question::Separation, model, opts);
    if model.starts_at_equilibrium() {
        // the limit θ0 → 0+: the closed branch's angles are finite, every
        // time infinite (the ideal models' closed forms)
        let ideal = model.ideal().ok_or_else(|| {
            infinite(
                model,
                "every time along the motion (and with friction every event)",
            )
        })?;
        let mut o = Oracle::new(&ideal, digits)?;
        let sep = o.separation()?;
        let star = o.branch_point()?;
        ans.start_mode = Some(conservative_mode(model));
        ans.notes = sep.notes;
        let Some(star) = star else {
            ans.values.push(sep.theta_s);
            ans.values.extend(sep.extra);
            return Ok(ans);
        };
        let window = format!(
            "the rigid-body motion is not unique from the branch point theta_indeterminate = {} (the limit theta0 -> 0+): the free relative normal acceleration r thetadot^2 - g cos(theta) turns positive while N12 > 0, so the cylinders may stay together or part anywhere up to theta = {} (N12 = 0)",
            star.text, sep.theta_s.text
        );
        match &opts.branch {
            Branch::Stay => {
                ans.values.push(sep.theta_s);
                ans.values.push(star);
                ans.values.extend(sep.extra);
                ans.notes.push(format!(
                    "{window}; the branch followed: they stay together (the limit of stiff \
                     compliant contact; velocity-level complementarity engines part at \
                     theta_indeterminate: --branch part)"
                ));
            }
            Branch::Part | Branch::PartAt(_) => {
                let at = match &opts.branch {
                    Branch::PartAt(a) => {
                        let inside = |v: &Verified, lower: bool| {
                            let d =
                                Float::with_val(256, a.to_float(256).abs() - v.value.clone().abs());
                            let e = Float::with_val(256, &v.err_bound);
                            if lower {
                                d >= -e
                            } else {
                                d <= e
                            }
                        };
                        if a.signum() != star.value.cmp0().map_or(0, |o| o as i32)
                            || !inside(&star, true)
                            || !inside(&sep.theta_s, false)
                        {
                            return Err(Error::invalid(
                                "part-at",
                                a,
                                format!(
                                    "must lie where parting is lawful: from theta_indeterminate = \
                                     {} to theta_s = {}",
                                    star.text, sep.theta_s.text
                                ),
                            ));
                        }
                        let exact = a.clone();
                        single_value(digits, "theta_s", |p| {
                            Estimate::rounded(exact.to_float(p), Float::with_val(p, 1u32))
                        })?
                    }
                    _ => {
                        let mut v = star.clone();
                        v.name = "theta_s".into();
                        v
                    }
                };
                ans.values.push(at);
                ans.values.push(star);
                // the closed branch's findings do not apply
                ans.notes.retain(|n| n.starts_with("t_s is infinite"));
                ans.notes.push(format!(
                    "{window}; the branch followed: they part {} (theta_s is where they part; the \
                     closed branch's findings are not computed)",
                    match &opts.branch {
                        Branch::PartAt(a) => format!("where theta reaches {a} (--part-at)"),
                        _ => "at the first instant they may (--branch part)".to_string(),
                    }
                ));
            }
        }
        return Ok(ans);
    }
    let mut runs = runs(model, opts, Vec::new(), Until::End);
    let (p1, _) = precisions(digits, 0);
    let mut first = runs.at(p1, Run::Low)?;
    runs.resolve_sides(&mut first)?;
    let n_ev = first.events.len();
    let mut names = event_names(n_ev);
    let sep_ev = first.events.iter().position(|e| e.kind == Kind::Separation);
    let ind_ev = first
        .events
        .iter()
        .position(|e| e.kind == Kind::Indeterminate);
    let has_impact = first.impact.is_some();
    if sep_ev.is_some() {
        names.extend(["theta_s", "t_s", "work_s"].map(String::from));
    }
    if ind_ev.is_some() {
        names.extend(
            [
                "theta_indeterminate",
                "t_indeterminate",
                "theta_dot_indeterminate",
                "N12_indeterminate",
                "F21_indeterminate",
            ]
            .map(String::from),
        );
    }
    if has_impact {
        names.extend(IMPACT_KEYS.map(String::from));
    }
    let vals = laddered(&mut runs, first.clone(), &names, 1, |m, _| {
        let m = &m;
        let mut out = Vec::new();
        let p = m.prec();
        let sc = ladder::column_scales(model, p);
        let work_scale = || Float::with_val(p, &*sc[col!("work")]);
        let ts = &sc[col!("t")];
        event_estimates(m, &sc[col!("t")], &mut out);
        if let Some(i) = sep_ev {
            out.push(out[2 * i + 1].clone());
            out.push(out[2 * i].clone());
            let w = &m.events[i].at.work;
            out.push(if m.events[i].at.is_exact_zero(col!("work")) {
                Estimate::zero(p, work_scale())
            } else {
                integrated(w, work_scale())
            });
        }
        if let Some(i) = ind_ev {
            out.push(out[2 * i + 1].clone());
            out.push(out[2 * i].clone());
            // the state there, with the event's location error carried
            let ev = &m.events[i];
            let all = ladder::point_estimates(&ev.at, &sc, None);
            let loc = Float::with_val(p, &ev.theta_err)
                + Float::with_val(p, &ev.t_err) * Float::with_val(p, ev.at.theta_dot.abs_ref());
            for k in [col!("theta_dot"), col!("N12"), col!("F21")] {
                let mut e = all[k].clone();
                e.err += Float::with_val(p, &loc * &*sc[k]) * 16u32;
                out.push(e);
            }
        }
        if let Some(imp) = &m.impact {
            let ev_err = sep_ev
                .map(|i| m.events[i].t_err.clone())
                .unwrap_or_else(|| Float::new(p));
            // zeros by structure, exact: a held cylinder 1 does not move; a
            // frictionless contact never turns cylinder 2, nor cylinder 1
            // where the floor is frictionless too (ω0 = 0: their spins 0
            // from the start). They read "indistinguishable from 0: |x| <=
            // 1.5e-48"
            let still = {
                let (phi1, psi2) = model.spins_never_turned();
                let mut z = 0u32;
                if matches!(model.floor(), crate::model::Law::Held) {
                    z |= (1 << col!("x1")) | (1 << col!("x1_dot"));
                }
                if phi1 {
                    z |= 1 << col!("phi1_dot");
                }
                if psi2 {
                    z |= 1 << col!("phi2_dot");
                }
                z
            };
            for (v, column) in [
                (&imp.t, col!("t")),
                (&imp.x1, col!("x1")),
                (&imp.x2, col!("x2")),
                (&imp.y2, col!("y2")),
                (&imp.vx1, col!("x1_dot")),
                (&imp.phi1_dot, col!("phi1_dot")),
                (&imp.vx2, col!("x2_dot")),
                (&imp.vy2, col!("y2_dot")),
                (&imp.psi2_dot, col!("phi2_dot")),
            ] {
                // the separation time's error δt: a first-order term of 16
                // natural scales per time unit, which over-covers it (at the
                // parting N12 = 0, so the free and the constrained motions
                // share their accelerations and a flight started δt later
                // along the motion differs at second order in δt). Checked
                // against 60 digits (tests/friction.rs,
                // separation_scalars_lie_within_their_bounds_of_60_digits)
                let sc = Float::with_val(p, &*sc[column]);
                if still & (1 << column) != 0 {
                    out.push(Estimate::zero(p, sc));
                    continue;
                }
                let mut e = integrated(v, sc.clone());
                e.err += Float::with_val(p, &ev_err * sc) / &**ts * 16u32;
                out.push(e);
            }
        }
        Ok(out)
    })?;
    let mut vals = vals.into_iter().next().unwrap_or_default();
    let rest = vals.split_off(2 * n_ev);
    for (v, name) in rest.into_iter().zip(names.iter().skip(2 * n_ev)) {
        let mut v = v;
        v.name = name.clone();
        ans.values.push(v);
    }
    ans.events = events_of(&first, &vals);
    ans.start_mode = Some(first.start_mode);
    ans.end = first.end;
    ans.routes = first.routes.clone();
    ans.notes = motion_notes(&first, opts);
    ans.notes.extend(crate::model::free_spin_note(model));
    if let (Some(i), Some(imp)) = (sep_ev, &first.impact) {
        // N12 at the parting, against 10^-12 of its unit m2 g (not of one
        // newton: in other units a rounding residual passed, a genuine force
        // did not), and positive: a residual of either sign is the ordinary
        // parting where N12 falls to 0
        // (compared in MPFR: in f64 a unit beyond 10^±308 overflows)
        let n = &first.events[i].at.n12;
        let pr = model.params();
        let unit = Float::with_val(n.prec(), &rug::Rational::from(&pr.m2 * &pr.g))
            / Float::with_val(n.prec(), Float::u_pow_u(10, 12));
        if *n > unit && opts.branch == Branch::Stay {
            ans.notes.push(format!(
                "the contact opens while N12 = {n:.7e} > 0 in the last closed mode: at that \
                 event no mode with the contact closed is consistent and the free motion \
                 separates, so the normal force drops to 0 at once"
            ));
        }
        ans.notes.push(format!(
            "the first impact is on the {}{}",
            imp.surface.name().replace('_', " "),
            if imp.surface == motion::Surface::Cylinder {
                " (cylinder 2 touches cylinder 1 again before it reaches the floor)"
            } else {
                ""
            }
        ));
    }
    match first.end {
        Some(motion::End::LiftOff) => ans.notes.push(
            "cylinder 1 leaves the floor (N1 = 0) before the cylinders part: the model ends there"
                .into(),
        ),
        Some(motion::End::Impact(motion::Surface::FloorInContact)) => ans.notes.push(
            "the cylinders do not part: cylinder 2 reaches the floor while still on cylinder 1, \
             an impact the model does not continue through"
                .into(),
        ),
        _ => {}
    }
    ans.notes
        .push("the model ends at the first impact (impact laws are outside it)".into());
    // the closed forms' findings over the closed branch
    let closed_branch = first.routes.first() == Some(&motion::Route::Energy)
        && sep_ev.is_some_and(|i| {
            first.events[..i]
                .iter()
                .all(|e| e.kind == Kind::Indeterminate)
        });
    if let (Some(ideal), Branch::Stay, true) = (model.ideal(), &opts.branch, closed_branch) {
        let route = runs
            .caches
            .sticking
            .take()
            .ok_or_else(|| Error::not_physical("internal: no energy route"))?;
        let mut o = Oracle::with_route(&ideal, digits, route)?;
        let theta_s = ans
            .value("theta_s")
            .cloned()
            .ok_or_else(|| Error::not_physical("internal: no theta_s"))?;
        let mut extra = Vec::new();
        let mut notes = Vec::new();
        o.separation_findings(&theta_s, &mut extra, &mut notes)?;
        let at = ans
            .values
            .iter()
            .position(|v| v.name == "work_s")
            .map_or(0, |i| i + 1);
        let at = if ind_ev.is_some() { at + 2 } else { at };
        for (k, v) in extra.into_iter().enumerate() {
            ans.values.insert(at + k, v);
        }
        ans.notes.extend(notes);
    }
    Ok(ans)
}

/// Whether a question at an angle stays in the closed branch of an ideal
/// model, where the energy route answers it directly.
fn ideal_at_angle(model: &Model, opts: &Options) -> Option<crate::model::Ideal> {
    (opts.branch == Branch::Stay && opts.method == Method::Auto && !model.has_coulomb())
        .then(|| model.ideal())
        .flatten()
}

/// The state where θ first reaches `theta`, verified: `keys` of it by
/// `est`, and the phase there.
fn at_angle(
    model: &Model,
    opts: &Options,
    theta: &Exact,
    name: &str,
    keys: &[&str],
    est: impl Fn(&motion::Point) -> Vec<Estimate>,
) -> Result<(Vec<Verified>, Phase, Vec<String>, motion::Mode)> {
    check_digits(opts.digits)?;
    check_part_at(model, opts)?;
    if model.starts_at_equilibrium() {
        return Err(infinite(model, "the time to any angle"));
    }
    let dir = model.direction();
    let th0 = model.start().theta0.to_float(256);
    let d = theta.to_float(256) - th0;
    if d.cmp0().map(|o| o as i32 * dir.signum()) == Some(-1) {
        return Err(Error::invalid(
            name,
            theta,
            "must lie beyond theta0 in the direction of the motion",
        ));
    }
    let mut runs = runs(
        model,
        opts,
        Vec::new(),
        Until::Angle {
            theta: theta.clone(),
            name: name.to_string(),
        },
    );
    let (p1, _) = precisions(opts.digits, 0);
    let mut first = runs.at(p1, Run::Low)?;
    runs.resolve_sides(&mut first)?;
    let phase = first
        .target
        .as_ref()
        .map(|t| t.phase)
        .ok_or_else(|| Error::not_physical("internal: the angle was not reached"))?;
    let start_mode = first.start_mode;
    // past a branch point on the way: which branch the value is on
    let branch = branch_notes(&first, opts);
    let names: Vec<String> = keys.iter().map(|k| k.to_string()).collect();
    let at_event = runs.target_at.map(|k| {
        format!(
            "theta = {theta} cannot be told apart from the angle of the {} (not even at {} \
             bits, or past it by less than the digits asked resolve): the values are the state \
             at the event (the forces and accelerations those of the phase before)",
            runs.target_kind
                .or_else(|| first.events.get(k).map(|e| e.kind))
                .map_or("event", |k| k.name())
                .replace('_', " "),
            runs.side_bits
        )
    });
    let rows = laddered(&mut runs, first, &names, 1, |m, _| {
        let m = &m;
        m.target
            .as_ref()
            .map(&est)
            .ok_or_else(|| Error::not_physical("internal: the angle was not reached"))
    })?;
    Ok((
        rows.into_iter().next().unwrap_or_default(),
        phase,
        at_event.into_iter().chain(branch).collect(),
        start_mode,
    ))
}

/// The note for an angle answered at θs ([`Route::delta_of`]: past it by
/// less than the digits asked resolve).
fn at_separation_note(theta: &Exact) -> String {
    format!(
        "theta = {theta} is past theta_s by less than the digits asked resolve: the values are \
         the state at theta_s (N12 = 0 there)"
    )
}

/// The time at which θ first reaches `theta`.
///
/// Errors: an angle behind the start or not reached while the cylinders
/// touch; see [`motion::run`].
pub fn time(model: &Model, theta: &Exact, opts: &Options) -> Result<Answer> {
    let mut ans = empty_answer(Question::Time, model, opts);
    if let Some(ideal) = ideal_at_angle(model, opts) {
        check_digits(opts.digits)?;
        let mut o = Oracle::new(&ideal, opts.digits)?;
        ans.values.push(o.time_at(theta)?);
        if o.route.at_separation {
            ans.notes.push(at_separation_note(theta));
        }
        ans.notes.extend(o.branch_window_note(theta)?);
        ans.phase = Some(Phase::Contact(conservative_mode(model)));
        ans.start_mode = Some(conservative_mode(model));
        ans.routes.push(motion::Route::Energy);
        return Ok(ans);
    }
    let (v, phase, note, start) = at_angle(model, opts, theta, "to", &["t"], |pt| {
        let p = pt.t.prec();
        vec![integrated(
            &pt.t,
            Float::with_val(p, &*ladder::column_scales(model, p)[0]),
        )]
    })?;
    ans.values = v;
    ans.phase = Some(phase);
    ans.start_mode = Some(start);
    ans.notes.extend(note);
    Ok(ans)
}

/// One verified value from one estimate per precision.
fn single_value(digits: u32, name: &str, est: impl Fn(u32) -> Estimate) -> Result<Verified> {
    ladder(digits, &[name], |p| Ok(vec![est(p)]))?
        .into_iter()
        .next()
        .ok_or_else(|| Error::not_physical("internal: the ladder returned no value"))
}

/// The contacts' states of an ideal model.
fn conservative_mode(model: &Model) -> motion::Mode {
    let st = |l: &Law| match l {
        Law::Held => motion::State::Held,
        Law::Frictionless => motion::State::Slip(0),
        _ => motion::State::Stick,
    };
    motion::Mode {
        floor: st(model.floor()),
        contact: st(model.contact()),
    }
}

/// The forces, rates, friction needed, slip speeds and work where θ first
/// reaches `theta` ([`FORCES_KEYS`]); for an ideal model also the most
/// friction each rolling contact needs over [θ0, θ], and where.
///
/// Errors: as [`time`].
pub fn forces(model: &Model, theta: &Exact, opts: &Options) -> Result<Answer> {
    let mut ans = empty_answer(Question::Forces, model, opts);
    let digits = opts.digits;
    if let Some(ideal) = ideal_at_angle(model, opts) {
        check_digits(digits)?;
        let mut o = Oracle::new(&ideal, digits)?;
        let mut values = o.forces_at(theta)?;
        // the slip speeds and the work: exactly 0 where the contact rolls,
        // and the work of a conservative motion
        let mode = conservative_mode(model);
        let extra = ladder(digits, &["s1", "s12", "work"], |p| {
            let d = o.route.delta_of("theta", theta, p, digits)?;
            let (cols, _) = o.route.columns_at(&d, &Float::new(p), p)?;
            let sc = ladder::column_scales(model, p);
            let z = |i: usize, zero: bool| {
                if zero {
                    Estimate::zero_shared(p, sc[i].clone())
                } else {
                    Estimate::rounded(cols[i].clone(), (*sc[i]).clone())
                }
            };
            Ok(vec![
                z(col!("s1"), mode.floor != motion::State::Slip(0)),
                z(col!("s12"), mode.contact != motion::State::Slip(0)),
                Estimate::zero_shared(p, sc[col!("work")].clone()),
            ])
        })?;
        values.extend(extra);
        // the most friction needed so far is ill-conditioned as N12 -> 0
        // (|F21|/N12 grows without bound): where it cannot reach the digits
        // asked, it is given with the digits it does verify, not dropped
        // with the whole answer
        if crate::integrate::energy::mass_spread_bits(ideal.params()).is_none() {
            ans.notes.push(ideal::NOT_COMPARED.to_string());
        }
        match o.friction_needed(theta) {
            Ok(v) => values.extend(v),
            Err(e) => {
                let (quantity, got) = match &e {
                    Error::NotConverged {
                        quantity, reached, ..
                    } => (
                        quantity.clone(),
                        reached
                            .split_whitespace()
                            .next()
                            .and_then(|n| n.parse::<u32>().ok())
                            .unwrap_or(0),
                    ),
                    _ => return Err(e),
                };
                if got == 0 {
                    return Err(e);
                }
                // fewer digits at lower working precisions may verify fewer
                // still: step down until the ladder agrees
                let mut d = got;
                let (got, v) = loop {
                    match Oracle::new(&ideal, d).and_then(|mut o| o.friction_needed(theta)) {
                        Ok(v) => break (d, v),
                        Err(Error::NotConverged { .. }) if d > 1 => d = (d * 2 / 3).max(1),
                        Err(_) => return Err(e),
                    }
                };
                values.extend(v);
                ans.notes.push(format!(
                    "the most friction needed so far (theta_mu_*_max, mu_*_max) is given to {got} \
                     digits only, not the {digits} asked: {quantity}, the friction a rolling \
                     contact needs, |F|/N, grows without bound as N -> 0, and the two working \
                     precisions agree no further here"
                ));
            }
        }
        ans.values = values;
        if o.route.at_separation {
            ans.notes.push(at_separation_note(theta));
        }
        ans.notes.extend(o.branch_window_note(theta)?);
        ans.phase = Some(Phase::Contact(mode));
        ans.start_mode = Some(mode);
        ans.routes.push(motion::Route::Energy);
        return Ok(ans);
    }
    let cols = [
        col!("F1"),
        col!("N1"),
        col!("F21"),
        col!("N12"),
        col!("theta_dot"),
        col!("theta_ddot"),
        col!("s1"),
        col!("s12"),
        col!("work"),
    ];
    let keys = cols.map(|k| motion::COLUMNS[k]);
    let (v, phase, note, start) = at_angle(model, opts, theta, "theta", &keys, |pt| {
        let p = pt.t.prec();
        let all = ladder::point_estimates(pt, &ladder::column_scales(model, p), None);
        cols.iter().map(|&k| all[k].clone()).collect()
    })?;
    let mut values: Vec<Verified> = v[..6].to_vec();
    let mode = phase.mode();
    for (key, fi, ni, which) in [
        ("mu_floor", 0usize, 1usize, Which::Floor),
        ("mu_contact", 2, 3, Which::Contact),
    ] {
        let applies = *model.law(which) != Law::Frictionless
            && mode.is_some_and(|m| m.of(which) != motion::State::Slip(0));
        values.push(friction_ratio(key, &v[fi], &v[ni], applies, digits)?);
    }
    values.extend(v[6..].iter().cloned());
    ans.values = values;
    ans.phase = Some(phase);
    ans.start_mode = Some(start);
    ans.notes.extend(note);
    Ok(ans)
}
