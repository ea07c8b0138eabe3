//! The sine and cosine of one argument, correctly rounded, in fixed point:
//! the same bits as MPFR's `sin_cos` (round to nearest), at about two
//! thirds of its cost (7 k instructions against 11 k at 124–171 bits; two
//! Horner sums of ten 4-limb products are most of it) where the energy
//! quadrature's integrand and the closed forms of the rolling phases ask
//! for them (δ/2, thousands of times per answer: in MPFR a third of an
//! ideal model's instructions; −9% of them at 30 digits).
//!
//! **Method.** |x| = a_j + b with a_j = j/32 the nearest of a table's
//! angles (j = 0…64, |x| ≤ 2) and |b| ≤ 1/64: sin b and cos b from their
//! Taylor series in u = b² by Horner's rule, then sin|x| = sin a_j cos b +
//! cos a_j sin b and cos|x| = cos a_j cos b − sin a_j sin b. The table's
//! entries (MPFR at 64 bits more, rounded to nearest) and the series'
//! coefficients are computed once per thread and limb count, an entry when
//! first asked. Everything runs on [`super::fixed`]'s numbers with F =
//! 64(L − 1) fraction bits, F at least 24 bits beyond the precision asked
//! (more for a small |x|, whose sine is small).
//!
//! **Accuracy and the rounding.** With ε = 2^−F: the argument is rounded
//! to F bits (ε/2), the table's entries and the coefficients likewise
//! (ε/2 each), every truncated product toward zero (< ε each, the products
//! left out below 2^−(F+64)), the series cut where its next term is below
//! ε/64. Through the two angle-sum formulas the sine and the cosine are
//! each within 8ε of the exact values (the bound is added up in the
//! comments of `fast_in`; 16ε is allowed). The result is rounded in
//! integer arithmetic and accepted only where the bits it drops are more
//! than 16ε from half a unit of the output's last place (`rounded`): the
//! exact value then rounds the same way, to what MPFR returns (its
//! `sin_cos` is correctly rounded). Where it is that close (about one call
//! in 2^(GUARD−6) or fewer), and for |x| > 2, |x| < 2^−40, zero, non-finite x, or a
//! precision beyond the instantiated limb counts, MPFR computes it. So the
//! answers are bit for bit MPFR's; only the cost differs.

use super::fixed::{add_signed, horner, mul_u, Conv, Fx};
use rug::integer::Order;
use rug::ops::NegAssign;
use rug::{Assign, Float, Integer};
use std::any::Any;
use std::cell::RefCell;

/// Table spacing: entries at j/32.
const STEPS: u32 = 32;
/// Largest |x| of the fast path (the table's last entry is 64/32).
const MAX_J: usize = 64;
/// Smallest exponent of x on the fast path (|x| ≥ 2^−41).
const MIN_EXP: i32 = -40;
/// Bits beyond the output precision the fixed point carries.
const GUARD: u32 = 24;

/// sin x into `s` and cos x into `c`, each rounded to nearest at its own
/// precision (x exact, whatever its precision): the same bits as MPFR's
/// `sin_cos`, `(&mut s, &mut c).assign(x.sin_cos_ref())`.
pub fn sin_cos_into(x: &Float, s: &mut Float, c: &mut Float) {
    if !try_fast(x, s, c) {
        (&mut *s, &mut *c).assign(x.sin_cos_ref());
    }
}

/// The fast path of [`sin_cos_into`]: `false` where it declines (`s`, `c`
/// then unspecified).
fn try_fast(x: &Float, s: &mut Float, c: &mut Float) -> bool {
    match x.get_exp() {
        Some(e) if x.is_finite() && (MIN_EXP..=2).contains(&e) => {
            let need = s.prec().max(c.prec()) + GUARD + (-e).max(0) as u32;
            // one integer limb, F = 64(L − 1) ≥ need
            match need.div_ceil(64) as usize + 1 {
                // a 2-limb need is served by 3 (the smallest instantiated)
                2..=3 => fast::<3>(x, s, c),
                4 => fast::<4>(x, s, c),
                5 => fast::<5>(x, s, c),
                6 => fast::<6>(x, s, c),
                7 => fast::<7>(x, s, c),
                8 => fast::<8>(x, s, c),
                9 => fast::<9>(x, s, c),
                10 => fast::<10>(x, s, c),
                _ => false,
            }
        }
        _ => false,
    }
}

/// (sin x, cos x) at precision `p` each ([`sin_cos_into`]).
pub fn sin_cos(x: &Float, p: u32) -> (Float, Float) {
    let mut s = Float::new(p);
    let mut c = Float::new(p);
    sin_cos_into(x, &mut s, &mut c);
    (s, c)
}

/// The constants of one limb count: the series' coefficients, the table,
/// scratch.
struct Tab<const L: usize> {
    /// (−1)^k/(2k+1)!, k = 1…m (index 0 unused).
    sin_c: Vec<Fx<L>>,
    /// (−1)^k/(2k)!, k = 1…m (index 0 unused).
    cos_c: Vec<Fx<L>>,
    /// Horner's degree in u.
    m: usize,
    /// (sin j/32, cos j/32), computed when first asked.
    entries: Vec<Option<(Fx<L>, Fx<L>)>>,
    /// Scratch for the conversions.
    int: Integer,
    conv: Conv,
    prod: Vec<u64>,
}

impl<const L: usize> Tab<L> {
    fn new() -> Self {
        let f = 64 * (L as u32 - 1);
        let wp = f + 64;
        let mut conv = Conv::new(wp);
        // the smallest m whose next terms u^(m+1)/(2m+2)! and
        // u^(m+1)/(2m+3)! are below ε/64: |b| ≤ 1/64 + 2^−51 (j from |x|
        // rounded to f64, |x| ≤ 2 + 1/64), so u < 2^−11.99
        let mut m = 1usize;
        loop {
            let lf = (1..=(2 * m as u32 + 2))
                .map(|k| f64::from(k).log2())
                .sum::<f64>();
            if 11.99 * (m as f64 + 1.0) + lf >= f64::from(f) + 6.0 {
                break;
            }
            m += 1;
        }
        let mut fact = rug::Integer::from(1u32);
        let mut sin_c = vec![Fx::ZERO];
        let mut cos_c = vec![Fx::ZERO];
        for k in 1..=m as u32 {
            // (2k)! then (2k+1)!
            fact *= 2 * k - 1;
            fact *= 2 * k;
            let mut cc = Float::with_val(wp, 1u32) / &fact;
            if k % 2 == 1 {
                cc = -cc;
            }
            cos_c.push(conv.to_fx(&cc));
            let sc = Float::with_val(wp, &cc / (2 * k + 1));
            sin_c.push(conv.to_fx(&sc));
        }
        Tab {
            sin_c,
            cos_c,
            m,
            entries: vec![None; MAX_J + 1],
            int: Integer::with_capacity(64 * L + 64),
            conv,
            prod: vec![0; 2 * L + 2],
        }
    }

    fn entry(&mut self, j: usize) -> (Fx<L>, Fx<L>) {
        if let Some(e) = self.entries[j] {
            return e;
        }
        let wp = 64 * L as u32 + 64;
        let a = Float::with_val(wp, j as u32) / STEPS;
        let (sa, ca) = a.sin_cos(Float::new(wp));
        let e = (self.conv.to_fx(&sa), self.conv.to_fx(&ca));
        self.entries[j] = Some(e);
        e
    }
}

thread_local! {
    /// One [`Tab`] per limb count used on this thread.
    static TABS: RefCell<Vec<(usize, Box<dyn Any>)>> = const { RefCell::new(Vec::new()) };
}

fn fast<const L: usize>(x: &Float, s: &mut Float, c: &mut Float) -> bool {
    TABS.with(|t| {
        let mut t = t.borrow_mut();
        let i = match t.iter().position(|(l, _)| *l == L) {
            Some(i) => i,
            None => {
                t.push((L, Box::new(Tab::<L>::new())));
                t.len() - 1
            }
        };
        let Some(tab) = t[i].1.downcast_mut::<Tab<L>>() else {
            return false;
        };
        fast_in(tab, x, s, c)
    })
}

fn fast_in<const L: usize>(tab: &mut Tab<L>, x: &Float, s: &mut Float, c: &mut Float) -> bool {
    let neg = x.is_sign_negative();
    // |x| to F bits (exact unless x has more: then truncated, within ε)
    let Some(ax) = to_fixed::<L>(x, &mut tab.int) else {
        return false;
    };
    let j = (x.to_f64().abs() * f64::from(STEPS)).round() as usize;
    if j > MAX_J {
        return false; // |x| > 2 + 1/64: beyond the table
    }
    // a_j = j/32 exactly: the integer limb j >> 5, the top fraction limb's
    // top bits (j & 31) << 59
    let mut aj = [0u64; L];
    aj[L - 1] = (j >> 5) as u64;
    aj[L - 2] = ((j & 31) as u64) << 59;
    let aj = Fx::<L> {
        m: aj,
        len: if aj[L - 1] != 0 {
            L as u16
        } else {
            L as u16 - 1
        },
        neg: true,
    };
    let aj = if j == 0 { Fx::ZERO } else { aj };
    // b = |x| − a_j, exact
    let b = add_signed(&ax, &aj);
    let mut bm = b;
    bm.neg = false;
    let (sa, ca) = tab.entry(j);
    let prod = &mut tab.prod;
    // u = b² (< ε); sin|b| = |b|(1 + Σ s_k u^k), cos b = 1 + Σ c_k u^k: each
    // sum within ε + ε/64 + ε/2^10 (last product, cut, the coefficients'
    // roundings times u^k)
    let u = mul_u(&bm, &bm, prod);
    let mut one = Fx::<L>::ZERO;
    one.m[L - 1] = 1;
    one.len = L as u16;
    let ss = add_signed(&one, &horner(&tab.sin_c, tab.m, &u, prod));
    // |b|·S: |b| ≤ 2^−5 times S's error, plus this product's ε
    let mut sb = mul_u(&ss, &bm, prod);
    sb.neg = b.neg && sb.len > 0;
    // C's error: its sum's (≤ 1.02ε) and u's ε times |dC/du| ≤ 1/2
    let cb = add_signed(&one, &horner(&tab.cos_c, tab.m, &u, prod));
    // sin = sa·cb + ca·sb: ε/2 (sa) + 1.6ε (cb) + ε/2^6 (ca's ε/2 times
    // |sb|) + 1.1ε (sb) + 2ε (two products) = 5.3ε, and ε/2 from x's
    // rounding: under 7ε (ε from x's truncation: 5.8ε); cos = ca·cb −
    // sa·sb likewise
    let sin = add_signed(&mul_signed(&sa, &cb, prod), &mul_signed(&ca, &sb, prod));
    let mut sasb = mul_signed(&sa, &sb, prod);
    sasb.neg = !sasb.neg && sasb.len > 0;
    let cos = add_signed(&mul_signed(&ca, &cb, prod), &sasb);
    let mut sin = sin;
    if neg {
        sin.neg = !sin.neg && sin.len > 0;
    }
    let ok = rounded(&sin, sin.neg, s, &mut tab.int);
    ok && rounded(&cos, cos.neg, c, &mut tab.int)
}

/// a·b with the sign of the product (truncated toward zero).
fn mul_signed<const L: usize>(a: &Fx<L>, b: &Fx<L>, prod: &mut [u64]) -> Fx<L> {
    let mut bm = *b;
    bm.neg = false;
    let mut r = mul_u(a, &bm, prod);
    r.neg = (a.neg != b.neg) && r.len > 0;
    r
}

/// |x|·2^F truncated to an integer, as a fixed-point number (x finite,
/// |x| < 4); `None` where x does not fit.
fn to_fixed<const L: usize>(x: &Float, int: &mut Integer) -> Option<Fx<L>> {
    let f = 64 * (L as i64 - 1);
    // |x| = i·2^e exactly
    let e = i64::from(x.to_integer_exp_in_place(int)?);
    let limbs = int.as_limbs();
    let sh = e + f;
    let mut m = [0u64; L];
    if sh >= 0 {
        let (w, b) = ((sh / 64) as usize, (sh % 64) as u32);
        for (k, &l) in limbs.iter().enumerate() {
            let lo = l << b;
            let hi = if b == 0 { 0 } else { l >> (64 - b) };
            if lo != 0 {
                *m.get_mut(k + w)? |= lo;
            }
            if hi != 0 {
                *m.get_mut(k + w + 1)? |= hi;
            }
        }
    } else {
        let d = -sh;
        let (w, b) = ((d / 64) as usize, (d % 64) as u32);
        for (k, o) in m.iter_mut().enumerate() {
            let lo = limbs.get(k + w).copied().unwrap_or(0) >> b;
            let hi = if b == 0 {
                0
            } else {
                limbs.get(k + w + 1).copied().unwrap_or(0) << (64 - b)
            };
            *o = lo | hi;
        }
        if limbs.len() > w + L + 1 {
            return None;
        }
    }
    let len = m.iter().rposition(|&l| l != 0).map_or(0, |i| i + 1) as u16;
    Some(Fx { m, len, neg: false })
}

/// Bit `i` of the magnitude.
#[inline]
fn bit(m: &[u64], i: usize) -> bool {
    m.get(i / 64).is_some_and(|l| (l >> (i % 64)) & 1 == 1)
}

/// Bits [lo, hi) of the magnitude all equal `b`.
fn all_bits(m: &[u64], lo: usize, hi: usize, b: bool) -> bool {
    let want = if b { u64::MAX } else { 0 };
    let mut i = lo;
    while i < hi {
        let (w, o) = (i / 64, i % 64);
        let n = (64 - o).min(hi - i);
        let mask = if n == 64 {
            u64::MAX
        } else {
            ((1u64 << n) - 1) << o
        };
        if (m.get(w).copied().unwrap_or(0) ^ want) & mask != 0 {
            return false;
        }
        i += n;
    }
    true
}

/// `out` = v (negated if `neg`) correctly rounded to `out`'s precision p,
/// where v, within 16 units of its last place of the exact value, decides
/// it; else `false` (`out` unspecified).
///
/// V = v·2^F has `bits` bits; rounding keeps the top p, dropping k = bits −
/// p with remainder r. Rounding to nearest is decided by r against half =
/// 2^(k−1); V within 16 of the exact value, r within 31 of half is declined
/// (bits [5, k−1) all the complement of bit k−1, a superset of that case).
/// Otherwise the exact value's remainder lies on the same side of half —
/// or, within 16 of a power of two, rounds to that power from either
/// binade — and V's rounding is the correct one: MPFR's.
fn rounded<const L: usize>(v: &Fx<L>, neg: bool, out: &mut Float, int: &mut Integer) -> bool {
    let m = &v.m[..v.len as usize];
    let Some(&top) = m.last() else {
        return false;
    };
    let bits = 64 * (m.len() - 1) + (64 - top.leading_zeros() as usize);
    let p = out.prec() as usize;
    if bits < p + 8 {
        return false;
    }
    let k = bits - p;
    let up = bit(m, k - 1);
    if all_bits(m, 5, k - 1, !up) {
        return false;
    }
    // R = V >> k, plus one if the dropped part is above half
    let mut r = [0u64; L];
    let (w, b) = (k / 64, (k % 64) as u32);
    for (i, o) in r.iter_mut().enumerate() {
        let lo = m.get(i + w).copied().unwrap_or(0) >> b;
        let hi = if b == 0 {
            0
        } else {
            m.get(i + w + 1).copied().unwrap_or(0) << (64 - b)
        };
        *o = lo | hi;
    }
    if up {
        for l in r.iter_mut() {
            let (x, c) = l.overflowing_add(1);
            *l = x;
            if !c {
                break;
            }
        }
    }
    let n = r.iter().rposition(|&l| l != 0).map_or(0, |i| i + 1);
    int.assign_digits(&r[..n], Order::Lsf);
    // exact: R has at most p + 1 bits (2^p after a carry)
    out.assign(&*int);
    let f = 64 * (L as i32 - 1);
    *out <<= k as i32 - f;
    if neg {
        out.neg_assign();
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Integer;

    fn mpfr(x: &Float, ps: u32, pc: u32) -> (Float, Float) {
        let mut s = Float::new(ps);
        let mut c = Float::new(pc);
        (&mut s, &mut c).assign(x.sin_cos_ref());
        (s, c)
    }

    fn same(a: &Float, b: &Float) -> bool {
        a == b && a.is_sign_negative() == b.is_sign_negative() && a.prec() == b.prec()
    }

    /// Many arguments at many precisions: the same bits as MPFR, the
    /// fast path taken for most (it is the point).
    #[test]
    fn the_same_bits_as_mpfr() {
        let mut next = crate::numeric::xorshift(0x9e3779b97f4a7c15);
        let mut fast_taken = 0;
        let mut eligible = 0;
        let mut n = 0;
        for &p in &[
            24u32, 53, 64, 100, 124, 128, 171, 200, 256, 357, 433, 512, 600,
        ] {
            for k in 0..300 {
                let px = if k % 3 == 0 { p + 40 } else { p };
                // |x| from 2^−45 to 2.5, both signs, random bits
                let e = -((next() % 48) as i32) + 2;
                let bits = Integer::from(next()) << 64 | Integer::from(next());
                let mut x = Float::with_val(px, bits) >> (128 - e);
                if next() % 2 == 0 {
                    x = -x;
                }
                let (ws, wc) = mpfr(&x, p, p + (k % 2) * 7);
                let mut s = Float::new(p);
                let mut c = Float::new(p + (k % 2) * 7);
                sin_cos_into(&x, &mut s, &mut c);
                assert!(same(&s, &ws), "sin {x} at {p}: {s} against {ws}");
                assert!(same(&c, &wc), "cos {x} at {p}: {c} against {wc}");
                n += 1;
                let mut s2 = Float::new(p);
                let mut c2 = Float::new(p + (k % 2) * 7);
                let l = x
                    .get_exp()
                    .map(|e| (p + (k % 2) * 7 + GUARD + (-e).max(0) as u32).div_ceil(64) + 1);
                if x.get_exp().is_some_and(|e| (MIN_EXP..=2).contains(&e))
                    && x.to_f64().abs() <= 2.0
                    && l.is_some_and(|l| l <= 10)
                {
                    eligible += 1;
                    if try_fast(&x, &mut s2, &mut c2) {
                        fast_taken += 1;
                        assert!(same(&s2, &ws) && same(&c2, &wc));
                    }
                }
            }
        }
        // the fast path declines only near a rounding boundary (rare)
        assert!(
            fast_taken * 100 >= eligible * 99 && eligible * 2 > n,
            "fast path {fast_taken} of {eligible} eligible, {n} in all"
        );
    }

    /// Arguments whose sine or cosine lies within a few units of the
    /// fixed point's error bound from a rounding boundary at the output
    /// precision: found by taking MPFR's value at p bits, nudging it to
    /// the midpoint of two p-bit numbers, and asking for the angle whose
    /// sine is that midpoint (asin at high precision): the fast path must
    /// decline or agree, never round the other way.
    #[test]
    fn near_rounding_boundaries_the_bits_still_agree() {
        for &p in &[53u32, 124, 171, 300] {
            for k in 1..200u32 {
                let hp = p + 200;
                let target = Float::with_val(hp, k) / 211u32;
                // the midpoint just above target's p-bit rounding
                let r = Float::with_val(p, &target);
                let ulp = Float::with_val(hp, 1u32) << (r.get_exp().unwrap() - p as i32);
                let mid = Float::with_val(hp, &r + Float::with_val(hp, &ulp >> 1));
                for x in [
                    Float::with_val(p + 100, mid.asin_ref()),
                    Float::with_val(p + 100, mid.acos_ref()),
                ] {
                    let (ws, wc) = mpfr(&x, p, p);
                    let (s, c) = sin_cos(&x, p);
                    assert!(same(&s, &ws), "sin at {p}, k {k}");
                    assert!(same(&c, &wc), "cos at {p}, k {k}");
                    // the fixed point's bound straddles the midpoint: the
                    // fast path itself declines (its check is what holds)
                    let (mut s2, mut c2) = (Float::new(p), Float::new(p));
                    assert!(!try_fast(&x, &mut s2, &mut c2), "declined at {p}, k {k}");
                }
            }
        }
    }

    /// Zero, the signs of zero, large and tiny arguments, infinities and
    /// NaN: MPFR's answers (the fallback).
    #[test]
    fn edge_arguments_are_mpfrs() {
        let p = 124;
        let cases = [
            Float::new(p),
            -Float::new(p),
            Float::with_val(p, 1e-30),
            Float::with_val(p, -3),
            Float::with_val(p, 2),
            Float::with_val(p, 1e10),
            Float::with_val(p, f64::INFINITY),
            Float::with_val(p, f64::NAN),
        ];
        for x in &cases {
            let (ws, wc) = mpfr(x, p, p);
            let (s, c) = sin_cos(x, p);
            if ws.is_nan() {
                assert!(s.is_nan() && c.is_nan());
            } else {
                assert!(same(&s, &ws) && same(&c, &wc), "{x}");
            }
        }
    }
}
