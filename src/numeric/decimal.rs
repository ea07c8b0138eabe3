//! Decimal rendering of `Float`s to a number of significant digits.

use rug::float::Round;
use rug::{Assign, Float};

/// `x` correctly rounded (to nearest) to `digits` significant decimal digits,
/// as (sign, digit string of length `digits`, decimal exponent e) meaning
/// ±0.d1d2…·10^e. `None` for zero or non-finite values.
pub fn round_sig(x: &Float, digits: u32) -> Option<(bool, String, i64)> {
    round_sig_dir(x, digits, Round::Nearest)
}

/// [`round_sig`] rounded in the direction `round` (toward +∞ for
/// `Round::Up`, as MPFR rounds its decimal output).
pub fn round_sig_dir(x: &Float, digits: u32, round: Round) -> Option<(bool, String, i64)> {
    if x.is_zero() || !x.is_finite() {
        return None;
    }
    let s = x.to_string_radix_round(10, Some(digits as usize), round);
    // forms: "-1.2345e-7", "1.2345", "1.2345e12"
    let (neg, s) = match s.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, s.as_str()),
    };
    let (mant, exp) = match s.find('e') {
        Some(i) => (&s[..i], s[i + 1..].parse::<i64>().ok()?),
        None => (s, 0),
    };
    let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
    let digits_str = format!("{int}{frac}");
    // value = int.frac × 10^exp = 0.(int frac) × 10^(exp + len(int))
    let e = exp + int.len() as i64;
    let trimmed = digits_str.trim_start_matches('0');
    let lead_zeros = (digits_str.len() - trimmed.len()) as i64;
    let mut d: String = trimmed.to_string();
    while d.len() < digits as usize {
        d.push('0');
    }
    d.truncate(digits as usize);
    Some((neg, d, e - lead_zeros))
}

thread_local! {
    /// Recent powers of ten used by [`approx_sig`]: (precision, exponent, value).
    /// A table row's columns have different magnitudes, so a few are kept.
    static POW10: std::cell::RefCell<Vec<(u32, u32, Float)>> =
        const { std::cell::RefCell::new(Vec::new()) };
}

/// How many powers of ten [`approx_sig`] keeps.
const POW10_KEPT: usize = 32;

/// `x` to `digits` significant decimal digits *within one unit of the last
/// digit*, as [`round_sig`]'s (sign, digits, exponent): |x| scaled by a
/// power of ten and rounded to an integer once — exactly where the power is
/// 10^0 … 10^400 (its significand times that integer: the correctly rounded
/// digits), else in floating point at a precision where the product is
/// exact to far below a unit (not always correctly rounded). Cheaper than
/// MPFR's correctly rounded conversion; for callers that allow for the unit
/// (the precision ladder's fast judgement). Needs digits·log2(10) < prec(x).
pub fn approx_sig(x: &Float, digits: u32) -> Option<(bool, String, i64)> {
    let mut buf = Vec::new();
    let (neg, e) = approx_sig_into(x, digits, &mut buf)?;
    Some((neg, String::from_utf8(buf).ok()?, e))
}

thread_local! {
    /// [`approx_sig_into`]'s working numbers, kept between calls (a table
    /// converts tens of thousands of values at one precision).
    static SCRATCH: std::cell::RefCell<(Float, rug::Integer, rug::Integer)> =
        std::cell::RefCell::new((Float::new(64), rug::Integer::new(), rug::Integer::new()));
    /// 10^k as integers, k = 0, 1, … (grown as asked, up to
    /// [`POW10_INT_MAX`]).
    static POW10_INT: std::cell::RefCell<Vec<rug::Integer>> =
        const { std::cell::RefCell::new(Vec::new()) };
}

/// The largest power of ten [`approx_sig_into`] scales by exactly (beyond
/// it, and for negative powers, it scales in floating point).
const POW10_INT_MAX: i64 = 400;

/// [`approx_sig`] with its digits written into `buf` (cleared first, ASCII
/// digits), returning (sign, exponent); allocates nothing once its scratch
/// numbers have grown to the precision.
pub fn approx_sig_into(x: &Float, digits: u32, buf: &mut Vec<u8>) -> Option<(bool, i64)> {
    if x.is_zero() || !x.is_finite() {
        return None;
    }
    let n = digits as i64;
    // |x| = m·2^bm exactly: m the significand's limbs as MPFR holds them
    // (read in place, not copied; the low bits below the precision zero)
    let sig = x.get_significand()?;
    let m = sig.as_limbs();
    let bm = i64::from(x.get_exp()?) - 64 * m.len() as i64;
    let bm = i32::try_from(bm).ok()?;
    // the decimal exponent from the top limb (a first guess: the loop
    // below corrects it by one where it is off)
    let top = *m.last()?;
    let lg = (top as f64).log10()
        + (i64::from(bm) + 64 * (m.len() as i64 - 1)) as f64 * std::f64::consts::LOG10_2;
    let mut e = lg.floor() as i64 + 1;
    SCRATCH.with(|sc| {
        let mut sc = sc.borrow_mut();
        let (y, mi, mx) = &mut *sc;
        // the general path's significand as an integer, made when needed
        let mut bx = None;
        for _ in 0..3 {
            let k = n - e;
            if let Some(u) = scaled_u128(m, k, bm) {
                // the common case in machine integers: the same rounding
                buf.clear();
                push_u128(buf, u);
                match (buf.len() as i64).cmp(&n) {
                    std::cmp::Ordering::Greater => e += 1,
                    std::cmp::Ordering::Less => e -= 1,
                    std::cmp::Ordering::Equal => return Some((x.is_sign_negative(), e)),
                }
                continue;
            }
            if (0..=POW10_INT_MAX).contains(&k) {
                // |x| = mx·2^bx exactly (mx the significand as an integer)
                let bx = match bx {
                    Some(b) => b,
                    None => {
                        let b = x.to_integer_exp_in_place(mx)?;
                        mx.abs_mut();
                        *bx.insert(b)
                    }
                };
                // exact: |x|·10^k = mx·10^k·2^bx, rounded once
                POW10_INT.with(|c| {
                    let mut c = c.borrow_mut();
                    while c.len() <= k as usize {
                        let next = match c.last() {
                            Some(l) => rug::Integer::from(l * 10u32),
                            None => rug::Integer::from(1u32),
                        };
                        c.push(next);
                    }
                    mi.assign(&*mx * &c[k as usize]);
                });
                round_shift(mi, bx);
            } else {
                let kk = u32::try_from(k.unsigned_abs()).ok()?;
                let p = x.prec() + 16;
                if y.prec() != p {
                    y.set_prec(p);
                }
                y.assign(x.abs_ref());
                // 10^kk at p bits, kept for later calls (a table's values share
                // their precision, and each column mostly its exponent)
                POW10.with(|c| {
                    let mut c = c.borrow_mut();
                    let i = match c.iter().position(|e| e.0 == p && e.1 == kk) {
                        Some(i) => i,
                        None => {
                            if c.len() == POW10_KEPT {
                                c.remove(0);
                            }
                            c.push((p, kk, Float::with_val(p, Float::u_pow_u(10, kk))));
                            c.len() - 1
                        }
                    };
                    if k >= 0 {
                        *y *= &c[i].2;
                    } else {
                        *y /= &c[i].2;
                    }
                });
                let ey = y.to_integer_exp_in_place(mi)?;
                round_shift(mi, ey);
            }
            buf.clear();
            match mi.to_u128() {
                Some(u) => push_u128(buf, u),
                None => buf.extend_from_slice(mi.to_string().as_bytes()),
            }
            match (buf.len() as i64).cmp(&n) {
                std::cmp::Ordering::Greater => e += 1,
                std::cmp::Ordering::Less => e -= 1,
                std::cmp::Ordering::Equal => return Some((x.is_sign_negative(), e)),
            }
        }
        None
    })
}

/// m·10^k·2^bx rounded to the nearest integer, ties to even (as
/// [`round_shift`] rounds m·10^k), for a significand `m` of at most 4
/// limbs (least significant first) and 0 ≤ k ≤ 38, where the result fits
/// in 127 bits; `None` otherwise (the general path decides).
fn scaled_u128(m: &[u64], k: i64, bx: i32) -> Option<u128> {
    const L: usize = 6;
    if m.len() > 4 || !(0..=38).contains(&k) {
        return None;
    }
    let pw = 10u128.pow(k as u32);
    let pl = [pw as u64, (pw >> 64) as u64];
    // P = m·10^k in up to 6 limbs
    let mut prod = [0u64; L];
    for (i, &mi) in m.iter().enumerate() {
        let mut carry: u128 = 0;
        for (j, &pj) in pl.iter().enumerate() {
            let t = u128::from(mi) * u128::from(pj) + u128::from(prod[i + j]) + carry;
            prod[i + j] = t as u64;
            carry = t >> 64;
        }
        let mut idx = i + 2;
        while carry != 0 {
            let t = u128::from(prod[idx]) + carry;
            prod[idx] = t as u64;
            carry = t >> 64;
            idx += 1;
        }
    }
    let top = prod.iter().rposition(|&l| l != 0);
    let Some(top) = top else {
        return Some(0);
    };
    let bits = 64 * top as i64 + 64 - i64::from(prod[top].leading_zeros());
    if bx >= 0 {
        if bits + i64::from(bx) > 127 {
            return None;
        }
        let v = u128::from(prod[0]) | u128::from(prod[1]) << 64;
        return Some(v << bx);
    }
    let sh = i64::from(bx).unsigned_abs();
    if bits - sh as i64 > 127 {
        return None;
    }
    if sh > 64 * L as u64 {
        return Some(0);
    }
    let limb = |i: u64| -> u64 { prod.get(i as usize).copied().unwrap_or(0) };
    let bit = |b: u64| (limb(b / 64) >> (b % 64)) & 1 == 1;
    let half = bit(sh - 1);
    let below = {
        let b = sh - 1;
        let w = b / 64;
        (0..w).any(|i| limb(i) != 0) || limb(w) & ((1u64 << (b % 64)) - 1) != 0
    };
    let (w, o) = (sh / 64, (sh % 64) as u32);
    let part = |i: u64| {
        if o == 0 {
            limb(i)
        } else {
            (limb(i) >> o) | (limb(i + 1) << (64 - o))
        }
    };
    let mut r = u128::from(part(w)) | u128::from(part(w + 1)) << 64;
    if half && (below || r & 1 == 1) {
        r = r.checked_add(1)?;
    }
    Some(r)
}

/// mi·2^ex (mi ≥ 0) to the nearest integer, ties to even (as mpfr_get_z at
/// RNDN), in place: cheaper than mpfr_get_z.
fn round_shift(mi: &mut rug::Integer, ex: i32) {
    if ex >= 0 {
        *mi <<= ex as u32;
    } else {
        let sh = ex.unsigned_abs();
        let half = mi.get_bit(sh - 1);
        let below = mi.find_one(0).is_some_and(|b| b + 1 < sh);
        *mi >>= sh;
        if half && (below || mi.get_bit(0)) {
            *mi += 1u32;
        }
    }
}

/// The decimal digits of `u` appended to `buf` (u64 arithmetic: the
/// formatting of a `u128` divides in software digit by digit).
fn push_u128(buf: &mut Vec<u8>, u: u128) {
    const E19: u128 = 10_000_000_000_000_000_000;
    if u < E19 {
        push_u64(buf, u as u64, 1);
    } else if u < E19 * E19 {
        push_u64(buf, (u / E19) as u64, 1);
        push_u64(buf, (u % E19) as u64, 19);
    } else {
        buf.extend_from_slice(u.to_string().as_bytes());
    }
}

/// The decimal digits of `v`, at least `width` of them (leading zeros).
fn push_u64(buf: &mut Vec<u8>, mut v: u64, width: usize) {
    // two digits a step from a table of 00..99
    const PAIRS: &[u8; 200] = b"0001020304050607080910111213141516171819\
2021222324252627282930313233343536373839\
4041424344454647484950515253545556575859\
6061626364656667686970717273747576777879\
8081828384858687888990919293949596979899";
    let mut tmp = [b'0'; 20];
    let mut i = tmp.len();
    while v >= 100 {
        let k = (v % 100) as usize * 2;
        v /= 100;
        i -= 2;
        tmp[i..i + 2].copy_from_slice(&PAIRS[k..k + 2]);
    }
    if v >= 10 {
        let k = v as usize * 2;
        i -= 2;
        tmp[i..i + 2].copy_from_slice(&PAIRS[k..k + 2]);
    } else if v > 0 {
        i -= 1;
        tmp[i] = b'0' + v as u8;
    }
    let start = i.min(tmp.len() - width.clamp(1, 20));
    buf.extend_from_slice(&tmp[start..]);
}

/// Plain text of ±0.d·10^e: positional when −7 ≤ e ≤ 21 and the integer
/// part has no more digits than `d` (so that every digit printed is one of
/// `d`, never a padding zero: 100 to 1 digit is `1e2`), else `d.ddde±x`.
pub fn render(neg: bool, d: &str, e: i64) -> String {
    let n = d.len() as i64;
    let mut out = String::with_capacity(d.len() + 10);
    if neg {
        out.push('-');
    }
    let zeros = |out: &mut String, k: i64| out.extend(std::iter::repeat_n('0', k.max(0) as usize));
    if (-6..=21).contains(&e) && e <= n {
        if e <= 0 {
            out.push_str("0.");
            zeros(&mut out, -e);
            out.push_str(d);
        } else if e == n {
            out.push_str(d);
        } else {
            let (a, b) = d.split_at(e as usize);
            out.push_str(a);
            out.push('.');
            out.push_str(b);
        }
    } else {
        let (a, b) = d.split_at(1);
        out.push_str(a);
        if !b.is_empty() {
            out.push('.');
            out.push_str(b);
        }
        use std::fmt::Write;
        let _ = write!(out, "e{}", e - 1);
    }
    out
}

/// `x` to `digits` significant digits as text, rounded in the direction
/// `round` ("0" for zero).
pub fn to_sig_dir(x: &Float, digits: u32, round: Round) -> String {
    match round_sig_dir(x, digits, round) {
        Some((neg, d, e)) => render(neg, &d, e),
        None => "0".to_string(),
    }
}

/// `x` to `digits` significant digits as text ("0" for zero).
pub fn to_sig(x: &Float, digits: u32) -> String {
    match round_sig(x, digits) {
        Some((neg, d, e)) => render(neg, &d, e),
        None => "0".to_string(),
    }
}

/// A short (2-digit) rendering of a non-negative upper bound, e.g.
/// `2.2e-41` for 2.13e-41: rounded up, so that the bound printed is still a
/// bound (|err| <= the text).
pub fn short(x: &Float) -> String {
    short_dir(x, Round::Up)
}

/// A short (2-digit) rendering of a non-negative lower bound, rounded down
/// (the text <= the value).
pub fn short_down(x: &Float) -> String {
    short_dir(x, Round::Down)
}

/// A short (2-digit) rendering of a number that is not a bound (a
/// parameter, a ratio, quoted in a message), rounded to nearest.
pub fn short_near(x: &Float) -> String {
    short_dir(x, Round::Nearest)
}

fn short_dir(x: &Float, round: Round) -> String {
    // a bound that is not finite is no bound: said so, never "0"
    if x.is_infinite() {
        return if x.is_sign_negative() { "-inf" } else { "inf" }.to_string();
    }
    if x.is_nan() {
        return "nan".to_string();
    }
    match round_sig_dir(x, 2, round) {
        Some((_, d, e)) => format!("{}.{}e{}", &d[..1], &d[1..], e - 1),
        None => "0".to_string(),
    }
}

/// An end `x` known to within `err`, quoted toward the start: the digits
/// its error leaves and the precision carries (a margin of 8 bits; 3 to
/// 40), from the end of its interval nearer the start, rounded toward 0
/// (times and angles grow away from 0 along the motion, a fall to the left
/// in negative angles): a value refused as past it reads as past it (to
/// nearest at 12 or 17 digits it could read as after it, its last digit
/// wrong).
pub fn toward_start(x: &Float, err: &Float) -> String {
    let p = x.prec();
    let carried = ((f64::from(p) - 8.0) * std::f64::consts::LOG10_2).floor() as i64;
    let digits = if err.is_zero() || x.is_zero() {
        carried
    } else {
        let rel = Float::with_val(p, x.abs_ref()) / err;
        (rel.log10().to_f64().floor() as i64).min(carried)
    }
    .clamp(3, 40) as u32;
    let mut near = Float::with_val(p, x.abs_ref()) - err;
    if near.is_sign_negative() {
        near = Float::new(p);
    }
    if x.is_sign_negative() {
        near = -near;
    }
    to_sig_dir(&near, digits, rug::float::Round::Zero)
}

/// A value computed at its own working precision, for a message: the
/// significant digits that precision carries with a margin for the
/// integration's error (40 bits), between 3 and 17; messages print it after
/// "≈" (a message never prints digits the computation cannot hold).
pub fn approx_text(x: &Float) -> String {
    let digits = ((f64::from(x.prec()) - 40.0) * std::f64::consts::LOG10_2)
        .floor()
        .clamp(3.0, 17.0) as u32;
    to_sig(x, digits)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The machine-integer path rounds m·10^k·2^bx as the general one does,
    /// bit for bit, wherever it answers: random significands of 1–4 limbs
    /// (dense, and sparse so that the dropped bits are often exactly half
    /// or zero: the ties), every k it takes, shifts either way.
    #[test]
    fn the_machine_integer_scaling_is_the_general_one() {
        let mut next = crate::numeric::xorshift(0x9e37_79b9_7f4a_7c15);
        let mut answered = 0;
        let mut ties = 0;
        for case in 0..40_000 {
            let n = 1 + (next() % 4) as usize;
            let mut m: Vec<u64> = (0..n)
                .map(|_| {
                    let x = next();
                    if case % 2 == 0 {
                        x
                    } else {
                        // sparse: one or two bits
                        (1u64 << (x % 64)) | if x & 1 == 0 { 1 << ((x >> 8) % 64) } else { 0 }
                    }
                })
                .collect();
            if m[n - 1] == 0 {
                m[n - 1] = 1;
            }
            let k = (next() % 39) as i64;
            let mut mi = rug::Integer::from_digits(&m, rug::integer::Order::Lsf);
            mi *= rug::Integer::from(rug::Integer::u_pow_u(10, k as u32));
            let bx = if case % 4 == 1 {
                // the lowest set bit is the half: a tie
                -(mi.find_one(0).unwrap_or(0) as i32 + 1)
            } else {
                (next() % 460) as i32 - 400
            };
            let exact_half = bx < 0 && {
                let sh = bx.unsigned_abs();
                mi.get_bit(sh - 1) && mi.find_one(0) == Some(sh - 1)
            };
            round_shift(&mut mi, bx);
            match scaled_u128(&m, k, bx) {
                Some(u) => {
                    answered += 1;
                    ties += usize::from(exact_half);
                    assert_eq!(rug::Integer::from(u), mi, "m {m:?} k {k} bx {bx}");
                }
                None => assert!(
                    mi.significant_bits() >= 128,
                    "declined m {m:?} k {k} bx {bx}"
                ),
            }
        }
        assert!(
            answered > 10_000 && ties > 100,
            "{answered} answered, {ties} ties"
        );
    }

    /// approx_sig's digits are within one unit of the last digit of the
    /// correctly rounded ones (`round_sig`), over magnitudes and digit counts
    /// on both sides of its 64- and 128-bit digit conversions.
    #[test]
    fn approximate_digits_within_one_unit() {
        use rug::{Integer, Rational};
        let p = 240;
        let value = |(neg, d, e): (bool, String, i64)| {
            // ±0.d·10^e exactly
            let n = d.len() as i64;
            let mut r = Rational::from(d.parse::<Integer>().unwrap());
            let k = e - n;
            let pow = Rational::from(Integer::from(Integer::u_pow_u(10, k.unsigned_abs() as u32)));
            r = if k >= 0 { r * pow } else { r / pow };
            if neg {
                -r
            } else {
                r
            }
        };
        let mut x = Float::with_val(p, 2u32).sqrt() / 1000u32;
        for i in 0..120u32 {
            // magnitudes 1e-3 … 1e12 and both signs
            x *= Float::with_val(p, 1.37f64);
            let v = if i % 2 == 0 { x.clone() } else { -x.clone() };
            for d in [1u32, 4, 18, 19, 20, 30, 37, 38, 39, 45, 60] {
                let exact = round_sig(&v, d).unwrap();
                let approx = approx_sig(&v, d).unwrap();
                assert_eq!(approx.1.len(), d as usize);
                let unit = {
                    let e = exact.2.max(approx.2) - d as i64;
                    let pow = Rational::from(Integer::from(Integer::u_pow_u(
                        10,
                        e.unsigned_abs() as u32,
                    )));
                    if e >= 0 {
                        pow
                    } else {
                        Rational::from(1) / pow
                    }
                };
                let gap = (value(exact) - value(approx.clone())).abs();
                assert!(gap <= unit, "x = {v}, {d} digits: {approx:?}");
            }
        }
    }

    /// Where the scaling is by an integer power of ten (10^0 … 10^400) the
    /// digits are exact: the correctly rounded ones, ties to even included,
    /// from 1e-300 to 1e30.
    #[test]
    fn exactly_scaled_digits_are_correctly_rounded() {
        let p = 200;
        let mut vals = vec![
            Float::with_val(p, 0.125),
            Float::with_val(p, 0.375),
            Float::with_val(p, 2.5),
            Float::with_val(p, 1e30),
        ];
        let mut x = Float::with_val(p, 3u32).sqrt() * Float::with_val(p, 1e-300);
        while x < 1e30 {
            vals.push(x.clone());
            vals.push(-x.clone());
            x *= Float::with_val(p, 7.7e4);
        }
        for v in &vals {
            for d in [1u32, 2, 17, 30, 33, 45] {
                let e = round_sig(v, d).unwrap();
                if d as i64 - e.2 > POW10_INT_MAX || (d as i64) < e.2 {
                    continue;
                }
                assert_eq!(approx_sig(v, d).unwrap(), e, "{v} at {d} digits");
            }
        }
    }

    /// The table-driven integer digits against the standard formatting, at
    /// every length 1–39 and around the 10^19 split and powers of ten.
    #[test]
    fn integer_digits_as_the_standard_formatting() {
        let mut vals: Vec<u128> = vec![0, 1, 9, 10, 99, 100, 101, u64::MAX as u128, u128::MAX];
        let mut x: u128 = 7;
        for _ in 0..39 {
            vals.extend([x, x.saturating_sub(1), x.saturating_add(1)]);
            x = x.saturating_mul(10).saturating_add(3);
        }
        let mut p: u128 = 1;
        for _ in 0..38 {
            p *= 10;
            vals.extend([p - 1, p, p + 1]);
        }
        for v in vals {
            let mut buf = Vec::new();
            push_u128(&mut buf, v);
            assert_eq!(String::from_utf8(buf).unwrap(), v.to_string(), "{v}");
            if let Ok(w) = u64::try_from(v) {
                let mut buf = Vec::new();
                push_u64(&mut buf, w, 20);
                assert_eq!(String::from_utf8(buf).unwrap(), format!("{w:020}"), "{w}");
            }
        }
    }

    #[test]
    fn rounding_and_layout() {
        let p = 200;
        let pi = Float::with_val(p, rug::float::Constant::Pi);
        assert_eq!(to_sig(&pi, 5), "3.1416");
        // no padding zero is printed as if it were a digit
        assert_eq!(to_sig(&Float::with_val(p, &pi * 1000u32), 3), "3.14e3");
        assert_eq!(to_sig(&Float::with_val(p, &pi * 1000u32), 4), "3142");
        assert_eq!(to_sig(&Float::with_val(p, 100), 1), "1e2");
        assert_eq!(
            to_sig(&Float::with_val(p, 14383358069470040.4f64), 15),
            "1.43833580694700e16"
        );
        assert_eq!(to_sig(&Float::with_val(p, &pi / 100000u32), 3), "0.0000314");
        assert_eq!(to_sig(&Float::with_val(p, &pi / 1e12), 3), "3.14e-12");
        assert_eq!(to_sig(&Float::with_val(p, -0.5), 2), "-0.50");
        assert_eq!(to_sig(&Float::with_val(p, 9.9996), 4), "10.00");
        assert_eq!(to_sig(&Float::with_val(p, 1e30), 2), "1.0e30");
        // bounds: an upper bound rounds up, a lower bound down, an exact
        // two-digit value stays
        assert_eq!(short(&Float::with_val(p, 2.13e-41)), "2.2e-41");
        assert_eq!(short_down(&Float::with_val(p, 2.17e-41)), "2.1e-41");
        assert_eq!(short(&Float::with_val(p, 6.82e-34)), "6.9e-34");
        assert_eq!(short(&Float::with_val(p, 9.91e-3)), "1.0e-2");
        assert_eq!(short(&Float::with_val(p, 0.25)), "2.5e-1");
        assert_eq!(short_down(&Float::with_val(p, 0.25)), "2.5e-1");
        // no bound is not a zero bound
        assert_eq!(short(&Float::with_val(p, f64::INFINITY)), "inf");
        assert_eq!(short(&Float::new(p)), "0");
    }
}
