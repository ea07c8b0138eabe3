//! What one check found: residuals per printed form, the verdict they imply,
//! the corrected form and its residuals, notes and separation roots.

use super::truth::PREC;
use crate::paper::X;
use rug::Float;

/// A printed form holds when its largest relative residual is at most
/// 10^`HOLD_EXP` (the working precision carries ≈ 67 digits).
pub const HOLD_EXP: i32 = -55;

/// 10^HOLD_EXP at the working precision.
pub fn hold_tol() -> X {
    X(Float::with_val(PREC, Float::i_pow_u(10, (-HOLD_EXP) as u32)).recip())
}

/// The largest residual of one form and where it was seen.
#[derive(Debug, Clone)]
pub struct FormStat {
    /// Which form ("form 2", "(F1 − F21) r1", …).
    pub label: String,
    /// Largest relative residual seen.
    pub max: X,
    /// The case (point, contacts, start) where it was seen.
    pub at: String,
    /// How many evaluations went into it.
    pub count: u32,
}

/// Residuals of several forms.
#[derive(Debug, Clone, Default)]
pub struct Tally {
    /// One entry per form, in the order first seen.
    pub forms: Vec<FormStat>,
}

impl Tally {
    /// Records |printed − truth| / max(|truth|, scale) for `label` at `at`.
    pub fn add(&mut self, label: &str, at: &str, printed: &X, truth: &X, scale: &X) {
        let den = truth.abs().max(scale.abs());
        let res = (printed - truth).abs() / den;
        self.add_res(label, at, res);
    }

    /// Records an already relative residual.
    pub fn add_res(&mut self, label: &str, at: &str, res: X) {
        let res = if res.0.is_nan() {
            X(Float::with_val(PREC, 1u32))
        } else {
            res
        };
        match self.forms.iter_mut().find(|f| f.label == label) {
            Some(f) => {
                f.count += 1;
                if res > f.max {
                    f.max = res;
                    f.at = at.to_string();
                }
            }
            None => self.forms.push(FormStat {
                label: label.to_string(),
                max: res,
                at: at.to_string(),
                count: 1,
            }),
        }
    }

    /// Whether something was recorded and every form holds.
    pub fn holds(&self) -> bool {
        let tol = hold_tol();
        !self.forms.is_empty() && self.forms.iter().all(|f| f.max <= tol)
    }

    /// The largest residual over all forms.
    pub fn max(&self) -> Option<X> {
        self.forms
            .iter()
            .map(|f| f.max.clone())
            .reduce(|a, b| a.max(b))
    }

    /// The forms that fail.
    pub fn failing(&self) -> Vec<&FormStat> {
        let tol = hold_tol();
        self.forms.iter().filter(|f| f.max > tol).collect()
    }
}

/// The verdict on one equation.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Verdict {
    /// Every printed form holds at every point.
    Holds,
    /// Holds only under the stated sign convention.
    Convention,
    /// Holds only under a stated reading of one of its symbols.
    Reading,
    /// A printed form fails; the corrected form holds.
    Erratum,
    /// A definition or statement with nothing to check numerically.
    Definition,
    /// The numbers do not support any of the above (a bug in the audit).
    Unresolved,
}

impl Verdict {
    /// The word used in the tables.
    pub fn word(&self) -> &'static str {
        match self {
            Verdict::Holds => "holds",
            Verdict::Convention => "holds only under a stated sign convention",
            Verdict::Reading => "holds only under a stated reading of a symbol",
            Verdict::Erratum => "erratum",
            Verdict::Definition => "definition (nothing to check)",
            Verdict::Unresolved => "UNRESOLVED",
        }
    }
}

/// A separation angle found by root-solving one equation.
#[derive(Debug, Clone)]
pub struct RootRow {
    /// The case ("P1 slip/slip").
    pub case: String,
    /// θs of the printed equation (None: no root in (0, π/2)).
    pub printed: Option<X>,
    /// θs of the corrected equation (None if the printed one holds).
    pub corrected: Option<X>,
    /// θs from N12 = 0 (the oracle, 60 digits).
    pub oracle: X,
}

/// Everything one check found.
#[derive(Debug, Clone, Default)]
pub struct Finding {
    /// The printed forms, evaluated under `convention` when one is stated.
    pub printed: Tally,
    /// The sign convention the printed forms need (the other reading fails,
    /// see the notes).
    pub convention: Option<String>,
    /// The convention is about what a symbol means, not about a sign.
    pub reading: bool,
    /// The corrected form (text) and its residuals.
    pub corrected: Option<(String, Tally)>,
    /// Why there is nothing to check (for definitions).
    pub definition: Option<String>,
    /// Evidence and remarks.
    pub notes: Vec<String>,
    /// Separation angles root-solved from the equation.
    pub roots: Vec<RootRow>,
}

impl Finding {
    /// A definition with its reason.
    pub fn definition(reason: &str) -> Self {
        Finding {
            definition: Some(reason.to_string()),
            ..Default::default()
        }
    }

    /// The verdict the numbers imply.
    pub fn verdict(&self) -> Verdict {
        if self.definition.is_some() {
            return Verdict::Definition;
        }
        if self.printed.holds() {
            return if self.convention.is_some() {
                if self.reading {
                    Verdict::Reading
                } else {
                    Verdict::Convention
                }
            } else {
                Verdict::Holds
            };
        }
        match &self.corrected {
            Some((_, t)) if t.holds() => Verdict::Erratum,
            _ => Verdict::Unresolved,
        }
    }

    /// Adds a note.
    pub fn note(&mut self, s: impl Into<String>) {
        self.notes.push(s.into());
    }
}
