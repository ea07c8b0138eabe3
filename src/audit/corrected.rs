//! The corrected forms of the paper's errata, each verified by the audit the
//! same way as the printed ones.

use crate::paper::{Sym, X};

/// A = m2 / ((1 + k1) m1 + (1 + k2) m2).
fn a_of(y: &Sym) -> X {
    &y.m2 / ((1 + &y.k1) * &y.m1 + (1 + &y.k2) * &y.m2)
}

/// Eq. (21), second form corrected: `φ2 = (r1/r2) ω0 t − (A r/r2)(sin θ − k2 θ)
/// − (r1/r2) θ` (ω0 t, not ω0).
pub fn eq21(y: &Sym) -> X {
    let q = &y.r1 / &y.r2;
    &q * &y.omega0 * &y.t - a_of(y) * y.rsum() / &y.r2 * (&y.s - &y.k2 * &y.th) - q * &y.th
}

/// Eq. (23), second form corrected: `θ̈ = [1 + k2 − A(cos θ − k2)(2 − k2 − cos θ)]
/// / [1 + k2 − A(cos θ − k2)²]² (g/r) sin θ` (start from rest at the top).
pub fn eq23(y: &Sym) -> X {
    let a = a_of(y);
    let cm = &y.c - &y.k2;
    let den = 1 + &y.k2 - &a * cm.sq();
    (1 + &y.k2 - a * &cm * (2 - &y.k2 - &y.c)) / den.sq() * (&y.g / y.rsum()) * &y.s
}

/// Eq. (29) corrected: `(F1 + F21) r1 = −I1 φ̈1` (F21 as in eq. 28). Returns
/// (F1 + F21) r1.
pub fn eq29(y: &Sym) -> X {
    (&y.f1 + &y.f21) * &y.r1
}

/// Eq. (33) corrected: `N12 = m2 (g cos θ + r1 sin θ φ̈1 − r θ̇²)`.
pub fn eq33(y: &Sym) -> X {
    &y.m2 * (&y.g * &y.c + &y.r1 * &y.s * &y.phi1dd - y.rsum() * y.thd.sq())
}

/// Eq. (34) corrected: `r θ̇s² = g cos θs + r1 sin θs φ̈1`. Returns the right side.
pub fn eq34(y: &Sym) -> X {
    &y.g * &y.c + &y.r1 * &y.s * &y.phi1dd
}

/// Eq. (43) corrected: `m2 cos³θs = (m1 + m2)(3 cos θs − 2)`. Returns left −
/// right at cos θs = `c`.
pub fn eq43(m1: &X, m2: &X, c: &X) -> X {
    m2 * c.cube() - (m1 + m2) * (3 * c - 2)
}

/// Eq. (50) corrected (identical cylinders, k1 = k2 = k, frictionless floor):
/// `(1 − k) cos³θs + 2k cos²θs − (2 + k)(3 + k) cos θs + 2(2 + k) = 0`.
pub fn eq50(k: &X, c: &X) -> X {
    (1 - k) * c.cube() + 2 * k * c.sq() - (2 + k) * (3 + k) * c + 2 * (2 + k)
}

/// Eq. (64), middle form corrected: `k1 m1 r1² φ̇1 + r1 k2 m2 (r1 φ̇1 − r θ̇)`.
pub fn eq64(y: &Sym) -> X {
    &y.k1 * &y.m1 * y.r1.sq() * &y.phi1d
        + &y.r1 * &y.k2 * &y.m2 * (&y.r1 * &y.phi1d - &y.r * &y.thd)
}

/// Eqs. (84)–(86) corrected: A.3 keeps φ2 as a coordinate, so the rolling
/// constraint (59) is relaxed too and its multiplier appears: `dp_φ1/dt =
/// −r1 λ2`, `dp_φ2/dt = r2 λ2`, `d/dt ∂L/∂θ̇ − ∂L/∂θ = r1 λ2` (as in (75)–(77)).
pub fn eq84_86(y: &Sym) -> [X; 3] {
    [-(&y.r1 * &y.lam[1]), &y.r2 * &y.lam[1], &y.r1 * &y.lam[1]]
}

/// Eq. (98) corrected: the spin term of cylinder 1 is `(m1 k1 r1²/2) φ̇1²`.
pub fn eq98(y: &Sym) -> X {
    crate::paper::appendix::eq98(y) - &y.m1 * &y.k2 * y.r1.sq() / 2 * y.phi1d.sq()
        + &y.m1 * &y.k1 * y.r1.sq() / 2 * y.phi1d.sq()
}

/// Eq. (99) corrected, with r a coordinate: `V = m2 g (r cos θ − r1 − r2) +
/// (m1 + m2) g (y1 − r1)` (as A.3 writes it).
pub fn eq99(y: &Sym) -> X {
    &y.m2 * &y.g * (&y.r * &y.c - &y.r1 - &y.r2) + (&y.m1 + &y.m2) * &y.g * (&y.y1 - &y.r1)
}

/// Footnote 6 corrected: `θ̇² = 12 g (1 − cos θ)/a(17 + 4 cos θ − 4 cos²θ)`.
pub fn fn6(y: &Sym) -> X {
    12 * &y.g * (1 - &y.c) / (&y.r1 * (17 + 4 * &y.c - 4 * y.c.sq()))
}
