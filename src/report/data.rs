//! The numbers behind the report: every plotted point and every table entry
//! is an oracle answer ([`Verified`]); the work is split into jobs that run on
//! a few threads and land in fixed slots, so the result does not depend on
//! the scheduling.

use super::Config;
use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::model::{Contact, Floor, Ideal, Params, Start};
use crate::numeric::verify::Verified;
use crate::oracle::{Oracle, Separation};
use indicatif::ProgressBar;
use rug::{Integer, Rational};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

pub use crate::model::VARIANTS;

/// Short name of a variant, e.g. `floor roll, contact slip`.
pub fn variant_name(v: (Floor, Contact)) -> String {
    format!("floor {}, contact {}", v.0, v.1)
}

/// File-name stem of a variant, e.g. `roll_slip`.
pub fn variant_stem(v: (Floor, Contact)) -> String {
    format!("{}_{}", v.0, v.1)
}

/// Where the paper treats the variant.
pub fn paper_ref(v: (Floor, Contact)) -> &'static str {
    match v {
        (Floor::Roll, Contact::Roll) => "§2 (main case)",
        (Floor::Slip, Contact::Slip) => "§3.1",
        (Floor::Slip, Contact::Roll) => "§3.2",
        (Floor::Roll, Contact::Slip) => "§3.3",
        (Floor::Fixed, Contact::Roll) => "footnote 8, eq. (36)",
        (Floor::Fixed, Contact::Slip) => "end of §3.1 and §3.3",
    }
}

/// The start angle of the time plots and its text.
pub const THETA0_TIME: &str = "1/10";
/// Starts of the separation table: the limit from rest at the top, and two
/// small angles (from rest).
pub const TABLE_STARTS: [&str; 3] = ["0", "1/100", "1/20"];
/// Angles of the force table (main case, from rest at the top).
pub const FORCE_ANGLES: [&str; 4] = ["pi/12", "pi/6", "pi/4", "1"];
/// Friction coefficients of the slip table (main case).
pub const MU_VALUES: [&str; 6] = ["0.05", "0.1", "0.2", "0.3", "0.5", "1"];
/// Mass ratios of the parameter-plane table.
pub const PLANE_TABLE_RATIOS: [&str; 5] = ["0.1", "0.5", "1", "2", "10"];
/// k2 values of the parameter-plane table and of the curve families.
pub const PLANE_K2: [&str; 5] = ["0", "0.25", "0.5", "1", "2"];

fn exact(name: &str, text: &str) -> Result<Exact> {
    Exact::parse(name, text, true)
}

fn rational(name: &str, text: &str) -> Result<Rational> {
    let e = Exact::parse(name, text, false)?;
    e.as_rational()
        .cloned()
        .ok_or_else(|| Error::invalid(name, text, "must be rational"))
}

/// Identical solid cylinders with the given contact model, from rest at θ0.
pub fn variant_model(v: (Floor, Contact), theta0: &str) -> Result<Ideal> {
    Ideal::new(
        Params::identical_solid(),
        v.0,
        v.1,
        Start::rest(exact("theta0", theta0)?),
    )
}

/// The parameter plane's model: m1 = r1 = r2 = g = 1, k1 = 1/2, m2 = ratio,
/// k2 as given, from rest at the top.
pub fn plane_model(floor: Floor, ratio: &str, k2: &str) -> Result<Ideal> {
    let mut p = Params::identical_solid();
    p.m2 = rational("m2", ratio)?;
    p.k2 = rational("k2", k2)?;
    Ideal::new(p, floor, Contact::Roll, Start::rest(Exact::zero()))
}

/// A rational just below `x`: ⌊x·10⁶⌋/10⁶ − 10⁻⁶ (for grids that must stay
/// inside the motion).
fn below(x: f64) -> Rational {
    let n = (x * 1e6).floor() as i64 - 1;
    Rational::from((Integer::from(n.max(0)), Integer::from(1_000_000)))
}

/// The motion of one variant from rest at θ0 = [`THETA0_TIME`], sampled
/// at its events (the main case to its first impact, the others to their
/// separation).
#[derive(Debug, Clone)]
pub struct TimeCurve {
    /// The track.
    pub track: super::track::Track,
    /// Points that could not be verified (none: the trajectory is verified
    /// whole or not at all).
    pub skipped: Vec<(String, String)>,
}

/// Forces against θ for one variant from rest at the top (θ0 → 0+), at
/// `points + 1` equally spaced angles from 0 to just before θs.
#[derive(Debug, Clone)]
pub struct ThetaCurve {
    /// Separation (at the plot digits).
    pub sep: Separation,
    /// Rows: θ, then the [`crate::oracle::FORCE_KEYS`] values.
    pub rows: Vec<Vec<f64>>,
    /// The branch point θ* (None: the motion is unique up to θs).
    pub star: Option<f64>,
    /// Points that could not be verified (θ, error), left out.
    pub skipped: Vec<(String, String)>,
}

/// One point of the parameter plane.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub struct PlaneKey {
    /// Floor model (roll, or fixed for the fixed-lower check).
    pub floor: FloorKey,
    /// m2/m1, exact text.
    pub ratio: String,
    /// k2, exact text.
    pub k2: String,
    /// Digits requested.
    pub digits: u32,
}

/// Floor as an ordered key.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum FloorKey {
    /// Rolling floor.
    Roll,
    /// Fixed lower cylinder.
    Fixed,
}

impl FloorKey {
    fn floor(self) -> Floor {
        match self {
            FloorKey::Roll => Floor::Roll,
            FloorKey::Fixed => Floor::Fixed,
        }
    }
}

/// A unit of work.
#[derive(Debug, Clone)]
enum Job {
    Time(usize),
    Theta(usize),
    Sep(usize, &'static str),
    Forces,
    Mu,
    Plane(Vec<PlaneKey>),
}

impl Job {
    /// Oracle calls the job makes (for the progress bar).
    fn weight(&self, cfg: &Config) -> u64 {
        match self {
            Job::Time(_) => cfg.time_points as u64 + 2,
            Job::Theta(_) => cfg.theta_points as u64 + 2,
            Job::Sep(..) => 1,
            Job::Forces => FORCE_ANGLES.len() as u64,
            Job::Mu => MU_VALUES.len() as u64,
            Job::Plane(k) => k.len() as u64,
        }
    }
}

enum Out {
    Time(Box<Result<TimeCurve>>),
    Theta(Result<ThetaCurve>),
    Sep(Result<Separation>),
    Forces(Vec<Result<Vec<Verified>>>),
    Mu(Vec<Result<Separation>>),
    Plane(Vec<Result<Verified>>),
}

/// Everything the report shows.
pub struct Data {
    /// Per variant ([`VARIANTS`] order): the trajectory from θ0 = 1/100.
    pub time: Vec<Result<TimeCurve>>,
    /// Per variant: forces against θ from rest at the top.
    pub theta: Vec<Result<ThetaCurve>>,
    /// Per variant, per start of [`TABLE_STARTS`]: the separation at the
    /// table digits.
    pub sep: Vec<Vec<Result<Separation>>>,
    /// Main case, per angle of [`FORCE_ANGLES`]: the forces at the table digits.
    pub forces: Vec<Result<Vec<Verified>>>,
    /// Main case, per μ of [`MU_VALUES`]: the separation with slip angles.
    pub mu: Vec<Result<Separation>>,
    /// θs at every parameter-plane point asked for.
    pub plane: std::collections::BTreeMap<PlaneKey, Result<Verified>>,
    /// Digits verified for the plotted points.
    pub plot_digits: u32,
    /// Digits of the tables.
    pub table_digits: u32,
}

/// Runs `f` on every job on `threads` threads; results in job order.
fn par_map<J: Sync, R: Send>(
    jobs: &[J],
    threads: usize,
    f: impl Fn(&J) -> R + Sync,
) -> Result<Vec<R>> {
    let next = AtomicUsize::new(0);
    let slots: Vec<Mutex<Option<R>>> = jobs.iter().map(|_| Mutex::new(None)).collect();
    let workers = threads.clamp(1, jobs.len().max(1));
    std::thread::scope(|s| {
        for _ in 0..workers {
            s.spawn(|| {
                // MPFR's per-thread caches outlive the thread otherwise
                let _caches = crate::numeric::ThreadCaches;
                loop {
                    let i = next.fetch_add(1, Ordering::SeqCst);
                    if i >= jobs.len() {
                        break;
                    }
                    let r = f(&jobs[i]);
                    let mut slot = slots[i].lock().unwrap_or_else(|e| e.into_inner());
                    *slot = Some(r);
                }
            });
        }
    });
    slots
        .into_iter()
        .enumerate()
        .map(|(i, m)| {
            m.into_inner()
                .unwrap_or_else(|e| e.into_inner())
                .ok_or_else(|| Error::not_physical(format!("report job {i} produced no result")))
        })
        .collect()
}

/// The parameter-plane points the figures and tables need.
pub fn plane_keys(cfg: &Config) -> Vec<PlaneKey> {
    let mut keys = std::collections::BTreeSet::new();
    let pd = cfg.plot_digits;
    let roll = |ratio: String, k2: String, digits: u32| PlaneKey {
        floor: FloorKey::Roll,
        ratio,
        k2,
        digits,
    };
    // curves θs(m2/m1) for the k2 of PLANE_K2
    for r in log_grid(cfg.ratio_range.0, cfg.ratio_range.1, cfg.ratio_per_decade) {
        for k in PLANE_K2 {
            keys.insert(roll(r.clone(), k.to_string(), pd));
        }
    }
    // curves θs(k2) for the ratios of PLANE_TABLE_RATIOS, and the fixed lower cylinder
    for k in k2_grid(cfg.k2_steps) {
        for r in PLANE_TABLE_RATIOS {
            keys.insert(roll(r.to_string(), k.clone(), pd));
        }
        keys.insert(PlaneKey {
            floor: FloorKey::Fixed,
            ratio: "1".into(),
            k2: k.clone(),
            digits: pd,
        });
    }
    // heat map nodes
    for r in log_grid(
        cfg.heat_ratio_range.0,
        cfg.heat_ratio_range.1,
        cfg.heat_per_decade,
    ) {
        for k in k2_grid(cfg.heat_k2_steps) {
            keys.insert(roll(r.clone(), k, pd));
        }
    }
    // the table
    for r in PLANE_TABLE_RATIOS {
        for k in PLANE_K2 {
            keys.insert(roll(r.to_string(), k.to_string(), cfg.plane_table_digits));
        }
    }
    for k in PLANE_K2 {
        keys.insert(PlaneKey {
            floor: FloorKey::Fixed,
            ratio: "1".into(),
            k2: k.to_string(),
            digits: cfg.digits,
        });
    }
    keys.into_iter().collect()
}

/// Exact texts of 10^(j/n), rounded to 3 significant digits, from 10^lo to
/// 10^hi (decades as integers).
pub fn log_grid(lo: i32, hi: i32, per_decade: usize) -> Vec<String> {
    let n = per_decade.max(1) as i32;
    (lo * n..=hi * n)
        .map(|j| {
            if j % n == 0 {
                pow10_text(j / n)
            } else {
                let v = 10f64.powf(f64::from(j) / f64::from(n));
                format!("{v:.2e}")
            }
        })
        .collect()
}

fn pow10_text(e: i32) -> String {
    if e >= 0 {
        format!("1{}", "0".repeat(e as usize))
    } else {
        format!("0.{}1", "0".repeat((-e - 1) as usize))
    }
}

/// Exact texts of k2 = 2 i/steps, i = 0..=steps.
pub fn k2_grid(steps: usize) -> Vec<String> {
    let s = steps.max(1);
    (0..=s)
        .map(|i| crate::exact::rational_text(&Rational::from((2 * i as i64, s as i64))))
        .collect()
}

/// The value of an exact text as f64 (for plotting only).
pub fn text_f64(text: &str) -> f64 {
    Exact::parse("x", text, true)
        .map(|e| e.to_f64())
        .unwrap_or(f64::NAN)
}

fn time_curve(v: usize, cfg: &Config, pb: &ProgressBar) -> Result<TimeCurve> {
    let model = crate::model::Model::from_ideal(&variant_model(VARIANTS[v], THETA0_TIME)?);
    let opts = crate::oracle::Options::digits(cfg.plot_digits);
    let until = if v == 0 {
        None
    } else {
        Some(crate::motion::Kind::Separation)
    };
    let track = super::track::track(&model, &opts, cfg.time_points, until)?;
    pb.inc(cfg.time_points as u64 + 2);
    Ok(TimeCurve {
        track,
        skipped: Vec::new(),
    })
}

fn theta_curve(v: usize, cfg: &Config, pb: &ProgressBar) -> Result<ThetaCurve> {
    let model = variant_model(VARIANTS[v], "0")?;
    let mut o = Oracle::new(&model, cfg.plot_digits)?;
    let sep = o.separation()?;
    let star = o.branch_point()?.map(|v| v.value.to_f64());
    pb.inc(1);
    let end = below(sep.theta_s.value.to_f64());
    let n = cfg.theta_points.max(1);
    let mut rows = Vec::new();
    let mut skipped = Vec::new();
    for i in 0..=n {
        let th = Exact::rational(&end * Rational::from((i as i64, n as i64)));
        match o.forces_at(&th) {
            Ok(f) => {
                let mut row = vec![th.to_f64()];
                row.extend(f.iter().map(|x| x.value.to_f64()));
                rows.push(row);
            }
            Err(e) => skipped.push((th.to_string(), e.to_string())),
        }
        pb.inc(1);
    }
    Ok(ThetaCurve {
        sep,
        rows,
        star,
        skipped,
    })
}

fn run_job(job: &Job, cfg: &Config, pb: &ProgressBar) -> Out {
    match job {
        Job::Time(v) => Out::Time(Box::new(time_curve(*v, cfg, pb))),
        Job::Theta(v) => Out::Theta(theta_curve(*v, cfg, pb)),
        Job::Sep(v, th0) => {
            let r = variant_model(VARIANTS[*v], th0)
                .and_then(|m| Oracle::new(&m, cfg.digits))
                .and_then(|mut o| o.separation());
            pb.inc(1);
            Out::Sep(r)
        }
        Job::Forces => {
            let mut oracle =
                variant_model(VARIANTS[0], "0").and_then(|m| Oracle::new(&m, cfg.digits));
            let mut out = Vec::new();
            for a in FORCE_ANGLES {
                let r = match oracle.as_mut() {
                    Ok(o) => exact("theta", a).and_then(|th| o.forces_at(&th)),
                    Err(e) => Err(e.clone()),
                };
                out.push(r);
                pb.inc(1);
            }
            Out::Forces(out)
        }
        Job::Mu => {
            let mut out = Vec::new();
            for mu in MU_VALUES {
                let r = variant_model(VARIANTS[0], "0")
                    .and_then(|m| Oracle::new(&m, cfg.digits))
                    .and_then(|o| o.with_mu(Some(exact("mu", mu)?)))
                    .and_then(|mut o| o.separation());
                out.push(r);
                pb.inc(1);
            }
            Out::Mu(out)
        }
        Job::Plane(keys) => {
            let mut out = Vec::new();
            for k in keys {
                let r = plane_model(k.floor.floor(), &k.ratio, &k.k2)
                    .and_then(|m| Oracle::new(&m, k.digits))
                    .and_then(|mut o| o.separation())
                    .map(|s| s.theta_s);
                out.push(r);
                pb.inc(1);
            }
            Out::Plane(out)
        }
    }
}

/// Computes everything, on `cfg.threads` threads, with progress on `pb`
/// (drawn if `show`).
pub fn compute(cfg: &Config, pb: &ProgressBar, show: bool) -> Result<Data> {
    let mut jobs = Vec::new();
    for v in 0..VARIANTS.len() {
        jobs.push(Job::Time(v));
    }
    for v in 0..VARIANTS.len() {
        jobs.push(Job::Theta(v));
    }
    let keys = plane_keys(cfg);
    for chunk in keys.chunks(24) {
        jobs.push(Job::Plane(chunk.to_vec()));
    }
    for v in 0..VARIANTS.len() {
        for th0 in TABLE_STARTS {
            jobs.push(Job::Sep(v, th0));
        }
    }
    jobs.push(Job::Forces);
    jobs.push(Job::Mu);
    pb.set_length(jobs.iter().map(|j| j.weight(cfg)).sum());
    super::show_progress(pb, show);

    let outs = par_map(&jobs, cfg.threads, |j| run_job(j, cfg, pb))?;

    let mut data = Data {
        time: Vec::new(),
        theta: Vec::new(),
        sep: (0..VARIANTS.len()).map(|_| Vec::new()).collect(),
        forces: Vec::new(),
        mu: Vec::new(),
        plane: std::collections::BTreeMap::new(),
        plot_digits: cfg.plot_digits,
        table_digits: cfg.digits,
    };
    let mut key_iter = keys.into_iter();
    for (job, out) in jobs.iter().zip(outs) {
        match (job, out) {
            (Job::Time(_), Out::Time(t)) => data.time.push(*t),
            (Job::Theta(_), Out::Theta(t)) => data.theta.push(t),
            (Job::Sep(v, _), Out::Sep(s)) => data.sep[*v].push(s),
            (Job::Forces, Out::Forces(f)) => data.forces = f,
            (Job::Mu, Out::Mu(m)) => data.mu = m,
            (Job::Plane(_), Out::Plane(vals)) => {
                for v in vals {
                    if let Some(k) = key_iter.next() {
                        data.plane.insert(k, v);
                    }
                }
            }
            _ => return Err(Error::not_physical("report job and result out of step")),
        }
    }
    Ok(data)
}
