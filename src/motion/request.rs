//! What a run of the motion is asked ([`Request`]) and what it gives
//! ([`Motion`], [`EventRec`]), the routes and integrators a phase may take,
//! and the caches kept between runs of one question.

use super::mode::{Branch, End, Kind, Mode, Phase};
use super::point::Point;
use super::sides::Side;
use super::{default_horizon, flight};
use crate::error::Result;
use crate::exact::{Exact, TableTimes};
use crate::integrate::energy::Route as EnergyRoute;
use crate::model::{Model, Which};
use crate::numeric::verify::Run;
use rug::Float;

/// A located event.
#[derive(Debug, Clone)]
pub struct EventRec {
    /// What happened.
    pub kind: Kind,
    /// The contact concerned (None for an impact).
    pub which: Option<Which>,
    /// The phase entered (None: the end of the model).
    pub phase: Option<Phase>,
    /// The state there (the values of the phase before the event).
    pub at: Point,
    /// The estimated error of the event time.
    pub t_err: Float,
    /// The estimated error of the event angle.
    pub theta_err: Float,
    /// The state just after the event, in the phase entered (the limit of
    /// its forces and accelerations at the event; None at the end of the
    /// model).
    pub after: Option<Point>,
    /// At a branch point, every other continuation consistent there: `part`
    /// and any other closed mode (empty for other events).
    pub also: Vec<String>,
}

/// The route that computed a phase.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Route {
    /// The energy route of a conservative phase (closed forms, quadrature).
    Energy,
    /// Chebyshev spectral integration in the angle.
    Spectral,
    /// Gragg–Bulirsch–Stoer extrapolation in time.
    Gbs,
    /// Gauss–Legendre collocation in time.
    Collocation,
    /// The free flight in closed form.
    Flight,
}

impl Route {
    /// A short name for notes.
    pub fn name(self) -> &'static str {
        match self {
            Route::Energy => "energy quadrature",
            Route::Spectral => "spectral in theta",
            Route::Gbs => "GBS",
            Route::Collocation => "collocation",
            Route::Flight => "closed-form flight",
        }
    }
}

/// Which integrators to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// The fastest verified route per phase: the energy route for a
    /// conservative first phase, the spectral route in θ for the others,
    /// GBS where it declines.
    Auto,
    /// Every contact phase by the spectral route (GBS where it declines):
    /// the hybrid engine without the energy route, to check it.
    Spectral,
    /// Every contact phase by GBS.
    Gbs,
    /// Every contact phase by Gauss–Legendre collocation.
    Collocation,
}

/// How far to compute.
#[derive(Debug, Clone, PartialEq)]
pub enum Until {
    /// To the last requested time.
    LastTime,
    /// To the end of the model (the first impact, or a lift-off).
    End,
    /// To the first time θ reaches the angle (`name`: the parameter named
    /// in errors).
    Angle {
        /// The angle (user frame).
        theta: Exact,
        /// The parameter it was given as.
        name: String,
    },
}

/// What a motion is computed for.
#[derive(Debug, Clone)]
pub struct Request {
    /// Times at which to sample every column (ascending, ≥ 0).
    pub times: Vec<Exact>,
    /// How far to compute.
    pub until: Until,
    /// θ only at the times (not the other columns).
    pub theta_only: bool,
    /// The branch to follow where the motion is not unique.
    pub branch: Branch,
    /// The integrators.
    pub method: Method,
    /// The time beyond which a motion that has not ended is an error;
    /// `None`: [`default_horizon`], computed when a motion needs it (one
    /// that ends at its last requested time never does) and kept in the
    /// [`Caches`] for the ladder's other runs.
    pub horizon: Option<Float>,
    /// Which run of the ladder this is.
    pub run: Run,
    /// Digits requested (for messages).
    pub digits: u32,
    /// Decided sides of requested times at events: (row, event index,
    /// side), applied to every run ([`super::sides::apply_sides`]).
    pub sides: Vec<(usize, usize, Side)>,
    /// The decided side of the target angle at an event.
    pub target_side: Option<(usize, Side)>,
    /// δ = θ − θ0 at each row of the conservative first phase in the
    /// ladder's lower run of this rung ([`Motion::deltas`]), given to the
    /// higher run (empty otherwise): where the two runs' δ differ by more
    /// than the higher run's own error bound on δ, that difference (counted
    /// twice by the ladder) covers the error δ's bound carries into the
    /// row's columns, and the second evaluation of the columns that would
    /// measure it is spared.
    pub low_deltas: Vec<Float>,
    /// A table of every column: the rows of the conservative first phase
    /// carry t and θ only in the ladder's lower run, and the higher run
    /// computes the other columns with the error δ's bound and the formulas'
    /// roundings carry into them (given the lower run's δ), instead of
    /// comparing them with a lower run's ([`crate::integrate::energy::Route::column_errors`]),
    /// at the fewest limbs that hold the digits asked and a guard
    /// (`energy::derived_prec`), those roundings counted, or at the run's
    /// precision where a column cancels there.
    pub derived_at_high: bool,
}

impl Request {
    /// A motion to its end, sampled at `times`, on the default branch and
    /// routes (the horizon [`default_horizon`] of the model it is run for,
    /// computed when needed).
    pub fn to_end(times: Vec<Exact>) -> Self {
        Request {
            times,
            until: Until::End,
            theta_only: false,
            branch: Branch::Stay,
            method: Method::Auto,
            horizon: None,
            run: Run::High,
            digits: 0,
            sides: Vec::new(),
            target_side: None,
            low_deltas: Vec::new(),
            derived_at_high: false,
        }
    }
}

/// The motion at one working precision.
#[derive(Debug, Clone)]
pub struct Motion {
    /// The mode at t = 0.
    pub start_mode: Mode,
    /// The events, in time order.
    pub events: Vec<EventRec>,
    /// The rows at the requested times.
    pub rows: Vec<Point>,
    /// δ = θ − θ0 (the energy route's working frame, at this precision) of
    /// the rows in a conservative first phase, as computed there (θ itself
    /// is rounded to the precision relative to θ0, δ is not).
    pub deltas: Vec<Float>,
    /// θ, the phase and (from the energy route) θ's error bound at the
    /// requested times ([`Request::theta_only`]).
    pub thetas: Vec<(Float, Phase, Option<Float>)>,
    /// The state at separation, if reached.
    pub separation: Option<Point>,
    /// The first impact (the state just before it).
    pub impact: Option<flight::Impact>,
    /// How it ended (None: at the last time, before the end of the model).
    pub end: Option<End>,
    /// The state where θ first reached the target angle.
    pub target: Option<Point>,
    /// Largest |E(t) + W(t) − E(0)| over every computed state, relative to
    /// the energy scale m2 g r.
    pub energy_drift: Float,
    /// The energy's own scale in units of m2 g r, at least 1: max(1,
    /// |E(0)|/(m2 g r)) (E's zero at cylinder 1's centre). The balance is
    /// verified relative to it: the roundings and the integration's
    /// tolerance act on E, which a fast common rolling (omega0) or a heavy
    /// lower cylinder's kinetic energy makes far larger than m2 g r.
    pub energy_unit: Float,
    /// Integrator work over all phases: (accepted steps or pieces,
    /// evaluations of the equations of motion).
    pub work_done: (u64, u64),
    /// The route of each phase, in order.
    pub routes: Vec<Route>,
    /// Where parting was lawful while the cylinders stayed together: (θ
    /// where it became so, θ where it stopped — None: up to the end of the
    /// closed branch). Empty where the motion is unique.
    pub windows: Vec<(Float, Option<Float>)>,
    /// A branch point before θs taken as θs, being θs to the digits asked.
    pub merged_branch: bool,
    /// Per row: the event whose time it cannot be told apart from at this
    /// precision ([`super::sides::mark_near`]).
    pub near: Vec<Option<usize>>,
    /// The event whose angle the target cannot be told apart from.
    pub target_near: Option<usize>,
    /// The time unit sqrt(r/g) of the model: the natural scale of its
    /// times (a time's margin at an event is relative to it).
    pub ts: Float,
    /// The requested times at the working precision (converted once: a
    /// rational's conversion is a division, and a table reads them in
    /// several places).
    pub times: Vec<Float>,
}

impl Motion {
    /// The working precision of the motion.
    pub fn prec(&self) -> u32 {
        self.energy_drift.prec()
    }
}

/// The energy routes a motion may use, kept by the caller across the
/// precisions of a ladder (explicit caches: the quadrature engines, δs and
/// t_s per precision).
#[derive(Default)]
pub struct Caches {
    /// The energy route of the model with every Coulomb contact sticking.
    pub sticking: Option<EnergyRoute>,
    /// The model's [`default_horizon`], once computed.
    pub horizon: Option<Float>,
    /// The request's times: rounded to odd once, for every run's rounding
    /// of them, and at the Taylor route's precision for both runs of a rung
    /// ([`TableTimes`]; without a rounding each run converts them). Made by
    /// the crate only, from the request's own times, which do not change
    /// after.
    pub(crate) times: TableTimes,
}

impl Caches {
    /// The energy route of `model.sticking()`, built on first use.
    ///
    /// Errors: as [`EnergyRoute::new`].
    pub fn sticking(&mut self, model: &Model) -> Result<&mut EnergyRoute> {
        if self.sticking.is_none() {
            self.sticking = Some(EnergyRoute::new(&model.sticking())?);
        }
        Ok(self.sticking.as_mut().expect("set above"))
    }

    /// [`default_horizon`] of `model`, computed on first use.
    pub fn horizon(&mut self, model: &Model) -> &Float {
        self.horizon.get_or_insert_with(|| default_horizon(model))
    }
}
