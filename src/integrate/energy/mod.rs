//! The energy route: a conservative phase (every contact rolling,
//! sticking, frictionless or held) reduced to one degree of freedom, whose
//! energy integral gives θ̇²(θ) in closed form and t(θ) as a quadrature.
//!
//! [`Route`] holds one [`Ideal`] model and, explicitly, what depends only on
//! that model and a working precision ([`Caches`]): the quadrature engines
//! with their node sets, the scan bracket of separation, δs = θs − θ0 and
//! t_s per precision, and the exact polynomials in cos θ of N12 and of the
//! forces. Each method computes at one working precision and returns a
//! value with its error estimate; the precision ladder is the caller's
//! ([`crate::oracle`]). Nothing here caches a requested answer.
//!
//! A model that falls to the left (θ0 < 0, or θ0 = 0 with θ̇0 < 0) is
//! solved as its mirror image ([`Route::odd`] restores the odd quantities).

pub mod engine;
mod kept;
mod roots;
mod start;
pub(crate) use roots::{mass_spread_bits, MAX_SPREAD_BITS};
mod rows;

pub use kept::forget as forget_kept;
pub use rows::RowContext;

use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::mechanics::dynamics::Dyn;
use crate::mechanics::Reduced;
use crate::model::Ideal;
use crate::numeric::taylor::{self, Conservative};
use crate::numeric::verify::Run;
pub use engine::Engine;
use rug::{Assign, Float};
use std::collections::HashMap;

/// From this working precision on (about 170 digits) the trajectory's θ(t)
/// comes from inverting t(θ) on a Chebyshev interpolant
/// ([`engine::Inverse`]) rather than from a Taylor run of θ̈ = F(θ): the
/// Taylor run's cost grows like the cube of the precision, an inversion's
/// like its square times the interpolant's size.
pub const TRAJECTORY_CHEB_MIN_BITS: u32 = 600;

/// Whether `rows` times of a rolling phase at working precision `p` are
/// found by the Chebyshev inversion rather than by the Taylor run (from a
/// start away from the top). The Taylor run costs a fixed part (the run to
/// the last time, like p³) and little per row (a Horner sum); the inversion
/// little to build and about two Clenshaw sums of ~p/5 terms per row. So
/// from [`TRAJECTORY_CHEB_MIN_BITS`] on the inversion wins for a few rows
/// and the Taylor run for many, up to a precision where the run's fixed
/// part outgrows any table. Measured, CPU of whole tables (2026-11-27):
/// 10 rows of the ideal main case at 200 and 300 digits 0.07 and 0.11 s
/// by inversion, 0.19 and 0.68 s by the Taylor run; 1000 rows 0.58 and
/// 0.98 s against 0.28 and 0.84 s; with friction (μ = 0.3, its rolling
/// phase), 1000 rows at 200, 250, 300, 400 and 600 digits 0.61, 0.86, 1.18,
/// 2.06 and 4.38 s by inversion against 0.36, 0.72, 1.11, 2.82 and 8.63 s
/// (the working precisions: 689 and 807 bits at 200 digits, 1021 and 1181
/// at 300, 1353 and 1555 at 400).
pub fn inversion_pays(p: u32, rows: usize) -> bool {
    let most_rows = match p {
        0..TRAJECTORY_CHEB_MIN_BITS => return false,
        TRAJECTORY_CHEB_MIN_BITS..900 => 250,
        900..1250 => 800,
        _ => return true,
    };
    rows <= most_rows
}

/// Below this |θ0| the trajectory takes the Chebyshev route at every
/// precision: its pieces grade towards the start's singularity, where a
/// Taylor run needs ever shorter steps (θ0 = 1e-100 failed after 26 s).
pub const NEAR_TOP: f64 = 1e-6;

/// Precision of the scans that locate brackets (refined afterwards).
pub const SCAN_PREC: u32 = 96;
/// Scan steps over the motion.
pub const SCAN_STEPS: u32 = 512;

/// What the route keeps between calls: facts of the model at a working
/// precision, computed once on first use.
#[derive(Default)]
pub struct Caches {
    /// The quadrature engines (dynamics constants, tanh-sinh and
    /// Gauss–Legendre node sets, Chebyshev fits), one per precision.
    pub engines: HashMap<u32, Engine>,
    /// The first sign change of N12 on the 96-bit scan.
    pub scan_s: Option<Option<(Float, Float)>>,
    /// δs = θs − θ0 and its error, per precision.
    pub delta_s_at: HashMap<u32, (Float, Float)>,
    /// t_s per precision (for the trajectory's time check).
    pub t_s_at: HashMap<u32, Float>,
    /// N12·K²/m2 as an exact polynomial in cos θ.
    pub n12_poly: Option<crate::mechanics::dynamics::N12Poly>,
    /// N1, F1, F21 as exact polynomials in cos θ.
    pub force_polys: Option<crate::mechanics::dynamics::ForcePolys>,
    /// The dynamics at 32 bits beyond a precision, per precision: the
    /// rows' columns where their error is measured ([`Route::column_errors`]).
    pub dyn_above: HashMap<u32, Dyn>,
}

/// The energy route of one conservative model.
pub struct Route {
    /// The model as given.
    pub model: Ideal,
    /// The model as solved: mirrored when it falls to the left.
    pub work: Ideal,
    /// +1, or −1 for a mirrored model.
    pub sign: i32,
    /// The exact reduction to one degree of freedom.
    pub red: Reduced,
    /// What depends only on the model and a precision.
    pub caches: Caches,
    /// Set by [`Route::delta_of`] when it answered an angle past θs by less
    /// than the digits asked resolve at θs itself (for the answer's note);
    /// never cleared by the route (`oracle::time` and `oracle::forces` read
    /// it from a route of their own): a caller reusing a route clears it.
    pub at_separation: bool,
    /// N12/(m2 g) at the start (64 bits; > 0 once the route is made): how
    /// close the start lies to the parting.
    pub n12_start: Float,
}

/// `what` (a time) is infinite: the motion starts from rest exactly at the
/// unstable top. The ideal models answer angles and forces as the limit
/// θ0 → 0+; with Coulomb friction (`coulomb`) that limit is not computed,
/// and the message must not say it is.
pub fn infinite_time_error(what: &str, coulomb: bool) -> Error {
    let limit = if coulomb {
        "with Coulomb friction the limit theta0 -> 0+ is not computed; the ideal laws (roll, \
         slip) give forces and the separation angle as that limit"
    } else {
        "forces and the separation angle are defined as the limit theta0 -> 0+"
    };
    Error::not_physical(format!(
        "{what} is infinite: the motion starts from rest exactly at the unstable top (theta0 = 0, \
         thetadot0 = 0); give a small --theta0 or --thetadot0 ({limit})"
    ))
}

impl Route {
    /// The route of `model`.
    ///
    /// Errors: a start where the cylinders already part (N12 ≤ 0) or
    /// cylinder 1 already lifts (N1 ≤ 0).
    pub fn new(model: &Ideal) -> Result<Self> {
        let sign = model.direction();
        let work = if sign < 0 {
            model.mirrored()
        } else {
            model.clone()
        };
        let red = Reduced::new(&work)?;
        let mut r = Route {
            model: model.clone(),
            work,
            sign,
            red,
            caches: Caches::default(),
            at_separation: false,
            n12_start: Float::new(64),
        };
        r.check_start()?;
        Ok(r)
    }

    pub fn engine(&mut self, prec: u32) -> Result<&mut Engine> {
        if !self.caches.engines.contains_key(&prec) {
            let e = Engine::new(&self.work, &self.red, prec)?;
            self.caches.engines.insert(prec, e);
        }
        Ok(self.caches.engines.get_mut(&prec).expect("inserted"))
    }

    pub fn infinite_time_error(&self, what: &str) -> Error {
        infinite_time_error(what, false)
    }

    /// The coefficients (ascending in c = cos θ) of N12·K²/m2 at `prec` bits
    /// ([`crate::mechanics::dynamics::N12Poly`], built once in exact
    /// rationals; the start enters through A_H).
    pub fn n12_coefficients(&mut self, prec: u32) -> Result<Vec<Float>> {
        use crate::mechanics::dynamics::N12Poly;
        let a_h = N12Poly::a_h(&self.engine(prec)?.dynm);
        let poly = self
            .caches
            .n12_poly
            .get_or_insert_with(|| N12Poly::new(&self.red, self.work.params()));
        Ok(poly.at(&a_h, prec))
    }

    /// The 96-bit scan's bracket of the first sign change of N12 (cached).
    ///
    /// The scan evaluates N12·K²/m2, the polynomial in c = cos θ of
    /// [`crate::mechanics::dynamics::N12Poly`] (one `cos` and a Horner sum per
    /// point; K > 0, so it has N12's sign), rather than the full dynamics: the
    /// same grid and the same signs at about a fifth of the cost, which is
    /// most of a cold `time_at`.
    pub fn scan_bracket(&mut self) -> Result<(Float, Float)> {
        if self.caches.scan_s.is_none() {
            // the heavier upper cylinder's scale in the coefficients, the
            // lighter one's in N12 near θs: the bits of their ratio more
            // (m2 = 10^30 m1 at 96 bits alone bracketed the wrong angle)
            let sp = SCAN_PREC + roots::disparity_bits(self.work.params());
            let coef = self.n12_coefficients(sp)?;
            let th0 = self.work.start().theta0.to_float(sp);
            let hi = Float::with_val(sp, rug::float::Constant::Pi) - &th0;
            let zero = Float::new(sp);
            let mut c = Float::new(sp);
            let bracket = crate::numeric::root::first_sign_change(&zero, &hi, SCAN_STEPS, |d| {
                c.assign(&th0 + d);
                c.cos_mut();
                let mut v = Float::new(sp);
                crate::numeric::poly::horner(&coef, &c, &mut v);
                v
            });
            self.caches.scan_s = Some(bracket);
        }
        match &self.caches.scan_s {
            Some(Some(b)) => Ok(b.clone()),
            _ => Err(Error::not_physical(
                "N12 stays positive up to theta = pi: the cylinders never separate",
            )),
        }
    }

    /// δs = θs − θ0 at `prec`, as (value, error), with the bracket scanned at
    /// low precision first. Both are deterministic and cached, and kept by
    /// the process between answers for the same model and precision (`kept`:
    /// the bits a fresh process computes).
    pub fn delta_s(&mut self, prec: u32) -> Result<(Float, Float)> {
        if let Some(v) = self.caches.delta_s_at.get(&prec) {
            return Ok(v.clone());
        }
        let v = match kept::get(&self.work, prec, kept::Fact::DeltaS, None) {
            Some((v, _)) => v,
            None => {
                let (lo, hi) = self.scan_bracket()?;
                // N12 near θs is of the lighter cylinder's scale, its terms
                // of the heavier one's: refined with the bits of their
                // ratio more (0 up to m2 = 2^16 m1), then rounded to prec
                let extra = roots::disparity_bits(self.work.params());
                let e = self.engine(prec + extra)?;
                let (d, err) = e.refine_root("theta_s", &lo, &hi, |eng, d| eng.n12(d))?;
                let default = e.settings_are_default();
                let v = if extra == 0 {
                    (d, err)
                } else {
                    let (dr, _) = Float::with_val_round(prec, &d, rug::float::Round::Nearest);
                    let ulp = Float::with_val(prec, dr.abs_ref()) >> (prec as i32 - 1);
                    (dr, Float::with_val(prec, &err) + ulp)
                };
                if default {
                    kept::put(&self.work, prec, kept::Fact::DeltaS, None, &v, 0.0);
                }
                v
            }
        };
        self.caches.delta_s_at.insert(prec, v.clone());
        Ok(v)
    }

    /// t(δs) at `prec` by [`Engine::time`] (the θ form's quadrature), as
    /// (value, error estimate): the time of the closed branch's end, as the
    /// motion has always taken it. Kept by the process as
    /// [`Route::delta_s`]. ([`Route::t_s_at`] is the cheaper half-angle
    /// quadrature's, for the ideal `Oracle`'s check that a time is before
    /// the separation: another rounding of the same time.)
    pub fn time_s(&mut self, prec: u32) -> Result<(Float, Float)> {
        if let Some((v, _)) = kept::get(&self.work, prec, kept::Fact::TimeS, None) {
            return Ok(v);
        }
        let (ds, _) = self.delta_s(prec)?;
        let e = self.engine(prec)?;
        let v = e.time(&ds);
        if e.settings_are_default() {
            kept::put(&self.work, prec, kept::Fact::TimeS, None, &v, 0.0);
        }
        Ok(v)
    }

    /// θ in the working frame from a user angle.
    pub fn to_work(&self, theta: &Exact) -> Exact {
        if self.sign < 0 {
            theta.neg()
        } else {
            theta.clone()
        }
    }

    pub fn odd(&self, x: Float) -> Float {
        if self.sign < 0 {
            -x
        } else {
            x
        }
    }

    pub fn scale_force(&self, p: u32) -> Float {
        let pr = self.work.params();
        Float::with_val(p, &rug::Rational::from(&pr.m1 + &pr.m2)) * &pr.g
    }

    pub fn scale_time(&self, p: u32) -> Float {
        let pr = self.work.params();
        Float::with_val(p, Float::with_val(p, &pr.r()) / &pr.g).sqrt()
    }

    /// N1, F1, F21 as polynomials in cos θ (built once).
    pub fn force_polys(&mut self) -> crate::mechanics::dynamics::ForcePolys {
        let (floor, contact) = (self.work.floor(), self.work.contact());
        self.caches
            .force_polys
            .get_or_insert_with(|| {
                crate::mechanics::dynamics::ForcePolys::new(
                    &self.red,
                    self.work.params(),
                    floor,
                    contact,
                )
            })
            .clone()
    }

    /// An angle (`w`, in the work frame) past the one where cylinder 2,
    /// still on cylinder 1, lands on the floor (cos θ = (r2 − r1)/(r1 + r2):
    /// θ < π/2 for r2 > r1, π/2 for equal radii, beyond π/2 for r2 < r1) —
    /// where that comes before the separation — is refused as the motion's
    /// walk refuses it: the model ends there. An angle within 2^−200 of it
    /// is that end (answered, as an event's). (Equal and smaller upper radii
    /// were let through: `time --to 1.6` from θ0 = 1.5 answered a time after
    /// the impact at π/2.)
    fn before_floor_impact(
        &mut self,
        param: &str,
        theta: &Exact,
        w: &Exact,
        th0: &Exact,
    ) -> Result<()> {
        const P: u32 = 256;
        let th_f = self.work.params().landing_angle(P);
        let margin = Float::with_val(P, &th_f >> 200);
        if Float::with_val(P, w.to_float(P) - &th_f) <= margin {
            return Ok(());
        }
        // past the landing angle: refused unless the separation comes first
        // (then the separation's own check below names it)
        let (ds, _) = self.delta_s(P)?;
        let df = Float::with_val(P, &th_f - th0.to_float(P));
        if ds < df {
            return Ok(());
        }
        Err(Error::invalid(
            param,
            theta,
            format!(
                "must be reached while the cylinders touch: cylinder 2 lands on the floor at \
                 theta = {} (the end of the model)",
                crate::numeric::decimal::to_sig(&self.odd(th_f), 12)
            ),
        ))
    }

    /// δ = θ − θ0 (working frame) for a user angle, checked to lie in the
    /// motion. An angle past θs by less than `digits` significant digits
    /// resolve ([`crate::motion::sides::within_digits`]: θs as printed to
    /// those digits, rounded to nearest, is one) is answered at θs: δs is
    /// returned and [`Route::at_separation`] set (`digits` 0: refused, for
    /// a proof at the angle itself).
    pub fn delta_of(&mut self, param: &str, theta: &Exact, p: u32, digits: u32) -> Result<Float> {
        let w = self.to_work(theta);
        let th0 = self.work.start().theta0.clone();
        let d = Float::with_val(p, w.to_float(p) - th0.to_float(p));
        self.before_floor_impact(param, theta, &w, &th0)?;
        // Inside the motion by a clear margin below the scan's bracket of δs:
        // no need to refine δs at this precision.
        let (lo, _) = self.scan_bracket()?;
        if !d.is_sign_negative() || d.is_zero() {
            let margin = Float::with_val(p, lo.abs_ref()) >> (p.min(SCAN_PREC) as i32 - 4);
            if Float::with_val(p.max(SCAN_PREC), &d + &margin) < lo {
                return Ok(d);
            }
        }
        let (ds, ds_err) = self.delta_s(p)?;
        let th_s = Float::with_val(p, th0.to_float(p) + &ds);
        // θs quoted toward the start, to the digits its error leaves and the
        // precision carries: an angle refused as past it reads as past it
        // (to 10 digits at 15 asked, 1.050772062 did not show why
        // 1.0507720620186 was refused)
        let range = format!(
            "must lie in the motion, between theta0 = {} and the separation angle theta_s = {} \
             (rounded toward the start",
            self.model.start().theta0,
            crate::numeric::decimal::toward_start(
                &Float::with_val(p.min(ds.prec()), self.odd(th_s)),
                &ds_err
            )
        );
        if d.is_sign_negative() && !d.is_zero() {
            return Err(Error::invalid(
                param,
                theta,
                format!("{range}; it is before the start)"),
            ));
        }
        // Before or after separation, decided whatever the digits asked: θ is
        // compared with the bracket [δs − ε, δs + ε] of the root of N12 (and
        // the rounding of θ − θ0), at doubling precision until the bracket
        // lies on one side. A θ that stays inside the bracket up to 8p bits
        // (at least 1024) is θs itself to that accuracy, where the forces
        // are defined (N12 = 0): it is answered, not refused.
        let cap = (8 * p).clamp(1024, 1 << 15);
        let mut q = p;
        loop {
            let (ds, err) = self.delta_s(q)?;
            let dq = Float::with_val(q, w.to_float(q) - th0.to_float(q));
            let ulp = Float::with_val(q, dq.abs_ref()) >> (q as i32 - 4);
            let margin = Float::with_val(q, &err + &ulp);
            if Float::with_val(q, &dq + &margin) < ds {
                return Ok(d);
            }
            if Float::with_val(q, &dq - &margin) > ds {
                // compared as angles (θ and θs: their digits, not δ's)
                let one = Float::with_val(q, 1u32);
                let th_q = Float::with_val(q, th0.to_float(q) + &dq);
                let ths_q = Float::with_val(q, th0.to_float(q) + &ds);
                if digits > 0 && crate::motion::sides::within_digits(&th_q, &ths_q, digits, &one) {
                    self.at_separation = true;
                    return Ok(Float::with_val(p, &ds));
                }
                return Err(Error::invalid(
                    param,
                    theta,
                    format!("{range}; it is after separation)"),
                ));
            }
            if q >= cap {
                return Ok(d);
            }
            q = (2 * q).min(cap);
        }
    }

    pub fn check_times(&self, times: &[Exact]) -> Result<()> {
        if self.work.starts_at_equilibrium() {
            return Err(self.infinite_time_error("every time along the motion"));
        }
        for t in times {
            if t.signum() < 0 {
                return Err(Error::invalid(
                    "times",
                    t,
                    "must be >= 0 (the start is at t = 0)",
                ));
            }
        }
        Ok(())
    }

    /// log2 of the time unit [`extra_bits_at`] counts small times in,
    /// sqrt(r/(2g)) = [`Route::scale_time`]/√2 (in f64).
    fn log2_time_unit(&self) -> f64 {
        log2_f64(&self.scale_time(64)) - 0.5
    }

    /// t_s at precision `p` (cached: a fact of the model).
    pub fn t_s_at(&mut self, p: u32) -> Result<Float> {
        if let Some(t) = self.caches.t_s_at.get(&p) {
            return Ok(t.clone());
        }
        let (ds, _) = self.delta_s(p)?;
        let (t_s, _, _) = self.engine(p)?.time_fast(&ds, false, false);
        self.caches.t_s_at.insert(p, t_s.clone());
        Ok(t_s)
    }

    /// t(δ) at a branch point δ at `prec` by [`Engine::time_fast`] (`high`:
    /// the ladder's higher run; no rule built), as (value, error estimate):
    /// kept by the process as [`Route::delta_s`] where the engine holds no
    /// Gauss–Legendre rule (then the route is the same fixed rule whatever
    /// the engine did before).
    pub fn branch_time(&mut self, delta: &Float, prec: u32, high: bool) -> Result<(Float, Float)> {
        let fact = kept::Fact::BranchTime { high };
        let e = self.engine(prec)?;
        let keep = !e.has_gauss_rules() && e.settings_are_default();
        if keep {
            if let Some((v, work)) = kept::get(&self.work, prec, fact, Some(delta)) {
                self.engine(prec)?.add_quadrature_work(work);
                return Ok(v);
            }
        }
        let e = self.engine(prec)?;
        let before = e.quadrature_work();
        let (t, err, _) = e.time_fast(delta, high, false);
        let work = e.quadrature_work() - before;
        let v = (t, err);
        if keep {
            kept::put(&self.work, prec, fact, Some(delta), &v, work);
        }
        Ok(v)
    }

    /// The right-hand side θ̈ = sin θ·P(c)/K(c)² of the model at `p` bits:
    /// with A_H = K(θ0)θ̇0² + 2(g/r) cos θ0, P = (g/r) q0 + q1 A_H/2 +
    /// q2 A_H c − (g/r) q2 c² (θ̈ = sin θ (g/r + ½K'θ̇²)/K with θ̇² = H/K).
    pub fn taylor_rhs(&mut self, p: u32) -> Result<Conservative> {
        let d = &self.engine(p)?.dynm;
        let a_h = crate::mechanics::dynamics::N12Poly::a_h(d);
        let e0 = Float::with_val(p, &d.gr * &d.q[0]) + Float::with_val(p, &d.q[1] * &a_h) / 2u32;
        let e1 = Float::with_val(p, &d.q[2] * &a_h);
        let e2 = -Float::with_val(p, &d.gr * &d.q[2]);
        Ok(Conservative {
            e: [e0, e1, e2],
            k: d.q.clone(),
        })
    }

    /// δ = θ − θ0 and its error bound ε at each time, at precision `p`: the
    /// separation-time check (each time ≤ t_s), one Taylor run to the last
    /// time, and the quadrature check there. ε is twice the estimate (at
    /// least |δ|·2^-(p−9)), as the Newton inversion used to report it.
    /// `cache` holds the times as Floats (converted once per rung, for
    /// both runs).
    #[allow(clippy::too_many_arguments)]
    pub fn deltas_at(
        &mut self,
        times: &[Exact],
        p: u32,
        run: Run,
        rel_delta: bool,
        cache: &mut crate::exact::TableTimes,
        digits: u32,
        t_end: Option<&Float>,
    ) -> Result<Vec<(Float, Float)>> {
        let t_s = match t_end {
            Some(t) => Float::with_val(p, t),
            None => self.t_s_at(p)?,
        };
        // the bits the smallest positive time needs beyond p, δ ≈ θ̈0 t²/2
        // there (only the trajectory's rows need δ to full relative
        // accuracy): the times' precision and the Chebyshev route's (the
        // Taylor route gives them to the times that need them)
        // (the smallest time only where the rows need it: a θ column's
        // absolute error does not)
        let extra = if rel_delta {
            let log2_ts = self.log2_time_unit();
            let log2_t_min = times
                .iter()
                .filter(|t| !t.is_zero())
                .min_by(|a, b| a.cmp_value(b))
                .map_or(f64::INFINITY, |t| log2_f64(&t.to_float(64)));
            extra_bits_at(log2_t_min - log2_ts, p)
        } else {
            0
        };
        let tq = taylor::time_prec_for(p, extra);
        // once for both runs of a rung: at the p2 run's precision
        let hi = taylor::time_prec_for(p + p / 8 + 40, extra);
        let tt_all = cache.at_least(times, tq, hi);
        // the separation-time check, and the last time
        let mut i_max = None;
        for (i, (t, tt)) in times.iter().zip(tt_all).enumerate() {
            if *tt > t_s {
                return Err(Error::invalid(
                    "times",
                    t,
                    format!(
                        "must be <= the separation time t_s = {}: the model ends when the cylinders part",
                        crate::numeric::decimal::to_sig(&t_s, 12)
                    ),
                ));
            }
            if !tt.is_zero() && i_max.is_none_or(|m: usize| *tt >= tt_all[m]) {
                i_max = Some(i);
            }
        }
        let Some(i_max) = i_max else {
            let zero = Float::new(p);
            return Ok(vec![(zero.clone(), zero); times.len()]);
        };
        // the Chebyshev route at high precision, and from a start near the
        // top at any (its pieces are graded towards the start; the Taylor
        // run crawls there)
        let near_top = self.work.start().theta0.to_f64().abs() < NEAR_TOP;
        let by_cheb = near_top || inversion_pays(p, times.len());
        let cheb = if by_cheb {
            self.deltas_cheb(times, tt_all, p, extra)?
        } else {
            None
        };
        let mut out = match cheb {
            Some(out) => out,
            None => self
                .deltas_taylor(times, tt_all, i_max, p, extra, digits)
                .or_else(|e| {
                    // the Taylor run taken for its speed failed: the
                    // inversion it stood in for (its own refusal says
                    // more where that fails too; a cancellation stops)
                    let stood_in = !by_cheb && p >= TRAJECTORY_CHEB_MIN_BITS;
                    if !stood_in || matches!(e, Error::Cancelled) {
                        return Err(e);
                    }
                    match self.deltas_cheb(times, tt_all, p, extra) {
                        Ok(Some(out)) => Ok(out),
                        Err(c @ Error::Cancelled) => Err(c),
                        _ => Err(e),
                    }
                })?,
        };
        let t_last = Float::with_val(tq, &tt_all[i_max]);
        let (d, eps) = out[i_max].clone();
        // certify at the last time: t(δ − ε) ≤ t ≤ t(δ + ε) by the energy
        // quadrature. One integral suffices when |t(δ) − t| + its error is
        // below ε/θ̇(δ) = ε dt/dδ (less 2^-16: θ̇ varies by far less over [δ−ε, δ+ε]);
        // otherwise both ends are integrated.
        let high = run == Run::High;
        let e = self.engine(p)?;
        let (tm, tm_err) = e.time_check(&d, high, near_top);
        let gap = Float::with_val(p, &tm - &t_last).abs() + &tm_err;
        // t(δ ± ε) − t(δ) ≈ ±ε dt/dδ = ±ε/θ̇
        let room = Float::with_val(p, &eps * e.inv_thetadot(&d));
        let room = Float::with_val(p, &room - Float::with_val(p, &room >> 16));
        let mut certified = gap <= room || {
            let dlo = Float::with_val(p, &d - &eps);
            let dhi = Float::with_val(p, &d + &eps);
            let tlo = if dlo.is_sign_positive() {
                e.time_check(&dlo, high, near_top).0
            } else {
                Float::new(p)
            };
            let thi = e.time_check(&dhi, high, near_top).0;
            tlo <= t_last && t_last <= thi
        };
        if !certified {
            // The bracket is too narrow for the quadrature at this precision
            // to decide: widen every ε by the same factor until the one-integral
            // test passes (a more conservative bound; the ladder then decides
            // how many digits remain verified).
            let mut widen = Float::with_val(p, 1u32);
            for _ in 0..6 {
                widen <<= 4;
                if gap <= Float::with_val(p, &room * &widen) {
                    certified = true;
                    for (_, x) in out.iter_mut() {
                        *x *= &widen;
                    }
                    break;
                }
            }
        }
        if !certified {
            return Err(Error::NotConverged {
                quantity: "theta(t)".into(),
                requested: digits,
                reached: format!("no certified bracket at {p} bits"),
                detail: format!("t = {}", crate::numeric::decimal::to_sig(&t_last, 20)),
            });
        }
        Ok(out)
    }

    /// δ and its error at each time by one Taylor run to the last time
    /// ([`crate::numeric::taylor`], dense output); the times whose δ needs
    /// more fixed-point bits for its relative accuracy than the run carries
    /// spare ([`extra_bits_at`], at most `extra`) from a second, short run
    /// with `extra` bits.
    pub fn deltas_taylor(
        &mut self,
        times: &[Exact],
        tt_all: &[Float],
        i_max: usize,
        p: u32,
        extra: u32,
        digits: u32,
    ) -> Result<Vec<(Float, Float)>> {
        // the integrator runs in a time unit 2^k near the model's
        // √(r/(2g)) (exact rescalings: θ̈ = F(θ) gains 4^k, θ̇ 2^k, times
        // 2^−k; its f64 step control then never sees a time or rate beyond
        // f64's range, and in the paper's units, r = 2 g, k = 0)
        let k = self.log2_time_unit().round() as i32;
        let mut rhs = self.taylor_rhs(p)?;
        for e in rhs.e.iter_mut() {
            *e <<= 2 * k;
        }
        let th0 = self.work.start().theta0.to_float(p);
        let td0 = Float::with_val(p, &self.work.start().thetadot0) << k;
        let in_unit = |t: &Float| Float::with_val(t.prec(), t >> k);
        let t_end = in_unit(&tt_all[i_max]);
        // `extra` is what the smallest time needs (extra_bits_at never
        // grows with t). The times that need more fraction bits than the
        // run's limbs carry spare come from one short run with `extra`, to
        // the latest of them, the rest from the main run (a limb more for
        // the whole run would cost every row); one run with `extra` when
        // the last time needs it too
        let spare = taylor::spare_frac_bits(p);
        let log2_ts = self.log2_time_unit();
        let needs: Vec<bool> = times
            .iter()
            .zip(tt_all)
            .map(|(t, tt)| {
                extra > spare && !t.is_zero() && extra_bits_at(log2_f64(tt) - log2_ts, p) > spare
            })
            .collect();
        // the latest time that needs the bits
        let short_end = tt_all
            .iter()
            .zip(&needs)
            .filter_map(|(tt, &n)| n.then_some(tt))
            .max_by(|a, b| a.total_cmp(b));
        let short_unit = short_end.map(in_unit);
        // (end, extra bits) of the main run, then of the short one
        let plan = match &short_unit {
            Some(_) if needs[i_max] => vec![(&t_end, extra)],
            Some(te) => vec![(&t_end, 0), (te, extra)],
            None => vec![(&t_end, 0)],
        };
        let mut runs = plan
            .into_iter()
            .map(|(te, extra)| taylor::integrate(&rhs, &th0, &td0, te, p, extra))
            .collect::<Result<Vec<_>>>()
            .map_err(|e| match k {
                0 => e,
                // its times are in the unit 2^k
                _ => e.map_not_converged(|q, d| {
                    (q, format!("{d} (in the integrator's time unit 2^{k})"))
                }),
            })?;
        let (traj, short) = runs.split_at_mut(1);
        let (traj, mut short) = (&mut traj[0], short.first_mut());
        let no_output = |t: &Float| Error::NotConverged {
            quantity: "theta(t)".into(),
            requested: digits,
            reached: format!("no Taylor output at {p} bits"),
            detail: format!("t = {}", crate::numeric::decimal::to_sig(t, 20)),
        };
        let mut out = Vec::with_capacity(times.len());
        let mut floor = Float::new(p);
        for ((t, tt), &n) in times.iter().zip(tt_all).zip(&needs) {
            if t.is_zero() {
                out.push((Float::new(p), Float::new(p)));
                continue;
            }
            let run = match short.as_mut() {
                Some(s) if n => s,
                _ => &mut *traj,
            };
            let scaled;
            let tu = if k == 0 {
                tt
            } else {
                scaled = in_unit(tt);
                &scaled
            };
            let (d, mut e) = run.delta_at(tu).ok_or_else(|| no_output(tt))?;
            floor.assign(d.abs_ref());
            floor >>= p as i32 - 8;
            if e < floor {
                e.assign(&floor);
            }
            e <<= 1;
            out.push((d, e));
        }
        // the short run answers to the main one (which the energy
        // quadrature certifies at the last time): at the short run's last
        // time the two agree within their error estimates
        if let (Some(s), Some(te), Some(tu)) = (short, short_end, &short_unit) {
            let (ds, es) = s.delta_at(tu).ok_or_else(|| no_output(te))?;
            let (dm, em) = traj.delta_at(tu).ok_or_else(|| no_output(te))?;
            let mut room = Float::with_val(p, &es + &em) << 1u32;
            room += Float::with_val(p, dm.abs_ref()) >> (p as i32 - 8);
            if Float::with_val(p, &ds - &dm).abs() > room {
                return Err(Error::NotConverged {
                    quantity: "theta(t)".into(),
                    requested: digits,
                    reached: format!(
                        "the small times' Taylor run disagrees with the main run at {p} bits"
                    ),
                    detail: format!("t = {}", crate::numeric::decimal::to_sig(te, 20)),
                });
            }
        }
        Ok(out)
    }

    /// δ and its error at each time by inverting t(θ) on one Chebyshev
    /// interpolant over [θ0, θs] ([`engine::Inverse`]), at `p` + `extra`
    /// bits (the extra bits keep δ's relative accuracy at small times, as
    /// the Taylor route's fixed-point bits do), rounded to `p`. `None` where
    /// the interpolant does not apply (θs beyond 2π/3, a start so near the
    /// top that the integrand's singularity crowds the interval).
    pub fn deltas_cheb(
        &mut self,
        times: &[Exact],
        tt_all: &[Float],
        p: u32,
        extra: u32,
    ) -> Result<Option<Vec<(Float, Float)>>> {
        let pe = p + extra;
        let (ds, _) = self.delta_s(pe)?;
        let Some(inv) = self.engine(pe)?.inverse(&ds, times.len()) else {
            return Ok(None);
        };
        let mut out = Vec::with_capacity(times.len());
        for (t, tt) in times.iter().zip(tt_all) {
            if t.is_zero() {
                out.push((Float::new(p), Float::new(p)));
                continue;
            }
            let (d, e) = inv.delta_at(&Float::with_val(pe, tt));
            let d = Float::with_val(p, d);
            let mut e = Float::with_val(p, e);
            e += Float::with_val(p, d.abs_ref()) >> (p as i32 - 2);
            out.push((d, e));
        }
        Ok(Some(out))
    }
}

/// log2 |x| in f64 for any exponent (−∞ for 0), from the mantissa and the
/// exponent apart (no MPFR logarithm, no f64 overflow).
fn log2_f64(x: &Float) -> f64 {
    if x.is_zero() {
        return f64::NEG_INFINITY;
    }
    let (m, e) = x.to_f64_exp();
    m.abs().log2() + f64::from(e)
}

/// Fraction bits beyond the working precision `p` that δ needs at time `t`
/// for full relative accuracy (δ ≈ θ̈0 t²/2 at small t, θ̈0 of the order of
/// g/r: 2 log2(T/t) and 8 more; none from t = T on), at most `p`. `log2_t`
/// is log2(t/T), the time in the unit T = sqrt(r/(2g)) (the mean radius's;
/// 1 in the paper's units, for which the 8 bits were set): in seconds, a
/// motion in microseconds would take every row as small, one in hours none.
pub fn extra_bits_at(log2_t: f64, p: u32) -> u32 {
    let lt = log2_t.max(-1e6);
    if lt < 0.0 {
        ((-2.0 * lt).ceil() as u32 + 8).min(p)
    } else {
        0
    }
}

/// The precision of a table's columns derived from θ alone in the higher
/// run (`Wants::derived_at_high`) at the ladder's precision `p` for
/// `digits`: the bits of the digits asked, 16 guard bits and the 48 more of
/// each rung the ladder has climbed (where a value falls short, the next
/// rung's columns carry smaller roundings too), up to the last bit but one
/// of the fewest limbs that hold them (MPFR's two-limb paths are below 128
/// bits: 127 bits at 20 or 30 digits on the first rung, where the run's own
/// precision takes three limbs; all of them where that bit is needed); at
/// most `p`, and `p` itself where `p` is not the higher precision of a rung.
/// The columns' error bounds count the roundings at this precision, and
/// δ's rounding to it.
pub(crate) fn derived_prec(digits: u32, p: u32) -> u32 {
    use crate::numeric::verify::{precisions, MAX_ATTEMPTS};
    let Some(rung) = (0..MAX_ATTEMPTS).find(|&a| precisions(digits, a).1 == p) else {
        return p;
    };
    let need = crate::numeric::bits_for_digits(digits) + 16 + 48 * rung;
    let top = need.div_ceil(64) * 64;
    (if top > need { top - 1 } else { top }).min(p)
}

#[cfg(test)]
mod derived_prec_tests {
    use super::derived_prec;
    use crate::numeric::bits_for_digits;
    use crate::numeric::verify::{precisions, MAX_ATTEMPTS};

    /// The digits' bits and 16 more, the fewest limbs, never above the
    /// higher run's precision; written out at 20, 30 and 100 digits.
    #[test]
    fn the_fewest_limbs_for_the_digits_and_a_guard() {
        assert_eq!(derived_prec(20, precisions(20, 0).1), 127);
        assert_eq!(derived_prec(30, precisions(30, 0).1), 127);
        // 333 + 16 bits: six limbs, one less than the higher run's seven
        assert_eq!(precisions(100, 0).1.div_ceil(64), 7);
        assert_eq!(derived_prec(100, precisions(100, 0).1), 383);
        for digits in 1..=2000 {
            for rung in 0..MAX_ATTEMPTS {
                let p2 = precisions(digits, rung).1;
                let pc = derived_prec(digits, p2);
                let need = bits_for_digits(digits) + 16 + 48 * rung;
                assert!(pc <= p2);
                assert!(pc == p2 || pc >= need, "{digits} {rung}");
                // no fewer limbs would hold the digits and the guard
                assert!(pc == p2 || pc.div_ceil(64) == need.div_ceil(64), "{digits}");
                assert!(pc == p2 || pc % 64 == 63 || pc == need, "{digits}");
            }
        }
        // each rung's columns more precise than the last's
        let pcs: Vec<u32> = (0..MAX_ATTEMPTS)
            .map(|a| derived_prec(30, precisions(30, a).1))
            .collect();
        assert_eq!(pcs, [127, 191, 255]);
        // a precision that is not a rung's higher one: itself
        assert_eq!(derived_prec(30, 100), 100);
        assert_eq!(derived_prec(30, precisions(30, 0).0), precisions(30, 0).0);
    }
}
