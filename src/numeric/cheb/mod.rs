//! Chebyshev interpolation on `rug::Float`: values at the N Chebyshev points
//! of the first kind, coefficients by a fast cosine transform (O(N log N)),
//! the integral, the antiderivative and Clenshaw evaluation.
//!
//! Why: an integrand analytic in the Bernstein ellipse E_ρ of its interval
//! has Chebyshev coefficients that decay like ρ^(−k) (Trefethen, *Approximation
//! Theory and Approximation Practice*, thm 8.1), so N ≈ bits/log2 ρ points
//! resolve it — against ~2.4 times as many tanh-sinh nodes, each of which
//! costs an `exp` to build. The points are cosines of equally spaced angles,
//! built from one table of cos/sin(kπ/2N) by complex rotations (a direct
//! `sin_cos` every 32 steps keeps the rounding at a few units), and the same
//! table gives the transform's twiddles: no transcendental per point.
//!
//! Transform: the DCT-II of the values by Makhoul's reordering and one
//! complex FFT of length N (mixed radix 2, 3, 5; the caller picks an N with
//! no other prime factor, [`smooth_at_least`]), then a rotation by
//! e^(−iπk/2N) (J. Makhoul, "A fast cosine transform in one and two
//! dimensions", IEEE Trans. ASSP 28 (1980) 27–34).
//!
//! Accuracy: *estimated*. The interpolant's error is estimated from the size
//! of its last coefficients ([`ChebFit::tail`]), which for a geometric decay
//! bounds the neglected ones; the caller chooses N from the integrand's
//! singularities so that the tail sits far below the target, and the
//! precision ladder checks the result at a second precision and size.
//! Working precision: the table carries 32 guard bits; every value and
//! coefficient is rounded to the fit's precision.

mod fft;
pub mod fixed_sums;

pub use fft::Roots;

use fft::{fft, real_fft};
use rug::ops::NegAssign;
use rug::{Assign, Float};

/// The smallest N ≥ `n` whose only prime factors are 2, 3 and 5.
pub fn smooth_at_least(n: usize) -> usize {
    let mut m = n.max(1);
    loop {
        let mut r = m;
        for p in [2, 3, 5] {
            while r % p == 0 {
                r /= p;
            }
        }
        if r == 1 {
            return m;
        }
        m += 1;
    }
}

/// Makhoul's slot of point j among n: even j at j/2, odd j at N − 1 − (j − 1)/2.
fn slot(j: usize, n: usize) -> usize {
    if j % 2 == 0 {
        j / 2
    } else {
        n - 1 - (j - 1) / 2
    }
}

/// Point j of `roots` mapped to [a, b]: (a + b)/2 + (b − a)/2 · x_j.
fn point_in(a: &Float, b: &Float, roots: &Roots, j: usize, p: u32) -> Float {
    let mut v = Float::with_val(p, b - a) * roots.point(j, p);
    v >>= 1;
    v += Float::with_val(p, a + b) >> 1;
    v
}

/// A Chebyshev interpolant on [a, b]: p(v) = Σ_k c_k T_k(x), x = (2v − a − b)/(b − a).
#[derive(Debug, Clone)]
pub struct ChebFit {
    /// Left end.
    pub a: Float,
    /// Right end.
    pub b: Float,
    /// Coefficients c_0 … c_{N−1} (c_0 is the true T_0 coefficient).
    pub c: Vec<Float>,
    /// max |f| over the points.
    pub fmax: Float,
}

impl ChebFit {
    /// Interpolates `f(v, out)` at the N points of `roots` mapped to [a, b],
    /// at `p` bits. `f` must write a finite value.
    pub fn new<F>(a: &Float, b: &Float, roots: &Roots, p: u32, mut f: F) -> Self
    where
        F: FnMut(&Float, &mut Float),
    {
        let n = roots.n;
        let mut fx = Float::new(p);
        let vals: Vec<Float> = (0..n)
            .map(|j| {
                f(&point_in(a, b, roots, j, p), &mut fx);
                fx.clone()
            })
            .collect();
        Self::from_values(a, b, roots, p, &vals)
    }

    /// The interpolant of the values `vals[j]` at the points
    /// [`ChebFit::points`] (point j of `roots` mapped to [a, b]), at `p` bits.
    pub fn from_values(a: &Float, b: &Float, roots: &Roots, p: u32, vals: &[Float]) -> Self {
        let n = roots.n;
        assert_eq!(vals.len(), n, "one value per point");
        // values in Makhoul's order: f_j (point j) goes to 2j → slot j/2,
        // odd j → slot N − 1 − (j − 1)/2
        let mut slots: Vec<Float> = vec![Float::new(p); n];
        let mut fmax = Float::new(p);
        for (j, fx) in vals.iter().enumerate() {
            if fx.cmp_abs(&fmax) == Some(std::cmp::Ordering::Greater) {
                fmax.assign(fx.abs_ref());
            }
            slots[slot(j, n)].assign(fx);
        }
        let vals = slots;
        let (re, im) = real_fft(vals, roots, p);
        // c_k = (2/N) Re(e^(−iπk/2N) V_k), c_0 halved
        let mut c = Vec::with_capacity(n);
        let mut t = Float::new(p);
        for k in 0..n {
            let (cs, nc, sn, ns) = roots.cis(k);
            let mut ck = Float::with_val(p, &re[k] * cs);
            if nc {
                ck = -ck;
            }
            t.assign(&im[k] * sn);
            if ns {
                ck -= &t;
            } else {
                ck += &t;
            }
            ck *= 2u32;
            ck /= n as u64;
            if k == 0 {
                ck /= 2u32;
            }
            c.push(ck);
        }
        ChebFit {
            a: Float::with_val(p, a),
            b: Float::with_val(p, b),
            c,
            fmax,
        }
    }

    /// Working precision.
    pub fn prec(&self) -> u32 {
        self.a.prec()
    }

    /// ∫_a^b p(v) dv = (b − a)/2 · Σ_{k even} c_k·2/(1 − k²).
    pub fn integral(&self) -> Float {
        let p = self.prec();
        let mut s = Float::new(p);
        let mut t = Float::new(p);
        for (k, ck) in self.c.iter().enumerate().step_by(2) {
            let k = k as i64;
            t.assign(ck * 2u32);
            t /= 1 - k * k;
            s += &t;
        }
        s * Float::with_val(p, &self.b - &self.a) / 2u32
    }

    /// The largest |c_k| over the last eight coefficients: for coefficients
    /// decaying like ρ^(−k) the neglected ones are below it times
    /// ρ^(−8)/(1 − 1/ρ), and the interpolant's uniform error (aliasing
    /// included) below twice their sum.
    pub fn tail(&self) -> Float {
        let p = self.prec();
        let n = self.c.len();
        let mut m = Float::new(p);
        for ck in &self.c[n.saturating_sub(8)..] {
            if ck.cmp_abs(&m) == Some(std::cmp::Ordering::Greater) {
                m.assign(ck.abs_ref());
            }
        }
        m
    }

    /// The antiderivative P(v) = ∫_a^v p, itself a Chebyshev series of N + 1
    /// terms on [a, b] (C_k = (c_{k−1} − c_{k+1})/2k, times (b − a)/2; C_0
    /// makes P(a) = 0).
    pub fn antiderivative(&self) -> ChebFit {
        let p = self.prec();
        let n = self.c.len();
        let zero = Float::new(p);
        let get = |k: usize| -> &Float { self.c.get(k).unwrap_or(&zero) };
        let half = Float::with_val(p, &self.b - &self.a) / 2u32;
        let mut cc = vec![Float::new(p); n + 1];
        for (k, slot) in cc.iter_mut().enumerate().skip(1) {
            let lo = if k == 1 {
                Float::with_val(p, get(0) * 2u32)
            } else {
                Float::with_val(p, get(k - 1))
            };
            let mut v = Float::with_val(p, &lo - get(k + 1));
            v /= 2 * k as u64;
            v *= &half;
            *slot = v;
        }
        // P(−1) = C_0 + Σ_{k≥1} C_k (−1)^k = 0
        let mut s = Float::new(p);
        for (k, ck) in cc.iter().enumerate().skip(1) {
            if k % 2 == 0 {
                s -= ck;
            } else {
                s += ck;
            }
        }
        cc[0] = s;
        ChebFit {
            a: self.a.clone(),
            b: self.b.clone(),
            c: cc,
            fmax: Float::new(p),
        }
    }

    /// p(v) by Clenshaw's recurrence, at `prec` bits (≤ the fit's; the
    /// coefficients are used as stored).
    pub fn eval(&self, v: &Float, prec: u32) -> Float {
        let p = prec;
        // x = (2v − a − b)/(b − a)
        let mut x = Float::with_val(p, v * 2u32);
        x -= &self.a;
        x -= &self.b;
        x /= Float::with_val(p, &self.b - &self.a);
        let x2 = Float::with_val(p, &x * 2u32);
        let mut b1 = Float::new(p);
        let mut b2 = Float::new(p);
        let mut t = Float::new(p);
        for ck in self.c.iter().skip(1).rev() {
            // b_k = c_k + 2x b_{k+1} − b_{k+2}
            t.assign(&x2 * &b1);
            t += ck;
            t -= &b2;
            std::mem::swap(&mut b2, &mut b1);
            std::mem::swap(&mut b1, &mut t);
        }
        // p = c_0 + x b_1 − b_2
        let mut r = Float::with_val(p, &x * &b1);
        r += &self.c[0];
        r -= &b2;
        r
    }

    /// The N points of `roots` mapped to [a, b] (point j = (a + b)/2 +
    /// (b − a)/2 cos((2j + 1)π/2N), descending), at `p` bits.
    pub fn points(a: &Float, b: &Float, roots: &Roots, p: u32) -> Vec<Float> {
        (0..roots.n).map(|j| point_in(a, b, roots, j, p)).collect()
    }

    /// The values at the N points of `roots` ([`ChebFit::points`]), by one
    /// inverse cosine transform (DCT-III: Makhoul's reordering of one
    /// complex FFT), at `p` bits. The fit has at most N + 1 coefficients
    /// (T_N vanishes at the points, so an antiderivative's last term drops).
    pub fn values(&self, roots: &Roots, p: u32) -> Vec<Float> {
        let n = roots.n;
        assert!(self.c.len() <= n + 1, "at most N + 1 coefficients");
        // y_m = Re Σ_k c_k e^(−iπk/2N) e^(−2πikm/N); f_2m = y_m, f_2m+1 = y_(N−1−m)
        let mut re = vec![Float::new(p); n];
        let mut im = vec![Float::new(p); n];
        for (k, ck) in self.c.iter().enumerate().take(n) {
            let (cs, nc, sn, ns) = roots.cis(k);
            re[k].assign(ck * cs);
            if nc {
                re[k].neg_assign();
            }
            im[k].assign(ck * sn);
            if !ns {
                im[k].neg_assign();
            }
        }
        fft(&mut re, &mut im, roots, p);
        let mut out = vec![Float::new(p); n];
        for (j, o) in out.iter_mut().enumerate() {
            std::mem::swap(o, &mut re[slot(j, n)]);
        }
        out
    }

    /// The derivative d/dv as a Chebyshev series on [a, b] (c'_(k−1) =
    /// c'_(k+1) + 2k c_k, times 2/(b − a)).
    pub fn derivative(&self) -> ChebFit {
        let p = self.prec();
        let n = self.c.len();
        let mut d = vec![Float::new(p); n.max(1)];
        for k in (1..n).rev() {
            let up = d.get(k + 1).cloned().unwrap_or_else(|| Float::new(p));
            d[k - 1] = up + Float::with_val(p, &self.c[k] * (2 * k) as u64);
        }
        d[0] >>= 1;
        let scale = Float::with_val(p, &self.b - &self.a).recip() * 2u32;
        for x in &mut d {
            *x *= &scale;
        }
        ChebFit {
            a: self.a.clone(),
            b: self.b.clone(),
            c: d,
            fmax: Float::new(p),
        }
    }

    /// T_0(x) … T_(n−1)(x) at x = (2v − a − b)/(b − a), at `p` bits: the
    /// basis that [`ChebFit::dot`] evaluates every fit on [a, b] with (one
    /// recurrence shared by many fits at the same point).
    pub fn basis(a: &Float, b: &Float, v: &Float, n: usize, p: u32) -> Vec<Float> {
        let mut t = Vec::new();
        Self::basis_into(a, b, v, n, p, &mut t);
        t
    }

    /// [`ChebFit::basis`] into `t`, reusing its values' storage (`t` keeps
    /// at least n entries; the first n are the basis).
    pub fn basis_into(a: &Float, b: &Float, v: &Float, n: usize, p: u32, t: &mut Vec<Float>) {
        if t.len() < n.max(2) {
            t.resize(n.max(2), Float::new(p));
        }
        let mut x = Float::with_val(p, v * 2u32);
        x -= a;
        x -= b;
        x /= Float::with_val(p, b - a);
        t[0].set_prec(p);
        t[0].assign(1u32);
        t[1].set_prec(p);
        t[1].assign(&x);
        x *= 2u32;
        for k in 2..n {
            let (done, rest) = t.split_at_mut(k);
            let next = &mut rest[0];
            next.set_prec(p);
            next.assign(&x * &done[k - 1]);
            *next -= &done[k - 2];
        }
    }

    /// Σ c_k T_k from a [`ChebFit::basis`] at least as long as the fit.
    pub fn dot(&self, basis: &[Float]) -> Float {
        let p = basis[0].prec();
        let mut acc = Float::new(p);
        for (c, t) in self.c.iter().zip(basis) {
            acc += c * t;
        }
        acc
    }

    /// The coefficients as f64 (for cheap seeds).
    pub fn to_f64(&self) -> Vec<f64> {
        self.c.iter().map(Float::to_f64).collect()
    }

    /// Clenshaw in f64 for coefficients `c` on [a, b].
    pub fn eval_f64(c: &[f64], a: f64, b: f64, v: f64) -> f64 {
        Self::eval_f64_at(c, a, b, [v])[0]
    }

    /// [`ChebFit::eval_f64`] at N points at once: the N recurrences
    /// interleaved, each the same operations in the same order as alone
    /// (the same bits), run side by side instead of one after another (the
    /// recurrence's chain of dependent operations is its cost).
    pub fn eval_f64_at<const N: usize>(c: &[f64], a: f64, b: f64, v: [f64; N]) -> [f64; N] {
        let x = v.map(|v| (2.0 * v - a - b) / (b - a));
        let (mut b1, mut b2) = ([0.0f64; N], [0.0f64; N]);
        for ck in c.iter().skip(1).rev() {
            for k in 0..N {
                let t = 2.0 * x[k] * b1[k] - b2[k] + ck;
                b2[k] = b1[k];
                b1[k] = t;
            }
        }
        let c0 = c.first().copied().unwrap_or(0.0);
        std::array::from_fn(|k| c0 + x[k] * b1[k] - b2[k])
    }

    /// The fit's coefficients rounded to `prec` bits (for cheap evaluations
    /// at a lower precision, e.g. the first Newton steps of an inversion).
    pub fn rounded(&self, prec: u32) -> ChebFit {
        ChebFit {
            a: Float::with_val(prec, &self.a),
            b: Float::with_val(prec, &self.b),
            c: self.c.iter().map(|c| Float::with_val(prec, c)).collect(),
            fmax: Float::with_val(prec, &self.fmax),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::float::Constant;

    /// The interleaved recurrences give the bits of one recurrence alone at each point
    /// (coefficients of mixed signs and sizes, points inside and outside
    /// the interval, degree 0 to 90).
    #[test]
    fn four_points_at_once_are_four_evaluations() {
        let mut bits = crate::numeric::xorshift(0x2545_f491_4f6c_dd1d);
        // uniform in [−1, 1)
        let mut next = || (bits() >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0;
        for n in [0usize, 1, 2, 3, 17, 64, 91] {
            let c: Vec<f64> = (0..n)
                .map(|k| next() * 10f64.powi(-(k as i32 % 9)))
                .collect();
            let (a, b) = (next() - 2.0, next() + 2.0);
            let v = [next() * 3.0, a, b, 0.5 * (a + b) + next()];
            let four = ChebFit::eval_f64_at(&c, a, b, v);
            for k in 0..4 {
                let one = ChebFit::eval_f64(&c, a, b, v[k]);
                assert_eq!(four[k].to_bits(), one.to_bits(), "n = {n}, point {k}");
                // Clenshaw's recurrence written out once more, alone
                let x = (2.0 * v[k] - a - b) / (b - a);
                let (mut b1, mut b2) = (0.0f64, 0.0f64);
                for ck in c.iter().skip(1).rev() {
                    (b1, b2) = (2.0 * x * b1 - b2 + ck, b1);
                }
                let alone = c.first().copied().unwrap_or(0.0) + x * b1 - b2;
                assert_eq!(four[k].to_bits(), alone.to_bits(), "n = {n}, point {k}");
            }
        }
    }

    /// values() is the interpolant at its own points, derivative() and
    /// antiderivative() invert each other, checked on e^v over [−1/2, 2].
    #[test]
    fn values_and_derivative_of_exp() {
        let p = 200;
        for n in [16usize, 30, 45, 64] {
            let roots = Roots::new(n, p);
            let a = Float::with_val(p, -0.5f64);
            let b = Float::with_val(p, 2u32);
            let f = ChebFit::new(&a, &b, &roots, p, |v, o| o.assign(v.exp_ref()));
            let pts = ChebFit::points(&a, &b, &roots, p);
            let tol = Float::with_val(p, 1u32) >> if n >= 45 { 150 } else { 30 };
            for (x, y) in pts.iter().zip(f.values(&roots, p)) {
                let e = Float::with_val(p, x.exp_ref()) - &y;
                assert!(e.abs() < Float::with_val(p, 1u32) >> 180, "n = {n}");
            }
            // the antiderivative's values: e^v − e^a (its N+1-th term vanishes at the points)
            let ea = Float::with_val(p, a.exp_ref());
            for (x, y) in pts.iter().zip(f.antiderivative().values(&roots, p)) {
                let e = Float::with_val(p, x.exp_ref()) - &ea - &y;
                assert!(e.clone().abs() < tol, "n = {n}: {e}");
            }
            let d = f.derivative();
            for x in [-0.4f64, 0.3, 1.9] {
                let xv = Float::with_val(p, x);
                let e = Float::with_val(p, xv.exp_ref()) - d.eval(&xv, p);
                assert!(e.clone().abs() < tol, "n = {n}, x = {x}: {e}");
            }
        }
    }

    /// The DCT-II by its definition, O(N²).
    fn direct(f: &[Float], p: u32) -> Vec<Float> {
        let n = f.len();
        let pi = Float::with_val(p, Constant::Pi);
        (0..n)
            .map(|k| {
                let mut s = Float::new(p);
                for (j, fj) in f.iter().enumerate() {
                    let a = Float::with_val(p, &pi * (k * (2 * j + 1)) as u64) / (2 * n) as u64;
                    s += Float::with_val(p, fj * a.cos());
                }
                s *= 2u32;
                s /= n as u64;
                if k == 0 {
                    s /= 2u32;
                }
                s
            })
            .collect()
    }

    #[test]
    fn smooth_sizes() {
        assert_eq!(smooth_at_least(7), 8);
        assert_eq!(smooth_at_least(11), 12);
        assert_eq!(smooth_at_least(2001), 2025);
        assert_eq!(smooth_at_least(1), 1);
    }

    #[test]
    fn transform_matches_the_definition_for_mixed_radices() {
        let p = 200;
        for n in [
            1usize, 2, 3, 4, 5, 6, 8, 9, 10, 12, 15, 16, 18, 25, 30, 45, 60, 64, 75, 90, 150, 200,
        ] {
            let roots = Roots::new(n, p);
            // a non-symmetric test function on [−1, 1]
            let fit = ChebFit::new(
                &Float::with_val(p, -1),
                &Float::with_val(p, 1),
                &roots,
                p,
                |x, out| {
                    out.assign(x * 3u32);
                    *out += 0.25f64;
                    out.exp_mut();
                    *out += Float::with_val(p, x.square_ref());
                },
            );
            let vals: Vec<Float> = (0..n)
                .map(|j| {
                    let x = roots.point(j, p);
                    let mut o = Float::with_val(p, &x * 3u32) + 0.25f64;
                    o.exp_mut();
                    o + Float::with_val(p, x.square_ref())
                })
                .collect();
            let want = direct(&vals, p);
            for (k, (a, b)) in fit.c.iter().zip(&want).enumerate() {
                let d = Float::with_val(p, a - b).abs().to_f64();
                assert!(d < 1e-55, "n = {n}, k = {k}: {d:e}");
            }
        }
    }

    #[test]
    fn integral_and_antiderivative_of_an_analytic_function() {
        // f(v) = 1/(1 + v²) on [0, 2]: ∫ = atan 2; P(v) = atan v. Poles at
        // ±i: ρ = |x + √(x²−1)| at x = −1 + i, ≈ 2.89, so 160 points give
        // ~245 bits.
        let p = 300;
        let roots = Roots::new(180, p);
        let a = Float::with_val(p, 0);
        let b = Float::with_val(p, 2);
        let fit = ChebFit::new(&a, &b, &roots, p, |v, out| {
            out.assign(v.square_ref());
            *out += 1u32;
            out.recip_mut();
        });
        let want = Float::with_val(p, 2u32).atan();
        let got = fit.integral();
        let err = Float::with_val(p, &got - &want).abs();
        assert!(err < Float::with_val(p, 1e-70), "{}", err.to_f64());
        let tail = fit.tail();
        assert!(
            tail < Float::with_val(p, 1e-70) && tail > 0u32,
            "{}",
            tail.to_f64()
        );
        let prim = fit.antiderivative();
        for v in ["0", "0.125", "0.9", "1.5", "2"] {
            let vv = Float::with_val(p, Float::parse(v).unwrap());
            let got = prim.eval(&vv, p);
            let want = Float::with_val(p, vv.atan_ref());
            let err = Float::with_val(p, &got - &want).abs();
            assert!(err < Float::with_val(p, 1e-70), "v = {v}: {}", err.to_f64());
        }
        // and the interpolant itself
        let vv = Float::with_val(p, 0.3);
        let got = fit.eval(&vv, p);
        let want = Float::with_val(p, Float::with_val(p, vv.square_ref()) + 1u32).recip();
        assert!(Float::with_val(p, &got - &want).abs() < Float::with_val(p, 1e-70));
    }

    #[test]
    fn coefficients_decay_at_the_bernstein_rate() {
        // 1/(1 + v²) on [0, 2]: |c_k| ~ ρ^(−k), ρ ≈ 2.89 (log10 ρ ≈ 0.46)
        let p = 200;
        let roots = Roots::new(120, p);
        let fit = ChebFit::new(
            &Float::with_val(p, 0),
            &Float::with_val(p, 2),
            &roots,
            p,
            |v, out| {
                out.assign(v.square_ref());
                *out += 1u32;
                out.recip_mut();
            },
        );
        // the largest of eight (complex-conjugate poles make c_k oscillate)
        let l = |k: usize| {
            fit.c[k..k + 8]
                .iter()
                .map(|c| c.to_f64().abs())
                .fold(0.0, f64::max)
                .log10()
        };
        let rate = (l(40) - l(100)) / 60.0;
        assert!((rate - 2.89f64.log10()).abs() < 0.03, "rate {rate}");
    }
}
