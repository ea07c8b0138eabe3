//! The motion verified: computed at the two working precisions of the
//! precision ladder ([`crate::numeric::verify`]), each integrating with its
//! own tolerance; the two must agree on the sequence of phases and events,
//! keep the energy balance E(0) − E(t) = W(t), and every number is printed
//! only to the digits that every value within |v(p1) − v(p2)| + err(p2)
//! shares.

use super::answer::{EventAnswer, Row};
use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::model::Model;
use crate::motion::{self, Caches, Motion, Phase, Point, Request, Side, Until};
use crate::numeric::verify::{
    estimate_rows, ladder_rows, precisions, Estimate, RowIter, Run, Verified,
};
use rug::Float;
use std::cell::RefCell;
use std::sync::Arc;

/// The skeleton of a motion: what the two precisions must agree on.
pub fn signature(m: &Motion) -> Vec<String> {
    let mut s: Vec<String> = m
        .events
        .iter()
        .map(|e| {
            format!(
                "{} {} -> {}",
                e.kind.name(),
                e.which.map_or("", |w| w.name()),
                e.phase.map_or_else(|| "-".to_string(), |p| p.tag())
            )
        })
        .collect();
    s.push(format!("start {}", m.start_mode.tag()));
    s.push(match m.end {
        Some(e) => format!("ends at the {}", e.name()),
        None => "no end before the last time".to_string(),
    });
    // the rows' phases, run by run ("rows: 3 stick/stick, 2 flight")
    let phases = m.rows.iter().map(|p| p.phase);
    let runs = tag_runs(phases.chain(m.thetas.iter().map(|(_, p, _)| *p)));
    if !runs.is_empty() {
        let text: Vec<String> = runs.iter().map(|(n, r)| format!("{n} {r}")).collect();
        s.push(format!("rows: {}", text.join(" ")));
    }
    s
}

/// The runs of equal tags in `phases`, with their lengths: a tag is made
/// where the phase changes, not per row (two phases may share a tag, a
/// flight's: their runs are one).
fn tag_runs(phases: impl Iterator<Item = Phase>) -> Vec<(usize, String)> {
    let mut runs: Vec<(usize, String)> = Vec::new();
    let mut last: Option<Phase> = None;
    for ph in phases {
        match runs.last_mut() {
            Some((n, _)) if last == Some(ph) => *n += 1,
            Some((n, tag)) if *tag == ph.tag() => *n += 1,
            _ => runs.push((1, ph.tag())),
        }
        last = Some(ph);
    }
    runs
}

/// An integrated value: its own error estimate is a few units of the
/// integrators' tolerance, relative to |v| plus the quantity's natural
/// scale as their error tests are (the comparison of the two precisions
/// carries the real weight). The scale, not 1: a time of 10^−15 s in a
/// motion whose time unit is that small is not known to 10^−45 s absolutely
/// because a unit of 1 s would allow it.
pub fn integrated(v: &Float, scale: Float) -> Estimate {
    integrated_owned(v.clone(), scale)
}

/// [`integrated`] keeping `v` itself.
pub fn integrated_owned(v: Float, scale: Float) -> Estimate {
    integrated_shared(v, Arc::new(scale))
}

/// [`integrated_owned`] with a shared scale.
pub fn integrated_shared(v: Float, scale: Arc<Float>) -> Estimate {
    let p = v.prec();
    let mut err = Float::with_val(p, v.abs_ref());
    err += &*scale;
    err >>= p as i32 - 24;
    Estimate::shared(v, err, scale)
}

fn one(p: u32) -> Float {
    Float::with_val(p, 1u32)
}

/// The natural scale of each column of [`crate::motion::COLUMNS`]: time
/// sqrt(r/g), angle 1, lengths r, forces (m1 + m2) g, energy m2 g r (shared
/// by a column's estimates, and by the columns of one kind).
pub fn column_scales(model: &Model, p: u32) -> Vec<Arc<Float>> {
    let pr = model.params();
    let r = Float::with_val(p, &pr.r());
    let g = Float::with_val(p, &pr.g);
    let ts = Float::with_val(p, &r / &g).sqrt();
    let inv_ts = Float::with_val(p, 1u32) / &ts;
    let inv_ts2 = Float::with_val(p, &inv_ts / &ts);
    let v = Float::with_val(p, &r / &ts);
    let f = Float::with_val(p, &rug::Rational::from(&pr.m1 + &pr.m2)) * &g;
    let e = Float::with_val(p, &pr.m2) * &g * &r;
    let [ts, o, inv_ts, inv_ts2, r, v, f, e] =
        [ts, one(p), inv_ts, inv_ts2, r, v, f, e].map(Arc::new);
    let c = Arc::clone;
    vec![
        ts,
        c(&o),
        c(&inv_ts),
        inv_ts2,
        c(&o),
        o,
        c(&r),
        c(&r),
        r,
        c(&v),
        c(&inv_ts),
        c(&v),
        c(&v),
        inv_ts,
        c(&f),
        c(&f),
        c(&f),
        f,
        c(&v),
        v,
        e,
    ]
}

/// The estimates of a point's columns (all of [`crate::motion::COLUMNS`]).
pub fn point_estimates(
    pt: &Point,
    scales: &[Arc<Float>],
    t_text: Option<&String>,
) -> Vec<Estimate> {
    let all: Vec<usize> = (0..crate::motion::COLUMNS.len()).collect();
    let mut out = Vec::with_capacity(all.len());
    push_point_estimates(pt.clone(), scales, t_text, &all, Run::High, &mut out);
    out
}

/// The estimates of the columns `idx` (indices of [`crate::motion::COLUMNS`],
/// each at most once) of a point, in that order, appended to `out`: the
/// point's values moved into them (a table's rows are the bulk of its
/// work). On the ladder's lower run (`run`) a value without an error of
/// its own gets none (zero): the ladder reads only the higher run's.
pub fn push_point_estimates(
    pt: Point,
    scales: &[Arc<Float>],
    t_text: Option<&String>,
    idx: &[usize],
    run: Run,
    out: &mut Vec<Estimate>,
) {
    let zero = pt.exact_zero;
    let weight = pt.diff_weight;
    let (vals, errs) = pt.into_columns();
    let mut vals: Vec<Option<Float>> = vals.into_iter().map(Some).collect();
    let mut errs: Option<Vec<Option<Float>>> = errs.map(|e| e.into_iter().map(Some).collect());
    for &i in idx {
        let Some(v) = vals.get_mut(i).and_then(Option::take) else {
            continue;
        };
        let p = v.prec();
        let sc = Arc::clone(&scales[i]);
        if zero & (1 << i) != 0 {
            out.push(Estimate::zero_shared(p, sc));
            continue;
        }
        let err = errs
            .as_mut()
            .and_then(|e| e.get_mut(i).and_then(Option::take));
        let mut e = match err {
            Some(err) if err.prec() == p => Estimate::shared(v, err, sc),
            Some(err) => Estimate::shared(v, Float::with_val(p, &err), sc),
            None if run == Run::Low => Estimate::shared(v, Float::new(p), sc),
            None => integrated_shared(v, sc),
        };
        if i == 0 {
            e.exact_text = t_text.cloned();
        } else if i == 1 && weight == 0 {
            // θ of a row whose other columns the higher run computed alone
            // is compared with the lower run's
            e.diff_weight = 1;
        } else {
            e.diff_weight = weight;
        }
        out.push(e);
    }
}

/// The estimates of each event's time (natural scale `ts`, the time unit
/// sqrt(r/g) of [`column_scales`]) and angle.
pub fn event_estimates(m: &Motion, ts: &Float, out: &mut Vec<Estimate>) {
    for e in &m.events {
        let p = e.at.t.prec();
        let mut te = integrated(&e.at.t, Float::with_val(p, ts));
        te.err += Float::with_val(p, &e.t_err);
        out.push(te);
        let mut th = integrated(&e.at.theta, one(p));
        th.err += Float::with_val(p, &e.theta_err);
        out.push(th);
    }
}

/// The energy balance E(0) − E(t) = W(t) to well below the printed digits.
fn check_balance(m: &Motion, digits: u32) -> Result<()> {
    let p = m.energy_drift.prec();
    // 10^-(digits+2) of the energy's own scale (m2 g r, or |E(0)| where
    // that is larger)
    let lim = Float::with_val(p, Float::u_pow_u(10, digits + 2)).recip() * &m.energy_unit;
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

/// The motion of a model at the precisions of a ladder, with the caches
/// the runs share.
pub struct Runs<'a> {
    /// The model.
    pub model: &'a Model,
    /// The request (its `run` is set per call).
    pub req: Request,
    /// Shared caches.
    pub caches: Caches,
    /// Rows whose time no reachable precision separated from an event:
    /// (row, event); their values are the state at the event.
    pub at_events: Vec<(usize, usize)>,
    /// The event whose angle the target could not be separated from.
    pub target_at: Option<usize>,
    /// The highest precision tried to decide a side.
    pub side_bits: u32,
    /// The kind of the event of `target_at`.
    pub target_kind: Option<motion::Kind>,
}

impl Runs<'_> {
    /// The motion at precision `p`.
    pub fn at(&mut self, p: u32, run: Run) -> Result<Motion> {
        self.req.run = run;
        motion::run(self.model, &self.req, p, &mut self.caches)
    }

    /// Decides the side of every row (and the target) that the first run
    /// cannot tell from an event: the motion is computed at doubling
    /// precision (from twice the ladder's higher one, at most two
    /// doublings) until the event time (angle) is known well enough; a row
    /// still inseparable is the state at the event. The sides go into the
    /// request, for every run of the ladder, and are applied to `first`.
    ///
    /// Errors: a run's; a precision at which the events differ.
    pub fn resolve_sides(&mut self, first: &mut Motion) -> Result<()> {
        let mut rows: Vec<(usize, usize)> = first
            .near
            .iter()
            .enumerate()
            .filter_map(|(i, k)| k.map(|k| (i, k)))
            .collect();
        let mut target = first.target_near;
        if rows.is_empty() && target.is_none() {
            return Ok(());
        }
        let digits = self.req.digits;
        let (_, p2) = precisions(self.req.digits, 0);
        let mut decided: Vec<(usize, usize, Side)> = Vec::new();
        let mut target_side = None;
        let mut q = 2 * p2;
        // the motion to its end, without a target (the events past the last
        // time, or beyond the target, are kept)
        let until = self.req.until.clone();
        self.req.until = Until::End;
        while q <= 8 * p2 && (!rows.is_empty() || target.is_some()) {
            self.side_bits = q;
            let m = match self.at(q, Run::High) {
                Ok(m) => m,
                Err(e) => {
                    self.req.until = until;
                    return Err(e);
                }
            };
            let same = |k: usize| {
                m.events
                    .get(k)
                    .zip(first.events.get(k))
                    .is_some_and(|(a, b)| {
                        // the first run's phase entered is None where it
                        // stopped at the event (the target angle reached
                        // there): the same event, whatever the next phase
                        a.kind == b.kind
                            && a.which == b.which
                            && (b.phase.is_none() || a.phase == b.phase)
                    })
            };
            rows.retain(|&(i, k)| {
                if !same(k) {
                    return true;
                }
                let ev = &m.events[k];
                let t = self.req.times[i].to_float(q);
                match motion::sides::side_of(&t, &ev.at.t, &ev.t_err, q, Some(&m.ts)) {
                    // past the end of the model by less than the digits
                    // asked resolve (the end's time printed to more digits
                    // and read back): the state at the end
                    Some(Side::After)
                        if ev.kind.ends()
                            && motion::sides::within_digits(&t, &ev.at.t, digits, &m.ts) =>
                    {
                        decided.push((i, k, Side::At));
                        false
                    }
                    Some(side) => {
                        decided.push((i, k, side));
                        false
                    }
                    None => true,
                }
            });
            if let (Some(k), Until::Angle { theta, .. }) = (target, &until) {
                if same(k) {
                    let ev = &m.events[k];
                    let th = theta.to_float(q);
                    if let Some(side) = motion::sides::angle_side(
                        &th,
                        &ev.at.theta,
                        &ev.theta_err,
                        q,
                        self.model.direction(),
                    ) {
                        // past the separation (or the end) by less than the
                        // digits asked resolve: the state at it. On the
                        // `part` branch the branch point that enters the
                        // flight is the parting (its separation event
                        // follows at the same instant, and is the nearer
                        // only in name): θs as printed, given back, was
                        // refused as "must be reached while the cylinders
                        // touch"
                        let parts = ev.kind == motion::Kind::Indeterminate
                            && matches!(ev.phase, Some(motion::mode::Phase::Flight { .. }));
                        let at_end =
                            (ev.kind == motion::Kind::Separation || parts || ev.kind.ends())
                                && side == Side::After
                                && motion::sides::within_digits(&th, &ev.at.theta, digits, &one(q));
                        target_side = Some((k, if at_end { Side::At } else { side }));
                        if at_end {
                            self.target_at = Some(k);
                            self.target_kind = Some(if parts {
                                motion::Kind::Separation
                            } else {
                                ev.kind
                            });
                        }
                        target = None;
                    }
                }
            }
            q *= 2;
        }
        self.req.until = until;
        for &(i, k) in &rows {
            decided.push((i, k, Side::At));
        }
        self.at_events = rows;
        if let Some(k) = target {
            target_side = Some((k, Side::At));
            self.target_at = Some(k);
            self.target_kind = first.events.get(k).map(|e| e.kind);
        }
        self.req.sides = decided;
        self.req.target_side = target_side;
        motion::sides::apply_sides(first, &self.req)?;
        let (p1, _) = precisions(self.req.digits, 0);
        motion::sides::trim_events(first, &self.req, p1, self.model.direction());
        Ok(())
    }
}

/// Runs the motion at both precisions of each rung, the first run (at
/// p1 of the first rung) fixing the skeleton; every other run must match
/// it. `est` gives the estimates of one run (`rows` rows of `names`); the
/// run is passed along (the lower run's error estimates are not read).
pub fn laddered(
    runs: &mut Runs,
    first: Motion,
    names: &[String],
    rows: usize,
    est: impl Fn(Motion, Run) -> Result<Vec<Estimate>>,
) -> Result<Vec<Vec<Verified>>> {
    let w = names.len();
    laddered_short(runs, first, names, rows, |m, run| {
        est(m, run).map(|v| estimate_rows(v, w))
    })
}

/// [`laddered`] whose estimates are made row by row as they are judged
/// (`est` returns the run's rows lazily, [`RowIter`]), and may leave rows of
/// the lower run short, as `numeric::verify::ladder_rows` takes them.
pub(crate) fn laddered_short<'a>(
    runs: &mut Runs,
    first: Motion,
    names: &[String],
    rows: usize,
    est: impl Fn(Motion, Run) -> Result<RowIter<'a>>,
) -> Result<Vec<Vec<Verified>>> {
    let digits = runs.req.digits;
    let sig = signature(&first);
    let (p1, _) = precisions(digits, 0);
    let cache = RefCell::new(Some(first));
    let refs: Vec<&str> = names.iter().map(String::as_str).collect();
    let f = |p: u32, run: Run| -> Result<RowIter<'a>> {
        let m = match (p == p1, cache.borrow_mut().take()) {
            (true, Some(m)) => m,
            _ => runs.at(p, run)?,
        };
        // the lower run's δ at each conservative row, for the higher run's
        // error of those rows (Request::low_deltas)
        runs.req.low_deltas = if run == Run::Low {
            m.deltas.clone()
        } else {
            Vec::new()
        };
        if signature(&m) != sig {
            return Err(Error::NotConverged {
                quantity: "event sequence".into(),
                requested: digits,
                reached: "the two working precisions disagree on the sequence of phases".into(),
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
        est(m, run)
    };
    // a single row's failure names the quantity alone, a table's its row
    ladder_rows(digits, &refs, rows, rows != 1, f)
}

/// The names of the event values: `event1_t`, `event1_theta`, …
pub fn event_names(n: usize) -> Vec<String> {
    (1..=n)
        .flat_map(|i| [format!("event{i}_t"), format!("event{i}_theta")])
        .collect()
}

/// The verified events from their values (t, θ per event, in order).
pub fn events_of(m: &Motion, vals: &[Verified]) -> Vec<EventAnswer> {
    m.events
        .iter()
        .enumerate()
        .map(|(i, e)| EventAnswer {
            kind: e.kind,
            which: e.which,
            phase: e.phase,
            t: vals[2 * i].clone(),
            theta: vals[2 * i + 1].clone(),
            also: e.also.clone(),
        })
        .collect()
}

/// A trajectory's rows from the verified table and the first run's phases.
pub fn rows_of(m: &Motion, table: Vec<Vec<Verified>>) -> Vec<Row> {
    table
        .into_iter()
        .zip(&m.rows)
        .map(|(values, pt)| Row {
            values,
            phase: pt.phase,
            at_event: None,
        })
        .collect()
}

/// The time of a row printed exactly when it is a terminating decimal.
pub fn exact_times(times: &[Exact]) -> Vec<Option<String>> {
    times.iter().map(Exact::terminating_text).collect()
}

/// θ at the times of a θ-only motion (moved out of it).
pub fn theta_estimates(m: &mut Motion) -> Vec<Estimate> {
    // the values and bounds moved, not copied; one scale per precision
    let mut scale: Option<Arc<Float>> = None;
    std::mem::take(&mut m.thetas)
        .into_iter()
        .map(|(th, _, err)| {
            let p = th.prec();
            let s = match &scale {
                Some(s) if s.prec() == p => s.clone(),
                _ => scale.insert(Arc::new(one(p))).clone(),
            };
            match err {
                Some(e) => Estimate::shared(th, e, s),
                None => integrated_shared(th, s),
            }
        })
        .collect()
}

/// The phases of a θ-only motion.
pub fn theta_phases(m: &Motion) -> Vec<Phase> {
    m.thetas.iter().map(|(_, p, _)| *p).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::motion::{Mode, State};

    #[test]
    fn tag_runs_are_the_runs_of_the_rows_tags() {
        let stick = Phase::Contact(Mode {
            floor: State::Stick,
            contact: State::Stick,
        });
        let slip = Phase::Contact(Mode {
            floor: State::Slip(1),
            contact: State::Stick,
        });
        // two flights of one tag ("flight"): one run
        let fly_slip = Phase::Flight {
            floor: State::Slip(-1),
        };
        let fly_stick = Phase::Flight {
            floor: State::Stick,
        };
        let rows = [
            stick, stick, stick, slip, fly_slip, fly_slip, fly_stick, stick,
        ];
        let got = tag_runs(rows.iter().copied());
        let want: Vec<(usize, String)> = vec![
            (3, "stick/stick".into()),
            (1, "slip+/stick".into()),
            (3, "flight".into()),
            (1, "stick/stick".into()),
        ];
        assert_eq!(got, want);
        assert!(tag_runs(std::iter::empty()).is_empty());
    }
}
