//! Finite Coulomb friction: the motion as a sequence of modes separated by
//! events, through slipping to separation, and the free flight to the first
//! impact.
//!
//! * [`law`]: the contact laws (`Roll` = μ ∞, `Slip` = μ 0, `Coulomb` with
//!   μs ≥ μk) and the modes (each contact sticking or slipping either way).
//! * This module: one constrained system per mode, built by the second
//!   route's KKT machinery ([`crate::mechanics::system`]): a sticking contact is a
//!   velocity constraint whose multiplier is its tangential force; a
//!   slipping one is the applied force −μk σ N along its slip direction,
//!   with N the multiplier of its normal row (so the KKT matrix gains μk σ
//!   J_t in N's column). Each mode is integrated by Chebyshev spectral
//!   quadrature in the angle ([`crate::integrate::spectral`]: q̈ and λ are affine
//!   in θ̇², so θ̇² solves a linear ODE in θ), with the dissipated work
//!   E(0) − E(t) = ∫ μk N |s| dt among the quadratures; its events (cone
//!   reached, slip speed zero, N12 = 0, N1 = 0) are roots of the
//!   interpolants. A mode the angle cannot parametrise (θ̇ reaching 0) is
//!   integrated by Gragg–Bulirsch–Stoer extrapolation in time instead, and
//!   [`Method`] selects GBS or Gauss–Legendre collocation throughout for
//!   the cross-checks.
//! * At the start and at every event every candidate continuation is tested
//!   for consistency just after it ([`decide`]): each contact sticking
//!   (needed |F| ≤ μs N), slipping either way (slip speed of that sign,
//!   N > 0) and the contact between the cylinders opening (free relative
//!   normal acceleration > 0). The unique consistent one is taken; none or
//!   several (Painlevé-type situations), or a singular constraint system,
//!   stop with [`Error::NotConverged`] (exit 3) naming the place.
//! * [`flight`]: after separation, cylinder 2 flies ballistically and
//!   cylinder 1 goes on under its floor law, in closed form, to the first
//!   impact (cylinder 2 on the floor or on cylinder 1 again).
//! * [`answer`]: the verified answers (two working precisions, the event
//!   sequences compared, every number judged by the precision ladder).
//!
//! Slip speeds (README, "Conventions"): floor s1 = ẋ1 − r1 φ̇1, the velocity
//! of cylinder 1's contact point over the floor along +x; contact s12 =
//! r θ̇ + r2 ψ̇2 − r1 φ̇1 (ψ2 = φ2 − θ the counter-clockwise rotation of
//! cylinder 2), the velocity of cylinder 2's contact point over cylinder 1's
//! along (cos θ, −sin θ). A slipping contact's tangential force is
//! F1 = −μk N1 sgn s1, F21 = −μk N12 sgn s12.

pub mod answer;
pub mod flight;
pub mod law;
pub mod point;

pub use law::{Friction, Law, Mode, State};

use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::integrate::solve::{self, Event, Opts, Sample, Start, Watch};
use crate::integrate::{time_scale, TOL_GUARD};
use crate::mechanics::system::{self as sy, Row, SlipTerm, StackModel, System, Tangent};
use crate::model::{Contact, Floor, Model};
use point::TwoState;
use rug::{Float, Rational};

/// Which contact an event concerns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Which {
    /// The floor under cylinder 1.
    Floor,
    /// The contact between the cylinders.
    Contact,
}

impl Which {
    /// `floor` or `contact`.
    pub fn name(self) -> &'static str {
        match self {
            Which::Floor => "floor",
            Which::Contact => "contact",
        }
    }
}

/// What happened at an event.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A sticking contact's needed |F|/N reached μs; it slips from here.
    SlipOnset,
    /// A slipping contact's slip speed returned to 0 and it sticks.
    Stick,
    /// A slipping contact's slip speed returned to 0 and it slips the other way.
    SlipReversal,
    /// N12 = 0: the cylinders part.
    Separation,
    /// N1 = 0: cylinder 1 leaves the floor (the motion after it is outside
    /// the model).
    LiftOff,
    /// The first impact after separation (impact laws are outside the model).
    Impact,
}

impl Kind {
    /// The JSON name.
    pub fn name(self) -> &'static str {
        match self {
            Kind::SlipOnset => "slip_onset",
            Kind::Stick => "stick",
            Kind::SlipReversal => "slip_reversal",
            Kind::Separation => "separation",
            Kind::LiftOff => "lift_off",
            Kind::Impact => "impact",
        }
    }
}

/// Every column of the motion at one time: the columns of the ideal
/// models ([`TwoState`], reached through `Deref`: `point.theta`), the slip
/// speeds and the dissipated work.
#[derive(Debug, Clone)]
pub struct Point {
    /// t, θ (in flight: the direction of the line of centres), its rates,
    /// the angles, positions and the forces F1, N1, F21, N12 (the contact's
    /// are 0 in flight).
    pub state: TwoState,
    /// Floor slip speed s1.
    pub s1: Float,
    /// Contact slip speed s12 (0 in flight, where there is no contact).
    pub s12: Float,
    /// Energy dissipated by friction since t = 0.
    pub work: Float,
    /// Total energy T + V.
    pub energy: Float,
    /// The mode (None: free flight after separation).
    pub mode: Option<Mode>,
}

impl std::ops::Deref for Point {
    type Target = TwoState;
    fn deref(&self) -> &TwoState {
        &self.state
    }
}

/// The columns a motion with friction adds to those of the ideal models
/// ([`crate::oracle::TRAJECTORY_COLUMNS`]).
pub const EXTRA_COLUMNS: [&str; 3] = ["s1", "s12", "work"];

/// The column names of [`Point::columns`]: the ideal models' columns, then
/// [`EXTRA_COLUMNS`].
pub fn columns() -> Vec<&'static str> {
    crate::oracle::TRAJECTORY_COLUMNS
        .iter()
        .chain(&EXTRA_COLUMNS)
        .copied()
        .collect()
}

impl Point {
    /// The values in [`columns`] order.
    pub fn columns(&self) -> Vec<Float> {
        let mut v = self.state.columns().to_vec();
        v.extend([self.s1.clone(), self.s12.clone(), self.work.clone()]);
        v
    }

    /// The mode's tag, or `flight`.
    pub fn mode_tag(&self) -> String {
        self.mode.map_or_else(|| "flight".to_string(), |m| m.tag())
    }
}

/// A located event.
#[derive(Debug, Clone)]
pub struct EventRec {
    /// What happened.
    pub kind: Kind,
    /// The contact concerned (None for an impact).
    pub which: Option<Which>,
    /// The mode entered (None: flight, or the end of the model).
    pub mode: Option<Mode>,
    /// The state there (the values of the mode before the event).
    pub at: Point,
    /// The estimated error of the event time.
    pub t_err: Float,
}

/// How the computed motion ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum End {
    /// At the last requested time (before separation).
    LastTime,
    /// At the first impact after separation.
    Impact,
    /// At lift-off of cylinder 1 (outside the model).
    LiftOff,
    /// Where θ reached the target angle.
    Target,
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
    /// The state at separation, if reached.
    pub separation: Option<Point>,
    /// The first impact after separation (the state just before it).
    pub impact: Option<flight::Impact>,
    /// Largest |E(t) + W(t) − E(0)| over every computed state, relative to
    /// the energy scale m2 g r.
    pub energy_drift: Float,
    /// How it ended.
    pub end: End,
    /// Integrator work over all modes: (accepted steps, evaluations of the
    /// equations of motion).
    pub work_done: (u64, u64),
    /// The state where θ first reached the target angle of [`solve_to_angle`].
    pub target: Option<Point>,
    /// θ and the mode (None: flight) at the requested times, for
    /// [`solve_theta`] (empty otherwise).
    pub thetas: Vec<(Float, Option<Mode>)>,
    /// The integrator that computed each mode, in order ([`Method::Spectral`]
    /// falls back to [`Method::Gbs`] where it declines).
    pub routes: Vec<Method>,
}

/// Checks that the laws fit the model ([`check_laws`]) and that the motion
/// has a finite time scale (not from rest exactly at the top).
///
/// Errors: [`Error::InvalidParameter`] naming the parameter;
/// [`Error::NotPhysical`] for a start from rest at the top.
pub fn validate(model: &Model, fr: &Friction) -> Result<()> {
    check_laws(model, fr)?;
    if model.starts_at_equilibrium() {
        return Err(Error::not_physical(
            "the motion starts from rest exactly at the unstable top: every time is infinite",
        ));
    }
    Ok(())
}

/// Checks that the laws fit the model: friction coefficients belong to a
/// rolling base (`--floor roll`, `--contact roll`), a fixed floor has no
/// floor law, and a spin that sliding friction turns has inertia (k2 > 0
/// under a frictional contact; k1 > 0 where the floor can slide too).
///
/// Errors: [`Error::InvalidParameter`] naming the parameter.
pub fn check_laws(model: &Model, fr: &Friction) -> Result<()> {
    if model.floor() == Floor::Fixed && fr.floor != Law::Roll {
        return Err(Error::invalid(
            "mu_floor",
            &fr.floor,
            "a fixed floor (cylinder 1 held) has no floor contact: drop --mu-floor",
        ));
    }
    if fr.floor.is_coulomb() && model.floor() != Floor::Roll {
        return Err(Error::invalid(
            "mu_floor",
            &fr.floor,
            "friction coefficients apply to --floor roll (slip is mu_floor = 0)",
        ));
    }
    if fr.contact.is_coulomb() && model.contact() != Contact::Roll {
        return Err(Error::invalid(
            "mu_contact",
            &fr.contact,
            "friction coefficients apply to --contact roll (slip is mu_contact = 0)",
        ));
    }
    let p = model.params();
    let kinetic = |l: &Law| l.kinetic().is_some_and(|k| k > 0);
    // cylinder 1's spin is free of the floor only where the floor can slide
    let floor_slides = fr.floor != Law::Roll && model.floor() != Floor::Fixed;
    if p.k1 == 0 && floor_slides && (kinetic(&fr.floor) || kinetic(&fr.contact)) {
        return Err(Error::invalid(
            "k1",
            "0",
            "must be > 0 with finite friction (a spin without inertia cannot slide under friction)",
        ));
    }
    if p.k2 == 0 && kinetic(&fr.contact) {
        return Err(Error::invalid(
            "k2",
            "0",
            "must be > 0 with finite friction (a spin without inertia cannot slide under friction)",
        ));
    }
    Ok(())
}

/// The ideal model equal to `model` with `fr` (a Coulomb contact starts
/// rolling; `inf` is roll, `0` is slip).
pub fn effective_model(model: &Model, fr: &Friction) -> Result<Model> {
    let floor = match (model.floor(), &fr.floor) {
        (Floor::Fixed, _) => Floor::Fixed,
        (f, Law::Roll) => f,
        (_, Law::Slip) => Floor::Slip,
        (_, Law::Coulomb { .. }) => Floor::Roll,
    };
    let contact = match (&fr.contact, model.contact()) {
        (Law::Roll, c) => c,
        (Law::Slip, _) => Contact::Slip,
        (Law::Coulomb { .. }, _) => Contact::Roll,
    };
    Model::new(
        model.params().clone(),
        floor,
        contact,
        model.start().clone(),
    )
}

/// The laws actually in force: the model's ideal contacts, overridden by
/// `fr` where it is not `Roll`.
fn laws(model: &Model, fr: &Friction) -> Friction {
    let floor = match (model.floor(), &fr.floor) {
        (Floor::Slip, Law::Roll) => Law::Slip,
        (_, l) => l.clone(),
    };
    let contact = match (model.contact(), &fr.contact) {
        (Contact::Slip, Law::Roll) => Law::Slip,
        (_, l) => l.clone(),
    };
    Friction { floor, contact }
}

/// The computation's fixed parts at one working precision.
struct Ctx {
    base: StackModel,
    laws: Friction,
    fixed: bool,
    /// Working precision of the integrator.
    wp: u32,
    opts: Opts,
    /// Time scale sqrt(r/g).
    ts: Float,
    /// Energy scale m2 g r.
    escale: Float,
    /// r = r1 + r2.
    base_r: Float,
    /// √tol: the relative size below which a quantity that vanishes in
    /// exact arithmetic (a slip speed at rest, N12 at separation, …) is
    /// taken as 0 — the integration and the event location leave errors
    /// of order tol, far below it, and no genuine value comes that close.
    rel_tiny: Float,
    mu_s: [Option<Float>; 2],
    mu_k: [Float; 2],
}

impl Ctx {
    fn law(&self, w: Which) -> &Law {
        match w {
            Which::Floor => &self.laws.floor,
            Which::Contact => &self.laws.contact,
        }
    }

    /// The constrained system of a mode.
    fn system(&self, mode: Mode) -> Result<System> {
        let wp = self.wp;
        let mut sm = self.base.clone();
        sm.floor = if self.fixed {
            Floor::Fixed
        } else {
            match mode.floor {
                State::Stick => Floor::Roll,
                State::Slip(_) => Floor::Slip,
            }
        };
        sm.contacts[0] = match mode.contact {
            State::Stick => Contact::Roll,
            State::Slip(_) => Contact::Slip,
        };
        let mut sys = System::new(&sm, wp)?;
        for (w, st) in [(Which::Floor, mode.floor), (Which::Contact, mode.contact)] {
            if let State::Slip(sg) = st {
                let mk = &self.mu_k[w as usize];
                if sg != 0 && !mk.is_zero() {
                    let normal = row(&sys, normal_row(w)).ok_or_else(|| {
                        Error::not_physical("internal: a slipping contact without a normal row")
                    })?;
                    sys.slips.push(SlipTerm {
                        at: tangent(w),
                        normal,
                        mu_sigma: Float::with_val(wp, mk * i32::from(sg)),
                    });
                }
            }
        }
        Ok(sys)
    }

    /// The candidate states of a contact.
    fn candidates(&self, w: Which) -> Vec<State> {
        if w == Which::Floor && self.fixed {
            return vec![State::Stick];
        }
        match self.law(w) {
            Law::Roll => vec![State::Stick],
            Law::Slip => vec![State::Slip(0)],
            Law::Coulomb { .. } => vec![State::Stick, State::Slip(1), State::Slip(-1)],
        }
    }
}

fn normal_row(w: Which) -> Row {
    match w {
        Which::Floor => Row::FloorNormal,
        Which::Contact => Row::Normal(0),
    }
}

fn tangent(w: Which) -> Tangent {
    match w {
        Which::Floor => Tangent::Floor,
        Which::Contact => Tangent::Line(0),
    }
}

fn row(sys: &System, r: Row) -> Option<usize> {
    sys.rows.iter().position(|x| *x == r)
}

fn lam(sys: &System, s: &Sample, r: Row) -> Float {
    row(sys, r).map_or_else(|| Float::new(sys.prec), |i| s.lambda[i].clone())
}

/// The tangential force of a contact in a mode (a multiplier while it
/// sticks, −μk σ N while it slips).
fn tangential(ctx: &Ctx, sys: &System, mode: Mode, w: Which, s: &Sample) -> Float {
    let st = match w {
        Which::Floor => mode.floor,
        Which::Contact => mode.contact,
    };
    match st {
        State::Stick => lam(
            sys,
            s,
            match w {
                Which::Floor => Row::FloorFriction,
                Which::Contact => Row::Friction(0),
            },
        ),
        State::Slip(sg) => {
            let n = lam(sys, s, normal_row(w));
            -(n * &ctx.mu_k[w as usize]) * i32::from(sg)
        }
    }
}

fn point(ctx: &Ctx, sys: &mut System, mode: Mode, s: &Sample) -> Point {
    let p = sys.prec;
    let mut state = crate::motion::point::two_state(sys, s);
    // a slipping contact's force is an applied force, not a multiplier
    state.f1 = tangential(ctx, sys, mode, Which::Floor, s);
    state.f21 = tangential(ctx, sys, mode, Which::Contact, s);
    Point {
        state,
        s1: if ctx.fixed {
            Float::new(p)
        } else {
            sys.slip_speed(Tangent::Floor, &s.q, &s.v)
        },
        s12: sys.slip_speed(Tangent::Line(0), &s.q, &s.v),
        work: s.work.clone(),
        energy: sys.energy(&s.q, &s.v),
        mode: Some(mode),
    }
}

/// The events watched in a mode: N12 = 0 (separation), N1 = 0 (lift-off,
/// not on a fixed floor), the cone μs N ∓ F = 0 of each sticking Coulomb
/// contact, the slip speed of each sliding Coulomb contact.
fn events(ctx: &Ctx, sys: &System, mode: Mode) -> Vec<Event> {
    let p = sys.prec;
    let mut ev = Vec::new();
    if let Some(i) = row(sys, Row::Normal(0)) {
        ev.push(Event {
            name: "separation".into(),
            watch: Watch::Multiplier(i),
            terminal: true,
        });
    }
    if !ctx.fixed {
        if let Some(i) = row(sys, Row::FloorNormal) {
            ev.push(Event {
                name: "lift_off".into(),
                watch: Watch::Multiplier(i),
                terminal: true,
            });
        }
    }
    // cylinder 2 reaching the floor while still on cylinder 1: y2 − r2 =
    // r1 + r cos θ − r2 = 0
    ev.push(Event {
        name: "floor_impact".into(),
        watch: Watch::Height {
            th: sy::th(0),
            r: Float::with_val(p, &sys.rho[0] + &sys.rho[1]),
            offset: Float::with_val(p, &sys.rho[0] - &sys.rho[1]),
        },
        terminal: true,
    });
    for (w, st) in [(Which::Floor, mode.floor), (Which::Contact, mode.contact)] {
        if !ctx.law(w).is_coulomb() || (w == Which::Floor && ctx.fixed) {
            continue;
        }
        match st {
            State::Stick => {
                let (Some(n), Some(f), Some(mu)) = (
                    row(sys, normal_row(w)),
                    row(
                        sys,
                        match w {
                            Which::Floor => Row::FloorFriction,
                            Which::Contact => Row::Friction(0),
                        },
                    ),
                    ctx.mu_s[w as usize].clone(),
                ) else {
                    continue;
                };
                for sign in [1i32, -1] {
                    ev.push(Event {
                        name: format!("cone:{}", w.name()),
                        watch: Watch::Lin(vec![
                            (Watch::Multiplier(n), mu.clone()),
                            (Watch::Multiplier(f), Float::with_val(p, -sign)),
                        ]),
                        terminal: true,
                    });
                }
            }
            State::Slip(sg) if sg != 0 => {
                let mut q = vec![Float::new(p); sys.nq()];
                q[sy::rr(0)] = Float::with_val(p, &sys.rho[0] + &sys.rho[1]);
                let terms = sys
                    .tangent_coeffs(tangent(w), &q)
                    .into_iter()
                    .map(|(i, c)| (Watch::Rate(i), c))
                    .collect();
                ev.push(Event {
                    name: format!("slip:{}", w.name()),
                    watch: Watch::Lin(terms),
                    terminal: true,
                });
            }
            State::Slip(_) => {}
        }
    }
    ev
}

/// Why a candidate mode is not consistent (None: it is).
fn inconsistency(ctx: &Ctx, mode: Mode, q: &[Float], v: &[Float]) -> Result<Option<String>> {
    let mut sys = ctx.system(mode)?;
    let p = sys.prec;
    let acc = match sys.accel(q, v) {
        Ok(a) => a,
        Err(_) => return Ok(Some("its constraint system is singular".into())),
    };
    // just after: one Euler step of ε = 2^−(p/3)·T along the mode's flow
    let eps = Float::with_val(p, &ctx.ts) >> (p as i32 / 3);
    let q1: Vec<Float> = q
        .iter()
        .zip(v)
        .map(|(x, d)| Float::with_val(p, x + Float::with_val(p, d * &eps)))
        .collect();
    let v1: Vec<Float> = v
        .iter()
        .zip(&acc.qdd)
        .map(|(x, d)| Float::with_val(p, x + Float::with_val(p, d * &eps)))
        .collect();
    let a1 = match sys.accel(&q1, &v1) {
        Ok(a) => a,
        Err(_) => return Ok(Some("its constraint system is singular".into())),
    };
    // a second step, for slip speeds that leave 0 only at second order (at
    // a slip onset with μs = μk the sliding force equals the sticking one,
    // so ṡ = 0 there and the sign of s̈ decides): s(2ε) ≈ s + 2ε ṡ + ε² s̈
    let v2: Vec<Float> = v1
        .iter()
        .zip(&a1.qdd)
        .map(|(x, d)| Float::with_val(p, x + Float::with_val(p, d * &eps)))
        .collect();
    let s1 = Sample {
        t: Float::new(p),
        q: q1.clone(),
        v: v1.clone(),
        qdd: a1.qdd,
        lambda: a1.lambda,
        work: Float::new(p),
        power: Float::new(p),
    };
    let n12 = lam(&sys, &s1, Row::Normal(0));
    if !n12.is_sign_positive() || n12.is_zero() {
        return Ok(Some(format!("N12 would be {:.3e} <= 0", n12.to_f64())));
    }
    if !ctx.fixed {
        let n1 = lam(&sys, &s1, Row::FloorNormal);
        if !n1.is_sign_positive() || n1.is_zero() {
            return Ok(Some(format!("N1 would be {:.3e} <= 0", n1.to_f64())));
        }
    }
    for (w, st) in [(Which::Floor, mode.floor), (Which::Contact, mode.contact)] {
        if w == Which::Floor && ctx.fixed {
            continue;
        }
        match (st, ctx.law(w)) {
            (State::Stick, Law::Coulomb { .. }) => {
                // a contact can stick only where it does not slide
                let s0 = sys.slip_speed(tangent(w), q, v);
                let vscale = Float::with_val(p, &ctx.base_r / &ctx.ts);
                if Float::with_val(p, s0.abs_ref()) > vscale * &ctx.rel_tiny {
                    return Ok(Some(format!(
                        "the {} slides (slip speed {:.3e}): it cannot stick",
                        w.name(),
                        s0.to_f64()
                    )));
                }
                let n = lam(&sys, &s1, normal_row(w));
                let f = tangential(ctx, &sys, mode, w, &s1);
                let mu = ctx.mu_s[w as usize]
                    .clone()
                    .unwrap_or_else(|| Float::new(p));
                let room = Float::with_val(p, &mu * &n) - Float::with_val(p, f.abs_ref());
                if room.is_sign_negative() {
                    return Ok(Some(format!(
                        "sticking at the {} would need |F|/N = {:.6e} > mu_s",
                        w.name(),
                        (Float::with_val(p, f.abs_ref()) / &n).to_f64()
                    )));
                }
            }
            (State::Slip(sg), Law::Coulomb { .. }) if sg != 0 => {
                let s = sys.slip_speed(tangent(w), &q1, &v2);
                if s.is_zero() || s.is_sign_negative() != (sg < 0) {
                    return Ok(Some(format!(
                        "slipping {} at the {} would need a slip speed of that sign (it would be {:.3e})",
                        if sg > 0 { "forwards" } else { "backwards" },
                        w.name(),
                        s.to_f64()
                    )));
                }
            }
            _ => {}
        }
    }
    Ok(None)
}

/// The relative normal acceleration r̈ of the centres if the contact
/// between the cylinders were open at (q, q̇): cylinder 2 falls freely,
/// cylinder 1 moves under its floor law alone.
fn free_normal_accel(ctx: &Ctx, sys: &System, q: &[Float], v: &[Float]) -> Float {
    let p = sys.prec;
    let th = &q[sy::th(0)];
    let (sn, cs) = th.clone().sin_cos(Float::new(p));
    let r = &q[sy::rr(0)];
    let thd = &v[sy::th(0)];
    let s1 = sys.slip_speed(Tangent::Floor, q, v);
    let snap = Float::with_val(p, ctx.ts.recip_ref()) * &ctx.base_r * &ctx.rel_tiny;
    let sticking = Float::with_val(p, s1.abs_ref()) <= snap;
    let a1x = flight::floor_accel(
        ctx.fixed,
        &ctx.laws.floor,
        &ctx.mu_k[0],
        sys,
        q,
        v,
        sticking,
    );
    // r̈ = n·(a2 − a1) + r θ̇², a2 = (0, −g)
    let mut rdd = Float::with_val(p, thd.square_ref()) * r;
    rdd -= Float::with_val(p, &sys.g * &cs);
    rdd -= Float::with_val(p, &sn * &a1x);
    rdd
}

/// The unique consistent continuation at (q, q̇): every combination of the
/// contacts' states is tested just after the present state.
///
/// Returns the mode, or None when the contact between the cylinders opening
/// is the one consistent continuation.
///
/// Errors: none consistent, or more than one, with the reasons.
fn decide(ctx: &Ctx, q: &[Float], v: &[Float], t: &Float) -> Result<Option<Mode>> {
    let mut ok = Vec::new();
    let mut why = Vec::new();
    for f in ctx.candidates(Which::Floor) {
        for c in ctx.candidates(Which::Contact) {
            let m = Mode {
                floor: f,
                contact: c,
            };
            match inconsistency(ctx, m, q, v)? {
                None => ok.push(m),
                Some(r) => why.push(format!("{}: {r}", m.tag())),
            }
        }
    }
    // the contact opening: consistent when the free motion separates
    let sys = ctx.system(ok.first().copied().unwrap_or(Mode {
        floor: State::Stick,
        contact: State::Stick,
    }))?;
    let rdd = free_normal_accel(ctx, &sys, q, v);
    let opens = rdd.is_sign_positive() && !rdd.is_zero();
    let theta = q[sy::th(0)].to_f64();
    let at = format!("t = {:.12}, theta = {:.12}", t.to_f64(), theta);
    // Coulomb's law: a contact at rest relative to its partner sticks if the
    // force that holds it is within μs N; sliding from rest is the
    // continuation only where sticking is not (this settles the choice
    // between sticking and kinetic sliding when μk < μs)
    if ok.len() > 1 && !opens {
        for w in [Which::Floor, Which::Contact] {
            let st = |m: &Mode| match w {
                Which::Floor => m.floor,
                Which::Contact => m.contact,
            };
            if ok.iter().any(|m| st(m) == State::Stick) {
                ok.retain(|m| st(m) == State::Stick);
            }
        }
    }
    match (ok.len(), opens) {
        (1, false) => Ok(Some(ok[0])),
        (0, true) => Ok(None),
        (0, false) => Err(Error::NotConverged {
            quantity: "mode".into(),
            requested: 0,
            reached: format!("no consistent continuation at {at}"),
            detail: format!(
                "every candidate fails ({}; the contact cannot open: free relative normal \
                 acceleration {:.3e}): a Painlevé-type inconsistency of the rigid-body model",
                why.join("; "),
                rdd.to_f64()
            ),
        }),
        (n, o) => Err(Error::NotConverged {
            quantity: "mode".into(),
            requested: 0,
            reached: format!("{} consistent continuations at {at}", n + usize::from(o)),
            detail: format!(
                "{}{}: the rigid-body model does not decide (Painlevé-type non-uniqueness)",
                ok.iter().map(|m| m.tag()).collect::<Vec<_>>().join(", "),
                if o { ", contact opening" } else { "" }
            ),
        }),
    }
}

/// A requested time after the end of the model (`what` ended it at `end`).
fn after_end(t: &Float, end: &Float, what: &str) -> Error {
    Error::invalid(
        "times",
        t.to_string_radix(10, Some(17)),
        format!(
            "must not be after {what} at t = {} (the model ends there)",
            end.to_string_radix(10, Some(17))
        ),
    )
}

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
    let sm = StackModel::from_model(model);
    let ts = time_scale(&sm, prec);
    let floor = if model.floor() == Floor::Fixed {
        Floor::Fixed
    } else {
        Floor::Roll
    };
    let rolling = Model::new(
        model.params().clone(),
        floor,
        Contact::Roll,
        model.start().clone(),
    );
    let t_roll = rolling
        .and_then(|m| crate::oracle::Oracle::new(&m, 12)?.separation())
        .ok()
        .and_then(|s| s.t_s.map(|t| t.value));
    match t_roll {
        Some(t) => Float::with_val(prec, &t * 4u32) + ts * 50u32,
        None => ts * 200u32,
    }
}

/// The integrator of the modes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Chebyshev spectral integration in the angle ([`crate::integrate::spectral`]),
    /// the default; a mode it declines is integrated by [`Method::Gbs`].
    Spectral,
    /// Gragg–Bulirsch–Stoer extrapolation.
    Gbs,
    /// Gauss–Legendre collocation, the independent second integrator.
    Collocation,
}

/// Solves the motion at working precision `prec` from t = 0, sampling at
/// `times` (ascending, ≥ 0) and going on to the first impact after
/// separation when `to_impact`, else stopping at the last time.
///
/// Errors: invalid laws ([`validate`]); a time after the first impact or
/// after lift-off ([`Error::NotPhysical`]); an undecidable mode change or a
/// numerical failure ([`Error::NotConverged`]); no separation before
/// `horizon` when `to_impact`.
pub fn solve(
    model: &Model,
    fr: &Friction,
    prec: u32,
    times: &[Float],
    to_impact: bool,
    horizon: &Float,
) -> Result<Motion> {
    solve_with(model, fr, prec, times, to_impact, horizon, Method::Spectral)
}

/// [`solve`] with a chosen integrator.
///
/// Errors: see [`solve`].
pub fn solve_with(
    model: &Model,
    fr: &Friction,
    prec: u32,
    times: &[Float],
    to_impact: bool,
    horizon: &Float,
    method: Method,
) -> Result<Motion> {
    solve_full(
        model, fr, prec, times, to_impact, horizon, method, None, false,
    )
}

/// The motion up to the first time θ reaches `theta` (an angle beyond θ0 in
/// the direction of the motion, before separation); `name` is the
/// parameter named in errors; `horizon` bounds the search ([`default_horizon`]).
/// The state there is [`Motion::target`].
///
/// Errors: an angle behind the start, or not reached before the cylinders
/// part ([`Error::InvalidParameter`]); see [`solve`].
pub fn solve_to_angle(
    model: &Model,
    fr: &Friction,
    prec: u32,
    theta: &Exact,
    name: &str,
    horizon: &Float,
) -> Result<Motion> {
    let h = Float::with_val(prec, horizon);
    let th0 = model.start().theta0.clone();
    let dir = model.direction();
    let d = theta.to_float(prec + 64) - th0.to_float(prec + 64);
    if d.cmp0().map(|o| o as i32 * dir.signum()) == Some(-1) {
        return Err(Error::invalid(
            name,
            theta,
            "must lie beyond theta0 in the direction of the motion",
        ));
    }
    solve_full(
        model,
        fr,
        prec,
        &[],
        true,
        &h,
        Method::Spectral,
        Some(Target {
            theta: theta.to_float(prec),
            name,
            text: theta.to_string(),
            at_start: d.is_zero(),
        }),
        false,
    )
}

/// θ alone at `times` (ascending, ≥ 0, before the first impact), into
/// [`Motion::thetas`]: the spectral route skips the other columns (and
/// their KKT solves); `rows` stays empty.
///
/// Errors: see [`solve`].
pub fn solve_theta(
    model: &Model,
    fr: &Friction,
    prec: u32,
    times: &[Float],
    horizon: &Float,
) -> Result<Motion> {
    solve_full(
        model,
        fr,
        prec,
        times,
        false,
        horizon,
        Method::Spectral,
        None,
        true,
    )
}

/// An angle to stop at ([`solve_to_angle`]).
struct Target<'a> {
    theta: Float,
    /// The parameter named in errors, and the angle as given.
    name: &'a str,
    text: String,
    /// The angle is θ0 itself.
    at_start: bool,
}

impl Target<'_> {
    fn not_reached(&self, what: &str, at: &Float) -> Error {
        Error::invalid(
            self.name,
            &self.text,
            format!(
                "must be reached while the contacts hold: {what} at theta = {}",
                at.to_string_radix(10, Some(17))
            ),
        )
    }
}

#[allow(clippy::too_many_arguments)]
fn solve_full(
    model: &Model,
    fr: &Friction,
    prec: u32,
    times: &[Float],
    to_impact: bool,
    horizon: &Float,
    method: Method,
    target: Option<Target>,
    theta_only: bool,
) -> Result<Motion> {
    validate(model, fr)?;
    let eff = effective_model(model, fr)?;
    let laws = laws(model, fr);
    let base = StackModel::from_model(&eff);
    let ts = time_scale(&base, prec);
    let mut opts = Opts::for_prec(prec, TOL_GUARD, &ts);
    opts.hcap = Some(Float::with_val(opts.prec, &ts * 2u32));
    let wp = opts.prec;
    let mut sys0 = System::new(&base, wp)?;
    let (q0, v0) = sys0.initial_state(&base)?;
    let fl = |q: &Rational| Float::with_val(wp, q);
    let pm = eff.params();
    let escale = fl(&pm.m2) * fl(&pm.g) * fl(&pm.r());
    let mu_s = [&laws.floor, &laws.contact].map(|l| match l {
        Law::Coulomb { mu_s, .. } => Some(fl(mu_s)),
        _ => None,
    });
    let mu_k = [&laws.floor, &laws.contact]
        .map(|l| l.kinetic().map_or_else(|| Float::new(wp), |k| fl(&k)));
    let rel_tiny = Float::with_val(wp, opts.tol.sqrt_ref());
    let ctx = Ctx {
        base,
        laws,
        fixed: eff.floor() == Floor::Fixed,
        wp,
        opts,
        ts: Float::with_val(wp, &ts),
        escale,
        base_r: fl(&pm.r()),
        rel_tiny,
        mu_s,
        mu_k,
    };
    let e0 = sys0.energy(&q0, &v0);
    let zero = Float::new(wp);
    let mut mode = decide(&ctx, &q0, &v0, &zero)?.ok_or_else(|| {
        Error::not_physical("the cylinders part at once: N12 <= 0 at the start in every mode")
    })?;
    let start_mode = mode;
    let mut q = q0;
    let mut v = v0;
    let mut t = Float::new(wp);
    let mut work = Float::new(wp);
    let mut out = Motion {
        start_mode,
        events: Vec::new(),
        rows: Vec::new(),
        separation: None,
        impact: None,
        energy_drift: Float::new(wp),
        end: End::LastTime,
        work_done: (0, 0),
        target: None,
        routes: Vec::new(),
        thetas: Vec::new(),
    };
    let mut next = 0usize;
    let t_last = times.last().cloned();
    let t_end = if to_impact {
        Float::with_val(wp, horizon)
    } else {
        t_last
            .clone()
            .map_or_else(|| Float::new(wp), |x| Float::with_val(wp, x))
    };
    let snap = Float::with_val(wp, &ctx.escale / &ctx.ts) * &ctx.rel_tiny;
    let note_drift = |pt: &Point, drift: &mut Float| {
        let d = Float::with_val(wp, &pt.energy + &pt.work) - &e0;
        let d = d.abs() / &ctx.escale;
        if d > *drift {
            *drift = d;
        }
    };
    for _ in 0..MAX_MODES {
        let mut sys = ctx.system(mode)?;
        let mut evs = events(&ctx, &sys, mode);
        if let Some(tg) = &target {
            if tg.at_start {
                let acc = sys.accel(&q, &v)?;
                let smp = Sample {
                    t: t.clone(),
                    q: q.clone(),
                    v: v.clone(),
                    qdd: acc.qdd,
                    lambda: acc.lambda,
                    work: work.clone(),
                    power: Float::new(wp),
                };
                out.target = Some(point(&ctx, &mut sys, mode, &smp));
                out.end = End::Target;
                return Ok(out);
            }
            evs.push(Event {
                name: "target".into(),
                watch: Watch::Reach {
                    i: sy::th(0),
                    value: Float::with_val(wp, &tg.theta),
                },
                terminal: true,
            });
        }
        let start = Start {
            t: t.clone(),
            q: &q,
            v: &v,
            work: work.clone(),
            snap: snap.clone(),
        };
        let spectral = match method {
            Method::Spectral => crate::integrate::spectral::run(
                &mut sys,
                &start,
                &times[next..],
                &t_end,
                &evs,
                &crate::integrate::spectral::Settings {
                    tol: ctx.opts.tol.clone(),
                    full: !theta_only,
                    ts: ctx.ts.clone(),
                    r: ctx.base_r.clone(),
                    escale: ctx.escale.clone(),
                },
            )?,
            _ => None,
        };
        out.routes.push(match (&spectral, method) {
            (Some(_), _) => Method::Spectral,
            (None, Method::Collocation) => Method::Collocation,
            (None, _) => Method::Gbs,
        });
        let run = match (spectral, method) {
            (Some(run), _) => run,
            (None, Method::Gbs | Method::Spectral) => {
                solve::run_from(&mut sys, &start, &times[next..], &t_end, &evs, &ctx.opts)?
            }
            (None, Method::Collocation) => {
                let stages = (wp as usize / 12).clamp(4, 24);
                let mut co = crate::integrate::collocation::Collocation::new(
                    wp,
                    ctx.opts.tol.clone(),
                    ctx.opts.h0.clone(),
                    stages,
                );
                solve::run_with(
                    &mut sys,
                    &start,
                    &times[next..],
                    &t_end,
                    &evs,
                    &ctx.opts,
                    &mut co,
                )?
            }
        };
        out.work_done.0 += run.stats.steps;
        out.work_done.1 += run.stats.evals;
        for s in &run.checkpoints {
            let pt = point(&ctx, &mut sys, mode, s);
            note_drift(&pt, &mut out.energy_drift);
        }
        let full = !theta_only || out.routes.last() != Some(&Method::Spectral);
        for s in &run.outputs {
            if theta_only {
                out.thetas.push((s.q[sy::th(0)].clone(), Some(mode)));
            }
            if !full {
                continue;
            }
            let pt = point(&ctx, &mut sys, mode, s);
            note_drift(&pt, &mut out.energy_drift);
            if !theta_only {
                out.rows.push(pt);
            }
        }
        next += run.outputs.len();
        if !run.stopped {
            let end_pt = point(&ctx, &mut sys, mode, &run.last);
            note_drift(&end_pt, &mut out.energy_drift);
            if to_impact {
                return Err(Error::NotConverged {
                    quantity: "separation".into(),
                    requested: 0,
                    reached: format!(
                        "no separation before t = {:.6} (the horizon searched)",
                        t_end.to_f64()
                    ),
                    detail: "the horizon is four times the rolling model's separation time".into(),
                });
            }
            out.end = End::LastTime;
            return Ok(out);
        }
        let hit = run
            .hits
            .last()
            .ok_or_else(|| Error::not_physical("internal: a stop without an event"))?;
        let at = point(&ctx, &mut sys, mode, &hit.at);
        note_drift(&at, &mut out.energy_drift);
        let name = evs[hit.event].name.clone();
        if name == "target" {
            out.target = Some(at);
            out.end = End::Target;
            return Ok(out);
        }
        if let Some(tg) = &target {
            let what = match name.as_str() {
                "separation" => Some("the cylinders part"),
                "lift_off" => Some("cylinder 1 lifts off"),
                "floor_impact" => Some("cylinder 2 lands on the floor"),
                _ => None,
            };
            if let Some(what) = what {
                return Err(tg.not_reached(what, &at.theta));
            }
        }
        if name == "floor_impact" {
            // cylinder 2 lands on the floor before the cylinders part
            out.events.push(EventRec {
                kind: Kind::Impact,
                which: None,
                mode: None,
                at: at.clone(),
                t_err: hit.t_err.clone(),
            });
            if next < times.len() {
                return Err(after_end(
                    &times[next],
                    &at.t,
                    "the first impact (cylinder 2 reaches the floor while still on cylinder 1)",
                ));
            }
            out.impact = Some(flight::Impact::in_contact(&sys, &hit.at, &at));
            out.end = End::Impact;
            return Ok(out);
        }
        // a change of friction state, or the contact opening
        let next_mode = if name == "separation" || name == "lift_off" {
            None
        } else {
            decide(&ctx, &hit.at.q, &hit.at.v, &hit.at.t)?
        };
        if next_mode.is_none() {
            if let Some(tg) = &target {
                return Err(tg.not_reached("the cylinders part", &at.theta));
            }
            let lift = name == "lift_off";
            out.events.push(EventRec {
                kind: if lift {
                    Kind::LiftOff
                } else {
                    Kind::Separation
                },
                which: Some(if lift { Which::Floor } else { Which::Contact }),
                mode: None,
                at: at.clone(),
                t_err: hit.t_err.clone(),
            });
            if lift {
                if next < times.len() {
                    return Err(after_end(&times[next], &at.t, "the lift-off of cylinder 1"));
                }
                out.end = End::LiftOff;
                return Ok(out);
            }
            let fli = flight::Flight::new(&ctx, &sys, mode, &hit.at, &at)?;
            for e in fli.events() {
                out.events.push(e);
            }
            for tt in &times[next..] {
                if *tt > fli.impact.t {
                    return Err(after_end(tt, &fli.impact.t, "the first impact"));
                }
                let pt = fli.point(tt);
                note_drift(&pt, &mut out.energy_drift);
                if theta_only {
                    out.thetas.push((pt.theta.clone(), None));
                } else {
                    out.rows.push(pt);
                }
            }
            let imp_pt = fli.point(&fli.impact.t);
            note_drift(&imp_pt, &mut out.energy_drift);
            out.events.push(EventRec {
                kind: Kind::Impact,
                which: None,
                mode: None,
                at: imp_pt,
                t_err: Float::new(wp),
            });
            out.separation = Some(at);
            out.impact = Some(fli.impact);
            out.end = End::Impact;
            return Ok(out);
        }
        let new = next_mode.ok_or_else(|| Error::not_physical("internal: no mode"))?;
        if new == mode {
            return Err(Error::NotConverged {
                quantity: "mode".into(),
                requested: 0,
                reached: format!(
                    "event {name} at t = {:.12} leaves the mode {} unchanged",
                    at.t.to_f64(),
                    mode.tag()
                ),
                detail: "a grazing event the rigid-body model cannot resolve at this precision"
                    .into(),
            });
        }
        for (w, old_s, new_s) in [
            (Which::Floor, mode.floor, new.floor),
            (Which::Contact, mode.contact, new.contact),
        ] {
            if old_s == new_s {
                continue;
            }
            let kind = match (old_s, new_s) {
                (State::Stick, _) => Kind::SlipOnset,
                (State::Slip(_), State::Stick) => Kind::Stick,
                (State::Slip(_), State::Slip(_)) => Kind::SlipReversal,
            };
            out.events.push(EventRec {
                kind,
                which: Some(w),
                mode: Some(new),
                at: at.clone(),
                t_err: hit.t_err.clone(),
            });
        }
        t = hit.at.t.clone();
        q = hit.at.q.clone();
        v = hit.at.v.clone();
        work = hit.at.work.clone();
        // a contact that starts to stick has the rolling constraint's
        // constant of its new start (positions drift is measured from it)
        mode = new;
    }
    Err(Error::NotConverged {
        quantity: "mode".into(),
        requested: 0,
        reached: format!("more than {MAX_MODES} mode changes"),
        detail: format!(
            "stopped at t = {:.12} (a Zeno cascade of stick-slip events?)",
            t.to_f64()
        ),
    })
}
