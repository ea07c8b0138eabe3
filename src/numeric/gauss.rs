//! Gauss–Legendre quadrature on `rug::Float`, with an a-priori error model.
//!
//! An n-point Gauss–Legendre rule integrates an f analytic inside the
//! Bernstein ellipse E_ρ (foci at the interval's ends, ρ = sum of its
//! semi-axes over the half-length) with error at most
//! (64/15)·M·ρ^(−2n)/(ρ² − 1) times the half-length, M = max |f| on E_ρ
//! (Trefethen, *Approximation Theory and Approximation Practice*, thm 19.3).
//! Given the integrand's singularities, [`bernstein_rho`] gives ρ, and
//! [`error_log2`] turns the bound into an estimate with a stated M: the caller
//! supplies the singularities, so the estimate is only as good as that list
//! (accuracy kind: *estimated*). The oracle uses it for the high-precision run
//! of the precision ladder, whose low-precision run is tanh-sinh: two methods
//! and two precisions must agree.
//!
//! Nodes: Newton's method on the Legendre three-term recurrence, from the
//! Tricomi seed refined in `f64` (a starting point only), then one Newton step
//! per doubling of the precision up to the working precision plus 16 guard
//! bits; the weight 2/((1 − x²) P_n'(x)²) takes P_n' at the last iterate,
//! corrected to first order with P_n'' from Legendre's equation. Cost:
//! about n²·2 multiplications at the working precision (O(n²)), so the rules
//! are worth building only when they are reused; see [`GaussLegendre::cost`].
//!
//! `f64` appears here only for the seeds of the nodes and for the
//! convergence-rate model (ρ and the number of nodes), never in a value.

use rug::float::Constant;
use rug::{Assign, Float};

/// An n-point Gauss–Legendre rule mapped to u ∈ [0, π/2], with sin u and
/// cos u at each node (for integrands written with u through sin²u).
#[derive(Debug, Clone)]
pub struct HalfPiRule {
    /// Points.
    pub n: usize,
    /// sin u_k.
    pub sin: Vec<Float>,
    /// cos u_k.
    pub cos: Vec<Float>,
    /// Weights, including the interval's half-length π/4.
    pub w: Vec<Float>,
}

/// The positive nodes and their weights of the n-point rule on [−1, 1]
/// (x_k > 0 descending; for odd n the last entry is the node 0).
#[derive(Debug, Clone)]
pub struct GaussLegendre {
    /// Points.
    pub n: usize,
    /// Nodes x_k ≥ 0.
    pub x: Vec<Float>,
    /// Weights w_k.
    pub w: Vec<Float>,
}

/// P_n(x) and P_{n−1}(x) by the three-term recurrence at x's precision.
fn legendre(n: usize, x: &Float, p0: &mut Float, p1: &mut Float, t: &mut Float) {
    p0.assign(1u32);
    p1.assign(x);
    for k in 1..n as u32 {
        // P_{k+1} = ((2k+1) x P_k − k P_{k−1}) / (k+1)
        t.assign(x * &*p1);
        *t *= 2 * k + 1;
        *p0 *= k;
        *t -= &*p0;
        *t /= k + 1;
        std::mem::swap(p0, p1);
        std::mem::swap(p1, t);
    }
}

fn legendre_f64(n: usize, x: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, x);
    for k in 1..n {
        let kf = k as f64;
        let p2 = ((2.0 * kf + 1.0) * x * p1 - kf * p0) / (kf + 1.0);
        p0 = p1;
        p1 = p2;
    }
    (p1, p0)
}

impl GaussLegendre {
    /// The n-point rule (n ≥ 1) at `prec` bits.
    pub fn new(n: usize, prec: u32) -> Self {
        let n = n.max(1);
        let pw = prec + 16;
        // Newton squares the error times C ≈ P''/(2P') ≲ n²/(1 − x²) ≲ n⁴:
        // each precision is half the next plus log2 C and a margin, from an
        // f64 seed good to ~50 bits
        let lc = 4 * (usize::BITS - n.leading_zeros()) + 8;
        let mut schedule = vec![pw];
        while *schedule.last().unwrap_or(&pw) > 80 {
            let q = schedule.last().unwrap_or(&pw) / 2 + lc;
            if q >= *schedule.last().unwrap_or(&pw) {
                break;
            }
            schedule.push(q);
        }
        schedule.reverse();
        let m = n / 2;
        let mut xs = Vec::with_capacity(m + 1);
        let mut ws = Vec::with_capacity(m + 1);
        let nf = n as f64;
        let nn1 = (n * (n + 1)) as u32;
        let (mut p0, mut p1, mut t) = (Float::new(pw), Float::new(pw), Float::new(pw));
        for k in 1..=m {
            // Tricomi's seed, polished in f64
            let th = std::f64::consts::PI * (k as f64 - 0.25) / (nf + 0.5);
            let mut xf = th.cos();
            for _ in 0..3 {
                let (pn, pm) = legendre_f64(n, xf);
                let dp = nf * (xf * pn - pm) / (xf * xf - 1.0);
                xf -= pn / dp;
            }
            let mut x = Float::with_val(schedule[0], xf);
            let mut dp = Float::new(pw);
            let mut pn_last = Float::new(pw);
            for (i, &q) in schedule.iter().enumerate() {
                x.set_prec(q);
                p0.set_prec(q);
                p1.set_prec(q);
                t.set_prec(q);
                dp.set_prec(q);
                legendre(n, &x, &mut p0, &mut p1, &mut t);
                // P_n' = n (x P_n − P_{n−1}) / (x² − 1)
                dp.assign(&x * &p1);
                dp -= &p0;
                dp *= n as u32;
                t.assign(x.square_ref());
                t -= 1u32;
                dp /= &t;
                t.assign(&p1 / &dp);
                x -= &t;
                if i + 1 == schedule.len() {
                    pn_last.set_prec(q);
                    pn_last.assign(&p1);
                }
            }
            // P_n'(x_new) ≈ P_n'(x_old) + P_n''(x_old)·(x_new − x_old), with
            // (1 − x²) P'' = 2x P' − n(n+1) P; the step was −t = −P/P'.
            let x_old = Float::with_val(pw, &x + &t);
            let one_m = Float::with_val(pw, 1u32 - Float::with_val(pw, x_old.square_ref()));
            let mut d2 = Float::with_val(pw, &x_old * &dp) * 2u32;
            d2 -= Float::with_val(pw, &pn_last * nn1);
            d2 /= &one_m;
            let dp_new = Float::with_val(pw, &dp - Float::with_val(pw, &d2 * &t));
            let one_m_new = Float::with_val(pw, 1u32 - Float::with_val(pw, x.square_ref()));
            let den = Float::with_val(pw, dp_new.square_ref()) * one_m_new;
            let w = Float::with_val(prec, Float::with_val(pw, 2u32) / den);
            xs.push(Float::with_val(prec, &x));
            ws.push(w);
        }
        if n % 2 == 1 {
            // node 0: P_n'(0) from the recurrence of P'_n(0) = n P_{n−1}(0)
            let zero = Float::new(pw);
            legendre(n, &zero, &mut p0, &mut p1, &mut t);
            let dp0 = Float::with_val(pw, &p0 * n as u32);
            let w = Float::with_val(prec, Float::with_val(pw, 2u32) / dp0.square());
            xs.push(Float::new(prec));
            ws.push(w);
        }
        GaussLegendre { n, x: xs, w: ws }
    }

    /// Rough cost of building an n-point rule, in multiplications at the
    /// working precision (for deciding whether a rule pays for itself).
    pub fn cost(n: usize) -> f64 {
        let n = n as f64;
        // n/2 nodes × n recurrence steps × (1 full + 4 linear ops) × ~1.6 passes
        n * n * 0.5 * 2.2 * 1.6
    }

    /// The rule mapped to u ∈ [0, π/2] with sin u, cos u at the nodes
    /// (u = π/4 (1 + x); the nodes ±x give u and π/2 − u, whose sine and
    /// cosine swap).
    pub fn half_pi(&self, prec: u32) -> HalfPiRule {
        let pw = prec + 8;
        let q = Float::with_val(pw, Constant::Pi) / 4u32;
        let mut sin = Vec::with_capacity(self.n);
        let mut cos = Vec::with_capacity(self.n);
        let mut w = Vec::with_capacity(self.n);
        let mut right = Vec::new();
        for (x, wk) in self.x.iter().zip(&self.w) {
            let u = Float::with_val(pw, &q * Float::with_val(pw, 1u32 + x));
            let (s, c) = u.sin_cos(Float::new(pw));
            let wq = Float::with_val(prec, wk * &q);
            if x.is_zero() {
                sin.push(Float::with_val(prec, &s));
                cos.push(Float::with_val(prec, &c));
                w.push(wq);
            } else {
                // u (x > 0) and π/2 − u (−x)
                sin.push(Float::with_val(prec, &s));
                cos.push(Float::with_val(prec, &c));
                w.push(wq.clone());
                right.push((Float::with_val(prec, &c), Float::with_val(prec, &s), wq));
            }
        }
        for (s, c, wq) in right {
            sin.push(s);
            cos.push(c);
            w.push(wq);
        }
        HalfPiRule {
            n: self.n,
            sin,
            cos,
            w,
        }
    }
}

/// A complex number in `f64`, for the convergence-rate model only.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct C64 {
    /// Real part.
    pub re: f64,
    /// Imaginary part.
    pub im: f64,
}

impl C64 {
    /// re + i·im.
    pub fn new(re: f64, im: f64) -> Self {
        C64 { re, im }
    }
    fn add(self, o: C64) -> C64 {
        C64::new(self.re + o.re, self.im + o.im)
    }
    fn sub(self, o: C64) -> C64 {
        C64::new(self.re - o.re, self.im - o.im)
    }
    fn mul(self, o: C64) -> C64 {
        C64::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
        )
    }
    fn scale(self, a: f64) -> C64 {
        C64::new(self.re * a, self.im * a)
    }
    fn abs(self) -> f64 {
        self.re.hypot(self.im)
    }
    /// Principal square root.
    pub fn sqrt(self) -> C64 {
        let r = self.abs();
        if r == 0.0 {
            return C64::new(0.0, 0.0);
        }
        let re = ((r + self.re) / 2.0).sqrt();
        let im = ((r - self.re) / 2.0).sqrt();
        C64::new(re, if self.im < 0.0 { -im } else { im })
    }
    fn ln(self) -> C64 {
        C64::new(self.abs().ln(), self.im.atan2(self.re))
    }
    /// Principal arcsine: −i ln(i w + √(1 − w²)).
    pub fn asin(self) -> C64 {
        let one = C64::new(1.0, 0.0);
        let iw = C64::new(-self.im, self.re);
        let l = iw.add(one.sub(self.mul(self)).sqrt()).ln();
        C64::new(l.im, -l.re)
    }
}

/// ρ of the Bernstein ellipse of [a, b] through z: with x = (2z − a − b)/(b − a),
/// ρ = |x ± √(x − 1)√(x + 1)|, the larger (1 for z on the interval).
pub fn bernstein_rho(a: f64, b: f64, z: C64) -> f64 {
    let x = z.scale(2.0).sub(C64::new(a + b, 0.0)).scale(1.0 / (b - a));
    let r = x
        .sub(C64::new(1.0, 0.0))
        .sqrt()
        .mul(x.add(C64::new(1.0, 0.0)).sqrt());
    x.add(r).abs().max(x.sub(r).abs())
}

/// ρ for an integrand of u ∈ [0, π/2] written through sin²u, singular where
/// sin²u takes one of the values `z` (each gives u = ±asin √z and π − those).
pub fn rho_sin2(z: &[C64]) -> f64 {
    let half_pi = std::f64::consts::FRAC_PI_2;
    let mut rho = f64::INFINITY;
    for &zk in z {
        let u = zk.sqrt().asin();
        for cand in [
            u,
            u.scale(-1.0),
            C64::new(std::f64::consts::PI - u.re, -u.im),
            C64::new(std::f64::consts::PI + u.re, u.im),
        ] {
            for c in [cand, C64::new(cand.re, -cand.im)] {
                let r = bernstein_rho(0.0, half_pi, c);
                if r.is_finite() {
                    rho = rho.min(r);
                }
            }
        }
    }
    rho
}

/// log2 of the estimated relative error of the n-point rule for an integrand
/// analytic inside E_ρ: the bound of the module docs on the ellipse
/// ρ' = ρ^(7/8), with M taken as 2^16 times the mean of |f| (the integral over
/// the interval's length): an estimate, not a bound, since M is not computed.
pub fn error_log2(n: usize, rho: f64) -> f64 {
    let rp = rho.powf(0.875);
    if rp.is_nan() || rp <= 1.0 {
        return 0.0;
    }
    // (64/15) · 2^16 · (1/2: mean → half-length scaling) / (ρ'² − 1) · ρ'^(−2n)
    (64.0f64 / 15.0).log2() + 16.0 - 1.0 - (rp * rp - 1.0).log2() - 2.0 * n as f64 * rp.log2()
}

/// The fewest points (a multiple of 8) whose [`error_log2`] is below
/// −`bits`, or `None` if more than `max_n` would be needed.
pub fn points_for(bits: u32, rho: f64, max_n: usize) -> Option<usize> {
    let rp = rho.powf(0.875);
    if rp.is_nan() || rp <= 1.0 || !rp.is_finite() {
        return None;
    }
    let c = (64.0f64 / 15.0).log2() + 15.0 - (rp * rp - 1.0).log2();
    let n = ((c + bits as f64) / (2.0 * rp.log2())).ceil().max(8.0) as usize;
    let n = n.div_ceil(8) * 8;
    if n <= max_n {
        Some(n)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integrates_polynomials_exactly() {
        // an n-point rule is exact for degree 2n − 1: ∫_{-1}^{1} x^(2n−2) = 2/(2n−1)
        for (n, prec) in [(5usize, 64u32), (16, 200), (33, 400)] {
            let g = GaussLegendre::new(n, prec);
            let deg = 2 * n as u32 - 2;
            let mut sum = Float::new(prec);
            let mut wsum = Float::new(prec);
            for (x, w) in g.x.iter().zip(&g.w) {
                let mult = if x.is_zero() { 1u32 } else { 2 };
                sum += Float::with_val(prec, rug::ops::Pow::pow(x, deg)) * w * mult;
                wsum += Float::with_val(prec, w * mult);
            }
            let exact = Float::with_val(prec, 2u32) / (deg + 1);
            let err = Float::with_val(prec, &sum - &exact).abs().to_f64();
            assert!(err < 2f64.powi(-(prec as i32) + 8), "n {n}: {err:e}");
            let werr = Float::with_val(prec, &wsum - 2u32).abs().to_f64();
            assert!(
                werr < 2f64.powi(-(prec as i32) + 8),
                "n {n}: weights {werr:e}"
            );
        }
    }

    #[test]
    fn large_rules_are_accurate_to_the_working_precision() {
        // the same rule at 433 and 900 bits integrates cos on [0, π/2] (= 1)
        // to the working precision: nodes and weights are not the limit
        for (n, prec) in [(232usize, 433u32), (97, 150)] {
            let r = GaussLegendre::new(n, prec).half_pi(prec);
            let mut sum = Float::new(prec + 64);
            for k in 0..r.n {
                sum += Float::with_val(prec + 64, &r.w[k] * &r.cos[k]);
            }
            let err = Float::with_val(prec, &sum - 1u32).abs();
            assert!(
                err < Float::with_val(prec, 1u32) >> (prec as i32 - 10),
                "n {n} at {prec} bits: error {err:e}"
            );
        }
    }

    #[test]
    fn converges_at_the_predicted_rate() {
        // ∫_0^{π/2} du / (1 + sin²u) = π/(2√2): singular where sin²u = −1
        let prec = 300;
        let exact = Float::with_val(prec, Constant::Pi) / Float::with_val(prec, 8u32).sqrt();
        let rho = rho_sin2(&[C64::new(-1.0, 0.0)]);
        assert!(rho > 1.5 && rho < 10.0, "{rho}");
        for n in [16usize, 32, 48] {
            let r = GaussLegendre::new(n, prec).half_pi(prec);
            let mut sum = Float::new(prec);
            for k in 0..r.n {
                let s2 = Float::with_val(prec, r.sin[k].square_ref());
                sum += Float::with_val(prec, &r.w[k] / Float::with_val(prec, s2 + 1u32));
            }
            let err = Float::with_val(prec, &sum - &exact).abs();
            let rel = (err / &exact).to_f64().max(1e-300).log2();
            // the estimate is pessimistic but not by more than ~30 bits + 1/8 of the rate
            let est = error_log2(n, rho);
            assert!(rel <= est, "n {n}: true 2^{rel:.1}, estimate 2^{est:.1}");
            assert!(
                rel >= est - 40.0 - 0.25 * 2.0 * n as f64 * rho.log2(),
                "n {n}: true 2^{rel:.1}, estimate 2^{est:.1}"
            );
        }
        assert_eq!(points_for(100, rho, 1000).map(|n| n % 8), Some(0));
        assert!(points_for(100, 1.0000001, 1000).is_none());
    }
}
