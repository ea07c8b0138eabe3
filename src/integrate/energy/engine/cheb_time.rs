//! t(θ) by Chebyshev interpolation of the half-angle integrand in v = √σ:
//! the interpolants on pieces graded towards the start by the Bernstein ρ
//! of the nearest singularity ([`breakpoints`]), the time with its error
//! estimate, and θ as a function of t by Newton's method on their
//! antiderivatives ([`Inverse`]), the trajectory's route at high precision.

use super::Engine;
use crate::numeric::cheb::{self, ChebFit, Roots};
use crate::numeric::gauss;
use rug::Float;

impl Engine {
    /// The half-angle integrand's Chebyshev interpolants over v ∈ [0, √Δσ]
    /// (σ = v²: the start's 1/√σ is gone, the integrand is analytic on the
    /// interval), on pieces graded towards the start (`breakpoints`)
    /// with N per piece from the Bernstein ρ of the nearest singularity
    /// ([`crate::mechanics::dynamics::HalfAngleTime::singular_sin2`], mapped
    /// by v = ±√σ) so that the coefficients fall ~20 bits below the working
    /// precision. `None` when the pieces would pass [`MAX_PIECES`] or a tail
    /// does not fall (then tanh-sinh).
    pub fn cheb_fit(&mut self, dsig: &Float) -> Option<Vec<ChebFit>> {
        self.cheb_fit_graded(dsig, self.cheb_target, WHOLE, MAX_PIECES)
    }

    /// [`Engine::cheb_fit`] with pieces of ρ ≈ `target` each, one piece
    /// only where the whole interval's ρ is at least `whole`, and `None`
    /// beyond `most` pieces.
    fn cheb_fit_graded(
        &mut self,
        dsig: &Float,
        target: f64,
        whole: f64,
        most: usize,
    ) -> Option<Vec<ChebFit>> {
        let p = self.prec();
        let vmax = Float::with_val(p, dsig.sqrt_ref());
        // the singularities in v, absolute
        let v64 = vmax.to_f64();
        let sing: Vec<gauss::C64> = self
            .half
            .singular_sin2(dsig)
            .iter()
            .flat_map(|z| {
                let r = z.sqrt();
                [r, gauss::C64::new(-r.re, -r.im)]
            })
            .map(|y| gauss::C64::new(y.re * v64, y.im * v64))
            .collect();
        let rho_of = |a: f64, b: f64| -> f64 {
            sing.iter()
                .map(|&y| gauss::bernstein_rho(a, b, y))
                .fold(f64::INFINITY, f64::min)
                .min(64.0)
        };
        let cuts = breakpoints(v64, &rho_of, target, whole, most)?;
        let mut fits = Vec::with_capacity(cuts.len());
        let mut a = Float::new(p);
        for (i, &(b64, rho)) in cuts.iter().enumerate() {
            let b = if i + 1 == cuts.len() {
                vmax.clone()
            } else {
                Float::with_val(p, b64)
            };
            let mut need = ((p as f64 + 20.0) / rho.log2()).ceil() as usize + 12;
            let mut done = None;
            for _ in 0..3 {
                if crate::cancel::cancelled() {
                    // the caller's next check reports the cancellation
                    return None;
                }
                let n = cheb::smooth_at_least(need);
                let roots = self.roots.entry(n).or_insert_with(|| Roots::new(n, p));
                let half = &mut self.half;
                let fit = ChebFit::new(&a, &b, roots, p, |v, out| half.eval_v(v, out));
                // the tail must sit below the working precision
                if fit.tail() <= Float::with_val(p, &fit.fmax >> (p as i32 - 4)) {
                    done = Some(fit);
                    break;
                }
                need = need * 3 / 2;
            }
            fits.push(done?);
            a = b;
        }
        Some(fits)
    }

    /// t(Δσ) by Chebyshev interpolation ([`Engine::cheb_fit`]), with its
    /// error estimate ([`Engine::cheb_answer`]).
    pub fn time_cheb(&mut self, dsig: &Float) -> Option<(Float, Float)> {
        let fits = self.cheb_fit(dsig)?;
        let p = self.prec();
        let mut integral = Float::new(p);
        for f in &fits {
            integral += f.integral();
        }
        Some(self.cheb_answer(&fits, integral))
    }

    /// θ(t) for every t in [0, t(δ_end)] from the Chebyshev interpolants of
    /// the half-angle integrand over v ∈ [0, √Δσ(δ_end)] ([`Engine::cheb_fit`])
    /// and their antiderivatives: `None` where [`Engine::cheb_fit`] declines
    /// or δ_end is beyond the half-angle form's range. `inversions`: about
    /// how many times will be inverted; the pieces are cut for them
    /// (`inverse_rho`).
    pub fn inverse(&mut self, delta_end: &Float, inversions: usize) -> Option<Inverse> {
        if *delta_end > self.half_limit || delta_end.is_zero() {
            return None;
        }
        let p = self.prec();
        let dsig = self.half.sigma_of(delta_end);
        // pieces of the table's ρ; where they would be more than
        // TABLE_PIECES (a start near the top grades them towards it), of
        // half that ρ, down to 8, then the default pieces (the fewest
        // terms; never ρ 4, the certificate's own pieces near the top). A
        // refusal of `breakpoints` costs only f64 arithmetic.
        let (want, default) = (inverse_rho(inversions), self.cheb_target);
        let table = [32.0, 16.0, 8.0]
            .into_iter()
            .filter(|&rho| rho <= want && rho > default)
            .find_map(|rho| self.cheb_fit_graded(&dsig, rho, rho.max(WHOLE), TABLE_PIECES));
        let fits = match table {
            Some(f) => f,
            None => self.cheb_fit(&dsig)?,
        };
        // T's error at v in piece i: the interpolants' errors over the
        // pieces up to i (∫|f − p| over [0, v]) and the roundings of
        // Clenshaw's recurrence in piece i; so a v in a short first piece
        // near the start keeps its relative accuracy
        let mut pieces = Vec::with_capacity(fits.len());
        let mut offset = Float::new(p);
        let mut err_left = Float::new(p);
        for f in fits {
            let e_f = self.cheb_answer_raw(std::slice::from_ref(&f));
            err_left += e_f;
            let prim = f.antiderivative();
            let n = prim.c.len() as f64;
            let mut abs_sum = Float::new(p);
            for c in &prim.c {
                abs_sum += Float::with_val(p, c.abs_ref());
            }
            let clenshaw = Float::with_val(p, abs_sum * (4.0 * n)) >> (p as i32);
            let err = Float::with_val(p, &clenshaw + &err_left);
            let next = Float::with_val(p, &offset + prim.eval(&f.b, p));
            // the next pieces' offset carries this piece's T at b (its
            // Clenshaw rounding) and the sum's rounding: many pieces (a
            // table's, or graded near the top) add them up
            err_left += clenshaw;
            err_left += Float::with_val(p, next.abs_ref()) >> (p as i32 - 1);
            pieces.push(Piece::new(f, prim, offset, err));
            offset = next;
        }
        Some(Inverse {
            s0: self.half.s0.clone(),
            c0h: Float::with_val(p, self.half.cos_half0()),
            factor: self.half.factor.clone(),
            pieces,
        })
    }

    /// The summed error of the interpolants `fits` as an integral (in the
    /// integrand's units, before the factor): per piece the interpolant's
    /// uniform error (twice the neglected coefficients, bounded by the last
    /// ones, [`ChebFit::tail`]) plus the transform's rounding (a few units
    /// per FFT level, relative to max |f|), times the piece's length.
    fn cheb_answer_raw(&self, fits: &[ChebFit]) -> Float {
        let p = self.prec();
        let mut e = Float::new(p);
        for fit in fits {
            let len = Float::with_val(p, &fit.b - &fit.a);
            let n = fit.c.len() as f64;
            let mut ei = Float::with_val(p, fit.tail() * 4u32);
            ei += Float::with_val(p, &fit.fmax * (16.0 + 4.0 * n.log2())) >> (p as i32);
            ei *= &len;
            e += ei;
        }
        e
    }

    /// The value `integral` of `fits` as a time, with its error (the
    /// interpolants' errors, `Engine::cheb_answer_raw`, and the roundings
    /// of the factor and the sum).
    pub fn cheb_answer(&self, fits: &[ChebFit], integral: Float) -> (Float, Float) {
        let p = self.prec();
        let mut e = self.cheb_answer_raw(fits);
        let v = Float::with_val(p, integral * &self.half.factor);
        e *= &self.half.factor;
        let ulps = Float::with_val(p, v.abs_ref()) >> (p as i32 - 4);
        e += ulps;
        (v, e)
    }
}

/// One piece where the whole interval's ρ is at least this ([`breakpoints`]).
const WHOLE: f64 = 2.5;

/// The ρ each piece of an [`Inverse`] is cut for, from the number of times
/// it will invert. A piece of ρ needs N ≈ (p + 20)/log2 ρ terms; each
/// inversion sums about two series of N terms at the working precision (and
/// a few at halving precisions), while building costs an integrand
/// evaluation and a share of a transform per term of every piece, once. For
/// a single time the fewest terms in all win (pieces of ρ 2.5–3, often one
/// piece); for a table's hundreds of rows the sums dominate, and shorter
/// pieces of larger ρ (fewer terms each, more of them) cost less. Measured
/// (friction, μ = 0.3, its rolling phase, both working precisions): 1000
/// rows at 300 digits 2.18 s at ρ 3, 1.41 s at 8, 1.19 s at 16, 1.06 s at
/// 32; at 1000 digits 22.9 s at ρ 3 and 13.4 s at 32; 100 rows at 300
/// digits 0.49 s at ρ 3 and 0.39 s at 16; 2 and 10 rows the same at ρ 3, 6
/// and 16, 12% slower at 64. A start near the top grades the pieces towards
/// it, and at a large ρ they may pass [`TABLE_PIECES`]: [`Engine::inverse`]
/// then takes the default pieces.
pub fn inverse_rho(inversions: usize) -> f64 {
    match inversions {
        0..=15 => 3.0,
        16..=63 => 8.0,
        64..=499 => 16.0,
        _ => 32.0,
    }
}

/// Most pieces cut for a table's inversions ([`inverse_rho`]): away from the
/// top a few to some 30 (the main case from θ0 = 1/10: 13 at ρ 32, with 4.3×
/// the default's terms in all; from 1/1000: 30), near it many more, each
/// holding its terms at several precisions; beyond this (from θ0 ≈ 1e-6 at
/// ρ 32) the default pieces, built for the fewest terms.
const TABLE_PIECES: usize = 40;

/// Most pieces of a graded Chebyshev interpolation. Near a singularity at
/// distance d from the start, pieces of ρ = 3 grow by ((ρ+1)/(ρ−1))² = 4
/// each, so a start from rest at θ0 needs about log4(1/√θ0) pieces: 83 for
/// θ0 = 1e-100, 250 for 1e-300.
pub const MAX_PIECES: usize = 256;

/// The pieces' right ends over [0, v_max] and each piece's ρ: one piece
/// where ρ of the whole interval is at least 2.5 (the common case), else
/// pieces from the left whose ρ is ~3 each (the singularities near the
/// start, a start near the top, make the first pieces short: a mesh graded
/// geometrically towards them), the last one to v_max; `target` is that ρ. `None` beyond
/// [`MAX_PIECES`] or for a piece that would be shorter than f64 resolves.
fn breakpoints(
    v_max: f64,
    rho_of: &dyn Fn(f64, f64) -> f64,
    target: f64,
    whole_min: f64,
    most: usize,
) -> Option<Vec<(f64, f64)>> {
    let whole = rho_of(0.0, v_max);
    if whole.is_nan() {
        return None;
    }
    if whole >= whole_min {
        return Some(vec![(v_max, whole)]);
    }
    let mut cuts = Vec::new();
    let mut a = 0.0f64;
    while cuts.len() < most.min(MAX_PIECES) {
        let r = rho_of(a, v_max);
        if r >= target {
            cuts.push((v_max, r));
            return Some(cuts);
        }
        // ρ(a, a + L) falls as L grows: bisect for ρ = TARGET on log L
        // (the first piece near a close singularity may be 1e-50 long)
        let (mut lo, mut hi) = (f64::MIN_POSITIVE.ln(), (v_max - a).ln());
        for _ in 0..80 {
            let m = 0.5 * (lo + hi);
            if rho_of(a, a + m.exp()) >= target {
                lo = m;
            } else {
                hi = m;
            }
        }
        let b = a + lo.exp();
        if b <= a || lo <= f64::MIN_POSITIVE.ln() + 1.0 || rho_of(a, b).is_nan() {
            return None;
        }
        cuts.push((b, rho_of(a, b)));
        a = b;
    }
    None
}

/// One piece of an [`Inverse`]: the integrand's interpolant f on [a, b],
/// its antiderivative T from a (plus `offset`, T at a), their copies at
/// lower precisions and in `f64`, and κ for the Newton error.
struct Piece {
    f: ChebFit,
    prim: ChebFit,
    offset: Float,
    /// (precision, T's and f's coefficients rounded to it) for the first steps.
    lower: Vec<(u32, ChebFit, ChebFit)>,
    /// T's and f's coefficients as `f64`, for the seed.
    seed: (Vec<f64>, Vec<f64>),
    offset64: f64,
    /// Bound on |T − T_true| over the piece (estimated, see
    /// [`Engine::inverse`]).
    err_tau: Float,
    /// The Chebyshev coefficients of df/dx, for Newton's error at a root
    /// (κ = |f'/2f| there: a step from an error e leaves about κ e²).
    dseed: Vec<f64>,
}

impl Piece {
    fn new(f: ChebFit, prim: ChebFit, offset: Float, err_tau: Float) -> Self {
        let p = f.prec();
        // the Newton steps' precisions, halving down from p/2 + 32 to ≥ 96
        // (each step doubles the correct bits from the f64 seed's ~50)
        let mut qs = Vec::new();
        let mut q = p / 2 + 32;
        while q < p && q >= 96 {
            qs.push(q);
            q = q / 2 + 32;
        }
        qs.push(96.min(p));
        qs.dedup();
        let lower = qs
            .into_iter()
            .rev()
            .map(|q| (q, prim.rounded(q), f.rounded(q / 2 + 32)))
            .collect();
        // f' in x, for Newton's error at the root found (f64: a size only)
        let half = Float::with_val(64, &f.b - &f.a).to_f64() / 2.0;
        let dseed = f.derivative().to_f64().iter().map(|d| d * half).collect();
        let seed = (prim.to_f64(), f.to_f64());
        Piece {
            offset64: offset.to_f64(),
            f,
            prim,
            offset,
            lower,
            seed,
            dseed,
            err_tau,
        }
    }
}

/// θ as a function of t by Newton's method on the Chebyshev antiderivative
/// T(v) of the half-angle integrand (t = F·T(v), σ = v², s = sin(θ/2) = s0 +
/// σ), built by [`Engine::inverse`]. One inversion costs about two Clenshaw
/// evaluations of N terms at the working precision (the first Newton steps
/// at halving precisions, each doubling the correct bits from an `f64`
/// seed), against a Taylor run whose cost grows like the cube of the
/// precision: the trajectory's route at high precision.
pub struct Inverse {
    s0: Float,
    c0h: Float,
    factor: Float,
    pieces: Vec<Piece>,
}

/// A series in x ∈ [−1, 1], in f64.
fn clenshaw64_x(c: &[f64], x: f64) -> f64 {
    ChebFit::eval_f64(c, -1.0, 1.0, x)
}

impl Inverse {
    /// x ∈ [−1, 1] with T(x) = τ on the piece, by Newton's method
    /// safeguarded by bisection in `f64` (T increases: f > 0 inside), as v
    /// relative to the piece's left end.
    fn seed64(pc: &Piece, t64: f64, half64: f64) -> f64 {
        let (cp, cf) = (&pc.seed.0, &pc.seed.1);
        let (mut lo, mut hi) = (-1.0f64, 1.0f64);
        let mut x = (2.0 * t64 / clenshaw64_x(cp, 1.0) - 1.0).clamp(-1.0, 1.0);
        for _ in 0..200 {
            let r = clenshaw64_x(cp, x) - t64;
            if r > 0.0 {
                hi = x;
            } else {
                lo = x;
            }
            let d = clenshaw64_x(cf, x) * half64;
            let mut nx = x - r / d;
            if !(nx > lo && nx < hi) {
                nx = 0.5 * (lo + hi);
            }
            if (nx - x).abs() <= 1e-15 * (1.0 + x.abs()) {
                x = nx;
                break;
            }
            x = nx;
        }
        (x + 1.0) * half64
    }

    /// The seed for a tiny τ at the start (v = 0) from T's leading term:
    /// T ≈ f(0)·v from rest, T ≈ f'(0)·v²/2 from a moving start (where the
    /// integrand in v vanishes at 0). In `Float` at 64 bits, whose exponent
    /// range holds any τ (a time of 1e-400).
    fn seed_near_start(pc: &Piece, tau: &Float, half64: f64) -> Float {
        let p = pc.f.prec();
        let f0 = clenshaw64_x(&pc.seed.1, -1.0);
        let tau = Float::with_val(64, tau);
        let v = if f0 > 1e-12 * clenshaw64_x(&pc.seed.1, 1.0).abs() {
            tau / f0
        } else {
            let d0 = (clenshaw64_x(&pc.dseed, -1.0) / half64)
                .abs()
                .max(f64::MIN_POSITIVE);
            (tau * 2u32 / d0).sqrt()
        };
        Float::with_val(p, v)
    }

    /// δ = θ − θ0 at time `t` (0 ≤ t ≤ t(δ_end)) and its error bound, at
    /// the working precision.
    pub fn delta_at(&self, t: &Float) -> (Float, Float) {
        let p = self.s0.prec();
        let tau = Float::with_val(p, t / &self.factor);
        if tau.is_zero() {
            return (Float::new(p), Float::new(p));
        }
        let tau64 = tau.to_f64();
        // the piece: the last whose T at its left end is ≤ τ
        let pc = self
            .pieces
            .iter()
            .rev()
            .find(|pc| pc.offset64 <= tau64)
            .unwrap_or(&self.pieces[0]);
        let tau_rel = Float::with_val(p, &tau - &pc.offset);
        let (a64, b64) = (pc.f.a.to_f64(), pc.f.b.to_f64());
        let half64 = (b64 - a64) / 2.0;
        let cf = &pc.seed.1;
        // lift: how many bits τ lies below T's span over the piece. At the
        // start of the first piece a tiny τ (a tiny time) cancels in any
        // evaluation of T at a fixed precision: the seed then comes from T's
        // leading term at v = 0, and every Newton step works `lift` bits
        // higher so that τ keeps its relative accuracy.
        let span_exp = clenshaw64_x(&pc.seed.0, 1.0).abs().log2().ceil() as i64;
        let lift = match tau_rel.get_exp() {
            Some(e) if pc.f.a.is_zero() => (span_exp - e as i64 - 30).max(0) as u32,
            _ => 0,
        };
        let mut v = if lift > 0 {
            Self::seed_near_start(pc, &tau_rel, half64)
        } else {
            Float::with_val(p, Self::seed64(pc, tau_rel.to_f64(), half64)) + &pc.f.a
        };
        // Newton steps, each doubling the correct bits
        for (q, prim, f) in &pc.lower {
            let (r, d) = if lift == 0 {
                let vq = Float::with_val(*q, &v);
                (
                    Float::with_val(*q, prim.eval(&vq, *q) - &tau_rel),
                    f.eval(&vq, f.prec()),
                )
            } else {
                let (qt, qf) = ((q + lift).min(p), (f.prec() + lift).min(p));
                let vq = Float::with_val(qt, &v);
                (
                    Float::with_val(qt, pc.prim.eval(&vq, qt) - &tau_rel),
                    pc.f.eval(&Float::with_val(qf, &v), qf),
                )
            };
            v -= Float::with_val(*q, r / d);
        }
        let half = (p / 2 + 32 + lift).min(p);
        let fh = pc.f.eval(&Float::with_val(half, &v), half);
        let r = Float::with_val(p, pc.prim.eval(&v, p) - &tau_rel);
        let step = Float::with_val(p, &r / &fh);
        v -= &step;
        // the last step leaves κ·step² of Newton's error, κ = |f'/2f| at the
        // root (×4; in v: df/dv = df/dx · 2/(b − a)), and T's own error
        // moves the root by err_T/f. κ is local: with θ̇0 ≠ 0 the integrand
        // vanishes at v = 0, where no bound over the piece is finite.
        let xr = ((2.0 * v.to_f64() - a64 - b64) / (b64 - a64)).clamp(-1.0, 1.0);
        let kappa =
            4.0 * (clenshaw64_x(&pc.dseed, xr) / (2.0 * clenshaw64_x(cf, xr) * half64)).abs();
        let kappa = if kappa.is_finite() {
            kappa.max(1.0)
        } else {
            1e30
        };
        let mut err_v = Float::with_val(p, &pc.err_tau / &fh);
        err_v += Float::with_val(p, step.square_ref()) * kappa;
        err_v += Float::with_val(p, &err_v >> 8);
        err_v += Float::with_val(p, v.abs_ref()) >> (p as i32 - 2);
        // δ = 2 asin(s c0 − s0 c), s c0 − s0 c = σ(σ + 2s0)/(s c0 + s0 c)
        let sigma = Float::with_val(p, v.square_ref());
        let s = Float::with_val(p, &self.s0 + &sigma);
        let c = Float::with_val(p, 1u32 - Float::with_val(p, s.square_ref())).sqrt();
        let num = Float::with_val(p, &sigma + Float::with_val(p, &self.s0 * 2u32)) * &sigma;
        let den = Float::with_val(p, &s * &self.c0h) + Float::with_val(p, &self.s0 * &c);
        let delta = Float::with_val(p, num / den).asin() * 2u32;
        // dδ/dv = (dδ/dσ)(2v) = 4v/cos(θ/2), cos(θ/2) = c
        let mut err = Float::with_val(p, &err_v * &v) * 4u32;
        err /= &c;
        err += Float::with_val(p, delta.abs_ref()) >> (p as i32 - 6);
        (delta, err)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::Exact;
    use crate::mechanics::Reduced;
    use crate::model::{Ideal, Params, VARIANTS};

    /// The pieces cut for a table (ρ 32, many short pieces) and for one time
    /// (ρ 3, one long piece here) invert to the same δ within their error
    /// bounds, bounds near the working precision, on every contact variant
    /// from rest and from a moving start; and the times of the δ found are
    /// the times asked, by the independent tanh-sinh route.
    #[test]
    fn pieces_cut_for_many_inversions_invert_as_the_default_ones() {
        let p = 700;
        for (floor, contact) in VARIANTS {
            for start in super::super::tests::rest_and_moving_starts() {
                let tag = format!("{floor:?} {contact:?} {}", start.theta0);
                let model = Ideal::new(Params::identical_solid(), floor, contact, start).unwrap();
                let red = Reduced::new(&model).unwrap();
                let mut e = Engine::new(&model, &red, p).unwrap();
                let d_end = Float::with_val(p, 7u32) / 10u32;
                let one = e.inverse(&d_end, 1).expect("default pieces");
                let many = e.inverse(&d_end, 1000).expect("pieces for a table");
                assert!(
                    many.pieces.len() > one.pieces.len() + 2,
                    "{tag}: {} and {} pieces",
                    many.pieces.len(),
                    one.pieces.len()
                );
                e.use_cheb = false;
                let (t_end, _) = e.time(&d_end);
                let tiny = Float::with_val(p, 1u32) >> (p as i32 - 16);
                for k in 1..20u32 {
                    let t = Float::with_val(p, &t_end * k) / 20u32;
                    let (d1, e1) = one.delta_at(&t);
                    let (d2, e2) = many.delta_at(&t);
                    let diff = Float::with_val(p, &d1 - &d2).abs();
                    assert!(diff <= Float::with_val(p, &e1 + &e2), "{tag} t = {t:.6}");
                    assert!(e2 <= tiny, "{tag}: bound {e2:e}");
                    // t(δ) back by tanh-sinh, within its bound and what
                    // δ's bound moves t by (e2·dt/dδ, twice): the higher
                    // run's stopping rule, whose estimate is a bound (the
                    // lower run's quadratic extrapolation is not one, and is
                    // not read as one: here it was 750× short once)
                    let (tb, terr, _) = e.time_fast(&d2, true, false);
                    let moved = Float::with_val(p, &e2 * e.inv_thetadot(&d2)) * 2u32;
                    let room = Float::with_val(p, &terr + &moved)
                        + (Float::with_val(p, &t) >> (p as i32 - 8));
                    assert!(
                        Float::with_val(p, &tb - &t).abs() <= room,
                        "{tag} t = {t:.6}: off by {:.3e}, room {room:.3e}",
                        Float::with_val(p, &tb - &t)
                    );
                }
            }
        }
    }

    /// The main case from rest at `theta0`: its engine at `p` bits and the
    /// inverses to `d_end` for one time and for a table's 1000.
    fn one_and_many(theta0: &str, p: u32, d_end: &Float) -> (Engine, Inverse, Inverse) {
        let m = Ideal::paper_default(Exact::parse("t", theta0, false).unwrap());
        let red = Reduced::new(&m).unwrap();
        let mut e = Engine::new(&m, &red, p).unwrap();
        let one = e.inverse(d_end, 1).expect("default pieces");
        let many = e.inverse(d_end, 1000).expect("pieces for a table");
        (e, one, many)
    }

    /// Near the top the pieces are graded towards the start, and the more
    /// of them the larger ρ: from θ0 = 1e-10 those of ρ 32 would pass
    /// [`TABLE_PIECES`] and the table's inverse takes ρ 16 (more pieces than
    /// the default's, at most TABLE_PIECES), agreeing with the default
    /// pieces within the bounds.
    #[test]
    fn a_start_near_the_top_takes_a_smaller_rho() {
        let p = 700;
        let d_end = Float::with_val(p, 4u32) / 5u32;
        let (mut e, one, many) = one_and_many("1e-10", p, &d_end);
        assert!(
            many.pieces.len() > one.pieces.len() && many.pieces.len() <= TABLE_PIECES,
            "{} and {} pieces",
            many.pieces.len(),
            one.pieces.len()
        );
        e.use_cheb = false;
        let (t_end, _) = e.time(&d_end);
        for k in 1..10u32 {
            let t = Float::with_val(p, &t_end * k) / 10u32;
            let ((d1, e1), (d2, e2)) = (one.delta_at(&t), many.delta_at(&t));
            let diff = Float::with_val(p, &d1 - &d2).abs();
            assert!(diff <= Float::with_val(p, &e1 + &e2), "t = {t:.6}");
        }
    }

    /// From θ0 = 1e-100 even pieces of ρ 8 would pass [`TABLE_PIECES`]: the
    /// default pieces, not a refusal.
    #[test]
    fn from_very_near_the_top_the_default_pieces() {
        let p = 700;
        let d_end = Float::with_val(p, 1u32) / 2u32;
        let (_, one, many) = one_and_many("1e-100", p, &d_end);
        assert_eq!(many.pieces.len(), one.pieces.len());
        assert!(
            one.pieces.len() > TABLE_PIECES,
            "{} pieces",
            one.pieces.len()
        );
    }
}
