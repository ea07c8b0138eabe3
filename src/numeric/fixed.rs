//! Fixed-point numbers for the Taylor integrator's inner loops: sign and
//! magnitude, the magnitude in `L` little-endian 64-bit limbs of which the
//! lowest `L − 1` are the fraction (value = ±m·2^(−64(L−1)), so |value| <
//! 2^64). Products are accumulated exactly (up to the truncation below) in a
//! double-length accumulator and rounded toward zero once per result, by
//! dropping whole limbs. A result that does not fit raises the accumulator's
//! overflow flag. Values below 1 leave the integer limb zero, and every loop
//! runs over the significant limbs only, so that limb costs nothing.
//!
//! The limb count is a const generic: the loops have fixed bounds, unroll,
//! and carry no bounds checks; the integrator is instantiated for a list of
//! sizes ([`limbs_for`]) and picks the smallest that holds its precision.
//!
//! Why not `rug::Integer` or `rug::Float`: at 2–8 limbs GMP's `mpz_addmul`
//! and MPFR's `mul`+`add` spend most of their time in call overhead, sign
//! handling, normalisation and temporaries (about 400 instructions per
//! multiply-add at 3 limbs, measured with callgrind); here a limb product costs
//! about 9 instructions. Safe Rust, `u128` partial products.
//!
//! **Truncated products.** Limb products a_i·b_j with i + j < L − 3 are left
//! out. Each would add less than 2^(64(L−2)) at the product scale
//! 2^(128(L−1)), i.e. less than 2^(−64L) = 2^-(F+64) to the value (F = 64(L−1)
//! fraction bits), far below the final rounding to F bits. For geometrically
//! decaying Taylor coefficients this skips most limb products: a small
//! coefficient times anything only reaches the low limbs.

use rug::integer::Order;
use rug::ops::NegAssign;
use rug::{Float, Integer};

/// The limb counts the integrator is instantiated for, ascending.
pub const SIZES: [usize; 24] = [
    2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 14, 16, 20, 24, 32, 40, 48, 64, 80, 96, 128, 160, 192, 256,
];

/// The smallest size in [`SIZES`] with at least `need` limbs (`None` if none).
pub fn limbs_for(need: usize) -> Option<usize> {
    SIZES.iter().copied().find(|&l| l >= need.max(2))
}

/// A fixed-point number of `L` limbs, `L − 1` of them fraction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fx<const L: usize> {
    /// Magnitude, little-endian.
    pub m: [u64; L],
    /// Significant limbs of `m` (the rest are zero).
    pub len: u16,
    /// Negative (never set for zero).
    pub neg: bool,
}

impl<const L: usize> Default for Fx<L> {
    fn default() -> Self {
        Self::ZERO
    }
}

fn sig_len(x: &[u64]) -> u16 {
    let mut n = x.len();
    while n > 0 && x[n - 1] == 0 {
        n -= 1;
    }
    n as u16
}

impl<const L: usize> Fx<L> {
    /// Fraction limbs.
    pub const LF: usize = L - 1;
    /// Zero.
    pub const ZERO: Self = Fx {
        m: [0; L],
        len: 0,
        neg: false,
    };

    /// Zero.
    pub fn is_zero(&self) -> bool {
        self.len == 0
    }

    fn from_mag(m: [u64; L], neg: bool) -> Self {
        let len = sig_len(&m);
        Fx {
            m,
            len,
            neg: neg && len > 0,
        }
    }

    /// `x` rounded to nearest (x finite, |x| < 2^64).
    pub fn from_float(x: &Float) -> Self {
        let lf = Self::LF as u32;
        let p = x.prec().max(64 * lf + 8);
        let scaled = Float::with_val(p, x << (64 * lf));
        let i = scaled
            .to_integer_round(rug::float::Round::Nearest)
            .map(|(i, _)| i)
            .unwrap_or_default();
        let mut m = [0u64; L];
        for (k, d) in i
            .as_abs()
            .to_digits::<u64>(Order::Lsf)
            .into_iter()
            .take(L)
            .enumerate()
        {
            m[k] = d;
        }
        Self::from_mag(m, i.is_negative())
    }

    /// The value as a Float of `prec` bits.
    pub fn to_float(&self, prec: u32) -> Float {
        let i = Integer::from_digits(&self.m[..self.len as usize], Order::Lsf);
        let f = Float::with_val(prec, &i) >> (64 * Self::LF as u32);
        if self.neg {
            -f
        } else {
            f
        }
    }

    /// log2 |value| (−∞ for 0).
    pub fn log2(&self) -> f64 {
        let n = self.len as usize;
        if n == 0 {
            return f64::NEG_INFINITY;
        }
        let mut m = self.m[n - 1] as f64;
        if n >= 2 {
            m += self.m[n - 2] as f64 / 18446744073709551616.0;
        }
        m.log2() + 64.0 * (n as f64 - 1.0 - Self::LF as f64)
    }

    /// self / k (k > 0, toward zero).
    pub fn div_small(&self, k: u64) -> Self {
        let mut m = self.m;
        let mut rem: u128 = 0;
        for x in m.iter_mut().rev() {
            let cur = (rem << 64) | *x as u128;
            *x = (cur / k as u128) as u64;
            rem = cur % k as u128;
        }
        Self::from_mag(m, self.neg)
    }

    /// k·self (k small; |result| < 2^64).
    pub fn mul_small(&self, k: u64) -> Self {
        let mut m = [0u64; L];
        let mut carry: u64 = 0;
        for (o, &x) in m.iter_mut().zip(self.m.iter()) {
            let t = (x as u128) * (k as u128) + carry as u128;
            *o = t as u64;
            carry = (t >> 64) as u64;
        }
        Self::from_mag(m, self.neg)
    }
}

/// Scratch for conversions between Floats and fixed point without
/// allocating (after the first use).
#[derive(Debug, Clone)]
pub struct Conv {
    f: Float,
    i: Integer,
}

impl Conv {
    /// Scratch for values of up to `prec` bits.
    pub fn new(prec: u32) -> Self {
        Conv {
            f: Float::new(prec.max(64)),
            i: Integer::with_capacity(prec as usize + 128),
        }
    }

    /// `x` rounded to nearest at `L − 1` fraction limbs (|x| < 2^64).
    pub fn to_fx<const L: usize>(&mut self, x: &Float) -> Fx<L> {
        let lf = Fx::<L>::LF as u32;
        let p = x.prec().max(64 * lf + 8);
        if self.f.prec() != p {
            self.f.set_prec(p);
        }
        rug::Assign::assign(&mut self.f, x << (64 * lf));
        if self
            .f
            .to_integer_round_in_place(&mut self.i, rug::float::Round::Nearest)
            .is_none()
        {
            return Fx::ZERO;
        }
        let mut m = [0u64; L];
        let neg = self.i.is_negative();
        if self.i.significant_digits::<u64>() <= L {
            self.i.as_abs().write_digits(&mut m, Order::Lsf);
        }
        Fx::from_mag(m, neg)
    }

    /// `v` into `out` (rounded to `out`'s precision).
    pub fn to_float<const L: usize>(&mut self, v: &Fx<L>, out: &mut Float) {
        self.i.assign_digits(&v.m[..v.len as usize], Order::Lsf);
        rug::Assign::assign(&mut *out, &self.i);
        *out >>= 64 * Fx::<L>::LF as u32;
        if v.neg {
            out.neg_assign();
        }
    }
}

/// acc += a·b (magnitudes), without the limb products a_i b_j, i + j < cut.
#[inline(always)]
pub(crate) fn mac_mag<const L: usize>(acc: &mut [u64], a: &Fx<L>, b: &Fx<L>, cut: usize) {
    let la = a.len as usize;
    let lb = b.len as usize;
    if la + lb < cut + 2 {
        return; // every limb product is below the cut
    }
    let acc = &mut acc[..2 * L + 2];
    for i in 0..la.min(L) {
        let ai = a.m[i];
        let j0 = cut.saturating_sub(i);
        if ai == 0 || j0 >= lb {
            continue;
        }
        let mut carry: u64 = 0;
        for j in j0..lb.min(L) {
            let t = (ai as u128) * (b.m[j] as u128) + (acc[i + j] as u128) + (carry as u128);
            acc[i + j] = t as u64;
            carry = (t >> 64) as u64;
        }
        let mut k = i + lb.min(L);
        while carry != 0 && k < 2 * L + 2 {
            let (v, c) = acc[k].overflowing_add(carry);
            acc[k] = v;
            carry = c as u64;
            k += 1;
        }
    }
}

/// acc += a·2^(64·shift) (magnitudes).
#[inline]
fn add_shifted(acc: &mut [u64], a: &[u64], shift: usize) {
    let mut carry = 0u64;
    let mut k = shift;
    for &x in a {
        if k >= acc.len() {
            return;
        }
        let (s1, c1) = acc[k].overflowing_add(x);
        let (s2, c2) = s1.overflowing_add(carry);
        acc[k] = s2;
        carry = (c1 as u64) + (c2 as u64);
        k += 1;
    }
    while carry != 0 && k < acc.len() {
        let (s, c) = acc[k].overflowing_add(carry);
        acc[k] = s;
        carry = c as u64;
        k += 1;
    }
}

/// An accumulator of products of `L`-limb numbers (2L + 2 limbs, positive
/// and negative parts), with truncated products.
#[derive(Debug, Clone)]
pub struct Acc<const L: usize> {
    pos: Vec<u64>,
    neg: Vec<u64>,
    /// Set when a result did not fit in the integer limb (sticky).
    pub overflow: bool,
}

impl<const L: usize> Default for Acc<L> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const L: usize> Acc<L> {
    const CUT: usize = L.saturating_sub(3);

    /// Zero.
    pub fn new() -> Self {
        Acc {
            pos: vec![0; 2 * L + 2],
            neg: vec![0; 2 * L + 2],
            overflow: false,
        }
    }

    /// Sets to zero (the overflow flag stays).
    #[inline]
    pub fn clear(&mut self) {
        self.pos.fill(0);
        self.neg.fill(0);
    }

    /// += a·b.
    #[inline]
    pub fn mac(&mut self, a: &Fx<L>, b: &Fx<L>) {
        if a.len == 0 || b.len == 0 {
            return;
        }
        if a.neg == b.neg {
            mac_mag(&mut self.pos, a, b, Self::CUT);
        } else {
            mac_mag(&mut self.neg, a, b, Self::CUT);
        }
    }

    /// −= a·b.
    #[inline]
    pub fn msub(&mut self, a: &Fx<L>, b: &Fx<L>) {
        if a.len == 0 || b.len == 0 {
            return;
        }
        if a.neg == b.neg {
            mac_mag(&mut self.neg, a, b, Self::CUT);
        } else {
            mac_mag(&mut self.pos, a, b, Self::CUT);
        }
    }

    /// += a (at the product scale, i.e. shifted up by the fraction limbs).
    pub fn add(&mut self, a: &Fx<L>) {
        let part = if a.neg { &mut self.neg } else { &mut self.pos };
        add_shifted(part, &a.m[..a.len as usize], Fx::<L>::LF);
    }

    /// ×2 (both parts).
    pub fn double(&mut self) {
        for v in [&mut self.pos, &mut self.neg] {
            let mut carry = 0u64;
            for x in v.iter_mut() {
                let nc = *x >> 63;
                *x = (*x << 1) | carry;
                carry = nc;
            }
        }
    }

    /// The sum, rounded toward zero to the fraction limbs, divided by `div`
    /// (> 0, toward zero). The accumulator is left in an unspecified state.
    pub fn finish(&mut self, div: u64) -> Fx<L> {
        let lf = Fx::<L>::LF;
        // sign: compare from the top
        let mut neg = false;
        for k in (0..2 * L + 2).rev() {
            if self.pos[k] != self.neg[k] {
                neg = self.pos[k] < self.neg[k];
                break;
            }
        }
        let (a, b) = if neg {
            (&self.neg, &self.pos)
        } else {
            (&self.pos, &self.neg)
        };
        let mut m = [0u64; L];
        let mut borrow = 0u64;
        let mut high = 0u64;
        for k in 0..2 * L + 2 {
            let (d1, b1) = a[k].overflowing_sub(b[k]);
            let (d2, b2) = d1.overflowing_sub(borrow);
            borrow = (b1 as u64) + (b2 as u64);
            if k >= lf + L {
                high |= d2;
            } else if k >= lf {
                m[k - lf] = d2;
            }
        }
        if high != 0 {
            self.overflow = true;
        }
        let r = Fx::from_mag(m, neg);
        if div > 1 {
            r.div_small(div)
        } else {
            r
        }
    }
}

/// r·u truncated (u ≥ 0), as a number of the same scale.
#[inline(always)]
pub(crate) fn mul_u<const L: usize>(r: &Fx<L>, u: &Fx<L>, prod: &mut [u64]) -> Fx<L> {
    let lf = Fx::<L>::LF;
    let prod = &mut prod[..2 * L + 2];
    // the products a_i b_j with i + j below the cut are left out: the limbs
    // below it are never written, nor read (the cut is at most lf)
    let cut = L.saturating_sub(3);
    prod[cut..].fill(0);
    mac_mag(prod, r, u, cut);
    let mut m = [0u64; L];
    m.copy_from_slice(&prod[lf..lf + L]);
    Fx::from_mag(m, r.neg)
}

/// r + c (signed).
#[inline]
pub(crate) fn add_signed<const L: usize>(r: &Fx<L>, c: &Fx<L>) -> Fx<L> {
    if c.len == 0 {
        return *r;
    }
    if r.len == 0 {
        return *c;
    }
    let mut m = [0u64; L];
    if c.neg == r.neg {
        let mut carry = 0u64;
        for (o, (&x, &y)) in m.iter_mut().zip(r.m.iter().zip(c.m.iter())) {
            let (s1, c1) = x.overflowing_add(y);
            let (s2, c2) = s1.overflowing_add(carry);
            *o = s2;
            carry = (c1 as u64) + (c2 as u64);
        }
        Fx::from_mag(m, r.neg)
    } else {
        let mut ge = true;
        for k in (0..L).rev() {
            if r.m[k] != c.m[k] {
                ge = r.m[k] > c.m[k];
                break;
            }
        }
        let (a, b) = if ge { (r, c) } else { (c, r) };
        let mut borrow = 0u64;
        for (o, (&x, &y)) in m.iter_mut().zip(a.m.iter().zip(b.m.iter())) {
            let (d1, b1) = x.overflowing_sub(y);
            let (d2, b2) = d1.overflowing_sub(borrow);
            *o = d2;
            borrow = (b1 as u64) + (b2 as u64);
        }
        Fx::from_mag(m, a.neg)
    }
}

/// Horner's rule Σ_{k=1}^{m} c_k u^k for 0 ≤ u ≤ 1 (m ≥ 1), with truncated
/// products; `prod` is scratch of at least 2L + 2 limbs.
pub fn horner<const L: usize>(c: &[Fx<L>], m: usize, u: &Fx<L>, prod: &mut [u64]) -> Fx<L> {
    let mut r = c[m];
    for k in (1..m).rev() {
        r = mul_u(&r, u, prod);
        r = add_signed(&r, &c[k]);
    }
    mul_u(&r, u, prod)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn products_and_sums<const L: usize>() {
        let prec = 64 * L as u32 + 64;
        let xs: Vec<Float> = [(1i32, 3u32), (-2, 7), (5, 11), (-13, 17)]
            .iter()
            .map(|&(a, b)| Float::with_val(prec, a) / b)
            .collect();
        let v: Vec<Fx<L>> = xs.iter().map(Fx::from_float).collect();
        let mut acc = Acc::<L>::new();
        acc.clear();
        acc.mac(&v[0], &v[1]);
        acc.msub(&v[2], &v[3]);
        acc.add(&v[0]);
        let r = acc.finish(3);
        let got = r.to_float(prec);
        let want = (Float::with_val(prec, &xs[0] * &xs[1])
            - Float::with_val(prec, &xs[2] * &xs[3])
            + &xs[0])
            / 3u32;
        let err = Float::with_val(prec, &got - &want).abs();
        let frac = 64 * (L as i32 - 1);
        assert!(
            err < Float::with_val(prec, 1u32) >> (frac - 4),
            "L {L}: {err:e}"
        );
        assert_eq!(r.neg, want.is_sign_negative());
        assert!((v[0].log2() - (1.0f64 / 3.0).log2()).abs() < 1e-9);
        let five = v[0].mul_small(5).to_float(prec);
        let want5 = Float::with_val(prec, &xs[0] * 5u32);
        assert!(
            Float::with_val(prec, five - want5).abs() < Float::with_val(prec, 1u32) >> (frac - 4)
        );
    }

    fn horner_case<const L: usize>() {
        let prec = 64 * L as u32 + 64;
        let cs: Vec<Float> = (0..12)
            .map(|k| Float::with_val(prec, if k % 3 == 0 { -1 } else { 1 }) / (k as u32 + 2))
            .collect();
        let v: Vec<Fx<L>> = cs.iter().map(Fx::from_float).collect();
        let u = Float::with_val(prec, 7u32) / 9u32;
        let mut prod = vec![0u64; 2 * L + 2];
        let got = horner(&v, 11, &Fx::from_float(&u), &mut prod).to_float(prec);
        let mut want = Float::new(prec);
        for k in (1..=11).rev() {
            want += &cs[k];
            want *= &u;
        }
        let err = Float::with_val(prec, &got - &want).abs();
        assert!(
            err < Float::with_val(prec, 1u32) >> (64 * (L as i32 - 1) - 8),
            "L {L}: {err:e}"
        );
    }

    #[test]
    fn products_sums_and_horner_match_mpfr() {
        products_and_sums::<2>();
        products_and_sums::<5>();
        products_and_sums::<16>();
        horner_case::<2>();
        horner_case::<4>();
        horner_case::<9>();
        let big = Fx::<2>::from_float(&Float::with_val(64, 2u64.pow(40)));
        let mut acc = Acc::<2>::new();
        acc.clear();
        acc.mac(&big, &big);
        let _ = acc.finish(1);
        assert!(acc.overflow, "overflow is flagged, not silent");
        assert_eq!(limbs_for(1), Some(2));
        assert_eq!(limbs_for(11), Some(12));
        assert_eq!(limbs_for(300), None);
    }
}
