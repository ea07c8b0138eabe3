//! The constraint rows of a mode and the slipping contacts: what each row
//! stands for ([`Row`]), the contacts whose tangential velocity is a slip
//! speed ([`Tangent`]) with their sliding friction ([`SlipTerm`]), the
//! coefficients of a slip speed and of each row over q̇, and the power the
//! slip terms dissipate.

use super::{psi, rr, th, System, PHI1, X1, Y1};
use crate::model::Floor;
use rug::Float;

/// What a constraint row stands for (and what its multiplier is).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Row {
    /// ẏ1 = 0: N1.
    FloorNormal,
    /// Rolling floor ẋ1 − r1 φ̇1 = 0, or fixed floor ẋ1 = 0: F1.
    FloorFriction,
    /// Fixed floor φ̇1 = 0: the holding torque (clockwise).
    Hold,
    /// ṙ_j = 0: the normal force N_{j,j+1} (0-based line j).
    Normal(usize),
    /// No slip at line j: F_{j+1,j}.
    Friction(usize),
    /// A cyclic direction without inertia (index into the list): its
    /// independent rate is held constant; multiplier 0.
    Massless(usize),
}

/// A contact whose tangential velocity is a slip speed: the floor under
/// cylinder 1, or line j between cylinders j+1 and j.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tangent {
    /// s1 = ẋ1 − r1 φ̇1: the velocity of cylinder 1's contact point over the floor.
    Floor,
    /// s = r_j θ̇_j + ρ_{j+1} ω_{j+1} + ρ_j ω_j (ω counter-clockwise): the
    /// velocity of the upper cylinder's contact point over the lower one's,
    /// along (cos θ_j, −sin θ_j). For two cylinders s12 = r θ̇ + r2 ψ̇2 − r1 φ̇1.
    Line(usize),
}

/// Sliding friction at a slipping contact: the applied tangential force
/// −μk σ N, with N the multiplier of the contact's normal row and σ = ±1 the
/// sign of the slip speed (the force opposes the slip).
#[derive(Debug, Clone)]
pub struct SlipTerm {
    /// The contact.
    pub at: Tangent,
    /// Index (into [`System::rows`]) of its normal row.
    pub normal: usize,
    /// μk σ.
    pub mu_sigma: Float,
}

impl System {
    /// The coefficients of a contact's slip speed over q̇ at q.
    pub fn tangent_coeffs(&self, at: Tangent, q: &[Float]) -> Vec<(usize, Float)> {
        Self::tangent_of(&self.rho, at, q)
    }

    /// A contact's slip speed at (q, q̇).
    pub fn slip_speed(&self, at: Tangent, q: &[Float], v: &[Float]) -> Float {
        let mut s = Float::new(self.prec);
        for (i, c) in self.tangent_coeffs(at, q) {
            s += &c * &v[i];
        }
        s
    }

    /// The power dissipated by the slip terms, Σ μk σ N s = Σ μk N |s| ≥ 0
    /// while every slip speed has the sign of its σ (λ: the multipliers of
    /// the same state).
    pub fn slip_power(&self, q: &[Float], v: &[Float], lambda: &[Float]) -> Float {
        let p = self.prec;
        let mut pw = Float::new(p);
        for sl in &self.slips {
            let s = self.slip_speed(sl.at, q, v);
            pw += Float::with_val(p, &sl.mu_sigma * &lambda[sl.normal]) * &s;
        }
        pw
    }

    pub(super) fn tangent_of(rho: &[Float], at: Tangent, q: &[Float]) -> Vec<(usize, Float)> {
        let p = q[0].prec().max(rho[0].prec());
        match at {
            Tangent::Floor => vec![
                (X1, Float::with_val(p, 1u32)),
                (PHI1, Float::with_val(p, -&rho[0])),
            ],
            Tangent::Line(j) => {
                let (i0, s0) = Self::spin(j);
                let (i1, s1) = Self::spin(j + 1);
                vec![
                    (th(j), q[rr(j)].clone()),
                    (i0, Float::with_val(p, &rho[j] * s0)),
                    (i1, Float::with_val(p, &rho[j + 1] * s1)),
                ]
            }
        }
    }

    /// Index and sign of cylinder i's counter-clockwise rate in q̇.
    pub(super) fn spin(i: usize) -> (usize, i32) {
        if i == 0 {
            (PHI1, -1)
        } else {
            (psi(i - 1), 1)
        }
    }

    /// The coefficients of constraint row `row` over q̇ at q, and −J̇q̇.
    pub(super) fn row_coeffs(
        &self,
        row: Row,
        q: &[Float],
        v: &[Float],
    ) -> (Vec<(usize, Float)>, Float) {
        let p = self.prec;
        let one = Float::with_val(p, 1u32);
        match row {
            Row::FloorNormal => (vec![(Y1, one)], Float::new(p)),
            Row::FloorFriction => match self.floor {
                Floor::Roll => (
                    vec![(X1, one), (PHI1, Float::with_val(p, -&self.rho[0]))],
                    Float::new(p),
                ),
                _ => (vec![(X1, one)], Float::new(p)),
            },
            Row::Hold => (vec![(PHI1, one)], Float::new(p)),
            Row::Normal(j) => (vec![(rr(j), one)], Float::new(p)),
            Row::Friction(j) => {
                let (i0, s0) = Self::spin(j);
                let (i1, s1) = Self::spin(j + 1);
                let c0 = Float::with_val(p, &self.rho[j] * s0);
                let c1 = Float::with_val(p, &self.rho[j + 1] * s1);
                let rhs = -Float::with_val(p, &v[rr(j)] * &v[th(j)]);
                (vec![(th(j), q[rr(j)].clone()), (i0, c0), (i1, c1)], rhs)
            }
            Row::Massless(k) => {
                // the direction's own independent coordinate (its first
                // nonzero entry: x1, φ1 or the free spin), whose rate no
                // other independent direction moves
                let i = self.massless[k]
                    .iter()
                    .position(|d| !d.is_zero())
                    .unwrap_or(PHI1);
                (vec![(i, one)], Float::new(p))
            }
        }
    }
}
