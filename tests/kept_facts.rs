//! An answer does not depend on what its thread asked before.
//!
//! A thread keeps a model's δs and t(δs) at each working precision between
//! answers, and the tanh-sinh rules' nodes: a library user asking the same
//! model again (a table, then another) does not pay for them again. What is
//! kept must be the very bits a fresh thread computes. Each answer here —
//! values, digits, error bounds, events, notes, written out whole with
//! `{:?}` — is computed on a fresh thread, then again on one thread after
//! the other questions, in an order that has the thread reuse every kept
//! fact (the mirrored start shares its model's facts: both are solved as
//! the same fall to the right), and the two must be the same text.

use cylroll::exact::Exact;
use cylroll::model::{Law, Model};
use cylroll::oracle::{self, Options};
use rug::Rational;

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
fn answers_after_other_answers_are_those_of_a_fresh_thread() {
    let fresh: Vec<String> = questions()
        .into_iter()
        .map(|(_, f)| std::thread::spawn(f).join().expect("fresh thread"))
        .collect();
    for (text, (name, _)) in fresh.iter().zip(questions()) {
        assert!(!text.starts_with("Err"), "{name}: {text}");
    }
    let warm: Vec<Vec<String>> = std::thread::spawn(|| {
        // each question after all the others, twice over
        (0..2)
            .map(|_| questions().into_iter().map(|(_, f)| f()).collect())
            .collect()
    })
    .join()
    .expect("warm thread");
    for round in &warm {
        for ((got, want), (name, _)) in round.iter().zip(&fresh).zip(questions()) {
            assert_eq!(
                got, want,
                "{name}: differs after the thread's other answers"
            );
        }
    }
}
