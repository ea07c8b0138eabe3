//! Root-solving the paper's separation equations, as printed and as
//! corrected, for comparison with the oracle's θs (where N12 = 0).

use super::truth::PREC;
use crate::numeric::root;
use crate::paper::X;
use rug::Float;

/// Scan steps over (0, π/2].
const STEPS: u32 = 256;

/// The first root in θ ∈ (2⁻¹⁰, π/2] of `f` (a function of θ), refined to
/// the working precision; `None` if `f` keeps its sign there.
pub fn first_root<F>(f: F) -> Option<X>
where
    F: FnMut(&X) -> X,
{
    let hi = Float::with_val(PREC, rug::float::Constant::Pi) / 2u32;
    first_root_below(&X(hi), f)
}

/// The first root in θ ∈ (2⁻¹⁰, `hi`] of `f`, refined to the working precision.
pub fn first_root_below<F>(hi: &X, mut f: F) -> Option<X>
where
    F: FnMut(&X) -> X,
{
    let lo = Float::with_val(PREC, 1u32) >> 10;
    let hi = hi.0.clone();
    let mut g = |x: &Float| f(&X(x.clone())).0;
    let (a, b) = root::first_sign_change(&lo, &hi, STEPS, &mut g)?;
    let tol = Float::with_val(PREC, 1u32) >> (PREC as i32 - 8);
    let r = root::bracket("separation", &a, &b, &tol, &mut g).ok()?;
    Some(X(r.mid()))
}

/// The first root in θ of a function of cos θ.
pub fn first_root_cos<F>(mut f: F) -> Option<X>
where
    F: FnMut(&X) -> X,
{
    first_root(|th| f(&th.cos()))
}
