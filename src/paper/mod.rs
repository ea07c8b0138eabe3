//! The paper's formulas exactly as printed, tagged by equation number.
//!
//! K. T. McDonald, *Cylinder Rolling on Another Rolling Cylinder*. Each
//! function is one numbered equation (or a footnote's formula) written as the
//! paper prints it, typographical slips included; the doc comment quotes it.
//! An equation with several printed forms (`a = b = c`) returns one value per
//! form, in the printed order, so that each form can be held against the
//! mechanics on its own. Nothing here is corrected: the corrections live in
//! [`crate::audit`], next to the evidence for them.
//!
//! Every formula is a function of a [`Sym`], the paper's symbols at one
//! instant (parameters, coordinates and their rates, forces). The functions do
//! no physics of their own and are not used by the oracle.
//!
//! [`CATALOGUE`] lists every numbered equation (1)–(114) and the footnote
//! formulas with the printed text, so that the audit can show what it checked.

pub mod appendix;
pub mod sec2;
pub mod sec3;
pub mod x;

pub use x::X;

/// The paper's symbols at one instant. Which fields are meaningful depends on
/// the equation (the main text works on the manifold y1 = r1, r = r1 + r2).
#[derive(Debug, Clone)]
pub struct Sym {
    /// m1.
    pub m1: X,
    /// m2.
    pub m2: X,
    /// r1.
    pub r1: X,
    /// r2.
    pub r2: X,
    /// k1 (I1 = k1 m1 r1²).
    pub k1: X,
    /// k2 (I2 = k2 m2 r2²).
    pub k2: X,
    /// g.
    pub g: X,
    /// ω0 (eq. 17: the value of φ̇1 when θ̇ = 0).
    pub omega0: X,
    /// Time since the start.
    pub t: X,
    /// x1: centre of cylinder 1.
    pub x1: X,
    /// y1: height of the centre of cylinder 1.
    pub y1: X,
    /// φ1: clockwise rotation of cylinder 1.
    pub phi1: X,
    /// φ2: the paper's angle of cylinder 2 (φ2 − θ is its counter-clockwise rotation).
    pub phi2: X,
    /// θ: the line of centres, clockwise from vertical.
    pub th: X,
    /// sin θ.
    pub s: X,
    /// cos θ.
    pub c: X,
    /// r: distance between the axes (r1 + r2 while touching).
    pub r: X,
    /// ẋ1.
    pub x1d: X,
    /// ẏ1.
    pub y1d: X,
    /// φ̇1.
    pub phi1d: X,
    /// φ̇2.
    pub phi2d: X,
    /// θ̇.
    pub thd: X,
    /// ṙ.
    pub rd: X,
    /// ẍ1.
    pub x1dd: X,
    /// ÿ1.
    pub y1dd: X,
    /// φ̈1.
    pub phi1dd: X,
    /// φ̈2.
    pub phi2dd: X,
    /// θ̈.
    pub thdd: X,
    /// r̈.
    pub rdd: X,
    /// ẋ2 (centre of cylinder 2).
    pub x2d: X,
    /// ẏ2.
    pub y2d: X,
    /// ÿ2.
    pub y2dd: X,
    /// F1: horizontal force of the floor on cylinder 1.
    pub f1: X,
    /// N1: vertical force of the floor on cylinder 1.
    pub n1: X,
    /// F21: friction force on cylinder 2 due to cylinder 1 (a signed number;
    /// its direction is a convention the audit states).
    pub f21: X,
    /// F12: friction force on cylinder 1 due to cylinder 2 (signed; the
    /// audit evaluates the paper's equations under each reading of its sign).
    pub f12: X,
    /// N12: normal force between the cylinders.
    pub n12: X,
    /// The multipliers λ1…λ4 of the constraints (58)–(61).
    pub lam: [X; 4],
}

impl Sym {
    /// r1 + r2 (the paper's r ≡ r1 + r2 of eq. 2, a constant).
    pub fn rsum(&self) -> X {
        &self.r1 + &self.r2
    }
    /// I1 = k1 m1 r1².
    pub fn i1(&self) -> X {
        &self.k1 * &self.m1 * self.r1.sq()
    }
    /// I2 = k2 m2 r2².
    pub fn i2(&self) -> X {
        &self.k2 * &self.m2 * self.r2.sq()
    }
}

/// One entry of the paper: its tag, section and the formula as printed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Printed {
    /// Equation number ("23"), footnote ("fn6") or prose claim ("p-signs").
    pub id: &'static str,
    /// Where it is printed.
    pub section: &'static str,
    /// The formula as printed (plain Unicode).
    pub text: &'static str,
}

macro_rules! printed {
    ($(($id:expr, $sec:expr, $text:expr)),* $(,)?) => {
        &[$(Printed { id: $id, section: $sec, text: $text }),*]
    };
}

/// Every numbered equation (1)–(114), the footnote formulas and the prose
/// claims the audit checks, in the paper's order, as printed.
pub const CATALOGUE: &[Printed] = printed![
    ("1", "2", "x1 = r1 φ1"),
    ("2", "2", "r2 φ2 = r1(φ1 − θ),  φ2 − θ = (r1/r2) φ1 − ((r1 + r2)/r2) θ = (r1 φ1 − r θ)/r2,  r ≡ r1 + r2"),
    ("3", "2", "V = −m2 g r (cos θ0 − cos θ)"),
    ("4", "2", "p_φ1 = ∂L/∂φ̇1 = ∂T/∂φ̇1"),
    ("5", "2", "T1 = m1 ẋ1²/2 + I1 φ̇1²/2 = ((1 + k1)/2) m1 r1² φ̇1²"),
    ("6", "2", "T2 = m2(ẋ2² + ẏ2²)/2 + I2(φ̇2 − θ̇)²/2 = m2(ẋ2² + ẏ2²)/2 + k2 m2 r2² (φ̇2 − θ̇)²/2"),
    ("7", "2", "x2 = x1 + r sin θ,  ẋ2 = r1 φ̇1 + r cos θ θ̇"),
    ("8", "2", "y2 = r1 + r cos θ,  ẏ2 = −r sin θ θ̇"),
    ("9", "2", "φ̇2 − θ̇ = (r1 φ̇1 − r θ̇)/r2"),
    ("10", "2", "T2 = (m2/2)[r1² φ̇1² + 2 r1 r cos θ φ̇1 θ̇ + r² θ̇²] + (k2 m2/2)[r1² φ̇1² − 2 r1 r φ̇1 θ̇ + r² θ̇²] = ((1 + k2)/2) m2 r1² φ̇1² + (cos θ − k2) m2 r1 r φ̇1 θ̇ + ((1 + k2)/2) m2 r² θ̇²"),
    ("11", "2", "T = (((1 + k1) m1 + (1 + k2) m2)/2) r1² φ̇1² + (cos θ − k2) m2 r1 r φ̇1 θ̇ + ((1 + k2)/2) m2 r² θ̇²"),
    ("12", "2", "p_φ1 = ∂T/∂φ̇1 = [(1 + k1) m1 + (1 + k2) m2] r1² φ̇1 + (cos θ − k2) m2 r1 r θ̇ = constant"),
    ("13", "2", "P_x = (m1 + m2) ẋ1 + m2 r cos θ θ̇ = (m1 + m2) r1 φ̇1 + m2 r cos θ θ̇"),
    ("14", "2", "L1 = k1 m1 r1² φ̇1"),
    ("15", "2", "L2 = k2 m2 r2² (φ̇2 − θ̇) = k2 m2 r2 (r1 φ̇1 − r θ̇)"),
    ("16", "2", "p_φ1 = r1 P_x + L1 + (r1/r2) L2"),
    ("17", "2", "φ̇1 = ω0 − (cos θ − k2) m2 r θ̇ / ([(1 + k1) m1 + (1 + k2) m2] r1) = ω0 − (A r/r1)(cos θ − k2) θ̇"),
    ("18", "2", "φ̈1 = −(A r/r1)[(cos θ − k2) θ̈ − sin θ θ̇²]"),
    ("19", "2", "A = m2 / ((1 + k1) m1 + (1 + k2) m2)"),
    ("20", "2", "φ1 = ω0 t − (A r/r1)(sin θ − k2 θ)   (θ0 = 0)"),
    ("21", "2", "φ2 = (r1/r2)(φ1 − θ) = (r1/r2) ω0 − (A r/r2)(sin θ − k2 θ) − (r1/r2) θ"),
    ("22", "2", "E/(m2 r²) = 0 = [1 + k2 − A(cos θ − k2)²] θ̇²/2 − (g/r)(1 − cos θ)"),
    ("23", "2.1", "θ̈ = [g/r − A(cos θ − k2) θ̇²] sin θ / [1 + k2 − A(cos θ − k2)²] = [1 + k2 − A(cos θ − k2)(3 − 2 cos θ)] / [1 + k2 − A(cos θ − k2)²]² (g/r) sin θ"),
    ("24", "2.1", "θ̈ ≈ (g/2r) θ   (k2 = 1, θ ≪ 1)"),
    ("25", "2.2.1", "x_cm = ((m1 + m2) x1 + m2 r sin θ)/(m1 + m2),  y_cm = ((m1 + m2) r1 + m2 r cos θ)/(m1 + m2)"),
    ("26", "2.2.1", "F1 = (m1 + m2) ẍ_cm = (m1 + m2) ẍ1 + m2 r (cos θ θ̈ − sin θ θ̇²) = (m1 + m2) r1 φ̈1 + m2 r (cos θ θ̈ − sin θ θ̇²)"),
    ("27", "2.2.1", "N1 = (m1 + m2) g + (m1 + m2) ÿ_cm = (m1 + m2) g − m2 r (sin θ θ̈ + cos θ θ̇²)"),
    ("28", "2.2.2", "F21 = (I2/r2)(φ̈2 − θ̈) = k2 m2 r2 (φ̈2 − θ̈) = k2 m2 (r1 φ̈1 − r θ̈)"),
    ("29", "2.2.2", "(F1 + F12) r1 = (F1 − F21) r1 = −I1 φ̈1 = −k1 m1 r1² φ̈1"),
    ("30", "2.2.2", "F1 = −(k1 m1 + k2 m2) r1 φ̈1 + k2 m2 r θ̈"),
    ("31", "2.2.3", "N12 cos θ = N1 − m1 g + F12 sin θ = m2 [g − r (sin θ θ̈ + cos θ θ̇²) + k2 (r1 φ̈1 − r θ̈) sin θ]"),
    ("32", "2.2.3", "N12 sin θ = F1 − m1 ẍ1 − F12 cos θ = m2 [r1 φ̈1 + r (cos θ θ̈ − sin θ θ̇²) − k2 (r1 φ̈1 − r θ̈) cos θ]"),
    ("33", "2.2.3", "N12 = N12 cos²θ + N12 sin²θ = g cos θ + r1 sin θ φ̇1 − r θ̇²"),
    ("34", "2.3", "r θ̇² = g cos θ + r1 sin θ φ̇1"),
    ("35", "2.3", "g_eff = −ẍ1 x̂ − g ŷ = −r1 φ̈1 x̂ − g ŷ"),
    ("36", "fn 8", "cos θs = 2/(3 + k2)"),
    ("37", "2.3", "r θ̇s² = r̂·g_eff = g cos θs + r1 sin θs φ̈1 = g cos θs − r A sin θs [(cos θs − k2) θ̈s − sin θs θ̇s²]"),
    ("38", "3.1", "T = ((m1 + m2)/2) ẋ1² + m2 r cos θ ẋ1 θ̇ + (m2/2) r² θ̇²"),
    ("39", "3.1", "p_x1 = ∂T/∂ẋ1 = (m1 + m2) ẋ1 + m2 r cos θ θ̇ = P_x = 0"),
    ("40", "3.1", "E/(m2 r²) = 0 = ((m1 + m2 sin²θ)/(m1 + m2)) θ̇²/2 − (g/r)(1 − cos θ)"),
    ("41", "3.1", "g_eff = −ẍ1 x̂ − g ŷ = (m2 r/(m1 + m2))(cos θ θ̈ − sin θ θ̇²) x̂ − g ŷ"),
    ("42", "3.1", "r θ̇s² = r̂·g_eff = g cos θs − (m2 r sin θs/(m1 + m2))(cos θs θ̈s − sin θs θ̇s²)"),
    ("43", "3.1", "m2 cos θs² = (m1 + m2)(3 cos θs − 2)"),
    ("44", "3.2", "T = ((m1 + m2)/2) ẋ1² + ((k1 m1 + k2 m2)/2) r1² φ̇1² + m2 r cos θ ẋ1 θ̇ − k2 m2 r1 r φ̇1 θ̇ + ((1 + k2)/2) m2 r² θ̇²"),
    ("45", "3.2", "p_x1 = ∂T/∂ẋ1 = (m1 + m2) ẋ1 + m2 r cos θ θ̇ = P_x = 0"),
    ("46", "3.2", "p_φ1 = ∂T/∂φ̇1 = (k1 m1 + k2 m2) r1² φ̇1 − k2 m2 r1 r θ̇ = L1 + (r1/r2) L2 = 0"),
    ("47", "3.2", "E/(m2 r²) = 0 = (1 + k2 − m2 cos²θ/(m1 + m2) − k2² m2/(k1 m1 + k2 m2)) θ̇²/2 − (g/r)(1 − cos θ)"),
    ("48", "3.2", "g_eff = −ẍ1 x̂ − g ŷ = (m2 r/(m1 + m2))(cos θ θ̈ − sin θ θ̇²) x̂ − g ŷ"),
    ("49", "3.2", "r θ̇s² = r̂·g_eff = g cos θs − (m2 r/(m1 + m2))(cos θs θ̈s − sin θs θ̇s²) sin θs"),
    ("50", "fn 12", "2[(2 + k) cos θs − 1] = cos θs (1 − cos θs)² (1 + cos θs)"),
    ("51", "3.3", "T = (((1 + k1) m1 + m2)/2) r1² φ̇1² + m2 r1 r cos θ φ̇1 θ̇ + (m2/2) r² θ̇²"),
    ("52", "3.3", "p_φ1 = ∂T/∂φ̇1 = [(1 + k1) m1 + m2] r1² φ̇1 + m2 r1 r cos θ θ̇ = 0"),
    ("53", "3.3", "E/(m2 r²) = 0 = (1 − m2 cos²θ/((1 + k1) m1 + m2)) θ̇²/2 − (g/r)(1 − cos θ)"),
    ("54", "3.3", "g_eff = −ẍ1 x̂ − g ŷ = −r1 φ̈1 x̂ − g ŷ = (m2 r/((1 + k1) m1 + m2))(cos θ θ̈ − sin θ θ̇²) x̂ − g ŷ"),
    ("55", "3.3", "r θ̇s² = r̂·g_eff = g cos θs − (m2 r sin θs/((1 + k1) m1 + m2))(cos θs θ̈s − sin θs θ̇s²)"),
    ("56", "A", "d/dt ∂L/∂q̇i = ∂L/∂qi"),
    ("57", "A", "d/dt ∂L/∂q̇i − ∂L/∂qi = Σj λj ∂fj/∂qi"),
    ("58", "A", "f1 = x1 − r1 φ1 = 0"),
    ("59", "A", "f2 = r2 φ2 − r1(φ1 − θ) = 0"),
    ("60", "A", "f3 = r − r1 − r2 = 0"),
    ("61", "A", "f4 = y1 − r1 = 0"),
    ("62", "A.1", "T2 = (m2/2) ẋ1² + m2 ẋ1 r cos θ θ̇ + ((1 + k2) m2/2) r² θ̇² + k2 m2 r1² φ̇1²/2 − k2 m2 r1 r φ̇1 θ̇"),
    ("63", "A.1", "p_x1 = ∂L/∂ẋ1 = (m1 + m2) ẋ1 + m2 r cos θ θ̇ = P_x"),
    ("64", "A.1", "p_φ1 = ∂L/∂φ̇1 = (k1 m1 + k2 m2) r1² φ̇1 − k2 m2 r1 r θ̇ = k1 m1 r1² φ̇1 + r1[k2 m2 (r1 φ̇1 − k2 m2 r θ̇)] = L1 + (r1/r2) L2"),
    ("65", "A.1", "∂f1/∂x1 = 1,  ∂f1/∂φ1 = −r1,  ∂f1/∂θ = 0"),
    ("66", "A.1", "dp_x1/dt = λ1 ∂f1/∂x1 = λ1"),
    ("67", "A.1", "dp_φ1/dt = λ1 ∂f1/∂φ1 = −r1 λ1"),
    ("68", "A.1", "d/dt ∂L/∂θ̇ − ∂L/∂θ = λ1 ∂f1/∂θ = 0"),
    ("69", "A.1", "d/dt (p_x1 + p_φ1/r1) = 0,  p_x1 + p_φ1/r1 = P_x + L1/r1 + L2/r2 = 0"),
    ("70", "A.1", "−λ1 = (1/r1) dp_φ1/dt = (k1 m1 + k2 m2) r1 φ̈1 − k2 m2 r θ̈   (\"the force F1 found in eq. (30)\")"),
    ("71", "A.2", "T2 = (m2/2)[r1² φ̇1² + 2 r1 r cos θ φ̇1 θ̇ + r² θ̇²] + (k2 m2 r2²/2)(φ̇2² − 2 φ̇2 θ̇ + θ̇²)"),
    ("72", "A.2", "p_φ1 = ∂L/∂φ̇1 = [(1 + k1) m1 + m2] r1² φ̇1 + m2 r1 r cos θ θ̇"),
    ("73", "A.2", "p_φ2 = ∂L/∂φ̇2 = k2 m2 r2² (φ̇2 − θ̇)"),
    ("74", "A.2", "∂f2/∂φ1 = −r1,  ∂f2/∂φ2 = r2,  ∂f2/∂θ = r1"),
    ("75", "A.2", "dp_φ1/dt = λ2 ∂f2/∂φ1 = −r1 λ2"),
    ("76", "A.2", "dp_φ2/dt = λ2 ∂f2/∂φ2 = r2 λ2"),
    ("77", "A.2", "d/dt ∂L/∂θ̇ − ∂L/∂θ = λ2 ∂f2/∂θ = r1 λ2"),
    ("78", "A.2", "d/dt (p_φ1/r1 + p_φ2/r2) = 0,  p_φ1/r1 + p_φ2/r2 = 0"),
    ("79", "A.2", "F2 = λ2 = (1/r2) dp_φ2/dt = k2 m2 r2 (φ̈2 − θ̈) = k2 m2 (r1 φ̈1 − r θ̈)   (\"previously found as F21 in eq. (28)\")"),
    ("80", "A.3", "T2 = (m2/2)[r1² φ̇1² + 2 r1 (r cos θ θ̇ + ṙ sin θ) φ̇1 + r² θ̇² + ṙ²] + (k2 m2 r2²/2)(φ̇2² − 2 φ̇2 θ̇ + θ̇²)"),
    ("A3-V", "A.3", "V = m2 g (r cos θ − r1 − r2)   (unnumbered, after eq. 80)"),
    ("81", "A.3", "p_φ1 = ∂L/∂φ̇1 = [(1 + k1) m1 + m2] r1² φ̇1 + m2 r1 (r cos θ θ̇ + ṙ sin θ) = r1 P_x + L1 + m2 r1 ṙ sin θ"),
    ("82", "A.3", "p_φ2 = ∂L/∂φ̇2 = k2 m2 r2² (φ̇2 − θ̇) = L2"),
    ("83", "A.3", "∂f3/∂φ1 = 0,  ∂f3/∂φ2 = 0,  ∂f3/∂θ = 0,  ∂f3/∂r = 1"),
    ("84", "A.3", "dp_φ1/dt = λ3 ∂f3/∂φ1 = 0"),
    ("85", "A.3", "dp_φ2/dt = λ3 ∂f3/∂φ2 = 0"),
    ("86", "A.3", "d/dt ∂L/∂θ̇ − ∂L/∂θ = λ3 ∂f3/∂θ = 0"),
    ("87", "A.3", "d/dt ∂L/∂ṙ − ∂L/∂r = λ3 ∂f3/∂r = λ3"),
    ("88", "A.3", "λ3 = m2 r1 (sin θ φ̈1 + cos θ φ̇1 θ̇) − m2 (r1 cos θ θ̇ φ̇1 + r θ̇²) + m2 g cos θ = m2 [r1 sin θ φ̈1 − r θ̇² + g cos θ]"),
    ("89", "A.3", "r θ̇s² = g cos θ + r1 sin θs φ̈1 = g cos θ − A r sin θs [(cos θs − k2) θ̈s − sin θs θ̇s²]   (\"using eq. (17)\")"),
    ("90", "A.4", "ΔT = ((m1 + m2)/2) ẏ1² − m2 r sin θ ẏ1 θ̇,  ΔV = (m1 + m2) g (y1 − r1)"),
    ("91", "A.4", "p_φ1 = [(1 + k1) m1 + (1 + k2) m2] r1² φ̇1 + (cos θ − k2) m2 r1 r θ̇ = r1 P_x + L1 + (r1/r2) L2"),
    ("92", "A.4", "∂f4/∂φ1 = 0,  ∂f4/∂θ = 0,  ∂f4/∂y1 = 1"),
    ("93", "A.4", "dp_φ1/dt = λ4 ∂f3/∂φ1 = 0"),
    ("94", "A.4", "d/dt ∂L/∂θ̇ − ∂L/∂θ = λ4 ∂f4/∂θ = 0"),
    ("95", "A.4", "d/dt ∂L/∂ẏ1 − ∂L/∂y1 = λ4 ∂f4/∂y1 = λ4"),
    ("96", "A.4", "F4 = λ4 = d/dt ∂L/∂ẏ1 − ∂L/∂y1 = (m1 + m2) ÿ1 − m2 r (sin θ θ̈ + cos θ θ̇²) + (m1 + m2) g"),
    ("97", "A.4", "F4 = N1 = (m1 + m2) g − m2 r (sin θ θ̈ + cos θ θ̇²) = (m1 + m2) g + m2 ÿ2"),
    ("98", "A.5", "T = ((m1 + m2)/2)(ẋ1² + ẏ1²) + (m1 k2 r1²/2) φ̇1² + (k2 m2 r2²/2)(φ̇2² − 2 φ̇2 θ̇ + θ̇²) + (m2/2)(ṙ² + r² θ̇²) + m2 ṙ (ẋ1 sin θ + ẏ1 cos θ) + m2 r θ̇ (ẋ1 cos θ − ẏ1 sin θ)"),
    ("99", "A.5", "V = −m2 g r (1 − cos θ) + (m1 + m2) g (y1 − r1)"),
    ("100", "A.5", "p_x1 = ∂L/∂ẋ1 = (m1 + m2) ẋ1 + m2 (ṙ sin θ + r cos θ θ̇) = P_x"),
    ("101", "A.5", "p_φ1 = ∂L/∂φ̇1 = m1 k1 r1² φ̇1 = L1"),
    ("102", "A.5", "p_φ2 = ∂L/∂φ̇2 = m2 k2 r2² (φ̇2 − θ̇) = L2"),
    ("103", "A.5", "dp_x1/dt = Σj λj ∂fj/∂x1 = λ1"),
    ("104", "A.5", "dp_φ1/dt = Σj λj ∂fj/∂φ1 = −r1 λ1 − r1 λ2"),
    ("105", "A.5", "dp_φ2/dt = Σj λj ∂fj/∂φ2 = r2 λ2"),
    ("106", "A.5", "d/dt ∂L/∂θ̇ − ∂L/∂θ = Σj λj ∂fj/∂θ = r1 λ2"),
    ("107", "A.5", "d/dt ∂L/∂ṙ − ∂L/∂r = Σj λj ∂fj/∂r = λ3"),
    ("108", "A.5", "d/dt ∂L/∂ẏ1 − ∂L/∂y1 = Σj λj ∂fj/∂y1 = λ4"),
    ("109", "A.5", "d/dt (p_x1 + p_φ1/r1 + p_φ2/r2) = d/dt (P_x + L1/r1 + L2/r2) = 0,  P_x + L1/r1 + L2/r2 = 0"),
    ("110", "A.5", "λ1 = dp_x1/dt = (m1 + m2) ẍ1 + m2 (r cos θ θ̈ − r sin θ θ̇²)"),
    ("111", "A.5", "F2 = λ2 = (1/r2) dp_φ2/dt = k2 m2 r2 (φ̈2 − θ̈) = k2 m2 (r1 φ̈1 − r θ̈)"),
    ("112", "A.5", "λ3 = m2 (ẍ1 sin θ + ẋ1 cos θ θ̇) − m2 (ẋ1 cos θ θ̇ + r θ̇²) + m2 g cos θ = m2 (ẍ1 sin θ − r θ̇² + g cos θ)"),
    ("113", "A.5", "F4 = λ4 = (m1 + m2) ÿ1 − m2 r (sin θ θ̈ + cos θ θ̇²) + (m1 + m2) g"),
    ("114", "A.5", "F4 = N1 = (m1 + m2) g − m2 r (sin θ θ̈ + cos θ θ̇²) = (m1 + m2) g + m2 ÿ2"),
    ("fn1", "fn 1", "one of the two constants k_i can be greater than 1 (a bobbin on a narrow track)"),
    ("fn3", "fn 3", "n cylinders: 3n degrees of freedom, n touching and n rolling constraints, n left; one conserved momentum"),
    ("fn6", "fn 6", "m1 = m2, r1 = r2 = a, k1 = k2 = 1/2:  θ̇² = 12(1 − cos θ)/a(17 + 4 cos θ − 4 cos²θ)"),
    ("fn8", "fn 8", "fixed lower cylinder: r θ̇s² = g cos θs;  (1 + k2) r θ̇²/2 = g(1 − cos θ);  cos θs → 2/3 (k2 → 0), 4/7 (k2 = 1/2), 10/17 (k2 = 2/5)"),
    ("fn11", "fn 11", "k1 = k2 = 1/2:  (3 m1 + 2 m2 sin²θ) θ̇² = 4(m1 + m2) g (1 − cos θ)/r"),
    ("fn12", "fn 12", "m1 = m2, r1 = r2 = a, k1 = k2 = k: (46) gives φ̇1 = θ̇, φ1 = θ, φ2 = φ1 − θ = 0: the cylinders roll together as one rigid body"),
    ("fn12-routh", "fn 12", "Routh: separation where (k + 1 + sin²θ) a θ̇² = 2g(1 − cos θ); the paper: this is just the energy relation (47)"),
    ("fn15", "fn 15", "F1 and F12 could also be determined via eqs. (104) and (106)"),
    ("p-steady", "2", "a particular solution: θ constant = θ0 with |θ0| < π/2, φ1 = ω0 t (the cylinders roll together), unstable"),
    ("p-phi1", "2", "k2 < 1, from rest: φ1 and θ have opposite signs until sin θ = k2 θ"),
    ("p-phi1dot", "2", "k2 < 1, from rest: φ̇1 and θ̇ have opposite signs until cos θ = k2"),
    ("p-bobbin", "2", "k2 > 1: φ1 and θ (and φ̇1 and θ̇) always have the same signs"),
    ("p-momentum", "2", "k2 > 1 (the figure): the system has positive x-momentum, although it started from rest"),
    ("p-phi2", "2", "k2 < 1: φ1 and φ2 have the same sign at small times, opposite to θ; k2 > 1: φ2 can share θ's sign for a subset of parameters"),
    ("p-fixed-slip", "3.1, 3.3", "no friction, lower cylinder fixed: cos θs = 2/3"),
    ("p-fixed-roll", "3.2", "rolling contact, lower cylinder fixed: cos θs = 2/(3 + k2)"),
];

/// The catalogue entry for `id` (`"23"`, `"fn6"`, …).
pub fn printed(id: &str) -> Option<&'static Printed> {
    CATALOGUE.iter().find(|p| p.id == id)
}
