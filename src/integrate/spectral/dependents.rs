//! The coordinates a mode's velocity constraints tie to the others (φ1
//! held, x1 rolling with φ1, ψ2 rolling on cylinder 1): they are not
//! integrated but filled in from the moving coordinates, with the constant
//! coefficients of a closed contact.

use crate::mechanics::system::{self as sy, Row, System};
use crate::model::Floor;
use rug::Float;

/// A coordinate fixed by a velocity constraint of the mode: q̇_dep =
/// Σ c_i q̇_i, so q_dep − q_dep(0) = Σ c_i (q_i − q_i(0)) (constant
/// coefficients: r is held while the contact is closed). No terms: held.
pub(super) type Dependent = (usize, Vec<(usize, Float)>);

/// The dependents of a two-cylinder mode, in an order in which each needs
/// only coordinates before it: φ1 held (a fixed floor), x1 rolling with φ1
/// (x1 = r1 φ1 + const) or held, ψ2 rolling on cylinder 1
/// (ψ̇2 = (r1 φ̇1 − r θ̇)/r2).
pub(super) fn dependents(sys: &System, q0: &[Float]) -> Vec<Dependent> {
    let p = sys.prec;
    let mut out = Vec::new();
    if sys.rows.contains(&Row::Hold) {
        out.push((sy::PHI1, Vec::new()));
    }
    if sys.rows.contains(&Row::FloorFriction) {
        out.push(match sys.floor {
            Floor::Roll => (sy::X1, vec![(sy::PHI1, sys.rho[0].clone())]),
            _ => (sy::X1, Vec::new()),
        });
    }
    if sys.rows.contains(&Row::Friction(0)) {
        let r2 = &sys.rho[1];
        out.push((
            sy::psi(0),
            vec![
                (sy::PHI1, Float::with_val(p, &sys.rho[0] / r2)),
                (sy::th(0), -Float::with_val(p, &q0[sy::rr(0)] / r2)),
            ],
        ));
    }
    out
}

/// The coordinates integrated besides θ: x1, φ1, ψ2 unless a dependent (y1
/// and r are held by the normal constraints while the contact is closed).
pub(super) fn moving(sys: &System, deps: &[Dependent]) -> Vec<usize> {
    (0..sys.nq())
        .filter(|&i| i != sy::Y1 && i != sy::th(0) && i != sy::rr(0))
        .filter(|i| deps.iter().all(|(d, _)| d != i))
        .collect()
}

/// Fills the dependents of (q, q̇) from the rest (q0: the piece's start).
pub(super) fn fill_dependents(deps: &[Dependent], q0: &[Float], q: &mut [Float], v: &mut [Float]) {
    for (d, terms) in deps {
        let p = q[*d].prec();
        let mut x = Float::with_val(p, &q0[*d]);
        let mut y = Float::new(p);
        for (i, c) in terms {
            x += Float::with_val(p, &q[*i] - &q0[*i]) * c;
            y += Float::with_val(p, &v[*i] * c);
        }
        q[*d] = x;
        v[*d] = y;
    }
}
