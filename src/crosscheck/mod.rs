//! The second route: time integration of the constrained equations of motion
//! (paper appendix A.5, eq. 57), independent of the energy quadrature.
//!
//! * [`system`]: the n-cylinder stack in relaxed coordinates
//!   q = (x1, y1, φ1, ψ2, θ1, r1, ψ3, θ2, r2, …) — for two cylinders exactly
//!   (x1, y1, φ1, ψ2, θ, r) — its mass matrix, generalised forces,
//!   constraint rows of every contact model, and the KKT solve for q̈ and the
//!   multipliers λ, which are the constraint forces (for n = 2: F1, F21, N12,
//!   N1 of the paper's eqs. 110–114).
//! * [`crate::integrate::gbs`]: Gragg–Bulirsch–Stoer extrapolation on `rug::Float` with error
//!   estimation, step-size and order control (ODEX-style), so the local
//!   error can be driven to hundreds of digits.
//! * [`solve`]: the driver: integrates y = (q, q̇), samples at given times,
//!   locates events (N12 = 0, N1 = 0, θ̇ = 0, …) to full precision by
//!   re-integration from the step's start and Newton's method safeguarded
//!   by the bracket, measures constraint drift (and projects back onto the
//!   manifold if it ever exceeds 2^−(prec+8); it has not in any case run).
//! * [`crate::stack::spec`]: the `--stack` SPEC syntax (`stack_report("help", ..)` prints it).
//! * [`golden`]: every number of a golden data file recomputed by this route.
//!
//! The route shares with the first only the model and the precision ladder
//! ([`crate::numeric::verify::ladder`]: every value is computed at two
//! precisions p, each with its own local tolerance 2^−(p−8), and only
//! agreeing digits are kept). Internally the arithmetic carries
//! ⌈1.1 kmax⌉ + 16 guard bits above p (kmax = the largest extrapolation
//! column, at most 60) because the extrapolation tableau amplifies rounding
//! errors by up to 2^(1.1 k) at column k. Accuracy kind: *estimated*, like
//! the first route.
//!
//! Limits: an event is found only if its function changes sign between two
//! step ends (two zeros inside one step, e.g. a brief double turning point,
//! would be missed); events are not searched for inside the first step if
//! the watched function starts at exactly 0 (a start from rest).
//!
//! Entry points: [`verify_report`] (both routes on a set of cases, a table
//! of agreeing digits), [`crate::stack::stack_report`] (footnote 3: n ≥ 2 cylinders),
//! [`two_cylinder`] (route 2 for a [`Ideal`] at one precision).

pub mod golden;
pub mod routes;
mod verify;

pub use verify::{agreement, cases, compare_case, CaseReport, Comparison, VerifyCase};

use crate::error::{Error, Result};
use crate::integrate::solve::{self, Event, Opts, Run, Watch};
use crate::integrate::{time_scale, TOL_GUARD};
use crate::mechanics::system::{self, Row, StackModel, System};
use crate::model::{Floor, Ideal};
use crate::motion::point::{two_state, TwoState};
use rug::Float;

/// Runs both routes on the built-in case set and returns the agreement table.
///
/// Errors: a route that cannot verify `digits` digits of some quantity.
pub fn verify_report(digits: u32) -> Result<verify::VerifyReport> {
    verify::report(digits)
}

/// Route 2 for a two-cylinder model at one precision.
#[derive(Debug, Clone)]
pub struct TwoRun {
    /// The samples at the requested times.
    pub rows: Vec<TwoState>,
    /// The state at separation (N12 = 0), if reached before `t_end`.
    pub separation: Option<(TwoState, Float)>,
    /// Where N1 first vanished (the run goes on through it, as the first
    /// route does), with the time's bracket half-width.
    pub n1_zero: Option<(TwoState, Float)>,
    /// Where φ̇1 and φ1 first changed sign (when asked for).
    pub phi1dot_zero: Option<(TwoState, Float)>,
    /// See `phi1dot_zero`.
    pub phi1_zero: Option<(TwoState, Float)>,
    /// Turning points θ̇ = 0 before separation.
    pub turning: Vec<(TwoState, Float)>,
    /// The state at the first crossing of each angle of [`TwoOpts::reach`]
    /// (`None`: not reached before separation).
    pub reached: Vec<Option<TwoState>>,
    /// Largest relative change of the energy over the samples and events.
    pub energy_drift: Float,
    /// Largest change of the conserved momenta over the samples and events.
    pub momentum_drift: Float,
    /// The integration record (drift, work).
    pub run: Run,
}

/// Options of [`two_cylinder`].
#[derive(Debug, Clone, Default)]
pub struct TwoOpts {
    /// Also locate where φ̇1 and φ1 change sign.
    pub phi1_events: bool,
    /// Angles θ at which to record the state (the first crossing of each).
    pub reach: Vec<Float>,
}

/// Integrates a two-cylinder model at `prec` bits from t = 0, sampling at
/// `times` and stopping at separation (N12 = 0) or at `t_end`.
///
/// Errors: a start exactly at rest at the top (nothing ever moves); a start
/// where the cylinders already part; numerical failures of the integrator.
pub fn two_cylinder(
    model: &Ideal,
    prec: u32,
    times: &[Float],
    t_end: &Float,
    opts: &TwoOpts,
) -> Result<TwoRun> {
    let sm = StackModel::from_model(model);
    if sm.starts_at_equilibrium() {
        return Err(Error::not_physical(
            "the motion starts from rest exactly at the unstable top: every time is infinite",
        ));
    }
    let ts = time_scale(&sm, prec);
    let o = Opts::for_prec(prec, TOL_GUARD, &ts);
    let mut sys = System::new(&sm, o.prec)?;
    let (q0, v0) = sys.initial_state(&sm)?;
    let idx = |row: Row| sys.rows.iter().position(|r| *r == row);
    let n12 = idx(Row::Normal(0)).ok_or_else(|| Error::not_physical("no N12 row"))?;
    let n1 = idx(Row::FloorNormal).ok_or_else(|| Error::not_physical("no N1 row"))?;
    let mut events = vec![
        Event {
            name: "N12".into(),
            watch: Watch::Multiplier(n12),
            terminal: true,
        },
        Event {
            name: "N1".into(),
            watch: Watch::Multiplier(n1),
            terminal: false,
        },
        Event {
            name: "theta_dot".into(),
            watch: Watch::Rate(system::th(0)),
            terminal: false,
        },
    ];
    if opts.phi1_events && model.floor() != Floor::Fixed {
        events.push(Event {
            name: "phi1_dot".into(),
            watch: Watch::Rate(system::PHI1),
            terminal: false,
        });
        events.push(Event {
            name: "phi1".into(),
            watch: Watch::Coord(system::PHI1),
            terminal: false,
        });
    }
    for (k, th) in opts.reach.iter().enumerate() {
        events.push(Event {
            name: format!("reach{k}"),
            watch: Watch::Reach {
                i: system::th(0),
                value: Float::with_val(o.prec, th),
            },
            terminal: false,
        });
    }
    // the start must have both contacts pressing
    let a0 = sys.accel(&q0, &v0)?;
    if !a0.lambda[n12].is_sign_positive() || a0.lambda[n12].is_zero() {
        return Err(Error::not_physical(
            "the cylinders part at once: N12 <= 0 at the start",
        ));
    }
    let run = solve::run(&mut sys, &q0, &v0, times, t_end, &events, &o)?;
    let mut out = TwoRun {
        rows: run.outputs.iter().map(|s| two_state(&sys, s)).collect(),
        separation: None,
        n1_zero: None,
        phi1dot_zero: None,
        phi1_zero: None,
        turning: Vec::new(),
        reached: vec![None; opts.reach.len()],
        energy_drift: Float::new(prec),
        momentum_drift: Float::new(prec),
        run: run.clone(),
    };
    for h in &run.hits {
        let st = (two_state(&sys, &h.at), h.t_err.clone());
        match events[h.event].name.as_str() {
            "N12" => out.separation = Some(st),
            "N1" => {
                if out.n1_zero.is_none() {
                    out.n1_zero = Some(st)
                }
            }
            "theta_dot" => out.turning.push(st),
            name if name.starts_with("reach") => {
                if let Ok(k) = name["reach".len()..].parse::<usize>() {
                    if out.reached[k].is_none() {
                        out.reached[k] = Some(st.0);
                    }
                }
            }
            "phi1_dot" => {
                if out.phi1dot_zero.is_none() {
                    out.phi1dot_zero = Some(st)
                }
            }
            _ => {
                if out.phi1_zero.is_none() {
                    out.phi1_zero = Some(st)
                }
            }
        }
    }
    // conservation over every recorded state
    let e0 = sys.energy(&q0, &v0);
    let p0 = sys.momenta(&q0, &v0);
    let (escale, pscale) = sys.drift_scales(&e0);
    (out.energy_drift, out.momentum_drift) = sys.drifts(run.states(), &e0, &p0, &escale, &pscale);
    Ok(out)
}
