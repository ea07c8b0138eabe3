//! The fast path of a conservative first phase: while every contact rolls,
//! sticks, is frictionless or held, the energy integral holds and the
//! motion is the ideal model's ([`crate::integrate::energy`]): θ̇²(θ) in
//! closed form, t(θ) a quadrature, and each event that can end the phase
//! a root in the angle — N12 = 0, a Coulomb contact's cone, N1 = 0,
//! cylinder 2 reaching the floor, a branch point where parting becomes
//! lawful, or a requested angle. The phase ends at the first of them;
//! the motion goes on from the state there.

use super::ctx::Ctx;
use super::mode::{Branch, Kind, Mode, Phase};
use super::point::{col, Point, TwoState, COLUMNS};
use super::EventRec;
use crate::error::{Error, Result};
use crate::exact::{Exact, TableTimes};
use crate::integrate::energy::Route;
use crate::integrate::solve::Sample;
use crate::mechanics::system::{self as sy, System};
use crate::model::{Law, Which};
use crate::numeric::verify::Run;
use rug::{Assign, Float};

/// What ended the conservative phase.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ending {
    /// N12 = 0: the cylinders part (the closed branch's end).
    Separation,
    /// A Coulomb contact's needed |F|/N reached μs.
    Cone(Which),
    /// N1 = 0: cylinder 1 leaves the floor.
    LiftOff,
    /// Cylinder 2 reaches the floor while still on cylinder 1.
    FloorImpact,
    /// Parting became lawful and the `part` branch parts here.
    BranchPart,
    /// θ reached the requested angle of `--part-at`.
    PartAt,
    /// θ reached the requested target angle.
    Target,
}

/// The first phase computed by the energy route at one precision.
pub struct Fast {
    /// The rows at the requested times inside the phase (full columns).
    pub rows: Vec<Point>,
    /// δ = θ − θ0 (working frame) at each of `rows`.
    pub deltas: Vec<Float>,
    /// θ at the requested times inside the phase (θ only).
    pub thetas: Vec<(Float, Phase, Option<Float>)>,
    /// How many of the requested times the phase covered.
    pub covered: usize,
    /// Events inside the phase that do not end it (a branch point on the
    /// `stay` branch).
    pub events: Vec<EventRec>,
    /// What ended the phase.
    pub ending: Ending,
    /// The state at the target angle when the phase went on past it (to
    /// an event just beyond).
    pub target_point: Option<Point>,
    /// The state at the end, as a sample of the mode's constrained system
    /// (at the integrators' working precision).
    pub end_sample: Sample,
    /// Its columns.
    pub end_point: Point,
    /// Error estimates of the end's time and angle.
    pub end_err: (Float, Float),
    /// Where parting is lawful on this branch: (θ where it becomes so, θ
    /// where it stops — None: up to the phase's end).
    pub window: Option<(Float, Option<Float>)>,
    /// A branch point found before θs but taken as θs, being θs to the
    /// digits asked (the window where parting is lawful is narrower than
    /// they resolve).
    pub merged_branch: bool,
}

/// What the phase must also stop at or note.
pub struct Wants<'a> {
    /// The requested times (ascending).
    pub times: &'a [Exact],
    /// The same rounded to nearest ([`super::Motion::times`]; empty: not
    /// given), to decide most comparisons without the exact ones.
    pub times_f: &'a [Float],
    /// Which run of the ladder (the energy route certifies θ(t) differently).
    pub run: Run,
    /// Digits requested (for messages).
    pub digits: u32,
    /// θ only at the times.
    pub theta_only: bool,
    /// The branch to follow.
    pub branch: &'a Branch,
    /// An angle to stop at (user frame).
    pub target: Option<&'a Exact>,
    /// How far past the target to look for events (in θ, > 0): an event
    /// the target cannot be told from is located too.
    pub beyond: Option<Float>,
    /// δ at each requested time in the ladder's lower run
    /// ([`super::Request::low_deltas`]; empty: none).
    pub low_deltas: &'a [Float],
    /// The rows' columns but t and θ computed by the higher run alone
    /// ([`super::Request::derived_at_high`]).
    pub derived_at_high: bool,
}

/// How many of `times` (ascending) are at most `end`: decided from the
/// rounded times (`rounded`, all at one precision q, each within a unit
/// of its time: a rational's rounding half a unit, a multiple of π's a
/// unit) where a rounded time lies outside end·(1 ± 2^(4−q)) — there the
/// time is on the same side of `end` as its rounding —, exactly where it
/// lies inside (or the rounded times are not given, or `end` ≤ 0). A
/// table's times before a phase's end cost one comparison each, not a
/// division of big integers.
fn covered_times(times: &[Exact], rounded: &[Float], end: &Float) -> usize {
    let q = rounded.first().map_or(0, |r| r.prec());
    let usable = rounded.len() == times.len()
        && q > 8
        && end.is_sign_positive()
        && !end.is_zero()
        && rounded.iter().all(|r| r.prec() == q);
    let bounds = usable.then(|| {
        let p = end.prec().max(q) + 8;
        let e = Float::with_val(p, end);
        let rel = Float::with_val(p, &e >> (q as i32 - 4));
        let below = Float::with_val_round(p, &e - &rel, rug::float::Round::Down).0;
        let above = Float::with_val_round(p, &e + &rel, rug::float::Round::Up).0;
        (below, above)
    });
    times
        .iter()
        .enumerate()
        .take_while(|(i, t)| {
            if let Some((below, above)) = &bounds {
                let r = &rounded[*i];
                if r <= below {
                    return true;
                }
                if r >= above {
                    return false;
                }
            }
            t.le_float(end)
        })
        .count()
}

/// The first phase from the start, in the conservative mode `mode`, by
/// the energy route of `model.sticking()` (`table_times`: the requested
/// times at the Taylor route's precision, kept by the answer for the
/// ladder's other run).
///
/// Errors: the energy route's (a time it cannot certify, an angle it
/// cannot verify); an angle that is not reached in the phase is not an
/// error (the phase ends first).
pub fn first_phase(
    ctx: &Ctx,
    route: &mut Route,
    table_times: &mut TableTimes,
    mode: Mode,
    wants: &Wants,
    p: u32,
) -> Result<Fast> {
    let sign = route.sign;
    let th0w = route.work.start().theta0.to_float(p);
    // δs at p (cached): the closed branch's end
    let (ds, ds_err) = route.delta_s(p)?;
    crate::cancel::check()?;
    let mut refined: Vec<(Ending, Float, Float)> = vec![(Ending::Separation, ds.clone(), ds_err)];
    // the other events that can end the phase, as roots of polynomials in c
    if !ctx.held {
        let hp = route.n1_poly();
        if let Some((d, e)) = route.first_root("lift-off", &hp, None, &ds, p, wants.digits)? {
            refined.push((Ending::LiftOff, d, e));
        }
    }
    for w in [Which::Floor, Which::Contact] {
        if let Law::Coulomb { mu_s, .. } = ctx.law(w) {
            let (hp, unit) = route.cone_poly(w, mu_s);
            // a tangential force identically 0 (a massless upper cylinder's
            // spin rolling on the lower: k2 = 0) never leaves the cone; its
            // polynomial μ²N² has only N's double roots, where the search
            // found no sign change and refused
            if unit.is_zero() {
                continue;
            }
            if let Some((d, e)) =
                route.first_root("slip onset", &hp, Some(&unit), &ds, p, wants.digits)?
            {
                refined.push((Ending::Cone(w), d, e));
            }
        }
    }
    {
        // cylinder 2 reaching the floor: y2 = r2, cos θ = (r2 − r1)/r
        let thf = route.work.params().landing_angle(p);
        let df = Float::with_val(p, &thf - &th0w);
        if df.is_sign_positive() && df < ds {
            let ulp = Float::with_val(p, thf.abs_ref()) >> (p as i32 - 4);
            refined.push((Ending::FloorImpact, df, ulp));
        }
    }
    // the branch point: parting becomes lawful while the contact holds
    let mut starts_open = false;
    let mut branch_found: Option<(Float, Float)> = None;
    // none under a frictionless contact: there ρ̈_free > 0 only where
    // N12 < 0, so the root of the free normal acceleration is θs itself —
    // searched for anyway, its rounding under a much heavier upper cylinder
    // (coefficients 10^6 times the values near θs) put it on either side
    // of θs by the digits asked, and a ghost branch point appeared
    if !ctx.held && !matches!(ctx.law(Which::Contact), Law::Frictionless) {
        let hp = route.free_normal_poly();
        if route.sign_at_start(&hp, wants.digits)? > 0 {
            starts_open = true;
        } else if let Some(found) =
            route.first_root("branch point", &hp, None, &ds, p, wants.digits)?
        {
            branch_found = Some(found);
        }
    }
    // the requested angles (user frame → δ in the working frame)
    // δ = θ − θ0 from the exact numbers: rounded apart (θ at p + 16 bits
    // against θ0 at p) an angle given as θ0 itself came out a hair before
    // the start, was dropped as not reached in the phase, and the answer at
    // θ0 was the state at the first event (t = 4.156… for t(θ0) = 0)
    let th0e = route.work.start().theta0.clone();
    let angle_at = |e: &Exact, kind: Ending| -> Option<(Ending, Float)> {
        let th = if sign < 0 { e.neg() } else { e.clone() };
        // both rational, or both multiples of π: exactly; else each at p + 32
        // bits (the rounding keeps the sign of a difference that far from 0)
        let pi = |x: &Exact| x.times_pi && x.coef != 0;
        let d = if pi(&th) == pi(&th0e) {
            let mut d = Float::with_val(p + 16, rug::Rational::from(&th.coef - &th0e.coef));
            if pi(&th) {
                d *= Float::with_val(p + 16, rug::float::Constant::Pi);
            }
            Float::with_val(p, &d)
        } else {
            Float::with_val(p, th.to_float(p + 32) - th0e.to_float(p + 32))
        };
        (d.is_sign_positive() || d.is_zero()).then_some((kind, d))
    };
    let mut exact_ends: Vec<(Ending, Float)> = Vec::new();
    if let Some(t) = wants.target {
        exact_ends.extend(angle_at(t, Ending::Target));
    }
    if let Branch::PartAt(a) = wants.branch {
        exact_ends.extend(angle_at(a, Ending::PartAt));
    }
    for (kind, d) in exact_ends {
        let ulp = Float::with_val(p, d.abs_ref()) >> (p as i32 - 2);
        // a --part-at angle at the branch point itself — to more than the
        // digits asked, the same decision at every precision, or to the
        // point's accuracy — is parting there: the part branch. Compared
        // bit for bit it fell just before the point at one precision
        // (parting where it is not yet lawful) and just after at the
        // other, and the two disagreed on the events
        if kind == Ending::PartAt {
            if let Some((dbp, ebp)) = &branch_found {
                let tol = Float::with_val(p, ebp + &ulp) * 4u32;
                let (th_pa, th_bp) = (
                    Float::with_val(p, &th0w + &d),
                    Float::with_val(p, &th0w + dbp),
                );
                let one = Float::with_val(p, 1u32);
                if Float::with_val(p, &d - dbp).abs() <= tol
                    || super::sides::within_digits(&th_pa, &th_bp, wants.digits, &one)
                {
                    refined.push((Ending::BranchPart, dbp.clone(), ebp.clone()));
                    continue;
                }
            }
        }
        refined.push((kind, d, ulp));
    }
    // the branch point, where parting becomes lawful while the contact
    // holds; it coincides with the separation for a held lower cylinder
    // (N12 = −m2 ρ̈_free there), which is then no branch point
    let mut branch_at: Option<(Float, Float)> = None;
    let mut merged_branch = false;
    if let Some((d, err)) = branch_found {
        // one that is θs to the digits asked is θs, in every run alike (and
        // said so: `merged_branch`)
        let tol = Float::with_val(p, &err + &refined[0].2) * 4u32;
        let apart = super::sides::apart_from_end(&d, &ds, &tol, &th0w, wants.digits);
        merged_branch = d < ds && super::sides::end_to_digits(&d, &ds, &th0w, wants.digits);
        // (said only where the phase ends at θs: below)
        if apart {
            if *wants.branch == Branch::Part {
                refined.push((Ending::BranchPart, d.clone(), err.clone()));
            }
            branch_at = Some((d, err));
        }
    }
    if starts_open {
        branch_at = Some((Float::new(p), Float::new(p)));
        if *wants.branch == Branch::Part {
            refined.push((Ending::BranchPart, Float::new(p), Float::new(p)));
        }
    }
    // the earliest ending (a requested angle ties with nothing: an angle at
    // an event is decided by the caller)
    refined.sort_by(|a, b| a.1.total_cmp(&b.1));
    // the target reached first, with another ending just beyond it: the
    // target's state is kept, and the phase goes on to that ending
    let mut target_point = None;
    if refined.len() > 1 && refined[0].0 == Ending::Target {
        if let Some(b) = &wants.beyond {
            let reach = Float::with_val(p, &refined[0].1 + b);
            if refined[1].1 <= reach {
                let (_, d, _) = refined.remove(0);
                let (t, _) = route.engine(p)?.time(&d);
                let (cols, en) = route.columns_at(&d, &t, p)?;
                target_point = Some(point_of(cols, en, mode, None, zero_bits(ctx, mode)));
            }
        }
    }
    let (ending, d_end, d_err) = refined
        .into_iter()
        .next()
        .ok_or_else(|| Error::not_physical("internal: no end of the conservative phase"))?;
    // a branch point merged with θs is said only where the phase ends there
    // (a slip onset or a target before it left the note on a motion whose
    // θs was a later phase's)
    let merged_branch = merged_branch && ending == Ending::Separation;
    if ending == Ending::PartAt {
        let lawful = branch_at
            .as_ref()
            .is_some_and(|(d, e)| Float::with_val(p, &d_end + e) >= *d);
        if !lawful {
            return Err(super::part_at_refused(wants.branch));
        }
    }
    // the branch window on the `stay` branch (parting lawful from the branch
    // point to the end of the closed branch)
    let window = branch_at.as_ref().and_then(|(d, _)| {
        (*d <= d_end).then(|| {
            let th = Float::with_val(p, &th0w + d);
            (route.odd(th), None)
        })
    });
    crate::cancel::check()?;
    let (t_end, t_err_q) = if ending == Ending::Separation {
        // d_end is δs itself: its time is the route's (kept between answers)
        route.time_s(p)?
    } else {
        route.engine(p)?.time(&d_end)
    };
    crate::cancel::check()?;
    let (cols_end, energy_end) = route.columns_at(&d_end, &t_end, p)?;
    let thd_end = Float::with_val(p, cols_end[2].abs_ref());
    let t_err = if thd_end.is_zero() {
        t_err_q
    } else {
        t_err_q + Float::with_val(p, &d_err / &thd_end)
    };
    let end_point = point_of(cols_end, energy_end, mode, None, zero_bits(ctx, mode));
    // the events inside the phase
    let mut events = Vec::new();
    if let (Some((d, err)), true) = (&branch_at, ending != Ending::BranchPart) {
        if *d <= d_end {
            // t* by the cheaper half-angle quadrature where it applies
            // (θ ≤ 2π/3; else the θ form, as `time`): the branch point's
            // detection is to cost little on top of the phase
            let (t, terr) = route.branch_time(d, p, wants.run == Run::High)?;
            let (cols, en) = route.columns_at(d, &t, p)?;
            let thd = Float::with_val(p, cols[col!("theta_dot")].abs_ref());
            let t_err = if thd.is_zero() {
                terr
            } else {
                terr + Float::with_val(p, err / &thd)
            };
            let at = point_of(cols, en, mode, None, zero_bits(ctx, mode));
            events.push(EventRec {
                kind: Kind::Indeterminate,
                which: Some(Which::Contact),
                phase: Some(Phase::Contact(mode)),
                after: Some(at.clone()),
                also: Vec::new(),
                at,
                t_err,
                theta_err: err.clone(),
            });
        }
    }
    // the rows inside the phase
    let covered = covered_times(wants.times, wants.times_f, &t_end);
    let times = &wants.times[..covered];
    let mut rows = Vec::with_capacity(if wants.theta_only { 0 } else { times.len() });
    let mut row_deltas = Vec::with_capacity(if wants.theta_only { 0 } else { times.len() });
    let mut thetas = Vec::with_capacity(if wants.theta_only { times.len() } else { 0 });
    if !times.is_empty() {
        let deltas = route.deltas_at(
            times,
            p,
            wants.run,
            !wants.theta_only,
            table_times,
            wants.digits,
            Some(&t_end),
        )?;
        let mut ulps = Float::new(p);
        for (i, (t, (d, derr))) in times.iter().zip(deltas).enumerate() {
            if wants.theta_only {
                // θ = θ0 + δ in δ's own number (at p), its bound in δ's
                // bound's: no new numbers per time
                let (mut th, mut err) = (d, derr);
                if th.prec() == p {
                    th += &th0w;
                } else {
                    th = Float::with_val(p, &th0w + &th);
                }
                ulps.assign(th.abs_ref());
                ulps >>= p as i32 - 4;
                err += &ulps;
                thetas.push((route.odd(th), Phase::Contact(mode), Some(err)));
                continue;
            }
            // the motion's own rounding of t at p bits where it has it
            let tf = match wants.times_f.get(i) {
                Some(x) if x.prec() == p => x.clone(),
                _ => t.to_float(p),
            };
            // a row within 2^−(p/2) of the phase's end or of an event in it
            // (in the time unit) is computed whole in both runs: the higher
            // run may place it on the other side of the event and give it
            // the event's state, which is compared with this run's value
            // (one this run had left would fail it, and the ladder climb)
            let near_event = || {
                std::iter::once(&t_end)
                    .chain(events.iter().map(|e| &e.at.t))
                    .any(|te| {
                        let guard = (Float::with_val(p, te.abs_ref()) + &ctx.ts) >> (p as i32 / 2);
                        Float::with_val(p, &tf - te).abs() <= guard
                    })
            };
            if wants.derived_at_high && wants.run == Run::Low && !near_event() {
                // the lower run of a table: t and θ only; the higher run
                // computes the other columns with their error (below)
                let mut a = vec![Float::new(p); COLUMNS.len()];
                a[0] = tf;
                a[1] = route.odd(Float::with_val(p, &th0w + &d));
                let mut pt = point_of(a, Float::new(p), mode, None, zero_bits(ctx, mode));
                pt.diff_weight = 0;
                rows.push(pt);
                row_deltas.push(d);
                continue;
            }
            let low = wants.low_deltas.get(i);
            let ulps = |x: &Float| Float::with_val(p, x.abs_ref()) >> (p as i32 - 4);
            if let (Run::High, Some(d1), true) = (wants.run, low, wants.derived_at_high) {
                // the lower run left these columns: their error is what δ's
                // bound (the two runs' difference and the route's own
                // bound) carries into them and the roundings
                let (a, energy, mut err) =
                    derived_columns(route, &d, d1, &derr, t, &tf, &th0w, wants.digits, p)?;
                // θ is compared with the lower run's, as in a θ-only table
                err[1] = Float::with_val(p, &derr) + ulps(&a[1]);
                err[0] = Float::with_val(p, tf.abs_ref()) >> (p as i32 - 2);
                let mut pt = point_of(a, energy, mode, Some(err), zero_bits(ctx, mode));
                pt.diff_weight = 0;
                rows.push(pt);
                row_deltas.push(d);
                continue;
            }
            let (a, energy) = route.columns_at(&d, &tf, p)?;
            let (err, weight) = match (wants.run, low) {
                (Run::Low, _) => (None, 1),
                (Run::High, _) => {
                    // the columns' errors from δ's. Where the lower run's δ
                    // differs from this one by more than δ's bound,
                    // |v(p1) − v(p2)| counted twice covers what δ's error
                    // carries into the columns (to first order: each column
                    // is a smooth closed form of δ); else a second
                    // evaluation at δ + bound measures it.
                    let apart = low.is_some_and(|d1| {
                        let gap = Float::with_val(p, d1 - &d).abs();
                        !gap.is_zero() && gap >= derr
                    });
                    let mut err: Vec<Float> = if apart {
                        a.iter().map(ulps).collect()
                    } else {
                        let d2 = Float::with_val(p, &d + &derr);
                        let (b, _) = route.columns_at(&d2, &tf, p)?;
                        a.iter()
                            .zip(&b)
                            .map(|(x, y)| Float::with_val(p, x - y).abs() + ulps(x))
                            .collect()
                    };
                    err[0] = Float::with_val(p, tf.abs_ref()) >> (p as i32 - 2);
                    (Some(err), if apart { 2 } else { 1 })
                }
            };
            let mut pt = point_of(a, energy, mode, err, zero_bits(ctx, mode));
            pt.diff_weight = weight;
            rows.push(pt);
            row_deltas.push(d);
        }
    }
    // the state at the end as a sample of the mode's system, at the
    // integrators' working precision: the mode decision there looks a
    // little ahead of it (second order in 2^−wp/3), so the end must be
    // known to wp bits, not to the answer's p
    let wp = ctx.wp;
    let d_wp = match ending {
        Ending::Separation => route.delta_s(wp)?.0,
        Ending::Cone(w) => {
            let mu = ctx
                .law(w)
                .static_coef()
                .ok_or_else(|| Error::not_physical("internal: a cone without a coefficient"))?;
            let (hp, unit) = route.cone_poly(w, &mu);
            root_or(
                route.first_root("slip onset", &hp, Some(&unit), &ds, wp, wants.digits)?,
                &d_end,
                wp,
            )
        }
        Ending::LiftOff => {
            let hp = route.n1_poly();
            root_or(
                route.first_root("lift-off", &hp, None, &ds, wp, wants.digits)?,
                &d_end,
                wp,
            )
        }
        Ending::BranchPart => {
            let hp = route.free_normal_poly();
            root_or(
                route.first_root("branch point", &hp, None, &ds, wp, wants.digits)?,
                &d_end,
                wp,
            )
        }
        Ending::FloorImpact => {
            route.work.params().landing_angle(wp) - route.work.start().theta0.to_float(wp)
        }
        Ending::PartAt | Ending::Target => Float::with_val(wp, &d_end),
    };
    let (cols_wp, energy_wp) = route.columns_at(&d_wp, &Float::with_val(wp, &t_end), wp)?;
    let end_sample = sample_at(
        ctx,
        mode,
        &point_of(cols_wp, energy_wp, mode, None, zero_bits(ctx, mode)),
    )?;
    let theta_err = d_err;
    Ok(Fast {
        rows,
        deltas: row_deltas,
        thetas,
        covered,
        events,
        ending,
        target_point,
        end_sample,
        end_point,
        end_err: (t_err, theta_err),
        window,
        merged_branch,
    })
}

/// The columns that are exactly 0 in a conservative mode.
fn zero_bits(ctx: &Ctx, mode: Mode) -> u32 {
    let _ = ctx;
    let mut z = 1 << col!("work");
    use super::mode::State;
    match mode.floor {
        State::Stick | State::Held => z |= 1 << col!("s1"),
        State::Slip(_) => z |= 1 << col!("F1"),
    }
    match mode.contact {
        State::Stick | State::Held => z |= 1 << col!("s12"),
        State::Slip(_) => z |= 1 << col!("F21"),
    }
    z
}

/// A table's higher-run row of a conservative phase (`Wants::derived_at_high`):
/// every column at δ = `d` and time `t` (`tf` at `p` bits; θ0 `th0w`) and its error,
/// what δ's bound — `derr`, and the lower run's δ `d1` — and the roundings
/// carry into it ([`Route::column_errors`]); with the total energy. The
/// columns are evaluated at the fewest limbs that hold the digits asked
/// ([`crate::integrate::energy::derived_prec`]: δ rounded there, four units
/// of its last place added to δ's bound, t rounded once from its exact
/// value), t and θ kept at `p`; where a column's bound there is not below
/// 2^−(b+4) of its value (b the digits' bits: a cancellation, N12 just before
/// the separation, or a column at 0), the row is evaluated at `p` instead,
/// where the ladder would otherwise climb for want of those roundings.
#[allow(clippy::too_many_arguments)]
fn derived_columns(
    route: &mut Route,
    d: &Float,
    d1: &Float,
    derr: &Float,
    t: &Exact,
    tf: &Float,
    th0w: &Float,
    digits: u32,
    p: u32,
) -> Result<(Vec<Float>, Float, Vec<Float>)> {
    let pc = crate::integrate::energy::derived_prec(digits, p);
    if pc < p {
        let dc = Float::with_val(pc, d);
        let tc = t.to_float(pc);
        let (mut a, energy) = route.columns_at(&dc, &tc, pc)?;
        // δ and the lower run's δ rounded to pc bits: four units of δ's
        // last place there (δ's rounding counted twice, the lower run's
        // once) join δ's bound, itself rounded up
        let (mut derr_c, _) = Float::with_val_round(pc, derr, rug::float::Round::Up);
        derr_c += Float::with_val(pc, d.abs_ref()) >> (pc as i32 - 2);
        let dl = Float::with_val(pc, d1);
        let err = route.column_errors(&a, &dc, &dl, &derr_c, &tc, tf, pc)?;
        let lim = crate::numeric::bits_for_digits(digits) as i32 + 5;
        let enough = a
            .iter()
            .zip(&err)
            .skip(2)
            .all(|(v, e)| match (v.get_exp(), e.get_exp()) {
                (_, None) => e.is_zero(),
                (Some(ev), Some(ee)) => ee + lim <= ev,
                (None, Some(_)) => false,
            });
        if enough {
            a[0] = tf.clone();
            a[1] = route.odd(Float::with_val(p, th0w + d));
            return Ok((a, energy, err));
        }
    }
    let (a, energy) = route.columns_at(d, tf, p)?;
    let err = route.column_errors(&a, d, d1, derr, tf, tf, p)?;
    Ok((a, energy, err))
}

/// A point from the 21 columns of [`Route::columns_at`].
fn point_of(c: Vec<Float>, energy: Float, mode: Mode, err: Option<Vec<Float>>, zero: u32) -> Point {
    debug_assert_eq!(c.len(), COLUMNS.len());
    let mut it = c.into_iter();
    let mut n = || it.next().unwrap_or_else(|| Float::new(2));
    let state = TwoState {
        t: n(),
        theta: n(),
        theta_dot: n(),
        theta_ddot: n(),
        phi1: n(),
        phi2: n(),
        x1: n(),
        x2: n(),
        y2: n(),
        x1_dot: n(),
        phi1_dot: n(),
        x2_dot: n(),
        y2_dot: n(),
        phi2_dot: n(),
        f1: n(),
        n1: n(),
        f21: n(),
        n12: n(),
    };
    let (s1, s12, work) = (n(), n(), n());
    Point {
        state,
        s1,
        s12,
        work,
        energy,
        phase: Phase::Contact(mode),
        err,
        exact_zero: zero,
        diff_weight: 1,
    }
}

/// The state of a point as a sample of the mode's constrained system at
/// the integrators' precision (accelerations and multipliers by one KKT
/// solve).
///
/// Errors: a singular constraint system.
pub fn sample_at(ctx: &Ctx, mode: Mode, pt: &Point) -> Result<Sample> {
    let wp = ctx.wp;
    let mut sys: System = ctx.system(mode)?;
    let f = |x: &Float| Float::with_val(wp, x);
    let nq = sys.nq();
    let mut q = vec![Float::new(wp); nq];
    let mut v = vec![Float::new(wp); nq];
    let p = ctx.model.params();
    q[sy::X1] = f(&pt.x1);
    q[sy::Y1] = Float::with_val(wp, &p.r1);
    q[sy::PHI1] = f(&pt.phi1);
    q[sy::psi(0)] = Float::with_val(wp, &pt.phi2 - &pt.theta);
    q[sy::th(0)] = f(&pt.theta);
    q[sy::rr(0)] = Float::with_val(wp, &p.r());
    v[sy::X1] = f(&pt.x1_dot);
    v[sy::PHI1] = f(&pt.phi1_dot);
    v[sy::psi(0)] = Float::with_val(wp, &pt.phi2_dot - &pt.theta_dot);
    v[sy::th(0)] = f(&pt.theta_dot);
    let acc = sys.accel(&q, &v)?;
    Ok(Sample {
        t: f(&pt.t),
        q,
        v,
        qdd: acc.qdd,
        lambda: acc.lambda,
        work: Float::new(wp),
        power: Float::new(wp),
        trig: Vec::new(),
        energy: None,
    })
}

/// A root refined at another precision, or the one found (lifted) where the
/// refinement found none (the same root, at the edge of the interval).
fn root_or(found: Option<(Float, Float)>, d: &Float, prec: u32) -> Float {
    found.map_or_else(|| Float::with_val(prec, d), |(x, _)| x)
}

#[cfg(test)]
mod derived_tests {
    use super::*;
    use crate::model::{Contact, Floor, Ideal, Params, Start};
    use crate::numeric::verify::precisions;

    /// A table's higher-run row takes its derived columns at the fewest
    /// limbs where their bounds there leave the digits asked to spare, and
    /// at the run's precision where a column cancels (N12 a hair from the
    /// separation): there the roundings at 127 bits would make the ladder
    /// climb. Either way each column is the one at the run's precision to
    /// within its bound.
    #[test]
    fn a_cancelling_row_takes_the_runs_precision() {
        let theta0 = Exact::parse("theta0", "1/10", false).unwrap();
        let ideal = Ideal::new(
            Params::identical_solid(),
            Floor::Roll,
            Contact::Roll,
            Start::rest(theta0),
        )
        .unwrap();
        let mut route = Route::new(&ideal).unwrap();
        let (digits, p) = (30, precisions(30, 0).1);
        let (ds, _) = route.delta_s(p).unwrap();
        let th0w = route.work.start().theta0.to_float(p);
        let t = Exact::parse("t", "1", true).unwrap();
        let tf = t.to_float(p);
        let n12 = col!("N12");
        for (d, want) in [
            (Float::with_val(p, &ds / 2u32), 127),
            (
                Float::with_val(p, &ds - (Float::with_val(p, 1u32) >> 60u32)),
                p,
            ),
        ] {
            let derr = Float::with_val(p, d.abs_ref()) >> (p as i32 - 8);
            let (a, _, err) =
                derived_columns(&mut route, &d, &d, &derr, &t, &tf, &th0w, digits, p).unwrap();
            assert_eq!(a[n12].prec(), want);
            let (full, _) = route.columns_at(&d, &tf, p).unwrap();
            for k in 2..COLUMNS.len() {
                let gap = Float::with_val(p, &a[k] - &full[k]).abs();
                assert!(gap <= err[k], "{} at δ = {d:.10e}", COLUMNS[k]);
            }
        }
    }
}

#[cfg(test)]
mod covered_tests {
    use super::*;
    use rug::{Integer, Rational};

    /// The count from the rounded times is the exact count: times at the
    /// end itself, a unit of the rounding and less on either side of it
    /// (rationals whose rounding is the end's own), multiples of π, zero,
    /// and without rounded times or with an end ≤ 0.
    #[test]
    fn times_covered_by_the_rounded_times_are_the_exact_count() {
        let q = 120;
        // end: 7/3 at 150 bits; rationals near it, offset by k/2^(q+s)
        let end = Float::with_val(150, Rational::from((7, 3)));
        let end_q = end.to_rational().expect("finite");
        let near = |k: i64, s: u32| {
            let step = Rational::from((k, 1)) / Rational::from(Integer::from(1) << (q + s));
            Exact::rational(end_q.clone() + step)
        };
        let pi_over = |n: i64| Exact::parse("t", &format!("pi/{n}"), true).expect("pi");
        let exact_count =
            |times: &[Exact], end: &Float| times.iter().take_while(|t| t.le_float(end)).count();
        let mut cases: Vec<Vec<Exact>> = Vec::new();
        for k in [-64i64, -9, -1, 0, 1, 9, 64] {
            for s in [0u32, 2, 20] {
                cases.push(vec![
                    Exact::rational(Rational::new()),
                    pi_over(4),
                    Exact::rational(Rational::from((2, 1))),
                    near(k - 1, s),
                    near(k, s),
                    near(k + 1, s),
                    Exact::rational(Rational::from((3, 1))),
                ]);
            }
        }
        cases.push(vec![pi_over(2), pi_over(2), near(0, 0), near(0, 0)]);
        cases.push(vec![near(1, 40), near(1, 40)]);
        let mut counts = std::collections::BTreeSet::new();
        for times in &cases {
            let rounded: Vec<Float> = times.iter().map(|t| t.to_float(q)).collect();
            let want = exact_count(times, &end);
            counts.insert(want);
            assert_eq!(covered_times(times, &rounded, &end), want, "{times:?}");
            assert_eq!(covered_times(times, &[], &end), want);
            let zero = Float::new(150);
            assert_eq!(
                covered_times(times, &rounded, &zero),
                exact_count(times, &zero)
            );
        }
        // the end falls before, inside and after the near run
        assert!(counts.len() >= 4, "{counts:?}");
    }
}
