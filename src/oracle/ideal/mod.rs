//! The questions users ask, answered with verified digits.
//!
//! An [`Oracle`] holds a model and a requested number of significant digits.
//! Each method runs its computation through the precision ladder
//! ([`crate::numeric::verify::ladder`]) and returns [`Verified`] numbers.
//!
//! Routes: `separation()` scans N12 and refines with Illinois regula falsi
//! (its output is part of the golden data and does not change);
//! `separation_angle()` roots an exact polynomial in cos θ; `time_at()` uses
//! the half-angle quadrature (tanh-sinh, then Gauss–Legendre once it pays);
//! `trajectory()` and `theta_at_times()` one Taylor-series run per precision
//! for all times. The oracle caches what depends only on the model and the
//! precision (engines with their node sets, the scan bracket, θs and t_s per
//! precision), never a requested answer.
//!
//! A model that falls to the left (θ0 < 0, or θ0 = 0 with θ̇0 < 0) is solved as
//! its mirror image and the odd quantities (θ, θ̇, θ̈, φ1, φ2, x1, x2, F1, F21)
//! change sign on the way out.

mod findings;
pub(crate) use findings::NOT_COMPARED;
pub mod rigorous;

use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::integrate::energy::Route;
use crate::mechanics::polys::HPoly;
use crate::model::{Contact, Floor, Ideal};
use crate::numeric::verify::{ladder, ladder_runs, ladder_table, Estimate, Run, Verified};
use rug::{Assign, Float};

/// Largest number of significant digits accepted.
pub const MAX_DIGITS: u32 = 2000;

/// Names of the columns of a trajectory row, in order.
pub const TRAJECTORY_COLUMNS: [&str; 13] = [
    "t",
    "theta",
    "theta_dot",
    "theta_ddot",
    "phi1",
    "phi2",
    "x1",
    "x2",
    "y2",
    "F1",
    "N1",
    "F21",
    "N12",
];

/// Names of the quantities of [`Oracle::forces_at`], in order.
pub const FORCE_KEYS: [&str; 8] = [
    "F1",
    "N1",
    "F21",
    "N12",
    "theta_dot",
    "theta_ddot",
    "mu_floor",
    "mu_contact",
];

/// What `separation` reports.
#[derive(Debug, Clone)]
pub struct Separation {
    /// θs: the angle where N12 = 0.
    pub theta_s: Verified,
    /// The time from the start to separation (`None`: infinite, start from rest
    /// at the top).
    pub t_s: Option<Verified>,
    /// Further verified quantities (sign-change angles, F21 at separation, the
    /// angles where rolling would first fail for `--mu`, where N1 vanishes).
    pub extra: Vec<Verified>,
    /// Plain-language findings (what does not exist, what coincides).
    pub notes: Vec<String>,
}

/// The oracle for one model at one requested accuracy.
pub struct Oracle {
    model: Ideal,
    digits: u32,
    mu: Option<Exact>,
    /// The energy route with its caches.
    pub route: Route,
}

/// Where an extremum along [θ0, θs] lies.
#[derive(Debug, Clone)]
enum At {
    /// θ0.
    Start,
    /// θs.
    Separation,
    /// A given angle inside the motion.
    Angle(Exact),
    /// An interior root c of a polynomial in c = cos θ (found at
    /// `SCAN_PREC` bits), refined at each precision.
    Root(Float, crate::mechanics::dynamics::HPoly),
}

/// The one value of a one-name ladder.
fn single(v: Vec<Verified>) -> Result<Verified> {
    v.into_iter()
        .next()
        .ok_or_else(|| Error::not_physical("internal: the ladder returned no value"))
}

impl Oracle {
    /// An oracle for `model` answering with `digits` significant digits.
    ///
    /// Errors: digits outside 1..=[`MAX_DIGITS`]; a start where the cylinders
    /// already part (N12 ≤ 0) or cylinder 1 already lifts (N1 ≤ 0).
    pub fn new(model: &Ideal, digits: u32) -> Result<Self> {
        super::check_digits(digits)?;
        Ok(Oracle {
            model: model.clone(),
            digits,
            mu: None,
            route: Route::new(model)?,
        })
    }

    /// An oracle for `model` that uses (and keeps) an energy route already
    /// built for it, with its caches.
    ///
    /// Errors: digits outside 1..=[`MAX_DIGITS`].
    pub fn with_route(model: &Ideal, digits: u32, route: Route) -> Result<Self> {
        super::check_digits(digits)?;
        Ok(Oracle {
            model: model.clone(),
            digits,
            mu: None,
            route,
        })
    }

    /// The energy route, with its caches.
    pub fn into_route(self) -> Route {
        self.route
    }

    /// Sets the friction coefficient μ for which `separation` reports where
    /// rolling without slipping would first fail (μ ≥ 0).
    pub fn with_mu(mut self, mu: Option<Exact>) -> Result<Self> {
        if let Some(m) = &mu {
            if m.signum() < 0 {
                return Err(Error::invalid("mu", m, "must be >= 0"));
            }
        }
        self.mu = mu;
        Ok(self)
    }

    /// The model as given.
    pub fn model(&self) -> &Ideal {
        &self.model
    }

    /// The requested significant digits.
    pub fn digits(&self) -> u32 {
        self.digits
    }

    /// The separation angle θs (where N12 = 0), the separation time, and the
    /// findings listed in [`Separation`].
    pub fn separation(&mut self) -> Result<Separation> {
        let digits = self.digits;
        let finite = !self.route.work.starts_at_equilibrium();
        let mut names = vec!["theta_s"];
        if finite {
            names.push("t_s");
        }
        let main = ladder(digits, &names, |p| {
            let (ds, err) = self.route.delta_s(p)?;
            let th0 = self.route.work.start().theta0.to_float(p);
            let one = Float::with_val(p, 1u32);
            let th = Float::with_val(p, &th0 + &ds);
            let mut out = vec![Estimate::new(self.route.odd(th), err.clone(), one)];
            if finite {
                let ts = self.route.scale_time(p);
                let e = self.route.engine(p)?;
                let (t, terr) = e.time(&ds);
                let st = e.dynm.state(&ds);
                let prop = Float::with_val(p, &err / &st.thetadot);
                out.push(Estimate::new(t, terr + prop, ts));
            }
            Ok(out)
        })?;
        let mut it = main.into_iter();
        let theta_s = it.next().expect("theta_s");
        let t_s = it.next();
        let mut extra = Vec::new();
        let mut notes = Vec::new();
        if !finite {
            notes.push(
                "t_s is infinite: the start is rest exactly at the unstable top; theta_s is the limit theta0 -> 0+"
                    .to_string(),
            );
        }
        self.separation_findings(&theta_s, &mut extra, &mut notes)?;
        Ok(Separation {
            theta_s,
            t_s,
            extra,
            notes,
        })
    }

    /// The branch point's δ* (isolated by [`Route::first_root`] at the
    /// digits' bits), with the free normal
    /// acceleration's polynomial: (polynomial, δ*, its error) — δ* = 0
    /// exactly where ρ̈_free > 0 from the start (parting lawful from θ0) —
    /// or `None` where the motion has none (a held lower cylinder, no root
    /// before θs, or one coinciding with θs within 4× the two bounds or to
    /// the digits asked).
    fn branch_delta(&mut self) -> Result<Option<(HPoly, Float, Float)>> {
        // none on a held floor, nor under a frictionless contact (there
        // ρ̈_free > 0 only where N12 < 0: its root is θs itself), as in the
        // motion
        if self.model.floor() == Floor::Fixed || self.model.contact() == Contact::Slip {
            return Ok(None);
        }
        let hp = self.route.free_normal_poly();
        if self.route.sign_at_start(&hp, self.digits)? > 0 {
            // parting lawful from the start (the motion's rule): θ* = θ0,
            // δ* = 0 exactly (a root of the polynomial is never at δ = 0).
            // This was None: `forces` in the window said nothing of the
            // branch, and the proof of θ* (from the start) enclosed a root
            // before θ0
            return Ok(Some((hp, Float::new(64), Float::new(64))));
        }
        // θ* and θs told apart with the digits asked and the masses' ratio's
        // bits more: under a lower cylinder 10^20 times heavier, or k1 =
        // 10^20, they lie ~10^-21 apart, and at 64 bits the branch point was
        // taken for θs (the motion called unique, and `forces` in the window
        // said nothing of it)
        let spread = crate::integrate::energy::mass_spread_bits(self.route.work.params())
            .unwrap_or(crate::integrate::energy::MAX_SPREAD_BITS);
        let p = 64 + spread + crate::numeric::bits_for_digits(self.digits);
        let (ds, ds_err) = self.route.delta_s(p)?;
        let Some((d, err)) =
            self.route
                .first_root("branch point", &hp, None, &ds, p, self.digits)?
        else {
            return Ok(None);
        };
        // the motion's rule: one that is θs to the digits asked is θs
        let th0 = self.route.work.start().theta0.to_float(p);
        let tol = Float::with_val(p, &err + &ds_err) * 4u32;
        let apart = crate::motion::sides::apart_from_end(&d, &ds, &tol, &th0, self.digits);
        Ok(apart.then_some((hp, d, err)))
    }

    /// θ*, the branch point: the first angle past θ0, before θs, where the
    /// free relative normal acceleration r θ̇² − g cos θ turns positive while
    /// the cylinders press on each other — from there parting is as lawful
    /// as staying together; θ0 itself where it is positive from the start
    /// (exactly, error 0). None where it coincides with θs (a frictionless
    /// contact, a held lower cylinder: the motion is unique) or does not
    /// come before it.
    ///
    /// Method: K²(r θ̇² − g cos θ) is a polynomial in c = cos θ
    /// ([`Route::free_normal_poly`]); its first sign change is isolated and
    /// refined like θs at both precisions of the ladder.
    ///
    /// Errors: a root the refinement cannot verify.
    pub fn branch_point(&mut self) -> Result<Option<Verified>> {
        let Some((hp, d0, _)) = self.branch_delta()? else {
            return Ok(None);
        };
        let at_start = d0.is_zero();
        let v = ladder(self.digits, &["theta_indeterminate"], |p| {
            if at_start {
                let th0 = self.route.work.start().theta0.to_float(p);
                // θ0's rounding at p bits
                let err = Float::with_val(p, th0.abs_ref()) >> p as i32;
                return Ok(vec![Estimate::new(
                    self.route.odd(th0),
                    err,
                    Float::with_val(p, 1u32),
                )]);
            }
            let (ds, _) = self.route.delta_s(p)?;
            let (d, err) = self
                .route
                .first_root("branch point", &hp, None, &ds, p, self.digits)?
                .ok_or_else(|| {
                    Error::not_physical(
                        "internal: the branch point was lost at one precision of the ladder",
                    )
                })?;
            let th0 = self.route.work.start().theta0.to_float(p);
            let th = Float::with_val(p, &th0 + &d);
            Ok(vec![Estimate::new(
                self.route.odd(th),
                err,
                Float::with_val(p, 1u32),
            )])
        })?;
        single(v).map(Some)
    }

    /// The note for an angle asked at or past the branch point θ* (where the
    /// cylinders may lawfully stay together or part, up to θs): the value
    /// is on the `stay` branch. `None` before θ* or where the motion has no
    /// branch point. Decided at the digits' bits with the root's bound: an
    /// angle within it of θ* counts as at θ* (the note says "at or past").
    ///
    /// Errors: as [`Oracle::branch_point`]'s isolation.
    pub fn branch_window_note(&mut self, theta: &Exact) -> Result<Option<String>> {
        let Some((_, d, err)) = self.branch_delta()? else {
            return Ok(None);
        };
        // θ − θ0 at the digits' bits: at 64 bits an angle 10^-20 from a
        // start of 0.1 was placed by θ's rounding
        let q = crate::numeric::bits_for_digits(self.digits) + 64;
        let th0 = self.route.work.start().theta0.to_float(q);
        let dq = Float::with_val(q, self.route.to_work(theta).to_float(q) - &th0);
        if Float::with_val(q, &dq + &err) < d {
            return Ok(None);
        }
        const P: u32 = 64;
        let th_star = self.route.odd(Float::with_val(P, &th0 + &d));
        Ok(Some(format!(
            "theta = {theta} lies at or past the branch point theta_indeterminate ≈ {}, where \
             the rigid-body motion is not unique (from there the cylinders may stay together or \
             part, up to theta_s): the values are on the branch where they stay together (the \
             branch followed); on --branch part the cylinders have parted at \
             theta_indeterminate and this angle is reached in flight, if at all",
            crate::numeric::decimal::approx_text(&th_star)
        )))
    }

    /// θs alone: the first angle past θ0 where N12 = 0, with verified digits
    /// (the same quantity as [`Separation::theta_s`], without the other
    /// findings of [`Oracle::separation`]).
    ///
    /// Method: N12·K²/m2 is a polynomial of degree ≤ 5 in c = cos θ
    /// ([`crate::mechanics::polys::N12Poly`]); its sign changes
    /// on [−1, cos θ0] are isolated at 64 bits by the monotone pieces between
    /// the roots of its derivatives (so, unlike a scan, no pair of close roots
    /// is missed), the largest one (the first in θ) is refined by Newton steps
    /// at doubling precision to a bracket [c − ε, c + ε] across which the
    /// polynomial changes sign, and θs = acos c with error ε/sin θs. Each call
    /// computes from scratch (nothing is memoised between calls).
    ///
    /// Errors: no sign change before θ = π.
    pub fn separation_angle(&mut self) -> Result<Verified> {
        use crate::numeric::poly;
        const ISO: u32 = 64;
        let c0 = self.route.engine(ISO)?.dynm.c0.clone();
        let coef = self.route.n12_coefficients(ISO)?;
        let roots = poly::sign_change_roots(&coef, &Float::with_val(ISO, -1), &c0);
        let start = roots.into_iter().rev().find(|c| *c < c0).ok_or_else(|| {
            Error::not_physical("N12 stays positive up to theta = pi: the cylinders never separate")
        })?;
        let v = ladder(self.digits, &["theta_s"], |p| {
            let coef = self.route.n12_coefficients(p + 16)?;
            let (c, eps) = poly::refine_root("theta_s", &coef, &start, p)?;
            let (th, th_err) = crate::numeric::root::acos_newton(&c, p);
            // dθ = −dc / sin θ, sin θ = √(1 − c²) (> 0 on (0, π)); ×(1 + 2^-16)
            let sin = Float::with_val(p, 1u32 - Float::with_val(p, c.square_ref())).sqrt();
            let mut err = Float::with_val(p, &eps / &sin);
            err += Float::with_val(p, &err >> 16);
            err += th_err;
            Ok(vec![Estimate::new(
                self.route.odd(th),
                err,
                Float::with_val(p, 1u32),
            )])
        })?;
        single(v)
    }

    /// t(θ): the time from the start to the angle θ (energy quadrature).
    ///
    /// Method: for θ ≤ 2π/3 the integral in s = sin(θ/2), an algebraic
    /// integrand ([`crate::mechanics::dynamics::HalfAngleTime`]); the ladder's
    /// first run by tanh-sinh, its second by tanh-sinh too — or, once this
    /// oracle has spent more on tanh-sinh integrals at that precision than a
    /// Gauss–Legendre rule costs to build, by Gauss–Legendre with its a-priori
    /// error model (two methods at two precisions). Beyond 2π/3 the θ form.
    ///
    /// Errors: θ outside [θ0, θs]; a start from rest at the top (infinite).
    pub fn time_at(&mut self, theta: &Exact) -> Result<Verified> {
        if self.route.work.starts_at_equilibrium() {
            return Err(self.route.infinite_time_error("the time to any angle"));
        }
        let v = ladder_runs(self.digits, &["t"], |p, run| {
            let d = self.route.delta_of("to", theta, p, self.digits)?;
            let ts = self.route.scale_time(p);
            let (t, err, _) = self.route.engine(p)?.time_fast(&d, run == Run::High, true);
            Ok(vec![Estimate::new(t, err, ts)])
        })?;
        Ok(v.into_iter().next().expect("one"))
    }

    /// F1, N1, F21, N12, θ̇, θ̈ and the friction coefficients needed
    /// (|F1|/N1 at a rolling floor, |F21|/N12 at a rolling contact; 0 where the
    /// contact slips or the floor is fixed) at angle θ, in [`FORCE_KEYS`] order.
    pub fn forces_at(&mut self, theta: &Exact) -> Result<Vec<Verified>> {
        let floor = self.route.work.floor();
        let contact = self.route.work.contact();
        let mut out = ladder(self.digits, &FORCE_KEYS[..6], |p| {
            let d = self.route.delta_of("theta", theta, p, self.digits)?;
            let sf = self.route.scale_force(p);
            let ts = self.route.scale_time(p);
            let e = self.route.engine(p)?;
            let st = e.dynm.state(&d);
            let f = e.dynm.forces(&st);
            let one = Float::with_val(p, 1u32);
            Ok(vec![
                self.force_est(f.f1.clone(), &sf, floor == Floor::Slip, true),
                Estimate::rounded(f.n1.clone(), sf.clone()),
                self.force_est(f.f21.clone(), &sf, contact == Contact::Slip, true),
                Estimate::rounded(f.n12.clone(), sf.clone()),
                Estimate::rounded(
                    self.route.odd(st.thetadot.clone()),
                    Float::with_val(p, one.clone() / &ts),
                ),
                Estimate::rounded(
                    self.route.odd(st.thetaddot.clone()),
                    Float::with_val(p, one.clone() / &ts) / &ts,
                ),
            ])
        })?;
        // The friction each contact needs, |F|/N, wherever F is a reaction
        // (a rolling floor, a held cylinder 1: the coefficient a floor would
        // need to hold it by friction; a rolling contact); 0 where the contact
        // is frictionless (F = 0). Where N is 0 to within its bound (at θs,
        // N12 = 0) the ratio has no finite verified value: it is given as the
        // lower bound |F|/bound(N), marked ">=".
        for (key, fi, ni, applies) in [
            ("mu_floor", 0usize, 1usize, floor != Floor::Slip),
            ("mu_contact", 2, 3, contact == Contact::Roll),
        ] {
            let v = friction_ratio(key, &out[fi], &out[ni], applies, self.digits)?;
            out.push(v);
        }
        Ok(out)
    }

    /// The largest friction each rolling contact needs over [θ0, θ], and
    /// where: `theta_mu_floor_max`, `mu_floor_max` (a rolling or held floor)
    /// and `theta_mu_contact_max`, `mu_contact_max` (a rolling contact),
    /// verified like [`Oracle::separation`]'s extrema. Where N12 is 0 at θ to
    /// within its bound (θ = θs), the contact's maximum is only bounded below
    /// (text `>=…`), as in [`Oracle::forces_at`].
    ///
    /// Errors: θ outside the motion (as [`Oracle::forces_at`]).
    pub fn friction_needed(&mut self, theta: &Exact) -> Result<Vec<Verified>> {
        let forces = self.forces_at(theta)?;
        // beyond the bits the comparison is given: not made (the caller
        // notes it, findings::NOT_COMPARED)
        let w64 = self.route.to_work(theta).to_float(64);
        let Some(fp) = self.findings_prec(&w64) else {
            return Ok(Vec::new());
        };
        let w = self.route.to_work(theta).to_float(fp);
        let c_end = Float::with_val(fp, w.cos_ref());
        let mut out = Vec::new();
        if self.route.work.floor() != Floor::Slip {
            out.extend(self.needed_max(false, At::Angle(theta.clone()), &c_end, fp)?);
        }
        if self.route.work.contact() == Contact::Roll {
            let mu = forces.iter().find(|v| v.name == "mu_contact");
            match mu {
                Some(m) if m.text.starts_with(">=") => {
                    let th = ladder(self.digits, &["theta_mu_contact_max"], |p| {
                        let d = self.route.delta_of("theta", theta, p, self.digits)?;
                        let th0 = self.route.work.start().theta0.to_float(p);
                        let th = Float::with_val(p, th0 + d);
                        Ok(vec![Estimate::rounded(
                            self.route.odd(th),
                            Float::with_val(p, 1u32),
                        )])
                    })?;
                    out.extend(th);
                    let mut m = m.clone();
                    m.name = "mu_contact_max".into();
                    out.push(m);
                }
                _ => out.extend(self.needed_max(true, At::Angle(theta.clone()), &c_end, fp)?),
            }
        }
        Ok(out)
    }

    fn force_est(&self, v: Float, scale: &Float, exact_zero: bool, odd: bool) -> Estimate {
        if exact_zero {
            Estimate::zero(v.prec(), scale.clone())
        } else {
            let v = if odd { self.route.odd(v) } else { v };
            Estimate::rounded(v, scale.clone())
        }
    }

    /// The trajectory at the given times: one row per time with the columns of
    /// [`TRAJECTORY_COLUMNS`] (t first, as given).
    ///
    /// Method: one Taylor-series run of θ̈ = F(θ) per working precision
    /// ([`crate::numeric::taylor`]) serves every time (dense output); each row
    /// then follows from δ = θ − θ0 as before. Verified by the precision
    /// ladder row by row ([`crate::numeric::verify::ladder_table`]), with the
    /// integrator's error estimate, and checked at the last time against the
    /// energy quadrature: t(θ ∓ ε) must bracket it.
    ///
    /// Errors: a start from rest at the top; a negative time; a time after
    /// separation.
    pub fn trajectory(&mut self, times: &[Exact]) -> Result<Vec<Vec<Verified>>> {
        self.route.check_times(times)?;
        let floor = self.route.work.floor();
        let contact = self.route.work.contact();
        let mut cache = crate::exact::TableTimes::default();
        // the time is an input: printed exactly when it is a terminating
        // decimal (a denominator of 2s and 5s only; checked first, as writing
        // out a long fraction costs more than the whole row), so that a time
        // such as 0.125 at two digits is not a rounding tie to decide
        let exact_t = crate::oracle::ladder::exact_times(times);
        let rows = ladder_table(self.digits, &TRAJECTORY_COLUMNS, times.len(), |p, run| {
            let deltas =
                self.route
                    .deltas_at(times, p, run, true, &mut cache, self.digits, None)?;
            let ctx = self.route.row_context(p);
            let mut out = Vec::with_capacity(times.len() * TRAJECTORY_COLUMNS.len());
            for ((t, (d, derr)), text) in times.iter().zip(deltas).zip(&exact_t) {
                let mut row = self
                    .route
                    .row_estimates(t, &d, &derr, &ctx, floor, contact)?;
                row[0].exact_text = text.clone();
                out.extend(row);
            }
            Ok(out)
        })?;
        Ok(rows)
    }

    /// θ alone at the given times (the `theta` column of
    /// [`Oracle::trajectory`], with the same digits), without the other
    /// columns: one Taylor run per working precision and one Horner
    /// evaluation per time.
    ///
    /// Errors: as [`Oracle::trajectory`].
    pub fn theta_at_times(&mut self, times: &[Exact]) -> Result<Vec<Verified>> {
        self.route.check_times(times)?;
        let mut cache = crate::exact::TableTimes::default();
        let rows = ladder_table(self.digits, &["theta"], times.len(), |p, run| {
            let deltas =
                self.route
                    .deltas_at(times, p, run, false, &mut cache, self.digits, None)?;
            let th0 = self.route.work.start().theta0.to_float(p);
            let one = Float::with_val(p, 1u32);
            let mut ulps = Float::new(p);
            Ok(deltas
                .into_iter()
                .map(|(d, mut err)| {
                    let th = Float::with_val(p, &th0 + &d);
                    ulps.assign(th.abs_ref());
                    ulps >>= p as i32 - 4;
                    err += &ulps;
                    Estimate::new(self.route.odd(th), err, one.clone())
                })
                .collect())
        })?;
        Ok(rows
            .into_iter()
            .filter_map(|r| r.into_iter().next())
            .collect())
    }
}

/// The friction a contact needs, |F|/N, from the verified F and N (`key`:
/// `mu_floor` or `mu_contact`): 0 where the contact is frictionless (not
/// `applies`); where N is 0 to within its bound (N12 at θs) no finite
/// value is verified and the lower bound |F|/bound(N) is given, marked
/// `>=`; otherwise the relative bounds of F and N add and the ratio keeps
/// the digits they support.
///
/// Errors: a ratio without one verified digit.
pub fn friction_ratio(
    key: &str,
    fv: &Verified,
    nv: &Verified,
    applies: bool,
    digits: u32,
) -> Result<Verified> {
    let v = if !applies {
        ladder(digits, &[key], |p| {
            Ok(vec![Estimate::zero(p, Float::with_val(p, 1u32))])
        })?
        .remove(0)
    } else if nv.digits == 0 && fv.digits > 0 {
        let p = fv.value.prec();
        // |F| >= |F~| − err(F) and N <= bound(N): the ratio is at least
        // their quotient (rounded down when printed)
        let lower = (Float::with_val(p, fv.value.abs_ref()) - &fv.err_bound) / &nv.err_bound;
        Verified {
            name: key.to_string(),
            text: format!(">={}", crate::numeric::decimal::short_down(&lower)),
            value: lower,
            digits: 0,
            err_bound: Float::with_val(p, f64::INFINITY),
            precs: fv.precs,
        }
    } else {
        // |F|/N from the verified F and N: relative bounds add, and
        // the ratio keeps the digits they support (no more than N12
        // keeps just before θs)
        let p = fv.value.prec().max(nv.value.prec());
        let ratio = Float::with_val(p, fv.value.abs_ref()) / &nv.value;
        let fa = Float::with_val(p, fv.value.abs_ref());
        let na = Float::with_val(p, nv.value.abs_ref());
        let rel = Float::with_val(p, &fv.err_bound / &fa) + Float::with_val(p, &nv.err_bound / &na);
        let ra = Float::with_val(p, ratio.abs_ref());
        let ulps = Float::with_val(p, &ra >> (p as i32 - 4));
        let err = Float::with_val(p, &rel * &ra) + ulps;
        let dg = if fv.digits == 0 { 0 } else { digits };
        if dg == 0 {
            // F is 0 to within its bound: so is the ratio
            Verified {
                name: key.to_string(),
                text: "0".into(),
                value: Float::new(p),
                digits: 0,
                err_bound: Float::with_val(p, &fv.err_bound / &nv.value),
                precs: fv.precs,
            }
        } else {
            crate::numeric::verify::verified_from(key, ratio, err, dg)?
        }
    };
    Ok(v)
}
