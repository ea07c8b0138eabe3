//! The constrained equations of motion of a stack of n ≥ 2 cylinders in
//! relaxed coordinates, and the KKT solve for accelerations and multipliers.
//!
//! This generalises the paper's appendix A.5 (eq. 57 with the constraints
//! f1…f4 of eqs. 58–61) from two cylinders to n (footnote 3), and is written
//! from the kinematics of the bodies rather than from a printed Lagrangian:
//!
//! * Coordinates (3n of them): x1, y1, φ1 (cylinder 1's centre and its
//!   **clockwise** rotation), then for each line of centres j = 1…n−1 (between
//!   cylinders j and j+1): ψ_{j+1} (cylinder j+1's **counter-clockwise**
//!   rotation), θ_j (the line of centres, clockwise from vertical, absolute)
//!   and r_j (the distance between the two axes). For n = 2 this is exactly
//!   q = (x1, y1, φ1, ψ2, θ, r), with ψ2 = φ2 − θ in the paper's notation.
//! * Centre of cylinder i: (x1, y1) + Σ_{j<i} r_j (sin θ_j, cos θ_j).
//! * T = ½ Σ m_i |v_i|² + ½ Σ I_i ω_i², V = g Σ m_i y_i, so that the Lagrange
//!   equations read M(q) q̈ = h(q, q̇) + Jᵀλ with M = Σ m_i A_iᵀA_i + diag(I)
//!   (A_i the Jacobian of centre i) and h = −Σ m_i A_iᵀ(Ȧ_i q̇) − ∂V/∂q.
//! * Constraints (velocity form J q̇ = 0, all holonomic on the manifold):
//!   floor normal ẏ1 = 0 (multiplier N1, the floor's upward force on cylinder
//!   1); rolling floor ẋ1 − r1 φ̇1 = 0 (multiplier F1, the floor's x force);
//!   fixed floor ẋ1 = 0 (F1) and φ̇1 = 0 (holding torque, clockwise); for
//!   every line j the touching constraint ṙ_j = 0 (multiplier N_j, the normal
//!   force between cylinders j and j+1, positive while they press) and, for a
//!   rolling contact, the no-slip condition of the contact points
//!   r_j θ̇_j + ρ_{j+1} ω_{j+1} + ρ_j ω_j = 0 with ω the counter-clockwise
//!   rates (ω_1 = −φ̇1) and ρ the radii (multiplier F_{j+1,j}: the tangential
//!   force of cylinder j on cylinder j+1 along (cos θ_j, −sin θ_j)). For
//!   n = 2 the multipliers are F1, F21, N12, N1 of the paper (eqs. 110–114).
//!
//! Index reduction: the acceleration form J q̈ = −J̇ q̇ (J̇ q̇ = ṙ_j θ̇_j for
//! a rolling contact, else 0), so at every state
//!
//! ```text
//! [ M  −Jᵀ ] [ q̈ ]   [   h   ]
//! [ J   0  ] [ λ ] = [ −J̇ q̇ ]
//! ```
//!
//! is solved by Gaussian elimination with partial pivoting on `rug::Float`.
//! A cyclic direction of motion without inertia (a frictionless spin with
//! k = 0, or a frictionless floor under k1 = 0 with spins rolling on it at
//! k = 0) gets an extra row fixing the acceleration of its independent
//! coordinate to 0 (its multiplier is 0): the system stays regular and that
//! rate keeps its reference value, the convention of the first route.

use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::model::{Contact, Floor, Ideal};
use rug::ops::NegAssign;
use rug::{Assign, Float, Rational};

/// Index of x1.
pub const X1: usize = 0;
/// Index of y1.
pub const Y1: usize = 1;
/// Index of φ1 (clockwise).
pub const PHI1: usize = 2;

/// Index of ψ_{j+2} (counter-clockwise rotation of the upper cylinder of
/// line j, 0-based line index).
pub fn psi(j: usize) -> usize {
    3 + 3 * j
}
/// Index of θ_j (0-based line index).
pub fn th(j: usize) -> usize {
    4 + 3 * j
}
/// Index of r_j (0-based line index).
pub fn rr(j: usize) -> usize {
    5 + 3 * j
}

/// The cylinder (0-based) whose spin coordinate is q[i], if any.
pub fn spin_cylinder(i: usize) -> Option<usize> {
    if i == PHI1 {
        Some(0)
    } else if i >= 3 && (i - 3) % 3 == 0 {
        Some((i - 3) / 3 + 1)
    } else {
        None
    }
}

/// An exact description of a stack of n ≥ 2 cylinders (cylinder 1 on the
/// floor, cylinder i+1 on cylinder i).
#[derive(Debug, Clone, PartialEq)]
pub struct StackModel {
    /// How cylinder 1 meets the floor.
    pub floor: Floor,
    /// Contact model of each line of centres, bottom up (n − 1 entries).
    pub contacts: Vec<Contact>,
    /// Masses, bottom up (n entries).
    pub m: Vec<Rational>,
    /// Radii, bottom up.
    pub r: Vec<Rational>,
    /// Inertia factors: I_i = k_i m_i r_i².
    pub k: Vec<Rational>,
    /// Gravitational acceleration.
    pub g: Rational,
    /// Initial angle of each line of centres, clockwise from vertical (n − 1).
    pub theta0: Vec<Exact>,
    /// Initial angular velocity of each line of centres (n − 1).
    pub thetadot0: Vec<Rational>,
    /// The common rolling rate that fixes the conserved momenta: the state
    /// with every θ̇_j = 0 and the same momenta has φ̇1 = ω0, ẋ1 = r1 ω0 and
    /// every spin rolling on the one below (README, "Conventions", extended).
    pub omega0: Rational,
}

impl StackModel {
    /// Number of cylinders.
    pub fn n(&self) -> usize {
        self.m.len()
    }

    /// The two-cylinder stack of a [`Ideal`].
    pub fn from_model(model: &Ideal) -> Self {
        let p = model.params();
        let st = model.start();
        StackModel {
            floor: model.floor(),
            contacts: vec![model.contact()],
            m: vec![p.m1.clone(), p.m2.clone()],
            r: vec![p.r1.clone(), p.r2.clone()],
            k: vec![p.k1.clone(), p.k2.clone()],
            g: p.g.clone(),
            theta0: vec![st.theta0.clone()],
            thetadot0: vec![st.thetadot0.clone()],
            omega0: st.omega0.clone(),
        }
    }

    /// Checks sizes and ranges.
    ///
    /// Errors: [`Error::InvalidParameter`] naming the offending key.
    pub fn validate(&self) -> Result<()> {
        let n = self.n();
        if n < 2 {
            return Err(Error::invalid("n", n, "must be >= 2"));
        }
        let lens = [
            ("r", self.r.len(), n),
            ("k", self.k.len(), n),
            ("contacts", self.contacts.len(), n - 1),
            ("theta0", self.theta0.len(), n - 1),
            ("thetadot0", self.thetadot0.len(), n - 1),
        ];
        for (name, got, want) in lens {
            if got != want {
                return Err(Error::invalid(
                    name,
                    format!("{got} values"),
                    format!("must have {want} values for n = {n}"),
                ));
            }
        }
        for (i, v) in self.m.iter().enumerate() {
            if *v <= 0 {
                return Err(Error::invalid(
                    "m",
                    crate::exact::rational_text(v),
                    format!("cylinder {}: must be > 0", i + 1),
                ));
            }
        }
        for (i, v) in self.r.iter().enumerate() {
            if *v <= 0 {
                return Err(Error::invalid(
                    "r",
                    crate::exact::rational_text(v),
                    format!("cylinder {}: must be > 0", i + 1),
                ));
            }
        }
        for (i, v) in self.k.iter().enumerate() {
            if *v < 0 {
                return Err(Error::invalid(
                    "k",
                    crate::exact::rational_text(v),
                    format!("cylinder {}: must be >= 0", i + 1),
                ));
            }
        }
        if self.g <= 0 {
            return Err(Error::invalid(
                "g",
                crate::exact::rational_text(&self.g),
                "must be > 0",
            ));
        }
        let half_pi = Float::with_val(256, rug::float::Constant::Pi) / 2u32;
        for (j, t) in self.theta0.iter().enumerate() {
            if t.to_float(256).abs() >= half_pi {
                return Err(Error::invalid(
                    "theta0",
                    t,
                    format!("line {}: must satisfy -pi/2 < theta0 < pi/2", j + 1),
                ));
            }
        }
        if self.floor == Floor::Fixed && self.omega0 != 0 {
            return Err(Error::invalid(
                "omega0",
                crate::exact::rational_text(&self.omega0),
                "must be 0 when the floor is fixed",
            ));
        }
        Ok(())
    }

    /// Whether every line starts at rest exactly on the vertical (then no
    /// time is finite).
    pub fn starts_at_equilibrium(&self) -> bool {
        self.theta0.iter().all(|t| t.is_zero()) && self.thetadot0.iter().all(|t| *t == 0)
    }
}

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

/// The solution of the KKT system at one state.
#[derive(Debug, Clone)]
pub struct Accel {
    /// q̈.
    pub qdd: Vec<Float>,
    /// One multiplier per row of [`System::rows`].
    pub lambda: Vec<Float>,
}

/// The stack's constants at one working precision, with a reusable
/// workspace for the KKT solve.
#[derive(Debug, Clone)]
pub struct System {
    /// Working precision (bits).
    pub prec: u32,
    /// Number of cylinders.
    pub n: usize,
    /// Floor model.
    pub floor: Floor,
    /// Contact models, bottom up.
    pub contacts: Vec<Contact>,
    /// Masses.
    pub m: Vec<Float>,
    /// Radii.
    pub rho: Vec<Float>,
    /// Moments of inertia I_i = k_i m_i r_i².
    pub inertia: Vec<Float>,
    /// g.
    pub g: Float,
    /// Mass above line j: Σ_{i>j} m_i.
    above: Vec<Float>,
    /// Total mass.
    mtot: Float,
    /// The constraint rows.
    pub rows: Vec<Row>,
    /// Massless free directions (unit coefficient vectors over q).
    massless: Vec<Vec<Float>>,
    /// Cyclic directions with inertia: their momenta are conserved.
    pub cyclic: Vec<(String, Vec<Float>)>,
    /// Sliding friction at slipping contacts (empty for the ideal models).
    pub slips: Vec<SlipTerm>,
    ws: Workspace,
}

#[derive(Debug, Clone)]
struct Workspace {
    m: Vec<Float>,
    h: Vec<Float>,
    a: Vec<Float>,
    b: Vec<Float>,
    x: Vec<Float>,
    s: Vec<Float>,
    c: Vec<Float>,
    t: Float,
    t2: Float,
}

impl System {
    /// The constants of `model` at `prec` bits.
    ///
    /// Errors: an invalid model ([`StackModel::validate`]).
    pub fn new(model: &StackModel, prec: u32) -> Result<Self> {
        model.validate()?;
        let n = model.n();
        let f = |q: &Rational| Float::with_val(prec, q);
        let m: Vec<Float> = model.m.iter().map(f).collect();
        let rho: Vec<Float> = model.r.iter().map(f).collect();
        let inertia: Vec<Float> = (0..n)
            .map(|i| {
                let q = Rational::from(&model.k[i] * &model.m[i]) * &model.r[i] * &model.r[i];
                f(&q)
            })
            .collect();
        let mut above = Vec::with_capacity(n - 1);
        for j in 0..n - 1 {
            let s = model.m[j + 1..].iter().fold(Rational::new(), |a, b| a + b);
            above.push(f(&s));
        }
        let mtot = f(&model.m.iter().fold(Rational::new(), |a, b| a + b));
        let mut rows = vec![Row::FloorNormal];
        match model.floor {
            Floor::Roll => rows.push(Row::FloorFriction),
            Floor::Slip => {}
            Floor::Fixed => {
                rows.push(Row::FloorFriction);
                rows.push(Row::Hold);
            }
        }
        for (j, c) in model.contacts.iter().enumerate() {
            rows.push(Row::Normal(j));
            if *c == Contact::Roll {
                rows.push(Row::Friction(j));
            }
        }
        let nq = 3 * n;
        let mut sys = System {
            prec,
            n,
            floor: model.floor,
            contacts: model.contacts.clone(),
            m,
            rho,
            inertia,
            g: f(&model.g),
            above,
            mtot,
            rows,
            massless: Vec::new(),
            cyclic: Vec::new(),
            slips: Vec::new(),
            ws: Workspace {
                m: vec![Float::new(prec); nq * nq],
                h: vec![Float::new(prec); nq],
                a: Vec::new(),
                b: Vec::new(),
                x: Vec::new(),
                s: vec![Float::new(prec); n - 1],
                c: vec![Float::new(prec); n - 1],
                t: Float::new(prec),
                t2: Float::new(prec),
            },
        };
        // cyclic directions; those without inertia become extra rows
        for (name, dir) in sys.cyclic_directions() {
            let massless = (0..nq)
                .all(|i| dir[i].is_zero() || spin_cylinder(i).is_some_and(|cyl| model.k[cyl] == 0));
            if massless {
                let idx = sys.massless.len();
                sys.massless.push(dir);
                sys.rows.push(Row::Massless(idx));
            } else {
                sys.cyclic.push((name, dir));
            }
        }
        let nk = nq + sys.rows.len();
        sys.ws.a = vec![Float::new(prec); nk * nk];
        sys.ws.b = vec![Float::new(prec); nk];
        sys.ws.x = vec![Float::new(prec); nk];
        Ok(sys)
    }

    /// Number of coordinates, 3n.
    pub fn nq(&self) -> usize {
        3 * self.n
    }

    /// Whether some contact slips with friction (the dissipated work is
    /// then integrated as an extra state).
    pub fn has_slips(&self) -> bool {
        !self.slips.is_empty()
    }

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

    fn tangent_of(rho: &[Float], at: Tangent, q: &[Float]) -> Vec<(usize, Float)> {
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
    fn spin(i: usize) -> (usize, i32) {
        if i == 0 {
            (PHI1, -1)
        } else {
            (psi(i - 1), 1)
        }
    }

    /// The velocity on the constraint manifold from the independent rates:
    /// ẋ1 (used only on a frictionless floor), φ̇1 (unused on a fixed floor),
    /// the θ̇_j, and the spins of cylinders above slipping contacts (`None`:
    /// the rate that rolls on the cylinder below). ẏ1 = ṙ_j = 0.
    pub fn chain_velocity(
        &self,
        x1d: &Float,
        phi1d: &Float,
        thd: &[Float],
        free_spin: &[Option<Float>],
    ) -> Vec<Float> {
        let p = self.prec;
        let mut v = vec![Float::new(p); self.nq()];
        match self.floor {
            Floor::Roll => {
                v[PHI1].assign(phi1d);
                v[X1].assign(&self.rho[0] * phi1d);
            }
            Floor::Slip => {
                v[PHI1].assign(phi1d);
                v[X1].assign(x1d);
            }
            Floor::Fixed => {}
        }
        // ω of the cylinder below, counter-clockwise
        let mut omega = Float::with_val(p, -&v[PHI1]);
        for j in 0..self.n - 1 {
            v[th(j)].assign(&thd[j]);
            let rj = Float::with_val(p, &self.rho[j] + &self.rho[j + 1]);
            let rolling = {
                // ρ_{j+1} ω_{j+1} = −(r_j θ̇_j + ρ_j ω_j)
                let s =
                    Float::with_val(p, &rj * &thd[j]) + Float::with_val(p, &self.rho[j] * &omega);
                -s / &self.rho[j + 1]
            };
            let w = match (self.contacts[j], &free_spin[j]) {
                (Contact::Slip, Some(w)) => Float::with_val(p, w),
                _ => rolling,
            };
            v[psi(j)].assign(&w);
            omega = w;
        }
        v
    }

    /// The cyclic directions (θ̇ = 0): translations of x1 (frictionless
    /// floor), rotations of φ1 (with the spins that roll on it), free spins
    /// above slipping contacts.
    fn cyclic_directions(&self) -> Vec<(String, Vec<Float>)> {
        let p = self.prec;
        let z = Float::new(p);
        let one = Float::with_val(p, 1u32);
        let nl = self.n - 1;
        let zeros = vec![Float::new(p); nl];
        let none: Vec<Option<Float>> = self
            .contacts
            .iter()
            .map(|c| match c {
                Contact::Slip => Some(Float::new(p)),
                Contact::Roll => None,
            })
            .collect();
        let mut out = Vec::new();
        match self.floor {
            Floor::Roll => out.push((
                "phi1".to_string(),
                self.chain_velocity(&z, &one, &zeros, &none),
            )),
            Floor::Slip => {
                out.push((
                    "x1".to_string(),
                    self.chain_velocity(&one, &z, &zeros, &none),
                ));
                out.push((
                    "phi1".to_string(),
                    self.chain_velocity(&z, &one, &zeros, &none),
                ));
            }
            Floor::Fixed => {}
        }
        for j in 0..nl {
            if self.contacts[j] == Contact::Slip {
                let mut free = none.clone();
                free[j] = Some(one.clone());
                out.push((
                    format!("psi{}", j + 2),
                    self.chain_velocity(&z, &z, &zeros, &free),
                ));
            }
        }
        out
    }

    /// The initial state (q0, q̇0) of `model`: x1 = φ1 = 0, y1 = r1,
    /// r_j = ρ_j + ρ_{j+1}, θ_j = θ0_j, and every φ_{j+1} = ψ_{j+1} + θ_j
    /// = 0 (whatever the contact: a rolling contact's constraint carries the
    /// constant; for n = 2, r2 φ2 = r1(φ1 − θ + θ0)). Velocities: θ̇_j = θ̇0_j, the momenta of the cyclic directions
    /// equal to those of the state with every θ̇ = 0 rolling at ω0.
    pub fn initial_state(&mut self, model: &StackModel) -> Result<(Vec<Float>, Vec<Float>)> {
        let p = self.prec;
        let n = self.n;
        let nq = self.nq();
        let mut q = vec![Float::new(p); nq];
        q[Y1].assign(&self.rho[0]);
        for j in 0..n - 1 {
            let t0 = model.theta0[j].to_float(p);
            let rj = Float::with_val(p, &self.rho[j] + &self.rho[j + 1]);
            // φ_{j+1} = ψ_{j+1} + θ_j starts at 0 for every contact (a
            // rolling contact's constraint carries the constant)
            let a = Float::with_val(p, -&t0);
            q[psi(j)].assign(&a);
            q[th(j)].assign(&t0);
            q[rr(j)].assign(&rj);
        }
        // reference velocity: every θ̇ = 0, everything rolling at ω0
        let w0 = Float::with_val(p, &model.omega0);
        let x1d = match self.floor {
            Floor::Fixed => Float::new(p),
            _ => Float::with_val(p, &self.rho[0] * &w0),
        };
        let zeros = vec![Float::new(p); n - 1];
        let rolling: Vec<Option<Float>> = vec![None; n - 1];
        let uref = self.chain_velocity(&x1d, &w0, &zeros, &rolling);
        // the part driven by θ̇0, with every other independent rate 0
        let thd: Vec<Float> = model
            .thetadot0
            .iter()
            .map(|t| Float::with_val(p, t))
            .collect();
        let free0: Vec<Option<Float>> = self
            .contacts
            .iter()
            .map(|c| match c {
                Contact::Slip => Some(Float::new(p)),
                Contact::Roll => None,
            })
            .collect();
        let z = Float::new(p);
        let vb = self.chain_velocity(&z, &z, &thd, &free0);
        // massless directions keep their reference rate: uref's coefficient
        // on them is the rate of their own coordinate
        let mut v = vb.clone();
        for dir in &self.massless {
            let (i, _) = dir
                .iter()
                .enumerate()
                .find(|(_, d)| !d.is_zero())
                .ok_or_else(|| Error::not_physical("an empty massless direction"))?;
            let coef = Float::with_val(p, &uref[i] / &dir[i]);
            for (vi, di) in v.iter_mut().zip(dir) {
                *vi += &coef * di;
            }
        }
        // conserved momenta: Eᵀ M (vb + E w) = Eᵀ M uref
        let nc = self.cyclic.len();
        if nc > 0 {
            self.mass_matrix(&q);
            let mq = |sys: &System, x: &[Float]| -> Vec<Float> {
                (0..nq)
                    .map(|i| {
                        let mut s = Float::new(p);
                        for (k, xk) in x.iter().enumerate() {
                            s += &sys.ws.m[i * nq + k] * xk;
                        }
                        s
                    })
                    .collect()
            };
            let dot = |a: &[Float], b: &[Float]| {
                let mut s = Float::new(p);
                for (x, y) in a.iter().zip(b) {
                    s += x * y;
                }
                s
            };
            let m_uref = mq(self, &uref);
            let m_v = mq(self, &v);
            let mut a = vec![Float::new(p); nc * nc];
            let mut b = vec![Float::new(p); nc];
            for c in 0..nc {
                let me = mq(self, &self.cyclic[c].1);
                for d in 0..nc {
                    a[d * nc + c] = dot(&self.cyclic[d].1, &me);
                }
                b[c] = dot(&self.cyclic[c].1, &m_uref) - dot(&self.cyclic[c].1, &m_v);
            }
            let mut x = vec![Float::new(p); nc];
            gauss(&mut a, &mut b, &mut x, nc)
                .ok_or_else(|| Error::not_physical("the cyclic mass matrix is singular"))?;
            for (xc, (_, dir)) in x.iter().zip(&self.cyclic) {
                for (vi, di) in v.iter_mut().zip(dir) {
                    *vi += xc * di;
                }
            }
        }
        Ok((q, v))
    }

    fn trig(&mut self, q: &[Float]) {
        for j in 0..self.n - 1 {
            let (s, c) = (&mut self.ws.s[j], &mut self.ws.c[j]);
            s.assign(&q[th(j)]);
            // sin_cos_mut computes both into s (sin) and c (cos)
            s.sin_cos_mut(c);
        }
    }

    /// Fills the workspace mass matrix at q (computes the trigonometry).
    fn mass_matrix(&mut self, q: &[Float]) {
        self.trig(q);
        let nq = self.nq();
        let nl = self.n - 1;
        let ws = &mut self.ws;
        for x in ws.m.iter_mut() {
            x.assign(0u32);
        }
        let mm = &mut ws.m;
        let idx = |i: usize, j: usize| i * nq + j;
        mm[idx(X1, X1)].assign(&self.mtot);
        mm[idx(Y1, Y1)].assign(&self.mtot);
        mm[idx(PHI1, PHI1)].assign(&self.inertia[0]);
        for j in 0..nl {
            mm[idx(psi(j), psi(j))].assign(&self.inertia[j + 1]);
        }
        let t = &mut ws.t;
        let t2 = &mut ws.t2;
        for j in 0..nl {
            let (a, b) = (th(j), rr(j));
            let s = &ws.s[j];
            let c = &ws.c[j];
            let sa = &self.above[j];
            let rj = &q[b];
            // x1–θ_j, x1–r_j, y1–θ_j, y1–r_j
            t.assign(sa * rj);
            mm[idx(X1, a)].assign(&*t * c);
            mm[idx(Y1, a)].assign(&*t * s);
            mm[idx(Y1, a)].neg_assign();
            mm[idx(X1, b)].assign(sa * s);
            mm[idx(Y1, b)].assign(sa * c);
            for k in 0..=j {
                // pairs (j, k), k ≤ j: bodies above line j move with both
                let (ak, bk) = (th(k), rr(k));
                let sk = &ws.s[k];
                let ck = &ws.c[k];
                let rk = &q[bk];
                // cos(θj − θk), sin(θk − θj)
                let mut cjk = Float::with_val(self.prec, c * ck);
                cjk += s * sk;
                let mut skj = Float::with_val(self.prec, sk * c);
                skj -= ck * s;
                t.assign(sa * &cjk);
                // r_j–r_k
                mm[idx(b, bk)].assign(&*t);
                // θ_j–θ_k
                t2.assign(&*t * rj);
                mm[idx(a, ak)].assign(&*t2 * rk);
                if k < j {
                    // θ_j–r_k: S r_j sin(θ_k − θ_j); θ_k–r_j: S r_k sin(θ_j − θ_k)
                    t.assign(sa * &skj);
                    mm[idx(a, bk)].assign(&*t * rj);
                    mm[idx(ak, b)].assign(&*t * rk);
                    mm[idx(ak, b)].neg_assign();
                }
            }
        }
        // symmetrise: each pair was written on one side only
        for i in 0..nq {
            for j in 0..i {
                let (lo, hi) = mm.split_at_mut(i * nq);
                let upper = &mut lo[j * nq + i];
                let lower = &mut hi[j];
                if lower.is_zero() {
                    lower.assign(&*upper);
                } else {
                    upper.assign(&*lower);
                }
            }
        }
    }

    /// Generalised forces h(q, q̇) (gravity and velocity terms), into the
    /// workspace; the trigonometry must be current (call after `mass_matrix`).
    fn forces_h(&mut self, q: &[Float], v: &[Float]) {
        let p = self.prec;
        let nl = self.n - 1;
        let ws = &mut self.ws;
        for x in ws.h.iter_mut() {
            x.assign(0u32);
        }
        let h = &mut ws.h;
        h[Y1].assign(&self.mtot * &self.g);
        h[Y1].neg_assign();
        // per-line centripetal/Coriolis accelerations of the relative vector
        let mut cx = vec![Float::new(p); nl];
        let mut cy = vec![Float::new(p); nl];
        for j in 0..nl {
            let s = &ws.s[j];
            let c = &ws.c[j];
            let rj = &q[rr(j)];
            let td = &v[th(j)];
            let rd = &v[rr(j)];
            let td2 = Float::with_val(p, td.square_ref());
            let rtd2 = Float::with_val(p, rj * &td2);
            let two_rd_td = Float::with_val(p, rd * td) * 2u32;
            // c^x = −r s θ̇² + 2 ṙ c θ̇ ; c^y = −r c θ̇² − 2 ṙ s θ̇
            cx[j].assign(&two_rd_td * c);
            cx[j] -= &rtd2 * s;
            cy[j].assign(&two_rd_td * s);
            cy[j] += &rtd2 * c;
            cy[j].neg_assign();
            // gravity on θ_j, r_j
            let sg = Float::with_val(p, &self.above[j] * &self.g);
            h[th(j)].assign(&sg * rj);
            h[th(j)] *= s;
            h[rr(j)].assign(&sg * c);
            h[rr(j)].neg_assign();
        }
        // body i ≥ 1 accelerates by Σ_{j<i} c_j (velocity part)
        let mut ax = Float::new(p);
        let mut ay = Float::new(p);
        // X_j = Σ_{i>j} m_i acx_i, accumulated from the top down
        let mut acx = vec![Float::new(p); self.n];
        let mut acy = vec![Float::new(p); self.n];
        for i in 1..self.n {
            ax += &cx[i - 1];
            ay += &cy[i - 1];
            acx[i].assign(&ax * &self.m[i]);
            acy[i].assign(&ay * &self.m[i]);
        }
        let mut sx = Float::new(p);
        let mut sy = Float::new(p);
        for j in (0..nl).rev() {
            sx += &acx[j + 1];
            sy += &acy[j + 1];
            let s = &ws.s[j];
            let c = &ws.c[j];
            let rj = &q[rr(j)];
            // h_θj −= r_j (c X − s Y); h_rj −= s X + c Y
            let mut t = Float::with_val(p, c * &sx);
            t -= s * &sy;
            t *= rj;
            h[th(j)] -= &t;
            let mut u = Float::with_val(p, s * &sx);
            u += c * &sy;
            h[rr(j)] -= &u;
        }
        h[X1] -= &sx;
        h[Y1] -= &sy;
    }

    /// The coefficients of constraint row `row` over q̇ at q, and −J̇q̇.
    fn row_coeffs(&self, row: Row, q: &[Float], v: &[Float]) -> (Vec<(usize, Float)>, Float) {
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

    /// Solves the KKT system at (q, q̇): the accelerations and the
    /// multipliers (one per row of [`System::rows`]).
    ///
    /// Errors: a singular system (not expected for a valid model).
    pub fn accel(&mut self, q: &[Float], v: &[Float]) -> Result<Accel> {
        let mut qdd = vec![Float::new(self.prec); self.nq()];
        let mut lambda = vec![Float::new(self.prec); self.rows.len()];
        self.accel_into(q, v, &mut qdd, Some(&mut lambda))?;
        Ok(Accel { qdd, lambda })
    }

    /// The accelerations and multipliers at q for θ̇_j = 0 and θ̇_j = 1 (every
    /// other rate 0), from one elimination with two right-hand sides. With
    /// ṙ = 0 the equations depend on the rates only through the θ̇_j², so
    /// q̈ = a + b θ̇_j² with a the first and a + b the second.
    ///
    /// Errors: a singular system.
    pub fn accel_pair(&mut self, q: &[Float], j: usize) -> Result<(Accel, Accel)> {
        let nq = self.nq();
        let nk = nq + self.rows.len();
        let p = self.prec;
        let mut v = vec![Float::new(p); nq];
        self.assemble(q, &v);
        // the second right-hand side: the rates enter h only (the rows'
        // right-hand sides carry −ṙ θ̇, which is 0 for both)
        v[th(j)].assign(1u32);
        self.forces_h(q, &v);
        let mut b1 = self.ws.b[..nk].to_vec();
        for (x, h) in b1.iter_mut().zip(&self.ws.h[..nq]) {
            x.assign(h);
        }
        let mut b0 = std::mem::take(&mut self.ws.b);
        let mut x0 = vec![Float::new(p); nk];
        let mut x1 = vec![Float::new(p); nk];
        let ok = gauss_many(
            &mut self.ws.a,
            &mut [&mut b0, &mut b1],
            &mut [&mut x0, &mut x1],
            nk,
        );
        self.ws.b = b0;
        ok.ok_or_else(|| Error::not_physical("the constraint (KKT) system is singular"))?;
        let mut out = [x0, x1].into_iter().map(|mut x| {
            let lambda = x.split_off(nq);
            Accel { qdd: x, lambda }
        });
        let a0 = out.next().expect("two solutions");
        let a1 = out.next().expect("two solutions");
        Ok((a0, a1))
    }

    /// [`System::accel`] into caller buffers (the multipliers only if asked).
    pub fn accel_into(
        &mut self,
        q: &[Float],
        v: &[Float],
        qdd: &mut [Float],
        lambda: Option<&mut Vec<Float>>,
    ) -> Result<()> {
        let nq = self.nq();
        let nk = nq + self.rows.len();
        self.assemble(q, v);
        let ws = &mut self.ws;
        gauss(&mut ws.a, &mut ws.b, &mut ws.x, nk)
            .ok_or_else(|| Error::not_physical("the constraint (KKT) system is singular"))?;
        for (o, x) in qdd.iter_mut().zip(&ws.x[..nq]) {
            o.assign(x);
        }
        if let Some(l) = lambda {
            for (o, x) in l.iter_mut().zip(&ws.x[nq..]) {
                o.assign(x);
            }
        }
        Ok(())
    }

    /// The KKT matrix and right-hand side at (q, q̇) into the workspace.
    fn assemble(&mut self, q: &[Float], v: &[Float]) {
        let nq = self.nq();
        self.mass_matrix(q);
        self.forces_h(q, v);
        let nr = self.rows.len();
        let nk = nq + nr;
        let rows: Vec<(Vec<(usize, Float)>, Float)> = self
            .rows
            .iter()
            .map(|&r| self.row_coeffs(r, q, v))
            .collect();
        let ws = &mut self.ws;
        for x in ws.a.iter_mut() {
            x.assign(0u32);
        }
        for i in 0..nq {
            for j in 0..nq {
                let mij = &ws.m[i * nq + j];
                if !mij.is_zero() {
                    ws.a[i * nk + j].assign(mij);
                }
            }
            ws.b[i].assign(&ws.h[i]);
        }
        for (k, (coefs, rhs)) in rows.iter().enumerate() {
            for (i, c) in coefs {
                ws.a[(nq + k) * nk + i].assign(c);
                ws.a[i * nk + nq + k].assign(c);
                ws.a[i * nk + nq + k].neg_assign();
            }
            ws.b[nq + k].assign(rhs);
        }
        // sliding friction −μk σ N along the slip direction: M q̈ − J_nᵀ N
        // + μk σ J_tᵀ N = h, so the normal row's column gains μk σ J_t
        for sl in &self.slips {
            let col = nq + sl.normal;
            for (i, c) in Self::tangent_of(&self.rho, sl.at, q) {
                ws.a[i * nk + col] += Float::with_val(self.prec, &c * &sl.mu_sigma);
            }
        }
    }

    /// Total energy T + V (V = g Σ m_i y_i).
    pub fn energy(&mut self, q: &[Float], v: &[Float]) -> Float {
        let p = self.prec;
        let nq = self.nq();
        self.mass_matrix(q);
        let mut t = Float::new(p);
        for i in 0..nq {
            if v[i].is_zero() {
                continue;
            }
            let mut row = Float::new(p);
            for (mk, vk) in self.ws.m[i * nq..(i + 1) * nq].iter().zip(v) {
                row += mk * vk;
            }
            t += &row * &v[i];
        }
        t /= 2u32;
        // heights: y1, then y_{i} = y_{i-1} + r c
        let mut y = Float::with_val(p, &q[Y1]);
        let mut vpot = Float::with_val(p, &self.m[0] * &y);
        for i in 1..self.n {
            y += &q[rr(i - 1)] * &self.ws.c[i - 1];
            vpot += &self.m[i] * &y;
        }
        vpot *= &self.g;
        t + vpot
    }

    /// The largest drifts of energy and momenta from `e0`, `p0` over the
    /// given states (q, q̇): |E − E0|/escale and max_c |p_c − p_c0|/pscale.
    pub fn drifts<'a>(
        &mut self,
        states: impl Iterator<Item = (&'a [Float], &'a [Float])>,
        e0: &Float,
        p0: &[Float],
        escale: &Float,
        pscale: &Float,
    ) -> (Float, Float) {
        let p = self.prec;
        let mut energy = Float::new(p);
        let mut momentum = Float::new(p);
        for (q, v) in states {
            let de = Float::with_val(p, &self.energy(q, v) - e0).abs() / escale;
            if de > energy {
                energy = de;
            }
            for (a, b) in self.momenta(q, v).iter().zip(p0) {
                let d = Float::with_val(p, a - b).abs() / pscale;
                if d > momentum {
                    momentum = d;
                }
            }
        }
        (energy, momentum)
    }

    /// The conserved momenta p_c = e_cᵀ M q̇ of the cyclic directions with
    /// inertia (for a rolling floor and rolling contacts: the one canonical
    /// momentum of footnote 3, conjugate to φ1).
    pub fn momenta(&mut self, q: &[Float], v: &[Float]) -> Vec<Float> {
        let p = self.prec;
        let nq = self.nq();
        self.mass_matrix(q);
        let mv: Vec<Float> = (0..nq)
            .map(|i| {
                let mut s = Float::new(p);
                for (mk, vk) in self.ws.m[i * nq..(i + 1) * nq].iter().zip(v) {
                    s += mk * vk;
                }
                s
            })
            .collect();
        self.cyclic
            .iter()
            .map(|(_, e)| {
                let mut s = Float::new(p);
                for (a, b) in e.iter().zip(&mv) {
                    s += a * b;
                }
                s
            })
            .collect()
    }

    /// The residuals of the position and velocity constraints at (q, q̇),
    /// relative to their values at (q0, q̇0): the drift of the integration.
    /// Returns the largest absolute residual (lengths and angles in the
    /// model's units; velocities as they are).
    pub fn drift(&self, q: &[Float], v: &[Float], q0: &[Float]) -> Float {
        let p = self.prec;
        let mut worst = Float::new(p);
        let mut upd = |x: Float| {
            let a = x.abs();
            if a > worst {
                worst = a;
            }
        };
        let pos = |q: &[Float], row: Row| -> Float {
            match row {
                Row::FloorNormal => q[Y1].clone(),
                Row::FloorFriction => match self.floor {
                    Floor::Roll => {
                        Float::with_val(p, &q[X1] - Float::with_val(p, &self.rho[0] * &q[PHI1]))
                    }
                    _ => q[X1].clone(),
                },
                Row::Hold => q[PHI1].clone(),
                Row::Normal(j) => q[rr(j)].clone(),
                Row::Friction(j) => {
                    // r_j θ_j + ρ_{j+1} a_{j+1} + ρ_j a_j, a the ccw angles
                    let (i0, s0) = Self::spin(j);
                    let (i1, s1) = Self::spin(j + 1);
                    let rj = Float::with_val(p, &self.rho[j] + &self.rho[j + 1]);
                    let mut s = Float::with_val(p, &rj * &q[th(j)]);
                    s += Float::with_val(p, &self.rho[j] * s0) * &q[i0];
                    s += Float::with_val(p, &self.rho[j + 1] * s1) * &q[i1];
                    s
                }
                Row::Massless(_) => Float::new(p),
            }
        };
        for &row in &self.rows {
            upd(pos(q, row) - pos(q0, row));
            let (coefs, _) = self.row_coeffs(row, q, v);
            if let Row::Massless(_) = row {
                continue;
            }
            let mut s = Float::new(p);
            for (i, c) in coefs {
                s += &c * &v[i];
            }
            upd(s);
        }
        worst
    }

    /// Puts (q, q̇) back on the constraint manifold by recomputing the
    /// dependent coordinates and rates from the independent ones (y1, r_j
    /// exact; x1 from φ1 on a rolling floor; spins of rolling contacts from
    /// the rolling constraints with the constants of q0).
    pub fn project(&self, q: &mut [Float], v: &mut [Float], q0: &[Float]) {
        let p = self.prec;
        q[Y1].assign(&q0[Y1]);
        v[Y1].assign(0u32);
        match self.floor {
            Floor::Roll => {
                let x = Float::with_val(p, &self.rho[0] * &q[PHI1]) + &q0[X1]
                    - Float::with_val(p, &self.rho[0] * &q0[PHI1]);
                q[X1].assign(&x);
                let xd = Float::with_val(p, &self.rho[0] * &v[PHI1]);
                v[X1].assign(&xd);
            }
            Floor::Fixed => {
                q[X1].assign(&q0[X1]);
                q[PHI1].assign(&q0[PHI1]);
                v[X1].assign(0u32);
                v[PHI1].assign(0u32);
            }
            Floor::Slip => {}
        }
        for j in 0..self.n - 1 {
            q[rr(j)].assign(&q0[rr(j)]);
            v[rr(j)].assign(0u32);
            if self.contacts[j] == Contact::Roll {
                let (i0, s0) = Self::spin(j);
                let rj = &q0[rr(j)];
                let f = |q: &[Float]| {
                    Float::with_val(p, rj * &q[th(j)])
                        + Float::with_val(p, &self.rho[j] * s0) * &q[i0]
                };
                let c0 = Float::with_val(
                    p,
                    f(q0) + Float::with_val(p, &self.rho[j + 1] * &q0[psi(j)]),
                );
                let a = (c0 - f(q)) / &self.rho[j + 1];
                q[psi(j)].assign(&a);
                let w = Float::with_val(p, rj * &v[th(j)])
                    + Float::with_val(p, &self.rho[j] * s0) * &v[i0];
                let w = -w / &self.rho[j + 1];
                v[psi(j)].assign(&w);
            }
        }
    }

    /// Heights of the centres (y_i) at q, bottom up.
    pub fn heights(&self, q: &[Float]) -> Vec<Float> {
        let p = self.prec;
        let mut out = Vec::with_capacity(self.n);
        let mut y = Float::with_val(p, &q[Y1]);
        out.push(y.clone());
        for j in 0..self.n - 1 {
            let c = Float::with_val(p, q[th(j)].cos_ref());
            y += Float::with_val(p, &q[rr(j)] * &c);
            out.push(y.clone());
        }
        out
    }
}

/// Gaussian elimination with partial pivoting on a row-major n×n matrix,
/// in place, for several right-hand sides at once (one elimination); the
/// solution of `bs[k]` goes to `xs[k]`. `None` if singular.
pub(crate) fn gauss_many(
    a: &mut [Float],
    bs: &mut [&mut [Float]],
    xs: &mut [&mut [Float]],
    n: usize,
) -> Option<()> {
    let p = bs
        .first()
        .and_then(|b| b.first())
        .map(|f| f.prec())
        .unwrap_or(64);
    let mut f = Float::new(p);
    for col in 0..n {
        let mut piv = col;
        for i in col + 1..n {
            if a[i * n + col].cmp_abs(&a[piv * n + col]) == Some(std::cmp::Ordering::Greater) {
                piv = i;
            }
        }
        if a[piv * n + col].is_zero() {
            return None;
        }
        if piv != col {
            for j in 0..n {
                a.swap(piv * n + j, col * n + j);
            }
            for b in bs.iter_mut() {
                b.swap(piv, col);
            }
        }
        let (top, bottom) = a.split_at_mut((col + 1) * n);
        let prow = &top[col * n..];
        for ii in 0..n - col - 1 {
            let row = &mut bottom[ii * n..(ii + 1) * n];
            if row[col].is_zero() {
                continue;
            }
            f.assign(&row[col] / &prow[col]);
            for j in col + 1..n {
                if !prow[j].is_zero() {
                    row[j] -= &f * &prow[j];
                }
            }
            row[col].assign(0u32);
            for b in bs.iter_mut() {
                let (btop, bbot) = b.split_at_mut(col + 1);
                bbot[ii] -= &f * &btop[col];
            }
        }
    }
    for (b, x) in bs.iter().zip(xs.iter_mut()) {
        for i in (0..n).rev() {
            let mut s = b[i].clone();
            for j in i + 1..n {
                if !a[i * n + j].is_zero() {
                    s -= &a[i * n + j] * &x[j];
                }
            }
            x[i].assign(&s / &a[i * n + i]);
        }
    }
    Some(())
}

/// [`gauss_many`] for one right-hand side.
pub(crate) fn gauss(a: &mut [Float], b: &mut [Float], x: &mut [Float], n: usize) -> Option<()> {
    gauss_many(a, &mut [b], &mut [x], n)
}
