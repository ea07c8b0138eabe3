//! Contact laws and modes.

use crate::error::{Error, Result};
use crate::exact::{rational_text, Exact};
use rug::Rational;
use std::fmt;

/// How a contact transmits tangential force.
#[derive(Debug, Clone, PartialEq)]
pub enum Law {
    /// No slip ever (μ = ∞): the ideal `roll`.
    Roll,
    /// Frictionless (μ = 0): the ideal `slip`.
    Slip,
    /// Coulomb friction: sticking while |F| ≤ μs N, sliding with |F| = μk N
    /// against the slip velocity; 0 ≤ μk ≤ μs, μs > 0 finite.
    Coulomb {
        /// Static coefficient μs.
        mu_s: Rational,
        /// Kinetic coefficient μk.
        mu_k: Rational,
    },
}

impl Law {
    /// Parses `inf`, a number μ ≥ 0 (static = kinetic) or `S,K` (S ≥ K ≥ 0).
    /// `inf` is [`Law::Roll`] and `0` (or `0,0`) is [`Law::Slip`], exactly.
    ///
    /// Errors: [`Error::InvalidParameter`] naming `name`.
    pub fn parse(name: &str, text: &str) -> Result<Law> {
        let allowed = "expected inf, a number >= 0, or S,K with S >= K >= 0 \
                       (static and kinetic coefficients)";
        let t = text.trim();
        if t.eq_ignore_ascii_case("inf") || t.eq_ignore_ascii_case("infinity") {
            return Ok(Law::Roll);
        }
        let parts: Vec<&str> = t.split(',').collect();
        if parts.len() > 2 || parts.iter().any(|p| p.trim().is_empty()) {
            return Err(Error::invalid(name, text, allowed));
        }
        let num = |s: &str| -> Result<Rational> {
            let e = Exact::parse(name, s.trim(), false)
                .map_err(|_| Error::invalid(name, text, allowed))?;
            Ok(e.coef)
        };
        let mu_s = num(parts[0])?;
        let mu_k = if parts.len() == 2 {
            num(parts[1])?
        } else {
            mu_s.clone()
        };
        if mu_s < 0 || mu_k < 0 {
            return Err(Error::invalid(name, text, "must be >= 0"));
        }
        if mu_k > mu_s {
            return Err(Error::invalid(
                name,
                text,
                "the kinetic coefficient must not exceed the static one (S,K with S >= K)",
            ));
        }
        if mu_s == 0 {
            return Ok(Law::Slip);
        }
        Ok(Law::Coulomb { mu_s, mu_k })
    }

    /// Whether the law can change state (stick ↔ slip).
    pub fn is_coulomb(&self) -> bool {
        matches!(self, Law::Coulomb { .. })
    }

    /// μk (0 for `Slip`; `None` for `Roll`).
    pub fn kinetic(&self) -> Option<Rational> {
        match self {
            Law::Roll => None,
            Law::Slip => Some(Rational::new()),
            Law::Coulomb { mu_k, .. } => Some(mu_k.clone()),
        }
    }
}

impl fmt::Display for Law {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Law::Roll => f.write_str("inf"),
            Law::Slip => f.write_str("0"),
            Law::Coulomb { mu_s, mu_k } if mu_s == mu_k => f.write_str(&rational_text(mu_s)),
            Law::Coulomb { mu_s, mu_k } => {
                write!(f, "{},{}", rational_text(mu_s), rational_text(mu_k))
            }
        }
    }
}

/// The state of one contact during a mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum State {
    /// No relative tangential motion (rolling); the tangential force is a
    /// constraint force.
    Stick,
    /// Sliding; the sign is that of the slip speed (0 for a frictionless
    /// contact, where the direction does not matter).
    Slip(i8),
}

impl fmt::Display for State {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            State::Stick => "stick",
            State::Slip(1) => "slip+",
            State::Slip(-1) => "slip-",
            State::Slip(_) => "slip",
        })
    }
}

/// The state of both contacts: a mode of the motion.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Mode {
    /// The floor under cylinder 1 (`Stick` also for a fixed floor).
    pub floor: State,
    /// The contact between the cylinders.
    pub contact: State,
}

impl fmt::Display for Mode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "floor {}, contact {}", self.floor, self.contact)
    }
}

impl Mode {
    /// A short tag for tables: `stick/slip+` (floor/contact).
    pub fn tag(&self) -> String {
        format!("{}/{}", self.floor, self.contact)
    }
}

/// The friction laws of both contacts.
#[derive(Debug, Clone, PartialEq)]
pub struct Friction {
    /// The floor under cylinder 1.
    pub floor: Law,
    /// The contact between the cylinders.
    pub contact: Law,
}
