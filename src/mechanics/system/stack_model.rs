//! The exact description of a stack of n ≥ 2 cylinders ([`StackModel`]):
//! masses, radii, inertia factors, the floor and contact models and the
//! start, the two-cylinder stack of an ideal model, and the checks of sizes
//! and ranges every [`super::System`] is built from.

use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::model::{Contact, Floor, Ideal};
use rug::{Float, Rational};

/// An exact description of a stack of n ≥ 2 cylinders (cylinder 1 on the
/// floor, cylinder i+1 on cylinder i).
#[derive(Debug, Clone, PartialEq)]
pub struct StackModel {
    /// How cylinder 1 meets the floor.
    pub floor: Floor,
    /// Contact model of each line of centres, bottom up (n − 1 entries).
    pub contacts: Vec<Contact>,
    /// Masses, bottom up (n entries).
    pub m: Vec<Rational>,
    /// Radii, bottom up.
    pub r: Vec<Rational>,
    /// Inertia factors: I_i = k_i m_i r_i².
    pub k: Vec<Rational>,
    /// Gravitational acceleration.
    pub g: Rational,
    /// Initial angle of each line of centres, clockwise from vertical (n − 1).
    pub theta0: Vec<Exact>,
    /// Initial angular velocity of each line of centres (n − 1).
    pub thetadot0: Vec<Rational>,
    /// The common rolling rate that fixes the conserved momenta: the state
    /// with every θ̇_j = 0 and the same momenta has φ̇1 = ω0, ẋ1 = r1 ω0 and
    /// every spin rolling on the one below (README, "Conventions", extended).
    pub omega0: Rational,
}

/// The natural units of a motion, in which tolerances and thresholds are
/// measured: its time unit sqrt(r/g), its length r (the first line of
/// centres, r1 + r2) and its force (the upper body's weight m2 g).
#[derive(Debug, Clone)]
pub struct Units {
    /// Time sqrt(r/g).
    pub ts: Float,
    /// Length r.
    pub r: Float,
    /// Force m2 g.
    pub force: Float,
}

impl StackModel {
    /// The stack's natural units at `prec` bits.
    pub fn units(&self, prec: u32) -> Units {
        let r = Float::with_val(prec, &self.r[0]) + Float::with_val(prec, &self.r[1]);
        let g = Float::with_val(prec, &self.g);
        let ts = Float::with_val(prec, &r / &g).sqrt();
        let force = Float::with_val(prec, &self.m[1]) * &g;
        Units { ts, r, force }
    }

    /// Number of cylinders.
    pub fn n(&self) -> usize {
        self.m.len()
    }

    /// The two-cylinder stack of a [`Ideal`].
    pub fn from_model(model: &Ideal) -> Self {
        let p = model.params();
        let st = model.start();
        StackModel {
            floor: model.floor(),
            contacts: vec![model.contact()],
            m: vec![p.m1.clone(), p.m2.clone()],
            r: vec![p.r1.clone(), p.r2.clone()],
            k: vec![p.k1.clone(), p.k2.clone()],
            g: p.g.clone(),
            theta0: vec![st.theta0.clone()],
            thetadot0: vec![st.thetadot0.clone()],
            omega0: st.omega0.clone(),
        }
    }

    /// Checks sizes and ranges.
    ///
    /// Errors: [`Error::InvalidParameter`] naming the offending key.
    pub fn validate(&self) -> Result<()> {
        let n = self.n();
        if n < 2 {
            return Err(Error::invalid("n", n, "must be >= 2"));
        }
        let lens = [
            ("r", self.r.len(), n),
            ("k", self.k.len(), n),
            ("contacts", self.contacts.len(), n - 1),
            ("theta0", self.theta0.len(), n - 1),
            ("thetadot0", self.thetadot0.len(), n - 1),
        ];
        for (name, got, want) in lens {
            if got != want {
                return Err(Error::invalid(
                    name,
                    format!("{got} values"),
                    format!("must have {want} values for n = {n}"),
                ));
            }
        }
        for (i, v) in self.m.iter().enumerate() {
            if *v <= 0 {
                return Err(Error::invalid(
                    "m",
                    crate::exact::rational_text(v),
                    format!("cylinder {}: must be > 0", i + 1),
                ));
            }
        }
        for (i, v) in self.r.iter().enumerate() {
            if *v <= 0 {
                return Err(Error::invalid(
                    "r",
                    crate::exact::rational_text(v),
                    format!("cylinder {}: must be > 0", i + 1),
                ));
            }
        }
        for (i, v) in self.k.iter().enumerate() {
            if *v < 0 {
                return Err(Error::invalid(
                    "k",
                    crate::exact::rational_text(v),
                    format!("cylinder {}: must be >= 0", i + 1),
                ));
            }
        }
        if self.g <= 0 {
            return Err(Error::invalid(
                "g",
                crate::exact::rational_text(&self.g),
                "must be > 0",
            ));
        }
        let half_pi = Float::with_val(256, rug::float::Constant::Pi) / 2u32;
        for (j, t) in self.theta0.iter().enumerate() {
            if t.to_float(256).abs() >= half_pi {
                return Err(Error::invalid(
                    "theta0",
                    t,
                    format!("line {}: must satisfy -pi/2 < theta0 < pi/2", j + 1),
                ));
            }
        }
        if self.floor == Floor::Fixed && self.omega0 != 0 {
            return Err(Error::invalid(
                "omega0",
                crate::exact::rational_text(&self.omega0),
                "must be 0 when the floor is fixed",
            ));
        }
        Ok(())
    }

    /// Whether every line starts at rest exactly on the vertical (then no
    /// time is finite).
    pub fn starts_at_equilibrium(&self) -> bool {
        self.theta0.iter().all(|t| t.is_zero()) && self.thetadot0.iter().all(|t| *t == 0)
    }
}
