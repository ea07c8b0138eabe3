//! One precision's worth of machinery: the dynamics constants and a tanh-sinh
//! rule with its node cache.

use crate::error::Result;
use crate::mechanics::dynamics::Dyn;
use crate::mechanics::{Reduced, PHI1};
use crate::model::Model;
use crate::numeric::quad::TanhSinh;
use crate::numeric::root;
use rug::Float;

pub(super) struct Engine {
    pub dynm: Dyn,
    pub ts: TanhSinh,
}

impl Engine {
    pub fn new(model: &Model, red: &Reduced, prec: u32) -> Result<Self> {
        Ok(Engine {
            dynm: Dyn::new(model, red, prec)?,
            ts: TanhSinh::new(prec),
        })
    }

    fn prec(&self) -> u32 {
        self.dynm.prec
    }

    /// t(δ) = ∫_0^δ dθ/θ̇ and its error estimate. δ = 0 gives 0.
    pub fn time(&mut self, delta: &Float) -> (Float, Float) {
        let p = self.prec();
        if delta.is_zero() {
            return (Float::new(p), Float::new(p));
        }
        let d = Float::with_val(p, delta);
        let dynm = &self.dynm;
        let r = self
            .ts
            .integrate(&d, p.saturating_sub(10), |x, out| dynm.inv_thetadot(x, out));
        let err = if r.converged {
            r.err
        } else {
            // not converged: report an error that blocks every digit the
            // estimate does not support
            Float::with_val(p, r.err * 16u32)
        };
        (r.value, err)
    }

    pub fn n12(&mut self, d: &Float) -> Float {
        let st = self.dynm.state(d);
        self.dynm.forces(&st).n12
    }

    pub fn n1(&mut self, d: &Float) -> Float {
        let st = self.dynm.state(d);
        self.dynm.forces(&st).n1
    }

    pub fn phi1_dot(&mut self, d: &Float) -> Float {
        self.dynm.state(d).v[PHI1].clone()
    }

    /// φ1 at δ (needs the time when the drift ω0 ≠ 0).
    pub fn phi1(&mut self, d: &Float) -> Float {
        let t = if self.dynm.gamma[PHI1].is_zero() {
            Float::new(self.prec())
        } else {
            self.time(d).0
        };
        let st = self.dynm.state(d);
        self.dynm.positions(&st, &t)[PHI1].clone()
    }

    /// Refines a root of `f` bracketed by [lo, hi] (found at low precision)
    /// to this engine's precision; returns (midpoint, half-width).
    pub fn refine_root<F>(
        &mut self,
        name: &str,
        lo: &Float,
        hi: &Float,
        mut f: F,
    ) -> Result<(Float, Float)>
    where
        F: FnMut(&mut Engine, &Float) -> Float,
    {
        let p = self.prec();
        let lo = Float::with_val(p, lo);
        let hi = Float::with_val(p, hi);
        let tol = Float::with_val(p, 1u32) >> (p as i32 - 8);
        let r = root::bracket(name, &lo, &hi, &tol, |x| f(self, x))?;
        let half = Float::with_val(p, r.width() / 2u32);
        let ulp = Float::with_val(p, r.mid().abs()) >> (p as i32 - 2);
        Ok((r.mid(), half + ulp))
    }
}
