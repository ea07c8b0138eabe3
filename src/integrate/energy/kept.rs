//! Facts of a model at a working precision kept per thread between
//! answers: δs = θs − θ0, t(δs), and the time of the branch point, each
//! with its error.
//!
//! Every answer builds its routes afresh (a [`super::Route`] per call), and
//! a library user asking the same model again and again — a table, then
//! another, an engine's test suite — paid the separation's root and its
//! quadratures again each time. They are functions of the model as solved
//! (its mirror image for a fall to the left), the precision and the point
//! alone: the root is refined from the scan's bracket by the closed form of
//! N12, t(δs) is the θ form's tanh-sinh quadrature of a fixed rule, and the
//! branch point's time the half-angle form's by a fixed rule where the
//! engine holds no Gauss–Legendre rule (the caller's condition: whether
//! one is used depends on what the engine did before). So the numbers
//! kept are the numbers a fresh thread computes, bit for bit (a test in
//! `tests/` asks this of whole answers); nothing that depends on what was
//! asked before is kept.

use crate::model::Ideal;
use rug::Float;
use std::cell::RefCell;

/// Which fact of a model at a precision.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Fact {
    /// δs and its error.
    DeltaS,
    /// t(δs) by [`super::Engine::time`] and its error.
    TimeS,
    /// t(δ) at a branch point δ by [`super::Engine::time_fast`] (`high`
    /// its stopping rule, no rule built) and its error.
    BranchTime {
        /// The ladder's higher run.
        high: bool,
    },
}

/// A fact, the point it is at (None: the fact names it) and its value.
type Kept = (Fact, Option<Float>, (Float, Float));

/// One model at one precision.
struct Entry {
    model: Ideal,
    prec: u32,
    facts: Vec<Kept>,
}

/// Models × precisions kept per thread: a ladder's two precisions of a
/// few models, the most recently used last.
const KEPT: usize = 16;

/// Facts kept per model and precision (each kind once or twice).
const FACTS_PER_ENTRY: usize = 8;

thread_local! {
    static FACTS: RefCell<Vec<Entry>> = const { RefCell::new(Vec::new()) };
}

fn same_point(a: Option<&Float>, b: Option<&Float>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(x), Some(y)) => x.prec() == y.prec() && x == y,
        _ => false,
    }
}

/// The fact kept for `model` at `prec` and the point `at`, if any (the
/// entry becomes the most recently used). A thread whose locals are torn
/// down keeps nothing.
pub fn get(model: &Ideal, prec: u32, fact: Fact, at: Option<&Float>) -> Option<(Float, Float)> {
    FACTS
        .try_with(|f| {
            let mut f = f.borrow_mut();
            let i = f.iter().position(|e| e.prec == prec && e.model == *model)?;
            let e = f.remove(i);
            let v = e
                .facts
                .iter()
                .find(|(k, x, _)| *k == fact && same_point(x.as_ref(), at))
                .map(|(_, _, v)| v.clone());
            f.push(e);
            v
        })
        .ok()
        .flatten()
}

/// Keeps `v` as the fact of `model` at `prec` and the point `at` (the
/// oldest entry leaves when [`KEPT`] are held; an entry's oldest fact when
/// it holds [`FACTS_PER_ENTRY`]).
pub fn put(model: &Ideal, prec: u32, fact: Fact, at: Option<&Float>, v: &(Float, Float)) {
    let _ = FACTS.try_with(|f| {
        let mut f = f.borrow_mut();
        let mut e = match f.iter().position(|e| e.prec == prec && e.model == *model) {
            Some(i) => f.remove(i),
            None => {
                if f.len() >= KEPT {
                    f.remove(0);
                }
                Entry {
                    model: model.clone(),
                    prec,
                    facts: Vec::new(),
                }
            }
        };
        e.facts
            .retain(|(k, x, _)| !(*k == fact && same_point(x.as_ref(), at)));
        if e.facts.len() >= FACTS_PER_ENTRY {
            e.facts.remove(0);
        }
        e.facts.push((fact, at.cloned(), v.clone()));
        f.push(e);
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::Exact;
    use crate::model::{Contact, Floor, Params, Start};

    fn model(theta0: &str) -> Ideal {
        Ideal::new(
            Params::identical_solid(),
            Floor::Roll,
            Contact::Roll,
            Start::rest(Exact::parse("theta0", theta0, false).unwrap()),
        )
        .unwrap()
    }

    #[test]
    fn kept_by_model_precision_and_fact_and_oldest_leaves() {
        let (a, b) = (model("1/10"), model("1/5"));
        let v = |x: u32| (Float::with_val(64, x), Float::with_val(64, 1u32));
        put(&a, 100, Fact::DeltaS, None, &v(1));
        put(&a, 200, Fact::DeltaS, None, &v(2));
        put(&b, 100, Fact::TimeS, None, &v(3));
        assert_eq!(get(&a, 100, Fact::DeltaS, None), Some(v(1)));
        assert_eq!(get(&a, 200, Fact::DeltaS, None), Some(v(2)));
        assert_eq!(get(&a, 100, Fact::TimeS, None), None);
        assert_eq!(get(&b, 100, Fact::TimeS, None), Some(v(3)));
        assert_eq!(get(&b, 100, Fact::DeltaS, None), None);
        assert_eq!(get(&b, 200, Fact::TimeS, None), None);
        // the oldest leaves: fill with other precisions of b
        for k in 0..KEPT as u32 {
            put(&b, 1000 + k, Fact::DeltaS, None, &v(k));
        }
        assert_eq!(get(&a, 100, Fact::DeltaS, None), None);
        assert_eq!(
            get(&b, 1000 + KEPT as u32 - 1, Fact::DeltaS, None),
            Some(v(KEPT as u32 - 1))
        );
    }

    #[test]
    fn a_fact_at_a_point_is_kept_for_that_point_and_run() {
        let a = model("1/10");
        let v = |x: u32| (Float::with_val(64, x), Float::with_val(64, 1u32));
        let at = |x: f64, p: u32| Float::with_val(p, x);
        let low = Fact::BranchTime { high: false };
        let high = Fact::BranchTime { high: true };
        put(&a, 300, low, Some(&at(0.5, 300)), &v(1));
        put(&a, 300, high, Some(&at(0.5, 300)), &v(2));
        assert_eq!(get(&a, 300, low, Some(&at(0.5, 300))), Some(v(1)));
        assert_eq!(get(&a, 300, high, Some(&at(0.5, 300))), Some(v(2)));
        // another point, the same point at another precision, no point
        assert_eq!(get(&a, 300, low, Some(&at(0.25, 300))), None);
        assert_eq!(get(&a, 300, low, Some(&at(0.5, 200))), None);
        assert_eq!(get(&a, 300, low, None), None);
        // replaced, not repeated; the oldest fact leaves a full entry
        put(&a, 300, low, Some(&at(0.5, 300)), &v(3));
        assert_eq!(get(&a, 300, low, Some(&at(0.5, 300))), Some(v(3)));
        for k in 0..FACTS_PER_ENTRY as u32 {
            put(&a, 300, low, Some(&at(k as f64 + 2.0, 300)), &v(k));
        }
        assert_eq!(get(&a, 300, high, Some(&at(0.5, 300))), None);
        assert_eq!(get(&a, 300, low, Some(&at(2.0, 300))), Some(v(0)));
    }
}
