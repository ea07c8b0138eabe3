//! Exact input numbers: decimal strings, fractions and rational multiples of π.
//!
//! Parameters are parsed straight into [`rug::Rational`] and rounded to a
//! working precision only when a computation asks for them, never through
//! `f64` (`0.3` is the rational 3/10, not the nearest double).

use crate::error::{Error, Result};
use rug::{Float, Integer, Rational};
use std::fmt;

/// An exact real number `coef` or `coef·π`.
#[derive(Debug, Clone, PartialEq)]
pub struct Exact {
    /// The rational coefficient.
    pub coef: Rational,
    /// Whether the number is `coef·π`.
    pub times_pi: bool,
}

impl Exact {
    /// The rational `q`.
    pub fn rational(q: Rational) -> Self {
        Exact {
            coef: q,
            times_pi: false,
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
            let forms = if allow_pi {
                "an exact number such as 0.25, 1/3, 1e-3, pi/6 or 2*pi/3"
            } else {
                "an exact number such as 0.25, 1/3 or 1e-3"
            };
            Error::invalid(name, text, format!("expected {forms}"))
        };
        let s: String = text.trim().chars().filter(|c| !c.is_whitespace()).collect();
        if s.is_empty() {
            return Err(bad());
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
            });
        }
        Ok(Exact::rational(parse_rational(&lower).ok_or_else(bad)?))
    }

    /// The value rounded to nearest at `prec` bits.
    pub fn to_float(&self, prec: u32) -> Float {
        if self.times_pi {
            let pi = Float::with_val(prec + 8, rug::float::Constant::Pi);
            Float::with_val(prec, pi * &self.coef)
        } else {
            Float::with_val(prec, &self.coef)
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
        }
    }

    /// A decimal approximation good to 17 digits, for messages and plots only.
    pub fn to_f64(&self) -> f64 {
        self.to_float(80).to_f64()
    }
}

impl fmt::Display for Exact {
    /// Canonical text: an exact decimal when the rational has one (e.g. `0.3`),
    /// otherwise a fraction (`1/3`); `·pi` forms as `2/3*pi`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let q = rational_text(&self.coef);
        if self.times_pi {
            match q.as_str() {
                "0" => write!(f, "0"),
                "1" => write!(f, "pi"),
                "-1" => write!(f, "-pi"),
                _ => write!(f, "{q}*pi"),
            }
        } else {
            write!(f, "{q}")
        }
    }
}

/// Exact decimal text of a rational when its denominator is 2^a 5^b, else `p/q`.
pub fn rational_text(q: &Rational) -> String {
    let mut den = q.denom().clone();
    let mut twos = 0u32;
    let mut fives = 0u32;
    while den.is_divisible_u(2) {
        den /= 2;
        twos += 1;
    }
    while den.is_divisible_u(5) {
        den /= 5;
        fives += 1;
    }
    if den != 1 {
        return format!("{}/{}", q.numer(), q.denom());
    }
    let k = twos.max(fives);
    if k == 0 {
        return q.numer().to_string();
    }
    let scaled = q.numer() * Integer::from(Integer::u_pow_u(10, k)) / q.denom();
    let neg = scaled < 0;
    let digits = Integer::from(scaled.abs_ref()).to_string();
    let k = k as usize;
    let padded = if digits.len() <= k {
        format!("{}{}", "0".repeat(k + 1 - digits.len()), digits)
    } else {
        digits
    };
    let (int, frac) = padded.split_at(padded.len() - k);
    let frac = frac.trim_end_matches('0');
    let sign = if neg { "-" } else { "" };
    if frac.is_empty() {
        format!("{sign}{int}")
    } else {
        format!("{sign}{int}.{frac}")
    }
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
    if exp.abs() > 100_000 {
        return None;
    }
    let (int, frac) = match mant.split_once('.') {
        Some((a, b)) => (a, b),
        None => (mant, ""),
    };
    if int.is_empty() && frac.is_empty() {
        return None;
    }
    if !int.bytes().all(|b| b.is_ascii_digit()) || !frac.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let digits = format!("{int}{frac}");
    let n = Integer::from_str_radix(if digits.is_empty() { "0" } else { &digits }, 10).ok()?;
    let e = exp - frac.len() as i64;
    let mut q = if e >= 0 {
        Rational::from(n * Integer::from(Integer::u_pow_u(10, e as u32)))
    } else {
        Rational::from((n, Integer::from(Integer::u_pow_u(10, (-e) as u32))))
    };
    if neg {
        q = -q;
    }
    Some(q)
}

#[cfg(test)]
mod tests {
    use super::*;

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
    }

    #[test]
    fn rejects_garbage() {
        for s in [
            "", "abc", "1/0", "nan", "inf", "1..2", "1e", "--1", "pi/0", "0x10",
        ] {
            assert!(Exact::parse("x", s, true).is_err(), "{s}");
        }
        assert!(Exact::parse("m1", "pi", false).is_err());
    }

    #[test]
    fn canonical_text() {
        let p = |s| Exact::parse("x", s, true).unwrap().to_string();
        assert_eq!(p("0.30"), "0.3");
        assert_eq!(p("1/3"), "1/3");
        assert_eq!(p("-0.05"), "-0.05");
        assert_eq!(p("9.81"), "9.81");
        assert_eq!(p("2pi/3"), "2/3*pi");
        assert_eq!(p("12"), "12");
    }

    #[test]
    fn exact_to_float() {
        let x = Exact::parse("x", "1/10", false).unwrap().to_float(200);
        let y = Float::with_val(200, 1) / 10u32;
        assert_eq!(x, y);
    }
}
