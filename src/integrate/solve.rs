//! Time integration of the index-reduced constrained equations with event
//! location: the driver around [`super::gbs`] and [`super::system`].
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

use super::gbs::{Gbs, Rhs, Stats, Stepper};
use crate::error::{Error, Result};
use crate::mechanics::system::System;
use rug::{Assign, Float};

/// What an event watches.
#[derive(Debug, Clone, PartialEq)]
pub enum Watch {
    /// The multiplier of constraint row i (a constraint force).
    Multiplier(usize),
    /// The rate q̇_i.
    Rate(usize),
    /// The coordinate q_i.
    Coord(usize),
    /// A linear combination of the above with constant coefficients (a
    /// slip velocity Σ c_i q̇_i, a friction cone μ N − F).
    Lin(Vec<(Watch, Float)>),
    /// q_i − value: a coordinate reaching a given value.
    Reach {
        /// Index of the coordinate.
        i: usize,
        /// The value.
        value: Float,
    },
    /// r θ̇² − g cos θ − a sin θ (θ = q_th, θ̇ = q̇_th): the relative normal
    /// acceleration of two centres at distance r along the line of centres
    /// θ if the upper body fell freely and the lower one accelerated
    /// horizontally by `a` (the free relative normal acceleration of a
    /// contact; positive: the free motion separates).
    FreeNormal {
        /// Index of θ.
        th: usize,
        /// r.
        r: Float,
        /// g.
        g: Float,
        /// The lower body's horizontal acceleration.
        a: Float,
    },
    /// offset + r cos q_th: a height above the floor of a point at distance
    /// r along the line of centres θ = q_th (e.g. cylinder 2's lowest point).
    Height {
        /// Index of θ.
        th: usize,
        /// r.
        r: Float,
        /// offset.
        offset: Float,
    },
}

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
    /// First step size.
    pub h0: Float,
    /// Largest extrapolation column.
    pub kmax: usize,
    /// Drift above which the state is projected back onto the manifold.
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
            h0: Float::with_val(work, time_scale / 8u32),
            kmax,
            project_above: Float::with_val(work, 1u32) >> (prec as i32 + 8),
            hcap: None,
            max_steps: 1_000_000,
        }
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
    })
}

/// The value of a watched function at a sample.
/// Every watched function at a sample, with sin θ and cos θ computed once
/// for all the watches that need them (a height, a free normal
/// acceleration): at high precision a trigonometric call costs more than the
/// rest of a watch.
pub fn watch_values<'a>(watches: impl Iterator<Item = &'a Watch>, s: &Sample) -> Vec<Float> {
    let mut trig: Option<(usize, Float, Float)> = None;
    let mut sc = |th: usize| -> (Float, Float) {
        match &trig {
            Some((i, sn, cs)) if *i == th => (sn.clone(), cs.clone()),
            _ => {
                let p = s.q[th].prec();
                let (sn, cs) = s.q[th].clone().sin_cos(Float::new(p));
                trig = Some((th, sn.clone(), cs.clone()));
                (sn, cs)
            }
        }
    };
    watches
        .map(|w| match w {
            Watch::Height { th, r, offset } => {
                let (_, cs) = sc(*th);
                cs * r + offset
            }
            Watch::FreeNormal { th, r, g, a } => {
                let p = s.q[*th].prec();
                let (sn, cs) = sc(*th);
                let td2 = Float::with_val(p, s.v[*th].square_ref());
                Float::with_val(p, r * &td2) - Float::with_val(p, g * &cs) - Float::with_val(p, a * &sn)
            }
            other => watch_value(other, s),
        })
        .collect()
}

/// The watched function at a sample.
pub fn watch_value(w: &Watch, s: &Sample) -> Float {
    match w {
        Watch::Multiplier(i) => s.lambda[*i].clone(),
        Watch::Rate(i) => s.v[*i].clone(),
        Watch::Coord(i) => s.q[*i].clone(),
        Watch::Lin(terms) => {
            let mut acc = Float::new(s.t.prec().max(s.v[0].prec()));
            for (w, c) in terms {
                acc += watch_value(w, s) * c;
            }
            acc
        }
        Watch::Height { th, r, offset } => {
            let c = Float::with_val(s.q[*th].prec(), s.q[*th].cos_ref());
            c * r + offset
        }
        Watch::Reach { i, value } => Float::with_val(s.q[*i].prec(), &s.q[*i] - value),
        Watch::FreeNormal { th, r, g, a } => {
            let p = s.q[*th].prec();
            let (sn, cs) = s.q[*th].clone().sin_cos(Float::new(p));
            let td2 = Float::with_val(p, s.v[*th].square_ref());
            Float::with_val(p, r * &td2) - Float::with_val(p, g * &cs) - Float::with_val(p, a * &sn)
        }
    }
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
        snap: Float::new(opts.prec),
    };
    run_from(sys, &start, times, t_end, events, opts)
}

/// Where a run starts: time, state, dissipated work so far, and the
/// threshold below which a watched function's initial |value| counts as 0
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
    /// Snap threshold for initial event values.
    pub snap: Float,
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
        opts.h0.clone(),
        opts.kmax,
        (opts.kmax / 2).max(4),
    );
    run_with(sys, start, times, t_end, events, opts, &mut gbs)
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
        .map(|e| {
            let g = watch_value(&e.watch, &cur);
            if Float::with_val(p, g.abs_ref()) <= start.snap {
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
                reached: format!("{} steps to t = {:.6e}", opts.max_steps, t.to_f64()),
                detail: "the integrator cannot follow this motion (extreme parameters?)".into(),
            });
        }
        let f0 = f_of(sys, &cur);
        let step = {
            let mut dae = Dae { sys, nq };
            gbs.step(&mut dae, &y, &f0, &hmax)?
        };
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

/// dg/dt of the watched function at a sample: q̈ or q̇ exactly; for a
/// multiplier, a central difference of λ along the flow with step
/// ε = 2^−(prec/3) (relative error about 2^−(2 prec/3)).
fn rate_of(sys: &mut System, w: &Watch, s: &Sample) -> Result<Float> {
    let p = sys.prec;
    match w {
        Watch::Rate(i) => Ok(s.qdd[*i].clone()),
        Watch::Coord(i) | Watch::Reach { i, .. } => Ok(s.v[*i].clone()),
        Watch::Height { th, r, .. } => {
            let sn = Float::with_val(p, s.q[*th].sin_ref());
            Ok(-(sn * r * &s.v[*th]))
        }
        Watch::FreeNormal { th, r, g, a } => {
            // d/dt (r θ̇² − g cos θ − a sin θ) = θ̇ (2 r θ̈ + g sin θ − a cos θ)
            let (sn, cs) = s.q[*th].clone().sin_cos(Float::new(p));
            let inner = Float::with_val(p, r * &s.qdd[*th]) * 2u32 + Float::with_val(p, g * &sn)
                - Float::with_val(p, a * &cs);
            Ok(inner * &s.v[*th])
        }
        Watch::Multiplier(k) => Ok(lambda_rates(sys, s)?.swap_remove(*k)),
        Watch::Lin(terms) => {
            let mut acc = Float::new(p);
            let mut lr: Option<Vec<Float>> = None;
            for (w, c) in terms {
                let d = match w {
                    Watch::Multiplier(k) => {
                        if lr.is_none() {
                            lr = Some(lambda_rates(sys, s)?);
                        }
                        lr.as_ref().map_or_else(|| Float::new(p), |l| l[*k].clone())
                    }
                    other => rate_of(sys, other, s)?,
                };
                acc += d * c;
            }
            Ok(acc)
        }
    }
}

/// dλ/dt of every multiplier at a sample: a central difference along the
/// flow with step ε = 2^−(prec/3) (relative error about 2^−(2 prec/3)).
fn lambda_rates(sys: &mut System, s: &Sample) -> Result<Vec<Float>> {
    let p = sys.prec;
    let eps = Float::with_val(p, 1u32) >> (p as i32 / 3);
    let shifted = |sign: i32| {
        let q: Vec<Float> =
            s.q.iter()
                .zip(&s.v)
                .map(|(q, v)| Float::with_val(p, q + Float::with_val(p, v * &eps) * sign))
                .collect();
        let v: Vec<Float> =
            s.v.iter()
                .zip(&s.qdd)
                .map(|(v, a)| Float::with_val(p, v + Float::with_val(p, a * &eps) * sign))
                .collect();
        (q, v)
    };
    let (qp, vp) = shifted(1);
    let (qm, vm) = shifted(-1);
    let ap = sys.accel(&qp, &vp)?;
    let am = sys.accel(&qm, &vm)?;
    let two_eps = Float::with_val(p, &eps * 2u32);
    Ok(ap
        .lambda
        .iter()
        .zip(&am.lambda)
        .map(|(a, b)| Float::with_val(p, a - b) / &two_eps)
        .collect())
}

/// The watched function and the state at t + x, re-integrated from the
/// step's start (y0, f0 at t) with one step of size x at `column`.
fn watch_after<I: Stepper>(
    sys: &mut System,
    gbs: &mut I,
    (y0, f0, t, column): (&[Float], &[Float], &Float, usize),
    x: &Float,
    watch: &Watch,
) -> Result<(Float, Sample)> {
    let y = {
        let nq = sys.nq();
        let mut dae = Dae { sys, nq };
        gbs.fixed_step(&mut dae, y0, f0, x, column)?
    };
    let tx = Float::with_val(gbs.prec(), t + x);
    let smp = sample(sys, &tx, &y)?;
    Ok((watch_value(watch, &smp), smp))
}

/// For a watch that is 0 at the step's start: a state a little into the
/// step where it is nonzero with the sign it leaves 0 with, and its value
/// there — at h·2^−k (k = 6, 10, 14, 18) the first point whose sign is that
/// of the rate at the start (or, where the rate vanishes, the first nonzero
/// value). `None` if the watch stays 0 that long.
fn left_zero<I: Stepper>(
    sys: &mut System,
    gbs: &mut I,
    (y0, f0, t, h, column): (&[Float], &[Float], &Float, &Float, usize),
    watch: &Watch,
    cur: &Sample,
    cache: &mut Option<Vec<Float>>,
) -> Result<Option<(Sample, Float)>> {
    let p = gbs.prec();
    let d0 = rate_cached(sys, watch, cur, cache)?;
    for k in [6u32, 10, 14, 18] {
        let x = Float::with_val(p, h >> k);
        let (gx, smp) = watch_after(sys, gbs, (y0, f0, t, column), &x, watch)?;
        if gx.is_zero() {
            continue;
        }
        if d0.is_zero() || gx.is_sign_negative() == d0.is_sign_negative() {
            return Ok(Some((smp, gx)));
        }
    }
    Ok(None)
}

/// dg/dt as [`rate_of`], with the multipliers' rates of the sample computed
/// at most once (`cache`).
fn rate_cached(
    sys: &mut System,
    w: &Watch,
    s: &Sample,
    cache: &mut Option<Vec<Float>>,
) -> Result<Float> {
    let p = sys.prec;
    match w {
        Watch::Multiplier(k) => {
            if cache.is_none() {
                *cache = Some(lambda_rates(sys, s)?);
            }
            Ok(cache
                .as_ref()
                .map_or_else(|| Float::new(p), |l| l[*k].clone()))
        }
        Watch::Lin(terms) => {
            let mut acc = Float::new(p);
            for (w, c) in terms {
                acc += rate_cached(sys, w, s, cache)? * c;
            }
            Ok(acc)
        }
        other => rate_of(sys, other, s),
    }
}

/// A watched function with the same sign at both ends of a step may still
/// have crossed zero twice inside it (a friction cone left and re-entered
/// within one long step). Its cubic Hermite interpolant (values and rates at
/// both ends) tells where it comes closest to zero; if the interpolant
/// reaches zero's side, g itself is evaluated there (re-integrating at the
/// step's column), and a sign opposite to the ends' gives a bracket of the
/// first crossing: (x, g(x), the state there).
#[allow(clippy::type_complexity)]
fn dip<I: Stepper>(
    sys: &mut System,
    gbs: &mut I,
    (y0, f0, t, h, column): (&[Float], &[Float], &Float, &Float, usize),
    watch: &Watch,
    ends: [(&Sample, &Float); 2],
    caches: [&mut Option<Vec<Float>>; 2],
) -> Result<Option<(Float, Float, Sample)>> {
    let (s0, ga) = ends[0];
    let (s1, gb) = ends[1];
    let [c0, c1] = caches;
    let d0 = rate_cached(sys, watch, s0, c0)?;
    // moving away from zero at the start and towards it never at the end:
    // a cubic with these slopes has no interior extremum on zero's side
    let pos = !ga.is_sign_negative();
    let toward0 = if pos {
        d0.is_sign_negative()
    } else {
        d0.is_sign_positive()
    };
    if !toward0 {
        return Ok(None);
    }
    let d1 = rate_cached(sys, watch, s1, c1)?;
    let hf = h.to_f64();
    let (g0, g1, r0, r1) = (ga.to_f64(), gb.to_f64(), d0.to_f64(), d1.to_f64());
    let val = |x: f64| hermite(hf, g0, r0, g1, r1, x);
    // the interpolant's closest approach to zero, on a fine grid
    let sgn = if pos { 1.0 } else { -1.0 };
    let (mut xm, mut vm) = (0.0, f64::INFINITY);
    for k in 1..128 {
        let x = hf * k as f64 / 128.0;
        let v = sgn * val(x);
        if v < vm {
            (xm, vm) = (x, v);
        }
    }
    // reaches zero, or comes within a tenth of the smaller end value
    if vm > 0.1 * (g0.abs().min(g1.abs())) {
        return Ok(None);
    }
    let p = gbs.prec();
    let x = Float::with_val(p, xm);
    let (gx, smp) = watch_after(sys, gbs, (y0, f0, t, column), &x, watch)?;
    if !gx.is_zero() && gx.is_sign_negative() != pos {
        return Ok(None);
    }
    Ok(Some((x, gx, smp)))
}

/// The cubic Hermite interpolant at x ∈ [0, h] of g with values g0, g1 and
/// slopes d0, d1 at the ends (f64: for starting points only).
fn hermite(h: f64, g0: f64, d0: f64, g1: f64, d1: f64, x: f64) -> f64 {
    let u = x / h;
    let h00 = 2.0 * u * u * u - 3.0 * u * u + 1.0;
    let h10 = u * u * u - 2.0 * u * u + u;
    let h01 = -2.0 * u * u * u + 3.0 * u * u;
    let h11 = u * u * u - u * u;
    h00 * g0 + h10 * h * d0 + h01 * g1 + h11 * h * d1
}

/// The root in (0, h) of the cubic Hermite interpolant of g with values
/// and slopes at both ends (f64: only a starting point).
fn hermite_root(h: f64, g0: f64, d0: f64, g1: f64, d1: f64) -> f64 {
    let val = |x: f64| hermite(h, g0, d0, g1, d1, x);
    // bisection on the cubic keeps the sign change of the ends
    let (mut a, mut b) = (0.0, h);
    let fa = val(a);
    for _ in 0..60 {
        let m = 0.5 * (a + b);
        let fm = val(m);
        if fm == 0.0 {
            return m;
        }
        if (fm < 0.0) == (fa < 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// Locates the zero of the watched function inside the step [t, t + h]
/// (`ends`: the samples and values of g at t and t + h, of opposite signs)
/// by re-integrating from y0 with step s at `column`: a start from the cubic
/// Hermite interpolant of g, then Newton's method on s (dg/dt from
/// [`rate_of`]) safeguarded by the bracket, until the correction is below
/// (|t| + 1)·tol/16. Returns (s, the state there, the error estimate).
#[allow(clippy::too_many_arguments)]
fn locate<I: Stepper>(
    sys: &mut System,
    gbs: &mut I,
    y0: &[Float],
    f0: &[Float],
    t: &Float,
    h: &Float,
    column: usize,
    watch: &Watch,
    ends: [(&Sample, &Float); 2],
) -> Result<(Float, Sample, Float)> {
    let p = gbs.prec();
    let eval = |sys: &mut System, gbs: &mut I, s: &Float| -> Result<(Float, Sample)> {
        watch_after(sys, gbs, (y0, f0, t, column), s, watch)
    };
    let (s0, ga) = ends[0];
    let (s1, gb) = ends[1];
    let tol = Float::with_val(p, Float::with_val(p, t + h).abs() + 1u32) * gbs.tol() / 16u32;
    // bracket [a, b] with g(a) of the sign of ga
    let neg_a = ga.is_sign_negative();
    // the bracket starts where the first end's sample is (0, or inside the
    // step for a watch that started at 0)
    let mut a = Float::with_val(p, &s0.t - t);
    let mut b = h.clone();
    let d0 = rate_of(sys, watch, s0)?;
    let d1 = rate_of(sys, watch, s1)?;
    let hf = Float::with_val(p, &b - &a).to_f64();
    let guess = hermite_root(hf, ga.to_f64(), d0.to_f64(), gb.to_f64(), d1.to_f64());
    let mut x = Float::with_val(p, guess) + &a;
    if !(x > a && x < b) {
        x = Float::with_val(p, &a + &b) / 2u32;
    }
    for _ in 0..200 {
        let (gx, smp) = eval(sys, gbs, &x)?;
        if gx.is_zero() {
            return Ok((x, smp, tol));
        }
        if gx.is_sign_negative() == neg_a {
            a = x.clone();
        } else {
            b = x.clone();
        }
        let d = rate_of(sys, watch, &smp)?;
        let corr = Float::with_val(p, &gx / &d);
        let width = Float::with_val(p, &b - &a);
        if Float::with_val(p, corr.abs_ref()) <= tol || width <= tol {
            let err = Float::with_val(p, corr.abs_ref()).min(&width) + &tol;
            return Ok((x, smp, err));
        }
        let mut nx = Float::with_val(p, &x - &corr);
        if !nx.is_finite() || nx <= a || nx >= b {
            nx = Float::with_val(p, &a + &b) / 2u32;
        }
        x = nx;
    }
    Err(Error::NotConverged {
        quantity: "event time".into(),
        requested: 0,
        reached: format!("bracket width {:.3e}", Float::with_val(p, &b - &a).to_f64()),
        detail: format!("inside the step from t = {:.6e}", t.to_f64()),
    })
}
