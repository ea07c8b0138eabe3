//! The benchmark tasks of `bench/anchors/README.md` (T1, T2, T2b, T3) through the public
//! library API, each result checked against the Arb references of
//! `bench/anchors/ref` before anything is timed.
//!
//! Two modes:
//! - `cargo bench --bench tasks` runs divan (wall time);
//! - `CYLROLL_BENCH=cpu cargo bench --bench tasks [-- TASK…]` prints one JSON line
//!   per task and precision with the median *CPU* time of warm repeats (and the
//!   cold first call), the numbers `bench/compare.sh` sets side by side with the
//!   anchors. The machine may be shared: CPU time is the steadier figure.
//!   The task `T3n` (run only when named) times T3 with 10, 100, 1000 and
//!   10000 output times, for the growth of the cost with the table's size;
//!   `T3friction_pair` (only when named) the frictional table's every-column
//!   call against its θ-only call in alternation (`CYLROLL_BENCH_PAIRS`
//!   pairs, 15 by default).
//!
//! The benchmark runs on the command's allocator (mimalloc for Rust's
//! allocations and, through [`cylroll::allocator`], GMP's), so that it times
//! the library as the command runs it.
//!
//! T1, T2, T2b (and the proved T1r, T2r) ask the energy route of the ideal
//! model directly: "warm" reuses one `Oracle` (its node caches filled by the
//! first call), as the anchors reuse their integrator objects; "cold" is a
//! fresh `Oracle`. T3 and T3rows time what a user gets for a table:
//! `oracle::theta_at_times` and `oracle::trajectory` on the `Model` (the
//! hybrid motion, verified at two precisions, every column of `cylroll
//! trajectory`), which keep no state between calls (warm = cold).
//!
//! The reference folder is `$CYLROLL_BENCH_REF` or `bench/anchors/ref`
//! relative to the crate.

use cylroll::exact::Exact;
use cylroll::model::{Contact, Floor, Ideal, Law, Model, Params, Start};
use cylroll::motion::Phase;
use cylroll::numeric::decimal::to_sig;
use cylroll::numeric::verify::Verified;
use cylroll::oracle::rigorous::Proved;
use cylroll::oracle::{self, Options, Oracle};
use rug::{Float, Rational};
use std::path::PathBuf;
use std::sync::OnceLock;
use std::time::Instant;

const DIGITS: [u32; 4] = [30, 100, 300, 1000];
const T3_DIGITS: [u32; 2] = [30, 100];
/// Output times of T3.
const T3_POINTS: usize = 1000;

struct Refs {
    t1: String,
    t2: String,
    t2b: String,
    t3_tend: String,
    t3: Vec<String>,
}

fn ref_dir() -> PathBuf {
    match std::env::var_os("CYLROLL_BENCH_REF") {
        Some(p) => PathBuf::from(p),
        None => PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("bench/anchors/ref"),
    }
}

fn refs() -> &'static Refs {
    static R: OnceLock<Refs> = OnceLock::new();
    R.get_or_init(|| {
        let dir = ref_dir();
        let path = dir.join("reference.json");
        let text = std::fs::read_to_string(&path)
            .unwrap_or_else(|e| panic!("{}: {e} (set CYLROLL_BENCH_REF)", path.display()));
        let j: serde_json::Value = serde_json::from_str(&text).expect("reference.json");
        let s = |a: &str, b: &str| j[a][b].as_str().expect("reference field").to_string();
        let table =
            std::fs::read_to_string(dir.join("T3_reference.txt")).expect("T3_reference.txt");
        let t3: Vec<String> = table.lines().map(|l| l.trim().to_string()).collect();
        assert_eq!(t3.len(), T3_POINTS, "T3_reference.txt rows");
        Refs {
            t1: s("T1", "mid"),
            t2: s("T2", "mid"),
            t2b: s("T2b", "mid"),
            t3_tend: s("T3", "t_end"),
            t3,
        }
    })
}

fn q(s: &str) -> Exact {
    Exact::parse("x", s, false).expect("exact")
}

/// Identical solid cylinders, both rolling, from rest at θ0; `m2` the upper mass.
fn model(m2: i64, theta0: &str) -> Ideal {
    let mut p = Params::identical_solid();
    p.m2 = Rational::from(m2);
    Ideal::new(p, Floor::Roll, Contact::Roll, Start::rest(q(theta0))).expect("model")
}

/// T3's θ column and phases, checked: every θ the reference's rounding with
/// all `digits` digits verified, every row with both contacts rolling (t_end
/// is before separation).
fn check_t3(task: &str, theta: &[&Verified], phases: &[Phase], digits: u32) {
    let r = refs();
    assert_eq!(theta.len(), T3_POINTS, "{task}: rows");
    assert_eq!(phases.len(), T3_POINTS, "{task}: phases");
    let rolling = Phase::parse("stick/stick").expect("tag");
    for (i, (v, ph)) in theta.iter().zip(phases).enumerate() {
        check(&format!("{task} row {i}"), v, &r.t3[i], digits);
        assert_eq!(*ph, rolling, "{task} row {i}: phase");
    }
}

/// `reference` (a long decimal) rounded to `digits` significant digits.
fn rounded(reference: &str, digits: u32) -> String {
    let f = Float::with_val(digits * 4 + 64, Float::parse(reference).expect("decimal"));
    to_sig(&f, digits)
}

fn check(task: &str, v: &Verified, reference: &str, digits: u32) {
    assert_eq!(
        v.digits, digits,
        "{task} at {digits} digits: digits verified"
    );
    assert_eq!(
        v.text,
        rounded(reference, digits),
        "{task} at {digits} digits"
    );
}

/// A proved value: all `digits` digits proved, the text the reference
/// rounded, and the enclosure containing the (1100-digit) reference.
fn check_proved(task: &str, v: &Proved, reference: &str, digits: u32) {
    check(task, &v.shown, reference, digits);
    let p = v.iv.prec();
    let want = Float::with_val(p.max(4000), Float::parse(reference).expect("decimal"));
    // the reference's own last digit: a margin of 10^-1050
    let tol = Float::with_val(64, Float::i_pow_u(10, 1050)).recip();
    let lo = Float::with_val(p.max(4000), &v.iv.lo - &tol);
    let hi = Float::with_val(p.max(4000), &v.iv.hi + &tol);
    assert!(
        lo <= want && want <= hi,
        "{task} at {digits} digits: the enclosure misses the reference"
    );
}

fn t3_times() -> Vec<Exact> {
    t3_times_n(T3_POINTS)
}

/// `n` equally spaced times from 0 to T3's t_end (both included).
fn t3_times_n(n: usize) -> Vec<Exact> {
    let tend = q(&refs().t3_tend).coef;
    (0..n)
        .map(|i| Exact::rational(&tend * Rational::from((i as i64, n as i64 - 1))))
        .collect()
}

/// Table sizes of the `T3n` task (cost against the number of output times).
const T3N_POINTS: [usize; 4] = [10, 100, 1000, 10000];

// ---------------------------------------------------------------- the tasks

struct Task {
    name: &'static str,
    /// The energy route of the ideal model (T1, T2, T2b, T1r, T2r).
    oracle: Oracle,
    /// The model a user asks about (T3, T3rows).
    model: Model,
    opts: Options,
    times: Vec<Exact>,
}

impl Task {
    fn new(name: &'static str, digits: u32) -> Task {
        let (m2, theta0) = match name {
            "T1" | "T1r" | "T3" | "T3rows" => (1, "1/10"),
            "T2" | "T2r" => (1, "0"),
            "T2b" => (2, "0"),
            _ => panic!("unknown task {name}"),
        };
        let times = if name.starts_with("T3") {
            t3_times()
        } else {
            Vec::new()
        };
        let ideal = model(m2, theta0);
        Task {
            name,
            oracle: Oracle::new(&ideal, digits).expect("oracle"),
            model: Model::from_ideal(&ideal),
            opts: Options::digits(digits),
            times,
        }
    }

    /// One run of the task; returns a short value for the record.
    fn run(&mut self) -> String {
        match self.name {
            "T1" => self.oracle.time_at(&q("9/10")).expect("T1").text,
            "T2" | "T2b" => self.oracle.separation_angle().expect("T2").text,
            "T1r" => self.proved_t1().shown.text,
            "T2r" => self.proved_t2().shown.text,
            "T3" => {
                let (th, _) =
                    oracle::theta_at_times(&self.model, &self.times, &self.opts).expect("T3");
                th[T3_POINTS - 1].text.clone()
            }
            "T3rows" => {
                let a = oracle::trajectory(&self.model, &self.times, &self.opts).expect("T3rows");
                a.rows[T3_POINTS - 1].values[1].text.clone()
            }
            _ => unreachable!(),
        }
    }

    /// The working precision of `--rigorous` (the command line's first try).
    fn rigorous_prec(&self) -> u32 {
        cylroll::numeric::bits_for_digits(self.oracle.digits()) + 32
    }

    /// T1 proved: the enclosure of t(9/10) (`time --rigorous`).
    fn proved_t1(&mut self) -> Proved {
        let p = self.rigorous_prec();
        self.oracle.rigorous_time(&q("9/10"), p).expect("T1r")
    }

    /// T2 proved: the enclosure of θs (`separation --rigorous`).
    fn proved_t2(&mut self) -> Proved {
        let p = self.rigorous_prec();
        self.oracle.rigorous_separation(p).expect("T2r").0
    }

    /// Runs once and checks every value against the references.
    fn run_checked(&mut self) {
        let d = self.oracle.digits();
        let r = refs();
        match self.name {
            "T1" => check(
                "T1",
                &self.oracle.time_at(&q("9/10")).expect("T1"),
                &r.t1,
                d,
            ),
            "T2" => check("T2", &self.oracle.separation_angle().expect("T2"), &r.t2, d),
            "T1r" => {
                let v = self.proved_t1();
                check_proved("T1r", &v, &r.t1, d);
            }
            "T2r" => {
                let v = self.proved_t2();
                check_proved("T2r", &v, &r.t2, d);
            }
            "T2b" => check(
                "T2b",
                &self.oracle.separation_angle().expect("T2b"),
                &r.t2b,
                d,
            ),
            "T3" => {
                let (th, phases) =
                    oracle::theta_at_times(&self.model, &self.times, &self.opts).expect("T3");
                check_t3("T3", &th.iter().collect::<Vec<_>>(), &phases, d);
            }
            "T3rows" => {
                let a = oracle::trajectory(&self.model, &self.times, &self.opts).expect("T3rows");
                let theta: Vec<&Verified> = a.rows.iter().map(|row| &row.values[1]).collect();
                let phases: Vec<Phase> = a.rows.iter().map(|row| row.phase).collect();
                check_t3("T3rows", &theta, &phases, d);
                for row in &a.rows {
                    assert_eq!(row.values.len(), cylroll::motion::COLUMNS.len());
                }
            }
            _ => unreachable!(),
        }
    }
}

// ---------------------------------------------------------------- divan

fn divan_task(bencher: divan::Bencher, name: &'static str, digits: u32) {
    let mut task = Task::new(name, digits);
    task.run_checked();
    bencher.bench_local(|| task.run());
}

#[divan::bench(args = DIGITS, sample_count = 10, sample_size = 1)]
fn t1(bencher: divan::Bencher, digits: u32) {
    divan_task(bencher, "T1", digits);
}

#[divan::bench(args = DIGITS, sample_count = 20, sample_size = 1)]
fn t2(bencher: divan::Bencher, digits: u32) {
    divan_task(bencher, "T2", digits);
}

#[divan::bench(args = DIGITS, sample_count = 20, sample_size = 1)]
fn t2b(bencher: divan::Bencher, digits: u32) {
    divan_task(bencher, "T2b", digits);
}

#[divan::bench(args = DIGITS, sample_count = 10, sample_size = 1)]
fn t1_rigorous(bencher: divan::Bencher, digits: u32) {
    divan_task(bencher, "T1r", digits);
}

#[divan::bench(args = DIGITS, sample_count = 20, sample_size = 1)]
fn t2_rigorous(bencher: divan::Bencher, digits: u32) {
    divan_task(bencher, "T2r", digits);
}

#[divan::bench(args = T3_DIGITS, sample_count = 5, sample_size = 1)]
fn t3(bencher: divan::Bencher, digits: u32) {
    divan_task(bencher, "T3", digits);
}

#[divan::bench(args = T3_DIGITS, sample_count = 3, sample_size = 1)]
fn t3_rows(bencher: divan::Bencher, digits: u32) {
    divan_task(bencher, "T3rows", digits);
}

/// The frictional main case: μ = 0.3 at both contacts, from rest at θ0 =
/// 1/10, 1000 equally spaced times from 0 to separation (t_s rounded down to
/// 3 decimals), through the stick and slip phases.
fn friction_case() -> (Model, Vec<Exact>) {
    let mu = || Law::parse_mu("mu", "0.3").expect("mu");
    let m = Model::from_ideal(&model(1, "1/10"))
        .with_laws(mu(), mu())
        .expect("model");
    // t_s = 4.92058… (golden/data/main_mu_0_3.json)
    let end = Rational::from((4920, 1000));
    let times: Vec<Exact> = (0..T3_POINTS)
        .map(|i| Exact::rational(&end * Rational::from((i as i64, T3_POINTS as i64 - 1))))
        .collect();
    (m, times)
}

/// The frictional table's θ column and phases, checked once before timing:
/// every θ with all `digits` digits verified, the contact sticking and then
/// slipping (onset at t = 4.156, golden/data/main_mu_0_3.json), never in
/// flight (the last time is before separation), and θ(4.92) the separation
/// state of the independent derivation (tests/fixtures/friction_independent.toml,
/// [main_b2]) carried back by Δt = t_s − 4.92 ≈ 5.9e-4: θs − θ̇s Δt, to the
/// second-order term θ̈ Δt²/2 < 1e-6.
fn check_friction_theta(theta: &[&Verified], phases: &[Phase], digits: u32) {
    assert_eq!(theta.len(), T3_POINTS);
    assert_eq!(phases.len(), T3_POINTS);
    for v in theta {
        assert_eq!(v.digits, digits, "{}", v.text);
    }
    let stick = Phase::parse("stick/stick").expect("tag");
    let slip = Phase::parse("stick/slip+").expect("tag");
    let first_slip = phases
        .iter()
        .position(|p| *p == slip)
        .expect("a slip phase");
    assert!(phases[..first_slip].iter().all(|p| *p == stick));
    assert!(phases[first_slip..].iter().all(|p| *p == slip));
    // the row at t = 4.156… · 999/4.92 ≈ 843.9: the onset is between rows 843 and 844
    assert_eq!(first_slip, 844, "slip onset");
    let (theta_s, theta_dot_s, t_s) = (
        0.912_091_565_684_723_3,
        0.553_214_745_511_575_5,
        4.920_586_699_027_24,
    );
    let want = theta_s - theta_dot_s * (t_s - 4.92);
    let last = theta[T3_POINTS - 1].value.to_f64();
    assert!(
        (last - want).abs() < 1e-6,
        "theta(4.92) = {last}, want {want}"
    );
}

/// T3 with friction (issue: within 10× of T3 at the same digits): θ at the
/// 1000 times, verified.
#[divan::bench(args = T3_DIGITS, sample_count = 3, sample_size = 1)]
fn t3_friction(bencher: divan::Bencher, digits: u32) {
    let (m, times) = friction_case();
    let opts = Options::digits(digits);
    let (th, phases) = oracle::theta_at_times(&m, &times, &opts).expect("theta");
    check_friction_theta(&th.iter().collect::<Vec<_>>(), &phases, digits);
    bencher.bench_local(|| {
        let (th, _) = oracle::theta_at_times(&m, &times, &opts).expect("theta");
        assert_eq!(th.len(), T3_POINTS);
        th[T3_POINTS - 1].text.clone()
    });
}

/// T3rows with friction: every column of `cylroll trajectory` at the 1000
/// times, verified.
#[divan::bench(args = T3_DIGITS, sample_count = 3, sample_size = 1)]
fn t3_friction_rows(bencher: divan::Bencher, digits: u32) {
    let (m, times) = friction_case();
    let opts = Options::digits(digits);
    let a = oracle::trajectory(&m, &times, &opts).expect("trajectory");
    let theta: Vec<&Verified> = a.rows.iter().map(|r| &r.values[1]).collect();
    let phases: Vec<Phase> = a.rows.iter().map(|r| r.phase).collect();
    check_friction_theta(&theta, &phases, digits);
    bencher.bench_local(|| {
        let t = oracle::trajectory(&m, &times, &opts).expect("trajectory");
        assert_eq!(t.rows.len(), T3_POINTS);
        t.rows[T3_POINTS - 1].phase.tag()
    });
}

// ---------------------------------------------------------------- CPU mode

#[repr(C)]
struct Timespec {
    tv_sec: i64,
    tv_nsec: i64,
}

extern "C" {
    fn clock_gettime(clock: i32, ts: *mut Timespec) -> i32;
}

/// CPU time of this thread in seconds (`clock_gettime(CLOCK_THREAD_CPUTIME_ID)`,
/// Linux x86_64/aarch64; NaN if the call fails).
fn cpu_now() -> f64 {
    const CLOCK_THREAD_CPUTIME_ID: i32 = 3;
    let mut ts = Timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid, writable timespec for the duration of the call.
    let rc = unsafe { clock_gettime(CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    if rc != 0 {
        return f64::NAN;
    }
    ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        (v[n / 2 - 1] + v[n / 2]) / 2.0
    }
}

/// CPU and wall seconds per call of `run`, each sample the mean of `batch`
/// calls: at least 5 samples, then more until 10 s have passed or there are 15.
fn samples(batch: usize, mut run: impl FnMut()) -> (Vec<f64>, Vec<f64>) {
    let (min_runs, max_runs, budget) = (5usize, 15usize, 10.0f64);
    let mut cpus = Vec::new();
    let mut walls = Vec::new();
    let start = Instant::now();
    while cpus.len() < max_runs && (cpus.len() < min_runs || start.elapsed().as_secs_f64() < budget)
    {
        let (c, w) = (cpu_now(), Instant::now());
        for _ in 0..batch {
            run();
        }
        cpus.push((cpu_now() - c) / batch as f64);
        walls.push(w.elapsed().as_secs_f64() / batch as f64);
    }
    (cpus, walls)
}

/// The `T3n` task: T3 at 30 and 100 digits with `n` output times; θ(t_end)
/// (the last time for every n) is checked against the reference first.
fn cpu_t3n(digits: u32, n: usize) {
    let m = Model::from_ideal(&model(1, "1/10"));
    let opts = Options::digits(digits);
    let times = t3_times_n(n);
    let (th, _) = oracle::theta_at_times(&m, &times, &opts).expect("T3n");
    check("T3n", &th[n - 1], &refs().t3[T3_POINTS - 1], digits);
    let (cpus, _) = samples(1, || {
        std::hint::black_box(oracle::theta_at_times(&m, &times, &opts).expect("T3n"));
    });
    println!(
        "{{\"tool\":\"cylroll\",\"task\":\"T3n\",\"digits\":{digits},\"points\":{n},\"cpu_median_s\":{:.6e},\"samples\":{},\"checked\":true}}",
        median(cpus.clone()),
        cpus.len()
    );
}

/// Times `name` at `digits`: the cold first call (fresh oracle), a check of
/// every value, then warm repeats (batched so each sample lasts ≥ 2 ms) until
/// `min_runs` samples and `budget` seconds, or `max_runs` samples.
fn cpu_task(name: &'static str, digits: u32) {
    let (c0, w0) = (cpu_now(), Instant::now());
    let mut task = Task::new(name, digits);
    let value = task.run();
    let (cold_cpu, cold_wall) = (cpu_now() - c0, w0.elapsed().as_secs_f64());
    task.run_checked();
    // batch size: enough calls for ≥ 2 ms per sample
    let c = cpu_now();
    task.run();
    let one = (cpu_now() - c).max(1e-7);
    let batch = ((2e-3 / one).ceil() as usize).clamp(1, 10_000);
    let (cpus, walls) = samples(batch, || {
        std::hint::black_box(task.run());
    });
    let short: String = value.chars().take(40).collect();
    println!(
        "{{\"tool\":\"cylroll\",\"task\":\"{name}\",\"digits\":{digits},\"cpu_median_s\":{:.6e},\
         \"wall_median_s\":{:.6e},\"cpu_min_s\":{:.6e},\"cold_cpu_s\":{:.6e},\"cold_wall_s\":{:.6e},\
         \"samples\":{},\"batch\":{batch},\"checked\":true,\"value\":\"{short}\"}}",
        median(cpus.clone()),
        median(walls),
        cpus.iter().cloned().fold(f64::INFINITY, f64::min),
        cold_cpu,
        cold_wall,
        cpus.len(),
    );
}

/// The frictional table's every-column call against its θ-only call, in
/// alternation (`pairs` pairs, at least 1, after one call of each; the
/// order within a pair alternates, θ first in the even pairs, so that
/// neither call always follows the other): CPU medians of each and their
/// ratio, with the pairs' own ratios' range — the library's side of the
/// every-column target (within 2× of θ only).
fn cpu_friction_pair(digits: u32, pairs: usize) {
    let pairs = pairs.max(1);
    let (m, times) = friction_case();
    let opts = Options::digits(digits);
    let (th, phases) = oracle::theta_at_times(&m, &times, &opts).expect("theta");
    check_friction_theta(&th.iter().collect::<Vec<_>>(), &phases, digits);
    // the table's θ column and phases are the θ-only call's (its own route)
    let table = oracle::trajectory(&m, &times, &opts).expect("trajectory");
    assert_eq!(table.rows.len(), T3_POINTS);
    for ((row, t), p) in table.rows.iter().zip(&th).zip(&phases) {
        assert_eq!(row.values[1].text, t.text, "theta at a table row");
        assert_eq!(row.phase, *p);
    }
    let (mut a, mut b) = (Vec::new(), Vec::new());
    let theta = |a: &mut Vec<f64>| {
        let c = cpu_now();
        std::hint::black_box(oracle::theta_at_times(&m, &times, &opts).expect("theta"));
        a.push(cpu_now() - c);
    };
    let rows = |b: &mut Vec<f64>| {
        let c = cpu_now();
        std::hint::black_box(oracle::trajectory(&m, &times, &opts).expect("trajectory"));
        b.push(cpu_now() - c);
    };
    for i in 0..pairs {
        if i % 2 == 0 {
            theta(&mut a);
            rows(&mut b);
        } else {
            rows(&mut b);
            theta(&mut a);
        }
    }
    let ratios: Vec<f64> = a.iter().zip(&b).map(|(x, y)| y / x).collect();
    let lo = ratios.iter().cloned().fold(f64::INFINITY, f64::min);
    let hi = ratios.iter().cloned().fold(0.0, f64::max);
    let (ma, mb) = (median(a), median(b));
    println!(
        "{{\"tool\":\"cylroll\",\"task\":\"T3friction_pair\",\"digits\":{digits},\"pairs\":{pairs},\
         \"theta_cpu_median_s\":{ma:.6e},\"rows_cpu_median_s\":{mb:.6e},\"ratio\":{:.4},\
         \"pair_ratio_min\":{lo:.4},\"pair_ratio_max\":{hi:.4},\"checked\":true}}",
        mb / ma
    );
}

fn cpu_main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    let wanted = |t: &str| args.is_empty() || args.iter().any(|a| a == t);
    let digits: Vec<u32> = match std::env::var("CYLROLL_BENCH_DIGITS") {
        Ok(s) => s.split(',').filter_map(|x| x.trim().parse().ok()).collect(),
        Err(_) => DIGITS.to_vec(),
    };
    if args.iter().any(|a| a == "T3n") {
        for &d in &digits {
            if T3_DIGITS.contains(&d) {
                for n in T3N_POINTS {
                    cpu_t3n(d, n);
                }
            }
        }
    }
    if args.iter().any(|a| a == "T3friction_pair") {
        let pairs = match std::env::var("CYLROLL_BENCH_PAIRS") {
            Ok(s) => s.trim().parse().unwrap_or_else(|_| {
                panic!("CYLROLL_BENCH_PAIRS={s:?}: a whole number of pairs is allowed")
            }),
            Err(_) => 15,
        };
        for &d in &digits {
            if T3_DIGITS.contains(&d) {
                cpu_friction_pair(d, pairs);
            }
        }
    }
    for name in ["T1", "T2", "T2b", "T1r", "T2r", "T3", "T3rows"] {
        if !wanted(name) {
            continue;
        }
        for &d in &digits {
            if name.starts_with("T3") && !T3_DIGITS.contains(&d) {
                continue;
            }
            cpu_task(name, d);
        }
    }
}

/// The command's allocator (src/main.rs), so that the library is timed as
/// the command runs it: mimalloc for Rust's allocations and GMP's.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    // SAFETY: first thing in main, before any big number or other thread
    unsafe { cylroll::allocator::use_mimalloc_for_gmp() };
    if std::env::var("CYLROLL_BENCH").as_deref() == Ok("cpu") {
        cpu_main();
    } else {
        divan::main();
    }
}
