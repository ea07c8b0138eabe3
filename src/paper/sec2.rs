//! Section 2 (both contacts rolling), eqs. (1)–(37), and footnotes 6 and 8,
//! as printed.

use super::{Sym, X};

/// A = m2 / ((1 + k1) m1 + (1 + k2) m2), eq. (19).
fn a_of(y: &Sym) -> X {
    eq19(y)
}

/// Eq. (1): `x1 = r1 φ1`. Returns r1 φ1.
pub fn eq1(y: &Sym) -> X {
    &y.r1 * &y.phi1
}

/// Eq. (2): `r2 φ2 = r1(φ1 − θ),  φ2 − θ = (r1/r2) φ1 − ((r1 + r2)/r2) θ =
/// (r1 φ1 − r θ)/r2`. Returns [φ2 from the first form, φ2 − θ from the second,
/// φ2 − θ from the third].
pub fn eq2(y: &Sym) -> [X; 3] {
    let r = y.rsum();
    [
        &y.r1 * (&y.phi1 - &y.th) / &y.r2,
        &y.r1 / &y.r2 * &y.phi1 - (&y.r1 + &y.r2) / &y.r2 * &y.th,
        (&y.r1 * &y.phi1 - r * &y.th) / &y.r2,
    ]
}

/// Eq. (3): `V = −m2 g r (cos θ0 − cos θ)`, with `cos0` = cos θ0.
pub fn eq3(y: &Sym, cos0: &X) -> X {
    -(&y.m2 * &y.g * y.rsum() * (cos0 - &y.c))
}

/// Eq. (4): `p_φ1 = ∂L/∂φ̇1 = ∂T/∂φ̇1` — the definition of the canonical
/// momentum (its value is eq. 12).
pub const EQ4: &str = "p_φ1 = ∂L/∂φ̇1 = ∂T/∂φ̇1";

/// Eq. (5): `T1 = m1 ẋ1²/2 + I1 φ̇1²/2 = ((1 + k1)/2) m1 r1² φ̇1²`.
pub fn eq5(y: &Sym) -> [X; 2] {
    [
        &y.m1 * y.x1d.sq() / 2 + y.i1() * y.phi1d.sq() / 2,
        (1 + &y.k1) / 2 * &y.m1 * y.r1.sq() * y.phi1d.sq(),
    ]
}

/// Eq. (6): `T2 = m2(ẋ2² + ẏ2²)/2 + I2(φ̇2 − θ̇)²/2 = m2(ẋ2² + ẏ2²)/2 +
/// k2 m2 r2² (φ̇2 − θ̇)²/2`.
pub fn eq6(y: &Sym) -> [X; 2] {
    let cm = &y.m2 * (y.x2d.sq() + y.y2d.sq()) / 2;
    let w = (&y.phi2d - &y.thd).sq();
    [
        &cm + y.i2() * &w / 2,
        cm + &y.k2 * &y.m2 * y.r2.sq() * w / 2,
    ]
}

/// Eq. (7): `x2 = x1 + r sin θ,  ẋ2 = r1 φ̇1 + r cos θ θ̇`. Returns [x2, ẋ2].
pub fn eq7(y: &Sym) -> [X; 2] {
    let r = y.rsum();
    [&y.x1 + &r * &y.s, &y.r1 * &y.phi1d + r * &y.c * &y.thd]
}

/// Eq. (8): `y2 = r1 + r cos θ,  ẏ2 = −r sin θ θ̇`. Returns [y2, ẏ2].
pub fn eq8(y: &Sym) -> [X; 2] {
    let r = y.rsum();
    [&y.r1 + &r * &y.c, -(r * &y.s * &y.thd)]
}

/// Eq. (9): `φ̇2 − θ̇ = (r1 φ̇1 − r θ̇)/r2`.
pub fn eq9(y: &Sym) -> X {
    (&y.r1 * &y.phi1d - y.rsum() * &y.thd) / &y.r2
}

/// Eq. (10): `T2 = (m2/2)[r1² φ̇1² + 2 r1 r cos θ φ̇1 θ̇ + r² θ̇²] + (k2 m2/2)
/// [r1² φ̇1² − 2 r1 r φ̇1 θ̇ + r² θ̇²] = ((1 + k2)/2) m2 r1² φ̇1² + (cos θ − k2)
/// m2 r1 r φ̇1 θ̇ + ((1 + k2)/2) m2 r² θ̇²`.
pub fn eq10(y: &Sym) -> [X; 2] {
    let r = y.rsum();
    let (p, t) = (&y.phi1d, &y.thd);
    let a = y.r1.sq() * p.sq();
    let b = 2 * &y.r1 * &r * p * t;
    let d = r.sq() * t.sq();
    [
        &y.m2 / 2 * (&a + &b * &y.c + &d) + &y.k2 * &y.m2 / 2 * (&a - &b + &d),
        (1 + &y.k2) / 2 * &y.m2 * y.r1.sq() * p.sq()
            + (&y.c - &y.k2) * &y.m2 * &y.r1 * &r * p * t
            + (1 + &y.k2) / 2 * &y.m2 * r.sq() * t.sq(),
    ]
}

/// Eq. (11): `T = (((1 + k1) m1 + (1 + k2) m2)/2) r1² φ̇1² + (cos θ − k2) m2
/// r1 r φ̇1 θ̇ + ((1 + k2)/2) m2 r² θ̇²`.
pub fn eq11(y: &Sym) -> X {
    let r = y.rsum();
    let (p, t) = (&y.phi1d, &y.thd);
    ((1 + &y.k1) * &y.m1 + (1 + &y.k2) * &y.m2) / 2 * y.r1.sq() * p.sq()
        + (&y.c - &y.k2) * &y.m2 * &y.r1 * &r * p * t
        + (1 + &y.k2) / 2 * &y.m2 * r.sq() * t.sq()
}

/// Eq. (12): `p_φ1 = [(1 + k1) m1 + (1 + k2) m2] r1² φ̇1 + (cos θ − k2) m2 r1 r
/// θ̇ = constant`.
pub fn eq12(y: &Sym) -> X {
    ((1 + &y.k1) * &y.m1 + (1 + &y.k2) * &y.m2) * y.r1.sq() * &y.phi1d
        + (&y.c - &y.k2) * &y.m2 * &y.r1 * y.rsum() * &y.thd
}

/// Eq. (13): `P_x = (m1 + m2) ẋ1 + m2 r cos θ θ̇ = (m1 + m2) r1 φ̇1 + m2 r cos θ θ̇`.
pub fn eq13(y: &Sym) -> [X; 2] {
    let m = &y.m1 + &y.m2;
    let tail = &y.m2 * y.rsum() * &y.c * &y.thd;
    [&m * &y.x1d + &tail, m * &y.r1 * &y.phi1d + tail]
}

/// Eq. (14): `L1 = k1 m1 r1² φ̇1`.
pub fn eq14(y: &Sym) -> X {
    &y.k1 * &y.m1 * y.r1.sq() * &y.phi1d
}

/// Eq. (15): `L2 = k2 m2 r2² (φ̇2 − θ̇) = k2 m2 r2 (r1 φ̇1 − r θ̇)`.
pub fn eq15(y: &Sym) -> [X; 2] {
    [
        &y.k2 * &y.m2 * y.r2.sq() * (&y.phi2d - &y.thd),
        &y.k2 * &y.m2 * &y.r2 * (&y.r1 * &y.phi1d - y.rsum() * &y.thd),
    ]
}

/// Eq. (16): `p_φ1 = r1 P_x + L1 + (r1/r2) L2`, given P_x, L1 and L2.
pub fn eq16(y: &Sym, px: &X, l1: &X, l2: &X) -> X {
    &y.r1 * px + l1 + &y.r1 / &y.r2 * l2
}

/// Eq. (17): `φ̇1 = ω0 − (cos θ − k2) m2 r θ̇ / ([(1 + k1) m1 + (1 + k2) m2] r1)
/// = ω0 − (A r/r1)(cos θ − k2) θ̇`.
pub fn eq17(y: &Sym) -> [X; 2] {
    let r = y.rsum();
    [
        &y.omega0
            - (&y.c - &y.k2) * &y.m2 * &r * &y.thd
                / (((1 + &y.k1) * &y.m1 + (1 + &y.k2) * &y.m2) * &y.r1),
        &y.omega0 - a_of(y) * r / &y.r1 * (&y.c - &y.k2) * &y.thd,
    ]
}

/// Eq. (18): `φ̈1 = −(A r/r1)[(cos θ − k2) θ̈ − sin θ θ̇²]`.
pub fn eq18(y: &Sym) -> X {
    -(a_of(y) * y.rsum() / &y.r1 * ((&y.c - &y.k2) * &y.thdd - &y.s * y.thd.sq()))
}

/// Eq. (19): `A = m2 / ((1 + k1) m1 + (1 + k2) m2)`.
pub fn eq19(y: &Sym) -> X {
    &y.m2 / ((1 + &y.k1) * &y.m1 + (1 + &y.k2) * &y.m2)
}

/// Eq. (20): `φ1 = ω0 t − (A r/r1)(sin θ − k2 θ)` (for θ0 = 0).
pub fn eq20(y: &Sym) -> X {
    &y.omega0 * &y.t - a_of(y) * y.rsum() / &y.r1 * (&y.s - &y.k2 * &y.th)
}

/// Eq. (21): `φ2 = (r1/r2)(φ1 − θ) = (r1/r2) ω0 − (A r/r2)(sin θ − k2 θ) −
/// (r1/r2) θ` (printed with ω0, not ω0 t).
pub fn eq21(y: &Sym) -> [X; 2] {
    let q = &y.r1 / &y.r2;
    [
        &q * (&y.phi1 - &y.th),
        &q * &y.omega0 - a_of(y) * y.rsum() / &y.r2 * (&y.s - &y.k2 * &y.th) - q * &y.th,
    ]
}

/// Eq. (22): `E/(m2 r²) = 0 = [1 + k2 − A(cos θ − k2)²] θ̇²/2 − (g/r)(1 − cos θ)`.
/// Returns the printed right-hand side (which the paper says is 0).
pub fn eq22(y: &Sym) -> X {
    let r = y.rsum();
    (1 + &y.k2 - a_of(y) * (&y.c - &y.k2).sq()) * y.thd.sq() / 2 - &y.g / r * (1 - &y.c)
}

/// Eq. (23): `θ̈ = [g/r − A(cos θ − k2) θ̇²] sin θ / [1 + k2 − A(cos θ − k2)²]
/// = [1 + k2 − A(cos θ − k2)(3 − 2 cos θ)] / [1 + k2 − A(cos θ − k2)²]²
/// (g/r) sin θ`.
pub fn eq23(y: &Sym) -> [X; 2] {
    let a = a_of(y);
    let gr = &y.g / y.rsum();
    let cm = &y.c - &y.k2;
    let den = 1 + &y.k2 - &a * cm.sq();
    [
        (&gr - &a * &cm * y.thd.sq()) * &y.s / &den,
        (1 + &y.k2 - &a * &cm * (3 - 2 * &y.c)) / den.sq() * gr * &y.s,
    ]
}

/// Eq. (24): `θ̈ ≈ (g/2r) θ` (k2 = 1, θ ≪ 1). Returns the coefficient g/(2r).
pub fn eq24(y: &Sym) -> X {
    &y.g / (2 * y.rsum())
}

/// Eq. (25): `x_cm = ((m1 + m2) x1 + m2 r sin θ)/(m1 + m2),  y_cm = ((m1 + m2)
/// r1 + m2 r cos θ)/(m1 + m2)`.
pub fn eq25(y: &Sym) -> [X; 2] {
    let m = &y.m1 + &y.m2;
    let r = y.rsum();
    [
        (&m * &y.x1 + &y.m2 * &r * &y.s) / &m,
        (&m * &y.r1 + &y.m2 * r * &y.c) / m,
    ]
}

/// Eq. (26): `F1 = (m1 + m2) ẍ_cm = (m1 + m2) ẍ1 + m2 r (cos θ θ̈ − sin θ θ̇²)
/// = (m1 + m2) r1 φ̈1 + m2 r (cos θ θ̈ − sin θ θ̇²)`. Returns the last two forms.
pub fn eq26(y: &Sym) -> [X; 2] {
    let m = &y.m1 + &y.m2;
    let tang = &y.m2 * y.rsum() * (&y.c * &y.thdd - &y.s * y.thd.sq());
    [&m * &y.x1dd + &tang, m * &y.r1 * &y.phi1dd + tang]
}

/// Eq. (27): `N1 = (m1 + m2) g + (m1 + m2) ÿ_cm = (m1 + m2) g − m2 r (sin θ θ̈
/// + cos θ θ̇²)`. Returns the last form.
pub fn eq27(y: &Sym) -> X {
    (&y.m1 + &y.m2) * &y.g - &y.m2 * y.rsum() * (&y.s * &y.thdd + &y.c * y.thd.sq())
}

/// Eq. (28): `F21 = (I2/r2)(φ̈2 − θ̈) = k2 m2 r2 (φ̈2 − θ̈) = k2 m2 (r1 φ̈1 − r θ̈)`.
pub fn eq28(y: &Sym) -> [X; 3] {
    let w = &y.phi2dd - &y.thdd;
    [
        y.i2() / &y.r2 * &w,
        &y.k2 * &y.m2 * &y.r2 * w,
        &y.k2 * &y.m2 * (&y.r1 * &y.phi1dd - y.rsum() * &y.thdd),
    ]
}

/// Eq. (29): `(F1 + F12) r1 = (F1 − F21) r1 = −I1 φ̈1 = −k1 m1 r1² φ̈1`.
/// Returns the four printed members.
pub fn eq29(y: &Sym) -> [X; 4] {
    [
        (&y.f1 + &y.f12) * &y.r1,
        (&y.f1 - &y.f21) * &y.r1,
        -(y.i1() * &y.phi1dd),
        -(&y.k1 * &y.m1 * y.r1.sq() * &y.phi1dd),
    ]
}

/// Eq. (30): `F1 = −(k1 m1 + k2 m2) r1 φ̈1 + k2 m2 r θ̈`.
pub fn eq30(y: &Sym) -> X {
    -((&y.k1 * &y.m1 + &y.k2 * &y.m2) * &y.r1 * &y.phi1dd) + &y.k2 * &y.m2 * y.rsum() * &y.thdd
}

/// Eq. (31): `N12 cos θ = N1 − m1 g + F12 sin θ = m2 [g − r (sin θ θ̈ + cos θ
/// θ̇²) + k2 (r1 φ̈1 − r θ̈) sin θ]`. Returns the two right-hand forms.
pub fn eq31(y: &Sym) -> [X; 2] {
    let r = y.rsum();
    [
        &y.n1 - &y.m1 * &y.g + &y.f12 * &y.s,
        &y.m2
            * (&y.g - &r * (&y.s * &y.thdd + &y.c * y.thd.sq())
                + &y.k2 * (&y.r1 * &y.phi1dd - &r * &y.thdd) * &y.s),
    ]
}

/// Eq. (32): `N12 sin θ = F1 − m1 ẍ1 − F12 cos θ = m2 [r1 φ̈1 + r (cos θ θ̈ −
/// sin θ θ̇²) − k2 (r1 φ̈1 − r θ̈) cos θ]`. Returns the two right-hand forms.
pub fn eq32(y: &Sym) -> [X; 2] {
    let r = y.rsum();
    [
        &y.f1 - &y.m1 * &y.x1dd - &y.f12 * &y.c,
        &y.m2
            * (&y.r1 * &y.phi1dd + &r * (&y.c * &y.thdd - &y.s * y.thd.sq())
                - &y.k2 * (&y.r1 * &y.phi1dd - &r * &y.thdd) * &y.c),
    ]
}

/// Eq. (33): `N12 = N12 cos²θ + N12 sin²θ = g cos θ + r1 sin θ φ̇1 − r θ̇²`.
/// Returns the last form.
pub fn eq33(y: &Sym) -> X {
    &y.g * &y.c + &y.r1 * &y.s * &y.phi1d - y.rsum() * y.thd.sq()
}

/// Eq. (34): `r θ̇² = g cos θ + r1 sin θ φ̇1` (the separation condition).
/// Returns [left side, right side].
pub fn eq34(y: &Sym) -> [X; 2] {
    [y.rsum() * y.thd.sq(), &y.g * &y.c + &y.r1 * &y.s * &y.phi1d]
}

/// Eq. (35): `g_eff = −ẍ1 x̂ − g ŷ = −r1 φ̈1 x̂ − g ŷ`. Returns the two printed
/// x components (the y component is −g in both).
pub fn eq35(y: &Sym) -> [X; 2] {
    [-&y.x1dd, -(&y.r1 * &y.phi1dd)]
}

/// Eq. (36) (footnote 8, lower cylinder fixed): `cos θs = 2/(3 + k2)`.
pub fn eq36(k2: &X) -> X {
    2i32 / (3 + k2)
}

/// r̂·g_eff with r̂ = −(sin θ, cos θ) and g_eff = (gx, −g) (eqs. 37, 42, 49, 55).
pub fn rhat_dot_geff(y: &Sym, gx: &X) -> X {
    -(&y.s * gx) + &y.c * &y.g
}

/// Eq. (37): `r θ̇s² = r̂·g_eff = g cos θs + r1 sin θs φ̈1 = g cos θs − r A sin θs
/// [(cos θs − k2) θ̈s − sin θs θ̇s²]`. Returns [r θ̇², r̂·g_eff with g_eff of (35),
/// second form, third form].
pub fn eq37(y: &Sym) -> [X; 4] {
    let r = y.rsum();
    [
        &r * y.thd.sq(),
        rhat_dot_geff(y, &eq35(y)[1]),
        &y.g * &y.c + &y.r1 * &y.s * &y.phi1dd,
        &y.g * &y.c - r * a_of(y) * &y.s * ((&y.c - &y.k2) * &y.thdd - &y.s * y.thd.sq()),
    ]
}

/// Footnote 6 (m1 = m2, r1 = r2 = a, k1 = k2 = 1/2): `θ̇² = 12(1 − cos θ)/a(17
/// + 4 cos θ − 4 cos²θ)` (printed without g). Returns the printed θ̇².
pub fn fn6(y: &Sym) -> X {
    let a = &y.r1;
    12 * (1 - &y.c) / (a * (17 + 4 * &y.c - 4 * y.c.sq()))
}

/// Footnote 8 (lower cylinder fixed): `r θ̇s² = g cos θs` and `(1 + k2) r θ̇²/2 =
/// g(1 − cos θ)`. Returns [r θ̇² − g cos θ, (1 + k2) r θ̇²/2 − g(1 − cos θ)].
pub fn fn8(y: &Sym) -> [X; 2] {
    let r = y.rsum();
    [
        &r * y.thd.sq() - &y.g * &y.c,
        (1 + &y.k2) * r * y.thd.sq() / 2 - &y.g * (1 - &y.c),
    ]
}

/// Footnote 8's values: cos θs = 2/3 (k2 → 0), 4/7 (k2 = 1/2), 10/17 (k2 = 2/5),
/// as (k2 numerator, k2 denominator, cos θs numerator, cos θs denominator).
pub const FN8_VALUES: [(i64, i64, i64, i64); 3] = [(0, 1, 2, 3), (1, 2, 4, 7), (2, 5, 10, 17)];
