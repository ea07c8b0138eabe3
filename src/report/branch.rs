//! The data of the branch figure: the main case from θ₀ = 1/10 on both
//! branches, and along the closed branch N₁₂ with the free relative normal
//! acceleration a = r θ̇² − g cos θ, which turns positive at θ*.

use super::track::{track, Track};
use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::model::Model;
use crate::motion::Branch;
use crate::oracle::{self, Options};
use rug::{Integer, Rational};

/// What the branch figure shows.
#[derive(Debug, Clone)]
pub struct BranchData {
    /// θ* (the stay answer's `theta_indeterminate`).
    pub star: f64,
    /// θs on the stay branch.
    pub theta_s: f64,
    /// Along the closed branch: (θ, N₁₂, a).
    pub closed: Vec<(f64, f64, f64)>,
    /// The motion on the `stay` branch.
    pub stay: Track,
    /// The motion on the `part` branch.
    pub part: Track,
    /// r₁ and r = r₁ + r₂ (the gap between the surfaces is the distance of
    /// the centres less r; cylinder 1's centre stays at height r₁).
    pub radii: (f64, f64),
}

impl BranchData {
    /// The gap between the cylinders' surfaces along a track, in units of
    /// r₁ (0 while they touch).
    pub fn gap(&self, tr: &Track) -> (Vec<(f64, f64)>, Vec<String>) {
        use crate::motion::point::col;
        let (x1, x2, y2) = (col!("x1"), col!("x2"), col!("y2"));
        let (r1, r) = self.radii;
        tr.map(|v| ((v[x2] - v[x1]).hypot(v[y2] - r1) - r) / r1)
    }
}

/// The main case from θ₀ = [`super::data::THETA0_TIME`].
pub fn main_model() -> Result<Model> {
    Ok(Model::paper_default(Exact::parse(
        "theta0",
        super::data::THETA0_TIME,
        false,
    )?))
}

/// Computes the branch figure's data at `digits`, `n` intervals per curve.
pub fn compute(digits: u32, n: usize, stay: Option<Track>) -> Result<BranchData> {
    let model = main_model()?;
    let opts = Options::digits(digits);
    let stay = match stay {
        Some(t) => t,
        None => track(&model, &opts, n, None)?,
    };
    let mut popts = opts.clone();
    popts.branch = Branch::Part;
    let part = track(&model, &popts, n, None)?;
    let star = stay
        .value("theta_indeterminate")
        .ok_or_else(|| Error::not_physical("the main case has no branch point"))?;
    let theta_s = stay
        .value("theta_s")
        .ok_or_else(|| Error::not_physical("the main case does not separate"))?;
    // angles from θ0 to just below θs, with θ* itself among them
    let th0 = 0.1;
    let mut angles: Vec<Rational> = (0..=n)
        .map(|i| {
            let x = th0 + (theta_s - th0) * i as f64 / n as f64;
            let k = (x * 1e6).floor() as i64 - i64::from(i == n);
            Rational::from((Integer::from(k), Integer::from(1_000_000)))
        })
        .collect();
    if let Some(v) = stay.answer.value("theta_indeterminate") {
        if let Some(r) = Exact::parse("theta", &v.text, false)?.as_rational() {
            angles.push(r.clone());
        }
    }
    angles.sort();
    angles.dedup();
    let r = model.params().r().to_f64();
    let g = model.params().g.to_f64();
    let mut closed = Vec::new();
    for a in angles {
        let th = Exact::rational(a);
        let f = oracle::forces(&model, &th, &opts)?;
        let get = |k: &str| f.value(k).map_or(f64::NAN, |v| v.value.to_f64());
        let (n12, thd) = (get("N12"), get("theta_dot"));
        let x = th.to_f64();
        closed.push((x, n12, r * thd * thd - g * x.cos()));
    }
    Ok(BranchData {
        star,
        theta_s,
        closed,
        stay,
        part,
        radii: (model.params().r1.to_f64(), r),
    })
}
