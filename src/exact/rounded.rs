//! A table's times converted once per answer: rounded to odd once
//! ([`RoundedTimes`]), and at the precision a route asks, kept for the two
//! runs of a rung ([`TableTimes`]).

use super::{word_denominator, Exact};
use rug::{Float, Rational};
use std::sync::Arc;

/// Times converted once for every precision a computation rounds them to.
///
/// A table's times are rounded to several precisions in one answer (each
/// run's working precision, the Taylor route's time precision), and a
/// rational whose denominator is not a machine word's (a time such as
/// i·t_end/999) costs a long division each time. Rounded to odd at P bits
/// — truncated, the last bit set where that was inexact — a number's
/// rounding to nearest at any q ≤ P − 2 bits is its own (Boldo and
/// Melquiond, "Emulation of FMA and correctly rounded sums: proved
/// algorithms using rounding to odd", IEEE TC 2008): the same bits as
/// [`Exact::to_float`], from one division. A decimal time (a word's
/// denominator, `Exact::to_float`'s machine-word division) and a multiple of π are converted
/// directly, as [`Exact::to_float`] converts them.
#[derive(Debug, Clone)]
pub struct RoundedTimes {
    times: Vec<Exact>,
    prec: u32,
    /// Each time rounded to odd at `prec` bits; None where converted
    /// directly.
    odd: Vec<Option<Float>>,
}

impl RoundedTimes {
    /// `times` rounded to odd at `prec` bits (at least 3).
    pub fn new(times: &[Exact], prec: u32) -> Self {
        let prec = prec.max(3);
        let odd = times
            .iter()
            .map(|t| {
                let direct = t.times_pi || word_denominator(&t.coef, prec).is_some();
                (!direct).then(|| round_to_odd(&t.coef, prec))
            })
            .collect();
        RoundedTimes {
            times: times.to_vec(),
            prec,
            odd,
        }
    }

    /// Whether `times` are these times' first ones, read from their count
    /// and ends where the crate made this rounding of a request's own times
    /// (every one compared in debug builds).
    fn starts(&self, times: &[Exact]) -> bool {
        let n = times.len();
        let ok = n <= self.times.len()
            && (n == 0 || (times[0] == self.times[0] && times[n - 1] == self.times[n - 1]));
        debug_assert!(
            !ok || self.times[..n] == *times,
            "the rounded times are of other times"
        );
        ok
    }

    /// How many times.
    pub fn len(&self) -> usize {
        self.times.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.times.is_empty()
    }

    /// The order of times `i` and `j` where their roundings to odd differ
    /// (a rounding to odd is monotone: unequal roundings order the times);
    /// None where they are equal or either was converted directly.
    pub fn order(&self, i: usize, j: usize) -> Option<std::cmp::Ordering> {
        match (self.odd.get(i)?, self.odd.get(j)?) {
            (Some(a), Some(b)) if a != b => a.partial_cmp(b),
            _ => None,
        }
    }

    /// The times rounded to nearest at `q` bits — [`Exact::to_float`] of
    /// each —, if these are `times` (or start with them) and `q` ≤ P − 2.
    pub fn rounded(&self, times: &[Exact], q: u32) -> Option<Vec<Float>> {
        if times.len() > self.times.len() || self.times[..times.len()] != *times {
            return None;
        }
        self.rounded_of(times, q)
    }

    /// [`RoundedTimes::rounded`] for times known to be these (or to start
    /// with them: a request's times and the rounding the crate made of
    /// them, which nothing outside it can set): their count and ends are
    /// checked, not each time (a comparison of every rational, in every
    /// run, was a tenth of a θ-only table's bookkeeping and missed the
    /// cache on every number).
    pub(crate) fn rounded_of(&self, times: &[Exact], q: u32) -> Option<Vec<Float>> {
        if q + 2 > self.prec || !self.starts(times) {
            return None;
        }
        Some(
            times
                .iter()
                .zip(&self.odd)
                .map(|(t, o)| match o {
                    Some(x) => Float::with_val(q, x),
                    None => t.to_float(q),
                })
                .collect(),
        )
    }
}

/// `q` rounded to odd at `prec` bits: toward zero, then the last bit set
/// where that was inexact (the neighbour away from zero when it was clear).
fn round_to_odd(q: &Rational, prec: u32) -> Float {
    let (mut f, dir) = Float::with_val_round(prec, q, rug::float::Round::Zero);
    if dir != std::cmp::Ordering::Equal {
        // the significand's limbs as MPFR holds them, its top bit set and
        // the bits below the precision zero: the last bit is bit
        // (limbs' bits − prec), whatever the limb size
        let clear = f
            .get_significand()
            .is_some_and(|sig| !sig.get_bit(sig.significant_bits() - prec));
        if clear {
            if f.is_sign_positive() {
                f.next_up();
            } else {
                f.next_down();
            }
        }
    }
    f
}

/// A table's times at the precision a route reads them (the Taylor route's
/// dense output, a few limbs above the run's), converted once for the two
/// runs of a rung and kept by the answer's caches — from the answer's
/// rounding to odd where there is one ([`RoundedTimes`]), else each time
/// from its exact value.
#[derive(Debug, Default)]
pub struct TableTimes {
    rounded: Option<Arc<RoundedTimes>>,
    /// Which times `floats` are.
    held: Held,
    /// Their precision (0: none).
    prec: u32,
    floats: Vec<Float>,
}

/// Which times a [`TableTimes`] holds.
#[derive(Debug, Default)]
enum Held {
    #[default]
    None,
    /// The first n of the rounding's times.
    First(usize),
    /// These.
    Times(Vec<Exact>),
}

impl TableTimes {
    /// For the times that `rounded` rounded (None: times converted from
    /// their exact values).
    pub fn new(rounded: Option<Arc<RoundedTimes>>) -> Self {
        TableTimes {
            rounded,
            ..Self::default()
        }
    }

    /// The answer's rounding of its times, if any.
    pub fn rounded(&self) -> Option<&RoundedTimes> {
        self.rounded.as_deref()
    }

    /// `times` rounded to nearest ([`Exact::to_float`]) at `hi` bits, or
    /// at the more bits they are already held at if at least `need`
    /// (`need` ≤ `hi`): converted again only where the held ones are of
    /// other times or fewer bits.
    pub fn at_least(&mut self, times: &[Exact], need: u32, hi: u32) -> &[Float] {
        let holds = match &self.held {
            Held::First(n) => {
                *n == times.len() && self.rounded.as_ref().is_some_and(|r| r.starts(times))
            }
            Held::Times(v) => v[..] == *times,
            Held::None => false,
        };
        if !holds || self.prec < need {
            match self.rounded.as_ref().and_then(|r| r.rounded_of(times, hi)) {
                Some(f) => {
                    self.floats = f;
                    self.held = Held::First(times.len());
                }
                None => {
                    self.floats = times.iter().map(|t| t.to_float(hi)).collect();
                    self.held = Held::Times(times.to_vec());
                }
            }
            self.prec = hi;
        }
        &self.floats
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Integer;

    /// Rounded to nearest from the odd rounding: the bits of the direct
    /// rounding at every precision up to P − 2, for times that are not
    /// words' quotients (their own route): a hair either side of every tie
    /// of the rounding (the midpoint of 1 and its next q-bit number ±
    /// 1/(3^45·2^(q+60)), a denominator beyond a word), of both signs; a
    /// quotient by 3^45·2^70, a numerator longer than P; the ties
    /// themselves are dyadic, a word's quotient, converted directly as
    /// decimals and multiples of π are. None beyond P − 2 or for other
    /// times.
    #[test]
    fn odd_rounding_gives_the_direct_rounding_at_every_lower_precision() {
        let m = Integer::from(Integer::u_pow_u(3, 45)); // 72 bits, odd
        let mut times: Vec<Exact> = Vec::new();
        for q in [53u32, 64, 65, 127, 128, 200] {
            let mid = Rational::from(1) + Rational::from((Integer::from(1), Integer::from(1) << q));
            let hair = Rational::from((Integer::from(1), Integer::from(&m << (q + 60))));
            for x in [mid.clone() + &hair, mid.clone() - &hair] {
                times.push(Exact::rational(x.clone()));
                times.push(Exact::rational(-x));
            }
            times.push(Exact::rational(mid));
        }
        times.push(Exact::rational(Rational::from((7, 999))));
        let long = Integer::from(Integer::u_pow_u(10, 40)) + 1;
        times.push(Exact::rational(Rational::from((
            long,
            Integer::from(&m << 70u32),
        ))));
        times.push(Exact::rational(Rational::from((
            (Integer::from(1) << 300u32) + 1,
            3,
        ))));
        times.push(Exact::parse("t", "0.125", false).unwrap());
        times.push(Exact::parse("t", "pi/7", true).unwrap());
        times.push(Exact::zero());
        let p = 260;
        let r = RoundedTimes::new(&times, p);
        // most go by the odd rounding (not a word's quotient)
        let by_odd = r.odd.iter().filter(|o| o.is_some()).count();
        assert_eq!(by_odd, 26);
        for q in 3..=p - 2 {
            let got = r.rounded(&times, q).expect("covered");
            for (t, g) in times.iter().zip(&got) {
                let want = t.to_float(q);
                assert!(
                    g.prec() == q && *g == want,
                    "{t:?} at {q} bits: {g} != {want}"
                );
            }
        }
        assert!(r.rounded(&times, p - 1).is_none());
        assert!(r.rounded(&times[..5], 100).is_some());
        assert!(r.rounded(&times[1..], 100).is_none());
    }

    /// A table's times at the precision asked: the bits of
    /// [`Exact::to_float`], from the rounding to odd or without one; held
    /// for the same times at enough bits, converted again for other times
    /// (another count, another table) or more bits.
    #[test]
    fn table_times_are_converted_again_only_for_other_times_or_bits() {
        let times: Vec<Exact> = (0..50)
            .map(|i| Exact::rational(Rational::from((i * 4901, 999 * 7))))
            .collect();
        let direct =
            |ts: &[Exact], q: u32| -> Vec<Float> { ts.iter().map(|t| t.to_float(q)).collect() };
        let rounded = Arc::new(RoundedTimes::new(&times, 300));
        for mut tt in [
            TableTimes::new(Some(rounded.clone())),
            TableTimes::default(),
        ] {
            assert_eq!(tt.at_least(&times, 200, 250).to_vec(), direct(&times, 250));
            // enough bits held: the same numbers, at their 250 bits
            let again = tt.at_least(&times, 180, 190).to_vec();
            assert_eq!(again, direct(&times, 250));
            assert!(again.iter().all(|f| f.prec() == 250));
            // a shorter table: converted again
            let short = tt.at_least(&times[..20], 180, 190).to_vec();
            assert_eq!(short, direct(&times[..20], 190));
            // more bits than held
            let more = tt.at_least(&times[..20], 260, 270).to_vec();
            assert_eq!(more, direct(&times[..20], 270));
            // other times of the same count
            let other: Vec<Exact> = times[30..].to_vec();
            assert_eq!(tt.at_least(&other, 100, 120).to_vec(), direct(&other, 120));
        }
    }
}
