//! The columns of one state of the motion.

use crate::integrate::solve::Sample;
use crate::mechanics::system::{self, Row, System};
use rug::Float;

/// Two cylinders: route 2's values at one sample, in the conventions of the
/// README (and of [`crate::oracle::TRAJECTORY_COLUMNS`]).
#[derive(Debug, Clone)]
pub struct TwoState {
    /// t.
    pub t: Float,
    /// θ.
    pub theta: Float,
    /// θ̇.
    pub theta_dot: Float,
    /// θ̈.
    pub theta_ddot: Float,
    /// φ1 (clockwise).
    pub phi1: Float,
    /// φ2 = ψ2 + θ (the paper's angle).
    pub phi2: Float,
    /// x1.
    pub x1: Float,
    /// x2.
    pub x2: Float,
    /// y2.
    pub y2: Float,
    /// F1 (floor's or holder's x force on cylinder 1; 0 on a frictionless floor).
    pub f1: Float,
    /// N1.
    pub n1: Float,
    /// F21 (0 at a frictionless contact).
    pub f21: Float,
    /// N12.
    pub n12: Float,
}

impl TwoState {
    /// The values in [`crate::oracle::TRAJECTORY_COLUMNS`] order, t first.
    pub fn columns(&self) -> [Float; 13] {
        [
            self.t.clone(),
            self.theta.clone(),
            self.theta_dot.clone(),
            self.theta_ddot.clone(),
            self.phi1.clone(),
            self.phi2.clone(),
            self.x1.clone(),
            self.x2.clone(),
            self.y2.clone(),
            self.f1.clone(),
            self.n1.clone(),
            self.f21.clone(),
            self.n12.clone(),
        ]
    }
}

fn row_value(sys: &System, s: &Sample, row: Row) -> Float {
    sys.rows
        .iter()
        .position(|r| *r == row)
        .map(|i| s.lambda[i].clone())
        .unwrap_or_else(|| Float::new(sys.prec))
}

/// The columns of a two-cylinder sample (the multipliers as forces).
pub fn two_state(sys: &System, s: &Sample) -> TwoState {
    let p = sys.prec;
    let q = &s.q;
    let th = &q[system::th(0)];
    let r = &q[system::rr(0)];
    let (sn, cs) = th.clone().sin_cos(Float::new(p));
    TwoState {
        t: s.t.clone(),
        theta: th.clone(),
        theta_dot: s.v[system::th(0)].clone(),
        theta_ddot: s.qdd[system::th(0)].clone(),
        phi1: q[system::PHI1].clone(),
        phi2: Float::with_val(p, &q[system::psi(0)] + th),
        x1: q[system::X1].clone(),
        x2: Float::with_val(p, r * &sn) + &q[system::X1],
        y2: Float::with_val(p, r * &cs) + &q[system::Y1],
        f1: row_value(sys, s, Row::FloorFriction),
        n1: row_value(sys, s, Row::FloorNormal),
        f21: row_value(sys, s, Row::Friction(0)),
        n12: row_value(sys, s, Row::Normal(0)),
    }
}
