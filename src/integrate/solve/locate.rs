//! Finding a watched function's zero inside one step: the state a little
//! into the step for a watch that starts at 0, a double crossing within a
//! step from the cubic Hermite interpolant of g, and the crossing itself by
//! Newton's method on re-integrated steps, safeguarded by the bracket.

use super::watch::{rate_cached, rate_of, watch_value, Watch};
use super::{sample, Dae, Sample};
use crate::error::{Error, Result};
use crate::integrate::gbs::Stepper;
use crate::mechanics::system::System;
use crate::numeric::decimal::to_sig;
use crate::numeric::{max_exp, scaled_f64};
use rug::Float;

/// The watched function and the state at t + x, re-integrated from the
/// step's start (y0, f0 at t) with one step of size x at `column`.
fn watch_after<I: Stepper>(
    sys: &mut System,
    gbs: &mut I,
    (y0, f0, t, column): (&[Float], &[Float], &Float, usize),
    x: &Float,
    watch: &Watch,
) -> Result<(Float, Sample)> {
    let y = {
        let nq = sys.nq();
        let mut dae = Dae { sys, nq };
        gbs.fixed_step(&mut dae, y0, f0, x, column)?
    };
    let tx = Float::with_val(gbs.prec(), t + x);
    let smp = sample(sys, &tx, &y)?;
    Ok((watch_value(watch, &smp), smp))
}

/// For a watch that is 0 at the step's start: a state a little into the
/// step where it is nonzero with the sign it leaves 0 with, and its value
/// there — at h·2^−k (k = 6, 10, 14, 18) the first point whose sign is that
/// of the rate at the start (or, where the rate vanishes, the first nonzero
/// value). `None` if the watch stays 0 that long.
pub(super) fn left_zero<I: Stepper>(
    sys: &mut System,
    gbs: &mut I,
    (y0, f0, t, h, column): (&[Float], &[Float], &Float, &Float, usize),
    watch: &Watch,
    cur: &Sample,
    cache: &mut Option<Vec<Float>>,
) -> Result<Option<(Sample, Float)>> {
    let p = gbs.prec();
    let d0 = rate_cached(sys, watch, cur, cache)?;
    for k in [6u32, 10, 14, 18] {
        let x = Float::with_val(p, h >> k);
        let (gx, smp) = watch_after(sys, gbs, (y0, f0, t, column), &x, watch)?;
        if gx.is_zero() {
            continue;
        }
        if d0.is_zero() || gx.is_sign_negative() == d0.is_sign_negative() {
            return Ok(Some((smp, gx)));
        }
    }
    Ok(None)
}

/// A watched function with the same sign at both ends of a step may still
/// have crossed zero twice inside it (a friction cone left and re-entered
/// within one long step). Its cubic Hermite interpolant (values and rates at
/// both ends) tells where it comes closest to zero; if the interpolant
/// reaches zero's side, g itself is evaluated there (re-integrating at the
/// step's column), and a sign opposite to the ends' gives a bracket of the
/// first crossing: (x, g(x), the state there).
#[allow(clippy::type_complexity)]
pub(super) fn dip<I: Stepper>(
    sys: &mut System,
    gbs: &mut I,
    (y0, f0, t, h, column): (&[Float], &[Float], &Float, &Float, usize),
    watch: &Watch,
    ends: [(&Sample, &Float); 2],
    caches: [&mut Option<Vec<Float>>; 2],
) -> Result<Option<(Float, Float, Sample)>> {
    let (s0, ga) = ends[0];
    let (s1, gb) = ends[1];
    let [c0, c1] = caches;
    let d0 = rate_cached(sys, watch, s0, c0)?;
    // moving away from zero at the start and towards it never at the end:
    // a cubic with these slopes has no interior extremum on zero's side
    let pos = !ga.is_sign_negative();
    let toward0 = if pos {
        d0.is_sign_negative()
    } else {
        d0.is_sign_positive()
    };
    if !toward0 {
        return Ok(None);
    }
    let d1 = rate_cached(sys, watch, s1, c1)?;
    let c = hermite_data(ga, &d0, gb, &d1, h);
    // the interpolant's closest approach to zero, on a fine grid of u = x/h
    let sgn = if pos { 1.0 } else { -1.0 };
    let (mut um, mut vm) = (0.0, f64::INFINITY);
    for k in 1..128 {
        let u = k as f64 / 128.0;
        let v = sgn * hermite(&c, u);
        if v < vm {
            (um, vm) = (u, v);
        }
    }
    // reaches zero, or comes within a tenth of the smaller end value
    if vm > 0.1 * (c[0].abs().min(c[2].abs())) {
        return Ok(None);
    }
    let p = gbs.prec();
    let x = Float::with_val(p, h * um);
    let (gx, smp) = watch_after(sys, gbs, (y0, f0, t, column), &x, watch)?;
    if !gx.is_zero() && gx.is_sign_negative() != pos {
        return Ok(None);
    }
    Ok(Some((x, gx, smp)))
}

/// The cubic Hermite data of g over a step of length h, in f64 for
/// starting points only: g0, h·g'0, g1, h·g'1 scaled by one power of two
/// ([`max_exp`], [`scaled_f64`]), so that they hold in any units (a force
/// of 10^−400 N is not 0 in f64, nor a rate of 10^400 N/s infinite).
fn hermite_data(g0: &Float, d0: &Float, g1: &Float, d1: &Float, h: &Float) -> [f64; 4] {
    let p = g0.prec().max(h.prec());
    let hd0 = Float::with_val(p, d0 * h);
    let hd1 = Float::with_val(p, d1 * h);
    let e = max_exp([g0, &hd0, g1, &hd1]).unwrap_or(0);
    [g0, &hd0, g1, &hd1].map(|v| scaled_f64(v, e))
}

/// The cubic Hermite interpolant of [`hermite_data`] `c` at u = x/h in
/// [0, 1].
fn hermite(c: &[f64; 4], u: f64) -> f64 {
    let h00 = 2.0 * u * u * u - 3.0 * u * u + 1.0;
    let h10 = u * u * u - 2.0 * u * u + u;
    let h01 = -2.0 * u * u * u + 3.0 * u * u;
    let h11 = u * u * u - u * u;
    h00 * c[0] + h10 * c[1] + h01 * c[2] + h11 * c[3]
}

/// The root u = x/h in (0, 1) of the cubic Hermite interpolant of
/// [`hermite_data`] `c` (f64: only a starting point).
fn hermite_root(c: &[f64; 4]) -> f64 {
    let val = |u: f64| hermite(c, u);
    // bisection on the cubic keeps the sign change of the ends
    let (mut a, mut b) = (0.0, 1.0);
    let fa = val(a);
    for _ in 0..60 {
        let m = 0.5 * (a + b);
        let fm = val(m);
        if fm == 0.0 {
            return m;
        }
        if (fm < 0.0) == (fa < 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// Locates the zero of the watched function inside the step [t, t + h]
/// (`ends`: the samples and values of g at t and t + h, of opposite signs)
/// by re-integrating from y0 with step s at `column`: a start from the cubic
/// Hermite interpolant of g, then Newton's method on s (dg/dt from
/// [`rate_of`]) safeguarded by the bracket, until the correction is below
/// (|t| + ts)·tol/16, ts the time unit. Returns (s, the state there, the error estimate).
#[allow(clippy::too_many_arguments)]
pub(super) fn locate<I: Stepper>(
    sys: &mut System,
    gbs: &mut I,
    y0: &[Float],
    f0: &[Float],
    t: &Float,
    h: &Float,
    column: usize,
    watch: &Watch,
    ends: [(&Sample, &Float); 2],
) -> Result<(Float, Sample, Float)> {
    let p = gbs.prec();
    let eval = |sys: &mut System, gbs: &mut I, s: &Float| -> Result<(Float, Sample)> {
        watch_after(sys, gbs, (y0, f0, t, column), s, watch)
    };
    let (s0, ga) = ends[0];
    let (s1, gb) = ends[1];
    // the event time to the integrator's tolerance relative to |t| plus the
    // time unit (not plus one second)
    let unit = Float::with_val(p, &sys.units.ts);
    let tol = Float::with_val(p, Float::with_val(p, t + h).abs() + unit) * gbs.tol() / 16u32;
    // bracket [a, b] with g(a) of the sign of ga
    let neg_a = ga.is_sign_negative();
    // the bracket starts where the first end's sample is (0, or inside the
    // step for a watch that started at 0)
    let mut a = Float::with_val(p, &s0.t - t);
    let mut b = h.clone();
    let d0 = rate_of(sys, watch, s0)?;
    let d1 = rate_of(sys, watch, s1)?;
    let width = Float::with_val(p, &b - &a);
    let guess = hermite_root(&hermite_data(ga, &d0, gb, &d1, &width));
    let mut x = width * guess + &a;
    if !(x > a && x < b) {
        x = Float::with_val(p, &a + &b) / 2u32;
    }
    for _ in 0..200 {
        let (gx, smp) = eval(sys, gbs, &x)?;
        if gx.is_zero() {
            return Ok((x, smp, tol));
        }
        if gx.is_sign_negative() == neg_a {
            a = x.clone();
        } else {
            b = x.clone();
        }
        let d = rate_of(sys, watch, &smp)?;
        let corr = Float::with_val(p, &gx / &d);
        let width = Float::with_val(p, &b - &a);
        if Float::with_val(p, corr.abs_ref()) <= tol || width <= tol {
            let err = Float::with_val(p, corr.abs_ref()).min(&width) + &tol;
            return Ok((x, smp, err));
        }
        let mut nx = Float::with_val(p, &x - &corr);
        if !nx.is_finite() || nx <= a || nx >= b {
            nx = Float::with_val(p, &a + &b) / 2u32;
        }
        x = nx;
    }
    Err(Error::NotConverged {
        quantity: "event time".into(),
        requested: 0,
        reached: format!("bracket width {}", to_sig(&Float::with_val(p, &b - &a), 4)),
        detail: format!("inside the step from t = {}", to_sig(t, 7)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Hermite starting point in any units: g(x) = x − 0.3 on a step of
    /// h = 1 (g0 = −0.3, g1 = 0.7, slopes 1), every value scaled by 2^k and
    /// the step by 2^j, k and j beyond f64's range both ways, gives the
    /// root u = 0.3 and the same closest approach of a dip; unscaled, the
    /// values were 0 or infinite in f64.
    #[test]
    fn the_hermite_start_holds_in_any_units() {
        let p = 200;
        for (k, j) in [(0, 0), (-1500, 0), (1500, 0), (-400, 700), (400, -700)] {
            let sc = |x: f64| Float::with_val(p, x) << k;
            let h = Float::with_val(p, 1u32) << j;
            // slope in units of value per step length
            let d = Float::with_val(p, 1u32) << (k - j);
            let c = hermite_data(&sc(-0.3), &d, &sc(0.7), &d, &h);
            let u = hermite_root(&c);
            assert!((u - 0.3).abs() < 1e-12, "2^{k}, h = 2^{j}: u = {u}");
            // g = (x − 1/2)² − 1/100 on [0, 1]: values 0.24 at both ends,
            // slopes ∓1, least −0.01 at u = 1/2
            let c = hermite_data(&sc(0.24), &(-d.clone()), &sc(0.24), &d, &h);
            // (a cubic interpolates the quadratic exactly)
            let r = hermite(&c, 0.5) / c[0];
            assert!((r + 0.01 / 0.24).abs() < 1e-12, "2^{k}, h = 2^{j}: {r}");
        }
    }
}
