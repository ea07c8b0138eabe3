//! The events of a conservative phase as roots of polynomials in c = cos θ.
//!
//! Along a conservative motion θ̇² = H/K with H = A_H − 2(g/r)c and K(c) a
//! quadratic, so every force is a rational function of c (and sin θ) with
//! the positive denominator K²: each event that can end the phase — a
//! Coulomb contact's cone |F| = μs N, N1 = 0, parting becoming lawful —
//! is a root of a polynomial with exact rational coefficients (in A_H,
//! which carries the start). Its real roots are isolated (at 64 bits and the
//! bits the coefficients' spread and the values at the phase's ends ask) by
//! the monotone pieces between the roots of its derivatives
//! ([`crate::numeric::poly::sign_change_roots`]: no pair of close roots is
//! missed, unlike a scan), the first in θ (the largest c) is refined by
//! Newton's method at doubling precision, and θ = acos c.

use super::Route;
use crate::error::Result;
use crate::mechanics::dynamics::{Dyn, HPoly, N12Poly};
use crate::model::Which;
use crate::numeric::poly;
use rug::{Float, Rational};

/// Precision at which roots are isolated.
const ISO: u32 = 64;

impl Route {
    /// K²·(r θ̇² − g cos θ): the free relative normal acceleration of the
    /// cylinders (cylinder 2 falling freely, cylinder 1 unaccelerated — so
    /// on every floor of a conservative phase) times K², as a polynomial
    /// in c: r (H K) − g c K². Its rise through 0 while N12 > 0 is where
    /// parting becomes lawful (a branch point).
    pub fn free_normal_poly(&mut self) -> HPoly {
        let fp = self.force_polys();
        let p = self.work.params();
        let r = p.r();
        let gr = Rational::from(&p.g / &r);
        let k = HPoly::constant(&fp.k);
        let c = HPoly::constant(&[Rational::new(), Rational::from(1)]);
        // H K = −2(g/r) c K + A_H K
        let hk = HPoly {
            parts: vec![Vec::new(), fp.k.clone()],
        }
        .add_scaled(&c.mul(&k), &Rational::from(&gr * -2i32));
        let gck2 = c.mul(&k).mul(&k);
        HPoly::default()
            .add_scaled(&hk, &r)
            .add_scaled(&gck2, &Rational::from(-&p.g))
    }

    /// μ² (N K²)² − (1 − c²)(F K²/sin θ)² of a contact while it rolls: ≥ 0
    /// exactly where |F| ≤ μ N (N > 0), so its fall through 0 is where
    /// rolling would first need more friction than μ (a slip onset); and
    /// its μ-free part −(1 − c²)(F K²)², whose size is that of the dip
    /// between the two roots a large μ puts close together (the scale
    /// [`Route::first_root`] isolates them against).
    pub fn cone_poly(&mut self, which: Which, mu: &Rational) -> (HPoly, HPoly) {
        let fp = self.force_polys();
        let (a, b) = match which {
            Which::Floor => (HPoly::linear(&fp.f1), HPoly::linear(&fp.n1)),
            Which::Contact => {
                let m2 = self.work.params().m2.clone();
                let b = HPoly::default().add_scaled(&self.n12_hpoly(), &m2);
                (HPoly::linear(&fp.f21), b)
            }
        };
        let one_m_c2 = HPoly::constant(&[Rational::from(1), Rational::new(), Rational::from(-1)]);
        let mu2 = Rational::from(mu.square_ref());
        let free = HPoly::default().add_scaled(&one_m_c2.mul(&a).mul(&a), &Rational::from(-1));
        let cone = HPoly::default()
            .add_scaled(&b.mul(&b), &mu2)
            .add_scaled(&free, &Rational::from(1));
        (cone, free)
    }

    /// N12·K²/m2 as a polynomial in c ([`N12Poly`], built once).
    pub fn n12_hpoly(&mut self) -> HPoly {
        let np = self
            .caches
            .n12_poly
            .get_or_insert_with(|| N12Poly::new(&self.red, self.work.params()));
        HPoly::linear(&(np.base.clone(), np.per_h.clone()))
    }

    /// N1·K² as a polynomial in c.
    pub fn n1_poly(&mut self) -> HPoly {
        HPoly::linear(&self.force_polys().n1)
    }

    /// The size of `hp`'s terms at c (64 bits): Σ_j |A_H|^j Σ_k |part_jk| |c|^k,
    /// the scale of its rounding.
    pub(super) fn term_size(hp: &HPoly, a_h: &Float, c: &Float) -> Float {
        let (ah, c) = (
            Float::with_val(64, a_h.abs_ref()),
            Float::with_val(64, c.abs_ref()),
        );
        let mut size = Float::new(64);
        let mut pow = Float::with_val(64, 1u32);
        for part in &hp.parts {
            let abs: Vec<Float> = part
                .iter()
                .map(|c| Float::with_val(64, Rational::from(c.abs_ref())))
                .collect();
            let mut s = Float::new(64);
            poly::horner(&abs, &c, &mut s);
            size += s * &pow;
            pow *= &ah;
        }
        size
    }

    /// `hp`'s value at the start c0 = cos θ0 (working frame; or, with
    /// `delta`, at cos(θ0 + δ)) and the bits it was taken at: at `from`
    /// bits, then at twice as many, up to `cap`, until it lies beyond its
    /// rounding (the coefficients, c and Horner's sum at those bits: 2^−(q−16)
    /// of [`Route::term_size`]), or `None` for the value where it is within
    /// its rounding at `cap` (0 to that precision). The same numbers at every
    /// working precision: the ladder depends on `from` and `cap` only.
    pub(super) fn value_resolved(
        &mut self,
        hp: &HPoly,
        delta: Option<&Float>,
        from: u32,
        cap: u32,
    ) -> Result<(Option<Float>, u32)> {
        let mut q = from;
        loop {
            let (c0, a_h) = if q == ISO {
                let d = &self.engine(ISO)?.dynm;
                (d.c0.clone(), N12Poly::a_h(d))
            } else {
                let d = Dyn::new(&self.work, &self.red, q)?;
                let a_h = N12Poly::a_h(&d);
                (d.c0, a_h)
            };
            let c = match delta {
                None => c0,
                Some(d) => {
                    let th0 = self.work.start().theta0.to_float(q);
                    Float::with_val(q, &th0 + d).cos()
                }
            };
            let mut v = Float::new(q);
            poly::horner(&hp.at(&a_h, q), &c, &mut v);
            let bound = Self::term_size(hp, &a_h, &c) >> (q as i32 - 16);
            if Float::with_val(q, v.abs_ref()) > bound {
                return Ok((Some(v), q));
            }
            if q >= cap {
                return Ok((None, q));
            }
            q = (2 * q).min(cap);
        }
    }

    /// The first sign change of `hp` in θ on (θ0, θ_end) (working frame;
    /// `delta_end` = θ_end − θ0, needed to a few bits): δ = θ − θ0 there and
    /// its error bound at `p` bits, or None. `unit`: a polynomial whose size
    /// is the natural scale of `hp`'s values (the μ-free part of a cone
    /// polynomial), or None where that is `hp`'s own.
    ///
    /// A root a hair after the start, or a hair before θs, is isolated at the
    /// bits that resolve the polynomial's value there (up to `start_cap`,
    /// and `resolve_cap` of the `digits` asked at θs): at 64 bits a branch
    /// point 10^-20 after θ0 was merged with the start, one 1.8·10^-21 before
    /// θs with θs, and missed (the motion called unique). `delta_end` is δs
    /// at the run's precision.
    ///
    /// Errors: a root the refinement cannot verify.
    pub fn first_root(
        &mut self,
        name: &str,
        hp: &HPoly,
        unit: Option<&HPoly>,
        delta_end: &Float,
        p: u32,
        digits: u32,
    ) -> Result<Option<(Float, Float)>> {
        let (c0, a_h) = {
            let d = &self.engine(ISO)?.dynm;
            (d.c0.clone(), N12Poly::a_h(d))
        };
        // isolation at 64 bits plus the coefficients' magnitude over the
        // values' natural scale: a cone polynomial carries μ², and for a
        // large μ its two roots around N12 = 0 lie ~1/μ apart with a dip
        // between them of the size of its μ-free part, which 64-bit Horner
        // sums of μ² times larger terms cannot see (the pair would be merged
        // and the slip onset missed). The ratio, not the sum in absolute
        // units: a model in other units (g = 10^-20) has the same roots.
        let coef = hp.at(&a_h, ISO);
        let Some(iso) = isolation_bits(
            &coef,
            &unit.map_or_else(|| coef.clone(), |u| u.at(&a_h, ISO)),
            p,
        ) else {
            // a cone polynomial whose μ² puts its pair of roots around
            // N12 = 0 closer than 2^−(p+64) together: the contact slips,
            // if at all, only that close to θs, a phase whose effect on
            // every value is below this precision's resolution; the
            // closed mode's motion to θs is the motion to the digits (the
            // limit μ → ∞). An isolation at fewer bits merged the pair, or
            // found a sign change its refinement could not (exit 3).
            return Ok(None);
        };
        // and the masses' ratio's bits, for every root (a branch point
        // ~0.12 m2/m1 before θs under a lower cylinder 10^20 times heavier was
        // merged with θs)
        let iso = iso
            + disparity_bits(self.work.params())
            + mass_spread_bits(self.work.params()).unwrap_or(MAX_SPREAD_BITS);
        // and the bits that resolve its value at the start (a root a hair
        // after θ0)
        let cap = self.start_cap(hp, digits)?.max(iso);
        let iso = self.value_resolved(hp, None, iso, cap)?.1;
        // and those that resolve it at the end θs (a branch point ~0.18/k1
        // before θs under k1 = 10^20, ~0.27 k2 under k2 = 10^-20, was merged
        // with θs at 64 bits: the motion called unique): beyond the bits
        // the isolation has, with θs known to the digits' bits, the same in
        // both runs. A value still within its rounding there is θs's own
        // root to those bits.
        let mut end = delta_end.clone();
        let iso = match self.value_resolved(hp, Some(delta_end), iso, iso)? {
            (Some(_), q) => q,
            (None, _) => {
                let q = resolve_cap(digits).max(iso);
                let (ds, _) = self.delta_s(q)?;
                match self.value_resolved(hp, Some(&ds), iso, q)? {
                    (Some(_), q) => {
                        end = ds;
                        q
                    }
                    (None, _) => iso,
                }
            }
        };
        let delta_end = &end;
        // the end of the range at the precision it is known to (a root ~1/μ
        // before θs must not fall outside a 64-bit rounding of cos θs)
        // a cone polynomial's pair of roots near a tangency of the cone (μ a
        // hair below the most friction the motion needs) lies ~√(depth)
        // apart around a dip whose depth is the μ gap Δ: searched with half
        // the digits' bits and 24 more (the slip's effect on the motion is
        // ~20 Δ²: work_s 2.06e-17 and 2.06e-19, t_s shifted 3.2e-17 and
        // 3.2e-19, at Δ = 10^-9 and 10^-10 below the main case's tangency),
        // a floor μ 4·10^-21 below it slipped unseen at 40 to 100 digits. The
        // root found is refined as before
        let search = if unit.is_some() {
            iso.max(crate::numeric::bits_for_digits(digits.max(1)) / 2 + 24)
        } else {
            iso
        };
        let ep = search.max(delta_end.prec());
        let th0 = self.work.start().theta0.to_float(ep);
        let c_end = Float::with_val(ep, &th0 + delta_end).cos();
        let lo = Float::with_val(search, &c_end).max(&Float::with_val(search, -1));
        // c0 at the isolation's bits (a 64-bit c0 would put a root a hair
        // after the start on either side of it)
        let (c0, a_hi) = if search > ISO {
            let d = Dyn::new(&self.work, &self.red, search)?;
            (d.c0.clone(), N12Poly::a_h(&d))
        } else {
            (c0, a_h)
        };
        let roots = poly::sign_change_roots(&hp.at(&a_hi, search), &lo, &c0);
        let Some(start) = roots.into_iter().rev().find(|c| *c < c0 && *c > lo) else {
            return Ok(None);
        };
        let start_full = start;
        let start = Float::with_val(iso, &start_full);
        // refined with the same extra bits: near the root the polynomial is
        // a difference of terms of the coefficients' size
        let mut extra = iso - ISO;
        let refine = |route: &mut Self, extra: u32, start: &Float| -> Result<(Float, Float)> {
            let a_hp = N12Poly::a_h(&Dyn::new(&route.work, &route.red, p + 16 + extra)?);
            let coef = hp.at(&a_hp, p + 16 + extra);
            poly::refine_root(name, &coef, start, p + extra)
        };
        // where the search needed more bits than the isolation (a cone's
        // close pair), a refinement that finds no sign change is retried
        // with them: the pair's dip is below the working precision's reach
        // A pair no refinement confirms lies below what the search's bits
        // resolve: a rounding's sign change near the tangency (μ the
        // program's own mu_floor_max), or a slip whose effect (~20 Δ²) is
        // below the digits asked — no slip onset, as for a pair closer than
        // `isolation_bits` resolves
        let (c, eps) = match refine(self, extra, &start) {
            Err(crate::error::Error::NoSignChange { .. }) if search > iso => {
                extra = search - ISO;
                match refine(self, extra, &Float::with_val(search, &start_full)) {
                    Err(crate::error::Error::NoSignChange { .. }) => return Ok(None),
                    r => r?,
                }
            }
            r => r?,
        };
        // θ and δ = θ − θ0 at the refinement's bits, δ then rounded to p: a
        // root 10^-200 after θ0 is lost in θ's rounding at p bits (δ came
        // out 0 or negative, and its time NaN)
        let q = p + extra;
        let (th, th_err) = crate::numeric::root::acos_newton(&c, q);
        // dθ = −dc / sin θ, sin θ = √(1 − c²) (> 0 on (0, π)); ×(1 + 2^-16)
        let sin = Float::with_val(q, 1u32 - Float::with_val(q, c.square_ref())).sqrt();
        let mut err = Float::with_val(q, &eps / &sin);
        err += Float::with_val(q, &err >> 16);
        err += th_err;
        let th0q = self.work.start().theta0.to_float(q);
        let d = Float::with_val(p, th - th0q);
        // and δ's rounding to p bits (half a unit; θ0's rounding at q bits
        // is in it: q ≥ p)
        err += Float::with_val(q, d.abs_ref()) >> (p as i32 - 1);
        let err = Float::with_val_round(p, &err, rug::float::Round::Up).0;
        if !d.is_finite() || !err.is_finite() {
            // a NaN root was sorted last among the phase's endings and
            // dropped (the angle's seed at cos θ = 1 − 3·10^-16): never again
            return Err(crate::error::Error::NotConverged {
                quantity: name.into(),
                requested: 0,
                reached: "no finite angle for its root".into(),
                detail: "the angle of a root of the phase's polynomial could not be computed"
                    .into(),
            });
        }
        Ok(Some((d, err)))
    }
}

/// The most bits a sign at the start is resolved with: twice the `digits`
/// asked and 128 more. A value at the start still within its rounding there
/// puts any root within ~2^−(cap/2) of θ0 (θ − θ0 ≤ √(2 (c0 − c)) where the
/// polynomial's slope is of its coefficients' size): the start to the
/// digits asked. The same for both runs of a request.
pub(crate) fn resolve_cap(digits: u32) -> u32 {
    2 * crate::numeric::bits_for_digits(digits.max(1)) + 128
}

/// Bits the isolation adds for unequal masses: 2 log2(m2/m1). The
/// polynomials' coefficients are of the heavier cylinder's scale (squared,
/// in a cone polynomial), while near the separation the forces whose roots
/// are sought are of the lighter one's: under an upper cylinder 10^12 times
/// heavier, F21 ~ m1 g where N12 → 0, and the two roots of the cone
/// polynomial around θs (μ N12 = ±|F21|) lie ~m1/(μ m2) apart, with a dip of
/// F21² ~ (m1 g)² between them in sums of terms ~(m2 g)² — merged at 64 bits
/// (the slip onset missed: the rolling model's θs was printed) or split in
/// the wrong place ("no sign change found"). The ratio of the coefficients
/// to the values' scale ([`isolation_bits`]) does not see it: the unit
/// polynomial is of the heavy scale too.
/// Only for a heavier upper cylinder: under a lighter one the polynomials
/// are of the upper cylinder's scale throughout. (Either way the isolation
/// also has [`mass_spread_bits`]: a branch point ~0.12 m2/m1 before θs is told
/// apart; one that is θs to the digits asked is taken as θs by every run,
/// [`crate::motion::sides::apart_from_end`].)
pub(super) fn disparity_bits(p: &crate::model::Params) -> u32 {
    let ratio = Float::with_val(64, Rational::from(&p.m2 / &p.m1));
    let e = ratio.get_exp().unwrap_or(0).max(0).unsigned_abs();
    // below 2^16 the 64 bits hold the dip with room to spare (tested to
    // 10^6, where the gap is 7·10^-6); the bits begin there, so that the
    // ordinary cases keep their bits
    if e <= 16 {
        0
    } else {
        (2 * e).min(8192)
    }
}

/// What a comparison of N1 along the motion needs beyond the scan's 96
/// bits: |log2(m1/m2)| rounded up, either way, where the ratio lies outside
/// [2^−16, 2^16] (0 inside). N1 = m1 g + m2 (g + ÿ2): under a lower cylinder
/// 10^29 times heavier its change along the motion lies below the 96th bit
/// of m1 g (the start was taken for N1's minimum); under one 10^40 times
/// lighter, N1 K² near θs is of the lighter scale in sums of the heavier (a
/// root of N1 a hair past θs was taken for one before it). `None` beyond
/// [`MAX_SPREAD_BITS`]: the comparison is not made (a ratio of 10^2500 and
/// more; the findings that need it say so).
pub(crate) fn mass_spread_bits(p: &crate::model::Params) -> Option<u32> {
    let r = Rational::from(&p.m1 / &p.m2);
    let bound = Rational::from(1u32 << 16);
    if r <= bound && Rational::from(&r * &bound) >= 1u32 {
        return Some(0);
    }
    // 2^(e−1) <= r < 2^e (rounded down to 64 bits, r keeps its exponent):
    // |log2 r| <= e above 1, <= 1 − e below
    let (r64, _) = Float::with_val_round(64, &r, rug::float::Round::Down);
    let e = r64.get_exp().unwrap_or(0);
    let bits = if e > 0 { e } else { 1 - e }.unsigned_abs();
    (bits <= MAX_SPREAD_BITS).then_some(bits)
}

/// The most bits [`mass_spread_bits`] adds (a masses' ratio of about
/// 10^2466): beyond it the N1 findings would isolate roots at hundreds of
/// thousands of bits.
pub(crate) const MAX_SPREAD_BITS: u32 = 8192;

/// The precision at which the sign changes of a polynomial with these
/// coefficients are isolated: 64 bits, plus the binary magnitude of the sum
/// of the coefficients' absolute values over that of `unit`'s (the natural
/// scale of its values) where above 1: Horner's rounding error at c in
/// [−1, 1] is about the sum times 2^−prec, so that a dip of the unit's size
/// between two close roots keeps its sign. Capped at 64 + 8192 bits, or
/// twice the working precision `p` (and 256 bits) where that is more: a
/// pair of roots 2^−(extra/2) apart (a cone's around N12 = 0, ~1/μ) is
/// then resolved wherever the working precision resolves it. `None` where
/// the excess is beyond the cap: the pair lies closer together than the
/// working precision resolves (a μ of 10^1233 and more at 30 digits).
fn isolation_bits(coef: &[Float], unit: &[Float], p: u32) -> Option<u32> {
    // log2 of Σ|c_k|: e + log2 Σ|c_k 2^−e|, the sum in f64 in any units
    let log_sum = |cs: &[Float]| -> Option<f64> {
        let e = crate::numeric::max_exp(cs)?;
        let sum: f64 = cs
            .iter()
            .map(|c| crate::numeric::scaled_f64(c, e).abs())
            .sum();
        Some(f64::from(e) + sum.log2())
    };
    let cap = f64::from(8192u32.max(2 * p + 256));
    let extra = match (log_sum(coef), log_sum(unit)) {
        (Some(a), Some(u)) if a - u > cap => return None,
        (Some(a), Some(u)) if a > u => (a - u).ceil() as u32,
        _ => 0,
    };
    Some(ISO + extra)
}
