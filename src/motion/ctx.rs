//! The fixed parts of one motion at one working precision: the model's
//! laws, the constrained system of each mode, the forces and columns of a
//! state.

use super::mode::{Mode, Phase, State};
use super::point::{col, two_state, Point};
use crate::error::{Error, Result};
use crate::integrate::solve::{Opts, Sample};
use crate::integrate::{time_scale, TOL_GUARD};
use crate::mechanics::system::{Row, SlipTerm, StackModel, System, Tangent};
use crate::model::{Contact, Floor, Law, Model, Which};
use rug::Float;

/// The computation's fixed parts at one working precision.
pub struct Ctx {
    /// The model.
    pub model: Model,
    /// The stack model of the conservative kinematics (every Coulomb
    /// contact rolling); a mode changes its floor and contact.
    pub base: StackModel,
    /// Cylinder 1 is held by the floor.
    pub held: bool,
    /// The ladder's precision (the integrators' tolerance is 2^−(p−8)).
    pub p: u32,
    /// Working precision of the integrators.
    pub wp: u32,
    /// Integrator settings.
    pub opts: Opts,
    /// Time scale sqrt(r/g).
    pub ts: Float,
    /// Energy scale m2 g r.
    pub escale: Float,
    /// r = r1 + r2.
    pub base_r: Float,
    /// √tol: the relative size below which a quantity that vanishes in
    /// exact arithmetic (a slip speed at rest, N12 at separation, …) is
    /// taken as 0 — the integration and the event location leave errors
    /// of order tol, far below it, and no genuine value comes that close.
    pub rel_tiny: Float,
    /// μs of each contact (floor, contact) where it has one.
    pub mu_s: [Option<Float>; 2],
    /// μk of each contact (0 where it never slides).
    pub mu_k: [Float; 2],
}

/// The constraint row of a contact's normal force.
pub fn normal_row(w: Which) -> Row {
    match w {
        Which::Floor => Row::FloorNormal,
        Which::Contact => Row::Normal(0),
    }
}

/// The constraint row of a sticking contact's tangential force.
pub fn friction_row(w: Which) -> Row {
    match w {
        Which::Floor => Row::FloorFriction,
        Which::Contact => Row::Friction(0),
    }
}

/// The tangent direction of a contact.
pub fn tangent(w: Which) -> Tangent {
    match w {
        Which::Floor => Tangent::Floor,
        Which::Contact => Tangent::Line(0),
    }
}

/// The index of a constraint row in a system.
pub fn row(sys: &System, r: Row) -> Option<usize> {
    sys.rows.iter().position(|x| *x == r)
}

/// The multiplier of a row at a sample (0 where the system has no such row).
pub fn lam(sys: &System, s: &Sample, r: Row) -> Float {
    row(sys, r).map_or_else(|| Float::new(sys.prec), |i| s.lambda[i].clone())
}

impl Ctx {
    /// The thresholds below which each watched function counts as 0 at a
    /// start: √tol of its natural scale
    /// ([`crate::integrate::solve::Watch::scale`]), in the order of `events`.
    ///
    /// An angle to reach (the target, a `--part-at` angle) is not snapped:
    /// whether it lies at the phase's start was decided before the phase
    /// (to the last event's margin); one √tol ahead of the start (10^-18
    /// rad at 30 digits, a slip onset just passed) was taken for 0 there,
    /// the watch never armed, and the phase ran on to the next event,
    /// whose time was answered as the target's.
    pub fn snaps(&self, events: &[crate::integrate::solve::Event]) -> Vec<Float> {
        let mut out = self.scaled(events, &self.rel_tiny);
        for (s, e) in out.iter_mut().zip(events) {
            if matches!(e.watch, crate::integrate::solve::Watch::Reach { .. }) {
                *s = Float::new(self.wp);
            }
        }
        out
    }

    /// The thresholds below which each watched function is 0 to the
    /// integration's accuracy (at a target angle): 2^16 tolerances of its
    /// natural scale. Not the snap's √tol: for a force that is of the upper
    /// cylinder's weight, and N12 is of m1 g under a cylinder 10^14 times
    /// heavier — an angle short of the parting was taken for it.
    pub fn accuracies(&self, events: &[crate::integrate::solve::Event]) -> Vec<Float> {
        let tol = Float::with_val(self.wp, &self.opts.tol << 16u32);
        self.scaled(events, &tol)
    }

    /// Each watched function's natural scale times `factor`.
    fn scaled(&self, events: &[crate::integrate::solve::Event], factor: &Float) -> Vec<Float> {
        let units = self.base.units(self.wp);
        events
            .iter()
            .map(|e| e.watch.scale(&units) * factor)
            .collect()
    }

    /// The fixed parts of the motion of `model` at working precision `prec`.
    ///
    /// Errors: a model the constrained system cannot represent.
    pub fn new(model: &Model, prec: u32) -> Result<Ctx> {
        let base = StackModel::from_model(&model.sticking());
        let ts = time_scale(&base, prec);
        let mut opts = Opts::for_prec(prec, TOL_GUARD, &ts);
        opts.hcap = Some(Float::with_val(opts.prec, &ts * 2u32));
        let wp = opts.prec;
        let fl = |q: &rug::Rational| Float::with_val(wp, q);
        let pm = model.params();
        let escale = fl(&pm.m2) * fl(&pm.g) * fl(&pm.r());
        let mu_s = [model.floor(), model.contact()].map(|l| l.static_coef().map(|m| fl(&m)));
        let mu_k = [model.floor(), model.contact()]
            .map(|l| l.kinetic().map_or_else(|| Float::new(wp), |k| fl(&k)));
        let rel_tiny = Float::with_val(wp, opts.tol.sqrt_ref());
        Ok(Ctx {
            model: model.clone(),
            base,
            held: *model.floor() == Law::Held,
            p: prec,
            wp,
            opts,
            ts: Float::with_val(wp, &ts),
            escale,
            base_r: fl(&pm.r()),
            rel_tiny,
            mu_s,
            mu_k,
        })
    }

    /// The law of a contact.
    pub fn law(&self, w: Which) -> &Law {
        self.model.law(w)
    }

    /// The constrained system of a mode.
    ///
    /// Errors: a singular or unrepresentable system.
    pub fn system(&self, mode: Mode) -> Result<System> {
        let wp = self.wp;
        let mut sm = self.base.clone();
        sm.floor = match mode.floor {
            State::Held => Floor::Fixed,
            State::Stick => Floor::Roll,
            State::Slip(_) => Floor::Slip,
        };
        sm.contacts[0] = match mode.contact {
            State::Slip(_) => Contact::Slip,
            State::Stick | State::Held => Contact::Roll,
        };
        let mut sys = System::new(&sm, wp)?;
        for w in [Which::Floor, Which::Contact] {
            if let State::Slip(sg) = mode.of(w) {
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

    /// The candidate states of a contact under its law.
    pub fn candidates(&self, w: Which) -> Vec<State> {
        match self.law(w) {
            Law::Held => vec![State::Held],
            Law::Rolling => vec![State::Stick],
            Law::Frictionless => vec![State::Slip(0)],
            Law::Coulomb { .. } => vec![State::Stick, State::Slip(1), State::Slip(-1)],
        }
    }

    /// The tangential force of a contact in a mode (a multiplier while it
    /// sticks, −μk σ N while it slips).
    pub fn tangential(&self, sys: &System, mode: Mode, w: Which, s: &Sample) -> Float {
        match mode.of(w) {
            State::Stick | State::Held => lam(sys, s, friction_row(w)),
            State::Slip(sg) => {
                let n = lam(sys, s, normal_row(w));
                -(n * &self.mu_k[w as usize]) * i32::from(sg)
            }
        }
    }

    /// Every column at a sample of a mode; `conservative`: no work has been
    /// dissipated so far (the `work` column is exactly 0).
    pub fn point(&self, sys: &mut System, mode: Mode, s: &Sample, conservative: bool) -> Point {
        let p = sys.prec;
        // the energy first: its mass matrix leaves sin θ and cos θ in the
        // workspace, where the columns find them (put back from the sample
        // where it kept them)
        sys.prime_trig(&s.q, &s.trig);
        let energy = match &s.energy {
            Some(e) if e.prec() == p => e.clone(),
            _ => sys.energy(&s.q, &s.v),
        };
        let mut state = two_state(sys, s);
        // a slipping contact's force is an applied force, not a multiplier
        state.f1 = self.tangential(sys, mode, Which::Floor, s);
        state.f21 = self.tangential(sys, mode, Which::Contact, s);
        let mut zero = 0u32;
        let s1 = match mode.floor {
            State::Stick | State::Held => {
                zero |= 1 << col!("s1");
                Float::new(p)
            }
            State::Slip(_) => sys.slip_speed(Tangent::Floor, &s.q, &s.v),
        };
        let s12 = match mode.contact {
            State::Stick | State::Held => {
                zero |= 1 << col!("s12");
                Float::new(p)
            }
            State::Slip(_) => sys.slip_speed(Tangent::Line(0), &s.q, &s.v),
        };
        if mode.floor == State::Slip(0) {
            zero |= 1 << col!("F1");
        }
        if mode.contact == State::Slip(0) {
            zero |= 1 << col!("F21");
        }
        if conservative {
            zero |= 1 << col!("work");
        }
        Point {
            state,
            s1,
            s12,
            work: s.work.clone(),
            energy,
            phase: Phase::Contact(mode),
            err: None,
            exact_zero: zero,
            diff_weight: 1,
        }
    }

    /// The horizontal acceleration of cylinder 1 alone on its floor at
    /// (q, q̇) (`sticking`: its floor contact does not slide): 0 unless it
    /// slides on a Coulomb floor, then −μk g sgn s1.
    pub fn floor_accel(&self, sys: &System, q: &[Float], v: &[Float], sticking: bool) -> Float {
        let p = sys.prec;
        if self.held || sticking || !self.law(Which::Floor).is_coulomb() {
            return Float::new(p);
        }
        let s1 = sys.slip_speed(Tangent::Floor, q, v);
        if s1.is_zero() {
            return Float::new(p);
        }
        let a = Float::with_val(p, &self.mu_k[0] * &sys.g);
        if s1.is_sign_positive() {
            -a
        } else {
            a
        }
    }

    /// The floor acceleration of cylinder 1 alone in a mode (its floor
    /// state fixes the sliding direction): the ẍ1_free of the free relative
    /// normal acceleration.
    pub fn floor_accel_of(&self, mode: Mode) -> Float {
        let p = self.wp;
        match (mode.floor, self.law(Which::Floor).is_coulomb()) {
            (State::Slip(sg), true) if sg != 0 => {
                let g = Float::with_val(p, &self.model.params().g);
                -(Float::with_val(p, &self.mu_k[0] * g) * i32::from(sg))
            }
            _ => Float::new(p),
        }
    }
}
