//! What the paper's formulas are held against: the first-principles
//! mechanics of `crate::mechanics`, evaluated on the motion, and the kinetic
//! and potential energy of the two bodies written from their definitions.
//!
//! * On the motion (a [`Case`]): θ, θ̇, θ̈ and the velocities and
//!   accelerations of x1, φ1, ψ2 come from the Routh-reduced dynamics
//!   ([`Dyn::state`]); the constraint forces from the Lagrange-multiplier
//!   system in six coordinates ([`kkt::solve`]), an independent route.
//! * Off the motion (any state of the six coordinates): T is the sum over the
//!   two bodies of ½m|v_centre|² + ½I ω², with cylinder 2's centre at
//!   (x1 + r sin θ, y1 + r cos θ) and its spin φ̇2 − θ̇; V = m1 g y1 + m2 g y2.
//!   Canonical momenta are ∂T/∂q̇ by an exact central difference (T is
//!   quadratic in the rates); Lagrange's left sides d/dt ∂L/∂q̇ − ∂L/∂q
//!   in the paper's six coordinates are [`e6`], and in a reduced set of
//!   coordinates their projection through the embedding ([`Sys`]).

use super::points::Point;
use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::mechanics::dynamics::{Dyn, State};
use crate::mechanics::kkt::{self, Bodies};
use crate::mechanics::{Reduced, PHI1, PSI2, X1};
use crate::model::{Contact, Floor, Ideal, Start};
use crate::oracle::Oracle;
use crate::paper::appendix::{QP1, QP2, QR, QTH, QX1, QY1};
use crate::paper::{Sym, X};
use rug::{Float, Rational};

/// Working precision of the audit (bits): 224 bits ≈ 67 decimal digits.
pub const PREC: u32 = 224;

/// Digits asked of the oracle where the audit compares with it.
pub const ORACLE_DIGITS: u32 = 60;

/// How the motion starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum StartKind {
    /// From rest exactly at the top, ω0 = 0 (the paper's premise in most places).
    Rest,
    /// The point's general start: θ0 > 0, θ̇0 > 0, ω0 ≠ 0.
    General,
    /// θ0 = 0 with the point's θ̇0 > 0 and ω0 ≠ 0 (eqs. 20, 21 need θ0 = 0).
    Kick,
}

impl StartKind {
    /// Short label.
    pub fn label(self) -> &'static str {
        match self {
            StartKind::Rest => "rest",
            StartKind::General => "general",
            StartKind::Kick => "kick",
        }
    }
}

/// Natural scales of one case, for relative residuals.
#[derive(Debug, Clone)]
pub struct Scales {
    /// (m1 + m2) g.
    pub force: X,
    /// (m1 + m2) g r: energy, torque.
    pub energy: X,
    /// √(g/r).
    pub omega: X,
    /// g/r.
    pub accel: X,
    /// (m1 + m2) √(g r): linear momentum.
    pub mom: X,
    /// (m1 + m2) r √(g r): angular momentum.
    pub angmom: X,
    /// r.
    pub len: X,
}

impl Scales {
    fn of(p: &crate::model::Params) -> Self {
        let m = X::q(PREC, &Rational::from(&p.m1 + &p.m2));
        let g = X::q(PREC, &p.g);
        let r = X::q(PREC, &p.r());
        let omega = (&g / &r).sqrt();
        Scales {
            force: &m * &g,
            energy: &m * &g * &r,
            accel: &g / &r,
            mom: &m * (&g * &r).sqrt(),
            angmom: &m * &r * (&g * &r).sqrt(),
            len: r,
            omega,
        }
    }
}

/// One model evaluated along its motion at a few sample angles.
pub struct Case {
    /// "P1 roll/roll rest", for messages.
    pub name: String,
    /// The model.
    pub model: Ideal,
    /// Exact reduced dynamics.
    pub red: Reduced,
    /// The dynamics at [`PREC`].
    pub dynm: Dyn,
    /// The bodies for the multiplier system.
    pub bodies: Bodies,
    /// Sample angles δ = θ − θ0 (exact), inside the motion before separation.
    pub deltas: Vec<Rational>,
    /// The paper's symbols at each sample angle.
    pub syms: Vec<Sym>,
    /// The paper's symbols at the start (δ = 0, t = 0).
    pub sym0: Option<Sym>,
    /// Natural scales.
    pub scales: Scales,
}

/// The model of `point` with the given contacts and start.
pub fn model_of(point: &Point, floor: Floor, contact: Contact, start: StartKind) -> Result<Ideal> {
    let (th0, td0, w0) = match start {
        StartKind::Rest => (Rational::new(), Rational::new(), Rational::new()),
        StartKind::General => (
            point.theta0.clone(),
            point.thetadot0.clone(),
            point.omega0.clone(),
        ),
        StartKind::Kick => (
            Rational::new(),
            point.thetadot0.clone(),
            point.omega0.clone(),
        ),
    };
    let w0 = if floor == Floor::Fixed {
        Rational::new()
    } else {
        w0
    };
    Ideal::new(
        point.params.clone(),
        floor,
        contact,
        Start {
            theta0: Exact::rational(th0),
            thetadot0: td0,
            omega0: w0,
        },
    )
}

fn fx(q: &Rational) -> X {
    X::q(PREC, q)
}

/// δs located by a coarse scan of N12 (for placing the sample angles only).
fn coarse_delta_s(model: &Ideal, red: &Reduced) -> Result<Float> {
    let p = 64;
    let d = Dyn::new(model, red, p)?;
    let th0 = model.start().theta0.to_float(p);
    let hi = Float::with_val(p, rug::float::Constant::Pi) - th0;
    let z = Float::new(p);
    let found = crate::numeric::root::first_sign_change(&z, &hi, 256, |x| {
        let st = d.state(x);
        d.forces(&st).n12
    });
    Ok(match found {
        Some((lo, _)) => lo,
        None => Float::with_val(p, rug::float::Constant::Pi) / 2u32,
    })
}

impl Case {
    /// Builds the case: sample angles at 1/5 … 4/5 of the way to separation
    /// (rounded to multiples of 2⁻¹⁶), the state and forces at each. With
    /// `with_time`, the time of each sample comes from the oracle (needed for
    /// positions when the drift ω0 ≠ 0).
    pub fn new(
        point: &Point,
        floor: Floor,
        contact: Contact,
        start: StartKind,
        with_time: bool,
    ) -> Result<Self> {
        let model = model_of(point, floor, contact, start)?;
        let red = Reduced::new(&model)?;
        let dynm = Dyn::new(&model, &red, PREC)?;
        let bodies = Bodies {
            m1: dynm.m1.clone(),
            m2: dynm.m2.clone(),
            r1: dynm.r1.clone(),
            r2: dynm.r2.clone(),
            i1: dynm.i1.clone(),
            i2: dynm.i2.clone(),
            g: dynm.g.clone(),
        };
        let ds = coarse_delta_s(&model, &red)?;
        let mut deltas = Vec::new();
        for j in 1..=4u32 {
            let x = Float::with_val(64, &ds * j) / 5u32 * 65536u32;
            let n = x.to_integer().ok_or_else(|| {
                Error::not_physical(format!("no separation angle for {}", model.describe()))
            })?;
            deltas.push(Rational::from((n, 65536)));
        }
        let name = format!("{} {floor}/{contact} {}", point.name, start.label());
        let mut case = Case {
            name,
            scales: Scales::of(model.params()),
            model,
            red,
            dynm,
            bodies,
            deltas,
            syms: Vec::new(),
            sym0: None,
        };
        let mut oracle = if with_time {
            Some(Oracle::new(&case.model, ORACLE_DIGITS)?)
        } else {
            None
        };
        let mut syms = Vec::new();
        for d in &case.deltas {
            let t = match oracle.as_mut() {
                Some(o) => {
                    let th0 = case
                        .model
                        .start()
                        .theta0
                        .as_rational()
                        .cloned()
                        .unwrap_or_default();
                    let th = Exact::rational(Rational::from(&th0 + d));
                    Float::with_val(PREC, &o.time_at(&th)?.value)
                }
                None => Float::new(PREC),
            };
            let st = case.dynm.state(&Float::with_val(PREC, d));
            syms.push(case.sym(&st, &t)?);
        }
        case.syms = syms;
        let st0 = case.dynm.state(&Float::new(PREC));
        case.sym0 = Some(case.sym(&st0, &Float::new(PREC))?);
        Ok(case)
    }

    /// Whether positions need the time (a drift ω0 ≠ 0).
    pub fn drifts(&self) -> bool {
        self.red.gamma.iter().any(|g| *g != 0)
    }

    /// The paper's symbols at state `st` reached at time `t`.
    pub fn sym(&self, st: &State, t: &Float) -> Result<Sym> {
        let d = &self.dynm;
        let p = self.model.params();
        let k = kkt::solve(
            &self.bodies,
            self.model.floor(),
            self.model.contact(),
            &st.theta,
            &st.thetadot,
        )?;
        let pos = d.positions(st, t);
        let x = |f: &Float| X(Float::with_val(PREC, f));
        let r = fx(&p.r());
        let (s, c) = (x(&st.s), x(&st.c));
        let thd = x(&st.thetadot);
        let thdd = x(&st.thetaddot);
        let zero = X::int(PREC, 0);
        let y2dd = -(&r * (&s * &thdd + &c * thd.sq()));
        Ok(Sym {
            m1: fx(&p.m1),
            m2: fx(&p.m2),
            r1: fx(&p.r1),
            r2: fx(&p.r2),
            k1: fx(&p.k1),
            k2: fx(&p.k2),
            g: fx(&p.g),
            omega0: fx(&self.model.start().omega0),
            t: x(t),
            x1: x(&pos[X1]),
            y1: fx(&p.r1),
            phi1: x(&pos[PHI1]),
            // the paper's gauge: r2 φ2 = r1(φ1 − θ) with no constant for a
            // rolling contact (cylroll's φ2 starts at 0: φ2 − r1 θ0/r2)
            phi2: x(&pos[PSI2]) + x(&st.theta) - paper_phi2_shift(&self.model, &d.th0),
            th: x(&st.theta),
            x1d: x(&st.v[X1]),
            y1d: zero.clone(),
            phi1d: x(&st.v[PHI1]),
            phi2d: x(&st.v[PSI2]) + &thd,
            rd: zero.clone(),
            x1dd: x(&st.a[X1]),
            y1dd: zero.clone(),
            phi1dd: x(&st.a[PHI1]),
            phi2dd: x(&st.a[PSI2]) + &thdd,
            rdd: zero,
            x2d: x(&st.v[X1]) + &r * &c * &thd,
            y2d: -(&r * &s * &thd),
            y2dd,
            f1: x(&k.f1),
            n1: x(&k.n1),
            f21: x(&k.f21),
            f12: -x(&k.f21),
            n12: x(&k.n12),
            lam: [x(&k.f1), x(&k.f21), x(&k.n12), x(&k.n1)],
            r,
            s,
            c,
            thd,
            thdd,
        })
    }
}

// ---------------------------------------------------------------- the bodies

/// ẋ2 from the six coordinates: ẋ1 + ṙ sin θ + r cos θ θ̇.
pub fn x2d(y: &Sym) -> X {
    &y.x1d + &y.rd * &y.s + &y.r * &y.c * &y.thd
}

/// ẏ2 from the six coordinates: ẏ1 + ṙ cos θ − r sin θ θ̇.
pub fn y2d(y: &Sym) -> X {
    &y.y1d + &y.rd * &y.c - &y.r * &y.s * &y.thd
}

/// Kinetic energy of cylinder 1: ½ m1 (ẋ1² + ẏ1²) + ½ I1 φ̇1².
pub fn t1(y: &Sym) -> X {
    &y.m1 * (y.x1d.sq() + y.y1d.sq()) / 2 + y.i1() * y.phi1d.sq() / 2
}

/// Kinetic energy of cylinder 2: ½ m2 (ẋ2² + ẏ2²) + ½ I2 (φ̇2 − θ̇)².
pub fn t2(y: &Sym) -> X {
    &y.m2 * (x2d(y).sq() + y2d(y).sq()) / 2 + y.i2() * (&y.phi2d - &y.thd).sq() / 2
}

/// Total kinetic energy.
pub fn t(y: &Sym) -> X {
    t1(y) + t2(y)
}

/// Potential energy m1 g y1 + m2 g y2, zero with cylinder 2 on top of
/// cylinder 1 standing on the floor: (m1 + m2) g (y1 − r1) + m2 g (r cos θ − r1 − r2).
pub fn v(y: &Sym) -> X {
    (&y.m1 + &y.m2) * &y.g * (&y.y1 - &y.r1) + &y.m2 * &y.g * (&y.r * &y.c - &y.r1 - &y.r2)
}

/// Total horizontal momentum m1 ẋ1 + m2 ẋ2.
pub fn px(y: &Sym) -> X {
    &y.m1 * &y.x1d + &y.m2 * x2d(y)
}

/// Spin angular momentum of cylinder 1, I1 φ̇1 (clockwise).
pub fn l1(y: &Sym) -> X {
    y.i1() * &y.phi1d
}

/// Spin angular momentum of cylinder 2, I2 (φ̇2 − θ̇) (counter-clockwise).
pub fn l2(y: &Sym) -> X {
    y.i2() * (&y.phi2d - &y.thd)
}

/// d/dt ∂L/∂q̇i − ∂L/∂qi in the paper's six coordinates (x1, y1, φ1, φ2, θ, r)
/// for L = T − V of the two bodies (derived by hand and checked symbolically).
pub fn e6(y: &Sym) -> [X; 6] {
    let (s, c, r) = (&y.s, &y.c, &y.r);
    let (thd, thdd) = (&y.thd, &y.thdd);
    let m = &y.m1 + &y.m2;
    let m2 = &y.m2;
    let spin2 = y.i2() * (&y.phi2dd - thdd);
    [
        &m * &y.x1dd + m2 * (&y.rdd * s + 2 * &y.rd * c * thd + r * c * thdd - r * s * thd.sq()),
        &m * &y.y1dd
            + m2 * (&y.rdd * c - 2 * &y.rd * s * thd - r * s * thdd - r * c * thd.sq())
            + &m * &y.g,
        y.i1() * &y.phi1dd,
        spin2.clone(),
        -spin2
            + m2 * r.sq() * thdd
            + 2 * m2 * r * &y.rd * thd
            + m2 * r * (&y.x1dd * c - &y.y1dd * s)
            - m2 * &y.g * r * s,
        m2 * (&y.rdd + &y.x1dd * s + &y.y1dd * c - r * thd.sq() + &y.g * c),
    ]
}

// ------------------------------------------------- coordinates and embeddings

/// The rate of coordinate `i` (order of [`crate::paper::appendix::COORDS`]).
pub fn rate(y: &Sym, i: usize) -> &X {
    match i {
        QX1 => &y.x1d,
        QY1 => &y.y1d,
        QP1 => &y.phi1d,
        QP2 => &y.phi2d,
        QTH => &y.thd,
        _ => &y.rd,
    }
}

/// Sets the rate of coordinate `i`.
pub fn set_rate(y: &mut Sym, i: usize, v: X) {
    match i {
        QX1 => y.x1d = v,
        QY1 => y.y1d = v,
        QP1 => y.phi1d = v,
        QP2 => y.phi2d = v,
        QTH => y.thd = v,
        _ => y.rd = v,
    }
}

/// The value of coordinate `i`.
pub fn coord(y: &Sym, i: usize) -> &X {
    match i {
        QX1 => &y.x1,
        QY1 => &y.y1,
        QP1 => &y.phi1,
        QP2 => &y.phi2,
        QTH => &y.th,
        _ => &y.r,
    }
}

/// Sets coordinate `i` (and sin θ, cos θ with θ).
pub fn set_coord(y: &mut Sym, i: usize, v: X) {
    match i {
        QX1 => y.x1 = v,
        QY1 => y.y1 = v,
        QP1 => y.phi1 = v,
        QP2 => y.phi2 = v,
        QTH => {
            y.s = v.sin();
            y.c = v.cos();
            y.th = v;
        }
        _ => y.r = v,
    }
}

/// A set of independent coordinates and how the others follow from them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sys {
    /// Sec. 2: φ1, θ (x1 = r1 φ1, r2 φ2 = r1(φ1 − θ)).
    Main,
    /// Sec. 3.1: x1, θ (no rotation: φ̇1 = 0, φ̇2 = θ̇).
    NoFriction,
    /// Sec. 3.3: φ1, θ (x1 = r1 φ1, cylinder 2 does not spin: φ̇2 = θ̇).
    SlipContact,
    /// A.1 (and sec. 3.2): x1, φ1, θ (r2 φ2 = r1(φ1 − θ)).
    A1,
    /// A.2: φ1, φ2, θ (x1 = r1 φ1).
    A2,
    /// A.3: φ1, φ2, θ, r (x1 = r1 φ1).
    A3,
    /// A.4: y1, φ1, θ (x1 = r1 φ1, r2 φ2 = r1(φ1 − θ)).
    A4,
    /// A.5: all six.
    A5,
}

impl Sys {
    /// Indices of the independent coordinates.
    pub fn free(self) -> &'static [usize] {
        match self {
            Sys::Main | Sys::SlipContact => &[QP1, QTH],
            Sys::NoFriction => &[QX1, QTH],
            Sys::A1 => &[QX1, QP1, QTH],
            Sys::A2 => &[QP1, QP2, QTH],
            Sys::A3 => &[QP1, QP2, QTH, QR],
            Sys::A4 => &[QY1, QP1, QTH],
            Sys::A5 => &[QX1, QY1, QP1, QP2, QTH, QR],
        }
    }

    /// Sets the dependent rates from the independent ones (a linear map).
    pub fn embed(self, y: &mut Sym) {
        let z = y.r1.zero();
        let roll_floor = matches!(
            self,
            Sys::Main | Sys::SlipContact | Sys::A2 | Sys::A3 | Sys::A4
        );
        if roll_floor {
            y.x1d = &y.r1 * &y.phi1d;
        }
        if !matches!(self, Sys::A4 | Sys::A5) {
            y.y1d = z.clone();
        }
        if !matches!(self, Sys::A3 | Sys::A5) {
            y.rd = z.clone();
        }
        match self {
            Sys::Main | Sys::A1 | Sys::A4 => {
                y.phi2d = &y.r1 * (&y.phi1d - &y.thd) / &y.r2;
            }
            Sys::NoFriction => {
                y.phi1d = z;
                y.phi2d = y.thd.clone();
            }
            Sys::SlipContact => y.phi2d = y.thd.clone(),
            _ => {}
        }
    }

    /// ∂qi/∂uk of the embedding: column k for the k-th free coordinate.
    pub fn jacobian(self, template: &Sym) -> Vec<[X; 6]> {
        self.free()
            .iter()
            .map(|&u| {
                let mut y = template.clone();
                let (zero, one) = (y.r1.zero(), y.r1.n(1));
                for i in 0..6 {
                    set_rate(&mut y, i, zero.clone());
                }
                set_rate(&mut y, u, one);
                self.embed(&mut y);
                [0, 1, 2, 3, 4, 5].map(|i| rate(&y, i).clone())
            })
            .collect()
    }
}

/// ∂T/∂u̇ for the free coordinate `u` of `sys` at `y` (exact central difference:
/// T is quadratic in the rates).
pub fn momentum(sys: Sys, y: &Sym, u: usize) -> X {
    let mut plus = y.clone();
    let mut minus = y.clone();
    set_rate(&mut plus, u, rate(y, u) + 1i32);
    set_rate(&mut minus, u, rate(y, u) - 1i32);
    sys.embed(&mut plus);
    sys.embed(&mut minus);
    (t(&plus) - t(&minus)) / 2
}

/// The Lagrange left side d/dt ∂L/∂u̇ − ∂L/∂u for the free coordinate `u` of
/// `sys`, on the motion: Σi e6_i ∂qi/∂u.
pub fn lagrange_lhs(sys: Sys, y: &Sym, u: usize) -> X {
    let e = e6(y);
    let k = sys
        .free()
        .iter()
        .position(|&f| f == u)
        .unwrap_or(usize::MAX);
    let cols = sys.jacobian(y);
    match cols.get(k) {
        Some(col) => {
            let mut s = y.r1.zero();
            for i in 0..6 {
                s = s + &e[i] * &col[i];
            }
            s
        }
        None => y.r1.zero(),
    }
}

/// ∂fj/∂qi of the printed constraints (58)–(61), by unit differences (exact:
/// they are linear).
pub fn constraint_jacobian(y: &Sym) -> crate::paper::appendix::Jac {
    use crate::paper::appendix::constraints;
    let base = constraints(y);
    let cols: Vec<[X; 4]> = (0..6)
        .map(|i| {
            let mut yp = y.clone();
            set_coord(&mut yp, i, coord(y, i) + 1i32);
            let f = constraints(&yp);
            std::array::from_fn(|j| &f[j] - &base[j])
        })
        .collect();
    std::array::from_fn(|j| std::array::from_fn(|i| cols[i][j].clone()))
}

/// A random state of the six coordinates (for the kinetic energies and
/// momenta off the motion), embedded into `sys`.
pub fn random_state(template: &Sym, sys: Sys, seed: u64) -> Sym {
    let mut s = seed;
    let mut next = || {
        s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = s;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        let z = z ^ (z >> 31);
        // a rational in [−1, 1] with denominator 1024
        X::q(PREC, &Rational::from(((z % 2049) as i64 - 1024, 1024)))
    };
    let mut y = template.clone();
    for i in 0..6 {
        let q = next();
        let val = match i {
            QY1 => &y.r1 + &q / 8,
            QR => &y.r1 + &y.r2 + &q / 8,
            _ => q,
        };
        set_coord(&mut y, i, val);
        let rt = next();
        set_rate(&mut y, i, rt);
    }
    if !sys.free().contains(&QY1) {
        y.y1 = y.r1.clone();
    }
    if !sys.free().contains(&QR) {
        y.r = &y.r1 + &y.r2;
    }
    sys.embed(&mut y);
    y
}

/// cylroll's φ2 (0 at t = 0) minus the paper's (eq. 2, r2 φ2 = r1(φ1 − θ)
/// for a rolling contact): r1 θ0/r2 for a rolling contact, 0 otherwise.
fn paper_phi2_shift(model: &Ideal, th0: &Float) -> X {
    let p = model.params();
    match model.contact() {
        crate::model::Contact::Roll => {
            X(Float::with_val(PREC, &p.r1 * th0) / Float::with_val(PREC, &p.r2))
        }
        crate::model::Contact::Slip => X::int(PREC, 0),
    }
}
