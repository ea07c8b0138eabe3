//! The model: parameters, contact laws and the start, all exact.
//!
//! A [`Model`] is what a user asks about: the parameters, one [`Law`] per
//! contact (rolling, frictionless, Coulomb, or a held lower cylinder) and
//! the start. An [`Ideal`] is the same system with a fixed constraint at
//! each contact ([`Floor`], [`Contact`]): the model of a *conservative
//! phase*, in which every contact rolls, sticks or is frictionless, so that
//! the energy integral holds and the motion reduces to one degree of
//! freedom. Both are validated on construction; every other part of the
//! crate may assume their invariants (positive masses, radii and g,
//! non-negative inertia factors, a start inside the supported range).

pub mod input;
pub mod law;

pub use law::{Law, Which};

use crate::error::{Error, Result};
use crate::exact::Exact;
use rug::Rational;
use serde::Serialize;
use std::fmt;
use std::str::FromStr;

/// The constraint at the floor in a conservative phase: how cylinder 1
/// meets the floor while its contact does not change state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Floor {
    /// Rolls without slipping: x1 = r1 φ1 (paper eq. 1).
    Roll,
    /// Frictionless floor: x1 and φ1 independent (paper secs. 3.1, 3.2).
    Slip,
    /// Cylinder 1 held still (paper footnote 8).
    Fixed,
}

/// The constraint between the cylinders in a conservative phase.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Contact {
    /// Rolls without slipping: r2 φ2 = r1(φ1 − θ) (paper eq. 2).
    Roll,
    /// Frictionless contact: cylinder 2 keeps its spin (paper secs. 3.1, 3.3).
    Slip,
}

impl FromStr for Floor {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        // keywords, like numbers, ignore surrounding whitespace and case
        match s.trim().to_ascii_lowercase().as_str() {
            "roll" => Ok(Floor::Roll),
            "slip" => Ok(Floor::Slip),
            "fixed" => Ok(Floor::Fixed),
            _ => Err(Error::invalid("floor", s, "expected roll, slip or fixed")),
        }
    }
}

impl FromStr for Contact {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        match s.trim().to_ascii_lowercase().as_str() {
            "roll" => Ok(Contact::Roll),
            "slip" => Ok(Contact::Slip),
            _ => Err(Error::invalid("contact", s, "expected roll or slip")),
        }
    }
}

impl fmt::Display for Floor {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Floor::Roll => "roll",
            Floor::Slip => "slip",
            Floor::Fixed => "fixed",
        })
    }
}

impl fmt::Display for Contact {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Contact::Roll => "roll",
            Contact::Slip => "slip",
        })
    }
}

/// Physical parameters, exact rationals. Units are any consistent set.
#[derive(Debug, Clone, PartialEq)]
pub struct Params {
    /// Mass of the lower cylinder.
    pub m1: Rational,
    /// Mass of the upper cylinder.
    pub m2: Rational,
    /// Rolling radius of the lower cylinder.
    pub r1: Rational,
    /// Rolling radius of the upper cylinder.
    pub r2: Rational,
    /// I1 = k1 m1 r1².
    pub k1: Rational,
    /// I2 = k2 m2 r2².
    pub k2: Rational,
    /// Gravitational acceleration.
    pub g: Rational,
}

impl Params {
    /// Identical solid cylinders, m = r = g = 1, k = 1/2 (the built-in default).
    pub fn identical_solid() -> Self {
        let one = Rational::from(1);
        let half = Rational::from((1, 2));
        Params {
            m1: one.clone(),
            m2: one.clone(),
            r1: one.clone(),
            r2: one.clone(),
            k1: half.clone(),
            k2: half,
            g: one,
        }
    }

    /// Distance between the axes, r = r1 + r2.
    pub fn r(&self) -> Rational {
        Rational::from(&self.r1 + &self.r2)
    }

    /// The angle of the line of centres at which cylinder 2, still on
    /// cylinder 1, touches the floor: y2 = r1 + r cos θ = r2, θ = acos((r2
    /// − r1)/r), at `prec` bits. In [0, π]; below π/2 only for r2 > r1 (the
    /// start must lie below it, the motion may end there).
    pub fn landing_angle(&self, prec: u32) -> rug::Float {
        let c = rug::Float::with_val(prec, Rational::from(&self.r2 - &self.r1) / self.r());
        rug::Float::with_val(prec, c.acos_ref())
    }
}

impl Model {
    /// Spins that nothing ever turns, from ω0 = 0, so 0 throughout by
    /// structure: (cylinder 1's φ̇1 — held, or both contacts frictionless;
    /// cylinder 2's ψ̇2 — a frictionless contact, whose force passes through
    /// its centre). The flight's rows and the impact mark them exact zeros.
    pub fn spins_never_turned(&self) -> (bool, bool) {
        let w0 = self.start.omega0 == 0;
        let free_c = self.contact == Law::Frictionless;
        let held = self.floor == Law::Held;
        let phi1 = held || (w0 && free_c && self.floor == Law::Frictionless);
        (phi1, w0 && free_c)
    }
}

/// The note on spins that nothing determines, where the model has one: a
/// spin without inertia on which no force acts (k2 = 0 under a
/// frictionless contact; k1 = 0 on a frictionless floor under one; k1 = k2
/// = 0 on a frictionless floor under a rolling contact, their common
/// rolling) turns at any rate; the program keeps its reference rate (ω0's
/// common rolling), a convention, not a consequence of the mechanics (the
/// limits k → 0 taken in different orders give other rates).
pub fn free_spin_note(model: &Model) -> Option<String> {
    let pr = model.params();
    let (ff, cf) = (
        *model.floor() == Law::Frictionless,
        *model.contact() == Law::Frictionless,
    );
    let which = if pr.k1 == 0 && pr.k2 == 0 && ff && *model.contact() == Law::Rolling {
        "the common rolling of both cylinders (k1 = k2 = 0 on a frictionless floor under a \
         rolling contact)"
    } else if pr.k1 == 0 && pr.k2 == 0 && ff && cf {
        "each cylinder's spin (k1 = k2 = 0, both contacts frictionless)"
    } else if pr.k2 == 0 && cf {
        "cylinder 2's spin (k2 = 0 under a frictionless contact)"
    } else if pr.k1 == 0 && ff && cf {
        "cylinder 1's spin (k1 = 0 on a frictionless floor under a frictionless contact)"
    } else {
        return None;
    };
    Some(format!(
        "{which} has no inertia and nothing acts on it: the mechanics leaves its rate free; \
         phi1_dot, phi2_dot and their angles take the convention that it keeps its reference \
         rate (omega0's common rolling) - the limits k -> 0 taken in other orders give other \
         rates; every other column is determined"
    ))
}

/// Initial conditions. Positions start at x1 = φ1 = 0.
#[derive(Debug, Clone, PartialEq)]
pub struct Start {
    /// θ0: line of centres, clockwise from vertical, radians, |θ0| < π/2.
    pub theta0: Exact,
    /// θ̇0, radians per unit time; must not point towards the top (θ0·θ̇0 ≥ 0).
    pub thetadot0: Rational,
    /// ω0: the common rolling rate of the conserved momenta — the value φ̇1
    /// takes whenever θ̇ = 0 (paper eq. 17). Zero for a start from rest.
    pub omega0: Rational,
}

impl Start {
    /// At rest at θ0.
    pub fn rest(theta0: Exact) -> Self {
        Start {
            theta0,
            thetadot0: Rational::new(),
            omega0: Rational::new(),
        }
    }
}

/// The six contact models, in the paper's order: §2, §3.1, §3.2, §3.3,
/// footnote 8, and the fixed lower cylinder with a frictionless contact.
pub const VARIANTS: [(Floor, Contact); 6] = [
    (Floor::Roll, Contact::Roll),
    (Floor::Slip, Contact::Slip),
    (Floor::Slip, Contact::Roll),
    (Floor::Roll, Contact::Slip),
    (Floor::Fixed, Contact::Roll),
    (Floor::Fixed, Contact::Slip),
];

/// A validated model of a conservative phase: parameters, the constraint
/// at each contact, and the start (the paper's contact models).
#[derive(Debug, Clone, PartialEq)]
pub struct Ideal {
    params: Params,
    floor: Floor,
    contact: Contact,
    start: Start,
}

/// Upper bound on |θ0|: the start must have the upper centre above the lower one.
const THETA0_RANGE: &str = "must satisfy -pi/2 < theta0 < pi/2";

/// The checks every model shares: m1, m2, r1, r2, g > 0; k1, k2 ≥ 0;
/// |θ0| < π/2; θ0·θ̇0 ≥ 0; ω0 = 0 when cylinder 1 is `held`.
fn validate(params: &Params, start: &Start, held: bool) -> Result<()> {
    for (name, v) in [
        ("m1", &params.m1),
        ("m2", &params.m2),
        ("r1", &params.r1),
        ("r2", &params.r2),
        ("g", &params.g),
    ] {
        if *v <= 0 {
            return Err(Error::invalid(
                name,
                crate::exact::rational_text(v),
                "must be > 0",
            ));
        }
    }
    for (name, v) in [("k1", &params.k1), ("k2", &params.k2)] {
        if *v < 0 {
            return Err(Error::invalid(
                name,
                crate::exact::rational_text(v),
                "must be >= 0 (k > 1 is a bobbin)",
            ));
        }
    }
    // |θ0| < π/2: compare with π/2 at a safe precision (θ0 is exact).
    let th = start.theta0.to_float(256);
    let half_pi = rug::Float::with_val(256, rug::float::Constant::Pi) / 2u32;
    if th.clone().abs() >= half_pi
        || start.theta0.coef.clone().abs() >= Rational::from((1, 2)) && start.theta0.times_pi
    {
        return Err(Error::invalid("theta0", &start.theta0, THETA0_RANGE));
    }
    // cylinder 2 starts above the floor: its lowest point, at height
    // r1 + (r1 + r2) cos θ0 − r2, must be above 0 (a start inside the floor,
    // or touching it, is outside the model: three bodies in contact)
    let rsum = params.r();
    let lowest = rug::Float::with_val(256, th.cos_ref()) * rug::Float::with_val(256, &rsum)
        + rug::Float::with_val(256, &params.r1)
        - rug::Float::with_val(256, &params.r2);
    let floor_tol = rug::Float::with_val(256, &rsum) >> 200;
    if lowest <= floor_tol {
        let bound = rug::Float::with_val(64, params.landing_angle(256));
        return Err(Error::invalid(
            "theta0",
            &start.theta0,
            format!(
                "must leave cylinder 2 above the floor at the start: r1 + (r1 + r2) cos theta0 > r2, \
                 i.e. |theta0| < acos((r2 - r1)/(r1 + r2)) = {} for these radii",
                crate::numeric::decimal::to_sig(&bound, 6)
            ),
        ));
    }
    if start.theta0.signum() * (start.thetadot0.cmp0() as i32) < 0 {
        return Err(Error::invalid(
            "thetadot0",
            crate::exact::rational_text(&start.thetadot0),
            "must not point towards the top: theta0*thetadot0 >= 0 \
         (a start that climbs back over the top is not supported)",
        ));
    }
    if held && start.omega0 != 0 {
        return Err(Error::invalid(
            "omega0",
            crate::exact::rational_text(&start.omega0),
            "must be 0 when the floor is fixed (cylinder 1 cannot roll)",
        ));
    }
    Ok(())
}

impl Ideal {
    /// Validates and builds a model.
    ///
    /// Errors: [`Error::InvalidParameter`] naming the parameter and its range
    /// (m1, m2, r1, r2, g > 0; k1, k2 ≥ 0; |θ0| < π/2; θ0·θ̇0 ≥ 0; ω0 = 0 when
    /// the floor is `fixed`).
    pub fn new(params: Params, floor: Floor, contact: Contact, start: Start) -> Result<Self> {
        validate(&params, &start, floor == Floor::Fixed)?;
        Ok(Ideal {
            params,
            floor,
            contact,
            start,
        })
    }

    /// The paper's main case: identical solid cylinders, both contacts rolling,
    /// from rest at θ0.
    pub fn paper_default(theta0: Exact) -> Self {
        Ideal::new(
            Params::identical_solid(),
            Floor::Roll,
            Contact::Roll,
            Start::rest(theta0),
        )
        .expect("the default model is valid")
    }

    /// Parameters.
    pub fn params(&self) -> &Params {
        &self.params
    }
    /// Floor contact model.
    pub fn floor(&self) -> Floor {
        self.floor
    }
    /// Contact model between the cylinders.
    pub fn contact(&self) -> Contact {
        self.contact
    }
    /// Initial conditions.
    pub fn start(&self) -> &Start {
        &self.start
    }

    /// Whether the motion starts from rest exactly at the top (θ0 = θ̇0 = 0):
    /// the paper's limiting case, where every time is infinite.
    pub fn starts_at_equilibrium(&self) -> bool {
        self.start.theta0.is_zero() && self.start.thetadot0 == 0
    }

    /// The sign of the motion: +1 if θ grows, −1 if it falls to the left.
    /// A start at rest at θ0 = 0 is taken as the limit θ0 → 0+.
    pub fn direction(&self) -> i32 {
        match self.start.theta0.signum() {
            0 => {
                if self.start.thetadot0 < 0 {
                    -1
                } else {
                    1
                }
            }
            s => s,
        }
    }

    /// The mirror image (x → −x): θ0, θ̇0, ω0 change sign. The motion of the
    /// mirror is the mirror of the motion, so the oracle computes with θ growing.
    pub fn mirrored(&self) -> Self {
        Ideal {
            params: self.params.clone(),
            floor: self.floor,
            contact: self.contact,
            start: Start {
                theta0: self.start.theta0.neg(),
                thetadot0: Rational::from(-&self.start.thetadot0),
                omega0: Rational::from(-&self.start.omega0),
            },
        }
    }

    /// A one-line description for messages (every value exact and short, a
    /// very long one shortened: [`crate::error::shorten`]).
    pub fn describe(&self) -> String {
        let t = |q: &Rational| crate::error::shorten(&crate::exact::rational_text(q));
        let p = &self.params;
        format!(
            "floor={} contact={} m1={} m2={} r1={} r2={} k1={} k2={} g={} theta0={} thetadot0={} omega0={}",
            self.floor,
            self.contact,
            t(&p.m1),
            t(&p.m2),
            t(&p.r1),
            t(&p.r2),
            t(&p.k1),
            t(&p.k2),
            t(&p.g),
            crate::error::shorten(&self.start.theta0.canonical()),
            t(&self.start.thetadot0),
            t(&self.start.omega0)
        )
    }

    /// The model as (key, exact text) pairs, in a stable order, for records.
    pub fn echo(&self) -> Vec<(&'static str, String)> {
        use crate::exact::rational_text as t;
        let p = &self.params;
        vec![
            ("floor", self.floor.to_string()),
            ("contact", self.contact.to_string()),
            ("m1", t(&p.m1)),
            ("m2", t(&p.m2)),
            ("r1", t(&p.r1)),
            ("r2", t(&p.r2)),
            ("k1", t(&p.k1)),
            ("k2", t(&p.k2)),
            ("g", t(&p.g)),
            ("theta0", self.start.theta0.canonical()),
            ("thetadot0", t(&self.start.thetadot0)),
            ("omega0", t(&self.start.omega0)),
        ]
    }
}

/// A validated model: parameters, the law of each contact, and the start.
///
/// The ideal contact models of the paper are the limits of Coulomb
/// friction (rolling μ = ∞, frictionless μ = 0), so every model — ideal or
/// not — is one `Model`, and every question about it has one answer
/// ([`crate::oracle`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    params: Params,
    floor: Law,
    contact: Law,
    start: Start,
}

impl Model {
    /// Validates and builds a model.
    ///
    /// Errors: [`Error::InvalidParameter`] naming the parameter: those of
    /// [`Ideal::new`]; a contact between the cylinders that is `held`; a
    /// spin that sliding friction would turn without inertia (k2 = 0 under
    /// a contact with kinetic friction; k1 = 0 where the floor can slide and
    /// a contact has kinetic friction).
    pub fn new(params: Params, floor: Law, contact: Law, start: Start) -> Result<Self> {
        validate(&params, &start, floor == Law::Held)?;
        if contact == Law::Held {
            return Err(Error::invalid(
                "contact",
                "fixed",
                "only cylinder 1 can be held (by the floor): expected roll, slip or a \
                 friction coefficient",
            ));
        }
        let kinetic = |l: &Law| l.kinetic().is_some_and(|k| k > 0);
        // cylinder 1's spin is free of the floor only where the floor can slide
        let floor_slides = matches!(floor, Law::Frictionless | Law::Coulomb { .. });
        if params.k1 == 0 && floor_slides && (kinetic(&floor) || kinetic(&contact)) {
            return Err(Error::invalid(
                "k1",
                "0",
                "must be > 0 with finite friction (a spin without inertia cannot slide under friction)",
            ));
        }
        if params.k2 == 0 && kinetic(&contact) {
            return Err(Error::invalid(
                "k2",
                "0",
                "must be > 0 with finite friction (a spin without inertia cannot slide under friction)",
            ));
        }
        Ok(Model {
            params,
            floor,
            contact,
            start,
        })
    }

    /// The model of an ideal (paper) contact model: `roll` is
    /// [`Law::Rolling`], `slip` [`Law::Frictionless`], `fixed` [`Law::Held`].
    pub fn from_ideal(ideal: &Ideal) -> Self {
        Model {
            params: ideal.params.clone(),
            floor: match ideal.floor {
                Floor::Roll => Law::Rolling,
                Floor::Slip => Law::Frictionless,
                Floor::Fixed => Law::Held,
            },
            contact: match ideal.contact {
                Contact::Roll => Law::Rolling,
                Contact::Slip => Law::Frictionless,
            },
            start: ideal.start.clone(),
        }
    }

    /// The paper's main case: identical solid cylinders, both contacts
    /// rolling, from rest at θ0.
    pub fn paper_default(theta0: Exact) -> Self {
        Model::from_ideal(&Ideal::paper_default(theta0))
    }

    /// Parameters.
    pub fn params(&self) -> &Params {
        &self.params
    }
    /// The law at the floor.
    pub fn floor(&self) -> &Law {
        &self.floor
    }
    /// The law between the cylinders.
    pub fn contact(&self) -> &Law {
        &self.contact
    }
    /// The law of one contact.
    pub fn law(&self, w: Which) -> &Law {
        match w {
            Which::Floor => &self.floor,
            Which::Contact => &self.contact,
        }
    }
    /// Initial conditions.
    pub fn start(&self) -> &Start {
        &self.start
    }

    /// The same model with other laws (validated again).
    ///
    /// Errors: as [`Model::new`].
    pub fn with_laws(&self, floor: Law, contact: Law) -> Result<Self> {
        Model::new(self.params.clone(), floor, contact, self.start.clone())
    }

    /// Whether some contact has Coulomb friction.
    pub fn has_coulomb(&self) -> bool {
        self.floor.is_coulomb() || self.contact.is_coulomb()
    }

    /// The ideal model equal to this one when no contact has Coulomb
    /// friction (`None` otherwise).
    pub fn ideal(&self) -> Option<Ideal> {
        (!self.has_coulomb()).then(|| self.sticking())
    }

    /// The conservative model of the phase in which every Coulomb contact
    /// sticks (rolls): the motion from the start as long as no contact
    /// slips.
    pub fn sticking(&self) -> Ideal {
        let floor = match self.floor {
            Law::Held => Floor::Fixed,
            Law::Frictionless => Floor::Slip,
            Law::Rolling | Law::Coulomb { .. } => Floor::Roll,
        };
        let contact = match self.contact {
            Law::Frictionless => Contact::Slip,
            _ => Contact::Roll,
        };
        Ideal {
            params: self.params.clone(),
            floor,
            contact,
            start: self.start.clone(),
        }
    }

    /// Whether the motion starts from rest exactly at the top (θ0 = θ̇0 = 0):
    /// the paper's limiting case, where every time is infinite.
    pub fn starts_at_equilibrium(&self) -> bool {
        self.start.theta0.is_zero() && self.start.thetadot0 == 0
    }

    /// The sign of the motion: +1 if θ grows, −1 if it falls to the left.
    pub fn direction(&self) -> i32 {
        self.sticking().direction()
    }

    /// A one-line description for messages (long values shortened).
    pub fn describe(&self) -> String {
        let mut s = format!(
            "floor={} contact={}",
            self.floor.keyword(),
            self.contact.keyword()
        );
        for (key, law) in [("mu_floor", &self.floor), ("mu_contact", &self.contact)] {
            if matches!(law, Law::Coulomb { .. }) {
                s.push_str(&format!(" {key}={}", crate::error::shorten(&law.mu_text())));
            }
        }
        let ideal = self.sticking().describe();
        if let Some(rest) = ideal.split_once(" m1=").map(|(_, r)| r) {
            s.push_str(" m1=");
            s.push_str(rest);
        }
        s
    }

    /// The model as (key, exact text) pairs, in a stable order, for records:
    /// `floor`, `contact` (roll, slip, fixed, coulomb), `mu_floor`,
    /// `mu_contact` (inf, 0, μ or μs,μk; `none` for a held cylinder), then
    /// the parameters and the start.
    pub fn echo(&self) -> Vec<(&'static str, String)> {
        let mut out = vec![
            ("floor", self.floor.keyword().to_string()),
            ("contact", self.contact.keyword().to_string()),
            ("mu_floor", self.floor.mu_text()),
            ("mu_contact", self.contact.mu_text()),
        ];
        out.extend(self.sticking().echo().into_iter().skip(2));
        out
    }
}
