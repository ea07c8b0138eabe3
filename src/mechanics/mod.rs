//! First-principles mechanics of the two cylinders.
//!
//! Velocity coordinates v = (ẋ1, φ̇1, ψ̇2, θ̇): x1 the centre of cylinder 1,
//! φ1 its clockwise rotation, ψ2 the counter-clockwise rotation of cylinder 2
//! (ψ2 = φ2 − θ in the paper's notation), θ the line of centres, clockwise
//! from vertical. With y1 = r1 and |centre distance| = r = r1 + r2 enforced,
//! the kinetic energy of the two bodies (centre-of-mass + spin) is
//!
//! T = ½(m1+m2)ẋ1² + ½I1φ̇1² + ½I2ψ̇2² + m2 r cosθ ẋ1θ̇ + ½m2r²θ̇²,
//!
//! i.e. T = ½ vᵀ(M0 + cosθ M1)v with constant 4×4 matrices M0, M1, and
//! V = m2 g r cosθ. Each contact model is a constant matrix B with v = B w,
//! w = (θ̇, ċ) where c are the remaining (cyclic) coordinates. The reduced
//! mass matrix BᵀMB = [[a, bᵀ], [b, C]] has C constant, so the conserved
//! momenta p = bθ̇ + Cċ eliminate ċ and leave
//!
//! M_eff(θ) = a − bᵀC⁻¹b = m2 r² K(cosθ),  K(c) = q0 + q1 c + q2 c²,
//!
//! an exact quadratic in cos θ whose coefficients are rationals computed here
//! by exact elimination (the Routh reduction / Schur complement). The θ motion
//! follows from ½ M_eff θ̇² + V = const and does not depend on p; every other
//! velocity is v_i = γ_i + (α_i + β_i cosθ) θ̇ with exact α, β and the drift γ
//! fixed by ω0, which integrates in closed form: x_i = γ_i t + α_i(θ−θ0) +
//! β_i(sinθ − sinθ0).
//!
//! The paper's formulas are not used here; `tests/closed_forms.rs` holds them
//! against this module.

pub mod dynamics;
pub mod half_angle;
pub mod kkt;
pub mod polys;
pub mod system;

use crate::error::{Error, Result};
use crate::model::{Contact, Floor, Ideal};
use nalgebra::{DMatrix, DVector};
use rug::Rational;

/// Index of x1 in the velocity vector.
pub const X1: usize = 0;
/// Index of φ1.
pub const PHI1: usize = 1;
/// Index of ψ2 (cylinder 2's counter-clockwise rotation).
pub const PSI2: usize = 2;
/// Index of θ.
pub const THETA: usize = 3;

/// The exact reduced dynamics of a model.
#[derive(Debug, Clone, PartialEq)]
pub struct Reduced {
    /// K(c) = `q[0] + q[1] c + q[2] c²`  (M_eff / (m2 r²)).
    pub q: [Rational; 3],
    /// For x1, φ1, ψ2: v_i = gamma_i + (alpha_i + beta_i cosθ) θ̇.
    pub alpha: [Rational; 3],
    /// See `alpha`.
    pub beta: [Rational; 3],
    /// Drift velocities (the velocities at θ̇ = 0), fixed by ω0.
    pub gamma: [Rational; 3],
    /// Names of the cyclic coordinates kept (for the conserved momenta).
    pub cyclic: Vec<&'static str>,
    /// B restricted to the kept cyclic columns (4 × n), for momenta.
    pub b_cyclic: Vec<[Rational; 4]>,
    /// The θ column of B.
    pub b_theta: [Rational; 4],
}

fn r(n: i64) -> Rational {
    Rational::from(n)
}

fn quad_form(u: &[Rational; 4], m: &DMatrix<Rational>, v: &[Rational; 4]) -> Rational {
    let mut s = Rational::new();
    for i in 0..4 {
        for j in 0..4 {
            if m[(i, j)] != 0 && u[i] != 0 && v[j] != 0 {
                s += Rational::from(&u[i] * &m[(i, j)]) * &v[j];
            }
        }
    }
    s
}

/// Inverts a small symmetric positive-definite rational matrix exactly
/// (Gauss–Jordan).
fn invert(c: &DMatrix<Rational>) -> Result<DMatrix<Rational>> {
    let n = c.nrows();
    let mut a = c.clone();
    let mut inv = DMatrix::from_fn(n, n, |i, j| if i == j { r(1) } else { r(0) });
    for col in 0..n {
        let piv = (col..n).find(|&i| a[(i, col)] != 0).ok_or_else(|| {
            Error::not_physical("the reduced mass matrix is singular (a massless cylinder?)")
        })?;
        if piv != col {
            a.swap_rows(piv, col);
            inv.swap_rows(piv, col);
        }
        let d = a[(col, col)].clone();
        for j in 0..n {
            a[(col, j)] /= &d;
            inv[(col, j)] /= &d;
        }
        for i in 0..n {
            if i != col && a[(i, col)] != 0 {
                let f = a[(i, col)].clone();
                for j in 0..n {
                    let t = Rational::from(&f * &a[(col, j)]);
                    a[(i, j)] -= t;
                    let t = Rational::from(&f * &inv[(col, j)]);
                    inv[(i, j)] -= t;
                }
            }
        }
    }
    Ok(inv)
}

impl Reduced {
    /// Derives the reduced dynamics of `model` (exact).
    pub fn new(model: &Ideal) -> Result<Self> {
        let p = model.params();
        let rr = p.r();
        let i1 = Rational::from(&p.k1 * &p.m1) * &p.r1 * &p.r1;
        let i2 = Rational::from(&p.k2 * &p.m2) * &p.r2 * &p.r2;
        let mut m0 = DMatrix::from_element(4, 4, r(0));
        m0[(X1, X1)] = Rational::from(&p.m1 + &p.m2);
        m0[(PHI1, PHI1)] = i1;
        m0[(PSI2, PSI2)] = i2;
        m0[(THETA, THETA)] = Rational::from(&p.m2 * &rr) * &rr;
        let mut m1 = DMatrix::from_element(4, 4, r(0));
        m1[(X1, THETA)] = Rational::from(&p.m2 * &rr);
        m1[(THETA, X1)] = Rational::from(&p.m2 * &rr);

        let roll2 = model.contact() == Contact::Roll;
        let r1_r2 = Rational::from(&p.r1 / &p.r2);
        let theta_col = [
            r(0),
            r(0),
            if roll2 {
                -Rational::from(&rr / &p.r2)
            } else {
                r(0)
            },
            r(1),
        ];
        let w0 = &model.start().omega0;
        let psi_col = [r(0), r(0), r(1), r(0)];
        let psi_drift = Rational::from(&r1_r2 * w0);
        let phi_psi = if roll2 { r1_r2.clone() } else { r(0) };
        // (name, column of B, drift velocity at θ̇ = 0 under common rolling ω0)
        let mut cols: Vec<(&'static str, [Rational; 4], Rational)> = Vec::new();
        match model.floor() {
            Floor::Roll => {
                cols.push(("phi1", [p.r1.clone(), r(1), phi_psi, r(0)], w0.clone()));
            }
            Floor::Slip => {
                cols.push(("x1", [r(1), r(0), r(0), r(0)], Rational::from(&p.r1 * w0)));
                cols.push(("phi1", [r(0), r(1), phi_psi, r(0)], w0.clone()));
            }
            Floor::Fixed => {}
        }
        if !roll2 {
            cols.push(("psi2", psi_col, psi_drift));
        }

        // Massless free coordinates (zero kinetic energy) carry no momentum:
        // their velocity is the drift and they drop out of the reduction.
        let mut gamma = [r(0), r(0), r(0)];
        let mut kept = Vec::new();
        for (name, col, drift) in cols {
            if quad_form(&col, &m0, &col) == 0 {
                for i in 0..3 {
                    gamma[i] += Rational::from(&col[i] * &drift);
                }
            } else {
                kept.push((name, col, drift));
            }
        }
        let n = kept.len();
        let a0 = quad_form(&theta_col, &m0, &theta_col);
        let a1 = quad_form(&theta_col, &m1, &theta_col);
        let b0 = DVector::from_fn(n, |j, _| quad_form(&kept[j].1, &m0, &theta_col));
        let b1 = DVector::from_fn(n, |j, _| quad_form(&kept[j].1, &m1, &theta_col));
        let c = DMatrix::from_fn(n, n, |i, j| quad_form(&kept[i].1, &m0, &kept[j].1));
        for i in 0..n {
            for j in 0..n {
                // C must not depend on θ for the reduction to be exact.
                assert!(
                    quad_form(&kept[i].1, &m1, &kept[j].1) == 0,
                    "cyclic block depends on theta"
                );
            }
        }
        let d = invert(&c)?;
        let db0 = DVector::from_fn(n, |i, _| {
            (0..n).fold(r(0), |s, j| s + Rational::from(&d[(i, j)] * &b0[j]))
        });
        let db1 = DVector::from_fn(n, |i, _| {
            (0..n).fold(r(0), |s, j| s + Rational::from(&d[(i, j)] * &b1[j]))
        });
        let dot = |u: &DVector<Rational>, v: &DVector<Rational>| {
            (0..n).fold(r(0), |s, j| s + Rational::from(&u[j] * &v[j]))
        };
        let mu = Rational::from(&p.m2 * &rr) * &rr;
        let q0 = (&a0 - dot(&b0, &db0)) / &mu;
        let q1 = (&a1 - (dot(&b0, &db1) * 2u32)) / &mu;
        let q2 = (-dot(&b1, &db1)) / &mu;

        let mut alpha = [
            theta_col[0].clone(),
            theta_col[1].clone(),
            theta_col[2].clone(),
        ];
        let mut beta = [r(0), r(0), r(0)];
        for (j, (_, col, drift)) in kept.iter().enumerate() {
            for i in 0..3 {
                alpha[i] -= Rational::from(&col[i] * &db0[j]);
                beta[i] -= Rational::from(&col[i] * &db1[j]);
                gamma[i] += Rational::from(&col[i] * drift);
            }
        }
        Ok(Reduced {
            q: [q0, q1, q2],
            alpha,
            beta,
            gamma,
            cyclic: kept.iter().map(|k| k.0).collect(),
            b_cyclic: kept.iter().map(|k| k.1.clone()).collect(),
            b_theta: theta_col,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::Exact;
    use crate::model::{Params, Start};

    fn q(a: i64, b: i64) -> Rational {
        Rational::from((a, b))
    }

    #[test]
    fn roll_roll_matches_eq_17_and_22() {
        // identical solid cylinders: A = 1/3, K = 1 + k2 − A(c − k2)²
        let m = Ideal::paper_default(Exact::zero());
        let red = Reduced::new(&m).unwrap();
        // K = 3/2 − (c² − c + 1/4)/3 = 17/12 + c/3 − c²/3
        assert_eq!(red.q, [q(17, 12), q(1, 3), q(-1, 3)]);
        // φ̇1 = −(A r/r1)(c − k2) θ̇ = (1/3) θ̇ − (2/3) c θ̇
        assert_eq!(red.alpha[PHI1], q(1, 3));
        assert_eq!(red.beta[PHI1], q(-2, 3));
        assert_eq!(red.cyclic, vec!["phi1"]);
    }

    #[test]
    fn fixed_roll_is_a_rolling_cylinder_on_a_log() {
        let mut p = Params::identical_solid();
        p.k2 = q(2, 5);
        let m = Ideal::new(p, Floor::Fixed, Contact::Roll, Start::rest(Exact::zero())).unwrap();
        let red = Reduced::new(&m).unwrap();
        assert_eq!(red.q, [q(7, 5), q(0, 1), q(0, 1)]);
        assert!(red.cyclic.is_empty());
    }

    #[test]
    fn massless_free_spin_drops_out() {
        // slip/slip with k1 = k2 = 0: φ1 and ψ2 are massless and free
        let mut p = Params::identical_solid();
        p.k1 = q(0, 1);
        p.k2 = q(0, 1);
        let m = Ideal::new(p, Floor::Slip, Contact::Slip, Start::rest(Exact::zero())).unwrap();
        let red = Reduced::new(&m).unwrap();
        assert_eq!(red.cyclic, vec!["x1"]);
        // eq. (40): K = (m1 + m2 sin²θ)/(m1+m2) = 1 − c²/2
        assert_eq!(red.q, [q(1, 1), q(0, 1), q(-1, 2)]);
    }
}
