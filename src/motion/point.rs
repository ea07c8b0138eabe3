//! The columns of one state of the motion, the same for every contact law.

use super::mode::Phase;
use crate::integrate::solve::Sample;
use crate::mechanics::system::{self, Row, System};
use rug::Float;

/// The columns of a trajectory row, in order (the `mode` column, a text,
/// follows them): time; the angle of the line of centres and its rates;
/// the angles and positions; the velocities; the forces; the slip speeds
/// and the work dissipated by friction.
pub const COLUMNS: [&str; 21] = [
    "t",
    "theta",
    "theta_dot",
    "theta_ddot",
    "phi1",
    "phi2",
    "x1",
    "x2",
    "y2",
    "x1_dot",
    "phi1_dot",
    "x2_dot",
    "y2_dot",
    "phi2_dot",
    "F1",
    "N1",
    "F21",
    "N12",
    "s1",
    "s12",
    "work",
];

/// Index of a column in [`COLUMNS`] (`None` for a name that is not one):
/// for names read at run time; in the code, the crate's `col!` macro.
pub fn column_index(name: &str) -> Option<usize> {
    COLUMNS.iter().position(|c| *c == name)
}

/// Index of a column in [`COLUMNS`]; a name that is not a column panics,
/// which in a `const` context — the crate's `col!` macro, the form every use in
/// the code takes — fails the build (`cargo build`; `cargo check` does not
/// evaluate it), not a silent column 0.
pub(crate) const fn column(name: &str) -> usize {
    let n = name.as_bytes();
    let mut i = 0;
    while i < COLUMNS.len() {
        let c = COLUMNS[i].as_bytes();
        if c.len() == n.len() {
            let mut j = 0;
            while j < n.len() && c[j] == n[j] {
                j += 1;
            }
            if j == n.len() {
                return i;
            }
        }
        i += 1;
    }
    panic!("not a column of motion::COLUMNS")
}

/// The index of column `$name` in [`COLUMNS`], found at compile time
/// ([`column`]): `col!("N12")`.
macro_rules! col {
    ($name:literal) => {
        const { $crate::motion::point::column($name) }
    };
}
pub(crate) use col;

/// The mechanical state at one time, in the conventions of the README:
/// θ (in flight the direction of the line of centres), its rates, the
/// angles φ1 (cylinder 1, clockwise) and φ2 (cylinder 2 relative to the
/// line of centres, the paper's angle, with φ2 = 0 at t = 0), the centres,
/// the velocities and the forces F1, N1 (floor on cylinder 1), F21, N12
/// (between the cylinders; 0 in flight).
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
    /// φ2 = ψ2 + θ (the paper's angle; ψ2 is cylinder 2's counter-clockwise
    /// rotation).
    pub phi2: Float,
    /// x1.
    pub x1: Float,
    /// x2.
    pub x2: Float,
    /// y2.
    pub y2: Float,
    /// ẋ1.
    pub x1_dot: Float,
    /// φ̇1.
    pub phi1_dot: Float,
    /// ẋ2.
    pub x2_dot: Float,
    /// ẏ2.
    pub y2_dot: Float,
    /// φ̇2.
    pub phi2_dot: Float,
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
    /// The values of the first 18 [`COLUMNS`] (t … N12).
    pub fn values(&self) -> [&Float; 18] {
        [
            &self.t,
            &self.theta,
            &self.theta_dot,
            &self.theta_ddot,
            &self.phi1,
            &self.phi2,
            &self.x1,
            &self.x2,
            &self.y2,
            &self.x1_dot,
            &self.phi1_dot,
            &self.x2_dot,
            &self.y2_dot,
            &self.phi2_dot,
            &self.f1,
            &self.n1,
            &self.f21,
            &self.n12,
        ]
    }
}

impl TwoState {
    /// The 13 values of the ideal oracle's rows
    /// ([`crate::oracle::TRAJECTORY_COLUMNS`]: t … y2, F1 … N12).
    pub fn ideal_columns(&self) -> [Float; 13] {
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

/// The state of a two-cylinder sample of a constrained system (the
/// multipliers as forces).
pub fn two_state(sys: &System, s: &Sample) -> TwoState {
    let p = sys.prec;
    let q = &s.q;
    let v = &s.v;
    let ith = system::th(0);
    let th = &q[ith];
    let r = &q[system::rr(0)];
    let (sn, cs) = match sys.cached_trig(th) {
        Some((sn, cs)) => (sn.clone(), cs.clone()),
        None => th.clone().sin_cos(Float::new(p)),
    };
    let thd = &v[ith];
    let rd = &v[system::rr(0)];
    // C2 = C1 + r (sin θ, cos θ)
    let x2_dot = Float::with_val(p, r * &cs) * thd + Float::with_val(p, rd * &sn) + &v[system::X1];
    let y2_dot = Float::with_val(p, rd * &cs) - Float::with_val(p, r * &sn) * thd + &v[system::Y1];
    TwoState {
        t: s.t.clone(),
        theta: th.clone(),
        theta_dot: thd.clone(),
        theta_ddot: s.qdd[ith].clone(),
        phi1: q[system::PHI1].clone(),
        phi2: Float::with_val(p, &q[system::psi(0)] + th),
        x1: q[system::X1].clone(),
        x2: Float::with_val(p, r * &sn) + &q[system::X1],
        y2: Float::with_val(p, r * &cs) + &q[system::Y1],
        x1_dot: v[system::X1].clone(),
        phi1_dot: v[system::PHI1].clone(),
        x2_dot,
        y2_dot,
        phi2_dot: Float::with_val(p, &v[system::psi(0)] + thd),
        f1: row_value(sys, s, Row::FloorFriction),
        n1: row_value(sys, s, Row::FloorNormal),
        f21: row_value(sys, s, Row::Friction(0)),
        n12: row_value(sys, s, Row::Normal(0)),
    }
}

/// Every column of the motion at one time, and the phase it belongs to.
#[derive(Debug, Clone)]
pub struct Point {
    /// The mechanical state (reached through `Deref`: `point.theta`).
    pub state: TwoState,
    /// Floor slip speed s1 = ẋ1 − r1 φ̇1 (exactly 0 while the floor rolls or
    /// holds).
    pub s1: Float,
    /// Contact slip speed s12 = r θ̇ + r2 ψ̇2 − r1 φ̇1 (exactly 0 while the
    /// contact rolls; 0 in flight, where there is no contact).
    pub s12: Float,
    /// Energy dissipated by friction since t = 0.
    pub work: Float,
    /// Total energy T + V.
    pub energy: Float,
    /// The phase (mode, or flight).
    pub phase: Phase,
    /// The route's estimate of each column's absolute error, in
    /// [`COLUMNS`] order, where it has one of its own (the energy route:
    /// from the bound on δ = θ − θ0); `None`: a few units of the
    /// integrator's tolerance.
    pub err: Option<Vec<Float>>,
    /// Columns that are exactly 0 by the laws (a rolling contact's slip
    /// speed, a frictionless contact's force, the work of a conservative
    /// phase), as a bit set over [`COLUMNS`].
    pub exact_zero: u32,
    /// How many times the ladder's bound counts the difference between its
    /// two runs for every column but t ([`crate::numeric::verify::Estimate::diff_weight`]):
    /// 2 where the route's own error is covered by that difference (a
    /// conservative row whose δ the two runs tell apart by more than δ's
    /// error bound), else 1; 0 where the higher run computes every column
    /// but t and θ alone (a table's conservative row: [`Point::is_bare`]).
    pub diff_weight: u32,
}

impl std::ops::Deref for Point {
    type Target = TwoState;
    fn deref(&self) -> &TwoState {
        &self.state
    }
}

impl Point {
    /// Whether this is a lower run's row that carries t and θ alone (the
    /// other columns placeholders: the higher run computes them with their
    /// error, `Request::derived_at_high`), with no energy to balance and no
    /// estimates beyond those two.
    pub fn is_bare(&self, run: crate::numeric::verify::Run) -> bool {
        run == crate::numeric::verify::Run::Low && self.diff_weight == 0
    }

    /// The values in [`COLUMNS`] order.
    pub fn columns(&self) -> Vec<Float> {
        let mut v: Vec<Float> = self.state.values().into_iter().cloned().collect();
        v.extend([self.s1.clone(), self.s12.clone(), self.work.clone()]);
        v
    }

    /// The values in [`COLUMNS`] order and the route's errors, moved out.
    pub fn into_columns(self) -> (Vec<Float>, Option<Vec<Float>>) {
        let s = self.state;
        let v = vec![
            s.t,
            s.theta,
            s.theta_dot,
            s.theta_ddot,
            s.phi1,
            s.phi2,
            s.x1,
            s.x2,
            s.y2,
            s.x1_dot,
            s.phi1_dot,
            s.x2_dot,
            s.y2_dot,
            s.phi2_dot,
            s.f1,
            s.n1,
            s.f21,
            s.n12,
            self.s1,
            self.s12,
            self.work,
        ];
        (v, self.err)
    }

    /// Whether column `i` of [`COLUMNS`] is exactly 0 by the laws.
    pub fn is_exact_zero(&self, i: usize) -> bool {
        self.exact_zero & (1 << i) != 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_column_is_found_at_its_index() {
        for (i, name) in COLUMNS.iter().enumerate() {
            assert_eq!(column(name), i, "{name}");
        }
        assert_eq!(col!("t"), 0);
        assert_eq!(col!("work"), COLUMNS.len() - 1);
        // a prefix or an extension of a name is not that column
        assert!(std::panic::catch_unwind(|| column("theta_do")).is_err());
        assert!(std::panic::catch_unwind(|| column("N12x")).is_err());
    }
}
