//! Checks as lists of forms: at every sample of a set of cases, each form
//! gives its value, the true value and a natural scale, and goes to the
//! printed forms, the corrected form or a side tally (evidence for a note).

use super::ctx::Ctx;
use super::finding::{Finding, Tally};
use super::points::Point;
use super::truth::{Case, StartKind};
use crate::error::Result;
use crate::model::{Contact, Floor};
use crate::paper::{Sym, X};

/// Which tally a form's residual goes to.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum To {
    /// A printed form (the verdict).
    Printed,
    /// The corrected form.
    Corrected,
    /// A side tally (another reading, for a note).
    Other,
}

/// One form at one sample: where it goes, its label, its value, the truth
/// and the scale of the relative residual.
pub(super) struct Form {
    to: To,
    label: String,
    value: X,
    truth: X,
    scale: X,
}

/// A printed form.
pub(super) fn printed(label: impl Into<String>, value: X, truth: &X, scale: &X) -> Form {
    form(To::Printed, label, value, truth, scale)
}

/// The corrected form.
pub(super) fn corrected(label: impl Into<String>, value: X, truth: &X, scale: &X) -> Form {
    form(To::Corrected, label, value, truth, scale)
}

/// Another reading, for a note.
pub(super) fn other(label: impl Into<String>, value: X, truth: &X, scale: &X) -> Form {
    form(To::Other, label, value, truth, scale)
}

fn form(to: To, label: impl Into<String>, value: X, truth: &X, scale: &X) -> Form {
    Form {
        to,
        label: label.into(),
        value,
        truth: truth.clone(),
        scale: scale.clone(),
    }
}

/// What a check samples.
#[derive(Clone)]
pub(super) struct On {
    /// The points.
    pub pts: Vec<Point>,
    /// The contact model.
    pub fc: (Floor, Contact),
    /// The starts, each with whether positions are at the oracle's times.
    pub starts: &'static [(StartKind, bool)],
}

/// From rest at the top.
pub(super) const REST: &[(StartKind, bool)] = &[(StartKind::Rest, false)];
/// The paper's general start (θ0, θ̇0, ω0 ≠ 0).
pub(super) const GENERAL: &[(StartKind, bool)] = &[(StartKind::General, false)];
/// From rest, then kick starts at the oracle's times.
pub(super) const REST_KICK: &[(StartKind, bool)] =
    &[(StartKind::Rest, false), (StartKind::Kick, true)];

/// The paper's general case: both rolling, general start (θ0, θ̇0, ω0 ≠ 0).
pub(super) fn gen(cx: &Ctx) -> On {
    both_rolling(cx, GENERAL)
}

/// Both rolling, from rest at the top and from kick starts (timed).
pub(super) fn rest_kick(cx: &Ctx) -> On {
    both_rolling(cx, REST_KICK)
}

/// Both rolling, at the random points and the paper's identical cylinders.
pub(super) fn both_rolling(cx: &Ctx, starts: &'static [(StartKind, bool)]) -> On {
    On {
        pts: cx.general(),
        fc: (Floor::Roll, Contact::Roll),
        starts,
    }
}

/// Both rolling, from rest at the top.
pub(super) fn rest(cx: &Ctx) -> On {
    both_rolling(cx, REST)
}

/// The residuals of a check: the finding (printed forms), the corrected
/// form's tally and the side tally.
#[derive(Default)]
pub(super) struct Sampled {
    pub f: Finding,
    pub corr: Tally,
    pub other: Tally,
}

impl Sampled {
    /// Records the forms of every sample of the cases of `on`.
    pub fn sample<F>(&mut self, cx: &mut Ctx, on: &On, mut forms: F) -> Result<()>
    where
        F: FnMut(&Case, &Sym) -> Vec<Form>,
    {
        for &(start, timed) in on.starts {
            for p in &on.pts {
                let c = cx.case(p, on.fc.0, on.fc.1, start, timed)?;
                for y in &c.syms {
                    self.add(&c.name, forms(&c, y));
                }
            }
        }
        Ok(())
    }

    /// Records the forms of one sample of case `at`.
    pub fn add(&mut self, at: &str, forms: Vec<Form>) {
        for m in forms {
            let t = match m.to {
                To::Printed => &mut self.f.printed,
                To::Corrected => &mut self.corr,
                To::Other => &mut self.other,
            };
            t.add(&m.label, at, &m.value, &m.truth, &m.scale);
        }
    }

    /// The finding, with the corrected form `text`.
    pub fn corrected(mut self, text: &str) -> Finding {
        self.f.corrected = Some((text.into(), self.corr));
        self.f
    }
}

/// Samples `forms` on every sample of the cases `on` selects.
pub(super) fn sample<F>(cx: &mut Ctx, on: impl FnOnce(&Ctx) -> On, forms: F) -> Result<Sampled>
where
    F: FnMut(&Case, &Sym) -> Vec<Form>,
{
    let on = on(cx);
    let mut s = Sampled::default();
    s.sample(cx, &on, forms)?;
    Ok(s)
}

/// A check of printed forms: the finding of [`sample`].
pub(super) fn check<F>(cx: &mut Ctx, on: impl FnOnce(&Ctx) -> On, forms: F) -> Result<Finding>
where
    F: FnMut(&Case, &Sym) -> Vec<Form>,
{
    Ok(sample(cx, on, forms)?.f)
}

impl Finding {
    /// The same finding with a note.
    pub fn with_note(mut self, s: impl Into<String>) -> Self {
        self.note(s);
        self
    }
}

/// Checks that are one call of a shared check: `name => helper(args…);`
/// defines `pub fn name(cx)` returning `helper(cx, args…)`.
macro_rules! calls {
    ($($name:ident => $f:ident($($arg:expr),* $(,)?);)*) => {
        $(
            pub fn $name(cx: &mut Ctx) -> Result<Finding> {
                $f(cx, $($arg),*)
            }
        )*
    };
}
pub(super) use calls;

/// Entries with nothing to check: `name: "why";` defines `pub fn name(cx)`
/// returning a definition with that reason.
macro_rules! definitions {
    ($($name:ident: $why:literal;)*) => {
        $(
            pub fn $name(_: &mut Ctx) -> Result<Finding> {
                Ok(Finding::definition($why))
            }
        )*
    };
}
pub(super) use definitions;
