//! The questions users ask, answered with verified digits.
//!
//! An [`Oracle`] holds a model and a requested number of significant digits.
//! Each method runs its computation through the precision ladder
//! ([`crate::numeric::verify::ladder`]) and returns [`Verified`] numbers.
//!
//! A model that falls to the left (θ0 < 0, or θ0 = 0 with θ̇0 < 0) is solved as
//! its mirror image and the odd quantities (θ, θ̇, θ̈, φ1, φ2, x1, x2, F1, F21)
//! change sign on the way out.

mod engine;

use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::mechanics::Reduced;
use crate::model::{Contact, Floor, Model};
use crate::numeric::verify::{ladder, Estimate, Verified};
use engine::Engine;
use rug::Float;
use std::collections::HashMap;

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
    model: Model,
    work: Model,
    sign: i32,
    red: Reduced,
    digits: u32,
    engines: HashMap<u32, Engine>,
    mu: Option<Exact>,
}

/// Precision of the scans that locate brackets (refined afterwards).
const SCAN_PREC: u32 = 96;
/// Scan steps over the motion.
const SCAN_STEPS: u32 = 512;

impl Oracle {
    /// An oracle for `model` answering with `digits` significant digits.
    ///
    /// Errors: digits outside 1..=[`MAX_DIGITS`]; a start where the cylinders
    /// already part (N12 ≤ 0) or cylinder 1 already lifts (N1 ≤ 0).
    pub fn new(model: &Model, digits: u32) -> Result<Self> {
        if digits == 0 || digits > MAX_DIGITS {
            return Err(Error::invalid(
                "digits",
                digits,
                format!("must be between 1 and {MAX_DIGITS}"),
            ));
        }
        let sign = model.direction();
        let work = if sign < 0 {
            model.mirrored()
        } else {
            model.clone()
        };
        let red = Reduced::new(&work)?;
        let mut o = Oracle {
            model: model.clone(),
            work,
            sign,
            red,
            digits,
            engines: HashMap::new(),
            mu: None,
        };
        let e = o.engine(SCAN_PREC)?;
        let z = Float::new(SCAN_PREC);
        let st = e.dynm.state(&z);
        let f = e.dynm.forces(&st);
        if !f.n12.is_sign_positive() || f.n12.is_zero() {
            return Err(Error::not_physical(format!(
                "the cylinders part at once: N12 = {:.3e} <= 0 at the start (thetadot0 too large for theta0)",
                f.n12.to_f64()
            )));
        }
        if !f.n1.is_sign_positive() || f.n1.is_zero() {
            return Err(Error::not_physical(format!(
                "cylinder 1 lifts off the floor at once: N1 = {:.3e} <= 0 at the start",
                f.n1.to_f64()
            )));
        }
        Ok(o)
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
    pub fn model(&self) -> &Model {
        &self.model
    }

    /// The requested significant digits.
    pub fn digits(&self) -> u32 {
        self.digits
    }

    fn engine(&mut self, prec: u32) -> Result<&mut Engine> {
        if !self.engines.contains_key(&prec) {
            let e = Engine::new(&self.work, &self.red, prec)?;
            self.engines.insert(prec, e);
        }
        Ok(self.engines.get_mut(&prec).expect("inserted"))
    }

    fn infinite_time_error(&self, what: &str) -> Error {
        Error::not_physical(format!(
            "{what} is infinite: the motion starts from rest exactly at the unstable top (theta0 = 0, thetadot0 = 0); \
             give a small --theta0 or --thetadot0 (forces and the separation angle are defined as the limit theta0 -> 0+)"
        ))
    }

    /// δs = θs − θ0 at `prec`, as (value, error), with the bracket scanned at
    /// low precision first.
    fn delta_s(&mut self, prec: u32) -> Result<(Float, Float)> {
        let th0 = self.work.start().theta0.to_float(SCAN_PREC);
        let hi = Float::with_val(SCAN_PREC, rug::float::Constant::Pi) - th0;
        let scan = self.engine(SCAN_PREC)?;
        let zero = Float::new(SCAN_PREC);
        let bracket =
            crate::numeric::root::first_sign_change(&zero, &hi, SCAN_STEPS, |d| scan.n12(d));
        let (lo, hi) = bracket.ok_or_else(|| {
            Error::not_physical("N12 stays positive up to theta = pi: the cylinders never separate")
        })?;
        let e = self.engine(prec)?;
        e.refine_root("theta_s", &lo, &hi, |eng, d| eng.n12(d))
    }

    /// θ in the working frame from a user angle.
    fn to_work(&self, theta: &Exact) -> Exact {
        if self.sign < 0 {
            theta.neg()
        } else {
            theta.clone()
        }
    }

    fn odd(&self, x: Float) -> Float {
        if self.sign < 0 {
            -x
        } else {
            x
        }
    }

    fn scale_force(&self, p: u32) -> Float {
        let pr = self.work.params();
        Float::with_val(p, &rug::Rational::from(&pr.m1 + &pr.m2)) * &pr.g
    }

    fn scale_time(&self, p: u32) -> Float {
        let pr = self.work.params();
        Float::with_val(p, Float::with_val(p, &pr.r()) / &pr.g).sqrt()
    }

    /// The separation angle θs (where N12 = 0), the separation time, and the
    /// findings listed in [`Separation`].
    pub fn separation(&mut self) -> Result<Separation> {
        let digits = self.digits;
        let finite = !self.work.starts_at_equilibrium();
        let mut names = vec!["theta_s"];
        if finite {
            names.push("t_s");
        }
        let main = ladder(digits, &names, |p| {
            let (ds, err) = self.delta_s(p)?;
            let th0 = self.work.start().theta0.to_float(p);
            let one = Float::with_val(p, 1u32);
            let th = Float::with_val(p, &th0 + &ds);
            let mut out = vec![Estimate::new(self.odd(th), err.clone(), one)];
            if finite {
                let ts = self.scale_time(p);
                let e = self.engine(p)?;
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

    /// Sign-change angles, N1 > 0, friction needed, slip angles for μ.
    fn separation_findings(
        &mut self,
        theta_s: &Verified,
        extra: &mut Vec<Verified>,
        notes: &mut Vec<String>,
    ) -> Result<()> {
        let digits = self.digits;
        let th0 = self.work.start().theta0.to_float(SCAN_PREC);
        let ds_scan = Float::with_val(SCAN_PREC, self.odd(theta_s.value.clone())) - &th0;
        let floor = self.work.floor();
        let contact = self.work.contact();
        let finite = !self.work.starts_at_equilibrium();
        let sign = self.sign;

        // --- N1 > 0 up to separation
        let n1_root = {
            let scan = self.engine(SCAN_PREC)?;
            let z = Float::new(SCAN_PREC);
            crate::numeric::root::first_sign_change(&z, &ds_scan, SCAN_STEPS, |d| scan.n1(d))
        };
        match n1_root {
            None => notes.push(format!(
                "N1 > 0 at all {SCAN_STEPS} scan points up to separation: cylinder 1 stays on the floor"
            )),
            Some((lo, hi)) => {
                let v = ladder(digits, &["theta_N1_zero"], |p| {
                    let (d, err) = self.engine(p)?.refine_root("theta_N1_zero", &lo, &hi, |e, d| e.n1(d))?;
                    let th = Float::with_val(p, self.work.start().theta0.to_float(p) + d);
                    Ok(vec![Estimate::new(self.odd(th), err, Float::with_val(p, 1u32))])
                })?;
                notes.push(format!(
                    "N1 vanishes at theta = {} before separation: cylinder 1 would leave the floor there, \
                     and the motion after that angle (including theta_s) is not the model's",
                    v[0].text
                ));
                extra.extend(v);
            }
        }

        // --- where φ̇1 and φ1 change sign
        let phi_moves = floor != Floor::Fixed
            && (self.red.alpha[1] != 0 || self.red.beta[1] != 0 || self.red.gamma[1] != 0);
        if phi_moves {
            let gamma0 = self.red.gamma[1] == 0;
            for (name, label) in [
                ("theta_phi1dot_zero", "phi1_dot"),
                ("theta_phi1_zero", "phi1"),
            ] {
                let needs_time = name == "theta_phi1_zero" && !gamma0;
                if needs_time && !finite {
                    notes.push(format!(
                        "{label} sign change not computed: it depends on the (infinite) time"
                    ));
                    continue;
                }
                let f = |e: &mut Engine, d: &Float| -> Float {
                    if name == "theta_phi1dot_zero" {
                        e.phi1_dot(d)
                    } else {
                        e.phi1(d)
                    }
                };
                let step = Float::with_val(SCAN_PREC, &ds_scan / SCAN_STEPS);
                let found = {
                    let scan = self.engine(SCAN_PREC)?;
                    let lo0 = Float::with_val(SCAN_PREC, &step / 4u32);
                    // include a sliver past θs so a root at separation is seen
                    let hi0 = Float::with_val(SCAN_PREC, &ds_scan + &step);
                    crate::numeric::root::first_sign_change(&lo0, &hi0, SCAN_STEPS + 1, |d| {
                        f(scan, d)
                    })
                };
                match found {
                    None => notes.push(format!(
                        "{label} keeps its sign from the start to separation"
                    )),
                    Some((lo, hi)) => {
                        let v = ladder(digits, &[name], |p| {
                            let (d, err) =
                                self.engine(p)?
                                    .refine_root(name, &lo, &hi, |e, d| f(e, d))?;
                            let th = Float::with_val(p, self.work.start().theta0.to_float(p) + d);
                            Ok(vec![Estimate::new(
                                self.odd(th),
                                err,
                                Float::with_val(p, 1u32),
                            )])
                        })?;
                        let v = v.into_iter().next().expect("one");
                        let bound =
                            Float::with_val(v.value.prec(), &v.err_bound + &theta_s.err_bound);
                        let gap = Float::with_val(v.value.prec(), &v.value - &theta_s.value).abs();
                        if gap <= bound {
                            notes.push(format!(
                                "{label} changes sign at separation (equal to all digits verified)"
                            ));
                        } else if (v.value.clone() * sign) > (theta_s.value.clone() * sign) {
                            notes.push(format!(
                                "{label} keeps its sign from the start to separation"
                            ));
                            continue;
                        }
                        extra.push(v);
                    }
                }
            }
        }

        // --- friction: F21 at separation (μ needed at the contact diverges if ≠ 0)
        if contact == Contact::Roll {
            let v = ladder(digits, &["F21_at_s"], |p| {
                let (ds, err) = self.delta_s(p)?;
                let sf = self.scale_force(p);
                let e = self.engine(p)?;
                let st = e.dynm.state(&ds);
                let f = e.dynm.forces(&st);
                let d2 = Float::with_val(p, &ds + &err);
                let f2 = e.dynm.forces(&e.dynm.state(&d2));
                let prop = Float::with_val(p, &f2.f21 - &f.f21).abs();
                Ok(vec![Estimate::new(self.odd(f.f21), prop, sf)])
            })?;
            if v[0].text != "0" {
                notes.push(
                    "F21 != 0 at separation while N12 -> 0: the friction coefficient the contact needs, |F21|/N12, grows without bound as theta -> theta_s, so the upper cylinder slips before it separates for any finite mu"
                        .to_string(),
                );
            }
            extra.extend(v);
        }
        if let Some(mu) = self.mu.clone() {
            let checks: Vec<(&str, bool)> = vec![
                ("theta_slip_floor", floor == Floor::Roll),
                ("theta_slip_contact", contact == Contact::Roll),
            ];
            for (name, applies) in checks {
                if !applies {
                    continue;
                }
                let floor_side = name == "theta_slip_floor";
                let g = move |e: &mut Engine, d: &Float, mu: &Float| -> Float {
                    let st = e.dynm.state(d);
                    let f = e.dynm.forces(&st);
                    let (fr, n) = if floor_side {
                        (f.f1, f.n1)
                    } else {
                        (f.f21, f.n12)
                    };
                    Float::with_val(d.prec(), mu * n) - fr.abs()
                };
                let found = {
                    let mu_s = mu.to_float(SCAN_PREC);
                    let scan = self.engine(SCAN_PREC)?;
                    let z = Float::new(SCAN_PREC);
                    crate::numeric::root::first_sign_change(&z, &ds_scan, SCAN_STEPS, |d| {
                        g(scan, d, &mu_s)
                    })
                };
                match found {
                    None => notes.push(format!(
                        "{name}: rolling holds up to separation with mu = {mu}"
                    )),
                    Some((lo, hi)) => {
                        let v = ladder(digits, &[name], |p| {
                            let mu_p = mu.to_float(p);
                            let (d, err) =
                                self.engine(p)?
                                    .refine_root(name, &lo, &hi, |e, d| g(e, d, &mu_p))?;
                            let th = Float::with_val(p, self.work.start().theta0.to_float(p) + d);
                            Ok(vec![Estimate::new(
                                self.odd(th),
                                err,
                                Float::with_val(p, 1u32),
                            )])
                        })?;
                        extra.extend(v);
                    }
                }
            }
        }
        Ok(())
    }

    /// δ = θ − θ0 (working frame) for a user angle, checked to lie in the motion.
    fn delta_of(&mut self, param: &str, theta: &Exact, p: u32) -> Result<Float> {
        let w = self.to_work(theta);
        let th0 = self.work.start().theta0.clone();
        let d = Float::with_val(p, w.to_float(p) - th0.to_float(p));
        let (ds, _) = self.delta_s(p.min(SCAN_PREC.max(p)))?;
        let th_s = Float::with_val(p, th0.to_float(p) + &ds);
        let range = format!(
            "must lie in the motion, between theta0 = {} and the separation angle theta_s = {}",
            self.model.start().theta0,
            crate::numeric::decimal::to_sig(&self.odd(th_s), 12)
        );
        if d.is_sign_negative() && !d.is_zero() {
            return Err(Error::invalid(
                param,
                theta,
                format!("{range} (it is before the start)"),
            ));
        }
        if d > ds {
            return Err(Error::invalid(
                param,
                theta,
                format!("{range} (it is after separation)"),
            ));
        }
        Ok(d)
    }

    /// t(θ): the time from the start to the angle θ (energy quadrature).
    ///
    /// Errors: θ outside [θ0, θs]; a start from rest at the top (infinite).
    pub fn time_at(&mut self, theta: &Exact) -> Result<Verified> {
        if self.work.starts_at_equilibrium() {
            return Err(self.infinite_time_error("the time to any angle"));
        }
        let v = ladder(self.digits, &["t"], |p| {
            let d = self.delta_of("to", theta, p)?;
            let ts = self.scale_time(p);
            let (t, err) = self.engine(p)?.time(&d);
            Ok(vec![Estimate::new(t, err, ts)])
        })?;
        Ok(v.into_iter().next().expect("one"))
    }

    /// F1, N1, F21, N12, θ̇, θ̈ and the friction coefficients needed
    /// (|F1|/N1 at a rolling floor, |F21|/N12 at a rolling contact; 0 where the
    /// contact slips or the floor is fixed) at angle θ, in [`FORCE_KEYS`] order.
    pub fn forces_at(&mut self, theta: &Exact) -> Result<Vec<Verified>> {
        let floor = self.work.floor();
        let contact = self.work.contact();
        ladder(self.digits, &FORCE_KEYS, |p| {
            let d = self.delta_of("theta", theta, p)?;
            let sf = self.scale_force(p);
            let ts = self.scale_time(p);
            let e = self.engine(p)?;
            let st = e.dynm.state(&d);
            let f = e.dynm.forces(&st);
            let one = Float::with_val(p, 1u32);
            let mut out = vec![
                self.force_est(f.f1.clone(), &sf, floor == Floor::Slip, true),
                Estimate::rounded(f.n1.clone(), sf.clone()),
                self.force_est(f.f21.clone(), &sf, contact == Contact::Slip, true),
                Estimate::rounded(f.n12.clone(), sf.clone()),
                Estimate::rounded(
                    self.odd(st.thetadot.clone()),
                    Float::with_val(p, one.clone() / &ts),
                ),
                Estimate::rounded(
                    self.odd(st.thetaddot.clone()),
                    Float::with_val(p, one.clone() / &ts) / &ts,
                ),
            ];
            let ratio = |fr: &Float, n: &Float| Float::with_val(p, fr.abs_ref()) / n;
            out.push(if floor == Floor::Roll {
                Estimate::rounded(ratio(&f.f1, &f.n1), one.clone())
            } else {
                Estimate::zero(p, one.clone())
            });
            out.push(if contact == Contact::Roll {
                Estimate::rounded(ratio(&f.f21, &f.n12), one.clone())
            } else {
                Estimate::zero(p, one.clone())
            });
            Ok(out)
        })
    }

    fn force_est(&self, v: Float, scale: &Float, exact_zero: bool, odd: bool) -> Estimate {
        if exact_zero {
            Estimate::zero(v.prec(), scale.clone())
        } else {
            let v = if odd { self.odd(v) } else { v };
            Estimate::rounded(v, scale.clone())
        }
    }

    /// The trajectory at the given times: one row per time with the columns of
    /// [`TRAJECTORY_COLUMNS`] (t first, as given).
    ///
    /// Errors: a start from rest at the top; a negative time; a time after
    /// separation.
    pub fn trajectory(&mut self, times: &[Exact]) -> Result<Vec<Vec<Verified>>> {
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
        let mut rows = Vec::with_capacity(times.len());
        for t in times {
            rows.push(self.row_at(t)?);
        }
        Ok(rows)
    }

    fn row_at(&mut self, t: &Exact) -> Result<Vec<Verified>> {
        let mut row = self.row_values(t)?;
        // the time is an input: print it exactly when it is a terminating decimal
        let exact = crate::exact::rational_text(&t.coef);
        if !t.times_pi && !exact.contains('/') {
            row[0].text = exact;
        }
        Ok(row)
    }

    fn row_values(&mut self, t: &Exact) -> Result<Vec<Verified>> {
        let floor = self.work.floor();
        let contact = self.work.contact();
        ladder(self.digits, &TRAJECTORY_COLUMNS, |p| {
            let tf = t.to_float(p);
            let (ds, _) = self.delta_s(p)?;
            let (t_s, _) = self.engine(p)?.time(&ds);
            if tf > t_s {
                return Err(Error::invalid(
                    "times",
                    t,
                    format!(
                        "must be <= the separation time t_s = {}: the model ends when the cylinders part",
                        crate::numeric::decimal::to_sig(&t_s, 12)
                    ),
                ));
            }
            let (d, derr) = self.delta_at_time(&tf, &ds, &t_s, p)?;
            let sf = self.scale_force(p);
            let ts = self.scale_time(p);
            let pr = self.work.params().clone();
            let rr = Float::with_val(p, &pr.r());
            let r1 = Float::with_val(p, &pr.r1);
            let e = self.engine(p)?;
            let st = e.dynm.state(&d);
            let d2 = Float::with_val(p, &d + &derr);
            let st2 = e.dynm.state(&d2);
            let vals = |st: &crate::mechanics::dynamics::State, e: &Engine| -> Vec<Float> {
                let pos = e.dynm.positions(st, &tf);
                let f = e.dynm.forces(st);
                let x2 = Float::with_val(p, &rr * &st.s) + &pos[0];
                let y2 = Float::with_val(p, &rr * &st.c) + &r1;
                let phi2 = Float::with_val(p, &pos[2] + &st.theta);
                vec![
                    st.theta.clone(),
                    st.thetadot.clone(),
                    st.thetaddot.clone(),
                    pos[1].clone(),
                    phi2,
                    pos[0].clone(),
                    x2,
                    y2,
                    f.f1,
                    f.n1,
                    f.f21,
                    f.n12,
                ]
            };
            let a = vals(&st, e);
            let b = vals(&st2, e);
            let one = Float::with_val(p, 1u32);
            let scales = [
                one.clone(),
                Float::with_val(p, &one / &ts),
                Float::with_val(p, &one / &ts) / &ts,
                one.clone(),
                one.clone(),
                rr.clone(),
                rr.clone(),
                rr.clone(),
                sf.clone(),
                sf.clone(),
                sf.clone(),
                sf.clone(),
            ];
            // odd columns change sign in the mirror
            let odd = [
                true, true, true, true, true, true, true, false, true, false, true, false,
            ];
            let mut out = vec![Estimate {
                value: tf.clone(),
                err: Float::with_val(p, tf.abs_ref()) >> (p as i32 - 2),
                exact_zero: t.is_zero(),
                scale: ts.clone(),
            }];
            for i in 0..12 {
                let prop = Float::with_val(p, &b[i] - &a[i]).abs();
                let ulps = Float::with_val(p, a[i].abs_ref()) >> (p as i32 - 4);
                let zero =
                    (i == 8 && floor == Floor::Slip) || (i == 10 && contact == Contact::Slip);
                let v = if odd[i] {
                    self.odd(a[i].clone())
                } else {
                    a[i].clone()
                };
                out.push(Estimate {
                    value: v,
                    err: prop + ulps,
                    exact_zero: zero,
                    scale: scales[i].clone(),
                });
            }
            Ok(out)
        })
    }

    /// Solves t(δ) = t for δ at `prec`: a safeguarded Newton iteration at low
    /// precision, then Newton steps at doubling precision, then a check that
    /// t(δ∓ε) brackets t. Returns (δ, error estimate).
    fn delta_at_time(
        &mut self,
        t: &Float,
        ds: &Float,
        t_s: &Float,
        prec: u32,
    ) -> Result<(Float, Float)> {
        if t.is_zero() {
            return Ok((Float::new(prec), Float::new(prec)));
        }
        let rest = self.work.start().thetadot0 == 0;
        // σ = sqrt(δ) for a start from rest (t is smooth in σ there), else σ = δ
        let to_sigma = |d: &Float| {
            if rest {
                Float::with_val(d.prec(), d.sqrt_ref())
            } else {
                d.clone()
            }
        };
        let to_delta = |s: &Float| {
            if rest {
                Float::with_val(s.prec(), s.square_ref())
            } else {
                s.clone()
            }
        };
        // stage 1: 64-bit safeguarded Newton on [0, σs]
        let lp = 64;
        let e = self.engine(lp)?;
        let tl = Float::with_val(lp, t);
        let mut lo = Float::new(lp);
        let mut hi = to_sigma(&Float::with_val(lp, ds));
        let ts_l = Float::with_val(lp, t_s);
        let mut s = Float::with_val(lp, &hi * Float::with_val(lp, &tl / &ts_l));
        for _ in 0..60 {
            let d = to_delta(&s);
            let (tv, _) = e.time(&d);
            let resid = Float::with_val(lp, &tv - &tl);
            if resid.is_sign_negative() {
                lo = s.clone();
            } else {
                hi = s.clone();
            }
            let mut dt = Float::new(lp);
            e.dynm.inv_thetadot(&d, &mut dt);
            if rest {
                dt *= Float::with_val(lp, &s * 2u32);
            }
            let mut next = Float::with_val(lp, &s - Float::with_val(lp, &resid / &dt));
            if next <= lo || next >= hi || !next.is_finite() {
                next = Float::with_val(lp, &lo + &hi) / 2u32;
            }
            let change = Float::with_val(lp, &next - &s).abs();
            s = next;
            if change <= Float::with_val(lp, s.abs_ref()) >> 40 {
                break;
            }
        }
        // stage 2: Newton at doubling precision (each step doubles the digits)
        let mut precs = vec![prec];
        while *precs.last().expect("nonempty") / 2 > 48 {
            let q = precs.last().expect("nonempty") / 2;
            precs.push(q);
        }
        precs.reverse();
        precs.push(prec); // a final confirming step at full precision
        let mut s = Float::with_val(prec, &s);
        let mut last_corr = Float::with_val(prec, 1u32);
        for &q in &precs {
            let e = self.engine(q)?;
            let sq = Float::with_val(q, &s);
            let d = to_delta(&sq);
            let (tv, _) = e.time(&d);
            let resid = Float::with_val(q, &tv - t);
            let mut dt = Float::new(q);
            e.dynm.inv_thetadot(&d, &mut dt);
            if rest {
                dt *= Float::with_val(q, &sq * 2u32);
            }
            let corr = Float::with_val(q, &resid / &dt);
            s = Float::with_val(prec, &sq - &corr);
            last_corr = Float::with_val(prec, corr.abs_ref());
        }
        let d = to_delta(&s);
        // error: the last correction (quadratic convergence makes it an
        // overestimate) plus the quadrature's error mapped through θ̇
        let e = self.engine(prec)?;
        let (tv, terr) = e.time(&d);
        let st = e.dynm.state(&d);
        let _ = tv;
        let mut err = Float::with_val(prec, &terr * &st.thetadot);
        let dcorr = if rest {
            Float::with_val(prec, &last_corr * &s) * 2u32
        } else {
            last_corr
        };
        err += dcorr;
        let floor = Float::with_val(prec, d.abs_ref()) >> (prec as i32 - 8);
        if err < floor {
            err = floor;
        }
        // certify: t(δ − ε) ≤ t ≤ t(δ + ε)
        let eps = Float::with_val(prec, &err * 2u32);
        let dlo = Float::with_val(prec, &d - &eps);
        let dhi = Float::with_val(prec, &d + &eps);
        let (tlo, _) = if dlo.is_sign_positive() {
            e.time(&dlo)
        } else {
            (Float::new(prec), Float::new(prec))
        };
        let (thi, _) = e.time(&dhi);
        if !(tlo <= *t && *t <= thi) {
            return Err(Error::NotConverged {
                quantity: "theta(t)".into(),
                requested: self.digits,
                reached: format!("no certified bracket at {prec} bits"),
                detail: format!("t = {}", crate::numeric::decimal::to_sig(t, 20)),
            });
        }
        Ok((d, eps))
    }
}
