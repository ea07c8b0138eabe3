//! Tanh-sinh (double-exponential) quadrature over [0, Δ] for integrands with an
//! integrable singularity at the left endpoint.
//!
//! The integrand receives the *distance from the left endpoint* δ ∈ (0, Δ),
//! computed to full relative accuracy from the stored node complements, so an
//! integrand written in δ (e.g. cos θ0 − cos(θ0+δ) = 2 sin(θ0+δ/2) sin(δ/2))
//! suffers no cancellation near the singular end. This is Boost's 2-argument
//! `tanh_sinh` idea, specialised to one singular end.
//!
//! Accuracy: *estimated*. Levels halve the step h = 2^-L and reuse all earlier
//! nodes; the error of level L is estimated by geometric extrapolation of the
//! last two level differences, never below the rounding floor. The estimate is
//! cross-checked by the precision ladder (`verify`), which reruns at a higher
//! precision (and so a stricter tolerance and usually one more level).

use rug::float::Constant;
use rug::{Assign, Float};

/// Nodes of one level: for t = k h (k odd at levels ≥ 1, all k ≥ 0 at level 0),
/// q = (1 − tanh(π/2 sinh t))/2, its complement 1 − q (rounded once, as the
/// right node's distance is formed from it) and the weight
/// w = (π/2) cosh t / cosh²(π/2 sinh t).
#[derive(Debug, Clone)]
struct Level {
    q: Vec<Float>,
    one_minus_q: Vec<Float>,
    w: Vec<Float>,
}

/// A tanh-sinh rule at a fixed working precision, with nodes cached per level.
#[derive(Debug, Clone)]
pub struct TanhSinh {
    prec: u32,
    t_max: f64,
    /// The levels made so far, shared with the process's other rules of
    /// the same precision and kind ([`shared_level`]).
    levels: Vec<std::sync::Arc<Level>>,
    /// Nodes by the exponential recurrence ([`TanhSinh::with_fast_nodes`]).
    fast_nodes: bool,
}

/// The levels made so far, by (precision, fast nodes), the most recently
/// used last: a rule's nodes depend on nothing else, and every answer
/// builds its rules afresh (an energy engine per precision), so the
/// process's later answers at the same precisions take the levels its
/// earlier ones made — the same numbers, not made again — whichever thread
/// asks (the Python package runs each call on a worker thread of its own;
/// a table's blocks run on several cores).
static LEVELS: std::sync::Mutex<Vec<Pooled>> = std::sync::Mutex::new(Vec::new());

/// [`LEVELS`], whatever a thread that panicked while holding it left
/// (every change is whole before the lock is released).
fn levels_pool() -> std::sync::MutexGuard<'static, Vec<Pooled>> {
    LEVELS.lock().unwrap_or_else(|e| e.into_inner())
}

/// One (precision, fast nodes) entry of [`LEVELS`]: its levels 0, 1, ….
type Pooled = ((u32, bool), Vec<std::sync::Arc<Level>>);

/// How many (precision, kind) entries [`LEVELS`] keeps: a ladder's two
/// precisions and a few more (a table and its events at other digits).
const LEVELS_KEPT: usize = 8;

/// The highest precision whose levels [`LEVELS`] keeps (about 330
/// digits): up to about a megabyte per precision there, where above it a rule's
/// nodes are a small part of its integrals' cost and tens of MB to keep.
const LEVELS_MAX_PREC: u32 = 1100;

/// Level `l` of the rules of `key` from the process's pool, made by `make`
/// (and kept) where the pool has only the levels below it; made alone above
/// [`LEVELS_MAX_PREC`].
fn shared_level(key: (u32, bool), l: usize, make: impl FnOnce() -> Level) -> std::sync::Arc<Level> {
    if key.0 > LEVELS_MAX_PREC {
        return std::sync::Arc::new(make());
    }
    let found = {
        let mut c = levels_pool();
        c.iter().position(|(k, _)| *k == key).and_then(|i| {
            let entry = c.remove(i);
            let lv = entry.1.get(l).cloned();
            c.push(entry);
            lv
        })
    };
    if let Some(lv) = found {
        return lv;
    }
    // made outside the lock (two threads may both make it: the first kept)
    let lv = std::sync::Arc::new(make());
    {
        let mut c = levels_pool();
        match c.iter_mut().find(|(k, _)| *k == key) {
            Some((_, levels)) if levels.len() == l => levels.push(lv.clone()),
            Some(_) => {}
            None if l == 0 => {
                if c.len() == LEVELS_KEPT {
                    c.remove(0);
                }
                c.push((key, vec![lv.clone()]));
            }
            None => {}
        }
    }
    lv
}

/// The result of one integration.
#[derive(Debug, Clone)]
pub struct QuadResult {
    /// The integral.
    pub value: Float,
    /// Estimated absolute error (see module docs).
    pub err: Float,
    /// Levels used (h = 2^-levels at the last).
    pub levels: u32,
    /// Integrand evaluations.
    pub evals: u32,
    /// Whether the requested tolerance was met.
    pub converged: bool,
}

/// The most levels tried before giving up (h = 2^-16).
pub const MAX_LEVEL: usize = 16;

/// How the error of the last level is estimated from the level sums S_L.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stop {
    /// Geometric extrapolation of the last two differences, ×4:
    /// |S_L − S_{L−1}|²/|S_{L−1} − S_{L−2}|·4 (safe for any linearly
    /// converging sequence; usually one level more than needed).
    Geometric,
    /// The double-exponential rule's quadratic convergence (E_L ≈ E_{L−1}²),
    /// as Bailey and mpmath estimate it: with d1 = log2|S_L − S_{L−1}|/|S| and
    /// d2 = log2|S_L − S_{L−2}|/|S|, the error is 2^max(d1²/d2, 2 d1) ×16.
    Quadratic,
}

impl TanhSinh {
    /// A rule for working precision `prec` bits. The abscissa range t ≤ t_max is
    /// chosen so that q(t_max) < 2^-(2 prec + 20): the neglected tail of an
    /// integrand ~ δ^(-1/2) is then below 2^-prec relative.
    pub fn new(prec: u32) -> Self {
        let u_max = (prec as f64 + 12.0) * std::f64::consts::LN_2;
        let t_max = (2.0 * u_max / std::f64::consts::PI).asinh() + 0.05;
        TanhSinh {
            prec,
            t_max,
            levels: Vec::new(),
            fast_nodes: false,
        }
    }

    /// A rule whose nodes come from the recurrence e^(t+2h) = e^t·e^(2h)
    /// (sinh and cosh from e^t by one division, refreshed by an `exp` every
    /// 64 nodes): one transcendental call per node instead of two, so about
    /// half the cost of building a level. The nodes sit within a few units of
    /// the working precision + 16 guard bits of k·h, and each weight belongs
    /// to its own node, so the rule is the same to far below the tolerance
    /// (but not bit for bit the rule of [`TanhSinh::new`]).
    pub fn with_fast_nodes(prec: u32) -> Self {
        TanhSinh {
            fast_nodes: true,
            ..Self::new(prec)
        }
    }

    /// Working precision in bits.
    pub fn prec(&self) -> u32 {
        self.prec
    }

    fn ensure_level(&mut self, level: usize) {
        while self.levels.len() <= level {
            let l = self.levels.len();
            let key = (self.prec, self.fast_nodes);
            let lv = shared_level(key, l, || self.make_level(l));
            self.levels.push(lv);
        }
    }

    /// The nodes and weights of level `l` (a function of the precision,
    /// the kind of nodes and `l` alone).
    fn make_level(&self, l: usize) -> Level {
        let p = self.prec + 16;
        let h = Float::with_val(p, 1u32) >> (l as i32);
        let half_pi = Float::with_val(p, Constant::Pi) / 2u32;
        let (start, step) = if l == 0 { (0u32, 1u32) } else { (1, 2) };
        let mut q = Vec::new();
        let mut one_minus_q = Vec::new();
        let mut w = Vec::new();
        let mut k = start;
        let step_exp = Float::with_val(p, &h * step).exp();
        let mut et = Float::new(p);
        loop {
            let t = Float::with_val(p, &h * k);
            if t.to_f64() > self.t_max {
                break;
            }
            // u = (π/2) sinh t; e = exp(-2u); q = e/(1+e); cosh u = (1+e)/(2 sqrt e)
            let (sh, ch) = if self.fast_nodes {
                if (k - start) % (64 * step) == 0 {
                    et.assign(t.exp_ref());
                } else {
                    et *= &step_exp;
                }
                let inv = Float::with_val(p, et.recip_ref());
                let sh = Float::with_val(p, &et - &inv) / 2u32;
                let ch = Float::with_val(p, &et + &inv) / 2u32;
                (sh, ch)
            } else {
                t.sinh_cosh(Float::new(p))
            };
            let u = Float::with_val(p, &half_pi * &sh);
            let e = Float::with_val(p, -2 * u).exp();
            let one_plus = Float::with_val(p, 1u32 + &e);
            let qk = Float::with_val(self.prec, &e / &one_plus);
            // 1/cosh²u = 4e/(1+e)²
            let wk = Float::with_val(p, &half_pi * ch) * 4u32 * &e / one_plus.square();
            one_minus_q.push(Float::with_val(self.prec, 1u32 - &qk));
            q.push(qk);
            w.push(Float::with_val(self.prec, wk));
            k += step;
        }
        Level { q, one_minus_q, w }
    }

    /// ∫_0^Δ f(δ) dδ, with `f(δ, out)` writing the integrand at distance δ from
    /// the left end into `out` (at this rule's precision). Stops when the
    /// estimated relative error is below 2^-`tol_bits`.
    ///
    /// Preconditions: Δ > 0; f finite on (0, Δ) and integrable; f may be
    /// singular (integrably) at δ = 0, analytic elsewhere on [0, Δ].
    ///
    /// The inner loop allocates nothing: nodes come from the cache, and the
    /// distance, integrand value and term reuse three Floats.
    pub fn integrate<F>(&mut self, delta: &Float, tol_bits: u32, f: F) -> QuadResult
    where
        F: FnMut(&Float, &mut Float),
    {
        self.integrate_with(delta, tol_bits, Stop::Geometric, f)
    }

    /// [`TanhSinh::integrate`] with a choice of error estimate ([`Stop`]).
    pub fn integrate_with<F>(
        &mut self,
        delta: &Float,
        tol_bits: u32,
        stop: Stop,
        mut f: F,
    ) -> QuadResult
    where
        F: FnMut(&Float, &mut Float),
    {
        let p = self.prec;
        let half_delta = Float::with_val(p, delta / 2u32);
        let mut sum = Float::new(p); // Σ w f over all nodes so far (unscaled by h)
        let mut x = Float::new(p);
        let mut fx = Float::new(p);
        let mut term = Float::new(p);
        let mut bound = Float::new(p);
        let mut prev: Option<Float> = None;
        let mut prev2: Option<Float> = None;
        let mut prev_diff: Option<Float> = None;
        let mut evals = 0u32;
        let tol = Float::with_val(p, 1u32) >> (tol_bits as i32);
        let floor = Float::with_val(p, 1u32) >> (p as i32);
        // |term| < |sum|·cut, with |sum|·cut rounded as |sum·cut| (round to
        // nearest is symmetric)
        let small = |term: &Float, sum: &Float, cut: &Float, bound: &mut Float| {
            if term.is_zero() {
                return true;
            }
            bound.assign(sum * cut);
            term.cmp_abs(bound) == Some(std::cmp::Ordering::Less)
        };
        let mut level = 0usize;
        loop {
            if crate::cancel::cancelled() {
                // the caller's next check reports the cancellation
                return QuadResult {
                    value: Float::with_val(p, f64::NAN),
                    err: Float::with_val(p, f64::INFINITY),
                    levels: level as u32,
                    evals,
                    converged: false,
                };
            }
            self.ensure_level(level);
            let lv = &self.levels[level];
            // a term below cut·|sum| ends a side: the tail beyond it sums to
            // at most ~term/(h·slope) with slope ≥ 1, hence the factor h/16
            let cut = Float::with_val(p, &floor >> (level as i32));
            for (k, ((q, omq), w)) in lv.q.iter().zip(&lv.one_minus_q).zip(&lv.w).enumerate() {
                if level == 0 && k == 0 {
                    x.assign(&half_delta);
                    f(&x, &mut fx);
                    evals += 1;
                    term.assign(&fx * w);
                    sum += &term;
                    continue;
                }
                // left node: δ = Δ q ; right node: δ = Δ (1 − q)
                x.assign(delta * q);
                f(&x, &mut fx);
                evals += 1;
                term.assign(&fx * w);
                let left_small = small(&term, &sum, &cut, &mut bound);
                sum += &term;
                x.assign(delta * omq);
                f(&x, &mut fx);
                evals += 1;
                term.assign(&fx * w);
                let right_small = small(&term, &sum, &cut, &mut bound);
                sum += &term;
                // Beyond the peak the terms decay double-exponentially on both
                // sides; once both are below the rounding floor the rest are too.
                if left_small && right_small && k > 2 {
                    break;
                }
            }
            let h = Float::with_val(p, 1u32) >> (level as i32);
            let integral = Float::with_val(p, &sum * &h) * &half_delta;
            if let Some(pv) = &prev {
                let diff = Float::with_val(p, &integral - pv).abs();
                let scale = Float::with_val(p, integral.abs_ref());
                // geometric extrapolation of the convergence; ×4 safety factor
                let est = match (stop, &prev2) {
                    (Stop::Quadratic, Some(p2)) => {
                        let d2v = Float::with_val(p, &integral - p2);
                        match (diff.get_exp(), d2v.get_exp(), integral.get_exp()) {
                            (Some(e1), Some(e2), Some(es)) => {
                                let d1 = (e1 - es) as i64;
                                let d2 = (e2 - es) as i64;
                                let q = if d2 < 0 { (d1 * d1) / d2 } else { d1 };
                                let e = q.max(2 * d1).min(d1) + 4;
                                Float::with_val(p, &scale) << e.clamp(-(1 << 30), 0) as i32
                            }
                            _ => Float::new(p),
                        }
                    }
                    _ => match &prev_diff {
                        Some(pd) if !pd.is_zero() => {
                            let ratio = Float::with_val(p, &diff / pd);
                            let ratio = if ratio > 1u32 {
                                Float::with_val(p, 1u32)
                            } else {
                                ratio
                            };
                            Float::with_val(p, &diff * ratio) * 4u32
                        }
                        _ => diff.clone(),
                    },
                };
                // rounding noise of a sum of `evals` terms, each correctly rounded
                let rounding = Float::with_val(p, &scale * &floor) * (evals.max(16) as f64).sqrt();
                let at_floor = diff <= Float::with_val(p, &rounding * 4u32);
                let est = if est < rounding { rounding } else { est };
                let done = level >= 3 && (est <= Float::with_val(p, &scale * &tol) || at_floor);
                if done || level == MAX_LEVEL {
                    return QuadResult {
                        value: integral,
                        err: est,
                        levels: level as u32,
                        evals,
                        converged: done,
                    };
                }
                prev_diff = Some(diff);
            } else if level == MAX_LEVEL {
                // only reachable with MAX_LEVEL = 0: no difference to judge
                let err = Float::with_val(p, integral.abs_ref());
                return QuadResult {
                    value: integral,
                    err,
                    levels: 0,
                    evals,
                    converged: false,
                };
            }
            prev2 = prev.take();
            prev = Some(integral);
            level += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A rule made where one at the same precision was made before (on
    /// this thread or another) takes that rule's levels (the same numbers,
    /// not made again), and integrates to the same bits as a rule whose
    /// levels are all its own.
    #[test]
    fn rules_share_their_levels() {
        let p = 200;
        let delta = Float::with_val(p, 1u32);
        let f = |x: &Float, out: &mut Float| {
            out.assign(x.sqrt_ref());
            *out += 1u32;
        };
        let fresh = {
            let mut ts = TanhSinh::with_fast_nodes(p);
            for l in 0..16 {
                let lv = std::sync::Arc::new(ts.make_level(l));
                ts.levels.push(lv);
            }
            let r = ts.integrate(&Float::with_val(p, 1u32), p - 20, f);
            (r.value, r.err, r.levels)
        };
        let mut a = std::thread::spawn(move || {
            let mut a = TanhSinh::with_fast_nodes(p);
            a.integrate(&Float::with_val(p, 1u32), p - 20, f);
            a
        })
        .join()
        .unwrap();
        let ra = a.integrate(&delta, p - 20, f);
        let mut b = TanhSinh::with_fast_nodes(p);
        let rb = b.integrate(&delta, p - 20, f);
        for r in [&ra, &rb] {
            assert_eq!((&r.value, &r.err, r.levels), (&fresh.0, &fresh.1, fresh.2));
        }
        assert!(a.levels.len() > 3);
        assert!(a
            .levels
            .iter()
            .zip(&b.levels)
            .all(|(x, y)| std::sync::Arc::ptr_eq(x, y)));
        // the other kind of nodes is kept apart
        let mut c = TanhSinh::new(p);
        c.integrate(&delta, p - 20, f);
        assert!(!std::sync::Arc::ptr_eq(&a.levels[1], &c.levels[1]));
    }

    fn check(
        prec: u32,
        digits_needed: f64,
        delta: Float,
        exact: Float,
        f: impl FnMut(&Float, &mut Float),
    ) {
        let mut ts = TanhSinh::new(prec);
        let r = ts.integrate(&delta, prec - 8, f);
        assert!(r.converged, "not converged: {r:?}");
        let err = Float::with_val(prec, &r.value - &exact).abs();
        let rel = (err / exact.clone().abs()).to_f64();
        assert!(
            rel < 10f64.powf(-digits_needed),
            "prec {prec}: rel err {rel:e}, {r:?}"
        );
        // the estimate must not be smaller than the true error by more than a rounding unit
        let ulp = Float::with_val(prec, 1u32) >> (prec as i32 - 12);
        let bound = Float::with_val(prec, &r.err * 4u32) + ulp * exact.clone().abs();
        let e2 = Float::with_val(prec, &r.value - &exact).abs();
        assert!(
            e2 <= bound,
            "estimate {} below true error {}",
            r.err.to_f64(),
            e2.to_f64()
        );
    }

    #[test]
    fn inverse_sqrt_endpoint() {
        // ∫_0^1 δ^(-1/2) dδ = 2
        for prec in [100u32, 340, 1000] {
            let d = Float::with_val(prec, 1u32);
            check(
                prec,
                (prec as f64 - 20.0) * std::f64::consts::LOG10_2,
                d,
                Float::with_val(prec, 2u32),
                |x, out| {
                    out.assign(x.sqrt_ref());
                    out.recip_mut();
                },
            );
        }
    }

    #[test]
    fn fast_nodes_integrate_as_well() {
        // ∫_0^1 δ^(-1/2) dδ = 2 with the recurrence-built nodes
        for prec in [100u32, 340, 1000] {
            let d = Float::with_val(prec, 1u32);
            let mut ts = TanhSinh::with_fast_nodes(prec);
            let r = ts.integrate(&d, prec - 8, |x, out| {
                out.assign(x.sqrt_ref());
                out.recip_mut();
            });
            assert!(r.converged);
            let err = Float::with_val(prec, &r.value - 2u32).abs();
            assert!(
                err <= Float::with_val(prec, &r.err * 4u32),
                "{prec}: {err:e} vs {:e}",
                r.err
            );
            assert!(
                err < Float::with_val(prec, 1u32) >> (prec as i32 - 20),
                "{prec}: {err:e}"
            );
        }
    }

    #[test]
    fn smooth_integrand() {
        // ∫_0^2 cos δ dδ = sin 2
        for prec in [64u32, 200, 700] {
            let d = Float::with_val(prec, 2u32);
            let exact = Float::with_val(prec, 2u32).sin();
            check(
                prec,
                (prec as f64 - 20.0) * std::f64::consts::LOG10_2,
                d,
                exact,
                |x, out| {
                    out.assign(x.cos_ref());
                },
            );
        }
    }

    #[test]
    fn arcsine_law() {
        // ∫_0^1 dδ / sqrt(δ (2 − δ)) = π/2
        let prec = 300;
        let d = Float::with_val(prec, 1u32);
        let exact = Float::with_val(prec, Constant::Pi) / 2u32;
        check(prec, 80.0, d, exact, |x, out| {
            let two_minus = Float::with_val(prec, 2u32 - x);
            out.assign(x * two_minus);
            out.sqrt_mut();
            out.recip_mut();
        });
    }

    #[test]
    fn digits_gained_per_level_grow() {
        // convergence is (at least) geometric in the level: each level roughly
        // doubles the correct digits of a smooth integrand until the floor.
        let prec = 400;
        let mut ts = TanhSinh::new(prec);
        let d = Float::with_val(prec, 1u32);
        let exact = Float::with_val(prec, 1u32).exp() - 1u32;
        let mut errs = vec![];
        for tol in [20u32, 60, 120, 240, 380] {
            let r = ts.integrate(&d, tol, |x, out| {
                out.assign(x.exp_ref());
            });
            let e = Float::with_val(prec, &r.value - &exact).abs();
            errs.push((r.levels, e.to_f64()));
        }
        for w in errs.windows(2) {
            assert!(w[1].0 >= w[0].0);
            assert!(w[1].1 <= w[0].1 * 1.01 + 1e-115, "{errs:?}");
        }
        assert!(errs.last().unwrap().1 < 1e-110, "{errs:?}");
    }
}
