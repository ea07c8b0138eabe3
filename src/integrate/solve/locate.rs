//! Finding a watched function's zero inside one step: the state a little
//! into the step for a watch that starts at 0, a double crossing within a
//! step from the cubic Hermite interpolant of g, and the crossing itself by
//! Newton's method on re-integrated steps, safeguarded by the bracket.

use super::watch::{rate_cached, rate_of, watch_value, Watch};
use super::{sample, Dae, Sample};
use crate::error::{Error, Result};
use crate::integrate::gbs::Stepper;
use crate::mechanics::system::System;
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
    let hf = h.to_f64();
    let (g0, g1, r0, r1) = (ga.to_f64(), gb.to_f64(), d0.to_f64(), d1.to_f64());
    let val = |x: f64| hermite(hf, g0, r0, g1, r1, x);
    // the interpolant's closest approach to zero, on a fine grid
    let sgn = if pos { 1.0 } else { -1.0 };
    let (mut xm, mut vm) = (0.0, f64::INFINITY);
    for k in 1..128 {
        let x = hf * k as f64 / 128.0;
        let v = sgn * val(x);
        if v < vm {
            (xm, vm) = (x, v);
        }
    }
    // reaches zero, or comes within a tenth of the smaller end value
    if vm > 0.1 * (g0.abs().min(g1.abs())) {
        return Ok(None);
    }
    let p = gbs.prec();
    let x = Float::with_val(p, xm);
    let (gx, smp) = watch_after(sys, gbs, (y0, f0, t, column), &x, watch)?;
    if !gx.is_zero() && gx.is_sign_negative() != pos {
        return Ok(None);
    }
    Ok(Some((x, gx, smp)))
}

/// The cubic Hermite interpolant at x ∈ [0, h] of g with values g0, g1 and
/// slopes d0, d1 at the ends (f64: for starting points only).
fn hermite(h: f64, g0: f64, d0: f64, g1: f64, d1: f64, x: f64) -> f64 {
    let u = x / h;
    let h00 = 2.0 * u * u * u - 3.0 * u * u + 1.0;
    let h10 = u * u * u - 2.0 * u * u + u;
    let h01 = -2.0 * u * u * u + 3.0 * u * u;
    let h11 = u * u * u - u * u;
    h00 * g0 + h10 * h * d0 + h01 * g1 + h11 * h * d1
}

/// The root in (0, h) of the cubic Hermite interpolant of g with values
/// and slopes at both ends (f64: only a starting point).
fn hermite_root(h: f64, g0: f64, d0: f64, g1: f64, d1: f64) -> f64 {
    let val = |x: f64| hermite(h, g0, d0, g1, d1, x);
    // bisection on the cubic keeps the sign change of the ends
    let (mut a, mut b) = (0.0, h);
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
    let hf = Float::with_val(p, &b - &a).to_f64();
    let guess = hermite_root(hf, ga.to_f64(), d0.to_f64(), gb.to_f64(), d1.to_f64());
    let mut x = Float::with_val(p, guess) + &a;
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
        reached: format!("bracket width {:.3e}", Float::with_val(p, &b - &a).to_f64()),
        detail: format!("inside the step from t = {:.6e}", t.to_f64()),
    })
}
