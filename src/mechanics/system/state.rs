//! The start on the constraint manifold: the velocity from the independent
//! rates (the chain of rolling and free spins up the stack), the cyclic
//! directions whose momenta are conserved, and the initial state (q0, q̇0)
//! of a model with the momenta of its reference rolling state.

use super::accel::gauss;
use super::{psi, rr, th, StackModel, System, PHI1, X1, Y1};
use crate::error::{Error, Result};
use crate::model::{Contact, Floor};
use rug::{Assign, Float};

impl System {
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
    pub(super) fn cyclic_directions(&self) -> Vec<(String, Vec<Float>)> {
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
}
