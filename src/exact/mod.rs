//! Exact input numbers: decimal strings, fractions and rational multiples of π.
//!
//! Parameters are parsed straight into [`rug::Rational`] and rounded to a
//! working precision only when a computation asks for them, never through
//! `f64` (`0.3` is the rational 3/10, not the nearest double).

mod rounded;

pub use rounded::{RoundedTimes, TableTimes};

use crate::error::{Error, Result};
use rug::{Float, Integer, Rational};
use std::fmt;

/// An exact real number `coef` or `coef·π`.
///
/// A number parsed from text keeps that text: messages quote it as it was
/// given (`1e3`, not `1000`), bounded in length ([`fmt::Display`]); records
/// use [`Exact::canonical`]. Two numbers are equal when their values are,
/// whatever their texts.
#[derive(Debug, Clone)]
pub struct Exact {
    /// The rational coefficient.
    pub coef: Rational,
    /// Whether the number is `coef·π`.
    pub times_pi: bool,
    /// The text it was parsed from (trimmed), if any.
    given: Option<Box<str>>,
}

impl PartialEq for Exact {
    fn eq(&self, other: &Self) -> bool {
        self.coef == other.coef && (self.times_pi == other.times_pi || self.coef == 0)
    }
}

impl Exact {
    /// The rational `q`.
    pub fn rational(q: Rational) -> Self {
        Exact {
            coef: q,
            times_pi: false,
            given: None,
        }
    }

    /// Zero.
    pub fn zero() -> Self {
        Self::rational(Rational::new())
    }

    /// Parses `name`'s value `text`. Accepted forms: `3`, `-0.25`, `1e-3`,
    /// `2.5E2`, `1/3`, `0.5/3`, and when `allow_pi`: `pi`, `pi/6`, `2pi/3`,
    /// `2*pi/3`, `0.1*pi`.
    pub fn parse(name: &str, text: &str, allow_pi: bool) -> Result<Self> {
        let bad = || {
            if exponent_out_of_range(text) {
                return Error::invalid(
                    name,
                    text,
                    format!("the exponent must be within ±{MAX_EXPONENT}"),
                );
            }
            let forms = if allow_pi {
                "an exact number such as 0.25, 1/3, 1e-3, pi/6 or 2*pi/3"
            } else {
                "an exact number such as 0.25, 1/3 or 1e-3"
            };
            Error::invalid(name, text, format!("expected {forms}"))
        };
        let trimmed = text.trim();
        // whitespace inside is dropped where it stands beside an operator
        // (`1 / 3`, `2 * pi / 3`); inside a number it is refused: `1 000`
        // (a thousands separator or two numbers?), `0. 3`, `1e 3`
        let s: std::borrow::Cow<str> = if trimmed.contains(char::is_whitespace) {
            // one pass: each run of spaces (never at the ends, trimmed) with
            // the characters just before and after it
            let operator = |x: char| x == '/' || x == '*';
            let mut kept = String::with_capacity(trimmed.len());
            let mut last = ' ';
            let mut in_run = false;
            for x in trimmed.chars() {
                if x.is_whitespace() {
                    in_run = true;
                    continue;
                }
                if in_run && !operator(last) && !operator(x) {
                    return Err(Error::invalid(
                        name,
                        text,
                        "a space may stand around the operators / and * and the whole, not \
                         inside a number",
                    ));
                }
                in_run = false;
                last = x;
                kept.push(x);
            }
            kept.into()
        } else {
            trimmed.into()
        };
        if s.is_empty() {
            return Err(bad());
        }
        // a rational (every time of a table) is parsed as it is: its
        // exponent may be `e` or `E`, and no other letter is valid in it
        if !s.bytes().any(|c| c.eq_ignore_ascii_case(&b'p')) {
            let mut e = Exact::rational(parse_rational(&s).ok_or_else(bad)?);
            e.given = Some(trimmed.into());
            return Ok(e);
        }
        let lower = s.to_ascii_lowercase();
        if let Some(pos) = lower.find("pi") {
            if !allow_pi {
                return Err(bad());
            }
            let before = &lower[..pos];
            let after = &lower[pos + 2..];
            let before = before.strip_suffix('*').unwrap_or(before);
            let coef = match before {
                "" | "+" => Rational::from(1),
                "-" => Rational::from(-1),
                b => parse_rational(b).ok_or_else(bad)?,
            };
            let coef = if after.is_empty() {
                coef
            } else {
                let d = after.strip_prefix('/').ok_or_else(bad)?;
                let d = parse_decimal(d).ok_or_else(bad)?;
                if d == 0 {
                    return Err(bad());
                }
                coef / d
            };
            return Ok(Exact {
                coef,
                times_pi: true,
                given: Some(text.trim().into()),
            });
        }
        let mut e = Exact::rational(parse_rational(&lower).ok_or_else(bad)?);
        e.given = Some(text.trim().into());
        Ok(e)
    }

    /// The text the number was parsed from, if it was.
    pub fn given(&self) -> Option<&str> {
        self.given.as_deref()
    }

    /// Canonical exact text, whatever the number was parsed from: an exact
    /// decimal when the rational has one (`0.3`; `1e-30` in scientific
    /// form when that is much shorter), otherwise a fraction (`1/3`); `·pi`
    /// forms as `2/3*pi`. For records (a model's echo); messages quote the
    /// given text ([`fmt::Display`]).
    pub fn canonical(&self) -> String {
        let q = rational_text(&self.coef);
        if self.times_pi {
            match q.as_str() {
                "0" => "0".into(),
                "1" => "pi".into(),
                "-1" => "-pi".into(),
                _ => format!("{q}*pi"),
            }
        } else {
            q
        }
    }

    /// The value rounded to nearest at `prec` bits.
    pub fn to_float(&self, prec: u32) -> Float {
        if self.times_pi {
            let pi = Float::with_val(prec + 8, rug::float::Constant::Pi);
            Float::with_val(prec, pi * &self.coef)
        } else {
            word_quotient(&self.coef, prec).unwrap_or_else(|| Float::with_val(prec, &self.coef))
        }
    }

    /// The order of two numbers: exact for rationals; a multiple of π is
    /// compared after rounding to 256 bits.
    pub fn cmp_value(&self, other: &Exact) -> std::cmp::Ordering {
        if !self.times_pi && !other.times_pi {
            self.coef.cmp(&other.coef)
        } else {
            let (a, b) = (self.to_float(256), other.to_float(256));
            a.partial_cmp(&b).unwrap_or(std::cmp::Ordering::Equal)
        }
    }

    /// Whether the number is at most `x`: decided exactly for a rational
    /// (no rounding to a precision first); a multiple of π (never a time)
    /// is rounded to 64 bits more than `x` carries first.
    pub fn le_float(&self, x: &Float) -> bool {
        if self.times_pi {
            self.to_float(x.prec() + 64) <= *x
        } else {
            *x >= self.coef
        }
    }

    /// The exact decimal text of a rational time or angle that is a
    /// terminating decimal (echoed as given, not rounded).
    ///
    /// A number given as a plain decimal (`0.0125`, `-3e-4`: every table's
    /// times) is written from the digits of its text, the same text as from
    /// its rational but with no big-integer arithmetic.
    pub fn terminating_text(&self) -> Option<String> {
        if self.times_pi {
            None
        } else if let Some(text) = self.given.as_deref().and_then(decimal_text_of_given) {
            Some(text)
        } else {
            terminating_text(&self.coef)
        }
    }

    /// The rational value, if the number is rational.
    pub fn as_rational(&self) -> Option<&Rational> {
        if self.times_pi && self.coef != 0 {
            None
        } else {
            Some(&self.coef)
        }
    }

    /// Whether the number is exactly zero.
    pub fn is_zero(&self) -> bool {
        self.coef == 0
    }

    /// Sign: -1, 0 or 1.
    pub fn signum(&self) -> i32 {
        self.coef.cmp0() as i32
    }

    /// The negated number.
    pub fn neg(&self) -> Self {
        Exact {
            coef: Rational::from(-&self.coef),
            times_pi: self.times_pi,
            given: None,
        }
    }

    /// A decimal approximation good to 17 digits, for messages and plots only.
    pub fn to_f64(&self) -> f64 {
        self.to_float(80).to_f64()
    }
}

impl fmt::Display for Exact {
    /// For messages: the text the number was given as (`1e3`, `pi/6`), else
    /// its [canonical](Exact::canonical) text; a text longer than
    /// [`crate::error::ECHO_MAX`] characters is shortened (its start, its
    /// length), so that a message stays one readable line.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = match &self.given {
            Some(g) => crate::error::shorten(g),
            None => crate::error::shorten(&self.canonical()),
        };
        f.write_str(&text)
    }
}

/// n/d rounded to nearest at `prec` bits where n fits in `prec` bits and
/// d = 2^a·o with o odd below 2^64 (a decimal time's 10^k up to k = 27, any
/// dyadic): n exactly, one correctly rounded division by the machine word o,
/// an exact scaling by 2^−a — the bits of MPFR's rounding of the rational
/// (`mpfr_set_q`), without its long division. `None` otherwise.
fn word_quotient(q: &Rational, prec: u32) -> Option<Float> {
    let (n, twos) = word_denominator(q, prec)?;
    let odd = Integer::from(q.denom() >> twos).to_u64()?;
    let mut f = Float::with_val(prec, n);
    f /= odd;
    f >>= twos;
    Some(f)
}

/// Whether [`word_quotient`] applies to `q` at `prec` bits: its numerator
/// and the power of 2 in its denominator.
pub(crate) fn word_denominator(q: &Rational, prec: u32) -> Option<(&Integer, u32)> {
    let (n, d) = (q.numer(), q.denom());
    if n.significant_bits() > prec {
        return None;
    }
    let twos = d.find_one(0)?;
    (d.significant_bits() - twos <= 64).then_some((n, twos))
}

/// Longest plain decimal text before [`rational_text`] switches to the
/// scientific form (when that is shorter).
const PLAIN_MAX: usize = 24;

/// (a, b, m) with d = 2^a·5^b·m and m prime to 10 (d > 0): the factors
/// counted by a shift and by divisions by 5^13 and 5 (a decimal time's
/// denominator 10^k costs a few machine divisions, where GMP's general
/// `remove` costs thousands of instructions); GMP's `remove` beyond 4096
/// bits, where one division per 5^13 would grow quadratically.
pub fn split_two_five(d: &Integer) -> (u32, u32, Integer) {
    const F13: u32 = 1_220_703_125; // 5^13
    let twos = d.find_one(0).unwrap_or(0);
    let mut m = Integer::from(d >> twos);
    if m.significant_bits() > 4096 {
        // a denominator of thousands of digits (a long decimal input):
        // GMP's remove, by squared powers, not a division per 5^13
        let fives = m.remove_factor_mut(&Integer::from(5));
        return (twos, fives, m);
    }
    let mut fives = 0;
    while m != 0 && m.is_divisible_u(F13) {
        m.div_exact_u_mut(F13);
        fives += 13;
    }
    while m != 0 && m.is_divisible_u(5) {
        m.div_exact_u_mut(5);
        fives += 1;
    }
    (twos, fives, m)
}

/// The exact decimal text of `q` when it is a terminating decimal.
pub fn terminating_text(q: &Rational) -> Option<String> {
    let (twos, fives, den) = split_two_five(q.denom());
    (den == 1).then(|| decimal_of(q, twos.max(fives)))
}

/// Exact decimal text of a rational when its denominator is 2^a 5^b, else
/// `p/q`. Plain (`0.05`, `1000`) unless that is longer than 24 characters
/// and the scientific form is shorter (`1e-30`, `2.5e100`), so that a value
/// such as 10^-100000 is written in a few characters, still exactly.
pub fn rational_text(q: &Rational) -> String {
    let (twos, fives, den) = split_two_five(q.denom());
    if den != 1 {
        return format!(
            "{}/{}",
            decimal_text(q.numer(), 0),
            decimal_text(q.denom(), 0)
        );
    }
    decimal_of(q, twos.max(fives))
}

/// q·10^k (an integer) as the exact text of q.
fn decimal_of(q: &Rational, k: u32) -> String {
    let scaled = if k == 0 {
        q.numer().clone()
    } else {
        (q.numer() * Integer::from(Integer::u_pow_u(10, k))) / q.denom()
    };
    decimal_text(&scaled, k as i64)
}

/// Exact text of `n`·10^-k: plain, or scientific when the plain text is
/// longer than [`PLAIN_MAX`] characters and the scientific one shorter.
fn decimal_text(n: &Integer, k: i64) -> String {
    let all = Integer::from(n.abs_ref()).to_string();
    if all == "0" {
        return "0".into();
    }
    // n = m·10^z with m free of trailing zeros: the value is m·10^e
    let m = all.trim_end_matches('0');
    let e = (all.len() - m.len()) as i64 - k;
    digits_text(*n < 0, m, e)
}

/// The exact text of the decimal `text` (what [`decimal_digits`] reads),
/// from its digits: the same text as [`decimal_text`] gives its value.
/// `None` for any other form.
fn decimal_text_of_given(text: &str) -> Option<String> {
    let (neg, m, e) = decimal_digits(text)?;
    if m.is_empty() {
        return Some("0".into());
    }
    Some(digits_text(neg, &m, e))
}

/// Largest |exponent| of a decimal's `e` part.
const MAX_EXPONENT: u64 = 100_000;

/// Whether some number of `text` (a decimal, or one side of a fraction)
/// has an integer exponent beyond ±[`MAX_EXPONENT`].
fn exponent_out_of_range(text: &str) -> bool {
    text.split(['/', '*']).any(|part| {
        let part = part.trim();
        part.rfind(['e', 'E']).is_some_and(|i| {
            let x = part[i + 1..].trim_start_matches(['+', '-']);
            // digits only, and above the range (or too many for a u64)
            !x.is_empty()
                && x.bytes().all(|b| b.is_ascii_digit())
                && x.parse::<u64>().map_or(true, |v| v > MAX_EXPONENT)
        })
    })
}

/// A decimal ±m·10^e read from an optional sign, digits with an optional
/// point and an optional exponent (|exponent| ≤ [`MAX_EXPONENT`]): its sign, m its
/// digits without leading or trailing zeros (empty for zero), e. `None` for
/// any other form.
fn decimal_digits(s: &str) -> Option<(bool, String, i64)> {
    let (neg, s) = match s.as_bytes().first()? {
        b'-' => (true, &s[1..]),
        b'+' => (false, &s[1..]),
        _ => (false, s),
    };
    let (mant, exp) = match s.find(['e', 'E']) {
        Some(i) => {
            let e: i64 = s[i + 1..].parse().ok()?;
            (&s[..i], e)
        }
        None => (s, 0),
    };
    if exp.unsigned_abs() > MAX_EXPONENT {
        return None;
    }
    let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
    if (int.is_empty() && frac.is_empty())
        || !int.bytes().chain(frac.bytes()).all(|b| b.is_ascii_digit())
    {
        return None;
    }
    // trailing zeros move to the exponent; leading ones are dropped
    let mut digits = String::with_capacity(int.len() + frac.len());
    digits.push_str(int);
    digits.push_str(frac);
    let kept = digits.trim_end_matches('0').len();
    let e = exp - frac.len() as i64 + (digits.len() - kept) as i64;
    digits.truncate(kept);
    let lead = digits.len() - digits.trim_start_matches('0').len();
    digits.drain(..lead);
    Some((neg, digits, e))
}

/// The exact text of ±m·10^e (m: decimal digits, neither leading nor
/// trailing zeros): plain, or scientific when the plain text is longer than
/// [`PLAIN_MAX`] characters and the scientific one shorter.
fn digits_text(neg: bool, m: &str, e: i64) -> String {
    let sign = if neg { "-" } else { "" };
    let d = m.len() as i64;
    let plain_len = if e >= 0 {
        d + e
    } else if d > -e {
        d + 1
    } else {
        1 - e
    };
    let exp = e + d - 1;
    // the scientific text's length: the digits, a point after the first
    // of several, `e`, the exponent
    let exp_len = exp.unsigned_abs().checked_ilog10().unwrap_or(0) as i64 + 1 + i64::from(exp < 0);
    let sci_len = d + i64::from(d > 1) + 1 + exp_len;
    if plain_len as usize > PLAIN_MAX && sci_len < plain_len {
        return if d == 1 {
            format!("{sign}{m}e{exp}")
        } else {
            format!("{sign}{}.{}e{exp}", &m[..1], &m[1..])
        };
    }
    let mut out = String::with_capacity(plain_len as usize + 2);
    out.push_str(sign);
    if e >= 0 {
        out.push_str(m);
        out.extend(std::iter::repeat_n('0', e as usize));
    } else if d > -e {
        let (int, frac) = m.split_at((d + e) as usize);
        out.push_str(int);
        out.push('.');
        out.push_str(frac);
    } else {
        out.push_str("0.");
        out.extend(std::iter::repeat_n('0', (-e - d) as usize));
        out.push_str(m);
    }
    out
}

/// Parses `a` or `a/b` with `a`, `b` decimals.
fn parse_rational(s: &str) -> Option<Rational> {
    match s.split_once('/') {
        Some((a, b)) => {
            let a = parse_decimal(a)?;
            let b = parse_decimal(b)?;
            if b == 0 {
                None
            } else {
                Some(a / b)
            }
        }
        None => parse_decimal(s),
    }
}

/// Parses a decimal number with optional sign, fraction and exponent exactly.
fn parse_decimal(s: &str) -> Option<Rational> {
    let (neg, digits, e) = decimal_digits(s)?;
    if digits.is_empty() {
        return Some(Rational::new());
    }
    // up to 38 digits (every time of a table) in two machine words, longer
    // by GMP's conversion
    let mut n = if digits.len() <= 38 {
        let word = |d: &[u8]| d.iter().fold(0u64, |a, &c| a * 10 + u64::from(c - b'0'));
        let b = digits.as_bytes();
        let split = b.len().saturating_sub(19);
        let (hi, lo) = b.split_at(split);
        Integer::from(word(hi)) * 10_000_000_000_000_000_000u64 + word(lo)
    } else {
        Integer::from_str_radix(&digits, 10).ok()?
    };
    if neg {
        n = -n;
    }
    if e >= 0 {
        return Some(Rational::from(
            n * Integer::from(Integer::u_pow_u(10, e as u32)),
        ));
    }
    // n / 10^k: n has no factor 10, so it shares 2s or 5s with 10^k, not
    // both; taken out here, the fraction is in lowest terms without GMP's
    // general gcd
    let k = (-e) as u32;
    let (mut twos, mut fives) = (k, k);
    let n_twos = n.find_one(0).unwrap_or(0);
    if n_twos > 0 {
        let c = n_twos.min(k);
        n >>= c;
        twos -= c;
    } else {
        while fives > 0 && n.is_divisible_u(5) {
            n.div_exact_u_mut(5);
            fives -= 1;
        }
    }
    let den = Integer::from(Integer::u_pow_u(5, fives)) << twos;
    // SAFETY: n and den = 2^twos·5^fives share no factor (every common 2
    // or 5 was divided out above, and den has no other prime) and den > 0
    Some(unsafe { Rational::from_canonical(n, den) })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A decimal's value the plain way (the digits as one integer over a
    /// power of ten, GMP's gcd), against which the parser's shortcut is
    /// checked.
    fn decimal_value(text: &str) -> Rational {
        let (neg, t) = match text.as_bytes()[0] {
            b'-' => (true, &text[1..]),
            b'+' => (false, &text[1..]),
            _ => (false, text),
        };
        let (mant, exp) = match t.find(['e', 'E']) {
            Some(i) => (&t[..i], t[i + 1..].parse::<i64>().unwrap()),
            None => (t, 0),
        };
        let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
        let digits = format!("0{int}{frac}");
        let n = Integer::from_str_radix(&digits, 10).unwrap();
        let e = exp - frac.len() as i64;
        let ten = |k: i64| Integer::from(Integer::u_pow_u(10, k as u32));
        let q = if e >= 0 {
            Rational::from(n * ten(e))
        } else {
            Rational::from((n, ten(-e)))
        };
        if neg {
            -q
        } else {
            q
        }
    }

    /// Decimal texts, given and generated: the parser's value is the text's
    /// value in lowest terms, and the text written from the given digits is
    /// the text of the value (the big-integer route).
    #[test]
    fn a_given_decimal_is_parsed_and_written_as_its_value() {
        let mut cases: Vec<String> = [
            "0",
            "-0",
            "+0.000",
            "0.0125",
            "-3e-4",
            "1E3",
            "1e+3",
            "000120.5000",
            ".5",
            "5.",
            "-.25e-30",
            "1e-24",
            "1e-23",
            "1e-30",
            "2.5e100",
            "-2.50e100",
            "12345678901234567890123456789e-20",
            "123456789012345678901234",
            "1234567890123456789012345",
            "0.004876257089126093852633724",
            "4.871380832036967758781090276",
            "7e-100000",
            "640e-3",
            "0.5e1",
            "250",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        // generated: random digits (runs of zeros and of 2s and 5s among
        // them), a point anywhere or none, an exponent or none, a sign
        let mut bits = crate::numeric::xorshift(0x9e37_79b9_7f4a_7c15);
        let mut next = |m: u64| bits() % m;
        for _ in 0..3000 {
            let len = 1 + next(40) as usize;
            let pool = [b"0123456789".as_slice(), b"00000", b"2580", b"5"];
            let pool = pool[next(4) as usize];
            let mut d: String = (0..len)
                .map(|_| pool[next(pool.len() as u64) as usize] as char)
                .collect();
            match next(3) {
                0 => {}
                _ => d.insert(next(len as u64 + 1) as usize, '.'),
            }
            if d == "." {
                d = "0".into();
            }
            if next(2) == 0 {
                d = format!("{d}e{}", next(81) as i64 - 40);
            }
            let sign = ["", "-", "+"][next(3) as usize];
            cases.push(format!("{sign}{d}"));
        }
        for c in &cases {
            let e = Exact::parse("t", c, false).unwrap();
            let want = decimal_value(c);
            assert_eq!(e.coef, want, "{c}");
            // lowest terms: the parser builds the fraction without the gcd
            let (n, d) = (e.coef.numer(), e.coef.denom());
            assert!(*d > 0 && Integer::from(n.gcd_ref(d)) == 1, "{c}: {n}/{d}");
            assert_eq!(decimal_text_of_given(c), terminating_text(&want), "{c}");
            assert_eq!(e.terminating_text(), terminating_text(&want), "{c}");
        }
        // the plain text while its length as counted (1 − e for 0.0…0d,
        // one short of the text) is at most 24, beyond that the scientific
        // one where it is shorter (written out by hand)
        for (c, want) in [
            ("1e-24", "1e-24"),
            ("1e-23", "0.00000000000000000000001"),
            ("-1e-23", "-0.00000000000000000000001"),
            ("-1e-24", "-1e-24"),
            ("1e-21", "0.000000000000000000001"),
            ("1234567890123456789012345", "1234567890123456789012345"),
            ("1e24", "1e24"),
            ("1e23", "100000000000000000000000"),
            ("12e-30", "1.2e-29"),
            ("123456789e-30", "1.23456789e-22"),
            (
                "4.871380832036967758781090276",
                "4.871380832036967758781090276",
            ),
            ("25e99", "2.5e100"),
            ("1e1000", "1e1000"),
        ] {
            assert_eq!(decimal_text_of_given(c).as_deref(), Some(want), "{c}");
        }
        // other forms are left to the rational route
        for c in ["1/4", "0.5/2", "1 000", "1e", "e3", "", "-", "1..2", "0x10"] {
            assert_eq!(decimal_text_of_given(c), None, "{c}");
        }
        let q = Exact::parse("t", "1/4", false).unwrap();
        assert_eq!(q.terminating_text().as_deref(), Some("0.25"));
    }

    #[test]
    fn compares_exactly_not_after_rounding() {
        // 1/3 lies strictly between its two 64-bit neighbours: exactly above
        // the one below, below the one above, whichever the rounding picks
        let third = Exact::parse("t", "1/3", false).unwrap();
        let down = Float::with_val_round(64, &third.coef, rug::float::Round::Down).0;
        let up = Float::with_val_round(64, &third.coef, rug::float::Round::Up).0;
        assert!(down < up);
        assert!(!third.le_float(&down));
        assert!(third.le_float(&up));
        let tenth = Exact::parse("t", "0.1", false).unwrap();
        assert_eq!(tenth.cmp_value(&third), std::cmp::Ordering::Less);
        assert_eq!(third.cmp_value(&third.clone()), std::cmp::Ordering::Equal);
        let pi_6 = Exact::parse("x", "pi/6", true).unwrap();
        // π/6 = 0.5236 against 1/2 and 11/20
        assert_eq!(
            pi_6.cmp_value(&Exact::parse("x", "1/2", true).unwrap()),
            std::cmp::Ordering::Greater
        );
        assert_eq!(
            pi_6.cmp_value(&Exact::parse("x", "11/20", true).unwrap()),
            std::cmp::Ordering::Less
        );
    }

    #[test]
    fn parses_exact_forms() {
        let p = |s| Exact::parse("x", s, true).unwrap();
        assert_eq!(p("0.3").coef, Rational::from((3, 10)));
        assert_eq!(p("-1/3").coef, Rational::from((-1, 3)));
        assert_eq!(p("1e-3").coef, Rational::from((1, 1000)));
        assert_eq!(p("2.5E2").coef, Rational::from(250));
        assert_eq!(p("0.5/3").coef, Rational::from((1, 6)));
        let q = p("2*pi/3");
        assert!(q.times_pi);
        assert_eq!(q.coef, Rational::from((2, 3)));
        assert_eq!(p("pi").coef, Rational::from(1));
        assert_eq!(p("-pi/6").coef, Rational::from((-1, 6)));
        // spaces around the operators and the whole
        assert_eq!(p(" 1 / 3 ").coef, Rational::from((1, 3)));
        let q = p("2 * pi / 3");
        assert!(q.times_pi && q.coef == Rational::from((2, 3)));
    }

    /// A space inside a number is refused, naming the rule: `1 000` is a
    /// thousands separator or two numbers (it was read as 1000), `0. 3` was
    /// read as 0.3, `1e 3` as 1000.
    #[test]
    fn a_space_inside_a_number_is_refused() {
        for s in [
            "1 000", "0. 3", "1e 3", "- 1", "0.3 0.4", "2 pi/3", "1/ 3 0",
        ] {
            let e = Exact::parse("m1", s, true).unwrap_err().to_string();
            assert!(e.contains("not inside a number"), "{s}: {e}");
        }
    }

    #[test]
    fn rejects_garbage() {
        for s in [
            "", "abc", "1/0", "nan", "inf", "1..2", "1e", "--1", "pi/0", "0x10",
        ] {
            assert!(Exact::parse("x", s, true).is_err(), "{s}");
        }
        assert!(Exact::parse("m1", "pi", false).is_err());
        // an exponent beyond the range is refused and named, not wrapped
        // around (i64::MIN read as 1 before)
        for s in [
            "1e-9223372036854775808",
            "1e9223372036854775807",
            "1e-100001",
            "2.5E100001",
            "1/1e-99999999999999999999999",
        ] {
            let e = Exact::parse("x", s, false).unwrap_err().to_string();
            assert!(e.contains("exponent must be within ±100000"), "{s}: {e}");
        }
        assert!(Exact::parse("x", "1e-100000", false).is_ok());
    }

    #[test]
    fn canonical_text() {
        let p = |s| Exact::parse("x", s, true).unwrap().canonical();
        assert_eq!(p("0.30"), "0.3");
        assert_eq!(p("1/3"), "1/3");
        assert_eq!(p("-0.05"), "-0.05");
        assert_eq!(p("9.81"), "9.81");
        assert_eq!(p("2pi/3"), "2/3*pi");
        assert_eq!(p("12"), "12");
    }

    #[test]
    fn given_text_is_quoted_and_canonical_text_is_short() {
        let e = Exact::parse("x", " 1e3 ", false).unwrap();
        assert_eq!(e.to_string(), "1e3");
        assert_eq!(e.canonical(), "1000");
        assert_eq!(e, Exact::rational(Rational::from(1000)));
        let c = |s| Exact::parse("x", s, true).unwrap().canonical();
        assert_eq!(c("1e-100000"), "1e-100000");
        assert_eq!(c("-2.50e100"), "-2.5e100");
        assert_eq!(c("1e-5000/3"), "1/3e5000");
        assert_eq!(c("1e-20"), "0.00000000000000000001");
        assert_eq!(c("1e-30"), "1e-30");
        assert_eq!(c("1.25e-3"), "0.00125");
        assert_eq!(c("123.5"), "123.5");
        assert_eq!(c("-0.5"), "-0.5");
        assert_eq!(c("0"), "0");
        assert_eq!(c("1e-4000*pi"), "1e-4000*pi");
        // a long given text is quoted shortened, its length noted
        let long = format!("0.{}", "1".repeat(5000));
        let q = Exact::parse("x", &long, false).unwrap().to_string();
        assert!(
            q.len() <= crate::error::ECHO_MAX && q.contains("5002 characters"),
            "{q}"
        );
    }

    #[test]
    fn exact_to_float() {
        let x = Exact::parse("x", "1/10", false).unwrap().to_float(200);
        let y = Float::with_val(200, 1) / 10u32;
        assert_eq!(x, y);
    }

    /// The quotient by a machine word gives MPFR's rounding of the rational
    /// bit for bit: decimals of up to 40 digits (denominators 10^k, some
    /// beyond a word), dyadics, odd denominators near 2^64, both signs, at
    /// precisions from 2 to 400 bits (numerators wider than the precision
    /// go to MPFR).
    #[test]
    fn a_word_quotient_is_mpfrs_rounding() {
        let mut next = crate::numeric::xorshift(0x5851_f42d_4c95_7f2d);
        let pow = |b: u32, e: u32| Integer::from(Integer::u_pow_u(b, e));
        for _ in 0..4000 {
            let n = Integer::from(next())
                * Integer::from(next() >> (next() % 64))
                * if next() % 2 == 0 { 1 } else { -1 };
            let d = match next() % 4 {
                0 => pow(10, (next() % 41) as u32),
                1 => pow(2, (next() % 300) as u32),
                2 => Integer::from(u64::MAX - (next() % 1000) * 2) << (next() % 70) as u32,
                _ => pow(5, (next() % 30) as u32) * pow(2, (next() % 10) as u32),
            };
            let q = Rational::from((n, d));
            for prec in [2, 53, 64, 100, 128, 171, 333, 400] {
                let want = Float::with_val(prec, &q);
                let e = Exact::rational(q.clone());
                let got = e.to_float(prec);
                assert_eq!(
                    (got.to_integer_exp(), got.is_sign_negative()),
                    (want.to_integer_exp(), want.is_sign_negative()),
                    "{q} at {prec} bits"
                );
                assert_eq!(got.prec(), prec);
            }
        }
    }

    /// The factors 2 and 5 of a denominator, counted by shifts and small
    /// divisions, against GMP's `remove`; and the exact text of terminating
    /// decimals only.
    #[test]
    fn twos_and_fives() {
        let pow = |b: u32, e: u32| Integer::from(Integer::u_pow_u(b, e));
        let cases = [
            Integer::from(1),
            Integer::from(2),
            Integer::from(5),
            Integer::from(7),
            pow(10, 25),
            pow(5, 12),
            pow(5, 13),
            pow(5, 26) * 3u32,
            pow(2, 70) * pow(5, 30) * 7u32,
            pow(2, 64) * pow(5, 39) * pow(3, 40),
            pow(10, 1000) * 11u32,
            pow(10, 5000),
            pow(5, 4000) * pow(3, 10),
        ];
        for d in cases {
            let mut r = d.clone();
            let twos = r.remove_factor_mut(&Integer::from(2));
            let fives = r.remove_factor_mut(&Integer::from(5));
            assert_eq!(split_two_five(&d), (twos, fives, r), "{d}");
        }
        // beyond 4096 bits the split is GMP's remove itself: held to the
        // exponents the cases are built from, not to that same call
        assert_eq!(
            split_two_five(&pow(10, 5000)),
            (5000, 5000, Integer::from(1))
        );
        assert_eq!(
            split_two_five(&(pow(5, 4000) * pow(3, 10))),
            (0, 4000, pow(3, 10))
        );
        assert_eq!(
            split_two_five(&(pow(2, 70) * pow(5, 30) * 7u32)),
            (70, 30, Integer::from(7))
        );
        let t = |s: &str| Exact::parse("t", s, true).unwrap().terminating_text();
        assert_eq!(
            t("0.0048762570891260938526337").as_deref(),
            Some("0.0048762570891260938526337")
        );
        assert_eq!(t("3/8").as_deref(), Some("0.375"));
        assert_eq!(t("-1e-30").as_deref(), Some("-1e-30"));
        assert_eq!(t("1/3"), None);
        assert_eq!(t("pi/2"), None);
    }
}
