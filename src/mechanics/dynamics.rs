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
use rug::{Assign, Float};

pub mod shadow;

pub use super::half_angle::{HalfAngleTime, TinyStart};
pub use super::polys::{ForcePolys, HPoly, N12Poly};

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
    /// Products of the constants the forces, the energy and the momenta
    /// use, each rounded as those formulas round it.
    k: Products,
    /// The constants in binary64 for the rows' error ([`shadow`]), built on
    /// first use.
    shadow: std::sync::OnceLock<shadow::Consts>,
}

/// Products of [`Dyn`]'s constants, each rounded as the formulas that use
/// them round it, from `m1`, `m2`, `r`, `g` as [`Dyn::new`] sets them (those
/// fields are not to be changed afterwards).
#[derive(Debug, Clone)]
struct Products {
    /// m1 + m2.
    m12: Float,
    /// (m1 + m2) g.
    m12g: Float,
    /// r m2.
    rm2: Float,
    /// (r r) m2.
    rrm2: Float,
    /// (m2 g) r.
    m2gr: Float,
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
        let (m1, m2) = (f(&p.m1), f(&p.m2));
        let m12 = Float::with_val(prec, &m1 + &m2);
        let m12g = Float::with_val(prec, &m12 * &g);
        let rm2 = Float::with_val(prec, &r * &m2);
        let rrm2 = Float::with_val(prec, &r * &r) * &m2;
        let m2gr = Float::with_val(prec, &m2 * &g) * &r;
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
            m1,
            m2,
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
            k: Products {
                m12,
                m12g,
                rm2,
                rrm2,
                m2gr,
            },
            shadow: std::sync::OnceLock::new(),
        })
    }

    /// K(c) = q0 + q1 c + q2 c².
    pub fn k_of(&self, c: &Float) -> Float {
        let mut t = Float::with_val(self.prec, &self.q[2] * c);
        t += &self.q[1];
        t *= c;
        t += &self.q[0];
        t
    }

    /// Trigonometry at δ: (sin θ, cos θ, sin(θ0+δ/2), cos(θ0+δ/2), sin(δ/2)).
    fn trig(&self, delta: &Float) -> [Float; 5] {
        let p = self.prec;
        let half = Float::with_val(p, delta / 2u32);
        let (sh, ch) = crate::numeric::trig::sin_cos(&half, p);
        // each sum of two products rounded as written, one temporary reused
        let mut t = Float::with_val(p, &self.c0 * &sh);
        let mut sm = Float::with_val(p, &self.s0 * &ch);
        sm += &t;
        t.assign(&self.s0 * &sh);
        let mut cm = Float::with_val(p, &self.c0 * &ch);
        cm -= &t;
        // θ = (θ0 + δ/2) + δ/2
        t.assign(&cm * &sh);
        let mut s = Float::with_val(p, &sm * &ch);
        s += &t;
        t.assign(&sm * &sh);
        let mut c = Float::with_val(p, &cm * &ch);
        c -= &t;
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
        t1.assign(delta / 2u32);
        crate::numeric::trig::sin_cos_into(t1, sh, ch);
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
        // the formulas' roundings, in place on a few temporaries
        let mut h = Float::with_val(p, &sm * &sh);
        h *= &self.gr;
        h *= 4u32;
        h += &self.h0;
        let k = self.k_of(&c);
        let td2 = Float::with_val(p, &h / &k);
        let thetadot = if td2.is_sign_negative() {
            Float::with_val(p, f64::NAN)
        } else {
            Float::with_val(p, td2.sqrt_ref())
        };
        // θ̈ = [ (g/r) sinθ + ½ sinθ (q1 + 2 q2 c) θ̇² ] / K
        let mut thetaddot = Float::with_val(p, &self.q[2] * &c);
        thetaddot *= 2u32;
        thetaddot += &self.q[1];
        thetaddot *= &td2;
        thetaddot /= 2u32;
        thetaddot += &self.gr;
        thetaddot *= &s;
        thetaddot /= &k;
        let mut v: [Float; 3] = [Float::new(p), Float::new(p), Float::new(p)];
        let mut a: [Float; 3] = [Float::new(p), Float::new(p), Float::new(p)];
        let s_td2 = Float::with_val(p, &s * &td2);
        // lin = β c + α; v = lin θ̇ + γ; a = lin θ̈ − β s θ̇²
        let (mut lin, mut u) = (h, k);
        for i in 0..3 {
            lin.assign(&self.beta[i] * &c);
            lin += &self.alpha[i];
            v[i].assign(&lin * &thetadot);
            v[i] += &self.gamma[i];
            a[i].assign(&lin * &thetaddot);
            u.assign(&self.beta[i] * &s_td2);
            a[i] -= &u;
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
        let mut out = self.moved(st, t);
        out[PSI2] += &self.psi0;
        out
    }

    /// x1, φ1 and φ2 = ψ2 + θ at state `st` reached at time `t`. φ2 is
    /// summed as (ψ2 − ψ0) + δ: ψ0 = −θ0, so the two constants cancel
    /// exactly (added to ψ2 and to θ, their roundings cost φ2 the digits by
    /// which it is smaller than θ0 — 11 at t = 1e-5 from rest).
    pub fn positions_phi2(&self, st: &State, t: &Float) -> [Float; 3] {
        let mut out = self.moved(st, t);
        out[PSI2] += &st.delta;
        out
    }

    /// x1, φ1 and ψ2 − ψ0: γ t + α δ + β (sin θ − sin θ0).
    fn moved(&self, st: &State, t: &Float) -> [Float; 3] {
        let p = self.prec;
        let mut out: [Float; 3] = [Float::new(p), Float::new(p), Float::new(p)];
        let mut u = Float::new(p);
        for (i, o) in out.iter_mut().enumerate() {
            o.assign(&self.gamma[i] * t);
            u.assign(&self.alpha[i] * &st.delta);
            *o += &u;
            u.assign(&self.beta[i] * &st.ds);
            *o += &u;
        }
        out
    }

    /// Constraint forces at `st` from the reduced dynamics (route 1): N12 from
    /// the radial motion of cylinder 2, F21 from its spin (torque), F1 and N1
    /// from the motion of the centre of mass of the pair (paper eqs. 26–28, 33).
    /// Forces at a frictionless contact are exactly 0.
    pub fn forces(&self, st: &State) -> Forces {
        let p = self.prec;
        let ax = &st.a[X1];
        let Products { m12, m12g, .. } = &self.k;
        let td2 = Float::with_val(p, st.thetadot.square_ref());
        // (g c + ẍ1 s − r θ̇²) m2, summed as written
        let mut t = Float::with_val(p, ax * &st.s);
        let mut n12 = Float::with_val(p, &self.g * &st.c);
        n12 += &t;
        t.assign(&self.r * &td2);
        n12 -= &t;
        n12 *= &self.m2;
        let f21 = match self.contact {
            Contact::Roll => Float::with_val(p, &self.i2 * &st.a[PSI2]) / &self.r2,
            Contact::Slip => Float::new(p),
        };
        let mut u = Float::new(p);
        let f1 = match self.floor {
            Floor::Slip => Float::new(p),
            _ => {
                // (m1 + m2) ẍ1 + (c θ̈ − s θ̇²) r m2
                t.assign(&st.c * &st.thetaddot);
                u.assign(&st.s * &td2);
                t -= &u;
                t *= &self.r;
                t *= &self.m2;
                let mut f1 = Float::with_val(p, m12 * ax);
                f1 += &t;
                f1
            }
        };
        // (m1 + m2) g − (s θ̈ + c θ̇²) r m2
        t.assign(&st.s * &st.thetaddot);
        u.assign(&st.c * &td2);
        t += &u;
        t *= &self.r;
        t *= &self.m2;
        let n1 = Float::with_val(p, m12g - &t);
        Forces { f1, n1, f21, n12 }
    }

    /// Total energy T + V from the full velocities, V = m2 g (y2 − r1) =
    /// m2 g r cos θ (heights above cylinder 1's centre, as
    /// [`crate::mechanics::system::System::energy`]).
    pub fn energy(&self, st: &State) -> Float {
        let p = self.prec;
        let [xd, pd, sd] = &st.v;
        let td = &st.thetadot;
        let Products {
            m12,
            rm2,
            rrm2,
            m2gr,
            ..
        } = &self.k;
        // the terms rounded as (m1+m2) ẋ1 ẋ1 + I1 φ̇1 φ̇1 + I2 ψ̇2 ψ̇2
        // + (r m2) c ẋ1 θ̇ 2 + ((r r) m2) θ̇ θ̇, halved, + ((m2 g) r) c
        let mut t = Float::with_val(p, m12 * xd);
        t *= xd;
        let mut u = Float::with_val(p, &self.i1 * pd);
        u *= pd;
        t += &u;
        u.assign(&self.i2 * sd);
        u *= sd;
        t += &u;
        u.assign(rm2 * &st.c);
        u *= xd;
        u *= td;
        u *= 2u32;
        t += &u;
        u.assign(rrm2 * td);
        u *= td;
        t += &u;
        t /= 2u32;
        u.assign(m2gr * &st.c);
        t += &u;
        t
    }
}

impl Dyn {
    /// The conserved canonical momenta of the cyclic coordinates,
    /// p_j = B_jᵀ M(θ) v, from the full velocities.
    pub fn momenta(&self, st: &State) -> Vec<Float> {
        let p = self.prec;
        let (m12, m2r) = (&self.k.m12, &self.k.rm2);
        // M v with v = (ẋ1, φ̇1, ψ̇2, θ̇)
        let mv = [
            Float::with_val(p, m12 * &st.v[0]) + Float::with_val(p, m2r * &st.c) * &st.thetadot,
            Float::with_val(p, &self.i1 * &st.v[1]),
            Float::with_val(p, &self.i2 * &st.v[2]),
            Float::with_val(p, m2r * &st.c) * &st.v[0]
                + Float::with_val(p, m2r * &self.r) * &st.thetadot,
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

/// Small helper: exact product of three rationals.
struct Rational3;
impl Rational3 {
    fn prod(a: &rug::Rational, b: &rug::Rational, c: &rug::Rational) -> rug::Rational {
        rug::Rational::from(a * b) * c
    }
}
