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

/// Frees MPFR's caches of the calling thread (its constants such as π and
/// its pool of integers). MPFR keeps them per thread and does not free
/// them when a thread ends: a thread that computes and exits calls this
/// last, or every such thread (a worker per Python call, a thread per block
/// of rows) leaves them behind (a few hundred bytes to kilobytes a call).
pub fn free_thread_caches() {
    rug::float::free_cache(rug::float::FreeCache::Local);
}

/// Frees the thread's MPFR caches when dropped ([`free_thread_caches`]):
/// made first in a thread that computes, it frees them however the thread
/// ends, a panic included. Bind it to a name (`let _caches =
/// ThreadCaches;`): `let _ = ThreadCaches;` drops it at once.
#[must_use = "the caches are freed when the guard is dropped"]
pub struct ThreadCaches;

impl Drop for ThreadCaches {
    fn drop(&mut self) {
        free_thread_caches();
    }
}

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

/// `x` rounded to binary64 to nearest (ties to even): `Float::to_f64`'s
/// value, from the significand's two top limbs read in place (the limbs
/// below them a sticky bit), without MPFR's general conversion; MPFR's
/// where x is zero, not finite or beyond 2^±1000.
pub fn to_f64_near(x: &Float) -> f64 {
    let (Some(sig), Some(e)) = (x.get_significand(), x.get_exp()) else {
        return x.to_f64();
    };
    if !(-1000..=1000).contains(&e) {
        return x.to_f64();
    }
    let m = sig.as_limbs();
    let n = m.len();
    let mut u = (m[n - 1] as u128) << 64;
    if n >= 2 {
        u |= m[n - 2] as u128;
    }
    // the top bit of u is set: rounding to 53 bits looks at bit 74 and
    // below, so the limbs below u count as one bit at bit 0
    if n >= 3 && m[..n - 2].iter().any(|&l| l != 0) {
        u |= 1;
    }
    // |x| = u·2^(e − 128): u rounded once, then scaled exactly (both
    // factors powers of two in binary64's normal range)
    let pow2 = |k: i32| f64::from_bits(((k + 1023) as u64) << 52);
    let r = (u as f64) * pow2(-128) * pow2(e);
    if x.is_sign_negative() {
        -r
    } else {
        r
    }
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

#[cfg(test)]
mod f64_tests {
    use super::*;

    /// [`to_f64_near`] is MPFR's conversion to nearest, for random
    /// significands (including ties and near-ties at the 53rd bit, and
    /// nonzero bits far below it) at one to five limbs and exponents
    /// across binary64's range; beyond ±1000 and at 0 it is MPFR's own.
    #[test]
    fn to_f64_near_is_mpfrs() {
        let mut rnd = xorshift(0x9e37_79b9_7f4a_7c15);
        for prec in [
            2u32, 53, 54, 63, 64, 65, 100, 127, 128, 129, 179, 192, 256, 300,
        ] {
            for i in 0..3000 {
                let limbs = prec.div_ceil(64) as usize;
                let mut words: Vec<u64> = (0..limbs).map(|_| rnd()).collect();
                // a tie or near-tie at binary64's last bit, with or without
                // bits below it
                match i % 4 {
                    0 => {
                        let top = limbs - 1;
                        words[top] = (words[top] & !0x7ff) | 0x400;
                        for w in &mut words[..top] {
                            *w = 0;
                        }
                        if i % 8 == 0 && top > 0 {
                            words[0] = 1;
                        }
                    }
                    1 => words[limbs - 1] |= 0x3ff,
                    _ => {}
                }
                let int = rug::Integer::from_digits(&words, rug::integer::Order::Lsf);
                let e = (rnd() % 2001) as i32 - 1000;
                let mut x = Float::with_val(prec, &int);
                x >>= 64 * limbs as u32;
                x <<= e;
                if i % 3 == 0 {
                    x = -x;
                }
                let want = x.to_f64();
                assert_eq!(
                    to_f64_near(&x).to_bits(),
                    want.to_bits(),
                    "{x:e} at {prec} bits"
                );
            }
        }
        for x in [0.0f64, -0.0, f64::INFINITY, f64::NAN, 1e-305, 1e305] {
            let f = Float::with_val(100, x);
            assert_eq!(to_f64_near(&f).to_bits(), f.to_f64().to_bits());
        }
    }
}
