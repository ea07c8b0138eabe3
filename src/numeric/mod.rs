//! Numerical building blocks on `rug::Float`: tanh-sinh ([`quad`]) and
//! Gauss–Legendre ([`gauss`]) quadrature, bracketed roots ([`root`]) and real
//! polynomial roots ([`poly`]), a Taylor-series ODE integrator with dense
//! output ([`taylor`], on the fixed-point kernel of [`fixed`]), decimal
//! output ([`decimal`]), the precision ladder that turns two runs into
//! verified digits ([`verify`]), Chebyshev interpolation with a fast cosine
//! transform for the high-precision routes ([`cheb`]), and interval
//! arithmetic with directed rounding for proved digits ([`interval`]), with
//! its proved Clenshaw–Curtis rules ([`ccrig`]).
//!
//! No Rust crate integrates or root-solves on MPFR numbers; these are ours and
//! are tested against closed forms in their own unit tests.

pub mod ccrig;
pub mod cheb;
pub mod decimal;
pub mod fixed;
pub mod gauss;
pub mod interval;
pub mod poly;
pub mod quad;
pub mod root;
pub mod taylor;
pub mod trig;
pub mod verify;

use rug::Float;

/// Bits needed for `digits` significant decimal digits: ⌈digits·log2 10⌉.
pub fn bits_for_digits(digits: u32) -> u32 {
    ((digits as f64) * std::f64::consts::LOG2_10).ceil() as u32
}

/// The binary exponent e of the largest of `vals` in magnitude (None where
/// every one is 0 or not finite): 2^−e brings them into (−1, 1), the
/// largest to at least 1/2.
pub fn max_exp<'a>(vals: impl IntoIterator<Item = &'a Float>) -> Option<i32> {
    vals.into_iter().filter_map(Float::get_exp).max()
}

/// v·2^−e in f64 (the scaling exact, one rounding). With e from
/// [`max_exp`] a set of values keeps its signs and ratios in f64 in any
/// units, where unscaled 10^−400 would be 0 and 10^400 infinite.
pub fn scaled_f64(v: &Float, e: i32) -> f64 {
    Float::with_val(53, v >> e).to_f64()
}

/// A new Float of value 0 at `prec` bits.
pub fn zero(prec: u32) -> Float {
    Float::new(prec)
}

/// A xorshift64 generator for the tests' random cases (deterministic from
/// `seed`, which must not be 0).
#[cfg(test)]
pub(crate) fn xorshift(mut seed: u64) -> impl FnMut() -> u64 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    }
}
