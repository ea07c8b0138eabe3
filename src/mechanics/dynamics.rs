//! The reduced dynamics evaluated at a working precision.
//!
//! Every quantity is a function of δ = θ − θ0 (the motion runs towards
//! growing θ; the oracle mirrors a model that falls to the left). Writing the
//! trigonometry in δ keeps cos θ0 − cos θ = 2 sin(θ0+δ/2) sin(δ/2) and
//! sin θ − sin θ0 = 2 cos(θ0+δ/2) sin(δ/2) free of cancellation, and costs one
//! `sin_cos` per evaluation.

use super::{Reduced, PSI2, X1};
use crate::error::Result;
use crate::model::{Contact, Floor, Ideal};
use rug::{Assign, Float, Rational};

/// Constants of a model at one precision.
#[derive(Debug, Clone)]
pub struct Dyn {
    /// Working precision (bits).
    pub prec: u32,
    /// Floor model.
    pub floor: Floor,
    /// Contact model.
    pub contact: Contact,
    /// θ0, sin θ0, cos θ0.
    pub th0: Float,
    /// sin θ0.
    pub s0: Float,
    /// cos θ0.
    pub c0: Float,
    /// K coefficients.
    pub q: [Float; 3],
    /// K(θ0) θ̇0².
    pub h0: Float,
    /// g / r.
    pub gr: Float,
    /// m1, m2, r1, r2, r, g.
    pub m1: Float,
    /// m2.
    pub m2: Float,
    /// r1.
    pub r1: Float,
    /// r2.
    pub r2: Float,
    /// r = r1 + r2.
    pub r: Float,
    /// g.
    pub g: Float,
    /// I1 = k1 m1 r1².
    pub i1: Float,
    /// I2 = k2 m2 r2².
    pub i2: Float,
    /// Velocity coefficients (see [`Reduced`]).
    pub alpha: [Float; 3],
    /// See `alpha`.
    pub beta: [Float; 3],
    /// See `alpha`.
    pub gamma: [Float; 3],
    /// ψ2 at t = 0.
    pub psi0: Float,
    /// Columns of B for the kept cyclic coordinates (conserved momenta).
    pub b_cyclic: Vec<[Float; 4]>,
}

/// The state of the system at one angle.
#[derive(Debug, Clone)]
pub struct State {
    /// δ = θ − θ0.
    pub delta: Float,
    /// θ.
    pub theta: Float,
    /// sin θ.
    pub s: Float,
    /// cos θ.
    pub c: Float,
    /// sin θ − sin θ0 (cancellation-free).
    pub ds: Float,
    /// θ̇ (≥ 0).
    pub thetadot: Float,
    /// θ̈.
    pub thetaddot: Float,
    /// ẋ1, φ̇1, ψ̇2.
    pub v: [Float; 3],
    /// ẍ1, φ̈1, ψ̈2.
    pub a: [Float; 3],
}

/// Constraint forces, in the conventions of the README: F1, N1 the floor's
/// force on cylinder 1 (x, y); N12 the normal force between the cylinders
/// (positive while they press); F21 cylinder 1's force on cylinder 2 along
/// (cos θ, −sin θ).
#[derive(Debug, Clone)]
pub struct Forces {
    /// F1.
    pub f1: Float,
    /// N1.
    pub n1: Float,
    /// F21.
    pub f21: Float,
    /// N12.
    pub n12: Float,
}

impl Dyn {
    /// Constants of `model` (which must move towards growing θ) at `prec` bits.
    pub fn new(model: &Ideal, red: &Reduced, prec: u32) -> Result<Self> {
        let f = |q: &rug::Rational| Float::with_val(prec, q);
        let p = model.params();
        let st = model.start();
        let th0 = st.theta0.to_float(prec);
        let (s0, c0) = th0.clone().sin_cos(Float::new(prec));
        let q = [f(&red.q[0]), f(&red.q[1]), f(&red.q[2])];
        let k0 = Float::with_val(prec, &q[2] * &c0) + &q[1];
        let k0 = Float::with_val(prec, k0 * &c0) + &q[0];
        let td0 = f(&st.thetadot0);
        let h0 = Float::with_val(prec, k0 * &td0) * &td0;
        let r = f(&p.r());
        let g = f(&p.g);
        let gr = Float::with_val(prec, &g / &r);
        let r1 = f(&p.r1);
        let r2 = f(&p.r2);
        // φ2 = ψ2 + θ starts at 0 for every contact model (ψ2(0) = −θ0), as
        // φ1 does; a rolling contact then reads r2 φ2 = r1(φ1 − θ + θ0), the
        // paper's eq. 2 with its constant (the paper's φ2 is φ2 − r1 θ0/r2)
        let psi0 = Float::with_val(prec, -&th0);
        Ok(Dyn {
            prec,
            floor: model.floor(),
            contact: model.contact(),
            th0,
            s0,
            c0,
            q,
            h0,
            gr,
            m1: f(&p.m1),
            m2: f(&p.m2),
            i1: f(&(Rational3::prod(&p.k1, &p.m1, &p.r1) * &p.r1)),
            i2: f(&(Rational3::prod(&p.k2, &p.m2, &p.r2) * &p.r2)),
            r1,
            r2,
            r,
            g,
            alpha: [f(&red.alpha[0]), f(&red.alpha[1]), f(&red.alpha[2])],
            beta: [f(&red.beta[0]), f(&red.beta[1]), f(&red.beta[2])],
            gamma: [f(&red.gamma[0]), f(&red.gamma[1]), f(&red.gamma[2])],
            psi0,
            b_cyclic: red
                .b_cyclic
                .iter()
                .map(|col| [f(&col[0]), f(&col[1]), f(&col[2]), f(&col[3])])
                .collect(),
        })
    }

    /// K(c) = q0 + q1 c + q2 c².
    pub fn k_of(&self, c: &Float) -> Float {
        let t = Float::with_val(self.prec, &self.q[2] * c) + &self.q[1];
        Float::with_val(self.prec, t * c) + &self.q[0]
    }

    /// Trigonometry at δ: (sin θ, cos θ, sin(θ0+δ/2), cos(θ0+δ/2), sin(δ/2)).
    fn trig(&self, delta: &Float) -> [Float; 5] {
        let p = self.prec;
        let half = Float::with_val(p, delta / 2u32);
        let (sh, ch) = half.sin_cos(Float::new(p));
        let sm = Float::with_val(p, &self.s0 * &ch) + Float::with_val(p, &self.c0 * &sh);
        let cm = Float::with_val(p, &self.c0 * &ch) - Float::with_val(p, &self.s0 * &sh);
        // θ = (θ0 + δ/2) + δ/2
        let s = Float::with_val(p, &sm * &ch) + Float::with_val(p, &cm * &sh);
        let c = Float::with_val(p, &cm * &ch) - Float::with_val(p, &sm * &sh);
        [s, c, sm, cm, sh]
    }

    /// H(δ) = K θ̇² = K(θ0)θ̇0² + 2(g/r)(cos θ0 − cos θ), and cos θ.
    pub fn h_of(&self, delta: &Float) -> (Float, Float) {
        let [_, c, sm, _, sh] = self.trig(delta);
        let t = Float::with_val(self.prec, &sm * &sh) * &self.gr;
        (Float::with_val(self.prec, t * 4u32) + &self.h0, c)
    }

    /// dt/dθ = 1/θ̇ at δ, written into `out`: the energy quadrature's integrand.
    pub fn inv_thetadot(&self, delta: &Float, out: &mut Float) {
        let (h, c) = self.h_of(delta);
        out.assign(self.k_of(&c) / h);
        out.sqrt_mut();
    }

    /// [`Dyn::inv_thetadot`] without allocating: the same operations in the
    /// same order at the same precision (so the same bits), on `w`'s Floats.
    /// `out` must have this precision.
    pub fn inv_thetadot_with(&self, delta: &Float, out: &mut Float, w: &mut Scratch) {
        let [sh, ch, sm, cm, c, t1, t2, h] = &mut w.f;
        sh.assign(delta / 2u32);
        sh.sin_cos_mut(ch);
        t1.assign(&self.s0 * &*ch);
        t2.assign(&self.c0 * &*sh);
        sm.assign(&*t1 + &*t2);
        t1.assign(&self.c0 * &*ch);
        t2.assign(&self.s0 * &*sh);
        cm.assign(&*t1 - &*t2);
        // cos θ = cos(θ0+δ/2) cos(δ/2) − sin(θ0+δ/2) sin(δ/2)
        t1.assign(&*cm * &*ch);
        t2.assign(&*sm * &*sh);
        c.assign(&*t1 - &*t2);
        // H = 4 (g/r) sin(θ0+δ/2) sin(δ/2) + K(θ0) θ̇0²   (t2 = sm·sh)
        h.assign(&*t2 * &self.gr);
        *h <<= 2;
        *h += &self.h0;
        // K(c) = (q2 c + q1) c + q0
        t1.assign(&self.q[2] * &*c);
        *t1 += &self.q[1];
        *t1 *= &*c;
        *t1 += &self.q[0];
        out.assign(&*t1 / &*h);
        out.sqrt_mut();
    }

    /// The full state at δ.
    pub fn state(&self, delta: &Float) -> State {
        let p = self.prec;
        let [s, c, sm, cm, sh] = self.trig(delta);
        let h = Float::with_val(p, &sm * &sh) * &self.gr * 4u32 + &self.h0;
        let k = self.k_of(&c);
        let td2 = Float::with_val(p, &h / &k);
        let thetadot = if td2.is_sign_negative() {
            Float::with_val(p, f64::NAN)
        } else {
            Float::with_val(p, td2.sqrt_ref())
        };
        // θ̈ = [ (g/r) sinθ + ½ sinθ (q1 + 2 q2 c) θ̇² ] / K
        let dk = Float::with_val(p, &self.q[2] * &c) * 2u32 + &self.q[1];
        let num = Float::with_val(p, &dk * &td2) / 2u32 + &self.gr;
        let thetaddot = Float::with_val(p, num * &s) / &k;
        let mut v: [Float; 3] = [Float::new(p), Float::new(p), Float::new(p)];
        let mut a: [Float; 3] = [Float::new(p), Float::new(p), Float::new(p)];
        let s_td2 = Float::with_val(p, &s * &td2);
        for i in 0..3 {
            let lin = Float::with_val(p, &self.beta[i] * &c) + &self.alpha[i];
            v[i] = Float::with_val(p, &lin * &thetadot) + &self.gamma[i];
            a[i] =
                Float::with_val(p, &lin * &thetaddot) - Float::with_val(p, &self.beta[i] * &s_td2);
        }
        let ds = Float::with_val(p, &cm * &sh) * 2u32;
        let theta = Float::with_val(p, &self.th0 + delta);
        State {
            delta: delta.clone(),
            theta,
            s,
            c,
            ds,
            thetadot,
            thetaddot,
            v,
            a,
        }
    }

    /// x1, φ1, ψ2 at state `st` reached at time `t`.
    pub fn positions(&self, st: &State, t: &Float) -> [Float; 3] {
        let p = self.prec;
        let mut out: [Float; 3] = [Float::new(p), Float::new(p), Float::new(p)];
        for (i, o) in out.iter_mut().enumerate() {
            let x = Float::with_val(p, &self.gamma[i] * t)
                + Float::with_val(p, &self.alpha[i] * &st.delta)
                + Float::with_val(p, &self.beta[i] * &st.ds);
            *o = x;
        }
        out[PSI2] += &self.psi0;
        out
    }

    /// Constraint forces at `st` from the reduced dynamics (route 1): N12 from
    /// the radial motion of cylinder 2, F21 from its spin (torque), F1 and N1
    /// from the motion of the centre of mass of the pair (paper eqs. 26–28, 33).
    /// Forces at a frictionless contact are exactly 0.
    pub fn forces(&self, st: &State) -> Forces {
        let p = self.prec;
        let ax = &st.a[X1];
        let td2 = Float::with_val(p, st.thetadot.square_ref());
        let n12 = (Float::with_val(p, &self.g * &st.c) + Float::with_val(p, ax * &st.s)
            - Float::with_val(p, &self.r * &td2))
            * &self.m2;
        let f21 = match self.contact {
            Contact::Roll => Float::with_val(p, &self.i2 * &st.a[PSI2]) / &self.r2,
            Contact::Slip => Float::new(p),
        };
        let m12 = Float::with_val(p, &self.m1 + &self.m2);
        let f1 = match self.floor {
            Floor::Slip => Float::new(p),
            _ => {
                let tang =
                    Float::with_val(p, &st.c * &st.thetaddot) - Float::with_val(p, &st.s * &td2);
                Float::with_val(p, &m12 * ax) + tang * &self.r * &self.m2
            }
        };
        let rad = Float::with_val(p, &st.s * &st.thetaddot) + Float::with_val(p, &st.c * &td2);
        let n1 = Float::with_val(p, &m12 * &self.g) - rad * &self.r * &self.m2;
        Forces { f1, n1, f21, n12 }
    }

    /// Total energy T + V (V = m2 g y2 + const) from the full velocities.
    pub fn energy(&self, st: &State) -> Float {
        let p = self.prec;
        let [xd, pd, sd] = &st.v;
        let td = &st.thetadot;
        let m12 = Float::with_val(p, &self.m1 + &self.m2);
        let mut t = Float::with_val(p, &m12 * xd) * xd;
        t += Float::with_val(p, &self.i1 * pd) * pd;
        t += Float::with_val(p, &self.i2 * sd) * sd;
        t += Float::with_val(p, &self.r * &self.m2) * &st.c * xd * td * 2u32;
        t += Float::with_val(p, &self.r * &self.r) * &self.m2 * td * td;
        t /= 2u32;
        t + Float::with_val(p, &self.m2 * &self.g) * &self.r * &st.c
    }
}

impl Dyn {
    /// The conserved canonical momenta of the cyclic coordinates,
    /// p_j = B_jᵀ M(θ) v, from the full velocities.
    pub fn momenta(&self, st: &State) -> Vec<Float> {
        let p = self.prec;
        let m12 = Float::with_val(p, &self.m1 + &self.m2);
        let m2r = Float::with_val(p, &self.m2 * &self.r);
        // M v with v = (ẋ1, φ̇1, ψ̇2, θ̇)
        let mv = [
            Float::with_val(p, &m12 * &st.v[0]) + Float::with_val(p, &m2r * &st.c) * &st.thetadot,
            Float::with_val(p, &self.i1 * &st.v[1]),
            Float::with_val(p, &self.i2 * &st.v[2]),
            Float::with_val(p, &m2r * &st.c) * &st.v[0]
                + Float::with_val(p, &m2r * &self.r) * &st.thetadot,
        ];
        self.b_cyclic
            .iter()
            .map(|col| {
                let mut s = Float::new(p);
                for i in 0..4 {
                    s += Float::with_val(p, &col[i] * &mv[i]);
                }
                s
            })
            .collect()
    }
}

/// Reusable Floats for the allocation-free evaluations ([`Dyn::inv_thetadot_with`]).
#[derive(Debug, Clone)]
pub struct Scratch {
    f: [Float; 8],
}

impl Scratch {
    /// Scratch Floats at `prec` bits.
    pub fn new(prec: u32) -> Self {
        Scratch {
            f: std::array::from_fn(|_| Float::new(prec)),
        }
    }
}

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

/// N12·K(c)²/m2 as a polynomial in c = cos θ, split as P0(c) + A_H·P1(c)
/// with exact rational coefficients (ascending, degree ≤ 5), where
/// A_H = K(θ0)θ̇0² + 2(g/r) cos θ0 carries the start. From the reduced
/// dynamics with the energy integral θ̇² = H/K, H(c) = A_H − 2(g/r) c:
///
/// N12/m2 = g c + ẍ1 sin θ − r θ̇²,  ẍ1 = (α + β c) θ̈ − β sin θ θ̇²,
/// θ̈ = sin θ ((g/r) K + ½ K' H)/K²,  sin²θ = 1 − c²,
///
/// so N12·K²/m2 = g c K² + (1 − c²)(α + β c)(g/r) K + H·R(c) with
/// R = (1 − c²)(½(α + β c)K' − β K) − r K (α, β those of ẋ1, K' = dK/dc).
/// K > 0, so N12 has the sign of the polynomial.
#[derive(Debug, Clone, PartialEq)]
pub struct N12Poly {
    /// P0 (with H's −2(g/r)c part folded in).
    pub base: Vec<Rational>,
    /// P1 = R.
    pub per_h: Vec<Rational>,
}

fn qmul(a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    let mut out = vec![Rational::new(); (a.len() + b.len()).saturating_sub(1)];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += Rational::from(x * y);
        }
    }
    out
}

fn qadd(a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    (0..a.len().max(b.len()))
        .map(|i| {
            let mut s = Rational::new();
            if let Some(x) = a.get(i) {
                s += x;
            }
            if let Some(y) = b.get(i) {
                s += y;
            }
            s
        })
        .collect()
}

fn qscale(a: &[Rational], k: &Rational) -> Vec<Rational> {
    a.iter().map(|x| Rational::from(x * k)).collect()
}

impl N12Poly {
    /// The polynomial of a reduced model with parameters `p`.
    pub fn new(red: &Reduced, p: &crate::model::Params) -> Self {
        use super::X1;
        let r = p.r();
        let gr = Rational::from(&p.g / &r);
        let k = red.q.to_vec();
        let dk = vec![red.q[1].clone(), Rational::from(&red.q[2] * 2u32)];
        let lin = vec![red.alpha[X1].clone(), red.beta[X1].clone()];
        let one_m_c2 = vec![Rational::from(1), Rational::new(), Rational::from(-1)];
        let c = vec![Rational::new(), Rational::from(1)];
        // R = (1 − c²)(½ lin K' − β K) − r K
        let inner = qadd(
            &qscale(&qmul(&lin, &dk), &Rational::from((1, 2))),
            &qscale(&k, &Rational::from(-&red.beta[X1])),
        );
        let rr = qadd(&qmul(&one_m_c2, &inner), &qscale(&k, &Rational::from(-&r)));
        // P0 = g c K² + (1 − c²) lin (g/r) K − 2 (g/r) c R
        let gck2 = qscale(&qmul(&c, &qmul(&k, &k)), &p.g);
        let lin_k = qscale(&qmul(&one_m_c2, &qmul(&lin, &k)), &gr);
        let h_part = qscale(&qmul(&c, &rr), &Rational::from(&gr * -2i32));
        let base = qadd(&qadd(&gck2, &lin_k), &h_part);
        N12Poly { base, per_h: rr }
    }

    /// A_H = K(θ0)θ̇0² + 2(g/r) cos θ0 at `d`'s precision.
    pub fn a_h(d: &Dyn) -> Float {
        let p = d.prec;
        Float::with_val(p, &d.gr * &d.c0) * 2u32 + &d.h0
    }

    /// The coefficients P0 + A_H·P1 at `prec` bits.
    pub fn at(&self, a_h: &Float, prec: u32) -> Vec<Float> {
        (0..self.base.len().max(self.per_h.len()))
            .map(|i| {
                let mut v = Float::new(prec);
                if let Some(x) = self.per_h.get(i) {
                    v.assign(x);
                    v *= a_h;
                }
                if let Some(x) = self.base.get(i) {
                    v += x;
                }
                v
            })
            .collect()
    }
}

/// The constraint forces as polynomials in c = cos θ along the motion, each
/// split as P0(c) + A_H·P1(c) with exact rational coefficients like
/// [`N12Poly`] (A_H = K(θ0)θ̇0² + 2(g/r) cos θ0):
///
/// with Θ = (g/r)K + ½K'H, H = A_H − 2(g/r)c, θ̈ = sin θ·Θ/K², θ̇² = H/K,
///
/// - N1·K² = (m1 + m2) g K² − m2 r ((1 − c²)Θ + c H K);
/// - F1·K²/sin θ = (m1 + m2)(lin Θ − β H K) + m2 r (c Θ − H K), lin = α + βc
///   of ẋ1 (a held cylinder 1 has α = β = 0; 0 on a frictionless floor);
/// - F21·K²/sin θ = (I2/r2)(lin2 Θ − β2 H K), lin2 = α2 + β2 c of ψ̇2
///   (0 at a frictionless contact).
///
/// K > 0, so N1 has the sign of its polynomial, and F1/N1 = sin θ·P_F1/P_N1.
#[derive(Debug, Clone, PartialEq)]
pub struct ForcePolys {
    /// N1·K²: (P0, P1).
    pub n1: (Vec<Rational>, Vec<Rational>),
    /// F1·K²/sin θ.
    pub f1: (Vec<Rational>, Vec<Rational>),
    /// F21·K²/sin θ.
    pub f21: (Vec<Rational>, Vec<Rational>),
    /// K(c).
    pub k: Vec<Rational>,
}

impl ForcePolys {
    /// The polynomials of a reduced model with parameters `p` and contacts.
    pub fn new(red: &Reduced, p: &crate::model::Params, floor: Floor, contact: Contact) -> Self {
        let r = p.r();
        let gr = Rational::from(&p.g / &r);
        let k = red.q.to_vec();
        let dk = vec![red.q[1].clone(), Rational::from(&red.q[2] * 2u32)];
        let c = vec![Rational::new(), Rational::from(1)];
        let one_m_c2 = vec![Rational::from(1), Rational::new(), Rational::from(-1)];
        let half = Rational::from((1, 2));
        // Θ = [(g/r)K − (g/r) c K'] + A_H ½K'
        let theta0 = qadd(
            &qscale(&k, &gr),
            &qscale(&qmul(&c, &dk), &Rational::from(-&gr)),
        );
        let theta1 = qscale(&dk, &half);
        // H K = [−2(g/r) c K] + A_H K
        let hk0 = qscale(&qmul(&c, &k), &Rational::from(&gr * -2i32));
        let hk1 = k.clone();
        let m12 = Rational::from(&p.m1 + &p.m2);
        let m2r = Rational::from(&p.m2 * &r);
        // N1 K² = m12 g K² − m2 r ((1 − c²)Θ + c HK)
        let n1_part = |th: &[Rational], hk: &[Rational]| {
            qscale(
                &qadd(&qmul(&one_m_c2, th), &qmul(&c, hk)),
                &Rational::from(-&m2r),
            )
        };
        let n1 = (
            qadd(
                &qscale(&qmul(&k, &k), &Rational::from(&m12 * &p.g)),
                &n1_part(&theta0, &hk0),
            ),
            n1_part(&theta1, &hk1),
        );
        // F1 K²/s = m12 (lin Θ − β HK) + m2 r (c Θ − HK)
        let lin = vec![red.alpha[X1].clone(), red.beta[X1].clone()];
        let beta = red.beta[X1].clone();
        let f1_part = |th: &[Rational], hk: &[Rational]| {
            let a = qadd(&qmul(&lin, th), &qscale(hk, &Rational::from(-&beta)));
            let b = qadd(&qmul(&c, th), &qscale(hk, &Rational::from(-1)));
            qadd(&qscale(&a, &m12), &qscale(&b, &m2r))
        };
        let f1 = if floor == Floor::Slip {
            (vec![Rational::new()], vec![Rational::new()])
        } else {
            (f1_part(&theta0, &hk0), f1_part(&theta1, &hk1))
        };
        // F21 K²/s = (I2/r2)(lin2 Θ − β2 HK)
        let lin2 = vec![red.alpha[PSI2].clone(), red.beta[PSI2].clone()];
        let beta2 = red.beta[PSI2].clone();
        let i2r2 = Rational::from(&p.k2 * &p.m2) * &p.r2;
        let f21_part = |th: &[Rational], hk: &[Rational]| {
            qscale(
                &qadd(&qmul(&lin2, th), &qscale(hk, &Rational::from(-&beta2))),
                &i2r2,
            )
        };
        let f21 = if contact == Contact::Slip {
            (vec![Rational::new()], vec![Rational::new()])
        } else {
            (f21_part(&theta0, &hk0), f21_part(&theta1, &hk1))
        };
        ForcePolys { n1, f1, f21, k }
    }

    /// P0 + A_H·P1 at `prec` bits.
    pub fn at(part: &(Vec<Rational>, Vec<Rational>), a_h: &Float, prec: u32) -> Vec<Float> {
        (0..part.0.len().max(part.1.len()))
            .map(|i| {
                let mut v = Float::new(prec);
                if let Some(x) = part.1.get(i) {
                    v.assign(x);
                    v *= a_h;
                }
                if let Some(x) = part.0.get(i) {
                    v += x;
                }
                v
            })
            .collect()
    }
}

/// A polynomial in c whose coefficients are polynomials in A_H:
/// `parts[j]` multiplies A_H^j (exact rationals, ascending in c).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct HPoly {
    /// The parts by power of A_H.
    pub parts: Vec<Vec<Rational>>,
}

impl HPoly {
    /// P0 + A_H P1.
    pub fn linear(part: &(Vec<Rational>, Vec<Rational>)) -> Self {
        HPoly {
            parts: vec![part.0.clone(), part.1.clone()],
        }
    }

    /// A polynomial free of A_H.
    pub fn constant(c: &[Rational]) -> Self {
        HPoly {
            parts: vec![c.to_vec()],
        }
    }

    /// The product.
    pub fn mul(&self, o: &HPoly) -> HPoly {
        let mut parts = vec![Vec::new(); self.parts.len() + o.parts.len() - 1];
        for (i, a) in self.parts.iter().enumerate() {
            for (j, b) in o.parts.iter().enumerate() {
                parts[i + j] = qadd(&parts[i + j], &qmul(a, b));
            }
        }
        HPoly { parts }
    }

    /// The sum with `k`·o.
    pub fn add_scaled(&self, o: &HPoly, k: &Rational) -> HPoly {
        let n = self.parts.len().max(o.parts.len());
        let empty = Vec::new();
        HPoly {
            parts: (0..n)
                .map(|i| {
                    qadd(
                        self.parts.get(i).unwrap_or(&empty),
                        &qscale(o.parts.get(i).unwrap_or(&empty), k),
                    )
                })
                .collect(),
        }
    }

    /// d/dc.
    pub fn deriv(&self) -> HPoly {
        HPoly {
            parts: self
                .parts
                .iter()
                .map(|p| {
                    p.iter()
                        .enumerate()
                        .skip(1)
                        .map(|(i, x)| Rational::from(x * i as u32))
                        .collect()
                })
                .collect(),
        }
    }

    /// The coefficients in c at `prec` bits for the given A_H.
    pub fn at(&self, a_h: &Float, prec: u32) -> Vec<Float> {
        let n = self.parts.iter().map(|p| p.len()).max().unwrap_or(0);
        (0..n)
            .map(|i| {
                // Horner in A_H
                let mut v = Float::new(prec);
                for part in self.parts.iter().rev() {
                    v *= a_h;
                    if let Some(x) = part.get(i) {
                        v += x;
                    }
                }
                v
            })
            .collect()
    }
}

/// Small helper: exact product of three rationals.
struct Rational3;
impl Rational3 {
    fn prod(a: &rug::Rational, b: &rug::Rational, c: &rug::Rational) -> rug::Rational {
        rug::Rational::from(a * b) * c
    }
}
