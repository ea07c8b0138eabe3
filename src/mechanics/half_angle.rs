//! The time integral of a conservative phase in the half-angle variable
//! s = sin(θ/2): the algebraic integrand (no trigonometry per evaluation)
//! in σ, in u (σ = Δσ sin²u) and in v (σ = v²), with its singularities for
//! the Gauss–Legendre convergence model ([`HalfAngleTime`]); and the split of
//! the integral from rest near the top whose logarithm in ln θ0 is exact
//! ([`TinyStart`]).

use super::dynamics::Dyn;
use rug::{Assign, Float};

/// The time integrand in the half-angle variable s = sin(θ/2), an algebraic
/// function (no trigonometry per evaluation):
///
/// dt = dθ/θ̇ = 2 √(K(c) / ((1 − s²) H)) ds,  c = cos θ = 1 − 2s²,
/// H = K θ̇² = K(θ0)θ̇0² + 2(g/r)(cos θ0 − cos θ) = K(θ0)θ̇0² + 4(g/r) σ (s + s0),
///
/// with σ = s − s0 the distance from the start, supplied exactly by the
/// quadrature (so H has no cancellation at the singular end). Written as
/// dt/dσ = F·√(K / ((1 − s²)(σ(s + s0) + h0'))), F = 1/√(g/r),
/// h0' = K(θ0)θ̇0²/(4 g/r). 1 − s² = cos²(θ/2) is free of cancellation while
/// θ stays away from π; the oracle uses this form up to θ = 2π/3 (1 − s² ≥ 1/4).
///
/// One evaluation costs one division, one square root and about ten
/// multiplications and additions, against one `sin_cos` more for the θ form.
#[derive(Debug, Clone)]
pub struct HalfAngleTime {
    /// sin(θ0/2).
    pub s0: Float,
    /// K coefficients.
    q: [Float; 3],
    q1_zero: bool,
    q2_zero: bool,
    /// K(θ0)θ̇0² / (4 g/r).
    h0r: Float,
    h0_zero: bool,
    /// 1/√(g/r).
    pub factor: Float,
    /// cos(θ0/2)
    c0h: Float,
    w: [Float; 3],
}

/// The half-angle integrands' common tail: with `s` = sin(θ/2) and `h` = H'
/// on entry, writes √(K(c) / ((1 − s²) H')) into `out`, c = cos θ = 1 − 2s²,
/// K(c) = (q2 c + q1) c + q0 without the terms that are exactly zero. `s`, `h`
/// and `a` are overwritten (scratch). No allocation.
#[inline(always)]
fn sqrt_k_over(
    q: &[Float; 3],
    q1_zero: bool,
    q2_zero: bool,
    [s, a, h]: [&mut Float; 3],
    out: &mut Float,
) {
    // (1 − s²) H'
    a.assign(s.square_ref());
    s.assign(1u32 - &*a);
    *h *= &*s;
    // c = 1 − 2 s²; K = (q2 c + q1) c + q0
    *a <<= 1;
    s.assign(1u32 - &*a);
    let c = &*s;
    if q2_zero {
        if q1_zero {
            out.assign(&q[0]);
        } else {
            out.assign(&q[1] * c);
            *out += &q[0];
        }
    } else {
        out.assign(&q[2] * c);
        *out += &q[1];
        *out *= c;
        *out += &q[0];
    }
    *out /= &*h;
    out.sqrt_mut();
}

impl HalfAngleTime {
    /// The integrand of `d`'s model at `d`'s precision.
    pub fn new(d: &Dyn) -> Self {
        let p = d.prec;
        let half = Float::with_val(p, &d.th0 / 2u32);
        let (s0, c0h) = half.sin_cos(Float::new(p));
        let gr4 = Float::with_val(p, &d.gr * 4u32);
        let h0r = Float::with_val(p, &d.h0 / &gr4);
        let factor = Float::with_val(p, d.gr.sqrt_ref()).recip();
        HalfAngleTime {
            s0,
            q: d.q.clone(),
            q1_zero: d.q[1].is_zero(),
            q2_zero: d.q[2].is_zero(),
            h0_zero: h0r.is_zero(),
            h0r,
            factor,
            c0h,
            w: std::array::from_fn(|_| Float::new(p)),
        }
    }

    /// Whether the start is from rest (θ̇0 = 0).
    pub fn from_rest(&self) -> bool {
        self.h0_zero
    }

    /// cos(θ0/2).
    pub fn cos_half0(&self) -> &Float {
        &self.c0h
    }

    /// σ = sin(θ/2) − sin(θ0/2) = 2 cos(θ0/2 + δ/4) sin(δ/4) for θ = θ0 + δ
    /// (no cancellation for small δ).
    pub fn sigma_of(&self, delta: &Float) -> Float {
        let p = self.s0.prec();
        let quarter = Float::with_val(p, delta / 4u32);
        let (sq, cq) = quarter.sin_cos(Float::new(p));
        // cos(θ0/2 + δ/4) = cos(θ0/2) cos(δ/4) − sin(θ0/2) sin(δ/4)
        let c = Float::with_val(p, &self.c0h * &cq) - Float::with_val(p, &self.s0 * &sq);
        Float::with_val(p, c * sq) * 2u32
    }

    /// Writes √(K(c) / ((1 − s²)(σ(s + s0) + h0'))) at distance σ into `out`
    /// (multiply the integral by [`HalfAngleTime::factor`]). No allocation.
    pub fn eval(&mut self, sigma: &Float, out: &mut Float) {
        let [s, a, b] = &mut self.w;
        s.assign(&self.s0 + sigma);
        // H' = σ (s + s0) + h0'
        b.assign(&*s + &self.s0);
        *b *= sigma;
        if !self.h0_zero {
            *b += &self.h0r;
        }
        sqrt_k_over(&self.q, self.q1_zero, self.q2_zero, [s, a, b], out);
    }
}

/// The half-angle time integral from rest near the top, split so that the
/// logarithm in ln θ0 is exact.
///
/// From rest (θ̇0 = 0) the half-angle integrand is F(s)/√(σ(σ + 2s0)) with
/// F(s) = √(K(c)/(1 − s²)), s = s0 + σ: for θ0 → 0 its near-singularity at
/// σ = −2s0 comes within 2s0 of the interval and t grows like ln(1/θ0),
/// which no quadrature of the whole integrand resolves (θ0 = 1e-200). With
/// u = s², F² = Kc(u)/(1 − u) is rational in u and
/// F(s) − F(s0) = (u − u0)·M(u)/((1 − u)(1 − u0)(F(s) + F(s0))),
/// M(u) = (1 − u0)(a1 + a2(u + u0)) + Kc(u0), Kc(u) = a0 + a1 u + a2 u²,
/// and u − u0 = σ(σ + 2s0). So
///
/// ∫_0^Δσ F/√(σ(σ+2s0)) dσ = 2 F(s0) asinh(√(Δσ/(2s0)))
///     + ∫_0^Δσ √(σ(σ+2s0)) M(u)/((1 − u)(1 − u0)(F(s) + F(s0))) dσ,
///
/// the first term in closed form, the second bounded and smooth on the
/// scale of the interval (its non-smooth part near σ ~ s0 weighs ~ s0²).
#[derive(Debug, Clone)]
pub struct TinyStart {
    s0: Float,
    u0: Float,
    /// Kc coefficients a0, a1, a2.
    a: [Float; 3],
    /// F(s0).
    pub f0: Float,
    /// (1 − u0)·... constant parts of M: M(u) = m0 + m1 u.
    m: [Float; 2],
    w: [Float; 3],
}

impl TinyStart {
    /// The split of `half`'s integral (from rest).
    pub fn new(half: &HalfAngleTime) -> Self {
        let p = half.s0.prec();
        let q = &half.q;
        let a0 = Float::with_val(p, &q[0] + &q[1]) + &q[2];
        let a1 = -(Float::with_val(p, &q[1] * 2u32) + Float::with_val(p, &q[2] * 4u32));
        let a2 = Float::with_val(p, &q[2] * 4u32);
        let s0 = half.s0.clone();
        let u0 = Float::with_val(p, s0.square_ref());
        let kc0 = Float::with_val(p, &a2 * &u0) + &a1;
        let kc0 = Float::with_val(p, kc0 * &u0) + &a0;
        let one_m_u0 = Float::with_val(p, 1u32 - &u0);
        let f0 = Float::with_val(p, &kc0 / &one_m_u0).sqrt();
        // M(u) = (1 − u0)(a1 + a2 u0) + Kc(u0) + (1 − u0) a2 · u
        let m1 = Float::with_val(p, &one_m_u0 * &a2);
        let m0 = Float::with_val(p, &a2 * &u0) + &a1;
        let m0 = Float::with_val(p, m0 * &one_m_u0) + &kc0;
        TinyStart {
            s0,
            u0,
            a: [a0, a1, a2],
            f0,
            m: [m0, m1],
            w: std::array::from_fn(|_| Float::new(p)),
        }
    }

    /// 2 F(s0) asinh(√(Δσ/(2 s0))): the closed-form part.
    pub fn log_part(&self, dsig: &Float) -> Float {
        let p = self.s0.prec();
        let x = Float::with_val(p, dsig / &self.s0) / 2u32;
        let v = x.sqrt().asinh();
        Float::with_val(p, &self.f0 * v) * 2u32
    }

    /// The regular integrand at σ.
    pub fn eval(&mut self, sigma: &Float, out: &mut Float) {
        let [s, u, t] = &mut self.w;
        s.assign(&self.s0 + sigma);
        u.assign(s.square_ref());
        // F(s) = √(Kc(u)/(1 − u))
        t.assign(&self.a[2] * &*u);
        *t += &self.a[1];
        *t *= &*u;
        *t += &self.a[0];
        s.assign(1u32 - &*u);
        *t /= &*s;
        t.sqrt_mut();
        *t += &self.f0;
        // (1 − u)(1 − u0)(F + F0)
        *t *= &*s;
        s.assign(1u32 - &self.u0);
        *t *= &*s;
        // M(u)
        out.assign(&self.m[1] * &*u);
        *out += &self.m[0];
        *out /= &*t;
        // √(σ(σ + 2 s0))
        s.assign(&self.s0 * 2u32);
        *s += sigma;
        *s *= sigma;
        s.sqrt_mut();
        *out *= &*s;
    }
}

impl HalfAngleTime {
    /// The integrand in u for σ = Δσ sin²u, u ∈ [0, π/2] (`sin`, `cos` = sin u,
    /// cos u), without its constant factor [`HalfAngleTime::u_factor`]:
    /// cos u·√(K/((1 − s²)(s + s0))) from rest (the σ^(−1/2) singularity
    /// divides out), cos u·sin u·√(K/((1 − s²)H')) otherwise. Analytic on the
    /// closed interval, for Gauss–Legendre. No allocation.
    pub fn eval_u(&mut self, dsig: &Float, sin: &Float, cos: &Float, out: &mut Float) {
        let [s, a, b] = &mut self.w;
        // σ = Δσ sin²u, s = s0 + σ
        a.assign(sin.square_ref());
        *a *= dsig;
        s.assign(&self.s0 + &*a);
        b.assign(&*s + &self.s0);
        if !self.h0_zero {
            *b *= &*a;
            *b += &self.h0r;
        }
        sqrt_k_over(&self.q, self.q1_zero, self.q2_zero, [s, a, b], out);
        *out *= cos;
        if !self.h0_zero {
            *out *= sin;
        }
    }

    /// The integrand in v = √σ (σ = v², dσ = 2v dv): writes
    /// 2√(K / ((1 − s²)(σ + 2s0))) from rest (the 1/√σ of the start cancels
    /// against 2v), 2v√(K / ((1 − s²) H')) otherwise, s = s0 + v²; the time
    /// is [`HalfAngleTime::factor`] times its integral over [0, √Δσ]. Both
    /// are analytic on the interval. No allocation.
    pub fn eval_v(&mut self, v: &Float, out: &mut Float) {
        let [s, a, b] = &mut self.w;
        a.assign(v.square_ref());
        s.assign(&self.s0 + &*a);
        // H' = σ (s + s0) + h0', or s + s0 = σ + 2 s0 from rest (÷ σ)
        b.assign(&*s + &self.s0);
        if !self.h0_zero {
            *b *= &*a;
            *b += &self.h0r;
        }
        sqrt_k_over(&self.q, self.q1_zero, self.q2_zero, [s, a, b], out);
        *out <<= 1;
        if !self.h0_zero {
            *out *= v;
        }
    }

    /// The constant factor of [`HalfAngleTime::eval_u`]'s integral:
    /// 2√Δσ/√(g/r) from rest, 2Δσ/√(g/r) otherwise.
    pub fn u_factor(&self, dsig: &Float) -> Float {
        let p = self.s0.prec();
        let f = if self.h0_zero {
            Float::with_val(p, dsig.sqrt_ref())
        } else {
            Float::with_val(p, dsig)
        };
        Float::with_val(p, f * &self.factor) * 2u32
    }

    /// The values of sin²u at which [`HalfAngleTime::eval_u`] is singular
    /// (s = ±1, K(1 − 2s²) = 0, H' = 0), as complex `f64` for the
    /// Gauss–Legendre convergence model ([`crate::numeric::gauss::rho_sin2`]).
    pub fn singular_sin2(&self, dsig: &Float) -> Vec<crate::numeric::gauss::C64> {
        use crate::numeric::gauss::C64;
        let s0 = self.s0.to_f64();
        let ds = dsig.to_f64();
        let q: Vec<f64> = self.q.iter().map(|x| x.to_f64()).collect();
        let mut svals = vec![C64::new(1.0, 0.0), C64::new(-1.0, 0.0)];
        // K(c) = 0 → c, then s = ±√((1 − c)/2)
        let mut cs = Vec::new();
        if q[2] != 0.0 {
            let disc = C64::new(q[1] * q[1] - 4.0 * q[2] * q[0], 0.0).sqrt();
            for sg in [1.0, -1.0] {
                cs.push(C64::new(
                    (-q[1] + sg * disc.re) / (2.0 * q[2]),
                    sg * disc.im / (2.0 * q[2]),
                ));
            }
        } else if q[1] != 0.0 {
            cs.push(C64::new(-q[0] / q[1], 0.0));
        }
        for c in cs {
            let r = C64::new((1.0 - c.re) / 2.0, -c.im / 2.0).sqrt();
            svals.push(r);
            svals.push(C64::new(-r.re, -r.im));
        }
        // H' = 0: s = −s0 from rest, s² = s0² − h0' otherwise
        if self.h0_zero {
            svals.push(C64::new(-s0, 0.0));
        } else {
            let r = C64::new(s0 * s0 - self.h0r.to_f64(), 0.0).sqrt();
            svals.push(r);
            svals.push(C64::new(-r.re, -r.im));
        }
        svals
            .into_iter()
            .map(|s| C64::new((s.re - s0) / ds, s.im / ds))
            .collect()
    }
}
