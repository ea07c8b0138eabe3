//! The precision ladder: "guess and verify".
//!
//! A computation `f(prec)` is run at two working precisions p1 < p2; each run
//! also returns its method's own error estimate. The answer is the p2 value
//! with the error bound |v(p1) − v(p2)| + err(p2). It is printed to the
//! requested number of significant digits only if every number inside that
//! bound rounds to the same digits; otherwise the ladder climbs (both
//! precisions raised) and tries again, and after [`MAX_ATTEMPTS`] reports how
//! many digits it did verify.
//!
//! Accuracy kind: *estimated*, not rigorous: MPFR rounds each operation
//! correctly, but the bound rests on the methods' error estimates and on the
//! two runs not sharing an error larger than their difference.

use super::bits_for_digits;
use super::decimal::{render, round_sig, short, to_sig};
use crate::error::{Error, Result};
use rug::Float;
use std::borrow::Cow;

/// How many times the ladder climbs before giving up.
pub const MAX_ATTEMPTS: u32 = 3;

/// Guard bits added to the bits the requested digits need.
pub const GUARD_BITS: u32 = 24;

/// One run's answer for one quantity.
#[derive(Debug, Clone)]
pub struct Estimate {
    /// The value at this run's working precision.
    pub value: Float,
    /// The method's estimate of its absolute error (0 if exact up to rounding).
    pub err: Float,
    /// The value is exactly zero by construction (e.g. a friction force at a
    /// frictionless contact).
    pub exact_zero: bool,
    /// The natural magnitude of the quantity (used only to decide that a value
    /// indistinguishable from zero may be printed as 0); shared by the
    /// values of a column.
    pub scale: std::sync::Arc<Float>,
    /// The exact decimal text of a value known exactly (an input echoed in
    /// the output, such as a terminating-decimal time): printed as it is,
    /// with no rounding to decide — a rounding tie such as 0.125 at two
    /// digits could never be settled by error bounds.
    pub exact_text: Option<String>,
    /// How many times the bound counts |v(p1) − v(p2)| (this, the higher
    /// run's, estimate decides; normally 1). 2 for a value whose method
    /// error `err` leaves out a part that is at most that difference to
    /// first order: a closed form of δ = θ − θ0 whose two runs differ by
    /// more than δ's own error bound (the conservative rows of a
    /// trajectory), so that |v(p1) − v(p2)| also bounds the error δ's
    /// error carries into it. 0 for a value the higher run computed alone
    /// (the lower run left it): `err` is its whole bound.
    pub diff_weight: u32,
}

impl Estimate {
    /// An estimate with error `err` and natural scale `scale`.
    pub fn new(value: Float, err: Float, scale: Float) -> Self {
        Self::shared(value, err, std::sync::Arc::new(scale))
    }
    /// [`Estimate::new`] with a scale shared with other estimates (a
    /// table's column).
    pub fn shared(value: Float, err: Float, scale: std::sync::Arc<Float>) -> Self {
        Estimate {
            value,
            err,
            exact_zero: false,
            scale,
            exact_text: None,
            diff_weight: 1,
        }
    }
    /// A value that is correctly rounded up to a few ulps (err = 4 ulp).
    pub fn rounded(value: Float, scale: Float) -> Self {
        let p = value.prec();
        let ulps = Float::with_val(p, value.abs_ref()) >> (p as i32 - 2);
        Estimate::new(value, ulps, scale)
    }
    /// An exact zero.
    pub fn zero(prec: u32, scale: Float) -> Self {
        Self::zero_shared(prec, std::sync::Arc::new(scale))
    }
    /// [`Estimate::zero`] with a shared scale.
    pub fn zero_shared(prec: u32, scale: std::sync::Arc<Float>) -> Self {
        Estimate {
            value: Float::new(prec),
            err: Float::new(prec),
            exact_zero: true,
            scale,
            exact_text: None,
            diff_weight: 1,
        }
    }
}

/// A verified number.
#[derive(Debug, Clone)]
pub struct Verified {
    /// Quantity name.
    pub name: String,
    /// The value at the higher working precision.
    pub value: Float,
    /// The decimal text printed: exactly the verified digits.
    pub text: String,
    /// Significant digits verified and printed (0 for a value printed as 0).
    pub digits: u32,
    /// The estimated absolute error bound of `value`.
    pub err_bound: Float,
    /// The two working precisions (bits).
    pub precs: (u32, u32),
}

impl Verified {
    /// The error bound as short text, e.g. `3.2e-41`.
    pub fn err_text(&self) -> String {
        short(&self.err_bound)
    }
}

/// The two working precisions for `digits` at ladder rung `attempt`: the
/// digits' bits and [`GUARD_BITS`], at least 64 (one limb: no dearer than
/// fewer bits; below it, with a few digits asked of widely ranging
/// parameters — an upper cylinder 10^20 times the lower's mass — both runs
/// agreed on wrong values), 48 more per rung; p2 = p1 + 32 + p1/8.
pub fn precisions(digits: u32, attempt: u32) -> (u32, u32) {
    let p1 = (bits_for_digits(digits) + GUARD_BITS).max(64) + 48 * attempt;
    let p2 = p1 + 32 + p1 / 8;
    (p1, p2)
}

/// Largest number of significant digits on which every value in [v−b, v+b]
/// agrees when rounded (0 if none).
pub fn agreeing_digits(v: &Float, b: &Float, max: u32) -> u32 {
    let (lo, hi) = outward(v, b, v.prec());
    if lo.is_sign_negative() != hi.is_sign_negative() || lo.is_zero() || hi.is_zero() {
        return 0;
    }
    let mut best = 0;
    for d in 1..=max {
        if round_sig(&lo, d) == round_sig(&hi, d) {
            best = d;
        } else {
            break;
        }
    }
    best
}

/// [v − b, v + b] at `p` bits, its ends rounded outward (down and up).
fn outward(v: &Float, b: &Float, p: u32) -> (Float, Float) {
    use rug::float::Round;
    let (lo, _) = Float::with_val_round(p, v - b, Round::Down);
    let (hi, _) = Float::with_val_round(p, v + b, Round::Up);
    (lo, hi)
}

/// The text [`judge`] would print, found with one decimal conversion
/// instead of two, or `None` to let the two-conversion path decide.
///
/// v is rendered with d + 3 digits good to one unit of the last
/// ([`super::decimal::approx_sig`]), D = A·T (A the first d digits, T the
/// last three, 0 ≤ T < 1000), |v − 0.D·10^e| ≤ 10^(e−d−3). v rounds to A
/// (T < 500) or A + 1, and sits at least |T − 500| − 1 units of 10^(e−d−3)
/// from the nearest boundary of that rounding cell (the midpoints A ± ½). If
/// the bound is below that distance less one more unit, v − bound and
/// v + bound both lie inside the cell and round to the same d digits — the
/// ones returned. Declined (the
/// exact path decides): a cell at a power of ten (A = 10…0, where the cell
/// below is finer) or a carry into d + 1 digits.
fn fast_text(v: &Float, bound: &Float, digits: u32) -> Option<String> {
    thread_local! {
        static BUF: std::cell::RefCell<Vec<u8>> = const { std::cell::RefCell::new(Vec::new()) };
    }
    BUF.with(|buf| fast_text_in(v, bound, digits, &mut buf.borrow_mut()))
}

/// [`fast_text`] on a reused digit buffer.
fn fast_text_in(v: &Float, bound: &Float, digits: u32, a: &mut Vec<u8>) -> Option<String> {
    let d = digits as usize;
    let (neg, e) = super::decimal::approx_sig_into(v, digits + 3, a)?;
    if a.len() != d + 3 || d == 0 {
        return None;
    }
    let t = a[d..]
        .iter()
        .fold(0i64, |t, &c| t * 10 + i64::from(c.wrapping_sub(b'0')));
    // the three guard digits are good to one unit: the rounding boundary
    // T = 500 is more than two units away
    let margin = (t - 500).abs() - 2;
    if margin <= 0 {
        return None;
    }
    // bound·10^(d+3−e) < margin ?  In log2, from the binary exponents
    // alone: bound < 2^eb, 2^⌊log2 margin⌋ ≤ margin, with a safety factor
    // of 4 over the f64 product k·log2 10 (its error ~1e-10 for any k)
    let k = d as i64 + 3 - e;
    if let Some(eb) = bound.get_exp() {
        let lb = f64::from(eb) + k as f64 * std::f64::consts::LOG2_10;
        let lm = f64::from(63 - (margin as u64).leading_zeros());
        if lb + 2.0 >= lm {
            return None;
        }
    }
    a.truncate(d);
    if a[0] == b'1' && a[1..].iter().all(|&c| c == b'0') {
        return None;
    }
    if t >= 500 {
        // A + 1
        let mut i = d;
        loop {
            if i == 0 {
                return None; // 99…9 + 1 carries into d + 1 digits
            }
            i -= 1;
            if a[i] == b'9' {
                a[i] = b'0';
            } else {
                a[i] += 1;
                break;
            }
        }
    }
    let digits_str = std::str::from_utf8(a).ok()?;
    Some(render(neg, digits_str, e))
}

fn judge(
    name: &str,
    digits: u32,
    precs: (u32, u32),
    a: &Estimate,
    b: &Estimate,
) -> std::result::Result<Verified, u32> {
    judged(digits, a, b).map(|j| j.verified(name, precs, || b.value.clone(), || b.err.clone()))
}

/// What [`judge`] decides of a value, without the value itself (a table's
/// values are moved into their [`Verified`], not copied).
struct Judged {
    /// The value the [`Verified`] holds instead of the higher run's (an
    /// exact zero).
    value: Option<Float>,
    text: String,
    digits: u32,
    /// The bound; `None`: the higher run's own error estimate (a value it
    /// computed alone, `diff_weight` 0), moved in rather than copied.
    err_bound: Option<Float>,
}

impl Judged {
    fn verified(
        self,
        name: &str,
        precs: (u32, u32),
        value: impl FnOnce() -> Float,
        err: impl FnOnce() -> Float,
    ) -> Verified {
        Verified {
            name: name.to_string(),
            value: self.value.unwrap_or_else(value),
            text: self.text,
            digits: self.digits,
            err_bound: self.err_bound.unwrap_or_else(err),
            precs,
        }
    }
}

/// A bound as [`Judged`] keeps it: `None` where it is the estimate's own
/// error.
fn kept(bound: Cow<'_, Float>) -> Option<Float> {
    match bound {
        Cow::Borrowed(_) => None,
        Cow::Owned(b) => Some(b),
    }
}

fn judged(digits: u32, a: &Estimate, b: &Estimate) -> std::result::Result<Judged, u32> {
    let p = b.value.prec();
    if let Some(text) = &b.exact_text {
        return Ok(Judged {
            value: None,
            text: text.clone(),
            digits,
            err_bound: Some(Float::new(p)),
        });
    }
    if a.exact_zero && b.exact_zero {
        return Ok(Judged {
            value: Some(Float::new(p)),
            text: "0".to_string(),
            digits,
            err_bound: Some(Float::new(p)),
        });
    }
    let bound = error_bound(a, b);
    if !b.value.is_finite() || !bound.is_finite() {
        return Err(0);
    }
    if b.value.cmp_abs(&bound) != Some(std::cmp::Ordering::Greater) {
        // indistinguishable from zero
        return zero_cell(b, &bound, digits).ok_or(0);
    }
    if let Some(text) = fast_text(&b.value, &bound, digits) {
        return Ok(Judged {
            value: None,
            text,
            digits,
            err_bound: kept(bound),
        });
    }
    // the interval's ends rounded outward (a value at fewer bits than its
    // bound's difference would lose the half unit otherwise)
    let (lo, hi) = outward(&b.value, &bound, p);
    match (round_sig(&lo, digits), round_sig(&hi, digits)) {
        (Some(a), Some(b2)) if a == b2 => {
            let (neg, d, e) = a;
            Ok(Judged {
                value: None,
                text: render(neg, &d, e),
                digits,
                err_bound: kept(bound),
            })
        }
        _ => Err(agreeing_digits(&b.value, &bound, digits)),
    }
}

/// The bound the ladder holds the higher run's value to:
/// |v(p1) − v(p2)|·diff_weight + err(p2), at p2 (err(p2) itself, not a
/// copy, where the weight is 0).
fn error_bound<'a>(a: &Estimate, b: &'a Estimate) -> Cow<'a, Float> {
    if b.diff_weight == 0 {
        return Cow::Borrowed(&b.err);
    }
    let mut bound = Float::with_val(b.value.prec(), &a.value - &b.value);
    bound.abs_mut();
    if b.diff_weight != 1 {
        bound *= b.diff_weight;
    }
    bound += &b.err;
    Cow::Owned(bound)
}

/// An error negligible at `digits` digits of the quantity's natural scale:
/// scale/10^digits.
fn negligible(b: &Estimate, digits: u32) -> Float {
    let p = b.value.prec();
    Float::with_val(
        p,
        &*b.scale / Float::with_val(p, rug::Integer::from(rug::Integer::u_pow_u(10, digits))),
    )
}

/// A verified number from a value and an absolute error bound that are
/// already established (e.g. a ratio of two verified numbers, with the
/// relative bounds added): the most significant digits, up to `digits`, that
/// every number within the bound shares.
///
/// Errors: [`Error::NotConverged`] when not even one digit is shared.
pub fn verified_from(name: &str, value: Float, err: Float, digits: u32) -> Result<Verified> {
    let p = value.prec();
    let est = Estimate::new(value, err, Float::with_val(p, 1u32));
    (1..=digits)
        .rev()
        .find_map(|d| judge(name, d, (p, p), &est, &est).ok())
        .ok_or_else(|| Error::NotConverged {
            quantity: name.to_string(),
            requested: digits,
            reached: "0 digits verified".into(),
            detail: format!(
                "value ≈ {}, error bound {}",
                to_sig(&est.value, 12),
                short(&est.err)
            ),
        })
}

/// A tiny value (|v| far below its natural scale, e.g. N12 just before θs)
/// whose absolute error is within scale·10^−digits but whose relative digits
/// fall short after the last rung: it is answered with the significant
/// digits its bound does verify (fewer than asked, and said so by
/// [`Verified::digits`]) instead of failing the whole answer. Only at the
/// last rung (`last`), so that a value that more precision would verify in
/// full is never cut short.
fn absolute_fallback(last: bool, digits: u32, a: &Estimate, b: &Estimate) -> Option<Judged> {
    if !last || !b.value.is_finite() || b.value.is_zero() {
        return None;
    }
    let bound = error_bound(a, b);
    if !bound.is_finite() || *bound > negligible(b, digits) {
        return None;
    }
    // no digit shared, but the value itself negligible with its bound (the
    // work 6.4e-80 a hair past a slip onset, the runs 5e-81 apart, refused
    // at 30 digits and 0 at 20): 0, as a value within its bound of 0 is
    (1..digits)
        .rev()
        .find_map(|d| judged(d, a, b).ok())
        .or_else(|| zero_cell(b, &bound, digits))
}

/// The value `b` printed 0: where |value| + `bound` (the true value's
/// distance from 0 at most: the bound is about the value, not about 0) is
/// negligible at `digits` relative to the quantity's natural scale.
fn zero_cell(b: &Estimate, bound: &Float, digits: u32) -> Option<Judged> {
    let p = b.value.prec();
    let whole = Float::with_val(p, b.value.abs_ref()) + bound;
    (whole <= negligible(b, digits)).then(|| Judged {
        value: None,
        text: "0".to_string(),
        digits: 0,
        err_bound: Some(whole),
    })
}

/// Runs `f` at two precisions (climbing the ladder if needed) and verifies
/// each of its outputs, named by `names`, to `digits` significant digits.
///
/// `f(prec)` must return one [`Estimate`] per name, in order.
///
/// Errors: whatever `f` returns; [`Error::NotConverged`] naming the first
/// quantity that could not be verified and the digits that were.
pub fn ladder<F>(digits: u32, names: &[&str], mut f: F) -> Result<Vec<Verified>>
where
    F: FnMut(u32) -> Result<Vec<Estimate>>,
{
    ladder_runs(digits, names, |p, _| f(p))
}

/// Which run of a rung of the ladder a computation is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Run {
    /// The lower precision p1: the value compared against.
    Low,
    /// The higher precision p2: the value kept, whose error estimate counts.
    High,
}

/// [`ladder`] with the run's role passed along, so that the two runs may use
/// two different methods (e.g. tanh-sinh at p1, Gauss–Legendre at p2): the
/// bound |v(p1) − v(p2)| + err(p2) then also compares the methods.
pub fn ladder_runs<F>(digits: u32, names: &[&str], mut f: F) -> Result<Vec<Verified>>
where
    F: FnMut(u32, Run) -> Result<Vec<Estimate>>,
{
    let w = names.len();
    let mut rows = ladder_rows(digits, names, 1, false, |p, run| {
        f(p, run).map(|v| estimate_rows(v, w))
    })?;
    Ok(rows.pop().unwrap_or_default())
}

/// The precision ladder for a table: `f(prec, run)` returns the estimates of
/// all rows in one flat vector (row after row, one per name), all computed in
/// one go (e.g. one ODE run serving every output time). Each row is judged on its own, exactly as
/// [`ladder`] would: a row keeps the first rung at which all its quantities
/// verify, and only when some row fails does the whole table climb.
///
/// Errors: whatever `f` returns; [`Error::NotConverged`] naming the first
/// quantity (and its row) that could not be verified.
pub fn ladder_table<F>(
    digits: u32,
    names: &[&str],
    rows: usize,
    mut f: F,
) -> Result<Vec<Vec<Verified>>>
where
    F: FnMut(u32, Run) -> Result<Vec<Estimate>>,
{
    let w = names.len();
    ladder_rows(digits, names, rows, true, |p, run| {
        f(p, run).map(|v| estimate_rows(v, w))
    })
}

/// One run's estimates, row by row, as the ladder judges them: a row's
/// estimates are made when the ladder comes to it, so that a long table's
/// estimates of both runs are never held at once (each row's are judged,
/// then dropped).
pub(crate) type RowIter<'a> = Box<dyn Iterator<Item = Vec<Estimate>> + 'a>;

/// The rows of a flat vector of estimates, `w` (one per name) in each.
pub(crate) fn estimate_rows(est: Vec<Estimate>, w: usize) -> RowIter<'static> {
    let mut it = est.into_iter();
    Box::new(std::iter::from_fn(move || {
        let row: Vec<Estimate> = it.by_ref().take(w).collect();
        (!row.is_empty()).then_some(row)
    }))
}

/// The ladder of [`ladder_table`] and [`ladder_runs`] (`rows` rows;
/// `label_rows`: name the row of a quantity that fails, a table's, or not,
/// a single row's), whose lower run may leave rows short: `f` returns the
/// run's rows, each made as it is judged ([`RowIter`]). A row's estimates are
/// the first names' in order; a value the lower run left must be one the
/// higher run's estimate decides alone (its `diff_weight` 0, or exactly
/// zero by construction in both runs): nothing is compared for it. A table
/// of every column computes a conservative row's columns but t and θ at the
/// higher precision only: its lower run needs no placeholders for them.
///
/// Errors: as [`ladder_table`]; a value missing from the higher run, or
/// from the lower run where it is compared, is not computed.
pub(crate) fn ladder_rows<'a, F>(
    digits: u32,
    names: &[&str],
    rows: usize,
    label_rows: bool,
    mut f: F,
) -> Result<Vec<Vec<Verified>>>
where
    F: FnMut(u32, Run) -> Result<RowIter<'a>>,
{
    let w = names.len();
    let mut done: Vec<Option<Vec<Verified>>> = vec![None; rows];
    let mut last_fail = None;
    for attempt in 0..MAX_ATTEMPTS {
        crate::cancel::check()?;
        let precs = precisions(digits, attempt);
        let mut a = f(precs.0, Run::Low)?;
        let mut b = f(precs.1, Run::High)?;
        let mut failed = None;
        // each row's estimates are made as the row is judged and dropped
        // after it: the memory of a row's estimates serves the next row's
        for (r, slot) in done.iter_mut().enumerate() {
            let row_a = a.next().unwrap_or_default();
            let row_b = b.next().unwrap_or_default();
            // a row wider than the names would shift its values into the
            // wrong columns
            if let Some(x) = [row_a.len(), row_b.len()].into_iter().find(|&x| x > w) {
                return Err(Error::not_physical(format!(
                    "internal: a row of {x} estimates for {w} names"
                )));
            }
            if slot.is_some() {
                continue;
            }
            let mut out = Vec::with_capacity(names.len());
            let mut row_failed = None;
            // the higher run's values move into the verified ones
            let mut bs = row_b.into_iter();
            for (i, name) in names.iter().enumerate() {
                let Some(eb) = bs.next() else {
                    return Err(Error::NotConverged {
                        quantity: name.to_string(),
                        requested: digits,
                        reached: "no value computed".into(),
                        detail: format!("row {r} of {rows}"),
                    });
                };
                let label = || {
                    if label_rows {
                        format!("{name} (row {r})")
                    } else {
                        name.to_string()
                    }
                };
                // a value the lower run left: one the higher run's estimate
                // decides alone (its bound is its own error; an exact zero
                // is zero in both runs) is judged against itself; one that
                // needs the comparison fails the rung (the runs disagree on
                // what the row is)
                let ea = match row_a.get(i) {
                    Some(ea) => ea,
                    None if eb.diff_weight == 0 || eb.exact_zero => &eb,
                    None => {
                        row_failed = Some((
                            label(),
                            0,
                            precs,
                            to_sig(&eb.value, 12),
                            "not computed by the lower precision".to_string(),
                            short(&eb.err),
                        ));
                        break;
                    }
                };
                let last = attempt + 1 == MAX_ATTEMPTS;
                match judged(digits, ea, &eb)
                    .or_else(|r| absolute_fallback(last, digits, ea, &eb).ok_or(r))
                {
                    Ok(j) => out.push(j.verified(name, precs, || eb.value, || eb.err)),
                    Err(reached) => {
                        // a value the higher run computed alone was not
                        // compared: its error estimate is its whole bound
                        let diff = if eb.diff_weight == 0 {
                            "not compared (the higher precision's alone)".to_string()
                        } else {
                            short(&Float::with_val(precs.1, &ea.value - &eb.value).abs())
                        };
                        row_failed = Some((
                            label(),
                            reached,
                            precs,
                            to_sig(&eb.value, 12),
                            diff,
                            short(&eb.err),
                        ));
                        break;
                    }
                }
            }
            match row_failed {
                None => *slot = Some(out),
                Some(fl) => {
                    if failed.is_none() {
                        failed = Some(fl);
                    }
                }
            }
        }
        match failed {
            None => return Ok(done.into_iter().flatten().collect()),
            Some(fl) => last_fail = Some(fl),
        }
    }
    let (name, reached, precs, value, diff, err) =
        last_fail.ok_or_else(|| Error::NotConverged {
            quantity: "table".into(),
            requested: digits,
            reached: "no rung ran".into(),
            detail: String::new(),
        })?;
    Err(Error::NotConverged {
        quantity: name,
        requested: digits,
        reached: format!("{reached} digits verified at {}/{} bits", precs.0, precs.1),
        detail: format!(
            "value ≈ {value}, difference between precisions {diff}, method error estimate {err}"
        ),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Only the higher run's error estimate counts: the lower run's may be
    /// anything (a table's lower run leaves it zero, uncomputed), and the
    /// higher run's widens the bound.
    #[test]
    fn the_lower_runs_error_is_not_read() {
        let table = |low_err: f64, high_err: f64| {
            ladder_table(30, &["a", "b"], 2, |p, run| {
                let e = if run == Run::Low { low_err } else { high_err };
                Ok([(1u32, 3u32), (2, 7), (5, 11), (13, 17)]
                    .iter()
                    .map(|&(n, d)| {
                        let v = Float::with_val(p, n) / d;
                        Estimate::new(v, Float::with_val(p, e), Float::with_val(p, 1u32))
                    })
                    .collect())
            })
        };
        let base = table(0.0, 1e-40).unwrap();
        for low in [1e-10, 1.0, 1e30] {
            let t = table(low, 1e-40).unwrap();
            for (ra, rb) in t.iter().zip(&base) {
                for (a, b) in ra.iter().zip(rb) {
                    assert_eq!((&a.text, a.digits, a.precs), (&b.text, b.digits, b.precs));
                    assert_eq!(a.err_bound, b.err_bound);
                }
            }
        }
        assert_eq!(base[0][0].text, "0.333333333333333333333333333333");
        // the higher run's error is read: 1e-20 leaves no 30 digits
        assert!(table(0.0, 1e-20).is_err());
    }

    /// A lower run's short row: a value it leaves is judged by the higher
    /// run's estimate alone where that decides alone (weight 0: 1/7 to the
    /// digits its error allows, the same as with a placeholder; an exact
    /// zero), and where it needs the comparison (weight 1) the rung fails
    /// and the ladder climbs; a rung whose lower run gives the value
    /// verifies it. A value missing from the higher run is an error.
    #[test]
    fn a_short_lower_row_leaves_what_the_higher_run_decides_alone() {
        use std::cell::Cell;
        let est = |p: u32, (n, d): (u32, u32), err: f64| {
            Estimate::new(
                Float::with_val(p, n) / d,
                Float::with_val(p, err),
                Float::with_val(p, 1u32),
            )
        };
        // row 0: a, then b decided alone (weight 0) and c exactly zero; row 1
        // whole; the lower run leaves row 0 short (a only) when `short`
        let table = |short: bool, b_weight: u32, rungs: &Cell<u32>| {
            ladder_rows(30, &["a", "b", "c"], 2, true, |p, run| {
                if run == Run::Low {
                    rungs.set(rungs.get() + 1);
                }
                let mut b = est(p, (1, 7), 1e-45);
                b.diff_weight = b_weight;
                let c = Estimate::zero(p, Float::with_val(p, 1u32));
                let row1 = [(2, 3), (3, 5), (4, 9)].map(|nd| est(p, nd, 0.0));
                let cut = short && run == Run::Low && rungs.get() == 1;
                let row0 = if cut {
                    vec![est(p, (1, 3), 0.0)]
                } else {
                    vec![est(p, (1, 3), 0.0), b, c]
                };
                Ok(Box::new([row0, row1.to_vec()].into_iter()) as RowIter)
            })
        };
        let rungs = Cell::new(0);
        let whole = table(false, 0, &rungs).unwrap();
        let cut = table(true, 0, &Cell::new(0)).unwrap();
        assert_eq!(rungs.get(), 1);
        for (rw, rc) in whole.iter().zip(&cut) {
            for (w, c) in rw.iter().zip(rc) {
                assert_eq!(
                    (&w.text, w.digits, &w.err_bound),
                    (&c.text, c.digits, &c.err_bound)
                );
            }
        }
        assert_eq!(cut[0][1].text, "0.142857142857142857142857142857");
        assert_eq!(cut[0][2].text, "0");
        assert_eq!(cut[1][2].text, "0.444444444444444444444444444444");
        // a value that needs the comparison: the first rung fails, the
        // second (whole rows) verifies it
        let climbs = Cell::new(0);
        let t = table(true, 1, &climbs).unwrap();
        assert_eq!(climbs.get(), 2);
        assert_eq!(t[0][1].precs, precisions(30, 1));
        assert_eq!(t[0][0].precs, precisions(30, 1));
        // the higher run leaving a value is an error
        let e = ladder_rows(30, &["a", "b"], 1, false, |p, run| {
            let n = if run == Run::High { 1 } else { 2 };
            Ok(Box::new(std::iter::once(vec![est(p, (1, 3), 0.0); n])) as RowIter)
        });
        assert!(matches!(e, Err(Error::NotConverged { .. })));
        // a row wider than the names is refused, not read into the next
        let e = ladder_rows(30, &["a"], 2, true, |p, _| {
            let rows = [vec![est(p, (1, 3), 0.0); 2], vec![est(p, (1, 3), 0.0)]];
            Ok(Box::new(rows.into_iter()) as RowIter)
        });
        assert!(e.is_err());
    }

    #[test]
    fn verifies_a_correct_computation() {
        let v = ladder(50, &["pi"], |p| {
            let x = Float::with_val(p, rug::float::Constant::Pi);
            Ok(vec![Estimate::rounded(x, Float::with_val(p, 1u32))])
        })
        .unwrap();
        assert_eq!(
            v[0].text,
            "3.1415926535897932384626433832795028841971693993751"
        );
        assert_eq!(v[0].digits, 50);
    }

    #[test]
    fn refuses_a_computation_stuck_at_low_accuracy() {
        // an "integral" whose truncation does not improve with precision
        let e = ladder(40, &["x"], |p| {
            let x = Float::with_val(p, 1e-25) + Float::with_val(p, 2u32).sqrt();
            let wrong = if p % 2 == 0 { x.clone() } else { x + 1e-20 };
            Ok(vec![Estimate::rounded(wrong, Float::with_val(p, 1u32))])
        });
        // precisions alternate parity at some rung, or all differ by 1e-20
        if let Err(Error::NotConverged { reached, .. }) = &e {
            assert!(
                reached.starts_with("19") || reached.starts_with("20"),
                "{reached}"
            );
        }
    }

    #[test]
    fn honest_error_estimate_blocks_digits() {
        let e = ladder(30, &["y"], |p| {
            let x = Float::with_val(p, 2u32).sqrt();
            Ok(vec![Estimate::new(
                x,
                Float::with_val(p, 1e-12),
                Float::with_val(p, 1u32),
            )])
        })
        .unwrap_err();
        match e {
            Error::NotConverged {
                reached, requested, ..
            } => {
                assert_eq!(requested, 30);
                assert!(
                    reached.starts_with("11 ") || reached.starts_with("12 "),
                    "{reached}"
                );
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn the_fast_judgement_agrees_with_the_two_conversions() {
        // values near rounding boundaries, powers of ten, carries, signs
        let p = 200;
        let mut cases = vec![];
        for num in [
            "1.23449999999",
            "1.2345",
            "9.9999999",
            "0.099999999",
            "1.000000001",
            "-7.77777777",
            "123456.5",
            "3.14159265358979",
            "0.999999999999",
            "2.5e-30",
        ] {
            cases.push(Float::with_val(p, Float::parse(num).unwrap()));
        }
        // digits on either side of the 19 and 38 of the digit conversion's
        // 64- and 128-bit paths
        for v in &cases {
            for digits in [1u32, 3, 5, 8, 12, 16, 17, 18, 19, 30, 35, 36, 40, 50] {
                for bexp in [5, 12, 20, 40, 60, 100, 150, 190] {
                    let bound = Float::with_val(p, v.abs_ref()) >> bexp;
                    let lo = Float::with_val(p, v - &bound);
                    let hi = Float::with_val(p, v + &bound);
                    let slow = match (round_sig(&lo, digits), round_sig(&hi, digits)) {
                        (Some(a), Some(b)) if a == b => Some(render(a.0, &a.1, a.2)),
                        _ => None,
                    };
                    if let Some(fast) = fast_text(v, &bound, digits) {
                        assert_eq!(Some(fast), slow, "v {v} digits {digits} bound 2^-{bexp}");
                    }
                }
            }
        }
    }

    /// A value on a decimal rounding boundary, held at fewer bits than its
    /// bound resolves: the interval's ends are rounded outward, so the
    /// digit it would round to either way is not printed (to nearest, both
    /// ends were the value itself, 1.5, and "2" was printed).
    #[test]
    fn an_interval_across_a_rounding_boundary_is_not_cut() {
        for p in [8u32, 64, 127] {
            let v = Float::with_val(p, 1.5);
            let err = Float::with_val(p, 1u32) >> (p as i32 + 40);
            let e = Estimate::new(v, err, Float::with_val(p, 1u32));
            assert!(
                judged(1, &e, &e).is_err(),
                "1.5 ± 2^-{} at {p} bits",
                p + 40
            );
            let (lo, hi) = outward(&e.value, &e.err, p);
            assert!(lo < 1.5 && hi > 1.5);
            // two digits: 1.5 either way
            assert_eq!(
                judged(2, &e, &e).map(|j| j.text).ok().as_deref(),
                Some("1.5")
            );
        }
    }

    #[test]
    fn zero_like_values() {
        let v = ladder(20, &["z"], |p| {
            let tiny = Float::with_val(p, 1u32) >> (p as i32);
            Ok(vec![Estimate::new(
                tiny.clone(),
                tiny,
                Float::with_val(p, 1u32),
            )])
        })
        .unwrap();
        assert_eq!(v[0].text, "0");
        assert_eq!(v[0].digits, 0);
    }
}
