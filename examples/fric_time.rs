//! Timing of the motion with friction (main case, μ = 0.3 at both contacts):
//! the event list at the ladder's two precisions, and 1000 rows to t_s.
//! `cargo run --release --example fric_time -- [DIGITS]` (with ONLY_THETA
//! set in the environment it stops after θ at the 1000 times).
use cylroll::exact::Exact;
use cylroll::model::{Law, Model};
use cylroll::motion::{self, Caches, Request, Until};
use cylroll::oracle::{self, Options};
use rug::Rational;

fn main() {
    let digits: u32 = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(30);
    let mu = || Law::parse_mu("mu", "0.3").expect("mu");
    let m = Model::paper_default(Exact::parse("theta0", "1/10", false).expect("theta0"))
        .with_laws(mu(), mu())
        .expect("model");
    let opts = Options::digits(digits);
    let (p1, p2) = cylroll::numeric::verify::precisions(digits, 0);
    for (p, run) in [
        (p1, cylroll::numeric::verify::Run::Low),
        (p2, cylroll::numeric::verify::Run::High),
    ] {
        let t = std::time::Instant::now();
        let req = Request {
            times: Vec::new(),
            until: Until::End,
            theta_only: false,
            branch: opts.branch.clone(),
            method: opts.method,
            horizon: None,
            run,
            digits,
            sides: Vec::new(),
            target_side: None,
            low_deltas: Vec::new(),
            derived_at_high: false,
        };
        let mo = motion::run(&m, &req, p, &mut Caches::default()).expect("motion");
        println!(
            "{p} bits: {:.1} ms, {} events, routes {:?}, work {:?}",
            t.elapsed().as_secs_f64() * 1e3,
            mo.events.len(),
            mo.routes,
            mo.work_done
        );
    }
    let t = std::time::Instant::now();
    let sep = oracle::separation(&m, &opts).expect("separation");
    println!("separation: {:.1} ms", t.elapsed().as_secs_f64() * 1e3);
    let ts = sep.value("t_s").expect("t_s").value.to_f64();
    let end = Rational::from(((ts * 1000.0).floor() as i64, 1000));
    let times: Vec<Exact> = (0..1000)
        .map(|i| Exact::rational(&end * Rational::from((i as i64, 999))))
        .collect();
    let t = std::time::Instant::now();
    let (th, _) = oracle::theta_at_times(&m, &times, &opts).expect("theta");
    println!(
        "theta at {} times: {:.1} ms (last {})",
        th.len(),
        t.elapsed().as_secs_f64() * 1e3,
        th[999].text
    );
    if std::env::var("ONLY_THETA").is_ok() {
        return;
    }
    let t = std::time::Instant::now();
    let tr = oracle::trajectory(&m, &times, &opts).expect("trajectory");
    println!(
        "trajectory, {} rows: {:.1} ms",
        tr.rows.len(),
        t.elapsed().as_secs_f64() * 1e3
    );
}
