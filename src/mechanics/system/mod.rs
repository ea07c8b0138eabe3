//! The constrained equations of motion of a stack of n ≥ 2 cylinders in
//! relaxed coordinates, and the KKT solve for accelerations and multipliers.
//!
//! This generalises the paper's appendix A.5 (eq. 57 with the constraints
//! f1…f4 of eqs. 58–61) from two cylinders to n (footnote 3), and is written
//! from the kinematics of the bodies rather than from a printed Lagrangian:
//!
//! * Coordinates (3n of them): x1, y1, φ1 (cylinder 1's centre and its
//!   **clockwise** rotation), then for each line of centres j = 1…n−1 (between
//!   cylinders j and j+1): ψ_{j+1} (cylinder j+1's **counter-clockwise**
//!   rotation), θ_j (the line of centres, clockwise from vertical, absolute)
//!   and r_j (the distance between the two axes). For n = 2 this is exactly
//!   q = (x1, y1, φ1, ψ2, θ, r), with ψ2 = φ2 − θ in the paper's notation.
//! * Centre of cylinder i: (x1, y1) + Σ_{j<i} r_j (sin θ_j, cos θ_j).
//! * T = ½ Σ m_i |v_i|² + ½ Σ I_i ω_i², V = g Σ m_i y_i, so that the Lagrange
//!   equations read M(q) q̈ = h(q, q̇) + Jᵀλ with M = Σ m_i A_iᵀA_i + diag(I)
//!   (A_i the Jacobian of centre i) and h = −Σ m_i A_iᵀ(Ȧ_i q̇) − ∂V/∂q.
//! * Constraints (velocity form J q̇ = 0, all holonomic on the manifold):
//!   floor normal ẏ1 = 0 (multiplier N1, the floor's upward force on cylinder
//!   1); rolling floor ẋ1 − r1 φ̇1 = 0 (multiplier F1, the floor's x force);
//!   fixed floor ẋ1 = 0 (F1) and φ̇1 = 0 (holding torque, clockwise); for
//!   every line j the touching constraint ṙ_j = 0 (multiplier N_j, the normal
//!   force between cylinders j and j+1, positive while they press) and, for a
//!   rolling contact, the no-slip condition of the contact points
//!   r_j θ̇_j + ρ_{j+1} ω_{j+1} + ρ_j ω_j = 0 with ω the counter-clockwise
//!   rates (ω_1 = −φ̇1) and ρ the radii (multiplier F_{j+1,j}: the tangential
//!   force of cylinder j on cylinder j+1 along (cos θ_j, −sin θ_j)). For
//!   n = 2 the multipliers are F1, F21, N12, N1 of the paper (eqs. 110–114).
//!
//! Index reduction: the acceleration form J q̈ = −J̇ q̇ (J̇ q̇ = ṙ_j θ̇_j for
//! a rolling contact, else 0), so at every state
//!
//! ```text
//! [ M  −Jᵀ ] [ q̈ ]   [   h   ]
//! [ J   0  ] [ λ ] = [ −J̇ q̇ ]
//! ```
//!
//! is solved by Gaussian elimination with partial pivoting on `rug::Float`.
//! A cyclic direction of motion without inertia (a frictionless spin with
//! k = 0, or a frictionless floor under k1 = 0 with spins rolling on it at
//! k = 0) gets an extra row fixing the acceleration of its independent
//! coordinate to 0 (its multiplier is 0): the system stays regular and that
//! rate keeps its reference value, the convention of the first route.

mod accel;
mod invariants;
mod rows;
mod stack_model;
mod state;

pub use rows::{Row, SlipTerm, Tangent};
pub use stack_model::{StackModel, Units};

use crate::error::Result;
use crate::model::{Contact, Floor};
use rug::{Float, Rational};

/// Index of x1.
pub const X1: usize = 0;
/// Index of y1.
pub const Y1: usize = 1;
/// Index of φ1 (clockwise).
pub const PHI1: usize = 2;

/// Index of ψ_{j+2} (counter-clockwise rotation of the upper cylinder of
/// line j, 0-based line index).
pub fn psi(j: usize) -> usize {
    3 + 3 * j
}
/// Index of θ_j (0-based line index).
pub fn th(j: usize) -> usize {
    4 + 3 * j
}
/// Index of r_j (0-based line index).
pub fn rr(j: usize) -> usize {
    5 + 3 * j
}
/// Whether coordinate `i` is a length (x1, y1, the r_j), not an angle (φ1,
/// the ψ and θ_j): its natural scale is then r, else 1.
pub fn is_length(i: usize) -> bool {
    i == X1 || i == Y1 || (i >= rr(0) && (i - rr(0)) % 3 == 0)
}

/// The cylinder (0-based) whose spin coordinate is `q[i]`, if any.
pub fn spin_cylinder(i: usize) -> Option<usize> {
    if i == PHI1 {
        Some(0)
    } else if i >= 3 && (i - 3) % 3 == 0 {
        Some((i - 3) / 3 + 1)
    } else {
        None
    }
}

/// The solution of the KKT system at one state.
#[derive(Debug, Clone)]
pub struct Accel {
    /// q̈.
    pub qdd: Vec<Float>,
    /// One multiplier per row of [`System::rows`].
    pub lambda: Vec<Float>,
}

/// The stack's constants at one working precision, with a reusable
/// workspace for the KKT solve.
#[derive(Debug, Clone)]
pub struct System {
    /// Working precision (bits).
    pub prec: u32,
    /// Number of cylinders.
    pub n: usize,
    /// Floor model.
    pub floor: Floor,
    /// Contact models, bottom up.
    pub contacts: Vec<Contact>,
    /// Masses.
    pub m: Vec<Float>,
    /// Radii.
    pub rho: Vec<Float>,
    /// Moments of inertia I_i = k_i m_i r_i².
    pub inertia: Vec<Float>,
    /// g.
    pub g: Float,
    /// The natural units ([`StackModel::units`]): every threshold of the
    /// time integrators is relative to them.
    pub units: Units,
    /// Mass above line j: Σ_{i>j} m_i.
    above: Vec<Float>,
    /// Total mass.
    mtot: Float,
    /// The constraint rows.
    pub rows: Vec<Row>,
    /// Massless free directions (unit coefficient vectors over q).
    massless: Vec<Vec<Float>>,
    /// Cyclic directions with inertia: their momenta are conserved.
    pub cyclic: Vec<(String, Vec<Float>)>,
    /// Sliding friction at slipping contacts (empty for the ideal models).
    pub slips: Vec<SlipTerm>,
    ws: Workspace,
}

#[derive(Debug, Clone)]
struct Workspace {
    m: Vec<Float>,
    h: Vec<Float>,
    a: Vec<Float>,
    b: Vec<Float>,
    x: Vec<Float>,
    s: Vec<Float>,
    c: Vec<Float>,
    /// The angles θ_j (rounded to the precision) that `s` and `c` hold the
    /// sine and cosine of (NaN: none yet): a sample's KKT solve, energy
    /// and columns ask for the same angles in turn.
    trig_at: Vec<Float>,
    /// The θ_j and r_j (as given) that `m` is the mass matrix at (NaN:
    /// none yet): a sample's energy asks for the matrix its KKT solve built.
    m_at: Vec<Float>,
    t: Float,
    t2: Float,
}

impl System {
    /// The constants of `model` at `prec` bits.
    ///
    /// Errors: an invalid model ([`StackModel::validate`]).
    pub fn new(model: &StackModel, prec: u32) -> Result<Self> {
        model.validate()?;
        let n = model.n();
        let f = |q: &Rational| Float::with_val(prec, q);
        let m: Vec<Float> = model.m.iter().map(f).collect();
        let rho: Vec<Float> = model.r.iter().map(f).collect();
        let inertia: Vec<Float> = (0..n)
            .map(|i| {
                let q = Rational::from(&model.k[i] * &model.m[i]) * &model.r[i] * &model.r[i];
                f(&q)
            })
            .collect();
        let mut above = Vec::with_capacity(n - 1);
        for j in 0..n - 1 {
            let s = model.m[j + 1..].iter().fold(Rational::new(), |a, b| a + b);
            above.push(f(&s));
        }
        let mtot = f(&model.m.iter().fold(Rational::new(), |a, b| a + b));
        let mut rows = vec![Row::FloorNormal];
        match model.floor {
            Floor::Roll => rows.push(Row::FloorFriction),
            Floor::Slip => {}
            Floor::Fixed => {
                rows.push(Row::FloorFriction);
                rows.push(Row::Hold);
            }
        }
        for (j, c) in model.contacts.iter().enumerate() {
            rows.push(Row::Normal(j));
            if *c == Contact::Roll {
                rows.push(Row::Friction(j));
            }
        }
        let nq = 3 * n;
        let mut sys = System {
            prec,
            n,
            floor: model.floor,
            contacts: model.contacts.clone(),
            m,
            rho,
            inertia,
            g: f(&model.g),
            units: model.units(prec),
            above,
            mtot,
            rows,
            massless: Vec::new(),
            cyclic: Vec::new(),
            slips: Vec::new(),
            ws: Workspace {
                m: vec![Float::new(prec); nq * nq],
                h: vec![Float::new(prec); nq],
                a: Vec::new(),
                b: Vec::new(),
                x: Vec::new(),
                s: vec![Float::new(prec); n - 1],
                c: vec![Float::new(prec); n - 1],
                trig_at: vec![Float::with_val(prec, f64::NAN); n - 1],
                m_at: vec![Float::with_val(prec, f64::NAN); 2 * (n - 1)],
                t: Float::new(prec),
                t2: Float::new(prec),
            },
        };
        // cyclic directions; those without inertia become extra rows
        for (name, dir) in sys.cyclic_directions() {
            let massless = (0..nq)
                .all(|i| dir[i].is_zero() || spin_cylinder(i).is_some_and(|cyl| model.k[cyl] == 0));
            if massless {
                let idx = sys.massless.len();
                sys.massless.push(dir);
                sys.rows.push(Row::Massless(idx));
            } else {
                sys.cyclic.push((name, dir));
            }
        }
        let nk = nq + sys.rows.len();
        sys.ws.a = vec![Float::new(prec); nk * nk];
        sys.ws.b = vec![Float::new(prec); nk];
        sys.ws.x = vec![Float::new(prec); nk];
        Ok(sys)
    }

    /// Number of coordinates, 3n.
    pub fn nq(&self) -> usize {
        3 * self.n
    }

    /// Whether some contact slips with friction (the dissipated work is
    /// then integrated as an extra state).
    pub fn has_slips(&self) -> bool {
        !self.slips.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The lengths among the coordinates of a stack of four (three lines):
    /// x1, y1 and each line's r_j; φ1, every ψ and every θ_j are angles.
    #[test]
    fn lengths_are_x1_y1_and_the_separations() {
        let lengths: Vec<usize> = (0..rr(2) + 1).filter(|&i| is_length(i)).collect();
        assert_eq!(lengths, [X1, Y1, rr(0), rr(1), rr(2)]);
        for j in 0..3 {
            assert!(!is_length(th(j)) && !is_length(psi(j)));
        }
        assert!(!is_length(PHI1));
    }
}
