//! The second route to the forces: Lagrange's equations with multipliers
//! (paper appendix A.5, eq. 57) in the six coordinates
//! q = (x1, y1, φ1, ψ2, θ, r), all constraints relaxed and re-imposed by
//! multipliers. At a state on the constraint manifold (y1 = r1, r = r1 + r2,
//! ẏ1 = ṙ = 0) the accelerations and multipliers solve the KKT system
//!
//! ```text
//! [ M  −Jᵀ ] [ q̈ ]   [ h ]
//! [ J   0  ] [ λ ] = [ 0 ]
//! ```
//!
//! with M(q) the 6×6 mass matrix, h the gravity and velocity terms and J the
//! constraint rows. The multipliers are the constraint forces: λ(f1) = F1,
//! λ(f2) = F21, λ(f3) = N12, λ(f4) = N1 (paper eqs. 110–114), and for a fixed
//! floor λ(x1) = F1 and λ(φ1) = the holding torque.
//!
//! Shares nothing with the reduced route but the model: it is how the tests
//! check the forces and θ̈ of `dynamics`.

use crate::error::{Error, Result};
use crate::model::{Contact, Floor};
use nalgebra::DMatrix;
use rug::Float;

/// Coordinates of the KKT system.
const NQ: usize = 6;
const QX: usize = 0;
const QY: usize = 1;
const QPHI: usize = 2;
const QPSI: usize = 3;
const QTH: usize = 4;
const QR: usize = 5;

/// Physical constants for the KKT system (precision of the Floats).
#[derive(Debug, Clone)]
pub struct Bodies {
    /// m1.
    pub m1: Float,
    /// m2.
    pub m2: Float,
    /// r1.
    pub r1: Float,
    /// r2.
    pub r2: Float,
    /// I1.
    pub i1: Float,
    /// I2.
    pub i2: Float,
    /// g.
    pub g: Float,
}

/// The solution of the KKT system at one state.
#[derive(Debug, Clone)]
pub struct KktSolution {
    /// ẍ1, ÿ1, φ̈1, ψ̈2, θ̈, r̈.
    pub qdd: Vec<Float>,
    /// F1 (x force of the floor or holder on cylinder 1).
    pub f1: Float,
    /// N1.
    pub n1: Float,
    /// F21.
    pub f21: Float,
    /// N12.
    pub n12: Float,
    /// Holding torque on cylinder 1 (fixed floor), else 0.
    pub hold: Float,
}

/// Solves the KKT system at θ with θ̇ and the velocities ẋ1, φ̇1, ψ̇2 (which
/// do not enter: the constraint Jacobian is constant on the manifold, and T
/// depends on q only through θ and r).
pub fn solve(
    b: &Bodies,
    floor: Floor,
    contact: Contact,
    theta: &Float,
    thetadot: &Float,
) -> Result<KktSolution> {
    let p = theta.prec();
    let z = || Float::new(p);
    let (s, c) = theta.clone().sin_cos(Float::new(p));
    let r = Float::with_val(p, &b.r1 + &b.r2);
    let m12 = Float::with_val(p, &b.m1 + &b.m2);
    let m2r = Float::with_val(p, &b.m2 * &r);
    let td2 = Float::with_val(p, thetadot.square_ref());

    let mut m = DMatrix::from_fn(NQ, NQ, |_, _| z());
    m[(QX, QX)] = m12.clone();
    m[(QY, QY)] = m12.clone();
    m[(QPHI, QPHI)] = b.i1.clone();
    m[(QPSI, QPSI)] = b.i2.clone();
    m[(QTH, QTH)] = Float::with_val(p, &m2r * &r);
    m[(QR, QR)] = b.m2.clone();
    let sym = |m: &mut DMatrix<Float>, i, j, v: Float| {
        m[(i, j)] = v.clone();
        m[(j, i)] = v;
    };
    sym(&mut m, QX, QTH, Float::with_val(p, &m2r * &c));
    sym(&mut m, QY, QTH, -Float::with_val(p, &m2r * &s));
    sym(&mut m, QX, QR, Float::with_val(p, &b.m2 * &s));
    sym(&mut m, QY, QR, Float::with_val(p, &b.m2 * &c));
    // h: generalized forces of gravity and the velocity (centripetal) terms
    let mut h = vec![z(); NQ];
    h[QX] = Float::with_val(p, &m2r * &td2) * &s;
    h[QY] = Float::with_val(p, &m2r * &td2) * &c - Float::with_val(p, &m12 * &b.g);
    h[QTH] = Float::with_val(p, &m2r * &b.g) * &s;
    h[QR] = Float::with_val(p, &m2r * &td2) - Float::with_val(p, &b.m2 * &b.g) * &c;

    // constraint rows and the name of each multiplier
    let row = |entries: &[(usize, Float)]| {
        let mut r = vec![z(); NQ];
        for (i, v) in entries {
            r[*i] = v.clone();
        }
        r
    };
    let one = Float::with_val(p, 1u32);
    let mut rows: Vec<(&str, Vec<Float>)> = Vec::new();
    match floor {
        Floor::Roll => rows.push((
            "F1",
            row(&[(QX, one.clone()), (QPHI, Float::with_val(p, -&b.r1))]),
        )),
        Floor::Slip => {}
        Floor::Fixed => {
            rows.push(("F1", row(&[(QX, one.clone())])));
            rows.push(("hold", row(&[(QPHI, one.clone())])));
        }
    }
    if contact == Contact::Roll {
        rows.push((
            "F21",
            row(&[
                (QPHI, Float::with_val(p, -&b.r1)),
                (QPSI, b.r2.clone()),
                (QTH, r.clone()),
            ]),
        ));
    }
    rows.push(("N12", row(&[(QR, one.clone())])));
    rows.push(("N1", row(&[(QY, one.clone())])));

    // A coordinate with no inertia and no constraint is free and massless:
    // drop it (its acceleration is undetermined and irrelevant).
    let mut active: Vec<usize> = (0..NQ).collect();
    active.retain(|&i| !(m[(i, i)].is_zero() && rows.iter().all(|(_, r)| r[i].is_zero())));
    let n = active.len() + rows.len();
    let mut a = DMatrix::from_fn(n, n, |_, _| z());
    let mut rhs = vec![z(); n];
    for (ii, &i) in active.iter().enumerate() {
        for (jj, &j) in active.iter().enumerate() {
            a[(ii, jj)] = m[(i, j)].clone();
        }
        for (k, (_, r)) in rows.iter().enumerate() {
            a[(ii, active.len() + k)] = Float::with_val(p, -&r[i]);
            a[(active.len() + k, ii)] = r[i].clone();
        }
        rhs[ii] = h[i].clone();
    }
    let x = gauss(a, rhs)
        .ok_or_else(|| Error::not_physical("the constraint (KKT) system is singular"))?;
    let mut qdd = vec![z(); NQ];
    for (ii, &i) in active.iter().enumerate() {
        qdd[i] = x[ii].clone();
    }
    let lam = |name: &str| {
        rows.iter()
            .position(|(n, _)| *n == name)
            .map(|k| x[active.len() + k].clone())
            .unwrap_or_else(z)
    };
    Ok(KktSolution {
        f1: lam("F1"),
        n1: lam("N1"),
        f21: lam("F21"),
        n12: lam("N12"),
        hold: lam("hold"),
        qdd,
    })
}

/// Gaussian elimination with partial pivoting; `None` if singular.
fn gauss(mut a: DMatrix<Float>, mut b: Vec<Float>) -> Option<Vec<Float>> {
    let n = b.len();
    for col in 0..n {
        let piv = (col..n).max_by(|&i, &j| {
            let ai = Float::with_val(a[(i, col)].prec(), a[(i, col)].abs_ref());
            let aj = Float::with_val(a[(j, col)].prec(), a[(j, col)].abs_ref());
            ai.partial_cmp(&aj).unwrap_or(std::cmp::Ordering::Equal)
        })?;
        if a[(piv, col)].is_zero() {
            return None;
        }
        if piv != col {
            a.swap_rows(piv, col);
            b.swap(piv, col);
        }
        for i in col + 1..n {
            if a[(i, col)].is_zero() {
                continue;
            }
            let f = Float::with_val(a[(i, col)].prec(), &a[(i, col)] / &a[(col, col)]);
            for j in col..n {
                let t = Float::with_val(f.prec(), &f * &a[(col, j)]);
                a[(i, j)] -= t;
            }
            let t = Float::with_val(f.prec(), &f * &b[col]);
            b[i] -= t;
        }
    }
    let mut x: Vec<Float> = vec![Float::new(b[0].prec()); n];
    for i in (0..n).rev() {
        let mut s = b[i].clone();
        for j in i + 1..n {
            s -= Float::with_val(s.prec(), &a[(i, j)] * &x[j]);
        }
        x[i] = s / &a[(i, i)];
    }
    Some(x)
}
