//! Repeats one benchmark task many times in one process, for a profiler:
//!
//! ```sh
//! cargo build --release --example profile
//! perf record --call-graph dwarf target/release/examples/profile T3 30 200
//! valgrind --tool=callgrind target/release/examples/profile T3 30 20
//! ```
//!
//! Tasks (those of `bench/anchors/README.md`, identical solid cylinders, both rolling):
//! `T1` t(9/10) from rest at θ0 = 1/10 on one oracle (warm), `T1cold` the same
//! on a fresh oracle each time, `T2cold` θs for m2 = 2 from θ0 = 0 on a fresh
//! oracle, `T3` θ at 1000 equally spaced times (`oracle::theta_at_times` on the
//! model, as the bench times it), `T3rows` every column of `cylroll trajectory`
//! at those times (`oracle::trajectory`), `F3` and `F3rows` the same two calls on
//! the benchmark's frictional case (μ = 0.3 at both contacts, 1000 times to
//! t = 4.92, `T3friction` of `benches/tasks.rs`). Prints the mean
//! wall time per run to stderr (use `benches/tasks.rs` for measurements).

use cylroll::exact::Exact;
use cylroll::model::{Contact, Floor, Ideal, Law, Model, Params, Start};
use cylroll::oracle::{self, Options, Oracle};
use rug::Rational;
use std::time::Instant;

/// T3's t_end = 0.99 t(θs) (bench/anchors/README.md).
const T3_TEND: &str = "5.1467589831225409016963170827052163394777";

fn q(s: &str) -> Exact {
    Exact::parse("value", s, false).expect("exact")
}

fn model(m2: i64, theta0: &str) -> Ideal {
    let mut p = Params::identical_solid();
    p.m2 = Rational::from(m2);
    Ideal::new(p, Floor::Roll, Contact::Roll, Start::rest(q(theta0))).expect("model")
}

/// The allocator of the command and the benchmark, so a profile sees their costs.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    // SAFETY: first thing in main, before any big number or other thread
    unsafe { cylroll::allocator::use_mimalloc_for_gmp() };
    let args: Vec<String> = std::env::args().skip(1).collect();
    const TASKS: [&str; 7] = ["T1", "T1cold", "T2cold", "T3", "T3rows", "F3", "F3rows"];
    if args.len() < 2 || !TASKS.contains(&args[0].as_str()) {
        eprintln!("usage: profile T1|T1cold|T2cold|T3|T3rows|F3|F3rows DIGITS [REPEATS]");
        std::process::exit(2);
    }
    let number = |i: usize, default: usize| -> usize {
        match args.get(i).map(|s| s.parse::<usize>()) {
            None => default,
            Some(Ok(n)) if n >= 1 => n,
            _ => {
                eprintln!("profile: argument {} must be a positive integer", i + 1);
                std::process::exit(2);
            }
        }
    };
    let (task, digits, repeats) = (args[0].as_str(), number(1, 30) as u32, number(2, 100));
    if let Err(e) = run(task, digits, repeats) {
        eprintln!("profile: {e}");
        std::process::exit(e.exit_code());
    }
}

fn run(task: &str, digits: u32, repeats: usize) -> cylroll::error::Result<()> {
    let m = model(1, "1/10");
    let mut oracle = Oracle::new(&m, digits)?;
    let user_model = Model::from_ideal(&m);
    let opts = Options::digits(digits);
    let tend = q(T3_TEND).coef;
    let times: Vec<Exact> = (0..1000)
        .map(|i| Exact::rational(&tend * Rational::from((i as i64, 999))))
        .collect();
    let mu = || Law::parse_mu("mu", "0.3");
    let friction = user_model.clone().with_laws(mu()?, mu()?)?;
    let end = Rational::from((4920, 1000));
    let friction_times: Vec<Exact> = (0..1000)
        .map(|i| Exact::rational(&end * Rational::from((i as i64, 999))))
        .collect();
    let start = Instant::now();
    for _ in 0..repeats {
        match task {
            "T1" => {
                std::hint::black_box(oracle.time_at(&q("9/10"))?);
            }
            "T1cold" => {
                let mut o = Oracle::new(&m, digits)?;
                std::hint::black_box(o.time_at(&q("9/10"))?);
            }
            "T2cold" => {
                let mut o = Oracle::new(&model(2, "0"), digits)?;
                std::hint::black_box(o.separation_angle()?);
            }
            "T3" => {
                std::hint::black_box(oracle::theta_at_times(&user_model, &times, &opts)?);
            }
            "F3" => {
                std::hint::black_box(oracle::theta_at_times(&friction, &friction_times, &opts)?);
            }
            "F3rows" => {
                std::hint::black_box(oracle::trajectory(&friction, &friction_times, &opts)?);
            }
            _ => {
                std::hint::black_box(oracle::trajectory(&user_model, &times, &opts)?);
            }
        }
    }
    eprintln!(
        "{task} at {digits} digits: {:.4} ms per run (wall, mean of {repeats})",
        start.elapsed().as_secs_f64() * 1e3 / repeats as f64
    );
    Ok(())
}
