//! What an event watches ([`Watch`]: a multiplier, a rate, a coordinate,
//! a linear combination of them, a height, a free normal acceleration), its
//! value at a sample (with one sine and cosine shared by every watch that
//! needs them) and its rate dg/dt there (a central difference along the
//! flow for a multiplier).

use super::Sample;
use crate::error::Result;
use crate::mechanics::system::{self as sy, System, Units};
use rug::Float;

/// What an event watches.
#[derive(Debug, Clone, PartialEq)]
pub enum Watch {
    /// The multiplier of constraint row i (a constraint force).
    Multiplier(usize),
    /// The rate q̇_i.
    Rate(usize),
    /// The coordinate q_i.
    Coord(usize),
    /// A linear combination of the above with constant coefficients (a
    /// slip velocity Σ c_i q̇_i, a friction cone μ N − F).
    Lin(Vec<(Watch, Float)>),
    /// q_i − value: a coordinate reaching a given value.
    Reach {
        /// Index of the coordinate.
        i: usize,
        /// The value.
        value: Float,
    },
    /// r θ̇² − g cos θ − a sin θ (θ = q_th, θ̇ = q̇_th): the relative normal
    /// acceleration of two centres at distance r along the line of centres
    /// θ if the upper body fell freely and the lower one accelerated
    /// horizontally by `a` (the free relative normal acceleration of a
    /// contact; positive: the free motion separates).
    FreeNormal {
        /// Index of θ.
        th: usize,
        /// r.
        r: Float,
        /// g.
        g: Float,
        /// The lower body's horizontal acceleration.
        a: Float,
    },
    /// offset + r cos q_th: a height above the floor of a point at distance
    /// r along the line of centres θ = q_th (e.g. cylinder 2's lowest point).
    Height {
        /// Index of θ.
        th: usize,
        /// r.
        r: Float,
        /// offset.
        offset: Float,
    },
}

impl Watch {
    /// The natural scale of the watched function in `u`: a force for a
    /// multiplier, a length or an angle (1) for a coordinate, that over the
    /// time unit for a rate, r/ts² for a free normal acceleration, the
    /// largest of its terms' for a combination. A threshold such as "this
    /// function starts at 0" is a small multiple of it, so that a motion in
    /// other units (g = 10^−40 or 10^40) takes the same decisions.
    pub fn scale(&self, u: &Units) -> Float {
        let p = u.ts.prec();
        let coord = |i: usize| {
            if sy::is_length(i) {
                u.r.clone()
            } else {
                Float::with_val(p, 1u32)
            }
        };
        match self {
            Watch::Multiplier(_) => u.force.clone(),
            Watch::Rate(i) => coord(*i) / &u.ts,
            Watch::Coord(i) | Watch::Reach { i, .. } => coord(*i),
            Watch::Lin(terms) => terms.iter().fold(Float::new(p), |m, (w, c)| {
                m.max(&(w.scale(u) * Float::with_val(p, c.abs_ref())))
            }),
            Watch::FreeNormal { .. } => Float::with_val(p, &u.r / &u.ts) / &u.ts,
            Watch::Height { .. } => u.r.clone(),
        }
    }
}

/// The value of a watched function at a sample.
/// Every watched function at a sample, with sin θ and cos θ computed once
/// for all the watches that need them (a height, a free normal
/// acceleration): at high precision a trigonometric call costs more than the
/// rest of a watch.
pub fn watch_values<'a>(watches: impl Iterator<Item = &'a Watch>, s: &Sample) -> Vec<Float> {
    let mut trig: Option<(usize, Float, Float)> = None;
    let mut sc = |th: usize| -> (Float, Float) {
        match &trig {
            Some((i, sn, cs)) if *i == th => (sn.clone(), cs.clone()),
            _ => {
                let p = s.q[th].prec();
                let (sn, cs) = s.q[th].clone().sin_cos(Float::new(p));
                trig = Some((th, sn.clone(), cs.clone()));
                (sn, cs)
            }
        }
    };
    watches
        .map(|w| match w {
            Watch::Height { th, r, offset } => {
                let (_, cs) = sc(*th);
                cs * r + offset
            }
            Watch::FreeNormal { th, r, g, a } => {
                let p = s.q[*th].prec();
                let (sn, cs) = sc(*th);
                let td2 = Float::with_val(p, s.v[*th].square_ref());
                Float::with_val(p, r * &td2)
                    - Float::with_val(p, g * &cs)
                    - Float::with_val(p, a * &sn)
            }
            other => watch_value(other, s),
        })
        .collect()
}

/// The watched function at a sample.
pub fn watch_value(w: &Watch, s: &Sample) -> Float {
    match w {
        Watch::Multiplier(i) => s.lambda[*i].clone(),
        Watch::Rate(i) => s.v[*i].clone(),
        Watch::Coord(i) => s.q[*i].clone(),
        Watch::Lin(terms) => {
            let mut acc = Float::new(s.t.prec().max(s.v[0].prec()));
            for (w, c) in terms {
                acc += watch_value(w, s) * c;
            }
            acc
        }
        Watch::Height { th, r, offset } => {
            let c = Float::with_val(s.q[*th].prec(), s.q[*th].cos_ref());
            c * r + offset
        }
        Watch::Reach { i, value } => Float::with_val(s.q[*i].prec(), &s.q[*i] - value),
        Watch::FreeNormal { th, r, g, a } => {
            let p = s.q[*th].prec();
            let (sn, cs) = s.q[*th].clone().sin_cos(Float::new(p));
            let td2 = Float::with_val(p, s.v[*th].square_ref());
            Float::with_val(p, r * &td2) - Float::with_val(p, g * &cs) - Float::with_val(p, a * &sn)
        }
    }
}

/// dg/dt of the watched function at a sample: q̈ or q̇ exactly; for a
/// multiplier, a central difference of λ along the flow with step
/// ε = 2^−(prec/3) (relative error about 2^−(2 prec/3)).
pub(super) fn rate_of(sys: &mut System, w: &Watch, s: &Sample) -> Result<Float> {
    let p = sys.prec;
    match w {
        Watch::Rate(i) => Ok(s.qdd[*i].clone()),
        Watch::Coord(i) | Watch::Reach { i, .. } => Ok(s.v[*i].clone()),
        Watch::Height { th, r, .. } => {
            let sn = Float::with_val(p, s.q[*th].sin_ref());
            Ok(-(sn * r * &s.v[*th]))
        }
        Watch::FreeNormal { th, r, g, a } => {
            // d/dt (r θ̇² − g cos θ − a sin θ) = θ̇ (2 r θ̈ + g sin θ − a cos θ)
            let (sn, cs) = s.q[*th].clone().sin_cos(Float::new(p));
            let inner = Float::with_val(p, r * &s.qdd[*th]) * 2u32 + Float::with_val(p, g * &sn)
                - Float::with_val(p, a * &cs);
            Ok(inner * &s.v[*th])
        }
        Watch::Multiplier(k) => Ok(lambda_rates(sys, s)?.swap_remove(*k)),
        Watch::Lin(terms) => {
            let mut acc = Float::new(p);
            let mut lr: Option<Vec<Float>> = None;
            for (w, c) in terms {
                let d = match w {
                    Watch::Multiplier(k) => {
                        if lr.is_none() {
                            lr = Some(lambda_rates(sys, s)?);
                        }
                        lr.as_ref().map_or_else(|| Float::new(p), |l| l[*k].clone())
                    }
                    other => rate_of(sys, other, s)?,
                };
                acc += d * c;
            }
            Ok(acc)
        }
    }
}

/// dλ/dt of every multiplier at a sample: a central difference along the
/// flow with step ε = ts·2^−(prec/3), ts the system's time unit (relative
/// error about 2^−(2 prec/3); a step of 2^−(prec/3) seconds would span many
/// time units of a fast motion, e.g. g = 10^40).
fn lambda_rates(sys: &mut System, s: &Sample) -> Result<Vec<Float>> {
    let p = sys.prec;
    let eps = Float::with_val(p, &sys.units.ts) >> (p as i32 / 3);
    let shifted = |sign: i32| {
        let q: Vec<Float> =
            s.q.iter()
                .zip(&s.v)
                .map(|(q, v)| Float::with_val(p, q + Float::with_val(p, v * &eps) * sign))
                .collect();
        let v: Vec<Float> =
            s.v.iter()
                .zip(&s.qdd)
                .map(|(v, a)| Float::with_val(p, v + Float::with_val(p, a * &eps) * sign))
                .collect();
        (q, v)
    };
    let (qp, vp) = shifted(1);
    let (qm, vm) = shifted(-1);
    let ap = sys.accel(&qp, &vp)?;
    let am = sys.accel(&qm, &vm)?;
    let two_eps = Float::with_val(p, &eps * 2u32);
    Ok(ap
        .lambda
        .iter()
        .zip(&am.lambda)
        .map(|(a, b)| Float::with_val(p, a - b) / &two_eps)
        .collect())
}

/// dg/dt as [`rate_of`], with the multipliers' rates of the sample computed
/// at most once (`cache`).
pub(super) fn rate_cached(
    sys: &mut System,
    w: &Watch,
    s: &Sample,
    cache: &mut Option<Vec<Float>>,
) -> Result<Float> {
    let p = sys.prec;
    match w {
        Watch::Multiplier(k) => {
            if cache.is_none() {
                *cache = Some(lambda_rates(sys, s)?);
            }
            Ok(cache
                .as_ref()
                .map_or_else(|| Float::new(p), |l| l[*k].clone()))
        }
        Watch::Lin(terms) => {
            let mut acc = Float::new(p);
            for (w, c) in terms {
                acc += rate_cached(sys, w, s, cache)? * c;
            }
            Ok(acc)
        }
        other => rate_of(sys, other, s),
    }
}
