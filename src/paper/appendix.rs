//! The appendix (constraint forces via Lagrange multipliers), eqs. (56)–(114),
//! as printed.
//!
//! Coordinates are the paper's six, in the order of [`COORDS`]; in A.3 and A.5
//! the distance between the axes r is a coordinate (`Sym::r`). A Lagrange
//! equation `d/dt ∂L/∂q̇i − ∂L/∂qi = Σj λj ∂fj/∂qi = …` is encoded by its
//! printed right-hand members; the left side is the mechanics, which the audit
//! supplies. The constraint derivatives ∂fj/∂qi of the sums come from the
//! printed constraints (58)–(61) through a [`Jac`].

use super::{Sym, X};

/// The six coordinates of the appendix, in the order used by [`Jac`].
pub const COORDS: [&str; 6] = ["x1", "y1", "φ1", "φ2", "θ", "r"];
/// Index of x1.
pub const QX1: usize = 0;
/// Index of y1.
pub const QY1: usize = 1;
/// Index of φ1.
pub const QP1: usize = 2;
/// Index of φ2.
pub const QP2: usize = 3;
/// Index of θ.
pub const QTH: usize = 4;
/// Index of r.
pub const QR: usize = 5;

/// ∂fj/∂qi: row j = constraint f(j+1), column i = coordinate (see [`COORDS`]).
pub type Jac = [[X; 6]; 4];

/// Eq. (56): `d/dt ∂L/∂q̇i = ∂L/∂qi` — Lagrange's equations (a statement of the
/// method; no formula to evaluate).
pub const EQ56: &str = "d/dt ∂L/∂q̇i = ∂L/∂qi";

/// Eq. (57): `d/dt ∂L/∂q̇i − ∂L/∂qi = Σj λj ∂fj/∂qi` — the method of multipliers
/// (encoded through its instances (66)–(68), (75)–(77), (84)–(87), (93)–(95),
/// (103)–(108)).
pub const EQ57: &str = "d/dt ∂L/∂q̇i − ∂L/∂qi = Σj λj ∂fj/∂qi";

/// Eq. (58): `f1 = x1 − r1 φ1 = 0`.
pub fn eq58(y: &Sym) -> X {
    &y.x1 - &y.r1 * &y.phi1
}

/// Eq. (59): `f2 = r2 φ2 − r1(φ1 − θ) = 0`.
pub fn eq59(y: &Sym) -> X {
    &y.r2 * &y.phi2 - &y.r1 * (&y.phi1 - &y.th)
}

/// Eq. (60): `f3 = r − r1 − r2 = 0`.
pub fn eq60(y: &Sym) -> X {
    &y.r - &y.r1 - &y.r2
}

/// Eq. (61): `f4 = y1 − r1 = 0`.
pub fn eq61(y: &Sym) -> X {
    &y.y1 - &y.r1
}

/// The four printed constraints (58)–(61).
pub fn constraints(y: &Sym) -> [X; 4] {
    [eq58(y), eq59(y), eq60(y), eq61(y)]
}

/// Eq. (62): `T2 = (m2/2) ẋ1² + m2 ẋ1 r cos θ θ̇ + ((1 + k2) m2/2) r² θ̇² + k2 m2
/// r1² φ̇1²/2 − k2 m2 r1 r φ̇1 θ̇`.
pub fn eq62(y: &Sym) -> X {
    &y.m2 / 2 * y.x1d.sq()
        + &y.m2 * &y.x1d * &y.r * &y.c * &y.thd
        + (1 + &y.k2) * &y.m2 / 2 * y.r.sq() * y.thd.sq()
        + &y.k2 * &y.m2 * y.r1.sq() * y.phi1d.sq() / 2
        - &y.k2 * &y.m2 * &y.r1 * &y.r * &y.phi1d * &y.thd
}

/// Eq. (63): `p_x1 = ∂L/∂ẋ1 = (m1 + m2) ẋ1 + m2 r cos θ θ̇ = P_x`.
pub fn eq63(y: &Sym) -> X {
    (&y.m1 + &y.m2) * &y.x1d + &y.m2 * &y.r * &y.c * &y.thd
}

/// Eq. (64): `p_φ1 = ∂L/∂φ̇1 = (k1 m1 + k2 m2) r1² φ̇1 − k2 m2 r1 r θ̇ = k1 m1 r1²
/// φ̇1 + r1[k2 m2 (r1 φ̇1 − k2 m2 r θ̇)] = L1 + (r1/r2) L2`, given L1 and L2.
/// Returns the three forms.
pub fn eq64(y: &Sym, l1: &X, l2: &X) -> [X; 3] {
    [
        (&y.k1 * &y.m1 + &y.k2 * &y.m2) * y.r1.sq() * &y.phi1d
            - &y.k2 * &y.m2 * &y.r1 * &y.r * &y.thd,
        &y.k1 * &y.m1 * y.r1.sq() * &y.phi1d
            + &y.r1 * (&y.k2 * &y.m2 * (&y.r1 * &y.phi1d - &y.k2 * &y.m2 * &y.r * &y.thd)),
        l1 + &y.r1 / &y.r2 * l2,
    ]
}

/// Eq. (65): `∂f1/∂x1 = 1,  ∂f1/∂φ1 = −r1,  ∂f1/∂θ = 0`.
pub fn eq65(y: &Sym) -> [X; 3] {
    [y.r1.n(1), -&y.r1, y.r1.zero()]
}

/// Eq. (66): `dp_x1/dt = λ1 ∂f1/∂x1 = λ1`. Returns the two right members.
pub fn eq66(y: &Sym, d: &Jac) -> [X; 2] {
    [&y.lam[0] * &d[0][QX1], y.lam[0].clone()]
}

/// Eq. (67): `dp_φ1/dt = λ1 ∂f1/∂φ1 = −r1 λ1`. Returns the two right members.
pub fn eq67(y: &Sym, d: &Jac) -> [X; 2] {
    [&y.lam[0] * &d[0][QP1], -(&y.r1 * &y.lam[0])]
}

/// Eq. (68): `d/dt ∂L/∂θ̇ − ∂L/∂θ = λ1 ∂f1/∂θ = 0`. Returns the two right members.
pub fn eq68(y: &Sym, d: &Jac) -> [X; 2] {
    [&y.lam[0] * &d[0][QTH], y.r1.zero()]
}

/// Eq. (69): `d/dt(p_x1 + p_φ1/r1) = 0,  p_x1 + p_φ1/r1 = P_x + L1/r1 + L2/r2 = 0`,
/// given P_x, L1, L2. Returns [p_x1 + p_φ1/r1 from (63), (64), P_x + L1/r1 + L2/r2].
pub fn eq69(y: &Sym, px: &X, l1: &X, l2: &X) -> [X; 2] {
    let p = eq64(y, l1, l2);
    [eq63(y) + &p[0] / &y.r1, px + l1 / &y.r1 + l2 / &y.r2]
}

/// Eq. (70): `−λ1 = (1/r1) dp_φ1/dt = (k1 m1 + k2 m2) r1 φ̈1 − k2 m2 r θ̈`, "which
/// is the force F1 found in eq. (30)". Returns [−λ1, the last form].
pub fn eq70(y: &Sym) -> [X; 2] {
    [
        -&y.lam[0],
        (&y.k1 * &y.m1 + &y.k2 * &y.m2) * &y.r1 * &y.phi1dd - &y.k2 * &y.m2 * &y.r * &y.thdd,
    ]
}

/// Eq. (71): `T2 = (m2/2)[r1² φ̇1² + 2 r1 r cos θ φ̇1 θ̇ + r² θ̇²] + (k2 m2 r2²/2)
/// (φ̇2² − 2 φ̇2 θ̇ + θ̇²)`.
pub fn eq71(y: &Sym) -> X {
    &y.m2 / 2
        * (y.r1.sq() * y.phi1d.sq()
            + 2 * &y.r1 * &y.r * &y.c * &y.phi1d * &y.thd
            + y.r.sq() * y.thd.sq())
        + &y.k2 * &y.m2 * y.r2.sq() / 2 * (y.phi2d.sq() - 2 * &y.phi2d * &y.thd + y.thd.sq())
}

/// Eq. (72): `p_φ1 = ∂L/∂φ̇1 = [(1 + k1) m1 + m2] r1² φ̇1 + m2 r1 r cos θ θ̇`.
pub fn eq72(y: &Sym) -> X {
    ((1 + &y.k1) * &y.m1 + &y.m2) * y.r1.sq() * &y.phi1d + &y.m2 * &y.r1 * &y.r * &y.c * &y.thd
}

/// Eq. (73): `p_φ2 = ∂L/∂φ̇2 = k2 m2 r2² (φ̇2 − θ̇)`.
pub fn eq73(y: &Sym) -> X {
    &y.k2 * &y.m2 * y.r2.sq() * (&y.phi2d - &y.thd)
}

/// Eq. (74): `∂f2/∂φ1 = −r1,  ∂f2/∂φ2 = r2,  ∂f2/∂θ = r1`.
pub fn eq74(y: &Sym) -> [X; 3] {
    [-&y.r1, y.r2.clone(), y.r1.clone()]
}

/// Eq. (75): `dp_φ1/dt = λ2 ∂f2/∂φ1 = −r1 λ2`.
pub fn eq75(y: &Sym, d: &Jac) -> [X; 2] {
    [&y.lam[1] * &d[1][QP1], -(&y.r1 * &y.lam[1])]
}

/// Eq. (76): `dp_φ2/dt = λ2 ∂f2/∂φ2 = r2 λ2`.
pub fn eq76(y: &Sym, d: &Jac) -> [X; 2] {
    [&y.lam[1] * &d[1][QP2], &y.r2 * &y.lam[1]]
}

/// Eq. (77): `d/dt ∂L/∂θ̇ − ∂L/∂θ = λ2 ∂f2/∂θ = r1 λ2`.
pub fn eq77(y: &Sym, d: &Jac) -> [X; 2] {
    [&y.lam[1] * &d[1][QTH], &y.r1 * &y.lam[1]]
}

/// Eq. (78): `d/dt(p_φ1/r1 + p_φ2/r2) = 0,  p_φ1/r1 + p_φ2/r2 = 0`. Returns
/// p_φ1/r1 + p_φ2/r2 from (72), (73).
pub fn eq78(y: &Sym) -> X {
    eq72(y) / &y.r1 + eq73(y) / &y.r2
}

/// Eq. (79): `F2 = λ2 = (1/r2) dp_φ2/dt = k2 m2 r2 (φ̈2 − θ̈) = k2 m2 (r1 φ̈1 −
/// r θ̈)`. Returns [λ2, k2 m2 r2 (φ̈2 − θ̈), k2 m2 (r1 φ̈1 − r θ̈)].
pub fn eq79(y: &Sym) -> [X; 3] {
    [
        y.lam[1].clone(),
        &y.k2 * &y.m2 * &y.r2 * (&y.phi2dd - &y.thdd),
        &y.k2 * &y.m2 * (&y.r1 * &y.phi1dd - &y.r * &y.thdd),
    ]
}

/// Eq. (80): `T2 = (m2/2)[r1² φ̇1² + 2 r1 (r cos θ θ̇ + ṙ sin θ) φ̇1 + r² θ̇² + ṙ²]
/// + (k2 m2 r2²/2)(φ̇2² − 2 φ̇2 θ̇ + θ̇²)`.
pub fn eq80(y: &Sym) -> X {
    &y.m2 / 2
        * (y.r1.sq() * y.phi1d.sq()
            + 2 * &y.r1 * (&y.r * &y.c * &y.thd + &y.rd * &y.s) * &y.phi1d
            + y.r.sq() * y.thd.sq()
            + y.rd.sq())
        + &y.k2 * &y.m2 * y.r2.sq() / 2 * (y.phi2d.sq() - 2 * &y.phi2d * &y.thd + y.thd.sq())
}

/// Unnumbered, after eq. (80): `V = m2 g (r cos θ − r1 − r2)`.
pub fn a3_v(y: &Sym) -> X {
    &y.m2 * &y.g * (&y.r * &y.c - &y.r1 - &y.r2)
}

/// Eq. (81): `p_φ1 = ∂L/∂φ̇1 = [(1 + k1) m1 + m2] r1² φ̇1 + m2 r1 (r cos θ θ̇ + ṙ
/// sin θ) = r1 P_x + L1 + m2 r1 ṙ sin θ`, given P_x and L1. Returns both forms.
pub fn eq81(y: &Sym, px: &X, l1: &X) -> [X; 2] {
    [
        ((1 + &y.k1) * &y.m1 + &y.m2) * y.r1.sq() * &y.phi1d
            + &y.m2 * &y.r1 * (&y.r * &y.c * &y.thd + &y.rd * &y.s),
        &y.r1 * px + l1 + &y.m2 * &y.r1 * &y.rd * &y.s,
    ]
}

/// Eq. (82): `p_φ2 = ∂L/∂φ̇2 = k2 m2 r2² (φ̇2 − θ̇) = L2`, given L2.
pub fn eq82(y: &Sym, l2: &X) -> [X; 2] {
    [eq73(y), l2.clone()]
}

/// Eq. (83): `∂f3/∂φ1 = 0,  ∂f3/∂φ2 = 0,  ∂f3/∂θ = 0,  ∂f3/∂r = 1`.
pub fn eq83(y: &Sym) -> [X; 4] {
    let z = y.r1.zero();
    [z.clone(), z.clone(), z, y.r1.n(1)]
}

/// Eq. (84): `dp_φ1/dt = λ3 ∂f3/∂φ1 = 0`.
pub fn eq84(y: &Sym, d: &Jac) -> [X; 2] {
    [&y.lam[2] * &d[2][QP1], y.r1.zero()]
}

/// Eq. (85): `dp_φ2/dt = λ3 ∂f3/∂φ2 = 0`.
pub fn eq85(y: &Sym, d: &Jac) -> [X; 2] {
    [&y.lam[2] * &d[2][QP2], y.r1.zero()]
}

/// Eq. (86): `d/dt ∂L/∂θ̇ − ∂L/∂θ = λ3 ∂f3/∂θ = 0`.
pub fn eq86(y: &Sym, d: &Jac) -> [X; 2] {
    [&y.lam[2] * &d[2][QTH], y.r1.zero()]
}

/// Eq. (87): `d/dt ∂L/∂ṙ − ∂L/∂r = λ3 ∂f3/∂r = λ3`.
pub fn eq87(y: &Sym, d: &Jac) -> [X; 2] {
    [&y.lam[2] * &d[2][QR], y.lam[2].clone()]
}

/// Eq. (88): `λ3 = m2 r1 (sin θ φ̈1 + cos θ φ̇1 θ̇) − m2 (r1 cos θ θ̇ φ̇1 + r θ̇²) +
/// m2 g cos θ = m2 [r1 sin θ φ̈1 − r θ̇² + g cos θ]`. Returns both forms.
pub fn eq88(y: &Sym) -> [X; 2] {
    [
        &y.m2 * &y.r1 * (&y.s * &y.phi1dd + &y.c * &y.phi1d * &y.thd)
            - &y.m2 * (&y.r1 * &y.c * &y.thd * &y.phi1d + &y.r * y.thd.sq())
            + &y.m2 * &y.g * &y.c,
        &y.m2 * (&y.r1 * &y.s * &y.phi1dd - &y.r * y.thd.sq() + &y.g * &y.c),
    ]
}

/// Eq. (89): `r θ̇s² = g cos θ + r1 sin θs φ̈1 = g cos θ − A r sin θs [(cos θs − k2)
/// θ̈s − sin θs θ̇s²]` ("using eq. (17)"). Returns [r θ̇², second, third].
pub fn eq89(y: &Sym) -> [X; 3] {
    let a = &y.m2 / ((1 + &y.k1) * &y.m1 + (1 + &y.k2) * &y.m2);
    [
        &y.r * y.thd.sq(),
        &y.g * &y.c + &y.r1 * &y.s * &y.phi1dd,
        &y.g * &y.c - a * &y.r * &y.s * ((&y.c - &y.k2) * &y.thdd - &y.s * y.thd.sq()),
    ]
}

/// Eq. (90): `ΔT = ((m1 + m2)/2) ẏ1² − m2 r sin θ ẏ1 θ̇,  ΔV = (m1 + m2) g (y1 −
/// r1)`. Returns [ΔT, ΔV].
pub fn eq90(y: &Sym) -> [X; 2] {
    [
        (&y.m1 + &y.m2) / 2 * y.y1d.sq() - &y.m2 * &y.r * &y.s * &y.y1d * &y.thd,
        (&y.m1 + &y.m2) * &y.g * (&y.y1 - &y.r1),
    ]
}

/// Eq. (91): `p_φ1 = [(1 + k1) m1 + (1 + k2) m2] r1² φ̇1 + (cos θ − k2) m2 r1 r θ̇ =
/// r1 P_x + L1 + (r1/r2) L2`, given P_x, L1, L2. Returns both forms.
pub fn eq91(y: &Sym, px: &X, l1: &X, l2: &X) -> [X; 2] {
    [
        ((1 + &y.k1) * &y.m1 + (1 + &y.k2) * &y.m2) * y.r1.sq() * &y.phi1d
            + (&y.c - &y.k2) * &y.m2 * &y.r1 * &y.r * &y.thd,
        &y.r1 * px + l1 + &y.r1 / &y.r2 * l2,
    ]
}

/// Eq. (92): `∂f4/∂φ1 = 0,  ∂f4/∂θ = 0,  ∂f4/∂y1 = 1`.
pub fn eq92(y: &Sym) -> [X; 3] {
    [y.r1.zero(), y.r1.zero(), y.r1.n(1)]
}

/// Eq. (93): `dp_φ1/dt = λ4 ∂f3/∂φ1 = 0` (printed with f3).
pub fn eq93(y: &Sym, d: &Jac) -> [X; 2] {
    [&y.lam[3] * &d[2][QP1], y.r1.zero()]
}

/// Eq. (94): `d/dt ∂L/∂θ̇ − ∂L/∂θ = λ4 ∂f4/∂θ = 0`.
pub fn eq94(y: &Sym, d: &Jac) -> [X; 2] {
    [&y.lam[3] * &d[3][QTH], y.r1.zero()]
}

/// Eq. (95): `d/dt ∂L/∂ẏ1 − ∂L/∂y1 = λ4 ∂f4/∂y1 = λ4`.
pub fn eq95(y: &Sym, d: &Jac) -> [X; 2] {
    [&y.lam[3] * &d[3][QY1], y.lam[3].clone()]
}

/// Eq. (96): `F4 = λ4 = d/dt ∂L/∂ẏ1 − ∂L/∂y1 = (m1 + m2) ÿ1 − m2 r (sin θ θ̈ +
/// cos θ θ̇²) + (m1 + m2) g`. Returns [λ4, the last form].
pub fn eq96(y: &Sym) -> [X; 2] {
    [
        y.lam[3].clone(),
        (&y.m1 + &y.m2) * &y.y1dd - &y.m2 * &y.r * (&y.s * &y.thdd + &y.c * y.thd.sq())
            + (&y.m1 + &y.m2) * &y.g,
    ]
}

/// Eq. (97): `F4 = N1 = (m1 + m2) g − m2 r (sin θ θ̈ + cos θ θ̇²) = (m1 + m2) g +
/// m2 ÿ2`. Returns the two right forms.
pub fn eq97(y: &Sym) -> [X; 2] {
    [
        (&y.m1 + &y.m2) * &y.g - &y.m2 * &y.r * (&y.s * &y.thdd + &y.c * y.thd.sq()),
        (&y.m1 + &y.m2) * &y.g + &y.m2 * &y.y2dd,
    ]
}

/// Eq. (98): `T = ((m1 + m2)/2)(ẋ1² + ẏ1²) + (m1 k2 r1²/2) φ̇1² + (k2 m2 r2²/2)(φ̇2²
/// − 2 φ̇2 θ̇ + θ̇²) + (m2/2)(ṙ² + r² θ̇²) + m2 ṙ (ẋ1 sin θ + ẏ1 cos θ) + m2 r θ̇
/// (ẋ1 cos θ − ẏ1 sin θ)`.
pub fn eq98(y: &Sym) -> X {
    (&y.m1 + &y.m2) / 2 * (y.x1d.sq() + y.y1d.sq())
        + &y.m1 * &y.k2 * y.r1.sq() / 2 * y.phi1d.sq()
        + &y.k2 * &y.m2 * y.r2.sq() / 2 * (y.phi2d.sq() - 2 * &y.phi2d * &y.thd + y.thd.sq())
        + &y.m2 / 2 * (y.rd.sq() + y.r.sq() * y.thd.sq())
        + &y.m2 * &y.rd * (&y.x1d * &y.s + &y.y1d * &y.c)
        + &y.m2 * &y.r * &y.thd * (&y.x1d * &y.c - &y.y1d * &y.s)
}

/// Eq. (99): `V = −m2 g r (1 − cos θ) + (m1 + m2) g (y1 − r1)`.
pub fn eq99(y: &Sym) -> X {
    -(&y.m2 * &y.g * &y.r * (1 - &y.c)) + (&y.m1 + &y.m2) * &y.g * (&y.y1 - &y.r1)
}

/// Eq. (100): `p_x1 = ∂L/∂ẋ1 = (m1 + m2) ẋ1 + m2 (ṙ sin θ + r cos θ θ̇) = P_x`.
pub fn eq100(y: &Sym) -> X {
    (&y.m1 + &y.m2) * &y.x1d + &y.m2 * (&y.rd * &y.s + &y.r * &y.c * &y.thd)
}

/// Eq. (101): `p_φ1 = ∂L/∂φ̇1 = m1 k1 r1² φ̇1 = L1`.
pub fn eq101(y: &Sym) -> X {
    &y.m1 * &y.k1 * y.r1.sq() * &y.phi1d
}

/// Eq. (102): `p_φ2 = ∂L/∂φ̇2 = m2 k2 r2² (φ̇2 − θ̇) = L2`.
pub fn eq102(y: &Sym) -> X {
    &y.m2 * &y.k2 * y.r2.sq() * (&y.phi2d - &y.thd)
}

/// Σj λj ∂fj/∂qi for coordinate `i`.
pub fn multiplier_sum(y: &Sym, d: &Jac, i: usize) -> X {
    let mut s = y.r1.zero();
    for (j, row) in d.iter().enumerate() {
        s = s + &y.lam[j] * &row[i];
    }
    s
}

/// Eq. (103): `dp_x1/dt = Σj λj ∂fj/∂x1 = λ1`. Returns [the sum, λ1].
pub fn eq103(y: &Sym, d: &Jac) -> [X; 2] {
    [multiplier_sum(y, d, QX1), y.lam[0].clone()]
}

/// Eq. (104): `dp_φ1/dt = Σj λj ∂fj/∂φ1 = −r1 λ1 − r1 λ2`.
pub fn eq104(y: &Sym, d: &Jac) -> [X; 2] {
    [
        multiplier_sum(y, d, QP1),
        -(&y.r1 * &y.lam[0]) - &y.r1 * &y.lam[1],
    ]
}

/// Eq. (105): `dp_φ2/dt = Σj λj ∂fj/∂φ2 = r2 λ2`.
pub fn eq105(y: &Sym, d: &Jac) -> [X; 2] {
    [multiplier_sum(y, d, QP2), &y.r2 * &y.lam[1]]
}

/// Eq. (106): `d/dt ∂L/∂θ̇ − ∂L/∂θ = Σj λj ∂fj/∂θ = r1 λ2`.
pub fn eq106(y: &Sym, d: &Jac) -> [X; 2] {
    [multiplier_sum(y, d, QTH), &y.r1 * &y.lam[1]]
}

/// Eq. (107): `d/dt ∂L/∂ṙ − ∂L/∂r = Σj λj ∂fj/∂r = λ3`.
pub fn eq107(y: &Sym, d: &Jac) -> [X; 2] {
    [multiplier_sum(y, d, QR), y.lam[2].clone()]
}

/// Eq. (108): `d/dt ∂L/∂ẏ1 − ∂L/∂y1 = Σj λj ∂fj/∂y1 = λ4`.
pub fn eq108(y: &Sym, d: &Jac) -> [X; 2] {
    [multiplier_sum(y, d, QY1), y.lam[3].clone()]
}

/// Eq. (109): `d/dt(p_x1 + p_φ1/r1 + p_φ2/r2) = d/dt(P_x + L1/r1 + L2/r2) = 0,
/// P_x + L1/r1 + L2/r2 = 0`, given P_x, L1, L2. Returns [p_x1 + p_φ1/r1 + p_φ2/r2
/// from (100)–(102), P_x + L1/r1 + L2/r2].
pub fn eq109(y: &Sym, px: &X, l1: &X, l2: &X) -> [X; 2] {
    [
        eq100(y) + eq101(y) / &y.r1 + eq102(y) / &y.r2,
        px + l1 / &y.r1 + l2 / &y.r2,
    ]
}

/// Eq. (110): `λ1 = dp_x1/dt = (m1 + m2) ẍ1 + m2 (r cos θ θ̈ − r sin θ θ̇²)`.
/// Returns [λ1, the last form].
pub fn eq110(y: &Sym) -> [X; 2] {
    [
        y.lam[0].clone(),
        (&y.m1 + &y.m2) * &y.x1dd + &y.m2 * (&y.r * &y.c * &y.thdd - &y.r * &y.s * y.thd.sq()),
    ]
}

/// Eq. (111): `F2 = λ2 = (1/r2) dp_φ2/dt = k2 m2 r2 (φ̈2 − θ̈) = k2 m2 (r1 φ̈1 −
/// r θ̈)`. Returns [λ2, k2 m2 r2 (φ̈2 − θ̈), k2 m2 (r1 φ̈1 − r θ̈)].
pub fn eq111(y: &Sym) -> [X; 3] {
    eq79(y)
}

/// Eq. (112): `λ3 = m2 (ẍ1 sin θ + ẋ1 cos θ θ̇) − m2 (ẋ1 cos θ θ̇ + r θ̇²) + m2 g
/// cos θ = m2 (ẍ1 sin θ − r θ̇² + g cos θ)`. Returns both forms.
pub fn eq112(y: &Sym) -> [X; 2] {
    [
        &y.m2 * (&y.x1dd * &y.s + &y.x1d * &y.c * &y.thd)
            - &y.m2 * (&y.x1d * &y.c * &y.thd + &y.r * y.thd.sq())
            + &y.m2 * &y.g * &y.c,
        &y.m2 * (&y.x1dd * &y.s - &y.r * y.thd.sq() + &y.g * &y.c),
    ]
}

/// Eq. (113): `F4 = λ4 = (m1 + m2) ÿ1 − m2 r (sin θ θ̈ + cos θ θ̇²) + (m1 + m2) g`.
/// Returns [λ4, the last form].
pub fn eq113(y: &Sym) -> [X; 2] {
    eq96(y)
}

/// Eq. (114): `F4 = N1 = (m1 + m2) g − m2 r (sin θ θ̈ + cos θ θ̇²) = (m1 + m2) g +
/// m2 ÿ2`. Returns the two right forms.
pub fn eq114(y: &Sym) -> [X; 2] {
    eq97(y)
}
