//! Contact laws: one type for every contact model.
//!
//! The ideal contacts of the paper are the limits of Coulomb friction:
//! rolling is μ = ∞, a frictionless contact μ = 0. A held lower cylinder
//! (the paper's footnote 8) is the floor law [`Law::Held`].

use crate::error::{Error, Result};
use crate::exact::{rational_text, Exact};
use rug::Rational;
use std::fmt;

/// Which contact: the floor under cylinder 1, or the contact between the
/// cylinders.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
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

    /// The name of the contact's coefficient key: `mu_floor`, `mu_contact`.
    pub fn mu_key(self) -> &'static str {
        match self {
            Which::Floor => "mu_floor",
            Which::Contact => "mu_contact",
        }
    }
}

/// How a contact transmits tangential force.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Law {
    /// No slip ever: μ = ∞ (the paper's rolling contact, `roll`).
    Rolling,
    /// No tangential force: μ = 0 (the paper's slipping contact, `slip`).
    Frictionless,
    /// Coulomb friction: sticking while |F| ≤ μs N, sliding with |F| = μk N
    /// against the slip; 0 ≤ μk ≤ μs, 0 < μs < ∞.
    Coulomb {
        /// Static coefficient μs.
        mu_s: Rational,
        /// Kinetic coefficient μk.
        mu_k: Rational,
    },
    /// The floor holds cylinder 1 still (`fixed`; a floor law only).
    Held,
}

const MU_ALLOWED: &str = "expected inf, a number >= 0, or S,K with S >= K >= 0 \
                          (static and kinetic coefficients)";

impl Law {
    /// Parses a friction coefficient: `inf` (rolling), a number μ ≥ 0
    /// (static = kinetic; `0` is frictionless) or `S,K` (S ≥ K ≥ 0).
    ///
    /// Errors: [`Error::InvalidParameter`] naming `name`.
    pub fn parse_mu(name: &str, text: &str) -> Result<Law> {
        let t = text.trim();
        if t.eq_ignore_ascii_case("inf") || t.eq_ignore_ascii_case("infinity") {
            return Ok(Law::Rolling);
        }
        let parts: Vec<&str> = t.split(',').collect();
        if parts.len() > 2 || parts.iter().any(|p| p.trim().is_empty()) {
            return Err(Error::invalid(name, text, MU_ALLOWED));
        }
        let num = |s: &str| -> Result<Rational> {
            let e = Exact::parse(name, s.trim(), false)
                .map_err(|_| Error::invalid(name, text, MU_ALLOWED))?;
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
            return Ok(Law::Frictionless);
        }
        Ok(Law::Coulomb { mu_s, mu_k })
    }

    /// Parses a contact keyword: `roll`, `slip` and, for the floor, `fixed`.
    ///
    /// Errors: [`Error::InvalidParameter`] naming the contact.
    pub fn parse_keyword(which: Which, text: &str) -> Result<Law> {
        match (which, text.trim().to_ascii_lowercase().as_str()) {
            (_, "roll") => Ok(Law::Rolling),
            (_, "slip") => Ok(Law::Frictionless),
            (Which::Floor, "fixed") => Ok(Law::Held),
            (Which::Floor, _) => Err(Error::invalid(
                "floor",
                text,
                "expected roll, slip or fixed (a friction coefficient goes to --mu-floor)",
            )),
            (Which::Contact, _) => Err(Error::invalid(
                "contact",
                text,
                "expected roll or slip (a friction coefficient goes to --mu-contact)",
            )),
        }
    }

    /// Coulomb friction (a contact that can change between sticking and
    /// sliding).
    pub fn is_coulomb(&self) -> bool {
        matches!(self, Law::Coulomb { .. })
    }

    /// Rolling, frictionless or held: a law whose contact never changes
    /// state, so that a motion under it keeps its energy.
    pub fn is_ideal(&self) -> bool {
        !self.is_coulomb()
    }

    /// μk: 0 for a frictionless contact, `None` where the contact never
    /// slides (rolling, held).
    pub fn kinetic(&self) -> Option<Rational> {
        match self {
            Law::Rolling | Law::Held => None,
            Law::Frictionless => Some(Rational::new()),
            Law::Coulomb { mu_k, .. } => Some(mu_k.clone()),
        }
    }

    /// μs: `None` where sticking has no limit (rolling, held) or no
    /// meaning (frictionless).
    pub fn static_coef(&self) -> Option<Rational> {
        match self {
            Law::Coulomb { mu_s, .. } => Some(mu_s.clone()),
            _ => None,
        }
    }

    /// The keyword echoed for the law: `roll`, `slip`, `fixed`, `coulomb`.
    pub fn keyword(&self) -> &'static str {
        match self {
            Law::Rolling => "roll",
            Law::Frictionless => "slip",
            Law::Held => "fixed",
            Law::Coulomb { .. } => "coulomb",
        }
    }

    /// The coefficient echoed for the law: `inf`, `0`, `S` or `S,K`;
    /// `none` for a held cylinder (no floor contact).
    pub fn mu_text(&self) -> String {
        match self {
            Law::Rolling => "inf".into(),
            Law::Frictionless => "0".into(),
            Law::Held => "none".into(),
            Law::Coulomb { mu_s, mu_k } if mu_s == mu_k => rational_text(mu_s),
            Law::Coulomb { mu_s, mu_k } => {
                format!("{},{}", rational_text(mu_s), rational_text(mu_k))
            }
        }
    }
}

impl fmt::Display for Law {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Law::Coulomb { .. } => write!(f, "coulomb mu = {}", self.mu_text()),
            _ => f.write_str(self.keyword()),
        }
    }
}
