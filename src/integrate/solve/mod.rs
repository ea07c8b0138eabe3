//! Time integration of the index-reduced constrained equations with event
//! location: the driver around [`super::gbs`] and [`crate::mechanics::system`].
//!
//! The state is y = (q, q̇) in all 3n coordinates; f(y) = (q̇, q̈) with q̈
//! from the KKT solve at y. The constraints are linear in q and q̇ on the
//! manifold (r_j constant), and extrapolation methods are linear in f, so
//! the position and velocity constraints are kept up to rounding; the drift
//! is measured after every step and the state is projected back onto the
//! manifold only if it exceeds a threshold far below the tolerance.
//!
//! Events (a multiplier, a velocity or a coordinate crossing zero) are
//! detected by a sign change between step ends and located by re-integrating
//! from the step's start with steps of size s at the accepted column and
//! solving g(s) = 0 by Newton's method (started from the cubic Hermite
//! interpolant of g, safeguarded by the bracket) to a correction below the
//! integration tolerance.

mod locate;
mod watch;

pub use crate::mechanics::system::Units;
pub use watch::{watch_value, watch_values, Watch};

use super::gbs::{Gbs, Rhs, Stats, Stepper};
use crate::error::{Error, Result};
use crate::mechanics::system::System;
use locate::{dip, left_zero, locate};
use rug::{Assign, Float};

/// An event: a named zero crossing, terminal or not.
#[derive(Debug, Clone)]
pub struct Event {
    /// Name used in reports.
    pub name: String,
    /// The watched function.
    pub watch: Watch,
    /// Whether the integration stops there.
    pub terminal: bool,
}

/// The full state at one time.
#[derive(Debug, Clone)]
pub struct Sample {
    /// Time.
    pub t: Float,
    /// q.
    pub q: Vec<Float>,
    /// q̇.
    pub v: Vec<Float>,
    /// q̈.
    pub qdd: Vec<Float>,
    /// The multipliers (constraint forces), one per row.
    pub lambda: Vec<Float>,
    /// Energy dissipated by sliding friction since t = 0 (an extra state
    /// integrated alongside when the system has slipping contacts; else
    /// carried unchanged).
    pub work: Float,
    /// Its rate, the sliding power Σ μk N |s| (0 without slipping contacts).
    pub power: Float,
    /// θ_j, sin θ_j and cos θ_j of each line as the sample's KKT solve
    /// computed them ([`System::trig_kept`]; empty: not kept): a row's
    /// energy and columns, made after the run, find them instead of
    /// computing them again ([`System::prime_trig`] takes them only for
    /// the same angles).
    pub trig: Vec<Float>,
    /// The total energy T + V at (q, q̇) where the sample computed it with
    /// its KKT solve's mass matrix (an output row's: [`System::energy`]'s
    /// bits, without building the matrix again after the run); `None`:
    /// not computed.
    pub energy: Option<Float>,
}

/// A located event.
#[derive(Debug, Clone)]
pub struct Hit {
    /// Index into the event list.
    pub event: usize,
    /// The state there.
    pub at: Sample,
    /// Half-width of the final bracket in time.
    pub t_err: Float,
}

/// The result of a run.
#[derive(Debug, Clone)]
pub struct Run {
    /// The samples at the requested output times that were reached.
    pub outputs: Vec<Sample>,
    /// The events located, in time order; the last is terminal if the run
    /// stopped at one.
    pub hits: Vec<Hit>,
    /// Whether the run stopped at a terminal event (else at `t_end`).
    pub stopped: bool,
    /// The last state (the terminal event's, or at `t_end`).
    pub last: Sample,
    /// Largest constraint drift seen (before any projection).
    pub max_drift: Float,
    /// Projections applied.
    pub projections: u32,
    /// Integrator work.
    pub stats: Stats,
    /// States between the outputs where the caller should check its
    /// invariants too (the ends of the spectral route's pieces; empty for
    /// the time integrators).
    pub checkpoints: Vec<Sample>,
}

impl Run {
    /// Every state the run recorded (outputs, events, the last state), as
    /// (q, q̇).
    pub fn states(&self) -> impl Iterator<Item = (&[Float], &[Float])> {
        self.outputs
            .iter()
            .chain(self.hits.iter().map(|h| &h.at))
            .chain(std::iter::once(&self.last))
            .map(|s| (s.q.as_slice(), s.v.as_slice()))
    }
}

/// Settings of a run.
#[derive(Debug, Clone)]
pub struct Opts {
    /// Internal working precision (bits): the requested precision plus the
    /// guard bits that the extrapolation tableau needs (its Lebesgue
    /// constant grows like 2^(1.1 k) with the column k).
    pub prec: u32,
    /// Local error tolerance (mixed absolute/relative).
    pub tol: Float,
    /// The motion's time unit; the first step is an eighth of it
    /// ([`Opts::h0`]).
    pub time_unit: Float,
    /// Largest extrapolation column.
    pub kmax: usize,
    /// Drift ([`System::drift`], in the system's units) above which the
    /// state is projected back onto the manifold.
    pub project_above: Float,
    /// Longest step allowed (None: only the output times limit it). A cap
    /// keeps the error control honest where the solution is tiny and grows
    /// (a start very near the top), since the tolerance is partly absolute.
    pub hcap: Option<Float>,
    /// Most accepted steps before giving up (a motion the integrator cannot
    /// follow, e.g. a stiff extreme of the parameters).
    pub max_steps: u64,
}

impl Opts {
    /// Settings for a result good to about `prec` bits: tolerance
    /// 2^−(prec−guard), columns up to kmax = digits/2 + 10 (at most 60), an
    /// internal precision of prec + ⌈1.1 kmax⌉ + 16 bits, and a drift
    /// threshold of 2^−(prec+8).
    pub fn for_prec(prec: u32, guard: u32, time_scale: &Float) -> Self {
        let digits = (prec as f64 * std::f64::consts::LOG10_2) as usize;
        let kmax = (digits / 2 + 10).clamp(8, 60);
        let work = prec + (1.1 * kmax as f64).ceil() as u32 + 16;
        let tol = Float::with_val(work, 1u32) >> (prec as i32 - guard as i32);
        Opts {
            prec: work,
            tol,
            time_unit: Float::with_val(work, time_scale),
            kmax,
            project_above: Float::with_val(work, 1u32) >> (prec as i32 + 8),
            hcap: None,
            max_steps: 1_000_000,
        }
    }

    /// The first step: an eighth of the time unit.
    pub fn h0(&self) -> Float {
        Float::with_val(self.prec, &self.time_unit / 8u32)
    }
}

struct Dae<'a> {
    sys: &'a mut System,
    nq: usize,
}

impl Rhs for Dae<'_> {
    fn eval(&mut self, y: &[Float], dy: &mut [Float]) -> Result<()> {
        let nq = self.nq;
        let (q, rest) = y.split_at(nq);
        let v = &rest[..nq];
        let (dq, rest) = dy.split_at_mut(nq);
        for (d, x) in dq.iter_mut().zip(v) {
            d.assign(x);
        }
        if self.sys.has_slips() {
            let (dv, dw) = rest.split_at_mut(nq);
            let mut lambda = vec![Float::new(self.sys.prec); self.sys.rows.len()];
            self.sys.accel_into(q, v, dv, Some(&mut lambda))?;
            if let Some(w) = dw.first_mut() {
                w.assign(self.sys.slip_power(q, v, &lambda));
            }
            Ok(())
        } else {
            self.sys.accel_into(q, v, &mut rest[..nq], None)
        }
    }
}

fn sample(sys: &mut System, t: &Float, y: &[Float]) -> Result<Sample> {
    let nq = sys.nq();
    let q = &y[..nq];
    let v = &y[nq..2 * nq];
    let acc = sys.accel(q, v)?;
    let p = sys.prec;
    let work = y.get(2 * nq).cloned().unwrap_or_else(|| Float::new(p));
    let power = if sys.has_slips() {
        sys.slip_power(q, v, &acc.lambda)
    } else {
        Float::new(p)
    };
    Ok(Sample {
        t: t.clone(),
        q: q.to_vec(),
        v: v.to_vec(),
        qdd: acc.qdd,
        lambda: acc.lambda,
        work,
        power,
        trig: Vec::new(),
        energy: None,
    })
}

fn f_of(sys: &System, s: &Sample) -> Vec<Float> {
    let mut f = s.v.clone();
    f.extend(s.qdd.iter().cloned());
    if sys.has_slips() {
        f.push(s.power.clone());
    }
    f
}

fn y_of(sys: &System, s: &Sample) -> Vec<Float> {
    let mut y = s.q.clone();
    y.extend(s.v.iter().cloned());
    if sys.has_slips() {
        y.push(s.work.clone());
    }
    y
}

/// Integrates from (q0, q̇0) at t = 0 to `t_end`, sampling at `times`
/// (ascending, within [0, t_end]) and stopping at the first terminal event.
///
/// Errors: from the KKT solve or the integrator; an event that cannot be
/// bracketed after re-integration.
pub fn run(
    sys: &mut System,
    q0: &[Float],
    v0: &[Float],
    times: &[Float],
    t_end: &Float,
    events: &[Event],
    opts: &Opts,
) -> Result<Run> {
    let start = Start {
        t: Float::new(opts.prec),
        q: q0,
        v: v0,
        work: Float::new(opts.prec),
        snap: Vec::new(),
    };
    run_from(sys, &start, times, t_end, events, opts)
}

/// Where a run starts: time, state, dissipated work so far, and the
/// thresholds below which a watched function's initial |value| counts as 0
/// (a function that starts on its boundary, e.g. a slip velocity just after
/// slip onset, is watched only once it has left it).
#[derive(Debug, Clone)]
pub struct Start<'a> {
    /// Initial time.
    pub t: Float,
    /// Initial q.
    pub q: &'a [Float],
    /// Initial q̇.
    pub v: &'a [Float],
    /// Work dissipated before t.
    pub work: Float,
    /// Snap threshold for each event's initial value, in the order of the
    /// events (a small multiple of its [`Watch::scale`]); none (0) for an
    /// event beyond the list.
    pub snap: Vec<Float>,
}

/// [`run`] from a given start (a later mode of a motion with friction):
/// outputs at `times` ≥ start.t, events watched from the start on.
pub fn run_from(
    sys: &mut System,
    start: &Start,
    times: &[Float],
    t_end: &Float,
    events: &[Event],
    opts: &Opts,
) -> Result<Run> {
    let mut gbs = Gbs::new(
        opts.prec,
        opts.tol.clone(),
        opts.h0(),
        opts.kmax,
        (opts.kmax / 2).max(4),
    );
    run_with(sys, start, times, t_end, events, opts, &mut gbs)
}

/// Steps in a row far below the tolerance's natural step that
/// [`run_with`] takes before it refuses the motion as stiff.
const TINY_STEPS: u32 = 1000;

/// The refusal of a stiff motion at time `t`, angle `theta`, after steps
/// of `h` in a motion whose time unit is `unit`.
fn stiff(t: &Float, theta: &Float, h: &Float, unit: &Float) -> Error {
    let ratio = Float::with_val(53, h / unit);
    Error::NotConverged {
        quantity: "integration".into(),
        requested: 0,
        reached: format!(
            "{TINY_STEPS} steps of {} of the time unit at t = {}, theta = {}",
            crate::numeric::decimal::to_sig(&ratio, 2),
            crate::numeric::decimal::to_sig(t, 12),
            crate::numeric::decimal::to_sig(theta, 12)
        ),
        detail: "the motion is stiff there: a sliding contact whose accelerations are many \
                 orders of magnitude above the rest of the motion's (an extreme ratio of the \
                 masses or moments of inertia); the integrators are explicit and cannot \
                 follow it"
            .into(),
    }
}

/// [`run_from`] with a given integrator (GBS, or the Gauss–Legendre
/// collocation of [`super::collocation`] as an independent second one).
pub fn run_with<I: Stepper>(
    sys: &mut System,
    start: &Start,
    times: &[Float],
    t_end: &Float,
    events: &[Event],
    opts: &Opts,
    gbs: &mut I,
) -> Result<Run> {
    let p = opts.prec;
    let nq = sys.nq();
    let q0 = start.q;
    let mut t = Float::with_val(p, &start.t);
    let mut y: Vec<Float> = start.q.iter().chain(start.v).cloned().collect();
    if sys.has_slips() {
        y.push(Float::with_val(p, &start.work));
    }
    debug_assert_eq!(y.len(), 2 * nq + usize::from(sys.has_slips()));
    let mut cur = sample(sys, &t, &y)?;
    cur.work = Float::with_val(p, &start.work);
    let mut gprev: Vec<Float> = events
        .iter()
        .enumerate()
        .map(|(k, e)| {
            let g = watch_value(&e.watch, &cur);
            if start
                .snap
                .get(k)
                .is_some_and(|s| Float::with_val(p, g.abs_ref()) <= *s)
            {
                Float::new(p)
            } else {
                g
            }
        })
        .collect();
    let mut outputs = Vec::new();
    let mut hits = Vec::new();
    let mut max_drift = Float::new(p);
    let mut projections = 0u32;
    let mut tiny_steps = 0u32;
    let tiny = {
        let (_, tol_exp) = opts.tol.to_f64_exp();
        let natural = f64::from(tol_exp) / (2 * opts.kmax + 1) as f64;
        opts.h0() >> (30 - natural.floor() as i32)
    };
    let mut next_out = 0usize;
    // dλ/dt at the current sample, computed when a dip test needs it
    let mut rates_cur: Option<Vec<Float>> = None;
    while next_out < times.len() && times[next_out] <= t {
        outputs.push(cur.clone());
        next_out += 1;
    }
    // the loop ends with (stopped at a terminal event, the last state)
    let (stopped, last) = loop {
        let stop = if next_out < times.len() && times[next_out] < *t_end {
            times[next_out].clone()
        } else {
            t_end.clone()
        };
        let mut hmax = Float::with_val(p, &stop - &t);
        if hmax.is_sign_negative() || hmax.is_zero() {
            break (false, cur);
        }
        let mut capped = false;
        if let Some(cap) = &opts.hcap {
            if hmax > *cap {
                hmax.assign(cap);
                capped = true;
            }
        }
        crate::cancel::check()?;
        if gbs.stats().steps >= opts.max_steps {
            return Err(Error::NotConverged {
                quantity: "integration".into(),
                requested: 0,
                reached: format!(
                    "{} steps to t = {}",
                    opts.max_steps,
                    crate::numeric::decimal::to_sig(&t, 7)
                ),
                detail: "the integrator cannot follow this motion (extreme parameters?)".into(),
            });
        }
        let f0 = f_of(sys, &cur);
        let step = {
            let mut dae = Dae { sys, nq };
            gbs.step(&mut dae, &y, &f0, &hmax)?
        };
        // a thousand steps in a row, none ending at a stop, each below
        // 2^-30 of the step the tolerance implies (the start's, an eighth of
        // the time unit, times tol^(1/(2 kmax + 1)): at 30 digits 2^-3, at
        // 2000 digits 2^-55): the motion is stiff here — a contact whose
        // accelerations are many orders above the rest's (an extreme ratio
        // of masses or inertias); an explicit integrator would creep on for
        // its million steps (hours), so it is refused
        if step.h < hmax {
            if step.h < tiny {
                tiny_steps += 1;
                if tiny_steps > TINY_STEPS {
                    let theta = &y[crate::mechanics::system::th(0)];
                    return Err(stiff(&t, theta, &step.h, &opts.time_unit));
                }
            } else {
                tiny_steps = 0;
            }
        }
        let reached_stop = step.h == hmax && !capped;
        let t1 = if reached_stop {
            stop.clone()
        } else {
            Float::with_val(p, &t + &step.h)
        };
        let mut y1 = step.y;
        {
            let (q1, v1) = y1.split_at(nq);
            let d = sys.drift(q1, &v1[..nq], q0);
            if d > max_drift {
                max_drift = d.clone();
            }
            if d > opts.project_above {
                let (q1, v1) = y1.split_at_mut(nq);
                sys.project(q1, &mut v1[..nq], q0);
                projections += 1;
            }
        }
        let mut next = sample(sys, &t1, &y1)?;
        if !sys.has_slips() {
            // no sliding contact: the work is not integrated, it stays that of the start
            next.work.assign(&start.work);
        }
        let mut rates_next: Option<Vec<Float>> = None;
        let g1: Vec<Float> = events
            .iter()
            .map(|e| watch_value(&e.watch, &next))
            .collect();
        // events changing sign in this step
        let mut found: Vec<(Float, usize, Sample, Float)> = Vec::new();
        for (i, ev) in events.iter().enumerate() {
            let a = &gprev[i];
            let b = &g1[i];
            if a.is_zero() {
                // the watch starts the step at 0 (a slip velocity at its
                // onset): it leaves 0 with the sign of its rate (or, where
                // that vanishes, of its value a little into the step); ending
                // the step on the other side, it came back through 0 inside
                if b.is_zero() {
                    continue;
                }
                if let Some((smp, gx)) = left_zero(
                    sys,
                    gbs,
                    (&y, &f0, &t, &step.h, step.column),
                    &ev.watch,
                    &cur,
                    &mut rates_cur,
                )? {
                    if gx.is_sign_negative() != b.is_sign_negative() {
                        let ends = [(&smp, &gx), (&next, b)];
                        let (s, at, err) =
                            locate(sys, gbs, &y, &f0, &t, &step.h, step.column, &ev.watch, ends)?;
                        found.push((s, i, at, err));
                    }
                }
                continue;
            }
            if b.is_zero() || a.is_sign_negative() != b.is_sign_negative() {
                let ends = [(&cur, a), (&next, b)];
                let (s, at, err) =
                    locate(sys, gbs, &y, &f0, &t, &step.h, step.column, &ev.watch, ends)?;
                found.push((s, i, at, err));
            } else if let Some((xm, gm, smp)) = dip(
                sys,
                gbs,
                (&y, &f0, &t, &step.h, step.column),
                &ev.watch,
                [(&cur, a), (&next, b)],
                [&mut rates_cur, &mut rates_next],
            )? {
                // g left zero's side and came back within the step (a long
                // step at a low precision): the first crossing is in [t, t + xm]
                let ends = [(&cur, a), (&smp, &gm)];
                let (s, at, err) =
                    locate(sys, gbs, &y, &f0, &t, &xm, step.column, &ev.watch, ends)?;
                found.push((s, i, at, err));
            }
        }
        found.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap_or(std::cmp::Ordering::Equal));
        let mut terminal = None;
        for (_, i, mut at, err) in found {
            if !sys.has_slips() {
                at.work.assign(&start.work);
            }
            let term = events[i].terminal;
            hits.push(Hit {
                event: i,
                at,
                t_err: err,
            });
            if term {
                terminal = Some(hits.len() - 1);
                break;
            }
        }
        if let Some(h) = terminal {
            break (true, hits[h].at.clone());
        }
        // zeros of g at a step end count as crossings of the next step only
        // if the sign really changes; keep the last nonzero value
        for (gp, g) in gprev.iter_mut().zip(g1) {
            if !g.is_zero() {
                *gp = g;
            }
        }
        t = t1;
        y = y_of(sys, &next);
        cur = next;
        rates_cur = rates_next;
        if reached_stop {
            // every output at this time (a time may be asked twice)
            while next_out < times.len() && t == times[next_out] {
                outputs.push(cur.clone());
                next_out += 1;
            }
            if t == *t_end {
                break (false, cur);
            }
        }
    };
    Ok(Run {
        outputs,
        hits,
        stopped,
        last,
        max_drift,
        projections,
        stats: gbs.stats(),
        checkpoints: Vec::new(),
    })
}
