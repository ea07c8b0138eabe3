//! Several Chebyshev sums at one point, in fixed point: the sums a dense
//! grid of output times asks of a piece's interpolants (every state
//! coordinate at every time).
//!
//! At a few limbs MPFR spends most of a multiply-add in call overhead and
//! temporaries (about 600 instructions at 3–4 limbs, measured with
//! callgrind); the fixed-point numbers of [`crate::numeric::fixed`] take a
//! few per limb product. The coefficients are converted once; at each point
//! the basis T_k(x) comes from the three-term recurrence in fixed point and
//! each sum from one exact accumulation, rounded once.
//!
//! Accuracy: each fit is summed in its own scale. Its coefficients are
//! multiplied by 2^−e (exactly), e the exponent of the largest, so that the
//! largest lies in [1/2, 1); the sum is multiplied back by 2^e (exactly).
//! With F = 64(L − 1) fraction bits chosen ≥ the precision asked for,
//! prec, plus 8, the point x and the scaled coefficients are rounded to
//! 2^−F; the recurrence (stable for |x| ≤ 1: an error made at step j
//! reaches T_k multiplied by U_{k−j−1}(x), |U_m| ≤ m + 1) leaves T_k within
//! k²·2^−F; the accumulation truncates once. A scaled sum is within
//! (n² + n)·2^−F·max(1, Σ|c_k|2^−e) of the exact one, and since
//! 2^e ≤ 2 max|c_k| ≤ 2 Σ|c_k|, every sum is within
//! 2^−(prec−10)·Σ|c_k| of the exact sum of the coefficients for the
//! n ≤ 256 allowed: relative to the fit's own scale, whatever that scale
//! (a time unit of 10^−10 s, forces of 10^20 N), never an absolute floor.
//! The spectral route asks for 16 bits beyond its interpolants' tolerance
//! 2^−b, which is relative to each interpolant's scale
//! ([`crate::integrate::solve::Opts::for_prec`]; `fixed_prec` in
//! `integrate/spectral/piece.rs`): the sums add at most 2^−6 of that
//! tolerance, to values only read (the rows of a trajectory, their times,
//! the state at the last time asked), never carried on into the motion.

use super::ChebFit;
use crate::numeric::fixed::{self, Conv, Fx};
use rug::{Assign, Float};

/// The fits' coefficients in fixed point, for their sums at many points of
/// their common interval.
#[derive(Debug, Clone)]
pub struct FixedSums {
    /// Limbs per number (one of them the integer limb).
    limbs: usize,
    /// The fits' lengths.
    lens: Vec<usize>,
    /// The longest fit.
    n: usize,
    /// Magnitudes, fit after fit, coefficient after coefficient, `limbs`
    /// limbs each (least significant first).
    mags: Vec<u64>,
    /// Signs, in the same order.
    negs: Vec<bool>,
    /// Significant limbs, in the same order.
    sig: Vec<u16>,
    /// Each fit's scale exponent e (its coefficients are held as c·2^−e).
    exps: Vec<i32>,
    conv: Conv,
    /// The working precision.
    prec: u32,
}

/// The limb counts instantiated (beyond them the caller sums in MPFR).
macro_rules! with_limbs {
    ($l:expr, $f:ident, $($args:expr),*) => {
        match $l {
            3 => $f::<3, 8>($($args),*),
            4 => $f::<4, 10>($($args),*),
            5 => $f::<5, 12>($($args),*),
            6 => $f::<6, 14>($($args),*),
            7 => $f::<7, 16>($($args),*),
            8 => $f::<8, 18>($($args),*),
            9 => $f::<9, 20>($($args),*),
            10 => $f::<10, 22>($($args),*),
            12 => $f::<12, 26>($($args),*),
            14 => $f::<14, 30>($($args),*),
            16 => $f::<16, 34>($($args),*),
            _ => None,
        }
    };
}

impl FixedSums {
    /// The coefficients of `fits` (one interval; working precision
    /// `prec`) in fixed point, each fit in its own scale; `None` where
    /// fixed point does not apply (a precision beyond the instantiated
    /// sizes, a coefficient not finite, a fit longer than 256).
    pub fn new(fits: &[&ChebFit], prec: u32) -> Option<Self> {
        let limbs = Self::limbs(prec)?;
        let lens: Vec<usize> = fits.iter().map(|f| f.c.len()).collect();
        let n = lens.iter().copied().max()?.max(2);
        if n > 256 {
            return None;
        }
        if fits.iter().flat_map(|f| f.c.iter()).any(|c| !c.is_finite()) {
            return None;
        }
        // the exponent of each fit's largest coefficient (0 for a zero fit)
        let exps = fits
            .iter()
            .map(|f| crate::numeric::max_exp(&f.c).unwrap_or(0))
            .collect();
        let mut s = FixedSums {
            limbs,
            lens,
            n,
            mags: Vec::new(),
            negs: Vec::new(),
            sig: Vec::new(),
            exps,
            conv: Conv::new(prec),
            prec,
        };
        with_limbs!(limbs, convert, &mut s, fits)?;
        Some(s)
    }

    /// The limbs of sums built for `prec` bits (8 more fraction bits, one
    /// integer limb, rounded up to an instantiated size; `None` beyond).
    pub fn limbs(prec: u32) -> Option<usize> {
        fixed::limbs_for((prec as usize + 8).div_ceil(64) + 1)
    }

    /// The sum of each fit at `v` of the interval [a, b] into `out` (one per
    /// fit, each rounded to its own precision); `false` (out unspecified)
    /// where a value left the fixed-point range.
    pub fn eval(&mut self, a: &Float, b: &Float, v: &Float, out: &mut [Float]) -> bool {
        // x to the fixed point's own fraction bits (at least the precision)
        let p = self.prec.max(64 * (self.limbs as u32 - 1));
        // x = (2v − a − b)/(b − a), as ChebFit::basis_into
        let mut x = Float::with_val(p, v * 2u32);
        x -= a;
        x -= b;
        x /= Float::with_val(p, b - a);
        if x > 1u32 || x < -1i32 {
            return false;
        }
        with_limbs!(self.limbs, sums, self, &x, out).unwrap_or(false)
    }
}

/// [`FixedSums`] built at the first sum asked, for fits that do not change
/// (a piece's interpolants): every call sums the same fits.
#[derive(Debug)]
pub struct LazySums {
    sums: std::cell::RefCell<Option<Option<FixedSums>>>,
    /// The precision the sums are built for.
    prec: u32,
}

impl LazySums {
    /// Sums built for precision `prec` ([`FixedSums::new`]): within
    /// 2^−(prec−10)·Σ|c_k| of each fit, whatever the point's precision.
    pub fn at(prec: u32) -> Self {
        LazySums {
            sums: Default::default(),
            prec,
        }
    }

    /// [`FixedSums::eval`] of `fits` at `v` of [a, b] (built at the first
    /// call, for [`LazySums::at`]'s precision); `false` (out
    /// unspecified) where fixed point does not apply, there or for these
    /// fits at all.
    pub fn eval(
        &self,
        fits: &[&ChebFit],
        a: &Float,
        b: &Float,
        v: &Float,
        out: &mut [Float],
    ) -> bool {
        let mut fx = self.sums.borrow_mut();
        fx.get_or_insert_with(|| FixedSums::new(fits, self.prec))
            .as_mut()
            .is_some_and(|fx| fx.eval(a, b, v, out))
    }
}

fn convert<const L: usize, const W: usize>(s: &mut FixedSums, fits: &[&ChebFit]) -> Option<()> {
    let mut scaled = Float::new(s.prec);
    for (f, &e) in fits.iter().zip(&s.exps) {
        for c in &f.c {
            if scaled.prec() != c.prec() {
                scaled.set_prec(c.prec());
            }
            scaled.assign(c >> e);
            let v: Fx<L> = s.conv.to_fx(&scaled);
            s.mags.extend_from_slice(&v.m);
            s.negs.push(v.neg);
            s.sig.push(v.len);
        }
    }
    Some(())
}

/// Exact sums of signed limb products in 128-bit columns (positive and
/// negative parts apart), the carries resolved once at the end: each
/// product adds to two columns independently, where a running carry would
/// chain every limb product of a sum on the one before. `W` = 2L + 2
/// limbs, as [`Acc`]; the same products left out (a_i·b_j with i + j below
/// the cut), so the same exact sum and the same truncated result. A column
/// takes at most 2·L·n additions below 2^64 each (two per limb product
/// that reaches it; n ≤ 256, L ≤ 16): far below 2^64 of them, no overflow.
/// The same kept products and truncations in the basis ([`next_t`], whose
/// product is `fixed::mac_mag` itself). The subtraction and truncation
/// ([`sub_truncated`]) run on arrays of W limbs, not on `Acc`'s vectors
/// through slices: shared that way they cost 2% of a friction table's
/// instructions.
struct Cols<const L: usize, const W: usize> {
    pos: [u128; W],
    neg: [u128; W],
}

impl<const L: usize, const W: usize> Cols<L, W> {
    /// [`Acc`]'s cut: a_i·b_j with i + j < L − 3 are left out.
    const CUT: usize = L.saturating_sub(3);
    /// W is the accumulator's 2L + 2 limbs (a wrong pair in `with_limbs`
    /// fails to compile).
    const SIZE: () = assert!(W == 2 * L + 2);

    fn new() -> Self {
        #[allow(clippy::let_unit_value)]
        let _ = Self::SIZE;
        Cols {
            pos: [0; W],
            neg: [0; W],
        }
    }

    #[inline(always)]
    fn clear(&mut self) {
        self.pos = [0; W];
        self.neg = [0; W];
    }

    /// += a·b, a given by its significant limbs `am` and sign.
    #[inline(always)]
    fn mac(&mut self, am: &[u64], a_neg: bool, b: &Fx<L>) {
        let lb = (b.len as usize).min(L);
        if am.is_empty() || lb == 0 {
            return;
        }
        let acc = if a_neg == b.neg {
            &mut self.pos
        } else {
            &mut self.neg
        };
        for (i, &ai) in am.iter().enumerate().take(L) {
            let ai = ai as u128;
            for j in Self::CUT.saturating_sub(i)..lb {
                let p = ai * b.m[j] as u128;
                acc[i + j] += p as u64 as u128;
                acc[i + j + 1] += p >> 64;
            }
        }
    }

    /// The sum rounded toward zero to the fraction limbs ([`Acc::finish`]
    /// with no divisor); `overflow` set where it does not fit.
    fn finish(&self, overflow: &mut bool) -> Fx<L> {
        let limbs = |cols: &[u128; W]| {
            let mut out = [0u64; W];
            let mut carry = 0u128;
            for (o, &c) in out.iter_mut().zip(cols) {
                let t = c + carry;
                *o = t as u64;
                carry = t >> 64;
            }
            out
        };
        let (p, n) = (limbs(&self.pos), limbs(&self.neg));
        let neg = below(&p, &n, 0);
        let (a, b) = if neg { (&n, &p) } else { (&p, &n) };
        let (m, high) = sub_truncated::<L, W>(a, b, 0, 0);
        *overflow |= high;
        let len = m.iter().rposition(|&x| x != 0).map_or(0, |k| k + 1);
        Fx {
            m,
            len: len as u16,
            neg: neg && len > 0,
        }
    }
}

/// a < b, two magnitudes of W limbs compared from the top down to limb
/// `from`.
#[inline(always)]
fn below<const W: usize>(a: &[u64; W], b: &[u64; W], from: usize) -> bool {
    for k in (from..W).rev() {
        if a[k] != b[k] {
            return a[k] < b[k];
        }
    }
    false
}

/// a − b (a ≥ b from limb `from` up; `borrow` comes in from below it) at
/// the products' scale, truncated toward zero to the fraction limbs: the
/// magnitude of an `Fx<L>`, and whether a limb above them is not zero (the
/// result does not fit). [`Acc::finish`]'s subtraction, on arrays.
#[inline(always)]
fn sub_truncated<const L: usize, const W: usize>(
    a: &[u64; W],
    b: &[u64; W],
    from: usize,
    mut borrow: u64,
) -> ([u64; L], bool) {
    let lf = L - 1;
    let mut m = [0u64; L];
    let mut high = 0u64;
    for k in from..W {
        let (d1, b1) = a[k].overflowing_sub(b[k]);
        let (d2, b2) = d1.overflowing_sub(borrow);
        borrow = (b1 as u64) + (b2 as u64);
        if k >= lf + L {
            high |= d2;
        } else if k >= lf {
            m[k - lf] = d2;
        }
    }
    (m, high != 0)
}

/// T_k = 2x·T_{k−1} − T_{k−2}, rounded toward zero to the fraction limbs:
/// [`Acc`]'s `mac`, `add` and `finish` of the same products (those with
/// i + j below the cut left out), so the same bits, with the exact product
/// in a fixed-size array and only its upper limbs combined with T_{k−2}
/// (whose lower limbs, at the product's scale, are zero).
#[inline(always)]
fn next_t<const L: usize, const W: usize>(
    x2: &Fx<L>,
    t1: &Fx<L>,
    t2: &Fx<L>,
    overflow: &mut bool,
) -> Fx<L> {
    let lf = L - 1;
    // the product's magnitude, exactly (less the products left out)
    let mut p = [0u64; W];
    let has_p = x2.len > 0 && t1.len > 0;
    if has_p {
        fixed::mac_mag(&mut p, x2, t1, L.saturating_sub(3));
    }
    // signs: the product's, and −T_{k−2}'s; T_{k−2} at the product's
    // scale (its limbs from the fraction limbs on)
    let p_neg = has_p && x2.neg != t1.neg;
    let q_neg = !t2.neg && t2.len > 0;
    let mut q = [0u64; W];
    q[lf..lf + L].copy_from_slice(&t2.m);
    let (m, high, neg) = if t2.len == 0 || p_neg == q_neg {
        // magnitudes add (the lower limbs carry nothing up: Q has none)
        let mut m = [0u64; L];
        let mut carry = 0u64;
        let mut high = 0u64;
        for k in lf..W {
            let (s1, c1) = p[k].overflowing_add(q[k]);
            let (s2, c2) = s1.overflowing_add(carry);
            carry = (c1 as u64) + (c2 as u64);
            if k >= lf + L {
                high |= s2;
            } else {
                m[k - lf] = s2;
            }
        }
        let neg = if t2.len == 0 { p_neg } else { q_neg };
        (m, high | carry != 0, neg)
    } else if !below(&p, &q, lf) {
        // P − Q·2^(64 lf): the lower limbs of P are truncated away
        let (m, high) = sub_truncated::<L, W>(&p, &q, lf, 0);
        (m, high, p_neg)
    } else {
        // Q·2^(64 lf) − P, truncated: Q − P_hi, less one where P has lower bits
        let low_nonzero = p[..lf].iter().any(|&x| x != 0);
        let (m, high) = sub_truncated::<L, W>(&q, &p, lf, low_nonzero as u64);
        (m, high, q_neg)
    };
    *overflow |= high;
    let len = m.iter().rposition(|&x| x != 0).map_or(0, |k| k + 1);
    Fx {
        m,
        len: len as u16,
        neg: neg && len > 0,
    }
}

fn sums<const L: usize, const W: usize>(
    s: &mut FixedSums,
    x: &Float,
    out: &mut [Float],
) -> Option<bool> {
    let xf: Fx<L> = s.conv.to_fx(x);
    let x2 = xf.mul_small(2);
    let mut one = [0u64; L];
    one[L - 1] = 1;
    let mut basis: Vec<Fx<L>> = Vec::with_capacity(s.n);
    basis.push(Fx {
        m: one,
        len: L as u16,
        neg: false,
    });
    basis.push(xf);
    // the basis by the recurrence, each T_k truncated once
    let mut overflow = false;
    for k in 2..s.n {
        let t = next_t::<L, W>(&x2, &basis[k - 1], &basis[k - 2], &mut overflow);
        basis.push(t);
    }
    // the sums, in columns
    let mut acc = Cols::<L, W>::new();
    let mut at = 0;
    for (i, o) in out.iter_mut().enumerate() {
        acc.clear();
        let len = s.lens.get(i).copied().unwrap_or(0);
        for (k, t) in basis.iter().enumerate().take(len) {
            let c = at + k;
            let sig = s.sig[c] as usize;
            acc.mac(&s.mags[c * L..c * L + sig], s.negs[c], t);
        }
        at += len;
        let r = acc.finish(&mut overflow);
        s.conv.to_float(&r, o);
        *o <<= s.exps.get(i).copied().unwrap_or(0);
    }
    Some(!overflow)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::fixed::Acc;
    use rug::ops::Pow;

    /// The sums as [`Acc`] takes them (the basis, then each fit's products
    /// with a running carry, one `finish` per sum): the reference the
    /// column sums and `next_t` must equal bit for bit.
    fn sums_by_acc<const L: usize>(s: &mut FixedSums, x: &Float, out: &mut [Float]) -> bool {
        let xf: Fx<L> = s.conv.to_fx(x);
        let x2 = xf.mul_small(2);
        let mut one = [0u64; L];
        one[L - 1] = 1;
        let mut basis = vec![
            Fx {
                m: one,
                len: L as u16,
                neg: false,
            },
            xf,
        ];
        let mut acc = Acc::<L>::new();
        for k in 2..s.n {
            acc.clear();
            acc.mac(&x2, &basis[k - 1]);
            let mut back = basis[k - 2];
            back.neg = !back.neg && back.len > 0;
            acc.add(&back);
            basis.push(acc.finish(1));
        }
        let mut at = 0;
        for (i, o) in out.iter_mut().enumerate() {
            acc.clear();
            for (k, t) in basis.iter().enumerate().take(s.lens[i]) {
                let c = at + k;
                let mut m = [0u64; L];
                m.copy_from_slice(&s.mags[c * L..(c + 1) * L]);
                let cf = Fx {
                    m,
                    len: s.sig[c],
                    neg: s.negs[c],
                };
                acc.mac(&cf, t);
            }
            at += s.lens[i];
            let r = acc.finish(1);
            s.conv.to_float(&r, o);
            *o <<= s.exps[i];
        }
        !acc.overflow
    }

    fn same_bits_as_acc<const L: usize, const W: usize>(p: u32, rng: &mut impl FnMut() -> u64) {
        let a = Float::with_val(p, -1i32);
        let b = Float::with_val(p, 1u32);
        for case in 0..6 {
            // fits of several lengths, random limbs, signs, scales and
            // exact zeros (whole coefficients and leading limbs)
            let fits: Vec<ChebFit> = (0..3)
                .map(|f| {
                    let n = 2 + (rng() % 120) as usize;
                    let c = (0..n)
                        .map(|k| {
                            if rng() % 9 == 0 {
                                return Float::new(p);
                            }
                            let mant = Float::with_val(p, rng()) / Float::with_val(p, u64::MAX);
                            let e = -((k as i32 * (p as i32 + 40)) / n as i32) - (rng() % 5) as i32;
                            let v = Float::with_val(p, (mant << e) << (f * 3 - case));
                            if rng() % 2 == 0 {
                                -v
                            } else {
                                v
                            }
                        })
                        .collect();
                    ChebFit {
                        a: a.clone(),
                        b: b.clone(),
                        c,
                        fmax: Float::with_val(p, 1u32),
                    }
                })
                .collect();
            let refs: Vec<&ChebFit> = fits.iter().collect();
            let mut fx = FixedSums::new(&refs, p).expect("fixed point applies");
            assert_eq!(fx.limbs, L, "p = {p}");
            let mut xs: Vec<Float> = vec![Float::with_val(p, -1i32), Float::new(p), b.clone()];
            for _ in 0..12 {
                let m = Float::with_val(p, rng()) / Float::with_val(p, u64::MAX);
                xs.push(Float::with_val(p, m * 2u32) - 1u32);
            }
            // every fixed-point bit of the sums in the output
            let wide = 64 * L as u32 + 64;
            for x in &xs {
                let mut got = vec![Float::new(wide); fits.len()];
                let mut want = vec![Float::new(wide); fits.len()];
                let ok = sums::<L, W>(&mut fx, x, &mut got) == Some(true);
                assert_eq!(ok, sums_by_acc::<L>(&mut fx, x, &mut want), "p {p} x {x}");
                for (g, w) in got.iter().zip(&want) {
                    assert!(
                        g == w && g.is_sign_negative() == w.is_sign_negative(),
                        "p {p}, x {x}: {g} against {w}"
                    );
                }
            }
        }
    }

    /// The column sums and the basis recurrence of `sums` give the same
    /// bits as the running-carry accumulator, at every limb count the
    /// spectral route and the inversions use.
    #[test]
    fn column_sums_are_the_accumulators_bits() {
        let mut rng = crate::numeric::xorshift(0x9e37_79b9_7f4a_7c15);
        // every instantiated count (`with_limbs`), at a precision that
        // takes it: 64(L − 1) − 8 bits
        same_bits_as_acc::<3, 8>(100, &mut rng);
        same_bits_as_acc::<4, 10>(179, &mut rng);
        same_bits_as_acc::<5, 12>(240, &mut rng);
        same_bits_as_acc::<6, 14>(312, &mut rng);
        same_bits_as_acc::<7, 16>(365, &mut rng);
        same_bits_as_acc::<8, 18>(440, &mut rng);
        same_bits_as_acc::<9, 20>(441, &mut rng);
        same_bits_as_acc::<10, 22>(568, &mut rng);
        same_bits_as_acc::<12, 26>(696, &mut rng);
        same_bits_as_acc::<14, 30>(824, &mut rng);
        same_bits_as_acc::<16, 34>(900, &mut rng);
    }

    /// The fixed-point sums against MPFR's, for fits of several lengths and
    /// magnitudes at several precisions, far inside the working precision.
    #[test]
    fn agree_with_the_floating_point_sums() {
        for &p in &[64u32, 171, 226, 400, 700] {
            let a = Float::with_val(p, 0u32);
            let b = Float::with_val(p, 3) / 7u32;
            let fits: Vec<ChebFit> = [(40usize, 1.0f64), (61, -3.5e3), (61, 2.0e-9)]
                .iter()
                .map(|&(n, scale)| {
                    let c = (0..n)
                        .map(|k| {
                            // decaying, alternating, irrational-ish coefficients
                            let mut v = Float::with_val(p, k as u32 + 2).sqrt() * scale;
                            v /= Float::with_val(p, 1.7f64).pow(k as u32);
                            if k % 3 == 1 {
                                -v
                            } else {
                                v
                            }
                        })
                        .collect();
                    ChebFit {
                        a: a.clone(),
                        b: b.clone(),
                        c,
                        fmax: Float::with_val(p, scale.abs()),
                    }
                })
                .collect();
            let refs: Vec<&ChebFit> = fits.iter().collect();
            let mut fx = FixedSums::new(&refs, p).expect("fixed point applies");
            for j in 0..9u32 {
                let v = Float::with_val(p, &b * j) / 8u32;
                let mut out = vec![Float::new(p); fits.len()];
                assert!(fx.eval(&a, &b, &v, &mut out));
                let mut basis = Vec::new();
                ChebFit::basis_into(&a, &b, &v, 61, p, &mut basis);
                for (f, o) in fits.iter().zip(&out) {
                    let want = f.dot(&basis);
                    let tol = (Float::with_val(p, want.abs_ref()) + 1u32) >> (p as i32 - 6);
                    let diff = Float::with_val(p, o - &want).abs();
                    assert!(diff <= tol, "p {p} v {j}/8: {o} vs {want}");
                }
            }
        }
    }

    /// Each fit summed in its own scale: fits of one shape at scales from
    /// 2^−300 to 2^200 (beyond the integer limb), summed together, each
    /// within 2^−(prec−10)·Σ|c_k| of MPFR's sum at twice the precision —
    /// relative to the fit, where one absolute error for all gave the small
    /// fits none of their digits and declined the large ones.
    #[test]
    fn sums_each_fit_in_its_own_scale() {
        for &p in &[128u32, 171, 400] {
            let hp = 2 * p;
            let a = Float::with_val(p, 0u32);
            let b = Float::with_val(p, 5u32) / 3u32;
            let shape: Vec<Float> = (0..48u32)
                .map(|k| {
                    let v =
                        Float::with_val(p, 2 * k + 3).sqrt() / Float::with_val(p, 1.9f64).pow(k);
                    if k % 2 == 1 {
                        -v
                    } else {
                        v
                    }
                })
                .collect();
            let exps = [-300i32, -40, 0, 61, 200];
            let fits: Vec<ChebFit> = exps
                .iter()
                .map(|&e| ChebFit {
                    a: a.clone(),
                    b: b.clone(),
                    c: shape.iter().map(|c| Float::with_val(p, c << e)).collect(),
                    fmax: Float::with_val(p, 1u32) << e,
                })
                .collect();
            let refs: Vec<&ChebFit> = fits.iter().collect();
            let mut fx = FixedSums::new(&refs, p).expect("fixed point applies at any scale");
            for j in 0..7u32 {
                let v = Float::with_val(p, &b * j) / 6u32;
                let mut out = vec![Float::new(p); fits.len()];
                assert!(fx.eval(&a, &b, &v, &mut out));
                let mut basis = Vec::new();
                ChebFit::basis_into(&a, &b, &Float::with_val(hp, &v), 48, hp, &mut basis);
                for ((f, o), e) in fits.iter().zip(&out).zip(exps) {
                    let want = f.dot(&basis);
                    let total = f.c.iter().fold(Float::new(hp), |s, c| s + c.clone().abs());
                    let tol = total >> (p as i32 - 10);
                    let diff = Float::with_val(hp, o - &want).abs();
                    assert!(diff <= tol, "p {p}, scale 2^{e}, v {j}/6: {o} vs {want}");
                }
            }
        }
    }
}
