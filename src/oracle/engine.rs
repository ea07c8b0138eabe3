//! One precision's worth of machinery: the dynamics constants and a tanh-sinh
//! rule with its node cache.

use crate::error::Result;
use crate::mechanics::dynamics::{Dyn, HalfAngleTime, Scratch, TinyStart};
use crate::mechanics::{Reduced, PHI1};
use crate::model::Model;
use crate::numeric::gauss::{self, GaussLegendre, HalfPiRule};
use crate::numeric::quad::{QuadResult, Stop, TanhSinh};
use crate::numeric::root;
use rug::Float;
use std::collections::HashMap;

pub(super) struct Engine {
    pub dynm: Dyn,
    /// The rule of [`Engine::time`] (its nodes are part of `separation()`'s
    /// recorded output, so they stay bit for bit as they were).
    pub ts: TanhSinh,
    /// The rule of [`Engine::time_fast`] (nodes built at half the cost).
    ts_half: TanhSinh,
    scratch: Scratch,
    half: HalfAngleTime,
    /// θ = 2π/3 − θ0: the half-angle form is used up to this δ.
    half_limit: Float,
    /// Gauss–Legendre rules on [0, π/2] built so far, by number of points.
    gl: HashMap<usize, HalfPiRule>,
    /// The split integral of a start from rest very near the top (built on
    /// first use).
    tiny: Option<TinyStart>,
    /// Multiplications spent on tanh-sinh integrals that a Gauss–Legendre
    /// rule could have done (decides when building a rule pays off).
    ts_work: f64,
}

/// The largest Gauss–Legendre rule considered, per bit of precision.
const GL_MAX_POINTS_PER_BIT: usize = 2;

/// Which rule a quadrature used.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rule {
    /// Tanh-sinh on the θ form.
    TanhSinhTheta,
    /// Tanh-sinh on the half-angle form.
    TanhSinh,
    /// Gauss–Legendre on the half-angle form.
    GaussLegendre,
}

impl Engine {
    pub fn new(model: &Model, red: &Reduced, prec: u32) -> Result<Self> {
        let dynm = Dyn::new(model, red, prec)?;
        let half = HalfAngleTime::new(&dynm);
        let half_limit = Float::with_val(prec, rug::float::Constant::Pi) * 2u32 / 3u32 - &dynm.th0;
        Ok(Engine {
            dynm,
            ts: TanhSinh::new(prec),
            ts_half: TanhSinh::with_fast_nodes(prec),
            scratch: Scratch::new(prec),
            half,
            half_limit,
            gl: HashMap::new(),
            tiny: None,
            ts_work: 0.0,
        })
    }

    fn prec(&self) -> u32 {
        self.dynm.prec
    }

    /// t(δ) = ∫_0^δ dθ/θ̇ and its error estimate. δ = 0 gives 0.
    pub fn time(&mut self, delta: &Float) -> (Float, Float) {
        let p = self.prec();
        if delta.is_zero() {
            return (Float::new(p), Float::new(p));
        }
        if let Some(r) = self.time_tiny(delta) {
            return r;
        }
        let d = Float::with_val(p, delta);
        let dynm = &self.dynm;
        let w = &mut self.scratch;
        let r = self.ts.integrate(&d, p.saturating_sub(10), |x, out| {
            dynm.inv_thetadot_with(x, out, w)
        });
        Self::quad_answer(p, r)
    }

    /// t(δ) as [`Engine::time`], by the cheaper routes where they apply (θ ≤
    /// 2π/3): the algebraic half-angle integrand ([`HalfAngleTime`]), by
    /// tanh-sinh — or, when `high` (the precision ladder's second run) and a
    /// Gauss–Legendre rule of the size the integrand's singularities call for
    /// is built or pays for itself by now, by Gauss–Legendre with its
    /// a-priori error estimate ([`gauss::error_log2`]). Beyond 2π/3 the θ form.
    /// `may_build`: whether this call may build a new rule.
    pub fn time_fast(
        &mut self,
        delta: &Float,
        high: bool,
        may_build: bool,
    ) -> (Float, Float, Rule) {
        let p = self.prec();
        if delta.is_zero() {
            return (Float::new(p), Float::new(p), Rule::TanhSinh);
        }
        if *delta > self.half_limit {
            let (v, e) = self.time(delta);
            return (v, e, Rule::TanhSinhTheta);
        }
        if let Some((v, e)) = self.time_tiny(delta) {
            return (v, e, Rule::TanhSinh);
        }
        let sigma = self.half.sigma_of(delta);
        if high {
            let rho = gauss::rho_sin2(&self.half.singular_sin2(&sigma));
            let max_n = GL_MAX_POINTS_PER_BIT * p as usize;
            if let Some(n) = gauss::points_for(p + 8, rho, max_n) {
                let ready = self.gl.contains_key(&n)
                    || (may_build && self.ts_work >= GaussLegendre::cost(n) * 0.5);
                if ready {
                    let (v, e) = self.time_gl(&sigma, n, rho);
                    return (v, e, Rule::GaussLegendre);
                }
            }
        }
        let stop = if high {
            Stop::Geometric
        } else {
            Stop::Quadratic
        };
        let half = &mut self.half;
        let r = self
            .ts_half
            .integrate_with(&sigma, p.saturating_sub(10), stop, |x, out| {
                half.eval(x, out)
            });
        // about 14 multiplications per evaluation; a rule of ~evals/5 points
        // would have done it
        self.ts_work += r.evals as f64 * 14.0;
        let (mut v, mut e) = Self::quad_answer(p, r);
        v *= &self.half.factor;
        e *= &self.half.factor;
        // the roundings of σ(δ), of the factor and of the product
        let ulps = Float::with_val(p, v.abs_ref()) >> (p as i32 - 4);
        e += ulps;
        (v, e, Rule::TanhSinh)
    }

    /// t(δ) for a start from rest within 2^−40 (relative to σ) of the top, by
    /// [`TinyStart`]: the ln θ0 part in closed form, the rest by tanh-sinh;
    /// `None` where it does not apply (θ̇0 ≠ 0, θ0 not tiny, θ > 2π/3).
    fn time_tiny(&mut self, delta: &Float) -> Option<(Float, Float)> {
        if !self.half.from_rest() || *delta > self.half_limit {
            return None;
        }
        let p = self.prec();
        let sigma = self.half.sigma_of(delta);
        if Float::with_val(p, &self.half.s0 << 41u32) >= sigma {
            return None;
        }
        let tiny = self.tiny.get_or_insert_with(|| TinyStart::new(&self.half));
        let log_part = tiny.log_part(&sigma);
        let r =
            self.ts_half
                .integrate_with(&sigma, p.saturating_sub(10), Stop::Geometric, |x, out| {
                    tiny.eval(x, out)
                });
        let (reg, mut e) = Self::quad_answer(p, r);
        let mut v = Float::with_val(p, &log_part + &reg);
        v *= &self.half.factor;
        e *= &self.half.factor;
        // the roundings of σ, asinh, the factor and the sum
        let ulps = Float::with_val(p, v.abs_ref()) >> (p as i32 - 6);
        e += ulps;
        Some((v, e))
    }

    /// The values of sin²u where the half-angle integrand in u is singular
    /// (see [`HalfAngleTime::singular_sin2`]).
    pub fn half_singular_sin2(&self, dsig: &Float) -> Vec<gauss::C64> {
        self.half.singular_sin2(dsig)
    }

    /// Gauss–Legendre with `n` points on the half-angle form in u.
    fn time_gl(&mut self, sigma: &Float, n: usize, rho: f64) -> (Float, Float) {
        let p = self.prec();
        let rule = self
            .gl
            .entry(n)
            .or_insert_with(|| GaussLegendre::new(n, p).half_pi(p));
        let mut sum = Float::new(p);
        let mut fx = Float::new(p);
        for k in 0..rule.n {
            self.half.eval_u(sigma, &rule.sin[k], &rule.cos[k], &mut fx);
            fx *= &rule.w[k];
            sum += &fx;
        }
        let v = Float::with_val(p, sum * self.half.u_factor(sigma));
        // truncation (the model) and rounding (n terms, ~20 roundings each)
        let trunc = gauss::error_log2(n, rho);
        let t_exp = trunc.ceil().clamp(-(p as f64) * 4.0, 0.0) as i32;
        let mut e = Float::with_val(p, v.abs_ref()) << t_exp;
        let rounding = (Float::with_val(p, v.abs_ref()) * (20.0 * (n as f64).sqrt())) >> (p as i32);
        e += rounding;
        (v, e)
    }

    fn quad_answer(p: u32, r: QuadResult) -> (Float, Float) {
        let err = if r.converged {
            r.err
        } else {
            // not converged: report an error that blocks every digit the
            // estimate does not support
            Float::with_val(p, r.err * 16u32)
        };
        (r.value, err)
    }

    /// 1/θ̇ at δ (allocation-free integrand of [`Engine::time`]).
    pub fn inv_thetadot(&mut self, d: &Float) -> Float {
        let mut out = Float::new(self.prec());
        self.dynm.inv_thetadot_with(d, &mut out, &mut self.scratch);
        out
    }

    pub fn n12(&mut self, d: &Float) -> Float {
        let st = self.dynm.state(d);
        self.dynm.forces(&st).n12
    }

    pub fn phi1_dot(&mut self, d: &Float) -> Float {
        self.dynm.state(d).v[PHI1].clone()
    }

    /// φ1 at δ (needs the time when the drift ω0 ≠ 0).
    pub fn phi1(&mut self, d: &Float) -> Float {
        let t = if self.dynm.gamma[PHI1].is_zero() {
            Float::new(self.prec())
        } else {
            self.time(d).0
        };
        let st = self.dynm.state(d);
        self.dynm.positions(&st, &t)[PHI1].clone()
    }

    /// Refines a root of `f` bracketed by [lo, hi] (found at low precision)
    /// to this engine's precision; returns (midpoint, half-width).
    pub fn refine_root<F>(
        &mut self,
        name: &str,
        lo: &Float,
        hi: &Float,
        mut f: F,
    ) -> Result<(Float, Float)>
    where
        F: FnMut(&mut Engine, &Float) -> Float,
    {
        let p = self.prec();
        let lo = Float::with_val(p, lo);
        let hi = Float::with_val(p, hi);
        let tol = Float::with_val(p, 1u32) >> (p as i32 - 8);
        let r = root::bracket(name, &lo, &hi, &tol, |x| f(self, x))?;
        let half = Float::with_val(p, r.width() / 2u32);
        let ulp = Float::with_val(p, r.mid().abs()) >> (p as i32 - 2);
        Ok((r.mid(), half + ulp))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::Exact;

    /// Bench T1 (Arb), 200 digits.
    const T1: &str = "4.92431546824328750958943890767440975619729716583700828514899461093135589746020777297976446424524230206377179649802708141731744155015356680000186295700477357023137793369600976317464740174177433799554600220397931327911392476381406432533800713103931733926945527301995113637198679903750992152105290692480683594699937880616";

    #[test]
    fn tanh_sinh_and_gauss_legendre_routes_agree_within_their_estimates() {
        let m = Model::paper_default(Exact::parse("t", "1/10", false).unwrap());
        let red = Reduced::new(&m).unwrap();
        let reference = Float::with_val(800, Float::parse(T1).unwrap());
        for p in [128u32, 400, 600] {
            let mut e = Engine::new(&m, &red, p).unwrap();
            let d = Float::with_val(p, 8u32) / 10u32;
            let (v_ts, e_ts, r_ts) = e.time_fast(&d, true, false);
            assert_eq!(r_ts, Rule::TanhSinh);
            // pretend enough work was done for the rule to pay
            e.ts_work = f64::INFINITY;
            let (v_gl, e_gl, r_gl) = e.time_fast(&d, true, true);
            assert_eq!(r_gl, Rule::GaussLegendre);
            for (name, v, err) in [("ts", &v_ts, &e_ts), ("gl", &v_gl, &e_gl)] {
                let true_err = Float::with_val(p, v - &reference).abs();
                assert!(
                    true_err <= *err,
                    "{name} at {p}: true {true_err:e} > estimate {err:e}"
                );
                let scale = Float::with_val(p, 1u32) >> (p as i32 - 12);
                assert!(*err < scale, "{name} at {p}: estimate {err:e}");
            }
            // the θ form of the same integral
            let (v_th, _) = e.time(&d);
            let diff = Float::with_val(p, &v_th - &v_ts).abs();
            assert!(diff < Float::with_val(p, 1u32) >> (p as i32 - 12), "{p}");
        }
    }
}
