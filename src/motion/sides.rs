//! Times and angles at events: on which side of an event a requested time
//! (or the target angle) lies.
//!
//! At one working precision an event's time is known to within its error
//! estimate; a requested time closer to it than that cannot be placed in
//! the phase before or after by this run alone, and two precisions may
//! place it differently. [`mark_near`] flags such rows; the caller decides
//! their side at a precision where it is certain (or, where no reachable
//! precision separates them, takes the state at the event, continuous
//! there), and every run of the ladder then applies that decision
//! ([`apply_sides`]): the row is the state of the phase it belongs to, or
//! the one-sided limit at the event where this precision places the event
//! on the other side of it.

use super::point::Point;
use super::{EventRec, Motion, Request};
use crate::error::{Error, Result};
use rug::{Assign, Float};

/// Where a requested time (or angle) lies relative to an event.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// In the phase before the event.
    Before,
    /// In the phase after it.
    After,
    /// Not separable from it at the precision reachable: the state at the
    /// event (the phase before's limit).
    At,
}

/// The margin within which a value cannot be told from an event's at the
/// ladder's precision `p` (the integrators' tolerance is 2^−(p−8), their
/// working precision higher): four times the event's error estimate and
/// the integration's, relative to |v| plus the value's natural scale
/// (`scale`: the time unit for a time; None, 1, for an angle) — not 1,
/// which for a motion in microseconds would put every time near its event.
fn margin(v: &Float, err: &Float, p: u32, scale: Option<&Float>) -> Float {
    let wp = v.prec();
    let mut floor = Float::with_val(wp, v.abs_ref());
    match scale {
        Some(s) => floor += s,
        None => floor += 1u32,
    }
    floor >>= p as i32 - 24;
    (Float::with_val(wp, err) + floor) * 4u32
}

/// Whether `t` is `end` to the `digits` significant digits asked: within
/// half a unit of `end`'s `digits`-th significant digit (so that `end` as
/// printed to those digits, rounded either way, is one; at least 10 digits
/// are held to, so that a coarse request does not take a value a per cent
/// past the end for the end), or within (|end| + scale)·10^−(digits+3),
/// `scale` the natural scale (the time unit for a time, 1 for an angle: an
/// `end` near 0). A value at an event to the digits asked; the same
/// decision at every working precision (the bounds are far above 2^−p).
pub fn within_digits(t: &Float, end: &Float, digits: u32, scale: &Float) -> bool {
    let p = t.prec();
    let mut tol = (Float::with_val(p, end.abs_ref()) + scale)
        / Float::with_val(p, Float::u_pow_u(10, digits + 3));
    let e = end.to_f64().abs();
    if e.is_finite() && e > 0.0 {
        // half a unit of the digits-th significant digit: 10^(k − digits)/2
        // with 10^(k−1) ≤ |end| < 10^k
        let k = e.log10().floor() as i64 + 1 - i64::from(digits.max(10));
        let unit = if k >= 0 {
            Float::with_val(p, Float::u_pow_u(10, k as u32))
        } else {
            Float::with_val(p, 1u32) / Float::with_val(p, Float::u_pow_u(10, (-k) as u32))
        };
        let half = unit / 2u32;
        if half > tol {
            tol = half;
        }
    }
    Float::with_val(p, t - end).abs() <= tol
}

/// Whether a root at δ = `d` (error `tol` beyond which it is apart) lies
/// before the end δ = `end` of a phase and apart from it — not within its
/// bound, and not the end to the `digits` asked ([`within_digits`] of the
/// angles θ0 + δ, `th0` the start in the working frame): the same decision at
/// every working precision. A branch point ~10^-40 before θs under a lower
/// cylinder 10^40 times heavier was told apart at one precision only, and
/// the two runs disagreed on the events.
pub fn apart_from_end(d: &Float, end: &Float, tol: &Float, th0: &Float, digits: u32) -> bool {
    let p = d.prec().max(end.prec());
    let gap = Float::with_val(p, d - end).abs();
    *d < *end && gap > *tol && !end_to_digits(d, end, th0, digits)
}

/// Whether the root at δ = `d` is the end δ = `end` to the `digits` asked
/// ([`within_digits`] of the angles θ0 + δ, `th0` the start in the working
/// frame): the same decision at every working precision.
pub fn end_to_digits(d: &Float, end: &Float, th0: &Float, digits: u32) -> bool {
    let p = d.prec().max(end.prec());
    let at = |x: &Float| Float::with_val(p, th0 + x);
    within_digits(&at(d), &at(end), digits, &Float::with_val(p, 1u32))
}

/// The event whose value in `ats` (with its margin in `margins`) is nearest
/// `x`, if `x` is within that margin: |x − a| rounded at x's precision (in
/// the scratch number `d`), the first of equally near ones.
fn nearest_within<'a>(
    x: &Float,
    ats: impl Iterator<Item = &'a Float>,
    margins: &[Float],
    d: &mut Float,
) -> Option<usize> {
    let mut best: Option<(usize, Float)> = None;
    for (k, (a, m)) in ats.zip(margins).enumerate() {
        if d.prec() != x.prec() {
            d.set_prec(x.prec());
        }
        d.assign(x - a);
        d.abs_mut();
        if *d <= *m && best.as_ref().is_none_or(|(_, b)| d.total_cmp(b).is_lt()) {
            best = Some((k, d.clone()));
        }
    }
    best.map(|(k, _)| k)
}

/// [`nearest_within`] of each of `xs`: where `xs` ascend (a table's times),
/// each event's rows are found by bisection — the rows within an event's
/// margin are a run (|x − a| rounded is monotone on each side of a), so a
/// table's rows far from every event cost no subtraction —, and the rows
/// in it are compared as [`nearest_within`] compares them (the first of
/// equally near events). Otherwise row by row.
fn nearest_rows(xs: &[Float], ats: &[&Float], margins: &[Float]) -> Vec<Option<usize>> {
    let Some(x0) = xs.first() else {
        return Vec::new();
    };
    let mut d = Float::new(x0.prec());
    if !xs.windows(2).all(|w| w[0] <= w[1]) {
        return xs
            .iter()
            .map(|x| nearest_within(x, ats.iter().copied(), margins, &mut d))
            .collect();
    }
    let mut best: Vec<Option<(usize, Float)>> = vec![None; xs.len()];
    for (k, (a, m)) in ats.iter().zip(margins).enumerate() {
        let mut within = |x: &Float| {
            if d.prec() != x.prec() {
                d.set_prec(x.prec());
            }
            d.assign(x - *a);
            d.abs_mut();
            d <= *m
        };
        // before a and out of the margin; then a run within it
        let lo = xs.partition_point(|x| x < *a && !within(x));
        let hi = lo + xs[lo..].partition_point(|x| x <= *a || within(x));
        for (x, b) in xs[lo..hi].iter().zip(&mut best[lo..hi]) {
            if d.prec() != x.prec() {
                d.set_prec(x.prec());
            }
            d.assign(x - *a);
            d.abs_mut();
            if d <= *m && b.as_ref().is_none_or(|(_, bd)| d.total_cmp(bd).is_lt()) {
                *b = Some((k, d.clone()));
            }
        }
    }
    best.into_iter().map(|b| b.map(|(k, _)| k)).collect()
}

/// The event nearest the angle `theta`, if within its margin.
pub fn near_in_angle(events: &[EventRec], theta: &Float, p: u32) -> Option<usize> {
    let margins: Vec<Float> = events
        .iter()
        .map(|e| margin(&e.at.theta, &e.theta_err, p, None))
        .collect();
    let ats = events.iter().map(|e| &e.at.theta);
    nearest_within(theta, ats, &margins, &mut Float::new(theta.prec()))
}

/// The side of `x` (a time, `scale` the time unit; or an angle, None)
/// relative to an event at `ev` (its value and error) at the ladder's
/// precision `p`, or None within the margin.
pub fn side_of(x: &Float, ev: &Float, err: &Float, p: u32, scale: Option<&Float>) -> Option<Side> {
    let d = Float::with_val(x.prec(), x - ev);
    if d.clone().abs() <= margin(ev, err, p, scale) {
        None
    } else if d.is_sign_negative() {
        Some(Side::Before)
    } else {
        Some(Side::After)
    }
}

/// [`side_of`] for an angle `x` against an event's angle, in the motion's
/// order: `dir` the model's direction (−1 for a fall to the left, whose
/// angles decrease: an angle above the event's is before it there).
pub fn angle_side(x: &Float, ev: &Float, err: &Float, p: u32, dir: i32) -> Option<Side> {
    side_of(x, ev, err, p, None).map(|s| match (s, dir < 0) {
        (Side::Before, true) => Side::After,
        (Side::After, true) => Side::Before,
        (s, _) => s,
    })
}

/// Flags the rows (and the target) that cannot be told from an event at
/// this precision.
pub fn mark_near(m: &mut Motion, req: &Request, p: u32) {
    let n = m.rows.len().max(m.thetas.len());
    // each event's margin in time (`ts` the time unit) once, not once per row
    let margins: Vec<Float> = m
        .events
        .iter()
        .map(|e| margin(&e.at.t, &e.t_err, p, Some(&m.ts)))
        .collect();
    let times = &m.times[..n.min(req.times.len()).min(m.times.len())];
    let ats: Vec<&Float> = m.events.iter().map(|e| &e.at.t).collect();
    m.near = nearest_rows(times, &ats, &margins);
    m.target_near = m
        .target
        .as_ref()
        .and_then(|pt| near_in_angle(&m.events, &pt.theta, p));
}

/// Whether a row in `phase` is already on `side` of the event (its phase
/// before, or the one it enters; at the event itself never). Phases are
/// compared whole (a flight with cylinder 1 sliding is not the flight after
/// it sticks). Where the event leaves the phase as it was (a branch point
/// on the `stay` branch), a row in it is on either side: it was computed
/// with the same dynamics as the other side's, at its own time. It was
/// replaced by the state at the event in every run, a substitution whose
/// error (θ̇ times the row's distance from the event, up to a unit of the
/// last digit) no run could see: wrong last digits printed as verified.
fn on_side(ev: &EventRec, side: Side, phase: super::mode::Phase) -> bool {
    match side {
        Side::At => false,
        Side::Before => phase == ev.at.phase,
        Side::After => ev.after.as_ref().is_some_and(|a| phase == a.phase),
    }
}

/// Event `k`, its state after taken from the next event at the same
/// instant where it has none of its own: on the `part` branch the branch
/// point and the separation coincide, and the flight's first state is the
/// separation's. (A row just past them took the branch point's missing
/// state after as its state before: the closed mode's forces and θ̈, to
/// the digits asked, where the cylinders had parted.)
fn with_after(events: &[EventRec], k: usize) -> Option<EventRec> {
    let mut ev = events.get(k)?.clone();
    if ev.after.is_none() {
        ev.after = events[k + 1..]
            .iter()
            .take_while(|e| e.at.t == ev.at.t)
            .find_map(|e| e.after.clone());
    }
    Some(ev)
}

/// The state of event `k` on `side`, at time `t`.
fn state_on(ev: &EventRec, side: Side, t: &Float) -> Point {
    let mut pt = match side {
        Side::After => ev.after.clone().unwrap_or_else(|| ev.at.clone()),
        Side::Before | Side::At => ev.at.clone(),
    };
    pt.state.t = Float::with_val(t.prec(), t);
    pt.err = None;
    pt
}

/// Applies the decided sides: a row (or the target) this precision placed
/// on the other side of its event becomes the one-sided limit at the event;
/// a row at an event becomes the state there.
///
/// Errors: a side that names a row or an event this motion does not have
/// (the precisions disagree on the events).
pub fn apply_sides(m: &mut Motion, req: &Request) -> Result<()> {
    let p = m.prec();
    let missing = || Error::NotConverged {
        quantity: "event sequence".into(),
        requested: req.digits,
        reached: "the working precisions disagree on the events".into(),
        detail: "a time decided at one precision has no event at another".into(),
    };
    for &(i, k, side) in &req.sides {
        let ev = with_after(&m.events, k).ok_or_else(missing)?;
        let t = req.times.get(i).ok_or_else(missing)?.to_float(p);
        let phase = if m.rows.len() > i {
            m.rows[i].phase
        } else if m.thetas.len() > i {
            m.thetas[i].1
        } else {
            return Err(missing());
        };
        let replace = !on_side(&ev, side, phase);
        if !replace {
            continue;
        }
        let pt = state_on(&ev, side, &t);
        if m.rows.len() > i {
            m.rows[i] = pt;
        } else if m.thetas.len() > i {
            m.thetas[i] = (pt.theta.clone(), pt.phase, None);
        }
    }
    if let (Some((k, side)), Some(target)) = (req.target_side, m.target.as_ref()) {
        // this precision reached the angle before the event: so is it
        // before or at the event (the phase before's state at the angle)
        if m.events.len() <= k && side != Side::After {
            return Ok(());
        }
        let ev = with_after(&m.events, k).ok_or_else(missing)?;
        let replace = !on_side(&ev, side, target.phase);
        if replace {
            let t = ev.at.t.clone();
            m.target = Some(state_on(&ev, side, &t));
        }
    }
    Ok(())
}

/// Drops the events found just past the last requested time (located to
/// place the times near them; not the answer's): only those up to the last
/// time stay — by the side decided for the last time where there is one,
/// the same at every precision.
pub fn trim_events(m: &mut Motion, req: &Request, p: u32, dir: i32) {
    // an angle decided before (or at) event k: the events from k on are
    // not the answer's (some precisions reach the angle first, some the
    // event)
    if let Some((k, Side::Before | Side::At)) = req.target_side {
        m.events.truncate(k);
    } else if let (None, Some(target)) = (req.target_side, m.target.as_ref()) {
        // the events found just past the angle are not the answer's
        let th = target.theta.clone();
        m.events
            .retain(|e| angle_side(&th, &e.at.theta, &e.theta_err, p, dir) != Some(Side::Before));
    }
    if req.until == super::Until::LastTime {
        if let Some(last) = req.times.last() {
            let tl = last.to_float(m.prec());
            let ts = m.ts.clone();
            let i_last = req.times.len() - 1;
            // an event the last time was decided to come before: it and
            // every event at its instant or later are past the last time
            // (on the `part` branch the separation coincides with the
            // branch point; it was kept at one precision and not at the
            // other)
            let cut: Option<Float> = req
                .sides
                .iter()
                .filter(|(i, _, s)| *i == i_last && *s == Side::Before)
                .filter_map(|(_, kk, _)| m.events.get(*kk).map(|e| e.at.t.clone()))
                .min_by(|a, b| a.total_cmp(b));
            let mut k = 0usize;
            m.events.retain(|e| {
                if cut.as_ref().is_some_and(|c| e.at.t >= *c) {
                    k += 1;
                    return false;
                }
                // a side decided for the last time rules (the same at every
                // precision); otherwise the event is clearly before or after
                let decided = req
                    .sides
                    .iter()
                    .find(|(i, kk, _)| *i == i_last && *kk == k)
                    .map(|(_, _, s)| *s);
                k += 1;
                match decided {
                    Some(s) => s != Side::Before,
                    None => side_of(&tl, &e.at.t, &e.t_err, p, Some(&ts)) != Some(Side::Before),
                }
            });
            if m.end.is_some() && m.events.last().is_none_or(|e| !e.kind.ends()) {
                m.end = None;
                m.impact = None;
            }
        }
    }
}

#[cfg(test)]
mod nearest_tests {
    use super::*;

    /// The nearest of the events whose margin holds the value, the first of
    /// equally near ones, none where no margin holds it (written out by
    /// hand).
    #[test]
    fn the_nearest_event_within_its_margin() {
        let f = |x: f64| Float::with_val(64, x);
        let ats = [f(1.0), f(2.0), f(2.5)];
        let margins = [f(0.1), f(1.0), f(1.0)];
        let mut d = Float::new(64);
        let near = |x: f64, d: &mut Float| nearest_within(&f(x), ats.iter(), &margins, d);
        // 2.2: events 1 (0.2) and 2 (0.3) hold it
        assert_eq!(near(2.2, &mut d), Some(1));
        // 1.05: event 0 (0.05, within 0.1) before event 1 (0.95)
        assert_eq!(near(1.05, &mut d), Some(0));
        // 1.5: event 0's margin does not hold it; event 1 and 2 do, 1 nearer
        assert_eq!(near(1.5, &mut d), Some(1));
        // 2.25: events 1 and 2 equally near, the first
        assert_eq!(near(2.25, &mut d), Some(1));
        assert_eq!(near(10.0, &mut d), None);
        assert_eq!(near(-0.5, &mut d), None);
    }

    /// A table's rows by bisection: the same event for every row as the
    /// row-by-row search (and, written out, at the margins' edges and the
    /// ties above), ascending or not, at rows with overlapping margins,
    /// at an event itself and beyond every event.
    #[test]
    fn the_rows_by_bisection_are_the_rows_one_by_one() {
        let f = |x: f64| Float::with_val(64, x);
        let events = [f(1.0), f(2.0), f(2.5)];
        let ats: Vec<&Float> = events.iter().collect();
        let margins = [f(0.1), f(1.0), f(1.0)];
        let one_by_one = |xs: &[Float]| -> Vec<Option<usize>> {
            let mut d = Float::new(64);
            xs.iter()
                .map(|x| nearest_within(x, ats.iter().copied(), &margins, &mut d))
                .collect()
        };
        // every 1/64 from −1 to 5 (the margins' edges 0.9, 1.1, 1.0, 3.0 and
        // 3.5 on the grid as near as binary64 has them)
        let grid: Vec<Float> = (-64..=320).map(|i| f(i as f64 / 64.0)).collect();
        let got = nearest_rows(&grid, &ats, &margins);
        assert_eq!(got, one_by_one(&grid));
        let at = |x: f64| got[((x + 1.0) * 64.0) as usize];
        assert_eq!(at(2.25), Some(1));
        assert_eq!(at(1.0), Some(0));
        assert_eq!(at(0.0), None);
        assert_eq!(at(1.5), Some(1));
        assert_eq!(at(3.5), Some(2));
        assert_eq!(at(3.515625), None);
        // repeated times and a descending stretch
        let odd: Vec<Float> = [3.0, 0.95, 0.95, 2.2, 1.05, 5.0, 2.25]
            .iter()
            .map(|&x| f(x))
            .collect();
        assert_eq!(nearest_rows(&odd, &ats, &margins), one_by_one(&odd));
        let mut sorted = odd.clone();
        sorted.sort_by(|a, b| a.total_cmp(b));
        assert_eq!(nearest_rows(&sorted, &ats, &margins), one_by_one(&sorted));
        assert!(nearest_rows(&[], &ats, &margins).is_empty());
        assert_eq!(nearest_rows(&grid[..3], &[], &[]), vec![None; 3]);
    }
}
