//! An answer does not depend on what the process asked before.
//!
//! The process keeps a model's δs, t(δs) and branch point's time at each
//! working precision between answers (and a thread the tanh-sinh rules'
//! nodes): a library user asking the same model again (a table, then
//! another) does not pay for them again. What is kept must be the very bits
//! a fresh process computes. Each answer here — values, digits, error
//! bounds, events, notes, written out whole with `{:?}` — is computed with
//! nothing kept (`forget_kept`, on a fresh thread), then again after the
//! other questions, on threads of their own, in an order that has every
//! kept fact reused (the mirrored start shares its model's facts: both are
//! solved as the same fall to the right), and the two must be the same
//! text. The tests of this file run one at a time (the kept facts are the
//! process's).

use cylroll::exact::Exact;
use cylroll::integrate::energy::forget_kept;
use cylroll::model::{Law, Model};
use cylroll::oracle::{self, Options};
use rug::Rational;

/// One test at a time: each forgets the process's kept facts.
static ONE_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn one_at_a_time() -> std::sync::MutexGuard<'static, ()> {
    ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner())
}

/// `f` on a fresh thread with nothing kept.
fn fresh<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    forget_kept();
    std::thread::spawn(f).join().expect("fresh thread")
}

fn q(s: &str) -> Exact {
    Exact::parse("x", s, true).expect("number")
}

fn ideal(theta0: &str) -> Model {
    Model::paper_default(q(theta0))
}

fn friction() -> Model {
    let mu = || Law::parse_mu("mu", "0.3").expect("mu");
    ideal("1/10").with_laws(mu(), mu()).expect("model")
}

fn times(n: i64, end: (i64, i64)) -> Vec<Exact> {
    let end = Rational::from(end);
    (0..n)
        .map(|i| Exact::rational(&end * Rational::from((i, n - 1))))
        .collect()
}

/// One question, its whole answer as text.
type Question = (&'static str, fn() -> String);

fn questions() -> Vec<Question> {
    vec![
        ("theta at 40 times, main case, 30 digits", || {
            let opts = Options::digits(30);
            format!(
                "{:?}",
                oracle::theta_at_times(&ideal("1/10"), &times(40, (49, 10)), &opts)
            )
        }),
        ("table at 7 times, main case, 30 digits", || {
            let opts = Options::digits(30);
            format!(
                "{:?}",
                oracle::trajectory(&ideal("1/10"), &times(7, (49, 10)), &opts)
            )
        }),
        ("theta at 40 times, mirrored start, 30 digits", || {
            let opts = Options::digits(30);
            format!(
                "{:?}",
                oracle::theta_at_times(&ideal("-1/10"), &times(40, (49, 10)), &opts)
            )
        }),
        ("separation, main case, 40 digits", || {
            format!(
                "{:?}",
                oracle::separation(&ideal("1/10"), &Options::digits(40))
            )
        }),
        ("theta at 40 times, mu = 0.3, 30 digits", || {
            let opts = Options::digits(30);
            format!(
                "{:?}",
                oracle::theta_at_times(&friction(), &times(40, (49, 10)), &opts)
            )
        }),
        ("table at 5 times, mu = 0.3, 20 digits", || {
            let opts = Options::digits(20);
            format!(
                "{:?}",
                oracle::trajectory(&friction(), &times(5, (49, 10)), &opts)
            )
        }),
        ("theta at 40 times, main case, 100 digits", || {
            let opts = Options::digits(100);
            format!(
                "{:?}",
                oracle::theta_at_times(&ideal("1/10"), &times(40, (49, 10)), &opts)
            )
        }),
    ]
}

#[test]
fn answers_after_other_answers_are_those_of_a_fresh_process() {
    let _one = one_at_a_time();
    let fresh_texts: Vec<String> = questions().into_iter().map(|(_, f)| fresh(f)).collect();
    for (text, (name, _)) in fresh_texts.iter().zip(questions()) {
        assert!(!text.starts_with("Err"), "{name}: {text}");
    }
    forget_kept();
    // each question after all the others, twice over: on one thread, then
    // each on a thread of its own (the facts are the process's)
    let warm: Vec<Vec<String>> = vec![
        std::thread::spawn(|| questions().into_iter().map(|(_, f)| f()).collect())
            .join()
            .expect("warm thread"),
        questions()
            .into_iter()
            .map(|(_, f)| std::thread::spawn(f).join().expect("warm thread"))
            .collect(),
    ];
    let fresh = fresh_texts;
    for round in &warm {
        for ((got, want), (name, _)) in round.iter().zip(&fresh).zip(questions()) {
            assert_eq!(
                got, want,
                "{name}: differs after the thread's other answers"
            );
        }
    }
}

fn separation_text(digits: u32) -> String {
    format!(
        "{:?}",
        oracle::separation(&ideal("1/10"), &Options::digits(digits))
    )
}

/// A quadrature stopped by a cancellation returns NaN: computed on a
/// thread whose flag is set, then cleared, it must leave nothing that the
/// thread's later answers read (it did: the next table on the thread
/// failed, its event sequence not converging).
#[test]
fn a_cancelled_computation_leaves_nothing_for_later_answers() {
    use cylroll::integrate::energy::Route;
    use cylroll::model::Ideal;
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::sync::Arc;
    let _one = one_at_a_time();
    let fresh = fresh(|| separation_text(30));
    forget_kept();
    let after = std::thread::spawn(|| {
        let mut r = Route::new(&Ideal::paper_default(q("1/10"))).expect("route");
        let (p1, p2) = cylroll::numeric::verify::precisions(30, 0);
        for p in [p1, p2] {
            r.delta_s(p).expect("delta_s");
        }
        let flag = Arc::new(AtomicBool::new(true));
        cylroll::cancel::install(flag.clone());
        let mut stopped = Vec::new();
        for p in [p1, p2] {
            if let Ok((t, e)) = r.time_s(p) {
                stopped.push(t.is_finite() && e.is_finite());
            }
        }
        flag.store(false, Ordering::Relaxed);
        (stopped, separation_text(30))
    })
    .join()
    .expect("cancelled thread");
    // the stopped quadratures were not finite (the case this guards)
    assert!(after.0.iter().all(|finite| !finite), "{:?}", after.0);
    assert_eq!(after.1, fresh);
}

/// An engine whose public settings were changed (the Chebyshev route off,
/// as a cross-check does) computes its own values; they are not kept for
/// the thread's later answers, which are a fresh thread's. (Its t(δs)
/// differs from the default engine's in the last bits: kept, it changed
/// the separation's time.)
#[test]
fn values_of_an_engine_with_changed_settings_are_not_kept() {
    use cylroll::integrate::energy::Route;
    use cylroll::model::Ideal;
    let (p1, p2) = cylroll::numeric::verify::precisions(100, 0);
    let route = || Route::new(&Ideal::paper_default(q("1/10"))).expect("route");
    let _one = one_at_a_time();
    let (fresh, default_times) = fresh(move || {
        let text = separation_text(100);
        let mut r = route();
        let times: Vec<_> = [p1, p2]
            .iter()
            .map(|&p| r.time_s(p).expect("t").0)
            .collect();
        (text, times)
    });
    forget_kept();
    let (after, changed_times) = std::thread::spawn(move || {
        let mut r = route();
        let mut times = Vec::new();
        for p in [p1, p2] {
            r.engine(p).expect("engine").use_cheb = false;
            times.push(r.time_s(p).expect("t").0);
        }
        (separation_text(100), times)
    })
    .join()
    .expect("changed");
    assert_ne!(default_times, changed_times, "the settings change no bits");
    assert_eq!(after, fresh);
}
