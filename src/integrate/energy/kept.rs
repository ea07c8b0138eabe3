//! Facts of a model at a working precision kept per thread between
//! answers: δs = θs − θ0 and t(δs), each with its error.
//!
//! Every answer builds its routes afresh (a [`super::Route`] per call), and
//! a library user asking the same model again and again — a table, then
//! another, an engine's test suite — paid the separation's root and its
//! quadrature again each time. Both are functions of the model as solved
//! (its mirror image for a fall to the left) and the precision alone: the
//! root is refined from the scan's bracket by the closed form of N12, and
//! t(δs) is the θ form's tanh-sinh quadrature of a fixed rule. So the
//! numbers kept are the numbers a fresh thread computes, bit for bit (a
//! test in `tests/` asks this of whole answers); nothing that depends on
//! what was asked before (the engines' adaptive choices) is kept.

use crate::model::Ideal;
use rug::Float;
use std::cell::RefCell;

/// One model at one precision.
struct Entry {
    model: Ideal,
    prec: u32,
    delta_s: Option<(Float, Float)>,
    t_s: Option<(Float, Float)>,
}

/// Models × precisions kept per thread: a ladder's two precisions of a
/// few models, the most recently used last.
const KEPT: usize = 16;

thread_local! {
    static FACTS: RefCell<Vec<Entry>> = const { RefCell::new(Vec::new()) };
}

/// Which fact of an entry.
#[derive(Clone, Copy)]
pub enum Fact {
    /// δs and its error.
    DeltaS,
    /// t(δs) by [`super::Engine::time`] and its error.
    TimeS,
}

fn slot(e: &mut Entry, fact: Fact) -> &mut Option<(Float, Float)> {
    match fact {
        Fact::DeltaS => &mut e.delta_s,
        Fact::TimeS => &mut e.t_s,
    }
}

/// The fact kept for `model` at `prec`, if any (the entry becomes the most
/// recently used). A thread whose locals are torn down keeps nothing.
pub fn get(model: &Ideal, prec: u32, fact: Fact) -> Option<(Float, Float)> {
    FACTS
        .try_with(|f| {
            let mut f = f.borrow_mut();
            let i = f.iter().position(|e| e.prec == prec && e.model == *model)?;
            let e = f.remove(i);
            let v = match fact {
                Fact::DeltaS => e.delta_s.clone(),
                Fact::TimeS => e.t_s.clone(),
            };
            f.push(e);
            v
        })
        .ok()
        .flatten()
}

/// Keeps `v` as the fact of `model` at `prec` (the oldest entry leaves
/// when [`KEPT`] are held).
pub fn put(model: &Ideal, prec: u32, fact: Fact, v: &(Float, Float)) {
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
                    delta_s: None,
                    t_s: None,
                }
            }
        };
        *slot(&mut e, fact) = Some(v.clone());
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
        put(&a, 100, Fact::DeltaS, &v(1));
        put(&a, 200, Fact::DeltaS, &v(2));
        put(&b, 100, Fact::TimeS, &v(3));
        assert_eq!(get(&a, 100, Fact::DeltaS), Some(v(1)));
        assert_eq!(get(&a, 200, Fact::DeltaS), Some(v(2)));
        assert_eq!(get(&a, 100, Fact::TimeS), None);
        assert_eq!(get(&b, 100, Fact::TimeS), Some(v(3)));
        assert_eq!(get(&b, 100, Fact::DeltaS), None);
        assert_eq!(get(&b, 200, Fact::TimeS), None);
        // the oldest leaves: fill with other precisions of b
        for k in 0..KEPT as u32 {
            put(&b, 1000 + k, Fact::DeltaS, &v(k));
        }
        assert_eq!(get(&a, 100, Fact::DeltaS), None);
        assert_eq!(
            get(&b, 1000 + KEPT as u32 - 1, Fact::DeltaS),
            Some(v(KEPT as u32 - 1))
        );
    }
}
