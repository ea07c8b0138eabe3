//! A Taylor-series (automatic differentiation) integrator for the reduced
//! equation of motion θ̈ = F(θ), F(θ) = sin θ · P(cos θ) / K(cos θ)², with P
//! and K quadratics in c = cos θ, with dense output.
//!
//! Every contact model reduces to this form: K θ̇² = H(c) (the energy
//! integral) turns θ̈ = sin θ (g/r + ½ K'(c) θ̇²)/K into a function of θ alone
//! (`Oracle` builds P from the model; see `Dyn`).
//!
//! # Method
//! On a step from T with the series variable u = (t − T)/H (H a power of
//! two), the coefficients X_k of θ(u) = Σ X_k u^k follow from X_0 = θ(T),
//! X_1 = H θ̇(T) and, for k = 0, 1, …, the coefficient recurrences of
//! sin/cos (S_k = Σ j X_j C_{k−j}/k, C_k = −Σ j X_j S_{k−j}/k), of c², of K,
//! K², P and of the quotient A = S·P/K², then X_{k+2} = H² A_k/((k+1)(k+2)).
//! That is about 5 N²/2 multiplications for order N.
//!
//! The coefficients are fixed-point integers (`rug::Integer`, value·2^F, F
//! the working precision plus guard bits): a product of two scaled
//! coefficients X_j·Y_{k−j} is an exact integer product, a sum of them is
//! exact, and each coefficient is rounded once. The scaled coefficients decay
//! geometrically, so their integers shrink with k and the convolutions cost
//! about half of the full-length products — the same effect as giving each
//! coefficient only the precision it needs.
//!
//! Order N = ⌈(p + 8)·ln 2 / 2⌉ + 1 (Jorba and Zou's optimum for the
//! tolerance 2^-(p+8)); the step h is the largest with
//! |X_k|(h/H)^k ≤ 2^-(p+8) for k = N−2, N−1, N (at most H, so that |u| ≤ 1
//! and no fixed-point error is amplified). The series stays valid over the
//! whole step, so every output time inside it is one Horner evaluation
//! (dense output), with the high-order terms that are below 2^-F at that u
//! left out. Step ends are short binary numbers, so times add up exactly.
//!
//! # Error estimate (accuracy kind: *estimated*)
//! Per step: the truncation |X_{N−2}|u^{N−2} + |X_{N−1}|u^{N−1} + |X_N|u^N
//! (for θ̇ its derivative), the fixed-point rounding (a few units of 2^-F per
//! coefficient, times the order), and the error carried in from earlier
//! steps, amplified by e^(Λ τ) with Λ = 1.25·max(1, |F'(θ)|) at both ends of
//! the step (the growth rate of the linearised equation in the max-norm of
//! (δθ, δθ̇)). The oracle adds an independent check: the energy quadrature
//! t(θ) must bracket the last output time (see `Oracle`), and the precision
//! ladder compares two runs at two precisions (and hence two orders and two
//! step sequences).
//!
//! `f64` is used for control only: step-size choice, growth rates and the
//! log2 of error estimates (which do not underflow as logarithms).

use super::fixed::{self, Acc, Fx};
use crate::error::{Error, Result};
use rug::{Assign, Float};

/// The right-hand side θ̈ = sin θ (e0 + e1 c + e2 c²) / (k0 + k1 c + k2 c²)².
#[derive(Debug, Clone)]
pub struct Conservative {
    /// P's coefficients (ascending in c).
    pub e: [Float; 3],
    /// K's coefficients (ascending in c).
    pub k: [Float; 3],
}

impl Conservative {
    /// F(θ) and F'(θ) in `f64` (for the growth-rate control only).
    fn f_and_df(&self, theta: f64) -> (f64, f64) {
        let (s, c) = theta.sin_cos();
        let e: Vec<f64> = self.e.iter().map(|x| x.to_f64()).collect();
        let k: Vec<f64> = self.k.iter().map(|x| x.to_f64()).collect();
        let p = e[0] + c * (e[1] + c * e[2]);
        let dp = e[1] + 2.0 * c * e[2];
        let kk = k[0] + c * (k[1] + c * k[2]);
        let dk = k[1] + 2.0 * c * k[2];
        let f = s * p / (kk * kk);
        // d/dθ: c P/K² + s (−s) (P' K − 2 P K')/K³
        let df = (c * p * kk + s * s * (2.0 * p * dk - dp * kk)) / (kk * kk * kk);
        (f, df)
    }
}

/// One step of a run.
#[derive(Debug, Clone)]
struct Step<const L: usize> {
    /// Start time.
    t0: Float,
    /// End time.
    t1: Float,
    /// 1/H.
    inv_h: Float,
    /// δ = θ − θ0 at t0.
    delta0: Float,
    /// Scaled coefficients X_0..X_N (fixed point).
    x: Vec<Fx<L>>,
    /// log2 of the carried error at t0.
    err0: f64,
    /// Growth rate on the step.
    lambda: f64,
    /// log2 of the rounding error of one evaluation.
    round: f64,
    /// log2 |X_k| for the last three orders (truncation estimate).
    tail: [(f64, f64); 3],
    /// log2 |X_k| for every k (to cut each evaluation's series short).
    lx: Vec<f64>,
}

/// The steps of a run at one limb count, and scratch for dense output.
#[derive(Debug, Clone)]
struct Run<const L: usize> {
    prec: u32,
    order: usize,
    steps: Vec<Step<L>>,
    prod: Vec<u64>,
    conv: fixed::Conv,
    tau: Float,
    inc: Float,
}

/// Dense output of a run, whatever its limb count.
trait Dense: std::fmt::Debug {
    fn delta_at(&mut self, t: &Float) -> Option<(Float, Float)>;
    fn steps(&self) -> usize;
}

/// A run of the integrator: dense output for t ∈ [0, t_end].
#[derive(Debug)]
pub struct TaylorRun {
    order: usize,
    time_prec: u32,
    inner: Box<dyn Dense>,
    /// Multiply-adds done for the coefficients (for reports).
    pub work: u64,
}

/// Fraction bits beyond the working precision. Few: the rounding of the
/// ~8N operations per coefficient (log2(8N) bits) is part of the error
/// estimate, and the ladder's precisions already carry 24 guard bits over
/// the requested digits; more fraction bits would mostly cost a limb.
fn guard_bits(_prec: u32) -> u32 {
    4
}

/// Limbs for working precision `prec` and `extra` bits (one integer limb).
fn limbs(prec: u32, extra: u32) -> Option<usize> {
    let lf = (prec + guard_bits(prec) + extra).div_ceil(64) as usize;
    fixed::limbs_for(lf + 1)
}

/// Fraction bits a run at working precision `prec` carries beyond its own
/// need for free: its limb count's fraction bits less `prec` and the guard
/// bits (an output needing no more than these extra bits is as accurate
/// from a run without extra bits).
pub fn spare_frac_bits(prec: u32) -> u32 {
    let l = limbs(prec, 0).unwrap_or(fixed::SIZES[fixed::SIZES.len() - 1]) as u32;
    (64 * (l - 1)).saturating_sub(prec + guard_bits(prec))
}

/// The precision (bits) at which times should be given to [`integrate`] and
/// [`TaylorRun::delta_at`] for working precision `prec` and `extra` bits.
pub fn time_prec_for(prec: u32, extra: u32) -> u32 {
    let l = limbs(prec, extra).unwrap_or(fixed::SIZES[fixed::SIZES.len() - 1]);
    64 * l as u32 + 32
}

/// The order used at working precision `prec`.
pub fn order_for(prec: u32) -> usize {
    ((prec as f64 + 8.0) * std::f64::consts::LN_2 / 2.0).ceil() as usize + 1
}

/// log2(2^a + 2^b).
fn log2_add(a: f64, b: f64) -> f64 {
    let (hi, lo) = if a >= b { (a, b) } else { (b, a) };
    if lo == f64::NEG_INFINITY {
        return hi;
    }
    hi + (1.0 + (lo - hi).exp2()).log2()
}

/// Series workspace at one limb count.
///
/// The quantities are kept O(1) (values below 1 leave the fixed-point integer
/// limb empty, and an overflow would be wrong): K is divided by κ (a power of
/// two with |k_i|/κ ≤ 1), P by κ², and P is multiplied by H² per step, so
/// that the series A of H²·θ̈ is computed directly and
/// X_{k+2} = A_k/((k+1)(k+2)). With H near the step size the scaled
/// coefficients are at most about 1; a result that does not fit raises the
/// overflow flag and the step is redone with H halved.
struct Series<const L: usize> {
    n: usize,
    x: Vec<Fx<L>>,
    d: Vec<Fx<L>>,
    s: Vec<Fx<L>>,
    c: Vec<Fx<L>>,
    c2: Vec<Fx<L>>,
    kser: Vec<Fx<L>>,
    kk: Vec<Fx<L>>,
    pser: Vec<Fx<L>>,
    a: Vec<Fx<L>>,
    /// K/κ.
    k: [Fx<L>; 3],
    /// P/κ² as Floats (scaled by H² per step).
    e: [Float; 3],
    /// κ² (Float).
    kappa2: Float,
    acc: Acc<L>,
    work: u64,
}

impl<const L: usize> Series<L> {
    fn new(rhs: &Conservative, n: usize) -> Self {
        let v = || vec![Fx::<L>::ZERO; n + 1];
        let pw = 64 * L as u32 + 32;
        let kmax = rhs
            .k
            .iter()
            .map(|x| x.to_f64().abs())
            .fold(0f64, f64::max)
            .max(1e-300);
        let kexp = kmax.log2().ceil() as i32;
        let kappa = Float::with_val(pw, 1u32) << kexp;
        let kappa2 = Float::with_val(pw, kappa.square_ref());
        let ks = |i: usize| Fx::from_float(&Float::with_val(pw, &rhs.k[i] / &kappa));
        let es = |i: usize| Float::with_val(pw, &rhs.e[i] / &kappa2);
        Series {
            n,
            x: v(),
            d: v(),
            s: v(),
            c: v(),
            c2: v(),
            kser: v(),
            kk: v(),
            pser: v(),
            a: v(),
            k: [ks(0), ks(1), ks(2)],
            e: [es(0), es(1), es(2)],
            kappa2,
            acc: Acc::new(),
            work: 0,
        }
    }

    /// Fills X_0..X_N for θ(T) = theta, θ̇(T) = thetadot and step scale H;
    /// false if a value overflowed (H too large for this step).
    fn compute(&mut self, rhs: &Conservative, theta: &Float, thetadot: &Float, h: &Float) -> bool {
        let n = self.n;
        let pw = 64 * L as u32 + 32;
        self.acc.overflow = false;
        self.x[0] = Fx::from_float(theta);
        let v1 = Float::with_val(pw, thetadot * h);
        if v1.to_f64().abs() >= 1e12 {
            return false;
        }
        self.x[1] = Fx::from_float(&v1);
        let (sn, cs) = Float::with_val(pw, theta).sin_cos(Float::new(pw));
        self.s[0] = Fx::from_float(&sn);
        self.c[0] = Fx::from_float(&cs);
        // κ²/K(c0)² and the per-step P·H²/κ²
        let kv = Float::with_val(pw, &rhs.k[2] * &cs) + &rhs.k[1];
        let kv = Float::with_val(pw, kv * &cs) + &rhs.k[0];
        let rinv = Float::with_val(pw, &self.kappa2 / Float::with_val(pw, kv.square_ref()));
        if rinv.to_f64() >= 1e12 {
            return false;
        }
        let rinv = Fx::<L>::from_float(&rinv);
        let h2 = Float::with_val(pw, h.square_ref());
        let mut e = [Fx::<L>::ZERO; 3];
        for (o, ei) in e.iter_mut().zip(&self.e) {
            let v = Float::with_val(pw, ei * &h2);
            if v.to_f64().abs() >= 1e12 {
                return false;
            }
            *o = Fx::from_float(&v);
        }
        self.d[0] = Fx::ZERO;
        self.d[1] = self.x[1];
        let Series {
            x,
            d,
            s,
            c,
            c2,
            kser,
            kk,
            pser,
            a,
            k: kc,
            acc,
            work,
            ..
        } = self;
        for k in 0..=n.saturating_sub(2) {
            if k >= 1 {
                // S_k = Σ_{j=1}^k j X_j C_{k−j} / k ; C_k = −Σ j X_j S_{k−j} / k
                acc.clear();
                for j in 1..=k {
                    acc.mac(&d[j], &c[k - j]);
                }
                s[k] = acc.finish(k as u64);
                acc.clear();
                for j in 1..=k {
                    acc.msub(&d[j], &s[k - j]);
                }
                c[k] = acc.finish(k as u64);
            }
            // c² (symmetric)
            acc.clear();
            for j in 0..k.div_ceil(2) {
                acc.mac(&c[j], &c[k - j]);
            }
            acc.double();
            if k % 2 == 0 {
                acc.mac(&c[k / 2], &c[k / 2]);
            }
            c2[k] = acc.finish(1);
            // K_k = k1 C_k + k2 C2_k (+ k0), P_k = e1 C_k + e2 C2_k (+ e0)
            acc.clear();
            acc.mac(&kc[1], &c[k]);
            acc.mac(&kc[2], &c2[k]);
            if k == 0 {
                acc.add(&kc[0]);
            }
            kser[k] = acc.finish(1);
            acc.clear();
            acc.mac(&e[1], &c[k]);
            acc.mac(&e[2], &c2[k]);
            if k == 0 {
                acc.add(&e[0]);
            }
            pser[k] = acc.finish(1);
            // K² (symmetric)
            acc.clear();
            for j in 0..k.div_ceil(2) {
                acc.mac(&kser[j], &kser[k - j]);
            }
            acc.double();
            if k % 2 == 0 {
                acc.mac(&kser[k / 2], &kser[k / 2]);
            }
            kk[k] = acc.finish(1);
            // A_k = (Σ_j S_j P_{k−j} − Σ_{j≥1} KK_j A_{k−j}) / KK_0
            acc.clear();
            for j in 0..=k {
                acc.mac(&s[j], &pser[k - j]);
            }
            for j in 1..=k {
                acc.msub(&kk[j], &a[k - j]);
            }
            let num = acc.finish(1);
            acc.clear();
            acc.mac(&num, &rinv);
            a[k] = acc.finish(1);
            *work += 5 * k as u64 + 7;
            // X_{k+2} = A_k / ((k+1)(k+2)), D_{k+2} = (k+2) X_{k+2}
            let idx = k + 2;
            if idx <= n {
                x[idx] = a[k].div_small(((k + 1) * (k + 2)) as u64);
                d[idx] = x[idx].mul_small(idx as u64);
            }
        }
        !acc.overflow
    }
}

/// Integrates from θ(0) = `theta0`, θ̇(0) = `thetadot0` to `t_end` ≥ 0 at
/// working precision `prec`, with `extra_frac` more fractional bits (for
/// outputs at very small times, where δ = θ − θ0 is tiny).
///
/// Errors: [`Error::NotConverged`] if a step size collapses (a singularity of
/// θ(t) on the way: not expected for a motion that stays in contact) or the
/// precision is beyond the largest instantiated limb count.
pub fn integrate(
    rhs: &Conservative,
    theta0: &Float,
    thetadot0: &Float,
    t_end: &Float,
    prec: u32,
    extra_frac: u32,
) -> Result<TaylorRun> {
    macro_rules! go {
        ($($l:literal),*) => {
            match limbs(prec, extra_frac) {
                $(Some($l) => run::<$l>(rhs, theta0, thetadot0, t_end, prec),)*
                _ => Err(Error::NotConverged {
                    quantity: "theta(t)".into(),
                    requested: 0,
                    reached: format!("no Taylor integrator for {prec} bits"),
                    detail: format!("at most {} limbs", fixed::SIZES[fixed::SIZES.len() - 1]),
                }),
            }
        };
    }
    go!(2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 14, 16, 20, 24, 32, 40, 48, 64, 80, 96, 128, 160, 192, 256)
}

fn collapsed(prec: u32, t: &Float) -> Error {
    Error::NotConverged {
        quantity: "theta(t)".into(),
        requested: 0,
        reached: format!("Taylor step size collapsed at {prec} bits"),
        detail: format!("t = {}", t.to_f64()),
    }
}

fn run<const L: usize>(
    rhs: &Conservative,
    theta0: &Float,
    thetadot0: &Float,
    t_end: &Float,
    prec: u32,
) -> Result<TaylorRun> {
    let frac = 64 * (L as u32 - 1);
    let n = order_for(prec);
    let pw = frac + 96;
    let log_tol = -(prec as f64 + 8.0);
    let mut ser = Series::<L>::new(rhs, n);
    let mut prod = vec![0u64; 2 * L + 2];
    let mut steps: Vec<Step<L>> = Vec::new();
    let mut t = Float::new(pw);
    let th0 = Float::with_val(pw, theta0);
    let mut delta = Float::new(pw);
    let mut theta = th0.clone();
    let mut thetadot = Float::with_val(pw, thetadot0);
    let t_end = Float::with_val(pw, t_end);
    // the growth rate of errors, in the norm max(|δθ|, |δθ̇|/ω): ω ≥ √|F'|
    // along the step (and ≥ 1/t_end, which bounds the growth where F' ≈ 0)
    let w_floor = 1.0 / t_end.to_f64().max(1e-300);
    let omega_at = |th: f64| rhs.f_and_df(th).1.abs().sqrt().max(w_floor);
    let w0 = omega_at(theta0.to_f64());
    // initial data: rounded at `prec` by the caller
    let mut err = log2_add(
        theta0.to_f64().abs().max(1e-300).log2() - prec as f64,
        (thetadot0.to_f64().abs() / w0).max(1e-300).log2() - prec as f64,
    );
    // the series scale H: a power of two near the local time scale first,
    // then the next step's expected size (doubled when a step is capped at
    // u = 1, halved when a value overflows)
    let scale0 = 1.0 / w0.max(thetadot0.to_f64().abs());
    let mut hscale =
        Float::with_val(pw, 1u32) << scale0.log2().floor().clamp(-1000.0, 1000.0) as i32;
    let mut dv = vec![Fx::<L>::ZERO; n + 1];
    while t < t_end {
        crate::cancel::check()?;
        if steps.len() > 100_000 {
            return Err(collapsed(prec, &t));
        }
        if !ser.compute(rhs, &theta, &thetadot, &hscale) {
            hscale >>= 1;
            if hscale.to_f64() * w0 < 1e-12 {
                return Err(collapsed(prec, &t));
            }
            continue;
        }
        // step: largest u ≤ 1 with |X_k| u^k ≤ tol for the last three orders
        let mut log_u = 0.0f64;
        for k in n.saturating_sub(2)..=n {
            let lx = ser.x[k].log2();
            if lx.is_finite() {
                log_u = log_u.min((log_tol - lx) / k as f64);
            }
        }
        let capped = log_u >= 0.0;
        // h = H·2^log_u rounded down to 20 significant bits; the last steps
        // are made equal, so that no sliver of a step remains at the end
        let mut h = Float::with_val(pw, log_u.exp2());
        h *= &hscale;
        let remaining = Float::with_val(pw, &t_end - &t);
        let last = remaining <= h;
        let h = if last {
            remaining
        } else {
            let k = Float::with_val(64, &remaining / &h).ceil();
            if k <= 3u32 {
                h = Float::with_val(pw, &remaining / &k);
            }
            h.set_prec_round(20, rug::float::Round::Down);
            Float::with_val(pw, &h)
        };
        if h.is_zero() || log_u < -60.0 {
            return Err(collapsed(prec, &t));
        }
        // end of step: δ increment and θ̇ by Horner at u_end = h/H
        let inv_h = Float::with_val(pw, hscale.recip_ref());
        let u_end = Float::with_val(pw, &h * &inv_h);
        let u = Fx::<L>::from_float(&u_end);
        let inc = fixed::horner(&ser.x, n, &u, &mut prod).to_float(pw);
        // θ̇ = (1/H) Σ_{k≥1} D_k u^(k−1): Horner on D shifted by one
        dv[..n].copy_from_slice(&ser.d[1..=n]);
        let dpart = fixed::horner(&dv, n - 1, &u, &mut prod).to_float(pw);
        let dsum = Float::with_val(pw, dpart + ser.d[1].to_float(pw));
        let t1 = Float::with_val(pw, &t + &h);
        let new_delta = Float::with_val(pw, &delta + &inc);
        let new_theta = Float::with_val(pw, &th0 + &new_delta);
        let new_thetadot = Float::with_val(pw, &dsum * &inv_h);
        // errors (log2): truncation at u_end for θ and θ̇, rounding, growth
        let lu = u_end.to_f64().max(1e-300).log2();
        let lh = hscale.to_f64().log2();
        let mut trunc = f64::NEG_INFINITY;
        let mut trunc_d = f64::NEG_INFINITY;
        for k in n.saturating_sub(2)..=n {
            let lx = ser.x[k].log2();
            trunc = log2_add(trunc, lx + k as f64 * lu);
            trunc_d = log2_add(trunc_d, lx + (k as f64).log2() + (k as f64 - 1.0) * lu - lh);
        }
        let sum_mag = ser.x[0].log2().max(0.0);
        let round = (8.0 * n as f64).log2() - frac as f64 + sum_mag;
        let omega = 1.25 * omega_at(theta.to_f64()).max(omega_at(new_theta.to_f64()));
        let lambda = omega;
        let hf = h.to_f64();
        let local = log2_add(log2_add(trunc, trunc_d - omega.log2()), round);
        let mut tail = [(0.0, f64::NEG_INFINITY); 3];
        for (i, k) in (n.saturating_sub(2)..=n).enumerate() {
            tail[i] = (k as f64, ser.x[k].log2());
        }
        steps.push(Step {
            t0: t.clone(),
            t1: t1.clone(),
            inv_h,
            delta0: delta.clone(),
            x: ser.x.clone(),
            err0: err,
            lambda,
            round,
            tail,
            lx: ser.x.iter().map(|x| x.log2()).collect(),
        });
        err = log2_add(err + lambda * hf * std::f64::consts::LOG2_E, local);
        t = t1;
        delta = new_delta;
        theta = new_theta;
        thetadot = new_thetadot;
        if !last {
            // the next scale: 1.1 h, or twice H when this step was capped
            let mut next = if capped {
                Float::with_val(pw, &hscale * 2u32)
            } else {
                Float::with_val(pw, &h * 1.1f64)
            };
            next.set_prec_round(16, rug::float::Round::Up);
            hscale = Float::with_val(pw, &next);
        }
    }
    Ok(TaylorRun {
        order: n,
        time_prec: 64 * L as u32 + 32,
        work: ser.work,
        inner: Box::new(Run::<L> {
            prec,
            order: n,
            steps,
            prod,
            conv: fixed::Conv::new(pw),
            tau: Float::new(pw),
            inc: Float::new(pw),
        }),
    })
}

impl<const L: usize> Dense for Run<L> {
    fn steps(&self) -> usize {
        self.steps.len()
    }

    fn delta_at(&mut self, t: &Float) -> Option<(Float, Float)> {
        let prec = self.prec;
        if t.is_zero() {
            return Some((Float::new(prec), Float::new(prec)));
        }
        let mut j = self.steps.partition_point(|s| s.t1 < *t);
        if j == self.steps.len() {
            // a time past the end by a rounding of t_end (the caller's time
            // may carry more bits than the run's): the last step's series
            // holds a little beyond its end
            let last = self.steps.last()?;
            let over = Float::with_val(64, t - &last.t1);
            let tol = Float::with_val(64, last.t1.abs_ref()) >> (prec as i32);
            if over > tol {
                return None;
            }
            j -= 1;
        }
        let st = self.steps.get(j)?;
        if *t < st.t0 {
            return None;
        }
        // u = (t − t0)/H, in place
        self.tau.assign(t - &st.t0);
        let tau = self.tau.to_f64();
        self.tau *= &st.inv_h;
        let lu = self.tau.to_f64().max(1e-300).log2();
        // highest order whose term is above 2^-(p+12) at this u: the terms
        // left out decay geometrically and add less than 2^-(p+10)
        let n = self.order;
        let floor = -(prec as f64 + 12.0);
        let mut m = n;
        while m > 1 && st.lx[m] + m as f64 * lu <= floor {
            m -= 1;
        }
        let u = self.conv.to_fx::<L>(&self.tau);
        let r = fixed::horner(&st.x, m, &u, &mut self.prod);
        self.conv.to_float(&r, &mut self.inc);
        let delta = Float::with_val(prec, &st.delta0 + &self.inc);
        // error: carried, truncation at u, rounding
        let mut trunc = f64::NEG_INFINITY;
        for &(k, lx) in &st.tail {
            trunc = log2_add(trunc, lx + k * lu);
        }
        let carried = st.err0 + st.lambda * tau * std::f64::consts::LOG2_E;
        let mut e = log2_add(log2_add(carried, trunc), st.round);
        if m < n {
            e = log2_add(e, floor + 2.0);
        }
        let e = e.clamp(-1e9, 1e6).ceil() as i32 + 1;
        let err = Float::with_val(prec, 1u32) << e;
        Some((delta, err))
    }
}

impl TaylorRun {
    /// Number of steps taken.
    pub fn steps(&self) -> usize {
        self.inner.steps()
    }

    /// The order of the series.
    pub fn order(&self) -> usize {
        self.order
    }

    /// δ = θ(t) − θ0 and its estimated error for 0 ≤ t ≤ t_end (`None`
    /// outside), at the run's precision. `t` should carry at least
    /// [`TaylorRun::time_prec`] bits.
    pub fn delta_at(&mut self, t: &Float) -> Option<(Float, Float)> {
        self.inner.delta_at(t)
    }

    /// Bits a time given to [`TaylorRun::delta_at`] should have.
    pub fn time_prec(&self) -> u32 {
        self.time_prec
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The inverted pendulum θ̈ = sin θ (P = 1, K = 1).
    fn pendulum(prec: u32) -> Conservative {
        let one = Float::with_val(prec, 1u32);
        let z = Float::new(prec);
        Conservative {
            e: [one.clone(), z.clone(), z.clone()],
            k: [one, z.clone(), z],
        }
    }

    #[test]
    fn the_series_converges_geometrically_with_the_order() {
        // one step of θ̈ = sin θ from θ = 1/10 at rest, H = 1, evaluated at
        // u = 3/4 with orders 8, 16, …, 48 against order 160: the error falls
        // by a roughly constant factor per order (|u|/ρ with ρ the radius of
        // convergence), i.e. log2(error) is about linear in N
        let prec = 480u32;
        let rhs = pendulum(prec);
        let th = Float::with_val(prec, 1u32) / 10u32;
        let z = Float::new(prec);
        let one = Float::with_val(prec, 1u32);
        let u = Fx::<9>::from_float(&(Float::with_val(prec, 3u32) / 4u32));
        let mut prod = vec![0u64; 2 * 9 + 2];
        let eval = |n: usize, prod: &mut Vec<u64>| {
            let mut ser = Series::<9>::new(&rhs, n);
            ser.compute(&rhs, &th, &z, &one);
            fixed::horner(&ser.x, n, &u, prod).to_float(prec)
        };
        let reference = eval(160, &mut prod);
        let errs: Vec<f64> = (1..=6)
            .map(|i| {
                let v = eval(8 * i, &mut prod);
                let e = Float::with_val(prec, &v - &reference).abs();
                e.to_f64_exp().1 as f64
            })
            .collect();
        for w in errs.windows(2) {
            let gain = w[0] - w[1];
            assert!(gain > 4.0, "{errs:?}");
        }
        let rates: Vec<f64> = errs.windows(2).map(|w| w[0] - w[1]).collect();
        let (lo, hi) = rates
            .iter()
            .fold((f64::INFINITY, 0f64), |(a, b), &r| (a.min(r), b.max(r)));
        assert!(hi < 3.0 * lo, "rate per 8 orders {rates:?}");
    }

    #[test]
    fn order_and_steps_scale_with_precision() {
        assert_eq!(order_for(124), 47);
        assert!(order_for(433) > 150 && order_for(433) < 160);
    }

    #[test]
    fn two_precisions_agree_within_the_estimates() {
        // θ0 = 1/10 at rest: θ(t) at 150 and 300 bits (orders 56 and 108,
        // different steps) differ by less than the two error estimates, and
        // the estimate at 150 bits is not wildly pessimistic.
        let lo = 150u32;
        let hi = 300u32;
        let t_end = Float::with_val(hi, 3u32);
        let th0 = Float::with_val(hi, 1u32) / 10u32;
        let z = Float::new(hi);
        let mut a =
            integrate(&pendulum(lo), &Float::with_val(lo, &th0), &z, &t_end, lo, 0).unwrap();
        let mut b = integrate(&pendulum(hi), &th0, &z, &t_end, hi, 0).unwrap();
        for i in 1..=30u32 {
            let t = Float::with_val(400, i) / 10u32;
            let (da, ea) = a.delta_at(&t).unwrap();
            let (db, eb) = b.delta_at(&t).unwrap();
            let diff = Float::with_val(hi, &da - &db).abs();
            assert!(
                diff <= Float::with_val(hi, &ea + &eb),
                "t = {i}/10: diff {diff:e} est {ea:e}"
            );
            // the estimate is not wildly pessimistic either (≤ 2^-(lo − 40))
            assert!(
                ea < Float::with_val(64, 1u32) >> (lo as i32 - 40),
                "t = {i}/10: {ea:e}"
            );
        }
    }

    #[test]
    fn energy_is_conserved_along_the_run() {
        // θ̇² = 2 (cos θ0 − cos θ) for the pendulum: check θ̇ from the series
        // derivative by a centred difference of δ(t) (order h²) at 200 bits
        let prec = 200u32;
        let th0 = Float::with_val(prec, 1u32) / 10u32;
        let z = Float::new(prec);
        let t_end = Float::with_val(prec, 4u32);
        let mut run = integrate(&pendulum(prec), &th0, &z, &t_end, prec, 0).unwrap();
        assert!(
            run.steps() >= 3 && run.steps() < 40,
            "{} steps",
            run.steps()
        );
        let eps = Float::with_val(400, 1u32) >> 60;
        for i in 1..8u32 {
            let t = Float::with_val(400, i) / 2u32;
            let (dp, _) = run.delta_at(&Float::with_val(400, &t + &eps)).unwrap();
            let (dm, _) = run.delta_at(&Float::with_val(400, &t - &eps)).unwrap();
            let (d, _) = run.delta_at(&t).unwrap();
            let v = Float::with_val(prec, &dp - &dm) / Float::with_val(prec, &eps * 2u32);
            let th = Float::with_val(prec, &th0 + &d);
            let e = (Float::with_val(prec, th0.cos_ref()) - th.cos()) * 2u32;
            let rel = ((Float::with_val(prec, v.square_ref()) - &e) / &e)
                .abs()
                .to_f64();
            assert!(rel < 1e-30, "t = {i}/2: {rel:e}");
        }
    }
}
