//! What the integration must keep: the energy T + V and the conserved
//! momenta of the cyclic directions (and their largest drifts over a run),
//! the residuals of the position and velocity constraints, the projection
//! back onto the constraint manifold, and the heights of the centres.

use super::{psi, rr, th, Row, System, PHI1, X1, Y1};
use crate::model::{Contact, Floor};
use rug::{Assign, Float};

impl System {
    /// Total energy T + V, V = g Σ m_i (y_i − ρ1): heights above cylinder
    /// 1's centre at rest on the floor.
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
                // the matrix is sparse: a zero entry adds an exact zero
                // (the velocities are finite) to a sum that starts at +0:
                // it cannot change it
                if !mk.is_zero() {
                    row += mk * vk;
                }
            }
            t += &row * &v[i];
        }
        t /= 2u32;
        // heights above cylinder 1's centre at rest on the floor (y1 = ρ1,
        // the potential's zero): y1 − ρ1 (exactly 0 on the floor), then
        // y_i = y_{i−1} + r c. With the floor's height as zero, E would
        // carry the constant Σ m_i g ρ1, and its rounding, m1 g ρ1 2^−p,
        // would swamp a light upper cylinder's energy m2 g r (at m2 = 10^−6
        // m1 the energy balance failed at 30 digits)
        let mut y = Float::with_val(p, &q[Y1] - &self.rho[0]);
        let mut vpot = Float::with_val(p, &self.m[0] * &y);
        for i in 1..self.n {
            y += &q[rr(i - 1)] * &self.ws.c[i - 1];
            vpot += &self.m[i] * &y;
        }
        vpot *= &self.g;
        t + vpot
    }

    /// The scales [`System::drifts`] measures in, from the start's energy
    /// `e0`: energy |E0| + Σ m_i ρ_i g, momentum Σ m_i ρ_i · ρ_0 / ts (ts
    /// the time unit): relative to the motion's own sizes in any units.
    pub fn drift_scales(&self, e0: &Float) -> (Float, Float) {
        let p = self.prec;
        let mut mr = Float::new(p);
        for (m, rho) in self.m.iter().zip(&self.rho) {
            mr += Float::with_val(p, m * rho);
        }
        let escale = Float::with_val(p, e0.abs_ref()) + Float::with_val(p, &mr * &self.g);
        let pscale = Float::with_val(p, &mr / &self.units.ts) * &self.rho[0];
        (escale, pscale)
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
    /// Returns the largest residual in the system's units ([`System::units`]):
    /// a length over r, a velocity over r/ts (an angle, the held φ1, over 1,
    /// its rate over 1/ts), so that one threshold serves every model.
    pub fn drift(&self, q: &[Float], v: &[Float], q0: &[Float]) -> Float {
        let p = self.prec;
        let (r, ts) = (&self.units.r, &self.units.ts);
        let mut worst = Float::new(p);
        let mut upd = |x: Float, unit: &Float| {
            let a = x.abs() / unit;
            if a > worst {
                worst = a;
            }
        };
        let one = Float::with_val(p, 1u32);
        let inv_ts = Float::with_val(p, ts.recip_ref());
        let r_ts = Float::with_val(p, r / ts);
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
            let angle = row == Row::Hold;
            upd(pos(q, row) - pos(q0, row), if angle { &one } else { r });
            let (coefs, _) = self.row_coeffs(row, q, v);
            if let Row::Massless(_) = row {
                continue;
            }
            let mut s = Float::new(p);
            for (i, c) in coefs {
                s += &c * &v[i];
            }
            upd(s, if angle { &inv_ts } else { &r_ts });
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
