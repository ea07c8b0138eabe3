//! Clenshaw–Curtis quadrature with a proved enclosure: the rule (nodes and
//! weights as intervals, computed once per (n, precision) and cached for
//! the process), the Bernstein-ellipse bound of the truncation error, and
//! the covering of the ellipse by complex boxes that proves the bound's
//! hypotheses.
//!
//! **Theorem** (Trefethen, *Approximation Theory and Approximation
//! Practice*, Thm 8.2). If g is analytic in the open Bernstein ellipse E_ρ
//! of [−1, 1] (foci ±1, semi-axes (ρ ± 1/ρ)/2, ρ > 1) and |g| ≤ M there, its
//! interpolant p_n in the n + 1 Chebyshev points cos(jπ/n) satisfies
//! ‖g − p_n‖∞ ≤ 4Mρ^(−n)/(ρ − 1) on [−1, 1]. The Clenshaw–Curtis rule
//! Q_n(g) = Σ w_j g(cos(jπ/n)) is ∫ p_n exactly, so
//! |∫_{−1}^{1} g − Q_n(g)| ≤ 8Mρ^(−n)/(ρ − 1); on [a, b] (x = m + h·z) the
//! bound is multiplied by h = (b − a)/2.
//!
//! The enclosure of Q_n itself: nodes are enclosed by interval arithmetic
//! ([`Iv::sin_cos`]); the weights
//! w_j = (c_j/n)(1 − Σ_{k=1}^{n/2} b_k cos(2πkj/n)/(4k² − 1)) (c_0 = c_n = 1,
//! else 2; b_{n/2} = 1, else 2) are summed in round-to-nearest arithmetic at
//! q = p + 16 bits from the node midpoints, and then widened by the a-priori
//! bound of that sum (see [`Rule::new`]); the sum Σ w_j g(x_j) is formed in
//! interval arithmetic. The enclosure therefore contains ∫g whatever the
//! rounding errors.

use super::interval::{Cx, Iv};
use rug::float::Round;
use rug::ops::Pow;
use rug::{Assign, Float};
use std::sync::{Arc, Mutex, OnceLock};

/// A Clenshaw–Curtis rule on [−1, 1] with n + 1 points, enclosed at `prec` bits.
#[derive(Debug)]
pub struct Rule {
    /// The number of intervals (even).
    pub n: usize,
    /// The precision of the enclosures.
    pub prec: u32,
    /// cos(jπ/n), j = 0..=n.
    pub nodes: Vec<Iv>,
    /// w_j, j = 0..=n.
    pub weights: Vec<Iv>,
}

/// How many rules the process keeps (the most recently built).
const CACHED_RULES: usize = 8;

/// The rule with `n` intervals at `p` bits, from the process-wide cache
/// (built on first use).
pub fn rule(n: usize, p: u32) -> Arc<Rule> {
    static CACHE: OnceLock<Mutex<Vec<Arc<Rule>>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
    if let Some(r) = cache
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .iter()
        .find(|r| r.n == n && r.prec == p)
    {
        return r.clone();
    }
    let r = Arc::new(Rule::new(n, p));
    if crate::cancel::cancelled() {
        // possibly cut short (see Rule::new): never cached; the caller's
        // next check ends the computation
        return r;
    }
    let mut c = cache.lock().unwrap_or_else(|e| e.into_inner());
    if c.len() >= CACHED_RULES {
        c.remove(0);
    }
    c.push(r.clone());
    r
}

/// The number of intervals actually used for a wanted `n`: even, and rounded
/// up to 16 steps per octave (m·2^e, 16 ≤ m < 32), so that nearby requests
/// share one cached rule (at most 1/16 more points).
pub fn round_n(n: usize) -> usize {
    let n = n.max(4);
    if n <= 32 {
        return n + n % 2;
    }
    let e = usize::BITS - 1 - n.leading_zeros() - 4; // n >> e in [16, 32)
    let m = n.div_ceil(1 << e);
    m << e
}

impl Rule {
    /// Builds the rule.
    ///
    /// Weights: with t̂_i the midpoints of the node enclosures (|t̂_i − cos(iπ/n)|
    /// ≤ r, r their largest radius) and â_k = b_k/(4k² − 1) rounded to
    /// nearest, S_j = Σ_{k=1}^{m} a_k cos(2πkj/n) (m = n/2) is computed at q
    /// bits (unit roundoff u = 2^−q) as Ŝ_j = fl(Ê_j ± Ô_j), the inner
    /// products over even and odd k of â_k t̂_{(2kj mod 2n)} (the sign − gives
    /// S_{m−j}). Its error is at most
    /// γ_{m}Σ|â_k||t̂| + u|Ê ± Ô| + Σ|â_k − a_k||t̂| + Σ a_k|t̂ − t|
    /// ≤ (2m + 2)u + 2r =: E (Higham, *Accuracy and Stability of Numerical
    /// Algorithms*, 2nd ed., eq. (3.5): |fl(xᵀy) − xᵀy| ≤ γ_k |x|ᵀ|y| for k
    /// terms, γ_k = ku/(1 − ku); here Σ a_k ≤ Σ_{k≥1} 2/(4k² − 1) = 1,
    /// |t̂| ≤ 1 + r, and mu, r ≪ 1). So w_j ∈ (c_j/n)(1 − [Ŝ_j ± E]), formed
    /// in interval arithmetic.
    pub fn new(n: usize, p: u32) -> Rule {
        assert!(n >= 2 && n % 2 == 0, "Clenshaw-Curtis with odd n");
        let q = p + 16;
        let m = n / 2;
        let pi = Iv::pi(q);
        // nodes: cos(jπ/n) for j ≤ n/4 and sin for the complement, by symmetry
        // beyond n/2 (exact at 0, n/2, n)
        let mut nodes = vec![Iv::int(q, 0); n + 1];
        nodes[0] = Iv::int(q, 1);
        nodes[n] = Iv::int(q, -1);
        for j in 1..=n / 4 {
            let arg = pi.mul_q(&rug::Rational::from((j as i64, n as i64)));
            let (s, c) = arg.sin_cos();
            // cos((n/2 − j)π/n) = sin(jπ/n)
            nodes[n / 2 - j] = s.clone();
            nodes[n / 2 + j] = s.neg();
            nodes[j] = c.clone();
            nodes[n - j] = c.neg();
        }
        // the table cos(iπ/n), i = 0..=n, as midpoints, and its radius bound
        let mut r = Float::new(64);
        let mids: Vec<Float> = nodes
            .iter()
            .map(|iv| {
                let (mid, rad) = iv.mid_rad();
                let rad = Float::with_val_round(64, &rad, Round::Up).0;
                if rad > r {
                    r = rad;
                }
                mid
            })
            .collect();
        let a: Vec<Float> = (1..=m)
            .map(|k| {
                let b = if k == m { 1u64 } else { 2 };
                Float::with_val(q, rug::Rational::from((b, 4 * (k as u64) * (k as u64) - 1)))
            })
            .collect();
        // E = (2m + 2)·2^−q + 2r, rounded up
        let e = {
            let u = Float::with_val(64, 1u32) >> q;
            let t = Float::with_val_round(64, &u * (2 * m as u64 + 2), Round::Up).0;
            Float::with_val_round(64, &t + Float::with_val(64, &r * 2u32), Round::Up).0
        };
        let mut weights = vec![Iv::int(p, 0); n + 1];
        // S_j = E_j + O_j and S_{m−j} = E_j − O_j (the sums over even and
        // odd k: cos(2πk(m − j)/n) = (−1)^k cos(2πkj/n)), half the products
        let mut even = Float::new(q);
        let mut odd = Float::new(q);
        let mut t = Float::new(q);
        for j in 0..=m / 2 {
            if j % 64 == 0 && crate::cancel::cancelled() {
                // cancelled: the rule is left unfinished and is not cached
                break;
            }
            even.assign(0);
            odd.assign(0);
            for (i, ak) in a.iter().enumerate() {
                let k = i + 1;
                let idx = (2 * k * j) % (2 * n);
                let idx = if idx > n { 2 * n - idx } else { idx };
                t.assign(ak * &mids[idx]);
                if k % 2 == 0 {
                    even += &t;
                } else {
                    odd += &t;
                }
            }
            for (jj, sum) in [
                (j, Float::with_val(q, &even + &odd)),
                (m - j, Float::with_val(q, &even - &odd)),
            ] {
                let sj = Iv::new(
                    Float::with_val_round(q, &sum - &e, Round::Down).0,
                    Float::with_val_round(q, &sum + &e, Round::Up).0,
                );
                let cj = if jj == 0 { 1i64 } else { 2 };
                let w = Iv::int(q, 1)
                    .sub(&sj)
                    .mul_q(&rug::Rational::from((cj, n as i64)))
                    .outward(p);
                weights[n - jj] = w.clone();
                weights[jj] = w;
            }
        }
        Rule {
            n,
            prec: p,
            nodes: nodes.iter().map(|x| x.outward(p)).collect(),
            weights,
        }
    }

    /// Q_n(g) on [a, b]: h·Σ w_j g(m + h·cos(jπ/n)), m = (a + b)/2,
    /// h = (b − a)/2, with g enclosed on each node's interval.
    pub fn apply<E>(
        &self,
        a: &Iv,
        b: &Iv,
        mut g: impl FnMut(&Iv) -> Result<Iv, E>,
    ) -> Result<Iv, E> {
        let p = self.prec;
        let half = Iv::rational(p, &rug::Rational::from((1, 2)));
        let h = b.sub(a).mul(&half);
        let mid = a.add(b).mul(&half);
        let mut sum = Iv::int(p, 0);
        for (j, (z, w)) in self.nodes.iter().zip(&self.weights).enumerate() {
            if j % 64 == 0 && crate::cancel::cancelled() {
                // cancelled: the caller's next check ends the computation
                break;
            }
            let x = mid.add(&h.mul(z));
            sum = sum.add(&w.mul(&g(&x)?));
        }
        Ok(sum.mul(&h))
    }
}

/// h·8Mρ^(−n)/(ρ − 1) rounded up (the theorem's bound on [a, b] with
/// half-length ≤ `h_hi`), at 64 bits.
pub fn truncation_bound(h_hi: &Float, m: &Float, rho: f64, n: usize) -> Float {
    let p = 64;
    let rho = Float::with_val(p, rho);
    let rm1 = Float::with_val_round(p, &rho - 1u32, Round::Down).0;
    let rn = Float::with_val_round(p, (&rho).pow(n as u32), Round::Down).0;
    let num = Float::with_val_round(p, h_hi * m, Round::Up).0;
    let num = Float::with_val_round(p, &num * 8u32, Round::Up).0;
    let num = Float::with_val_round(p, &num / &rm1, Round::Up).0;
    Float::with_val_round(p, &num / &rn, Round::Up).0
}

/// The smallest even n (before [`round_n`]) for which h·8Mρ^(−n)/(ρ − 1) ≤
/// 2^(−`tol_log2`) (an f64 estimate in logarithms; the bound itself is then
/// computed rigorously). `usize::MAX` when no n would do.
pub fn n_for(h: f64, m: f64, rho: f64, tol_log2: f64) -> usize {
    let need = ((8.0 * h * m / (rho - 1.0)).ln() + tol_log2 * std::f64::consts::LN_2) / rho.ln();
    if !need.is_finite() || need > 1e9 {
        return usize::MAX;
    }
    let n = need.ceil().max(4.0) as usize;
    n + n % 2
}

/// Boxes the covering may examine before it gives up.
const MAX_BOXES: usize = 20_000;

/// An upper bound of |g| on the closed Bernstein ellipse E_ρ of [−1, 1],
/// from a covering of its upper half by complex boxes at 64 bits.
///
/// `box_bound(z)` must return an upper bound of |g| over the box z, or
/// `None` when it cannot prove that g is analytic there (a factor under a
/// root or a denominator may vanish); such boxes are split, up to a depth.
/// Only the upper half plane is covered: the caller's g must satisfy
/// |g(z̄)| = |g(z)| with its singularities symmetric about the real axis
/// (true for every function built from real-coefficient polynomials, roots
/// and quotients, as here). The ellipse is widened by 10^−12 relative so the
/// f64 grid covers it with margin.
///
/// Returns `None` if some box could not be proved (g may not be analytic on
/// E_ρ).
pub fn ellipse_max(rho: f64, mut box_bound: impl FnMut(&Cx) -> Option<Float>) -> Option<Float> {
    let p = 64;
    let a = (rho + 1.0 / rho) / 2.0 * (1.0 + 1e-12);
    let b = (rho - 1.0 / rho) / 2.0 * (1.0 + 1e-12);
    let (nx, ny) = (16usize, 4usize);
    let mut stack: Vec<(f64, f64, f64, f64, u32)> = Vec::new();
    for ix in 0..nx {
        for iy in 0..ny {
            let x0 = -a + 2.0 * a * ix as f64 / nx as f64;
            let x1 = -a + 2.0 * a * (ix + 1) as f64 / nx as f64;
            let y0 = b * iy as f64 / ny as f64;
            let y1 = b * (iy + 1) as f64 / ny as f64;
            stack.push((x0, x1, y0, y1, 0));
        }
    }
    let mut m = Float::new(p);
    let mut boxes = 0usize;
    while let Some((x0, x1, y0, y1, depth)) = stack.pop() {
        // the box's point nearest the centre: outside the ellipse (with a
        // margin far above the f64 rounding here) means the box misses it
        let cx = if x0 > 0.0 {
            x0
        } else if x1 < 0.0 {
            x1
        } else {
            0.0
        };
        let cy = y0.max(0.0);
        if (cx / a).powi(2) + (cy / b).powi(2) > 1.0 + 1e-9 {
            continue;
        }
        boxes += 1;
        if boxes > MAX_BOXES || crate::cancel::cancelled() {
            return None;
        }
        let z = Cx {
            re: Iv::new(
                Float::with_val_round(p, x0, Round::Down).0,
                Float::with_val_round(p, x1, Round::Up).0,
            ),
            im: Iv::new(
                Float::with_val_round(p, y0, Round::Down).0,
                Float::with_val_round(p, y1, Round::Up).0,
            ),
        };
        match box_bound(&z) {
            Some(v) if v.is_finite() => {
                if v > m {
                    m = v;
                }
            }
            _ => {
                if depth >= 6 {
                    return None;
                }
                let (xm, ym) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
                for (u0, u1) in [(x0, xm), (xm, x1)] {
                    for (v0, v1) in [(y0, ym), (ym, y1)] {
                        stack.push((u0, u1, v0, v1, depth + 1));
                    }
                }
            }
        }
    }
    Some(m)
}

/// ρ of the Bernstein ellipse of [−1, 1] through the point z (complex, as
/// (re, im)): |z ± √(z² − 1)|, the larger.
pub fn rho_through(re: f64, im: f64) -> f64 {
    // w = z² − 1
    let (wr, wi) = (re * re - im * im - 1.0, 2.0 * re * im);
    // principal √w
    let r = (wr * wr + wi * wi).sqrt().sqrt();
    let th = wi.atan2(wr) / 2.0;
    let (sr, si) = (r * th.cos(), r * th.sin());
    let p1 = ((re + sr).powi(2) + (im + si).powi(2)).sqrt();
    let p2 = ((re - sr).powi(2) + (im - si).powi(2)).sqrt();
    p1.max(p2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Rational;

    #[test]
    fn weights_of_small_rules_are_the_exact_rationals() {
        // n = 2: Simpson (1/3, 4/3, 1/3); n = 4: (1, 8, 12, 8, 1)/15
        for (n, w) in [
            (2usize, vec![(1, 3), (4, 3), (1, 3)]),
            (4, vec![(1, 15), (8, 15), (12, 15), (8, 15), (1, 15)]),
        ] {
            let r = Rule::new(n, 128);
            for (iv, (a, b)) in r.weights.iter().zip(w) {
                let want = Float::with_val(512, Rational::from((a, b)));
                assert!(
                    iv.contains(&want),
                    "n = {n}: {a}/{b} not in [{}, {}]",
                    iv.lo,
                    iv.hi
                );
                assert!(iv.width() < Float::with_val(64, 1) >> 110u32);
            }
        }
    }

    #[test]
    fn rules_integrate_monomials_exactly_and_shrinking_is_caught() {
        // Σ w_j x_j^k = ∫_{−1}^{1} x^k = 2/(k + 1) (k even), 0 (odd), k ≤ n
        for (n, p) in [(6usize, 96u32), (16, 200), (40, 300), (64, 160), (102, 256)] {
            let r = Rule::new(n, p);
            for k in 0..=n {
                let mut s = Iv::int(p, 0);
                for (x, w) in r.nodes.iter().zip(&r.weights) {
                    let mut xk = Iv::int(p, 1);
                    for _ in 0..k {
                        xk = xk.mul(x);
                    }
                    s = s.add(&w.mul(&xk));
                }
                let want = if k % 2 == 0 {
                    Rational::from((2, k as i64 + 1))
                } else {
                    Rational::new()
                };
                let want = Float::with_val(2 * p, &want);
                assert!(s.contains(&want), "n = {n}, k = {k}: [{}, {}]", s.lo, s.hi);
                assert!(
                    s.width() < Float::with_val(64, 1) >> (p - 24),
                    "n = {n}, k = {k}"
                );
                // the same sum with its radius taken away misses (k = 0: 2)
                if k == 0 {
                    let (mid, rad) = s.mid_rad();
                    let off = Float::with_val(2 * p, &mid - &want).abs();
                    assert!(off <= rad);
                }
            }
        }
    }

    #[test]
    fn the_error_bound_holds_for_an_entire_and_a_singular_function() {
        // ∫_0^1 e^x = e − 1 (entire: any ρ) and ∫_{−1}^{1} 1/(x² + 1/4) =
        // 4 arctan 2 (poles at ±i/2: ρ < (1 + √5)/2)
        let p = 200;
        let r = rule(round_n(120), p);
        let (a, b) = (Iv::int(p, 0), Iv::int(p, 1));
        let q = r.apply::<()>(&a, &b, |x| Ok(x.exp())).unwrap();
        let h = Float::with_val(64, 0.5);
        let bound = truncation_bound(&h, &Float::with_val(64, 40.0f64.exp()), 20.0, r.n);
        let enc = q.add(&Iv::new(
            Float::with_val(p, -&bound),
            Float::with_val(p, &bound),
        ));
        let e1 = Float::with_val(600, 1u32).exp() - 1u32;
        assert!(enc.contains(&e1));
        assert!(enc.width() < Float::with_val(64, 1) >> 150u32);
        // the covering: |1/(z² + 1/4)| on E_1.5 (poles at ±i/2 outside:
        // ρ(i/2) = 1.618)
        let quarter = Iv::rational(64, &Rational::from((1, 4)));
        let m = ellipse_max(1.5, |z| {
            let d = z.sqr().add_real(&quarter);
            let lo = d.abs_lo();
            (!lo.is_zero()).then(|| Float::with_val_round(64, lo.recip_ref(), Round::Up).0)
        })
        .expect("analytic on E_1.5");
        // the true maximum is at z = ±0.4166i (semi-axis): 1/(1/4 − 0.1736)
        assert!(m >= 13.09 && m.to_f64() < 1e3, "{m}");
        // an ellipse through the poles cannot be proved
        assert!(ellipse_max(1.7, |z| {
            let d = z.sqr().add_real(&quarter);
            let lo = d.abs_lo();
            (!lo.is_zero()).then(|| Float::with_val_round(64, lo.recip_ref(), Round::Up).0)
        })
        .is_none());
        assert!((rho_through(0.0, 0.5) - 1.618_033_988_749_895).abs() < 1e-12);
    }

    #[test]
    fn without_the_truncation_bound_a_short_rule_misses() {
        // ∫_0^1 e^x with n = 8: Q_8 alone is wrong in the 12th digit and its
        // enclosure (rounding only) misses e − 1; with the bound on E_ρ
        // (|e^x| ≤ e^(1/2 + (ρ + 1/ρ)/4)) it holds
        let p = 128;
        let r = Rule::new(8, p);
        let q = r
            .apply::<()>(&Iv::int(p, 0), &Iv::int(p, 1), |x| Ok(x.exp()))
            .unwrap();
        let e1 = Float::with_val(600, 1u32).exp() - 1u32;
        assert!(!q.contains(&e1));
        let rho = 8.0f64;
        let m = (0.5 + (rho + 1.0 / rho) / 4.0).exp() * (1.0 + 1e-9);
        let b = truncation_bound(&Float::with_val(64, 0.5), &Float::with_val(64, m), rho, 8);
        let enc = q.add(&Iv::new(Float::with_val(p, -&b), Float::with_val(p, &b)));
        assert!(enc.contains(&e1));
    }

    #[test]
    fn n_is_rounded_up_to_a_few_values_per_octave() {
        for n in 4..5000 {
            let r = round_n(n);
            assert!(
                r >= n && r % 2 == 0 && (r as f64) <= (n as f64) * 1.07 + 2.0,
                "{n} -> {r}"
            );
        }
        assert_eq!(round_n(1000), 1024);
        assert_eq!(round_n(1025), 1088);
    }
}
