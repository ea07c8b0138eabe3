//! Integrators of the equations of motion of one mode, in arbitrary precision.
//!
//! * [`gbs`]: Gragg–Bulirsch–Stoer extrapolation with error estimation,
//!   step-size and order control (ODEX-style).
//! * [`collocation`]: Gauss–Legendre collocation (implicit Runge–Kutta of
//!   any order), the time integrator independent of GBS.
//! * [`solve`]: the driver: integrates y = (q, q̇) of a constrained system,
//!   samples at given times, locates events to full precision.
//! * [`spectral`]: each mode as quadratures in the angle (Chebyshev
//!   interpolants in θ), the default route of a dissipative mode.

pub mod collocation;
pub mod energy;
pub mod gbs;
pub mod solve;
pub mod spectral;

use crate::mechanics::system::StackModel;
use rug::Float;

/// Guard bits between the working precision and the integrator's tolerance.
pub const TOL_GUARD: u32 = 8;

/// The natural time scale sqrt(r/g) of a stack (r = r1 + r2).
pub fn time_scale(sm: &StackModel, prec: u32) -> Float {
    sm.units(prec).ts
}
