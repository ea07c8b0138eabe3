//! Section 3 (variants), eqs. (38)–(55), and footnotes 11 and 12, as printed.

use super::sec2::rhat_dot_geff;
use super::{Sym, X};

/// Eq. (38) (no friction anywhere): `T = ((m1 + m2)/2) ẋ1² + m2 r cos θ ẋ1 θ̇ +
/// (m2/2) r² θ̇²`.
pub fn eq38(y: &Sym) -> X {
    let r = y.rsum();
    (&y.m1 + &y.m2) / 2 * y.x1d.sq()
        + &y.m2 * &r * &y.c * &y.x1d * &y.thd
        + &y.m2 / 2 * r.sq() * y.thd.sq()
}

/// Eq. (39): `p_x1 = ∂T/∂ẋ1 = (m1 + m2) ẋ1 + m2 r cos θ θ̇ = P_x = 0`.
pub fn eq39(y: &Sym) -> X {
    (&y.m1 + &y.m2) * &y.x1d + &y.m2 * y.rsum() * &y.c * &y.thd
}

/// Eq. (40): `E/(m2 r²) = 0 = ((m1 + m2 sin²θ)/(m1 + m2)) θ̇²/2 − (g/r)(1 −
/// cos θ)`. Returns the printed right-hand side.
pub fn eq40(y: &Sym) -> X {
    (&y.m1 + &y.m2 * y.s.sq()) / (&y.m1 + &y.m2) * y.thd.sq() / 2 - &y.g / y.rsum() * (1 - &y.c)
}

/// Eq. (41): `g_eff = −ẍ1 x̂ − g ŷ = (m2 r/(m1 + m2))(cos θ θ̈ − sin θ θ̇²) x̂ −
/// g ŷ`. Returns the two printed x components.
pub fn eq41(y: &Sym) -> [X; 2] {
    [
        -&y.x1dd,
        &y.m2 * y.rsum() / (&y.m1 + &y.m2) * (&y.c * &y.thdd - &y.s * y.thd.sq()),
    ]
}

/// Eq. (42): `r θ̇s² = r̂·g_eff = g cos θs − (m2 r sin θs/(m1 + m2))(cos θs θ̈s −
/// sin θs θ̇s²)`. Returns [r θ̇², r̂·g_eff with (41), last form].
pub fn eq42(y: &Sym) -> [X; 3] {
    let r = y.rsum();
    [
        &r * y.thd.sq(),
        rhat_dot_geff(y, &eq41(y)[1]),
        &y.g * &y.c - &y.m2 * r * &y.s / (&y.m1 + &y.m2) * (&y.c * &y.thdd - &y.s * y.thd.sq()),
    ]
}

/// Eq. (43): `m2 cos θs² = (m1 + m2)(3 cos θs − 2)`, read as m2 cos²θs.
/// Returns left − right at cos θs = `c`.
pub fn eq43(m1: &X, m2: &X, c: &X) -> X {
    m2 * c.sq() - (m1 + m2) * (3 * c - 2)
}

/// Eq. (43) under the other reading of `cos θs²`, cos(θs²): left − right at θs.
pub fn eq43_cos_of_square(m1: &X, m2: &X, th: &X) -> X {
    m2 * th.sq().cos() - (m1 + m2) * (3 * th.cos() - 2)
}

/// Eq. (44) (frictionless floor, rolling contact): `T = ((m1 + m2)/2) ẋ1² +
/// ((k1 m1 + k2 m2)/2) r1² φ̇1² + m2 r cos θ ẋ1 θ̇ − k2 m2 r1 r φ̇1 θ̇ +
/// ((1 + k2)/2) m2 r² θ̇²`.
pub fn eq44(y: &Sym) -> X {
    let r = y.rsum();
    (&y.m1 + &y.m2) / 2 * y.x1d.sq()
        + (&y.k1 * &y.m1 + &y.k2 * &y.m2) / 2 * y.r1.sq() * y.phi1d.sq()
        + &y.m2 * &r * &y.c * &y.x1d * &y.thd
        - &y.k2 * &y.m2 * &y.r1 * &r * &y.phi1d * &y.thd
        + (1 + &y.k2) / 2 * &y.m2 * r.sq() * y.thd.sq()
}

/// Eq. (45): `p_x1 = ∂T/∂ẋ1 = (m1 + m2) ẋ1 + m2 r cos θ θ̇ = P_x = 0`.
pub fn eq45(y: &Sym) -> X {
    eq39(y)
}

/// Eq. (46): `p_φ1 = ∂T/∂φ̇1 = (k1 m1 + k2 m2) r1² φ̇1 − k2 m2 r1 r θ̇ = L1 +
/// (r1/r2) L2 = 0`, given L1 and L2. Returns the two forms.
pub fn eq46(y: &Sym, l1: &X, l2: &X) -> [X; 2] {
    [
        (&y.k1 * &y.m1 + &y.k2 * &y.m2) * y.r1.sq() * &y.phi1d
            - &y.k2 * &y.m2 * &y.r1 * y.rsum() * &y.thd,
        l1 + &y.r1 / &y.r2 * l2,
    ]
}

/// Eq. (47): `E/(m2 r²) = 0 = (1 + k2 − m2 cos²θ/(m1 + m2) − k2² m2/(k1 m1 +
/// k2 m2)) θ̇²/2 − (g/r)(1 − cos θ)`. Returns the printed right-hand side.
pub fn eq47(y: &Sym) -> X {
    (1 + &y.k2
        - &y.m2 * y.c.sq() / (&y.m1 + &y.m2)
        - y.k2.sq() * &y.m2 / (&y.k1 * &y.m1 + &y.k2 * &y.m2))
        * y.thd.sq()
        / 2
        - &y.g / y.rsum() * (1 - &y.c)
}

/// Eq. (48): same printed form as (41). Returns the two x components.
pub fn eq48(y: &Sym) -> [X; 2] {
    eq41(y)
}

/// Eq. (49): `r θ̇s² = r̂·g_eff = g cos θs − (m2 r/(m1 + m2))(cos θs θ̈s − sin θs
/// θ̇s²) sin θs`. Returns [r θ̇², r̂·g_eff with (48), last form].
pub fn eq49(y: &Sym) -> [X; 3] {
    let r = y.rsum();
    [
        &r * y.thd.sq(),
        rhat_dot_geff(y, &eq48(y)[1]),
        &y.g * &y.c - &y.m2 * r / (&y.m1 + &y.m2) * (&y.c * &y.thdd - &y.s * y.thd.sq()) * &y.s,
    ]
}

/// Eq. (50) (footnote 12; identical cylinders, k1 = k2 = k, frictionless floor):
/// `2[(2 + k) cos θs − 1] = cos θs (1 − cos θs)² (1 + cos θs)`. Returns left −
/// right at cos θs = `c`.
pub fn eq50(k: &X, c: &X) -> X {
    2 * ((2 + k) * c - 1) - c * (1 - c).sq() * (1 + c)
}

/// Eq. (51) (rolling floor, frictionless contact): `T = (((1 + k1) m1 + m2)/2)
/// r1² φ̇1² + m2 r1 r cos θ φ̇1 θ̇ + (m2/2) r² θ̇²`.
pub fn eq51(y: &Sym) -> X {
    let r = y.rsum();
    ((1 + &y.k1) * &y.m1 + &y.m2) / 2 * y.r1.sq() * y.phi1d.sq()
        + &y.m2 * &y.r1 * &r * &y.c * &y.phi1d * &y.thd
        + &y.m2 / 2 * r.sq() * y.thd.sq()
}

/// Eq. (52): `p_φ1 = ∂T/∂φ̇1 = [(1 + k1) m1 + m2] r1² φ̇1 + m2 r1 r cos θ θ̇ = 0`.
pub fn eq52(y: &Sym) -> X {
    ((1 + &y.k1) * &y.m1 + &y.m2) * y.r1.sq() * &y.phi1d + &y.m2 * &y.r1 * y.rsum() * &y.c * &y.thd
}

/// Eq. (53): `E/(m2 r²) = 0 = (1 − m2 cos²θ/((1 + k1) m1 + m2)) θ̇²/2 − (g/r)(1 −
/// cos θ)`. Returns the printed right-hand side.
pub fn eq53(y: &Sym) -> X {
    (1 - &y.m2 * y.c.sq() / ((1 + &y.k1) * &y.m1 + &y.m2)) * y.thd.sq() / 2
        - &y.g / y.rsum() * (1 - &y.c)
}

/// Eq. (54): `g_eff = −ẍ1 x̂ − g ŷ = −r1 φ̈1 x̂ − g ŷ = (m2 r/((1 + k1) m1 + m2))
/// (cos θ θ̈ − sin θ θ̇²) x̂ − g ŷ`. Returns the three printed x components.
pub fn eq54(y: &Sym) -> [X; 3] {
    [
        -&y.x1dd,
        -(&y.r1 * &y.phi1dd),
        &y.m2 * y.rsum() / ((1 + &y.k1) * &y.m1 + &y.m2) * (&y.c * &y.thdd - &y.s * y.thd.sq()),
    ]
}

/// Eq. (55): `r θ̇s² = r̂·g_eff = g cos θs − (m2 r sin θs/((1 + k1) m1 + m2))(cos θs
/// θ̈s − sin θs θ̇s²)`. Returns [r θ̇², r̂·g_eff with (54), last form].
pub fn eq55(y: &Sym) -> [X; 3] {
    let r = y.rsum();
    [
        &r * y.thd.sq(),
        rhat_dot_geff(y, &eq54(y)[2]),
        &y.g * &y.c
            - &y.m2 * r * &y.s / ((1 + &y.k1) * &y.m1 + &y.m2)
                * (&y.c * &y.thdd - &y.s * y.thd.sq()),
    ]
}

/// Footnote 11 (k1 = k2 = 1/2, frictionless floor): `(3 m1 + 2 m2 sin²θ) θ̇² =
/// 4(m1 + m2) g (1 − cos θ)/r`. Returns left − right.
pub fn fn11(y: &Sym) -> X {
    (3 * &y.m1 + 2 * &y.m2 * y.s.sq()) * y.thd.sq()
        - 4 * (&y.m1 + &y.m2) * &y.g * (1 - &y.c) / y.rsum()
}

/// Footnote 12 (m1 = m2, r1 = r2, k1 = k2, frictionless floor): (46) `becomes
/// φ̇1 = θ̇, such that φ1 = θ, and ... φ2 = φ1 − θ = 0`. Returns [φ̇1, φ1, φ2] as
/// printed (θ̇, θ, 0).
pub fn fn12(y: &Sym) -> [X; 3] {
    [y.thd.clone(), y.th.clone(), &y.phi1 - &y.th]
}

/// Footnote 12, Routh's relation (a = r1 = r2, k1 = k2 = k): `(k + 1 + sin²θ)
/// a θ̇² = 2g(1 − cos θ)`. Returns left − right.
pub fn fn12_routh(y: &Sym) -> X {
    (&y.k2 + 1 + y.s.sq()) * &y.r1 * y.thd.sq() - 2 * &y.g * (1 - &y.c)
}
