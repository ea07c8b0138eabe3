//! Repeats one benchmark task many times in one process, for a profiler:
//!
//! ```sh
//! cargo build --release --example profile
//! perf record --call-graph dwarf target/release/examples/profile T3 30 200
//! valgrind --tool=callgrind target/release/examples/profile T3 30 20
//! ```
//!
//! Tasks (those of `../shared/bench`, identical solid cylinders, both rolling):
//! `T1` t(9/10) from rest at θ0 = 1/10 on one oracle (warm), `T1cold` the same
//! on a fresh oracle each time, `T2cold` θs for m2 = 2 from θ0 = 0 on a fresh
//! oracle, `T3` θ at 1000 equally spaced times on one oracle, `T3rows` all 13
//! columns of `trajectory` at those times. Prints the mean
//! wall time per run to stderr (use `benches/tasks.rs` for measurements).

use cylroll::exact::Exact;
use cylroll::model::{Contact, Floor, Model, Params, Start};
use cylroll::oracle::Oracle;
use rug::Rational;
use std::time::Instant;

/// T3's t_end = 0.99 t(θs) (../shared/bench/README.md).
const T3_TEND: &str = "5.1467589831225409016963170827052163394777";

fn q(s: &str) -> Exact {
    Exact::parse("value", s, false).expect("exact")
}

fn model(m2: i64, theta0: &str) -> Model {
    let mut p = Params::identical_solid();
    p.m2 = Rational::from(m2);
    Model::new(p, Floor::Roll, Contact::Roll, Start::rest(q(theta0))).expect("model")
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.len() < 2 {
        eprintln!("usage: profile T1|T1cold|T2cold|T3|T3rows DIGITS [REPEATS]");
        std::process::exit(2);
    }
    let task = args[0].as_str();
    let digits: u32 = args[1].parse().expect("DIGITS");
    let repeats: usize = args.get(2).map_or(100, |s| s.parse().expect("REPEATS"));
    let m = model(1, "1/10");
    let mut oracle = Oracle::new(&m, digits).expect("oracle");
    let tend = q(T3_TEND).coef;
    let times: Vec<Exact> = (0..1000)
        .map(|i| Exact::rational(&tend * Rational::from((i as i64, 999))))
        .collect();
    let start = Instant::now();
    for _ in 0..repeats {
        match task {
            "T1" => {
                std::hint::black_box(oracle.time_at(&q("9/10")).expect("T1"));
            }
            "T1cold" => {
                let mut o = Oracle::new(&m, digits).expect("oracle");
                std::hint::black_box(o.time_at(&q("9/10")).expect("T1"));
            }
            "T2cold" => {
                let mut o = Oracle::new(&model(2, "0"), digits).expect("oracle");
                std::hint::black_box(o.separation_angle().expect("T2b"));
            }
            "T3" => {
                std::hint::black_box(oracle.theta_at_times(&times).expect("T3"));
            }
            "T3rows" => {
                std::hint::black_box(oracle.trajectory(&times).expect("T3rows"));
            }
            other => {
                eprintln!("unknown task {other}");
                std::process::exit(2);
            }
        }
    }
    eprintln!(
        "{task} at {digits} digits: {:.4} ms per run (wall, mean of {repeats})",
        start.elapsed().as_secs_f64() * 1e3 / repeats as f64
    );
}
