//! The mutable state of one run of the motion ([`super::run`]): the
//! answer being built, the next requested time, the energy balance, and
//! what happens at the end of the model (the remaining times, a target
//! angle at an event, the flight to the impact).

use super::ctx::Ctx;
use super::mode::{End, Kind, Mode, Surface};
use super::request::{EventRec, Motion, Request, Route, Until};
use super::sides::{self, Side};
use super::{flight, Point};
use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::integrate::solve::Sample;
use crate::numeric::decimal::toward_start;
use rug::Float;

/// A requested time after the end of the model (`what` ended it at `end`,
/// known to within `err`; quoted by [`toward_start`](crate::numeric::decimal::toward_start)).
fn after_end(t: &Exact, end: &Float, err: &Float, what: &str) -> Error {
    Error::invalid(
        "times",
        t,
        format!(
            "must not be after {what} at t = {} (rounded down; the model ends there)",
            toward_start(end, err)
        ),
    )
}

/// The mutable state of [`super::run`].
pub(super) struct Walk<'a> {
    pub(super) ctx: &'a Ctx,
    pub(super) req: &'a Request,
    pub(super) out: Motion,
    /// Index of the next requested time.
    pub(super) next: usize,
    /// The energy at the start.
    pub(super) e0: Float,
    /// No work has been dissipated so far.
    pub(super) conservative: bool,
}

impl Walk<'_> {
    /// Keeps the largest drift of E + W from E(0) seen at `pt`.
    pub(super) fn note(&mut self, pt: &Point) {
        let d = Float::with_val(self.ctx.wp, &pt.energy + &pt.work) - &self.e0;
        let d = d.abs() / &self.ctx.escale;
        if d > self.out.energy_drift {
            self.out.energy_drift = d;
        }
    }

    /// A row at the next requested time.
    pub(super) fn push_row(&mut self, pt: Point) {
        // a lower run's row that carries t and θ alone (a conservative
        // phase's row of a table of every column, `Request::derived_at_high`:
        // the higher run computes the rest) has no energy to balance
        if !pt.is_bare(self.req.run) {
            self.note(&pt);
        }
        if self.req.theta_only {
            self.out.thetas.push((pt.theta.clone(), pt.phase, None));
        } else {
            self.out.rows.push(pt);
        }
    }

    /// The last event so far (an end or a target at an event has one).
    fn last_event(&self) -> Result<EventRec> {
        self.out
            .events
            .last()
            .cloned()
            .ok_or_else(|| Error::not_physical("internal: no event before the end"))
    }

    /// The next requested time `tt` lies at the end `end` (`what` for
    /// messages) to within the end time's margin `err`, or was decided to
    /// lie there (`Side::At`); else it is after the end of the model.
    fn within_end(&self, tt: &Float, end: &Float, err: &Float, what: &str) -> Result<()> {
        let at_end = self
            .req
            .sides
            .iter()
            .any(|(i, _, s)| *i == self.next && *s == Side::At);
        if at_end || sides::side_of(tt, end, err, self.ctx.p, Some(&self.ctx.ts)).is_none() {
            return Ok(());
        }
        // past the end by less than the digits asked resolve (the end's
        // time printed to more digits and read back): the state there, at
        // every precision — the side resolution's runs at many more bits
        // refused it, and the README's promise with it
        if sides::within_digits(tt, end, self.req.digits, &self.ctx.ts) {
            return Ok(());
        }
        Err(after_end(&self.req.times[self.next], end, err, what))
    }

    /// The motion ends at the last event (`what` for messages): every time
    /// still requested must lie there to within the event time's margin
    /// (then its row is the state at the end), else it is after the end.
    pub(super) fn end_here(&mut self, end: End, what: &str) -> Result<()> {
        let ev = self.last_event()?;
        while self.next < self.req.times.len() {
            let tt = self.out.times[self.next].clone();
            self.within_end(&tt, &ev.at.t, &ev.t_err, what)?;
            let mut pt = ev.at.clone();
            pt.state.t = tt;
            pt.err = None;
            self.push_row(pt);
            self.next += 1;
        }
        self.out.end = Some(end);
        Ok(())
    }

    /// The angle to stop at is not reached while the cylinders touch: `what`
    /// (the last event) comes first. A target within the event angle's
    /// margin is the state there (Ok(true): stop); otherwise an error.
    pub(super) fn target_at_event(&mut self, what: &str) -> Result<bool> {
        let Until::Angle { theta: th, name } = &self.req.until else {
            return Ok(false);
        };
        if self.out.target.is_some() {
            // reached already: this event lies just past it
            return Ok(true);
        }
        let ev = self.last_event()?;
        let thf = th.to_float(self.ctx.wp);
        let decided_at = matches!(self.req.target_side, Some((_, Side::At)));
        if decided_at
            || sides::side_of(&thf, &ev.at.theta, &ev.theta_err, self.ctx.p, None).is_none()
        {
            self.out.target = Some(ev.at.clone());
            return Ok(true);
        }
        Err(Error::invalid(
            name,
            th,
            format!(
                "must be reached while the cylinders touch: {what} at theta = {} (rounded \
                 toward the start)",
                toward_start(&ev.at.theta, &ev.theta_err)
            ),
        ))
    }

    /// The cylinders part at `at` (the state `s` of `mode`): the separation
    /// event `ev`, then the flight to the first impact, unless the angle to
    /// stop at comes first.
    pub(super) fn part(&mut self, ev: EventRec, mode: Mode, s: &Sample, at: &Point) -> Result<()> {
        self.out.events.push(ev);
        if self.target_at_event("the cylinders part")? {
            return Ok(());
        }
        self.fly(mode, s, at)
    }

    /// Cylinder 1 lifts off the floor (the event `ev`): the model ends there,
    /// unless the angle to stop at comes first.
    pub(super) fn lift_off(&mut self, ev: EventRec) -> Result<()> {
        self.out.events.push(ev);
        if self.target_at_event("cylinder 1 lifts off")? {
            return Ok(());
        }
        self.end_here(End::LiftOff, "the lift-off of cylinder 1")
    }

    /// Cylinder 2 reaches the floor while still on cylinder 1 (the event
    /// `ev`, the state `s` of `mode` at `at`): the model ends at that
    /// impact, unless the angle to stop at comes first.
    pub(super) fn floor_impact(
        &mut self,
        ev: EventRec,
        mode: Mode,
        s: &Sample,
        at: &Point,
    ) -> Result<()> {
        self.out.events.push(ev);
        if self.target_at_event("cylinder 2 lands on the floor")? {
            return Ok(());
        }
        self.end_here(
            End::Impact(Surface::FloorInContact),
            "the first impact (cylinder 2 reaches the floor while still on cylinder 1)",
        )?;
        let sys = self.ctx.system(mode)?;
        self.out.impact = Some(flight::Impact::in_contact(&sys, s, at));
        Ok(())
    }

    /// The flight from a separation state (of `mode` in its system) to the
    /// first impact; the separation event itself is pushed by the caller.
    pub(super) fn fly(&mut self, mode: Mode, s: &Sample, at: &Point) -> Result<()> {
        let sys = self.ctx.system(mode)?;
        let fli = flight::Flight::new(self.ctx, &sys, mode, s, at)?;
        self.out.routes.push(Route::Flight);
        // the state just after separation: the flight's first; the
        // impact's time inherits the separation's error (its closed form
        // starts from the separation state)
        let mut imp_err = Float::new(self.ctx.wp);
        if let Some(ev) = self.out.events.last_mut() {
            if ev.kind == Kind::Separation {
                ev.after = Some(fli.point(&s.t));
                imp_err = Float::with_val(self.ctx.wp, &ev.t_err) * 16u32;
            }
        }
        for e in fli.events() {
            self.out.events.push(e);
        }
        while self.next < self.out.times.len() {
            let tt = self.out.times[self.next].clone();
            let pt = if tt > fli.impact.t {
                // after the impact: only within its time's margin (the
                // state at the impact), else outside the model
                self.within_end(&tt, &fli.impact.t, &imp_err, "the first impact")?;
                let mut pt = fli.point(&fli.impact.t);
                pt.state.t = tt;
                pt
            } else {
                fli.point(&tt)
            };
            self.push_row(pt);
            self.next += 1;
        }
        let imp_pt = fli.point(&fli.impact.t);
        self.note(&imp_pt);
        let theta_err = Float::with_val(self.ctx.wp, imp_pt.theta_dot.abs_ref()) * &imp_err;
        self.out.events.push(EventRec {
            kind: Kind::Impact,
            which: None,
            phase: None,
            at: imp_pt,
            t_err: imp_err,
            theta_err,
            after: None,
            also: Vec::new(),
        });
        self.out.separation = Some(at.clone());
        self.out.end = Some(End::Impact(fli.impact.surface));
        self.out.impact = Some(fli.impact);
        Ok(())
    }
}
