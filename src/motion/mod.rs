//! One hybrid motion for every contact law: a sequence of phases — a mode
//! of the contacts, or the free flight after separation — separated by
//! typed events, from the start to the end of the model (the first impact,
//! or a lift-off).
//!
//! * [`mode`]: the vocabulary (contact states, modes, phases, event kinds,
//!   how the motion ends, which branch to follow where it is not unique).
//! * [`ctx`]: the fixed parts at one working precision; the constrained
//!   system of each mode (a sticking contact is a velocity constraint whose
//!   multiplier is its tangential force; a slipping one the applied force
//!   −μk σ N with N the multiplier of its normal row).
//! * [`decide`]: at the start and at every event every candidate
//!   continuation is tested for consistency just after it; a contact at
//!   rest sticks if it can; where a closed mode and the contact opening are
//!   both consistent (a branch point) the requested [`Branch`] decides.
//! * [`watch`]: the functions whose zeros end a mode.
//! * [`conservative`]: the fast path of a conservative first phase (every
//!   contact rolling, sticking, frictionless or held): the energy route,
//!   with its closed forms and quadratures.
//! * A dissipative phase is integrated by Chebyshev spectral quadrature in
//!   the angle ([`crate::integrate::spectral`]); a mode the angle cannot
//!   parametrise by Gragg–Bulirsch–Stoer extrapolation in time.
//! * [`request`]: what is asked of a run ([`Request`]: times, how far, the
//!   branch, the integrators) and what it gives ([`Motion`]: the events,
//!   rows, separation, impact and end; [`EventRec`]), with the caches
//!   kept between runs.
//! * `walk`: the mutable state of one run (the answer being built, the
//!   next requested time, the energy balance, the end of the model).
//! * [`flight`]: after separation, cylinder 2 flies ballistically and
//!   cylinder 1 goes on under its floor law, in closed form, to the first
//!   impact.
//!
//! [`run`] computes the motion at one working precision; the verified
//! answers (two precisions, the precision ladder) are [`crate::oracle`]'s.
//!
//! Slip speeds (README, "Conventions"): floor s1 = ẋ1 − r1 φ̇1, contact
//! s12 = r θ̇ + r2 ψ̇2 − r1 φ̇1 (ψ2 = φ2 − θ the counter-clockwise rotation
//! of cylinder 2). A slipping contact's tangential force is
//! F1 = −μk N1 sgn s1, F21 = −μk N12 sgn s12.

pub mod conservative;
pub mod ctx;
pub mod decide;
pub mod flight;
pub mod mode;
pub mod point;
pub mod request;
pub mod sides;
mod walk;
pub mod watch;

pub use mode::{Branch, End, Kind, Mode, Phase, State, Surface};
pub use point::{Point, TwoState, COLUMNS};
pub use request::{Caches, EventRec, Method, Motion, Request, Route, Until};
pub use sides::Side;

use crate::error::{Error, Result};
use crate::integrate::energy::Route as EnergyRoute;
use crate::integrate::solve::{self, Event, Sample, Start, Watch};
use crate::mechanics::system::{self as sy};
use crate::model::{Model, Which};
use ctx::Ctx;
use rug::Float;
use walk::Walk;
use watch::What;

/// Most mode changes followed before giving up (a Zeno cascade).
pub const MAX_MODES: usize = 64;

/// Default horizon: four times the separation time of the same model with
/// both contacts rolling (friction makes the cylinders part earlier) plus
/// 50 sqrt(r/g); 200 sqrt(r/g) if that time is not finite.
///
/// At 64 bits: a bound, needed to a few digits only; the answers compute it
/// once for both precisions of their ladder.
pub fn default_horizon(model: &Model) -> Float {
    let prec = 64;
    let ideal = model.sticking();
    let sm = crate::mechanics::system::StackModel::from_model(&ideal);
    let ts = crate::integrate::time_scale(&sm, prec);
    let rolling = crate::model::Ideal::new(
        model.params().clone(),
        if ideal.floor() == crate::model::Floor::Fixed {
            crate::model::Floor::Fixed
        } else {
            crate::model::Floor::Roll
        },
        crate::model::Contact::Roll,
        model.start().clone(),
    );
    let t_roll = rolling.ok().and_then(|m| {
        let mut r = EnergyRoute::new(&m).ok()?;
        let (ds, _) = r.delta_s(prec).ok()?;
        let (t, _) = r.engine(prec).ok()?.time(&ds);
        Some(t)
    });
    match t_roll {
        Some(t) => Float::with_val(prec, &t * 4u32) + ts * 50u32,
        None => ts * 200u32,
    }
}

/// The motion of `model` at working precision `prec`.
///
/// Errors: a start from rest exactly at the top (every time infinite); a
/// requested time after the end of the model, or an angle not reached
/// while the cylinders touch ([`Error::InvalidParameter`]); an undecidable
/// mode change (Painlevé-type situations) or a grazing event
/// ([`Error::NotConverged`]); an integrator's failure.
pub fn run(model: &Model, req: &Request, prec: u32, caches: &mut Caches) -> Result<Motion> {
    let mut m = walk(model, req, prec, caches)?;
    if m.events.iter().any(|e| e.kind == Kind::Indeterminate) {
        let ctx = Ctx::new(model, prec)?;
        for e in m
            .events
            .iter_mut()
            .filter(|e| e.kind == Kind::Indeterminate)
        {
            if let Some(mode) = e.at.phase.mode() {
                let s = conservative::sample_at(&ctx, mode, &e.at)?;
                e.also = decide::alternatives(&ctx, mode, &s.q, &s.v)?;
                // where the motion parted here (the part branch), the other
                // continuation is the closed mode it left, not "part"
                if matches!(e.phase, Some(Phase::Flight { .. })) {
                    for a in e.also.iter_mut().filter(|a| *a == "part") {
                        *a = mode.tag();
                    }
                }
            }
        }
    }
    sides::mark_near(&mut m, req, prec);
    sides::apply_sides(&mut m, req)?;
    sides::trim_events(&mut m, req, prec, model.direction());
    Ok(m)
}

/// Each sliding contact's slip speed keeps its mode's sign along the phase
/// (at every sample the integration kept, and where it stopped): a slip
/// window that closes within one piece (the floor sticking again ~7·10^-5
/// after a slip onset near a tangency of its friction cone, μ 3·10^-11 below
/// the most the motion needs) was not located, the contact slid on with its
/// slip speed of the other sign — friction doing work on the motion — and
/// wrong numbers were printed as verified. Not computed at this precision.
///
/// Errors: a slip speed of the wrong sign beyond the test's resolution.
fn slip_signs_hold(
    ctx: &Ctx,
    sys: &crate::mechanics::system::System,
    mode: mode::Mode,
    run: &solve::Run,
) -> Result<()> {
    let wp = sys.prec;
    let tiny = Float::with_val(wp, &ctx.base_r / &ctx.ts) * &ctx.rel_tiny;
    for (which, st) in [(Which::Floor, mode.floor), (Which::Contact, mode.contact)] {
        let mode::State::Slip(sg) = st else { continue };
        if sg == 0 {
            continue;
        }
        let samples = run
            .checkpoints
            .iter()
            .chain(&run.outputs)
            .chain(run.hits.last().map(|h| &h.at));
        for smp in samples {
            let v = sys.slip_speed(ctx::tangent(which), &smp.q, &smp.v);
            let wrong = if sg > 0 {
                Float::with_val(wp, -&v)
            } else {
                v.clone()
            };
            if wrong > tiny {
                return Err(Error::NotConverged {
                    quantity: "slip phase".into(),
                    requested: 0,
                    reached: format!(
                        "the {} slides {} while its slip speed is {} at t = {}",
                        which.name(),
                        if sg > 0 { "forwards" } else { "backwards" },
                        crate::numeric::decimal::short_near(&Float::with_val(64, &v)),
                        crate::numeric::decimal::to_sig(&smp.t, 12)
                    ),
                    detail: format!(
                        "the {} sticks again within a step of the integration (a short slip \
                         window, near a tangency of its friction cone) and the return of its \
                         slip speed to 0 was not located; not computed at this precision (a \
                         higher --digits may resolve it)",
                        which.name()
                    ),
                });
            }
        }
    }
    Ok(())
}

/// The error of a `--part-at` angle where parting is not lawful.
pub(crate) fn part_at_refused(branch: &Branch) -> Error {
    let th = match branch {
        Branch::PartAt(a) => a.to_string(),
        _ => String::new(),
    };
    Error::invalid(
        "part-at",
        th,
        "must lie where parting is lawful (the window between the branch point \
         theta_indeterminate and the end of the closed branch)",
    )
}

/// [`run`] before the sides of times at events are marked and applied.
fn walk(model: &Model, req: &Request, prec: u32, caches: &mut Caches) -> Result<Motion> {
    if model.starts_at_equilibrium() {
        return Err(Error::not_physical(
            "the motion starts from rest exactly at the unstable top: every time is infinite",
        ));
    }
    let ctx = Ctx::new(model, prec)?;
    let wp = ctx.wp;
    // the start's velocities under each contact's first law: a
    // frictionless contact's spin is the one its conserved momentum gives
    // (omega0's reference), not the rolling one
    let mut sys0 = ctx.system(Mode {
        floor: ctx.candidates(Which::Floor)[0],
        contact: ctx.candidates(Which::Contact)[0],
    })?;
    let (q0, v0) = sys0.initial_state(&ctx.base)?;
    let e0 = sys0.energy(&q0, &v0);
    let zero = Float::new(wp);
    // whether the contact may open at the start: the closed motion's exact
    // sign where it has one (the test reads a rounding where the free
    // normal acceleration is 0 at θ0). Its refusal of a start at the
    // parting, or too close to it to compute, is the answer (the mode test
    // read the rounding of 0 and called such a start a Painlevé
    // inconsistency); a start the closed motion finds past the parting may
    // still hold in a sliding mode, which the test decides
    let opens = match caches.sticking(model) {
        Ok(route) => {
            let hp = route.free_normal_poly();
            match route.sign_at_start(&hp, req.digits)? {
                0 => None,
                s => Some(s > 0),
            }
        }
        // with friction the closed motion is one candidate among others:
        // its parting at the start does not decide the start (sticking may
        // fail μ by far, and the cylinders part at once)
        Err(e @ Error::NotConverged { .. }) if !model.has_coulomb() => return Err(e),
        Err(_) => None,
    };
    // a start that holds (N12 > 0 in the closed motion), but so close to
    // the parting that the parting comes within the mode test's step (θs ~
    // 10^-8 after θ0 = 0.1 at N12 = 10^-16 m2 g): not decided, whatever the
    // test concludes there (it called the start a Painlevé inconsistency,
    // or parting at once for friction the model does not have)
    let step = Float::with_val(64, 1u32) >> (wp as i32 / 3 - 16);
    let coulomb = model.has_coulomb();
    let too_close = |caches: &Caches| {
        if coulomb {
            return None;
        }
        caches
            .sticking
            .as_ref()
            .map(|r| r.n12_start.clone())
            .filter(|n| n.is_sign_positive() && *n < step)
            .map(|n12| Error::NotConverged {
                quantity: "mode at the start".into(),
                requested: 0,
                reached: "no candidate passed the test at t = 0".into(),
                detail: format!(
                    "N12 = {} m2 g > 0 at the start holds the cylinders together, but the start \
                     lies so close to the parting that it comes within the mode test's step at \
                     this precision; not decided (not a Painlevé-type inconsistency)",
                    crate::numeric::decimal::short_near(&n12)
                ),
            })
    };
    let choice = match decide::decide_with(&ctx, &q0, &v0, &zero, &req.branch, opens) {
        Ok(c) => c,
        Err(e) => {
            caches.sticking(model)?;
            return Err(too_close(caches).unwrap_or(e));
        }
    };
    // parting lawful from the start, on the part branch: the closed mode's
    // energy route parts at δ = 0 (the branch point at θ0, then the
    // separation there); the other routes have no such ending
    let choice = match (choice.mode, choice.closed) {
        (None, Some(closed)) if choice.branch_point => {
            if req.method == Method::Auto && closed.is_conservative() {
                decide::Choice {
                    mode: Some(closed),
                    ..choice
                }
            } else {
                return Err(Error::NotConverged {
                    quantity: "mode at the start".into(),
                    requested: 0,
                    reached: "parting lawful from the start".into(),
                    detail: "on the part branch from a start where parting is already lawful, \
                             only the energy route of a conservative start is computed (--branch \
                             stay follows the closed motion)"
                        .into(),
                });
            }
        }
        _ => choice,
    };
    // no closed mode, and the free motion parts: where the closed motion
    // presses at the start (its route was made), the start is too close to
    // the parting for the test, or friction is why
    let mut mode = match choice.mode {
        Some(m) => m,
        None => {
            if let Some(e) = too_close(caches) {
                return Err(e);
            }
            if !model.has_coulomb() {
                caches.sticking(model)?;
            }
            return Err(Error::not_physical(
                if caches.sticking.is_some() && model.has_coulomb() {
                    "the cylinders part at once: the closed motion would press (N12 > 0 at the \
                     start), but no closed mode is consistent with the contact laws there \
                     (sticking would need more friction than mu_s, and no sliding mode holds), \
                     and the free motion parts"
                } else {
                    "the cylinders part at once: N12 <= 0 at the start in every mode \
                     (the start lies past the parting: theta0, thetadot0 or omega0 too large)"
                },
            ));
        }
    };
    let mut w = Walk {
        ctx: &ctx,
        req,
        out: Motion {
            start_mode: mode,
            events: Vec::new(),
            // room for a row (or an angle) at every time asked: a row is
            // large, and a growing vector would copy every row before it
            rows: Vec::with_capacity(if req.theta_only { 0 } else { req.times.len() }),
            deltas: Vec::new(),
            thetas: Vec::with_capacity(if req.theta_only { req.times.len() } else { 0 }),
            separation: None,
            impact: None,
            end: None,
            target: None,
            energy_drift: Float::new(wp),
            energy_unit: Float::with_val(wp, Float::with_val(wp, e0.abs_ref()) / &ctx.escale)
                .max(&Float::with_val(wp, 1u32)),
            work_done: (0, 0),
            routes: Vec::new(),
            windows: Vec::new(),
            merged_branch: false,
            near: Vec::new(),
            target_near: None,
            ts: ctx.ts.clone(),
            times: caches
                .times
                .rounded()
                .and_then(|r| r.rounded_of(&req.times, wp))
                .unwrap_or_else(|| req.times.iter().map(|t| t.to_float(wp)).collect()),
        },
        next: 0,
        e0,
        conservative: true,
    };
    let mut t = Float::new(wp);
    let mut q = q0;
    let mut v = v0;
    let mut work = Float::new(wp);
    let mut window_open = false;
    // the angle to stop at, in the user frame, and how far past it events
    // are still looked for (an event the target cannot be told from)
    let mut target_theta = match &req.until {
        Until::Angle { theta, .. } => Some(theta.clone()),
        _ => None,
    };
    let beyond = target_theta.as_ref().map(|th| {
        let bits = crate::numeric::bits_for_digits(req.digits.max(1)) as i32;
        (Float::with_val(wp, th.to_float(wp).abs_ref()) + 1u32) >> (bits / 4 + 4)
    });
    let beyond_theta = target_theta.as_ref().zip(beyond.as_ref()).map(|(th, b)| {
        Float::with_val(
            wp,
            th.to_float(wp) + Float::with_val(wp, b * model.direction()),
        )
    });
    let t_end = match req.until {
        // a little past the last time (2^−p/4 of the time scale, far beyond
        // an event's margin): an event that the last time cannot be told
        // apart from is located too
        Until::LastTime => {
            let last = w
                .out
                .times
                .last()
                .cloned()
                .unwrap_or_else(|| Float::new(wp));
            let bits = crate::numeric::bits_for_digits(req.digits.max(1)) as i32;
            let beyond = (Float::with_val(wp, last.abs_ref()) + &ctx.ts) >> (bits / 4 + 4);
            last + beyond
        }
        _ => match &req.horizon {
            Some(h) => Float::with_val(wp, h),
            None => Float::with_val(wp, caches.horizon(model)),
        },
    };
    // --- a conservative first phase: the energy route
    crate::cancel::check()?;
    if req.method == Method::Auto && mode.is_conservative() {
        // the route and the table's times: two of the caches at once
        if caches.sticking.is_none() {
            caches.sticking(model)?;
        }
        let route = caches.sticking.as_mut().expect("made above");
        let wants = conservative::Wants {
            times: &req.times,
            times_f: &w.out.times,
            run: req.run,
            digits: req.digits,
            theta_only: req.theta_only,
            branch: &req.branch,
            target: target_theta.as_ref(),
            beyond: beyond.clone(),
            low_deltas: &req.low_deltas,
            derived_at_high: req.derived_at_high,
        };
        let fast = conservative::first_phase(&ctx, route, &mut caches.times, mode, &wants, prec)?;
        crate::cancel::check()?;
        w.out.routes.push(Route::Energy);
        for e in fast.events {
            w.note(&e.at);
            w.out.events.push(e);
            window_open = true;
        }
        w.out.merged_branch = fast.merged_branch;
        if let Some(win) = fast.window {
            w.out.windows.push(win);
        }
        w.out.deltas = fast.deltas;
        for pt in fast.rows {
            w.push_row(pt);
        }
        for th in fast.thetas {
            w.out.thetas.push(th);
        }
        if let Some(tp) = fast.target_point {
            w.out.target = Some(tp);
            target_theta = None;
        }
        w.next = fast.covered;
        let at = fast.end_point;
        w.note(&at);
        let (t_err, theta_err) = fast.end_err;
        let ev = |kind, which, phase| EventRec {
            kind,
            which,
            phase,
            at: at.clone(),
            t_err: t_err.clone(),
            theta_err: theta_err.clone(),
            after: None,
            also: Vec::new(),
        };
        use conservative::Ending;
        match fast.ending {
            Ending::Target => {
                w.out.target = Some(at);
                return Ok(w.out);
            }
            Ending::LiftOff => {
                w.lift_off(ev(Kind::LiftOff, Some(Which::Floor), None))?;
                return Ok(w.out);
            }
            Ending::FloorImpact => {
                w.floor_impact(ev(Kind::Impact, None, None), mode, &fast.end_sample, &at)?;
                return Ok(w.out);
            }
            Ending::Separation | Ending::BranchPart | Ending::PartAt => {
                if fast.ending != Ending::Separation && !window_open {
                    w.out.events.push(ev(
                        Kind::Indeterminate,
                        Some(Which::Contact),
                        Some(Phase::Flight { floor: mode.floor }),
                    ));
                }
                let e = ev(
                    Kind::Separation,
                    Some(Which::Contact),
                    Some(Phase::Flight { floor: mode.floor }),
                );
                w.part(e, mode, &fast.end_sample, &at)?;
                return Ok(w.out);
            }
            Ending::Cone(which) => {
                let s = fast.end_sample;
                let choice = decide::decide(&ctx, &s.q, &s.v, &s.t, &req.branch)?;
                let new = match choice.mode {
                    Some(m) => m,
                    None => {
                        // no closed mode is consistent: the contact opens
                        let e = ev(
                            Kind::Separation,
                            Some(Which::Contact),
                            Some(Phase::Flight { floor: mode.floor }),
                        );
                        w.part(e, mode, &s, &at)?;
                        return Ok(w.out);
                    }
                };
                if new == mode {
                    return Err(grazing(&format!("cone:{}", which.name()), &at.t, mode));
                }
                let after = just_after(&ctx, new, &s, w.conservative)?;
                push_changes(&mut w.out, mode, new, &at, &t_err, &theta_err, after);
                t = s.t.clone();
                q = s.q.clone();
                v = s.v.clone();
                work = s.work.clone();
                mode = new;
            }
        }
    }
    // --- the other phases: the spectral route in θ, GBS where it declines
    for _ in 0..MAX_MODES {
        crate::cancel::check()?;
        // a table whose times all lie before this phase (its last time by
        // more than the margin): nothing after them is asked (the energy
        // route's first phase finds its end whatever the times)
        if req.until == Until::LastTime && w.next >= w.out.times.len() && t > t_end {
            return Ok(w.out);
        }
        let mut sys = ctx.system(mode)?;
        // the branch watch (parting becoming lawful) while the contact holds
        let branch_watch = !ctx.held;
        let mut ws = watch::of_mode(&ctx, &sys, mode, branch_watch);
        if let Some(th) = &target_theta {
            ws.events.push(Event {
                name: "target".into(),
                watch: Watch::Reach {
                    i: sy::th(0),
                    value: th.to_float(wp),
                },
                terminal: true,
            });
            ws.what.push(What::Target);
        } else if let (Some(b), true) = (&beyond_theta, w.out.target.is_some()) {
            // the target is behind: look a little past it, then stop
            ws.events.push(Event {
                name: "beyond".into(),
                watch: Watch::Reach {
                    i: sy::th(0),
                    value: b.clone(),
                },
                terminal: true,
            });
            ws.what.push(What::Beyond);
        }
        if let Branch::PartAt(th) = &req.branch {
            ws.events.push(Event {
                name: "part_at".into(),
                watch: Watch::Reach {
                    i: sy::th(0),
                    value: th.to_float(wp),
                },
                terminal: true,
            });
            ws.what.push(What::PartAt);
        }
        // a target at the present angle (to within the last event's margin,
        // or already passed at this precision)
        if let Some(th) = &target_theta {
            let ahead = Float::with_val(wp, th.to_float(wp) - &q[sy::th(0)]) * model.direction();
            let err = w
                .out
                .events
                .last()
                .map_or_else(|| Float::new(wp), |e| Float::with_val(wp, &e.theta_err));
            let passed = !ahead.is_sign_positive()
                || sides::side_of(&th.to_float(wp), &q[sy::th(0)], &err, prec, None).is_none();
            if passed {
                let acc = sys.accel(&q, &v)?;
                let smp = sample(&t, &q, &v, acc, &work);
                w.out.target = Some(ctx.point(&mut sys, mode, &smp, w.conservative));
                return Ok(w.out);
            }
        }
        let start = Start {
            t: t.clone(),
            q: &q,
            v: &v,
            work: work.clone(),
            snap: ctx.snaps(&ws.events),
        };
        let times = &w.out.times[w.next..];
        let spectral = match req.method {
            Method::Auto | Method::Spectral => crate::integrate::spectral::run(
                &mut sys,
                &start,
                times,
                &t_end,
                &ws.events,
                &crate::integrate::spectral::Settings {
                    tol: ctx.opts.tol.clone(),
                    full: !req.theta_only,
                    ts: ctx.ts.clone(),
                    r: ctx.base_r.clone(),
                    escale: ctx.escale.clone(),
                },
            )?,
            _ => None,
        };
        w.out.routes.push(match (&spectral, req.method) {
            (Some(_), _) => Route::Spectral,
            (None, Method::Collocation) => Route::Collocation,
            (None, _) => Route::Gbs,
        });
        let run = match (spectral, req.method) {
            (Some(run), _) => run,
            (None, Method::Collocation) => {
                let stages = (wp as usize / 12).clamp(4, 24);
                let mut co = crate::integrate::collocation::Collocation::new(
                    wp,
                    ctx.opts.tol.clone(),
                    ctx.opts.h0(),
                    stages,
                );
                solve::run_with(
                    &mut sys, &start, times, &t_end, &ws.events, &ctx.opts, &mut co,
                )?
            }
            (None, _) => solve::run_from(&mut sys, &start, times, &t_end, &ws.events, &ctx.opts)?,
        };
        w.out.work_done.0 += run.stats.steps;
        w.out.work_done.1 += run.stats.evals;
        slip_signs_hold(&ctx, &sys, mode, &run)?;
        if !mode.is_conservative() {
            w.conservative = false;
        }
        for s in &run.checkpoints {
            let pt = ctx.point(&mut sys, mode, s, w.conservative);
            w.note(&pt);
        }
        let full = !req.theta_only || w.out.routes.last() != Some(&Route::Spectral);
        for s in &run.outputs {
            if req.theta_only {
                w.out
                    .thetas
                    .push((s.q[sy::th(0)].clone(), Phase::Contact(mode), None));
            }
            if !full {
                continue;
            }
            let pt = ctx.point(&mut sys, mode, s, w.conservative);
            w.note(&pt);
            if !req.theta_only {
                w.out.rows.push(pt);
            }
        }
        w.next += run.outputs.len();
        if !run.stopped {
            let end_pt = ctx.point(&mut sys, mode, &run.last, w.conservative);
            w.note(&end_pt);
            if req.until != Until::LastTime {
                return Err(Error::NotConverged {
                    quantity: "motion".into(),
                    requested: req.digits,
                    reached: format!(
                        "no end of the motion before t = {} (the horizon searched)",
                        crate::numeric::decimal::to_sig(&t_end, 7)
                    ),
                    detail: "the horizon is four times the rolling model's separation time".into(),
                });
            }
            return Ok(w.out);
        }
        let hit = run
            .hits
            .last()
            .ok_or_else(|| Error::not_physical("internal: a stop without an event"))?;
        let at = ctx.point(&mut sys, mode, &hit.at, w.conservative);
        w.note(&at);
        let mut what = ws.what[hit.event];
        // ρ̈_free vanishes with N12 where the contact slides (no force left
        // between the cylinders) or cylinder 1 is held: that zero is the
        // separation, not a branch point
        if what == What::FreeNormal {
            let tiny_n = Float::with_val(wp, &ctx.escale / &ctx.base_r) * &ctx.rel_tiny;
            if Float::with_val(wp, at.n12.abs_ref()) <= tiny_n {
                what = What::Separation;
            }
        }
        let theta_err = Float::with_val(wp, at.theta_dot.abs_ref()) * &hit.t_err;
        let ev = |kind, which, phase| EventRec {
            kind,
            which,
            phase,
            at: at.clone(),
            t_err: hit.t_err.clone(),
            theta_err: theta_err.clone(),
            after: None,
            also: Vec::new(),
        };
        let flight_phase = Phase::Flight { floor: mode.floor };
        match what {
            What::Target => {
                // keep the state at the angle, and look a little past it;
                // an event whose watch is already 0 at the angle (to the
                // integration's accuracy) lies at the angle itself
                let vals = solve::watch_values(ws.events.iter().map(|e| &e.watch), &hit.at);
                let accs = ctx.accuracies(&ws.events);
                // only a watch the phase armed: one already 0 at the phase's
                // start (to its snap, the integrator's own rule) has not
                // come back to 0 at the angle, it has not left it yet — a
                // slip speed just after its own slip onset was recorded as
                // a stick at the angle, and the two precisions disagreed on
                // the events (or a note said the angle was the event's state)
                let acc0 = sys.accel(&q, &v)?;
                let s0 = sample(&t, &q, &v, acc0, &work);
                let vals0 = solve::watch_values(ws.events.iter().map(|e| &e.watch), &s0);
                let snaps = ctx.snaps(&ws.events);
                let at_zero = ws.what.iter().enumerate().find_map(|(k, wt)| {
                    let armed = Float::with_val(wp, vals0[k].abs_ref()) > snaps[k];
                    let kind = match wt {
                        _ if !armed => return None,
                        What::Separation => (Kind::Separation, Some(Which::Contact)),
                        What::LiftOff => (Kind::LiftOff, Some(Which::Floor)),
                        What::FloorImpact => (Kind::Impact, None),
                        What::Cone(c) => (Kind::SlipOnset, Some(*c)),
                        What::SlipZero(c) => (Kind::Stick, Some(*c)),
                        _ => return None,
                    };
                    (Float::with_val(wp, vals[k].abs_ref()) <= accs[k]).then_some(kind)
                });
                w.out.target = Some(at.clone());
                if let Some((kind, which)) = at_zero {
                    w.out.events.push(ev(kind, which, None));
                    return Ok(w.out);
                }
                target_theta = None;
                t = hit.at.t.clone();
                q = hit.at.q.clone();
                v = hit.at.v.clone();
                work = hit.at.work.clone();
                continue;
            }
            What::Beyond => return Ok(w.out),
            What::FloorImpact => {
                w.floor_impact(ev(Kind::Impact, None, None), mode, &hit.at, &at)?;
                return Ok(w.out);
            }
            What::LiftOff => {
                w.lift_off(ev(Kind::LiftOff, Some(Which::Floor), None))?;
                return Ok(w.out);
            }
            What::Separation => {
                let e = ev(Kind::Separation, Some(Which::Contact), Some(flight_phase));
                w.part(e, mode, &hit.at, &at)?;
                return Ok(w.out);
            }
            What::FreeNormal | What::PartAt => {
                // parting becomes lawful (the free motion separates while
                // the contact still holds), or stops being so
                let rising = what == What::PartAt || !window_open;
                if what == What::FreeNormal {
                    if rising {
                        window_open = true;
                        w.out.windows.push((at.theta.clone(), None));
                        let entered = if req.branch == Branch::Part {
                            flight_phase
                        } else {
                            Phase::Contact(mode)
                        };
                        let mut e = ev(Kind::Indeterminate, Some(Which::Contact), Some(entered));
                        e.after = after_if_unchanged(&at, entered);
                        w.out.events.push(e);
                    } else {
                        window_open = false;
                        if let Some(last) = w.out.windows.last_mut() {
                            last.1 = Some(at.theta.clone());
                        }
                    }
                }
                let part_now = match (&req.branch, what) {
                    (Branch::Part, What::FreeNormal) => rising,
                    (Branch::PartAt(_), What::PartAt) => {
                        if !window_open {
                            return Err(part_at_refused(&req.branch));
                        }
                        true
                    }
                    _ => false,
                };
                if part_now {
                    let e = ev(Kind::Separation, Some(Which::Contact), Some(flight_phase));
                    w.part(e, mode, &hit.at, &at)?;
                    return Ok(w.out);
                }
                // the same mode goes on from here
                t = hit.at.t.clone();
                q = hit.at.q.clone();
                v = hit.at.v.clone();
                work = hit.at.work.clone();
                continue;
            }
            What::Cone(_) | What::SlipZero(_) => {}
        }
        // a change of friction state, or the contact opening
        let choice = decide::decide(&ctx, &hit.at.q, &hit.at.v, &hit.at.t, &req.branch)?;
        if choice.branch_point && !window_open {
            window_open = true;
            w.out.windows.push((at.theta.clone(), None));
            let entered = choice.mode.map_or(flight_phase, Phase::Contact);
            let mut e = ev(Kind::Indeterminate, Some(Which::Contact), Some(entered));
            e.after = after_if_unchanged(&at, entered);
            w.out.events.push(e);
        }
        let Some(new) = choice.mode else {
            let e = ev(Kind::Separation, Some(Which::Contact), Some(flight_phase));
            w.part(e, mode, &hit.at, &at)?;
            return Ok(w.out);
        };
        if new == mode {
            return Err(grazing(&ws.events[hit.event].name, &at.t, mode));
        }
        let after = just_after(&ctx, new, &hit.at, w.conservative && new.is_conservative())?;
        push_changes(&mut w.out, mode, new, &at, &hit.t_err, &theta_err, after);
        t = hit.at.t.clone();
        q = hit.at.q.clone();
        v = hit.at.v.clone();
        work = hit.at.work.clone();
        mode = new;
    }
    Err(Error::NotConverged {
        quantity: "mode".into(),
        requested: req.digits,
        reached: format!("more than {MAX_MODES} mode changes"),
        detail: format!(
            "stopped at t = {} (a Zeno cascade of stick-slip events?)",
            crate::numeric::decimal::to_sig(&t, 12)
        ),
    })
}

fn sample(
    t: &Float,
    q: &[Float],
    v: &[Float],
    acc: crate::mechanics::system::Accel,
    work: &Float,
) -> Sample {
    Sample {
        t: t.clone(),
        q: q.to_vec(),
        v: v.to_vec(),
        qdd: acc.qdd,
        lambda: acc.lambda,
        work: work.clone(),
        power: Float::new(t.prec()),
        trig: Vec::new(),
        energy: None,
    }
}

fn grazing(name: &str, t: &Float, mode: Mode) -> Error {
    Error::NotConverged {
        quantity: "mode".into(),
        requested: 0,
        reached: format!(
            "event {name} at t = {} leaves the mode {} unchanged",
            crate::numeric::decimal::to_sig(t, 12),
            mode.tag()
        ),
        detail: "a grazing event the rigid-body model cannot resolve at this precision".into(),
    }
}

/// A branch point's state after: the state at it where the phase it
/// enters is the one it was in (the `stay` branch goes on in the same
/// mode); else none of its own, and the rows just past it take the next
/// event's at the same instant (the parting's first flight state, the new
/// mode's: [`sides`]' `with_after`). The state at it, given as the state
/// after a parting, kept the closed mode's θ̈, forces and mode for a row
/// just past the parting (printed as verified, with θ off by θ̇ times the
/// row's distance from the event).
fn after_if_unchanged(at: &Point, entered: Phase) -> Option<Point> {
    (at.phase == entered).then(|| at.clone())
}

/// The state just after an event at sample `s`, in the mode entered (its
/// forces and accelerations; positions and velocities are continuous).
///
/// Errors: a singular constraint system.
fn just_after(ctx: &Ctx, mode: Mode, s: &Sample, conservative: bool) -> Result<Point> {
    let mut sys = ctx.system(mode)?;
    let acc = sys.accel(&s.q, &s.v)?;
    let smp = sample(&s.t, &s.q, &s.v, acc, &s.work);
    Ok(ctx.point(&mut sys, mode, &smp, conservative))
}

/// The events of a change of contact states from `old` to `new` at `at`.
#[allow(clippy::too_many_arguments)]
fn push_changes(
    out: &mut Motion,
    old: Mode,
    new: Mode,
    at: &Point,
    t_err: &Float,
    th_err: &Float,
    after: Point,
) {
    for w in [Which::Floor, Which::Contact] {
        let (o, n) = (old.of(w), new.of(w));
        if o == n {
            continue;
        }
        let kind = match (o, n) {
            (State::Stick, _) => Kind::SlipOnset,
            (State::Slip(_), State::Stick) => Kind::Stick,
            _ => Kind::SlipReversal,
        };
        out.events.push(EventRec {
            kind,
            which: Some(w),
            phase: Some(Phase::Contact(new)),
            at: at.clone(),
            t_err: t_err.clone(),
            theta_err: th_err.clone(),
            after: Some(after.clone()),
            also: Vec::new(),
        });
    }
}
