//! The forces of a conservative phase as polynomials in c = cos θ with
//! exact rational coefficients, split as P0(c) + A_H·P1(c) with A_H
//! carrying the start: N12 ([`N12Poly`]), N1, F1 and F21 ([`ForcePolys`]),
//! and polynomials in A_H as well as c ([`HPoly`]) for the events' roots.

use super::dynamics::Dyn;
use super::{Reduced, PSI2, X1};
use crate::model::{Contact, Floor};
use rug::{Assign, Float, Rational};

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
    /// Identically zero (every coefficient of every part).
    pub fn is_zero(&self) -> bool {
        self.parts.iter().all(|p| p.iter().all(|c| *c == 0))
    }

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
