//! Facts of a model at a working precision kept by the process between
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
//! kept are the numbers a fresh process computes, bit for bit (a test in
//! `tests/` asks this of whole answers); nothing that depends on what was
//! asked before is kept. The callers keep only what an engine with its
//! settings as made computes (a cross-check may turn a route off), nothing
//! while the thread's computation is cancelled (a stopped quadrature
//! returns NaN), and with each value the quadrature work it added to the
//! engine, which a kept value adds again: an engine that takes a kept
//! value is left as one that computed it.

use crate::model::Ideal;
use rug::Float;
use std::sync::Mutex;

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

/// A fact, the point it is at (None: the fact names it), its value, and
/// the work its computation added to the engine's count of quadrature
/// work (which decides when a Gauss–Legendre rule pays for itself: a kept
/// fact adds it again, so that the engine is left as a fresh one's).
type Kept = (Fact, Option<Float>, (Float, Float), f64);

/// One model at one precision.
struct Entry {
    model: Ideal,
    prec: u32,
    facts: Vec<Kept>,
}

/// Models × precisions kept: a ladder's two precisions of a few models,
/// the most recently used last.
const KEPT: usize = 16;

/// Facts kept per model and precision (each kind once or twice).
const FACTS_PER_ENTRY: usize = 8;

/// Kept facts, the most recently used entry last.
#[derive(Default)]
struct Store(Vec<Entry>);

impl Store {
    fn get(
        &mut self,
        model: &Ideal,
        prec: u32,
        fact: Fact,
        at: Option<&Float>,
    ) -> Option<((Float, Float), f64)> {
        let f = &mut self.0;
        let i = f.iter().position(|e| e.prec == prec && e.model == *model)?;
        let e = f.remove(i);
        let v = e
            .facts
            .iter()
            .find(|(k, x, _, _)| *k == fact && same_point(x.as_ref(), at))
            .map(|(_, _, v, w)| (v.clone(), *w));
        f.push(e);
        v
    }

    fn put(
        &mut self,
        model: &Ideal,
        prec: u32,
        fact: Fact,
        at: Option<&Float>,
        v: &(Float, Float),
        work: f64,
    ) {
        let f = &mut self.0;
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
            .retain(|(k, x, _, _)| !(*k == fact && same_point(x.as_ref(), at)));
        if e.facts.len() >= FACTS_PER_ENTRY {
            e.facts.remove(0);
        }
        e.facts.push((fact, at.cloned(), v.clone(), work));
        f.push(e);
    }
}

/// The facts, for every thread of the process: an answer's rows computed
/// on several threads at once, and each call of the Python package on a
/// worker thread of its own, take what another thread made (the values
/// are the same whoever computes them; a thread that finds a fact missing
/// computes it, as it would alone). Looked up a few times per answer.
static FACTS: Mutex<Store> = Mutex::new(Store(Vec::new()));

/// The facts, whatever a thread that panicked while holding them left
/// (every change is whole before the lock is released).
fn facts() -> std::sync::MutexGuard<'static, Store> {
    FACTS.lock().unwrap_or_else(|e| e.into_inner())
}

/// Forgets every kept fact (the next answers compute them again, to the
/// same bits): for a test of that, or a caller that wants the memory.
pub fn forget() {
    facts().0.clear();
}

fn same_point(a: Option<&Float>, b: Option<&Float>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(x), Some(y)) => x.prec() == y.prec() && x == y,
        _ => false,
    }
}

/// The fact kept for `model` at `prec` and the point `at`, if any, with
/// its engine work (the entry becomes the most recently used).
pub fn get(
    model: &Ideal,
    prec: u32,
    fact: Fact,
    at: Option<&Float>,
) -> Option<((Float, Float), f64)> {
    facts().get(model, prec, fact, at)
}

/// Keeps `v` as the fact of `model` at `prec` and the point `at`, with
/// the quadrature work its computation did (the oldest entry leaves when
/// [`KEPT`] are held; an entry's oldest fact when it holds
/// [`FACTS_PER_ENTRY`]). Nothing is kept while the thread's computation
/// is cancelled, nor a value or bound that is not finite: a quadrature
/// stopped by the cancellation returns NaN, which later answers would
/// have read.
pub fn put(
    model: &Ideal,
    prec: u32,
    fact: Fact,
    at: Option<&Float>,
    v: &(Float, Float),
    work: f64,
) {
    if crate::cancel::cancelled() || !v.0.is_finite() || !v.1.is_finite() {
        return;
    }
    facts().put(model, prec, fact, at, v, work);
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

    /// A store of the test's own: the process's is shared with the other
    /// tests running at the same time (fake values must not reach them).
    #[test]
    fn kept_by_model_precision_and_fact_and_oldest_leaves() {
        let mut s = Store::default();
        let (a, b) = (model("1/10"), model("1/5"));
        let v = |x: u32| (Float::with_val(64, x), Float::with_val(64, 1u32));
        s.put(&a, 100, Fact::DeltaS, None, &v(1), 0.0);
        s.put(&a, 200, Fact::DeltaS, None, &v(2), 0.0);
        s.put(&b, 100, Fact::TimeS, None, &v(3), 0.0);
        assert_eq!(s.get(&a, 100, Fact::DeltaS, None), Some((v(1), 0.0)));
        assert_eq!(s.get(&a, 200, Fact::DeltaS, None), Some((v(2), 0.0)));
        assert_eq!(s.get(&a, 100, Fact::TimeS, None), None);
        assert_eq!(s.get(&b, 100, Fact::TimeS, None), Some((v(3), 0.0)));
        assert_eq!(s.get(&b, 100, Fact::DeltaS, None), None);
        assert_eq!(s.get(&b, 200, Fact::TimeS, None), None);
        // the oldest leaves: fill with other precisions of b
        for k in 0..KEPT as u32 {
            s.put(&b, 1000 + k, Fact::DeltaS, None, &v(k), 0.0);
        }
        assert_eq!(s.get(&a, 100, Fact::DeltaS, None), None);
        assert_eq!(
            s.get(&b, 1000 + KEPT as u32 - 1, Fact::DeltaS, None),
            Some((v(KEPT as u32 - 1), 0.0))
        );
    }

    /// A kept branch time leaves the engine's count of quadrature work
    /// where computing it leaves it (the count decides when a
    /// Gauss–Legendre rule is built), and gives the computed bits. (A
    /// model no other test asks about: the process's facts.)
    #[test]
    fn a_kept_time_adds_the_work_its_computation_did() {
        let m = model("1/7901");
        let route = || super::super::Route::new(&m).unwrap();
        let p = 200;
        let d = Float::with_val(p, 0.5);
        let (mut a, mut b) = (route(), route());
        let computed = a.branch_time(&d, p, false).unwrap();
        let work = a.engine(p).unwrap().quadrature_work();
        assert!(work > 0.0);
        assert!(get(&m, p, Fact::BranchTime { high: false }, Some(&d)).is_some());
        let taken = b.branch_time(&d, p, false).unwrap();
        assert_eq!(taken, computed);
        assert_eq!(b.engine(p).unwrap().quadrature_work(), work);
    }

    #[test]
    fn a_fact_at_a_point_is_kept_for_that_point_and_run() {
        let mut s = Store::default();
        let a = model("1/10");
        let v = |x: u32| (Float::with_val(64, x), Float::with_val(64, 1u32));
        let at = |x: f64, p: u32| Float::with_val(p, x);
        let low = Fact::BranchTime { high: false };
        let high = Fact::BranchTime { high: true };
        s.put(&a, 300, low, Some(&at(0.5, 300)), &v(1), 0.0);
        s.put(&a, 300, high, Some(&at(0.5, 300)), &v(2), 0.0);
        assert_eq!(s.get(&a, 300, low, Some(&at(0.5, 300))), Some((v(1), 0.0)));
        assert_eq!(s.get(&a, 300, high, Some(&at(0.5, 300))), Some((v(2), 0.0)));
        // another point, the same point at another precision, no point
        assert_eq!(s.get(&a, 300, low, Some(&at(0.25, 300))), None);
        assert_eq!(s.get(&a, 300, low, Some(&at(0.5, 200))), None);
        assert_eq!(s.get(&a, 300, low, None), None);
        // replaced, not repeated; the oldest fact leaves a full entry
        s.put(&a, 300, low, Some(&at(0.5, 300)), &v(3), 0.0);
        assert_eq!(s.get(&a, 300, low, Some(&at(0.5, 300))), Some((v(3), 0.0)));
        for k in 0..FACTS_PER_ENTRY as u32 {
            s.put(&a, 300, low, Some(&at(k as f64 + 2.0, 300)), &v(k), 0.0);
        }
        assert_eq!(s.get(&a, 300, high, Some(&at(0.5, 300))), None);
        assert_eq!(s.get(&a, 300, low, Some(&at(2.0, 300))), Some((v(0), 0.0)));
    }

    /// Nothing is kept while the thread's computation is cancelled, nor a
    /// value that is not finite.
    #[test]
    fn nothing_kept_while_cancelled_or_not_finite() {
        use std::sync::atomic::{AtomicBool, Ordering};
        use std::sync::Arc;
        let m = model("1/7907");
        let one = (Float::with_val(64, 1), Float::with_val(64, 1));
        let nan = (Float::with_val(64, f64::NAN), Float::with_val(64, 1));
        let inf = (Float::with_val(64, 1), Float::with_val(64, f64::INFINITY));
        put(&m, 64, Fact::DeltaS, None, &nan, 0.0);
        put(&m, 64, Fact::TimeS, None, &inf, 0.0);
        assert_eq!(get(&m, 64, Fact::DeltaS, None), None);
        assert_eq!(get(&m, 64, Fact::TimeS, None), None);
        std::thread::spawn(move || {
            let flag = Arc::new(AtomicBool::new(true));
            crate::cancel::install(flag.clone());
            put(&m, 65, Fact::DeltaS, None, &one, 0.0);
            assert_eq!(get(&m, 65, Fact::DeltaS, None), None);
            flag.store(false, Ordering::Relaxed);
            put(&m, 65, Fact::DeltaS, None, &one, 0.0);
            assert_eq!(get(&m, 65, Fact::DeltaS, None), Some((one, 0.0)));
        })
        .join()
        .unwrap();
    }
}
